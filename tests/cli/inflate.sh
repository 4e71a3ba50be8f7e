#!/usr/bin/env bash
# `pathref inflate` (spec/inflation.md, section CLI): a scene becomes a pathref-grid 1 map that
# `pathref plan` reads; --out/--svg write files; bad scenes are exit 2 with a located message.
# Usage: bash tests/cli/inflate.sh path/to/pathref   (from the repository root)
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

s=tests/data/scenes/ushape.json
# stdout and --out give the same text; it is a 20x16 pathref-grid map with the scene's start/goal.
"$pathref" inflate "$s" >"$tmp/a.txt"
"$pathref" inflate "$s" --out "$tmp/b.txt" --svg "$tmp/u.svg"
cmp -s "$tmp/a.txt" "$tmp/b.txt" || { echo "FAIL: stdout and --out differ"; exit 1; }
# -o and --output (convert's spelling) are the same option as --out (spec/cli.md#output-files)
"$pathref" inflate "$s" -o "$tmp/c.txt" >/dev/null
"$pathref" inflate "$s" --output "$tmp/d/e.txt" >/dev/null
cmp -s "$tmp/a.txt" "$tmp/c.txt" && cmp -s "$tmp/a.txt" "$tmp/d/e.txt" || { echo "FAIL: -o/--output differ from --out"; exit 1; }
head -1 "$tmp/a.txt" | grep -q '^pathref-grid 1' || { echo "FAIL: not pathref-grid 1"; head -3 "$tmp/a.txt"; exit 1; }
grep -q '^size 20 16' "$tmp/a.txt" || { echo "FAIL: size"; cat "$tmp/a.txt"; exit 1; }
grep -q '<svg' "$tmp/u.svg" || { echo "FAIL: no SVG written"; exit 1; }
# Inflation blocks strictly more cells than r = 0 would: the U-shape's own cells are a subset.
python3 - "$s" "$tmp" "$pathref" <<'PY'
import json, subprocess, sys
scene, tmp, exe = sys.argv[1], sys.argv[2], sys.argv[3]
d = json.load(open(scene)); d["radius"] = 0; d["margin"] = 0
open(tmp + "/zero.json", "w").write(json.dumps(d))
def blocked(path):
    rows = [l for l in subprocess.run([exe, "inflate", path], check=True, capture_output=True, text=True).stdout.splitlines()]
    grid = rows[rows.index("map") + 1:] if "map" in rows else None
    assert grid, rows[:8]
    return {(x, y) for y, row in enumerate(reversed(grid)) for x, ch in enumerate(row) if ch == "#"}
inflated, bare = blocked(scene), blocked(tmp + "/zero.json")
assert bare and bare < inflated, (len(bare), len(inflated))
PY
# The inflated map plans.
expect_exit 0 "" plan --map "$tmp/a.txt" --algo astar
# Errors.
expect_exit 2 "cannot read" inflate "$tmp/none.json"
printf '{"format": "pathref-scene 1", "width": 0}' >"$tmp/bad.json"
expect_exit 2 "$tmp/bad.json" inflate "$tmp/bad.json"
printf '{"format": "pathref-scene 1",\n  "width": 4,,}' >"$tmp/syntax.json"
expect_exit 2 "$tmp/syntax.json:2" inflate "$tmp/syntax.json"
# scenes as maps (spec/formats.md#scene-as-map): plan and convert read .json through the inflation
expect_exit 0 "" plan --map tests/data/scenes/ushape.json --algo astar --json
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['found'] and d['path'][0]==[0,0] and d['path'][-1]==[19,15], d" "$tmp/out"
expect_exit 0 "" inflate tests/data/scenes/ushape.json --out "$tmp/ushape.grid"
expect_exit 0 "" convert tests/data/scenes/ushape.json --to pathref-grid
cmp -s "$tmp/out" "$tmp/ushape.grid" || { echo "FAIL: convert of a scene differs from inflate"; exit 1; }
printf '{"format": "pathref-scene 1", "origin": [0, 0], "width": 4, "height": 4, "cell_size": 1, "radius": 0.5, "margin": 0, "polygons": [{"vertices": [[1, 1], [2, 2], [3, 3]]}], "start": [0, 3], "goal": [3, 0]}' >"$tmp/degenerate.json"
expect_exit 2 "DomainError: $tmp/degenerate.json: /polygons/0: degenerate polygon" plan --map "$tmp/degenerate.json" --algo astar
expect_exit 2 "DomainError: $tmp/degenerate.json: /polygons/0: degenerate polygon" inflate "$tmp/degenerate.json"
expect_exit 2 "tests/data/scenes/ushape.json:5:12: /width: a 20x16 grid exceeds the limit of 10 cells per side" plan --map tests/data/scenes/ushape.json --algo astar --max-side 10
# width or height 0 (issue 27): refused at its value, not as "start ... is not free" or a DomainError
sed 's/"width": 20/"width": 0/' tests/data/scenes/ushape.json >"$tmp/w0.json"
sed 's/"height": 16/"height": 0/' tests/data/scenes/ushape.json >"$tmp/h0.json"
for cmd in "plan --algo astar --map" "plan --algo rrt --map" "inflate"; do
  # shellcheck disable=SC2086
  expect_exit 2 "$tmp/w0.json:5:12: /width: expected an integer in [1, 268435456], got 0" $cmd "$tmp/w0.json"
  # shellcheck disable=SC2086
  expect_exit 2 "$tmp/h0.json:6:13: /height: expected an integer in [1, 268435456], got 0" $cmd "$tmp/h0.json"
done
echo "inflate: ok"
