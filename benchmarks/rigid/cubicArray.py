#!/usr/bin/env python3
"""cubicArray.py DIR [DIR...]: K = F/(6 pi mu a U) of cubicArray.sh's cases.

F = f rho L^3, the force that holds the sphere against the body force on
the whole cell; U = Q/L^2, the mean velocity over the cell, Q the flow
rate through the periodic face x = 0 at the end.  Against Hasimoto
(1959)'s dilute series for a simple cubic array (U there the mean over
the cell as well; the series is good to O(C^(8/3)) at small C).
"""
import math, re, sys

F, MU, L = 0.1, 1.0, 1.0

print('cells C K Hasimoto err drift')
for d in sys.argv[1:]:
    rows = [l.split() for l in open(d + '/postProcessing/flowRate/0/surfaceFieldValue.dat')
            if not l.startswith('#')]
    q = [-float(r[1]) for r in rows]
    n = int(re.search(r'cells\s+(\d+);', open(d + '/system/parameters').read()).group(1))
    c = float(re.findall(r'Phase rubber volume (\S+)', open(d + '/log.vheFoam').read())[-1])
    a = (3*c/(4*math.pi))**(1/3)
    K = F*L**3/(6*math.pi*MU*a*q[-1]/L)
    ref = 1/(1 - 1.7601*c**(1/3) + c - 1.5593*c*c)
    print('%d %.5f %.4f %.4f %+.4f %.1e' % (n, c, K, ref, K/ref - 1, abs(q[-1] - q[-10])/q[-1]))
