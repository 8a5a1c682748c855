/*
 * shapes.c -- signed distance, volume, cell volume fraction and bounding
 * box of the body shapes.  Lengths in m.
 */
#include "vhe.h"

#include <math.h>

#define VHE_PI 3.14159265358979323846

/* Deepest refinement vhe_shape_fraction honours (2^-24 of a cell edge is
 * far below any use; the bound sizes the explicit stack). */
#define VHE_FRACTION_DEPTH_CAP 24

static int finite3(const double *v)
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

int vhe_shape_check(const struct vhe_shape *s)
{
    if (s == NULL || !finite3(s->centre)) {
        return VHE_EBADARG;
    }
    switch (s->kind) {
    case VHE_SPHERE:
        return (isfinite(s->radius) && s->radius > 0.0) ? VHE_OK
                                                         : VHE_EBADARG;
    case VHE_CYLINDER: {
        double a2;
        if (!(isfinite(s->radius) && s->radius > 0.0) || !finite3(s->axis)
            || s->half_length != s->half_length
            || s->half_length == HUGE_VAL) {
            return VHE_EBADARG;
        }
        a2 = s->axis[0] * s->axis[0] + s->axis[1] * s->axis[1]
             + s->axis[2] * s->axis[2];
        return a2 > 0.0 ? VHE_OK : VHE_EBADARG;
    }
    case VHE_BOX:
    case VHE_ELLIPSOID:
        return (finite3(s->semi) && s->semi[0] > 0.0 && s->semi[1] > 0.0
                && s->semi[2] > 0.0) ? VHE_OK : VHE_EBADARG;
    default:
        return VHE_EBADARG;
    }
}

/* Unit cylinder axis (the contract asks for a unit vector; normalising
 * here makes a slightly denormalised input harmless). */
static void unit_axis(const struct vhe_shape *s, double a[3])
{
    const double n = sqrt(s->axis[0] * s->axis[0] + s->axis[1] * s->axis[1]
                          + s->axis[2] * s->axis[2]);
    a[0] = s->axis[0] / n;
    a[1] = s->axis[1] / n;
    a[2] = s->axis[2] / n;
}

double vhe_shape_sdf(const struct vhe_shape *s, const double x[3])
{
    double d[3];

    if (vhe_shape_check(s) != VHE_OK) {
        return HUGE_VAL;   /* an invalid shape contains nothing */
    }
    d[0] = x[0] - s->centre[0];
    d[1] = x[1] - s->centre[1];
    d[2] = x[2] - s->centre[2];

    switch (s->kind) {
    case VHE_SPHERE:
        return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - s->radius;

    case VHE_CYLINDER: {
        double a[3], t, r[3], rho, dr, da;
        unit_axis(s, a);
        t = d[0] * a[0] + d[1] * a[1] + d[2] * a[2];
        r[0] = d[0] - t * a[0];
        r[1] = d[1] - t * a[1];
        r[2] = d[2] - t * a[2];
        rho = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
        dr = rho - s->radius;
        if (!(s->half_length > 0.0)) {
            return dr;   /* infinite: exact distance to the mantle */
        }
        /* Capped cylinder, exact: a 2D box in (rho, |t|). */
        da = fabs(t) - s->half_length;
        return fmin(fmax(dr, da), 0.0)
               + hypot(fmax(dr, 0.0), fmax(da, 0.0));
    }

    case VHE_BOX: {
        double q[3], o = 0.0, in;
        int i;
        for (i = 0; i < 3; ++i) {
            q[i] = fabs(d[i]) - s->semi[i];
            if (q[i] > 0.0) {
                o += q[i] * q[i];
            }
        }
        in = fmin(fmax(q[0], fmax(q[1], q[2])), 0.0);
        return sqrt(o) + in;   /* exact inside and outside */
    }

    case VHE_ELLIPSOID: {
        /*
         * f(x) = |A^{-1}(x - c)| - 1 has |grad f| <= 1/min(semi), so
         * min(semi) f is Lipschitz-1 and a lower bound of the distance,
         * with the right sign (exact for a sphere).
         */
        const double y0 = d[0] / s->semi[0], y1 = d[1] / s->semi[1],
                     y2 = d[2] / s->semi[2];
        const double m = fmin(s->semi[0], fmin(s->semi[1], s->semi[2]));
        return m * (sqrt(y0 * y0 + y1 * y1 + y2 * y2) - 1.0);
    }
    default:
        return HUGE_VAL;
    }
}

double vhe_shape_volume(const struct vhe_shape *s)
{
    if (vhe_shape_check(s) != VHE_OK) {
        return 0.0;
    }
    switch (s->kind) {
    case VHE_SPHERE:
        return 4.0 / 3.0 * VHE_PI * s->radius * s->radius * s->radius;
    case VHE_CYLINDER: {
        const double area = VHE_PI * s->radius * s->radius;
        /* Infinite: the cross-section area, i.e. volume per unit length. */
        return s->half_length > 0.0 ? area * 2.0 * s->half_length : area;
    }
    case VHE_BOX:
        return 8.0 * s->semi[0] * s->semi[1] * s->semi[2];
    case VHE_ELLIPSOID:
        return 4.0 / 3.0 * VHE_PI * s->semi[0] * s->semi[1] * s->semi[2];
    default:
        return 0.0;
    }
}

void vhe_shape_bounds(const struct vhe_shape *s, double lo[3], double hi[3])
{
    double e[3] = {0.0, 0.0, 0.0};
    int i;

    if (vhe_shape_check(s) != VHE_OK) {
        /* Empty box. */
        for (i = 0; i < 3; ++i) {
            lo[i] = HUGE_VAL;
            hi[i] = -HUGE_VAL;
        }
        return;
    }
    switch (s->kind) {
    case VHE_SPHERE:
        e[0] = e[1] = e[2] = s->radius;
        break;
    case VHE_CYLINDER: {
        double a[3];
        unit_axis(s, a);
        for (i = 0; i < 3; ++i) {
            /* The end disk reaches r sqrt(1 - a_i^2) off the axis in i. */
            const double disk = s->radius * sqrt(fmax(0.0, 1.0 - a[i] * a[i]));
            if (s->half_length > 0.0) {
                e[i] = s->half_length * fabs(a[i]) + disk;
            } else {
                e[i] = a[i] != 0.0 ? HUGE_VAL : disk;
            }
        }
        break;
    }
    case VHE_BOX:
    case VHE_ELLIPSOID:
        e[0] = s->semi[0];
        e[1] = s->semi[1];
        e[2] = s->semi[2];
        break;
    default:
        break;
    }
    for (i = 0; i < 3; ++i) {
        if (e[i] == HUGE_VAL) {
            lo[i] = -HUGE_VAL;
            hi[i] = HUGE_VAL;
        } else {
            lo[i] = s->centre[i] - e[i];
            hi[i] = s->centre[i] + e[i];
        }
    }
}

/* The point of the shape as given that a pose carries to x: centre +
 * Q^T (x - X); no pose (Q NULL): x itself. */
static void unpose(const struct vhe_shape *s, const double *Q,
                   const double *X, const double x[3], double y[3])
{
    int i;
    if (Q == NULL) {
        y[0] = x[0];
        y[1] = x[1];
        y[2] = x[2];
        return;
    }
    for (i = 0; i < 3; ++i) {
        y[i] = s->centre[i] + Q[i] * (x[0] - X[0]) + Q[3 + i] * (x[1] - X[1])
               + Q[6 + i] * (x[2] - X[2]);
    }
}

static double fraction(const struct vhe_shape *s, const double *Q,
                       const double *X, const double lo[3],
                       const double hi[3], int ndim, int max_depth);

double vhe_shape_sdf_posed(const struct vhe_shape *s, const double Q[9],
                           const double X[3], const double x[3])
{
    double y[3];
    if (Q == NULL || X == NULL) {
        return HUGE_VAL;
    }
    unpose(s, Q, X, x, y);
    return vhe_shape_sdf(s, y);
}

double vhe_shape_crossing(const struct vhe_shape *s, const double Q[9],
                          const double X[3], const double xo[3],
                          const double xi[3], double so, double si)
{
    double a = 0.0, z = 1.0, t, len2 = 0.0;
    int it, d, side = 0;
    if (!(so > 0.0) || !(si < 0.0)) {
        return 1.0;
    }
    for (d = 0; d < 3; ++d) {
        len2 += (xi[d] - xo[d]) * (xi[d] - xo[d]);
    }
    t = so / (so - si);
    for (it = 0; it < 8; ++it) {
        double x[3], f;
        for (d = 0; d < 3; ++d) {
            x[d] = xo[d] + t * (xi[d] - xo[d]);
        }
        f = vhe_shape_sdf_posed(s, Q, X, x);
        if (f * f <= 1e-18 * len2) {
            break;
        }
        /* Illinois: halve the value of an end kept twice in a row */
        if (f > 0.0) {
            a = t;
            so = f;
            if (side == 1) {
                si *= 0.5;
            }
            side = 1;
        } else {
            z = t;
            si = f;
            if (side == -1) {
                so *= 0.5;
            }
            side = -1;
        }
        t = a + (z - a) * so / (so - si);
    }
    return t < 1e-6 ? 1e-6 : (t > 1.0 ? 1.0 : t);
}

double vhe_wall_coefficient(double magS, double dist, double delta)
{
    const double dl = delta < 1e-6 ? 1e-6 : delta;
    return dl >= 1.0 || dist <= 0.0 ? 0.0 : magS / dist * (1.0 / dl - 1.0);
}

double vhe_shape_fraction(const struct vhe_shape *s, const double lo[3],
                          const double hi[3], int ndim, int max_depth)
{
    return fraction(s, NULL, NULL, lo, hi, ndim, max_depth);
}

double vhe_shape_fraction_posed(const struct vhe_shape *s, const double Q[9],
                                const double X[3], const double lo[3],
                                const double hi[3], int ndim, int max_depth)
{
    if (Q == NULL || X == NULL) {
        return 0.0;
    }
    return fraction(s, Q, X, lo, hi, ndim, max_depth);
}

void vhe_shape_bounds_posed(const struct vhe_shape *s, const double Q[9],
                            const double X[3], double lo[3], double hi[3])
{
    double e[3];
    int i, j;

    vhe_shape_bounds(s, lo, hi);
    if (lo[0] > hi[0] || Q == NULL || X == NULL) {
        return;   /* an empty box stays empty */
    }
    for (j = 0; j < 3; ++j) {
        e[j] = lo[j] == -HUGE_VAL ? HUGE_VAL : 0.5 * (hi[j] - lo[j]);
    }
    /* The box of the turned box: half-extents sum_j |Q_ij| e_j, where an
     * infinite extent counts only along a direction it is turned into
     * (a 2D disk turned about its own axis stays infinite along it). */
    for (i = 0; i < 3; ++i) {
        double h = 0.0;
        for (j = 0; j < 3; ++j) {
            const double q = fabs(Q[3 * i + j]);
            if (q != 0.0) {
                h += q * e[j];
            }
        }
        lo[i] = h == HUGE_VAL ? -HUGE_VAL : X[i] - h;
        hi[i] = h == HUGE_VAL ? HUGE_VAL : X[i] + h;
    }
}

static double fraction(const struct vhe_shape *s, const double *Q,
                       const double *X, const double lo[3],
                       const double hi[3], int ndim, int max_depth)
{
    /*
     * Depth-first over sub-boxes with an explicit stack: each split pops one
     * box and pushes 2^nd children, so the stack never holds more than
     * 1 + (2^nd - 1) * depth entries.
     */
    struct node {
        double c[3];   /* sub-box centre [m] */
        int level;     /* 0 = the cell itself */
    } stack[1 + 7 * VHE_FRACTION_DEPTH_CAP];
    double edge[3];    /* cell edge lengths [m] */
    double frac = 0.0; /* accumulated fraction of the cell */
    const int nd = (ndim == 2) ? 2 : 3;
    const int nchild = 1 << nd;
    int top = 0, d;

    if (vhe_shape_check(s) != VHE_OK || lo == NULL || hi == NULL) {
        return 0.0;
    }
    for (d = 0; d < nd; ++d) {
        edge[d] = hi[d] - lo[d];
        if (!(edge[d] > 0.0) || !isfinite(edge[d])) {
            return 0.0;
        }
    }
    edge[2] = nd == 3 ? edge[2] : 0.0;
    if (max_depth < 0) {
        max_depth = 0;
    } else if (max_depth > VHE_FRACTION_DEPTH_CAP) {
        max_depth = VHE_FRACTION_DEPTH_CAP;
    }

    stack[0].c[0] = 0.5 * (lo[0] + hi[0]);
    stack[0].c[1] = 0.5 * (lo[1] + hi[1]);
    stack[0].c[2] = 0.5 * (lo[2] + hi[2]);  /* 2D: the cell's mid z */
    stack[0].level = 0;
    top = 1;

    while (top > 0) {
        const struct node b = stack[--top];
        double he[3], hd2 = 0.0, sdf, w;
        int k;

        /* Half-edges of this level and the half-diagonal over nd dims. */
        for (d = 0; d < nd; ++d) {
            he[d] = ldexp(0.5 * edge[d], -b.level);
            hd2 += he[d] * he[d];
        }
        /* This sub-box's share of the cell (exact power of two). */
        w = ldexp(1.0, -nd * b.level);
        {
            double y[3];
            unpose(s, Q, X, b.c, y);
            sdf = vhe_shape_sdf(s, y);   /* a rigid motion keeps distances */
        }

        /* |sdf| bounds the distance from below: the whole box is on one
         * side when the surface is no closer than the half-diagonal. */
        if (sdf >= 0.0 && sdf * sdf >= hd2) {
            continue;                      /* wholly outside */
        }
        if (sdf < 0.0 && sdf * sdf >= hd2) {
            frac += w;                     /* wholly inside */
            continue;
        }
        if (b.level >= max_depth) {
            /* Leaf: linear estimate from a plane at distance sdf. */
            double h = 0.0, f;
            for (d = 0; d < nd; ++d) {
                h += he[d];
            }
            h /= nd;
            f = 0.5 - sdf / (2.0 * h);
            frac += w * (f < 0.0 ? 0.0 : (f > 1.0 ? 1.0 : f));
            continue;
        }
        for (k = 0; k < nchild; ++k) {
            struct node *ch = &stack[top++];
            ch->level = b.level + 1;
            ch->c[2] = b.c[2];
            for (d = 0; d < nd; ++d) {
                ch->c[d] = b.c[d] + ((k >> d) & 1 ? 0.5 : -0.5) * he[d];
            }
        }
    }
    return frac > 1.0 ? 1.0 : frac;
}
