"""spec/shi2022-ga.md: the GA operators and the GA / hybrid planners, replayed from the spec.

Written from spec/shi2022-ga.md (and the rules it composes: spec/shi2022.md Eq. 8-20,
spec/rng.md, spec/grid.md), not from the C++. The random stream is this crosscheck's own pure
Python MT19937 (rng.py); the ant colony of the hybrids is the independent replay of
spec/shi2022-aco.md in aco_planners.py (when present).
"""
import math

from .common import DomainError, require
from .rng import MT19937
from .search import Map, UsageError, allowed, cell

SQRT2 = math.sqrt(2.0)
HALF_PI = math.pi / 2.0
POLICIES = ("never", "strict", "one", "always")


# ---- draws (spec/rng.md) ----------------------------------------------------------------------


class Stream:
    def __init__(self, seed):
        self.mt = MT19937(seed)
        self.drawn = 0

    def u(self):
        self.drawn += 1
        return self.mt.genrand_res53()


def r_index(u, n):
    require(n >= 1, "index over an empty set")
    return min(math.floor(u * n), n - 1)


def r_roulette(w, u):
    total = 0.0
    for x in w:
        total += x
    require(total > 0 and math.isfinite(total), "roulette weights")
    target = u * total
    c = 0.0
    for k, x in enumerate(w):
        c += x
        if x > 0 and c >= target:
            return k
    raise AssertionError("unreachable")


# ---- inputs ---------------------------------------------------------------------------------


def _policy(inp, default="strict"):
    p = inp.get("policy", default)
    if p not in POLICIES:
        raise UsageError(f"unknown policy {p!r}")
    return p


def _path(v):
    if not isinstance(v, list):
        raise UsageError("a path is a list of cells")
    return [cell(c) for c in v]


def _opt(inp, key, options):
    v = inp.get(key, options[0])
    if v not in options:
        raise UsageError(f"unknown {key} {v!r}")
    return v


def _out_path(p):
    return [[c[0], c[1]] for c in p]


# ---- operators ------------------------------------------------------------------------------


def chebyshev(a, b):
    return max(abs(a[0] - b[0]), abs(a[1] - b[1]))


def half(s, rounding):
    if rounding == "floor":
        return s // 2
    if rounding == "ceil":
        return (s + 1) // 2
    # half_even: ties (s odd) to the even neighbour
    if s % 2 == 0:
        return s // 2
    lo = s // 2
    return lo if lo % 2 == 0 else lo + 1


def repair(m, genes, pol, rounding="floor", reject="shift", illegal="repair"):
    """r[shi2022.op.init]: (feasible, path, reason)."""
    for c in genes:
        if not m.free(c):
            return False, [], "blocked_gene"
    p = list(genes)
    k = 0
    shifts = 0
    while k + 1 < len(p):
        a, b = p[k], p[k + 1]
        d = chebyshev(a, b)
        if d == 0:
            del p[k + 1]
        elif d == 1:
            if allowed(m, a, b, pol):
                k += 1
                continue
            # illegal_step = repair: a disallowed diagonal is "not continuous"; the orthogonal
            # cell (b.x, a.y), else (a.x, b.y), goes between, if free.
            if illegal != "repair":
                return False, [], "illegal_step"
            mid = None
            for q in ((b[0], a[1]), (a[0], b[1])):
                if q != a and q != b and m.free(q):
                    mid = q
                    break
            if mid is None:
                return False, [], "illegal_step"
            p.insert(k + 1, mid)
        else:
            mid = (half(a[0] + b[0], rounding), half(a[1] + b[1], rounding))
            if not m.free(mid) and reject == "shift":
                for dx, dy in ((-1, 0), (1, 0), (0, 1), (0, -1)):
                    q = (mid[0] + dx, mid[1] + dy)
                    if m.free(q) and q != a and q != b:
                        mid = q
                        shifts += 1
                        break
                else:
                    return False, [], "blocked_insert"
                if shifts > m.w * m.h:
                    return False, [], "insert_limit"
            if not m.free(mid):
                return False, [], "blocked_insert"
            if reject == "near_obstacle":
                for dy in (-1, 0, 1):
                    for dx in (-1, 0, 1):
                        q = (mid[0] + dx, mid[1] + dy)
                        if (dx or dy) and m.inside(q) and not m.free(q):
                            return False, [], "near_obstacle"
            p.insert(k + 1, mid)
    return True, p, "ok"


def common_points(a, b):
    """r[shi2022.op.crossover]: (k, j) per interior k of a whose cell is an interior cell of b."""
    first = {}
    for j in range(1, len(b) - 1):
        first.setdefault(b[j], j)
    return [(k, first[a[k]]) for k in range(1, len(a) - 1) if a[k] in first]


def script_points(a, b):
    """r[classic.plan.ga]: interior k of a whose cell is anywhere in b, j its first index in b."""
    first = {}
    for j, c in enumerate(b):
        first.setdefault(c, j)
    return [(k, first[a[k]]) for k in range(1, len(a) - 1) if a[k] in first]


def round_choice(u, n):
    """r[classic.plan.ga]: MATLAB round(u * (n - 1)), half away from zero."""
    require(n >= 1 and 0.0 <= u < 1.0, "round_choice")
    x = u * float(n - 1)
    r = math.floor(x)
    if x - r >= 0.5:  # x - floor(x) is exact; a half rounds away from zero (x >= 0)
        r += 1
    return min(int(r), n - 1)


def cross(a, b, k, j):
    return a[: k + 1] + b[j + 1:], b[: j + 1] + a[k + 1:]


def candidates(m, p, k, pol):
    """r[shi2022.op.mutation]."""
    prev, nxt = p[k - 1], p[k + 1]
    out = []
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            c = (prev[0] + dx, prev[1] + dy)
            if (dx or dy) and c != p[k] and c != nxt and allowed(m, prev, c, pol) and allowed(m, c, nxt, pol):
                out.append(c)
    return out


def delete(m, path, pol):
    """r[shi2022.op.deletion]."""
    p = list(path)
    i = 1
    while i <= len(p) - 2:
        if allowed(m, p[i - 1], p[i + 1], pol):
            del p[i]
            i = max(1, i - 1)
        else:
            i += 1
    return p


def cut_loops(path):
    """r[shi2022.op.loops]."""
    out, pos = [], {}
    for c in path:
        if c in pos:
            q = pos[c]
            for d in out[q + 1:]:
                del pos[d]
            del out[q + 1:]
        else:
            pos[c] = len(out)
            out.append(c)
    return out


def elite(fit, count):
    """r[shi2022.op.elite]: indices of the `count` largest, ties by index."""
    require(count <= len(fit), "count > n")
    require(all(math.isfinite(f) for f in fit), "finite fitness")
    return sorted(range(len(fit)), key=lambda i: (-fit[i], i))[:count]


def elite_count(n, frac):
    require(math.isfinite(frac) and 0.0 < frac <= 1.0, "fraction in (0, 1]")
    if n == 0:
        return 0
    return min(max(math.ceil(frac * n), 1), n)


# ---- fitness (spec/shi2022.md Eq. 10, 14-18) ------------------------------------------------


def length(p):
    s = 0.0
    for k in range(1, len(p)):
        dx, dy = p[k][0] - p[k - 1][0], p[k][1] - p[k - 1][1]
        s += math.sqrt(dx * dx + dy * dy)
    return s


def band(a, b, c):
    ux, uy, vx, vy = b[0] - a[0], b[1] - a[1], c[0] - b[0], c[1] - b[1]
    dot, cr = ux * vx + uy * vy, ux * vy - uy * vx
    if dot < 0:
        return 3
    if dot == 0:
        return 2
    if cr == 0:
        return 0
    return 1 if abs(cr) <= dot else 2


def fit2(p, cfg):
    P = [1.0] + [float(x) for x in cfg["penalties"]]
    reading = cfg["smoothness"]
    s, turns = 0.0, 0
    for k in range(1, len(p) - 1):
        bd = band(p[k - 1], p[k], p[k + 1])
        turns += bd != 0
        if reading == "per_node":
            s += 1.0 / P[bd]
        elif bd and reading == "per_turn":
            s += 1.0 / P[bd]
        elif bd and reading == "angle_times_penalty":
            ux, uy = p[k][0] - p[k - 1][0], p[k][1] - p[k - 1][1]
            vx, vy = p[k + 1][0] - p[k][0], p[k + 1][1] - p[k][1]
            s += 1.0 / (P[bd] * math.atan2(float(abs(ux * vy - uy * vx)), float(ux * vx + uy * vy)))
        elif bd and reading in ("inverse_total", "inverse_total_plus_one"):
            s += P[bd]
    if reading == "inverse_total":
        require(turns > 0, "inverse_total without turns")
        return 1.0 / s
    if reading == "inverse_total_plus_one":
        return 1.0 / (1.0 + s)
    return s


def fit3(m, p, cfg):
    n = len(p)
    idx = {"all_but_goal": range(0, n - 1), "all": range(0, n), "interior": range(1, n - 1)}[cfg["safety_nodes"]]
    hazards = []
    for k in idx:
        x, y = p[k]
        s = 0
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                if dx or dy:
                    q = (x + dx, y + dy)
                    if m.inside(q):
                        s += not m.free(q)
                    elif cfg["outside"] == "blocked":
                        s += 1
        hazards.append(s if cfg["safety_count"] == "count" else (1 if s > 0 else 0))
    if cfg["safety_aggregate"] == "inverse_total_plus_one":
        return 1.0 / (1 + sum(hazards))
    total = 0.0
    for v in hazards:
        S = 1 + v if cfg["safe_node"] == "one" else v
        if S:
            total += 1.0 / S
    if cfg["safety_aggregate"] == "mean":
        return total / len(hazards) if hazards else 0.0
    return total


def fitness(m, p, cfg):
    L = length(p)
    require(L > 0, "no fitness for one node")
    f1 = 1.0 / L
    if cfg["fitness"] == "inverse_length":
        return f1
    return ((cfg["a"] * f1) + (cfg["b"] * fit2(p, cfg))) + (cfg["c"] * fit3(m, p, cfg))


class Ind:
    __slots__ = ("path", "length", "fit", "origin", "born")

    def __init__(self, m, path, cfg, origin, born):
        self.path = path
        self.length = length(path)
        self.fit = fitness(m, path, cfg)
        self.origin = origin
        self.born = born


# ---- parameters -----------------------------------------------------------------------------

GA_DEFAULTS = {
    "population": 200, "generations": 50, "fitness": "inverse_length", "a": 5.0, "b": 4.0, "c": 1.0,
    "smoothness": "inverse_total_plus_one", "penalties": [5.0, 100.0, 1000.0],
    "safety_aggregate": "inverse_total_plus_one", "safety_count": "count", "safe_node": "one", "safety_nodes": "all_but_goal", "outside": "free",
    "ga_probabilities": "fixed", "pc": 0.8, "pm": 0.1, "pm_max": 0.3, "pc_reading": "printed",
    "pm_reading": "printed", "pm_at_zero": "binary64", "ga_i_origin": 1, "duplicate_gene": "drop",
    "mid_rounding": "floor", "init_reject": "shift", "init_attempts": 100000,
    "illegal_step": "repair", "crossover_keep": "children", "loops": "keep", "result_by": "fitness",
}
GA_DEFAULTS.update({"init_retry": "per_individual", "selection": "independent",
                    "crossover_points": "interior", "mutation": "point", "mutation_attempts": 100000})
IGA = dict(GA_DEFAULTS, fitness="weighted", ga_probabilities="adaptive", loops="cut")
# spec/classic.md r[classic.plan.ga]: the classic MATLAB GA script's values.
CLASSIC = dict(GA_DEFAULTS, population=200, generations=50, pc=0.8, pm=0.2, fitness="weighted",
               a=1.0, b=1.0, c=0.0, smoothness="inverse_total", penalties=[3.0, 15.0, 20.0],
               init_reject="shift", init_retry="none", selection="sorted",
               crossover_points="script", mutation="segment")
PLANNER_DEFAULTS = {
    "ga": GA_DEFAULTS,
    "iga-shi": IGA,
    "iga-shi-nomax": dict(IGA, pm_max=1.0),
    "ga-classic": CLASSIC,
}


def _config(inp, defaults, extra=()):
    cfg = dict(defaults)
    for k, v in inp.items():
        if k in ("grid", "start", "goal", "seed", "policy", "algo"):
            continue
        if k not in cfg and k not in extra:
            raise UsageError(f"unknown parameter {k!r}")
        cfg[k] = v
    require(2 <= cfg["population"] <= 10 ** 6, "population")
    require(1 <= cfg["generations"] <= 10 ** 6, "generations")
    require(0.0 <= cfg["pc"] <= 1.0 and 0.0 <= cfg["pm"] <= 1.0, "pc, pm in [0, 1]")
    require(0.0 < cfg["pm_max"] <= 1.0, "pm_max in (0, 1]")
    require(cfg["init_attempts"] >= 1, "init_attempts")
    return cfg


# ---- the GA (r[shi2022.plan.ga], r[shi2022.plan.iga]) ---------------------------------------


def init_paths(m, S, E, pol, cfg, st, count):
    """Step 2 of shi2022.plan.ga: (ok, failure, paths, chains)."""
    step = 1 if E[1] > S[1] else -1
    rows = list(range(S[1] + step, E[1], step)) if E[1] != S[1] else []
    F = []
    for y in rows:
        xs = [x for x in range(m.w) if m.free((x, y))]
        if not xs:
            return False, "row_blocked", [], 0
        F.append(xs)
    paths, chains = [], 0
    attempts = 1 if cfg["init_retry"] == "none" else cfg["init_attempts"]
    for _ in range(count):
        got = None
        for _attempt in range(attempts):
            genes = [S]
            for y, xs in zip(rows, F):
                genes.append((xs[r_index(st.u(), len(xs))], y))
            genes.append(E)
            chains += 1
            ok, p, _ = repair(m, genes, pol, cfg["mid_rounding"], cfg["init_reject"],
                              cfg["illegal_step"])
            if ok:
                got = p
                break
        if got is None:
            if cfg["init_retry"] == "none":
                continue  # the classic script drops a rejected chain
            return False, "init_attempts_exhausted", paths, chains
        paths.append(got)
    if not paths:
        return False, "init_all_rejected", paths, chains
    return True, "", paths, chains


def better(x, y, by):
    return x.fit > y.fit if by == "fitness" else x.length < y.length


def probabilities(cfg, i):
    if cfg["ga_probabilities"] == "fixed":
        return cfg["pc"], cfg["pm"]
    G = cfg["generations"]
    ii = i if cfg["ga_i_origin"] == 1 else i - 1
    sc = cfg["pc"] if cfg["pc_reading"] == "scaled" else 1.0
    pc = sc * math.cos(HALF_PI * (float(ii) / float(G + ii)))
    sm = cfg["pm"] if cfg["pm_reading"] == "scaled" else 1.0
    if ii == 0 and cfg["pm_at_zero"] == "exact_zero":
        mm = 0.0
    else:
        mm = sm * math.cos(HALF_PI * (float(G - ii) / float(G + ii)))
    return pc, (mm if mm < cfg["pm_max"] else cfg["pm_max"])


def evolve(m, pol, cfg, st, pop, elitist=False):
    best, best_gen = pop[0], 0
    for ind in pop:
        if better(ind, best, cfg["result_by"]):
            best = ind
    S = len(pop)
    bests, means = [], []
    for i in range(1, cfg["generations"] + 1):
        pc, pm = probabilities(cfg, i)
        f = [q.fit for q in pop]
        if cfg["selection"] == "sorted":
            us = sorted(st.u() for _ in range(S))
            pool = [pop[r_roulette(f, u)] for u in us]
        else:
            pool = [pop[r_roulette(f, st.u())] for _ in range(S)]
        for q in range(S // 2):
            A, B = pool[2 * q], pool[2 * q + 1]
            if not st.u() < pc:
                continue
            if cfg["crossover_points"] == "script":
                pts = script_points(A.path, B.path)
                if not pts:
                    continue
                k, j = pts[round_choice(st.u(), len(pts))]
            else:
                pts = common_points(A.path, B.path)
                if not pts:
                    continue
                k, j = pts[r_index(st.u(), len(pts))]
            p1, p2 = cross(A.path, B.path, k, j)
            if cfg["loops"] == "cut":
                p1, p2 = cut_loops(p1), cut_loops(p2)
            c1, c2 = Ind(m, p1, cfg, "crossover", i), Ind(m, p2, cfg, "crossover", i)
            if cfg["crossover_keep"] == "children":
                pool[2 * q], pool[2 * q + 1] = c1, c2
            else:
                four = sorted([A, B, c1, c2], key=lambda t: t.length)  # stable
                pool[2 * q], pool[2 * q + 1] = four[0], four[1]
        if elitist:
            merged = pop + pool
            pool = [merged[t] for t in elite([q.fit for q in merged], S)]
        for a in range(S):
            if not st.u() < pm:
                continue
            p = pool[a].path
            if len(p) < 3:
                continue
            if cfg["mutation"] == "segment":
                for _t in range(cfg["mutation_attempts"]):
                    k1 = 1 + round_choice(st.u(), len(p) - 2)
                    k2 = 1 + round_choice(st.u(), len(p) - 2)
                    lo, hi = min(k1, k2), max(k1, k2)
                    ok, sl, _ = repair(m, [p[lo - 1], p[hi + 1]], pol, cfg["mid_rounding"],
                                       cfg["init_reject"], cfg["illegal_step"])
                    if not ok:
                        continue
                    if len(sl) >= 2:
                        np_ = p[:lo] + sl[1:-1] + p[hi + 1:]
                    else:  # both ends the same cell: drop the loop and one copy
                        np_ = p[:lo] + p[hi + 2:]
                    if cfg["loops"] == "cut":
                        np_ = cut_loops(np_)
                    pool[a] = Ind(m, np_, cfg, "mutation", i)
                    break
                continue
            k = 1 + r_index(st.u(), len(p) - 2)
            cands = candidates(m, p, k, pol)
            if not cands:
                continue
            np_ = list(p)
            np_[k] = cands[r_index(st.u(), len(cands))]
            if cfg["loops"] == "cut":
                np_ = cut_loops(np_)
            pool[a] = Ind(m, np_, cfg, "mutation", i)
        pop = pool
        s = 0.0
        for ind in pop:
            if better(ind, best, cfg["result_by"]):
                best, best_gen = ind, i
            s += ind.length
        bests.append(best.length)
        means.append(s / S)
    return best, best_gen, bests, means


def _num_out(v):
    if isinstance(v, float) and not math.isfinite(v):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")
    return v


def _setup(inp, default_policy="strict"):
    m = Map(inp["grid"])
    S, E = cell(inp["start"]), cell(inp["goal"])
    pol = _policy(inp, default_policy)
    seed = inp["seed"]
    require(isinstance(seed, int) and 0 <= seed <= 0xFFFFFFFF, "seed")
    require(m.inside(S) and m.inside(E), "start/goal outside the grid")
    require(m.free(S) and m.free(E), "start/goal blocked")
    return m, S, E, pol, seed


def _trivial(S):
    return {"found": True, "path": [[S[0], S[1]]], "length": 0.0, "iterations": 0,
            "best_per_iteration": [], "mean_per_iteration": [], "draws": 0}


def plan_ga(inp, default_algo="ga", algos=("ga",)):
    algo = inp.get("algo", default_algo)
    if algo not in algos:
        raise UsageError("algo not covered")
    cfg = _config(inp, PLANNER_DEFAULTS[algo])
    m, S, E, pol, seed = _setup(inp, "always" if algo == "ga-classic" else "strict")
    if S == E:
        return dict(_trivial(S), best_generation=0, best_origin="init", init_chains=0)
    st = Stream(seed)
    ok, failure, paths, chains = init_paths(m, S, E, pol, cfg, st, cfg["population"])
    if not ok:
        return {"found": False, "path": [], "length": 0.0, "iterations": 0, "best_per_iteration": [],
                "mean_per_iteration": [], "failure": failure, "draws": st.drawn, "init_chains": chains,
                "population_size": 0, "init_built": len(paths),
                "init_exhausted": failure == "init_attempts_exhausted"}
    pop = [Ind(m, p, cfg, "init", 0) for p in paths]
    best, bg, bests, means = evolve(m, pol, cfg, st, pop)
    return {"found": True, "path": _out_path(best.path), "length": best.length,
            "iterations": cfg["generations"], "best_per_iteration": bests, "mean_per_iteration": means,
            "best_generation": bg, "best_origin": best.origin, "draws": st.drawn, "init_chains": chains,
            "population_size": len(pop), "init_built": len(paths), "init_exhausted": False}


def plan_iga(inp):
    return plan_ga(inp, "iga-shi", ("iga-shi", "iga-shi-nomax"))


def plan_ga_classic(inp):
    return plan_ga(inp, "ga-classic", ("ga-classic",))


# ---- the hybrids (r[shi2022.plan.hybrid], r[shi2022.plan.iha]) ------------------------------

# The colony phase of the hybrids: a replay of spec/shi2022-aco.md (shi2022.plan.aco and
# shi2022.plan.iaco) written from that spec for this module, so that the hybrids' crosscheck does
# not depend on another module's internals. It returns what the hybrids need: the curves and the
# distinct surviving-ant paths in order of first appearance.

ACO_DEFAULTS = {
    "aco": {"ants": 50, "iterations": 100, "alpha": 1.0, "beta": 7.0, "Q": 1.0, "tau0": 8.0,
            "eta": "inverse_distance", "edge_sense": "directed", "dead_end": "die", "rho": 0.9},
    "iaco-shi": {"ants": 50, "iterations": 100, "alpha": 1.0, "beta": 7.0, "Q": 1.0, "tau0": 8.0,
                 "eta": "goal_directed", "edge_sense": "directed", "dead_end": "die",
                 "rho_initial": 0.9, "rho_min": 0.1, "rho_reading": "factor", "rho_t_origin": 1},
}
SLOTS = [(-1, -1), (0, -1), (1, -1), (-1, 0), (1, 0), (-1, 1), (0, 1), (1, 1)]


def _dist(a, b):
    dx, dy = a[0] - b[0], a[1] - b[1]
    return math.sqrt(dx * dx + dy * dy)


def _adaptive_rho(rho, t, T, rho_min, reading):
    a = float(T) / float(T + t)
    b = 1.0 / math.exp(1.0 - rho)
    if reading == "factor":
        v = (a * b) * rho
        return v if v > rho_min else rho_min
    v = a * b
    if reading == "condition":
        return v if rho > rho_min else rho_min
    return v if v > rho_min else rho_min  # clamp


def _colony(m, S, E, pol, st, params, algo):
    cfg = dict(ACO_DEFAULTS[algo])
    for k, v in params.items():
        if k not in cfg:
            raise UsageError(f"unknown ant-colony parameter {k!r}")
        cfg[k] = v
    require(1 <= cfg["ants"] <= 10 ** 6 and 1 <= cfg["iterations"] <= 10 ** 6, "ants, iterations")
    require(cfg["alpha"] >= 0 and cfg["beta"] >= 0 and cfg["Q"] > 0 and cfg["tau0"] > 0, "alpha, beta, Q, tau0")
    rho = cfg["rho"] if algo == "aco" else cfg["rho_initial"]
    require(0.0 < rho < 1.0, "rho in (0, 1)")
    if algo != "aco":
        require(0.0 <= cfg["rho_min"] < 1.0, "rho_min in [0, 1)")
    T, ants = cfg["iterations"], cfg["ants"]
    tau = {}  # (cell, slot) -> tau of the slots that ever got a deposit
    base = cfg["tau0"]  # the common tau of every slot that never got one (same updates)
    best, bests, means, distinct, seen = math.inf, [], [], [], set()
    for t in range(1, T + 1):
        lengths, paths = [], []
        for _a in range(ants):
            path, V = [S], {S}
            alive = True
            while path[-1] != E:
                c = path[-1]
                cand = []
                for k, (dx, dy) in enumerate(SLOTS):
                    b = (c[0] + dx, c[1] + dy)
                    if b not in V and allowed(m, c, b, pol):
                        cand.append((k, b))
                if not cand:
                    if cfg["dead_end"] == "die":
                        alive = False
                        break
                    path.pop()
                    if not path:
                        alive = False
                        break
                    continue
                w = []
                for k, b in cand:
                    tv = tau.get((c, k), base)
                    d = _dist(c, b)
                    eta = 1.0 / d if cfg["eta"] == "inverse_distance" else 1.0 / (d + _dist(b, E))
                    w.append(math.pow(tv, cfg["alpha"]) * math.pow(eta, cfg["beta"]))
                k, b = cand[r_roulette(w, st.u())]
                path.append(b)
                V.add(b)
            if alive:
                paths.append(path)
                lengths.append(length(path))
        # statistics, deposits, update
        delta = {}
        for path, L in zip(paths, lengths):
            d = cfg["Q"] / L
            for r in range(1, len(path)):
                a, b = path[r - 1], path[r]
                k = SLOTS.index((b[0] - a[0], b[1] - a[1]))
                delta[(a, k)] = delta.get((a, k), 0.0) + d
                if cfg["edge_sense"] == "undirected":
                    delta[(b, 7 - k)] = delta.get((b, 7 - k), 0.0) + d
        for key in set(tau) | set(delta):
            tau[key] = ((1.0 - rho) * tau.get(key, base)) + delta.get(key, 0.0)
        base = ((1.0 - rho) * base) + 0.0
        if algo != "aco" and t < T:
            tp = t if cfg["rho_t_origin"] == 1 else t - 1
            rho = _adaptive_rho(rho, tp, T, cfg["rho_min"], cfg["rho_reading"])
        if lengths:
            s = 0.0
            for L in lengths:
                s += L
            means.append(s / len(lengths))
            Ln = min(lengths)
            if Ln < best:
                best = Ln
        else:
            means.append(math.nan)
        bests.append(best)
        for p in paths:
            key = tuple(p)
            if key not in seen:
                seen.add(key)
                distinct.append(p)
    return bests, means, T, distinct


def _split(inp, ga_defaults, own):
    aco, rest = {}, {}
    for k, v in inp.items():
        if k.startswith("aco_"):
            aco[k[4:]] = v
        elif k not in own:
            rest[k] = v
    return aco, _config(rest, ga_defaults)


def _finish(colony, best, bg, bests, means, cfg, st, chains):
    cb, cm, T, _ = colony
    return {"found": True, "path": _out_path(best.path), "length": best.length,
            "iterations": T + cfg["generations"],
            "best_per_iteration": [_num_out(v) for v in cb] + bests,
            "mean_per_iteration": [_num_out(v) for v in cm] + means,
            "best_generation": bg, "best_origin": best.origin,
            "phase": "aco" if best.origin == "aco" else "ga", "draws": st.drawn, "init_chains": chains}


def _not_found(colony, failure, st, chains):
    cb, cm, T, _ = colony
    return {"found": False, "path": [], "length": 0.0, "iterations": T,
            "best_per_iteration": [_num_out(v) for v in cb], "mean_per_iteration": [_num_out(v) for v in cm],
            "failure": failure, "draws": st.drawn, "init_chains": chains}


def _sorted_distinct(colony):
    return sorted(colony[3], key=length)  # stable: equal lengths keep first appearance


def plan_hybrid(inp):
    if inp.get("algo", "hybrid-ga-aco") != "hybrid-ga-aco":
        raise UsageError("algo not covered")
    fill = _opt(inp, "fill", ["repeat", "random"])
    aco_params, cfg = _split(inp, GA_DEFAULTS, ("fill",))
    m, S, E, pol, seed = _setup(inp)
    if S == E:
        return dict(_trivial(S), phase="none")
    st = Stream(seed)
    colony = _colony(m, S, E, pol, st, aco_params, "aco")
    D = _sorted_distinct(colony)
    N = cfg["population"]
    pop = [Ind(m, p, cfg, "aco", 0) for p in D[:N]]
    chains = 0
    if len(pop) < N and (fill == "random" or not D):
        ok, failure, paths, chains = init_paths(m, S, E, pol, cfg, st, N - len(pop))
        if ok:
            pop += [Ind(m, p, cfg, "init", 0) for p in paths]
        elif not D:
            return _not_found(colony, failure, st, chains)
    k = 0
    while len(pop) < N:
        pop.append(pop[k % len(D)])
        k += 1
    best, bg, bests, means = evolve(m, pol, cfg, st, pop)
    return _finish(colony, best, bg, bests, means, cfg, st, chains)


def plan_iha(inp):
    if inp.get("algo", "iha") != "iha":
        raise UsageError("algo not covered")
    inject = inp.get("inject", 10)
    require(isinstance(inject, int) and 0 <= inject <= 10 ** 6, "inject")
    scope = _opt(inp, "deletion_scope", ["initial", "merged"])
    aco_params, cfg = _split(inp, IGA, ("inject", "deletion_scope", "elite_fraction"))
    frac = inp.get("elite_fraction", 0.5)
    m, S, E, pol, seed = _setup(inp)
    if S == E:
        return dict(_trivial(S), phase="none")
    st = Stream(seed)
    colony = _colony(m, S, E, pol, st, aco_params, "iaco-shi")
    D = _sorted_distinct(colony)
    K = min(inject, len(D))
    ok, failure, paths, chains = init_paths(m, S, E, pol, cfg, st, cfg["population"])
    initial = []
    if ok:
        initial = [Ind(m, delete(m, p, pol), cfg, "init", 0) for p in paths]
    elif K == 0:
        return _not_found(colony, failure, st, chains)
    pop = [initial[t] for t in elite([q.fit for q in initial], elite_count(len(initial), frac))]
    for p in D[:K]:
        pop.append(Ind(m, delete(m, p, pol) if scope == "merged" else list(p), cfg, "aco", 0))
    best, bg, bests, means = evolve(m, pol, cfg, st, pop, elitist=True)
    return _finish(colony, best, bg, bests, means, cfg, st, chains)


# ---- operator rules -------------------------------------------------------------------------


def op_init(inp):
    m = Map(inp["grid"])
    genes = _path(inp["genes"])
    require(len(genes) >= 2, "two genes")
    require(all(m.inside(c) for c in genes), "gene outside")
    ok, p, why = repair(m, genes, _policy(inp), _opt(inp, "mid_rounding", ["floor", "ceil", "half_even"]),
                        _opt(inp, "init_reject", ["shift", "blocked", "near_obstacle"]),
                        _opt(inp, "illegal_step", ["repair", "reject"]))
    return {"feasible": ok, "path": _out_path(p), "reason": why}


def op_crossover(inp):
    a, b = _path(inp["a"]), _path(inp["b"])
    pts = common_points(a, b)
    out = {"points": [[k, j] for k, j in pts]}
    if "choice" in inp:
        c = inp["choice"]
        require(isinstance(c, int) and 0 <= c < len(pts), "choice")
        c1, c2 = cross(a, b, *pts[c])
        out["first"], out["second"] = _out_path(c1), _out_path(c2)
    return out


def op_mutation(inp):
    m = Map(inp["grid"])
    p = _path(inp["path"])
    k = inp["k"]
    require(isinstance(k, int) and len(p) >= 3 and 1 <= k <= len(p) - 2, "k interior")
    cands = candidates(m, p, k, _policy(inp))
    out = {"candidates": _out_path(cands)}
    if "choice" in inp:
        c = inp["choice"]
        require(isinstance(c, int) and 0 <= c < len(cands), "choice")
        q = list(p)
        q[k] = cands[c]
        out["mutated"] = _out_path(q)
    return out


def op_deletion(inp):
    m = Map(inp["grid"])
    p = _path(inp["path"])
    require(all(m.inside(c) for c in p), "node outside")
    q = delete(m, p, _policy(inp))
    return {"path": _out_path(q), "removed": len(p) - len(q)}


def op_loops(inp):
    p = _path(inp["path"])
    q = cut_loops(p)
    return {"path": _out_path(q), "removed": len(p) - len(q)}


def op_elite(inp):
    f = [float(x) for x in inp["fitness"]]
    if "fraction" in inp:
        count = elite_count(len(f), float(inp["fraction"]))
    else:
        count = inp["count"]
        require(count >= 0, "count")
    return {"indices": elite(f, count)}


RULES = {
    "shi2022.op.init": op_init,
    "shi2022.op.crossover": op_crossover,
    "shi2022.op.mutation": op_mutation,
    "shi2022.op.deletion": op_deletion,
    "shi2022.op.elite": op_elite,
    "shi2022.op.loops": op_loops,
    "shi2022.plan.ga": plan_ga,
    "shi2022.plan.iga": plan_iga,
    "shi2022.plan.hybrid": plan_hybrid,
    "shi2022.plan.iha": plan_iha,
    "classic.plan.ga": plan_ga_classic,
}

__all__ = ["RULES", "DomainError"]
