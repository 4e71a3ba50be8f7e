#!/usr/bin/env bash
# `pathref scen` (spec/formats.md#cli-scen): the report, the agreement rule, the exit codes, the errors of
# spec/formats.md#movingai-scen through the CLI, the samples in tests/data, and — when present —
# every shared MovingAI benchmark scenario file (../shared/data/movingai, run with a stride).
# Usage: bash tests/cli/scen.sh path/to/pathref   (from the repository root)
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
expect_out() { grep -qF -- "$1" "$tmp/out" || { echo "FAIL: stdout lacks '$1':"; cat "$tmp/out"; exit 1; }; }

d=tests/data/movingai
# The samples (optimal lengths by tests/data/make_samples.py's own Dijkstra): all agree.
expect_exit 0 "" scen "$d/rooms40x30.map.scen"
expect_out "  version     1 (9 columns)"
expect_out "  map         $d/rooms40x30.map (40x30, 253 blocked cells)"
expect_out "scenario 1 line 2 bucket 2 start (11, 18) goal (18, 16) optimal 10.6569 pathref 10.65685424949238 agree"
expect_out "summary: 40 run, 40 agree, 0 differ (40 scenarios in the file, every 1)"
expect_exit 0 "" scen "$d/rooms40x30-v0.scen" --every 5
expect_out "  version     0 (7 columns)"
expect_out "summary: 3 run, 3 agree, 0 differ (12 scenarios in the file, every 5)"
expect_exit 0 "" scen "$d/rooms40x30.map.scen" --json --every 20
python3 - "$tmp/out" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["format"] == "pathref-scen" and d["format_version"] == 1, d
assert d["summary"] == {"scenarios": 40, "run": 2, "agree": 2, "differ": 0}, d["summary"]
s = d["scenarios"][0]
assert s["index"] == 1 and s["line"] == 2 and s["start"] == [11, 18] and s["goal"] == [18, 16], s
assert s["optimal"] == "10.6569" and s["tolerance"] == 1e-4 and s["agree"] is True, s
assert d["scenarios"][1]["index"] == 21, d["scenarios"][1]
PY

# A wrong length disagrees (exit 1); an unreachable goal disagrees; --digits 0 is looser.
printf 'version 1\n0\tm.map\t4\t3\t0\t0\t3\t0\t3\n1\tm.map\t4\t3\t0\t2\t3\t2\t3.0\n' >"$tmp/a.scen"
printf 'type octile\nheight 3\nwidth 4\nmap\n....\n....\n....\n' >"$tmp/m.map"
expect_exit 0 "" scen "$tmp/a.scen"
printf 'version 1\n0\tm.map\t4\t3\t0\t0\t1\t1\t1\n' >"$tmp/b.scen"
expect_exit 1 "" scen "$tmp/b.scen"
expect_out "optimal 1 pathref 1.4142135623730951 DIFFER (tolerance 1e-05)"
expect_out "summary: 1 run, 0 agree, 1 differ"
expect_exit 0 "" scen "$tmp/b.scen" --digits 0  # literal last printed digit: 1 +- 1
printf 'type octile\nheight 3\nwidth 4\nmap\n.@..\n@@..\n....\n' >"$tmp/w.map"
printf 'version 1\n0\tw.map\t4\t3\t0\t0\t3\t0\t3\n' >"$tmp/c.scen"
expect_exit 1 "" scen "$tmp/c.scen"
expect_out "pathref none DIFFER (no path found)"
# Map resolution: --map overrides; the column resolved relative to the .scen; then its file name.
printf 'version 1\n0\tmaps/sub/m.map\t4\t3\t0\t0\t3\t0\t3\n' >"$tmp/d.scen"
expect_exit 0 "" scen "$tmp/d.scen"
expect_out "  map         $tmp/m.map (4x3"
mkdir -p "$tmp/maps/sub"; printf 'type octile\nheight 3\nwidth 4\nmap\n@...\n....\n....\n' >"$tmp/maps/sub/m.map"
expect_exit 2 "pathref: error: $tmp/d.scen:2:22: start (0, 0) is a blocked cell of $tmp/maps/sub/m.map" scen "$tmp/d.scen"
expect_exit 0 "" scen "$tmp/d.scen" --map "$tmp/m.map"
printf 'version 1\n0\tnowhere/x.map\t4\t3\t0\t0\t3\t0\t3\n' >"$tmp/e.scen"
expect_exit 2 "cannot find the map 'nowhere/x.map' named on line 2 of '$tmp/e.scen' (tried '$tmp/nowhere/x.map' and '$tmp/x.map'); give --map FILE" scen "$tmp/e.scen"

# Errors (exit 2, nothing printed on stdout): the file, its lines, the map, the options.
expect_exit 2 "cannot read scenario file '$tmp/missing.scen'" scen "$tmp/missing.scen"
printf 'version 1\n0\tm.map\t5\t3\t0\t0\t3\t0\t3\n' >"$tmp/f.scen"
expect_exit 2 "pathref: error: $tmp/f.scen:2:9: the map $tmp/m.map is 4x3 but this line says 5x3 (pathref does not scale maps)" scen "$tmp/f.scen"
printf 'version 1\r\n0\tm.map\t4\t3\t0\t0\t4\t0\t3\r\n' >"$tmp/g.scen"
expect_exit 2 "$tmp/g.scen:2:17: goal (4, 0) is outside the 4x3 map of this line (x must be < 4, y < 3)" scen "$tmp/g.scen"
printf '0\tm.map\t4\t3\t0\t0\t3\t0\t3\n' >"$tmp/h.scen"
expect_exit 2 "$tmp/h.scen:1:19: expected end of line after 7 fields" scen "$tmp/h.scen"
printf 'version 1\n0\tm.map\t4\t3\t1\t1\t1\t1\t0\n' >"$tmp/i.scen"
expect_exit 2 "$tmp/i.scen:2:13: start (1, 1) equals the goal" scen "$tmp/i.scen"
printf 'version 1\n0\tm.map\t4\t3\t0\t0\t3\t0\t3,0\n' >"$tmp/j.scen"
expect_exit 2 "$tmp/j.scen:2:21: expected the optimal length as a decimal number such as 3.41421, got '3,0'" scen "$tmp/j.scen"
printf 'version 1\n0\tm.map\t4\t3\t0\t0\t3\t0\t3\n' >"$tmp/k.scen"
printf 'type octile\nheight 3\nwidth 4\nmap\n....\n..x.\n....\n' >"$tmp/m.map"
expect_exit 2 "pathref: error: $tmp/m.map:6:3: expected a MovingAI terrain letter (. G S W @ O T), got 'x'" scen "$tmp/k.scen"
[ ! -s "$tmp/out" ] || { echo "FAIL: a failed run printed a report"; cat "$tmp/out"; exit 1; }
expect_exit 2 "--every expects a decimal integer from 1 to 2147483647, got '0'" scen "$d/rooms40x30.map.scen" --every 0
expect_exit 2 "--digits expects a decimal integer from 0 to 17, got '18'" scen "$d/rooms40x30.map.scen" --digits 18
expect_exit 2 "unknown --algo 'nope' (known: " scen "$d/rooms40x30.map.scen" --algo nope
expect_exit 2 "--max-side expects a decimal integer from 1 to 268435456, got '0'" scen "$d/rooms40x30.map.scen" --max-side 0
expect_exit 2 "$d/rooms40x30.map.scen:2:31: width must be between 1 and 39, got '40'" scen "$d/rooms40x30.map.scen" --max-side 39
expect_exit 2 "$d/rooms40x30.map:3:7: a 40x30 map exceeds the limit of 1000 cells" scen "$d/rooms40x30.map.scen" --max-cells 1000
# --water free opens the water cells: the samples were computed with W blocked, so some differ.
expect_exit 1 "" scen "$d/rooms40x30.map.scen" --water free

# The shared MovingAI benchmarks (not part of the repository): every file must agree.
# Strides keep this under ~20 s with ASan+UBSan (see spec/formats.md#cli-scen for the measurements).
shared=../shared/data/movingai
if [ ! -d "$shared" ]; then
  echo "skipped: $shared is absent (shared MovingAI benchmark files)"
  echo "scen: ok"
  exit 0
fi
declare -A stride=([arena]=4 [den312d]=8 [lak303d]=25 [8room_000]=48 [random512-10-0]=42 [maze512-1-0]=398)
for f in "$shared"/*.map.scen; do
  name=$(basename "$f" .map.scen)
  every=${stride[$name]:-50}
  expect_exit 0 "" scen "$f" --every "$every"
  grep -qE "^summary: [0-9]+ run, [0-9]+ agree, 0 differ" "$tmp/out" || { echo "FAIL: $f"; tail -3 "$tmp/out"; exit 1; }
  echo "$name: $(tail -1 "$tmp/out")"
done
echo "scen: ok"
