/*
 * layer_cli.c: the option tables of the layer commands (layer_cli.h). One
 * table for an impact (docs/physics.md 2.3: R_b = rb-rm R_m, V_i, alpha_i, impact
 * abscissa, height H = height-rm R_m; B.5, B.6) used by `granwave layer-impact`
 * and by the `layer` sweep model, so a sweep case and the command resolve the
 * same options to the same gw_layer_impact call.
 * Units: SI, angles in degrees.
 */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "gw_cli.h"
#include "layer_cli.h"

int layer_mat_options(layer_mat_cli *m, gw_opt *o)
{
    m->lp = gw_layer_params_default();
    m->mass_law = "disc";
    m->clump_mass = gw_layer_clump_mass_name(GW_LAYER_CLUMP_MASS_SUM);
    int i = 0;
    /* ranges are checked by gw_layer_params_validate, so the message names the
     * physical quantity (e.g. friction outside [0, 90)) */
    o[i++] = OPT_D("friction", &m->lp.friction_deg, "PHI", "friction angle phi, deg in [0, 90) [30]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("shear-modulus", &m->lp.shear_modulus, "G", "shear modulus, Pa [40e9]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("poisson", &m->lp.poisson, "NU", "Poisson ratio [0.25]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("density", &m->lp.density, "RHO", "particle density, kg/m^3 [2650]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("gravity", &m->lp.gravity, "G", "gravity, m/s^2 [9.81]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("skin", &m->lp.skin, "S", "contact-list skin, m [0.1]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_S("mass-law", &m->mass_law, "LAW", "disc (unit thickness) or sphere [disc; impacts: the sample's]");
    o[i++] = OPT_S("clump-mass", &m->clump_mass, "HOW", "clump mass: sum (members added, overlaps twice, as PFC2D) "
                   "or union (density x the union's area; disc law) [sum; impacts: the sample's]");
    return i;
}

int layer_mat_resolve(layer_mat_cli *m, gw_err *err)
{
    if (strcmp(m->mass_law, "disc") == 0)
        m->lp.mass_law = GW_LAYER_MASS_DISC;
    else if (strcmp(m->mass_law, "sphere") == 0)
        m->lp.mass_law = GW_LAYER_MASS_SPHERE;
    else
        return gw_err_set(err, GW_EINVAL, "--mass-law: unknown '%s' (disc, sphere)", m->mass_law);
    if ((m->lp.clump_mass = gw_layer_clump_mass_parse(m->clump_mass)) < 0)
        return gw_err_set(err, GW_EINVAL, "--clump-mass: unknown '%s' (sum, union)", m->clump_mass);
    int rc = gw_layer_params_validate(&m->lp, err);
    if (rc == GW_OK || !err)
        return rc;
    /* The library names the quantity; the message names the flag too: the
     * first flag whose value alone, on the defaults, fails the same check. */
    static const struct { const char *flag; size_t off; } fields[] = {
        {"shear-modulus", offsetof(gw_layer_params, shear_modulus)}, {"poisson", offsetof(gw_layer_params, poisson)},
        {"friction", offsetof(gw_layer_params, friction_deg)}, {"density", offsetof(gw_layer_params, density)},
        {"gravity", offsetof(gw_layer_params, gravity)}, {"skin", offsetof(gw_layer_params, skin)}};
    for (size_t k = 0; k < sizeof fields / sizeof fields[0]; k++) {
        gw_layer_params one = gw_layer_params_default();
        memcpy((char *)&one + fields[k].off, (const char *)&m->lp + fields[k].off, sizeof(double));
        if (gw_layer_params_validate(&one, NULL) != GW_OK) {
            char tmp[sizeof err->msg];
            snprintf(tmp, sizeof tmp, "%s", err->msg);
            return gw_err_set(err, rc, "--%s: %s", fields[k].flag, tmp);
        }
    }
    return rc;
}

int layer_impact_options(layer_impact_cli *c, gw_opt *o)
{
    memset(c, 0, sizeof *c);
    int i = layer_mat_options(&c->m, o);
    c->ip = gw_layer_impact_params_default();
    c->solver = NULL; /* verlet, or rk4 with --exact */
    c->method = "default";
    c->dt = 0; /* auto */
    c->rtol = 1e-8;
    c->atol = 1e-8;
    c->rings = c->ip.nrings;
    c->until = gw_layer_until_name(c->ip.until);
    /* physical ranges are checked by gw_layer_impact_check (messages name the
     * quantity); the table only bounds the solver settings. An option added here must also
     * raise LAYER_IMPACT_NOPTS (layer_cli.h): callers size their tables by it. */
    o[i++] = OPT_S("sample", &c->sample, "FILE", "sample written by layer-make (required)");
    o[i++] = OPT_D("rb-rm", &c->ip.rb_rm, "R", "block radius in R_m [1]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("vi", &c->ip.vi, "V", "incident speed, m/s [20]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("alpha", &c->ip.alpha_deg, "DEG", "incidence from the normal, deg in [0, 90) [0]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("x", &c->ip.x, "X", "impact abscissa from the box centre, m [0]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("height-rm", &c->ip.height_rm, "H", "mobile layer height in R_m; deeper particles frozen [0 = all]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("gap", &c->ip.gap, "G", "initial block-target gap, m [1e-6]; < 0 = overlapping (refused)", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("t-max", &c->ip.t_max, "T", "end of the run, s [0.05]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("dt-out", &c->ip.dt_out, "DT", "sampling interval, s [2e-5]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_D("ring-width", &c->ip.ring_width, "DC", "crown width d_c, m [2 R_m]", -INFINITY, INFINITY, 0);
    o[i++] = OPT_L("rings", &c->rings, "N", "number of crowns [12]", 1, 1000);
    o[i++] = OPT_S("solver", &c->solver, "NAME", "verlet (explicit DEM, no located events), rk4, cvode or arkode [verlet; rk4 with --exact]");
    o[i++] = OPT_S("method", &c->method, "NAME", "cvode: bdf|adams; arkode: erk|dirk [default]");
    o[i++] = OPT_D("dt", &c->dt, "DT", "fixed step of verlet or rk4, s [0 = auto: verlet the shortest binary contact time / 100, rk4 1e-6]", 0, 1, 1);
    o[i++] = (gw_opt){.name = "exact", .kind = GW_OPT_FLAG, .dest = &c->exact, .help = "exact mode: RK4 (or --solver cvode|arkode) stopping at every contact and stick/slip transition, dt 1e-6 s; the reference the fast default is tested against"};
    o[i++] = OPT_D("rtol", &c->rtol, "R", "relative tolerance of cvode/arkode [1e-8]", 0, 1, 1);
    o[i++] = OPT_D("atol", &c->atol, "A", "absolute tolerance (scaled per component) [1e-8]", 0, 1, 1);
    o[i++] = OPT_D("energy-tol", &c->ip.energy_tol, "E", "stop (exit 1) when the ledger closure |sum - A|/A exceeds E [0 = off]", -INFINITY, INFINITY, 0);
    o[i++] = (gw_opt){.name = "remove-walls", .kind = GW_OPT_FLAG, .dest = &c->ip.remove_walls, .help = "take the left, right and bottom walls away at the start of the impact"};
    o[i++] = (gw_opt){.name = "full", .kind = GW_OPT_FLAG, .dest = &c->ip.full, .help = "run to t-max even after the outcome is decided (for the crowns)"};
    o[i++] = OPT_S("until", &c->until, "WHAT", "rebound: run until the rebound is complete (T_f: the block's normal velocity back to "
                   "zero after it left, physics.md 2.3) or the block is found not to bounce; verdict: stop at the bounce "
                   "verdict (e_n, e, alpha_r then null; the _first values given) [rebound]");
    return i;
}

int layer_impact_resolve(layer_impact_cli *c, gw_err *err)
{
    c->ip.nrings = (int)c->rings;
    int rc = layer_mat_resolve(&c->m, err);
    if (rc != GW_OK)
        return rc;
    if ((c->ip.until = gw_layer_until_parse(c->until)) < 0)
        return gw_err_set(err, GW_EINVAL, "--until: unknown '%s' (rebound, verdict)", c->until);
    if (c->ip.full && c->ip.until == GW_LAYER_UNTIL_VERDICT)
        return gw_err_set(err, GW_EINVAL, "--until verdict: has no effect with --full (which runs to t-max)");
    if (!c->solver)
        c->solver = c->exact ? "rk4" : "verlet";
    c->type = gw_solver_type_find(c->solver);
    if (!c->type)
        return gw_err_set(err, GW_EINVAL, "--solver: unknown solver '%s' (verlet, rk4, cvode, arkode)", c->solver);
    if (c->exact && c->type == gw_solver_verlet)
        return gw_err_set(err, GW_EINVAL, "--exact: needs a solver that locates contact events (rk4, cvode, "
                          "arkode), not verlet");
    c->sp = gw_solver_params_default();
    c->sp.method = gw_solver_method_find(c->method);
    if (c->sp.method < 0)
        return gw_err_set(err, GW_EINVAL, "--method: unknown method '%s' (bdf, adams, erk, dirk)", c->method);
    /* a method the backend does not offer would have no effect: refused here,
     * before any output, not by the solver set-up after the sample is read */
    const int m = c->sp.method, cv = c->type == gw_solver_cvode, ak = c->type == gw_solver_arkode;
    if (m != GW_METHOD_DEFAULT && !((cv && (m == GW_CVODE_BDF || m == GW_CVODE_ADAMS)) ||
                                    (ak && (m == GW_ARKODE_ERK || m == GW_ARKODE_DIRK))))
        return gw_err_set(err, GW_EINVAL, "--method: '%s' has no effect with the %s solver (cvode: bdf, adams; "
                          "arkode: erk, dirk)", c->method, c->solver);
    c->sp.dt = c->type == gw_solver_verlet ? c->dt /* 0: gw_layer_impact chooses */
             : c->type == gw_solver_rk4 ? (c->dt > 0 ? c->dt : 1e-6) : 0;
    c->sp.rtol = c->rtol;
    c->sp.atol = c->atol;
    if ((rc = gw_solver_tolerances_check(c->rtol, c->atol, "--rtol", "--atol", err)) != GW_OK)
        return rc;
    if (!c->sample)
        return gw_err_set(err, GW_EINVAL, "--sample: a sample file (from layer-make) is required");
    return GW_OK;
}

int layer_impact_use_sample(layer_impact_cli *c, const gw_opt *o, const gw_layer_sample *s, gw_err *err)
{
    c->rm = s->rm;
    /* options that would have no effect in this combination are refused */
    const int fixed_step = c->type == gw_solver_verlet || c->type == gw_solver_rk4;
    static const char *const tols[] = {"rtol", "atol"};
    for (int k = 0; k < 2; k++) {
        const gw_opt *t = gw_cli_find(o, tols[k]);
        if (fixed_step && t && t->seen)
            return gw_err_set(err, GW_EINVAL, "--%s: has no effect with the fixed-step %s solver (the tolerances "
                              "are cvode's and arkode's)", tols[k], c->solver);
    }
    const gw_opt *cmo = gw_cli_find(o, "clump-mass");
    if (cmo && cmo->seen && !s->body)
        return gw_err_set(err, GW_EINVAL, "--clump-mass: has no effect: the sample '%s' has no clumps", c->sample);
    const gw_opt *ml = gw_cli_find(o, "mass-law");
    if (!ml || !ml->seen) /* the sample's mass law unless overridden */
        c->m.lp.mass_law = s->mass_law;
    const gw_opt *cm = gw_cli_find(o, "clump-mass");
    if (!cm || !cm->seen) /* and its clump mass */
        c->m.lp.clump_mass = s->clump_mass;
    return gw_layer_impact_check(s, &c->ip, err);
}
