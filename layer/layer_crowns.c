/*
 * layer_crowns.c: shock-wave analysis on concentric crowns (docs/physics.md 2.5).
 *
 * Ring k holds distances [k d_c, (k+1) d_c) from the impact point. For each
 * ring, the arrival times of the strain-energy increase (over its value at
 * t = 0) and of the kinetic energy are the first local maxima that reach a
 * quarter of the ring's largest value (so reflections from the walls later in a long
 * run are not taken); a ring counts when its peak exceeds 1e-4 of the incident
 * energy and is not at the last sample.
 * The wave speed is the slope c of the least-squares line (GSL, gw_fit_linear)
 * r_k = r_0 + c t_k through the rings k >= 1 with a peak, with its standard
 * error; fewer than three rings give NaN. Ring 0 holds the impact itself.
 * Units: SI (m, s, m/s).
 */
#include <math.h>
#include <stdlib.h>

#include "gw_layer.h"

/* Time of the first arrival peak of series v[k * stride] (k < ns): the first
 * local maximum reaching a quarter of the series' largest value (later, larger
 * maxima from reflections at the walls do not count), or NaN when the series
 * never exceeds thr or the peak is the last sample. */
static double peak_time(const double *t, const double *v, int ns, int stride, double thr)
{
    double vmax = 0;
    for (int k = 0; k < ns; k++)
        vmax = fmax(vmax, v[(size_t)k * stride]);
    if (!(vmax > thr))
        return NAN;
    for (int k = 1; k < ns - 1; k++) {
        double a = v[(size_t)(k - 1) * stride], b = v[(size_t)k * stride], c = v[(size_t)(k + 1) * stride];
        if (b >= 0.25 * vmax && b >= a && b > c)
            return t[k];
    }
    return NAN;
}

static void fit(const gw_layer_impact_result *r, const double *tp, double *c, double *cerr,
                int *nused)
{
    double *x = malloc(2 * (size_t)r->nrings * sizeof *x);
    *c = *cerr = NAN;
    *nused = 0;
    if (!x)
        return;
    double *y = x + r->nrings;
    int m = 0;
    for (int k = 1; k < r->nrings; k++)
        if (isfinite(tp[k]))
            x[m] = tp[k], y[m] = r->ring_r[k], m++;
    gw_linfit f;
    if (m >= 3 && gw_fit_linear(x, y, m, &f) == GW_OK) {
        *c = f.c1;
        *cerr = f.c1_err;
    }
    *nused = m;
    free(x);
}

int gw_layer_crowns(gw_layer_impact_result *r)
{
    const double thr = 1e-4 * r->e_incident;
    for (int k = 0; k < r->nrings; k++) {
        r->peak_strain_t[k] = peak_time(r->t, r->ring_strain + k, r->ns, r->nrings, thr);
        r->peak_kin_t[k] = peak_time(r->t, r->ring_kin + k, r->ns, r->nrings, thr);
    }
    int nk;
    fit(r, r->peak_strain_t, &r->wave_speed, &r->wave_speed_err, &r->wave_rings);
    fit(r, r->peak_kin_t, &r->wave_speed_kin, &r->wave_speed_kin_err, &nk);
    return GW_OK;
}
