/*
 * gw_stats_table_check.c: a layer sweep table's checks over all its rows: a
 * case number appearing once, two cases never with the same grid values, a
 * bouncing row with its e_n, e, alpha_r (B.16-B.18; or their _first), a table
 * with the sweep's first line holding every case of its grid with its case's
 * grid values ("# grid" lines), and each row's config and input hashes those
 * its "# param" and "# input" lines give. A table stitched from two sweeps, cut,
 * or edited by hand would change the groups' statistics silently.
 * Units: as in the table.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_stats.h"
#include "gw_locale.h"
#include "gw_stats_impl.h"

/* The rows' hashes (the cells after the model's columns): each row's case
 * config hash is the one its grid values, the model and the "# param" lines
 * give, and the hash of the file it read is the "# input" line's for that
 * file. A row pasted from a sweep over the same grid with other [params] was
 * read as this sweep's. Run after the grid checks, which name an edited grid
 * cell more precisely. */
int gw_stats_table_check_hashes(const gw_stats_table *t, gw_err *err)
{
    const char *names[2 * GW_STATS_MAX_KEYS], *values[2 * GW_STATS_MAX_KEYS];
    for (long r = 0; r < t->nrows; r++) {
        int nk = 0;
        for (int i = 0; i < t->ngrid; i++)
            names[nk] = t->grid_name[i], values[nk++] = t->grid_value[r * t->ngrid + i];
        for (int i = 0; i < t->nparams; i++)
            names[nk] = t->param_name[i], values[nk++] = t->param_value[i];
        const long k = t->case_id[r], ln = t->row_line[r];
        for (int j = 0; j < t->nhash; j++) {
            const unsigned long long h = t->row_hash[r * t->nhash + j];
            const char *col = t->hash_name[j];
            if (j == 0) {
                const unsigned long long want = gw_case_config_hash(t->model, nk, names, values);
                if (h != want)
                    return gw_err_set(err, GW_EFORMAT, "%s:%ld: case %ld ran under config hash %016llx, but the "
                                      "table's model and '# param' lines give %016llx for it (a row of a sweep with "
                                      "other [params] or another model)", t->path, ln, k, h, want);
                continue;
            }
            /* KEY_fnv1a64: the file the row's KEY names, and its '# input' line */
            const size_t kl = strlen(col) - 8;
            const char *file = NULL;
            for (int i = 0; i < nk && !file; i++)
                if (strlen(names[i]) == kl && strncmp(names[i], col, kl) == 0)
                    file = values[i];
            for (int i = 0; file && i < t->ninputs; i++)
                if (strlen(t->input_key[i]) == kl && strncmp(t->input_key[i], col, kl) == 0 &&
                    strcmp(t->input_value[i], file) == 0 && t->input_hash[i] != h)
                    return gw_err_set(err, GW_EFORMAT, "%s:%ld: case %ld read %.*s '%s' with content fnv1a64 "
                                      "%016llx, but the table's '# input' line gives %016llx (a row of a sweep over "
                                      "another version of the file, or one that read it while it was changed)",
                                      t->path, ln, k, (int)kl, col, file, h, t->input_hash[i]);
        }
    }
    return GW_OK;
}

static int cmp_case(const void *a, const void *b)
{
    long x = *(const long *)a, y = *(const long *)b;
    return (x > y) - (x < y);
}

/* Value j (0-based) of a "# grid" list: into out (size n); 0 when absent. */
static int list_value(const char *list, long j, char *out, size_t n)
{
    const char *p = list + strlen(list) + 1;
    for (long k = 0; k < j; k++) {
        p = strchr(p, ',');
        if (!p)
            return 0;
        p++;
    }
    while (*p == ' ' || *p == '\t')
        p++;
    size_t l = strcspn(p, ",");
    while (l > 0 && (p[l - 1] == ' ' || p[l - 1] == '\t'))
        l--;
    if (l == 0 || l >= n)
        return 0;
    memcpy(out, p, l);
    out[l] = '\0';
    return 1;
}

static long list_count(const char *list)
{
    long n = 1;
    for (const char *p = list + strlen(list) + 1; (p = strchr(p, ',')); p++)
        n++;
    return n;
}

/* The grid values of case k from the "# grid" lines ("a = 1, b = 2"), the
 * last key fastest as a sweep numbers its cases. */
static void case_values(const gw_stats_table *t, long k, char *buf, size_t n)
{
    long idx[GW_STATS_MAX_KEYS];
    for (int i = t->ngrid - 1; i >= 0; i--) {
        long c = list_count(t->grid_list[i]);
        idx[i] = k % c;
        k /= c;
    }
    size_t w = 0;
    buf[0] = '\0';
    for (int i = 0; i < t->ngrid && w < n; i++) {
        char v[256];
        if (!list_value(t->grid_list[i], idx[i], v, sizeof v))
            gw_snprintf(v, sizeof v, "?");
        w += (size_t)gw_snprintf(buf + w, n - w, "%s%s = %s", i ? ", " : "", t->grid_list[i], v);
    }
}

/* A table written by a sweep holds every case of its grid: its first line
 * says "N of C cases" and a sweep writes it when all C have run. A row
 * deleted by hand, the table cut short or rows pasted in changed the groups'
 * statistics silently (a group of five points read as four). With the grid
 * lines, each row must also carry its case's grid values (an edited cell
 * moved a point into another group). Tables without the sweep's first line
 * (made by hand) are read as they are. */
int gw_stats_table_check_complete(const gw_stats_table *t, gw_err *err)
{
    int nl = 0;
    while (nl < GW_STATS_MAX_KEYS && t->grid_list[nl])
        nl++;
    if (nl > 0) {
        if (t->sweep_cases < 0)
            return gw_err_set(err, GW_EFORMAT, "%s: '# grid' lines without the sweep's first line (an edited "
                              "header)", t->path);
        long prod = 1;
        int same = nl == t->ngrid;
        for (int i = 0; same && i < nl; i++) {
            same = strcmp(t->grid_list[i], t->grid_name[i]) == 0;
            prod *= list_count(t->grid_list[i]);
            if (prod > 1000000000L)
                same = 0;
        }
        if (!same || prod != t->sweep_cases)
            return gw_err_set(err, GW_EFORMAT, "%s: the '# grid' lines (%d keys) do not describe the table's %d grid "
                              "columns and %ld cases (an edited header)", t->path, nl, t->ngrid, t->sweep_cases);
    }
    if (t->sweep_cases < 0)
        return GW_OK;
    const long c = t->sweep_cases;
    /* The cases are marked up to m = min(C, rows + 1) only: with fewer rows
     * than C a case below m is missing, and the count C comes from the file.
     * A first line saying "3 of 1000000000000 cases" allocated 1 TB (an
     * AddressSanitizer abort, "out of memory" exit 1 in release); 5e9 cases
     * took 15 s and 5 GB of address space to be refused. */
    const long m = t->nrows < c ? t->nrows + 1 : c;
    char *seen = calloc((size_t)m, 1);
    long *high = malloc(((size_t)t->nrows + 1) * sizeof *high), nhigh = 0;
    if (!seen || !high) {
        free(seen), free(high);
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", t->path);
    }
    int rc = GW_OK;
    for (long r = 0; r < t->nrows && rc == GW_OK; r++) {
        long k = t->case_id[r];
        if (k >= c) {
            rc = gw_err_set(err, GW_EFORMAT, "%s: case %ld is beyond the %ld cases of the sweep its first line "
                            "names (a row from another sweep)", t->path, k, c);
            break;
        }
        if (k < m)
            seen[k] = 1;
        else
            high[nhigh++] = k;
        for (int i = 0; nl > 0 && i < t->ngrid; i++) {
            long cnt = 1;
            for (int j = i + 1; j < t->ngrid; j++)
                cnt *= list_count(t->grid_list[j]);
            char v[256];
            const char *got = t->grid_value[r * t->ngrid + i];
            if (!list_value(t->grid_list[i], (k / cnt) % list_count(t->grid_list[i]), v, sizeof v) ||
                strcmp(v, got) != 0) {
                rc = gw_err_set(err, GW_EFORMAT, "%s: case %ld has %s = %s, but the sweep's grid gives case %ld "
                                "%s = %s (a row edited by hand)", t->path, k, t->grid_name[i], got, k,
                                t->grid_name[i], v);
                break;
            }
        }
    }
    if (rc == GW_OK && (t->nrows != c || t->sweep_rows != c)) {
        long miss = 0, first = -1;
        for (long k = 0; k < m; k++)
            if (!seen[k] && miss++ == 0)
                first = k;
        /* the cases in [m, C) not in the table: C - m less the distinct ones seen there */
        qsort(high, (size_t)nhigh, sizeof *high, cmp_case);
        long distinct = 0;
        for (long i = 0; i < nhigh; i++)
            distinct += i == 0 || high[i] != high[i - 1];
        miss += (c - m) - distinct;
        char vals[1024] = "";
        if (first >= 0 && nl > 0) {
            char tmp[1000];
            case_values(t, first, tmp, sizeof tmp);
            gw_snprintf(vals, sizeof vals, " (%s)", tmp);
        }
        if (first >= 0)
            rc = gw_err_set(err, GW_EFORMAT, "%s: case %ld%s is missing (%ld of the sweep's %ld cases are): the "
                            "table was cut or edited by hand (a sweep writes its table when every case has run), and "
                            "statistics over part of the grid are not the sweep's", t->path, first, vals, miss, c);
        else
            rc = gw_err_set(err, GW_EFORMAT, "%s: the first line says %ld of %ld cases, but the table holds all "
                            "%ld (an edited header)", t->path, t->sweep_rows, c, c);
    }
    free(seen);
    free(high);
    return rc;
}

/* A row's grid values as one string "key = value, ...", numbers printed back
 * in %.17g so that 1 and 1.0 are one value; NULL on out of memory. */
static char *grid_combination(const gw_stats_table *t, long r)
{
    size_t len = 1;
    for (int i = 0; i < t->ngrid; i++)
        len += strlen(t->grid_name[i]) + strlen(t->grid_value[r * t->ngrid + i]) + 40;
    char *s = malloc(len), *p = s;
    if (!s)
        return NULL;
    *p = '\0';
    for (int i = 0; i < t->ngrid; i++) {
        double v = t->grid_num[r * t->ngrid + i];
        size_t left = len - (size_t)(p - s);
        int k = isnan(v) ? gw_snprintf(p, left, "%s%s = %s", i ? ", " : "", t->grid_name[i],
                                    t->grid_value[r * t->ngrid + i])
                         : gw_snprintf(p, left, "%s%s = %.17g", i ? ", " : "", t->grid_name[i], v == 0 ? 0.0 : v);
        p += k;
    }
    return s;
}

typedef struct combo {
    char *key;
    long row;
} combo;

static int cmp_combo(const void *a, const void *b)
{
    return strcmp(((const combo *)a)->key, ((const combo *)b)->key);
}

/* No two rows with the same grid values: a sweep runs each combination once,
 * so a repeat is a table stitched from two sweeps (or a config listing a
 * value twice), and layer-stats would count the point twice. */
static int check_combinations(const gw_stats_table *t, gw_err *err)
{
    if (t->ngrid == 0 || t->nrows < 2)
        return GW_OK;
    combo *c = calloc((size_t)t->nrows, sizeof *c);
    int rc = c ? GW_OK : GW_ENOMEM;
    for (long r = 0; rc == GW_OK && r < t->nrows; r++)
        if (!(c[r].key = grid_combination(t, r)))
            rc = GW_ENOMEM;
        else
            c[r].row = r;
    if (rc == GW_OK) {
        qsort(c, (size_t)t->nrows, sizeof *c, cmp_combo);
        for (long r = 1; r < t->nrows && rc == GW_OK; r++)
            if (strcmp(c[r].key, c[r - 1].key) == 0) {
                long a = t->case_id[c[r - 1].row], b = t->case_id[c[r].row];
                rc = gw_err_set(err, GW_EFORMAT, "%s: cases %ld and %ld ran the same grid values (%s): a sweep "
                                "runs each combination once, so the table mixes two sweeps or its config listed a "
                                "value twice", t->path, a < b ? a : b, a < b ? b : a, c[r].key);
            }
    }
    for (long r = 0; c && r < t->nrows; r++)
        free(c[r].key);
    free(c);
    return rc == GW_ENOMEM ? gw_err_set(err, rc, "%s: out of memory", t->path) : rc;
}

/* Whole-table checks: a case number appears once (a table stitched from two
 * runs would count its points twice), and a bouncing point carries its e_n, e
 * and alpha_r (a NaN there would drop out of the means while the point still
 * counts in the share). */
int gw_stats_table_check_rows(const gw_stats_table *t, gw_err *err)
{
    long *ids = malloc((size_t)t->nrows * sizeof *ids);
    if (!ids)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", t->path);
    memcpy(ids, t->case_id, (size_t)t->nrows * sizeof *ids);
    qsort(ids, (size_t)t->nrows, sizeof *ids, cmp_case);
    long dup = -1;
    for (long i = 1; i < t->nrows && dup < 0; i++)
        if (ids[i] == ids[i - 1])
            dup = ids[i];
    free(ids);
    if (dup >= 0)
        return gw_err_set(err, GW_EFORMAT, "%s: case %ld appears more than once (a table of one sweep holds each case once)",
                          t->path, dup);
    int rc = check_combinations(t, err);
    if (rc != GW_OK)
        return rc;
    const int cb = gw_stats_table_col(t, "bounced");
    /* a bouncing row has its first free-flight maximum; e_n, e, alpha_r (taken
     * at T_f) are NaN when the run ended before T_f. Tables before e_n_first
     * have no such rows. */
    const int first = gw_stats_table_col(t, "e_n_first") >= 0;
    /* a sweep writes the three together: without e_n_first, e_first and
     * alpha_r_first kept, the table was read as one before them and refused
     * as "case 0 bounced but its e_n is nan" (a rebound cut before T_f) */
    const int nfirst = first + (gw_stats_table_col(t, "e_first") >= 0) + (gw_stats_table_col(t, "alpha_r_first") >= 0);
    if (nfirst > 0 && nfirst < 3)
        return gw_err_set(err, GW_EFORMAT, "%s: the header has %d of the columns e_n_first, e_first, alpha_r_first, "
                          "which a sweep writes together (a column removed by hand?)", t->path, nfirst);
    const char *const need[] = {first ? "e_n_first" : "e_n", first ? "e_first" : "e",
                                first ? "alpha_r_first" : "alpha_r"};
    for (long r = 0; cb >= 0 && r < t->nrows; r++) {
        if (t->val[r * t->ncols + cb] != 1)
            continue;
        for (int j = 0; j < 3; j++) {
            int c = gw_stats_table_col(t, need[j]);
            if (c >= 0 && !isfinite(t->val[r * t->ncols + c]))
                return gw_err_set(err, GW_EFORMAT, "%s: case %ld bounced but its %s is %g", t->path,
                                  t->case_id[r], need[j], t->val[r * t->ncols + c]);
        }
    }
    return GW_OK;
}
