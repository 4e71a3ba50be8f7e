"""Self-test of tools/mutate on a miniature CMake project (no compiler: LANGUAGES NONE) whose
tests grep the "source": a linked test must kill its mutant, an unlinked one must let it survive,
the source must be restored, a rerun must skip done mutants, a journal left by a killed run must
be undone, and a broken catalogue must be refused.
"""
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCRIPT = os.path.join(TOOLS, "mutate")

SOURCE = "if (x >= 1) return a;\nif (y < 2) return b;\n"
CMAKE = """cmake_minimum_required(VERSION 3.16)
project(mini LANGUAGES NONE)
enable_testing()
add_test(NAME t.x COMMAND grep -q "x >= 1" ${CMAKE_SOURCE_DIR}/src/rule.cpp)
add_test(NAME t.skip COMMAND sh -c "exit 77")
set_tests_properties(t.skip PROPERTIES SKIP_RETURN_CODE 77)
"""


def write(root, rel, text):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(text)


@unittest.skipUnless(shutil.which("cmake") and shutil.which("ctest"), "cmake not installed")
class TestMutate(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        self.src = os.path.join(self.tmp, "src")
        self.build = os.path.join(self.tmp, "build")
        write(self.src, "CMakeLists.txt", CMAKE)
        write(self.src, "src/rule.cpp", SOURCE)
        write(self.src, "spec/index/demo.json", json.dumps({"module": "demo", "rules": [
            {"id": "demo.x", "tests": ["t.x", "t.skip"]},
            {"id": "demo.y", "tests": ["t.skip"]}]}))
        self.write_catalogue([
            {"id": "x.boundary", "file": "src/rule.cpp", "original": "x >= 1", "replacement": "x > 1",
             "rules": ["demo.x"], "kind": "relational"},
            {"id": "y.boundary", "file": "src/rule.cpp", "original": "y < 2", "replacement": "y <= 2",
             "rules": ["demo.y"], "kind": "relational"},
        ])
        subprocess.run(["cmake", "-S", self.src, "-B", self.build], check=True, capture_output=True)

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def write_catalogue(self, mutants):
        write(self.src, "tools/mutate.d/catalogue.json", json.dumps({"mutants": mutants}))

    def run_mutate(self, *args):
        return subprocess.run([sys.executable, SCRIPT, "--build-dir", self.build, "--jobs", "1", *args],
                              capture_output=True, text=True)

    def source(self):
        with open(os.path.join(self.src, "src/rule.cpp"), encoding="utf-8") as fh:
            return fh.read()

    def test_kills_survives_restores_and_resumes(self):
        p = self.run_mutate()
        self.assertEqual(p.returncode, 1, p.stdout + p.stderr)  # y.boundary survives
        self.assertEqual(self.source(), SOURCE)
        with open(os.path.join(self.build, "mutate", "results.json"), encoding="utf-8") as fh:
            results = json.load(fh)
        self.assertEqual(results["x.boundary"]["status"], "killed")
        self.assertEqual(results["x.boundary"]["killers"], ["t.x"])
        self.assertEqual(results["x.boundary"]["skipped"], ["t.skip"])
        self.assertEqual(results["y.boundary"]["status"], "survived")
        self.assertIn("score: killed 1/2", p.stdout)
        again = self.run_mutate()
        self.assertIn("2 already done", again.stdout)
        self.assertEqual(self.source(), SOURCE)
        # A changed entry is run again.
        self.write_catalogue([
            {"id": "x.boundary", "file": "src/rule.cpp", "original": "x >= 1", "replacement": "x >= 2",
             "rules": ["demo.x"], "kind": "constant"}])
        third = self.run_mutate()
        self.assertIn("0 already done", third.stdout)
        self.assertEqual(third.returncode, 0, third.stdout + third.stderr)

    def test_restores_a_mutation_left_by_a_killed_run(self):
        state = os.path.join(self.build, "mutate")
        os.makedirs(state)
        original = SOURCE.encode("utf-8")
        with open(os.path.join(state, "backup.orig"), "wb") as fh:
            fh.write(original)
        with open(os.path.join(state, "journal.json"), "w", encoding="utf-8") as fh:
            json.dump({"id": "x.boundary", "file": "src/rule.cpp",
                       "sha256": hashlib.sha256(original).hexdigest()}, fh)
        write(self.src, "src/rule.cpp", SOURCE.replace("x >= 1", "x > 1"))
        p = self.run_mutate("--restore-only")
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("restored src/rule.cpp", p.stdout)
        self.assertEqual(self.source(), SOURCE)
        self.assertFalse(os.path.exists(os.path.join(state, "journal.json")))

    def test_refuses_a_broken_catalogue(self):
        self.write_catalogue([
            {"id": "twice", "file": "src/rule.cpp", "original": "return", "replacement": "throw",
             "rules": ["demo.x"], "kind": "logic"},
            {"id": "bad-kind", "file": "src/rule.cpp", "original": "x >= 1", "replacement": "x > 1",
             "rules": ["demo.x"], "kind": "vibes"}])
        p = self.run_mutate("--list")
        self.assertEqual(p.returncode, 2)
        self.assertIn("occurs 2 times", p.stderr)
        self.assertIn("kind 'vibes'", p.stderr)


if __name__ == "__main__":
    unittest.main()
