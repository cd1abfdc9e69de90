/*
 * chain_wave_study.c: the wave-speed and soft-wall studies as library calls
 * (gw_chain_study.h); `granwave wavespeed` (chain_wavespeed.c) and `granwave
 * softwall` (chain_softwall.c) print what these compute.
 *
 * Wave speed against v_imp (docs/physics.md 1.3), three independent ways:
 *   (a) v_tq    = 4R / T_q, T_q the slope of tau_N against N - 1 (F.4, F.6);
 *   (b) v_front = the compression front's time of flight: the first time each
 *       contact carries threshold x F_max(1) (F.13), position 2R i fitted
 *       linearly against time over contacts 2..N-2 of the longest column;
 *   (c) v_group = 2R sqrt(kappa/m), kappa = (3/2) k^(2/3) F^(1/3) (physics.md
 *       1.6) at the mean wall force F = impulse/tau_N of the longest column, and
 *       v_group/sqrt(3/2), the front speed V of the momentum balance F.27
 *       (k d^(3/2) = m v_imp V/(2R) gives c0 = sqrt(3/2) V).
 *   Each fitted as v = A v_imp^beta (log-log), A as C3 in
 *   v = C3 (k/m)^(2/5) R v_imp^beta (F.16; F.27: C3 = 2); the period as
 *   P = C2 (m/k)^(2/5) v_imp^(-1/5) (F.15).
 * Soft wall: K_c = (c_tau/4)^(5/2) (5k/4) (F.22), rigid if K > K_c; N_d the first
 *   N from which F_max stays within tol of the plateau F_max(n_max) (at least
 *   SATURATION_RUN sizes, else not reached; from the first size run when it is
 *   above 1: N_d <= that size, not located); N_d predicted ceil(tau_max(N_d)/T_q)
 *   (F.8) and its fixed point; T_q measured on a steel wall (slope over N = 1..20).
 *   With sheets: each sheet of Table 2 under the sheet law (chain_sheets.c),
 *   model against measured (h = 2.9 mm).
 * Units: SI (m, s, kg, N, N/m^1.5).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_setup_rows.h"
#include "chain_model.h"
#include "gw_locale.h"

#define SATURATION_RUN 6

/* ---- the tables of the inputs ---- */


#define OFF(f) offsetof(gw_chain_wavespeed_setup, col.f)
#define OWN(f) offsetof(gw_chain_wavespeed_setup, f)
static const gw_param ws_params[] = {
    {.name = "vimp", .type = GW_PARAM_LIST, .offset = OWN(vimp), .unit = "m/s", .min = GW_CHAIN_VIMP_MIN,
     .max = GW_CHAIN_VIMP_MAX, .def = "0.075,0.15,0.3,0.5", .rows = SPEEDS_MOST, .metavar = "V,V..",
     .help = "impact velocities, m/s [0.075,0.15,0.3,0.5]"},
    {.name = "n", .type = GW_PARAM_RANGE, .offset = OWN(n), .unit = "", .min = 1, .max = 100000, .def = "5:40",
     .metavar = "A:B", .help = "column sizes for the tau_N fit; B is the front column [5:40]"},
    /* below about 1e-6 of F_max(1) the front is read in the solitary wave's
     * precursor tail and then in the solver's tolerance: v_front moved by 0.5 %
     * from 1e-4 to 1e-10, 2 % at 1e-30, 35 % at 1e-300 (beta 0.186 +- 0.023) */
    {.name = "threshold", .type = GW_PARAM_DOUBLE, .offset = OWN(threshold), .unit = "", .min = 1e-6, .max = 1,
     .def = "0.1", .metavar = "F", .help = "front threshold as a fraction of F_max(1), in [1e-6, 1] [0.1]"},
    {.name = "jobs", .type = GW_PARAM_LONG, .offset = OWN(jobs), .unit = "", .min = 0, .max = 1024, .def = "0",
     .metavar = "J", .help = "threads [0 = one per CPU]"},
    GW_CHAIN_MODEL_ROWS
    GW_PARAM_END};
#undef OFF
#undef OWN

#define OFF(f) offsetof(gw_chain_softwall_setup, col.f)
#define OWN(f) offsetof(gw_chain_softwall_setup, f)
static const gw_param sw_params[] = {
    {.name = "n", .type = GW_PARAM_RANGE, .offset = OWN(n), .unit = "", .min = 1, .max = 100000, .def = "1:30",
     .metavar = "A:B", .help = "column sizes [1:30]"},
    {.name = "vimp", .type = GW_PARAM_DOUBLE, .offset = OWN(vimp), .unit = "m/s", .min = GW_CHAIN_VIMP_MIN,
     .max = GW_CHAIN_VIMP_MAX, .metavar = "V", .help = "impact velocity, m/s [0.2385 = h 2.9 mm]"},
    {.name = "tol", .type = GW_PARAM_DOUBLE, .offset = OWN(tol), .unit = "", .min = 0, .max = 0.5, .open_min = 1,
     .def = "0.01", .metavar = "F", .help = "plateau tolerance for N_d (fraction) [0.01]"},
    {.name = "sheets", .type = GW_PARAM_FLAG, .offset = OWN(sheets), .unit = "", .min = 0, .max = 1, .def = "0",
     .help = "the paper's sheets (Table 2) with fitted K_eff"},
    {.name = "jobs", .type = GW_PARAM_LONG, .offset = OWN(jobs), .unit = "", .min = 0, .max = 1024, .def = "0",
     .metavar = "J", .help = "threads [0 = one per CPU]"},
    GW_CHAIN_MODEL_ROWS
    GW_PARAM_END};
#undef OFF
#undef OWN

const gw_param *gw_chain_wavespeed_setup_params(void) { return ws_params; }
const gw_param *gw_chain_softwall_setup_params(void) { return sw_params; }

int gw_chain_wavespeed_setup_init(gw_chain_wavespeed_setup *s)
{
    if (!s)
        return GW_EINVAL;
    return chain_study_setup_init(s, sizeof *s, &s->col, ws_params);
}

void gw_chain_wavespeed_setup_clear(gw_chain_wavespeed_setup *s)
{
    if (!s)
        return;
    chain_study_setup_clear(s, &s->col, ws_params);
}

int gw_chain_softwall_setup_init(gw_chain_softwall_setup *s)
{
    if (!s)
        return GW_EINVAL;
    return chain_study_setup_init(s, sizeof *s, &s->col, sw_params);
}

void gw_chain_softwall_setup_clear(gw_chain_softwall_setup *s)
{
    if (!s)
        return;
    chain_study_setup_clear(s, &s->col, sw_params);
}

/* ---- the tables of the results ---- */

/* result rows of struct T (two outcome structs here) */
#define RDT(T, nm, f, un, hl) GW_RESULT_ROW(nm, GW_PARAM_DOUBLE, offsetof(T, f), un, hl)
#define RIT(T, nm, f, hl) GW_RESULT_ROW(nm, GW_PARAM_INT, offsetof(T, f), "", hl)
#define RAT(T, nm, f, un, r, c, hl) GW_RESULT_ARRAY(nm, offsetof(T, f), un, r, c, NULL, hl)
#define RFA(T, nm, f, r, hl) \
    {.name = nm, .type = GW_PARAM_FARRAY, .offset = offsetof(T, f), .unit = "", .rows = r, .help = hl}

#define W gw_chain_wavespeed_outcome
#define WFIT(k, j, nm, un, hl) RDT(W, nm, fits[k][j], un, hl)
#define WFITS(k, w, hl)                                                         \
    WFIT(k, 0, "fit_" w "_beta", "", "exponent of v = A v_imp^beta, " hl),      \
    WFIT(k, 1, "fit_" w "_beta_err", "", "its standard error"),               \
    WFIT(k, 2, "fit_" w "_prefactor", "", "A (SI units of v over v_imp^beta)"), \
    WFIT(k, 3, "fit_" w "_c3", "", "A as C3 of (F.16)")
static const gw_param ws_fields[] = {
    RIT(W, "nv", nv, "impact velocities"),
    RAT(W, "v_imp", v_imp, "m/s", "nv", NULL, "impact velocity"),
    RAT(W, "v_tq", v_tq, "m/s", "nv", NULL, "4R/T_q (F.6)"),
    RAT(W, "v_front", v_front, "m/s", "nv", NULL, "time of flight of the compression front"),
    RAT(W, "v_group", v_group, "m/s", "nv", NULL, "long-wave group speed at the mean wall force (1.6)"),
    RAT(W, "v_group_front", v_group_front, "m/s", "nv", NULL, "v_group/sqrt(3/2): the front speed of F.27"),
    RAT(W, "t_q", t_q, "s", "nv", NULL, "slope of tau_N against N - 1 (F.4)"),
    RAT(W, "mean_wall_force", mean_wall_force, "N", "nv", NULL, "impulse/tau_N of the longest column"),
    RAT(W, "period", period, "s", "nv", NULL, "mean wall-force period over N >= 10"),
    RIT(W, "nn", nn, "column sizes n_min..n_max"),
    RIT(W, "ncase", ncase, "collisions of the tau_N sweep"),
    RAT(W, "t_max", t_max, "s", "nv", "nn", "time limit of each collision [velocity, N]"),
    RAT(W, "dt_out", dt_out, "s", "nv", "nn", "its sampling interval [velocity, N]"),
    RAT(W, "dt", dt, "s", "nv", "nn", "its RK4 step (0: cvode, arkode) [velocity, N]"),
    RAT(W, "dt_max", dt_max, "s", "nv", "nn", "its largest step [velocity, N]"),
    RDT(W, "beta", beta, "", "exponent of 4R/T_q against v_imp (F.16: 1/5)"),
    RDT(W, "beta_err", beta_err, "", "its standard error"),
    RDT(W, "c3", c3, "", "C3 of the 4R/T_q fit (F.16)"),
    RDT(W, "c3_theory", c3_theory, "", "C3 of the momentum balance (F.27): 2"),
    WFITS(0, "tq", "4R/T_q"), WFITS(1, "front", "front"), WFITS(2, "group", "group"),
    WFITS(3, "group_front", "group/sqrt(3/2)"),
    RDT(W, "c2", c2, "", "C2 of P = C2 (m/k)^(2/5) v_imp^(-1/5) (F.15)"),
    RDT(W, "beta_period", beta_period, "", "exponent of P against v_imp (F.15: -1/5)"),
    RDT(W, "beta_period_err", beta_period_err, "", "its standard error"),
    RDT(W, "max_disagreement", max_disagreement, "", "largest relative difference of tq, front, group/sqrt(3/2)"),
    GW_RESULT_FLAG("fitted", offsetof(W, fitted), "1: the power-law fits over v_imp made; 0: one speed, beta, c3, the fits and "
                             "beta_period NaN (not fitted)"),
    RDT(W, "front_threshold_fraction", threshold, "", "front threshold / F_max(1)"),
    RIT(W, "n_min", n_min, "smallest column"),
    RIT(W, "n_max", n_max, "longest column (the front's)"),
    RDT(W, "wall_time_s", wall_time_s, "s", "wall-clock time"),
    RIT(W, "unfinished", unfinished, "collisions of the tau_N sweep not ended at t_max"),
    RIT(W, "n_held", n_held, "collisions held by gravity, of the tau_N sweep (counted in unfinished) and the front "
                             "columns: undecided, left out of every fit and speed"),
    {.name = "held", .type = GW_PARAM_FARRAY, .offset = offsetof(W, held), .unit = "", .rows = "nv", .cols = "nn",
     .help = "1: the tau_N sweep's collision was held by gravity (the column fell back onto the wall before it "
             "ended): undecided, left out of the fits [velocity, N]"},
    {.name = "front_held", .type = GW_PARAM_FARRAY, .offset = offsetof(W, front_held), .unit = "", .rows = "nv",
     .help = "1: the front's column was held by gravity: v_front undecided (NaN) unless the front had reached "
             "every contact it fits (2..N-2) by then [velocity]"},
    RDT(W, "gamma", gamma, "N s/m^1.5", "Kuwabara-Kono constant run (calibrated with restitution; 0: none)"),
    RDT(W, "alpha", alpha, "s/m", "Hunt-Crossley constant run (calibrated with restitution; 0: none)"),
    GW_PARAM_WARNINGS(offsetof(W, warnings)),
    GW_PARAM_END};
#undef W

#define S gw_chain_softwall_outcome
static const gw_param sw_fields[] = {
    RIT(S, "nw", nw, "walls (1, or the sheets of Table 2)"),
    RIT(S, "nn", nn, "column sizes"),
    RIT(S, "nsheet", nsheet, "sheets compared with the paper (0, 1 or nw)"),
    RDT(S, "v_imp", v_imp, "m/s", "impact velocity"),
    RDT(S, "k_c", k_c, "N/m^1.5", "critical wall coefficient K_c (F.22)"),
    RDT(S, "t_q_rigid", t_q_rigid, "s", "T_q on a steel wall (slope of tau_N, N = 1..20)"),
    RDT(S, "tol", tol, "", "plateau tolerance"),
    RIT(S, "sheet_law", sheet_law, "0 fitted, 1 hertz, 2 layer, 3 material"),
    RAT(S, "n", n, "", "nn", NULL, "column sizes N"),
    RAT(S, "kwall", kwall, "N/m^1.5", "nw", NULL, "wall coefficient K [wall]"),
    RFA(S, "rigid", rigid, "nw", "1: K > K_c [wall]"),
    RFA(S, "saturated", saturated, "nw", "1: F_max reached its plateau within the sizes [wall]"),
    RAT(S, "f_max", f_max, "N", "nw", "nn", "largest wall force [wall, N]"),
    RAT(S, "tau_max", tau_max, "s", "nw", "nn", "time of f_max [wall, N]"),
    RAT(S, "t_max", t_max, "s", "nw", "nn", "time limit of each collision [wall, N]"),
    RAT(S, "dt_out", dt_out, "s", "nw", "nn", "its sampling interval [wall, N]"),
    RAT(S, "dt", dt, "s", "nw", "nn", "its RK4 step (0: cvode, arkode) [wall, N]"),
    RAT(S, "dt_max", dt_max, "s", "nw", "nn", "its largest step [wall, N]"),
    RAT(S, "n_d", n_d, "", "nw", NULL, "saturation number N_d (NaN: not reached) [wall]"),
    RAT(S, "n_d_predicted", n_d_predicted, "", "nw", NULL, "ceil(tau_max(N_d)/T_q) (F.8) [wall]"),
    RAT(S, "n_d_fixed_point", n_d_fixed_point, "", "nw", NULL, "smallest N >= ceil(tau_max(N)/T_q) [wall]"),
    RAT(S, "f_plateau", f_plateau, "N", "nw", NULL, "F_max of the longest column [wall]"),
    RAT(S, "tau_max_at_n_d", tau_max_at_n_d, "s", "nw", NULL, "tau_max at N_d [wall]"),
    RAT(S, "n_d_at_most", n_d_at_most, "", "nw", NULL,
        "the first size run, when F_max is on its plateau from there (N_d <= it, not located: n_d NaN) [wall]"),
    {.name = "sheet_table", .type = GW_PARAM_DARRAY, .offset = offsetof(S, sheet_table), .unit = "SI",
     .rows = "nsheet", .cols = "25", .choices = GW_SOFTWALL_SHEET_COLS,
     .help = "model against measured per sheet (s, N, m, N/m^1.5; NaN: not defined) [sheet, column]"},
    {.name = "sheet_names", .type = GW_PARAM_TEXT, .offset = offsetof(S, sheet_names), .unit = "",
     .help = "the compared sheets, comma-separated"},
    {.name = "sheet_materials", .type = GW_PARAM_TEXT, .offset = offsetof(S, sheet_materials), .unit = "",
     .help = "what their constants describe, separated by semicolons"},
    RDT(S, "wall_time_s", wall_time_s, "s", "wall-clock time"),
    RIT(S, "unfinished", unfinished, "collisions still at the wall at t_max (their F_max, tau_max may not be final)"),
    RIT(S, "n_held", n_held, "collisions held by gravity (counted in unfinished): undecided, left out of N_d and "
                             "F_plateau"),
    {.name = "held", .type = GW_PARAM_FARRAY, .offset = offsetof(S, held), .unit = "", .rows = "nw", .cols = "nn",
     .help = "1: the collision was held by gravity (the column fell back onto the wall before it ended): its F_max, "
             "tau_max undecided, left out of N_d [wall, N]"},
    RIT(S, "n_held_rigid", n_held_rigid, "of the rigid wall's 20 columns of t_q_rigid, those held by gravity "
                                         "(left out of its fit; NaN with fewer than two decided)"),
    RDT(S, "gamma", gamma, "N s/m^1.5", "Kuwabara-Kono constant run (calibrated with restitution; 0: none)"),
    RDT(S, "alpha", alpha, "s/m", "Hunt-Crossley constant run (calibrated with restitution; 0: none)"),
    GW_PARAM_WARNINGS(offsetof(S, warnings)),
    GW_PARAM_END};
#undef S

const gw_param *gw_chain_wavespeed_outcome_fields(void) { return ws_fields; }
const gw_param *gw_chain_softwall_outcome_fields(void) { return sw_fields; }

void gw_chain_wavespeed_outcome_free(gw_chain_wavespeed_outcome *out)
{
    if (!out)
        return;
    free(out->v_imp); /* one block */
    free(out->held);  /* and front_held */
    free(out->warnings);
    memset(out, 0, sizeof *out);
}

void gw_chain_softwall_outcome_free(gw_chain_softwall_outcome *out)
{
    if (!out)
        return;
    free(out->n);
    free(out->rigid);
    free(out->sheet_table);
    free(out->sheet_names);
    free(out->sheet_materials);
    free(out->warnings);
    memset(out, 0, sizeof *out);
}

/* ---- wave speed ---- */

static void power_fit(const double *v, const double *s, int n, double scale, double f[4])
{
    gw_linfit lf;
    f[0] = f[1] = f[2] = f[3] = NAN;
    if (n >= 2 && gw_fit_power(v, s, n, &lf) == GW_OK) {
        f[0] = lf.c1;
        f[1] = lf.c1_err;
        f[2] = exp(lf.c0);
        f[3] = f[2] / scale;
    }
}

/* Front speed of one long column: linear fit of 2R k against front_t[k]. A
 * run that ends without the front at three contacts fails naming the
 * threshold (it failed with no reason, "no front fit at v_imp = 0.3 ()", when
 * a stiff wall's F_max(1) put the threshold above every contact's force:
 * wavespeed --kwall 1e13). A column held by gravity (*held = 1: stopped when
 * it fell back onto the wall) keeps its speed when the front had reached
 * every contact 2..N-2 by then: first arrivals, which nothing after the stop
 * changes. Otherwise the contacts it had not reached might still be reached
 * in the column's next impact: the speed is undecided (NaN), not a failure. */
static int front_speed(const gw_chain_params *p, const gw_chain_run_opts *run, double frac, double *speed,
                       int *held, gw_err *err)
{
    gw_chain *c = NULL;
    gw_chain_run_opts o = *run;
    o.front_threshold = frac * gw_chain_fmax1(p->mass, p->kwall, p->v_imp);
    /* the front times are interpolated between samples: at most tau_1/200 apart
     * whatever the study's dt-out (--dt-out 1e-3 moved v_front by 1.1 %) */
    double fine = gw_chain_tau1(p->mass, p->kwall, p->v_imp) / 200;
    o.dt_out = o.dt_out > 0 ? fmin(o.dt_out, fine) : fine;
    gw_chain_result r;
    memset(&r, 0, sizeof r);
    *speed = NAN;
    int rc = gw_chain_create(p, &c, err);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, &o, &r, err);
    *held = rc == GW_OK && chain_result_held(&r);
    int reached = 1;
    for (int k = 2; rc == GW_OK && *held && k <= p->n - 2; k++)
        reached &= isfinite(r.front_t[k]);
    if (rc == GW_OK && reached) {
        int n = p->n, m = 0;
        double *x = malloc(2 * (size_t)n * sizeof *x), *y = x ? x + n : NULL;
        for (int k = 2; x && k <= n - 2; k++)
            if (isfinite(r.front_t[k])) {
                x[m] = r.front_t[k];
                y[m] = 2 * p->radius * k;
                m++;
            }
        gw_linfit lf;
        if (!x)
            rc = gw_err_set(err, GW_ENOMEM, "out of memory");
        else if (m >= 3 && gw_fit_linear(x, y, m, &lf) == GW_OK)
            *speed = lf.c1;
        else
            rc = gw_err_set(err, GW_ESOLVER,
                            "the force of %d of contacts 2..%d of the %d-bead column reached the front "
                            "threshold %.4g N (%g of F_max(1) = %.4g N, one bead on this wall; at least 3 "
                            "are fitted): lower --threshold",
                            m, n - 2, n, o.front_threshold, frac, o.front_threshold / frac);
        free(x);
    }
    gw_chain_result_free(&r);
    gw_chain_free(c);
    return rc;
}

/* tau_N line, period, mean wall force and the three speeds at velocity iv. */
static int ws_velocity(const gw_chain_params *p, const gw_chain_run_opts *run, const gw_chain_result *rv,
                       int a, int per_v, double frac, int iv, gw_chain_wavespeed_outcome *o, gw_err *err)
{
    double *x = malloc(2 * (size_t)per_v * sizeof *x);
    if (!x)
        return gw_err_set(err, GW_ENOMEM, "wavespeed: out of memory");
    /* the decided columns only (as if the held sizes had not been run): a
     * column held by gravity stopped when it fell back onto the wall, its
     * tau_N that of that time; without held ones, the arithmetic as before */
    int np = 0, m = 0;
    o->period[iv] = 0;
    for (int j = 0; j < per_v; j++) {
        if (chain_result_held(&rv[j]))
            continue;
        x[m] = a + j - 1;
        x[per_v + m] = rv[j].tau_n;
        m++;
        if (a + j >= 10 && rv[j].n_maxima >= 2) {
            o->period[iv] += rv[j].period;
            np++;
        }
    }
    o->period[iv] = np ? o->period[iv] / np : NAN;
    gw_linfit lf = {.c1 = NAN};
    if (m >= 2)
        gw_fit_linear(x, x + per_v, m, &lf);
    free(x);
    o->t_q[iv] = lf.c1;
    o->v_tq[iv] = 4 * p->radius / lf.c1;
    /* the longest column's mean wall force, undecided when it was held */
    const gw_chain_result *rl = &rv[per_v - 1];
    o->mean_wall_force[iv] = chain_result_held(rl) ? NAN : rl->impulse / rl->tau_n;
    double kappa = 1.5 * pow(p->k, 2.0 / 3.0) * cbrt(o->mean_wall_force[iv]);
    o->v_group[iv] = 2 * p->radius * sqrt(kappa / p->mass);
    o->v_group_front[iv] = o->v_group[iv] / sqrt(1.5);
    gw_chain_params q = *p;
    q.v_imp = o->v_imp[iv];
    int rc = front_speed(&q, run, frac, &o->v_front[iv], &o->front_held[iv], err);
    if (rc != GW_OK) {
        char tmp[sizeof err->msg];
        gw_snprintf(tmp, sizeof tmp, "%s", err->msg);
        return gw_err_set(err, rc, "wavespeed: no front fit at v_imp = %g (%s)", o->v_imp[iv], tmp);
    }
    return GW_OK;
}

/* Speed iv of an estimator is left out of the fits over v_imp when the held
 * columns left it undecided (NaN with columns held at that speed): a fit of
 * the decided speeds; NaN with fewer than two. A NaN for another reason (a
 * period without maxima) still makes its fit NaN, as before. */
static int ws_skip(const gw_chain_wavespeed_outcome *o, const double *val, int iv)
{
    if (!isnan(val[iv]))
        return 0;
    for (int j = 0; j < o->nn; j++)
        if (o->held[iv * o->nn + j])
            return 1;
    return o->front_held[iv];
}

/* power_fit over the speeds not skipped (ws_skip); the number fitted in *m */
static void ws_power_fit(const gw_chain_wavespeed_outcome *o, const double *val, double scale, double f[4],
                         double *buf, int *m)
{
    *m = 0;
    for (int iv = 0; iv < o->nv; iv++)
        if (!ws_skip(o, val, iv)) {
            buf[*m] = o->v_imp[iv];
            buf[o->nv + *m] = val[iv];
            (*m)++;
        }
    power_fit(buf, buf + o->nv, *m, scale, f);
}

/* The fits over v_imp; *undecided: those that the held columns left without
 * two decided speeds (nv >= 2). GW_ENOMEM. */
static int ws_fits(const gw_chain_params *p, gw_chain_wavespeed_outcome *o, int *undecided)
{
    int nv = o->nv, m;
    const double *v = o->v_imp;
    double scale = pow(p->k / p->mass, 0.4) * p->radius, fp[4];
    double *buf = malloc(2 * (size_t)nv * sizeof *buf);
    if (!buf)
        return GW_ENOMEM;
    const double *speeds[4] = {o->v_tq, o->v_front, o->v_group, o->v_group_front};
    *undecided = 0;
    for (int i = 0; i < 4; i++) {
        ws_power_fit(o, speeds[i], scale, o->fits[i], buf, &m);
        *undecided += nv >= 2 && m < 2;
    }
    ws_power_fit(o, o->period, pow(p->mass / p->k, 0.4), fp, buf, &m);
    *undecided += nv >= 2 && m < 2;
    free(buf);
    /* one speed: no line through one point (power_fit leaves NaN); the
     * speeds at it, t_q, the period, C2 (its exponent is fixed) and the
     * estimators' disagreement stand, so the run is kept and says so */
    o->fitted = nv >= 2;
    o->beta = o->fits[0][0];
    o->beta_err = o->fits[0][1];
    o->c3 = o->fits[0][3];
    o->c3_theory = 2.0;
    o->beta_period = fp[0];
    o->beta_period_err = fp[1];
    o->c2 = o->max_disagreement = 0;
    int n2 = 0, n3 = 0;
    for (int iv = 0; iv < nv; iv++)
        n2 += !ws_skip(o, o->period, iv);
    for (int iv = 0; iv < nv; iv++) {
        if (!ws_skip(o, o->period, iv))
            o->c2 += o->period[iv] * pow(v[iv], 0.2) / pow(p->mass / p->k, 0.4) / n2;
        double s3[3] = {o->v_tq[iv], o->v_front[iv], o->v_group_front[iv]};
        if (!(isfinite(s3[0]) && isfinite(s3[1]) && isfinite(s3[2])))
            continue; /* an estimator undecided at this speed (held columns) */
        n3++;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                o->max_disagreement = fmax(o->max_disagreement, fabs(s3[i] - s3[j]) / s3[j]);
    }
    if (n2 == 0)
        o->c2 = NAN;
    if (n3 == 0)
        o->max_disagreement = NAN;
    return GW_OK;
}

int gw_chain_wavespeed_run(const gw_chain_wavespeed_setup *s, gw_progress_fn progress, void *pctx,
                           gw_chain_wavespeed_outcome *out, gw_err *err)
{
    if (!s || !out)
        return gw_err_set(err, GW_EINVAL, "gw_chain_wavespeed_run: %s is NULL", !s ? "setup" : "out");
    memset(out, 0, sizeof *out);
    int rc = chain_study_range_check(ws_params, s, &s->col, s->vimp.n, err);
    if (rc != GW_OK)
        return rc;
    long a = s->n[0], b = s->n[1];
    if (b - a < 2 || b < 8)
        return gw_err_set(err, GW_EINVAL, "n: need at least 3 sizes and a largest column of >= 8 beads");
    int nv = s->vimp.n, per_v = (int)(b - a + 1);
    if (nv < 1)
        return gw_err_set(err, GW_EINVAL, "vimp: no impact velocity");
    if ((rc = gw_chain_study_speeds_check(s->vimp.v, nv, nv, err)) != GW_OK)
        return rc;
    double *blk = calloc(8 * (size_t)nv + 4 * (size_t)nv * (size_t)per_v, sizeof *blk);
    gw_chain_result *res = calloc((size_t)nv * (size_t)per_v, sizeof *res);
    int *flags = calloc((size_t)nv * ((size_t)per_v + 1), sizeof *flags); /* held, then front_held */
    if (!blk || !res || !flags) {
        free(blk);
        free(res);
        free(flags);
        return gw_err_set(err, GW_ENOMEM, "wavespeed: out of memory");
    }
    out->held = flags;
    out->front_held = flags + (size_t)nv * (size_t)per_v;
    double **arr[] = {&out->v_imp, &out->v_tq, &out->v_front, &out->v_group, &out->v_group_front,
                      &out->t_q, &out->mean_wall_force, &out->period};
    for (int i = 0; i < 8; i++)
        *arr[i] = blk + (size_t)i * (size_t)nv;
    double **runs[] = {&out->t_max, &out->dt_out, &out->dt, &out->dt_max};
    for (int i = 0; i < 4; i++)
        *runs[i] = blk + 8 * (size_t)nv + (size_t)i * (size_t)nv * (size_t)per_v;
    out->nv = nv;
    out->nn = per_v;
    out->ncase = nv * per_v;
    memcpy(out->v_imp, s->vimp.v, (size_t)nv * sizeof *out->v_imp);
    out->threshold = s->threshold;
    out->n_min = (int)a;
    out->n_max = (int)b;
    gw_chain_setup col = s->col; /* shallow: no radii */
    col.n = b;
    col.vimp = out->v_imp[0];
    gw_chain_resolved r;
    rc = gw_chain_setup_resolve(&col, &r, err);
    if (rc == GW_OK) { /* as the JSON's settings.model */
        out->gamma = r.params.gamma;
        out->alpha = r.params.alpha;
    }
    double t0 = gw_clock_ms();
    if (rc == GW_OK)
        rc = gw_chain_sweep_n_progress(&r.params, &r.run, out->v_imp, nv, (int)a, (int)b, (int)s->jobs, progress,
                                       pctx, res, err);
    int held = 0; /* of the tau_N sweep (out->n_held counts the front columns too) */
    for (int i = 0; rc == GW_OK && i < nv * per_v; i++) {
        out->unfinished += !res[i].converged;
        out->held[i] = chain_result_held(&res[i]);
        held += out->held[i];
        out->t_max[i] = res[i].run_t_max;
        out->dt_out[i] = res[i].run_dt_out;
        out->dt[i] = res[i].run_dt;
        out->dt_max[i] = res[i].run_dt_max;
    }
    for (int iv = 0; rc == GW_OK && iv < nv; iv++)
        rc = ws_velocity(&r.params, &r.run, &res[iv * per_v], (int)a, per_v, s->threshold, iv, out, err);
    out->wall_time_s = (gw_clock_ms() - t0) / 1e3;
    int fits_undecided = 0;
    if (rc == GW_OK && ws_fits(&r.params, out, &fits_undecided) != GW_OK)
        rc = gw_err_set(err, GW_ENOMEM, "wavespeed: out of memory");
    /* the speeds at which the held columns left an estimator undecided, and
     * the fits over v_imp they left without two decided speeds */
    static const char *const why[3] = {"4R/T_q at v_imp = %s m/s (fewer than two decided columns)",
                                       "the group speeds at v_imp = %s m/s (the longest column held)",
                                       "v_front at v_imp = %s m/s (its column held before the front's end)"};
    const double *est[3] = {out->v_tq, out->v_group, out->v_front};
    char where[600] = "";
    out->n_held = held;
    for (int iv = 0; rc == GW_OK && iv < nv; iv++)
        out->n_held += out->front_held[iv];
    for (int e = 0; rc == GW_OK && e < 3; e++) {
        char list[128] = "";
        int n_list = 0;
        for (int iv = 0; iv < nv; iv++)
            if (ws_skip(out, est[e], iv))
                chain_list_speed(list, sizeof list, &n_list, out->v_imp[iv]);
        size_t len = strlen(where);
        if (n_list && len < sizeof where) {
            gw_snprintf(where + len, sizeof where - len, "%s", len ? ", " : "");
            len = strlen(where);
            gw_snprintf(where + len, sizeof where - len, why[e], list);
        }
    }
    size_t wl = strlen(where);
    if (fits_undecided && wl < sizeof where)
        gw_snprintf(where + wl, sizeof where - wl, "%sthe fits over v_imp with fewer than two decided speeds",
                    wl ? ", and " : "");
    if (rc == GW_OK &&
        ((rc = gw_chain_unfinished_warnings(out->unfinished - held, out->ncase, &out->warnings)) != GW_OK ||
         (rc = chain_held_warnings(out->n_held, out->ncase + nv, "the fits over N and over v_imp, the front and "
                                   "group speeds", where, &out->warnings)) != GW_OK))
        rc = gw_err_set(err, rc, "wavespeed: out of memory");
    for (int i = 0; i < nv * per_v; i++)
        gw_chain_result_free(&res[i]);
    free(res);
    gw_chain_resolved_free(&r);
    return rc;
}

/* ---- soft wall ---- */

typedef struct sw_result {
    int n_d;      /* -1: not saturated within the sizes run, or not located (at_most) */
    int n_d_pred; /* (F.8) at the measured N_d, -1 without N_d */
    int n_d_fix;  /* smallest N >= ceil(tau_max(N)/T_q), -1 if none or if n_lo > 1 meets it */
    int at_most;  /* n_lo > 1 when the plateau reaches back to it: N_d <= n_lo, -1 otherwise */
    double plateau;
} sw_result;

/* F_max(N) against its plateau, over the decided columns only: a column held
 * by gravity (stopped when it fell back onto the wall, its F_max that of that
 * time) counts as a size not run. The plateau is F_max of the longest decided
 * column; N_d the first size from which the decided F_max stay within tol of
 * it, counted when at least SATURATION_RUN decided sizes lie there (or the
 * plateau reaches back to N = 1). Where the plateau reaches back to a size
 * below which nothing decided was run (n_lo > 1, or a held column), N_d is at
 * most that size, not located. Without held columns, the rule and arithmetic
 * as before. */
static sw_result analyse(const gw_chain_result *r, int n_lo, int n_hi, double tol, double t_q)
{
    sw_result s = {-1, -1, -1, -1, NAN};
    int top = n_hi;
    while (top >= n_lo && chain_result_held(&r[top - n_lo]))
        top--;
    if (top < n_lo) /* every column held: no plateau */
        return s;
    s.plateau = r[top - n_lo].f_max;
    int low = top, on = 0, n = top;
    for (; n >= n_lo; n--) {
        if (chain_result_held(&r[n - n_lo]) || fabs(r[n - n_lo].f_max - s.plateau) > tol * s.plateau)
            break;
        low = n;
        on++;
    }
    /* A plateau that reaches back to n_lo = 1 is N_d = 1 (no column is shorter);
     * one that reaches back to n_lo > 1, or to a held column, began there or
     * before, among sizes not run or not decided: N_d <= that size is all they
     * tell (softwall --kwall 1e9 --n 10:30 said N_d = 10, and --n 1:30 finds 7) */
    const int unknown_below = (n < n_lo && n_lo > 1) || (n >= n_lo && chain_result_held(&r[n - n_lo]));
    if (low == 1)
        s.n_d = 1;
    else if (on < SATURATION_RUN)
        s.n_d = -1;
    else if (unknown_below)
        s.at_most = low;
    else
        s.n_d = low;
    if (!isfinite(t_q)) /* the rigid wall's T_q undecided (its columns held): no F.8 */
        return s;
    if (s.n_d > 0)
        s.n_d_pred = (int)ceil(r[s.n_d - n_lo].tau_max / t_q - 1e-9);
    int gap = 0; /* a held column below: the smallest N could be that one */
    for (int m = n_lo; m <= n_hi; m++) {
        if (chain_result_held(&r[m - n_lo])) {
            gap = 1;
            continue;
        }
        if (m >= (int)ceil(r[m - n_lo].tau_max / t_q - 1e-9)) {
            s.n_d_fix = !gap && (m > n_lo || n_lo == 1) ? m : -1; /* at n_lo > 1: smallest among those run only */
            break;
        }
    }
    return s;
}

/* Rigid-wall T_q of the beads at v: slope of tau_N over N = 1..20, over the
 * columns not held by gravity (*held of the 20; NaN with fewer than two). */
static int measure_tq(const gw_chain_resolved *rs, double v, int jobs, double *t_q, int *held, gw_err *err)
{
    gw_chain_params p = rs->params;
    const gw_material *steel = gw_material_find("steel");
    p.kwall = gw_hertz_coefficient(p.radius, steel, INFINITY, steel);
    memset(&p.wall, 0, sizeof p.wall); /* the bare sensor */
    gw_chain_result r[20];
    int rc = gw_chain_sweep_n_progress(&p, &rs->run, &v, 1, 1, 20, jobs, NULL, NULL, r, err);
    double x[20], y[20];
    int m = 0;
    *held = 0;
    for (int i = 0; i < 20; i++) {
        if (rc == GW_OK && chain_result_held(&r[i])) {
            (*held)++;
        } else {
            x[m] = i;
            y[m] = r[i].tau_n;
            m++;
        }
        gw_chain_result_free(&r[i]);
    }
    gw_linfit lf;
    if (rc == GW_OK && m >= 2 && gw_fit_linear(x, y, m, &lf) == GW_OK)
        *t_q = lf.c1;
    return rc;
}

/* One sheet's row of the sheet table: model against measured (times in s). */
static void sheet_row(const gw_sheet *sh, const sw_result *sr, const gw_chain_result *r, int n_lo, int n_hi,
                      double t_q, double kwall, const gw_layer_law *layer, double *row)
{
    /* N = 1 and the measured N_d: NaN where that column was held (undecided) */
    int nm = (int)sh->n_d, in = nm >= n_lo && nm <= n_hi && !chain_result_held(&r[nm - n_lo]), k = 0;
    const int one = n_lo == 1 && !chain_result_held(&r[0]);
    row[k++] = sh->thickness > 0 ? sh->thickness : NAN;
    row[k++] = sr->n_d > 0 ? sr->n_d : NAN;
    row[k++] = sh->n_d;
    row[k++] = sh->n_d_err;
    row[k++] = sr->n_d_pred > 0 ? sr->n_d_pred : NAN;
    row[k++] = one ? r[0].tau_max : NAN;
    row[k++] = sh->tau_max1_us * 1e-6;
    row[k++] = sr->n_d > 0 ? r[sr->n_d - n_lo].tau_max : NAN;
    row[k++] = sh->tau_max_nd_us * 1e-6;
    row[k++] = sh->tau_max_nd_err_us * 1e-6;
    /* tolerance-free comparisons at the measured N_d */
    row[k++] = in ? r[nm - n_lo].tau_max : NAN;
    row[k++] = in ? r[nm - n_lo].f_max / sr->plateau : NAN;
    static const double tols[] = {0.01, 0.02, 0.05, 0.1};
    for (int i = 0; i < 4; i++) {
        sw_result x = analyse(r, n_lo, n_hi, tols[i], t_q);
        row[k++] = x.n_d > 0 ? x.n_d : NAN;
        row[k++] = x.n_d > 0 ? r[x.n_d - n_lo].tau_max : NAN;
    }
    row[k++] = one ? r[0].f_max : NAN;
    row[k++] = sr->plateau;
    row[k++] = one ? r[0].eps_eff : NAN;
    row[k++] = kwall;
    /* contact radius over thickness at the single bead's peak force */
    row[k++] = layer && one ? gw_layer_law_contact_radius(layer, gw_layer_law_overlap(layer, r[0].f_max)) /
                                        gw_layer_law_thickness(layer)
                                  : NAN;
}

static int sw_alloc(gw_chain_softwall_outcome *o, int nw, int nn, int nsheet, gw_err *err)
{
    o->nw = nw;
    o->nn = nn;
    o->ncase = nw * nn;
    o->nsheet = nsheet;
    o->n = calloc((size_t)nn + (size_t)nw * (7 + 6 * (size_t)nn), sizeof *o->n);
    o->rigid = calloc(2 * (size_t)nw + (size_t)o->ncase, sizeof *o->rigid); /* rigid, saturated, held */
    o->sheet_table = calloc((size_t)nsheet * GW_SOFTWALL_NSHEET_COLS + 1, sizeof *o->sheet_table);
    o->sheet_names = calloc((size_t)nsheet * 16 + 1, 1);
    o->sheet_materials = calloc((size_t)nsheet * GW_SOFTWALL_LABEL_MAX + 1, 1);
    if (!o->n || !o->rigid || !o->sheet_table || !o->sheet_names || !o->sheet_materials)
        return gw_err_set(err, GW_ENOMEM, "softwall: out of memory");
    o->saturated = o->rigid + nw;
    o->held = o->rigid + 2 * (size_t)nw;
    double *b = o->n + nn;
    double **per_w[] = {&o->kwall, &o->n_d, &o->n_d_predicted, &o->n_d_fixed_point, &o->f_plateau,
                        &o->tau_max_at_n_d, &o->n_d_at_most};
    for (int i = 0; i < 7; i++, b += nw)
        *per_w[i] = b;
    double **per_case[] = {&o->f_max, &o->tau_max, &o->t_max, &o->dt_out, &o->dt, &o->dt_max};
    for (int i = 0; i < 6; i++, b += o->ncase)
        *per_case[i] = b;
    return GW_OK;
}

/* The walls' results into out (after every wall has run). */
static void sw_fill(const gw_chain_softwall_setup *s, const gw_chain_resolved *rs, const gw_chain_result *res,
                    const sw_result *sr, gw_layer_law *const *lay, gw_chain_softwall_outcome *o)
{
    int a = (int)s->n[0], b = (int)s->n[1], nn = o->nn;
    char name[32];
    for (int k = 0; k < nn; k++)
        o->n[k] = a + k;
    for (int w = 0; w < o->nw; w++) {
        const gw_chain_result *rw = res + (size_t)w * nn;
        for (int k = 0; k < nn; k++) {
            o->f_max[w * nn + k] = rw[k].f_max;
            o->tau_max[w * nn + k] = rw[k].tau_max;
            o->t_max[w * nn + k] = rw[k].run_t_max;
            o->dt_out[w * nn + k] = rw[k].run_dt_out;
            o->dt[w * nn + k] = rw[k].run_dt;
            o->dt_max[w * nn + k] = rw[k].run_dt_max;
            o->held[w * nn + k] = chain_result_held(&rw[k]);
        }
        o->rigid[w] = o->kwall[w] > o->k_c;
        o->saturated[w] = sr[w].n_d > 0 || sr[w].at_most > 0;
        o->n_d_at_most[w] = sr[w].at_most > 0 ? sr[w].at_most : NAN;
        o->n_d[w] = sr[w].n_d > 0 ? sr[w].n_d : NAN;
        o->n_d_predicted[w] = sr[w].n_d_pred > 0 ? sr[w].n_d_pred : NAN;
        o->n_d_fixed_point[w] = sr[w].n_d_fix > 0 ? sr[w].n_d_fix : NAN;
        o->f_plateau[w] = sr[w].plateau;
        o->tau_max_at_n_d[w] = sr[w].n_d > 0 ? rw[sr[w].n_d - a].tau_max : NAN;
    }
    /* sheet none under a law other than fitted is the Hertz half-space of the
     * sensor's material: one label for the run, whichever wall it is */
    char wall[32], bare[GW_SOFTWALL_LABEL_MAX];
    if (gw_param_format(gw_param_find(sw_params, "wall-material"), s, wall, sizeof wall) <= 0)
        gw_snprintf(wall, sizeof wall, "steel");
    gw_snprintf(bare, sizeof bare, "no sheet (%s sensor)", wall);
    for (int w = 0; w < o->nsheet; w++) {
        const gw_sheet *sh = s->sheets ? gw_sheet_get(w)
                                       : (gw_param_format(gw_param_find(sw_params, "sheet"), s, name, sizeof name) > 0
                                              ? gw_sheet_find(name)
                                              : NULL);
        if (!sh)
            continue;
        sheet_row(sh, &sr[w], res + (size_t)w * nn, a, b, o->t_q_rigid, o->kwall[w], s->sheets ? lay[w] : rs->layer,
                  o->sheet_table + (size_t)w * GW_SOFTWALL_NSHEET_COLS);
        size_t ln = strlen(o->sheet_names), lm = strlen(o->sheet_materials);
        gw_snprintf(o->sheet_names + ln, 16, "%s%s", w ? "," : "", sh->name);
        gw_snprintf(o->sheet_materials + lm, GW_SOFTWALL_LABEL_MAX, "%s%s", w ? ";" : "",
                    !(sh->thickness > 0) && rs->law != GW_SHEET_FITTED ? bare : sh->material);
    }
}

/* The held columns' warning: those of the walls, and the rigid wall's of T_q
 * (counted apart: the study's total is its walls' columns; the rigid wall's
 * alone when no wall column was held). */
static int sw_held_warnings(const gw_chain_softwall_outcome *o, int held, const char *where, char **list)
{
    char left[160];
    if (held == 0)
        return chain_held_warnings(o->n_held_rigid, 20, "the rigid wall's T_q and F.8's predictions", where, list);
    if (o->n_held_rigid)
        gw_snprintf(left, sizeof left, "N_d, F_plateau and the rigid wall's T_q (%d of whose 20 columns were held "
                    "too)", o->n_held_rigid);
    else
        gw_snprintf(left, sizeof left, "N_d and F_plateau");
    return chain_held_warnings(held, o->ncase, left, where, list);
}

/* What the held columns leave undecided, for their warning: N_d at the walls
 * with held columns where the decided ones do not locate it, and T_q when
 * fewer than two of the rigid wall's 20 columns were decided ("" when nothing). */
static int sw_held_where(const gw_chain_softwall_outcome *o, int sheets, char *buf, size_t size)
{
    char walls[200] = "";
    int nu = 0;
    for (int w = 0; w < o->nw; w++) {
        int held = 0;
        for (int k = 0; k < o->nn; k++)
            held += o->held[w * o->nn + k];
        if (held && !o->saturated[w] && sheets) {
            size_t len = strlen(walls);
            if (len + 20 < sizeof walls)
                gw_snprintf(walls + len, sizeof walls - len, "%s%s", nu ? ", " : "", gw_sheet_get(w)->name);
            nu++;
        } else if (held && !o->saturated[w]) {
            nu++;
        }
    }
    gw_snprintf(buf, size, "%s%s%s%s%s", nu ? "N_d" : "", nu && sheets ? " (sheets " : "", walls,
                nu && sheets ? ")" : "", nu ? " (too few decided sizes on the plateau)" : "");
    if (!isfinite(o->t_q_rigid) && o->n_held_rigid > 0) {
        size_t len = strlen(buf);
        gw_snprintf(buf + len, size - len, "%sthe rigid wall's T_q and F.8 (%d of its 20 columns held)",
                    nu ? ", " : "", o->n_held_rigid);
    }
    return GW_OK;
}

int gw_chain_softwall_sheet_material(const gw_chain_softwall_outcome *o, int w, char *buf, size_t size)
{
    if (!buf || size == 0)
        return GW_EINVAL;
    buf[0] = '\0';
    if (!o || !o->sheet_materials || w < 0 || w >= o->nsheet)
        return GW_EINVAL;
    const char *m = o->sheet_materials;
    for (int i = 0; i < w; i++) {
        m = strchr(m, ';');
        if (!m)
            return GW_EINVAL; /* fewer labels than sheets: a sheet left out */
        m++;
    }
    size_t len = strcspn(m, ";");
    if (len >= size)
        return GW_EINVAL;
    memcpy(buf, m, len);
    buf[len] = '\0';
    return GW_OK;
}

int gw_chain_softwall_run(const gw_chain_softwall_setup *s, gw_progress_fn progress, void *pctx,
                          gw_chain_softwall_outcome *out, gw_err *err)
{
    if (!s || !out)
        return gw_err_set(err, GW_EINVAL, "gw_chain_softwall_run: %s is NULL", !s ? "setup" : "out");
    memset(out, 0, sizeof *out);
    int rc = chain_study_range_check(sw_params, s, &s->col, s->sheets ? gw_sheet_count() : 1, err);
    if (rc != GW_OK)
        return rc;
    if (s->sheets && (!isnan(s->col.kwall) || s->col.sheet >= 0))
        return gw_err_set(err, GW_EINVAL, "%s: has no effect with sheets (each sheet of Table 2 is its own wall)",
                          s->col.sheet >= 0 ? "sheet" : "kwall");
    /* the wall material, given at steel too (an optional row), where the wall
     * is a stiffness (kwall, 1e9 by default) or each sheet of Table 2 with its
     * fitted K_eff; under the laws hertz, layer and material the sheet none
     * among them is the Hertz half-space of the sensor's material
     * (gw_sheet_apply), which the wall material sets */
    const int fitted = s->col.sheet_law < 0 || s->col.sheet_law == GW_SHEET_FITTED;
    if (gw_param_given(gw_param_find(sw_params, "wall-material"), s) &&
        ((s->sheets && fitted) || (!s->sheets && s->col.sheet < 0)))
        return gw_err_set(err, GW_EINVAL, "wall-material: has no effect %s",
                          s->sheets ? "with sheets under sheet-law fitted (each sheet of Table 2 is its own wall, "
                                      "sheet none too: its fitted K_eff)"
                                    : "(the wall is kwall, default 1e9 N/m^1.5, or sheets)");
    long a = s->n[0], b = s->n[1];
    if (b - a < 2)
        return gw_err_set(err, GW_EINVAL, "n: need at least 3 column sizes");
    double vimp = isnan(s->vimp) ? sqrt(2 * GW_CHAIN_G_EARTH * 2.9e-3) : s->vimp;
    gw_chain_setup col = s->col; /* shallow: no radii */
    col.n = a;
    col.vimp = vimp;
    col.sheets = s->sheets;
    if (isnan(col.kwall) && !s->sheets && col.sheet < 0)
        col.kwall = 1e9; /* the soft wall of the command */
    int nw = s->sheets ? gw_sheet_count() : 1, per = (int)(b - a + 1);
    int held = 0; /* of the unfinished: stopped as held by gravity (chain_held_pending) */
    gw_chain_resolved rs;
    rc = gw_chain_setup_resolve(&col, &rs, err);
    if (rc != GW_OK) {
        gw_chain_resolved_free(&rs);
        return rc;
    }
    if ((rc = sw_alloc(out, nw, per, s->sheets ? nw : s->col.sheet >= 0, err)) != GW_OK) {
        gw_chain_resolved_free(&rs);
        return rc;
    }
    out->v_imp = vimp;
    out->tol = s->tol;
    out->sheet_law = (int)rs.law;
    out->k_c = gw_chain_kc(rs.params.k);
    out->gamma = rs.params.gamma; /* as the JSON's settings.model */
    out->alpha = rs.params.alpha;
    out->t_q_rigid = NAN;
    gw_chain_result *res = calloc((size_t)nw * (size_t)per, sizeof *res);
    sw_result *sr = calloc((size_t)nw, sizeof *sr);
    gw_layer_law **lay = calloc((size_t)nw, sizeof *lay);
    double t0 = gw_clock_ms();
    rc = res && sr && lay ? measure_tq(&rs, vimp, (int)s->jobs, &out->t_q_rigid, &out->n_held_rigid, err)
                          : gw_err_set(err, GW_ENOMEM, "softwall: out of memory");
    char name[32];
    const gw_material *bm = gw_material_find(
        gw_param_format(gw_param_find(sw_params, "material"), s, name, sizeof name) > 0 ? name : "steel");
    const gw_material *wm = gw_material_find(
        gw_param_format(gw_param_find(sw_params, "wall-material"), s, name, sizeof name) > 0 ? name : "steel");
    for (int w = 0; rc == GW_OK && w < nw; w++) {
        gw_chain_params q = rs.params;
        if (s->sheets && (rc = gw_sheet_apply(gw_sheet_get(w), rs.law, -1, -1, bm, wm, &q, &lay[w], err)) != GW_OK)
            break;
        out->kwall[w] = q.kwall;
        rc = gw_chain_sweep_n_progress(&q, &rs.run, &vimp, 1, (int)a, (int)b, (int)s->jobs, NULL, NULL,
                                       res + (size_t)w * per, err);
        if (rc == GW_OK)
            sr[w] = analyse(res + (size_t)w * per, (int)a, (int)b, s->tol, out->t_q_rigid);
        for (int i = 0; rc == GW_OK && i < per; i++) {
            out->unfinished += !res[(size_t)w * per + i].wall_done; /* F_max, tau_max: the wall's */
            held += chain_result_held(&res[(size_t)w * per + i]);
        }
        if (rc == GW_OK && progress && progress(pctx, w + 1, nw))
            rc = gw_err_set(err, GW_ECANCELED, "softwall: stopped by the progress callback");
    }
    out->wall_time_s = (gw_clock_ms() - t0) / 1e3;
    out->n_held = held;
    if (rc == GW_OK)
        sw_fill(s, &rs, res, sr, lay, out);
    char where[300] = "";
    if (rc == GW_OK)
        rc = sw_held_where(out, s->sheets, where, sizeof where);
    if (rc == GW_OK &&
        ((rc = gw_chain_softwall_warnings(out->unfinished - held, out->ncase, &out->warnings)) != GW_OK ||
         (rc = sw_held_warnings(out, held, where, &out->warnings)) != GW_OK))
        rc = gw_err_set(err, rc, "softwall: out of memory");
    for (int i = 0; res && i < nw * per; i++)
        gw_chain_result_free(&res[i]);
    free(res);
    free(sr);
    for (int w = 0; lay && w < nw; w++)
        gw_layer_law_free(lay[w]);
    free(lay);
    gw_chain_resolved_free(&rs);
    return rc;
}
