#!/usr/bin/env python3
"""A conform program (spec/conform.md) that answers hostile lines, for the hostile catalogue.

Usage: conform_answer.py MODE
It implements grid.index correctly (mode `correct`: the control case) and otherwise answers every
request with the hostile line MODE names:

  correct        right answers for grid.index (the control: pathref conform exits 0)
  deep100k       an output nested 100 000 arrays deep
  deep10k-20kb   an output nested 10 000 deep, about 20 KB per answer
  deep65         an output nested 65 deep (one over the limit of 64)
  deep64         an output whose outer object plus arrays are 64 deep (at the limit: read, then judged wrong)
  bom            a UTF-8 byte order mark before the answer object
  dup            the key "output" twice
  nul            a NUL byte inside a string of the answer
  badutf8        a byte 0xFF inside a string of the answer
  1e400          a number overflowing a double
  huge           an answer line of 17 MiB (over the 16 MiB limit of io::answer_limits)
  hello-deep     a hello nested 100 000 deep (the session fails)
Standard library only. Writes bytes, never lets Python re-encode them.
"""
import json
import sys

MODE = sys.argv[1] if len(sys.argv) > 1 else "correct"
out = sys.stdout.buffer


def send(raw: bytes) -> None:
    out.write(raw + b"\n")
    out.flush()


def grid_index(inp: dict) -> dict:
    w, h = inp.get("width"), inp.get("height")
    if not (isinstance(w, int) and isinstance(h, int)) or w < 1 or h < 1 or w * h > 1 << 28:
        raise ValueError
    if "cell" in inp:
        x, y = inp["cell"]
        if not (0 <= x < w and 0 <= y < h):
            raise ValueError
        return {"index": y * w + x}
    i = inp["index"]
    if not (0 <= i < w * h):
        raise ValueError
    return {"cell": [i % w, i // w]}


def hostile(rid: int) -> bytes:
    head = b'{"id": %d, "output": ' % rid
    if MODE == "deep100k":
        return head + b"[" * 100000 + b"]" * 100000 + b"}"
    if MODE == "deep10k-20kb":
        return head + b"[" * 10000 + b"1" + b"]" * 10000 + b"}"
    if MODE == "deep65":
        return head + b'{"index": ' + b"[" * 63 + b"]" * 63 + b"}}"
    if MODE == "deep64":
        return head + b'{"index": ' + b"[" * 62 + b"]" * 62 + b"}}"
    if MODE == "bom":
        return b"\xef\xbb\xbf" + head + b'{"index": 0}}'
    if MODE == "dup":
        return b'{"id": %d, "output": {"index": 0}, "output": {"index": 1}}' % rid
    if MODE == "nul":
        return head + b'{"index": "a\x00b"}}'
    if MODE == "badutf8":
        return head + b'{"index": "a\xffb"}}'
    if MODE == "1e400":
        return head + b'{"index": 1e400}}'
    if MODE == "huge":
        return head + b'{"index": "' + b"x" * (17 << 20) + b'"}}'
    raise SystemExit(f"conform_answer.py: unknown mode {MODE!r}")


def main() -> None:
    first = sys.stdin.buffer.readline()
    if not first:
        return
    if MODE == "hello-deep":
        send(b"[" * 100000 + b"]" * 100000)
    else:
        send(b'{"protocol": "pathref-conform", "version": 1, "rules": ["grid.index"]}')
    for line in sys.stdin.buffer:
        req = json.loads(line)
        rid = req["id"]
        if MODE in ("correct", "hello-deep"):
            try:
                ans = {"id": rid, "output": grid_index(req["input"])}
            except (ValueError, KeyError, TypeError):
                ans = {"id": rid, "error": "DomainError", "message": "out of range"}
            send(json.dumps(ans).encode())
        else:
            send(hostile(rid))


if __name__ == "__main__":
    try:
        main()
    except BrokenPipeError:
        pass
