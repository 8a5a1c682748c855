/*
 * packing.c -- deterministic body packings: lattice and seeded random
 * sequential addition, with periodic images.  Lengths in m.
 */
#include "vhe.h"

#include <math.h>

uint64_t vhe_rng_next(uint64_t *state)
{
    /* splitmix64 (Steele, Lea, Flood 2014): pure 64-bit integer arithmetic,
     * so the sequence is bit-identical on every platform. */
    uint64_t z = (*state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

double vhe_rng_uniform(uint64_t *state)
{
    /* Top 53 bits scaled by 2^-53: exact doubles in [0, 1). */
    return (double)(vhe_rng_next(state) >> 11) * (1.0 / 9007199254740992.0);
}

/* Tolerance for "exactly fits": spacing >= (2r + gap)(1 - tol). */
#define VHE_FIT_TOL 1e-12

static int finite_box(const double *lo, const double *hi, int nd)
{
    int d;
    for (d = 0; d < nd; ++d) {
        if (!isfinite(lo[d]) || !isfinite(hi[d]) || !(hi[d] > lo[d])) {
            return 0;
        }
    }
    return 1;
}

int vhe_pack_lattice(const double lo[3], const double hi[3], const int n[3],
                     double radius, double gap, int ndim, double *centres)
{
    const int nd = (ndim == 2) ? 2 : 3;
    double sp[3];
    int d, i, j, k;
    size_t m = 0;

    if (lo == NULL || hi == NULL || n == NULL || !(radius > 0.0)
        || !(gap >= 0.0) || !isfinite(radius) || !isfinite(gap)
        || n[0] < 0 || n[1] < 0 || n[2] < 0) {
        return VHE_EBADARG;
    }
    if (n[0] == 0 || n[1] == 0 || n[2] == 0) {
        return VHE_OK;   /* no body requested */
    }
    if (centres == NULL || !finite_box(lo, hi, nd)
        || (nd == 2 && !(isfinite(lo[2]) && isfinite(hi[2])))) {
        return VHE_EBADARG;
    }
    /*
     * Each body owns a lattice cell of edge sp[d]; it fits with clearance
     * >= gap to its neighbours (and >= gap/2 to the box) iff
     * sp[d] >= 2 r + gap in every counted direction.  In 2D, n[2] > 1
     * would stack coincident disks: they overlap.
     */
    for (d = 0; d < 3; ++d) {
        sp[d] = (hi[d] - lo[d]) / n[d];
        if (d < nd && sp[d] < (2.0 * radius + gap) * (1.0 - VHE_FIT_TOL)) {
            return VHE_ENOFIT;
        }
    }
    if (nd == 2 && n[2] > 1) {
        return VHE_ENOFIT;
    }
    /* x fastest, then y, then z. */
    for (k = 0; k < n[2]; ++k) {
        for (j = 0; j < n[1]; ++j) {
            for (i = 0; i < n[0]; ++i) {
                centres[3 * m] = lo[0] + (i + 0.5) * sp[0];
                centres[3 * m + 1] = lo[1] + (j + 0.5) * sp[1];
                centres[3 * m + 2] = lo[2] + (k + 0.5) * sp[2];
                ++m;
            }
        }
    }
    return VHE_OK;
}

/* Squared centre distance, nearest periodic image (minimum image is exact
 * for an orthogonal box), z ignored when nd = 2. */
static double dist2(const double *a, const double *b, const double *len,
                    const int *periodic, int nd)
{
    double s = 0.0;
    int d;

    for (d = 0; d < nd; ++d) {
        double x = a[d] - b[d];
        if (periodic != NULL && periodic[d]) {
            x -= len[d] * floor(x / len[d] + 0.5);
        }
        s += x * x;
    }
    return s;
}

int vhe_pack_random(const double lo[3], const double hi[3],
                    const int periodic[3], int ndim, size_t count,
                    double radius, double gap, uint64_t seed,
                    size_t max_tries, double *centres, size_t *placed)
{
    const int nd = (ndim == 2) ? 2 : 3;
    const double reach = 2.0 * radius + gap;  /* min centre distance [m] */
    const double reach2 = reach * reach;
    double len[3], base[3], span[3];
    uint64_t state = seed;
    size_t np = 0, tries = 0, j;
    int d;

    if (placed != NULL) {
        *placed = 0;
    }
    if (lo == NULL || hi == NULL || placed == NULL || !(radius > 0.0)
        || !(gap >= 0.0) || !isfinite(radius) || !isfinite(gap)
        || !finite_box(lo, hi, nd) || (count > 0 && centres == NULL)) {
        return VHE_EBADARG;
    }
    if (count == 0) {
        return VHE_OK;
    }
    for (d = 0; d < nd; ++d) {
        len[d] = hi[d] - lo[d];
        if (periodic != NULL && periodic[d]) {
            /* A body closer than gap to its own image cannot be placed. */
            if (len[d] < reach) {
                return VHE_ENOFIT;
            }
            base[d] = lo[d];
            span[d] = len[d];
        } else {
            /* Centres at least r + gap from the walls. */
            base[d] = lo[d] + radius + gap;
            span[d] = len[d] - 2.0 * (radius + gap);
            if (span[d] < 0.0) {
                return VHE_ENOFIT;
            }
        }
    }

    while (np < count && tries < max_tries) {
        double c[3];
        int ok = 1;

        ++tries;
        for (d = 0; d < nd; ++d) {
            c[d] = base[d] + span[d] * vhe_rng_uniform(&state);
        }
        if (nd == 2) {
            c[2] = 0.5 * (lo[2] + hi[2]);   /* 2D: disks at mid z */
        }
        for (j = 0; j < np; ++j) {
            if (dist2(c, centres + 3 * j, len, periodic, nd) < reach2) {
                ok = 0;
                break;
            }
        }
        if (ok) {
            centres[3 * np] = c[0];
            centres[3 * np + 1] = c[1];
            centres[3 * np + 2] = c[2];
            ++np;
        }
    }
    *placed = np;
    return np == count ? VHE_OK : VHE_ENOFIT;
}

double vhe_min_clearance(const double lo[3], const double hi[3],
                         const int periodic[3], int ndim, size_t n,
                         double radius, const double *centres)
{
    const int nd = (ndim == 2) ? 2 : 3;
    double len[3], m2 = HUGE_VAL;
    size_t i, j;
    int d;

    if (n < 2 || centres == NULL) {
        return HUGE_VAL;
    }
    for (d = 0; d < 3; ++d) {
        len[d] = (lo != NULL && hi != NULL) ? hi[d] - lo[d] : 0.0;
    }
    for (i = 0; i < n; ++i) {
        for (j = i + 1; j < n; ++j) {
            const double s = dist2(centres + 3 * i, centres + 3 * j, len,
                                   (lo != NULL && hi != NULL) ? periodic
                                                              : NULL, nd);
            if (s < m2) {
                m2 = s;
            }
        }
    }
    return sqrt(m2) - 2.0 * radius;
}
