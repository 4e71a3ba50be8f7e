#!/usr/bin/env bash
# `pathref simulate` on a pathref-sim 2 scenario (spec/sensors2023-dwa.md, sensors2023.sim.run):
# the README command, JSON output, SVG, the exit codes and a parse error with line and column.
set -euo pipefail
P="$1"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$P" simulate tests/data/sim/sensors2023_mixed.json --svg "$out/mixed.svg" > "$out/report.txt"
grep -q '^outcome: reached$' "$out/report.txt"
grep -q '^parameters: ' "$out/report.txt"
grep -q 'class="trajectory"' "$out/mixed.svg"
grep -q 'class="temporary"' "$out/mixed.svg"
"$P" simulate tests/data/sim/sensors2023_mixed.json --json --full > "$out/r.json"
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['format']=='pathref-sim-result 2' and d['outcome']=='reached' and len(d['samples'])==len(d['tracks']), d['outcome']" "$out/r.json"
# a pathref-sim 1 file still runs Han's simulation
for f in tests/data/sim/*.json; do
  if grep -q '"pathref-sim 1"' "$f"; then "$P" simulate "$f" > /dev/null || [ $? -eq 1 ]; break; fi
done
printf '{"format": "pathref-sim 2",\n "map": ["..."], "start": [0, 0], "goal": [2, 0],\n "t_max": -1}\n' > "$out/bad.json"
set +e
"$P" simulate "$out/bad.json" 2> "$out/err.txt"
rc=$?
set -e
[ "$rc" -eq 2 ]
grep -q 'bad.json:3:11: /t_max: expected a number' "$out/err.txt"
echo ok
