/*
 * drain.c -- the fluids in a drawn rigid body's edge cells (vheMixture's
 * drainEdges).
 *
 * A rigid body's edge cells move wholly with it: their faces carry its
 * rigid flux, so the fluids in them keep their mix wherever the body
 * goes.  A light body that rises through a free surface carries a row of
 * water into the air on its top, whose weight sinks it (a tenth-density
 * box floated 7 mm, two thirds of its draft, too deep).  Which fluid
 * fills the part of an edge cell the body leaves is not resolved by the
 * mesh; it is the fluid beside the body.  So each edge cell's fluids take
 * the composition of its face neighbours outside the body, each such
 * face moving 1/n of the difference (n the edge cell's outside faces)
 * between the two cells as an exchange of volumes that sums to zero: no
 * cell's total changes, and every fluid's volume is kept to round-off.
 *
 * A cell is an edge cell where lo <= held < 1 (held the drawn bodies'
 * sum; lo the fraction from which a cell moves wholly with its body),
 * outside where held < lo: its fluids move with the flow.  (With lo at
 * round-off, 1e-6, a cell that a tilted body's corner reached by 1e-6
 * took its neighbours' fluids wholly in one step; the tilt of a box
 * rising through a free surface fed on that, 3e-3 rad by t = 0.48
 * against 6e-6, and runs on 1 and 2 ranks parted.)  Face kernels take, for
 * internal faces, owner and neighbour indices; for boundary faces nei is
 * NULL and the neighbour's values are given per face (a coupled patch's
 * other side), the same sums computed on both sides.
 */
#include "vhe.h"

static int is_edge(double h, double lo) { return h >= lo && h < 1.0; }
static int is_out(double h, double lo) { return h < lo; }
static double pos(double a) { return a > 0.0 ? a : 0.0; }

void vhe_drain_links(long nFaces, const int *own, const int *nei,
                     const double *held, const double *heldNei, double lo,
                     double *links)
{
    long f;
    for (f = 0; f < nFaces; ++f) {
        const double ho = held[own[f]];
        const double hn = nei ? held[nei[f]] : heldNei[f];
        const int pair = (is_edge(ho, lo) && is_out(hn, lo))
                      || (is_out(ho, lo) && is_edge(hn, lo));
        if (!pair) continue;
        links[own[f]] += 1.0;
        if (nei) links[nei[f]] += 1.0;
    }
}

/* Volumes t[k] moving from the outside cell (fractions ao, volume Vo,
 * no) into the edge cell (ae, Ve, ne), n the cells' link counts */
static void exchange(int K, const double *ae, double Ve, double ne,
                     const double *ao, double Vo, double no, double *t)
{
    double Fe = 0.0, Fo = 0.0, lambda = 1.0;
    int k;
    for (k = 0; k < K; ++k) {
        Fe += pos(ae[k]);
        Fo += pos(ao[k]);
    }
    for (k = 0; k < K; ++k) t[k] = 0.0;
    if (!(Fe > 0.0) || !(Fo > 0.0) || !(ne > 0.0) || !(no > 0.0)) return;
    for (k = 0; k < K; ++k) {
        t[k] = (Fe * pos(ao[k]) / Fo - pos(ae[k])) * Ve / ne;
        /* the outside cell gives each of its edge faces at most 1/no of
           what it holds */
        if (t[k] > pos(ao[k]) * Vo / no) lambda = pos(ao[k]) * Vo / (no * t[k]);
    }
    for (k = 0; k < K; ++k) t[k] *= lambda;
}

void vhe_drain_faces(long nFaces, const int *own, const int *nei, int K,
                     const double *const *a, const double *held,
                     const double *V, const double *links,
                     const double *const *aNei, const double *heldNei,
                     const double *VNei, const double *linksNei, double lo,
                     double *const *d)
{
    double ae[VHE_DRAIN_MAX], ao[VHE_DRAIN_MAX], t[VHE_DRAIN_MAX];
    long f;
    int k;

    if (K > VHE_DRAIN_MAX) K = VHE_DRAIN_MAX;
    for (f = 0; f < nFaces; ++f) {
        const int o = own[f];
        const double ho = held[o];
        const double hn = nei ? held[nei[f]] : heldNei[f];
        const double Vn = nei ? V[nei[f]] : VNei[f];
        const double ln = nei ? links[nei[f]] : linksNei[f];
        for (k = 0; k < K; ++k) {
            d[k][f] = 0.0;
            ao[k] = nei ? a[k][nei[f]] : aNei[k][f];
        }
        if (is_edge(ho, lo) && is_out(hn, lo)) {
            for (k = 0; k < K; ++k) ae[k] = a[k][o];
            exchange(K, ae, V[o], links[o], ao, Vn, ln, t);
            for (k = 0; k < K; ++k) d[k][f] = t[k];
        } else if (is_out(ho, lo) && is_edge(hn, lo)) {
            for (k = 0; k < K; ++k) ae[k] = a[k][o];
            exchange(K, ao, Vn, ln, ae, V[o], links[o], t);
            for (k = 0; k < K; ++k) d[k][f] = -t[k];
        }
    }
}
