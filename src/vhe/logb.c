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
    vhe_sym_eigen(S, l, V, warm);
    for (i = 0; i < 3; ++i) {
        f[i] = l[i] > DBL_MIN ? log(l[i]) : log(DBL_MIN);
        floored += !(l[i] > DBL_MIN);
    }
    vhe_sym_from_eigen(V, f, L);
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
    vhe_sym_eigen(S, l, V, warm);
    for (i = 0; i < 3; ++i) {
        f[i] = exp(l[i]);
    }
    vhe_sym_from_eigen(V, f, E);
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
