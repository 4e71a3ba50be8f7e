"""spec/cin2021-ml.md (cin2021.data, eq1-eq11, knn, gini, folds), written from the spec.
Python 3 standard library only.

Independent of the C++ on purpose:
  - the tree grower compares split scores with fractions.Fraction (the C++ uses 128-bit integer
    cross-multiplication) and finds the best split by scanning every threshold of every feature
    with set-based class counts (the C++ sweeps sorted rows);
  - the SVM dual (Eq. 3) is solved by a plain SMO over the maximal violating pair in double
    precision to a 1e-12 gap (libsvm uses the second-order working set and a single-precision kernel
    cache), so Eq. 3's vectors carry a tolerance for libsvm's float cache;
  - MCC uses Python integers, the averages are written from the formulas;
  - the data parser is a regular-expression grammar.
"""
import math
import re
from fractions import Fraction

from .common import DomainError, require
from .rng import MT19937

LABELS = ["Move-Forward", "Slight-Right-Turn", "Sharp-Right-Turn", "Slight-Left-Turn"]
NUMBER = re.compile(r"^[+-]?([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][+-]?[0-9]+)?$")


class ParseError(Exception):
    """Malformed data (spec: the C++ ParseError)."""


def _argmax_first(v):
    best = 0
    for i in range(1, len(v)):
        if v[i] > v[best]:
            best = i
    return best


# ---- data ---------------------------------------------------------------------------------

def data(inp):
    text = inp["text"]
    lines = text.split("\n")
    if lines and lines[-1] == "" and len(lines) > 1:
        lines.pop()  # a final line end
    rows, ys, d = [], [], None
    if text == "":
        raise ParseError("empty file")
    for ln, line in enumerate(lines, 1):
        if line.endswith("\r"):
            line = line[:-1]
        if line == "":
            raise ParseError(f"line {ln}: empty")
        fields = line.split(",")
        label = fields[-1]
        nums = fields[:-1]
        if label not in LABELS or not nums:
            raise ParseError(f"line {ln}: label")
        vals = []
        for f in nums:
            if not NUMBER.match(f):
                raise ParseError(f"line {ln}: number")
            v = float(f)
            if not math.isfinite(v):
                raise ParseError(f"line {ln}: not finite")
            vals.append(v)
        if d is None:
            d = len(vals)
        if len(vals) != d:
            raise ParseError(f"line {ln}: column count")
        rows.append(vals)
        ys.append(LABELS.index(label))
    return {"rows": len(rows), "features": d, "x": rows, "y": ys}


# ---- naive Bayes ----------------------------------------------------------------------------

def _dataset(inp):
    x, y, k = inp["x"], inp["y"], inp["classes"]
    require(len(x) >= 1 and len(x) == len(y), "one label per row")
    require(all(0 <= c < k for c in y), "labels in [0, classes)")
    require(all(all(math.isfinite(v) for v in r) for r in x), "finite values")
    return x, y, k


def eq1(inp):
    x, y, k = _dataset(inp)
    q = inp["query"]
    d = len(x[0])
    require(len(q) == d, "query length")
    n = len(x)
    count = [y.count(c) for c in range(k)]
    jll = [-math.inf] * k
    if inp["likelihood"] == "gaussian":
        vs = inp.get("var_smoothing", 1e-9)
        require(vs >= 0, "var_smoothing >= 0")
        col_var = []
        for j in range(d):
            mu = sum(r[j] for r in x) / n
            col_var.append(sum((r[j] - mu) ** 2 for r in x) / n)
        eps = vs * max(col_var)
        for c in range(k):
            if count[c] == 0:
                continue
            rows = [r for r, l in zip(x, y) if l == c]
            mean = [sum(r[j] for r in rows) / count[c] for j in range(d)]
            var = [sum((r[j] - mean[j]) ** 2 for r in rows) / count[c] + eps for j in range(d)]
            require(all(v > 0 for v in var), "variance > 0")
            a = sum(math.log(2 * math.pi * v) for v in var)
            b = sum((q[j] - mean[j]) ** 2 / var[j] for j in range(d))
            jll[c] = math.log(count[c] / n) + (-0.5 * a - 0.5 * b)
    elif inp["likelihood"] == "multinomial":
        alpha = inp.get("alpha", 1.0)
        require(alpha > 0, "alpha > 0")
        require(all(v >= 0 for r in x for v in r) and all(v >= 0 for v in q), "counts >= 0")
        for c in range(k):
            if count[c] == 0:
                continue
            fc = [sum(r[j] for r, l in zip(x, y) if l == c) for j in range(d)]
            tot = sum(f + alpha for f in fc)
            flp = [math.log(f + alpha) - math.log(tot) for f in fc]
            jll[c] = sum(q[j] * flp[j] for j in range(d)) + (math.log(count[c]) - math.log(n))
    else:
        raise KeyError("likelihood")
    return {"jll": [("-inf" if v == -math.inf else v) for v in jll], "class": _argmax_first(jll)}


# ---- SVM --------------------------------------------------------------------------------------

def _rbf(g, a, b):
    return math.exp(-g * sum((p - q) ** 2 for p, q in zip(a, b)))


def eq2(inp):
    g, labels, n_sv, sv, coef, rho = inp["gamma"], inp["labels"], inp["n_sv"], inp["sv"], inp["coef"], inp["rho"]
    k = len(labels)
    require(g > 0 and k >= 2 and all(labels[i] < labels[i + 1] for i in range(k - 1)), "model")
    require(len(n_sv) == k and len(sv) == sum(n_sv) and len(coef) == k - 1 and len(rho) == k * (k - 1) // 2, "sizes")
    q = inp["query"]
    require(all(len(s) == len(q) for s in sv), "query length")
    start = [sum(n_sv[:c]) for c in range(k)]
    kv = [_rbf(g, q, s) for s in sv]
    dec, votes, p = [], [0] * k, 0
    for i in range(k):
        for j in range(i + 1, k):
            s = 0.0
            for m in range(n_sv[i]):
                s += coef[j - 1][start[i] + m] * kv[start[i] + m]
            for m in range(n_sv[j]):
                s += coef[i][start[j] + m] * kv[start[j] + m]
            s -= rho[p]
            dec.append(s)
            votes[i if s > 0 else j] += 1
            p += 1
    return {"decision": dec, "class": labels[_argmax_first(votes)]}


def _smo(xs, ys, C, g):
    """Binary C-SVC dual by SMO on the maximal violating pair; returns alpha, rho."""
    n = len(xs)
    K = [[_rbf(g, a, b) for b in xs] for a in xs]
    Q = [[ys[i] * ys[j] * K[i][j] for j in range(n)] for i in range(n)]
    a = [0.0] * n
    G = [-1.0] * n
    for _ in range(100000):
        up = [i for i in range(n) if (ys[i] > 0 and a[i] < C) or (ys[i] < 0 and a[i] > 0)]
        low = [i for i in range(n) if (ys[i] > 0 and a[i] > 0) or (ys[i] < 0 and a[i] < C)]
        i = max(up, key=lambda t: -ys[t] * G[t])
        j = min(low, key=lambda t: -ys[t] * G[t])
        if -ys[i] * G[i] - (-ys[j] * G[j]) < 1e-12:
            break
        # move along y_i d_i = -y_j d_j: analytic two-variable step, clipped to the box
        quad = Q[i][i] + Q[j][j] - 2 * ys[i] * ys[j] * Q[i][j]
        quad = quad if quad > 0 else 1e-12
        step = (-ys[i] * G[i] + ys[j] * G[j]) / quad
        # bounds on step for a_i += y_i step, a_j -= y_j step
        lo, hi = -math.inf, math.inf
        for idx, sgn in ((i, ys[i]), (j, -ys[j])):
            if sgn > 0:
                hi, lo = min(hi, C - a[idx]), max(lo, -a[idx])
            else:
                hi, lo = min(hi, a[idx]), max(lo, a[idx] - C)
        step = max(lo, min(hi, step))
        di, dj = ys[i] * step, -ys[j] * step
        a[i] += di
        a[j] += dj
        for t in range(n):
            G[t] += Q[t][i] * di + Q[t][j] * dj
    free = [t for t in range(n) if 0 < a[t] < C]
    if free:
        rho = sum(ys[t] * G[t] for t in free) / len(free)
    else:
        ub = min([ys[t] * G[t] for t in range(n) if (ys[t] > 0 and a[t] == C) or (ys[t] < 0 and a[t] == 0)] or [math.inf])
        lb = max([ys[t] * G[t] for t in range(n) if (ys[t] > 0 and a[t] == 0) or (ys[t] < 0 and a[t] == C)] or [-math.inf])
        rho = (ub + lb) / 2
    return a, rho


def eq3(inp):
    x, y, k = _dataset(inp)
    C = inp.get("C", 1.0)
    require(C > 0, "C > 0")
    d = len(x[0])
    gamma = inp.get("gamma", "scale")
    if gamma == "scale":
        vals = [v for r in x for v in r]
        mu = sum(vals) / len(vals)
        var = sum((v - mu) ** 2 for v in vals) / len(vals)
        gamma = 1.0 / (d * var) if var != 0 else 1.0
    elif gamma == "auto":
        gamma = 1.0 / d
    require(gamma > 0, "gamma > 0")
    labels = sorted(set(y))
    require(len(labels) >= 2, "two classes")
    K = len(labels)
    groups = [[i for i in range(len(x)) if y[i] == l] for l in labels]
    alpha_of = {}  # (pair, row) -> signed coefficient
    rho = []
    for a in range(K):
        for b in range(a + 1, K):
            rows = groups[a] + groups[b]
            ys = [1.0] * len(groups[a]) + [-1.0] * len(groups[b])
            al, r = _smo([x[i] for i in rows], ys, C, gamma)
            rho.append(r)
            for t, i in enumerate(rows):
                alpha_of[(a, b, i)] = ys[t] * al[t]
    # support vectors: rows with a non-zero coefficient in some pair (tolerance: libsvm's float cache)
    sv_rows, n_sv = [], []
    for c in range(K):
        mine = [i for i in groups[c] if any(abs(alpha_of.get((min(c, o), max(c, o), i), 0.0)) > 1e-9
                                            for o in range(K) if o != c)]
        sv_rows += mine
        n_sv.append(len(mine))
    coef = [[0.0] * len(sv_rows) for _ in range(K - 1)]
    pos = 0
    for c in range(K):
        for i in sv_rows[pos:pos + n_sv[c]]:
            # libsvm layout: the coefficient of SV of class c in pair (c, o) sits in row o-1 if o > c, else row o
            for o in range(K):
                if o == c:
                    continue
                row = o - 1 if o > c else o
                coef[row][sv_rows.index(i)] = alpha_of.get((min(c, o), max(c, o), i), 0.0)
        pos += n_sv[c]
    return {"gamma": gamma, "labels": labels, "n_sv": n_sv, "sv_rows": sv_rows, "coef": coef, "rho": rho}


# ---- distances and KNN ------------------------------------------------------------------------

def eq4(inp):
    x, y = inp["x"], inp["y"]
    require(len(x) == len(y) and len(x) >= 1, "equal lengths >= 1")
    return {"d": math.sqrt(sum((a - b) * (a - b) for a, b in zip(x, y)))}


def eq5(inp):
    x, y, w = inp["x"], inp["y"], inp["w"]
    require(len(x) == len(y) == len(w) and len(x) >= 1, "equal lengths >= 1")
    require(all(math.isfinite(v) and v >= 0 for v in w), "weights >= 0")
    return {"d": math.sqrt(sum(wi * ((a - b) * (a - b)) for a, b, wi in zip(x, y, w)))}


def knn(inp):
    x, y, k = _dataset(inp)
    kk, q = inp["k"], inp["query"]
    require(1 <= kk <= len(x), "k in [1, rows]")
    w = inp.get("w", [1.0] * len(q))
    require(len(w) == len(q) and all(v >= 0 for v in w), "weights")
    d2 = [sum(wi * ((a - b) * (a - b)) for a, b, wi in zip(q, r, w)) for r in x]
    order = sorted(range(len(x)), key=lambda i: (d2[i], i))
    nb = order[:kk]
    tie = any(d2[i] == d2[nb[-1]] for i in order[kk:])
    vote = inp.get("knn_vote", "uniform")
    dist = [math.sqrt(d2[i]) for i in nb]
    votes = [0.0] * k
    zero = any(v == 0 for v in dist)
    for i, dd in zip(nb, dist):
        if vote == "uniform":
            wt = 1.0
        else:
            wt = (1.0 if dd == 0 else 0.0) if zero else 1.0 / dd
        votes[y[i]] += wt
    return {"neighbours": nb, "distance_tie": tie, "class": _argmax_first(votes)}


# ---- CART and the forest ----------------------------------------------------------------------

def _grow(x, y, k, weights, m, gen):
    """Returns nodes [feature, threshold, left, right, counts], preorder; ties[0] counts tied nodes."""
    nodes = []
    ties = [0]
    d = len(x[0])
    stack = [([i for i in range(len(x)) if weights[i] > 0], -1, False)]
    while stack:
        rows, parent, is_left = stack.pop()
        me = len(nodes)
        counts = [0] * k
        for i in rows:
            counts[y[i]] += weights[i]
        nodes.append([-1, 0.0, -1, -1, counts])
        if parent >= 0:
            nodes[parent][2 if is_left else 3] = me
        if sum(1 for c in counts if c > 0) <= 1 or len(rows) < 2:
            continue
        def constant(j):
            return len({x[i][j] for i in rows}) == 1
        if m == 0:
            cand = [j for j in range(d) if not constant(j)]
        else:
            pool, cand = list(range(d)), []
            while pool and len(cand) < m:
                u = gen.genrand_res53()
                r = min(math.floor(u * len(pool)), len(pool) - 1)
                j = pool[r]
                pool[r] = pool[-1]
                pool.pop()
                if not constant(j):
                    cand.append(j)
        best, tied = None, False
        for j in cand:
            vals = sorted({x[i][j] for i in rows})
            for a, b in zip(vals, vals[1:]):
                left = [i for i in rows if x[i][j] <= a]
                L = [0] * k
                for i in left:
                    L[y[i]] += weights[i]
                R = [c - l for c, l in zip(counts, L)]
                nl, nr = sum(L), sum(R)
                s = Fraction(sum(v * v for v in L), nl) + Fraction(sum(v * v for v in R), nr)
                if best is None or s > best[0]:
                    t = a / 2.0 + b / 2.0
                    if t == b:
                        t = a
                    best = (s, j, t)
                    tied = False
                elif s == best[0]:
                    tied = True
        if best is None:
            continue
        if tied:
            ties[0] += 1
        nodes[me][0], nodes[me][1] = best[1], best[2]
        lrows = [i for i in rows if x[i][best[1]] <= best[2]]
        rrows = [i for i in rows if x[i][best[1]] > best[2]]
        stack.append((rrows, me, False))
        stack.append((lrows, me, True))
    return nodes, ties[0]


def gini(inp):
    if inp["op"] == "impurity":
        c = inp["counts"]
        require(len(c) >= 1 and all(v >= 0 for v in c) and sum(c) > 0, "counts")
        n = sum(c)
        return {"gini": 1.0 - sum((v / n) * (v / n) for v in c)}
    x, y, k = _dataset(inp)
    w = inp.get("weights", [1] * len(x))
    require(len(w) == len(x) and all(v >= 0 for v in w) and sum(w) > 0, "weights")
    nodes, n_tied = _grow(x, y, k, w, 0, None)
    return {"feature": [n[0] for n in nodes], "threshold": [n[1] for n in nodes], "left": [n[2] for n in nodes],
            "right": [n[3] for n in nodes], "value": [[float(v) for v in n[4]] for n in nodes],
            "tied_splits": n_tied}


def eq6(inp):
    k = inp["classes"]
    vote = inp.get("forest_vote", "majority")
    if inp["op"] == "vote":
        q = inp["query"]
        acc, tree_classes = [0.0] * k, []
        require(len(inp["trees"]) >= 1, "trees")
        for t in inp["trees"]:
            i = 0
            for _ in range(len(t["feature"]) + 1):
                if t["feature"][i] < 0:
                    break
                i = t["left"][i] if q[t["feature"][i]] <= t["threshold"][i] else t["right"][i]
            v = t["value"][i]
            require(all(c >= 0 for c in v) and sum(v) > 0, "leaf counts")
            c = _argmax_first(v)
            tree_classes.append(c)
            if vote == "majority":
                acc[c] += 1.0
            else:
                s = sum(v)
                for cc in range(k):
                    acc[cc] += v[cc] / s
        return {"class": _argmax_first(acc), "tree_classes": tree_classes}
    x, y, k = _dataset(inp)
    n, d = len(x), len(x[0])
    m = max(1, int(math.isqrt(d)))
    gen = MT19937(inp["seed"])
    draws = 0
    trees = []
    for _ in range(inp["n_trees"]):
        w = [0] * n
        for _ in range(n):
            w[min(math.floor(gen.genrand_res53() * n), n - 1)] += 1
        counter = _Counting(gen)
        nodes, _ = _grow(x, y, k, w, m, counter)
        draws += n + counter.count
        trees.append({"feature": [nd[0] for nd in nodes], "threshold": [nd[1] for nd in nodes],
                      "value": [[float(v) for v in nd[4]] for nd in nodes]})
    return {"trees": trees, "draws": draws}


class _Counting:
    def __init__(self, gen):
        self.gen, self.count = gen, 0

    def genrand_res53(self):
        self.count += 1
        return self.gen.genrand_res53()


# ---- metrics ------------------------------------------------------------------------------------

def _confusion(inp):
    t, p, k = inp["y_true"], inp["y_pred"], inp["classes"]
    require(k >= 1 and len(t) == len(p) and len(t) >= 1, "samples")
    require(all(0 <= v < k for v in t + p), "labels in range")
    c = [[0] * k for _ in range(k)]
    for a, b in zip(t, p):
        c[a][b] += 1
    return c


def _div(a, b):
    return 0.0 if b == 0 else a / b


def _averaged(c, per_class_fn, micro):
    k = len(c)
    true_n = [sum(c[i]) for i in range(k)]
    per = per_class_fn(c)
    macro = sum(per) / k
    wsum = sum(true_n)
    weighted = 0.0 if wsum == 0 else sum(v * n for v, n in zip(per, true_n)) / wsum
    return {"per_class": per, "macro": macro, "weighted": weighted, "micro": micro}


def _prec(c):
    k = len(c)
    return [_div(c[i][i], sum(c[t][i] for t in range(k))) for i in range(k)]


def _rec(c):
    return [_div(c[i][i], sum(c[i])) for i in range(len(c))]


def _f1(c):
    return [0.0 if p + r == 0 else 2 * p * r / (p + r) for p, r in zip(_prec(c), _rec(c))]


def eq7(inp):
    c = _confusion(inp)
    return {"confusion": c, "accuracy": sum(c[i][i] for i in range(len(c))) / sum(map(sum, c))}


def _micro(c):
    tp = sum(c[i][i] for i in range(len(c)))
    return tp / sum(map(sum, c))


def eq8(inp):
    c = _confusion(inp)
    return _averaged(c, _prec, _micro(c))


def eq9(inp):
    c = _confusion(inp)
    return _averaged(c, _rec, _micro(c))


def eq10(inp):
    c = _confusion(inp)
    m = _micro(c)
    return _averaged(c, _f1, 0.0 if m == 0 else 2 * m * m / (m + m))


def eq11(inp):
    c = _confusion(inp)
    k = len(c)
    s = sum(map(sum, c))
    corr = sum(c[i][i] for i in range(k))
    t = [sum(c[i]) for i in range(k)]
    p = [sum(c[r][i] for r in range(k)) for i in range(k)]
    num = corr * s - sum(a * b for a, b in zip(p, t))
    den = (s * s - sum(v * v for v in p)) * (s * s - sum(v * v for v in t))
    return {"mcc": 0.0 if den == 0 else num / math.sqrt(den)}


# ---- folds --------------------------------------------------------------------------------------

def _fisher_yates(v, gen):
    for i in range(len(v) - 1, 0, -1):
        j = min(math.floor(gen.genrand_res53() * (i + 1)), i)
        v[i], v[j] = v[j], v[i]


def folds(inp):
    mode = inp["mode"]
    if mode == "holdout":
        n, f = inp["n"], inp["test_fraction"]
        require(0 < f < 1, "test_fraction in (0, 1)")
        nt = math.ceil(f * n)
        require(1 <= nt <= n - 1, "both parts non-empty")
        gen = MT19937(inp["seed"])
        perm = list(range(n))
        _fisher_yates(perm, gen)
        test = [False] * n
        for i in perm[:nt]:
            test[i] = True
        return {"test": test, "draws": n - 1 if n > 1 else 0}
    y, k = inp["y"], inp["k"]
    require(k >= 2 and k <= len(y), "2 <= k <= n")
    require(all(v >= 0 for v in y), "labels >= 0")
    order = []
    for v in y:
        if v not in order:
            order.append(v)
    counts = [y.count(v) for v in order]
    require(max(counts) >= k, "k <= largest class")
    sorted_codes = [c for c, n in enumerate(counts) for _ in range(n)]
    alloc = [[0] * len(order) for _ in range(k)]
    for pos, c in enumerate(sorted_codes):
        alloc[pos % k][c] += 1
    out = [0] * len(y)
    gen = MT19937(inp["seed"]) if mode == "shuffled" else None
    draws = 0
    for c, v in enumerate(order):
        block = [f for f in range(k) for _ in range(alloc[f][c])]
        if gen is not None:
            _fisher_yates(block, gen)
            draws += max(len(block) - 1, 0)
        idx = [i for i in range(len(y)) if y[i] == v]
        for i, f in zip(idx, block):
            out[i] = f
    res = {"folds": out}
    if gen is not None:
        res["draws"] = draws
    return res


RULES = {
    "cin2021.data": data,
    "cin2021.eq1": eq1,
    "cin2021.eq2": eq2,
    "cin2021.eq3": eq3,
    "cin2021.eq4": eq4,
    "cin2021.eq5": eq5,
    "cin2021.knn": knn,
    "cin2021.gini": gini,
    "cin2021.eq6": eq6,
    "cin2021.eq7": eq7,
    "cin2021.eq8": eq8,
    "cin2021.eq9": eq9,
    "cin2021.eq10": eq10,
    "cin2021.eq11": eq11,
    "cin2021.folds": folds,
}
