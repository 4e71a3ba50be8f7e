#!/usr/bin/env python3
"""Replays the hostile-input catalogue (tests/hostile/manifest.json) against the pathref CLI.

Issue 27: hostile input never crashes, hangs or eats the machine. Every case of the manifest runs
one pathref command on a malformed input (a committed file under tests/hostile/, or one generated
at test time: deep nesting, FIFOs, directories, big answers) and must

- exit with the stated code (2 for refused input) and not with a signal,
- print on stderr a message matching the case's regex, which names the location
  (FILE:LINE:COLUMN:, FILE: /pointer:, or `cannot read ... 'PATH': REASON`),
- finish within its time bound (a HANG GUARD, not a performance test: the bound is far above a
  normal run's time) and within its memory bound, both enforced here:
    normal build:    RLIMIT_AS (address space, default 1024 MiB) and RLIMIT_FSIZE (64 MiB of
                     output per file) in the child; a timeout of 10 s per case;
    sanitizer build  (--sanitize, passed by CMake when PATHREF_SANITIZE=ON): ASan reserves
                     terabytes of address space, so RLIMIT_AS cannot be used; ASAN_OPTIONS gets
                     hard_rss_limit_mb = 2 x the case's bound (ASan's redzones and quarantine)
                     and time bounds are scaled x5;
  in both builds the runner also polls the RSS of the command's process group and kills it when
  it passes the bound (a backstop: the only bound for children the rlimit does not reach), and
  checks the peak RSS (wait4) against the bound,
- write at most max_output bytes on stdout + stderr (default 1 MiB; issue 27 item 3).

Usage: run.py PATHREF [--sanitize] [--only REGEX] [--items 1,6] [--list] [--verbose]
                      [--keep DIR] [--jobs N] [--expect-failures]
Exit 0 when every selected case passes, 1 otherwise, 2 on a broken manifest.
Standard library only.
"""
from __future__ import annotations

import argparse
import concurrent.futures
import json
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
MIB = 1 << 20
PAGE = os.sysconf("SC_PAGE_SIZE")

DEFAULT_TIMEOUT = 10.0      # seconds per case, normal build (a hang guard)
DEFAULT_MEMORY_MB = 1024    # address space per case, normal build
DEFAULT_MAX_OUTPUT = 1 << 20
FSIZE_LIMIT = 64 * MIB      # no file written by a case may grow past this
SANITIZER_TIME_FACTOR = 5
SANITIZER_MEMORY_FACTOR = 2


# argv: AS_BYTES (0: no RLIMIT_AS) FSIZE_BYTES COMMAND...
LIMIT_WRAPPER = (
    "import os, resource, sys\n"
    "a, f = int(sys.argv[1]), int(sys.argv[2])\n"
    "if a: resource.setrlimit(resource.RLIMIT_AS, (a, a))\n"
    "resource.setrlimit(resource.RLIMIT_FSIZE, (f, f))\n"
    "resource.setrlimit(resource.RLIMIT_CORE, (0, 0))\n"
    "os.execv(sys.argv[3], sys.argv[3:])\n")


class ManifestError(Exception):
    pass


# ---- generators --------------------------------------------------------------------------------

def gen_bytes(spec: dict) -> bytes:
    """The content of a generated file. Strings are written as Latin-1, so that "\\u00ff" is the
    single byte 0xFF (invalid UTF-8 on purpose) and "\\u0000" a NUL byte; write non-ASCII UTF-8
    as its bytes ("\\u00c3\\u00a9" for e-acute)."""
    kind = spec["kind"]
    enc = lambda s: s.encode("latin-1")  # noqa: E731
    if kind == "text":
        return enc(spec["text"])
    if kind == "deep":
        # prefix + open*depth + inner + close*depth + suffix
        n = int(spec["depth"])
        return enc(spec.get("prefix", "") + spec.get("open", "[") * n + spec.get("inner", "")
                   + spec.get("close", "]") * n + spec.get("suffix", ""))
    if kind == "repeat":
        return enc(spec.get("prefix", "") + spec["unit"] * int(spec["count"]) + spec.get("suffix", ""))
    if kind == "copy":
        with open(os.path.join(SOURCE, spec["from"]), "rb") as f:
            data = f.read()
        for old, new in spec.get("replace", []):
            # {deep:N} in the new text: N nested empty arrays ("[[...]]")
            new = re.sub(r"\{deep:(\d+)\}", lambda m: "[" * int(m.group(1)) + "]" * int(m.group(1)), new)
            if enc(old) not in data:
                raise ManifestError(f"copy of {spec['from']}: {old!r} not found")
            data = data.replace(enc(old), enc(new), 1)
        if "truncate" in spec:
            data = data[: int(spec["truncate"])]
        return enc(spec.get("prefix", "")) + data + enc(spec.get("suffix", ""))
    raise ManifestError(f"unknown generator kind {kind!r}")


def materialise(case: dict, casedir: str) -> dict[str, str]:
    """Creates the case's generated inputs under casedir; returns {name: absolute path}."""
    paths = {}
    for name, spec in case.get("generate", {}).items():
        path = os.path.join(casedir, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        kind = spec["kind"]
        if kind == "dir":
            os.makedirs(path, exist_ok=True)
        elif kind == "fifo":
            os.mkfifo(path)
        elif kind == "symlink":
            os.symlink(spec["to"], path)
        else:
            with open(path, "wb") as f:
                f.write(gen_bytes(spec))
        paths[name] = path
    return paths


# ---- substitution ------------------------------------------------------------------------------

PLACEHOLDER = re.compile(r"\{(f|g|src|hostile|dir|pathref|python|deepobj|deep):?([^{}]*)\}")


def substitute(text: str, ctx: dict, as_regex: bool) -> str:
    """{f:REL} a committed file under tests/hostile/, {g:NAME} a generated input, {src} the
    source tree, {hostile} tests/hostile, {dir} the case's temporary folder, {pathref} the CLI,
    {python} this interpreter, {deep:N} N nested empty arrays, {deepobj:N} N nested objects
    {"a": ... 1 ...}. In a regex every substituted text is escaped."""
    def value(m: re.Match) -> str:
        kind, arg = m.group(1), m.group(2)
        if kind == "f":
            v = os.path.join(HERE, arg)
            if not os.path.exists(v):
                raise ManifestError(f"case {ctx['id']}: no file tests/hostile/{arg}")
        elif kind == "g":
            if arg not in ctx["generated"]:
                raise ManifestError(f"case {ctx['id']}: no generated input {arg!r}")
            v = ctx["generated"][arg]
        elif kind == "src":
            v = SOURCE
        elif kind == "hostile":
            v = HERE
        elif kind == "dir":
            v = ctx["casedir"]
        elif kind == "pathref":
            v = ctx["pathref"]
        elif kind == "deep":
            v = "[" * int(arg) + "]" * int(arg)
        elif kind == "deepobj":
            v = '{"a":' * int(arg) + "1" + "}" * int(arg)
        else:
            v = sys.executable
        return re.escape(v) if as_regex else v
    if as_regex:
        # placeholders are written literally in the regex; escape nothing else
        return PLACEHOLDER.sub(value, text)
    return PLACEHOLDER.sub(value, text)


# ---- running one case --------------------------------------------------------------------------

def group_rss_mb(pgid: int) -> float:
    """The resident memory of every process of group pgid, in MiB (0 when /proc is unreadable)."""
    total = 0
    try:
        pids = [int(p) for p in os.listdir("/proc") if p.isdigit()]
    except OSError:
        return 0.0
    for pid in pids:
        try:
            with open(f"/proc/{pid}/stat", "rb") as f:
                fields = f.read().rsplit(b")", 1)[1].split()
            # fields[0] is field 3 (state): pgrp is field 5, rss (pages) field 24
            if int(fields[2]) != pgid:
                continue
            total += int(fields[21]) * PAGE
        except (OSError, ValueError, IndexError):
            continue
    return total / MIB


def describe_signal(n: int) -> str:
    try:
        return f"signal {n} ({signal.Signals(n).name})"
    except ValueError:
        return f"signal {n}"


def run_case(case: dict, opts, workroot: str) -> dict:
    cid = case["id"]
    casedir = os.path.join(workroot, re.sub(r"[^A-Za-z0-9_.-]", "_", cid))
    os.makedirs(casedir, exist_ok=True)
    ctx = {"id": cid, "casedir": casedir, "pathref": opts.pathref, "generated": {}}
    result = {"id": cid, "needs": case.get("needs", ""), "ok": False, "why": [], "seconds": 0.0,
              "rss_mb": 0.0, "exit": None}
    try:
        ctx["generated"] = materialise(case, casedir)
        argv = [opts.pathref] + [substitute(a, ctx, False) for a in case["args"]]
        stderr_re = substitute(case.get("stderr", ""), ctx, True)
        stdout_re = substitute(case.get("stdout", ""), ctx, True)
    except (ManifestError, KeyError, OSError, ValueError) as e:
        result["why"].append(f"broken case: {e}")
        return result

    timeout = float(case.get("timeout", DEFAULT_TIMEOUT))
    memory_mb = int(case.get("memory_mb", DEFAULT_MEMORY_MB))
    max_output = int(case.get("max_output", DEFAULT_MAX_OUTPUT))
    env = dict(os.environ)
    env.update(case.get("env", {}))
    if opts.sanitize:
        timeout *= SANITIZER_TIME_FACTOR
        rss_bound_mb = memory_mb * SANITIZER_MEMORY_FACTOR
        asan = env.get("ASAN_OPTIONS", "")
        env["ASAN_OPTIONS"] = (asan + ":" if asan else "") + f"hard_rss_limit_mb={rss_bound_mb}"
    else:
        rss_bound_mb = memory_mb

    # The limits are set by a small exec wrapper (this interpreter, -S -E), not by preexec_fn,
    # which is unsafe when cases run on several threads.
    as_bytes = 0 if opts.sanitize else memory_mb * MIB
    wrapper = [sys.executable, "-S", "-E", "-c", LIMIT_WRAPPER, str(as_bytes), str(FSIZE_LIMIT)]

    out_path = os.path.join(casedir, "stdout")
    err_path = os.path.join(casedir, "stderr")
    stdin_spec = case.get("stdin")
    start = time.monotonic()
    timed_out = False
    over_rss = 0.0
    with open(out_path, "wb") as out_f, open(err_path, "wb") as err_f:
        stdin = subprocess.DEVNULL
        if stdin_spec is not None:
            stdin = open(os.path.join(casedir, "stdin"), "wb+")
            stdin.write(gen_bytes(stdin_spec))
            stdin.seek(0)
        proc = subprocess.Popen(wrapper + argv, stdin=stdin, stdout=out_f, stderr=err_f, cwd=casedir, env=env,
                                start_new_session=True, close_fds=True)
        if stdin is not subprocess.DEVNULL:
            stdin.close()
        status = None
        rusage = None
        delay = 0.002
        while True:
            pid, st, ru = os.wait4(proc.pid, os.WNOHANG)
            if pid == proc.pid:
                status, rusage = st, ru
                break
            rss = group_rss_mb(proc.pid)
            if rss > rss_bound_mb:
                # backstop of the memory bound (the only one for a program the rlimit does not
                # cover): the whole process group is killed as soon as it is seen over the bound
                over_rss = rss
                try:
                    os.killpg(proc.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                _, status, rusage = os.wait4(proc.pid, 0)
                break
            if time.monotonic() - start > timeout:
                timed_out = True
                try:
                    os.killpg(proc.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                _, status, rusage = os.wait4(proc.pid, 0)
                break
            time.sleep(delay)
            delay = min(delay * 2, 0.05)
        proc.returncode = 0  # reaped here; keep Popen from waiting again
    result["seconds"] = time.monotonic() - start
    result["rss_mb"] = rusage.ru_maxrss / 1024.0 if rusage else 0.0
    with open(err_path, "rb") as f:
        err = f.read()
    with open(out_path, "rb") as f:
        out = f.read()
    result["stderr"] = err[:2000].decode("utf-8", "replace")
    code = None
    why = result["why"]
    if over_rss:
        why.append(f"MEMORY: the process group reached {over_rss:.0f} MiB of RSS, over the bound of "
                   f"{rss_bound_mb} MiB (killed)")
    elif timed_out:
        why.append(f"HANG: no exit within {timeout:g} s (killed; bound of this case"
                   f"{', x5 under the sanitizers' if opts.sanitize else ''})")
    elif os.WIFSIGNALED(status) and not over_rss:
        sig = os.WTERMSIG(status)
        extra = ""
        if sig == signal.SIGXFSZ:
            extra = f": an output file grew past {FSIZE_LIMIT // MIB} MiB"
        why.append(f"CRASH: killed by {describe_signal(sig)}{extra}")
    else:
        code = os.WEXITSTATUS(status)
    result["exit"] = code
    mem_words = (b"std::bad_alloc", b"bad_alloc", b"out of memory", b"hard rss limit exhausted",
                 b"RSS limit", b"allocator is out of memory", b"requested allocation size")
    if any(w in err for w in mem_words):
        why.append(f"MEMORY: the command ran out of its memory bound ({memory_mb} MiB"
                   f"{', RSS ' + str(rss_bound_mb) + ' MiB under ASan' if opts.sanitize else ' address space'})")
    if result["rss_mb"] > rss_bound_mb:
        why.append(f"MEMORY: peak RSS {result['rss_mb']:.0f} MiB over the bound of {rss_bound_mb} MiB")
    if b"AddressSanitizer" in err or b"runtime error:" in err or b"LeakSanitizer" in err:
        why.append("SANITIZER: a sanitizer report on stderr")
    expected = case["exit"] if isinstance(case["exit"], list) else [case["exit"]]
    if code is not None and code not in expected:
        why.append(f"exit code {code}, expected {' or '.join(map(str, expected))}")
    for hexbytes in case.get("raw_excluded", []):
        raw = bytes.fromhex(hexbytes)
        if raw in out or raw in err:
            why.append(f"the raw bytes {hexbytes} appear in the output (input echoed unescaped)")
    if len(out) + len(err) > max_output:
        why.append(f"OUTPUT: {len(out) + len(err)} bytes on stdout + stderr, more than {max_output}")
    text = err.decode("utf-8", "replace")
    for rx in [stderr_re, stdout_re] + list(case.get("stderr_excludes", [])):
        try:
            re.compile(rx)
        except re.error as e:
            why.append(f"broken case: regex /{rx}/: {e}")
            result["ok"] = False
            return result
    if stderr_re and not re.search(stderr_re, text, re.S):
        why.append(f"stderr does not match /{stderr_re}/")
    if stdout_re and not re.search(stdout_re, out.decode("utf-8", "replace"), re.S):
        why.append(f"stdout does not match /{stdout_re}/")
    output_re = case.get("output")
    if output_re:
        output_re = substitute(output_re, ctx, True)
        if not re.search(output_re, out.decode("utf-8", "replace") + text, re.S):
            why.append(f"neither stdout nor stderr matches /{output_re}/")
    if case.get("stderr_excludes"):
        for bad in case["stderr_excludes"]:
            if re.search(bad, text):
                why.append(f"stderr contains /{bad}/ (it must not)")
    result["ok"] = not why
    return result


# ---- manifest ----------------------------------------------------------------------------------

REQUIRED = ("id", "format", "needs", "args", "exit", "why")


def load_manifest(path: str) -> dict:
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    if doc.get("format") != "pathref-hostile-catalogue 1":
        raise ManifestError(f"{path}: format must be 'pathref-hostile-catalogue 1'")
    seen = set()
    for i, case in enumerate(doc["cases"]):
        for k in REQUIRED:
            if k not in case:
                raise ManifestError(f"{path}: case {i} ({case.get('id', '?')}) has no '{k}'")
        if case["id"] in seen:
            raise ManifestError(f"{path}: duplicate case id {case['id']}")
        seen.add(case["id"])
        codes = case["exit"] if isinstance(case["exit"], list) else [case["exit"]]
        if 2 in codes and not (case.get("stderr") or case.get("output")):
            raise ManifestError(f"{path}: case {case['id']}: a refused input needs a stderr regex")
        if case["needs"] not in doc["needs"]:
            raise ManifestError(f"{path}: case {case['id']}: needs {case['needs']!r} is not in 'needs'")
    return doc


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pathref")
    ap.add_argument("--manifest", default=os.path.join(HERE, "manifest.json"))
    ap.add_argument("--sanitize", action="store_true",
                    help="the CLI is an ASan build: ASan RSS limit instead of RLIMIT_AS, time x5")
    ap.add_argument("--only", help="run only cases whose id matches this regex")
    ap.add_argument("--needs", help="run only cases needing these items (comma-separated, e.g. 27.1,27.6)")
    ap.add_argument("--list", action="store_true", help="list the cases and exit")
    ap.add_argument("--verbose", "-v", action="store_true", help="print every case, not only failures")
    ap.add_argument("--keep", help="keep the generated inputs and outputs in this folder")
    ap.add_argument("--jobs", type=int, default=int(os.environ.get("PATHREF_HOSTILE_JOBS", "2")))
    ap.add_argument("--json", help="write the results as JSON to this file")
    opts = ap.parse_args(argv)
    opts.pathref = os.path.abspath(opts.pathref)
    if os.environ.get("PATHREF_SANITIZE", "").upper() in ("1", "ON", "TRUE"):
        opts.sanitize = True
    try:
        doc = load_manifest(opts.manifest)
    except (ManifestError, OSError, json.JSONDecodeError, KeyError) as e:
        print(f"hostile: broken manifest: {e}", file=sys.stderr)
        return 2
    cases = doc["cases"]
    if opts.only:
        cases = [c for c in cases if re.search(opts.only, c["id"])]
    if opts.needs:
        wanted = set(opts.needs.split(","))
        cases = [c for c in cases if c["needs"] in wanted]
    if opts.list:
        for c in cases:
            print(f"{c['id']:48} needs {c['needs']:8} exit {c['exit']}  {' '.join(c['args'])}")
        return 0
    if not os.access(opts.pathref, os.X_OK):
        print(f"hostile: not an executable: {opts.pathref}", file=sys.stderr)
        return 2
    if not cases:
        print("hostile: no case selected", file=sys.stderr)
        return 1

    workroot = opts.keep or tempfile.mkdtemp(prefix="pathref-hostile-")
    os.makedirs(workroot, exist_ok=True)
    start = time.monotonic()
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, opts.jobs)) as pool:
            results = list(pool.map(lambda c: run_case(c, opts, workroot), cases))
    finally:
        if not opts.keep:
            shutil.rmtree(workroot, ignore_errors=True)
    wall = time.monotonic() - start

    failed = [r for r in results if not r["ok"]]
    for r in results:
        if r["ok"] and not opts.verbose:
            continue
        mark = "ok  " if r["ok"] else "FAIL"
        print(f"{mark} {r['id']} (needs {r['needs']}; exit {r['exit']}, {r['seconds']:.2f} s, "
              f"{r['rss_mb']:.0f} MiB)")
        for w in r["why"]:
            print(f"       {w}")
        if not r["ok"] or opts.verbose:
            first = r.get("stderr", "").strip().splitlines()[:3]
            for line in first:
                print(f"       stderr: {line[:300]}")
    # per format and per item
    by_format: dict[str, list[int]] = {}
    by_needs: dict[str, list[int]] = {}
    fmt_of = {c["id"]: c["format"] for c in cases}
    for r in results:
        for table, key in ((by_format, fmt_of[r["id"]]), (by_needs, r["needs"])):
            t = table.setdefault(key, [0, 0])
            t[0 if r["ok"] else 1] += 1
    print("== hostile catalogue: cases per format (pass / fail) ==")
    for k in sorted(by_format):
        print(f"  {k:14} {by_format[k][0]:4} pass {by_format[k][1]:4} fail")
    print("== by the issue item each case needs ==")
    for k in sorted(by_needs):
        print(f"  {k:8} {by_needs[k][0]:4} pass {by_needs[k][1]:4} fail   {doc['needs'].get(k, '')}")
    slowest = max(results, key=lambda r: r["seconds"])
    biggest = max(results, key=lambda r: r["rss_mb"])
    print(f"hostile: {len(results) - len(failed)} passed, {len(failed)} failed of {len(results)} "
          f"in {wall:.1f} s ({'sanitizer build: ASan RSS limit, time x5' if opts.sanitize else 'RLIMIT_AS'}; "
          f"slowest {slowest['id']} {slowest['seconds']:.2f} s, largest {biggest['id']} {biggest['rss_mb']:.0f} MiB)")
    if opts.json:
        with open(opts.json, "w", encoding="utf-8") as f:
            json.dump({"wall_seconds": wall, "results": results}, f, indent=1)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
