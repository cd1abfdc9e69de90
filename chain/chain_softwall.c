/*
 * chain_softwall.c: `granwave softwall`, columns on a soft wall (docs/physics.md 1.3).
 *
 *   K_c = (c_tau/4)^(5/2) (5k/4)                        (F.22): rigid if K > K_c
 *   N_d = first N from which F_max(N') stays within a tolerance (default 1 %) of
 *         the plateau F_max(n_max) for every N' >= N            (measured)
 *         A plateau needs SATURATION_RUN sizes within the tolerance: with fewer
 *         the force may still be rising and N_d is reported as not reached.
 *   N_d predicted = ceil(tau_max(N_d) / T_q)                      (F.8)
 *         evaluated at the measured N_d; also its self-consistent form, the
 *         smallest N with N >= ceil(tau_max(N)/T_q) (n_d_fixed_point).
 * T_q is measured on the same beads with the steel (rigid) wall: slope of tau_N
 * over N = 1..20 (F.4); tau_max comes from the soft-wall runs.
 * Sheet mode (--sheets): each sheet of the paper's Table 2 with its effective K
 * (gw_sheet_kwall, chain_material.c), then N_d of the model against the
 * measured N_d (h = 2.9 mm). With --sheet-law hertz|layer|material each sheet is
 * instead a wall law from its material constants and thickness alone
 * (chain_sheets.c); JSON "sheets" lists model against measured for every sheet
 * (N_d, tau_max(N = 1), tau_max(N_d)) in either mode.
 * Units: SI (tables print us).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_cli.h"
#include "chain_options.h"

#define SATURATION_RUN 6

typedef struct sw_result {
    int n_d;      /* -1: not saturated within the sizes run */
    int n_d_pred; /* (F.8) at the measured N_d, -1 without N_d */
    int n_d_fix;  /* smallest N >= ceil(tau_max(N)/T_q), -1 if none */
    double plateau;
} sw_result;

static sw_result analyse(const gw_chain_result *r, int n_lo, int n_hi, double tol, double t_q)
{
    sw_result s = {n_hi, -1, -1, r[n_hi - n_lo].f_max};
    for (int n = n_hi; n >= n_lo; n--) {
        if (fabs(r[n - n_lo].f_max - s.plateau) > tol * s.plateau)
            break;
        s.n_d = n;
    }
    if (n_hi - s.n_d + 1 < SATURATION_RUN && s.n_d > n_lo)
        s.n_d = -1;
    if (s.n_d > 0)
        s.n_d_pred = (int)ceil(r[s.n_d - n_lo].tau_max / t_q - 1e-9);
    for (int n = n_lo; n <= n_hi; n++)
        if (n >= (int)ceil(r[n - n_lo].tau_max / t_q - 1e-9)) {
            s.n_d_fix = n;
            break;
        }
    return s;
}

/* Rigid-wall T_q of the beads at v: slope of tau_N over N = 1..20. */
static int measure_tq(const chain_cli *c, double v, int jobs, double *t_q, gw_err *err)
{
    gw_chain_params p = c->params;
    const gw_material *steel = gw_material_find("steel");
    p.kwall = gw_hertz_coefficient(p.radius, steel, INFINITY, steel);
    memset(&p.wall, 0, sizeof p.wall); /* the bare sensor */
    gw_chain_result r[20];
    int rc = gw_chain_sweep_n(&p, &c->run, &v, 1, 1, 20, jobs, 0, r, err);
    double x[20], y[20];
    for (int i = 0; i < 20; i++) {
        x[i] = i;
        y[i] = r[i].tau_n;
        gw_chain_result_free(&r[i]);
    }
    gw_linfit lf;
    if (rc == GW_OK && gw_fit_linear(x, y, 20, &lf) == GW_OK)
        *t_q = lf.c1;
    return rc;
}

/* One sheet, model against measured (times in s). */
static cJSON *sheet_json(const gw_sheet *sh, const sw_result *sr, const gw_chain_result *r, int n_lo,
                         int n_hi, double t_q, double kwall, const gw_layer_law *layer)
{
    cJSON *e = cJSON_CreateObject();
    cJSON_AddStringToObject(e, "name", sh->name);
    cJSON_AddStringToObject(e, "material", sh->material);
    cJSON_AddNumberToObject(e, "thickness", sh->thickness > 0 ? sh->thickness : NAN);
    cJSON_AddNumberToObject(e, "n_d_model", sr->n_d > 0 ? sr->n_d : NAN);
    cJSON_AddNumberToObject(e, "n_d_measured", sh->n_d);
    cJSON_AddNumberToObject(e, "n_d_measured_err", sh->n_d_err);
    cJSON_AddNumberToObject(e, "n_d_predicted_f8", sr->n_d_pred > 0 ? sr->n_d_pred : NAN);
    cJSON_AddNumberToObject(e, "tau_max_1_model", n_lo == 1 ? r[0].tau_max : NAN);
    cJSON_AddNumberToObject(e, "tau_max_1_measured", sh->tau_max1_us * 1e-6);
    cJSON_AddNumberToObject(e, "tau_max_nd_model", sr->n_d > 0 ? r[sr->n_d - n_lo].tau_max : NAN);
    cJSON_AddNumberToObject(e, "tau_max_nd_measured", sh->tau_max_nd_us * 1e-6);
    cJSON_AddNumberToObject(e, "tau_max_nd_measured_err", sh->tau_max_nd_err_us * 1e-6);
    /* tolerance-free comparisons at the measured N_d: the model's tau_max there,
     * and how close its F_max is to the plateau (the band the experiment's N_d
     * corresponds to in the model) */
    int nm = (int)sh->n_d, in = nm >= n_lo && nm <= n_hi;
    cJSON_AddNumberToObject(e, "tau_max_at_measured_nd_model", in ? r[nm - n_lo].tau_max : NAN);
    cJSON_AddNumberToObject(e, "f_max_at_measured_nd_over_plateau", in ? r[nm - n_lo].f_max / sr->plateau : NAN);
    cJSON *bt = cJSON_AddArrayToObject(e, "n_d_model_by_tol");
    static const double tols[] = {0.01, 0.02, 0.05, 0.1};
    for (int i = 0; i < 4; i++) {
        sw_result x = analyse(r, n_lo, n_hi, tols[i], t_q);
        cJSON *b = cJSON_CreateObject();
        cJSON_AddNumberToObject(b, "tol", tols[i]);
        cJSON_AddNumberToObject(b, "n_d", x.n_d > 0 ? x.n_d : NAN);
        cJSON_AddNumberToObject(b, "tau_max_nd", x.n_d > 0 ? r[x.n_d - n_lo].tau_max : NAN);
        cJSON_AddItemToArray(bt, b);
    }
    cJSON_AddNumberToObject(e, "f_max_1_model", n_lo == 1 ? r[0].f_max : NAN);
    cJSON_AddNumberToObject(e, "f_plateau_model", sr->plateau);
    cJSON_AddNumberToObject(e, "eps_eff_1_model", n_lo == 1 ? r[0].eps_eff : NAN);
    cJSON_AddNumberToObject(e, "kwall", kwall);
    if (layer && n_lo == 1) /* contact radius over thickness at the single bead's peak force */
        cJSON_AddNumberToObject(e, "a_over_h_1", gw_layer_law_contact_radius(layer, gw_layer_law_overlap(layer, r[0].f_max)) /
                                                     gw_layer_law_thickness(layer));
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

int gw_cmd_softwall(int argc, char **argv)
{
    chain_cli c;
    gw_opt opts[CHAIN_CLI_NOPTS + 7];
    chain_cli_options(&c, opts);
    const char *nrange = "1:30";
    double vimp = sqrt(2 * 9.81 * 2.9e-3), tol = 0.01;
    long jobs = 0;
    int quiet = 0, use_sheets = 0, k = CHAIN_CLI_NOPTS;
    opts[k++] = (gw_opt){.name = "n", .kind = GW_OPT_STRING, .dest = &nrange, .metavar = "A:B", .help = "column sizes [1:30]"};
    opts[k++] = (gw_opt){.name = "vimp", .kind = GW_OPT_DOUBLE, .dest = &vimp, .metavar = "V",
                         .help = "impact velocity, m/s [0.2385 = h 2.9 mm]", .lo = 0, .hi = GW_CHAIN_VIMP_MAX, .open_lo = 1};
    opts[k++] = (gw_opt){.name = "tol", .kind = GW_OPT_DOUBLE, .dest = &tol, .metavar = "F",
                         .help = "plateau tolerance for N_d (fraction) [0.01]", .lo = 0, .hi = 0.5, .open_lo = 1};
    opts[k++] = (gw_opt){.name = "sheets", .kind = GW_OPT_FLAG, .dest = &use_sheets, .help = "the paper's sheets (Table 2) with fitted K_eff"};
    chain_cli_sweep_opts(opts, &k, &jobs, &quiet);
    opts[k] = (gw_opt){0};
    int done = chain_cli_parse("softwall", "granwave softwall [--kwall K | --sheets] [options]", sw_summary, opts, argc, argv);
    if (done >= 0)
        return done;
    if (c.radii)
        return chain_cli_fail("softwall --radii: per-bead radii need a fixed N (use granwave chain)");
    gw_err err = {{0}};
    c.sheets_mode = use_sheets;
    /* every wall option is ignored with --sheets (each sheet has its fitted K_eff),
     * and the wall material is ignored when the wall is a stiffness */
    static const char *const wall_opts[] = {"kwall", "sheet", "wall-material"};
    for (int i = 0; i < 3; i++)
        if (gw_cli_find(opts, wall_opts[i])->seen && (use_sheets || i == 2)) {
            char msg[160];
            snprintf(msg, sizeof msg, "softwall --%s: has no effect %s", wall_opts[i],
                     use_sheets ? "with --sheets (each sheet of Table 2 is its own wall)"
                                : "(the wall is --kwall, default 1e9 N/m^1.5, or --sheets)");
            return chain_cli_fail(msg);
        }
    if (!gw_cli_find(opts, "kwall")->seen && !use_sheets && !c.sheet) /* (--sheet: its own wall) */
        c.kwall = 1e9, ((gw_opt *)gw_cli_find(opts, "kwall"))->seen = 1;
    long a, b;
    if (gw_parse_int_range(nrange, "softwall --n", 1, 100000, &a, &b, &err) != GW_OK)
        return chain_cli_fail(err.msg);
    if (b - a < 2)
        return chain_cli_fail("softwall --n: need at least 3 column sizes");
    c.params.n = (int)a;
    c.params.v_imp = vimp;
    if (chain_cli_resolve(&c, opts, "softwall", &err) != GW_OK || (c.out && gw_mkdir_p(c.out, &err) != GW_OK)) {
        chain_cli_free(&c);
        return chain_cli_fail(err.msg);
    }
    const gw_chain_params *p = &c.params;
    double kc = gw_chain_kc(p->k), t_q = NAN, t0 = gw_clock_ms();
    int nw = use_sheets ? gw_sheet_count() : 1, per = (int)(b - a + 1);
    gw_chain_result *res = calloc((size_t)(nw * per), sizeof *res);
    double *kw = calloc((size_t)nw, sizeof *kw);
    sw_result *sr = calloc((size_t)nw, sizeof *sr);
    gw_layer_law **lay = calloc((size_t)nw, sizeof *lay);
    int rc = res && kw && sr && lay ? measure_tq(&c, vimp, (int)jobs, &t_q, &err) : GW_ENOMEM;
    for (int w = 0; rc == GW_OK && w < nw; w++) {
        gw_chain_params q = *p;
        if (use_sheets && (rc = chain_cli_sheet(&c, gw_sheet_get(w), &q, &lay[w], &err)) != GW_OK)
            break;
        kw[w] = q.kwall;
        if (!quiet)
            fprintf(stderr, "softwall: K = %.4g N/m^1.5%s%s (%d/%d)\n", q.kwall, use_sheets ? ", sheet " : "",
                    use_sheets ? gw_sheet_get(w)->name : "", w + 1, nw);
        rc = gw_chain_sweep_n(&q, &c.run, &vimp, 1, (int)a, (int)b, (int)jobs, 0, res + w * per, &err);
        if (rc == GW_OK)
            sr[w] = analyse(res + w * per, (int)a, (int)b, tol, t_q);
    }
    double wall_s = (gw_clock_ms() - t0) / 1e3;
    int code = 0;
    if (rc != GW_OK) {
        fprintf(stderr, "granwave softwall: %s\n", err.msg);
        code = rc == GW_EINVAL ? 2 : 1;
    } else {
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "version", gw_version());
        cJSON_AddNumberToObject(o, "v_imp", vimp);
        cJSON_AddNumberToObject(o, "k_c", kc);
        cJSON_AddNumberToObject(o, "t_q_rigid", t_q);
        cJSON_AddNumberToObject(o, "tol", tol);
        int ns = per;
        int *nn = malloc((size_t)ns * sizeof *nn);
        double *fm = malloc(2 * (size_t)ns * sizeof *fm);
        for (int i = 0; nn && i < ns; i++)
            nn[i] = (int)a + i;
        cJSON_AddItemToObject(o, "n", gw_json_ints(nn, ns));
        cJSON *walls = cJSON_AddArrayToObject(o, "walls");
        for (int w = 0; fm && w < nw; w++) {
            cJSON *e = use_sheets ? cJSON_CreateObject() : o;
            for (int i = 0; i < ns; i++) {
                fm[i] = res[w * per + i].f_max;
                fm[ns + i] = res[w * per + i].tau_max;
            }
            if (use_sheets) {
                cJSON_AddStringToObject(e, "sheet", gw_sheet_get(w)->name);
                cJSON_AddNumberToObject(e, "tau_max_n1_measured", gw_sheet_get(w)->tau_max1_us * 1e-6);
                cJSON_AddNumberToObject(e, "n_d_measured", gw_sheet_get(w)->n_d);
                cJSON_AddNumberToObject(e, "n_d_measured_err", gw_sheet_get(w)->n_d_err);
                cJSON_AddItemToArray(walls, e);
            }
            cJSON_AddNumberToObject(e, "kwall", kw[w]);
            cJSON_AddStringToObject(e, "wall", kw[w] > kc ? "rigid" : "soft");
            cJSON_AddItemToObject(e, "f_max", gw_json_doubles(fm, ns));
            cJSON_AddItemToObject(e, "tau_max", gw_json_doubles(fm + ns, ns));
            /* null when F_max has not saturated (or F.8 is not met) within n_max */
            cJSON_AddNumberToObject(e, "n_d", sr[w].n_d > 0 ? sr[w].n_d : NAN);
            cJSON_AddNumberToObject(e, "n_d_predicted", sr[w].n_d_pred > 0 ? sr[w].n_d_pred : NAN);
            cJSON_AddNumberToObject(e, "n_d_fixed_point", sr[w].n_d_fix > 0 ? sr[w].n_d_fix : NAN);
            cJSON_AddNumberToObject(e, "f_plateau", sr[w].plateau);
            cJSON_AddNumberToObject(e, "tau_max_at_n_d", sr[w].n_d > 0 ? res[w * per + sr[w].n_d - a].tau_max : NAN);
            cJSON_AddBoolToObject(e, "saturated", sr[w].n_d > 0);
        }
        if (use_sheets || c.sheet) { /* --sheets, or one --sheet: model against measured */
            cJSON_AddStringToObject(o, "sheet_law", gw_sheet_law_name(c.law));
            cJSON *sl = cJSON_AddArrayToObject(o, "sheets");
            for (int w = 0; w < nw; w++)
                cJSON_AddItemToArray(sl, sheet_json(use_sheets ? gw_sheet_get(w) : gw_sheet_find(c.sheet), &sr[w],
                                                    res + w * per, (int)a, (int)b, t_q, kw[w],
                                                    use_sheets ? lay[w] : c.layer));
        }
        cJSON_AddNumberToObject(o, "wall_time_s", wall_s);
        cJSON_AddItemToObject(o, "settings", chain_cli_settings_json(&c));
        char path[4096];
        if (c.out && (gw_path_join(path, sizeof path, c.out, "softwall.json") != GW_OK ||
                      gw_json_write(path, o, &err) != GW_OK)) {
            fprintf(stderr, "granwave softwall --out: %s\n", err.msg);
            code = 1;
        }
        if (code == 0 && c.json) {
            gw_json_print(o, stdout);
        } else if (code == 0) {
            printf("granwave %s softwall: v_imp %.4g m/s, K_c %.4g N/m^1.5, rigid-wall T_q %.3f us (%.1f s)\n",
                   gw_version(), vimp, kc, t_q * 1e6, wall_s);
            printf("  %-14s %11s %6s %9s %8s %11s %14s%s\n", "wall", "K", "kind", "N_d", "F.8", "F_plateau",
                   use_sheets ? "N_d measured" : "",
                   use_sheets ? "  tau_max(1) model/meas  tau_max(N_d) model/meas (us)" : "");
            for (int w = 0; w < nw; w++) {
                char meas[32] = "";
                if (use_sheets)
                    snprintf(meas, sizeof meas, "%g +- %g", gw_sheet_get(w)->n_d, gw_sheet_get(w)->n_d_err);
                char nd[32], np[32];
                if (sr[w].n_d > 0)
                    snprintf(nd, sizeof nd, "%d", sr[w].n_d);
                else
                    snprintf(nd, sizeof nd, "not in %ld", b);
                if (sr[w].n_d_pred > 0)
                    snprintf(np, sizeof np, "%d", sr[w].n_d_pred);
                else
                    snprintf(np, sizeof np, "-");
                char taus[96] = "";
                if (use_sheets) {
                    const gw_sheet *sh = gw_sheet_get(w);
                    snprintf(taus, sizeof taus, "  %8.1f / %-8.1f     %8.1f / %.0f", res[w * per].tau_max * 1e6,
                             sh->tau_max1_us, sr[w].n_d > 0 ? res[w * per + sr[w].n_d - a].tau_max * 1e6 : NAN,
                             sh->tau_max_nd_us);
                }
                printf("  %-14s %11.4g %6s %9s %8s %9.2f N %14s%s\n", use_sheets ? gw_sheet_get(w)->name : c.sheet ? c.sheet : "--kwall",
                       kw[w], kw[w] > kc ? "rigid" : "soft", nd, np, sr[w].plateau, meas, taus);
            }
        }
        free(nn);
        free(fm);
        cJSON_Delete(o);
    }
    for (int i = 0; res && i < nw * per; i++)
        gw_chain_result_free(&res[i]);
    free(res);
    free(kw);
    free(sr);
    for (int w = 0; lay && w < nw; w++)
        gw_layer_law_free(lay[w]);
    free(lay);
    chain_cli_free(&c);
    return code;
}
