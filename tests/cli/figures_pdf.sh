#!/usr/bin/env bash
# --svg FILE.pdf (spec/figures.md#pdf): a PDF through rsvg-convert when it is on PATH; without it a
# clear error, exit 2, and no file. The SVG path is unchanged by the PDF option.
# Usage: bash tests/cli/figures_pdf.sh path/to/pathref
set -euo pipefail
pathref=$(realpath "$1")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
source tests/support/expect_exit.sh

# Without rsvg-convert on PATH (an empty PATH folder): exit 2, the message, no PDF, no leftover.
mkdir "$tmp/empty"
set +e; PATH="$tmp/empty" "$pathref" plan --builtin grid20 --algo astar --svg "$tmp/a.pdf" >"$tmp/out" 2>"$tmp/err"; rc=$?; set -e
[ "$rc" = 2 ] || { echo "FAIL: --svg a.pdf without rsvg-convert exited $rc"; cat "$tmp/err"; exit 1; }
grep -qF "cannot write '$tmp/a.pdf': PDF output needs rsvg-convert (Debian librsvg2-bin)" "$tmp/err" ||
  { echo "FAIL: message"; cat "$tmp/err"; exit 1; }
[ ! -e "$tmp/a.pdf" ] && [ ! -e "$tmp/a.pdf.tmp.svg" ] || { echo "FAIL: files left behind"; exit 1; }

if ! command -v rsvg-convert >/dev/null; then
  [ "${CI:-}" != true ] || { echo "FAIL: rsvg-convert missing under CI (tools/deps.sh installs librsvg2-bin)"; exit 1; }
  echo "SKIP: rsvg-convert is not installed"; exit 77
fi
# With it: a PDF (header %PDF), upper-case extension too, and no temporary SVG left.
expect_exit 0 "" plan --builtin grid20 --algo iha --seed 1 --svg "$tmp/b.pdf"
expect_exit 0 "" simulate tests/data/sim/fig8.json --svg "$tmp/c.PDF"
for f in b.pdf c.PDF; do
  head -c 4 "$tmp/$f" | grep -q '%PDF' || { echo "FAIL: $f is not a PDF"; exit 1; }
done
[ ! -e "$tmp/b.pdf.tmp.svg" ] || { echo "FAIL: temporary SVG left behind"; exit 1; }
# .svg stays SVG
expect_exit 0 "" plan --builtin grid20 --algo astar --svg "$tmp/d.svg"
head -c 4 "$tmp/d.svg" | grep -q '<svg' || { echo "FAIL: d.svg is not SVG"; exit 1; }
echo "figures_pdf: ok"
