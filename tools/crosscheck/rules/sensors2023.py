"""spec/sensors2023.md eq1-eq5 and the planner sensors2023.plan.astar-kinematic, written from the
spec alone (Python 3 standard library only).

The search is the plainest reading of spec/search.md with an expansion rule: OPEN is a set of
cells and each selection scans it for the least key (f, h, index). The collision test checks
every blocked cell of the segment's bounding box with the separating-axis test in doubled
integer coordinates; the safety test checks every blocked cell of the map. The B-spline,
sampling and clearance come from curves.py (the same spec, spec/curves.md).
"""
import math

from .common import DomainError, require
from .search import Map, UsageError, cell, policy, allowed, cost, h_euclidean
from .metrics import turns as metrics_turns, length as metrics_length
from . import curves

RAD = 57.29577951308232  # the double nearest 180 / pi
LIMIT = 1 << 30
# bearing -> move; the 8 moves in grid.neighbour-order
BEARING_MOVE = {0: (0, 1), 45: (1, 1), 90: (1, 0), 135: (1, -1), 180: (0, -1), 225: (-1, -1), 270: (-1, 0), 315: (-1, 1)}
ORDER = [(-1, -1), (0, -1), (1, -1), (-1, 0), (1, 0), (-1, 1), (0, 1), (1, 1)]


def label(b):
    return "%03dT" % b


# ---- eq1 -----------------------------------------------------------------------------------

def bearing(n, g):
    for v in (*n, *g):
        require(-LIMIT < v < LIMIT, "coordinates")
    require(n != g, "bearing of the goal from itself")
    return math.fmod(RAD * math.atan2(float(g[0] - n[0]), float(g[1] - n[1])) + 360.0, 360.0)


def sector(theta):
    require(0.0 <= theta < 360.0, "theta in [0, 360)")
    return sum(1 for j in range(8) if theta >= 22.5 + 45.0 * j) % 8


def kept(s):
    require(0 <= s <= 7, "sector")
    return sorted((45 * s + 270 + 45 * i) % 360 for i in range(5))


def abandoned(s):
    require(0 <= s <= 7, "sector")
    return sorted((45 * s + 135 + 45 * i) % 360 for i in range(3))


def nbhd_free(m, n, radius):
    require(m.inside(n), "node outside the grid")
    require(1 <= radius <= 64, "radius")
    for dy in range(-radius, radius + 1):
        for dx in range(-radius, radius + 1):
            if (dx, dy) == (0, 0):
                continue
            c = (n[0] + dx, n[1] + dy)
            if m.inside(c) and c in m.blocked:
                return False
    return True


def moves_at(m, n, goal, radius):
    """The set of moves (dx, dy) generated at n."""
    free = nbhd_free(m, n, radius)
    if n == goal or not free:
        return set(ORDER)
    return {BEARING_MOVE[b] for b in kept(sector(bearing(n, goal)))}


def rule_eq1(inp):
    out = {}
    if "theta" in inp:
        theta = float(inp["theta"])
    else:
        theta = bearing(cell(inp["n"]), cell(inp["goal"]))
        out["theta"] = theta
    s = sector(theta)
    out["sector"] = s
    out["keep"] = [label(b) for b in kept(s)]
    out["abandon"] = [label(b) for b in abandoned(s)]
    if "grid" in inp:
        m = Map(inp["grid"])
        n = cell(inp["n"])
        radius = inp.get("radius", 1)
        out["reduced"] = nbhd_free(m, n, radius)
        mv = moves_at(m, n, cell(inp["goal"]), radius)
        out["moves"] = [label(b) for b in range(0, 360, 45) if BEARING_MOVE[b] in mv]
    return out


# ---- eq2-eq4 -------------------------------------------------------------------------------

def rule_eq2(inp):
    return {"h": h_euclidean(cell(inp["n"]), cell(inp["goal"]))}


def _nonneg(*xs):
    for x in xs:
        require(math.isfinite(x) and x >= 0.0, "finite and >= 0")


def rule_eq3(inp):
    g, h = float(inp["g"]), float(inp["h"])
    _nonneg(g, h)
    return {"f": g + h}


def weight(r, R, form):
    _nonneg(r, R)
    if form not in ("linear", "exp", "none"):
        raise UsageError("weight")
    if form == "none" or R == 0.0:
        return 1.0
    q = r / R
    return 1.0 + q if form == "linear" else math.exp(q)


def f_weighted(g, h, r, R, form):
    _nonneg(g, h)
    return g + weight(r, R, form) * h


def rule_eq4(inp):
    g, h, r, R = (float(inp[k]) for k in ("g", "h", "r", "R"))
    form = inp.get("weight", "linear")
    return {"f": f_weighted(g, h, r, R, form), "w": weight(r, R, form)}


# ---- eq5 -----------------------------------------------------------------------------------

def segment_blocked(m, a, b):
    require(m.inside(a) and m.inside(b), "segment end outside the grid")
    if a == b:
        return a in m.blocked
    ax, ay, bx, by = 2 * a[0] + 1, 2 * a[1] + 1, 2 * b[0] + 1, 2 * b[1] + 1
    dx, dy = bx - ax, by - ay
    for x in range(min(a[0], b[0]), max(a[0], b[0]) + 1):
        for y in range(min(a[1], b[1]), max(a[1], b[1]) + 1):
            if (x, y) not in m.blocked:
                continue
            x0, y0 = 2 * x, 2 * y
            if max(ax, bx) <= x0 or min(ax, bx) >= x0 + 2 or max(ay, by) <= y0 or min(ay, by) >= y0 + 2:
                continue
            sides = [dx * (cy - ay) - dy * (cx - ax) for cx in (x0, x0 + 2) for cy in (y0, y0 + 2)]
            if any(s > 0 for s in sides) and any(s < 0 for s in sides):
                return True
    return False


def safety(m, a, b, k, ds, cmp):
    require(m.inside(a) and m.inside(b), "outside")
    require(a != b, "distinct")
    require(1 <= k <= 1024, "k")
    require(math.isfinite(ds) and 0.0 <= ds <= 64.0, "ds")
    if cmp not in ("ge", "gt"):
        raise UsageError("safety")
    ix, iy = b[0] - a[0], b[1] - a[1]
    norm = math.sqrt(float(ix * ix + iy * iy))
    N = math.ceil(float(k) * norm)
    cells = sorted(m.blocked)
    for mm in range(N + 1):
        t = float(mm) / float(N)
        qx = float(a[0]) + t * float(ix)
        qy = float(a[1]) + t * float(iy)
        for (ox, oy) in cells:
            ex, ey = qx - float(ox), qy - float(oy)
            d = math.sqrt(ex * ex + ey * ey)
            if not (d >= ds if cmp == "ge" else d > ds):
                return False, N
    return True, N


def rule_eq5(inp):
    m = Map(inp["grid"])
    a, b = cell(inp["a"]), cell(inp["b"])
    safe, n = safety(m, a, b, inp.get("k", 4), float(inp.get("ds", 1.0)), inp.get("safety", "ge"))
    return {"safe": safe, "divisions": n, "blocked": segment_blocked(m, a, b)}


# ---- the planner ---------------------------------------------------------------------------

DEFAULTS = {"directions": 5, "radius": 1, "fallback": "full", "weight": "linear", "redundancy": "secondary",
            "secondary_input": "raw", "k": 4, "ds": 1.0, "safety": "ge", "degree": 3, "end": "repeated",
            "spacing": 0.1, "inflation": 0.0}


def search(m, start, goal, pol, directions, radius, form, R):
    require(m.inside(start) and m.inside(goal), "outside")
    require(m.free(start) and m.free(goal), "blocked")
    g = {start: 0.0}
    parent = {start: None}
    hval = {start: h_euclidean(start, goal)}
    f = {start: f_weighted(0.0, hval[start], hval[start], R, form)}
    opened, closed = {start}, set()
    expansions = generated = children = 0
    while opened:
        n = min(opened, key=lambda c: (f[c], hval[c], m.index(c)))
        opened.remove(n)
        closed.add(n)
        expansions += 1
        if n == goal:
            path = []
            c = n
            while c is not None:
                path.append(c)
                c = parent[c]
            path.reverse()
            return True, path, g[goal], expansions, generated, children
        mv = moves_at(m, n, goal, radius) if directions == 5 else set(ORDER)
        for d in ORDER:
            if d not in mv:
                continue
            q = (n[0] + d[0], n[1] + d[1])
            if not allowed(m, n, q, pol) or q in closed:
                continue
            generated += 1
            gq = g[n] + cost(n, q)
            if q not in g or gq < g[q]:
                if q not in g:
                    children += 1
                g[q], parent[q] = gq, n
                hval[q] = h_euclidean(q, goal)
                f[q] = f_weighted(gq, hval[q], hval[q], R, form)
                opened.add(q)
    return False, [], 0.0, expansions, generated, children


def greedy(path, ok):
    kept_nodes = [path[0]]
    a = 0
    last = len(path) - 1
    while a < last:
        b = last
        while b > a + 1 and not ok(path[a], path[b]):
            b -= 1
        kept_nodes.append(path[b])
        a = b
    return kept_nodes


def _clear(c, r):
    d, lo, up, verdict, _ = c
    num = lambda v: None if math.isinf(v) else v  # noqa: E731
    return {"distance": num(d), "lower": num(lo), "upper": num(up), "verdict": verdict, "inflation": r}


def plan(inp):
    m = Map(inp["grid"])
    start, goal, pol = cell(inp["start"]), cell(inp["goal"]), policy(inp)
    params = dict(DEFAULTS)
    for k, v in inp.get("params", {}).items():
        if k not in DEFAULTS:
            raise UsageError("unknown parameter " + k)
        params[k] = v
    p = params
    require(p["directions"] in (5, 8), "directions")
    require(1 <= p["radius"] <= 64, "radius")
    require(1 <= p["k"] <= 1024, "k")
    require(0.0 <= p["ds"] <= 64.0, "ds")
    require(1 <= p["degree"] <= 20, "degree")
    require(p["spacing"] > 0.0, "spacing")
    require(p["inflation"] >= 0.0, "inflation")
    require(m.inside(start) and m.inside(goal), "outside")
    R = h_euclidean(start, goal)
    found, path, length, exp, gen, ch = search(m, start, goal, pol, p["directions"], p["radius"], p["weight"], R)
    used = False
    if not found and p["directions"] == 5 and p["fallback"] == "full":
        found, path, length, e2, g2, c2 = search(m, start, goal, pol, 8, p["radius"], p["weight"], R)
        exp, gen, ch, used = exp + e2, gen + g2, ch + c2, True
    extra = {"fallback_used": used, "start_goal_distance": R, "expansions": exp, "generated": gen, "child_nodes": ch}
    out = {"found": found, "path": [list(c) for c in path], "length": length, "extra": extra}
    if not found:
        return out
    ordinary = greedy(path, lambda a, b: not segment_blocked(m, a, b))
    src = path if p["secondary_input"] == "raw" else ordinary
    secondary = greedy(src, lambda a, b: not segment_blocked(m, a, b)
                       and safety(m, a, b, p["k"], float(p["ds"]), p["safety"])[0])
    keys = {"secondary": secondary, "ordinary": ordinary, "none": path}[p["redundancy"]]
    t = lambda q: metrics_turns({"path": [list(c) for c in q]})["turns"]  # noqa: E731
    centres = [(c[0] + 0.5, c[1] + 0.5) for c in keys]
    r = float(p["inflation"])
    extra.update({
        "turns_raw": t(path), "ordinary_nodes": [list(c) for c in ordinary], "turns_ordinary": t(ordinary),
        "secondary_nodes": [list(c) for c in secondary], "turns_secondary": t(secondary),
        "key_nodes": [list(c) for c in keys], "turns_key": t(keys),
        "key_length": metrics_length({"path": [list(c) for c in keys]})["length"],
        "key_clearance": _clear(curves.clearance(m, centres, r, 0.0, True), r)})
    try:
        deg = curves.degree_for(len(centres), p["degree"], p["end"])
    except DomainError:
        return out
    deg, knots, ctrl = curves.make_curve(centres, deg, p["end"])
    params_u, pts, chord = curves.sample(deg, knots, ctrl, float(p["spacing"]))
    total = 0.0
    for i in range(1, len(pts)):
        dx, dy = pts[i][0] - pts[i - 1][0], pts[i][1] - pts[i - 1][1]
        total = total + math.sqrt(dx * dx + dy * dy)
    extra["curve"] = {"degree": deg, "end": p["end"], "spacing": p["spacing"], "chord": chord, "samples": len(pts),
                      "length": total,
                      "clearance": _clear(curves.clearance(m, [tuple(q) for q in pts], r, chord / 2.0, True), r),
                      "points": pts}
    return out


RULES = {
    "sensors2023.eq1": rule_eq1,
    "sensors2023.eq2": rule_eq2,
    "sensors2023.eq3": rule_eq3,
    "sensors2023.eq4": rule_eq4,
    "sensors2023.eq5": rule_eq5,
    "sensors2023.plan.astar-kinematic": plan,
}
