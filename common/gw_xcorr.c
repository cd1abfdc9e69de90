/*
 * gw_xcorr.c: cross-correlation of two real series by FFT (FFTW's real
 * halfcomplex transforms R2HC / HC2R),
 * the lag of its peak to a fraction of a sample, and one-sided power spectra.
 *
 * Series a, b of m <= n samples are zero-padded to M >= 2n - 1, so the circular
 * correlation of the padded series is the linear one:
 *     c[L] = sum_i a[i] b[i + L] = (1/M) IDFT(X)[L mod M],   X_l = conj(A_l) B_l,
 * with A, B the length-M DFTs; L = -(m-1) .. m-1.
 * Sub-sample lag of the largest c[L*] (L* inside the lag window):
 *   parabolic: vertex of the parabola through c at L* - 1, L*, L* + 1,
 *       delta = (c[L*-1] - c[L*+1]) / (2 (c[L*-1] - 2 c[L*] + c[L*+1])),  |delta| <= 1/2;
 *     its bias depends on the peak's shape (for a Gaussian correlation peak it
 *     pulls toward the nearest integer, vanishing at delta = 0 and 1/2);
 *   fourier: the maximum of the trigonometric interpolant of the padded correlation
 *       c(tau) = (1/M) sum_{l=0}^{M/2} w_l Re( X_l e^{i theta_l tau} ),
 *       theta_l = 2 pi l / M, w_0 = w_{M/2} = 1, w_l = 2 otherwise (M even),
 *     which equals c[L] at every integer L; the root of
 *       c'(tau) = -(1/M) sum w_l theta_l Im( X_l e^{i theta_l tau} )
 *     is bracketed between L* and L* +- 1 and found by Newton steps with a
 *     bisection safeguard (c''(tau) = -(1/M) sum w_l theta_l^2 Re(...)). For
 *     band-limited series whose correlation lies inside the padded window the
 *     interpolant is the correlation of the underlying continuous signals
 *     (sampled products of band-limited functions keep Parseval's identity), so
 *     the peak is exact; the remaining error is the series' aliasing and noise.
 * Normalised peak rho = c(peak) / sqrt(sum a^2 sum b^2), c(peak) the refined
 * value (|rho| <= 1 at integer lags by Cauchy-Schwarz, and for band-limited
 * series between them; so 1 for a series and its shifted copy).
 * One-sided PSD on the padded grid f_l = l / (M dt), l = 0 .. M/2:
 *   P_l = g_l dt |A_l|^2 / m,  g_0 = g_{M/2} = 1, g_l = 2 otherwise,
 * so that sum_l P_l df = (1/m) sum_i a_i^2 (Parseval; df = 1 / (M dt)).
 * Units: lags in samples, P in (unit of a)^2 / Hz.
 * The transforms are FFTW's r2r R2HC and HC2R of the same DFT, not its r2c and
 * c2r: at FFTW_ESTIMATE the planner took 4.5 ms of CPU for the r2c / c2r pair
 * of 5040 points (a default layer impact's 2,501 samples: 5 % of its CPU) and
 * 0.5 ms for the r2r pair; the executions cost about the same. A halfcomplex
 * array holds Re A_0 .. Re A_(M/2), then Im A_(M/2-1) .. Im A_1 (M even).
 * FFTW's planner is not thread-safe: plan creation and destruction hold the one
 * process-wide lock below (the only file-scope state: a lock, not data).
 */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include <fftw3.h>

#include "gw_global.h"
#include "gw_xcorr.h"

#define GW_XCORR_MAX_N (1 << 26)

/* fork() while another thread plans: the child got the lock held by a thread it
 * does not have, and its first FFT waited for ever (Python's multiprocessing,
 * fork start method). The fork waits for the planner instead (gw_global.h). */
static gw_forklock planner_lock = GW_FORKLOCK(NULL);

void gw_fftw_planner_lock(void)
{
    gw_forklock_take(&planner_lock);
}

void gw_fftw_planner_unlock(void)
{
    gw_forklock_give(&planner_lock);
}

struct gw_xcorr {
    int n, M, nf;        /* series length limit, padded length, M/2 + 1 */
    double *in, *out;    /* [M] */
    double *hc;          /* [M] halfcomplex: R2HC's output, HC2R's input */
    fftw_complex *fa;    /* [nf] transform of `in` */
    fftw_complex *xs;    /* [nf] cross-spectrum conj(A) B of the last correlation */
    fftw_plan r2hc, hc2r;
};

/* Smallest even 2^p 3^q 5^r 7^s >= k (k >= 2): sizes FFTW transforms fast. */
static int fft_size(long k)
{
    long best = 2;
    while (best < k)
        best <<= 1;
    for (long p2 = 2; p2 < 2 * k; p2 *= 2)
        for (long p3 = p2; p3 < 2 * k; p3 *= 3)
            for (long p5 = p3; p5 < 2 * k; p5 *= 5)
                for (long p7 = p5; p7 < 2 * k; p7 *= 7)
                    if (p7 >= k && p7 < best)
                        best = p7;
    return (int)best;
}

int gw_xcorr_create(int n, int measure, gw_xcorr **out, gw_err *err)
{
    *out = NULL;
    if (n < 2 || n > GW_XCORR_MAX_N)
        return gw_err_set(err, GW_EINVAL, "cross-correlation: series length %d is outside [2, %d]", n,
                          GW_XCORR_MAX_N);
    gw_xcorr *x = calloc(1, sizeof *x);
    if (!x)
        return gw_err_set(err, GW_ENOMEM, "cross-correlation: out of memory");
    x->n = n;
    x->M = fft_size(2L * n - 1);
    x->nf = x->M / 2 + 1;
    x->in = fftw_malloc((size_t)x->M * sizeof *x->in);
    x->out = fftw_malloc((size_t)x->M * sizeof *x->out);
    x->hc = fftw_malloc((size_t)x->M * sizeof *x->hc);
    x->fa = fftw_malloc((size_t)x->nf * sizeof *x->fa);
    x->xs = fftw_malloc((size_t)x->nf * sizeof *x->xs);
    if (x->in && x->out && x->hc && x->fa && x->xs) {
        /* plans first: FFTW_MEASURE overwrites the arrays */
        unsigned flags = measure ? FFTW_MEASURE : FFTW_ESTIMATE;
        gw_fftw_planner_lock();
        x->r2hc = fftw_plan_r2r_1d(x->M, x->in, x->hc, FFTW_R2HC, flags);
        x->hc2r = fftw_plan_r2r_1d(x->M, x->hc, x->out, FFTW_HC2R, flags);
        gw_fftw_planner_unlock();
    }
    if (!x->r2hc || !x->hc2r) {
        gw_xcorr_free(x);
        return gw_err_set(err, GW_ENOMEM, "cross-correlation: cannot plan FFTs of %d points", 2 * n - 1);
    }
    *out = x;
    return GW_OK;
}

void gw_xcorr_free(gw_xcorr *x)
{
    if (!x)
        return;
    gw_fftw_planner_lock();
    if (x->r2hc)
        fftw_destroy_plan(x->r2hc);
    if (x->hc2r)
        fftw_destroy_plan(x->hc2r);
    gw_fftw_planner_unlock();
    fftw_free(x->in);
    fftw_free(x->out);
    fftw_free(x->hc);
    fftw_free(x->fa);
    fftw_free(x->xs);
    free(x);
}

int gw_xcorr_max_len(const gw_xcorr *x)
{
    return x->n;
}

int gw_xcorr_fft_len(const gw_xcorr *x)
{
    return x->M;
}

/* Power of 2 that brings the largest |a[i]| to [1/2, 1) (1 for a zero series):
 * the correlation's sums of products then neither overflow (a series of 1e155
 * gave NaN, EDGE) nor underflow (one of 1e-150 was "identically zero"), and the
 * scaling is exact, so ordinary series give the same bits as unscaled. NaN when
 * a sample is not finite. */
static double scale_of(const double *a, int m)
{
    double big = 0;
    for (int i = 0; i < m; i++) {
        if (!isfinite(a[i]))
            return NAN;
        big = fmax(big, fabs(a[i]));
    }
    int e = 0;
    if (big > 0)
        frexp(big, &e);
    return ldexp(1.0, -e);
}

/* DFT of s * a (m samples, zero-padded) into x->fa. */
static void transform(gw_xcorr *x, const double *a, int m, double sc)
{
    for (int i = 0; i < m; i++)
        x->in[i] = a[i] * sc;
    memset(x->in + m, 0, (size_t)(x->M - m) * sizeof *x->in);
    fftw_execute(x->r2hc);
    const double *hc = x->hc;
    const int M = x->M, h = M / 2;
    x->fa[0][0] = hc[0], x->fa[0][1] = 0;
    for (int l = 1; l < h; l++)
        x->fa[l][0] = hc[l], x->fa[l][1] = hc[M - l];
    x->fa[h][0] = hc[h], x->fa[h][1] = 0;
}

static int check_len(const gw_xcorr *x, int m, gw_err *err)
{
    if (m < 1 || m > x->n)
        return gw_err_set(err, GW_EINVAL, "cross-correlation: %d samples, the plans hold 1 to %d", m, x->n);
    return GW_OK;
}

/* Cross-spectrum of sa a and sb b into x->xs and their correlation into x->out
 * (x->out[L mod M] = sa sb c[L]), sa, sb the powers of 2 of scale_of (*unscale =
 * 1 / (sa sb), NaN when a sample is not finite); returns sum (sa a)^2 * sum (sb b)^2. */
static double correlate(gw_xcorr *x, const double *a, const double *b, int m, double *unscale)
{
    const double sa = scale_of(a, m), sb = scale_of(b, m);
    *unscale = 1 / sa / sb;
    if (isnan(sa) || isnan(sb))
        return NAN;
    double ea = 0, eb = 0;
    for (int i = 0; i < m; i++)
        ea += (a[i] * sa) * (a[i] * sa), eb += (b[i] * sb) * (b[i] * sb);
    transform(x, a, m, sa);
    memcpy(x->xs, x->fa, (size_t)x->nf * sizeof *x->xs);
    transform(x, b, m, sb);
    for (int l = 0; l < x->nf; l++) {
        double ar = x->xs[l][0], ai = x->xs[l][1], br = x->fa[l][0], bi = x->fa[l][1];
        x->xs[l][0] = ar * br + ai * bi; /* conj(A) B */
        x->xs[l][1] = ar * bi - ai * br;
    }
    /* the cross-spectrum into halfcomplex order (the imaginary parts at 0 and
     * M/2 are 0: A_0 B_0 and A_(M/2) B_(M/2) are real) */
    double *hc = x->hc;
    const int M = x->M, h = M / 2;
    hc[0] = x->xs[0][0], hc[h] = x->xs[h][0];
    for (int l = 1; l < h; l++)
        hc[l] = x->xs[l][0], hc[M - l] = x->xs[l][1];
    fftw_execute(x->hc2r);
    const double s = 1.0 / x->M;
    for (int i = 0; i < x->M; i++)
        x->out[i] *= s;
    return ea * eb;
}

int gw_xcorr_series(gw_xcorr *x, const double *a, const double *b, int m, double *c, gw_err *err)
{
    int rc = check_len(x, m, err);
    if (rc != GW_OK)
        return rc;
    double us;
    if (isnan(correlate(x, a, b, m, &us)))
        us = NAN; /* a sample not finite: every value NaN */
    for (int L = -(m - 1); L <= m - 1; L++)
        c[L + m - 1] = x->out[L < 0 ? L + x->M : L] * us;
    return GW_OK;
}

/* Interpolant of the correlation: value, first and second derivative at tau.
 * The phases e^(i theta_l tau) come from a rotation by e^(i theta_1 tau),
 * restarted from cos/sin every 256 terms (rounding grows as the count of
 * rotations: below 1e-13 relative here). */
static void interp(const gw_xcorr *x, double tau, double *c, double *d1, double *d2)
{
    double s0 = 0, s1 = 0, s2 = 0, cs = 1, sn = 0;
    const double th1 = 2 * M_PI / x->M, wr = cos(th1 * tau), wi = sin(th1 * tau);
    for (int l = 0; l < x->nf; l++) {
        if (l % 256 == 0)
            cs = cos(th1 * l * tau), sn = sin(th1 * l * tau);
        const double w = l == 0 || 2 * l == x->M ? 1 : 2, th = th1 * l;
        const double re = x->xs[l][0] * cs - x->xs[l][1] * sn, im = x->xs[l][0] * sn + x->xs[l][1] * cs;
        s0 += w * re;
        s1 -= w * th * im;
        s2 -= w * th * th * re;
        const double t = cs * wr - sn * wi;
        sn = sn * wr + cs * wi;
        cs = t;
    }
    *c = s0 / x->M;
    *d1 = s1 / x->M;
    *d2 = s2 / x->M;
}

/* Root of c'(tau) in [lo, hi] with c'(lo) > 0 > c'(hi): Newton steps kept inside
 * the shrinking bracket, bisection when a step leaves it; stops at a step or
 * bracket below 1e-10 sample. */
static double fourier_peak(const gw_xcorr *x, double lo, double hi, double start)
{
    double tau = start, c, g, h;
    for (int it = 0; it < 100; it++) {
        interp(x, tau, &c, &g, &h);
        if (g == 0)
            return tau;
        if (g > 0)
            lo = tau;
        else
            hi = tau;
        const double step = h < 0 ? -g / h : INFINITY;
        if (fabs(step) < 1e-10)
            return tau + step;
        if (hi - lo < 1e-10)
            return 0.5 * (lo + hi);
        tau = tau + step > lo && tau + step < hi ? tau + step : 0.5 * (lo + hi);
    }
    return tau;
}

int gw_xcorr_peak_find(gw_xcorr *x, const double *a, const double *b, int m, int lo, int hi,
                       int method, gw_xcorr_peak *pk, gw_err *err)
{
    int rc = check_len(x, m, err);
    if (rc != GW_OK)
        return rc;
    if (lo < -(m - 1) || hi > m - 1 || lo >= hi)
        return gw_err_set(err, GW_EINVAL, "cross-correlation: lag window [%d, %d] is not inside [%d, %d] "
                          "with lo < hi", lo, hi, -(m - 1), m - 1);
    if (method != GW_XCORR_PARABOLIC && method != GW_XCORR_FOURIER)
        return gw_err_set(err, GW_EINVAL, "cross-correlation: unknown interpolation %d", method);
    memset(pk, 0, sizeof *pk);
    pk->lag = NAN;
    double us;
    const double e2 = correlate(x, a, b, m, &us);
    if (isnan(e2)) {
        pk->status = GW_XCORR_PEAK_NONFINITE;
        pk->value = pk->rho = NAN;
        return GW_OK;
    }
    const double *c = x->out;
    const int M = x->M;
#define C_AT(L) c[(L) < 0 ? (L) + M : (L)]
    int best = lo;
    for (int L = lo + 1; L <= hi; L++)
        if (C_AT(L) > C_AT(best))
            best = L;
    pk->lag_int = best;
    pk->value = C_AT(best) * us;
    if (!(e2 > 0)) {
        pk->status = GW_XCORR_PEAK_ZERO;
        pk->rho = NAN;
        return GW_OK;
    }
    pk->rho = C_AT(best) / sqrt(e2);
    if (best == lo || best == hi) {
        pk->status = GW_XCORR_PEAK_EDGE;
        return GW_OK;
    }
    if (!(pk->rho > 1e-9)) { /* b anti-correlated with a: b = -a shifted gave lag 97.16 at rho 3e-17 */
        pk->status = GW_XCORR_PEAK_NOT_POSITIVE;
        return GW_OK;
    }
    const double ym = C_AT(best - 1), y0 = C_AT(best), yp = C_AT(best + 1);
#undef C_AT
    const double den = ym - 2 * y0 + yp;
    const double delta = den < 0 ? 0.5 * (ym - yp) / den : 0;
    pk->lag = best + delta;
    pk->value = y0 - 0.25 * (ym - yp) * delta;
    if (method == GW_XCORR_FOURIER) {
        double v, g0, h, gs;
        interp(x, best, &v, &g0, &h);
        const double side = g0 > 0 ? 1 : -1;
        interp(x, best + side, &v, &gs, &h);
        if (g0 == 0) {
            pk->lag = best;
        } else if (gs * g0 < 0) {
            double l = side > 0 ? best : best - 1, r = side > 0 ? best + 1 : best;
            double start = pk->lag > l && pk->lag < r ? pk->lag : 0.5 * (l + r);
            pk->lag = fourier_peak(x, l, r, start);
        } else {
            pk->fallback = 1;
        }
        if (!pk->fallback)
            interp(x, pk->lag, &pk->value, &g0, &h);
    }
    pk->rho = pk->value / sqrt(e2);
    pk->value *= us;
    pk->status = GW_XCORR_PEAK_OK;
    return GW_OK;
}

int gw_xcorr_psd(gw_xcorr *x, const double *a, int m, double dt, double *psd, gw_err *err)
{
    int rc = check_len(x, m, err);
    if (rc != GW_OK)
        return rc;
    if (!(dt > 0) || !isfinite(dt))
        return gw_err_set(err, GW_EINVAL, "power spectrum: sampling step %g s must be positive", dt);
    transform(x, a, m, 1.0);
    for (int l = 0; l < x->nf; l++) {
        const double g = l == 0 || 2 * l == x->M ? 1 : 2;
        psd[l] = g * dt * (x->fa[l][0] * x->fa[l][0] + x->fa[l][1] * x->fa[l][1]) / m;
    }
    return GW_OK;
}
