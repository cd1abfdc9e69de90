/*
 * layer_cmd.c: the commands `granwave layer-make` (pluviation, docs/physics.md 2.2)
 * and `granwave layer-impact` (one block impact, docs/physics.md 2.3-2.5; B.5-B.18).
 * Option tables (gw_cli), JSON results (cJSON) and the --out files: ledger.csv
 * (energy ledger B.7-B.14 over time), crowns.csv (per-ring strain, kinetic
 * energy and coordination over time), crowns_peaks.csv (peak times and the
 * cross-correlation delays), crowns_spectra.csv (per-ring power spectra),
 * impact.json and VTK snapshots. Every output records the version, the parameters and the solver.
 * Exit codes: 0 ok, 1 run failure, 2 bad input (one line naming the input).
 * Units: SI; angles in degrees on the command line.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gw_cli.h"
#include "layer_cli.h"
#include "layer_plan_run.h"

static cJSON *mat_json(const gw_layer_params *p)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "shear_modulus", p->shear_modulus);
    cJSON_AddNumberToObject(o, "poisson", p->poisson);
    cJSON_AddNumberToObject(o, "friction_deg", p->friction_deg);
    cJSON_AddNumberToObject(o, "density", p->density);
    cJSON_AddNumberToObject(o, "gravity", p->gravity);
    cJSON_AddNumberToObject(o, "skin", p->skin);
    cJSON_AddNumberToObject(o, "normal_damping", p->damping);
    cJSON_AddStringToObject(o, "mass_law", gw_layer_mass_law_name(p->mass_law));
    cJSON_AddStringToObject(o, "clump_mass", gw_layer_clump_mass_name(p->clump_mass));
    cJSON_AddStringToObject(o, "contact_law", "Hertz-Mindlin B.1-B.4, R_p = 2RaRb/(Ra+Rb), R_ball at walls");
    return o;
}

/* One line on stderr, exit status 2; a message that already names the command
 * (the option parser's "layer-impact --vi: ...") is not prefixed twice. */
static int fail(const char *cmd, const char *msg)
{
    gw_cli_error(cmd, msg);
    return 2;
}

/* fail, but exit 1 when the status is out of memory (a run failure, not the
 * input: "granwave layer-impact: sample '...': out of memory for 12 particles"
 * ended 2, as if the sample were bad). */
static int fail_rc(const char *cmd, int rc, const char *msg)
{
    int code = fail(cmd, msg);
    return rc == GW_ENOMEM ? 1 : code;
}

/* ------------------------------------------------------------ layer-make --- */

/* A progress line on stderr every PROGRESS_MS of wall time once a run has
 * lasted that long: the simulated time reached (layer-make, layer-impact;
 * --quiet: none). Printed on a terminal only before, so a pluviation of 300
 * discs in a pipe or a log (18 s on a loaded machine, a thousand discs
 * minutes) said nothing until its end, where every chain command speaks.
 * GW_PROGRESS_MS, when set, replaces it (gw_cli_progress_ms). */
#define PROGRESS_MS 3000.0
typedef struct sim_progress {
    const char *cmd, *until; /* "layer-make", "until the pile settles" */
    double t_max, wall0, last;
} sim_progress;

static sim_progress sim_progress_start(const char *cmd, const char *until, double t_max)
{
    const double now = gw_clock_ms();
    return (sim_progress){.cmd = cmd, .until = until, .t_max = t_max, .wall0 = now, .last = now};
}

static void sim_progress_report(sim_progress *p, double t)
{
    const double now = gw_clock_ms();
    if (now - p->last < gw_cli_progress_ms(PROGRESS_MS))
        return;
    fprintf(stderr, "granwave %s: t = %.4g s simulated (%s, at most t-max %g s), %.0f s elapsed\n", p->cmd, t,
            p->until, p->t_max, (now - p->wall0) / 1e3);
    p->last = now;
}

/* layer-make's progress (gw_layer_make_params.progress: done in hundredths of a
 * second simulated) */
static int make_report(void *ctx, long done, long total)
{
    (void)total;
    sim_progress_report(ctx, 0.01 * (double)done);
    return 0;
}

static const char *make_summary =
    "Pluviate a 2D sample (Bourrier et al. 2008, docs/physics.md 2.2): polydisperse discs\n"
    "dropped under gravity in a box with rigid walls until the kinetic energy is below\n"
    "a threshold; Hertz-Mindlin contacts with friction, Hunt-Crossley normal damping\n"
    "while settling. Writes the text sample format of gw_layer.h. Deterministic for a\n"
    "seed. SI units. --clumps: type B soil, n rigid clumps of overlapping discs\n"
    "(quasi-rectangular, aspect ratio uniform in [1, A] with A = --aspect-max, 4 by\n"
    "default; equivalent radius on the discs' grading curve); the sample then carries\n"
    "a body id per disc.";

/* Every setting of a pluviation, defaults included (the JSON "settings" and
 * the sample's header). */
static cJSON *make_settings(const gw_layer_make_params *mp, const gw_layer_params *lp)
{
    cJSON *st = cJSON_CreateObject();
    cJSON_AddNumberToObject(st, "n", mp->n);
    cJSON_AddNumberToObject(st, "rm", mp->rm);
    cJSON_AddNumberToObject(st, "volume_ratio", mp->volume_ratio);
    cJSON_AddNumberToObject(st, "width_rm", mp->width_rm);
    cJSON_AddNumberToObject(st, "seed", (double)mp->seed);
    cJSON_AddNumberToObject(st, "ke_threshold", mp->ke_threshold);
    cJSON_AddNumberToObject(st, "t_max", mp->t_max);
    cJSON_AddNumberToObject(st, "damping", mp->damping);
    cJSON_AddNumberToObject(st, "modulus_factor", mp->modulus_factor);
    cJSON_AddStringToObject(st, "solver", gw_solver_type_name(mp->solver));
    cJSON_AddBoolToObject(st, "contact_events_located", 0);
    cJSON_AddNumberToObject(st, "dt", mp->dt);
    cJSON_AddNumberToObject(st, "height_rm", mp->height_rm);
    cJSON_AddBoolToObject(st, "clumps", mp->clumps);
    cJSON_AddNumberToObject(st, "aspect_max", mp->aspect_max);
    cJSON_AddItemToObject(st, "material", mat_json(lp));
    return st;
}

int gw_cmd_layer_make(int argc, char **argv)
{
    layer_make_cli c;
    gw_opt o[LAYER_MAKE_NOPTS + 2];
    int i = layer_make_options(&c, o); /* the rows of the library's table (layer_make_study.c) */
    int quiet = 0;
    o[i++] = (gw_opt){.name = "quiet", .kind = GW_OPT_FLAG, .dest = &quiet,
                      .help = "no progress lines (a run that lasts 3 s or more reports on stderr)"};
    o[i] = (gw_opt){0};
    layer_mat_cli m;
    gw_layer_make_params mp;
    const char *out, *solver;
    gw_err err = {{0}};
    int help = 0, npos = 0;
    const char *pos[1];
    if (layer_opts_ok(o, &err) != GW_OK || gw_cli_parse("layer-make", o, argc, argv, &help, pos, 0, &npos, &err) != GW_OK)
        return fail("layer-make", err.msg);
    if (help)
        return gw_cli_help(stdout, "layer-make", "granwave layer-make --out FILE [options]", make_summary, o, help);
    /* the library's setup from the same command line, checked and resolved by
     * the library (gw_layer_make_plan): what Python's layer_make does */
    if (!c.out)
        return fail("layer-make", "layer-make --out: the sample file to write is required");
    gw_layer_make_setup st;
    if (gw_layer_make_setup_init(&st) != GW_OK) {
        gw_layer_make_setup_clear(&st);
        return gw_cli_nomem("layer-make");
    }
    int prc = gw_cli_study_setup(gw_layer_make_setup_params(), &st, o, argc, argv, "layer-make", &err);
    if (prc == GW_OK && (prc = gw_layer_make_plan(&st, &m.lp, &mp, &err)) != GW_OK)
        gw_cli_study_error(gw_layer_make_setup_params(), "layer-make", prc, &err); /* "NAME:" -> "--NAME:" */
    gw_layer_make_setup_clear(&st);
    if (prc != GW_OK)
        return fail_rc("layer-make", prc, err.msg);
    out = c.out;
    solver = gw_solver_type_name(mp.solver);
    const int json = c.json;
    gw_layer_sample s;
    gw_layer_make_result r;
    /* a line every PROGRESS_MS of wall time once the run has lasted that long
     * (a pluviation of 1000 discs takes minutes); --quiet: none */
    sim_progress mpr = sim_progress_start("layer-make", "until the pile settles", mp.t_max);
    if (!quiet) {
        mp.progress = make_report;
        mp.progress_ctx = &mpr;
    }
    int rc = gw_layer_make(&m.lp, &mp, &s, &r, &err);
    if (rc == GW_EINVAL) { /* a value refused by the run ("dt: ..."): named as its flag */
        gw_cli_study_error(gw_layer_make_setup_params(), "layer-make", rc, &err);
        return fail("layer-make", err.msg);
    }
    if (rc != GW_OK) { /* the library's "layer-make: out of memory" said once */
        gw_cli_error("layer-make", err.msg);
        return 1;
    }
    cJSON *settings = make_settings(&mp, &m.lp);
    char *hdr = gw_cli_provenance("layer-make", argc, argv, settings);
    size_t ilen = (hdr ? strlen(hdr) : 0) + 512;
    char *info = malloc(ilen);
    if (info)
        snprintf(info, ilen, "%s\nsettled: t = %.4g s, E_k = %.4g J, converged %d, max overlap %.3g R_p, floor "
                 "load %.4g of the weight; mass law %s, clump mass %s; settling damping alpha = %g s/m, modulus "
                 "factor %g, %s dt = %g s",
                 hdr ? hdr : "", r.t_settle, r.ke_final, r.converged, r.max_overlap, r.floor_load,
                 gw_layer_mass_law_name(m.lp.mass_law), gw_layer_clump_mass_name(m.lp.clump_mass), mp.damping,
                 mp.modulus_factor, solver, mp.dt);
    /* no header (out of memory for it): the sample would not record its settings */
    rc = info && hdr ? gw_layer_sample_write(&s, out, info, &err) : gw_err_set(&err, GW_ENOMEM, "out of memory");
    free(hdr);
    free(info);
    if (rc != GW_OK) {
        gw_layer_sample_free(&s);
        cJSON_Delete(settings);
        fprintf(stderr, "granwave layer-make --out: %s\n", err.msg);
        return 1;
    }
    /* written: a pile not settled (its header says converged 0), a trim that
     * took nothing away; the library's texts (out of memory for them: none),
     * on stderr and in --json's warnings */
    char *mw = NULL;
    (void)gw_layer_make_result_warnings(&r, mp.t_max, out, &mw);
    gw_cli_warnings("layer-make", mw);
    double h = 0;
    for (int k = 0; k < s.n; k++)
        h = fmax(h, s.y[k] + s.r[k]);
    int code = 0;
    if (json) {
        cJSON *j = cJSON_CreateObject();
        cJSON_AddStringToObject(j, "version", gw_version());
        cJSON_AddStringToObject(j, "sample", out);
        unsigned long long fh = 0; /* the content written: what layer-impact records */
        char hx[17] = "";
        gw_err he = {{0}};
        int hrc = gw_fnv1a64_file(out, "sample", &fh, &he);
        if (hrc == GW_OK)
            snprintf(hx, sizeof hx, "%016llx", fh);
        else if (hrc == GW_ENOMEM) { /* out of memory, not a hash the file lacks: no JSON (exit 1) */
            cJSON_Delete(j);
            j = NULL;
        }
        if (hx[0])
            cJSON_AddStringToObject(j, "sample_fnv1a64", hx);
        else
            cJSON_AddNullToObject(j, "sample_fnv1a64");
        cJSON_AddNumberToObject(j, "n", s.n);
        cJSON_AddNumberToObject(j, "n_removed_above_height", r.n_removed);
        if (mp.clumps) { /* type B: n counts discs, n_bodies the clumps */
            cJSON_AddBoolToObject(j, "clumps", 1);
            cJSON_AddNumberToObject(j, "n_bodies", r.n_bodies);
            cJSON_AddNumberToObject(j, "aspect_max", mp.aspect_max);
        }
        cJSON_AddNumberToObject(j, "porosity", r.porosity);
        cJSON_AddNumberToObject(j, "height", h);
        cJSON_AddNumberToObject(j, "height_rm", h / mp.rm);
        cJSON_AddNumberToObject(j, "width", s.width);
        cJSON_AddNumberToObject(j, "t_settle", r.t_settle);
        cJSON_AddNumberToObject(j, "ke_final", r.ke_final);
        cJSON_AddBoolToObject(j, "converged", r.converged);
        cJSON_AddNumberToObject(j, "t_judge", r.t_judge);
        cJSON_AddNumberToObject(j, "max_overlap_over_rp", r.max_overlap);
        cJSON_AddNumberToObject(j, "floor_load", r.floor_load);
        cJSON_AddNumberToObject(j, "wall_load", r.wall_load);
        cJSON_AddNumberToObject(j, "fall_energy", r.fall_energy);
        cJSON_AddNumberToObject(j, "ke_limit", r.ke_limit);
        cJSON_AddNumberToObject(j, "ke_top_share", r.ke_top_share);
        cJSON_AddNumberToObject(j, "steps", (double)r.steps);
        cJSON_AddNumberToObject(j, "rebuilds", (double)r.rebuilds);
        cJSON_AddNumberToObject(j, "wall_time_ms", r.wall_ms);
        cJSON_AddItemToObject(j, "settings", settings);
        if (!j)
            cJSON_Delete(settings);
        settings = NULL;
        gw_cli_json_warnings(j, mw);
        code = gw_cli_json_stdout("layer-make", j);
        cJSON_Delete(j);
    } else {
        char por[48] = "porosity not measured (no disc in its window)"; /* NaN: a warning says why */
        if (!isnan(r.porosity))
            snprintf(por, sizeof por, "porosity %.4f", r.porosity);
        printf("granwave %s layer-make: %d particles, %s, height %.3f m (%.2f R_m)\n", gw_version(), s.n, por, h,
               h / mp.rm);
        if (mp.clumps)
            printf("  type B: %d rigid clumps of %d discs, aspect ratio in [1, %g], clump mass %s\n", r.n_bodies,
                   s.n, mp.aspect_max, gw_layer_clump_mass_name(m.lp.clump_mass));
        if (r.n_removed > 0)
            printf("  %d particles above %g R_m removed after settling\n", r.n_removed, mp.height_rm);
        printf("  settled in %.3g s simulated (%s), E_k = %.3g J, max overlap %.3g R_p, floor load %.3g of the "
               "weight\n", r.t_settle, r.converged ? "converged" : "NOT converged: t-max reached", r.ke_final,
               r.max_overlap, r.floor_load);
        printf("  mass law %s; settling: Hunt-Crossley alpha %g s/m, modulus factor %g; %s dt %g s\n",
               gw_layer_mass_law_name(m.lp.mass_law), mp.damping, mp.modulus_factor, solver, mp.dt);
        char q[GW_CLI_PATH_TEXT];
        printf("  wall time %.0f ms, %ld steps, %ld list rebuilds; written to %s\n", r.wall_ms, r.steps,
               r.rebuilds, gw_cli_path(q, sizeof q, out));
    }
    free(mw);
    gw_layer_sample_free(&s);
    cJSON_Delete(settings);
    return code;
}

/* ---------------------------------------------------------- layer-impact --- */

static const char *impact_summary =
    "One block impact on a 2D granular layer (Bourrier et al. 2008, docs/physics.md 2.3):\n"
    "a disc of radius rb-rm * R_m hits the sample at speed vi and incidence alpha.\n"
    "Reports bouncing, restitution (e_n, e, alpha_r), penetration, the energy ledger\n"
    "closure, the friction loss of the first contact and the wave speed from crowns.\n"
    "SI units, angles in degrees.";

/* The impact options are shared with the layer sweep model (layer_cli.c). */
typedef layer_impact_cli impact_cli;

/* nulled: the rules that left a crown speed null with a warning
 * (GW_LAYER_NULLED_*, gw_layer_impact_outcome.crowns_nulled) */
static cJSON *impact_json(const impact_cli *c, const gw_layer_impact_result *r, const gw_solver_params *sp,
                          int nulled)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "version", gw_version());
    if (r->bounced < 0) /* undecided: null, never false */
        cJSON_AddNullToObject(o, "bounced");
    else
        cJSON_AddBoolToObject(o, "bounced", r->bounced);
    if (r->fell_off > 0) /* only then, so that every other run's JSON is unchanged */
        cJSON_AddStringToObject(o, "fell_off", gw_layer_fell_off_name(r->fell_off));
    cJSON_AddNumberToObject(o, "e_n", r->e_n);
    cJSON_AddNumberToObject(o, "e", r->e);
    cJSON_AddNumberToObject(o, "alpha_r", r->alpha_r_deg);
    cJSON_AddNumberToObject(o, "v_nr", r->v_nr);
    cJSON_AddNumberToObject(o, "v_ni", r->v_ni);
    cJSON_AddNumberToObject(o, "v_r", r->v_r);
    cJSON_AddNumberToObject(o, "t_rebound", r->t_rebound);
    cJSON_AddNumberToObject(o, "t_f", r->t_f);
    cJSON_AddNumberToObject(o, "t_leave", r->t_leave);
    cJSON_AddNumberToObject(o, "e_n_first", r->e_n_first);
    cJSON_AddNumberToObject(o, "e_first", r->e_first);
    cJSON_AddNumberToObject(o, "alpha_r_first", r->alpha_r_first_deg);
    cJSON_AddNumberToObject(o, "v_nr_first", r->v_nr_first);
    cJSON_AddNumberToObject(o, "v_r_first", r->v_r_first);
    cJSON_AddNumberToObject(o, "t_rebound_first", r->t_rebound_first);
    if (r->undecided[0])
        cJSON_AddStringToObject(o, "undecided", r->undecided);
    else
        cJSON_AddNullToObject(o, "undecided");
    cJSON_AddNumberToObject(o, "penetration", r->penetration);
    cJSON_AddNumberToObject(o, "penetration_rm", r->penetration / c->rm);
    cJSON_AddNumberToObject(o, "energy_error", r->energy_error);
    cJSON_AddNumberToObject(o, "e_incident", r->e_incident);
    if (c->ip.side_walls != GW_LAYER_SIDES_BOTH) /* only then: every other run's JSON unchanged */
        cJSON_AddNumberToObject(o, "slump_ke", r->slump_ke);
    cJSON_AddNumberToObject(o, "dissipated_first_contact", r->dissipated_first_contact);
    cJSON_AddNumberToObject(o, "block_loss_first_contact", r->block_loss_first_contact);
    cJSON_AddNumberToObject(o, "dissipated_first_contact_block", r->dissipated_first_contact_block);
    cJSON_AddNumberToObject(o, "t_first_contact", r->t_first_contact);
    cJSON_AddNumberToObject(o, "contact_angle", r->contact_angle_deg);
    cJSON_AddNumberToObject(o, "t_contact_open", r->t_contact_open);
    cJSON_AddNumberToObject(o, "dissipated_contact_open", r->dissipated_contact_open);
    cJSON_AddNumberToObject(o, "block_loss_contact_open", r->block_loss_contact_open);
    cJSON_AddNumberToObject(o, "wave_speed", r->wave_speed);
    cJSON_AddNumberToObject(o, "wave_speed_err", r->wave_speed_err);
    cJSON_AddNumberToObject(o, "wave_speed_kinetic", r->wave_speed_kin);
    cJSON_AddNumberToObject(o, "wave_speed_kinetic_err", r->wave_speed_kin_err);
    cJSON_AddNumberToObject(o, "wave_rings", r->wave_rings);
    cJSON_AddNumberToObject(o, "wave_speed_xcorr", r->wave_speed_xcorr);
    cJSON_AddNumberToObject(o, "wave_speed_xcorr_err", r->wave_speed_xcorr_err);
    cJSON_AddNumberToObject(o, "wave_xcorr_gaps", r->xcorr_gaps);
    /* the bits a sweep's row and Python's outcome carry: the JSON had only
     * the warnings' text to tell a nulled speed's rule by */
    cJSON_AddNumberToObject(o, "crowns_nulled", nulled);
    cJSON_AddNumberToObject(o, "t_end", r->t_end);
    cJSON_AddNumberToObject(o, "block_mass", r->block_mass);
    cJSON_AddNumberToObject(o, "froude", c->ip.vi / sqrt(2 * c->m.lp.gravity * c->ip.rb_rm * c->rm));
    cJSON_AddNumberToObject(o, "n_mobile", r->n_mobile);
    cJSON_AddNumberToObject(o, "n_frozen", r->n_frozen);
    const gw_layer_energy *e = &r->ledger[r->ns - 1];
    cJSON *l = cJSON_AddObjectToObject(o, "ledger_end");
    cJSON_AddNumberToObject(l, "kinetic_block", e->kinetic_block);
    cJSON_AddNumberToObject(l, "kinetic_soil", e->kinetic_soil);
    cJSON_AddNumberToObject(l, "strain_normal", e->strain_normal);
    cJSON_AddNumberToObject(l, "strain_tangent", e->strain_tangent);
    cJSON_AddNumberToObject(l, "mindlin_excess", e->mindlin_excess);
    cJSON_AddNumberToObject(l, "dissipated", e->dissipated);
    cJSON_AddNumberToObject(l, "potential", e->potential);
    cJSON_AddNumberToObject(l, "total", e->total);
    cJSON_AddNumberToObject(l, "A", r->ledger[0].total);
    cJSON *rg = cJSON_AddArrayToObject(o, "regions_end");
    for (int q = 0; r->regions && q < r->nrings + 2; q++) {
        const gw_layer_energy *g = &r->regions[q];
        cJSON *x = cJSON_CreateObject();
        char nm[32];
        snprintf(nm, sizeof nm, q < r->nrings ? "ring %d" : q == r->nrings ? "outside" : "block", q);
        cJSON_AddStringToObject(x, "region", nm);
        cJSON_AddNumberToObject(x, "kinetic", g->kinetic_block + g->kinetic_soil);
        cJSON_AddNumberToObject(x, "strain", g->strain_normal + g->strain_tangent);
        cJSON_AddNumberToObject(x, "mindlin_excess", g->mindlin_excess);
        cJSON_AddNumberToObject(x, "dissipated", g->dissipated);
        cJSON_AddNumberToObject(x, "potential", g->potential);
        cJSON_AddNumberToObject(x, "total", g->total);
        cJSON_AddItemToArray(rg, x);
    }
    cJSON *cr = cJSON_AddObjectToObject(o, "crowns");
    cJSON_AddNumberToObject(cr, "x", r->impact_x);
    cJSON_AddNumberToObject(cr, "y", r->impact_y);
    cJSON_AddItemToObject(cr, "ring_r", gw_json_doubles(r->ring_r, r->nrings));
    cJSON_AddItemToObject(cr, "peak_strain_t", gw_json_doubles(r->peak_strain_t, r->nrings));
    cJSON_AddItemToObject(cr, "peak_kinetic_t", gw_json_doubles(r->peak_kin_t, r->nrings));
    /* delays from ring k to k + 1 (k = 0 .. nrings - 2); null: pair not used */
    const int ng = r->nrings > 1 ? r->nrings - 1 : 0;
    double *nan = r->xcorr_delay ? NULL : malloc((size_t)(ng + 1) * sizeof *nan);
    for (int q = 0; nan && q < ng; q++)
        nan[q] = NAN;
    const double *dl = r->xcorr_delay ? r->xcorr_delay : nan, *rh = r->xcorr_rho ? r->xcorr_rho : nan;
    cJSON_AddItemToObject(cr, "xcorr_delay", gw_json_doubles(dl, dl ? ng : 0));
    cJSON_AddItemToObject(cr, "xcorr_rho", gw_json_doubles(rh, rh ? ng : 0));
    free(nan);
    cJSON_AddStringToObject(cr, "xcorr_signal", "sample-to-sample change of the ring's strain increase + kinetic energy");
    cJSON_AddNumberToObject(o, "wall_time_ms", r->wall_ms);
    cJSON_AddNumberToObject(o, "steps", (double)r->stats.steps);
    cJSON_AddNumberToObject(o, "rhs_evals", (double)r->stats.rhs_evals);
    cJSON_AddNumberToObject(o, "events", (double)r->stats.events);
    cJSON_AddNumberToObject(o, "rebuilds", (double)r->stats.rebuilds);
    cJSON_AddNumberToObject(o, "zeno_guards", (double)r->stats.zeno_guards);
    cJSON *s = cJSON_AddObjectToObject(o, "settings");
    cJSON_AddStringToObject(s, "sample", c->sample);
    char hx[17];
    snprintf(hx, sizeof hx, "%016llx", c->sample_hash);
    cJSON_AddStringToObject(s, "sample_fnv1a64", hx); /* the content the run read */
    cJSON_AddNumberToObject(s, "rb_rm", c->ip.rb_rm);
    cJSON_AddNumberToObject(s, "vi", c->ip.vi);
    cJSON_AddNumberToObject(s, "alpha_deg", c->ip.alpha_deg);
    cJSON_AddNumberToObject(s, "x", c->ip.x);
    cJSON_AddNumberToObject(s, "height_rm", c->ip.height_rm);
    cJSON_AddNumberToObject(s, "gap", c->ip.gap);
    cJSON_AddNumberToObject(s, "t_max", c->ip.t_max);
    cJSON_AddNumberToObject(s, "dt_out", c->ip.dt_out);
    cJSON_AddNumberToObject(s, "ring_width", c->ip.ring_width > 0 ? c->ip.ring_width : 2 * c->rm);
    cJSON_AddNumberToObject(s, "rings", c->ip.nrings);
    cJSON_AddNumberToObject(s, "energy_tol", c->ip.energy_tol);
    cJSON_AddBoolToObject(s, "full", c->ip.full);
    cJSON_AddStringToObject(s, "until", gw_layer_until_name(c->ip.until));
    cJSON_AddBoolToObject(s, "remove_walls", c->ip.remove_walls);
    static const char *const side_names[] = {"both", "left", "right", "none"}; /* GW_LAYER_SIDES_* */
    if (c->ip.side_walls != GW_LAYER_SIDES_BOTH) /* only then: every other run's JSON unchanged */
        cJSON_AddStringToObject(s, "side_walls", side_names[c->ip.side_walls & 3]);
    cJSON_AddBoolToObject(s, "other_settling", c->ip.other_settling);
    cJSON_AddBoolToObject(s, "zero_springs", c->ip.zero_springs);
    /* the tangential springs the sample carries, from which the run started
     * unless zero_springs (0: a sample without them, every spring from zero) */
    cJSON_AddNumberToObject(s, "sample_springs", c->sample_springs);
    cJSON_AddItemToObject(s, "material", mat_json(&c->m.lp));
    /* what the sample's settings line recorded of its settling (null: nothing) */
    if (c->settled.recorded) {
        gw_layer_params sl = c->m.lp;
        sl.shear_modulus = c->settled.shear_modulus, sl.poisson = c->settled.poisson;
        sl.friction_deg = c->settled.friction_deg, sl.density = c->settled.density;
        sl.gravity = c->settled.gravity, sl.mass_law = c->settled.mass_law;
        cJSON *st = cJSON_AddObjectToObject(s, "sample_settled");
        cJSON_AddNumberToObject(st, "shear_modulus", sl.shear_modulus);
        cJSON_AddNumberToObject(st, "poisson", sl.poisson);
        cJSON_AddNumberToObject(st, "friction_deg", sl.friction_deg);
        cJSON_AddNumberToObject(st, "density", sl.density);
        cJSON_AddNumberToObject(st, "gravity", sl.gravity);
        cJSON_AddStringToObject(st, "mass_law", gw_layer_mass_law_name(sl.mass_law));
        cJSON_AddStringToObject(st, "clump_mass", gw_layer_clump_mass_name(c->settled.clump_mass));
        /* q = W_settled / W_impact is +inf for an impact without gravity
         * (other-settling): JSON has no infinity and cJSON printed null, the
         * JSON's "undefined", where the sweep's table says inf. It is the
         * text "inf" here, as the table writes it and as float() and strtod
         * read it back; a finite q stays a number (docs/formats.md) */
        if (isinf(c->settled_q))
            cJSON_AddStringToObject(st, "load_ratio", c->settled_q > 0 ? "inf" : "-inf");
        else
            cJSON_AddNumberToObject(st, "load_ratio", c->settled_q);
    } else {
        cJSON_AddNullToObject(s, "sample_settled");
    }
    cJSON *so = cJSON_AddObjectToObject(s, "solver");
    cJSON_AddStringToObject(so, "name", c->solver);
    cJSON_AddStringToObject(so, "method", r->method ? r->method : c->method);
    cJSON_AddNumberToObject(so, "rtol", sp->rtol);
    cJSON_AddNumberToObject(so, "atol", sp->atol);
    cJSON_AddNumberToObject(so, "dt", r->dt > 0 ? r->dt : sp->dt);
    cJSON_AddBoolToObject(so, "exact", c->type != gw_solver_verlet); /* events located */
    return o;
}

/* crowns_spectra.csv: each ring's power spectra (layer_crowns.c). */
static int write_spectra(const impact_cli *c, const gw_layer_impact_result *r, const char *hdr, gw_err *err)
{
    char path[4096];
    gw_afile f;
    int rc;
    if (gw_path_join(path, sizeof path, c->out, "crowns_spectra.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "--out: directory name too long");
    if ((rc = gw_afile_open(&f, path, err)) != GW_OK)
        return rc;
    fprintf(f.fp, "# %s\n# one-sided power spectral density (J^2/Hz) of each ring's strain-energy increase and "
            "kinetic energy over the evenly spaced samples, zero-padded (f step %.6g Hz); sum over f of psd * "
            "df = mean square of the series\n", hdr, r->spec_df);
    fprintf(f.fp, "f,ring,psd_strain,psd_kinetic\n");
    for (int l = 0; l < r->spec_len; l++)
        for (int q = 0; q < r->nrings; q++) {
            size_t i = (size_t)l * r->nrings + q;
            fprintf(f.fp, "%.9g,%d,%.9g,%.9g\n", l * r->spec_df, q, r->spec_strain[i], r->spec_kin[i]);
        }
    return gw_afile_commit(&f, err);
}

/* The CSVs, then impact.h5, which takes r's series (written to every file
 * by then): HDF5's image of the file is a second copy of them, and the
 * program's peak with --out was the series twice (192 MB on the 40-disc pile
 * at --gravity 0.5 --other-settling --t-max 10, where --json took 110 MB) */
static int write_csvs(const impact_cli *c, gw_layer_impact_result *r, const char *hdr,
                      gw_err *err)
{
    char path[4096];
    gw_afile f;
    int rc;
    if (gw_path_join(path, sizeof path, c->out, "ledger.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "--out: directory name too long");
    if ((rc = gw_afile_open(&f, path, err)) != GW_OK)
        return rc;
    fprintf(f.fp, "# %s\n# energy ledger (B.7-B.14), J; A = total at t = 0; potential from the initial "
            "heights; closure = |total - A| / A\n", hdr);
    fprintf(f.fp, "t,kinetic_block,kinetic_soil,strain_normal,strain_tangent,mindlin_excess,dissipated,"
            "potential,total,closure,block_x,block_y,block_vx,block_vy\n");
    const double A = r->ledger[0].total;
    for (int k = 0; k < r->ns; k++) {
        const gw_layer_energy *e = &r->ledger[k];
        const double *b = r->block + 4 * k;
        fprintf(f.fp, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.12g,%.3e,%.9g,%.9g,%.9g,%.9g\n", r->t[k],
                e->kinetic_block, e->kinetic_soil, e->strain_normal, e->strain_tangent, e->mindlin_excess,
                e->dissipated, e->potential, e->total, fabs(e->total - A) / A, b[0], b[1], b[2], b[3]);
    }
    if ((rc = gw_afile_commit(&f, err)) != GW_OK)
        return rc;
    if (gw_path_join(path, sizeof path, c->out, "crowns.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "--out: directory name too long");
    if ((rc = gw_afile_open(&f, path, err)) != GW_OK)
        return rc;
    fprintf(f.fp, "# %s\n# rings of width d_c around (%.6g, %.6g) m: strain energy increase over t = 0 "
            "and kinetic energy (J), coordination (contacts per particle), friction dissipation "
            "at contacts in the ring (J, integrated)\n", hdr, r->impact_x, r->impact_y);
    fprintf(f.fp, "t,ring,r_mid,strain,kinetic,coordination,dissipated\n");
    for (int k = 0; k < r->ns; k++)
        for (int q = 0; q < r->nrings; q++) {
            size_t i = (size_t)k * r->nrings + q;
            fprintf(f.fp, "%.9g,%d,%.6g,%.9g,%.9g,%.6g,%.9g\n", r->t[k], q, r->ring_r[q], r->ring_strain[i],
                    r->ring_kin[i], r->ring_coord[i], r->ring_diss[i]);
        }
    if ((rc = gw_afile_commit(&f, err)) != GW_OK)
        return rc;
    if (gw_path_join(path, sizeof path, c->out, "crowns_peaks.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "--out: directory name too long");
    if ((rc = gw_afile_open(&f, path, err)) != GW_OK)
        return rc;
    fprintf(f.fp, "# %s\n# peak times per ring (s, empty = no significant peak); wave speed %.6g +- %.3g m/s "
            "(strain), %.6g +- %.3g m/s (kinetic); cross-correlation delay to the next ring (s, empty = pair "
            "not used) and its normalised peak: wave speed %.6g +- %.3g m/s over %d pairs\n", hdr, r->wave_speed,
            r->wave_speed_err, r->wave_speed_kin, r->wave_speed_kin_err, r->wave_speed_xcorr,
            r->wave_speed_xcorr_err, r->xcorr_gaps);
    fprintf(f.fp, "ring,r_mid,t_peak_strain,t_peak_kinetic,xcorr_delay_next,xcorr_rho_next\n");
    for (int q = 0; q < r->nrings; q++) {
        const double v[4] = {r->peak_strain_t[q], r->peak_kin_t[q], r->xcorr_delay ? r->xcorr_delay[q] : NAN,
                             r->xcorr_rho ? r->xcorr_rho[q] : NAN};
        fprintf(f.fp, "%d,%.6g", q, r->ring_r[q]);
        for (int j = 0; j < 4; j++) {
            fprintf(f.fp, ",");
            if (isfinite(v[j]))
                fprintf(f.fp, "%.9g", v[j]);
        }
        fprintf(f.fp, "\n");
    }
    if ((rc = gw_afile_commit(&f, err)) != GW_OK)
        return rc;
    if ((rc = write_spectra(c, r, hdr, err)) != GW_OK)
        return rc;
#if GW_HAVE_HDF5
    if (gw_path_join(path, sizeof path, c->out, "impact.h5") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "--out: directory name too long");
    return layer_impact_write_h5_release(r, path, hdr, err);
#else
    return GW_OK;
#endif
}

/* What the command does at the library's on_sample hook. With --out, the VTK
 * snapshots: snapshot_0.vtk at the first sample, snapshot_end.vtk and
 * snapshots.pvd (the two as a ParaView series with their times) at the end,
 * snapshot_failure.vtk with the state where a failed run stopped. A
 * progress line every PROGRESS_MS of wall time once a run has lasted that
 * long (exact mode to T_f takes minutes; --quiet: none): the simulated time
 * reached; the run ends at T_f, at most at t-max. */
typedef struct vtk_ctx {
    const char *dir;       /* NULL: no snapshots */
    double t0;
    int failed;            /* a write failed: err holds its message */
    gw_err err;
    char failure_file[4096];
    int lines;             /* progress lines (not --quiet) */
    sim_progress prog;
} vtk_ctx;

static int write_snapshot(void *ctx, const gw_layer *L, int k, int final)
{
    vtk_ctx *v = ctx;
    if (v->lines && final == 0)
        sim_progress_report(&v->prog, gw_layer_time(L));
    if (!v->dir || v->failed || (final == 0 && k > 0))
        return GW_OK;
    static const char *const files[3] = {"snapshot_0.vtk", "snapshot_end.vtk", "snapshot_failure.vtk"};
    static const char *const titles[3] = {"granwave layer-impact t = 0", "granwave layer-impact t = t_end",
                                          "granwave layer-impact: state at the failure"};
    char path[4096];
    gw_err e = {{0}};
    int rc = gw_path_join(path, sizeof path, v->dir, files[final]) != GW_OK
                 ? gw_err_set(&e, GW_EINVAL, "out: directory name too long")
                 : gw_layer_write_vtk(L, path, titles[final], &e);
    if (rc == GW_OK && final == 0)
        v->t0 = gw_layer_time(L);
    if (rc == GW_OK && final == 1) {
        const char *two[2] = {files[0], files[1]};
        const double times[2] = {v->t0, gw_layer_time(L)};
        rc = gw_path_join(path, sizeof path, v->dir, "snapshots.pvd") != GW_OK
                 ? gw_err_set(&e, GW_EINVAL, "out: directory name too long")
                 : gw_layer_write_pvd(path, 2, two, times, &e); /* ParaView: one series with time */
    }
    if (final == 2) { /* best effort: the run's own error is what the user sees */
        if (rc == GW_OK)
            snprintf(v->failure_file, sizeof v->failure_file, "%s", path);
        return GW_OK;
    }
    if (rc != GW_OK) {
        v->failed = 1;
        v->err = e;
    }
    return rc;
}

/* every file layer-impact --out may write (gw_outset: what a run does not write
 * of these is an earlier run's, removed when this run's files are placed) */
static const char *const impact_files[] = {"ledger.csv", "crowns.csv", "crowns_peaks.csv", "crowns_spectra.csv",
                                           "impact.json", "impact.h5", "snapshot_0.vtk", "snapshot_end.vtk",
                                           "snapshots.pvd", "snapshot_failure.vtk", NULL};

/* What sets the step ends of an impact run under type, as advice to have
 * more of them in the first contact: verlet's and rk4's fixed step, or
 * cvode's and arkode's own steps, which follow their tolerances (they refuse
 * --dt: "lower --dt" was told under every solver) */
static const char *step_control(const gw_solver_type *type)
{
    return type == gw_solver_cvode || type == gw_solver_arkode
               ? "fewer than 3 step ends in it: lower --rtol and --atol, the solver chooses its steps"
               : "fewer than 3 step ends in it: lower --dt";
}

int gw_cmd_layer_impact(int argc, char **argv)
{
    impact_cli c;
    gw_opt o[LAYER_IMPACT_NOPTS + 8];
    int i = layer_impact_options(&c, o); /* the rows of the library's table (layer_setup.c) */
    o[i++] = (gw_opt){.name = "json", .kind = GW_OPT_FLAG, .dest = &c.json, .help = "print the result as JSON"};
    o[i++] = OPT_S("out", &c.out, "DIR", "write ledger.csv, crowns.csv, crowns_peaks.csv, crowns_spectra.csv, impact.json, VTK (and impact.h5 with HDF5)");
    int quiet = 0;
    o[i++] = (gw_opt){.name = "quiet", .kind = GW_OPT_FLAG, .dest = &quiet,
                      .help = "no progress lines (a run that lasts 3 s or more reports on stderr)"};
    o[i] = (gw_opt){0};
    gw_err err = {{0}};
    int help = 0, npos = 0;
    const char *pos[1];
    if (layer_opts_ok(o, &err) != GW_OK || gw_cli_parse("layer-impact", o, argc, argv, &help, pos, 0, &npos, &err) != GW_OK)
        return fail("layer-impact", err.msg);
    if (help)
        return gw_cli_help(stdout, "layer-impact", "granwave layer-impact --sample FILE [options]", impact_summary, o,
                           help);
    /* --out before the sample is read, as every other command checks it: its
     * directory was made only after the plan, and a file, a symbolic link to
     * nothing or a loop there was refused as "X: not a directory" */
    if (c.out && (gw_out_check(c.out, "layer-impact --out", &err) != GW_OK ||
                  gw_out_names_check(c.out, impact_files, "layer-impact --out", &err) != GW_OK))
        return fail("layer-impact", err.msg);
    /* the library's setup from the same command line, read and resolved by the
     * library (the sample, the materials, the solver, the options without
     * effect): what a sweep case and Python do */
    gw_layer_impact_setup st;
    if (gw_layer_impact_setup_init(&st) != GW_OK) {
        gw_layer_impact_setup_clear(&st);
        return gw_cli_nomem("layer-impact");
    }
    gw_layer_impact_plan plan;
    memset(&plan, 0, sizeof plan);
    /* the plan's settling verdict, which the run takes: the sample's settling
     * checked once (its pile weighed once), not again by gw_layer_impact */
    layer_settling_found found;
    int prc = gw_cli_study_setup(gw_layer_impact_setup_params(), &st, o, argc, argv, "layer-impact", &err);
    if (prc == GW_OK && (prc = layer_impact_plan_make_found(&st, &plan, &found, &err)) != GW_OK)
        gw_cli_study_error(gw_layer_impact_setup_params(), "layer-impact", prc, &err); /* "NAME:" -> "--NAME:" */
    gw_layer_impact_setup_clear(&st);
    if (prc != GW_OK) {
        gw_layer_impact_plan_free(&plan);
        return fail_rc("layer-impact", prc, err.msg);
    }
    c.m.lp = plan.lp; /* what the JSON settings and the text report */
    c.ip = plan.ip;
    c.type = plan.type;
    c.sp = plan.sp;
    c.rm = plan.sample.rm;
    c.sample_hash = plan.sample.content_hash;
    c.settled = plan.sample.settled;
    if (c.settled.clump_mass < 0) /* the line does not say: the sample's own clump_mass line */
        c.settled.clump_mass = plan.sample.clump_mass;
    c.settled_q = NAN; /* the run's (gw_layer_impact_result.settled_load_ratio): weighed once there */
    c.sample_springs = plan.sample.n_springs;
    c.solver = gw_solver_type_name(plan.type);
    const gw_solver_type *type = c.type;
    gw_solver_params sp = c.sp;
    gw_layer_sample s = plan.sample; /* owned from here */
    char made[4096] = ""; /* the first directory of --out this run creates */
    if (c.out && (gw_outset_check_input(c.out, impact_files, c.sample, "layer-impact --sample", &err) != GW_OK ||
                  gw_cli_mkdir_out(c.out, made, sizeof made, &err) != GW_OK)) {
        gw_layer_sample_free(&s);
        return fail("layer-impact", err.msg);
    }
    /* every file of the run, the snapshots written during it included, is placed
     * at the end, together: a run that fails leaves its snapshots and no earlier
     * run's results beside them; a write that fails leaves the earlier run's files */
    gw_outset oset;
    memset(&oset, 0, sizeof oset);
    if (c.out && gw_outset_begin(&oset, c.out, impact_files, &err) != GW_OK) {
        gw_layer_sample_free(&s);
        if (made[0])
            gw_cli_unmake(c.out, made);
        return fail("layer-impact", err.msg);
    }
    gw_layer_impact_result r;
    vtk_ctx vc = {.dir = c.out, .lines = !quiet, .prog = sim_progress_start("layer-impact", "to T_f", c.ip.t_max)};
    if (c.out || vc.lines) {
        c.ip.on_sample = write_snapshot;
        c.ip.sample_ctx = &vc;
    }
    int rc = layer_impact_run(&s, &c.m.lp, &c.ip, type, &sp, &found, &r, &err);
    char *w = NULL; /* the warnings: the crowns' against the sample first, while it is here */
    int nulled = 0; /* the rules that nulled a crown speed (the JSON's crowns_nulled) */
    if (rc == GW_OK)
        (void)layer_crowns_warning_kinds(&s, &c.ip, &r, &w, &nulled);
    if (vc.failed) /* the writer's own message, not the run's "the hook stopped it" */
        err = vc.err;
    else if (rc != GW_OK && vc.failure_file[0]) {
        const size_t k = strlen(err.msg), room = sizeof err.msg - k;
        char q[GW_CLI_PATH_TEXT]; /* one line: the message is printed as it is */
        gw_cli_path(q, sizeof q, vc.failure_file);
        if (room > 24 + strlen(q))
            snprintf(err.msg + k, room, "; state at failure in %.*s", (int)(room - 24), q);
    }
    gw_layer_sample_free(&s);
    if (rc == GW_EINVAL || rc == GW_EUNSUPPORTED || vc.failed)
        gw_outset_abort(&oset); /* refused, or a snapshot not written: nothing of this run */
    if (rc != GW_OK) {
        gw_err cerr = {{0}};
        if (oset.active && gw_outset_commit(&oset, &cerr) != GW_OK) /* the snapshots of the failed run */
            fprintf(stderr, "granwave layer-impact --out: %s\n", cerr.msg);
        /* a refused input leaves nothing behind, and a run that failed (exit 1)
         * before a snapshot of it was placed no empty directory it made (the
         * directories go only while empty: a failure's snapshots keep them) */
        if (made[0])
            gw_cli_unmake(c.out, made);
        if ((rc == GW_EINVAL || rc == GW_EUNSUPPORTED) && !vc.failed) { /* "dt: ..." -> "layer-impact --dt: ...", as the plan's */
            gw_cli_study_error(gw_layer_impact_setup_params(), "layer-impact", rc, &err);
            fprintf(stderr, "granwave %s\n", err.msg);
        } else /* the library's "layer-impact: out of memory ..." said once */
            gw_cli_error("layer-impact", err.msg);
        return rc == GW_EINVAL || rc == GW_EUNSUPPORTED ? 2 : 1;
    }
    c.settled_q = r.settled_load_ratio;
    int code = 0;
    /* the library's texts, one line each (out of memory for them: no line): a
     * sample settled under another material, an undecided outcome (the JSON
     * says null); the JSON's "warnings" and the outputs' headers record them */
    if (gw_layer_impact_result_warnings(&r, &w) == GW_OK)
        (void)layer_energy_warning(&r, &c.ip, type, &sp, &w);
    gw_cli_warnings("layer-impact", w);
    cJSON *j = impact_json(&c, &r, &sp, nulled);
    gw_cli_json_warnings(j, w);
    if (c.out) {
        /* the command line and every setting (defaults included, the step used)
         * head each CSV and the HDF5 "run" attribute, and the warnings after them */
        char *hdr = gw_cli_one_line(gw_cli_provenance("layer-impact", argc, argv, cJSON_GetObjectItem(j, "settings")), ';');
        if (hdr && r.settling[0]) {
            const size_t hl = strlen(hdr) + strlen(r.settling) + 16;
            char *h2 = malloc(hl);
            if (h2)
                snprintf(h2, hl, "%s;warning: %s", hdr, r.settling);
            free(hdr);
            hdr = h2;
        }
        char path[4096];
        /* a snapshot_failure.vtk left by an earlier failed run in DIR is not this
         * run's (beside its results it read as the state where it failed): the
         * set's commit removes it */
        if ((!hdr && gw_err_set(&err, GW_ENOMEM, "out of memory") != GW_OK) ||
            write_csvs(&c, &r, hdr, &err) != GW_OK ||
            gw_path_join(path, sizeof path, c.out, "impact.json") != GW_OK ||
            gw_json_write(path, j, &err) != GW_OK || gw_outset_commit(&oset, &err) != GW_OK) {
            gw_outset_abort(&oset);
            if (made[0]) /* nothing of this run placed: no empty directory it made */
                gw_cli_unmake(c.out, made);
            fprintf(stderr, "granwave layer-impact --out: %s\n", err.msg);
            code = 1;
        }
        free(hdr);
    }
    if (code == 0) {
        if (c.json) {
            code = gw_cli_json_stdout("layer-impact", j);
        } else {
            printf("granwave %s layer-impact: R_b = %g R_m, V_i = %g m/s, alpha = %g deg, solver %s\n",
                   gw_version(), c.ip.rb_rm, c.ip.vi, c.ip.alpha_deg, c.solver);
            printf("  mass law %s, %d mobile + %d frozen particles\n",
                   gw_layer_mass_law_name(c.m.lp.mass_law), r.n_mobile, r.n_frozen);
            /* what the JSON gives as null (undecided, not reached) reads n/a */
            char v[6][32];
            printf("  bounced %s: e_n = %s, e = %s, alpha_r = %s deg (V_nr = %s m/s at T_i = %s ms, "
                   "T_f = %s ms)\n", r.bounced > 0 ? "yes" : r.fell_off > 0 ? "no (fell off the layer)" : r.bounced == 0 ? "no" : "undecided",
                   gw_cli_num(v[0], sizeof v[0], "%.4g", r.e_n), gw_cli_num(v[1], sizeof v[1], "%.4g", r.e),
                   gw_cli_num(v[2], sizeof v[2], "%.4g", r.alpha_r_deg), gw_cli_num(v[3], sizeof v[3], "%.4g", r.v_nr),
                   gw_cli_num(v[4], sizeof v[4], "%.4g", r.t_rebound * 1e3), gw_cli_num(v[5], sizeof v[5], "%.4g", r.t_f * 1e3));
            printf("  first free-flight maximum: e_n = %s, e = %s, alpha_r = %s deg (V_nr = %s m/s at "
                   "%s ms; left at %s ms)\n", gw_cli_num(v[0], sizeof v[0], "%.4g", r.e_n_first),
                   gw_cli_num(v[1], sizeof v[1], "%.4g", r.e_first), gw_cli_num(v[2], sizeof v[2], "%.4g", r.alpha_r_first_deg),
                   gw_cli_num(v[3], sizeof v[3], "%.4g", r.v_nr_first), gw_cli_num(v[4], sizeof v[4], "%.4g", r.t_rebound_first * 1e3),
                   gw_cli_num(v[5], sizeof v[5], "%.4g", r.t_leave * 1e3));
            printf("  penetration %s m (%s R_m)\n", gw_cli_num(v[0], sizeof v[0], "%.4g", r.penetration),
                   gw_cli_num(v[1], sizeof v[1], "%.3g", r.penetration / c.rm));
            if (isnan(r.t_first_contact))
                printf("  first contact: unresolved (%s)\n",
                       !(r.bounced >= 0) && r.t_end >= c.ip.t_max && isnan(r.t_contact_open)
                           ? "the run ended at t-max inside it: raise --t-max"
                           : step_control(c.type));
            else
                printf("  first contact: E_d = %s of E_incident, block loss %s (ends at %.4g ms); at its opening "
                       "block loss %s (B.28)\n", gw_cli_num(v[1], sizeof v[1], "%.3g", r.dissipated_first_contact),
                       gw_cli_num(v[2], sizeof v[2], "%.3g", r.block_loss_first_contact), r.t_first_contact * 1e3,
                       gw_cli_num(v[0], sizeof v[0], "%.3g", r.block_loss_contact_open));
            /* a crown speed the samples do not resolve is null in JSON: "unresolved"
             * here; one following the pile's slow motion (a warning says so):
             * "undecided", where it said "unresolved" too */
            char ws[3][64];
            const double wv[3] = {r.wave_speed, r.wave_speed_kin, r.wave_speed_xcorr};
            const double we[3] = {r.wave_speed_err, r.wave_speed_kin_err, r.wave_speed_xcorr_err};
            double cs[3], es[3];
            const unsigned locked = layer_crowns_locked(&r), scatter = layer_crowns_imprecise(&r, cs, es);
            for (int q = 0; q < 3; q++)
                if (isfinite(wv[q]))
                    snprintf(ws[q], sizeof ws[q], "%.4g +- %.3g m/s", wv[q], we[q]);
                else
                    snprintf(ws[q], sizeof ws[q], "%s", locked & (1u << q)    ? "undecided, the pile's motion"
                                                        : scatter & (1u << q) ? "undecided, its scatter"
                                                                              : "unresolved");
            printf("  wave speed %s (strain peaks, %d rings), %s (kinetic)\n", ws[0], r.wave_rings, ws[1]);
            printf("  wave speed %s (cross-correlation of neighbouring rings, %d pairs)\n", ws[2], r.xcorr_gaps);
            printf("  energy closure max %.3g; t_end %.4g ms; wall %.0f ms, %ld steps, %ld events, %ld rebuilds\n",
                   r.energy_error, r.t_end * 1e3, r.wall_ms, r.stats.steps, r.stats.events, r.stats.rebuilds);
        }
    }
    cJSON_Delete(j);
    free(w);
    gw_layer_impact_result_free(&r);
    return code;
}
