/*
 * test_contact.c -- unit tests of the contact kernels (contact.c): a
 * body's proximity over a 1D row of cells and the contact force density.
 */
#include <check.h>
#include <math.h>

#include "vhe.h"

/* A row of 10 cells, faces f between cells f and f + 1. */
#define N 10

static void row_faces(int own[N - 1], int nei[N - 1])
{
    int f;
    for (f = 0; f < N - 1; ++f) { own[f] = f; nei[f] = f + 1; }
}

/* A body covering cells 0..3 (edge cell 3 at fraction 0.3): psi is 1
 * where alpha >= 1/2, 2 alpha in the edge, and falls by 1/range per
 * layer: with range 1.5, 0.6 - 2/3 < 0 next to the edge, and each
 * layer only raises psi (a max). */
START_TEST(test_proximity)
{
    const double alpha[N] = {1, 1, 0.9, 0.3, 0, 0, 0, 0, 0, 0};
    int own[N - 1], nei[N - 1], c, layer;
    double psi[N], last[N];
    const double step = 1.0 / 1.5;

    row_faces(own, nei);
    vhe_proximity_start(N, alpha, psi);
    ck_assert_double_eq_tol(psi[2], 1.0, 1e-15);
    ck_assert_double_eq_tol(psi[3], 0.6, 1e-15);
    ck_assert_double_eq_tol(psi[4], 0.0, 1e-15);

    for (layer = 0; layer < 2; ++layer) {
        for (c = 0; c < N; ++c) last[c] = psi[c];
        vhe_proximity_layer(N - 1, own, nei, last, step, psi);
    }
    /* two layers (ceil 1.5): cell 3 keeps max(0.6, 1 - 2/3) = 0.6, and
     * cell 4 gets nothing: 0.6 - 2/3 < 0 */
    ck_assert_double_eq_tol(psi[3], 0.6, 1e-15);
    ck_assert_double_eq_tol(psi[4], 0.0, 1e-15);
    for (c = 5; c < N; ++c) ck_assert_double_eq(psi[c], 0.0);

    /* range 2: one more layer reaches, 1 - 1/2 = 0.5 next to the core */
    vhe_proximity_start(N, alpha, psi);
    for (layer = 0; layer < 2; ++layer) {
        for (c = 0; c < N; ++c) last[c] = psi[c];
        vhe_proximity_layer(N - 1, own, nei, last, 0.5, psi);
    }
    ck_assert_double_eq_tol(psi[3], 0.6, 1e-15);
    ck_assert_double_eq_tol(psi[4], 0.1, 1e-15);
    ck_assert_double_eq_tol(psi[5], 0.0, 1e-15);
}
END_TEST

/* The force density -coef alpha psi grad(psi) points down the proximity's
 * gradient (away from the body) in proportion to each factor, and is
 * zero where any factor is. */
START_TEST(test_contact_force)
{
    const double coef[3] = {2.0, 2.0, 2.0};
    const double alpha[3] = {0.5, 1.0, 0.0};
    const double psi[3] = {0.4, 0.2, 0.9};
    const double grad[9] = {-3, 0, 0,  -1, 2, 0,  5, 5, 5};
    double f[9] = {1, 1, 1,  0, 0, 0,  0, 0, 0};

    vhe_contact_add(3, coef, alpha, psi, grad, f);
    /* cell 0: 1 - 2 0.5 0.4 (-3) = 2.2 in x, the rest kept */
    ck_assert_double_eq_tol(f[0], 2.2, 1e-15);
    ck_assert_double_eq_tol(f[1], 1.0, 1e-15);
    ck_assert_double_eq_tol(f[2], 1.0, 1e-15);
    /* cell 1: -2 1 0.2 (-1, 2, 0) */
    ck_assert_double_eq_tol(f[3], 0.4, 1e-15);
    ck_assert_double_eq_tol(f[4], -0.8, 1e-15);
    ck_assert_double_eq_tol(f[5], 0.0, 1e-15);
    /* cell 2: no material, no force */
    ck_assert_double_eq(f[6], 0.0);
    ck_assert_double_eq(f[7], 0.0);
}
END_TEST

Suite *contact_suite(void)
{
    Suite *s = suite_create("contact");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_proximity);
    tcase_add_test(tc, test_contact_force);
    suite_add_tcase(s, tc);
    return s;
}
