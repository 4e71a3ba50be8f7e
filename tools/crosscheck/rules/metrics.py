"""spec/metrics.md, written from the spec alone (Python 3 standard library only).

Vectors are Python integers (exact); lengths are sqrt of the exact integer dx^2 + dy^2
(correctly rounded, as the spec's coordinate bound guarantees); OMPL's smoothness is evaluated
in the order the spec prescribes.
"""
import math

from .common import DomainError, require
from .grid import GridMap, UsageError, cell_arg, step_allowed

BOUND = 1 << 25


def path_arg(inp):
    v = inp["path"]
    if not isinstance(v, list):
        raise UsageError("a path is an array of cells")
    return [cell_arg(c) for c in v]


def check_shape(p):
    require(len(p) >= 1, "empty path")
    require(all(p[k] != p[k + 1] for k in range(len(p) - 1)), "consecutive repeat")


def check_path(p):
    check_shape(p)
    require(all(abs(x) <= BOUND and abs(y) <= BOUND for x, y in p), "coordinate beyond 2^25")


def seg(p, q):
    return (q[0] - p[0], q[1] - p[1])


def norm(v):
    return math.sqrt(v[0] * v[0] + v[1] * v[1])  # exact integer, <= 2^53


def interior(p):
    """(u, v, previous, node, next) for each interior node."""
    return [(seg(p[k - 1], p[k]), seg(p[k], p[k + 1]), p[k - 1], p[k], p[k + 1]) for k in range(1, len(p) - 1)]


def angle(u, v):
    cross = u[0] * v[1] - u[1] * v[0]
    dot = u[0] * v[0] + u[1] * v[1]
    return math.atan2(float(abs(cross)), float(dot))


def length(inp):
    p = path_arg(inp)
    check_path(p)
    total = 0.0
    for k in range(1, len(p)):
        total += norm(seg(p[k - 1], p[k]))
    return {"length": total}


def turn_angle(inp):
    p = path_arg(inp)
    check_path(p)
    return {"angles": [angle(u, v) for u, v, *_ in interior(p)]}


def turns(inp):
    p = path_arg(inp)
    check_path(p)
    n = 0
    for u, v, *_ in interior(p):
        same_direction = u[0] * v[1] == u[1] * v[0] and u[0] * v[0] + u[1] * v[1] > 0
        n += 0 if same_direction else 1
    return {"turns": n}


def smoothness(inp):
    p = path_arg(inp)
    check_path(p)
    form = inp.get("form", "ompl")
    if form not in ("ompl", "angle"):
        raise UsageError(f"unknown form {form!r}")
    s = 0.0
    for u, v, prev, _node, nxt in interior(p):
        a, b = norm(u), norm(v)
        if form == "ompl":
            c = norm(seg(prev, nxt))
            q = ((a * a + b * b) - c * c) / ((2.0 * a) * b)
            if not -1.0 < q < 1.0:
                continue
            phi = math.pi - math.acos(q)
        else:
            phi = angle(u, v)
        k = (2.0 * phi) / (a + b)
        s += k * k
    return {"smoothness": s}


def safety(inp):
    m = GridMap(inp["grid"])
    p = path_arg(inp)
    check_shape(p)
    require(all(m.inside(x, y) for x, y in p), "node outside the grid")
    outside = inp.get("outside", "free")
    if outside not in ("free", "blocked"):
        raise UsageError(f"unknown outside reading {outside!r}")
    counts = []
    for x, y in p:
        ring = [(x + dx, y + dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1) if dx or dy]
        counts.append(sum(1 for q in ring if (m.is_blocked(*q) if m.inside(*q) else outside == "blocked")))
    return {"counts": counts}


def _value(v):
    if isinstance(v, str):
        table = {"inf": math.inf, "-inf": -math.inf, "nan": math.nan}
        if v not in table:
            raise UsageError(f"not a number: {v!r}")
        return table[v]
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise UsageError(f"not a number: {v!r}")
    return float(v)


def converge(inp):
    vals = [_value(v) for v in inp["values"]]
    sense = inp.get("sense", "min")
    if sense not in ("min", "max"):
        raise UsageError(f"unknown sense {sense!r}")
    require(len(vals) >= 1, "no iterations")
    require(not any(math.isnan(v) for v in vals), "NaN")
    forbidden = -math.inf if sense == "min" else math.inf
    require(forbidden not in vals, "forbidden infinity")
    # best-so-far series, then the first iteration (1-based) equal to the final best
    best_so_far, b = [], None
    for v in vals:
        b = v if b is None else (min(b, v) if sense == "min" else max(b, v))
        best_so_far.append(b)
    final = best_so_far[-1]
    require(math.isfinite(final), "no finite value")
    return {"iteration": best_so_far.index(final) + 1}


def valid_path(inp):
    m = GridMap(inp["grid"])
    p = path_arg(inp)
    start, goal = cell_arg(inp["start"]), cell_arg(inp["goal"])
    policy = inp.get("policy", "strict")

    def fail(reason, i):
        return {"valid": False, "reason": reason, "index": i}

    if not p:
        return fail("empty", -1)
    if p[0] != start:
        return fail("start_mismatch", 0)
    for k, c in enumerate(p):
        if not m.inside(*c):
            return fail("out_of_bounds", k)
        if m.is_blocked(*c):
            return fail("blocked", k)
        if k:
            d = seg(p[k - 1], c)
            if d == (0, 0):
                return fail("repeated", k)
            if max(abs(d[0]), abs(d[1])) > 1:
                return fail("not_adjacent", k)
            if not step_allowed(m, p[k - 1], c, policy):
                return fail("corner_cut", k)
    if p[-1] != goal:
        return fail("goal_mismatch", len(p) - 1)
    return {"valid": True, "reason": "ok", "index": -1}


RULES = {
    "metrics.length": length,
    "metrics.turn-angle": turn_angle,
    "metrics.turns": turns,
    "metrics.smoothness": smoothness,
    "metrics.safety": safety,
    "metrics.converge": converge,
    "metrics.valid-path": valid_path,
}
