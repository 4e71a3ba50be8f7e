"""spec/han-sim.md (Han, IJACSA: random maps of the protocol, the Fig. 5 collision test, the speed
profile, the frontal detour and whole simulation runs), written from the spec alone.

Geometry is written out on Python floats in the evaluation order the spec pins (no math.hypot, no
fused operations), so distances, classifications and trajectories match bit for bit. The random
stream is this package's own MT19937 (rules/rng.py), the search its own best-first A*
(rules/search.py), and the RLS recursion its own (rules/han.py): none shares code with the C++.
"""
import math

from .common import require
from . import rng as _rng
from . import search as _search
from . import han as _han
from . import aco_planners as _aco

SQRT2 = math.sqrt(2.0)
FRONTAL_COS = -SQRT2 / 2.0


class UsageError(Exception):
    """A malformed request (the C++ UsageError); never expected by a golden vector."""


# ---- han.maps.random ---------------------------------------------------------------------------


def random_map(seed, edge, ratio):
    require(2 <= edge <= 1000, "edge in [2, 1000]")
    require(isinstance(ratio, (int, float)) and math.isfinite(ratio) and 0.0 <= ratio <= 1.0, "ratio in [0, 1]")
    cells = edge * edge
    n = int(math.floor(float(ratio) * float(cells)))
    require(n <= cells - (2 * edge - 1), "too many obstacles for the corridor")
    g = _rng.MT19937(seed)
    draws = 0
    c = (0, 0)
    goal = (edge - 1, edge - 1)
    corridor = [c]
    while c != goal:
        rx, ry = goal[0] - c[0], goal[1] - c[1]
        if rx == 0:
            c = (c[0], c[1] + 1)
        elif ry == 0:
            c = (c[0] + 1, c[1])
        else:
            u = g.genrand_res53()
            draws += 1
            k = int(math.floor(u * (rx + ry)))
            c = (c[0] + 1, c[1]) if k < rx else (c[0], c[1] + 1)
        corridor.append(c)
    reserved = {y * edge + x for x, y in corridor}
    cand = [i for i in range(cells) if i not in reserved]
    blocked = set()
    for i in range(n):
        u = g.genrand_res53()
        draws += 1
        j = i + int(math.floor(u * (len(cand) - i)))
        cand[i], cand[j] = cand[j], cand[i]
        blocked.add(cand[i])
    rows = []
    for y in range(edge - 1, -1, -1):
        rows.append("".join("#" if (y * edge + x) in blocked else "." for x in range(edge)))
    return rows, corridor, n, draws


def maps_random(inp):
    seed, edge, ratio = inp["seed"], inp["edge"], inp["ratio"]
    if not (isinstance(seed, int) and 0 <= seed <= 0xFFFFFFFF):
        raise UsageError("seed")
    rows, corridor, n, draws = random_map(seed, edge, float(ratio))
    return {"grid": rows, "start": [0, 0], "goal": [edge - 1, edge - 1],
            "corridor": [[x, y] for x, y in corridor], "obstacles": n, "draws": draws}


# ---- geometry and han.collision.classify -------------------------------------------------------


def pseg(p, a, b, ray=False):
    dx = b[0] - a[0]
    dy = b[1] - a[1]
    l2 = (dx * dx) + (dy * dy)
    s = 0.0
    if l2 != 0.0:
        s = (((p[0] - a[0]) * dx) + ((p[1] - a[1]) * dy)) / l2
        s = max(s, 0.0) if ray else min(max(s, 0.0), 1.0)
    qx = a[0] + (s * dx)
    qy = a[1] + (s * dy)
    ex, ey = p[0] - qx, p[1] - qy
    return math.sqrt((ex * ex) + (ey * ey))


def _orient(a, b, c):
    return ((b[0] - a[0]) * (c[1] - a[1])) - ((b[1] - a[1]) * (c[0] - a[0]))


def _opp(s, t):
    return (s > 0.0 and t < 0.0) or (s < 0.0 and t > 0.0)


def segdist(a, b, c, d):
    if _opp(_orient(a, b, c), _orient(a, b, d)) and _opp(_orient(c, d, a), _orient(c, d, b)):
        return 0.0
    return min(pseg(a, c, d), pseg(b, c, d), pseg(c, a, b), pseg(d, a, b))


def classify(robot, p, q, clearance, fc=FRONTAL_COS):
    require(len(robot) >= 2, "at least two robot points")
    for k in range(1, len(robot)):
        require(robot[k] != robot[k - 1], "distinct consecutive points")
    require(all(math.isfinite(v) for pt in robot + [p, q] for v in pt), "finite")
    require(math.isfinite(clearance) and clearance > 0.0, "clearance > 0")
    require(-1.0 <= fc <= 1.0, "frontal_cos in [-1, 1]")
    best, piece = segdist(robot[0], robot[1], p, q), 0
    for k in range(1, len(robot) - 1):
        d = segdist(robot[k], robot[k + 1], p, q)
        if d < best:
            best, piece = d, k
    static = (p[0] == q[0] and p[1] == q[1])
    inside = pseg(robot[0], p, q, ray=True) < clearance
    cos_angle = 0.0
    if static:
        kind = "none" if best >= clearance else "frontal"
    else:
        ux, uy = robot[piece + 1][0] - robot[piece][0], robot[piece + 1][1] - robot[piece][1]
        vx, vy = q[0] - p[0], q[1] - p[1]
        dot = (ux * vx) + (uy * vy)
        nu = math.sqrt((ux * ux) + (uy * uy))
        nv = math.sqrt((vx * vx) + (vy * vy))
        cos_angle = dot / (nu * nv)
        if best >= clearance:
            kind = "none"
        else:
            kind = "frontal" if dot <= ((fc * nu) * nv) else "side"
    return {"kind": kind, "distance": best, "piece": piece, "cos_angle": cos_angle, "robot_inside": inside}


def _pt(v):
    if not (isinstance(v, list) and len(v) == 2):
        raise UsageError("point")
    return (float(v[0]), float(v[1]))


def collision_classify(inp):
    robot = [_pt(v) for v in inp["robot"]]
    return classify(robot, _pt(inp["p"]), _pt(inp["q"]), float(inp["clearance"]),
                    float(inp.get("frontal_cos", FRONTAL_COS)))


# ---- han.sim.motion ----------------------------------------------------------------------------


def motion(v0, dt, vmax, a, rem=math.inf):
    require(math.isfinite(dt) and dt > 0.0, "dt > 0")
    require(math.isfinite(vmax) and vmax > 0.0, "v_max > 0")
    require(math.isfinite(a) and a > 0.0, "a > 0")
    require(math.isfinite(v0) and 0.0 <= v0 <= vmax, "v0 in [0, v_max]")
    require(not math.isnan(rem) and rem >= 0.0, "remaining >= 0")
    ta = (vmax - v0) / a
    da = (v0 * ta) + ((a * (ta * ta)) / 2.0)
    if dt <= ta:
        ds, v1 = (v0 * dt) + ((a * (dt * dt)) / 2.0), v0 + (a * dt)
    else:
        ds, v1 = da + (vmax * (dt - ta)), vmax
    used, arrived = dt, False
    if ds >= rem:
        arrived, ds = True, rem
        if rem == 0.0:
            used, v1 = 0.0, v0
        elif rem <= da:
            tau = (2.0 * rem) / (v0 + math.sqrt((v0 * v0) + ((2.0 * a) * rem)))
            used, v1 = tau, v0 + (a * tau)
        else:
            used, v1 = ta + ((rem - da) / vmax), vmax
    return ds, v1, used, arrived


def ramp_cruise(length, vmax, a):
    require(math.isfinite(length) and length >= 0.0, "length >= 0")
    da = (vmax * vmax) / (2.0 * a)
    if length <= da:
        return math.sqrt((2.0 * length) / a)
    return (vmax / a) + ((length - da) / vmax)


def sim_motion(inp):
    rem = float(inp["remaining"]) if "remaining" in inp else math.inf
    vmax, a = float(inp["v_max"]), float(inp["a"])
    ds, v1, used, arrived = motion(float(inp["v0"]), float(inp["dt"]), vmax, a, rem)
    out = {"distance": ds, "v_end": v1, "time": used, "arrived": arrived}
    if math.isfinite(rem):
        out["ramp_cruise_time"] = ramp_cruise(rem, vmax, a)
    return out


# ---- han.sim.detour ----------------------------------------------------------------------------


def centre(c):
    return (float(c[0]) + 0.5, float(c[1]) + 0.5)


def swept(w, h, p, q, clearance):
    require(math.isfinite(clearance) and clearance > 0.0, "clearance > 0")
    reach = clearance + (SQRT2 / 2.0)
    return [(x, y) for y in range(h) for x in range(w) if pseg(centre((x, y)), p, q) < reach]


def swept_ray(w, h, p, q, clearance):
    """han.sim.evade: cells closer than clearance + sqrt(2)/2 to the ray from p through q."""
    require(math.isfinite(clearance) and clearance > 0.0, "clearance > 0")
    reach = clearance + (SQRT2 / 2.0)
    return [(x, y) for y in range(h) for x in range(w) if pseg(centre((x, y)), p, q, ray=True) < reach]


def local_target(flags, frm):
    require(0 <= frm < len(flags), "from indexes the path")
    last = -1
    for i in range(frm, len(flags)):
        if flags[i]:
            last = i
    if last < 0:
        return frm
    return -1 if last + 1 >= len(flags) else last + 1


def sim_detour(inp):
    m = _search.Map(inp["grid"])
    cells = swept(m.w, m.h, _pt(inp["p"]), _pt(inp["q"]), float(inp["clearance"]))
    path = [tuple(c) for c in inp["path"]]
    s = set(cells)
    flags = [c in s for c in path]
    return {"swept": [[x, y] for x, y in cells], "target": local_target(flags, inp["from"])}


# ---- han.sim.run -------------------------------------------------------------------------------


def _step_cost(a, b):
    return SQRT2 if (a[0] != b[0] and a[1] != b[1]) else 1.0


class _Plan:
    """The robot's plan (han.sim.step): cells, their global indices (-1 off the global path), the
    robot's piece and offset, and the stop cell (the goal, or the refuge of an evasion)."""

    def __init__(self, cells, gidx, seg=0, off=0.0, stop=None):
        self.cells, self.gidx, self.seg, self.off = cells, gidx, seg, off
        self.stop = len(cells) - 1 if stop is None else stop

    def at_end(self):
        return self.seg + 1 >= len(self.cells)

    def piece(self, i):
        return _step_cost(self.cells[i], self.cells[i + 1])

    def at(self, i, f):
        a = centre(self.cells[i])
        if f == 0.0:
            return a
        b = centre(self.cells[i + 1])
        r = f / self.piece(i)
        return (a[0] + (r * (b[0] - a[0])), a[1] + (r * (b[1] - a[1])))

    def pos(self):
        return centre(self.cells[-1]) if self.at_end() else self.at(self.seg, self.off)

    def remaining_to(self, last):
        if self.seg >= last:
            return 0.0
        r = self.piece(self.seg) - self.off
        for j in range(self.seg + 1, last):
            r += self.piece(j)
        return r

    def lookahead(self, L, last=None):
        last = len(self.cells) - 1 if last is None else last
        pts = [self.pos()]
        if self.seg >= last:
            return pts
        acc = self.piece(self.seg) - self.off
        if acc >= L:
            pts.append(self.at(self.seg, self.off + L))
            return pts
        pts.append(centre(self.cells[self.seg + 1]))
        for j in range(self.seg + 1, last):
            ln = self.piece(j)
            if acc + ln >= L:
                pts.append(self.at(j, L - acc))
                return pts
            acc += ln
            pts.append(centre(self.cells[j + 1]))
        return pts

    def advance(self, ds):
        while ds > 0.0 and not self.at_end():
            r = self.piece(self.seg) - self.off
            if ds < r:
                self.off += ds
                ds = 0.0
            else:
                ds -= r
                self.seg += 1
                self.off = 0.0


# ---- han.sim.safety ----------------------------------------------------------------------------


def _norm(dx, dy):
    return math.sqrt((dx * dx) + (dy * dy))


def along(pts, L):
    """The point at arc length L along the polyline (han.sim.safety)."""
    require(len(pts) >= 1, "a polyline needs a point")
    if L <= 0.0 or len(pts) == 1:
        return pts[0]
    acc = 0.0
    for a, b in zip(pts, pts[1:]):
        dx, dy = b[0] - a[0], b[1] - a[1]
        ln = _norm(dx, dy)
        if L <= acc + ln:
            if ln == 0.0:
                return a
            f = (L - acc) / ln
            return (a[0] + (f * dx), a[1] + (f * dy))
        acc += ln
    return pts[-1]


def margins(pts, v0, vmax, acc, dt, H, line, tau):
    require(len(pts) >= 1 and all(math.isfinite(c) for p in pts for c in p), "finite robot points")
    require(math.isfinite(dt) and dt > 0.0 and math.isfinite(H) and H > 0.0, "dt, horizon > 0")
    require(math.isfinite(tau), "tau finite")
    require(math.isfinite(vmax) and vmax > 0.0 and math.isfinite(acc) and acc > 0.0, "v_max, a > 0")
    require(math.isfinite(v0) and 0.0 <= v0 <= vmax, "v0 in [0, v_max]")
    a, b, c, d = line
    waits, gos = [], []
    j = 0
    while float(j) * dt <= H:
        sj = float(j) * dt
        tt = tau + sj
        ox, oy = (a * tt) + b, (c * tt) + d
        r = along(pts, 0.0 if j == 0 else motion(v0, sj, vmax, acc)[0])
        waits.append(_norm(pts[0][0] - ox, pts[0][1] - oy))
        gos.append(_norm(r[0] - ox, r[1] - oy))
        j += 1
    closing = len(gos) >= 2 and gos[-1] < gos[-2]
    return min(waits), min(gos), closing, len(gos)


def sim_safety(inp):
    pts = [_pt(v) for v in inp["robot"]]
    line = [float(x) for x in inp["motion"]]
    if len(line) != 4:
        raise UsageError("motion is [a, b, c, d]")
    w, g, closing, n = margins(pts, float(inp["v0"]), float(inp["v_max"]), float(inp["a"]), float(inp["dt"]),
                               float(inp["horizon"]), line, float(inp["tau"]))
    return {"wait": w, "go": g, "go_closing": closing, "samples": n}


# ---- han.sim.evade -----------------------------------------------------------------------------


def refuge(m, sources, band, pol):
    """Multi-source Dijkstra, smallest (g, index) first; the first settled cell off the band."""
    require(len(sources) >= 1, "a source")
    dist, parent, src = {}, {}, {}
    for i, (c, cst) in enumerate(sources):
        require(m.inside(c), "sources inside the grid")
        require(math.isfinite(cst) and cst >= 0.0, "source costs >= 0")
        if not m.free(c):
            continue
        if c not in dist or cst < dist[c]:
            dist[c], parent[c], src[c] = cst, None, i
    opened, done = set(dist), set()
    while opened:
        u = min(opened, key=lambda c: (dist[c], m.index(c)))
        opened.remove(u)
        done.add(u)
        if u not in band:
            path = []
            c = u
            while c is not None:
                path.append(c)
                c = parent[c]
            path.reverse()
            return True, path, src[u], dist[u]
        for ddy in (-1, 0, 1):
            for ddx in (-1, 0, 1):
                q = (u[0] + ddx, u[1] + ddy)
                if q in done or not _search.allowed(m, u, q, pol):
                    continue
                nd = dist[u] + _search.cost(u, q)
                if q not in dist or nd < dist[q]:
                    dist[q], parent[q], src[q] = nd, u, src[u]
                    opened.add(q)
    return False, [], -1, 0.0


def sim_evade(inp):
    m = _search.Map(inp["grid"])
    pol = inp.get("policy", "strict")
    sources = []
    for v in inp["sources"]:
        if not (isinstance(v, list) and len(v) == 3):
            raise UsageError("a source is [x, y, cost]")
        sources.append(((int(v[0]), int(v[1])), float(v[2])))
    band = {tuple(c) for c in inp["band"]}
    for r in inp.get("rays", []):
        if not (isinstance(r, list) and len(r) == 5):
            raise UsageError("a ray is [px, py, qx, qy, clearance]")
        band |= set(swept_ray(m.w, m.h, (float(r[0]), float(r[1])), (float(r[2]), float(r[3])), float(r[4])))
    found, path, source, cst = refuge(m, sources, band, pol)
    return {"band": [list(c) for c in sorted(band, key=m.index)], "found": found, "path": [list(c) for c in path],
            "source": source, "cost": cst}


def _num(v, lo, hi):
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise _ParseError("number")
    v = float(v)
    if not (math.isfinite(v) and lo <= v <= hi):
        raise _ParseError("range")
    return v


class _ParseError(Exception):
    pass


class ParseError(Exception):
    """A malformed scenario (the C++ ParseError of the scenario reader)."""


def _astar_path(rows_blocked, w, h, start, goal, policy):
    m = _search.Map(["." * w])
    m.w, m.h, m.blocked = w, h, rows_blocked
    found, path, _, _ = _search.best_first(m, start, goal, policy, "chebyshev")
    return found, path


def _global_path(m, s, start, goal, policy):
    """The scenario's global path: the given path, or the planner's (astar, or the colony replay
    for iaco-han and for iaco-astar with its global planner)."""
    if "path" in s:
        gp = [tuple(c) for c in s["path"]]
        # A given path is checked while the scenario is read (spec/han-sim.md,
        # han.sim.scenario-format): a malformed scenario, ParseError at /path/N.
        if not (gp[0] == start and gp[-1] == goal):
            raise ParseError("/path: from the start to the goal")
        for a, b in zip(gp, gp[1:]):
            if not _search.allowed(m, a, b, policy):
                raise ParseError("/path: a step allowed under the corner policy")
        return True, gp
    planner = s.get("planner", "iaco-han")
    params = {}
    if isinstance(planner, dict):
        params = dict(planner.get("params", {}))
        planner = planner["name"]
    if planner == "iaco-astar":
        planner = params.pop("global", "iaco-han")
        prefix = planner + "."
        for k in params:
            if not k.startswith(prefix):
                raise UsageError(f"iaco-astar: {k!r} is not a parameter of {planner}")
        params = {k[len(prefix):]: v for k, v in params.items()}
    if planner == "astar":
        found, gp, _, _ = _search.best_first(m, start, goal, policy, params.get("heuristic", "octile"))
        return found, gp
    if planner == "iaco-han":
        inp = dict(params, grid=s["map"], start=list(start), goal=list(goal), policy=policy, seed=s.get("seed", 1))
        r = _aco.replay("iaco-han", inp)
        return r["found"], [tuple(c) for c in r["path"]]
    raise UsageError("the crosscheck replays given paths and the planners astar, iaco-han, iaco-astar")


def run(inp):
    s = inp["scenario"]
    require(s.get("format") == "pathref-sim 1", "format")
    m = _search.Map(s["map"])
    start, goal = tuple(s["start"]), tuple(s["goal"])
    policy = s.get("policy", "strict")
    dt = float(s.get("dt", 0.125))
    H = float(s.get("horizon", 3.0))
    robot = s.get("robot", {})
    rr, vmax, acc = float(robot.get("radius", 0.3)), float(robot.get("speed", 1.0)), float(robot.get("accel", 1.0))
    margin, noise = float(s.get("margin", 0.25)), float(s.get("noise", 0.0))
    tmax, lam = float(s.get("t_max", 600.0)), float(s.get("lambda", 0.95))
    fc = float(s.get("frontal_cos", FRONTAL_COS))
    seed = s.get("seed", 1)
    obs = [((float(o["position"][0]), float(o["position"][1])), (float(o["velocity"][0]), float(o["velocity"][1])),
            float(o.get("radius", 0.3))) for o in s.get("obstacles", [])]
    require(m.free(start) and m.free(goal), "start and goal free")
    found, gp = _global_path(m, s, start, goal, policy)
    if not found:
        return {"global_found": False, "reached_goal": False}
    glen = 0.0
    for a, b in zip(gp, gp[1:]):
        glen += _step_cost(a, b)
    plan = _Plan(list(gp), list(range(len(gp))))
    stream = _rng.MT19937(seed)
    trackers = [None] * len(obs)   # [samples, t0, x0, y0, A, B, P]
    look = vmax * H
    v = 0.0
    waiting, wait_start, wait_obs = False, 0.0, []
    evading = False
    res = {"waits": [], "replans": [], "evasions": [], "unavoidable": [], "collisions": [], "trajectory": []}
    dist, wait_time, reached, tend, steps = 0.0, 0.0, False, 0.0, 0

    def clear(o):
        return (rr + obs[o][2]) + margin

    def truepos(o, t):
        (px, py), (vx, vy), _ = obs[o]
        return (px + (vx * t), py + (vy * t))

    tracks = [[] for _ in obs]
    draws = 0

    def record(t, st):
        p = plan.pos()
        res["trajectory"].append([t, p[0], p[1], v, st])
        for o in range(len(obs)):
            tracks[o].append(list(truepos(o, t)))

    def check(t, p0, p1, ta, tb):
        for o in range(len(obs)):
            a, b = truepos(o, ta), truepos(o, tb)
            d = pseg((0.0, 0.0), (p0[0] - a[0], p0[1] - a[1]), (p1[0] - b[0], p1[1] - b[1]))
            if d < rr + obs[o][2]:
                res["collisions"].append({"t": t, "obstacle": o, "distance": d,
                                          "outside_guarantee": "unobserved" if trackers[o][0] < 2 else False})

    if plan.at_end():
        reached = True
        record(0.0, "arrive")
    k = 0
    while not reached:
        t = float(k) * dt
        if t >= tmax:
            tend = t
            if waiting:
                res["waits"].append({"start": wait_start, "end": t, "duration": t - wait_start, "obstacles": wait_obs})
                wait_time += t - wait_start
            break
        for o in range(len(obs)):
            z = truepos(o, t)
            if noise > 0.0:
                ux, uy = stream.genrand_res53(), stream.genrand_res53()
                draws += 2
                z = (z[0] + (((2.0 * ux) - 1.0) * noise), z[1] + (((2.0 * uy) - 1.0) * noise))
            tr = trackers[o]
            if tr is None:
                trackers[o] = [1, t, z[0], z[1], None, None, None]
            elif tr[0] == 1:
                A, B, P = _han._rls_init([0.0, t - tr[1]], [tr[2], z[0]], [tr[3], z[1]], lam, True)
                trackers[o] = [2, tr[1], tr[2], tr[3], A, B, P]
            else:
                A, B, P = _han._rls_step(tr[4], tr[5], tr[6], t - tr[1], z[0], z[1], lam)
                trackers[o] = [tr[0] + 1, tr[1], tr[2], tr[3], A, B, P]
        ahead = plan.lookahead(look)
        frontal, side, conflicting, pred, lines = [], [], [], {}, {}
        for o in range(len(obs)):
            tr = trackers[o]
            if tr[0] < 2:
                continue
            A, B = tr[4], tr[5]
            ta, tb = t - tr[1], (t - tr[1]) + H
            p = ((A[0] * ta) + A[1], (B[0] * ta) + B[1])
            q = ((A[0] * tb) + A[1], (B[0] * tb) + B[1])
            pred[o] = (p, q)
            lines[o] = ((A[0], A[1], B[0], B[1]), ta)
            c = classify(ahead, p, q, clear(o), fc)
            if c["kind"] == "none":
                continue
            (frontal if c["kind"] == "frontal" else side).append(o)
            conflicting.append(o)

        def predict():
            """(worst wait slack, worst go slack, some obstacle still closing in at the end)."""
            pts = plan.lookahead(look, plan.stop)
            ws, gs, cl = math.inf, math.inf, False
            for o in conflicting:
                w, g, closing, _ = margins(pts, v, vmax, acc, dt, H, lines[o][0], lines[o][1])
                ws, gs, cl = min(ws, w - clear(o)), min(gs, g - clear(o)), cl or closing
            return ws, gs, cl

        def first_global(ps):
            for i in range(ps, len(plan.cells)):
                if plan.gidx[i] >= 0:
                    return plan.gidx[i]
            return -1

        def band():
            b = set()
            for o in conflicting:
                p, q = pred[o]
                for c in swept(m.w, m.h, p, q, clear(o)):
                    if m.free(c):
                        b.add(c)
            return b

        wait_now = evade_now = False
        if evading:
            if not conflicting:
                evading = False
                plan.stop = len(plan.cells) - 1
            elif predict()[1] < 0.0:
                evade_now = True
        elif conflicting:
            replanned = False
            if frontal:
                ps = plan.seg + 1 if plan.off > 0.0 else plan.seg
                from_cell = plan.cells[ps]
                frm = first_global(ps)
                blocked = set(m.blocked) | band()
                flags = [c in blocked for c in gp]
                target = local_target(flags, frm) if frm >= 0 else -1
                if target >= 0 and from_cell not in blocked and tuple(gp[target]) != from_cell:
                    ok, det = _astar_path(blocked, m.w, m.h, from_cell, gp[target], policy)
                    if ok:
                        cells, gidx = [], []
                        if plan.off > 0.0:
                            cells.append(plan.cells[plan.seg])
                            gidx.append(plan.gidx[plan.seg])
                        for c in det[:-1]:
                            cells.append(c)
                            gidx.append(-1)
                        for i in range(target, len(gp)):
                            cells.append(gp[i])
                            gidx.append(i)
                        plan = _Plan(cells, gidx, 0, plan.off)
                        res["replans"].append({"t": t, "from": list(from_cell), "target": list(gp[target]),
                                               "target_index": target, "detour": [list(c) for c in det],
                                               "obstacles": list(frontal)})
                        replanned = True
            if not replanned:
                ws, gs, cl = predict()
                if ws >= 0.0:
                    wait_now = True
                elif gs < 0.0 or cl:
                    evade_now = True
        if evade_now:
            bnd = set()
            for o in conflicting:
                p, q = pred[o]
                bnd |= {c for c in swept_ray(m.w, m.h, p, q, clear(o)) if m.free(c)}
            if plan.off > 0.0:
                sources = [(plan.cells[plan.seg], plan.off), (plan.cells[plan.seg + 1], plan.piece(plan.seg) - plan.off)]
            else:
                sources = [(plan.cells[plan.seg], 0.0)]
            bodies = _search.Map(["." * m.w])
            bodies.w, bodies.h, bodies.blocked = m.w, m.h, set(m.blocked)
            for o in conflicting:
                p = pred[o][0]
                touch = rr + obs[o][2]
                bodies.blocked |= {(x, y) for y in range(m.h) for x in range(m.w) if pseg(centre((x, y)), p, p) < touch}
            ok, rpath, source, _ = refuge(bodies, sources, bnd, policy)
            if ok and evading and rpath[-1] == plan.cells[plan.stop]:
                res["unavoidable"].append({"t": t, "obstacles": list(conflicting), "reason": "late"})
            elif ok:
                was_evading = evading
                reverses = plan.off > 0.0 and source == 0
                frm = first_global(plan.seg + 1 if plan.off > 0.0 else plan.seg)
                tgt = gp[frm]
                ref = rpath[-1]
                at_goal = ref == gp[-1]
                if plan.off > 0.0:
                    back = source == 0
                    other = plan.seg + 1 if back else plan.seg
                    cells, gidx = [plan.cells[other]], [plan.gidx[other]]
                    off = plan.piece(plan.seg) - plan.off if back else plan.off
                    first = plan.seg if back else plan.seg + 1
                else:
                    cells, gidx, off, first = [], [], 0.0, plan.seg
                for i, c in enumerate(rpath):
                    cells.append(c)
                    gidx.append(plan.gidx[first] if i == 0 else -1)
                stop = len(cells) - 1
                if at_goal:
                    gidx[-1] = len(gp) - 1
                else:
                    if ref != tgt:
                        ok2, back_path = _astar_path(set(m.blocked), m.w, m.h, ref, tgt, policy)
                        require(ok2, "a way back from the refuge")
                        for c in back_path[1:]:
                            cells.append(c)
                            gidx.append(-1)
                    gidx[-1] = frm
                    for i in range(frm + 1, len(gp)):
                        cells.append(gp[i])
                        gidx.append(i)
                plan = _Plan(cells, gidx, 0, off, stop)
                evading = True
                if not was_evading or reverses:
                    v = 0.0
                res["evasions"].append({"t": t, "from": list(rpath[0]), "refuge": list(ref),
                                        "path": [list(c) for c in rpath],
                                        "target": list(ref if at_goal else tgt),
                                        "target_index": len(gp) - 1 if at_goal else frm,
                                        "obstacles": list(conflicting)})
                if predict()[1] < 0.0:
                    res["unavoidable"].append({"t": t, "obstacles": list(conflicting), "reason": "late"})
            else:
                res["unavoidable"].append({"t": t, "obstacles": list(conflicting), "reason": "trapped"})
                ws, gs, _ = predict()
                wait_now = ws >= gs
        p0 = plan.pos()
        t_next = float(k + 1) * dt
        if wait_now:
            if not waiting:
                waiting, wait_start, wait_obs = True, t, list(conflicting)
            v = 0.0
            record(t, "wait")
            check(t, p0, p0, t, t_next)
            k += 1
            continue
        if waiting:
            waiting = False
            res["waits"].append({"start": wait_start, "end": t, "duration": t - wait_start, "obstacles": wait_obs})
            wait_time += t - wait_start
        record(t, "evade" if evading else "move")
        ds, v1, used, arrived = motion(v, dt, vmax, acc, plan.remaining_to(plan.stop))
        plan.advance(ds)
        goal_reached = arrived and plan.stop == len(plan.cells) - 1
        if arrived:
            plan.seg, plan.off = plan.stop, 0.0
        dist += ds
        v = v1
        t1 = t + used
        p1 = plan.pos()
        check(t, p0, p1, t, t1)
        if goal_reached:
            reached, tend, steps = True, t1, k + 1
            record(t1, "arrive")
            break
        if arrived:
            evading = False
            v = 0.0
            plan.stop = len(plan.cells) - 1
            check(t, p1, p1, t1, t_next)
        k += 1
    if not reached:
        steps = int(math.ceil(tend / dt))
    for c in res["collisions"]:
        if c["outside_guarantee"] is not False:
            continue
        for u in res["unavoidable"]:
            if u["t"] <= c["t"] and c["t"] - u["t"] <= H and c["obstacle"] in u["obstacles"]:
                c["outside_guarantee"] = "unavoidable"
                break
    res.update({"format": "pathref-sim-result", "noise_draws": draws, "obstacle_tracks": tracks,
                "global_found": True, "global_path": [list(c) for c in gp], "global_length": glen,
                "reached_goal": reached, "collided": len(res["collisions"]) > 0, "time": tend,
                "distance": dist, "wait_time": wait_time, "steps": steps,
                "unexplained_collisions": sum(1 for c in res["collisions"] if c["outside_guarantee"] is False),
                "estimates": [[tr[4][0], tr[4][1], tr[5][0], tr[5][1]] if tr is not None and tr[0] >= 2 else [0.0] * 4
                              for tr in trackers]})
    return res


def plan_iaco_astar(inp):
    """han.plan.iaco-astar: the global planner's run, and with obstacles the simulation."""
    reserved = ("grid", "start", "goal", "seed", "policy", "obstacles")
    params = {k: v for k, v in inp.items() if k not in reserved}
    name = params.pop("global", "iaco-han")
    if name != "iaco-han":
        raise UsageError("the crosscheck replays iaco-astar with the global planner iaco-han")
    prefix = name + "."
    for k in params:
        if not k.startswith(prefix):
            raise UsageError(f"{k!r} is not a parameter of {name}")
    inner = {k[len(prefix):]: v for k, v in params.items()}
    pol = inp.get("policy", "strict")
    seed = inp.get("seed", 1)
    r = _aco.replay("iaco-han", dict(inner, grid=inp["grid"], start=inp["start"], goal=inp["goal"],
                                     policy=pol, seed=seed))
    used = {"global": name}
    for k, v in _aco.params_for("iaco-han", inner).items():
        used[prefix + k] = v
    out = {"found": r["found"], "path": r["path"], "length": r["length"], "iterations": r["iterations"],
           "best_per_iteration": r["best_per_iteration"], "global": name, "draws": r["draws"],
           "params_used": used}
    if "obstacles" in inp:
        sc = {"format": "pathref-sim 1", "map": inp["grid"], "start": inp["start"], "goal": inp["goal"],
              "policy": pol, "seed": seed, "planner": {"name": "iaco-astar", "params": {k: v for k, v in inp.items() if k not in reserved}},
              "obstacles": inp["obstacles"]}
        out["simulation"] = run({"scenario": sc})
    return out


RULES = {
    "han.maps.random": maps_random,
    "han.collision.classify": collision_classify,
    "han.sim.motion": sim_motion,
    "han.sim.detour": sim_detour,
    "han.sim.run": run,
    "han.sim.safety": sim_safety,
    "han.sim.evade": sim_evade,
    "han.plan.iaco-astar": plan_iaco_astar,
}
