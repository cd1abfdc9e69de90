/*
 * test_hostile_sixteenth.c: the crowns' estimators on inputs whose answer is known
 * (sixteenth hostile pass of issue 18).
 *
 * 1. Scale: the cross-correlation's lag and rho do not depend on the series' units.
 *    A Gaussian pulse (sigma 5 samples) and its copy 17.25 samples later, both times
 *    1e-150, 1e150 or 1e200, or the copy alone times 1e-200, must give lag 17.25
 *    (1e-6) and rho 1 (1e-9); before, 1e-150 was "identically zero" (status ZERO),
 *    1e150 gave rho 0 and 1e155 no peak (EDGE).
 * 2. A NaN or an infinite sample is no series: status NONFINITE, lag NaN (before:
 *    ZERO "identically zero" and EDGE).
 * 3. An anti-correlated pair (the copy negated) has no delay: before, a lag of 97.16
 *    at rho 3e-17 came back with status OK.
 * 4. Crowns with a NaN sample: rings at r_k = (k + 1/2) 0.65 m reached by a Gaussian
 *    pulse at 600 m/s (sampled every 20 us), ring 5's strain holding a NaN just after
 *    its peak and a smaller echo at 25 ms. Ring 5 has no arrival (before: the echo,
 *    25 ms, was taken for it), and the strain speed is the least-squares slope of the
 *    other rings' grid arrivals computed here (1e-12), with its standard error (1e-9).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_layer.h"
#include "gw_test.h"
#include "layer_test_util.h"
#include "gw_xcorr.h"

enum { N = 200 };

static gw_xcorr_peak peak(gw_xcorr *x, const double *a, const double *b)
{
    gw_xcorr_peak pk;
    memset(&pk, 0, sizeof pk);
    pk.status = -1;
    gw_xcorr_peak_find(x, a, b, N, 0, N / 2 - 1, GW_XCORR_FOURIER, &pk, NULL);
    return pk;
}

static void test_xcorr_edges(void)
{
    double a[N], b[N], sa[N], sb[N];
    gw_xcorr *x = NULL;
    gw_test_true(gw_xcorr_create(N, 0, &x, NULL) == GW_OK, "xcorr object");
    if (!x)
        return;
    for (int i = 0; i < N; i++)
        a[i] = exp(-pow((i - 50.0) / 5, 2)), b[i] = exp(-pow((i - 67.25) / 5, 2));
    const double scale[][2] = {{1e-150, 1e-150}, {1e150, 1e150}, {1e200, 1e200}, {1, 1e-200}};
    char what[160];
    for (int s = 0; s < 4; s++) {
        for (int i = 0; i < N; i++)
            sa[i] = a[i] * scale[s][0], sb[i] = b[i] * scale[s][1];
        gw_xcorr_peak pk = peak(x, sa, sb);
        snprintf(what, sizeof what, "series times %g and %g: status OK (got %d)", scale[s][0], scale[s][1], pk.status);
        gw_test_true(pk.status == GW_XCORR_PEAK_OK, what);
        snprintf(what, sizeof what, "series times %g and %g: lag 17.25", scale[s][0], scale[s][1]);
        gw_test_abs(pk.lag, 17.25, 1e-6, what);
        snprintf(what, sizeof what, "series times %g and %g: rho 1", scale[s][0], scale[s][1]);
        gw_test_abs(pk.rho, 1, 1e-9, what);
    }
    gw_xcorr_peak p1 = peak(x, a, b);
    for (int i = 0; i < N; i++)
        sa[i] = a[i] * 0x1p-100, sb[i] = b[i] * 0x1p-100;
    gw_xcorr_peak p2 = peak(x, sa, sb);
    gw_test_true(p1.lag == p2.lag && p1.rho == p2.rho && p2.value == p1.value * 0x1p-200,
                 "a power of 2 scales the value exactly and leaves lag and rho bit for bit");
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (int k = 0; k < 3; k++) {
        memcpy(sb, b, sizeof sb);
        sb[120] = bad[k];
        gw_xcorr_peak pk = peak(x, a, sb);
        snprintf(what, sizeof what, "a sample %g: status NONFINITE, lag NaN (got %d, %g)", bad[k], pk.status, pk.lag);
        gw_test_true(pk.status == GW_XCORR_PEAK_NONFINITE && isnan(pk.lag), what);
    }
    for (int i = 0; i < N; i++)
        sb[i] = -b[i];
    gw_xcorr_peak pk = peak(x, a, sb);
    snprintf(what, sizeof what, "anti-correlated: no delay (got status %d, lag %g, rho %g)", pk.status, pk.lag, pk.rho);
    gw_test_true(pk.status == GW_XCORR_PEAK_NOT_POSITIVE && isnan(pk.lag), what);
    gw_xcorr_free(x);
}

/* Slope of y on x by least squares and its standard error, written out here. */
static void own_fit(const double *x, const double *y, int m, double *b, double *se)
{
    double mx = 0, my = 0, sxx = 0, sxy = 0, ss = 0;
    for (int i = 0; i < m; i++)
        mx += x[i] / m, my += y[i] / m;
    for (int i = 0; i < m; i++)
        sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
    *b = sxy / sxx;
    for (int i = 0; i < m; i++)
        ss += pow(y[i] - (my + *b * (x[i] - mx)), 2);
    *se = sqrt(ss / (m - 2) / sxx);
}

static void test_crowns_nan(void)
{
    enum { nr = 12, ns = 1500 };
    const double c = 600, dc = 0.65, dt = 2e-5, w = 5e-4;
    gw_layer_impact_result r = test_crowns_result(nr, ns, dt);
    double x[nr], y[nr];
    int m = 0;
    for (int q = 0; q < nr; q++) {
        r.ring_r[q] = (q + 0.5) * dc;
        const double T = r.ring_r[q] / c;
        for (int k = 0; k < ns; k++) {
            const double u = r.t[k] - T, e = r.t[k] - 0.025;
            r.ring_strain[k * nr + q] = 0.1 * exp(-u * u / (w * w)) + (q == 5 ? 0.05 * exp(-e * e / (w * w)) : 0);
            r.ring_kin[k * nr + q] = 0.1 * exp(-pow(u - 2e-4, 2) / (w * w));
        }
        const int kp = (int)lround(T / dt); /* the grid sample nearest the arrival is the largest */
        if (q == 5)
            r.ring_strain[(kp + 1) * nr + q] = NAN;
        else if (q >= 1)
            x[m] = r.t[kp], y[m] = r.ring_r[q], m++;
    }
    gw_layer_crowns(&r);
    char what[160];
    snprintf(what, sizeof what, "ring 5 with a NaN sample has no arrival (got %g s)", r.peak_strain_t[5]);
    gw_test_true(isnan(r.peak_strain_t[5]), what);
    double b, se;
    own_fit(x, y, m, &b, &se);
    gw_test_true(r.wave_rings == m, "the strain fit uses the 10 other rings");
    gw_test_rel(r.wave_speed, b, 1e-12, "strain speed = own least squares of the grid arrivals");
    gw_test_rel(r.wave_speed_err, se, 1e-9, "its standard error = own");
    gw_test_rel(r.wave_speed_xcorr, c, 1e-6, "cross-correlation speed 600 m/s without the NaN ring's pairs");
    gw_test_true(isnan(r.xcorr_delay[4]) && isnan(r.xcorr_delay[5]), "the NaN ring's two pairs are left out");
    test_crowns_result_free(&r);
}

int main(void)
{
    test_xcorr_edges();
    test_crowns_nan();
    return gw_test_summary("test_hostile_sixteenth");
}
