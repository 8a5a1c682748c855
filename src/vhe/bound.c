/*
 * vheFoam C core: fractions brought into bounds conservatively (the
 * solids carried one by one by isoAdvector, solidAdvection::bound).
 */
#include "vhe.h"

/* Move dV of field k from cell c to cell n over internal face f */
static void bound_move(int k, int c, int n, int f, double dV, const int *own,
                       const double *V, double dt, double *const *a,
                       double *const *flux, double *moved)
{
    a[k][c] -= dV / V[c];
    a[k][n] += dV / V[n];
    flux[k][f] += (own[f] == c ? 1.0 : -1.0) * dV / dt;
    *moved += dV;
}

double vhe_bound_fractions(long nCells, long nInt, const int *own,
                           const int *nei, const long *cellStart,
                           const int *cellFaces, const double *V, int nS,
                           double *const *a, double *const *flux, double dt,
                           double *s, int nSweeps)
{
    const double tol = 1e-15;
    double moved = 0.0;

    /* Below 0: what a cell lacks, from the neighbours that hold the field */
    for (int k = 0; k < nS; ++k) {
        for (int sweep = 0; sweep < nSweeps; ++sweep) {
            long nUnder = 0;
            for (long c = 0; c < nCells; ++c) {
                if (a[k][c] >= -tol) continue;
                ++nUnder;
                double held = 0.0;
                for (long j = cellStart[c]; j < cellStart[c + 1]; ++j) {
                    const int f = cellFaces[j];
                    if (f >= nInt) continue;
                    const int n = own[f] == c ? nei[f] : own[f];
                    if (a[k][n] > 0) held += a[k][n] * V[n];
                }
                if (held <= 0) continue;
                const double need = -a[k][c] * V[c];
                const double take = need < held ? need : held;
                for (long j = cellStart[c]; j < cellStart[c + 1]; ++j) {
                    const int f = cellFaces[j];
                    if (f >= nInt) continue;
                    const int n = own[f] == c ? nei[f] : own[f];
                    if (a[k][n] <= 0) continue;
                    bound_move(k, n, (int)c, f, take * a[k][n] * V[n] / held,
                               own, V, dt, a, flux, &moved);
                }
            }
            if (nUnder == 0) break;
        }
    }

    /* Sum above 1: the excess to the neighbours with room, each field's
     * part in proportion to its fraction */
    for (long c = 0; c < nCells; ++c) {
        s[c] = 0.0;
        for (int k = 0; k < nS; ++k) s[c] += a[k][c];
    }
    for (int sweep = 0; sweep < nSweeps; ++sweep) {
        long nOver = 0;
        for (long c = 0; c < nCells; ++c) {
            if (s[c] <= 1.0 + tol) continue;
            ++nOver;
            double room = 0.0;
            for (long j = cellStart[c]; j < cellStart[c + 1]; ++j) {
                const int f = cellFaces[j];
                if (f >= nInt) continue;
                const int n = own[f] == c ? nei[f] : own[f];
                if (s[n] < 1.0) room += (1.0 - s[n]) * V[n];
            }
            if (room <= 0) continue;
            const double excess = (s[c] - 1.0) * V[c];
            const double give = excess < room ? excess : room;
            for (long j = cellStart[c]; j < cellStart[c + 1]; ++j) {
                const int f = cellFaces[j];
                if (f >= nInt) continue;
                const int n = own[f] == c ? nei[f] : own[f];
                if (s[n] >= 1.0) continue;
                const double dV = give * (1.0 - s[n]) * V[n] / room;
                for (int k = 0; k < nS; ++k) {
                    /* in proportion: a[k][c]/s[c] stays as it was */
                    if (a[k][c] > 0)
                        bound_move(k, (int)c, n, f, dV * a[k][c] / s[c], own,
                                   V, dt, a, flux, &moved);
                }
                s[n] += dV / V[n];
                s[c] -= dV / V[c];
            }
        }
        if (nOver == 0) break;
    }
    return moved;
}

/* Face f of cell c: the volume it could carry out of c over the step
 * (returned; <= 0 if it is no downwind face) and in *lim what it can still
 * take: over, room for more of the field through it; under, what it
 * carries out */
static double downwind_face(int f, long c, const int *own, const double *phi,
                            const double *dVf, double dt, int over,
                            double *s, double *lim)
{
    *s = own[f] == c ? 1.0 : -1.0;
    const double out = *s * phi[f] * dt;
    *lim = over ? out - *s * dVf[f] : *s * dVf[f];
    return out;
}

double vhe_bound_downwind(long nCells, long nInt, const int *own,
                          const int *nei, const long *cellStart,
                          const int *cellFaces, const double *V,
                          const double *phi, double *dVf, double *a,
                          double dt, const unsigned char *check, int above,
                          int below, double tol, int nSweeps)
{
    double moved = 0.0;
    for (int sweep = 0; sweep < nSweeps; ++sweep) {
        long nOut = 0;
        for (long c = 0; c < nCells; ++c) {
            if (check && !check[c]) continue;
            const int over = above && a[c] > 1.0 + tol;
            if (!over && !(below && a[c] < -tol)) continue;
            ++nOut;
            /* Repeated while a face reaches its limit and some is left:
             * the rest goes to the other downwind faces */
            for (long pass = cellStart[c]; pass <= cellStart[c + 1]; ++pass) {
                const double left = over ? (a[c] - 1.0) * V[c] : -a[c] * V[c];
                if (left <= tol * V[c]) break;
                double total = 0.0;
                for (long j = cellStart[c]; j < cellStart[c + 1]; ++j) {
                    double s, lim;
                    const double out = downwind_face(cellFaces[j], c, own,
                                                     phi, dVf, dt, over, &s,
                                                     &lim);
                    if (out > 0 && lim > tol * V[c]) total += out;
                }
                if (total <= 0) break;
                int capped = 0;
                for (long j = cellStart[c]; j < cellStart[c + 1]; ++j) {
                    const int f = cellFaces[j];
                    double s, lim;
                    const double out = downwind_face(f, c, own, phi, dVf, dt,
                                                     over, &s, &lim);
                    if (out <= 0 || lim <= tol * V[c]) continue;
                    double dV = left * out / total;
                    if (dV >= lim) { dV = lim; capped = 1; }
                    /* over: more leaves c; under: less leaves c */
                    const double sg = over ? 1.0 : -1.0;
                    dVf[f] += sg * s * dV;
                    a[c] -= sg * dV / V[c];
                    if (f < nInt) {
                        const int n = own[f] == c ? nei[f] : own[f];
                        a[n] += sg * dV / V[n];
                    }
                    moved += dV;
                }
                if (!capped) break;
            }
        }
        if (nOut == 0) break;
    }
    return moved;
}
