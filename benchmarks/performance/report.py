#!/usr/bin/env python3
"""Tables, ratios and the bar chart of benchmarks/performance (run by Allrun).

Cost per step is measured inside the time loop, so start-up (reading the
mesh and fields) is left out: for the serial runs from the solvers'
"ExecutionTime" lines (cpu time of the process, printed by interFoam and
vheFoam alike), for the 1- and 2-rank runs from vheFoam's "Progress" wall
clock.  Of the repeats the fastest is kept.
"""
import csv
import glob
import os
import re
import subprocess
import sys

steps, bigSteps, hugeSteps = (int(a) for a in sys.argv[1:4])
R = "results"


def nCells(case):
    with open(f"cases/{case}/constant/polyMesh/owner") as f:
        return int(re.search(r"nCells:\s*(\d+)", f.read(2000)).group(1))


def loopCost(log, key):
    """Seconds per step between the first and the last step of LOG;
    key: 'ExecutionTime' (cpu) or 'wall' (vheFoam's Progress line)"""
    text = open(log).read()
    if key == "ExecutionTime":
        t = [float(x) for x in re.findall(r"^ExecutionTime = (\S+) s", text, re.M)]
    else:
        t = [float(x) for x in re.findall(r"^Progress: .* wall (\S+) s", text, re.M)]
    n = len(re.findall(r"^Time = ", text, re.M))
    if len(t) < 2 or len(t) != n:
        sys.exit(f"report.py: {log}: {n} steps but {len(t)} {key} lines")
    return (t[-1] - t[0]) / (len(t) - 1), n


def runs(case, prefix, key):
    """Fastest repeat of CASE's runs labelled PREFIX.*:
    (seconds per step, steps, wall of the process, peak memory MB)"""
    best = None
    with open(f"cases/{case}/times") as f:
        for line in f:
            label, wall, rss = line.split()
            if not label.startswith(prefix + "."):
                continue
            cost, n = loopCost(f"cases/{case}/log.{label}", key)
            row = (cost, n, float(wall), float(rss) / 1024)
            if best is None or cost < best[0]:
                best = row
    return best


rows = []
for name, case, prefix, ranks, key in [
        ("interFoam, no solid", "interFoam", "interFoam", 1, "ExecutionTime"),
        ("vheFoam, no solid", "vheNone", "vheFoam", 1, "ExecutionTime"),
        ("vheFoam, 4 spheres", "vheSpheres", "vheFoam", 1, "ExecutionTime"),
        ("multiphaseInterFoam, 4 phases", "multiphase", "multiphaseInterFoam",
         1, "ExecutionTime"),
        ("vheFoam, 4 spheres, big, 1 rank", "big", "np1", 1, "wall"),
        ("vheFoam, 4 spheres, big, 2 ranks", "big", "np2", 2, "wall"),
        ("vheFoam, 4 spheres, huge, 1 rank", "huge", "np1", 1, "wall"),
        ("vheFoam, 4 spheres, huge, 2 ranks", "huge", "np2", 2, "wall")]:
    cost, n, wall, rss = runs(case, prefix, key)
    cells = nCells(case)
    rows.append(dict(run=name, cells=cells, ranks=ranks, steps=n,
                     wall_s=f"{wall:.2f}", s_per_step=f"{cost:.5f}",
                     us_per_cell_step=f"{1e6 * cost / cells:.3f}",
                     maxRSS_MB=f"{rss:.1f}" if ranks == 1 else ""))

with open(f"{R}/performance.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)

c = {r["run"]: float(r["s_per_step"]) for r in rows}
m = {r["run"]: float(r["maxRSS_MB"] or 0) for r in rows}
inter, none, sph = "interFoam, no solid", "vheFoam, no solid", "vheFoam, 4 spheres"
multi = "multiphaseInterFoam, 4 phases"
big1, big2 = "vheFoam, 4 spheres, big, 1 rank", "vheFoam, 4 spheres, big, 2 ranks"
huge1, huge2 = "vheFoam, 4 spheres, huge, 1 rank", "vheFoam, 4 spheres, huge, 2 ranks"
ratios = [
    ("time per step, vheFoam no solid / interFoam", c[none] / c[inter], "<= 1.05"),
    ("peak memory, vheFoam no solid / interFoam", m[none] / m[inter], "<= 1.05"),
    ("cost per cell-step, 4 spheres / no solid", c[sph] / c[none], "<= 1.3"),
    ("peak memory, 4 spheres / no solid", m[sph] / m[none], "<= 1.1"),
    ("time per step, 4 spheres / multiphaseInterFoam 4 phases",
     c[sph] / c[multi], "<= 1"),
    ("2-rank parallel efficiency (t1 / 2 t2)", c[big1] / (2 * c[big2]), ">= 0.85"),
    ("2-rank parallel efficiency, 453,600 cells", c[huge1] / (2 * c[huge2]), ">= 0.85"),
]


def mpiShare(case):
    """Share of the perf samples of a 2-rank run in Open MPI's libraries"""
    path = f"cases/{case}/perf.txt"
    if not os.path.exists(path):
        return None
    share = 0.0
    for line in open(path):
        mm = re.match(r"\s*([\d.]+)%\s+(\S+)", line)
        if mm and re.search(r"(libmpi|libopen-|mca_|libucp|libuct|libucs|libfabric|libpsm)",
                            mm.group(2)):
            share += float(mm.group(1)) / 100
    return share


for case, name in (("big", "262,500"), ("huge", "453,600")):
    share = mpiShare(case)
    if share is not None:
        ratios.append((f"MPI share of the 2-rank run, {name} cells (perf)",
                       share, "(model input)"))


# Profile: OpenFOAM's sections (inclusive times) and perf's symbols
def profiling():
    files = glob.glob("cases/profile/*/uniform/profiling")
    if not files:
        return []
    text = open(files[0]).read()
    sections = []
    for body in re.findall(r"trigger\d+\s*\{([^}]*)\}", text):
        d = dict(re.findall(r"(\w+)\s+(\"[^\"]*\"|\S+);", body))
        sections.append((d["description"].strip('"'), int(d["calls"]),
                         float(d["totalTime"])))
    return sections


sections = profiling()
total = max((s[2] for s in sections), default=0)
profile = [("profiling", name, calls, t, t / total)
           for name, calls, t in sections if total and t / total >= 0.005]

perfShare = {}
if os.path.exists("cases/profile/perf.txt"):
    for line in open("cases/profile/perf.txt"):
        mm = re.match(r"\s*([\d.]+)%\s+(\S+)\s+\[.\]\s+(.*\S)", line)
        if mm:
            perfShare[(mm.group(2), mm.group(3))] = float(mm.group(1)) / 100
core = sum(v for (dso, sym), v in perfShare.items() if re.match(r"vhe_\w+$", sym))
byDso = {}
for (dso, sym), v in perfShare.items():
    byDso[dso] = byDso.get(dso, 0) + v
for (dso, sym), v in sorted(perfShare.items(), key=lambda kv: -kv[1])[:12]:
    profile.append(("perf", f"{sym} ({dso})", "", "", v))
for (dso, sym), v in perfShare.items():
    if re.match(r"vhe_\w+$", sym):
        profile.append(("perf C core", sym, "", "", v))
for dso, v in sorted(byDso.items(), key=lambda kv: -kv[1])[:8]:
    profile.append(("perf library", dso, "", "", v))
if perfShare:
    ratios.append(("C core kernels (vhe_*) share of the run, perf", core, "<= 0.10"))

with open(f"{R}/profile.csv", "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["source", "section", "calls", "seconds", "share"])
    for src, name, calls, t, share in profile:
        w.writerow([src, name, calls, f"{t:.3f}" if t != "" else "", f"{share:.4f}"])

# Print
machine = open(f"{R}/machine.txt").read().strip()
print(f"\n{machine}")
print(f"{'run':36s} {'cells':>8s} {'ranks':>5s} {'steps':>5s} {'s/step':>9s} "
      f"{'us/cell-step':>12s} {'peak MB':>8s}")
for r in rows:
    print(f"{r['run']:36s} {r['cells']:8d} {r['ranks']:5d} {r['steps']:5d} "
          f"{r['s_per_step']:>9s} {r['us_per_cell_step']:>12s} {r['maxRSS_MB']:>8s}")
print()
for name, v, target in ratios:
    print(f"{name:52s} {v:7.3f}   target {target}")
if profile:
    print("\nWhere the time goes (4 spheres, serial):")
    for src, name, calls, t, share in profile:
        if src in ("profiling", "perf C core"):
            print(f"  {src:12s} {100 * share:6.1f}%  {name}")
with open(f"{R}/ratios.txt", "w") as f:
    for name, v, target in ratios:
        f.write(f"{name}: {v:.3f} (target {target})\n")

# Bar chart: cost per cell-step of every run; the profile's sections
with open(f"{R}/cost.dat", "w") as f:
    for r in rows:
        label = r["run"].replace("vheFoam, ", "").replace(", ", "\\n")
        f.write(f"\"{label}\" {r['us_per_cell_step']}\n")
top = [p for p in profile if p[0] == "profiling"
       and re.match(r"(vheFoam::|fvMatrix::solve)", p[1])]
with open(f"{R}/sections.dat", "w") as f:
    for src, name, calls, t, share in top:
        f.write(f"\"{name}\" {100 * share:.2f}\n")
    if core:
        f.write(f"\"C core (perf)\" {100 * core:.2f}\n")
subprocess.run(["gnuplot"], check=True, input=f"""
set terminal pngcairo size 1300,520 font ",10"
set output "{R}/performance.png"
set multiplot layout 1,2 title "vheFoam cost, {machine}"
set style fill solid 0.6 border -1
set boxwidth 0.6
set grid ytics
set yrange [0:*]
set bmargin 7
set xtics rotate by -30 left noenhanced
set ylabel "wall/cpu us per cell-step"
set title "Cost per cell and time step (fixed dt)"
plot "{R}/cost.dat" using 0:2:xtic(1) with boxes notitle, \\
     "" using 0:2:(sprintf("%.2f", $2)) with labels offset 0,0.7 notitle
set ylabel "share of the run [%]"
set title "Where the time goes: 4 spheres, serial (inclusive)"
plot "{R}/sections.dat" using 0:2:xtic(1) with boxes lc rgb "#b05050" notitle, \\
     "" using 0:2:(sprintf("%.1f", $2)) with labels offset 0,0.7 notitle
unset multiplot
""", text=True)
print(f"\nWrote {R}/performance.csv, {R}/profile.csv, {R}/ratios.txt, "
      f"{R}/performance.png")
