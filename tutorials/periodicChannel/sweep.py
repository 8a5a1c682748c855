#!/usr/bin/env python3
"""The area-fraction sweep of Allrun -sweep, from summary.csv.

Usage: sweep.py SUMMARY_CSV RESULTS_DIR
Writes RESULTS_DIR/sweep.csv (area fraction, material, disks, nu_m/nu0 and
the dilute limit 1 + 2 phi) and one sweep_<G>.dat per material (G in Pa,
or "rigid") for the plot.
"""
import csv
import os
import sys


def main(summary, results):
    rows = [r for r in csv.DictReader(open(summary))
            if r["case"].startswith("phi")]
    rows.sort(key=lambda r: (r["G"], float(r["areaFraction"])))
    with open(os.path.join(results, "sweep.csv"), "w") as f:
        f.write("areaFraction,G,nDisks,nu_m/nu0,dilute_rigid_1+2phi\n")
        for r in rows:
            f.write(f'{r["areaFraction"]},{r["G"]},{r["nDisks"]},'
                    f'{r["nu_m/nu0"]},{r["dilute_rigid_1+2phi"]}\n')
    for g in sorted({r["G"] for r in rows}):
        with open(os.path.join(results, f"sweep_{g}.dat"), "w") as f:
            for r in rows:
                if r["G"] == g:
                    f.write(f'{r["areaFraction"]} {r["nu_m/nu0"]}\n')


if __name__ == "__main__":
    main(*sys.argv[1:3])
