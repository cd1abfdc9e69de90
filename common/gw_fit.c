/*
 * gw_fit.c: least-squares lines (gsl_fit_linear) and power laws fitted as lines
 * in log-log. Standard errors come from the scatter of the points about the line
 * (GSL's covariance for unweighted data).
 */
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_fit.h>
#include <pthread.h>

#include "gw_global.h"

#include "gw_common.h"

/* A refused fit: every number of it undefined (a caller that reads it
 * regardless reads NaN, not the previous fit's numbers). */
static int no_fit(gw_linfit *fit, int n)
{
    if (fit)
        *fit = (gw_linfit){.c0 = NAN, .c1 = NAN, .c0_err = NAN, .c1_err = NAN, .r2 = NAN, .max_rel_resid = NAN, .n = n};
    return GW_EINVAL;
}

int gw_fit_linear(const double *x, const double *y, int n, gw_linfit *fit)
{
    if (!x || !y || !fit || n < 2)
        return no_fit(fit, 0);
    /* every point finite and two abscissas apart: a NaN among the points gave
     * the slope 0 with GW_OK (1, NaN, 3 over 1, 2, 3), one abscissa a NaN slope
     * with GW_OK */
    int apart = 0;
    for (int i = 0; i < n; i++) {
        if (!isfinite(x[i]) || !isfinite(y[i]))
            return no_fit(fit, n);
        apart |= x[i] != x[0];
    }
    if (!apart)
        return no_fit(fit, n);
    /* The fit of x / 2^ex and y / 2^ey, each scaled to a largest magnitude in
     * [0.5, 1): by powers of two, so that every sum, product and quotient of
     * the fit is the unscaled one's times a power of two, exactly (the same
     * numbers, bit for bit, as long as no sum overflowed), and scaled back.
     * GSL's sums of squares overflowed from |x| near 1e154: abscissas of
     * 1e300 gave a NaN line with GW_OK, and abscissas near 1e-160 underflowed
     * to a slope of inf or NaN. A line that cannot be held in doubles (its
     * slope or intercept beyond them once scaled back) is refused. */
    double xmax = 0, ymax = 0;
    for (int i = 0; i < n; i++) {
        xmax = fmax(xmax, fabs(x[i]));
        ymax = fmax(ymax, fabs(y[i]));
    }
    int ex = 0, ey = 0;
    (void)frexp(xmax, &ex);
    if (ymax > 0)
        (void)frexp(ymax, &ey);
    double *xs = malloc(2 * (size_t)n * sizeof *xs);
    if (!xs) {
        no_fit(fit, n); /* NaN, as every refused fit */
        return GW_ENOMEM;
    }
    double *ys = xs + n;
    for (int i = 0; i < n; i++) {
        xs[i] = ldexp(x[i], -ex);
        ys[i] = ldexp(y[i], -ey);
    }
    double c0, c1, cov00, cov01, cov11, sumsq;
    if (gsl_fit_linear(xs, 1, ys, 1, (size_t)n, &c0, &c1, &cov00, &cov01, &cov11, &sumsq) != 0) {
        free(xs);
        return no_fit(fit, n);
    }
    double mean = 0, sst = 0, maxrel = 0;
    for (int i = 0; i < n; i++)
        mean += ys[i] / n;
    for (int i = 0; i < n; i++) {
        double f = c0 + c1 * xs[i];
        sst += (ys[i] - mean) * (ys[i] - mean);
        if (f != 0 && fabs(ys[i] - f) / fabs(f) > maxrel)
            maxrel = fabs(ys[i] - f) / fabs(f);
    }
    free(xs);
    const double a = ldexp(c0, ey), b = ldexp(c1, ey - ex);
    if (!isfinite(a) || !isfinite(b) || !isfinite(sumsq) || !isfinite(sst))
        return no_fit(fit, n);
    fit->c0 = a;
    fit->c1 = b;
    fit->c0_err = n > 2 ? ldexp(sqrt(cov00), ey) : NAN;
    fit->c1_err = n > 2 ? ldexp(sqrt(cov11), ey - ex) : NAN;
    fit->r2 = sst > 0 ? 1.0 - sumsq / sst : 1.0;
    fit->max_rel_resid = maxrel;
    fit->n = n;
    return GW_OK;
}

int gw_fit_power(const double *x, const double *y, int n, gw_linfit *fit)
{
    if (!x || !y || !fit || n < 2) /* as gw_fit_linear (x and y were read: SIGSEGV) */
        return no_fit(fit, 0);
    double *lx = malloc(2 * (size_t)n * sizeof *lx);
    if (!lx)
        return GW_ENOMEM;
    double *ly = lx + n;
    for (int i = 0; i < n; i++) {
        if (!(x[i] > 0) || !(y[i] > 0)) {
            free(lx);
            return no_fit(fit, n);
        }
        lx[i] = log(x[i]);
        ly[i] = log(y[i]);
    }
    int rc = gw_fit_linear(lx, ly, n, fit);
    free(lx);
    return rc;
}

double gw_peak_offset_log(double pm, double p0, double pp)
{
    if (!(pm > 0 && p0 > 0 && pp > 0))
        return 0.0;
    double a = log(pm), b = log(p0), c = log(pp), den = a - 2 * b + c;
    double off = den < 0 ? 0.5 * (a - c) / den : 0.0;
    return fabs(off) <= 1.0 ? off : 0.0;
}

/* GSL's error handler is process-wide: sections that turn it off hold one
 * recursive lock (gw_global.h); a fork waits for the section under way (a
 * child forked during another thread's restitution calibration waited for
 * ever on this lock). */
static gw_forklock gsl_handler_lock = GW_FORKLOCK_RECURSIVE;

gsl_error_handler_t *gw_gsl_quiet_begin(void)
{
    gw_forklock_take(&gsl_handler_lock);
    return gsl_set_error_handler_off();
}

void gw_gsl_quiet_end(gsl_error_handler_t *old)
{
    gsl_set_error_handler(old);
    gw_forklock_give(&gsl_handler_lock);
}
