#!/usr/bin/env python3
"""stirrer.py DIR: the turned disk of a stirrer.sh case.  Prints the torque
that turns it (per unit depth, from postProcessing/fixedBodies: the
fluid's torque on it with the sign turned) over 4 pi mu Omega R^2, with
the Taylor-Couette bounds of the box, the angle it turned against Omega t,
and the largest drift of its centre.
"""
import math
import sys

d = sys.argv[1]
R, mu, omega, depth = 0.1, 1.0, 1.0, 1.0
for line in open(d + '/system/parameters'):
    c = line.replace(';', ' ').split()
    if len(c) >= 2 and c[0] == 'depth':
        depth = float(c[1])
Tz = None
for line in open(d + '/postProcessing/fixedBodies/0/forces.dat'):
    if line.startswith('#'):
        continue
    c = line.split()
    Tz = float(c[7])
ref = 4 * math.pi * mu * omega * R * R * depth
lo = 0.5 / (0.5 - R * R)
hi = 0.25 / (0.25 - R * R)
rows = [l.split() for l in open(d + '/postProcessing/rigidBodies/0/poses.dat')
        if not l.startswith('#')]
t, angle = float(rows[-1][0]), float(rows[-1][11])
drift = max(math.hypot(float(r[2]) - 0.5, float(r[3]) - 0.5) for r in rows)
print('# torque/(4 pi mu Omega R^2), bounds, angle/(Omega t) - 1, centre drift')
print('%.5f %.4f %.4f %.3e %.3e' % (-Tz / ref, lo, hi, angle / (omega * t) - 1, drift))
