"""Self-test of the crosscheck's Mecanum model: the hand-written pseudo-inverse really is a left
inverse of J and its residual really is the least-squares residual (checked against the normal
equations solved by Gaussian elimination, a method that shares nothing with the closed form)."""
import random
import unittest

from rules import mecanum as M


def solve3(a, b):
    """Solves the 3x3 system a x = b by Gaussian elimination with partial pivoting."""
    a = [row[:] + [b[i]] for i, row in enumerate(a)]
    for c in range(3):
        p = max(range(c, 3), key=lambda r: abs(a[r][c]))
        a[c], a[p] = a[p], a[c]
        for r in range(c + 1, 3):
            f = a[r][c] / a[c][c]
            a[r] = [x - f * y for x, y in zip(a[r], a[c])]
    x = [0.0, 0.0, 0.0]
    for r in (2, 1, 0):
        x[r] = (a[r][3] - sum(a[r][k] * x[k] for k in range(r + 1, 3))) / a[r][r]
    return x


class TestMecanum(unittest.TestCase):
    def setUp(self):
        self.rng = random.Random(2022)

    def geometry(self):
        return self.rng.uniform(0.01, 0.2), self.rng.uniform(0.05, 0.5), self.rng.uniform(0.05, 0.5)

    def test_fk_is_a_left_inverse_of_ik(self):
        for _ in range(500):
            r, lx, ly = self.geometry()
            t = [self.rng.uniform(-5, 5) for _ in range(3)]
            w = M.ik({"vx": t[0], "vy": t[1], "omega": t[2], "r": r, "lx": lx, "ly": ly})["w"]
            back = M.fk({"w": w, "r": r, "lx": lx, "ly": ly})
            for got, want in zip((back["vx"], back["vy"], back["omega"]), t):
                self.assertAlmostEqual(got, want, places=10)

    def test_fk_solves_the_normal_equations(self):
        for _ in range(500):
            r, lx, ly = self.geometry()
            k = lx + ly
            j = [[sx, sy, sk * k] for sx, sy, sk in M.J_SIGNS]
            w = [self.rng.uniform(-100, 100) for _ in range(4)]
            jtj = [[sum(j[i][a] * j[i][b] for i in range(4)) for b in range(3)] for a in range(3)]
            jtw = [sum(j[i][a] * r * w[i] for i in range(4)) for a in range(3)]
            want = solve3(jtj, jtw)
            got = M.fk({"w": w, "r": r, "lx": lx, "ly": ly})
            for g, x in zip((got["vx"], got["vy"], got["omega"]), want):
                self.assertAlmostEqual(g, x, delta=1e-9 * max(1.0, abs(x)))
            res = M.residual({"w": w, "r": r, "lx": lx, "ly": ly})
            proj = M.ik({"vx": got["vx"], "vy": got["vy"], "omega": got["omega"], "r": r, "lx": lx, "ly": ly})["w"]
            for i in range(4):
                self.assertAlmostEqual(res["projection"][i], proj[i], delta=1e-9 * max(1.0, abs(proj[i])))

    def test_trapezoid_closed_forms(self):
        for _ in range(500):
            d, v, a = self.rng.uniform(0, 20), self.rng.uniform(0.1, 5), self.rng.uniform(0.1, 5)
            t = M.trapezoid({"d": d, "v0": 0.0, "v1": 0.0, "v_max": v, "a": a})["time"]
            want = 2 * (d / a) ** 0.5 if d <= v * v / a else d / v + v / a
            self.assertAlmostEqual(t, want, delta=1e-12 * max(1.0, want))


if __name__ == "__main__":
    unittest.main()
