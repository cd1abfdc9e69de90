/*
 * chain_softwall.c: `granwave softwall`, columns on a soft wall (docs/physics.md
 * 1.3): K_c (F.22), the saturation number N_d against ceil(tau_max(N_d)/T_q)
 * (F.8), and with --sheets each sheet of the paper's Table 2, model against
 * measured. The study is gw_chain_softwall_run (chain_softwall_study.c, with its
 * equations); here only the command line: options, JSON and the table.
 * Units: SI (tables print us).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_cli.h"
#include "chain_options.h"

/* One compared sheet's JSON object from row w of the outcome's sheet table. */
static cJSON *sheet_json(const gw_chain_softwall_outcome *so, int w, const gw_sheet *sh)
{
    const double *row = so->sheet_table + (size_t)w * GW_SOFTWALL_NSHEET_COLS;
    static const char *const keys[] = {"thickness", "n_d_model", "n_d_measured", "n_d_measured_err",
                                       "n_d_predicted_f8", "tau_max_1_model", "tau_max_1_measured",
                                       "tau_max_nd_model", "tau_max_nd_measured", "tau_max_nd_measured_err",
                                       "tau_max_at_measured_nd_model", "f_max_at_measured_nd_over_plateau"};
    cJSON *e = cJSON_CreateObject();
    cJSON_AddStringToObject(e, "name", sh->name);
    char label[GW_SOFTWALL_LABEL_MAX]; /* the library's: sheet none may name the sensor's material */
    cJSON_AddStringToObject(e, "material",
                            gw_chain_softwall_sheet_material(so, w, label, sizeof label) == GW_OK ? label : sh->material);
    int k = 0;
    for (; k < 12; k++)
        cJSON_AddNumberToObject(e, keys[k], row[k]);
    cJSON *bt = cJSON_AddArrayToObject(e, "n_d_model_by_tol");
    static const double tols[] = {0.01, 0.02, 0.05, 0.1};
    for (int i = 0; i < 4; i++, k += 2) {
        cJSON *b = cJSON_CreateObject();
        cJSON_AddNumberToObject(b, "tol", tols[i]);
        cJSON_AddNumberToObject(b, "n_d", row[k]);
        cJSON_AddNumberToObject(b, "tau_max_nd", row[k + 1]);
        cJSON_AddItemToArray(bt, b);
    }
    cJSON_AddNumberToObject(e, "f_max_1_model", row[k++]);
    cJSON_AddNumberToObject(e, "f_plateau_model", row[k++]);
    cJSON_AddNumberToObject(e, "eps_eff_1_model", row[k++]);
    cJSON_AddNumberToObject(e, "kwall", row[k++]);
    if (!isnan(row[k])) /* a layer law */
        cJSON_AddNumberToObject(e, "a_over_h_1", row[k]);
    return e;
}

static const char *sw_summary =
    "Columns on a soft wall: F_max(N) and tau_max(N) for a wall coefficient K, the\n"
    "saturation number N_d (F_max within --tol of its plateau from N_d on) against\n"
    "the prediction N_d = ceil(tau_max(N_d)/T_q) (F.8), K_c (F.22) and the rigid/soft\n"
    "verdict. --sheets fits K_eff for each sheet of the paper's Table 2 from its\n"
    "measured tau_max(N=1) and compares the model's N_d with the measured one;\n"
    "--sheets --sheet-law material predicts every sheet from its material constants\n"
    "and thickness (bonded layer, plastic or viscoelastic; docs/sheets.md).";

/* the file of --out DIR */
static const char *const sw_files[] = {"softwall.json", NULL};

int gw_cmd_softwall(int argc, char **argv)
{
    chain_cli c;
    gw_opt opts[CHAIN_CLI_NOPTS + 7];
    chain_cli_options(&c, opts);
    c.out_names = sw_files;
    chain_cli_out_help(opts, "write softwall.json into DIR");
    const char *nrange = "1:30";
    double vimp = sqrt(2 * GW_CHAIN_G_EARTH * 2.9e-3), tol = 0.01;
    long jobs = 0;
    int quiet = 0, use_sheets = 0, k = CHAIN_CLI_NOPTS;
    opts[k++] = (gw_opt){.name = "n", .kind = GW_OPT_STRING, .dest = &nrange, .metavar = "A:B", .help = "column sizes [1:30]"};
    opts[k++] = (gw_opt){.name = "vimp", .kind = GW_OPT_DOUBLE, .dest = &vimp, .metavar = "V",
                         .help = "impact velocity, m/s [0.2385 = h 2.9 mm]", .lo = GW_CHAIN_VIMP_MIN, .hi = GW_CHAIN_VIMP_MAX};
    opts[k++] = (gw_opt){.name = "tol", .kind = GW_OPT_DOUBLE, .dest = &tol, .metavar = "F",
                         .help = "plateau tolerance for N_d (fraction) [0.01]", .lo = 0, .hi = 0.5, .open_lo = 1};
    opts[k++] = (gw_opt){.name = "sheets", .kind = GW_OPT_FLAG, .dest = &use_sheets, .help = "the paper's sheets (Table 2) with fitted K_eff"};
    chain_cli_sweep_opts(opts, &k, &jobs, &quiet);
    opts[k] = (gw_opt){0};
    /* with --sheets there are nine walls and one constant: the library
     * calibrates it on the bare sensor (the Hertz wall of --wall-material),
     * as for a sheet under sheet-law hertz; kk then gives each sheet its own
     * rebound (0.48 on sheet none's fitted wall to 0.94 for E = 0.5), which
     * "rebounds with E on the wall" did not say */
    chain_cli_opt_help(opts, "restitution", "calibrate gamma/alpha so one bead on the wall rebounds with E (with --sheets, "
                                            "or a sheet under sheet-law hertz: on the bare sensor, the Hertz wall of "
                                            "wall-material, one constant for every sheet; hc then rebounds at E on each "
                                            "sheet, kk not), in (0, 1)");
    int done = chain_cli_parse("softwall", "granwave softwall [--kwall K | --sheets] [options]", sw_summary, opts, argc, argv);
    if (done >= 0)
        return done;
    if (c.radii)
        return chain_cli_study_radii("softwall");
    gw_err err = {{0}};
    c.sheets_mode = use_sheets;
    /* every wall option is ignored with --sheets (each sheet has its fitted
     * K_eff); the wall material where the wall is a stiffness is the library's
     * rule (gw_chain_softwall_run), as Python meets it */
    static const char *const wall_opts[] = {"kwall", "sheet"};
    for (int i = 0; i < 2; i++)
        if (gw_cli_find(opts, wall_opts[i])->seen && use_sheets) {
            char msg[160];
            snprintf(msg, sizeof msg, "softwall --%s: has no effect with --sheets (each sheet of Table 2 is its own wall)",
                     wall_opts[i]);
            return chain_cli_fail(msg);
        }
    /* (--sheet: its own wall; --wall-material there: the library refuses it,
     * naming the default wall, not a kwall the user did not give) */
    if (!gw_cli_find(opts, "kwall")->seen && !use_sheets && !c.sheet && !gw_cli_find(opts, "wall-material")->seen)
        c.kwall = 1e9, ((gw_opt *)gw_cli_find(opts, "kwall"))->seen = 1;
    long a, b;
    if (gw_parse_int_range(nrange, "softwall --n", 1, 100000, &a, &b, &err) != GW_OK)
        return chain_cli_fail(err.msg);
    if (b - a < 2)
        return chain_cli_fail("softwall --n: need at least 3 column sizes");
    int src = gw_chain_study_work_check(a, b, use_sheets ? gw_sheet_count() : 1, &err);
    if (src != GW_OK)
        return chain_cli_study_fail("softwall", src, err.msg);
    c.params.n = (int)a;
    c.params.v_imp = vimp;
    /* --out checked here, before the work, and made only to write (as chain's):
     * a run that fails or is interrupted leaves no directory it made */
    int rrc = chain_cli_resolve(&c, opts, "softwall", &err);
    if (rrc != GW_OK) {
        chain_cli_free(&c);
        return chain_cli_fail_rc(rrc, err.msg);
    }
    gw_chain_softwall_setup ss;
    if (gw_chain_softwall_setup_init(&ss) != GW_OK) {
        gw_chain_softwall_setup_clear(&ss);
        return gw_cli_nomem("softwall");
    }
    gw_chain_softwall_outcome so;
    memset(&so, 0, sizeof so);
    int rc = gw_cli_study_setup(gw_chain_softwall_setup_params(), &ss, opts, argc, argv, "softwall", &err);
    /* progress within the collisions, as falcon's: a header line once, then
     * whole lines on stderr, the first at 2 s, the last at the end (--quiet:
     * none); the collisions are the rigid wall's 20 (T_q) and every wall's */
    gw_cli_progress prog;
    gw_cli_progress_init(&prog, "  ", "collisions", GW_CLI_STUDY_PROGRESS_MS);
    prog.quiet = quiet;
    char header[160];
    snprintf(header, sizeof header, "granwave softwall: N = %ld..%ld on %s (and N = 1..20 on the rigid wall for T_q)",
             a, b, use_sheets ? "every sheet of Table 2 and the rigid wall" : "one wall");
    prog.header = header;
    gw_chain_watch_fn watch = quiet ? NULL : gw_cli_progress_watch; /* none: no lock at every sample */
    if (rc == GW_OK && (rc = gw_chain_softwall_run_watch(&ss, NULL, NULL, watch, &prog, &so, &err)) == GW_OK)
        gw_cli_progress_part(&prog, 20 + (long)so.nw * so.nn, 20 + (long)so.nw * so.nn, 1.0, 1);
    int nw = so.nw, ns = so.nn, per = so.nn, code = 0;
    double kc = so.k_c, t_q = so.t_q_rigid, wall_s = so.wall_time_s;
    const double *kw = so.kwall;
    if (rc != GW_OK) {
        gw_cli_study_error(gw_chain_softwall_setup_params(), "softwall", rc, &err);
        fprintf(stderr, "granwave %s\n", err.msg);
        code = rc == GW_EINVAL ? 2 : 1;
    } else {
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "version", gw_version());
        cJSON_AddNumberToObject(o, "v_imp", vimp);
        cJSON_AddNumberToObject(o, "k_c", kc);
        cJSON_AddNumberToObject(o, "t_q_rigid", t_q);
        cJSON_AddNumberToObject(o, "tol", tol);
        int *nn = malloc((size_t)ns * sizeof *nn);
        for (int i = 0; nn && i < ns; i++)
            nn[i] = (int)a + i;
        cJSON_AddItemToObject(o, "n", gw_json_ints(nn, ns));
        cJSON *walls = cJSON_AddArrayToObject(o, "walls");
        for (int w = 0; w < nw; w++) {
            cJSON *e = use_sheets ? cJSON_CreateObject() : o;
            if (use_sheets) {
                cJSON_AddStringToObject(e, "sheet", gw_sheet_get(w)->name);
                cJSON_AddNumberToObject(e, "tau_max_n1_measured", gw_sheet_get(w)->tau_max1_us * 1e-6);
                cJSON_AddNumberToObject(e, "n_d_measured", gw_sheet_get(w)->n_d);
                cJSON_AddNumberToObject(e, "n_d_measured_err", gw_sheet_get(w)->n_d_err);
                cJSON_AddItemToArray(walls, e);
            }
            cJSON_AddNumberToObject(e, "kwall", kw[w]);
            cJSON_AddStringToObject(e, "wall", so.rigid[w] ? "rigid" : "soft");
            cJSON_AddItemToObject(e, "f_max", gw_json_doubles(so.f_max + (size_t)w * per, ns));
            cJSON_AddItemToObject(e, "tau_max", gw_json_doubles(so.tau_max + (size_t)w * per, ns));
            /* per N: held by gravity, F_max and tau_max undecided (those of the stop), left out of N_d */
            cJSON_AddItemToObject(e, "held", gw_json_bools(so.held + (size_t)w * per, ns));
            /* null when F_max has not saturated (or F.8 is not met) within n_max */
            cJSON_AddNumberToObject(e, "n_d", so.n_d[w]);
            cJSON_AddNumberToObject(e, "n_d_predicted", so.n_d_predicted[w]);
            cJSON_AddNumberToObject(e, "n_d_fixed_point", so.n_d_fixed_point[w]);
            cJSON_AddNumberToObject(e, "f_plateau", so.f_plateau[w]);
            cJSON_AddNumberToObject(e, "tau_max_at_n_d", so.tau_max_at_n_d[w]);
            /* the first size, when the plateau reaches back to it (N_d <= it; n_d null) */
            cJSON_AddNumberToObject(e, "n_d_at_most", so.n_d_at_most[w]);
            if (so.saturated[w] < 0) /* undecided: held columns (the warning says), never false */
                cJSON_AddNullToObject(e, "saturated");
            else
                cJSON_AddBoolToObject(e, "saturated", so.saturated[w]);
        }
        if (use_sheets || c.sheet) { /* --sheets, or one --sheet: model against measured */
            cJSON_AddStringToObject(o, "sheet_law", gw_sheet_law_name(c.law));
            cJSON *sl = cJSON_AddArrayToObject(o, "sheets");
            for (int w = 0; w < so.nsheet; w++)
                cJSON_AddItemToArray(sl, sheet_json(&so, w, use_sheets ? gw_sheet_get(w) : gw_sheet_find(c.sheet)));
        }
        cJSON_AddNumberToObject(o, "wall_time_s", wall_s);
        cJSON_AddNumberToObject(o, "unfinished", so.unfinished);
        cJSON_AddNumberToObject(o, "n_held", so.n_held);             /* of them, held by gravity */
        cJSON_AddNumberToObject(o, "n_held_rigid", so.n_held_rigid); /* of t_q_rigid's 20 columns */
        gw_cli_warnings("softwall", so.warnings); /* unfinished: F_max, tau_max may not be final */
        gw_cli_json_warnings(o, so.warnings);     /* and in softwall.json and --json */
        cJSON *set = chain_cli_settings_json(&c);
        chain_cli_settings_runs(set, so.ncase, so.t_max, so.dt_out, so.dt, so.dt_max);
        cJSON_AddItemToObject(o, "settings", set);
        char path[4096];
        char made[4096] = ""; /* the first directory of --out this run creates, taken back on a failure */
        if (c.out && (gw_cli_mkdir_out(c.out, made, sizeof made, &err) != GW_OK ||
                      gw_path_join(path, sizeof path, c.out, sw_files[0]) != GW_OK ||
                      gw_json_write(path, o, &err) != GW_OK)) {
            if (made[0])
                gw_cli_unmake(c.out, made);
            fprintf(stderr, "granwave softwall --out: %s\n", err.msg);
            code = 1;
        } else if (c.out && made[0])
            gw_cli_outset_end(NULL, c.out, made, 1);
        if (code == 0 && c.json) {
            code = gw_cli_json_stdout("softwall", o);
        } else if (code == 0) {
            char tq[32]; /* n/a: the rigid wall's columns held by gravity (the warning says) */
            printf("granwave %s softwall: v_imp %.4g m/s, K_c %.4g N/m^1.5, rigid-wall T_q %s us (%.1f s)\n",
                   gw_version(), vimp, kc, gw_cli_num(tq, sizeof tq, "%.3f", t_q * 1e6), wall_s);
            printf("  %-14s %11s %6s %9s %8s %11s %14s%s\n", "wall", "K", "kind", "N_d", "F.8", "F_plateau",
                   use_sheets ? "N_d measured" : "",
                   use_sheets ? "  tau_max(1) model/meas  tau_max(N_d) model/meas (us)" : "");
            for (int w = 0; w < nw; w++) {
                char meas[32] = "";
                if (use_sheets)
                    snprintf(meas, sizeof meas, "%g +- %g", gw_sheet_get(w)->n_d, gw_sheet_get(w)->n_d_err);
                char nd[32], np[32];
                if (so.saturated[w] > 0 && isnan(so.n_d[w]))
                    snprintf(nd, sizeof nd, "<= %d", (int)so.n_d_at_most[w]);
                else if (so.saturated[w] > 0)
                    snprintf(nd, sizeof nd, "%d", (int)so.n_d[w]);
                else if (so.saturated[w] < 0) /* held columns keep the decided ones from locating it (the warning says) */
                    snprintf(nd, sizeof nd, "undecided");
                else
                    snprintf(nd, sizeof nd, "not in %ld", b);
                if (!isnan(so.n_d_predicted[w]))
                    snprintf(np, sizeof np, "%d", (int)so.n_d_predicted[w]);
                else
                    snprintf(np, sizeof np, GW_CLI_NA);
                char taus[96] = "";
                if (use_sheets) {
                    const gw_sheet *sh = gw_sheet_get(w);
                    /* tau_max(1) only when N = 1 was run (the JSON's tau_max_1_model): the first
                     * size's was printed under that name (--n 3:12: 17.6 us for none, tau_max(3));
                     * n/a where the model gives none (the JSON's null), not "nan" */
                    char t1[16] = GW_CLI_NA, tn[16] = GW_CLI_NA;
                    if (so.n[0] == 1 && !so.held[(size_t)w * per]) /* held: undecided */
                        snprintf(t1, sizeof t1, "%.1f", so.tau_max[(size_t)w * per] * 1e6);
                    if (!isnan(so.tau_max_at_n_d[w]))
                        snprintf(tn, sizeof tn, "%.1f", so.tau_max_at_n_d[w] * 1e6);
                    snprintf(taus, sizeof taus, "  %8s / %-8.1f     %8s / %.0f", t1, sh->tau_max1_us, tn,
                             sh->tau_max_nd_us);
                }
                char fp[32]; /* n/a: every column held */
                printf("  %-14s %11.4g %6s %9s %8s %9s N %14s%s\n", use_sheets ? gw_sheet_get(w)->name : c.sheet ? c.sheet : "--kwall",
                       kw[w], so.rigid[w] ? "rigid" : "soft", nd, np, gw_cli_num(fp, sizeof fp, "%.4g", so.f_plateau[w]),
                       meas, taus);
            }
        }
        free(nn);
        cJSON_Delete(o);
    }
    gw_chain_softwall_outcome_free(&so);
    gw_chain_softwall_setup_clear(&ss);
    chain_cli_free(&c);
    return code;
}
