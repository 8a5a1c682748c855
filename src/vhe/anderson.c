/*
 * anderson.c -- the small least-squares problem of Anderson acceleration.
 *
 * A fixed point x = G(x) is iterated as x_{k+1} = G(x_k) - sum_i gamma_i
 * dG_i, with dG_i, dF_i the differences of successive map values and
 * residuals f = G(x) - x (type II, Walker & Ni 2011).  gamma minimises
 * |f_k - sum_i gamma_i dF_i|; on a linear map this is GMRES.  The caller
 * forms the inner products (summed over processors), this kernel solves the
 * normal equations.
 */
#include <math.h>

#include "vhe.h"

int vhe_anderson_gamma(int m, const double *gram, const double *b,
                       double *gamma)
{
    double N[VHE_ANDERSON_MAX][VHE_ANDERSON_MAX];
    double r[VHE_ANDERSON_MAX], s[VHE_ANDERSON_MAX];
    int k, l, j;

    if (m < 0 || m > VHE_ANDERSON_MAX || (m > 0 && (!gram || !b || !gamma))) {
        return VHE_EBADARG;
    }
    /* Columns scaled to unit norm; a column of zero norm (a repeated
       iterate) takes no weight */
    for (k = 0; k < m; ++k) {
        s[k] = sqrt(fmax(gram[k*m + k], 0.0));
    }
    for (k = 0; k < m; ++k) {
        for (l = 0; l < m; ++l) {
            N[k][l] = (s[k] > 0.0 && s[l] > 0.0)
                    ? gram[k*m + l]/(s[k]*s[l]) : (k == l ? 1.0 : 0.0);
        }
        /* Tikhonov regularisation: nearly parallel columns (a converged
           history) give bounded weights instead of round-off */
        N[k][k] += 1e-10;
        r[k] = s[k] > 0.0 ? b[k]/s[k] : 0.0;
    }
    /* Cholesky: N = L L^T, the scaled normal matrix is positive definite */
    for (j = 0; j < m; ++j) {
        double d = N[j][j];
        for (k = 0; k < j; ++k) d -= N[j][k]*N[j][k];
        if (!(d > 0.0)) return VHE_EBADARG;
        N[j][j] = sqrt(d);
        for (l = j + 1; l < m; ++l) {
            double v = N[l][j];
            for (k = 0; k < j; ++k) v -= N[l][k]*N[j][k];
            N[l][j] = v/N[j][j];
        }
    }
    for (k = 0; k < m; ++k) {
        double v = r[k];
        for (l = 0; l < k; ++l) v -= N[k][l]*r[l];
        r[k] = v/N[k][k];
    }
    for (k = m - 1; k >= 0; --k) {
        double v = r[k];
        for (l = k + 1; l < m; ++l) v -= N[l][k]*r[l];
        r[k] = v/N[k][k];
    }
    for (k = 0; k < m; ++k) {
        gamma[k] = s[k] > 0.0 ? r[k]/s[k] : 0.0;
    }
    return VHE_OK;
}
