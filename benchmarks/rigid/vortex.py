#!/usr/bin/env python3
"""The orbit of vortex.sh's disk: psi = sin(kX) sin(kY) of its centre
(0.809 at the start; the streamline it starts on) and its distance from
the vortex centre (0.25, 0.25), at t = 0, 0.5, ..., the end.

Usage: vortex.py DIR...   (one line per case: DIR, then t:psi(r) pairs)
       vortex.py -at T DIR   (psi at the sample nearest T)"""
import math
import os
import sys

K = 2*math.pi


def orbit(case):
    base = os.path.join(case, 'postProcessing', 'rigidBodies')
    rows = []
    for start in sorted(os.listdir(base), key=float):
        rows = [r for r in rows if r[0] <= float(start)]
        with open(os.path.join(base, start, 'poses.dat')) as f:
            for line in f:
                if line.startswith('#') or not line.strip():
                    continue
                p = line.split()
                rows.append((float(p[0]), float(p[2]), float(p[3])))
    return rows


def at(rows, t):
    t0, x, y = min(rows, key=lambda r: abs(r[0] - t))
    return t0, math.sin(K*x)*math.sin(K*y), math.hypot(x - 0.25, y - 0.25)


if __name__ == '__main__':
    args = sys.argv[1:]
    if args[:1] == ['-at']:
        print('%.6f' % at(orbit(args[2]), float(args[1]))[1])
        sys.exit(0)
    for case in args:
        rows = orbit(case)
        end = rows[-1][0]
        out = ['%.2f:%.4f(%.4f)' % at(rows, 0.5*i)
               for i in range(int(round(end/0.5)) + 1)]
        print(case, ' '.join(out))
