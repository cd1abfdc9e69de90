/*
 * chain_wavespeed.c: `granwave wavespeed`, the deformation-wave speed of the
 * column against v_imp measured three independent ways (docs/physics.md 1.3;
 * equations in chain_wave_study.c, which computes them: 4R/T_q (F.4, F.6), the
 * front's time of flight, the group speed of the compressed chain and its
 * relation to the front speed of F.27). Fits v = A v_imp^beta, C3 of (F.16),
 * P = C2 (m/k)^(2/5) v_imp^(-1/5) (F.15). Here only the command line: options,
 * the study call, JSON, CSV and text. Units: SI.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_cli.h"
#include "chain_options.h"

static cJSON *fit_json(const double f[4])
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "beta", f[0]);
    cJSON_AddNumberToObject(o, "beta_err", f[1]);
    cJSON_AddNumberToObject(o, "prefactor", f[2]);
    cJSON_AddNumberToObject(o, "c3", f[3]);
    return o;
}

static const char *ws_summary =
    "Deformation-wave speed of the column against the impact velocity, three ways:\n"
    "(a) 4R/T_q from the slope of tau_N(N), (b) time of flight of the compression\n"
    "front, (c) long-wave group velocity of the chain compressed by the mean wall\n"
    "force. Power-law fits v = A v_imp^beta with standard errors, C3 of (F.16), and\n"
    "the period fit P = C2 (m/k)^(2/5) v_imp^(-1/5) (F.15).";

/* the files of --out DIR (the table and the JSON of one run) */
static const char *const ws_files[] = {"wavespeed.csv", "wavespeed.json", NULL};

int gw_cmd_wavespeed(int argc, char **argv)
{
    chain_cli c;
    gw_opt opts[CHAIN_CLI_NOPTS + 6];
    chain_cli_options(&c, opts);
    c.out_names = ws_files;
    chain_cli_out_help(opts, "write wavespeed.csv and wavespeed.json into DIR");
    const char *vlist = "0.075,0.15,0.3,0.5", *nrange = "5:40";
    double frac = 0.1;
    long jobs = 0;
    int quiet = 0, k = CHAIN_CLI_NOPTS;
    opts[k++] = (gw_opt){.name = "vimp", .kind = GW_OPT_STRING, .dest = &vlist, .metavar = "V,V..",
                         .help = "impact velocities, m/s [0.075,0.15,0.3,0.5]"};
    opts[k++] = (gw_opt){.name = "n", .kind = GW_OPT_STRING, .dest = &nrange, .metavar = "A:B",
                         .help = "column sizes for the tau_N fit; B is the front column [5:40]"};
    /* --threshold is the table's row: its range [1e-6, 1] and help. The option
     * had its own range, (0, 1], and help without one: "0 is outside (0, 1]",
     * then "1e-07 is outside [1e-06, 1]" from the library for a value inside */
    if (gw_cli_opt_param(gw_param_find(gw_chain_wavespeed_setup_params(), "threshold"), &frac, &opts[k++], NULL) !=
        GW_OK)
        return chain_cli_fail("wavespeed --threshold: not an option row (a bug)");
    chain_cli_sweep_opts(opts, &k, &jobs, &quiet);
    opts[k] = (gw_opt){0};
    int done = chain_cli_parse("wavespeed", "granwave wavespeed [options]", ws_summary, opts, argc, argv);
    if (done >= 0)
        return done;
    if (c.radii)
        return chain_cli_study_radii("wavespeed");
    gw_err err = {{0}};
    long a, b;
    double *v = NULL;
    int nv = 0;
    int prc;
    if ((prc = gw_parse_int_range(nrange, "wavespeed --n", 1, 100000, &a, &b, &err)) != GW_OK ||
        (prc = gw_parse_double_list_in(vlist, "wavespeed --vimp", GW_CHAIN_VIMP_MIN, GW_CHAIN_VIMP_MAX, 0, &v, &nv,
                                       &err)) != GW_OK)
        return chain_cli_fail_rc(prc, err.msg);
    if (b - a < 2 || b < 8) {
        free(v);
        return chain_cli_fail("wavespeed --n: need at least 3 sizes and a largest column of >= 8 beads");
    }
    if ((prc = gw_chain_study_speeds_check(v, nv, nv, &err)) != GW_OK ||
        (prc = gw_chain_study_work_check(a, b, nv, &err)) != GW_OK) {
        free(v);
        return chain_cli_study_fail("wavespeed", prc, err.msg);
    }
    c.params.n = (int)b;
    c.params.v_imp = v[0];
    /* --out checked here, before the work, and made only to write (as chain's):
     * a run that fails or is interrupted leaves no directory it made */
    int rrc = chain_cli_resolve(&c, opts, "wavespeed", &err);
    if (rrc != GW_OK) {
        free(v);
        chain_cli_free(&c);
        return chain_cli_fail_rc(rrc, err.msg);
    }
    int code = 0;
    gw_chain_wavespeed_setup ws;
    if (gw_chain_wavespeed_setup_init(&ws) != GW_OK) {
        gw_chain_wavespeed_setup_clear(&ws);
        return gw_cli_nomem("wavespeed");
    }
    gw_chain_wavespeed_outcome wo;
    memset(&wo, 0, sizeof wo);
    /* progress within the collisions, as falcon's (--quiet: none) */
    gw_cli_progress prog;
    gw_cli_progress_init(&prog, "  ", "collisions", GW_CLI_STUDY_PROGRESS_MS);
    prog.quiet = quiet;
    int rc = gw_cli_study_setup(gw_chain_wavespeed_setup_params(), &ws, opts, argc, argv, "wavespeed", &err);
    const int ncoll = nv * (int)(b - a + 2); /* the tau_N sweep's and a front column per velocity */
    char header[160]; /* with the first progress line: after the study's checks */
    snprintf(header, sizeof header, "granwave wavespeed: %d collisions (N = %ld..%ld and the front's N = %ld at %d "
             "velocities)", ncoll, a, b, b, nv);
    prog.header = header;
    gw_chain_watch_fn watch = quiet ? NULL : gw_cli_progress_watch; /* none: no lock at every sample */
    if (rc == GW_OK && (rc = gw_chain_wavespeed_run_watch(&ws, NULL, NULL, watch, &prog, &wo, &err)) == GW_OK)
        gw_cli_progress_part(&prog, ncoll, ncoll, 1.0, 1);
    if (rc != GW_OK) {
        if (strncmp(err.msg, "wavespeed", 9) != 0)
            gw_cli_study_error(gw_chain_wavespeed_setup_params(), "wavespeed", rc, &err);
        fprintf(stderr, "granwave %s\n", err.msg);
        code = rc == GW_EINVAL ? 2 : 1;
    } else {
        const double *v_tq = wo.v_tq, *v_front = wo.v_front, *v_group = wo.v_group, *v_gf = wo.v_group_front;
        const double *t_q = wo.t_q, *fbar = wo.mean_wall_force, *period = wo.period;
        const double *f_tq = wo.fits[0], *f_fr = wo.fits[1], *f_gr = wo.fits[2], *f_gf = wo.fits[3];
        double wall_s = wo.wall_time_s, c2 = wo.c2, worst = wo.max_disagreement;
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "version", gw_version());
        cJSON_AddItemToObject(o, "v_imp", gw_json_doubles(v, nv));
        cJSON_AddItemToObject(o, "v_tq", gw_json_doubles(v_tq, nv));
        cJSON_AddItemToObject(o, "v_front", gw_json_doubles(v_front, nv));
        cJSON_AddItemToObject(o, "v_group", gw_json_doubles(v_group, nv));
        cJSON_AddItemToObject(o, "v_group_front", gw_json_doubles(v_gf, nv));
        cJSON_AddItemToObject(o, "t_q", gw_json_doubles(t_q, nv));
        cJSON_AddItemToObject(o, "mean_wall_force", gw_json_doubles(fbar, nv));
        cJSON_AddItemToObject(o, "period", gw_json_doubles(period, nv));
        cJSON_AddNumberToObject(o, "beta", wo.beta);
        cJSON_AddNumberToObject(o, "beta_err", wo.beta_err);
        cJSON_AddNumberToObject(o, "c3", wo.c3);
        cJSON_AddNumberToObject(o, "c3_theory", wo.c3_theory);
        cJSON *fits = cJSON_AddObjectToObject(o, "fits");
        cJSON_AddItemToObject(fits, "tq", fit_json(f_tq));
        cJSON_AddItemToObject(fits, "front", fit_json(f_fr));
        cJSON_AddItemToObject(fits, "group", fit_json(f_gr));
        cJSON_AddItemToObject(fits, "group_front", fit_json(f_gf));
        cJSON_AddNumberToObject(o, "c2", c2);
        cJSON_AddNumberToObject(o, "beta_period", wo.beta_period);
        cJSON_AddNumberToObject(o, "beta_period_err", wo.beta_period_err);
        cJSON_AddNumberToObject(o, "max_disagreement", worst); /* tq, front, group/sqrt(3/2) */
        cJSON_AddBoolToObject(o, "fitted", wo.fitted); /* false: one speed, the fits null */
        cJSON_AddNumberToObject(o, "front_threshold_fraction", frac);
        cJSON_AddNumberToObject(o, "n_min", (double)a);
        cJSON_AddNumberToObject(o, "n_max", (double)b);
        cJSON_AddNumberToObject(o, "wall_time_s", wall_s);
        cJSON_AddNumberToObject(o, "unfinished", wo.unfinished);
        /* held by gravity (undecided, left out of every fit and speed): the count (the
           tau_N sweep's and the front columns), per [velocity][N] and per front column */
        cJSON_AddNumberToObject(o, "n_held", wo.n_held);
        cJSON *held = cJSON_AddArrayToObject(o, "held");
        for (int iv = 0; iv < nv; iv++)
            cJSON_AddItemToArray(held, gw_json_bools(wo.held + (size_t)iv * wo.nn, wo.nn));
        cJSON_AddItemToObject(o, "front_held", gw_json_bools(wo.front_held, nv));
        gw_cli_warnings("wavespeed", wo.warnings); /* unfinished collisions of the tau_N sweep */
        gw_cli_json_warnings(o, wo.warnings);      /* and in wavespeed.json and --json */
        cJSON *set = chain_cli_settings_json(&c);
        chain_cli_settings_runs(set, wo.ncase, wo.t_max, wo.dt_out, wo.dt, wo.dt_max);
        cJSON_AddItemToObject(o, "settings", set);
        char path[4096];
        if (c.out) {
            gw_afile af;
            gw_outset oset; /* the table and the JSON of one run, or (a write failed) the earlier run's */
            memset(&oset, 0, sizeof oset);
            char *hdr = gw_cli_one_line(gw_cli_provenance("wavespeed", argc, argv, set), ' ');
            char made[4096] = ""; /* the first directory of --out this run creates, taken back on a failure */
            if ((!hdr && gw_err_set(&err, GW_ENOMEM, "out of memory") != GW_OK) ||
                gw_cli_outset_begin(&oset, c.out, ws_files, made, sizeof made, &err) != GW_OK ||
                gw_path_join(path, sizeof path, c.out, "wavespeed.csv") != GW_OK ||
                gw_afile_open(&af, path, &err) != GW_OK) {
                code = 1;
            } else {
                fprintf(af.fp, "# %s\nv_imp_m_s,v_tq_m_s,v_front_m_s,v_group_m_s,v_group_front_m_s,t_q_s,period_s,mean_wall_force_N\n",
                        hdr ? hdr : "");
                for (int iv = 0; iv < nv; iv++)
                    fprintf(af.fp, "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", v[iv], v_tq[iv],
                            v_front[iv], v_group[iv], v_gf[iv], t_q[iv], period[iv], fbar[iv]);
                if (gw_afile_commit(&af, &err) != GW_OK)
                    code = 1;
            }
            if (code == 0 && (gw_path_join(path, sizeof path, c.out, "wavespeed.json") != GW_OK ||
                              gw_json_write(path, o, &err) != GW_OK))
                code = 1;
            if (code == 0 && gw_outset_commit(&oset, &err) != GW_OK)
                code = 1;
            gw_cli_outset_end(&oset, c.out, made, code == 0);
            if (code)
                fprintf(stderr, "granwave wavespeed --out: %s\n", err.msg);
            free(hdr);
        }
        if (code == 0 && c.json) {
            code = gw_cli_json_stdout("wavespeed", o);
        } else if (code == 0) {
            printf("granwave %s wavespeed (%.1f s)\n  v_imp     v_tq    v_front  v_group  v_group/sqrt(3/2)  (m/s)\n",
                   gw_version(), wall_s);
            for (int iv = 0; iv < nv; iv++) { /* n/a: undecided, held columns (the warning says) */
                char s1[32], s2[32], s3[32], s4[32];
                printf("  %-8.4g %8s %8s %8s %8s\n", v[iv], gw_cli_num(s1, sizeof s1, "%.2f", v_tq[iv]),
                       gw_cli_num(s2, sizeof s2, "%.2f", v_front[iv]), gw_cli_num(s3, sizeof s3, "%.2f", v_group[iv]),
                       gw_cli_num(s4, sizeof s4, "%.2f", v_gf[iv]));
            }
            if (!wo.fitted) { /* no power law through one point: said, not printed as nan */
                printf("  beta, C3: not fitted (one speed; the fits over v_imp need two)\n");
            } else {
                /* each estimator's exponent, "+- err" where the fit has one (three speeds or
                 * more); n/a where held columns left fewer than two decided speeds */
                const double *fs[3] = {f_tq, f_fr, f_gr};
                char b[3][64], c[4][32];
                int all_err = 1, all_val = 1;
                for (int i = 0; i < 3; i++) {
                    all_err &= isfinite(fs[i][1]);
                    all_val &= isfinite(fs[i][0]);
                    if (isfinite(fs[i][1]))
                        snprintf(b[i], sizeof b[i], "%.5f +- %.5f", fs[i][0], fs[i][1]);
                    else
                        gw_cli_num(b[i], sizeof b[i], "%.5f", fs[i][0]);
                }
                const double *cs[4] = {f_tq, f_fr, f_gr, f_gf};
                for (int i = 0; i < 4; i++) {
                    all_val &= isfinite(cs[i][3]);
                    gw_cli_num(c[i], sizeof c[i], "%.4f", cs[i][3]);
                }
                printf("  beta: tq %s, front %s, group %s%s\n", b[0], b[1], b[2],
                       !all_val ? (wo.n_held > 0 ? " (n/a: the warning says why)" : " (n/a: not finite)")
                       : all_err ? "" : " (two speeds: each fit goes through both, no standard error)");
                printf("  C3: tq %s, front %s, group %s, group/sqrt(3/2) %s (F.27: 2)\n", c[0], c[1], c[2], c[3]);
            }
            /* the period null: why is the warning's, printed once (stderr,
             * and the JSON's warnings): the line said its own reason beside
             * it, "no column of 10 beads or more shows two maxima" for a
             * longest column of 9, "held by gravity" for a speed whose
             * columns were not held */
            if (!isfinite(c2))
                printf("  period: n/a (period, c2 and beta_period null: the warning says why); ");
            else if (wo.fitted && !isfinite(wo.beta_period))
                printf("  period: C2 %.4f, beta n/a (beta_period null: the warning says why); ", c2);
            else if (wo.fitted && isfinite(wo.beta_period_err)) /* its error as the JSON's: damping
                                                                  moved beta to -0.076 +- 0.043 */
                printf("  period: C2 %.4f, beta %.5f +- %.5f; ", c2, wo.beta_period, wo.beta_period_err);
            else if (wo.fitted)
                printf("  period: C2 %.4f, beta %.5f (no standard error); ", c2, wo.beta_period);
            else
                printf("  period: C2 %.4f, beta not fitted; ", c2);
            char dis[32]; /* n/a: no speed with all three decided */
            printf("front-speed estimators (tq, front, group/sqrt(3/2)) disagree by up to %s %%\n",
                   gw_cli_num(dis, sizeof dis, "%.1f", 100 * worst));
        }
        cJSON_Delete(o);
    }
    gw_chain_wavespeed_outcome_free(&wo);
    gw_chain_wavespeed_setup_clear(&ws);
    free(v);
    chain_cli_free(&c);
    return code;
}
