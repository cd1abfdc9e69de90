/*
 * chain_drop_study.c: the whole drop of `granwave drop` as a library call
 * (gw_chain_study.h); app/chain/chain_drop_cmd.c prints what this computes, chain_drop.c
 * integrates it. docs/drop.md holds the definitions.
 *
 * The column of N beads (physics.md 1.1, (F.11)) is released from rest with
 * bead 1 at a height h (m) above the sensor, under gravity g (m/s^2) toward it:
 *     m_i x_i'' = F_i - F_(i-1) + m_i g,   F_(-1) = K x_1^(3/2) (+ damping),
 * followed from the first contact, t = 0, where every bead moves at
 *     v_imp = sqrt(2 g h)   after a fall of   t_fall = sqrt(2 h / g),
 * up to t_max (s). Damping and its calibration to a one-bead restitution at
 * v_imp are those of `granwave chain` (physics.md 1.5). With block the column is
 * one rigid body of mass sum m_i with bead 1's contact law. The peak threshold
 * defaults to 1 % of the single-bead F_max(1) = C1 m^(3/5) v_imp^(6/5) K^(2/5)
 * (F.13). The energy ledger E = kinetic + (2/5) k d^(5/2) per contact
 * - sum m_i g x_i + dissipated is checked against E(0) = N m g h (touching beads).
 * Units: SI (m, s, kg, N, J).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_setup_rows.h"
#include "chain_model.h"
#include "chain_wall.h"
#include "gw_locale.h"
#include "gw_number_impl.h"

/* ---- the table of the inputs: the drop's rows, then the column's with the
 * drop's gravity, t-max and dt-out ---- */

#define OFF(f) offsetof(gw_chain_drop_setup, col.f)
#define OWN(f) offsetof(gw_chain_drop_setup, f)

static const gw_param drop_params[] = {
    ROW("n", GW_PARAM_LONG, n, "", 1, 100000, 0, "1", "N", "number of beads [1]"),
    {.name = "height", .type = GW_PARAM_DOUBLE, .offset = OWN(height), .unit = "m", .min = GW_CHAIN_DROP_H_MIN,
     .max = GW_CHAIN_DROP_H_MAX, .def = "5.1e-3", .metavar = "H",
     .help = "fall of bead 1 to the sensor, m, in [1e-6, 1] [5.1e-3]"},
    {.name = "gap", .type = GW_PARAM_LIST, .offset = OWN(gap), .unit = "m", .min = 0, .max = GW_CHAIN_DROP_GAP_MAX,
     .rows = "n", .metavar = "G,G..", /* n - 1 pairs at most (gw_chain_drop_setup_gaps checks the count) */
     .help = "initial gap between neighbouring beads, m, in [0, 0.1]: one value for every pair or n-1 values, "
             "bead 1 first [0 = touching]"},
    {.name = "block", .type = GW_PARAM_FLAG, .offset = OWN(block), .unit = "", .min = 0, .max = 1, .def = "0",
     .help = "drop one rigid block instead: a single bead of the column's total mass with bead 1's contact law"},
    {.name = "peak-threshold", .type = GW_PARAM_DOUBLE, .offset = OWN(peak_threshold), .unit = "N", .min = 0,
     .max = 1e9, .metavar = "F",
     .help = "smallest peak force, N, in [0, 1e9] [1 % of F_max(1) (F.13) at v_imp; 0 = every maximum]"},
    GW_CHAIN_MATERIAL_ROWS
    ROW("gravity", GW_PARAM_DOUBLE, gravity, "m/s^2", GW_CHAIN_DROP_G_MIN, 1e4, 0, "9.81", "G",
        "gravity toward the sensor, m/s^2, in [1e-3, 1e4] [9.81]"),
    GW_CHAIN_SOLVER_ROWS
    ROW("t-max", GW_PARAM_DOUBLE, t_max, "s", GW_CHAIN_DROP_T_MIN, GW_CHAIN_DROP_T_MAX, 0, "10e-3", "T",
        "time followed after the first contact, s, in [1e-6, 1] [10e-3, the paper's Fig. 12]"),
    /* [t-max/1e7, t-max] over t-max's row [1e-6, 1], or 0: the row said [0, 1]
     * while (0, 1e-13) is below t-max/1e7 at every t-max (test_cli_property) */
    {.name = "dt-out", .type = GW_PARAM_DOUBLE, .offset = OFF(dt_out), .unit = "s", .min = 1e-6 * 1e-7,
     .max = GW_CHAIN_DROP_T_MAX, .or_zero = 1, .def = "0", .metavar = "DT",
     .help = "sampling interval of the signal, s, in [t-max/1e7, t-max] [0 = 1e-6]; peaks and impacts are "
             "located by events, not read from the samples (long runs are chaotic: docs/drop.md)"},
    GW_CHAIN_ENERGY_ROW
    GW_CHAIN_WALL_ROWS
    ROW("trace", GW_PARAM_FLAG, trace, "", 0, 1, 0, "0", NULL,
        "library: keep the bead series x, v as well (the signal t, f_wall is always kept) [0]"),
    GW_PARAM_END};
#undef OFF
#undef OWN

/* ---- the table of the results ---- */

#define O gw_chain_drop_outcome
#define OFF(f) offsetof(O, f)
#define RIA(nm, f, r, c, hl) \
    {.name = nm, .type = GW_PARAM_IARRAY, .offset = offsetof(O, f), .unit = "", .rows = r, .cols = c, .help = hl}

static const gw_param drop_fields[] = {
    RI("n", n, "bodies simulated (1 with block)"),
    RI("n_column", n_column, "beads of the column"),
    RF("block", block, "1: one rigid block of the column's mass"),
    RD("height", height, "m", "fall of bead 1 to the sensor"),
    RD("gravity", gravity, "m/s^2", "gravity toward the sensor"),
    RD("v_imp", v_imp, "m/s", "sqrt(2 g h): every bead's velocity at the first contact"),
    RD("t_fall", t_fall, "s", "sqrt(2 h / g): the fall before t = 0"),
    RD("t_max", t_max, "s", "time followed after the first contact"),
    RD("dt_out", dt_out, "s", "sampling of the signal"),
    RD("dt", dt, "s", "the step the run used: RK4's (at most dt_max and dt_out), cvode's and arkode's first (0: their own)"),
    RD("dt_given", r.run_dt_given, "s", "the dt given (0: none); dt differs when it was above dt_max or rk4's dt_out"),
    RD("dt_max", dt_max, "s", "the largest step the run allowed (given, or a quarter of the shortest contact)"),
    RD("rtol", r.first.run_rtol, "", "the relative tolerance the run used (cvode, arkode; NaN under rk4: no error test)"),
    RD("atol", r.first.run_atol, "", "the absolute tolerance the run used (cvode, arkode; NaN under rk4: no error test)"),
    RD("peak_threshold", peak_threshold, "N", "smallest peak force counted"),
    RD("mass", mass, "kg", "bead mass (bead 1 with radii; the block's with block)"),
    RD("k", k, "N/m^1.5", "bead-bead Hertz coefficient"),
    RD("kwall", kwall, "N/m^1.5", "bead-sensor Hertz coefficient K"),
    RD("radius", radius, "m", "bead radius"),
    RD("gamma", gamma, "N s/m^1.5", "Kuwabara-Kono constant (calibrated with restitution)"),
    RD("alpha", alpha, "s/m", "Hunt-Crossley constant (calibrated with restitution)"),
    RI("n_gaps", n_gaps, "gaps (n - 1, or 0: touching)"),
    RA("gaps", gaps, "m", "n_gaps", NULL, "initial gap between beads i and i+1"),
    RI("n_impacts", r.n_impacts, "contact episodes whose largest peak reaches the threshold"),
    RI("n_contact_episodes", r.n_episodes, "every contact episode of bead 1 with the sensor"),
    RI("n_peaks", r.n_peaks, "located wall-force maxima at or above the threshold"),
    RD("f_max", r.f_max, "N", "largest peak of the run"),
    RD("t_fmax", r.t_fmax, "s", "its time"),
    RI("impact_rises", impact_rises, "impacts whose peak exceeds the previous impact's by more than 1e-6 of it"),
    RF("impacts_monotone", impacts_monotone, "1: no impact_rises"),
    {.name = "wall_peaks", .type = GW_PARAM_DARRAY, .offset = offsetof(O, wall_peaks), .unit = "s, N",
     .rows = "n_peaks", .cols = "2", .choices = "t,f", .help = "every peak: time (s) and force (N) [peak, column]"},
    RIA("peak_impact", peak_impact, "n_peaks", NULL, "the impact (index into impacts) of each peak"),
    RIA("peak_cluster", peak_cluster, "n_peaks", NULL, "beads joined to the sensor by closed contacts at each peak"),
    RIA("peak_contacts", peak_contacts, "n_peaks", "n",
        "1 = contact closed at the peak: the sensor first, then beads k, k+1 [peak, contact]"),
    {.name = "impacts", .type = GW_PARAM_DARRAY, .offset = offsetof(O, impacts), .unit = "SI",
     .rows = "n_impacts", .cols = "10", .choices = GW_DROP_IMPACT_COLS,
     .help = "per impact: t_start, t_end (NaN: in contact at t_max), f_max, t_fmax (s, N), v_in, v_out (m/s, "
             "toward the sensor > 0), n_peaks, cluster, located, chatter (its F_max's relative change in the "
             "chatter's rerun, 1: absent from it; NaN: not run again) [impact, column]"},
    RF("cut_first_collision", r.first_cut, "1: t_max came before the first collision's end (its results are those at t_max)"),
    RF("open_at_t_max", r.open_at_t_max, "1: bead 1 still on the sensor at t_max (the last episode open)"),
    RI("n_first", n_first, "entries of the first collision's arrays"),
    RD("first_f_max", r.first.f_max, "N", "first collision as `granwave chain`: largest wall force"),
    RD("first_tau_max", r.first.tau_max, "s", "first collision: time of f_max"),
    RD("first_tau_n", r.first.tau_n, "s", "first collision: bead 1's departure from the sensor"),
    RD("first_period", r.first.period, "s", "first collision: mean spacing of wall-force maxima"),
    RI("first_n_maxima", r.first.n_maxima, "first collision: wall-force maxima"),
    RD("first_energy_error", r.first.energy_error, "", "first collision: max relative energy error"),
    RA("first_final_velocities", r.first.final_v, "m/s", "n_first", NULL, "first collision: velocities at its end"),
    RA("first_detach_times", r.first.detach_t, "s", "n_first", NULL, "first collision: last opening per bead"),
    RA("first_velocities_at_tau_n", r.first.v_tau_n, "m/s", "n_first", NULL, "first collision: velocities at tau_n"),
    RI("first_n_s", r.first.n_s, "first collision: beads leaving from the top before the cluster"),
    RI("first_cluster", r.first.cluster, "first collision: beads in contact with bead 1 when it left"),
    RD("first_e_rel_over_e_k", r.first.e_rel_over_e_k, "", "first collision: E_rel/E_K at tau_n (F.20)"),
    RD("first_eps_eff", r.first.eps_eff, "", "first collision: momentum restitution (F.7)"),
    RD("first_eps_col", r.first.eps_col, "", "first collision: energy restitution (F.30)"),
    RI("first_wall_contacts", r.first.wall_contacts, "first collision: separate wall contacts"),
    RD("first_overlap_max_rel", r.first.overlap_max_rel, "", "first collision: largest contact overlap, in bead radii"),
    RF("first_converged", r.first.converged, "first collision: 1 = ended at the chain's end"),
    RF("first_wall_done", r.first.wall_done,
       "first collision: 1 = bead 1 off the wall and separating at its end, or off it at the cut half way through its flight"),
    {.name = "first_wall_pending", .type = GW_PARAM_TEXT, .offset = OFF(r.first.wall_pending), .unit = "",
     .help = "first collision: first_wall_done 0: what kept the wall's contact going at its end (None: done)"},
    RD("first_t_end", r.first.t_end, "s", "first collision: its end"),
    RL("first_events", r.first.n_events, "first collision: contact events"),
    RL("first_missed_events", r.first.missed_events, "first collision: contact changes found from the state"),
    RL("first_steps", r.first.stats.steps, "first collision: solver steps"),
    RL("first_rhs_evals", r.first.stats.rhs_evals, "first collision: right-hand side evaluations"),
    RL("first_jac_evals", r.first.stats.jac_evals, "first collision: Jacobian evaluations"),
    RL("first_restarts", r.first.stats.restarts, "first collision: solver restarts"),
    RD("first_chatter", first_chatter, "", "first collision: bead 1's chatter on a sensor body, as chain's (NaN: not checked, cut at t_max)"),
    RD("chatter", chatter, "", "bead 1's chatter on a sensor body over the drop: 0 none, the impacts' largest relative F_max change a rerun measured, -1 not run again (costly), -2 the rerun failed"),
    RD("energy_error", r.energy_error, "", "max |E(t) - E(0)| / E(0) over every sample and event"),
    RD("e0", r.e0, "J", "E(0): N m g h for touching beads"),
    RD("energy_kinetic", e_kinetic, "J", "kinetic energy at t_end"),
    RD("energy_elastic", e_elastic, "J", "elastic energy at t_end"),
    RD("energy_gravity", e_gravity, "J", "gravity potential -sum m g x at t_end"),
    RD("energy_dissipated", e_dissipated, "J", "energy dissipated by t_end"),
    RD("energy_total", e_total, "J", "their sum at t_end"),
    RD("t_end", r.t_end, "s", "end of the run (t_max unless stopped)"),
    RL("events", r.n_events, "events located"),
    RL("missed_events", r.missed_events, "contact changes found from the state, not a root"),
    RL("steps", r.stats.steps, "solver steps"),
    RL("rhs_evals", r.stats.rhs_evals, "right-hand side evaluations"),
    RL("restarts", r.stats.restarts, "solver restarts"),
    RD("wall_time_ms", wall_time_ms, "ms", "wall-clock time of the run"),
    RI("trace_len", trace_len, "samples of the signal"),
    RA("t", t, "s", "trace_len", NULL, "sample times (every dt_out and at every event)"),
    RA("f_wall", f_wall, "N", "trace_len", NULL, "the sensor signal F(t)"),
    RA("x", x, "m", "trace_len", "n", "bead displacements toward the sensor (trace = 1)"),
    RA("v", v, "m/s", "trace_len", "n", "bead velocities toward the sensor (trace = 1)"),
    RF("canceled", canceled, "1: stopped by the progress callback (at t_end, or in the first collision's own run)"),
    GW_PARAM_WARNINGS(OFF(warnings)),
    GW_PARAM_END};
#undef OFF
#undef O

const gw_param *gw_chain_drop_setup_params(void) { return drop_params; }
const gw_param *gw_chain_drop_outcome_fields(void) { return drop_fields; }

int gw_chain_drop_setup_init(gw_chain_drop_setup *s)
{
    if (!s)
        return GW_EINVAL;
    return chain_study_setup_init(s, sizeof *s, &s->col, drop_params);
}

void gw_chain_drop_setup_clear(gw_chain_drop_setup *s)
{
    if (!s)
        return;
    chain_study_setup_clear(s, &s->col, drop_params);
}

void gw_chain_drop_outcome_free(gw_chain_drop_outcome *out)
{
    if (!out)
        return;
    gw_chain_drop_result_free(&out->r);
    free(out->gaps);
    free(out->wall_peaks);
    free(out->peak_impact);
    free(out->peak_cluster);
    free(out->peak_contacts);
    free(out->impacts);
    free(out->t);
    free(out->f_wall);
    free(out->x);
    free(out->v);
    free(out->warnings);
    memset(out, 0, sizeof *out);
}

int gw_chain_drop_setup_gaps(const gw_chain_drop_setup *s, double **gaps, gw_err *err)
{
    if (!s || !gaps)
        return gw_err_set(err, GW_EINVAL, "gw_chain_drop_setup_gaps: %s is NULL", !s ? "s" : "gaps");
    *gaps = NULL;
    const int n = (int)s->col.n, ng = s->gap.n;
    if (s->block && n < 2) /* one bead is one body of the column's mass already */
        return gw_err_set(err, GW_EINVAL, "block: has no effect with one bead (n = 1 is already one body of the "
                          "column's mass)");
    if (ng == 0)
        return GW_OK;
    if (n < 2 || s->block)
        return gw_err_set(err, GW_EINVAL, "gap: has no effect with %s", s->block ? "block" : "one bead");
    if (ng != 1 && ng != n - 1)
        return n == 2 ? gw_err_set(err, GW_EINVAL, "gap: %d values for the 1 pair of 2 beads (give 1)", ng)
                      : gw_err_set(err, GW_EINVAL, "gap: %d values for %d pairs (give 1 or %d)", ng, n - 1, n - 1);
    double *g = malloc((size_t)(n - 1) * sizeof *g);
    if (!g)
        return gw_err_set(err, GW_ENOMEM, "gap: out of memory");
    for (int i = 0; i < n - 1; i++)
        g[i] = s->gap.v[ng == 1 ? 0 : i];
    *gaps = g;
    return GW_OK;
}

/* ---- the signal from the run's sample callback ---- */

typedef struct drop_rec {
    gw_chain_drop_outcome *out;
    size_t cap;
    int n, keep_beads;
} drop_rec;

static int grow(double **a, size_t cap)
{
    double *p = realloc(*a, cap * sizeof *p);
    if (!p)
        return 0;
    *a = p;
    return 1;
}

static int record(void *ctx, double t, const double *y, double f_wall, int is_event)
{
    (void)is_event;
    drop_rec *rc = ctx;
    gw_chain_drop_outcome *o = rc->out;
    size_t len = (size_t)o->trace_len;
    if (len == rc->cap) {
        size_t cap = rc->cap ? 2 * rc->cap : 1024, nb = (size_t)rc->n;
        if (!grow(&o->t, cap) || !grow(&o->f_wall, cap) ||
            (rc->keep_beads && (!grow(&o->x, cap * nb) || !grow(&o->v, cap * nb))))
            return GW_ENOMEM;
        rc->cap = cap;
    }
    o->t[len] = t;
    o->f_wall[len] = f_wall;
    if (rc->keep_beads)
        for (int i = 0; i < rc->n; i++) {
            o->x[len * (size_t)rc->n + (size_t)i] = y[2 * i];
            o->v[len * (size_t)rc->n + (size_t)i] = y[2 * i + 1];
        }
    o->trace_len++;
    return 0;
}

/* ---- the results that the run leaves in gw_chain_drop_result, as tables ---- */

static int fill_tables(gw_chain_drop_outcome *o, gw_err *err)
{
    const gw_chain_drop_result *r = &o->r;
    const int np = r->n_peaks, ni = r->n_impacts, n = r->n;
    o->n_first = r->first.n;
    o->chatter = chain_chatter_value(r->chatter_kind, r->chatter_spread);
    o->first_chatter = r->first_status == GW_OK ? chain_result_chatter_value(&r->first) : NAN;
    o->impact_rises = gw_chain_drop_impact_rises(r);
    o->impacts_monotone = o->impact_rises == 0;
    o->e_kinetic = r->e_end.kinetic;
    o->e_elastic = r->e_end.elastic;
    o->e_gravity = r->e_end.gravity;
    o->e_dissipated = r->e_end.dissipated;
    o->e_total = r->e_end.total;
    o->wall_peaks = malloc(((size_t)np * 2 + 1) * sizeof *o->wall_peaks);
    o->peak_impact = malloc(((size_t)np + 1) * sizeof *o->peak_impact);
    o->peak_cluster = malloc(((size_t)np + 1) * sizeof *o->peak_cluster);
    o->peak_contacts = malloc(((size_t)np * (size_t)n + 1) * sizeof *o->peak_contacts);
    o->impacts = malloc(((size_t)ni * GW_DROP_NIMPACT_COLS + 1) * sizeof *o->impacts);
    if (!o->wall_peaks || !o->peak_impact || !o->peak_cluster || !o->peak_contacts || !o->impacts)
        return gw_err_set(err, GW_ENOMEM, "drop: out of memory for %d peaks", np);
    for (int j = 0; j < np; j++) {
        o->wall_peaks[2 * j] = r->peaks[j].t;
        o->wall_peaks[2 * j + 1] = r->peaks[j].f;
        o->peak_impact[j] = r->peaks[j].impact;
        o->peak_cluster[j] = r->peaks[j].cluster;
        for (int k = 0; k < n; k++)
            o->peak_contacts[(size_t)j * (size_t)n + (size_t)k] = r->peak_contacts[(size_t)j * (size_t)n + (size_t)k] != 0;
    }
    for (int j = 0; j < ni; j++) {
        const gw_chain_drop_impact *im = &r->impacts[j];
        double *row = o->impacts + (size_t)j * GW_DROP_NIMPACT_COLS;
        row[0] = im->t_start;
        row[1] = im->t_end;
        row[2] = im->f_max;
        row[3] = im->t_fmax;
        row[4] = im->v_in;
        row[5] = im->v_out;
        row[6] = im->n_peaks;
        row[7] = im->cluster;
        row[8] = im->located;
        row[9] = im->chatter; /* the JSON's per-impact chatter (NaN: no key there) */
    }
    return GW_OK;
}

void gw_chain_drop_block_params(gw_chain_params *p)
{
    if (!p)
        return;
    double mtot = 0;
    for (int i = 0; i < p->n; i++)
        mtot += p->masses ? p->masses[i] : p->mass;
    p->mass = mtot;
    p->n = 1;
    p->masses = NULL;
    p->kc = NULL;
}

int gw_chain_drop_study_run(const gw_chain_drop_setup *s, gw_progress_fn progress, void *pctx,
                            gw_chain_drop_outcome *out, gw_err *err)
{
    if (out) /* emptied on every refusal, a NULL setup's too (docs/library.md) */
        memset(out, 0, sizeof *out);
    if (!s || !out)
        return gw_err_set(err, GW_EINVAL, "gw_chain_drop_study_run: %s is NULL", !s ? "setup" : "out");
    double t0 = gw_clock_ms();
    int rc = gw_param_check(drop_params, s, err);
    if (rc != GW_OK)
        return rc;
    if ((rc = gw_chain_drop_guide_check(s->col.guide_friction, s->col.guide_viscous, err)) != GW_OK ||
        (rc = gw_chain_drop_setup_gaps(s, &out->gaps, err)) != GW_OK)
        return rc;
    const int n = (int)s->col.n;
    out->n_gaps = out->gaps ? n - 1 : 0;
    /* the column as `granwave chain` resolves it, arriving at sqrt(2 g h) (the
     * damping calibration runs at that velocity, under g) */
    gw_chain_setup col = s->col; /* shallow: s keeps what it owns */
    col.vimp = sqrt(2.0 * s->col.gravity * s->height);
    col.trace = 0;
    gw_chain_resolved res;
    if ((rc = gw_chain_setup_resolve(&col, &res, err)) != GW_OK) {
        gw_chain_resolved_free(&res);
        return rc;
    }
    gw_chain_params *p = &res.params;
    if (s->block)
        gw_chain_drop_block_params(p);
    if ((rc = chain_damping_check(p, err)) != GW_OK || (rc = chain_one_body_check(&s->col, p->n, err)) != GW_OK) {
        gw_chain_resolved_free(&res);
        return rc;
    }
    if ((rc = gw_chain_memory_check(p, res.run.solver, res.run.sp.method, err)) != GW_OK ||
        (rc = chain_drop_work_check(p, res.run.t_max, err)) != GW_OK) {
        gw_chain_resolved_free(&res);
        return rc;
    }
    const double t_max = res.run.t_max;
    const double dt_out = s->col.dt_out > 0 ? s->col.dt_out : fmin(1e-6, t_max);
    if (dt_out < t_max * 1e-7 || dt_out > t_max) {
        char xs[32], ls[32], hs[32];
        gw_chain_resolved_free(&res);
        return gw_err_set(err, GW_EINVAL, "dt-out: %s s is outside [t-max/1e7, t-max] = [%s, %s]",
                          gw_num_text(xs, sizeof xs, dt_out), gw_num_bound(ls, sizeof ls, t_max * 1e-7, 0),
                          gw_num_bound(hs, sizeof hs, t_max, 1));
    }
    /* with trace = 1 (the program: --out) every bead's x and v are kept at each
     * sample and event: --n 1000 --t-max 1 --dt-out 1e-7 --out grew past 1.3 GB
     * in its first minute toward 160 GB. Bounded before the run, with about 8
     * events per bead (6.4 measured for 100 beads over the default 10 ms). */
    if (s->col.trace && (rc = gw_chain_trace_check(p->n, t_max, dt_out, 8.0 * p->n + 2, err)) != GW_OK) {
        gw_chain_resolved_free(&res);
        return rc;
    }
    res.run.dt_out = dt_out;
    out->n = p->n;
    out->n_column = n;
    out->block = s->block;
    out->height = s->height;
    out->gravity = p->gravity;
    out->t_max = t_max;
    out->dt_out = dt_out;
    out->peak_threshold = isnan(s->peak_threshold) ? 0.01 * gw_chain_fmax1(p->mass, p->kwall, p->v_imp)
                                                   : s->peak_threshold;
    out->mass = p->mass;
    out->k = p->k;
    out->kwall = p->kwall;
    out->radius = p->radius;
    out->gamma = p->gamma;
    out->alpha = p->alpha;

    gw_chain_drop_params dp = gw_chain_drop_params_default();
    dp.chain = *p;
    dp.height = s->height;
    dp.gaps = s->block ? NULL : out->gaps;
    dp.t_max = t_max;
    dp.peak_threshold = out->peak_threshold;
    drop_rec rec = {.out = out, .n = p->n, .keep_beads = s->col.trace};
    res.run.sample = record;
    res.run.sample_ctx = &rec;
    rc = gw_chain_drop_run_progress(&dp, &res.run, progress, pctx, &out->r, err);
    out->canceled = rc == GW_ECANCELED;
    out->v_imp = out->r.v_imp;
    out->t_fall = out->r.t_fall;
    out->dt = out->r.run_dt;
    out->dt_max = out->r.run_dt_max;
    int rc2 = fill_tables(out, err);
    if (rc == GW_OK)
        rc = rc2;
    gw_chain_params at_impact = *p; /* the damping acts at the speed the fall gives */
    at_impact.v_imp = out->v_imp;
    if (rc == GW_OK && ((rc = chain_damping_zero_warnings(p, 0, 1, &out->warnings)) != GW_OK ||
                        (rc = chain_damping_small_warning(&at_impact, res.run.sp.rtol, &out->warnings)) != GW_OK ||
                        (rc = chain_drag_small_warnings(&at_impact, res.run.sp.rtol, &out->warnings)) != GW_OK ||
                        (rc = chain_drop_warnings(&out->r, p, &res.run, &out->warnings)) != GW_OK))
        rc = gw_err_set(err, rc, "drop: out of memory");
    /* a threshold above every peak: f_max, t_fmax, the peaks and the impacts
     * are empty (null), which said nothing of why (drop --peak-threshold 1e9:
     * f_max null, warnings [], a first collision of 72.5 N). Only where the
     * first collision stays below it: one cut by t-max before its force fell
     * has no peak at any threshold, and its own warning says why (this one
     * said "lower --peak-threshold" at 0.7 N of a first collision of 48 N) */
    /* impacts without a located peak (a sensor body's reading still rising
     * as bead 1 leaves: largest at the contact's end) are not empty: the
     * warning said "the peaks and the impacts are empty" over 21 impacts of
     * 0.71 to 0.78 N (drop --n 3 --sensor-mass 1e-4 --sensor-stiffness 1e3) */
    if (rc == GW_OK && out->r.n_peaks == 0 && out->r.n_impacts > 0 && !out->r.first_cut) {
        /* (a first collision cut by t-max has its own warning: its one
         * impact is open, its f_max that at t_max, not at a contact's end) */
        if ((rc = gw_warnings_add(&out->warnings, "no wall-force peak at or above --peak-threshold = %g N was "
                                  "located while bead 1 touched the sensor: f_max, t_fmax and the peaks are empty; "
                                  "the %d impacts (located false) reached it at a contact's start or end, where "
                                  "their f_max is read", out->peak_threshold, out->r.n_impacts)) != GW_OK)
            rc = gw_err_set(err, rc, "drop: out of memory");
    } else if (rc == GW_OK && out->r.n_peaks == 0 && !out->r.first_cut && isfinite(out->r.first.f_max) &&
        out->r.first.f_max < out->peak_threshold) {
        if ((rc = gw_warnings_add(&out->warnings, "no wall-force peak reached --peak-threshold = %g N (the first "
                                  "collision's F_max is %.6g N): f_max, t_fmax, the peaks and the impacts are empty; "
                                  "lower --peak-threshold", out->peak_threshold, out->r.first.f_max)) != GW_OK)
            rc = gw_err_set(err, rc, "drop: out of memory");
    }
    gw_chain_resolved_free(&res);
    out->wall_time_ms = gw_clock_ms() - t0;
    return rc;
}
