"""spec/shi2022-aco.md and spec/han-iaco.md: whole-run replays of the ant-colony planners.

Written from the planner specs (the algorithm steps, the draw tables and the parameter tables)
and from the equation rules of spec/shi2022.md and spec/han.md, not from the C++ engine. The
structure differs on purpose: pheromone lives in a dict keyed by ordered pairs of free cells
(the spec's slots towards blocked or outside cells are never read, so they are not kept), the
tabu set is a Python set, and every equation is evaluated inline with the operation order its
rule states. The random stream is the crosscheck's own pure-Python MT19937 (rules/rng.py).

astar-han (han.plan.astar) is search.astar with the Chebyshev heuristic: it reuses the
crosscheck's independent best-first search of rules/search.py.
"""
import math

from .common import DomainError, require
from .rng import MT19937
from . import search as _search

# canonical neighbour order (grid.neighbour-order): increasing cell index
ORDER = [(-1, -1), (0, -1), (1, -1), (-1, 0), (1, 0), (-1, 1), (0, 1), (1, 1)]
SQRT2 = math.sqrt(2.0)
INF = math.inf


class UsageError(Exception):
    """A malformed request (the C++ UsageError); never expected by a golden vector."""


class Grid:
    def __init__(self, rows):
        if not isinstance(rows, list) or not rows or not all(isinstance(r, str) for r in rows):
            raise UsageError("grid must be a non-empty array of strings")
        self.w, self.h = len(rows[0]), len(rows)
        require(self.w >= 1 and all(len(r) == self.w for r in rows), "rows of equal length")
        require(all(ch in ".#" for r in rows for ch in r), "only . and #")
        self.blocked = {(x, self.h - 1 - r) for r, row in enumerate(rows) for x, ch in enumerate(row) if ch == "#"}

    def free(self, c):
        return 0 <= c[0] < self.w and 0 <= c[1] < self.h and c not in self.blocked

    def step_ok(self, a, b, pol):
        if not (self.free(a) and self.free(b)):
            return False
        dx, dy = b[0] - a[0], b[1] - a[1]
        if dx == 0 or dy == 0:
            return True
        f1, f2 = self.free((a[0] + dx, a[1])), self.free((a[0], a[1] + dy))
        return {"never": False, "strict": f1 and f2, "one": f1 or f2, "always": True}[pol]

    def moves(self, c, pol):
        return [(c[0] + dx, c[1] + dy) for dx, dy in ORDER if self.step_ok(c, (c[0] + dx, c[1] + dy), pol)]


def dist(a, b):
    dx, dy = a[0] - b[0], a[1] - b[1]
    return math.sqrt(float(dx * dx + dy * dy))


def step(a, b):
    return SQRT2 if a[0] != b[0] and a[1] != b[1] else 1.0


def roulette(w, u):
    s = 0.0
    for x in w:
        s += x
    require(s > 0 and math.isfinite(s), "roulette: positive finite sum")
    target = u * s
    c = 0.0
    for k, x in enumerate(w):
        c += x
        if x > 0 and c >= target:
            return k
    raise AssertionError("unreachable")


# ---- parameters ------------------------------------------------------------------------------

SHI_COMMON = {"ants": 50, "iterations": 100, "alpha": 1.0, "beta": 7.0, "Q": 1.0, "tau0": 8.0,
              "edge_sense": "directed", "dead_end": "die"}
DEFAULTS = {
    "aco": dict(SHI_COMMON, eta="inverse_distance", rho=0.9),
    "iaco-shi": dict(SHI_COMMON, eta="goal_directed", rho_initial=0.9, rho_min=0.1,
                     rho_reading="factor", rho_t_origin=1),
    "iaco-shi-nomin": dict(SHI_COMMON, eta="goal_directed", rho_initial=0.9, rho_min=0.0,
                           rho_reading="factor", rho_t_origin=1),
    # spec/classic.md r[classic.plan.aco]: the classic MATLAB script's values.
    "aco-classic": {"ants": 50, "iterations": 100, "alpha": 1.0, "beta": 7.0, "Q": 1.0, "tau0": 8.0,
                    "rho": 0.3, "eta": "goal_inverse", "eta_goal": 100.0, "edge_sense": "undirected",
                    "dead_end": "die"},
    "iaco-han": {"ants": 50, "iterations": 50, "alpha": 4.0, "beta": 8.0, "rho": 0.7, "gamma": 1.0,
                 "omega_i": 0.5, "omega_form": "multiply", "at90": "two", "epsilon": 1.0,
                 "q0_origin": 1, "draw_u": "lazy", "h": 1.0, "tau_min": 0.01,
                 "bonus_edges": "best_path", "Q": 1.0, "tau0": 1.0, "a": 1.0, "b": 5.0,
                 "rho_min": 0.1, "spread_reference": "iteration_worst", "rho_timing": "next",
                 "eta": "goal_directed", "edge_sense": "directed", "dead_end": "backtrack"},
}
CHOICES = {"eta": ("inverse_distance", "goal_directed", "goal_inverse"), "edge_sense": ("directed", "undirected"),
           "dead_end": ("die", "backtrack"), "rho_reading": ("factor", "condition", "clamp"),
           "omega_form": ("multiply", "divide"), "at90": ("two", "one"), "draw_u": ("lazy", "always"),
           "bonus_edges": ("best_path", "all_edges"), "spread_reference": ("iteration_worst", "history_best"),
           "rho_timing": ("next", "current")}


def params_for(algo, inp):
    p = dict(DEFAULTS[algo])
    for k, v in inp.items():
        if k in ("grid", "start", "goal", "seed", "policy", "algo"):
            continue
        if k not in p:
            raise UsageError(f"unknown parameter {k!r}")
        if k in ("rho_t_origin", "q0_origin") and isinstance(v, str):
            if v not in ("0", "1"):
                raise UsageError(k)
            v = int(v)  # golden INTERPRETATION options are strings
        if k in CHOICES and v not in CHOICES[k]:
            raise UsageError(f"{k} = {v!r}")
        p[k] = v
    i = lambda k: p[k]  # noqa: E731
    require(isinstance(i("ants"), int) and 1 <= i("ants") <= 10**6, "ants")
    require(isinstance(i("iterations"), int) and 1 <= i("iterations") <= 10**6, "iterations")
    require(p["alpha"] >= 0 and p["beta"] >= 0 and p["Q"] > 0 and p["tau0"] > 0, "alpha beta Q tau0")
    if "eta_goal" in p:
        require(math.isfinite(p["eta_goal"]) and p["eta_goal"] > 0, "eta_goal > 0")
    rho = p.get("rho", p.get("rho_initial"))
    require(0 < rho < 1, "rho in (0, 1)")
    if "rho_min" in p:
        require(0 <= p["rho_min"] < 1, "rho_min in [0, 1)")
    for k in ("rho_t_origin", "q0_origin"):
        if k in p:
            require(p[k] in (0, 1), k)
    if algo == "iaco-han":
        require(0 <= p["a"] < p["b"], "0 <= a < b")
        require(p["gamma"] >= 0 and 0 < p["omega_i"] < 1, "gamma, omega_i")
        require(p["epsilon"] > 0 and p["epsilon"] * (0.2 + (1.0 * 0.7)) <= 1, "epsilon")
        require(p["h"] >= 0 and p["tau_min"] > 0, "h, tau_min")
    return p


# ---- one run ---------------------------------------------------------------------------------


def replay(algo, inp):
    g = Grid(inp["grid"])
    S, E = tuple(inp["start"]), tuple(inp["goal"])
    pol = inp.get("policy", "always" if algo == "aco-classic" else "strict")
    seed = inp.get("seed", 1)
    require(isinstance(seed, int) and 0 <= seed < 2**32, "seed")
    require(g.free(S), "start outside or blocked")
    require(g.free(E), "goal outside or blocked")
    p = params_for(algo, inp)
    han = algo == "iaco-han"
    out = {"found": True, "path": [list(S)], "length": 0.0, "iterations": 0, "best_per_iteration": [],
           "mean_per_iteration": [], "best_iteration": 0, "dead_ants_per_iteration": [],
           "rho_per_iteration": [], "draws": 0}
    if S == E:
        # spec/shi2022-aco.md, Golden adapters: iteration_best is absent when start = goal
        # (step 1 returns "no curves"); the per-iteration extras (q0 for Han) are absent too.
        return out
    out["iteration_best"] = []
    if han:
        out["q0_per_iteration"] = []

    rng = MT19937(seed)
    draws = 0
    N, m = p["iterations"], p["ants"]
    alpha, beta = p["alpha"], p["beta"]
    free_cells = [(x, y) for y in range(g.h) for x in range(g.w) if g.free((x, y))]
    adj = {c: g.moves(c, pol) for c in free_cells}
    tau = {(c, b): p["tau0"] for c in free_cells for b in adj[c]}
    best_len, best_path = INF, None
    rho_prev = p["rho"] if "rho" in p else p["rho_initial"]  # Shi adaptive: rho(t); Han: rho(t-1)

    for t in range(1, N + 1):
        if han:
            Nc = t if p["q0_origin"] == 1 else t - 1
            q0 = p["epsilon"] * (0.2 + (((N - Nc) / N) * 0.7))
            out["q0_per_iteration"].append(q0)
        tours = []  # (ant, path, length) of survivors
        dead = 0
        for a in range(m):
            path, seen = [S], {S}
            alive = True
            while path[-1] != E:
                c = path[-1]
                cands = [b for b in adj[c] if b not in seen]
                if not cands:
                    if p["dead_end"] == "die":
                        alive = False
                        break
                    path.pop()
                    if not path:
                        alive = False
                        break
                    continue
                w = []
                prev = path[-2] if len(path) >= 2 else None
                for b in cands:
                    if p["eta"] == "inverse_distance":
                        eta = 1.0 / dist(c, b)
                    elif p["eta"] == "goal_directed":
                        eta = 1.0 / (dist(c, b) + dist(b, E))
                    else:  # goal_inverse: 1 / d(b, E), eta_goal at E
                        eta = p.get("eta_goal", 100.0) if b == E else 1.0 / dist(b, E)
                    x = math.pow(tau[(c, b)], alpha) * math.pow(eta, beta)
                    if han:
                        if prev is None:
                            T = 2 if p["omega_form"] == "multiply" else 1
                        else:
                            dot = (c[0] - prev[0]) * (b[0] - c[0]) + (c[1] - prev[1]) * (b[1] - c[1])
                            s = dot if p["omega_form"] == "multiply" else -dot
                            T = 2 if s > 0 else (1 if s < 0 else (2 if p["at90"] == "two" else 1))
                        omega = p["omega_i"] * T if p["omega_form"] == "multiply" else p["omega_i"] / T
                        x = x * math.pow(omega, p["gamma"])
                    w.append(x)
                if han:
                    q = rng.genrand_res53()
                    draws += 1
                    u = 0.0
                    if p["draw_u"] == "always" or q > q0:
                        u = rng.genrand_res53()
                        draws += 1
                    if q <= q0:
                        top = max(w)
                        require(top > 0, "argmax needs a positive weight")
                        k = w.index(top)
                    else:
                        k = roulette(w, u)
                else:
                    u = rng.genrand_res53()
                    draws += 1
                    k = roulette(w, u)
                path.append(cands[k])
                seen.add(cands[k])
            if not alive:
                dead += 1
                continue
            L = 0.0
            for r in range(1, len(path)):
                L += step(path[r - 1], path[r])
            tours.append((a, path, L))

        # statistics
        L_n, L_A, nbest = INF, -INF, None
        total = 0.0
        for a, path, L in tours:
            total += L
            if L < L_n:
                L_n, nbest = L, path
            if L > L_A:
                L_A = L
        out["dead_ants_per_iteration"].append(dead)
        out["iteration_best"].append(L_n)
        out["mean_per_iteration"].append(total / len(tours) if tours else math.nan)
        L_a = best_len if best_len < INF else L_n

        # rho of this update
        if algo == "aco":
            rho = p["rho"]
        elif not han:
            rho = rho_prev
        else:
            rho_t = rho_prev
            if tours:
                ref = L_A if p["spread_reference"] == "iteration_worst" else L_a
                d = ref - L_n
                f = 0.9 if d > p["b"] else (0.8 if d > p["a"] else 0.7)
                rho_t = max(f * rho_prev, p["rho_min"])
            rho = rho_prev if p["rho_timing"] == "next" else rho_t
            rho_prev = rho_t
        require(0 < rho < 1, "rho must stay in (0, 1)")
        out["rho_per_iteration"].append(rho)

        # deposits, ants in order, per ordered pair
        contrib = {}
        for a, path, L in tours:
            d = p["Q"] / L
            for r in range(1, len(path)):
                contrib.setdefault((path[r - 1], path[r]), []).append(d)
                if p["edge_sense"] == "undirected":
                    contrib.setdefault((path[r], path[r - 1]), []).append(d)
        bonus_on = set()
        B = 0.0
        if han and tours:
            B = (p["h"] * (L_a - L_n)) / L_n
            if p["bonus_edges"] == "all_edges":
                bonus_on = set(tau)
            else:
                for r in range(1, len(nbest)):
                    bonus_on.add((nbest[r - 1], nbest[r]))
                    if p["edge_sense"] == "undirected":
                        bonus_on.add((nbest[r], nbest[r - 1]))
        for e in tau:
            delta = 0.0
            for d in contrib.get(e, ()):
                delta += d
            v = ((1.0 - rho) * tau[e]) + delta
            if han:
                v = max(v + (B if e in bonus_on else 0.0), p["tau_min"])
            tau[e] = v

        if tours and L_n < best_len:
            best_len, best_path = L_n, nbest
            out["best_iteration"] = t
        out["best_per_iteration"].append(best_len)

        if algo in ("iaco-shi", "iaco-shi-nomin") and t < N:
            tt = t - 1 + p["rho_t_origin"]
            A = N / (N + tt)
            Bf = 1.0 / math.exp(1.0 - rho_prev)
            rmin = p["rho_min"]
            if p["rho_reading"] == "factor":
                v = (A * Bf) * rho_prev
                rho_prev = v if v > rmin else rmin
            elif p["rho_reading"] == "condition":
                rho_prev = (A * Bf) if rho_prev > rmin else rmin
            else:
                v = A * Bf
                rho_prev = v if v > rmin else rmin

    out["iterations"] = N
    out["found"] = best_path is not None
    out["path"] = [list(c) for c in best_path] if best_path else []
    out["length"] = best_len if best_path else 0.0
    out["draws"] = draws
    return out


def plan_aco(inp):
    return replay("aco", inp)


def plan_iaco(inp):
    algo = inp.get("algo", "iaco-shi")
    if algo not in ("iaco-shi", "iaco-shi-nomin"):
        raise UsageError("algo")
    return replay(algo, inp)


def plan_aco_classic(inp):
    return replay("aco-classic", inp)


def plan_iaco_han(inp):
    return replay("iaco-han", inp)


def plan_astar_han(inp):
    form = inp.get("h_form", "chebyshev")
    if form not in ("chebyshev", "octile"):
        raise UsageError("h_form")
    q = {k: v for k, v in inp.items() if k in ("grid", "start", "goal", "policy")}
    q["heuristic"] = form
    r = _search.astar(q)
    return {k: r[k] for k in ("found", "path", "length", "expansions")}


RULES = {
    "shi2022.plan.aco": plan_aco,
    "shi2022.plan.iaco": plan_iaco,
    "han.plan.iaco": plan_iaco_han,
    "classic.plan.aco": plan_aco_classic,
    "han.plan.astar": plan_astar_han,
}

__all__ = ["RULES", "DomainError"]
