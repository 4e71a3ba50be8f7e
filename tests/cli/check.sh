#!/usr/bin/env bash
# `pathref check` (spec/check.md): paths in every format other programs write, the first invalid
# step and why, length/turns/optimum/ratio/clearance, several paths with a summary, exit codes.
# Usage: bash tests/cli/check.sh path/to/pathref
set -euo pipefail
pathref=$(realpath "$1")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
source "$(dirname "${BASH_SOURCE[0]}")/../support/expect_exit.sh"
cd "$tmp"

# 4x3 map, (1,1) blocked; rows top first.
cat > m.grid <<'M'
pathref-grid 1
size 4 3
start 0 0
goal 3 2
map
....
.#..
....
M
# The same valid path (0,0) (1,0) (2,0) (3,1) (3,2) in five forms.
printf '0 0\n1 0\n2 0\n3 1\n3 2\n' > xy.txt
printf '[[0,0],[1,0],[2,0],[3,1],[3,2]]\n' > xy.json
printf '%% MATLAB node numbers, 1-based, row-major, first row on top\n9\n10\n11\n8\n4\n' > node.txt
printf '9 10 11 8 4\n' > node_row.txt
printf '[3 1;3 2;3 3;2 4;1 4]' > rowcol.txt                          # mat2str of [row col] pairs
printf '   9.0000000e+00\n   1.0000000e+01\n   1.1000000e+01\n   8.0000000e+00\n   4.0000000e+00\n' > save_ascii.txt
for f in xy.txt xy.json node.txt node_row.txt save_ascii.txt; do
  expect_exit 0 "  valid       yes" check --map m.grid --path $f
done
expect_exit 0 "(rowcol, base 1, origin upper), 5 nodes" check --map m.grid --path rowcol.txt --path-format rowcol
expect_exit 0 "(node, base 1, origin upper), 5 nodes" check --map m.grid --path node.txt
expect_exit 0 "(xy, base 0, origin lower), 5 nodes" check --map m.grid --path xy.txt
grep -qF "  start       (0, 0) from the map" out || { echo "FAIL: start source"; cat out; exit 1; }
# the same nodes under other base/origin conventions
printf '1 1\n2 1\n3 1\n4 2\n4 3\n' > xy1.txt
expect_exit 0 "  valid       yes" check --map m.grid --path xy1.txt --base 1
printf '0 2\n1 2\n2 2\n3 1\n3 0\n' > xyup.txt
expect_exit 0 "  valid       yes" check --map m.grid --path xyup.txt --origin upper
printf '0\n1\n2\n7\n11\n' > index.txt   # pathref's own index i = y W + x
expect_exit 0 "  valid       yes" check --map m.grid --path index.txt --path-format node --base 0 --origin lower

expect_exit 0 "" check --map m.grid --path xy.txt --json
python3 - out <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["format"] == "pathref-check" and d["format_version"] == 1
p = d["paths"][0]
assert p["valid"] and p["reason"] == "ok" and p["index"] == -1 and p["step"] is None, p
assert p["length"] == 4.414213562373095 and p["turns"] == 2, p          # 3 + sqrt(2); turns at (2,0), (3,1)
assert p["optimum"] == 4.414213562373095 and p["ratio"] == 1.0, p       # strict: no shorter path past (1,1)
assert p["clearance"] == 0.5, p                                         # the border, from the centre of (0,0)
assert p["cells"] == [[0, 0], [1, 0], [2, 0], [3, 1], [3, 2]] and p["policy"] == "strict"
assert d["summary"] == {"paths": 1, "valid": 1, "invalid": 0,
                        "length": {"n": 1, "mean": 4.414213562373095, "sd": None, "min": 4.414213562373095, "max": 4.414213562373095},
                        "ratio": {"n": 1, "mean": 1.0, "sd": None, "min": 1.0, "max": 1.0}}, d["summary"]
PY

# invalid paths: the first failure, located and explained
printf '0 0\n1 0\n2 1\n3 2\n' > cut.txt
expect_exit 1 "NO: corner_cut at node 2: diagonal step (1, 0) -> (2, 1) (node 1 to 2) is refused by policy strict (it passes blocked (1, 1))" check --map m.grid --path cut.txt
expect_exit 0 "  valid       yes" check --map m.grid --path cut.txt --policy one
printf '0 0\n1 0\n2 1\n' > diag.txt
expect_exit 1 "NO: corner_cut at node 2: diagonal step (1, 0) -> (2, 1) (node 1 to 2) is refused by policy never (no diagonal step)" check --map m.grid --path diag.txt --policy never --goal 2,1
printf '0 0\n2 0\n3 1\n3 2\n' > jump.txt
expect_exit 1 "NO: not_adjacent at node 1: step (0, 0) -> (2, 0) (node 0 to 1) is not a step to one of the 8 neighbours" check --map m.grid --path jump.txt
printf '0 0\n0 1\n1 1\n2 2\n3 2\n' > wall.txt
expect_exit 1 "NO: blocked at node 2: node 2 (1, 1) is a blocked cell" check --map m.grid --path wall.txt
printf '0 0\n1 0\n2 0\n3 1\n' > short.txt
expect_exit 1 "NO: goal_mismatch at node 3: the last node (3, 1) is not the goal (3, 2)" check --map m.grid --path short.txt
expect_exit 1 "NO: start_mismatch at node 0: the first node (0, 0) is not the start (1, 0)" check --map m.grid --path xy.txt --start 1,0
printf '0 0\n1 0\n1 0\n' > rep.txt
expect_exit 1 "NO: repeated at node 2: node 2 repeats node 1 (1, 0)" check --map m.grid --path rep.txt --goal 1,0
printf '1\n2\n99\n' > far.txt
expect_exit 1 "NO: out_of_bounds at node 2: node 2 (2, -22) is outside the 4x3 map" check --map m.grid --path far.txt --start 0,2 --goal 1,2

# a pathref-plan record carries its own map, endpoints and policy
"$pathref" plan --builtin shi6x6 --algo astar --json-out plan.json > /dev/null
expect_exit 0 "map         plan.json (plan, 6x6" check --path plan.json
expect_exit 0 "from the plan record" check --path plan.json
expect_exit 2 "is a pathref-plan record (cells [x, y], base 0, origin lower): --base and --origin" check --path plan.json --base 1
# issue 27 (item 5): a plan record whose map.width/height contradicts its rows is refused at the value
python3 - plan.json <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["map"]["width"] = 7
json.dump(d, open("wide.json", "w"), indent=2)
d["map"]["width"] = 6; d["map"]["height"] = 5
json.dump(d, open("short.json", "w"), indent=2)
d["map"]["height"] = 6; d["map"]["rows"][2] = "..x..."
json.dump(d, open("letter.json", "w"), indent=2)
PY
expect_exit 2 "" check --path wide.json
grep -qE '^pathref: error: wide.json:[0-9]+:[0-9]+: /map/width: expected 6 \(the length of each of /map/rows\), got 7$' "$tmp/err" ||
  { echo "FAIL: plan record width message"; cat "$tmp/err"; exit 1; }
expect_exit 2 "/map/height: expected 6 (the number of /map/rows), got 5" check --path short.json
expect_exit 2 "/map/rows/2: expected only '.' (free) and '#' (blocked), got 'x' at character 3" check --path letter.json
expect_exit 2 "/map/width: expected 6" check --path wide.json --map m.grid   # also when --map gives the map

# many paths: JSON lines and a folder, with a summary; exit 1 when any is invalid
{ cat xy.json; printf '[[0,0],[1,0],[2,1],[3,2]]\n\n[[0,0],[0,1],[0,2],[1,2],[2,2],[3,2]]\n'; } > runs.jsonl
expect_exit 1 "summary: 3 paths, 2 valid, 1 invalid" check --map m.grid --path runs.jsonl
grep -qE "^runs.jsonl:2 +NO +corner_cut +2 " out || { echo "FAIL: table row of runs.jsonl:2"; cat out; exit 1; }
grep -qF "length of valid paths: n 2, mean 4.70711, sd 0.414214, min 4.41421, max 5" out || { echo "FAIL: summary line"; cat out; exit 1; }
mkdir runs; cp xy.txt runs/a.txt; cp xy.json runs/b.json; cp save_ascii.txt runs/c.txt
expect_exit 0 "summary: 3 paths, 3 valid, 0 invalid" check --map m.grid --path runs --json-out res/check.json
[ -s res/check.json ] || { echo "FAIL: --json-out"; exit 1; }

# bad input: exit 2 with file, line, column
printf '0 0\n1\n2 0\n' > ragged.txt
expect_exit 2 "ragged.txt:2:1: expected 2 number(s) on this line like line 1" check --map m.grid --path ragged.txt
printf '0 0\n1.5 0\n' > frac.txt
expect_exit 2 "frac.txt:2:1: expected an integer of magnitude at most 2147483648 (a cell coordinate or node number), got '1.5'" check --map m.grid --path frac.txt
printf '0 0 1\n1 0 1\n' > three.txt
expect_exit 2 "three.txt:1:1: 3 numbers per line: expected two (x y) or one (a node number)" check --map m.grid --path three.txt
expect_exit 2 "node.txt:2:1: expected two numbers (row col) on this line, got 1" check --map m.grid --path node.txt --path-format rowcol
printf '[[0,0],[1,0]' > broken.json
expect_exit 2 "broken.json:1:1" check --map m.grid --path broken.json
printf '{"path": [[0,0]]}' > obj.json
expect_exit 2 "a JSON object must be a pathref-plan record" check --map m.grid --path obj.json
printf '# nothing\n' > empty.txt
expect_exit 2 "empty.txt:1:1: no path" check --map m.grid --path empty.txt
expect_exit 2 "give the map: --map FILE or --builtin NAME" check --path xy.txt
expect_exit 2 "cannot read path file 'missing.txt'" check --map m.grid --path missing.txt
expect_exit 2 "--base expects 0 or 1, got '2'" check --map m.grid --path xy.txt --base 2
mkdir none
expect_exit 2 "--path: the folder 'none' has no file" check --map m.grid --path none
echo "check: ok"
