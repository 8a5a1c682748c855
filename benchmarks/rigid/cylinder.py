#!/usr/bin/env python3
"""cylinder.py DIR [T0]: drag and lift of cylinder.sh's case: Cd = 2 Fx/(rho
U^2 D), Cl = 2 Fy/(rho U^2 D) (U = 1 m/s the mean inflow, D = 0.1 m, depth
the mesh's one cell, D/CELLS), their largest values over t >= T0 (default
the last third of the run) and the Strouhal number D f/U from the lift's
upward zero crossings.  Schaefer & Turek (1996), 2D-2: Cd max 3.22-3.24,
Cl max 0.99-1.01, St 0.295-0.305."""
import re, sys

d = sys.argv[1]
n = int(re.search(r'\((\d+) (\d+) 1\)', open(d + '/system/blockMeshDict').read()).group(1)) // 22
depth = 0.1/n
# every start time's file (a restarted run writes one more), in order
import glob, os
rows = []
for f in sorted(glob.glob(d + '/postProcessing/fixedBodies/*/forces.dat'),
                key=lambda f: float(os.path.basename(os.path.dirname(f)))):
    new = [l.split() for l in open(f) if not l.startswith('#')]
    if rows and new:
        rows = [r for r in rows if float(r[0]) < float(new[0][0])]
    rows += new
t = [float(r[0]) for r in rows]
k = 2/(1.0*1.0**2*0.1*depth)
cd = [k*float(r[2]) for r in rows]
cl = [k*float(r[3]) for r in rows]
t0 = float(sys.argv[2]) if len(sys.argv) > 2 else t[-1]*2/3
i0 = next(i for i, ti in enumerate(t) if ti >= t0)
up = [t[i] - cl[i]*(t[i + 1] - t[i])/(cl[i + 1] - cl[i])
      for i in range(i0, len(t) - 1) if cl[i] < 0 <= cl[i + 1]]
st = (len(up) - 1)/(up[-1] - up[0])*0.1/1.0 if len(up) > 2 else float('nan')
print('cellsPerD %d  t %g..%g  Cd max %.4f  Cl max %.4f  St %.4f  (periods %d)'
      % (n, t0, t[-1], max(cd[i0:]), max(cl[i0:]), st, max(len(up) - 1, 0)))
