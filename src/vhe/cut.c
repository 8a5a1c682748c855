/*
 * cut.c -- a polyhedral cell cut by an isosurface of a point field that is
 * linear along the edges (a plane when the field is linear): the part
 * where f > iso, its volume, and the area vector and centre of the cut.
 * vhe_cell_cut_fraction finds the iso value at which that part holds a
 * given fraction of the cell (PLIC: the plane of a given normal that cuts a
 * cell at its volume fraction; isoAdvector's isosurface cut).
 *
 * The part's volume is (1/3) sum over its boundary of (c - x0).S: the
 * submerged parts of the cell's faces (each a fan of triangles about its
 * mean point) and the cut itself, whose area vector closes the surface
 * (minus the sum of the others) and whose centre is the area-weighted
 * centre of the fan of the cut's edge segments about their length-weighted
 * mean point (isoCutCell's construction, but for the weights; exact for a
 * plane).  No allocation.
 */
#include "vhe.h"

#include <math.h>
#include <string.h>

static void sub3(const double a[3], const double b[3], double r[3])
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}

static void cross3(const double a[3], const double b[3], double r[3])
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Largest polygon handled (points of a face plus its cuts) and cut
 * segments of a cell */
#define VHE_CUT_MAXP 64
#define VHE_CUT_MAXSEG 64

void vhe_polygon_fan(int np, const double *p, double m[3], double S[3])
{
    /* (scalars: sums kept in arrays stall on their own stores) */
    double mx = 0.0, my = 0.0, mz = 0.0, sx = 0.0, sy = 0.0, sz = 0.0;
    double ax, ay, az;
    const double r = 1.0 / np;
    int i;
    for (i = 0; i < np; ++i) {
        mx += p[3 * i];
        my += p[3 * i + 1];
        mz += p[3 * i + 2];
    }
    mx *= r; my *= r; mz *= r;
    ax = p[0] - mx; ay = p[1] - my; az = p[2] - mz;
    for (i = 1; i <= np; ++i) {
        const int k = i < np ? i : 0;
        const double bx = p[3 * k] - mx, by = p[3 * k + 1] - my,
                     bz = p[3 * k + 2] - mz;
        sx += ay * bz - az * by;
        sy += az * bx - ax * bz;
        sz += ax * by - ay * bx;
        ax = bx; ay = by; az = bz;
    }
    m[0] = mx; m[1] = my; m[2] = mz;
    S[0] = 0.5 * sx; S[1] = 0.5 * sy; S[2] = 0.5 * sz;
}

/* The cut's edge segments (a cut's own, for its centre) */
struct cut_segments {
    int n;
    double s[VHE_CUT_MAXSEG][2][3];
    double m[3];                        /* the fan's point (cut_part's) */
};

/* The part where f > iso: status, volume and area (its centre is
 * cut_centre's, from the segments kept in sg).  The cut closes the part
 * as the fan of its segments about a point m (below); each of the fan's
 * triangles has (c - m).S = 0, so with the faces' shares taken about x0
 * the cut's share of 3 x the volume is (m - x0).A: no centre needed (the
 * exact volume of the polyhedron the fans bound; for a plane cut m and
 * the centre are both on the plane and give the same) */
static int cut_part(const struct vhe_cell *cell, const double *f, double iso,
                    struct vhe_cut *out, struct cut_segments *sg)
{
    double S_sub[3] = {0.0, 0.0, 0.0};  /* submerged faces' area vector */
    double vol3 = 0.0;                  /* 3 x volume, about x0 */
    double (*seg)[2][3] = sg->s;        /* the cut's edge segments */
    int nseg = 0, nsub = 0, k;
    const double *x0 = cell->x0, *X = cell->x;

    sg->n = 0;

    out->iso = iso;
    out->volume = 0.0;
    for (k = 0; k < 3; ++k) {
        out->area[k] = 0.0;
        out->centre[k] = 0.0;
    }
    for (k = 0; k < cell->nfaces; ++k) {
        const int s = cell->face_start[k], n = cell->face_start[k + 1] - s;
        double poly[VHE_CUT_MAXP][3], cuts[VHE_CUT_MAXP][3], d[VHE_CUT_MAXP / 2];
        double mean[3], S[3];
        int idx[VHE_CUT_MAXP / 2], np = 0, ncut = 0, nin = 0, i, j;

        if (n > VHE_CUT_MAXP / 2) {
            return -1;
        }
        /* the face's points in outward order, and f - iso at them */
        for (i = 0; i < n; ++i) {
            idx[i] = cell->face_pts[s + (cell->flip[k] ? n - 1 - i : i)];
            d[i] = f[idx[i]] - iso;
            nin += d[i] > 0.0;
        }
        if (nin == 0) {
            continue;
        }
        ++nsub;
        for (i = 0; i < n; ++i) {
            const int b = i + 1 < n ? i + 1 : 0;
            const double *xa = &X[3 * idx[i]];
            if (d[i] > 0.0) {
                poly[np][0] = xa[0];
                poly[np][1] = xa[1];
                poly[np][2] = xa[2];
                ++np;
            }
            if ((d[i] > 0.0) != (d[b] > 0.0)) {
                const double t = d[i] / (d[i] - d[b]);
                const double *xb = &X[3 * idx[b]];
                for (j = 0; j < 3; ++j) {
                    poly[np][j] = cuts[ncut][j] = xa[j] + t * (xb[j] - xa[j]);
                }
                ++ncut;
                ++np;
            }
        }
        /* the submerged part's fan of triangles about its mean point m:
         * the triangles' centres being m + (p_i - m + p_i+1 - m)/3, whose
         * second part is normal to the triangle's area, (m - x0).S is its
         * share of 3 x the volume */
        vhe_polygon_fan(np, &poly[0][0], mean, S);
        for (j = 0; j < 3; ++j) {
            S_sub[j] += S[j];
            mean[j] -= x0[j];
        }
        vol3 += dot3(mean, S);
        /* its cut points pair up into the cut's edge segments: from where
         * the walk leaves the submerged part to where it comes back (the
         * walk starts at the face's first point, inside or not) */
        {
            const int shift = d[0] > 0.0 ? 0 : 1;
            for (i = 0; i + 1 < ncut; i += 2) {
                if (nseg == VHE_CUT_MAXSEG) {
                    return -1;
                }
                memcpy(seg[nseg][0], cuts[(i + shift) % ncut], 3 * sizeof(double));
                memcpy(seg[nseg][1], cuts[(i + 1 + shift) % ncut],
                       3 * sizeof(double));
                ++nseg;
            }
        }
    }

    sg->n = nseg;
    if (nsub == 0) {
        out->status = 1;                 /* all above: nothing where f > iso */
        return 0;
    }
    out->area[0] = -S_sub[0];
    out->area[1] = -S_sub[1];
    out->area[2] = -S_sub[2];
    if (nseg == 0) {
        out->status = -1;                /* no cut: all of the cell */
        out->volume = vol3 / 3.0;
        return 0;
    }
    /* A cut of no area (the iso value at a point, or within round-off of
     * one) is still a cut: the part's volume says how much of the cell it
     * holds (nearly none or nearly all).  Taking it for all of the cell
     * sent the search for a small fraction to the wrong pair of point
     * values when the two largest differed by round-off, and the cell lost
     * its cut (a disk's edge cell at 0.025 in test_rigid's obstacle case,
     * serial; not on 2 ranks, whose point values differed in the last
     * digit). */

    /* The fan's point m: the mean of the segments' midpoints weighted by
     * their lengths.  With equal weights (isoCutCell's mean point) m
     * jumped where the iso value crossed a point value (a cut point
     * becomes three, or three one, next to that point), and so did a
     * curved cut's volume: the fraction was discontinuous in the iso
     * value, a cell whose fraction fell in a jump had no cut within the
     * tolerance and lost its plane (43 of 20,000 random cells of a curved
     * field), and the cubic through a bracket missed more often.  The
     * segments born or dying at a point value have no length, so this m
     * moves continuously. */
    {
        double m[3] = {0.0, 0.0, 0.0}, L = 0.0;
        int i, j;
        for (i = 0; i < nseg; ++i) {
            double e[3], l;
            sub3(seg[i][1], seg[i][0], e);
            l = sqrt(dot3(e, e));
            L += l;
            for (j = 0; j < 3; ++j) {
                m[j] += (seg[i][0][j] + seg[i][1][j]) * l;
            }
        }
        if (L > 0.0) {
            for (j = 0; j < 3; ++j) m[j] *= 0.5 / L;
        } else {
            for (j = 0; j < 3; ++j) m[j] = 0.5 * (seg[0][0][j] + seg[0][1][j]);
        }
        for (j = 0; j < 3; ++j) {
            sg->m[j] = m[j];
            m[j] -= x0[j];
        }
        vol3 += dot3(m, out->area);
    }
    out->status = 0;
    out->volume = vol3 / 3.0;
    return 0;
}

/* The cut's centre: its segments' fan about cut_part's point m, each
 * triangle's area signed along the cut's area vector (isoCutCell's) */
static void cut_centre(const struct cut_segments *sg, struct vhe_cut *out)
{
    const double *mean = sg->m;
    double sumA = 0.0, sumAc[3] = {0.0, 0.0, 0.0};
    double nhat[3], m;
    const int nseg = sg->n;
    int i, j;
    if (nseg == 0 || out->status != 0) {
        return;                          /* no cut: no centre (0) */
    }
    m = sqrt(dot3(out->area, out->area));
    for (j = 0; j < 3; ++j) {
        nhat[j] = m > 0.0 ? out->area[j] / m : 0.0;
    }
    for (i = 0; i < nseg; ++i) {
        double e1[3], e2[3], n[3], a;
        sub3(sg->s[i][0], mean, e1);
        sub3(sg->s[i][1], mean, e2);
        cross3(e1, e2, n);
        a = fabs(dot3(n, nhat));
        sumA += a;
        for (j = 0; j < 3; ++j) {
            sumAc[j] += a * (sg->s[i][0][j] + sg->s[i][1][j] + mean[j]);
        }
    }
    for (j = 0; j < 3; ++j) {
        out->centre[j] = sumA > 0.0 ? sumAc[j] / (3.0 * sumA) : mean[j];
    }
}

int vhe_cell_cut(const struct vhe_cell *cell, const double *f, double iso,
                 struct vhe_cut *out)
{
    struct cut_segments sg;
    const int r = cut_part(cell, f, iso, out, &sg);
    if (r == 0) {
        cut_centre(&sg, out);
    }
    return r;
}

/* The fraction of the cell where f > iso */
static double fraction(const struct vhe_cell *cell, const double *f,
                       double iso, double V, struct vhe_cut *out,
                       struct cut_segments *sg)
{
    cut_part(cell, f, iso, out, sg);
    return out->status == -1 ? 1.0 : out->status == 1 ? 0.0 : out->volume / V;
}

/* Newton on the iso value of a linear f whose gradient has magnitude g:
 * d(fraction)/d(iso) = -|cut area|/(g V); kept inside the bracket [lo, hi]
 * of the point values (bisection where a step leaves it) */
static int newton(const struct vhe_cell *cell, const double *f, double V,
                  double alpha, double tol, double g, double x,
                  struct vhe_cut *out)
{
    double lo = f[0], hi = f[0];
    struct cut_segments sg;
    int i, it;
    for (i = 1; i < cell->npoints; ++i) {
        lo = f[i] < lo ? f[i] : lo;
        hi = f[i] > hi ? f[i] : hi;
    }
    if (!(x > lo && x < hi)) {
        x = lo + (1.0 - alpha) * (hi - lo);
    }
    for (it = 0; it < 60; ++it) {
        const double r = fraction(cell, f, x, V, out, &sg) - alpha;
        const double A = sqrt(dot3(out->area, out->area));
        double xn;
        if (fabs(r) <= tol) {
            cut_centre(&sg, out);
            out->volume = r + alpha;
            return 0;
        }
        if (r > 0.0) {
            lo = x;                     /* too much: the iso value rises */
        } else {
            hi = x;
        }
        xn = A > 0.0 ? x + r * g * V / A : 0.5 * (lo + hi);
        x = xn > lo && xn < hi ? xn : 0.5 * (lo + hi);
    }
    return 1;
}

int vhe_cell_cut_fraction(const struct vhe_cell *cell, const double *f,
                          double V, double alpha, double tol, double g,
                          double guess, struct vhe_cut *out)
{
    double fs[VHE_CUT_MAXP], lo, hi, alo, ahi;
    struct cut_segments sg;
    int n = cell->npoints, i, j, L, H, it;

    if (n > VHE_CUT_MAXP || n < 4 || !(V > 0.0)) {
        return -1;
    }
    if (g > 0.0) {
        return newton(cell, f, V, alpha, tol, g, guess, out);
    }
    /* the point values sorted (insertion: a handful of points) */
    for (i = 0; i < n; ++i) {
        const double v = f[i];
        for (j = i; j > 0 && fs[j - 1] > v; --j) {
            fs[j] = fs[j - 1];
        }
        fs[j] = v;
    }
    /* fraction where f > iso falls from 1 at fs[0] to 0 at fs[n-1]: the
     * pair of neighbouring point values that brackets alpha */
    L = 0; H = n - 1; alo = 1.0; ahi = 0.0;
    while (H - L > 1) {
        const int M = (L + H) / 2;
        double a;
        cut_part(cell, f, fs[M], out, &sg);
        a = out->status == -1 ? 1.0 : out->volume / V;
        if (a > alpha) {
            L = M; alo = a;
        } else if (a < alpha) {
            H = M; ahi = a;
        } else {
            cut_centre(&sg, out);
            out->volume /= V;
            return 0;
        }
    }
    lo = fs[L]; hi = fs[H];
    if (hi - lo <= 0.0) {
        vhe_cell_cut(cell, f, lo, out);
        out->volume /= V;
        return 0;
    }

    /* on [lo, hi] the fraction is a cubic in iso (exact for a plane):
     * through four values, then Newton from the secant's root */
    {
        double t[4] = {0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0}, a[4], c[4], x, r;
        a[0] = alo; a[3] = ahi;
        for (i = 1; i <= 2; ++i) {
            cut_part(cell, f, lo + t[i] * (hi - lo), out, &sg);
            a[i] = out->status == -1 ? 1.0
                 : out->status == 1 ? 0.0 : out->volume / V;
        }
        /* Newton form of the interpolating cubic */
        c[0] = a[0];
        c[1] = (a[1] - a[0]) / (t[1] - t[0]);
        c[2] = ((a[2] - a[1]) / (t[2] - t[1]) - c[1]) / (t[2] - t[0]);
        c[3] = (((a[3] - a[2]) / (t[3] - t[2])
                 - (a[2] - a[1]) / (t[2] - t[1])) / (t[3] - t[1])
                - c[2]) / (t[3] - t[0]);
        x = (a[0] - alpha) / (a[0] - a[3]);
        for (it = 0; it < 50; ++it) {
            const double p = c[0] + (x - t[0]) * (c[1] + (x - t[1])
                           * (c[2] + (x - t[2]) * c[3]));
            const double dp = c[1] + c[2] * ((x - t[0]) + (x - t[1]))
                            + c[3] * ((x - t[1]) * (x - t[2])
                                      + (x - t[0]) * (x - t[2])
                                      + (x - t[0]) * (x - t[1]));
            double step;
            r = p - alpha;
            if (fabs(r) <= 0.01 * tol || dp == 0.0) {
                break;
            }
            step = r / dp;
            x -= step;
            x = x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x);
            if (fabs(step) < 1e-15) {
                break;
            }
        }
        /* checked on the cell itself; regula falsi (Illinois) if not */
        {
            double xa = 0.0, xb = 1.0, ra = a[0] - alpha, rb = a[3] - alpha;
            int side = 0;
            for (it = 0; it < 100; ++it) {
                double frac;
                cut_part(cell, f, lo + x * (hi - lo), out, &sg);
                frac = out->status == -1 ? 1.0
                     : out->status == 1 ? 0.0 : out->volume / V;
                r = frac - alpha;
                if (fabs(r) <= tol) {
                    cut_centre(&sg, out);
                    out->volume = frac;
                    return 0;
                }
                if ((r > 0.0) == (ra > 0.0)) {
                    xa = x; ra = r;
                    if (side == -1) rb *= 0.5;
                    side = -1;
                } else {
                    xb = x; rb = r;
                    if (side == 1) ra *= 0.5;
                    side = 1;
                }
                x = (xa * rb - xb * ra) / (rb - ra);
            }
        }
    }
    return 1;
}
