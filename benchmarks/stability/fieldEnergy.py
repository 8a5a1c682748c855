#!/usr/bin/env python3
"""Kinetic + potential energy of a two-fluid case from its written fields.

Usage: fieldEnergy.py CASE RHO1 RHO2 ALPHA G
For every written time of CASE (serial, ASCII, a uniform mesh: blockMesh),
the integrals of 0.5 rho |U|^2 and of -rho g.x, rho = alpha RHO1 + (1 -
alpha) RHO2 with alpha the field ALPHA (alpha.liquid, say) and G the
vertical gravity (-10: along z).  The cell centres come from
`postProcess -func writeCellCentres -time 0`.  Prints a row per time and
the largest growth of the total between two writes over the largest
kinetic energy: the stability suite's energy criterion (evaluate.py) for
any solver, interFoam included (bin/vheToInterFoam), without vheFoam's
solidDiagnostics.
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "tests", "cases"))
from fieldDiff import internal_field  # noqa: E402


def cells(path, n):
    """A volField's n internal values (a uniform one repeated)"""
    m, values = internal_field(path)
    return [values]*n if m is None else values


def main(case, rho1, rho2, alpha, g):
    rho1, rho2, g = float(rho1), float(rho2), float(g)
    _, C = internal_field(os.path.join(case, "0", "C"))
    pts = open(os.path.join(case, "constant", "polyMesh", "points")).read()
    P = [[float(x) for x in t.split()]
         for t in re.findall(r"\(([^()]*)\)", pts[pts.index("("):])]
    V = 1.0
    for i in range(3):
        V *= max(p[i] for p in P) - min(p[i] for p in P)
    V /= len(C)
    times = sorted((d for d in os.listdir(case)
                    if re.fullmatch(r"[0-9.e+-]+", d)
                    and os.path.exists(os.path.join(case, d, alpha))),
                   key=float)
    rows = []
    for t in times:
        U = cells(os.path.join(case, t, "U"), len(C))
        a = cells(os.path.join(case, t, alpha), len(C))
        ke = pe = 0.0
        for u, al, c in zip(U, a, C):
            r = al[0]*rho1 + (1 - al[0])*rho2
            ke += 0.5*r*(u[0]**2 + u[1]**2 + u[2]**2)*V
            pe -= r*g*c[2]*V
        rows.append((float(t), ke, pe, ke + pe))
        print("%g kinetic %.6e potential %.10e total %.10e" % rows[-1])
    growth = max(max(b[3] - a[3] for a, b in zip(rows, rows[1:])), 0.0)
    print("largest growth between writes / largest kinetic energy: %.3e"
          % (growth/max(r[1] for r in rows)))


if __name__ == "__main__":
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    main(*sys.argv[1:6])
