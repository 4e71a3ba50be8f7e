#!/usr/bin/env python3
"""Writes the MovingAI sample scenario files of tests/data/movingai/ from the hand-drawn map
tests/data/movingai/rooms40x30.map, with optimal lengths computed HERE by an independent
Dijkstra (not by pathref): 8-connected, diagonal sqrt(2), no corner cutting (a diagonal step
needs both orthogonal neighbours passable), '.', 'G', 'S' passable, '@', 'O', 'T', 'W' blocked.
Lengths are printed like the MovingAI files: C++ stream default precision 6 ('%g').
Coordinates: MovingAI (0,0) = upper left, x = column, y = row from the top.
Run from the repository root:  python3 tests/data/make_samples.py
"""
import heapq
import math
import random

MAP = "tests/data/movingai/rooms40x30.map"


def read_map(path):
    with open(path) as f:
        lines = f.read().split("\n")
    assert lines[0] == "type octile"
    h = int(lines[1].split()[1])
    w = int(lines[2].split()[1])
    assert lines[3] == "map"
    rows = lines[4:4 + h]
    assert all(len(r) == w for r in rows)
    return w, h, [[c in ".GS" for c in r] for r in rows]


def dijkstra(w, h, free, s):
    dist = {s: 0.0}
    pq = [(0.0, s)]
    while pq:
        d, (x, y) = heapq.heappop(pq)
        if d > dist[(x, y)]:
            continue
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                if dx == 0 and dy == 0:
                    continue
                nx, ny = x + dx, y + dy
                if not (0 <= nx < w and 0 <= ny < h) or not free[ny][nx]:
                    continue
                if dx != 0 and dy != 0 and not (free[y][nx] and free[ny][x]):
                    continue
                nd = d + (math.sqrt(2) if dx and dy else 1.0)
                if nd < dist.get((nx, ny), math.inf):
                    dist[(nx, ny)] = nd
                    heapq.heappush(pq, (nd, (nx, ny)))
    return dist


def main():
    w, h, free = read_map(MAP)
    cells = [(x, y) for y in range(h) for x in range(w) if free[y][x]]
    rng = random.Random(20261122)
    v1 = ["version 1"]
    v0 = []
    while len(v1) < 41:
        s, g = rng.sample(cells, 2)
        d = dijkstra(w, h, free, s).get(g)
        if d is None:
            continue
        length = "%g" % d
        bucket = int(d // 4)
        v1.append("\t".join(map(str, [bucket, "maps/samples/rooms40x30.map", w, h, s[0], s[1], g[0], g[1], length])))
        if len(v0) < 12:
            v0.append("\t".join(map(str, [bucket, "rooms40x30.map", s[0], s[1], g[0], g[1], length])))
    with open("tests/data/movingai/rooms40x30.map.scen", "w") as f:
        f.write("\n".join(v1) + "\n")
    with open("tests/data/movingai/rooms40x30-v0.scen", "w") as f:
        f.write("\n".join(v0) + "\n")


if __name__ == "__main__":
    main()
