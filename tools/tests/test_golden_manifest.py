"""Self-test of tools/golden-manifest: the golden-change gate must fail on a changed, added or
removed vector file until CHANGELOG.md names the rule id and the manifest is updated.
Run from the repository root:
    python3 -m unittest discover -s tools/tests -p "test_*.py"
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TOOL = os.path.join(TOOLS, "golden-manifest")


def doc(rule, value):
    return {"rule": rule, "module": "demo", "notes": {"Basic": {"description": "d"}},
            "testGroups": [{"tgId": 1, "tests": [{"tcId": 1, "input": {"x": 1}, "expected": {"y": value}}]}]}


class GoldenManifestTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name
        os.makedirs(os.path.join(self.root, "golden", "demo"))
        os.makedirs(os.path.join(self.root, "golden", "schema"))
        with open(os.path.join(self.root, "CMakeLists.txt"), "w") as f:
            f.write("project(pathref VERSION 1.2.3 LANGUAGES CXX)\n")
        self.write("demo.a", 1)
        self.write("demo.b", 2)
        with open(os.path.join(self.root, "golden", "schema", "x.json"), "w") as f:
            f.write("{}")
        self.changelog("")
        self.assertEqual(self.run_tool("--update").returncode, 0)

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, rule, value, extra_note=None):
        d = doc(rule, value)
        if extra_note:
            d["notes"]["Basic"]["description"] = extra_note
        with open(os.path.join(self.root, "golden", "demo", rule + ".json"), "w") as f:
            json.dump(d, f)

    def changelog(self, unreleased, released=""):
        with open(os.path.join(self.root, "CHANGELOG.md"), "w") as f:
            f.write(f"# Changelog\n\n## [Unreleased]\n{unreleased}\n## [1.2.3] - 2026-01-01\n{released}\n"
                    "## [1.2.2] - 2025-01-01\n- `demo.a` old entry\n")

    def run_tool(self, mode):
        return subprocess.run([sys.executable, TOOL, "--root", self.root, mode], capture_output=True, text=True)

    def test_clean_set_passes(self):
        r = self.run_tool("--check")
        self.assertEqual(r.returncode, 0, r.stdout)
        self.assertIn("1 passed, 0 failed", r.stdout)

    def test_note_edit_is_not_a_vector_change(self):
        self.write("demo.a", 1, extra_note="reworded")
        self.assertEqual(self.run_tool("--check").returncode, 0)

    def test_changed_vector_fails_and_says_what_to_do(self):
        self.write("demo.a", 5)
        r = self.run_tool("--check")
        self.assertEqual(r.returncode, 1)
        self.assertIn("demo.a: vectors changed (NOT named in CHANGELOG.md)", r.stdout)
        self.assertIn("tools/golden-manifest --update", r.stdout)
        self.assertIn("'## [Unreleased]'", r.stdout)
        # an entry in an older release's section does not count
        u = self.run_tool("--update")
        self.assertEqual(u.returncode, 1, u.stdout)
        self.assertEqual(self.run_tool("--check").returncode, 1)

    def test_changelog_entry_then_update_passes(self):
        self.write("demo.a", 5)
        self.changelog("- `demo.a`: new default reading\n")
        self.assertEqual(self.run_tool("--check").returncode, 1)  # named, but manifest not updated
        self.assertEqual(self.run_tool("--update").returncode, 0)
        self.assertEqual(self.run_tool("--check").returncode, 0)
        m = json.load(open(os.path.join(self.root, "golden", "MANIFEST")))
        self.assertTrue(m["golden_set_version"].startswith("1.2.3+"), m["golden_set_version"])

    def test_release_section_counts_and_sets_plain_version(self):
        self.write("demo.b", 7)
        self.changelog("", released="- demo.b changed because of X\n")
        self.assertEqual(self.run_tool("--update").returncode, 0)
        m = json.load(open(os.path.join(self.root, "golden", "MANIFEST")))
        self.assertEqual(m["golden_set_version"], "1.2.3")

    def test_prefix_of_another_id_does_not_count(self):
        self.write("demo.a", 5)
        self.changelog("- `demo.ab` and demo.a.x changed\n")
        self.assertEqual(self.run_tool("--update").returncode, 1)

    def test_added_and_removed_rules_are_changes(self):
        self.write("demo.c", 3)
        os.remove(os.path.join(self.root, "golden", "demo", "demo.b.json"))
        r = self.run_tool("--check")
        self.assertEqual(r.returncode, 1)
        self.assertIn("demo.c: vectors added", r.stdout)
        self.assertIn("demo.b: vectors removed", r.stdout)
        self.assertNotIn("schema", r.stdout)


if __name__ == "__main__":
    unittest.main()
