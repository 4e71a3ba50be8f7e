"""spec/mecanum.md (mecanum.* and drive.*), written from the spec. Python 3 standard library only.

Independent of the C++ on purpose:
  - the wheel map J (4x3) and its least-squares inverse are written out by hand. The columns of J
    are orthogonal, J^T J = diag(4, 4, 4k^2), so J^+ = diag(1/4, 1/4, 1/(4k^2)) J^T in closed form
    (the C++ solves the least-squares problem with Eigen's QR instead);
  - the residual uses the left null vector (1, 1, -1, -1) directly (the C++ computes w - IK(FK(w)));
  - the trapezoid is evaluated by case analysis (top speed reached or not) with the phase formulas
    rearranged, and turning angles with atan2 (the C++ counts 45-degree steps).
Agreement is therefore up to rounding, which every golden tolerance states.
"""
import math

from .common import DomainError, require

INF = math.inf
SQRT2 = math.sqrt(2.0)


# ---------------------------------------------------------------------------------------------
# input helpers


def _num(inp, key, default=None):
    if key not in inp:
        if default is None:
            raise KeyError(key)
        return default
    v = inp[key]
    if isinstance(v, str):
        return {"inf": INF, "-inf": -INF, "nan": math.nan}[v]
    return float(v)


def _nums(v):
    return [{"inf": INF, "-inf": -INF, "nan": math.nan}[x] if isinstance(x, str) else float(x) for x in v]


def _finite_pos(x):
    return math.isfinite(x) and x > 0


def _pos_or_inf(x):
    return not math.isnan(x) and x > 0


def _out(x):
    """A float as the golden format writes it (non-finite as strings)."""
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return x


def _geometry(inp, r=None, lx=None, ly=None):
    r = _num(inp, "r") if r is None else r
    lx = _num(inp, "lx") if lx is None else lx
    ly = _num(inp, "ly") if ly is None else ly
    require(_finite_pos(r), "r must be finite and > 0")
    require(_finite_pos(lx), "lx must be finite and > 0")
    require(_finite_pos(ly), "ly must be finite and > 0")
    return r, lx + ly


# ---------------------------------------------------------------------------------------------
# kinematics

# Rows FL, FR, RL, RR of J / columns (v_x, v_y, k*omega): signs only; k multiplies the third.
J_SIGNS = ((1, -1, -1), (1, 1, 1), (1, 1, -1), (1, -1, 1))
NULL = (1, 1, -1, -1)  # spans the left null space of J
ROS2 = (0, 1, 3, 2)    # ros2_controllers order FL, FR, RR, RL as indices into pathref order


def _ik(vx, vy, om, r, k):
    require(all(math.isfinite(x) for x in (vx, vy, om)), "twist must be finite")
    w = []
    for sx, sy, sk in J_SIGNS:
        num = vx + (vy if sy > 0 else -vy)
        num = num + (k * om if sk > 0 else -(k * om))
        w.append(num / r)
    require(all(math.isfinite(x) for x in w), "wheel speeds overflow")
    return w


def _fk(w, r, k):
    require(len(w) == 4 and all(math.isfinite(x) for x in w), "four finite wheel speeds")
    # J^+ (r w): row i of J^T times r w, divided by the diagonal of J^T J.
    rw = [r * x for x in w]
    require(all(math.isfinite(x) for x in rw), "rim speeds overflow")
    sums = [0.0, 0.0, 0.0]
    for i, (sx, sy, sk) in enumerate(J_SIGNS):
        sums[0] += sx * rw[i]
        sums[1] += sy * rw[i]
        sums[2] += sk * rw[i]
    return sums[0] / 4.0, sums[1] / 4.0, sums[2] / (4.0 * k)


def _order(inp):
    o = inp.get("wheel_order", "pathref")
    require(o in ("pathref", "ros2"), "wheel_order")
    return o


def ik(inp):
    r, k = _geometry(inp)
    w = _ik(_num(inp, "vx"), _num(inp, "vy"), _num(inp, "omega"), r, k)
    if _order(inp) == "ros2":
        w = [w[i] for i in ROS2]
    return {"w": w, "rpm": [x * 60.0 / (2.0 * math.pi) for x in w]}


def fk(inp):
    r, k = _geometry(inp)
    w = _nums(inp["w"])
    if _order(inp) == "ros2":
        w = [w[i] for i in ROS2]  # the permutation is its own inverse
    vx, vy, om = _fk(w, r, k)
    return {"vx": vx, "vy": vy, "omega": om}


def residual(inp):
    _geometry(inp)  # validated although the projection does not depend on it
    w = _nums(inp["w"])
    require(len(w) == 4 and all(math.isfinite(x) for x in w), "four finite wheel speeds")
    c = (w[0] + w[1] - w[2] - w[3]) / 4.0
    e = [c * n for n in NULL]
    return {"projection": [w[i] - e[i] for i in range(4)], "residual": e, "norm": abs(c) * 2.0}


def wheel_limit(inp):
    n = _num(inp, "rpm")
    at = inp.get("limit_at", "output")
    ratio = _num(inp, "gear_ratio", 36.0)
    require(_finite_pos(n), "rpm must be finite and > 0")
    require(math.isfinite(ratio) and ratio >= 1.0, "gear ratio must be finite and >= 1")
    require(at in ("output", "rotor"), "limit_at")
    g = 1.0 if at == "output" else ratio
    return {"w_max": (n * (2.0 * math.pi)) / 60.0 / g, "wheel_rpm": n / g}


def _scale(w, w_max):
    require(_finite_pos(w_max), "w_max must be finite and > 0")
    m = max(abs(x) for x in w)
    if m <= w_max:
        return 1.0
    s = w_max / m
    while s * m > w_max:
        s = math.nextafter(s, 0.0)
    require(s > 0.0, "scale underflows")
    return s


def saturate(inp):
    r, k = _geometry(inp)
    vx, vy, om = _num(inp, "vx"), _num(inp, "vy"), _num(inp, "omega")
    w = _ik(vx, vy, om, r, k)
    s = _scale(w, _num(inp, "w_max"))
    return {"scale": s, "vx": s * vx, "vy": s * vy, "omega": s * om, "w": [s * x for x in w],
            "saturated": s < 1.0}


def _factor(dx, dy):
    require(math.isfinite(dx) and math.isfinite(dy), "direction must be finite")
    require(dx != 0.0 or dy != 0.0, "direction must not be zero")
    return (abs(dx) + abs(dy)) / math.hypot(dx, dy)


def max_speed(inp):
    dx, dy, r, w_max = _num(inp, "dx"), _num(inp, "dy"), _num(inp, "r"), _num(inp, "w_max")
    require(_finite_pos(r) and _finite_pos(w_max), "r and w_max must be finite and > 0")
    g = _factor(dx, dy)
    return {"v_max": r * w_max / g, "factor": g}


# ---------------------------------------------------------------------------------------------
# driving


def _trapezoid(d, v0, v1, vmax, a):
    require(math.isfinite(d) and d >= 0, "d must be finite and >= 0")
    require(math.isfinite(v0) and v0 >= 0 and math.isfinite(v1) and v1 >= 0, "speeds")
    require(_finite_pos(a), "a must be finite and > 0")
    require(_pos_or_inf(vmax), "V must be > 0")
    require(v0 <= vmax and v1 <= vmax, "speeds above the limit")
    edge = max(v0, v1)
    # Reachability: v1^2 <= v0^2 + 2ad and v0^2 <= v1^2 + 2ad, with the spec's relative slack.
    apex = math.sqrt(a * d + (v0 * v0 + v1 * v1) / 2.0)
    require(apex >= edge * (1.0 - 1e-12), "end speed not reachable")
    # Distance needed to touch V and come back: reaches V iff it fits in d.
    if vmax < INF and (2.0 * vmax * vmax - v0 * v0 - v1 * v1) / (2.0 * a) <= d:
        vp = vmax
        t_acc, t_dec = (vp - v0) / a, (vp - v1) / a
        d_cru = d - (2.0 * vp * vp - v0 * v0 - v1 * v1) / (2.0 * a)
        t_cru = max(d_cru, 0.0) / vp
        shape = "trapezoid"
    else:
        vp = max(apex, edge)
        t_acc, t_dec = (vp - v0) / a, (vp - v1) / a
        d_cru, t_cru = 0.0, 0.0
        shape = "trapezoid" if vp == vmax else "triangle"
    time = t_acc + t_dec + t_cru
    require(math.isfinite(time), "time overflows")
    return {"time": time, "v_peak": vp, "t_acc": t_acc, "t_cruise": t_cru, "t_dec": t_dec,
            "d_acc": (vp - v0) * (vp + v0) / (2.0 * a), "d_cruise": max(d_cru, 0.0),
            "d_dec": (vp - v1) * (vp + v1) / (2.0 * a), "shape": shape}


def trapezoid(inp):
    return _trapezoid(_num(inp, "d"), _num(inp, "v0"), _num(inp, "v1"), _num(inp, "v_max"),
                      _num(inp, "a"))


def _rotation(angle, om, al):
    require(math.isfinite(angle), "angle must be finite")
    require(_pos_or_inf(om), "omega_max must be > 0")
    require(_finite_pos(al), "alpha_max must be finite and > 0")
    return _trapezoid(abs(angle), 0.0, 0.0, om, al)


def rotation(inp):
    p = _rotation(_num(inp, "angle"), _num(inp, "omega_max"), _num(inp, "alpha_max"))
    return {k: p[k] for k in ("time", "v_peak", "t_acc", "t_cruise", "t_dec", "shape")}


def _runs(path):
    require(len(path) >= 1, "empty path")
    for c in path:
        require(isinstance(c, list) and len(c) == 2, "cell")
        require(abs(c[0]) <= 2 ** 25 and abs(c[1]) <= 2 ** 25, "coordinates beyond 2^25")
    runs, joints = [], []
    for k in range(1, len(path)):
        s = (path[k][0] - path[k - 1][0], path[k][1] - path[k - 1][1])
        require(max(abs(s[0]), abs(s[1])) == 1, f"step {k} is not an 8-neighbour step")
        if runs and runs[-1]["dir"] == s:
            runs[-1]["steps"] += 1
            continue
        if runs:
            u = runs[-1]["dir"]
            cross, dot = u[0] * s[1] - u[1] * s[0], u[0] * s[0] + u[1] * s[1]
            angle = math.atan2(abs(cross), dot)
            sense = 1 if cross > 0 else -1 if cross < 0 else 1
            joints.append((angle, round(angle / (math.pi / 4)), sense))
        runs.append({"dir": s, "first_step": k, "steps": 1})
    for r in runs:
        r["length"] = r["steps"] * (SQRT2 if r["dir"][0] and r["dir"][1] else 1.0)
    return runs, joints


def runs(inp):
    rs, js = _runs(inp["path"])
    return {"runs": [{"dir": list(r["dir"]), "first_step": r["first_step"], "steps": r["steps"],
                      "length": r["length"]} for r in rs],
            "turns": len(js), "angles": [j[0] for j in js], "eighths": [j[1] for j in js],
            "senses": [j[2] for j in js]}


def _corner_speeds(d, vmax, acc, vc):
    m = len(d)
    require(m >= 1 and len(vmax) == m and len(acc) == m, "list lengths")
    require(all(_finite_pos(x) for x in d), "lengths")
    require(all(_pos_or_inf(x) for x in vmax), "speed limits")
    require(all(_finite_pos(x) for x in acc), "accelerations")
    require(math.isfinite(vc) and vc >= 0, "corner speed")
    u = [0.0] + [min(vc, vmax[j - 1], vmax[j]) for j in range(1, m)] + [0.0]
    for j in range(1, m):
        u[j] = min(u[j], math.sqrt(u[j - 1] ** 2 + 2.0 * acc[j - 1] * d[j - 1]))
    for j in range(m - 1, 0, -1):
        u[j] = min(u[j], math.sqrt(u[j + 1] ** 2 + 2.0 * acc[j] * d[j]))
    return u


def corner_speeds(inp):
    return {"speeds": [_out(x) for x in _corner_speeds(_nums(inp["lengths"]), _nums(inp["v_max"]),
                                                        _nums(inp["a_max"]), _num(inp, "corner_speed"))]}


def path_time(inp):
    base = inp["base"]
    require(base in ("mecanum", "diff"), "base")  # the C++ raises UsageError (a bad request)
    cell = _num(inp, "cell")
    r, lx, ly = _num(inp, "r", 0.05), _num(inp, "lx", 0.15), _num(inp, "ly", 0.15)
    _geometry(inp, r, lx, ly)
    w = _num(inp, "w_max", (500.0 * (2.0 * math.pi)) / 60.0)
    a = _num(inp, "a_max", 1.0)
    vcap = _num(inp, "v_cap", INF)
    vc = _num(inp, "corner_speed", 0.0)
    b = _num(inp, "half_track", ly)
    ycap = _num(inp, "yaw_rate_cap", INF)
    require(_finite_pos(cell), "cell")
    require(_finite_pos(w) and _finite_pos(a) and _finite_pos(b), "limits")
    require(_pos_or_inf(vcap) and _pos_or_inf(ycap), "caps")
    require(math.isfinite(vc) and vc >= 0, "corner speed")
    rs, js = _runs(inp["path"])
    m = len(rs)
    d, vl, al = [], [], []
    for run in rs:
        d.append(run["length"] * cell)
        if base == "mecanum":
            g = _factor(float(run["dir"][0]), float(run["dir"][1]))
            vl.append(min(vcap, r * w / g))
            al.append(a / g)
        else:
            vl.append(min(vcap, r * w))
            al.append(a)
    if m == 0:
        u = [0.0]
    elif base == "mecanum":
        u = _corner_speeds(d, vl, al, vc)
    else:
        u = [0.0] * (m + 1)
    omega = min(ycap, r * w / b)
    alpha = a / b
    total, run_time, rot_time, out_runs, out_joints = 0.0, 0.0, 0.0, [], []
    for j in range(m):
        p = _trapezoid(d[j], u[j], u[j + 1], vl[j], al[j])
        total += p["time"]
        run_time += p["time"]
        out_runs.append({"distance": d[j], "v_limit": _out(vl[j]), "a_limit": al[j],
                         "v_start": u[j], "v_end": u[j + 1], "v_peak": p["v_peak"], "time": p["time"]})
        if j + 1 < m:
            angle = js[j][0]
            t = _rotation(angle, omega, alpha)["time"] if base == "diff" else 0.0
            total += t
            rot_time += t
            out_joints.append({"angle": angle, "time": t})
    return {"time": total, "distance": math.fsum(d), "turns": len(js), "run_time": run_time,
            "rotate_time": rot_time, "runs": out_runs, "joints": out_joints}


RULES = {
    "mecanum.ik": ik,
    "mecanum.fk": fk,
    "mecanum.residual": residual,
    "mecanum.wheel-limit": wheel_limit,
    "mecanum.saturate": saturate,
    "mecanum.max-speed": max_speed,
    "drive.trapezoid": trapezoid,
    "drive.rotation": rotation,
    "drive.runs": runs,
    "drive.corner-speeds": corner_speeds,
    "drive.path-time": path_time,
}
