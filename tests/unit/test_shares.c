/*
 * test_shares.c -- unit tests of the colour-share kernels (shares.c): the
 * split of a material's flux over its colours, the mixed outflow of a
 * cell its flux passes through, the test for two colours meeting; and the
 * interface compression of one phase against another (compress.c).
 */
#include <check.h>
#include <math.h>

#include "vhe.h"

#define N 8

static void row_faces(int own[N - 1], int nei[N - 1])
{
    int f;
    for (f = 0; f < N - 1; ++f) { own[f] = f; nei[f] = f + 1; }
}

/* Two faces: a mixed upwind cell (shares 0.25/0.75 summing to 1 - 1e-16)
   and an upwind cell that gives nothing (then F is 0: all to colour 0). */
START_TEST(test_share_split)
{
    const double F[2] = {2.0, 0.0};
    const double u0[2] = {0.25, 0.0}, u1[2] = {0.75 - 1e-16, 0.0};
    const double *up[2] = {u0, u1};
    double o0[2], o1[2];
    double *out[2] = {o0, o1};
    int f;

    vhe_share_split(2, 2, F, up, out);
    ck_assert_double_eq_tol(o0[0], 0.5, 1e-15);
    ck_assert_double_eq_tol(o1[0], 1.5, 1e-15);
    ck_assert_double_eq(o0[1], 0.0);
    ck_assert_double_eq(o1[1], 0.0);
    for (f = 0; f < 2; ++f) {
        ck_assert_double_eq_tol(o0[f] + o1[f], F[f], 1e-15);
    }
}
END_TEST

/* A row of unit cells (dt 1) carrying two colours to the right at a flux
   of 0.5: cell 3 holds 0.1 of colour a and gives 0.5, so its outflow is
   its content and its inflow mixed (0.1 a + 0.5 b from cell 2); the cell
   shares elsewhere.  Every colour stays >= 0 after the update, and the
   colours sum to the total's update. */
START_TEST(test_share_mix)
{
    int own[N - 1], nei[N - 1], c, f, k;
    double a[N] = {0, 0, 0, 0.1, 0.6, 0.6, 0, 0};
    double b[N] = {0.6, 0.6, 0.6, 0, 0, 0, 0, 0};
    const double *ab[2] = {a, b};
    double V[N], F[N - 1], out[N] = {0}, in[N] = {0};
    double sa[N], sb[N], ia[N] = {0}, ib[N] = {0}, fa[N - 1], fb[N - 1];
    double *s[2] = {sa, sb}, *inK[2] = {ia, ib}, *fk[2] = {fa, fb};
    const double *sc[2] = {sa, sb}, *up[2];
    double ua[N - 1], ub[N - 1], t[N];
    long nMixed;

    row_faces(own, nei);
    for (c = 0; c < N; ++c) { V[c] = 1; t[c] = a[c] + b[c]; }
    for (f = 0; f < N - 1; ++f) F[f] = f < 5 ? 0.5 : 0.0;
    vhe_share_cells(N, 2, ab, s);
    ck_assert_double_eq(sa[3], 1.0);
    vhe_share_flows(N - 1, own, nei, F, out, in);
    vhe_share_inflow(N - 1, own, nei, F, 2, sc, 0, inK);
    nMixed = vhe_share_mix(N, 2, ab, V, 1.0, out, in, (const double *const *)inK, s);
    ck_assert_int_eq(nMixed, 1);                       /* cell 3 only */
    ck_assert_double_eq_tol(sa[3], 0.1 / 0.6, 1e-15);
    ck_assert_double_eq_tol(sb[3], 0.5 / 0.6, 1e-15);
    ck_assert_double_eq(sa[4], 1.0);
    for (f = 0; f < N - 1; ++f) { ua[f] = s[0][own[f]]; ub[f] = s[1][own[f]]; }
    up[0] = ua; up[1] = ub;
    vhe_share_split(N - 1, 2, F, up, fk);
    for (f = 0; f < N - 1; ++f) {
        for (k = 0; k < 2; ++k) {
            double *x = k ? b : a;
            x[own[f]] -= fk[k][f];
            x[nei[f]] += fk[k][f];
        }
        t[own[f]] -= F[f];
        t[nei[f]] += F[f];
    }
    for (c = 0; c < N; ++c) {
        ck_assert(a[c] >= 0 && b[c] >= 0);
        ck_assert_double_eq_tol(a[c] + b[c], t[c], 1e-15);
    }
    /* cell 3 keeps 0.1 of the 0.6 it held over the step, mixed */
    ck_assert_double_eq_tol(a[3], 0.1 / 6, 1e-15);
    ck_assert_double_eq_tol(b[3], 0.5 / 6, 1e-15);
}
END_TEST

/* Colour a on cells 0..3, colour b on cells 4..7: they meet on face 3
   only; with b moved to 5..7 (cell 4 empty) they do not, and a tail of
   1e-6 against 1 is below tol 1e-5 but above 1e-7.  A boundary face with
   the other side's values given per face detects them too. */
START_TEST(test_share_meet)
{
    int own[N - 1], nei[N - 1];
    double a[N] = {1, 1, 1, 0.6, 0, 0, 0, 0};
    double b[N] = {0, 0, 0, 0, 0.4, 1, 1, 1};
    const int bOwn[1] = {3};
    const double aNei[1] = {0.0}, bNei[1] = {0.5};

    row_faces(own, nei);
    ck_assert_int_eq(vhe_share_meet(N - 1, own, nei, a, b, 0, 0, 1e-10), 1);
    b[4] = 0;
    ck_assert_int_eq(vhe_share_meet(N - 1, own, nei, a, b, 0, 0, 1e-10), 0);
    b[4] = 1e-6;
    ck_assert_int_eq(vhe_share_meet(N - 1, own, nei, a, b, 0, 0, 1e-5), 0);
    ck_assert_int_eq(vhe_share_meet(N - 1, own, nei, a, b, 0, 0, 1e-7), 1);
    b[4] = 0;
    ck_assert_int_eq(vhe_share_meet(1, bOwn, 0, a, b, aNei, bNei, 1e-10), 1);
}
END_TEST

/* Interface compression of phase i against phase j on three faces of
   unit normal x (|Sf| = 2): where i grows along x the flux is + (towards
   i) with magnitude phic |Sf| a_i a_j (n = x); where i falls, -; a face
   where j is absent carries none.  j's flux is the exact opposite. */
START_TEST(test_compress_pair)
{
    const double phic[3] = {0.5, 0.5, 0.5};
    const double Sf[9] = {2, 0, 0, 2, 0, 0, 2, 0, 0};
    const double ai[3] = {0.25, 0.25, 1.0}, aj[3] = {0.75, 0.75, 0.0};
    const double gi[9] = {3, 0, 0, -3, 0, 0, 0, 1, 0};
    const double gj[9] = {-3, 0, 0, 3, 0, 0, 0, 0, 0};
    double fi[3] = {0, 0, 0}, fj[3] = {0, 0, 0};
    /* g = aj gi - ai gj = 3 x (face 0), -3 x (face 1): n = +-x */
    const double C = 0.5 * 2 * 0.25 * 0.75 * (3 / (3 + 1e-8));
    int f;

    vhe_compress_pair(3, phic, Sf, ai, aj, gi, gj, 1e-8, fi, fj);
    ck_assert_double_eq_tol(fi[0], C, 1e-15);
    ck_assert_double_eq_tol(fi[1], -C, 1e-15);
    ck_assert_double_eq(fi[2], 0.0);
    for (f = 0; f < 3; ++f) ck_assert_double_eq(fi[f], -fj[f]);
}
END_TEST

Suite *shares_suite(void)
{
    Suite *s = suite_create("shares");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_share_split);
    tcase_add_test(tc, test_share_mix);
    tcase_add_test(tc, test_share_meet);
    tcase_add_test(tc, test_compress_pair);
    suite_add_tcase(s, tc);
    return s;
}
