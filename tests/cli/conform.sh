#!/usr/bin/env bash
# `pathref conform` (spec/conform.md): the example Python adapter passes its rules, the planted
# bug is caught with the first failing vector in full, and a crashing, silent or confused program
# is reported, not hung on.
# Usage: bash tests/cli/conform.sh path/to/pathref   (run from the repository root)
set -euo pipefail
pathref=$(realpath "$1")
root=$PWD
adapter="python3 $root/tools/conform/example_adapter.py"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
sel='grid.*,metrics.*'

source "$(dirname "${BASH_SOURCE[0]}")/../support/expect_exit.sh"

# the adapter answers its six rules; every other selected rule is skipped without being sent
expect_exit 0 "" conform --exec "$adapter" --rules "$sel" --json golden
python3 - "$tmp/out" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["format"] == "pathref-conform-report" and d["program_failure"] is None, d["program_failure"]
r = d["rules"]
for rule in ["grid.coord", "grid.index", "grid.moves", "metrics.length", "metrics.turns", "metrics.valid-path"]:
    assert r[rule]["pass"] > 0 and r[rule]["fail"] == 0, (rule, r[rule])
assert r["metrics.smoothness"]["pass"] == 0 and r["metrics.smoothness"]["skip"] > 0, r["metrics.smoothness"]
assert d["total"]["fail"] == 0 and d["first_failure"] is None
# acceptable (non-default reading) vectors are sent with their interpretation and pass too
assert any(c["rule"] == "grid.coord" and c["status"] == "pass" for c in d["cases"])
PY
expect_exit 0 "total" conform --exec "$adapter" --rules 'grid.coord' golden
grep -qE "^grid.coord +[1-9][0-9]* +0 +0$" "$tmp/out" || { echo "FAIL: table"; cat "$tmp/out"; exit 1; }

# the planted bug (metrics.length drops the last step) is caught, the first failure shown in full
expect_exit 1 "first failing vector:" conform --exec "$adapter --planted-bug" --rules "$sel" golden
grep -qE '"rule": "metrics.length"' "$tmp/out" || { echo "FAIL: first failure not in metrics.length"; cat "$tmp/out"; exit 1; }
grep -qE "^metrics.length +[0-9]+ +[1-9][0-9]* +0$" "$tmp/out" || { echo "FAIL: metrics.length fails"; cat "$tmp/out"; exit 1; }
grep -qE "^grid.coord +[1-9][0-9]* +0 +0$" "$tmp/out" || { echo "FAIL: the other rules still pass"; cat "$tmp/out"; exit 1; }

# broken programs: crash, silence, no hello, wrong id, garbage
cat > "$tmp/crash.py" <<'PY'
import json, sys
sys.stdout.write(json.dumps({"protocol": "pathref-conform", "version": 1}) + "\n"); sys.stdout.flush()
sys.stdin.readline()
sys.exit(7)
PY
expect_exit 1 "program failure: the program closed its output (exit status 7)" conform --exec "python3 $tmp/crash.py" --rules grid.coord golden
cat > "$tmp/silent.py" <<'PY'
import json, sys, time
sys.stdout.write(json.dumps({"protocol": "pathref-conform", "version": 1}) + "\n"); sys.stdout.flush()
time.sleep(30)
PY
start=$(date +%s)
expect_exit 1 "program failure: no answer within 3 s" conform --exec "python3 $tmp/silent.py" --rules grid.coord --timeout 3 golden
[ $(( $(date +%s) - start )) -lt 20 ] || { echo "FAIL: a silent program was waited on too long"; exit 1; }
expect_exit 1 "the program's first line is not the hello" conform --exec "read line; echo hello" --rules grid.coord golden
cat > "$tmp/wrongid.py" <<'PY'
import json, sys
for line in sys.stdin:
    r = json.loads(line)
    a = {"protocol": "pathref-conform", "version": 1} if "protocol" in r else {"id": r["id"] + 1, "output": {}}
    sys.stdout.write(json.dumps(a) + "\n"); sys.stdout.flush()
PY
expect_exit 1 "program failure: out of step: the answer's id is 2, expected 1" conform --exec "python3 $tmp/wrongid.py" --rules grid.coord golden
cat > "$tmp/garbage.py" <<'PY'
import json, sys
for line in sys.stdin:
    r = json.loads(line)
    sys.stdout.write((json.dumps({"protocol": "pathref-conform", "version": 1}) if "protocol" in r else "not json") + "\n"); sys.stdout.flush()
PY
expect_exit 1 "the answer is not a JSON object: not json" conform --exec "python3 $tmp/garbage.py" --rules grid.coord golden

# bad arguments
expect_exit 2 "--rules 'nope.*' selects no golden file in 'golden'" conform --exec true --rules 'nope.*' golden
expect_exit 2 "--timeout expects seconds in (0, 3600]" conform --exec true --timeout 0 golden
expect_exit 2 "--exec is required" conform golden
echo "conform: ok"
