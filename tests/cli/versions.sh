#!/usr/bin/env bash
# Every output says which pathref and which golden-vector set produced it, and reconstructed rules
# say so (docs/versioning.md): `--version` is "X.Y.Z (golden vectors V)" with X.Y.Z from
# CMakeLists.txt and V from golden/MANIFEST; every JSON document of plan (grid and continuous),
# check, eval (single and --list), drive, simulate (both formats), scen, learn (output, model file,
# predictions) and classify carries the same "pathref_version" and "golden_set_version"; eval
# marks exactly the rules that spec/index/*.json grades with their grade and "reconstructed".
# Usage: bash tests/cli/versions.sh path/to/pathref   (from the repository root)
set -euo pipefail
pathref=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

version=$(sed -n 's/^project(pathref VERSION \([0-9.]*\) .*/\1/p' CMakeLists.txt)
golden=$(python3 -c 'import json; print(json.load(open("golden/MANIFEST"))["golden_set_version"])')
[ -n "$version" ] && [ -n "$golden" ] || fail "cannot read the version ($version) or the golden-set version ($golden)"
got=$("$pathref" --version)
[ "$got" = "$version (golden vectors $golden)" ] || fail "--version printed '$got', expected '$version (golden vectors $golden)'"

# stamped FILE WHAT: FILE is one JSON document carrying both versions.
stamped() {
  python3 - "$1" "$2" "$version" "$golden" <<'PY' || fail "$2: $1 lacks the versions"
import json, sys
path, what, version, golden = sys.argv[1:]
doc = json.load(open(path))
if doc.get("pathref_version") != version or doc.get("golden_set_version") != golden:
    print(f"{what}: pathref_version {doc.get('pathref_version')!r}, golden_set_version "
          f"{doc.get('golden_set_version')!r}; expected {version!r}, {golden!r}")
    sys.exit(1)
PY
}

"$pathref" plan --builtin shi6x6 --algo astar --json >"$tmp/plan.json"; stamped "$tmp/plan.json" "plan --json"
"$pathref" plan --builtin shi6x6 --algo astar --json-out "$tmp/plan2.json" >/dev/null; stamped "$tmp/plan2.json" "plan --json-out"
"$pathref" plan --map tests/data/scenes/srrt_walls.json --algo s-rrt --seed 3 --json >"$tmp/c.json"
stamped "$tmp/c.json" "plan (continuous) --json"
"$pathref" check --path "$tmp/plan.json" --json >"$tmp/check.json"; stamped "$tmp/check.json" "check --json"
"$pathref" eval grid.coord index=7 width=6 height=6 >"$tmp/e.json"; stamped "$tmp/e.json" "eval"
"$pathref" eval --list --json >"$tmp/list.json"; stamped "$tmp/list.json" "eval --list --json"
"$pathref" drive --path "$tmp/plan.json" --base mecanum --cell 1 --json >"$tmp/drive.json"; stamped "$tmp/drive.json" "drive --json"
"$pathref" simulate tests/data/sim/none.json --json >"$tmp/sim.json"; stamped "$tmp/sim.json" "simulate --json (pathref-sim 1)"
set +e; "$pathref" simulate tests/data/sim/sensors2023_mixed.json --json >"$tmp/fused.json"; rc=$?; set -e
[ "$rc" -le 1 ] || fail "simulate sensors2023_mixed.json exited $rc"
stamped "$tmp/fused.json" "simulate --json (pathref-sim 2)"
"$pathref" scen tests/data/movingai/rooms40x30.map.scen --json --every 20 >"$tmp/scen.json"; stamped "$tmp/scen.json" "scen --json"
: >"$tmp/d.data"
for i in 1 2 3 4 5 6; do
  printf '%s.5,1.0%s,Move-Forward\n0.%s,1.1%s,Sharp-Right-Turn\n' "$((i + 3))" "$i" "$((i + 2))" "$i" >>"$tmp/d.data"
done
"$pathref" learn --data "$tmp/d.data" --classifier gnb --holdout 0.5 --seed 3 --json --save-model "$tmp/m.json" \
  --predictions "$tmp/p.json" >"$tmp/learn.json"
stamped "$tmp/learn.json" "learn --json"; stamped "$tmp/m.json" "learn --save-model"; stamped "$tmp/p.json" "learn --predictions"
"$pathref" classify --model "$tmp/m.json" 6.5 1.0 --json >"$tmp/cls.json"; stamped "$tmp/cls.json" "classify --json"

# reproduce run-job (the jobs of --emit-jobs): one job's JSON output
(cd "$tmp" && "$pathref" reproduce han --quick --emit-jobs jobs.txt --out-dir "$tmp/e" >/dev/null 2>&1) || fail "--emit-jobs"
(cd "$tmp" && bash -c "$(head -n 1 jobs.txt)") || fail "the first run-job command"
stamped "$(ls "$tmp"/jobs.txt.results/* | head -n 1)" "reproduce run-job"

# Grades: eval --list (text and JSON) and a single eval agree with spec/index/*.json.
"$pathref" eval --list >"$tmp/list.txt"
"$pathref" eval sensors2023.eq1 theta=30 >"$tmp/g.json"; stamped "$tmp/g.json" "eval sensors2023.eq1"
python3 - "$tmp/list.json" "$tmp/list.txt" <<'PY' || fail "grades in eval --list"
import glob, json, re, sys
index = {}
for f in glob.glob("spec/index/*.json"):
    for r in json.load(open(f))["rules"]:
        if "grade" in r:
            index[r["id"]] = r["grade"]
assert len(index) >= 50, f"only {len(index)} graded rules in spec/index"
listed = json.load(open(sys.argv[1]))["rules"]
bad = []
for r in listed:
    want = index.get(r["id"])
    got = (r.get("grade"), r.get("reconstructed"))
    if got != ((want, True) if want else (None, None)):
        bad.append(f"{r['id']}: eval --list --json says {got}, spec/index says grade {want}")
text = {}
for line in open(sys.argv[2]):
    if line and not line[0].isspace():
        m = re.match(r"(\S+)  \[grade ([ABC]), reconstructed\]  ", line)
        text[line.split("  ", 1)[0]] = m.group(2) if m else None
for rid, g in text.items():
    if g != index.get(rid):
        bad.append(f"{rid}: eval --list says grade {g}, spec/index says {index.get(rid)}")
missing = set(index) - {r["id"] for r in listed}
bad += [f"{rid}: graded in spec/index but not listed" for rid in sorted(missing)]
if bad:
    print("\n".join(bad[:20]))
    sys.exit(1)
PY
# a single eval of a graded rule and of a paper's own rule
"$pathref" eval --list --json | python3 -c '
import json, subprocess, sys
rules = {r["id"]: r for r in json.load(sys.stdin)["rules"]}
assert rules["grid.coord"].get("grade") is None and rules["grid.coord"].get("reconstructed") is None
assert rules["sensors2023.eq1"]["grade"] in "ABC" and rules["sensors2023.eq1"]["reconstructed"] is True
' || fail "grade of grid.coord / sensors2023.eq1 in eval --list --json"
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert "grade" not in d and "reconstructed" not in d' "$tmp/e.json" \
  || fail "eval grid.coord carries a grade"
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["grade"] in "ABC" and d["reconstructed"] is True' "$tmp/g.json" \
  || fail "eval sensors2023.eq1 lacks its grade"
echo "versions: ok"
