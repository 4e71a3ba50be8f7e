"""pathref from Python: the reference implementation's own C++ library (no second implementation).

    import numpy as np, pathref
    grid = np.zeros((6, 6), dtype=np.uint8); grid[2, 1:5] = 1       # 1 = blocked
    r = pathref.plan(grid, (0, 0), (5, 5), algo="aco", seed=7, iterations=20)
    print(r.length, r.path)                                           # path: (N, 2) array of (x, y)
    print(pathref.check(grid, r.path)["valid"])

Coordinates: a cell is (x, y) = (column, row) of the array as you pass it. With
``origin="lower"`` (default) array row 0 is pathref's y = 0 (the bottom row of its figures); with
``origin="upper"`` (MATLAB/image style) row 0 is the top row, and pathref converts both ways, so
paths come back in your convention. ``Result.json`` is pathref's own JSON (y up), equal to
``pathref plan --json``. Errors: ``ParseError`` (a ValueError with ``file``, ``line``,
``column``) for malformed files, ``ValueError`` for arguments outside a rule's domain or unknown
names, ``KeyboardInterrupt`` when Ctrl-C stops a run at an iteration boundary. docs/python.md.
"""
import json as _json

import numpy as _np

from . import _pathref
from ._pathref import ParseError, Stream, bernoulli, roulette, uniform_index  # noqa: F401

__all__ = ["Stream", "ParseError", "eval", "rules", "plan", "Result", "check", "load_map", "golden",
           "uniform_index", "roulette", "bernoulli", "version", "golden_set_version"]
__version__ = _pathref.version()


def version():
    """pathref's version (CMakeLists.txt), as `pathref --version` prints first."""
    return _pathref.version()


def golden_set_version():
    """The golden-vector set this module was built with (golden/MANIFEST)."""
    return _pathref.golden_set_version()


def eval(rule, **inputs):  # noqa: A001 - the CLI's name
    """Evaluates spec rule `rule` at `inputs` (the same registry as `pathref eval`).

    Returns {"rule", "input", "output"} (+ "grade", "reconstructed" for a reconstructed rule).
    ValueError for an unknown rule, an unknown input name or an input outside the domain."""
    return _json.loads(_pathref._eval(rule, _json.dumps(inputs, default=_plain)))


def rules():
    """Every rule: id, summary, function, inputs, outputs (and grade), as `pathref eval --list --json`."""
    return _json.loads(_pathref._rules())["rules"]


def _plain(x):
    """JSON for NumPy scalars and arrays."""
    if isinstance(x, _np.ndarray):
        return x.tolist()
    if isinstance(x, _np.generic):
        return x.item()
    raise TypeError(f"not JSON serialisable: {type(x).__name__}")


def _blocked(grid, origin):
    a = _np.asarray(grid)
    if a.ndim != 2:
        raise ValueError(f"the grid must be a 2-D array (rows, columns), got {a.ndim} dimensions")
    if origin not in ("lower", "upper"):
        raise ValueError(f"origin must be 'lower' or 'upper', got {origin!r}")
    b = (a != 0).astype(_np.uint8)
    return _np.ascontiguousarray(b[::-1] if origin == "upper" else b)


def _to_pathref(cell, height, origin):
    x, y = (int(v) for v in cell)
    return (x, height - 1 - y) if origin == "upper" else (x, y)


def _from_pathref(cells, height, origin):
    p = _np.asarray(cells, dtype=_np.int64).reshape(-1, 2)
    if origin == "upper" and len(p):
        p = p.copy()
        p[:, 1] = height - 1 - p[:, 1]
    return p


class Result:
    """One planner run: what `pathref plan --json` prints, with the path in your convention.

    Attributes: found, path ((N, 2) int64 array of (x, y)), length, turns, valid, expansions,
    iterations, best_per_iteration, mean_per_iteration (NumPy arrays; NaN where an iteration found
    no path), converged_at, params (every parameter used), seed, algo, policy, extra, json (the
    whole pathref-plan object, pathref's own coordinates)."""

    def __init__(self, doc, height, origin):
        self.json = doc
        self.found = doc["found"]
        self.path = _from_pathref(doc["path"], height, origin)
        for k in ("length", "turns", "valid", "expansions", "iterations", "converged_at", "params", "seed",
                  "algo", "policy", "extra"):
            setattr(self, k, doc.get(k))
        nan = float("nan")
        self.best_per_iteration = _np.array([nan if v is None else v for v in doc["best_per_iteration"]], dtype=float)
        self.mean_per_iteration = _np.array([nan if v is None else v for v in doc["mean_per_iteration"]], dtype=float)

    def __repr__(self):
        return (f"pathref.Result(algo={self.algo!r}, seed={self.seed}, found={self.found}, "
                f"length={self.length}, nodes={len(self.path)})")


def plan(grid, start, goal, algo="astar", seed=1, policy=None, origin="lower", **params):
    """Runs planner `algo` (as `pathref plan --algo`) on a 2-D array (nonzero = blocked).

    `start`, `goal`: (x, y) cells in the array's convention (`origin`). `policy`: the corner policy
    (None: the planner's default, as the CLI). `params`: planner parameters (as --set), e.g.
    iterations=20. The GIL is released while the planner runs; Ctrl-C stops it at the next
    iteration boundary (KeyboardInterrupt)."""
    b = _blocked(grid, origin)
    h = b.shape[0]
    doc = _json.loads(_pathref._plan(b, _to_pathref(start, h, origin), _to_pathref(goal, h, origin), algo,
                                     int(seed), policy or "", _json.dumps(params, default=_plain), "python array"))
    return Result(doc, h, origin)


def check(grid, path, start=None, goal=None, policy="strict", origin="lower"):
    """The checker of `pathref check`: is `path` ((N, 2) cells (x, y)) a legal plan on `grid`?

    Returns {"valid", "reason", "index", "step", "message", "length", "turns", "optimum", "ratio",
    "clearance", "nodes", "policy"} (spec/check.md). `start`/`goal` default to the path's ends."""
    b = _blocked(grid, origin)
    h = b.shape[0]
    p = _np.asarray(path, dtype=_np.int64).reshape(-1, 2)
    if start is None and len(p) == 0:
        raise ValueError("an empty path needs start and goal")
    s = _to_pathref(p[0] if start is None else start, h, origin)
    t = _to_pathref(p[-1] if goal is None else goal, h, origin)
    q = _from_pathref(p, h, origin)  # the conversion is its own inverse
    r = _json.loads(_pathref._check(b, _np.ascontiguousarray(q), s, t, policy))
    if r.get("step"):
        r["step"] = {k: [int(v) for v in _from_pathref([c], h, origin)[0]] for k, c in r["step"].items()}
    return r


def load_map(file, origin="lower"):
    """Reads a map file of any format pathref reads (pathref-grid, MovingAI, matrix, MATLAB, ROS
    YAML, polygon scene). Returns {"grid": (H, W) uint8 array (1 = blocked), "start", "goal"
    ((x, y) or None), "name", "format"}; rows in the `origin` convention."""
    a, s, t, name, fmt = _pathref._load_map(str(file))
    h = a.shape[0]
    conv = (lambda c: None if c is None else tuple(int(v) for v in _from_pathref([c], h, origin)[0]))
    return {"grid": a[::-1].copy() if origin == "upper" else a, "start": conv(s), "goal": conv(t), "name": name,
            "format": fmt}


class _Golden:
    """pathref.golden.check(dir): the library against a folder of golden vectors."""

    @staticmethod
    def check(directory):
        """Returns {"pass", "fail", "skipped", "failures": [{file, rule, tcId, message}]}."""
        return _json.loads(_pathref._golden_check(str(directory)))


golden = _Golden()
