"""spec/rng.md, written from the spec and Matsumoto & Nishimura's mt19937ar.c description.

MT19937 is re-implemented here in pure Python (not via the `random` module), so that the C++
stream is checked against code that shares nothing with it. The self-test compares this
implementation with CPython's own C genrand_res53 through random.setstate.
"""
import math

from .common import require

N, M = 624, 397
MATRIX_A, UPPER, LOWER = 0x9908B0DF, 0x80000000, 0x7FFFFFFF


class MT19937:
    def __init__(self, seed):
        require(0 <= seed <= 0xFFFFFFFF, "seed must be a 32-bit unsigned integer")
        self.mt = [0] * N
        self.mt[0] = seed
        for i in range(1, N):  # init_genrand
            self.mt[i] = (1812433253 * (self.mt[i - 1] ^ (self.mt[i - 1] >> 30)) + i) & 0xFFFFFFFF
        self.mti = N

    def genrand_int32(self):
        mt = self.mt
        if self.mti >= N:
            for k in range(N):
                y = (mt[k] & UPPER) | (mt[(k + 1) % N] & LOWER)
                mt[k] = mt[(k + M) % N] ^ (y >> 1) ^ (MATRIX_A if y & 1 else 0)
            self.mti = 0
        y = mt[self.mti]
        self.mti += 1
        y ^= y >> 11
        y ^= (y << 7) & 0x9D2C5680
        y ^= (y << 15) & 0xEFC60000
        y ^= y >> 18
        return y

    def genrand_res53(self):
        a = self.genrand_int32() >> 5
        b = self.genrand_int32() >> 6
        return (a * 67108864.0 + b) * (1.0 / 9007199254740992.0)


def _unit(u):
    require(isinstance(u, (int, float)) and math.isfinite(u) and 0.0 <= u < 1.0, "u must lie in [0, 1)")
    return float(u)


def stream(inp):
    g = MT19937(inp["seed"])
    require(1 <= inp["count"] <= 10000, "count out of range")
    out = [g.genrand_int32() for _ in range(inp["count"])]
    return {"u32": out, "last": out[-1]}


def res53(inp):
    g = MT19937(inp["seed"])
    for _ in range(inp.get("skip", 0)):
        g.genrand_res53()
    require(0 <= inp["count"] <= 10000, "count out of range")
    return {"u": [g.genrand_res53() for _ in range(inp["count"])]}


def index(inp):
    u = _unit(inp["u"])
    n = inp["n"]
    require(isinstance(n, int) and n >= 1, "n must be at least 1")
    return {"k": min(math.floor(u * n), n - 1)}


def roulette(inp):
    u = _unit(inp["u"])
    w = inp["weights"]
    require(len(w) > 0, "roulette needs at least one weight")
    require(all(math.isfinite(x) and x >= 0 for x in w), "weights must be finite and >= 0")
    total = 0.0
    for x in w:
        total += x
    require(total > 0, "weights must have a positive sum")
    target = u * total
    c = 0.0
    for k, x in enumerate(w):
        c += x
        if x > 0 and c >= target:
            return {"k": k}
    raise AssertionError("unreachable")


def bernoulli(inp):
    u = _unit(inp["u"])
    p = inp["p"]
    require(math.isfinite(p) and 0.0 <= p <= 1.0, "p must lie in [0, 1]")
    return {"b": u < p}


RULES = {
    "rng.stream": stream,
    "rng.res53": res53,
    "rng.index": index,
    "rng.roulette": roulette,
    "rng.bernoulli": bernoulli,
}
