#!/usr/bin/env python3
"""galilean.py FIXED MOVING [T0]: the drag coefficient Cd = 2 Fx/(rho U^2 D
dz) of galilean.sh's two runs (U 1, D 0.1, rho 1; dz from the mesh) at a
few times and its mean over t >= T0 (default 0.1), and the moving run's
excess over the fixed one's; with PIMPLE outer iterations, the force of
each step's last."""
import sys


def forces(case):
    """(t, Fx) per step: the last row of each time (one a PIMPLE outer
    iteration)"""
    last = {}
    for line in open(case + '/postProcessing/fixedBodies/0/forces.dat'):
        if line.startswith('#') or not line.strip():
            continue
        c = line.split()
        last[float(c[0])] = float(c[2])
    return sorted(last.items())


def depth(case):
    for line in open(case + '/system/blockMeshDict'):
        if line.startswith('dz'):
            return 1.0 / int(line.split('/')[1].split('}')[0])
    raise SystemExit(case + ': no dz in blockMeshDict')


fixed, moving = sys.argv[1], sys.argv[2]
t0 = float(sys.argv[3]) if len(sys.argv) > 3 else 0.1
scale = 2 / (1 * 1 * 0.1 * depth(fixed))
ff, fm = forces(fixed), forces(moving)
for (t, a), (_, b) in list(zip(ff, fm))[9::40]:
    print('t %.4f  Cd fixed %.4f  moving %.4f  (%+.1f %%)'
          % (t, a * scale, b * scale, 100 * (b / a - 1)))
mf = [a for t, a in ff if t >= t0]
mm = [b for t, b in fm if t >= t0]
cf, cm = scale * sum(mf) / len(mf), scale * sum(mm) / len(mm)
print('# mean over t >= %g: Cd fixed %.4f, moving %.4f, moving/fixed - 1 = %+.2f %%'
      % (t0, cf, cm, 100 * (cm / cf - 1)))
