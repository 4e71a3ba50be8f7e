#!/usr/bin/env bash
# `pathref plan --algo rrt | s-rrt` (spec/cli.md#plan-continuous, spec/cin2021-srrt.md): scenes
# planned exactly, grid maps as unit squares, world-coordinate endpoints, plan JSON version 2,
# the SVG layers, and the usage errors that keep grid notions out of the continuous planners.
# Usage: bash tests/cli/plan_continuous.sh path/to/pathref   (from the repository root)
set -euo pipefail
pathref=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

expect_exit() {
  local want=$1 msg=$2; shift 2
  set +e; "$pathref" "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?; set -e
  if [ "$got" != "$want" ]; then
    echo "FAIL: pathref $* exited $got, expected $want"; cat "$tmp/out" "$tmp/err"; exit 1
  fi
  [ -z "$msg" ] || grep -qF -- "$msg" "$tmp/err" || { echo "FAIL: pathref $*: stderr lacks '$msg':"; cat "$tmp/err"; exit 1; }
}

s=tests/data/scenes/srrt_walls.json
# s-rrt on a scene: JSON v2 with tree, raw and shortcut paths; SVG with every layer.
expect_exit 0 "" plan --map "$s" --algo s-rrt --seed 3 --json --json-out "$tmp/a.json" --svg "$tmp/a.svg"
cmp -s "$tmp/out" "$tmp/a.json" || { echo "FAIL: --json and --json-out differ"; exit 1; }
python3 - "$tmp/a.json" <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
assert d["format"] == "pathref-plan" and d["format_version"] == 2 and d["space"] == "continuous", d.keys()
for k in ("path", "valid", "policy", "start", "goal"):
    assert k not in d, k  # no grid field is reused
assert d["found"] and d["start_xy"] == [1.5, 1.5] and d["goal_xy"] == [18.5, 18.5]
assert d["raw_path"][0] == d["start_xy"] and d["raw_path"][-1] == d["goal_xy"]
assert d["shortcut_path"][0] == d["start_xy"] and d["shortcut_path"][-1] == d["goal_xy"]
assert d["shortcut"]["length"] <= d["raw"]["length"] and d["shortcut"]["nodes"] <= d["raw"]["nodes"]
assert d["raw"]["clearance"] > 0.3 - 1e-12  # every edge keeps more than r = 0.3
assert d["tree_size"] == len(d["tree"]["nodes"]) == len(d["tree"]["parent"])
assert d["params"]["delta"] == 1.7 and d["params"]["goal_probability"] == 0.6 and d["params"]["bias"] == "lt"
assert d["map"]["kind"] == "scene" and d["map"]["radius"] == "0.2" and d["map"]["margin"] == "0.1"
# the clamped B-spline of Eq. 12-15 over the kept nodes (spec r[cin2021.srrt.curve])
c = d["curve"]
assert d["params"]["degree"] == 3 and d["params"]["knots"] == "uniform" and d["params"]["repair"] is False
assert c["end"] == "clamped" and c["degree"] == min(3, len(d["shortcut_path"]) - 1)
assert c["control"] == d["shortcut_path"] and c["kept"] == d["shortcut_kept"] and c["repair"] == "off"
assert c["samples"][0] == d["start_xy"] and c["samples"][-1] == d["goal_xy"]
assert len(c["samples"]) == len(c["params"]) and 0 < c["chord"] <= d["params"]["spacing"]
assert len(c["knots"]) == len(c["control"]) + c["degree"] + 1
assert abs(c["clearance"]["inflation"] - 0.3) < 1e-15
assert c["clearance"]["lower"] <= c["clearance"]["distance"] <= c["clearance"]["upper"]
assert c["clearance"]["verdict"] in ("clear", "enters", "undetermined")
assert c["max_curvature"] is None or c["max_curvature"] >= 0
assert c["length"] <= d["shortcut"]["length"] + 1e-9  # a clamped B-spline is no longer than its control polygon
PY
for layer in 'class="obstacle"' 'class="tree"' 'class="raw-path"' 'class="shortcut-path"' 'class="curve"' 'class="start"' 'class="goal"' 'class="legend"'; do
  grep -q "$layer" "$tmp/a.svg" || { echo "FAIL: SVG lacks $layer"; exit 1; }
done
# The same seed gives the same run (time_ms aside).
"$pathref" plan --map "$s" --algo s-rrt --seed 3 --json >"$tmp/b.json"
python3 -c "
import json,sys
a,b=(json.load(open(p)) for p in sys.argv[1:3])
for d in (a, b): d.pop('time_ms'); d['curve'].pop('time_ms')
assert a==b" "$tmp/a.json" "$tmp/b.json"
# The repair (off by default) and the curve parameters; smooth=false drops the curve.
expect_exit 0 "" plan --map "$s" --algo s-rrt --seed 3 --set repair=true --set knots=chord --set degree=2 --json
python3 -c "
import json,sys
d=json.load(open(sys.argv[1])); c=d['curve']
assert c['repair'] in ('clear','stuck') and c['degree'] <= 2 and d['params']['knots']=='chord'
assert (c['repair']=='clear') == (c['clearance']['verdict']=='clear')
assert sorted(c['kept']) == c['kept'] and set(d['shortcut_kept']) <= set(c['kept'])" "$tmp/out"
expect_exit 0 "" plan --map "$s" --algo s-rrt --seed 3 --set smooth=false --json
python3 -c "import json,sys; assert json.load(open(sys.argv[1]))['curve'] is None" "$tmp/out"
expect_exit 0 "" plan --map "$s" --algo s-rrt --seed 3
grep -q '^  curve       degree' "$tmp/out" || { echo "FAIL: text report lacks the curve"; cat "$tmp/out"; exit 1; }
# Text report: seed, every parameter, world coordinates.
expect_exit 0 "" plan --map "$s" --algo rrt --start-xy 1.25,2 --goal-xy 19,19.5 --set variant=ompl
grep -q '^  start       (1.25, 2)' "$tmp/out" || { echo "FAIL: start"; cat "$tmp/out"; exit 1; }
grep -q 'variant=ompl' "$tmp/out" || { echo "FAIL: params"; cat "$tmp/out"; exit 1; }
grep -q '^  seed        1' "$tmp/out" || { echo "FAIL: seed"; cat "$tmp/out"; exit 1; }
# --start X,Y is a cell: its centre.
expect_exit 0 "" plan --map "$s" --algo rrt --start 2,1 --json
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['start_xy']==[2.5,1.5], d['start_xy']" "$tmp/out"
# Grid maps: blocked cells as unit squares.
expect_exit 0 "" plan --builtin grid20 --algo s-rrt --json
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['map']['kind']=='grid' and d['found'], d['map']" "$tmp/out"
# Not found within max_iterations: exit 1.
expect_exit 1 "" plan --map "$s" --algo rrt --set max_iterations=3
# Errors.
expect_exit 2 "--policy is a grid notion" plan --map "$s" --algo rrt --policy never
expect_exit 2 "give at most one of --start" plan --map "$s" --algo rrt --start 1,1 --start-xy 1,1
expect_exit 2 "--start-xy expects X,Y" plan --map "$s" --algo rrt --start-xy 1
expect_exit 2 "--start-xy is for the continuous planners" plan --map "$s" --algo astar --start-xy 1,1
expect_exit 2 "is not free" plan --map "$s" --algo rrt --start-xy 6,6
expect_exit 2 "is not free" plan --map "$s" --algo rrt --goal-xy 25,1
expect_exit 2 "same point" plan --map "$s" --algo rrt --start-xy 2,2 --goal-xy 2,2
expect_exit 2 "bias must be one of lt, gt" plan --map "$s" --algo rrt --set bias=le
expect_exit 2 "unknown parameter" plan --map "$s" --algo rrt --set shortcut=false
expect_exit 2 "delta must be > 0" plan --map "$s" --algo rrt --set delta=0
expect_exit 2 "unknown parameter" plan --map "$s" --algo rrt --set repair=true
expect_exit 2 "knots must be uniform or chord" plan --map "$s" --algo s-rrt --set knots=centripetal
expect_exit 2 "degree must be in" plan --map "$s" --algo s-rrt --set degree=0
expect_exit 2 "spacing must be finite and > 0" plan --map "$s" --algo s-rrt --set spacing=0
echo "plan_continuous: ok"
