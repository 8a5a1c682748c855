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
import re
import sys


def field(case, t, name):
    s = open('%s/%s/%s' % (case, t, name)).read()
    m = re.search(r'internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(', s)
    n = int(m.group(2))
    body = s[m.end():]
    if m.group(1) == 'scalar':
        return [float(v) for v in body.split(None, n)[:n]]
    return [[float(x) for x in v.split()]
            for v in re.findall(r'\(([^()]*)\)', body)[:n]]


def param(case, key):
    m = re.search(r'^%s\s+([^;]+);' % key,
                  open(case + '/system/parameters').read(), re.M)
    return float(m.group(1))


def main(case, t):
    G = param(case, 'GperRho')*param(case, 'rhoSolid')
    B, ph = field(case, t, 'Bstar'), field(case, t, 'phis')
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
    weight = param(case, 'rhoSolid')*param(case, 'g') \
        * param(case, 'blockWidth')*param(case, 'blockHeight')
    print('t = %s: up through the sides %.3f N/m (%.2f %% of the weight %.1f '
          'N/m), through top and bottom %.3f N/m'
          % (t, side, 100*side/weight, weight, ends))


if __name__ == '__main__':
    main(*sys.argv[1:3])
