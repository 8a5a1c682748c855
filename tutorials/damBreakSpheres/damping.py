#!/usr/bin/env python3
"""h_L(t) per case and a damping measure of the dam-break cases.

Usage: damping.py CASES_DIR RESULTS_DIR
Writes RESULTS_DIR/hL_<case>.dat (t, h_L at x1 = 0) and damping.csv with,
over 1 <= t <= 5 (the sloshing after the first run-up), the time-weighted
RMS of h_L about its mean (the amplitude measure), the range max - min,
and both as a ratio to the case without spheres.
"""
import csv
import math
import os
import sys

T0, T1 = 1.0, 5.0


def level(case):
    """h_L(t) from every start time's file (a restarted run writes one
    directory per start), the later start taking over from its time on"""
    base = os.path.join(case, "postProcessing", "liquidLevel")
    rows = []
    for start in sorted(os.listdir(base), key=float):
        path = os.path.join(base, start, "liquidLevel.dat")
        if not os.path.exists(path):
            continue
        rows = [r for r in rows if r[0] < float(start)]
        with open(path) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                v = line.split()
                rows.append((float(v[0]), float(v[1])))
    return rows


def amplitude(rows):
    w = [(t, h) for t, h in rows if T0 <= t <= T1]
    if len(w) < 2:
        return float("nan"), float("nan"), 0.0
    span = w[-1][0] - w[0][0]
    # trapezoidal time averages (the steps are not uniform)
    mean = sum((b[0] - a[0]) * (a[1] + b[1]) / 2 for a, b in zip(w, w[1:])) / span
    var = sum((b[0] - a[0]) * ((a[1] - mean) ** 2 + (b[1] - mean) ** 2) / 2
              for a, b in zip(w, w[1:])) / span
    return math.sqrt(var), max(h for _, h in w) - min(h for _, h in w), w[-1][0]


def main(cases_dir, results_dir):
    os.makedirs(results_dir, exist_ok=True)
    table = {}
    for name in sorted(os.listdir(cases_dir)):
        rows = level(os.path.join(cases_dir, name))
        with open(os.path.join(results_dir, f"hL_{name}.dat"), "w") as f:
            f.write("# t h_L(x1=0)\n")
            for t, h in rows:
                f.write(f"{t:.6g} {h:.6g}\n")
        table[name] = amplitude(rows)
    ref = table.get("none")
    with open(os.path.join(results_dir, "damping.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "rms_hL_1to5", "range_hL_1to5", "rms/none",
                    "range/none", "t_end"])
        for name, (rms, rng, tend) in table.items():
            w.writerow([name, f"{rms:.4g}", f"{rng:.4g}",
                        f"{rms / ref[0]:.3f}" if ref else "",
                        f"{rng / ref[1]:.3f}" if ref else "", f"{tend:.3g}"])


if __name__ == "__main__":
    main(*sys.argv[1:3])
