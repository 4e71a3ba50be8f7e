#!/usr/bin/env bash
# `pathref reproduce cin2021-srrt` (spec/reproduce.md r[reproduce.cin2021-srrt.scenes],
# r[reproduce.cin2021-srrt.protocol]): bad input is exit 2 with a clear message; a run with 2 runs
# per series writes the report, its JSON, the scene files and the figures; the JSON holds every
# scene, series, run, claim, alternative and check; the report's results cells and claim verdicts
# are the JSON's; every drawn point and text of the figures lies on its canvas; a scene file
# replays run 0 of S-RRT with `pathref plan`. A few seconds.
# Usage: bash tests/cli/reproduce_cin2021_srrt.sh path/to/pathref   (from the repository root)
set -euo pipefail
pathref=$(realpath "$1")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

expect_exit() {
  local want=$1 msg=$2; shift 2
  set +e; "$pathref" "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?; set -e
  if [ "$got" != "$want" ]; then
    echo "FAIL: pathref $* exited $got, expected $want"; cat "$tmp/out" "$tmp/err"; exit 1
  fi
  [ -z "$msg" ] || grep -qF -- "$msg" "$tmp/err" || { echo "FAIL: pathref $*: stderr lacks '$msg':"; cat "$tmp/err"; exit 1; }
}

"$pathref" reproduce --help | grep -qF cin2021-srrt || { echo "FAIL: reproduce --help lacks cin2021-srrt"; exit 1; }
for w in --runs --seed --out-dir --quick; do
  "$pathref" reproduce cin2021-srrt --help | grep -qF -- "$w" || { echo "FAIL: --help lacks $w"; exit 1; }
done
expect_exit 2 "--runs expects a decimal integer from 2 to 1000, got '1'" reproduce cin2021-srrt --runs 1 --out-dir "$tmp/o"
expect_exit 2 "--runs expects a decimal integer from 2 to 1000, got 'x'" reproduce cin2021-srrt --runs x --out-dir "$tmp/o"
expect_exit 2 "--seed + 2 --runs - 1 must not exceed 4294967295" reproduce cin2021-srrt --runs 2 --seed 4294967294 --out-dir "$tmp/o"
[ ! -e "$tmp/o" ] || { echo "FAIL: a rejected command wrote $tmp/o"; exit 1; }

"$pathref" reproduce cin2021-srrt --runs 2 --seed 5 --out-dir "$tmp/r" >"$tmp/out" 2>"$tmp/err" || {
  echo "FAIL: reproduce cin2021-srrt"; cat "$tmp/out" "$tmp/err"; exit 1; }
for f in cin2021-srrt.md cin2021-srrt/reproduce.json cin2021-srrt/scene-A.json cin2021-srrt/scene-C.json \
         cin2021-srrt/A-s-rrt.svg cin2021-srrt/C-rrt.svg cin2021-srrt/length.svg cin2021-srrt/nodes.svg cin2021-srrt/time.svg; do
  [ -s "$tmp/r/$f" ] || { echo "FAIL: $f not written"; cat "$tmp/out" "$tmp/err"; exit 1; }
done
grep -qF "cin2021-srrt: 12 claims:" "$tmp/out" || { echo "FAIL: summary line"; cat "$tmp/out"; exit 1; }

python3 - "$tmp/r" <<'PY'
import glob, json, re, sys
import xml.etree.ElementTree as ET
root = sys.argv[1]
d = json.load(open(f"{root}/cin2021-srrt/reproduce.json"))
md = open(f"{root}/cin2021-srrt.md").read()
assert d["protocol"]["runs_n"] == 2 and d["protocol"]["runs_2n"] == 4 and d["protocol"]["seed"] == 5
assert d["protocol"]["delta"] == 1.7 and d["protocol"]["goal_probability"] == 0.6
assert [s["id"] for s in d["scenes"]] == ["A", "B", "C"]
series = ["s-rrt", "rrt", "rrt-alg1", "s-rrt@gt", "rrt-alg1@gt"]
for s in d["scenes"]:
    assert sorted(s["series"]) == sorted(series), s["series"].keys()
    for k in series:
        se = s["series"][k]
        runs = se["runs"]
        assert [r["seed"] for r in runs] == [5, 6, 7, 8], k
        p = se["params_used"]
        assert p["delta"] == 1.7 and p["goal_probability"] == 0.6, k
        assert p["variant"] == ("plain" if k == "rrt" else "paper"), k
        assert p["bias"] == ("gt" if k.endswith("@gt") else "lt"), k
        for r in runs:
            if r["found"]:
                assert r["valid"] and r["length"] > 0 and r["nodes"] >= 2, (k, r)
                if k.startswith("s-rrt"):
                    assert r["nodes"] <= r["raw_nodes"] and r["length"] <= r["raw_length"] * (1 + 1e-12), (k, r)
                    assert r["curve_verdict"] in ("clear", "enters", "undetermined")
                    assert r["curve_length"] <= r["length"] * (1 + 1e-9), (k, r)  # the curve cuts corners
    # S-RRT and Algorithm 1 alone grow the same trees (same seeds)
    for a, b in (("s-rrt", "rrt-alg1"), ("s-rrt@gt", "rrt-alg1@gt")):
        for x, y in zip(s["series"][a]["runs"], s["series"][b]["runs"]):
            assert (x["tree_size"], x["iterations"]) == (y["tree_size"], y["iterations"])
            if x["found"]:
                assert x["raw_length"] == y["length"] and x["raw_nodes"] == y["nodes"]
# claims: 3 scenes x 4 quantities; alternatives: 3 readings each + @nodes for length and smooth
assert len(d["claims"]) == 12, len(d["claims"])
assert len(d["reading_claims"]) == 3 * (4 * 3 + 2), len(d["reading_claims"])
alts = {c["id"]: c for c in d["reading_claims"]}
for c in d["claims"]:
    assert c["depends_on"] and "Mann" in c["rule"], c["id"]
    assert c["verdict"] in ("holds", "does not hold", "not significant", "cannot be tested"), c
    assert c["at_2n"] is not None, c["id"]
    for suf in ("@alg1", "@gt", "@alg1+gt"):
        assert c["id"] + suf in alts, c["id"] + suf
    assert (c["id"] + "@nodes" in alts) == (c["id"].split(".")[1] in ("length", "smooth")), c["id"]
    st = c["statistics"]["n"]
    assert st["kind"] == "comparison" and st["claim"] == "a_less"
    row = next(l for l in md.splitlines() if l.startswith(f"| {c['id']} †"))
    assert c["verdict_text"] in row, (c["id"], row)
assert [k["id"] for k in d["checks"]] == ["K.1", "K.2", "K.3"]
assert all(k["verdict"] == "holds" for k in d["checks"]), d["checks"]
# the results tables are the JSON's numbers
def fx(v, n):
    return "—" if v is None else f"{v:.{n}f}"
for s in d["scenes"]:
    block = md.split(f"<!-- results:{s['id']} -->")[1].split("\n\n")[0]
    for k in series:
        se = s["series"][k]
        sm = se["summary_n"]
        row = next(l for l in block.splitlines() if l.startswith(f"| {s['id']} | {se['label']} |"))
        cells = [x.strip() for x in row.strip("|").split("|")]
        assert cells[2] == f"{se['found_n']}/2 · {se['found_2n']}/4", cells
        m = sm["length"]
        if m["mean"] is not None:
            assert cells[3] == f"{fx(m['mean'],4)} ± {fx(m['std'],4)} [{fx(m['min'],4)}, {fx(m['max'],4)}]", (cells[3], m)
assert "rebuilt by pathref" in md and "QUICK RUN" in md
# every figure: points and text inside the canvas
for f in glob.glob(f"{root}/cin2021-srrt/*.svg"):
    t = ET.parse(f).getroot()
    w, h = float(t.get("width")), float(t.get("height"))
    parent = {c: p for p in t.iter() for c in p}
    def font_size(el):
        while el is not None:
            if el.get("font-size"):
                return float(el.get("font-size").rstrip("px"))
            el = parent.get(el)
        return 16.0
    for el in t.iter():
        tag = el.tag.split("}")[1]
        if tag == "polyline":
            for xy in el.get("points").split():
                x, y = map(float, xy.split(","))
                assert -1e-6 <= x <= w + 1e-6 and -1e-6 <= y <= h + 1e-6, (f, x, y)
        if tag == "text" and el.get("x") is not None:
            x, y = float(el.get("x")), float(el.get("y"))
            size = font_size(el)
            txt = "".join(el.itertext())
            anchor = el.get("text-anchor") or "start"
            est = 0.55 * size * len(txt)
            if "rotate(-90" in (el.get("transform") or ""):  # vertical text: its extent runs along y
                x, y = y, x
                w_, h_ = h, w
            else:
                w_, h_ = w, h
            x0 = x - (est if anchor == "end" else est / 2 if anchor == "middle" else 0)
            assert 0 <= y <= h_ and x0 >= -1 and x0 + est <= w_ + 1, (f, txt, x, y, w, h)
PY

# a scene file replays run 0 of S-RRT (scene A, seed 5)
set +e; (cd "$tmp/r" && "$pathref" plan --map cin2021-srrt/scene-A.json --algo s-rrt --seed 5 --json >"$tmp/plan.json"); rc=$?; set -e
[ "$rc" = 0 ] || [ "$rc" = 1 ] || { echo "FAIL: plan on the scene file exited $rc"; exit 1; }
python3 - "$tmp/r/cin2021-srrt/reproduce.json" "$tmp/plan.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
p = json.load(open(sys.argv[2]))
r = d["scenes"][0]["series"]["s-rrt"]["runs"][0]
assert p["start_xy"] == [1.5, 1.5] and p["goal_xy"] == [18.5, 18.5], (p["start_xy"], p["goal_xy"])
assert p["found"] == r["found"] and p["tree_size"] == r["tree_size"] and p["iterations"] == r["iterations"]
if r["found"]:
    assert p["shortcut"]["length"] == r["length"] and p["curve"]["length"] == r["curve_length"]
PY
echo "reproduce cin2021-srrt: OK"
