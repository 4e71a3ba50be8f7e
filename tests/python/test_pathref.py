"""Tests of `import pathref` (issue 20; docs/python.md), run by ctest `python.pytest` with the
module from the build tree (PYTHONPATH) and /usr/bin/python3. PATHREF_CLI is the CLI built from
the same library: whole runs must give the CLI's JSON."""
import json
import os
import re
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import pathref

CLI = os.environ.get("PATHREF_CLI", "")
SOURCE = os.environ.get("PATHREF_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))


def cli(*args):
    r = subprocess.run([CLI, *args], capture_output=True, text=True, timeout=120)
    assert r.returncode in (0, 1), r.stderr
    return r.stdout


# ---- the stream -------------------------------------------------------------------------------
@pytest.mark.parametrize("seed", [0, 1, 42, 5489, 2**32 - 1])
def test_stream_is_numpy_randomstate_bit_for_bit(seed):
    s = pathref.Stream(seed)
    mine = s.random_sample(2000)
    want = np.random.RandomState(seed).random_sample(2000)
    assert mine.dtype == np.float64 and mine.shape == (2000,)
    assert np.array_equal(mine, want)  # exact, not approximate
    assert s.doubles_drawn == 2000 and s.seed == seed
    assert s.random_sample() == np.random.RandomState(seed).random_sample(2001)[-1]


def test_derived_draws_follow_the_rules():
    s, r = pathref.Stream(7), np.random.RandomState(7)
    assert s.uniform_index(10) == int(np.floor(r.random_sample() * 10))
    u = r.random_sample()
    w = [1.0, 0.0, 3.0]
    want = next(k for k, c in enumerate(np.cumsum(w)) if w[k] > 0 and c >= u * sum(w))
    assert s.roulette(w) == want
    assert s.bernoulli(0.5) == (r.random_sample() < 0.5)
    assert pathref.uniform_index(0.5, 4) == 2
    assert pathref.roulette([1.0, 1.0], 0.5) == 0  # cumsum 1.0 >= 0.5 * 2: the first (a tie)
    assert pathref.bernoulli(0.25, 0.25) is False
    with pytest.raises(ValueError):
        pathref.uniform_index(1.0, 3)


# ---- rules --------------------------------------------------------------------------------------
def test_eval_and_rules_are_the_cli_registry():
    out = pathref.eval("grid.coord", index=7, width=6, height=6)
    cli_out = json.loads(cli("eval", "grid.coord", "index=7", "width=6", "height=6"))
    assert out["output"] == cli_out["output"]
    ids = [r["id"] for r in pathref.rules()]
    cli_ids = [r["id"] for r in json.loads(cli("eval", "--list", "--json"))["rules"]]
    assert ids == cli_ids and len(ids) > 150
    graded = {r["id"]: r.get("grade") for r in pathref.rules()}
    assert graded["sensors2023.eq1"] in ("A", "B", "C") and graded["grid.coord"] is None
    assert pathref.eval("sensors2023.eq1", theta=30)["reconstructed"] is True


def test_eval_errors_are_value_errors():
    with pytest.raises(ValueError, match="has no input 'frm'"):
        pathref.eval("grid.coord", frm=1, width=6, height=6)
    with pytest.raises(ValueError, match="unknown rule"):
        pathref.eval("no.such.rule")
    with pytest.raises(ValueError):
        pathref.eval("grid.coord", index=99, width=6, height=6)  # outside the domain


# ---- plan ---------------------------------------------------------------------------------------
def shi6x6():
    rows = json.loads(cli("plan", "--builtin", "shi6x6", "--algo", "astar", "--json"))["map"]["rows"]
    return np.array([[c == "#" for c in r] for r in rows], dtype=np.uint8)  # top row first


@pytest.mark.parametrize("algo,params", [("astar", {}), ("aco", {"iterations": 5, "ants": 4}),
                                         ("iga-shi", {"generations": 3, "population": 10})])
def test_plan_whole_run_equals_the_cli_json(algo, params):
    top_first = shi6x6()
    cli_doc = json.loads(cli("plan", "--builtin", "shi6x6", "--algo", algo, "--seed", "3", "--json",
                             *sum((["--set", f"{k}={v}"] for k, v in params.items()), [])))
    start, goal = tuple(cli_doc["start"]), tuple(cli_doc["goal"])
    r = pathref.plan(top_first[::-1], start, goal, algo=algo, seed=3, **params)  # origin lower: row 0 = y 0
    for k in ("found", "path", "length", "turns", "valid", "iterations", "expansions", "best_per_iteration",
              "mean_per_iteration", "params", "policy", "seed", "algo", "converged_at"):
        assert r.json[k] == cli_doc[k], k
    assert r.json["map"]["rows"] == cli_doc["map"]["rows"]
    assert np.array_equal(r.path, np.array(cli_doc["path"]).reshape(-1, 2))
    assert r.params == cli_doc["params"] and r.json["pathref_version"] == pathref.version()


def test_plan_origin_upper_is_matlab_rows():
    top_first = shi6x6()
    h = top_first.shape[0]
    lower = pathref.plan(top_first[::-1], (0, 0), (5, 5))
    upper = pathref.plan(top_first, (0, h - 1), (5, h - 1 - 5), origin="upper")
    assert lower.length == upper.length
    conv = upper.path.copy()
    conv[:, 1] = h - 1 - conv[:, 1]
    assert np.array_equal(conv, lower.path)


def test_plan_errors():
    g = np.zeros((4, 4), dtype=bool)
    with pytest.raises(ValueError, match="unknown algo"):
        pathref.plan(g, (0, 0), (3, 3), algo="nope")
    with pytest.raises(ValueError, match="bogus"):
        pathref.plan(g, (0, 0), (3, 3), algo="aco", bogus=1)
    with pytest.raises(ValueError):
        pathref.plan(np.zeros(4), (0, 0), (3, 3))


def test_plan_is_interruptible_with_ctrl_c():
    code = textwrap.dedent("""
        import numpy as np, pathref, sys
        print("ready", flush=True)
        try:
            pathref.plan(np.zeros((40, 40), dtype=np.uint8), (0, 0), (39, 39), algo="aco",
                         iterations=100000, ants=50)
        except KeyboardInterrupt:
            print("interrupted", flush=True)
            sys.exit(0)
        sys.exit(3)
    """)
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True, env=os.environ)
    assert p.stdout.readline().strip() == "ready"
    time.sleep(1.0)
    t0 = time.monotonic()
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=60)
    assert p.returncode == 0 and "interrupted" in out
    assert time.monotonic() - t0 < 30


# ---- check, load_map, golden --------------------------------------------------------------------
def test_check_is_the_cli_checker(tmp_path):
    grid = np.zeros((3, 3), dtype=np.uint8)
    grid[1, 1] = 1  # centre blocked
    ok = pathref.check(grid, [(0, 0), (1, 0), (2, 0), (2, 1), (2, 2)])
    assert ok["valid"] and ok["length"] == 4 and ok["turns"] == 1 and ok["optimum"] == 4 and ok["ratio"] == 1
    bad = pathref.check(grid, [(0, 0), (1, 1), (2, 2)])
    assert not bad["valid"] and bad["reason"] == "blocked" and bad["index"] == 1
    cut = pathref.check(grid, [(0, 0), (1, 0), (2, 1), (2, 2)], policy="strict")
    assert cut["reason"] == "corner_cut" and cut["step"] == {"from": [1, 0], "to": [2, 1]}
    # the CLI on the same map and path
    (tmp_path / "m.grid").write_text("pathref-grid 1\nsize 3 3\nmap\n...\n.#.\n...\n")
    (tmp_path / "p.txt").write_text("0 0\n1 0\n2 1\n2 2\n")
    c = json.loads(cli("check", "--map", str(tmp_path / "m.grid"), "--path", str(tmp_path / "p.txt"), "--json"))
    p = c["paths"][0]
    for k in ("valid", "reason", "index", "step", "message", "length", "turns", "optimum"):
        assert p[k] == cut[k], k


def test_load_map_and_parse_errors(tmp_path):
    f = tmp_path / "m.grid"
    f.write_text("pathref-grid 1\nname tiny\nsize 3 2\nstart 0 0\ngoal 2 1\nmap\n.#.\n...\n")
    m = pathref.load_map(f)
    assert m["name"] == "tiny" and m["start"] == (0, 0) and m["goal"] == (2, 1) and m["format"] == "pathref-grid"
    assert m["grid"].tolist() == [[0, 0, 0], [0, 1, 0]]  # row 0 = y 0 (bottom)
    up = pathref.load_map(f, origin="upper")
    assert up["grid"].tolist() == [[0, 1, 0], [0, 0, 0]] and up["goal"] == (2, 0)
    bad = tmp_path / "bad.grid"
    bad.write_text("pathref-grid 1\nsize 3 2\nmap\n.x.\n...\n")
    with pytest.raises(pathref.ParseError) as e:
        pathref.load_map(bad)
    assert isinstance(e.value, ValueError)
    assert e.value.file == str(bad) and e.value.line == 4 and e.value.column == 2, str(e.value)
    with pytest.raises(ValueError, match="cannot read"):
        pathref.load_map(tmp_path / "missing.grid")


def test_golden_check():
    r = pathref.golden.check(os.path.join(SOURCE, "golden", "grid"))
    assert r["fail"] == 0 and r["pass"] > 20
    with pytest.raises(ValueError):
        pathref.golden.check(os.path.join(SOURCE, "spec"))  # no vectors: never a pass


def test_versions():
    assert pathref.__version__ == pathref.version() == cli("--version").split()[0]
    assert pathref.golden_set_version() in cli("--version")


# ---- docs/python.md: every python block runs as printed --------------------------------------------
def test_docs_python_md_example(tmp_path, monkeypatch):
    text = open(os.path.join(SOURCE, "docs", "python.md")).read()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "docs/python.md has no python block"
    monkeypatch.chdir(tmp_path)
    env = {}
    for b in blocks:
        exec(compile(b, "docs/python.md", "exec"), env)  # noqa: S102 - the documentation's own code
