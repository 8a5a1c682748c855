/*
 * test_bodies.c -- unit tests of one body's motion and shape from its
 * moments (bodies.c) and of the per-cell |dev B| (symm.c).
 */
#include <check.h>
#include <math.h>

#include "vhe.h"

#define PI 3.14159265358979323846

/* Moments J and L of a uniform ellipse (2D, in x-y) with semi-axes a, b,
 * major axis at angle th, in solid rotation omega, summed over an n x n
 * grid of cells of the bounding box (w = cell area inside). */
static void ellipse_moments(double a, double b, double th, double omega,
                            int n, double J[6], double L[3])
{
    const double R = a > b ? a : b, h = 2.0 * R / n;
    const double c = cos(th), s = sin(th);
    int i, j, k;

    for (k = 0; k < 6; ++k) J[k] = 0.0;
    L[0] = L[1] = L[2] = 0.0;
    for (i = 0; i < n; ++i) {
        for (j = 0; j < n; ++j) {
            const double x = -R + (i + 0.5) * h, y = -R + (j + 0.5) * h;
            const double xe = c * x + s * y, ye = -s * x + c * y;
            const double ux = -omega * y, uy = omega * x;
            double w;
            if (xe * xe / (a * a) + ye * ye / (b * b) > 1.0) continue;
            w = h * h;
            J[0] += w * x * x;
            J[1] += w * x * y;
            J[3] += w * y * y;
            L[2] += w * (x * uy - y * ux);
        }
    }
}

START_TEST(test_omega_2d)
{
    double J[6], L[3], om[3];
    ellipse_moments(0.1, 0.05, 0.3, 2.5, 200, J, L);
    vhe_body_omega(J, L, 2, om);
    ck_assert_double_eq_tol(om[2], 2.5, 1e-12);
    ck_assert_double_eq(om[0], 0.0);
    ck_assert_double_eq(om[1], 0.0);
}
END_TEST

START_TEST(test_omega_3d)
{
    /* eight points of a box in solid rotation about (1, 2, 3) */
    const double w0[3] = {1.0, 2.0, 3.0};
    double J[6] = {0, 0, 0, 0, 0, 0}, L[3] = {0, 0, 0}, om[3];
    int i;
    for (i = 0; i < 8; ++i) {
        const double r[3] = {(i & 1) ? 0.3 : -0.3, (i & 2) ? 0.2 : -0.2,
                             (i & 4) ? 0.1 : -0.1};
        const double u[3] = {w0[1] * r[2] - w0[2] * r[1],
                             w0[2] * r[0] - w0[0] * r[2],
                             w0[0] * r[1] - w0[1] * r[0]};
        J[0] += r[0] * r[0]; J[1] += r[0] * r[1]; J[2] += r[0] * r[2];
        J[3] += r[1] * r[1]; J[4] += r[1] * r[2]; J[5] += r[2] * r[2];
        L[0] += r[1] * u[2] - r[2] * u[1];
        L[1] += r[2] * u[0] - r[0] * u[2];
        L[2] += r[0] * u[1] - r[1] * u[0];
    }
    vhe_body_omega(J, L, -1, om);
    for (i = 0; i < 3; ++i) {
        ck_assert_double_eq_tol(om[i], w0[i], 1e-12);
    }
}
END_TEST

START_TEST(test_shape_2d)
{
    /* D = (a - b)/(a + b) and the major axis of a resolved ellipse */
    const double a = 0.1, b = 0.06, th = 0.4;
    double J[6], L[3], ax[3];
    double D;
    ellipse_moments(a, b, th, 0.0, 400, J, L);
    D = vhe_body_shape(J, 2, ax);
    ck_assert_double_eq_tol(D, (a - b) / (a + b), 2e-3);
    ck_assert_double_eq_tol(ax[0], cos(th), 1e-3);
    ck_assert_double_eq_tol(ax[1], sin(th), 1e-3);
    ck_assert_double_eq(ax[2], 0.0);
    /* a circle: D = 0 */
    ellipse_moments(0.1, 0.1, 0.0, 0.0, 400, J, L);
    ck_assert_double_le(vhe_body_shape(J, 2, ax), 1e-3);
    /* the axis' sign: at angle -th the largest component is positive */
    ellipse_moments(a, b, PI - th, 0.0, 400, J, L);
    vhe_body_shape(J, 2, ax);
    ck_assert_double_gt(ax[0], 0.0);
    ck_assert_double_eq_tol(ax[1], -sin(th), 1e-3);
}
END_TEST

START_TEST(test_shape_3d)
{
    /* a uniform ellipsoid's J is diag(a^2, b^2, c^2) V/5: D from the
     * largest and smallest semi-axes, the major axis along y here */
    const double J[6] = {0.04, 0.0, 0.0, 0.09, 0.0, 0.01};
    double ax[3];
    const double D = vhe_body_shape(J, -1, ax);
    ck_assert_double_eq_tol(D, (0.3 - 0.1) / (0.3 + 0.1), 1e-12);
    ck_assert_double_eq_tol(fabs(ax[1]), 1.0, 1e-12);
    ck_assert_double_gt(ax[1], 0.0);
}
END_TEST

START_TEST(test_devb_mag)
{
    /* simple shear B = [[1+g^2, g, 0], [g, 1, 0], [0, 0, 1]], phi 0.25 */
    const double g = 0.5, phis[2] = {0.25, 0.01};
    double Bs[12], out[2], tr, d[3];
    int k;
    const double B[6] = {1.0 + g * g, g, 0.0, 1.0, 0.0, 1.0};
    for (k = 0; k < 6; ++k) {
        Bs[k] = 0.5 * B[k];
        Bs[6 + k] = 0.1 * B[k];
    }
    vhe_devb_mag(2, phis, Bs, 0.1, out);
    tr = (B[0] + B[3] + B[5]) / 3.0;
    d[0] = B[0] - tr; d[1] = B[3] - tr; d[2] = B[5] - tr;
    ck_assert_double_eq_tol(out[0], sqrt(d[0] * d[0] + d[1] * d[1]
                            + d[2] * d[2] + 2.0 * g * g), 1e-14);
    ck_assert_double_eq(out[1], 0.0);
}
END_TEST

/* A chain of three disks (A near B, B near C, A far from C) needs two
 * colours; a fourth disk near all three a third; across a periodic
 * boundary the nearest image counts; with one colour every near pair
 * shares it. */
START_TEST(test_colour_bodies)
{
    const double r[4] = {0.1, 0.1, 0.1, 0.1};
    const double none[3] = {0.0, 0.0, 0.0}, px[3] = {1.0, 0.0, 0.0};
    double c[12] = {0.1, 0.5, 0.0,  0.32, 0.5, 0.0,  0.54, 0.5, 0.0,
                    0.32, 0.6, 0.0};
    int col[4], shared;

    shared = vhe_colour_bodies(3, c, r, none, 0.05, 4, col);
    ck_assert_int_eq(shared, 0);
    ck_assert_int_eq(col[0], 0);
    ck_assert_int_eq(col[1], 1);
    ck_assert_int_eq(col[2], 0);

    /* the fourth is near all three: 0.1 from B, 0.242 < 0.25 from A, C */
    shared = vhe_colour_bodies(4, c, r, none, 0.05, 4, col);
    ck_assert_int_eq(shared, 0);
    ck_assert_int_eq(col[3], 2);

    /* no margin: only B and D (0.1 apart) are near */
    shared = vhe_colour_bodies(4, c, r, none, 0.0, 4, col);
    ck_assert_int_eq(shared, 0);
    ck_assert_int_eq(col[0] + col[1] + col[2] + col[3], 1);

    /* periodic in x: disks at 0.05 and 0.95 are 0.1 apart */
    c[0] = 0.05; c[3] = 0.95; c[4] = 0.5;
    shared = vhe_colour_bodies(2, c, r, px, 0.01, 4, col);
    ck_assert_int_ne(col[0], col[1]);
    shared = vhe_colour_bodies(2, c, r, none, 0.01, 4, col);
    ck_assert_int_eq(col[1], 0);

    /* one colour: the near pairs share it and are counted */
    c[0] = 0.1; c[3] = 0.32;
    shared = vhe_colour_bodies(3, c, r, none, 0.05, 1, col);
    ck_assert_int_eq(shared, 2);
}
END_TEST


/* A posed shape at the identity pose is the shape itself, to the bit; a
 * box turned by 90 degrees about z is the box with its x and y half-edges
 * swapped; a translation moves the fraction with it. */
START_TEST(test_shape_posed)
{
    struct vhe_shape box = {VHE_BOX, {0.5, 0.5, 0.5}, {0, 0, 1}, 0, 0,
                            {0.3, 0.1, 1.0}};
    struct vhe_shape swapped = box;
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const double Rz[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
    const double X[3] = {0.5, 0.5, 0.5}, Y[3] = {0.57, 0.43, 0.5};
    struct vhe_shape moved = box;
    int i, j;
    swapped.semi[0] = 0.1;
    swapped.semi[1] = 0.3;
    moved.centre[0] = Y[0];
    moved.centre[1] = Y[1];
    for (i = 0; i < 20; ++i) {
        for (j = 0; j < 20; ++j) {
            const double lo[3] = {i * 0.05, j * 0.05, 0.0};
            const double hi[3] = {lo[0] + 0.05, lo[1] + 0.05, 1.0};
            ck_assert(vhe_shape_fraction_posed(&box, I, X, lo, hi, 2, 5)
                      == vhe_shape_fraction(&box, lo, hi, 2, 5));
            ck_assert_double_eq_tol(
                vhe_shape_fraction_posed(&box, Rz, X, lo, hi, 2, 5),
                vhe_shape_fraction(&swapped, lo, hi, 2, 5), 1e-12);
            ck_assert_double_eq_tol(
                vhe_shape_fraction_posed(&box, I, Y, lo, hi, 2, 5),
                vhe_shape_fraction(&moved, lo, hi, 2, 5), 1e-12);
        }
    }
}
END_TEST

/* The box of a turned shape holds it; a 2D disk turned about its axis
 * stays infinite along it and a circle in the plane. */
START_TEST(test_bounds_posed)
{
    const double c = cos(PI / 4), s = sin(PI / 4);
    const double Q[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
    const double X[3] = {1.0, 2.0, 0.0};
    struct vhe_shape box = {VHE_BOX, {0, 0, 0}, {0, 0, 1}, 0, 0,
                            {0.3, 0.1, 0.05}};
    struct vhe_shape disk = {VHE_CYLINDER, {0, 0, 0}, {0, 0, 1}, 0.2, 0,
                             {0, 0, 0}};
    double lo[3], hi[3];
    vhe_shape_bounds_posed(&box, Q, X, lo, hi);
    ck_assert_double_eq_tol(hi[0] - X[0], (0.3 + 0.1) * c, 1e-14);
    ck_assert_double_eq_tol(X[1] - lo[1], (0.3 + 0.1) * s, 1e-14);
    ck_assert_double_eq_tol(hi[2], 0.05, 1e-14);
    {
        /* the turned box's corner (0.3, 0.1) lies at X + Q (0.3, 0.1) */
        const double x[3] = {X[0] + c * 0.3 - s * 0.1, X[1] + s * 0.3 + c * 0.1,
                             0.0};
        const double y[3] = {X[0] + c * 0.5, X[1] + s * 0.5, 0.0};
        ck_assert_double_eq_tol(vhe_shape_sdf_posed(&box, Q, X, x), 0.0,
                                1e-14);
        ck_assert_double_eq_tol(vhe_shape_sdf_posed(&box, Q, X, y), 0.2,
                                1e-14);
    }
    vhe_shape_bounds_posed(&disk, Q, X, lo, hi);
    ck_assert_double_eq_tol(hi[0] - X[0], 0.2 * (c + s), 1e-14);
    ck_assert(lo[2] == -HUGE_VAL && hi[2] == HUGE_VAL);
}
END_TEST

/* A quarter turn about z in 1000 steps is the quarter turn; a million
 * small turns about a skew axis leave Q orthonormal to round-off; a 2D
 * pose keeps its exact zeros. */
START_TEST(test_pose_rotate)
{
    double Q[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const double wz[3] = {0, 0, 2.0};
    const double w[3] = {0.3, -1.1, 0.7};
    int i, j, k;
    for (i = 0; i < 1000; ++i) {
        vhe_pose_rotate(Q, wz, PI / 4 / 1000);
    }
    ck_assert_double_eq_tol(Q[0], 0.0, 1e-12);
    ck_assert_double_eq_tol(Q[1], -1.0, 1e-12);
    ck_assert_double_eq_tol(Q[3], 1.0, 1e-12);
    ck_assert(Q[2] == 0.0 && Q[5] == 0.0 && Q[6] == 0.0 && Q[7] == 0.0
              && Q[8] == 1.0);
    for (i = 0; i < 1000000; ++i) {
        vhe_pose_rotate(Q, w, 1e-3);
    }
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            double d = 0.0;
            for (k = 0; k < 3; ++k) {
                d += Q[3 * k + i] * Q[3 * k + j];
            }
            ck_assert_double_eq_tol(d, i == j ? 1.0 : 0.0, 1e-14);
        }
    }
}
END_TEST

/* The fit reaches its target to round-off, keeps fractions in [0, 1] and
 * leaves cells of 0 and 1 alone; a target out of reach clamps s. */
START_TEST(test_volume_fit)
{
    double a[200], V[200], sums[2], target, s;
    int c;
    for (c = 0; c < 200; ++c) {
        a[c] = c < 50 ? 0.0 : (c < 100 ? 1.0 : 0.5 + 0.49 * sin(c));
        V[c] = 1.0 + 0.1 * cos(c);
    }
    vhe_volume_sums(200, a, V, sums);
    target = sums[0] * (1 + 3e-3);
    s = vhe_volume_shift(200, a, sums, target);
    ck_assert(s > 0 && s < 1);
    vhe_volume_sums(200, a, V, sums);
    ck_assert_double_eq_tol(sums[0] / target, 1.0, 1e-14);
    for (c = 0; c < 200; ++c) {
        ck_assert(a[c] >= 0.0 && a[c] <= 1.0);
        if (c < 50) ck_assert(a[c] == 0.0);
        if (c >= 50 && c < 100) ck_assert(a[c] == 1.0);
    }
    ck_assert_double_eq(vhe_volume_shift(200, a, sums, 1e3), 1.0);
    for (c = 0; c < 200; ++c) {
        ck_assert(a[c] >= 0.0 && a[c] <= 1.0);
    }
}
END_TEST

Suite *bodies_suite(void)
{
    Suite *s = suite_create("bodies");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_omega_2d);
    tcase_add_test(tc, test_omega_3d);
    tcase_add_test(tc, test_shape_2d);
    tcase_add_test(tc, test_shape_3d);
    tcase_add_test(tc, test_devb_mag);
    tcase_add_test(tc, test_colour_bodies);
    tcase_add_test(tc, test_shape_posed);
    tcase_add_test(tc, test_bounds_posed);
    tcase_add_test(tc, test_pose_rotate);
    tcase_add_test(tc, test_volume_fit);
    suite_add_tcase(s, tc);
    return s;
}
