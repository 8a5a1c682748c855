/* Check tests of cut.c: a unit cube (and a sheared one) cut by planes with
   known volumes, areas and centres; the fraction inverted to tol; faces
   given from the other side (flip) give the same cut */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include "vhe.h"

/* points i + 2j + 4k at (i, j, k); faces with outward right-hand normals */
static double X[24];
static const int START[7] = {0, 4, 8, 12, 16, 20, 24};
static const int FACES[24] = {0, 4, 6, 2,  1, 3, 7, 5,  0, 1, 5, 4,
                              2, 6, 7, 3,  0, 2, 3, 1,  4, 5, 7, 6};
static const unsigned char NOFLIP[6] = {0, 0, 0, 0, 0, 0};

static struct vhe_cell cube(double shear)
{
    struct vhe_cell c;
    int p;
    for (p = 0; p < 8; ++p) {
        X[3 * p] = (p & 1) + shear * ((p >> 2) & 1);   /* x += shear z */
        X[3 * p + 1] = (p >> 1) & 1;
        X[3 * p + 2] = (p >> 2) & 1;
    }
    c.npoints = 8; c.x = X; c.nfaces = 6;
    c.face_start = START; c.face_pts = FACES; c.flip = NOFLIP;
    c.x0[0] = 0.5 + 0.5 * shear; c.x0[1] = 0.5; c.x0[2] = 0.5;
    return c;
}

static void plane(const double n[3], double f[8])
{
    int p;
    for (p = 0; p < 8; ++p)
        f[p] = n[0] * X[3 * p] + n[1] * X[3 * p + 1] + n[2] * X[3 * p + 2];
}

START_TEST(test_cut_known)
{
    struct vhe_cell c = cube(0.0);
    struct vhe_cut out;
    double f[8];
    const double ex[3] = {1, 0, 0}, diag[3] = {1, 1, 1}, d2[3] = {1, 1, 0};

    /* x > 0.3: 0.7 of the cube, cut of area 1 facing -x at x = 0.3 */
    plane(ex, f);
    ck_assert_int_eq(vhe_cell_cut(&c, f, 0.3, &out), 0);
    ck_assert_int_eq(out.status, 0);
    ck_assert_double_eq_tol(out.volume, 0.7, 1e-14);
    ck_assert_double_eq_tol(out.area[0], -1.0, 1e-14);
    ck_assert_double_eq_tol(out.area[1], 0.0, 1e-14);
    ck_assert_double_eq_tol(out.centre[0], 0.3, 1e-14);
    ck_assert_double_eq_tol(out.centre[1], 0.5, 1e-14);
    ck_assert_double_eq_tol(out.centre[2], 0.5, 1e-14);

    /* x + y > 0.5: all but a prism of 1/8 */
    plane(d2, f);
    vhe_cell_cut(&c, f, 0.5, &out);
    ck_assert_double_eq_tol(out.volume, 0.875, 1e-14);
    ck_assert_double_eq_tol(out.area[0], -0.5, 1e-14);
    ck_assert_double_eq_tol(out.area[1], -0.5, 1e-14);
    ck_assert_double_eq_tol(out.centre[2], 0.5, 1e-14);

    /* x + y + z > 2.5: the corner tetrahedron of legs 1/2 */
    plane(diag, f);
    vhe_cell_cut(&c, f, 2.5, &out);
    ck_assert_double_eq_tol(out.volume, 0.125 / 6.0, 1e-15);
    ck_assert_double_eq_tol(out.area[0], -0.125, 1e-15);
    ck_assert_double_eq_tol(out.centre[0], 5.0 / 6.0, 1e-14);
    ck_assert_double_eq_tol(out.centre[2], 5.0 / 6.0, 1e-14);

    /* none, all */
    vhe_cell_cut(&c, f, 3.5, &out);
    ck_assert_int_eq(out.status, 1);
    ck_assert(out.volume == 0.0);
    vhe_cell_cut(&c, f, -1.0, &out);
    ck_assert_int_eq(out.status, -1);
    ck_assert_double_eq_tol(out.volume, 1.0, 1e-14);
}
END_TEST

/* The sheared cube (volume 1): x - 0.4 z > 0.6 - 0.4 z... a plane parallel
   to the sheared faces cuts off its share exactly; a plane through the
   centre halves it */
START_TEST(test_cut_sheared)
{
    struct vhe_cell c = cube(0.4);
    struct vhe_cut out;
    double f[8];
    const double n[3] = {1, 0, -0.4}, m[3] = {0.3, -0.8, 0.52};
    plane(n, f);
    vhe_cell_cut(&c, f, 0.25, &out);
    ck_assert_double_eq_tol(out.volume, 0.75, 1e-14);
    plane(m, f);
    vhe_cell_cut(&c, f, m[0] * 0.7 + m[1] * 0.5 + m[2] * 0.5, &out);
    ck_assert_double_eq_tol(out.volume, 0.5, 1e-14);
}
END_TEST

/* Random planes and fractions: the fraction found to tol, the cut's area
   vector along -n (the part is where f rises), and the same cut with the
   faces listed from the other side */
START_TEST(test_cut_fraction)
{
    struct vhe_cell c = cube(0.2), r;
    struct vhe_cut out, out2;
    double f[8];
    int rev[24], k, i, trial;
    unsigned char flip[6] = {1, 1, 1, 1, 1, 1};
    srand(7);
    for (k = 0; k < 6; ++k)
        for (i = 0; i < 4; ++i) rev[START[k] + i] = FACES[START[k] + 3 - i];
    r = c; r.face_pts = rev; r.flip = flip;
    for (trial = 0; trial < 200; ++trial) {
        double n[3], alpha, m;
        for (i = 0; i < 3; ++i) n[i] = 2.0 * rand() / RAND_MAX - 1.0;
        m = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (i = 0; i < 3; ++i) n[i] /= m;
        alpha = 1e-6 + (1 - 2e-6) * rand() / RAND_MAX;
        plane(n, f);
        /* the plane's Newton (unit normal: g = 1), from no guess and from
           a guess, gives the general method's iso value */
        ck_assert_int_eq(vhe_cell_cut_fraction(&c, f, 1.0, alpha, 1e-10, 1.0,
                                               NAN, &out2), 0);
        ck_assert_double_eq_tol(out2.volume, alpha, 1e-10);
        ck_assert_int_eq(vhe_cell_cut_fraction(&c, f, 1.0, alpha, 1e-10, 1.0,
                                               out2.iso + 0.01, &out2), 0);
        ck_assert_double_eq_tol(out2.volume, alpha, 1e-10);
        ck_assert_int_eq(vhe_cell_cut_fraction(&c, f, 1.0, alpha, 1e-10, 0.0,
                                               NAN, &out), 0);
        ck_assert_double_eq_tol(out.volume, alpha, 1e-10);
        ck_assert_double_eq_tol(out.iso, out2.iso, 1e-9);
        ck_assert(out.area[0] * n[0] + out.area[1] * n[1]
                  + out.area[2] * n[2] < 0);
        /* the cut's centre on the plane */
        ck_assert_double_eq_tol(n[0] * out.centre[0] + n[1] * out.centre[1]
                                + n[2] * out.centre[2], out.iso, 1e-12);
        vhe_cell_cut(&r, f, out.iso, &out2);
        ck_assert_double_eq_tol(out2.volume, alpha, 1e-10);
        for (i = 0; i < 3; ++i) {
            ck_assert_double_eq_tol(out2.area[i], out.area[i], 1e-13);
            ck_assert_double_eq_tol(out2.centre[i], out.centre[i], 1e-13);
        }
    }
}
END_TEST

/* A cut through a point (or within round-off of one) holds nearly none of
   the cell, not all of it; and a small fraction is found when the two
   largest point values differ in the last digit (the values of a disk's
   edge cell in test_rigid's obstacle case, where the search once took the
   cut at the top pair for the whole cell and failed) */
/* A curved field (a sphere's smoothed fraction at the cube's points): the
 * fraction where f > iso moves continuously as the iso value crosses a
 * point value (the fan's point is the segments' length-weighted mean), so
 * every fraction has its cut; with the segments' plain mean this field's
 * fraction jumped by 1e-4 at a point value and 0.61882 had no cut */
START_TEST(test_cut_curved)
{
    struct vhe_cell c = cube(0.0);
    struct vhe_cut out, lo, hi;
    const double f[8] = {0.179517, 0.294306, 0.624285, 0.864858,
                         0.0693619, 0.110997, 0.251654, 0.408241};
    int p;
    for (p = 0; p < 8; ++p) {
        vhe_cell_cut(&c, f, f[p] - 1e-12, &lo);
        vhe_cell_cut(&c, f, f[p] + 1e-12, &hi);
        ck_assert_msg(fabs(lo.volume - hi.volume) < 1e-10,
                      "jump %g at point %d", lo.volume - hi.volume, p);
    }
    ck_assert_int_eq(vhe_cell_cut_fraction(&c, f, 1.0, 0.61882, 1e-8, 0.0,
                                           0.0, &out), 0);
    ck_assert_double_eq_tol(out.volume, 0.61882, 1e-8);
}
END_TEST

START_TEST(test_cut_degenerate)
{
    struct vhe_cell c = cube(0.0);
    struct vhe_cut out;
    const double diag[3] = {1, 1, 1};
    double f[8] = {0.1813229861, 0.55654390999999981, 0.0063313725000000015,
                   0.13241650499999996, 0.1813229861, 0.55654391000000003,
                   0.006331372499999998, 0.13241650499999999};
    double g[8];
    plane(diag, g);
    vhe_cell_cut(&c, g, 3.0 - 1e-15, &out);
    ck_assert(out.status != -1);
    ck_assert(out.volume < 1e-12);
    vhe_cell_cut(&c, f, 0.55654390999999981, &out);
    ck_assert(out.status != -1);
    ck_assert(out.volume < 1e-12);
    /* that cell itself: 5e-4 x 5e-4 x 0.0125 m at (0.00875, 0.03175) */
    {
        double Y[24];
        int p;
        for (p = 0; p < 8; ++p) {
            Y[3 * p] = 0.0085 + 5e-4 * (p & 1);
            Y[3 * p + 1] = 0.0315 + 5e-4 * ((p >> 1) & 1);
            Y[3 * p + 2] = 0.0125 * ((p >> 2) & 1);
        }
        c.x = Y;
        c.x0[0] = 0.00875; c.x0[1] = 0.03175; c.x0[2] = 0.00625;
        ck_assert_int_eq(vhe_cell_cut_fraction(&c, f, 3.125e-9, 0.02532549,
                                               1e-8, 0.0, 0.0, &out), 0);
        ck_assert_int_eq(out.status, 0);
        ck_assert_double_eq_tol(out.volume, 0.02532549, 1e-8);
    }
}
END_TEST

Suite *cut_suite(void)
{
    Suite *s = suite_create("cut");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_cut_known);
    tcase_add_test(tc, test_cut_sheared);
    tcase_add_test(tc, test_cut_fraction);
    tcase_add_test(tc, test_cut_degenerate);
    tcase_add_test(tc, test_cut_curved);
    suite_add_tcase(s, tc);
    return s;
}
