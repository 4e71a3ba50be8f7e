#!/usr/bin/env bash
# `pathref golden regenerate` on a copy of golden/ must change nothing: every library-produced
# (characterization) value in golden/ is what the library computes now, bit for bit, and
# regenerate leaves hand-, paper- and crosscheck-provenance values alone.
# Usage: regenerate_noop.sh PATHREF GOLDEN_DIR
set -euo pipefail
pathref=$1 golden=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cp -r "$golden" "$tmp/golden"
"$pathref" golden regenerate "$tmp/golden" > "$tmp/log"
if ! diff -r "$golden" "$tmp/golden" > "$tmp/diff"; then
  echo "FAIL: golden regenerate changed files:"; head -40 "$tmp/diff"; exit 1
fi
grep -qF "0 file(s) changed" "$tmp/log" || { echo "FAIL: unexpected regenerate output:"; cat "$tmp/log"; exit 1; }
echo "golden regenerate: no-op"
