#!/usr/bin/env python3
"""Differential replay of whole runs: pathref against tools/crosscheck on inputs golden/ does not hold.

The golden vectors pin each seeded planner, random map and the drive rules at a few inputs; a
mutant that changes a run elsewhere passes every test that only reads those vectors' inputs.
This test takes the golden inputs of the whole-run rules below, moves them to inputs no golden
file contains (seed + 1000 for every seeded run; for some rules a mirrored map, the start and goal
swapped, or reversed/rescaled lists), evaluates each with `pathref eval RULE key=value ...` and
with tools/crosscheck's own function for the rule (the independent Python implementation), and
compares every output the golden test pins under that test's own tolerance (tools/crosscheck's
`compare`, the runner's semantics). Both sides rejecting an input counts as agreement but not as
a compared run.

Usage: crosscheck_replay.py PATHREF [SOURCE_DIR] [-v]
Exit 0: every run agrees and at least MIN_RUNS runs (MIN_PER_RULE per rule) were compared;
1: a disagreement (each listed), too few runs, a rule with no golden file, or a variant that
collides with a golden input. Python 3 standard library only.
"""
import copy
import json
import os
import subprocess
import sys
import time

ARGS = [a for a in sys.argv[1:] if a != "-v"]
VERBOSE = "-v" in sys.argv[1:]
if not ARGS:
    print(__doc__)
    sys.exit(2)
PATHREF = ARGS[0]
SOURCE = ARGS[1] if len(ARGS) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(SOURCE, "tools", "crosscheck"))

from crosscheck import compare, compose_input  # noqa: E402  (the crosscheck runner's own semantics)
from rules import RULES  # noqa: E402

SEED_SHIFT = 1000  # golden seeds are small (<= 100); seed + 1000 and seed + 2000 are new inputs

# rule -> golden file, the variants to build from each valid/acceptable golden test, and which of
# its tests to use (None: all; a set of tcIds where the Python side of a run costs seconds).
#   seed      seed + 1000
#   mirror    the grid mirrored left-right (x -> W-1-x for the grid, start and goal), seed + 2000
#             when seeded: a second map
#   swap      start and goal swapped (unseeded searches)
#   reverse   the per-run lists reversed (a backward-pass case becomes a forward-pass one)
#   scale     lengths halved and the corner speed doubled (the acceleration limits bind)
# What the variants are for, beyond new seeds (each checked on 2026-12-03 by applying the
# tools/mutate.d/catalogue.json mutant to the crosscheck's own copy of the rule: the replay fails):
# `reverse`/`scale` make the forward pass of drive.corner-speeds bind (drive.corner-speeds.forward);
# `swap`/`mirror` give han.plan.astar equal-g ties resolved differently (han.plan.astar.parent);
# `seed2` adds corridors with a draw at k = rx (han.maps.random.corridor).
NOT_TC1 = set(range(2, 100))  # tc 1 runs the default colony size: 0.7 s in Python per run
PLAN = {
    "shi2022.plan.aco": ("shi2022-aco", ("seed", "mirror"), NOT_TC1),
    "shi2022.plan.iaco": ("shi2022-aco", ("seed",), {2, 3, 5, 6, 7, 8}),
    "shi2022.plan.ga": ("shi2022-ga", ("seed", "mirror"), None),
    "shi2022.plan.iga": ("shi2022-ga", ("seed", "mirror"), None),
    "shi2022.plan.hybrid": ("shi2022-ga", ("seed", "mirror"), None),
    "shi2022.plan.iha": ("shi2022-ga", ("seed", "mirror"), None),
    "han.plan.iaco": ("han-iaco", ("seed",), {2, 3, 4, 5, 6, 7, 8, 9, 10, 11}),
    "han.plan.astar": ("han-iaco", ("swap", "mirror"), None),
    "han.plan.iaco-astar": ("han-sim", ("seed", "mirror"), {3}),
    "classic.plan.aco": ("classic", ("seed", "mirror"), None),
    "classic.plan.ga": ("classic", ("seed", "mirror"), None),
    "cin2021.plan.aco": ("cin2021-hga-aco", ("seed",), {1, 2, 5, 6}),
    "cin2021.plan.ga": ("cin2021-hga-aco", ("seed",), {1, 2, 5, 6}),
    "cin2021.plan.hga-aco": ("cin2021-hga-aco", ("seed",), {1, 2}),
    "cin2021.alg1": ("cin2021-srrt", ("seed",), {6, 9}),
    "han.maps.random": ("han-sim", ("seed", "seed2"), None),
    "drive.corner-speeds": ("mecanum", ("reverse", "scale"), None),
    "sensors2023.plan.astar-kinematic": ("sensors2023", ("swap", "mirror"), None),
}
# Hand-picked inputs beyond the golden variants, each for a case the variants do not reach (the
# same comparison: pathref eval against tools/crosscheck under the rule's golden tolerance, on the
# outputs its first valid golden test pins). cin2021.plan.ga: equal-fitness mutants A != B inside
# the multidirectional mutation (pm = 1), where only "B replaces only if strictly fitter" keeps A
# (mutant cin2021.op.mutation.fitter-tie changes draws and curves on each of these; found by a
# search over 400 small random maps on 2026-12-03).
EXTRA = {
    "cin2021.plan.ga": [
        {"grid": [".#...", ".....", "....."], "start": [1, 1], "goal": [4, 0], "seed": 12,
         "population": 10, "generations": 4, "pm": 1.0, "research": "random"},
        {"grid": [".....", ".....", "....#", ".....", "#.#.."], "start": [2, 1], "goal": [1, 4],
         "seed": 32, "population": 6, "generations": 6, "pm": 1.0, "research": "greedy"},
        {"grid": ["....", "....", "...."], "start": [3, 1], "goal": [1, 1], "seed": 4,
         "population": 6, "generations": 4, "pm": 1.0, "research": "random"},
    ],
}
MIN_PER_RULE = 2
MIN_RUNS = 150  # 190 compared on 2026-12-03 (6 variants equal a golden input, 2 rejected by both)


def mirrored(inp):
    rows = inp["grid"]
    w = len(rows[0])
    out = dict(inp, grid=[r[::-1] for r in rows])
    for k in ("start", "goal"):
        if k in out:
            out[k] = [w - 1 - out[k][0], out[k][1]]
    return out


def variants(inp, kinds):
    """(label, input) for each variant kind that applies to this input."""
    for kind in kinds:
        if kind == "seed" and "seed" in inp:
            yield "seed+1000", dict(inp, seed=inp["seed"] + SEED_SHIFT)
        elif kind == "seed2" and "seed" in inp:
            yield "seed+2000", dict(inp, seed=inp["seed"] + 2 * SEED_SHIFT)
        elif kind == "mirror" and isinstance(inp.get("grid"), list) and inp["grid"]:
            v = mirrored(inp)
            if "seed" in v:
                v["seed"] += 2 * SEED_SHIFT
            yield "mirrored map", v
        elif kind == "swap" and "start" in inp and "goal" in inp and inp["start"] != inp["goal"]:
            yield "start/goal swapped", dict(inp, start=inp["goal"], goal=inp["start"])
        elif kind == "reverse" and len(inp.get("lengths", [])) >= 2:
            yield "lists reversed", {k: (v[::-1] if isinstance(v, list) else v) for k, v in inp.items()}
        elif kind == "scale" and inp.get("lengths"):
            yield "lengths/2, corner speed*2", dict(inp, lengths=[x / 2 for x in inp["lengths"]],
                                                    corner_speed=inp["corner_speed"] * 2)


def start_cpp(rule, inp):
    args = [PATHREF, "eval", rule] + [f"{k}={json.dumps(v)}" for k, v in sorted(inp.items())]
    return subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def finish_cpp(proc):
    out, err = proc.communicate()
    if proc.returncode == 0:
        return json.loads(out)["output"], None
    return None, f"exit {proc.returncode}: {err.strip()}"


def run_python(rule, inp):
    try:
        return RULES[rule](copy.deepcopy(inp)), None
    except Exception as e:  # DomainError, UsageError, ParseError: the crosscheck's rejections
        if type(e).__name__ not in ("DomainError", "UsageError", "ParseError"):
            raise
        return None, f"{type(e).__name__}: {e}"


def main():
    t0 = time.time()
    failures, counts, rejected, collisions, seconds = [], {}, 0, 0, {}
    golden_root = os.path.join(SOURCE, "golden")
    for rule, (module, kinds, only) in PLAN.items():
        counts[rule] = 0
        t_rule = time.time()
        path = os.path.join(golden_root, module, rule + ".json")
        if not os.path.isfile(path):
            failures.append(f"{rule}: no golden file {os.path.relpath(path, SOURCE)}")
            continue
        if rule not in RULES:
            failures.append(f"{rule}: tools/crosscheck does not implement it")
            continue
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
        tests = [(g, t) for g in doc["testGroups"] for t in g["tests"]]
        golden_inputs = [compose_input(doc, g, t) for g, t in tests]
        first_valid = next((g, t) for g, t in tests if t["result"] == "valid")
        extra = [(first_valid[0], first_valid[1], "hand-picked input", inp) for inp in EXTRA.get(rule, [])]
        for g, t in tests:
            if t["result"] == "invalid" or (only is not None and t["tcId"] not in only):
                continue
            extra.extend((g, t, label, inp) for label, inp in variants(compose_input(doc, g, t), kinds))
        for g, t, label, inp in extra:  # hand-picked inputs use the first valid test's keys
            tol = t.get("tolerance", g["tolerance"])
            keys = sorted(t["expected"])
            where = f"{rule} tcId {t['tcId']} ({label})"
            if inp in golden_inputs:  # a symmetric map or list: nothing new to compare
                collisions += 1
                continue
            proc = start_cpp(rule, inp)  # runs while Python computes
            py, py_err = run_python(rule, inp)
            cpp, cpp_err = finish_cpp(proc)
            if py_err and cpp_err:
                rejected += 1
                if VERBOSE:
                    print(f"both reject {where}: {py_err} | {cpp_err}")
                continue
            if py_err or cpp_err:
                failures.append(f"{where}: pathref {cpp_err or 'accepts'}, crosscheck {py_err or 'accepts'}; "
                                f"input {json.dumps(inp, sort_keys=True)}")
                continue
            counts[rule] += 1
            for k in keys:
                if k not in py:
                    failures.append(f"{where}: crosscheck gives no output {k!r}")
                    continue
                d = compare({k: py[k]}, cpp, tol)
                if d:
                    failures.append(f"{where}: pathref differs from crosscheck: {d}; "
                                    f"input {json.dumps(inp, sort_keys=True)}")
            if VERBOSE:
                print(f"ok   {where}")
        seconds[rule] = time.time() - t_rule
    runs = sum(counts.values())
    for rule, n in counts.items():
        if n < MIN_PER_RULE:
            failures.append(f"{rule}: only {n} runs compared (at least {MIN_PER_RULE})")
    if runs < MIN_RUNS:
        failures.append(f"only {runs} runs compared in all (at least {MIN_RUNS})")
    if VERBOSE:
        for rule, n in counts.items():
            print(f"{rule}: {n} runs, {seconds.get(rule, 0.0):.2f} s")
    for f in failures:
        print("FAIL " + f)
    print(f"crosscheck-replay: {len(counts)} rules, {runs} runs compared, {rejected} rejected by both, "
          f"{collisions} variants skipped as golden inputs, "
          f"{len(failures)} failures, {time.time() - t0:.1f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
