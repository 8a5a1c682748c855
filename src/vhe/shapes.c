/*
 * shapes.c -- signed distance, volume, cell volume fraction and bounding
 * box of the body shapes.  Lengths in m.
 */
#include "vhe.h"

#include <math.h>
#include <string.h>

#define VHE_PI 3.14159265358979323846

/* Deepest refinement vhe_shape_fraction honours (2^-24 of a cell edge is
 * far below any use; the bound sizes the explicit stack). */
#define VHE_FRACTION_DEPTH_CAP 24
/* levels a smooth shape's second-order leaf saves (vhe_shape_fraction) */
#define SMOOTH_LEVELS 3

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

/* The distance bound of a checked shape; a: its unit axis (unit_axis),
 * used by a cylinder only.  The sub-cell integration below calls it for
 * every sub-box: the check and the axis are its caller's, once. */
static double sdf_checked(const struct vhe_shape *s, const double a[3],
                          const double x[3])
{
    double d[3];

    d[0] = x[0] - s->centre[0];
    d[1] = x[1] - s->centre[1];
    d[2] = x[2] - s->centre[2];

    switch (s->kind) {
    case VHE_SPHERE:
        return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - s->radius;

    case VHE_CYLINDER: {
        double t, r[3], rho, dr, da;
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

double vhe_shape_sdf(const struct vhe_shape *s, const double x[3])
{
    double a[3] = {0.0, 0.0, 1.0};
    if (vhe_shape_check(s) != VHE_OK) {
        return HUGE_VAL;   /* an invalid shape contains nothing */
    }
    if (s->kind == VHE_CYLINDER) {
        unit_axis(s, a);
    }
    return sdf_checked(s, a, x);
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

double vhe_shape_half_width(const struct vhe_shape *s, const int solved[3])
{
    double w = HUGE_VAL;
    int d;

    if (vhe_shape_check(s) != VHE_OK) {
        return 0.0;
    }
    switch (s->kind) {
    case VHE_SPHERE:
        return s->radius;
    case VHE_CYLINDER: {
        /* its axis along an unsolved direction: a 2D disk, however long */
        int along = 0;
        for (d = 0; d < 3; ++d) {
            along |= !solved[d] && fabs(s->axis[d]) > 0.5;
        }
        return s->half_length > 0.0 && !along && s->half_length < s->radius
             ? s->half_length : s->radius;
    }
    default:
        for (d = 0; d < 3; ++d) {
            if (solved[d] && s->semi[d] < w) {
                w = s->semi[d];
            }
        }
        return w < HUGE_VAL ? w : 0.0;
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

/* Child k (bit d: the upper half along d) of the box centred at p with
 * half-edges he, split along the nd integrated directions: its centre */
static void child_centre(const double p[3], const double he[3], int k,
                         int nd, double c[3])
{
    int d;
    c[2] = p[2];
    for (d = 0; d < nd; ++d) {
        c[d] = p[d] + ((k >> d) & 1 ? 0.5 : -0.5) * he[d];
    }
}

/* A smooth shape's leaf: the part of the box [c - he, c + he] where the
 * shape's distance bound, linear along each edge, is negative (the C
 * core's cell cut at the corner values), taken on the box and on its 2^nd
 * halves from one grid of 3^nd values, the two extrapolated by their error
 * ratio: a cut's error is its chords' sagitta, h^2 times the curvature
 * over the surface in the box, so it falls by 4 a level whatever nd is.
 * (4 fine - coarse)/3 clamped to [0, 1].  In 2D the box keeps its depth
 * and its corners' values along z are the mid plane's. */
static const int box_face_start[7] = {0, 4, 8, 12, 16, 20, 24};
static const int box_face_pts[24] = {0, 4, 6, 2, 1, 3, 7, 5, 0, 1, 5, 4,
                                     2, 6, 7, 3, 0, 2, 3, 1, 4, 5, 7, 6};
static const unsigned char box_flip[6] = {0, 0, 0, 0, 0, 0};

static double box_cut(const double c[3], const double he[3],
                      const double f[8])
{
    double x[24];
    struct vhe_cell cell;
    struct vhe_cut out;
    int k, d, in = 0;
    for (k = 0; k < 8; ++k) {
        in += f[k] > 0.0;
    }
    if (in == 0 || in == 8) {
        return in == 8 ? 1.0 : 0.0;
    }
    for (k = 0; k < 8; ++k) {
        for (d = 0; d < 3; ++d) {
            x[3 * k + d] = c[d] + ((k >> d) & 1 ? he[d] : -he[d]);
        }
    }
    cell.npoints = 8;
    cell.x = x;
    cell.nfaces = 6;
    cell.face_start = box_face_start;
    cell.face_pts = box_face_pts;
    cell.flip = box_flip;
    for (d = 0; d < 3; ++d) {
        cell.x0[d] = c[d];
    }
    vhe_cell_cut(&cell, f, 0.0, &out);
    return out.status == -1 ? 1.0
         : out.status == 1 ? 0.0 : out.volume / (8.0 * he[0] * he[1] * he[2]);
}

static double smooth_leaf(const struct vhe_shape *s, const double *Q,
                          const double *X, const double axis[3],
                          const double c[3], const double he[3], int nd)
{
    double g[27], f[8], hc[3], cc[3], fine = 0.0, coarse, r;
    const int nz = nd == 3 ? 3 : 1, nch = 1 << nd;
    int i, j, k, d, ch;
    for (k = 0; k < nz; ++k) {
        for (j = 0; j < 3; ++j) {
            for (i = 0; i < 3; ++i) {
                double x[3], y[3];
                x[0] = c[0] + (i - 1) * he[0];
                x[1] = c[1] + (j - 1) * he[1];
                x[2] = nd == 3 ? c[2] + (k - 1) * he[2] : c[2];
                unpose(s, Q, X, x, y);
                g[i + 3 * j + 9 * k] = -sdf_checked(s, axis, y);
            }
        }
    }
    /* corner k of a box of grid offset (oi, oj, ok) and grid step st */
#define GRID(oi, oj, ok, st, k)                                              \
    g[(oi) + (st) * ((k) & 1) + 3 * ((oj) + (st) * (((k) >> 1) & 1))       \
      + (nd == 3 ? 9 * ((ok) + (st) * (((k) >> 2) & 1)) : 0)]
    for (k = 0; k < 8; ++k) {
        f[k] = GRID(0, 0, 0, 2, k);
    }
    coarse = box_cut(c, he, f);
    for (d = 0; d < 3; ++d) {
        hc[d] = d < nd ? 0.5 * he[d] : he[d];
    }
    for (ch = 0; ch < nch; ++ch) {
        const int oi = ch & 1, oj = (ch >> 1) & 1, ok = (ch >> 2) & 1;
        child_centre(c, he, ch, nd, cc);
        for (k = 0; k < 8; ++k) {
            f[k] = GRID(oi, oj, ok, 1, k);
        }
        fine += box_cut(cc, hc, f);
    }
#undef GRID
    r = (4.0 * fine / nch - coarse) / 3.0;
    return r < 0.0 ? 0.0 : (r > 1.0 ? 1.0 : r);
}

/* A box shape's fraction of the cell [lo, hi], exact: the cell, a convex
 * polyhedron of at most CLIP_FACES faces of at most CLIP_PTS points, is
 * clipped by the six half-spaces +-a_i.(x - X) <= semi_i of the posed box
 * (a_i the box's axis i in the world, column i of Q), each face by
 * Sutherland-Hodgman, the points on the plane closing the cut as a new
 * face (ordered by angle about their mean); its volume is a third of the
 * sum over its faces of (mean - cell centre).area (vhe_polygon_fan).
 * Returns -1 if a polygon would overflow (not met: six planes add at most
 * six faces and a point to a face each). */
#define CLIP_FACES 16
#define CLIP_PTS 16

struct clip_poly {
    int nf;
    int np[CLIP_FACES];
    double p[CLIP_FACES][CLIP_PTS][3];
};

static int clip_plane(struct clip_poly *P, const double n[3], double d)
{
    double cap[2 * CLIP_FACES][3], m[3] = {0.0, 0.0, 0.0}, u[3], v[3];
    double ang[2 * CLIP_FACES];
    int nc = 0, f, i, k, out = 0, nf = 0;
    for (f = 0; f < P->nf && !out; ++f) {
        for (i = 0; i < P->np[f]; ++i) {
            out = out || n[0] * P->p[f][i][0] + n[1] * P->p[f][i][1]
                         + n[2] * P->p[f][i][2] > d;
        }
    }
    if (!out) {
        return 0;                              /* wholly inside the plane */
    }
    for (f = 0; f < P->nf; ++f) {
        double q[CLIP_PTS][3];
        int nq = 0;
        const int np = P->np[f];
        for (i = 0; i < np; ++i) {
            const double *a = P->p[f][i], *b = P->p[f][(i + 1) % np];
            const double da = n[0] * a[0] + n[1] * a[1] + n[2] * a[2] - d;
            const double db = n[0] * b[0] + n[1] * b[1] + n[2] * b[2] - d;
            if (da <= 0.0) {
                if (nq == CLIP_PTS) return -1;
                memcpy(q[nq++], a, sizeof q[0]);
            }
            if ((da <= 0.0) != (db <= 0.0)) {
                const double t = da / (da - db);
                if (nq == CLIP_PTS || nc == 2 * CLIP_FACES) return -1;
                for (k = 0; k < 3; ++k) {
                    q[nq][k] = a[k] + t * (b[k] - a[k]);
                    cap[nc][k] = q[nq][k];
                }
                ++nq;
                ++nc;
            }
        }
        if (nq >= 3) {
            P->np[nf] = nq;
            memcpy(P->p[nf], q, (size_t)nq * sizeof q[0]);
            ++nf;
        }
    }
    P->nf = nf;
    if (nc < 3) {
        return 0;
    }
    if (nf == CLIP_FACES) return -1;
    /* the cut's face, its points in order about n (outward: the cut side) */
    for (i = 0; i < nc; ++i) {
        for (k = 0; k < 3; ++k) m[k] += cap[i][k] / nc;
    }
    k = fabs(n[0]) < 0.6 ? 0 : (fabs(n[1]) < 0.6 ? 1 : 2);
    u[0] = u[1] = u[2] = 0.0;
    u[k] = 1.0;
    {
        const double un = u[0] * n[0] + u[1] * n[1] + u[2] * n[2];
        for (i = 0; i < 3; ++i) u[i] -= un * n[i];
    }
    v[0] = n[1] * u[2] - n[2] * u[1];
    v[1] = n[2] * u[0] - n[0] * u[2];
    v[2] = n[0] * u[1] - n[1] * u[0];
    for (i = 0; i < nc; ++i) {
        double r[3];
        for (k = 0; k < 3; ++k) r[k] = cap[i][k] - m[k];
        ang[i] = atan2(r[0] * v[0] + r[1] * v[1] + r[2] * v[2],
                       r[0] * u[0] + r[1] * u[1] + r[2] * u[2]);
    }
    /* insertion sort by angle (a handful of points) */
    for (i = 1; i < nc; ++i) {
        double a = ang[i], c[3];
        int j = i;
        memcpy(c, cap[i], sizeof c);
        for (; j > 0 && ang[j - 1] > a; --j) {
            ang[j] = ang[j - 1];
            memcpy(cap[j], cap[j - 1], sizeof c);
        }
        ang[j] = a;
        memcpy(cap[j], c, sizeof c);
    }
    if (nc > CLIP_PTS) return -1;
    P->np[nf] = nc;
    memcpy(P->p[nf], cap, (size_t)nc * sizeof cap[0]);
    P->nf = nf + 1;
    return 0;
}

static double box_fraction(const struct vhe_shape *s, const double *Q,
                           const double *X, const double lo[3],
                           const double hi[3])
{
    struct clip_poly P;
    const double *C = Q ? X : s->centre;
    double c[3], h[3], vol = 0.0;
    int f, i, k;
    for (k = 0; k < 3; ++k) {
        c[k] = 0.5 * (lo[k] + hi[k]);
        h[k] = 0.5 * (hi[k] - lo[k]);
    }
    /* the cell about its centre (coordinates relative to c), its faces
     * as box_cut's */
    P.nf = 6;
    for (f = 0; f < 6; ++f) {
        P.np[f] = 4;
        for (i = 0; i < 4; ++i) {
            for (k = 0; k < 3; ++k) {
                P.p[f][i][k] =
                    (box_face_pts[4 * f + i] >> k) & 1 ? h[k] : -h[k];
            }
        }
    }
    for (i = 0; i < 3; ++i) {
        /* axis i of the posed box; its centre C relative to c */
        double a[3], ac = 0.0, sg;
        for (k = 0; k < 3; ++k) {
            a[k] = Q ? Q[3 * k + i] : (k == i ? 1.0 : 0.0);
            ac += a[k] * (C[k] - c[k]);
        }
        for (sg = -1.0; sg <= 1.0; sg += 2.0) {
            const double n[3] = {sg * a[0], sg * a[1], sg * a[2]};
            if (clip_plane(&P, n, s->semi[i] + sg * ac) != 0) {
                return -1.0;
            }
            if (P.nf == 0) {
                return 0.0;
            }
        }
    }
    for (f = 0; f < P.nf; ++f) {
        double m[3], S[3];
        vhe_polygon_fan(P.np[f], &P.p[f][0][0], m, S);
        vol += m[0] * S[0] + m[1] * S[1] + m[2] * S[2];
    }
    vol /= 3.0 * 8.0 * h[0] * h[1] * h[2];
    return vol < 0.0 ? 0.0 : (vol > 1.0 ? 1.0 : vol);
}

/* One sub-box of fraction() (centre c, squared half-diagonal hd2, twice
 * its mean half-edge twoh, share w of the cell): wholly inside or outside
 * when the surface is no closer than its half-diagonal (|sdf| bounds the
 * distance from below; a rigid motion keeps distances), its share added
 * to *frac; a leaf straddling the surface adds the linear estimate from a
 * plane at distance sdf, or a smooth shape's second-order one (smooth_leaf;
 * he: the box's half-edges).  Returns 1 for a box to split, else 0. */
static inline int straddles(const struct vhe_shape *s, const double *Q,
                            const double *X, const double axis[3],
                            const double c[3], const double he[3],
                            double hd2, double twoh, double *frac, double w,
                            int leaf, int smooth, int nd)
{
    double y[3], sdf, f;
    unpose(s, Q, X, c, y);
    sdf = sdf_checked(s, axis, y);
    if (sdf >= 0.0 && sdf * sdf >= hd2) {
        return 0;                          /* wholly outside */
    }
    if (sdf < 0.0 && sdf * sdf >= hd2) {
        *frac += w;                        /* wholly inside */
        return 0;
    }
    if (!leaf) {
        return 1;
    }
    if (smooth) {
        *frac += w * smooth_leaf(s, Q, X, axis, c, he, nd);
        return 0;
    }
    f = 0.5 - sdf / twoh;
    *frac += w * (f < 0.0 ? 0.0 : (f > 1.0 ? 1.0 : f));
    return 0;
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
    double hd2 = 0.0;  /* the cell's squared half-diagonal over nd dims */
    double frac = 0.0; /* accumulated fraction of the cell */
    /* each level's half-edges, squared half-diagonal and share of the
     * cell (exact powers of two), made once: ldexp in the loop was a
     * quarter of a drawing's time */
    double half[VHE_FRACTION_DEPTH_CAP + 1][3];
    double diag2[VHE_FRACTION_DEPTH_CAP + 1];
    double share[VHE_FRACTION_DEPTH_CAP + 1];
    double twoh[VHE_FRACTION_DEPTH_CAP + 1];  /* twice the mean half-edge */
    double axis[3] = {0.0, 0.0, 1.0};
    const int nd = (ndim == 2) ? 2 : 3;
    const int nchild = 1 << nd;
    int top = 0, d, level, smooth;

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
    for (d = 0; d < nd; ++d) {
        hd2 += 0.25 * edge[d] * edge[d];
    }
    if (s->kind == VHE_BOX) {
        /* exact, once the cell is not wholly on one side */
        double y[3], mid[3], plo[3], phi[3], r;
        for (d = 0; d < 3; ++d) {
            mid[d] = 0.5 * (lo[d] + hi[d]);
            plo[d] = d < nd ? lo[d] : mid[d] - 0.5;    /* 2D: a unit prism */
            phi[d] = d < nd ? hi[d] : mid[d] + 0.5;
        }
        unpose(s, Q, X, mid, y);
        r = sdf_checked(s, axis, y);
        if (r * r >= hd2) {
            return r < 0.0 ? 1.0 : 0.0;
        }
        r = box_fraction(s, Q, X, plo, phi);
        if (r >= 0.0) {
            return r;
        }
    }
    if (max_depth < 0) {
        max_depth = 0;
    } else if (max_depth > VHE_FRACTION_DEPTH_CAP) {
        max_depth = VHE_FRACTION_DEPTH_CAP;
    }
    /* A smooth surface (sphere, ellipsoid, infinite cylinder) takes the
     * second-order leaf SMOOTH_LEVELS levels higher up (vhe.h) */
    smooth = s->kind == VHE_SPHERE || s->kind == VHE_ELLIPSOID
          || (s->kind == VHE_CYLINDER && !(s->half_length > 0.0));
    if (smooth) {
        /* ... but no coarser than a quarter of the smallest radius of
         * curvature a leaf's half-diagonal: the extrapolation needs the
         * surface resolved by the leaf's grid (a sphere of a tenth of a
         * cell's radius fell between the points of a depth-2 leaf and lost
         * three quarters of its volume; from 0.87 cells' radius up in 3D
         * nothing changes at the default depth) */
        /* an ellipsoid's: the smallest semi-axis squared over the largest
         * (in 2D of the two in the plane; the third is infinite) */
        const double a = fmin(s->semi[0], s->semi[1]);
        const double b = fmax(s->semi[0], s->semi[1]);
        const double rmin = s->kind != VHE_ELLIPSOID ? s->radius
            : nd == 2 ? a * a / b
            : fmin(a, s->semi[2]) * fmin(a, s->semi[2]) / fmax(b, s->semi[2]);
        max_depth = max_depth > SMOOTH_LEVELS ? max_depth - SMOOTH_LEVELS : 0;
        while (max_depth < VHE_FRACTION_DEPTH_CAP
               && ldexp(hd2, -2 * max_depth) > 0.0625 * rmin * rmin) {
            ++max_depth;
        }
    }

    for (level = 0; level <= max_depth; ++level) {
        diag2[level] = 0.0;
        for (d = 0; d < nd; ++d) {
            half[level][d] = ldexp(0.5 * edge[d], -level);
            diag2[level] += half[level][d] * half[level][d];
        }
        half[level][2] = nd == 3 ? half[level][2] : 0.5;  /* 2D: a prism */
        share[level] = ldexp(1.0, -nd * level);
        twoh[level] = 0.0;
        for (d = 0; d < nd; ++d) {
            twoh[level] += half[level][d];
        }
        twoh[level] = 2.0 * (twoh[level] / nd);
    }
    if (s->kind == VHE_CYLINDER) {
        unit_axis(s, axis);
    }

    stack[0].c[0] = 0.5 * (lo[0] + hi[0]);
    stack[0].c[1] = 0.5 * (lo[1] + hi[1]);
    stack[0].c[2] = 0.5 * (lo[2] + hi[2]);  /* 2D: the cell's mid z */
    stack[0].level = 0;
    top = 1;

    while (top > 0) {
        const struct node b = stack[--top];
        int k;
        if (!straddles(s, Q, X, axis, b.c, half[b.level], diag2[b.level],
                       twoh[b.level], &frac, share[b.level],
                       b.level >= max_depth, smooth, nd)) {
            continue;
        }
        /* Split in 2 along each integrated direction */
        for (k = 0; k < nchild; ++k) {
            struct node *ch = &stack[top++];
            ch->level = b.level + 1;
            child_centre(b.c, half[b.level], k, nd, ch->c);
        }
    }
    return frac > 1.0 ? 1.0 : frac;
}
