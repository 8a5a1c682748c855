/*
 * test_vhe.c -- unit tests of the vheFoam C core (Check framework).
 *
 * One suite per concern: mixture, stretch, symm, shapes, packing, exact.
 * Tolerances are set from the accuracy each kernel is meant to have (round-
 * off for the algebra, the discretisation error for the sub-cell
 * integration), with a margin, so a wrong formula fails.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "vhe.h"

#define PI 3.14159265358979323846

/* |a - b| <= tol, with the values in the failure message. */
#define ASSERT_NEAR(a, b, tol)                                               \
    do {                                                                     \
        const double a_ = (a), b_ = (b), t_ = (tol);                         \
        ck_assert_msg(fabs(a_ - b_) <= t_,                                   \
                      "%s = %.17g, expected %s = %.17g (|diff| %.3g > %.3g)", \
                      #a, a_, #b, b_, fabs(a_ - b_), t_);                    \
    } while (0)

/* |a - b| <= rel |b| */
#define ASSERT_REL(a, b, rel) ASSERT_NEAR(a, b, (rel) * fabs(b))

/* ------------------------------------------------------------ helpers */

/* Rotation by angle t about the axis (x, y, z) (Rodrigues). */
static void rotation(double x, double y, double z, double t, double *R)
{
    const double n = sqrt(x * x + y * y + z * z);
    const double c = cos(t), s = sin(t), C = 1.0 - c;
    x /= n; y /= n; z /= n;
    R[0] = c + x * x * C;     R[1] = x * y * C - z * s; R[2] = x * z * C + y * s;
    R[3] = y * x * C + z * s; R[4] = c + y * y * C;     R[5] = y * z * C - x * s;
    R[6] = z * x * C - y * s; R[7] = z * y * C + x * s; R[8] = c + z * z * C;
}

/* S = R diag(l) R^T in symmTensor layout. */
static void rotated_diag(const double *R, const double *l, double *S)
{
    static const int ii[6] = {0, 0, 0, 1, 1, 2};
    static const int jj[6] = {0, 1, 2, 1, 2, 2};
    int m, k;
    for (m = 0; m < 6; ++m) {
        double s = 0.0;
        for (k = 0; k < 3; ++k) {
            s += R[3 * ii[m] + k] * l[k] * R[3 * jj[m] + k];
        }
        S[m] = s;
    }
}

static double max_abs(const double *a, int n)
{
    double m = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        if (fabs(a[i]) > m) {
            m = fabs(a[i]);
        }
    }
    return m;
}

/* max |a - b| over n entries. */
static double max_diff(const double *a, const double *b, int n)
{
    double m = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        if (fabs(a[i] - b[i]) > m) {
            m = fabs(a[i] - b[i]);
        }
    }
    return m;
}

/* ============================================================= mixture */

/* Phases: water, air (fluids), rubber (solid). */
static const double RHO3[3] = {1000.0, 1.2, 1100.0};
static const double MU3[3] = {1e-3, 1.8e-5, 0.1};
static const double G3[3] = {0.0, 0.0, 1e5};
static const int SOLID3[3] = {0, 0, 1};

START_TEST(test_mixture_three_phases)
{
    /* cells: water, air, rubber, a mix, a trace of solid below phis_min */
    const double aw[5] = {1.0, 0.0, 0.0, 0.2, 1.0 - 1e-9};
    const double aa[5] = {0.0, 1.0, 0.0, 0.3, 0.0};
    const double as[5] = {0.0, 0.0, 1.0, 0.5, 1e-9};
    const double *alpha[3] = {aw, aa, as};
    double rho[5], mu[5], phis[5], Ghat[5];
    int c;

    vhe_mixture(5, 3, alpha, RHO3, MU3, G3, SOLID3, NULL, 1e-6, rho, mu,
                phis, Ghat);
    for (c = 0; c < 5; ++c) {
        const double er = aw[c] * RHO3[0] + aa[c] * RHO3[1] + as[c] * RHO3[2];
        const double em = aw[c] * MU3[0] + aa[c] * MU3[1] + as[c] * MU3[2];
        ASSERT_REL(rho[c], er, 1e-15);
        ASSERT_REL(mu[c], em, 1e-15);
        ASSERT_NEAR(phis[c], as[c], 1e-16);
    }
    ASSERT_NEAR(rho[3], 0.2 * 1000.0 + 0.3 * 1.2 + 0.5 * 1100.0, 1e-12);
    /* No elasticity in fluid cells, nor below phis_min. */
    ck_assert(Ghat[0] == 0.0);
    ck_assert(Ghat[1] == 0.0);
    ck_assert(Ghat[4] == 0.0);
    /* One solid: Ghat is its modulus wherever there is solid. */
    ASSERT_REL(Ghat[2], 1e5, 1e-15);
    ASSERT_REL(Ghat[3], 1e5, 1e-15);
}
END_TEST

START_TEST(test_mixture_two_solids_and_nulls)
{
    /* water, rubber (G 1e5), gel (G 1e3): Ghat is the solid-weighted mean */
    const double aw[2] = {0.4, 0.0};
    const double ar[2] = {0.45, 0.25};
    const double ag[2] = {0.15, 0.75};
    const double *alpha[3] = {aw, ar, ag};
    const double rk[3] = {1000.0, 1100.0, 1050.0};
    const double mk[3] = {1e-3, 0.1, 0.5};
    const double gk[3] = {0.0, 1e5, 1e3};
    const int sk[3] = {0, 1, 1};
    double phis[2], Ghat[2];

    /* rho and mu skipped (NULL outputs) */
    vhe_mixture(2, 3, alpha, rk, mk, gk, sk, NULL, 1e-6, NULL, NULL, phis,
                Ghat);
    ASSERT_NEAR(phis[0], 0.6, 1e-15);
    ASSERT_NEAR(phis[1], 1.0, 1e-15);
    ASSERT_REL(Ghat[0], (0.45 * 1e5 + 0.15 * 1e3) / 0.6, 1e-14);
    ASSERT_REL(Ghat[1], 0.25 * 1e5 + 0.75 * 1e3, 1e-14);
}
END_TEST

/* A rigid material has no viscosity of its own (its mu_k is not read):
   below a quarter of a cell mu is the fluids' mean over their fraction,
   from a quarter on -1 (the body holds the cell; its neighbours' is taken),
   whatever traces of fluid the cell has; a cell without it keeps the
   plain sum, bit for bit */
START_TEST(test_mixture_rigid)
{
    /* water (1e-3 Pa s), oil (0.1), wood (rigid, 7: not read) */
    const double aw[6] = {1.0, 0.5, 0.9, 0.0, 0.0, -1e-9};
    const double ao[6] = {0.0, 0.3, 0.0, 1e-5, 0.75, 0.8};
    const double ar[6] = {0.0, 0.2, 0.1, 1.0 - 1e-5, 0.25, 0.2};
    const double *alpha[3] = {aw, ao, ar};
    const double rk[3] = {1000.0, 800.0, 600.0};
    const double mk[3] = {1e-3, 0.1, 7.0};
    const int sk[3] = {0, 0, 0}, rg[3] = {0, 0, 1};
    double rho[6], mu[6], phis[6];

    vhe_mixture(6, 3, alpha, rk, mk, NULL, sk, rg, 1e-6, rho, mu, phis, NULL);
    ck_assert(mu[0] == 1e-3);
    ASSERT_REL(mu[1], (0.5 * 1e-3 + 0.3 * 0.1) / 0.8, 1e-14);
    ASSERT_REL(mu[2], 1e-3, 1e-14);
    ck_assert(mu[3] == -1.0);
    ck_assert(mu[4] == -1.0);
    ASSERT_REL(mu[5], 0.1, 1e-14);   /* round-off below 0 left out */
    /* its density counts; it is not an elastic solid */
    ASSERT_REL(rho[1], 0.5 * 1000.0 + 0.3 * 800.0 + 0.2 * 600.0, 1e-15);
    ck_assert(phis[2] == 0.0);
}
END_TEST

START_TEST(test_elastic_stress)
{
    /* B: an SPD, non-isochoric B; B* = phi_s^(1/2) B */
    const double B[6] = {1.7, 0.3, -0.2, 0.9, 0.15, 1.2};
    const double Ghat[5] = {2e5, 0.0, 2e5, 2e5, 2e5};
    const double phis[5] = {0.81, 0.0, 1e-9, 0.2, 0.5};
    double Bs[30], sig[30];
    const double tr3 = (B[0] + B[3] + B[5]) / 3.0;
    int i;

    for (i = 0; i < 6; ++i) {
        Bs[i] = 0.9 * B[i];        /* sqrt(0.81) */
        Bs[6 + i] = 0.3 * B[i];    /* garbage in a fluid cell */
        Bs[12 + i] = 0.3 * B[i];   /* and below phis_min */
        Bs[18 + i] = 0.7 * B[i];   /* a centre outside the outline */
        Bs[24 + i] = sqrt(0.5) * B[i];   /* on the outline: half */
    }
    vhe_elastic_stress(5, Ghat, phis, Bs, 1e-6, sig);
    /* Ghat phi_s^(1/2) dev(B*) = Ghat phi_s dev(B) */
    ASSERT_REL(sig[0], 2e5 * 0.81 * (B[0] - tr3), 1e-14);
    ASSERT_REL(sig[1], 2e5 * 0.81 * B[1], 1e-14);
    ASSERT_REL(sig[2], 2e5 * 0.81 * B[2], 1e-14);
    ASSERT_REL(sig[3], 2e5 * 0.81 * (B[3] - tr3), 1e-14);
    ASSERT_REL(sig[4], 2e5 * 0.81 * B[4], 1e-14);
    ASSERT_REL(sig[5], 2e5 * 0.81 * (B[5] - tr3), 1e-14);
    /* traceless */
    ASSERT_NEAR(sig[0] + sig[3] + sig[5], 0.0, 1e-14 * max_abs(sig, 6));
    /* zero in fluid, below phis_min and a quarter cell outside */
    ck_assert(max_abs(sig + 6, 18) == 0.0);
    /* half the stress on the outline: w(1/2) = 1/2 */
    for (i = 0; i < 6; ++i) {
        ASSERT_REL(sig[24 + i], 0.5 * 0.5 / 0.81 * sig[i], 1e-14);
    }
}
END_TEST

START_TEST(test_body_weight)
{
    /* 0 up to 1/4, 1 from 3/4, linear (continuous) between */
    ck_assert(vhe_body_weight(0.0) == 0.0);
    ck_assert(vhe_body_weight(0.25) == 0.0);
    ASSERT_NEAR(vhe_body_weight(0.5), 0.5, 1e-15);
    ck_assert(vhe_body_weight(0.75) == 1.0);
    ck_assert(vhe_body_weight(1.0 + 1e-12) == 1.0);
    ASSERT_NEAR(vhe_body_weight(0.25 + 1e-9), 2e-9, 1e-15);
    ASSERT_NEAR(vhe_body_weight(0.75 - 1e-9), 1.0 - 2e-9, 1e-15);
}
END_TEST

START_TEST(test_wave_speed_and_elastic_dt)
{
    /*
     * Uniform cubic cells of edge dx: sum_f |S_f| / V = 6 dx^2 / dx^3.
     * Cell 0: rubber G 1e5, rho 1000 -> c = 10 m/s.  Cell 1: quarter solid
     * -> c = 5 m/s.  Cell 2: fluid (Ghat 0) with a finer mesh: ignored.
     */
    const double dx = 0.01;
    const double Ghat[3] = {1e5, 1e5, 0.0};
    const double phis[3] = {1.0, 0.25, 0.0};
    const double rho[3] = {1000.0, 1000.0, 1000.0};
    const double sm[3] = {6.0 / dx, 6.0 / dx, 60.0 / dx};
    const double zero[3] = {0.0, 0.0, 0.0};
    double c[3], co, dt;

    vhe_wave_speed(3, Ghat, phis, rho, c);
    ASSERT_REL(c[0], 10.0, 1e-15);
    ASSERT_REL(c[1], 5.0, 1e-15);
    ck_assert(c[2] == 0.0);

    dt = vhe_elastic_dt(3, Ghat, phis, rho, sm, 0.5, 1e-4, &co);
    ASSERT_REL(dt, 0.5 / (0.5 * 10.0 * 6.0 / dx), 1e-14);
    /* Co_e for the given dt: 0.5 dt c sum|Sf|/V of the stiffest cell */
    ASSERT_REL(co, 0.5 * 1e-4 * 10.0 * 6.0 / dx, 1e-14);

    /* no solid anywhere: no elastic limit */
    dt = vhe_elastic_dt(3, zero, phis, rho, sm, 0.5, 1e-4, &co);
    ck_assert(dt == HUGE_VAL);
    ck_assert(co == 0.0);
    ck_assert(vhe_elastic_dt(0, NULL, NULL, NULL, NULL, 0.5, 1.0, NULL)
              == HUGE_VAL);
}
END_TEST

START_TEST(test_energies)
{
    const double g = 0.6;
    const double B[6] = {1.0 + g * g, g, 0.0, 1.0, 0.0, 1.0};  /* shear */
    const double Ghat[3] = {3e4, 3e4, 0.0};
    const double phis[3] = {0.36, 0.81, 0.0};
    double Bs[18], e[3], ek[2];
    const double rho[2] = {998.0, 1.2};
    const double U[6] = {1.0, -2.0, 0.5, 3.0, 0.0, 4.0};
    int i;

    /* cell 0 undeformed, cell 1 sheared, cell 2 fluid */
    vhe_bstar_undeformed(3, phis, Bs);
    for (i = 0; i < 6; ++i) {
        Bs[6 + i] = 0.9 * B[i];
    }
    vhe_elastic_energy(3, Ghat, phis, Bs, e);
    ck_assert_msg(e[0] == 0.0, "undeformed energy %g", e[0]);
    /* G/2 phi_s (tr B - 3) = G/2 phi_s g^2 */
    ASSERT_REL(e[1], 0.5 * 3e4 * 0.81 * g * g, 1e-13);
    ck_assert(e[2] == 0.0);

    vhe_kinetic_energy(2, rho, U, ek);
    ASSERT_REL(ek[0], 0.5 * 998.0 * 5.25, 1e-15);
    ASSERT_REL(ek[1], 0.5 * 1.2 * 25.0, 1e-15);
}
END_TEST

static Suite *mixture_suite(void)
{
    Suite *s = suite_create("mixture");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_mixture_three_phases);
    tcase_add_test(tc, test_mixture_two_solids_and_nulls);
    tcase_add_test(tc, test_mixture_rigid);
    tcase_add_test(tc, test_elastic_stress);
    tcase_add_test(tc, test_body_weight);
    tcase_add_test(tc, test_wave_speed_and_elastic_dt);
    tcase_add_test(tc, test_energies);
    suite_add_tcase(s, tc);
    return s;
}

/* ============================================================= stretch */

START_TEST(test_expm3_known)
{
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double A[9], E[9], X[9];
    int i;

    /* zero -> identity, exactly */
    memset(A, 0, sizeof A);
    vhe_expm3(A, E);
    ck_assert(max_diff(E, I, 9) == 0.0);

    /* diagonal */
    memset(A, 0, sizeof A);
    A[0] = 1.0; A[4] = -2.0; A[8] = 0.5;
    vhe_expm3(A, E);
    memset(X, 0, sizeof X);
    X[0] = exp(1.0); X[4] = exp(-2.0); X[8] = exp(0.5);
    ck_assert_msg(max_diff(E, X, 9) <= 1e-13 * max_abs(X, 9),
                  "diag: %g", max_diff(E, X, 9));

    /* nilpotent shear: exp([[0,g],[0,0]]) = [[1,g],[0,1]] */
    memset(A, 0, sizeof A);
    A[1] = 7.5;
    vhe_expm3(A, E);
    memcpy(X, I, sizeof X);
    X[1] = 7.5;
    ck_assert_msg(max_diff(E, X, 9) <= 1e-13 * 7.5, "shear: %g",
                  max_diff(E, X, 9));

    /* rotation about z, small and large angles (scaling and squaring) */
    for (i = 0; i < 2; ++i) {
        const double t = i == 0 ? 0.7 : 10.0;
        memset(A, 0, sizeof A);
        A[1] = -t; A[3] = t;
        vhe_expm3(A, E);
        rotation(0.0, 0.0, 1.0, t, X);
        ck_assert_msg(max_diff(E, X, 9) <= 1e-13, "rot %g: %g", t,
                      max_diff(E, X, 9));
    }

    /* rotation about a skew axis: exp(t K), K the cross-product matrix */
    {
        const double n = sqrt(14.0), x = 1.0 / n, y = 2.0 / n, z = 3.0 / n;
        const double t = 2.3;
        A[0] = 0.0;    A[1] = -t * z; A[2] = t * y;
        A[3] = t * z;  A[4] = 0.0;    A[5] = -t * x;
        A[6] = -t * y; A[7] = t * x;  A[8] = 0.0;
        vhe_expm3(A, E);
        rotation(1.0, 2.0, 3.0, t, X);
        ck_assert_msg(max_diff(E, X, 9) <= 1e-13, "skew rot: %g",
                      max_diff(E, X, 9));
    }

    /* non-normal upper triangular: exp([[a,b],[0,c]]) */
    {
        const double a = 1.0, b = 3.0, c = -0.5;
        memset(A, 0, sizeof A);
        A[0] = a; A[1] = b; A[4] = c;
        vhe_expm3(A, E);
        memset(X, 0, sizeof X);
        X[0] = exp(a); X[1] = b * (exp(a) - exp(c)) / (a - c);
        X[4] = exp(c); X[8] = 1.0;
        ck_assert_msg(max_diff(E, X, 9) <= 1e-13 * max_abs(X, 9),
                      "triangular: %g", max_diff(E, X, 9));
    }
}
END_TEST

START_TEST(test_stretch_simple_shear)
{
    /*
     * u_x = g y: L_xy = g, OpenFOAM gradU(y,x) = d u_x / d y = g, i.e.
     * index 3 of the row-major tensor.  F = [[1, g t],[0, 1]], so from
     * B = I: B = F F^T = [[1 + (g t)^2, g t], [g t, 1]], zz = 1.
     * Second cell: the same in a solid of phi_s = 0.64 (B* scales).
     */
    const double g = 2.0, t = 0.75, gt = g * t;
    double gradU[18], Bs[12];
    const double phis[2] = {1.0, 0.64};
    int c;

    memset(gradU, 0, sizeof gradU);
    gradU[3] = g;
    gradU[9 + 3] = g;
    vhe_bstar_undeformed(2, phis, Bs);
    vhe_stretch(2, t, gradU, Bs);
    for (c = 0; c < 2; ++c) {
        const double sp = c == 0 ? 1.0 : 0.8;
        const double X[6] = {sp * (1.0 + gt * gt), sp * gt, 0.0, sp, 0.0, sp};
        ck_assert_msg(max_diff(Bs + 6 * c, X, 6) <= 1e-12 * max_abs(X, 6),
                      "cell %d: %g", c, max_diff(Bs + 6 * c, X, 6));
    }
}
END_TEST

START_TEST(test_stretch_det_and_fluid)
{
    /* traceless L: det(B*) preserved; fluid B* = 0 stays 0 */
    const double gradU[18] = {0.3, -1.1, 0.4, 0.7, -0.9, 0.25, -0.5, 0.8, 0.6,
                              5, 5, 5, 5, 5, 5, 5, 5, 5};
    double Bs[12] = {1.3, 0.2, -0.1, 0.8, 0.05, 1.1, 0, 0, 0, 0, 0, 0};
    const double d0 = vhe_sym_det(Bs);
    double l[3];
    int k;

    for (k = 0; k < 20; ++k) {
        vhe_stretch(2, 0.1, gradU, Bs);
    }
    ASSERT_REL(vhe_sym_det(Bs), d0, 1e-12);
    vhe_sym_eigenvalues(Bs, l);
    ck_assert(l[0] > 0.0);
    ck_assert(max_abs(Bs + 6, 6) == 0.0);
}
END_TEST

START_TEST(test_stretch_huge_dt)
{
    /*
     * In-plane shear plus rotation, L = [[0, 1.5], [-0.5, 0]]: eigenvalues
     * +-i sqrt(0.75), so F = exp(dt L) stays bounded, with dt |L| = 1e3.
     * OpenFOAM gradU = L^T.  B* must stay SPD with det(B*) kept.
     */
    double gradU[9] = {0, -0.5, 0, 1.5, 0, 0, 0, 0, 0};
    double Bs[6] = {1.3, 0.2, -0.1, 0.8, 0.05, 1.1};
    const double normL = sqrt(1.5 * 1.5 + 0.5 * 0.5);
    const double d0 = vhe_sym_det(Bs);
    double l[3];

    vhe_stretch(1, 1e3 / normL, gradU, Bs);
    vhe_sym_eigenvalues(Bs, l);
    ck_assert_msg(l[0] > 0.1, "min eigenvalue %g", l[0]);
    ASSERT_REL(vhe_sym_det(Bs), d0, 1e-11);
}
END_TEST

START_TEST(test_stretch_composition)
{
    /* constant L (with a trace): 10 steps of dt == one step of 10 dt */
    const double gradU[9] = {0.2, -0.7, 0.1, 0.9, -0.4, 0.3, -0.2, 0.5, 0.35};
    double B1[6] = {1.1, 0.1, 0.0, 0.9, -0.2, 1.4};
    double B2[6];
    int k;

    memcpy(B2, B1, sizeof B2);
    for (k = 0; k < 10; ++k) {
        vhe_stretch(1, 0.05, gradU, B1);
    }
    vhe_stretch(1, 0.5, gradU, B2);
    ck_assert_msg(max_diff(B1, B2, 6) <= 1e-12 * max_abs(B2, 6), "%g",
                  max_diff(B1, B2, 6));
    /* and det changes by exp(2 dt tr L) exactly */
    {
        const double B0[6] = {1.1, 0.1, 0.0, 0.9, -0.2, 1.4};
        ASSERT_REL(vhe_sym_det(B2),
                   vhe_sym_det(B0) * exp(2.0 * 0.5 * (0.2 - 0.4 + 0.35)),
                   1e-12);
    }
}
END_TEST

START_TEST(test_stretch_implicit_shear_and_residual)
{
    /*
     * Simple shear u_x = g y from Bhat = I: B_yy = 1, B_xy = tau g,
     * B_xx = 1 + 2 (tau g)^2; a fluid cell (Bhat = 0) stays 0; and for a
     * general L the solution satisfies B - tau (L B + B L^T) = Bhat.
     */
    const double g = 2.0, tau = 0.3;
    double gradU[27], Bh[18], B[18];
    int c;

    memset(gradU, 0, sizeof gradU);
    memset(Bh, 0, sizeof Bh);
    gradU[3] = g;
    Bh[0] = Bh[3] = Bh[5] = 1.0;
    {
        const double G2[9] = {0.2, -0.7, 0.1, 0.9, -0.4, 0.3, -0.2, 0.5, 0.35};
        const double b[6] = {1.1, 0.1, 0.0, 0.9, -0.2, 1.4};
        memcpy(gradU + 18, G2, sizeof G2);
        memcpy(Bh + 12, b, sizeof b);
    }
    ck_assert_uint_eq(vhe_stretch_implicit(3, tau, gradU, Bh, B), 0);
    {
        const double X[6] = {1.0 + 2.0 * tau * g * tau * g, tau * g, 0.0,
                             1.0, 0.0, 1.0};
        ck_assert_msg(max_diff(B, X, 6) <= 1e-13, "shear: %g",
                      max_diff(B, X, 6));
    }
    for (c = 0; c < 6; ++c) ck_assert(B[6 + c] == 0.0);
    {
        /* residual with L = gradU^T, full 3x3 products */
        const double *g3 = gradU + 18, *b = B + 12;
        const double Bf[9] = {b[0], b[1], b[2], b[1], b[3], b[4],
                              b[2], b[4], b[5]};
        static const int ij[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2},
                                     {2, 2}};
        double r = 0.0;
        int p, k;
        for (p = 0; p < 6; ++p) {
            const int i = ij[p][0], j = ij[p][1];
            double LB = 0.0;
            for (k = 0; k < 3; ++k) {
                /* L_ik = g3[3k + i]; (L B)_ij + (L B)_ji */
                LB += g3[3 * k + i] * Bf[3 * k + j]
                      + g3[3 * k + j] * Bf[3 * k + i];
            }
            r = fmax(r, fabs(Bf[3 * i + j] - tau * LB - Bh[12 + p]));
        }
        ck_assert_msg(r <= 1e-13, "residual %g", r);
    }
}
END_TEST

START_TEST(test_stretch_implicit_bdf2_order)
{
    /*
     * dB/dt = L B + B L^T with constant L to T = 1 by BDF2 (implicit Euler
     * first step, then tau = 2h/3 and the carry 1/3 of the last
     * increment) against the exact stretch: halving h must cut the error
     * about 4x (second order), where implicit Euler alone gives 2x.
     */
    const double gradU[9] = {0.2, -0.7, 0.1, 0.9, -0.4, 0.3, -0.2, 0.5, 0.35};
    const double B0[6] = {1.1, 0.1, 0.0, 0.9, -0.2, 1.4};
    double exact[6], err[2];
    int level;

    memcpy(exact, B0, sizeof exact);
    vhe_stretch(1, 1.0, gradU, exact);
    for (level = 0; level < 2; ++level) {
        const int steps = 20 << level;
        const double h = 1.0 / steps;
        double B[6], D[6], Bh[6];
        int k, q;

        memcpy(B, B0, sizeof B);
        memset(D, 0, sizeof D);
        for (k = 0; k < steps; ++k) {
            const double tau = k == 0 ? h : 2.0 * h / 3.0;
            const double carry = k == 0 ? 0.0 : 1.0 / 3.0;
            double Bn[6];
            for (q = 0; q < 6; ++q) Bh[q] = B[q] + carry * D[q];
            vhe_stretch_implicit(1, tau, gradU, Bh, Bn);
            for (q = 0; q < 6; ++q) {
                D[q] = Bn[q] - B[q];
                B[q] = Bn[q];
            }
        }
        err[level] = max_diff(B, exact, 6);
    }
    ck_assert_msg(err[0] / err[1] > 3.5 && err[0] / err[1] < 4.5,
                  "errors %g %g ratio %g", err[0], err[1], err[0] / err[1]);
}
END_TEST

START_TEST(test_clip_and_undeformed)
{
    const double phis[3] = {0.25, 1e-9, 0.0};
    double Bs[18];
    int i;

    vhe_bstar_undeformed(3, phis, Bs);
    ASSERT_NEAR(Bs[0], 0.5, 1e-16);
    ASSERT_NEAR(Bs[3], 0.5, 1e-16);
    ASSERT_NEAR(Bs[5], 0.5, 1e-16);
    ck_assert(Bs[1] == 0.0 && Bs[2] == 0.0 && Bs[4] == 0.0);
    ck_assert(max_abs(Bs + 12, 6) == 0.0);
    for (i = 0; i < 18; ++i) {
        Bs[i] = 1.0;
    }
    vhe_clip_fluid(3, phis, 1e-6, Bs);
    ck_assert(max_abs(Bs + 6, 12) == 0.0);
    ck_assert(Bs[0] == 1.0 && Bs[5] == 1.0);
}
END_TEST

START_TEST(test_b_from_bstar)
{
    /* B = [[1+g^2, g, 0],[g, 1, 0],[0, 0, 1]] (simple shear, det 1) in a
     * solid cell (phi_s 0.64), an edge cell (phi_s 1e-3) and a fluid cell. */
    const double g = 0.7;
    const double phis[3] = {0.64, 1e-3, 0.0};
    const double Bexact[6] = {1.0 + g * g, g, 0.0, 1.0, 0.0, 1.0};
    double Bs[18], B[18];
    int c, k;

    for (c = 0; c < 3; ++c) {
        for (k = 0; k < 6; ++k) {
            Bs[6 * c + k] = sqrt(phis[c]) * Bexact[k];
        }
    }
    vhe_b_from_bstar(3, phis, Bs, 1e-6, B);
    for (k = 0; k < 6; ++k) {
        ASSERT_NEAR(B[k], Bexact[k], 1e-14);
        ASSERT_NEAR(B[6 + k], Bexact[k], 1e-12);
    }
    /* no solid: the neutral donor value I */
    ck_assert(B[12] == 1.0 && B[15] == 1.0 && B[17] == 1.0);
    ck_assert(B[13] == 0.0 && B[14] == 0.0 && B[16] == 0.0);
}
END_TEST

START_TEST(test_bdonor)
{
    /* Three unit cells in a row, faces 0->1 and 1->2, solid leaving cell 0
     * to the right; a boundary face feeds cell 0 from outside. */
    const int32_t owner[2] = {0, 1}, neighbour[2] = {1, 2}, bcell[1] = {0};
    const double V[3] = {1, 1, 1};
    const double a[2] = {0.2, 0.1}, ab[1] = {-0.1};
    const double Ba[6] = {2, 0.5, 0, 1, 0, 0.5};      /* SPD, det 0.875 */
    const double Bb[6] = {1, -0.3, 0.1, 2, 0, 1};
    const double Bc[6] = {1, 0, 0, 1, 0, 1};
    const double phis0[3] = {1, 0.5, 0};
    const double phis[3] = {0.9, 0.6, 0.1};            /* after the fluxes */
    double B[18], out[3] = {0}, W[3] = {0}, S[18] = {0}, Bs[18], lam[3];
    int k, c;
    size_t flushed;

    for (k = 0; k < 6; ++k) {
        B[k] = Ba[k]; B[6 + k] = Bb[k]; B[12 + k] = Bc[k];
    }
    vhe_bdonor_internal(2, owner, neighbour, a, B, out, W, S);
    vhe_bdonor_boundary(1, bcell, ab, Bc, out, W, S);
    flushed = vhe_bdonor_finish(3, V, phis0, phis, B, out, W, S, 1e-6, Bs);
    ck_assert_uint_eq(flushed, 0);
    for (k = 0; k < 6; ++k) {
        /* cell 0 keeps 0.8 of Ba and receives 0.1 of Bc */
        ASSERT_NEAR(Bs[k], sqrt(0.9) * (0.8 * Ba[k] + 0.1 * Bc[k]) / 0.9, 1e-14);
        /* cell 1 keeps 0.4 of Bb and receives 0.2 of Ba */
        ASSERT_NEAR(Bs[6 + k], sqrt(0.6) * (0.4 * Bb[k] + 0.2 * Ba[k]) / 0.6, 1e-14);
        /* cell 2 had no solid: all of it is Bb from cell 1 */
        ASSERT_NEAR(Bs[12 + k], sqrt(0.1) * Bb[k], 1e-14);
    }
    /* solid-weighted B is conserved: what entered minus what left */
    for (k = 0; k < 6; ++k) {
        double before = 0, after = 0;
        for (c = 0; c < 3; ++c) {
            before += phis0[c] * V[c] * B[6 * c + k];
            after += sqrt(phis[c]) * V[c] * Bs[6 * c + k];
        }
        ASSERT_NEAR(after, before + 0.1 * Bc[k], 1e-14);
    }
    for (c = 0; c < 3; ++c) {
        vhe_sym_eigenvalues(Bs + 6 * c, lam);
        ck_assert(lam[0] > 0.0);
    }

    /* uniform B stays exactly uniform, whatever the fluxes */
    for (c = 0; c < 3; ++c) {
        for (k = 0; k < 6; ++k) {
            B[6 * c + k] = Bb[k];
        }
        out[c] = W[c] = 0;
    }
    for (k = 0; k < 18; ++k) {
        S[k] = 0;
    }
    vhe_bdonor_internal(2, owner, neighbour, a, B, out, W, S);
    vhe_bdonor_boundary(1, bcell, ab, Bb, out, W, S);
    vhe_bdonor_finish(3, V, phis0, phis, B, out, W, S, 1e-6, Bs);
    for (c = 0; c < 3; ++c) {
        for (k = 0; k < 6; ++k) {
            ASSERT_NEAR(Bs[6 * c + k], sqrt(phis[c]) * Bb[k], 1e-14);
        }
    }

    /* a cell whose content leaves entirely takes what entered */
    {
        const double p0[1] = {0.1}, p1[1] = {0.1}, o[1] = {0.3};
        const double w[1] = {0.3};
        double s1[6], bs[6];
        for (k = 0; k < 6; ++k) {
            s1[k] = 0.3 * Bb[k];
        }
        ck_assert_uint_eq(vhe_bdonor_finish(1, V, p0, p1, Ba, o, w, s1,
                                            1e-6, bs), 1);
        for (k = 0; k < 6; ++k) {
            ASSERT_NEAR(bs[k], sqrt(0.1) * Bb[k], 1e-14);
        }
    }
}
END_TEST

static Suite *stretch_suite(void)
{
    Suite *s = suite_create("stretch");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_expm3_known);
    tcase_add_test(tc, test_stretch_simple_shear);
    tcase_add_test(tc, test_stretch_det_and_fluid);
    tcase_add_test(tc, test_stretch_huge_dt);
    tcase_add_test(tc, test_stretch_composition);
    tcase_add_test(tc, test_stretch_implicit_shear_and_residual);
    tcase_add_test(tc, test_stretch_implicit_bdf2_order);
    tcase_add_test(tc, test_clip_and_undeformed);
    tcase_add_test(tc, test_b_from_bstar);
    tcase_add_test(tc, test_bdonor);
    suite_add_tcase(s, tc);
    return s;
}

/* ================================================================ symm */

START_TEST(test_eigenvalues)
{
    /* ascending eigenvalue triples, incl. repeated and nearly repeated */
    static const double cases[][3] = {
        {-1.0, 2.0, 3.0},
        {2.0, 2.0, 5.0},
        {2.0, 5.0, 5.0},
        {4.0, 4.0, 4.0},
        {1.0, 1.0 + 1e-10, 3.0},
        {1e-8, 1.0, 1e6},
        {-3.0, -3.0, 1e-3},
    };
    const double diag[6] = {3.0, 0.0, 0.0, -1.0, 0.0, 2.0};
    double R[9], S[6], l[3];
    size_t k;
    int r;

    vhe_sym_eigenvalues(diag, l);
    ck_assert(l[0] == -1.0 && l[1] == 2.0 && l[2] == 3.0);

    for (k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        for (r = 0; r < 3; ++r) {
            const double scale = max_abs(cases[k], 3);
            if (r == 0) {
                rotation(1.0, 0.0, 0.0, 0.0, R);
            } else if (r == 1) {
                rotation(0.0, 0.0, 1.0, 0.4, R);
            } else {
                rotation(0.3, -1.2, 0.7, 2.1, R);
            }
            rotated_diag(R, cases[k], S);
            vhe_sym_eigenvalues(S, l);
            ck_assert_msg(max_diff(l, cases[k], 3) <= 1e-13 * scale,
                          "case %d rot %d: (%.17g %.17g %.17g) err %g",
                          (int)k, r, l[0], l[1], l[2],
                          max_diff(l, cases[k], 3));
            ASSERT_REL(vhe_sym_det(S), cases[k][0] * cases[k][1] * cases[k][2],
                       1e-12 + 1e-15 * scale * scale * scale
                                   / fabs(cases[k][0] * cases[k][1]
                                          * cases[k][2]));
        }
    }
}
END_TEST

START_TEST(test_solid_diagnostics)
{
    /*
     * Cell 0: simple shear B (det 1) with gamma = 0.5 in phi_s = 0.64:
     *   |dev B|^2 = 2 g^4 / 3 + 2 g^2.
     * Cell 1: B* = diag(1.1, 1, 1), phi_s = 1: det - 1 = 0.1,
     *   |dev| = sqrt(0.06) / 3.
     * Cell 2: fluid with a slightly negative B*: only min eigenvalue.
     * Cell 3: fluid with garbage: must not enter out[1], out[2].
     */
    const double g = 0.5;
    const double phis[4] = {0.64, 1.0, 0.0, 0.005};
    const double Bs[24] = {
        0.8 * (1 + g * g), 0.8 * g, 0, 0.8, 0, 0.8,
        1.1, 0, 0, 1, 0, 1,
        -0.01, 0, 0, 0, 0, 0,
        50, 0, 0, 1, 0, 1};
    double out[3];

    vhe_solid_diagnostics(4, phis, Bs, 0.01, out);
    ASSERT_NEAR(out[0], -0.01, 1e-15);
    ASSERT_REL(out[1], sqrt(2.0 * pow(g, 4) / 3.0 + 2.0 * g * g), 1e-14);
    ASSERT_REL(out[2], 0.1, 1e-13);

    /* only the sheared cell counted: det error ~ 0 */
    vhe_solid_diagnostics(1, phis, Bs, 0.01, out);
    ASSERT_NEAR(out[2], 0.0, 1e-14);
    ASSERT_REL(out[0], 0.8 * (1.0 + g * g / 2.0 - g * sqrt(1.0 + g * g / 4.0)),
               1e-13);

    vhe_solid_diagnostics(0, phis, Bs, 0.01, out);
    ck_assert(out[0] == HUGE_VAL && out[1] == 0.0 && out[2] == 0.0);
}
END_TEST

START_TEST(test_spd_repair)
{
    /* B* = R diag(-0.5, 1, 2) R^T in phi_s = 0.25 with lambda_min = 0.1:
     * the floor is 0.1 * 0.5 = 0.05, eigenvectors kept. */
    const double l0[3] = {-0.5, 1.0, 2.0}, l1[3] = {0.05, 1.0, 2.0};
    const double lspd[3] = {0.3, 0.7, 1.9};
    const double phis[2] = {0.25, 1.0};
    double R[9], Bs[12], X[6], keep[6], l[3];
    size_t changed;

    rotation(0.3, -1.2, 0.7, 2.1, R);
    rotated_diag(R, l0, Bs);
    rotated_diag(R, lspd, Bs + 6);
    memcpy(keep, Bs + 6, sizeof keep);
    rotated_diag(R, l1, X);

    changed = vhe_spd_repair(2, phis, 0.1, Bs);
    ck_assert_uint_eq(changed, 1);
    ck_assert_msg(max_diff(Bs, X, 6) <= 1e-13, "repaired: %g",
                  max_diff(Bs, X, 6));
    vhe_sym_eigenvalues(Bs, l);
    ASSERT_NEAR(l[0], 0.05, 1e-13);
    /* the SPD tensor is left bit-identical */
    ck_assert(memcmp(Bs + 6, keep, sizeof keep) == 0);
    /* nothing left to repair */
    ck_assert_uint_eq(vhe_spd_repair(2, phis, 0.1, Bs), 0);
}
END_TEST

static Suite *symm_suite(void)
{
    Suite *s = suite_create("symm");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_eigenvalues);
    tcase_add_test(tc, test_solid_diagnostics);
    tcase_add_test(tc, test_spd_repair);
    suite_add_tcase(s, tc);
    return s;
}

/* ============================================================== shapes */

/*
 * Sum of fraction * cell volume over the unit-cell grid cells [i, i+1]
 * that cover the shape's bounds.  ndim 2: one layer z in [z0, z0 + dz].
 */
static double grid_volume(const struct vhe_shape *s, int ndim, int depth,
                          double z0, double dz)
{
    double lo[3], hi[3], sum = 0.0;
    int i, j, k, i0, i1, j0, j1, k0, k1;

    vhe_shape_bounds(s, lo, hi);
    i0 = (int)floor(lo[0]) - 1; i1 = (int)ceil(hi[0]) + 1;
    j0 = (int)floor(lo[1]) - 1; j1 = (int)ceil(hi[1]) + 1;
    if (ndim == 2) {
        k0 = 0; k1 = 1;
    } else {
        k0 = (int)floor(lo[2]) - 1; k1 = (int)ceil(hi[2]) + 1;
    }
    for (k = k0; k < k1; ++k) {
        for (j = j0; j < j1; ++j) {
            for (i = i0; i < i1; ++i) {
                double cl[3], ch[3], f;
                cl[0] = i; cl[1] = j;
                ch[0] = i + 1.0; ch[1] = j + 1.0;
                if (ndim == 2) {
                    cl[2] = z0; ch[2] = z0 + dz;
                } else {
                    cl[2] = k; ch[2] = k + 1.0;
                }
                f = vhe_shape_fraction(s, cl, ch, ndim, depth);
                ck_assert_msg(f >= 0.0 && f <= 1.0, "fraction %g", f);
                sum += f * (ch[0] - cl[0]) * (ch[1] - cl[1]) * (ch[2] - cl[2]);
            }
        }
    }
    return sum;
}

static struct vhe_shape make_shape(int kind, double cx, double cy, double cz)
{
    struct vhe_shape s;
    memset(&s, 0, sizeof s);
    s.kind = kind;
    s.centre[0] = cx;
    s.centre[1] = cy;
    s.centre[2] = cz;
    s.axis[2] = 1.0;
    return s;
}

START_TEST(test_shape_sphere_volume)
{
    struct vhe_shape s = make_shape(VHE_SPHERE, 0.31, -0.17, 0.43);
    const double exact = 4.0 / 3.0 * PI * 1000.0;
    s.radius = 10.0;
    ASSERT_REL(vhe_shape_volume(&s), exact, 1e-15);
    ASSERT_REL(grid_volume(&s, 3, 4, 0.0, 0.0), exact, 1e-3);
}
END_TEST

START_TEST(test_shape_half_width)
{
    /* the smallest half-width over the solved directions */
    const int all[3] = {1, 1, 1}, xy[3] = {1, 1, 0};
    struct vhe_shape s = make_shape(VHE_SPHERE, 0.0, 0.0, 0.0);
    s.radius = 0.05;
    ck_assert(vhe_shape_half_width(&s, all) == 0.05);
    s = make_shape(VHE_CYLINDER, 0.0, 0.0, 0.0);       /* axis z */
    s.radius = 0.05;
    ck_assert(vhe_shape_half_width(&s, xy) == 0.05);   /* a 2D disk */
    s.half_length = 0.02;
    ck_assert(vhe_shape_half_width(&s, all) == 0.02);  /* a coin */
    ck_assert(vhe_shape_half_width(&s, xy) == 0.05);   /* its length unsolved */
    s = make_shape(VHE_BOX, 0.0, 0.0, 0.0);
    s.semi[0] = 0.15; s.semi[1] = 0.05; s.semi[2] = 0.01;
    ck_assert(vhe_shape_half_width(&s, all) == 0.01);
    ck_assert(vhe_shape_half_width(&s, xy) == 0.05);   /* the depth left out */
    s.kind = VHE_ELLIPSOID;
    ck_assert(vhe_shape_half_width(&s, xy) == 0.05);
    s.semi[1] = -1.0;                                  /* invalid */
    ck_assert(vhe_shape_half_width(&s, all) == 0.0);
}
END_TEST

START_TEST(test_shape_convergence)
{
    /*
     * A smooth shape's cells take the second-order leaf (the corner-value
     * cut of a leaf and of its halves, extrapolated), three levels above
     * max_depth but no coarser than a quarter of the smallest radius of
     * curvature: every cell's fraction converges by 4.9 to 9.4 a level
     * from depth 4 to 6 against depth 8 (require 3.5), and at the default
     * depth 5 the largest cell error of a sphere and an ellipsoid 10 cells
     * across is 7.6e-5 and 4.0e-5 (the plane leaf's 1.7e-4 and 2.9e-4 on a
     * 5.3-cell sphere and an ellipsoid).  One slab of cells through the
     * middle.  A sphere of a tenth of a cell's radius keeps its volume on
     * the grid to 1e-3 (without the floor on the leaf's size it fell
     * between a leaf's points: 0.25 of it).
     */
    struct vhe_shape s = make_shape(VHE_SPHERE, 0.31, -0.17, 0.43);
    int shape, d, i, j, k;
    double sum = 0.0;
    s.radius = 10.0;
    s.semi[0] = 9.0; s.semi[1] = 6.5; s.semi[2] = 5.0;
    for (shape = 0; shape < 2; ++shape) {
        double prev = 0.0, at5 = 0.0;
        s.kind = shape ? VHE_ELLIPSOID : VHE_SPHERE;
        for (d = 4; d <= 6; ++d) {
            double emax = 0.0;
            for (j = -12; j < 12; ++j) {
                for (i = -12; i < 12; ++i) {
                    const double cl[3] = {i, j, 0.0};
                    const double ch[3] = {i + 1.0, j + 1.0, 1.0};
                    emax = fmax(emax,
                                fabs(vhe_shape_fraction(&s, cl, ch, 3, d)
                                     - vhe_shape_fraction(&s, cl, ch, 3, 8)));
                }
            }
            if (d > 4) {
                ck_assert_msg(emax < prev / 3.5, "depth %d: error %g, was %g",
                              d, emax, prev);
            }
            at5 = d == 5 ? emax : at5;
            prev = emax;
        }
        ck_assert_msg(at5 < 2e-4, "depth 5: largest cell error %g", at5);
    }

    s = make_shape(VHE_SPHERE, 0.537, 0.413, 0.471);
    s.radius = 0.1;
    for (i = -1; i <= 1; ++i) {
        for (j = -1; j <= 1; ++j) {
            for (k = -1; k <= 1; ++k) {
                const double cl[3] = {i, j, k};
                const double ch[3] = {i + 1.0, j + 1.0, k + 1.0};
                sum += vhe_shape_fraction(&s, cl, ch, 3, 5);
            }
        }
    }
    ASSERT_REL(sum, 4.0 / 3.0 * PI * 1e-3, 1e-3);
}
END_TEST

START_TEST(test_shape_ellipsoid_volume)
{
    struct vhe_shape s = make_shape(VHE_ELLIPSOID, 0.23, 0.61, -0.37);
    double exact;
    s.semi[0] = 9.0; s.semi[1] = 6.5; s.semi[2] = 5.0;
    exact = 4.0 / 3.0 * PI * 9.0 * 6.5 * 5.0;
    ASSERT_REL(vhe_shape_volume(&s), exact, 1e-15);
    ASSERT_REL(grid_volume(&s, 3, 4, 0.0, 0.0), exact, 1e-3);
}
END_TEST

START_TEST(test_shape_box_volume)
{
    /* offset from the grid: discretisation error only at the faces */
    struct vhe_shape s = make_shape(VHE_BOX, 0.37, 0.21, -0.44);
    double exact;
    s.semi[0] = 3.3; s.semi[1] = 2.6; s.semi[2] = 4.1;
    exact = 8.0 * 3.3 * 2.6 * 4.1;
    ASSERT_REL(vhe_shape_volume(&s), exact, 1e-15);
    ASSERT_REL(grid_volume(&s, 3, 4, 0.0, 0.0), exact, 1e-3);

    /* aligned to cell faces: exact at any depth */
    s = make_shape(VHE_BOX, 0.0, 1.0, 0.0);
    s.semi[0] = 3.0; s.semi[1] = 2.0; s.semi[2] = 4.0;
    ASSERT_REL(grid_volume(&s, 3, 0, 0.0, 0.0), 192.0, 1e-14);
    ASSERT_REL(grid_volume(&s, 3, 3, 0.0, 0.0), 192.0, 1e-14);

    /* faces on quarter-cell planes: exact from depth 2 */
    s = make_shape(VHE_BOX, 0.125, 0.0, 0.5);
    s.semi[0] = 2.125; s.semi[1] = 1.75; s.semi[2] = 1.5;
    ASSERT_REL(grid_volume(&s, 3, 2, 0.0, 0.0), 8.0 * 2.125 * 1.75 * 1.5,
               1e-14);
}
END_TEST

START_TEST(test_shape_box_exact)
{
    /*
     * A box's fraction is its clip of the cell, exact: a cell [0,1]^3 cut
     * by one face of a large turned box at x + y = 1, x + y + z = 1.5 and
     * x + y + z = 0.5 holds 1/2, 1/2 and the corner's 1/48 (to 1e-12: the
     * box's centre lies 100 away); a box turned
     * about two axes sums to its volume over a grid to round-off (the
     * plane leaf at depth 5: 1.1e-5).
     */
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    const double r2 = sqrt(0.5), r3 = sqrt(1.0 / 3.0);
    struct vhe_shape s = make_shape(VHE_BOX, 0, 0, 0);
    double Q[9], X[3], sum = 0.0;
    const double a = 0.3, b = 0.4;
    int i, j, k;
    s.semi[0] = s.semi[1] = s.semi[2] = 100.0;
    /* axis 0 of the box along (1, 1, 0)/sqrt(2), its face at x + y = 1 */
    {
        const double q[9] = {r2, -r2, 0, r2, r2, 0, 0, 0, 1};
        memcpy(Q, q, sizeof Q);
    }
    X[0] = X[1] = 0.5 - 100.0 * r2; X[2] = 0.5;
    ASSERT_NEAR(vhe_shape_fraction_posed(&s, Q, X, lo, hi, 3, 5), 0.5, 1e-12);
    /* axis 0 along (1, 1, 1)/sqrt(3): faces at x + y + z = 1.5 and 0.5 */
    {
        const double r6 = sqrt(1.0 / 6.0);
        const double q[9] = {r3, -r2, -r6, r3, r2, -r6, r3, 0, 2 * r6};
        memcpy(Q, q, sizeof Q);
    }
    for (k = 0; k < 3; ++k) X[k] = 0.5 - 100.0 * r3;
    ASSERT_NEAR(vhe_shape_fraction_posed(&s, Q, X, lo, hi, 3, 5), 0.5, 1e-12);
    for (k = 0; k < 3; ++k) X[k] = 0.5 / 3.0 - 100.0 * r3;
    ASSERT_NEAR(vhe_shape_fraction_posed(&s, Q, X, lo, hi, 3, 5),
                1.0 / 48.0, 1e-12);

    /* turned about z by a, then about x by b */
    {
        const double ca = cos(a), sa = sin(a), cb = cos(b), sb = sin(b);
        const double q[9] = {ca, -sa * cb, sa * sb, sa, ca * cb, -ca * sb,
                             0, sb, cb};
        memcpy(Q, q, sizeof Q);
    }
    s.semi[0] = 6.4; s.semi[1] = 3.2; s.semi[2] = 4.16;
    X[0] = 16.03; X[1] = 15.96; X[2] = 16.01;
    for (i = 0; i < 32; ++i) {
        for (j = 0; j < 32; ++j) {
            for (k = 0; k < 32; ++k) {
                const double cl[3] = {i, j, k};
                const double ch[3] = {i + 1.0, j + 1.0, k + 1.0};
                sum += vhe_shape_fraction_posed(&s, Q, X, cl, ch, 3, 5);
            }
        }
    }
    ASSERT_REL(sum, 8.0 * 6.4 * 3.2 * 4.16, 1e-13);
}
END_TEST

START_TEST(test_shape_cylinder_2d)
{
    /* infinite cylinder along z, 2D case: one layer of depth 0.1 */
    struct vhe_shape s = make_shape(VHE_CYLINDER, 0.2, 0.13, 7.0);
    const double depth = 0.1;
    s.radius = 8.3;
    s.half_length = 0.0;
    ASSERT_REL(vhe_shape_volume(&s), PI * 8.3 * 8.3, 1e-15);
    ASSERT_REL(grid_volume(&s, 2, 4, -0.05, depth), PI * 8.3 * 8.3 * depth,
               1e-3);
}
END_TEST

START_TEST(test_shape_cylinder_3d)
{
    /* finite, tilted: exercises the caps and the axis projection */
    struct vhe_shape s = make_shape(VHE_CYLINDER, 0.1, 0.2, 0.3);
    double exact;
    s.axis[0] = 1.0; s.axis[1] = 2.0; s.axis[2] = 2.0;  /* normalised: /3 */
    s.axis[0] /= 3.0; s.axis[1] /= 3.0; s.axis[2] /= 3.0;
    s.radius = 4.0;
    s.half_length = 6.0;
    exact = PI * 16.0 * 12.0;
    ASSERT_REL(vhe_shape_volume(&s), exact, 1e-15);
    ASSERT_REL(grid_volume(&s, 3, 4, 0.0, 0.0), exact, 1e-3);
}
END_TEST

START_TEST(test_shape_fraction_limits)
{
    struct vhe_shape s = make_shape(VHE_SPHERE, 0.0, 0.0, 0.0);
    const double lo[3] = {-0.5, -0.5, -0.5}, hi[3] = {0.5, 0.5, 0.5};
    const double flo[3] = {20.0, 0.0, 0.0}, fhi[3] = {21.0, 1.0, 1.0};
    s.radius = 5.0;
    ck_assert(vhe_shape_fraction(&s, lo, hi, 3, 6) == 1.0);
    ck_assert(vhe_shape_fraction(&s, flo, fhi, 3, 6) == 0.0);
    ck_assert(vhe_shape_fraction(&s, lo, hi, 2, 6) == 1.0);

    /* nearly plane surface x = 0.3 through the cell [0,1]^3 */
    s = make_shape(VHE_SPHERE, 0.3 - 1e6, 0.5, 0.5);
    s.radius = 1e6;
    {
        const double a[3] = {0, 0, 0}, b[3] = {1, 1, 1};
        ASSERT_NEAR(vhe_shape_fraction(&s, a, b, 3, 0), 0.3, 1e-6);
        ASSERT_NEAR(vhe_shape_fraction(&s, a, b, 3, 4), 0.3, 1e-6);
    }
    /* invalid shape: empty */
    s.radius = -1.0;
    ck_assert(vhe_shape_check(&s) == VHE_EBADARG);
    ck_assert(vhe_shape_fraction(&s, lo, hi, 3, 4) == 0.0);
    ck_assert(vhe_shape_volume(&s) == 0.0);
    ck_assert(vhe_shape_check(NULL) == VHE_EBADARG);
}
END_TEST

START_TEST(test_shape_crossing)
{
    /* Where a surface cuts a segment: exact at once across a box's face,
     * to 1e-9 across a sphere's and an ellipsoid's curved ones */
    const double Q[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    struct vhe_shape box = make_shape(VHE_BOX, 0, 0, 0);
    struct vhe_shape sph = make_shape(VHE_SPHERE, 0, 0, 0);
    struct vhe_shape ell = make_shape(VHE_ELLIPSOID, 0, 0, 0);
    double X[3] = {0, 0, 0}, xo[3], xi[3], x[3], t, f;
    int d;
    box.semi[0] = 1; box.semi[1] = 1; box.semi[2] = 1;
    sph.radius = 1.0;
    ell.semi[0] = 2; ell.semi[1] = 1; ell.semi[2] = 1;

    xo[0] = 1.3; xo[1] = 0.2; xo[2] = 0.1;   /* the face x = 1 at 0.6 */
    xi[0] = 0.8; xi[1] = 0.2; xi[2] = 0.1;
    t = vhe_shape_crossing(&box, Q, X, xo, xi,
                           vhe_shape_sdf_posed(&box, Q, X, xo),
                           vhe_shape_sdf_posed(&box, Q, X, xi));
    ASSERT_NEAR(t, 0.6, 1e-14);

    xo[0] = 1.2; xo[1] = 0.3; xo[2] = 0;     /* x = sqrt(1 - 0.09) */
    xi[0] = 0.7; xi[1] = 0.3; xi[2] = 0;
    t = vhe_shape_crossing(&sph, Q, X, xo, xi,
                           vhe_shape_sdf_posed(&sph, Q, X, xo),
                           vhe_shape_sdf_posed(&sph, Q, X, xi));
    ASSERT_NEAR(t, (1.2 - sqrt(0.91)) / 0.5, 1e-9);

    /* the ellipsoid's sdf is a bound, not a distance: the crossing is
     * still on its surface */
    xo[0] = 1.5; xo[1] = 0.9; xo[2] = 0;
    xi[0] = 1.0; xi[1] = 0.5; xi[2] = 0;
    t = vhe_shape_crossing(&ell, Q, X, xo, xi,
                           vhe_shape_sdf_posed(&ell, Q, X, xo),
                           vhe_shape_sdf_posed(&ell, Q, X, xi));
    for (d = 0; d < 3; ++d) {
        x[d] = xo[d] + t * (xi[d] - xo[d]);
    }
    f = x[0] * x[0] / 4 + x[1] * x[1] - 1;
    ASSERT_NEAR(f, 0.0, 1e-8);

    /* no crossing: 1 */
    ck_assert(vhe_shape_crossing(&sph, Q, X, xi, xo, -0.1, 0.2) == 1.0);
}
END_TEST

START_TEST(test_wall_linear_shear)
{
    /* Plane shear beside a wall anywhere in a cell: cells of width h on
     * [0, L], the wall at xw (a box's face), cells whose centres are inside
     * held at 0, u = s (L - xw) at x = L; the first fluid cell's wall
     * penalty mu vhe_wall_coefficient/V makes the discrete steady
     * diffusion reproduce u = s (x - xw) exactly.  Without it the error is
     * of the cell's order (checked too) */
    const double Q[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const int n = 10;
    const double L = 1.0, h = L / n, mu = 1.7, sl = 2.0;
    double xw;
    int pen;
    for (xw = 0.21; xw < 0.45; xw += 0.037) {
        for (pen = 1; pen >= 0; --pen) {
            struct vhe_shape wall = make_shape(VHE_BOX, xw - 5, 0, 0);
            double X[3], a[10], b[10], c[10], r[10], u[10], err = 0;
            int i;
            wall.semi[0] = 5; wall.semi[1] = 50; wall.semi[2] = 50;
            X[0] = wall.centre[0]; X[1] = 0; X[2] = 0;
            for (i = 0; i < n; ++i) {
                const double xc = (i + 0.5) * h;
                const double p[3] = {xc, 0, 0};
                a[i] = 0; b[i] = 0; c[i] = 0; r[i] = 0;
                if (vhe_shape_sdf_posed(&wall, Q, X, p) < 0) {
                    b[i] = 1;                        /* held at 0 */
                    continue;
                }
                /* unit area: V = h, faces' coefficient mu/h */
                a[i] = -mu / h;
                b[i] = 2 * mu / h;
                c[i] = -mu / h;
                if (i == n - 1) {                    /* u(L) at h/2 */
                    b[i] = mu / h + 2 * mu / h;
                    c[i] = 0;
                    r[i] = 2 * mu / h * sl * (L - xw);
                }
                if (i > 0 && b[i - 1] == 1 && a[i - 1] == 0) {
                    const double q[3] = {xc - h, 0, 0};
                    const double dl = vhe_shape_crossing
                    (
                        &wall, Q, X, p, q,
                        vhe_shape_sdf_posed(&wall, Q, X, p),
                        vhe_shape_sdf_posed(&wall, Q, X, q)
                    );
                    b[i] += pen * mu * vhe_wall_coefficient(1.0, h, dl);
                }
            }
            /* Thomas */
            for (i = 1; i < n; ++i) {
                const double m = a[i] / b[i - 1];
                b[i] -= m * c[i - 1];
                r[i] -= m * r[i - 1];
            }
            u[n - 1] = r[n - 1] / b[n - 1];
            for (i = n - 2; i >= 0; --i) {
                u[i] = (r[i] - c[i] * u[i + 1]) / b[i];
            }
            for (i = 0; i < n; ++i) {
                const double xc = (i + 0.5) * h;
                if (xc > xw) {
                    const double e = fabs(u[i] - sl * (xc - xw));
                    err = e > err ? e : err;
                }
            }
            if (pen) {
                ASSERT_NEAR(err, 0.0, 1e-12);
            } else {
                ck_assert(err > 1e-3 * sl * h);
            }
        }
    }
}
END_TEST

START_TEST(test_shape_sdf)
{
    /* exact values, and Lipschitz-1 with the right sign on random pairs */
    struct vhe_shape sh[5];
    uint64_t st = 12345;
    double x[3], y[3];
    int k, m;

    sh[0] = make_shape(VHE_SPHERE, 1, 2, 3);
    sh[0].radius = 2.0;
    sh[1] = make_shape(VHE_BOX, 0, 0, 0);
    sh[1].semi[0] = 1; sh[1].semi[1] = 2; sh[1].semi[2] = 3;
    sh[2] = make_shape(VHE_CYLINDER, 0, 0, 0);
    sh[2].axis[0] = 1; sh[2].axis[2] = 0;
    sh[2].radius = 1.0; sh[2].half_length = 2.0;
    sh[3] = make_shape(VHE_CYLINDER, 0, 0, 0);
    sh[3].radius = 1.5; sh[3].half_length = 0.0;
    sh[4] = make_shape(VHE_ELLIPSOID, 0.5, 0, 0);
    sh[4].semi[0] = 3; sh[4].semi[1] = 1; sh[4].semi[2] = 2;

    x[0] = 1; x[1] = 2; x[2] = 6;
    ASSERT_NEAR(vhe_shape_sdf(&sh[0], x), 1.0, 1e-15);
    x[0] = 4; x[1] = 6; x[2] = 0;      /* off a box edge: (3, 4) -> 5 */
    ASSERT_NEAR(vhe_shape_sdf(&sh[1], x), 5.0, 1e-15);
    x[0] = 0.5; x[1] = 0; x[2] = 0;    /* inside: nearest face x = 1 */
    ASSERT_NEAR(vhe_shape_sdf(&sh[1], x), -0.5, 1e-15);
    x[0] = 5; x[1] = 0; x[2] = 0;      /* beyond the cap of the x cylinder */
    ASSERT_NEAR(vhe_shape_sdf(&sh[2], x), 3.0, 1e-15);
    x[0] = 6; x[1] = 5; x[2] = 0;      /* off the rim: (4, 4) -> 4 sqrt 2 */
    ASSERT_NEAR(vhe_shape_sdf(&sh[2], x), 4.0 * sqrt(2.0), 1e-14);
    x[0] = 0.5; x[1] = 0.5; x[2] = 0;  /* inside: rim 0.5 away, cap 1.5 */
    ASSERT_NEAR(vhe_shape_sdf(&sh[2], x), -0.5, 1e-15);
    x[0] = 3; x[1] = 4; x[2] = 100;    /* infinite along z */
    ASSERT_NEAR(vhe_shape_sdf(&sh[3], x), 3.5, 1e-15);
    x[0] = 3.5; x[1] = 0; x[2] = 0;    /* ellipsoid surface point */
    ASSERT_NEAR(vhe_shape_sdf(&sh[4], x), 0.0, 1e-15);

    for (k = 0; k < 5; ++k) {
        for (m = 0; m < 2000; ++m) {
            double sx, sy, dxy;
            int d;
            for (d = 0; d < 3; ++d) {
                x[d] = -6.0 + 12.0 * vhe_rng_uniform(&st);
                y[d] = x[d] + (vhe_rng_uniform(&st) - 0.5);
            }
            sx = vhe_shape_sdf(&sh[k], x);
            sy = vhe_shape_sdf(&sh[k], y);
            dxy = sqrt((x[0] - y[0]) * (x[0] - y[0])
                       + (x[1] - y[1]) * (x[1] - y[1])
                       + (x[2] - y[2]) * (x[2] - y[2]));
            ck_assert_msg(fabs(sx - sy) <= dxy * (1.0 + 1e-12) + 1e-14,
                          "shape %d not Lipschitz-1", k);
        }
    }
    /* ellipsoid sign: inside the semi-axes box corner region is outside */
    x[0] = 0.5 + 2.9; x[1] = 0.9; x[2] = 1.9;
    ck_assert(vhe_shape_sdf(&sh[4], x) > 0.0);
    x[0] = 0.5 + 1.0; x[1] = 0.3; x[2] = 0.5;
    ck_assert(vhe_shape_sdf(&sh[4], x) < 0.0);
}
END_TEST

START_TEST(test_shape_bounds)
{
    struct vhe_shape s;
    double lo[3], hi[3];

    s = make_shape(VHE_SPHERE, 1, 2, 3);
    s.radius = 0.5;
    vhe_shape_bounds(&s, lo, hi);
    ASSERT_NEAR(lo[0], 0.5, 1e-15); ASSERT_NEAR(hi[2], 3.5, 1e-15);

    s = make_shape(VHE_ELLIPSOID, 0, 1, 0);
    s.semi[0] = 3; s.semi[1] = 1; s.semi[2] = 2;
    vhe_shape_bounds(&s, lo, hi);
    ASSERT_NEAR(lo[0], -3, 0); ASSERT_NEAR(lo[1], 0, 0);
    ASSERT_NEAR(hi[1], 2, 0); ASSERT_NEAR(hi[2], 2, 0);

    s = make_shape(VHE_BOX, 0, 0, 0);
    s.semi[0] = 1; s.semi[1] = 2; s.semi[2] = 3;
    vhe_shape_bounds(&s, lo, hi);
    ASSERT_NEAR(lo[2], -3, 0); ASSERT_NEAR(hi[1], 2, 0);

    /* cylinder tilted in xz at 45 deg: e_x = e_z = hl/sqrt2 + r/sqrt2,
     * e_y = r */
    s = make_shape(VHE_CYLINDER, 0, 0, 0);
    s.axis[0] = sqrt(0.5); s.axis[2] = sqrt(0.5);
    s.radius = 1.0; s.half_length = 3.0;
    vhe_shape_bounds(&s, lo, hi);
    ASSERT_NEAR(hi[0], 4.0 * sqrt(0.5), 1e-14);
    ASSERT_NEAR(lo[2], -4.0 * sqrt(0.5), 1e-14);
    ASSERT_NEAR(hi[1], 1.0, 1e-14);

    /* infinite along z */
    s.axis[0] = 0; s.axis[2] = 1; s.half_length = 0;
    vhe_shape_bounds(&s, lo, hi);
    ck_assert(lo[2] == -HUGE_VAL && hi[2] == HUGE_VAL);
    ASSERT_NEAR(hi[0], 1.0, 1e-15); ASSERT_NEAR(lo[1], -1.0, 1e-15);
}
END_TEST

static Suite *shapes_suite(void)
{
    Suite *s = suite_create("shapes");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_shape_sphere_volume);
    tcase_add_test(tc, test_shape_half_width);
    tcase_add_test(tc, test_shape_convergence);
    tcase_add_test(tc, test_shape_ellipsoid_volume);
    tcase_add_test(tc, test_shape_box_volume);
    tcase_add_test(tc, test_shape_box_exact);
    tcase_add_test(tc, test_shape_cylinder_2d);
    tcase_add_test(tc, test_shape_cylinder_3d);
    tcase_add_test(tc, test_shape_fraction_limits);
    tcase_add_test(tc, test_shape_sdf);
    tcase_add_test(tc, test_shape_crossing);
    tcase_add_test(tc, test_wall_linear_shear);
    tcase_add_test(tc, test_shape_bounds);
    suite_add_tcase(s, tc);
    return s;
}

/* ============================================================= packing */

START_TEST(test_rng)
{
    /* Reference values of splitmix64 (Vigna's splitmix64.c). */
    uint64_t st = 0;
    double sum = 0.0;
    int i;

    ck_assert(vhe_rng_next(&st) == UINT64_C(0xE220A8397B1DCDAF));
    st = 1234567;
    ck_assert(vhe_rng_next(&st) == UINT64_C(6457827717110365317));
    ck_assert(vhe_rng_next(&st) == UINT64_C(3203168211198807973));
    st = 99;
    for (i = 0; i < 100000; ++i) {
        const double u = vhe_rng_uniform(&st);
        ck_assert(u >= 0.0 && u < 1.0);
        sum += u;
    }
    /* mean 1/2, standard error 0.29/sqrt(1e5) ~ 9e-4 */
    ASSERT_NEAR(sum / 100000.0, 0.5, 5e-3);
}
END_TEST

START_TEST(test_pack_lattice)
{
    const double lo[3] = {0, 0, 0}, hi[3] = {4, 2, 1};
    const int n[3] = {4, 2, 1};
    double c[3 * 8];
    int r;

    r = vhe_pack_lattice(lo, hi, n, 0.4, 0.1, 3, c);
    ck_assert_int_eq(r, VHE_OK);
    /* x fastest: body 5 is (i, j) = (1, 1) */
    ASSERT_NEAR(c[0], 0.5, 1e-15); ASSERT_NEAR(c[1], 0.5, 1e-15);
    ASSERT_NEAR(c[2], 0.5, 1e-15);
    ASSERT_NEAR(c[15], 1.5, 1e-15); ASSERT_NEAR(c[16], 1.5, 1e-15);
    ASSERT_NEAR(c[21], 3.5, 1e-15); ASSERT_NEAR(c[22], 1.5, 1e-15);
    ck_assert(vhe_min_clearance(lo, hi, NULL, 3, 8, 0.4, c) >= 0.1);

    /* 2r + gap = 1.06 > spacing 1: too tight */
    ck_assert_int_eq(vhe_pack_lattice(lo, hi, n, 0.48, 0.1, 3, c),
                     VHE_ENOFIT);
    /* exact fit passes */
    ck_assert_int_eq(vhe_pack_lattice(lo, hi, n, 0.45, 0.1, 3, c), VHE_OK);
    /* 2D: a thin z layer does not count, z at mid */
    {
        const double hz[3] = {4, 2, 0.1};
        ck_assert_int_eq(vhe_pack_lattice(lo, hz, n, 0.4, 0.1, 3, c),
                         VHE_ENOFIT);
        ck_assert_int_eq(vhe_pack_lattice(lo, hz, n, 0.4, 0.1, 2, c),
                         VHE_OK);
        ASSERT_NEAR(c[2], 0.05, 1e-15);
        ASSERT_NEAR(c[23], 0.05, 1e-15);
    }
    ck_assert_int_eq(vhe_pack_lattice(lo, hi, n, -1.0, 0.1, 3, c),
                     VHE_EBADARG);
}
END_TEST

/* Brute-force clearance over all 27 periodic images (independent of the
 * minimum-image code under test). */
static double brute_clearance(const double *lo, const double *hi,
                              const int *per, int nd, size_t n, double r,
                              const double *c)
{
    double m = HUGE_VAL;
    size_t i, j;
    int a, b, e;

    for (i = 0; i < n; ++i) {
        for (j = i + 1; j < n; ++j) {
            for (a = -1; a <= 1; ++a) {
                for (b = -1; b <= 1; ++b) {
                    for (e = -1; e <= 1; ++e) {
                        const int sh[3] = {a, b, e};
                        double s = 0.0;
                        int d, skip = 0;
                        for (d = 0; d < nd; ++d) {
                            double x;
                            if (sh[d] != 0 && !per[d]) {
                                skip = 1;
                            }
                            x = c[3 * i + d] - c[3 * j + d]
                                + sh[d] * (hi[d] - lo[d]);
                            s += x * x;
                        }
                        if (nd == 2 && e != 0) {
                            skip = 1;
                        }
                        if (!skip && sqrt(s) - 2.0 * r < m) {
                            m = sqrt(s) - 2.0 * r;
                        }
                    }
                }
            }
        }
    }
    return m;
}

START_TEST(test_pack_random_3d)
{
    const double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};
    const int per[3] = {1, 1, 0};
    const double r = 0.6, gap = 0.05;
    double c[3 * 80], c2[3 * 80];
    size_t placed = 0, i;
    int rc, crossing = 0;

    rc = vhe_pack_random(lo, hi, per, 3, 80, r, gap, 42, 100000, c, &placed);
    ck_assert_int_eq(rc, VHE_OK);
    ck_assert_uint_eq(placed, 80);
    ck_assert(vhe_min_clearance(lo, hi, per, 3, 80, r, c) >= gap - 1e-12);
    ck_assert(brute_clearance(lo, hi, per, 3, 80, r, c) >= gap - 1e-12);
    /* the minimum-image and the brute-force clearances agree */
    ASSERT_NEAR(vhe_min_clearance(lo, hi, per, 3, 80, r, c),
                brute_clearance(lo, hi, per, 3, 80, r, c), 1e-12);
    for (i = 0; i < 80; ++i) {
        /* walls in z: clearance gap */
        ck_assert(c[3 * i + 2] >= r + gap - 1e-12);
        ck_assert(c[3 * i + 2] <= 10.0 - r - gap + 1e-12);
        ck_assert(c[3 * i] >= 0.0 && c[3 * i] < 10.0);
        if (c[3 * i] < r || c[3 * i] > 10.0 - r || c[3 * i + 1] < r
            || c[3 * i + 1] > 10.0 - r) {
            ++crossing;
        }
    }
    /* some bodies do cross the periodic boundaries */
    ck_assert_int_gt(crossing, 0);

    /* reproducible from the seed */
    rc = vhe_pack_random(lo, hi, per, 3, 80, r, gap, 42, 100000, c2, &placed);
    ck_assert_int_eq(rc, VHE_OK);
    ck_assert(memcmp(c, c2, sizeof c) == 0);
    rc = vhe_pack_random(lo, hi, per, 3, 80, r, gap, 43, 100000, c2, &placed);
    ck_assert_int_eq(rc, VHE_OK);
    ck_assert(max_diff(c, c2, 3 * 80) > 0.1);
}
END_TEST

START_TEST(test_pack_random_nofit)
{
    /* 200 spheres of r = 1 (volume 838) in a 10^3 box with walls: the
     * random jamming limit (~38% of the reduced box) is far below that */
    const double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};
    const int per[3] = {0, 0, 0};
    static double c[3 * 200];
    size_t placed = 0;
    int rc;

    rc = vhe_pack_random(lo, hi, per, 3, 200, 1.0, 0.0, 7, 20000, c, &placed);
    ck_assert_int_eq(rc, VHE_ENOFIT);
    ck_assert_uint_lt(placed, 200);
    ck_assert_uint_gt(placed, 10);
    ck_assert(vhe_min_clearance(lo, hi, per, 3, placed, 1.0, c) >= -1e-12);

    /* a periodic direction shorter than 2r + gap: nothing fits */
    {
        const double h2[3] = {10, 10, 1.5};
        const int p2[3] = {0, 0, 1};
        rc = vhe_pack_random(lo, h2, p2, 3, 1, 1.0, 0.0, 7, 100, c, &placed);
        ck_assert_int_eq(rc, VHE_ENOFIT);
        ck_assert_uint_eq(placed, 0);
    }
}
END_TEST

START_TEST(test_pack_random_2d)
{
    const double lo[3] = {0, 0, -0.05}, hi[3] = {6, 4, 0.15};
    const int per[3] = {1, 0, 0};
    const double r = 0.3, gap = 0.02;
    double c[3 * 25];
    size_t placed = 0, i;
    int rc;

    rc = vhe_pack_random(lo, hi, per, 2, 25, r, gap, 2024, 100000, c,
                         &placed);
    ck_assert_int_eq(rc, VHE_OK);
    for (i = 0; i < 25; ++i) {
        ck_assert(c[3 * i + 2] == 0.5 * (lo[2] + hi[2]));
        ck_assert(c[3 * i + 1] >= r + gap - 1e-12);
    }
    ck_assert(vhe_min_clearance(lo, hi, per, 2, 25, r, c) >= gap - 1e-12);
    ck_assert(brute_clearance(lo, hi, per, 2, 25, r, c) >= gap - 1e-12);
}
END_TEST

static Suite *packing_suite(void)
{
    Suite *s = suite_create("packing");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_rng);
    tcase_add_test(tc, test_pack_lattice);
    tcase_add_test(tc, test_pack_random_3d);
    tcase_add_test(tc, test_pack_random_nofit);
    tcase_add_test(tc, test_pack_random_2d);
    suite_add_tcase(s, tc);
    return s;
}

/* =============================================================== exact */

START_TEST(test_poiseuille)
{
    const double f = 0.5, nu = 1e-3, h = 0.02;
    const int m = 100;   /* Simpson is exact for the parabola */
    double q = 0.0;
    int i;

    for (i = 0; i <= m; ++i) {
        const double w = (i == 0 || i == m) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        q += w * vhe_poiseuille_u(f, nu, h, h * i / m);
    }
    q *= h / m / 3.0;
    ASSERT_REL(q, vhe_poiseuille_q(f, nu, h), 1e-12);
    ASSERT_REL(vhe_poiseuille_q(f, nu, h), f * h * h * h / (12.0 * nu), 1e-15);
    ck_assert(vhe_poiseuille_u(f, nu, h, 0.0) == 0.0);
    ASSERT_NEAR(vhe_poiseuille_u(f, nu, h, h), 0.0, 1e-15);
    /* centreline f h^2 / (8 nu), and nu u'' = -f by central differences */
    ASSERT_REL(vhe_poiseuille_u(f, nu, h, h / 2), f * h * h / (8.0 * nu),
               1e-15);
    {
        const double y = 0.3 * h, dy = 1e-3 * h;
        const double d2 = (vhe_poiseuille_u(f, nu, h, y + dy)
                           - 2.0 * vhe_poiseuille_u(f, nu, h, y)
                           + vhe_poiseuille_u(f, nu, h, y - dy)) / (dy * dy);
        ASSERT_REL(nu * d2, -f, 1e-5);
    }
}
END_TEST

START_TEST(test_couette_reference)
{
    /* REFERENCE.md check values: solid 0 < y < 0.5 (mu 0, G 5) under fluid
     * 0.5 < y < 1 (mu 1), rho 1, V 1, w pi; wall at rest at y = 0. */
    const double h[2] = {0.5, 0.5}, rho[2] = {1, 1}, mu[2] = {0, 1};
    const double G[2] = {5, 0};
    const double t2[11] = {0, .0923, .1827, .2695, .3511, .4257, .2947,
                           .1836, .0956, .0335, 0};
    const double t28[11] = {0, -.0072, -.0142, -.0209, -.0273, -.0331,
                            .1355, .2825, .4074, .5095, .5878};
    struct vhe_couette c;
    double re, im, u;
    int i;

    ck_assert_int_eq(vhe_couette_setup(&c, 2, h, rho, mu, G, 1.0, PI),
                     VHE_OK);
    vhe_couette_interface(&c, 0, &re, &im);
    ASSERT_NEAR(re, 0.52966, 6e-6);
    ASSERT_NEAR(im, 0.42569, 6e-6);
    for (i = 0; i <= 10; ++i) {
        vhe_couette_eval(&c, 0.1 * i, 2.0, &u, NULL);
        ASSERT_NEAR(u, t2[i], 6e-5);
        vhe_couette_eval(&c, 0.1 * i, 2.8, &u, NULL);
        ASSERT_NEAR(u, t28[i], 6e-5);
    }
}
END_TEST

START_TEST(test_couette_pde)
{
    /* fluid / solid / fluid (Parthasarathy et al. 2022 parameters): the
     * solution satisfies rho du/dt = d/dy (mu du/dy + G gamma), with
     * velocity and shear stress continuous at the interfaces. */
    const double h[3] = {0.2, 0.2, 0.2}, rho[3] = {1, 1, 1};
    const double mu[3] = {0.02, 0.002, 0.02}, G[3] = {0, 0.02, 0};
    const double w = PI, t = 0.37, d = 1e-4;
    struct vhe_couette c;
    double y, u0, u1, um, up, g0, gm, gp, ua, ub, ga, gb, top;

    ck_assert_int_eq(vhe_couette_setup(&c, 3, h, rho, mu, G, 0.4, w), VHE_OK);
    for (y = 0.05; y < 0.6; y += 0.1) {
        const int j = y < 0.2 ? 0 : (y < 0.4 ? 1 : 2);
        vhe_couette_eval(&c, y, t - d, &u0, NULL);
        vhe_couette_eval(&c, y, t + d, &u1, NULL);
        vhe_couette_eval(&c, y - d, t, &um, &gm);
        vhe_couette_eval(&c, y + d, t, &up, &gp);
        vhe_couette_eval(&c, y, t, &ua, &g0);
        /* rho du/dt against d/dy(mu du/dy + G gamma), central differences */
        ASSERT_NEAR(rho[j] * (u1 - u0) / (2 * d),
                    mu[j] * (up - 2 * ua + um) / (d * d)
                    + G[j] * (gp - gm) / (2 * d), 2e-4);
    }
    /* interface y = 0.2: velocity and stress continuous */
    vhe_couette_eval(&c, 0.2 - 1e-9, t, &ua, &ga);
    vhe_couette_eval(&c, 0.2 + 1e-9, t, &ub, &gb);
    ASSERT_NEAR(ua, ub, 1e-8);
    vhe_couette_eval(&c, 0.2 - 2e-5, t, &um, NULL);
    vhe_couette_eval(&c, 0.2 + 2e-5, t, &up, NULL);
    ASSERT_NEAR(mu[0] * (ua - um) / 2e-5,
                mu[1] * (up - ub) / 2e-5 + G[1] * gb, 2e-5);
    /* the moving wall */
    vhe_couette_eval(&c, 0.6, t, &top, NULL);
    ASSERT_NEAR(top, 0.4 * sin(w * t), 1e-12);
    vhe_couette_eval(&c, 0.0, t, &top, NULL);
    ASSERT_NEAR(top, 0.0, 1e-14);
    ck_assert_int_eq(vhe_couette_setup(&c, 0, h, rho, mu, G, 1, w),
                     VHE_EBADARG);
}
END_TEST

static Suite *exact_suite(void)
{
    Suite *s = suite_create("exact");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_poiseuille);
    tcase_add_test(tc, test_couette_reference);
    tcase_add_test(tc, test_couette_pde);
    suite_add_tcase(s, tc);
    return s;
}

/* ================================================================ main */

Suite *logb_suite(void);   /* test_logb.c */
Suite *bodies_suite(void); /* test_bodies.c */
Suite *contact_suite(void); /* test_contact.c */
Suite *shares_suite(void);  /* test_shares.c */
Suite *tension_suite(void); /* test_tension.c */
Suite *anderson_suite(void); /* test_anderson.c */
Suite *bound_suite(void); /* test_bound.c */
Suite *cut_suite(void); /* test_cut.c */
Suite *drain_suite(void); /* test_drain.c */
Suite *sweep_suite(void); /* test_sweep.c */

int main(void)
{
    SRunner *sr = srunner_create(mixture_suite());
    int nf;

    srunner_add_suite(sr, stretch_suite());
    srunner_add_suite(sr, symm_suite());
    srunner_add_suite(sr, shapes_suite());
    srunner_add_suite(sr, packing_suite());
    srunner_add_suite(sr, exact_suite());
    srunner_add_suite(sr, logb_suite());
    srunner_add_suite(sr, bodies_suite());
    srunner_add_suite(sr, contact_suite());
    srunner_add_suite(sr, shares_suite());
    srunner_add_suite(sr, tension_suite());
    srunner_add_suite(sr, anderson_suite());
    srunner_add_suite(sr, bound_suite());
    srunner_add_suite(sr, cut_suite());
    srunner_add_suite(sr, drain_suite());
    srunner_add_suite(sr, sweep_suite());
    srunner_run_all(sr, CK_NORMAL);
    nf = srunner_ntests_failed(sr);
    srunner_free(sr);
    return nf == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
