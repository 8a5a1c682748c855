/*
 * logb.c -- the deformation carried as its logarithm, Psi = log B
 * (log-conformation, Fattal & Kupferman 2004): matrix log and exp of
 * symmetric 3x3 tensors, and the kernels of the bounded second-order
 * conservative transport of phi_s Psi with the solid volume flux.
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

static int is_diagonal(const double S[6])
{
    return S[1] == 0.0 && S[2] == 0.0 && S[4] == 0.0;
}

int vhe_sym_log(const double S[6], double L[6])
{
    double l[3], V[9], f[3];
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
        return floored;
    }
    vhe_sym_eigen(S, l, V);
    for (i = 0; i < 3; ++i) {
        f[i] = l[i] > DBL_MIN ? log(l[i]) : log(DBL_MIN);
        floored += !(l[i] > DBL_MIN);
    }
    sym_from_eigen(V, f, L);
    return floored;
}

void vhe_sym_exp(const double S[6], double E[6])
{
    double l[3], V[9], f[3];
    int i;

    if (is_diagonal(S)) {
        E[0] = exp(S[0]); E[1] = 0.0; E[2] = 0.0;
        E[3] = exp(S[3]); E[4] = 0.0; E[5] = exp(S[5]);
        return;
    }
    vhe_sym_eigen(S, l, V);
    for (i = 0; i < 3; ++i) {
        f[i] = exp(l[i]);
    }
    sym_from_eigen(V, f, E);
}

size_t vhe_logb_from_bstar(size_t n, const double *phis, const double *Bstar,
                           double phis_min, double *Psi)
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
            bad += vhe_sym_log(B, P) != 0;
        } else {
            P[0] = P[1] = P[2] = P[3] = P[4] = P[5] = 0.0;
        }
    }
    return bad;
}

void vhe_bstar_from_logb(size_t n, const double *phis, const double *Psi,
                         double phis_min, double *Bstar)
{
    size_t c;
    int k;

    for (c = 0; c < n; ++c) {
        double *Bs = Bstar + 6 * c;
        if (phis[c] > phis_min) {
            const double r = sqrt(phis[c]);
            vhe_sym_exp(Psi + 6 * c, Bs);
            for (k = 0; k < 6; ++k) {
                Bs[k] *= r;
            }
        } else {
            Bs[0] = Bs[1] = Bs[2] = Bs[3] = Bs[4] = Bs[5] = 0.0;
        }
    }
}

/* ------------------------------------------------ low order (donor cell) */

size_t vhe_donor_finish(size_t n, const double *V, const double *phis0,
                        const double *phis, const double *Xold,
                        const double *out, const double *W, const double *S,
                        double phis_min, double *m, double *X)
{
    size_t c, flushed = 0;
    int k;

    for (c = 0; c < n; ++c) {
        double *x = X + 6 * c;
        m[c] = 0.0;
        x[0] = x[1] = x[2] = x[3] = x[4] = x[5] = 0.0;
        if (phis[c] > phis_min) {
            double w0 = phis0[c] * V[c] - out[c];
            if (w0 < 0.0) {
                w0 = 0.0;
                flushed += phis0[c] > phis_min;
            }
            m[c] = w0 + W[c];
            if (m[c] > 0.0) {
                for (k = 0; k < 6; ++k) {
                    x[k] = (w0 * Xold[6 * c + k] + S[6 * c + k]) / m[c];
                }
            }
            /* else: solid appeared without a donor (round-off): X = 0 */
        }
    }
    return flushed;
}

/* --------------------------------------------- high order (the gradient) */

void vhe_masked_grad_internal(size_t nf, const int32_t *owner,
                              const int32_t *neighbour, const double *Sf,
                              const double *w, const double *phis,
                              double phis_grad, const double *X, double *G)
{
    size_t f;
    int d, k;

    for (f = 0; f < nf; ++f) {
        const int32_t o = owner[f], nb = neighbour[f];
        if (!(phis[o] > phis_grad) || !(phis[nb] > phis_grad)) {
            continue;
        }
        for (k = 0; k < 6; ++k) {
            const double dX = X[6 * nb + k] - X[6 * o + k];
            for (d = 0; d < 3; ++d) {
                /* owner: S_f (X_f - X_o), X_f - X_o = (1 - w) dX;
                 * neighbour: -S_f (X_f - X_n), X_f - X_n = -w dX */
                G[18 * o + 6 * d + k] += Sf[3 * f + d] * (1.0 - w[f]) * dX;
                G[18 * nb + 6 * d + k] += Sf[3 * f + d] * w[f] * dX;
            }
        }
    }
}

void vhe_masked_grad_boundary(size_t nf, const int32_t *face_cells,
                              const double *Sf, const double *w,
                              const double *phis, const double *phis_nb,
                              double phis_grad, const double *X,
                              const double *X_nb, double *G)
{
    size_t f;
    int d, k;

    for (f = 0; f < nf; ++f) {
        const int32_t o = face_cells[f];
        if (!(phis[o] > phis_grad) || !(phis_nb[f] > phis_grad)) {
            continue;
        }
        for (k = 0; k < 6; ++k) {
            const double dX = X_nb[6 * f + k] - X[6 * o + k];
            for (d = 0; d < 3; ++d) {
                G[18 * o + 6 * d + k] += Sf[3 * f + d] * (1.0 - w[f]) * dX;
            }
        }
    }
}

/* ------------------------------------- antidiffusive flux and its limiter */

/* a (r . G) for the upwind cell's gradient G (18) and displacement r. */
static void face_increment(double a, const double r[3], const double *G,
                           double *A)
{
    int k;

    for (k = 0; k < 6; ++k) {
        A[k] = a * (r[0] * G[k] + r[1] * G[6 + k] + r[2] * G[12 + k]);
    }
}

void vhe_antidiffusive_internal(size_t nf, const int32_t *owner,
                                const int32_t *neighbour, const double *a,
                                const double *Cf, const double *C,
                                const double *U, double dt, const double *G,
                                double *A)
{
    size_t f;
    int d;

    for (f = 0; f < nf; ++f) {
        const int32_t up = a[f] >= 0.0 ? owner[f] : neighbour[f];
        double r[3];
        for (d = 0; d < 3; ++d) {
            r[d] = Cf[3 * f + d] - C[3 * up + d] - 0.5 * dt * U[3 * up + d];
        }
        face_increment(a[f], r, G + 18 * (size_t)up, A + 6 * f);
    }
}

void vhe_antidiffusive_boundary(size_t nf, const int32_t *face_cells,
                                const double *a, const double *Cf,
                                const double *C, const double *U,
                                const double *delta, const double *U_nb,
                                const double *G_nb, double dt,
                                const double *G, double *A)
{
    size_t f;
    int d;

    for (f = 0; f < nf; ++f) {
        const int32_t o = face_cells[f];
        double r[3];
        if (a[f] >= 0.0) {
            for (d = 0; d < 3; ++d) {
                r[d] = Cf[3 * f + d] - C[3 * o + d] - 0.5 * dt * U[3 * o + d];
            }
            face_increment(a[f], r, G + 18 * (size_t)o, A + 6 * f);
        } else {
            /* the neighbour's centre is C_o + delta */
            for (d = 0; d < 3; ++d) {
                r[d] = Cf[3 * f + d] - C[3 * o + d] - delta[3 * f + d]
                       - 0.5 * dt * U_nb[3 * f + d];
            }
            face_increment(a[f], r, G_nb + 18 * f, A + 6 * f);
        }
    }
}

void vhe_fct_extrema_init(size_t n, const double *phis0, const double *Xold,
                          const double *m, const double *X, double phis_min,
                          double *Xmin, double *Xmax)
{
    size_t c;
    int k;

    for (c = 0; c < n; ++c) {
        for (k = 0; k < 6; ++k) {
            double lo = HUGE_VAL, hi = -HUGE_VAL;
            if (phis0[c] > phis_min) {
                lo = hi = Xold[6 * c + k];
            }
            if (m[c] > 0.0) {
                lo = fmin(lo, X[6 * c + k]);
                hi = fmax(hi, X[6 * c + k]);
            }
            Xmin[6 * c + k] = lo;
            Xmax[6 * c + k] = hi;
        }
    }
}

void vhe_fct_extrema_internal(size_t nf, const int32_t *owner,
                              const int32_t *neighbour, const double *Emin,
                              const double *Emax, double *Xmin, double *Xmax)
{
    size_t f;
    int k;

    for (f = 0; f < nf; ++f) {
        const size_t o = 6 * (size_t)owner[f], nb = 6 * (size_t)neighbour[f];
        for (k = 0; k < 6; ++k) {
            Xmin[o + k] = fmin(Xmin[o + k], Emin[nb + k]);
            Xmax[o + k] = fmax(Xmax[o + k], Emax[nb + k]);
            Xmin[nb + k] = fmin(Xmin[nb + k], Emin[o + k]);
            Xmax[nb + k] = fmax(Xmax[nb + k], Emax[o + k]);
        }
    }
}

void vhe_fct_extrema_boundary(size_t nf, const int32_t *face_cells,
                              const double *Emin_nb, const double *Emax_nb,
                              double *Xmin, double *Xmax)
{
    size_t f;
    int k;

    for (f = 0; f < nf; ++f) {
        const size_t o = 6 * (size_t)face_cells[f];
        for (k = 0; k < 6; ++k) {
            Xmin[o + k] = fmin(Xmin[o + k], Emin_nb[6 * f + k]);
            Xmax[o + k] = fmax(Xmax[o + k], Emax_nb[6 * f + k]);
        }
    }
}

/* A[f] enters the neighbour (sign +1) or leaves the owner (sign -1). */
static void fct_sum(const double *A, double sign, double *Pp, double *Pm)
{
    int k;

    for (k = 0; k < 6; ++k) {
        const double v = sign * A[k];
        if (v > 0.0) {
            Pp[k] += v;
        } else {
            Pm[k] -= v;
        }
    }
}

void vhe_fct_sums_internal(size_t nf, const int32_t *owner,
                           const int32_t *neighbour, const double *A,
                           double *Pp, double *Pm)
{
    size_t f;

    for (f = 0; f < nf; ++f) {
        const size_t o = 6 * (size_t)owner[f], nb = 6 * (size_t)neighbour[f];
        fct_sum(A + 6 * f, -1.0, Pp + o, Pm + o);
        fct_sum(A + 6 * f, 1.0, Pp + nb, Pm + nb);
    }
}

void vhe_fct_sums_boundary(size_t nf, const int32_t *face_cells,
                           const double *A, double *Pp, double *Pm)
{
    size_t f;

    for (f = 0; f < nf; ++f) {
        const size_t o = 6 * (size_t)face_cells[f];
        fct_sum(A + 6 * f, -1.0, Pp + o, Pm + o);
    }
}

void vhe_fct_ratios(size_t n, const double *m, const double *X,
                    const double *Xmin, const double *Xmax, double *Rp,
                    double *Rm)
{
    size_t c;
    int k;

    for (c = 0; c < n; ++c) {
        for (k = 0; k < 6; ++k) {
            const size_t i = 6 * c + k;
            /* room above and below the local extrema, as content [m^3] */
            const double qp = m[c] * fmax(Xmax[i] - X[i], 0.0);
            const double qm = m[c] * fmax(X[i] - Xmin[i], 0.0);
            Rp[i] = Rp[i] > qp ? qp / Rp[i] : 1.0;
            Rm[i] = Rm[i] > qm ? qm / Rm[i] : 1.0;
        }
    }
}

/*
 * Limiters of a face flux A (into `in`, out of `from`), per component the
 * smaller of Zalesak's R+ and R- that bound it, then shared where the
 * trace needs it: tr Psi stays 0 if the three diagonal components take one
 * limiter (their increments sum to 0); each off-diagonal component keeps
 * its own.  (One limiter for all six would clip the shear wherever a
 * stretch component has an extremum and the other way round: 36x the
 * error of a smooth 1D profile at 64 cells, order 1.5 instead of 2.)
 */
static void fct_lambda(const double *A, const double *Rp_in,
                       const double *Rm_in, const double *Rp_from,
                       const double *Rm_from, double lam[6])
{
    int k;

    for (k = 0; k < 6; ++k) {
        lam[k] = 1.0;
        if (A[k] > 0.0) {
            lam[k] = fmin(Rp_in[k], Rm_from[k]);
        } else if (A[k] < 0.0) {
            lam[k] = fmin(Rm_in[k], Rp_from[k]);
        }
    }
    /* xx, yy, zz are components 0, 3, 5 */
    lam[0] = lam[3] = lam[5] = fmin(lam[0], fmin(lam[3], lam[5]));
}

void vhe_fct_apply_internal(size_t nf, const int32_t *owner,
                            const int32_t *neighbour, const double *A,
                            const double *Rp, const double *Rm, double *mX)
{
    size_t f;
    int k;

    for (f = 0; f < nf; ++f) {
        const size_t o = 6 * (size_t)owner[f], nb = 6 * (size_t)neighbour[f];
        const double *Af = A + 6 * f;
        double lam[6];
        fct_lambda(Af, Rp + nb, Rm + nb, Rp + o, Rm + o, lam);
        for (k = 0; k < 6; ++k) {
            mX[o + k] -= lam[k] * Af[k];
            mX[nb + k] += lam[k] * Af[k];
        }
    }
}

void vhe_fct_apply_boundary(size_t nf, const int32_t *face_cells,
                            const double *A, const double *Rp,
                            const double *Rm, const double *Rp_nb,
                            const double *Rm_nb, double *mX)
{
    size_t f;
    int k;

    for (f = 0; f < nf; ++f) {
        const size_t o = 6 * (size_t)face_cells[f];
        const double *Af = A + 6 * f;
        double lam[6];
        fct_lambda(Af, Rp_nb + 6 * f, Rm_nb + 6 * f, Rp + o, Rm + o, lam);
        for (k = 0; k < 6; ++k) {
            mX[o + k] -= lam[k] * Af[k];
        }
    }
}
