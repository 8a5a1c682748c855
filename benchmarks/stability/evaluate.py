#!/usr/bin/env python3
"""Verdicts of the stability suite (benchmarks/stability/Allrun).

Usage: evaluate.py CASES_DIR CSV
For every run in CASES_DIR: did it end (no NaN, no fatal error), the worst
excursion of any phase fraction outside [0, 1], the largest relative drift
of any material's volume (vheFoam's "Phase <name> volume" lines, every
step, summed over the material's colours),
the smallest eigenvalue of B* and the largest |det B - 1| and |dev B| of
solid cells, and, in closed undriven boxes, the largest growth of the total
energy (kinetic + elastic + potential) between writes and the largest gain
of the balance (total + viscous dissipation; information only: the
potential and dissipation integrals are not the scheme's own discrete
ones) (solidDiagnostics).  Prints a table and one "PASS name: ..." or
"FAIL name: ..." line per run, and writes CSV.
"""
import csv
import glob
import math
import os
import re
import sys

ALPHA_TOL = 1e-6      # every alpha in [-tol, 1 + tol]
VOLUME_TOL = 1e-6     # relative drift of every fluid's volume
SOLID_VOLUME_TOL = 1e-12  # and of every solid material's (issue 25): bodies
                      # are carried geometrically and settled conservatively
EIG_TOL = -1e-9       # B* positive semi-definite
DET_TOL = 1e-8        # |det B - 1| in solid cells (phi_s > 0.5): log B is
                      # carried, det B = 1 up to round-off
ENERGY_FLOOR = 1e-30  # [J] round-off: speeds of 1e-15 m/s in the unit box
ENERGY_TOL = 1e-6     # growth of total energy between writes, relative to
                      # the largest kinetic + elastic energy (closed,
                      # undriven boxes only: a file "closedUndriven" in the
                      # case)

PHASE = re.compile(r"^Phase (\S+) volume (\S+)\s+fraction min, max = (\S+) (\S+)",
                   re.M)


def evaluate(case):
    log = open(os.path.join(case, "log.vheFoam"), errors="replace").read()
    ended = bool(re.search(r"^End\s*$", log, re.M)) and "FOAM FATAL" not in log \
        and not re.search(r"\bnan\b", log, re.I)
    steps = len(re.findall(r"^Time = ", log, re.M))
    # Volumes per material, summed over its colours (<name>.<k>): a body
    # moved to another colour (bodyColours) changes the colours' volumes,
    # not the material's
    volumes, alphaWorst = {}, 0.0
    for block in re.split(r"^Time = ", log, flags=re.M):
        sums = {}
        for name, v, lo, hi in PHASE.findall(block):
            material = re.sub(r"\.\d+$", "", name)
            sums[material] = sums.get(material, 0.0) + float(v)
            alphaWorst = max(alphaWorst, -float(lo), float(hi) - 1)
        for material, v in sums.items():
            volumes.setdefault(material, []).append(v)
    def drifts(names):
        return max((max(abs(x / volumes[m][0] - 1) for x in volumes[m])
                    for m in names if volumes[m][0] > 0), default=0.0)
    solids = set(re.findall(r"(\S+) \(solid,", log)) if "Phases:" in log else set()
    solids = {re.sub(r"\.\d+$", "", m) for m in solids}
    drift = drifts(volumes)
    solidDrift = drifts([m for m in volumes if m in solids])
    minEig, detDrift, devB = math.inf, 0.0, 0.0
    total, balance, scale = [], [], 0.0
    diag = os.path.join(case, "postProcessing", "solidDiagnostics", "0",
                        "solidDiagnostics.dat")
    if os.path.exists(diag):
        for line in open(diag):
            if line.startswith("#") or not line.strip():
                continue
            c = [float(x) for x in line.split()]
            devB, minEig, detDrift = max(devB, c[2]), min(minEig, c[3]), \
                max(detDrift, c[4])
            scale = max(scale, c[5] + c[6])
            total.append(c[8])
            balance.append(c[10])
    closed = os.path.exists(os.path.join(case, "closedUndriven"))
    growth = gain = ""
    if closed and len(total) > 1:
        # a body at rest (scale at round-off) is judged against the floor
        scale = max(scale, ENERGY_FLOOR)
        growth = max(0.0, max(b - a for a, b in zip(total, total[1:]))) / scale
        gain = max(0.0, max(b - balance[0] for b in balance)) / scale
    seconds = open(os.path.join(case, "time")).read().strip() \
        if os.path.exists(os.path.join(case, "time")) else ""
    failed = []
    if not ended:
        failed.append("did not end")
    if alphaWorst > ALPHA_TOL:
        failed.append(f"alpha out of [0, 1] by {alphaWorst:.2e}")
    if drift > VOLUME_TOL:
        failed.append(f"volume drift {drift:.2e}")
    if solidDrift > SOLID_VOLUME_TOL:
        failed.append(f"solid volume drift {solidDrift:.2e}")
    if minEig < EIG_TOL:
        failed.append(f"B* eigenvalue {minEig:.2e}")
    if detDrift > DET_TOL:
        failed.append(f"det(B) drift {detDrift:.2e}")
    if growth != "" and growth > ENERGY_TOL:
        failed.append(f"energy grew by {growth:.2e}")
    return dict(case=os.path.basename(case), steps=steps, seconds=seconds,
                alphaExcursion=f"{alphaWorst:.2e}", volumeDrift=f"{drift:.2e}",
                minEigBstar=f"{minEig:.2e}" if math.isfinite(minEig) else "",
                maxDetDrift=f"{detDrift:.2e}", maxDevB=f"{devB:.3g}",
                energyGrowth=f"{growth:.1e}" if growth != "" else "",
                balanceGain=f"{gain:.1e}" if gain != "" else "",
                verdict="PASS" if not failed else "FAIL",
                why="; ".join(failed))


def main(cases, out):
    rows = [evaluate(c) for c in sorted(glob.glob(os.path.join(cases, "*")))
            if os.path.exists(os.path.join(c, "log.vheFoam"))]
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    head = ("case", "steps", "seconds", "alphaExcursion", "volumeDrift",
            "minEigBstar", "maxDetDrift", "maxDevB",
            "energyGrowth",
            "balanceGain", "verdict")
    widths = [max(len(h), *(len(str(r[h])) for r in rows)) for h in head]
    print("  ".join(h.ljust(n) for h, n in zip(head, widths)))
    for r in rows:
        print("  ".join(str(r[h]).ljust(n) for h, n in zip(head, widths)))
    print(f"(criteria: ends without NaN; alpha in [0, 1] within {ALPHA_TOL:g}; "
          f"fluid volumes within {VOLUME_TOL:g}, solid volumes within "
          f"{SOLID_VOLUME_TOL:g}; min eig B* >= {EIG_TOL:g}; "
          f"|det B - 1| < {DET_TOL:g}; in closed undriven boxes total energy "
          f"never growing by more than {ENERGY_TOL:g} of the largest kinetic "
          f"+ elastic energy)")
    for r in rows:
        print(f"{r['verdict']} stability_{r['case']}: {r['steps']} steps, "
              f"alpha excursion {r['alphaExcursion']}, volume drift "
              f"{r['volumeDrift']}, det drift {r['maxDetDrift']}"
              + (f" -- {r['why']}" if r["why"] else ""))
    return 0 if all(r["verdict"] == "PASS" for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
