/*
 * chain_dispersion.c: small-amplitude dispersion of a precompressed Hertz chain
 * from its space-time spectrum (physics.md 1.6), the power spectrum of a
 * column's wall force, and `granwave dispersion`.
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
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <fftw3.h>

#include "chain_options.h"

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
    return 1.5 * pow(k, 2.0 / 3.0) * cbrt(f0);
}

double gw_chain_disp_omega(double kappa, double m, double qa)
{
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
static double disp_dt_sample(const gw_chain_disp_params *p)
{
    return p->dt_sample > 0 ? p->dt_sample : M_PI / (1.25 * disp_omega_c(p));
}

/* Sites of the spatial transform: n (periodic) or 2(n+1) (odd extension). */
static int disp_nx(const gw_chain_disp_params *p)
{
    return p->ends == GW_CHAIN_DISP_FIXED ? 2 * (p->n + 1) : p->n;
}

int gw_chain_disp_params_validate(const gw_chain_disp_params *p, gw_err *err)
{
    int rc;
    if (p->n < 8 || p->n > (1 << 22))
        return gw_err_set(err, GW_EINVAL, "--n: %d beads outside [8, %d]", p->n, 1 << 22);
    if ((rc = gw_check_positive(p->f0, "--f0 (precompression, N)", err)) != GW_OK ||
        (rc = gw_check_positive(p->mass, "mass (kg)", err)) != GW_OK ||
        (rc = gw_check_positive(p->k, "k (Hertz coefficient, N/m^1.5)", err)) != GW_OK ||
        (rc = gw_check_positive(p->radius, "radius (m)", err)) != GW_OK)
        return rc;
    if (!(disp_d0(p) < p->radius))
        return gw_err_set(err, GW_EINVAL, "--f0: %g N gives an overlap d0 = %g m beyond the bead radius %g m (Hertz invalid)",
                          p->f0, disp_d0(p), p->radius);
    if (p->ends != GW_CHAIN_DISP_PERIODIC && p->ends != GW_CHAIN_DISP_FIXED)
        return gw_err_set(err, GW_EINVAL, "--ends: unknown end condition %d", (int)p->ends);
    if (!(p->amp > 0 && p->amp <= 0.1))
        return gw_err_set(err, GW_EINVAL, "--amp: %g outside (0, 0.1] (the analysis is linear)", p->amp);
    if (p->t_samples < 64 || p->t_samples > (1 << 24) || p->t_samples % 2)
        return gw_err_set(err, GW_EINVAL, "--t-samples: %d must be even and in [64, %d]", p->t_samples, 1 << 24);
    if ((double)disp_nx(p) * p->t_samples > (double)(1L << 27))
        return gw_err_set(err, GW_EINVAL, "--t-samples: %d samples x %d sites exceed the 2^27-point transform limit",
                          p->t_samples, disp_nx(p));
    if (!(p->dt_sample >= 0) || !isfinite(p->dt_sample))
        return gw_err_set(err, GW_EINVAL, "--dt-out: %g must be >= 0 (0 = auto)", p->dt_sample);
    double wc = disp_omega_c(p), dts = disp_dt_sample(p);
    if (!(wc * dts < M_PI))
        return gw_err_set(err, GW_EINVAL, "--dt-out: %g s puts the cutoff omega_c = %g rad/s above Nyquist pi/dt = %g rad/s",
                          dts, wc, M_PI / dts);
    if (p->steps_per_sample < 1 || p->steps_per_sample > 100000)
        return gw_err_set(err, GW_EINVAL, "--steps-per-sample: %d outside [1, 100000]", p->steps_per_sample);
    /* RK4 is stable for h omega < 2.8; at h omega_c = 1 its frequency error is
     * already ~1e-2, so refuse coarser steps. */
    if (wc * dts / p->steps_per_sample > 1.0)
        return gw_err_set(err, GW_EINVAL, "--steps-per-sample: %d gives h omega_c = %.3g > 1 (RK4 inaccurate); use >= %d",
                          p->steps_per_sample, wc * dts / p->steps_per_sample, (int)ceil(wc * dts));
    if (!(p->min_bins >= 1) || !isfinite(p->min_bins))
        return gw_err_set(err, GW_EINVAL, "--min-bins: %g must be >= 1", p->min_bins);
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
    if (v && fixed && (a = fftw_malloc((size_t)n * sizeof *a)))
        plan = fftw_plan_r2r_1d(n, a, v, FFTW_RODFT00, FFTW_ESTIMATE);
    else if (v && !fixed && (c = fftw_malloc((size_t)(n / 2 + 1) * sizeof *c)))
        plan = fftw_plan_dft_c2r_1d(n, c, v, FFTW_ESTIMATE);
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
    fftw_destroy_plan(plan);
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
static double log_parabola(double pm, double p0, double pp)
{
    if (!(pm > 0 && p0 > 0 && pp > 0))
        return 0.0;
    double a = log(pm), b = log(p0), c = log(pp), den = a - 2 * b + c;
    double off = den < 0 ? 0.5 * (a - c) / den : 0.0;
    return fabs(off) <= 1.0 ? off : 0.0;
}

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

/* Fold +q and -q into r->power, then ridge, cutoff and long-wave speed. */
static void disp_analyse(const gw_chain_disp_params *p, fftw_complex *out, int nx,
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
    r->n_resolved = 0;
    r->qa_resolved_min = r->qa_resolved_max = NAN;
    double xs[64], ys[64];
    int nfit = 0;
    for (int j = 1; j <= nq; j++) {
        const double *row = r->power + (size_t)(j - 1) * (size_t)nw;
        int lm = 1;
        for (int l = 2; l < nw - 1; l++)
            if (row[l] > row[lm])
                lm = l;
        double bins = lm + log_parabola(row[lm - 1], row[lm], row[lm + 1]);
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
        r->omega_c_measured = fmax(r->omega_c_measured, r->omega_ridge[k]);
        if (r->n_resolved++ == 0)
            r->qa_resolved_min = r->qa[k];
        r->qa_resolved_max = r->qa[k];
        if (r->qa[k] <= 0.5 && nfit < 64) {
            xs[nfit] = r->qa[k] * r->qa[k];
            ys[nfit++] = r->omega_ridge[k] / r->qa[k];
        }
    }
    if (r->n_resolved == 0)
        r->omega_c_measured = NAN;
    r->omega_c_rel_err = fabs(r->omega_c_measured - wc) / wc;
    /* omega/(qa) = sqrt(kappa/m) (1 - (qa)^2/24 + ...): the intercept against
     * (qa)^2 is the long-wave limit, free of the curvature to O((qa)^4). */
    gw_linfit fit;
    r->c0_measured = NAN;
    if (nfit >= 3 && gw_fit_linear(xs, ys, nfit, &fit) == GW_OK)
        r->c0_measured = r->a * fit.c0;
}

/* Integrate and sample into in[nx][nt]. */
static int disp_integrate(const gw_chain_disp_params *p, const gw_solver_type *type,
                          const gw_solver_params *sp0, double *in, gw_chain_disp_result *r,
                          gw_err *err)
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
        rc = gw_err_set(err, GW_EUNSUPPORTED, "dispersion --method: %s needs --ends fixed (the periodic Jacobian is not banded)",
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
    memset(r, 0, sizeof *r);
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
    r->dt_sample = disp_dt_sample(p);
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
    fftw_plan plan = fftw_plan_dft_r2c_2d(nx, nt, in, out, p->fftw_measure ? FFTW_MEASURE : FFTW_ESTIMATE);
    if (!plan)
        rc = gw_err_set(err, GW_ENOMEM, "dispersion: FFTW could not plan a %d x %d transform", nx, nt);
    double plan_ms = gw_clock_ms() - t0;
    if (rc == GW_OK) {
        t0 = gw_clock_ms();
        rc = disp_integrate(p, solver ? solver : gw_solver_rk4, sp, in, r, err);
        r->integrate_ms = gw_clock_ms() - t0;
    }
    if (rc == GW_OK) {
        t0 = gw_clock_ms();
        fftw_execute(plan);
        disp_analyse(p, out, nx, r);
        r->fft_ms = gw_clock_ms() - t0 + plan_ms;
    }
    if (plan)
        fftw_destroy_plan(plan);
    fftw_free(in);
    fftw_free(out);
    return rc;
}

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
    memset(sp, 0, sizeof *sp);
    if (!tr || tr->len < 2 || !(t1 > t0) || !isfinite(t1) || t0 < tr->t[0] || t1 > tr->t[tr->len - 1])
        return gw_err_set(err, GW_EINVAL, "wall spectrum: interval [%g, %g] s not inside the trace", t0, t1);
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
    else if (!(plan = fftw_plan_dft_r2c_1d(M, in, out, fftw_measure ? FFTW_MEASURE : FFTW_ESTIMATE)))
        rc = gw_err_set(err, GW_ENOMEM, "wall spectrum: FFTW could not plan %d points", M);
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
        sp->f_peak = lm > 0 ? (lm + log_parabola((lm - 1.0) * (lm - 1.0) * sp->power[lm - 1],
                                                 (double)lm * lm * sp->power[lm],
                                                 (lm + 1.0) * (lm + 1.0) * sp->power[lm + 1])) * sp->df
                            : NAN;
    }
    if (plan)
        fftw_destroy_plan(plan);
    fftw_free(in);
    fftw_free(out);
    if (rc != GW_OK)
        gw_chain_spectrum_free(sp);
    return rc;
}

/* ---- `granwave dispersion` ---- */

static const char *disp_summary =
    "Small-amplitude dispersion of a Hertz chain under static precompression F0\n"
    "(physics.md 1.6): random small velocities, velocities sampled in time, space-time\n"
    "power spectrum (FFTW r2c, Hann window in time), ridge omega(q) against\n"
    "omega = 2 sqrt(kappa/m) |sin(qa/2)|, kappa = (3/2) k^(2/3) F0^(1/3). Steel beads\n"
    "(R = 4 mm). Wavenumbers in lattice units qa. --column-n N instead runs one column\n"
    "collision (granwave chain) and reports the wall-force spectrum peak against 1/P.";

typedef struct disp_cli {
    long n, t_samples, steps, seed, column_n;
    double f0, dt_out, amp, min_bins, rtol, atol, vimp;
    int measure, json;
    const char *ends, *solver, *method, *out, *wisdom;
} disp_cli;

enum { DISP_NOPTS = 20 };

#define DOPT_L(nm, dst, mv, hl, lo_, hi_)                                                 \
    (gw_opt) { .name = nm, .kind = GW_OPT_LONG, .dest = dst, .metavar = mv, .help = hl, \
               .lo = lo_, .hi = hi_ }
#define DOPT_D(nm, dst, mv, hl, lo_, hi_, open_)                                           \
    (gw_opt) { .name = nm, .kind = GW_OPT_DOUBLE, .dest = dst, .metavar = mv, .help = hl, \
               .lo = lo_, .hi = hi_, .open_lo = open_ }
#define DOPT_S(nm, dst, mv, hl) \
    (gw_opt) { .name = nm, .kind = GW_OPT_STRING, .dest = dst, .metavar = mv, .help = hl }

static void disp_options(disp_cli *c, gw_opt *o)
{
    gw_chain_disp_params d = gw_chain_disp_params_default();
    memset(c, 0, sizeof *c);
    c->n = d.n;
    c->f0 = d.f0;
    c->t_samples = d.t_samples;
    c->steps = d.steps_per_sample;
    c->amp = d.amp;
    c->seed = (long)d.seed;
    c->min_bins = d.min_bins;
    c->rtol = c->atol = 1e-10;
    c->vimp = 0.3;
    c->ends = "periodic";
    c->solver = "rk4";
    c->method = "default";
    int i = 0;
    o[i++] = DOPT_L("n", &c->n, "N", "number of beads [1024]", 8, 1 << 22);
    o[i++] = DOPT_D("f0", &c->f0, "F", "static precompression, N [10]", 0, 1e9, 1);
    o[i++] = DOPT_S("ends", &c->ends, "KIND", "periodic or fixed [periodic]");
    o[i++] = DOPT_L("t-samples", &c->t_samples, "T", "velocity samples in time, even [2048]", 64, 1 << 24);
    o[i++] = DOPT_D("dt-out", &c->dt_out, "DT", "sampling interval, s [pi / (1.25 omega_c)]", 0, 1, 0);
    o[i++] = DOPT_L("steps-per-sample", &c->steps, "K", "RK4 steps per sampling interval [16]", 1, 100000);
    o[i++] = DOPT_D("amp", &c->amp, "A", "rms overlap perturbation / d0 of the initial velocities [1e-3]", 0, 0.1, 1);
    o[i++] = DOPT_L("seed", &c->seed, "S", "seed of the random velocities [1]", 0, 9.0e18);
    o[i++] = DOPT_D("min-bins", &c->min_bins, "B", "ridge resolved from B frequency bins up [8]", 1, 1e9, 0);
    o[i++] = DOPT_S("solver", &c->solver, "NAME", "rk4, cvode or arkode [rk4]");
    o[i++] = DOPT_S("method", &c->method, "NAME", "cvode: adams|bdf; arkode: erk|dirk (bdf, dirk: fixed ends) [adams / erk]");
    o[i++] = DOPT_D("rtol", &c->rtol, "R", "relative tolerance, cvode/arkode [1e-10]", 0, 1, 1);
    o[i++] = DOPT_D("atol", &c->atol, "A", "absolute tolerance in units of the perturbation scales [1e-10]", 0, INFINITY, 1);
    o[i++] = (gw_opt){.name = "fftw-measure", .kind = GW_OPT_FLAG, .dest = &c->measure,
                      .help = "plan the FFTs with FFTW_MEASURE (default FFTW_ESTIMATE)"};
    o[i++] = DOPT_S("wisdom", &c->wisdom, "FILE", "import FFTW wisdom from FILE if present, export it after the run");
    o[i++] = DOPT_L("column-n", &c->column_n, "N", "instead: wall-force spectrum of an N-bead column collision", 1, 100000);
    o[i++] = DOPT_D("vimp", &c->vimp, "V", "impact velocity of that column, m/s [0.3]", 0, 1e3, 1);
    o[i++] = (gw_opt){.name = "json", .kind = GW_OPT_FLAG, .dest = &c->json, .help = "print results as one JSON object on stdout"};
    o[i++] = DOPT_S("out", &c->out, "DIR", "write CSV files (and the JSON) into DIR");
    o[i++] = (gw_opt){0};
}

/* Solver and method from the options; GW_EINVAL with a message naming them. */
static int disp_solver(const disp_cli *c, const gw_solver_type **type, gw_solver_params *sp,
                       gw_err *err)
{
    *type = gw_solver_type_find(c->solver);
    if (!*type)
        return gw_err_set(err, GW_EINVAL, "dispersion --solver: unknown solver '%s' (rk4, cvode, arkode)", c->solver);
    int m = gw_solver_method_find(c->method);
    int ok = m == GW_METHOD_DEFAULT ||
             (*type == gw_solver_cvode && (m == GW_CVODE_ADAMS || m == GW_CVODE_BDF)) ||
             (*type == gw_solver_arkode && (m == GW_ARKODE_ERK || m == GW_ARKODE_DIRK));
    if (!ok)
        return gw_err_set(err, GW_EINVAL, "dispersion --method: '%s' is not a method of solver %s (cvode: adams, bdf; arkode: erk, dirk; rk4: none)",
                          c->method, c->solver);
    *sp = gw_solver_params_default();
    sp->method = m;
    sp->rtol = c->rtol;
    sp->atol = c->atol;
    return GW_OK;
}

static cJSON *disp_settings_json(const disp_cli *c, const gw_chain_disp_params *p,
                                 const gw_solver_params *sp)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "version", gw_version());
    cJSON *m = cJSON_AddObjectToObject(o, "model");
    cJSON_AddNumberToObject(m, "n", p->n);
    cJSON_AddNumberToObject(m, "f0", p->f0);
    cJSON_AddStringToObject(m, "ends", c->ends);
    cJSON_AddNumberToObject(m, "mass", p->mass);
    cJSON_AddNumberToObject(m, "k", p->k);
    cJSON_AddNumberToObject(m, "radius", p->radius);
    cJSON_AddNumberToObject(m, "amp", p->amp);
    cJSON_AddNumberToObject(m, "seed", (double)p->seed);
    cJSON *s = cJSON_AddObjectToObject(o, "solver");
    cJSON_AddStringToObject(s, "name", c->solver);
    cJSON_AddStringToObject(s, "method", c->method);
    cJSON_AddNumberToObject(s, "rtol", sp->rtol);
    cJSON_AddNumberToObject(s, "atol", sp->atol);
    cJSON_AddNumberToObject(s, "steps_per_sample", p->steps_per_sample);
    cJSON *f = cJSON_AddObjectToObject(o, "spectrum");
    cJSON_AddNumberToObject(f, "t_samples", p->t_samples);
    cJSON_AddNumberToObject(f, "dt_out", disp_dt_sample(p));
    cJSON_AddStringToObject(f, "window", "hann (time)");
    cJSON_AddStringToObject(f, "fftw_planner", p->fftw_measure ? "measure" : "estimate");
    cJSON_AddNumberToObject(f, "min_bins", p->min_bins);
    return o;
}

/* "granwave VERSION\ncommand: ...\nsettings: {...}"; caller frees (NULL: ENOMEM). */
static char *disp_header(const cJSON *settings, int argc, char **argv)
{
    char *js = cJSON_PrintUnformatted(settings);
    size_t len = 256 + (js ? strlen(js) : 0);
    for (int i = 0; i < argc; i++)
        len += strlen(argv[i]) + 1;
    char *h = malloc(len);
    if (h) {
        size_t w = (size_t)snprintf(h, len, "granwave %s\ncommand: granwave dispersion", gw_version());
        for (int i = 0; i < argc && w < len; i++)
            w += (size_t)snprintf(h + w, len - w, " %s", argv[i]);
        if (w < len)
            snprintf(h + w, len - w, "\nsettings: %s", js ? js : "{}");
    }
    free(js);
    return h;
}

static void write_comment(FILE *fp, const char *text)
{
    for (const char *p = text; p && *p;) {
        const char *nl = strchr(p, '\n');
        int len = nl ? (int)(nl - p) : (int)strlen(p);
        fprintf(fp, "# %.*s\n", len, p);
        p += len + (nl != NULL);
    }
}

/* DIR/name through an atomic file: header, then body(ctx). */
static int write_csv(const char *dir, const char *name, const char *hdr,
                     void (*body)(FILE *, const void *), const void *ctx, gw_err *err)
{
    char path[4096];
    gw_afile f;
    if (gw_path_join(path, sizeof path, dir, name) != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s/%s: path too long", dir, name);
    int rc = gw_afile_open(&f, path, err);
    if (rc != GW_OK)
        return rc;
    write_comment(f.fp, hdr);
    body(f.fp, ctx);
    return gw_afile_commit(&f, err);
}

static void ridge_body(FILE *fp, const void *ctx)
{
    const gw_chain_disp_result *r = ctx;
    fprintf(fp, "j,qa_rad,omega_ridge_rad_s,omega_theory_rad_s,rel_err,resolved,ridge_power\n");
    for (int k = 0; k < r->nq; k++)
        fprintf(fp, "%d,%.10g,%.10g,%.10g,%.6g,%d,%.6g\n", k + 1, r->qa[k], r->omega_ridge[k],
                r->omega_theory[k], fabs(r->omega_ridge[k] / r->omega_theory[k] - 1), r->resolved[k],
                r->ridge_power[k]);
}

/* The power spectrum reduced to at most 128 x 256 blocks (max over a block keeps
 * the ridge visible), long format. */
static void power_body(FILE *fp, const void *ctx)
{
    const gw_chain_disp_result *r = ctx;
    const int gq = (r->nq + 127) / 128, gw = (r->n_omega + 255) / 256;
    const int rows = (r->nq + gq - 1) / gq, cols = (r->n_omega + gw - 1) / gw;
    fprintf(fp, "# grid: %d qa rows x %d omega columns, each the max over %d x %d bins\n", rows, cols, gq, gw);
    fprintf(fp, "qa_rad,omega_rad_s,power\n");
    for (int bq = 0; bq < rows; bq++)
        for (int bw = 0; bw < cols; bw++) {
            double pmax = 0, qs = 0, ws = 0;
            int cq = 0, cw = 0;
            for (int j = bq * gq; j < r->nq && j < (bq + 1) * gq; j++, cq++) {
                qs += r->qa[j];
                for (int l = bw * gw; l < r->n_omega && l < (bw + 1) * gw; l++)
                    pmax = fmax(pmax, r->power[(size_t)j * (size_t)r->n_omega + (size_t)l]);
            }
            for (int l = bw * gw; l < r->n_omega && l < (bw + 1) * gw; l++, cw++)
                ws += l * r->d_omega;
            fprintf(fp, "%.8g,%.8g,%.6g\n", qs / cq, ws / cw, pmax);
        }
}

static cJSON *disp_json(const gw_chain_disp_params *p, const gw_chain_disp_result *r,
                        cJSON *settings, double wall_ms)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "version", gw_version());
    cJSON_AddNumberToObject(o, "n", p->n);
    cJSON_AddNumberToObject(o, "f0", p->f0);
    cJSON_AddStringToObject(o, "ends", p->ends == GW_CHAIN_DISP_FIXED ? "fixed" : "periodic");
    cJSON_AddNumberToObject(o, "d0", r->d0);
    cJSON_AddNumberToObject(o, "kappa", r->kappa);
    cJSON_AddNumberToObject(o, "a", r->a);
    cJSON_AddNumberToObject(o, "omega_c_theory", r->omega_c_theory);
    cJSON_AddNumberToObject(o, "omega_c_measured", r->omega_c_measured);
    cJSON_AddNumberToObject(o, "omega_c_rel_err", r->omega_c_rel_err);
    cJSON_AddNumberToObject(o, "omega_edge", r->omega_edge);
    cJSON_AddNumberToObject(o, "ridge_max_rel_err", r->ridge_max_rel_err);
    cJSON_AddNumberToObject(o, "n_resolved", r->n_resolved);
    cJSON_AddNumberToObject(o, "qa_resolved_min", r->qa_resolved_min);
    cJSON_AddNumberToObject(o, "qa_resolved_max", r->qa_resolved_max);
    cJSON_AddNumberToObject(o, "c0", r->c0_theory);
    cJSON_AddNumberToObject(o, "c0_measured", r->c0_measured);
    cJSON_AddNumberToObject(o, "c0_rel_err", fabs(r->c0_measured / r->c0_theory - 1));
    cJSON_AddNumberToObject(o, "max_overlap_dev", r->max_overlap_dev);
    cJSON_AddNumberToObject(o, "d_omega", r->d_omega);
    cJSON_AddNumberToObject(o, "dt_out", r->dt_sample);
    cJSON_AddNumberToObject(o, "dt_step", r->dt_step);
    cJSON_AddNumberToObject(o, "t_total", r->t_total);
    cJSON_AddStringToObject(o, "q_units", "qa, rad per bead");
    cJSON_AddItemToObject(o, "q", gw_json_doubles(r->qa, r->nq));
    cJSON_AddItemToObject(o, "omega_ridge", gw_json_doubles(r->omega_ridge, r->nq));
    cJSON_AddItemToObject(o, "omega_theory", gw_json_doubles(r->omega_theory, r->nq));
    cJSON_AddItemToObject(o, "resolved", gw_json_ints(r->resolved, r->nq));
    cJSON_AddNumberToObject(o, "steps", (double)r->stats.steps);
    cJSON_AddNumberToObject(o, "rhs_evals", (double)r->stats.rhs_evals);
    cJSON_AddNumberToObject(o, "integrate_ms", r->integrate_ms);
    cJSON_AddNumberToObject(o, "fft_ms", r->fft_ms);
    cJSON_AddNumberToObject(o, "wall_time_ms", wall_ms);
    cJSON_AddItemToObject(o, "settings", cJSON_Duplicate(settings, 1));
    return o;
}

static void disp_print(const disp_cli *c, const gw_chain_disp_result *r, double wall_ms)
{
    printf("granwave %s dispersion: n = %ld beads, F0 = %g N, %s ends, solver %s\n", gw_version(),
           c->n, c->f0, c->ends, c->solver);
    printf("  d0 = %.6g m, kappa = %.6g N/m, a = %.6g m\n", r->d0, r->kappa, r->a);
    printf("  omega_c   theory %.6g rad/s, ridge max %.6g (rel err %.2e), edge %.6g\n",
           r->omega_c_theory, r->omega_c_measured, r->omega_c_rel_err, r->omega_edge);
    printf("  ridge     max rel err %.2e over qa in [%.4g, %.4g] (%d of %d resolved)\n",
           r->ridge_max_rel_err, r->qa_resolved_min, r->qa_resolved_max, r->n_resolved, r->nq);
    printf("  c0        theory %.6g m/s, long-wave fit %.6g m/s\n", r->c0_theory, r->c0_measured);
    printf("  linearity max |d - d0| / d0 = %.3g\n", r->max_overlap_dev);
    printf("  run       %.0f ms (integration %.0f ms, %ld steps; FFT %.0f ms)\n", wall_ms,
           r->integrate_ms, r->stats.steps, r->fft_ms);
}

static int disp_write_out(const char *dir, const char *hdr, const cJSON *o,
                          const gw_chain_disp_result *r, gw_err *err)
{
    char path[4096];
    int rc = gw_mkdir_p(dir, err);
    if (rc == GW_OK)
        rc = write_csv(dir, "dispersion_ridge.csv", hdr, ridge_body, r, err);
    if (rc == GW_OK)
        rc = write_csv(dir, "dispersion_power.csv", hdr, power_body, r, err);
    if (rc == GW_OK && gw_path_join(path, sizeof path, dir, "dispersion.json") != GW_OK)
        rc = gw_err_set(err, GW_EINVAL, "%s: path too long", dir);
    if (rc == GW_OK)
        rc = gw_json_write(path, o, err);
    return rc;
}

static void spectrum_body(FILE *fp, const void *ctx)
{
    const gw_chain_spectrum *sp = ctx;
    fprintf(fp, "freq_hz,power_n2s2\n");
    for (int l = 0; l < sp->len && sp->freq[l] <= 8 * sp->f_peak; l++)
        fprintf(fp, "%.8g,%.6g\n", sp->freq[l], sp->power[l]);
}

/* --column-n: one column collision, then the wall-force spectrum over the
 * contact [0, tau_N] against 1/P from the maxima of the wall force. */
static int disp_column(const disp_cli *c, const gw_opt *opts, int argc, char **argv)
{
    gw_err err = {{0}};
    gw_chain_params p = gw_chain_params_default();
    p.n = (int)c->column_n;
    p.v_imp = c->vimp;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    const gw_solver_type *type;
    if (disp_solver(c, &type, &o.sp, &err) != GW_OK)
        return chain_cli_fail(err.msg);
    if (gw_cli_find(opts, "solver")->seen)
        o.solver = type;
    else
        o.sp.method = GW_METHOD_DEFAULT;
    /* Tolerances of `granwave chain` unless given. */
    o.sp.rtol = gw_cli_find(opts, "rtol")->seen ? c->rtol : 1e-12;
    o.sp.atol = gw_cli_find(opts, "atol")->seen ? c->atol : 1e-12;
    o.dt_out = gw_chain_tau1(p.mass, p.kwall, p.v_imp) / 200;
    gw_chain *ch = NULL;
    gw_chain_trace tr;
    gw_chain_trace_init(&tr, p.n);
    o.sample = gw_chain_trace_sample;
    o.sample_ctx = &tr;
    gw_chain_result r;
    memset(&r, 0, sizeof r);
    gw_chain_spectrum sp;
    memset(&sp, 0, sizeof sp);
    int rc = gw_chain_create(&p, &ch, &err), code = 0;
    if (rc == GW_OK)
        rc = gw_chain_collide(ch, &o, &r, &err);
    if (rc == GW_OK)
        rc = gw_chain_wall_spectrum(&tr, 0.0, r.tau_n, o.dt_out, 0.0, c->measure, &sp, &err);
    if (rc != GW_OK) {
        fprintf(stderr, "granwave dispersion --column-n: %s\n", err.msg);
        code = rc == GW_EINVAL ? 2 : 1;
    } else {
        cJSON *js = cJSON_CreateObject();
        cJSON_AddStringToObject(js, "version", gw_version());
        cJSON_AddStringToObject(js, "mode", "column_wall_spectrum");
        cJSON_AddNumberToObject(js, "column_n", p.n);
        cJSON_AddNumberToObject(js, "v_imp", p.v_imp);
        cJSON_AddStringToObject(js, "solver", gw_solver_type_name(o.solver));
        cJSON_AddNumberToObject(js, "tau_n", r.tau_n);
        cJSON_AddNumberToObject(js, "period", r.period);
        cJSON_AddNumberToObject(js, "inv_period", 1.0 / r.period);
        cJSON_AddNumberToObject(js, "f_peak", sp.f_peak);
        cJSON_AddNumberToObject(js, "f_peak_rel_diff", sp.f_peak * r.period - 1);
        cJSON_AddNumberToObject(js, "df", sp.df);
        cJSON_AddNumberToObject(js, "f_min", sp.f_min);
        cJSON_AddNumberToObject(js, "samples", sp.samples);
        cJSON_AddNumberToObject(js, "n_maxima", r.n_maxima);
        cJSON_AddStringToObject(js, "fftw_planner", c->measure ? "measure" : "estimate");
        char *hdr = disp_header(js, argc, argv);
        if (c->out && (gw_mkdir_p(c->out, &err) != GW_OK ||
                       write_csv(c->out, "wall_spectrum.csv", hdr ? hdr : "", spectrum_body, &sp, &err) != GW_OK)) {
            fprintf(stderr, "granwave dispersion --out: %s\n", err.msg);
            code = 1;
        }
        if (code == 0 && c->json)
            gw_json_print(js, stdout);
        else if (code == 0)
            printf("granwave %s dispersion --column-n %d (v_imp %g m/s): wall-force peak %.6g Hz, "
                   "1/P %.6g Hz (rel diff %+.2e), bin %.3g Hz, contact %.4g us\n",
                   gw_version(), p.n, p.v_imp, sp.f_peak, 1.0 / r.period, sp.f_peak * r.period - 1,
                   sp.df, r.tau_n * 1e6);
        free(hdr);
        cJSON_Delete(js);
    }
    gw_chain_spectrum_free(&sp);
    gw_chain_result_free(&r);
    gw_chain_trace_free(&tr);
    gw_chain_free(ch);
    return code;
}

static void disp_export_wisdom(const char *path)
{
    gw_afile f;
    gw_err err = {{0}};
    if (gw_afile_open(&f, path, &err) != GW_OK) {
        fprintf(stderr, "granwave dispersion --wisdom: %s (not saved)\n", err.msg);
        return;
    }
    fftw_export_wisdom_to_file(f.fp);
    if (gw_afile_commit(&f, &err) != GW_OK)
        fprintf(stderr, "granwave dispersion --wisdom: %s (not saved)\n", err.msg);
}

int gw_cmd_dispersion(int argc, char **argv)
{
    disp_cli c;
    gw_opt opts[DISP_NOPTS];
    disp_options(&c, opts);
    gw_err err = {{0}};
    int help = 0, npos = 0;
    const char *pos[1];
    if (gw_cli_parse("dispersion", opts, argc, argv, &help, pos, 0, &npos, &err) != GW_OK)
        return chain_cli_fail(err.msg);
    if (help) {
        gw_cli_help(stdout, "dispersion", "granwave dispersion [options]", disp_summary, opts);
        return 0;
    }
    if (c.wisdom)
        fftw_import_wisdom_from_filename(c.wisdom); /* absent file: plan afresh */
    if (c.column_n > 0) {
        int code = disp_column(&c, opts, argc, argv);
        if (c.wisdom && code == 0)
            disp_export_wisdom(c.wisdom);
        return code;
    }
    gw_chain_disp_params p = gw_chain_disp_params_default();
    p.n = (int)c.n;
    p.f0 = c.f0;
    if (strcmp(c.ends, "periodic") == 0)
        p.ends = GW_CHAIN_DISP_PERIODIC;
    else if (strcmp(c.ends, "fixed") == 0)
        p.ends = GW_CHAIN_DISP_FIXED;
    else
        return chain_cli_fail("dispersion --ends: expected periodic or fixed");
    p.t_samples = (int)c.t_samples;
    p.dt_sample = c.dt_out;
    p.steps_per_sample = (int)c.steps;
    p.amp = c.amp;
    p.seed = (unsigned long)c.seed;
    p.min_bins = c.min_bins;
    p.fftw_measure = c.measure;
    const gw_solver_type *type;
    gw_solver_params sp;
    if (disp_solver(&c, &type, &sp, &err) != GW_OK)
        return chain_cli_fail(err.msg);
    char msg[sizeof err.msg + 32];
    if (gw_chain_disp_params_validate(&p, &err) != GW_OK) {
        snprintf(msg, sizeof msg, "dispersion %s", err.msg);
        return chain_cli_fail(msg);
    }
    gw_chain_disp_result r;
    double t0 = gw_clock_ms();
    int rc = gw_chain_disp_run(&p, type, &sp, &r, &err);
    double wall_ms = gw_clock_ms() - t0;
    int code = 0;
    if (rc != GW_OK) {
        fprintf(stderr, "granwave %s\n", err.msg);
        code = rc == GW_EINVAL || rc == GW_EUNSUPPORTED ? 2 : 1;
    } else {
        cJSON *settings = disp_settings_json(&c, &p, &sp);
        cJSON *o = disp_json(&p, &r, settings, wall_ms);
        char *hdr = disp_header(settings, argc, argv);
        if (c.out && disp_write_out(c.out, hdr ? hdr : "", o, &r, &err) != GW_OK) {
            fprintf(stderr, "granwave dispersion --out: %s\n", err.msg);
            code = 1;
        }
        if (code == 0 && c.json)
            gw_json_print(o, stdout);
        else if (code == 0)
            disp_print(&c, &r, wall_ms);
        free(hdr);
        cJSON_Delete(o);
        cJSON_Delete(settings);
    }
    if (c.wisdom && code == 0)
        disp_export_wisdom(c.wisdom);
    gw_chain_disp_result_free(&r);
    return code;
}
