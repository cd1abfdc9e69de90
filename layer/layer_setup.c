/*
 * layer_setup.c: one block impact on a 2D granular layer as a library call
 * (gw_layer_study.h): the table of its inputs, their resolution as
 * `granwave layer-impact` resolves them, the run, and the table of its results.
 * Derived numbers: Froude number Fr = V_i / sqrt(2 g R_b) (B.15) with
 * R_b = rb-rm R_m; penetration in R_m. Model: physics.md 2.1-2.4 (Hertz normal
 * force B.1, B.3, Mindlin tangential stiffness B.4, Coulomb cap B.2, ledger
 * B.7-B.14). SI units, angles in degrees.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_setup_rows.h"

_Static_assert(GW_LAYER_UNTIL_REBOUND == 0 && GW_LAYER_UNTIL_VERDICT == 1, "until choices rebound,verdict");

#define OFF(f) offsetof(gw_layer_impact_setup, f)
#define ROW(nm, ty, f, un, lo, hi, op, opx, df, mv, hl)                                           \
    {.name = nm, .type = ty, .offset = OFF(f), .unit = un, .min = lo, .max = hi, .open_min = op,    \
     .open_max = opx, .def = df, .metavar = mv, .help = hl}
#define CHOICE(nm, f, ch, df, mv, hl)                                                             \
    {.name = nm, .type = GW_PARAM_CHOICE, .offset = OFF(f), .unit = "", .def = df, .choices = ch,  \
     .metavar = mv, .help = hl}
#define FLAG(nm, f, hl) {.name = nm, .type = GW_PARAM_FLAG, .offset = OFF(f), .unit = "", .min = 0, .max = 1, \
                         .def = "0", .help = hl}


static const gw_param impact_params[] = {
    {.name = "sample", .type = GW_PARAM_TEXT, .offset = OFF(sample), .unit = "", .metavar = "FILE",
     .help = "sample written by layer-make (required)"},
    GW_LAYER_MATERIAL_ROWS(NULL, NULL, "[the sample's]", "[the sample's]")
    ROW("rb-rm", GW_PARAM_DOUBLE, rb_rm, "", 0, 1e6, 1, 0, "1", "R", "block radius in R_m [1]"),
    ROW("vi", GW_PARAM_DOUBLE, vi, "m/s", 0, 1e3, 1, 0, "20", "V", "incident speed, m/s [20]"),
    ROW("alpha", GW_PARAM_DOUBLE, alpha, "deg", 0, 90, 0, 1, "0", "DEG", "incidence from the normal, deg in [0, 90) [0]"),
    ROW("x", GW_PARAM_DOUBLE, x, "m", -1e6, 1e6, 0, 0, "0", "X", "impact abscissa from the box centre, m [0]"),
    ROW("height-rm", GW_PARAM_DOUBLE, height_rm, "", 0, 1e6, 0, 0, "0", "H",
        "mobile layer height in R_m; deeper particles frozen [0 = all]"),
    ROW("gap", GW_PARAM_DOUBLE, gap, "m", 0, 1e3, 0, 0, "1e-6", "G",
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
           "cvode: bdf|adams; arkode: erk|dirk [default]"),
    ROW("dt", GW_PARAM_DOUBLE, dt, "s", 0, 1, 0, 0, "0", "DT",
        "fixed step of verlet or rk4, s [0 = auto: verlet the shortest binary contact time / 100, rk4 1e-6]"),
    FLAG("exact", exact, "exact mode: RK4 (or solver cvode|arkode) stopping at every contact and stick/slip "
                         "transition, dt 1e-6 s; the reference the fast default is tested against"),
    ROW("rtol", GW_PARAM_DOUBLE, rtol, "", GW_TOL_MIN, GW_TOL_MAX, 0, 0, "1e-8", "R",
        "relative tolerance of cvode/arkode [1e-8]"),
    ROW("atol", GW_PARAM_DOUBLE, atol, "", GW_TOL_MIN, GW_TOL_MAX, 0, 0, "1e-8", "A",
        "absolute tolerance (scaled per component) [1e-8]"),
    ROW("energy-tol", GW_PARAM_DOUBLE, energy_tol, "", 0, 1, 0, 0, "0", "E",
        "stop (an error; the command exits 1) when the ledger closure |sum - A|/A exceeds E [0 = off]"),
    FLAG("remove-walls", remove_walls, "take the left, right and bottom walls away at the start of the impact"),
    FLAG("full", full, "run to t-max even after the outcome is decided (for the crowns)"),
    CHOICE("until", until, "rebound,verdict", "rebound", "WHAT",
           "rebound: run until the rebound is complete (T_f: the block's normal velocity back to zero after it "
           "left, physics.md 2.3) or the block is found not to bounce; verdict: stop at the bounce verdict (e_n, "
           "e, alpha_r then null; the _first values given) [rebound]"),
    GW_PARAM_END};

const gw_param *gw_layer_impact_setup_params(void)
{
    return impact_params;
}

int gw_layer_impact_setup_init(gw_layer_impact_setup *s)
{
    memset(s, 0, sizeof *s);
    return gw_param_init(impact_params, s, NULL);
}

void gw_layer_impact_setup_clear(gw_layer_impact_setup *s)
{
    gw_param_clear(impact_params, s);
}

#undef OFF
#define OFF(f) offsetof(gw_layer_impact_outcome, f)
#define RD(nm, f, un, hl) {.name = nm, .type = GW_PARAM_DOUBLE, .offset = OFF(f), .unit = un, .help = hl}
#define RI(nm, f, hl) {.name = nm, .type = GW_PARAM_INT, .offset = OFF(f), .unit = "", .help = hl}
#define RL(nm, f, hl) {.name = nm, .type = GW_PARAM_LONG, .offset = OFF(f), .unit = "", .help = hl}
#define RA(nm, f, un, r, c, names, hl)                                                       \
    {.name = nm, .type = GW_PARAM_DARRAY, .offset = OFF(f), .unit = un, .rows = r, .cols = c, \
     .choices = names, .help = hl}

static const gw_param outcome_fields[] = {
    RI("bounced", r.bounced, "1: vy changed sign and the block left all contacts"),
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
    RD("dissipated_first_contact", r.dissipated_first_contact, "", "E_d / E_incident at the end of the first contact"),
    RD("block_loss_first_contact", r.block_loss_first_contact, "", "block kinetic energy lost in the first contact / E_incident"),
    RD("dissipated_first_contact_block", r.dissipated_first_contact_block, "", "the part of it at the block's contacts"),
    RD("t_first_contact", r.t_first_contact, "s", "end of the first contact"),
    RD("contact_angle", r.contact_angle_deg, "deg", "incident velocity to block-target contact normal"),
    RD("t_contact_open", r.t_contact_open, "s", "block-target contact opening (or t_end)"),
    RD("dissipated_contact_open", r.dissipated_contact_open, "", "E_d / E_incident then"),
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
    RI("exact", exact, "1: exact mode"),
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
    GW_PARAM_END};

const gw_param *gw_layer_impact_outcome_fields(void)
{
    return outcome_fields;
}

void gw_layer_impact_outcome_free(gw_layer_impact_outcome *out)
{
    gw_layer_impact_result_free(&out->r);
    out->nregions = 0;
}

/* the name of a choice row's value ("" when not given) */
static const char *choice(const gw_layer_impact_setup *s, const char *row, char *buf, size_t n)
{
    if (gw_param_format(gw_param_find(impact_params, row), s, buf, n) < 0)
        buf[0] = '\0';
    return buf;
}

/* Materials, solver and impact parameters as layer-impact resolves them. */
static int resolve(const gw_layer_impact_setup *s, const gw_layer_sample *smp, gw_layer_params *lp,
                   gw_layer_impact_params *ip, const gw_solver_type **type, gw_solver_params *sp,
                   gw_err *err)
{
    char sname[16], mname[16];
    *lp = gw_layer_params_default();
    lp->friction_deg = s->friction;
    lp->shear_modulus = s->shear_modulus;
    lp->poisson = s->poisson;
    lp->density = s->density;
    lp->gravity = s->gravity;
    lp->skin = s->skin;
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
    sp->dt = *type == gw_solver_verlet ? s->dt /* 0: gw_layer_impact chooses */
           : *type == gw_solver_rk4 ? (s->dt > 0 ? s->dt : 1e-6) : 0;
    sp->rtol = s->rtol;
    sp->atol = s->atol;
    *ip = gw_layer_impact_params_default();
    ip->rb_rm = s->rb_rm;
    ip->vi = s->vi;
    ip->alpha_deg = s->alpha;
    ip->x = s->x;
    ip->height_rm = s->height_rm;
    ip->gap = s->gap;
    ip->t_max = s->t_max;
    ip->dt_out = s->dt_out;
    ip->ring_width = s->ring_width;
    ip->nrings = (int)s->rings;
    ip->energy_tol = s->energy_tol;
    ip->remove_walls = s->remove_walls;
    ip->full = s->full;
    ip->until = s->until;
    if (ip->full && ip->until == GW_LAYER_UNTIL_VERDICT)
        return gw_err_set(err, GW_EINVAL, "until: verdict has no effect with full (which runs to t-max)");
    return gw_layer_impact_check(smp, ip, err);
}

int gw_layer_impact_run(const gw_layer_impact_setup *s, gw_layer_impact_outcome *out, gw_err *err)
{
    memset(out, 0, sizeof *out);
    int rc = gw_param_check(impact_params, s, err);
    if (rc != GW_OK)
        return rc;
    if (!s->sample)
        return gw_err_set(err, GW_EINVAL, "sample: a sample file (from layer-make) is required");
    gw_layer_sample smp;
    if ((rc = gw_layer_sample_read(s->sample, &smp, err)) != GW_OK)
        return rc;
    gw_layer_params lp;
    gw_layer_impact_params ip;
    const gw_solver_type *type = NULL;
    gw_solver_params sp;
    rc = resolve(s, &smp, &lp, &ip, &type, &sp, err);
    if (rc == GW_OK)
        rc = gw_layer_impact(&smp, &lp, &ip, type, &sp, NULL, &out->r, err);
    if (rc == GW_OK || out->r.ns > 0) {
        out->rm = smp.rm;
        out->penetration_rm = out->r.penetration / smp.rm;
        out->froude = ip.vi / sqrt(2 * lp.gravity * ip.rb_rm * smp.rm);
        out->a_total = out->r.ns > 0 ? out->r.ledger[0].total : NAN;
        out->nregions = out->r.regions ? out->r.nrings + 2 : 0;
        out->mass_law = lp.mass_law;
        out->exact = s->exact;
        out->dt = out->r.dt;
    }
    gw_layer_sample_free(&smp);
    return rc;
}
