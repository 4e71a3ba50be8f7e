"""spec/shi2022.md (and the parts of spec/grid.md and spec/metrics.md it uses), from the spec alone.

Every rule is re-derived from the spec text: cells are tuples, sums run left to right as the spec
says, the turning bands use the exact integer tests of r[shi2022.eq17], and the readings are
selected by the parameter names the spec gives. Python floats are binary64 with the same IEEE
operations, so hand values match bit for bit; libm calls (exp, cos, atan2, pow) match within the
tolerance each golden file states.
"""
import math

from .common import require


class UsageError(Exception):
    """A malformed request (the C++ UsageError); never expected by a golden vector."""


LIM25 = 1 << 25
LIM30 = 1 << 30
MAX_CELLS = 1 << 28
HALF_PI = math.pi / 2.0  # the binary64 pi halved (exact)

# Table 1 (r[shi2022.table1]).
TABLE1 = {"ants": 50, "aco_iterations": 100, "alpha": 1.0, "beta": 7.0, "Q": 1.0, "rho_initial": 0.9,
          "rho_min": 0.1, "ga_population": 200, "ga_generations": 50, "a": 5.0, "b": 4.0, "c": 1.0,
          "pc": 0.8, "pm": 0.1, "pm_max": 0.3}


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


def _cell(v):
    if not (isinstance(v, list) and len(v) == 2 and all(_is_int(t) for t in v)):
        raise UsageError("a cell is [x, y] with two integers")
    return (v[0], v[1])


def _path(v):
    if not isinstance(v, list):
        raise UsageError("a path is a list of cells")
    return [_cell(c) for c in v]


def _choice(inp, key, options):
    v = inp.get(key, options[0])
    if v not in options:
        raise UsageError(f"{key} must be one of {options}")
    return v


def _finite_nonneg(x):
    return math.isfinite(x) and x >= 0.0


# ---- metrics pieces (spec/metrics.md) -------------------------------------------------------


def _coord_ok(c, lim=LIM25):
    return abs(c[0]) <= lim and abs(c[1]) <= lim


def _dist(a, b):
    """metrics.length segment: sqrt of the exact integer sum of squares, correctly rounded."""
    require(_coord_ok(a) and _coord_ok(b), "coordinates must satisfy |x|, |y| <= 2^25")
    dx, dy = b[0] - a[0], b[1] - a[1]
    return math.sqrt(float(dx * dx + dy * dy))


def _check_path(path):
    require(len(path) >= 1, "empty path")
    for k in range(1, len(path)):
        require(path[k] != path[k - 1], "consecutive repeated node")
    for c in path:
        require(_coord_ok(c), "coordinates must satisfy |x|, |y| <= 2^25")


def _length(path):
    _check_path(path)
    total = 0.0
    for k in range(1, len(path)):
        total += _dist(path[k - 1], path[k])
    return total


def _uv(a, b, c):
    return (b[0] - a[0], b[1] - a[1]), (c[0] - b[0], c[1] - b[1])


def _theta(a, b, c):
    (ux, uy), (vx, vy) = _uv(a, b, c)
    return math.atan2(float(abs(ux * vy - uy * vx)), float(ux * vx + uy * vy))


def _band(a, b, c):
    """r[shi2022.eq17]: 0 straight, 1 (0, 45], 2 (45, 90], 3 (90, 180] degrees, exactly."""
    (ux, uy), (vx, vy) = _uv(a, b, c)
    dot = ux * vx + uy * vy
    cross = ux * vy - uy * vx
    if cross == 0 and dot > 0:
        return 0
    if dot > 0 and abs(cross) <= dot:
        return 1
    if dot >= 0:
        return 2
    return 3


BAND_NAMES = ["straight", "up_to_45", "up_to_90", "above_90"]


class _Grid:
    def __init__(self, rows):
        if not isinstance(rows, list) or not all(isinstance(r, str) for r in rows):
            raise UsageError("grid must be an array of strings")
        require(len(rows) >= 1 and len(rows[0]) >= 1, "empty grid")
        require(all(len(r) == len(rows[0]) for r in rows), "ragged rows")
        require(all(ch in ".#" for r in rows for ch in r), "only '.' and '#'")
        self.w, self.h = len(rows[0]), len(rows)
        self.blocked = {(x, self.h - 1 - r) for r, row in enumerate(rows) for x, ch in enumerate(row) if ch == "#"}

    def inside(self, c):
        return 0 <= c[0] < self.w and 0 <= c[1] < self.h


def _safety_counts(g, path, outside):
    """metrics.safety: blocked 8-neighbours per node; outside cells count when outside = blocked."""
    require(len(path) >= 1, "empty path")
    for k in range(1, len(path)):
        require(path[k] != path[k - 1], "consecutive repeated node")
    for c in path:
        require(g.inside(c), "node outside the grid")
    out = []
    for (x, y) in path:
        s = 0
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                if dx == 0 and dy == 0:
                    continue
                q = (x + dx, y + dy)
                if g.inside(q):
                    s += q in g.blocked
                elif outside == "blocked":
                    s += 1
        out.append(s)
    return out


# ---- rules ----------------------------------------------------------------------------------


def table1(inp):
    return dict(TABLE1)


def eq1(inp):
    """grid.coord: corrected x = (i mod W) + 0.5, y = floor(i/W) + 0.5; printed forms."""
    i, w, h = inp["i"], inp["width"], inp["height"]
    form = _choice(inp, "form", ["corrected", "printed0", "printed1"])
    require(w >= 1 and h >= 1 and w * h <= MAX_CELLS, "bad grid size")
    require(0 <= i < w * h, "i out of range")
    if form == "corrected":
        return {"x": (i % w) + 0.5, "y": (i // w) + 0.5}
    k = i if form == "printed0" else i + 1
    return {"x": (k % w) + 0.5, "y": -(-k // w) - 0.5}


def eq2(inp):
    tau = [_num(v) for v in inp["tau"]]
    eta = [_num(v) for v in inp["eta"]]
    alpha, beta = _num(inp["alpha"]), _num(inp["beta"])
    require(len(tau) >= 1, "empty allowed set")
    require(len(tau) == len(eta), "length mismatch")
    require(_finite_nonneg(alpha) and _finite_nonneg(beta), "alpha, beta >= 0")
    w = []
    for t, e in zip(tau, eta):
        require(_finite_nonneg(t) and _finite_nonneg(e), "tau, eta >= 0")
        try:
            v = math.pow(t, alpha) * math.pow(e, beta)
        except OverflowError:
            v = math.inf
        require(math.isfinite(v), "weight overflows")
        w.append(v)
    return {"weights": w, "p": _proportional(w)}


def _proportional(w):
    require(len(w) >= 1, "no weights")
    s = 0.0
    for v in w:
        require(_finite_nonneg(v), "weights >= 0")
        s += v
    require(math.isfinite(s) and s > 0.0, "sum must be positive and finite")
    return [v / s for v in w]


def eq3(inp):
    i, j = _cell(inp["i"]), _cell(inp["j"])
    require(i != j, "i == j")
    return {"eta": 1.0 / _dist(i, j)}


def eq4(inp):
    return {"d": _dist(_cell(inp["i"]), _cell(inp["j"]))}


def eq5(inp):
    tau, rho, delta = _num(inp["tau"]), _num(inp["rho"]), _num(inp["delta"])
    require(_finite_nonneg(tau) and _finite_nonneg(delta), "tau, delta >= 0")
    require(math.isfinite(rho) and 0.0 < rho < 1.0, "0 < rho < 1")
    r = (1.0 - rho) * tau + delta
    require(math.isfinite(r), "overflow")
    return {"tau_next": r}


def eq6(inp):
    s = 0.0
    for v in inp["deposits"]:
        v = _num(v)
        require(_finite_nonneg(v), "deposit >= 0")
        s += v
    require(math.isfinite(s), "overflow")
    return {"delta": s}


def eq7(inp):
    Q = _num(inp["Q"])
    path = _path(inp["path"])
    frm, to = _cell(inp["from"]), _cell(inp["to"])
    sense = _choice(inp, "edge_sense", ["directed", "undirected"])
    repeats = _choice(inp, "edge_repeats", ["once", "per_traversal"])
    require(frm != to, "from == to")
    require(math.isfinite(Q) and Q > 0.0, "Q > 0")
    L = _length(path)
    require(len(path) >= 2, "L = 0")
    c = 0
    for k in range(1, len(path)):
        step = (path[k - 1], path[k])
        if step == (frm, to) or (sense == "undirected" and step == (to, frm)):
            c += 1
    if c == 0:
        d = 0.0
    elif repeats == "once":
        d = Q / L
    else:
        d = float(c) * (Q / L)
    return {"deposit": d, "L": L}


def eq8(inp):
    a, b = _cell(inp["a"]), _cell(inp["b"])
    require(_coord_ok(a, LIM30 - 1) and _coord_ok(b, LIM30 - 1), "|coordinates| < 2^30")
    d = max(abs(b[0] - a[0]), abs(b[1] - a[1]))
    return {"delta": d, "continuous": d == 1}


def _half(s, rounding):
    q, r = divmod(s, 2)
    if r == 0 or rounding == "floor":
        return q
    if rounding == "ceil":
        return q + 1
    return q if q % 2 == 0 else q + 1  # half_even


def eq9(inp):
    a, b = _cell(inp["a"]), _cell(inp["b"])
    w, h = inp["width"], inp["height"]
    rounding = _choice(inp, "mid_rounding", ["floor", "ceil", "half_even"])
    number = _choice(inp, "mid_number", ["row_major", "printed_sum"])
    require(w >= 1 and h >= 1 and w * h <= MAX_CELLS, "bad grid size")
    for c in (a, b):
        require(0 <= c[0] < w and 0 <= c[1] < h, "cell outside the grid")
    x, y = _half(a[0] + b[0], rounding), _half(a[1] + b[1], rounding)
    n = y * w + x if number == "row_major" else x + y
    return {"cell": [x, y], "number": n}


def _inverse_length(inp):
    L = _num(inp["length"])
    require(math.isfinite(L) and L > 0.0, "length > 0")
    return 1.0 / L


def eq10(inp):
    return {"fit": _inverse_length(inp)}


def eq15(inp):
    return {"fit1": _inverse_length(inp)}


def eq11(inp):
    return {"p": _proportional([_num(v) for v in inp["fitness"]])}


def eq12(inp):
    i, j, e = _cell(inp["i"]), _cell(inp["j"]), _cell(inp["goal"])
    require(i != j, "i == j")
    return {"eta": 1.0 / (_dist(i, j) + _dist(j, e))}


def _rho_step(rho, t, T, rho_min, reading):
    require(1 <= T <= (1 << 31), "T")
    require(0 <= t <= T, "t in [0, T]")
    require(math.isfinite(rho) and 0.0 < rho < 1.0, "rho in (0, 1)")
    require(math.isfinite(rho_min) and 0.0 <= rho_min < 1.0, "rho_min in [0, 1)")
    a = float(T) / float(T + t)
    b = 1.0 / math.exp(1.0 - rho)
    if reading == "factor":
        v = (a * b) * rho
        return v if v > rho_min else rho_min
    if reading == "condition":
        return a * b if rho > rho_min else rho_min
    v = a * b
    return v if v > rho_min else rho_min


def eq13(inp):
    reading = _choice(inp, "rho_reading", ["factor", "condition", "clamp"])
    rho, t, T, rho_min = _num(inp["rho"]), inp["t"], inp["T"], _num(inp["rho_min"])
    out = {"rho_next": _rho_step(rho, t, T, rho_min, reading)}
    if "steps" in inp:
        steps = inp["steps"]
        require(steps >= 1 and t + steps - 1 <= T, "steps")
        seq = []
        for s in range(steps):
            rho = _rho_step(rho, t + s, T, rho_min, reading)
            seq.append(rho)
        out["sequence"] = seq
    return out


def eq14(inp):
    f1, f2, f3 = _num(inp["fit1"]), _num(inp["fit2"]), _num(inp["fit3"])
    a = _num(inp.get("a", TABLE1["a"]))
    b = _num(inp.get("b", TABLE1["b"]))
    c = _num(inp.get("c", TABLE1["c"]))
    require(all(_finite_nonneg(v) for v in (f1, f2, f3, a, b, c)), "finite and >= 0")
    r = ((a * f1) + (b * f2)) + (c * f3)
    require(math.isfinite(r), "overflow")
    return {"fit": r}


def eq16(inp):
    path = _path(inp["path"])
    reading = _choice(inp, "smoothness", ["inverse_total_plus_one", "per_node", "per_turn",
                                          "angle_times_penalty", "inverse_total"])
    pen = [_num(v) for v in inp.get("penalties", [5, 100, 1000])]
    if len(pen) != 3:
        raise UsageError("penalties")
    require(all(math.isfinite(p) and p > 0.0 for p in pen), "penalties > 0")
    _check_path(path)
    P = [1.0] + pen
    s, turns = 0.0, 0
    for k in range(1, len(path) - 1):
        band = _band(path[k - 1], path[k], path[k + 1])
        p = P[band]
        if band:
            turns += 1
        if reading == "per_node":
            s += 1.0 / p
        elif band and reading == "per_turn":
            s += 1.0 / p
        elif band and reading == "angle_times_penalty":
            s += 1.0 / (p * _theta(path[k - 1], path[k], path[k + 1]))
        elif band and reading in ("inverse_total", "inverse_total_plus_one"):
            s += p
    if reading == "inverse_total":
        require(turns > 0, "no turn: 1/0")
        return {"fit2": 1.0 / s}
    if reading == "inverse_total_plus_one":
        return {"fit2": 1.0 / (1.0 + s)}
    return {"fit2": s}


def eq17(inp):
    path = _path(inp["path"])
    _check_path(path)
    theta, band = [], []
    for k in range(1, len(path) - 1):
        theta.append(_theta(path[k - 1], path[k], path[k + 1]))
        band.append(BAND_NAMES[_band(path[k - 1], path[k], path[k + 1])])
    return {"theta": theta, "band": band}


def eq18(inp):
    g = _Grid(inp["grid"])
    path = _path(inp["path"])
    aggregate = _choice(inp, "safety_aggregate", ["inverse_total_plus_one", "per_node", "mean"])
    count = _choice(inp, "safety_count", ["count", "indicator"])
    safe = _choice(inp, "safe_node", ["one", "skip"])
    nodes = _choice(inp, "safety_nodes", ["all_but_goal", "all", "interior"])
    outside = _choice(inp, "outside", ["free", "blocked"])
    s = _safety_counts(g, path, outside)
    n = len(path)
    idx = {"all_but_goal": range(0, n - 1), "all": range(0, n), "interior": range(1, n - 1)}[nodes]
    hazards = [s[k] if count == "count" else (1 if s[k] > 0 else 0) for k in idx]
    if aggregate == "inverse_total_plus_one":
        # the reciprocal of 1 + the path's total hazard, the convention of Eq. (16)
        return {"fit3": 1.0 / (1 + sum(hazards))}
    total = 0.0
    for v in hazards:
        S = 1 + v if safe == "one" else v
        if S:
            total += 1.0 / S
    if aggregate == "mean":
        return {"fit3": total / len(hazards) if hazards else 0.0}
    return {"fit3": total}


def _gens(i, mg):
    require(1 <= mg <= (1 << 31), "M_g")
    require(0 <= i <= mg, "i in [0, M_g]")


def eq19(inp):
    i, mg = inp["i"], inp["M_g"]
    reading = _choice(inp, "pc_reading", ["printed", "scaled"])
    _gens(i, mg)
    scale = TABLE1["pc"] if reading == "scaled" else 1.0
    return {"pc": scale * math.cos(HALF_PI * (float(i) / float(mg + i)))}


def eq20(inp):
    i, mg, pm_max = inp["i"], inp["M_g"], _num(inp["pm_max"])
    reading = _choice(inp, "pm_reading", ["printed", "scaled"])
    at_zero = _choice(inp, "pm_at_zero", ["binary64", "exact_zero"])
    _gens(i, mg)
    require(math.isfinite(pm_max) and 0.0 < pm_max <= 1.0, "P_m_max in (0, 1]")
    scale = TABLE1["pm"] if reading == "scaled" else 1.0
    if i == 0 and at_zero == "exact_zero":
        m = 0.0
    else:
        m = scale * math.cos(HALF_PI * (float(mg - i) / float(mg + i)))
    return {"pm": m if m < pm_max else pm_max}


RULES = {
    "shi2022.table1": table1,
    "shi2022.eq1": eq1,
    "shi2022.eq2": eq2,
    "shi2022.eq3": eq3,
    "shi2022.eq4": eq4,
    "shi2022.eq5": eq5,
    "shi2022.eq6": eq6,
    "shi2022.eq7": eq7,
    "shi2022.eq8": eq8,
    "shi2022.eq9": eq9,
    "shi2022.eq10": eq10,
    "shi2022.eq11": eq11,
    "shi2022.eq12": eq12,
    "shi2022.eq13": eq13,
    "shi2022.eq14": eq14,
    "shi2022.eq15": eq15,
    "shi2022.eq16": eq16,
    "shi2022.eq17": eq17,
    "shi2022.eq18": eq18,
    "shi2022.eq19": eq19,
    "shi2022.eq20": eq20,
}
