#!/usr/bin/env python3
"""squareArray.py DIR [DIR...]: F/(mu U) of squareArray.sh's cases.

F = f rho L^2 per unit depth, the force that holds the cylinder against
the body force on the whole cell (fluid and cylinder, as a mean pressure
gradient G acts: F = G L^2); U = Q/L, the mean velocity over the cell
(the superficial velocity, zero in the cylinder), Q the flow rate through
a periodic face.  Prints per case: cells, c (the body's volume fraction
from the log), F/(mu U), its change over the last 10 % of the run (the
distance from steady state), the reference value and the relative error.
"""
import math, re, sys

# Sangani & Acrivos (1982) Table 1 (square array), as issue 24 quotes it
REF = {0.05: 15.56, 0.1: 24.83, 0.2: 51.53, 0.3: 102.90}
F, MU, L = 0.1, 1.0, 1.0

def case(d):
    rows = [l.split() for l in open(d + '/postProcessing/flowRate/0/surfaceFieldValue.dat')
            if not l.startswith('#')]
    t = [float(r[0]) for r in rows]
    q = [-float(r[1]) for r in rows]
    K = [F*L*L/(MU*qi/L) for qi in q]
    i9 = min(range(len(t)), key=lambda i: abs(t[i] - 0.9*t[-1]))
    vol = [float(m.group(1)) for m in
           re.finditer(r'Phase rubber volume (\S+)', open(d + '/log.vheFoam').read())]
    n = int(re.search(r'cells\s+(\d+);', open(d + '/system/parameters').read()).group(1))
    return n, vol[-1], K[-1], abs(K[-1] - K[i9])/K[-1], vol

if __name__ == '__main__':
    print('cells c F/(mu U) drift ref err volume_change')
    for d in sys.argv[1:]:
        n, c, K, drift, vol = case(d)
        ref = min(REF, key=lambda k: abs(k - c))
        print('%d %.6f %.4f %.1e %.2f %+.4f %.1e'
              % (n, c, K, drift, REF[ref], K/REF[ref] - 1, max(vol) - min(vol)))
