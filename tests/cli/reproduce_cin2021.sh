#!/usr/bin/env bash
# `pathref reproduce cin2021-hga-aco` (spec/cin2021-hga-aco.md, reproduce.cin2021.*): bad input is
# exit 2 with a clear message; a --quick run writes the report, its JSON and the figures, the JSON
# parses and holds every scenario, planner and claim. With the shared MATLAB maps present, the
# maps B and C are run too (skipped with a message otherwise).
# Usage: bash tests/cli/reproduce_cin2021.sh path/to/pathref   (from the repository root)
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

"$pathref" reproduce --help | grep -qF cin2021-hga-aco || { echo "FAIL: reproduce --help lacks cin2021-hga-aco"; exit 1; }
for w in --map-b --map-c --runs --seed --out-dir --policy --quick; do
  "$pathref" reproduce cin2021-hga-aco --help | grep -qF -- "$w" || { echo "FAIL: --help lacks $w"; exit 1; }
done
expect_exit 2 "--runs expects a decimal integer from 2 to 10000, got '1'" reproduce cin2021-hga-aco --runs 1 --out-dir "$tmp/o"
expect_exit 2 "cannot read map file '$tmp/missing.txt'" reproduce cin2021-hga-aco --map-b "$tmp/missing.txt" --out-dir "$tmp/o"

maps=()
data=../shared/data/matlab-maps
if [ -f "$data/mapB_20x20_ga.txt" ] && [ -f "$data/mapC_20x20_winsleo_traditional.txt" ]; then
  maps=(--map-b "$data/mapB_20x20_ga.txt" --map-c "$data/mapC_20x20_winsleo_traditional.txt")
else
  echo "SKIP part: $data absent, maps B and C not run"
fi
"$pathref" reproduce cin2021-hga-aco --quick --runs 2 --jobs 2 "${maps[@]}" --out-dir "$tmp/r" >"$tmp/out" 2>"$tmp/err"
for f in cin2021-hga-aco.md cin2021-hga-aco/reproduce.json cin2021-hga-aco/s1-paths.svg cin2021-hga-aco/s3-convergence.svg; do
  [ -s "$tmp/r/$f" ] || { echo "FAIL: $f not written"; cat "$tmp/out" "$tmp/err"; exit 1; }
done
python3 - "$tmp/r/cin2021-hga-aco/reproduce.json" "${#maps[@]}" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
keys = [m["key"] for m in d["maps"]]
want = ["s1", "s2", "s3"] + (["shiC", "shiB"] if sys.argv[2] != "0" else [])
assert keys == want, keys
for k in keys:
    for p in ("hga-aco-cin", "aco-cin", "ga-cin"):
        r = d["results"][k][p]
        assert r["available"] and r["summary"]["runs"] == 4, (k, p)  # 2n runs
        assert r["summary"]["valid"] == r["summary"]["found"], (k, p)
assert d["protocol"]["runs"] == 2 and d["protocol"]["runs_2n"] == 4
assert d["provenance"]["jobs"] == 2
assert len(d["claims"]) == len(keys) * 4 * 2, len(d["claims"])
alts = {c["id"] for c in d["reading_claims"]}
for c in d["claims"]:
    assert c["verdict"] in ("holds", "does not hold", "not significant", "cannot be tested"), c
    assert c["id"] + "@any_stuck" in alts and c["id"] + "@goal_inverse" in alts, c["id"]
    assert c["depends_on"], c["id"]
    if c["verdict"] != "cannot be tested":
        assert c["at_2n"] is not None and "Mann" in c["rule"], c
assert len(d["cross_paper"]) == (16 if sys.argv[2] != "0" else 0), len(d["cross_paper"])
PY
grep -qF "project" "$tmp/r/cin2021-hga-aco.md" || { echo "FAIL: the report does not say the parameters are the project's"; exit 1; }
for w in "QUICK RUN" "verdicts on the protocol's n runs" "under the alternative readings" "Verdicts that change between n and 2n"; do
  grep -qF "$w" "$tmp/r/cin2021-hga-aco.md" || { echo "FAIL: the report lacks '$w'"; exit 1; }
done
echo "reproduce cin2021-hga-aco: ok"
