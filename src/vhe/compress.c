/*
 * compress.c -- interface compression between two phases (vheMixture's
 * MULES fluxes), as multiphaseMixture computes it with linear face values:
 * the flux of phase i towards itself across its interface with phase j,
 *   C = phic (n . Sf) a_i a_j,  n = g / (|g| + deltaN),
 *   g = a_j grad a_i - a_i grad a_j,
 * added to phase i's flux and taken from phase j's, in one pass over the
 * faces (no field temporaries per pair).  Faces where a_i a_j < 1e-15,
 * where |C| is below the round-off of the flux, are skipped.
 */
#include <math.h>

#include "vhe.h"

void vhe_compress_pair(long nFaces, const double *restrict phic,
                       const double *restrict Sf, const double *restrict ai,
                       const double *restrict aj, const double *restrict gi,
                       const double *restrict gj, double deltaN,
                       double *restrict fi, double *restrict fj)
{
    long f;
    int k;
    for (f = 0; f < nFaces; ++f) {
        double g[3], gS = 0.0, g2 = 0.0, C;
        /* |C| <= phic |Sf| a_i a_j: below round-off of the flux where the
           product is below 1e-15 (most faces: one phase is absent) */
        if (ai[f] * aj[f] < 1e-15) continue;
        for (k = 0; k < 3; ++k) {
            g[k] = aj[f] * gi[3 * f + k] - ai[f] * gj[3 * f + k];
            gS += g[k] * Sf[3 * f + k];
            g2 += g[k] * g[k];
        }
        C = phic[f] * (gS / (sqrt(g2) + deltaN)) * ai[f] * aj[f];
        fi[f] += C;
        fj[f] -= C;
    }
}
