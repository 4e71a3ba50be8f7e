#!/usr/bin/env bash
# The classic-MATLAB profile and the no-path message (spec/classic.md, spec/cli.md#plan,
# spec/grid.md "Per-planner default"): aco-classic and ga-classic run with their default corner
# policy `always` and print it; a GA that gives up says why, and the JSON keeps the code.
# Usage: bash tests/cli/classic_profile.sh path/to/pathref
set -euo pipefail
pathref=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# Diagonal gaps only: a path exists only with corner cutting.
printf 'pathref-grid 1\nname gaps\nsize 3 3\nstart 0 0\ngoal 2 2\nmap\n##.\n#.#\n.##\n' >"$tmp/gaps.txt"
"$pathref" plan --map "$tmp/gaps.txt" --algo aco-classic --set ants=5 --set iterations=3 >"$tmp/out"
grep -qE "^  policy +always \(diagonal allowed between any two free cells\), the planner's default$" "$tmp/out" \
  || { echo "FAIL: aco-classic policy line"; cat "$tmp/out"; exit 1; }
grep -qE '^  found +yes$' "$tmp/out" || { echo "FAIL: aco-classic found"; cat "$tmp/out"; exit 1; }
grep -qF 'eta=goal_inverse' "$tmp/out" && grep -qF 'eta_goal=100' "$tmp/out" && grep -qF 'rho=0.3' "$tmp/out" \
  || { echo "FAIL: aco-classic params"; cat "$tmp/out"; exit 1; }
# An explicit --policy overrides the planner's default (and is not called the default).
set +e; "$pathref" plan --map "$tmp/gaps.txt" --algo aco-classic --policy strict --set ants=5 --set iterations=3 >"$tmp/out"; rc=$?; set -e
[ "$rc" = 1 ] || { echo "FAIL: aco-classic under strict exited $rc"; cat "$tmp/out"; exit 1; }
grep -qE "^  policy +strict \(diagonal needs both orthogonal neighbours free\)$" "$tmp/out" \
  || { echo "FAIL: explicit policy line"; cat "$tmp/out"; exit 1; }
grep -qF 'no (no ant or individual reached the goal in the iterations run; this does not prove the goal unreachable)' "$tmp/out" \
  || { echo "FAIL: colony no-path message"; cat "$tmp/out"; exit 1; }
# ga-classic on a 10x10 map (the golden vectors' map), JSON out.
printf 'pathref-grid 1\nname m10\nsize 10 10\nstart 0 0\ngoal 9 9\nmap\n..........\n...##.....\n.#....#...\n.#..#.#.#.\n....#...#.\n.##.#.#...\n......#.#.\n.#.##.....\n.#.....##.\n..........\n' >"$tmp/m10.txt"
"$pathref" plan --map "$tmp/m10.txt" --algo ga-classic --set population=20 --set generations=4 --json >"$tmp/ga.json"
python3 - "$tmp/ga.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["found"] is True and d["policy"] == "always" and d["valid"] is True, d
assert d["params"]["mutation"] == "segment" and d["params"]["penalties"] == [3.0, 15.0, 20.0], d["params"]
assert d["extra"]["population_size"] == d["extra"]["init_built"] <= 20, d["extra"]
PY
# Shi's GA with the literal corner reading and a tiny attempt bound gives up: the report says it
# is not a proof of unreachability, the JSON keeps failure = init_attempts_exhausted, exit 1.
set +e; "$pathref" plan --builtin shi6x6 --algo ga --set illegal_step=reject --set init_attempts=1 >"$tmp/out"; rc=$?; set -e
[ "$rc" = 1 ] || { echo "FAIL: ga exited $rc"; cat "$tmp/out"; exit 1; }
grep -qF 'no (failure init_attempts_exhausted: the GA initialisation gave up after' "$tmp/out" \
  || { echo "FAIL: ga no-path message"; cat "$tmp/out"; exit 1; }
grep -qF 'this does not mean the goal is unreachable' "$tmp/out" || { echo "FAIL: ga message"; cat "$tmp/out"; exit 1; }
set +e; "$pathref" plan --builtin shi6x6 --algo ga --set illegal_step=reject --set init_attempts=1 --json >"$tmp/ga2.json"; set -e
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["found"] is False and d["extra"]["failure"] == "init_attempts_exhausted" and d["extra"]["init_exhausted"] is True, d["extra"]' "$tmp/ga2.json"
# Under the default corner repair the same GA starts.
"$pathref" plan --builtin shi6x6 --algo ga --set population=20 --set generations=3 >"$tmp/out"
grep -qE '^  found +yes$' "$tmp/out" || { echo "FAIL: ga with corner repair"; cat "$tmp/out"; exit 1; }
echo "classic_profile: ok"
