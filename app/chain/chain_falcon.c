/*
 * chain_falcon.c: `granwave falcon`, the rigid-wall study of Falcon et al. (1998)
 * for steel beads: N = 1..nmax at v_imp = 0.3 m/s and at the paper's drop heights
 * (v_imp = sqrt(2 g h), g = 9.81 m/s^2 or --gravity: gw_chain_falcon_speeds).
 *
 * Per velocity: F_max(N), tau_max(N), tau_N(N) with the GSL line
 * tau_N = T_q (N - 1) + tau_1 (F.4) giving T_q and its intercept, the wave speed
 * v = 4R/T_q (F.6) against 2 (k/m)^(2/5) R v_imp^(1/5) (F.27), the force period
 * P, detachment (final velocities, times, N_s) and E_rel/E_K(N) (F.20).
 * Outputs (--out DIR): falcon_runs.csv, falcon_final_velocities.csv,
 * falcon_summary.json, traces for N = 7, 15, 30 at the first velocity, report.md.
 * The study is the library's gw_chain_falcon_run (chain_falcon_study.c), which
 * Python's granwave.falcon runs too: here only the flags, the checks made before
 * --out is created, and the outputs of its outcome (the command ran its own loop
 * of collisions beside it until issue #18; tests/test_falcon_one_path.c holds
 * the two to one answer). The paper's measured values (chain_falcon_report.c)
 * are quoted for comparison only (docs/physics.md 1.7); every granwave number in
 * the outputs comes from the runs.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_cli.h"
#include "chain_commands.h"
#include "chain_falcon.h"
#include "gw_chain_study.h"

/* The settings with each collision's t_max, dt_out, dt and dt_max (the rows
 * of falcon_runs.csv, velocity by velocity), or NULL when out of memory. */
static cJSON *falcon_settings(const falcon *f)
{
    cJSON *o = chain_cli_settings_json(&f->c);
    chain_cli_settings_runs(o, f->o.ncase, f->o.t_max, f->o.dt_out, f->o.dt, f->o.dt_max);
    return o;
}

static cJSON *summary_json(const falcon *f)
{
    const gw_chain_falcon_outcome *fo = &f->o;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "version", gw_version());
    cJSON_AddItemToObject(o, "settings", falcon_settings(f));
    cJSON_AddNumberToObject(o, "n_min", f->n_lo);
    cJSON_AddNumberToObject(o, "n_max", f->n_hi);
    cJSON_AddNumberToObject(o, "k_c", fo->k_c);
    cJSON_AddStringToObject(o, "wall", fo->rigid ? "rigid" : "soft");
    cJSON *a = cJSON_AddArrayToObject(o, "velocities");
    for (int iv = 0; iv < fo->nv; iv++) {
        cJSON *e = cJSON_CreateObject();
        cJSON_AddNumberToObject(e, "v_imp", fo->v_imp[iv]);
        cJSON_AddNumberToObject(e, "h_mm", fo->h_mm[iv]);
        cJSON_AddNumberToObject(e, "t_q", fo->t_q[iv]);
        cJSON_AddNumberToObject(e, "t_q_err", fo->t_q_err[iv]);
        cJSON_AddNumberToObject(e, "tau_fit_intercept", fo->tau_fit_intercept[iv]);
        cJSON_AddNumberToObject(e, "tau_fit_intercept_err", fo->tau_fit_intercept_err[iv]);
        cJSON_AddNumberToObject(e, "r2", fo->r2[iv]);
        cJSON_AddNumberToObject(e, "tau_fit_max_rel_resid", fo->tau_fit_max_rel_resid[iv]);
        cJSON_AddNumberToObject(e, "t_q_n20", fo->t_q_n20[iv]);
        cJSON_AddNumberToObject(e, "t_q_n20_err", fo->t_q_n20_err[iv]);
        cJSON_AddNumberToObject(e, "wave_speed", fo->wave_speed[iv]);
        cJSON_AddNumberToObject(e, "wave_speed_n20", fo->wave_speed_n20[iv]);
        cJSON_AddNumberToObject(e, "wave_speed_theory", fo->wave_speed_theory[iv]);
        cJSON_AddNumberToObject(e, "t_q_theory", fo->t_q_theory[iv]);
        cJSON_AddNumberToObject(e, "tau_1_theory", fo->tau_1_theory[iv]);
        cJSON_AddNumberToObject(e, "f_max_1_theory", fo->f_max_1_theory[iv]);
        cJSON_AddNumberToObject(e, "f_max_mean", fo->f_max_mean[iv]);
        cJSON_AddNumberToObject(e, "f_max_min", fo->f_max_min[iv]);
        cJSON_AddNumberToObject(e, "f_max_max", fo->f_max_max[iv]);
        cJSON_AddNumberToObject(e, "tau_max_mean", fo->tau_max_mean[iv]);
        cJSON_AddNumberToObject(e, "period_mean", fo->period_mean[iv]);
        int c1 = falcon_case(f, iv, f->n_lo), cn = falcon_case(f, iv, f->n_hi);
        /* a column held by gravity: its values are those of the stop, undecided (null) */
        const int h1 = fo->held[c1], hn = fo->held[cn];
        cJSON_AddNumberToObject(e, "tau_n_first", h1 ? NAN : fo->tau_n[c1]);
        cJSON_AddNumberToObject(e, "tau_n_last", hn ? NAN : fo->tau_n[cn]);
        cJSON_AddNumberToObject(e, "e_rel_over_e_k_last", hn ? NAN : fo->e_rel_over_e_k[cn]);
        cJSON_AddNumberToObject(e, "n_s_last", hn ? NAN : fo->n_s[cn]);
        double emax = 0;
        for (int n = f->n_lo; n <= f->n_hi; n++)
            emax = fmax(emax, fo->energy_error[falcon_case(f, iv, n)]);
        cJSON_AddNumberToObject(e, "energy_error_max", emax);
        /* per N: held by gravity (undecided, left out of the fits, means and extremes above) */
        cJSON_AddItemToObject(e, "held", gw_json_bools(fo->held + (size_t)iv * fo->nn, fo->nn));
        cJSON_AddItemToArray(a, e);
    }
    if (fo->accuracy > 0)
        cJSON_AddNumberToObject(o, "accuracy_target", fo->accuracy);
    cJSON_AddNumberToObject(o, "wall_time_s", fo->wall_time_s);
    cJSON_AddNumberToObject(o, "unfinished", fo->unfinished); /* collisions not ended at t_max */
    cJSON_AddNumberToObject(o, "n_held", fo->n_held);         /* of them, held by gravity */
    return o;
}

static int write_tables(const falcon *f, const char *dir, const char *hdr, gw_err *err)
{
    const gw_chain_falcon_outcome *o = &f->o;
    char path[4096];
    gw_afile a;
    int rc;
    if (gw_path_join(path, sizeof path, dir, "falcon_runs.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", dir);
    if ((rc = gw_afile_open(&a, path, err)) != GW_OK)
        return rc;
    fprintf(a.fp, "# %s\n", hdr);
    fprintf(a.fp, "v_imp_m_s,h_mm,n,f_max_N,tau_max_s,tau_n_s,period_s,n_maxima,n_s,cluster,"
                  "e_rel_over_e_k,eps_eff,eps_col,energy_error,steps,rhs_evals,t_max_s,dt_out_s,dt_s,dt_max_s,held\n");
    for (int iv = 0; iv < o->nv; iv++)
        for (int n = f->n_lo; n <= f->n_hi; n++) {
            int c = falcon_case(f, iv, n);
            /* held: 1 when gravity held the column (its values those of the stop, undecided) */
            fprintf(a.fp, "%.10g,%.4g,%d,%.12g,%.12g,%.12g,%.12g,%d,%d,%d,%.12g,%.12g,%.12g,%.4g,%ld,%ld,%.17g,%.17g,"
                          "%.17g,%.17g,%d\n",
                    o->v_imp[iv], o->h_mm[iv], n, o->f_max[c], o->tau_max[c], o->tau_n[c], o->period[c],
                    (int)o->n_maxima[c], (int)o->n_s[c], (int)o->cluster[c], o->e_rel_over_e_k[c], o->eps_eff[c],
                    o->eps_col[c], o->energy_error[c], (long)o->steps[c], (long)o->rhs_evals[c], o->t_max[c],
                    o->dt_out[c], o->dt[c], o->dt_max[c], o->held[c]);
        }
    if ((rc = gw_afile_commit(&a, err)) != GW_OK)
        return rc;
    if (gw_path_join(path, sizeof path, dir, "falcon_final_velocities.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", dir);
    if ((rc = gw_afile_open(&a, path, err)) != GW_OK)
        return rc;
    fprintf(a.fp, "# %s\n", hdr);
    fprintf(a.fp, "v_imp_m_s,n,bead,final_v_m_s,detach_t_s,v_tau_n_m_s\n");
    for (int i = 0; i < o->nbeads; i++) /* velocity, N, bead: the library's order */
        fprintf(a.fp, "%.10g,%d,%d,%.12g,%.12g,%.12g\n", o->bead_v_imp[i], (int)o->bead_n[i], (int)o->bead[i],
                o->final_v[i], o->detach_t[i], o->v_tau_n[i]);
    return gw_afile_commit(&a, err);
}

/* every file falcon --out may write: those a run does not write (the traces of
 * N = 15 and 30 when --n stops below them, the bead tables of long columns) are
 * an earlier run's, removed when this run's files are placed (gw_outset) */
static const char *const falcon_files[] = {
    "falcon_runs.csv", "falcon_final_velocities.csv", "falcon_summary.json", "report.md",
    "trace_n7_wall_force.csv", "trace_n7_beads.csv", "trace_n7.h5",
    "trace_n15_wall_force.csv", "trace_n15_beads.csv", "trace_n15.h5",
    "trace_n30_wall_force.csv", "trace_n30_beads.csv", "trace_n30.h5", NULL};

/* The library's traces (gw_chain_falcon_trace: N = 7, 15, 30 at the first
 * velocity; the beads for N = 7), each with its own run's settings. */
static int write_traces(const falcon *f, const char *dir, int argc, char **argv, gw_err *err)
{
    for (int k = 0; k < f->o.ntrace; k++) {
        const gw_chain_falcon_trace *t = &f->o.trace[k];
        char stem[64];
        snprintf(stem, sizeof stem, "trace_n%d", t->n);
        cJSON *set = chain_cli_settings_json(&f->c); /* this run's own settings (its dt_out may be the traces') */
        gw_chain_result r = {.run_t_max = t->t_max, .run_dt_out = t->dt_out, .run_dt = t->dt, .run_dt_max = t->dt_max};
        chain_cli_settings_run(set, &r);
        cJSON *run = cJSON_CreateObject(); /* this trace's column and impact velocity */
        cJSON_AddNumberToObject(run, "n", t->n);
        cJSON_AddNumberToObject(run, "v_imp", t->v_imp);
        char *hdr = gw_cli_one_line(gw_cli_provenance_add(gw_cli_provenance("falcon", argc, argv, set), "run", run), ' ');
        cJSON_Delete(run);
        cJSON_Delete(set);
        int rc = hdr ? gw_chain_trace_write(&t->tr, dir, stem, hdr, err)
                     : gw_err_set(err, GW_ENOMEM, "falcon: out of memory");
        free(hdr);
        if (rc != GW_OK)
            return rc;
    }
    return GW_OK;
}

/* --accuracy against the solver options is the library's rule (pick_solver in
 * chain_falcon_study.c, run before any collision; a refusal takes back what
 * --out made): the command kept a copy of it, and of the row's range, that
 * refused --accuracy 0 ("the solver options as given"), which the library and
 * Python take (test_frontend_parity). */

static const char *falcon_summary =
    "The rigid-wall study of Falcon et al. (1998): one collision for every N in\n"
    "[1, nmax] at each impact velocity (v_imp = 0.3 m/s and the paper's drop heights\n"
    "1.9, 2.9, 3.1, 5.1 mm by default). Fits tau_N = T_q (N-1) + tau_1 (GSL), gives\n"
    "the wave speed 4R/T_q, F_max(N), the force period, detachment and E_rel/E_K, and\n"
    "with --out writes CSV tables, a JSON summary, traces and a markdown report that\n"
    "sets each number beside the paper's measured value and the closed forms.";

int gw_cmd_falcon(int argc, char **argv)
{
    falcon f;
    memset(&f, 0, sizeof f);
    gw_opt opts[CHAIN_CLI_NOPTS + 7];
    chain_cli_options(&f.c, opts);
    f.c.out_names = falcon_files;
    chain_cli_out_help(opts, "write falcon_runs.csv, falcon_final_velocities.csv, falcon_summary.json, report.md and the traces of N = 7, 15, 30 (wall force; the beads for N = 7; and .h5 with HDF5) into DIR");
    const char *vlist = "0.3", *hlist = "1.9,2.9,3.1,5.1", *nrange = "1:40";
    double accuracy; /* given or not (NaN): the setup's row, set by gw_cli_study_setup */
    long jobs = 0;
    int quiet = 0;
    int k = CHAIN_CLI_NOPTS;
    opts[k++] = (gw_opt){.name = "vimp", .kind = GW_OPT_STRING, .dest = &vlist, .metavar = "V,V..",
                         .help = "impact velocities, m/s [0.3]"};
    opts[k++] = (gw_opt){.name = "heights", .kind = GW_OPT_STRING, .dest = &hlist, .metavar = "H,H..",
                         .help = "drop heights, mm, v = sqrt(2 g h), g the gravity or 9.81 when off ['none' to skip] [1.9,2.9,3.1,5.1]"};
    opts[k++] = (gw_opt){.name = "n", .kind = GW_OPT_STRING, .dest = &nrange, .metavar = "A:B",
                         .help = "column sizes [1:40]"};
    const gw_param *rows = gw_chain_falcon_setup_params(); /* falcon's own rows: accuracy; solver, dt, dt-out defaults */
    /* --accuracy is the table's row: its range [0, 1e-2] (0: the solver options
     * as given; (0, 1e-9) refused by the library) and help, checked by the row */
    if (gw_cli_opt_param(gw_param_find(rows, "accuracy"), &accuracy, &opts[k++], NULL) != GW_OK)
        return chain_cli_fail("falcon --accuracy: not an option row (a bug)");
    chain_cli_sweep_opts(opts, &k, &jobs, &quiet);
    opts[k] = (gw_opt){0};
    /* the shared rows state chain's defaults; falcon's are those of --accuracy
     * (the library's pick of the solver): its help said cvode, T_c/400 and
     * tau_1/200 while the runs used rk4 at T_c/37 sampled every tau_1/10 */
    for (const char *const *nm = (const char *const[]){"solver", "dt", "dt-out", NULL}; *nm; nm++)
        chain_cli_opt_help(opts, *nm, gw_param_find(rows, *nm)->help);
    int done = chain_cli_parse("falcon", "granwave falcon [--out DIR] [options]", falcon_summary, opts, argc, argv);
    if (done >= 0)
        return done;
    if (f.c.radii)
        return chain_cli_study_radii("falcon");
    gw_err err = {{0}};
    long a, b;
    double *vv = NULL, *hh = NULL, *v = NULL;
    int nvv = 0, nhh = 0;
    int prc;
    /* the lists in their rows' ranges, as the library's table reads them (a
     * subnormal item was refused naming no range: "give 0 or a larger value") */
    const gw_param *vrow = gw_param_find(rows, "vimp"), *hrow = gw_param_find(rows, "heights");
    if ((prc = gw_parse_int_range(nrange, "falcon --n", 1, 100000, &a, &b, &err)) != GW_OK ||
        (prc = gw_parse_double_list_in(vlist, "falcon --vimp", vrow->min, vrow->max, vrow->open_min, &vv, &nvv,
                                       &err)) != GW_OK ||
        (strcmp(hlist, "none") != 0 &&
         (prc = gw_parse_double_list_in(hlist, "falcon --heights", hrow->min, hrow->max, hrow->open_min, &hh, &nhh,
                                        &err)) != GW_OK)) {
        free(vv);
        return chain_cli_fail_rc(prc, err.msg);
    }
    if ((prc = gw_chain_falcon_sizes_check_at(a, b, nvv + nhh, &err)) != GW_OK ||
        (prc = gw_chain_study_work_check(a, b, nvv + nhh, &err)) != GW_OK) {
        free(vv);
        free(hh);
        return chain_cli_study_fail("falcon", prc, err.msg);
    }
    f.n_lo = (int)a;
    f.n_hi = (int)b;
    int nv = nvv + nhh, code = 0, rc0;
    gw_chain_falcon_setup fs;
    if (gw_chain_falcon_setup_init(&fs) != GW_OK) {
        gw_chain_falcon_setup_clear(&fs);
        return gw_cli_nomem("falcon");
    }
    /* the speeds, then the heights fallen in the run's gravity (or Earth's),
     * checked before --out is made (the library's one rule, which
     * gw_chain_falcon_run applies again) */
    v = malloc((size_t)nv * sizeof *v);
    if (!v) {
        code = chain_cli_fail_rc(GW_ENOMEM, "falcon: out of memory");
        goto out;
    }
    if ((rc0 = gw_chain_falcon_speeds(vv, nvv, hh, nhh, f.c.gravity, v, NULL, &err)) != GW_OK) {
        code = chain_cli_study_fail("falcon", rc0, err.msg);
        goto out;
    }
    f.c.params.n = f.n_lo;
    f.c.params.v_imp = v[0];
    if ((rc0 = chain_cli_resolve(&f.c, opts, "falcon", &err)) != GW_OK) {
        code = chain_cli_fail_rc(rc0, err.msg);
        goto out;
    }
    /* --out was checked by chain_cli_resolve, before the work, and is made
     * only to write (as chain's): a run that fails or is interrupted leaves
     * no directory it made */
    int ncase = nv * (f.n_hi - f.n_lo + 1);
    /* progress within the collisions (the study's watch): the first line at
     * 2 s however long the first collision, then at a bounded interval, the
     * last when the study ends; --quiet: none */
    gw_cli_progress prog;
    gw_cli_progress_init(&prog, "  ", "collisions", GW_CLI_STUDY_PROGRESS_MS);
    prog.quiet = quiet;
    int ntrace = f.c.out ? (f.n_hi >= 30) + (f.n_hi >= 15) + (f.n_hi >= 7) : 0; /* run_traces' N = 7, 15, 30 */
    char header[160]; /* with the first progress line: after the study's checks */
    snprintf(header, sizeof header, "granwave falcon: %d collisions (N = %d..%d, %d velocities%s)", ncase + ntrace,
             f.n_lo, f.n_hi, nv, ntrace == 0 ? "" : ntrace == 1 ? ", and a trace" : ntrace == 2 ? ", and 2 traces"
                                                                                             : ", and 3 traces");
    prog.header = header;
    /* the study: the library's, from the flags given (its rows are the flags) */
    int rc = gw_cli_study_setup(rows, &fs, opts, argc, argv, "falcon", &err);
    if (rc == GW_OK) {
        fs.traces = f.c.out != NULL;
        gw_chain_watch_fn watch = quiet ? NULL : gw_cli_progress_watch; /* none: no lock at every sample */
        rc = gw_chain_falcon_run_watch(&fs, NULL, NULL, watch, &prog, &f.o, &err);
        if (rc == GW_OK)
            gw_cli_progress_part(&prog, ncase + ntrace, ncase + ntrace, 1.0, 1);
    }
    if (rc != GW_OK && !f.o.trace_failed) {
        if (rc == GW_EINVAL) { /* "NAME: ..." of an option -> "falcon --NAME: ...", as the other studies */
            if (strncmp(err.msg, "falcon", 6) != 0)
                gw_cli_study_error(rows, "falcon", rc, &err);
            fprintf(stderr, "granwave %s\n", err.msg);
        } else {
            gw_cli_error("falcon", err.msg); /* the library's "falcon: out of memory" said once */
        }
        code = rc == GW_EINVAL ? 2 : 1;
        goto out;
    }
    if (f.o.accuracy > 0) { /* what the library ran, for the settings reported */
        f.c.solver = "rk4";
        f.c.method = "default";
        f.c.run.solver = gw_solver_rk4;
        f.c.run.sp.method = GW_METHOD_DEFAULT;
        f.c.run.steps_per_tc = f.o.steps_per_tc;
    }
    cJSON *sum = summary_json(&f);
    gw_cli_warnings("falcon", f.o.warnings); /* the library's text: unfinished collisions */
    gw_cli_json_warnings(sum, f.o.warnings); /* and in falcon_summary.json and --json */
    if (f.o.trace_failed) { /* a trace's run: the study stands, its --out files are not written */
        fprintf(stderr, "granwave falcon --out: %s\n", err.msg);
        code = 1;
    } else if (f.c.out) {
        cJSON *set = falcon_settings(&f);
        char *hdr = set ? gw_cli_one_line(gw_cli_provenance("falcon", argc, argv, set), ' ') : NULL;
        cJSON_Delete(set);
        char path[4096];
        gw_outset oset; /* all of this run's files in place, or none (and the earlier run's as they were) */
        memset(&oset, 0, sizeof oset);
        char made[4096] = ""; /* the first directory of --out this run creates, taken back on a failure */
        rc = hdr ? gw_cli_outset_begin(&oset, f.c.out, falcon_files, made, sizeof made, &err)
                 : gw_err_set(&err, GW_ENOMEM, "out of memory");
        if (rc == GW_OK)
            rc = write_tables(&f, f.c.out, hdr, &err);
        if (rc == GW_OK)
            rc = write_traces(&f, f.c.out, argc, argv, &err);
        if (rc == GW_OK && gw_path_join(path, sizeof path, f.c.out, "falcon_summary.json") == GW_OK)
            rc = gw_json_write(path, sum, &err);
        if (rc == GW_OK && gw_path_join(path, sizeof path, f.c.out, "report.md") == GW_OK)
            rc = falcon_write_report(&f, path, &err);
        if (rc == GW_OK)
            rc = gw_outset_commit(&oset, &err);
        gw_cli_outset_end(&oset, f.c.out, made, rc == GW_OK);
        free(hdr);
        if (rc != GW_OK) {
            fprintf(stderr, "granwave falcon --out: %s\n", err.msg);
            code = 1;
        }
    }
    if (code == 0) {
        if (f.c.json) {
            code = gw_cli_json_stdout("falcon", sum);
        } else {
            printf("granwave %s falcon: %d collisions in %.2f s\n", gw_version(), ncase, f.o.wall_time_s);
            for (int iv = 0; iv < nv; iv++) { /* n/a: undecided, the columns held (the warning says) */
                char per[32], fm[32], f0[32], f1[32], tq[32], ws[32];
                /* four significant digits, not fixed decimals: a legal slow
                 * impact (--heights 1e-7, 1.4e-6 m/s) printed v_imp 0.0000
                 * m/s and F_max 0.00 N */
                printf("  v_imp %.4g m/s: F_max %s N (%s..%s), T_q %s us, v = 4R/T_q %s m/s "
                       "(F.27: %.4g), P %s us\n",
                       f.o.v_imp[iv], gw_cli_num(fm, sizeof fm, "%.4g", f.o.f_max_mean[iv]),
                       gw_cli_num(f0, sizeof f0, "%.4g", f.o.f_max_min[iv]),
                       gw_cli_num(f1, sizeof f1, "%.4g", f.o.f_max_max[iv]),
                       gw_cli_num(tq, sizeof tq, "%.5g", f.o.t_q[iv] * 1e6),
                       gw_cli_num(ws, sizeof ws, "%.4g", f.o.wave_speed[iv]), f.o.wave_speed_theory[iv],
                       gw_cli_num(per, sizeof per, "%.4g", f.o.period_mean[iv] * 1e6));
            }
            if (f.c.out) {
                char q[GW_CLI_PATH_TEXT];
                printf("  report: %s/report.md\n", gw_cli_path(q, sizeof q, f.c.out));
            }
        }
    }
    cJSON_Delete(sum);
out:
    gw_chain_falcon_outcome_free(&f.o);
    gw_chain_falcon_setup_clear(&fs);
    free(v);
    free(vv);
    free(hh);
    chain_cli_free(&f.c);
    return code;
}
