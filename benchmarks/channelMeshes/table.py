#!/usr/bin/env python3
"""Channel mesh study: results/table.csv and results/courant.csv.

table.csv: cells, case, Q/Q_th, nu_m/nu0, steps, CPU seconds (from each
mesh's summary.csv and the logs).  courant.csv: cells, case, the largest
over unit time windows of (max Courant of the case)/(max Courant of the
disk-free run) in the same window.  The disk-free flow is steady
Poiseuille flow after t = 1 (viscous time h^2/nu = 1): where its run is
shorter than the case's (280 cells: to t = 3), its last window stands for
the later ones.  Meshes whose cases are gone keep their rows of the
existing tables; a run restarted from a written time (log appended) has
the CPU seconds of each part summed.
"""
import csv
import os
import re
import sys

cases_dir, results = sys.argv[1:3]
COURANT = re.compile(r"^Courant Number mean: \S+ max: (\S+)")


def courant_by_window(log):
    """Largest Courant number per unit time window: {window: max}."""
    out, t = {}, 0.0
    for line in open(log):
        if line.startswith("Time = "):
            t = float(line.split()[2])
        m = COURANT.match(line)
        if m:
            w = int(t)
            out[w] = max(out.get(w, 0.0), float(m.group(1)))
    return out


def kept(path, ran):
    """Rows of an existing table for meshes not run now."""
    if not os.path.exists(path):
        return []
    return [r for r in list(csv.reader(open(path)))[1:] if r[0] not in ran]


def cpu_seconds(text):
    """ExecutionTime at the end, summed over restarts (where it drops)."""
    total, last = 0.0, 0.0
    for v in map(float, re.findall(r"ExecutionTime = (\S+) s", text)):
        if v < last:
            total += last
        last = v
    return "%.2f" % (total + last) if last else ""


ran = [n for n in os.listdir(cases_dir)
       if os.path.exists(os.path.join(results, n, "summary.csv"))]
rows = kept(os.path.join(results, "table.csv"), ran)
co_rows = kept(os.path.join(results, "courant.csv"), ran)
header = next(csv.reader(open(os.path.join(results, "table.csv")))) \
    if os.path.exists(os.path.join(results, "table.csv")) else None
for n in sorted(os.listdir(cases_dir), key=int):
    summary = os.path.join(results, n, "summary.csv")
    if not os.path.exists(summary):
        continue
    ref = courant_by_window(os.path.join(cases_dir, n, "none", "log.vheFoam"))
    for r in csv.DictReader(open(summary)):
        case = r["case"]
        log = os.path.join(cases_dir, n, case, "log.vheFoam")
        text = open(log).read()
        steps = text.count("\nTime = ")
        rows.append([n, case] + [r[k] for k in r if k != "case"]
                    + [steps, cpu_seconds(text)])
        if case != "none":
            co = courant_by_window(log)
            last = ref[max(ref)]
            ratio = max(co[w]/ref.get(w, last) for w in co
                        if ref.get(w, last) > 0)
            co_rows.append([n, case, "%.3g" % ratio])
    header = ["cells", "case"] + [k for k in r if k != "case"] + ["steps", "cpuSeconds"]

rows.sort(key=lambda r: (int(r[0]), r[1]))
co_rows.sort(key=lambda r: (int(r[0]), r[1]))
with open(os.path.join(results, "table.csv"), "w") as f:
    w = csv.writer(f)
    w.writerow(header)
    w.writerows(rows)
with open(os.path.join(results, "courant.csv"), "w") as f:
    w = csv.writer(f)
    w.writerow(["cells", "case", "maxCourantRatioToDiskFree"])
    w.writerows(co_rows)
for path in ("table.csv", "courant.csv"):
    print(open(os.path.join(results, path)).read())
