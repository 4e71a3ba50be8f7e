#!/usr/bin/env bash
# `--help` on the program and on every subcommand exits 0 and documents that command's options
# (spec/cli.md). Usage: bash tests/cli/help.sh path/to/pathref
set -euo pipefail
pathref=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# help ARGS... -- WORD...: `pathref ARGS --help` exits 0 and its output contains every WORD.
help() {
  local args=() words=()
  while [ "$1" != "--" ]; do args+=("$1"); shift; done
  shift; words=("$@")
  if ! "$pathref" "${args[@]}" --help >"$tmp/out" 2>&1; then
    echo "FAIL: pathref ${args[*]} --help exited non-zero"; cat "$tmp/out"; exit 1
  fi
  for w in "${words[@]}"; do
    grep -qF -- "$w" "$tmp/out" || { echo "FAIL: pathref ${args[*]} --help lacks '$w'"; cat "$tmp/out"; exit 1; }
  done
}

help -- plan maps eval golden check conform scen convert inflate drive
help check -- --map --builtin --path --path-format --base --origin --policy --start --goal --json --json-out
help conform -- --exec --rules --timeout --json --json-out dir
help scen -- --map --algo --every --digits --json --format --max-side
help convert -- --to --format --swamp --water --unknown --max-side --max-cells
help inflate -- --output --out --svg scene
help drive -- --path --base --cell --svg --json
help plan -- --map --builtin --algo --start --goal --seed --policy --set --json --json-out --svg astar
help maps -- --svg name
help eval -- --list --json rule
help golden -- check regenerate
help golden check -- --verbose dir
help golden regenerate -- dir
help trace-diff -- --context a b
help plan -- --trace
"$pathref" --version | grep -qE '^[0-9]+\.[0-9]+\.[0-9]+' || { echo "FAIL: --version"; exit 1; }
# No subcommand is a usage error (exit 2), not a crash.
set +e; "$pathref" >/dev/null 2>&1; rc=$?; set -e
[ "$rc" = 2 ] || { echo "FAIL: pathref without a subcommand exited $rc, expected 2"; exit 1; }
echo "help: ok"
