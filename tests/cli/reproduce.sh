#!/usr/bin/env bash
# `pathref reproduce` (spec/reproduce.md): bad input is exit 2 with a clear message; `--quick` runs of
# both protocols write the report, its JSON and figures, the JSON parses, and every number of the
# markdown's tables equals the JSON's. shi2022 needs the shared MATLAB maps (../shared/data/matlab-maps)
# and is skipped with a message when they are absent.
# Usage: bash tests/cli/reproduce.sh path/to/pathref   (from the repository root)
set -euo pipefail
pathref=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")  # absolute: some steps run in another directory
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

expect_exit() {
  local want=$1 msg=$2; shift 2
  set +e; "$pathref" "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?; set -e
  if [ "$got" != "$want" ]; then
    echo "FAIL: pathref $* exited $got, expected $want"; cat "$tmp/out" "$tmp/err"; exit 1
  fi
  [ -z "$msg" ] || grep -qF -- "$msg" "$tmp/err" || { echo "FAIL: pathref $*: stderr lacks '$msg':"; cat "$tmp/err"; exit 1; }
}

# ---- --help ---------------------------------------------------------------------------------------
"$pathref" --help | grep -qF reproduce || { echo "FAIL: pathref --help lacks reproduce"; exit 1; }
"$pathref" reproduce --help | grep -qF shi2022 || { echo "FAIL: reproduce --help lacks shi2022"; exit 1; }
for w in --simple --complex --runs --seed --out-dir --policy --quick; do
  "$pathref" reproduce shi2022 --help | grep -qF -- "$w" || { echo "FAIL: reproduce shi2022 --help lacks $w"; exit 1; }
done
for w in --runs --sweep-runs --maps-per-edge --edges --seed --out-dir --quick; do
  "$pathref" reproduce han --help | grep -qF -- "$w" || { echo "FAIL: reproduce han --help lacks $w"; exit 1; }
done

# ---- bad input (no shared data needed) ---------------------------------------------------------
printf '0 0 0\n0 0 0\n0 0 0\n' >"$tmp/free.txt"
printf '1 0 0\n0 0 0\n0 0 0\n' >"$tmp/blocked.txt"
printf '0 0 0\n0 0 0\n0 0 1\n' >"$tmp/goal.txt"
expect_exit 2 "" reproduce
expect_exit 2 "--complex is required" reproduce shi2022 --simple "$tmp/free.txt"
expect_exit 2 "cannot read map file '$tmp/missing.txt'" reproduce shi2022 --simple "$tmp/missing.txt" --complex "$tmp/free.txt" --out-dir "$tmp/o"
expect_exit 2 "--runs expects a decimal integer from 1 to 10000, got '0'" reproduce shi2022 --simple "$tmp/free.txt" --complex "$tmp/free.txt" --runs 0 --out-dir "$tmp/o"
expect_exit 2 "--runs expects a decimal integer from 1 to 10000, got 'x'" reproduce han --runs x --out-dir "$tmp/o"
expect_exit 2 "--runs expects a decimal integer from 1 to 10000, got '-3'" reproduce han --runs=-3 --out-dir "$tmp/o"
expect_exit 2 "--seed expects a decimal integer from 0 to 4294967295, got '4294967296'" reproduce han --seed 4294967296 --out-dir "$tmp/o"
expect_exit 2 "--seed + --runs - 1 must not exceed 4294967295" reproduce shi2022 --simple "$tmp/free.txt" --complex "$tmp/free.txt" --seed 4294967295 --runs 2 --out-dir "$tmp/o"
expect_exit 2 "--orientation: up not in {paper,file}" reproduce shi2022 --simple "$tmp/free.txt" --complex "$tmp/free.txt" --orientation up --out-dir "$tmp/o"
expect_exit 2 "--edges expects a decimal integer from 2 to 1000, got 'y'" reproduce han --edges 10,y --out-dir "$tmp/o"
expect_exit 2 "start (0, 0) is a blocked cell of the simple map '$tmp/blocked.txt'" reproduce shi2022 --simple "$tmp/blocked.txt" --complex "$tmp/free.txt" --out-dir "$tmp/o"
expect_exit 2 "goal (2, 2) is a blocked cell of the complex map '$tmp/goal.txt'" reproduce shi2022 --simple "$tmp/free.txt" --complex "$tmp/goal.txt" --out-dir "$tmp/o"
[ ! -e "$tmp/o" ] || { echo "FAIL: a failed reproduce wrote $tmp/o"; exit 1; }

# ---- the markdown's numbers are the JSON's --------------------------------------------------------
check_report() {  # paper out-dir
  python3 - "$1" "$2" <<'PY'
import json, re, sys
paper, out = sys.argv[1], sys.argv[2]
doc = json.load(open(f"{out}/{paper}/reproduce.json"))
md = open(f"{out}/{paper}.md").read()
assert doc["format"] == "pathref-reproduce" and doc["format_version"] == 1 and doc["paper"] == paper, doc.keys()
assert doc["protocol"]["quick"] is True
assert "QUICK RUN" in md
for key in ("command", "build_type", "date_utc", "machine"):
    assert doc["provenance"][key], key
    assert str(doc["provenance"][key]) in md, key

def fx(v, d):
    return "—" if v is None else format(v, f".{d}f")

def table(marker):
    i = md.index(f"<!-- results:{marker} -->")
    rows = []
    for line in md[i:].splitlines()[3:]:
        if not line.startswith("|"):
            break
        rows.append([c.strip() for c in line.strip().strip("|").split("|")])
    return rows

checked = 0
if paper == "shi2022":
    # the main tables list the default series; each reading's table its planners and PLANNER@KEY
    tables = [(key, key, [n for n in doc["results"][key] if "@" not in n]) for key in ("simple", "complex", "shi6x6")]
    for rd in doc["protocol"]["readings"]:
        for key in ("simple", "complex"):
            tables.append((key, f"{key}-{rd['key']}", [n for p in rd["planners"] for n in (p, p + "@" + rd["key"])]))
    every = {key: sorted(n for n in doc["results"][key]) for key in ("simple", "complex", "shi6x6")}
    for key in ("simple", "complex"):
        listed = set(n for k, _, names in tables if k == key for n in names)
        assert sorted(listed) == every[key], (key, sorted(listed), every[key])
    for key, marker, names in tables:
        res = doc["results"][key]
        rows = table(marker)
        assert sorted(r[0] for r in rows) == sorted(f"`{n}`" for n in names), (marker, [r[0] for r in rows])
        for r in rows:
            series = res[r[0].strip("`")]
            if not series["available"]:
                assert r[1] == "not available in this build", r
                continue
            s = series["summary"]
            want = [str(s["runs"]), str(s["found"]), str(s["valid"]),
                    fx(s["length"]["min"], 4), fx(s["length"]["mean"], 4), fx(s["length"]["std"], 4),
                    fx(s["turns"]["mean"], 2), fx(s["turns"]["std"], 2), fx(s["turns"]["min"], 0),
                    fx(s["converged_at"]["mean"], 2), fx(s["converged_at"]["std"], 2),
                    fx(s["converged_at_whole_curve"]["mean"], 2), fx(s["drive_time_s"]["mean"], 2),
                    fx(s["wall_ms"]["mean"], 1)]
            assert r[1:] == want, (key, r, want)
            # the summary is the runs' statistics
            lengths = [x["length"] for x in series["runs"] if x["found"]]
            assert s["found"] == len(lengths)
            if lengths:
                assert s["length"]["min"] == min(lengths)
                assert abs(s["length"]["mean"] - sum(lengths) / len(lengths)) < 1e-9
            checked += 1
    # the maps' optima (protocol check M.1, M.2) are the Shi optima on the shared maps
    assert abs(doc["results"]["simple"]["dijkstra"]["summary"]["length"]["min"] - (10 + 14 * 2 ** 0.5)) < 1e-12
    assert abs(doc["results"]["complex"]["dijkstra"]["summary"]["length"]["min"] - (16 + 11 * 2 ** 0.5)) < 1e-12
    assert doc["maps"]["simple"]["start"] == [0, 0] and doc["maps"]["simple"]["goal"] == [19, 19]
    assert doc["maps"]["simple"]["orientation"] == "paper"
else:
    rows = table("edges")
    assert len(rows) == len(doc["edges"]) == 2, rows
    for r, e in zip(rows, doc["edges"]):
        v = e["variants"]
        f = lambda k: f'{v[k]["found"]}/{v[k]["runs"]}' if k in v else "—"
        # variants restricted to some edges (only_edges) are absent elsewhere: "—"
        want = [str(e["edge"]), f'{e["degenerate_maps"]}/{v["iaco-han"]["maps"]}',
                fx(v["iaco-han"]["min_length"], 4), fx(v["aco"]["min_length"], 4),
                fx(v["astar-han"]["min_length"], 4), fx(v.get("iaco-han:1/d", {}).get("min_length"), 4),
                fx(v.get("aco:1/d", {}).get("min_length"), 4), f("iaco-han"), f("aco"), f("iaco-han@die"), f("aco@die"),
                fx(v["iaco-han"]["converged_at"], 2), fx(v["aco"]["converged_at"], 2),
                fx(v["iaco-han"]["wall_ms"], 1), fx(v["aco"]["wall_ms"], 1)]
        assert r == want, (r, want)
        checked += 1
    rows = table("dynamic")
    assert len(rows) == len(doc["edges"]), rows
    for r, e in zip(rows, doc["edges"]):
        a, b = e["dynamic"]["iaco-han"], e["dynamic"]["aco"]
        want = [str(e["edge"]), fx(a["min_distance"], 4), fx(b["min_distance"], 4), fx(a["min_time"], 2),
                fx(b["min_time"], 2), f'{a["reached"]}/{a["simulated"]}', f'{b["reached"]}/{b["simulated"]}',
                str(a["collided"]), str(b["collided"]), str(a["unexplained_collisions"] + b["unexplained_collisions"]),
                fx(a["waits"], 2), fx(a["replans"], 2), fx(a["evasions"], 2)]
        assert r == want, (r, want)
        checked += 1
    # the per-map dynamic summaries are the statistics of their runs (collision-free, goal reached)
    for m in doc["maps"]:
        for key, d in m["dynamic"].items():
            ok = [x["distance"] for x in d["runs"] if x["simulated"] and x["reached_goal"] and x["collision_steps"] == 0]
            assert d["summary"]["distance"]["n"] == len(ok), (key, d["summary"])
            if ok:
                assert d["summary"]["distance"]["min"] == min(ok)
            # every simulated run has its two scripted obstacles recorded
            assert all(len(x["obstacles"]) == 2 for x in d["runs"] if x["simulated"])
    for m in doc["maps"]:
        assert m["edge"] in (10, 15) and len(m["rows"]) == m["edge"]
# the claims table: one row per claim, the same 'paper', 'pathref' and verdict texts (at n and 2n)
VERDICTS = ("holds", "does not hold", "not significant", "inconclusive", "cannot be tested")
def claim_table(start):
    i = md.index(start)
    j = min([k for k in (md.find("\n## ", i + 1), md.find("\n### ", i + 1)) if k > 0] or [len(md)])
    return [[c.strip() for c in l.strip().strip("|").split("|")] for l in md[i:j].splitlines()
            if l.startswith("| ") and not l.startswith("| id") and not l.startswith("| ---")]
def check_claims(rows, claims):
    assert len(rows) == len(claims) > 0, (len(rows), len(claims))
    for r, c in zip(rows, claims):
        assert r[0].replace(" †", "") == c["id"] and r[3] == c["paper"] and r[4] == c["ours"], (r, c)
        assert (" †" in r[0]) == bool(c["depends_on"]), (r, c)
        assert r[5].strip("*") == c["verdict_text"] and c["verdict_text"].startswith(c["verdict"]), (r, c)
        assert c["verdict"] in VERDICTS, c
        a2 = c["at_2n"]
        assert r[6] == ("—" if a2 is None else ("**changed:** " if c["changed"] else "") + a2["verdict_text"]), (r, c)
        # every tested claim carries the statistics that decided it (stats.*)
        if c["verdict"] != "cannot be tested" and not c["id"].startswith(("M.", "C.")):
            assert c["statistics"] is not None, c
check_claims(claim_table("## Claims"), doc["claims"])
if "checks" in doc:
    check_claims(claim_table("## pathref's checks"), doc["checks"])
if paper == "shi2022":  # the claims under other readings (reproduce.shi2022.readings)
    rows = claim_table("Summary under the other readings")
    check_claims(rows, doc["reading_claims"])
    suffixes = {rd["suffix"] for rd in doc["protocol"]["readings"]}
    for c in doc["reading_claims"]:
        assert c["id"][-1] in suffixes and "[reading: " in c["text"], c
print(f"{paper}: {checked} result rows and {len(doc['claims'])} claims agree")
PY
}

# ---- han --quick (generated maps: no shared data needed) ----------------------------------------
expect_exit 0 "" reproduce han --quick --out-dir "$tmp/r"
grep -qF "wrote $tmp/r/han.md" "$tmp/out" || { echo "FAIL: no 'wrote' line for han.md"; cat "$tmp/out"; exit 1; }
grep -qF "[reproduce] han edge 10 map 1" "$tmp/err" || { echo "FAIL: no progress on stderr"; cat "$tmp/err"; exit 1; }
for f in han.md han/reproduce.json han/length-vs-edge.svg han/time-vs-edge.svg han/convergence-10m.svg han/paths-10m.svg han/dynamic-10m.svg; do
  [ -s "$tmp/r/$f" ] || { echo "FAIL: $f not written"; exit 1; }
done
check_report han "$tmp/r"

# ---- --jobs, --emit-jobs, --merge (reproduce.execution; docs/reproduction/README.md) -------------------
same_results() {  # two reproduce.json: equal in every field except the measured wall times and provenance
  python3 - "$1" "$2" <<'PY'
import json, sys
def strip(x):
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items() if k not in ("wall_ms", "provenance", "planning-time")}
    if isinstance(x, list):
        return [strip(v) for v in x]
    return x
a, b = (json.load(open(f)) for f in sys.argv[1:3])
# per-edge wall-time aggregates are measurements too
for d in (a, b):
    for e in d.get("edges", []):
        for v in e.get("variants", {}).values():
            v.pop("wall_ms", None)
sa, sb = strip(a), strip(b)
if sa != sb:
    for k in sa:
        if sa[k] != sb.get(k):
            print("differs:", k)
    sys.exit(1)
PY
}
expect_exit 0 "" reproduce han --quick --out-dir "$tmp/j2" --jobs 2
grep -qF -- "--jobs 2" "$tmp/j2/han.md" || { echo "FAIL: the report does not record --jobs 2"; exit 1; }
grep -qF "measured under 2 parallel jobs" "$tmp/j2/han.md" || { echo "FAIL: wall times not marked as measured under 2 jobs"; exit 1; }
same_results "$tmp/r/han/reproduce.json" "$tmp/j2/han/reproduce.json" || { echo "FAIL: --jobs 2 differs from --jobs 1"; exit 1; }
expect_exit 2 "--jobs expects a decimal integer from 1 to 256, got '0'" reproduce han --quick --jobs 0 --out-dir "$tmp/o"
expect_exit 2 "--emit-jobs and --merge exclude each other" reproduce han --quick --emit-jobs "$tmp/x.txt" --merge "$tmp" --out-dir "$tmp/o"
expect_exit 2 "--merge: '$tmp/nonexistent' is not a directory" reproduce han --quick --merge "$tmp/nonexistent" --out-dir "$tmp/o"
# emit: one self-contained command per run, no report
(cd "$tmp" && "$pathref" reproduce han --quick --emit-jobs jobs.txt --out-dir "$tmp/e" >"$tmp/out" 2>"$tmp/err") ||
  { echo "FAIL: --emit-jobs"; cat "$tmp/out" "$tmp/err"; exit 1; }
[ ! -e "$tmp/e/han.md" ] || { echo "FAIL: --emit-jobs wrote a report"; exit 1; }
[ -d "$tmp/jobs.txt.results" ] || { echo "FAIL: --emit-jobs did not create jobs.txt.results"; exit 1; }
njobs=$(wc -l <"$tmp/jobs.txt")
[ "$njobs" -gt 10 ] || { echo "FAIL: only $njobs jobs"; exit 1; }
grep -q "reproduce run-job '{" "$tmp/jobs.txt" || { echo "FAIL: jobs are not run-job commands"; head -c 300 "$tmp/jobs.txt"; exit 1; }
# merging before the jobs ran: a clear error
expect_exit 2 "--merge: no result for the run" reproduce han --quick --merge "$tmp/jobs.txt.results" --out-dir "$tmp/o"
if command -v parallel >/dev/null; then
  # the README's GNU parallel example, on the --quick protocol
  (cd "$tmp" && parallel -j 2 < jobs.txt) || { echo "FAIL: parallel < jobs.txt"; exit 1; }
  [ "$(ls "$tmp/jobs.txt.results" | wc -l)" = "$njobs" ] || { echo "FAIL: not every job wrote its result"; exit 1; }
  (cd "$tmp" && "$pathref" reproduce han --quick --merge jobs.txt.results --out-dir "$tmp/m" >"$tmp/out" 2>"$tmp/err") ||
    { echo "FAIL: --merge"; cat "$tmp/out" "$tmp/err"; exit 1; }
  same_results "$tmp/r/han/reproduce.json" "$tmp/m/han/reproduce.json" || { echo "FAIL: --merge differs from --jobs 1"; exit 1; }
  grep -qF "merged with \`--merge\`" "$tmp/m/han.md" || { echo "FAIL: the merged report does not say so"; exit 1; }
  # a result file that is not a run-job output
  echo '{}' >"$tmp/jobs.txt.results/zzz.json"
  expect_exit 2 "is not the output of 'pathref reproduce run-job'" reproduce han --quick --merge "$tmp/jobs.txt.results" --out-dir "$tmp/o"
elif [ "${CI:-}" = "true" ]; then
  echo "FAIL: GNU parallel is missing (tools/deps.sh installs it)"; exit 1
else
  echo "skipped: GNU parallel is not installed (apt-get install parallel); the --emit-jobs/--merge round trip was not run"
fi
# one job by hand: a tampered job is refused
line=$(head -n 1 "$tmp/jobs.txt")
job=$(python3 -c "import shlex,sys; w=shlex.split(sys.argv[1]); print(w[3])" "$line")
"$pathref" reproduce run-job "$job" | python3 -c "import json,sys; d=json.load(sys.stdin); assert d['format']=='pathref-reproduce-run' and d['record']['seed']>=1, d"
bad=$(python3 -c "import json,sys; j=json.loads(sys.argv[1]); j['seed']+=1; print(json.dumps(j))" "$job")
expect_exit 2 "the job's key does not match its contents" reproduce run-job "$bad"

# ---- shi2022 --quick on the shared maps ----------------------------------------------------------
maps=../shared/data/matlab-maps
if [ ! -d "$maps" ]; then
  echo "skipped: $maps is absent (the shared MATLAB maps); shi2022 --quick not run"
  exit 0
fi
expect_exit 0 "" reproduce shi2022 --quick --simple "$maps/mapC_20x20_winsleo_traditional.txt" \
  --complex "$maps/mapB_20x20_ga.txt" --out-dir "$tmp/r" --seed 5
for f in shi2022.md shi2022/reproduce.json shi2022/simple-paths.svg shi2022/complex-paths.svg \
         shi2022/simple-convergence.svg shi2022/complex-convergence.svg shi2022/trial-error.svg; do
  [ -s "$tmp/r/$f" ] || { echo "FAIL: $f not written"; exit 1; }
done
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['protocol']['seeds']==[5,7], d['protocol']" "$tmp/r/shi2022/reproduce.json"
check_report shi2022 "$tmp/r"
echo "ok"
