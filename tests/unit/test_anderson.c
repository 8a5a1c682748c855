/* Check tests of anderson.c */
#include <check.h>
#include <math.h>

#include "vhe.h"

/* gamma solves a least-squares problem whose answer is known: f = 2 dF_0
   - dF_1 exactly */
START_TEST(test_gamma_exact)
{
    const double dF[2][3] = {{1, 0, 1}, {0, 2, 1}};
    double f[3], G[4], b[2], gamma[2];
    int i, k, l;
    for (i = 0; i < 3; ++i) f[i] = 2*dF[0][i] - dF[1][i];
    for (k = 0; k < 2; ++k) {
        b[k] = 0;
        for (i = 0; i < 3; ++i) b[k] += dF[k][i]*f[i];
        for (l = 0; l < 2; ++l) {
            G[k*2 + l] = 0;
            for (i = 0; i < 3; ++i) G[k*2 + l] += dF[k][i]*dF[l][i];
        }
    }
    ck_assert_int_eq(vhe_anderson_gamma(2, G, b, gamma), VHE_OK);
    ck_assert_double_eq_tol(gamma[0], 2.0, 1e-8);
    ck_assert_double_eq_tol(gamma[1], -1.0, 1e-8);
    /* A repeated iterate (a zero column) takes no weight */
    G[1] = G[2] = G[3] = 0;
    b[1] = 0;
    ck_assert_int_eq(vhe_anderson_gamma(2, G, b, gamma), VHE_OK);
    ck_assert(gamma[1] == 0.0);
    ck_assert_int_eq(vhe_anderson_gamma(VHE_ANDERSON_MAX + 1, G, b, gamma),
                     VHE_EBADARG);
}
END_TEST

/* The stiff body's fixed point in miniature: x = A x + c with three modes
   that a plain iteration barely moves (contraction 0.9999, as a rigid
   mode of a stiff body under a lagged coupling) among fast ones in
   [0, 0.5].  With six differences Anderson reaches 1e-4 of the error in 12
   map evaluations and 1e-10 in 27 (the slow modes leave the history and
   come back); the plain iteration is still at 0.99 of its first error
   after 100 */
START_TEST(test_slow_modes)
{
    enum { n = 24, m = 6 };
    double lam[n], c[n], x[n], g[n], f[n], xs[n];
    double dG[m][n], dF[m][n], gPrev[n], fPrev[n];
    double G[m*m], b[m], gamma[m];
    int i, k, l, it, h = 0, conv = 0;
    for (i = 0; i < n; ++i) {
        lam[i] = i < 3 ? 0.9999 : 0.25*(1 + sin(1.0 + i));
        c[i] = 1.0 + 0.1*i;
        xs[i] = c[i]/(1 - lam[i]);
        x[i] = 0;
    }
    for (it = 0; it < 30; ++it) {
        double err = 0;
        for (i = 0; i < n; ++i) {
            g[i] = lam[i]*x[i] + c[i];
            f[i] = g[i] - x[i];
            err = fmax(err, fabs(x[i] - xs[i])/xs[0]);
        }
        if (err < 1e-4 && !conv) conv = it;
        if (err < 1e-10) break;
        if (it > 0) {
            if (h == m) {
                for (k = 1; k < m; ++k) {
                    for (i = 0; i < n; ++i) {
                        dG[k-1][i] = dG[k][i];
                        dF[k-1][i] = dF[k][i];
                    }
                }
                --h;
            }
            for (i = 0; i < n; ++i) {
                dG[h][i] = g[i] - gPrev[i];
                dF[h][i] = f[i] - fPrev[i];
            }
            ++h;
        }
        for (i = 0; i < n; ++i) { gPrev[i] = g[i]; fPrev[i] = f[i]; }
        for (k = 0; k < h; ++k) {
            b[k] = 0;
            for (i = 0; i < n; ++i) b[k] += dF[k][i]*f[i];
            for (l = 0; l < h; ++l) {
                G[k*h + l] = 0;
                for (i = 0; i < n; ++i) G[k*h + l] += dF[k][i]*dF[l][i];
            }
        }
        ck_assert_int_eq(vhe_anderson_gamma(h, G, b, gamma), VHE_OK);
        for (i = 0; i < n; ++i) {
            x[i] = g[i];
            for (k = 0; k < h; ++k) x[i] -= gamma[k]*dG[k][i];
        }
    }
    ck_assert_msg(conv > 0 && conv <= 12, "1e-4 at %d", conv);
    ck_assert_msg(it < 30, "1e-10 not reached");
    /* The plain iteration on the slow mode */
    {
        double y = 0;
        for (it = 0; it < 100; ++it) y = lam[0]*y + c[0];
        ck_assert(fabs(y - xs[0])/xs[0] > 0.99);
    }
}
END_TEST

Suite *anderson_suite(void)
{
    Suite *s = suite_create("anderson");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_gamma_exact);
    tcase_add_test(tc, test_slow_modes);
    suite_add_tcase(s, tc);
    return s;
}
