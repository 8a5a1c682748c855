"""Figures of a floatingBlock case (tutorials/floatingBlock) for the tests.

Usage:
  floating.py draft CASE HEIGHT T0   mean draft over t >= T0: water level at
                                     the wall minus the body's lowest point
                                     (centroid - HEIGHT/2, an upright box)
  floating.py bodyDraft CASE HEIGHT T0
                                     the same from the bodies function
                                     object's centroid (at its writes; a
                                     rigid body has no solidDiagnostics)
  floating.py sink CASE HEIGHT       lowest point at the start and the end,
                                     and the largest upward velocity
  floating.py volumes CASE           largest relative drift of any phase
                                     volume (phaseVolumes function object)
  floating.py airSpeed CASE TIME     largest speed in pure air (alpha.air
                                     > 0.99) at TIME (ascii fields)
  floating.py edgePressure CASE TIME W H
                                     largest |p - p at the wall| over the
                                     cells of one fluid that hold some of
                                     the W x H box but whose centres lie
                                     outside it, against the pure cell of
                                     that fluid at the left wall in the
                                     same row, at TIME (2D, nx = ny, a
                                     1 x 1 m tank; the box's pose from
                                     the rigidBodies function object)
  floating.py submerged CASE TIME    the body's area below the water level
                                     at the wall against Archimedes', at
                                     TIME (2D, nx = ny, a 1 x 1 m tank)
"""
import math
import re
import sys


def table(path):
    with open(path) as f:
        return [[float(x) for x in line.split()] for line in f
                if line.strip() and not line.startswith('#')]


def diagnostics(case):
    # solidDiagnostics columns: time, 10 scalars, centroid x y z, velocity x y z
    return table(case + '/postProcessing/solidDiagnostics/0/solidDiagnostics.dat')


def internalField(path, kind):
    text = open(path).read()
    m = re.search(r'internalField\s+nonuniform\s+List<%s>\s*(\d+)\s*\((.*?)\n\)'
                  % kind, text, re.S)
    values = [line.strip('() ').split() for line in m.group(2).split('\n')
              if line.strip()]
    return [float(v[0]) for v in values] if kind == 'scalar' \
        else [[float(x) for x in v] for v in values]


def parameter(case, key):
    # a number of the case's system/parameters
    m = re.search(r'^%s\s+([^;]+);' % key,
                  open(case + '/system/parameters').read(), re.M)
    return float(m.group(1))


def main():
    what, case = sys.argv[1:3]
    if what == 'draft':
        height, t0 = float(sys.argv[3]), float(sys.argv[4])
        level = {r[0]: r[1] for r in
                 table(case + '/postProcessing/waterLevel/0/liquidLevel.dat')}
        drafts = [level[r[0]] - (r[12] - height/2)
                  for r in diagnostics(case) if r[0] >= t0 and r[0] in level]
        print('%.6g' % (sum(drafts)/len(drafts)))
    elif what == 'bodyDraft':
        height, t0 = float(sys.argv[3]), float(sys.argv[4])
        level = {r[0]: r[1] for r in
                 table(case + '/postProcessing/waterLevel/0/liquidLevel.dat')}
        drafts = [level[r[0]] - (r[6] - height/2)
                  for r in table(case + '/postProcessing/bodies/0/bodies.dat')
                  if r[0] >= t0 and r[0] in level]
        print('%.6g' % (sum(drafts)/len(drafts)))
    elif what == 'sink':
        height = float(sys.argv[3])
        d = diagnostics(case)
        print('%.6g %.6g %.6g' % (d[0][12] - height/2, d[-1][12] - height/2,
                                  max(r[15] for r in d)))
    elif what == 'volumes':
        v = table(case + '/postProcessing/phaseVolumes/0/volFieldValue.dat')
        print('%.3g' % max(abs(r[k] - v[0][k])/v[0][k]
                           for r in v for k in range(1, len(v[0]))
                           if v[0][k] > 0))
    elif what == 'airSpeed':
        time = sys.argv[3]
        U = internalField('%s/%s/U' % (case, time), 'vector')
        air = internalField('%s/%s/alpha.air' % (case, time), 'scalar')
        print('%.3g' % max(math.sqrt(sum(c*c for c in u))
                           for u, a in zip(U, air) if a > 0.99))
    elif what == 'edgePressure':
        time, W, H = sys.argv[3], float(sys.argv[4]), float(sys.argv[5])
        f = {k: internalField('%s/%s/%s' % (case, time, k), 'scalar')
             for k in ('p', 'alpha.block', 'alpha.water', 'alpha.air')}
        pose = min(table(case + '/postProcessing/rigidBodies/0/poses.dat'),
                   key=lambda r: abs(r[0] - float(time)))
        X, Y, angle = pose[2], pose[3], pose[11]
        n = int(round(math.sqrt(len(f['p']))))
        dx = 1.0/n
        worst = 0.0
        for j in range(n):
            for i in range(1, n):
                c = j*n + i
                if f['alpha.block'][c] <= 0:
                    continue
                # the centre in the box's frame
                x, y = (i + 0.5)*dx - X, (j + 0.5)*dx - Y
                u = math.cos(angle)*x + math.sin(angle)*y
                v = -math.sin(angle)*x + math.cos(angle)*y
                if abs(u) < W/2 and abs(v) < H/2:
                    continue
                fluid = 1 - f['alpha.block'][c]
                for k in ('alpha.water', 'alpha.air'):
                    if f[k][c] > 0.999*fluid and f[k][j*n] > 0.999:
                        worst = max(worst, abs(f['p'][c] - f['p'][j*n]))
        print('%.4g' % worst)
    elif what == 'submerged':
        time = sys.argv[3]
        a = internalField('%s/%s/alpha.block' % (case, time), 'scalar')
        w = internalField('%s/%s/alpha.water' % (case, time), 'scalar')
        n = int(round(math.sqrt(len(a))))
        dx = 1.0/n
        level = sum(w[j*n] for j in range(n))*dx   # the wall's water column
        sub = sum(a[j*n + i]*min(max((level - j*dx)/dx, 0), 1)
                  for j in range(n) for i in range(n))*dx*dx
        rho = [parameter(case, k) for k in ('rhoSolid', 'rhoWater', 'rhoAir')]
        print('%.4f' % (sub/(sum(a)*dx*dx*(rho[0] - rho[2])/(rho[1] - rho[2]))))
    else:
        sys.exit(__doc__)


if __name__ == '__main__':
    main()
