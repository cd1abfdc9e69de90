/*
 * gw_stats_table.c: reading a layer sweep table (OUT/results.csv of
 * `granwave sweep` with model = layer) and the per-group statistics of
 * docs/physics.md 2.3: over the N impact points of one configuration, the mean and
 * sample standard deviation of e_n = V_nr/V_ni, e = V_r/V_i and
 * alpha_r = arccos(V_nr/V_r) (B.16-B.18; over the bouncing points, the only
 * ones where they are defined), of the penetration and of the first-contact
 * energy fractions; the bounce share and the global verdict share >= S
 * (docs/physics.md 2.5, S = 75 % in the paper); the running means over the first k
 * points (the paper's Fig. 10: how many points make the mean stable).
 * The table is read as a regular file only (gw_input_read); a case number
 * appearing twice, two cases with the same grid values, a grid value nan or
 * inf, or a bouncing row without e_n, e or alpha_r, is refused.
 * Units: as in the table (m, deg, fractions of the incident energy, R_m).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_stats.h"
#include "gw_locale.h"

const char *const gw_stats_table_required[] = {
    "x_impact", "bounced", "e_n", "e", "alpha_r", "penetration", "penetration_rm",
    "block_loss_first_contact"};
const int gw_stats_table_nrequired =
    (int)(sizeof gw_stats_table_required / sizeof gw_stats_table_required[0]);

void gw_stats_table_free(gw_stats_table *t)
{
    if (!t)
        return;
    for (int i = 0; i < t->ngrid; i++)
        free(t->grid_name[i]);
    for (int i = 0; i < t->ncols; i++)
        free(t->col_name ? t->col_name[i] : NULL);
    free(t->col_name);
    if (t->grid_value)
        for (long i = 0; i < t->nrows * t->ngrid; i++)
            free(t->grid_value[i]);
    free(t->grid_value);
    free(t->grid_num);
    free(t->val);
    free(t->case_id);
    for (int i = 0; i < t->nparams; i++) {
        free(t->param_name[i]);
        free(t->param_value[i]);
    }
    for (int i = 0; i < GW_STATS_MAX_KEYS; i++)
        free(t->grid_list[i]);
    for (int i = 0; i < 2; i++)
        free(t->hash_name[i]);
    free(t->row_hash);
    free(t->row_line);
    for (int i = 0; i < t->ninputs; i++) {
        free(t->input_key[i]);
        free(t->input_value[i]);
    }
    free(t->input_key);
    free(t->input_value);
    free(t->input_hash);
    memset(t, 0, sizeof *t);
    t->sweep_rows = t->sweep_cases = -1;
}


/* Split line in place at commas into at most max cells; returns the count
 * (max + 1 when there are more). */
static int split(char *line, char **cells, int max)
{
    int n = 0;
    for (char *p = line;;) {
        char *c = strchr(p, ',');
        if (c)
            *c = '\0';
        if (n < max)
            cells[n] = gw_str_trim(p);
        n++;
        if (!c || n > max)
            return n;
        p = c + 1;
    }
}

/* A whole cell as a double; nan and inf are accepted. */
static int cell_number(const char *s, double *v)
{
    if (!*s)
        return 0;
    char *end;
    errno = 0;
    *v = gw_strtod(s, &end);
    return *end == '\0' && !(errno == ERANGE && fabs(*v) > 1);
}

static int numeric_setting(const char *name);
static const char *setting_domain(const char *name, double v);

static int add_param(gw_stats_table *t, char *text, long ln, gw_err *err)
{
    char *eq = strchr(text, '=');
    if (!eq || t->nparams >= GW_STATS_MAX_KEYS)
        return GW_OK; /* other comments carry no parameter */
    *eq = '\0';
    char *name = gw_str_trim(text), *value = gw_str_trim(eq + 1);
    if (!*name)
        return GW_OK;
    /* "# param rb-rm = abc" (or nan) was read as no value: the default 1 */
    double v = 0;
    if (numeric_setting(name) && !(cell_number(value, &v) && isfinite(v)))
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: param %s: '%s' is not a finite number", t->path, ln, name, value);
    const char *dom = numeric_setting(name) ? setting_domain(name, v) : NULL;
    if (dom)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: param %s: '%s' is not a value a sweep runs (%s must be %s)",
                          t->path, ln, name, value, name, dom);
    t->param_name[t->nparams] = strdup(name);
    t->param_value[t->nparams] = strdup(value);
    if (!t->param_name[t->nparams] || !t->param_value[t->nparams]) {
        free(t->param_name[t->nparams]);
        free(t->param_value[t->nparams]);
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", t->path);
    }
    t->nparams++;
    return GW_OK;
}

/* The settings the analysis reads by name (gw_stats_table_value): a grid key,
 * a "# param" line or the caller's default; all but remove-walls (a flag) are
 * numbers. */
static const char *const settings[] = {"point", "rb-rm", "height-rm", "alpha", "vi", "density", "remove-walls"};

static int numeric_setting(const char *name)
{
    for (size_t k = 0; k + 1 < sizeof settings / sizeof settings[0]; k++)
        if (strcmp(name, settings[k]) == 0)
            return 1;
    return 0;
}

/* The domain of each numeric setting, as the layer model takes it (a sweep
 * refuses any other value): NULL when v is in it, else what it must be.
 * R_b/R_m = 0 or -1 gave a diagram with R_crit -2 and a binary row of mass
 * ratio 0, H/R_m = -4 a group of its own (exit 0). */
static const char *setting_domain(const char *name, double v)
{
    static const struct {
        const char *name;
        double lo, hi;
        int open_lo, open_hi;
        const char *what;
    } dom[] = {{"point", 0, INFINITY, 0, 1, ">= 0"},      {"rb-rm", 0, INFINITY, 1, 1, "> 0"},
               {"height-rm", 0, INFINITY, 0, 1, ">= 0"},  {"alpha", 0, 90, 0, 1, "in [0, 90) deg"},
               {"vi", 0, INFINITY, 1, 1, "> 0"},          {"density", 0, INFINITY, 1, 1, "> 0"}};
    for (size_t k = 0; k < sizeof dom / sizeof dom[0]; k++)
        if (strcmp(name, dom[k].name) == 0) {
            int ok = (dom[k].open_lo ? v > dom[k].lo : v >= dom[k].lo) &&
                     (dom[k].open_hi ? v < dom[k].hi : v <= dom[k].hi);
            return ok ? NULL : dom[k].what;
        }
    return NULL;
}

/* Whether s is a number as a whole, in range or not (strtod reads all of it). */
static int numeric_text(const char *s)
{
    char *end;
    errno = 0;
    (void)gw_strtod(s, &end);
    return *s && *end == '\0';
}

static int parse_header(gw_stats_table *t, char *line, long ln, int *ncells, gw_err *err)
{
    char *cells[GW_STATS_MAX_KEYS + 256];
    const int max = (int)(sizeof cells / sizeof cells[0]);
    int n = split(line, cells, max);
    if (n > max)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: more than %d columns", t->path, ln, max);
    /* a table saved by a spreadsheet program: cells separated by ';' or a
     * tab, or quoted. It was refused as "must start with 'case'", which it
     * seemed to. */
    if (strncmp(cells[0], "case", 4) == 0 && (cells[0][4] == ';' || cells[0][4] == '\t'))
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: the header's cells are separated by %s, a sweep table's by ',' "
                          "(saved by a spreadsheet program?)", t->path, ln, cells[0][4] == ';' ? "';'" : "tabs");
    if (strncmp(cells[0], "\"case\"", 6) == 0)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: the header's cells are in double quotes, a sweep table's are "
                          "not (saved by a spreadsheet program?)", t->path, ln);
    if (strcmp(cells[0], "case") != 0)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: header must start with 'case' (a sweep results table)",
                          t->path, ln);
    int xi = -1;
    for (int i = 1; i < n && xi < 0; i++)
        if (strcmp(cells[i], "x_impact") == 0)
            xi = i;
    if (xi < 0)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: header has no column 'x_impact' (not a layer sweep table)",
                          t->path, ln);
    if (xi - 1 > GW_STATS_MAX_KEYS)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: more than %d grid keys", t->path, ln,
                          GW_STATS_MAX_KEYS);
    for (int i = 0; i < n; i++) {
        if (!*cells[i])
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: header column %d is empty", t->path, ln, i + 1);
        for (int j = 0; j < i; j++)
            if (strcmp(cells[i], cells[j]) == 0)
                return gw_err_set(err, GW_EFORMAT, "%s:%ld: header column '%s' appears twice", t->path,
                                  ln, cells[i]);
    }
    /* the hashes a sweep writes after the model's columns (at most two:
     * case_config_fnv1a64, then the read file's KEY_fnv1a64) */
    int nh = 0;
    while (nh < 2 && n - nh - 1 > xi) {
        const char *c = cells[n - nh - 1];
        const size_t cl = strlen(c);
        if (cl <= 8 || strcmp(c + cl - 8, "_fnv1a64") != 0)
            break;
        nh++;
    }
    if (nh > 0 && strcmp(cells[n - nh], "case_config_fnv1a64") != 0)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: column '%s' is not where a sweep writes it (case_config_fnv1a64 "
                          "follows the model's columns, then the read file's hash)", t->path, ln, cells[n - nh]);
    for (int i = 0; i < nh; i++)
        if (!(t->hash_name[i] = strdup(cells[n - nh + i])))
            return gw_err_set(err, GW_ENOMEM, "%s: out of memory", t->path);
    t->nhash = nh;
    n -= nh;
    t->ngrid = xi - 1;
    /* ncols only once its names are there: with the count set and the array
     * not allocated, the reader's next look-up of a column (and the table's
     * free) read through a null pointer (SIGSEGV, tests/test_alloc_failure.sh) */
    t->col_name = calloc((size_t)(n - xi), sizeof *t->col_name);
    if (!t->col_name)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", t->path);
    t->ncols = n - xi;
    for (int i = 1; i < n; i++) {
        char *s = strdup(cells[i]);
        if (!s)
            return gw_err_set(err, GW_ENOMEM, "%s: out of memory", t->path);
        if (i < xi)
            t->grid_name[i - 1] = s;
        else
            t->col_name[i - xi] = s;
    }
    /* the settings the analysis reads by name from the grid (or a "# param"
     * line, or the defaults): among the results, after x_impact (columns
     * moved by a CSV tool), R_b/R_m was read from the default 1 for every
     * row and the binary table put all the rows under it (exit 0) */
    for (int i = 0; i < t->ncols; i++)
        for (size_t k = 0; k < sizeof settings / sizeof settings[0]; k++)
            if (strcmp(t->col_name[i], settings[k]) == 0)
                return gw_err_set(err, GW_EFORMAT, "%s:%ld: column '%s' comes after x_impact, among the results: a "
                                  "grid key goes between 'case' and 'x_impact' (were the columns reordered?)", t->path,
                                  ln, settings[k]);
    for (int k = 0; k < gw_stats_table_nrequired; k++)
        if (gw_stats_table_col(t, gw_stats_table_required[k]) < 0)
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: header has no column '%s' (a layer sweep table is required)",
                              t->path, ln, gw_stats_table_required[k]);
    *ncells = n + nh;
    return GW_OK;
}

static int grow(gw_stats_table *t, long *cap)
{
    long nc = *cap ? 2 * *cap : 64;
    long *ci = realloc(t->case_id, (size_t)nc * sizeof *ci);
    if (ci)
        t->case_id = ci;
    char **gv = realloc(t->grid_value, (size_t)(nc * t->ngrid + 1) * sizeof *gv);
    if (gv)
        t->grid_value = gv;
    double *gn = realloc(t->grid_num, (size_t)(nc * t->ngrid + 1) * sizeof *gn);
    if (gn)
        t->grid_num = gn;
    double *v = realloc(t->val, (size_t)(nc * t->ncols) * sizeof *v);
    if (v)
        t->val = v;
    unsigned long long *rh = realloc(t->row_hash, (size_t)(nc * t->nhash + 1) * sizeof *rh);
    if (rh)
        t->row_hash = rh;
    long *rl = realloc(t->row_line, (size_t)nc * sizeof *rl);
    if (rl)
        t->row_line = rl;
    if (!ci || !gv || !gn || !v || !rh || !rl)
        return GW_ENOMEM;
    *cap = nc;
    return GW_OK;
}

/* Result columns of the layer model that are never negative: speeds and
 * their ratios, angles, the penetration (y0 - min(y0, y)), the ledger
 * closure, times, step counts (not the first-contact energies: the stored
 * diagram holds a dissipation of -5.5e-10, the ledger's round-off; nor the
 * wave speed: tables written before it was checked hold negative ones). */
static int nonnegative(const char *col)
{
    static const char *const names[] = {"bounced", "e_n", "e", "alpha_r", "v_ni", "v_nr", "v_r", "penetration",
                                        "penetration_rm", "energy_error",
                                        "t_end", "steps", "e_n_first", "e_first", "alpha_r_first",
                                        "v_nr_first", "v_r_first", "t_leave", "t_rebound", "t_f"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        if (strcmp(col, names[k]) == 0)
            return 1;
    return 0;
}

/* The rows' hashes (the cells after the model's columns): each row's case
 * config hash is the one its grid values, the model and the "# param" lines
 * give, and the hash of the file it read is the "# input" line's for that
 * file. A row pasted from a sweep over the same grid with other [params] was
 * read as this sweep's. Run after the grid checks, which name an edited grid
 * cell more precisely. */
static int check_hashes(const gw_stats_table *t, gw_err *err)
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

/* "# input KEY = VALUE fnv1a64 HEX": the content hash of a file the sweep's
 * cases read. */
static int add_input(gw_stats_table *t, const char *text, gw_err *err)
{
    const char *eq = strstr(text, " = ");
    const size_t len = strlen(text);
    unsigned long long h;
    if (!eq || len < 26 || (size_t)(eq - text) + 3 + 25 > len || strncmp(text + len - 25, " fnv1a64 ", 9) != 0 ||
        !gw_fnv1a64_parse(text + len - 16, 16, &h))
        return GW_OK; /* another comment (a table made by hand): it names no file's hash */
    char **k = realloc(t->input_key, (size_t)(t->ninputs + 1) * sizeof *k);
    if (k)
        t->input_key = k;
    char **v = realloc(t->input_value, (size_t)(t->ninputs + 1) * sizeof *v);
    if (v)
        t->input_value = v;
    unsigned long long *hh = realloc(t->input_hash, (size_t)(t->ninputs + 1) * sizeof *hh);
    if (hh)
        t->input_hash = hh;
    char *ks = k && v && hh ? strndup(text, (size_t)(eq - text)) : NULL;
    char *vs = ks ? strndup(eq + 3, len - 25 - (size_t)(eq + 3 - text)) : NULL;
    if (!vs) {
        free(ks);
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", t->path);
    }
    t->input_key[t->ninputs] = ks;
    t->input_value[t->ninputs] = vs;
    t->input_hash[t->ninputs++] = h;
    return GW_OK;
}

static int parse_row(gw_stats_table *t, char *line, long ln, int ncells, int cb, gw_err *err)
{
    char *cells[GW_STATS_MAX_KEYS + 256];
    int n = split(line, cells, ncells);
    if (n != ncells)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: %s%d cells, header has %d", t->path, ln,
                          n > ncells ? "more than " : "", n > ncells ? ncells : n, ncells);
    long r = t->nrows;
    char *end;
    errno = 0;
    long k = strtol(cells[0], &end, 10);
    if (!*cells[0] || *end || errno || k < 0)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: case '%s' is not a case number", t->path, ln, cells[0]);
    t->case_id[r] = k;
    for (int i = 0; i < t->ngrid; i++) {
        if (!*cells[1 + i])
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: grid key %s: empty cell", t->path, ln, t->grid_name[i]);
        double v;
        int num = cell_number(cells[1 + i], &v);
        /* a sweep checks every value: nan, inf or 1e999 was never run (1e999
         * was taken for a name, as a sample file's, and its rows left out of
         * the diagram); R_b/R_m 'abc' gave binary rows of NaN with no points */
        if ((num && !isfinite(v)) || (!num && numeric_text(cells[1 + i])))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: grid key %s: '%s' is not a finite number", t->path, ln,
                              t->grid_name[i], cells[1 + i]);
        if (!num && numeric_setting(t->grid_name[i]))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: grid key %s: '%s' is not a number", t->path, ln,
                              t->grid_name[i], cells[1 + i]);
        const char *dom = num ? setting_domain(t->grid_name[i], v) : NULL;
        if (dom)
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: grid key %s: '%s' is not a value a sweep runs (%s must be %s)",
                              t->path, ln, t->grid_name[i], cells[1 + i], t->grid_name[i], dom);
        t->grid_num[r * t->ngrid + i] = num ? v : NAN;
        t->grid_value[r * t->ngrid + i] = NULL;
    }
    for (int i = 0; i < t->ncols; i++) {
        double v;
        const char *c = cells[1 + t->ngrid + i];
        if (!cell_number(c, &v))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: column %s: '%s' is not a number", t->path, ln,
                              t->col_name[i], c);
        if (i == cb && !(v == 0 || v == 1 || isnan(v)))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: column bounced: '%s' is not 0 or 1", t->path, ln, c);
        /* a sweep writes finite numbers or nan, and these columns are never
         * negative: e_n = -3 or 1e300... entered the means silently */
        if (isinf(v) || (v < 0 && nonnegative(t->col_name[i])))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: column %s: '%s' is not a value a sweep writes (%s)",
                              t->path, ln, t->col_name[i], c, isinf(v) ? "not finite" : "negative");
        t->val[r * t->ncols + i] = v;
    }
    for (int j = 0; j < t->nhash; j++) { /* compared in check_hashes */
        const char *c = cells[1 + t->ngrid + t->ncols + j];
        if (!gw_fnv1a64_parse(c, strlen(c), &t->row_hash[r * t->nhash + j]))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: column %s: '%s' is not a hash a sweep writes (16 hex digits)",
                              t->path, ln, t->hash_name[j], c);
    }
    t->row_line[r] = ln;
    /* strings last, so that a refused row leaves nothing half-owned */
    for (int i = 0; i < t->ngrid; i++)
        if (!(t->grid_value[r * t->ngrid + i] = strdup(cells[1 + i]))) {
            for (int j = 0; j < i; j++)
                free(t->grid_value[r * t->ngrid + j]);
            return gw_err_set(err, GW_ENOMEM, "%s: out of memory", t->path);
        }
    t->nrows++;
    return GW_OK;
}

static int cmp_case(const void *a, const void *b)
{
    long x = *(const long *)a, y = *(const long *)b;
    return (x > y) - (x < y);
}

/* The sweep's first line: "granwave V sweep, model M, config H, N of C cases"
 * (after the '#'). Only the counts are kept; a first line that ends " cases"
 * but does not say them is refused (an edited header). */
static int sweep_line(gw_stats_table *t, const char *line, long ln, gw_err *err)
{
    const char *p = strstr(line, " sweep, model ");
    size_t l = strlen(line);
    if (p) { /* the model, for the rows' case config hashes */
        const size_t ml = strcspn(p + 14, ",");
        gw_snprintf(t->model, sizeof t->model, "%.*s", (int)(ml < sizeof t->model ? ml : 0), p + 14);
    }
    if (!p || l < 6 || strcmp(line + l - 6, " cases") != 0)
        return GW_OK; /* another file's first line, or a sweep's before it said its counts */
    const char *c = strrchr(line, ',');
    long n = -1, total = -1;
    int used = 0;
    if (!c || sscanf(c + 1, " %ld of %ld cases%n", &n, &total, &used) != 2 || c[1 + used] != '\0' || n < 0 ||
        total < 1 || n > total)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: the sweep's first line does not end 'N of C cases' with "
                          "0 <= N <= C (an edited header)", t->path, ln);
    t->sweep_rows = n;
    t->sweep_cases = total;
    return GW_OK;
}

/* "# grid NAME = v1, v2, ...": the sweep's grid, in the config's order. */
static int add_grid_list(gw_stats_table *t, char *text, long ln, gw_err *err)
{
    char *eq = strchr(text, '=');
    int i = 0;
    while (i < GW_STATS_MAX_KEYS && t->grid_list[i])
        i++;
    if (!eq || i >= GW_STATS_MAX_KEYS)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: a '# grid' line that is not 'NAME = v1, v2, ...' (an edited "
                          "header)", t->path, ln);
    *eq = '\0';
    char *name = gw_str_trim(text), *values = gw_str_trim(eq + 1);
    size_t a = strlen(name), b = strlen(values);
    if (!a || !b)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: a '# grid' line without %s (an edited header)", t->path, ln,
                          a ? "values" : "a name");
    /* kept as "NAME\0v1, v2, ..." */
    char *s = malloc(a + b + 2);
    if (!s)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", t->path);
    memcpy(s, name, a + 1);
    memcpy(s + a + 1, values, b + 1);
    t->grid_list[i] = s;
    return GW_OK;
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
static int check_complete(const gw_stats_table *t, gw_err *err)
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
static int check_rows(const gw_stats_table *t, gw_err *err)
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

int gw_stats_table_parse(const char *text, const char *name, gw_stats_table *t, gw_err *err)
{
    memset(t, 0, sizeof *t);
    t->sweep_rows = t->sweep_cases = -1;
    gw_snprintf(t->path, sizeof t->path, "%s", name);
    /* a UTF-8 byte-order mark, as spreadsheet programs save CSV: it was read
     * into the first cell, and the table refused as "header must start with
     * 'case'" (or its first '#' line taken for the header) */
    if (strncmp(text, "\xEF\xBB\xBF", 3) == 0)
        text += 3;
    /* lines ending in CR alone (a classic Mac OS file): the whole table was
     * one line, a comment, and refused as "no header line (an empty table)" */
    if (strchr(text, '\r') && !strchr(text, '\n'))
        return gw_err_set(err, GW_EFORMAT, "%s:1: lines end in CR alone, a sweep table's in LF (CR LF is read "
                          "too): convert its line ends", name);
    char *buf = strdup(text);
    if (!buf)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", name);
    int rc = GW_OK, ncells = 0, cb = -1;
    long ln = 0, cap = 0, header_line = 0;
    for (char *p = buf, *next; p && rc == GW_OK; p = next) {
        next = strchr(p, '\n');
        if (next)
            *next++ = '\0';
        ln++;
        char *line = gw_str_trim(p);
        if (!*line)
            continue;
        if (*line == '#') {
            line = gw_str_trim(line + 1);
            if (!header_line && strncmp(line, "param ", 6) == 0)
                rc = add_param(t, line + 6, ln, err);
            else if (!header_line && strncmp(line, "grid ", 5) == 0)
                rc = add_grid_list(t, line + 5, ln, err);
            else if (!header_line && strncmp(line, "input ", 6) == 0)
                rc = add_input(t, line + 6, err);
            else if (!header_line && ln == 1 && strncmp(line, "granwave ", 9) == 0)
                rc = sweep_line(t, line, ln, err);
            continue;
        }
        if (!header_line) {
            header_line = ln;
            rc = parse_header(t, line, ln, &ncells, err);
            cb = rc == GW_OK ? gw_stats_table_col(t, "bounced") : -1;
            continue;
        }
        if (t->nrows == cap && grow(t, &cap) != GW_OK)
            rc = gw_err_set(err, GW_ENOMEM, "%s: out of memory", name);
        else
            rc = parse_row(t, line, ln, ncells, cb, err);
    }
    free(buf);
    if (rc == GW_OK && header_line && t->nrows > 0)
        rc = check_rows(t, err);
    if (rc == GW_OK && header_line && t->nrows > 0)
        rc = check_complete(t, err);
    /* only against the sweep's first line (its model) and '# param' lines: a
     * table without it (its comment lines dropped by a CSV tool) is read as it
     * is. It was refused as "the table's model and '# param' lines give ..."
     * for a hash taken over lines it did not have. */
    if (rc == GW_OK && header_line && t->nrows > 0 && t->nhash > 0 && t->model[0])
        rc = check_hashes(t, err);
    if (rc == GW_OK && !header_line)
        rc = gw_err_set(err, GW_EFORMAT, "%s:%ld: no header line (an empty table)", name, ln);
    else if (rc == GW_OK && t->nrows == 0)
        rc = gw_err_set(err, GW_EFORMAT, "%s:%ld: no data rows after the header", name, header_line);
    if (rc != GW_OK)
        gw_stats_table_free(t);
    return rc;
}

int gw_stats_table_read(const char *path, gw_stats_table *t, gw_err *err)
{
    if (!t || !path)
        return gw_err_set(err, GW_EINVAL, "gw_stats_table_read: %s is NULL", !t ? "t" : "path");
    memset(t, 0, sizeof *t);
    t->sweep_rows = t->sweep_cases = -1;
    char *buf = NULL;
    size_t len = 0;
    /* a regular file only (a FIFO or device is refused, never read), bounded */
    int rc = gw_input_read(path, "sweep table", (size_t)1 << 32, &buf, &len, err);
    if (rc == GW_EINVAL)
        rc = GW_EFORMAT;
    const char *nul = rc == GW_OK ? memchr(buf, '\0', len) : NULL;
    if (nul) { /* on its line (it said line 1 wherever the byte was) */
        long ln = 1;
        for (const char *q = buf; q < nul; q++)
            ln += *q == '\n';
        rc = gw_err_set(err, GW_EFORMAT, "%s:%ld: binary data (NUL byte), not a CSV table", path, ln);
    }
    if (rc == GW_OK)
        rc = gw_stats_table_parse(buf, path, t, err);
    if (rc == GW_OK) {
        t->content_hash = gw_fnv1a64(GW_FNV1A64_INIT, buf, len);
        t->has_content_hash = 1;
    }
    free(buf);
    return rc;
}

int gw_stats_table_col(const gw_stats_table *t, const char *name)
{
    for (int i = 0; i < t->ncols; i++)
        if (strcmp(t->col_name[i], name) == 0)
            return i;
    return -1;
}

int gw_stats_table_key(const gw_stats_table *t, const char *name)
{
    for (int i = 0; i < t->ngrid; i++)
        if (strcmp(t->grid_name[i], name) == 0)
            return i;
    return -1;
}

const char *gw_stats_table_param(const gw_stats_table *t, const char *name)
{
    for (int i = 0; i < t->nparams; i++)
        if (strcmp(t->param_name[i], name) == 0)
            return t->param_value[i];
    return NULL;
}

double gw_stats_table_value(const gw_stats_table *t, long i, const char *name, double dflt)
{
    int k = gw_stats_table_key(t, name);
    if (k >= 0)
        return t->grid_num[i * t->ngrid + k];
    const char *s = gw_stats_table_param(t, name);
    double v;
    if (s && cell_number(s, &v))
        return v;
    return dflt;
}

/* ------------------------------------------------------------- statistics --- */

void gw_stats_moment_of(const double *v, int n, gw_stats_moment *m)
{
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
              cx = gw_stats_table_col(t, "x_impact"),
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
    g->n_valid = g->n_bounced = 0;
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

int gw_stats_groups_make(const gw_stats_table *t, double criterion, gw_stats_groups *gs,
                         gw_err *err)
{
    memset(gs, 0, sizeof *gs);
    if (!(criterion > 0 && criterion <= 1))
        return gw_err_set(err, GW_EINVAL, "criterion: %g is not in (0, 1]", criterion);
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
    double m = sphere ? r * r * r : r * r;
    /* a block no heavier than its target stops and turns back inside the
     * contact: its smallest energy there is 0 */
    return m <= 1 ? 1.0 : 4 * m / ((1 + m) * (1 + m));
}
