#!/usr/bin/env bash
# `pathref plan --algo astar-kinematic` (spec/sensors2023.md r[sensors2023.plan.astar-kinematic]):
# the report names every parameter and the counts; --json carries the key nodes, the sampled
# curve (spacing selectable), turns, expansions, child nodes and the curve's clearance; --svg
# draws the grid, the A* path, the key nodes and the curve. Bad parameters exit 2.
# Usage: bash tests/cli/plan_kinematic.sh path/to/pathref
set -euo pipefail
pathref=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

"$pathref" plan --builtin grid20 --algo astar-kinematic >"$tmp/report.txt"
for word in "algo        astar-kinematic" "directions=5" "weight=linear" "redundancy=secondary" \
            "spacing=0.1" "end=repeated" "child_nodes" "turns_key" "points: see --json"; do
  grep -qF -- "$word" "$tmp/report.txt" || { echo "FAIL: report lacks '$word'"; cat "$tmp/report.txt"; exit 1; }
done

"$pathref" plan --builtin grid20 --algo astar-kinematic --set spacing=0.25 --json --svg "$tmp/k.svg" >"$tmp/k.json"
python3 - "$tmp/k.json" "$tmp/k.svg" <<'PY'
import json, math, sys
import xml.etree.ElementTree as ET
d = json.load(open(sys.argv[1]))
assert d["algo"] == "astar-kinematic" and d["found"] is True and d["valid"] is True, d["validation"]
assert d["params"]["spacing"] == 0.25 and d["params"]["directions"] == 5, d["params"]
e = d["extra"]
for k in ("expansions", "generated", "child_nodes", "turns_raw", "turns_key", "key_nodes", "key_length", "curve"):
    assert k in e, k
assert e["expansions"] == d["expansions"] and e["child_nodes"] <= e["generated"]
keys = e["key_nodes"]
assert keys[0] == d["start"] and keys[-1] == d["goal"], keys
assert all(k in d["path"] for k in keys), "key nodes must lie on the A* path"
c = e["curve"]
assert c["degree"] == 3 and c["end"] == "repeated" and c["spacing"] == 0.25 and c["chord"] <= 0.25
pts = c["points"]
assert len(pts) == c["samples"] >= 2
assert abs(pts[0][0] - (d["start"][0] + 0.5)) < 1e-12 and abs(pts[-1][1] - (d["goal"][1] + 0.5)) < 1e-12
for a, b in zip(pts, pts[1:]):
    assert math.dist(a, b) <= c["chord"] * (1 + 1e-12) + 1e-12
assert c["clearance"]["verdict"] in ("clear", "enters", "undetermined")
assert c["clearance"]["lower"] <= c["clearance"]["upper"]
root = ET.parse(sys.argv[2]).getroot()
ns = "{http://www.w3.org/2000/svg}"
lines = root.findall(f".//{ns}polyline[@class='path']")
assert len(lines) == 3, f"expected A* path, key nodes and curve, got {len(lines)}"
assert len(root.findall(f".//{ns}circle[@class='marker']")) == len(keys)
assert len(root.findall(f".//{ns}rect[@class='obstacle']")) == d["map"]["blocked"]
w, h = float(root.get("width")), float(root.get("height"))
for pl in lines:
    for xy in pl.get("points").split():
        x, y = map(float, xy.split(","))
        assert 0 <= x <= w and 0 <= y <= h, "curve outside the canvas"
PY

# ablation: plain A* settings give astar's path with the Euclidean heuristic
"$pathref" plan --builtin grid20 --algo astar-kinematic --set directions=8 --set weight=none \
  --set redundancy=none --json >"$tmp/plain.json"
"$pathref" plan --builtin grid20 --algo astar --set heuristic=euclidean --json >"$tmp/astar.json"
python3 - "$tmp/plain.json" "$tmp/astar.json" <<'PY'
import json, sys
a, b = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert a["path"] == b["path"] and a["expansions"] == b["expansions"], "plain settings must equal astar"
PY

# bad values are usage/domain errors: exit 2
for bad in "directions=6" "weight=square" "spacing=0" "k=0" "end=open" "safety=maybe"; do
  set +e; "$pathref" plan --builtin grid20 --algo astar-kinematic --set "$bad" >/dev/null 2>"$tmp/err"; rc=$?; set -e
  [ "$rc" = 2 ] || { echo "FAIL: --set $bad gave exit $rc, expected 2"; cat "$tmp/err"; exit 1; }
done
echo "plan_kinematic: ok"
