/*
 * gw_sweep_config.c: a sweep config (libinih) read into gw_sweep_config: its
 * [sweep], [grid] and [params] keys, the grid's values (lists, ranges A:B, a
 * list continued over indented lines), the config's hash (FNV-1a 64 over the
 * model, the keys, their values and the bytes of the files they name), and
 * case k's values, the last grid key varying fastest (see gw_sweep.h).
 * No units: values are kept as the config spells them.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <ini.h>

#include "gw_sweep.h"
#include "gw_io_lines.h"
#include "gw_locale.h"
#include "gw_number_impl.h"
#include "gw_io_impl.h"
#include "gw_sweep_impl.h"

typedef struct parse_ctx {
    gw_sweep_config *cfg;
    const gw_sweep_model *const *models;
    int nmodels;
    char msg[400];
    int line; /* current line, counted by the reader */
    int failed; /* a handler call failed: later calls are ignored */
    /* The reader's handler calls in order, as scan_lines found them: bit 0 a
     * call that continues a [grid] list on an indented line, bit 1 a call that
     * the next one continues. A continued list is gathered in 'pending' and
     * read as one value at its last line. */
    unsigned char *calls;
    long ncalls, call;
    char *pending;
    int nomem; /* the failed call was out of memory (not a mistake of the file) */
    const char *data_section; /* "grid" or "params" once a key of one was read */
} parse_ctx;

char *gw_sweep_strdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

/* "A:B" with two integers (blanks allowed around them): a range, even when it is
 * empty or out of bounds, so that its error is a range error. */
static int looks_like_range(const char *v)
{
    const char *colon = strchr(v, ':');
    if (!colon || strchr(colon + 1, ':'))
        return 0;
    for (const char *p = v; *p; p++)
        if (p != colon && !(*p == ' ' || *p == '\t' || *p == '-' || *p == '+' || (*p >= '0' && *p <= '9')))
            return 0;
    return 1;
}

/* Split a grid value: "A:B" (integers) or "a, b, c". */
/* Out of memory in a handler call: 0 (the call failed), the cause noted. */
static int parse_nomem(parse_ctx *pc)
{
    pc->nomem = 1;
    gw_snprintf(pc->msg, sizeof pc->msg, "out of memory");
    return 0;
}

/* One value of a grid list as the duplicate search sorts it. */
typedef struct dup_item {
    const char *s; /* the text */
    double v;      /* its number (kind 1) or flag (kind 2) */
    long idx;
} dup_item;

static int dup_cmp_text(const void *pa, const void *pb)
{
    const dup_item *a = pa, *b = pb;
    const int c = strcmp(a->s, b->s);
    return c ? c : (a->idx > b->idx) - (a->idx < b->idx);
}

static int dup_cmp_value(const void *pa, const void *pb)
{
    const dup_item *a = pa, *b = pb;
    if (a->v != b->v)
        return a->v < b->v ? -1 : 1;
    return (a->idx > b->idx) - (a->idx < b->idx);
}

/* Numbers a and b as one grid value: equal, or for numbers (kind 1) within
 * GW_SWEEP_SAME_REL of each other, a difference only printing makes
 * ('vimp = 0.3, 0.30000000000000004' ran the same case twice, where falcon
 * refuses speeds within 1e-6 of each other) */
#define GW_SWEEP_SAME_REL 1e-12
static int same_number(double a, double b, int kind)
{
    return a == b || (kind == 1 && fabs(a - b) <= GW_SWEEP_SAME_REL * fmax(fabs(a), fabs(b)));
}

/* The first pair (j < i, i smallest, then j) of k's values that are the same
 * value: the same text, the same number ("1", "1.0", "1e0") or the same flag
 * ("1", "true"): 1 and *j, *i; 0 when there is none; -1 out of memory. Each
 * relation's classes are found by sorting, so a list of n values costs
 * n log n: the pairwise search took 64 s to read a config of 20000 speeds,
 * and about half an hour for the 1 MiB a config may take. */
static int first_duplicate(const gw_sweep_key *k, long *jp, long *ip)
{
    const long n = k->nvalues;
    dup_item *it = malloc((size_t)(n ? n : 1) * sizeof *it);
    long *first = malloc((size_t)(n ? n : 1) * sizeof *first); /* per value: the smallest index it equals */
    if (!it || !first) {
        free(it);
        free(first);
        return -1;
    }
    for (long q = 0; q < n; q++)
        first[q] = q;
    for (int kind = 0; kind < 3; kind++) {
        long m = 0;
        for (long q = 0; q < n; q++) {
            double v = 0;
            int keep = 1;
            if (kind == 1) {
                /* by the data files' rule: a hexadecimal value is no number
                 * (refused by its row), not the duplicate of a decimal one */
                keep = gw_data_number(k->values[q], &v) == GW_DATA_NUMBER && !isnan(v); /* NaN equals nothing */
            } else if (kind == 2) {
                const int f = gw_parse_flag(k->values[q]);
                keep = f >= 0;
                v = f;
            }
            if (keep)
                it[m++] = (dup_item){k->values[q], v, q};
        }
        qsort(it, (size_t)m, sizeof *it, kind ? dup_cmp_value : dup_cmp_text);
        /* a class is a run of the sorted items, by index within it: its
         * head holds its smallest index */
        long head = 0;
        for (long q = 0; q < m; q++) {
            if (q > 0 && !(kind ? same_number(it[q].v, it[q - 1].v, kind) : strcmp(it[q].s, it[q - 1].s) == 0))
                head = q;
            if (it[head].idx < first[it[q].idx])
                first[it[q].idx] = it[head].idx;
        }
    }
    int found = 0;
    for (long q = 0; q < n && !found; q++)
        if (first[q] < q) {
            *ip = q;
            *jp = first[q];
            found = 1;
        }
    free(it);
    free(first);
    return found;
}

/* A [grid] value into k's values. An allocation that failed was read as an
 * empty item ("empty value in list '0.2, 0.3'", exit 2) or stored as a null
 * value that the duplicate check then read (SIGSEGV): out of memory now. */
static int split_values(const char *value, gw_sweep_key *k, parse_ctx *pc)
{
    char *msg = pc->msg;
    const size_t mlen = sizeof pc->msg;
    long a, b;
    gw_err err;
    if (looks_like_range(value)) {
        if (gw_parse_int_range(value, k->name, -1000000000L, 1000000000L, &a, &b, &err) != GW_OK) {
            size_t l = strnlen(err.msg, mlen - 1); /* "5:1": an empty range, not "not an integer" */
            memcpy(msg, err.msg, l);
            msg[l] = '\0';
            return 0;
        }
        if (b - a >= 1000000L) { /* each value is a string: bound the memory */
            gw_snprintf(msg, mlen, "%s: range %s has more than 1000000 values", k->name, value);
            return 0;
        }
        k->nvalues = (int)(b - a + 1);
        k->values = calloc((size_t)k->nvalues, sizeof *k->values);
        if (!k->values) {
            k->nvalues = 0;
            return parse_nomem(pc);
        }
        for (long i = 0; i <= b - a; i++) {
            char buf[32];
            gw_snprintf(buf, sizeof buf, "%ld", a + i);
            if (!(k->values[i] = gw_sweep_strdup(buf)))
                return parse_nomem(pc);
        }
        return 1;
    }
    char *copy = gw_sweep_strdup(value);
    if (!copy)
        return parse_nomem(pc);
    int cap = 1;
    for (const char *p = value; *p; p++)
        cap += *p == ',';
    k->values = calloc((size_t)cap, sizeof *k->values);
    if (!k->values) {
        free(copy);
        return parse_nomem(pc);
    }
    char *save = NULL;
    for (char *tok = strtok_r(copy, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        char *t = gw_str_trim(tok);
        if (!*t) {
            gw_snprintf(msg, mlen, "%s: empty value in list '%s'", k->name, value);
            free(copy);
            return 0;
        }
        if (looks_like_range(t)) { /* "5:6, 7": the range was read as one value, "not an integer" */
            gw_snprintf(msg, mlen, "%s: a range '%s' cannot be an item of the list '%s': give a range A:B "
                        "alone, or list every value", k->name, t, value);
            free(copy);
            return 0;
        }
        if (!(k->values[k->nvalues] = gw_sweep_strdup(t))) {
            free(copy);
            return parse_nomem(pc);
        }
        k->nvalues++;
    }
    free(copy);
    if (k->nvalues != cap) {
        gw_snprintf(msg, mlen, "%s: empty value in list '%s'", k->name, value);
        return 0;
    }
    /* a value listed twice runs the same case twice: the table then holds a
     * combination twice and its statistics count it twice ("1, 1.0" too, and
     * a flag's words: "1, true", "0, FALSE") */
    long j, i;
    const int dup = k->values ? first_duplicate(k, &j, &i) : 0;
    if (dup < 0)
        return parse_nomem(pc);
    if (dup) { /* a long list quoted whole cut the message before its reason */
        double a = 0, b = 0; /* two numbers apart by their last digits: said so */
        const int near = gw_data_number(k->values[j], &a) == GW_DATA_NUMBER &&
                         gw_data_number(k->values[i], &b) == GW_DATA_NUMBER && a != b;
        const char *same = near ? "are the same value to 12 digits" : "are the same value";
        if (strlen(value) <= 120)
            gw_snprintf(msg, mlen, "%s: '%s' and '%s' in list '%s' %s (each case would run twice)",
                     k->name, k->values[j], k->values[i], value, same);
        else
            gw_snprintf(msg, mlen, "%s: '%s' and '%s' (values %ld and %ld of its list of %d) %s "
                     "(each case would run twice)", k->name, k->values[j], k->values[i], j + 1, i + 1, k->nvalues,
                     same);
        return 0;
    }
    return k->values != NULL;
}

/* Each value of a [grid] key by the model's rule for one value (the table of
 * the model's options, as [params] is read): a misspelt choice or a number
 * out of its row's range in a list ('solver = rk4, cvod', 'n = 0:3') was
 * refused only by the check of every case, as "case 1: solver: ...", without
 * the config's line. 1, or 0 with the message naming the key and the value. */
static int grid_values_rule(parse_ctx *pc, const gw_sweep_key *k)
{
    const gw_sweep_value_rule rule = gw_sweep_value_rule_of(pc->cfg->model);
    for (int j = 0; rule && j < k->nvalues; j++) {
        gw_err e;
        if (rule(k->name, k->values[j], &e) != GW_OK) {
            gw_snprintf(pc->msg, sizeof pc->msg, "[grid] %s", e.msg);
            return 0;
        }
    }
    return 1;
}

static int find_key(const gw_sweep_key *keys, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (strcmp(keys[i].name, name) == 0)
            return i;
    return -1;
}

/* libinih goes on after a handler error and reports the first error's line: keep
 * the first message too (a misspelt model would otherwise be reported as the
 * next section's "model must come before"). */
static int handler_one(parse_ctx *pc, const char *section, const char *name, const char *value);

static int handler(void *user, const char *section, const char *name, const char *value)
{
    parse_ctx *pc = user;
    const long i = pc->call++;
    const int part = i < pc->ncalls ? pc->calls[i] : 0;
    if (pc->failed)
        return 0;
    if (part) { /* a [grid] list over several lines: "a, b," then "  c, d" */
        size_t have = pc->pending ? strlen(pc->pending) : 0, add = strlen(value);
        char *p = realloc(pc->pending, have + add + 2);
        if (!p) {
            pc->failed = 1;
            return parse_nomem(pc);
        }
        if (have)
            p[have++] = ' ';
        memcpy(p + have, value, add + 1);
        pc->pending = p;
        if (part & 2)
            return 1; /* more to come */
        value = pc->pending;
    }
    int ok = handler_one(pc, section, name, value);
    if (part) {
        free(pc->pending);
        pc->pending = NULL;
    }
    if (!ok)
        pc->failed = 1;
    return ok;
}

static int handler_one(parse_ctx *pc, const char *section, const char *name, const char *value)
{
    gw_sweep_config *cfg = pc->cfg;
    if (strcmp(section, "sweep") == 0) {
        /* a second [sweep] after [grid] set its keys as the first one's
         * (out = x there was the sweep's output directory) */
        if (pc->data_section) {
            gw_snprintf(pc->msg, sizeof pc->msg, "'%s' in a [sweep] section after [%s]: the config has one [sweep] "
                        "section, before [grid] and [params]", name, pc->data_section);
            return 0;
        }
        char **dst = strcmp(name, "model") == 0 ? &cfg->model : strcmp(name, "out") == 0 ? &cfg->out : NULL;
        if (!dst) {
            gw_snprintf(pc->msg, sizeof pc->msg, "unknown key '%s' in [sweep] (model, out)", name);
            return 0;
        }
        if (*dst) { /* the first value kept would run silently; either */
            gw_snprintf(pc->msg, sizeof pc->msg, "duplicate key '%s' in [sweep] (given before in [sweep]: each key "
                        "once)", name);
            return 0;
        }
        if (!*value) {
            gw_snprintf(pc->msg, sizeof pc->msg, "empty value for '%s'", name);
            return 0;
        }
        if (dst == &cfg->model) {
            int known = 0;
            for (int i = 0; i < pc->nmodels; i++)
                known |= strcmp(pc->models[i]->name, value) == 0;
            if (!known) {
                gw_snprintf(pc->msg, sizeof pc->msg, "unknown model '%s'", value);
                return 0;
            }
        }
        *dst = gw_sweep_strdup(value);
        return *dst ? 1 : parse_nomem(pc);
    }
    int is_grid = strcmp(section, "grid") == 0;
    if (!*section) { /* a key above the first header was "unknown section []" */
        gw_snprintf(pc->msg, sizeof pc->msg, "'%s' before any section header: a config opens with [sweep] (then "
                    "[grid] and [params])", name);
        return 0;
    }
    if (!is_grid && strcmp(section, "params") != 0) {
        gw_snprintf(pc->msg, sizeof pc->msg, "unknown section [%s] (sweep, grid, params)", section);
        return 0;
    }
    if (!cfg->model) {
        gw_snprintf(pc->msg, sizeof pc->msg, "[sweep] model must come before [%s]", section);
        return 0;
    }
    pc->data_section = is_grid ? "grid" : "params";
    const gw_sweep_model *m = NULL;
    for (int i = 0; i < pc->nmodels; i++)
        if (strcmp(pc->models[i]->name, cfg->model) == 0)
            m = pc->models[i];
    if (!m) {
        gw_snprintf(pc->msg, sizeof pc->msg, "unknown model '%s'", cfg->model);
        return 0;
    }
    if (!m->has_key(name)) {
        gw_snprintf(pc->msg, sizeof pc->msg, "'%s' is not an option of model %s", name, cfg->model);
        return 0;
    }
    /* The key under its one spelling: the options take '_' for '-' (t_max is
     * t-max), and keys compared as written let 't-max' in [grid] and 't_max'
     * in [params] both through, the later one silently setting every case
     * (a grid of wall materials gave three equal rows, exit 0), and a table
     * keyed 'rb_rm' that layer-stats did not know as R_b/R_m. */
    char *canon = gw_sweep_strdup(name);
    if (!canon)
        return parse_nomem(pc);
    for (char *c = canon; *c; c++)
        if (*c == '_')
            *c = '-';
    const int in_grid = find_key(cfg->grid, cfg->ngrid, canon) >= 0;
    if (in_grid || find_key(cfg->params, cfg->nparams, canon) >= 0) {
        if (strcmp(canon, name) != 0)
            gw_snprintf(pc->msg, sizeof pc->msg, "duplicate key '%s' in [%s] (the option '%s', given before in [%s]: "
                        "'_' and '-' are one)", name, section, canon, in_grid ? "grid" : "params");
        else
            gw_snprintf(pc->msg, sizeof pc->msg, "duplicate key '%s' in [%s] (given before in [%s]: each key once)",
                        name, section, in_grid ? "grid" : "params");
        free(canon);
        return 0;
    }
    gw_sweep_key *keys = is_grid ? cfg->grid : cfg->params;
    int *nk = is_grid ? &cfg->ngrid : &cfg->nparams;
    if (*nk >= GW_SWEEP_MAX_KEYS) {
        gw_snprintf(pc->msg, sizeof pc->msg, "more than %d keys in [%s]", GW_SWEEP_MAX_KEYS, section);
        free(canon);
        return 0;
    }
    gw_sweep_key *k = &keys[(*nk)++];
    memset(k, 0, sizeof *k);
    k->name = canon;
    if (is_grid)
        return split_values(value, k, pc) && grid_values_rule(pc, k);
    k->values = calloc(1, sizeof *k->values);
    if (!k->values || !(k->values[0] = gw_sweep_strdup(value)))
        return parse_nomem(pc);
    k->nvalues = 1;
    /* One value, by the model's rule for it: a range 'n = 3:5' or a list
     * 'vimp = 1, 2' in [params] was read as one text and refused only by the
     * first case's check, without its line ([grid] takes lists and ranges). */
    const gw_sweep_value_rule rule = gw_sweep_value_rule_of(cfg->model);
    gw_err e;
    if (rule && rule(canon, value, &e) != GW_OK) {
        /* the hint where the value is a list or a range, not on a subnormal */
        gw_snprintf(pc->msg, sizeof pc->msg, "[params] %s%s", e.msg,
                    strpbrk(value, ":,") ? " (one value: lists and ranges go in [grid])" : "");
        return 0;
    }
    return 1;
}

static unsigned long fnv64(unsigned long h, const char *s)
{
    for (; *s; s++) {
        h ^= (unsigned char)*s;
        h *= 1099511628211UL;
    }
    return h ^ 0xff; /* separator */
}

/* A value that names an existing regular file (a layer sample, say) adds the
 * file's bytes to the config hash: a journal made with another version of the
 * file is then refused instead of silently mixing rows of both. */
static unsigned long fnv64_file(unsigned long h, const char *path, int *nomem)
{
    struct stat sb;
    if (stat(path, &sb) != 0 || !S_ISREG(sb.st_mode))
        return h;
    /* bounded as every input's hash (it read a file that grew while read, or
     * a /proc file, on and on); never blocks on a FIFO (gw_input_open). A file
     * it refuses is left out, for the model's check to name. */
    unsigned long long v = 0;
    gw_err err;
    const int rc = gw_io_fnv1a64_file_from(h, path, "sweep", GW_INPUT_HASH_MAX, 0, &v, &err);
    if (rc == GW_ENOMEM) /* the file left out of the hash: another sweep's identity */
        *nomem = 1;
    return rc == GW_OK ? (unsigned long)(v ^ 0xfe) : h;
}

static int config_finish(const char *path, const char *base, const gw_sweep_model *const *models, int nmodels,
                         gw_sweep_config *cfg, const gw_sweep_model **model, int rc,
                         const parse_ctx *pc, gw_err *err);

/* libinih reads an indented line after a key as more of that key's value
 * (Python's multi-line style) and passes it to the handler under the key's
 * name again. In [grid] that continues a long list: a line whose value ends
 * with a comma goes on over the indented lines after it (each line within the
 * reader's buffer, below), and pc->calls marks those handler calls so that the
 * handler reads the list whole. Anywhere else such a line was misread ('  rings
 * = 4' after 't-max = 0.003' refused as "duplicate key 't-max'", an indented
 * '  [params]' after 'vi = 10, 20' as "duplicate key 'vi'": the wrong key and
 * the wrong cause), so it is refused here, naming the key it would continue.
 * The rules are the reader's: an indented line that is neither blank nor a
 * comment continues the last key since the last section header; a ';' after a
 * blank starts a comment (a '#' there is refused: comment_hash); a line with
 * neither '=' nor ':' calls no handler. */
/* The first '#' of the value p[from, end) that begins it or follows a blank:
 * where a ';' would start a comment (the reader takes ';' only), so a '#'
 * there was meant as one. -1 when there is none. 'n = 40  # beads' was
 * refused as "case 0: n: '40  # beads' is not an integer", naming neither
 * the line nor the cause, and 'out = o2  # where' made a directory of that
 * name (exit 0). A value cannot hold such a '#' (a path 'runs #2' neither),
 * so that no value is read otherwise than it was meant. */
static long comment_hash(const char *p, size_t from, size_t end)
{
    while (from < end && (p[from] == ' ' || p[from] == '\t'))
        from++;
    for (size_t q = from; q < end; q++)
        if (p[q] == '#' && (q == from || p[q - 1] == ' ' || p[q - 1] == '\t'))
            return (long)q;
    return -1;
}

/* whole: the text is a file's (gw_sweep_config_read), whose last line holding
 * a value must end with a newline (see below); a config given as text
 * (gw_sweep_config_read_string, Python's sweep) may end without one. */
static int scan_lines(const char *text, const char *name, int whole, parse_ctx *pc, gw_err *err)
{
    char key[64] = "", sect[64] = "";
    long key_ln = 0, ln = 1, cap = 0;
    int in_grid = 0, comma = 0; /* the last value line of the key ends with ',' */
    /* the last line of a file when it has no newline after it (0: none) */
    const long cut = whole ? gw_input_unended_line(text, strlen(text), 1, NULL) : 0;
    for (const char *p = text; *p; ln++) {
        const char *e = strchr(p, '\n');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        size_t i = 0;
        if (ln == 1 && len >= 3 && memcmp(p, "\xef\xbb\xbf", 3) == 0)
            i = 3; /* the BOM the reader skips */
        const size_t lead = i;
        while (i < len && (p[i] == ' ' || p[i] == '\t' || p[i] == '\r' || p[i] == '\f' || p[i] == '\v'))
            i++;
        const int blank = i == len, comment = !blank && (p[i] == ';' || p[i] == '#');
        /* the line's end without an inline comment and trailing blanks */
        size_t end = i;
        while (end < len && !(p[end] == ';' && end > i && (p[end - 1] == ' ' || p[end - 1] == '\t')))
            end++;
        while (end > i && (p[end - 1] == ' ' || p[end - 1] == '\t' || p[end - 1] == '\r'))
            end--;
        int call = -1; /* this line's handler call: 0 a key, 1 a continuation */
        if (!blank && !comment) {
            if (i > lead && key[0]) {
                /* (a section header or a key there is a mistake, not values) */
                if (!(in_grid && comma))
                    return gw_err_set(err, GW_EINVAL, "%s:%ld: an indented line: the config reader takes it as "
                                      "more of the value of '%s' (line %ld); remove the indentation (a [grid] "
                                      "list goes on over indented lines after a line ending with a comma)", name,
                                      ln, key, key_ln);
                if (p[i] == '[' || memchr(p + i, '=', end - i))
                    return gw_err_set(err, GW_EINVAL, "%s:%ld: an indented %s where the list of '%s' (line %ld) "
                                      "goes on after its comma; remove the indentation", name, ln,
                                      p[i] == '[' ? "section header" : "key", key, key_ln);
                call = 1;
            } else if (p[i] == '[') {
                key[0] = '\0';
                const char *q = memchr(p + i, ']', len - i);
                /* the reader keeps the section before and reports a syntax
                 * error at this line only after the keys below it were taken
                 * in it: '[grid' was "unknown key 'n' in [sweep]", '[sweep'
                 * first "unknown section []" */
                if (!q)
                    return gw_err_set(err, GW_EINVAL, "%s:%ld: the section header '%.*s' has no ']'", name, ln,
                                      (int)(end - i), p + i);
                in_grid = q - (p + i) == 5 && memcmp(p + i, "[grid", 5) == 0;
                gw_snprintf(sect, sizeof sect, "%.*s ", q ? (int)(q - (p + i) + 1) : 0, p + i);
                /* The reader drops whatever follows the ']': '[grid] n = 1:2'
                 * ran without n (one case, exit 0), '[params] solver = rk4'
                 * the default solver. Only blanks or a comment may follow. */
                const char *t = q ? q + 1 : NULL, *le = p + len;
                while (t && t < le && (*t == ' ' || *t == '\t' || *t == '\r'))
                    t++;
                if (t && t < le && *t != ';' && *t != '#')
                    return gw_err_set(err, GW_EINVAL, "%s:%ld: '%.*s' after the section header %.*s: the config "
                                      "reader ignores it; put it on a line of its own", name, ln,
                                      (int)(end > (size_t)(t - p) ? end - (size_t)(t - p) : (size_t)(le - t)), t,
                                      (int)(q - (p + i) + 1), p + i);
            } else {
                size_t k = i;
                while (k < len && p[k] != '=' && p[k] != ':')
                    k++;
                size_t kl = k;
                while (kl > i && (p[kl - 1] == ' ' || p[kl - 1] == '\t'))
                    kl--;
                if (k < len) {
                    gw_snprintf(key, sizeof key, "%.*s", (int)(kl - i), p + i);
                    key_ln = ln;
                    call = 0;
                } else {
                    /* the reader notes the line's error and reads on: the
                     * first message of a later line came out under this
                     * line's number ("s.ini:5: [grid] vimp: 'abc' is not a
                     * number" for 'n 3' on line 5, vimp on line 6), or
                     * "syntax error" alone */
                    return gw_err_set(err, GW_EINVAL, "%s:%ld: '%.*s' is neither a key = value nor a [section] "
                                      "header%s", name, ln, (int)(end - i), p + i,
                                      key[0] || sect[0] ? "" : " (a config opens with [sweep])");
                }
            }
        }
        if (call >= 0) {
            /* the value (after the key's '=' or ':', or the whole continued line) */
            size_t v = i;
            if (call == 0)
                while (p[v] != '=' && p[v] != ':')
                    v++;
            const long hash = comment_hash(p, call == 0 ? v + 1 : v, end);
            if (hash >= 0)
                return gw_err_set(err, GW_EINVAL, "%s:%ld: %s%s: a '#' after a value starts no comment in a config, "
                                  "';' does: '%.*s' would be read as part of the value; write ';' for that '#'",
                                  name, ln, sect, key, (int)(end - (size_t)hash), p + hash);
            if (pc->ncalls == cap) {
                cap = cap ? 2 * cap : 64;
                unsigned char *c = realloc(pc->calls, (size_t)cap);
                if (!c)
                    return gw_err_set(err, GW_ENOMEM, "%s: out of memory", name);
                pc->calls = c;
            }
            pc->calls[pc->ncalls] = (unsigned char)call;
            if (call == 1)
                pc->calls[pc->ncalls - 1] |= 2; /* the previous call is this key's (blank and comment lines make none) */
            pc->ncalls++;
            comma = end > i && p[end - 1] == ',';
            /* A file whose last value line has no newline after it (LF, or the
             * CR of a CR LF) may be a file cut short there, and a value cut in
             * its digits still reads: 'vi = 10, 0.25' cut to 'vi = 10, 0.2'
             * ran another grid with exit 0, 't-max = 0.002' cut to
             * 't-max = 0.00' was refused only as a bad value. A comment or a
             * section header cut short changes nothing read (or is a syntax
             * error). The rule of text samples (layer_sample.c). */
            if (ln == cut)
                return gw_err_set(err, GW_EINVAL, "%s:%ld: the file ends inside this line (no newline after it): "
                                  "cut short? '%.*s' may hold a value cut short (0.25 cut to 0.2 still reads); end the file "
                                  "with a newline",
                                  name, ln, (int)(end - i), p + i);
        }
        if (!e)
            break;
        p = e + 1;
    }
    return GW_OK;
}

/* libinih reads a line into INI_MAX_LINE bytes (200 in Debian's build) and
 * parses what does not fit as the next line: 'point = 0, 1, ..., 99' was cut
 * after '49, 5' (refused as the value 5 listed twice; granwave.sweep writes
 * its lists this way), a longer value ended as a syntax error on the wrong
 * line or a path cut short. Lines that do not fit are refused whole. */
static int lines_fit(const char *text, const char *name, int whole, parse_ctx *pc, gw_err *err)
{
    const long max = INI_MAX_LINE - 2; /* the newline and the NUL fit too */
    long ln = 1;
    for (const char *p = text; *p; ln++) {
        const char *e = strchr(p, '\n');
        long len = e ? (long)(e - p) : (long)strlen(p);
        if (len > 0 && p[len - 1] == '\r')
            len--;
        /* a CR not ending the line: a file whose lines end in CR alone was one
         * line to the reader, refused as "no [sweep] model" (or as too long) */
        if (memchr(p, '\r', (size_t)len))
            return gw_err_set(err, GW_EINVAL, "%s:%ld: a carriage return inside the line: lines that end in CR "
                              "alone are one line to the config reader; convert them to LF (CR LF is read too)",
                              name, ln);
        /* a long comment too: the reader takes what does not fit as a line of
         * its own ("give integers as a range" was no help there) */
        const size_t lead = strspn(p, " \t");
        if (len > max && (long)lead < len && (p[lead] == ';' || p[lead] == '#'))
            return gw_err_set(err, GW_EINVAL, "%s:%ld: a comment of %ld characters, above the %ld of a line the "
                              "config reader takes (it reads the rest as another line): split it over several "
                              "comment lines", name, ln, len, max);
        if (len > max)
            return gw_err_set(err, GW_EINVAL, "%s:%ld: a line of %ld characters, above the %ld the config reader "
                              "takes: give integers as a range A:B, or go on over indented lines after a comma", name, ln, len, max);
        if (!e)
            break;
        p = e + 1;
    }
    return scan_lines(text, name, whole, pc, err);
}

int gw_sweep_config_read(const char *path, const gw_sweep_model *const *models, int nmodels,
                         gw_sweep_config *cfg, const gw_sweep_model **model, gw_err *err)
{
    if (cfg) /* emptied on every refusal, a NULL argument's too (docs/library.md) */
        memset(cfg, 0, sizeof *cfg);
    if (model)
        *model = NULL;
    if (!cfg || !model || !path || !models)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_config_read: %s is NULL",
                          !cfg ? "cfg" : !model ? "model" : !path ? "path" : "models");
    parse_ctx pc = {cfg, models, nmodels, "", 0, 0, NULL, 0, 0, NULL, 0, NULL};
    char *text = NULL;
    size_t len = 0;
    int rc = gw_input_read(path, "sweep CONFIG", GW_SWEEP_CONFIG_MAX, &text, &len, err);
    if (rc != GW_OK) /* a config that cannot be read is bad input (exit 2); out of memory is not */
        return rc == GW_ENOMEM ? rc : GW_EINVAL;
    /* the reader takes the text as a C string: everything after a NUL byte was
     * dropped without a word ('rings = 2' after one ran the default rings) */
    const char *nul = memchr(text, '\0', len);
    if (nul) {
        long ln = 1;
        for (const char *q = text; q < nul; q++)
            ln += *q == '\n';
        free(text);
        return gw_err_set(err, GW_EINVAL, "%s:%ld: a NUL byte (binary data, not a config)", path, ln);
    }
    if ((rc = lines_fit(text, path, 1, &pc, err)) != GW_OK) {
        free(text);
        free(pc.calls);
        return rc == GW_ENOMEM ? rc : GW_EINVAL;
    }
    rc = ini_parse_string(text, handler, &pc);
    free(text);
    free(pc.calls);
    free(pc.pending);
    int drc = GW_OK;
    char *base = gw_sweep_config_dir(path, &drc, err);
    if (!base) {
        gw_sweep_config_free(cfg);
        return drc;
    }
    rc = config_finish(path, base, models, nmodels, cfg, model, rc, &pc, err);
    free(base);
    if (rc != GW_OK)
        return rc;
    if (!(cfg->path = strdup(path))) {
        gw_sweep_config_free(cfg);
        *model = NULL;
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", path);
    }
    return GW_OK;
}

int gw_sweep_config_read_string(const char *text, const char *name, const gw_sweep_model *const *models,
                                int nmodels, gw_sweep_config *cfg, const gw_sweep_model **model, gw_err *err)
{
    if (cfg) /* emptied on every refusal, a NULL argument's too (docs/library.md) */
        memset(cfg, 0, sizeof *cfg);
    if (model)
        *model = NULL;
    if (!cfg || !model || !text || !models)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_config_read_string: %s is NULL",
                          !cfg ? "cfg" : !model ? "model" : !text ? "text" : "models");
    /* the bound of a config file (gw_sweep_config_read), for a config given as text too */
    size_t len = strlen(text);
    if (len > (size_t)GW_SWEEP_CONFIG_MAX)
        return gw_err_set(err, GW_EINVAL, "%s: the config takes %zu bytes, above the %ld of a sweep config", name,
                          len, GW_SWEEP_CONFIG_MAX);
    parse_ctx pc = {cfg, models, nmodels, "", 0, 0, NULL, 0, 0, NULL, 0, NULL};
    int lrc = lines_fit(text, name, 0, &pc, err);
    if (lrc != GW_OK) {
        free(pc.calls);
        return lrc == GW_ENOMEM ? lrc : GW_EINVAL;
    }
    int rc = ini_parse_string(text, handler, &pc);
    free(pc.calls);
    free(pc.pending);
    return config_finish(name, NULL, models, nmodels, cfg, model, rc, &pc, err);
}

static int config_finish(const char *path, const char *base, const gw_sweep_model *const *models, int nmodels,
                         gw_sweep_config *cfg, const gw_sweep_model **model, int rc,
                         const parse_ctx *pc, gw_err *err)
{
    if (rc == -1) {
        gw_sweep_config_free(cfg);
        return gw_err_set(err, GW_EINVAL, "%s: cannot open the config file", path);
    }
    if (rc == -2 || (rc > 0 && pc->nomem)) { /* the reader's line buffer, or a handler's copy */
        gw_sweep_config_free(cfg);
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory reading the config", path);
    }
    if (rc != 0) {
        gw_err_set(err, GW_EINVAL, "%s:%d: %s", path, rc, pc->msg[0] ? pc->msg : "syntax error");
        gw_sweep_config_free(cfg);
        return GW_EINVAL;
    }
    if (!cfg->model) {
        gw_sweep_config_free(cfg);
        return gw_err_set(err, GW_EINVAL, "%s: no [sweep] model", path);
    }
    for (int i = 0; i < nmodels; i++)
        if (strcmp(models[i]->name, cfg->model) == 0)
            *model = models[i];
    if (!*model) {
        gw_err_set(err, GW_EINVAL, "%s: unknown model '%s'", path, cfg->model);
        gw_sweep_config_free(cfg);
        return GW_EINVAL;
    }
    cfg->read_key = (*model)->read_key;
    cfg->ncolumns = (*model)->ncolumns;
    if (cfg->ngrid == 0) {
        gw_sweep_config_free(cfg);
        return gw_err_set(err, GW_EINVAL, "%s: the [grid] section is empty or missing", path);
    }
    if (base && (rc = gw_sweep_resolve_paths(cfg, base, path, err)) != GW_OK) {
        gw_sweep_config_free(cfg);
        return rc;
    }
    /* the files the cases read pass their reader's rules before any byte of
     * them is hashed (the config's hash, the inputs' hashes) */
    if ((rc = gw_sweep_inputs_readable(cfg, path, err)) != GW_OK) {
        gw_sweep_config_free(cfg);
        return rc;
    }
    cfg->ncases = 1;
    int nomem = 0;
    unsigned long h = fnv64(14695981039346656037UL, cfg->model);
    for (int i = 0; i < cfg->ngrid; i++) {
        cfg->ncases *= cfg->grid[i].nvalues;
        if (cfg->ncases > 1000000000L) {
            gw_sweep_config_free(cfg);
            return gw_err_set(err, GW_EINVAL, "%s: the grid has more than 1e9 cases", path);
        }
        h = fnv64(h, cfg->grid[i].name);
        const int file = gw_sweep_names_file(cfg, cfg->grid[i].name);
        for (int j = 0; j < cfg->grid[i].nvalues; j++) {
            h = fnv64(h, cfg->grid[i].values[j]);
            if (file)
                h = fnv64_file(h, cfg->grid[i].values[j], &nomem);
        }
    }
    for (int i = 0; i < cfg->nparams; i++) {
        h = fnv64(fnv64(h, cfg->params[i].name), cfg->params[i].values[0]);
        if (gw_sweep_names_file(cfg, cfg->params[i].name))
            h = fnv64_file(h, cfg->params[i].values[0], &nomem);
    }
    if (nomem) {
        gw_sweep_config_free(cfg);
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory reading the files it names", path);
    }
    cfg->hash = h;
    return gw_sweep_find_inputs(path, cfg, err);
}

static void free_keys(gw_sweep_key *k, int n)
{
    for (int i = 0; i < n; i++) {
        for (int j = 0; k[i].values && j < k[i].nvalues; j++)
            free(k[i].values[j]);
        free(k[i].values);
        free(k[i].name);
    }
}

void gw_sweep_config_free(gw_sweep_config *cfg)
{
    if (!cfg)
        return;
    free_keys(cfg->grid, cfg->ngrid);
    free_keys(cfg->params, cfg->nparams);
    free(cfg->inputs);
    free(cfg->model);
    free(cfg->out);
    free(cfg->path);
    memset(cfg, 0, sizeof *cfg);
}

/* The shape of a config (counts, arrays, the case count), without its values:
 * what gw_sweep_case reads at every case. */
static int config_shape(const gw_sweep_config *cfg, gw_err *err)
{
    if (cfg->ngrid < 0 || cfg->ngrid > GW_SWEEP_MAX_KEYS || cfg->nparams < 0 || cfg->nparams > GW_SWEEP_MAX_KEYS)
        return gw_err_set(err, GW_EINVAL, "sweep config: %d grid keys and %d params (each in [0, %d])", cfg->ngrid,
                          cfg->nparams, GW_SWEEP_MAX_KEYS);
    long prod = 1;
    for (int i = 0; i < cfg->ngrid + cfg->nparams; i++) {
        const int grid = i < cfg->ngrid;
        const gw_sweep_key *key = grid ? &cfg->grid[i] : &cfg->params[i - cfg->ngrid];
        if (!key->name || !key->values || key->nvalues < 1)
            return gw_err_set(err, GW_EINVAL, "sweep config: %s %d ('%s') has %d values%s%s", grid ? "grid key" : "param",
                              grid ? i : i - cfg->ngrid, key->name ? key->name : "(NULL name)", key->nvalues,
                              key->values ? "" : " and no array", key->nvalues < 1 ? " (at least 1)" : "");
        if (grid) {
            prod *= key->nvalues;
            if (prod > 1000000000L)
                return gw_err_set(err, GW_EINVAL, "sweep config: the grid has more than 1e9 cases");
        }
    }
    /* a zeroed config (no grid) has no case */
    if (cfg->ncases != prod && !(cfg->ngrid == 0 && cfg->ncases == 0))
        return gw_err_set(err, GW_EINVAL, "sweep config: ncases %ld is not the grid's %ld cases (the product of its "
                          "keys' value counts)", cfg->ncases, cfg->ngrid ? prod : 0L);
    return GW_OK;
}

int gw_sweep_config_check(const gw_sweep_config *cfg, gw_err *err)
{
    if (!cfg)
        return gw_err_set(err, GW_EINVAL, "sweep config is NULL");
    int rc = config_shape(cfg, err);
    for (int i = 0; rc == GW_OK && i < cfg->ngrid + cfg->nparams; i++) {
        const int grid = i < cfg->ngrid;
        const gw_sweep_key *key = grid ? &cfg->grid[i] : &cfg->params[i - cfg->ngrid];
        for (int j = 0; j < key->nvalues; j++)
            if (!key->values[j])
                return gw_err_set(err, GW_EINVAL, "sweep config: %s '%s': value %d is NULL", grid ? "grid key" : "param",
                                  key->name, j);
    }
    if (rc == GW_OK && (cfg->ninputs < 0 || (cfg->ninputs > 0 && !cfg->inputs)))
        return gw_err_set(err, GW_EINVAL, "sweep config: %d inputs%s", cfg->ninputs,
                          cfg->ninputs < 0 ? " (a negative count)" : " and no array");
    for (int i = 0; rc == GW_OK && i < cfg->ninputs; i++)
        if (!cfg->inputs[i].key || !cfg->inputs[i].value)
            return gw_err_set(err, GW_EINVAL, "sweep config: input %d has a NULL key or value", i);
    return rc;
}

int gw_sweep_case(const gw_sweep_config *cfg, long k, const char **names, const char **values)
{
    if (!cfg || !names || !values)
        return GW_EINVAL;
    /* a config filled by hand: a key of no values divided by zero (SIGFPE), a
     * NULL array or more keys than the struct holds were read, a case count
     * beyond the grid's gave its cases again */
    if (k < 0 || k >= cfg->ncases || config_shape(cfg, NULL) != GW_OK)
        return GW_EINVAL;
    for (int i = cfg->ngrid - 1; i >= 0; i--) {
        names[i] = cfg->grid[i].name;
        values[i] = cfg->grid[i].values[k % cfg->grid[i].nvalues];
        k /= cfg->grid[i].nvalues;
        if (!values[i])
            return GW_EINVAL;
    }
    for (int i = 0; i < cfg->nparams; i++) {
        names[cfg->ngrid + i] = cfg->params[i].name;
        values[cfg->ngrid + i] = cfg->params[i].values[0];
        if (!values[cfg->ngrid + i])
            return GW_EINVAL;
    }
    return GW_OK;
}

unsigned long long gw_sweep_case_hash(const gw_sweep_config *cfg, long k)
{
    if (!cfg) /* (as a case that does not exist) */
        return 0;
    const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
    if (gw_sweep_case(cfg, k, names, values) != GW_OK)
        return 0;
    return gw_case_config_hash(cfg->model, cfg->ngrid + cfg->nparams, names, values);
}
