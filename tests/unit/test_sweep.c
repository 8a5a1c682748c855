/* Check tests of sweep.c: a plane moving across a unit square face; exact
   areas swept; the step split in two gives the same volume (the quadrature
   is exact on each piece only if the pieces are right); a plane at rest */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include "vhe.h"

/* the unit square in z = 0, then a pentagon tilted out of the axes */
static const double SQ[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
static double PENT[15];

START_TEST(test_sweep_known)
{
    const double ex[3] = {1, 0, 0}, r2 = sqrt(0.5), diag[3] = {r2, r2, 0};
    double x0[3] = {0.25, 0.5, 0};
    /* fluid x < 0.25 + 0.5 t over t in [0, 1]: width 0.25 + 0.5 t */
    ck_assert_double_eq_tol(vhe_face_sweep(4, SQ, x0, ex, 0.5, 1.0, 1.0, 1.0,
                                           1e-14), 0.5, 1e-14);
    /* the flux scales it: phi/|S| */
    ck_assert_double_eq_tol(vhe_face_sweep(4, SQ, x0, ex, 0.5, 1.0, 3.0, 2.0,
                                           1e-14), 0.75, 1e-14);
    /* the face full from t = 0.5: 0.375 + 0.5 */
    x0[0] = 0.5;
    ck_assert_double_eq_tol(vhe_face_sweep(4, SQ, x0, ex, 1.0, 1.0, 1.0, 1.0,
                                           1e-14), 0.875, 1e-14);
    /* moving back: width 0.5 - t until empty at 0.5: 0.125 */
    ck_assert_double_eq_tol(vhe_face_sweep(4, SQ, x0, ex, -1.0, 1.0, 1.0, 1.0,
                                           1e-14), 0.125, 1e-14);
    /* at rest: the area x < 0.5, the whole step */
    ck_assert_double_eq_tol(vhe_face_sweep(4, SQ, x0, ex, 0.0, 2.0, 1.0, 1.0,
                                           1e-14), 1.0, 1e-14);
    /* along the diagonal from the corner (0, 0) at unit speed: the
       triangle x + y < sqrt(2) t, of area t^2 (t <= sqrt(2)/2); over
       [0, 0.5]: 1/24 */
    x0[0] = 0.0; x0[1] = 0.0;
    ck_assert_double_eq_tol(vhe_face_sweep(4, SQ, x0, diag, 1.0, 0.5, 1.0, 1.0,
                                           1e-14), 1.0 / 24.0, 1e-14);
    /* the plane parallel to the face (isoAdvector's own integration gives
       nothing there): reached at t = 0.25, full after */
    {
        const double ez[3] = {0, 0, 1};
        const double z0[3] = {0.5, 0.5, -0.25};
        ck_assert_double_eq_tol(vhe_face_sweep(4, SQ, z0, ez, 1.0, 1.0, 1.0,
                                               1.0, 1e-14), 0.75, 1e-14);
    }
}
END_TEST

START_TEST(test_sweep_split)
{
    int trial, i, k;
    srand(11);
    /* a pentagon in a tilted plane */
    for (k = 0; k < 5; ++k) {
        const double a = 8.0 * atan(1.0) * k / 5, u = cos(a), v = 0.8 * sin(a);
        PENT[3 * k] = u;
        PENT[3 * k + 1] = 0.6 * v;
        PENT[3 * k + 2] = 0.8 * v + 0.1 * u;
    }
    for (trial = 0; trial < 500; ++trial) {
        double n[3], x0[3], m = 0, Un, dt, dt1, full, part, x1[3];
        const double *x = trial % 2 ? SQ : PENT;
        const int np = trial % 2 ? 4 : 5;
        for (i = 0; i < 3; ++i) {
            n[i] = 2.0 * rand() / RAND_MAX - 1.0;
            m += n[i] * n[i];
            x0[i] = 2.0 * rand() / RAND_MAX - 0.5;
        }
        m = sqrt(m);
        for (i = 0; i < 3; ++i) n[i] /= m;
        Un = 4.0 * rand() / RAND_MAX - 2.0;
        dt = 0.05 + 0.5 * rand() / RAND_MAX;
        dt1 = dt * rand() / RAND_MAX;
        full = vhe_face_sweep(np, x, x0, n, Un, dt, 1.0, 1.0, 1e-14);
        for (i = 0; i < 3; ++i) x1[i] = x0[i] + n[i] * Un * dt1;
        part = vhe_face_sweep(np, x, x0, n, Un, dt1, 1.0, 1.0, 1e-14)
             + vhe_face_sweep(np, x, x1, n, Un, dt - dt1, 1.0, 1.0, 1e-14);
        ck_assert_double_eq_tol(full, part, 1e-13);
        /* bounded by the face's area over the step */
        ck_assert(full >= -1e-15 && full <= 2.0 * dt);
    }
}
END_TEST

Suite *sweep_suite(void)
{
    Suite *s = suite_create("sweep");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_sweep_known);
    tcase_add_test(tc, test_sweep_split);
    suite_add_tcase(s, tc);
    return s;
}
