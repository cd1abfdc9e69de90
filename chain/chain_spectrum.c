/*
 * chain_spectrum.c: power spectrum of a column's wall force (FFTW), whose
 * dominant plateau peak is compared with 1/P (P the mean spacing of wall-force
 * maxima, chain_collide.c). The trace is resampled uniformly, windowed and
 * transformed; the peak is taken on the spectrum of dF/dt (f^2 weighting),
 * which the contact's slow envelope does not dominate. Units: s, N, Hz.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <fftw3.h>

#include "gw_chain.h"
#include "chain_model.h"
#include "gw_chain_study.h"
#include "gw_global.h"

/* ---- wall-force spectrum of the column ---- */

void gw_chain_spectrum_free(gw_chain_spectrum *sp)
{
    if (!sp)
        return;
    free(sp->freq);
    memset(sp, 0, sizeof *sp);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median positive spacing of the trace times (events add close pairs). */
static double median_spacing(const gw_chain_trace *tr)
{
    double *d = malloc(tr->len * sizeof *d);
    if (!d)
        return NAN;
    size_t m = 0;
    for (size_t i = 1; i < tr->len; i++)
        if (tr->t[i] > tr->t[i - 1])
            d[m++] = tr->t[i] - tr->t[i - 1];
    qsort(d, m, sizeof *d, cmp_double);
    double med = m ? d[m / 2] : NAN;
    free(d);
    return med;
}

int gw_chain_wall_spectrum(const gw_chain_trace *tr, double t0, double t1, double dt,
                           double f_min, int fftw_measure, gw_chain_spectrum *sp,
                           gw_err *err)
{
    if (!sp)
        return gw_err_set(err, GW_EINVAL, "gw_chain_wall_spectrum: sp is NULL");
    memset(sp, 0, sizeof *sp);
    if (chain_trace_check(tr, "gw_chain_wall_spectrum", err) != GW_OK)
        return GW_EINVAL;
    if (tr->len < 2 || !(t1 > t0) || !isfinite(t1) || t0 < tr->t[0] || t1 > tr->t[tr->len - 1])
        return gw_err_set(err, GW_EINVAL, "wall spectrum: interval [%g, %g] s not inside the trace", t0, t1);
    /* a force or time that is not finite in the interval made every bin NaN
     * and the peak a bin of no meaning (a NaN at one of 64 samples: f_peak
     * 64 kHz, GW_OK) */
    for (size_t k = 0; k < tr->len; k++)
        if (tr->t[k] >= t0 && tr->t[k] <= t1 && (!isfinite(tr->f[k]) || !isfinite(tr->t[k])))
            return gw_err_set(err, GW_EINVAL, "wall spectrum: the trace's force at sample %zu (t = %g s) is not "
                              "finite", k, tr->t[k]);
    /* dt NaN took the median spacing as if it were <= 0, f_min NaN or inf
     * gave no peak (NaN) with GW_OK: neither is a choice the call offers */
    if (isnan(dt) || isinf(dt))
        return gw_err_set(err, GW_EINVAL, "wall spectrum: dt = %g s is not finite (<= 0: the median spacing)", dt);
    if (isnan(f_min) || isinf(f_min))
        return gw_err_set(err, GW_EINVAL, "wall spectrum: f_min = %g Hz is not finite (<= 0: 4 / (t1 - t0))",
                          f_min);
    if (!(dt > 0))
        dt = median_spacing(tr);
    double span = (t1 - t0) / dt;
    if (!(span >= 15) || span > 1e8)
        return gw_err_set(err, GW_EINVAL, "wall spectrum: %g samples in [%g, %g] s (need 16 to 1e8)", span + 1, t0, t1);
    const int ns = (int)floor(span) + 1;
    int M = 1;
    while (M < 8 * ns)
        M <<= 1;
    const int len = M / 2 + 1;
    double *in = fftw_malloc((size_t)M * sizeof *in);
    fftw_complex *out = fftw_malloc((size_t)len * sizeof *out);
    sp->freq = malloc(2 * (size_t)len * sizeof *sp->freq);
    fftw_plan plan = NULL;
    int rc = GW_OK;
    if (!in || !out || !sp->freq)
        rc = gw_err_set(err, GW_ENOMEM, "wall spectrum: out of memory for %d points", M);
    else {
        gw_fftw_planner_lock(); /* FFTW's planner is not thread-safe */
        plan = fftw_plan_dft_r2c_1d(M, in, out, fftw_measure ? FFTW_MEASURE : FFTW_ESTIMATE);
        gw_fftw_planner_unlock();
        if (!plan)
            rc = gw_err_set(err, GW_ENOMEM, "wall spectrum: FFTW could not plan %d points", M);
    }
    if (rc == GW_OK) {
        size_t k = 0;
        double mean = 0;
        for (int i = 0; i < ns; i++) {
            double t = t0 + i * dt;
            while (k + 2 < tr->len && tr->t[k + 1] <= t)
                k++;
            double ta = tr->t[k], tb = tr->t[k + 1];
            double u = tb > ta ? fmin(fmax((t - ta) / (tb - ta), 0.0), 1.0) : 1.0;
            in[i] = tr->f[k] + u * (tr->f[k + 1] - tr->f[k]);
            mean += in[i] / ns;
        }
        for (int i = 0; i < M; i++) {
            double w = i < ns ? sin(M_PI * i / (ns - 1)) : 0.0;
            in[i] = i < ns ? (in[i] - mean) * w * w : 0.0;
        }
        fftw_execute(plan);
        sp->len = len;
        sp->power = sp->freq + len;
        sp->df = 1.0 / (M * dt);
        sp->dt = dt;
        sp->samples = ns;
        sp->f_min = f_min > 0 ? f_min : 4.0 / (t1 - t0);
        for (int l = 0; l < len; l++) {
            sp->freq[l] = l * sp->df;
            sp->power[l] = dt * dt * (out[l][0] * out[l][0] + out[l][1] * out[l][1]);
        }
        /* The peak of f^2 P, the spectrum of dF/dt: in long columns the
         * envelope of the contact (rise, plateau, release) outweighs the plateau
         * oscillation in P itself well above 4/(t1 - t0), but not in dF/dt. */
        int lm = -1;
        for (int l = 1; l < len - 1; l++)
            if (sp->freq[l] >= sp->f_min && (lm < 0 || l * (double)l * sp->power[l] > lm * (double)lm * sp->power[lm]))
                lm = l;
        sp->f_peak = lm > 0 ? (lm + gw_peak_offset_log((lm - 1.0) * (lm - 1.0) * sp->power[lm - 1],
                                                 (double)lm * lm * sp->power[lm],
                                                 (lm + 1.0) * (lm + 1.0) * sp->power[lm + 1])) * sp->df
                            : NAN;
    }
    if (plan) {
        gw_fftw_planner_lock();
        fftw_destroy_plan(plan);
        gw_fftw_planner_unlock();
    }
    fftw_free(in);
    fftw_free(out);
    if (rc != GW_OK)
        gw_chain_spectrum_free(sp);
    return rc;
}
