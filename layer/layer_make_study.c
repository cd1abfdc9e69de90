/*
 * layer_make_study.c: pluviation of a 2D sample (physics.md 2.2) as a library
 * call (gw_layer_study.h): the table of `granwave layer-make`'s inputs, the run
 * (gw_layer_make: polydisperse discs, radii uniform between R_min and
 * R_max = V^(1/3) R_min with mean R_m, dropped under gravity until
 * E_k < E M g R_m), the sample written when asked, and the table of results.
 * SI units, angles in degrees.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_setup_rows.h"
#include "gw_locale.h"

#define OFF(f) offsetof(gw_layer_make_setup, f)

/* the ranges of `granwave layer-make` (the final overlap check is O(n^2): 1e5
 * particles take seconds there, and days of pluviation before) */
static const gw_param make_params[] = {
    GW_LAYER_MATERIAL_ROWS("disc", "sum", "[disc]", "[sum]")
    ROW("n", GW_PARAM_LONG, n, "", 1, 100000, 0, 0, "300", "N", "number of particles [300]"),
    ROW("rm", GW_PARAM_DOUBLE, rm, "m", GW_LAYER_MAKE_RM_MIN, GW_LAYER_MAKE_RM_MAX, 0, 0, "0.325", "R", "mean particle radius R_m, m in [1e-5, 1e3] [0.325]"),
    ROW("volume-ratio", GW_PARAM_DOUBLE, volume_ratio, "", 1, 1e6, 0, 0, "10", "V", "largest/smallest particle volume [10]"),
    ROW("width-rm", GW_PARAM_DOUBLE, width_rm, "", 0, 1e6, 1, 0, "50", "W", "box width in R_m [50]"),
    ROW("seed", GW_PARAM_LONG, seed, "", 0, 9e18, 0, 0, "1", "S", "random seed [1]"),
    ROW("ke-threshold", GW_PARAM_DOUBLE, ke_threshold, "", 0, 1, 1, 0, "1e-5", "E", "stop when E_k < E * M g R_m [1e-5]"),
    ROW("t-max", GW_PARAM_DOUBLE, t_max, "s", 0, 1e4, 1, 0, "6", "T", "give up after T s simulated [6]"),
    ROW("damping", GW_PARAM_DOUBLE, damping, "s/m", 0, 1e3, 0, 0, "0.3", "A", "Hunt-Crossley alpha while settling, s/m [0.3]"),
    /* the range the pluviation takes (layer_make.c): the row said (0, 1] while
     * values below 1e-9 were refused */
    ROW("modulus-factor", GW_PARAM_DOUBLE, modulus_factor, "", GW_LAYER_MODULUS_FACTOR_MIN, 1, 0, 0, "1", "F",
        "settle with F*G (at most half of t-max) then relax with G, F in [1e-9, 1] [1]"),
    ROW("dt", GW_PARAM_DOUBLE, dt, "s", 0, 1, 1, 0, "2e-5", "DT", "fixed step, s [2e-5]"),
    CHOICE("solver", solver, "rk4,verlet", "rk4", "NAME",
           "rk4 or verlet (explicit DEM); contact events are not located while settling [rk4]"),
    ROW("height-rm", GW_PARAM_DOUBLE, height_rm, "", 0, 1e6, 0, 0, "0", "H",
        "keep the particles wholly below H R_m after settling, then settle those again "
        "(within t-max) [0 = all]"),
    {.name = "clumps", .type = GW_PARAM_FLAG, .offset = OFF(clumps), .unit = "", .min = 0, .max = 1, .def = "0",
     .help = "type B soil: n rigid clumps (aspect ratio 1-4) instead of n discs"},
    GW_PARAM_OPT_ROW("aspect-max", GW_PARAM_DOUBLE, OFF(aspect_max), "", 1, 4, 0, 0, "4", "A",
        "clumps: aspect ratio uniform in [1, A], A in [1, 4] [4]"),
    {.name = "out", .type = GW_PARAM_TEXT, .offset = OFF(out), .unit = "", .metavar = "FILE",
     .help = "sample file to write (HDF5 when it ends in .h5) [none: the sample is only returned]"},
    GW_PARAM_END};

const gw_param *gw_layer_make_setup_params(void)
{
    return make_params;
}

int gw_layer_make_setup_init(gw_layer_make_setup *s)
{
    if (!s)
        return GW_EINVAL;
    memset(s, 0, sizeof *s);
    return gw_param_init(make_params, s, NULL);
}

void gw_layer_make_setup_clear(gw_layer_make_setup *s)
{
    gw_param_clear(make_params, s);
}

#undef OFF
#define OFF(f) offsetof(gw_layer_make_outcome, f)

static const gw_param make_fields[] = {
    RI("n", sample.n, "discs in the sample"),
    RD("width", sample.width, "m", "box width"),
    RD("rm", sample.rm, "m", "mean radius R_m"),
    RD("porosity", r.porosity, "", "porosity in the window x in [0.1, 0.9] W, y in [0.1, 0.8] h"),
    RD("height", height, "m", "max(y + r)"),
    RD("height_rm", height_rm, "", "height in R_m"),
    RD("t_settle", r.t_settle, "s", "simulated settling time"),
    RD("ke_final", r.ke_final, "J", "kinetic energy at the end"),
    RF("converged", r.converged, "1: the kinetic energy, with the fall of the grains in flight, went below the "
       "threshold (ke_limit), the floor carrying 0.5 to 1.5 times the weight"),
    RD("floor_load", r.floor_load, "", "the floor's Hertz forces over the pile's weight at the end (at rest: about 1)"),
    RD("wall_load", r.wall_load, "", "the side walls' friction over the pile's weight at the end (upward; negative: "
       "pulling it down); the pile rests when floor_load or floor_load + wall_load lies in [0.5, 1.5]"),
    RD("fall_energy", r.fall_energy, "J", "what the grains in flight at the end (touching nothing) land with"),
    RD("ke_limit", r.ke_limit, "J", "the settling threshold ke-threshold M g R_m (M: the sample's mass)"),
    RD("ke_top_share", r.ke_top_share, "", "the share of ke_final the one grain (clump or disc) that moves most "
       "holds at the end, in [0, 1] (0: none moves; near 1 on a pile that did not settle: one grain still rolling "
       "or rocking on a pile at rest)"),
    RD("t_judge", r.t_judge, "s", "the settling is judged from this time on (a t-max below it cannot converge)"),
    RD("max_overlap_over_rp", r.max_overlap, "", "largest u_n / R_p at the end"),
    RI("n_removed_above_height", r.n_removed, "particles (clumps: grains) above height-rm taken away"),
    RI("n_bodies", r.n_bodies, "grains (clumps) in the sample"),
    RD("wall_time_ms", r.wall_ms, "ms", "wall-clock time"),
    {.name = "steps", .type = GW_PARAM_LONG, .offset = OFF(r.steps), .unit = "", .help = "steps"},
    {.name = "rebuilds", .type = GW_PARAM_LONG, .offset = OFF(r.rebuilds), .unit = "", .help = "contact-list rebuilds"},
    {.name = "x", .type = GW_PARAM_DARRAY, .offset = OFF(sample.x), .unit = "m", .rows = "n", .help = "disc centres x"},
    {.name = "y", .type = GW_PARAM_DARRAY, .offset = OFF(sample.y), .unit = "m", .rows = "n", .help = "disc centres y"},
    {.name = "r", .type = GW_PARAM_DARRAY, .offset = OFF(sample.r), .unit = "m", .rows = "n", .help = "disc radii"},
    {.name = "body", .type = GW_PARAM_IARRAY, .offset = OFF(sample.body), .unit = "", .rows = "n",
     .help = "clump of each disc (clumps only)"},
    {.name = "sample_fnv1a64", .type = GW_PARAM_TEXT, .offset = OFF(sample_fnv1a64), .unit = "",
     .help = "with out: FNV-1a 64 hash of the file written (what layer-impact records), else None"},
    GW_PARAM_WARNINGS(OFF(warnings)),
    GW_PARAM_END};

const gw_param *gw_layer_make_outcome_fields(void)
{
    return make_fields;
}

void gw_layer_make_outcome_free(gw_layer_make_outcome *out)
{
    if (!out)
        return;
    gw_layer_sample_free(&out->sample);
    free(out->sample_fnv1a64);
    free(out->warnings);
    memset(out, 0, sizeof *out);
}

/* The header of a written sample: version and every setting, as the run used
 * it (the optional rows not given at their defaults). */
static char *header(const gw_layer_make_setup *given, const gw_layer_make_outcome *o)
{
    gw_layer_make_setup s = *given; /* owned text shared, read only */
    cJSON *j = gw_param_resolve(make_params, &s, NULL) == GW_OK ? gw_param_json(make_params, &s) : NULL;
    char *js = j ? gw_json_string(j, 0) : NULL;
    cJSON_Delete(j);
    if (!js) /* a sample whose header left its settings out ("{}") was written */
        return NULL;
    size_t len = 512 + strlen(js);
    char *h = malloc(len);
    if (h)
        gw_snprintf(h, len, "granwave %s library gw_layer_make_run\nsettings: %s\nsettled: t = %.4g s, E_k = %.4g J, "
                 "converged %d, max overlap %.3g R_p, floor load %.4g of the weight", gw_version(), js,
                 o->r.t_settle, o->r.ke_final, o->r.converged, o->r.max_overlap, o->r.floor_load);
    free(js);
    return h;
}

int gw_layer_make_plan(const gw_layer_make_setup *given, gw_layer_params *lp_out, gw_layer_make_params *mp_out,
                       gw_err *err)
{
    /* its outputs were written through NULL once the setup passed (SIGSEGV) */
    if (!given || !lp_out || !mp_out)
        return gw_err_set(err, GW_EINVAL, "gw_layer_make_plan: %s is NULL", !given ? "s" : !lp_out ? "lp" : "mp");
    int rc = gw_param_check(make_params, given, err);
    if (rc != GW_OK)
        return rc;
    if (!(given->gravity > 0))
        return gw_err_set(err, GW_EINVAL, "gravity: pluviation needs gravity > 0 m/s^2");
    /* the clumps' rows given (at any value, their defaults' too) without clumps */
    if (gw_param_given(gw_param_find(make_params, "aspect-max"), given) && !given->clumps)
        return gw_err_set(err, GW_EINVAL, "aspect-max: shapes clumps, so it needs clumps");
    if (gw_param_given(gw_param_find(make_params, "clump-mass"), given) && !given->clumps)
        return gw_err_set(err, GW_EINVAL, "clump-mass: has no effect without clumps (a disc sample has no clumps)");
    gw_layer_make_setup r = *given; /* the values the run uses (owned text shared, read only) */
    if ((rc = gw_param_resolve(make_params, &r, err)) != GW_OK)
        return rc;
    const gw_layer_make_setup *s = &r;
    /* aspect-max 1 draws one-disc grains (layer_clump_shape): the union of a
     * clump is its disc, the same mass as the sum */
    if (gw_param_given(gw_param_find(make_params, "clump-mass"), given) && s->aspect_max == 1)
        return gw_err_set(err, GW_EINVAL, "clump-mass: has no effect with aspect-max 1 (one-disc grains: the sum "
                          "and the union of a clump's discs are the same mass)");
    if (s->out && (rc = gw_layer_sample_out_check(s->out, "out", err)) != GW_OK)
        return rc; /* before the run: a result that cannot be written is not computed */
    gw_layer_params lp = gw_layer_params_default();
    GW_LAYER_MATERIAL_TO_PARAMS(&lp, s);
    lp.mass_law = s->mass_law;
    lp.clump_mass = s->clump_mass;
    if ((rc = gw_layer_params_validate(&lp, err)) != GW_OK)
        return rc;
    gw_layer_make_params mp = gw_layer_make_params_default();
    mp.n = (int)s->n;
    mp.rm = s->rm;
    mp.volume_ratio = s->volume_ratio;
    mp.width_rm = s->width_rm;
    mp.seed = s->seed;
    mp.ke_threshold = s->ke_threshold;
    mp.t_max = s->t_max;
    mp.damping = s->damping;
    mp.modulus_factor = s->modulus_factor;
    mp.dt = s->dt;
    mp.solver = s->solver == 1 ? gw_solver_verlet : gw_solver_rk4;
    mp.height_rm = s->height_rm;
    mp.clumps = s->clumps;
    mp.aspect_max = s->aspect_max;
    *lp_out = lp;
    *mp_out = mp;
    return GW_OK;
}

int gw_layer_make_run(const gw_layer_make_setup *s, gw_layer_make_outcome *out, gw_err *err)
{
    return gw_layer_make_run_progress(s, NULL, NULL, out, err);
}

int gw_layer_make_run_progress(const gw_layer_make_setup *s, gw_progress_fn progress, void *pctx,
                               gw_layer_make_outcome *out, gw_err *err)
{
    if (out) /* emptied on every refusal, a NULL setup's too (docs/library.md) */
        memset(out, 0, sizeof *out);
    if (!s || !out)
        return gw_err_set(err, GW_EINVAL, "gw_layer_make_run: %s is NULL", !s ? "setup" : "out");
    /* a study run is a unit of work for its caller (Python, a C program): the
     * cJSON failures of an earlier call in this thread, an out-of-memory error
     * the caller went on from, are not this run's (its sample header is JSON) */
    gw_json_failures_clear();
    gw_layer_params lp;
    gw_layer_make_params mp;
    int rc = gw_layer_make_plan(s, &lp, &mp, err);
    if (rc != GW_OK)
        return rc;
    mp.progress = progress;
    mp.progress_ctx = pctx;
    if ((rc = gw_layer_make(&lp, &mp, &out->sample, &out->r, err)) != GW_OK)
        return rc;
    for (int k = 0; k < out->sample.n; k++)
        out->height = fmax(out->height, out->sample.y[k] + out->sample.r[k]);
    out->height_rm = out->height / mp.rm;
    if (s->out) {
        char *h = header(s, out);
        rc = h ? gw_layer_sample_write(&out->sample, s->out, h, err)
               : gw_err_set(err, GW_ENOMEM, "%s: out of memory for the header", s->out);
        free(h);
        unsigned long long fh = 0; /* the content written, as the program's JSON gives it */
        gw_err he = {{0}};
        int hrc = rc == GW_OK ? gw_fnv1a64_file(s->out, "sample", &fh, &he) : rc;
        if (hrc == GW_OK && !(out->sample_fnv1a64 = malloc(17)))
            hrc = GW_ENOMEM;
        if (hrc == GW_OK)
            gw_snprintf(out->sample_fnv1a64, 17, "%016llx", fh);
        else if (rc == GW_OK && hrc == GW_ENOMEM) /* the outcome would lack the hash of what it wrote */
            rc = gw_err_set(err, hrc, "%s: out of memory", s->out);
    }
    if (rc == GW_OK && (rc = gw_layer_make_result_warnings(&out->r, mp.t_max, s->out, &out->warnings)) != GW_OK)
        rc = rc == GW_ENOMEM ? gw_err_set(err, rc, "layer-make: out of memory")
                             : gw_err_set(err, rc, "layer-make: the result (converged %d, E_k %g J, floor load %g, "
                                          "t-max %g s) is not one a pluviation gives", out->r.converged,
                                          out->r.ke_final, out->r.floor_load, mp.t_max);
    return rc;
}
