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
 * The paper's measured values below are quoted for comparison only (docs/physics.md
 * 1.7); every granwave number in the outputs comes from the runs.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_cli.h"
#include "chain_commands.h"
#include "chain_falcon.h"
#include "gw_chain_study.h"

static void analyse_velocity(falcon *f, int iv)
{
    falcon_vel *fv = &f->fv[iv];
    gw_chain_falcon_fit a;
    gw_chain_falcon_analyse(&f->c.params, fv->v, res_at(f, iv, f->n_lo), f->n_lo, f->n_hi, &a);
    fv->fit = a.fit;
    fv->fit20 = a.fit20;
    fv->f_mean = a.f_mean;
    fv->f_min = a.f_min;
    fv->f_max = a.f_max;
    fv->tau_max_mean = a.tau_max_mean;
    fv->period_mean = a.period_mean;
    fv->t_q_theory = a.t_q_theory;
    fv->tau_1_theory = a.tau_1_theory;
    fv->f_max_1_theory = a.f_max_1_theory;
    fv->speed = a.speed;
    fv->speed20 = a.speed20;
    fv->speed_theory = a.speed_theory;
}

/* The settings with each collision's t_max, dt_out, dt and dt_max (the rows
 * of falcon_runs.csv, velocity by velocity), or NULL when out of memory. */
static cJSON *falcon_settings(const falcon *f)
{
    long nc = falcon_ncase(f);
    double *v = malloc(4 * (size_t)(nc > 0 ? nc : 1) * sizeof *v);
    if (!v)
        return NULL;
    for (long i = 0; i < nc; i++) {
        v[i] = f->res[i].run_t_max;
        v[nc + i] = f->res[i].run_dt_out;
        v[2 * nc + i] = f->res[i].run_dt;
        v[3 * nc + i] = f->res[i].run_dt_max;
    }
    cJSON *o = chain_cli_settings_json(&f->c);
    chain_cli_settings_runs(o, nc, v, v + nc, v + 2 * nc, v + 3 * nc);
    free(v);
    return o;
}

static cJSON *summary_json(const falcon *f)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "version", gw_version());
    cJSON_AddItemToObject(o, "settings", falcon_settings(f));
    cJSON_AddNumberToObject(o, "n_min", f->n_lo);
    cJSON_AddNumberToObject(o, "n_max", f->n_hi);
    cJSON_AddNumberToObject(o, "k_c", gw_chain_kc(f->c.params.k));
    cJSON_AddStringToObject(o, "wall", f->c.params.kwall > gw_chain_kc(f->c.params.k) ? "rigid" : "soft");
    cJSON *a = cJSON_AddArrayToObject(o, "velocities");
    for (int iv = 0; iv < f->nv; iv++) {
        const falcon_vel *fv = &f->fv[iv];
        cJSON *e = cJSON_CreateObject();
        cJSON_AddNumberToObject(e, "v_imp", fv->v);
        cJSON_AddNumberToObject(e, "h_mm", fv->h_mm);
        cJSON_AddNumberToObject(e, "t_q", fv->fit.c1);
        cJSON_AddNumberToObject(e, "t_q_err", fv->fit.c1_err);
        cJSON_AddNumberToObject(e, "tau_fit_intercept", fv->fit.c0);
        cJSON_AddNumberToObject(e, "tau_fit_intercept_err", fv->fit.c0_err);
        cJSON_AddNumberToObject(e, "r2", fv->fit.r2);
        cJSON_AddNumberToObject(e, "tau_fit_max_rel_resid", fv->fit.max_rel_resid);
        cJSON_AddNumberToObject(e, "t_q_n20", fv->fit20.c1);
        cJSON_AddNumberToObject(e, "t_q_n20_err", fv->fit20.c1_err);
        cJSON_AddNumberToObject(e, "wave_speed", fv->speed);
        cJSON_AddNumberToObject(e, "wave_speed_n20", fv->speed20);
        cJSON_AddNumberToObject(e, "wave_speed_theory", fv->speed_theory);
        cJSON_AddNumberToObject(e, "t_q_theory", fv->t_q_theory);
        cJSON_AddNumberToObject(e, "tau_1_theory", fv->tau_1_theory);
        cJSON_AddNumberToObject(e, "f_max_1_theory", fv->f_max_1_theory);
        cJSON_AddNumberToObject(e, "f_max_mean", fv->f_mean);
        cJSON_AddNumberToObject(e, "f_max_min", fv->f_min);
        cJSON_AddNumberToObject(e, "f_max_max", fv->f_max);
        cJSON_AddNumberToObject(e, "tau_max_mean", fv->tau_max_mean);
        cJSON_AddNumberToObject(e, "period_mean", fv->period_mean);
        const gw_chain_result *r1 = res_at(f, iv, f->n_lo), *rn = res_at(f, iv, f->n_hi);
        cJSON_AddNumberToObject(e, "tau_n_first", r1->tau_n);
        cJSON_AddNumberToObject(e, "tau_n_last", rn->tau_n);
        cJSON_AddNumberToObject(e, "e_rel_over_e_k_last", rn->e_rel_over_e_k);
        cJSON_AddNumberToObject(e, "n_s_last", rn->n_s);
        double emax = 0;
        for (int n = f->n_lo; n <= f->n_hi; n++)
            emax = fmax(emax, res_at(f, iv, n)->energy_error);
        cJSON_AddNumberToObject(e, "energy_error_max", emax);
        cJSON_AddItemToArray(a, e);
    }
    if (f->accuracy > 0)
        cJSON_AddNumberToObject(o, "accuracy_target", f->accuracy);
    cJSON_AddNumberToObject(o, "wall_time_s", f->wall_s);
    int unfinished = 0;
    for (int i = 0; i < falcon_ncase(f); i++)
        unfinished += !f->res[i].converged;
    cJSON_AddNumberToObject(o, "unfinished", unfinished); /* collisions not ended at t_max */
    return o;
}

static int write_tables(const falcon *f, const char *dir, const char *hdr, gw_err *err)
{
    char path[4096];
    gw_afile a;
    int rc;
    if (gw_path_join(path, sizeof path, dir, "falcon_runs.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", dir);
    if ((rc = gw_afile_open(&a, path, err)) != GW_OK)
        return rc;
    fprintf(a.fp, "# %s\n", hdr);
    fprintf(a.fp, "v_imp_m_s,h_mm,n,f_max_N,tau_max_s,tau_n_s,period_s,n_maxima,n_s,cluster,"
                  "e_rel_over_e_k,eps_eff,eps_col,energy_error,steps,rhs_evals,t_max_s,dt_out_s,dt_s,dt_max_s\n");
    for (int iv = 0; iv < f->nv; iv++)
        for (int n = f->n_lo; n <= f->n_hi; n++) {
            const gw_chain_result *r = res_at(f, iv, n);
            fprintf(a.fp, "%.10g,%.4g,%d,%.12g,%.12g,%.12g,%.12g,%d,%d,%d,%.12g,%.12g,%.12g,%.4g,%ld,%ld,%.17g,%.17g,"
                          "%.17g,%.17g\n",
                    f->fv[iv].v, f->fv[iv].h_mm, n, r->f_max, r->tau_max, r->tau_n, r->period,
                    r->n_maxima, r->n_s, r->cluster, r->e_rel_over_e_k, r->eps_eff, r->eps_col,
                    r->energy_error, r->stats.steps, r->stats.rhs_evals, r->run_t_max, r->run_dt_out, r->run_dt,
                    r->run_dt_max);
        }
    if ((rc = gw_afile_commit(&a, err)) != GW_OK)
        return rc;
    if (gw_path_join(path, sizeof path, dir, "falcon_final_velocities.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", dir);
    if ((rc = gw_afile_open(&a, path, err)) != GW_OK)
        return rc;
    fprintf(a.fp, "# %s\n", hdr);
    fprintf(a.fp, "v_imp_m_s,n,bead,final_v_m_s,detach_t_s,v_tau_n_m_s\n");
    for (int iv = 0; iv < f->nv; iv++)
        for (int n = f->n_lo; n <= f->n_hi; n++) {
            const gw_chain_result *r = res_at(f, iv, n);
            for (int i = 0; i < n; i++)
                fprintf(a.fp, "%.10g,%d,%d,%.12g,%.12g,%.12g\n", f->fv[iv].v, n, i + 1,
                        r->final_v[i], r->detach_t[i], r->v_tau_n[i]);
        }
    return gw_afile_commit(&a, err);
}

/* Traces for N = 7, 15, 30 at the first velocity (bead trajectories for N = 7). */
/* every file falcon --out may write: those a run does not write (the traces of
 * N = 15 and 30 when --n stops below them, the bead tables of long columns) are
 * an earlier run's, removed when this run's files are placed (gw_outset) */
static const char *const falcon_files[] = {
    "falcon_runs.csv", "falcon_final_velocities.csv", "falcon_summary.json", "report.md",
    "trace_n7_wall_force.csv", "trace_n7_beads.csv", "trace_n7.h5",
    "trace_n15_wall_force.csv", "trace_n15_beads.csv", "trace_n15.h5",
    "trace_n30_wall_force.csv", "trace_n30_beads.csv", "trace_n30.h5", NULL};

static int write_traces(const falcon *f, const char *dir, int argc, char **argv, gw_err *err)
{
    const int ns[] = {7, 15, 30};
    for (size_t k = 0; k < sizeof ns / sizeof ns[0]; k++) {
        if (ns[k] > f->n_hi)
            continue;
        gw_chain_params p = f->c.params;
        p.n = ns[k];
        p.v_imp = f->v[0];
        gw_chain *c = NULL;
        int rc = gw_chain_create(&p, &c, err);
        if (rc != GW_OK)
            return rc;
        gw_chain_trace tr;
        gw_chain_trace_init(&tr, p.n);
        gw_chain_run_opts o = f->c.run;
        if (f->accuracy > 0) /* tau_1/50, 0.7 us at 0.3 m/s: one sample per pixel of
                                the 1080-pixel-wide figures of the longest (N = 30,
                                0.8 ms) trace, 45 per force period; maxima are events */
            o.dt_out = gw_chain_tau1(p.mass, p.kwall, p.v_imp) / 50;
        o.sample = gw_chain_trace_sample;
        o.sample_ctx = &tr;
        gw_chain_result r;
        rc = gw_chain_collide(c, &o, &r, err);
        char stem[64];
        snprintf(stem, sizeof stem, "trace_n%d", p.n);
        char *hdr = NULL; /* this run's own settings (its dt_out may be the traces') */
        if (rc == GW_OK) {
            cJSON *set = chain_cli_settings_json(&f->c);
            chain_cli_settings_run(set, &r);
            cJSON *run = cJSON_CreateObject(); /* this trace's column and impact velocity */
            cJSON_AddNumberToObject(run, "n", p.n);
            cJSON_AddNumberToObject(run, "v_imp", p.v_imp);
            hdr = gw_cli_one_line(gw_cli_provenance_add(gw_cli_provenance("falcon", argc, argv, set), "run", run), ' ');
            cJSON_Delete(run);
            cJSON_Delete(set);
            if (!hdr)
                rc = gw_err_set(err, GW_ENOMEM, "falcon: out of memory");
        }
        if (rc == GW_OK) {
            if (p.n == 7) {
                rc = gw_chain_trace_write(&tr, dir, stem, hdr, err);
            } else { /* wall force only (no _beads.csv, no x, v in the .h5): the bead
                        table of long columns is large; an earlier run's _beads.csv
                        is removed when the set is placed (falcon_files) */
                gw_chain_trace w = tr;
                w.n = 0;
                rc = gw_chain_trace_write(&w, dir, stem, hdr, err);
            }
        }
        free(hdr);
        gw_chain_result_free(&r);
        gw_chain_trace_free(&tr);
        gw_chain_free(c);
        if (rc != GW_OK)
            return rc;
    }
    return GW_OK;
}

/* The solver by accuracy target: unless a solver option is given, RK4 with events
 * as roots and dt = T_c/M, M = gw_chain_rk4_steps_per_tc(accuracy) (F_max and
 * tau_N within the target, measured), sampled every tau_1/10 of the fastest
 * impact (samples only feed the energy check and the state-based contact check;
 * F_max and tau_N are events). The traces are sampled every tau_1/50 (see
 * write_traces). */
static int falcon_pick_solver(falcon *f, const gw_opt *opts, double accuracy, gw_err *err)
{
    const char *given[] = {"solver", "method", "rtol", "atol", "dt"};
    int any = 0;
    for (size_t i = 0; i < sizeof given / sizeof given[0]; i++)
        any |= gw_cli_find(opts, given[i])->seen;
    if (any) {
        if (gw_cli_find(opts, "accuracy")->seen)
            return gw_err_set(err, GW_EINVAL, "falcon --accuracy: give either --accuracy or the solver options");
        return GW_OK;
    }
    if (!gw_chain_rk4_study_covers(&f->c.params, f->n_hi)) { /* the library's rule, as gw_chain_falcon_run */
        if (gw_cli_find(opts, "accuracy")->seen)
            return gw_err_set(err, GW_EINVAL, "falcon --accuracy: the step study covers undamped columns "
                                              "of N <= 40 without gravity on a Hertz wall, without sensor "
                                              "body or guide friction; give --solver instead");
        return GW_OK; /* outside the study: the adaptive default */
    }
    double vmax = 0;
    for (int i = 0; i < f->nv; i++)
        vmax = fmax(vmax, f->v[i]);
    if (gw_chain_rk4_study_apply(&f->c.run, &f->c.params, accuracy, vmax, gw_cli_find(opts, "dt-out")->seen) <= 0)
        return gw_err_set(err, GW_EINVAL, "falcon --accuracy: %g outside [1e-9, 1e-2]", accuracy);
    f->c.solver = "rk4";
    f->c.method = "default";
    f->accuracy = accuracy;
    return GW_OK;
}

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
    chain_cli_out_help(opts, "write falcon_runs.csv, falcon_final_velocities.csv, falcon_summary.json, report.md and the traces of N = 7, 15, 30 (wall force; the beads for N = 7; and .h5 with HDF5) into DIR");
    const char *vlist = "0.3", *hlist = "1.9,2.9,3.1,5.1", *nrange = "1:40";
    double accuracy = 1e-6;
    long jobs = 0;
    int quiet = 0;
    int k = CHAIN_CLI_NOPTS;
    opts[k++] = (gw_opt){.name = "vimp", .kind = GW_OPT_STRING, .dest = &vlist, .metavar = "V,V..",
                         .help = "impact velocities, m/s [0.3]"};
    opts[k++] = (gw_opt){.name = "heights", .kind = GW_OPT_STRING, .dest = &hlist, .metavar = "H,H..",
                         .help = "drop heights, mm, v = sqrt(2 g h), g the gravity or 9.81 when off ['none' to skip] [1.9,2.9,3.1,5.1]"};
    opts[k++] = (gw_opt){.name = "n", .kind = GW_OPT_STRING, .dest = &nrange, .metavar = "A:B",
                         .help = "column sizes [1:40]"};
    opts[k++] = (gw_opt){.name = "accuracy", .kind = GW_OPT_DOUBLE, .dest = &accuracy, .metavar = "A",
                         .help = "relative accuracy of F_max and tau_N when no solver option is given: "
                                 "RK4, dt = T_c/M with M from a measured convergence study [1e-6]",
                         .lo = 1e-9, .hi = 1e-2};
    chain_cli_sweep_opts(opts, &k, &jobs, &quiet);
    opts[k] = (gw_opt){0};
    /* the shared rows state chain's defaults; falcon's are those of --accuracy
     * (falcon_pick_solver): its help said cvode, T_c/400 and tau_1/200 while
     * the runs used rk4 at T_c/37 sampled every tau_1/10 */
    const gw_param *rows = gw_chain_falcon_setup_params(); /* falcon's own solver, dt, dt-out defaults */
    for (const char *const *nm = (const char *const[]){"solver", "dt", "dt-out", NULL}; *nm; nm++)
        chain_cli_opt_help(opts, *nm, gw_param_find(rows, *nm)->help);
    int done = chain_cli_parse("falcon", "granwave falcon [--out DIR] [options]", falcon_summary, opts, argc, argv);
    if (done >= 0)
        return done;
    if (f.c.radii)
        return chain_cli_fail("falcon --radii: per-bead radii need a fixed N (use granwave chain)");
    gw_err err = {{0}};
    long a, b;
    double *vv = NULL, *hh = NULL;
    int nvv = 0, nhh = 0;
    if (gw_parse_int_range(nrange, "falcon --n", 1, 100000, &a, &b, &err) != GW_OK ||
        gw_parse_double_list(vlist, "falcon --vimp", &vv, &nvv, &err) != GW_OK ||
        (strcmp(hlist, "none") != 0 &&
         gw_parse_double_list(hlist, "falcon --heights", &hh, &nhh, &err) != GW_OK)) {
        free(vv);
        return chain_cli_fail(err.msg);
    }
    if (gw_chain_falcon_sizes_check(a, b, &err) != GW_OK || gw_chain_study_work_check(a, b, nvv + nhh, &err) != GW_OK) {
        free(vv);
        free(hh);
        return chain_cli_study_fail("falcon", err.msg);
    }
    f.n_lo = (int)a;
    f.n_hi = (int)b;
    f.nv = nvv + nhh;
    f.v = malloc((size_t)f.nv * sizeof *f.v);
    f.fv = calloc((size_t)f.nv, sizeof *f.fv);
    int code = 0, rc0;
    if (!f.v || !f.fv) {
        code = chain_cli_fail("falcon: out of memory");
        goto out;
    }
    /* the speeds, then the heights fallen in the run's gravity (or Earth's):
     * the library's one rule, as gw_chain_falcon_run */
    double *h_mm = malloc((size_t)f.nv * sizeof *h_mm);
    if (!h_mm) {
        code = chain_cli_fail("falcon: out of memory");
        goto out;
    }
    if (gw_chain_falcon_speeds(vv, nvv, hh, nhh, f.c.gravity, f.v, h_mm, &err) != GW_OK) {
        free(h_mm);
        code = chain_cli_study_fail("falcon", err.msg);
        goto out;
    }
    for (int i = 0; i < f.nv; i++) {
        f.fv[i].v = f.v[i];
        f.fv[i].h_mm = h_mm[i];
    }
    free(h_mm);
    f.c.params.n = f.n_lo;
    f.c.params.v_imp = f.v[0];
    if ((rc0 = chain_cli_resolve(&f.c, opts, "falcon", &err)) != GW_OK) {
        code = chain_cli_fail_rc(rc0, err.msg);
        goto out;
    }
    if ((rc0 = falcon_pick_solver(&f, opts, accuracy, &err)) != GW_OK) {
        code = chain_cli_fail(err.msg);
        goto out;
    }
    char made[4096] = ""; /* what --out this run creates, taken back on a refusal */
    if (f.c.out && gw_cli_mkdir_out(f.c.out, made, sizeof made, &err) != GW_OK) {
        fprintf(stderr, "granwave falcon --out: %s\n", err.msg); /* the library's message names the path only */
        code = 2;
        goto out;
    }
    int ncase = f.nv * (f.n_hi - f.n_lo + 1);
    f.res = calloc((size_t)ncase, sizeof *f.res);
    if (!f.res) {
        code = chain_cli_fail("falcon: out of memory");
        goto out;
    }
    double t0 = gw_clock_ms();
    gw_cli_progress prog;
    gw_cli_progress_init(&prog, "  ", "collisions", 0);
    char header[128]; /* with the first progress line: after the study's checks */
    snprintf(header, sizeof header, "granwave falcon: %d collisions (N = %d..%d, %d velocities)", ncase, f.n_lo,
             f.n_hi, f.nv);
    prog.header = header;
    int rc = gw_chain_sweep_n_progress(&f.c.params, &f.c.run, f.v, f.nv, f.n_lo, f.n_hi, (int)jobs,
                                       quiet ? NULL : gw_cli_progress_report, &prog, f.res, &err);
    f.wall_s = (gw_clock_ms() - t0) / 1e3;
    if (rc != GW_OK) {
        if (rc == GW_EINVAL) { /* "NAME: ..." of an option -> "falcon --NAME: ...", as the other studies */
            gw_cli_study_error(gw_chain_setup_params(), "falcon", rc, &err);
            fprintf(stderr, "granwave %s\n", err.msg);
        } else {
            fprintf(stderr, "granwave falcon: %s\n", err.msg);
        }
        code = rc == GW_EINVAL ? 2 : 1;
        if (rc == GW_EINVAL && made[0])
            gw_cli_unmake(f.c.out, made);
        goto out;
    }
    for (int iv = 0; iv < f.nv; iv++)
        analyse_velocity(&f, iv);
    cJSON *sum = summary_json(&f);
    chain_cli_warn_unfinished("falcon", (int)cJSON_GetObjectItem(sum, "unfinished")->valuedouble, ncase);
    if (f.c.out) {
        cJSON *set = falcon_settings(&f);
        char *hdr = set ? gw_cli_one_line(gw_cli_provenance("falcon", argc, argv, set), ' ') : NULL;
        cJSON_Delete(set);
        char path[4096];
        gw_outset oset; /* all of this run's files in place, or none (and the earlier run's as they were) */
        rc = gw_outset_begin(&oset, f.c.out, falcon_files, &err);
        if (rc == GW_OK)
            rc = write_tables(&f, f.c.out, hdr ? hdr : "", &err);
        if (rc == GW_OK)
            rc = write_traces(&f, f.c.out, argc, argv, &err);
        if (rc == GW_OK && gw_path_join(path, sizeof path, f.c.out, "falcon_summary.json") == GW_OK)
            rc = gw_json_write(path, sum, &err);
        if (rc == GW_OK && gw_path_join(path, sizeof path, f.c.out, "report.md") == GW_OK)
            rc = falcon_write_report(&f, path, &err);
        if (rc == GW_OK)
            rc = gw_outset_commit(&oset, &err);
        gw_outset_abort(&oset);
        free(hdr);
        if (rc != GW_OK) {
            fprintf(stderr, "granwave falcon --out: %s\n", err.msg);
            code = 1;
        }
    }
    if (code == 0) {
        if (f.c.json) {
            gw_json_print(sum, stdout);
        } else {
            printf("granwave %s falcon: %d collisions in %.2f s\n", gw_version(), ncase, f.wall_s);
            for (int iv = 0; iv < f.nv; iv++) {
                const falcon_vel *fv = &f.fv[iv];
                char per[32];
                printf("  v_imp %.4f m/s: F_max %.2f N (%.2f..%.2f), T_q %.3f us, v = 4R/T_q %.1f m/s "
                       "(F.27: %.1f), P %s us\n",
                       fv->v, fv->f_mean, fv->f_min, fv->f_max, fv->fit.c1 * 1e6, fv->speed,
                       fv->speed_theory, gw_cli_num(per, sizeof per, "%.2f", fv->period_mean * 1e6));
            }
            if (f.c.out)
                printf("  report: %s/report.md\n", f.c.out);
        }
    }
    cJSON_Delete(sum);
out:
    for (int i = 0; f.res && i < falcon_ncase(&f); i++)
        gw_chain_result_free(&f.res[i]);
    free(f.res);
    free(f.v);
    free(f.fv);
    free(vv);
    free(hh);
    chain_cli_free(&f.c);
    return code;
}
