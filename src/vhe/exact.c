/*
 * exact.c -- analytic solutions used by the verification tests.
 */
#include "vhe.h"

#include <complex.h>
#include <math.h>

/*
 * Plane Poiseuille flow between walls y = 0 and y = h driven by a body
 * force f per unit mass [m/s^2], kinematic viscosity nu [m^2/s]:
 * nu u'' = -f with u(0) = u(h) = 0.  Returns u [m/s].
 */
double vhe_poiseuille_u(double f, double nu, double h, double y)
{
    return f / (2.0 * nu) * y * (h - y);
}

/* Flow rate per unit depth [m^2/s]: int_0^h u dy = f h^3 / (12 nu). */
double vhe_poiseuille_q(double f, double nu, double h)
{
    return f * h * h * h / (12.0 * nu);
}

/*
 * Oscillating Couette flow through layers: shoot from the wall at rest
 * with Vh = 0 and unit shear stress, carry velocity and stress mu* Vh'
 * across each interface, and scale so that Vh = V at the moving wall
 * (the problem is linear).
 */
int vhe_couette_setup(struct vhe_couette *c, int n, const double *h,
                      const double *rho, const double *mu, const double *G,
                      double V, double w)
{
    double complex a[VHE_COUETTE_MAX_LAYERS], b[VHE_COUETTE_MAX_LAYERS];
    double complex k[VHE_COUETTE_MAX_LAYERS];
    double complex v = 0.0, tau = 1.0, scale;
    int j;

    if (!c || n < 1 || n > VHE_COUETTE_MAX_LAYERS || !(w > 0.0)) {
        return VHE_EBADARG;
    }
    c->n = n;
    c->w = w;
    c->y0[0] = 0.0;
    for (j = 0; j < n; ++j) {
        /* mu* = mu + G/(i w): the solid's elasticity as an imaginary
         * viscosity in the periodic state */
        const double complex mustar = mu[j] + G[j] / (I * w);
        if (!(h[j] > 0.0) || !(rho[j] > 0.0) || mu[j] < 0.0 || G[j] < 0.0
            || cabs(mustar) == 0.0) {
            return VHE_EBADARG;
        }
        k[j] = csqrt(I * w * rho[j] / mustar);
        /* Vh(y0) = v, mu* Vh'(y0) = tau */
        a[j] = v;
        b[j] = tau / (mustar * k[j]);
        v = a[j] * ccosh(k[j] * h[j]) + b[j] * csinh(k[j] * h[j]);
        tau = mustar * k[j] * (a[j] * csinh(k[j] * h[j])
                               + b[j] * ccosh(k[j] * h[j]));
        c->y0[j + 1] = c->y0[j] + h[j];
    }
    scale = V / v;
    for (j = 0; j < n; ++j) {
        a[j] *= scale;
        b[j] *= scale;
        c->k_re[j] = creal(k[j]); c->k_im[j] = cimag(k[j]);
        c->a_re[j] = creal(a[j]); c->a_im[j] = cimag(a[j]);
        c->b_re[j] = creal(b[j]); c->b_im[j] = cimag(b[j]);
    }
    return VHE_OK;
}

static int couette_layer(const struct vhe_couette *c, double y)
{
    int j = 0;
    while (j < c->n - 1 && y > c->y0[j + 1]) {
        ++j;
    }
    return j;
}

void vhe_couette_eval(const struct vhe_couette *c, double y, double t,
                      double *u, double *gamma)
{
    const int j = couette_layer(c, y);
    const double complex k = c->k_re[j] + I * c->k_im[j];
    const double complex a = c->a_re[j] + I * c->a_im[j];
    const double complex b = c->b_re[j] + I * c->b_im[j];
    const double complex s = k * (y - c->y0[j]);
    const double complex e = cexp(I * c->w * t);

    if (u) {
        *u = cimag((a * ccosh(s) + b * csinh(s)) * e);
    }
    if (gamma) {
        /* d gamma/dt = du/dy */
        const double complex dv = k * (a * csinh(s) + b * ccosh(s));
        *gamma = cimag(dv / (I * c->w) * e);
    }
}

void vhe_couette_interface(const struct vhe_couette *c, int j,
                           double *re, double *im)
{
    const double complex k = c->k_re[j] + I * c->k_im[j];
    const double complex a = c->a_re[j] + I * c->a_im[j];
    const double complex b = c->b_re[j] + I * c->b_im[j];
    const double complex s = k * (c->y0[j + 1] - c->y0[j]);
    const double complex v = a * ccosh(s) + b * csinh(s);
    *re = creal(v);
    *im = cimag(v);
}

/* ------------------------------------------------------ prescribed flows */

#define VHE_FLOW_PI 3.14159265358979323846

double vhe_flow_psi(const struct vhe_flow *f, const double x[3], double t)
{
    switch (f->kind) {
    case VHE_FLOW_TRANSLATION:
        return f->U[0] * x[1] - f->U[1] * x[0];
    case VHE_FLOW_ROTATION: {
        const double dx = x[0] - f->origin[0], dy = x[1] - f->origin[1];
        return -0.5 * f->omega * (dx * dx + dy * dy);
    }
    case VHE_FLOW_SINGLE_VORTEX: {
        const double sx = sin(VHE_FLOW_PI * x[0]), sy = sin(VHE_FLOW_PI * x[1]);
        return sx * sx * sy * sy * cos(VHE_FLOW_PI * t / f->period)
               / VHE_FLOW_PI;
    }
    default:
        return 0.0;
    }
}

void vhe_flow_u(const struct vhe_flow *f, const double x[3], double t,
                double u[3])
{
    u[0] = u[1] = u[2] = 0.0;
    switch (f->kind) {
    case VHE_FLOW_TRANSLATION:
        u[0] = f->U[0];
        u[1] = f->U[1];
        break;
    case VHE_FLOW_ROTATION:
        u[0] = -f->omega * (x[1] - f->origin[1]);
        u[1] = f->omega * (x[0] - f->origin[0]);
        break;
    case VHE_FLOW_SINGLE_VORTEX: {
        const double c = cos(VHE_FLOW_PI * t / f->period);
        const double sx = sin(VHE_FLOW_PI * x[0]), sy = sin(VHE_FLOW_PI * x[1]);
        u[0] = sx * sx * sin(2.0 * VHE_FLOW_PI * x[1]) * c;
        u[1] = -sy * sy * sin(2.0 * VHE_FLOW_PI * x[0]) * c;
        break;
    }
    default:
        break;
    }
}
