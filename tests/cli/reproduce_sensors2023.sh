#!/usr/bin/env bash
# `pathref reproduce sensors2023` (spec/sensors2023-dwa.md "Reproduction"): the options are
# documented, bad input is exit 2 with a clear message. The run itself (hundreds of simulations)
# belongs to the reproduction, not to ctest: docs/reproduction/sensors2023.md is its output.
# Usage: bash tests/cli/reproduce_sensors2023.sh path/to/pathref   (from the repository root)
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

"$pathref" reproduce --help | grep -qF sensors2023 || { echo "FAIL: reproduce --help lacks sensors2023"; exit 1; }
for w in --maps --seed --out-dir --quick --jobs; do
  "$pathref" reproduce sensors2023 --help | grep -qF -- "$w" || { echo "FAIL: --help lacks $w"; exit 1; }
done
expect_exit 2 "--jobs" reproduce sensors2023 --jobs 0 --out-dir "$tmp/o"
expect_exit 2 "--maps" reproduce sensors2023 --maps 0 --out-dir "$tmp/o"
expect_exit 2 "--seed must leave room" reproduce sensors2023 --seed 4294967295 --out-dir "$tmp/o"
[ ! -e "$tmp/o" ] || { echo "FAIL: a rejected command wrote $tmp/o"; exit 1; }
echo "cli.reproduce_sensors2023: ok"
