/*
 * gw_sweep_rows.c: one row of a sweep's journal and table: the case number,
 * its grid values, the model's numbers (%.17g, nan never -nan), the case's
 * config hash and the read file's hash (FNV-1a 64), then an FNV-1a 32
 * checksum of all that; and why a line is not a row of this sweep (torn,
 * edited, of another grid, run under other [params] or on another file).
 * Units: the model's columns, as it gives them.
 */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_sweep.h"
#include "gw_locale.h"
#include "gw_sweep_impl.h"

static unsigned fnv32(const char *s, size_t n)
{
    unsigned h = 2166136261u;
    for (size_t i = 0; i < n; i++) {
        h ^= (unsigned char)s[i];
        h *= 16777619u;
    }
    return h;
}

int gw_sweep_format_row(const gw_sweep_config *cfg, long k, const double *out, int ncol,
                        unsigned long long read_hash, char *buf, size_t n)
{
    if (!cfg || !out || !buf || ncol < 0)
        return GW_EINVAL;
    const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
    /* a case the config has not (k < 0 or k >= ncases): its grid values and
     * config hash were read from the arrays gw_sweep_case had not filled
     * (pointers off the stack) and the row returned GW_OK */
    if (gw_sweep_case(cfg, k, names, values) != GW_OK)
        return GW_EINVAL;
    size_t w = (size_t)gw_snprintf(buf, n, "%ld", k);
    for (int i = 0; i < cfg->ngrid && w < n; i++)
        w += (size_t)gw_snprintf(buf + w, n - w, ",%s", values[i]);
    for (int i = 0; i < ncol && w < n; i++)
        w += isnan(out[i]) ? (size_t)gw_snprintf(buf + w, n - w, ",nan") /* never "-nan" */
                           : (size_t)gw_snprintf(buf + w, n - w, ",%.17g", out[i]);
    /* what the case ran under, and on: a row pasted from a sweep with other
     * [params] carried a good checksum and its case's grid values */
    if (w < n)
        w += (size_t)gw_snprintf(buf + w, n - w, ",%016llx",
                              gw_case_config_hash(cfg->model, cfg->ngrid + cfg->nparams, names, values));
    if (cfg->read_key && w < n)
        w += (size_t)gw_snprintf(buf + w, n - w, ",%016llx", read_hash);
    if (w + 12 >= n)
        return GW_EINVAL;
    buf[w] = ','; /* the checksum covers the row up to and including this comma */
    gw_snprintf(buf + w + 1, n - w - 1, "%08x\n", fnv32(buf, w + 1));
    return GW_OK;
}

/* A complete journal line: returns its case number, or -1. */
long gw_sweep_line_case(const char *line, size_t len, long ncases)
{
    if (len < 11 || line[len - 1] != '\n' || line[0] == '#')
        return -1;
    const char *comma = NULL;
    for (size_t i = len - 2; i > 0; i--)
        if (line[i] == ',') {
            comma = line + i;
            break;
        }
    if (!comma || (size_t)(line + len - 1 - comma) != 9)
        return -1;
    char hex[9];
    memcpy(hex, comma + 1, 8);
    hex[8] = '\0';
    char *end;
    unsigned long sum = strtoul(hex, &end, 16);
    if (*end || sum != fnv32(line, (size_t)(comma - line) + 1))
        return -1;
    long k = strtol(line, &end, 10);
    return (*end == ',' && k >= 0 && k < ncases) ? k : -1;
}

/* Why a complete line that check_line refused is no row of this sweep. */
const char *gw_sweep_line_fault(const char *line, size_t len, long ncases)
{
    if (line[0] == '#')
        return "a comment line among the rows";
    /* a case number as a sweep writes it: digits at the start of this line
     * (strtol skipped a blank line's newline and read the next line's number;
     * then the comma search below started at len - 2 of a one-byte line,
     * before the line, and read backwards out of the buffer) */
    char *end;
    if (len < 2 || line[0] < '0' || line[0] > '9')
        return "not a row (it does not start with a case number)";
    long k = strtol(line, &end, 10);
    if (end >= line + len || *end != ',')
        return "not a row (it does not start with a case number)";
    const char *comma = NULL;
    for (size_t i = len - 2; i > 0 && !comma; i--)
        if (line[i] == ',')
            comma = line + i;
    if (comma && (size_t)(line + len - 1 - comma) == 9) {
        char hex[9];
        memcpy(hex, comma + 1, 8);
        hex[8] = '\0';
        unsigned long sum = strtoul(hex, &end, 16);
        if (!*end && sum == fnv32(line, (size_t)(comma - line) + 1))
            return k < 0 || k >= ncases ? "a case number outside the sweep's cases" : "not a row of this sweep";
    }
    return "its checksum does not match its values";
}

/* NULL when the grid values of row k (the fields after the case number) are
 * case k's, as the sweep writes them; else why not. A row with a good
 * checksum from a sweep over another grid was taken for case k silently. */
const char *gw_sweep_row_grid_fault(const gw_sweep_config *cfg, long k, const char *line, size_t len)
{
    const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
    if (gw_sweep_case(cfg, k, names, values) != GW_OK)
        return "a case number outside the sweep's cases";
    const char *p = memchr(line, ',', len), *end = line + len;
    for (int i = 0; i < cfg->ngrid; i++) {
        if (!p)
            return "fewer grid values than the sweep has";
        p++;
        const size_t vl = strlen(values[i]);
        if ((size_t)(end - p) <= vl || memcmp(p, values[i], vl) != 0 || p[vl] != ',')
            return "its grid values are not its case's (a row of another sweep)";
        p += vl;
    }
    return NULL;
}

/* The hashes that end a row (s, len: without ",checksum\n"): the case config
 * hash, then the read hash when cfg->read_key is set. 0 when they are not
 * there (a row of the format before them, or garbled). */
static int row_hashes(const gw_sweep_config *cfg, const char *s, size_t len, unsigned long long *ch,
                      unsigned long long *rh)
{
    *rh = 0;
    for (int f = cfg->read_key ? 2 : 1; f > 0; f--) {
        if (len < 17 || s[len - 17] != ',')
            return 0;
        if (!gw_fnv1a64_parse(s + len - 16, 16, f == 2 ? rh : ch))
            return 0;
        len -= 17;
    }
    return 1;
}

/* The hash the sweep started with of the file case k reads (cfg->read_key):
 * 1 and *h, or 0 when the case reads no file the sweep hashed. *value: the
 * file's name. */
static int case_read_hash(const gw_sweep_config *cfg, long k, unsigned long long *h, const char **value)
{
    const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
    if (!cfg->read_key || gw_sweep_case(cfg, k, names, values) != GW_OK)
        return 0;
    for (int j = 0; j < cfg->ngrid + cfg->nparams; j++)
        if (strcmp(names[j], cfg->read_key) == 0)
            for (int i = 0; i < cfg->ninputs; i++)
                if (strcmp(cfg->inputs[i].key, names[j]) == 0 && strcmp(cfg->inputs[i].value, values[j]) == 0) {
                    *h = cfg->inputs[i].hash;
                    *value = values[j];
                    return 1;
                }
    return 0;
}

/* Row k (s, len: without ",checksum\n") ran under case k's config and on the
 * file the sweep hashed: NULL, or why not into msg. */
const char *gw_sweep_row_hash_fault(const gw_sweep_config *cfg, long k, const char *s, size_t len, int live,
                                  char *msg, size_t n)
{
    unsigned long long ch, rh, want, wr;
    const char *file = NULL;
    if (!row_hashes(cfg, s, len, &ch, &rh)) {
        gw_snprintf(msg, n, "case %ld's row does not end with its config hash%s (16 hex digits)", k,
                 cfg->read_key ? " and the hash of the file it read" : "");
        return msg;
    }
    if (ch != (want = gw_sweep_case_hash(cfg, k))) {
        gw_snprintf(msg, n, "case %ld ran under config hash %016llx, not this sweep's %016llx for it (a row of a "
                 "sweep with other [params] or another model)", k, ch, want);
        return msg;
    }
    if (case_read_hash(cfg, k, &wr, &file) && rh != wr) {
        gw_snprintf(msg, n, "case %ld read %s '%s' with content fnv1a64 %016llx, but the sweep runs on %016llx (%s)", k,
                 cfg->read_key, file, rh, wr, live ? "the file was changed when the case read it, and restored "
                 "before the case ended" : "the file was changed when the case read it, or a row of another sweep");
        return msg;
    }
    return NULL;
}

/* NULL when line (len bytes with its newline; its checksum, grid values and
 * hashes already found right) is, byte for byte, the row this build writes
 * for case k with the numbers it holds: cfg->ncolumns of them (when known),
 * each "nan" or a number as %.17g prints it. Else why not, into msg. Only the
 * checksum vouched for the rest, and a checksum is no guard against a tool
 * that recomputes it or a build whose model writes other columns: a row with
 * a column dropped or added, "abc", an empty cell, "-nan", "1e999", a quoted
 * number or a NUL byte was resumed and copied into results.csv (exit 0). */
const char *gw_sweep_row_values_fault(const gw_sweep_config *cfg, long k, const char *line, size_t len, char *msg,
                                      size_t n)
{
    unsigned long long ch, rh;
    const size_t body = len - 10; /* without ",checksum\n" (gw_sweep_line_case checked them) */
    if (!row_hashes(cfg, line, body, &ch, &rh))
        return "its hashes are missing";
    const char *end = line + body - (cfg->read_key ? 34 : 17); /* the comma before the hashes */
    const char *p = line;
    for (int i = 0; i <= cfg->ngrid; i++) /* past the case number and the grid values (checked) */
        p = (const char *)memchr(p, ',', (size_t)(end - p) + 1) + 1;
    p--; /* the comma before the first result, or the hashes' */
    long count = 0;
    for (const char *q = p; q < end; q++)
        count += *q == ',';
    if (cfg->ncolumns > 0 && count != cfg->ncolumns) {
        gw_snprintf(msg, n, "case %ld's row holds %ld result values where model %s writes %d (a row of another "
                 "granwave, or edited)", k, count, cfg->model, cfg->ncolumns);
        return msg;
    }
    double *out = malloc((size_t)(count ? count : 1) * sizeof *out);
    char *again = malloc(len + 64);
    const char *why = NULL;
    if (!out || !again)
        why = "out of memory checking it";
    for (long j = 0; j < count && !why; j++) {
        const char *f = p + 1, *fe = memchr(f, ',', (size_t)(end - f) + 1);
        const size_t fl = (size_t)(fe - f);
        char text[48], *e = text;
        int bad = fl == 0 || fl >= sizeof text;
        if (!bad) {
            memcpy(text, f, fl);
            text[fl] = '\0';
            out[j] = strcmp(text, "nan") == 0 ? NAN : gw_strtod(text, &e);
            bad = strcmp(text, "nan") != 0 && (*e || isnan(out[j]));
        }
        if (bad) {
            gw_snprintf(msg, n, "case %ld's result value %ld ('%.*s') is not a number as a sweep writes it", k, j + 1,
                     (int)(fl < 40 ? fl : 40), f);
            why = msg;
        }
        p = fe;
    }
    if (!why && (gw_sweep_format_row(cfg, k, out, (int)count, rh, again, len + 64) != GW_OK ||
                 strlen(again) != len || memcmp(again, line, len) != 0)) {
        gw_snprintf(msg, n, "case %ld's row is not as a sweep writes it (a number, its case number or a hash spelt "
                 "otherwise)", k);
        why = msg;
    }
    free(out);
    free(again);
    return why;
}

int gw_sweep_row_check(const gw_sweep_config *cfg, const char *row, gw_err *err)
{
    if (!cfg || !row)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_row_check: %s is NULL", !cfg ? "cfg" : "row");
    char msg[1024];
    size_t len = strlen(row);
    char *end;
    long k = strtol(row, &end, 10);
    if (end == row || *end != ',' || k < 0 || k >= cfg->ncases || len < 10)
        return gw_err_set(err, GW_EINVAL, "sweep: a row that is not one of this sweep's: %.40s", row);
    const char *why = gw_sweep_row_hash_fault(cfg, k, row, len - 10, 1, msg, sizeof msg);
    if (why)
        return gw_err_set(err, GW_EINVAL, "%s: its row is not kept; restore the file and rerun to resume (the "
                          "rows before are kept), or start a new sweep", why);
    return GW_OK;
}

double gw_sweep_row_bound(const gw_sweep_config *cfg, int ncolumns)
{
    double row = 1 + (double)gw_snprintf(NULL, 0, "%ld", cfg->ncases > 0 ? cfg->ncases - 1 : 0);
    for (int i = 0; i < cfg->ngrid; i++) {
        size_t w = 0;
        for (int j = 0; cfg->grid[i].values && j < cfg->grid[i].nvalues; j++) {
            const size_t l = cfg->grid[i].values[j] ? strlen(cfg->grid[i].values[j]) : 0;
            w = l > w ? l : w;
        }
        row += 1 + (double)w;
    }
    /* "%.17g": a sign, 17 digits, the point and e-308 */
    return row + 25.0 * ncolumns + 17.0 * (cfg->read_key ? 2 : 1) + 10; /* the hashes, ",checksum\n" */
}

/* The rows' warnings (their texts and their keys), here with the rows so
 * that the table's writer needs no run: gw_sweep_table.c writes them. */
int gw_sweep_undecided_warning(const gw_sweep_model *m, long n, long total, long first, char **list)
{
    if (!m || !list || n <= 0)
        return GW_OK;
    if (n > total || first < 0 || first >= total) /* 5 of 3 cases, or a first case outside them, was written as given */
        return GW_EINVAL;
    /* the chain's column: converged 0 is a collision held by gravity (its
     * row nan) or not ended at t-max (its values those there), the texts
     * gw_chain_result_warnings gives a single run */
    return gw_warnings_add(list, "%ld of %ld cases did not end their collision (column converged = 0; the first, "
                           "case %ld): one held on the wall by gravity has its undecided values nan, one cut at t-max "
                           "those at t-max (raise t-max); a single run of such a case says which", n, total, first);
}

long gw_sweep_undecided_rows(const gw_sweep_model *m, const double *values, long ncases, long *first)
{
    int col = -1;
    for (int j = 0; m && m->columns && j < m->ncolumns; j++)
        if (m->columns[j] && strcmp(m->columns[j], "converged") == 0)
            col = j;
    long n = 0;
    for (long k = 0; col >= 0 && values && k < ncases; k++)
        if (values[k * m->ncolumns + col] == 0 && n++ == 0 && first)
            *first = k;
    return n;
}

/* The single run's warning texts name its flags (--vimp); a sweep's config
 * has keys (vimp): each "--NAME" whose NAME is a key of the model's options
 * table (has_key, the one mapping) loses its dashes, in place. */
void gw_sweep_warnings_keys(const gw_sweep_model *m, char *list)
{
    if (!m || !m->has_key || !list)
        return;
    char *out = list;
    for (const char *p = list; *p;) {
        if (p[0] == '-' && p[1] == '-' && (p == list || !(isalnum((unsigned char)p[-1]) || p[-1] == '-'))) {
            size_t n = 0;
            char name[64];
            while (n + 1 < sizeof name && (islower((unsigned char)p[2 + n]) || isdigit((unsigned char)p[2 + n]) ||
                                           p[2 + n] == '-'))
                name[n] = p[2 + n], n++;
            while (n > 0 && name[n - 1] == '-') /* "--vimp-" of a dash after the name: the name alone */
                n--;
            name[n] = '\0';
            if (n > 0 && m->has_key(name)) {
                p += 2;
                continue;
            }
        }
        *out++ = *p++;
    }
    *out = '\0';
}

int gw_sweep_warnings_append(char **list, const char *w)
{
    if (!w || !*w)
        return GW_OK;
    const size_t have = *list ? strlen(*list) : 0;
    char *grown = realloc(*list, have + strlen(w) + 1);
    if (!grown)
        return GW_ENOMEM;
    strcpy(grown + have, w);
    *list = grown;
    return GW_OK;
}
