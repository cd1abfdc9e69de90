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
    double c0, c1, cov00, cov01, cov11, sumsq;
    if (gsl_fit_linear(x, 1, y, 1, (size_t)n, &c0, &c1, &cov00, &cov01, &cov11, &sumsq) != 0)
        return GW_EINVAL;
    double mean = 0, sst = 0, maxrel = 0;
    for (int i = 0; i < n; i++)
        mean += y[i] / n;
    for (int i = 0; i < n; i++) {
        double f = c0 + c1 * x[i];
        sst += (y[i] - mean) * (y[i] - mean);
        if (f != 0 && fabs(y[i] - f) / fabs(f) > maxrel)
            maxrel = fabs(y[i] - f) / fabs(f);
    }
    fit->c0 = c0;
    fit->c1 = c1;
    fit->c0_err = n > 2 ? sqrt(cov00) : NAN;
    fit->c1_err = n > 2 ? sqrt(cov11) : NAN;
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
