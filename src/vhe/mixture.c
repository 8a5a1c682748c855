/*
 * mixture.c -- mixture properties, elastic stress, elastic wave speed and
 * stable elastic time step, energy densities.
 *
 * All kernels are pointwise loops over caller-owned arrays (see vhe.h for
 * the layouts).  SI units throughout.
 */
#include "vhe.h"

#include <math.h>

/*
 * phi_s^(1/2) with phi_s clipped to [0, 1]: a transported fraction may
 * overshoot by round-off, and sqrt of a tiny negative number must not
 * produce a NaN that would spread through the stress.
 */
static double sqrt_phis(double p)
{
    if (!(p > 0.0)) {
        return 0.0;
    }
    return p < 1.0 ? sqrt(p) : 1.0;
}

void vhe_mixture(size_t n, int nphase, const double *const *alpha,
                 const double *rho_k, const double *mu_k, const double *G_k,
                 const int *is_solid, const int *is_rigid, double phis_min,
                 double *rho, double *mu, double *phis, double *Ghat)
{
    size_t c;
    int k;

    if (alpha == NULL || nphase <= 0) {
        return;
    }
    for (c = 0; c < n; ++c) {
        double r = 0.0;    /* [kg/m^3] */
        double m = 0.0;    /* [Pa s] */
        double s = 0.0;    /* solid fraction, unclipped */
        double sG = 0.0;   /* sum_solids alpha_m G_m [Pa] */
        double fr = 0.0;   /* the rigid phases' fraction */
        double f = 0.0, mf = 0.0;   /* the others', round-off below 0 out */
        double sc;

        for (k = 0; k < nphase; ++k) {
            const double a = alpha[k][c];
            if (rho_k != NULL) {
                r += a * rho_k[k];
            }
            if (is_rigid != NULL && is_rigid[k]) {
                fr += a;
            } else if (mu_k != NULL) {
                m += a * mu_k[k];
                mf += (a > 0.0 ? a : 0.0) * mu_k[k];
                f += a > 0.0 ? a : 0.0;
            }
            if (is_solid != NULL && is_solid[k]) {
                s += a;
                if (G_k != NULL) {
                    sG += a * G_k[k];
                }
            }
        }
        sc = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
        if (rho != NULL) {
            rho[c] = r;
        }
        if (mu != NULL) {
            if (!(fr > 0.0)) {
                mu[c] = m;
            } else {
                /* the other phases' mean over their own fraction (3/4
                 * of the cell or more), from the fractions above 0 */
                mu[c] = fr < VHE_RIGID_HELD && f > 0.0 ? mf / f : -1.0;
            }
        }
        if (phis != NULL) {
            phis[c] = sc;
        }
        if (Ghat != NULL) {
            /*
             * The solid-weighted mean modulus: divide by the unclipped sum so
             * Ghat stays between the smallest and largest G_m even when the
             * fractions overshoot by round-off.
             */
            Ghat[c] = (sc > phis_min && s > 0.0) ? sG / s : 0.0;
        }
    }
}

double vhe_body_weight(double phis)
{
    const double w = (phis - 0.25) / 0.5;   /* 0 at 1/4, 1 at 3/4 */
    return w < 0.0 ? 0.0 : (w > 1.0 ? 1.0 : w);
}

void vhe_elastic_stress(size_t n, const double *Ghat, const double *phis,
                        const double *Bstar, double phis_min, double *sigma)
{
    size_t c;

    for (c = 0; c < n; ++c) {
        const double *B = Bstar + 6 * c;
        double *S = sigma + 6 * c;
        double f, tr3;

        if (!(phis[c] > phis_min)) {
            S[0] = S[1] = S[2] = S[3] = S[4] = S[5] = 0.0;
            continue;
        }
        /* w Ghat phi_s^(1/2) [Pa] times the dimensionless dev(B*). */
        f = vhe_body_weight(phis[c]) * Ghat[c] * sqrt_phis(phis[c]);
        tr3 = (B[0] + B[3] + B[5]) / 3.0;
        S[0] = f * (B[0] - tr3);
        S[1] = f * B[1];
        S[2] = f * B[2];
        S[3] = f * (B[3] - tr3);
        S[4] = f * B[4];
        S[5] = f * (B[5] - tr3);
    }
}

void vhe_wave_speed(size_t n, const double *Ghat, const double *phis,
                    const double *rho, double *c)
{
    size_t i;

    for (i = 0; i < n; ++i) {
        /* Effective shear modulus of the mixture Ghat phi_s [Pa]. */
        const double G = Ghat[i] * phis[i];
        c[i] = (G > 0.0 && rho[i] > 0.0) ? sqrt(G / rho[i]) : 0.0;
    }
}

double vhe_elastic_dt(size_t n, const double *Ghat, const double *phis,
                      const double *rho, const double *sumMagSfByV,
                      double maxCo, double dt, double *courant_out)
{
    /* kmax = max_c 0.5 c sum|Sf|/V [1/s]: Co_e = dt kmax. */
    double kmax = 0.0;
    size_t i;

    for (i = 0; i < n; ++i) {
        const double G = Ghat[i] * phis[i];
        if (G > 0.0 && rho[i] > 0.0) {
            const double k = 0.5 * sqrt(G / rho[i]) * sumMagSfByV[i];
            if (k > kmax) {
                kmax = k;
            }
        }
    }
    if (courant_out != NULL) {
        *courant_out = dt * kmax;
    }
    return kmax > 0.0 ? maxCo / kmax : HUGE_VAL;
}

void vhe_kinetic_energy(size_t n, const double *rho, const double *U,
                        double *e)
{
    size_t i;

    for (i = 0; i < n; ++i) {
        const double *u = U + 3 * i;
        e[i] = 0.5 * rho[i] * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    }
}

void vhe_elastic_energy(size_t n, const double *Ghat, const double *phis,
                        const double *Bstar, double *e)
{
    size_t i;

    for (i = 0; i < n; ++i) {
        const double *B = Bstar + 6 * i;
        const double sp = sqrt_phis(phis[i]);
        /*
         * Neo-Hookean W = G/2 (tr B - 3) per unit solid volume, times phi_s:
         * phi_s^(1/2) tr(B*) = phi_s tr(B).  Uses sp^2 (the clipped phi_s)
         * so that B* = phi_s^(1/2) I gives exactly zero.
         */
        e[i] = 0.5 * Ghat[i] * (sp * (B[0] + B[3] + B[5]) - 3.0 * sp * sp);
    }
}
