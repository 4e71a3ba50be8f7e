#!/usr/bin/env bash
# Memory budgets (spec/cli.md#memory; issue 27): the measured outliers are refused before they
# allocate, under a virtual-memory rlimit far below what they used to take, with exit 2 and a
# message naming the estimate and the limit. No timing: the rlimit bounds memory, ctest's
# timeout bounds time.
# Usage: bash tests/cli/memory.sh path/to/pathref   (from the repository root)
set -euo pipefail
pathref=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# Runs pathref under `ulimit -v KB` (a subshell: the limit ends with it); checks the exit code
# and that stderr contains MSG.
expect_limited() {
  local kb=$1 want=$2 msg=$3; shift 3
  set +e
  if [ "${PATHREF_SANITIZE:-}" = ON ]; then
    # ASan reserves terabytes of address space for its shadow memory, so `ulimit -v` would stop it
    # at start; its own resident-memory limit (about twice the rlimit: shadow and redzones) bounds
    # the run instead.
    ( export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}hard_rss_limit_mb=$(( kb / 512 ))"; exec "$pathref" "$@" ) \
      >"$tmp/out" 2>"$tmp/err"
  else
    ( ulimit -v "$kb"; exec "$pathref" "$@" ) >"$tmp/out" 2>"$tmp/err"
  fi
  local got=$?; set -e
  if [ "$got" != "$want" ]; then
    echo "FAIL: pathref $* (ulimit -v $kb) exited $got, expected $want"; head -c 2000 "$tmp/out"; cat "$tmp/err"; exit 1
  fi
  [ -z "$msg" ] || grep -qF -- "$msg" "$tmp/err" || { echo "FAIL: pathref $*: stderr lacks '$msg':"; cat "$tmp/err"; exit 1; }
}

# 1. aco-classic, 2 ants, 1 iteration, on an empty 4096x4096 map (a 16 MB file): 7.3 GB before
#    issue 27; now 84 bytes per cell = 1409286144 bytes, refused under --max-memory 1G before the
#    colony allocates (the map itself takes 2 x 16 MB).
python3 - "$tmp/empty4096.txt" <<'PY'
import sys
n = 4096
with open(sys.argv[1], "w") as f:
    f.write(f"pathref-grid 1\nsize {n} {n}\nstart 0 0\ngoal {n-1} {n-1}\nmap\n")
    row = "." * n + "\n"
    f.write(row * n)
PY
expect_limited 400000 2 "the ant colony on a 4096x4096 grid (84 bytes per cell) needs an estimated 1409286144 bytes (1.3 GiB), more than the memory limit of 1073741824 bytes (1.0 GiB)" \
  plan --map "$tmp/empty4096.txt" --algo aco-classic --set ants=2 --set iterations=1 --max-memory 1G

# 2. A 229-byte scene declaring a 16384x16384 world: plan --algo astar took 5.1 GB. Refused with
#    the default limit (4 GiB) before the world is rasterised: 2^28 cells x 20 bytes per cell.
cat >"$tmp/huge.json" <<'JSON'
{"format": "pathref-scene 1", "name": "huge", "origin": [0, 0], "width": 16384, "height": 16384, "cell_size": 1,
 "radius": 0.5, "margin": 0, "polygons": [{"vertices": [[100, 100], [200, 100], [200, 200]]}],
 "start": [1, 1], "goal": [16000, 16000]}
JSON
expect_limited 300000 2 "the scene's 16384x16384 world (20 bytes per cell, the grid and the planner's state) needs an estimated 5368709120 bytes (5.0 GiB), more than the memory limit of 4294967296 bytes (4.0 GiB)" \
  plan --map "$tmp/huge.json" --algo astar
# inflate (1 GB before): the raster and its text, 2 bytes per cell, against --max-memory.
expect_limited 300000 2 "the scene's 16384x16384 world (2 bytes per cell" \
  inflate "$tmp/huge.json" --max-memory 256M -o "$tmp/huge.txt"
[ ! -e "$tmp/huge.txt" ] || { echo "FAIL: inflate wrote a file before refusing"; exit 1; }

# 3. A path file of 2^24 + 1 nodes (1.5 GB before its limit error): refused at the first node too
#    many, holding the text and nothing per number.
python3 -c "import sys; sys.stdout.write('7\\n' * (2**24 + 1))" >"$tmp/long.txt"
expect_limited 400000 2 "long.txt:16777217:1: a path has more than 16777216 nodes" \
  check --path "$tmp/long.txt" --path-format node --builtin grid20

# 4. The option itself: a bad size is exit 2 naming the option; sizes are on every map reader.
expect_limited 400000 2 "--max-memory expects a size in bytes" plan --builtin grid20 --algo astar --max-memory 12Q
expect_limited 400000 2 "--max-memory expects a size in bytes" inflate tests/data/scenes/ushape.json --max-memory 0
expect_limited 400000 0 "" plan --builtin grid20 --algo astar --max-memory 64M
python3 -c 'import sys; n=256; sys.stdout.write(f"pathref-grid 1\nsize {n} {n}\nstart 0 0\ngoal {n-1} {n-1}\nmap\n" + ("." * n + "\n") * n)' >"$tmp/empty256.txt"
expect_limited 400000 2 "astar on a 256x256 grid (20 bytes per cell) needs an estimated 1310720 bytes (1.2 MiB), more than the memory limit of 1048576 bytes (1.0 MiB)" \
  plan --map "$tmp/empty256.txt" --algo astar --max-memory 1M
expect_limited 400000 0 "" plan --map "$tmp/empty256.txt" --algo astar --max-memory 2M
echo "memory: ok"
