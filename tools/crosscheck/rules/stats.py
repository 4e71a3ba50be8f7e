"""spec/stats.md, written from the spec alone (Python 3 standard library only).

Independent of the C++ in method where the spec allows it: the incomplete beta function is
summed from its power series (not the continued fraction), the exact Mann-Whitney distribution
comes from the classical counting recursion in exact integers (not the Gaussian-binomial product),
ranks are assigned by counting (not by sorting the pooled sample). The bootstrap replays the
pinned stream (rules/rng.py's own MT19937) in the spec's draw order.
"""
import math
from fractions import Fraction
from functools import lru_cache

from .common import DomainError, require
from .rng import MT19937


class UsageError(Exception):
    pass


def _num(v):
    if isinstance(v, str):
        m = {"inf": math.inf, "-inf": -math.inf, "nan": math.nan}
        if v not in m:
            raise UsageError("not a number")
        return m[v]
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise UsageError("not a number")
    return float(v)


def _values(inp, key):
    v = inp[key]
    if not isinstance(v, list):
        raise UsageError(f"{key} must be an array")
    return [_num(e) for e in v]


def _finite(xs):
    require(all(math.isfinite(x) for x in xs), "every value must be finite")


def _mean(xs):
    require(len(xs) >= 1, "mean of nothing")
    _finite(xs)
    s = 0.0
    for x in xs:  # left to right, plain binary64 additions (never sum(), which compensates on 3.12)
        s = s + x
    return s / len(xs)


def _sd(xs):
    require(len(xs) >= 2, "sd needs two values")
    _finite(xs)
    m = _mean(xs)
    ss = 0.0
    for x in xs:
        d = x - m
        ss = ss + d * d
    return math.sqrt(ss / (len(xs) - 1))


def _quantile_sorted(xs, p):
    require(len(xs) >= 1, "quantile of nothing")
    _finite(xs)
    require(math.isfinite(p) and 0.0 <= p <= 1.0, "p outside [0, 1]")
    h = (len(xs) - 1) * p
    j = math.floor(h)
    if j >= len(xs) - 1:
        return xs[-1]
    return xs[j] + (h - j) * (xs[j + 1] - xs[j])


def mean(inp):
    return {"mean": _mean(_values(inp, "values"))}


def sd(inp):
    return {"sd": _sd(_values(inp, "values"))}


def quantile(inp):
    xs = _values(inp, "values")
    _finite(xs)
    return {"quantile": _quantile_sorted(sorted(xs), _num(inp["p"]))}


ONE = ("mean", "minimum")
TWO = ("mean_difference", "reduction_percent", "sd_difference")


def _bootstrap_paired(inp, stat):
    """Paired: one index k per pair and replicate, a*_i = a[k], b*_i = b[k] (spec stats.bootstrap_ci)."""
    require(stat in ("mean_difference", "reduction_percent"), "paired: mean_difference or reduction_percent")
    a = _values(inp, "a")
    b = _values(inp, "b")
    require(len(a) == len(b), "paired samples of different lengths")
    require(len(a) >= 2, "needs two pairs")
    _finite(a)
    _finite(b)
    if stat == "reduction_percent":
        require(all(v > 0 for v in b), "reduction_percent needs b > 0")
    B = inp.get("resamples", 2000)
    level = _num(inp.get("level", 0.95))
    require(isinstance(B, int) and 1 <= B <= 10**6, "resamples outside [1, 10^6]")
    require(math.isfinite(level) and 0.0 < level < 1.0, "level outside (0, 1)")
    g = MT19937(inp["seed"])
    n = len(a)
    reps = []
    for _ in range(B):
        sa, sb = [], []
        for _ in range(n):
            u = g.genrand_res53()
            k = min(math.floor(u * float(n)), n - 1)
            sa.append(a[k])
            sb.append(b[k])
        if stat == "mean_difference":
            r = _mean(sa) - _mean(sb)
        else:
            mb = _mean(sb)
            r = 100.0 * (mb - _mean(sa)) / mb
        reps.append(r)
    reps.sort()
    alpha = 1.0 - level
    return {"lo": _quantile_sorted(reps, alpha / 2.0), "hi": _quantile_sorted(reps, 1.0 - alpha / 2.0)}


def bootstrap_ci(inp):
    stat = inp.get("statistic", "mean")
    paired = inp.get("paired", False)
    if not isinstance(paired, bool):
        raise UsageError("paired must be true or false")
    if paired:
        if stat not in ONE + TWO:
            raise UsageError("unknown statistic")
        return _bootstrap_paired(inp, stat)
    if stat not in ONE + TWO:
        raise UsageError("unknown statistic")
    a = _values(inp, "a")
    b = _values(inp, "b") if stat in TWO else []
    require(len(a) >= 2 and (stat in ONE or len(b) >= 2), "each sample needs two values")
    _finite(a)
    _finite(b)
    if stat == "reduction_percent":
        require(all(v > 0 for v in b), "reduction_percent needs b > 0")
    B = inp.get("resamples", 2000)
    level = _num(inp.get("level", 0.95))
    require(isinstance(B, int) and 1 <= B <= 10**6, "resamples outside [1, 10^6]")
    require(math.isfinite(level) and 0.0 < level < 1.0, "level outside (0, 1)")
    g = MT19937(inp["seed"])

    def draw(xs):
        out = []
        for _ in xs:
            u = g.genrand_res53()
            k = min(math.floor(u * float(len(xs))), len(xs) - 1)
            out.append(xs[k])
        return out

    reps = []
    for _ in range(B):
        sa = draw(a)
        sb = draw(b) if stat in TWO else None
        if stat == "mean":
            r = _mean(sa)
        elif stat == "minimum":
            r = min(sa)
        elif stat == "mean_difference":
            r = _mean(sa) - _mean(sb)
        elif stat == "reduction_percent":
            mb = _mean(sb)
            r = 100.0 * (mb - _mean(sa)) / mb
        else:
            r = _sd(sa) - _sd(sb)
        reps.append(r)
    reps.sort()
    alpha = 1.0 - level
    return {"lo": _quantile_sorted(reps, alpha / 2.0), "hi": _quantile_sorted(reps, 1.0 - alpha / 2.0)}


def _betainc_series(a, b, x):
    """I_x(a, b) = x^a (1-x)^b / (a B(a, b)) * sum_n (a+b)_n / (a+1)_n x^n."""
    log_pre = a * math.log(x) + b * math.log1p(-x) - (math.lgamma(a) + math.lgamma(b) - math.lgamma(a + b))
    term, total, n = 1.0, 1.0, 0
    while True:
        term *= (a + b + n) / (a + 1.0 + n) * x
        total += term
        n += 1
        if term < 1e-17 * total or n > 10**7:
            break
    return math.exp(log_pre) * total / a


def _betainc(a, b, x):
    if x == 0.0:
        return 0.0
    if x == 1.0:
        return 1.0
    if x > (a + 1.0) / (a + b + 2.0):
        return 1.0 - _betainc_series(b, a, 1.0 - x)
    return _betainc_series(a, b, x)


def betainc(inp):
    a, b, x = _num(inp["a"]), _num(inp["b"]), _num(inp["x"])
    require(math.isfinite(a) and a > 0 and math.isfinite(b) and b > 0, "a, b must be > 0")
    require(math.isfinite(x) and 0.0 <= x <= 1.0, "x outside [0, 1]")
    return {"value": min(1.0, max(0.0, _betainc(a, b, x)))}


def _t_p(t, df):
    require(math.isfinite(df) and df > 0, "df must be > 0")
    require(not math.isnan(t), "t is NaN")
    if math.isinf(t) or math.isinf(t * t):
        return 0.0
    return min(1.0, max(0.0, _betainc(df / 2.0, 0.5, df / (df + t * t))))


def student_t(inp):
    return {"p": _t_p(_num(inp["t"]), _num(inp["df"]))}


@lru_cache(maxsize=None)
def _count(m, n, k):
    """Number of orderings of m a's and n b's with exactly k (a, b) pairs where a is larger."""
    if k < 0 or k > m * n:
        return 0
    if m == 0 or n == 0:
        return 1 if k == 0 else 0
    # the largest element is an a (it beats all n b's) or a b
    return _count(m - 1, n, k - n) + _count(m, n - 1, k)


def mann_whitney(inp):
    a, b = _values(inp, "a"), _values(inp, "b")
    require(len(a) >= 1 and len(b) >= 1, "each sample needs a value")
    require(len(a) <= 100000 and len(b) <= 100000, "too many values")
    _finite(a)
    _finite(b)
    pooled = a + b
    n1, n2, n = len(a), len(b), len(a) + len(b)

    def midrank(v):  # 1-based: (#below) + (#equal + 1) / 2
        below = sum(1 for w in pooled if w < v)
        equal = sum(1 for w in pooled if w == v)
        return Fraction(2 * below + equal + 1, 2)

    r1 = sum((midrank(v) for v in a), Fraction(0))
    u1 = r1 - Fraction(n1 * (n1 + 1), 2)
    u2 = n1 * n2 - u1
    u = max(u1, u2)
    groups = {}
    for v in pooled:
        groups[v] = groups.get(v, 0) + 1
    ties = any(t > 1 for t in groups.values())
    out = {"u_a": float(u1), "u_b": float(u2)}
    if min(n1, n2) <= 8 and not ties:
        m, nn = min(n1, n2), max(n1, n2)
        total = math.comb(n, n1)
        tail = sum(_count(m, nn, k) for k in range(int(u), m * nn + 1))
        out.update({"exact": True, "p": float(min(Fraction(1), Fraction(2 * tail, total)))})
        return out
    tie_term = sum(t ** 3 - t for t in groups.values())
    var = n1 * n2 / 12.0 * ((n + 1) - tie_term / (n * (n - 1)))
    out["exact"] = False
    if not var > 0.0:
        out["p"] = 1.0
        return out
    z = (float(u) - n1 * n2 / 2.0 - 0.5) / math.sqrt(var)
    out.update({"z": z, "p": min(1.0, math.erfc(z / math.sqrt(2.0)))})
    return out


def welch(inp):
    a, b = _values(inp, "a"), _values(inp, "b")
    require(len(a) >= 2 and len(b) >= 2, "each sample needs two values")
    va = _sd(a) ** 2 / len(a)
    vb = _sd(b) ** 2 / len(b)
    se2 = va + vb
    d = _mean(a) - _mean(b)
    if se2 == 0.0:
        if d == 0.0:
            return {"mean_difference": d, "t": 0.0, "p": 1.0}
        return {"mean_difference": d, "t": "inf" if d > 0 else "-inf", "p": 0.0}
    t = d / math.sqrt(se2)
    df = se2 * se2 / (va * va / (len(a) - 1) + vb * vb / (len(b) - 1))
    return {"mean_difference": d, "t": t, "df": df, "p": _t_p(t, df)}


def margin(inp):
    q, p = inp["quantity"], _num(inp["paper"])
    if q not in ("length", "turns", "iterations", "time", "percent"):
        raise UsageError("unknown quantity")
    require(math.isfinite(p), "paper value must be finite")
    m = {"length": 0.01 * abs(p), "turns": 1.0, "iterations": max(1.0, 0.1 * abs(p)),
         "time": 0.05 * abs(p), "percent": 5.0}[q]
    return {"margin": m}


TEXT = {
    ("holds", "none"): "holds", ("holds", "as_claimed"): "holds",
    ("fails", "pathref_better"): "does not hold — pathref better",
    ("fails", "pathref_worse"): "does not hold — pathref worse",
    ("fails", "opposite"): "does not hold — the opposite is significant",
    ("not_significant", "as_claimed"): "not significant — difference as claimed",
    ("not_significant", "opposite"): "not significant — difference opposite",
    ("not_significant", "equal"): "not significant — no difference",
    ("inconclusive", "pathref_better"): "inconclusive — pathref better",
    ("inconclusive", "pathref_worse"): "inconclusive — pathref worse",
    ("inconclusive", "none"): "inconclusive — interval wider than the margin",
}


def _judgement(verdict, direction):
    return {"verdict": verdict, "direction": direction, "text": TEXT[(verdict, direction)]}


def equivalence(inp):
    lo, hi, p, m = _num(inp["lo"]), _num(inp["hi"]), _num(inp["paper"]), _num(inp["margin"])
    require(all(math.isfinite(v) for v in (lo, hi, p, m)), "finite values required")
    require(lo <= hi and m >= 0, "lo <= hi and margin >= 0 required")
    sense = inp.get("sense", "lower_is_better")
    if sense not in ("lower_is_better", "higher_is_better"):
        raise UsageError("bad sense")
    low_dir = "pathref_better" if sense == "lower_is_better" else "pathref_worse"
    high_dir = "pathref_worse" if sense == "lower_is_better" else "pathref_better"
    if p - m <= lo and hi <= p + m:
        return _judgement("holds", "none")
    if hi < p - m:
        return _judgement("fails", low_dir)
    if lo > p + m:
        return _judgement("fails", high_dir)
    below, above = lo < p - m, hi > p + m
    if below and above:
        return _judgement("inconclusive", "none")
    return _judgement("inconclusive", low_dir if below else high_dir)


def compare(inp):
    alpha = _num(inp.get("alpha", 0.05))
    require(math.isfinite(alpha) and 0.0 < alpha < 1.0, "alpha outside (0, 1)")
    claim = inp.get("claim", "a_less")
    if claim not in ("a_less", "a_greater"):
        raise UsageError("bad claim")
    if "a" in inp or "b" in inp:
        a, b = _values(inp, "a"), _values(inp, "b")
        mw = mann_whitney({"a": a, "b": b})
        half = len(a) * len(b) / 2.0
        if mw["u_a"] == half:
            observed = "equal"
        else:
            observed = "as_claimed" if (mw["u_a"] < half) == (claim == "a_less") else "opposite"
        out = _from_p(mw["p"], alpha, observed)
        out["p"] = mw["p"]
        return out
    if "lo" in inp or "hi" in inp:
        lo, hi = _num(inp["lo"]), _num(inp["hi"])
        require(math.isfinite(lo) and math.isfinite(hi) and lo <= hi, "bad interval")
        if claim == "a_greater":
            lo, hi = -hi, -lo
        if hi < 0.0:
            return _judgement("holds", "as_claimed")
        if lo > 0.0:
            return _judgement("fails", "opposite")
        mid = lo / 2.0 + hi / 2.0
        return _judgement("not_significant", "as_claimed" if mid < 0 else "opposite" if mid > 0 else "equal")
    p = _num(inp["p"])
    require(math.isfinite(p) and 0.0 <= p <= 1.0, "p outside [0, 1]")
    observed = inp["observed"]
    if observed not in ("as_claimed", "opposite", "equal"):
        raise UsageError("bad observed")
    return _from_p(p, alpha, observed)


def _from_p(p, alpha, observed):
    if p < alpha and observed == "as_claimed":
        return _judgement("holds", "as_claimed")
    if p < alpha and observed == "opposite":
        return _judgement("fails", "opposite")
    return _judgement("not_significant", observed)


RULES = {
    "stats.mean": mean,
    "stats.sd": sd,
    "stats.quantile": quantile,
    "stats.bootstrap_ci": bootstrap_ci,
    "stats.betainc": betainc,
    "stats.student_t": student_t,
    "stats.mann_whitney": mann_whitney,
    "stats.welch": welch,
    "stats.margin": margin,
    "stats.equivalence": equivalence,
    "stats.compare": compare,
}
