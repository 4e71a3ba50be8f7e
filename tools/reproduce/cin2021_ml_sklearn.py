#!/usr/bin/env python3
"""scikit-learn's side of `pathref reproduce cin2021-ml` (spec/cin2021-ml.md#reproduction).

Usage: cin2021_ml_sklearn.py --data FILE --seeds N --first-seed S --out FILE

Runs scikit-learn's classifiers on exactly the splits pathref uses:
  - tenfold: StratifiedKFold(n_splits=10) without shuffling (pathref's folds are identical);
  - hold-out: pathref's split (spec r[cin2021.folds]: n_test = ceil(f n), Fisher-Yates from the back
    with j = floor(u (i+1)), u = RandomState(seed).random_sample(), the same stream as rng::Stream),
    for the test fractions 0.7 (the paper's stated 1636/3820) and 0.3 (swapped), seeds S..S+N-1;
    and, for comparison, scikit-learn's own train_test_split(test_size, random_state=seed).
Writes accuracies (and macro F1, MCC for the tenfold protocol) as JSON. Needs Debian's
python3-sklearn (run with /usr/bin/python3).
"""
import argparse
import json
import math
import sys
import time

import numpy as np
import sklearn
from sklearn.ensemble import RandomForestClassifier
from sklearn.metrics import f1_score, matthews_corrcoef
from sklearn.model_selection import StratifiedKFold, train_test_split
from sklearn.naive_bayes import GaussianNB, MultinomialNB
from sklearn.neighbors import KNeighborsClassifier
from sklearn.svm import SVC

LABELS = {"Move-Forward": 0, "Slight-Right-Turn": 1, "Sharp-Right-Turn": 2, "Slight-Left-Turn": 3}

# the variants pathref reports, by pathref's row name
VARIANTS = {
    "rf": lambda: RandomForestClassifier(random_state=0),
    "rf-10": lambda: RandomForestClassifier(n_estimators=10, random_state=0),
    "knn": KNeighborsClassifier,
    "svm": SVC,
    "svm-auto": lambda: SVC(gamma="auto"),
    "gnb": GaussianNB,
    "mnb": MultinomialNB,
}


def pathref_holdout(n, fraction, seed):
    n_test = math.ceil(fraction * n)
    rs = np.random.RandomState(seed)
    perm = list(range(n))
    for i in range(n - 1, 0, -1):
        j = min(math.floor(rs.random_sample() * (i + 1)), i)
        perm[i], perm[j] = perm[j], perm[i]
    test = np.zeros(n, bool)
    test[perm[:n_test]] = True
    return test


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--data", required=True)
    ap.add_argument("--seeds", type=int, default=10)
    ap.add_argument("--first-seed", type=int, default=1)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    X, y = [], []
    with open(a.data, encoding="ascii") as fh:
        for line in fh:
            line = line.strip()
            if line:
                p = line.split(",")
                X.append([float(v) for v in p[:-1]])
                y.append(LABELS[p[-1]])
    X, y = np.array(X), np.array(y)
    t0 = time.time()
    out = {"sklearn_version": sklearn.__version__, "python": sys.version.split()[0], "tenfold": {},
           "holdout": {}, "holdout_sklearn_split": {}}
    folds = np.empty(len(y), int)
    for f, (_, te) in enumerate(StratifiedKFold(n_splits=10).split(X, y)):
        folds[te] = f
    for name, make in VARIANTS.items():
        pred = np.empty(len(y), int)
        for f in range(10):
            tr, te = folds != f, folds == f
            pred[te] = make().fit(X[tr], y[tr]).predict(X[te])
        out["tenfold"][name] = {"accuracy": float(np.mean(pred == y)),
                                "f1_macro": float(f1_score(y, pred, average="macro")),
                                "mcc": float(matthews_corrcoef(y, pred))}
        print(f"[sklearn] tenfold {name}: {100 * np.mean(pred == y):.3f} %", file=sys.stderr)
    for reading, frac in (("stated", 0.7), ("swapped", 0.3)):
        out["holdout"][reading] = {k: [] for k in VARIANTS}
        out["holdout_sklearn_split"][reading] = {k: [] for k in VARIANTS}
        for seed in range(a.first_seed, a.first_seed + a.seeds):
            test = pathref_holdout(len(y), frac, seed)
            Xa, Xb, ya, yb = train_test_split(X, y, test_size=frac, random_state=seed)
            for name, make in VARIANTS.items():
                m = make().fit(X[~test], y[~test])
                out["holdout"][reading][name].append(float(np.mean(m.predict(X[test]) == y[test])))
                m = make().fit(Xa, ya)
                out["holdout_sklearn_split"][reading][name].append(float(np.mean(m.predict(Xb) == yb)))
        print(f"[sklearn] hold-out {reading} done", file=sys.stderr)
    out["wall_s"] = time.time() - t0
    with open(a.out, "w", encoding="utf-8") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
