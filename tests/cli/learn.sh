#!/usr/bin/env bash
# `pathref learn` and `pathref classify` (spec/cin2021-ml.md#cli): a small hand data set (GNB
# and the tree classify their own training rows; the model file round-trips through classify),
# every error is exit 2 naming file, line and column; with ../shared present, the paper's tenfold
# GNB accuracy on the 4-sensor file (88.416 %, equal to scikit-learn's).
# Usage: bash tests/cli/learn.sh path/to/pathref
set -euo pipefail
pathref=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# a separable 2-sensor data set: front distance large -> Move-Forward, small -> Sharp-Right-Turn
: >"$tmp/d.data"
for i in 0 1 2 3 4 5; do
  printf '%s.5,1.0%s,Move-Forward\r\n0.%s,1.1%s,Sharp-Right-Turn\r\n' "$((i + 3))" "$i" "$((i + 2))" "$i" >>"$tmp/d.data"
done
"$pathref" learn --data "$tmp/d.data" --classifier gnb,tree,knn --cv 3 --set k=1 >"$tmp/out.txt"
grep -q 'classifier gnb' "$tmp/out.txt" || fail "no gnb section"
grep -q 'accuracy (Eq. 7)     1.000000' "$tmp/out.txt" || { cat "$tmp/out.txt"; fail "separable data: accuracy 1 expected"; }
grep -q 'MCC (Eq. 11' "$tmp/out.txt" || fail "no MCC line"
"$pathref" learn --data "$tmp/d.data" --classifier gnb --holdout 0.5 --seed 3 --json --save-model "$tmp/m.json" >"$tmp/out.json"
grep -q '"test_rows": 6' "$tmp/out.json" || fail "hold-out 0.5 of 12 rows: 6 test rows"
grep -q '"format":"pathref-ml-model"' "$tmp/m.json" || fail "model file format"
[ "$("$pathref" classify --model "$tmp/m.json" 6.5 1.0)" = "0 Move-Forward" ] || fail "classify 6.5 1.0"
[ "$("$pathref" classify --model "$tmp/m.json" 0.1 1.2)" = "2 Sharp-Right-Turn" ] || fail "classify 0.1 1.2"

# errors: exit 2, file:line:column
expect2() { local out; set +e; out=$("$@" 2>&1); local rc=$?; set -e; [ $rc -eq 2 ] || fail "exit $rc (expected 2): $*"; echo "$out"; }
printf '1,2,Move-Forward\n1,x,Move-Forward\n' >"$tmp/bad.data"
expect2 "$pathref" learn --data "$tmp/bad.data" --cv 2 | grep -q "bad.data:2:3: a decimal number" || fail "bad number message"
printf '1,2,Move-Forward\n1,2,Go-Back\n' >"$tmp/bad2.data"
expect2 "$pathref" learn --data "$tmp/bad2.data" --cv 2 | grep -q "bad2.data:2:5: a label" || fail "bad label message"
expect2 "$pathref" learn --data "$tmp/d.data" >/dev/null                     # neither --cv nor --holdout
expect2 "$pathref" learn --data "$tmp/d.data" --cv 2 --holdout 0.3 >/dev/null
expect2 "$pathref" learn --data "$tmp/d.data" --holdout 1.5 >/dev/null
expect2 "$pathref" learn --data "$tmp/d.data" --cv 2 --set bogus=1 >/dev/null
expect2 "$pathref" learn --data "$tmp/d.data" --cv 2 --classifier lda >/dev/null
expect2 "$pathref" classify --model "$tmp/m.json" 1 >/dev/null               # wrong number of values
echo '{"format":"pathref-ml-model","version":9}' >"$tmp/v9.json"
expect2 "$pathref" classify --model "$tmp/v9.json" 1 2 | grep -qF "v9.json:1:40: /version: expected 1 (this reader reads model file version 1), got 9" || fail "version message"

# model files (issue 27): every refusal at its line, column and JSON pointer, never library text
sed 's/"mean":\[[^]]*\]/"mean":"abc"/' "$tmp/m.json" >"$tmp/m_mean.json"
out=$(expect2 "$pathref" classify --model "$tmp/m_mean.json" 1 2)
echo "$out" | grep -q "m_mean.json:1:[0-9]*: /model/mean: expected an array, got a string" || fail "model type message: $out"
echo "$out" | grep -q "json.exception" && fail "library text in: $out"
sed 's/"var_smoothing"/"var_smoothin"/' "$tmp/m.json" >"$tmp/m_key.json"
out=$(expect2 "$pathref" classify --model "$tmp/m_key.json" 1 2)
echo "$out" | grep -q "m_key.json:1:[0-9]*: /params: missing key \"var_smoothing\"" || fail "model missing key message: $out"
"$pathref" learn --data "$tmp/d.data" --classifier tree --holdout 0.5 --save-model "$tmp/t.json" >/dev/null
sed 's/"feature":/"featur":/' "$tmp/t.json" >"$tmp/t_key.json"
out=$(expect2 "$pathref" classify --model "$tmp/t_key.json" 1 2)
echo "$out" | grep -q "t_key.json:1:[0-9]*: /model: missing key \"feature\"" || fail "tree missing key message: $out"
echo "$out" | grep -q "not found" && fail "library text in: $out"

# classify's values (issue 27): negative numbers and -inf are values, never options
[ "$("$pathref" classify --model "$tmp/m.json" 6.5 -1.0)" = "0 Move-Forward" ] || fail "classify 6.5 -1.0"
[ "$("$pathref" classify --model "$tmp/m.json" -.5 1.2)" = "2 Sharp-Right-Turn" ] || fail "classify -.5 1.2"
"$pathref" classify --model "$tmp/m.json" -.5 1.2 --json | grep -q '"label":"Sharp-Right-Turn"' || fail "classify -.5 1.2 --json"
expect2 "$pathref" classify --model "$tmp/m.json" 1 -inf | grep -qF "sensor distance '-inf' is not a finite number" || fail "-inf message"
expect2 "$pathref" classify --model "$tmp/m.json" -inf 1 --json | grep -qF "sensor distance '-inf' is not a finite number" || fail "leading -inf message"
expect2 "$pathref" classify --model "$tmp/m.json" inf -inf | grep -qF "sensor distance 'inf' is not a finite number" || fail "inf message"
expect2 "$pathref" classify --model "$tmp/m.json" 1 2 --jsn | grep -qF "unknown option '--jsn'" || fail "unknown option message"

# KNN and finite values whose squared distance overflows (spec/cin2021-ml.md, cin2021.knn domain)
"$pathref" learn --data "$tmp/d.data" --classifier knn --set k=1 --holdout 0.5 --save-model "$tmp/knn.json" >/dev/null
[ "$("$pathref" classify --model "$tmp/knn.json" 6.5 1.0)" = "0 Move-Forward" ] || fail "knn classify 6.5 1.0"
"$pathref" classify --model "$tmp/knn.json" 1e150 1.0 >/dev/null || fail "knn classify 1e150 1.0 (finite distances)"
out=$(expect2 "$pathref" classify --model "$tmp/knn.json" 1e308 1e308)
echo "$out" | grep -qF "outside the model's domain: KNN: the squared distance from the sample to training row 0 overflows" || fail "knn overflow message: $out"

# unreadable inputs: the reason, never "(empty file)"
expect2 "$pathref" learn --data "$tmp" --cv 2 | grep -qF "cannot read data file '$tmp': it is a directory" || fail "directory message"
expect2 "$pathref" learn --data "$tmp/absent.data" --cv 2 | grep -qF "cannot read data file '$tmp/absent.data': No such file or directory" || fail "missing file message"
expect2 "$pathref" classify --model "$tmp" 1 2 | grep -qF "cannot read model file '$tmp': it is a directory" || fail "model directory message"

data="$(dirname "$0")/../../../shared/data/uci-wall-following/sensor_readings_4.data"
if [ -f "$data" ]; then
  "$pathref" learn --data "$data" --classifier gnb,mnb --cv 10 --json >"$tmp/uci.json"
  grep -q '"accuracy": 0.8841642228739003' "$tmp/uci.json" || fail "GNB tenfold accuracy 0.8841642228739003 (scikit-learn 1.2.1)"
  grep -q '"accuracy": 0.5837609970674487' "$tmp/uci.json" || fail "MNB tenfold accuracy 0.5837609970674487 (scikit-learn 1.2.1)"
else
  echo "skipped the UCI part: $data is absent"
fi
echo "learn.sh: ok"
