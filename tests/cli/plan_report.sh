#!/usr/bin/env bash
# The text report of `pathref plan` names everything used (map and size, algo, policy, seed,
# every parameter, start, goal) and the results (spec/cli.md#plan).
# Usage: bash tests/cli/plan_report.sh path/to/pathref
set -euo pipefail
pathref=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# expect FILE REGEX...: every extended regex matches some line of FILE.
expect() {
  local f=$1; shift
  for re in "$@"; do
    grep -qE -- "$re" "$f" || { echo "FAIL: no line matches '$re' in:"; cat "$f"; exit 1; }
  done
}

"$pathref" plan --builtin grid20 --algo astar >"$tmp/a.txt"
expect "$tmp/a.txt" \
  '^  map +grid20 \(builtin, 20x20, 92 blocked cells\)$' \
  '^  algo +astar$' \
  '^  policy +strict \(diagonal needs both orthogonal neighbours free\), the planner'"'"'s default$' \
  '^  seed +1$' \
  '^  params +heuristic=octile$' \
  '^  start +\(0, 0\)$' '^  goal +\(19, 19\)$' \
  '^  found +yes$' '^  length +50\.24264068711928[0-9]*$' '^  turns +[0-9]+$' \
  '^  valid +yes \(ok\)$' '^  expansions +[1-9][0-9]*$' '^  path +\(0,0\) .* \(19,19\)$'

"$pathref" plan --builtin shi6x6 --algo astar --policy always --seed 12345 --set heuristic=euclidean \
  --json-out "$tmp/x.json" --svg "$tmp/x.svg" >"$tmp/b.txt"
expect "$tmp/b.txt" '^  map +shi6x6 \(builtin, 6x6, 5 blocked cells\)$' '^  seed +12345$' \
  '^  policy +always ' '^  params +heuristic=euclidean$' '^  start +\(0, 0\)$' '^  goal +\(5, 5\)$' \
  '^  length +7\.0710678118654755$' '^  turns +0$' "^wrote $tmp/x.json\$" "^wrote $tmp/x.svg\$"
[ -s "$tmp/x.json" ] && [ -s "$tmp/x.svg" ] || { echo "FAIL: files not written"; exit 1; }

# The corner policy changes the result on shi6x6 (spec/cli.md#builtin-maps).
"$pathref" plan --builtin shi6x6 --algo dijkstra >"$tmp/c.txt"
expect "$tmp/c.txt" '^  length +8\.828427124746' '^  params +\(none\)$'
"$pathref" plan --builtin shi6x6 --algo dijkstra --policy never >"$tmp/d.txt"
expect "$tmp/d.txt" '^  length +10$' '^  policy +never \(4-connected, no diagonal moves\)$'

# A map file: its name line and path are reported; --start/--goal default to the file's own.
printf 'pathref-grid 1\nname corridor\nsize 4 1\nstart 0 0\ngoal 3 0\nmap\n....\n' >"$tmp/m.txt"
"$pathref" plan --map "$tmp/m.txt" --algo astar >"$tmp/e.txt"
expect "$tmp/e.txt" "^  map +corridor \\(file $tmp/m.txt, 4x1, 0 blocked cells\\)\$" '^  length +3$' \
  '^  path +\(0,0\) \(1,0\) \(2,0\) \(3,0\)$'
echo "plan_report: ok"
