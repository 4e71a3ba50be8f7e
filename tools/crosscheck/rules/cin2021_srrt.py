"""spec/cin2021-srrt.md, written from the spec alone (Python 3 standard library only).

Independent of the C++ (CGAL Epeck, a k-d tree, bucket grids): here every collision decision is
made with fractions.Fraction by the definition (distance between the closed segment and each
closed polygon, 0 when they meet, compared with r^2), the nearest node is a linear scan, and
Algorithm 1 is replayed draw for draw from this package's own MT19937.
Scene numbers arrive as Python floats (json.load) and mean the decimal of their shortest
round-trip text (repr); query points, start and goal are binary64 values and are taken exactly.
"""
import math
from fractions import Fraction

from .common import DomainError, require
from .inflation import in_polygon_closed, point_seg_d2, read_scene, segments_meet, validate
from .rng import MT19937
from . import curves


class World:
    def __init__(self, inp):
        ox, oy, w, h, s, r, polys = read_scene(inp)
        validate(polys)
        self.r2 = r * r
        self.r = r
        self.polys = polys
        # the world rectangle, each bound rounded to the nearest double (spec: collision)
        self.lo = (float(ox), float(oy))
        self.hi = (float(ox + w * s), float(oy + h * s))

    def d2(self, k, a, b):
        """Exact squared distance between segment [a, b] (Fractions) and polygon k."""
        vs = self.polys[k]
        if in_polygon_closed(a, vs):
            return Fraction(0)
        n = len(vs)
        best = None
        for i in range(n):
            c, d = vs[i], vs[(i + 1) % n]
            if a == b:
                v = point_seg_d2(a, c, d)
            elif segments_meet(a, b, c, d):
                return Fraction(0)
            else:
                v = min(point_seg_d2(a, c, d), point_seg_d2(b, c, d),
                        point_seg_d2(c, a, b), point_seg_d2(d, a, b))
            best = v if best is None else min(best, v)
        return best

    def sign(self, k, a, b):
        v = self.d2(k, exact(a), exact(b)) - self.r2
        return (v > 0) - (v < 0)

    def in_rect(self, p):
        return self.lo[0] <= p[0] <= self.hi[0] and self.lo[1] <= p[1] <= self.hi[1]

    def free(self, a, b):
        if not (self.in_rect(a) and self.in_rect(b)):
            return False
        return all(self.sign(k, a, b) > 0 for k in range(len(self.polys)))

    def clearance(self, a, b):
        if not self.polys:
            return math.inf
        d2 = min(self.d2(k, exact(a), exact(b)) for k in range(len(self.polys)))
        return math.sqrt(float(d2))


def exact(p):
    return (Fraction(p[0]), Fraction(p[1]))


def pt(v):
    require(isinstance(v, list) and len(v) == 2, "a point is [x, y]")
    x, y = float(v[0]), float(v[1])
    require(math.isfinite(x) and math.isfinite(y), "coordinates must be finite")
    return (x, y)


def sqd(a, b):
    dx = b[0] - a[0]
    dy = b[1] - a[1]
    return dx * dx + dy * dy


def nearest_index(points, q):
    require(len(points) > 0, "empty tree")
    best, bd = 0, sqd(points[0], q)
    for k in range(1, len(points)):
        d = sqd(points[k], q)
        if d < bd:
            best, bd = k, d
    return best


def steer_point(n, t, delta, clip=True):
    require(math.isfinite(delta) and delta > 0, "delta must be > 0")
    dx = t[0] - n[0]
    dy = t[1] - n[1]
    d = math.sqrt(dx * dx + dy * dy)
    if d == 0.0:
        return n
    if clip and d <= delta:
        return t
    s = delta / d
    return (n[0] + s * dx, n[1] + s * dy)


def collision(inp):
    w = World(inp)
    a, b = pt(inp["a"]), pt(inp["b"])
    return {"free": w.free(a, b), "signs": [w.sign(k, a, b) for k in range(len(w.polys))]}


def nearest(inp):
    pts = [pt(p) for p in inp["points"]]
    return {"index": nearest_index(pts, pt(inp["q"]))}


def steer(inp):
    mode = inp.get("steer", "clip")
    require(mode in ("clip", "fixed"), "steer: clip or fixed")
    x = steer_point(pt(inp["near"]), pt(inp["target"]), float(inp["delta"]), mode == "clip")
    return {"new": [x[0], x[1]]}


def rrt(w, start, goal, p, g):
    """Algorithm 1 as spec/cin2021-srrt.md lists it; returns (found, nodes, parent, iters, rejected, draws)."""
    delta = p["delta"]
    require(math.isfinite(delta) and delta > 0, "delta")
    require(0.0 <= p["goal_probability"] <= 1.0, "P_g")
    require(p["max_iterations"] >= 0 and p["max_rejections"] >= 1, "limits")
    require(w.free(start, start) and w.free(goal, goal), "start and goal must be free")
    require(start != goal, "start != goal")
    draws = [0]

    def u():
        draws[0] += 1
        return g.genrand_res53()

    lo, hi = w.lo, w.hi
    wx, wy = hi[0] - lo[0], hi[1] - lo[1]
    nodes, parent = [start], [-1]

    def reaches(k):
        v = nodes[k]
        if v == goal:
            return True
        if sqd(v, goal) <= delta * delta and w.free(v, goal):
            nodes.append(goal)
            parent.append(k)
            return True
        return False

    def sample():
        tries = 0
        while True:
            x = (lo[0] + u() * wx, lo[1] + u() * wy)
            if p["sample"] == "rect" or w.free(x, x):
                return x
            tries += 1
            if tries >= p["max_rejections"]:
                raise DomainError("sample=free: too many rejections")

    def goal_chosen(pv):
        return pv < p["goal_probability"] if p["bias"] == "lt" else pv > p["goal_probability"]

    found = reaches(0)
    it = rejected = 0
    while not found and it < p["max_iterations"]:
        it += 1
        if p["variant"] == "paper":
            x_rand = sample()
            if p["near"] == "sample":
                near = nearest_index(nodes, x_rand)
            target = goal if goal_chosen(u()) else x_rand
            if p["near"] == "target":
                near = nearest_index(nodes, target)
        elif p["variant"] == "plain":
            target = sample()
            near = nearest_index(nodes, target)
        else:  # ompl
            target = goal if goal_chosen(u()) else sample()
            near = nearest_index(nodes, target)
        x_near = nodes[near]
        x_new = steer_point(x_near, target, delta, p["steer"] == "clip")
        if x_new == x_near:
            continue
        if not w.free(x_near, x_new):
            rejected += 1
            continue
        nodes.append(x_new)
        parent.append(near)
        found = reaches(len(nodes) - 1)
    return found, nodes, parent, it, rejected, draws[0]


def branch(parent, leaf):
    out = [leaf]
    while out[-1] != 0:
        out.append(parent[out[-1]])
    return out[::-1]


def params(inp):
    p = {"delta": 1.7, "goal_probability": 0.6, "max_iterations": 20000, "max_rejections": 1000,
         "bias": "lt", "near": "sample", "variant": "paper", "sample": "rect", "steer": "clip"}
    for k in p:
        if k in inp:
            p[k] = inp[k]
    p["delta"] = float(p["delta"])
    p["goal_probability"] = float(p["goal_probability"])
    for k, allowed in (("bias", ("lt", "gt")), ("near", ("sample", "target")),
                       ("variant", ("paper", "plain", "ompl")), ("sample", ("rect", "free")),
                       ("steer", ("clip", "fixed"))):
        require(p[k] in allowed, f"{k} must be one of {allowed}")
    return p


def alg1(inp):
    w = World(inp)
    g = MT19937(inp["seed"])
    found, nodes, parent, it, rejected, draws = rrt(w, pt(inp["start"]), pt(inp["goal"]), params(inp), g)
    path = [list(nodes[k]) for k in branch(parent, len(nodes) - 1)] if found else []
    return {"found": found, "path": path, "tree_size": len(nodes), "iterations": it,
            "rejected_edges": rejected, "draws": draws}


def length(points):
    total = 0.0
    for i in range(1, len(points)):
        total += math.sqrt(sqd(points[i - 1], points[i]))
    return total


def alg2(inp):
    w = World(inp)
    path = [pt(p) for p in inp["path"]]
    require(len(path) > 0, "empty path")
    m = len(path) - 1
    out, s = [0], 0
    while s != m:
        c = m
        while not w.free(path[s], path[c]):
            c -= 1
            require(c != s, "the input path is not free")
        out.append(c)
        s = c
    return {"kept": out, "length_before": length(path), "length_after": length([path[k] for k in out])}


def metrics(inp):
    w = World(inp)
    path = [pt(p) for p in inp["path"]]
    require(len(path) > 0, "empty path")
    if len(path) == 1:
        c = w.clearance(path[0], path[0])
    else:
        c = min(w.clearance(path[i - 1], path[i]) for i in range(1, len(path)))
    turning = 0.0
    for i in range(1, len(path) - 1):
        ux, uy = path[i][0] - path[i - 1][0], path[i][1] - path[i - 1][1]
        vx, vy = path[i + 1][0] - path[i][0], path[i + 1][1] - path[i][1]
        if (ux == 0.0 and uy == 0.0) or (vx == 0.0 and vy == 0.0):
            continue
        turning += math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy)
    return {"length": length(path), "nodes": len(path), "clearance": "inf" if math.isinf(c) else c,
            "turning": turning}


# ---- curves.polygon-clearance and cin2021.srrt.curve (spec/curves.md, spec/cin2021-srrt.md) ----

def _border_rect(p, lo, hi):
    return max(0.0, min(p[0] - lo[0], hi[0] - p[0], p[1] - lo[1], hi[1] - p[1]))


def polygon_clearance(w, pts, inflation, tolerance, border):
    """The exact distance of every segment to every polygon (Fractions), then the bounds and the
    verdict as spec/curves.md r[curves.clearance] states them."""
    require(len(pts) >= 1, "no points")
    require(all(math.isfinite(q[0]) and math.isfinite(q[1]) for q in pts), "finite")
    require(math.isfinite(inflation) and inflation >= 0.0, "inflation")
    require(math.isfinite(tolerance) and tolerance >= 0.0, "tolerance")

    def seg(a, b):
        d = math.inf
        if border:
            d = min(_border_rect(a, w.lo, w.hi), _border_rect(b, w.lo, w.hi))
        return min(d, w.clearance(a, b))

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


def _num(x):
    return ("inf" if x > 0 else "-inf") if isinstance(x, float) and math.isinf(x) else x


def rule_polygon_clearance(inp):
    w = World(inp)
    pts = [pt(p) for p in inp["points"]]
    border = inp.get("border", True)
    require(isinstance(border, bool), "border must be a bool")
    d, lo, up, verdict, s = polygon_clearance(w, pts, float(inp.get("inflation", 0.0)),
                                              float(inp.get("tolerance", 0.0)), border)
    return {"distance": _num(d), "lower": _num(lo), "upper": _num(up), "verdict": verdict, "segment": s}


def _curve_once(w, raw, kept, degree, knots_mode, spacing):
    p, knots, ctrl = curves.clamped_curve([raw[k] for k in kept], degree, knots_mode)
    params, points, chord = curves.sample(p, knots, ctrl, spacing)
    pts = [tuple(q) for q in points]
    d, lo, up, verdict, s = polygon_clearance(w, pts, float(w.r), chord / 2.0, False)
    kappa = 0.0
    for u in params:
        kappa = max(kappa, abs(curves.curvature(p, knots, ctrl, u)))
    return {"p": p, "knots": knots, "ctrl": ctrl, "params": params, "points": pts, "chord": chord,
            "lower": lo, "upper": up, "verdict": verdict, "segment": s, "kept": list(kept),
            "length": length(pts), "kappa": kappa}


def rule_curve(inp):
    w = World(inp)
    raw = [pt(p) for p in inp["raw"]]
    kept = inp["kept"]
    require(len(raw) >= 2, "raw path needs >= 2 points")
    require(len(kept) >= 2 and kept[0] == 0 and kept[-1] == len(raw) - 1, "kept ends")
    require(all(kept[i - 1] < kept[i] for i in range(1, len(kept))), "kept increasing")
    degree = inp.get("degree", 3)
    require(isinstance(degree, int) and 1 <= degree <= curves.MAX_DEGREE, "degree")
    knots_mode = inp.get("knots", "uniform")
    spacing = float(inp.get("spacing", 0.05))
    require(math.isfinite(spacing) and spacing > 0.0, "spacing")
    repair = inp.get("repair", False)
    c = _curve_once(w, raw, kept, degree, knots_mode, spacing)
    status, inserted = "off", []
    if repair:
        status = "clear"
        while c["verdict"] != "clear":
            u = c["params"][c["segment"]]
            at = c["points"][c["segment"]]
            k = curves.span_index(c["knots"], c["p"], len(c["ctrl"]), u)
            lo, hi = c["kept"][k - c["p"]], c["kept"][k]
            best = None
            for i in range(lo + 1, hi):
                if i in c["kept"]:
                    continue
                d = sqd(raw[i], at)
                if best is None or d < best[0]:
                    best = (d, i)
            if best is None:
                status = "stuck"
                break
            inserted.append(best[1])
            c = _curve_once(w, raw, sorted(c["kept"] + [best[1]]), degree, knots_mode, spacing)
    return {"degree": c["p"], "kept": c["kept"], "inserted": inserted, "samples": len(c["points"]),
            "chord": c["chord"], "length": c["length"], "max_curvature": _num(c["kappa"]),
            "lower": _num(c["lower"]), "upper": _num(c["upper"]), "verdict": c["verdict"], "repair": status}


RULES = {
    "cin2021.srrt.collision": collision,
    "cin2021.srrt.nearest": nearest,
    "cin2021.srrt.steer": steer,
    "cin2021.alg1": alg1,
    "cin2021.alg2": alg2,
    "cin2021.srrt.metrics": metrics,
    "curves.polygon-clearance": rule_polygon_clearance,
    "cin2021.srrt.curve": rule_curve,
}
