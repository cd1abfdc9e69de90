/*
 * test_xcorr.c: FFT cross-correlation and sub-sample delays (common/gw_xcorr.c)
 * on synthetic series with known delays.
 *
 * 1. The correlation series equals the direct sum c[L] = sum_i a[i] b[i+L] to
 *    1e-12 of its largest value (random series shorter than the plans).
 * 2. Clean pulses delayed by d samples, sampled analytically (b[i] = p(i - d)):
 *    Gaussians (sigma 2, 3, 5, 10 samples) and crown-like asymmetric pulses (a
 *    gamma pulse (t/th)^4 e^(-t/th) with a fast rise and a slow tail, a
 *    log-normal pulse), integer and fractional d, positive and negative. The
 *    Fourier refinement must find d to 1e-3 sample (the goal; its only error is
 *    the pulses' aliasing, below 1e-6 for these widths). The parabolic vertex
 *    must equal the vertex computed from the closed form of a Gaussian's
 *    sampled correlation, sqrt(pi) sigma exp(-(L - d)^2 / (4 sigma^2)) (Poisson
 *    summation, aliasing below 1e-15 for sigma >= 2), to 1e-9 sample: so its
 *    bias is known exactly, and it must be below 0.03 sample for sigma >= 3.
 * 3. Noise: white Gaussian noise of standard deviation s_n on both series
 *    (SNR = peak / s_n = 200 and 50). With S = sum_i p'(i)^2, the slope of the
 *    correlation at d is perturbed by sum p'(i) (n_a(i) - n_b(i + d)) (variance
 *    2 s_n^2 S) and by the noise-noise term sum n_a(i) n_b'(i + d) (variance
 *    (n - d) s_n^4 pi^2 / 3, the derivative of band-limited white noise), and
 *    divided by the curvature -S: var = (2 s_n^2 S + (n - d) s_n^4 pi^2/3) / S^2.
 *    Over 400 draws the RMS error of the Fourier refinement must be within 15 %
 *    of that (the RMS of 400 draws scatters by 3.5 %); the parabola, which
 *    smooths the noise above the pulse's band, must lie between 0.9 x the
 *    first-order term and 1.1 x the whole; both means within 4 standard errors.
 * 4. A pulse with a plateau cut by the end of the record (a ring's energy that
 *    stays raised) is not a shifted copy of itself inside the record: its delay
 *    is biased (measured, must exceed 0.1 sample here), while its sample
 *    differences are pulses again and give d to 1e-3 sample.
 * 5. The lag window: a largest value on its edge is no peak (EDGE, NaN); a zero
 *    series is ZERO; equal series give lag 0 to 1e-12.
 * 6. Bad input (length, window, method, dt) is GW_EINVAL with a message.
 * 7. PSD: Parseval, sum psd df = mean square, to 1e-12; a sine of amplitude A
 *    on a frequency bin peaks there with psd = T A^2 / 2, to 1e-9.
 * 8. Threads: two threads creating, using and freeing objects at once (the
 *    planner serialised by the module; FFTW_ESTIMATE, so the plans do not depend
 *    on timings) give bit-identical delays to one thread. (Without the lock no
 *    crash showed in 20 runs either: a planner race is rare, so this checks the
 *    numbers under concurrency, not the lock itself.)
 */
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gw_test.h"
#include "gw_xcorr.h"

/* splitmix64 and Box-Muller: deterministic noise */
static uint64_t rng_state = 12345;
static double urand(void)
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return ((z >> 11) + 0.5) / 9007199254740992.0;
}
static double grand(void)
{
    return sqrt(-2 * log(urand())) * cos(2 * M_PI * urand());
}

typedef double (*pulse_fn)(double t, double w);
static double gauss(double t, double w) { return exp(-0.5 * t * t / (w * w)); }
static double gamma4(double t, double w) { return t > 0 ? pow(t / w, 4) * exp(-t / w) : 0; }
static double lognorm(double t, double w)
{
    return t > 0 ? exp(-0.5 * pow(log(t / (4 * w)) / 0.45, 2)) : 0;
}
/* rise to a plateau of 0.4 with a pulse on top (a ring's energy that stays raised) */
static double plateau(double t, double w) { return 0.4 * (1 + erf(t / w)) / 2 + gauss(t - w, w); }

static void fill(double *v, int n, pulse_fn p, double t0, double w)
{
    for (int i = 0; i < n; i++)
        v[i] = p(i - t0, w);
}

static double delay_of(gw_xcorr *x, const double *a, const double *b, int m, int method)
{
    gw_xcorr_peak pk;
    gw_err err = {{0}};
    if (gw_xcorr_peak_find(x, a, b, m, -(m - 1) / 2, (m - 1) / 2, method, &pk, &err) != GW_OK)
        return NAN;
    return pk.status == GW_XCORR_PEAK_OK ? pk.lag : NAN;
}

static void test_series(void)
{
    enum { N = 300, m = 211 };
    gw_xcorr *x = NULL;
    gw_err err = {{0}};
    gw_test_true(gw_xcorr_create(N, 0, &x, &err) == GW_OK, "create for 300 samples");
    gw_test_true(gw_xcorr_fft_len(x) >= 2 * N - 1 && gw_xcorr_fft_len(x) % 2 == 0, "padded length even, >= 2n - 1");
    double a[m], b[m], c[2 * m - 1];
    for (int i = 0; i < m; i++)
        a[i] = urand() - 0.3, b[i] = urand() - 0.6;
    gw_test_true(gw_xcorr_series(x, a, b, m, c, &err) == GW_OK, "correlation series");
    double worst = 0, cmax = 0;
    for (int L = -(m - 1); L <= m - 1; L++) {
        double s = 0;
        for (int i = 0; i < m; i++)
            if (i + L >= 0 && i + L < m)
                s += a[i] * b[i + L];
        worst = fmax(worst, fabs(s - c[L + m - 1]));
        cmax = fmax(cmax, fabs(s));
    }
    gw_test_abs(worst / cmax, 0, 1e-12, "FFT correlation = direct sum (relative to its largest value)");
    gw_xcorr_free(x);
}

static void test_clean(void)
{
    enum { n = 400 };
    gw_xcorr *x = NULL;
    gw_err err = {{0}};
    gw_xcorr_create(n, 1, &x, &err);
    double a[n], b[n];
    const double ds[] = {17, 17.25, 17.5, 0.3, -9.73, 41.001};
    const struct { pulse_fn p; double w; const char *name; } P[] = {
        {gauss, 2, "Gaussian sigma 2"}, {gauss, 3, "Gaussian sigma 3"}, {gauss, 5, "Gaussian sigma 5"},
        {gauss, 10, "Gaussian sigma 10"}, {gamma4, 4, "gamma pulse (t/4)^4 e^(-t/4)"},
        {lognorm, 5, "log-normal pulse"}};
    for (size_t q = 0; q < sizeof P / sizeof P[0]; q++) {
        double worst = 0, worst_par = 0, worst_pred = 0;
        for (size_t k = 0; k < sizeof ds / sizeof ds[0]; k++) {
            fill(a, n, P[q].p, 150, P[q].w);
            fill(b, n, P[q].p, 150 + ds[k], P[q].w);
            double df = delay_of(x, a, b, n, GW_XCORR_FOURIER), dp = delay_of(x, a, b, n, GW_XCORR_PARABOLIC);
            worst = fmax(worst, isfinite(df) ? fabs(df - ds[k]) : INFINITY);
            worst_par = fmax(worst_par, fabs(dp - ds[k]));
            if (P[q].p == gauss) { /* parabola through the closed-form sampled correlation */
                const double s2 = 4 * P[q].w * P[q].w;
                const int L = (int)lround(ds[k]);
                const double ym = exp(-pow(L - 1 - ds[k], 2) / s2), y0 = exp(-pow(L - ds[k], 2) / s2),
                             yp = exp(-pow(L + 1 - ds[k], 2) / s2);
                const double pred = L + 0.5 * (ym - yp) / (ym - 2 * y0 + yp);
                worst_pred = fmax(worst_pred, fabs(dp - pred));
            }
        }
        char what[160];
        snprintf(what, sizeof what, "%s: Fourier refinement, worst |delay error| over 6 delays (samples)", P[q].name);
        gw_test_abs(worst, 0, 1e-3, what);
        printf("  %s: parabolic worst |error| %.3g samples\n", P[q].name, worst_par);
        if (P[q].p == gauss) {
            snprintf(what, sizeof what, "%s: parabolic vertex = the closed form's (samples)", P[q].name);
            gw_test_abs(worst_pred, 0, 1e-9, what);
            if (P[q].w >= 3) {
                snprintf(what, sizeof what, "%s: parabolic bias below 0.03 sample", P[q].name);
                gw_test_abs(worst_par, 0, 0.03, what);
            }
        }
    }
    /* the bias of the parabola is real: sigma 2 at d = 17.25 */
    fill(a, n, gauss, 150, 2);
    fill(b, n, gauss, 167.25, 2);
    double dp = delay_of(x, a, b, n, GW_XCORR_PARABOLIC);
    gw_test_true(fabs(dp - 17.25) > 1e-3, "parabolic vertex biased for a narrow peak (sigma 2, d = 17.25)");
    printf("  parabolic bias at sigma 2, d = 17.25: %.4f sample\n", dp - 17.25);
    gw_xcorr_free(x);
}

static void test_noise(void)
{
    enum { n = 256, draws = 400 };
    const double w = 5, d = 20.37;
    gw_xcorr *x = NULL;
    gw_err err = {{0}};
    gw_xcorr_create(n, 0, &x, &err);
    double a[n], b[n], a0[n], b0[n];
    fill(a0, n, gauss, 100, w);
    fill(b0, n, gauss, 100 + d, w);
    double S = 0; /* sum of p'(i)^2 */
    for (int i = 0; i < n; i++) {
        double t = i - 100;
        S += pow(-t / (w * w) * gauss(t, w), 2);
    }
    const double sns[] = {0.005, 0.02}; /* SNR (peak / noise) 200 and 50 */
    for (int q = 0; q < 2; q++) {
        const double sn = sns[q];
        const double first = sqrt(2 * sn * sn / S);
        const double full = sqrt((2 * sn * sn * S + (n - d) * pow(sn, 4) * M_PI * M_PI / 3) / (S * S));
        for (int method = GW_XCORR_PARABOLIC; method <= GW_XCORR_FOURIER; method++) {
            double s1 = 0, s2 = 0;
            for (int k = 0; k < draws; k++) {
                for (int i = 0; i < n; i++)
                    a[i] = a0[i] + sn * grand(), b[i] = b0[i] + sn * grand();
                double e = delay_of(x, a, b, n, method) - d;
                s1 += e, s2 += e * e;
            }
            const double mean = s1 / draws, rms = sqrt(s2 / draws);
            const char *mn = method == GW_XCORR_FOURIER ? "Fourier" : "parabolic";
            char what[200];
            if (method == GW_XCORR_FOURIER) {
                snprintf(what, sizeof what, "noisy Gaussians (SNR %.0f), Fourier: RMS delay error (samples) = theory "
                         "with the noise-noise term", 1 / sn);
                gw_test_rel(rms, full, 0.15, what);
            } else {
                snprintf(what, sizeof what, "noisy Gaussians (SNR %.0f), parabolic: RMS %.4g between 0.9 x the "
                         "first-order %.4g and 1.1 x the full theory %.4g", 1 / sn, rms, first, full);
                gw_test_true(rms > 0.9 * first && rms < 1.1 * full, what);
            }
            snprintf(what, sizeof what, "noisy Gaussians (SNR %.0f), %s: mean error within 4 standard errors (samples)",
                     1 / sn, mn);
            gw_test_abs(mean, 0, 4 * rms / sqrt(draws), what);
        }
    }
    gw_xcorr_free(x);
}

static void test_plateau(void)
{
    enum { n = 300 };
    const double d = 23.4, w = 6;
    gw_xcorr *x = NULL;
    gw_err err = {{0}};
    gw_xcorr_create(n, 0, &x, &err);
    double a[n], b[n], da[n - 1], db[n - 1];
    fill(a, n, plateau, 120, w);
    fill(b, n, plateau, 120 + d, w);
    for (int i = 0; i + 1 < n; i++)
        da[i] = a[i + 1] - a[i], db[i] = b[i + 1] - b[i];
    double raw = delay_of(x, a, b, n, GW_XCORR_FOURIER), dif = delay_of(x, da, db, n - 1, GW_XCORR_FOURIER);
    printf("  plateau cut by the record's end: raw series give %.4f, differences %.6f (true %.1f)\n", raw, dif, d);
    gw_test_true(fabs(raw - d) > 0.1, "raw series with a cut plateau: delay biased by more than 0.1 sample");
    gw_test_abs(dif, d, 1e-3, "their sample differences: delay to 1e-3 sample");
    gw_xcorr_free(x);
}

static void test_edges_and_errors(void)
{
    enum { n = 200 };
    gw_xcorr *x = NULL;
    gw_err err = {{0}};
    gw_xcorr_create(n, 0, &x, &err);
    double a[n], b[n], z[n];
    fill(a, n, gauss, 100, 4);
    fill(b, n, gauss, 95, 4); /* 5 samples early */
    memset(z, 0, sizeof z);
    gw_xcorr_peak pk;
    gw_test_true(gw_xcorr_peak_find(x, a, b, n, 0, 50, GW_XCORR_FOURIER, &pk, &err) == GW_OK &&
                 pk.status == GW_XCORR_PEAK_EDGE && isnan(pk.lag) && pk.lag_int == 0,
                 "a delay of -5 outside the window [0, 50]: EDGE, NaN");
    gw_test_true(gw_xcorr_peak_find(x, a, b, n, -50, 50, GW_XCORR_FOURIER, &pk, &err) == GW_OK &&
                 pk.status == GW_XCORR_PEAK_OK && fabs(pk.lag + 5) < 1e-6 && fabs(pk.rho - 1) < 1e-9,
                 "negative delay -5 found, rho = 1");
    gw_test_true(gw_xcorr_peak_find(x, a, z, n, -50, 50, GW_XCORR_FOURIER, &pk, &err) == GW_OK &&
                 pk.status == GW_XCORR_PEAK_ZERO && isnan(pk.lag), "zero series: ZERO, NaN");
    gw_test_true(gw_xcorr_peak_find(x, a, a, n, -50, 50, GW_XCORR_FOURIER, &pk, &err) == GW_OK &&
                 pk.status == GW_XCORR_PEAK_OK && fabs(pk.lag) < 1e-12, "equal series: lag 0");
    gw_test_true(gw_xcorr_peak_find(x, a, b, n + 1, -5, 5, 1, &pk, &err) == GW_EINVAL && strstr(err.msg, "201"),
                 "more samples than planned refused, message names the count");
    gw_test_true(gw_xcorr_peak_find(x, a, b, n, 5, 5, 1, &pk, &err) == GW_EINVAL && strstr(err.msg, "window"),
                 "empty lag window refused");
    gw_test_true(gw_xcorr_peak_find(x, a, b, n, -n, 5, 1, &pk, &err) == GW_EINVAL, "window beyond the lags refused");
    gw_test_true(gw_xcorr_peak_find(x, a, b, n, -5, 5, 7, &pk, &err) == GW_EINVAL, "unknown method refused");
    double psd[1024];
    gw_test_true(gw_xcorr_psd(x, a, n, 0, psd, &err) == GW_EINVAL && strstr(err.msg, "step"), "dt = 0 refused");
    gw_xcorr *y = x; /* must come back NULL */
    gw_test_true(gw_xcorr_create(1, 0, &y, &err) == GW_EINVAL && y == NULL && strstr(err.msg, "length 1"),
                 "one-sample plans refused, *out NULL");
    gw_xcorr_free(NULL);
    gw_xcorr_free(x);
}

static void test_psd(void)
{
    enum { m = 500 };
    const double dt = 1e-4, A = 3;
    gw_xcorr *x = NULL;
    gw_err err = {{0}};
    gw_xcorr_create(m, 0, &x, &err);
    const int M = gw_xcorr_fft_len(x), nf = M / 2 + 1;
    double *psd = malloc((size_t)nf * sizeof *psd), a[m];
    double ms = 0;
    for (int i = 0; i < m; i++)
        a[i] = urand() - 0.5, ms += a[i] * a[i] / m;
    gw_xcorr_psd(x, a, m, dt, psd, &err);
    double s = 0, df = 1 / (M * dt);
    for (int l = 0; l < nf; l++)
        s += psd[l] * df;
    gw_test_rel(s, ms, 1e-12, "Parseval: sum psd df = mean square");
    const int k = 37; /* 37 whole cycles over the record */
    for (int i = 0; i < m; i++)
        a[i] = A * sin(2 * M_PI * k * i / m);
    gw_xcorr_psd(x, a, m, dt, psd, &err);
    int lmax = 0;
    for (int l = 1; l < nf; l++)
        if (psd[l] > psd[lmax])
            lmax = l;
    const double f0 = k / (m * dt);
    gw_test_abs(lmax * df, f0, 1e-9 * f0, "sine: peak at its frequency (Hz)");
    gw_test_rel(psd[lmax], m * dt * A * A / 2, 1e-9, "sine: psd at its frequency = T A^2 / 2");
    free(psd);
    gw_xcorr_free(x);
}

/* threads: create, correlate, free, many times, different lengths */
typedef struct { double out[40]; } thread_res;
static void *worker(void *arg)
{
    thread_res *r = arg;
    for (int k = 0; k < 40; k++) {
        int n = 100 + 7 * k;
        gw_xcorr *x = NULL;
        gw_err err = {{0}};
        double *a = malloc(2 * (size_t)n * sizeof *a), *b = a + n;
        if (gw_xcorr_create(n, 0, &x, &err) == GW_OK && a) { /* ESTIMATE: plans chosen without timing */
            fill(a, n, gamma4, 20, 3 + 0.1 * k);
            fill(b, n, gamma4, 20 + 11.3 + 0.01 * k, 3 + 0.1 * k);
            r->out[k] = delay_of(x, a, b, n, GW_XCORR_FOURIER);
        } else {
            r->out[k] = NAN;
        }
        free(a);
        gw_xcorr_free(x);
    }
    return NULL;
}

static void test_threads(void)
{
    thread_res one, t1, t2;
    worker(&one);
    pthread_t th[2];
    int ok = pthread_create(&th[0], NULL, worker, &t1) == 0 && pthread_create(&th[1], NULL, worker, &t2) == 0;
    if (ok)
        pthread_join(th[0], NULL), pthread_join(th[1], NULL);
    gw_test_true(ok && memcmp(one.out, t1.out, sizeof one.out) == 0 && memcmp(one.out, t2.out, sizeof one.out) == 0,
                 "two threads planning and correlating at once = one thread, bit for bit");
    double worst = 0;
    for (int k = 0; k < 40; k++)
        worst = fmax(worst, fabs(one.out[k] - (11.3 + 0.01 * k)));
    gw_test_abs(worst, 0, 1e-3, "their delays (gamma pulses, 40 lengths) to 1e-3 sample");
}

int main(void)
{
    test_series();
    test_clean();
    test_noise();
    test_plateau();
    test_edges_and_errors();
    test_psd();
    test_threads();
    return gw_test_summary("test_xcorr");
}
