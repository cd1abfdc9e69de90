/*
 * chain_falcon_study.c: the rigid-wall study of Falcon et al. (1998) as a
 * library call (gw_chain_study.h): one collision for every N in [n_lo, n_hi]
 * at each impact velocity (given directly, or from drop heights h in mm:
 * v = sqrt(2 g h), g the run's gravity or 9.81 m/s^2 when it has none:
 * gw_chain_falcon_speeds), then per velocity
 *   tau_N = T_q (N - 1) + tau_1            (F.4, GSL least squares)
 *   wave speed 4R/T_q                      (F.6)
 *   against 2 (k/m)^(2/5) R v^(1/5)        (F.27), T_q = 2 (m/k)^(2/5) v^(-1/5) (F.17)
 * F_max over N (flat on a rigid wall, K > K_c, F.22), the mean period P of the
 * wall force (N >= 10), the closed forms of one bead (F.2, F.13).
 * The solver by accuracy target: RK4 with events as roots and dt = T_c/M,
 * M = gw_chain_rk4_steps_per_tc(accuracy) (a measured convergence study).
 * SI units (heights in mm).
 */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_setup_rows.h"
#include "chain_model.h"
#include "chain_watch.h"
#include "gw_locale.h"
#include "gw_number_impl.h"

int gw_chain_falcon_analyse_check(const gw_chain_params *p, const gw_chain_result *res, int n_lo, int n_hi,
                                  const gw_chain_falcon_fit *a, gw_err *err)
{
    static const char who[] = "gw_chain_falcon_analyse";
    if (!p || !res || !a)
        return gw_err_set(err, GW_EINVAL, "%s: %s is NULL", who, !p ? "p" : !res ? "res" : "a");
    /* sizes N are bead counts >= 1, n_lo .. n_hi a range: n_lo > n_hi or a
     * size below 1 gave GW_OK with a fit of no column (or read res[-1]), and
     * n_hi = INT_MAX overflowed the loop's n++ */
    if (n_lo < 1)
        return gw_err_set(err, GW_EINVAL, "%s: n_lo = %d: column sizes are bead counts >= 1", who, n_lo);
    if (n_hi < n_lo)
        return gw_err_set(err, GW_EINVAL, "%s: n_lo = %d > n_hi = %d: no column (res holds n_hi - n_lo + 1)", who,
                          n_lo, n_hi);
    if (n_hi == INT_MAX)
        return gw_err_set(err, GW_EINVAL, "%s: n_hi = %d (INT_MAX): the largest column size is INT_MAX - 1", who,
                          n_hi);
    return GW_OK;
}

int gw_chain_falcon_analyse(const gw_chain_params *p, double v, const gw_chain_result *res, int n_lo,
                             int n_hi, gw_chain_falcon_fit *a)
{
    if (gw_chain_falcon_analyse_check(p, res, n_lo, n_hi, a, NULL) != GW_OK)
        return GW_EINVAL;
    /* Only the decided columns: one held by gravity (chain_held_pending) was
     * stopped when it fell back onto the wall, its tau_N and F_max those of
     * that time, not its collision's (softwall --gravity 1e4 fitted them). The
     * numbers below are those of the decided columns alone, as if the held
     * sizes had not been run; without held columns, the same arithmetic in the
     * same order as before, bit for bit. */
    int count = 0, c20 = 0, np = 0;
    for (int n = n_lo; n <= n_hi; n++)
        count += !chain_result_held(&res[n - n_lo]);
    double *x = calloc(2 * (size_t)(count > 0 ? count : 1), sizeof *x), *y = x ? x + (count > 0 ? count : 1) : NULL;
    memset(a, 0, sizeof *a);
    a->f_min = INFINITY;
    a->f_max = -INFINITY;
    for (int n = n_lo, k = 0; n <= n_hi; n++) {
        const gw_chain_result *r = &res[n - n_lo];
        if (chain_result_held(r))
            continue;
        if (x) {
            x[k] = n - 1;
            y[k] = r->tau_n;
        }
        k++;
        if (n <= 20)
            c20++;
        a->f_mean += r->f_max / count;
        a->tau_max_mean += r->tau_max / count;
        a->f_min = fmin(a->f_min, r->f_max);
        a->f_max = fmax(a->f_max, r->f_max);
        if (n >= 10 && r->n_maxima >= 2) {
            a->period_mean += r->period;
            np++;
        }
    }
    a->period_mean = np ? a->period_mean / np : NAN;
    if (count == 0) /* every column held: no mean, no extreme */
        a->f_mean = a->tau_max_mean = a->f_min = a->f_max = NAN;
    a->n_decided = count;
    a->n_decided20 = c20;
    /* no line through fewer than 2 points: every number of it undefined (a
     * single N reported t_q null beside t_q_err 0 and r2 0) */
    a->fit = a->fit20 = (gw_linfit){.c0 = NAN, .c1 = NAN, .c0_err = NAN, .c1_err = NAN, .r2 = NAN, .max_rel_resid = NAN};
    if (x && count >= 2)
        gw_fit_linear(x, y, count, &a->fit);
    if (x && c20 >= 2)
        gw_fit_linear(x, y, c20, &a->fit20);
    free(x);
    a->t_q_theory = gw_chain_tq_theory(p->mass, p->k, v);
    a->tau_1_theory = gw_chain_tau1(p->mass, p->kwall, v);
    a->f_max_1_theory = gw_chain_fmax1(p->mass, p->kwall, v);
    a->speed = 4 * p->radius / a->fit.c1;
    a->speed20 = 4 * p->radius / a->fit20.c1;
    a->speed_theory = 4 * p->radius / a->t_q_theory;
    return x ? GW_OK : GW_ENOMEM;
}

/* ---- the table of the inputs ---- */

/* The accuracy row's default (its .def string says the same). */
#define FALCON_ACCURACY_DEFAULT 1e-6

#define OFF(f) offsetof(gw_chain_falcon_setup, col.f)
#define OWN(f) offsetof(gw_chain_falcon_setup, f)

static const gw_param falcon_params[] = {
    {.name = "vimp", .type = GW_PARAM_LIST, .offset = OWN(vimp), .unit = "m/s", .min = GW_CHAIN_VIMP_MIN,
     .max = GW_CHAIN_VIMP_MAX, .def = "0.3", .rows = SPEEDS_MOST, .metavar = "V,V..", .help = "impact velocities, m/s [0.3]"},
    {.name = "heights", .type = GW_PARAM_LIST, .offset = OWN(heights), .unit = "mm", .min = GW_CHAIN_HEIGHT_MIN_MM,
     .max = GW_CHAIN_HEIGHT_MAX_MM, .def = "1.9,2.9,3.1,5.1",
     .rows = SPEEDS_MOST, .metavar = "H,H..", .help = "drop heights, mm, v = sqrt(2 g h), g the gravity or 9.81 when off ['none' to skip] [1.9,2.9,3.1,5.1]"},
    {.name = "n", .type = GW_PARAM_RANGE, .offset = OWN(n), .unit = "", .min = 1, .max = 100000, .def = "1:40",
     .metavar = "A:B", .help = "column sizes [1:40]"},
    /* no default in the table: not given (NaN) is the default target
     * FALCON_ACCURACY_DEFAULT, and a value given, even that one, is asked for
     * (pick_solver), as the command's --accuracy */
    /* the range is the step study's, [1e-9, 1e-2] (gw_chain_rk4_steps_per_tc),
     * and 0 besides it (or_zero): the row said [0, 1e-2] while the study
     * refused (0, 1e-9) */
    {.name = "accuracy", .type = GW_PARAM_DOUBLE, .offset = OWN(accuracy), .unit = "",
     .min = GW_CHAIN_RK4_ACCURACY_MIN, .max = GW_CHAIN_RK4_ACCURACY_MAX, .or_zero = 1, .metavar = "A",
     .help = "relative accuracy of F_max and tau_N when no solver option is given, in [1e-9, 1e-2]: RK4, dt = "
             "T_c/M with M from a measured convergence study [1e-6]; 0 = the solver options as given"},
    {.name = "jobs", .type = GW_PARAM_LONG, .offset = OWN(jobs), .unit = "", .min = 0, .max = 1024, .def = "0",
     .metavar = "J", .help = "threads [0 = one per CPU]"},
    /* the defaults of --accuracy (pick_solver), not chain's: the help said
     * cvode, T_c/400 and tau_1/200 while the runs used rk4 at T_c/37 sampled
     * every tau_1/10 (the program takes these three from here) */
    GW_CHAIN_MODEL_ROWS_HELP("cvode, arkode or rk4 [rk4 by --accuracy; cvode when a solver option is given or "
                             "the column is outside the step study]",
                             "RK4 step, s, in [0, 1] [0 = T_c/M by --accuracy, M = 37 at 1e-6; T_c/400 with --solver rk4]; "
                             "initial step for cvode/arkode",
                             "sampling interval for the energy check, s, in [0, 1] [0 = tau_1/10 of the fastest impact by "
                             "--accuracy, else tau_1/200; the traces every tau_1/50]")
    GW_PARAM_END};

const gw_param *gw_chain_falcon_setup_params(void)
{
    return falcon_params;
}

int gw_chain_falcon_setup_init(gw_chain_falcon_setup *s)
{
    if (!s)
        return GW_EINVAL;
    return chain_study_setup_init(s, sizeof *s, &s->col, falcon_params);
}

void gw_chain_falcon_setup_clear(gw_chain_falcon_setup *s)
{
    if (!s)
        return;
    chain_study_setup_clear(s, &s->col, falcon_params);
}

/* ---- the table of the results ---- */

#undef OFF
#define OFF(f) offsetof(gw_chain_falcon_outcome, f)
#define CASE(nm, f, un, hl) RA(nm, f, un, "nv", "nn", hl " [velocity, N]")
#define VEL(nm, f, un, hl) RA(nm, f, un, "nv", NULL, hl " [velocity]")
#define BEAD(nm, f, un, hl) RA(nm, f, un, "nbeads", NULL, hl " [bead row: velocity, N, bead]")

static const gw_param falcon_fields[] = {
    {.name = "nv", .type = GW_PARAM_INT, .offset = OFF(nv), .unit = "", .help = "impact velocities"},
    {.name = "nn", .type = GW_PARAM_INT, .offset = OFF(nn), .unit = "", .help = "column sizes"},
    {.name = "ncase", .type = GW_PARAM_INT, .offset = OFF(ncase), .unit = "", .help = "collisions"},
    {.name = "k_c", .type = GW_PARAM_DOUBLE, .offset = OFF(k_c), .unit = "N/m^1.5", .help = "critical wall coefficient K_c (F.22)"},
    GW_RESULT_FLAG("rigid", OFF(rigid), "1: K > K_c (rigid wall)"),
    {.name = "accuracy", .type = GW_PARAM_DOUBLE, .offset = OFF(accuracy), .unit = "",
     .help = "the accuracy target the solver was chosen by (0: the solver options as given)"},
    {.name = "wall_time_s", .type = GW_PARAM_DOUBLE, .offset = OFF(wall_time_s), .unit = "s", .help = "wall-clock time of the collisions"},
    VEL("v_imp", v_imp, "m/s", "impact velocity"),
    VEL("h_mm", h_mm, "mm", "drop height (NaN: velocity given directly)"),
    RA("n", n, "", "nn", NULL, "column sizes N"),
    CASE("f_max", f_max, "N", "largest wall force"),
    CASE("tau_max", tau_max, "s", "time of f_max"),
    CASE("tau_n", tau_n, "s", "contact time tau_N"),
    CASE("period", period, "s", "mean spacing of wall-force maxima"),
    CASE("eps_eff", eps_eff, "", "momentum restitution (F.7)"),
    CASE("eps_col", eps_col, "", "energy restitution (F.30)"),
    CASE("e_rel_over_e_k", e_rel_over_e_k, "", "E_rel/E_K at tau_N (F.20)"),
    CASE("n_s", n_s, "", "beads leaving from the top before the cluster"),
    CASE("energy_error", energy_error, "", "max relative energy error"),
    CASE("t_max", t_max, "s", "time limit of the collision (default 20 (N T_q + tau_1 + t_s), t_s the column's ride on a sensor spring)"),
    CASE("dt_out", dt_out, "s", "its sampling interval"),
    CASE("dt", dt, "s", "its RK4 step (0: cvode, arkode)"),
    CASE("dt_max", dt_max, "s", "its largest step"),
    CASE("n_maxima", n_maxima, "", "wall-force maxima"),
    CASE("cluster", cluster, "", "beads in contact with bead 1 when it left the wall"),
    CASE("steps", steps, "", "solver steps"),
    CASE("rhs_evals", rhs_evals, "", "right-hand side evaluations"),
    {.name = "gamma", .type = GW_PARAM_DOUBLE, .offset = OFF(gamma), .unit = "N s/m^1.5",
     .help = "Kuwabara-Kono constant run (calibrated with restitution; 0: none)"},
    {.name = "alpha", .type = GW_PARAM_DOUBLE, .offset = OFF(alpha), .unit = "s/m",
     .help = "Hunt-Crossley constant run (calibrated with restitution; 0: none)"},
    VEL("t_q", t_q, "s", "T_q: slope of tau_N against N - 1 (F.4), all N"),
    VEL("t_q_err", t_q_err, "s", "its standard error"),
    VEL("tau_fit_intercept", tau_fit_intercept, "s", "intercept of that line"),
    VEL("tau_fit_intercept_err", tau_fit_intercept_err, "s", "its standard error"),
    VEL("r2", r2, "", "coefficient of determination of the line"),
    VEL("tau_fit_max_rel_resid", tau_fit_max_rel_resid, "", "largest relative residual"),
    VEL("t_q_n20", t_q_n20, "s", "T_q over N <= 20"),
    VEL("t_q_n20_err", t_q_n20_err, "s", "its standard error"),
    VEL("wave_speed", wave_speed, "m/s", "4R/T_q (F.6)"),
    VEL("wave_speed_n20", wave_speed_n20, "m/s", "4R/T_q over N <= 20"),
    VEL("wave_speed_theory", wave_speed_theory, "m/s", "2 (k/m)^(2/5) R v^(1/5) (F.27)"),
    VEL("t_q_theory", t_q_theory, "s", "2 (m/k)^(2/5) v^(-1/5) (F.17, F.29)"),
    VEL("tau_1_theory", tau_1_theory, "s", "one bead's contact time (F.2)"),
    VEL("f_max_1_theory", f_max_1_theory, "N", "one bead's largest force (F.13)"),
    VEL("f_max_mean", f_max_mean, "N", "F_max averaged over N"),
    VEL("f_max_min", f_max_min, "N", "smallest F_max over N"),
    VEL("f_max_max", f_max_max, "N", "largest F_max over N"),
    VEL("tau_max_mean", tau_max_mean, "s", "tau_max averaged over N"),
    VEL("period_mean", period_mean, "s", "P averaged over N >= 10"),
    {.name = "unfinished", .type = GW_PARAM_INT, .offset = OFF(unfinished), .unit = "",
     .help = "collisions not ended at t_max (their tau_N and eps are those at t_max)"},
    RI("n_held", n_held, "collisions held by gravity (counted in unfinished): undecided, left out of every fit, "
                         "mean and extreme"),
    {.name = "held", .type = GW_PARAM_FARRAY, .offset = OFF(held), .unit = "", .rows = "nv", .cols = "nn",
     .help = "1: the collision was held by gravity (the column fell back onto the wall before it ended): its "
             "values are those of that time, undecided, and the fits leave it out [velocity, N]"},
    RI("steps_per_tc", steps_per_tc, "RK4 steps per T_c by the accuracy target (0: the solver options as given)"),
    RI("nbeads", nbeads, "rows of the bead table: every bead of every collision"),
    BEAD("bead_v_imp", bead_v_imp, "m/s", "impact velocity of the bead's collision"),
    BEAD("bead_n", bead_n, "", "column size N of the bead's collision"),
    BEAD("bead", bead, "", "the bead, 1 (on the wall) to N"),
    BEAD("final_v", final_v, "m/s", "velocity at the end, toward the wall > 0"),
    BEAD("detach_t", detach_t, "s", "last opening of a contact of the bead"),
    BEAD("v_tau_n", v_tau_n, "m/s", "velocity at tau_N"),
    GW_PARAM_WARNINGS(OFF(warnings)),
    GW_PARAM_END};

const gw_param *gw_chain_falcon_outcome_fields(void)
{
    return falcon_fields;
}

void gw_chain_falcon_outcome_free(gw_chain_falcon_outcome *out)
{
    if (!out)
        return;
    free(out->v_imp); /* one block holds every array */
    free(out->held);
    free(out->warnings);
    for (int i = 0; i < GW_CHAIN_FALCON_NTRACE; i++)
        gw_chain_trace_free(&out->trace[i].tr); /* zeroed or initialised */
    memset(out, 0, sizeof *out);
}

/* Point out's arrays into one block of doubles. */
static int alloc_outcome(gw_chain_falcon_outcome *o, int nv, int n_lo, int nn, gw_err *err)
{
    double **vel[] = {&o->v_imp, &o->h_mm, &o->t_q, &o->t_q_err, &o->tau_fit_intercept,
                      &o->tau_fit_intercept_err, &o->r2, &o->tau_fit_max_rel_resid, &o->t_q_n20,
                      &o->t_q_n20_err, &o->wave_speed, &o->wave_speed_n20, &o->wave_speed_theory,
                      &o->t_q_theory, &o->tau_1_theory, &o->f_max_1_theory, &o->f_max_mean, &o->f_max_min,
                      &o->f_max_max, &o->tau_max_mean, &o->period_mean};
    double **cas[] = {&o->f_max, &o->tau_max, &o->tau_n, &o->period, &o->eps_eff, &o->eps_col,
                      &o->e_rel_over_e_k, &o->n_s, &o->energy_error, &o->t_max, &o->dt_out, &o->dt, &o->dt_max,
                      &o->n_maxima, &o->cluster, &o->steps, &o->rhs_evals};
    double **bead[] = {&o->bead_v_imp, &o->bead_n, &o->bead, &o->final_v, &o->detach_t, &o->v_tau_n};
    const size_t nvel = sizeof vel / sizeof vel[0], ncas = sizeof cas / sizeof cas[0];
    const size_t nbead = sizeof bead / sizeof bead[0];
    o->nv = nv;
    o->nn = nn;
    o->ncase = nv * nn;
    /* every bead of every collision: nv (n_lo + ... + n_hi), within the work
       bound of the study (gw_chain_study_work_check) */
    double rows = (double)nv * nn * (n_lo + (n_lo + nn - 1)) / 2;
    if (rows > INT_MAX / 8)
        return gw_err_set(err, GW_EINVAL, "n: %g bead rows: too many", rows);
    o->nbeads = (int)rows;
    double *b = calloc(nvel * (size_t)nv + ncas * (size_t)o->ncase + (size_t)nn + nbead * (size_t)o->nbeads,
                       sizeof *b);
    if (!b)
        return gw_err_set(err, GW_ENOMEM, "falcon: out of memory for %d collisions", o->ncase);
    for (size_t i = 0; i < nvel; i++, b += nv)
        *vel[i] = b; /* v_imp first: the block's start */
    for (size_t i = 0; i < ncas; i++, b += o->ncase)
        *cas[i] = b;
    o->n = b;
    b += nn;
    for (size_t i = 0; i < nbead; i++, b += o->nbeads)
        *bead[i] = b;
    return GW_OK;
}

/* The traces of N = 7, 15, 30 (those <= n_hi) at the first velocity, each its
 * own run of p, o: sampled every tau_1/50 of that velocity when the solver was
 * picked by the accuracy target (one sample per pixel of the 1080-pixel-wide
 * figures of the longest, N = 30, 0.8 ms trace at 0.3 m/s, 45 per force period;
 * maxima are events), else at o's dt_out. The beads' series are kept for N = 7
 * only (the bead table of long columns is large). */
static const int trace_n[GW_CHAIN_FALCON_NTRACE] = {7, 15, 30};

/* A trace's run options: o0 sampled as run_traces says. */
static gw_chain_run_opts trace_opts(const gw_chain_falcon_outcome *out, const gw_chain_params *p,
                                    const gw_chain_run_opts *o0)
{
    gw_chain_run_opts o = *o0;
    if (out->accuracy > 0)
        o.dt_out = gw_chain_tau1(p->mass, p->kwall, p->v_imp) / 50;
    return o;
}

/* The traces' runs to come (watch's plan), as run_traces runs them. */
static void plan_traces(chain_watch *watch, const gw_chain_falcon_outcome *out, const gw_chain_params *p0,
                        const gw_chain_run_opts *o0, int n_hi)
{
    for (int k = 0; k < GW_CHAIN_FALCON_NTRACE; k++) {
        if (trace_n[k] > n_hi)
            continue;
        gw_chain_params p = *p0;
        p.n = trace_n[k];
        p.v_imp = out->v_imp[0];
        gw_chain_run_opts o = trace_opts(out, &p, o0);
        chain_watch_plan(watch, &p, &o);
    }
}

static int run_traces(gw_chain_falcon_outcome *out, const gw_chain_params *p0, const gw_chain_run_opts *o0,
                      int n_hi, chain_dt_tally *dt_tally, chain_watch *watch, gw_err *err)
{
    for (int k = 0; k < GW_CHAIN_FALCON_NTRACE; k++) {
        if (trace_n[k] > n_hi)
            continue;
        gw_chain_falcon_trace *t = &out->trace[out->ntrace];
        gw_chain_params p = *p0;
        p.n = trace_n[k];
        p.v_imp = out->v_imp[0];
        gw_chain *c = NULL;
        int rc = gw_chain_create(&p, &c, err);
        if (rc != GW_OK)
            return rc;
        gw_chain_trace_init(&t->tr, p.n);
        gw_chain_run_opts o = trace_opts(out, &p, o0);
        o.sample = gw_chain_trace_sample;
        o.sample_ctx = &t->tr;
        gw_chain_result r;
        rc = chain_watch_collide(watch, c, &p, &o, &r, err);
        t->n = p.n;
        t->v_imp = p.v_imp;
        t->t_max = r.run_t_max;
        t->dt_out = r.run_dt_out;
        t->dt = r.run_dt;
        t->dt_max = r.run_dt_max;
        if (rc == GW_OK) /* its own run: the step it took, as the study's (the --dt warning) */
            chain_dt_tally_results(dt_tally, &r, 1);
        /* a trace stopped at its 5 GB bound while its run went on (cut without a
           word before); under --accuracy the traces sample every tau_1/50 */
        if (rc == GW_OK &&
            chain_trace_cut_warnings(&t->tr, r.t_end,
                                     out->accuracy > 0 ? "--dt-out (given with --accuracy 0: under --accuracy the "
                                                         "traces sample every tau_1/50)"
                                                       : "--dt-out",
                                     &out->warnings) != GW_OK)
            rc = gw_err_set(err, GW_ENOMEM, "falcon: out of memory");
        gw_chain_result_free(&r);
        gw_chain_free(c);
        if (rc != GW_OK) {
            gw_chain_trace_free(&t->tr);
            return rc;
        }
        if (p.n != 7) { /* wall force only */
            free(t->tr.x);
            free(t->tr.v);
            t->tr.x = t->tr.v = NULL;
            t->tr.n = 0;
        }
        out->ntrace++;
    }
    return GW_OK;
}

/* The solver by accuracy target, when col's solver rows are all at their
 * defaults and the study's range covers the column (undamped, no gravity,
 * N <= 40); otherwise col's solver as resolved, and *used = 0. */
static int pick_solver(const gw_chain_falcon_setup *s, gw_chain_resolved *r, double vmax, double *used,
                       gw_err *err)
{
    /* any solver row given, even at its default's value (solver = cvode), is
     * the solver as given: before the rows had a "not given" state, a C
     * caller's solver = cvode ran RK4 by the accuracy target */
    const int at_defaults = s->col.solver < 0 && s->col.method < 0 && isnan(s->col.rtol) && isnan(s->col.atol) &&
                            isnan(s->col.dt);
    *used = 0;
    /* an accuracy given (the row set, to any value: NaN is not given) is asked
     * for: where it cannot act it is refused, as the command refuses --accuracy
     * (not silently ignored). Before, "asked" was a value other than the
     * default, so accuracy=1e-6 given with a damped column or a solver option
     * ran the solver as given where `granwave falcon --accuracy 1e-6` is
     * refused (exit 2). */
    const int asked = !isnan(s->accuracy);
    const double acc = asked ? s->accuracy : FALCON_ACCURACY_DEFAULT;
    if (acc > 0 && gw_chain_rk4_steps_per_tc(acc) <= 0)
        return gw_err_set(err, GW_EINVAL, "accuracy: %g outside [1e-9, 1e-2] (or 0: the solver options as given)",
                          acc);
    if (!(acc > 0))
        return GW_OK;
    if (!at_defaults)
        return asked ? gw_err_set(err, GW_EINVAL, "accuracy: give either accuracy or the solver options") : GW_OK;
    if (!gw_chain_rk4_study_covers(&r->params, s->n[1]))
        return asked ? gw_err_set(err, GW_EINVAL, "accuracy: the step study covers undamped columns of N <= 40 "
                                                  "without gravity on a Hertz wall, without sensor body or guide "
                                                  "friction; give the solver instead")
                     : GW_OK;
    gw_chain_rk4_study_apply(&r->run, &r->params, acc, vmax, s->col.dt_out != 0); /* checked above */
    *used = acc;
    return GW_OK;
}

int gw_chain_falcon_sizes_check_at(long a, long b, int ncols, gw_err *err)
{
    if (a < 1 || b < a) /* -5:9.2e18 passed */
        return gw_err_set(err, GW_EINVAL, "n: %ld:%ld is not a range of column sizes (1 <= A < B)", a, b);
    if (a == b) {
        /* the pair suggested within the studies' work bound at the study's
         * velocities (1415:1415 was told "e.g. 1414:1415", which the bound
         * refuses; then "999:1000", which it refuses at falcon's default 5
         * speeds): above it the largest pair it holds, 999:1000 at one
         * velocity, 447:448 at five */
        const double m = ncols > 1 ? (double)ncols : 1.0;
        long hi = a > 1 ? b : b + 1;
        char why[96] = "";
        if (m * ((double)(hi - 1) * (double)(hi - 1) + (double)hi * (double)hi) > GW_CHAIN_STUDY_WORK_MAX) {
            hi = 1;
            while (m * ((double)hi * hi + (double)(hi + 1) * (hi + 1)) <= GW_CHAIN_STUDY_WORK_MAX)
                hi++;
            if (hi < 2)
                hi = 2; /* the smallest pair: the work check names the speeds */
            if (ncols > 1)
                gw_snprintf(why, sizeof why, ", the largest pair the studies' work bound holds at %d velocities",
                            ncols);
            else
                gw_snprintf(why, sizeof why, ", the largest pair the studies' work bound holds at one velocity");
        }
        if ((double)a * (double)a > GW_CHAIN_STUDY_WORK_MAX) /* chain --n 1415 is refused too */
            return gw_err_set(err, GW_EINVAL, "n: %ld:%ld is one column size, and the study fits tau_N = T_q (N - 1) "
                              "+ tau_1 over N (T_q, the wave speed 4R/T_q): give at least two sizes, e.g. %ld:%ld%s "
                              "(one column of %ld beads is above the column's work bound too: granwave chain --n "
                              "runs up to %ld over a whole collision)", a, b, hi - 1, hi, why, a,
                              (long)floor(sqrt(GW_CHAIN_STUDY_WORK_MAX)));
        return gw_err_set(err, GW_EINVAL, "n: %ld:%ld is one column size, and the study fits tau_N = T_q (N - 1) + "
                          "tau_1 over N (T_q, the wave speed 4R/T_q): give at least two sizes, e.g. %ld:%ld%s (one "
                          "column's collision: granwave chain --n %ld)", a, b, hi - 1, hi, why, a);
    }
    return GW_OK;
}

int gw_chain_falcon_sizes_check(long a, long b, gw_err *err)
{
    return gw_chain_falcon_sizes_check_at(a, b, 1, err);
}

int gw_chain_falcon_speeds(const double *vimp, int n_vimp, const double *heights_mm, int n_heights, double gravity,
                           double *v, double *h_mm, gw_err *err)
{
    /* a negative count was "both empty" (n_vimp -1 with a height given);
     * gravity NaN fell as Earth's and infinite gave speeds of inf m/s, refused
     * as two speeds "within a relative -nan" of each other */
    if (n_vimp < 0 || n_heights < 0)
        return gw_err_set(err, GW_EINVAL, "gw_chain_falcon_speeds: %s = %d is negative",
                          n_vimp < 0 ? "n_vimp" : "n_heights", n_vimp < 0 ? n_vimp : n_heights);
    char gs[32];
    if (!(gravity >= 0 && gravity <= 1e4)) /* as given: 10000.0000001 was "10000 ... is outside [0, 10000]" */
        return gw_err_set(err, GW_EINVAL, "gravity: %s m/s^2 is outside [0, 10000]",
                          gw_num_text(gs, sizeof gs, gravity));
    /* two counts near INT_MAX overflowed their int sum (undefined; a
     * negative total was told "both empty"): summed as longs, a total no int
     * holds refused naming both */
    if ((long)n_vimp + n_heights > INT_MAX)
        return gw_err_set(err, GW_EINVAL, "gw_chain_falcon_speeds: n_vimp + n_heights = %d + %d impact velocities, "
                          "above %d", n_vimp, n_heights, INT_MAX);
    int nv = n_vimp + n_heights;
    if (nv <= 0)
        return gw_err_set(err, GW_EINVAL, "vimp: no impact velocity (vimp and heights both empty)");
    if (!v || (n_vimp && !vimp) || (n_heights && !heights_mm))
        return gw_err_set(err, GW_EINVAL, "gw_chain_falcon_speeds: a list is NULL");
    /* the fall in the run's gravity when it has one (as drop's), else Earth's:
     * with gravity 100 the heights were converted at 9.81 while the column
     * felt 100 (falcon --heights 5.1 --gravity 100: 0.316 m/s, not 1.01) */
    const double g_fall = gravity > 0 ? gravity : GW_CHAIN_G_EARTH;
    for (int i = 0; i < nv; i++) {
        int is_h = i >= n_vimp;
        double x = is_h ? heights_mm[i - n_vimp] : vimp[i];
        if (!(x > 0))
            return gw_err_set(err, GW_EINVAL, "%s: %g must be > 0", is_h ? "heights" : "vimp", x);
        if (h_mm)
            h_mm[i] = is_h ? x : NAN;
        v[i] = is_h ? sqrt(2 * g_fall * x * 1e-3) : x;
    }
    /* the ranges, before the velocities are compared (a height beyond its row
     * named as given: --heights 1e308 fell at 2 g h = inf, and the comparison
     * said "the impact velocity inf m/s, within a relative -nan of item 1 of
     * vimp"): the table's rows (speeds as every chain command takes
     * them; heights GW_CHAIN_HEIGHT_MIN_MM to GW_CHAIN_HEIGHT_MAX_MM, those
     * speeds at 9.81), and under another gravity each height's fall within the
     * speeds of the row, chain's [GW_CHAIN_VIMP_MIN, GW_CHAIN_VIMP_MAX]: the
     * row alone let --heights 5e7 --gravity 1e4 run at 31623 m/s and --heights
     * 1 --gravity 1e-300 at 4.5e-152 m/s (the lower end was the smallest
     * height's speed at 9.81, 0.99e-9 m/s, below chain's until session 45) */
    const double vlo = GW_CHAIN_VIMP_MIN;
    for (int i = 0; i < nv; i++) {
        int is_h = i >= n_vimp, k = is_h ? i - n_vimp + 1 : i + 1;
        double x = is_h ? heights_mm[i - n_vimp] : vimp[i];
        double lo = is_h ? GW_CHAIN_HEIGHT_MIN_MM : GW_CHAIN_VIMP_MIN, hi = is_h ? GW_CHAIN_HEIGHT_MAX_MM : GW_CHAIN_VIMP_MAX;
        char xs[32], ls[32], hs[32];
        if (!(x >= lo && x <= hi)) /* the list parser's message (gw_parse_double_list_in) */
            return gw_err_set(err, GW_EINVAL, "%s: item %d is %s, outside [%s, %s]", is_h ? "heights" : "vimp", k,
                              gw_num_text(xs, sizeof xs, x), gw_num_bound(ls, sizeof ls, lo, 0),
                              gw_num_bound(hs, sizeof hs, hi, 1));
        if (is_h && g_fall != GW_CHAIN_G_EARTH && !(v[i] >= vlo && v[i] <= GW_CHAIN_VIMP_MAX))
            return gw_err_set(err, GW_EINVAL, "heights: item %d is %g mm: at gravity %g m/s^2 it falls to v = "
                              "sqrt(2 g h) = %g m/s, outside the impact speeds [%s, %s] m/s", k, x, g_fall, v[i],
                              gw_num_bound(ls, sizeof ls, vlo, 0), gw_num_bound(hs, sizeof hs, GW_CHAIN_VIMP_MAX, 1));
    }
    return gw_chain_study_speeds_check(v, nv, n_vimp, err);
}

static int falcon_run(const gw_chain_falcon_setup *s, gw_progress_fn progress, void *pctx, chain_watch *watch,
                      gw_chain_falcon_outcome *out, gw_err *err);

int gw_chain_falcon_run(const gw_chain_falcon_setup *s, gw_progress_fn progress, void *pctx,
                        gw_chain_falcon_outcome *out, gw_err *err)
{
    return gw_chain_falcon_run_watch(s, progress, pctx, NULL, NULL, out, err);
}

int gw_chain_falcon_run_watch(const gw_chain_falcon_setup *s, gw_progress_fn progress, void *pctx,
                              gw_chain_watch_fn watch, void *wctx, gw_chain_falcon_outcome *out, gw_err *err)
{
    chain_watch w;
    chain_watch_init(&w, watch, wctx);
    int rc = falcon_run(s, progress, pctx, &w, out, err);
    chain_watch_destroy(&w);
    return rc;
}

static int falcon_run(const gw_chain_falcon_setup *s, gw_progress_fn progress, void *pctx, chain_watch *watch,
                      gw_chain_falcon_outcome *out, gw_err *err)
{
    if (out) /* emptied on every refusal, a NULL setup's too (docs/library.md) */
        memset(out, 0, sizeof *out);
    if (!s || !out)
        return gw_err_set(err, GW_EINVAL, "gw_chain_falcon_run: %s is NULL", !s ? "setup" : "out");
    /* the lists' counts summed as longs: vimp.n or heights.n set by hand near
     * INT_MAX overflowed the int sum before the range check refused them */
    const long nvl = (long)s->vimp.n + s->heights.n;
    int rc = chain_study_range_check(falcon_params, s, &s->col, nvl > INT_MAX ? INT_MAX : (int)nvl, err);
    if (rc != GW_OK)
        return rc;
    int nv = (int)nvl, nn = (int)(s->n[1] - s->n[0] + 1);
    if ((rc = gw_chain_falcon_sizes_check_at(s->n[0], s->n[1], nv, err)) != GW_OK)
        return rc;
    if ((rc = alloc_outcome(out, nv, (int)s->n[0], nn, err)) != GW_OK)
        return rc;
    /* the speeds and heights to velocities (none: refused there) */
    if ((rc = gw_chain_falcon_speeds(s->vimp.v, s->vimp.n, s->heights.v, s->heights.n, s->col.gravity, out->v_imp,
                                     out->h_mm, err)) != GW_OK) {
        gw_chain_falcon_outcome_free(out);
        return rc;
    }
    double vmax = 0;
    for (int i = 0; i < nv; i++)
        vmax = fmax(vmax, out->v_imp[i]);
    for (int k = 0; k < nn; k++)
        out->n[k] = (double)(s->n[0] + k);
    gw_chain_setup col = s->col; /* shallow: n and vimp of the first case, no radii */
    col.n = s->n[0];
    col.vimp = out->v_imp[0];
    gw_chain_resolved r;
    gw_chain_result *res = calloc((size_t)out->ncase, sizeof *res);
    rc = res ? gw_chain_setup_resolve(&col, &r, err) : gw_err_set(err, GW_ENOMEM, "falcon: out of memory");
    if (rc == GW_OK)
        rc = chain_damping_study_check(&r.params, s->n[0], NULL, err);
    if (rc == GW_OK)
        rc = pick_solver(s, &r, vmax, &out->accuracy, err);
    double t0 = gw_clock_ms();
    if (rc == GW_OK) { /* the whole study's work first: the sweep's, then the traces' */
        chain_watch_plan_sweep(watch, &r.params, &r.run, out->v_imp, nv, (int)s->n[0], (int)s->n[1],
                               (int)s->jobs);
        if (s->traces)
            plan_traces(watch, out, &r.params, &r.run, (int)s->n[1]);
        rc = chain_sweep_watch(&r.params, &r.run, out->v_imp, nv, (int)s->n[0], (int)s->n[1], (int)s->jobs,
                               progress, pctx, watch, res, err);
    }
    out->wall_time_s = (gw_clock_ms() - t0) / 1e3;
    if (rc == GW_OK && !(out->held = calloc((size_t)out->ncase, sizeof *out->held)))
        rc = gw_err_set(err, GW_ENOMEM, "falcon: out of memory");
    for (int i = 0; rc == GW_OK && i < out->ncase; i++) {
        out->unfinished += !res[i].converged;
        out->held[i] = chain_result_held(&res[i]);
        out->n_held += out->held[i];
    }
    char undecided[256] = ""; /* the velocities whose fits the held columns leave undecided */
    int n_undecided = 0, none_decided = 0;
    int row = 0;
    for (int iv = 0; rc == GW_OK && iv < nv; iv++) {
        gw_chain_falcon_fit a;
        const gw_chain_result *rv = &res[iv * nn];
        const int arc = gw_chain_falcon_analyse(&r.params, out->v_imp[iv], rv, (int)s->n[0], (int)s->n[1], &a);
        if (arc != GW_OK) { /* a refusal named by the check (the sizes are the table's: none seen) */
            rc = arc == GW_ENOMEM ? gw_err_set(err, GW_ENOMEM, "out of memory for the fits")
                                  : gw_chain_falcon_analyse_check(&r.params, rv, (int)s->n[0], (int)s->n[1], &a, err);
            break;
        }
        for (int k = 0; k < nn; k++) {
            int c = iv * nn + k;
            out->f_max[c] = rv[k].f_max;
            out->tau_max[c] = rv[k].tau_max;
            out->tau_n[c] = rv[k].tau_n;
            out->period[c] = rv[k].period;
            out->eps_eff[c] = rv[k].eps_eff;
            out->eps_col[c] = rv[k].eps_col;
            out->e_rel_over_e_k[c] = rv[k].e_rel_over_e_k;
            out->n_s[c] = rv[k].n_s;
            out->energy_error[c] = rv[k].energy_error;
            out->t_max[c] = rv[k].run_t_max;
            out->dt_out[c] = rv[k].run_dt_out;
            out->dt[c] = rv[k].run_dt;
            out->dt_max[c] = rv[k].run_dt_max;
            out->n_maxima[c] = rv[k].n_maxima;
            out->cluster[c] = rv[k].cluster;
            out->steps[c] = (double)rv[k].stats.steps;
            out->rhs_evals[c] = (double)rv[k].stats.rhs_evals;
            for (int i = 0, n = (int)s->n[0] + k; i < n; i++, row++) {
                out->bead_v_imp[row] = out->v_imp[iv];
                out->bead_n[row] = n;
                out->bead[row] = i + 1;
                out->final_v[row] = rv[k].final_v[i];
                out->detach_t[row] = rv[k].detach_t[i];
                out->v_tau_n[row] = rv[k].v_tau_n[i];
            }
        }
        out->t_q[iv] = a.fit.c1;
        out->t_q_err[iv] = a.fit.c1_err;
        out->tau_fit_intercept[iv] = a.fit.c0;
        out->tau_fit_intercept_err[iv] = a.fit.c0_err;
        out->r2[iv] = a.fit.r2;
        out->tau_fit_max_rel_resid[iv] = a.fit.max_rel_resid;
        out->t_q_n20[iv] = a.fit20.c1;
        out->t_q_n20_err[iv] = a.fit20.c1_err;
        out->wave_speed[iv] = a.speed;
        out->wave_speed_n20[iv] = a.speed20;
        out->wave_speed_theory[iv] = a.speed_theory;
        out->t_q_theory[iv] = a.t_q_theory;
        out->tau_1_theory[iv] = a.tau_1_theory;
        out->f_max_1_theory[iv] = a.f_max_1_theory;
        out->f_max_mean[iv] = a.f_mean;
        out->f_max_min[iv] = a.f_min;
        out->f_max_max[iv] = a.f_max;
        out->tau_max_mean[iv] = a.tau_max_mean;
        out->period_mean[iv] = a.period_mean;
        /* a fit that the held columns leave without two points (every size
         * range has two: gw_chain_falcon_sizes_check; N <= 20 when it has) */
        const long top20 = s->n[1] < 20 ? s->n[1] : 20, c20 = s->n[0] <= 20 ? top20 - s->n[0] + 1 : 0;
        if (a.n_decided < 2 || (c20 >= 2 && a.n_decided20 < 2))
            chain_list_speed(undecided, sizeof undecided, &n_undecided, out->v_imp[iv]);
        none_decided |= a.n_decided == 0;
    }
    char where[300];
    gw_snprintf(where, sizeof where, "T_q and 4R/T_q at v_imp = %s m/s (fewer than two decided columns%s)", undecided,
                none_decided ? "; the means and extremes of F_max and tau_max too where none is decided" : "");
    if (rc == GW_OK) {
        out->k_c = gw_chain_kc(r.params.k);
        out->rigid = r.params.kwall > out->k_c;
        out->gamma = r.params.gamma; /* as the JSON's settings.model */
        out->alpha = r.params.alpha;
        out->steps_per_tc = out->accuracy > 0 ? (int)r.run.steps_per_tc : 0;
        if ((rc = gw_chain_unfinished_warnings(out->unfinished - out->n_held, out->ncase, &out->warnings)) !=
                GW_OK ||
            (rc = chain_held_warnings(out->n_held, out->ncase, "the fits over N (T_q, the wave speeds), the means "
                                      "and extremes", n_undecided ? where : NULL, &out->warnings)) != GW_OK)
            rc = gw_err_set(err, rc, "falcon: out of memory");
    }
    /* a --dt above the step taken: the grid's columns and the traces'; the chatter's reruns by the solver */
    chain_dt_tally dt_tally = {.solver = r.run.solver ? r.run.solver : gw_solver_cvode,
                               .rtol = r.run.sp.rtol,
                               .atol = r.run.sp.atol};
    if (rc == GW_OK)
        chain_dt_tally_results(&dt_tally, res, out->ncase);
    if (rc == GW_OK && s->traces &&
        (rc = run_traces(out, &r.params, &r.run, (int)s->n[1], &dt_tally, watch, err)) != GW_OK)
        out->trace_failed = 1;
    if (rc == GW_OK && ((rc = chain_dt_tally_warnings(&dt_tally, "--dt", "collisions", &out->warnings)) != GW_OK ||
                        (rc = chain_damping_zero_warnings(&r.params, 0, 1, &out->warnings)) != GW_OK ||
                        (rc = chain_damping_small_study_warning(&r.params, r.run.sp.rtol, out->v_imp, out->nv,
                                                                &out->warnings)) != GW_OK ||
                        (rc = chain_drag_small_study_warnings(&r.params, r.run.sp.rtol, out->v_imp, out->nv,
                                                              (int)s->n[0], (int)s->n[1], &out->warnings)) != GW_OK))
        rc = gw_err_set(err, rc, "falcon: out of memory");
    for (int i = 0; res && i < out->ncase; i++)
        gw_chain_result_free(&res[i]);
    free(res);
    if (res)
        gw_chain_resolved_free(&r);
    return rc;
}
