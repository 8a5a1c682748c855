#!/usr/bin/env python3
"""jeffery.py DIR: the tumbling ellipse of a jeffery.sh case.  From the
angle turned (postProcessing/rigidBodies/0/poses.dat, 2D) it finds the
times at which the ellipse has turned by pi/2 and pi (a quarter and a half
of Jeffery's orbit: the major axis across the flow, then along it again)
and prints them against Jeffery's, with the half period's ratio, the
largest drift of the centre and the ellipse's angle against Jeffery's
angle over the run (largest difference)."""
import math
import sys

d = sys.argv[1]
a, b, G = 0.15, 0.075, 2.0
T = 2 * math.pi * (a / b + b / a) / G
rows = [[float(x) for x in l.split()] for l in
        open(d + '/postProcessing/rigidBodies/0/poses.dat')
        if l.strip() and not l.startswith('#')]


def jeffery(t):
    """Jeffery's angle (clockwise, turning with the shear: negative)."""
    phase = 2 * math.pi * t / T
    # tan(theta) = (b/a) tan(2 pi t/T), unwrapped
    k = math.floor(phase / math.pi + 0.5)
    return -(math.atan((b / a) * math.tan(phase)) + k * math.pi)


def crossing(level):
    for r0, r1 in zip(rows, rows[1:]):
        if -r0[11] < level <= -r1[11]:
            f = (level + r0[11]) / (r0[11] - r1[11])
            return r0[0] + f * (r1[0] - r0[0])
    return float('nan')


tq, th = crossing(math.pi / 2), crossing(math.pi)
drift = max(math.hypot(r[2] - 0.5, r[3] - 0.5) for r in rows)
dev = max(abs(r[11] - jeffery(r[0])) for r in rows)
print('# t(pi/2) Jeffery t(pi) Jeffery t(pi)/(T/2) centreDrift maxAngleError')
print('%.4f %.4f %.4f %.4f %.4f %.2e %.4f' % (tq, T / 4, th, T / 2, th / (T / 2), drift, dev))
