/*
 * gw_stats_study.c: the analysis of a layer sweep table (gw_stats_run.c) as
 * tables with named columns (gw_stats_outcome, its table
 * gw_stats_outcome_fields), for the library's index of studies ("layer-stats")
 * and the Python module. The numbers are those of the command's JSON and CSV
 * files under their names, one per statistic (docs/formats.md, layer-stats
 * outputs; docs/physics.md 2.3, 2.5): groups as groups.csv, the running means
 * of Fig. 10, the first contact against B.24-B.28, walls kept/removed, per
 * diagram R_crit, (R_min, H_min) and the B.31 fit (offset, beta, a/b, tan
 * gamma; a = (pi/2) rho V_i^2 in J/m^3 per unit thickness, b = a / (a/b)),
 * its cells (R_b/R_m, H/R_m, bounce share) and its boundary H*(R_b/R_m).
 * Lengths in R_m, angles in degrees, energies as fractions of the incident
 * one; NaN where a value is undefined. Flags and counts are stored as doubles
 * (exact). No printing, no files.
 */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "gw_stats.h"

#define CONV_COLS "group,k,case,point,bounced,e_n,e,running_mean_e_n,running_mean_e,running_share"
/* the names of the JSON and the CSV files (gw_stats_out.c), one per statistic */
#define BIN_COLS                                                                                          \
    "rb_rm,alpha,n_block_loss_first_contact,block_loss_first_contact_mean,block_loss_first_contact_std," \
    "binary_disc,binary_sphere"
#define WALL_SIDE(p)                                                                                      \
    p "group," p "n_points," p "bounce_share," p "bouncing," p "e_n_mean," p "e_mean," p                 \
      "penetration_rm_mean," p "block_loss_first_contact_mean," p "rebound_energy_mean"
#define WALL_COLS WALL_SIDE("walls_") "," WALL_SIDE("walls_removed_")
#define DIA_COLS                                                                                         \
    "ok,ncross,r_crit,r_crit_upper,r_min,h_min,penetration_rm_boundary,fit_ok,offset,offset_err,beta,"   \
    "beta_err,a_over_b,a_over_b_err,tan_gamma,tan_gamma_err,gamma_deg,corr_beta_a_over_b,a,b,b_err,"     \
    "x_min,h_min_fit,n_fit,dof,rms_residual,iterations"
#define CELL_COLS "diagram,rb_rm,height_rm,share,penetration_rm"
#define BND_COLS "diagram,rb_rm,kind,h_star,h_lo,h_hi,share_lo,share_hi,changes,penetration_rm,b31"
enum { NCONV = 10, NBIN = 7, NWALL = 18, NDIA = 27, NCELL = 5, NBND = 11 };

#define OFF(f) offsetof(gw_stats_outcome, f)
#define RD(nm, f, hl) {.name = nm, .type = GW_PARAM_DOUBLE, .offset = OFF(f), .unit = "", .help = hl}
#define RI(nm, f, hl) {.name = nm, .type = GW_PARAM_INT, .offset = OFF(f), .unit = "", .help = hl}
#define RA(nm, f, r, c, names, hl) \
    {.name = nm, .type = GW_PARAM_DARRAY, .offset = OFF(f), .unit = "", .rows = r, .cols = c, .choices = names, .help = hl}

static const gw_param outcome_fields[] = {
    {.name = "rows", .type = GW_PARAM_LONG, .offset = OFF(rows), .unit = "", .help = "rows of the sweep table"},
    RD("criterion", criterion, "the verdict's criterion S"),
    RI("ngroups", ngroups, "groups of impact points (every grid key but point)"),
    RI("nkeys", nkeys, "grouping keys"),
    {.name = "group_keys", .type = GW_PARAM_TEXT, .offset = OFF(group_keys), .unit = "",
     .help = "the grouping keys' names, comma-separated (columns of keys)"},
    RA("keys", keys, "ngroups", "nkeys", NULL, "each group's values of the grouping keys (NaN: not a number)"),
    RA("groups", groups, "ngroups", "46", GW_STATS_GROUP_COLUMNS, /* GW_STATS_GROUP_NCOLS */
       "per group, as groups.csv: moments of e_n, e, alpha_r (bouncing points), penetration (m, R_m), shares; "
       "X_mean, X_std and n_X of the JSON's X"),
    RI("nconvergence", nconvergence, "rows of convergence"),
    RA("convergence", convergence, "nconvergence", "10", CONV_COLS,
       "running means over the first k points of each group (Fig. 10), as convergence.csv"),
    RI("nbinary", nbinary, "rows of binary"),
    RA("binary", binary, "nbinary", "7", BIN_COLS,
       "first-contact block loss per R_b/R_m and incidence (deg) beside the binary impact (B.24-B.28)"),
    RI("nwalls", nwalls, "rows of walls"),
    RA("walls", walls, "nwalls", "18", WALL_COLS,
       "groups with walls kept and removed side by side (walls_group, walls_removed_group: their rows of groups)"),
    RI("ndiagrams", ndiagrams, "bouncing-occurrence diagrams"),
    RA("diagrams", diagrams, "ndiagrams", "27", DIA_COLS,
       "per diagram: R_crit in [r_crit, r_crit_upper), (r_min, h_min), the B.31 fit (NaN when not done)"),
    RI("ncells", ncells, "rows of cells"),
    RA("cells", cells, "ncells", "5", CELL_COLS, "the diagrams' cells: R_b/R_m, H/R_m, bounce share (NaN: no cell)"),
    RI("nboundary", nboundary, "rows of boundary"),
    RA("boundary", boundary, "nboundary", "11", BND_COLS,
       "H*/R_m per R_b/R_m column; kind 0 cross, 1 above, 2 below, 3 inverted; b31 = fitted curve there"),
    {.name = "offset_sources", .type = GW_PARAM_TEXT, .offset = OFF(offset_sources), .unit = "",
     .help = "per diagram, one line each: the B.31 fit's offset source (the JSON's fit.offset_source; "
             "empty without a fit)"},
    {.name = "fit_reasons", .type = GW_PARAM_TEXT, .offset = OFF(fit_reasons), .unit = "",
     .help = "per diagram, one line each: why it has no B.31 fit (the JSON's fit_reason; empty with one)"},
    GW_PARAM_WARNINGS(OFF(a.warnings)),
    GW_PARAM_END};

const gw_param *gw_stats_outcome_fields(void)
{
    return outcome_fields;
}

void gw_stats_group_row(const gw_stats_group *g, double row[GW_STATS_GROUP_NCOLS])
{
    if (!row)
        return;
    if (!g) { /* no group: no numbers */
        for (int k = 0; k < GW_STATS_GROUP_NCOLS; k++)
            row[k] = NAN;
        return;
    }
    int i = 0;
    row[i++] = g->n;
    row[i++] = g->n_valid;
    row[i++] = g->n_bounced;
    row[i++] = g->share;
    row[i++] = g->bouncing;
    const gw_stats_moment *m[] = {&g->e_n, &g->e, &g->alpha_r};
    for (int k = 0; k < 3; k++) {
        row[i++] = m[k]->mean;
        row[i++] = m[k]->std;
    }
    row[i++] = g->e.n;
    const gw_stats_moment *m2[] = {&g->penetration, &g->penetration_rm, &g->block_loss, &g->dissipated,
                                   &g->rebound_energy};
    for (int k = 0; k < 5; k++) {
        row[i++] = m2[k]->mean;
        row[i++] = m2[k]->std;
    }
    row[i++] = g->energy_error_max;
    row[i++] = g->k_stable_e;
    row[i++] = g->x_span;
    row[i++] = g->x_span_rm;
    const gw_stats_moment *m3[] = {&g->e_n_first, &g->e_first, &g->alpha_r_first};
    for (int k = 0; k < 3; k++) {
        row[i++] = m3[k]->mean;
        row[i++] = m3[k]->std;
    }
    row[i++] = g->e_first.n;
    row[i++] = g->share_decided;
    row[i++] = g->share_high;
    row[i++] = g->verdict_certain;
    /* the counts of the other moments, after the columns of the tables written before them */
    const gw_stats_moment *m4[] = {&g->e_n, &g->alpha_r, &g->penetration, &g->penetration_rm, &g->block_loss,
                                   &g->dissipated, &g->rebound_energy, &g->e_n_first, &g->alpha_r_first};
    for (int k = 0; k < 9; k++)
        row[i++] = m4[k]->n;
    row[i++] = g->n_fell_off; /* after the counts (session 43) */
}

static double *table(int rows, int cols)
{
    return malloc(((size_t)rows * (size_t)cols + 1) * sizeof(double));
}

static void wall_side(const gw_stats_groups *gs, int group, double *r)
{
    const gw_stats_group *g = &gs->g[group];
    r[0] = group;
    r[1] = g->n;
    r[2] = g->share;
    r[3] = g->bouncing;
    r[4] = g->e_n.mean;
    r[5] = g->e.mean;
    r[6] = g->penetration_rm.mean;
    r[7] = g->block_loss.mean;
    r[8] = g->rebound_energy.mean;
}

static void diagram_row(const gw_stats_panel *D, double *r)
{
    for (int i = 0; i < NDIA; i++)
        r[i] = NAN;
    r[0] = D->ok;
    r[7] = D->fit_ok;
    if (!D->ok)
        return;
    const gw_stats_diagram *d = &D->d;
    r[1] = d->ncross;
    r[2] = d->r_crit;
    r[3] = d->r_crit_upper;
    r[4] = d->r_min;
    r[5] = d->h_min;
    r[6] = d->penetration_rm;
    if (!D->fit_ok)
        return;
    const gw_stats_b31_fit *f = &D->fit;
    double v[] = {f->p.offset, f->err.offset, f->p.beta, f->err.beta, f->p.a_over_b, f->err.a_over_b,
                  f->p.tan_gamma, f->err.tan_gamma, atan(f->p.tan_gamma) * 180 / M_PI, f->corr_beta_ab, D->a,
                  D->a / f->p.a_over_b, D->a / f->p.a_over_b * f->err.a_over_b / f->p.a_over_b, f->x_min,
                  f->h_min, f->n, f->dof, f->rms, f->iterations};
    memcpy(r + 8, v, sizeof v);
}

/* The texts of a diagram as the JSON has them (gw_stats_out.c): its fit's
 * offset source, or why it has no fit; NULL where the JSON has none. */
static const char *offset_source(const gw_stats_analysis *A, const gw_stats_panel *D)
{
    return !D->ok || !D->fit_ok ? NULL : (A->fit_mask & GW_STATS_B31_OFFSET) ? "fitted" : D->offset_source;
}

static const char *fit_reason(const gw_stats_panel *D)
{
    return D->ok && !D->fit_ok ? D->fit_reason : NULL;
}

/* out->offset_sources and out->fit_reasons: a line per diagram. GW_ENOMEM. */
static int diagram_texts(gw_stats_outcome *out)
{
    const gw_stats_analysis *A = &out->a;
    size_t ns = 1, nr = 1;
    for (int q = 0; q < A->ndia; q++) {
        const char *s = offset_source(A, &A->dia[q]), *r = fit_reason(&A->dia[q]);
        ns += (s ? strlen(s) : 0) + 1;
        nr += (r ? strlen(r) : 0) + 1;
    }
    out->offset_sources = malloc(ns);
    out->fit_reasons = malloc(nr);
    if (!out->offset_sources || !out->fit_reasons)
        return GW_ENOMEM;
    char *ps = out->offset_sources, *pr = out->fit_reasons;
    for (int q = 0; q < A->ndia; q++) {
        const char *s = offset_source(A, &A->dia[q]), *r = fit_reason(&A->dia[q]);
        size_t ls = s ? strlen(s) : 0, lr = r ? strlen(r) : 0;
        memcpy(ps, s ? s : "", ls);
        memcpy(pr, r ? r : "", lr);
        ps[ls] = pr[lr] = '\n';
        ps += ls + 1;
        pr += lr + 1;
    }
    *ps = *pr = '\0';
    return GW_OK;
}

/* The tables of out from out->a. GW_ENOMEM. */
static int tables_make(gw_stats_outcome *out)
{
    const gw_stats_analysis *A = &out->a;
    const gw_stats_table *t = &A->t;
    const gw_stats_groups *gs = &A->gs;
    out->rows = t->nrows;
    out->criterion = gs->criterion;
    out->ngroups = gs->n;
    out->nkeys = gs->nkeys;
    size_t len = 1;
    for (int k = 0; k < gs->nkeys; k++)
        len += strlen(t->grid_name[gs->key[k]]) + 1;
    for (int q = 0; q < A->ndia; q++)
        if (A->dia[q].ok) {
            out->ncells += A->dia[q].d.nx * A->dia[q].d.nh;
            out->nboundary += A->dia[q].d.nx;
        }
    for (int a = 0; a < gs->n; a++)
        out->nconvergence += gs->g[a].n;
    out->nbinary = A->nbin;
    out->nwalls = A->nwalls;
    out->ndiagrams = A->ndia;
    out->group_keys = malloc(len);
    out->keys = table(out->ngroups, out->nkeys);
    out->groups = table(out->ngroups, GW_STATS_GROUP_NCOLS);
    out->convergence = table(out->nconvergence, NCONV);
    out->binary = table(out->nbinary, NBIN);
    out->walls = table(out->nwalls, NWALL);
    out->diagrams = table(out->ndiagrams, NDIA);
    out->cells = table(out->ncells, NCELL);
    out->boundary = table(out->nboundary, NBND);
    if (!out->group_keys || !out->keys || !out->groups || !out->convergence || !out->binary || !out->walls ||
        !out->diagrams || !out->cells || !out->boundary)
        return GW_ENOMEM;
    out->group_keys[0] = '\0';
    for (int k = 0; k < gs->nkeys; k++) {
        if (k)
            strcat(out->group_keys, ",");
        strcat(out->group_keys, t->grid_name[gs->key[k]]);
    }
    int cb = gw_stats_table_col(t, "bounced"), cen = gw_stats_table_col(t, "e_n"), ce = gw_stats_table_col(t, "e");
    long c = 0;
    for (int a = 0; a < gs->n; a++) {
        const gw_stats_group *g = &gs->g[a];
        for (int k = 0; k < gs->nkeys; k++)
            out->keys[a * gs->nkeys + k] = t->grid_num[g->first * t->ngrid + gs->key[k]];
        gw_stats_group_row(g, out->groups + (size_t)a * GW_STATS_GROUP_NCOLS);
        for (int k = 0; k < g->n; k++, c++) {
            long r = g->rows[k];
            double v[NCONV] = {a, k + 1, (double)t->case_id[r],
                               gs->point_key >= 0 ? t->grid_num[r * t->ngrid + gs->point_key] : NAN,
                               t->val[r * t->ncols + cb], t->val[r * t->ncols + cen], t->val[r * t->ncols + ce],
                               g->run_e_n[k], g->run_e[k], g->run_share[k]};
            memcpy(out->convergence + c * NCONV, v, sizeof v);
        }
    }
    for (int k = 0; k < A->nbin; k++) {
        const gw_stats_binary *b = &A->bin[k];
        double v[NBIN] = {b->rb_rm, b->alpha, b->loss.n, b->loss.mean, b->loss.std, b->disc, b->sphere};
        memcpy(out->binary + k * NBIN, v, sizeof v);
    }
    for (int k = 0; k < A->nwalls; k++) {
        double *r = out->walls + k * NWALL;
        wall_side(gs, A->walls[k][0], r);
        wall_side(gs, A->walls[k][1], r + NWALL / 2);
    }
    if (diagram_texts(out) != GW_OK)
        return GW_ENOMEM;
    long ic = 0, ib = 0;
    for (int q = 0; q < A->ndia; q++) {
        const gw_stats_panel *D = &A->dia[q];
        diagram_row(D, out->diagrams + q * NDIA);
        if (!D->ok)
            continue;
        const gw_stats_diagram *d = &D->d;
        for (int i = 0; i < d->nx; i++) {
            for (int j = 0; j < d->nh; j++, ic++) {
                double v[NCELL] = {q, d->xs[i], d->hs[j], d->share[i * d->nh + j], d->pen[i * d->nh + j]};
                memcpy(out->cells + ic * NCELL, v, sizeof v);
            }
            const gw_stats_boundary_pt *p = &d->pts[i];
            double v[NBND] = {q, p->x, p->kind, p->h, p->h_lo, p->h_hi, p->s_lo, p->s_hi, p->changes,
                              p->penetration_rm, D->fit_ok ? gw_stats_b31_eval(&D->fit.p, p->x) : NAN};
            memcpy(out->boundary + ib++ * NBND, v, sizeof v);
        }
    }
    return GW_OK;
}

int gw_stats_run(const gw_stats_setup *s, gw_stats_outcome *out, gw_err *err)
{
    if (out) /* emptied on every refusal, a NULL setup's too (docs/library.md) */
        memset(out, 0, sizeof *out);
    if (!s || !out)
        return gw_err_set(err, GW_EINVAL, "gw_stats_run: %s is NULL", !s ? "setup" : "out");
    int rc = gw_stats_analyse(s, &out->a, err);
    if (rc == GW_OK && tables_make(out) != GW_OK)
        rc = gw_err_set(err, GW_ENOMEM, "%s: out of memory", out->a.input);
    return rc;
}

void gw_stats_outcome_free(gw_stats_outcome *out)
{
    if (!out)
        return;
    gw_stats_analysis_free(&out->a);
    free(out->group_keys);
    free(out->keys);
    free(out->groups);
    free(out->convergence);
    free(out->binary);
    free(out->walls);
    free(out->diagrams);
    free(out->cells);
    free(out->boundary);
    free(out->offset_sources);
    free(out->fit_reasons);
    memset(out, 0, sizeof *out);
}
