/*
 * chain_options.c: shared options of the chain commands (see chain_options.h).
 * Coefficients come from the materials (F.12, F.3) unless given directly:
 * --k and --kwall in N/m^1.5, --mass in kg. One validation path for every chain
 * command: impact speeds (a single --vimp, a --vimp list, --heights in mm) in
 * (0, GW_CHAIN_VIMP_MAX] m/s, tolerances in [GW_TOL_MIN, GW_TOL_MAX], and options
 * that would have no effect (--gamma without --damping kk, --alpha without
 * --damping hc, either with --restitution) refused.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_falcon.h" /* G_EARTH: falcon's --heights are drop heights in mm */
#include "chain_wall.h"

/* Physical ranges of the option table (beyond them a run overflows its step
 * count or never ends): the stiffest real contact (diamond on diamond, R = 1 m)
 * has k ~ 1e12 N/m^1.5, the softest sheet of Table 2 K_eff ~ 1e6; the beads are
 * at most 1 m and 1 t. */
#define GW_CHAIN_K_MIN 1e3
#define GW_CHAIN_K_MAX 1e14

/* Every impact speed of the command: --vimp (one value, or a list for falcon and
 * wavespeed) and falcon's --heights (mm, v = sqrt(2 g h)), checked in the list
 * parser itself so that chain, falcon, wavespeed and sweeps agree. */
static int check_speeds(const gw_opt *opts, const char *cmd, gw_err *err)
{
    char name[96];
    const gw_opt *o = gw_cli_find(opts, "vimp");
    if (o && o->kind == GW_OPT_STRING && *(const char *const *)o->dest) {
        double *v = NULL;
        int nv = 0;
        snprintf(name, sizeof name, "%s --vimp", cmd);
        int rc = gw_parse_double_list_in(*(const char *const *)o->dest, name, 0, GW_CHAIN_VIMP_MAX, 1,
                                         &v, &nv, err);
        free(v);
        if (rc != GW_OK)
            return rc;
    }
    o = gw_cli_find(opts, "heights");
    if (o && o->kind == GW_OPT_STRING && *(const char *const *)o->dest &&
        strcmp(*(const char *const *)o->dest, "none") != 0) {
        double *h = NULL;
        int nh = 0;
        double hmax = GW_CHAIN_VIMP_MAX * GW_CHAIN_VIMP_MAX / (2 * G_EARTH * 1e-3);
        snprintf(name, sizeof name, "%s --heights", cmd);
        int rc = gw_parse_double_list_in(*(const char *const *)o->dest, name, 0, hmax, 1, &h, &nh, err);
        free(h);
        if (rc != GW_OK)
            return rc;
    }
    return GW_OK;
}

/* An option given on the command line that the chosen model would ignore. */
static int check_no_effect(const chain_cli *c, const gw_opt *opts, const char *cmd, gw_err *err)
{
    int restitution = gw_cli_find(opts, "restitution")->seen;
    if (gw_cli_find(opts, "gamma")->seen) {
        if (c->params.damping != GW_DAMP_KUWABARA_KONO)
            return gw_err_set(err, GW_EINVAL, "%s --gamma: has no effect without --damping kk", cmd);
        if (restitution)
            return gw_err_set(err, GW_EINVAL, "%s --gamma: --restitution sets gamma; give one of them", cmd);
    }
    if (gw_cli_find(opts, "alpha")->seen) {
        if (c->params.damping != GW_DAMP_HUNT_CROSSLEY)
            return gw_err_set(err, GW_EINVAL, "%s --alpha: has no effect without --damping hc", cmd);
        if (restitution)
            return gw_err_set(err, GW_EINVAL, "%s --alpha: --restitution sets alpha; give one of them", cmd);
    }
    if (gw_cli_find(opts, "restitution-v")->seen && !restitution)
        return gw_err_set(err, GW_EINVAL, "%s --restitution-v: has no effect without --restitution", cmd);
    /* the sheet as a material */
    if (gw_cli_find(opts, "sheet-law")->seen && !c->sheet && !c->sheets_mode)
        return gw_err_set(err, GW_EINVAL, "%s --sheet-law: has no effect without --sheet%s", cmd,
                          strcmp(cmd, "softwall") == 0 ? " or --sheets" : "");
    static const char *const mat_opts[] = {"sheet-yield", "sheet-loss"};
    for (int i = 0; i < 2; i++) {
        if (gw_cli_find(opts, mat_opts[i])->seen && c->law != GW_SHEET_MATERIAL)
            return gw_err_set(err, GW_EINVAL, "%s --%s: has no effect without --sheet-law material", cmd,
                              mat_opts[i]);
        if (gw_cli_find(opts, mat_opts[i])->seen && c->sheets_mode)
            return gw_err_set(err, GW_EINVAL, "%s --%s: overrides one sheet's constant; give it with --sheet, "
                              "not --sheets", cmd, mat_opts[i]);
    }
    if (gw_cli_find(opts, "sheet-yield")->seen && c->sheet_yield > 0 && c->sheet_yield < 1e5)
        return gw_err_set(err, GW_EINVAL, "%s --sheet-yield: %g Pa is below any solid's yield stress "
                          "(0 = elastic, or >= 1e5 Pa)", cmd, c->sheet_yield);
    /* the sensor as a body */
    int ms = gw_cli_find(opts, "sensor-mass")->seen;
    if (!ms && gw_cli_find(opts, "sensor-stiffness")->seen)
        return gw_err_set(err, GW_EINVAL, "%s --sensor-stiffness: has no effect without --sensor-mass", cmd);
    if (!ms && gw_cli_find(opts, "sensor-damping")->seen)
        return gw_err_set(err, GW_EINVAL, "%s --sensor-damping: has no effect without --sensor-mass", cmd);
    if (ms && !gw_cli_find(opts, "sensor-stiffness")->seen)
        return gw_err_set(err, GW_EINVAL, "%s --sensor-mass: a sensor body needs --sensor-stiffness", cmd);
    return GW_OK;
}

int chain_cli_sheet(const chain_cli *c, const gw_sheet *s, gw_chain_params *p,
                    gw_layer_law **layer, gw_err *err)
{
    const gw_material *bm = gw_material_find(c->material), *wm = gw_material_find(c->wall_material);
    return gw_sheet_apply(s, c->law, c->law == GW_SHEET_MATERIAL ? c->sheet_yield : -1,
                          c->law == GW_SHEET_MATERIAL ? c->sheet_loss : -1, bm, wm, p, layer, err);
}

#define OPT_D(nm, dst, mv, hl, lo_, hi_, open_)                                          \
    (gw_opt) { .name = nm, .kind = GW_OPT_DOUBLE, .dest = dst, .metavar = mv, .help = hl, \
               .lo = lo_, .hi = hi_, .open_lo = open_ }
#define OPT_S(nm, dst, mv, hl)                                                           \
    (gw_opt) { .name = nm, .kind = GW_OPT_STRING, .dest = dst, .metavar = mv, .help = hl }

void chain_cli_options(chain_cli *c, gw_opt *o)
{
    memset(c, 0, sizeof *c);
    c->radius = 4e-3;
    c->material = "steel";
    c->wall_material = "steel";
    c->damping = "none";
    c->solver = "cvode";
    c->method = "default";
    gw_solver_params sp = gw_solver_params_default();
    /* 1e-12 on both: at the solver default 1e-10 the energy error of a 40-bead
     * column is ~3e-8 (the absolute tolerance limits it); at 1e-12, ~1e-9. */
    c->rtol = 1e-12;
    c->atol = 1e-12;
    c->sheet_law = "fitted";
    c->sheet_yield = c->sheet_loss = -1; /* the sheet's own constants */
    c->max_steps = sp.max_steps;
    int i = 0;
    o[i++] = OPT_S("material", &c->material, "NAME", "bead material (steel, rigid, brass, aluminium, glass, pmma, pvc) [steel]");
    o[i++] = OPT_D("radius", &c->radius, "R", "bead radius, m, in (0, 1] [4e-3]", 0, 1, 1);
    o[i++] = OPT_S("wall-material", &c->wall_material, "NAME", "wall material (a half-space) [steel]");
    o[i++] = OPT_S("sheet", &c->sheet, "NAME", "wall: a sheet of the paper's Table 2 (none, brass, tape, pvc, pmma, cardboard2, beech, cardboard1, rubber), by default its fitted K_eff (see --sheet-law)");
    o[i++] = OPT_S("radii", &c->radii, "R,R..", "per-bead radii, m, bead 1 first (masses and contact k from the material)");
    o[i++] = OPT_D("k", &c->k, "K", "bead-bead Hertz coefficient, N/m^1.5, in [1e3, 1e14] [from material, F.12]", GW_CHAIN_K_MIN, GW_CHAIN_K_MAX, 0);
    o[i++] = OPT_D("kwall", &c->kwall, "K", "bead-wall Hertz coefficient, N/m^1.5, in [1e3, 1e14] [from materials, F.3]", GW_CHAIN_K_MIN, GW_CHAIN_K_MAX, 0);
    o[i++] = OPT_D("mass", &c->mass, "M", "bead mass, kg, in (0, 1e3] [4/3 pi R^3 rho]", 0, 1e3, 1);
    o[i++] = OPT_D("gravity", &c->gravity, "G", "gravity toward the wall, m/s^2 [0 = off]", 0, 1e4, 0);
    o[i++] = OPT_S("damping", &c->damping, "MODEL", "none, kk (Kuwabara-Kono) or hc (Hunt-Crossley) [none]");
    o[i++] = OPT_D("gamma", &c->gamma, "G", "Kuwabara-Kono constant of bead contacts, N s/m^1.5 [0]", 0, INFINITY, 0);
    o[i++] = OPT_D("alpha", &c->alpha, "A", "Hunt-Crossley constant, s/m [0]", 0, INFINITY, 0);
    o[i++] = OPT_D("restitution", &c->restitution, "E", "calibrate gamma/alpha so one bead on the wall rebounds with E", 0, 1, 1);
    o[i++] = OPT_D("restitution-v", &c->restitution_v, "V", "impact velocity of that calibration, m/s [v_imp]", 0, 1e3, 1);
    o[i++] = OPT_S("solver", &c->solver, "NAME", "cvode, arkode or rk4 [cvode]");
    o[i++] = OPT_S("method", &c->method, "NAME", "cvode: bdf|adams; arkode: erk|dirk|imex [bdf / erk]");
    o[i++] = OPT_D("rtol", &c->rtol, "R", "relative tolerance [1e-12]", GW_TOL_MIN, GW_TOL_MAX, 0);
    o[i++] = OPT_D("atol", &c->atol, "A", "absolute tolerance in units of the overlap and velocity scales [1e-12]", GW_TOL_MIN, GW_TOL_MAX, 0);
    o[i++] = OPT_D("dt", &c->dt, "DT", "RK4 step, s [T_c/400]; initial step for cvode/arkode", 0, 1, 0);
    o[i++] = OPT_D("dt-max", &c->dt_max, "DT", "largest step, s [unlimited]", 0, 1, 0);
    o[i++] = (gw_opt){.name = "max-steps", .kind = GW_OPT_LONG, .dest = &c->max_steps, .metavar = "N",
                      .help = "internal steps allowed between outputs [1e7]", .lo = 1, .hi = 1e12};
    o[i++] = OPT_D("t-max", &c->t_max, "T", "stop after T seconds [20 (n T_q + tau_1)]", 0, 1e6, 0);
    o[i++] = OPT_D("dt-out", &c->dt_out, "DT", "sampling interval for traces, energy and F_max, s [tau_1/200]", 0, 1, 0);
    o[i++] = OPT_D("energy-tol", &c->energy_tol, "E", "abort when the relative energy error exceeds E [off]", 0, INFINITY, 0);
    o[i++] = OPT_S("sheet-law", &c->sheet_law, "LAW", "how --sheet becomes a wall: fitted (Hertz K_eff from the measured tau_max(N=1)), hertz, layer (bonded elastic layer) or material (layer with the sheet's loss; Thornton plastic for a sheet with a yield stress) [fitted]");
    o[i++] = OPT_D("sheet-yield", &c->sheet_yield, "Y", "yield stress of the sheet with --sheet-law material, Pa (0 = elastic) [the sheet's]", 0, 1e10, 0);
    o[i++] = OPT_D("sheet-loss", &c->sheet_loss, "T", "loss factor tan(delta) of the sheet with --sheet-law material (0 = elastic) [the sheet's]", 0, 2, 0);
    o[i++] = OPT_D("sensor-mass", &c->sensor_mass, "M", "the sensor as a body: mass under the wall contact, kg, in [1e-7, 1e3] [rigid sensor]", 1e-7, 1e3, 0);
    o[i++] = OPT_D("sensor-stiffness", &c->sensor_stiffness, "K", "stiffness of the sensor body, N/m, in [1e3, 1e14]", 1e3, 1e14, 0);
    o[i++] = OPT_D("sensor-damping", &c->sensor_damping, "C", "damping of the sensor body, N s/m, in [0, 1e9] [0]", 0, 1e9, 0);
    o[i++] = OPT_D("guide-friction", &c->guide_friction, "F", "Coulomb friction of each bead on its guide, N, in [0, 1] [0]", 0, 1, 0);
    o[i++] = OPT_D("guide-viscous", &c->guide_viscous, "C", "viscous friction of each bead on its guide, N s/m, in [0, 100] [0]", 0, 100, 0);
    o[i++] = (gw_opt){.name = "json", .kind = GW_OPT_FLAG, .dest = &c->json, .help = "print results as one JSON object on stdout"};
    o[i++] = OPT_S("out", &c->out, "DIR", "write CSV (and HDF5) files into DIR");
}

int chain_cli_resolve(chain_cli *c, const gw_opt *opts, const char *cmd, gw_err *err)
{
    int src = check_speeds(opts, cmd, err);
    if (src != GW_OK)
        return src;
    if (!(c->params.v_imp > 0 && c->params.v_imp <= GW_CHAIN_VIMP_MAX))
        return gw_err_set(err, GW_EINVAL, "%s --vimp: %g is outside (0, %g]", cmd, c->params.v_imp,
                          GW_CHAIN_VIMP_MAX);
    const gw_material *bm = gw_material_find(c->material);
    if (!bm || isinf(bm->density))
        return gw_err_set(err, GW_EINVAL, "%s --material: unknown or unusable bead material '%s' (known: %s; not rigid)",
                          cmd, c->material, gw_material_names());
    const gw_material *wm = gw_material_find(c->wall_material);
    if (!wm)
        return gw_err_set(err, GW_EINVAL, "%s --wall-material: unknown material '%s' (known: %s)",
                          cmd, c->wall_material, gw_material_names());
    gw_chain_params *p = &c->params;
    int n = p->n;
    double v = p->v_imp;
    *p = gw_chain_params_default();
    p->n = n;
    p->v_imp = v;
    p->radius = c->radius;
    p->mass = gw_cli_find(opts, "mass")->seen ? c->mass
                                               : 4.0 / 3.0 * M_PI * pow(c->radius, 3) * bm->density;
    p->k = gw_cli_find(opts, "k")->seen ? c->k : gw_hertz_coefficient(c->radius, bm, c->radius, bm);
    p->kwall = gw_cli_find(opts, "kwall")->seen ? c->kwall
                                                 : gw_hertz_coefficient(c->radius, bm, INFINITY, wm);
    if (c->sheet) {
        const gw_sheet *sh = gw_sheet_find(c->sheet);
        if (!sh)
            return gw_err_set(err, GW_EINVAL, "%s --sheet: unknown sheet '%s' (none, brass, tape, pvc, pmma, cardboard2, beech, cardboard1, rubber)",
                              cmd, c->sheet);
        if (gw_cli_find(opts, "kwall")->seen)
            return gw_err_set(err, GW_EINVAL, "%s --sheet: give either --sheet or --kwall", cmd);
        p->kwall = gw_sheet_kwall(sh, p->mass);
    }
    if (c->radii) {
        int nr = 0;
        chain_cli_free(c);
        if (gw_parse_double_list_in(c->radii, "--radii", 0, 1, 1, &c->radii_v, &nr, err) != GW_OK) {
            char tmp[sizeof err->msg];
            snprintf(tmp, sizeof tmp, "%s", err->msg);
            return gw_err_set(err, GW_EINVAL, "%s %s", cmd, tmp);
        }
        if (nr != n)
            return gw_err_set(err, GW_EINVAL, "%s --radii: %d radii for %d beads", cmd, nr, n);
        c->masses_v = malloc((size_t)nr * sizeof *c->masses_v);
        c->kc_v = malloc((size_t)nr * sizeof *c->kc_v);
        if (!c->masses_v || !c->kc_v)
            return gw_err_set(err, GW_ENOMEM, "%s --radii: out of memory", cmd);
        for (int i = 0; i < nr; i++) {
            double r = c->radii_v[i];
            if (!(r > 0))
                return gw_err_set(err, GW_EINVAL, "%s --radii: radius %d is %g, must be > 0", cmd, i + 1, r);
            c->masses_v[i] = 4.0 / 3.0 * M_PI * r * r * r * bm->density;
            if (i > 0)
                c->kc_v[i - 1] = gw_hertz_coefficient(c->radii_v[i - 1], bm, r, bm);
        }
        if (gw_cli_find(opts, "mass")->seen || gw_cli_find(opts, "k")->seen)
            return gw_err_set(err, GW_EINVAL, "%s --radii: derives masses and k; drop --mass and --k", cmd);
        p->masses = c->masses_v;
        p->kc = n > 1 ? c->kc_v : NULL;
        p->mass = c->masses_v[0];
        p->radius = c->radii_v[0];
        if (!gw_cli_find(opts, "kwall")->seen && !c->sheet)
            p->kwall = gw_hertz_coefficient(p->radius, bm, INFINITY, wm);
    }
    int law = gw_sheet_law_find(c->sheet_law);
    if (law < 0)
        return gw_err_set(err, GW_EINVAL, "%s --sheet-law: unknown law '%s' (fitted, hertz, layer, material)",
                          cmd, c->sheet_law);
    c->law = (gw_sheet_law)law;
    if (c->sheet && c->law != GW_SHEET_FITTED) {
        gw_layer_law_free(c->layer);
        c->layer = NULL;
        if (gw_cli_find(opts, "kwall")->seen)
            return gw_err_set(err, GW_EINVAL, "%s --sheet: give either --sheet or --kwall", cmd);
        if ((src = chain_cli_sheet(c, gw_sheet_find(c->sheet), p, &c->layer, err)) != GW_OK) {
            char tmp[sizeof err->msg];
            snprintf(tmp, sizeof tmp, "%s", err->msg);
            return gw_err_set(err, src, "%s --sheet %s: %s", cmd, c->sheet, tmp);
        }
    }
    if (p->wall.loss > 0) { /* a loss the Maxwell arms cannot give is refused here, by name */
        chain_wall_law wl;
        if (chain_wall_law_init(&wl, p, err) != GW_OK) {
            char tmp[sizeof err->msg];
            snprintf(tmp, sizeof tmp, "%s", err->msg);
            return gw_err_set(err, GW_EINVAL, "%s --sheet-loss: %s", cmd, tmp);
        }
    }
    if (isinf(p->kwall))
        return gw_err_set(err, GW_EINVAL, "%s --wall-material: a rigid wall needs a deformable bead material", cmd);
    if (gw_cli_find(opts, "sensor-mass")->seen) {
        p->sensor.mass = c->sensor_mass;
        p->sensor.stiffness = c->sensor_stiffness;
        p->sensor.damping = c->sensor_damping;
    }
    p->guide.coulomb = c->guide_friction;
    p->guide.viscous = c->guide_viscous;
    p->gravity = c->gravity;
    if (strcmp(c->damping, "none") == 0)
        p->damping = GW_DAMP_NONE;
    else if (strcmp(c->damping, "kk") == 0)
        p->damping = GW_DAMP_KUWABARA_KONO;
    else if (strcmp(c->damping, "hc") == 0)
        p->damping = GW_DAMP_HUNT_CROSSLEY;
    else
        return gw_err_set(err, GW_EINVAL, "%s --damping: unknown model '%s' (none, kk, hc)", cmd, c->damping);
    p->gamma = c->gamma;
    p->alpha = c->alpha;
    if ((src = check_no_effect(c, opts, cmd, err)) != GW_OK)
        return src;
    if ((src = gw_solver_tolerances_check(c->rtol, c->atol, "--rtol", "--atol", err)) != GW_OK) {
        char tmp[sizeof err->msg];
        snprintf(tmp, sizeof tmp, "%s", err->msg);
        return gw_err_set(err, src, "%s %s", cmd, tmp);
    }

    gw_chain_run_opts *r = &c->run;
    *r = gw_chain_run_opts_default();
    r->solver = gw_solver_type_find(c->solver);
    if (!r->solver || r->solver == gw_solver_verlet) /* (verlet: the layer's explicit DEM step) */
        return gw_err_set(err, GW_EINVAL, "%s --solver: unknown solver '%s' for the column (cvode, arkode, "
                          "rk4)", cmd, c->solver);
    int method = gw_solver_method_find(c->method);
    if (method < 0)
        return gw_err_set(err, GW_EINVAL, "%s --method: unknown method '%s' (bdf, adams, erk, dirk, imex)", cmd, c->method);
    int ok = method == GW_METHOD_DEFAULT ||
             (r->solver == gw_solver_cvode && (method == GW_CVODE_BDF || method == GW_CVODE_ADAMS)) ||
             (r->solver == gw_solver_arkode &&
              (method == GW_ARKODE_ERK || method == GW_ARKODE_DIRK || method == GW_ARKODE_IMEX));
    if (!ok)
        return gw_err_set(err, GW_EINVAL, "%s --method: '%s' is not a method of solver %s (cvode: bdf, adams; arkode: erk, dirk, imex; rk4: none)",
                          cmd, c->method, c->solver);
    r->sp.method = method;
    r->sp.rtol = c->rtol;
    r->sp.atol = c->atol;
    r->sp.dt = c->dt;
    r->sp.dt_max = c->dt_max;
    r->sp.max_steps = c->max_steps;
    r->t_max = c->t_max;
    r->dt_out = c->dt_out;
    r->energy_tol = c->energy_tol;
    int rc = gw_chain_params_validate(p, err);
    if (rc == GW_OK && gw_cli_find(opts, "restitution")->seen) {
        if (c->restitution >= 1)
            return gw_err_set(err, GW_EINVAL, "%s --restitution: %g must be below 1", cmd, c->restitution);
        if (p->damping == GW_DAMP_NONE)
            return gw_err_set(err, GW_EINVAL, "%s --restitution: needs --damping kk or hc", cmd);
        gw_chain_params q = *p;
        if (c->restitution_v > 0)
            q.v_imp = c->restitution_v;
        if (c->law != GW_SHEET_FITTED) /* a material sheet: the beads' damping on the bare sensor */
            q.kwall = gw_hertz_coefficient(p->radius, bm, INFINITY, wm);
        double cst = 0;
        rc = gw_chain_calibrate(&q, r, c->restitution, &cst, err);
        if (rc == GW_OK) {
            if (p->damping == GW_DAMP_HUNT_CROSSLEY)
                p->alpha = c->alpha = cst;
            else
                p->gamma = c->gamma = cst;
        }
    }
    if (rc != GW_OK) {
        char tmp[sizeof err->msg];
        snprintf(tmp, sizeof tmp, "%s", err->msg);
        return gw_err_set(err, rc, "%s: %s", cmd, tmp);
    }
    if (c->out) { /* before any work: a run that cannot write its results never starts */
        char name[96];
        snprintf(name, sizeof name, "%s --out", cmd);
        return gw_out_check(c->out, name, err);
    }
    return GW_OK;
}

cJSON *chain_cli_settings_json(const chain_cli *c)
{
    const gw_chain_params *p = &c->params;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "version", gw_version());
    cJSON *m = cJSON_AddObjectToObject(o, "model");
    cJSON_AddStringToObject(m, "material", c->material);
    cJSON_AddStringToObject(m, "wall_material", c->wall_material);
    if (c->sheet)
        cJSON_AddStringToObject(m, "sheet", c->sheet);
    if (c->sheet || c->sheets_mode) {
        cJSON_AddStringToObject(m, "sheet_law", gw_sheet_law_name(c->law));
        if (c->law == GW_SHEET_MATERIAL) {
            cJSON_AddNumberToObject(m, "sheet_yield_override", c->sheet_yield >= 0 ? c->sheet_yield : NAN);
            cJSON_AddNumberToObject(m, "sheet_loss_override", c->sheet_loss >= 0 ? c->sheet_loss : NAN);
        }
    }
    if (p->wall.layer)
        cJSON_AddNumberToObject(m, "wall_layer_thickness", gw_layer_law_thickness(p->wall.layer));
    if (p->wall.yield_pressure > 0)
        cJSON_AddNumberToObject(m, "wall_yield_pressure", p->wall.yield_pressure);
    if (p->wall.loss > 0)
        cJSON_AddNumberToObject(m, "wall_loss", p->wall.loss);
    if (p->sensor.mass > 0) {
        cJSON *sn = cJSON_AddObjectToObject(m, "sensor");
        cJSON_AddNumberToObject(sn, "mass", p->sensor.mass);
        cJSON_AddNumberToObject(sn, "stiffness", p->sensor.stiffness);
        cJSON_AddNumberToObject(sn, "damping", p->sensor.damping);
    }
    if (p->guide.coulomb > 0 || p->guide.viscous > 0) {
        cJSON *gd = cJSON_AddObjectToObject(m, "guide");
        cJSON_AddNumberToObject(gd, "coulomb", p->guide.coulomb);
        cJSON_AddNumberToObject(gd, "viscous", p->guide.viscous);
    }
    if (c->radii_v)
        cJSON_AddItemToObject(m, "radii", gw_json_doubles(c->radii_v, p->n));
    cJSON_AddNumberToObject(m, "radius", p->radius);
    cJSON_AddNumberToObject(m, "mass", p->mass);
    cJSON_AddNumberToObject(m, "k", p->k);
    cJSON_AddNumberToObject(m, "kwall", p->kwall);
    cJSON_AddNumberToObject(m, "gravity", p->gravity);
    cJSON_AddStringToObject(m, "damping", c->damping);
    cJSON_AddNumberToObject(m, "gamma", p->gamma);
    cJSON_AddNumberToObject(m, "alpha", p->alpha);
    cJSON_AddNumberToObject(m, "restitution_target", c->restitution > 0 ? c->restitution : NAN);
    cJSON_AddNumberToObject(m, "restitution_v", c->restitution_v > 0 ? c->restitution_v : p->v_imp);
    cJSON *s = cJSON_AddObjectToObject(o, "solver");
    cJSON_AddStringToObject(s, "name", c->solver);
    cJSON_AddStringToObject(s, "method", c->method);
    cJSON_AddNumberToObject(s, "rtol", c->run.sp.rtol);
    cJSON_AddNumberToObject(s, "atol", c->run.sp.atol);
    cJSON_AddNumberToObject(s, "dt", c->run.sp.dt);
    if (c->run.steps_per_tc > 0)
        cJSON_AddNumberToObject(s, "steps_per_tc", c->run.steps_per_tc);
    cJSON_AddNumberToObject(s, "dt_max", c->run.sp.dt_max);
    cJSON_AddNumberToObject(s, "max_steps", (double)c->run.sp.max_steps);
    cJSON_AddNumberToObject(s, "t_max", c->run.t_max);
    cJSON_AddNumberToObject(s, "dt_out", c->run.dt_out);
    return o;
}

char *chain_cli_header(const chain_cli *c, const char *cmd, int argc, char **argv)
{
    cJSON *o = chain_cli_settings_json(c);
    char *js = cJSON_PrintUnformatted(o);
    cJSON_Delete(o);
    size_t len = 256 + strlen(cmd) + (js ? strlen(js) : 0);
    for (int i = 0; i < argc; i++)
        len += strlen(argv[i]) + 1;
    char *h = malloc(len);
    if (h) {
        size_t w = (size_t)snprintf(h, len, "granwave %s\ncommand: granwave %s", gw_version(), cmd);
        for (int i = 0; i < argc && w < len; i++)
            w += (size_t)snprintf(h + w, len - w, " %s", argv[i]);
        if (w < len)
            snprintf(h + w, len - w, "\nsettings: %s", js ? js : "{}");
    }
    free(js);
    return h;
}

int chain_cli_fail(const char *msg)
{
    fprintf(stderr, "granwave %s\n", msg);
    return 2;
}

int chain_cli_parse(const char *cmd, const char *usage, const char *summary, gw_opt *opts,
                    int argc, char **argv)
{
    gw_err err = {{0}};
    int help = 0, npos = 0;
    const char *pos[1];
    if (gw_cli_parse(cmd, opts, argc, argv, &help, pos, 0, &npos, &err) != GW_OK)
        return chain_cli_fail(err.msg);
    if (help) {
        gw_cli_help(stdout, cmd, usage, summary, opts);
        return 0;
    }
    return -1;
}

void chain_cli_sweep_opts(gw_opt *opts, int *k, long *jobs, int *quiet)
{
    opts[(*k)++] = (gw_opt){.name = "jobs", .kind = GW_OPT_LONG, .dest = jobs, .metavar = "J",
                            .help = "threads [0 = one per CPU]", .lo = 0, .hi = 1024};
    opts[(*k)++] = (gw_opt){.name = "quiet", .kind = GW_OPT_FLAG, .dest = quiet,
                            .help = "no progress lines"};
}

void chain_cli_free(chain_cli *c)
{
    free(c->radii_v);
    free(c->masses_v);
    free(c->kc_v);
    c->radii_v = c->masses_v = c->kc_v = NULL;
    gw_layer_law_free(c->layer);
    c->layer = NULL;
}
