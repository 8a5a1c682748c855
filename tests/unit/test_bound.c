/* Check tests of bound.c */
#include <check.h>
#include <math.h>

#include "vhe.h"

/* A row of 6 cells (internal faces f between cells f and f+1, volumes 1
   and 2 alternating), two fields: cell 1 of field 0 at -1e-3 (what
   isoAdvector's bounding leaves), cells 3 and 4 filled beyond 1 by both.
   After bounding: every fraction >= 0, every sum <= 1, each field's volume
   kept to 1e-15, and each field equal to its start minus dt div(flux) of
   the fluxes added (to 1e-15) */
START_TEST(test_row)
{
    enum { N = 6, F = N - 1, S = 2 };
    int own[F], nei[F], cellFaces[2 * F];
    long cellStart[N + 1];
    double V[N], a0[S][N] = {{0.5, -1e-3, 0.3, 0.7, 0.9, 0.0},
                             {0.0, 0.2, 0.0, 0.5, 0.3, 0.1}};
    double a[S][N], flux[S][F] = {{0}}, s[N];
    double *ap[S] = {a[0], a[1]}, *fp[S] = {flux[0], flux[1]};
    const double dt = 0.1;
    int c, f, k, j = 0;
    for (f = 0; f < F; ++f) { own[f] = f; nei[f] = f + 1; }
    for (c = 0; c < N; ++c) {
        V[c] = c % 2 ? 2.0 : 1.0;
        cellStart[c] = j;
        if (c > 0) cellFaces[j++] = c - 1;
        if (c < N - 1) cellFaces[j++] = c;
    }
    cellStart[N] = j;
    for (k = 0; k < S; ++k)
        for (c = 0; c < N; ++c) a[k][c] = a0[k][c];
    const double moved = vhe_bound_fractions(N, F, own, nei, cellStart,
                                             cellFaces, V, S, ap, fp, dt, s,
                                             10);
    ck_assert(moved > 0);
    for (k = 0; k < S; ++k) {
        double v0 = 0, v1 = 0;
        for (c = 0; c < N; ++c) {
            double div = 0;
            ck_assert(a[k][c] >= -1e-15);
            v0 += a0[k][c] * V[c];
            v1 += a[k][c] * V[c];
            if (c > 0) div -= flux[k][c - 1];
            if (c < N - 1) div += flux[k][c];
            ck_assert_double_eq_tol(a[k][c], a0[k][c] - dt * div / V[c],
                                    1e-15);
        }
        ck_assert_double_eq_tol(v1, v0, 1e-15);
    }
    for (c = 0; c < N; ++c) {
        ck_assert(a[0][c] + a[1][c] <= 1 + 1e-15);
        ck_assert_double_eq_tol(s[c], a[0][c] + a[1][c], 1e-15);
    }
    /* the overfull cells gave in proportion: field 0's share of cell 3
       (7/12) is kept */
    ck_assert_double_eq_tol(a[0][3] / (a[0][3] + a[1][3]), 0.7 / 1.2, 1e-14);
}
END_TEST

/* Bounded fields are left alone */
START_TEST(test_bounded)
{
    int own[1] = {0}, nei[1] = {1}, cellFaces[2] = {0, 0};
    long cellStart[3] = {0, 1, 2};
    double V[2] = {1, 1}, a[2] = {0.0, 1.0}, flux[1] = {0}, s[2];
    double *ap[1] = {a}, *fp[1] = {flux};
    ck_assert(vhe_bound_fractions(2, 1, own, nei, cellStart, cellFaces, V, 1,
                                  ap, fp, 1.0, s, 10) == 0.0);
    ck_assert(a[0] == 0.0 && a[1] == 1.0 && flux[0] == 0.0);
}
END_TEST

/* Downwind bounding on a row of 6 cells (volumes 1 and 2 alternating),
   flow to the right (phi 1, dt 1: a full face carries 1).  Cell 2 at 1.2
   passes its excess on through face 2 until that face is full (0.95 ->
   1: 0.05 of 0.2), the rest stays for vhe_bound_fractions; cell 4 at
   -0.05 lets 0.05 less out through face 4.  Nothing moves upwind, the
   volume is kept and a stays the update of dVf */
START_TEST(test_downwind)
{
    enum { N = 6, F = N - 1 };
    int own[F], nei[F], cellFaces[2 * F];
    long cellStart[N + 1];
    double V[N], phi[F], dVf[F], dVf0[F] = {0.5, 0.9, 0.95, 0.2, 0.3};
    double a0[N] = {0.5, 0.6, 1.2, 0.4, -0.05, 0.1}, a[N];
    int c, f, j = 0;
    for (f = 0; f < F; ++f) {
        own[f] = f; nei[f] = f + 1; phi[f] = 1.0; dVf[f] = dVf0[f];
    }
    for (c = 0; c < N; ++c) {
        V[c] = c % 2 ? 2.0 : 1.0;
        a[c] = a0[c];
        cellStart[c] = j;
        if (c > 0) cellFaces[j++] = c - 1;
        if (c < N - 1) cellFaces[j++] = c;
    }
    cellStart[N] = j;
    const double moved = vhe_bound_downwind(N, F, own, nei, cellStart,
                                            cellFaces, V, phi, dVf, a, 1.0,
                                            NULL, 1, 1, 1e-15, 3);
    ck_assert_double_eq_tol(moved, 0.1, 1e-15);
    ck_assert_double_eq_tol(dVf[2], 1.0, 1e-15);
    ck_assert_double_eq_tol(dVf[4], 0.25, 1e-15);
    ck_assert(dVf[0] == dVf0[0] && dVf[1] == dVf0[1] && dVf[3] == dVf0[3]);
    ck_assert_double_eq_tol(a[2], 1.15, 1e-15);
    ck_assert_double_eq_tol(a[3], 0.425, 1e-15);
    ck_assert_double_eq_tol(a[4], 0.0, 1e-15);
    ck_assert_double_eq_tol(a[5], 0.075, 1e-15);
    double v0 = 0, v1 = 0;
    for (c = 0; c < N; ++c) {
        double div = 0;
        if (c > 0) div -= dVf[c - 1] - dVf0[c - 1];
        if (c < N - 1) div += dVf[c] - dVf0[c];
        ck_assert_double_eq_tol(a[c], a0[c] - div / V[c], 1e-15);
        v0 += a0[c] * V[c];
        v1 += a[c] * V[c];
    }
    ck_assert_double_eq_tol(v1, v0, 1e-15);

    /* Only what is asked: from above alone, or cells outside check, leave
       the others as they are */
    double b[N] = {0.5, 0.6, 1.2, 0.4, -0.05, 0.1};
    for (f = 0; f < F; ++f) dVf[f] = dVf0[f];
    vhe_bound_downwind(N, F, own, nei, cellStart, cellFaces, V, phi, dVf, b,
                       1.0, NULL, 1, 0, 1e-15, 3);
    ck_assert(b[4] == -0.05 && dVf[4] == dVf0[4]);
    ck_assert_double_eq_tol(b[2], 1.15, 1e-15);
    const unsigned char check[N] = {1, 1, 0, 1, 1, 1};
    double e[N] = {0.5, 0.6, 1.2, 0.4, -0.05, 0.1};
    for (f = 0; f < F; ++f) dVf[f] = dVf0[f];
    vhe_bound_downwind(N, F, own, nei, cellStart, cellFaces, V, phi, dVf, e,
                       1.0, check, 1, 1, 1e-15, 3);
    ck_assert(e[2] == 1.2 && dVf[2] == dVf0[2]);
    ck_assert_double_eq_tol(e[4], 0.0, 1e-15);
}
END_TEST

/* A boundary face (index nInt on) takes what its cell passes on and no
   cell receives it: two cells, face 0 internal (0 -> 1), face 1 cell 1's
   outlet; cell 1 at 1.1 passes 0.1 out through the outlet */
START_TEST(test_downwind_boundary)
{
    int own[2] = {0, 1}, nei[1] = {1}, cellFaces[3] = {0, 0, 1};
    long cellStart[3] = {0, 1, 3};
    double V[2] = {1, 1}, phi[2] = {1, 1}, dVf[2] = {0.5, 0.9};
    double a[2] = {0.5, 1.1};
    vhe_bound_downwind(2, 1, own, nei, cellStart, cellFaces, V, phi, dVf, a,
                       1.0, NULL, 1, 1, 1e-15, 3);
    ck_assert_double_eq_tol(a[1], 1.0, 1e-15);
    ck_assert_double_eq_tol(dVf[1], 1.0, 1e-15);
    ck_assert(a[0] == 0.5 && dVf[0] == 0.5);
}
END_TEST

Suite *bound_suite(void)
{
    Suite *s = suite_create("bound");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_row);
    tcase_add_test(tc, test_bounded);
    tcase_add_test(tc, test_downwind);
    tcase_add_test(tc, test_downwind_boundary);
    suite_add_tcase(s, tc);
    return s;
}
