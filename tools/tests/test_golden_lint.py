"""Self-test of tools/golden-lint: a linter that cannot fail proves nothing.

Feeds the linter a valid document and then one broken variant per check, and requires each
problem to be reported (naming the tcId where there is one). Run from the repository root:
    python3 -m unittest discover -s tools/tests -p "test_*.py"
"""
import copy
import importlib.machinery
import importlib.util
import json
import os
import subprocess
import sys
import tempfile
import unittest

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REPO = os.path.dirname(TOOLS)
LINT_PATH = os.path.join(TOOLS, "golden-lint")


def _load_lint():
    loader = importlib.machinery.SourceFileLoader("golden_lint", LINT_PATH)
    spec = importlib.util.spec_from_loader("golden_lint", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


lint = _load_lint()


def base_doc():
    """A small valid document that uses every feature of the format."""
    return {
        "schema": "golden_v1.schema.json",
        "rule": "demo.rule",
        "module": "demo",
        "source": {"ref": "Shi2022", "doi": "10.3389/fbioe.2022.905983", "equation": "(13)",
                   "page": 5},
        "numberOfTests": 4,
        "header": ["A demonstration rule."],
        "notes": {
            "Basic": {"kind": "BASIC", "description": "Hand-computed."},
            "Domain": {"kind": "EDGE_CASE", "description": "Outside the domain."},
            "Diagonal": {"kind": "INTERPRETATION", "description": "Diagonal step cost.",
                         "param": "diagonal", "options": ["euclidean", "octile"],
                         "default": "euclidean", "links": ["spec/demo.md#diagonal"]},
        },
        "testGroups": [
            {"tgId": 1, "type": "ScalarFunctionTest", "provenance": "hand",
             "params": {"scale": 1.0},
             "tolerance": {"abs": 1e-12, "rel": 0, "why": "closed form"},
             "tests": [
                 {"tcId": 1, "comment": "basic", "flags": ["Basic"], "input": {"x": 0.5},
                  "expected": {"y": 0.25}, "result": "valid"},
                 {"tcId": 2, "comment": "default reading named", "flags": ["Basic", "Diagonal"],
                  "input": {"x": 1.0}, "expected": {"y": [1, "inf", "nan:any"]},
                  "result": "valid", "interpretation": {"Diagonal": "euclidean"}},
                 {"tcId": 3, "comment": "x < 0", "flags": ["Domain"], "input": {"x": -1.0},
                  "expected": {"error": "DomainError"}, "result": "invalid"},
             ]},
            {"tgId": 2, "type": "ScalarFunctionTest", "provenance": "characterization",
             "source": {"name": "pathref", "version": "0.1.0"},
             "tolerance": {"abs": 0, "rel": 1e-15, "ulps": 2, "compare": "elementwise",
                           "why": "one rounding"},
             "tests": [
                 {"tcId": 4, "comment": "octile reading", "flags": ["Diagonal"],
                  "input": {"x": 2.0}, "expected": {"y": 4.0}, "result": "acceptable",
                  "interpretation": {"Diagonal": "octile"},
                  "tolerance": {"abs": 0, "rel": 0, "why": "exact"}},
             ]},
        ],
    }


def text_of(doc):
    return lint.canonical_text(doc)


def problems(doc, path="golden/demo/demo.rule.json", root=None, text=None, use_jsonschema=True):
    return lint.lint_text(text if text is not None else text_of(doc), path, root, use_jsonschema)


class TestValidDocuments(unittest.TestCase):
    def test_base_document_passes(self):
        self.assertEqual(problems(base_doc()), [])

    def test_base_document_passes_without_jsonschema(self):
        self.assertEqual(problems(base_doc(), use_jsonschema=False), [])

    def test_repository_rng_files_pass(self):
        root = os.path.join(REPO, "golden")
        rng = os.path.join(root, "rng")
        for name in sorted(os.listdir(rng)):
            path = os.path.join(rng, name)
            with open(path, encoding="utf-8") as fh:
                self.assertEqual(lint.lint_text(fh.read(), path, root), [], name)

    def test_hyphenated_rule_id(self):
        d = base_doc()
        d["rule"] = "demo.corner-policy"
        self.assertEqual(problems(d, path="golden/demo/demo.corner-policy.json"), [])

    def test_doi_may_be_null(self):
        d = base_doc()
        d["source"]["doi"] = None
        self.assertEqual(problems(d), [])


class TestEachProblemIsReported(unittest.TestCase):
    def assertReported(self, doc, *needles, path="golden/demo/demo.rule.json", text=None, root=None):
        found = problems(doc, path=path, text=text, root=root)
        joined = "\n".join(found)
        for needle in needles:
            self.assertIn(needle, joined, f"{needle!r} not reported; got:\n{joined}")
        # Also without jsonschema: the built-in validator alone must catch it.
        found2 = problems(doc, path=path, text=text, root=root, use_jsonschema=False)
        self.assertTrue(found2, "not reported without jsonschema")
        return found

    # -- JSON and schema ------------------------------------------------------------------
    def test_invalid_json(self):
        self.assertReported(None, "invalid JSON", text='{"rule": ')

    def test_nan_literal(self):
        t = text_of(base_doc()).replace('"y": 0.25', '"y": NaN')
        self.assertReported(None, "non-standard JSON constant NaN", text=t)

    def test_duplicate_key(self):
        t = text_of(base_doc()).replace('"y": 0.25', '"y": 0.25, "y": 0.5')
        self.assertReported(None, "duplicate key 'y'", text=t)

    def test_unknown_top_level_property(self):
        d = base_doc()
        d["algorithm"] = "x"
        self.assertReported(d, "unknown property 'algorithm'")

    def test_unknown_test_property(self):
        d = base_doc()
        d["testGroups"][0]["tests"][0]["weight"] = 1
        self.assertReported(d, "/testGroups/0/tests/0: unknown property 'weight'")

    def test_missing_required(self):
        d = base_doc()
        del d["testGroups"][0]["tests"][0]["result"]
        self.assertReported(d, "missing required property 'result'")

    def test_wrong_schema_name(self):
        d = base_doc()
        d["schema"] = "golden_v2.schema.json"
        self.assertReported(d, "/schema: must be")

    def test_bad_result_value(self):
        d = base_doc()
        d["testGroups"][0]["tests"][0]["result"] = "ok"
        self.assertReported(d, "is not one of ['valid', 'invalid', 'acceptable']")

    def test_bad_provenance(self):
        d = base_doc()
        d["testGroups"][0]["provenance"] = "library"
        self.assertReported(d, "/testGroups/0/provenance")

    def test_bad_note_kind(self):
        d = base_doc()
        d["notes"]["Basic"]["kind"] = "FUNCTIONALITY"
        self.assertReported(d, "/notes/Basic/kind")

    def test_bad_rule_id(self):
        d = base_doc()
        d["rule"] = "Demo"
        self.assertReported(d, "/rule")

    def test_tcid_not_integer(self):
        d = base_doc()
        d["testGroups"][0]["tests"][0]["tcId"] = "1"
        self.assertReported(d, "/testGroups/0/tests/0/tcId")

    def test_negative_tolerance(self):
        d = base_doc()
        d["testGroups"][0]["tolerance"]["abs"] = -1
        self.assertReported(d, "/testGroups/0/tolerance/abs")

    def test_missing_why(self):
        d = base_doc()
        del d["testGroups"][0]["tolerance"]["why"]
        self.assertReported(d, "missing required property 'why'")

    def test_blank_why(self):
        d = base_doc()
        d["testGroups"][1]["tests"][0]["tolerance"]["why"] = "  "
        self.assertReported(d, "tcId 4: tolerance.why is empty")

    def test_blank_group_why(self):
        d = base_doc()
        d["testGroups"][0]["tolerance"]["why"] = ""
        self.assertReported(d, "tgId 1: tolerance.why is empty")

    def test_empty_flags(self):
        d = base_doc()
        d["testGroups"][0]["tests"][0]["flags"] = []
        self.assertReported(d, "/testGroups/0/tests/0/flags: fewer than 1 items")

    # -- location -------------------------------------------------------------------------
    def test_file_name_is_rule_id(self):
        self.assertReported(base_doc(), "is not the rule id + .json",
                            path="golden/demo/demo.other.json")

    def test_directory_is_module(self):
        self.assertReported(base_doc(), "not in golden/demo/", path="golden/grid/demo.rule.json")

    def test_depth_under_root(self):
        self.assertReported(base_doc(), "under the golden directory",
                            path="golden/x/demo/demo.rule.json", root="golden")

    # -- ids and counts -------------------------------------------------------------------
    def test_duplicate_tcid(self):
        d = base_doc()
        d["testGroups"][1]["tests"][0]["tcId"] = 2
        self.assertReported(d, "tcId 2: duplicate tcId")

    def test_duplicate_tgid(self):
        d = base_doc()
        d["testGroups"][1]["tgId"] = 1
        self.assertReported(d, "tgId 1 is used by more than one test group")

    def test_number_of_tests(self):
        d = base_doc()
        d["numberOfTests"] = 5
        self.assertReported(d, "numberOfTests is 5, but the file has 4 tests")

    # -- notes and flags ------------------------------------------------------------------
    def test_undefined_flag(self):
        d = base_doc()
        d["testGroups"][0]["tests"][0]["flags"].append("Mystery")
        self.assertReported(d, "tcId 1: flag 'Mystery' is not defined in notes")

    def test_unused_note(self):
        d = base_doc()
        d["notes"]["Spare"] = {"kind": "EDGE_CASE", "description": "never used"}
        self.assertReported(d, "note 'Spare' is defined but no test carries it")

    def test_interpretation_note_without_options(self):
        d = base_doc()
        del d["notes"]["Diagonal"]["options"]
        self.assertReported(d, "note Diagonal: INTERPRETATION note has no 'options'")

    def test_interpretation_default_not_in_options(self):
        d = base_doc()
        d["notes"]["Diagonal"]["default"] = "manhattan"
        self.assertReported(d, "note Diagonal: default 'manhattan' is not one of options")

    def test_reading_fields_only_on_interpretation(self):
        d = base_doc()
        d["notes"]["Basic"]["options"] = ["a", "b"]
        self.assertReported(d, "note Basic: 'options' is only allowed on INTERPRETATION notes")

    def test_two_notes_one_param(self):
        d = base_doc()
        d["notes"]["Other"] = dict(d["notes"]["Diagonal"])
        d["testGroups"][0]["tests"][0]["flags"].append("Other")
        self.assertReported(d, "param 'diagonal' is also the param of note")

    # -- results and interpretations ------------------------------------------------------
    def test_acceptable_without_interpretation(self):
        d = base_doc()
        del d["testGroups"][1]["tests"][0]["interpretation"]
        self.assertReported(d, "tcId 4: an acceptable test needs an interpretation")

    def test_acceptable_with_default_option(self):
        d = base_doc()
        d["testGroups"][1]["tests"][0]["interpretation"] = {"Diagonal": "euclidean"}
        self.assertReported(d, "tcId 4: an acceptable test must name a non-default option")

    def test_acceptable_names_unknown_note(self):
        d = base_doc()
        d["testGroups"][1]["tests"][0]["interpretation"] = {"Nope": "octile"}
        self.assertReported(d, "tcId 4: interpretation names 'Nope', which is not a note")

    def test_interpretation_names_non_interpretation_note(self):
        d = base_doc()
        d["testGroups"][1]["tests"][0]["interpretation"] = {"Basic": "octile"}
        self.assertReported(d, "which is not of kind INTERPRETATION")

    def test_interpretation_option_unknown(self):
        d = base_doc()
        d["testGroups"][1]["tests"][0]["interpretation"] = {"Diagonal": "chebyshev"}
        self.assertReported(d, "tcId 4: interpretation Diagonal='chebyshev' is not one of")

    def test_acceptable_must_flag_its_note(self):
        d = base_doc()
        d["testGroups"][1]["tests"][0]["flags"] = ["Basic"]
        self.assertReported(d, "tcId 4: an acceptable test must carry the flag 'Diagonal'")

    def test_valid_with_non_default_reading(self):
        d = base_doc()
        d["testGroups"][0]["tests"][1]["interpretation"] = {"Diagonal": "octile"}
        self.assertReported(d, "tcId 2: names the non-default reading(s) Diagonal")

    def test_reading_selected_through_input(self):
        d = base_doc()
        d["testGroups"][0]["tests"][0]["input"]["diagonal"] = "octile"
        self.assertReported(d, "tcId 1: input sets 'diagonal'")

    def test_reading_selected_through_params(self):
        d = base_doc()
        d["testGroups"][0]["params"]["diagonal"] = "octile"
        self.assertReported(d, "tgId 1: params sets 'diagonal'")

    def test_invalid_must_expect_error(self):
        d = base_doc()
        d["testGroups"][0]["tests"][2]["expected"] = {"y": 1}
        self.assertReported(d, "tcId 3: an invalid test must expect exactly")

    def test_invalid_extra_key(self):
        d = base_doc()
        d["testGroups"][0]["tests"][2]["expected"]["message"] = "x < 0"
        self.assertReported(d, "tcId 3: an invalid test must expect exactly")

    def test_invalid_unknown_error_name(self):
        d = base_doc()
        d["testGroups"][0]["tests"][2]["expected"] = {"error": "ValueError"}
        self.assertReported(d, "tcId 3: unknown error name 'ValueError'")

    def test_valid_cannot_expect_error(self):
        d = base_doc()
        d["testGroups"][0]["tests"][0]["expected"] = {"error": "DomainError"}
        self.assertReported(d, "tcId 1: a valid test cannot expect an error")

    def test_null_expected(self):
        d = base_doc()
        d["testGroups"][0]["tests"][0]["expected"] = None
        self.assertReported(d, "tcId 1: expected is null or missing")

    def test_null_inside_expected(self):
        d = base_doc()
        d["testGroups"][0]["tests"][0]["expected"] = {"y": [1.0, None]}
        self.assertReported(d, "tcId 1: null at expected y[1]")

    def test_empty_expected(self):
        d = base_doc()
        d["testGroups"][0]["tests"][0]["expected"] = {}
        self.assertReported(d, "/testGroups/0/tests/0/expected: fewer than 1 properties")

    def test_todo_marker(self):
        d = base_doc()
        d["testGroups"][0]["tests"][0]["comment"] = "TODO: derivation"
        self.assertReported(d, "unfinished: /testGroups/0/tests/0/comment contains TODO")

    def test_golden_new_scaffold_fails_until_completed(self):
        r = subprocess.run([sys.executable, os.path.join(TOOLS, "golden-new"), "rng.index",
                            "--stdout"], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        doc = json.loads(r.stdout)
        self.assertEqual(doc["rule"], "rng.index")
        self.assertEqual(doc["module"], "rng")
        found = "\n".join(problems(None, path="golden/rng/rng.index.json", text=r.stdout))
        self.assertIn("unfinished", found)
        self.assertIn("tcId 1: expected is null", found)
        self.assertNotIn("schema: /notes", found)  # the scaffold's structure is right

    # -- formatting -----------------------------------------------------------------------
    def test_not_canonical_indent(self):
        t = json.dumps(base_doc(), indent=4, sort_keys=True) + "\n"
        self.assertReported(None, "not canonically formatted: line 2", text=t)

    def test_not_canonical_key_order(self):
        t = json.dumps(base_doc(), indent=2) + "\n"
        self.assertReported(None, "not canonically formatted", text=t)

    def test_not_canonical_missing_newline(self):
        self.assertReported(None, "not canonically formatted", text=text_of(base_doc())[:-1])

    def test_not_canonical_number_spelling(self):
        t = text_of(base_doc()).replace('"y": 0.25', '"y": 2.5e-1')
        self.assertReported(None, "not canonically formatted", text=t)

    def test_canonical_text_is_json_dumps(self):
        d = {"b": [1e15, 0.1, 1e16, -0.0], "a": "é"}
        self.assertEqual(lint.canonical_text(d),
                         json.dumps(d, indent=2, sort_keys=True, ensure_ascii=False) + "\n")


class TestSchema(unittest.TestCase):
    def setUp(self):
        with open(lint.SCHEMA_PATH, encoding="utf-8") as fh:
            self.schema = json.load(fh)

    def test_every_field_has_a_description(self):
        missing = []

        def walk(node, where):
            if isinstance(node, dict):
                for name, sub in node.get("properties", {}).items():
                    if isinstance(sub, dict) and "description" not in sub:
                        missing.append(f"{where}/properties/{name}")
                for name, sub in node.get("$defs", {}).items():
                    if "description" not in sub:
                        missing.append(f"{where}/$defs/{name}")
                for key in ("items", "additionalProperties", "propertyNames"):
                    sub = node.get(key)
                    if isinstance(sub, dict) and "description" not in sub and "$ref" not in sub:
                        missing.append(f"{where}/{key}")
                for k, v in node.items():
                    if k != "if":  # a condition, not a field
                        walk(v, f"{where}/{k}")
            elif isinstance(node, list):
                for i, v in enumerate(node):
                    walk(v, f"{where}/{i}")

        walk(self.schema, "#")
        self.assertEqual(missing, [])

    def test_objects_are_closed(self):
        open_objects = []

        def walk(node, where):
            if isinstance(node, dict):
                if "properties" in node and "additionalProperties" not in node and \
                        not where.endswith(("/if", "/then", "/else")):
                    open_objects.append(where)
                for k, v in node.items():
                    walk(v, f"{where}/{k}")
            elif isinstance(node, list):
                for i, v in enumerate(node):
                    walk(v, f"{where}/{i}")

        walk(self.schema, "#")
        self.assertEqual(open_objects, [])

    def test_validator_rejects_unsupported_keywords(self):
        with self.assertRaises(ValueError):
            lint.MiniValidator({"type": "object", "patternProperties": {}})

    def test_builtin_validator_agrees_with_jsonschema(self):
        try:
            import jsonschema
        except ImportError:
            self.skipTest("jsonschema not installed (optional)")
        jsonschema.validators.validator_for(self.schema).check_schema(self.schema)
        _, mini = lint.load_schema()
        cls = jsonschema.validators.validator_for(self.schema)(self.schema)
        cases = [base_doc()]
        mutations = [
            lambda d: d.update(extra=1),
            lambda d: d["notes"]["Diagonal"].pop("default"),
            lambda d: d["notes"]["Basic"].update(param="p"),
            lambda d: d["testGroups"][0]["tests"][2].update(expected={"error": "Nope"}),
            lambda d: d["testGroups"][0]["tests"][0].update(expected={"error": "DomainError"}),
            lambda d: d["testGroups"][1]["tests"][0].pop("interpretation"),
            lambda d: d["source"].update(doi="doi:10.1/x"),
            lambda d: d["testGroups"][0]["tolerance"].update(compare="fuzzy"),
            lambda d: d["testGroups"][0].update(source={}),
            lambda d: d.update(numberOfTests=0),
            lambda d: d["header"].append(""),
            lambda d: d["testGroups"][0]["tests"][0].update(tcId=True),
        ]
        for m in mutations:
            d = base_doc()
            m(d)
            cases.append(d)
        for i, d in enumerate(cases):
            ours = bool(mini.errors(d))
            theirs = bool(list(cls.iter_errors(d)))
            self.assertEqual(ours, theirs, f"case {i}: built-in {ours}, jsonschema {theirs}")
            if i > 0:
                self.assertTrue(ours, f"mutation {i} not rejected")


class TestCommandLine(unittest.TestCase):
    def test_summary_and_exit_code(self):
        with tempfile.TemporaryDirectory() as tmp:
            os.makedirs(os.path.join(tmp, "demo"))
            os.makedirs(os.path.join(tmp, "schema"))
            good = base_doc()
            with open(os.path.join(tmp, "demo", "demo.rule.json"), "w", encoding="utf-8") as fh:
                fh.write(text_of(good))
            bad = copy.deepcopy(good)
            bad["rule"] = "demo.bad"
            bad["testGroups"][0]["tests"][0]["flags"] = ["Mystery"]
            with open(os.path.join(tmp, "demo", "demo.bad.json"), "w", encoding="utf-8") as fh:
                fh.write(text_of(bad))
            with open(os.path.join(tmp, "schema", "ignored.json"), "w", encoding="utf-8") as fh:
                fh.write("not json")
            r = subprocess.run([sys.executable, LINT_PATH, tmp], capture_output=True, text=True)
            self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
            self.assertIn("golden-lint: 1 passed, 1 failed", r.stdout)
            self.assertIn("demo.bad.json: tcId 1: flag 'Mystery' is not defined in notes", r.stdout)
            os.remove(os.path.join(tmp, "demo", "demo.bad.json"))
            r = subprocess.run([sys.executable, LINT_PATH, tmp], capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertIn("golden-lint: 1 passed, 0 failed", r.stdout)

    def test_fix_format(self):
        with tempfile.TemporaryDirectory() as tmp:
            os.makedirs(os.path.join(tmp, "demo"))
            p = os.path.join(tmp, "demo", "demo.rule.json")
            with open(p, "w", encoding="utf-8") as fh:
                fh.write(json.dumps(base_doc(), indent=4))
            r = subprocess.run([sys.executable, LINT_PATH, "--fix-format", tmp],
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            with open(p, encoding="utf-8") as fh:
                self.assertEqual(fh.read(), text_of(base_doc()))

    def test_empty_directory_fails(self):
        with tempfile.TemporaryDirectory() as tmp:
            r = subprocess.run([sys.executable, LINT_PATH, tmp], capture_output=True, text=True)
            self.assertEqual(r.returncode, 1)


if __name__ == "__main__":
    unittest.main()
