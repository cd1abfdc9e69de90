/*
 * gw_xcorr.h: cross-correlation of two real series by FFT (FFTW), the lag of its
 * peak to a fraction of a sample, and the power spectrum of one series.
 *
 * An object holds FFTW plans and buffers for series of up to n samples, padded
 * with zeros to M >= 2n - 1 so that the correlation is the linear one:
 *     c[L] = sum_i a[i] b[i + L],   L = -(m - 1) .. m - 1   (m <= n samples).
 * A series b that is a delayed by d samples (b[i] = a[i - d]) peaks at L = d.
 * Lags are in samples; multiply by the sampling step for seconds.
 *
 * Threads: plan once, execute many times. Creating and freeing objects goes
 * through FFTW's planner, which is not thread-safe; granwave serialises it with
 * one process-wide lock (gw_fftw_planner_lock, gw_global.h) held by gw_xcorr_create and
 * gw_xcorr_free and by every other FFTW planner call of the library. The
 * other calls use only the object's own plans and buffers (fftw_execute is
 * thread-safe), so each thread may use its own object concurrently; one object
 * must not be used by two threads at once.
 *
 * Errors: GW_EINVAL (bad length or lag window, message names it), GW_ENOMEM.
 * The library never prints; err may be NULL.
 */
#ifndef GW_XCORR_H
#define GW_XCORR_H

#include "gw_common.h"

typedef struct gw_xcorr gw_xcorr;

/* Sub-sample refinement of the correlation peak. */
enum {
    /* vertex of the parabola through the three samples around the largest one:
     * cheap, biased toward the nearest integer lag for narrow peaks */
    GW_XCORR_PARABOLIC = 0,
    /* maximum of the band-limited (trigonometric) interpolant of the correlation
     * (Newton's method on its derivative, bracketed): exact for band-limited
     * series whose correlation lies inside the padded window */
    GW_XCORR_FOURIER = 1
};

/* Peak status. */
enum {
    GW_XCORR_PEAK_OK = 0,    /* a maximum strictly inside the lag window */
    GW_XCORR_PEAK_EDGE = 1,  /* the largest value is on the window's edge: no peak found */
    GW_XCORR_PEAK_ZERO = 2,  /* a or b is identically zero */
    GW_XCORR_PEAK_NONFINITE = 3, /* a or b holds a NaN or an infinite sample: no peak */
    GW_XCORR_PEAK_NOT_POSITIVE = 4 /* the largest correlation in the window is not above 1e-9
                                      of sqrt(sum a^2 sum b^2) (0 but for rounding): b is no
                                      delayed copy of a there (an anti-correlation), no peak */
};

/* Plans for series of up to n samples, 2 <= n <= 2^26. measure = 1 plans with
 * FFTW_MEASURE (slower planning), 0 with FFTW_ESTIMATE. On failure *out is NULL. */
int gw_xcorr_create(int n, int measure, gw_xcorr **out, gw_err *err);
/* NULL is a no-op. */
void gw_xcorr_free(gw_xcorr *x);

/* Largest series length n, and the padded transform length M (even, of the form
 * 2^p 3^q 5^r 7^s, >= 2n - 1). The spectra have M/2 + 1 frequencies. */
int gw_xcorr_max_len(const gw_xcorr *x);
int gw_xcorr_fft_len(const gw_xcorr *x);

/* The whole correlation of a and b (m samples each, 1 <= m <= n):
 * c[L + m - 1] for L = -(m - 1) .. m - 1 (2m - 1 values, caller's array). */
int gw_xcorr_series(gw_xcorr *x, const double *a, const double *b, int m, double *c,
                    gw_err *err);

typedef struct gw_xcorr_peak {
    double lag;   /* lag of the maximum, samples, refined (b behind a: > 0); NaN unless OK */
    double value; /* correlation at lag (interpolated; c at lag_int for EDGE) */
    double rho;   /* value / sqrt(sum a^2 sum b^2): 1 for b a shifted copy of a, |rho| <= 1
                     (up to the series' aliasing between integer lags); NaN for ZERO and
                     NONFINITE. The lag and rho do not depend on the series' scales (each
                     series is scaled by a power of 2 before the transforms: 1e-150 or
                     1e150 times a series gives the same lag and rho) */
    int lag_int;  /* integer lag of the largest correlation in the window */
    int status;   /* GW_XCORR_PEAK_* */
    int fallback; /* FOURIER only: 1 when the interpolant was not bracketed around
                     lag_int and the parabolic vertex was kept */
} gw_xcorr_peak;

/* Delay of b behind a: the largest correlation over the integer lags lo .. hi
 * (-(m-1) <= lo < hi <= m - 1), refined by method (GW_XCORR_*). A largest value
 * at lo or hi is not a peak (status EDGE, lag NaN), nor one not above 1e-9 of sqrt(sum a^2 sum b^2) (NOT_POSITIVE),
 * nor anything of series with a sample that is not finite (NONFINITE). GW_EINVAL for a bad m,
 * window or method; the peak is then untouched. */
int gw_xcorr_peak_find(gw_xcorr *x, const double *a, const double *b, int m, int lo, int hi,
                       int method, gw_xcorr_peak *pk, gw_err *err);

/* One-sided power spectral density of a (m samples, 1 <= m <= n, step dt > 0):
 * psd[l] at f_l = l / (M dt), l = 0 .. M/2 (zero padding interpolates between the
 * m-point frequencies):  psd[l] = g_l dt |A_l|^2 / m, A = DFT of the padded a,
 * g_l = 1 at l = 0 and M/2, 2 otherwise; so sum_l psd[l] df = (1/m) sum_i a[i]^2
 * with df = 1 / (M dt). Units: (unit of a)^2 / Hz. */
int gw_xcorr_psd(gw_xcorr *x, const double *a, int m, double dt, double *psd, gw_err *err);

#endif
