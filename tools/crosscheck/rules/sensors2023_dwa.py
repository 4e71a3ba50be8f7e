"""spec/sensors2023-dwa.md (sensors2023 Eq. 9-14: the dynamic window approach, the following
heading term, clearance, key-node following, scripted obstacles, the continuous-time collision
test, turns and the fused run), written from the spec alone.

Arithmetic follows the spec's evaluation order on Python floats (no math.hypot, no fused
operations); sin, cos, atan2 and fmod are the C library's, as the spec names them.
"""
import math

from .common import require

PI = 3.141592653589793
DEG = 57.29577951308232
INF = math.inf


class UsageError(Exception):
    """A malformed request (never expected by a golden vector)."""


class ParseError(Exception):
    """A scenario the format rejects (the C++ ParseError)."""


def fin(*xs):
    return all(isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) for x in xs)


def opt(inp, key, default):
    return inp[key] if key in inp else default


# ---- grid ---------------------------------------------------------------------------------------


class Grid:
    def __init__(self, rows):
        require(isinstance(rows, list) and rows and all(isinstance(r, str) for r in rows), "rows")
        require(len({len(r) for r in rows}) == 1 and len(rows[0]) > 0, "equal rows")
        self.w, self.h = len(rows[0]), len(rows)
        self.blocked = set()
        for r, row in enumerate(rows):
            y = self.h - 1 - r
            for x, ch in enumerate(row):
                require(ch in ".#", "only . and #")
                if ch == "#":
                    self.blocked.add((x, y))

    def free(self, x, y):
        return 0 <= x < self.w and 0 <= y < self.h and (x, y) not in self.blocked


# ---- Eq. 9 --------------------------------------------------------------------------------------


def step(p, v, w, dt, order):
    require(fin(p[0], p[1], p[2], v, w), "finite")
    require(fin(dt) and dt > 0, "dt > 0")
    ds = v * dt
    if order == "heading-last":
        return (p[0] + ds * math.cos(p[2]), p[1] + ds * math.sin(p[2]), p[2] + w * dt)
    if order == "heading-first":
        th = p[2] + w * dt
        return (p[0] + ds * math.cos(th), p[1] + ds * math.sin(th), th)
    raise UsageError("motion_order")


def n_steps(horizon, dt):
    require(fin(dt, horizon) and dt > 0 and horizon > 0, "positive")
    q = horizon / dt
    n = math.floor(q + 0.5) if q >= 0 else -math.floor(-q + 0.5)  # half away from zero
    require(1 <= n <= 10000, "N in [1, 10000]")
    return int(n)


def eq9(inp):
    order = opt(inp, "motion_order", "heading-last")
    p = tuple(inp["pose"])
    out = {"pose": list(step(p, inp["v"], inp["w"], inp["dt"], order))}
    if "horizon" in inp:
        n = n_steps(inp["horizon"], inp["dt"])
        traj = []
        q = p
        for _ in range(n):
            q = step(q, inp["v"], inp["w"], inp["dt"], order)
            traj.append(list(q))
        out["trajectory"] = traj
    return out


# ---- Eq. 10, 11 ---------------------------------------------------------------------------------

DEFAULT_LIMITS = {"v_min": 0.0, "v_max": 1.0, "w_max": 0.6981317007977318, "acc_v": 0.5, "dec_v": 0.5,
                  "acc_w": 1.7453292519943295, "dec_w": 1.7453292519943295}


def vspace(lim):
    require(fin(lim["v_min"], lim["v_max"], lim["w_max"]), "finite")
    require(lim["v_min"] <= lim["v_max"], "v_min <= v_max")
    require(lim["w_max"] >= 0, "w_max >= 0")
    return (lim["v_min"], lim["v_max"], -lim["w_max"], lim["w_max"])


def eq10(inp):
    lo, hi, wlo, whi = vspace(inp)
    return {"v_lo": lo, "v_hi": hi, "w_lo": wlo, "w_hi": whi}


def window(vc, wc, lim, dt):
    s = vspace(lim)
    rates = (lim["acc_v"], lim["dec_v"], lim["acc_w"], lim["dec_w"])
    require(fin(*rates) and min(rates) >= 0, "rates")
    require(fin(dt) and dt > 0, "dt")
    require(fin(vc) and lim["v_min"] <= vc <= lim["v_max"], "v_c")
    require(fin(wc) and abs(wc) <= lim["w_max"], "w_c")
    return (max(s[0], vc - lim["dec_v"] * dt), min(s[1], vc + lim["acc_v"] * dt),
            max(s[2], wc - lim["dec_w"] * dt), min(s[3], wc + lim["acc_w"] * dt))


def samples(lo, hi, r, upper):
    require(fin(lo, hi) and lo <= hi, "lo <= hi")
    require(fin(r) and r > 0, "r > 0")
    s = (hi - lo) / r
    require(s <= 1e6, "samples")
    if upper == "include":
        k = math.floor(s + 1e-9)
    elif upper == "exclude":
        k = max(0.0, math.ceil(s - 1e-9) - 1.0)
    else:
        raise UsageError("window_upper")
    return [lo + float(i) * r for i in range(int(k) + 1)]


def limits_of(inp):
    return {k: opt(inp, k, v) for k, v in DEFAULT_LIMITS.items()}


def eq11(inp):
    up = opt(inp, "window_upper", "include")
    w = window(inp["v_c"], inp["w_c"], limits_of(inp), inp["dt"])
    out = {"v_lo": w[0], "v_hi": w[1], "w_lo": w[2], "w_hi": w[3]}
    if "v_res" in inp:
        out["v_samples"] = samples(w[0], w[1], inp["v_res"], up)
    if "w_res" in inp:
        out["w_samples"] = samples(w[2], w[3], inp["w_res"], up)
    return out


# ---- Eq. 12 -------------------------------------------------------------------------------------


def adm(v, w, d, dv, dw, mode):
    require(fin(v, w, d, dv, dw), "finite")
    require(d >= 0, "dist >= 0")
    require(dv >= 0 and dw >= 0, "decelerations")
    if mode == "off":
        return True
    lin = v <= math.sqrt((2.0 * d) * dv)
    if mode == "linear":
        return lin
    if mode != "both":
        raise UsageError("admissible")
    return lin and abs(w) <= math.sqrt((2.0 * d) * dw)


def eq12(inp):
    return {"admissible": adm(inp["v"], inp["w"], inp["dist"], inp["dec_v"], inp["dec_w"],
                              opt(inp, "admissible", "both"))}


# ---- Eq. 14 -------------------------------------------------------------------------------------


def wrap(a):
    require(fin(a), "finite")
    r = math.fmod(a + PI, 2.0 * PI)
    if r <= 0.0:
        r = r + 2.0 * PI
    return r - PI


def heading(pose, target, mode):
    require(fin(pose[0], pose[1], pose[2], target[0], target[1]), "finite")
    d = pose[2] - math.atan2(target[1] - pose[1], target[0] - pose[0])
    if mode == "on":
        a = abs(wrap(d))
    elif mode == "off":
        a = abs(d)
    else:
        raise UsageError("heading_wrap")
    return 180.0 - a * DEG, a


def num(v):
    return {"inf": math.inf, "-inf": -math.inf, "nan": math.nan}[v] if isinstance(v, str) else v


def eq14(inp):
    h, a = heading([num(x) for x in inp["pose"]], inp["target"], opt(inp, "heading_wrap", "on"))
    return {"heading": h, "dtheta": a}


# ---- Eq. 13 -------------------------------------------------------------------------------------

DEFAULT_WEIGHTS = {"alpha": 0.2, "beta": 0.2, "gamma": 0.1, "k_heading": 0.15, "k_clearance": 1.0,
                   "k_velocity": 1.0}


def evaluate(cands, wts, mode, vmax):
    """cands: list of (heading, dtheta, clearance, velocity, valid)."""
    require(len(cands) <= 10 ** 6, "size")
    for v in wts.values():
        require(fin(v) and v >= 0, "weights")
    require(fin(vmax), "v_max")
    for h, a, d, v, ok in cands:
        if not ok:
            continue
        require(fin(h, a, d, v), "finite terms")
        require(d >= 0, "clearance >= 0")
        if mode == "normalised":
            require(v >= 0, "velocity >= 0")
    scores = [math.nan] * len(cands)
    best = -1
    if mode == "normalised":
        hs = ds = vs = 0.0
        for h, a, d, v, ok in cands:
            if ok:
                hs = hs + h
                ds = ds + d
                vs = vs + v
        for i, (h, a, d, v, ok) in enumerate(cands):
            if not ok:
                continue
            hb = 0.0 if hs == 0.0 else h / hs
            db = 0.0 if ds == 0.0 else d / ds
            vb = 0.0 if vs == 0.0 else v / vs
            g = ((wts["alpha"] * hb) + (wts["beta"] * db)) + (wts["gamma"] * vb)
            scores[i] = g
            if best < 0 or g > scores[best]:
                best = i
    elif mode == "cost":
        for i, (h, a, d, v, ok) in enumerate(cands):
            if not ok:
                continue
            inv = INF if d == 0.0 else 1.0 / d
            c = ((wts["k_heading"] * a) + (wts["k_velocity"] * (vmax - v))) + (wts["k_clearance"] * inv)
            scores[i] = c
            if best < 0 or c < scores[best]:
                best = i
    else:
        raise UsageError("evaluation")
    return scores, best


def eq13(inp):
    wts = {k: opt(inp, k, v) for k, v in DEFAULT_WEIGHTS.items()}
    cands = [(c["heading"], c["dtheta"], c["clearance"], c["velocity"], c["valid"]) for c in inp["candidates"]]
    scores, best = evaluate(cands, wts, opt(inp, "evaluation", "normalised"), opt(inp, "v_max", 1.0))
    return {"scores": scores, "best": best}


# ---- clearance ----------------------------------------------------------------------------------


def cell_dist(p, c):
    x0, y0 = float(c[0]), float(c[1])
    dx = max(max(x0 - p[0], 0.0), p[0] - (x0 + 1.0))
    dy = max(max(y0 - p[1], 0.0), p[1] - (y0 + 1.0))
    return math.sqrt(dx * dx + dy * dy)


def point_clear(p, g, temp, discs, radius, cap, tau=0.0):
    require(fin(p[0], p[1]) and abs(p[0]) <= 1e9 and abs(p[1]) <= 1e9, "point")
    require(fin(tau), "tau")
    require(fin(cap) and cap > 0, "cap")
    require(fin(radius) and radius >= 0, "radius")
    reach = cap + radius
    m = INF
    for y in range(math.floor(p[1] - reach), math.floor(p[1] + reach) + 1):
        for x in range(math.floor(p[0] - reach), math.floor(p[0] + reach) + 1):
            if not g.free(x, y):
                m = min(m, cell_dist(p, (x, y)))
    for c in temp:
        m = min(m, cell_dist(p, c))
    for (cx, cy), r, (vx, vy) in discs:
        require(fin(cx, cy, r, vx, vy) and r >= 0, "disc")
        dx, dy = p[0] - (cx + tau * vx), p[1] - (cy + tau * vy)
        m = min(m, math.sqrt(dx * dx + dy * dy) - r)
    return min(cap, m - radius)


def discs_of(inp):
    return [((d["c"][0], d["c"][1]), d["r"], tuple(d.get("vel", (0.0, 0.0)))) for d in inp.get("discs", [])]


def clearance(inp):
    g = Grid(inp["grid"])
    temp = [tuple(c) for c in inp.get("temporary", [])]
    discs = discs_of(inp)
    at = opt(inp, "clearance_at", "trajectory")
    pts = inp["points"]
    require(len(pts) > 0, "empty trajectory")
    dt = opt(inp, "dt", 0.0)
    require(fin(dt) and dt >= 0, "dt")
    pcs = [point_clear(p, g, temp, discs, inp["radius"], inp["cap"], (j + 1) * dt) for j, p in enumerate(pts)]
    if at == "trajectory":
        c = min(pcs)
    elif at == "end":
        c = pcs[-1]
    else:
        raise UsageError("clearance_at")
    return {"clearance": c, "point_clearances": pcs}


# ---- control step -------------------------------------------------------------------------------

DEFAULT_DWA = dict(DEFAULT_LIMITS, **DEFAULT_WEIGHTS, dt=0.1, horizon=3.0, v_res=0.01,
                   w_res=0.017453292519943295, clearance_cap=1.0, evaluation="normalised",
                   clearance_at="trajectory", heading_wrap="on", window_upper="include", admissible="both",
                   motion_order="heading-last", heading_target="key-node", obstacle_prediction="linear")


def dwa_params(block):
    p = dict(DEFAULT_DWA)
    for k, v in (block or {}).items():
        if k not in p:
            raise UsageError("dwa key " + k)
        p[k] = v
    return p


def control(pose, vc, wc, target, g, temp, discs, p, radius):
    lim = {k: p[k] for k in DEFAULT_LIMITS}
    w = window(vc, wc, lim, p["dt"])
    vs = samples(w[0], w[1], p["v_res"], p["window_upper"])
    ws = samples(w[2], w[3], p["w_res"], p["window_upper"])
    n = n_steps(p["horizon"], p["dt"])
    cap = p["clearance_cap"]
    cands = []
    for v in vs:
        for om in ws:
            q = tuple(pose)
            c = INF
            for j in range(n):
                q = step(q, v, om, p["dt"], p["motion_order"])
                if p["clearance_at"] == "trajectory" or j == n - 1:
                    tau = float(j + 1) * p["dt"] if p["obstacle_prediction"] == "linear" else 0.0
                    c = min(c, point_clear(q, g, temp, discs, radius, cap, tau))
            h, a = heading(q, target, p["heading_wrap"])
            ok = c >= 0.0 and adm(v, om, c, lim["dec_v"], lim["dec_w"], p["admissible"])
            cands.append((h, a, c if ok else max(0.0, c), v, ok))
    wts = {k: p[k] for k in DEFAULT_WEIGHTS}
    scores, best = evaluate(cands, wts, p["evaluation"], lim["v_max"])
    valid = sum(1 for x in cands if x[4])
    if best >= 0:
        return {"v": vs[best // len(ws)], "w": ws[best % len(ws)], "braked": False, "candidates": len(cands),
                "valid": valid, "best": best, "score": scores[best]}
    v = max(lim["v_min"], vc - lim["dec_v"] * p["dt"])
    om = max(0.0, wc - lim["dec_w"] * p["dt"]) if wc >= 0.0 else min(0.0, wc + lim["dec_w"] * p["dt"])
    return {"v": v, "w": om, "braked": True, "candidates": len(cands), "valid": valid, "best": -1, "score": 0.0}


def dwa_step(inp):
    g = Grid(inp["grid"])
    p = dwa_params(inp.get("dwa"))
    return control(inp["pose"], inp["v_c"], inp["w_c"], inp["target"], g,
                   [tuple(c) for c in inp.get("temporary", [])], discs_of(inp), p, opt(inp, "radius", 0.3))


# ---- following ----------------------------------------------------------------------------------


def keys_of(path):
    require(len(path) > 0, "empty path")
    p = []
    for c in path:
        c = tuple(c)
        if not p or p[-1] != c:
            p.append(c)
    out = [p[0]]
    for i in range(1, len(p) - 1):
        ax, ay = p[i][0] - p[i - 1][0], p[i][1] - p[i - 1][1]
        bx, by = p[i + 1][0] - p[i][0], p[i + 1][1] - p[i][1]
        if not (ax * by - ay * bx == 0 and ax * bx + ay * by > 0):
            out.append(p[i])
    if len(p) > 1:
        out.append(p[-1])
    return out


def follow(state, p, keys, blocked, t, dt, reach, btimeout, ktimeout):
    k, since, bfor = state
    m = len(keys) - 1
    require(len(keys) > 0 and len(blocked) == len(keys), "keys")
    require(0 <= k <= m, "k")
    require(fin(dt, reach, btimeout, ktimeout) and dt > 0 and reach > 0 and btimeout > 0 and ktimeout > 0, "params")
    switched = 0
    while k < m:
        dx, dy = p[0] - keys[k][0], p[1] - keys[k][1]
        if math.sqrt(dx * dx + dy * dy) > reach:
            break
        k, since, bfor = k + 1, t, 0.0
        switched += 1
    skipped = "none"
    if k < m:
        bfor = bfor + dt if blocked[k] else 0.0
        if bfor >= btimeout:
            skipped = "blocked"
        elif t - since >= ktimeout:
            skipped = "timeout"
        if skipped != "none":
            k, since, bfor = k + 1, t, 0.0
    return (k, since, bfor), switched, skipped


def waypoints(nodes, spacing):
    """Target points of the traditional fusion: each segment in ceil(L/spacing - 1e-9) equal parts."""
    require(len(nodes) > 0, "empty path")
    require(fin(spacing) and spacing > 0, "spacing")
    for q in nodes:
        require(fin(*q), "finite")
    out = [tuple(nodes[0])]
    total = 1.0
    for a, b in zip(nodes, nodes[1:]):
        dx, dy = b[0] - a[0], b[1] - a[1]
        L = math.sqrt(dx * dx + dy * dy)
        if L == 0.0:
            continue
        n = max(1.0, math.ceil(L / spacing - 1e-9))
        require(total + n <= 1e6, "at most 10^6 waypoints")
        total += n
        n = int(n)
        for j in range(1, n):
            f = float(j) / float(n)
            out.append((a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])))
        out.append(tuple(b))
    return out


def follow_rule(inp):
    out = {}
    if "waypoints_of" in inp:
        out["waypoints"] = [list(q) for q in waypoints(inp["waypoints_of"], opt(inp, "spacing", 1.0))]
    if "path" in inp:
        out["key_nodes"] = [list(c) for c in keys_of(inp["path"])]
    if "keys" in inp:
        st, sw, sk = follow((inp["k"], inp["since"], inp["blocked_for"]), inp["p"], inp["keys"], inp["blocked"],
                            inp["t"], inp["dt"], opt(inp, "reach", 1.0), opt(inp, "blocked_timeout", 3.0),
                            opt(inp, "key_timeout", 30.0))
        out.update({"k": st[0], "since": st[1], "blocked_for": st[2], "switched": sw, "skipped": sk})
    return out


# ---- obstacles, collision, turns ----------------------------------------------------------------


def position(wps, t):
    require(len(wps) > 0, "no waypoints")
    require(fin(t), "t")
    for i, w in enumerate(wps):
        require(fin(*w), "finite")
        if i:
            require(w[0] > wps[i - 1][0], "increasing")
    if t <= wps[0][0]:
        return (wps[0][1], wps[0][2])
    if t >= wps[-1][0]:
        return (wps[-1][1], wps[-1][2])
    i = 0
    while not t < wps[i + 1][0]:
        i += 1
    a, b = wps[i], wps[i + 1]
    f = (t - a[0]) / (b[0] - a[0])
    return (a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]))


def obstacles_rule(inp):
    return {"position": list(position(inp["waypoints"], inp["t"]))}


def pseg(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = dx * dx + dy * dy
    s = 0.0 if L == 0 else min(1.0, max(0.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L))
    qx, qy = a[0] + s * dx, a[1] + s * dy
    return math.sqrt((p[0] - qx) * (p[0] - qx) + (p[1] - qy) * (p[1] - qy))


def orient(a, b, x):
    return (b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0])


def segseg(a, b, c, d):
    o1, o2 = orient(a, b, c), orient(a, b, d)
    o3, o4 = orient(c, d, a), orient(c, d, b)
    if ((o1 > 0 > o2) or (o1 < 0 < o2)) and ((o3 > 0 > o4) or (o3 < 0 < o4)):
        return 0.0
    return min(pseg(a, c, d), pseg(b, c, d), pseg(c, a, b), pseg(d, a, b))


def seg_cell(a, b, c):
    x0, y0 = float(c[0]), float(c[1])
    x1, y1 = x0 + 1.0, y0 + 1.0
    for p in (a, b):
        if x0 <= p[0] <= x1 and y0 <= p[1] <= y1:
            return 0.0
    c00, c10, c11, c01 = (x0, y0), (x1, y0), (x1, y1), (x0, y1)
    return min(segseg(a, b, c00, c10), segseg(a, b, c10, c11), segseg(a, b, c11, c01), segseg(a, b, c01, c00))


def step_clear(a, b, t0, t1, radius, g, temp, movers):
    require(fin(a[0], a[1], b[0], b[1]), "finite")
    require(fin(t0, t1) and t0 < t1, "t0 < t1")
    require(fin(radius) and radius >= 0, "radius")
    m = INF
    for y in range(math.floor(min(a[1], b[1]) - 10.0), math.floor(max(a[1], b[1]) + 10.0) + 1):
        for x in range(math.floor(min(a[0], b[0]) - 10.0), math.floor(max(a[0], b[0]) + 10.0) + 1):
            if not g.free(x, y):
                m = min(m, seg_cell(a, b, (x, y)))
    for c in temp:
        m = min(m, seg_cell(a, b, c))
    m = m - radius
    for r, wps in movers:
        require(fin(r) and r >= 0, "mover radius")
        cuts = [t0] + [w[0] for w in wps if t0 < w[0] < t1] + [t1]
        for i in range(len(cuts) - 1):
            s0, s1 = cuts[i], cuts[i + 1]
            f0, f1 = (s0 - t0) / (t1 - t0), (s1 - t0) / (t1 - t0)
            r0 = (a[0] + f0 * (b[0] - a[0]), a[1] + f0 * (b[1] - a[1]))
            r1 = (a[0] + f1 * (b[0] - a[0]), a[1] + f1 * (b[1] - a[1]))
            o0, o1 = position(wps, s0), position(wps, s1)
            dax, day = r0[0] - o0[0], r0[1] - o0[1]
            ex, ey = (r1[0] - o1[0]) - dax, (r1[1] - o1[1]) - day
            L = ex * ex + ey * ey
            s = 0.0
            if L > 0.0:
                s = min(1.0, max(0.0, -(dax * ex + day * ey) / L))
            qx, qy = dax + s * ex, day + s * ey
            m = min(m, (math.sqrt(qx * qx + qy * qy) - r) - radius)
    return min(m, 10.0)


def collision_rule(inp):
    g = Grid(inp["grid"])
    movers = [(m["r"], [tuple(w) for w in m["waypoints"]]) for m in inp.get("movers", [])]
    c = step_clear(inp["a"], inp["b"], inp["t0"], inp["t1"], inp["radius"], g,
                   [tuple(c) for c in inp.get("temporary", [])], movers)
    return {"clearance": c, "collides": c < 0.0}


def length(track):
    L = 0.0
    for i in range(1, len(track)):
        dx, dy = track[i][0] - track[i - 1][0], track[i][1] - track[i - 1][1]
        L = L + math.sqrt(dx * dx + dy * dy)
    return L


def turns(track, ds, delta, theta):
    require(fin(ds) and ds > 0, "ds")
    require(fin(delta, theta) and 0 < delta <= theta, "delta, theta")
    pts = []
    for p in track:
        require(fin(p[0], p[1]), "finite")
        if not pts or pts[-1] != (p[0], p[1]):
            pts.append((p[0], p[1]))
    if len(pts) < 2:
        return 0
    # piece table: cumulative arc length in order
    acc = [0.0]
    lens = []
    for i in range(len(pts) - 1):
        dx, dy = pts[i + 1][0] - pts[i][0], pts[i + 1][1] - pts[i][1]
        lens.append(math.sqrt(dx * dx + dy * dy))
        acc.append(acc[-1] + lens[-1])
    rs = []
    i = 0
    k = 0
    while True:
        s = float(i) * ds
        while s > acc[k] + lens[k] and k + 1 < len(lens):
            k += 1
        if s > acc[k] + lens[k]:
            break
        f = (s - acc[k]) / lens[k]
        rs.append((pts[k][0] + f * (pts[k + 1][0] - pts[k][0]), pts[k][1] + f * (pts[k + 1][1] - pts[k][1])))
        i += 1
    if len(rs) < 3:
        return 0
    n = 0
    run_sum, sign = 0.0, 0
    prev = math.atan2(rs[1][1] - rs[0][1], rs[1][0] - rs[0][0])
    for i in range(2, len(rs)):
        h = math.atan2(rs[i][1] - rs[i - 1][1], rs[i][0] - rs[i - 1][0])
        d = wrap(h - prev)
        prev = h
        if abs(d) >= delta:
            sg = 1 if d > 0 else -1
            if sg == sign:
                run_sum = run_sum + d
            else:
                if sign != 0 and abs(run_sum) >= theta:
                    n += 1
                sign, run_sum = sg, d
        else:
            if sign != 0 and abs(run_sum) >= theta:
                n += 1
            sign, run_sum = 0, 0.0
    if sign != 0 and abs(run_sum) >= theta:
        n += 1
    return n


def turns_rule(inp):
    tr = [tuple(p) for p in inp["track"]]
    delta = inp["delta_deg"] / DEG if "delta_deg" in inp else 0.04363323129985824
    theta = inp["theta_deg"] / DEG if "theta_deg" in inp else 0.3490658503988659
    return {"turns": turns(tr, opt(inp, "ds", 1.0), delta, theta), "length": length(tr)}


# ---- the fused run ------------------------------------------------------------------------------


def run(sc):
    """A pathref-sim 2 scenario with the map as rows and an explicit path (no planner here)."""
    g = Grid(sc["map"])
    start, goal = tuple(sc["start"]), tuple(sc["goal"])
    require(g.free(*start) and g.free(*goal), "free ends")
    if "path" not in sc:
        raise UsageError("the crosscheck runs scenarios with an explicit path only")
    path = [tuple(c) for c in sc["path"]]
    p = dwa_params(sc.get("dwa"))
    target_mode = p["heading_target"]
    require(target_mode in ("key-node", "waypoint", "goal"), "heading_target")
    to_goal = target_mode == "goal"
    radius = sc.get("robot", {}).get("radius", 0.3)
    fo = sc.get("follow", {})
    reach, goal_reach = fo.get("reach", 1.0), fo.get("goal_reach", 0.5)
    bmargin, btimeout, ktimeout = fo.get("blocked_margin", 0.2), fo.get("blocked_timeout", 3.0), fo.get("key_timeout", 30.0)
    st = sc.get("stall", {})
    swin, sdist = st.get("window", 10.0), st.get("distance", 0.1)
    tu = sc.get("turns", {})
    tds = tu.get("ds", 1.0)
    tdelta = tu["delta_deg"] / DEG if "delta_deg" in tu else 0.04363323129985824
    ttheta = tu["theta_deg"] / DEG if "theta_deg" in tu else 0.3490658503988659
    t_max = sc.get("t_max", 300.0)
    movers = [(m.get("radius", 0.4), [tuple(w) for w in m["waypoints"]]) for m in sc.get("moving", [])]
    temps = [(tuple(t["cell"]), t.get("appear", 0.0), t.get("disappear", 1e5)) for t in sc.get("temporary", [])]
    keys_c = keys_of(path)
    keys = [(c[0] + 0.5, c[1] + 0.5) for c in keys_c]
    gp = (goal[0] + 0.5, goal[1] + 0.5)
    dt = p["dt"]
    theta0 = sc["heading0"] if "heading0" in sc else (
        math.atan2(keys[1][1] - keys[0][1], keys[1][0] - keys[0][0]) if len(keys) > 1 else 0.0)
    if target_mode == "waypoint":
        keys = waypoints(keys, fo.get("waypoint_spacing", 1.0))
    pose = (keys[0][0], keys[0][1], theta0)
    v = w = 0.0
    state = (0, 0.0, 0.0)
    stall_n = int(math.floor(swin / dt + 0.5))
    track = []
    skips = []
    length_ = 0.0
    min_c = 10.0
    steps = braked = 0
    outcome = None
    k = 0
    t = 0.0
    while True:
        t = float(k) * dt
        pos = (pose[0], pose[1])
        track.append(pos)
        dx, dy = pos[0] - gp[0], pos[1] - gp[1]
        if math.sqrt(dx * dx + dy * dy) <= goal_reach:
            outcome = "reached"
            break
        present = [c for c, a, d in temps if a <= t < d]
        discs = []
        for r, wps in movers:
            o = position(wps, t)
            vel = (0.0, 0.0)
            if k > 0:
                b = position(wps, float(k - 1) * dt)
                vel = ((o[0] - b[0]) / dt, (o[1] - b[1]) / dt)
            discs.append((o, r, vel))
        blocked = [point_clear(kp, g, present, discs, radius, bmargin + 1.0) < bmargin for kp in keys]
        state2, sw, sk = follow(state, pos, keys, blocked, t, dt, reach, btimeout, ktimeout)
        if sk != "none":
            skips.append({"t": t, "key": state[0] + sw, "reason": sk})
        state = state2
        if k >= stall_n and stall_n > 0:
            ox, oy = track[k - stall_n]
            if math.sqrt((pos[0] - ox) * (pos[0] - ox) + (pos[1] - oy) * (pos[1] - oy)) < sdist:
                outcome = "stalled"
                break
        if t >= t_max:
            outcome = "timed_out"
            break
        target = gp if to_goal else keys[state[0]]
        r = control(pose, v, w, target, g, present, discs, p, radius)
        braked += 1 if r["braked"] else 0
        v, w = r["v"], r["w"]
        nxt = step(pose, v, w, dt, p["motion_order"])
        t1 = float(k + 1) * dt
        present1 = [c for c, a, d in temps if a < t1 and d > t]
        c = step_clear(pos, (nxt[0], nxt[1]), t, t1, radius, g, present1, movers)
        min_c = min(min_c, c)
        ddx, ddy = pos[0] - nxt[0], pos[1] - nxt[1]
        length_ = length_ + math.sqrt(ddx * ddx + ddy * ddy)
        pose = nxt
        steps += 1
        k += 1
        if c < 0.0:
            outcome = "collided"
            t = t1
            track.append((pose[0], pose[1]))
            break
    return {"outcome": outcome, "time": t, "length": length_, "min_clearance": min_c,
            "turns": turns(track, tds, tdelta, ttheta), "steps": steps, "braked_steps": braked,
            "key_nodes": [list(c) for c in keys_c], "skips": skips, "end": list(pose)}


def run_rule(inp):
    return run(inp["scenario"])


RULES = {
    "sensors2023.eq9": eq9,
    "sensors2023.eq10": eq10,
    "sensors2023.eq11": eq11,
    "sensors2023.eq12": eq12,
    "sensors2023.eq13": eq13,
    "sensors2023.eq14": eq14,
    "sensors2023.dwa.clearance": clearance,
    "sensors2023.dwa.step": dwa_step,
    "sensors2023.dwa.follow": follow_rule,
    "sensors2023.sim.obstacles": obstacles_rule,
    "sensors2023.sim.collision": collision_rule,
    "sensors2023.sim.turns": turns_rule,
    "sensors2023.sim.run": run_rule,
}
