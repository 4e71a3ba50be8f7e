#!/usr/bin/env bash
# Runs every command of README.md's ```sh blocks (issue 16: "every README command works"), in a
# fresh temporary folder that sees the repository's golden/, tests/, tools/, spec/ and the built
# program as build/pathref, so a command that needs a file the README does not create fails here.
# Not run: `bash tools/test` and `bash tools/demo` (CI runs those themselves). Commands reading
# ../shared run only when the shared data folder exists (skipped with a message otherwise).
# Normal build only (tests/CMakeLists.txt). Usage: readme_commands.sh PATHREF REPO_ROOT
set -euo pipefail
pathref=$(realpath "$1")
root=$(realpath "$2")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/repo/build"
for d in golden tests tools spec; do ln -s "$root/$d" "$tmp/repo/$d"; done
ln -s "$pathref" "$tmp/repo/build/pathref"
have_shared=0
if [ -d "$root/../shared/data" ]; then ln -s "$(realpath "$root/../shared")" "$tmp/shared"; have_shared=1; fi

# The commands: every line of every ```sh block, with '\' continuations joined.
python3 - "$root/README.md" > "$tmp/commands" <<'PY'
import sys
lines, inside = [], False
for raw in open(sys.argv[1], encoding="utf-8"):
    s = raw.rstrip("\n")
    if s.startswith("```"):
        inside = s.strip() == "```sh" if not inside else False
        continue
    if inside and s.strip() and not s.lstrip().startswith("#"):
        lines.append(s)
cmds, cur = [], ""
for s in lines:
    cur += s
    if cur.endswith("\\"):
        cur = cur[:-1] + " "
        continue
    cmds.append(cur.strip())
    cur = ""
print("\n".join(cmds))
PY
cd "$tmp/repo"
n=0 skipped=0 skipped_outputs=""
while IFS= read -r cmd; do
  case "$cmd" in
    "bash tools/test"*|"bash tools/demo"*) skipped=$((skipped + 1)); continue ;;
  esac
  # A command that reads a file written by a skipped command (out/...) is skipped too.
  needs_skipped=0
  for f in $skipped_outputs; do [[ " $cmd " == *" $f "* ]] && needs_skipped=1; done
  if [[ "$cmd" == *"../shared"* && $have_shared == 0 ]] || [ $needs_skipped == 1 ]; then
    echo "SKIP (no ../shared/data, or needs the output of a command skipped for it): $cmd"
    skipped=$((skipped + 1))
    skipped_outputs="$skipped_outputs $(grep -o 'out/[^ ]*' <<< "$cmd" | tr '\n' ' ' || true)"
    continue
  fi
  n=$((n + 1))
  start=$(date +%s%N)
  set +e; bash -c "$cmd" > "$tmp/out" 2> "$tmp/err" < /dev/null; rc=$?; set -e
  ms=$(( ($(date +%s%N) - start) / 1000000 ))
  if [ $rc -ne 0 ]; then
    echo "FAIL (exit $rc): $cmd"; head -20 "$tmp/out" "$tmp/err"; exit 1
  fi
  printf 'ok %6d ms  %s\n' "$ms" "$cmd"
done < "$tmp/commands"
[ $n -ge 10 ] || { echo "FAIL: only $n commands found in README.md"; exit 1; }
echo "readme: $n commands ran, $skipped skipped"
