/*
 * test_drain.c -- unit tests of the exchange that gives a drawn body's
 * edge cells the fluid composition beside them (drain.c).
 */
#include <check.h>
#include <math.h>

#include "vhe.h"

/* A row of four unit cells: body (held 1), edge (0.4, water 0.5 and air
   0.1 trapped), outside air (0.9 air, 0.1 water), air that the body
   reaches by 0.01, below the fraction 0.025 from which a cell moves with
   it: outside too.  One pass
   gives the edge cell the outside cell's composition (its fluid 0.6:
   0.06 water, 0.54 air), the outside cell taking the difference; fluid
   volumes and every cell's total are kept. */
START_TEST(test_drain_row)
{
    const int own[3] = {0, 1, 2}, nei[3] = {1, 2, 3};
    const double held[4] = {1.0, 0.4, 0.0, 0.01}, V[4] = {1, 1, 1, 1};
    double w[4] = {0.0, 0.5, 0.1, 0.0}, a[4] = {0.0, 0.1, 0.9, 0.99};
    const double *aa[2] = {w, a};
    double links[4] = {0}, dw[3], da[3];
    double *d[2] = {dw, da};
    int f;

    vhe_drain_links(3, own, nei, held, NULL, 0.025, links);
    ck_assert_double_eq(links[0], 0.0);
    ck_assert_double_eq(links[1], 1.0);
    ck_assert_double_eq(links[2], 1.0);
    ck_assert_double_eq(links[3], 0.0);
    vhe_drain_faces(3, own, nei, 2, aa, held, V, links, NULL, NULL, NULL,
                    NULL, 0.025, d);
    ck_assert_double_eq(dw[0], 0.0);
    ck_assert_double_eq(dw[2], 0.0);
    for (f = 0; f < 3; ++f) ck_assert_double_eq_tol(dw[f] + da[f], 0, 1e-16);
    for (f = 0; f < 3; ++f) {
        w[own[f]] += dw[f]; w[nei[f]] -= dw[f];
        a[own[f]] += da[f]; a[nei[f]] -= da[f];
    }
    ck_assert_double_eq_tol(w[1], 0.06, 1e-15);
    ck_assert_double_eq_tol(a[1], 0.54, 1e-15);
    ck_assert_double_eq_tol(w[2], 0.54, 1e-15);
    ck_assert_double_eq_tol(a[2], 0.46, 1e-15);
    ck_assert_double_eq_tol(w[0] + w[1] + w[2] + w[3], 0.6, 1e-15);
}
END_TEST

/* The outside cell holds too little of what the edge cells want (water
   0.01; each edge cell, of volume 4, wants 0.02 of it): each of its two
   edge faces (links 2) takes at most half of what it holds, and nothing
   goes below zero.  Across a coupled patch (nei NULL, the other side's
   values per face) each side computes the same volumes, opposite in
   sign. */
START_TEST(test_drain_limit)
{
    const int own[2] = {0, 2}, nei[2] = {1, 1};
    const double held[3] = {0.5, 0.0, 0.5}, V[3] = {4, 1, 4};
    double w[3] = {0.0, 0.01, 0.0}, a[3] = {0.5, 0.99, 0.5};
    const double *aa[2] = {w, a};
    double links[3] = {0}, dw[2], da[2];
    double *d[2] = {dw, da};
    int f;

    vhe_drain_links(2, own, nei, held, NULL, 0.025, links);
    ck_assert_double_eq(links[1], 2.0);
    vhe_drain_faces(2, own, nei, 2, aa, held, V, links, NULL, NULL, NULL,
                    NULL, 0.025, d);
    for (f = 0; f < 2; ++f) {
        ck_assert_double_eq_tol(dw[f], 0.005, 1e-15);
        ck_assert_double_eq_tol(dw[f] + da[f], 0.0, 1e-16);
        w[own[f]] += dw[f] / V[own[f]];
        w[nei[f]] -= dw[f] / V[nei[f]];
    }
    ck_assert(w[1] > -1e-17);
}
END_TEST

START_TEST(test_drain_coupled)
{
    /* side A: cell 0 outside (water 0.01, links 2); beyond, an edge cell */
    const int o[1] = {0};
    const double wA[1] = {0.01}, aA[1] = {0.99}, hA[1] = {0.0};
    const double VA[1] = {1.0}, lA[1] = {2.0};
    /* side B: cell 0 edge (held 0.5, air 0.5, links 1) */
    const double wB[1] = {0.0}, aB[1] = {0.5}, hB[1] = {0.5};
    const double VB[1] = {4.0}, lB[1] = {1.0};
    const double *fA[2] = {wA, aA}, *fB[2] = {wB, aB};
    double dwA, daA, dwB, daB;
    double *dA[2] = {&dwA, &daA}, *dB[2] = {&dwB, &daB};

    vhe_drain_faces(1, o, NULL, 2, fA, hA, VA, lA, fB, hB, VB, lB, 0.025, dA);
    vhe_drain_faces(1, o, NULL, 2, fB, hB, VB, lB, fA, hA, VA, lA, 0.025, dB);
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
    tcase_add_test(tc, test_drain_limit);
    tcase_add_test(tc, test_drain_coupled);
    suite_add_tcase(s, tc);
    return s;
}
