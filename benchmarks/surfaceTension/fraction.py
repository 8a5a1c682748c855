#!/usr/bin/env python3
"""fraction.py NX NY NZ LX LY LZ CX CY CZ R [OUT]

The volume fraction of a disk (NZ = 1: a circle of radius R about (CX, CY)
in the x-y plane) or a sphere (NZ > 1) in each cell of blockMesh's uniform
box [0, LX] x [0, LY] x [0, LZ] (cells numbered x fastest), as an
OpenFOAM internalField entry on stdout; OUT = 1 - fraction when given
as 'outside'.  Cells the surface cuts are sampled on a 16 x 16 (x 16)
grid of points, the others are 0 or 1.
"""
import math
import sys


def main():
    nx, ny, nz = (int(a) for a in sys.argv[1:4])
    lx, ly, lz, cx, cy, cz, r = (float(a) for a in sys.argv[4:11])
    outside = len(sys.argv) > 11 and sys.argv[11] == "outside"
    dx, dy, dz = lx/nx, ly/ny, lz/nz
    two_d = nz == 1
    m = 16
    vals = []
    for k in range(nz):
        z0 = k*dz
        for j in range(ny):
            y0 = j*dy
            for i in range(nx):
                x0 = i*dx
                # nearest and farthest points of the cell from the centre
                near = [min(max(c, a), a + d) for c, a, d in
                        ((cx, x0, dx), (cy, y0, dy), (cz, z0, dz))]
                far = [a if abs(c - a) > abs(c - a - d) else a + d for c, a, d
                       in ((cx, x0, dx), (cy, y0, dy), (cz, z0, dz))]
                if two_d:
                    near[2] = far[2] = cz
                dn = math.dist(near, (cx, cy, cz))
                df = math.dist(far, (cx, cy, cz))
                if df <= r:
                    f = 1.0
                elif dn >= r:
                    f = 0.0
                else:
                    inside = 0
                    ks = [0.5] if two_d else [(c + 0.5)/m for c in range(m)]
                    for a in range(m):
                        x = x0 + (a + 0.5)/m*dx - cx
                        for b in range(m):
                            y = y0 + (b + 0.5)/m*dy - cy
                            for c in ks:
                                z = 0 if two_d else z0 + c*dz - cz
                                inside += x*x + y*y + z*z < r*r
                    f = inside/(m*m*len(ks))
                vals.append(1 - f if outside else f)
    print(f"internalField nonuniform List<scalar> {len(vals)}\n(")
    print("\n".join(f"{v:.10g}" for v in vals))
    print(");")


if __name__ == "__main__":
    main()
