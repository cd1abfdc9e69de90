/*
 * gw_test_overlap.h: the largest overlap u_n / R_p of a sample, R_p = 2 r_i
 * r_j / (r_i + r_j), over every pair of discs of different bodies and every
 * disc against the bottom and side walls, compared pair by pair (no grid): the
 * reference for layer-make's max_overlap, which takes its pairs from a cell
 * grid. Units: those of the sample (m); the result is dimensionless.
 */
#ifndef GW_TEST_OVERLAP_H
#define GW_TEST_OVERLAP_H

#include <math.h>

#include "gw_layer.h"

static inline double gw_test_max_overlap(const gw_layer_sample *s)
{
    double m = 0;
    for (int i = 0; i < s->n; i++) {
        const double ri = s->r[i];
        m = fmax(m, fmax((ri - s->y[i]) / ri, fmax((ri - s->x[i]) / ri, (ri - (s->width - s->x[i])) / ri)));
        for (int j = i + 1; j < s->n; j++) {
            if (s->body && s->body[i] == s->body[j])
                continue;
            const double d = hypot(s->x[j] - s->x[i], s->y[j] - s->y[i]), rp = 2 * ri * s->r[j] / (ri + s->r[j]);
            m = fmax(m, (ri + s->r[j] - d) / rp);
        }
    }
    return m;
}

#endif
