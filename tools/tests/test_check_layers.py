"""Self-test of tools/check-layers: a planted include against the layer order must be reported.
Run from the repository root:
    python3 -m unittest discover -s tools/tests -p "test_*.py"
"""
import os
import subprocess
import sys
import tempfile
import unittest

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TOOL = os.path.join(TOOLS, "check-layers")


class CheckLayersTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name
        self.put("src/pathref/core/error.hpp", "#pragma once\n")
        self.put("src/pathref/grid/grid.hpp", '#include "pathref/core/error.hpp"\n#include <vector>\n')
        self.put("src/pathref/io/map_file.hpp", '#include "pathref/grid/grid.hpp"\n')
        self.put("src/cli/main.cpp", '#include "commands.hpp"\n#include "pathref/io/map_file.hpp"\n')

    def tearDown(self):
        self.tmp.cleanup()

    def put(self, rel, text):
        path = os.path.join(self.root, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)

    def run_tool(self):
        return subprocess.run([sys.executable, TOOL, "--root", self.root], capture_output=True, text=True)

    def test_clean_tree_passes(self):
        r = self.run_tool()
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)

    def test_upward_include_is_reported_with_file_and_line(self):
        self.put("src/pathref/geometry/scene.cpp", '// reads scenes\n#include "pathref/io/map_file.hpp"\n')
        r = self.run_tool()
        self.assertEqual(r.returncode, 1)
        self.assertIn("src/pathref/geometry/scene.cpp:2: geometry (layer 1) includes io (layer 5)", r.stdout)

    def test_same_layer_and_downward_includes_pass(self):
        self.put("src/pathref/rng/draws.hpp", '#include "pathref/grid/grid.hpp"\n')  # same layer
        self.put("src/pathref/sim/run.cpp", '#include "pathref/grid/grid.hpp"\n')
        self.assertEqual(self.run_tool().returncode, 0)

    def test_unplaced_folder_is_reported(self):
        self.put("src/pathref/newthing/x.cpp", '#include "pathref/core/error.hpp"\n')
        r = self.run_tool()
        self.assertEqual(r.returncode, 1)
        self.assertIn("'newthing' has no place in the layer order", r.stdout)

    def test_geometry_cgal_may_use_rules_but_core_may_not_use_cli(self):
        self.put("src/geometry_cgal/inflate.cpp", '#include "pathref/rules/registry.hpp"\n')
        self.assertEqual(self.run_tool().returncode, 0)
        self.put("src/pathref/core/bad.hpp", '#include "pathref/rules/registry.hpp"\n')
        self.assertEqual(self.run_tool().returncode, 1)

    def test_known_list_is_a_ratchet(self):
        self.put("src/pathref/geometry/scene.cpp", '#include "pathref/io/map_file.hpp"\n')
        known = os.path.join(self.root, "known.txt")
        with open(known, "w") as f:
            f.write('# comment\nsrc/pathref/geometry/scene.cpp: #include "pathref/io/map_file.hpp"\n')
        run = lambda: subprocess.run([sys.executable, TOOL, "--root", self.root, "--known", known],
                                     capture_output=True, text=True)
        self.assertEqual(run().returncode, 0)
        # a new violation outside the list fails
        self.put("src/pathref/rng/trace.cpp", '#include "pathref/io/json_text.hpp"\n')
        r = run()
        self.assertEqual(r.returncode, 1)
        self.assertIn("src/pathref/rng/trace.cpp:1: rng (layer 1) includes io (layer 5)", r.stdout)
        os.remove(os.path.join(self.root, "src/pathref/rng/trace.cpp"))
        # a listed violation that was fixed must leave the list
        self.put("src/pathref/geometry/scene.cpp", '#include "pathref/grid/grid.hpp"\n')
        r = run()
        self.assertEqual(r.returncode, 1)
        self.assertIn("no longer runs against the order", r.stdout)


if __name__ == "__main__":
    unittest.main()
