#!/usr/bin/python3
"""Oracle test of the stats.* rules (spec/stats.md) against SciPy and NumPy.

Runs `pathref eval` on random samples (NumPy RandomState(20261202)) and compares with
scipy.stats.mannwhitneyu(method='auto'), scipy.stats.ttest_ind(equal_var=False),
scipy.special.betainc, scipy.stats.t.sf, numpy.quantile (linear = type 7) and a NumPy replay of the
bootstrap's draw order (RandomState(seed).random_sample() is the pinned stream, spec/rng.md).

Usage: scipy_stats.py PATHREF
Exit 0: all agree; 1: a mismatch; 77: SciPy is missing (a skip) -- unless CI=true, where a missing
SciPy is a failure (exit 1): tools/deps.sh installs python3-scipy.
"""
import json
import math
import os
import subprocess
import sys

try:
    import numpy as np
    import scipy
    from scipy import special
    from scipy import stats as ss
except ImportError as e:  # pragma: no cover
    msg = f"oracle.scipy-stats: SciPy/NumPy not importable by {sys.executable} ({e}); install python3-scipy (tools/deps.sh)"
    if os.environ.get("CI") == "true":
        print("FAIL " + msg)
        sys.exit(1)
    print("SKIP " + msg)
    sys.exit(77)

PATHREF = sys.argv[1]
failures = []
checked = 0


def ev(rule, **inputs):
    args = [PATHREF, "eval", rule] + [f"{k}={json.dumps(v)}" for k, v in inputs.items()]
    out = subprocess.run(args, capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"{' '.join(args)}: exit {out.returncode}: {out.stderr.strip()}")
    return json.loads(out.stdout)["output"]


def close(what, got, want, rel, abs_=0.0):
    global checked
    checked += 1
    if isinstance(got, str) or not (abs(got - want) <= max(abs_, rel * abs(want))):
        failures.append(f"{what}: pathref {got!r}, oracle {want!r} (rel {rel})")


rs = np.random.RandomState(20261202)


def sample(n, kind):
    if kind == "continuous":
        return [float(x) for x in rs.normal(30.0, 2.0, n)]
    if kind == "lengths":  # grid path lengths a + b sqrt 2: many ties
        return [float(a + b * math.sqrt(2.0)) for a, b in zip(rs.randint(10, 14, n), rs.randint(10, 13, n))]
    return [float(x) for x in rs.randint(0, 6, n)]  # turn counts


cases = []
for na, nb in [(3, 5), (8, 12), (5, 5), (1, 4), (20, 20), (50, 50), (7, 40), (9, 9), (30, 12)]:
    for kind in ("continuous", "lengths", "turns"):
        cases.append((sample(na, kind), sample(nb, kind), f"{kind} n=({na},{nb})"))
# shifted samples (significant differences)
for na, nb in [(6, 6), (25, 25)]:
    a = sample(na, "continuous")
    cases.append((a, [x + 3.0 for x in sample(nb, "continuous")], f"shifted n=({na},{nb})"))

for a, b, what in cases:
    out = ev("stats.mann_whitney", a=a, b=b)
    r = ss.mannwhitneyu(a, b, alternative="two-sided", method="auto", use_continuity=True)
    close(f"mann_whitney u_a {what}", out["u_a"], float(r.statistic), 0.0)
    if not (len(set(a + b)) == 1):
        close(f"mann_whitney p {what}", out["p"], float(r.pvalue), 1e-12)
    if len(a) >= 2 and len(b) >= 2 and (np.var(a) > 0 or np.var(b) > 0):
        w = ev("stats.welch", a=a, b=b)
        t = ss.ttest_ind(a, b, equal_var=False)
        close(f"welch t {what}", w["t"], float(t.statistic), 1e-13, 1e-15)
        close(f"welch p {what}", w["p"], float(t.pvalue), 1e-10)

for a_, b_, x in [(0.5, 0.5, 0.3), (2.0, 9.5, 0.1), (30.0, 0.5, 0.97), (0.5, 200.0, 0.001), (400.0, 380.0, 0.51), (1.5, 1.5, 0.999)]:
    close(f"betainc I_{x}({a_},{b_})", ev("stats.betainc", a=a_, b=b_, x=x)["value"], float(special.betainc(a_, b_, x)), 1e-10)
for t, df in [(0.3, 1.0), (2.1, 4.5), (-3.3, 17.2), (8.0, 60.0), (1e-6, 9.0), (40.0, 3.0)]:
    close(f"student_t t={t} df={df}", ev("stats.student_t", t=t, df=df)["p"], float(2 * ss.t.sf(abs(t), df)), 1e-10)

for n in (1, 2, 7, 50):
    xs = sample(n, "continuous")
    for p in (0.0, 0.025, 0.3, 0.5, 0.975, 1.0):
        close(f"quantile n={n} p={p}", ev("stats.quantile", values=xs, p=p)["quantile"], float(np.quantile(xs, p)), 1e-15)

# Bootstrap: replay the spec's draw order with NumPy's MT19937 (the same stream).
for n, seed, B, stat in [(10, 1, 500, "mean"), (50, 42, 300, "mean"), (12, 5, 400, "minimum")]:
    a = sample(n, "lengths")
    out = ev("stats.bootstrap_ci", a=a, seed=seed, resamples=B, statistic=stat)
    u = np.random.RandomState(seed).random_sample(B * n).reshape(B, n)
    idx = np.minimum(np.floor(u * n).astype(int), n - 1)
    res = np.array(a)[idx]
    reps = np.sort(res.mean(axis=1) if stat == "mean" else res.min(axis=1))
    alpha = 1.0 - 0.95
    # NumPy's mean sums pairwise: allow a few ulps of the replicates
    close(f"bootstrap {stat} lo n={n}", out["lo"], float(np.quantile(reps, alpha / 2)), 1e-13)
    close(f"bootstrap {stat} hi n={n}", out["hi"], float(np.quantile(reps, 1 - alpha / 2)), 1e-13)

# Paired bootstrap: one index per pair, the same index for a and b (spec stats.bootstrap_ci, paired).
for n, seed, B, stat in [(12, 3, 400, "mean_difference"), (30, 8, 300, "reduction_percent")]:
    b = sample(n, "lengths")
    a = [x - 0.25 * (i % 5) for i, x in enumerate(b)]
    out = ev("stats.bootstrap_ci", a=a, b=b, paired=True, seed=seed, resamples=B, statistic=stat)
    u = np.random.RandomState(seed).random_sample(B * n).reshape(B, n)
    idx = np.minimum(np.floor(u * n).astype(int), n - 1)
    ma, mb = np.array(a)[idx].mean(axis=1), np.array(b)[idx].mean(axis=1)
    reps = np.sort(ma - mb if stat == "mean_difference" else 100.0 * (mb - ma) / mb)
    alpha = 1.0 - 0.95
    close(f"paired bootstrap {stat} lo n={n}", out["lo"], float(np.quantile(reps, alpha / 2)), 1e-12)
    close(f"paired bootstrap {stat} hi n={n}", out["hi"], float(np.quantile(reps, 1 - alpha / 2)), 1e-12)

for f in failures:
    print("FAIL " + f)
print(f"oracle.scipy-stats: {checked - len(failures)} of {checked} values agree with SciPy {scipy.__version__} / NumPy {np.__version__}")
sys.exit(1 if failures else 0)
