#!/usr/bin/env python3
"""Self-convergence of the dam-break liquid level h_L(t) (scene B).

Usage: compare.py CASES_DIR
CASES_DIR holds <case>_<n1> runs (n1 = 21, 42, 84 cells along x1); prints,
per case, the RMS over 0 < t <= 5 of h_L differences between successive
meshes (linear interpolation in time) and the observed order.
"""
import math
import os
import sys


def load(path):
    rows = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        v = line.split()
        rows.append((float(v[0]), float(v[1])))
    return rows


def interp(rows, t):
    lo, hi = 0, len(rows) - 1
    if t <= rows[0][0]:
        return rows[0][1]
    if t >= rows[-1][0]:
        return rows[-1][1]
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if rows[mid][0] <= t:
            lo = mid
        else:
            hi = mid
    (t0, h0), (t1, h1) = rows[lo], rows[hi]
    return h0 + (h1 - h0) * (t - t0) / (t1 - t0)


def main(cases):
    times = [i * 0.01 for i in range(1, 501)]
    for case in ("none", "G10", "G0.1"):
        runs = [os.path.join(cases, f"{case}_{n}", "postProcessing",
                             "liquidLevel", "0", "liquidLevel.dat")
                for n in (21, 42, 84)]
        if not all(os.path.exists(r) for r in runs):
            continue
        c, m, f = (load(r) for r in runs)
        d1 = math.sqrt(sum((interp(c, t) - interp(m, t)) ** 2
                           for t in times) / len(times))
        d2 = math.sqrt(sum((interp(m, t) - interp(f, t)) ** 2
                           for t in times) / len(times))
        print(f"{case}: RMS of h21 - h42 {d1:.4f}, h42 - h84 {d2:.4f},"
              f" observed order {math.log(d1 / d2) / math.log(2):.2f}")


if __name__ == "__main__":
    main(sys.argv[1])
