/*
 * chain_drop_cmd.c: `granwave drop`, the whole drop of a column on the sensor
 * (chain_drop.c; physics.md 1.1, 1.2, 1.5). The column is released from rest with
 * bead 1 at a height h (m) above the sensor; v_imp = sqrt(2 g h) (m/s). Options
 * shared with `granwave chain` keep their names and meaning; --t-max is the time
 * followed after the first contact (s), --gravity defaults to 9.81 m/s^2.
 * Outputs: the sensor signal F(t) (N), every peak and impact (definitions in
 * gw_chain.h), the first collision as `granwave chain` reports it, the energy
 * ledger. SI units. The options are the rows of the drop study's table
 * (chain_drop_study.c: help, ranges); the command checks them with its own
 * messages, runs the study (gw_chain_drop_study_run) and prints its outcome.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_cli.h"
#include "chain_options.h"
#include "chain_wall.h"

static const char *drop_summary =
    "The whole drop (Falcon et al. 1998, Fig. 12): a column of N beads released from\n"
    "rest with bead 1 at a height h above the sensor falls under gravity and is followed\n"
    "from its first contact (t = 0, v_imp = sqrt(2 g h)) through the first collision,\n"
    "detachment, free flight and the bounces that follow, up to --t-max. Reports the\n"
    "sensor signal, every wall-force peak (a located local maximum of the force, at or\n"
    "above --peak-threshold, with the beads in contact), the impacts (contact episodes\n"
    "of bead 1 with the sensor whose largest peak reaches the threshold), the first\n"
    "collision as `granwave chain` reports it, and the energy ledger with gravity and\n"
    "dissipation. SI units.";

enum { DROP_NOPTS = 6 };

typedef struct drop_cli {
    chain_cli c;
    long n;
    double height, peak_threshold;
    const char *gap;
    int block, quiet;
    double *gaps;   /* [n-1] or NULL */
    double dt_out;  /* resolved signal sampling, s */
    double dt_given; /* the --dt given (0: none), s; the settings' dt is the step taken */
    int n_column;   /* beads of the column (before --block) */
} drop_cli;

static gw_opt *opt_named(gw_opt *opts, const char *name)
{
    return (gw_opt *)gw_cli_find(opts, name);
}

/* An option as the drop study's row: help, metavar and range from the table;
 * a number checked by the row itself (gw_param_set_value: dt-out's 0 besides
 * its range, or_zero). */
static gw_opt opt_row(const char *name, gw_opt_kind kind, void *dest)
{
    const gw_param *p = gw_param_find(gw_chain_drop_setup_params(), name);
    gw_opt o = {.name = p->name, .kind = kind, .dest = dest, .metavar = p->metavar, .help = p->help};
    if (kind == GW_OPT_DOUBLE || kind == GW_OPT_LONG || kind == GW_OPT_COUNT) {
        o.lo = p->min;
        o.hi = p->max;
        o.open_lo = p->open_min;
        o.open_hi = p->open_max;
        if ((kind == GW_OPT_DOUBLE && p->type == GW_PARAM_DOUBLE) || (kind == GW_OPT_LONG && p->type == GW_PARAM_LONG) ||
            (kind == GW_OPT_COUNT && p->type == GW_PARAM_COUNT))
            o.param = p;
    }
    return o;
}

/* the files of --out DIR */
static const char *const drop_files[] = {"drop_wall_force.csv", "drop_beads.csv", "drop.h5", "drop_peaks.csv",
                                         "drop_impacts.csv", "drop.json", NULL};

static void drop_options(drop_cli *d, gw_opt *opts)
{
    memset(d, 0, sizeof *d);
    chain_cli_options(&d->c, opts);
    d->c.out_names = drop_files;
    chain_cli_out_help(opts, "write drop_wall_force.csv, drop_beads.csv, drop_peaks.csv, drop_impacts.csv, drop.json (and drop.h5 with HDF5) into DIR");
    d->n = 1;
    d->height = 5.1e-3;
    d->peak_threshold = NAN;
    d->c.gravity = GW_CHAIN_G_EARTH;
    d->c.t_max = 10e-3;
    static const char *const own[] = {"gravity", "t-max", "dt-out"}; /* the drop's own rows */
    for (int i = 0; i < 3; i++) {
        gw_opt *o = opt_named(opts, own[i]);
        *o = opt_row(own[i], o->kind, o->dest);
    }
    int k = CHAIN_CLI_NOPTS;
    opts[k++] = opt_row("n", GW_OPT_LONG, &d->n);
    opts[k++] = opt_row("height", GW_OPT_DOUBLE, &d->height);
    opts[k++] = opt_row("gap", GW_OPT_STRING, &d->gap);
    opts[k++] = opt_row("block", GW_OPT_FLAG, &d->block);
    opts[k++] = opt_row("peak-threshold", GW_OPT_DOUBLE, &d->peak_threshold);
    opts[k++] = (gw_opt){.name = "quiet", .kind = GW_OPT_FLAG, .dest = &d->quiet,
                         .help = "no progress lines (a run that lasts 2 s or more reports on stderr)"};
    opts[k] = (gw_opt){0};
}

/* Everything the drop's settings need beyond chain_cli_resolve, from the
 * study's setup ds (its checks: the gaps by gw_chain_drop_setup_gaps, dt-out by
 * the run); GW_EINVAL naming the flag. */
static int drop_resolve(drop_cli *d, const gw_chain_drop_setup *ds, gw_opt *opts, gw_err *err)
{
    chain_cli *c = &d->c;
    int n = (int)d->n, rc;
    if ((rc = gw_chain_drop_setup_gaps(ds, &d->gaps, err)) != GW_OK)
        return gw_cli_study_error(gw_chain_drop_setup_params(), "drop", rc, err);
    c->params.n = n;
    c->params.v_imp = sqrt(2.0 * c->gravity * d->height);
    /* the drop's own defaults (gravity 9.81, t-max 10 ms) count as given: the
     * resolution takes only given options over the column table's defaults */
    opt_named(opts, "gravity")->seen = 1;
    opt_named(opts, "t-max")->seen = 1;
    if ((rc = chain_cli_resolve(c, opts, "drop", err)) != GW_OK)
        return rc;
    d->n_column = n;
    if (d->block) /* one body of the column's mass, bead 1's contact constants */
        gw_chain_drop_block_params(&c->params);
    return GW_OK; /* dt-out and the peak threshold: the study's, taken after its run */
}

static cJSON *settings_json(const drop_cli *d)
{
    cJSON *o = chain_cli_settings_json(&d->c);
    cJSON *sv = cJSON_GetObjectItemCaseSensitive(o, "solver");
    if (sv) /* dt is the step taken (o.dt), the one given beside it */
        cJSON_ReplaceItemInObjectCaseSensitive(sv, "dt_given", cJSON_CreateNumber(d->dt_given));
    cJSON *dr = cJSON_AddObjectToObject(o, "drop");
    cJSON_AddNumberToObject(dr, "n_column", d->n_column);
    cJSON_AddBoolToObject(dr, "block", d->block);
    cJSON_AddNumberToObject(dr, "height", d->height);
    cJSON_AddNumberToObject(dr, "gravity", d->c.params.gravity);
    if (d->gaps && !d->block)
        cJSON_AddItemToObject(dr, "gaps", gw_json_doubles(d->gaps, d->n_column - 1));
    else
        cJSON_AddItemToObject(dr, "gaps", cJSON_CreateArray());
    cJSON_AddNumberToObject(dr, "t_max", d->c.run.t_max);
    cJSON_AddNumberToObject(dr, "dt_out", d->dt_out);
    cJSON_AddNumberToObject(dr, "peak_threshold", d->peak_threshold);
    return o;
}

static void contacts_string(const gw_chain_drop_result *r, int j, char *buf)
{
    const unsigned char *cl = r->peak_contacts + (size_t)j * (size_t)r->n;
    for (int k = 0; k < r->n; k++)
        buf[k] = cl[k] ? '1' : '0';
    buf[r->n] = '\0';
}

static cJSON *result_json(const drop_cli *d, const gw_chain_drop_result *r, double wall_ms,
                          char *buf)
{
    const chain_cli *c = &d->c;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "version", gw_version());
    cJSON_AddStringToObject(o, "command", "drop");
    cJSON_AddNumberToObject(o, "n", r->n);
    cJSON_AddBoolToObject(o, "block", d->block);
    cJSON_AddNumberToObject(o, "height", d->height);
    cJSON_AddNumberToObject(o, "v_imp", r->v_imp);
    cJSON_AddNumberToObject(o, "t_fall", r->t_fall);
    cJSON_AddStringToObject(o, "solver", c->solver);
    cJSON_AddNumberToObject(o, "t_max", c->run.t_max);
    cJSON_AddNumberToObject(o, "peak_threshold", d->peak_threshold);
    cJSON_AddNumberToObject(o, "n_impacts", r->n_impacts);
    cJSON_AddNumberToObject(o, "n_contact_episodes", r->n_episodes);
    cJSON_AddNumberToObject(o, "n_peaks", r->n_peaks);
    cJSON_AddNumberToObject(o, "f_max", r->f_max);
    cJSON_AddNumberToObject(o, "t_fmax", r->t_fmax);
    int rises = gw_chain_drop_impact_rises(r);
    cJSON_AddNumberToObject(o, "impact_rises", rises);
    cJSON_AddBoolToObject(o, "impacts_monotone", rises == 0);
    cJSON *imp = cJSON_AddArrayToObject(o, "impacts");
    for (int j = 0; j < r->n_impacts; j++) {
        const gw_chain_drop_impact *im = &r->impacts[j];
        cJSON *e = cJSON_CreateObject();
        cJSON_AddNumberToObject(e, "t_start", im->t_start);
        cJSON_AddNumberToObject(e, "t_end", im->t_end);
        cJSON_AddNumberToObject(e, "f_max", im->f_max);
        cJSON_AddNumberToObject(e, "t_fmax", im->t_fmax);
        cJSON_AddNumberToObject(e, "v_in", im->v_in);
        cJSON_AddNumberToObject(e, "v_out", im->v_out);
        cJSON_AddNumberToObject(e, "n_peaks", im->n_peaks);
        cJSON_AddNumberToObject(e, "cluster", im->cluster);
        cJSON_AddBoolToObject(e, "located", im->located);
        if (!isnan(im->chatter)) /* the drop's chatter check ran it again: its F_max's relative change */
            cJSON_AddNumberToObject(e, "chatter", im->chatter);
        cJSON_AddItemToArray(imp, e);
    }
    cJSON *pk = cJSON_AddArrayToObject(o, "wall_peaks");
    for (int j = 0; j < r->n_peaks; j++) {
        const gw_chain_drop_peak *p = &r->peaks[j];
        cJSON *e = cJSON_CreateObject();
        cJSON_AddNumberToObject(e, "t", p->t);
        cJSON_AddNumberToObject(e, "f", p->f);
        cJSON_AddNumberToObject(e, "impact", p->impact);
        cJSON_AddNumberToObject(e, "cluster", p->cluster);
        contacts_string(r, j, buf);
        cJSON_AddStringToObject(e, "contacts", buf);
        cJSON_AddItemToArray(pk, e);
    }
    cJSON *first = chain_result_json(c, &r->first, NAN);
    /* the first collision is checked for chatter on a sensor body as chain's
     * when it ran to its end (first_status GW_OK); cut at t_max it was not,
     * and its chatter key would read "none" (0) without having looked */
    if (r->first_status != GW_OK)
        cJSON_DeleteItemFromObject(first, "chatter");
    cJSON_AddItemToObject(o, "first_collision", first);
    /* the drop's own, over its contact episodes: 0 none, the impacts' largest
     * F_max change a rerun measured, -1 not run again (costly), -2 its rerun failed */
    cJSON_AddNumberToObject(o, "chatter", chain_chatter_value(r->chatter_kind, r->chatter_spread));
    cJSON_AddNumberToObject(o, "energy_error", r->energy_error);
    cJSON *en = cJSON_AddObjectToObject(o, "energy");
    cJSON_AddNumberToObject(en, "e0", r->e0);
    cJSON_AddNumberToObject(en, "kinetic", r->e_end.kinetic);
    cJSON_AddNumberToObject(en, "elastic", r->e_end.elastic);
    cJSON_AddNumberToObject(en, "gravity", r->e_end.gravity);
    cJSON_AddNumberToObject(en, "dissipated", r->e_end.dissipated);
    cJSON_AddNumberToObject(en, "total", r->e_end.total);
    cJSON_AddNumberToObject(o, "t_end", r->t_end);
    cJSON_AddBoolToObject(o, "cut_first_collision", r->first_cut);
    cJSON_AddBoolToObject(o, "open_at_t_max", r->open_at_t_max);
    cJSON_AddNumberToObject(o, "events", (double)r->n_events);
    cJSON_AddNumberToObject(o, "missed_events", (double)r->missed_events);
    cJSON_AddNumberToObject(o, "steps", (double)r->stats.steps);
    cJSON_AddNumberToObject(o, "rhs_evals", (double)r->stats.rhs_evals);
    cJSON_AddNumberToObject(o, "restarts", (double)r->stats.restarts);
    cJSON_AddNumberToObject(o, "wall_time_ms", wall_ms);
    cJSON_AddItemToObject(o, "settings", settings_json(d));
    return o;
}

static void print_text(const drop_cli *d, const gw_chain_drop_result *r)
{
    const gw_chain_params *p = &d->c.params;
    printf("granwave %s drop: n = %d%s, h = %g m (v_imp = %.6g m/s, fall %.6g ms), solver %s\n",
           gw_version(), r->n, d->block ? " (rigid block)" : "", d->height, r->v_imp,
           r->t_fall * 1e3, d->c.solver);
    printf("  m = %.6g kg, k = %.6g N/m^1.5, K = %.6g N/m^1.5, g = %g m/s^2, damping %s\n",
           p->mass, p->k, p->kwall, p->gravity, d->c.damping);
    printf("  first collision  F_max %.6g N at %.6g us, tau_N %.6g us, eps_eff %.6g\n",
           r->first.f_max, r->first.tau_max * 1e6, r->first.tau_n * 1e6, r->first.eps_eff);
    printf("  over %.6g ms     %d impacts (%d contact episodes), %d peaks >= %.3g N, "
           "%d impact(s) above the previous one\n",
           r->t_end * 1e3, r->n_impacts, r->n_episodes, r->n_peaks, d->peak_threshold,
           gw_chain_drop_impact_rises(r));
    printf("  energy           max relative error %.3g; dissipated %.4g of %.4g J\n",
           r->energy_error, r->e_end.dissipated, r->e0);
    /* impacts numbered from 0, as the JSON's wall_peaks[].impact, drop_impacts.csv's and
     * drop_peaks.csv's impact column and Python's arrays (the table numbered from 1) */
    printf("  impact      t (ms)     F_max (N)  cluster  peaks\n");
    for (int j = 0; j < r->n_impacts; j++)
        printf("  %6d  %10.5f  %12.5g  %7d  %5d\n", j, r->impacts[j].t_fmax * 1e3,
               r->impacts[j].f_max, r->impacts[j].cluster, r->impacts[j].n_peaks);
}

static int write_tables(const drop_cli *d, const gw_chain_drop_result *r, const char *hdr,
                        char *buf, gw_err *err)
{
    char path[4096];
    gw_afile f;
    int rc;
    if (gw_path_join(path, sizeof path, d->c.out, "drop_peaks.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "drop --out: path too long");
    if ((rc = gw_afile_open(&f, path, err)) != GW_OK)
        return rc;
    gw_write_comment(f.fp, hdr);
    fprintf(f.fp, "# peak: located local maximum of the sensor force with F >= peak_threshold; "
                  "contacts: one digit per contact, sensor first (1 = closed)\n");
    fprintf(f.fp, "t_s,f_N,impact,cluster,contacts\n");
    for (int j = 0; j < r->n_peaks; j++) {
        contacts_string(r, j, buf);
        fprintf(f.fp, "%.12e,%.12e,%d,%d,%s\n", r->peaks[j].t, r->peaks[j].f, r->peaks[j].impact,
                r->peaks[j].cluster, buf);
    }
    if ((rc = gw_afile_commit(&f, err)) != GW_OK)
        return rc;
    if (gw_path_join(path, sizeof path, d->c.out, "drop_impacts.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "drop --out: path too long");
    if ((rc = gw_afile_open(&f, path, err)) != GW_OK)
        return rc;
    gw_write_comment(f.fp, hdr);
    fprintf(f.fp, "# impact: contact episode of bead 1 with the sensor whose largest peak is >= "
                  "peak_threshold; t_end and v_out nan (JSON null) while in contact at t_max\n");
    fprintf(f.fp, "impact,t_start_s,t_end_s,f_max_N,t_fmax_s,v_in_m_s,v_out_m_s,n_peaks,cluster,located\n");
    for (int j = 0; j < r->n_impacts; j++) {
        const gw_chain_drop_impact *im = &r->impacts[j];
        fprintf(f.fp, "%d,%.12e,%.12e,%.12e,%.12e,%.12e,%.12e,%d,%d,%d\n", j, im->t_start, im->t_end,
                im->f_max, im->t_fmax, im->v_in, im->v_out, im->n_peaks, im->cluster, im->located);
    }
    return gw_afile_commit(&f, err);
}

static char *drop_header(const drop_cli *d, int argc, char **argv)
{
    cJSON *s = settings_json(d);
    char *h = gw_cli_provenance_add(chain_cli_header(&d->c, "drop", argc, argv), "drop",
                                    cJSON_GetObjectItem(s, "drop"));
    cJSON_Delete(s);
    return h;
}

static int write_outputs(const drop_cli *d, const gw_chain_drop_result *r, const gw_chain_trace *tr,
                         double wall_ms, const char *warnings, int argc, char **argv, char *buf, gw_err *err)
{
    char *hdr = drop_header(d, argc, argv);
    if (!hdr)
        return gw_err_set(err, GW_ENOMEM, "drop --out: out of memory");
    char path[4096];
    /* this run's files all in place, or (a write failed) the earlier run's as they were */
    gw_outset oset;
    char made[4096] = ""; /* the first directory of --out this run creates, taken back on a failure */
    int rc = gw_cli_outset_begin(&oset, d->c.out, drop_files, made, sizeof made, err);
    if (rc == GW_OK)
        rc = gw_chain_trace_write(tr, d->c.out, "drop", hdr, err);
    if (rc == GW_OK)
        rc = write_tables(d, r, hdr, buf, err);
    if (rc == GW_OK) {
        cJSON *o = result_json(d, r, wall_ms, buf);
        gw_cli_json_warnings(o, warnings);
        if (gw_path_join(path, sizeof path, d->c.out, "drop.json") != GW_OK)
            rc = gw_err_set(err, GW_EINVAL, "drop --out: path too long");
        else
            rc = gw_json_write(path, o, err);
        cJSON_Delete(o);
    }
    if (rc == GW_OK)
        rc = gw_outset_commit(&oset, err);
    gw_cli_outset_end(&oset, d->c.out, made, rc == GW_OK);
    free(hdr);
    return rc;
}

/* Progress of one drop on stderr, through the display of falcon, wavespeed,
 * softwall and sweep, in output samples of the drop and of its first
 * collision's own run (the study's count: twice t_max / dt_out), once the run
 * has lasted DROP_PROGRESS_MS: `drop --n 1000` ran 66 s of CPU without a
 * word, while the default drop ends in milliseconds and stays silent (a
 * refusal or a warning is still its one line). The header, with the first
 * line, says what is counted. */
#define DROP_PROGRESS_MS 2000.0

typedef struct drop_progress {
    gw_cli_progress p;
    char header[160];
    int n;
    double t_max;
} drop_progress;

static int drop_progress_report(void *ctx, long done, long total)
{
    drop_progress *dp = ctx;
    if (!dp->header[0]) { /* the count is the study's: t_max / dt_out */
        snprintf(dp->header, sizeof dp->header, "granwave drop: %d bead%s, %g ms from the first contact, then the first "
                 "collision again (at most as long): %ld samples", dp->n, dp->n == 1 ? "" : "s", dp->t_max * 1e3, total);
        dp->p.header = dp->header;
    }
    return gw_cli_progress_report(&dp->p, done, total);
}

int gw_cmd_drop(int argc, char **argv)
{
    drop_cli d;
    gw_opt opts[CHAIN_CLI_NOPTS + DROP_NOPTS + 1];
    drop_options(&d, opts);
    int done = chain_cli_parse("drop", "granwave drop [options]", drop_summary, opts, argc, argv);
    if (done >= 0)
        return done;
    gw_err err = {{0}};
    /* the study from the same command line (its rows are these options) */
    gw_chain_drop_setup ds;
    if (gw_chain_drop_setup_init(&ds) != GW_OK) {
        gw_chain_drop_setup_clear(&ds);
        return gw_cli_nomem("drop");
    }
    gw_chain_drop_outcome o;
    memset(&o, 0, sizeof o);
    int code = 0;
    int rc = gw_cli_study_setup(gw_chain_drop_setup_params(), &ds, opts, argc, argv, "drop", &err);
    if (rc == GW_OK)
        rc = drop_resolve(&d, &ds, opts, &err);
    if (rc != GW_OK) {
        gw_chain_drop_setup_clear(&ds);
        free(d.gaps);
        chain_cli_free(&d.c);
        return chain_cli_fail_rc(rc, err.msg);
    }
    ds.col.trace = d.c.out != NULL; /* the bead series for drop_beads.csv */
    drop_progress prog = {.n = d.c.params.n, .t_max = d.c.run.t_max};
    gw_cli_progress_init(&prog.p, "  ", "samples", DROP_PROGRESS_MS);
    prog.p.after_ms = gw_cli_progress_ms(DROP_PROGRESS_MS);
    if ((rc = gw_chain_drop_study_run(&ds, d.quiet ? NULL : drop_progress_report, &prog, &o, &err)) ==
        GW_EINVAL) /* "NAME:" -> "--NAME:" */
        gw_cli_study_error(gw_chain_drop_setup_params(), "drop", rc, &err);
    d.dt_out = d.c.run.dt_out = o.dt_out; /* as the study resolved them, for the settings */
    d.c.run.sp.dt = o.dt;
    d.dt_given = o.r.run_dt_given;
    d.c.run.sp.dt_max = o.dt_max;
    d.peak_threshold = o.peak_threshold;
    const gw_chain_drop_result *r = &o.r;
    gw_chain_trace tr = {.n = o.n, .len = (size_t)o.trace_len, .cap = (size_t)o.trace_len,
                         .t = o.t, .f = o.f_wall, .x = o.x, .v = o.v}; /* a view, not owned */
    char *buf = malloc((size_t)o.n + 1);
    if (!buf && rc == GW_OK)
        rc = gw_err_set(&err, GW_ENOMEM, "drop: out of memory");
    if (rc == GW_OK) /* cut at t_max: said, and recorded (cut_first_collision, open_at_t_max) */
        gw_cli_warnings("drop", o.warnings);
    if (rc != GW_OK) {
        fprintf(stderr, "granwave %s%s\n", rc == GW_EINVAL || strncmp(err.msg, "drop: ", 6) == 0 ? "" : "drop: ", err.msg);
        code = rc == GW_EINVAL ? 2 : 1;
    } else if (d.c.out && write_outputs(&d, r, &tr, o.wall_time_ms, o.warnings, argc, argv, buf, &err) != GW_OK) {
        fprintf(stderr, "granwave drop --out: %s\n", err.msg);
        code = 1;
    } else if (d.c.json) {
        cJSON *j = result_json(&d, r, o.wall_time_ms, buf);
        gw_cli_json_warnings(j, o.warnings);
        code = gw_cli_json_stdout("drop", j);
        cJSON_Delete(j);
    } else {
        print_text(&d, r);
    }
    free(buf);
    gw_chain_drop_outcome_free(&o);
    gw_chain_drop_setup_clear(&ds);
    free(d.gaps);
    chain_cli_free(&d.c);
    return code;
}
