/*
 * layer_stats.c: `granwave layer-stats RESULTS.csv`, the Bourrier analyses of a
 * layer sweep table (docs/physics.md 2.3, 2.5):
 *  - per group (every grid key but `point`): mean and sample standard deviation
 *    of e_n, e, alpha_r (B.16-B.18, bouncing points only) and the penetration,
 *    bounce share and global verdict share >= S (S = 75 % in the paper), the
 *    running means over the first k points (Fig. 10);
 *  - binary-impact check: per R_b/R_m (and incidence) the block's energy loss
 *    in its first contact beside 4 m/(1 + m)^2, m = r^2 (discs) or r^3
 *    (spheres) (B.24-B.28);
 *  - walls: with and without the walls side by side (grid key remove-walls);
 *  - bouncing-occurrence diagram (grid keys rb-rm and height-rm; one diagram
 *    per combination of the other keys): boundary H*(R_b/R_m), R_crit,
 *    (R_min, H_min) and a fit of B.31 (layer_stats_diagram.c).
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
#include "gw_layer.h"
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

static int fail(const char *msg)
{
    fprintf(stderr, "granwave layer-stats: %s\n", msg);
    return 2;
}

/* Parse --fit: names among offset, beta, a_over_b, tan_gamma. */
static int parse_fit_mask(const char *s, int *mask, gw_err *err)
{
    static const struct {
        const char *name;
        int bit;
    } names[] = {{"offset", GW_LAYER_B31_OFFSET}, {"beta", GW_LAYER_B31_BETA},
                 {"a_over_b", GW_LAYER_B31_AB}, {"tan_gamma", GW_LAYER_B31_TANG}};
    *mask = 0;
    const char *p = s;
    while (*p) {
        size_t len = strcspn(p, ",");
        int found = 0;
        for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
            if (strlen(names[i].name) == len && strncmp(p, names[i].name, len) == 0) {
                *mask |= names[i].bit;
                found = 1;
            }
        if (!found)
            return gw_err_set(err, GW_EINVAL, "--fit: unknown parameter '%.*s' (offset, beta, a_over_b, tan_gamma)",
                              (int)len, p);
        p += len + (p[len] == ',');
    }
    if (!*mask)
        return gw_err_set(err, GW_EINVAL, "--fit: no parameter given");
    return GW_OK;
}

static char *command_line(int argc, char **argv)
{
    size_t len = 64;
    for (int i = 0; i < argc; i++)
        len += strlen(argv[i]) + 1;
    char *h = malloc(len);
    if (!h)
        return NULL;
    size_t w = (size_t)snprintf(h, len, "granwave layer-stats");
    for (int i = 0; i < argc && w < len; i++)
        w += (size_t)snprintf(h + w, len - w, " %s", argv[i]);
    return h;
}

/* ------------------------------------------------------------ binary table --- */

static int binary_make(layer_stats_run *R)
{
    const gw_layer_results *t = &R->t;
    const gw_layer_impact_params ip = gw_layer_impact_params_default();
    int cl = gw_layer_results_col(t, "block_loss_first_contact");
    R->bin = calloc((size_t)t->nrows, sizeof *R->bin);
    double *v = malloc((size_t)t->nrows * sizeof *v);
    if (!R->bin || !v) {
        free(v);
        return GW_ENOMEM;
    }
    for (long i = 0; i < t->nrows; i++) {
        double rb = gw_layer_results_value(t, i, "rb-rm", ip.rb_rm);
        double al = gw_layer_results_value(t, i, "alpha", ip.alpha_deg);
        int k = 0;
        while (k < R->nbin && !(R->bin[k].rb_rm == rb && R->bin[k].alpha == al))
            k++;
        if (k == R->nbin)
            R->bin[R->nbin++] = (layer_stats_binary){.rb_rm = rb, .alpha = al};
    }
    for (int k = 0; k < R->nbin; k++) {
        int n = 0;
        for (long i = 0; i < t->nrows; i++)
            if (gw_layer_results_value(t, i, "rb-rm", ip.rb_rm) == R->bin[k].rb_rm &&
                gw_layer_results_value(t, i, "alpha", ip.alpha_deg) == R->bin[k].alpha)
                v[n++] = t->val[i * t->ncols + cl];
        gw_layer_moment_of(v, n, &R->bin[k].loss);
        R->bin[k].disc = gw_layer_binary_loss(R->bin[k].rb_rm, 0);
        R->bin[k].sphere = gw_layer_binary_loss(R->bin[k].rb_rm, 1);
    }
    free(v);
    return GW_OK;
}

/* ------------------------------------------------------------------- walls --- */

/* Do groups a and b agree on every grouping key except grid key skip? */
static int same_except(const gw_layer_results *t, const gw_layer_groups *gs, long ra, long rb,
                       int skip)
{
    for (int k = 0; k < gs->nkeys; k++) {
        int c = gs->key[k];
        if (c != skip && strcmp(t->grid_value[ra * t->ngrid + c], t->grid_value[rb * t->ngrid + c]) != 0)
            return 0;
    }
    return 1;
}


static int walls_make(layer_stats_run *R)
{
    const gw_layer_results *t = &R->t;
    int kw = gw_layer_results_key(t, "remove-walls");
    if (kw < 0)
        return GW_OK;
    R->walls = calloc((size_t)R->gs.n, sizeof *R->walls);
    if (!R->walls)
        return GW_ENOMEM;
    for (int a = 0; a < R->gs.n; a++) {
        long ra = R->gs.g[a].first;
        if (gw_parse_flag(t->grid_value[ra * t->ngrid + kw]) != 0)
            continue;
        for (int b = 0; b < R->gs.n; b++) {
            long rb = R->gs.g[b].first;
            if (gw_parse_flag(t->grid_value[rb * t->ngrid + kw]) == 1 && same_except(t, &R->gs, ra, rb, kw)) {
                R->walls[R->nwalls][0] = a;
                R->walls[R->nwalls++][1] = b;
                break;
            }
        }
    }
    return GW_OK;
}

/* ---------------------------------------------------------------- diagrams --- */

static void diagram_fit(layer_stats_run *R, layer_stats_diagram *D)
{
    const gw_layer_diagram *d = &D->d;
    const gw_layer_results *t = &R->t;
    D->offset = isfinite(R->delta_rm) ? R->delta_rm / 2 : d->penetration_rm / 2;
    D->offset_source = isfinite(R->delta_rm) ? "--delta-rm" : "measured: mean penetration_rm / 2 "
                                                              "of the cells bracketing the boundary";
    /* a = (pi/2) rho V_i^2 for the translation of a/b into b */
    long r0 = R->gs.g[D->groups[0]].first;
    double vi = gw_layer_results_value(t, r0, "vi", gw_layer_impact_params_default().vi);
    double rho = gw_layer_results_value(t, r0, "density", gw_layer_params_default().density);
    D->a = M_PI / 2 * rho * vi * vi;
    double *x = malloc(2 * ((size_t)d->nx + 1) * sizeof *x), *h = x ? x + d->nx + 1 : NULL;
    int n = 0;
    for (int i = 0; x && i < d->nx; i++)
        if (d->pts[i].kind == GW_LAYER_BND_CROSS) {
            x[n] = d->pts[i].x;
            h[n++] = d->pts[i].h;
        }
    gw_layer_b31 st = {.offset = D->offset, .beta = 1, .a_over_b = 1,
                       .tan_gamma = tan(R->gamma_deg * M_PI / 180)};
    gw_err err = {{0}};
    if (!x)
        snprintf(D->fit_reason, sizeof D->fit_reason, "out of memory");
    else if (!isfinite(D->offset) && !(R->fit_mask & GW_LAYER_B31_OFFSET))
        snprintf(D->fit_reason, sizeof D->fit_reason, "no offset: no boundary crossing with a "
                                                      "penetration (give --delta-rm)");
    else if ((D->fit_ok = gw_layer_b31_fit_points(x, h, n, &st, R->fit_mask, &D->fit, &err) == GW_OK) == 0)
        snprintf(D->fit_reason, sizeof D->fit_reason, "%s", err.msg);
    free(x);
}

static int diagrams_make(layer_stats_run *R)
{
    const gw_layer_results *t = &R->t;
    const gw_layer_groups *gs = &R->gs;
    int kx = gw_layer_results_key(t, "rb-rm"), kh = gw_layer_results_key(t, "height-rm");
    if (kx < 0 || kh < 0)
        return GW_OK;
    int *owner = malloc(((size_t)gs->n + 1) * sizeof *owner);
    R->dia = calloc((size_t)gs->n + 1, sizeof *R->dia);
    if (!owner || !R->dia) {
        free(owner);
        return GW_ENOMEM;
    }
    /* partition the groups by the values of the other keys */
    for (int a = 0; a < gs->n; a++) {
        owner[a] = -1;
        for (int b = 0; b < a && owner[a] < 0; b++) {
            long ra = gs->g[a].first, rb = gs->g[b].first;
            int same = 1;
            for (int k = 0; k < gs->nkeys && same; k++) {
                int c = gs->key[k];
                same = c == kx || c == kh ||
                       strcmp(t->grid_value[ra * t->ngrid + c], t->grid_value[rb * t->ngrid + c]) == 0;
            }
            if (same)
                owner[a] = owner[b];
        }
        if (owner[a] < 0) {
            owner[a] = R->ndia++;
            R->dia[owner[a]].groups = malloc((size_t)gs->n * sizeof(int));
            if (!R->dia[owner[a]].groups) {
                free(owner);
                return GW_ENOMEM;
            }
        }
        layer_stats_diagram *D = &R->dia[owner[a]];
        D->groups[D->ngroups++] = a;
    }
    free(owner);
    for (int q = 0; q < R->ndia; q++) {
        layer_stats_diagram *D = &R->dia[q];
        double *buf = malloc(4 * (size_t)D->ngroups * sizeof *buf);
        if (!buf)
            return GW_ENOMEM;
        double *x = buf, *h = buf + D->ngroups, *s = h + D->ngroups, *p = s + D->ngroups;
        for (int i = 0; i < D->ngroups; i++) {
            const gw_layer_group *g = &gs->g[D->groups[i]];
            x[i] = t->grid_num[g->first * t->ngrid + kx];
            h[i] = t->grid_num[g->first * t->ngrid + kh];
            s[i] = g->share;
            p[i] = g->penetration_rm.mean;
        }
        gw_err err = {{0}};
        D->ok = gw_layer_diagram_make(D->ngroups, x, h, s, p, R->gs.criterion, &D->d, &err) == GW_OK;
        free(buf);
        if (!D->ok)
            snprintf(D->reason, sizeof D->reason, "%s", err.msg);
        else
            diagram_fit(R, D);
    }
    return GW_OK;
}

void layer_stats_run_free(layer_stats_run *R)
{
    for (int q = 0; R->dia && q < R->ndia; q++) {
        free(R->dia[q].groups);
        gw_layer_diagram_free(&R->dia[q].d);
    }
    free(R->dia);
    free(R->bin);
    free(R->walls);
    free(R->cmdline);
    gw_layer_groups_free(&R->gs);
    gw_layer_results_free(&R->t);
}

/* ------------------------------------------------------------------ command --- */

static void print_text(const layer_stats_run *R)
{
    const gw_layer_results *t = &R->t;
    printf("granwave %s layer-stats: %s: %ld rows, %d groups, criterion %.3g\n", gw_version(),
           R->input, t->nrows, R->gs.n, R->gs.criterion);
    for (int a = 0; a < R->gs.n; a++) {
        const gw_layer_group *g = &R->gs.g[a];
        printf("  ");
        for (int k = 0; k < R->gs.nkeys; k++)
            printf("%s=%s ", t->grid_name[R->gs.key[k]], t->grid_value[g->first * t->ngrid + R->gs.key[k]]);
        printf(": n %d, share %.3f (%s%s), e_n %.3f +- %.3f, e %.3f +- %.3f, alpha_r %.1f +- %.1f deg, "
               "e_n_first %.3f +- %.3f, penetration %.3g R_m, points over %.3g R_m\n", g->n, g->share,
               g->bouncing ? "bounces" : "no bounce", g->verdict_certain ? "" : "; undecided points could change it",
               g->e_n.mean, g->e_n.std, g->e.mean, g->e.std, g->alpha_r.mean, g->alpha_r.std, g->e_n_first.mean,
               g->e_n_first.std, g->penetration_rm.mean, g->x_span_rm);
    }
    for (int k = 0; k < R->nbin; k++)
        printf("  binary: R_b/R_m %g, alpha %g: block loss %.3f +- %.3f (n %d); disc %.3f, sphere %.3f\n",
               R->bin[k].rb_rm, R->bin[k].alpha, R->bin[k].loss.mean, R->bin[k].loss.std, R->bin[k].loss.n,
               R->bin[k].disc, R->bin[k].sphere);
    for (int q = 0; q < R->ndia; q++) {
        const layer_stats_diagram *D = &R->dia[q];
        if (!D->ok) {
            printf("  diagram %d: %s\n", q, D->reason);
            continue;
        }
        printf("  diagram %d: %d crossings, R_crit %g (next %g), R_min %g, H_min %g\n", q, D->d.ncross,
               D->d.r_crit, D->d.r_crit_upper, D->d.r_min, D->d.h_min);
        if (D->fit_ok && D->fit.dof == 0)
            printf("    B.31 fit: beta %.4g, a/b %.4g (as many points as free parameters: exact, no errors), "
                   "tan gamma %.4g, offset %.4g\n", D->fit.p.beta, D->fit.p.a_over_b, D->fit.p.tan_gamma,
                   D->fit.p.offset);
        else if (D->fit_ok)
            printf("    B.31 fit: beta %.4g +- %.2g, a/b %.4g +- %.2g, tan gamma %.4g, offset %.4g, rms %.3g R_m "
                   "(%d dof)\n", D->fit.p.beta, D->fit.err.beta, D->fit.p.a_over_b, D->fit.err.a_over_b,
                   D->fit.p.tan_gamma, D->fit.p.offset, D->fit.rms, D->fit.dof);
        else
            printf("    B.31 fit: not done: %s\n", D->fit_reason);
    }
}

int gw_cmd_layer_stats(int argc, char **argv)
{
    layer_stats_run R;
    memset(&R, 0, sizeof R);
    double criterion = 0.75;
    const char *out = NULL, *fit = "beta,a_over_b";
    int json = 0;
    R.gamma_deg = 0.2;
    R.delta_rm = NAN;
    gw_opt o[] = {
        {.name = "criterion", .kind = GW_OPT_DOUBLE, .dest = &criterion, .metavar = "S",
         .help = "global bouncing verdict: share of bouncing points >= S, in (0, 1] [0.75]", .lo = 0, .hi = 1,
         .open_lo = 1},
        {.name = "fit", .kind = GW_OPT_STRING, .dest = &fit, .metavar = "LIST",
         .help = "B.31 parameters to fit among offset, beta, a_over_b, tan_gamma [beta,a_over_b]"},
        {.name = "gamma-deg", .kind = GW_OPT_DOUBLE, .dest = &R.gamma_deg, .metavar = "G",
         .help = "cone angle gamma (start value, or fixed when not fitted), deg [0.2, the paper's]", .lo = 0,
         .hi = 89, .open_lo = 1},
        {.name = "delta-rm", .kind = GW_OPT_DOUBLE, .dest = &R.delta_rm, .metavar = "D",
         .help = "delta* / R_m of B.31 [measured: mean penetration_rm at the boundary]", .lo = 0, .hi = 1e6},
        {.name = "out", .kind = GW_OPT_STRING, .dest = &out, .metavar = "DIR",
         .help = "write groups.csv, convergence.csv, binary.csv, walls.csv, diagram.csv, boundary_fit.json"},
        {.name = "json", .kind = GW_OPT_FLAG, .dest = &json, .help = "print the results as JSON"},
        {0}};
    gw_err err = {{0}};
    int help = 0, npos = 0;
    const char *pos[1] = {NULL};
    if (gw_cli_parse("layer-stats", o, argc, argv, &help, pos, 1, &npos, &err) != GW_OK)
        return fail(err.msg);
    if (help) {
        gw_cli_help(stdout, "layer-stats", "granwave layer-stats RESULTS.csv [options]", summary, o);
        return 0;
    }
    if (npos != 1)
        return fail("a results table is required: granwave layer-stats RESULTS.csv");
    if (parse_fit_mask(fit, &R.fit_mask, &err) != GW_OK)
        return fail(err.msg);
    if (out && gw_out_check(out, "layer-stats --out", &err) != GW_OK) /* before any work */
        return fail(err.msg);
    R.input = pos[0];
    R.cmdline = command_line(argc, argv);
    int rc = gw_layer_results_read(R.input, &R.t, &err);
    if (rc == GW_OK)
        rc = gw_layer_groups_make(&R.t, criterion, &R.gs, &err);
    if (rc != GW_OK) {
        layer_stats_run_free(&R);
        fprintf(stderr, "granwave layer-stats: %s\n", err.msg);
        return rc == GW_ENOMEM ? 1 : 2;
    }
    if (!R.cmdline || binary_make(&R) != GW_OK || walls_make(&R) != GW_OK || diagrams_make(&R) != GW_OK) {
        layer_stats_run_free(&R);
        fprintf(stderr, "granwave layer-stats: %s: out of memory\n", R.input);
        return 1;
    }
    long undecided = 0, uncertain = 0;
    for (int i = 0; i < R.gs.n; i++) {
        undecided += R.gs.g[i].n - R.gs.g[i].n_valid;
        uncertain += !R.gs.g[i].verdict_certain;
    }
    if (undecided > 0) /* recorded as n_points - n_valid in groups.csv and the JSON */
        fprintf(stderr, "granwave layer-stats: warning: %ld point(s) with bounced = nan (undecided: the run ended "
                        "before the verdict) count as not bounced in bounce_share and are left out of "
                        "bounce_share_decided; %ld group verdict(s) could change with longer runs\n", undecided,
                uncertain);
    long cut = 0; /* bouncing points whose run ended before T_f */
    for (int i = 0; i < R.gs.n; i++)
        cut += R.gs.g[i].n_bounced - R.gs.g[i].e.n;
    if (cut > 0) /* recorded as n_bounced - n_rebound in groups.csv and the JSON */
        fprintf(stderr, "granwave layer-stats: warning: %ld bouncing point(s) with e = nan (the run ended before "
                        "T_f, or stopped at the verdict: until = verdict) are left out of the e_n, e, alpha_r "
                        "statistics; e_n_first, e_first, alpha_r_first cover them\n", cut);
    int status = 0;
    if (out && layer_stats_write_files(&R, out, &err) != GW_OK) {
        fprintf(stderr, "granwave layer-stats --out: %s\n", err.msg);
        status = 1;
    }
    if (json) {
        cJSON *j = layer_stats_json(&R, 1);
        if (!j || gw_json_print(j, stdout) != GW_OK)
            status = 1;
        cJSON_Delete(j);
    } else {
        print_text(&R);
    }
    layer_stats_run_free(&R);
    return status;
}
