"""spec/grid.md, written from the spec alone (Python 3 standard library only).

The map is kept as a list of rows indexed bottom-up (rows_by_y[y][x]), decoded from the
top-row-first text by reversing it; corner policies are a table of predicates over the two
orthogonal cells; neighbours are found by filtering all cells of the 3x3 block and sorting by
index, rather than by a fixed loop order.
"""
import math

from .common import DomainError, require

MAX_CELLS = 1 << 28
SQRT2 = math.sqrt(2.0)  # IEEE sqrt is correctly rounded: the binary64 nearest sqrt(2)
POLICIES = {
    "never": lambda f1, f2: False,
    "strict": lambda f1, f2: f1 and f2,
    "one": lambda f1, f2: f1 or f2,
    "always": lambda f1, f2: True,
}


class UsageError(Exception):
    """Malformed request (C++ UsageError); no golden vector expects one."""


def is_int(v):
    return isinstance(v, int) and not isinstance(v, bool)


def check_dims(w, h):
    require(is_int(w) and is_int(h) and w >= 1 and h >= 1, "W and H must be at least 1")
    require(w * h <= MAX_CELLS, "more than 2^28 cells")


class GridMap:
    """A W x H map decoded from rows, first row = top row (r[grid.encoding])."""

    def __init__(self, rows):
        if not isinstance(rows, list) or any(not isinstance(r, str) for r in rows):
            raise UsageError("a grid is an array of strings")
        require(len(rows) > 0, "no rows")
        widths = {len(r) for r in rows}
        require(len(widths) == 1, "rows of unequal length")
        self.w, self.h = widths.pop(), len(rows)
        check_dims(self.w, self.h)
        require(set("".join(rows)) <= {".", "#"}, "only '.' and '#' allowed")
        self.rows_by_y = [rows[self.h - 1 - y] for y in range(self.h)]

    def inside(self, x, y):
        return 0 <= x < self.w and 0 <= y < self.h

    def is_blocked(self, x, y):
        return self.rows_by_y[y][x] == "#"

    def is_free(self, x, y):
        return self.inside(x, y) and not self.is_blocked(x, y)

    def index_of(self, x, y):
        return x + self.w * y


def cell_arg(v):
    if not (isinstance(v, list) and len(v) == 2 and all(is_int(e) for e in v)):
        raise UsageError(f"a cell is [x, y], got {v!r}")
    return v[0], v[1]


def step_allowed(m, a, b, policy):
    """r[grid.corner-policy]."""
    (ax, ay), (bx, by) = a, b
    dx, dy = bx - ax, by - ay
    if max(abs(dx), abs(dy)) != 1:
        return False
    if not (m.is_free(ax, ay) and m.is_free(bx, by)):
        return False
    if dx == 0 or dy == 0:
        return True
    return POLICIES[policy](m.is_free(bx, ay), m.is_free(ax, by))


def step_cost(a, b):
    """r[grid.moves]."""
    dx, dy = abs(b[0] - a[0]), abs(b[1] - a[1])
    require(max(dx, dy) == 1, "not two distinct 8-neighbours")
    return SQRT2 if dx == 1 and dy == 1 else 1.0


def policy_arg(inp):
    p = inp.get("policy", "strict")
    if p not in POLICIES:
        raise UsageError(f"unknown policy {p!r}")
    return p


# ---- rules ----------------------------------------------------------------------------------


def encoding(inp):
    m = GridMap(inp["grid"])
    blocked = sorted(m.index_of(x, y) for y in range(m.h) for x in range(m.w) if m.is_blocked(x, y))
    return {"width": m.w, "height": m.h, "blocked": blocked}


def index(inp):
    w, h = inp["width"], inp["height"]
    check_dims(w, h)
    if ("cell" in inp) == ("index" in inp):
        raise UsageError("exactly one of cell and index")
    if "cell" in inp:
        x, y = cell_arg(inp["cell"])
        require(0 <= x < w and 0 <= y < h, "cell outside the grid")
        return {"index": x + w * y}
    i = inp["index"]
    require(is_int(i) and 0 <= i < w * h, "index outside [0, W*H)")
    y, x = divmod(i, w)
    return {"cell": [x, y]}


def coord(inp):
    w, h, i = inp["width"], inp["height"], inp["index"]
    check_dims(w, h)
    require(is_int(i) and 0 <= i < w * h, "index outside [0, W*H)")
    form = inp.get("form", "corrected")
    if form == "corrected":
        return {"centre": [i % w + 0.5, i // w + 0.5]}
    if form == "printed0":
        seq = i
    elif form == "printed1":
        seq = i + 1
    else:
        raise UsageError(f"unknown form {form!r}")
    # Eq. (1) as printed: x = mod(i, N) + 0.5, y = ceil(i/N) - 0.5, exact integer ceil
    return {"centre": [seq % w + 0.5, -((-seq) // w) - 0.5]}


def moves(inp):
    return {"cost": step_cost(cell_arg(inp["from"]), cell_arg(inp["to"]))}


def corner_policy(inp):
    m = GridMap(inp["grid"])
    return {"allowed": step_allowed(m, cell_arg(inp["from"]), cell_arg(inp["to"]), policy_arg(inp))}


def neighbour_order(inp):
    m = GridMap(inp["grid"])
    c = cell_arg(inp["cell"])
    require(m.is_free(*c), "cell blocked or outside the grid")
    policy = policy_arg(inp)
    block = [(c[0] + dx, c[1] + dy) for dx in (1, 0, -1) for dy in (1, 0, -1)]  # any order
    allowed = [b for b in block if m.inside(*b) and step_allowed(m, c, b, policy)]
    allowed.sort(key=lambda b: m.index_of(*b))
    return {"neighbours": [list(b) for b in allowed], "costs": [step_cost(c, b) for b in allowed]}


RULES = {
    "grid.encoding": encoding,
    "grid.index": index,
    "grid.coord": coord,
    "grid.moves": moves,
    "grid.corner-policy": corner_policy,
    "grid.neighbour-order": neighbour_order,
}
