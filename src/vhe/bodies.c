/*
 * bodies.c -- the motion and shape of one body from its moments, for the
 * per-body output (the bodies function object).  The framework sums over
 * the body's cells, with weights w = alpha V (the body's volume in the
 * cell) and r the position relative to the body's centroid:
 *   J = sum w r r^T              second moment of volume [m^5] (6 entries)
 *   L = sum w r x (u - u_c)      angular momentum per unit density [m^5/s]
 */
#include <math.h>

#include "vhe.h"

/* Components of a symmTensor (xx xy xz yy yz zz) */
static double sym_at(const double S[6], int i, int j)
{
    static const int idx[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    return S[idx[i][j]];
}

void vhe_body_omega(const double J[6], const double L[3], int normal,
                    double omega[3])
{
    const double trJ = J[0] + J[3] + J[5];
    int i, j;

    omega[0] = omega[1] = omega[2] = 0.0;
    if (normal >= 0 && normal < 3) {
        /* 2D: rotation about the normal only, I_nn = tr J - J_nn */
        const double Inn = trJ - sym_at(J, normal, normal);
        if (Inn > 0.0) {
            omega[normal] = L[normal] / Inn;
        }
        return;
    }
    {
        /* 3D: I omega = L, I = tr(J) 1 - J, by Cramer's rule */
        double I[3][3], det, inv[3][3];
        for (i = 0; i < 3; ++i) {
            for (j = 0; j < 3; ++j) {
                I[i][j] = (i == j ? trJ : 0.0) - sym_at(J, i, j);
            }
        }
        inv[0][0] = I[1][1] * I[2][2] - I[1][2] * I[2][1];
        inv[0][1] = I[0][2] * I[2][1] - I[0][1] * I[2][2];
        inv[0][2] = I[0][1] * I[1][2] - I[0][2] * I[1][1];
        inv[1][0] = I[1][2] * I[2][0] - I[1][0] * I[2][2];
        inv[1][1] = I[0][0] * I[2][2] - I[0][2] * I[2][0];
        inv[1][2] = I[0][2] * I[1][0] - I[0][0] * I[1][2];
        inv[2][0] = I[1][0] * I[2][1] - I[1][1] * I[2][0];
        inv[2][1] = I[0][1] * I[2][0] - I[0][0] * I[2][1];
        inv[2][2] = I[0][0] * I[1][1] - I[0][1] * I[1][0];
        det = I[0][0] * inv[0][0] + I[0][1] * inv[1][0]
            + I[0][2] * inv[2][0];
        if (!(fabs(det) > 0.0)) {
            return;
        }
        for (i = 0; i < 3; ++i) {
            omega[i] = (inv[i][0] * L[0] + inv[i][1] * L[1]
                        + inv[i][2] * L[2]) / det;
        }
    }
}

double vhe_body_shape(const double J[6], int normal, double axis[3])
{
    double lmax, lmin, a, b;
    int k, big = 0;

    axis[0] = axis[1] = axis[2] = 0.0;
    if (normal >= 0 && normal < 3) {
        /* 2D: the in-plane 2x2 block, closed form */
        const int p = (normal + 1) % 3, q = (normal + 2) % 3;
        const double xx = sym_at(J, p, p), yy = sym_at(J, q, q);
        const double xy = sym_at(J, p, q);
        const double m = 0.5 * (xx + yy);
        const double h = sqrt(0.25 * (xx - yy) * (xx - yy) + xy * xy);
        const double th = 0.5 * atan2(2.0 * xy, xx - yy);
        lmax = m + h;
        lmin = m - h;
        axis[p] = cos(th);
        axis[q] = sin(th);
    } else {
        double l[3], V[9];
        int imax = 0, imin = 0;
        vhe_sym_eigen(J, l, V, 0);
        for (k = 1; k < 3; ++k) {
            if (l[k] > l[imax]) imax = k;
            if (l[k] < l[imin]) imin = k;
        }
        lmax = l[imax];
        lmin = l[imin];
        for (k = 0; k < 3; ++k) {
            axis[k] = V[3 * k + imax];
        }
    }
    /* the sign: the axis' largest component positive */
    for (k = 1; k < 3; ++k) {
        if (fabs(axis[k]) > fabs(axis[big]) + 1e-12) big = k;
    }
    if (axis[big] < 0.0) {
        for (k = 0; k < 3; ++k) axis[k] = -axis[k];
    }
    a = sqrt(fmax(lmax, 0.0));
    b = sqrt(fmax(lmin, 0.0));
    return a + b > 0.0 ? (a - b) / (a + b) : 0.0;
}


int vhe_colour_bodies(int n, const double *centre, const double *radius,
                      const double period[3], double margin, int ncolours,
                      int *colour)
{
    int i, j, k, shared = 0;
    /* near[c]: near bodies already coloured c (ncolours <= 64) */
    int near[64];

    if (ncolours < 1) ncolours = 1;
    if (ncolours > 64) ncolours = 64;
    for (i = 0; i < n; ++i) {
        int best = 0;
        for (k = 0; k < ncolours; ++k) near[k] = 0;
        for (j = 0; j < i; ++j) {
            double d2 = 0.0, d, reach;
            for (k = 0; k < 3; ++k) {
                double dk = centre[3 * i + k] - centre[3 * j + k];
                if (period[k] > 0.0) {
                    dk -= period[k] * floor(dk / period[k] + 0.5);
                }
                d2 += dk * dk;
            }
            d = sqrt(d2);
            reach = radius[i] + radius[j] + margin;
            if (d < reach) near[colour[j]] += 1;
        }
        for (k = 1; k < ncolours; ++k) {
            if (near[k] < near[best]) best = k;
        }
        colour[i] = best;
        shared += near[best] > 0;
    }
    return shared;
}

void vhe_pose_rotate(double Q[9], const double omega[3], double dt)
{
    const double w = sqrt(omega[0] * omega[0] + omega[1] * omega[1]
                          + omega[2] * omega[2]);
    const double th = w * dt;
    double R[9], P[9], n[3];
    int i, j, k;

    if (!(th != 0.0) || !isfinite(th)) {
        return;
    }
    n[0] = omega[0] / w;
    n[1] = omega[1] / w;
    n[2] = omega[2] / w;
    {
        const double c = cos(th), s = sin(th), t = 1.0 - c;
        R[0] = c + t * n[0] * n[0];
        R[1] = t * n[0] * n[1] - s * n[2];
        R[2] = t * n[0] * n[2] + s * n[1];
        R[3] = t * n[1] * n[0] + s * n[2];
        R[4] = c + t * n[1] * n[1];
        R[5] = t * n[1] * n[2] - s * n[0];
        R[6] = t * n[2] * n[0] - s * n[1];
        R[7] = t * n[2] * n[1] + s * n[0];
        R[8] = c + t * n[2] * n[2];
    }
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            double v = 0.0;
            for (k = 0; k < 3; ++k) {
                v += R[3 * i + k] * Q[3 * k + j];
            }
            P[3 * i + j] = v;
        }
    }
    /* Gram-Schmidt on the columns: an exact zero stays exactly zero (a 2D
     * pose turned about the normal keeps its normal row and column). */
    for (j = 0; j < 3; ++j) {
        double m = 0.0;
        for (k = 0; k < j; ++k) {
            double d = 0.0;
            for (i = 0; i < 3; ++i) {
                d += P[3 * i + j] * P[3 * i + k];
            }
            for (i = 0; i < 3; ++i) {
                P[3 * i + j] -= d * P[3 * i + k];
            }
        }
        for (i = 0; i < 3; ++i) {
            m += P[3 * i + j] * P[3 * i + j];
        }
        m = sqrt(m);
        for (i = 0; i < 3; ++i) {
            P[3 * i + j] /= m;
        }
    }
    for (i = 0; i < 9; ++i) {
        Q[i] = P[i];
    }
}

void vhe_volume_sums(size_t n, const double *alpha, const double *V,
                     double sums[2])
{
    size_t c;
    sums[0] = 0.0;
    sums[1] = 0.0;
    for (c = 0; c < n; ++c) {
        sums[0] += alpha[c] * V[c];
        sums[1] += alpha[c] * (1.0 - alpha[c]) * V[c];
    }
}

double vhe_volume_shift(size_t n, double *alpha, const double sums[2],
                        double target)
{
    double s;
    size_t c;
    if (!(sums[1] > 0.0)) {
        return 0.0;
    }
    s = (target - sums[0]) / sums[1];
    s = s > 1.0 ? 1.0 : (s < -1.0 ? -1.0 : s);
    for (c = 0; c < n; ++c) {
        const double a = alpha[c] + s * alpha[c] * (1.0 - alpha[c]);
        alpha[c] = a < 0.0 ? 0.0 : (a > 1.0 ? 1.0 : a);
    }
    return s;
}
