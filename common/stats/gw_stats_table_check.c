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

/* A row's file named by a KEY_fnv1a64 column, for sorting by (file, row). */
typedef struct file_row {
    const char *file;
    long r;
    unsigned long long h;
} file_row;

static int file_row_cmp(const void *pa, const void *pb)
{
    const file_row *a = pa, *b = pb;
    const int c = strcmp(a->file, b->file);
    return c ? c : (a->r > b->r) - (a->r < b->r);
}

/* The rows that name one file carry one content hash: a sweep reads one
 * version of each file (a file changed while it ran stops it, a rerun over a
 * changed one is refused). Checked against the '# input' line above when the
 * table has one; without it (the line removed, a table joined by hand from
 * sweeps over two versions of a sample under one name) the rows of both
 * versions were grouped as one sample, their points counted together. */
int gw_stats_table_check_file_hashes(const gw_stats_table *t, gw_err *err)
{
    if (t->nhash < 2 || t->nrows < 2)
        return GW_OK;
    file_row *fr = malloc((size_t)t->nrows * sizeof *fr);
    if (!fr)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", t->path);
    int rc = GW_OK;
    for (int j = 1; j < t->nhash && rc == GW_OK; j++) {
        const char *col = t->hash_name[j];
        const size_t kl = strlen(col) - 8;
        int gi = -1, pi = -1;
        for (int i = 0; i < t->ngrid && gi < 0; i++)
            if (strlen(t->grid_name[i]) == kl && strncmp(t->grid_name[i], col, kl) == 0)
                gi = i;
        for (int i = 0; gi < 0 && i < t->nparams && pi < 0; i++)
            if (strlen(t->param_name[i]) == kl && strncmp(t->param_name[i], col, kl) == 0)
                pi = i;
        if (gi < 0 && pi < 0)
            continue;
        for (long r = 0; r < t->nrows; r++)
            fr[r] = (file_row){gi >= 0 ? t->grid_value[r * t->ngrid + gi] : t->param_value[pi], r,
                               t->row_hash[r * t->nhash + j]};
        qsort(fr, (size_t)t->nrows, sizeof *fr, file_row_cmp);
        for (long q = 1, first = 0; q < t->nrows && rc == GW_OK; q++) {
            if (strcmp(fr[q].file, fr[first].file) != 0) {
                first = q;
                continue;
            }
            if (fr[q].h != fr[first].h) {
                const long a = fr[first].r, b = fr[q].r;
                rc = gw_err_set(err, GW_EFORMAT, "%s:%ld: case %ld read %.*s '%s' with content fnv1a64 %016llx, but "
                                "case %ld (line %ld) read it with %016llx: a sweep reads one version of each file "
                                "(rows of sweeps over two versions of it, joined?)", t->path, t->row_line[b],
                                t->case_id[b], (int)kl, col, fr[q].file, fr[q].h, t->case_id[a], t->row_line[a],
                                fr[first].h);
            }
        }
    }
    free(fr);
    return rc;
}

/* A row of one sample and its penetration / penetration_rm, for sorting by
 * (sample, ratio). */
typedef struct rm_row {
    const char *file;
    long r;
    double rm;
} rm_row;

static int rm_row_cmp(const void *pa, const void *pb)
{
    const rm_row *a = pa, *b = pb;
    const int c = strcmp(a->file, b->file);
    return c ? c : (a->rm > b->rm) - (a->rm < b->rm);
}

/* penetration_rm is penetration over the sample's R_m (layer_setup.c), one
 * R_m for every row of one sample: the rows that name one sample (its value
 * in the grid or a '# param' line; a table that names none is not checked,
 * its rows may be of several) give one penetration / penetration_rm, to
 * 1e-9 (both written with 17 digits: rounding is 1e-16; the stored diagrams
 * agree to 1e-15). One of the two cells edited was read: the diagram reads
 * penetration_rm and x_span_rm divides by the first row's ratio, so the edit
 * of one cell moved the diagram or every group's span silently. The R_m most
 * rows of the sample give is its own; the first row (in the table's order)
 * giving another is refused. */
int gw_stats_table_check_rm(const gw_stats_table *t, gw_err *err)
{
    const int cp = gw_stats_table_col(t, "penetration"), cq = gw_stats_table_col(t, "penetration_rm");
    int gi = -1, pi = -1;
    for (int i = 0; i < t->ngrid && gi < 0; i++)
        if (strcmp(t->grid_name[i], "sample") == 0)
            gi = i;
    for (int i = 0; gi < 0 && i < t->nparams && pi < 0; i++)
        if (strcmp(t->param_name[i], "sample") == 0)
            pi = i;
    if (cp < 0 || cq < 0 || (gi < 0 && pi < 0) || t->nrows < 1)
        return GW_OK;
    char what[384];
    for (long r = 0; r < t->nrows; r++) { /* one of the two zero */
        const double pen = t->val[r * t->ncols + cp], prm = t->val[r * t->ncols + cq];
        if (isfinite(pen) && isfinite(prm) && (pen == 0) != (prm == 0))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: column penetration_rm: %.17g where penetration is %.17g: "
                              "penetration_rm is penetration over the sample's R_m (case %ld; a row no run writes: "
                              "edited by hand?)", t->path, t->row_line[r], prm, pen, t->case_id[r]);
    }
    rm_row *fr = malloc((size_t)t->nrows * sizeof *fr);
    if (!fr)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", t->path);
    long m = 0;
    for (long r = 0; r < t->nrows; r++) {
        const double pen = t->val[r * t->ncols + cp], prm = t->val[r * t->ncols + cq];
        if (isfinite(pen) && isfinite(prm) && pen > 0 && prm > 0)
            fr[m++] = (rm_row){gi >= 0 ? t->grid_value[r * t->ngrid + gi] : t->param_value[pi], r, pen / prm};
    }
    qsort(fr, (size_t)m, sizeof *fr, rm_row_cmp);
    long bad = -1, bad_ref = -1, bad_n = 0;
    for (long g0 = 0, g1; g0 < m; g0 = g1) { /* each sample's rows [g0, g1), by ratio */
        for (g1 = g0 + 1; g1 < m && strcmp(fr[g1].file, fr[g0].file) == 0; g1++)
            ;
        long best = g0, best_n = 0; /* the largest run of one R_m */
        for (long a = g0, b; a < g1; a = b) {
            for (b = a + 1; b < g1 && fr[b].rm - fr[a].rm <= 1e-9 * fr[a].rm; b++)
                ;
            if (b - a > best_n)
                best = a, best_n = b - a;
        }
        for (long q = g0; q < g1; q++) /* the first row outside it, in the table's order */
            if ((q < best || q >= best + best_n) && (bad < 0 || fr[q].r < fr[bad].r))
                bad = q, bad_ref = best, bad_n = best_n;
    }
    int rc = GW_OK;
    if (bad >= 0) {
        const long r = fr[bad].r;
        gw_snprintf(what, sizeof what, "%.17g with penetration %.17g gives the sample's R_m as %.9g m, where %ld "
                    "other row(s) of sample '%s' give %.9g m", t->val[r * t->ncols + cq], t->val[r * t->ncols + cp],
                    fr[bad].rm, bad_n, fr[bad].file, fr[bad_ref].rm);
        rc = gw_err_set(err, GW_EFORMAT, "%s:%ld: column penetration_rm: %s: penetration_rm is penetration over the "
                        "sample's R_m (case %ld; a row no run writes: edited by hand?)", t->path, t->row_line[r], what,
                        t->case_id[r]);
    }
    free(fr);
    return rc;
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

/* ------------------------------------------------ one pile under two names ---
 * A sweep of a build before the sample check by content (layer_sweep_model.c)
 * ran a grid listing a copy of a sample, or two layer-make outputs of one
 * seed and options, as two samples: every case twice, and the binary check
 * counted each point twice (n 8 where 4 are distinct). The file hashes of the
 * rows differ (a sample's comments record the command that made it), and the
 * table does not hold the particles; but a run is deterministic, and two
 * distinct piles part in their model cells from the first step (measured on
 * two 20-disc samples of seeds 2 and 3: energy_error 2.416e-14 and 2.400e-14
 * after 1 ms of free fall above the pile, 9.47e-6 and 8.88e-6 after one step
 * in contact). Two samples are taken for one pile when every row of each
 * agrees, in every model cell and every other grid value, with a row of the
 * other (one row alike by chance is not enough). */

/* The grid key whose values name the file each case read: the one a hash
 * column KEY_fnv1a64 names, else "sample" (a table before the hash columns);
 * -1 when the table has none. */
static int file_key(const gw_stats_table *t)
{
    for (int j = 1; j < t->nhash; j++) {
        const size_t kl = strlen(t->hash_name[j]) - 8;
        for (int i = 0; i < t->ngrid; i++)
            if (strlen(t->grid_name[i]) == kl && strncmp(t->grid_name[i], t->hash_name[j], kl) == 0)
                return i;
    }
    return gw_stats_table_key(t, "sample");
}

/* v's bits, -0 as 0 and every NaN one value (as a table prints them). */
static unsigned long long bits_of(double v)
{
    v = isnan(v) ? NAN : v == 0 ? 0.0 : v;
    unsigned long long b;
    memcpy(&b, &v, sizeof b);
    return b;
}

typedef struct outcome_row {
    unsigned long long hash; /* of the row's cells but the file key's */
    long sid, row;           /* sid: its file value's rank among the table's */
} outcome_row;

static int cmp_outcome(const void *pa, const void *pb)
{
    const outcome_row *a = pa, *b = pb;
    if (a->hash != b->hash)
        return a->hash < b->hash ? -1 : 1;
    if (a->sid != b->sid)
        return a->sid < b->sid ? -1 : 1;
    return (a->row > b->row) - (a->row < b->row);
}

typedef struct named_row {
    const char *value;
    long row;
} named_row;

static int cmp_named(const void *pa, const void *pb)
{
    const named_row *a = pa, *b = pb;
    const int c = strcmp(a->value, b->value);
    return c ? c : (a->row > b->row) - (a->row < b->row);
}

/* Rows ra and rb agree in every cell but grid key skip's. */
static int rows_agree(const gw_stats_table *t, long ra, long rb, int skip)
{
    for (int i = 0; i < t->ngrid; i++)
        if (i != skip && !gw_stats_table_same(t, ra, rb, i))
            return 0;
    for (int c = 0; c < t->ncols; c++)
        if (bits_of(t->val[ra * t->ncols + c]) != bits_of(t->val[rb * t->ncols + c]))
            return 0;
    return 1;
}

/* A pair of samples with a row alike: (a, b) by rank, a < b, its first rows. */
typedef struct pile_pair {
    long a, b, ra, rb;
} pile_pair;

static int cmp_pair(const void *pa, const void *pb)
{
    const pile_pair *x = pa, *y = pb;
    if (x->a != y->a)
        return x->a < y->a ? -1 : 1;
    if (x->b != y->b)
        return x->b < y->b ? -1 : 1;
    return (x->ra > y->ra) - (x->ra < y->ra);
}

/* The first pair of samples that are one pile (above), into *pa and *pb
 * (rows of each, the first alike; -1: none), given the rows ranked (o, by
 * outcome) and each sample's row count cnt[sid]. GW_OK or GW_ENOMEM. */
static int find_pile_pair(const gw_stats_table *t, int kf, const outcome_row *o, const long *cnt, long *pa, long *pb)
{
    *pa = *pb = -1;
    pile_pair *p = malloc((size_t)t->nrows * sizeof *p);
    if (!p)
        return GW_ENOMEM;
    long np = 0;
    for (long a = 0, b; a < t->nrows; a = b) /* a run of one hash: each row against its first */
        for (b = a + 1; b < t->nrows && o[b].hash == o[a].hash; b++)
            if (o[b].sid != o[a].sid && rows_agree(t, o[a].row, o[b].row, kf))
                p[np++] = (pile_pair){o[a].sid, o[b].sid, o[a].row, o[b].row};
    qsort(p, (size_t)np, sizeof *p, cmp_pair);
    long best = -1;
    for (long i = 0, j; i < np; i = j) {
        for (j = i; j < np && p[j].a == p[i].a && p[j].b == p[i].b; j++)
            ;
        if (j - i == cnt[p[i].a] && j - i == cnt[p[i].b] && (best < 0 || p[i].ra < p[best].ra))
            best = i;
    }
    if (best >= 0)
        *pa = p[best].ra, *pb = p[best].rb;
    free(p);
    return GW_OK;
}

/* No two samples of the table are one pile (above): GW_OK, GW_EFORMAT naming
 * both samples and their first rows alike, GW_ENOMEM. */
static int check_same_piles(const gw_stats_table *t, gw_err *err)
{
    const int kf = file_key(t);
    if (kf < 0 || t->nrows < 2)
        return GW_OK;
    const size_t n = (size_t)t->nrows;
    named_row *nr = malloc(n * sizeof *nr);
    outcome_row *o = malloc(n * sizeof *o);
    long *cnt = calloc(n, sizeof *cnt), ra = -1, rb = -1, nsamples = 0;
    int rc = nr && o && cnt ? GW_OK : GW_ENOMEM;
    for (long r = 0; rc == GW_OK && r < t->nrows; r++)
        nr[r] = (named_row){t->grid_value[r * t->ngrid + kf], r};
    if (rc == GW_OK)
        qsort(nr, n, sizeof *nr, cmp_named);
    for (long i = 0; rc == GW_OK && i < t->nrows; i++) {
        /* a sample spelt as a number (grid_num set) is compared as the reader does */
        nsamples += i > 0 && !gw_stats_table_same(t, nr[i].row, nr[i - 1].row, kf);
        o[nr[i].row].sid = nsamples;
        cnt[nsamples]++;
    }
    for (long r = 0; rc == GW_OK && r < t->nrows; r++) {
        unsigned long long h = GW_FNV1A64_INIT;
        for (int i = 0; i < t->ngrid; i++) {
            const double v = t->grid_num[r * t->ngrid + i];
            const char *txt = t->grid_value[r * t->ngrid + i];
            if (i == kf)
                continue;
            if (isnan(v))
                h = gw_fnv1a64(h, txt, strlen(txt) + 1);
            else {
                const unsigned long long b = bits_of(v);
                h = gw_fnv1a64(h, &b, sizeof b);
            }
        }
        for (int c = 0; c < t->ncols; c++) {
            const unsigned long long b = bits_of(t->val[r * t->ncols + c]);
            h = gw_fnv1a64(h, &b, sizeof b);
        }
        o[r].hash = h, o[r].row = r;
    }
    if (rc == GW_OK && nsamples > 0) {
        qsort(o, n, sizeof *o, cmp_outcome);
        rc = find_pile_pair(t, kf, o, cnt, &ra, &rb);
    }
    free(nr);
    free(o);
    free(cnt);
    if (rc != GW_OK)
        return gw_err_set(err, rc, "%s: out of memory", t->path);
    if (ra < 0)
        return GW_OK;
    long same = 0;
    for (long r = 0; r < t->nrows; r++)
        same += gw_stats_table_same(t, r, ra, kf);
    const char *key = t->grid_name[kf];
    return gw_err_set(err, GW_EFORMAT, "%s:%ld: %s '%s' holds the pile of %s '%s' (line %ld) under another name: "
                      "each of their %ld rows agrees in every cell with a row of the other (cases %ld and %ld the "
                      "first), so every point would count twice (a copy of a sample, or layer-make run twice with "
                      "one seed and options, listed in a sweep of a build before the sweep compared samples by "
                      "content); rerun the sweep listing one of them", t->path, t->row_line[rb], key,
                      t->grid_value[rb * t->ngrid + kf], key, t->grid_value[ra * t->ngrid + kf], t->row_line[ra],
                      same, t->case_id[ra], t->case_id[rb]);
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
    if (rc == GW_OK)
        rc = check_same_piles(t, err);
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
