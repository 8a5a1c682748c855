#!/usr/bin/env python3
"""couette.py DIR N: the mean wall stress of a Couette case of
couette.sh over that of the flow without a body, 2 mu (walls -1/+1 m/s, h 1;
half-cell gradient, exact for the linear profile), at its last write, and
the disk's rotation rate and Taylor deformation there (bodies function
object).  Prints "t tau/tau0 omega_z D"."""
import os, re, sys

d, n = sys.argv[1], int(sys.argv[2])
times = sorted((float(t), t) for t in os.listdir(d)
               if re.fullmatch(r'[0-9.eE+-]+', t) and float(t) > 0)
t, tn = times[-1]
s = open(os.path.join(d, tn, 'U')).read()
m = re.search(r'internalField\s+nonuniform\s+List<vector>\s+(\d+)\s*\(', s)
vals = re.findall(r'\(([^()]*)\)', s[m.end():m.end() + 60 * int(m.group(1))])
ux = [float(v.split()[0]) for v in vals[:int(m.group(1))]]
dx = 1.0 / n
bot = sum(ux[i] + 1 for i in range(n)) / n / (0.5 * dx)
top = sum(1 - ux[len(ux) - n + i] for i in range(n)) / n / (0.5 * dx)
w = D = float('nan')
f = os.path.join(d, 'postProcessing/bodies/0/bodies.dat')
if os.path.exists(f):
    for line in open(f):
        c = line.split()
        if line.startswith('#') or not c:
            continue
        if abs(float(c[0]) - t) < 1e-9:
            w, D = float(c[13]), float(c[14])
print('%g %.6g %.6g %.4g' % (t, 0.5 * (bot + top) / 2, w, D))
