#!/usr/bin/env python3
"""Independent cross-check of golden/ (Python 3 standard library only).

Every rule that has golden vectors is re-implemented here from spec/, without reading the C++
code, and every vector is re-evaluated and compared with its expected value under the vector's
own tolerance. CI fails on any mismatch and on any rule this checker does not implement.

Usage: crosscheck.py [GOLDEN_DIR] [-v]
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from rules import RULES  # noqa: E402  (rule id -> function(input dict) -> output dict)
from rules.common import DomainError  # noqa: E402


def compose_input(doc, group, test):
    inp = {}
    inp.update(group.get("params", {}))
    inp.update(test.get("input", {}))
    for note, option in test.get("interpretation", {}).items():
        inp[doc["notes"][note]["param"]] = option
    return inp


def _num(v):
    if isinstance(v, str):
        return {"inf": math.inf, "-inf": -math.inf, "nan": math.nan, "nan:any": math.nan}[v]
    return float(v)


def compare(expected, actual, tol, where=""):
    """Returns None on match, else a description (same semantics as the C++ runner)."""
    at = f" at {where}" if where else ""
    if expected == "nan:any":
        return None if isinstance(actual, float) and math.isnan(actual) or actual == "nan" else f"expected nan, got {actual!r}{at}"
    if isinstance(expected, bool) or isinstance(actual, bool):
        return None if expected is actual or expected == actual and type(expected) is type(actual) else f"expected {expected!r}, got {actual!r}{at}"
    if isinstance(expected, (int, float)) or expected in ("inf", "-inf", "nan"):
        if not (isinstance(actual, (int, float)) or actual in ("inf", "-inf", "nan")):
            return f"expected number {expected!r}, got {actual!r}{at}"
        if isinstance(expected, int) and isinstance(actual, int):
            return None if expected == actual else f"expected {expected}, got {actual}{at}"
        e, a = _num(expected), _num(actual)
        if math.isnan(e) or math.isinf(e) or math.isnan(a) or math.isinf(a):
            return None if (math.isnan(e) and math.isnan(a)) or e == a else f"expected {expected!r}, got {actual!r}{at}"
        allowed = max(tol.get("abs", 0.0), tol.get("rel", 0.0) * abs(e))
        return None if abs(a - e) <= allowed else f"expected {e!r}, got {a!r} (|diff| {abs(a - e)!r} > {allowed!r}){at}"
    if isinstance(expected, list):
        if not isinstance(actual, (list, tuple)):
            return f"expected a list, got {actual!r}{at}"
        if len(expected) != len(actual):
            return f"expected {len(expected)} elements, got {len(actual)}{at}"
        for i, (x, y) in enumerate(zip(expected, actual)):
            d = compare(x, y, tol, f"{where}[{i}]")
            if d:
                return d
        return None
    if isinstance(expected, dict):
        if not isinstance(actual, dict):
            return f"expected an object, got {actual!r}{at}"
        for k, v in expected.items():
            if k not in actual:
                return f"missing output {k!r}{at}"
            d = compare(v, actual[k], tol, f"{where}.{k}" if where else k)
            if d:
                return d
        return None
    return None if expected == actual else f"expected {expected!r}, got {actual!r}{at}"


def check_document(doc, path, verbose=False):
    rule = doc["rule"]
    fn = RULES.get(rule)
    if fn is None:
        return 0, [f"{path}: rule {rule} has no independent implementation in tools/crosscheck"]
    passed, failures = 0, []
    for group in doc["testGroups"]:
        for test in group["tests"]:
            tol = test.get("tolerance", group["tolerance"])
            where = f"{path} {rule} tcId {test['tcId']}"
            try:
                actual = fn(compose_input(doc, group, test))
                err = None
            except DomainError as e:
                actual, err = None, ("DomainError", str(e))
            except Exception as e:  # a rule module's own ParseError (malformed input text)
                if type(e).__name__ != "ParseError":
                    raise
                actual, err = None, ("ParseError", str(e))
            expected = test["expected"]
            if test["result"] == "invalid":
                if err is None:
                    failures.append(f"{where}: expected error {expected.get('error')}, got {actual!r}")
                elif err[0] != expected.get("error"):
                    failures.append(f"{where}: expected error {expected.get('error')}, got {err[0]}")
                else:
                    passed += 1
                continue
            if err is not None:
                failures.append(f"{where}: unexpected {err[0]}: {err[1]}")
                continue
            d = compare(expected, actual, tol)
            if d:
                failures.append(f"{where}: {d}")
            else:
                passed += 1
                if verbose:
                    print(f"ok   {where}")
    return passed, failures


def golden_files(root):
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames.sort()
        if os.path.basename(dirpath) == "schema":
            continue
        for f in sorted(filenames):
            if f.endswith(".json"):
                yield os.path.join(dirpath, f)


def main(argv):
    verbose = "-v" in argv
    args = [a for a in argv if a != "-v"]
    root = args[0] if args else os.path.join(os.path.dirname(__file__), "..", "..", "golden")
    total, failures, files = 0, [], 0
    for path in golden_files(root):
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
        files += 1
        p, f = check_document(doc, os.path.relpath(path, root), verbose)
        total += p
        failures += f
    for f in failures:
        print("FAIL " + f)
    print(f"crosscheck: {files} files, {len(RULES)} rules implemented")
    print(f"crosscheck: {total} passed, {len(failures)} failed")
    if files == 0:
        print("crosscheck: no golden files found", file=sys.stderr)
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
