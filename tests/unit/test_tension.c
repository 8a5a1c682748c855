/*
 * test_tension.c -- unit tests of the height-function curvature
 * (tension.c): a circle's and a sphere's cap, sampled as heights, give the
 * exact curvature (1/R in 2D, 2/R in 3D) to second order in the spacing;
 * a plane gives 0 whatever its slope; a cap seen from below (the heights
 * measured downward) gives the opposite sign.
 */
#include <check.h>
#include <math.h>

#include "vhe.h"

/* Heights of the upper cap of a circle (dim 2) or sphere (dim 3) of
   radius R about the origin, around (x0, y0), spacing d */
static void cap_heights(int dim, double R, double x0, double y0, double d,
                        double h[9])
{
    int i, j;
    for (i = -1; i <= 1; ++i) {
        for (j = -1; j <= 1; ++j) {
            const double x = x0 + i * d, y = dim == 3 ? y0 + j * d : 0;
            h[3 * (i + 1) + (j + 1)] = sqrt(R * R - x * x - y * y);
        }
    }
}

START_TEST(test_curvature_circle_converges)
{
    const double R = 0.25;
    double e[2], h[9];
    int k;
    for (k = 0; k < 2; ++k) {
        const double d = R / (8 << k);
        cap_heights(2, R, 0.3 * R, 0, d, h);
        e[k] = fabs(vhe_height_curvature(h, d, d, 2) - 1 / R) * R;
    }
    ck_assert_double_lt(e[0], 1e-2);
    /* second order: the error falls by 4 when d halves */
    ck_assert_double_gt(e[0] / e[1], 3.5);
}
END_TEST

START_TEST(test_curvature_sphere_converges)
{
    const double R = 0.25;
    double e[2], h[9];
    int k;
    for (k = 0; k < 2; ++k) {
        const double d = R / (8 << k);
        cap_heights(3, R, 0.3 * R, -0.2 * R, d, h);
        e[k] = fabs(vhe_height_curvature(h, d, d, 3) - 2 / R) * R;
    }
    ck_assert_double_lt(e[0], 2e-2);
    ck_assert_double_gt(e[0] / e[1], 3.5);
}
END_TEST

START_TEST(test_curvature_plane_and_sign)
{
    double h[9];
    int i, j;
    for (i = -1; i <= 1; ++i) {
        for (j = -1; j <= 1; ++j) {
            h[3 * (i + 1) + (j + 1)] = 0.7 + 0.8 * i * 0.1 - 0.3 * j * 0.1;
        }
    }
    ck_assert_double_eq_tol(vhe_height_curvature(h, 0.1, 0.1, 3), 0, 1e-12);
    ck_assert_double_eq_tol(vhe_height_curvature(h, 0.1, 0.1, 2), 0, 1e-12);
    /* the cap seen from the other side: heights negated */
    cap_heights(2, 1.0, 0, 0, 0.05, h);
    for (i = 0; i < 9; ++i) h[i] = -h[i];
    ck_assert_double_lt(vhe_height_curvature(h, 0.05, 0.05, 2), -0.99);
}
END_TEST

Suite *tension_suite(void)
{
    Suite *s = suite_create("tension");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_curvature_circle_converges);
    tcase_add_test(tc, test_curvature_sphere_converges);
    tcase_add_test(tc, test_curvature_plane_and_sign);
    suite_add_tcase(s, tc);
    return s;
}
