#!/usr/bin/env python3
"""offWall.py N_DIR N1: scene B's sloshing measured at the wall and away
from it, from the written fields instead of the liquidLevel probe.

N_DIR is a mesh's directory of Allrun (cases/n<N1>, reconstructed), N1 its
cells along x1 (the tutorial's blockMesh: one block, N1 x N1/2.1 x N1/2.1
cells, x1 fastest).  For the cases none, G10 and G0.1, every written time
1 <= t <= 5 (0.1 s apart): the liquid level h = sum(alpha.liquid dx3) of
the cell column at x2 = L2/2 next to the wall x1 = 0 (the probe's column)
and of the column about 0.1 m from it.  Prints per column the RMS of h
about its mean and its ratio to the case without spheres.
"""
import math
import os
import re
import sys


def internal(path):
    """a volScalarField's nonuniform internal values"""
    s = open(path).read()
    i = s.index('internalField')
    m = re.search(r'nonuniform List<scalar>\s*(\d+)\s*\(', s[i:])
    n = int(m.group(1))
    return [float(v) for v in s[i + m.end():].split(')')[0].split()][:n]


base, n1 = sys.argv[1], int(sys.argv[2])
n2 = n3 = round(n1/2.1)
columns = (0, round(0.1*n1/2.1 - 0.5))
rms = {}
for case in ('none', 'G10', 'G0.1'):
    d = os.path.join(base, 'cases', case)
    times = sorted((t for t in os.listdir(d)
                    if re.match(r'^[0-9.]+$', t) and 1 <= float(t) <= 5 + 1e-9
                    and os.path.exists(os.path.join(d, t, 'alpha.liquid'))),
                   key=float)
    h = {i: [] for i in columns}
    for t in times:
        a = internal(os.path.join(d, t, 'alpha.liquid'))
        for i in columns:
            j = n2//2
            h[i].append(sum(a[i + n1*(j + n2*k)] for k in range(n3))/n3)
    for i in columns:
        mean = sum(h[i])/len(h[i])
        rms[case, i] = math.sqrt(sum((x - mean)**2 for x in h[i])/len(h[i]))
for i in columns:
    print('n1 %d, x1 = %.4f m: ' % (n1, (i + 0.5)*2.1/n1) + ', '.join(
        '%s RMS %.5f (%.3f)' % (c, rms[c, i], rms[c, i]/rms['none', i])
        for c in ('none', 'G10', 'G0.1')))
