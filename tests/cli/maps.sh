#!/usr/bin/env bash
# `pathref maps` lists the built-ins; `pathref maps NAME` prints one as pathref-grid 1 text that
# `plan --map` reads back to the same map (spec/cli.md#maps, spec/formats.md).
# Usage: bash tests/cli/maps.sh path/to/pathref
set -euo pipefail
pathref=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

"$pathref" maps >"$tmp/list.txt"
grep -qE '^grid20  20x20  start \(0, 0\)  goal \(19, 19\)  92 blocked cells$' "$tmp/list.txt" || { echo "FAIL: grid20 line"; cat "$tmp/list.txt"; exit 1; }
grep -qE '^shi6x6  6x6  start \(0, 0\)  goal \(5, 5\)  5 blocked cells$' "$tmp/list.txt" || { echo "FAIL: shi6x6 line"; cat "$tmp/list.txt"; exit 1; }
grep -qF 'RECONSTRUCTED' "$tmp/list.txt" || { echo "FAIL: the reconstructed map does not say so"; exit 1; }

for name in grid20 shi6x6; do
  "$pathref" maps "$name" --svg "$tmp/$name.svg" >"$tmp/$name.txt"
  head -n1 "$tmp/$name.txt" | grep -qx 'pathref-grid 1' || { echo "FAIL: $name text header"; exit 1; }
  # Same result from the exported file as from the built-in (only the map's source differs).
  "$pathref" plan --builtin "$name" --algo astar --json >"$tmp/$name.b.json"
  "$pathref" plan --map "$tmp/$name.txt" --algo astar --json >"$tmp/$name.f.json"
  python3 - "$tmp/$name.b.json" "$tmp/$name.f.json" "$tmp/$name.svg" <<'PY'
import json, sys
import xml.etree.ElementTree as ET
b, f = (json.load(open(p)) for p in sys.argv[1:3])
assert b["map"]["source"] == "builtin" and f["map"]["source"] == "file"
assert f["map"]["name"] == b["map"]["name"], (f["map"]["name"], b["map"]["name"])
for d in (b, f):
    del d["map"]["source"], d["map"]["file"]
assert b == f, "built-in and exported file give different runs"
ns = "{http://www.w3.org/2000/svg}"
root = ET.parse(sys.argv[3]).getroot()
obst = [e for e in root.iter(ns + "rect") if e.get("class") == "obstacle"]
assert len(obst) == b["map"]["blocked"], (len(obst), b["map"]["blocked"])
assert not [e for e in root.iter(ns + "polyline") if e.get("class") == "path"]
assert [e for e in root.iter(ns + "g") if e.get("class") == "start"]
PY
done

set +e; "$pathref" maps nope >/dev/null 2>"$tmp/err"; rc=$?; set -e
[ "$rc" = 2 ] && grep -qF "unknown built-in map 'nope' (known: grid20, shi6x6)" "$tmp/err" || { echo "FAIL: maps nope (rc $rc)"; cat "$tmp/err"; exit 1; }
set +e; "$pathref" maps --svg "$tmp/x.svg" >/dev/null 2>"$tmp/err"; rc=$?; set -e
[ "$rc" = 2 ] || { echo "FAIL: maps --svg without NAME exited $rc"; exit 1; }
echo "maps: ok"
