/*
 * sweep.c -- the volume a moving plane carries through a face over a step
 * (isoAdvector's time-integrated face flux, Roenby, Bredmose and Jasak
 * 2016): the fluid lies behind the plane, where (x - x0).n < 0, and the
 * plane moves along its unit normal n at the speed Un.  The face's
 * submerged area A(t) is the part where (x - x0).n < Un t; the volume
 * through the face is phi/|S_f| times the integral of A over [0, dt].
 *
 * A(t) is piecewise quadratic in t (the submerged part of a plane polygon
 * grows by a strip whose width is linear in t), its pieces bounded by the
 * times the plane reaches the face's points: two-point Gauss on each piece
 * is exact.  The cut is made on the face's own points, its area the fan
 * about the part's mean point that cut.c takes (vhe_polygon_fan), so a
 * face that is not quite plane is swept as the cell cuts see it.  No
 * allocation.
 */
#include "vhe.h"

#include <math.h>

#define VHE_SWEEP_MAXP 64

/* The area of the part of the face (n points x, their distances d to the
 * plane) where d < s */
static double submerged(int n, const double *x, const double *d, double s)
{
    double poly[VHE_SWEEP_MAXP][3], m[3], S[3];
    int np = 0, nin = 0, i, j;

    for (i = 0; i < n; ++i) {
        nin += d[i] < s;
    }
    if (nin == 0) {
        return 0.0;
    }
    for (i = 0; i < n; ++i) {
        const int b = i + 1 < n ? i + 1 : 0;
        const double *xa = x + 3 * i;
        const int ina = d[i] < s, inb = d[b] < s;
        if (ina) {
            poly[np][0] = xa[0];
            poly[np][1] = xa[1];
            poly[np][2] = xa[2];
            ++np;
        }
        if (ina != inb) {
            const double t = (s - d[i]) / (d[b] - d[i]);
            const double *xb = x + 3 * b;
            for (j = 0; j < 3; ++j) {
                poly[np][j] = xa[j] + t * (xb[j] - xa[j]);
            }
            ++np;
        }
    }
    vhe_polygon_fan(np, &poly[0][0], m, S);
    return sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2]);
}

double vhe_face_sweep(int n, const double *x, const double x0[3],
                      const double nrm[3], double Un, double dt,
                      double phi, double magSf, double Untol)
{
    double d[VHE_SWEEP_MAXP], t[VHE_SWEEP_MAXP + 2], sum = 0.0;
    int i, j, nt = 0;

    if (n < 3 || n > VHE_SWEEP_MAXP / 2 || !(magSf > 0.0)) {
        return 0.0;
    }
    for (i = 0; i < n; ++i) {
        d[i] = (x[3 * i] - x0[0]) * nrm[0] + (x[3 * i + 1] - x0[1]) * nrm[1]
             + (x[3 * i + 2] - x0[2]) * nrm[2];
    }
    /* a plane at rest: the area now, all the step */
    if (fabs(Un) <= Untol) {
        return phi / magSf * dt * submerged(n, x, d, 0.0);
    }
    /* the pieces: 0, the times the plane reaches points in (0, dt), dt */
    t[nt++] = 0.0;
    for (i = 0; i < n; ++i) {
        const double ti = d[i] / Un;
        if (ti > 0.0 && ti < dt) {
            for (j = nt; j > 1 && t[j - 1] > ti; --j) {
                t[j] = t[j - 1];
            }
            t[j] = ti;
            ++nt;
        }
    }
    t[nt++] = dt;
    /* two-point Gauss on each piece (exact to cubics; its points inside
     * the piece, where A is one quadratic: A jumps at a piece's end where
     * the face is parallel to the plane) */
    {
        const double g = 0.5 / sqrt(3.0);
        for (i = 0; i + 1 < nt; ++i) {
            const double a = t[i], b = t[i + 1], m = 0.5 * (a + b);
            if (b <= a) {
                continue;
            }
            sum += 0.5 * (b - a)
                 * (submerged(n, x, d, Un * (m - g * (b - a)))
                    + submerged(n, x, d, Un * (m + g * (b - a))));
        }
    }
    return phi / magSf * sum;
}
