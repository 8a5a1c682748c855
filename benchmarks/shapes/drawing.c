/* drawing NDIM KIND DEPTH OUT: the fractions of one shape over a grid of
 * 32^NDIM cells of edge 1/32 (vhe_shape_fraction_posed, a turned pose),
 * written to OUT as doubles; prints the time taken and the cells cut.
 * KIND: sphere (a disk in 2D), box, ellipsoid, cylinder (finite, tilted; 3D
 * only).  The body: radius 5.3 cells, or semi-axes 1.3, 0.6 and 0.8 times
 * that, off the grid's points; benchmarks/shapes/Allrun compares runs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "vhe.h"

int main(int argc, char **argv)
{
    const double dx = 1.0 / 32, R = 5.3 * dx, th = 0.3, ph = 0.4;
    struct vhe_shape s;
    double Q[9], X[3], *f;
    int nd, depth, i, j, k, nz, n = 0;
    long cut = 0;
    clock_t t0;
    FILE *out;
    if (argc != 5) {
        fprintf(stderr, "usage: %s NDIM KIND DEPTH OUT\n", argv[0]);
        return 1;
    }
    nd = atoi(argv[1]);
    depth = atoi(argv[3]);
    memset(&s, 0, sizeof s);
    s.centre[0] = 0.5013; s.centre[1] = 0.4971; s.centre[2] = 0.5037;
    s.axis[2] = 1.0;
    s.radius = R;
    s.semi[0] = 1.3 * R; s.semi[1] = 0.6 * R; s.semi[2] = nd == 3 ? 0.8 * R : 1e15;
    if (!strcmp(argv[2], "sphere")) {
        s.kind = nd == 3 ? VHE_SPHERE : VHE_CYLINDER;
    } else if (!strcmp(argv[2], "box")) {
        s.kind = VHE_BOX;
    } else if (!strcmp(argv[2], "ellipsoid")) {
        s.kind = VHE_ELLIPSOID;
    } else if (!strcmp(argv[2], "cylinder") && nd == 3) {
        s.kind = VHE_CYLINDER;
        s.half_length = 1.2 * R;
        s.axis[0] = 0.3; s.axis[1] = 0.2; s.axis[2] = sqrt(1.0 - 0.13);
    } else {
        fprintf(stderr, "unknown kind %s\n", argv[2]);
        return 1;
    }
    {
        /* turned by th about z, then (3D) by ph about x */
        const double c = cos(th), sn = sin(th);
        const double cb = nd == 3 ? cos(ph) : 1.0, sb = nd == 3 ? sin(ph) : 0.0;
        const double q[9] = {c, -sn * cb, sn * sb, sn, c * cb, -c * sb,
                             0.0, sb, cb};
        memcpy(Q, q, sizeof Q);
    }
    X[0] = s.centre[0] + 0.0011; X[1] = s.centre[1] - 0.0007;
    X[2] = s.centre[2] + 0.0003;
    nz = nd == 3 ? 32 : 1;
    f = malloc(sizeof(double) * 32 * 32 * nz);
    t0 = clock();
    for (i = 0; i < 32; ++i) {
        for (j = 0; j < 32; ++j) {
            for (k = 0; k < nz; ++k, ++n) {
                const double lo[3] = {i * dx, j * dx, nd == 3 ? k * dx : 0.0};
                const double hi[3] = {lo[0] + dx, lo[1] + dx,
                                      nd == 3 ? lo[2] + dx : 1.0};
                f[n] = vhe_shape_fraction_posed(&s, Q, X, lo, hi, nd, depth);
                cut += f[n] > 0.0 && f[n] < 1.0;
            }
        }
    }
    printf("%.4f %ld\n", (double)(clock() - t0) / CLOCKS_PER_SEC, cut);
    out = fopen(argv[4], "wb");
    if (!out || fwrite(f, sizeof(double), (size_t)n, out) != (size_t)n) {
        return 1;
    }
    fclose(out);
    free(f);
    return 0;
}
