/*
 * logb.c -- the deformation carried as its logarithm, Psi = log B
 * (log-conformation, Fattal & Kupferman 2004): matrix log and exp of
 * symmetric 3x3 tensors, B* <-> Psi per cell.  The transport of Psi is in
 * transport.c.
 *
 * Why log B: for the incompressible solid tr Psi = log det B = 0, and a
 * linear conservative update whose face values are linear in Psi with one
 * coefficient for all six components keeps tr Psi = 0 exactly, so
 * B = exp(Psi) has det B = 1 and is symmetric positive definite by
 * construction, whatever the scheme's accuracy.
 *
 * symmTensor layout (xx xy xz yy yz zz); gradients of a symmTensor are 18
 * doubles per cell: d/dx (6), d/dy (6), d/dz (6).
 */
#include "vhe.h"

#include <float.h>
#include <math.h>

/* min and max without fmin/fmax's NaN rules (library calls at -O2) */
#define MIN2(a, b) ((a) < (b) ? (a) : (b))
#define MAX2(a, b) ((a) > (b) ? (a) : (b))

/* V diag(f) V^T, upper triangle, V's columns the eigenvectors. */
static void sym_from_eigen(const double V[9], const double f[3], double S[6])
{
    static const int ii[6] = {0, 0, 0, 1, 1, 2};
    static const int jj[6] = {0, 1, 2, 1, 2, 2};
    int k;

    for (k = 0; k < 6; ++k) {
        const int a = ii[k], b = jj[k];
        S[k] = V[3 * a] * f[0] * V[3 * b]
               + V[3 * a + 1] * f[1] * V[3 * b + 1]
               + V[3 * a + 2] * f[2] * V[3 * b + 2];
    }
}

/*
 * Cyclic Jacobi on the six entries of a symmetric 3x3 (Numerical Recipes'
 * rotation formulas): eigenvalues in l, eigenvectors as the columns of V
 * (row-major).  Stops once the off-diagonal part is below 1e-15 of the
 * diagonal's (sums of squares 1e-30): the rotations' own round-off.
 * About twice as fast as the general jacobi3 of symm.c, which updates all
 * nine entries; log and exp of B call it twice per solid cell and step.
 */
static void sym_jacobi(const double S[6], double l[3], double V[9], int warm)
{
    /* a[p][q] of the symmetric matrix in the 6-entry layout */
    static const int idx[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    double a[6];
    int sweep, k;

    if (warm) {
        /* start in the basis V (the last eigenvectors of this cell, made
         * orthonormal again): a = V^T S V is nearly diagonal, and one or
         * two sweeps finish it instead of four or five */
        double *c0 = V, SV[9], n;
        double c1[3], c2[3];
        int i, j;
        n = sqrt(V[0] * V[0] + V[3] * V[3] + V[6] * V[6]);
        for (i = 0; i < 3; ++i) {
            c0[3 * i] /= n;
        }
        n = V[0] * V[1] + V[3] * V[4] + V[6] * V[7];
        for (i = 0; i < 3; ++i) {
            c1[i] = V[3 * i + 1] - n * V[3 * i];
        }
        n = sqrt(c1[0] * c1[0] + c1[1] * c1[1] + c1[2] * c1[2]);
        for (i = 0; i < 3; ++i) {
            c1[i] /= n;
        }
        c2[0] = V[3] * c1[2] - V[6] * c1[1];
        c2[1] = V[6] * c1[0] - V[0] * c1[2];
        c2[2] = V[0] * c1[1] - V[3] * c1[0];
        for (i = 0; i < 3; ++i) {
            V[3 * i + 1] = c1[i];
            V[3 * i + 2] = c2[i];
        }
        for (i = 0; i < 3; ++i) {
            for (j = 0; j < 3; ++j) {
                SV[3 * i + j] = S[idx[i][0]] * V[j] + S[idx[i][1]] * V[3 + j]
                                + S[idx[i][2]] * V[6 + j];
            }
        }
        for (k = 0; k < 6; ++k) {
            static const int ii[6] = {0, 0, 0, 1, 1, 2};
            static const int jj[6] = {0, 1, 2, 1, 2, 2};
            a[k] = V[ii[k]] * SV[jj[k]] + V[3 + ii[k]] * SV[3 + jj[k]]
                   + V[6 + ii[k]] * SV[6 + jj[k]];
        }
    } else {
        for (k = 0; k < 6; ++k) {
            a[k] = S[k];
        }
        for (k = 0; k < 9; ++k) {
            V[k] = (k % 4 == 0) ? 1.0 : 0.0;
        }
    }
    for (sweep = 0; sweep < 50; ++sweep) {
        const double off = a[1] * a[1] + a[2] * a[2] + a[4] * a[4];
        const double dia = a[0] * a[0] + a[3] * a[3] + a[5] * a[5];
        int p;
        if (off == 0.0 || off < 1e-30 * dia) {
            break;
        }
        for (p = 0; p < 2; ++p) {
            int q;
            for (q = p + 1; q < 3; ++q) {
                const int r = 3 - p - q;
                const double apq = a[idx[p][q]];
                double theta, t, c, sn, tau, g, h;
                if (apq == 0.0) {
                    continue;
                }
                theta = 0.5 * (a[idx[q][q]] - a[idx[p][p]]) / apq;
                t = 1.0 / (fabs(theta) + sqrt(theta * theta + 1.0));
                if (theta < 0.0) {
                    t = -t;
                }
                c = 1.0 / sqrt(t * t + 1.0);
                sn = t * c;
                tau = sn / (1.0 + c);
                a[idx[p][p]] -= t * apq;
                a[idx[q][q]] += t * apq;
                a[idx[p][q]] = 0.0;
                g = a[idx[r][p]];
                h = a[idx[r][q]];
                a[idx[r][p]] = g - sn * (h + g * tau);
                a[idx[r][q]] = h + sn * (g - h * tau);
                for (k = 0; k < 3; ++k) {
                    g = V[3 * k + p];
                    h = V[3 * k + q];
                    V[3 * k + p] = g - sn * (h + g * tau);
                    V[3 * k + q] = h + sn * (g - h * tau);
                }
            }
        }
    }
    l[0] = a[0]; l[1] = a[3]; l[2] = a[5];
}

static int is_diagonal(const double S[6])
{
    return S[1] == 0.0 && S[2] == 0.0 && S[4] == 0.0;
}

/* log S and exp S through the eigen-decomposition; V: the eigenvectors
 * (in: a guess if warm, out: those of S) */
static int sym_log_v(const double S[6], double L[6], double V[9], int warm)
{
    double l[3], f[3];
    int i, floored = 0;

    if (is_diagonal(S)) {
        /* exact, and keeps an undeformed or plane-strain B's zeros */
        for (i = 0; i < 3; ++i) {
            const double d = S[i == 0 ? 0 : (i == 1 ? 3 : 5)];
            f[i] = d > DBL_MIN ? log(d) : log(DBL_MIN);
            floored += !(d > DBL_MIN);
        }
        L[0] = f[0]; L[1] = 0.0; L[2] = 0.0;
        L[3] = f[1]; L[4] = 0.0; L[5] = f[2];
        for (i = 0; i < 9; ++i) {
            V[i] = (i % 4 == 0) ? 1.0 : 0.0;
        }
        return floored;
    }
    sym_jacobi(S, l, V, warm);
    for (i = 0; i < 3; ++i) {
        f[i] = l[i] > DBL_MIN ? log(l[i]) : log(DBL_MIN);
        floored += !(l[i] > DBL_MIN);
    }
    sym_from_eigen(V, f, L);
    return floored;
}

static void sym_exp_v(const double S[6], double E[6], double V[9], int warm)
{
    double l[3], f[3];
    int i;

    if (is_diagonal(S)) {
        E[0] = exp(S[0]); E[1] = 0.0; E[2] = 0.0;
        E[3] = exp(S[3]); E[4] = 0.0; E[5] = exp(S[5]);
        for (i = 0; i < 9; ++i) {
            V[i] = (i % 4 == 0) ? 1.0 : 0.0;
        }
        return;
    }
    sym_jacobi(S, l, V, warm);
    for (i = 0; i < 3; ++i) {
        f[i] = exp(l[i]);
    }
    sym_from_eigen(V, f, E);
}

int vhe_sym_log(const double S[6], double L[6])
{
    double V[9];
    return sym_log_v(S, L, V, 0);
}

void vhe_sym_exp(const double S[6], double E[6])
{
    double V[9];
    sym_exp_v(S, E, V, 0);
}

size_t vhe_logb_from_bstar(size_t n, const double *phis, const double *Bstar,
                           double phis_min, double *Psi, double *V)
{
    size_t c, bad = 0;
    int k;

    for (c = 0; c < n; ++c) {
        double *P = Psi + 6 * c;
        if (phis[c] > phis_min) {
            const double r = 1.0 / sqrt(phis[c]);
            double B[6];
            for (k = 0; k < 6; ++k) {
                B[k] = r * Bstar[6 * c + k];
            }
            if (V) {
                bad += sym_log_v(B, P, V + 9 * c, 1) != 0;
            } else {
                bad += vhe_sym_log(B, P) != 0;
            }
        } else {
            P[0] = P[1] = P[2] = P[3] = P[4] = P[5] = 0.0;
        }
    }
    return bad;
}

void vhe_bstar_from_logb(size_t n, const double *phis, const double *Psi,
                         double phis_min, double *Bstar, double *V)
{
    size_t c;
    int k;

    for (c = 0; c < n; ++c) {
        double *Bs = Bstar + 6 * c;
        if (phis[c] > phis_min) {
            const double r = sqrt(phis[c]);
            if (V) {
                sym_exp_v(Psi + 6 * c, Bs, V + 9 * c, 1);
            } else {
                vhe_sym_exp(Psi + 6 * c, Bs);
            }
            for (k = 0; k < 6; ++k) {
                Bs[k] *= r;
            }
        } else {
            Bs[0] = Bs[1] = Bs[2] = Bs[3] = Bs[4] = Bs[5] = 0.0;
        }
    }
}

double vhe_bstar_unimodular(size_t n, const double *phis, double phis_min,
                            double phis_solid, double *Bstar)
{
    double worst = 0.0;
    size_t c;
    int k;

    for (c = 0; c < n; ++c) {
        double *Bs = Bstar + 6 * c;
        double B[6], P[6], t;
        const double r = sqrt(phis[c]);
        if (!(phis[c] > phis_min)) {
            continue;
        }
        for (k = 0; k < 6; ++k) {
            B[k] = Bs[k] / r;
        }
        if (phis[c] > phis_solid) {
            worst = MAX2(worst, fabs(vhe_sym_det(B) - 1.0));
        }
        vhe_sym_log(B, P);
        t = (P[0] + P[3] + P[5]) / 3.0;
        P[0] -= t; P[3] -= t; P[5] -= t;
        vhe_sym_exp(P, B);
        for (k = 0; k < 6; ++k) {
            Bs[k] = r * B[k];
        }
    }
    return worst;
}
