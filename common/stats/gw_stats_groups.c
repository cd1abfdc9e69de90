/*
 * gw_stats_groups.c: the per-group statistics of docs/physics.md 2.3 over a
 * layer sweep table: over the N impact points of one configuration, the mean
 * and sample standard deviation of e_n = V_nr/V_ni, e = V_r/V_i and
 * alpha_r = arccos(V_nr/V_r) (B.16-B.18; over the bouncing points, the only
 * ones where they are defined), of the penetration and of the first-contact
 * energy fractions; the bounce share and the global verdict share >= S
 * (docs/physics.md 2.5, S = 75 % in the paper); the running means over the
 * first k points (the paper's Fig. 10: how many points make the mean stable);
 * the binary impact's smallest block energy (gw_stats_binary_loss).
 * Units: as in the table (m, deg, fractions of the incident energy, R_m).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_stats.h"
#include "gw_locale.h"
#include "gw_stats_impl.h"

void gw_stats_moment_of(const double *v, int n, gw_stats_moment *m)
{
    if (!m)
        return;
    if (!v) /* no values: as n of them not finite */
        n = 0;
    double s = 0, lo = INFINITY, hi = -INFINITY;
    int k = 0;
    for (int i = 0; i < n; i++)
        if (isfinite(v[i])) {
            s += v[i];
            k++;
            lo = fmin(lo, v[i]);
            hi = fmax(hi, v[i]);
        }
    m->n = k;
    if (k > 0 && lo == hi) { /* all equal: six values 0.1 gave a std of 1.5e-17 */
        m->mean = lo;
        m->std = k > 1 ? 0 : NAN;
        return;
    }
    m->mean = k ? s / k : NAN;
    double ss = 0, dmax = 0; /* two-pass: no cancellation in the variance */
    for (int i = 0; i < n; i++)
        if (isfinite(v[i])) {
            const double d = v[i] - m->mean;
            ss += d * d;
            dmax = fmax(dmax, fabs(d));
        }
    m->std = k > 1 ? sqrt(ss / (k - 1)) : NAN;
    /* Finite values whose sum or squared deviations leave the range of a
     * double: the sum of 1e308 and 1.5e308 gave a mean of inf (printed null),
     * deviations below 1e-154 squared to 0 (a std of 0 for 1e-320 and
     * 3e-320). Then in units of the largest |value| (exact scaling up to
     * rounding); ordinary values keep the plain sums, to the bit. */
    if (k > 0 && (!isfinite(m->mean) || !isfinite(ss) || (dmax > 0 && dmax < 1e-150))) {
        double big = 0, su = 0, ssu = 0;
        for (int i = 0; i < n; i++)
            if (isfinite(v[i]))
                big = fmax(big, fabs(v[i]));
        for (int i = 0; i < n; i++)
            if (isfinite(v[i]))
                su += v[i] / big;
        const double mu = su / k;
        for (int i = 0; i < n; i++)
            if (isfinite(v[i]))
                ssu += (v[i] / big - mu) * (v[i] / big - mu);
        m->mean = mu * big;
        m->std = k > 1 ? sqrt(ssu / (k - 1)) * big : NAN;
    }
}

typedef struct row_key {
    const char *key;
    double point;
    long case_id, row;
} row_key;

static int cmp_row_key(const void *a, const void *b)
{
    const row_key *x = a, *y = b;
    int c = strcmp(x->key, y->key);
    if (c)
        return c;
    int nx = isnan(x->point), ny = isnan(y->point);
    if (nx != ny)
        return nx - ny;
    if (!nx && x->point != y->point)
        return x->point < y->point ? -1 : 1;
    return (x->case_id > y->case_id) - (x->case_id < y->case_id);
}

typedef struct group_ref {
    long first_case;
    gw_stats_group g;
} group_ref;

static int cmp_group_ref(const void *a, const void *b)
{
    const group_ref *x = a, *y = b;
    return (x->first_case > y->first_case) - (x->first_case < y->first_case);
}

/* Order the groups by their first case (the config's grid order). */
static int sort_groups(gw_stats_group *g, int n, const gw_stats_table *t)
{
    group_ref *ref = malloc((size_t)n * sizeof *ref);
    if (!ref)
        return GW_ENOMEM;
    for (int i = 0; i < n; i++)
        ref[i] = (group_ref){t->case_id[g[i].first], g[i]};
    qsort(ref, (size_t)n, sizeof *ref, cmp_group_ref);
    for (int i = 0; i < n; i++)
        g[i] = ref[i].g;
    free(ref);
    return GW_OK;
}

static double cell(const gw_stats_table *t, long row, int col)
{
    return col >= 0 ? t->val[row * t->ncols + col] : NAN;
}

static int group_stats(const gw_stats_table *t, double criterion, gw_stats_group *g)
{
    const int cb = gw_stats_table_col(t, "bounced"), cen = gw_stats_table_col(t, "e_n"),
              ce = gw_stats_table_col(t, "e"), ca = gw_stats_table_col(t, "alpha_r"),
              cp = gw_stats_table_col(t, "penetration"),
              cpr = gw_stats_table_col(t, "penetration_rm"),
              cl = gw_stats_table_col(t, "block_loss_first_contact"),
              cd = gw_stats_table_col(t, "dissipated_first_contact"),
              cee = gw_stats_table_col(t, "energy_error"),
              cx = gw_stats_table_col(t, "x_impact"), cfo = gw_stats_table_col(t, "fell_off"),
              cf[3] = {gw_stats_table_col(t, "e_n_first"), gw_stats_table_col(t, "e_first"),
                       gw_stats_table_col(t, "alpha_r_first")};
    int n = g->n;
    double *w = malloc(11 * (size_t)n * sizeof *w);
    g->run_e_n = malloc(3 * (size_t)n * sizeof *g->run_e_n);
    if (!w || !g->run_e_n) {
        free(w);
        return GW_ENOMEM;
    }
    g->run_e = g->run_e_n + n;
    g->run_share = g->run_e + n;
    double *en = w, *e = w + n, *al = w + 2 * n, *pen = w + 3 * n, *penrm = w + 4 * n,
           *loss = w + 5 * n, *dis = w + 6 * n, *reb = w + 7 * n, *fst = w + 8 * n;
    double sen = 0, se = 0, men = 0, me = 0;
    int nen = 0, ne = 0;
    g->n_valid = g->n_bounced = g->n_fell_off = 0;
    g->energy_error_max = NAN;
    double xlo = INFINITY, xhi = -INFINITY, rm = NAN;
    for (int k = 0; k < n; k++) {
        long r = g->rows[k];
        double x = cell(t, r, cx), pm = cell(t, r, cp), prm = cell(t, r, cpr);
        if (isfinite(x))
            xlo = fmin(xlo, x), xhi = fmax(xhi, x);
        if (isnan(rm) && isfinite(pm) && isfinite(prm) && pm > 0 && prm > 0)
            rm = pm / prm;
        double b = cell(t, r, cb);
        int bounced = b == 1;
        g->n_valid += !isnan(b);
        g->n_bounced += bounced;
        g->n_fell_off += cfo >= 0 && cell(t, r, cfo) == 1; /* (no column: none recorded) */
        en[k] = bounced ? cell(t, r, cen) : NAN;
        e[k] = bounced ? cell(t, r, ce) : NAN;
        al[k] = bounced ? cell(t, r, ca) : NAN;
        for (int q = 0; q < 3; q++)
            fst[q * n + k] = bounced ? cell(t, r, cf[q]) : NAN;
        reb[k] = bounced ? e[k] * e[k] : b == 0 ? 0 : NAN;
        pen[k] = cell(t, r, cp);
        penrm[k] = cell(t, r, cpr);
        loss[k] = cell(t, r, cl);
        dis[k] = cell(t, r, cd);
        double ee = cell(t, r, cee);
        if (isfinite(ee) && !(ee <= g->energy_error_max))
            g->energy_error_max = ee;
        if (isfinite(en[k])) {
            sen += en[k];
            nen++;
            men += (en[k] - men) / nen;
        }
        if (isfinite(e[k])) {
            se += e[k];
            ne++;
            me += (e[k] - me) / ne;
        }
        /* the plain sums; the updated means where a sum overflows (values
         * near 1e308: the running mean read inf) */
        g->run_e_n[k] = nen ? (isfinite(sen) ? sen / nen : men) : NAN;
        g->run_e[k] = ne ? (isfinite(se) ? se / ne : me) : NAN;
        g->run_share[k] = (double)g->n_bounced / (k + 1);
    }
    g->x_span = xhi >= xlo ? xhi - xlo : NAN;
    g->x_span_rm = g->x_span / rm;
    g->share = n > 0 ? (double)g->n_bounced / n : NAN;
    g->share_decided = g->n_valid ? (double)g->n_bounced / g->n_valid : NAN;
    g->share_high = n > 0 ? (double)(g->n_bounced + n - g->n_valid) / n : NAN;
    g->bouncing = g->share >= criterion;
    g->verdict_certain = g->bouncing || g->share_high < criterion;
    gw_stats_moment_of(en, n, &g->e_n);
    gw_stats_moment_of(e, n, &g->e);
    gw_stats_moment_of(al, n, &g->alpha_r);
    gw_stats_moment_of(pen, n, &g->penetration);
    gw_stats_moment_of(penrm, n, &g->penetration_rm);
    gw_stats_moment_of(loss, n, &g->block_loss);
    gw_stats_moment_of(dis, n, &g->dissipated);
    gw_stats_moment_of(reb, n, &g->rebound_energy);
    gw_stats_moment_of(fst, n, &g->e_n_first);
    gw_stats_moment_of(fst + n, n, &g->e_first);
    gw_stats_moment_of(fst + 2 * n, n, &g->alpha_r_first);
    /* stable from k on: every running mean from k to n within 5 % of the last */
    double fin = g->run_e[n - 1];
    g->k_stable_e = 0;
    if (isfinite(fin) && fin != 0) {
        int k = n;
        while (k > 1 && fabs(g->run_e[k - 2] - fin) <= 0.05 * fabs(fin))
            k--;
        g->k_stable_e = k;
    }
    free(w);
    return GW_OK;
}

void gw_stats_groups_free(gw_stats_groups *gs)
{
    if (!gs)
        return;
    for (int i = 0; i < gs->n; i++) {
        free(gs->g[i].rows);
        free(gs->g[i].run_e_n);
    }
    free(gs->g);
    memset(gs, 0, sizeof *gs);
}

int gw_stats_table_same(const gw_stats_table *t, long ra, long rb, int key)
{
    if (!t || key < 0 || key >= t->ngrid || ra < 0 || rb < 0 || ra >= t->nrows || rb >= t->nrows ||
        !t->grid_num || !t->grid_value) /* (a table filled by hand without its arrays) */
        return 0;
    const double a = t->grid_num[ra * t->ngrid + key], b = t->grid_num[rb * t->ngrid + key];
    if (!isnan(a) || !isnan(b))
        return a == b;
    return strcmp(t->grid_value[ra * t->ngrid + key], t->grid_value[rb * t->ngrid + key]) == 0;
}

/* The group key of row r: its grouping grid values joined by '\x1f', numbers
 * printed back in %.17g (as check_combinations does): the rows "2" and "2.0"
 * of one R_b/R_m made two groups of one point each, with the same keys. */
static char *row_key_string(const gw_stats_table *t, const gw_stats_groups *gs, long r)
{
    size_t len = 1;
    for (int k = 0; k < gs->nkeys; k++)
        len += strlen(t->grid_value[r * t->ngrid + gs->key[k]]) + 32;
    char *s = malloc(len);
    size_t used = 0;
    for (int k = 0; s && k < gs->nkeys; k++) {
        const double v = t->grid_num[r * t->ngrid + gs->key[k]];
        if (isnan(v))
            used += (size_t)gw_snprintf(s + used, len - used, "s%s\x1f", t->grid_value[r * t->ngrid + gs->key[k]]);
        else /* -0 and 0 are one value */
            used += (size_t)gw_snprintf(s + used, len - used, "n%.17g\x1f", v == 0 ? 0.0 : v);
    }
    if (s)
        s[used] = '\0';
    return s;
}

/* A table as the groups read it: a table filled by hand with rows and no
 * arrays, more grid keys than the struct holds or a negative row count read
 * past them (SIGSEGV) or asked calloc for SIZE_MAX ("out of memory"). */
int stats_table_shape(const gw_stats_table *t, gw_err *err)
{
    if (t->ngrid < 0 || t->ngrid > GW_STATS_MAX_KEYS || t->nparams < 0 || t->nparams > GW_STATS_MAX_KEYS ||
        t->ncols < 0 || t->nrows < 0)
        return gw_err_set(err, GW_EINVAL, "stats table: %d grid keys, %d params, %d columns and %ld rows (keys and "
                          "params in [0, %d], columns and rows >= 0)", t->ngrid, t->nparams, t->ncols, t->nrows,
                          GW_STATS_MAX_KEYS);
    const int rows = t->nrows > 0;
    if ((t->ncols > 0 && !t->col_name) || (rows && !t->case_id) || (rows && t->ncols > 0 && !t->val) ||
        (rows && t->ngrid > 0 && (!t->grid_value || !t->grid_num)))
        return gw_err_set(err, GW_EINVAL, "stats table: %ld rows of %d grid keys and %d columns without their arrays",
                          t->nrows, t->ngrid, t->ncols);
    for (int k = 0; k < t->ngrid; k++)
        if (!t->grid_name[k])
            return gw_err_set(err, GW_EINVAL, "stats table: grid key %d has no name", k);
    for (int k = 0; k < t->nparams; k++)
        if (!t->param_name[k] || !t->param_value[k])
            return gw_err_set(err, GW_EINVAL, "stats table: param %d has no name or value", k);
    for (int c = 0; c < t->ncols; c++)
        if (!t->col_name[c])
            return gw_err_set(err, GW_EINVAL, "stats table: column %d has no name", c);
    for (long i = 0; i < t->nrows * t->ngrid; i++)
        if (!t->grid_value[i])
            return gw_err_set(err, GW_EINVAL, "stats table: row %ld has no value of grid key %ld", i / t->ngrid,
                              i % t->ngrid);
    return GW_OK;
}

int gw_stats_groups_make(const gw_stats_table *t, double criterion, gw_stats_groups *gs,
                         gw_err *err)
{
    if (!t || !gs) {
        if (gs)
            memset(gs, 0, sizeof *gs);
        return gw_err_set(err, GW_EINVAL, "gw_stats_groups_make: %s is NULL", !t ? "t" : "gs");
    }
    memset(gs, 0, sizeof *gs);
    char xs[32]; /* the value as given: 1.0000001 was "1 is not in (0, 1]" */
    if (!(criterion > 0 && criterion <= 1))
        return gw_err_set(err, GW_EINVAL, "criterion: %s is not in (0, 1]", gw_num_text(xs, sizeof xs, criterion));
    const int shape = stats_table_shape(t, err);
    if (shape != GW_OK)
        return shape;
    gs->criterion = criterion;
    gs->point_key = gw_stats_table_key(t, "point");
    for (int k = 0; k < t->ngrid; k++)
        if (k != gs->point_key)
            gs->key[gs->nkeys++] = k;
    row_key *rk = calloc((size_t)t->nrows, sizeof *rk);
    gs->g = calloc((size_t)t->nrows, sizeof *gs->g);
    int rc = rk && gs->g ? GW_OK : GW_ENOMEM;
    for (long r = 0; rc == GW_OK && r < t->nrows; r++) {
        rk[r] = (row_key){row_key_string(t, gs, r),
                          gs->point_key >= 0 ? t->grid_num[r * t->ngrid + gs->point_key] : NAN,
                          t->case_id[r], r};
        if (!rk[r].key)
            rc = GW_ENOMEM;
    }
    if (rc == GW_OK)
        qsort(rk, (size_t)t->nrows, sizeof *rk, cmp_row_key);
    for (long a = 0, b; rc == GW_OK && a < t->nrows; a = b) {
        for (b = a + 1; b < t->nrows && strcmp(rk[b].key, rk[a].key) == 0; b++)
            ;
        gw_stats_group *g = &gs->g[gs->n++];
        g->n = (int)(b - a);
        g->rows = malloc((size_t)g->n * sizeof *g->rows);
        if (!g->rows) {
            rc = GW_ENOMEM;
            break;
        }
        g->first = rk[a].row;
        for (long i = a; i < b; i++) {
            g->rows[i - a] = rk[i].row;
            if (t->case_id[rk[i].row] < t->case_id[g->first])
                g->first = rk[i].row;
        }
        rc = group_stats(t, criterion, g);
    }
    for (long r = 0; rk && r < t->nrows; r++)
        free((void *)rk[r].key);
    free(rk);
    if (rc == GW_OK)
        rc = sort_groups(gs->g, gs->n, t);
    if (rc != GW_OK) {
        gw_stats_groups_free(gs);
        return gw_err_set(err, rc, "%s: out of memory", t->path);
    }
    return GW_OK;
}

double gw_stats_binary_loss(double r, int sphere)
{
    if (!(r > 0)) /* no ratio of radii: r = -5 gave the loss of r = 5 (discs) */
        return NAN;
    double m = sphere ? r * r * r : r * r;
    /* a block no heavier than its target stops and turns back inside the
     * contact: its smallest energy there is 0. Past 1e100, 4 m / (1 + m)^2 is
     * 4 / m to 1e-100: (1 + m)^2 overflowed above r = 1.3e154 (discs) and an
     * infinite ratio gave inf / inf, NaN where the loss tends to 0 */
    return m <= 1 ? 1.0 : m > 1e100 ? 4 / m : 4 * m / ((1 + m) * (1 + m));
}
