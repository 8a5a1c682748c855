/*
 * tension.c -- the curvature of an interface from its heights (Cummins,
 * Francois & Kothe 2005; Popinet 2009).
 */
#include <math.h>

#include "vhe.h"

double vhe_height_curvature(const double h[9], double d1, double d2,
                            int dim)
{
    /* h[3 (i + 1) + (j + 1)] is the height at offsets (i, j) */
#define H(i, j) h[3 * ((i) + 1) + ((j) + 1)]
    const double h1 = (H(1, 0) - H(-1, 0)) / (2 * d1);
    const double h11 = (H(1, 0) - 2 * H(0, 0) + H(-1, 0)) / (d1 * d1);
    double h2, h22, h12;
    if (dim == 2) {
        return -h11 / pow(1 + h1 * h1, 1.5);
    }
    h2 = (H(0, 1) - H(0, -1)) / (2 * d2);
    h22 = (H(0, 1) - 2 * H(0, 0) + H(0, -1)) / (d2 * d2);
    h12 = (H(1, 1) - H(1, -1) - H(-1, 1) + H(-1, -1)) / (4 * d1 * d2);
    return -(h11 * (1 + h2 * h2) + h22 * (1 + h1 * h1) - 2 * h12 * h1 * h2)
           / pow(1 + h1 * h1 + h2 * h2, 1.5);
#undef H
}
