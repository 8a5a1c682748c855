#!/usr/bin/env python3
"""Stiffness benchmark: one CSV row per case, or the judgement of the CSV.

  evaluate.py CASE SCENE RATIO G UREF WALL   -> a row of results/stiffness.csv
  evaluate.py --judge CSV                    -> PASS/FAIL lines per target
"""
import csv
import glob
import math
import sys


def table(pattern):
    """Rows of the numbers of a function object's .dat files (all times)."""
    rows = []
    for path in sorted(glob.glob(pattern)):
        for line in open(path):
            if line.startswith("#") or not line.strip():
                continue
            parts = line.split()
            try:
                rows.append([float(p) for p in parts if not p.isalpha()])
            except ValueError:
                continue
    return rows


def header(pattern):
    for path in sorted(glob.glob(pattern)):
        for line in open(path):
            if line.startswith("# Time"):
                return line[1:].split()
    return []


def row(case, scene, ratio, G, uref, wall):
    log = open(f"{case}/log.vheFoam").read()
    steps = log.count("\nTime = ")
    ended = "\nEnd\n" in log
    maxu = table(f"{case}/postProcessing/maxU/*/fieldMinMax.dat")
    # columns: Time, min, max (the field name dropped)
    umax = max(r[-1] for r in maxu) if maxu else float("nan")
    pat = f"{case}/postProcessing/solidDiagnostics/*/solidDiagnostics.dat"
    cols = header(pat)
    diag = table(pat)
    det = max(r[cols.index("maxDetDrift")] for r in diag)
    dev = max(r[cols.index("maxDevB")] for r in diag)
    xc = diag[-1][cols.index("centroid_x")]
    yc = diag[-1][cols.index("centroid_y")]
    print(f"{scene},{ratio},{G},{steps},{umax/float(uref):.4g},{det:.3g},"
          f"{dev:.4g},{wall},{xc:.6f},{yc:.6f},{'yes' if ended else 'no'}")


def judge(path):
    rows = list(csv.DictReader(open(path)))
    ok = True
    for scene in dict.fromkeys(r["scene"] for r in rows):
        rs = [r for r in rows if r["scene"] == scene]
        base = int(rs[0]["steps"])
        stiffest = rs[-1]
        for r in rs:
            cond = (r["ended"] == "yes" and int(r["steps"]) <= 1.2*base
                    and float(r["maxUByUref"]) <= 1.1)
            ok &= cond
            print(f"{'PASS' if cond else 'FAIL'} {scene} G/(rho U^2) "
                  f"{r['ratio']}: {r['steps']} steps ({base} at the softest),"
                  f" max |U|/U {r['maxUByUref']}, det drift {r['detDrift']},"
                  f" {r['wallTime']} s")
        # the disk's path converges to the stiffest one's
        d = [math.hypot(float(r["xc"]) - float(stiffest["xc"]),
                        float(r["yc"]) - float(stiffest["yc"]))
             for r in rs[:-1]]
        print(f"  {scene}: centroid distance to the stiffest disk's, by G: "
              + " ".join(f"{x:.2e}" for x in d))
    return ok


if __name__ == "__main__":
    if sys.argv[1] == "--judge":
        sys.exit(0 if judge(sys.argv[2]) else 1)
    row(*sys.argv[1:7])
