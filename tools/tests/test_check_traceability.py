"""Self-test of tools/check-traceability on a miniature repository built in a temporary directory.

A complete rule must pass; each way of breaking one link of the chain (spec anchor, function,
Spec: line, golden file, test name, crosscheck, eval --list, index) must be reported and fail.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCRIPT = os.path.join(TOOLS, "check-traceability")


def write(root, rel, text):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(text)
    if rel.endswith("pathref"):
        os.chmod(path, 0o755)


class MiniRepo:
    """A repository with one complete rule, demo.a."""

    def __init__(self):
        self.root = tempfile.mkdtemp(prefix="trace-")
        self.index = {"module": "demo", "rules": [{
            "id": "demo.a", "spec": "spec/demo.md", "function": "pathref::demo::fa",
            "header": "src/pathref/demo/a.hpp", "golden": "golden/demo/demo.a.json",
            "tests": ["demo.a: works", "prop_demo_a"]}]}
        self.files = {
            "spec/demo.md": "# demo\n\n### r[demo.a] The a rule\n\n- **Source**: pathref.\n",
            "src/pathref/demo/a.hpp": "#pragma once\n/// One line.\n/// Spec: demo.a. Golden: golden/demo/demo.a.json\n"
                                      "[[nodiscard]] int fa(int x);\n",
            "golden/demo/demo.a.json": json.dumps({"rule": "demo.a", "module": "demo"}),
            "golden/schema/golden_v1.schema.json": "{}",
            "tests/unit/demo_test.cpp": 'TEST_CASE("demo.a: works", "[demo]") {}\n'
                                        'TEST_CASE("prop_demo_a", "[demo][prop]") {}\n',
            "tools/crosscheck/rules/__init__.py": "from . import demo\nRULES = dict(demo.RULES)\n",
            "tools/crosscheck/rules/demo.py": "RULES = {'demo.a': lambda i: {}}\n",
            "bin/pathref": "#!/bin/sh\nprintf 'demo.a  The a rule\\n    in  x : integer - x\\n'\n",
        }

    def build(self):
        write(self.root, "spec/index/demo.json", json.dumps(self.index))
        for rel, text in self.files.items():
            write(self.root, rel, text)
        return self

    def run(self, *extra, pathref=True):
        args = [sys.executable, SCRIPT, "--root", self.root]
        if pathref:
            args += ["--pathref", os.path.join(self.root, "bin", "pathref")]
        r = subprocess.run(args + list(extra), capture_output=True, text=True)
        return r.returncode, r.stdout + r.stderr

    def cleanup(self):
        shutil.rmtree(self.root, ignore_errors=True)


class TestTraceability(unittest.TestCase):
    def setUp(self):
        self.repo = MiniRepo()

    def tearDown(self):
        self.repo.cleanup()

    def assertGap(self, *needles):
        rc, out = self.repo.build().run()
        self.assertEqual(rc, 1, out)
        for n in needles:
            self.assertIn(n, out)
        return out

    def test_complete_rule_passes(self):
        rc, out = self.repo.build().run()
        self.assertEqual(rc, 0, out)
        self.assertIn("| demo.a", out)
        self.assertIn("1 rules, 1 complete, 0 with gaps", out)

    def test_without_pathref_eval_is_not_checked(self):
        rc, out = self.repo.build().run(pathref=False)
        self.assertEqual(rc, 0, out)
        self.assertIn("not checked", out)

    def test_spec_file_missing(self):
        del self.repo.files["spec/demo.md"]
        self.assertGap("GAP demo.a: spec: spec file 'spec/demo.md' not found")

    def test_anchor_missing(self):
        self.repo.files["spec/demo.md"] = "# demo\n\n### r[demo.b] Another\n"
        self.assertGap("GAP demo.a: spec: spec/demo.md has no heading with r[demo.a]")

    def test_anchor_not_in_heading(self):
        self.repo.files["spec/demo.md"] = "# demo\n\nSee r[demo.a].\n"
        self.assertGap("but not in a heading")

    def test_header_missing(self):
        del self.repo.files["src/pathref/demo/a.hpp"]
        self.assertGap("GAP demo.a: function: header src/pathref/demo/a.hpp not found")

    def test_function_name_missing(self):
        self.repo.files["src/pathref/demo/a.hpp"] = "/// Spec: demo.a\nint fb(int x);\n"
        self.assertGap("fa not found in src/pathref/demo/a.hpp")

    def test_function_name_must_be_a_whole_word(self):
        self.repo.files["src/pathref/demo/a.hpp"] = "/// Spec: demo.a\nint fab(int x);\n"
        self.assertGap("fa not found")

    def test_spec_line_missing(self):
        self.repo.files["src/pathref/demo/a.hpp"] = "/// Computes a.\nint fa(int x);\n"
        self.assertGap("no doc-comment line `Spec: demo.a`")

    def test_spec_line_must_be_a_comment(self):
        self.repo.files["src/pathref/demo/a.hpp"] = 'const char* s = "Spec: demo.a";\nint fa(int x);\n'
        self.assertGap("no doc-comment line `Spec: demo.a`")

    def test_spec_line_names_a_longer_id(self):
        self.repo.files["src/pathref/demo/a.hpp"] = "/// Spec: demo.ab, demo.a-b\nint fa(int x);\n"
        self.assertGap("no doc-comment line `Spec: demo.a`")

    def test_spec_line_anchor_form_accepted(self):
        self.repo.files["src/pathref/demo/a.hpp"] = "/// Spec: r[demo.a]\nint fa(int x);\n"
        rc, out = self.repo.build().run()
        self.assertEqual(rc, 0, out)

    def test_several_functions(self):
        self.repo.index["rules"][0]["function"] = ["pathref::demo::fa", "pathref::demo::fz"]
        self.assertGap("fz not found")

    def test_golden_missing(self):
        del self.repo.files["golden/demo/demo.a.json"]
        self.assertGap("GAP demo.a: golden: golden file 'golden/demo/demo.a.json' not found")

    def test_golden_names_another_rule(self):
        self.repo.files["golden/demo/demo.a.json"] = json.dumps({"rule": "demo.b"})
        out = self.assertGap("has rule 'demo.b', not 'demo.a'")
        self.assertIn("demo.b: no spec/index entry, but golden file golden/demo/demo.a.json", out)  # and demo.b is not indexed

    def test_test_name_unknown(self):
        self.repo.index["rules"][0]["tests"].append("demo.a: missing")
        self.assertGap("no TEST_CASE or ctest add_test named 'demo.a: missing' under tests/")

    def test_ctest_add_test_name_accepted(self):
        self.repo.index["rules"][0]["tests"] = ["oracle.demo-replay", "demo.quoted name", "demo.a: works"]
        self.repo.files["tests/CMakeLists.txt"] = (
            "# add_test(NAME demo.commented-out COMMAND x)\n"
            "add_test(NAME oracle.demo-replay\n         COMMAND python3 replay.py $<TARGET_FILE:pathref_cli>)\n"
            "add_test( NAME \"demo.quoted name\" COMMAND true)\n")
        rc, out = self.repo.build().run()
        self.assertEqual(rc, 0, out)

    def test_ctest_names_from_subdirectory_and_top_level(self):
        self.repo.index["rules"][0]["tests"] = ["demo.sub", "demo.top"]
        self.repo.files["tests/sub/CMakeLists.txt"] = "add_test(NAME demo.sub COMMAND true)\n"
        self.repo.files["CMakeLists.txt"] = "add_test(NAME demo.top COMMAND true)\n"
        rc, out = self.repo.build().run()
        self.assertEqual(rc, 0, out)

    def test_ctest_name_commented_out_or_generated_is_unknown(self):
        self.repo.index["rules"][0]["tests"] = ["demo.commented-out", "cli.${name}", "cli.demo"]
        self.repo.files["tests/CMakeLists.txt"] = (
            "# add_test(NAME demo.commented-out COMMAND x)\n"
            "foreach(name demo)\n  add_test(NAME cli.${name} COMMAND true)\nendforeach()\n")
        self.assertGap("no TEST_CASE or ctest add_test named 'demo.commented-out'",
                       "named 'cli.${name}'", "named 'cli.demo'")

    def test_ctest_name_outside_cmake_files_is_unknown(self):
        self.repo.index["rules"][0]["tests"] = ["demo.elsewhere"]
        self.repo.files["tests/notes.txt"] = "add_test(NAME demo.elsewhere COMMAND true)\n"
        self.repo.files["tools/CMakeLists.txt"] = "add_test(NAME demo.elsewhere COMMAND true)\n"
        self.assertGap("named 'demo.elsewhere'")

    def test_test_names_must_be_exact(self):
        self.repo.index["rules"][0]["tests"] = ["demo.a: work"]
        self.assertGap("no TEST_CASE or ctest add_test named 'demo.a: work'")

    def test_no_tests_listed(self):
        self.repo.index["rules"][0]["tests"] = []
        self.assertGap("GAP demo.a: tests: no tests listed")

    def test_crosscheck_missing(self):
        self.repo.files["tools/crosscheck/rules/demo.py"] = "RULES = {}\n"
        self.assertGap("GAP demo.a: crosscheck: not in tools/crosscheck/rules RULES")

    def test_crosscheck_import_error(self):
        self.repo.files["tools/crosscheck/rules/demo.py"] = "import nonexistent_module_xyz\n"
        self.assertGap("cannot import tools/crosscheck/rules")

    def test_eval_missing(self):
        self.repo.files["bin/pathref"] = "#!/bin/sh\nprintf 'demo.b  Other\\n'\n"
        out = self.assertGap("GAP demo.a: eval: not listed by `pathref eval --list`")
        self.assertIn("demo.b: no spec/index entry, but listed by `pathref eval --list`", out)

    def test_eval_fails(self):
        self.repo.files["bin/pathref"] = "#!/bin/sh\necho boom >&2\nexit 3\n"
        self.assertGap("exited 3")

    def test_golden_file_not_indexed(self):
        self.repo.files["golden/demo/demo.c.json"] = json.dumps({"rule": "demo.c"})
        self.assertGap("GAP demo.c: no spec/index entry, but golden file golden/demo/demo.c.json")

    def test_duplicate_index_entry(self):
        self.repo.index["rules"].append(dict(self.repo.index["rules"][0]))
        self.assertGap("demo.a is also indexed in spec/index/demo.json")

    def test_index_module_is_file_name(self):
        self.repo.index["module"] = "other"
        self.assertGap("\"module\" is 'other', expected 'demo'")

    def test_index_entry_keys(self):
        del self.repo.index["rules"][0]["golden"]
        self.repo.index["rules"][0]["gold"] = "x"
        self.assertGap("missing keys ['golden']", "unknown keys ['gold']")

    def test_write_docs(self):
        rc, out = self.repo.build().run("--write-docs")
        self.assertEqual(rc, 0, out)
        with open(os.path.join(self.repo.root, "docs", "traceability.md"), encoding="utf-8") as fh:
            doc = fh.read()
        self.assertIn("| rule ", doc)
        self.assertIn("| demo.a ", doc)

    def test_runs_from_any_directory(self):
        self.repo.build()
        r = subprocess.run([sys.executable, SCRIPT, "--root", self.repo.root], capture_output=True,
                           text=True, cwd=tempfile.gettempdir())
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)


if __name__ == "__main__":
    unittest.main()


class TestConfidenceGrades(unittest.TestCase):
    """cin2021/sensors2023 rules must carry a grade that the index and the golden source block agree on."""

    def setUp(self):
        self.repo = MiniRepo()
        rid = "sensors2023.demo"
        self.repo.index = json.loads(json.dumps(self.repo.index).replace("demo.a", rid))
        self.repo.files = {k: v.replace("demo.a", rid) for k, v in self.repo.files.items()}
        self.repo.index["rules"][0].update({"grade": "B", "reconstructed": True, "grade_basis": "eq14 (B)"})
        self.repo.files["golden/demo/" + rid + ".json"] = json.dumps(
            {"rule": rid, "module": "demo", "source": {"grade": "B", "reconstructed": True}})
        self.repo.index["rules"][0]["golden"] = "golden/demo/" + rid + ".json"
        self.repo.files["bin/pathref"] = ("#!/bin/sh\nprintf '" + rid +
                                          "  [grade B, reconstructed]  The rule\\n    in  x : integer - x\\n'\n")

    def tearDown(self):
        self.repo.cleanup()

    def test_graded_rule_passes(self):
        rc, out = self.repo.build().run()
        self.assertEqual(rc, 0, out)

    def test_missing_grade_is_a_gap(self):
        del self.repo.index["rules"][0]["grade"]
        rc, out = self.repo.build().run()
        self.assertEqual(rc, 1, out)
        self.assertIn("sensors2023.demo: grade: index \"grade\" must be A, B or C", out)

    def test_golden_grade_must_agree(self):
        self.repo.files["golden/demo/sensors2023.demo.json"] = json.dumps(
            {"rule": "sensors2023.demo", "module": "demo", "source": {"grade": "A", "reconstructed": True}})
        rc, out = self.repo.build().run()
        self.assertEqual(rc, 1, out)
        self.assertIn("golden source block has grade 'A'", out)
