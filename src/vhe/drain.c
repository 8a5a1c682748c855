/*
 * drain.c -- the fluids in a drawn rigid body's edge cells (vheMixture's
 * drainEdges).
 *
 * A rigid body's edge cells move wholly with it: their faces carry its
 * rigid flux, so the fluids in them keep their mix wherever the body
 * goes.  A light box that rose through a free surface carried a row of
 * water into the air on its top, whose weight sank it (a tenth-density
 * box floated 6.7 mm, two thirds of its draft, too deep).  Transported
 * by the flow, those fluids would make no new extremes: so an edge cell
 * whose fluid composition s (each fluid's share of its fluids) lies
 * outside the range of its outside face neighbours' compositions is moved
 * towards their mean m, s + lambda (m - s), by the least lambda in
 * [0, 1] that brings every fluid's share into its range.  Each outside
 * face exchanges lambda/n of the difference between the two cells (n the
 * edge cell's outside faces) as volumes that sum to zero, so no cell's
 * total changes and every fluid's volume is kept to round-off.  (Moved
 * to the mean whatever its composition, the edge ring carried air from
 * the cells beside a floating disk at the surface down to the cells
 * under it: the disk rose to a sixth of its draft.)
 *
 * A cell is an edge cell where lo <= held < 1 (held the drawn bodies'
 * sum; lo the fraction from which a cell moves wholly with its body),
 * outside where held < lo: its fluids move with the flow.  (With lo at
 * round-off, 1e-6, a cell that a tilted body's corner reached by 1e-6
 * took its neighbours' fluids wholly in one step; the tilt of a box
 * rising through a free surface fed on that, and runs on 1 and 2 ranks
 * parted by 2.9e-4 m.)
 *
 * Face kernels take, for internal faces, owner and neighbour indices;
 * for boundary faces nei is NULL and the neighbour's values are given per
 * face (a coupled patch's other side): both sides compute the same.
 */
#include "vhe.h"

static int is_edge(double h, double lo) { return h >= lo && h < 1.0; }
static int is_out(double h, double lo) { return h < lo; }
static double pos(double a) { return a > 0.0 ? a : 0.0; }

/* The fluids' sum in cell c of K fractions a[k] */
static double fluid(int K, const double *const *a, long c)
{
    double F = 0.0;
    int k;
    for (k = 0; k < K; ++k) F += pos(a[k][c]);
    return F;
}

/* On face f: 1 if the owner is the edge cell, -1 if the neighbour is,
 * 0 if the face joins no edge cell to an outside cell holding fluid */
static int side(long f, const int *own, const int *nei, int K,
                const double *const *a, const double *held,
                const double *const *aNei, const double *heldNei, double lo)
{
    const double ho = held[own[f]];
    const double hn = nei ? held[nei[f]] : heldNei[f];
    if (is_edge(ho, lo) && is_out(hn, lo)) {
        return (nei ? fluid(K, a, nei[f]) : fluid(K, aNei, f)) > 0.0;
    }
    if (is_out(ho, lo) && is_edge(hn, lo)) {
        return fluid(K, a, own[f]) > 0.0 ? -1 : 0;
    }
    return 0;
}

void vhe_drain_links(long nFaces, const int *own, const int *nei, int K,
                     const double *const *a, const double *held,
                     const double *const *aNei, const double *heldNei,
                     double lo, double *links)
{
    long f;
    for (f = 0; f < nFaces; ++f) {
        if (!side(f, own, nei, K, a, held, aNei, heldNei, lo)) continue;
        links[own[f]] += 1.0;
        if (nei) links[nei[f]] += 1.0;
    }
}

void vhe_drain_range(long nFaces, const int *own, const int *nei, int K,
                     const double *const *a, const double *held,
                     const double *const *aNei, const double *heldNei,
                     double lo, double *const *sum, double *const *mn,
                     double *const *mx)
{
    long f;
    int k;
    for (f = 0; f < nFaces; ++f) {
        const int s = side(f, own, nei, K, a, held, aNei, heldNei, lo);
        long e, o = -1;
        const double *const *ao = a;
        double Fo;
        /* a boundary face's edge cell on the other side: its own */
        if (s == 0 || (s < 0 && !nei)) continue;
        if (s > 0) {
            e = own[f];
            if (nei) o = nei[f]; else { ao = aNei; o = f; }
        } else {
            e = nei[f];
            o = own[f];
        }
        Fo = fluid(K, ao, o);
        for (k = 0; k < K; ++k) {
            const double sk = pos(ao[k][o]) / Fo;
            sum[k][e] += sk;
            if (sk < mn[k][e]) mn[k][e] = sk;
            if (sk > mx[k][e]) mx[k][e] = sk;
        }
    }
}

void vhe_drain_lambda(long n, int K, const double *const *a,
                      const double *links, const double *const *sum,
                      const double *const *mn, const double *const *mx,
                      double *lambda)
{
    long c;
    int k;
    for (c = 0; c < n; ++c) {
        const double F = fluid(K, a, c);
        double L = 0.0;
        lambda[c] = 0.0;
        /* no range gathered: not an edge cell */
        if (!(links[c] > 0.0) || !(F > 0.0) || mx[0][c] < 0.0) continue;
        for (k = 0; k < K; ++k) {
            const double s = pos(a[k][c]) / F, m = sum[k][c] / links[c];
            double l = 0.0;
            if (s < mn[k][c] && m > s) l = (mn[k][c] - s) / (m - s);
            if (s > mx[k][c] && m < s) l = (s - mx[k][c]) / (s - m);
            if (l > L) L = l;
        }
        lambda[c] = L < 1.0 ? L : 1.0;
    }
}

/* Volumes t[k] moving from the outside cell (fractions ao, volume Vo,
 * links no) into the edge cell (ae, Ve, ne, lambda le) */
static void exchange(int K, const double *ae, double Ve, double ne,
                     double le, const double *ao, double Vo, double no,
                     double *t)
{
    double Fe = 0.0, Fo = 0.0, scale = 1.0;
    int k;
    for (k = 0; k < K; ++k) {
        Fe += pos(ae[k]);
        Fo += pos(ao[k]);
        t[k] = 0.0;
    }
    if (!(le > 0.0) || !(Fe > 0.0) || !(Fo > 0.0) || !(ne > 0.0)
        || !(no > 0.0)) {
        return;
    }
    for (k = 0; k < K; ++k) {
        t[k] = le * (Fe * pos(ao[k]) / Fo - pos(ae[k])) * Ve / ne;
        /* the outside cell gives each of its edge faces at most 1/no of
           what it holds */
        if (t[k] * scale > pos(ao[k]) * Vo / no) {
            scale = pos(ao[k]) * Vo / (no * t[k]);
        }
    }
    for (k = 0; k < K; ++k) t[k] *= scale;
}

void vhe_drain_faces(long nFaces, const int *own, const int *nei, int K,
                     const double *const *a, const double *held,
                     const double *V, const double *links,
                     const double *lambda, const double *const *aNei,
                     const double *heldNei, const double *VNei,
                     const double *linksNei, const double *lambdaNei,
                     double lo, double *const *d)
{
    double ae[VHE_DRAIN_MAX], ao[VHE_DRAIN_MAX], t[VHE_DRAIN_MAX];
    long f;
    int k;

    if (K > VHE_DRAIN_MAX) K = VHE_DRAIN_MAX;
    for (f = 0; f < nFaces; ++f) {
        const int o = own[f];
        const int s = side(f, own, nei, K, a, held, aNei, heldNei, lo);
        const double Vn = nei ? V[nei[f]] : VNei[f];
        const double ln = nei ? links[nei[f]] : linksNei[f];
        const double lamn = nei ? lambda[nei[f]] : lambdaNei[f];
        for (k = 0; k < K; ++k) {
            d[k][f] = 0.0;
            ae[k] = a[k][o];
            ao[k] = nei ? a[k][nei[f]] : aNei[k][f];
        }
        if (s > 0) {
            exchange(K, ae, V[o], links[o], lambda[o], ao, Vn, ln, t);
            for (k = 0; k < K; ++k) d[k][f] = t[k];
        } else if (s < 0) {
            exchange(K, ao, Vn, ln, lamn, ae, V[o], links[o], t);
            for (k = 0; k < K; ++k) d[k][f] = -t[k];
        }
    }
}
