#!/usr/bin/env bash
# `pathref simulate`: Han's dynamic-obstacle simulation (spec/han-sim.md, han.sim.run, section CLI).
# Checks: the three scripted encounters (none, side, frontal) with their hand-computed key numbers
# in the text report and the JSON; the SVG; --planner; exit 1 when a collision happens; exit 2 with
# a JSON-pointer message for bad scenario files.
# Usage: bash tests/cli/simulate.sh path/to/pathref
set -euo pipefail
pathref=$1
data=tests/data/sim
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# --- none: the global path at the ramp-cruise time 1 + (9 - 0.5) = 9.5 s -----------------------
"$pathref" simulate "$data/none.json" >"$tmp/none.txt" || fail "none: exit $?"
grep -qx 'time: 9.500000 s' "$tmp/none.txt" || { cat "$tmp/none.txt"; fail "none: time"; }
grep -qx 'waits: 0 (0.000000 s)' "$tmp/none.txt" || fail "none: waits"
grep -qx 'collisions: 0 (0 outside the guarantee)' "$tmp/none.txt" || fail "none: collisions"

# --- side: wait 4.75 s -> 9.375 s, arrival 16.625 s ---------------------------------------------
"$pathref" simulate "$data/side.json" >"$tmp/side.txt"
grep -qx 'wait: 4.750000 s to 9.375000 s (4.625000 s)' "$tmp/side.txt" || { cat "$tmp/side.txt"; fail "side: wait"; }
grep -qx 'time: 16.625000 s' "$tmp/side.txt" || fail "side: time"

# --- frontal: one replan at 4.125 s to the local target (11, 2); JSON and SVG -------------------
"$pathref" simulate "$data/frontal.json" --json --full --svg "$tmp/f.svg" >"$tmp/f.json"
python3 - "$tmp/f.json" "$tmp/f.svg" <<'PY'
import json, sys
import xml.etree.ElementTree as ET
r = json.load(open(sys.argv[1]))
assert r["format"] == "pathref-sim-result"
assert r["reached_goal"] and not r["collided"], r
assert len(r["replans"]) == 1 and r["replans"][0]["t"] == 4.125 and r["replans"][0]["target"] == [11, 2]
assert r["waits"] == []
assert r["trajectory"][-1][4] == "arrive" and r["trajectory"][-1][0] == r["time"]
assert len(r["obstacle_tracks"]) == 1 and len(r["obstacle_tracks"][0]) == len(r["trajectory"])
svg = ET.parse(sys.argv[2]).getroot()
ns = "{http://www.w3.org/2000/svg}"
classes = [e.get("class") for e in svg.iter(ns + "polyline")]
assert "trajectory" in classes and "obstacle-track" in classes and "detour" in classes and "global-path" in classes, classes
PY

# --- --planner: the global path from a registered planner ---------------------------------------
"$pathref" simulate "$data/frontal.json" --planner astar >"$tmp/p.txt"
grep -q '^global path: 12 cells, 11.000000 m (astar)$' "$tmp/p.txt" || { cat "$tmp/p.txt"; fail "--planner astar"; }

# --- the Fig. 8 demo: one side wait (O1) and one frontal replan (O2), no collision ----------------
"$pathref" simulate "$data/fig8.json" >"$tmp/fig8.txt" || fail "fig8: exit $?"
grep -qx 'waits: 1 (5.375000 s)' "$tmp/fig8.txt" || { cat "$tmp/fig8.txt"; fail "fig8: waits"; }
grep -qx 'replans: 1' "$tmp/fig8.txt" || fail "fig8: replans"

# --- a collision is exit 1 ----------------------------------------------------------------------
python3 - "$data/frontal.json" "$tmp/blind.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1])); d["horizon"] = 0.0625; d["margin"] = 0
json.dump(d, open(sys.argv[2], "w"))
PY
set +e; "$pathref" simulate "$tmp/blind.json" >"$tmp/blind.txt"; rc=$?; set -e
[ "$rc" = 1 ] || fail "a collision must exit 1, got $rc"
grep -q '^collisions: [1-9]' "$tmp/blind.txt" || fail "collision not reported"

# --- overtaking from behind: an evasion, no collision; a dead end: collisions outside the guarantee
"$pathref" simulate "$data/overtake.json" >"$tmp/ov.txt" || { cat "$tmp/ov.txt"; fail "overtake: exit $?"; }
grep -qx 'collisions: 0 (0 outside the guarantee)' "$tmp/ov.txt" || fail "overtake: collisions"
grep -q '^evade: t = 0.125000 s from (0, 4) to refuge (0, 2)' "$tmp/ov.txt" || { cat "$tmp/ov.txt"; fail "overtake: evade"; }
set +e; "$pathref" simulate "$data/deadend.json" >"$tmp/de.txt"; rc=$?; set -e
[ "$rc" = 1 ] || fail "deadend: a collision must exit 1, got $rc"
python3 - "$tmp/de.txt" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
m = re.search(r"^collisions: (\d+) \((\d+) outside the guarantee\)$", text, re.M)
assert m and int(m.group(1)) > 0 and m.group(1) == m.group(2), text[:400]
assert re.search(r"^unavoidable: t = [0-9.]+ s with O1 \(trapped\)$", text, re.M), text[:400]
PY

# --- iaco-astar: the global planner's parameters as iaco-han.<name>, printed and in the JSON -----
"$pathref" plan --builtin shi6x6 --algo iaco-astar --set iaco-han.dead_end=die --set iaco-han.ants=5 \
  --set iaco-han.iterations=3 --json >"$tmp/ia.json" || fail "iaco-astar --set iaco-han.*"
python3 - "$tmp/ia.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
p = d["params"]
assert p["global"] == "iaco-han" and p["iaco-han.dead_end"] == "die" and p["iaco-han.ants"] == 5, p
assert p["iaco-han.eta"] == "goal_directed", p
PY
"$pathref" plan --builtin shi6x6 --algo iaco-astar --set iaco-han.ants=5 --set iaco-han.iterations=3 >"$tmp/ia.txt"
grep -q 'params .*global=iaco-han.*iaco-han.ants=5' "$tmp/ia.txt" || { cat "$tmp/ia.txt"; fail "iaco-astar params printed"; }
set +e; "$pathref" plan --builtin shi6x6 --algo iaco-astar --set dead_end=die 2>"$tmp/err.txt" >/dev/null; rc=$?; set -e
[ "$rc" = 2 ] || fail "iaco-astar: an unprefixed parameter must exit 2, got $rc"

# --- bad input: exit 2 with a JSON pointer --------------------------------------------------------
expect_error() {  # FILE-CONTENT PATTERN
  printf '%s' "$1" >"$tmp/bad.json"
  set +e; "$pathref" simulate "$tmp/bad.json" 2>"$tmp/err.txt" >/dev/null; rc=$?; set -e
  [ "$rc" = 2 ] || fail "expected exit 2 for $1, got $rc"
  grep -q -- "$2" "$tmp/err.txt" || { cat "$tmp/err.txt"; fail "expected '$2'"; }
}
expect_error '{"format": "pathref-sim 1", "map": ["...."], "start": [0,0], "goal": [3,0], "obstacles": [{"position": [1, 2]}]}' \
  '/obstacles/0/velocity: missing'
expect_error '{"format": "pathref-sim 1", "map": ["...."], "start": [0,0], "goal": [3,0], "dt": "fast"}' \
  '/dt: expected a number'
expect_error '{"format": "pathref-sim 1", "map": ["..#."], "start": [0,0], "goal": [2,0]}' \
  '/goal: on a blocked cell'
expect_error '{"format": "pathref-sim 1", "map": [' 'bad.json:1:'
expect_error '{"format": "pathref-sim 1", "map": ["...."], "start": [0,0], "goal": [3,0], "planner": "nope"}' \
  'bad.json:1:88: /planner: expected a planner name (.*astar.*), got "nope"'
# issue 27: the path, the planner and its parameters at their pointers, with line and column
expect_error '{"format": "pathref-sim 1", "map": ["...."], "start": [0,0], "goal": [3,0], "path": [[0,0], [2,0], [3,0]]}' \
  'bad.json:1:93: /path/1: expected a free cell one step from (0, 0) allowed under the corner policy strict, got (2, 0)'
expect_error '{"format": "pathref-sim 1", "map": ["...."], "start": [0,0], "goal": [3,0], "planner": {"name": "astar", "params": {"weight": 2}}}' \
  "bad.json:1:[0-9]*: /planner/params/weight: expected a parameter of astar: unknown parameter 'weight' (known: heuristic)"
expect_error '{"format": "pathref-sim 1", "map": ["...."], "start": [0,0], "goal": [3,0], "planner": {"name": "iaco-han", "params": {"ants": -3}}}' \
  'bad.json:1:[0-9]*: /planner/params: the planner iaco-han refused its parameters: ant colony: ants must be in'
expect_error '{"format": "pathref-sim 1", "map": ["...."], "start": [0,0], "goal": [3,0], "planner": {"name": "astarr"}}' \
  '/planner/name: expected a planner name'
set +e; "$pathref" simulate --planner nope tests/data/sim/none.json 2>"$tmp/err.txt" >/dev/null; rc=$?; set -e
[ "$rc" = 2 ] || fail "--planner nope must exit 2, got $rc"
grep -q -- "--planner expects a planner name (.*), got 'nope'" "$tmp/err.txt" || { cat "$tmp/err.txt"; fail "--planner message"; }
# a polygon scene as the map file: what to do instead, no internal API name
cp tests/data/scenes/ushape.json "$tmp/scene.json"
expect_error '{"format": "pathref-sim 1", "map": "scene.json", "start": [0,0], "goal": [3,0]}' \
  "is a polygon scene (pathref-scene 1), which cannot be read as a grid map here: inflate it into one first (pathref inflate .*scene.json -o MAP.grid)"
grep -q "MapReadOptions" "$tmp/err.txt" && fail "internal API name in: $(cat "$tmp/err.txt")"
set +e; "$pathref" simulate "$tmp/missing.json" 2>/dev/null; rc=$?; set -e
[ "$rc" = 2 ] || fail "missing file must exit 2, got $rc"
echo "simulate: ok"
