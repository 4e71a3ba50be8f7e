"""spec/han.md (Han, IJACSA, Eq. 1-15 and the parameter table), from the spec alone.

Every rule is re-derived from the spec text with Python floats (binary64, the same IEEE
operations), in the evaluation order each rule states, so hand values match bit for bit. The
angle tests of Eq. (3) are exact integer dot products; the 2x2 matrix algebra of the recursive
least squares (Eq. 15) is written out by hand on scalars from the spec formulas.
"""
import math

from .common import require


class UsageError(Exception):
    """A malformed request (the C++ UsageError); never expected by a golden vector."""


LIM25 = 1 << 25
LIM30 = 1 << 30

# r[han.params]: printed values and pathref's choices.
PARAMS = {"ants": 50, "max_cycles": 50, "alpha": 4.0, "beta": 8.0, "rho_initial": 0.7,
          "gamma": 1.0, "omega_i": 0.5, "epsilon": 1.0, "h": 1.0, "Q": 1.0, "tau_initial": 1.0,
          "tau_min": 0.01, "a": 1.0, "b": 5.0, "rho_min": 0.1, "lambda": 0.95,
          "rls_init_samples": 2}


# ---- input helpers --------------------------------------------------------------------------


def _is_int(v):
    return isinstance(v, int) and not isinstance(v, bool)


def _num(v):
    if isinstance(v, str):
        if v in ("inf", "-inf", "nan"):
            return float(v)
        raise UsageError("expected a number")
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise UsageError("expected a number")
    return float(v)


def _nums(v):
    if not isinstance(v, list):
        raise UsageError("expected a list of numbers")
    return [_num(x) for x in v]


def _pair(v):
    p = _nums(v)
    if len(p) != 2:
        raise UsageError("expected a pair")
    return p


def _int(v):
    if not _is_int(v):
        raise UsageError("expected an integer")
    return v


def _cell(v):
    if not (isinstance(v, list) and len(v) == 2 and all(_is_int(t) for t in v)):
        raise UsageError("a cell is [x, y] with two integers")
    return (v[0], v[1])


def _choice(inp, key, options):
    v = inp.get(key, options[0])
    if v not in options:
        raise UsageError(f"{key} must be one of {options}")
    return v


def _fin(x):
    return math.isfinite(x)


def _finite_nonneg(x):
    return math.isfinite(x) and x >= 0.0


def _pow(x, y):
    try:
        return math.pow(x, y)
    except OverflowError:
        return math.inf


# ---- rules ----------------------------------------------------------------------------------


def params(inp):
    return dict(PARAMS)


def _weights(tau, eta, omega, alpha, beta, gamma):
    require(len(tau) >= 1, "empty allowed set")
    require(len(tau) == len(eta) == len(omega), "one value per candidate")
    require(_finite_nonneg(alpha) and _finite_nonneg(beta) and _finite_nonneg(gamma), "exponents >= 0")
    w = []
    for t, e, o in zip(tau, eta, omega):
        require(_finite_nonneg(t) and _finite_nonneg(e) and _finite_nonneg(o), "values >= 0")
        v = (_pow(t, alpha) * _pow(e, beta)) * _pow(o, gamma)
        require(math.isfinite(v), "weight overflows")
        w.append(v)
    return w


def eq1(inp):
    w = _weights(_nums(inp["tau"]), _nums(inp["eta"]), _nums(inp["omega"]), _num(inp["alpha"]),
                 _num(inp["beta"]), _num(inp["gamma"]))
    s = 0.0
    for x in w:
        s += x
    require(math.isfinite(s) and s > 0.0, "weights sum to 0 or overflow")
    return {"weights": w, "p": [x / s for x in w]}


def _form(inp):
    return _choice(inp, "omega_form", ["multiply", "divide"])


def eq2(inp):
    form = _form(inp)
    wi = _num(inp["omega_i"])
    T = _int(inp["T"])
    require(math.isfinite(wi) and 0.0 < wi < 1.0, "omega_i in (0, 1)")
    require(T in (1, 2), "T in {1, 2}")
    return {"omega": wi * float(T) if form == "multiply" else wi / float(T)}


def _coord_ok(c):
    return abs(c[0]) <= LIM25 and abs(c[1]) <= LIM25


def eq3(inp):
    form = _form(inp)
    at90 = _choice(inp, "at90", ["two", "one"])
    cur, nxt = _cell(inp["cur"]), _cell(inp["next"])
    prev = inp.get("prev")
    require(_coord_ok(cur) and _coord_ok(nxt), "|coordinates| <= 2^25")
    require(cur != nxt, "next != cur")
    if prev is None:
        dot = 1  # first move: straight on (heading change 0, interior angle 180 degrees)
    else:
        p = _cell(prev)
        require(_coord_ok(p), "|coordinates| <= 2^25")
        require(p != cur, "prev != cur")
        dot = (cur[0] - p[0]) * (nxt[0] - cur[0]) + (cur[1] - p[1]) * (nxt[1] - cur[1])
    # multiply: theta = heading change, theta < 90 iff dot > 0, = 90 iff dot == 0.
    # divide: theta = interior angle 180 - heading change, theta < 90 iff dot < 0.
    s = dot if form == "multiply" else -dot
    if s > 0:
        T = 2
    elif s == 0:
        T = 2 if at90 == "two" else 1
    else:
        T = 1
    return {"T": T}


def _argmax(w):
    require(len(w) >= 1, "empty allowed set")
    best = 0
    for k, x in enumerate(w):
        require(_finite_nonneg(x), "weights finite and >= 0")
        if x > w[best]:
            best = k
    require(w[best] > 0.0, "all weights 0")
    return best


def _roulette(w, u):
    """spec rng.roulette: first k with w_k > 0 and C_k >= fl(u * S)."""
    s = 0.0
    for x in w:
        s += x
    target = u * s
    c = 0.0
    for k, x in enumerate(w):
        c += x
        if x > 0.0 and c >= target:
            return k
    raise AssertionError("roulette: no index (cannot happen)")


def eq4(inp):
    w = _nums(inp["weights"])
    q, q0, u = _num(inp["q"]), _num(inp["q0"]), _num(inp["u"])
    require(math.isfinite(q) and 0.0 <= q < 1.0, "q in [0, 1)")
    require(math.isfinite(u) and 0.0 <= u < 1.0, "u in [0, 1)")
    require(math.isfinite(q0) and 0.0 <= q0 <= 1.0, "q0 in [0, 1]")
    best = _argmax(w)
    if q <= q0:
        return {"index": best, "mode": "argmax"}
    return {"index": _roulette(w, u), "mode": "roulette"}


def eq5(inp):
    eps, nc, nmax = _num(inp["epsilon"]), _int(inp["N_c"]), _int(inp["N_max"])
    require(1 <= nmax <= (1 << 31), "N_max in [1, 2^31]")
    require(0 <= nc <= nmax, "N_c in [0, N_max]")
    require(math.isfinite(eps) and eps > 0.0, "epsilon > 0")
    r = float(nmax - nc) / float(nmax)
    q0 = eps * (0.2 + (r * 0.7))
    require(q0 <= 1.0, "q0 <= 1")
    return {"q0": q0}


def eq6(inp):
    edges = _choice(inp, "bonus_edges", ["best_path", "all_edges"])
    tau, rho, delta = _num(inp["tau"]), _num(inp["rho"]), _num(inp["delta"])
    h, la, ln, tmin = _num(inp["h"]), _num(inp["L_a"]), _num(inp["L_n"]), _num(inp["tau_min"])
    on = inp["on_best_path"]
    if not isinstance(on, bool):
        raise UsageError("on_best_path must be a bool")
    require(_finite_nonneg(h), "h >= 0")
    require(_fin(la) and la > 0.0 and _fin(ln) and ln > 0.0, "lengths > 0")
    full = (h * (la - ln)) / ln
    bonus = full if (on or edges == "all_edges") else 0.0
    require(_finite_nonneg(tau), "tau >= 0")
    require(_fin(rho) and 0.0 < rho < 1.0, "rho in (0, 1)")
    require(_finite_nonneg(delta), "delta >= 0")
    require(_fin(tmin) and tmin > 0.0, "tau_min > 0")
    base = ((1.0 - rho) * tau) + delta
    require(_fin(base), "overflow")
    v = base + bonus
    require(_fin(v), "overflow")
    return {"bonus": bonus, "tau_next": v if v > tmin else tmin}


def eq7(inp):
    ref = _choice(inp, "spread_reference", ["iteration_worst", "history_best"])
    rho, lref, ln = _num(inp["rho"]), _num(inp["L_ref"]), _num(inp["L_n"])
    a, b, rmin = _num(inp["a"]), _num(inp["b"]), _num(inp["rho_min"])
    require(_fin(rho) and 0.0 < rho < 1.0, "rho in (0, 1)")
    require(_fin(rmin) and 0.0 <= rmin < 1.0, "rho_min in [0, 1)")
    require(_fin(a) and _fin(b) and 0.0 <= a < b, "0 <= a < b")
    require(_fin(lref) and lref > 0.0 and _fin(ln) and ln > 0.0, "lengths > 0")
    if ref == "iteration_worst":
        require(lref >= ln, "worst >= best")
    d = lref - ln
    if d > b:
        f = 0.9
    elif d > a:
        f = 0.8
    else:
        f = 0.7
    v = f * rho
    out = v if v > rmin else rmin
    require(out > 0.0, "underflow")
    return {"rho_next": out}


def eq8(inp):
    form = _choice(inp, "h_form", ["chebyshev", "octile"])
    n, g = _cell(inp["n"]), _cell(inp["g"])
    for c in (n, g):
        require(abs(c[0]) < LIM30 and abs(c[1]) < LIM30, "|coordinates| < 2^30")
    dx, dy = abs(n[0] - g[0]), abs(n[1] - g[1])
    big, small = max(dx, dy), min(dx, dy)
    if form == "chebyshev":
        return {"h": float(big)}
    return {"h": float(big - small) + (math.sqrt(2.0) * float(small))}


# ---- Eq. 9-15: linear motion and recursive least squares -----------------------------------


def _all_fin(v):
    return all(math.isfinite(x) for x in v)


def eq9(inp):
    a, b, c, d, t = (_num(inp[k]) for k in ("a", "b", "c", "d", "t"))
    require(_all_fin([a, b, c, d, t]), "finite")
    x, y = (a * t) + b, (c * t) + d
    require(_all_fin([x, y]), "overflow")
    return {"x": x, "y": y}


def _line(th, t):
    return (t * th[0]) + th[1]


def _stacked(t, th):
    require(len(t) >= 1, "need a time")
    require(_all_fin(t) and _all_fin(th), "finite")
    out = [_line(th, tl) for tl in t]
    require(_all_fin(out), "overflow")
    return out


def eq10(inp):
    t = _nums(inp["t"])
    return {"X": _stacked(t, _pair(inp["A"])), "Y": _stacked(t, _pair(inp["B"]))}


def eq11(inp):
    t = _nums(inp["t"])
    require(len(t) >= 1 and _all_fin(t), "non-empty, finite")
    return {"T": [[tl, 1.0] for tl in t]}


def _residuals(t, z, th):
    require(len(t) >= 1, "need a sample")
    require(len(t) == len(z), "one observation per time")
    require(_all_fin(t) and _all_fin(z) and _all_fin(th), "finite")
    e = [zl - _line(th, tl) for tl, zl in zip(t, z)]
    require(_all_fin(e), "overflow")
    return e


def eq12(inp):
    return {"E": _residuals(_nums(inp["t"]), _nums(inp["x"]), _pair(inp["A"]))}


def eq13(inp):
    t = _nums(inp["t"])
    return {"E_x": _residuals(t, _nums(inp["x"]), _pair(inp["A"])),
            "E_y": _residuals(t, _nums(inp["y"]), _pair(inp["B"]))}


def _lam_ok(lam):
    require(math.isfinite(lam) and 0.0 < lam <= 1.0, "lambda in (0, 1]")


def eq14(inp):
    e, lam = _nums(inp["e"]), _num(inp["lambda"])
    require(len(e) >= 1 and _all_fin(e), "non-empty, finite")
    _lam_ok(lam)
    J = e[0] * e[0]
    for x in e[1:]:
        J = (lam * J) + (x * x)
    require(math.isfinite(J), "overflow")
    return {"J": J}


def _rls_init(t, x, y, lam, weighted):
    """Batch (weighted) least squares on the first m samples; P = (T^T W T)^-1 by cofactors."""
    m = len(t)
    w = [1.0] * m
    if weighted:
        for l in range(m - 2, -1, -1):
            w[l] = w[l + 1] * lam
    stt = st = s1 = rx = rx1 = ry = ry1 = 0.0
    for l in range(m):
        wt = w[l] * t[l]
        stt += w[l] * (t[l] * t[l])
        st += wt
        s1 += w[l]
        rx += wt * x[l]
        rx1 += w[l] * x[l]
        ry += wt * y[l]
        ry1 += w[l] * y[l]
    det = (stt * s1) - (st * st)
    require(math.isfinite(det) and det > 0.0, "singular")
    P = [[s1 / det, -st / det], [-st / det, stt / det]]
    A = [(P[0][0] * rx) + (P[0][1] * rx1), (P[1][0] * rx) + (P[1][1] * rx1)]
    B = [(P[0][0] * ry) + (P[0][1] * ry1), (P[1][0] * ry) + (P[1][1] * ry1)]
    require(_all_fin(A + B + P[0] + P[1]), "overflow")
    return A, B, P


def _rls_step(A, B, P, t, x, y, lam):
    Ps = [[P[0][0] / lam, P[0][1] / lam], [P[1][0] / lam, P[1][1] / lam]]  # Eq. 15 as printed
    g0 = (Ps[0][0] * t) + Ps[0][1]
    g1 = (Ps[1][0] * t) + Ps[1][1]
    s = (t * g0) + g1
    den = 1.0 + s
    require(math.isfinite(den) and den > 0.0, "1 + phi^T P phi > 0")
    K = [g0 / den, g1 / den]

    def upd(th, z):
        err = z - _line(th, t)
        return [th[0] + (K[0] * err), th[1] + (K[1] * err)]

    h0 = (t * Ps[0][0]) + Ps[1][0]
    h1 = (t * Ps[0][1]) + Ps[1][1]
    Pn = [[Ps[0][0] - (K[0] * h0), Ps[0][1] - (K[0] * h1)],
          [Ps[1][0] - (K[1] * h0), Ps[1][1] - (K[1] * h1)]]
    A2, B2 = upd(A, x), upd(B, y)
    require(_all_fin(A2 + B2 + Pn[0] + Pn[1] + K), "overflow")
    return A2, B2, Pn


def eq15(inp):
    init = _choice(inp, "init_weights", ["weighted", "unweighted"])
    t, x, y, lam = _nums(inp["t"]), _nums(inp["x"]), _nums(inp["y"]), _num(inp["lambda"])
    m = _int(inp.get("m", 2))
    n = len(t)
    require(len(x) == n and len(y) == n, "one x and one y per time")
    require(2 <= m <= n, "2 <= m <= n")
    require(_all_fin(t) and _all_fin(x) and _all_fin(y), "finite")
    require(all(t[l - 1] < t[l] for l in range(1, n)), "strictly increasing times")
    _lam_ok(lam)
    A, B, P = _rls_init(t[:m], x[:m], y[:m], lam, init == "weighted")
    for l in range(m, n):
        A, B, P = _rls_step(A, B, P, t[l], x[l], y[l], lam)
    return {"A": A, "B": B, "P": P}


RULES = {
    "han.params": params,
    "han.eq1": eq1,
    "han.eq2": eq2,
    "han.eq3": eq3,
    "han.eq4": eq4,
    "han.eq5": eq5,
    "han.eq6": eq6,
    "han.eq7": eq7,
    "han.eq8": eq8,
    "han.eq9": eq9,
    "han.eq10": eq10,
    "han.eq11": eq11,
    "han.eq12": eq12,
    "han.eq13": eq13,
    "han.eq14": eq14,
    "han.eq15": eq15,
}
