#!/usr/bin/env python3
"""sessileDrop.py CASE THETA: the drop's centroid height at the last step
of postProcessing/drop/0/phaseStatistics.dat against the circular cap of
its area with the contact angle THETA (degrees) on a flat wall.  Prints

    yc  yc_cap  relative_error  |U|mean
"""
import math
import sys


def main(case, theta_deg):
    rows = [[float(x) for x in l.split()] for l in
            open(f"{case}/postProcessing/drop/0/phaseStatistics.dat")
            if not l.startswith("#")]
    t, vol, x, y, z, ux, uy, uz, area, circ = rows[-1]
    th = math.radians(theta_deg)
    dz = 2*rows[0][4]            # the mesh's thickness (centroid z = dz/2)
    A = vol/dz
    R = math.sqrt(A/(th - math.sin(th)*math.cos(th)))
    ycap = 2*R*math.sin(th)**3/(3*(th - math.sin(th)*math.cos(th))) \
        - R*math.cos(th)
    print(f"{y:.5f} {ycap:.5f} {(y - ycap)/ycap:+.4f} "
          f"{math.sqrt(ux*ux + uy*uy):.2e}")


if __name__ == "__main__":
    main(sys.argv[1], float(sys.argv[2]))
