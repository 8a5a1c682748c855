/*
 * transport.c -- bounded conservative transport of a symmTensor per unit
 * solid volume (Psi = log B, logb.c) with the solid volume flux: donor
 * cell, least-squares gradient, the antidiffusive flux to the QUICKEST face
 * value and Zalesak's flux-corrected transport (vhe.h says how the steps
 * fit together).  Every update is linear in X with one coefficient for the
 * three diagonal components, so tr X is kept exactly.
 *
 * symmTensor layout (xx xy xz yy yz zz); gradients of a symmTensor are 18
 * doubles per cell: d/dx (6), d/dy (6), d/dz (6).
 */
#include "vhe.h"

#include <math.h>

/* min and max without fmin/fmax's NaN rules (library calls at -O2) */
#define MIN2(a, b) ((a) < (b) ? (a) : (b))
#define MAX2(a, b) ((a) > (b) ? (a) : (b))

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

/* Weighted least squares over the neighbour d (from the cell), X_nb - X_c */
static void lsq_add(const double *d, const double *dX, double *M, double *b)
{
    const double w = 1.0 / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    int i, k;

    M[0] += w * d[0] * d[0]; M[1] += w * d[0] * d[1];
    M[2] += w * d[0] * d[2]; M[3] += w * d[1] * d[1];
    M[4] += w * d[1] * d[2]; M[5] += w * d[2] * d[2];
    for (i = 0; i < 3; ++i) {
        for (k = 0; k < 6; ++k) {
            b[6 * i + k] += w * d[i] * dX[k];
        }
    }
}

void vhe_lsq_grad_internal(size_t nf, const int32_t *owner,
                           const int32_t *neighbour, const double *delta,
                           const double *phis, double phis_grad,
                           const double *X, double *M, double *b)
{
    size_t f;
    int k;

    for (f = 0; f < nf; ++f) {
        const int32_t o = owner[f], nb = neighbour[f];
        double dX[6];
        if (!(phis[o] > phis_grad) || !(phis[nb] > phis_grad)) {
            continue;
        }
        for (k = 0; k < 6; ++k) {
            dX[k] = X[6 * nb + k] - X[6 * o + k];
        }
        /* the same d dX products for both cells */
        lsq_add(delta + 3 * f, dX, M + 6 * o, b + 18 * o);
        lsq_add(delta + 3 * f, dX, M + 6 * nb, b + 18 * nb);
    }
}

void vhe_lsq_grad_boundary(size_t nf, const int32_t *face_cells,
                           const double *delta, const double *phis,
                           const double *phis_nb, double phis_grad,
                           const double *X, const double *X_nb, double *M,
                           double *b)
{
    size_t f;
    int k;

    for (f = 0; f < nf; ++f) {
        const int32_t o = face_cells[f];
        double dX[6];
        if (!(phis[o] > phis_grad) || !(phis_nb[f] > phis_grad)) {
            continue;
        }
        for (k = 0; k < 6; ++k) {
            dX[k] = X_nb[6 * f + k] - X[6 * o + k];
        }
        lsq_add(delta + 3 * f, dX, M + 6 * o, b + 18 * o);
    }
}

void vhe_lsq_grad_finish(size_t n, double *M, double *b, double *G)
{
    size_t c;
    int i, j, k;

    for (c = 0; c < n; ++c) {
        double *m = M + 6 * c;
        const double tr = m[0] + m[3] + m[5];
        if (!(tr > 0.0)) {
            for (k = 0; k < 18; ++k) {
                G[18 * c + k] = 0.0;   /* no neighbour: no gradient */
            }
            continue;
        }
        /* directions without neighbours (2D's empty one, a cell with
         * neighbours on one line only) get no gradient: regularise by a
         * round-off fraction of the trace */
        const double e = 1e-10 * tr;
        const double a00 = m[0] + e, a01 = m[1], a02 = m[2];
        const double a11 = m[3] + e, a12 = m[4], a22 = m[5] + e;
        double inv[9], det;
        inv[0] = a11 * a22 - a12 * a12;
        inv[1] = a02 * a12 - a01 * a22;
        inv[2] = a01 * a12 - a02 * a11;
        inv[4] = a00 * a22 - a02 * a02;
        inv[5] = a01 * a02 - a00 * a12;
        inv[8] = a00 * a11 - a01 * a01;
        inv[3] = inv[1]; inv[6] = inv[2]; inv[7] = inv[5];
        det = a00 * inv[0] + a01 * inv[1] + a02 * inv[2];
        for (i = 0; i < 3; ++i) {
            for (k = 0; k < 6; ++k) {
                double g = 0.0;
                if (tr > 0.0) {
                    for (j = 0; j < 3; ++j) {
                        g += inv[3 * i + j] * b[18 * c + 6 * j + k];
                    }
                    g /= det;
                }
                G[18 * c + 6 * i + k] = g;
            }
        }
        /* consumed: ready for the next step without a pass over all cells */
        for (k = 0; k < 6; ++k) {
            m[k] = 0.0;
        }
        for (k = 0; k < 18; ++k) {
            b[18 * c + k] = 0.0;
        }
    }
}

/* ------------------------------------- antidiffusive flux and its limiter */

/*
 * Antidiffusive flux of one face: a (X_f - X_up), the QUICKEST face value
 * (Leonard 1979) in the gradient form of MUSCL-Hancock:
 *   X_f = X_up + r . G_up + k/2 ((X_dn - X_up) - d . G_up),
 *   r = x_f - x_up - dt/2 U_up,  d = x_dn - x_up,
 *   k = (1 - c)(1 - 2c)/3,  c = |a| / (|S_f| |d| phis_up) (face Courant),
 * which in 1D on a uniform mesh is third order in space and time; k = 0
 * (Fromm's scheme, second order, its error 5x larger at c = 0.1 than at
 * 0.4) where the downwind cell takes no part in gradients.
 */
static void face_increment(double a, double magSf, const double *d,
                           const double *r, double phis_up, int curvature,
                           const double *X_up, const double *X_dn,
                           const double *G, double *A)
{
    const double magd = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double c = fabs(a) / (magSf * magd * phis_up);
    double k;
    int i;

    c = c < 1.0 ? c : 1.0;
    k = curvature ? (1.0 - c) * (1.0 - 2.0 * c) / 3.0 : 0.0;
    for (i = 0; i < 6; ++i) {
        const double rG = r[0] * G[i] + r[1] * G[6 + i] + r[2] * G[12 + i];
        const double dG = d[0] * G[i] + d[1] * G[6 + i] + d[2] * G[12 + i];
        A[i] = a * (rG + 0.5 * k * ((X_dn[i] - X_up[i]) - dG));
    }
}

void vhe_antidiffusive_internal(size_t nf, const int32_t *owner,
                                const int32_t *neighbour, const double *a,
                                const double *Sf, const double *delta,
                                const double *Cf, const double *C,
                                const double *U, const double *phis,
                                double phis_grad, const double *X,
                                const double *G, double dt, double *A)
{
    size_t f;
    int k;

    for (f = 0; f < nf; ++f) {
        const int fwd = a[f] >= 0.0;
        const int32_t up = fwd ? owner[f] : neighbour[f];
        const int32_t dn = fwd ? neighbour[f] : owner[f];
        const double *S = Sf + 3 * f;
        double r[3], d[3];
        if (!(phis[up] > phis_grad)) {
            for (k = 0; k < 6; ++k) {
                A[6 * f + k] = 0.0;    /* G_up = 0: donor cell */
            }
            continue;
        }
        for (k = 0; k < 3; ++k) {
            r[k] = Cf[3 * f + k] - C[3 * up + k] - 0.5 * dt * U[3 * up + k];
            d[k] = fwd ? delta[3 * f + k] : -delta[3 * f + k];
        }
        face_increment(a[f], sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2]),
                       d, r, phis[up], phis[dn] > phis_grad, X + 6 * up,
                       X + 6 * dn, G + 18 * (size_t)up, A + 6 * f);
    }
}

void vhe_antidiffusive_boundary(size_t nf, const int32_t *face_cells,
                                const double *a, const double *Sf,
                                const double *delta, const double *Cf,
                                const double *C, const double *U,
                                const double *phis, const double *phis_nb,
                                double phis_grad, const double *X,
                                const double *X_nb, const double *U_nb,
                                const double *G, const double *G_nb,
                                double dt, double *A)
{
    size_t f;
    int k;

    for (f = 0; f < nf; ++f) {
        const int32_t o = face_cells[f];
        const double *S = Sf + 3 * f;
        const double magSf = sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2]);
        const int fwd = a[f] >= 0.0;
        const double phis_up = fwd ? phis[o] : phis_nb[f];
        const double phis_dn = fwd ? phis_nb[f] : phis[o];
        double r[3], d[3];
        if (!(phis_up > phis_grad)) {
            for (k = 0; k < 6; ++k) {
                A[6 * f + k] = 0.0;
            }
            continue;
        }
        if (fwd) {
            for (k = 0; k < 3; ++k) {
                r[k] = Cf[3 * f + k] - C[3 * o + k] - 0.5 * dt * U[3 * o + k];
                d[k] = delta[3 * f + k];
            }
            face_increment(a[f], magSf, d, r, phis_up, phis_dn > phis_grad,
                           X + 6 * o, X_nb + 6 * f, G + 18 * (size_t)o,
                           A + 6 * f);
        } else {
            /* the neighbour's centre is x_o + delta */
            for (k = 0; k < 3; ++k) {
                r[k] = Cf[3 * f + k] - C[3 * o + k] - delta[3 * f + k]
                       - 0.5 * dt * U_nb[3 * f + k];
                d[k] = -delta[3 * f + k];
            }
            face_increment(a[f], magSf, d, r, phis_up, phis_dn > phis_grad,
                           X_nb + 6 * f, X + 6 * o, G_nb + 18 * f,
                           A + 6 * f);
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
                lo = MIN2(lo, X[6 * c + k]);
                hi = MAX2(hi, X[6 * c + k]);
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
        if (Emin[o] == HUGE_VAL && Emin[nb] == HUGE_VAL) {
            continue;   /* no solid on either side: nothing to bound */
        }
        for (k = 0; k < 6; ++k) {
            Xmin[o + k] = MIN2(Xmin[o + k], Emin[nb + k]);
            Xmax[o + k] = MAX2(Xmax[o + k], Emax[nb + k]);
            Xmin[nb + k] = MIN2(Xmin[nb + k], Emin[o + k]);
            Xmax[nb + k] = MAX2(Xmax[nb + k], Emax[o + k]);
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
            Xmin[o + k] = MIN2(Xmin[o + k], Emin_nb[6 * f + k]);
            Xmax[o + k] = MAX2(Xmax[o + k], Emax_nb[6 * f + k]);
        }
    }
}

static int is_zero6(const double *A)
{
    return A[0] == 0.0 && A[1] == 0.0 && A[2] == 0.0 && A[3] == 0.0
           && A[4] == 0.0 && A[5] == 0.0;
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
        if (is_zero6(A + 6 * f)) {
            continue;
        }
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
        if (m[c] == 0.0) {
            /* no solid content: no room, so no flux into it (none leaves
             * it either: its gradient is 0) */
            for (k = 0; k < 6; ++k) {
                Rp[6 * c + k] = Rp[6 * c + k] > 0.0 ? 0.0 : 1.0;
                Rm[6 * c + k] = Rm[6 * c + k] > 0.0 ? 0.0 : 1.0;
            }
            continue;
        }
        for (k = 0; k < 6; ++k) {
            const size_t i = 6 * c + k;
            /* room above and below the local extrema, as content [m^3],
             * plus a round-off allowance: a component that is constant
             * to round-off (Psi_zz = 0 in 2D) has no room, and its
             * round-off fluxes would otherwise stop the antidiffusion of
             * the diagonal components it shares its limiter with */
            const double tiny = 1e-12 * m[c];
            const double qp = m[c] * MAX2(Xmax[i] - X[i], 0.0) + tiny;
            const double qm = m[c] * MAX2(X[i] - Xmin[i], 0.0) + tiny;
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
            lam[k] = MIN2(Rp_in[k], Rm_from[k]);
        } else if (A[k] < 0.0) {
            lam[k] = MIN2(Rm_in[k], Rp_from[k]);
        }
    }
    /* xx, yy, zz are components 0, 3, 5 */
    lam[0] = lam[3] = lam[5] = MIN2(lam[0], MIN2(lam[3], lam[5]));
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
        if (is_zero6(Af)) {
            continue;
        }
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

