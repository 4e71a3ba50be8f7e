"""spec/search.md (and the parts of spec/grid.md it uses), written from the spec alone.

The search here is deliberately the plainest reading of the normative pseudocode: OPEN is a
dict of cells, and each selection scans it for the smallest key (f, h, index) with Python's
tuple comparison (exact on floats). The C++ library uses a binary heap with lazy deletion; the
spec says both must select the same cell at every step, so whole-run vectors (paths and
expansion counts) are checked bit for bit.
"""
import math

from .common import DomainError, require

SQRT2 = math.sqrt(2.0)  # correctly rounded: the double nearest sqrt(2) (grid.moves)
LIMIT = 1 << 30
POLICIES = ("never", "strict", "one", "always")
HEURISTICS = ("zero", "manhattan", "chebyshev", "octile", "euclidean")


class UsageError(Exception):
    """A malformed request (the C++ UsageError); never expected by a golden vector."""


# ---- grid.* pieces --------------------------------------------------------------------------


class Map:
    def __init__(self, rows):
        if not isinstance(rows, list) or not all(isinstance(r, str) for r in rows):
            raise UsageError("grid must be an array of strings")
        require(len(rows) >= 1, "a grid needs at least one row")
        self.w, self.h = len(rows[0]), len(rows)
        require(self.w >= 1, "rows must not be empty")
        require(all(len(r) == self.w for r in rows), "all rows must have the same length")
        require(all(ch in ".#" for r in rows for ch in r), "only '.' and '#'")
        # rows[0] is the top row: y = H - 1 - r
        self.blocked = set()
        for r, row in enumerate(rows):
            for x, ch in enumerate(row):
                if ch == "#":
                    self.blocked.add((x, self.h - 1 - r))

    def inside(self, c):
        return 0 <= c[0] < self.w and 0 <= c[1] < self.h

    def free(self, c):
        return self.inside(c) and c not in self.blocked

    def index(self, c):
        return c[1] * self.w + c[0]


def cell(v):
    if not (isinstance(v, list) and len(v) == 2 and all(isinstance(t, int) and not isinstance(t, bool) for t in v)):
        raise UsageError("a cell is [x, y] with two integers")
    return (v[0], v[1])


def policy(inp):
    p = inp.get("policy", "strict")
    if p not in POLICIES:
        raise UsageError(f"unknown policy {p!r}")
    return p


def allowed(m, a, b, pol):
    """grid.corner-policy: the single step a -> b."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    if (dx, dy) == (0, 0) or abs(dx) > 1 or abs(dy) > 1:
        return False
    if not (m.free(a) and m.free(b)):
        return False
    if dx == 0 or dy == 0:
        return True
    s1, s2 = m.free((a[0] + dx, a[1])), m.free((a[0], a[1] + dy))
    return {"never": False, "strict": s1 and s2, "one": s1 or s2, "always": True}[pol]


def cost(a, b):
    return SQRT2 if a[0] != b[0] and a[1] != b[1] else 1.0


# ---- heuristics (search.h.*) ----------------------------------------------------------------


def _deltas(n, g):
    for v in (*n, *g):
        require(-LIMIT < v < LIMIT, "heuristic: |x|, |y| must be < 2^30")
    return abs(n[0] - g[0]), abs(n[1] - g[1])


def h_manhattan(n, g):
    dx, dy = _deltas(n, g)
    return float(dx + dy)


def h_chebyshev(n, g):
    dx, dy = _deltas(n, g)
    return float(max(dx, dy))


def h_octile(n, g):
    dx, dy = _deltas(n, g)
    big, small = max(dx, dy), min(dx, dy)
    return float(big - small) + SQRT2 * float(small)


def h_euclidean(n, g):
    dx, dy = _deltas(n, g)
    return math.sqrt(float(dx * dx + dy * dy))


def h_zero(n, g):
    _deltas(n, g)
    return 0.0


HFUN = {"zero": h_zero, "manhattan": h_manhattan, "chebyshev": h_chebyshev,
        "octile": h_octile, "euclidean": h_euclidean}


def heuristic_rule(fn):
    return lambda inp: {"h": fn(cell(inp["n"]), cell(inp["goal"]))}


def admissible(inp):
    h, p = inp["heuristic"], inp["policy"]
    if h not in HEURISTICS or p not in POLICIES:
        raise UsageError("unknown heuristic or policy")
    # Table of spec/search.md: everything is admissible and consistent except manhattan with
    # diagonal steps (one free diagonal step: exact cost sqrt2 < h = 2).
    ok = not (h == "manhattan" and p != "never")
    return {"admissible": ok, "consistent": ok}


def order(inp):
    a, b = inp["a"], inp["b"]
    return {"precedes": (a["f"], a["h"], a["index"]) < (b["f"], b["h"], b["index"])}


# ---- the search (search.astar, search.dijkstra) ---------------------------------------------


def best_first(m, start, goal, pol, hname):
    require(m.inside(start), "start outside the grid")
    require(m.inside(goal), "goal outside the grid")
    require(m.free(start), "start blocked")
    require(m.free(goal), "goal blocked")
    hf = HFUN[hname]
    g = {start: 0.0}
    parent = {start: None}
    hval = {start: hf(start, goal)}
    f = {start: 0.0 + hval[start]}
    opened, closed = {start}, set()
    expansions = 0
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
            return True, path, g[goal], expansions
        for ddy in (-1, 0, 1):
            for ddx in (-1, 0, 1):
                q = (n[0] + ddx, n[1] + ddy)
                if not allowed(m, n, q, pol) or q in closed:
                    continue
                gq = g[n] + cost(n, q)
                if q not in opened or gq < g[q]:
                    g[q], parent[q] = gq, n
                    hval[q] = hf(q, goal)
                    f[q] = gq + hval[q]
                    opened.add(q)
    return False, [], 0.0, expansions


def _run(inp, hname):
    if hname not in HEURISTICS:
        raise UsageError(f"unknown heuristic {hname!r}")
    m = Map(inp["grid"])
    found, path, length, exp = best_first(m, cell(inp["start"]), cell(inp["goal"]), policy(inp), hname)
    diag = sum(1 for a, b in zip(path, path[1:]) if a[0] != b[0] and a[1] != b[1])
    return {"found": found, "path": [[x, y] for x, y in path], "length": length,
            "expansions": exp, "steps": [len(path) - 1 - diag if path else 0, diag]}


def astar(inp):
    return _run(inp, inp.get("heuristic", "octile"))


def dijkstra(inp):
    return _run(inp, "zero")


RULES = {
    "search.h.manhattan": heuristic_rule(h_manhattan),
    "search.h.chebyshev": heuristic_rule(h_chebyshev),
    "search.h.octile": heuristic_rule(h_octile),
    "search.h.euclidean": heuristic_rule(h_euclidean),
    "search.admissible": admissible,
    "search.order": order,
    "search.astar": astar,
    "search.dijkstra": dijkstra,
}

__all__ = ["RULES", "DomainError"]
