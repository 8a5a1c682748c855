#!/usr/bin/env python3
"""settling.py DIR [NU D]: the settling disk's track from the bodies
function object of a settling.sh case: prints, per write, t, the centre
(x, y), the particle Reynolds number |U| d/nu and the Taylor deformation
of the largest body, then the largest Reynolds number and when.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bodiesdat import bodies_rows  # noqa: E402

d = sys.argv[1]
nu = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-6
dia = float(sys.argv[3]) if len(sys.argv) > 3 else 2.5e-3
rows = {}
for c in bodies_rows(d):
    t, vol = float(c[0]), float(c[4])
    if t not in rows or vol > rows[t][0]:
        rows[t] = (vol, float(c[5]), float(c[6]),
                   (float(c[8])**2 + float(c[9])**2)**0.5 * dia / nu,
                   float(c[14]))
best = (0, 0)
for t in sorted(rows):
    vol, x, y, re, D = rows[t]
    print('%.3f %.5f %.5f %.1f %.4f' % (t, x, y, re, D))
    if re > best[0]:
        best = (re, t)
print('# largest Re %.1f at t = %.3f' % best)
