#!/usr/bin/env python3
"""Observed orders and the error-against-run-time plot of the study.

Usage: plot.py results.csv
Writes orders.txt and errorVsRuntime.png (gnuplot): L2 error of u (and of
B_xy) against wall-clock seconds, one line per case and variant.
"""
import csv
import math
import os
import subprocess
import sys
from collections import defaultdict


def final_u(case_dir):
    """x-velocity of every cell at the last time of a case (or None)."""
    times = [t for t in os.listdir(case_dir)
             if t.replace(".", "", 1).isdigit() and float(t) > 0]
    if not times:
        return None
    text = open(os.path.join(case_dir, max(times, key=float), "U")).read()
    body = text.split("internalField", 1)[1].split("(", 1)[1]
    return [float(v.split()[0].lstrip("("))
            for v in body.split("\n")[1:] if v.startswith("(")]


def time_self_convergence(series):
    """Order in time alone: RMS difference of the final u between runs at
    successive halvings of dt on the same mesh (the spatial error cancels)."""
    lines = []
    for (case, variant), rs in sorted(series.items()):
        if case != "timeStep":
            continue
        us = [(r["dt"], final_u(f"cases/{case}_{variant}_{r['cells']}_{r['dt']}"))
              for r in rs]
        diffs = []
        for (dt1, u1), (dt2, u2) in zip(us, us[1:]):
            if u1 is None or u2 is None:
                continue
            d = math.sqrt(sum((a - b) ** 2 for a, b in zip(u1, u2)) / len(u1))
            diffs.append((f"{dt1} - {dt2}", d))
        lines.append(f"{case} {variant} (time self-convergence, final u):")
        for k, (label, d) in enumerate(diffs):
            order = ""
            if k > 0 and d > 0:
                order = f"  order {math.log(diffs[k - 1][1] / d, 2):.2f}"
            lines.append(f"  dt {label:>11}  RMS difference {d:.3e}{order}")
    return lines


def main(path):
    rows = list(csv.DictReader(open(path)))
    series = defaultdict(list)
    for r in rows:
        series[(r["case"], r["variant"])].append(r)

    lines = []
    for (case, variant), rs in sorted(series.items()):
        key = "dt" if case == "timeStep" else "cells"
        rs.sort(key=lambda r: float(r[key]), reverse=(key == "dt"))
        lines.append(f"{case} {variant} (refining {key}):")
        prev = None
        for r in rs:
            e_u, e_b = float(r["L2_u"]), float(r["L2_Bxy"])
            h = float(r["dt"]) if key == "dt" else 1.0 / float(r["cells"])
            order = ""
            if prev and all(math.isfinite(x) and x > 0
                            for x in (e_u, e_b, prev[1], prev[2])):
                ratio = math.log(prev[0] / h)
                order = (f"  order u {math.log(prev[1] / e_u) / ratio:.2f}"
                         f", B_xy {math.log(prev[2] / e_b) / ratio:.2f}")
            lines.append(f"  {key} {r[key]:>6}  L2(u) {e_u:.3e}  "
                         f"L2(Bxy) {e_b:.3e}  {r['seconds']} s{order}")
            prev = (h, e_u, e_b)
    lines += time_self_convergence(series)
    open("orders.txt", "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))

    # One panel per case, one colour per variant: u solid, B_xy dashed
    # (not for the solid gap, whose strain keeps the start-up's mean shear)
    colours = {"semiImplicit": "#1f77b4", "stabilised": "#ff7f0e",
               "stabilisedBDF2": "#d62728", "explicit": "#2ca02c"}
    os.makedirs("plotdata", exist_ok=True)
    panels = []
    for case in sorted({c for c, _ in series}):
        plots = []
        for variant in colours:
            rs = series.get((case, variant))
            if not rs:
                continue
            name = f"plotdata/{case}_{variant}.dat"
            with open(name, "w") as f:
                for r in rs:
                    if math.isfinite(float(r["L2_u"])):
                        f.write(f"{r['seconds']} {r['L2_u']} {r['L2_Bxy']}\n")
            c = colours[variant]
            plots.append(f"'{name}' u 1:2 w lp lw 2 pt 7 lc rgb '{c}' t '{variant}: u'")
            if case != "solidGap":
                plots.append(f"'{name}' u 1:3 w lp dt 2 pt 6 lc rgb '{c}' t 'B_{{xy}}'")
        panels.append(f"set title '{case}'\nplot {', '.join(plots)}")
    gp = f"""set terminal pngcairo size 1500,950 font ",10"
set output 'errorVsRuntime.png'
set logscale xy; set grid
set xlabel 'wall-clock time [s]'; set ylabel 'RMS L2 error over a period'
set key bottom left font ",8"
set multiplot layout 2,3 title 'Oscillating Couette flow: error against run time (meshes doubling; timeStep: 40 cells, dt halving)'
{chr(10).join(panels)}
unset multiplot
"""
    subprocess.run(["gnuplot"], input=gp, text=True, check=True)


if __name__ == "__main__":
    main(sys.argv[1])
