/*
 * chain_disp_study.c: the dispersion study of `granwave dispersion` as a library
 * call (gw_chain_study.h). Equations (docs/physics.md 1.6, chain_dispersion.c):
 * a chain precompressed by f0 (N) has overlap d0 = (f0/k)^(2/3) (m), linear
 * stiffness kappa = (3/2) k^(2/3) f0^(1/3) (N/m) and, for small vibrations,
 *     omega(q) = 2 sqrt(kappa/m) |sin(qa/2)|,  a = 2R - d0,  c0 = a sqrt(kappa/m);
 * the ridge of the space-time power spectrum of the bead velocities is measured
 * against it. With column_n > 0 instead: one column collision (physics.md 1.1)
 * and the peak of its wall-force spectrum (Hz) against 1/P, P the mean spacing
 * of the wall-force maxima (chain_spectrum.c). SI units (rad/s, Hz).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_model.h"
#include "chain_setup_rows.h"
#include "gw_locale.h"

#define OFF(f) offsetof(gw_chain_dispersion_setup, f)

/* The rows of one mode only (all but the solver rows and fftw-measure) are
 * optional: not given until set, so that one given at its default's value in
 * the other mode is refused as having no effect (disp_unused_check), as any
 * other value is; a run uses their defaults (gw_param_resolve). */
#define OROW(nm, ty, f, un, lo, hi, op, df, mv, hl) GW_PARAM_OPT_ROW(nm, ty, OFF(f), un, lo, hi, op, 0, df, mv, hl)
#define OCHOICE(nm, f, ch, df, mv, hl) GW_PARAM_OPT_CHOICE_ROW(nm, OFF(f), ch, df, mv, hl)

static const gw_param disp_params[] = {
    OROW("n", GW_PARAM_LONG, n, "", 8, 1 << 22, 0, "1024", "N", "number of beads [1024]"),
    OROW("f0", GW_PARAM_DOUBLE, f0, "N", 0, 1e9, 1, "10", "F", "static precompression, N [10]"),
    OCHOICE("ends", ends, "periodic,fixed", "periodic", "KIND", "periodic or fixed [periodic]"),
    OROW("t-samples", GW_PARAM_LONG, t_samples, "", 64, 1 << 24, 0, "2048", "T",
        "velocity samples in time, even [2048]"),
    OROW("dt-out", GW_PARAM_DOUBLE, dt_out, "s", 0, 1, 0, "0", "DT", "sampling interval, s, in [0, 1] [0 = pi / (1.25 omega_c)]"),
    OROW("steps-per-sample", GW_PARAM_LONG, steps_per_sample, "", 1, 100000, 0, "16", "K",
        "RK4 steps per sampling interval (rk4 only) [16]"),
    OROW("amp", GW_PARAM_DOUBLE, amp, "", GW_CHAIN_DISP_AMP_MIN, 0.1, 0, "1e-3", "A",
        "rms overlap perturbation / d0 of the initial velocities, in [1e-12, 0.1] (smaller nears the rounding "
        "of d0) [1e-3]"),
    OROW("seed", GW_PARAM_LONG, seed, "", 0, 9.0e18, 0, "1", "S",
        "seed of the random mode phases of the initial velocities [1]"),
    OROW("min-bins", GW_PARAM_COUNT, min_bins, "", 1, GW_CHAIN_DISP_MIN_BINS_MAX, 0, "8", "B",
        "ridge resolved from B frequency bins up, B <= T/2 - 2 [8]"),
    CHOICE("solver", solver, "rk4,cvode,arkode", NULL, "NAME", "rk4, cvode or arkode [rk4; column-n: cvode]"),
    CHOICE("method", method, "default,adams,bdf,erk,dirk", NULL, "NAME",
           "cvode: adams|bdf; arkode: erk|dirk (bdf, dirk: fixed ends) [adams / erk; column-n: bdf / erk]"),
    ROW("rtol", GW_PARAM_DOUBLE, rtol, "", GW_TOL_MIN, GW_TOL_MAX, 0, NULL, "R", "relative tolerance, cvode/arkode [1e-10]"),
    ROW("atol", GW_PARAM_DOUBLE, atol, "", GW_TOL_MIN, GW_TOL_MAX, 0, NULL, "A",
        "absolute tolerance in units of the perturbation scales [1e-10]"),
    ROW("fftw-measure", GW_PARAM_FLAG, fftw_measure, "", 0, 1, 0, "0", NULL,
        "plan the FFTs with FFTW_MEASURE (default FFTW_ESTIMATE)"),
    OROW("column-n", GW_PARAM_LONG, column_n, "", 1, 100000, 0, NULL, "N",
        "instead: wall-force spectrum of an N-bead column collision [not given: off]"),
    OROW("vimp", GW_PARAM_DOUBLE, vimp, "m/s", GW_CHAIN_VIMP_MIN, GW_CHAIN_VIMP_MAX, 0, "0.3", "V",
        "impact velocity of that column, m/s [0.3]"),
    GW_PARAM_END};
#undef OROW
#undef OCHOICE
#undef OFF

#define OFF(f) offsetof(gw_chain_dispersion_outcome, f)

static const gw_param disp_fields[] = {
    RF("column", column, "0: dispersion, 1: column wall-force spectrum (column_n)"),
    RI("nq", r.nq, "wavenumbers qa = 2 pi j / n (periodic) or pi j / (n + 1) (fixed), j = 1..nq"),
    RI("n_omega", r.n_omega, "frequency bins"),
    RA("q", r.qa, "rad", "nq", NULL, "qa, rad per bead"),
    RA("omega_ridge", r.omega_ridge, "rad/s", "nq", NULL, "frequency of maximum power"),
    RA("omega_theory", r.omega_theory, "rad/s", "nq", NULL, "2 sqrt(kappa/m) |sin(qa/2)| (1.6)"),
    RA("ridge_power", r.ridge_power, "m^2/s^2", "nq", NULL, "power at the ridge"),
    {.name = "resolved", .type = GW_PARAM_FARRAY, .offset = OFF(r.resolved), .unit = "", .rows = "nq",
     .help = "1: the ridge counts (min-bins)"},
    RA("power", r.power, "m^2/s^2", "nq", "n_omega", "|V(q, omega)|^2 [q, omega bin]"),
    RD("d_omega", r.d_omega, "rad/s", "bin spacing"),
    RD("d0", r.d0, "m", "static overlap (f0/k)^(2/3)"),
    RD("kappa", r.kappa, "N/m", "linear contact stiffness"),
    RD("a", r.a, "m", "lattice spacing 2R - d0"),
    RD("omega_c_theory", r.omega_c_theory, "rad/s", "cutoff 2 sqrt(kappa/m)"),
    RD("omega_c_measured", r.omega_c_measured, "rad/s", "highest resolved ridge"),
    RD("omega_c_rel_err", r.omega_c_rel_err, "", "its relative error against omega(qa) at its own qa"),
    RD("omega_edge", r.omega_edge, "rad/s", "edge of the q-summed power (1e-3 of its peak)"),
    RD("ridge_max_rel_err", r.ridge_max_rel_err, "", "max |ridge - theory| / theory over resolved q"),
    RI("n_resolved", r.n_resolved, "resolved wavenumbers"),
    RD("qa_resolved_min", r.qa_resolved_min, "rad", "smallest resolved qa"),
    RD("qa_resolved_max", r.qa_resolved_max, "rad", "largest resolved qa"),
    RD("c0", r.c0_theory, "m/s", "long-wave speed a sqrt(kappa/m)"),
    RD("c0_measured", r.c0_measured, "m/s", "long-wave fit"),
    RD("c0_rel_err", c0_rel_err, "", "|c0_measured / c0 - 1|"),
    RD("max_overlap_dev", r.max_overlap_dev, "", "max |d - d0| / d0 (linearity)"),
    RD("dt_step", r.dt_step, "s", "RK4 step"),
    RD("t_total", r.t_total, "s", "time sampled"),
    RL("steps", r.stats.steps, "solver steps"),
    RL("rhs_evals", r.stats.rhs_evals, "right-hand side evaluations"),
    RD("integrate_ms", r.integrate_ms, "ms", "integration time"),
    RD("fft_ms", r.fft_ms, "ms", "transform time"),
    RD("mass", mass, "kg", "bead mass"),
    RD("k", k, "N/m^1.5", "bead-bead Hertz coefficient"),
    RD("kwall", kwall, "N/m^1.5", "column mode: wall coefficient"),
    RD("radius", radius, "m", "bead radius"),
    RD("wall_time_ms", wall_time_ms, "ms", "wall-clock time"),
    RI("column_n", column_n, "column mode: beads"),
    RD("v_imp", v_imp, "m/s", "column mode: impact velocity"),
    RD("tau_n", tau_n, "s", "column mode: contact time"),
    RD("period", period, "s", "column mode: mean spacing of wall-force maxima P"),
    RI("n_maxima", n_maxima, "column mode: wall-force maxima"),
    RD("dt_out", dt_out, "s", "sampling interval (dispersion) or trace sampling (column)"),
    RD("rtol", rtol, "", "relative tolerance used"),
    RD("atol", atol, "", "absolute tolerance used"),
    RI("len", sp.len, "column mode: spectrum bins"),
    RA("freq", sp.freq, "Hz", "len", NULL, "column mode: frequencies"),
    RA("spectrum", sp.power, "N^2 s^2", "len", NULL, "column mode: wall-force power"),
    RD("f_peak", sp.f_peak, "Hz", "column mode: spectrum peak (against 1/P)"),
    RD("inv_period", inv_period, "Hz", "column mode: 1/P (NaN: fewer than two maxima)"),
    RD("f_peak_rel_diff", f_peak_rel_diff, "", "column mode: f_peak P - 1"),
    RD("df", sp.df, "Hz", "column mode: bin spacing"),
    RD("f_min", sp.f_min, "Hz", "column mode: lowest frequency searched"),
    RI("samples", sp.samples, "column mode: uniform samples"),
    GW_PARAM_WARNINGS(OFF(warnings)),
    GW_PARAM_END};

const gw_param *gw_chain_dispersion_setup_params(void) { return disp_params; }
const gw_param *gw_chain_dispersion_outcome_fields(void) { return disp_fields; }

int gw_chain_dispersion_setup_init(gw_chain_dispersion_setup *s)
{
    if (!s)
        return GW_EINVAL;
    memset(s, 0, sizeof *s);
    return gw_param_init(disp_params, s, NULL);
}

void gw_chain_dispersion_setup_clear(gw_chain_dispersion_setup *s)
{
    gw_param_clear(disp_params, s);
}

void gw_chain_dispersion_outcome_free(gw_chain_dispersion_outcome *out)
{
    if (!out)
        return;
    gw_chain_disp_result_free(&out->r);
    gw_chain_spectrum_free(&out->sp);
    free(out->warnings);
    memset(out, 0, sizeof *out);
}

static const char *choice(const gw_chain_dispersion_setup *s, const char *row, const char *def, char *buf,
                          size_t n)
{
    return gw_param_format(gw_param_find(disp_params, row), s, buf, n) > 0 ? buf : def;
}

int gw_chain_dispersion_solver(const gw_chain_dispersion_setup *s, const gw_solver_type **type,
                               gw_solver_params *sp, gw_err *err)
{
    if (!s || !type || !sp)
        return gw_err_set(err, GW_EINVAL, "gw_chain_dispersion_solver: %s is NULL", !s ? "s" : !type ? "type" : "sp");
    char sname[16], mname[16];
    /* the column (column_n > 0) is `granwave chain`'s collision and takes its
     * default solver, cvode; the method and the tolerances are checked against
     * the solver that runs (they were checked against rk4, and --column-n with
     * --rtol or --method adams was refused as having no effect with rk4) */
    const char *sv = choice(s, "solver", s->column_n > 0 ? "cvode" : "rk4", sname, sizeof sname);
    const char *mv = choice(s, "method", "default", mname, sizeof mname);
    *type = gw_solver_type_find(sv);
    int m = gw_solver_method_find(mv);
    int ok = m == GW_METHOD_DEFAULT || (*type == gw_solver_cvode && (m == GW_CVODE_ADAMS || m == GW_CVODE_BDF)) ||
             (*type == gw_solver_arkode && (m == GW_ARKODE_ERK || m == GW_ARKODE_DIRK));
    if (!*type || !ok)
        return gw_err_set(err, GW_EINVAL, "method: '%s' is not a method of solver %s (cvode: adams, bdf; "
                          "arkode: erk, dirk; rk4: none)", mv, sv);
    int rc = gw_solver_tolerances_unused_check(*type, disp_params, s, err); /* no effect on a fixed step */
    if (rc != GW_OK)
        return rc;
    /* the reverse: RK4's steps per sample have no effect on an adaptive solver,
     * which chooses its own steps from rtol and atol (the column's mode refuses
     * the row before this, as a row of the other mode) */
    if (*type != gw_solver_rk4 && gw_param_given(gw_param_find(disp_params, "steps-per-sample"), s))
        return gw_err_set(err, GW_EINVAL, "steps-per-sample: has no effect with the %s solver (it chooses its "
                          "steps from rtol and atol; steps-per-sample is rk4's)", sv);
    *sp = gw_solver_params_default();
    sp->method = m;
    sp->rtol = isnan(s->rtol) ? 1e-10 : s->rtol;
    sp->atol = isnan(s->atol) ? 1e-10 : s->atol;
    return gw_solver_tolerances_check(sp->rtol, sp->atol, "rtol", "atol", err);
}

/* column_n > 0: one collision, then the wall-force spectrum over [0, tau_N]. */
/* gw_chain_sample_fn keeping t and the wall force (ctx: a gw_chain_trace of
 * n = 0): --column-n stored every bead's x and v as well (a 20000-bead column
 * was refused for 90 GB of bead series no output uses). */
static int wall_sample(void *ctx, double t, const double *y, double f_wall, int is_event)
{
    (void)y;
    (void)is_event;
    gw_chain_trace *tr = ctx;
    if (tr->len == tr->cap) {
        size_t cap = tr->cap ? 2 * tr->cap : 1024;
        double *nt = realloc(tr->t, cap * sizeof *nt);
        if (nt)
            tr->t = nt;
        double *nf = nt ? realloc(tr->f, cap * sizeof *nf) : NULL;
        if (nf)
            tr->f = nf;
        if (!nt || !nf)
            return GW_ENOMEM;
        tr->cap = cap;
    }
    tr->t[tr->len] = t;
    tr->f[tr->len] = f_wall;
    tr->len++;
    return 0;
}

/* Column mode's progress as a gw_progress_fn in output samples of dt_out: k of
 * those over the collision's expected length. A run goes on past it (every
 * contact open and separating comes after bead 1 leaves the wall, 125 % of it
 * at 250 beads): the count then stays one short of the total until the end's
 * report, the total itself (run_column). */
typedef struct column_progress {
    gw_progress_fn fn;
    void *ctx;
    double dt_out;
    long total; /* the expected samples, from the first report */
    int stop;   /* the callback asked to stop: at the collision's end (it is not cut) */
} column_progress;

static void column_report(void *ctx, double t, double t_expect, double t_max)
{
    column_progress *cp = ctx;
    (void)t_max;
    if (!cp->total)
        cp->total = (long)ceil(t_expect / cp->dt_out) + 1;
    long k = (long)floor(t / cp->dt_out);
    if (!cp->stop && cp->fn(cp->ctx, k < cp->total ? k : cp->total - 1, cp->total) != 0)
        cp->stop = 1;
}

/* s: resolved (gw_param_resolve); type, sp: gw_chain_dispersion_solver's */
static int run_column(const gw_chain_dispersion_setup *s, const gw_solver_type *type, const gw_solver_params *sp,
                      gw_progress_fn progress, void *pctx, gw_chain_dispersion_outcome *out, gw_err *err)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = (int)s->column_n;
    p.v_imp = s->vimp;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.sp = *sp;
    o.solver = type; /* cvode unless solver is given, as the chain's default */
    o.sp.rtol = isnan(s->rtol) ? GW_CHAIN_TOL_DEFAULT : s->rtol; /* the tolerances of `granwave chain` */
    o.sp.atol = isnan(s->atol) ? GW_CHAIN_TOL_DEFAULT : s->atol;
    o.dt_out = gw_chain_tau1(p.mass, p.kwall, p.v_imp) / 200;
    gw_chain *ch = NULL;
    gw_chain_trace tr; /* the wall force only: the spectrum needs no bead series */
    gw_chain_trace_init(&tr, 0);
    o.sample = wall_sample;
    o.sample_ctx = &tr;
    gw_chain_result r;
    memset(&r, 0, sizeof r);
    /* the column's work, bounded as chain's (chain_column_work_check) and
     * named as this study's row: the plan's "n" is dispersion's lattice (the
     * bound said "dispersion --n" to --column-n 100000); before the chain is
     * made. Its other refusals that name n name column-n too. */
    gw_chain_params q = p;
    q.v_imp = chain_speed_scale(&p);
    const double t_col = chain_collision_length(&q, NULL);
    int rc = chain_column_work_check(p.n, t_col, t_col, NULL, "column-n", NULL, err);
    if (rc == GW_OK && (rc = gw_chain_run_check(&p, &o, err)) != GW_OK && strncmp(err->msg, "n: ", 3) == 0) {
        char tmp[sizeof err->msg];
        gw_snprintf(tmp, sizeof tmp, "column-n: %s", err->msg + 3);
        gw_err_set(err, rc, "%s", tmp);
    }
    if (rc != GW_OK) {
        gw_chain_trace_free(&tr);
        return rc;
    }
    rc = gw_chain_create(&p, &ch, err);
    column_progress cp = {.fn = progress, .ctx = pctx, .dt_out = o.dt_out};
    if (rc == GW_OK)
        rc = gw_chain_collide_progress(ch, &o, progress ? column_report : NULL, &cp, &r, err);
    if (rc == GW_OK && progress && cp.total > 0 && (cp.stop || progress(pctx, cp.total, cp.total) != 0))
        rc = gw_err_set(err, GW_ECANCELED, "dispersion: stopped by the progress callback at the collision's end, "
                        "t = %.9g s", r.t_end); /* the end's report reaches the total */
    if (rc == GW_OK)
        rc = gw_chain_wall_spectrum(&tr, 0.0, r.tau_n, o.dt_out, 0.0, s->fftw_measure, &out->sp, err);
    out->column = 1;
    out->column_n = p.n;
    out->v_imp = p.v_imp;
    out->mass = p.mass;
    out->k = p.k;
    out->kwall = p.kwall;
    out->radius = p.radius;
    out->dt_out = o.dt_out;
    out->rtol = o.sp.rtol;
    out->atol = o.sp.atol;
    out->solver = type;
    out->solver_params = o.sp;
    out->tau_n = r.tau_n;
    out->period = r.period;
    out->inv_period = 1.0 / r.period;
    out->f_peak_rel_diff = out->sp.f_peak * r.period - 1;
    out->n_maxima = r.n_maxima;
    /* the collision's own warnings, as chain's (a step above dt-max, an
     * overlap beyond the radius, a collision cut at t_max): the column mode
     * had none, and its JSON no "warnings" */
    if (rc == GW_OK && gw_chain_result_warnings(&r, &out->warnings) != GW_OK)
        rc = gw_err_set(err, GW_ENOMEM, "dispersion: out of memory");
    gw_chain_result_free(&r);
    gw_chain_trace_free(&tr);
    gw_chain_free(ch);
    return rc;
}

/* The two modes' own rows: a row of the other mode given (at any value, its
 * default's too) has no effect (the column is the chain command's steel column
 * at vimp; the dispersion study has no impact). */
static int disp_unused_check(const gw_chain_dispersion_setup *s, gw_err *err)
{
    static const char *const chain_rows[] = {"n", "f0", "ends", "t-samples", "dt-out", "steps-per-sample",
                                             "amp", "seed", "min-bins"};
    const int column = gw_param_given(gw_param_find(disp_params, "column-n"), s);
    for (size_t i = 0; column && i < sizeof chain_rows / sizeof chain_rows[0]; i++)
        if (gw_param_given(gw_param_find(disp_params, chain_rows[i]), s))
            return gw_err_set(err, GW_EINVAL, "%s: has no effect with column-n (the column's wall-force spectrum)",
                              chain_rows[i]);
    if (!column && gw_param_given(gw_param_find(disp_params, "vimp"), s))
        return gw_err_set(err, GW_EINVAL, "vimp: has no effect without column-n (the impact speed of that column)");
    return GW_OK;
}

int gw_chain_dispersion_run(const gw_chain_dispersion_setup *s, gw_chain_dispersion_outcome *out, gw_err *err)
{
    return gw_chain_dispersion_run_progress(s, NULL, NULL, out, err);
}

int gw_chain_dispersion_run_progress(const gw_chain_dispersion_setup *s, gw_progress_fn progress, void *pctx,
                                     gw_chain_dispersion_outcome *out, gw_err *err)
{
    if (out) /* emptied on every refusal, a NULL setup's too (docs/library.md) */
        memset(out, 0, sizeof *out);
    if (!s || !out)
        return gw_err_set(err, GW_EINVAL, "gw_chain_dispersion_run: %s is NULL", !s ? "setup" : "out");
    const gw_solver_type *type;
    gw_solver_params sp;
    int rc = gw_param_check(disp_params, s, err);
    if (rc == GW_OK)
        rc = disp_unused_check(s, err);
    if (rc == GW_OK) /* what was given decides (steps-per-sample with cvode) */
        rc = gw_chain_dispersion_solver(s, &type, &sp, err);
    if (rc != GW_OK)
        return rc;
    gw_chain_dispersion_setup r = *s; /* the values the run uses (no owned fields) */
    if ((rc = gw_param_resolve(disp_params, &r, err)) != GW_OK)
        return rc;
    double t0 = gw_clock_ms();
    if (r.column_n > 0) {
        rc = run_column(&r, type, &sp, progress, pctx, out, err);
        out->wall_time_ms = gw_clock_ms() - t0;
        return rc;
    }
    gw_chain_disp_params p = gw_chain_disp_params_default();
    p.n = (int)r.n;
    p.f0 = r.f0;
    p.ends = r.ends == 1 ? GW_CHAIN_DISP_FIXED : GW_CHAIN_DISP_PERIODIC;
    p.t_samples = (int)r.t_samples;
    p.dt_sample = r.dt_out;
    p.steps_per_sample = (int)r.steps_per_sample;
    p.amp = r.amp;
    p.seed = (unsigned long)r.seed;
    p.min_bins = r.min_bins;
    p.fftw_measure = r.fftw_measure;
    if ((rc = gw_chain_disp_params_validate(&p, err)) != GW_OK) {
        if (strncmp(err->msg, "--", 2) == 0) { /* the model names its fields as flags */
            char tmp[sizeof err->msg];
            gw_snprintf(tmp, sizeof tmp, "%s", err->msg + 2);
            gw_err_set(err, rc, "%s", tmp);
        }
        return rc;
    }
    out->params = p;
    out->solver = type;
    out->solver_params = sp;
    rc = gw_chain_disp_run_progress(&p, type, &sp, progress, pctx, &out->r, err);
    out->wall_time_ms = gw_clock_ms() - t0;
    out->c0_rel_err = fabs(out->r.c0_measured / out->r.c0_theory - 1);
    out->mass = p.mass;
    out->k = p.k;
    out->radius = p.radius;
    out->kwall = NAN;
    out->dt_out = out->r.dt_sample;
    out->rtol = sp.rtol;
    out->atol = sp.atol;
    if (rc == GW_OK && (rc = gw_chain_dispersion_warnings(&out->r, &out->warnings)) != GW_OK)
        rc = gw_err_set(err, rc, "dispersion: out of memory");
    return rc;
}
