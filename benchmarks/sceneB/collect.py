#!/usr/bin/env python3
"""Scene B at several meshes: one table and one h_L plot per case.

Usage: collect.py CASES_DIR RESULTS_DIR
CASES_DIR holds n<N>/ (a copy of tutorials/damBreakSpheres run with
-cells N, its results/damping.csv and results/hL_<case>.dat written by the
tutorial's postProcess.sh).  Writes RESULTS_DIR/sceneB.csv (cells, case,
RMS and range of h_L over 1 <= t <= 5 and their ratios to "none", steps,
solver wall time summed over the restarted chunks) and hL_<case>.png.
"""
import csv
import glob
import os
import re
import subprocess
import sys


def wall(case):
    """Solver wall seconds (the last Progress line of every chunk's log)
    and steps (one h_L row a step)"""
    total = 0.0
    for log in glob.glob(os.path.join(case, "log.vheFoam.*")):
        last = None
        for line in open(log, errors="replace"):
            m = re.match(r"Progress: .* wall ([0-9.eE+-]+) s", line)
            if m:
                last = float(m.group(1))
        total += last or 0.0
    return total


def main(cases, results):
    os.makedirs(results, exist_ok=True)
    meshes = sorted(int(d[1:]) for d in os.listdir(cases)
                    if re.fullmatch(r"n\d+", d)
                    and os.path.exists(os.path.join(cases, d, "results",
                                                    "damping.csv")))
    rows = []
    for n in meshes:
        res = os.path.join(cases, f"n{n}", "results")
        for r in csv.DictReader(open(os.path.join(res, "damping.csv"))):
            name = r["case"]
            hl = os.path.join(res, f"hL_{name}.dat")
            steps = sum(1 for l in open(hl) if not l.startswith("#"))
            cells = n * (20 * n // 42) ** 2
            rows.append([n, cells, name, r["rms_hL_1to5"], r["range_hL_1to5"],
                         r["rms/none"], r["range/none"], r["t_end"], steps,
                         f"{wall(os.path.join(cases, f'n{n}', 'cases', name)):.0f}"])
    with open(os.path.join(results, "sceneB.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["n1", "cells", "case", "rms_hL", "range_hL", "rms/none",
                    "range/none", "t_end", "steps", "wall_s"])
        w.writerows(rows)
    for name in ("none", "G0.1", "G10"):
        curves = [f"'{cases}/n{n}/results/hL_{name}.dat' u 1:2 w l lw 2 "
                  f"t '{n} x {20 * n // 42} x {20 * n // 42}'" for n in meshes
                  if os.path.exists(f"{cases}/n{n}/results/hL_{name}.dat")]
        if not curves:
            continue
        subprocess.run(["gnuplot"], check=True, text=True, input=f"""
set terminal pngcairo size 900,500 font ",11"
set output '{results}/hL_{name}.png'
set grid; set key top right
set xlabel 't [s]'; set ylabel 'h_L at x1 = 0 [m]'
set title 'Scene B ({name}): liquid level at the left wall, three meshes'
plot {", ".join(curves)}
""")


if __name__ == "__main__":
    main(*sys.argv[1:3])
