#!/usr/bin/env bash
# `pathref convert` and `pathref plan --map` with every map format (spec/formats.md#cli-convert,
# #map-options; spec/formats.md#map-files): conversions round-trip, detection by extension and
# --format, S/W options, errors with file:line:column.
# Usage: bash tests/cli/convert.sh path/to/pathref   (from the repository root)
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
same() { cmp -s "$1" "$2" || { echo "FAIL: $1 and $2 differ"; diff "$1" "$2" | head; exit 1; }; }

m=tests/data/movingai/rooms40x30.map
w=tests/data/matrix/warehouse.m
# Every sample through every writer and back: the pathref-grid text is the same each time.
for src in "$m" "$w" tests/data/matrix/warehouse.txt; do
  "$pathref" convert "$src" --to pathref-grid -o "$tmp/ref.txt"
  for to in pathref-grid movingai matrix matlab; do
    "$pathref" convert "$src" --to "$to" -o "$tmp/a.$to"
    fmt=$(case $to in pathref-grid) echo pathref-grid;; movingai) echo movingai;; *) echo matrix;; esac)
    "$pathref" convert "$tmp/a.$to" --format "$fmt" --to pathref-grid >"$tmp/back.txt"
    same "$tmp/ref.txt" "$tmp/back.txt"
  done
done
# The MovingAI writer's text equals the sample minus its extra letters (G, S -> .; T, W, O -> @).
"$pathref" convert "$m" --to movingai >"$tmp/m.map"
tr 'GSTWO' '..@@@' <"$m" >"$tmp/expect.map"
same "$tmp/expect.map" "$tmp/m.map"
# The two matrix samples are the same map; the MATLAB writer's form.
"$pathref" convert "$w" --to matrix >"$tmp/w1"; "$pathref" convert tests/data/matrix/warehouse.txt --to matrix >"$tmp/w2"
same "$tmp/w1" "$tmp/w2"; same tests/data/matrix/warehouse.txt "$tmp/w1"
"$pathref" convert "$w" --to matlab | head -2 >"$tmp/w3"
printf 'G = [0 0 0 0 0 0 0 0 0 0 0 0\n     0 1 1 1 0 0 0 1 1 1 1 0\n' >"$tmp/w4"; same "$tmp/w4" "$tmp/w3"
# S and W options: the sample has 12 S and 21 W cells.
base=$("$pathref" convert "$m" --to matrix | grep -o 1 | wc -l)
open=$("$pathref" convert "$m" --to matrix --water free | grep -o 1 | wc -l)
shut=$("$pathref" convert "$m" --to matrix --swamp blocked | grep -o 1 | wc -l)
[ "$open" -eq $((base - 21)) ] && [ "$shut" -eq $((base + 12)) ] || { echo "FAIL: S/W options: $base $open $shut"; exit 1; }
# start/goal/name are only kept by pathref-grid; a note says so.
"$pathref" maps grid20 >"$tmp/g20.txt"
expect_exit 0 "pathref: note: the movingai format has no start, goal or name; they were not written" convert "$tmp/g20.txt" --to movingai

# plan reads every format; MovingAI/matrix maps need --start/--goal (pathref coordinates).
expect_exit 0 "" plan --map "$w" --algo astar --start 0,8 --goal 11,0
grep -qE '^  map +tests/data/matrix/warehouse.m \(file tests/data/matrix/warehouse.m, 12x9, 32 blocked cells\)$' "$tmp/out" || { echo "FAIL: plan report"; cat "$tmp/out"; exit 1; }
expect_exit 0 "" plan --map "$m" --algo dijkstra --start 1,1 --goal 38,28 --json
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["found"] and d["map"]["width"] == 40 and d["map"]["height"] == 30, d["map"]' "$tmp/out"
cp "$w" "$tmp/warehouse.dat"
expect_exit 0 "" plan --map "$tmp/warehouse.dat" --algo astar --start 0,8 --goal 11,0        # content rule: matrix
expect_exit 2 "$tmp/warehouse.dat:1:1: expected 'type octile' as the first line" plan --map "$tmp/warehouse.dat" --format movingai --algo astar --start 0,8 --goal 11,0
expect_exit 2 "the map defines no start: give --start X,Y" plan --map "$m" --algo astar

# ROS map_server maps (YAML + PGM) by extension; --unknown decides the 6 unexplored cells.
r=tests/data/ros/office.yaml
expect_exit 0 "" plan --map "$r" --algo astar --start 1,1 --goal 14,1
"$pathref" convert "$r" --to matrix >"$tmp/r1"; "$pathref" convert "$r" --format ros --unknown free --to matrix >"$tmp/r2"
[ "$(grep -o 1 "$tmp/r1" | wc -l)" -eq $(( $(grep -o 1 "$tmp/r2" | wc -l) + 6 )) ] || { echo "FAIL: --unknown"; exit 1; }
expect_exit 2 "$r:1:8: the image is a 16x10 grid, which exceeds the limit of 15 cells per side" convert "$r" --to matrix --max-side 15
expect_exit 2 "--unknown: maybe not in {blocked,free}" convert "$r" --to matrix --unknown maybe

# Errors: file:line:column and what was expected; unknown formats; missing files; .scen.
printf 'G=[0 0 1;\n1 2 0];\n' >"$tmp/bad.m"
expect_exit 2 "pathref: error: $tmp/bad.m:2:3: expected 0 (free) or 1 (obstacle), got '2'" convert "$tmp/bad.m" --to movingai
printf 'type octile\r\nheight 2\r\nwidth 2\r\nmap\r\n..\r\n.\r.\r\n' >"$tmp/cr.map"
expect_exit 2 "pathref: error: $tmp/cr.map:6:2: unexpected carriage return (lines must end in LF or CRLF)" convert "$tmp/cr.map" --to matrix
printf 'type octile\nheight -1\nwidth 2\nmap\n' >"$tmp/neg.map"
expect_exit 2 "$tmp/neg.map:2:8: expected height as a decimal integer, got '-1'" plan --map "$tmp/neg.map" --algo astar
printf 'type octile\nheight 100000\nwidth 100000\nmap\n' >"$tmp/huge.map"
expect_exit 2 "$tmp/huge.map:3:7: a 100000x100000 map exceeds the limit of 268435456 cells" convert "$tmp/huge.map" --to matrix
expect_exit 2 "$tmp/huge.map:2:8: height must be between 1 and 5000, got '100000'" convert "$tmp/huge.map" --to matrix --max-side 5000
expect_exit 2 "cannot read map file '$tmp/none.map'" convert "$tmp/none.map" --to matrix
expect_exit 2 "is a MovingAI scenario file, not a map: run it with pathref scen" plan --map tests/data/movingai/rooms40x30.map.scen --algo astar
expect_exit 2 "--to: png not in {pathref-grid,movingai,matrix,matlab}" convert "$m" --to png
expect_exit 2 "--format: png not in {auto,pathref-grid,movingai,matrix,ros,scene}" convert "$m" --to matrix --format png
expect_exit 2 "--max-cells expects a decimal integer from 1 to 268435456, got '268435457'" convert "$m" --to matrix --max-cells 268435457
expect_exit 0 "" convert "$m" --to matrix -o "$tmp/no/dir/x"   # missing folders are created
[ -s "$tmp/no/dir/x" ] || { echo "FAIL: convert -o into a new folder wrote nothing"; exit 1; }
expect_exit 2 "cannot write '$tmp/no/dir': it is a folder" convert "$m" --to matrix -o "$tmp/no/dir"
echo "convert: ok"
