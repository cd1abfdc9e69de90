/*
 * gw_stats_table.c: reading a layer sweep table (OUT/results.csv of
 * `granwave sweep` with model = layer): its comment lines (the sweep's first
 * line with its model and "N of C cases", "# param", "# grid" and "# input"
 * lines), the header (case, the grid keys, x_impact and the model's columns,
 * then the rows' hashes) and the rows, each cell checked as a sweep writes
 * it (a number, nan, 0 or 1 for bounced, never negative where the quantity
 * is not, a grid value in the range a sweep runs). The table is read as a
 * regular file only (gw_input_read). The checks over the whole table are in
 * gw_stats_table_check.c, the statistics in gw_stats_groups.c.
 * Units: as in the table (m, deg, fractions of the incident energy, R_m).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_stats.h"
#include "gw_io_lines.h"
#include "gw_locale.h"
#include "gw_number_impl.h"
#include "gw_stats_impl.h"
#include "gw_sweep_impl.h"

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

/* A whole cell as a double by the data files' rule (gw_data_number: decimal,
 * as the program's options; a table's 0x1p-2 was read as 0.25); nan and inf
 * are accepted. */
static int cell_number(const char *s, double *v)
{
    return gw_data_number(s, v) == GW_DATA_NUMBER;
}

/* The words of a cell's refusal: "not a decimal number (...)" for a
 * hexadecimal one, else dflt. */
static const char *cell_why(const char *s, const char *dflt)
{
    double v;
    return gw_data_number(s, &v) == GW_DATA_HEX ? gw_data_number_why(GW_DATA_HEX) : dflt;
}

static int numeric_setting(const char *name);
static int setting_domain(const gw_stats_table *t, const char *name, const char *text, double v, char *why,
                          size_t n);

/* Two names of one option: a sweep takes '_' for '-' in a key (rb_rm is
 * rb-rm), so a table's grid keys and params are matched the same way. Read
 * by their spelling, the rb_rm and height_rm of a sweep made that way were
 * grid keys like any other: the binary table put every row under the default
 * R_b/R_m = 1 and no diagram was drawn (exit 0). */
int gw_stats_same_key(const char *a, const char *b)
{
    if (!a || !b)
        return 0;
    for (; *a && *b; a++, b++)
        if (*a != *b && !((*a == '-' || *a == '_') && (*b == '-' || *b == '_')))
            return 0;
    return *a == *b;
}

static int add_param(gw_stats_table *t, char *text, long ln, gw_err *err)
{
    char *eq = strchr(text, '=');
    if (!eq || t->nparams >= GW_STATS_MAX_KEYS)
        return GW_OK; /* other comments carry no parameter */
    *eq = '\0';
    char *name = gw_str_trim(text), *value = gw_str_trim(eq + 1);
    if (!*name)
        return GW_OK;
    for (int i = 0; i < t->nparams; i++) /* a sweep writes each key once, in one spelling */
        if (gw_stats_same_key(t->param_name[i], name))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: param %s given twice (as '%s' before)", t->path, ln, name,
                              t->param_name[i]);
    /* "# param rb-rm = abc" (or nan) was read as no value: the default 1 */
    double v = 0;
    if (numeric_setting(name) && !(cell_number(value, &v) && isfinite(v)))
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: param %s: '%s' is %s", t->path, ln, name, value,
                          cell_why(value, "not a finite number"));
    char why[sizeof(gw_err)];
    if (setting_domain(t, name, value, v, why, sizeof why))
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: param %s: '%s' is not a value a sweep runs (%s)", t->path, ln,
                          name, value, why);
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
        if (gw_stats_same_key(name, settings[k]))
            return 1;
    return 0;
}

/* Whether the setting name = text (v: its number, NaN for none) is outside what a sweep of the
 * table's model runs: 1 with why (n bytes) saying what it must be, else 0.
 * The model's own rule for its rows (gw_sweep_value_rule, the layer's
 * parameter table: rb-rm and density in [1e-06, 1e+06], vi in (0, 1000], ...)
 * where it registered one; a table of no known model keeps the analysis's own
 * domain. R_b/R_m = 0 or -1 gave a diagram with R_crit -2 and a binary row of
 * mass ratio 0, H/R_m = -4 a group of its own (exit 0); rb-rm = 1e308, vi =
 * 1e308 or a subnormal height, which no sweep runs, were analysed. */
static int setting_domain(const gw_stats_table *t, const char *name, const char *text, double v, char *why,
                          size_t n)
{
    const gw_sweep_value_rule rule = gw_sweep_value_rule_of(t->model[0] ? t->model : "layer");
    if (rule) {
        gw_err e = {{0}};
        if (rule(name, text, &e) == GW_OK)
            return 0;
        gw_snprintf(why, n, "%s", e.msg);
        return 1;
    }
    static const struct {
        const char *name;
        double lo, hi;
        int open_lo, open_hi;
        const char *what;
    } dom[] = {{"point", 0, INFINITY, 0, 1, ">= 0"},      {"rb-rm", 0, INFINITY, 1, 1, "> 0"},
               {"height-rm", 0, INFINITY, 0, 1, ">= 0"},  {"alpha", 0, 90, 0, 1, "in [0, 90) deg"},
               {"vi", 0, INFINITY, 1, 1, "> 0"},          {"density", 0, INFINITY, 1, 1, "> 0"}};
    for (size_t k = 0; k < sizeof dom / sizeof dom[0]; k++)
        if (gw_stats_same_key(name, dom[k].name)) {
            int ok = (dom[k].open_lo ? v > dom[k].lo : v >= dom[k].lo) &&
                     (dom[k].open_hi ? v < dom[k].hi : v <= dom[k].hi);
            if (!ok)
                gw_snprintf(why, n, "%s must be %s", name, dom[k].what);
            return !ok;
        }
    return 0;
}

/* Whether s is a number as a whole, in range or not, in any base strtod
 * reads (gw_data_number: one beyond a double or in hexadecimal). */
static int numeric_text(const char *s)
{
    double v;
    return gw_data_number(s, &v) != GW_DATA_NONE;
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
        for (int j = 0; j < i; j++) /* a grid key under both spellings too (rb_rm, rb-rm) */
            if (i < xi ? gw_stats_same_key(cells[i], cells[j]) : strcmp(cells[i], cells[j]) == 0)
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
            if (gw_stats_same_key(t->col_name[i], settings[k]))
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
                                        "v_nr_first", "v_r_first", "t_leave", "t_rebound", "t_f",
                                        "settled_load_ratio", "settling_warning", "fell_off", "slump_ke",
                                        "crowns_nulled"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        if (strcmp(col, names[k]) == 0)
            return 1;
    return 0;
}

/* "# input KEY = VALUE fnv1a64 HEX": the content hash of a file the sweep's
 * cases read. */
static int add_input(gw_stats_table *t, const char *text, long ln, gw_err *err)
{
    const char *eq = strstr(text, " = ");
    const size_t len = strlen(text);
    unsigned long long h;
    if (!eq || len < 26 || (size_t)(eq - text) + 3 + 25 > len || strncmp(text + len - 25, " fnv1a64 ", 9) != 0 ||
        !gw_fnv1a64_parse(text + len - 16, 16, &h))
        return GW_OK; /* another comment (a table made by hand): it names no file's hash */
    /* a sweep writes one line per file: a second one (with another hash, the
     * rows were checked against the last line alone and named it) is an edit */
    const size_t kl = (size_t)(eq - text), vl = len - 25 - (kl + 3);
    for (int i = 0; i < t->ninputs; i++)
        if (strlen(t->input_key[i]) == kl && strncmp(t->input_key[i], text, kl) == 0 &&
            strlen(t->input_value[i]) == vl && strncmp(t->input_value[i], eq + 3, vl) == 0)
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: input %.*s = %.*s given twice (a sweep writes one '# input' "
                              "line per file: an edited header)", t->path, ln, (int)kl, text, (int)vl, eq + 3);
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

/* A case number as a sweep writes it ("%ld" of a case >= 0): decimal digits,
 * no leading zero but "0" itself, no sign, blank or other text. strtol took
 * "00", "+0", " 0" and "0x" as well, all silently as case 0: a cell no sweep
 * writes (an edited or hand-made table) read as a sweep's. 1 with *k, else 0. */
static int case_number(const char *s, long *k)
{
    if (!(s[0] >= '0' && s[0] <= '9') || (s[0] == '0' && s[1] != '\0'))
        return 0;
    for (const char *p = s; *p; p++)
        if (!(*p >= '0' && *p <= '9'))
            return 0;
    char *end;
    errno = 0;
    const long v = strtol(s, &end, 10);
    if (errno || *end)
        return 0;
    *k = v;
    return 1;
}

/* line: the row, trimmed; raw: the same line as the file has it (its case
 * field with any blanks before it) */
static int parse_row(gw_stats_table *t, char *line, const char *raw, long ln, int ncells, int cb, gw_err *err)
{
    char *cells[GW_STATS_MAX_KEYS + 256];
    const size_t raw0 = strcspn(raw, ","); /* the case field as written, blanks and all */
    char shown[48];
    gw_snprintf(shown, sizeof shown, "%.*s%s", (int)(raw0 < 40 ? raw0 : 40), raw, raw0 > 40 ? "..." : "");
    int n = split(line, cells, ncells);
    if (n != ncells)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: %s%d cells, header has %d", t->path, ln,
                          n > ncells ? "more than " : "", n > ncells ? ncells : n, ncells);
    long r = t->nrows;
    long k;
    if (strlen(cells[0]) != raw0 || !case_number(cells[0], &k))
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: case '%s' is not a case number as a sweep writes it (decimal "
                          "digits, no sign, blank or leading zero)", t->path, ln, shown);
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
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: grid key %s: '%s' is %s", t->path, ln,
                              t->grid_name[i], cells[1 + i], cell_why(cells[1 + i], "not a finite number"));
        if (!num && numeric_setting(t->grid_name[i]))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: grid key %s: '%s' is not a number", t->path, ln,
                              t->grid_name[i], cells[1 + i]);
        char why[sizeof(gw_err)];
        if (setting_domain(t, t->grid_name[i], cells[1 + i], num ? v : NAN, why, sizeof why))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: grid key %s: '%s' is not a value a sweep runs (%s)", t->path,
                              ln, t->grid_name[i], cells[1 + i], why);
        t->grid_num[r * t->ngrid + i] = num ? v : NAN;
        t->grid_value[r * t->ngrid + i] = NULL;
    }
    for (int i = 0; i < t->ncols; i++) {
        double v;
        const char *c = cells[1 + t->ngrid + i];
        if (!cell_number(c, &v))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: column %s: '%s' is %s", t->path, ln,
                              t->col_name[i], c, cell_why(c, "not a number"));
        if (i == cb && !(v == 0 || v == 1 || isnan(v)))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: column bounced: '%s' is not 0 or 1", t->path, ln, c);
        /* a flag the sweep writes 0 or 1 (never nan): 7, 0.5 or nan counted as
         * no warning, where the row was edited to say something else */
        if (!(v == 0 || v == 1) && (strcmp(t->col_name[i], "settling_warning") == 0 ||
                                    strcmp(t->col_name[i], "fell_off") == 0))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: column %s: '%s' is not 0 or 1", t->path, ln,
                              t->col_name[i], c);
        /* the rules' bits a sweep writes (GW_LAYER_NULLED_*: 0 to 15, never nan) */
        if (strcmp(t->col_name[i], "crowns_nulled") == 0 && !(v >= 0 && v <= 15 && v == floor(v)))
            return gw_err_set(err, GW_EFORMAT, "%s:%ld: column crowns_nulled: '%s' is not an integer in [0, 15]",
                              t->path, ln, c);
        /* a sweep writes finite numbers or nan, and these columns are never
         * negative: e_n = -3 or 1e300... entered the means silently. One
         * exception: settled_load_ratio is q = W_settled / W_impact, +inf for a
         * case run without gravity (other-settling, a pile touching no floor:
         * an unsettled one in the air), which the sweep writes as 'inf' and
         * layer-stats refused as no value a sweep writes */
        if ((isinf(v) && !(v > 0 && strcmp(t->col_name[i], "settled_load_ratio") == 0)) ||
            (v < 0 && nonnegative(t->col_name[i])))
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
    /* a count past a long reads as LONG_MAX (glibc's sscanf): the refusals
     * after it named 9223372036854775807 for "99999999999999999999 cases" */
    if (n == LONG_MAX || total == LONG_MAX)
        return gw_err_set(err, GW_EFORMAT, "%s:%ld: the sweep's first line counts '%.40s', beyond any sweep's (an "
                          "edited header)", t->path, ln, c + 1 + strspn(c + 1, " "));
    t->sweep_rows = n;
    t->sweep_cases = total;
    return GW_OK;
}

/* "# warning: TEXT": a warning of the sweep that wrote the table (its check
 * pass's or its rows', docs/formats.md), appended to *list (NULL: not kept)
 * once however often given: a reader of layer-stats' output lost them. */
static int add_sweep_warning(char **list, const char *text, const char *name, gw_err *err)
{
    if (!list || !*text)
        return GW_OK;
    const size_t len = strlen(text);
    for (const char *p = *list; p && *p;) {
        const char *e = strchr(p, '\n');
        const size_t n = e ? (size_t)(e - p) : strlen(p);
        if (n == len && memcmp(p, text, len) == 0)
            return GW_OK;
        p += n + (e ? 1 : 0);
    }
    if (gw_warnings_add(list, "%s", text) != GW_OK)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", name);
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

static int table_parse(const char *text, const char *name, gw_stats_table *t, char **warnings, gw_err *err);

int gw_stats_table_parse(const char *text, const char *name, gw_stats_table *t, gw_err *err)
{
    return table_parse(text, name, t, NULL, err);
}

static int table_parse(const char *text, const char *name, gw_stats_table *t, char **warnings, gw_err *err)
{
    if (!t)
        return gw_err_set(err, GW_EINVAL, "gw_stats_table_parse: t is NULL");
    if (!text) {
        memset(t, 0, sizeof *t);
        return gw_err_set(err, GW_EINVAL, "gw_stats_table_parse: text is NULL");
    }
    /* no name (NULL or ""): its messages named nothing (":1: lines end in
     * CR alone"), as the parsers say "value" for a NULL name */
    if (!name || !name[0])
        name = "<table>";
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
    int journal = 0; /* the first line is a sweep journal's: rows without a header */
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
                rc = add_input(t, line + 6, ln, err);
            else if (!header_line && strncmp(line, "warning: ", 9) == 0)
                rc = add_sweep_warning(warnings, gw_str_trim(line + 9), name, err);
            else if (ln == 1 && strncmp(line, "granwave sweep journal ", 23) == 0)
                journal = 1;
            else if (!header_line && ln == 1 && strncmp(line, "granwave ", 9) == 0)
                rc = sweep_line(t, line, ln, err);
            continue;
        }
        if (!header_line && journal) {
            /* it was "header must start with 'case'", of a file that has no
             * header: the sweep's record of its runs, beside its table */
            const char *slash = strrchr(name, '/');
            rc = gw_err_set(err, GW_EFORMAT, "%s: a sweep's journal (its first line '# granwave sweep journal ...'), "
                            "not its table: give the table the sweep wrote beside it, %.*sresults.csv",
                            name, slash ? (int)(slash - name + 1) : 0, name);
            break;
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
            rc = parse_row(t, line, p, ln, ncells, cb, err);
    }
    free(buf);
    if (rc == GW_OK && header_line && t->nrows > 0)
        rc = gw_stats_table_check_rows(t, err);
    if (rc == GW_OK && header_line && t->nrows > 0)
        rc = gw_stats_table_check_complete(t, err);
    /* only against the sweep's first line (its model) and '# param' lines: a
     * table without it (its comment lines dropped by a CSV tool) is read as it
     * is. It was refused as "the table's model and '# param' lines give ..."
     * for a hash taken over lines it did not have. */
    if (rc == GW_OK && header_line && t->nrows > 0 && t->nhash > 0 && t->model[0])
        rc = gw_stats_table_check_hashes(t, err);
    /* the rows naming one file carry one hash: with or without the head */
    if (rc == GW_OK && header_line && t->nrows > 0)
        rc = gw_stats_table_check_file_hashes(t, err);
    if (rc == GW_OK && header_line && t->nrows > 0)
        rc = gw_stats_table_check_rm(t, err);
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
    return gw_stats_table_read_warned(path, t, NULL, err);
}

int gw_stats_table_read_warned(const char *path, gw_stats_table *t, char **warnings, gw_err *err)
{
    if (t) { /* emptied on every refusal, a NULL path's too (docs/library.md) */
        memset(t, 0, sizeof *t);
        t->sweep_rows = t->sweep_cases = -1;
    }
    if (!t || !path)
        return gw_err_set(err, GW_EINVAL, "gw_stats_table_read: %s is NULL", !t ? "t" : "path");
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
    /* A row without its newline (LF, or the CR of a CR LF) is the end of a
     * table cut short (a full disk, a copy stopped): a sweep ends every line,
     * and a number cut in its digits still reads. The hash columns catch a
     * cut in the row's hashes, but a table without them (written before
     * them, or made by hand) read its last e_n 0.734 cut to 0.7 into the
     * means with exit 0. A comment line may end the file so. */
    size_t s = 0;
    const long ln = rc == GW_OK ? gw_input_unended_line(buf, len, 1, &s) : 0;
    if (ln > 0) {
        size_t lead = s + (ln == 1 && len - s >= 3 && memcmp(buf, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0);
        while (lead < len && (buf[lead] == ' ' || buf[lead] == '\t'))
            lead++;
        if (lead < len && buf[lead] != '#')
            rc = gw_err_set(err, GW_EFORMAT, "%s:%ld: the file ends inside this line (no newline after it): cut "
                            "short? a sweep ends every line of its table", path, ln);
    }
    if (rc == GW_OK)
        rc = table_parse(buf, path, t, warnings, err);
    if (rc == GW_OK) {
        t->content_hash = gw_fnv1a64(GW_FNV1A64_INIT, buf, len);
        t->has_content_hash = 1;
    }
    free(buf);
    return rc;
}

/* The accessors below take tables filled by hand too: counts beyond the
 * arrays (ngrid or nparams above GW_STATS_MAX_KEYS overran them: a stack
 * buffer overflow), columns counted without their names and rows without
 * their values (SIGSEGV) find nothing, as a name the table has not. */
int gw_stats_table_col(const gw_stats_table *t, const char *name)
{
    if (!t || !name || !t->col_name)
        return -1;
    for (int i = 0; i < t->ncols; i++)
        if (t->col_name[i] && strcmp(t->col_name[i], name) == 0)
            return i;
    return -1;
}

int gw_stats_table_key(const gw_stats_table *t, const char *name)
{
    if (!t || !name || t->ngrid > GW_STATS_MAX_KEYS)
        return -1;
    for (int i = 0; i < t->ngrid; i++)
        if (t->grid_name[i] && gw_stats_same_key(t->grid_name[i], name))
            return i;
    return -1;
}

const char *gw_stats_table_param(const gw_stats_table *t, const char *name)
{
    if (!t || !name || t->nparams > GW_STATS_MAX_KEYS)
        return NULL;
    for (int i = 0; i < t->nparams; i++)
        if (t->param_name[i] && gw_stats_same_key(t->param_name[i], name))
            return t->param_value[i];
    return NULL;
}

double gw_stats_table_value(const gw_stats_table *t, long i, const char *name, double dflt)
{
    if (!t || !name || i < 0 || i >= t->nrows)
        return dflt;
    int k = gw_stats_table_key(t, name);
    if (k >= 0)
        return t->grid_num ? t->grid_num[i * t->ngrid + k] : dflt;
    const char *s = gw_stats_table_param(t, name);
    double v;
    if (s && cell_number(s, &v))
        return v;
    return dflt;
}
