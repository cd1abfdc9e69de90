/*
 * gw_stats_out.c: the outputs of `granwave layer-stats` (app/layer/layer_stats.c):
 * JSON (stdout, boundary_fit.json) and the CSV tables groups.csv,
 * convergence.csv, binary.csv, walls.csv and diagram.csv. Every file opens
 * with the program version, the command line and the input path, and says
 * how the boundary is placed and which B.31 parameters were fitted.
 * Units: R_m for the diagram, degrees for angles, fractions of the incident
 * kinetic energy for the first-contact losses; NaN prints as "nan" (CSV) or
 * null (JSON).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "gw_stats.h"
#include "gw_locale.h"
#include "gw_stats_impl.h"
#include "gw_io_impl.h"

static const char *placement =
    "bouncing lies below the boundary; in each R_b/R_m column H* is placed between the lowest "
    "globally bouncing cell h_lo and its upper neighbour h_hi that does not bounce, where the bounce "
    "share interpolated linearly in H equals the criterion S: "
    "H* = h_lo + (s_lo - S) / (s_lo - s_hi) (h_hi - h_lo)";

static const char *identifiability =
    "B.31 depends on a and b only through a/b. With u = x - beta and K = (a/b) tan(gamma), "
    "f = offset + (sqrt(u^2 + K x^2) - u) / (2 tan gamma), which for u >> sqrt(K) x is "
    "offset + (a/b) x^2 / (4 u): tan(gamma) shapes the curve only within about sqrt(K) x of "
    "x = beta, where a grid boundary has no points (those columns bounce at every H), so it is "
    "fixed (--gamma-deg, 0.2 deg as in the paper). The offset delta* / (2 R_m) trades off against "
    "beta and a/b (the large-x line is offset + (a/b)(x + beta)/4), so it is fixed from the "
    "measured mean penetration at the boundary (or --delta-rm). Free by default: beta and a/b "
    "(--fit changes this). b = a / (a/b) with a = (pi/2) rho V_i^2.";

static const char *kind_name(int k)
{
    static const char *names[] = {"cross", "above", "below", "inverted"};
    return k >= 0 && k < 4 ? names[k] : "?";
}

static cJSON *moment_json(const gw_stats_moment *m)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "mean", m->mean);
    cJSON_AddNumberToObject(o, "std", m->std);
    cJSON_AddNumberToObject(o, "n", m->n);
    return o;
}

static const char *gval(const gw_stats_analysis *R, long row, int key)
{
    return R->t.grid_value[row * R->t.ngrid + key];
}

/* {key: value} of the grouping keys of row, except skip1/skip2 (grid indices). */
static cJSON *keys_json(const gw_stats_analysis *R, long row, int skip1, int skip2)
{
    cJSON *o = cJSON_CreateObject();
    for (int k = 0; k < R->gs.nkeys; k++) {
        int c = R->gs.key[k];
        if (c == skip1 || c == skip2)
            continue;
        double v = R->t.grid_num[row * R->t.ngrid + c];
        if (isfinite(v))
            cJSON_AddNumberToObject(o, R->t.grid_name[c], v);
        else
            cJSON_AddStringToObject(o, R->t.grid_name[c], gval(R, row, c));
    }
    return o;
}

static cJSON *group_json(const gw_stats_analysis *R, const gw_stats_group *g)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, "keys", keys_json(R, g->first, -1, -1));
    cJSON_AddNumberToObject(o, "n_points", g->n);
    cJSON_AddNumberToObject(o, "n_valid", g->n_valid);
    cJSON_AddNumberToObject(o, "n_bounced", g->n_bounced);
    cJSON_AddNumberToObject(o, "n_fell_off", g->n_fell_off);
    cJSON_AddNumberToObject(o, "bounce_share", g->share);
    cJSON_AddNumberToObject(o, "bounce_share_decided", g->share_decided);
    cJSON_AddNumberToObject(o, "bounce_share_high", g->share_high);
    cJSON_AddBoolToObject(o, "bouncing", g->bouncing);
    cJSON_AddBoolToObject(o, "verdict_certain", g->verdict_certain);
    cJSON_AddItemToObject(o, "e_n", moment_json(&g->e_n));
    cJSON_AddItemToObject(o, "e", moment_json(&g->e));
    cJSON_AddItemToObject(o, "alpha_r", moment_json(&g->alpha_r));
    cJSON_AddItemToObject(o, "penetration", moment_json(&g->penetration));
    cJSON_AddItemToObject(o, "penetration_rm", moment_json(&g->penetration_rm));
    cJSON_AddItemToObject(o, "block_loss_first_contact", moment_json(&g->block_loss));
    cJSON_AddItemToObject(o, "rebound_energy", moment_json(&g->rebound_energy));
    cJSON_AddItemToObject(o, "dissipated_first_contact", moment_json(&g->dissipated));
    cJSON_AddItemToObject(o, "e_n_first", moment_json(&g->e_n_first));
    cJSON_AddItemToObject(o, "e_first", moment_json(&g->e_first));
    cJSON_AddItemToObject(o, "alpha_r_first", moment_json(&g->alpha_r_first));
    cJSON_AddNumberToObject(o, "energy_error_max", g->energy_error_max);
    cJSON_AddNumberToObject(o, "k_stable_e", g->k_stable_e);
    cJSON_AddNumberToObject(o, "x_span", g->x_span);
    cJSON_AddNumberToObject(o, "x_span_rm", g->x_span_rm);
    cJSON_AddItemToObject(o, "running_mean_e_n", gw_json_doubles(g->run_e_n, g->n));
    cJSON_AddItemToObject(o, "running_mean_e", gw_json_doubles(g->run_e, g->n));
    cJSON_AddItemToObject(o, "running_share", gw_json_doubles(g->run_share, g->n));
    return o;
}

static cJSON *fit_json(const gw_stats_analysis *R, const gw_stats_panel *D)
{
    const gw_stats_b31_fit *f = &D->fit;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "model", "B.31: f(x) = offset + (x - beta)/(2 tan gamma) (sqrt(1 + (a tan gamma / b) "
                                        "x^2/(x - beta)^2) - 1), offset = delta* / (2 R_m)");
    cJSON *fr = cJSON_AddArrayToObject(o, "free"), *fx = cJSON_AddArrayToObject(o, "fixed");
    static const struct {
        int bit;
        const char *name;
    } bits[] = {{GW_STATS_B31_OFFSET, "offset"}, {GW_STATS_B31_BETA, "beta"},
                {GW_STATS_B31_AB, "a_over_b"}, {GW_STATS_B31_TANG, "tan_gamma"}};
    for (int k = 0; k < 4; k++)
        cJSON_AddItemToArray(R->fit_mask & bits[k].bit ? fr : fx, cJSON_CreateString(bits[k].name));
    cJSON_AddStringToObject(o, "offset_source", (R->fit_mask & GW_STATS_B31_OFFSET) ? "fitted" : D->offset_source);
    cJSON_AddNumberToObject(o, "offset", f->p.offset);
    cJSON_AddNumberToObject(o, "offset_err", f->err.offset);
    cJSON_AddNumberToObject(o, "beta", f->p.beta);
    cJSON_AddNumberToObject(o, "beta_err", f->err.beta);
    cJSON_AddNumberToObject(o, "a_over_b", f->p.a_over_b);
    cJSON_AddNumberToObject(o, "a_over_b_err", f->err.a_over_b);
    cJSON_AddNumberToObject(o, "tan_gamma", f->p.tan_gamma);
    cJSON_AddNumberToObject(o, "tan_gamma_err", f->err.tan_gamma);
    cJSON_AddNumberToObject(o, "gamma_deg", atan(f->p.tan_gamma) * 180 / M_PI);
    cJSON_AddNumberToObject(o, "corr_beta_a_over_b", f->corr_beta_ab);
    cJSON_AddNumberToObject(o, "a", D->a);
    cJSON_AddNumberToObject(o, "b", D->a / f->p.a_over_b);
    cJSON_AddNumberToObject(o, "b_err", D->a / f->p.a_over_b * f->err.a_over_b / f->p.a_over_b);
    /* the fitted curve's minimum and the boundary points fitted: h_min_fit and n_fit, as no
     * name of the fit is one of the diagram's (h_min: its lowest crossing) or of a group's
     * (n_points: impact points); the library's table lends the fit's names to the diagram's row */
    cJSON_AddNumberToObject(o, "x_min", f->x_min);
    cJSON_AddNumberToObject(o, "h_min_fit", f->h_min);
    cJSON_AddNumberToObject(o, "n_fit", f->n);
    cJSON_AddNumberToObject(o, "dof", f->dof);
    cJSON_AddNumberToObject(o, "rms_residual", f->rms);
    cJSON_AddNumberToObject(o, "iterations", f->iterations);
    cJSON *ab = cJSON_AddArrayToObject(o, "at_bound");
    for (int k = 0; k < 4; k++)
        if (f->at_bound & bits[k].bit)
            cJSON_AddItemToArray(ab, cJSON_CreateString(bits[k].name));
    cJSON_AddStringToObject(o, "box", "the global least-squares minimum over beta in [0, the smallest boundary "
                                      "R_b/R_m], a/b in [1e-6, 1e6], tan gamma in [tan 1e-6 deg, tan 89 deg] and "
                                      "offset >= 0 (the free ones); at_bound: free parameters on an edge of it");
    cJSON_AddStringToObject(o, "errors", "standard errors from (J^T J)^-1 scaled by chi^2/dof (unweighted); "
                                         "null when dof = 0");
    cJSON_AddStringToObject(o, "identifiability", identifiability);
    /* the fitted curve over the diagram's R_b/R_m range, for plots */
    enum { NCURVE = 201 };
    double cx[NCURVE], cf[NCURVE], x0 = D->d.xs[0], x1 = D->d.xs[D->d.nx - 1];
    for (int i = 0; i < NCURVE; i++) {
        cx[i] = x0 + (x1 - x0) * i / (NCURVE - 1);
        cf[i] = gw_stats_b31_eval(&f->p, cx[i]);
    }
    cJSON *c = cJSON_AddObjectToObject(o, "curve");
    cJSON_AddItemToObject(c, "rb_rm", gw_json_doubles(cx, NCURVE));
    cJSON_AddItemToObject(c, "h", gw_json_doubles(cf, NCURVE));
    return o;
}

static cJSON *diagram_json(const gw_stats_analysis *R, const gw_stats_panel *D)
{
    int kx = gw_stats_table_key(&R->t, "rb-rm"), kh = gw_stats_table_key(&R->t, "height-rm");
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, "keys", keys_json(R, R->gs.g[D->groups[0]].first, kx, kh));
    if (!D->ok) {
        cJSON_AddStringToObject(o, "error", D->reason);
        return o;
    }
    const gw_stats_diagram *d = &D->d;
    cJSON_AddItemToObject(o, "rb_rm", gw_json_doubles(d->xs, d->nx));
    cJSON_AddItemToObject(o, "height_rm", gw_json_doubles(d->hs, d->nh));
    cJSON *sh = cJSON_AddArrayToObject(o, "share"), *pm = cJSON_AddArrayToObject(o, "penetration_rm");
    for (int i = 0; i < d->nx; i++) {
        cJSON_AddItemToArray(sh, gw_json_doubles(d->share + (size_t)i * d->nh, d->nh));
        cJSON_AddItemToArray(pm, gw_json_doubles(d->pen + (size_t)i * d->nh, d->nh));
    }
    cJSON_AddStringToObject(o, "placement", placement);
    cJSON *b = cJSON_AddArrayToObject(o, "boundary");
    for (int i = 0; i < d->nx; i++) {
        const gw_stats_boundary_pt *p = &d->pts[i];
        cJSON *q = cJSON_CreateObject();
        cJSON_AddNumberToObject(q, "rb_rm", p->x);
        cJSON_AddStringToObject(q, "kind", kind_name(p->kind));
        cJSON_AddNumberToObject(q, "h_star", p->h);
        cJSON_AddNumberToObject(q, "h_lo", p->h_lo);
        cJSON_AddNumberToObject(q, "h_hi", p->h_hi);
        cJSON_AddNumberToObject(q, "share_lo", p->s_lo);
        cJSON_AddNumberToObject(q, "share_hi", p->s_hi);
        cJSON_AddNumberToObject(q, "changes", p->changes);
        cJSON_AddNumberToObject(q, "penetration_rm", p->penetration_rm);
        cJSON_AddNumberToObject(q, "b31", D->fit_ok ? gw_stats_b31_eval(&D->fit.p, p->x) : NAN);
        cJSON_AddItemToArray(b, q);
    }
    cJSON_AddNumberToObject(o, "ncross", d->ncross);
    cJSON_AddNumberToObject(o, "r_crit", d->r_crit);
    cJSON_AddNumberToObject(o, "r_crit_upper", d->r_crit_upper);
    cJSON_AddStringToObject(o, "r_crit_means", "largest R_b/R_m of the grid up to which every column bounces at "
                                               "every H; the true R_crit lies in [r_crit, r_crit_upper)");
    cJSON_AddNumberToObject(o, "r_min", d->r_min);
    cJSON_AddNumberToObject(o, "h_min", d->h_min);
    cJSON_AddNumberToObject(o, "penetration_rm_boundary", d->penetration_rm);
    if (D->fit_ok) {
        cJSON_AddItemToObject(o, "fit", fit_json(R, D));
    } else {
        cJSON_AddNullToObject(o, "fit");
        cJSON_AddStringToObject(o, "fit_reason", D->fit_reason);
    }
    return o;
}

static cJSON *binary_json(const gw_stats_analysis *R)
{
    cJSON *a = cJSON_CreateArray();
    for (int k = 0; k < R->nbin; k++) {
        const gw_stats_binary *b = &R->bin[k];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddNumberToObject(o, "rb_rm", b->rb_rm);
        cJSON_AddNumberToObject(o, "alpha", b->alpha);
        cJSON_AddItemToObject(o, "block_loss_first_contact", moment_json(&b->loss));
        cJSON_AddNumberToObject(o, "binary_disc", b->disc);
        cJSON_AddNumberToObject(o, "binary_sphere", b->sphere);
        cJSON_AddItemToArray(a, o);
    }
    return a;
}

/* A walls pair: two sides (walls kept, removed at impact time) of these
 * statistics of a group, named side_col in walls.csv and side: {col} in the
 * JSON. group is the side's row of groups.csv (and of the JSON's groups). */
static const char *const wall_side[2] = {"walls", "walls_removed"};
static const char *const wall_cols[] = {"group", "n_points", "bounce_share", "bouncing", "e_n_mean", "e_mean",
                                        "penetration_rm_mean", "block_loss_first_contact_mean",
                                        "rebound_energy_mean"};
enum { NWALL_COLS = sizeof wall_cols / sizeof wall_cols[0] };

static cJSON *walls_json(const gw_stats_analysis *R)
{
    cJSON *a = cJSON_CreateArray();
    int kw = gw_stats_table_key(&R->t, "remove-walls");
    for (int k = 0; k < R->nwalls; k++) {
        cJSON *o = cJSON_CreateObject();
        cJSON_AddItemToObject(o, "keys", keys_json(R, R->gs.g[R->walls[k][0]].first, kw, -1));
        for (int w = 0; w < 2; w++) {
            const gw_stats_group *g = &R->gs.g[R->walls[k][w]];
            /* walls.csv's columns without the side's prefix (write_walls) */
            cJSON *q = cJSON_AddObjectToObject(o, wall_side[w]);
            cJSON_AddNumberToObject(q, wall_cols[0], R->walls[k][w]);
            cJSON_AddNumberToObject(q, wall_cols[1], g->n);
            cJSON_AddNumberToObject(q, wall_cols[2], g->share);
            cJSON_AddBoolToObject(q, wall_cols[3], g->bouncing);
            const double v[] = {g->e_n.mean, g->e.mean, g->penetration_rm.mean, g->block_loss.mean,
                                g->rebound_energy.mean};
            for (int c = 4; c < NWALL_COLS; c++)
                cJSON_AddNumberToObject(q, wall_cols[c], v[c - 4]);
        }
        cJSON_AddItemToArray(a, o);
    }
    return a;
}

/* An analysis as the JSON and the files read it: its table's shape
 * (stats_table_shape), the groups' keys and rows within the table, the
 * binary, walls and diagram lists with their arrays, each wall pair and panel
 * naming groups it has, a panel's texts ended within their fields and a built
 * diagram's arrays given. An analysis filled by hand with counts and no arrays
 * (3 diagrams, 2 groups, 3 walls) was read through NULL (SIGSEGV) before
 * session 34. GW_EINVAL naming the field. */
static int analysis_shape(const gw_stats_analysis *R, gw_err *err)
{
    const gw_stats_table *t = &R->t;
    const gw_stats_groups *gs = &R->gs;
    int rc = stats_table_shape(t, err);
    if (rc != GW_OK)
        return rc;
    if (gs->nkeys < 0 || gs->nkeys > GW_STATS_MAX_KEYS || gs->n < 0 || (gs->n > 0 && !gs->g) ||
        (gs->n > 0 && gs->point_key >= t->ngrid)) /* (a zeroed analysis: point key 0 of no keys, unread) */
        return gw_err_set(err, GW_EINVAL, "stats analysis: gs: %d groups%s, %d keys, point key %d (keys in [0, %d], "
                          "the table's %d)", gs->n, gs->n > 0 && !gs->g ? " without their array" : "", gs->nkeys,
                          gs->point_key, GW_STATS_MAX_KEYS, t->ngrid);
    for (int k = 0; k < gs->nkeys; k++)
        if (gs->key[k] < 0 || gs->key[k] >= t->ngrid)
            return gw_err_set(err, GW_EINVAL, "stats analysis: gs.key[%d] = %d is not a grid key of the table's %d",
                              k, gs->key[k], t->ngrid);
    for (int k = 0; gs->n > 0 && k < gw_stats_table_nrequired; k++)
        if (gw_stats_table_col(t, gw_stats_table_required[k]) < 0)
            return gw_err_set(err, GW_EINVAL, "stats analysis: groups of a table without its column '%s'",
                              gw_stats_table_required[k]);
    for (int a = 0; a < gs->n; a++) {
        const gw_stats_group *g = &gs->g[a];
        if (g->first < 0 || g->first >= t->nrows || g->n < 0 ||
            (g->n > 0 && (!g->rows || !g->run_e_n || !g->run_e || !g->run_share)))
            return gw_err_set(err, GW_EINVAL, "stats analysis: group %d: first row %ld, %d rows%s (rows in [0, %ld))",
                              a, g->first, g->n, g->n > 0 && !g->rows ? " without their array" : "", t->nrows);
        for (int k = 0; k < g->n; k++)
            if (g->rows[k] < 0 || g->rows[k] >= t->nrows)
                return gw_err_set(err, GW_EINVAL, "stats analysis: group %d: row %ld is outside [0, %ld)", a,
                                  g->rows[k], t->nrows);
    }
    if (R->nbin < 0 || (R->nbin > 0 && !R->bin) || R->nwalls < 0 || (R->nwalls > 0 && !R->walls) || R->ndia < 0 ||
        (R->ndia > 0 && !R->dia))
        return gw_err_set(err, GW_EINVAL, "stats analysis: nbin %d, nwalls %d, ndia %d (>= 0, with their arrays: "
                          "bin %s, walls %s, dia %s)", R->nbin, R->nwalls, R->ndia, R->bin ? "given" : "NULL",
                          R->walls ? "given" : "NULL", R->dia ? "given" : "NULL");
    for (int k = 0; k < R->nwalls; k++)
        for (int w = 0; w < 2; w++)
            if (R->walls[k][w] < 0 || R->walls[k][w] >= gs->n)
                return gw_err_set(err, GW_EINVAL, "stats analysis: walls[%d][%d] = %d is not one of the %d groups", k,
                                  w, R->walls[k][w], gs->n);
    for (int q = 0; q < R->ndia; q++) {
        const gw_stats_panel *D = &R->dia[q];
        if (D->ngroups < 1 || !D->groups)
            return gw_err_set(err, GW_EINVAL, "stats analysis: diagram %d: %d groups%s (at least one)", q,
                              D->ngroups, D->groups ? "" : ", groups NULL");
        for (int k = 0; k < D->ngroups; k++)
            if (D->groups[k] < 0 || D->groups[k] >= gs->n)
                return gw_err_set(err, GW_EINVAL, "stats analysis: diagram %d: group %d is not one of the %d groups",
                                  q, D->groups[k], gs->n);
        if (!memchr(D->reason, '\0', sizeof D->reason) || !memchr(D->fit_reason, '\0', sizeof D->fit_reason))
            return gw_err_set(err, GW_EINVAL, "stats analysis: diagram %d: its %s has no NUL within its %zu bytes", q,
                              memchr(D->reason, '\0', sizeof D->reason) ? "fit_reason" : "reason",
                              sizeof D->reason);
        const gw_stats_diagram *d = &D->d;
        if (D->ok && (d->nx < 1 || d->nh < 0 || !d->xs || !d->pts || (d->nh > 0 && (!d->hs || !d->share || !d->pen))))
            return gw_err_set(err, GW_EINVAL, "stats analysis: diagram %d: built (ok) with %d x %d cells%s", q, d->nx,
                              d->nh, d->nx < 1 || d->nh < 0 ? "" : " without their arrays");
    }
    return GW_OK;
}

cJSON *gw_stats_json(const gw_stats_analysis *R, int full)
{
    if (!R || analysis_shape(R, NULL) != GW_OK)
        return NULL;
    const gw_stats_table *t = &R->t;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "program", "granwave layer-stats");
    cJSON_AddStringToObject(o, "version", gw_version());
    cJSON_AddStringToObject(o, "command", R->cmdline ? R->cmdline : "(library call)");
    cJSON_AddStringToObject(o, "input", R->input);
    if (t->has_content_hash) {
        char hx[17];
        gw_snprintf(hx, sizeof hx, "%016llx", t->content_hash);
        cJSON_AddStringToObject(o, "input_fnv1a64", hx);
    }
    cJSON_AddNumberToObject(o, "criterion", R->gs.criterion);
    cJSON_AddNumberToObject(o, "rows", (double)t->nrows);
    cJSON *p = cJSON_AddObjectToObject(o, "params");
    for (int i = 0; i < t->nparams; i++)
        cJSON_AddStringToObject(p, t->param_name[i], t->param_value[i]);
    cJSON *gk = cJSON_AddArrayToObject(o, "group_keys");
    for (int k = 0; k < R->gs.nkeys; k++)
        cJSON_AddItemToArray(gk, cJSON_CreateString(t->grid_name[R->gs.key[k]]));
    if (full) {
        cJSON *g = cJSON_AddArrayToObject(o, "groups");
        for (int a = 0; a < R->gs.n; a++)
            cJSON_AddItemToArray(g, group_json(R, &R->gs.g[a]));
        cJSON_AddItemToObject(o, "binary", binary_json(R));
        cJSON_AddItemToObject(o, "walls", walls_json(R));
    }
    cJSON *d = cJSON_AddArrayToObject(o, "diagrams");
    for (int q = 0; q < R->ndia; q++)
        cJSON_AddItemToArray(d, diagram_json(R, &R->dia[q]));
    /* the analysis's warnings (undecided points, rows on a sample settled
     * under another material or not settled), one text each, as Python's
     * result and layer-impact's JSON give them: they were on stderr alone,
     * and a script reading the JSON or boundary_fit.json took statistics
     * that include such rows for clean ones */
    cJSON *w = cJSON_AddArrayToObject(o, "warnings");
    for (const char *p = R->warnings; w && p && *p;) {
        const char *e = strchr(p, '\n');
        const size_t len = e ? (size_t)(e - p) : strlen(p);
        char *one = strndup(p, len);
        if (one)
            cJSON_AddItemToArray(w, cJSON_CreateString(one));
        free(one);
        p += len + (e ? 1 : 0);
    }
    return o;
}

/* ------------------------------------------------------------------- CSVs --- */

static void num(FILE *fp, double v)
{
    if (isnan(v))
        fputs(",nan", fp);
    else
        gw_fprintf(fp, ",%.9g", v);
}

/* "# LABEL: TEXT" where every line break in text (a file name may hold one)
 * starts a new comment line: the next line of a CSV file never reads as its
 * header or as data. */
static void comment_kv(FILE *fp, const char *label, const char *text)
{
    gw_fprintf(fp, "# %s: ", label);
    for (const char *p = text ? text : ""; *p; p++)
        if (*p == '\n' || *p == '\r')
            fputs("\n# ", fp);
        else
            fputc(*p, fp);
    fputc('\n', fp);
}

static void head(FILE *fp, const gw_stats_analysis *R, const char *what)
{
    gw_fprintf(fp, "# granwave %s layer-stats\n", gw_version());
    comment_kv(fp, "command", R->cmdline ? R->cmdline : "(library call)");
    comment_kv(fp, "input", R->input);
    if (R->t.has_content_hash) /* the version of the table read */
        gw_fprintf(fp, "# input fnv1a64: %016llx\n", R->t.content_hash);
    gw_fprintf(fp, "# criterion: %.6g (a group bounces globally when its share of bouncing impact points >= "
                "criterion)\n# %s\n", R->gs.criterion, what);
}

/* Header cells of the grouping keys (skipping grid indices skip1, skip2). */
static void key_names(FILE *fp, const gw_stats_analysis *R, int skip1, int skip2)
{
    for (int k = 0; k < R->gs.nkeys; k++)
        if (R->gs.key[k] != skip1 && R->gs.key[k] != skip2)
            gw_fprintf(fp, ",%s", R->t.grid_name[R->gs.key[k]]);
}

static void key_values(FILE *fp, const gw_stats_analysis *R, long row, int skip1, int skip2)
{
    for (int k = 0; k < R->gs.nkeys; k++)
        if (R->gs.key[k] != skip1 && R->gs.key[k] != skip2)
            gw_fprintf(fp, ",%s", gval(R, row, R->gs.key[k]));
}

static void write_groups(FILE *fp, const gw_stats_analysis *R)
{
    head(fp, R, "per group of impact points (every grid key but point), the JSON's groups under the same "
                "names: X_mean, X_std, n_X = mean, sample standard deviation (n - 1) and number of the finite "
                "values of X; e_n, e, alpha_r (deg) over the bouncing points, the others over all points; "
                "penetration in m and in R_m; block_loss_first_contact and dissipated_first_contact (first-contact "
                "block loss and friction dissipation) as fractions of the incident energy; rebound_energy = e^2, "
                "the block's rebound kinetic energy (translation) over the incident one, 0 where it does not "
                "bounce; k_stable_e = points after which the running mean of e stays within 5 % of the final "
                "mean; x_span = spread of the impact points (max - min x_impact, m; x_span_rm in R_m); e_n_first, "
                "e_first, alpha_r_first: the same at the first free-flight maximum (nan when the table has no "
                "such columns); n_e < n_bounced when runs ended before T_f; n_points - n_valid points are "
                "undecided (the run ended before the verdict): bounce_share counts them as not bounced (bounced "
                "before the end of the run), bounce_share_decided leaves them out, bounce_share_high counts them "
                "as bounced; verdict_certain = 1 when no outcome of theirs could change the verdict; n_fell_off = "
                "points whose block fell off the layer (column fell_off 1: decided, not bounced)");
    gw_fprintf(fp, "group");
    key_names(fp, R, -1, -1);
    gw_fprintf(fp, ",%s\n", GW_STATS_GROUP_COLUMNS);
    for (int a = 0; a < R->gs.n; a++) {
        const gw_stats_group *g = &R->gs.g[a];
        double row[GW_STATS_GROUP_NCOLS];
        gw_stats_group_row(g, row);
        gw_fprintf(fp, "%d", a);
        key_values(fp, R, g->first, -1, -1);
        for (int c = 0; c < GW_STATS_GROUP_NCOLS; c++)
            num(fp, row[c]); /* counts and flags print as integers ("%.9g") */
        fputc('\n', fp);
    }
}

static void write_convergence(FILE *fp, const gw_stats_analysis *R)
{
    const gw_stats_table *t = &R->t;
    int cb = gw_stats_table_col(t, "bounced"), cen = gw_stats_table_col(t, "e_n"),
        ce = gw_stats_table_col(t, "e");
    head(fp, R, "convergence with the number of points (the paper's Fig. 10): row k of a group holds its k-th "
                "point (by point index) and the means of e_n and e over the bouncing points among the first k, "
                "and the bounce share of the first k");
    gw_fprintf(fp, "group");
    key_names(fp, R, -1, -1);
    gw_fprintf(fp, ",k,case,point,bounced,e_n,e,running_mean_e_n,running_mean_e,running_share\n");
    for (int a = 0; a < R->gs.n; a++) {
        const gw_stats_group *g = &R->gs.g[a];
        for (int k = 0; k < g->n; k++) {
            long r = g->rows[k];
            gw_fprintf(fp, "%d", a);
            key_values(fp, R, g->first, -1, -1);
            gw_fprintf(fp, ",%d,%ld,%s", k + 1, t->case_id[r], R->gs.point_key >= 0 ? gval(R, r, R->gs.point_key) : "nan");
            num(fp, t->val[r * t->ncols + cb]);
            num(fp, t->val[r * t->ncols + cen]);
            num(fp, t->val[r * t->ncols + ce]);
            num(fp, g->run_e_n[k]);
            num(fp, g->run_e[k]);
            num(fp, g->run_share[k]);
            fputc('\n', fp);
        }
    }
}

static void write_binary(FILE *fp, const gw_stats_analysis *R)
{
    head(fp, R, "first contact against the binary impact (B.24-B.28): block_loss_first_contact = (E_kb(0) - "
                "E_kb)/E_incident at the end of the block's first contact, over the rows with this R_b/R_m and "
                "incidence (deg) where it is defined (n_block_loss_first_contact of them); "
                "binary_disc = 4 m/(1 + m)^2 with m = r^2 (disc masses, the layer default), binary_sphere the "
                "same with m = r^3, r = R_b/R_m, and 1 where m <= 1 (the block stops inside the contact)");
    gw_fprintf(fp, "rb_rm,alpha,n_block_loss_first_contact,block_loss_first_contact_mean,"
                "block_loss_first_contact_std,binary_disc,binary_sphere\n");
    for (int k = 0; k < R->nbin; k++) {
        const gw_stats_binary *b = &R->bin[k];
        gw_fprintf(fp, "%.9g,%.9g,%d", b->rb_rm, b->alpha, b->loss.n);
        num(fp, b->loss.mean);
        num(fp, b->loss.std);
        num(fp, b->disc);
        num(fp, b->sphere);
        fputc('\n', fp);
    }
}

static void write_walls(FILE *fp, const gw_stats_analysis *R)
{
    int kw = gw_stats_table_key(&R->t, "remove-walls");
    head(fp, R, kw < 0 ? "walls: the table has no remove-walls grid key, nothing to compare"
                       : "walls kept (remove-walls = 0) and removed at impact time (remove-walls = 1) side by "
                         "side, for the groups that agree on every other key: the JSON's walls and walls_removed, "
                         "each name prefixed with its side; walls_group and walls_removed_group are the rows of "
                         "groups.csv, the other columns means over their points");
    gw_fprintf(fp, "pair");
    key_names(fp, R, kw, -1);
    for (int w = 0; w < 2; w++)
        for (int c = 0; c < NWALL_COLS; c++)
            gw_fprintf(fp, ",%s_%s", wall_side[w], wall_cols[c]);
    fputc('\n', fp);
    for (int k = 0; k < R->nwalls; k++) {
        gw_fprintf(fp, "%d", k);
        key_values(fp, R, R->gs.g[R->walls[k][0]].first, kw, -1);
        for (int w = 0; w < 2; w++) {
            const gw_stats_group *g = &R->gs.g[R->walls[k][w]];
            gw_fprintf(fp, ",%d,%d", R->walls[k][w], g->n);
            num(fp, g->share);
            gw_fprintf(fp, ",%d", g->bouncing);
            num(fp, g->e_n.mean);
            num(fp, g->e.mean);
            num(fp, g->penetration_rm.mean);
            num(fp, g->block_loss.mean);
            num(fp, g->rebound_energy.mean);
        }
        fputc('\n', fp);
    }
}

static void write_diagram(FILE *fp, const gw_stats_analysis *R)
{
    int kx = gw_stats_table_key(&R->t, "rb-rm"), kh = gw_stats_table_key(&R->t, "height-rm");
    head(fp, R, placement);
    gw_fprintf(fp, "# kind: cross (boundary between two cells), above (every H bounces), below (no H bounces), "
                "inverted (bouncing only above); changes > 1: the verdict changes more than once along H; "
                "b31 = the fitted B.31 at rb_rm (boundary_fit.json)\n");
    gw_fprintf(fp, "diagram");
    key_names(fp, R, kx, kh);
    gw_fprintf(fp, ",rb_rm,kind,h_star,h_lo,h_hi,share_lo,share_hi,changes,penetration_rm,b31\n");
    for (int q = 0; q < R->ndia; q++) {
        const gw_stats_panel *D = &R->dia[q];
        for (int i = 0; D->ok && i < D->d.nx; i++) {
            const gw_stats_boundary_pt *p = &D->d.pts[i];
            gw_fprintf(fp, "%d", q);
            key_values(fp, R, R->gs.g[D->groups[0]].first, kx, kh);
            gw_fprintf(fp, ",%.9g,%s", p->x, kind_name(p->kind));
            num(fp, p->h);
            num(fp, p->h_lo);
            num(fp, p->h_hi);
            num(fp, p->s_lo);
            num(fp, p->s_hi);
            gw_fprintf(fp, ",%d", p->changes);
            num(fp, p->penetration_rm);
            num(fp, D->fit_ok ? gw_stats_b31_eval(&D->fit.p, p->x) : NAN);
            fputc('\n', fp);
        }
    }
}

typedef void (*writer)(FILE *fp, const gw_stats_analysis *R);

/* the six files of one analysis */
static const char *const stats_files[] = {"groups.csv", "convergence.csv", "binary.csv", "walls.csv", "diagram.csv",
                                          "boundary_fit.json", NULL};

int gw_stats_out_check_input(const char *dir, const char *input, gw_err *err)
{
    /* NULL was GW_OK (gw_outset_check_input takes NULL as "no input") */
    if (!dir || !input)
        return gw_err_set(err, GW_EINVAL, "gw_stats_out_check_input: %s is NULL", !dir ? "dir" : "input");
    return gw_outset_check_input(dir, stats_files, input, "layer-stats RESULTS.csv", err);
}

int gw_stats_write_files(const gw_stats_analysis *R, const char *dir, gw_err *err)
{
    static const struct {
        const char *name;
        writer fn;
    } files[] = {{"groups.csv", write_groups}, {"convergence.csv", write_convergence},
                 {"binary.csv", write_binary}, {"walls.csv", write_walls}, {"diagram.csv", write_diagram}};
    /* the six files of one analysis, or (a write failed) the earlier ones as they were */
    if (!R || !dir) /* before the directory is made (R NULL was read by the first writer: SIGSEGV) */
        return gw_err_set(err, GW_EINVAL, "gw_stats_write_files: %s is NULL", !R ? "A" : "dir");
    gw_outset set;
    memset(&set, 0, sizeof set);
    int rc = analysis_shape(R, err); /* before the directory is made */
    char made[4096] = ""; /* the first directory of dir this call creates: taken back on a failure */
    if (rc == GW_OK)
        rc = gw_mkdir_made(dir, made, sizeof made, err);
    if (rc == GW_OK)
        rc = gw_outset_begin(&set, dir, stats_files, err);
    char path[4096];
    for (size_t i = 0; rc == GW_OK && i < sizeof files / sizeof files[0]; i++) {
        if (gw_path_join(path, sizeof path, dir, files[i].name) != GW_OK) {
            rc = gw_err_set(err, GW_EINVAL, "%s: path too long", dir);
            break;
        }
        gw_afile f;
        if ((rc = gw_afile_open(&f, path, err)) != GW_OK)
            break;
        files[i].fn(f.fp, R);
        rc = gw_afile_commit(&f, err);
    }
    if (rc == GW_OK && gw_path_join(path, sizeof path, dir, "boundary_fit.json") != GW_OK)
        rc = gw_err_set(err, GW_EINVAL, "%s: path too long", dir);
    if (rc == GW_OK) {
        cJSON *j = gw_stats_json(R, 0);
        rc = j ? gw_json_write(path, j, err) : gw_err_set(err, GW_ENOMEM, "%s: out of memory", path);
        cJSON_Delete(j);
    }
    if (rc == GW_OK)
        rc = gw_outset_commit(&set, err);
    gw_outset_abort(&set);
    if (made[0] && rc != GW_OK) /* an empty directory it made goes, as a refused run leaves none */
        gw_temps_unmake(dir, made);
    else if (made[0])
        gw_temps_drop(dir);
    return rc;
}

int gw_stats_out_check(const char *dir, const char *what, gw_err *err)
{
    int rc = gw_out_check(dir, what, err);
    if (rc == GW_OK)
        rc = gw_out_names_check(dir, stats_files, what, err);
    if (rc != GW_OK)
        return rc;
    /* the nearest existing ancestor (gw_out_check found it a directory) */
    char d[4096], probe[4200];
    gw_snprintf(d, sizeof d, "%s", dir);
    struct stat st;
    while (stat(d, &st) != 0) {
        size_t n = strlen(d);
        while (n > 1 && d[n - 1] == '/')
            d[--n] = '\0';
        gw_path_parent(d);
    }
    if (gw_path_join(probe, sizeof probe, d, ".granwave-out-check") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", what);
    gw_afile f;
    gw_err e = {{0}};
    int orc = gw_afile_open(&f, probe, &e);
    if (orc == GW_ENOMEM) /* not the directory's fault */
        return gw_err_set(err, orc, "%s: %s", what, e.msg);
    if (orc != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: cannot write into '%s' (%s)", what, d,
                          strstr(e.msg, ": cannot create: ") ? strstr(e.msg, ": cannot create: ") + 17 : e.msg);
    gw_afile_abort(&f);
    return GW_OK;
}
