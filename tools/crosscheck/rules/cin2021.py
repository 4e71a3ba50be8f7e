"""spec/cin2021-hga-aco.md: HGA-ACO (cin2021 Eq. 16-35, the operators, the planners ga-cin,
aco-cin and hga-aco-cin), replayed from the spec.

Written from spec/cin2021-hga-aco.md and the rules it composes (spec/shi2022.md, spec/shi2022-ga.md
"Initialisation", spec/rng.md, spec/grid.md), not from the C++. The colony is a fresh replay
(pheromone in a dict keyed by ordered cell pairs, default tau_C; the dead-angle table a set);
the GA reuses the crosscheck's own Shi pieces (ga_planners.py: chain repair, initial chains,
common-gene crossover, loop cutting, elite order), which the spec names as shared concepts.
"""
import math

from .common import DomainError, require
from .search import Map, UsageError, allowed, cell
from . import ga_planners as G

ORDER = [(-1, -1), (0, -1), (1, -1), (-1, 0), (1, 0), (-1, 1), (0, 1), (1, 1)]
EPS_DEG = 1e-3


def _path(v):
    if not isinstance(v, list):
        raise UsageError("a path is a list of cells")
    return [cell(c) for c in v]


def _dist(a, b):
    for c in (a, b):
        require(abs(c[0]) <= 2 ** 25 and abs(c[1]) <= 2 ** 25, "coordinates")
    dx, dy = b[0] - a[0], b[1] - a[1]
    return math.sqrt(float(dx * dx + dy * dy))


def _length(p):
    s = 0.0
    for k in range(1, len(p)):
        s += _dist(p[k - 1], p[k])
    return s


def _moves(m, c, pol):
    out = []
    for dx, dy in ORDER:
        q = (c[0] + dx, c[1] + dy)
        if m.inside(q) and allowed(m, c, q, pol):
            out.append(q)
    return out


def _opt(inp, key, options):
    v = inp.get(key, options[0])
    if v not in options:
        raise UsageError(f"unknown {key} {v!r}")
    return v


# ---- Eq. 16-19 ---------------------------------------------------------------------------------


def eq16(inp):
    m = Map(inp["grid"])
    p = _path(inp["path"])
    pol = G._policy(inp)
    if not p:
        return {"safe": False, "reason": "empty"}
    for i, c in enumerate(p):
        if not m.inside(c):
            return {"safe": False, "reason": "out_of_bounds"}
        if not m.free(c):
            return {"safe": False, "reason": "blocked"}
        if i > 0:
            a = p[i - 1]
            if a == c:
                return {"safe": False, "reason": "repeated"}
            if max(abs(a[0] - c[0]), abs(a[1] - c[1])) != 1:
                return {"safe": False, "reason": "not_adjacent"}
            if not allowed(m, a, c, pol):
                return {"safe": False, "reason": "corner_cut"}
    return {"safe": True, "reason": "ok"}


def cosine(a, b, c):
    require(a != b and b != c, "degenerate segment")
    ux, uy, vx, vy = b[0] - a[0], b[1] - a[1], c[0] - b[0], c[1] - b[1]
    dot = ux * vx + uy * vy
    if ux * vy - uy * vx == 0:
        return 1.0 if dot > 0 else -1.0
    return float(dot) / (_dist(a, b) * _dist(b, c))


def eq17(inp):
    p = _path(inp["path"])
    s = 0.0
    for i in range(len(p) - 2):
        s += 1.0 - cosine(p[i], p[i + 1], p[i + 2])
    if len(p) == 2:
        require(p[0] != p[1], "repeat")
    return {"S": s}


def eq18(inp):
    return {"cos": cosine(cell(inp["a"]), cell(inp["b"]), cell(inp["c"]))}


def eq19(inp):
    return {"length": _length(_path(inp["path"]))}


def eq20(inp):
    L = _length(_path(inp["path"]))
    require(math.isfinite(L) and L > 0, "length > 0")
    return {"f1": 1.0 / L}


def _d12(p):
    return [_dist(p[i], p[i + 1]) for i in range(len(p) - 1)], [_dist(p[i], p[i + 2]) for i in range(len(p) - 2)]


def eq21(inp):
    return {"d1": _d12(_path(inp["path"]))[0]}


def eq22(inp):
    return {"d2": _d12(_path(inp["path"]))[1]}


def angle_acos(d1a, d1b, d2):
    require(math.isfinite(d1a) and d1a > 0 and math.isfinite(d1b) and d1b > 0, "d1 > 0")
    require(math.isfinite(d2) and d2 >= 0, "d2 >= 0")
    c = (((d1a * d1a) + (d1b * d1b)) - (d2 * d2)) / ((2.0 * d1a) * d1b)
    c = min(1.0, max(-1.0, c))
    return math.acos(c) * (180.0 / math.pi)


def angle_lookup(a, b, c):
    u = (b[0] - a[0], b[1] - a[1])
    v = (c[0] - b[0], c[1] - b[1])
    for w in (u, v):
        require(max(abs(w[0]), abs(w[1])) == 1, "8-neighbour steps")
    dot = u[0] * v[0] + u[1] * v[1]
    cross = u[0] * v[1] - u[1] * v[0]
    # heading change 0 / 45 / 90 / 135 / 180 -> included angle 180 - change
    if dot > 0:
        change = 0 if cross == 0 else 45
    elif dot == 0:
        change = 90
    else:
        change = 180 if cross == 0 else 135
    return float(180 - change)


def eq23(inp):
    a, b, c = cell(inp["a"]), cell(inp["b"]), cell(inp["c"])
    if _opt(inp, "angle", ("arccos", "lookup")) == "lookup":
        return {"theta": angle_lookup(a, b, c)}
    d1, d2 = _d12([a, b, c])
    return {"theta": angle_acos(d1[0], d1[1], d2[0])}


def _pen(inp):
    p = inp.get("penalties", [5.0, 100.0, 1000.0])
    if not isinstance(p, list) or len(p) != 3:
        raise UsageError("penalties")
    return [float(x) for x in p]


def penalty(theta, pen):
    require(math.isfinite(theta) and 0.0 <= theta <= 180.0 + EPS_DEG, "theta in [0, 180]")
    c135, c90, c45 = pen
    require(all(math.isfinite(x) for x in pen) and 0.0 <= c135 <= c90 <= c45, "penalties ordered")
    if theta >= 180.0 - EPS_DEG:
        return 0.0
    if theta >= 135.0 - EPS_DEG:
        return c135
    if theta >= 90.0 - EPS_DEG:
        return c90
    return c45


def eq24(inp):
    return {"c": penalty(float(inp["theta"]), _pen(inp))}


def f2(p, pen, guard, angle):
    require(len(p) >= 2, "n >= 2")
    penalty(180.0, pen)
    d1, d2 = _d12(p)
    require(all(x > 0 for x in d1), "repeats")
    s = 0.0
    for i in range(len(p) - 2):
        th = angle_acos(d1[i], d1[i + 1], d2[i]) if angle == "arccos" else angle_lookup(p[i], p[i + 1], p[i + 2])
        s += penalty(th, pen)
    return 1.0 / ((1.0 if guard == "one_plus" else 1e-3) + s)


def eq25(inp):
    return {"f2": f2(_path(inp["path"]), _pen(inp), _opt(inp, "f2_guard", ("one_plus", "epsilon")),
                     _opt(inp, "angle", ("arccos", "lookup")))}


def eq26(inp):
    a, b, f1_, f2_ = (float(inp[k]) for k in ("a", "b", "f1", "f2"))
    for x in (a, b, f1_, f2_):
        require(math.isfinite(x) and x >= 0, "finite >= 0")
    f = (a * f1_) + (b * f2_)
    require(math.isfinite(f), "finite")
    return {"f": f}


def eq27(inp):
    w = [float(x) for x in inp["fitness"]]
    require(len(w) >= 1 and all(math.isfinite(x) and x >= 0 for x in w), "weights")
    t = 0.0
    for x in w:
        t += x
    require(math.isfinite(t) and t > 0, "sum > 0")
    return {"p": [x / t for x in w]}


def conversion(rows, Q, form):
    require(math.isfinite(Q) and Q > 0, "Q > 0")
    tau, order = {}, []
    for row in rows:
        require(len(row) >= 2, "rows of >= 2 cells")
        L = _length(row)
        seen = set()
        for r in range(len(row) - 1):
            e = (row[r], row[r + 1])
            require(e[0] != e[1], "repeat")
            if e not in tau:
                tau[e] = 0.0
                order.append(e)
            if e in seen:
                continue
            seen.add(e)
            d = _dist(*e)
            require(L > 0 and d > 0, "L, d > 0")
            if form == "q_over_l":
                v = Q / L
            elif form == "q_d_over_l":
                v = (Q * d) / L
            else:
                v = Q / (L * d)
            tau[e] += v
    return [(e, tau[e]) for e in order]


def eq28(inp):
    rows = [_path(r) for r in inp["rows"]]
    tc = float(inp["tau_C"])
    require(math.isfinite(tc) and tc > 0, "tau_C > 0")
    form = _opt(inp, "conversion_form", ("q_over_l", "q_d_over_l", "q_over_l_d"))
    mode = _opt(inp, "conversion", ("add", "replace"))
    out = []
    for (a, b), t in conversion(rows, float(inp["Q"]), form):
        out.append({"from": [a[0], a[1]], "to": [b[0], b[1]], "tau": tc + t if mode == "add" else t})
    return {"edges": out}


def eq29(inp):
    tau, eta = [float(x) for x in inp["tau"]], [float(x) for x in inp["eta"]]
    al, be = float(inp["alpha"]), float(inp["beta"])
    require(len(tau) >= 1 and len(tau) == len(eta), "sizes")
    require(al >= 0 and be >= 0 and all(x >= 0 and math.isfinite(x) for x in tau + eta), "domain")
    w = [(t if al == 1.0 else t ** al) * (e ** be) for t, e in zip(tau, eta)]
    return {"weights": w, "p": eq27({"fitness": w})["p"]}


def eta_goal_inverse(j, goal):
    return 1.0 / (0.5 if j == goal else _dist(j, goal))


def eq30(inp):
    form = _opt(inp, "eta", ("inverse_distance", "goal_inverse"))
    if form == "inverse_distance":
        i, j = cell(inp["i"]), cell(inp["j"])
        require(i != j, "i != j")
        return {"eta": 1.0 / _dist(i, j)}
    return {"eta": eta_goal_inverse(cell(inp["j"]), cell(inp["goal"]))}


def update(tau, rho, delta):
    require(math.isfinite(tau) and tau >= 0, "tau")
    require(0.0 < rho < 1.0, "rho in (0, 1)")
    require(math.isfinite(delta) and delta >= 0, "delta")
    v = ((1.0 - rho) * tau) + delta
    require(math.isfinite(v), "finite")
    return v


def eq31(inp):
    return {"tau": update(float(inp["tau"]), float(inp["rho"]), float(inp["delta"]))}


def deposit(on_ib, w_ib, L_ib, on_gb, w_gb, L_gb, Q):
    require(math.isfinite(Q) and Q > 0, "Q")
    a = b = 0.0
    if on_ib:
        require(math.isfinite(w_ib) and w_ib >= 0 and math.isfinite(L_ib) and L_ib > 0, "ib")
        a = w_ib * (Q / L_ib)
    if on_gb:
        require(math.isfinite(w_gb) and w_gb >= 0 and math.isfinite(L_gb) and L_gb > 0, "gb")
        b = w_gb * (Q / L_gb)
    return a + b


def eq32(inp):
    return {"delta": deposit(inp["on_ib"], float(inp.get("w_ib", 0.0)), float(inp.get("L_ib", 1.0)),
                             inp["on_gb"], float(inp.get("w_gb", 0.0)), float(inp.get("L_gb", 1.0)),
                             float(inp["Q"]))}


def weights(t, N, norm):
    require(1 <= N <= 10 ** 6 and 0 <= t < N, "0 <= t < N")
    ib, gb = float(N - t), float(t)
    if norm == "normalised":
        ib, gb = ib / N, gb / N
    return ib, gb


def eq33(inp):
    ib, gb = weights(inp["t"], inp["N"], _opt(inp, "weight_norm", ("raw", "normalised")))
    return {"w_ib": ib, "w_gb": gb}


def eq34(inp):
    return {"tau": update(float(inp["tau"]), float(inp["rho"]), 0.0)}


def penal(tau, lam, form):
    require(math.isfinite(lam) and 0.0 < lam < 1.0, "lambda in (0, 1)")
    require(math.isfinite(tau) and tau >= 0, "tau >= 0")
    return lam * tau if form == "lambda" else (1.0 - lam) * tau


def eq35(inp):
    return {"tau": penal(float(inp["tau"]), float(inp["lambda"]), _opt(inp, "lambda_form", ("lambda", "one_minus")))}


# ---- operators ----------------------------------------------------------------------------------


def cut_cross(m, a, b, k, j, pol, rounding="floor", reject="blocked", illegal="reject"):
    require(len(a) >= 3 and len(b) >= 3 and 1 <= k <= len(a) - 2 and 1 <= j <= len(b) - 2, "interior cuts")
    ok1, p1, _ = G.repair(m, a[: k + 1] + b[j + 1:], pol, rounding, reject, illegal)
    if not ok1:
        return False, [], []
    ok2, p2, _ = G.repair(m, b[: j + 1] + a[k + 1:], pol, rounding, reject, illegal)
    if not ok2:
        return False, [], []
    return True, p1, p2


def op_crossover(inp):
    m = Map(inp["grid"])
    ok, p1, p2 = cut_cross(m, _path(inp["a"]), _path(inp["b"]), inp["k"], inp["j"], G._policy(inp))
    return {"feasible": ok, "first": G._out_path(p1), "second": G._out_path(p2)}


def walk(m, frm, to, avoid, pol, mode, st, backtrack=False):
    require(m.free(frm) and m.free(to), "end cells free")
    closed = set(avoid)
    closed.discard(to)
    closed.add(frm)
    w = [frm]
    while w[-1] != to:
        cand = [q for q in _moves(m, w[-1], pol) if q not in closed]
        if not cand:
            if not backtrack:
                return None
            w.pop()
            if not w:
                return None
            continue
        if mode == "random":
            q = cand[G.r_index(st.u(), len(cand))]
        else:
            q = min(cand, key=lambda c: ((c[0] - to[0]) ** 2 + (c[1] - to[1]) ** 2, cand.index(c)))
        w.append(q)
        closed.add(q)
    return w


def mutants(m, p, k, pol, mode, st):
    n = len(p)
    require(n >= 3 and 1 <= k <= n - 2, "interior k")
    wa = walk(m, p[k], p[0], p[k + 1:], pol, mode, st)
    A = (wa[::-1] + p[k + 1:]) if wa is not None else []
    wb = walk(m, p[n - 1], p[k], p[:k], pol, mode, st)
    B = (p[:k] + wb[::-1]) if wb is not None else []
    return A, B


def op_mutation(inp):
    m = Map(inp["grid"])
    st = G.Stream(inp.get("seed", 1))
    A, B = mutants(m, _path(inp["path"]), inp["k"], G._policy(inp), _opt(inp, "research", ("greedy", "random")), st)
    return {"a": G._out_path(A), "b": G._out_path(B), "draws": st.drawn}


# ---- planners -----------------------------------------------------------------------------------

GA_DEF = dict(G.GA_DEFAULTS, population=50, generations=50, fitness="cin", a=1.0, b=0.1, c=0.0, pc=0.8,
              pm=0.2, init="walk", crossover="cin", crossover_keep="best_two_fitness", mutation="multidirectional",
              research="greedy", loops="cut", result_by="fitness", corner_penalties=[5.0, 100.0, 1000.0],
              f2_guard="one_plus", angle="arccos",
              # cin2021.plan.ga pins the chain-repair readings it was specified with (not the Shi
              # planners' defaults shift / repair / inverse_total_plus_one of issue 11)
              init_reject="blocked", illegal_step="reject", smoothness="per_node")
ACO_DEF = {"ants": 30, "iterations": 50, "alpha": 1.0, "beta": 2.0, "Q": 1.0, "tau0": 0.1, "rho": 0.3,
           "eta": "inverse_distance", "edge_sense": "directed", "dead_end": "dead_angle",
           "weight_norm": "raw", "tau_bounds": "off", "tau_lower": 0.001, "tau_upper": 100.0,
           "lambda": 0.5, "lambda_form": "lambda", "dead_angle": "exclude",
           "dead_angle_record": "cul_de_sac"}
HGA_OWN = {"conversion_form": "q_over_l", "conversion": "add", "elite_share": 0.2}


class Ind:
    def __init__(self, path, cfg):
        self.path = path
        self.length = _length(path)
        f1 = 1.0 / self.length
        f2_ = f2(path, [float(x) for x in cfg["corner_penalties"]], cfg["f2_guard"], cfg["angle"])
        self.fit = (cfg["a"] * f1) + (cfg["b"] * f2_)


def _cfg(inp, defaults):
    cfg = dict(defaults)
    for k, v in inp.items():
        if k in ("grid", "start", "goal", "seed", "policy"):
            continue
        if k not in cfg:
            raise UsageError(f"unknown parameter {k!r}")
        cfg[k] = v
    return cfg


def ga_run(m, S, E, pol, cfg, st):
    """(best, best_gen, bests, final population) or None when initialisation fails."""
    for k, v in (("fitness", "cin"), ("crossover", "cin"), ("crossover_keep", "best_two_fitness"),
                 ("mutation", "multidirectional"), ("result_by", "fitness")):
        if cfg[k] != v:
            raise UsageError(f"the crosscheck replays {k} = {v} only")
    if cfg["init"] == "walk":
        paths = []
        for _ in range(cfg["population"]):
            w = walk(m, S, E, [], pol, "random", st, backtrack=True)
            if w is None:
                return None
            paths.append(w)
    else:
        ok, _, paths, _ = G.init_paths(m, S, E, pol, cfg, st, cfg["population"])
        if not ok:
            return None
    pop = [Ind(p, cfg) for p in paths]
    best, best_gen = pop[0], 0
    for q in pop:
        if q.fit > best.fit:
            best = q
    M = len(pop)
    bests = []
    for i in range(1, cfg["generations"] + 1):
        fit = [q.fit for q in pop]
        pool = [pop[G.r_roulette(fit, st.u())] for _ in range(M)]
        for q in range(M // 2):
            A, B = pool[2 * q], pool[2 * q + 1]
            if not st.u() < cfg["pc"]:
                continue
            pts = G.common_points(A.path, B.path)
            if pts:
                k, j = pts[G.r_index(st.u(), len(pts))]
                p1, p2 = G.cross(A.path, B.path, k, j)
            else:
                if len(A.path) < 3 or len(B.path) < 3:
                    continue
                k = 1 + G.r_index(st.u(), len(A.path) - 2)
                j = 1 + G.r_index(st.u(), len(B.path) - 2)
                ok, p1, p2 = cut_cross(m, A.path, B.path, k, j, pol, cfg["mid_rounding"], cfg["init_reject"],
                                       cfg["illegal_step"])
                if not ok:
                    continue
            if cfg["loops"] == "cut":
                p1, p2 = G.cut_loops(p1), G.cut_loops(p2)
            four = sorted([A, B, Ind(p1, cfg), Ind(p2, cfg)], key=lambda t: -t.fit)  # stable
            pool[2 * q], pool[2 * q + 1] = four[0], four[1]
        for a in range(M):
            if not st.u() < cfg["pm"]:
                continue
            p = pool[a].path
            if len(p) < 3:
                continue
            k = 1 + G.r_index(st.u(), len(p) - 2)
            mA, mB = mutants(m, p, k, pol, cfg["research"], st)
            cands = [Ind(x, cfg) for x in (mA, mB) if x]
            if not cands:
                continue
            pool[a] = cands[1] if len(cands) == 2 and cands[1].fit > cands[0].fit else cands[0]
        pop = pool
        for q in pop:
            if q.fit > best.fit:
                best, best_gen = q, i
        bests.append(best.length)
    return best, best_gen, bests, pop


def colony(m, S, E, pol, p, st, init_tau):
    N = p["iterations"]
    tau = dict(init_tau)
    tc = p["tau0"]
    T = lambda e: tau.get(e, tc)  # noqa: E731
    table = []
    table_set = set()
    gb, L_gb, gb_it = None, math.inf, 0
    bests = []
    exclude = p["dead_angle"] == "exclude"
    for t in range(1, N + 1):
        tours = []
        for _a in range(p["ants"]):
            path, V = [S], {S}
            alive = True
            while path[-1] != E:
                c = path[-1]
                cand = [q for q in _moves(m, c, pol) if q not in V and not (exclude and q in table_set)]
                if not cand:
                    rec = len(path) >= 2
                    if rec and p["dead_angle_record"] == "cul_de_sac":
                        rec = sum(1 for n in _moves(m, c, pol) if n not in table_set) <= 1
                    if rec:
                        if c not in table_set:
                            table_set.add(c)
                            table.append(c)
                        for n in _moves(m, c, pol):
                            tau[(n, c)] = penal(T((n, c)), p["lambda"], p["lambda_form"])
                    path.pop()
                    if not path:
                        alive = False
                        break
                    continue
                w = []
                for q in cand:
                    eta = 1.0 / _dist(c, q) if p["eta"] == "inverse_distance" else eta_goal_inverse(q, E)
                    tt = T((c, q))
                    w.append((tt if p["alpha"] == 1.0 else tt ** p["alpha"]) * (eta ** p["beta"]))
                q = cand[G.r_roulette(w, st.u())]
                path.append(q)
                V.add(q)
            tours.append(path if alive else None)
        ib, L_ib = None, math.inf
        for path in tours:
            if path is not None:
                L = _length(path)
                if L < L_ib:
                    ib, L_ib = path, L
        if ib is not None and L_ib < L_gb:
            gb, L_gb, gb_it = ib, L_ib, t
        w_ib, w_gb = weights(t - 1, N, p["weight_norm"])
        on = {}
        if ib is not None:
            for r in range(len(ib) - 1):
                on.setdefault((ib[r], ib[r + 1]), set()).add("ib")
        if gb is not None:
            for r in range(len(gb) - 1):
                on.setdefault((gb[r], gb[r + 1]), set()).add("gb")
        # every edge evaporates (Eq. 34); an edge never touched stays below tau_C forever, so
        # only the touched ones and tau_C itself are tracked
        for e in list(tau.keys()) + [e for e in on if e not in tau]:
            d = 0.0
            if e in on:
                d = deposit("ib" in on[e], w_ib, L_ib, "gb" in on[e], w_gb, L_gb, p["Q"])
            v = update(T(e), p["rho"], d)
            if p["tau_bounds"] == "on":
                v = min(max(v, p["tau_lower"]), p["tau_upper"])
            tau[e] = v
        tc_new = update(tc, p["rho"], 0.0)
        if p["tau_bounds"] == "on":
            tc_new = min(max(tc_new, p["tau_lower"]), p["tau_upper"])
        tc = tc_new
        bests.append(L_gb)
    return gb, L_gb, gb_it, bests, table


def _setup(inp):
    m = Map(inp["grid"])
    S, E = cell(inp["start"]), cell(inp["goal"])
    pol = G._policy(inp)
    seed = inp.get("seed", 1)
    require(m.inside(S) and m.inside(E) and m.free(S) and m.free(E), "start/goal free")
    return m, S, E, pol, G.Stream(seed)


def _out(found, path, L, iters, bests, it, table, st):
    return {"found": found, "path": G._out_path(path), "length": L if found else 0.0, "iterations": iters,
            "best_per_iteration": [G._num_out(x) for x in bests], "best_iteration": it,
            "dead_angle_table": G._out_path(table), "draws": st.drawn}


def plan_ga(inp):
    m, S, E, pol, st = _setup(inp)
    cfg = _cfg(inp, GA_DEF)
    if S == E:
        return _out(True, [S], 0.0, 0, [], 0, [], st)
    r = ga_run(m, S, E, pol, cfg, st)
    if r is None:
        return _out(False, [], 0.0, 0, [], 0, [], st)
    best, bg, bests, _ = r
    return _out(True, best.path, best.length, cfg["generations"], bests, bg, [], st)


def plan_aco(inp):
    m, S, E, pol, st = _setup(inp)
    p = _cfg(inp, ACO_DEF)
    require(0 < p["rho"] < 1 and p["tau0"] > 0 and p["Q"] > 0, "domain")
    if S == E:
        return _out(True, [S], 0.0, 0, [], 0, [], st)
    gb, L, it, bests, table = colony(m, S, E, pol, p, st, {})
    return _out(gb is not None, gb or [], L, p["iterations"], bests, it if gb else 0, table, st)


def plan_hga(inp):
    m, S, E, pol, st = _setup(inp)
    own = {k: inp[k] for k in HGA_OWN if k in inp}
    hp = dict(HGA_OWN, **own)
    aco_in = {k[4:]: v for k, v in inp.items() if k.startswith("aco_")}
    ga_in = {k: v for k, v in inp.items() if not k.startswith("aco_") and k not in HGA_OWN}
    cfg = _cfg(ga_in, GA_DEF)
    p = _cfg(aco_in, ACO_DEF)
    if S == E:
        return _out(True, [S], 0.0, 0, [], 0, [], st)
    r = ga_run(m, S, E, pol, cfg, st)
    if r is None:
        return _out(False, [], 0.0, 0, [], 0, [], st)
    _, _, ga_bests, final = r
    count = G.elite_count(len(final), hp["elite_share"])
    rows = [final[k].path for k in G.elite([q.fit for q in final], count)]
    init = {}
    for e, t in conversion(rows, p["Q"], hp["conversion_form"]):
        init[e] = p["tau0"] + t if hp["conversion"] == "add" else t
    gb, L, it, bests, table = colony(m, S, E, pol, p, st, init)
    return _out(gb is not None, gb or [], L, cfg["generations"] + p["iterations"], ga_bests + bests,
                it if gb else 0, table, st)


RULES = {
    "cin2021.eq16": eq16, "cin2021.eq17": eq17, "cin2021.eq18": eq18, "cin2021.eq19": eq19,
    "cin2021.eq20": eq20, "cin2021.eq21": eq21, "cin2021.eq22": eq22, "cin2021.eq23": eq23,
    "cin2021.eq24": eq24, "cin2021.eq25": eq25, "cin2021.eq26": eq26, "cin2021.eq27": eq27,
    "cin2021.eq28": eq28, "cin2021.eq29": eq29, "cin2021.eq30": eq30, "cin2021.eq31": eq31,
    "cin2021.eq32": eq32, "cin2021.eq33": eq33, "cin2021.eq34": eq34, "cin2021.eq35": eq35,
    "cin2021.op.crossover": op_crossover, "cin2021.op.mutation": op_mutation,
    "cin2021.plan.ga": plan_ga, "cin2021.plan.aco": plan_aco, "cin2021.plan.hga-aco": plan_hga,
}
