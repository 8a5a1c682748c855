/*
 * symm.c -- symmetric 3x3 tools: eigenvalues, determinant, solid
 * diagnostics, SPD repair.  symmTensor layout (xx xy xz yy yz zz).
 */
#include "vhe.h"

#include <float.h>
#include <math.h>

#define VHE_PI 3.14159265358979323846

static double sqrt_phis(double p)
{
    if (!(p > 0.0)) {
        return 0.0;
    }
    return p < 1.0 ? sqrt(p) : 1.0;
}

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* s = S v for a symmTensor S. */
static void symv(const double *S, const double *v, double *s)
{
    s[0] = S[0] * v[0] + S[1] * v[1] + S[2] * v[2];
    s[1] = S[1] * v[0] + S[3] * v[1] + S[4] * v[2];
    s[2] = S[2] * v[0] + S[4] * v[1] + S[5] * v[2];
}

double vhe_sym_det(const double S[6])
{
    return S[0] * (S[3] * S[5] - S[4] * S[4])
           - S[1] * (S[1] * S[5] - S[4] * S[2])
           + S[2] * (S[1] * S[4] - S[3] * S[2]);
}

static void sort3(double *l)
{
    double t;
    if (l[0] > l[1]) { t = l[0]; l[0] = l[1]; l[1] = t; }
    if (l[1] > l[2]) { t = l[1]; l[1] = l[2]; l[2] = t; }
    if (l[0] > l[1]) { t = l[0]; l[0] = l[1]; l[1] = t; }
}

/*
 * Trigonometric (Cardano) form with the deflation of Scherzinger and
 * Dohrmann (2008).  The plain trig formula loses half the digits of a
 * (nearly) repeated pair: acos is ill conditioned next to +-1, so a pair
 * lambda2 ~ lambda3 comes out with errors ~ sqrt(eps) |S|.  Instead only
 * the eigenvalue farthest from the other two is taken from the trig
 * formula (where it is well conditioned), its eigenvector is found from
 * the rows of S - eta1 I, and the other two are the eigenvalues of S
 * restricted to the orthogonal plane: a 2x2 problem solved with hypot,
 * accurate to ~eps |S| even for an exactly repeated pair.
 */
void vhe_sym_eigenvalues(const double S[6], double lambda[3])
{
    const double q = (S[0] + S[3] + S[5]) / 3.0;
    double s[6], r[3][3], v1[3], u1[3], u2[3], t[3], w[3];
    double J2, J3, scale, cos3a, alpha, eta1, rn[3], a11, a12, a22, m, d;
    int i, imax;

    for (i = 0; i < 6; ++i) {
        if (!isfinite(S[i])) {
            lambda[0] = lambda[1] = lambda[2] = NAN;
            return;
        }
    }
    /* Deviator, scaled to O(1) to keep J3 (a cubic) from over/underflow. */
    s[0] = S[0] - q; s[1] = S[1]; s[2] = S[2];
    s[3] = S[3] - q; s[4] = S[4]; s[5] = S[5] - q;
    scale = 0.0;
    for (i = 0; i < 6; ++i) {
        if (fabs(s[i]) > scale) {
            scale = fabs(s[i]);
        }
    }
    if (scale == 0.0) {
        /* A multiple of the identity. */
        lambda[0] = lambda[1] = lambda[2] = q;
        return;
    }
    if (S[1] == 0.0 && S[2] == 0.0 && S[4] == 0.0) {
        /* Diagonal: exact. */
        lambda[0] = S[0];
        lambda[1] = S[3];
        lambda[2] = S[5];
        sort3(lambda);
        return;
    }
    for (i = 0; i < 6; ++i) {
        s[i] /= scale;
    }

    J2 = 0.5 * (s[0] * s[0] + s[3] * s[3] + s[5] * s[5])
         + s[1] * s[1] + s[2] * s[2] + s[4] * s[4];
    J3 = vhe_sym_det(s);
    cos3a = 0.5 * J3 * pow(3.0 / J2, 1.5);
    if (cos3a > 1.0) {
        cos3a = 1.0;
    } else if (cos3a < -1.0) {
        cos3a = -1.0;
    }
    alpha = acos(cos3a) / 3.0;   /* in [0, pi/3] */
    /* The most distinct eigenvalue: the largest if alpha < pi/6, else the
     * smallest. */
    if (alpha < VHE_PI / 6.0) {
        eta1 = 2.0 * sqrt(J2 / 3.0) * cos(alpha);
    } else {
        eta1 = 2.0 * sqrt(J2 / 3.0) * cos(alpha + 2.0 * VHE_PI / 3.0);
    }

    /* Rows of s - eta1 I span the plane orthogonal to its eigenvector. */
    r[0][0] = s[0] - eta1; r[0][1] = s[1];        r[0][2] = s[2];
    r[1][0] = s[1];        r[1][1] = s[3] - eta1; r[1][2] = s[4];
    r[2][0] = s[2];        r[2][1] = s[4];        r[2][2] = s[5] - eta1;
    for (i = 0; i < 3; ++i) {
        rn[i] = dot3(r[i], r[i]);
    }
    imax = 0;
    if (rn[1] > rn[imax]) { imax = 1; }
    if (rn[2] > rn[imax]) { imax = 2; }
    if (!(rn[imax] > 0.0)) {
        /* Cannot happen for a non-zero deviator; be safe. */
        lambda[0] = lambda[1] = lambda[2] = q;
        return;
    }
    {
        /* s1 = the longest row, normalised; the others minus their s1 part. */
        const double inv = 1.0 / sqrt(rn[imax]);
        double s1[3], t1[3], t2[3], n1, n2;
        const int j1 = (imax + 1) % 3, j2 = (imax + 2) % 3;
        double p1, p2;

        s1[0] = r[imax][0] * inv;
        s1[1] = r[imax][1] * inv;
        s1[2] = r[imax][2] * inv;
        p1 = dot3(s1, r[j1]);
        p2 = dot3(s1, r[j2]);
        for (i = 0; i < 3; ++i) {
            t1[i] = r[j1][i] - p1 * s1[i];
            t2[i] = r[j2][i] - p2 * s1[i];
        }
        n1 = dot3(t1, t1);
        n2 = dot3(t2, t2);
        if (n2 > n1) {
            t1[0] = t2[0]; t1[1] = t2[1]; t1[2] = t2[2];
            n1 = n2;
        }
        if (n1 > 0.0) {
            const double inv2 = 1.0 / sqrt(n1);
            t1[0] *= inv2; t1[1] *= inv2; t1[2] *= inv2;
            cross3(s1, t1, v1);
        } else {
            /* Rank 1: any unit vector orthogonal to s1. */
            const double a[3] = {1.0, 0.0, 0.0}, b[3] = {0.0, 1.0, 0.0};
            cross3(s1, fabs(s1[0]) < 0.9 ? a : b, v1);
        }
    }
    {
        const double nv = sqrt(dot3(v1, v1));
        v1[0] /= nv; v1[1] /= nv; v1[2] /= nv;
    }

    /* Orthonormal basis (u1, u2) of the plane orthogonal to v1. */
    {
        const double a[3] = {1.0, 0.0, 0.0}, b[3] = {0.0, 1.0, 0.0};
        double nu;
        cross3(v1, fabs(v1[0]) < 0.6 ? a : b, u1);
        nu = sqrt(dot3(u1, u1));
        u1[0] /= nu; u1[1] /= nu; u1[2] /= nu;
        cross3(v1, u1, u2);
    }
    symv(s, u1, t);
    symv(s, u2, w);
    a11 = dot3(u1, t);
    a12 = 0.5 * (dot3(u2, t) + dot3(u1, w));
    a22 = dot3(u2, w);
    m = 0.5 * (a11 + a22);
    d = hypot(0.5 * (a11 - a22), a12);

    lambda[0] = q + scale * eta1;
    lambda[1] = q + scale * (m - d);
    lambda[2] = q + scale * (m + d);
    sort3(lambda);
}

/* |dev(A)| (Frobenius) of a symmTensor. */
static double mag_dev(const double *A)
{
    const double t = (A[0] + A[3] + A[5]) / 3.0;
    const double a = A[0] - t, b = A[3] - t, c = A[5] - t;
    return sqrt(a * a + b * b + c * c
                + 2.0 * (A[1] * A[1] + A[2] * A[2] + A[4] * A[4]));
}

void vhe_solid_diagnostics(size_t n, const double *phis, const double *Bstar,
                           double phis_solid, double out[3])
{
    double lmin = HUGE_VAL, devmax = 0.0, detmax = 0.0;
    size_t c;

    for (c = 0; c < n; ++c) {
        const double *Bs = Bstar + 6 * c;
        double l[3];

        vhe_sym_eigenvalues(Bs, l);
        if (l[0] < lmin || l[0] != l[0]) {
            lmin = l[0];
        }
        if (phis[c] > phis_solid) {
            const double sp = sqrt_phis(phis[c]);
            double B[6], dv, dd;
            int i;

            if (!(sp > 0.0)) {
                continue;   /* phis_solid < 0 and phis <= 0: no B */
            }
            for (i = 0; i < 6; ++i) {
                B[i] = Bs[i] / sp;
            }
            dv = mag_dev(B);
            dd = fabs(vhe_sym_det(B) - 1.0);
            if (dv > devmax || dv != dv) {
                devmax = dv;
            }
            if (dd > detmax || dd != dd) {
                detmax = dd;
            }
        }
    }
    out[0] = lmin;
    out[1] = devmax;
    out[2] = detmax;
}

void vhe_devb_mag(size_t n, const double *phis, const double *Bstar,
                  double phis_solid, double *out)
{
    size_t c;
    int i;

    for (c = 0; c < n; ++c) {
        const double sp = sqrt_phis(phis[c]);
        double B[6];

        out[c] = 0.0;
        if (!(phis[c] > phis_solid) || !(sp > 0.0)) {
            continue;
        }
        for (i = 0; i < 6; ++i) {
            B[i] = Bstar[6 * c + i] / sp;
        }
        out[c] = mag_dev(B);
    }
}

void vhe_sym_from_eigen(const double V[9], const double f[3], double S[6])
{
    static const int ii[6] = {0, 0, 0, 1, 1, 2};
    static const int jj[6] = {0, 1, 2, 1, 2, 2};
    int k;

    for (k = 0; k < 6; ++k) {
        const int a = ii[k], b = jj[k];
        S[k] = V[3 * a] * f[0] * V[3 * b]
               + V[3 * a + 1] * f[1] * V[3 * b + 1]
               + V[3 * a + 2] * f[2] * V[3 * b + 2];
    }
}

/*
 * Cyclic Jacobi on the six entries of a symmetric 3x3 (Numerical Recipes'
 * rotation formulas; vhe.h).  Stops once the off-diagonal part is below
 * 1e-15 of the diagonal's (sums of squares 1e-30): the rotations' own
 * round-off.
 */
void vhe_sym_eigen(const double S[6], double l[3], double V[9], int warm)
{
    /* a[p][q] of the symmetric matrix in the 6-entry layout */
    static const int idx[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    double a[6];
    int sweep, k;

    if (warm) {
        /* start in the basis V (the last eigenvectors of this cell, made
         * orthonormal again): a = V^T S V is nearly diagonal, and one or
         * two sweeps finish it instead of four or five */
        double *c0 = V, SV[9], n;
        double c1[3], c2[3];
        int i, j;
        n = sqrt(V[0] * V[0] + V[3] * V[3] + V[6] * V[6]);
        for (i = 0; i < 3; ++i) {
            c0[3 * i] /= n;
        }
        n = V[0] * V[1] + V[3] * V[4] + V[6] * V[7];
        for (i = 0; i < 3; ++i) {
            c1[i] = V[3 * i + 1] - n * V[3 * i];
        }
        n = sqrt(c1[0] * c1[0] + c1[1] * c1[1] + c1[2] * c1[2]);
        for (i = 0; i < 3; ++i) {
            c1[i] /= n;
        }
        c2[0] = V[3] * c1[2] - V[6] * c1[1];
        c2[1] = V[6] * c1[0] - V[0] * c1[2];
        c2[2] = V[0] * c1[1] - V[3] * c1[0];
        for (i = 0; i < 3; ++i) {
            V[3 * i + 1] = c1[i];
            V[3 * i + 2] = c2[i];
        }
        for (i = 0; i < 3; ++i) {
            for (j = 0; j < 3; ++j) {
                SV[3 * i + j] = S[idx[i][0]] * V[j] + S[idx[i][1]] * V[3 + j]
                                + S[idx[i][2]] * V[6 + j];
            }
        }
        for (k = 0; k < 6; ++k) {
            static const int ii[6] = {0, 0, 0, 1, 1, 2};
            static const int jj[6] = {0, 1, 2, 1, 2, 2};
            a[k] = V[ii[k]] * SV[jj[k]] + V[3 + ii[k]] * SV[3 + jj[k]]
                   + V[6 + ii[k]] * SV[6 + jj[k]];
        }
    } else {
        for (k = 0; k < 6; ++k) {
            a[k] = S[k];
        }
        for (k = 0; k < 9; ++k) {
            V[k] = (k % 4 == 0) ? 1.0 : 0.0;
        }
    }
    for (sweep = 0; sweep < 50; ++sweep) {
        const double off = a[1] * a[1] + a[2] * a[2] + a[4] * a[4];
        const double dia = a[0] * a[0] + a[3] * a[3] + a[5] * a[5];
        int p;
        if (off == 0.0 || off < 1e-30 * dia) {
            break;
        }
        for (p = 0; p < 2; ++p) {
            int q;
            for (q = p + 1; q < 3; ++q) {
                const int r = 3 - p - q;
                const double apq = a[idx[p][q]];
                double theta, t, c, sn, tau, g, h;
                if (apq == 0.0) {
                    continue;
                }
                theta = 0.5 * (a[idx[q][q]] - a[idx[p][p]]) / apq;
                t = 1.0 / (fabs(theta) + sqrt(theta * theta + 1.0));
                if (theta < 0.0) {
                    t = -t;
                }
                c = 1.0 / sqrt(t * t + 1.0);
                sn = t * c;
                tau = sn / (1.0 + c);
                a[idx[p][p]] -= t * apq;
                a[idx[q][q]] += t * apq;
                a[idx[p][q]] = 0.0;
                g = a[idx[r][p]];
                h = a[idx[r][q]];
                a[idx[r][p]] = g - sn * (h + g * tau);
                a[idx[r][q]] = h + sn * (g - h * tau);
                for (k = 0; k < 3; ++k) {
                    g = V[3 * k + p];
                    h = V[3 * k + q];
                    V[3 * k + p] = g - sn * (h + g * tau);
                    V[3 * k + q] = h + sn * (g - h * tau);
                }
            }
        }
    }
    l[0] = a[0]; l[1] = a[3]; l[2] = a[5];
}

size_t vhe_spd_repair(size_t n, const double *phis, double lambda_min,
                      double *Bstar)
{
    size_t c, changed = 0;

    for (c = 0; c < n; ++c) {
        double *B = Bstar + 6 * c;
        const double floor_c = lambda_min * sqrt_phis(phis[c]);
        double l[3], e[3], V[9], d[3];
        int i;

        vhe_sym_eigenvalues(B, l);
        /*
         * Below the floor by more than the eigenvalue round-off
         * (~eps |B|): a tensor already at the floor (e.g. repaired before)
         * is left alone, which makes the repair idempotent.
         */
        if (!(l[0] < floor_c - 16.0 * DBL_EPSILON * fmax(fabs(l[0]),
                                                         fabs(l[2])))) {
            continue;   /* SPD enough (or NaN): leave bit-identical */
        }
        vhe_sym_eigen(B, e, V, 0);
        for (i = 0; i < 3; ++i) {
            d[i] = e[i] < floor_c ? floor_c : e[i];
        }
        vhe_sym_from_eigen(V, d, B);
        ++changed;
    }
    return changed;
}
