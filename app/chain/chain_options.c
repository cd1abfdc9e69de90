/*
 * chain_options.c: shared options of the chain commands (see chain_options.h).
 * The options are the rows of the column's parameter table (gw_chain_study.h:
 * name, help, range, default) and resolve through gw_chain_setup_resolve, the
 * library's one path: coefficients from the materials (F.12, F.3) unless given
 * directly (--k and --kwall in N/m^1.5, --mass in kg), tolerances in
 * [GW_TOL_MIN, GW_TOL_MAX], options that would have no effect (--gamma without
 * --damping kk, --alpha without --damping hc, either with --restitution)
 * refused, the sheet laws, the sensor body and guide friction. Here only what is
 * the command line's own: impact speeds as lists
 * (falcon, wavespeed: --vimp, --heights in mm) checked in [GW_CHAIN_VIMP_MIN, GW_CHAIN_VIMP_MAX]
 * m/s, messages prefixed "CMD --NAME", and the --out check.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_options.h"
#include "chain_wall.h"
#include "gw_cli.h"
#include "gw_chain_study.h"

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
        int rc = gw_parse_double_list_in(*(const char *const *)o->dest, name, GW_CHAIN_VIMP_MIN, GW_CHAIN_VIMP_MAX, 0,
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
        const gw_param *row = gw_param_find(gw_chain_falcon_setup_params(), "heights"); /* the library's range */
        snprintf(name, sizeof name, "%s --heights", cmd);
        int rc = gw_parse_double_list_in(*(const char *const *)o->dest, name, row->min, row->max, 0, &h, &nh, err);
        free(h);
        if (rc != GW_OK)
            return rc;
    }
    return GW_OK;
}

/* Where each row of the setup table (gw_chain_study.h) lands in chain_cli: the
 * command-line options are the table's rows (name, help, range, default), read
 * into chain_cli's raw fields that the commands use; chain_cli_resolve hands them
 * to gw_chain_setup_resolve, the one resolution of a column. n and vimp are the
 * commands' own options (a list in falcon and wavespeed), trace is the library's.
 * The first NBASE rows come before --json and --out in --help, the wall rows
 * (sheet law, sensor body, guide friction) after them. */
static const struct {
    const char *name;
    size_t off;
} cli_dest[] = {
    {"material", offsetof(chain_cli, material)},   {"radius", offsetof(chain_cli, radius)},
    {"wall-material", offsetof(chain_cli, wall_material)}, {"sheet", offsetof(chain_cli, sheet)},
    {"radii", offsetof(chain_cli, radii)},         {"k", offsetof(chain_cli, k)},
    {"kwall", offsetof(chain_cli, kwall)},         {"mass", offsetof(chain_cli, mass)},
    {"gravity", offsetof(chain_cli, gravity)},     {"damping", offsetof(chain_cli, damping)},
    {"gamma", offsetof(chain_cli, gamma)},         {"alpha", offsetof(chain_cli, alpha)},
    {"restitution", offsetof(chain_cli, restitution)}, {"restitution-v", offsetof(chain_cli, restitution_v)},
    {"solver", offsetof(chain_cli, solver)},       {"method", offsetof(chain_cli, method)},
    {"rtol", offsetof(chain_cli, rtol)},           {"atol", offsetof(chain_cli, atol)},
    {"dt", offsetof(chain_cli, dt)},               {"dt-max", offsetof(chain_cli, dt_max)},
    {"max-steps", offsetof(chain_cli, max_steps)}, {"t-max", offsetof(chain_cli, t_max)},
    {"dt-out", offsetof(chain_cli, dt_out)},       {"energy-tol", offsetof(chain_cli, energy_tol)},
    {"sheet-law", offsetof(chain_cli, sheet_law)}, {"sheet-yield", offsetof(chain_cli, sheet_yield)},
    {"sheet-loss", offsetof(chain_cli, sheet_loss)}, {"sensor-mass", offsetof(chain_cli, sensor_mass)},
    {"sensor-stiffness", offsetof(chain_cli, sensor_stiffness)},
    {"sensor-damping", offsetof(chain_cli, sensor_damping)},
    {"guide-friction", offsetof(chain_cli, guide_friction)}, {"guide-viscous", offsetof(chain_cli, guide_viscous)}};
#define NDEST (sizeof cli_dest / sizeof cli_dest[0])
#define NBASE 24
_Static_assert(NDEST + 2 == CHAIN_CLI_NOPTS, "chain_cli options: the table's rows, --json and --out");

void chain_cli_options(chain_cli *c, gw_opt *o)
{
    memset(c, 0, sizeof *c);
    for (size_t i = 0; i < NDEST; i++) {
        const gw_param *p = gw_param_find(gw_chain_setup_params(), cli_dest[i].name);
        void *dest = (char *)c + cli_dest[i].off;
        gw_opt *x = &o[i < NBASE ? i : i + 2];
        *x = (gw_opt){.name = p->name, .dest = dest, .metavar = p->metavar, .help = p->help,
                      .lo = p->min, .hi = p->max, .open_lo = p->open_min,
                      .open_hi = p->open_max};
        if (p->type == GW_PARAM_DOUBLE || p->type == GW_PARAM_COUNT) {
            x->kind = p->type == GW_PARAM_COUNT ? GW_OPT_COUNT : GW_OPT_DOUBLE;
            *(double *)dest = p->def ? strtod(p->def, NULL) : 0;
        } else if (p->type == GW_PARAM_LONG) {
            x->kind = GW_OPT_LONG;
            *(long *)dest = p->def ? strtol(p->def, NULL, 10) : 0;
        } else { /* choices and the radii list: text, resolved by the table */
            x->kind = GW_OPT_STRING;
            *(const char **)dest = p->def;
        }
    }
    o[NBASE] = (gw_opt){.name = "json", .kind = GW_OPT_FLAG, .dest = &c->json, .help = "print results as one JSON object on stdout"};
    o[NBASE + 1] = (gw_opt){.name = "out", .kind = GW_OPT_STRING, .dest = &c->out, .metavar = "DIR",
                            .help = "write CSV (and HDF5) files into DIR"}; /* each command names its files: chain_cli_out_help */
    c->sheet_yield = c->sheet_loss = -1; /* the sheet's own constants */
}

void chain_cli_out_help(gw_opt *o, const char *help)
{
    o[NBASE + 1].help = help;
}

void chain_cli_opt_help(gw_opt *o, const char *name, const char *help)
{
    for (; o->name; o++)
        if (strcmp(o->name, name) == 0)
            o->help = help;
}

int chain_cli_sheet(const chain_cli *c, const gw_sheet *s, gw_chain_params *p,
                    gw_layer_law **layer, gw_err *err)
{
    const gw_material *bm = gw_material_find(c->material), *wm = gw_material_find(c->wall_material);
    return gw_sheet_apply(s, c->law, c->law == GW_SHEET_MATERIAL ? c->sheet_yield : -1,
                          c->law == GW_SHEET_MATERIAL ? c->sheet_loss : -1, bm, wm, p, layer, err);
}

/* "NAME: reason" from the library as "CMD --NAME: reason"; other messages as
 * "CMD: message". */
static int cli_error(const char *cmd, int rc, gw_err *err)
{
    char tmp[sizeof err->msg];
    snprintf(tmp, sizeof tmp, "%s", err->msg);
    const char *colon = strchr(tmp, ':');
    int named = 0;
    if (colon) {
        char name[64];
        size_t n = (size_t)(colon - tmp);
        if (n < sizeof name) {
            memcpy(name, tmp, n);
            name[n] = '\0';
            named = gw_param_find(gw_chain_setup_params(), name) && strcmp(name, "trace") != 0;
        }
    }
    return gw_err_set(err, rc, named ? "%s --%s" : "%s: %s", cmd, tmp);
}

/* The raw options into a setup: given options and text values over the table's
 * defaults (so an option not given keeps the library's default or "not given"). */
static int cli_setup(const chain_cli *c, const gw_opt *opts, gw_chain_setup *s, gw_err *err)
{
    const gw_param *t = gw_chain_setup_params();
    if (gw_chain_setup_init(s) != GW_OK)
        return gw_err_set(err, GW_ENOMEM, "out of memory");
    s->n = c->params.n;
    s->vimp = c->params.v_imp;
    s->sheets = c->sheets_mode;
    for (size_t i = 0; i < NDEST; i++) {
        const gw_param *p = gw_param_find(t, cli_dest[i].name);
        const gw_opt *o = gw_cli_find(opts, cli_dest[i].name);
        const void *src = (const char *)c + cli_dest[i].off;
        void *dst = (char *)s + p->offset;
        int rc = GW_OK;
        if (p->type == GW_PARAM_DOUBLE || p->type == GW_PARAM_COUNT) {
            if (o->seen)
                *(double *)dst = *(const double *)src;
        } else if (p->type == GW_PARAM_LONG) {
            if (o->seen)
                *(long *)dst = *(const long *)src;
        } else if (o->seen && *(const char *const *)src) { /* given: an optional row's default too */
            rc = gw_param_set(t, s, p->name, *(const char *const *)src, err);
        }
        if (rc != GW_OK)
            return rc;
    }
    return GW_OK;
}

int chain_cli_resolve(chain_cli *c, const gw_opt *opts, const char *cmd, gw_err *err)
{
    int rc = check_speeds(opts, cmd, err);
    if (rc != GW_OK)
        return rc;
    gw_chain_setup s;
    gw_chain_resolved r;
    memset(&r, 0, sizeof r);
    chain_cli_free(c);
    rc = cli_setup(c, opts, &s, err);
    if (rc == GW_OK)
        rc = gw_chain_setup_resolve(&s, &r, err);
    if (rc == GW_OK && strcmp(cmd, "chain") == 0) /* a single run's one bead (the drop's: its study) */
        rc = chain_one_body_check(&s, r.params.n, err);
    if (rc == GW_OK && s.radii.n > 0) { /* the radii for the settings JSON */
        c->radii_v = s.radii.v;
        s.radii.v = NULL;
        s.radii.n = 0;
    }
    gw_chain_setup_clear(&s);
    c->masses_v = r.masses; /* owned by c from here (chain_cli_free) */
    c->kc_v = r.kc;
    c->layer = r.layer; /* owned by c from here */
    if (rc != GW_OK)
        return cli_error(cmd, rc, err);
    c->params = r.params;
    c->run = r.run;
    if (!c->solver) /* not given: the solver the library resolved (cvode) */
        c->solver = gw_solver_type_name(r.run.solver);
    if (!c->method)
        c->method = "default";
    c->law = r.law;
    c->gamma = r.params.gamma; /* calibrated by --restitution */
    c->alpha = r.params.alpha;
    if (!gw_cli_find(opts, "sheet-yield")->seen) /* the sheet's own constants */
        c->sheet_yield = -1;
    if (!gw_cli_find(opts, "sheet-loss")->seen)
        c->sheet_loss = -1;
    if (c->out) { /* before any work: a run that cannot write its results never starts */
        char name[96];
        snprintf(name, sizeof name, "%s --out", cmd);
        int rc = gw_out_check(c->out, name, err);
        return rc == GW_OK && c->out_names ? gw_out_names_check(c->out, c->out_names, name, err) : rc;
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
    cJSON_AddStringToObject(s, "method", gw_solver_method_used(c->run.solver ? c->run.solver : gw_solver_cvode,
                                                               c->run.sp.method));
    /* rk4 has no error test: its run used no tolerance (null, as the library's
     * run_rtol is NaN under rk4); falcon's --accuracy ran rk4 while the rows
     * held cvode's 1e-12, which the settings recorded as run */
    const int rk4 = c->run.solver == gw_solver_rk4 || (c->solver && strcmp(c->solver, "rk4") == 0);
    cJSON_AddNumberToObject(s, "rtol", rk4 ? NAN : c->run.sp.rtol);
    cJSON_AddNumberToObject(s, "atol", rk4 ? NAN : c->run.sp.atol);
    cJSON_AddNumberToObject(s, "dt", c->run.sp.dt);
    /* the --dt given (0: none): a run's settings replace dt by the step it took
     * (chain_cli_settings_run, _runs), which a dt above dt-max (or rk4's dt-out)
     * is not */
    cJSON_AddNumberToObject(s, "dt_given", c->run.sp.dt);
    if (c->run.steps_per_tc > 0)
        cJSON_AddNumberToObject(s, "steps_per_tc", c->run.steps_per_tc);
    cJSON_AddNumberToObject(s, "dt_max", c->run.sp.dt_max);
    cJSON_AddNumberToObject(s, "max_steps", (double)c->run.sp.max_steps);
    cJSON_AddNumberToObject(s, "t_max", c->run.t_max);
    cJSON_AddNumberToObject(s, "dt_out", c->run.dt_out);
    cJSON_AddNumberToObject(s, "energy_tol", c->run.energy_tol);
    return o;
}

void chain_cli_settings_run(cJSON *settings, const gw_chain_result *r)
{
    cJSON *s = cJSON_GetObjectItemCaseSensitive(settings, "solver");
    const struct {
        const char *key;
        double v;
    } used[] = {{"dt", r->run_dt}, {"dt_max", r->run_dt_max}, {"t_max", r->run_t_max}, {"dt_out", r->run_dt_out}};
    for (size_t i = 0; s && i < sizeof used / sizeof used[0]; i++)
        cJSON_ReplaceItemInObjectCaseSensitive(s, used[i].key, cJSON_CreateNumber(used[i].v));
}

void chain_cli_settings_runs(cJSON *settings, long nrun, const double *t_max, const double *dt_out,
                             const double *dt, const double *dt_max)
{
    cJSON *s = cJSON_GetObjectItemCaseSensitive(settings, "solver");
    cJSON *runs = cJSON_AddObjectToObject(settings, "runs");
    const struct {
        const char *key;
        const double *v;
    } per[] = {{"t_max", t_max}, {"dt_out", dt_out}, {"dt", dt}, {"dt_max", dt_max}};
    for (size_t i = 0; s && runs && i < sizeof per / sizeof per[0]; i++) {
        int same = nrun > 0;
        for (long k = 1; same && k < nrun; k++)
            same = per[i].v[k] == per[i].v[0];
        cJSON_ReplaceItemInObjectCaseSensitive(s, per[i].key, same ? cJSON_CreateNumber(per[i].v[0]) : cJSON_CreateNull());
        cJSON_AddItemToObject(runs, per[i].key, gw_json_doubles(per[i].v, (int)nrun));
    }
}

char *chain_cli_header(const chain_cli *c, const char *cmd, int argc, char **argv)
{
    cJSON *o = chain_cli_settings_json(c);
    char *h = gw_cli_provenance(cmd, argc, argv, o);
    cJSON_Delete(o);
    return h;
}

int chain_cli_fail(const char *msg)
{
    fprintf(stderr, "granwave %s\n", msg);
    return 2;
}

/* exit 1 for a run's failure (a solver, a limit, the energy monitor, memory), else 2 */
static int fail_status(int rc)
{
    return rc == GW_ESOLVER || rc == GW_ELIMIT || rc == GW_EENERGY || rc == GW_ENOMEM ? 1 : 2;
}

int chain_cli_fail_rc(int rc, const char *msg)
{
    fprintf(stderr, "granwave %s\n", msg);
    return fail_status(rc);
}

int chain_cli_study_fail(const char *cmd, int rc, const char *msg)
{
    fprintf(stderr, "granwave %s --%s\n", cmd, msg);
    return fail_status(rc);
}

int chain_cli_parse(const char *cmd, const char *usage, const char *summary, gw_opt *opts,
                    int argc, char **argv)
{
    gw_err err = {{0}};
    int help = 0, npos = 0;
    const char *pos[1];
    if (gw_cli_parse(cmd, opts, argc, argv, &help, pos, 0, &npos, &err) != GW_OK)
        return chain_cli_fail(err.msg);
    if (help)
        return gw_cli_help(stdout, cmd, usage, summary, opts, help);
    return -1;
}

void chain_cli_sweep_opts(gw_opt *opts, int *k, long *jobs, int *quiet)
{
    opts[(*k)++] = (gw_opt){.name = "jobs", .kind = GW_OPT_LONG, .dest = jobs, .metavar = "J",
                            .help = "threads [0 = one per CPU]", .lo = 0, .hi = 1024};
    opts[(*k)++] = (gw_opt){.name = "quiet", .kind = GW_OPT_FLAG, .dest = quiet,
                            .help = "no progress lines"};
    /* the shared rows list --radii, which a study cannot take: its help said
     * "per-bead radii" and the run refused it, even at --n 3:3 */
    opts[*k] = (gw_opt){0};
    chain_cli_opt_help(opts, "radii", "not taken by a study: its columns have several sizes, per-bead radii "
                       "fit one (granwave chain takes them)");
}

int chain_cli_study_radii(const char *cmd)
{
    char msg[200];
    snprintf(msg, sizeof msg, "%s --radii: a study runs columns of several sizes N (even --n A:A is a range), "
             "and per-bead radii fit one column: use granwave chain", cmd);
    return chain_cli_fail(msg);
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

