"""spec/curves.md (curves.knots, curves.sample, curves.clearance) and the B-spline rules of
spec/sensors2023.md (eq6, eq7, eq8, a1, a2, a3), written from the spec alone.

Deliberately the plainest readings: the Cox-de Boor recursion fills the whole triangular table
N_{i,q} for every i (the C++ library computes only the p + 1 non-zero entries of the span), the
curve sums over every control point, and the clearance takes the minimum over every blocked cell
of the map (the C++ library searches growing windows). The spec says these give the same doubles.
"""
import math

from .common import DomainError, require
from .search import Map, UsageError

MAX_DEGREE = 20
MAX_CONTROL = 1 << 20
MAX_SAMPLES = 1 << 24


def _pt(v):
    if not (isinstance(v, list) and len(v) == 2 and all(isinstance(t, (int, float)) and not isinstance(t, bool) for t in v)):
        raise UsageError("a point is [x, y]")
    return (float(v[0]), float(v[1]))


def _pts(inp, key):
    v = inp[key]
    if not isinstance(v, list):
        raise UsageError(key + " must be a list of points")
    return [_pt(p) for p in v]


def _finite(p):
    return math.isfinite(p[0]) and math.isfinite(p[1])


def _num(x):
    if isinstance(x, float) and math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return x


# ---- curves.knots --------------------------------------------------------------------------

def _check_count(m, p):
    require(1 <= p <= MAX_DEGREE, "degree")
    require(m <= MAX_CONTROL, "too many control points")
    require(m >= p + 1, "m >= p + 1")


def uniform_knots(m, p):
    _check_count(m, p)
    return [float(j) for j in range(m + p + 1)]


def clamped_knots(m, p):
    _check_count(m, p)
    u = []
    for j in range(m + p + 1):
        if j <= p:
            u.append(0.0)
        elif j >= m:
            u.append(float(m - p))
        else:
            u.append(float(j - p))
    return u


def control_polygon(points, p, end):
    require(1 <= p <= MAX_DEGREE, "degree")
    require(len(points) >= 1, "no points")
    require(all(_finite(q) for q in points), "finite")
    if end != "repeated":
        return list(points)
    return [points[0]] * (p - 1) + list(points) + [points[-1]] * (p - 1)


def make_curve(points, p, end):
    if end not in ("clamped", "repeated", "none"):
        raise UsageError("end")
    ctrl = control_polygon(points, p, end)
    knots = clamped_knots(len(ctrl), p) if end == "clamped" else uniform_knots(len(ctrl), p)
    return p, knots, ctrl


def degree_for(n, p, end):
    require(1 <= p <= MAX_DEGREE, "degree")
    require(n >= 1, "no points")
    for q in range(p, 0, -1):
        m = n + 2 * (q - 1) if end == "repeated" else n
        if m >= q + 1:
            return q
    raise DomainError("no degree")


def check_curve(p, knots, ctrl):
    m = len(ctrl)
    _check_count(m, p)
    require(len(knots) == m + p + 1, "knot count")
    require(all(math.isfinite(u) for u in knots), "finite knots")
    require(all(knots[j - 1] <= knots[j] for j in range(1, len(knots))), "non-decreasing")
    require(knots[p] < knots[m], "empty domain")
    require(all(_finite(q) for q in ctrl), "finite control")


def _degree(inp):
    p = inp["degree"]
    if not isinstance(p, int) or isinstance(p, bool):
        raise UsageError("degree must be an integer")
    return p


def _curve(inp):
    p = _degree(inp)
    if "knots" in inp:
        knots = [float(u) for u in inp["knots"]]
        return p, knots, _pts(inp, "control")
    return make_curve(_pts(inp, "points"), p, inp.get("end", "repeated"))


def rule_knots(inp):
    points = _pts(inp, "points")
    p = _degree(inp)
    end = inp.get("end", "repeated")
    p, knots, ctrl = make_curve(points, p, end)
    check_curve(p, knots, ctrl)
    return {"knots": knots, "control": [list(q) for q in ctrl], "domain": [knots[p], knots[len(ctrl)]],
            "degree_for": degree_for(len(points), _degree(inp), end)}


# ---- sensors2023.eq7 / eq6 -----------------------------------------------------------------

def span_index(knots, p, m, u):
    require(u >= knots[p] and u <= knots[m], "u outside the domain")
    if u == knots[m]:
        k = m - 1
        while not knots[k] < knots[k + 1]:
            k -= 1
        return k
    k = p
    while not (knots[k] <= u < knots[k + 1]):
        k += 1
    return k


def basis(knots, p, m, u):
    """The whole Cox-de Boor table, every i, 0/0 := 0."""
    _check_count(m, p)
    require(len(knots) == m + p + 1, "knot count")
    require(all(knots[j - 1] <= knots[j] for j in range(1, len(knots))), "non-decreasing")
    require(knots[p] < knots[m], "empty domain")
    k = span_index(knots, p, m, u)
    size = m + p  # N_{i,0} for i = 0 .. m + p - 1
    n = [1.0 if i == k else 0.0 for i in range(size)]
    for q in range(1, p + 1):
        nxt = []
        for i in range(size - q):
            dl = knots[i + q] - knots[i]
            dr = knots[i + q + 1] - knots[i + 1]
            a = 0.0 if dl == 0.0 else ((u - knots[i]) / dl) * n[i]
            b = 0.0 if dr == 0.0 else ((knots[i + q + 1] - u) / dr) * n[i + 1]
            nxt.append(a + b)
        n = nxt
    return n[:m], k


def evaluate(p, knots, ctrl, u):
    check_curve(p, knots, ctrl)
    n, _ = basis(knots, p, len(ctrl), u)
    x = 0.0
    y = 0.0
    for i, q in enumerate(ctrl):
        x = x + n[i] * q[0]
        y = y + n[i] * q[1]
    return (x, y)


def rule_eq7(inp):
    p = _degree(inp)
    m = inp["count"]
    require(m >= 0, "count")
    knots = [float(u) for u in inp["knots"]]
    n, k = basis(knots, p, m, float(inp["u"]))
    return {"n": n, "span": k}


def rule_eq6(inp):
    p, knots, ctrl = _curve(inp)
    return {"point": list(evaluate(p, knots, ctrl, float(inp["u"])))}


# ---- uniform forms -------------------------------------------------------------------------

def _check_t(t):
    require(0.0 <= t <= 1.0, "t in [0, 1]")


def uniform_basis(j, n, t):
    require(1 <= n <= MAX_DEGREE, "degree")
    require(0 <= j <= n, "0 <= j <= n")
    _check_t(t)
    s = 0.0
    for q in range(0, n - j + 1):
        sign = 1.0 if q % 2 == 0 else -1.0
        b = t + float(n - j - q)
        power = 1.0
        for _ in range(n):
            power *= b
        binom = 1.0
        for i in range(1, q + 1):
            binom = binom * float(n + 1 - q + i) / float(i)
        s = s + sign * binom * power
    fact = 1.0
    for i in range(2, n + 1):
        fact *= float(i)
    return s / fact


def rule_a2(inp):
    return {"f": uniform_basis(inp["j"], inp["n"], float(inp["t"]))}


def rule_a3(inp):
    t = float(inp["t"])
    _check_t(t)
    s = 1.0 - t
    t2 = t * t
    t3 = t2 * t
    return {"f": [s * s * s / 6.0, (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0,
                  (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0, t3 / 6.0]}


def rule_a1(inp):
    pts = _pts(inp, "control")
    require(2 <= len(pts) <= MAX_DEGREE + 1, "2 .. 21 points")
    require(all(_finite(q) for q in pts), "finite")
    t = float(inp["t"])
    _check_t(t)
    n = len(pts) - 1
    x = 0.0
    y = 0.0
    for j in range(n + 1):
        f = uniform_basis(j, n, t)
        x = x + f * pts[j][0]
        y = y + f * pts[j][1]
    return {"point": [x, y]}


M8 = [[-1.0, 3.0, -3.0, 1.0], [3.0, -6.0, 3.0, 0.0], [-3.0, 0.0, 3.0, 0.0], [1.0, 4.0, 1.0, 0.0]]


def rule_eq8(inp):
    pts = _pts(inp, "control")
    if len(pts) != 4:
        raise UsageError("4 points")
    require(all(_finite(q) for q in pts), "finite")
    t = float(inp["t"])
    _check_t(t)
    row = [t * t * t, t * t, t, 1.0]
    w = []
    for j in range(4):
        s = 0.0
        for r in range(4):
            s = s + row[r] * M8[r][j]
        w.append(s)
    x = 0.0
    y = 0.0
    for j in range(4):
        x = x + w[j] * pts[j][0]
        y = y + w[j] * pts[j][1]
    return {"point": [x / 6.0, y / 6.0]}


# ---- curves.sample -------------------------------------------------------------------------

def sample(p, knots, ctrl, spacing):
    check_curve(p, knots, ctrl)
    require(math.isfinite(spacing) and spacing > 0.0, "spacing")
    m = len(ctrl)
    plan = []
    total = 1
    for k in range(p, m):
        width = knots[k + 1] - knots[k]
        if not width > 0.0:
            continue
        d = 0.0
        for i in range(k - p + 1, k + 1):
            den = knots[i + p] - knots[i]
            if den == 0.0:
                continue
            dx = ctrl[i][0] - ctrl[i - 1][0]
            dy = ctrl[i][1] - ctrl[i - 1][1]
            d = max(d, float(p) * math.sqrt(dx * dx + dy * dy) / den)
        want = math.ceil(d * width / spacing)
        require(want < MAX_SAMPLES, "too many samples")
        steps = max(1, want)
        total += steps
        require(total <= MAX_SAMPLES, "too many samples")
        plan.append((k, width, steps, d * width / float(steps)))
    params, points, chord = [], [], 0.0
    for k, width, steps, bound in plan:
        for j in range(steps):
            u = knots[k] + float(j) * width / float(steps)
            params.append(u)
            points.append(list(evaluate(p, knots, ctrl, u)))
        chord = max(chord, bound)
    params.append(knots[m])
    points.append(list(evaluate(p, knots, ctrl, knots[m])))
    return params, points, chord


def rule_sample(inp):
    p, knots, ctrl = _curve(inp)
    params, points, chord = sample(p, knots, ctrl, float(inp["spacing"]))
    return {"params": params, "points": points, "chord": chord}


# ---- curves.clearance ----------------------------------------------------------------------

def point_box(p, x0, y0, x1, y1):
    dx = max(x0 - p[0], 0.0, p[0] - x1)
    dy = max(y0 - p[1], 0.0, p[1] - y1)
    return math.sqrt(dx * dx + dy * dy)


def point_segment(p, a, b):
    dx = b[0] - a[0]
    dy = b[1] - a[1]
    len2 = dx * dx + dy * dy
    s = 0.0
    if len2 > 0.0:
        s = min(max(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2, 0.0), 1.0)
    qx = a[0] + s * dx
    qy = a[1] + s * dy
    return math.sqrt((p[0] - qx) * (p[0] - qx) + (p[1] - qy) * (p[1] - qy))


def segment_meets_box(a, b, x0, y0, x1, y1):
    dx = b[0] - a[0]
    dy = b[1] - a[1]
    t0, t1 = 0.0, 1.0
    for pk, qk in ((-dx, a[0] - x0), (dx, x1 - a[0]), (-dy, a[1] - y0), (dy, y1 - a[1])):
        if pk == 0.0:
            if qk < 0.0:
                return False
            continue
        t = qk / pk
        if pk < 0.0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
    return t0 <= t1


def segment_box(a, b, x0, y0, x1, y1):
    if segment_meets_box(a, b, x0, y0, x1, y1):
        return 0.0
    return min(point_box(a, x0, y0, x1, y1), point_box(b, x0, y0, x1, y1),
               point_segment((x0, y0), a, b), point_segment((x1, y0), a, b),
               point_segment((x0, y1), a, b), point_segment((x1, y1), a, b))


def _border(p, w, h):
    return max(0.0, min(p[0], w - p[0], p[1], h - p[1]))


def clearance(g, pts, inflation, tolerance, border):
    require(len(pts) >= 1, "no points")
    require(all(_finite(q) for q in pts), "finite")
    require(math.isfinite(inflation) and inflation >= 0.0, "inflation")
    require(math.isfinite(tolerance) and tolerance >= 0.0, "tolerance")
    w, h = float(g.w), float(g.h)
    cells = sorted(g.blocked)

    def seg(a, b):
        d = math.inf
        if border:
            d = min(_border(a, w, h), _border(b, w, h))
        for (x, y) in cells:
            d = min(d, segment_box(a, b, float(x), float(y), float(x) + 1.0, float(y) + 1.0))
        return d

    dist, index = math.inf, -1
    pieces = 1 if len(pts) == 1 else len(pts) - 1
    for s in range(pieces):
        a = pts[s]
        b = pts[s] if len(pts) == 1 else pts[s + 1]
        d = seg(a, b)
        if d < dist:
            dist, index = d, s
    if tolerance == 0.0:
        lower = upper = dist
    else:
        lower = max(0.0, dist - tolerance)
        upper = min(seg(q, q) for q in pts)
    if upper <= inflation:
        verdict = "enters"
    elif lower > inflation:
        verdict = "clear"
    else:
        verdict = "undetermined"
    return dist, lower, upper, verdict, index


def rule_clearance(inp):
    g = Map(inp["grid"])
    border = inp.get("border", True)
    d, lo, up, verdict, seg = clearance(g, _pts(inp, "points"), float(inp.get("inflation", 0.0)),
                                        float(inp.get("tolerance", 0.0)), border)
    return {"distance": _num(d), "lower": _num(lo), "upper": _num(up), "verdict": verdict, "segment": seg}


# ---- curves.curvature ----------------------------------------------------------------------

def _basis_table(knots, q, k, u):
    """N_{i,q}(u) for every i (whole Cox-de Boor table) from N_{i,0} = [i == k], 0/0 := 0."""
    size = len(knots) - 1
    n = [1.0 if i == k else 0.0 for i in range(size)]
    for r in range(1, q + 1):
        nxt = []
        for i in range(size - r):
            dl = knots[i + r] - knots[i]
            dr = knots[i + r + 1] - knots[i + 1]
            a = 0.0 if dl == 0.0 else ((u - knots[i]) / dl) * n[i]
            b = 0.0 if dr == 0.0 else ((knots[i + r + 1] - u) / dr) * n[i + 1]
            nxt.append(a + b)
        n = nxt
    return n


def derivatives(p, knots, ctrl, u):
    check_curve(p, knots, ctrl)
    m = len(ctrl)
    k = span_index(knots, p, m, u)
    pt = evaluate(p, knots, ctrl, u)
    # Q_j = p (P_j - P_{j-1}) / (u_{j+p} - u_j), j = 1 .. m - 1 (0 where the denominator is 0)
    q = {}
    for j in range(1, m):
        den = knots[j + p] - knots[j]
        if den == 0.0:
            q[j] = (0.0, 0.0)
        else:
            q[j] = ((float(p) * (ctrl[j][0] - ctrl[j - 1][0])) / den, (float(p) * (ctrl[j][1] - ctrl[j - 1][1])) / den)
    n1 = _basis_table(knots, p - 1, k, u)
    fx = fy = 0.0
    for j in range(1, m):
        fx = fx + n1[j] * q[j][0]
        fy = fy + n1[j] * q[j][1]
    sx = sy = 0.0
    if p >= 2:
        n2 = _basis_table(knots, p - 2, k, u)
        for j in range(2, m):
            den = knots[j + p - 1] - knots[j]
            if den == 0.0:
                continue
            rx = (float(p - 1) * (q[j][0] - q[j - 1][0])) / den
            ry = (float(p - 1) * (q[j][1] - q[j - 1][1])) / den
            sx = sx + n2[j] * rx
            sy = sy + n2[j] * ry
    return pt, (fx, fy), (sx, sy)


def curvature(p, knots, ctrl, u):
    _, d1, d2 = derivatives(p, knots, ctrl, u)
    s2 = d1[0] * d1[0] + d1[1] * d1[1]
    if s2 == 0.0:
        return math.inf
    return (d1[0] * d2[1] - d1[1] * d2[0]) / (s2 * math.sqrt(s2))


def rule_curvature(inp):
    p, knots, ctrl = _curve(inp)
    u = float(inp["u"])
    pt, d1, d2 = derivatives(p, knots, ctrl, u)
    return {"point": list(pt), "first": list(d1), "second": list(d2),
            "curvature": _num(curvature(p, knots, ctrl, u))}


# ---- cin2021 Eq. 12-15 (spec/cin2021-srrt.md): clamped curves over S-RRT's nodes --------------

def clamped_chord_knots(ctrl, p):
    m = len(ctrl)
    _check_count(m, p)
    require(all(_finite(q) for q in ctrl), "finite")
    t = [0.0] * m
    for i in range(1, m):
        dx = ctrl[i][0] - ctrl[i - 1][0]
        dy = ctrl[i][1] - ctrl[i - 1][1]
        t[i] = t[i - 1] + math.sqrt(dx * dx + dy * dy)
    total = t[m - 1]
    u = clamped_knots(m, p)
    if not total > 0.0:
        return u
    top = float(m - p)
    den = float(p) * total
    for j in range(1, m - p):
        s = 0.0
        for i in range(j, j + p):
            s = s + t[i]
        u[p + j] = min(top, (top * s) / den)
    return u


def clamped_curve(points, degree, spacing):
    if spacing not in ("uniform", "chord"):
        raise UsageError("knots must be uniform or chord")
    p = degree_for(len(points), degree, "clamped")
    ctrl = control_polygon(points, p, "clamped")
    knots = clamped_knots(len(ctrl), p) if spacing == "uniform" else clamped_chord_knots(ctrl, p)
    return p, knots, ctrl


def _clamped(inp):
    return clamped_curve(_pts(inp, "points"), _degree(inp), inp.get("knots", "uniform"))


def rule_eq12(inp):
    p, knots, ctrl = _clamped(inp)
    return {"point": list(evaluate(p, knots, ctrl, float(inp["u"]))), "degree": p}


def rule_eq13(inp):
    p = _degree(inp)
    m = inp["count"]
    knots = [float(u) for u in inp["knots"]]
    _check_count(m, p)
    require(len(knots) == m + p + 1, "knot count")
    require(all(math.isfinite(u) for u in knots), "finite knots")
    require(all(knots[j - 1] <= knots[j] for j in range(1, len(knots))), "non-decreasing")
    require(knots[p] < knots[m], "empty domain")
    k = span_index(knots, p, m, float(inp["u"]))
    return {"n0": [1 if i == k else 0 for i in range(len(knots) - 1)], "span": k}


def rule_eq15(inp):
    p, knots, ctrl = _clamped(inp)
    check_curve(p, knots, ctrl)
    return {"degree": p, "knots": knots, "domain": [knots[p], knots[len(ctrl)]]}


RULES = {
    "curves.knots": rule_knots,
    "curves.sample": rule_sample,
    "curves.clearance": rule_clearance,
    "curves.curvature": rule_curvature,
    "cin2021.eq12": rule_eq12,
    "cin2021.eq13": rule_eq13,
    "cin2021.eq14": rule_eq7,
    "cin2021.eq15": rule_eq15,
    "sensors2023.eq6": rule_eq6,
    "sensors2023.eq7": rule_eq7,
    "sensors2023.eq8": rule_eq8,
    "sensors2023.a1": rule_a1,
    "sensors2023.a2": rule_a2,
    "sensors2023.a3": rule_a3,
}
