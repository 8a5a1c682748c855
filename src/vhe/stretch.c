/*
 * stretch.c -- the upper-convected stretch of B* over a time step.
 *
 * With the velocity gradient L held constant over dt, dB/dt = L B + B L^T
 * has the exact solution B(dt) = F B(0) F^T with F = exp(dt L).  The update
 * is a congruence, so it keeps B* symmetric positive (semi)definite for any
 * dt, and det(B*) changes by det(F)^2 = exp(2 dt tr L) exactly.
 */
#include "vhe.h"

#include <math.h>

/* C = A B for row-major 3x3 matrices (C must not alias A or B). */
static void mul3(const double *restrict A, const double *restrict B,
                 double *restrict C)
{
    int i, j;

    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j]
                           + A[3 * i + 2] * B[6 + j];
        }
    }
}

/*
 * Solves Q X = P for X (3x3, 3 right-hand sides) by Gaussian elimination
 * with partial pivoting.  Q and P are overwritten.  Q is the Pade
 * denominator, well conditioned after scaling (||A|| <= 1/2), so no
 * singularity check beyond a zero pivot is needed.
 */
static void solve3(double *restrict Q, double *restrict P,
                   double *restrict X)
{
    int col, r, j;

    for (col = 0; col < 3; ++col) {
        int piv = col;
        double best = fabs(Q[3 * col + col]);
        double d;

        for (r = col + 1; r < 3; ++r) {
            if (fabs(Q[3 * r + col]) > best) {
                best = fabs(Q[3 * r + col]);
                piv = r;
            }
        }
        if (piv != col) {
            for (j = 0; j < 3; ++j) {
                double t = Q[3 * col + j];
                Q[3 * col + j] = Q[3 * piv + j];
                Q[3 * piv + j] = t;
                t = P[3 * col + j];
                P[3 * col + j] = P[3 * piv + j];
                P[3 * piv + j] = t;
            }
        }
        d = Q[3 * col + col];
        for (r = col + 1; r < 3; ++r) {
            const double f = Q[3 * r + col] / d;
            for (j = col; j < 3; ++j) {
                Q[3 * r + j] -= f * Q[3 * col + j];
            }
            for (j = 0; j < 3; ++j) {
                P[3 * r + j] -= f * P[3 * col + j];
            }
        }
    }
    for (j = 0; j < 3; ++j) {
        for (r = 2; r >= 0; --r) {
            double s = P[3 * r + j];
            int k;
            for (k = r + 1; k < 3; ++k) {
                s -= Q[3 * r + k] * X[3 * k + j];
            }
            X[3 * r + j] = s / Q[3 * r + r];
        }
    }
}

void vhe_expm3(const double A[9], double E[9])
{
    /*
     * Diagonal Pade(6,6) coefficients c_k = (12-k)! 6! / (12! k! (6-k)!).
     * With ||A/2^s||_inf <= 1/2 the truncation error is below 1e-17
     * relative, under double round-off.
     */
    static const double c[7] = {
        1.0, 1.0 / 2.0, 5.0 / 44.0, 1.0 / 66.0, 1.0 / 792.0,
        1.0 / 15840.0, 1.0 / 665280.0
    };
    double As[9], A2[9], A4[9], A6[9], T[9], U[9], V[9], P[9], Q[9];
    double norm = 0.0;
    int i, s = 0, e = 0;

    /* Infinity norm (max row sum) decides the scaling. */
    for (i = 0; i < 3; ++i) {
        const double r = fabs(A[3 * i]) + fabs(A[3 * i + 1])
                         + fabs(A[3 * i + 2]);
        if (r > norm || r != r) {
            norm = r;
        }
    }
    if (!isfinite(norm)) {
        for (i = 0; i < 9; ++i) {
            E[i] = NAN;
        }
        return;
    }
    if (norm > 0.5) {
        /* norm = m 2^e, m in [0.5, 1): norm / 2^(e+1) = m/2 < 1/2. */
        (void)frexp(norm, &e);
        s = e + 1;
    }
    for (i = 0; i < 9; ++i) {
        As[i] = ldexp(A[i], -s);   /* exact: a power-of-two scaling */
    }

    mul3(As, As, A2);
    mul3(A2, A2, A4);
    mul3(A4, A2, A6);

    /* U = A (c1 I + c3 A^2 + c5 A^4),  V = c0 I + c2 A^2 + c4 A^4 + c6 A^6 */
    for (i = 0; i < 9; ++i) {
        T[i] = c[3] * A2[i] + c[5] * A4[i];
        V[i] = c[2] * A2[i] + c[4] * A4[i] + c[6] * A6[i];
    }
    T[0] += c[1];
    T[4] += c[1];
    T[8] += c[1];
    V[0] += c[0];
    V[4] += c[0];
    V[8] += c[0];
    mul3(As, T, U);

    /* exp(A) ~ (V - U)^{-1} (V + U) */
    for (i = 0; i < 9; ++i) {
        P[i] = V[i] + U[i];
        Q[i] = V[i] - U[i];
    }
    solve3(Q, P, E);

    /* Undo the scaling: exp(A) = exp(A/2^s)^(2^s). */
    for (; s > 0; --s) {
        mul3(E, E, T);
        for (i = 0; i < 9; ++i) {
            E[i] = T[i];
        }
    }
}

void vhe_stretch(size_t n, double dt, const double *gradU, double *Bstar)
{
    size_t c;

    for (c = 0; c < n; ++c) {
        const double *g = gradU + 9 * c;
        double *B = Bstar + 6 * c;
        double A[9], F[9], FB[9], Bf[9];

        /* Pure fluid carries B* = 0, which any congruence keeps at 0. */
        if (B[0] == 0.0 && B[1] == 0.0 && B[2] == 0.0 && B[3] == 0.0
            && B[4] == 0.0 && B[5] == 0.0) {
            continue;
        }

        /* dt L with L = gradU^T (OpenFOAM's grad(U)(i,j) = d u_j/d x_i). */
        A[0] = dt * g[0]; A[1] = dt * g[3]; A[2] = dt * g[6];
        A[3] = dt * g[1]; A[4] = dt * g[4]; A[5] = dt * g[7];
        A[6] = dt * g[2]; A[7] = dt * g[5]; A[8] = dt * g[8];
        vhe_expm3(A, F);

        Bf[0] = B[0]; Bf[1] = B[1]; Bf[2] = B[2];
        Bf[3] = B[1]; Bf[4] = B[3]; Bf[5] = B[4];
        Bf[6] = B[2]; Bf[7] = B[4]; Bf[8] = B[5];
        mul3(F, Bf, FB);

        /*
         * (F B F^T)_ij = sum_k (F B)_ik F_jk; only the upper triangle is
         * formed, so the result is symmetric by construction.
         */
#define VHE_FBFT(i, j) (FB[3 * (i)] * F[3 * (j)] \
                        + FB[3 * (i) + 1] * F[3 * (j) + 1] \
                        + FB[3 * (i) + 2] * F[3 * (j) + 2])
        B[0] = VHE_FBFT(0, 0);
        B[1] = VHE_FBFT(0, 1);
        B[2] = VHE_FBFT(0, 2);
        B[3] = VHE_FBFT(1, 1);
        B[4] = VHE_FBFT(1, 2);
        B[5] = VHE_FBFT(2, 2);
#undef VHE_FBFT
    }
}

void vhe_clip_fluid(size_t n, const double *phis, double phis_min,
                    double *Bstar)
{
    size_t c;

    for (c = 0; c < n; ++c) {
        if (!(phis[c] > phis_min)) {
            double *B = Bstar + 6 * c;
            B[0] = B[1] = B[2] = B[3] = B[4] = B[5] = 0.0;
        }
    }
}

void vhe_bstar_undeformed(size_t n, const double *phis, double *Bstar)
{
    size_t c;

    for (c = 0; c < n; ++c) {
        double *B = Bstar + 6 * c;
        const double p = phis[c];
        /* phi_s^(1/2), phi_s clipped to [0, 1] (0 in pure fluid). */
        const double sp = p > 0.0 ? (p < 1.0 ? sqrt(p) : 1.0) : 0.0;
        B[0] = sp; B[1] = 0.0; B[2] = 0.0;
        B[3] = sp; B[4] = 0.0; B[5] = sp;
    }
}

void vhe_b_from_bstar(size_t n, const double *phis, const double *Bstar,
                      double phis_min, double *B)
{
    size_t c;
    int k;

    for (c = 0; c < n; ++c) {
        const double *Bs = Bstar + 6 * c;
        double *b = B + 6 * c;
        if (phis[c] > phis_min) {
            const double r = 1.0 / sqrt(phis[c]);
            for (k = 0; k < 6; ++k) {
                b[k] = r * Bs[k];
            }
        } else {
            b[0] = 1.0; b[1] = 0.0; b[2] = 0.0;
            b[3] = 1.0; b[4] = 0.0; b[5] = 1.0;
        }
    }
}

void vhe_bdonor_internal(size_t nf, const int32_t *owner,
                         const int32_t *neighbour, const double *a,
                         const double *B, double *out, double *W, double *S)
{
    size_t f;
    int k;

    for (f = 0; f < nf; ++f) {
        /* from: the donor cell, to: the receiving cell */
        const int32_t from = a[f] >= 0.0 ? owner[f] : neighbour[f];
        const int32_t to = a[f] >= 0.0 ? neighbour[f] : owner[f];
        const double v = fabs(a[f]);
        const double *Bd = B + 6 * (size_t)from;
        double *s = S + 6 * (size_t)to;
        out[from] += v;
        W[to] += v;
        for (k = 0; k < 6; ++k) {
            s[k] += v * Bd[k];
        }
    }
}

void vhe_bdonor_boundary(size_t nf, const int32_t *face_cells,
                         const double *a, const double *Bnb, double *out,
                         double *W, double *S)
{
    size_t f;
    int k;

    for (f = 0; f < nf; ++f) {
        const int32_t c = face_cells[f];
        if (a[f] >= 0.0) {
            out[c] += a[f];
        } else {
            const double v = -a[f];
            double *s = S + 6 * (size_t)c;
            W[c] += v;
            for (k = 0; k < 6; ++k) {
                s[k] += v * Bnb[6 * f + k];
            }
        }
    }
}

size_t vhe_bdonor_finish(size_t n, const double *V, const double *phis0,
                         const double *phis, const double *Bold,
                         const double *out, const double *W, const double *S,
                         double phis_min, double *Bstar)
{
    size_t c, flushed = 0;
    int k;

    for (c = 0; c < n; ++c) {
        double *Bs = Bstar + 6 * c;
        if (phis[c] > phis_min) {
            const double *b0 = Bold + 6 * c;
            const double *s = S + 6 * c;
            double w0 = phis0[c] * V[c] - out[c];
            double wsum, r;
            if (w0 < 0.0) {
                w0 = 0.0;
                if (phis0[c] > phis_min) {
                    ++flushed;
                }
            }
            wsum = w0 + W[c];
            if (wsum > 0.0) {
                r = sqrt(phis[c]) / wsum;
                for (k = 0; k < 6; ++k) {
                    Bs[k] = r * (w0 * b0[k] + s[k]);
                }
            } else {
                /* solid appeared without a donor (round-off): undeformed */
                r = sqrt(phis[c]);
                Bs[0] = r; Bs[1] = 0.0; Bs[2] = 0.0;
                Bs[3] = r; Bs[4] = 0.0; Bs[5] = r;
            }
        } else {
            Bs[0] = Bs[1] = Bs[2] = Bs[3] = Bs[4] = Bs[5] = 0.0;
        }
    }
    return flushed;
}


/* Symmetric 3x3 from its 6 components (xx xy xz yy yz zz) and back. */
static void sym_full(const double *s, double *A)
{
    A[0] = s[0]; A[1] = s[1]; A[2] = s[2];
    A[3] = s[1]; A[4] = s[3]; A[5] = s[4];
    A[6] = s[2]; A[7] = s[4]; A[8] = s[5];
}

size_t vhe_stretch_implicit(size_t n, double tau, const double *gradU,
                            const double *Bhat, double *Bstar)
{
    static const int ij[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2},
                                 {2, 2}};
    size_t c, singular = 0;

    for (c = 0; c < n; ++c) {
        const double *g = gradU + 9 * c;
        const double *bh = Bhat + 6 * c;
        double *B = Bstar + 6 * c;
        double L[9], M[6][7];
        int p, q, k;

        if (bh[0] == 0.0 && bh[1] == 0.0 && bh[2] == 0.0 && bh[3] == 0.0
            && bh[4] == 0.0 && bh[5] == 0.0) {
            for (k = 0; k < 6; ++k) B[k] = 0.0;
            continue;
        }
        /* L = gradU^T (OpenFOAM's grad(U)(i,j) = d u_j/d x_i). */
        for (p = 0; p < 3; ++p) {
            for (q = 0; q < 3; ++q) L[3 * p + q] = g[3 * q + p];
        }
        /*
         * Column q of the system matrix: E_q - tau (L E_q + E_q L^T), E_q
         * the symmetric unit tensor of component q; last column Bhat.
         */
        for (q = 0; q < 6; ++q) {
            double e[6] = {0, 0, 0, 0, 0, 0}, E[9], LE[9];
            int i, j;

            e[q] = 1.0;
            sym_full(e, E);
            mul3(L, E, LE);
            for (p = 0; p < 6; ++p) {
                i = ij[p][0];
                j = ij[p][1];
                /* (L E + E L^T)_ij = (L E)_ij + (L E)_ji */
                M[p][q] = e[p] - tau * (LE[3 * i + j] + LE[3 * j + i]);
            }
        }
        for (p = 0; p < 6; ++p) M[p][6] = bh[p];

        /* Gaussian elimination with partial pivoting */
        for (k = 0; k < 6; ++k) {
            int piv = k;
            double big = fabs(M[k][k]), f;

            for (p = k + 1; p < 6; ++p) {
                if (fabs(M[p][k]) > big) {
                    big = fabs(M[p][k]);
                    piv = p;
                }
            }
            if (big < 1e-12) break;
            if (piv != k) {
                for (q = k; q < 7; ++q) {
                    double t = M[k][q];
                    M[k][q] = M[piv][q];
                    M[piv][q] = t;
                }
            }
            for (p = k + 1; p < 6; ++p) {
                f = M[p][k] / M[k][k];
                for (q = k; q < 7; ++q) M[p][q] -= f * M[k][q];
            }
        }
        if (k < 6) {
            ++singular;
            for (q = 0; q < 6; ++q) B[q] = bh[q];
            continue;
        }
        for (p = 5; p >= 0; --p) {
            double sum = M[p][6];
            for (q = p + 1; q < 6; ++q) sum -= M[p][q] * B[q];
            B[p] = sum / M[p][p];
        }
    }
    return singular;
}
