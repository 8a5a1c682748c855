#!/usr/bin/env python3
"""Self-convergence of the dam-break liquid level h_L(t) (scene B).

Usage: compare.py CASES_DIR
CASES_DIR holds <case>_<n1> runs (n1 = 24, 48, 96 cells along x1); prints,
per case, the RMS over 0 < t <= 5 of h_L differences between successive
meshes (linear interpolation in time) and the observed order.
"""
import math
import os
import subprocess
import sys


MESHES = (24, 48, 96)      # cells along x1; x2 and x3: 10/24 of that


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
                for n in MESHES]
        if not all(os.path.exists(r) for r in runs):
            continue
        c, m, f = (load(r) for r in runs)
        d1 = math.sqrt(sum((interp(c, t) - interp(m, t)) ** 2
                           for t in times) / len(times))
        d2 = math.sqrt(sum((interp(m, t) - interp(f, t)) ** 2
                           for t in times) / len(times))
        print(f"{case}: RMS of h{MESHES[0]} - h{MESHES[1]} {d1:.4f}, "
              f"h{MESHES[1]} - h{MESHES[2]} {d2:.4f},"
              f" observed order {math.log(d1 / d2) / math.log(2):.2f}")
        plot(case, runs)


def plot(case, runs):
    """h_L(t) on the three meshes: hL_<case>.png beside this script"""
    curves = ", ".join(f"'{r}' u 1:2 w l lw 2 t '{n} x {n * 10 // 24} x "
                       f"{n * 10 // 24}'" for r, n in zip(runs, MESHES))
    subprocess.run(["gnuplot"], check=True, text=True, input=f"""
set terminal pngcairo size 900,500 font ",11"
set output 'hL_{case}.png'
set grid; set key top right
set xlabel 't [s]'; set ylabel 'h_L at x1 = 0 [m]'
set title 'Scene B ({case}): liquid level at the left wall on three meshes'
plot {curves}
""")


if __name__ == "__main__":
    main(sys.argv[1])
