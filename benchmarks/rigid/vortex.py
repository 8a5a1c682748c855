#!/usr/bin/env python3
"""The orbit of vortex.sh's disk: psi = sin(kX) sin(kY) of its centre
(0.809 at the start; the streamline it starts on), its distance from the
vortex centre (0.25, 0.25) and its angular velocity, at t = 0, 0.5, ...,
the end.  A rigid disk's centre is its pose (postProcessing/rigidBodies),
an elastic one's its centroid (postProcessing/bodies, at the writes).

Usage: vortex.py DIR...        (one line per case: t:psi(r) pairs)
       vortex.py -at T DIR     (psi and omega_z at the sample nearest T)"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bodiesdat import function_rows  # noqa: E402

K = 2*math.pi


def orbit(case):
    """(t, X, Y, omega_z) rows"""
    if os.path.isdir(os.path.join(case, 'postProcessing', 'rigidBodies')):
        rows, cols = function_rows(case, 'rigidBodies', 'poses.dat'), (0, 2, 3, 10)
        start = []
    else:
        rows, cols = function_rows(case, 'bodies', 'bodies.dat'), (0, 5, 6, 13)
        start = [(0.0, 0.35, 0.25, float('nan'))]
    return start + [tuple(float(r[c]) for c in cols) for r in rows]


def at(rows, t):
    t0, x, y, w = min(rows, key=lambda r: abs(r[0] - t))
    return t0, math.sin(K*x)*math.sin(K*y), math.hypot(x - 0.25, y - 0.25), w


if __name__ == '__main__':
    args = sys.argv[1:]
    if args[:1] == ['-at']:
        _, psi, _, w = at(orbit(args[2]), float(args[1]))
        print('%.6f %.6f' % (psi, w))
        sys.exit(0)
    for case in args:
        rows = orbit(case)
        end = rows[-1][0]
        out = ['%.2f:%.4f(%.4f)' % at(rows, 0.5*i)[:3]
               for i in range(int(round(end/0.5)) + 1)]
        print(case, ' '.join(out))
