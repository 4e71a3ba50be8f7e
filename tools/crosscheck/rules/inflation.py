"""spec/inflation.md, written from the spec alone (Python 3 standard library only).

Independent of the C++ (CGAL, cell units, per-edge passes): here everything is in WORLD units with
fractions.Fraction, every cell is tested against every polygon by the definition, and the distance
between the closed square and the closed polygon is computed as a Fraction:
0 if a square corner is in the polygon (ray casting with an exact on-boundary test), a polygon
vertex is in the square, or an edge crosses a side; else the minimum of the point-segment squared
distances over the endpoints of every edge/side pair. It is compared with r^2 exactly.
Numbers arrive as Python floats (json.load): each is read as the decimal of its shortest
round-trip text, repr(x) (spec/formats.md, numbers in rule inputs).
"""
from fractions import Fraction

from .common import DomainError, require
from .grid import GridMap


def num(v):
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise TypeError("expected a number")
    return Fraction(v) if isinstance(v, int) else Fraction(repr(v))


def orient(a, b, c):
    v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (v > 0) - (v < 0)


def on_segment(p, a, b):
    return orient(a, b, p) == 0 and min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and \
        min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def segments_meet(a, b, c, d):
    o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
    if o1 != o2 and o3 != o4 and o1 * o2 <= 0 and o3 * o4 <= 0:
        return True
    return on_segment(c, a, b) or on_segment(d, a, b) or on_segment(a, c, d) or on_segment(b, c, d)


def point_seg_d2(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = dx * dx + dy * dy
    t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L
    t = min(max(t, Fraction(0)), Fraction(1))
    qx, qy = a[0] + t * dx - p[0], a[1] + t * dy - p[1]
    return qx * qx + qy * qy


def in_polygon_closed(p, vs):
    n = len(vs)
    for i in range(n):
        if on_segment(p, vs[i], vs[(i + 1) % n]):
            return True
    inside = False
    for i in range(n):
        a, b = vs[i], vs[(i + 1) % n]
        if (a[1] > p[1]) != (b[1] > p[1]):
            x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if x > p[0]:
                inside = not inside
    return inside


def validate(polys):
    for k, vs in enumerate(polys):
        n = len(vs)
        where = f"/polygons/{k}"
        require(n >= 3, f"{where}: degenerate polygon: fewer than 3 vertices")
        for i in range(n):
            require(vs[i] != vs[(i + 1) % n], f"{where}: degenerate polygon: equal consecutive vertices")
        require(any(orient(vs[0], vs[1], vs[i]) != 0 for i in range(2, n)),
                f"{where}: degenerate polygon: all vertices collinear")
        for i in range(n):
            a, b, c = vs[i], vs[(i + 1) % n], vs[(i + 2) % n]
            # consecutive edges overlap iff collinear and the boundary turns back at b
            back = (b[0] - a[0]) * (c[0] - b[0]) + (b[1] - a[1]) * (c[1] - b[1]) < 0
            require(not (orient(a, b, c) == 0 and back), f"{where}: self-intersecting polygon: spike")
        for i in range(n):
            for j in range(i + 1, n):
                if j == i + 1 or (i == 0 and j == n - 1):
                    continue
                require(not segments_meet(vs[i], vs[(i + 1) % n], vs[j], vs[(j + 1) % n]),
                        f"{where}: self-intersecting polygon: edges {i} and {j} meet")


def square_poly_d2(sq, vs):
    x0, y0, x1, y1 = sq
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    if any(in_polygon_closed(c, vs) for c in corners):
        return Fraction(0)
    if any(x0 <= v[0] <= x1 and y0 <= v[1] <= y1 for v in vs):
        return Fraction(0)
    n = len(vs)
    best = None
    for i in range(n):
        a, b = vs[i], vs[(i + 1) % n]
        for j in range(4):
            c, d = corners[j], corners[(j + 1) % 4]
            if segments_meet(a, b, c, d):
                return Fraction(0)
            d2 = min(point_seg_d2(a, c, d), point_seg_d2(b, c, d),
                     point_seg_d2(c, a, b), point_seg_d2(d, a, b))
            best = d2 if best is None else min(best, d2)
    return best


def read_scene(inp):
    ox, oy = (num(v) for v in inp["origin"])
    w, h = inp["width"], inp["height"]
    s = num(inp["cell_size"])
    rad, mar = num(inp["radius"]), num(inp["margin"])
    require(s > 0 and rad >= 0 and mar >= 0, "cell_size > 0, radius >= 0, margin >= 0")
    polys = [[(num(p[0]), num(p[1])) for p in poly["vertices"]] for poly in inp["polygons"]]
    return ox, oy, w, h, s, rad + mar, polys


def blocked_rows(inp):
    ox, oy, w, h, s, r, polys = read_scene(inp)
    validate(polys)
    r2 = r * r
    rows = []
    for y in range(h - 1, -1, -1):
        row = ""
        for x in range(w):
            sq = (ox + x * s, oy + y * s, ox + (x + 1) * s, oy + (y + 1) * s)
            row += "#" if any(square_poly_d2(sq, vs) <= r2 for vs in polys) else "."
        rows.append(row)
    return rows


def cell_blocked(inp):
    rows = blocked_rows(inp)
    return {"rows": rows, "blocked": sum(r.count("#") for r in rows)}


def inflate_grid(inp):
    m = GridMap(inp["map"])
    s = num(inp["cell_size"])
    r = num(inp["radius"]) + num(inp["margin"])
    require(s > 0 and num(inp["radius"]) >= 0 and num(inp["margin"]) >= 0, "s > 0, r >= 0")
    blocked = [(x, y) for y in range(m.h) for x in range(m.w) if m.is_blocked(x, y)]
    rows = []
    for y in range(m.h - 1, -1, -1):
        row = ""
        for x in range(m.w):
            hit = False
            for bx, by in blocked:
                gx, gy = max(0, abs(x - bx) - 1), max(0, abs(y - by) - 1)
                if s * s * (gx * gx + gy * gy) <= r * r:
                    hit = True
                    break
            row += "#" if hit else "."
        rows.append(row)
    return {"rows": rows}


def inflate_scene(inp):
    rows = blocked_rows(inp)
    w, h = inp["width"], inp["height"]
    cells = {}
    for key in ("start", "goal"):
        require(key in inp, f"/{key}: missing")
        x, y = inp[key]
        require(0 <= x < w and 0 <= y < h, f"/{key}: outside the map")
        require(rows[h - 1 - y][x] == ".", f"/{key}: blocked")
        cells[key] = [x, y]
    require(cells["start"] != cells["goal"], "/goal: equals the start cell")
    return {"rows": rows, "start": cells["start"], "goal": cells["goal"]}


RULES = {
    "inflation.cell-blocked": cell_blocked,
    "inflation.grid": inflate_grid,
    "inflation.scene": inflate_scene,
}
