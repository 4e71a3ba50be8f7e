#!/usr/bin/env bash
# Regression tests for the rough edges of issue 16 (spec/cli.md): eval rejects unknown inputs,
# eval --list --json, output files into missing folders, golden check's default folder, 0 vectors,
# malformed golden files named with file/line/column/key, a bare .pgm, inflate -o/--output.
# Usage: bash tests/cli/hygiene.sh path/to/pathref   (run from the repository root)
set -euo pipefail
pathref=$(realpath "$1")
root=$PWD
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

source "$(dirname "${BASH_SOURCE[0]}")/../support/expect_exit.sh"

# eval: the README example, unknown inputs named with the valid ones, duplicates, --list --json
expect_exit 0 '"centre": [' eval grid.coord width=6 height=4 index=7
grep -qF '1.5' "$tmp/out" || { echo "FAIL: grid.coord index 7 on 6x4"; cat "$tmp/out"; exit 1; }
expect_exit 2 "rule grid.coord has no input 'frm' (its inputs: width, height, index, form)" eval grid.coord width=6 height=4 index=7 frm=printed1
expect_exit 2 "rule grid.coord has no input 'i' (its inputs: " eval grid.coord i=7 width=6
expect_exit 2 "input 'index' given more than once" eval grid.coord width=6 height=4 index=7 index=8
expect_exit 2 "--json goes with --list" eval --json grid.coord
expect_exit 0 "" eval --list --json
python3 - "$tmp/out" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["format"] == "pathref-rules" and d["format_version"] == 1, d.keys()
ids = [r["id"] for r in d["rules"]]
assert ids == sorted(ids) and len(ids) > 100, len(ids)
coord = next(r for r in d["rules"] if r["id"] == "grid.coord")
assert [f["name"] for f in coord["inputs"]] == ["width", "height", "index", "form"], coord
assert coord["outputs"][0]["name"] == "centre"
PY
# every input key of every golden vector is a listed input (so eval's check never rejects a vector's input)
"$pathref" eval --list --json > "$tmp/rules.json"
python3 - "$tmp/rules.json" "$root/golden" <<'PY'
import json, os, sys
rules = {r["id"]: {f["name"] for f in r["inputs"]} for r in json.load(open(sys.argv[1]))["rules"]
         if not any(f["name"].startswith("<") for f in r["inputs"])}  # <parameter>: any key (checked by the planner)
bad = []
for dp, _, fs in os.walk(sys.argv[2]):
    if os.path.basename(dp) == "schema":
        continue
    for f in fs:
        if not f.endswith(".json"):
            continue
        d = json.load(open(os.path.join(dp, f)))
        if d["rule"] not in rules:
            continue
        known = rules[d["rule"]]
        for g in d["testGroups"]:
            for t in g["tests"]:
                keys = set(g.get("params", {})) | set(t.get("input", {}))
                keys |= {d["notes"][n]["param"] for n in t.get("interpretation", {})}
                for k in sorted(keys - known):
                    bad.append(f"{d['rule']} tcId {t['tcId']}: input '{k}' not in eval --list")
if bad:
    print("\n".join(bad[:20])); print(f"{len(bad)} unlisted inputs"); sys.exit(1)
PY

# output files: missing folders are created; a folder that cannot be created gives the reason
mkdir "$tmp/w"; cd "$tmp/w"
expect_exit 0 "wrote out/grid20.svg" plan --builtin grid20 --algo astar --policy always --svg out/grid20.svg
[ -s out/grid20.svg ] || { echo "FAIL: --svg into a new folder wrote nothing"; exit 1; }
expect_exit 0 "" plan --builtin shi6x6 --algo astar --json-out deep/er/plan.json
[ -s deep/er/plan.json ] || { echo "FAIL: --json-out into a new folder"; exit 1; }
: > afile
expect_exit 2 "cannot write 'afile/x.svg': cannot create the folder 'afile': " plan --builtin shi6x6 --algo astar --svg afile/x.svg
expect_exit 2 "cannot write 'out': it is a folder" plan --builtin shi6x6 --algo astar --svg out

# golden check: ./golden of the working directory by default; 0 vectors fail; malformed files named
expect_exit 2 "not a directory: 'golden'" golden check
mkdir -p golden/grid
expect_exit 2 "no golden vectors in 'golden'" golden check
cp "$root/golden/grid/grid.coord.json" golden/grid/
expect_exit 0 "golden: " golden check
expect_exit 2 "dir is required" golden regenerate     # nothing is rewritten by default
python3 - golden/grid/grid.coord.json <<'PY'
import json, sys
d = json.load(open(sys.argv[1])); del d["rule"]
json.dump(d, open(sys.argv[1], "w"), indent=2)
PY
expect_exit 2 'golden/grid/grid.coord.json:1:1: /: missing key "rule" (expected the rule id, a string)' golden check
# issue 27: golden messages say what was expected, with their spaces (was "the document'testGroups' must be an array")
cp "$root/golden/grid/grid.coord.json" golden/grid/
python3 - golden/grid/grid.coord.json <<'PY'
import json, sys
d = json.load(open(sys.argv[1])); d["testGroups"] = "none"
json.dump(d, open(sys.argv[1], "w"), indent=2)
PY
expect_exit 2 "golden/grid/grid.coord.json:" golden check
grep -qE 'grid.coord.json:[0-9]+:[0-9]+: /testGroups: expected an array of at least one test group, got a string$' "$tmp/err" ||
  { echo "FAIL: golden testGroups message"; cat "$tmp/err"; exit 1; }
cp "$root/golden/grid/grid.coord.json" golden/grid/
python3 - golden/grid/grid.coord.json <<'PY'
import json, sys
d = json.load(open(sys.argv[1])); del d["testGroups"][0]["tests"][1]["expected"]
json.dump(d, open(sys.argv[1], "w"), indent=2)
PY
expect_exit 2 '/testGroups/0/tests/1: missing key "expected" (expected the expected output (null until generated))' golden check
printf '{\n  "rule": "grid.coord",\n  "testGroups": [\n    {"tcId": 1,,}\n' > golden/grid/grid.coord.json
expect_exit 2 "pathref: error: golden/grid/grid.coord.json:4:" golden check   # the line of the error, not 0
grep -qF "expected valid JSON (" "$tmp/err" || { echo "FAIL: JSON error message"; cat "$tmp/err"; exit 1; }

# a bare .pgm: ROS maps are read through their YAML
printf 'P5\n2 2\n255\n\0\0\0\0' > map.pgm
expect_exit 2 "'map.pgm' is an image: a ROS map is read through its YAML file" plan --map map.pgm --algo astar
echo "hygiene: ok"
