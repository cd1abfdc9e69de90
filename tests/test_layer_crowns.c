/*
 * test_layer_crowns.c: the crowns analysis (docs/physics.md 2.5) on synthetic ring
 * series with a known front speed.
 *
 * Ring k (mid radius r_k = (k + 1/2) d_c) sees a strain pulse peaking at
 * t_k = r_k / c and a kinetic pulse at t_k + 0.3 ms, Gaussian of width 0.2 ms,
 * sampled every 10 us; a later "reflection" pulse at 9 ms, three times larger,
 * must not be taken as the arrival (arrivals are first maxima reaching 1/4 of
 * the largest). The fit must return the least-squares speed of the true
 * (grid-rounded) arrival times to 1e-9 relative from both series (within 2 %
 * of 1000 m/s), use every ring k >= 1, and mark a ring without signal as NaN.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_layer.h"
#include "gw_test.h"

int main(void)
{
    const int nr = 8, ns = 1201;
    const double c = 1000, dc = 0.65, dt = 1e-5, w = 2e-4;
    gw_layer_impact_result r;
    memset(&r, 0, sizeof r);
    r.ns = ns;
    r.nrings = nr;
    r.e_incident = 1;
    r.t = malloc(ns * sizeof *r.t);
    r.ring_strain = calloc((size_t)ns * nr, sizeof *r.ring_strain);
    r.ring_kin = calloc((size_t)ns * nr, sizeof *r.ring_kin);
    r.peak_strain_t = malloc(3 * nr * sizeof *r.peak_strain_t);
    r.peak_kin_t = r.peak_strain_t + nr;
    r.ring_r = r.peak_strain_t + 2 * nr;
    for (int k = 0; k < ns; k++)
        r.t[k] = k * dt;
    for (int q = 0; q < nr; q++) {
        r.ring_r[q] = (q + 0.5) * dc;
        double tq = round(r.ring_r[q] / c / dt) * dt; /* on the sample grid */
        for (int k = 0; q < nr - 1 && k < ns; k++) {
            double t = r.t[k];
            r.ring_strain[k * nr + q] = 0.1 * exp(-pow((t - tq) / w, 2)) + 0.3 * exp(-pow((t - 9e-3) / w, 2));
            r.ring_kin[k * nr + q] = 0.2 * exp(-pow((t - tq - 3e-4) / w, 2));
        }
    }
    /* the grid rounding moves the peaks: the exact speed is the fit of the rounded times */
    gw_layer_crowns(&r);
    double tx[8], ry[8];
    int m = 0;
    for (int q = 1; q < nr - 1; q++)
        tx[m] = round(r.ring_r[q] / c / dt) * dt, ry[m] = r.ring_r[q], m++;
    gw_linfit f;
    gw_fit_linear(tx, ry, m, &f);
    gw_test_rel(r.wave_speed, f.c1, 1e-9, "wave speed from strain peaks (m/s) = fit of the true arrivals");
    gw_test_rel(r.wave_speed_kin, f.c1, 1e-9, "wave speed from kinetic peaks (m/s)");
    gw_test_rel(r.wave_speed, c, 2e-2, "wave speed close to the synthetic 1000 m/s (grid rounding)");
    gw_test_true(r.wave_rings == nr - 2, "rings k >= 1 with a signal are all used");
    gw_test_true(isnan(r.peak_strain_t[nr - 1]), "a ring without signal has no peak");
    gw_test_rel(r.peak_strain_t[3], round(r.ring_r[3] / c / dt) * dt, 1e-12,
                "arrival peak taken, not the later larger reflection (s)");
    free(r.t);
    free(r.ring_strain);
    free(r.ring_kin);
    free(r.peak_strain_t);
    return gw_test_summary("test_layer_crowns");
}
