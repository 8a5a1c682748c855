/*
 * test_drain.c -- unit tests of the exchange that brings a drawn body's
 * edge cells' fluids into the range of the fluids beside them (drain.c).
 */
#include <check.h>
#include <math.h>

#include "vhe.h"

#define LO 0.025

/* The four kernels over n cells and the internal faces own/nei, two
   fluids w and a; d the volumes per face */
static void drain2(long n, long nF, const int *own, const int *nei,
                   double *w, double *a, const double *held,
                   const double *V, double *lambda, double *dw, double *da)
{
    const double *aa[2] = {w, a};
    double links[8] = {0}, s0[8] = {0}, s1[8] = {0};
    double n0[8], n1[8], x0[8], x1[8];
    double *sum[2] = {s0, s1}, *mn[2] = {n0, n1}, *mx[2] = {x0, x1};
    double *d[2] = {dw, da};
    long c;
    for (c = 0; c < n; ++c) { n0[c] = n1[c] = 2.0; x0[c] = x1[c] = -1.0; }
    vhe_drain_links(nF, own, nei, 2, aa, held, NULL, NULL, LO, links);
    vhe_drain_range(nF, own, nei, 2, aa, held, NULL, NULL, LO, sum, mn, mx);
    vhe_drain_lambda(n, 2, aa, links, (const double *const *)sum,
                     (const double *const *)mn, (const double *const *)mx,
                     lambda);
    vhe_drain_faces(nF, own, nei, 2, aa, held, V, links, lambda, NULL,
                    NULL, NULL, NULL, NULL, LO, d);
}

static void apply(long nF, const int *own, const int *nei, const double *V,
                  const double *dw, const double *da, double *w, double *a)
{
    long f;
    for (f = 0; f < nF; ++f) {
        w[own[f]] += dw[f] / V[own[f]]; w[nei[f]] -= dw[f] / V[nei[f]];
        a[own[f]] += da[f] / V[own[f]]; a[nei[f]] -= da[f] / V[nei[f]];
    }
}

/* A row of four unit cells: body (held 1), edge (0.4; water 0.5 and air
   0.1 trapped: water's share 0.83), air with a little water (share 0.1),
   air that the body reaches by 0.01, below the fraction 0.025 from which
   a cell moves with it: outside, but not beside the edge cell.  The edge
   cell takes the share 0.1 (0.06 water, 0.54 air), the outside cell the
   difference; fluid volumes and every cell's total are kept. */
START_TEST(test_drain_row)
{
    const int own[3] = {0, 1, 2}, nei[3] = {1, 2, 3};
    const double held[4] = {1.0, 0.4, 0.0, 0.01}, V[4] = {1, 1, 1, 1};
    double w[4] = {0.0, 0.5, 0.1, 0.0}, a[4] = {0.0, 0.1, 0.9, 0.99};
    double lambda[4], dw[3], da[3];
    int f;

    drain2(4, 3, own, nei, w, a, held, V, lambda, dw, da);
    ck_assert_double_eq(lambda[1], 1.0);
    ck_assert_double_eq(lambda[2], 0.0);   /* outside: no range */
    ck_assert_double_eq(dw[0], 0.0);
    ck_assert_double_eq(dw[2], 0.0);
    for (f = 0; f < 3; ++f) ck_assert_double_eq_tol(dw[f] + da[f], 0, 1e-16);
    apply(3, own, nei, V, dw, da, w, a);
    ck_assert_double_eq_tol(w[1], 0.06, 1e-15);
    ck_assert_double_eq_tol(a[1], 0.54, 1e-15);
    ck_assert_double_eq_tol(w[2], 0.54, 1e-15);
    ck_assert_double_eq_tol(a[2], 0.46, 1e-15);
    ck_assert_double_eq_tol(w[0] + w[1] + w[2] + w[3], 0.6, 1e-15);
}
END_TEST

/* An edge cell (held 0.5) between a half-air cell (water's share 0.2)
   and a water cell (1.0): a share of 0.6 lies in their range and is left
   as it is (taken to their mean, the edge cell would pass air from the
   one to the other every step); a share of 0.1 is brought to 0.2
   (lambda 0.2 towards the mean 0.6), both sides giving water. */
START_TEST(test_drain_range)
{
    const int own[2] = {0, 1}, nei[2] = {1, 2};
    const double held[3] = {0.0, 0.5, 0.0}, V[3] = {1, 1, 1};
    double w[3] = {0.2, 0.3, 1.0}, a[3] = {0.8, 0.2, 0.0};
    double lambda[3], dw[2], da[2];

    drain2(3, 2, own, nei, w, a, held, V, lambda, dw, da);
    ck_assert_double_eq(lambda[1], 0.0);
    ck_assert_double_eq(dw[0], 0.0);
    ck_assert_double_eq(dw[1], 0.0);

    w[1] = 0.05; a[1] = 0.45;
    drain2(3, 2, own, nei, w, a, held, V, lambda, dw, da);
    ck_assert_double_eq_tol(lambda[1], 0.2, 1e-15);
    ck_assert(dw[0] < 0.0);     /* from the owner (0) into cell 1 */
    ck_assert(dw[1] > 0.0);     /* from the neighbour (2) into cell 1 */
    apply(2, own, nei, V, dw, da, w, a);
    ck_assert_double_eq_tol(w[1] / (w[1] + a[1]), 0.2, 1e-15);
    ck_assert_double_eq_tol(w[0] + w[1] + w[2], 1.25, 1e-15);
    ck_assert_double_eq_tol(w[1] + a[1], 0.5, 1e-15);
}
END_TEST

/* The outside cell holds too little of what the edge cells want (water
   0.01; each edge cell, of volume 4, wants 0.02 of it): each of its two
   links takes at most half of what it holds, and nothing goes below
   zero. */
START_TEST(test_drain_limit)
{
    const int own[2] = {0, 2}, nei[2] = {1, 1};
    const double held[3] = {0.5, 0.0, 0.5}, V[3] = {4, 1, 4};
    double w[3] = {0.0, 0.01, 0.0}, a[3] = {0.5, 0.99, 0.5};
    double lambda[3], dw[2], da[2];
    int f;

    drain2(3, 2, own, nei, w, a, held, V, lambda, dw, da);
    for (f = 0; f < 2; ++f) {
        ck_assert_double_eq_tol(dw[f], 0.005, 1e-15);
        ck_assert_double_eq_tol(dw[f] + da[f], 0.0, 1e-16);
    }
    apply(2, own, nei, V, dw, da, w, a);
    ck_assert(w[1] > -1e-17);
}
END_TEST

/* Across a coupled patch (nei NULL, the other side's values per face)
   each side computes the same volumes, opposite in sign. */
START_TEST(test_drain_coupled)
{
    const int o[1] = {0};
    /* side A: an outside cell (water 0.01, links 2) */
    const double wA[1] = {0.01}, aA[1] = {0.99}, hA[1] = {0.0};
    const double VA[1] = {1.0}, lA[1] = {2.0}, mA[1] = {0.0};
    /* side B: an edge cell (held 0.5, air 0.5, links 1, lambda 1) */
    const double wB[1] = {0.0}, aB[1] = {0.5}, hB[1] = {0.5};
    const double VB[1] = {4.0}, lB[1] = {1.0}, mB[1] = {1.0};
    const double *fA[2] = {wA, aA}, *fB[2] = {wB, aB};
    double dwA, daA, dwB, daB;
    double *dA[2] = {&dwA, &daA}, *dB[2] = {&dwB, &daB};

    double s0 = 0, s1 = 0, n0 = 2, n1 = 2, x0 = -1, x1 = -1;
    double *sum[2] = {&s0, &s1}, *mn[2] = {&n0, &n1}, *mx[2] = {&x0, &x1};
    double links = 0;

    /* side A's range and links: its outside cell gets the link, the
       range is the edge cell's, on side B */
    vhe_drain_links(1, o, NULL, 2, fA, hA, fB, hB, LO, &links);
    ck_assert_double_eq(links, 1.0);
    vhe_drain_range(1, o, NULL, 2, fA, hA, fB, hB, LO, sum, mn, mx);
    ck_assert_double_eq(s0, 0.0);
    ck_assert_double_eq(x0, -1.0);
    vhe_drain_range(1, o, NULL, 2, fB, hB, fA, hA, LO, sum, mn, mx);
    ck_assert_double_eq_tol(s0, 0.01, 1e-15);
    ck_assert_double_eq_tol(x0, 0.01, 1e-15);

    vhe_drain_faces(1, o, NULL, 2, fA, hA, VA, lA, mA, fB, hB, VB, lB, mB,
                    LO, dA);
    vhe_drain_faces(1, o, NULL, 2, fB, hB, VB, lB, mB, fA, hA, VA, lA, mA,
                    LO, dB);
    ck_assert(dwB > 0.0);
    ck_assert_double_eq(dwA, -dwB);
    ck_assert_double_eq(daA, -daB);
    ck_assert_double_eq_tol(dwB, 0.005, 1e-15);
}
END_TEST

Suite *drain_suite(void)
{
    Suite *s = suite_create("drain");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_drain_row);
    tcase_add_test(tc, test_drain_range);
    tcase_add_test(tc, test_drain_limit);
    tcase_add_test(tc, test_drain_coupled);
    suite_add_tcase(s, tc);
    return s;
}
