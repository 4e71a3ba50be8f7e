#!/usr/bin/env bash
# `pathref drive`: the time to drive a grid path with a Mecanum or differential-drive base
# (spec/mecanum.md, rule drive.path-time and section "CLI"). Checks: a straight axis-parallel path
# costs the same on both bases; hand-computed totals; text and JSON path files and stdin JSON
# (from `pathref plan --json` when that command exists); the SVG speed profile; exit 1 for a plan
# without a path and exit 2 for bad arguments or input.
# Usage: bash tests/cli/drive.sh path/to/pathref
set -euo pipefail
pathref=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

fail() { echo "FAIL: $*"; exit 1; }
# total TIME-LINE-OF-REPORT: the "time: X s" line of a report.
total() { grep -E '^time: ' "$1" || fail "no 'time:' line in $1"; }

# --- a straight path: equal times on both bases -------------------------------------------------
printf '# five cells east\n0 0\n1 0\n2 0\n3 0\n4 0\n' >"$tmp/straight.txt"
"$pathref" drive --path "$tmp/straight.txt" --base mecanum --cell 0.5 >"$tmp/m.txt"
"$pathref" drive --path "$tmp/straight.txt" --base diff --cell 0.5 >"$tmp/d.txt"
[ "$(total "$tmp/m.txt")" = "$(total "$tmp/d.txt")" ] || fail "straight path: $(total "$tmp/m.txt") vs $(total "$tmp/d.txt")"
grep -qx 'turns: 0' "$tmp/m.txt" || fail "straight path has turns"
# Hand value: r*w_max = 1 m/s (w_max = 20 rad/s = 190.98593171027440 rpm), a = 1: 3 m -> 3/1 + 1/1 = 4 s.
printf '0,0\n1,0\n2,0\n3,0\n' >"$tmp/three.txt"
for base in mecanum diff; do
  "$pathref" drive --path "$tmp/three.txt" --base "$base" --cell 1 --rpm 190.9859317102744 >"$tmp/h.txt"
  grep -qx 'time: 4.000000 s' "$tmp/h.txt" || { cat "$tmp/h.txt"; fail "3 m at 1 m/s, a = 1 on $base: expected 4 s"; }
done

# --- an L path: the diff base pays a rotation, the Mecanum base does not ------------------------
printf '[[0,0],[1,0],[2,0],[2,1],[2,2]]\n' >"$tmp/l.json"
"$pathref" drive --path "$tmp/l.json" --base mecanum --cell 1 --rpm 190.9859317102744 --json >"$tmp/lm.json"
"$pathref" drive --path "$tmp/l.json" --base diff --cell 1 --rpm 190.9859317102744 --half-track 0.1 --json >"$tmp/ld.json"
python3 - "$tmp/lm.json" "$tmp/ld.json" <<'PY'
import json, math, sys
m, d = (json.load(open(p)) for p in sys.argv[1:3])
assert m["format"] == "pathref-drive" and m["base"] == "mecanum" and d["base"] == "diff"
assert m["turns"] == 1 and d["turns"] == 1
assert abs(m["time"] - 6.0) < 1e-9, m["time"]                       # 2 runs of 2 m: 3 s each
rot = 2.0 * math.sqrt((math.pi / 2) / 10.0)                          # Omega = A = 10: triangle
assert abs(d["time"] - (6.0 + rot)) < 1e-9, d["time"]
assert abs(d["rotate_time"] - rot) < 1e-9
assert len(m["schedule"][0]["wheel_rpm"]) == 4 and len(d["schedule"][0]["wheel_rpm"]) == 2
assert m["schedule"][-1]["t"] == m["time"]
PY

# --- the speed profile SVG ----------------------------------------------------------------------
"$pathref" drive --path "$tmp/l.json" --base diff --cell 1 --svg "$tmp/p.svg" >/dev/null
python3 - "$tmp/p.svg" <<'PY'
import sys
import xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
assert root.tag.endswith("svg"), root.tag
text = open(sys.argv[1]).read()
assert "body speed [m/s]" in text and "yaw rate [rad/s]" in text
PY

# --- stdin: a pathref plan JSON object -----------------------------------------------------------
echo '{"found": true, "path": [[0,0],[1,1],[2,2]]}' | "$pathref" drive --base mecanum --cell 1 >"$tmp/s.txt"
grep -qx 'turns: 0' "$tmp/s.txt" || fail "stdin JSON"
if "$pathref" plan --help >/dev/null 2>&1 && "$pathref" plan --builtin grid20 --algo astar --json >"$tmp/plan.json" 2>/dev/null; then
  "$pathref" drive --base mecanum --cell 1 <"$tmp/plan.json" >"$tmp/pm.txt"
  "$pathref" drive --base diff --cell 1 --json <"$tmp/plan.json" >"$tmp/pd.json"
  python3 - "$tmp/plan.json" "$tmp/pm.txt" "$tmp/pd.json" <<'PY'
import json, sys
plan = json.load(open(sys.argv[1]))
report = open(sys.argv[2]).read()
d = json.load(open(sys.argv[3]))
assert f"turns: {d['turns']}" in report
assert abs(d["distance"] - plan["length"]) < 1e-9, (d["distance"], plan["length"])
assert d["cells"] == len(plan["path"])
PY
fi

# --- exit codes ----------------------------------------------------------------------------------
expect() {  # expect CODE ARGS...: pathref ARGS exits with CODE
  local code=$1; shift
  set +e; "$pathref" "$@" >"$tmp/out" 2>&1 </dev/null; local rc=$?; set -e
  [ "$rc" = "$code" ] || { cat "$tmp/out"; fail "pathref $* exited $rc, expected $code"; }
}
expect 2 drive --path "$tmp/straight.txt" --base tank --cell 1        # unknown base
expect 2 drive --path "$tmp/straight.txt" --cell 1                    # --base missing
expect 2 drive --path "$tmp/straight.txt" --base diff                 # --cell missing
expect 2 drive --path "$tmp/straight.txt" --base diff --cell 0        # DomainError
expect 2 drive --path "$tmp/straight.txt" --base diff --cell 1 --accel -1
expect 2 drive --path "$tmp/straight.txt" --base diff --cell 1 --limit-at motor
expect 2 drive --path "$tmp/missing.txt" --base diff --cell 1         # cannot open
expect 2 drive --base diff --cell 1                                   # empty stdin
printf '0 0\n2 0\n' >"$tmp/jump.txt"
expect 2 drive --path "$tmp/jump.txt" --base mecanum --cell 1         # not an 8-neighbour step
printf '0 0\n1 zero\n' >"$tmp/bad.txt"
expect 2 drive --path "$tmp/bad.txt" --base mecanum --cell 1          # ParseError
grep -q 'bad.txt:2:' "$tmp/out" || fail "ParseError names file and line"
printf '{"path": [[0,0],' >"$tmp/trunc.json"
expect 2 drive --path "$tmp/trunc.json" --base mecanum --cell 1       # invalid JSON
echo '{"found": false, "path": []}' >"$tmp/none.json"
expect 1 drive --path "$tmp/none.json" --base mecanum --cell 1        # the plan found no path
echo "drive: ok"
