#!/usr/bin/env bash
# `pathref plan --json` prints one pathref-plan v1 object (spec/cli.md#plan-json); --json-out
# writes the same object; --svg writes the figure (checked by structure).
# Usage: bash tests/cli/plan_json.sh path/to/pathref
set -euo pipefail
pathref=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

"$pathref" plan --builtin grid20 --algo astar --json --json-out "$tmp/out.json" --svg "$tmp/out.svg" >"$tmp/stdout.json"
cmp "$tmp/stdout.json" "$tmp/out.json" || { echo "FAIL: --json and --json-out differ"; exit 1; }

python3 - "$tmp/stdout.json" "$tmp/out.svg" <<'PY'
import json, math, sys
import xml.etree.ElementTree as ET

d = json.load(open(sys.argv[1]))
required = ["format", "format_version", "pathref_version", "golden_set_version", "algo", "seed", "policy", "params",
            "map", "found", "start", "goal", "path", "length", "turns", "valid", "validation",
            "expansions", "iterations", "best_per_iteration", "mean_per_iteration",
            "converged_at", "extra"]
missing = [k for k in required if k not in d]
assert not missing, f"missing fields {missing}"
assert set(d) == set(required), f"unexpected fields {set(d) - set(required)}"
assert d["format"] == "pathref-plan" and d["format_version"] == 1
assert d["algo"] == "astar" and d["seed"] == 1 and d["policy"] == "strict", d
assert d["params"] == {"heuristic": "octile"}, d["params"]
m = d["map"]
assert m["source"] == "builtin" and m["name"] == "grid20" and m["file"] is None, m
assert (m["width"], m["height"], m["blocked"]) == (20, 20, 92), m
assert len(m["rows"]) == 20 and all(len(r) == 20 for r in m["rows"])
assert sum(r.count("#") for r in m["rows"]) == 92
assert d["start"] == [0, 0] and d["goal"] == [19, 19]
assert d["found"] is True and d["valid"] is True and d["validation"] == "ok"
p = d["path"]
assert p[0] == d["start"] and p[-1] == d["goal"], (p[0], p[-1])

def free(x, y):
    return 0 <= x < 20 and 0 <= y < 20 and m["rows"][19 - y][x] == "."

length = 0.0
for (x0, y0), (x1, y1) in zip(p, p[1:]):
    dx, dy = x1 - x0, y1 - y0
    assert max(abs(dx), abs(dy)) == 1, ("not a step", (x0, y0), (x1, y1))
    assert free(x1, y1), ("blocked cell on path", x1, y1)
    if dx and dy:  # strict: both orthogonal neighbours free
        assert free(x0 + dx, y0) and free(x0, y0 + dy), ("corner cut", (x0, y0), (x1, y1))
    length += math.sqrt(2) if dx and dy else 1.0
assert abs(length - d["length"]) < 1e-9, (length, d["length"])
# strict shortest on grid20 is 46 + 3*sqrt(2) (spec/cli.md#builtin-maps)
assert abs(d["length"] - (46 + 3 * math.sqrt(2))) < 1e-9, d["length"]
turns = 0
for a, b, c in zip(p, p[1:], p[2:]):
    if (b[0] - a[0], b[1] - a[1]) != (c[0] - b[0], c[1] - b[1]):
        turns += 1
assert d["turns"] == turns, (d["turns"], turns)
assert isinstance(d["expansions"], int) and d["expansions"] > 0
assert d["iterations"] == 0 and d["best_per_iteration"] == [] and d["converged_at"] is None

# SVG: well-formed, one obstacle rect per blocked cell, one path polyline with as many points as
# path cells, S and T markers, the legend naming the algorithm.
ns = "{http://www.w3.org/2000/svg}"
root = ET.parse(sys.argv[2]).getroot()
assert root.tag == ns + "svg", root.tag
def cls(tag, c):
    return [e for e in root.iter(ns + tag) if e.get("class") == c]
assert len(cls("rect", "obstacle")) == 92, len(cls("rect", "obstacle"))
lines = cls("polyline", "path")
assert len(lines) == 1 and len(lines[0].get("points").split()) == len(p)
assert len(cls("g", "start")) == 1 and len(cls("g", "goal")) == 1
legend = cls("g", "legend")
assert len(legend) == 1
legend_text = " ".join(t.text or "" for t in legend[0].iter(ns + "text"))
assert "astar (length 50.24" in legend_text and "start S" in legend_text and "goal T" in legend_text, legend_text
title = cls("text", "title")[0].text
assert "grid20" in title and "strict" in title and "seed 1" in title, title
# The path is drawn through cell centres, (0,0) at the lower left: check first and last point.
mp = cls("rect", "map")[0]
mx, my, s = float(mp.get("x")), float(mp.get("y")), float(mp.get("width")) / 20
pts = [tuple(map(float, q.split(","))) for q in lines[0].get("points").split()]
for (x, y), (px, py) in [(p[0], pts[0]), (p[-1], pts[-1])]:
    assert abs(px - (mx + (x + 0.5) * s)) < 0.01 and abs(py - (my + (19 - y + 0.5) * s)) < 0.01, (x, y, px, py)
PY

# Leading zeros are decimal (not octal); the extremes of the seed range are accepted.
for s in 010:10 0:0 4294967295:4294967295; do
  "$pathref" plan --builtin shi6x6 --algo astar --json --seed "${s%%:*}" >"$tmp/s.json"
  python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["seed"] == int(sys.argv[2]), d["seed"]' "$tmp/s.json" "${s##*:}"
done

# Options are reflected in the JSON: seed, policy, parameters, start and goal.
"$pathref" plan --builtin shi6x6 --algo astar --json --seed 77 --policy one --set heuristic=chebyshev \
  --start 0,1 --goal 4,5 >"$tmp/b.json"
python3 - "$tmp/b.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["seed"] == 77 and d["policy"] == "one" and d["params"] == {"heuristic": "chebyshev"}, d
assert d["start"] == [0, 1] and d["goal"] == [4, 5] and d["path"][0] == [0, 1] and d["path"][-1] == [4, 5]
assert d["map"]["name"] == "shi6x6" and d["map"]["width"] == 6
PY
echo "plan_json: ok"
