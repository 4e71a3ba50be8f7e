#!/usr/bin/env python3
"""Example `pathref conform` adapter (spec/conform.md), Python 3 standard library only.

Speaks the pathref-conform v1 JSON-lines protocol on stdin/stdout and answers with the
independent implementation of tools/crosscheck (written from spec/ alone). It announces a
handful of rules (ANNOUNCED); `pathref conform` skips every other rule without sending it.

    pathref conform --exec "python3 tools/conform/example_adapter.py" golden/
    pathref conform --exec "python3 tools/conform/example_adapter.py --planted-bug" golden/   # must fail

--planted-bug makes metrics.length forget the last step of the path (an off-by-one loop
bound), the kind of bug the golden vectors exist to catch.
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "crosscheck"))

from rules import RULES  # noqa: E402  (rule id -> function(input dict) -> output dict)
from rules.common import DomainError  # noqa: E402

ANNOUNCED = ["grid.coord", "grid.index", "grid.moves", "metrics.length", "metrics.turns", "metrics.valid-path"]


def buggy_length(inp):
    out = RULES["metrics.length"](inp)
    path = inp.get("path")
    if isinstance(path, list) and len(path) >= 2:  # forget the last step
        out = RULES["metrics.length"](dict(inp, path=path[:-1]))
    return out


def wire(v):
    """Non-finite numbers as the vectors write them: "inf", "-inf", "nan" (JSON has none)."""
    if isinstance(v, float) and not math.isfinite(v):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")
    if isinstance(v, dict):
        return {k: wire(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [wire(x) for x in v]
    return v


def main(argv):
    planted = "--planted-bug" in argv[1:]
    rules = dict(RULES)
    if planted:
        rules["metrics.length"] = buggy_length
    for line in sys.stdin:
        if not line.strip():
            continue
        req = json.loads(line)
        if "protocol" in req:  # the hello
            answer = {"protocol": "pathref-conform", "version": 1, "rules": ANNOUNCED,
                      "implementation": "tools/conform/example_adapter.py" + (" --planted-bug" if planted else "")}
        else:
            fn = rules.get(req["rule"]) if req["rule"] in ANNOUNCED else None
            if fn is None:
                answer = {"id": req["id"], "skip": "rule not implemented"}
            else:
                try:
                    answer = {"id": req["id"], "output": fn(req["input"])}
                except DomainError as e:
                    answer = {"id": req["id"], "error": "DomainError", "message": str(e)}
                except Exception as e:  # noqa: BLE001  a rule module's own ParseError, or a request it cannot read
                    kind = "ParseError" if type(e).__name__ == "ParseError" else "UsageError"
                    answer = {"id": req["id"], "error": kind, "message": repr(e)}
        sys.stdout.write(json.dumps(wire(answer), allow_nan=False) + "\n")
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
