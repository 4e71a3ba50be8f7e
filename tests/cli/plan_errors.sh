#!/usr/bin/env bash
# Exit codes of `pathref plan` (spec/cli.md#exit-codes): 2 with a clear message for bad
# arguments or input, 1 when no path exists, 0 otherwise.
# Usage: bash tests/cli/plan_errors.sh path/to/pathref
set -euo pipefail
pathref=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# expect_exit CODE MESSAGE ARGS...: pathref ARGS exits CODE and stderr contains MESSAGE (if not
# empty). stdout is left in $tmp/out, stderr in $tmp/err.
expect_exit() {
  local want=$1 msg=$2; shift 2
  set +e; "$pathref" "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?; set -e
  if [ "$got" != "$want" ]; then
    echo "FAIL: pathref $* exited $got, expected $want"; cat "$tmp/out" "$tmp/err"; exit 1
  fi
  [ -z "$msg" ] || grep -qF -- "$msg" "$tmp/err" || { echo "FAIL: pathref $*: stderr lacks '$msg':"; cat "$tmp/err"; exit 1; }
}

g=(plan --builtin grid20)
expect_exit 2 "unknown --algo 'nope' (known: " "${g[@]}" --algo nope
expect_exit 2 "--algo is required" "${g[@]}"
for bad in "" 1 1, ,1 a,b -1,0 1,2,3 "1, 2" 1.5,2 " 1,2" 1234567890123456789,0; do
  expect_exit 2 "--start expects X,Y (two non-negative integers), got '$bad'" "${g[@]}" --algo astar --start "$bad"
done
expect_exit 2 "--goal expects X,Y" "${g[@]}" --algo astar --goal x
expect_exit 2 "--start: At Most 1 required but received 2" "${g[@]}" --algo astar --start 0,0 --start 1,0
expect_exit 2 "--algo: At Most 1 required but received 2" "${g[@]}" --algo astar --algo dijkstra
expect_exit 2 "start (4, 0) is a blocked cell" "${g[@]}" --algo astar --start 4,0
expect_exit 2 "goal (20, 19) is outside the 20x20 map" "${g[@]}" --algo astar --goal 20,19
expect_exit 2 "start and goal are the same cell (0, 0): there is nothing to plan (give different --start and --goal)" "${g[@]}" --algo astar --start 0,0 --goal 0,0
expect_exit 2 "unknown parameter 'foo' (known: heuristic)" "${g[@]}" --algo astar --set foo=1
expect_exit 2 "parameter 'heuristic' must be of the same type" "${g[@]}" --algo astar --set heuristic=3
expect_exit 2 "--set expects key=value, got 'heuristic'" "${g[@]}" --algo astar --set heuristic
expect_exit 2 "--set heuristic given more than once" "${g[@]}" --algo astar --set heuristic=octile --set heuristic=zero
expect_exit 2 "unknown parameter 'heuristic' (known: none)" "${g[@]}" --algo dijkstra --set heuristic=octile
expect_exit 2 "--policy: diag not in {never,strict,one,always}" "${g[@]}" --algo astar --policy diag
# --cell-numbers (figures.cell-numbers): only with --svg, only on cells the numbers fit, never a
# JSON file left behind by a figure that could not be drawn, never on the continuous planners.
expect_exit 2 "--cell-numbers goes with --svg FILE" "${g[@]}" --algo astar --cell-numbers
expect_exit 2 "cell numbers need cells of at least" "${g[@]}" --algo astar --cell-numbers --svg "$tmp/n.svg" --json-out "$tmp/n.json"
[ ! -e "$tmp/n.svg" ] && [ ! -e "$tmp/n.json" ] || { echo "FAIL: a failed --cell-numbers figure left files"; exit 1; }
expect_exit 0 "" plan --builtin shi6x6 --algo astar --cell-numbers --svg "$tmp/n.svg"
grep -q 'class="cell-numbers"' "$tmp/n.svg" || { echo "FAIL: no cell numbers in $tmp/n.svg"; exit 1; }
expect_exit 2 "maps --cell-numbers needs a map NAME and --svg FILE" maps --cell-numbers
expect_exit 2 "--cell-numbers goes with --svg FILE" maps shi6x6 --cell-numbers
for bad in -1 4294967296 0x10 +5 1e3 "" " 7" 99999999999; do
  expect_exit 2 "--seed expects a decimal integer from 0 to 4294967295, got '$bad'" "${g[@]}" --algo astar --seed "$bad"
done
expect_exit 2 "unknown built-in map 'nope' (known: grid20, shi6x6)" plan --builtin nope --algo astar
expect_exit 2 "give exactly one of --map FILE or --builtin NAME" plan --algo astar
expect_exit 2 "--map excludes --builtin" plan --builtin grid20 --map "$tmp/x" --algo astar
expect_exit 2 "cannot read map file '$tmp/missing.txt'" plan --map "$tmp/missing.txt" --algo astar
: >"$tmp/afile"   # a file where a folder is needed: the reason is given (spec/cli.md#output-files)
expect_exit 2 "cannot write '$tmp/afile/dir/f.svg': cannot create the folder '$tmp/afile/dir': " "${g[@]}" --algo astar --svg "$tmp/afile/dir/f.svg"
[ ! -s "$tmp/out" ] || { echo "FAIL: a failed run printed a report"; cat "$tmp/out"; exit 1; }
expect_exit 2 "The following argument was not expected: --frobnicate" plan --builtin grid20 --algo astar --frobnicate

# Malformed map files: the message names file, line and column and what was expected.
printf 'pathref-grid 1\nsize 3 2\nmap\n...\n.x.\n' >"$tmp/bad1.txt"
expect_exit 2 "$tmp/bad1.txt:5:2: expected '.' (free) or '#' (blocked), got 'x'" plan --map "$tmp/bad1.txt" --algo astar
printf 'pathref-grid 2\n' >"$tmp/bad2.txt"
expect_exit 2 "$tmp/bad2.txt:1:14: unsupported format version '2'" plan --map "$tmp/bad2.txt" --algo astar
printf 'pathref-grid 1\nsize 3 2\nmap\n...\n' >"$tmp/bad3.txt"
expect_exit 2 "$tmp/bad3.txt:5:1: unexpected end of file: expected map row 2 of 2" plan --map "$tmp/bad3.txt" --algo astar
# A map without start/goal needs --start/--goal.
printf 'pathref-grid 1\nsize 3 1\nmap\n...\n' >"$tmp/nostart.txt"
expect_exit 2 "the map defines no start: give --start X,Y" plan --map "$tmp/nostart.txt" --algo astar
expect_exit 2 "the map defines no goal: give --goal X,Y" plan --map "$tmp/nostart.txt" --algo astar --start 0,0
expect_exit 0 "" plan --map "$tmp/nostart.txt" --algo astar --start 0,0 --goal 2,0

# No path: exit 1, found false in the JSON, the files are still written.
printf 'pathref-grid 1\nname walled\nsize 5 3\nstart 0 0\ngoal 4 2\nmap\n..#..\n..#..\n..#..\n' >"$tmp/walled.txt"
expect_exit 1 "" plan --map "$tmp/walled.txt" --algo astar --json --svg "$tmp/w.svg"
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["found"] is False and d["path"] == [] and d["length"] is None and d["turns"] is None and d["validation"] == "not_found", d' "$tmp/out"
grep -qF "astar (no path)" "$tmp/w.svg" || { echo "FAIL: the SVG legend does not say (no path)"; exit 1; }
expect_exit 1 "" plan --map "$tmp/walled.txt" --algo dijkstra
grep -qE '^  found +no \(the goal is not reachable\)$' "$tmp/out" || { echo "FAIL: report"; cat "$tmp/out"; exit 1; }
# Diagonal through the wall's gap only under 'always': one cell opened diagonally.
printf 'pathref-grid 1\nsize 2 2\nstart 0 0\ngoal 1 1\nmap\n#.\n.#\n' >"$tmp/diag.txt"
expect_exit 1 "" plan --map "$tmp/diag.txt" --algo astar --policy one
expect_exit 0 "" plan --map "$tmp/diag.txt" --algo astar --policy always
echo "plan_errors: ok"
