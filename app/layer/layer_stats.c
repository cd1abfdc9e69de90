/*
 * layer_stats.c: the command `granwave layer-stats RESULTS.csv`: flags, the
 * text summary and --json / --out around gw_stats_analyse (common/stats/,
 * the Bourrier analyses of a layer sweep table, docs/physics.md 2.3, 2.5).
 * It stays in layer/ because it gives the statistics the layer model's
 * defaults (R_b/R_m, incidence, V_i, density) for the parameters a table
 * leaves out; the statistics themselves include no model header.
 * Outputs: JSON on stdout (--json) or a text summary; with --out DIR the files
 * groups.csv, convergence.csv, binary.csv, walls.csv, diagram.csv and
 * boundary_fit.json, each written atomically and carrying the version and
 * input. Exit codes: 0 ok, 1 output failure, 2 bad input (one line naming the
 * file and line). Units: R_m for the diagram, degrees for angles.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "gw_cli.h"
#include "gw_locale.h"
#include "gw_layer.h"
#include "gw_layer_study.h"
#include "layer_commands.h"
#include "gw_stats.h"

static const char *summary =
    "Statistics of a layer sweep table (OUT/results.csv of `granwave sweep` with\n"
    "model = layer; Bourrier et al. 2008, docs/physics.md 2.3 and 2.5): per group of impact\n"
    "points, mean and standard deviation of e_n, e, alpha_r (bouncing points) and the\n"
    "penetration; bounce share and global verdict (share >= criterion); running means\n"
    "(Fig. 10); first-contact energy loss against the binary-impact formula (B.24-B.28);\n"
    "walls on/off; bouncing-occurrence diagram with its boundary H*(R_b/R_m), R_crit,\n"
    "(R_min, H_min) and a GSL least-squares fit of B.31 (free parameters: --fit).";

/* One line on stderr, exit status 2 (the option parser's messages already
 * name the command). */
static int fail(const char *msg)
{
    if (strncmp(msg, "layer-stats", 11) == 0 && (msg[11] == ' ' || msg[11] == ':'))
        fprintf(stderr, "granwave %s\n", msg);
    else
        fprintf(stderr, "granwave layer-stats: %s\n", msg);
    return 2;
}

/* The layer model's values of the parameters a table may leave out. */
static gw_stats_defaults layer_defaults(void)
{
    const gw_layer_impact_params ip = gw_layer_impact_params_default();
    return (gw_stats_defaults){.rb_rm = ip.rb_rm, .alpha = ip.alpha_deg, .vi = ip.vi,
                               .density = gw_layer_params_default().density};
}

/* ------------------------------------------------------------------ command --- */

/* "mean +- std" with n/a for what the JSON gives as null (no value, or the
 * spread of one), then "(k of N points)" when the mean rests on some but not
 * all of the group's N points (the JSON's n: an undecided point, or one that
 * did not bounce, has no e_n), so that "e_n 0.149 +- n/a" is not read as the
 * group's; points 0: no count (the binary lines give theirs) */
static const char *pm(char *b, size_t n, const char *fmt, gw_stats_moment m, const char *unit, int points)
{
    char a[32], c[32];
    gw_cli_num(a, sizeof a, fmt, m.mean);
    gw_cli_num(c, sizeof c, fmt, m.std);
    if (m.n > 0 && m.n < points)
        snprintf(b, n, "%s +- %s%s (%d of %d points)", a, c, unit, m.n, points);
    else
        snprintf(b, n, "%s +- %s%s", a, c, unit);
    return b;
}

/* The mean alone, counted as pm does. */
static const char *mean_of(char *b, size_t n, const char *fmt, gw_stats_moment m, const char *unit, int points)
{
    char a[32];
    gw_cli_num(a, sizeof a, fmt, m.mean);
    if (m.n > 0 && m.n < points)
        snprintf(b, n, "%s%s (%d of %d points)", a, unit, m.n, points);
    else
        snprintf(b, n, "%s%s", a, unit);
    return b;
}

static void print_text(const gw_stats_analysis *R)
{
    const gw_stats_table *t = &R->t;
    char q[GW_CLI_PATH_TEXT];
    printf("granwave %s layer-stats: %s: %ld rows, %d groups, criterion %.3g\n", gw_version(),
           gw_cli_path(q, sizeof q, R->input), t->nrows, R->gs.n, R->gs.criterion);
    for (int a = 0; a < R->gs.n; a++) {
        const gw_stats_group *g = &R->gs.g[a];
        printf("  ");
        for (int k = 0; k < R->gs.nkeys; k++)
            printf("%s=%s ", t->grid_name[R->gs.key[k]], t->grid_value[g->first * t->ngrid + R->gs.key[k]]);
        char b[4][128], pen[80];
        printf(": n %d, share %.3f (%s%s), e_n %s, e %s, alpha_r %s, "
               "e_n_first %s, penetration %s, points over %.3g R_m\n", g->n, g->share,
               g->bouncing ? "bounces" : "no bounce", g->verdict_certain ? "" : "; undecided points could change it",
               pm(b[0], sizeof b[0], "%.3f", g->e_n, "", g->n), pm(b[1], sizeof b[1], "%.3f", g->e, "", g->n),
               pm(b[2], sizeof b[2], "%.1f", g->alpha_r, " deg", g->n),
               pm(b[3], sizeof b[3], "%.3f", g->e_n_first, "", g->n),
               mean_of(pen, sizeof pen, "%.3g", g->penetration_rm, " R_m", g->n), g->x_span_rm);
    }
    for (int k = 0; k < R->nbin; k++) {
        char b[72];
        printf("  binary: R_b/R_m %g, alpha %g: block loss %s (n %d); disc %.3f, sphere %.3f\n",
               R->bin[k].rb_rm, R->bin[k].alpha, pm(b, sizeof b, "%.3f", R->bin[k].loss, "", 0), R->bin[k].loss.n,
               R->bin[k].disc, R->bin[k].sphere);
    }
    for (int q = 0; q < R->ndia; q++) {
        const gw_stats_panel *D = &R->dia[q];
        if (!D->ok) {
            printf("  diagram %d: %s\n", q, D->reason);
            continue;
        }
        char v[4][32];
        printf("  diagram %d: %d crossings, R_crit %s (next %s), R_min %s, H_min %s\n", q, D->d.ncross,
               gw_cli_num(v[0], sizeof v[0], "%g", D->d.r_crit), gw_cli_num(v[1], sizeof v[1], "%g", D->d.r_crit_upper),
               gw_cli_num(v[2], sizeof v[2], "%g", D->d.r_min), gw_cli_num(v[3], sizeof v[3], "%g", D->d.h_min));
        char edge[96] = "";
        if (D->fit_ok && D->fit.at_bound) /* the box stopped the search there: no free minimum */
            gw_snprintf(edge, sizeof edge, "; at the edge of the fit's box: %s%s%s%s",
                        D->fit.at_bound & GW_STATS_B31_OFFSET ? "offset " : "",
                        D->fit.at_bound & GW_STATS_B31_BETA ? "beta " : "",
                        D->fit.at_bound & GW_STATS_B31_AB ? "a/b " : "",
                        D->fit.at_bound & GW_STATS_B31_TANG ? "tan_gamma " : "");
        if (edge[0])
            edge[strlen(edge) - 1] = 0;
        if (D->fit_ok && D->fit.dof == 0)
            printf("    B.31 fit: beta %.4g, a/b %.4g (as many points as free parameters: %s, no errors), "
                   "tan gamma %.4g, offset %.4g%s\n", D->fit.p.beta, D->fit.p.a_over_b,
                   D->fit.at_bound ? "not exact" : "exact", D->fit.p.tan_gamma, D->fit.p.offset, edge);
        else if (D->fit_ok)
            printf("    B.31 fit: beta %.4g +- %.2g, a/b %.4g +- %.2g, tan gamma %.4g, offset %.4g, rms %.3g R_m "
                   "(%d dof)%s\n", D->fit.p.beta, D->fit.err.beta, D->fit.p.a_over_b, D->fit.err.a_over_b,
                   D->fit.p.tan_gamma, D->fit.p.offset, D->fit.rms, D->fit.dof, edge);
        else
            printf("    B.31 fit: not done: %s\n", D->fit_reason);
    }
}

int gw_cmd_layer_stats(int argc, char **argv)
{
    gw_stats_analysis R;
    memset(&R, 0, sizeof R);
    gw_stats_setup S;
    if (gw_stats_setup_init(&S) != GW_OK) {
        gw_stats_setup_clear(&S);
        return gw_cli_nomem("layer-stats");
    }
    S.defaults = layer_defaults();
    const char *out = NULL, *fit = NULL;
    int json = 0;
    /* criterion, fit, gamma-deg, delta-rm: the table's rows (range, default,
     * help, and "not given" for the optional fit and gamma-deg: a list given
     * at the default's text is told from none, as in Python and C) */
    const gw_param *tab = gw_stats_setup_params();
    gw_opt o[7];
    memset(o, 0, sizeof o);
    if (gw_cli_opt_param(gw_param_find(tab, "criterion"), &S.criterion, &o[0], NULL) != GW_OK ||
        gw_cli_opt_param(gw_param_find(tab, "fit"), &fit, &o[1], NULL) != GW_OK ||
        gw_cli_opt_param(gw_param_find(tab, "gamma-deg"), &S.gamma_deg, &o[2], NULL) != GW_OK ||
        gw_cli_opt_param(gw_param_find(tab, "delta-rm"), &S.delta_rm, &o[3], NULL) != GW_OK) {
        gw_stats_setup_clear(&S);
        return fail("the setup table lacks a row (a bug)");
    }
    gw_opt more[] = {
        {.name = "out", .kind = GW_OPT_STRING, .dest = &out, .metavar = "DIR",
         .help = "write groups.csv, convergence.csv, binary.csv, walls.csv, diagram.csv, boundary_fit.json"},
        {.name = "json", .kind = GW_OPT_FLAG, .dest = &json, .help = "print the results as JSON"}};
    memcpy(&o[4], more, sizeof more); /* o[6] stays the end */
    gw_err err = {{0}};
    int help = 0, npos = 0, mask = 0;
    const char *pos[1] = {NULL};
    /* (every return before the analysis frees what the setup's defaults own) */
    if (gw_cli_parse("layer-stats", o, argc, argv, &help, pos, 1, &npos, &err) != GW_OK)
        return gw_stats_setup_clear(&S), fail(err.msg);
    if (help) {
        const int code = gw_cli_help(stdout, "layer-stats", "granwave layer-stats RESULTS.csv [options]", summary, o,
                                     help);
        gw_stats_setup_clear(&S);
        return code;
    }
    if (npos != 1)
        return gw_stats_setup_clear(&S), fail("a results table is required: granwave layer-stats RESULTS.csv");
    if (fit && gw_stats_fit_parse(fit, &mask, &err) != GW_OK) {
        fprintf(stderr, "granwave layer-stats --%s\n", err.msg); /* "fit: ...": the flag's name */
        gw_stats_setup_clear(&S);
        return 2;
    }
    int orc = GW_OK;
    if (out && ((orc = gw_stats_out_check(out, "layer-stats --out", &err)) != GW_OK || /* before any work */
                (orc = gw_stats_out_check_input(out, pos[0], &err)) != GW_OK)) {
        gw_stats_setup_clear(&S);
        int code = fail(err.msg);
        return orc == GW_ENOMEM ? 1 : code; /* the check ran out of memory: not the directory's fault */
    }
    if (!*pos[0]) /* the table reader's message (the setup refuses an empty input as "input: ...") */
        return gw_stats_setup_clear(&S), fail("layer-stats RESULTS.csv: empty file name");
    int rc = gw_param_set(tab, &S, "input", pos[0], &err);
    if (rc == GW_OK && fit) /* given (at the default's text too); not given stays NULL */
        rc = gw_param_set(tab, &S, "fit", fit, &err);
    if (rc == GW_OK)
        rc = gw_stats_analyse(&S, &R, &err);
    gw_stats_setup_clear(&S);
    if (rc == GW_OK && !(R.cmdline = gw_cli_command_line("layer-stats", argc, argv)))
        rc = gw_err_set(&err, GW_ENOMEM, "%s: out of memory", R.input);
    if (rc == GW_EINVAL) /* a parameter named by the library ("delta-rm: ..."): as its flag */
        gw_cli_study_error(tab, "layer-stats", rc, &err);
    if (rc != GW_OK) {
        gw_stats_analysis_free(&R);
        if (rc == GW_EINVAL)
            return fail(err.msg);
        gw_cli_error("layer-stats", err.msg);
        return rc == GW_ENOMEM ? 1 : 2;
    }
    /* undecided points (n_points - n_valid in groups.csv and the JSON), bouncing
     * points without e (n_bounced - n_e): the library's texts */
    gw_cli_warnings("layer-stats", R.warnings);
    int status = 0;
    if (out && gw_stats_write_files(&R, out, &err) != GW_OK) {
        fprintf(stderr, "granwave layer-stats --out: %s\n", err.msg);
        status = 1;
    }
    if (status != 0) {
        /* as every other command: nothing on stdout when the files were not written */
    } else if (json) {
        cJSON *j = gw_stats_json(&R, 1);
        status = gw_cli_json_stdout("layer-stats", j); /* it ended 1 without a word */
        cJSON_Delete(j);
    } else {
        print_text(&R);
    }
    gw_stats_analysis_free(&R);
    return status;
}
