/*
 * gw_stats_run.c: the whole analysis of a layer sweep table (gw_stats.h),
 * the computation behind `granwave layer-stats` (docs/physics.md 2.3, 2.5):
 *  - per group (every grid key but `point`): the moments and shares of
 *    gw_stats_groups_make (gw_stats_groups.c);
 *  - binary-impact check: per R_b/R_m (and incidence) the block's energy loss
 *    in its first contact beside 4 m/(1 + m)^2, m = r^2 (discs) or r^3
 *    (spheres) (B.24-B.28);
 *  - walls: with and without the walls side by side (grid key remove-walls);
 *  - bouncing-occurrence diagram (grid keys rb-rm and height-rm; one panel
 *    per combination of the other keys): boundary H*(R_b/R_m), R_crit,
 *    (R_min, H_min) and a fit of B.31 with a = (pi/2) rho V_i^2 (J/m^3 per
 *    unit thickness) for b = a / (a/b) (gw_stats_diagram.c).
 * The setup's table (gw_stats_setup_params) has the command's flags as rows.
 * Units: R_m for the diagram, degrees for angles.
 */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "gw_stats.h"
#include "gw_locale.h"
#include "gw_stats_impl.h"

#define OFF(f) offsetof(gw_stats_setup, f)

static const gw_param setup_params[] = {
    {.name = "input", .type = GW_PARAM_TEXT, .offset = OFF(input), .unit = "", .metavar = "RESULTS.csv",
     .help = "the sweep table (OUT/results.csv of `granwave sweep` with model = layer; required)"},
    {.name = "criterion", .type = GW_PARAM_DOUBLE, .offset = OFF(criterion), .unit = "", .min = 0, .max = 1,
     .open_min = 1, .def = "0.75", .metavar = "S",
     .help = "global bouncing verdict: share of bouncing points >= S, in (0, 1] [0.75]"},
    /* optional: given at its default's text too, it is refused or warned of
     * where it has no effect (a table without a diagram, or without a fit) */
    {.name = "fit", .type = GW_PARAM_TEXT, .offset = OFF(fit), .unit = "", .def = "beta,a_over_b",
     .metavar = "LIST", .optional = 1, .help = "B.31 parameters to fit: beta,a_over_b and optionally offset, tan_gamma [beta,a_over_b]"},
    {.name = "gamma-deg", .type = GW_PARAM_DOUBLE, .offset = OFF(gamma_deg), .unit = "deg", .min = 0, .max = 89,
     .open_min = 1, .def = "0.2", .metavar = "G", .optional = 1, /* given at 0.2 too: refused where it has no effect */
     .help = "cone angle gamma, deg, held when not fitted (a fitted one is searched over 1e-6 to 89 deg) [0.2, the paper's]"},
    {.name = "delta-rm", .type = GW_PARAM_DOUBLE, .offset = OFF(delta_rm), .unit = "", .min = 0, .max = 1e6,
     .metavar = "D",
     .help = "delta* / R_m of B.31, held when the offset is not fitted (a fitted one is searched over >= 0) [measured: mean penetration_rm at the "
             "boundary]"},
    GW_PARAM_END};

const gw_param *gw_stats_setup_params(void)
{
    return setup_params;
}

int gw_stats_setup_init(gw_stats_setup *s)
{
    if (!s)
        return GW_EINVAL;
    memset(s, 0, sizeof *s);
    s->defaults = (gw_stats_defaults){NAN, NAN, NAN, NAN};
    gw_err err = {{0}};
    return gw_param_init(setup_params, s, &err);
}

void gw_stats_setup_clear(gw_stats_setup *s)
{
    gw_param_clear(setup_params, s);
}

int gw_stats_fit_parse(const char *s, int *mask, gw_err *err)
{
    if (!s || !mask)
        return gw_err_set(err, GW_EINVAL, "gw_stats_fit_parse: %s is NULL", !s ? "s" : "mask");
    static const struct {
        const char *name;
        int bit;
    } names[] = {{"offset", GW_STATS_B31_OFFSET}, {"beta", GW_STATS_B31_BETA},
                 {"a_over_b", GW_STATS_B31_AB}, {"tan_gamma", GW_STATS_B31_TANG}};
    *mask = 0;
    const char *p = s ? s : "";
    while (*p) {
        size_t len = strcspn(p, ",");
        if (len == 0 || (p[len] == ',' && !p[len + 1])) /* "beta,": an item left out, as a sweep list refuses */
            return gw_err_set(err, GW_EINVAL, "fit: '%s' has an empty item", s);
        /* blanks around an item, as every other list takes them ("0.3, 0.4"):
         * "beta, a_over_b" was "unknown parameter ' a_over_b'" */
        const char *q = p;
        size_t qlen = len;
        while (qlen && (*q == ' ' || *q == '\t'))
            q++, qlen--;
        while (qlen && (q[qlen - 1] == ' ' || q[qlen - 1] == '\t'))
            qlen--;
        if (qlen == 0)
            return gw_err_set(err, GW_EINVAL, "fit: '%s' has an empty item", s);
        int found = 0;
        for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
            if (strlen(names[i].name) == qlen && strncmp(q, names[i].name, qlen) == 0) {
                if (*mask & names[i].bit) /* "beta,beta" fitted beta alone, silently */
                    return gw_err_set(err, GW_EINVAL, "fit: '%s' is listed twice in '%s'", names[i].name, s);
                *mask |= names[i].bit;
                found = 1;
            }
        if (!found)
            return gw_err_set(err, GW_EINVAL, "fit: unknown parameter '%.*s' (offset, beta, a_over_b, tan_gamma)",
                              (int)qlen, q);
        p += len + (p[len] == ',');
    }
    if (!*mask)
        return gw_err_set(err, GW_EINVAL, "fit: no parameter given");
    /* A parameter left out of the fit is held at a value: the offset at
     * delta-rm / 2 (or half the measured penetration at the boundary), tan gamma
     * at gamma-deg. beta and a/b have no such input: left out, they were held at
     * 1, and the fit reported them (and b = a / (a/b)) with an error of 0 as if
     * measured (--fit beta: a/b 1 +- 0, b = a). */
    const int need = GW_STATS_B31_BETA | GW_STATS_B31_AB;
    if ((*mask & need) != need) {
        const char *left = (*mask & GW_STATS_B31_BETA) ? "a_over_b" : (*mask & GW_STATS_B31_AB) ? "beta"
                                                                                              : "beta and a_over_b";
        return gw_err_set(err, GW_EINVAL, "fit: '%s' leaves %s out, and no input gives %s value to hold fixed "
                          "(only the offset, by delta-rm, and tan_gamma, by gamma-deg, can be held): list beta "
                          "and a_over_b", s, left, (*mask & need) ? "its" : "their");
    }
    return GW_OK;
}

/* ------------------------------------------------------------ binary table --- */

typedef struct bin_row {
    double rb, al;
    long id, row;
} bin_row;

static int cmp_bin_row(const void *pa, const void *pb)
{
    const bin_row *a = pa, *b = pb;
    if (a->rb != b->rb)
        return a->rb < b->rb ? -1 : 1;
    if (a->al != b->al)
        return a->al < b->al ? -1 : 1;
    return (a->id > b->id) - (a->id < b->id);
}

/* One row per (R_b/R_m, incidence), in increasing order, over its rows in
 * case order: the same table with its rows in another order gives the same
 * rows and the same sums. (The rows were listed in the table's order and each
 * was found by a scan of all the rows: shuffled rows changed the order, and
 * a table of 1e6 rows and 1000 R_b/R_m took 58 s.) */
static int binary_make(gw_stats_analysis *A, gw_err *err)
{
    const gw_stats_table *t = &A->t;
    const gw_stats_defaults *df = &A->defaults;
    if (isnan(df->rb_rm) && gw_stats_table_key(t, "rb-rm") < 0 && !gw_stats_table_param(t, "rb-rm"))
        return gw_err_set(err, GW_EINVAL, "%s: rb-rm is neither a grid key nor a \"# param\" line and has no "
                                          "default", t->path);
    if (isnan(df->alpha) && gw_stats_table_key(t, "alpha") < 0 && !gw_stats_table_param(t, "alpha"))
        return gw_err_set(err, GW_EINVAL, "%s: alpha is neither a grid key nor a \"# param\" line and has no "
                                          "default", t->path);
    int cl = gw_stats_table_col(t, "block_loss_first_contact");
    const int krb = gw_stats_table_key(t, "rb-rm"), kal = gw_stats_table_key(t, "alpha");
    const double rb0 = gw_stats_table_value(t, 0, "rb-rm", df->rb_rm), al0 = gw_stats_table_value(t, 0, "alpha", df->alpha);
    A->bin = calloc((size_t)t->nrows + 1, sizeof *A->bin);
    double *v = malloc(((size_t)t->nrows + 1) * sizeof *v);
    bin_row *r = malloc(((size_t)t->nrows + 1) * sizeof *r);
    if (!A->bin || !v || !r) {
        free(v);
        free(r);
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", t->path);
    }
    for (long i = 0; i < t->nrows; i++) {
        r[i].rb = krb >= 0 ? t->grid_num[i * t->ngrid + krb] : rb0;
        r[i].al = kal >= 0 ? t->grid_num[i * t->ngrid + kal] : al0;
        r[i].rb += 0.0, r[i].al += 0.0; /* -0 and 0 are one value */
        r[i].id = t->case_id[i];
        r[i].row = i;
    }
    qsort(r, (size_t)t->nrows, sizeof *r, cmp_bin_row);
    for (long a = 0, b; a < t->nrows; a = b) {
        int n = 0;
        for (b = a; b < t->nrows && r[b].rb == r[a].rb && r[b].al == r[a].al; b++)
            v[n++] = t->val[r[b].row * t->ncols + cl];
        gw_stats_binary *B = &A->bin[A->nbin++];
        *B = (gw_stats_binary){.rb_rm = r[a].rb, .alpha = r[a].al};
        gw_stats_moment_of(v, n, &B->loss);
        B->disc = gw_stats_binary_loss(B->rb_rm, 0);
        B->sphere = gw_stats_binary_loss(B->rb_rm, 1);
    }
    free(v);
    free(r);
    return GW_OK;
}

/* ------------------------------------------------------------------- walls --- */

/* Do groups a and b agree on every grouping key except grid key skip? */
static int same_except(const gw_stats_table *t, const gw_stats_groups *gs, long ra, long rb, int skip)
{
    for (int k = 0; k < gs->nkeys; k++) {
        int c = gs->key[k];
        if (c != skip && !gw_stats_table_same(t, ra, rb, c))
            return 0;
    }
    return 1;
}

static int walls_make(gw_stats_analysis *A)
{
    const gw_stats_table *t = &A->t;
    int kw = gw_stats_table_key(t, "remove-walls");
    if (kw < 0)
        return GW_OK;
    A->walls = calloc((size_t)A->gs.n, sizeof *A->walls);
    if (!A->walls)
        return GW_ENOMEM;
    for (int a = 0; a < A->gs.n; a++) {
        long ra = A->gs.g[a].first;
        if (gw_parse_flag(t->grid_value[ra * t->ngrid + kw]) != 0)
            continue;
        for (int b = 0; b < A->gs.n; b++) {
            long rb = A->gs.g[b].first;
            if (gw_parse_flag(t->grid_value[rb * t->ngrid + kw]) == 1 && same_except(t, &A->gs, ra, rb, kw)) {
                A->walls[A->nwalls][0] = a;
                A->walls[A->nwalls++][1] = b;
                break;
            }
        }
    }
    return GW_OK;
}

/* ---------------------------------------------------------------- diagrams --- */

static void diagram_fit(gw_stats_analysis *A, gw_stats_panel *D)
{
    const gw_stats_diagram *d = &D->d;
    const gw_stats_table *t = &A->t;
    D->offset = isfinite(A->delta_rm) ? A->delta_rm / 2 : d->penetration_rm / 2;
    D->offset_source = isfinite(A->delta_rm) ? "--delta-rm" : "measured: mean penetration_rm / 2 "
                                                              "of the cells bracketing the boundary";
    /* a = (pi/2) rho V_i^2 for the translation of a/b into b */
    long r0 = A->gs.g[D->groups[0]].first;
    double vi = gw_stats_table_value(t, r0, "vi", A->defaults.vi);
    double rho = gw_stats_table_value(t, r0, "density", A->defaults.density);
    D->a = M_PI / 2 * rho * vi * vi;
    double *x = malloc(2 * ((size_t)d->nx + 1) * sizeof *x), *h = x ? x + d->nx + 1 : NULL;
    int n = 0;
    for (int i = 0; x && i < d->nx; i++)
        if (d->pts[i].kind == GW_STATS_BND_CROSS) {
            x[n] = d->pts[i].x;
            h[n++] = d->pts[i].h;
        }
    gw_stats_b31 st = {.offset = D->offset, .beta = 1, .a_over_b = 1,
                       .tan_gamma = tan(A->gamma_deg * M_PI / 180)};
    gw_err err = {{0}};
    if (!x)
        gw_snprintf(D->fit_reason, sizeof D->fit_reason, "out of memory");
    else if (n == 0) /* "no offset ... (give --delta-rm)" sent the user after an input that changes nothing */
        gw_snprintf(D->fit_reason, sizeof D->fit_reason, "no boundary crossing (no column changes from bouncing "
                                                      "to not bouncing along H)");
    else if (!isfinite(D->offset) && !(A->fit_mask & GW_STATS_B31_OFFSET))
        gw_snprintf(D->fit_reason, sizeof D->fit_reason, "no offset: no boundary crossing with a "
                                                      "penetration (give --delta-rm)");
    else if ((D->fit_ok = gw_stats_b31_fit_points(x, h, n, &st, A->fit_mask, &D->fit, &err) == GW_OK) == 0)
        gw_snprintf(D->fit_reason, sizeof D->fit_reason, "%s", err.msg);
    free(x);
}

static int diagrams_make(gw_stats_analysis *A)
{
    const gw_stats_table *t = &A->t;
    const gw_stats_groups *gs = &A->gs;
    int kx = gw_stats_table_key(t, "rb-rm"), kh = gw_stats_table_key(t, "height-rm");
    if (kx < 0 || kh < 0)
        return GW_OK;
    int *owner = malloc(((size_t)gs->n + 1) * sizeof *owner);
    A->dia = calloc((size_t)gs->n + 1, sizeof *A->dia);
    if (!owner || !A->dia) {
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
                same = c == kx || c == kh || gw_stats_table_same(t, ra, rb, c);
            }
            if (same)
                owner[a] = owner[b];
        }
        if (owner[a] < 0) {
            owner[a] = A->ndia++;
            A->dia[owner[a]].groups = malloc((size_t)gs->n * sizeof(int));
            if (!A->dia[owner[a]].groups) {
                free(owner);
                return GW_ENOMEM;
            }
        }
        gw_stats_panel *D = &A->dia[owner[a]];
        D->groups[D->ngroups++] = a;
    }
    free(owner);
    for (int q = 0; q < A->ndia; q++) {
        gw_stats_panel *D = &A->dia[q];
        double *buf = malloc(4 * (size_t)D->ngroups * sizeof *buf);
        if (!buf)
            return GW_ENOMEM;
        double *x = buf, *h = buf + D->ngroups, *s = h + D->ngroups, *p = s + D->ngroups;
        for (int i = 0; i < D->ngroups; i++) {
            const gw_stats_group *g = &gs->g[D->groups[i]];
            x[i] = t->grid_num[g->first * t->ngrid + kx];
            h[i] = t->grid_num[g->first * t->ngrid + kh];
            s[i] = g->share;
            p[i] = g->penetration_rm.mean;
        }
        gw_err err = {{0}};
        D->ok = gw_stats_diagram_make(D->ngroups, x, h, s, p, A->gs.criterion, &D->d, &err) == GW_OK;
        free(buf);
        if (!D->ok)
            gw_snprintf(D->reason, sizeof D->reason, "%s", err.msg);
        else
            diagram_fit(A, D);
    }
    return GW_OK;
}

void gw_stats_analysis_free(gw_stats_analysis *A)
{
    if (!A)
        return;
    for (int q = 0; A->dia && q < A->ndia; q++) {
        free(A->dia[q].groups);
        gw_stats_diagram_free(&A->dia[q].d);
    }
    free(A->dia);
    free(A->bin);
    free(A->walls);
    free(A->cmdline);
    free(A->warnings);
    gw_stats_groups_free(&A->gs);
    gw_stats_table_free(&A->t);
    memset(A, 0, sizeof *A);
}

/* The sweep's own settling line, as layer_sweep_model.c's memo_warnings
 * writes it into the table's "# warning:" lines */
#define SWEEP_SETTLING "cases run on a sample settled under another material or not settled"
static const char sweep_warned[] = ": the sweep that wrote it warned: ";

/* 1 when line (a "# warning:" text of the table) is the sweep's settling line */
static int is_sweep_settling(const char *line, int len)
{
    long n = -1, m = -1;
    int at = 0;
    char head[160];
    gw_snprintf(head, sizeof head, "%.*s", len, line);
    return sscanf(head, "%ld of %ld " SWEEP_SETTLING "%n", &n, &m, &at) == 2 && at > 0;
}

/* 1 when A's warnings say the sweep's settling line (sweep_settling_said) */
static int sweep_said_settling(const gw_stats_analysis *A)
{
    for (const char *p = A->warnings; p && (p = strstr(p, sweep_warned)) != NULL;) {
        p += sizeof sweep_warned - 1;
        const char *e = strchr(p, '\n');
        if (is_sweep_settling(p, e ? (int)(e - p) : (int)strlen(p)))
            return 1;
    }
    return 0;
}

/* The table's rows whose case ran on a sample settled under another
 * material (column settling_warning = 1): how many (-1: no such column, an
 * older table) and, in qs, their settled_load_ratio range ("" when none has
 * a number). */
static long settling_rows(const gw_stats_table *t, char *qs, size_t n)
{
    const int cw = gw_stats_table_col(t, "settling_warning"), cq = gw_stats_table_col(t, "settled_load_ratio");
    long nw = 0;
    double lo = INFINITY, hi = -INFINITY;
    qs[0] = '\0';
    if (cw < 0)
        return -1;
    for (long r = 0; r < t->nrows; r++)
        if (t->val[r * t->ncols + cw] == 1) {
            nw++;
            const double q = cq >= 0 ? t->val[r * t->ncols + cq] : NAN;
            lo = fmin(lo, q), hi = fmax(hi, q); /* fmin and fmax pass over nan */
        }
    if (lo <= hi)
        gw_snprintf(qs, n, "settled_load_ratio %.3g to %.3g, 1 at rest", lo, hi);
    return nw;
}

/* The sweep's settling line (len bytes at line) as layer-stats says it: the
 * sweep's words (its count of cases, the first case's verdict), then what
 * the table's rows hold, their count and their settled_load_ratio range.
 * The sweep's line was said alone when its count was the table's, without
 * the range; a table cut or joined by hand had the sweep's line and
 * layer-stats' own one beside it, the settling said twice. */
static int sweep_settling_said(gw_stats_analysis *A, const char *line, int len)
{
    char qs[96];
    const long nw = settling_rows(&A->t, qs, sizeof qs);
    if (nw < 0)
        return gw_warnings_add(&A->warnings, "%s%s%.*s", A->input, sweep_warned, len, line);
    if (nw == 0)
        return gw_warnings_add(&A->warnings, "%s: the sweep that wrote it warned: %.*s; in this table none of its "
                               "%ld rows has settling_warning = 1", A->input, len, line, A->t.nrows);
    return gw_warnings_add(&A->warnings, "%s: the sweep that wrote it warned: %.*s; in this table %ld of its %ld "
                           "rows have settling_warning = 1%s%s: their outcomes hold the pile's own motion as well as "
                           "the block's, and the statistics include them", A->input, len, line, nw, A->t.nrows,
                           qs[0] ? ", " : "", qs);
}

/* The rows of a layer sweep whose case ran on a sample settled under
 * another material, gravity, mass law, clump mass or friction (the model's
 * column settling_warning = 1, tables since session 28; an older table has
 * no such column and nothing is said): their outcomes hold the pile's own
 * motion as well as the block's, which the table's numbers cannot show.
 * Said here for a table without the sweep's settling line (an older table,
 * or one whose "# warning:" lines were taken out); with it, that line says
 * the rows' count and range (sweep_settling_said): one line in every case. */
static int settling_warning(gw_stats_analysis *A)
{
    char qs[96];
    const long nw = settling_rows(&A->t, qs, sizeof qs);
    if (nw <= 0 || sweep_said_settling(A))
        return GW_OK;
    return gw_warnings_add(&A->warnings,
                           "%ld of %ld rows ran on a sample settled under another material, gravity, mass law, "
                           "clump mass or friction than their case's, or not settled (column settling_warning = 1%s%s): "
                           "their outcomes hold the pile's own motion as well as the block's, and the statistics "
                           "include them",
                           nw, A->t.nrows, qs[0] ? "; " : "", qs);
}

/* The rows of a layer sweep whose block fell off the layer (column fell_off
 * = 1, tables since session 42; layer_outcome.c): bounced 0, a decided verdict
 * (the block can never come back), but not a rebound that ended inside the
 * layer: counted apart here, as not bounced in the shares. */
static int fell_off_warning(gw_stats_analysis *A)
{
    const gw_stats_table *t = &A->t;
    const int cf = gw_stats_table_col(t, "fell_off");
    long nf = 0;
    for (long r = 0; cf >= 0 && r < t->nrows; r++)
        nf += t->val[r * t->ncols + cf] == 1;
    if (nf == 0)
        return GW_OK;
    return gw_warnings_add(&A->warnings,
                           "%ld of %ld rows fell off the layer (column fell_off = 1: the block left it for good, "
                           "with no wall there, before a verdict): bounced 0, decided, they count as not bounced in "
                           "bounce_share and bounce_share_decided; not rebounds that ended inside the layer",
                           nf, t->nrows);
}

/* A diagram's B.31 fit stopped by its box (at_bound): no free minimum, its
 * parameters there the box's and its errors (0 where the Jacobian is flat:
 * beta_err 0 at the edge) not a free fit's. layer-stats --delta-rm 1e6 held
 * the offset at 5e5 R_m over crossings at H* 5 to 13 R_m: beta 0 and a/b
 * 1e-6 on their edges, rms residual 5e5 R_m, beta_err 0, exit 0 and no
 * warning; --gamma-deg 89 put beta on its edge (beta_err 957), --fit with
 * tan_gamma put it at 1e-6 deg and --fit with offset the offset at 0, each
 * said by the text's "at the edge" only. The default fit of the measured
 * diagram is inside the box. */
static int fit_edge_warning(const gw_stats_analysis *A, int q, char **list)
{
    const gw_stats_panel *D = &A->dia[q];
    const gw_stats_b31_fit *f = &D->fit;
    if (!D->ok || !D->fit_ok || !f->at_bound)
        return GW_OK;
    /* each parameter on its edge named with the end it is at: its value
     * against the middle of its range (at_bound is set only within 1e-6 of an
     * end); beta's upper end is the smallest boundary R_b/R_m, the fit's x_lo */
    double hmax = -INFINITY, xlo = INFINITY;
    for (int i = 0; i < D->d.nx; i++)
        if (D->d.pts[i].kind == GW_STATS_BND_CROSS) {
            hmax = fmax(hmax, D->d.pts[i].h);
            xlo = fmin(xlo, D->d.pts[i].x);
        }
    const int lo[4] = {1, f->p.beta < xlo / 2, f->p.a_over_b < 1, f->p.tan_gamma < 1};
    static const struct {
        int bit;
        const char *name, *low, *high, *range;
    } bits[] = {{GW_STATS_B31_OFFSET, "offset", "0", "", ""},
                {GW_STATS_B31_BETA, "beta", "0", "", "[0, the smallest R_b/R_m]"},
                {GW_STATS_B31_AB, "a/b", "1e-6", "1e6", "[1e-6, 1e6]"},
                {GW_STATS_B31_TANG, "tan_gamma", "tan 1e-6 deg", "tan 89 deg", "[tan 1e-6 deg, tan 89 deg]"}};
    char edge[400] = "";
    for (int k = 0; k < 4; k++) {
        if (!(f->at_bound & bits[k].bit))
            continue;
        const size_t u = strlen(edge);
        if (k == 0) /* offset >= 0: one end */
            gw_snprintf(edge + u, sizeof edge - u, "%soffset at 0", *edge ? ", " : "");
        else if (k == 1 && !lo[k]) /* the smallest R_b/R_m, its value too */
            gw_snprintf(edge + u, sizeof edge - u, "%sbeta at its upper end, the smallest R_b/R_m (%.4g), of %s",
                        *edge ? ", " : "", f->p.beta, bits[k].range);
        else
            gw_snprintf(edge + u, sizeof edge - u, "%s%s at its %s end, %s, of %s", *edge ? ", " : "", bits[k].name,
                        lo[k] ? "lower" : "upper", lo[k] ? bits[k].low : bits[k].high, bits[k].range);
    }
    char why[200] = "";
    if (!(A->fit_mask & GW_STATS_B31_OFFSET) && D->offset > hmax) /* B.31 lies above its offset */
        gw_snprintf(why, sizeof why, ": the offset held at %.4g R_m (%s) lies above every boundary crossing (H* up "
                    "to %.4g R_m), where B.31, never below its offset, cannot reach them",
                    D->offset, isfinite(A->delta_rm) ? "delta-rm / 2" : "the measured penetration / 2", hmax);
    return gw_warnings_add(list, "diagram %d: the B.31 fit stopped at the edge of its box (%s), not at a free "
                           "minimum: those parameters are the box's and the fit's errors are not a free fit's "
                           "(beta_err %.3g, a_over_b_err %.3g); rms residual %.3g R_m%s", q, edge, f->err.beta,
                           f->err.a_over_b, f->rms, why);
}

/* The analysis's warnings, from the counts groups.csv records: points whose
 * bounce is undecided (n_points - n_valid) and bouncing points without e
 * (n_bounced - n_e: the run ended before T_f, or stopped at the verdict);
 * rows on a sample settled under another material (settling_warning). */
static int warnings_make(gw_stats_analysis *A)
{
    long undecided = 0, uncertain = 0, cut = 0;
    for (int i = 0; i < A->gs.n; i++) {
        undecided += A->gs.g[i].n - A->gs.g[i].n_valid;
        uncertain += !A->gs.g[i].verdict_certain;
        cut += A->gs.g[i].n_bounced - A->gs.g[i].e.n;
    }
    int rc = GW_OK;
    if (undecided > 0)
        rc = gw_warnings_add(&A->warnings,
                             "%ld point(s) with bounced = nan (undecided: the run ended before the verdict) count as "
                             "not bounced in bounce_share and are left out of bounce_share_decided; %ld group "
                             "verdict(s) could change with longer runs",
                             undecided, uncertain);
    if (rc == GW_OK && cut > 0)
        rc = gw_warnings_add(&A->warnings,
                             "%ld bouncing point(s) with e = nan (the run ended before T_f, or stopped at the "
                             "verdict: until = verdict) are left out of the e_n, e, alpha_r statistics; e_n_first, "
                             "e_first, alpha_r_first cover them",
                             cut);
    if (rc == GW_OK)
        rc = settling_warning(A);
    if (rc == GW_OK)
        rc = fell_off_warning(A);
    for (int q = 0; rc == GW_OK && q < A->ndia; q++)
        rc = fit_edge_warning(A, q, &A->warnings);
    /* the B.31 options act on the fits alone: given (other than their
     * defaults) on a table whose diagrams have no boundary crossing, no fit
     * can be made whatever they say, and they changed nothing (with crossings,
     * a fit that fails may fail by them: fewer crossings than the parameters
     * of fit, a start that does not converge). A table without a diagram at
     * all refuses them before this (gw_stats_analyse). */
    char given[64] = "";
    if (A->fit_given) /* given, at the default's list too (judged by value, "beta,a_over_b" given was
                         not said and "a_over_b,beta" was, on a table without a diagram) */
        gw_snprintf(given, sizeof given, "fit");
    if (A->gamma_given)
        gw_snprintf(given + strlen(given), sizeof given - strlen(given), "%sgamma-deg", *given ? ", " : "");
    if (!isnan(A->delta_rm))
        gw_snprintf(given + strlen(given), sizeof given - strlen(given), "%sdelta-rm", *given ? ", " : "");
    int crossings = 0, built = 0, fitted = 0, failed = -1;
    for (int q = 0; q < A->ndia; q++) {
        crossings += A->dia[q].ok ? A->dia[q].d.ncross : 0;
        built += A->dia[q].ok;
        fitted += A->dia[q].ok && A->dia[q].fit_ok;
        if (failed < 0 && A->dia[q].ok && A->dia[q].d.ncross > 0 && !A->dia[q].fit_ok)
            failed = q;
    }
    if (rc == GW_OK && *given && A->ndia > 0 && crossings == 0)
        rc = gw_warnings_add(&A->warnings, "%s: %s no effect: no diagram has a B.31 fit (%s%s)", given,
                             strchr(given, ',') ? "have" : "has",
                             built ? "no R_b/R_m column changes from bouncing to not along H: no boundary crossing "
                                     "to fit" : "no diagram could be built: ",
                             built ? "" : A->dia[0].reason);
    /* crossings, but no diagram's fit made (fewer crossings than free
     * parameters, a fit that did not converge): the options chose at most
     * the failure's reason, and changed no number; exit 0 with no warning
     * before (a 1-crossing table with --gamma-deg 5) */
    else if (rc == GW_OK && *given && crossings > 0 && fitted == 0 && failed >= 0)
        rc = gw_warnings_add(&A->warnings, "%s: %s no effect on any number: no diagram's B.31 fit could be made "
                             "(%s)", given, strchr(given, ',') ? "have" : "has", A->dia[failed].fit_reason);
    return rc;
}

int gw_stats_analyse(const gw_stats_setup *s, gw_stats_analysis *A, gw_err *err)
{
    if (!s || !A) {
        if (A)
            memset(A, 0, sizeof *A);
        return gw_err_set(err, GW_EINVAL, "gw_stats_analyse: %s is NULL", !s ? "s" : "A");
    }
    memset(A, 0, sizeof *A);
    int rc = gw_param_check(setup_params, s, err);
    if (rc != GW_OK)
        return rc;
    if (!s->input || !*s->input)
        return gw_err_set(err, GW_EINVAL, "input: a sweep table (results.csv) is required");
    /* the settings as the run uses them: the optional rows not given at their
     * defaults (fit's text, gamma-deg); a deep copy, cleared below */
    gw_stats_setup r;
    memset(&r, 0, sizeof r);
    if ((rc = gw_param_copy(setup_params, sizeof r, &r, s, err)) != GW_OK)
        return rc;
    if ((rc = gw_param_resolve(setup_params, &r, err)) == GW_OK)
        rc = gw_stats_fit_parse(r.fit, &A->fit_mask, err);
    A->gamma_deg = r.gamma_deg;
    gw_param_clear(setup_params, &r);
    if (rc != GW_OK)
        return rc;
    A->fit_given = gw_param_given(gw_param_find(setup_params, "fit"), s);
    /* a fitted offset or tan gamma is searched over its whole range (the
     * global fit): the value that would hold it is not used, not even as a
     * start, so giving it has no effect (the option-effect test found
     * --fit beta,a_over_b,offset --delta-rm 0.5 silent) */
    if ((A->fit_mask & GW_STATS_B31_OFFSET) && !isnan(s->delta_rm))
        return gw_err_set(err, GW_EINVAL, "delta-rm: has no effect when the offset is fitted (fit lists offset)");
    A->gamma_given = gw_param_given(gw_param_find(setup_params, "gamma-deg"), s);
    if ((A->fit_mask & GW_STATS_B31_TANG) && A->gamma_given)
        return gw_err_set(err, GW_EINVAL, "gamma-deg: has no effect when tan_gamma is fitted (fit lists tan_gamma)");
    A->delta_rm = s->delta_rm;
    A->defaults = s->defaults;
    char *said = NULL; /* the sweep's warnings its table kept ("# warning:" lines) */
    rc = gw_stats_table_read_warned(s->input, &A->t, &said, err);
    A->input = A->t.path;
    /* said first and once each, named as the table's: a user reading
     * layer-stats' output alone (stderr, --json, boundary_fit.json, Python)
     * lost them */
    for (const char *p = rc == GW_OK ? said : NULL; p && *p && rc == GW_OK;) {
        const char *e = strchr(p, '\n');
        const int n = e ? (int)(e - p) : (int)strlen(p);
        if ((is_sweep_settling(p, n) ? sweep_settling_said(A, p, n)
                                     : gw_warnings_add(&A->warnings, "%s%s%.*s", A->input, sweep_warned, n, p)) != GW_OK)
            rc = gw_err_set(err, GW_ENOMEM, "%s: out of memory", A->input);
        p += n + (e ? 1 : 0);
    }
    free(said);
    /* the rows against the definitions of e_n, e, alpha_r: with the run's
     * settings, which the reader does not know */
    if (rc == GW_OK && (rc = gw_stats_table_bounds(&A->t, &A->defaults, &A->warnings, err)) == GW_ENOMEM)
        gw_err_set(err, rc, "%s: out of memory", A->input);
    /* the B.31 options act on the bouncing diagram only: refused, as having no
     * effect, on a table without one (given: set, at the row's default too) */
    if (rc == GW_OK && (gw_stats_table_key(&A->t, "rb-rm") < 0 || gw_stats_table_key(&A->t, "height-rm") < 0)) {
        const char *given = A->fit_given ? "fit" : A->gamma_given ? "gamma-deg" : !isnan(s->delta_rm) ? "delta-rm" : NULL;
        if (given) {
            gw_stats_table_free(&A->t);
            A->input = NULL;
            return gw_err_set(err, GW_EINVAL, "%s: has no effect: the table has no bouncing diagram (it needs the "
                              "grid keys rb-rm and height-rm)", given);
        }
    }
    if (rc == GW_OK)
        rc = gw_stats_groups_make(&A->t, s->criterion, &A->gs, err);
    if (rc == GW_OK)
        rc = binary_make(A, err);
    if (rc == GW_OK && (walls_make(A) != GW_OK || diagrams_make(A) != GW_OK || warnings_make(A) != GW_OK))
        rc = gw_err_set(err, GW_ENOMEM, "%s: out of memory", A->input);
    return rc;
}
