/*
 * exact.c -- analytic solutions used by the verification tests.
 */
#include "vhe.h"

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
