/*
 * vheFoam C core: short-range contact between bodies (bodyContact).
 *
 * A body's proximity psi is 1 on the body (min(1, 2 alpha)) and falls by
 * 1/range per layer of cells around it, to 0 at range cells from its
 * diffuse edge.  The contact force density on another body's material is
 * -coef alpha psi grad(psi): it pushes that material away from the body,
 * with a magnitude growing as it comes nearer.
 */
#include "vhe.h"

void vhe_proximity_start(long n, const double *restrict alpha,
                         double *restrict psi)
{
    long c;
    for (c = 0; c < n; ++c) {
        const double p = 2.0 * alpha[c];
        psi[c] = p < 0.0 ? 0.0 : (p > 1.0 ? 1.0 : p);
    }
}


void vhe_proximity_layer(long nFaces, const int *restrict own,
                         const int *restrict nei, const double *restrict psi,
                         double step, double *restrict out)
{
    long f;
    for (f = 0; f < nFaces; ++f) {
        const double a = psi[own[f]] - step, b = psi[nei[f]] - step;
        if (b > out[own[f]]) out[own[f]] = b;
        if (a > out[nei[f]]) out[nei[f]] = a;
    }
}


void vhe_contact_add(long n, const double *restrict coef,
                     const double *restrict alpha, const double *restrict psi,
                     const double *restrict gradPsi, double *restrict f)
{
    long c;
    int k;
    for (c = 0; c < n; ++c) {
        const double w = coef[c] * alpha[c] * psi[c];
        if (w == 0.0) continue;
        for (k = 0; k < 3; ++k) f[3 * c + k] -= w * gradPsi[3 * c + k];
    }
}
