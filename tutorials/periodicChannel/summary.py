#!/usr/bin/env python3
"""Summary of the periodic channel cases: Q/Q_th and nu_m/nu0 per case.

Usage: summary.py CASES_DIR RESULTS_DIR
Writes RESULTS_DIR/summary.csv.  Q is the flow rate per unit depth
(-sum of phi over the cyclic patch 'left', whose normal points in -x,
divided by the depth), averaged over the last 10% of the run.
"""
import csv
import math
import os
import re
import subprocess
import sys


def param(case, key):
    out = subprocess.run(
        ["foamDictionary", "-entry", key, "-value",
         os.path.join(case, "system", "parameters")],
        check=True, capture_output=True, text=True).stdout
    return float(out.split()[0])


def word(case, key, default):
    out = subprocess.run(
        ["foamDictionary", "-entry", key, "-value",
         os.path.join(case, "system", "parameters")],
        capture_output=True, text=True).stdout.split()
    return out[0] if out else default


def flow_rate(case):
    """(t, sum phi) samples; a restarted run's later time directories
    replace the earlier one's samples from their start on."""
    base = os.path.join(case, "postProcessing", "flowRate")
    rows = []
    for start in sorted(os.listdir(base), key=float):
        rows = [r for r in rows if r[0] <= float(start)]
        with open(os.path.join(base, start, "surfaceFieldValue.dat")) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                t, s = line.split()[:2]
                if float(t) > float(start):
                    rows.append((float(t), float(s)))
    return rows


def cells(case):
    with open(os.path.join(case, "constant", "polyMesh", "owner")) as f:
        m = re.search(r"nCells:\s*(\d+)", f.read(2000))
    return int(m.group(1)) if m else 0


def main(cases_dir, results_dir):
    names = sorted(os.listdir(cases_dir))
    rows = []
    for name in names:
        case = os.path.join(cases_dir, name)
        f, L, rho, mu = (param(case, k) for k in ("f", "L", "rho", "mu"))
        depth, n, r = (param(case, k) for k in ("depth", "nDisks", "radius"))
        rigid = n > 0 and word(case, "rigid", "no") in ("yes", "on", "true")
        G = "rigid" if rigid else (param(case, "G") if n > 0 else 0.0)
        end = param(case, "endTime")
        q_th = f * L**3 * rho / (12 * mu)
        data = flow_rate(case)
        tail = [-s / depth for t, s in data if t >= 0.9 * end]
        if not tail:
            sys.exit(f"{case}: no flow rate samples after t = {0.9 * end}")
        q = sum(tail) / len(tail)
        frac = n * math.pi * r**2 / L**2
        rows.append({
            "case": name, "G": G, "nDisks": int(n),
            "areaFraction": round(frac, 4), "cells": cells(case),
            "endTime": end, "Qth": f"{q_th:.6g}", "Q": f"{q:.6g}",
            "Q/Qth": f"{q / q_th:.4f}", "nu_m/nu0": f"{q_th / q:.4f}",
            "dilute_rigid_1+2phi": f"{1 + 2 * frac:.4f}",
        })
    os.makedirs(results_dir, exist_ok=True)
    with open(os.path.join(results_dir, "summary.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main(*sys.argv[1:3])
