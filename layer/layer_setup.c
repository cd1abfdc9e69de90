/*
 * layer_setup.c: one block impact on a 2D granular layer as a library call
 * (gw_layer_study.h): the table of its inputs, their resolution as
 * `granwave layer-impact` resolves them, the run, and the table of its results.
 * Derived numbers: Froude number Fr = V_i / sqrt(2 g R_b) (B.15) with
 * R_b = rb-rm R_m; penetration in R_m. Snapshots (off by default): the
 * particles' states x, y (m), theta (rad), vx, vy (m/s), omega (rad/s) copied
 * by the impact's sample hook at the output samples asked for. Model: physics.md 2.1-2.4 (Hertz normal
 * force B.1, B.3, Mindlin tangential stiffness B.4, Coulomb cap B.2, ledger
 * B.7-B.14). SI units, angles in degrees.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"
#include "layer_setup_rows.h"
#include "gw_locale.h"

_Static_assert(GW_LAYER_UNTIL_REBOUND == 0 && GW_LAYER_UNTIL_VERDICT == 1, "until choices rebound,verdict");
_Static_assert(GW_LAYER_SIDES_BOTH == 0 && GW_LAYER_SIDES_LEFT == 1 && GW_LAYER_SIDES_RIGHT == 2 &&
                   GW_LAYER_SIDES_NONE == 3, "side-walls choices both,left,right,none");

#define OFF(f) offsetof(gw_layer_impact_setup, f)


static const gw_param impact_params[] = {
    {.name = "sample", .type = GW_PARAM_TEXT, .offset = OFF(sample), .unit = "", .metavar = "FILE",
     .help = "sample written by layer-make (required)"},
    GW_LAYER_MATERIAL_ROWS(NULL, NULL, "[the sample's]", "[the sample's]")
    /* a millionth of R_m up: (0, 1e6] took 3e-308, whose contact time underflowed
     * the automatic step to 0 ("layer: solver set-up failed at t = 0 s: verlet:
     * the fixed step dt must be set", naming neither rb-rm nor a fix); 1e-6 runs,
     * and from 1e-10 the work bound refuses naming t-max (test_frontend_parity) */
    ROW("rb-rm", GW_PARAM_DOUBLE, rb_rm, "", 1e-6, 1e6, 0, 0, "1", "R", "block radius in R_m, in [1e-6, 1e6] [1]"),
    ROW("vi", GW_PARAM_DOUBLE, vi, "m/s", 0, 1e3, 1, 0, "20", "V", "incident speed, m/s [20]"),
    ROW("alpha", GW_PARAM_DOUBLE, alpha, "deg", 0, 90, 0, 1, "0", "DEG", "incidence from the normal, deg in [0, 90) [0]"),
    ROW("x", GW_PARAM_DOUBLE, x, "m", -1e6, 1e6, 0, 0, "0", "X", "impact abscissa from the box centre, m [0]"),
    ROW("height-rm", GW_PARAM_DOUBLE, height_rm, "", 0, 1e6, 0, 0, "0", "H",
        "mobile layer height in R_m; particles whose centre lies deeper are frozen (a clump with one such "
        "member whole), at least one left mobile [0 = all]"),
    /* optional: a gap given at the default's value is told from none (a slow
     * impact's refusal names vi and the default gap, or the gap given: an
     * explicit --gap 1e-6 was told "the default gap" until session 44) */
    GW_PARAM_OPT_ROW("gap", GW_PARAM_DOUBLE, OFF(gap), "m", 0, 1e3, 0, 0, "1e-6", "G",
                     "initial block-target gap, m in [0, 1000] (< 0 would overlap the layer) [1e-6]"),
    /* an impact lasts milliseconds: 1000 s bounds a block that falls 1000 m
     * (gap) at the smallest speed, and a run's steps with it. The default
     * decides e_n (physics.md 2.3: the run ends at T_f, when the block's normal
     * velocity is back to zero under gravity, T_f ~ t_kick + e_n V_i / g):
     * measured on the default 300-disc sample, R_b = R_m, normal, T_f = 0.230,
     * 0.416, 0.813 s at 10, 20, 40 m/s (e_n 0.18, 0.15, 0.16); 2 s covers
     * e_n V_i up to ~19 m/s, and a run stops at T_f (until = rebound) anyway.
     * (0.05 s, the default before, left the default impact undecided.) */
    ROW("t-max", GW_PARAM_DOUBLE, t_max, "s", 0, 1e3, 1, 0, "2", "T",
        "end of the run, s in (0, 1000]; a run stops at T_f before it [2]"),
    ROW("dt-out", GW_PARAM_DOUBLE, dt_out, "s", 0, 1e3, 1, 0, "2e-5", "DT",
        "sampling interval, s (at most 2e6 samples up to t-max) [2e-5]"),
    ROW("ring-width", GW_PARAM_DOUBLE, ring_width, "m", 0, 1e6, 0, 0, "0", "DC", "crown width d_c, m [0 = 2 R_m]"),
    ROW("rings", GW_PARAM_LONG, rings, "", 1, 1000, 0, 0, "12", "N", "number of crowns [12]"),
    CHOICE("solver", solver, "verlet,rk4,cvode,arkode", NULL, "NAME",
           "verlet (explicit DEM, no located events), rk4, cvode or arkode [verlet; rk4 with exact]"),
    CHOICE("method", method, "default,bdf,adams,erk,dirk,imex", "default", "NAME",
           "cvode: bdf|adams; arkode: erk|dirk [adams / erk]"),
    ROW("dt", GW_PARAM_DOUBLE, dt, "s", 0, GW_LAYER_DT_MAX, 0, 0, "0", "DT",
        "fixed step of verlet or rk4, s [0 = auto: verlet the shortest binary contact time / 100, rk4 1e-6]"),
    FLAG("exact", exact, "exact mode: RK4 (or solver cvode|arkode) stopping at every contact and stick/slip "
                         "transition, dt 1e-6 s; the reference the fast default is tested against"),
    /* optional (not given: NaN): a tolerance given at its default's value
     * with verlet or rk4 passed in silence (--rtol 1e-8), where chain's and
     * dispersion's, rows without a default, are refused at any value */
    GW_PARAM_OPT_ROW("rtol", GW_PARAM_DOUBLE, OFF(rtol), "", GW_TOL_MIN, GW_TOL_MAX, 0, 0, "1e-8", "R",
                     "relative tolerance of cvode/arkode [1e-8]"),
    GW_PARAM_OPT_ROW("atol", GW_PARAM_DOUBLE, OFF(atol), "", GW_TOL_MIN, GW_TOL_MAX, 0, 0, "1e-8", "A",
                     "absolute tolerance (scaled per component) [1e-8]"),
    ROW("energy-tol", GW_PARAM_DOUBLE, energy_tol, "", 0, 1, 0, 0, "0", "E",
        "stop (an error; the command exits 1) when the ledger closure |sum - A|/A exceeds E [0 = off]"),
    FLAG("remove-walls", remove_walls, "take the left, right and bottom walls away at the start of the impact"),
    /* one side wall taken away over the floor (the library's walls mask:
     * until session 44 no option removed one alone) */
    /* optional (not given: -1): both given with remove-walls passed in
     * silence, as its default's value */
    GW_PARAM_OPT_CHOICE_ROW("side-walls", OFF(side_walls), "both,left,right,none", "both", "KIND",
           "the side walls kept from the start of the impact, the floor kept: both, left (the right one taken "
           "away), right or none; a pile whose side walls help hold it is refused without both, and any is "
           "refused with remove-walls [both]"),
    FLAG("full", full, "run to t-max even after the outcome is decided (for the crowns)"),
    /* layer-make's settings line records the pile's settling material: far
     * from it the pile is not at rest at t = 0 (layer_settled.c) */
    FLAG("other-settling", other_settling, "run a sample settled with another material or gravity (its settings line) "
         "whose contacts carry less than 0.5 or more than 1.5 times the weight they carried at rest under "
         "this material (and the floor load that explains), or whose friction angle is below "
         "the settling's; the result records a warning (docs/cli.md)"),
    /* the sample's springs (gw_layer_spring): a peer's input without them
     * (the LAMMPS data file) is compared from zero springs */
    FLAG("zero-springs", zero_springs, "start every contact's tangential spring at zero, not from the springs the "
         "sample carries (layer-make writes them; docs/formats.md): the pile then sags into the impact until "
         "friction builds up"),
    /* optional: with full, until is refused at either value (rebound, the
     * default's value given, passed in silence though full runs to t-max) */
    GW_PARAM_OPT_CHOICE_ROW("until", OFF(until), "rebound,verdict", "rebound", "WHAT",
           "rebound: run until the rebound is complete (T_f: the block's normal velocity back to zero after it "
           "left, physics.md 2.3) or the block is found not to bounce; verdict: stop at the bounce verdict (e_n, "
           "e, alpha_r then null; the _first values given) [rebound]"),
    {.name = "snapshots", .type = GW_PARAM_LIST, .offset = OFF(snapshots), .unit = "s", .min = 0, .max = 1e3,
     .rows = "10000", .metavar = "T,...", /* the most snapshots a run keeps (below) */
     .help = "particle snapshots at these times, s: each the first output sample at or after it, the end state "
             "when the run ended before (library only) [none]"},
    GW_PARAM_END};

const gw_param *gw_layer_impact_setup_params(void)
{
    return impact_params;
}

int gw_layer_impact_setup_init(gw_layer_impact_setup *s)
{
    if (!s)
        return GW_EINVAL;
    memset(s, 0, sizeof *s);
    return gw_param_init(impact_params, s, NULL);
}

void gw_layer_impact_setup_clear(gw_layer_impact_setup *s)
{
    gw_param_clear(impact_params, s);
}

#undef OFF
#define OFF(f) offsetof(gw_layer_impact_outcome, f)

static const gw_param outcome_fields[] = {
    RF("bounced", r.bounced, "1: vy changed sign and the block left all contacts; 0: not; -1: undecided (see undecided)"),
    RI("fell_off", r.fell_off, "0; else bounced 0 as the block left the layer for good: 1 below it, 2 beyond its left side, 3 its right (no wall there)"),
    RD("e_n", r.e_n, "", "normal restitution V_nr/V_ni (B.16)"),
    RD("e", r.e, "", "restitution V_r/V_i (B.17)"),
    RD("alpha_r", r.alpha_r_deg, "deg", "rebound angle arccos(V_nr/V_r) (B.18)"),
    RD("v_nr", r.v_nr, "m/s", "reflected normal velocity (at the largest upward velocity)"),
    RD("v_ni", r.v_ni, "m/s", "incident normal velocity"),
    RD("v_r", r.v_r, "m/s", "reflected speed"),
    RD("t_rebound", r.t_rebound, "s", "T_i: time of the largest upward velocity"),
    RD("penetration", r.penetration, "m", "largest downward block displacement"),
    RD("penetration_rm", penetration_rm, "", "penetration in R_m"),
    RD("energy_error", r.energy_error, "", "max ledger closure |sum - A| / A over the run"),
    RD("e_incident", r.e_incident, "J", "(1/2) M V_i^2"),
    RD("slump_ke", r.slump_ke, "J", "with a side wall taken away, the pile's kinetic energy at the block's first touch (NaN: both walls, or no touch)"),
    RD("dissipated_first_contact", r.dissipated_first_contact, "", "E_d / E_incident at the end of the first contact"),
    RD("block_loss_first_contact", r.block_loss_first_contact, "", "block kinetic energy lost in the first contact / E_incident"),
    RD("dissipated_first_contact_block", r.dissipated_first_contact_block, "", "the part of it at the block's contacts"),
    RD("t_first_contact", r.t_first_contact, "s", "end of the first contact"),
    RD("contact_angle", r.contact_angle_deg, "deg", "incident velocity to block-target contact normal"),
    RD("t_contact_open", r.t_contact_open, "s", "block-target contact opening (NaN: not by the verdict)"),
    RD("dissipated_contact_open", r.dissipated_contact_open, "", "E_d / E_incident then"),
    RD("block_loss_contact_open", r.block_loss_contact_open, "", "block kinetic energy lost by then / E_incident (B.28's loss for every R_b/R_m)"),
    RD("wave_speed", r.wave_speed, "m/s", "crown-to-crown speed of the strain-energy peaks"),
    RD("wave_speed_err", r.wave_speed_err, "m/s", "its standard error"),
    RD("wave_speed_kinetic", r.wave_speed_kin, "m/s", "the same from the kinetic-energy peaks"),
    RD("wave_speed_kinetic_err", r.wave_speed_kin_err, "m/s", "its standard error"),
    RI("wave_rings", r.wave_rings, "rings in the strain fit"),
    RD("t_end", r.t_end, "s", "end of the run"),
    RD("block_mass", r.block_mass, "kg", "block mass"),
    RD("froude", froude, "", "Froude number V_i / sqrt(2 g R_b) (B.15)"),
    RI("n_mobile", r.n_mobile, "mobile particles"),
    RI("n_frozen", r.n_frozen, "frozen particles (below height-rm)"),
    RD("impact_x", r.impact_x, "m", "crown centre x"),
    RD("impact_y", r.impact_y, "m", "crown centre y"),
    RD("rm", rm, "m", "the sample's mean radius R_m"),
    RD("a_total", a_total, "J", "ledger total A at the start"),
    RI("mass_law", mass_law, "mass law used (0 disc, 1 sphere)"),
    RF("exact", exact, "1: exact mode"),
    RD("dt", dt, "s", "fixed step used (0 for cvode/arkode)"),
    RD("wall_time_ms", r.wall_ms, "ms", "wall-clock time of the run"),
    RL("steps", r.stats.steps, "solver steps"),
    RL("rhs_evals", r.stats.rhs_evals, "right-hand side evaluations"),
    RL("events", r.stats.events, "contact events located"),
    RL("rebuilds", r.stats.rebuilds, "contact-list rebuilds"),
    RI("ns", r.ns, "samples in the series"),
    RI("nrings", r.nrings, "crowns"),
    RI("nregions", nregions, "regions: the crowns, outside, the block"),
    RA("t", r.t, "s", "ns", NULL, NULL, "sample times"),
    RA("ledger", r.ledger, "J", "ns", "8", GW_LAYER_ENERGY_COLUMNS, "energy ledger (B.7-B.14) at each sample"),
    RA("block", r.block, "m, m/s", "ns", "4", "x,y,vx,vy", "block centre and velocity at each sample"),
    RA("ring_kinetic", r.ring_kin, "J", "ns", "nrings", NULL, "soil kinetic energy per crown"),
    RA("ring_strain", r.ring_strain, "J", "ns", "nrings", NULL, "strain energy per crown"),
    RA("ring_coordination", r.ring_coord, "", "ns", "nrings", NULL, "coordination number per crown"),
    RA("ring_dissipated", r.ring_diss, "J", "ns", "nrings", NULL, "friction dissipation per crown"),
    RA("regions", r.regions, "J", "nregions", "8", GW_LAYER_ENERGY_COLUMNS,
       "ledger per region at the end: crowns, outside, block"),
    RA("peak_strain_t", r.peak_strain_t, "s", "nrings", NULL, NULL, "time of each crown's strain-energy peak"),
    RA("peak_kinetic_t", r.peak_kin_t, "s", "nrings", NULL, NULL, "time of each crown's kinetic-energy peak"),
    RA("ring_r", r.ring_r, "m", "nrings", NULL, NULL, "crown mid radius"),
    /* the bounce's events and the first free-flight maximum (layer_outcome.c) */
    RD("t_f", r.t_f, "s", "T_f: normal velocity back to zero after the bounce (NaN: not reached)"),
    RD("t_leave", r.t_leave, "s", "the bounce event: the block leaves the layer moving up (NaN: none)"),
    RD("e_n_first", r.e_n_first, "", "e_n at the first free-flight maximum (the largest v_y up to t_leave)"),
    RD("e_first", r.e_first, "", "e at the first free-flight maximum"),
    RD("alpha_r_first", r.alpha_r_first_deg, "deg", "alpha_r at the first free-flight maximum"),
    RD("v_nr_first", r.v_nr_first, "m/s", "V_nr at the first free-flight maximum"),
    RD("v_r_first", r.v_r_first, "m/s", "V_r at the first free-flight maximum"),
    RD("t_rebound_first", r.t_rebound_first, "s", "time of the first free-flight maximum"),
    {.name = "undecided", .type = GW_PARAM_TEXT, .offset = OFF(undecided), .unit = "",
     .help = "why the outcome is undecided (None: decided, or stopped at the verdict on purpose)"},
    RL("zeno_guards", r.stats.zeno_guards, "Zeno guards: event restarts forced past"),
    /* crowns by cross-correlation and the rings' spectra (layer_crowns.c) */
    RD("wave_speed_xcorr", r.wave_speed_xcorr, "m/s", "crown speed from the cross-correlation delays of neighbouring rings"),
    RD("wave_speed_xcorr_err", r.wave_speed_xcorr_err, "m/s", "its standard error from the delays' scatter"),
    RI("wave_xcorr_gaps", r.xcorr_gaps, "ring pairs used"),
    RI("nxcorr", nxcorr, "ring pairs listed: nrings - 1 (0 without the analysis)"),
    RA("xcorr_delay", r.xcorr_delay, "s", "nxcorr", NULL, NULL, "delay from ring k to ring k + 1 (NaN: pair unused)"),
    RA("xcorr_rho", r.xcorr_rho, "", "nxcorr", NULL, NULL, "normalised correlation peak of that pair (NaN: unused)"),
    RI("spec_len", r.spec_len, "frequencies of the spectra, f_l = l spec_df"),
    RD("spec_df", r.spec_df, "Hz", "frequency step of the spectra"),
    RA("spec_strain", r.spec_strain, "J^2/Hz", "spec_len", "nrings", NULL,
       "one-sided PSD of each ring's strain-energy increase"),
    RA("spec_kinetic", r.spec_kin, "J^2/Hz", "spec_len", "nrings", NULL, "one-sided PSD of each ring's kinetic energy"),
    {.name = "sample_fnv1a64", .type = GW_PARAM_TEXT, .offset = OFF(sample_fnv1a64), .unit = "",
     .help = "FNV-1a 64 hash of the sample file's bytes, 16 hex digits: the content the run read"},
    RI("crowns_nulled", crowns_nulled, "rules that nulled a crown speed, each warned of: 1 the sampling, 2 the run's end before 3 rings, 4 the pile's slow motion (locked), 8 the scatter (0: none)"),
    /* snapshots (off unless the setup's snapshots asks) */
    RI("nsnap", nsnap, "snapshots taken"),
    RI("nparticles", nparticles, "particles per snapshot (the discs, then the block)"),
    RI("block_index", block_index, "the block's index in a snapshot (-1: no snapshots)"),
    RI("snap_rows", snap_rows, "nsnap * nparticles"),
    RA("snapshot_t", snap_t, "s", "nsnap", NULL, NULL, "time of each snapshot"),
    RA("snapshot_r", particle_r, "m", "nparticles", NULL, NULL, "particle radii"),
    RA("snapshot", snap, "m, rad, m/s, rad/s", "snap_rows", "6", "x,y,theta,vx,vy,omega",
       "particle states, snapshot after snapshot"),
    GW_PARAM_WARNINGS(OFF(warnings)),
    GW_PARAM_END};

const gw_param *gw_layer_impact_outcome_fields(void)
{
    return outcome_fields;
}

void gw_layer_impact_outcome_free(gw_layer_impact_outcome *out)
{
    if (!out)
        return;
    gw_layer_impact_result_free(&out->r);
    out->nregions = 0;
    free(out->undecided);
    free(out->warnings);
    free(out->sample_fnv1a64);
    free(out->snap_t); /* snap and particle_r with it */
    out->undecided = out->warnings = NULL;
    out->sample_fnv1a64 = NULL;
    out->snap_t = out->snap = out->particle_r = NULL;
    out->nxcorr = out->nsnap = out->nparticles = out->snap_rows = 0;
    out->block_index = -1;
}

/* ---- snapshots: the impact's on_sample hook ---- */

typedef struct snap_req {
    double t; /* asked for, s */
    int j;    /* its place in the list */
} snap_req;

typedef struct snap_ctx {
    gw_layer_impact_outcome *out;
    snap_req *req; /* sorted by time */
    int next;      /* first request not taken */
    gw_progress_fn progress; /* may be NULL */
    void *pctx;
    void (*part)(void *pctx, double x); /* the run's part done (layer_run_part; may be NULL) */
    void *part_ctx;
    const gw_layer_impact_params *ip;   /* the run's (for part) */
    long total, every;       /* samples at most, and how often progress and part are called */
} snap_ctx;

static int req_cmp(const void *a, const void *b)
{
    const snap_req *x = a, *y = b;
    return x->t < y->t ? -1 : x->t > y->t ? 1 : x->j - y->j;
}

double layer_run_part(const gw_layer *L, const gw_layer_impact_params *ip)
{
    const double t = gw_layer_time(L), t_max = ip->t_max;
    double end = t_max;
    if (!ip->full && ip->until == GW_LAYER_UNTIL_REBOUND) {
        double b[6];
        gw_layer_particle(L, gw_layer_n(L) - 1, b);
        gw_layer_block_extremes ex;
        gw_layer_block_extremes_get(L, &ex);
        const double g = gw_layer_get_params(L)->gravity;
        /* rising past its largest v_y (its push over): v_y back to zero in
         * v_y / g, or sooner; while still pushed up v_y / g says nothing (a
         * sample at v_y = 0.001 m/s just after the turn read x = 0.99) */
        if (b[4] > 0 && g > 0 && ex.n > 0 && b[4] < ex.vy_max)
            end = fmin(t_max, t + b[4] / g);
    }
    return end > 0 && t > 0 ? fmin(t / end, 1.0) : 0;
}

/* Copy the layer's state into snapshot j (allocating them all at the first call). */
static int take_snapshots(void *ctx, const gw_layer *L, int k, int final)
{
    if (final == 2) /* a failed run gives no snapshots */
        return GW_OK;
    snap_ctx *c = ctx;
    if (c->progress && (final || k % c->every == 0) &&
        c->progress(c->pctx, final ? c->total : k, c->total) != 0)
        return GW_ECANCELED;
    if (c->part && !final && k % c->every == 0)
        c->part(c->part_ctx, layer_run_part(L, c->ip));
    if (c->out->nsnap == 0)
        return GW_OK;
    gw_layer_impact_outcome *o = c->out;
    const int np = gw_layer_n(L);
    if (!o->snap_t) {
        size_t rows = (size_t)o->nsnap * (size_t)np;
        o->snap_t = malloc(((size_t)o->nsnap + 6 * rows + (size_t)np) * sizeof(double));
        if (!o->snap_t)
            return GW_ENOMEM;
        o->snap = o->snap_t + o->nsnap;
        o->particle_r = o->snap + 6 * rows;
        o->nparticles = np;
        o->block_index = np - 1;
        o->snap_rows = (int)rows;
        for (int i = 0; i < np; i++)
            o->particle_r[i] = gw_layer_radius(L, i);
    }
    const double t = gw_layer_time(L);
    /* k dt_out is computed, not summed: a time asked for as such a multiple is
     * met at its sample, within rounding */
    for (; c->next < o->nsnap && (final || t >= c->req[c->next].t - 1e-12 * fmax(t, 1e-300)); c->next++) {
        const int j = c->req[c->next].j;
        o->snap_t[j] = t;
        for (int i = 0; i < np; i++)
            gw_layer_particle(L, i, o->snap + 6 * ((size_t)j * np + i));
    }
    return GW_OK;
}

/* the name of a choice row's value ("" when not given) */
static const char *choice(const gw_layer_impact_setup *s, const char *row, char *buf, size_t n)
{
    if (gw_param_format(gw_param_find(impact_params, row), s, buf, n) < 0)
        buf[0] = '\0';
    return buf;
}

/* Kept here, apart from the checks it calls (layer_settled.c, layer_impact.c),
 * so that they are not inlined into it: the number of times
 * gw_layer_impact_settled_check is entered is what test_sweep_check_settling
 * counts. */
int layer_settling_verdict(const gw_layer_sample *smp, const gw_layer_params *lp, int other_settling,
                           const char *name, layer_settling_memo *memo, char *warning, size_t n, gw_err *err)
{
    return layer_settling_verdict_found(smp, lp, other_settling, name, memo, NULL, warning, n, err);
}

/* The verdict a run takes (found may be NULL). */
static void found_set(layer_settling_found *found, const struct layer_settling_kept *k)
{
    if (!found)
        return;
    found->q = k->q;
    gw_snprintf(found->warning, sizeof found->warning, "%s", k->rc == GW_OK ? k->warning : "");
}

int layer_settling_verdict_found(const gw_layer_sample *smp, const gw_layer_params *lp, int other_settling,
                                 const char *name, layer_settling_memo *memo, layer_settling_found *found,
                                 char *warning, size_t n, gw_err *err)
{
    for (int k = 0; memo && k < LAYER_SETTLING_KEPT; k++) {
        const struct layer_settling_kept *m = &memo->kept[k];
        if (m->valid && m->other_settling == other_settling && memcmp(&m->lp, lp, sizeof *lp) == 0) {
            if (warning && n > 0)
                gw_snprintf(warning, n, "%s", m->warning);
            if (m->rc != GW_OK && err)
                *err = m->err;
            found_set(found, m);
            return m->rc;
        }
    }
    struct layer_settling_kept f = {.other_settling = other_settling, .lp = *lp};
    /* the check, then the floor's load against the ratio it found (one
     * weighing of a union-clump pile for both) */
    f.rc = layer_settled_check_q(smp, lp, other_settling, name, f.warning, sizeof f.warning, &f.q, &f.err);
    if (f.rc == GW_OK)
        f.rc = layer_rest_check(smp, lp, other_settling, name, f.q, &f.err);
    if (warning && n > 0)
        gw_snprintf(warning, n, "%s", f.rc == GW_OK ? f.warning : "");
    found_set(found, &f);
    if (f.rc != GW_OK && err)
        *err = f.err;
    if (memo && f.rc != GW_ENOMEM) {
        f.valid = 1;
        memo->kept[memo->next] = f;
        memo->next = (memo->next + 1) % LAYER_SETTLING_KEPT;
    }
    return f.rc;
}

/* Materials, solver and impact parameters as layer-impact resolves them. */
static int resolve(const gw_layer_impact_setup *s, const gw_layer_sample *smp, gw_layer_params *lp,
                   gw_layer_impact_params *ip, const gw_solver_type **type, gw_solver_params *sp,
                   layer_settling_memo *memo, layer_settling_found *found, gw_err *err)
{
    char sname[16], mname[16];
    *lp = gw_layer_params_default();
    GW_LAYER_MATERIAL_TO_PARAMS(lp, s);
    lp->mass_law = s->mass_law >= 0 ? s->mass_law : smp->mass_law;
    lp->clump_mass = s->clump_mass >= 0 ? s->clump_mass : smp->clump_mass;
    int rc = gw_layer_params_validate(lp, err);
    if (rc != GW_OK)
        return rc;
    *type = s->solver >= 0 ? gw_solver_type_find(choice(s, "solver", sname, sizeof sname))
                           : s->exact ? gw_solver_rk4 : gw_solver_verlet;
    if (s->exact && *type == gw_solver_verlet)
        return gw_err_set(err, GW_EINVAL, "exact: needs a solver that locates contact events (rk4, cvode, "
                          "arkode), not verlet");
    *sp = gw_solver_params_default();
    sp->method = gw_solver_method_find(choice(s, "method", mname, sizeof mname));
    if (!*type || sp->method < 0)
        return gw_err_set(err, GW_EINVAL, "solver: unknown solver or method");
    /* options that would have no effect in this combination are refused: a
     * method the backend does not offer, tolerances of a fixed-step solver
     * (at any value given: rtol and atol are optional rows), a clump mass
     * without clumps */
    const int m = sp->method, cv = *type == gw_solver_cvode, ak = *type == gw_solver_arkode;
    if (m != GW_METHOD_DEFAULT && !((cv && (m == GW_CVODE_BDF || m == GW_CVODE_ADAMS)) ||
                                    (ak && (m == GW_ARKODE_ERK || m == GW_ARKODE_DIRK))))
        return gw_err_set(err, GW_EINVAL, "method: '%s' has no effect with the %s solver (cvode: bdf, adams; "
                          "arkode: erk, dirk)", mname, gw_solver_type_name(*type));
    if ((rc = gw_solver_tolerances_unused_check(*type, impact_params, s, err)) != GW_OK)
        return rc;
    if (s->clump_mass >= 0 && !smp->body)
        return gw_err_set(err, GW_EINVAL, "clump-mass: has no effect: the sample '%s' has no clumps", s->sample);
    if (s->clump_mass >= 0) { /* clumps of one disc each: sum and union are the same mass */
        int *members = calloc((size_t)smp->n, sizeof *members), shared = 0;
        if (!members)
            return gw_err_set(err, GW_ENOMEM, "layer-impact: out of memory");
        for (int i = 0; i < smp->n && !shared; i++)
            shared = ++members[smp->body[i]] > 1;
        free(members);
        if (!shared)
            return gw_err_set(err, GW_EINVAL, "clump-mass: has no effect: every clump of the sample '%s' is one disc "
                              "(the sum and the union of its discs are the same mass)", s->sample);
    }
    if ((cv || ak) && s->dt > 0) /* the fixed step of verlet and rk4 (0: auto); cvode and arkode choose theirs */
        return gw_err_set(err, GW_EINVAL, "dt: has no effect with the %s solver (it chooses its steps from rtol "
                          "and atol; dt is the fixed step of verlet and rk4)", gw_solver_type_name(*type));
    sp->dt = *type == gw_solver_verlet ? s->dt /* 0: gw_layer_impact chooses */
           : *type == gw_solver_rk4 ? (s->dt > 0 ? s->dt : 1e-6) : 0;
    sp->rtol = isnan(s->rtol) ? 1e-8 : s->rtol; /* the rows' default, not given */
    sp->atol = isnan(s->atol) ? 1e-8 : s->atol;
    *ip = gw_layer_impact_params_default();
    ip->rb_rm = s->rb_rm;
    ip->vi = s->vi;
    ip->alpha_deg = s->alpha;
    ip->x = s->x;
    ip->height_rm = s->height_rm;
    const int gap_given = gw_param_given(gw_param_find(impact_params, "gap"), s);
    if (gap_given)
        ip->gap = s->gap;
    ip->t_max = s->t_max;
    ip->dt_out = s->dt_out;
    ip->ring_width = s->ring_width;
    ip->nrings = (int)s->rings;
    ip->energy_tol = s->energy_tol;
    ip->remove_walls = s->remove_walls;
    ip->side_walls = s->side_walls >= 0 ? s->side_walls : GW_LAYER_SIDES_BOTH;
    if (ip->remove_walls && s->side_walls >= 0) /* both too (any other: layer_impact_params_check) */
        return gw_err_set(err, GW_EINVAL, "side-walls: %s is given with remove-walls, which takes every wall away "
                          "(the floor too): give one or the other", choice(s, "side-walls", sname, sizeof sname));
    ip->full = s->full;
    ip->other_settling = s->other_settling;
    ip->zero_springs = s->zero_springs;
    ip->until = s->until >= 0 ? s->until : GW_LAYER_UNTIL_REBOUND;
    if (ip->full && s->until >= 0)
        return gw_err_set(err, GW_EINVAL, "until: %s has no effect with full (which runs to t-max)",
                          gw_layer_until_name(s->until));
    /* the sample was read (gw_layer_sample_read: the shared check,
     * layer_sample_limits_check, which gw_layer_impact_check and
     * gw_layer_impact_gap_check take first): their rules alone */
    rc = layer_impact_params_check(smp, ip, err);
    if (rc == GW_OK)
        rc = layer_impact_gap_rules(smp, ip, s->gravity, !gap_given, err);
    if (rc == GW_OK)
        rc = gw_layer_impact_step_check(ip, *type, sp, err);
    /* (the side walls kept: a sweep's check refuses the case before any runs) */
    if (rc == GW_OK)
        rc = layer_side_walls_rest_check(smp, lp, ip, err);
    /* the warning is the run's (gw_layer_impact keeps it in its result) */
    return rc == GW_OK ? layer_settling_verdict_found(smp, lp, s->other_settling, s->sample, memo, found, NULL, 0, err)
                       : rc;
}

/* The setup's rows in their ranges and a sample named: what a plan (the
 * sample read) and a check against a sample already read both need first. */
static int setup_rows_check(const gw_layer_impact_setup *s, gw_err *err)
{
    int rc = gw_param_check(impact_params, s, err);
    if (rc == GW_OK && !s->sample)
        rc = gw_err_set(err, GW_EINVAL, "sample: a sample file (from layer-make) is required");
    return rc;
}

/* The plan, its settling verdict through memo (may be NULL) into found (may be NULL). */
static int plan_make(const gw_layer_impact_setup *s, gw_layer_impact_plan *p, layer_settling_memo *memo,
                     layer_settling_found *found, gw_err *err)
{
    /* p emptied first, s NULL too: a plan declared without a value and
     * refused was left as it was, and freeing it freed what it held (before
     * session 45: "writes nothing", SIGSEGV in gw_layer_impact_plan_free) */
    if (p)
        memset(p, 0, sizeof *p);
    if (!s || !p)
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_plan_make: %s is NULL", !s ? "s" : "p");
    int rc = setup_rows_check(s, err);
    if (rc != GW_OK)
        return rc;
    if ((rc = gw_layer_sample_read(s->sample, &p->sample, err)) != GW_OK)
        return rc;
    return resolve(s, &p->sample, &p->lp, &p->ip, &p->type, &p->sp, memo, found, err);
}

/* other-settling runs a sample whose recorded settling puts its pile away from
 * rest, or a floor load that settling explains; on a sample that runs without
 * it (settled under the impact's material and gravity, or with no settings
 * line to compare) it had no effect and the run said nothing: layer-impact
 * --other-settling on a pile of layer-make's defaults ran with exit 0, its
 * result the run's without the flag. A single run's check (the program and
 * gw_layer_impact_run): a sweep's case keeps it, as a grid's key acts on its
 * other samples. Called once the plan with the flag is made, on the plan's
 * sample: the setup without the flag is resolved against it, not read again. */
static int other_settling_idle_check(const gw_layer_impact_setup *s, const gw_layer_sample *smp, gw_err *err)
{
    if (!s || !smp || !s->other_settling)
        return GW_OK;
    gw_layer_impact_setup t = *s; /* shallow: read only */
    t.other_settling = 0;
    gw_err e = {{0}};
    if (layer_impact_setup_check_sample(&t, smp, NULL, &e) != GW_OK)
        return GW_OK;
    return gw_err_set(err, GW_EINVAL, "other-settling: has no effect: sample '%s' runs without it (%s)", s->sample,
                      smp->settled.recorded
                          ? "the settling its settings line records is within what a run takes without it: "
                            "contacts carrying 0.5 to 1.5 times the weight they carried at rest, a friction angle "
                            "at least the settling's"
                          : "it has no settings line to compare with the impact's material");
}

/* zero-springs starts every contact's tangential spring at zero instead of
 * from the springs the sample carries; a sample without springs (no springs
 * section, or one of none) starts them at zero as it is, and the flag ran
 * with exit 0 and no effect. A single run's check, as other-settling's. */
static int single_run_idle_check(const gw_layer_impact_setup *s, const gw_layer_impact_plan *p, gw_err *err)
{
    if (s && p && s->zero_springs && p->sample.n_springs == 0)
        return gw_err_set(err, GW_EINVAL, "zero-springs: has no effect: sample '%s' carries no springs (every "
                          "contact's tangential spring starts at zero without it)", s->sample);
    return p ? other_settling_idle_check(s, &p->sample, err) : GW_OK;
}

int layer_impact_plan_make_memo(const gw_layer_impact_setup *s, gw_layer_impact_plan *p, layer_settling_memo *memo,
                                gw_err *err)
{
    return plan_make(s, p, memo, NULL, err);
}

int layer_impact_plan_make_found(const gw_layer_impact_setup *s, gw_layer_impact_plan *p,
                                 layer_settling_found *found, gw_err *err)
{
    if (!found)
        return gw_err_set(err, GW_EINVAL, "layer_impact_plan_make_found: found is NULL");
    found->q = NAN;
    found->warning[0] = '\0';
    int rc = plan_make(s, p, NULL, found, err);
    return rc == GW_OK ? single_run_idle_check(s, p, err) : rc; /* the program's single run */
}

int gw_layer_impact_plan_make(const gw_layer_impact_setup *s, gw_layer_impact_plan *p, gw_err *err)
{
    return layer_impact_plan_make_memo(s, p, NULL, err);
}

void gw_layer_impact_plan_free(gw_layer_impact_plan *p)
{
    if (!p)
        return;
    gw_layer_sample_free(&p->sample);
}

int layer_impact_setup_check_sample(const gw_layer_impact_setup *s, const gw_layer_sample *smp,
                                    layer_settling_memo *memo, gw_err *err)
{
    if (!s || !smp)
        return gw_err_set(err, GW_EINVAL, "layer_impact_setup_check_sample: %s is NULL", !s ? "s" : "smp");
    int rc = setup_rows_check(s, err);
    if (rc != GW_OK)
        return rc;
    gw_layer_params lp;
    gw_layer_impact_params ip;
    const gw_solver_type *type;
    gw_solver_params sp;
    return resolve(s, smp, &lp, &ip, &type, &sp, memo, NULL, err);
}

int layer_impact_setup_check_case(const gw_layer_impact_setup *s, gw_err *err)
{
    gw_layer_impact_plan p;
    int rc = gw_layer_impact_plan_make(s, &p, err);
    gw_layer_impact_plan_free(&p);
    return rc;
}

int gw_layer_impact_setup_check(const gw_layer_impact_setup *s, gw_err *err)
{
    /* the single run's refusals too, as gw_layer_impact_run's: other-settling
     * and zero-springs of no effect on the sample passed this check (and
     * Python's layer_impact_check), which the run then refused */
    gw_layer_impact_plan p;
    int rc = gw_layer_impact_plan_make(s, &p, err);
    if (rc == GW_OK)
        rc = single_run_idle_check(s, &p, err);
    gw_layer_impact_plan_free(&p);
    return rc;
}

int gw_layer_impact_setup_settling(const gw_layer_impact_setup *s, double *q, char *warning, size_t n,
                                   gw_err *err)
{
    if (q)
        *q = NAN;
    if (warning && n > 0)
        warning[0] = '\0';
    if (!s || (!warning && n > 0))
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_setup_settling: %s is NULL", !s ? "s" : "warning");
    layer_settling_found found = {.q = NAN};
    gw_layer_impact_plan p;
    const int rc = layer_impact_plan_make_found(s, &p, &found, err); /* the single run's checks too */
    gw_layer_impact_plan_free(&p);
    if (rc != GW_OK)
        return rc;
    if (q)
        *q = found.q;
    if (warning && n > 0)
        gw_snprintf(warning, n, "%s", found.warning);
    return GW_OK;
}

int gw_layer_impact_run(const gw_layer_impact_setup *s, gw_layer_impact_outcome *out, gw_err *err)
{
    return gw_layer_impact_run_progress(s, NULL, NULL, out, err);
}

static int impact_run(const gw_layer_impact_setup *s, gw_progress_fn progress, void *pctx,
                      void (*part)(void *part_ctx, double x), void *part_ctx, int single,
                      gw_layer_impact_outcome *out, gw_err *err);

int gw_layer_impact_run_progress(const gw_layer_impact_setup *s, gw_progress_fn progress, void *pctx,
                                 gw_layer_impact_outcome *out, gw_err *err)
{
    return impact_run(s, progress, pctx, NULL, NULL, 1, out, err); /* a single run: its idle flags refused */
}

/* A sweep's case: other-settling and zero-springs kept where idle, as a
 * grid's key acts on its other samples. */
int layer_impact_run_part(const gw_layer_impact_setup *s, gw_progress_fn progress, void *pctx,
                          void (*part)(void *part_ctx, double x), void *part_ctx, gw_layer_impact_outcome *out,
                          gw_err *err)
{
    return impact_run(s, progress, pctx, part, part_ctx, 0, out, err);
}

/* The speeds a coarse --dt-out left unresolved (layer_crowns_undersampled):
 * `--dt-out 5e-3` on the 40-disc pile of `layer-make --n 40` gave every speed
 * null (98 +- 45 m/s by the strain peaks at the default 2e-5 s) with no
 * warning, in the program, a sweep's case and Python alike. */
static int crowns_sampling_warning(const gw_layer_impact_params *ip, const gw_layer_impact_result *r, char **list)
{
    double dt, dc;
    int few;
    const unsigned which = layer_crowns_undersampled(r, &dt, &dc, &few);
    if (!which)
        return GW_OK;
    static const char *const name[3] = {"wave_speed", "wave_speed_kinetic", "wave_speed_xcorr"};
    char names[96] = "";
    for (int k = 0, first = 1; k < 3; k++)
        if (which & (1u << k)) {
            strcat(names, first ? "" : ", ");
            strcat(names, name[k]);
            first = 0;
        }
    /* The first impact not closed by T_f: the run ended before it, and that
     * end, not the sampling, is named. `--until verdict --dt-out 0.2` (the
     * bounce verdict at 1.56 ms on the 40-disc pile) was told "give a smaller
     * --dt-out" while the default sampling of the same run leaves every speed
     * null too, and `--t-max 0.001 --dt-out 0.2` alike. At t-max a --dt-out
     * above a third of the run is named besides: it left the run fewer than 4
     * samples (`--t-max 0.01`: 651 m/s at the default sampling). */
    if (few > 0 && (r->bounced != 1 || !isfinite(r->t_f))) {
        const double span = r->t[r->ns - 1] - r->t[0];
        const int verdict = r->bounced == 1 && ip && ip->until == GW_LAYER_UNTIL_VERDICT && !r->undecided[0];
        const int nobounce = !verdict && r->bounced == 0;
        char fix[160] = "raise --t-max";
        if (!verdict && !nobounce && ip && ip->dt_out > span / 3 * (1 + 1e-9))
            gw_snprintf(fix, sizeof fix, "give a --dt-out of at most %.3g s (a third of the run) or raise --t-max",
                        span / 3);
        return gw_warnings_add(list, "%s: the run ended at t = %.6g s %s, with %d samples of the first impact: %s "
                               "%s null (unresolved): the crowns' arrivals need that impact up to its end sampled "
                               "4 times or more; %s", verdict ? "until" : nobounce ? "no bounce" : "t-max",
                               r->t[r->ns - 1],
                               verdict ? "at the bounce verdict (the block left the layer; --until verdict), before T_f"
                               : nobounce ? "when the block was found not to bounce (its rebound ended inside the layer)"
                                          : "at t-max, before T_f",
                               few, names, (which & (which - 1)) ? "are" : "is",
                               verdict ? "--until rebound runs on to T_f" : nobounce ? "--full runs on to t-max" : fix);
    }
    if (few > 0)
        return gw_warnings_add(list, "dt-out: the first impact holds %d samples %g s apart, where a crown's arrival "
                               "is a sample between two others: %s %s null (unresolved); give a smaller --dt-out "
                               "(the default is 2e-05 s)", few, dt, names, (which & (which - 1)) ? "are" : "is");
    return gw_warnings_add(list, "dt-out: samples %g s apart are too coarse for the crowns: the wave crosses a crown "
                           "of %g m in fewer than two samples, so %s %s null (unresolved); give a smaller --dt-out "
                           "(the default is 2e-05 s)", dt, dc, names, (which & (which - 1)) ? "are" : "is");
}

unsigned layer_crowns_locked(const gw_layer_impact_result *r)
{
    double delay, ref, cp[2];
    unsigned which = layer_crowns_peaks_locked(r, cp, &ref) &
                     ((isnan(r->wave_speed) ? 1u : 0u) | (isnan(r->wave_speed_kin) ? 2u : 0u));
    if (isnan(r->wave_speed_xcorr) && layer_crowns_xcorr_locked(r, &delay, &ref))
        which |= 4u;
    return which;
}

/* The speeds a run ended before the wave crossed 3 crowns left null: the
 * arrivals are read over the first impact, and a run that ended inside it (at
 * t-max, at the bounce verdict, or found not to bounce) before the wave's
 * peaks reached 3 of rings 1 .. nrings - 1 has no speed to fit, well sampled
 * as it is. On the 40-disc pile of `layer-make --n 40`, `--until verdict`
 * (the verdict at 1.56 ms, the strain peaks in 1 ring) and `--t-max 0.003`
 * (2 rings) gave every speed null with no word of it (--t-max 0.005: 733 m/s
 * over 4 rings). Said after the sampling's warning (a speed it names is not
 * named again) and the locks of the cross-correlation and the peaks (likewise), on crowns that
 * hold particles in 3 rings at least. */
static int crowns_cut_warning(const gw_layer_impact_params *ip, const gw_layer_impact_result *r, char **list)
{
    if (!ip || (r->bounced == 1 && isfinite(r->t_f)) || !r->t || r->ns < 1 || r->wave_rings >= 3)
        return GW_OK; /* the first impact ran to its end (not the run's end), or the rings were reached */
    double dt, dc;
    int few;
    double cs[3], es[3];
    const unsigned warned = layer_crowns_undersampled(r, &dt, &dc, &few) | layer_crowns_locked(r) |
                            layer_crowns_imprecise(r, cs, es);
    static const char *const name[3] = {"wave_speed", "wave_speed_kinetic", "wave_speed_xcorr"};
    const double v[3] = {r->wave_speed, r->wave_speed_kin, r->wave_speed_xcorr};
    char names[96] = "";
    int count = 0;
    for (int k = 0; k < 3; k++)
        if (isnan(v[k]) && !(warned & (1u << k))) {
            strcat(names, count ? ", " : "");
            strcat(names, name[k]);
            count++;
        }
    if (!count)
        return GW_OK;
    const int verdict = r->bounced == 1 && ip->until == GW_LAYER_UNTIL_VERDICT && !r->undecided[0];
    const int nobounce = !verdict && r->bounced == 0;
    return gw_warnings_add(list, "crowns: the run ended at t = %.6g s %s, before the wave's strain peaks reached 3 of "
                           "rings 1 to %d (they reached %d): %s %s null (unresolved); %s", r->t[r->ns - 1],
                           verdict ? "at the bounce verdict (--until verdict), inside the first impact"
                           : nobounce ? "when the block was found not to bounce, inside the first impact"
                                      : "at t-max, inside the first impact",
                           ip->nrings - 1, r->wave_rings, names, count > 1 ? "are" : "is",
                           verdict ? "--until rebound runs on to T_f" : nobounce ? "--full runs on to t-max"
                                                                        : "raise --t-max");
}

/* The speeds the resolution rule nulled for their scatter alone
 * (layer_crowns_imprecise: the sampling resolves them, their standard error
 * is at or above half the speed), not named by the sampling's warning: the
 * default impact on the 40-disc pile of `layer-make --n 40` gave
 * wave_speed_xcorr null and "warnings": [] (issue 18 class 6). One line,
 * each speed with its value and its error. */
static int crowns_scatter_warning(const gw_layer_impact_result *r, char **list)
{
    double dt, dc, c[3], e[3];
    int few;
    const unsigned which = layer_crowns_imprecise(r, c, e) & ~layer_crowns_undersampled(r, &dt, &dc, &few);
    if (!which)
        return GW_OK;
    static const char *const name[3] = {"wave_speed", "wave_speed_kinetic", "wave_speed_xcorr"};
    char read[240] = "", names[96] = "";
    for (int k = 0, n = 0; k < 3; k++)
        if (which & (1u << k)) {
            const size_t at = strlen(read);
            gw_snprintf(read + at, sizeof read - at, "%s%s %.4g +- %.3g m/s", n ? ", " : "", name[k], c[k], e[k]);
            strcat(names, n ? ", " : "");
            strcat(names, name[k]);
            n++;
        }
    return gw_warnings_add(list, "crowns: %s: a standard error at or above half the speed, so %s %s null "
                           "(undecided: the rings' arrivals scatter too much to fit a speed)", read, names,
                           (which & (which - 1)) ? "are" : "is");
}

/* The crowns as set against the sample: the wave speeds fit the peak times
 * of rings 1 .. nrings - 1 and need 3 of them (layer_crowns.c), so crowns too
 * narrow to reach a particle (--ring-width 1e-9: every speed null, "0 rings"),
 * too wide to part them (1e6: all in ring 0) or too few (--rings 3) made a
 * run whose speeds could never be read, said nowhere but in "unresolved". A
 * ring counts here when a particle's centre lies in it (the contacts the
 * crowns sum lie between centres); the run itself is unchanged. The default
 * width (2 R_m) is not judged: on a pile too small for 3 rings (60 discs,
 * 14 R_m wide: 2) the speeds' "unresolved" is the pile's size, not a flag's. */
static int crowns_warning(const gw_layer_sample *smp, const gw_layer_impact_params *ip,
                          const gw_layer_impact_result *r, char **list, int *cut);

/* The lines of *list from byte at on: 1 when a rule added one */
static int added(char *const *list, size_t at)
{
    return *list && strlen(*list) > at;
}

int layer_crowns_warning_kinds(const gw_layer_sample *smp, const gw_layer_impact_params *ip,
                               const gw_layer_impact_result *r, char **list, int *kinds)
{
    if (kinds)
        *kinds = 0;
    const size_t at = *list ? strlen(*list) : 0;
    int cut = 0;
    int rc = crowns_warning(smp, ip, r, list, &cut);
    if (rc != GW_OK || !kinds || !added(list, at))
        return rc;
    /* which rules said them: each rule's line starts as its own */
    double dt, dc, c[3], e[3];
    int few;
    const unsigned under = layer_crowns_undersampled(r, &dt, &dc, &few);
    *kinds = (under ? GW_LAYER_NULLED_SAMPLING : 0) | (layer_crowns_locked(r) ? GW_LAYER_NULLED_LOCKED : 0) |
             ((layer_crowns_imprecise(r, c, e) & ~under) ? GW_LAYER_NULLED_SCATTER : 0);
    if (cut)
        *kinds |= GW_LAYER_NULLED_CUT;
    return rc;
}

int layer_crowns_warning(const gw_layer_sample *smp, const gw_layer_impact_params *ip,
                         const gw_layer_impact_result *r, char **list)
{
    return layer_crowns_warning_kinds(smp, ip, r, list, NULL);
}

static int crowns_warning(const gw_layer_sample *smp, const gw_layer_impact_params *ip,
                          const gw_layer_impact_result *r, char **list, int *cut)
{
    int rc = crowns_sampling_warning(ip, r, list);
    if (rc != GW_OK)
        return rc;
    /* the cross-correlation locked onto something slower than the wave
     * (layer_crowns_xcorr_locked): its speed null, said here */
    double delay, ref;
    if (isnan(r->wave_speed_xcorr) && layer_crowns_xcorr_locked(r, &delay, &ref) &&
        (rc = gw_warnings_add(list, "crowns: the cross-correlation's ring pairs are %.3g s apart on average, %.0f "
                              "times the %.3g s %s: they follow the pile's slower motion over the first impact, not "
                              "the wave, so wave_speed_xcorr is null (undecided; it read %.4g m/s)", delay,
                              delay / ref, ref, r->t_contact_open > 0 && isfinite(r->t_contact_open)
                              ? "the block's first contact lasted (to its opening)"
                              : "a crown takes at the faster peak speed", (r->ring_r[1] - r->ring_r[0]) / delay))
        != GW_OK)
        return rc;
    /* the peak speeds following that motion (layer_crowns_peaks_locked): null, said here */
    double cp[2];
    const unsigned peaks = layer_crowns_peaks_locked(r, cp, &ref) &
                           ((isnan(r->wave_speed) ? 1u : 0u) | (isnan(r->wave_speed_kin) ? 2u : 0u));
    if (peaks) {
        const double dc = r->ring_r[1] - r->ring_r[0], c0 = peaks & 1u ? cp[0] : cp[1];
        char also[96] = "";
        if (peaks == 3u)
            gw_snprintf(also, sizeof also, ", the kinetic peaks' %.4g m/s in %.3g s (%.0f times)", cp[1],
                        dc / cp[1], dc / cp[1] / ref);
        if ((rc = gw_warnings_add(list, "crowns: the %s peaks' speed %.4g m/s crosses a crown of %g m in %.3g s "
                                  "(%.0f times the %.3g s the block's first contact lasted, to its opening)%s: the "
                                  "rings' peaks follow the pile's slower motion over the first impact, not the wave, "
                                  "so %s null (undecided)", peaks & 1u ? "strain" : "kinetic", c0, dc, dc / c0,
                                  dc / c0 / ref, ref, also,
                                  peaks == 3u ? "wave_speed and wave_speed_kinetic are"
                                  : peaks & 1u ? "wave_speed is" : "wave_speed_kinetic is")) != GW_OK)
            return rc;
    }
    if ((rc = crowns_scatter_warning(r, list)) != GW_OK)
        return rc;
    const double w = ip->ring_width > 0 ? ip->ring_width : 2 * smp->rm;
    if (ip->nrings < 4)
        return gw_warnings_add(list, "rings: %d crowns leave %d beyond the first, where the wave speeds need 3: "
                               "no wave speed can be read (give --rings 4 or more)", ip->nrings, ip->nrings - 1);
    int held = 0;
    for (int k = 1; k < ip->nrings && held < 3; k++) {
        int any = 0;
        for (int i = 0; i < smp->n && !any; i++) {
            const double d = hypot(smp->x[i] - r->impact_x, smp->y[i] - r->impact_y) / w;
            any = d >= k && d < k + 1;
        }
        held += any;
    }
    if (held >= 3) {
        const size_t at = *list ? strlen(*list) : 0;
        rc = crowns_cut_warning(ip, r, list);
        *cut = rc == GW_OK && added(list, at);
        return rc;
    }
    if (!(ip->ring_width > 0))
        return GW_OK;
    return gw_warnings_add(list, "ring-width: crowns %g m wide around the impact point hold particle centres in %d "
                           "of rings 1 to %d, where the wave speeds need 3: no wave speed can be read (the default "
                           "is 2 R_m = %g m)", w, held, ip->nrings - 1, 2 * smp->rm);
}

/* The run from the setup, its plan made once (single: with its idle-flag check). */
static int impact_run(const gw_layer_impact_setup *s, gw_progress_fn progress, void *pctx,
                      void (*part)(void *part_ctx, double x), void *part_ctx, int single,
                      gw_layer_impact_outcome *out, gw_err *err)
{
    if (out) { /* emptied on every refusal, a NULL setup's too (docs/library.md) */
        memset(out, 0, sizeof *out);
        out->block_index = -1;
    }
    if (!s || !out)
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_run: %s is NULL", !s ? "setup" : "out");
    gw_layer_impact_plan plan;
    layer_settling_found found = {.q = NAN}; /* the plan's verdict: the run does not find it again */
    int rc = plan_make(s, &plan, NULL, &found, err);
    if (rc == GW_OK && single)
        rc = single_run_idle_check(s, &plan, err);
    const gw_layer_sample smp = plan.sample; /* a view: freed with the plan */
    const gw_layer_params lp = plan.lp;
    gw_layer_impact_params ip = plan.ip;
    const gw_solver_type *type = plan.type;
    const gw_solver_params sp = plan.sp;
    snap_ctx sc = {.out = out, .req = NULL, .next = 0, .progress = progress, .pctx = pctx, .part = part,
                   .part_ctx = part_ctx, .ip = &ip};
    if (rc == GW_OK && (progress || part)) { /* about a thousand calls over the longest run */
        sc.total = (long)ceil(ip.t_max / ip.dt_out - 1e-9) + 1;
        sc.every = sc.total / 1000 > 1 ? sc.total / 1000 : 1;
        ip.on_sample = take_snapshots;
        ip.sample_ctx = &sc;
    }
    if (rc == GW_OK && s->snapshots.n > 0) {
        /* every snapshot holds 6 doubles of each particle and the block, taken
         * as the run goes: 10000 of a 5000-disc sample reached 5.8 GB in
         * Python (2.4 GB here, copied into arrays) before the bound, 1 GiB */
        const double snap_bytes = (double)s->snapshots.n * (smp.n + 1.0) * 6 * sizeof(double);
        if (s->snapshots.n > 10000)
            rc = gw_err_set(err, GW_EINVAL, "snapshots: %d times, at most 10000", s->snapshots.n);
        else if (snap_bytes > 1073741824.0)
            rc = gw_err_set(err, GW_EINVAL, "snapshots: %d snapshots of %d particles need %.3g GB, above the 1.07 GB "
                            "limit: at most %.0f of this sample", s->snapshots.n, smp.n + 1, snap_bytes / 1e9,
                            floor(1073741824.0 / ((smp.n + 1.0) * 6 * sizeof(double))));
        else if (!(sc.req = malloc((size_t)s->snapshots.n * sizeof *sc.req)))
            rc = gw_err_set(err, GW_ENOMEM, "snapshots: out of memory");
        for (int j = 0; rc == GW_OK && j < s->snapshots.n; j++)
            sc.req[j] = (snap_req){.t = s->snapshots.v[j], .j = j};
        if (rc == GW_OK) {
            qsort(sc.req, (size_t)s->snapshots.n, sizeof *sc.req, req_cmp);
            out->nsnap = s->snapshots.n;
            ip.on_sample = take_snapshots;
            ip.sample_ctx = &sc;
        }
    }
    if (rc == GW_OK)
        rc = layer_impact_run(&smp, &lp, &ip, type, &sp, &found, &out->r, err);
    if (rc == GW_ECANCELED)
        gw_err_set(err, rc, "stopped by the progress callback");
    free(sc.req);
    if (rc == GW_ENOMEM && out->nsnap > 0 && !out->snap_t)
        gw_err_set(err, rc, "snapshots: out of memory for %d snapshots of %d particles", out->nsnap, smp.n + 1);
    if (rc != GW_OK) { /* no snapshots from a failed run */
        free(out->snap_t);
        out->snap_t = out->snap = out->particle_r = NULL;
        out->nsnap = out->nparticles = out->snap_rows = 0;
        out->block_index = -1;
    }
    if (rc == GW_OK || out->r.ns > 0) {
        out->rm = smp.rm;
        out->penetration_rm = out->r.penetration / smp.rm;
        out->froude = ip.vi / sqrt(2 * lp.gravity * ip.rb_rm * smp.rm);
        out->a_total = out->r.ns > 0 ? out->r.ledger[0].total : NAN;
        out->nregions = out->r.regions ? out->r.nrings + 2 : 0;
        out->mass_law = lp.mass_law;
        out->exact = s->exact;
        out->dt = out->r.dt;
        out->nxcorr = out->r.xcorr_delay && out->r.nrings > 1 ? out->r.nrings - 1 : 0;
        if ((out->sample_fnv1a64 = malloc(17)))
            gw_snprintf(out->sample_fnv1a64, 17, "%016llx", smp.content_hash);
        else if (rc == GW_OK)
            rc = gw_err_set(err, GW_ENOMEM, "layer-impact: out of memory");
        const size_t nu = strlen(out->r.undecided);
        if (nu > 0 && (out->undecided = malloc(nu + 1)))
            memcpy(out->undecided, out->r.undecided, nu + 1);
        else if (nu > 0 && rc == GW_OK)
            rc = gw_err_set(err, GW_ENOMEM, "layer-impact: out of memory");
        if (rc == GW_OK && ((rc = gw_layer_impact_result_warnings(&out->r, &out->warnings)) != GW_OK ||
                            (rc = layer_crowns_warning_kinds(&smp, &ip, &out->r, &out->warnings, &out->crowns_nulled)) !=
                                GW_OK ||
                            (rc = layer_energy_warning(&out->r, &ip, type, &sp, &out->warnings)) != GW_OK))
            rc = gw_err_set(err, rc, "layer-impact: out of memory");
    }
    gw_layer_impact_plan_free(&plan);
    return rc;
}
