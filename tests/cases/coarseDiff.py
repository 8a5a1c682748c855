#!/usr/bin/env python3
"""Differences between cases on one block mesh and its 2x refinement.

Usage: coarseDiff.py TIME NX NY NZ CASE_A CASE_B [FINE_CASE]
CASE_A and CASE_B have NX x NY x NZ cells (one blockMesh block), FINE_CASE
twice as many per direction; its fields are restricted to the coarse
cells (mean of each 2 x 2 x 2 group).  Prints, for the liquid fraction
alpha.liquid and U: the mean |alpha_A - alpha_B| over the cells, the mean
|U_A - U_B|, and with FINE_CASE the same between CASE_B and the restricted
fine case (CASE_B's discretisation error, as far as the fine case shows
it), then the liquid centroid x of each case (fraction of NX):
  "dAlpha dU dAlphaFine dUFine xA xB xFine"
"""
import sys

from fieldDiff import internal_field


def field(case, time, name):
    n, values = internal_field(f"{case}/{time}/{name}")
    return values


def restrict(v, nx, ny, nz):
    out = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                s = [0.0]*len(v[0])
                for dk in (0, 1):
                    for dj in (0, 1):
                        for di in (0, 1):
                            c = v[2*i + di + 2*nx*(2*j + dj + 2*ny*(2*k + dk))]
                            s = [a + b/8 for a, b in zip(s, c)]
                out.append(s)
    return out


def mean_diff(a, b):
    return sum(sum((p - q)**2 for p, q in zip(x, y))**0.5
               for x, y in zip(a, b))/len(a)


def centroid_x(alpha, nx):
    s = sum(a[0] for a in alpha)
    return sum(a[0]*((n % nx) + 0.5)/nx for n, a in enumerate(alpha))/s


def main(time, nx, ny, nz, a, b, fine=None):
    nx, ny, nz = int(nx), int(ny), int(nz)
    aa, ab = field(a, time, "alpha.liquid"), field(b, time, "alpha.liquid")
    ua, ub = field(a, time, "U"), field(b, time, "U")
    out = [mean_diff(aa, ab), mean_diff(ua, ub)]
    xs = [centroid_x(aa, nx), centroid_x(ab, nx)]
    if fine:
        af = restrict(field(fine, time, "alpha.liquid"), nx, ny, nz)
        uf = restrict(field(fine, time, "U"), nx, ny, nz)
        out += [mean_diff(ab, af), mean_diff(ub, uf)]
        xs.append(centroid_x(af, nx))
    print(" ".join("%.6g" % x for x in out + xs))


if __name__ == "__main__":
    main(*sys.argv[1:])
