/*
 * chain_dispersion.c: small-amplitude dispersion of a precompressed Hertz chain
 * from its space-time spectrum (docs/physics.md 1.6). The column's wall-force
 * spectrum is in chain_spectrum.c, the command in app/chain/chain_dispersion_cmd.c.
 *
 * Model: u_i is the displacement of bead i from its equilibrium site along the
 * chain (m), v_i = u_i' (m/s), state y[2i] = u_i, y[2i+1] = v_i. Contact
 * (i, i+1) has overlap d_i = d0 + u_i - u_(i+1) and force F_i = k d_i^(3/2) for
 * d_i > 0, else 0 (no tension); m u_i'' = F_(i-1) - F_i. With
 * d0 = (F0/k)^(2/3) every contact carries F0 at rest; F0 is subtracted from
 * every force (it cancels in each difference) so the small perturbation keeps
 * its digits. Periodic ends: u_n = u_0. Fixed ends: rigid neighbours
 * u_(-1) = u_n = 0 touching beads 0 and n-1 with the same law (n+1 contacts).
 * Linearised: kappa = dF/dd(d0) = (3/2) k^(2/3) F0^(1/3),
 *     omega(q) = 2 sqrt(kappa/m) |sin(q a/2)|,  a = 2R - d0,  c0 = a sqrt(kappa/m).
 *
 * Spectrum: v_i(t_l), t_l = l dt, l < T, windowed by w_l = sin^2(pi l/T) (Hann),
 * 2D r2c FFT over (site, time). Fixed ends: the samples are extended oddly to
 * 2(n+1) sites, (0, v_0 .. v_(n-1), 0, -v_(n-1) .. -v_0), so the standing modes
 * sin(pi j (i+1)/(n+1)) fall exactly on FFT bin j. Power of wavenumber j:
 * |V(j, l)|^2 + |V(-j, l)|^2 (both travelling directions). Ridge: the bin of
 * maximum power refined by a parabola through log P at l-1, l, l+1.
 * Units: SI (m, s, kg, N, rad/s; wall spectrum in Hz).
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <fftw3.h>

#include "gw_chain.h"
#include "gw_chain_study.h"
#include "gw_global.h"
#include "gw_locale.h"
#include "gw_number_impl.h"

gw_chain_disp_params gw_chain_disp_params_default(void)
{
    gw_chain_params c = gw_chain_params_default();
    gw_chain_disp_params p;
    memset(&p, 0, sizeof p);
    p.n = 1024;
    p.f0 = 10.0;
    p.mass = c.mass;
    p.k = c.k;
    p.radius = c.radius;
    p.ends = GW_CHAIN_DISP_PERIODIC;
    p.amp = 1e-3;
    p.seed = 1;
    p.t_samples = 2048;
    p.dt_sample = 0.0;
    p.steps_per_sample = 16;
    p.min_bins = 8.0;
    p.fftw_measure = 0;
    return p;
}

double gw_chain_disp_kappa(double k, double f0)
{
    if (!(k >= 0) || !(f0 >= 0)) /* cbrt of a negative f0: a negative stiffness */
        return NAN;
    return 1.5 * pow(k, 2.0 / 3.0) * cbrt(f0);
}

double gw_chain_disp_omega(double kappa, double m, double qa)
{
    if (!(kappa >= 0) || !(m > 0)) /* a mass of 0 gave inf rad/s, a negative one or kappa -nan */
        return NAN;
    return 2.0 * sqrt(kappa / m) * fabs(sin(0.5 * qa));
}

static double disp_d0(const gw_chain_disp_params *p)
{
    return pow(p->f0 / p->k, 2.0 / 3.0);
}

static double disp_omega_c(const gw_chain_disp_params *p)
{
    return 2.0 * sqrt(gw_chain_disp_kappa(p->k, p->f0) / p->mass);
}

/* Sampling interval: the given one or omega_c at 80 % of Nyquist. */
double gw_chain_disp_dt_sample(const gw_chain_disp_params *p)
{
    /* 0 is automatic; a NaN, negative or infinite interval is none (it was
     * given the automatic value, as gw_chain_disp_params_validate refuses it) */
    if (!p || !(p->dt_sample >= 0) || !isfinite(p->dt_sample))
        return NAN;
    return p->dt_sample > 0 ? p->dt_sample : M_PI / (1.25 * disp_omega_c(p));
}

/* Sites of the spatial transform: n (periodic) or 2(n+1) (odd extension). */
static int disp_nx(const gw_chain_disp_params *p)
{
    return p->ends == GW_CHAIN_DISP_FIXED ? 2 * (p->n + 1) : p->n;
}

int gw_chain_disp_params_validate(const gw_chain_disp_params *p, gw_err *err)
{
    if (!p)
        return gw_err_set(err, GW_EINVAL, "gw_chain_disp_params_validate: p is NULL");
    int rc;
    if (p->n < 8 || p->n > (1 << 22))
        return gw_err_set(err, GW_EINVAL, "n: %d beads outside [8, %d]", p->n, 1 << 22);
    if ((rc = gw_check_positive(p->f0, "--f0 (precompression, N)", err)) != GW_OK ||
        (rc = gw_check_positive(p->mass, "mass (kg)", err)) != GW_OK ||
        (rc = gw_check_positive(p->k, "k (Hertz coefficient, N/m^1.5)", err)) != GW_OK ||
        (rc = gw_check_positive(p->radius, "radius (m)", err)) != GW_OK)
        return rc;
    /* the overlap d0 sets the solver's scales: a subnormal one (f0 4.9e-324 N:
     * 0 m) failed at the run as "solver: scale[0] = 0 must be finite", naming
     * no input (the fiftieth pass) */
    if (!(disp_d0(p) >= DBL_MIN))
        return gw_err_set(err, GW_EINVAL, "f0: %g N gives an overlap d0 = %g m below the normal doubles "
                          "(2.2251e-308): the solver's scales underflow; give a larger precompression", p->f0,
                          disp_d0(p));
    if (!(disp_d0(p) < p->radius))
        return gw_err_set(err, GW_EINVAL, "f0: %g N gives an overlap d0 = %g m beyond the bead radius %g m (Hertz invalid)",
                          p->f0, disp_d0(p), p->radius);
    if (p->ends != GW_CHAIN_DISP_PERIODIC && p->ends != GW_CHAIN_DISP_FIXED)
        return gw_err_set(err, GW_EINVAL, "ends: unknown end condition %d", (int)p->ends);
    if (!(p->amp >= GW_CHAIN_DISP_AMP_MIN && p->amp <= 0.1)) {
        char xs[40], ls[40], hs[40];
        gw_num_bound(ls, sizeof ls, GW_CHAIN_DISP_AMP_MIN, 0);
        return gw_err_set(err, GW_EINVAL, "amp: %s outside [%s, %s] (the analysis is linear; below %s the "
                          "perturbation nears the rounding of the overlap d0 and the ridge moves, by 12 %% at 1e-16)",
                          gw_num_text(xs, sizeof xs, p->amp), ls, gw_num_bound(hs, sizeof hs, 0.1, 1), ls);
    }
    if (p->t_samples < 64 || p->t_samples > (1 << 24) || p->t_samples % 2)
        return gw_err_set(err, GW_EINVAL, "t-samples: %d must be even and in [64, %d]", p->t_samples, 1 << 24);
    if ((double)disp_nx(p) * p->t_samples > (double)(1L << 27))
        return gw_err_set(err, GW_EINVAL, "t-samples: %d samples x %d sites exceed the 2^27-point transform limit",
                          p->t_samples, disp_nx(p));
    if (!(p->dt_sample >= 0) || !isfinite(p->dt_sample))
        return gw_err_set(err, GW_EINVAL, "dt-out: %g must be >= 0 (0 = auto)", p->dt_sample);
    /* a subnormal interval made rk4's step 0 ("rk4: the fixed step dt must be
     * set (> 0)", naming no input; the fiftieth pass) */
    if (p->dt_sample > 0 && p->dt_sample < DBL_MIN)
        return gw_err_set(err, GW_EINVAL, "dt-out: %g s is a subnormal number (below 2.2251e-308, the smallest "
                          "normal double): give 0 (auto) or a normal number", p->dt_sample);
    if (p->fftw_measure != 0 && p->fftw_measure != 1)
        return gw_err_set(err, GW_EINVAL, "fftw_measure: %d is not a flag (0: FFTW_ESTIMATE, 1: FFTW_MEASURE)",
                          p->fftw_measure);
    double wc = disp_omega_c(p), dts = gw_chain_disp_dt_sample(p);
    if (!(wc * dts < M_PI))
        return gw_err_set(err, GW_EINVAL, "dt-out: %g s puts the cutoff omega_c = %g rad/s above Nyquist pi/dt = %g rad/s",
                          dts, wc, M_PI / dts);
    if (p->steps_per_sample < 1 || p->steps_per_sample > 100000)
        return gw_err_set(err, GW_EINVAL, "steps-per-sample: %d outside [1, 100000]", p->steps_per_sample);
    /* the run's work, sites x samples x steps, bounded as the layer's (1e10):
     * the largest transform at the default 16 steps is 2.1e9 bead-steps (about
     * 2 min); --steps-per-sample 100000 at the defaults meant 2.1e11 (about 3 h,
     * measured 1.7e7 bead-steps/s) and up to 1.3e13 with no line said */
    const double work = (double)disp_nx(p) * p->t_samples * p->steps_per_sample;
    if (work > 1e10)
        return gw_err_set(err, GW_EINVAL, "steps-per-sample: %d steps x %d samples x %d sites are %.3g bead-steps, "
                          "more than 1e10: at most %.0f steps per sample here", p->steps_per_sample, p->t_samples,
                          disp_nx(p), work, floor(1e10 / ((double)disp_nx(p) * p->t_samples)));
    /* RK4 is stable for h omega < 2.8; at h omega_c = 1 its frequency error is
     * already ~1e-2, so refuse coarser steps. */
    if (wc * dts / p->steps_per_sample > 1.0)
        return gw_err_set(err, GW_EINVAL, "steps-per-sample: %d gives h omega_c = %.3g > 1 (RK4 inaccurate); use >= %d",
                          p->steps_per_sample, wc * dts / p->steps_per_sample, (int)ceil(wc * dts));
    if (!(p->min_bins >= 1) || !isfinite(p->min_bins))
        return gw_err_set(err, GW_EINVAL, "min-bins: %g must be >= 1", p->min_bins);
    /* a count held as a double (ABI 3): 1.5 bins ran as a ridge from 2 bins up */
    if (p->min_bins != floor(p->min_bins))
        return gw_err_set(err, GW_EINVAL, "min-bins: %.17g is not a whole number (a count of frequency bins)",
                          p->min_bins);
    /* the ridge search (disp_analyse below) takes the peak bin lm in [1, T/2 - 2] and
     * refines it by at most half a bin: a ridge above T/2 - 2 bins is never found */
    if (p->min_bins > p->t_samples / 2 - 2)
        return gw_err_set(err, GW_EINVAL,
                          "min-bins: %.0f is above %d, the highest frequency bin a ridge can be found in "
                          "with t-samples %d (T/2 - 2): nothing would be resolved",
                          p->min_bins, p->t_samples / 2 - 2, p->t_samples);
    return GW_OK;
}

/* ---- model ---- */

typedef struct disp_model {
    int n, fixed;
    double k, f0, d0, minv;
} disp_model;

/* Contact force minus F0 (clamped: an open contact carries nothing). */
static inline double excess_force(const disp_model *md, double d)
{
    return (d > 0 ? md->k * d * sqrt(d) : 0.0) - md->f0;
}

static int disp_rhs(double t, const double *y, double *yd, void *P)
{
    (void)t;
    const disp_model *md = P;
    const int n = md->n;
    const double d0 = md->d0;
    double gprev = md->fixed ? excess_force(md, d0 - y[0])
                             : excess_force(md, d0 + y[2 * n - 2] - y[0]);
    for (int i = 0; i < n; i++) {
        double unext = i < n - 1 ? y[2 * i + 2] : (md->fixed ? 0.0 : y[0]);
        double g = excess_force(md, d0 + y[2 * i] - unext);
        yd[2 * i] = y[2 * i + 1];
        yd[2 * i + 1] = (gprev - g) * md->minv;
        gprev = g;
    }
    return 0;
}

/* splitmix64: a small deterministic generator, state on the caller's stack. */
static double rng_uniform(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) / 9007199254740992.0;
}

/* Equilibrium positions and random small velocities with a flat mode spectrum:
 * every normal mode gets the same amplitude and a random phase (periodic:
 * v_i = sum_j 2 cos(2 pi j i/n + phi_j), j = 1..n/2, by a c2r transform) or a
 * random sign (fixed: v_i = sum_j 2 s_j sin(pi j (i+1)/(n+1)), j = 1..n, by a
 * DST-I). White random velocities leave some modes with almost no energy, and
 * there the weak nonlinear combination tones can outweigh the mode's own
 * line. No q = 0 component: the ring does not drift. A mode of velocity V
 * changes the overlaps by V / sqrt(kappa/m) whatever its q, so the rms velocity
 * is v_rms = amp d0 sqrt(kappa/m). */
static int disp_initial_state(const gw_chain_disp_params *p, double v_rms, double *y)
{
    const int n = p->n, fixed = p->ends == GW_CHAIN_DISP_FIXED;
    uint64_t s = (uint64_t)p->seed;
    double *v = fftw_malloc((size_t)n * sizeof *v), *a = NULL;
    fftw_complex *c = NULL;
    fftw_plan plan = NULL;
    gw_fftw_planner_lock(); /* FFTW's planner is not thread-safe */
    if (v && fixed && (a = fftw_malloc((size_t)n * sizeof *a)))
        plan = fftw_plan_r2r_1d(n, a, v, FFTW_RODFT00, FFTW_ESTIMATE);
    else if (v && !fixed && (c = fftw_malloc((size_t)(n / 2 + 1) * sizeof *c)))
        plan = fftw_plan_dft_c2r_1d(n, c, v, FFTW_ESTIMATE);
    gw_fftw_planner_unlock();
    if (!plan) {
        fftw_free(v);
        fftw_free(a);
        fftw_free(c);
        return GW_ENOMEM;
    }
    for (int j = 0; fixed && j < n; j++)
        a[j] = rng_uniform(&s) < 0.5 ? -1.0 : 1.0;
    for (int j = 0; !fixed && j <= n / 2; j++) {
        double phi = 2.0 * M_PI * rng_uniform(&s);
        c[j][0] = j > 0 ? cos(phi) : 0.0;
        c[j][1] = j > 0 && 2 * j != n ? sin(phi) : 0.0;
    }
    fftw_execute(plan);
    double ss = 0;
    for (int i = 0; i < n; i++)
        ss += v[i] * v[i];
    double f = v_rms / sqrt(ss / n);
    for (int i = 0; i < n; i++) {
        y[2 * i] = 0.0;
        y[2 * i + 1] = f * v[i];
    }
    gw_fftw_planner_lock();
    fftw_destroy_plan(plan);
    gw_fftw_planner_unlock();
    fftw_free(v);
    fftw_free(a);
    fftw_free(c);
    return GW_OK;
}

/* Store the windowed velocities of sample it into column it of in[nx][nt] and
 * track the largest overlap deviation. */
static void disp_record(const disp_model *md, const double *y, double w, int it, int nt,
                        double *in, double *maxdev)
{
    const int n = md->n;
    const size_t T = (size_t)nt, m = (size_t)n + 1;
    double dev = md->fixed ? fmax(fabs(y[0]), fabs(y[2 * n - 2])) : fabs(y[2 * n - 2] - y[0]);
    for (int i = 0; i < n - 1; i++)
        dev = fmax(dev, fabs(y[2 * i] - y[2 * i + 2]));
    *maxdev = fmax(*maxdev, dev / md->d0);
    if (!md->fixed) {
        for (int i = 0; i < n; i++)
            in[(size_t)i * T + (size_t)it] = w * y[2 * i + 1];
        return;
    }
    in[it] = 0.0;
    in[m * T + (size_t)it] = 0.0;
    for (size_t i = 0; i < (size_t)n; i++) {
        double v = w * y[2 * i + 1];
        in[(1 + i) * T + (size_t)it] = v;
        in[(2 * m - 1 - i) * T + (size_t)it] = -v;
    }
}

/* Parabola through log power at l-1, l, l+1: offset of the vertex in bins. */
static int disp_alloc(gw_chain_disp_result *r, int nq, int nw)
{
    r->nq = nq;
    r->n_omega = nw;
    r->qa = malloc((size_t)nq * 4 * sizeof *r->qa);
    r->resolved = calloc((size_t)nq, sizeof *r->resolved);
    r->power = malloc((size_t)nq * (size_t)nw * sizeof *r->power);
    if (!r->qa || !r->resolved || !r->power)
        return GW_ENOMEM;
    r->omega_ridge = r->qa + nq;
    r->omega_theory = r->qa + 2 * nq;
    r->ridge_power = r->qa + 3 * nq;
    return GW_OK;
}

void gw_chain_disp_result_free(gw_chain_disp_result *r)
{
    if (!r)
        return;
    free(r->qa);
    free(r->resolved);
    free(r->power);
    memset(r, 0, sizeof *r);
}

/* Fold +q and -q into r->power, then ridge, cutoff and long-wave speed.
 * GW_ENOMEM when the long-wave fit's points find no memory. */
static int disp_analyse(const gw_chain_disp_params *p, fftw_complex *out, int nx,
                        gw_chain_disp_result *r)
{
    const int nq = r->nq, nw = r->n_omega;
    const double dq = 2.0 * M_PI / nx, wc = r->omega_c_theory;
    double smax = 0, edge_level = 0;
    for (int j = 1; j <= nq; j++) {
        double *row = r->power + (size_t)(j - 1) * (size_t)nw;
        fftw_complex *a = out + (size_t)j * (size_t)nw, *b = out + (size_t)(nx - j) * (size_t)nw;
        for (int l = 0; l < nw; l++) {
            row[l] = a[l][0] * a[l][0] + a[l][1] * a[l][1];
            if (nx - j != j)
                row[l] += b[l][0] * b[l][0] + b[l][1] * b[l][1];
        }
    }
    /* q-summed spectrum for the edge estimate, one frequency at a time. */
    r->omega_edge = NAN;
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1)
            edge_level = 1e-3 * smax;
        for (int l = 0; l < nw; l++) {
            double s = 0;
            for (int j = 0; j < nq; j++)
                s += r->power[(size_t)j * (size_t)nw + (size_t)l];
            if (pass == 0)
                smax = fmax(smax, s);
            else if (s >= edge_level)
                r->omega_edge = l * r->d_omega;
        }
    }
    r->ridge_max_rel_err = 0;
    r->omega_c_measured = 0;
    double wc_at = wc; /* the theory at the wavenumber of the highest ridge */
    r->n_resolved = 0;
    r->qa_resolved_min = r->qa_resolved_max = NAN;
    /* every resolved qa <= 0.5 (a fixed 64 of them kept the first 64: with n = 1024,
     * 78 resolved, c0 598.7556 where the fit over all gives 598.7587 m/s) */
    double *xs = malloc(2 * (size_t)nq * sizeof *xs), *ys = xs ? xs + nq : NULL;
    int nfit = 0;
    if (!xs)
        return GW_ENOMEM;
    for (int j = 1; j <= nq; j++) {
        const double *row = r->power + (size_t)(j - 1) * (size_t)nw;
        int lm = 1;
        for (int l = 2; l < nw - 1; l++)
            if (row[l] > row[lm])
                lm = l;
        double bins = lm + gw_peak_offset_log(row[lm - 1], row[lm], row[lm + 1]);
        int k = j - 1;
        r->qa[k] = j * dq;
        r->omega_ridge[k] = bins * r->d_omega;
        r->omega_theory[k] = wc * fabs(sin(0.5 * r->qa[k]));
        r->ridge_power[k] = row[lm];
        r->resolved[k] = bins >= p->min_bins && lm < nw - 2 && row[lm] > 0;
        if (!r->resolved[k])
            continue;
        double e = fabs(r->omega_ridge[k] - r->omega_theory[k]) / r->omega_theory[k];
        r->ridge_max_rel_err = fmax(r->ridge_max_rel_err, e);
        if (r->omega_ridge[k] > r->omega_c_measured) {
            r->omega_c_measured = r->omega_ridge[k];
            wc_at = r->omega_theory[k];
        }
        if (r->n_resolved++ == 0)
            r->qa_resolved_min = r->qa[k];
        r->qa_resolved_max = r->qa[k];
        if (r->qa[k] <= 0.5) {
            xs[nfit] = r->qa[k] * r->qa[k];
            ys[nfit++] = r->omega_ridge[k] / r->qa[k];
        }
    }
    if (r->n_resolved == 0) /* nothing measured: no error to report either */
        r->omega_c_measured = r->ridge_max_rel_err = NAN;
    /* against omega(qa) at that ridge's own wavenumber: qa = pi (where omega =
     * omega_c) is a wavenumber of the ring only for even n, never of fixed ends
     * (qa = pi j/(n+1)); n = 9 periodic or 8 fixed put the highest one at 0.89 pi,
     * and the model's exact ridge was reported 1.5 % off omega_c */
    r->omega_c_rel_err = fabs(r->omega_c_measured - wc_at) / wc_at;
    /* omega/(qa) = sqrt(kappa/m) (1 - (qa)^2/24 + ...): the intercept against
     * (qa)^2 is the long-wave limit, free of the curvature to O((qa)^4). */
    gw_linfit fit;
    r->c0_measured = NAN;
    if (nfit >= 3 && gw_fit_linear(xs, ys, nfit, &fit) == GW_OK)
        r->c0_measured = r->a * fit.c0;
    free(xs);
    return GW_OK;
}

/* Integrate and sample into in[nx][nt]. */
static int disp_integrate(const gw_chain_disp_params *p, const gw_solver_type *type,
                          const gw_solver_params *sp0, gw_progress_fn progress, void *pctx, double *in,
                          gw_chain_disp_result *r, gw_err *err)
{
    const int n = p->n, nt = p->t_samples, fixed = p->ends == GW_CHAIN_DISP_FIXED;
    disp_model md = {n, fixed, p->k, p->f0, r->d0, 1.0 / p->mass};
    double v_rms = p->amp * r->d0 * sqrt(r->kappa / p->mass);
    double *y = malloc((size_t)(4 * n) * sizeof *y), *scale = y + 2 * n;
    if (!y)
        return gw_err_set(err, GW_ENOMEM, "dispersion: out of memory for %d beads", n);
    for (int i = 0; i < n; i++) {
        scale[2 * i] = p->amp * r->d0;
        scale[2 * i + 1] = v_rms;
    }
    gw_system sys = {.dim = 2L * n, .rhs = disp_rhs, .mu = fixed ? 3 : 2L * n - 1,
                     .ml = fixed ? 3 : 2L * n - 1, .scale = scale, .params = &md};
    gw_solver_params sp = *sp0;
    if (type == gw_solver_rk4) {
        sp.dt = r->dt_step;
        if (sp.max_steps < 2L * p->steps_per_sample)
            sp.max_steps = 2L * p->steps_per_sample;
    } else if (sp.method == GW_METHOD_DEFAULT) {
        sp.method = type == gw_solver_cvode ? GW_CVODE_ADAMS : GW_ARKODE_ERK;
    }
    int rc = GW_OK;
    if (!fixed && (sp.method == GW_CVODE_BDF || sp.method == GW_ARKODE_DIRK))
        rc = gw_err_set(err, GW_EUNSUPPORTED, "method: %s needs ends fixed (the periodic Jacobian is not banded)",
                        gw_solver_method_name(sp.method));
    if (rc == GW_OK && disp_initial_state(p, v_rms, y) != GW_OK)
        rc = gw_err_set(err, GW_ENOMEM, "dispersion: out of memory for the initial state");
    gw_solver *s = NULL;
    if (rc == GW_OK)
        rc = gw_solver_create(type, &sys, &sp, 0.0, y, &s, err);
    double t = 0;
    for (int it = 0; rc == GW_OK && it < nt; it++) {
        if (it > 0 && (rc = gw_solver_advance(s, it * r->dt_sample, &t, y, NULL)) != GW_OK) {
            rc = gw_err_set(err, rc == GW_ROOT ? GW_ESOLVER : rc, "dispersion: %s", gw_solver_error(s));
            break;
        }
        double w = sin(M_PI * it / nt);
        disp_record(&md, y, w * w, it, nt, in, &r->max_overlap_dev);
        if (progress && progress(pctx, it + 1L, nt) != 0) {
            rc = gw_err_set(err, GW_ECANCELED, "dispersion: stopped by the progress callback after %d of %d samples",
                            it + 1, nt);
            break;
        }
    }
    if (s)
        gw_solver_get_stats(s, &r->stats);
    gw_solver_free(s);
    free(y);
    return rc;
}

int gw_chain_disp_run(const gw_chain_disp_params *p, const gw_solver_type *solver,
                      const gw_solver_params *sp, gw_chain_disp_result *r, gw_err *err)
{
    return gw_chain_disp_run_progress(p, solver, sp, NULL, NULL, r, err);
}

int gw_chain_disp_run_progress(const gw_chain_disp_params *p, const gw_solver_type *solver,
                               const gw_solver_params *sp, gw_progress_fn progress, void *pctx,
                               gw_chain_disp_result *r, gw_err *err)
{
    if (r) /* NULL refused as gw_chain_collide does (it was dereferenced: SIGSEGV) */
        memset(r, 0, sizeof *r);
    if (!p || !sp || !r)
        return gw_err_set(err, GW_EINVAL, "gw_chain_disp_run: %s is NULL", !p ? "p" : !sp ? "sp" : "r");
    int rc = gw_chain_disp_params_validate(p, err);
    if (rc != GW_OK)
        return rc;
    const int nx = disp_nx(p), nt = p->t_samples, nw = nt / 2 + 1;
    const int nq = p->ends == GW_CHAIN_DISP_FIXED ? p->n : p->n / 2;
    r->d0 = disp_d0(p);
    r->kappa = gw_chain_disp_kappa(p->k, p->f0);
    r->a = 2.0 * p->radius - r->d0;
    r->omega_c_theory = disp_omega_c(p);
    r->c0_theory = r->a * sqrt(r->kappa / p->mass);
    r->dt_sample = gw_chain_disp_dt_sample(p);
    r->dt_step = r->dt_sample / p->steps_per_sample;
    r->t_total = (nt - 1) * r->dt_sample;
    r->d_omega = 2.0 * M_PI / (nt * r->dt_sample);
    double *in = fftw_malloc((size_t)nx * (size_t)nt * sizeof *in);
    fftw_complex *out = fftw_malloc((size_t)nx * (size_t)nw * sizeof *out);
    if (!in || !out || disp_alloc(r, nq, nw) != GW_OK) {
        fftw_free(in);
        fftw_free(out);
        return gw_err_set(err, GW_ENOMEM, "dispersion: out of memory for %d x %d samples", nx, nt);
    }
    /* Plan before filling: FFTW_MEASURE overwrites the arrays while planning. */
    double t0 = gw_clock_ms();
    gw_fftw_planner_lock(); /* FFTW's planner is not thread-safe */
    fftw_plan plan = fftw_plan_dft_r2c_2d(nx, nt, in, out, p->fftw_measure ? FFTW_MEASURE : FFTW_ESTIMATE);
    gw_fftw_planner_unlock();
    if (!plan)
        rc = gw_err_set(err, GW_ENOMEM, "dispersion: FFTW could not plan a %d x %d transform", nx, nt);
    double plan_ms = gw_clock_ms() - t0;
    if (rc == GW_OK) {
        t0 = gw_clock_ms();
        rc = disp_integrate(p, solver ? solver : gw_solver_rk4, sp, progress, pctx, in, r, err);
        r->integrate_ms = gw_clock_ms() - t0;
    }
    if (rc == GW_OK) {
        t0 = gw_clock_ms();
        fftw_execute(plan);
        if (disp_analyse(p, out, nx, r) != GW_OK)
            rc = gw_err_set(err, GW_ENOMEM, "dispersion: out of memory for the long-wave fit");
        r->fft_ms = gw_clock_ms() - t0 + plan_ms;
    }
    if (plan) {
        gw_fftw_planner_lock();
        fftw_destroy_plan(plan);
        gw_fftw_planner_unlock();
    }
    fftw_free(in);
    fftw_free(out);
    return rc;
}
