/*
 * layer_crowns.c: shock-wave analysis on concentric crowns (docs/physics.md 2.5).
 *
 * Ring k holds distances [k d_c, (k+1) d_c) from the impact point. For each
 * ring, the arrival times of the strain-energy increase (over its value at
 * t = 0) and of the kinetic energy are the first local maxima that reach a
 * quarter of the ring's largest value (so reflections from the walls later in a long
 * run are not taken), over the samples of the first impact (up to the first at or
 * after T_f when the block bounced: the run's end but with --full, where the
 * block's next impact follows); a ring counts when its peak exceeds 1e-4 of the incident
 * energy and is not at the last sample; a ring with a sample that is not finite
 * has no arrival (and no cross-correlation pair).
 * The wave speed is the slope c of the least-squares line (GSL, gw_fit_linear)
 * r_k = r_0 + c t_k through the rings k >= 1 with a peak, with its standard
 * error; fewer than three rings give NaN. Ring 0 holds the impact itself.
 * Every speed (this one, the kinetic one and the cross-correlation's below)
 * is NaN unless it is positive, resolved by the samples (the wave takes at
 * least two sampling intervals dt to cross a ring, d_c / c >= 2 dt) and known
 * to better than half of it (standard error < c / 2); the cross-correlation's
 * also when its pairs' mean delay per crown exceeds 10 times the first
 * contact's opening time (pairs locked onto the pile's slow motion:
 * layer_crowns_xcorr_locked, warned of by layer_crowns_warning), and a peak
 * speed also when its crown transit d_c / c does (peaks following that
 * motion: layer_crowns_peaks_locked).
 *
 * Delays by FFT cross-correlation (gw_xcorr.c). Ring k's total energy
 * E_k(t) = strain increase + kinetic energy, sampled every dt; its changes
 * f_k[i] = E_k[i + 1] - E_k[i] (the energy flowing into the ring per sample,
 * times dt) are pulses even where E_k stays raised after the front (a raised
 * level cut by the end of the record biases the delay of E_k itself, test_xcorr).
 * A ring counts when E_k has a first arrival peak by the rule above. For
 * neighbours k, k + 1 >= 1 that both count, the delay tau_k is the lag of the
 * largest correlation sum_i f_k[i] f_(k+1)[i + L] over -1 <= L <= (n - 2)/2,
 * refined by the band-limited interpolant (GW_XCORR_FOURIER), so a delay below
 * half a sample (largest integer value at L = 0) is measured, not left out; when
 * the largest value is at L = -1, the one over 0 <= L <= (n - 2)/2 (a largest
 * value at L = 0 there is no outward delay); a largest value at the far end of
 * the window is no delay. With m >= 2 delays tau_k over the ring
 * spacings dr_k (slowness p_k = tau_k / dr_k):
 *     c = sum dr_k / sum tau_k = 1 / p,   p = mean of p_k (equal spacings),
 *     c_err = c * s_p / (sqrt(m) p),      s_p the standard deviation of the p_k.
 * Arrival times built by adding delays carry errors that add up ring to ring (a
 * random walk); the generalised least-squares slope of arrival against radius
 * for such errors is exactly this mean delay, and c_err its standard error from
 * the scatter of the delays. rho_k = normalised correlation peak.
 * Spectra: the one-sided power spectral density (gw_xcorr_psd, J^2/Hz) of each
 * ring's strain increase and kinetic energy over the evenly spaced samples
 * (the last sample is dropped when the run was cut at t_max off the dt grid),
 * zero-padded to the correlation's length M: f_l = l / (M dt), l = 0 .. M/2.
 * Units: SI (m, s, m/s, J^2/Hz).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_layer.h"
#include "layer_impl.h"
#include "gw_xcorr.h"

/* Time of the first arrival peak of series v[k * stride] (k < ns): the first
 * local maximum reaching a quarter of the series' largest value (later, larger
 * maxima from reflections at the walls do not count), or NaN when the series
 * never exceeds thr, the peak is the last sample, or a sample or its time is not
 * finite (a NaN next to the arrival hid it, and a later, smaller maximum was
 * taken: 25 ms for a front at 5.96 ms). */
static double peak_time(const double *t, const double *v, int ns, int stride, double thr)
{
    double vmax = 0;
    for (int k = 0; k < ns; k++) {
        if (!isfinite(v[(size_t)k * stride]) || !isfinite(t[k]))
            return NAN;
        vmax = fmax(vmax, v[(size_t)k * stride]);
    }
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

/* Leading samples of r->t evenly spaced (to 1e-9 of the first step). */
static int even_samples(const gw_layer_impact_result *r)
{
    if (r->ns < 2)
        return r->ns;
    const double dt = r->t[1] - r->t[0];
    int k = 2;
    while (k < r->ns && fabs(r->t[k] - r->t[k - 1] - dt) <= 1e-9 * dt)
        k++;
    return dt > 0 ? k : 1;
}

/* Spectra of ring q's strain and kinetic series (n samples) into column q of
 * out_s, out_k ([spec_len * nrings]; they may be the series' own arrays: ring
 * q's column is read before it is written); leaves the ring's total energy in
 * e[n]. k: scratch of n; ps, pk: scratch of spec_len. */
static void ring_spectra(gw_layer_impact_result *r, gw_xcorr *xc, int q, int n, double dt, double *e,
                         double *k, double *ps, double *pk, double *out_s, double *out_k)
{
    const int nr = r->nrings;
    for (int i = 0; i < n; i++)
        e[i] = r->ring_strain[(size_t)i * nr + q], k[i] = r->ring_kin[(size_t)i * nr + q];
    gw_xcorr_psd(xc, e, n, dt, ps, NULL);
    gw_xcorr_psd(xc, k, n, dt, pk, NULL);
    for (int l = 0; l < r->spec_len; l++)
        out_s[(size_t)l * nr + q] = ps[l], out_k[(size_t)l * nr + q] = pk[l];
    for (int i = 0; i < n; i++)
        e[i] = k[i] + e[i];
}

/* Speed and error from the used pairs' delays into *c, *cerr (NaN with fewer
 * than 2 pairs), the pairs used into *m (slow: scratch of nrings). */
static void pair_speed_of(const gw_layer_impact_result *r, double *slow, double *c, double *cerr, int *nused)
{
    int m = 0;
    for (int q = 1; q + 1 < r->nrings; q++)
        if (isfinite(r->xcorr_delay[q]))
            slow[m++] = r->xcorr_delay[q] / (r->ring_r[q + 1] - r->ring_r[q]);
    *nused = m;
    *c = *cerr = NAN;
    if (m < 2)
        return;
    double pm = 0, var = 0;
    for (int k = 0; k < m; k++)
        pm += slow[k] / m;
    for (int k = 0; k < m; k++)
        var += (slow[k] - pm) * (slow[k] - pm) / (m - 1);
    *c = 1 / pm;
    *cerr = *c * sqrt(var / m) / pm;
}

static void pair_speed(gw_layer_impact_result *r, double *slow)
{
    pair_speed_of(r, slow, &r->wave_speed_xcorr, &r->wave_speed_xcorr_err, &r->xcorr_gaps);
}

/* Delay of f_(k+1) (b) behind f_k (a), m samples each, into *pk; 1 when there is
 * one. The largest correlation over the lags -1 .. (m - 1)/2: lag 0 is inside the
 * window, so a pair less than half a sample apart (two rings reached at once) is
 * refined like any other. It was the window's edge (0 .. (m - 1)/2), and such pairs
 * were left out: rings reached at once gave 540 m/s for 600. When the largest value
 * is at -1 (the pair matches best with ring k + 1 ahead), the outward lags
 * 0 .. (m - 1)/2 alone are searched, as before: a largest value at 0 there means
 * the correlation still rises toward ring k + 1 ahead, no outward delay. */
static int pair_delay(gw_xcorr *xc, const double *a, const double *b, int m, gw_xcorr_peak *pk)
{
    const int hi = (m - 1) / 2;
    if (gw_xcorr_peak_find(xc, a, b, m, -1, hi, GW_XCORR_FOURIER, pk, NULL) != GW_OK)
        return 0;
    if (pk->status == GW_XCORR_PEAK_EDGE && pk->lag_int == -1 &&
        gw_xcorr_peak_find(xc, a, b, m, 0, hi, GW_XCORR_FOURIER, pk, NULL) != GW_OK)
        return 0;
    return pk->status == GW_XCORR_PEAK_OK;
}

/* The cross-correlation and the spectra; donor (NULL: a new block): the
 * series' own block (layer_crowns_series: 2 nrings of room, strain and kin of
 * rows rows each, r's ring_strain and ring_kin), grown to the spectra's
 * length when shorter, turned into the result's block in place (ring q's
 * spectra written over its own column once read) and *donor set NULL; the
 * spectra and delays are those of a new block value for value. */
static int crowns_xcorr(gw_layer_impact_result *r, double thr, int nw, double **donor, int rows)
{
    const int nr = r->nrings, ne = even_samples(r), n = ne < nw ? ne : nw;
    if (n < 4)
        return GW_OK;
    const double dt = r->t[1] - r->t[0];
    gw_xcorr *xc = NULL;
    if (gw_xcorr_create(n, 0, &xc, NULL) != GW_OK)
        return GW_ENOMEM;
    const int nf = gw_xcorr_fft_len(xc) / 2 + 1;
    double *block = NULL;
    if (donor && nf > rows) {
        /* room for nf rows: the kinetic rows move up */
        block = realloc(*donor, (2 + 2 * (size_t)nf) * nr * sizeof *block);
        if (block) {
            memmove(block + (2 + (size_t)nf) * nr, block + (2 + (size_t)rows) * nr,
                    (size_t)rows * nr * sizeof *block);
            *donor = block;
            rows = nf;
        }
    } else
        block = donor ? *donor : malloc((2 * (size_t)nr + 2 * (size_t)nf * nr) * sizeof *block);
    double *e = malloc((3 * (size_t)n + 2 * (size_t)nf + (size_t)nr) * sizeof *e);
    int *used = malloc((size_t)nr * sizeof *used);
    if (!block || !e || !used) {
        if (!donor)
            free(block);
        free(e), free(used);
        gw_xcorr_free(xc);
        return GW_ENOMEM;
    }
    double *out_s = block + 2 * nr, *out_k = out_s + (size_t)nf * nr;
    if (donor) {
        r->ring_strain = out_s;
        r->ring_kin = out_k = out_s + (size_t)rows * nr;
    }
    r->xcorr_delay = block;
    r->xcorr_rho = block + nr;
    r->spec_len = nf;
    r->spec_df = 1 / (gw_xcorr_fft_len(xc) * dt);
    double *fprev = e + n, *fcur = e + 2 * (size_t)n, *ps = e + 3 * (size_t)n, *pk = ps + nf, *slow = pk + nf;
    for (int q = 0; q < nr; q++) {
        r->xcorr_delay[q] = r->xcorr_rho[q] = NAN;
        ring_spectra(r, xc, q, n, dt, e, fcur, ps, pk, out_s, out_k);
        used[q] = q >= 1 && isfinite(peak_time(r->t, e, n, 1, thr));
        for (int i = 0; i + 1 < n; i++)
            fcur[i] = e[i + 1] - e[i];
        gw_xcorr_peak pk_q;
        if (q >= 2 && used[q - 1] && used[q] && pair_delay(xc, fprev, fcur, n - 1, &pk_q)) {
            r->xcorr_delay[q - 1] = pk_q.lag * dt;
            r->xcorr_rho[q - 1] = pk_q.rho;
        }
        double *sw = fprev;
        fprev = fcur, fcur = sw;
    }
    if (donor) {
        /* the kinetic spectra down to follow the strain's nf rows */
        if (rows > nf) {
            memmove(out_s + (size_t)nf * nr, out_k, (size_t)nf * nr * sizeof *block);
            double *b = realloc(block, (2 + 2 * (size_t)nf) * nr * sizeof *b);
            if (b)
                block = b, r->xcorr_delay = b, r->xcorr_rho = b + nr;
        }
        *donor = NULL;
    }
    r->spec_strain = block + 2 * nr;
    r->spec_kin = r->spec_strain + (size_t)nf * nr;
    pair_speed(r, slow);
    free(e);
    free(used);
    gw_xcorr_free(xc);
    return GW_OK;
}

/* A speed c is kept only when the samples resolve it: positive, the wave
 * takes at least two sampling intervals to cross a ring (d_c / c >= 2 dt),
 * and its standard error is below half of it; otherwise NaN. On the default impact (c about 580 m/s, d_c = 0.65 m) the
 * strain fit gave 579, 580, 579, 591 m/s at dt-out 2e-5, 1e-4, 2.5e-4, 5e-4 s
 * (2.2 samples a ring), then 483 at 1e-3 (1.1), 102 at 1e-2 and -4.7 m/s at
 * 0.05 s, reported as speeds; at 1e-2 s the cross-correlation gave
 * 13 +- 8.6 m/s from 4 of 10 ring pairs. */
static void resolved_at(const gw_layer_impact_result *r, double dt, double *c, double *cerr)
{
    const double dc = r->nrings >= 2 ? r->ring_r[1] - r->ring_r[0] : NAN;
    if (!(*c > 0) || !(dc / *c >= 2 * dt) || !(*cerr < 0.5 * *c))
        *c = *cerr = NAN;
}

/* resolved_at over the interval of r's series (r->t: the one being read) */
static void resolved(const gw_layer_impact_result *r, double *c, double *cerr)
{
    resolved_at(r, r->ns >= 2 ? r->t[1] - r->t[0] : NAN, c, cerr);
}

/* The interval of the series the run's crowns were read from (layer_crowns_series:
 * the checks' when --dt-out is coarser), for the lock rules asked after the run,
 * when r->t is the written samples again: a peak speed of 38.6 m/s nulled as
 * locked at the checks' 2e-5 s was found unresolved at --dt-out 1e-2 (0.65 m in
 * 0.017 s, under two samples) and not warned of. */
static double crowns_dt(const gw_layer_impact_result *r)
{
    return r->peak_strain_t[3 * (size_t)r->nrings];
}

int layer_result_shape(const gw_layer_impact_result *r, int whole, gw_err *err)
{
    /* a result filled by hand: its series were read over ns samples and
     * nrings rings whatever arrays it held (NULL: SIGSEGV) */
    const int rows = r->ns > 0, rings = r->nrings > 0, spec = whole && r->xcorr_delay && r->spec_len > 0;
    if (r->ns < 0 || r->nrings < 0 || r->spec_len < 0 || (rows && !r->t) ||
        (whole && rows && (!r->ledger || !r->block)) || (rows && rings && (!r->ring_kin || !r->ring_strain)) ||
        (whole && rows && rings && (!r->ring_coord || !r->ring_diss)) ||
        (rings && (!r->peak_strain_t || !r->peak_kin_t || !r->ring_r)) ||
        (whole && r->xcorr_delay && rings && !r->xcorr_rho) || (spec && rings && (!r->spec_strain || !r->spec_kin)))
        return gw_err_set(err, GW_EINVAL, "impact result: %d samples, %d rings and %d spectrum bins without the "
                          "arrays that hold them (a result filled by hand)", r->ns, r->nrings, r->spec_len);
    return GW_OK;
}

/* The samples of the first impact: up to the first at or after T_f when the
 * block bounced and reached it (where a run that is not --full stops), else
 * all. Past T_f the block falls back: its next impact sends a new wave, and
 * with --full the rings' largest values (and so the quarter rule) and their
 * energy changes were those of that impact: the default 40-disc pile's strain
 * arrivals of rings 8 to 11 moved from 8.6-11.2 ms to 0.582-0.588 s, and the
 * wave speed from 98 +- 45 to 6.2 +- 1.3 m/s. */
static int first_impact_samples(const gw_layer_impact_result *r)
{
    /* (a result filled by hand holds t_f 0 and bounced 0: all its samples) */
    if (r->bounced != 1 || !isfinite(r->t_f) || r->ns < 1 || !(r->t_f > r->t[0]))
        return r->ns;
    int k = 0;
    while (k < r->ns && r->t[k] < r->t_f)
        k++;
    return k < r->ns ? k + 1 : r->ns;
}

/* 1 when the cross-correlation's pairs lock onto something slower than the
 * wave: their mean delay per crown d_c / c (c from the pairs' delays, before
 * the resolution rule) more than LAYER_XCORR_LOCK times the first contact's
 * time to its opening (the block's whole first contact, which sends the
 * pulse), or, when that contact did not open, the crown's transit at the
 * faster of the strain and kinetic peak speeds (the wave is at the crown no
 * later than it says). Its mean delay into *delay and that time into *ref (NaN
 * when none is known: then 0). On a long first impact the pairs locked onto
 * the pile's slow motion and read it as a speed: the 300-disc pile of
 * `layer-make --n 300 --seed 1` at --vi 40 --gravity 1 --other-settling
 * --t-max 20 --dt-out 1e-2 (T_f 5.8 s) gave 11.10 +- 2.55 m/s from delays near
 * 0.09 s, against the strain peaks' 755.5 and a first contact open at 1.6 ms;
 * the default impact's pairs are 0.6 of its first contact (1.07 against
 * 1.73 ms). The threshold checked over a sweep of 29 impacts (42 runs,
 * gravity 9.81, 1 and 0.5, --vi 5 to 60, three piles): the locked pairs at
 * 23.2 to 103 times the contact, the kept at 0.47 to 0.76 (layer_impl.h). */
static int xcorr_locked_at(const gw_layer_impact_result *r, double dt, double *delay, double *ref)
{
    *delay = *ref = NAN;
    if (!r || !r->xcorr_delay || r->nrings < 3 || !r->ring_r)
        return 0;
    double *slow = malloc((size_t)r->nrings * sizeof *slow);
    if (!slow)
        return 0;
    double c, cerr;
    int m;
    pair_speed_of(r, slow, &c, &cerr, &m);
    free(slow);
    const double dc = r->ring_r[1] - r->ring_r[0];
    if (!(c > 0) || !(dc > 0))
        return 0;
    /* a speed the resolution rule nulls already is not locked but unresolved
     * (not warned of as locked: a 60-disc pile's default impact, null before,
     * was warned of as locked at 17.55 m/s; its scatter is said instead,
     * layer_crowns_imprecise) */
    double cr = c, crerr = cerr;
    resolved_at(r, dt, &cr, &crerr);
    if (isnan(cr))
        return 0;
    /* the faster peak speed: the wave is at the crown no later than it says */
    const double cp = fmax(r->wave_speed > 0 ? r->wave_speed : 0, r->wave_speed_kin > 0 ? r->wave_speed_kin : 0);
    const double t = r->t_contact_open > 0 && isfinite(r->t_contact_open) ? r->t_contact_open
                     : cp > 0 ? dc / cp : NAN;
    if (!(t > 0))
        return 0;
    *delay = dc / c, *ref = t;
    return dc / c > LAYER_XCORR_LOCK * t;
}

int layer_crowns_xcorr_locked(const gw_layer_impact_result *r, double *delay, double *ref)
{
    *delay = *ref = NAN;
    return r && r->peak_strain_t && r->nrings >= 3 && xcorr_locked_at(r, crowns_dt(r), delay, ref);
}

/* Bits 1, 2 (strain peaks, kinetic peaks) when that peak speed, as fit and
 * kept by the resolution rule, follows the pile's slow motion: its crown
 * transit d_c / c more than LAYER_XCORR_LOCK times the first contact's time
 * to its opening (the rule of layer_crowns_xcorr_locked; none when that
 * contact did not open). The speeds read into c[0], c[1] (NaN when not
 * locked), that time into *ref. The 40-disc pile of `layer-make --n 40` at
 * --vi 40 --gravity 1 --other-settling --t-max 20 --dt-out 1e-2 (T_f 1.30 s)
 * gave 23.75 +- 6.0 and 14.75 +- 0.57 m/s, crowns of 0.65 m crossed in 0.027
 * and 0.044 s, 20 and 32 times its first contact (open at 1.36 ms), reported
 * without a word; the default impact's strain peaks cross a crown in 0.6 of
 * its first contact. */
static unsigned peaks_locked_at(const gw_layer_impact_result *r, double dt, double c[2], double *ref)
{
    c[0] = c[1] = *ref = NAN;
    if (!r || r->nrings < 3 || !r->ring_r || !r->peak_strain_t || !r->peak_kin_t)
        return 0;
    const double dc = r->ring_r[1] - r->ring_r[0], t = r->t_contact_open;
    if (!(dc > 0) || !(t > 0) || !isfinite(t))
        return 0;
    unsigned which = 0;
    for (int k = 0; k < 2; k++) {
        double v, err;
        int m;
        fit(r, k ? r->peak_kin_t : r->peak_strain_t, &v, &err, &m);
        resolved_at(r, dt, &v, &err);
        if (v > 0 && dc / v > LAYER_XCORR_LOCK * t)
            which |= 1u << k, c[k] = v;
    }
    if (which)
        *ref = t;
    return which;
}

unsigned layer_crowns_peaks_locked(const gw_layer_impact_result *r, double c[2], double *ref)
{
    c[0] = c[1] = *ref = NAN;
    return r && r->peak_strain_t && r->nrings >= 3 ? peaks_locked_at(r, crowns_dt(r), c, ref) : 0;
}

/* Bits 1, 2, 4 (strain peaks, kinetic peaks, cross-correlation) of the
 * speeds the resolution rule nulled for their scatter alone: read positive
 * and resolved by the sampling (d_c / c >= 2 dt at the interval the crowns
 * were read from) but with a standard error at or above half the speed; the
 * speeds and errors as read into c[3], err[3] (NaN for the others). The
 * default impact on the 40-disc pile of `layer-make --n 40` read its
 * cross-correlation speed from 10 ring pairs and nulled it so, with no
 * warning (issue 18 class 6: an undecided value is null with a warning). */
unsigned layer_crowns_imprecise(const gw_layer_impact_result *r, double c[3], double err[3])
{
    for (int q = 0; q < 3; q++)
        c[q] = err[q] = NAN;
    if (!r || r->nrings < 3 || !r->ring_r || !r->peak_strain_t || !r->peak_kin_t)
        return 0;
    const double dt = crowns_dt(r), dc = r->ring_r[1] - r->ring_r[0];
    const double now[3] = {r->wave_speed, r->wave_speed_kin, r->wave_speed_xcorr};
    double v[3] = {NAN, NAN, NAN}, e[3] = {NAN, NAN, NAN};
    int m;
    fit(r, r->peak_strain_t, &v[0], &e[0], &m);
    fit(r, r->peak_kin_t, &v[1], &e[1], &m);
    if (r->xcorr_delay) {
        double *slow = malloc((size_t)r->nrings * sizeof *slow);
        if (slow)
            pair_speed_of(r, slow, &v[2], &e[2], &m);
        free(slow);
    }
    unsigned which = 0;
    for (int q = 0; q < 3; q++)
        if (isnan(now[q]) && v[q] > 0 && dc / v[q] >= 2 * dt && !(e[q] < 0.5 * v[q]))
            which |= 1u << q, c[q] = v[q], err[q] = e[q];
    return which;
}

/* 1 when the arrivals tp of rings 1 .. nrings - 1 (3 or more) show a wave
 * faster than the sampling resolves: the outermost ring with an arrival within
 * two sampling intervals a crown of the innermost, either way (all in one
 * sample: a fit has no slope; a few samples apart: d_c / c < 2 dt). */
static int arrivals_undersampled(const gw_layer_impact_result *r, const double *tp, double dt)
{
    int k1 = -1, k2 = -1, m = 0;
    for (int k = 1; k < r->nrings; k++)
        if (isfinite(tp[k])) {
            if (k1 < 0)
                k1 = k;
            k2 = k, m++;
        }
    return m >= 3 && fabs(tp[k2] - tp[k1]) < 2 * dt * (k2 - k1);
}

/* The speeds the sampling left unresolved: an estimator whose speed is NaN
 * while its arrivals (or its pairs' delays) put the wave across a crown in
 * fewer than two sampling intervals, or the first impact holds fewer than 4
 * samples (*few: their count, else 0), where no arrival is a local maximum,
 * over a time the default interval (2e-5 s) samples 4 times.
 * Bits 1, 2, 4 (strain peaks, kinetic peaks, cross-correlation) into the
 * return value, the sampling interval into *dt_s and the crown width into
 * *dc_s. A --dt-out of 5 ms on the 40-disc pile
 * of `layer-make --n 40` nulled all three speeds (98, 372 m/s at 20 us)
 * without a word: layer_crowns_warning now says so, naming dt-out. */
unsigned layer_crowns_undersampled(const gw_layer_impact_result *r, double *dt_s, double *dc_s, int *few)
{
    *dt_s = *dc_s = NAN;
    *few = 0;
    if (!r || r->nrings < 2 || !r->ring_r || !r->peak_strain_t || !r->peak_kin_t)
        return 0;
    /* the series the crowns were read from (layer_crowns_series): the run's
     * checks, not the written samples, when --dt-out is coarser than them */
    const double *g = r->peak_strain_t + 3 * (size_t)r->nrings;
    const double dt = g[0], dc = r->ring_r[1] - r->ring_r[0], span = g[2];
    const int nw = (int)g[1];
    if (!(dt > 0) || !(dc > 0) || nw < 1)
        return 0;
    /* no arrival can be a sample's local maximum; put to the sampling when the
     * default interval (2e-5 s) would have given the first impact 4 samples,
     * else to the run's length (--t-max 3e-5 s) */
    if (nw < 4) {
        if (!(span >= 3 * 2e-5))
            return 0;
        *few = nw;
        *dt_s = dt, *dc_s = dc;
        return (isnan(r->wave_speed) ? 1u : 0u) | (isnan(r->wave_speed_kin) ? 2u : 0u) |
               (isnan(r->wave_speed_xcorr) ? 4u : 0u);
    }
    unsigned which = 0;
    double c, cerr;
    int m;
    if (isnan(r->wave_speed)) {
        fit(r, r->peak_strain_t, &c, &cerr, &m);
        if ((c > 0 && dc / c < 2 * dt) || arrivals_undersampled(r, r->peak_strain_t, dt))
            which |= 1;
    }
    if (isnan(r->wave_speed_kin)) {
        fit(r, r->peak_kin_t, &c, &cerr, &m);
        if ((c > 0 && dc / c < 2 * dt) || arrivals_undersampled(r, r->peak_kin_t, dt))
            which |= 2;
    }
    double *slow = r->xcorr_delay ? malloc((size_t)r->nrings * sizeof *slow) : NULL;
    if (isnan(r->wave_speed_xcorr) && slow) {
        pair_speed_of(r, slow, &c, &cerr, &m);
        if (isfinite(c) && dc / fabs(c) < 2 * dt)
            which |= 4;
    }
    free(slow);
    *few = 0;
    if (which)
        *dt_s = dt, *dc_s = dc;
    return which;
}

static int crowns_of(gw_layer_impact_result *r, double **donor, int rows)
{
    if (!r || layer_result_shape(r, 0, NULL) != GW_OK)
        return GW_EINVAL;
    const double thr = 1e-4 * r->e_incident;
    const int nw = first_impact_samples(r);
    for (int k = 0; k < r->nrings; k++) {
        r->peak_strain_t[k] = peak_time(r->t, r->ring_strain + k, nw, r->nrings, thr);
        r->peak_kin_t[k] = peak_time(r->t, r->ring_kin + k, nw, r->nrings, thr);
    }
    int nk;
    fit(r, r->peak_strain_t, &r->wave_speed, &r->wave_speed_err, &r->wave_rings);
    fit(r, r->peak_kin_t, &r->wave_speed_kin, &r->wave_speed_kin_err, &nk);
    r->wave_speed_xcorr = r->wave_speed_xcorr_err = NAN;
    r->xcorr_gaps = 0;
    free(r->xcorr_delay); /* a second analysis of the same series */
    r->xcorr_delay = r->xcorr_rho = r->spec_strain = r->spec_kin = NULL;
    r->spec_len = 0;
    r->spec_df = NAN;
    int rc = crowns_xcorr(r, thr, nw, donor, rows);
    resolved(r, &r->wave_speed, &r->wave_speed_err);
    resolved(r, &r->wave_speed_kin, &r->wave_speed_kin_err);
    resolved(r, &r->wave_speed_xcorr, &r->wave_speed_xcorr_err);
    double delay, ref;
    const double dt = r->ns >= 2 ? r->t[1] - r->t[0] : NAN;
    if (xcorr_locked_at(r, dt, &delay, &ref))
        r->wave_speed_xcorr = r->wave_speed_xcorr_err = NAN; /* undecided: layer_crowns_warning */
    double cp[2];
    const unsigned peaks = peaks_locked_at(r, dt, cp, &ref);
    if (peaks & 1u)
        r->wave_speed = r->wave_speed_err = NAN; /* undecided: layer_crowns_warning */
    if (peaks & 2u)
        r->wave_speed_kin = r->wave_speed_kin_err = NAN;
    return rc;
}

int gw_layer_crowns(gw_layer_impact_result *r)
{
    return crowns_of(r, NULL, 0);
}

int layer_crowns_series(gw_layer_impact_result *r, double *t, double **buf, int rows, int n)
{
    double *const t0 = r->t, *const s0 = r->ring_strain, *const k0 = r->ring_kin;
    const int ns0 = r->ns;
    if (t)
        r->t = t, r->ring_strain = *buf + 2 * (size_t)r->nrings,
        r->ring_kin = r->ring_strain + (size_t)rows * r->nrings, r->ns = n;
    const int rc = crowns_of(r, t ? buf : NULL, rows);
    double *g = r->peak_strain_t + 3 * (size_t)r->nrings;
    const int nw = rc == GW_OK ? first_impact_samples(r) : 0;
    g[0] = r->ns >= 2 ? r->t[1] - r->t[0] : NAN;
    g[1] = nw;
    g[2] = nw >= 1 ? r->t[nw - 1] - r->t[0] : 0;
    r->t = t0, r->ring_strain = s0, r->ring_kin = k0, r->ns = ns0;
    return rc;
}
