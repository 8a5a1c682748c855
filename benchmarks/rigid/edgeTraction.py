#!/usr/bin/env python3
"""Vertical elastic traction through a floating box's outline (floating.sh).

Usage: edgeTraction.py CASE TIME
Reads Bstar and phis at TIME of a 2D floatingBlock case (nx = ny, 1 x 1 m,
depth 0.0125 m), G = GperRho x rhoSolid from system/parameters, and sums,
over the faces between cells with a share of the stress (w(phi_s) > 0, the
ramp of vhe_body_weight) and cells without, the vertical component of the
face stress (the linear face value: half the body cell's) in N per metre
of depth, split into side faces and top/bottom faces, and prints it
against the box's weight rho_s g A.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', 'tests', 'cases'))
from floating import internalField, parameter  # noqa: E402


def main(case, t):
    G = parameter(case, 'GperRho')*parameter(case, 'rhoSolid')
    B = internalField('%s/%s/Bstar' % (case, t), 'symmTensor')
    ph = internalField('%s/%s/phis' % (case, t), 'scalar')
    n = int(round(math.sqrt(len(ph))))
    dx = 1.0/n
    w = [min(max((p - 0.25)/0.5, 0), 1) for p in ph]
    # sigma = w G phi_s^(1/2) dev(B*); xy and yy components
    sxy = [w[c]*G*math.sqrt(ph[c])*B[c][1] for c in range(len(ph))]
    syy = [w[c]*G*math.sqrt(ph[c])*(B[c][3] - (B[c][0] + B[c][3] + B[c][5])/3)
           for c in range(len(ph))]
    side = ends = 0.0
    for j in range(n):
        for i in range(n):
            c = j*n + i
            if w[c] <= 0:
                continue
            for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                ii, jj = i + di, j + dj
                if not (0 <= ii < n and 0 <= jj < n) or w[jj*n + ii] > 0:
                    continue
                d = jj*n + ii
                if di:
                    side += 0.5*(sxy[c] + sxy[d])*di*dx
                else:
                    ends += 0.5*(syy[c] + syy[d])*dj*dx
    weight = parameter(case, 'rhoSolid')*parameter(case, 'g') \
        * parameter(case, 'blockWidth')*parameter(case, 'blockHeight')
    print('t = %s: up through the sides %.3f N/m (%.2f %% of the weight %.1f '
          'N/m), through top and bottom %.3f N/m'
          % (t, side, 100*side/weight, weight, ends))


if __name__ == '__main__':
    main(*sys.argv[1:3])
