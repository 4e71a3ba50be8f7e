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
    def __init__(self, cells, gidx, seg=0, off=0.0):
        self.cells, self.gidx, self.seg, self.off = cells, gidx, seg, off

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

    def remaining(self):
        if self.at_end():
            return 0.0
        r = self.piece(self.seg) - self.off
        for j in range(self.seg + 1, len(self.cells) - 1):
            r += self.piece(j)
        return r

    def lookahead(self, L):
        pts = [self.pos()]
        if self.at_end():
            return pts
        acc = self.piece(self.seg) - self.off
        if acc >= L:
            pts.append(self.at(self.seg, self.off + L))
            return pts
        pts.append(centre(self.cells[self.seg + 1]))
        for j in range(self.seg + 1, len(self.cells) - 1):
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


def _num(v, lo, hi):
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise _ParseError("number")
    v = float(v)
    if not (math.isfinite(v) and lo <= v <= hi):
        raise _ParseError("range")
    return v


class _ParseError(Exception):
    pass


def _astar_path(rows_blocked, w, h, start, goal, policy):
    m = _search.Map(["." * w])
    m.w, m.h, m.blocked = w, h, rows_blocked
    found, path, _, _ = _search.best_first(m, start, goal, policy, "chebyshev")
    return found, path


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
    if "path" in s:
        gp = [tuple(c) for c in s["path"]]
        require(gp[0] == start and gp[-1] == goal, "path from start to goal")
        for a, b in zip(gp, gp[1:]):
            require(_search.allowed(m, a, b, policy), "path step allowed")
    else:
        planner = s.get("planner", "iaco-han")
        params = {}
        if isinstance(planner, dict):
            params = planner.get("params", {})
            planner = planner["name"]
        if planner != "astar":
            raise UsageError("the crosscheck replays only given paths and the astar planner")
        found, gp, _, _ = _search.best_first(m, start, goal, policy, params.get("heuristic", "octile"))
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
    res = {"waits": [], "replans": [], "collisions": [], "trajectory": []}
    dist, wait_time, reached, tend, steps = 0.0, 0.0, False, 0.0, 0

    def truepos(o, t):
        (px, py), (vx, vy), _ = obs[o]
        return (px + (vx * t), py + (vy * t))

    def record(t, st):
        p = plan.pos()
        res["trajectory"].append([t, p[0], p[1], v, st])

    def check(t, p0, p1, t1):
        for o in range(len(obs)):
            a, b = truepos(o, t), truepos(o, t1)
            d = pseg((0.0, 0.0), (p0[0] - a[0], p0[1] - a[1]), (p1[0] - b[0], p1[1] - b[1]))
            if d < rr + obs[o][2]:
                res["collisions"].append({"t": t, "obstacle": o, "distance": d})

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
        frontal, side, conflicting, pred, inside = [], [], [], {}, False
        for o in range(len(obs)):
            tr = trackers[o]
            if tr[0] < 2:
                continue
            A, B = tr[4], tr[5]
            ta, tb = t - tr[1], (t - tr[1]) + H
            p = ((A[0] * ta) + A[1], (B[0] * ta) + B[1])
            q = ((A[0] * tb) + A[1], (B[0] * tb) + B[1])
            pred[o] = (p, q)
            c = classify(ahead, p, q, (rr + obs[o][2]) + margin, fc)
            if c["kind"] == "none":
                continue
            (frontal if c["kind"] == "frontal" else side).append(o)
            conflicting.append(o)
            inside = inside or c["robot_inside"]
        wait_now = False
        if frontal:
            replanned = False
            ps = plan.seg + 1 if plan.off > 0.0 else plan.seg
            from_cell = plan.cells[ps]
            frm = -1
            for i in range(ps, len(plan.cells)):
                if plan.gidx[i] >= 0:
                    frm = plan.gidx[i]
                    break
            blocked = set(m.blocked)
            for o in conflicting:
                p, q = pred[o]
                for c in swept(m.w, m.h, p, q, (rr + obs[o][2]) + margin):
                    blocked.add(c)
            flags = [c in blocked for c in gp]
            target = local_target(flags, frm) if frm >= 0 else -1
            if target >= 0 and from_cell not in blocked and tuple(gp[target]) != from_cell:
                found, det = _astar_path(blocked, m.w, m.h, from_cell, gp[target], policy)
                if found:
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
            wait_now = not replanned and not inside
        elif side:
            wait_now = not inside
        p0 = plan.pos()
        if wait_now:
            if not waiting:
                waiting, wait_start, wait_obs = True, t, list(conflicting)
            v = 0.0
            record(t, "wait")
            check(t, p0, p0, float(k + 1) * dt)
            k += 1
            continue
        if waiting:
            waiting = False
            res["waits"].append({"start": wait_start, "end": t, "duration": t - wait_start, "obstacles": wait_obs})
            wait_time += t - wait_start
        record(t, "move")
        ds, v1, used, arrived = motion(v, dt, vmax, acc, plan.remaining())
        plan.advance(ds)
        if arrived:
            plan.seg, plan.off = len(plan.cells) - 1, 0.0
        dist += ds
        v = v1
        t1 = t + used
        check(t, p0, plan.pos(), t1)
        if arrived:
            reached, tend, steps = True, t1, k + 1
            record(t1, "arrive")
            break
        k += 1
    if not reached:
        steps = int(math.ceil(tend / dt))
    res.update({"global_found": True, "global_path": [list(c) for c in gp], "global_length": glen,
                "reached_goal": reached, "collided": len(res["collisions"]) > 0, "time": tend,
                "distance": dist, "wait_time": wait_time, "steps": steps,
                "estimates": [[tr[4][0], tr[4][1], tr[5][0], tr[5][1]] if tr is not None and tr[0] >= 2 else [0.0] * 4
                              for tr in trackers]})
    return res


RULES = {
    "han.maps.random": maps_random,
    "han.collision.classify": collision_classify,
    "han.sim.motion": sim_motion,
    "han.sim.detour": sim_detour,
    "han.sim.run": run,
}
