#!/usr/bin/env python3
"""Self-test of tests/hostile/run.py: the catalogue runner must be able to fail.

Runs run.py on a small manifest against a fake CLI (a Python script written at test time) that
misbehaves on demand, and checks that each misbehaviour fails its case with the right reason:
a hang (time bound), memory growth (memory bound), a signal, output blow-up, a raw byte echoed,
a wrong exit code, a message without the location; and that a well-behaved case passes. Also runs
one real case of the catalogue against the real CLI with a wrong expected exit code (a planted
defect) and checks that it fails.

Usage: test_run.py PATHREF      Standard library only.
"""
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
RUN = os.path.join(HERE, "run.py")

FAKE = r'''#!/usr/bin/env python3
import os, signal, sys, time
mode = sys.argv[1]
if mode == "ok":
    sys.stderr.write("pathref: error: %s:3:7: expected a number\n" % sys.argv[2]); sys.exit(2)
if mode == "hang":
    time.sleep(60)
if mode == "memory":
    try:
        blocks = []
        while True:
            blocks.append(bytearray(64 << 20))
    except MemoryError:
        sys.stderr.write("pathref: internal error: std::bad_alloc\n"); sys.exit(3)
if mode == "segv":
    os.kill(os.getpid(), signal.SIGSEGV)
if mode == "blowup":
    sys.stdout.write("x" * (4 << 20)); sys.exit(1)
if mode == "raw":
    sys.stderr.buffer.write(b"pathref: error: f:1:1: got '\x00'\n"); sys.exit(2)
if mode == "nolocation":
    sys.stderr.write("pathref: error: something is wrong\n"); sys.exit(2)
if mode == "exit0":
    sys.exit(0)
'''


def case(cid, args, exit, stderr="f:\\d+:\\d+: ", **kw):
    c = {"id": cid, "format": "selftest", "needs": "selftest", "args": args, "exit": exit, "stderr": stderr,
         "why": "runner self-test"}
    c.update(kw)
    return c


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    pathref = os.path.abspath(sys.argv[1])
    failures = []
    with tempfile.TemporaryDirectory(prefix="pathref-hostile-selftest-") as tmp:
        fake = os.path.join(tmp, "fake-pathref")
        with open(fake, "w") as f:
            f.write("#!" + sys.executable + "\n" + FAKE)
        os.chmod(fake, 0o755)
        cases = [
            case("ok", ["ok", "f"], 2),
            case("hang", ["hang"], 2, timeout=1),
            case("memory", ["memory"], 2, memory_mb=256),
            case("segv", ["segv"], 2),
            case("blowup", ["blowup"], 1, stderr=""),
            case("raw", ["raw"], 2, raw_excluded=["00"]),
            case("nolocation", ["nolocation"], 2),
            case("wrong-exit", ["exit0"], 2),
        ]
        expect = {
            "ok": None,
            "hang": "HANG",
            "memory": "MEMORY",
            "segv": "CRASH: killed by signal 11",
            "blowup": "OUTPUT",
            "raw": "raw bytes 00",
            "nolocation": "stderr does not match",
            "wrong-exit": "exit code 0, expected 2",
        }
        manifest = os.path.join(tmp, "manifest.json")
        with open(manifest, "w") as f:
            json.dump({"format": "pathref-hostile-catalogue 1", "needs": {"selftest": "runner self-test"},
                       "cases": cases}, f)
        out = os.path.join(tmp, "results.json")
        sanitize = os.environ.get("PATHREF_SANITIZE", "").upper() in ("1", "ON", "TRUE")
        if sanitize:
            # the fake is not an ASan program: its memory case needs RLIMIT_AS, so run it normally
            env = dict(os.environ, PATHREF_SANITIZE="")
        else:
            env = dict(os.environ)
        p = subprocess.run([sys.executable, RUN, fake, "--manifest", manifest, "--json", out], env=env,
                           capture_output=True, text=True, timeout=120)
        if p.returncode != 1:
            failures.append(f"run.py on the self-test manifest exited {p.returncode}, expected 1 (some cases fail)\n"
                            f"{p.stdout}\n{p.stderr}")
        else:
            with open(out) as f:
                results = {r["id"]: r for r in json.load(f)["results"]}
            for cid, want in expect.items():
                r = results[cid]
                why = " | ".join(r["why"])
                if want is None and not r["ok"]:
                    failures.append(f"case {cid}: expected to pass, failed: {why}")
                elif want is not None and (r["ok"] or want not in why):
                    failures.append(f"case {cid}: expected a failure mentioning {want!r}, got ok={r['ok']}: {why}")
        # a planted defect on a real case: the catalogue's first control with a wrong exit code
        with open(os.path.join(HERE, "manifest.json")) as f:
            doc = json.load(f)
        real = next(c for c in doc["cases"] if c["id"] == "scene/bom")
        planted = dict(real, exit=0)
        with open(manifest, "w") as f:
            json.dump(dict(doc, cases=[planted]), f)
        p = subprocess.run([sys.executable, RUN, pathref, "--manifest", manifest] + (["--sanitize"] if sanitize else []),
                           capture_output=True, text=True, timeout=300)
        if p.returncode != 1 or "expected 0" not in p.stdout:
            failures.append(f"the planted defect (scene/bom expected to exit 0) was not caught: exit {p.returncode}\n"
                            f"{p.stdout}")
    for f in failures:
        print("FAIL", f)
    print(f"hostile self-test: {len(expect) + 1 - len(failures)} of {len(expect) + 1} checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
