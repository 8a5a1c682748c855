/*
 * shares.c -- the colours of one material that meet no other, carried on
 * the flux of their sum (vheMixture's colour transport, colourShares).
 *
 * The colours alpha_k of a material whose bodies touch no body of another
 * of its colours are transported as one phase, their sum A (MULES, as any
 * phase); colour k takes the share s_k of A's face flux F that its upwind
 * cell gives: the cell's composition alpha_k / A, or, where the step's
 * outflow exceeds what the cell holds (material passing through), the
 * composition of its content and its inflow together.  The colours sum to
 * A and none falls below zero.  vhe_share_meet tells which colours meet.
 *
 * The face kernels take, for internal faces, owner and neighbour cell
 * indices (own, nei); for boundary faces nei is NULL and the neighbour
 * cell's value (a coupled patch's other side) is given per face.
 */
#include "vhe.h"

void vhe_share_cells(long n, int K, const double *const *a,
                     double *const *s)
{
    long c;
    int k;
    for (c = 0; c < n; ++c) {
        double t = 0.0;
        for (k = 0; k < K; ++k) t += a[k][c] > 0.0 ? a[k][c] : 0.0;
        for (k = 0; k < K; ++k) {
            s[k][c] = t > 0.0 && a[k][c] > 0.0 ? a[k][c] / t : 0.0;
        }
    }
}


void vhe_share_flows(long nFaces, const int *own, const int *nei,
                     const double *restrict F, double *restrict out,
                     double *restrict in)
{
    long f;
    for (f = 0; f < nFaces; ++f) {
        if (F[f] > 0.0) {
            out[own[f]] += F[f];
            if (nei) in[nei[f]] += F[f];
        } else if (F[f] < 0.0) {
            in[own[f]] -= F[f];
            if (nei) out[nei[f]] -= F[f];
        }
    }
}


void vhe_share_inflow(long nFaces, const int *own, const int *nei,
                      const double *F, int K, const double *const *s,
                      const double *const *sNei, double *const *inK)
{
    long f;
    int k;
    for (f = 0; f < nFaces; ++f) {
        if (F[f] > 0.0 && nei) {
            for (k = 0; k < K; ++k) inK[k][nei[f]] += F[f] * s[k][own[f]];
        } else if (F[f] < 0.0) {
            for (k = 0; k < K; ++k) {
                inK[k][own[f]] -= F[f] * (nei ? s[k][nei[f]] : sNei[k][f]);
            }
        }
    }
}


long vhe_share_mix(long n, int K, const double *const *a,
                   const double *restrict V, double dt,
                   const double *restrict out, const double *restrict in,
                   const double *const *inK, double *const *s)
{
    long c, nMixed = 0;
    int k;
    for (c = 0; c < n; ++c) {
        double t = 0.0;
        for (k = 0; k < K; ++k) t += a[k][c] > 0.0 ? a[k][c] : 0.0;
        if (out[c] * dt > t * V[c]) {
            const double den = t * V[c] / dt + in[c];
            if (den > 0.0) {
                for (k = 0; k < K; ++k) {
                    const double ak = a[k][c] > 0.0 ? a[k][c] : 0.0;
                    s[k][c] = (ak * V[c] / dt + inK[k][c]) / den;
                }
            }
            ++nMixed;
        }
    }
    return nMixed;
}


void vhe_share_split(long nFaces, int K, const double *restrict F,
                     const double *const *up, double *const *out)
{
    long f;
    int k;
    for (f = 0; f < nFaces; ++f) {
        double su = 0.0;
        for (k = 0; k < K; ++k) su += up[k][f];
        if (su > 0.0) {
            for (k = 0; k < K; ++k) out[k][f] = F[f] * (up[k][f] / su);
        } else {
            /* The upwind cell neither holds nor receives any of the
               material: F is zero here; all of it to colour 0 keeps the
               sum exact */
            out[0][f] = F[f];
            for (k = 1; k < K; ++k) out[k][f] = 0.0;
        }
    }
}


int vhe_share_meet(long nFaces, const int *own, const int *nei,
                   const double *a, const double *b, const double *aNei,
                   const double *bNei, double tol)
{
    long f;
    for (f = 0; f < nFaces; ++f) {
        const double a0 = a[own[f]], b0 = b[own[f]];
        const double a1 = nei ? a[nei[f]] : aNei[f];
        const double b1 = nei ? b[nei[f]] : bNei[f];
        const double am = a0 > a1 ? a0 : a1, bm = b0 > b1 ? b0 : b1;
        if (am * bm > tol) return 1;
    }
    return 0;
}
