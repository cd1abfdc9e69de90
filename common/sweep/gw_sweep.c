/*
 * gw_sweep.c: sweep configs (libinih), grid expansion, the append-only journal
 * and the final table (see gw_sweep.h). A journal row is complete only with its
 * trailing FNV-1a checksum and newline, so a row torn by kill -9 is detected and
 * dropped on the next run; rows are appended with one write() each (a kill
 * loses none: the row is in the kernel's cache once write() returns) and the
 * journal is fsynced at most every GW_SWEEP_SYNC_MS and at the sweep's end, so
 * a power cut loses at most the rows of that interval, which the rerun runs
 * again. An fsync per row made a 0.32 ms case cost 3.7 ms.
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
#include "gw_locale.h"

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
} parse_ctx;

static char *dupstr(const char *s)
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
            if (!(k->values[i] = dupstr(buf)))
                return parse_nomem(pc);
        }
        return 1;
    }
    char *copy = dupstr(value);
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
        if (!(k->values[k->nvalues] = dupstr(t))) {
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
    for (int i = 0; k->values && i < k->nvalues; i++)
        for (int j = 0; j < i; j++) {
            char *ei, *ej;
            double vi = gw_strtod(k->values[i], &ei), vj = gw_strtod(k->values[j], &ej);
            const int fi = gw_parse_flag(k->values[i]), fj = gw_parse_flag(k->values[j]);
            if (strcmp(k->values[i], k->values[j]) == 0 || (!*ei && !*ej && ei != k->values[i] && vi == vj) ||
                (fi >= 0 && fi == fj)) {
                gw_snprintf(msg, mlen, "%s: '%s' and '%s' in list '%s' are the same value (each case would run "
                         "twice)", k->name, k->values[j], k->values[i], value);
                return 0;
            }
        }
    return k->values != NULL;
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
        char **dst = strcmp(name, "model") == 0 ? &cfg->model : strcmp(name, "out") == 0 ? &cfg->out : NULL;
        if (!dst) {
            gw_snprintf(pc->msg, sizeof pc->msg, "unknown key '%s' in [sweep] (model, out)", name);
            return 0;
        }
        if (*dst) {
            gw_snprintf(pc->msg, sizeof pc->msg, "duplicate key '%s'", name);
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
        *dst = dupstr(value);
        return *dst ? 1 : parse_nomem(pc);
    }
    int is_grid = strcmp(section, "grid") == 0;
    if (!is_grid && strcmp(section, "params") != 0) {
        gw_snprintf(pc->msg, sizeof pc->msg, "unknown section [%s] (sweep, grid, params)", section);
        return 0;
    }
    if (!cfg->model) {
        gw_snprintf(pc->msg, sizeof pc->msg, "[sweep] model must come before [%s]", section);
        return 0;
    }
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
    if (find_key(cfg->grid, cfg->ngrid, name) >= 0 || find_key(cfg->params, cfg->nparams, name) >= 0) {
        gw_snprintf(pc->msg, sizeof pc->msg, "duplicate key '%s'", name);
        return 0;
    }
    gw_sweep_key *keys = is_grid ? cfg->grid : cfg->params;
    int *nk = is_grid ? &cfg->ngrid : &cfg->nparams;
    if (*nk >= GW_SWEEP_MAX_KEYS) {
        gw_snprintf(pc->msg, sizeof pc->msg, "more than %d keys in [%s]", GW_SWEEP_MAX_KEYS, section);
        return 0;
    }
    gw_sweep_key *k = &keys[(*nk)++];
    memset(k, 0, sizeof *k);
    k->name = dupstr(name);
    if (!k->name)
        return parse_nomem(pc);
    if (is_grid)
        return split_values(value, k, pc);
    k->values = calloc(1, sizeof *k->values);
    if (!k->values || !(k->values[0] = dupstr(value)))
        return parse_nomem(pc);
    k->nvalues = 1;
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
    FILE *f = NULL;
    gw_err err;
    int rc = gw_input_open(path, "sweep", &f, &err); /* never blocks on a FIFO */
    if (rc == GW_ENOMEM) /* the file left out of the hash: another sweep's identity */
        *nomem = 1;
    if (rc != GW_OK)
        return h;
    unsigned char buf[8192]; /* 64 KiB here overflowed a 64 KiB stack (ulimit -s 64) */
    size_t got;
    while ((got = fread(buf, 1, sizeof buf, f)) > 0)
        for (size_t i = 0; i < got; i++) {
            h ^= buf[i];
            h *= 1099511628211UL;
        }
    fclose(f);
    return h ^ 0xfe;
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
 * blank starts a comment; a line with neither '=' nor ':' calls no handler. */
static int scan_lines(const char *text, const char *name, parse_ctx *pc, gw_err *err)
{
    char key[64] = "";
    long key_ln = 0, ln = 1, cap = 0;
    int in_grid = 0, comma = 0; /* the last value line of the key ends with ',' */
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
                in_grid = q && q - (p + i) == 5 && memcmp(p + i, "[grid", 5) == 0;
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
                }
            }
        }
        if (call >= 0) {
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
static int lines_fit(const char *text, const char *name, parse_ctx *pc, gw_err *err)
{
    const long max = INI_MAX_LINE - 2; /* the newline and the NUL fit too */
    long ln = 1;
    for (const char *p = text; *p; ln++) {
        const char *e = strchr(p, '\n');
        long len = e ? (long)(e - p) : (long)strlen(p);
        if (len > 0 && p[len - 1] == '\r')
            len--;
        if (len > max)
            return gw_err_set(err, GW_EINVAL, "%s:%ld: a line of %ld characters, above the %ld the config reader "
                              "takes: give integers as a range A:B, or go on over indented lines after a comma", name, ln, len, max);
        if (!e)
            break;
        p = e + 1;
    }
    return scan_lines(text, name, pc, err);
}

/* The directory of the config file at path, absolute (realpath of the part
 * before its last '/', "." without one); NULL with err set when it cannot be
 * found. */
static char *config_dir(const char *path, int *status, gw_err *err)
{
    const char *slash = strrchr(path, '/');
    char *dir = slash ? malloc((size_t)(slash - path) + 2) : dupstr(".");
    if (dir && slash) {
        const size_t n = slash == path ? 1 : (size_t)(slash - path); /* "/x.ini": "/" */
        memcpy(dir, path, n);
        dir[n] = '\0';
    }
    char *real = dir ? realpath(dir, NULL) : NULL;
    const int e = errno;
    free(dir);
    if (!real)
        *status = gw_err_set(err, e == ENOMEM || !dir ? GW_ENOMEM : GW_EINVAL,
                             "%s: cannot find the config's directory: %s", path, strerror(e));
    return real;
}

/* value resolved against base (the config's directory): a relative path is
 * taken from the config's directory, an absolute one is kept. *value
 * replaced by a new string; GW_ENOMEM. */
static int resolve_one(char **value, const char *base)
{
    if ((*value)[0] == '/')
        return GW_OK;
    const size_t bl = strlen(base), vl = strlen(*value);
    char *r = malloc(bl + vl + 2);
    if (!r)
        return GW_ENOMEM;
    memcpy(r, base, bl);
    size_t at = bl;
    if (!(bl > 0 && base[bl - 1] == '/')) /* base "/" */
        r[at++] = '/';
    memcpy(r + at, *value, vl + 1);
    free(*value);
    *value = r;
    return GW_OK;
}

/* A relative file named in the config that is not there: refused naming the
 * key, the value as written and the path it was taken as. */
static int resolved_missing(const char *path, const char *section, const char *key, const char *written,
                            const char *resolved, gw_err *err)
{
    struct stat sb;
    if (stat(resolved, &sb) == 0 || (errno != ENOENT && errno != ENOTDIR))
        return GW_OK; /* there (or unreadable: the model's check names it) */
    return gw_err_set(err, GW_EINVAL, "%s: [%s] %s = %s: no such file %s (a relative path in a config is taken "
                      "from the config's directory)", path, section, key, written, resolved);
}

/* The paths a config names, taken from the config's directory (base,
 * absolute) instead of the working directory: [sweep] out and the values of
 * the model's read_key (the layer's sample). The same config then names the
 * same files from every working directory, and the journal and the table
 * record the paths the cases read. A relative read_key value that names
 * nothing there is refused. */
static int resolve_paths(gw_sweep_config *cfg, const char *base, const char *path, gw_err *err)
{
    if (cfg->out && resolve_one(&cfg->out, base) != GW_OK)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", path);
    if (!cfg->read_key)
        return GW_OK;
    for (int s = 0; s < 2; s++) {
        gw_sweep_key *keys = s ? cfg->params : cfg->grid;
        const int nk = s ? cfg->nparams : cfg->ngrid;
        for (int i = 0; i < nk; i++) {
            if (strcmp(keys[i].name, cfg->read_key) != 0)
                continue;
            for (int j = 0; j < keys[i].nvalues; j++) {
                if (keys[i].values[j][0] == '/')
                    continue;
                char *written = dupstr(keys[i].values[j]);
                int rc = written ? resolve_one(&keys[i].values[j], base) : GW_ENOMEM;
                if (rc != GW_OK) {
                    free(written);
                    return gw_err_set(err, GW_ENOMEM, "%s: out of memory", path);
                }
                rc = resolved_missing(path, s ? "params" : "grid", keys[i].name, written, keys[i].values[j], err);
                free(written);
                if (rc != GW_OK)
                    return rc;
            }
        }
    }
    return GW_OK;
}

int gw_sweep_config_read(const char *path, const gw_sweep_model *const *models, int nmodels,
                         gw_sweep_config *cfg, const gw_sweep_model **model, gw_err *err)
{
    if (!cfg || !model || !path || !models)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_config_read: %s is NULL",
                          !cfg ? "cfg" : !model ? "model" : !path ? "path" : "models");
    memset(cfg, 0, sizeof *cfg);
    *model = NULL;
    parse_ctx pc = {cfg, models, nmodels, "", 0, 0, NULL, 0, 0, NULL, 0};
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
    if ((rc = lines_fit(text, path, &pc, err)) != GW_OK) {
        free(text);
        free(pc.calls);
        return rc == GW_ENOMEM ? rc : GW_EINVAL;
    }
    rc = ini_parse_string(text, handler, &pc);
    free(text);
    free(pc.calls);
    free(pc.pending);
    int drc = GW_OK;
    char *base = config_dir(path, &drc, err);
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
    if (!cfg || !model || !text || !models)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_config_read_string: %s is NULL",
                          !cfg ? "cfg" : !model ? "model" : !text ? "text" : "models");
    memset(cfg, 0, sizeof *cfg);
    *model = NULL;
    /* the bound of a config file (gw_sweep_config_read), for a config given as text too */
    size_t len = strlen(text);
    if (len > (size_t)GW_SWEEP_CONFIG_MAX)
        return gw_err_set(err, GW_EINVAL, "%s: the config takes %zu bytes, above the %ld of a sweep config", name,
                          len, GW_SWEEP_CONFIG_MAX);
    parse_ctx pc = {cfg, models, nmodels, "", 0, 0, NULL, 0, 0, NULL, 0};
    int lrc = lines_fit(text, name, &pc, err);
    if (lrc != GW_OK) {
        free(pc.calls);
        return lrc == GW_ENOMEM ? lrc : GW_EINVAL;
    }
    int rc = ini_parse_string(text, handler, &pc);
    free(pc.calls);
    free(pc.pending);
    return config_finish(name, NULL, models, nmodels, cfg, model, rc, &pc, err);
}

/* A value naming a regular file: its content hash into cfg->inputs (once per
 * key and value). */
static int add_input(gw_sweep_config *cfg, const char *key, const char *value, long *cap)
{
    struct stat sb;
    if (stat(value, &sb) != 0 || !S_ISREG(sb.st_mode))
        return GW_OK;
    unsigned long long fh;
    gw_err e;
    int rc = gw_fnv1a64_file(value, "sweep", &fh, &e);
    if (rc != GW_OK) /* unreadable: the model's check names it; out of memory: said here */
        return rc == GW_ENOMEM ? rc : GW_OK;
    for (int i = 0; i < cfg->ninputs; i++)
        if (strcmp(cfg->inputs[i].key, key) == 0 && strcmp(cfg->inputs[i].value, value) == 0)
            return GW_OK;
    if (cfg->ninputs == *cap) {
        long nc = *cap ? 2 * *cap : 8;
        void *p = realloc(cfg->inputs, (size_t)nc * sizeof *cfg->inputs);
        if (!p)
            return GW_ENOMEM;
        cfg->inputs = p;
        *cap = nc;
    }
    cfg->inputs[cfg->ninputs++] = (struct gw_sweep_input){key, value, fh};
    return GW_OK;
}

/* 1 when the values of key name name files the cases read: the model's
 * read_key only. Every value that named a regular file was taken as one: a
 * chain sweep ('solver = rk4', 'n = 1:40') run where a file 'rk4' or '5'
 * happened to be had that file's bytes in its identity, so its rerun from
 * another directory, or after the file changed, was refused as "another
 * sweep (different config)", and a change to the file while it ran stopped
 * it ("solver 'rk4' changed while the sweep ran"). */
static int names_file(const gw_sweep_config *cfg, const char *name)
{
    return cfg->read_key && strcmp(cfg->read_key, name) == 0;
}

static int find_inputs(const char *path, gw_sweep_config *cfg, gw_err *err)
{
    long cap = 0;
    int rc = GW_OK;
    for (int i = 0; rc == GW_OK && i < cfg->ngrid; i++)
        for (int j = 0; rc == GW_OK && names_file(cfg, cfg->grid[i].name) && j < cfg->grid[i].nvalues; j++)
            rc = add_input(cfg, cfg->grid[i].name, cfg->grid[i].values[j], &cap);
    for (int i = 0; rc == GW_OK && i < cfg->nparams; i++)
        if (names_file(cfg, cfg->params[i].name))
            rc = add_input(cfg, cfg->params[i].name, cfg->params[i].values[0], &cap);
    if (rc != GW_OK) {
        gw_sweep_config_free(cfg);
        return gw_err_set(err, rc, "%s: out of memory", path);
    }
    return GW_OK;
}

int gw_sweep_inputs_check(const gw_sweep_config *cfg, gw_err *err)
{
    return gw_sweep_case_inputs_check(cfg, -1, err);
}

/* 1 when case k (k < 0: every case) reads input in. */
static int case_reads(const gw_sweep_config *cfg, long k, const struct gw_sweep_input *in)
{
    const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
    if (k < 0 || gw_sweep_case(cfg, k, names, values) != GW_OK)
        return 1;
    for (int j = 0; j < cfg->ngrid + cfg->nparams; j++)
        if (strcmp(names[j], in->key) == 0 && strcmp(values[j], in->value) == 0)
            return 1;
    return 0;
}

int gw_sweep_case_inputs_check(const gw_sweep_config *cfg, long k, gw_err *err)
{
    for (int i = 0; i < cfg->ninputs; i++) {
        const struct gw_sweep_input *in = &cfg->inputs[i];
        if (!case_reads(cfg, k, in))
            continue;
        unsigned long long fh = 0;
        gw_err e;
        if (gw_fnv1a64_file(in->value, in->key, &fh, &e) != GW_OK)
            return gw_err_set(err, GW_EINVAL, "%s '%s' cannot be read any more while the sweep runs (%s)", in->key,
                              in->value, e.msg);
        if (fh != in->hash)
            return gw_err_set(err, GW_EINVAL, "%s '%s' changed while the sweep ran (content fnv1a64 %016llx when it "
                              "started, now %016llx): the case that just finished may have read either; its row is "
                              "not kept. Restore the file and rerun to resume, or start a new sweep", in->key,
                              in->value, in->hash, fh);
    }
    return GW_OK;
}

/* "# input KEY = VALUE fnv1a64 HEX" lines of cfg, then its "# grid KEY = v1,
 * v2, ..." lines (the values as the config gives them, ranges listed) and
 * "# param KEY = VALUE" lines in the config's order, into a new string. A
 * journal held the config's hash alone: a rerun after a small edit that makes
 * another sweep (0.1 spelt 1e-1, two [params] lines swapped) was refused as
 * "another sweep (different config)", naming nothing the user could find. */
static char *input_lines(const gw_sweep_config *cfg)
{
    size_t n = 1;
    for (int i = 0; i < cfg->ninputs; i++)
        n += strlen(cfg->inputs[i].key) + strlen(cfg->inputs[i].value) + 48;
    for (int i = 0; i < cfg->ngrid; i++) {
        n += strlen(cfg->grid[i].name) + 12;
        for (int j = 0; j < cfg->grid[i].nvalues; j++)
            n += strlen(cfg->grid[i].values[j]) + 2;
    }
    for (int i = 0; i < cfg->nparams; i++)
        n += strlen(cfg->params[i].name) + strlen(cfg->params[i].values[0]) + 14;
    char *s = malloc(n), *p = s;
    if (!s)
        return NULL;
    *p = '\0';
    for (int i = 0; i < cfg->ninputs; i++)
        p += gw_snprintf(p, n - (size_t)(p - s), "# input %s = %s fnv1a64 %016llx\n", cfg->inputs[i].key,
                      cfg->inputs[i].value, cfg->inputs[i].hash);
    for (int i = 0; i < cfg->ngrid; i++) {
        p += gw_snprintf(p, n - (size_t)(p - s), "# grid %s = ", cfg->grid[i].name);
        for (int j = 0; j < cfg->grid[i].nvalues; j++)
            p += gw_snprintf(p, n - (size_t)(p - s), "%s%s", j ? ", " : "", cfg->grid[i].values[j]);
        p += gw_snprintf(p, n - (size_t)(p - s), "\n");
    }
    for (int i = 0; i < cfg->nparams; i++)
        p += gw_snprintf(p, n - (size_t)(p - s), "# param %s = %s\n", cfg->params[i].name, cfg->params[i].values[0]);
    return s;
}

/* The journal's "# grid" or "# param" line of key name (sec "grid " or
 * "param "): its value (the text after " = ") and length, or NULL. nth: the
 * key's place among the journal's lines of that section. */
static const char *journal_key(const char *buf, size_t len, const char *sec, const char *name, size_t *vl, int *nth)
{
    const size_t sl = strlen(sec), nl = strlen(name);
    *nth = 0;
    for (const char *p = memchr(buf, '\n', len); p && (size_t)(p + 1 - buf) < len && p[1] == '#';
         p = memchr(p + 1, '\n', len - (size_t)(p + 1 - buf))) {
        const char *line = p + 1, *end = memchr(line, '\n', len - (size_t)(line - buf));
        if (!end)
            break;
        if ((size_t)(end - line) < 2 + sl || memcmp(line + 2, sec, sl) != 0)
            continue;
        const char *k = line + 2 + sl;
        if ((size_t)(end - k) >= nl + 3 && memcmp(k, name, nl) == 0 && memcmp(k + nl, " = ", 3) == 0) {
            *vl = (size_t)(end - k - nl - 3);
            return k + nl + 3;
        }
        (*nth)++;
    }
    return NULL;
}

/* The number of "# SEC" lines in the journal's head. */
static int journal_nkeys(const char *buf, size_t len, const char *sec)
{
    int n = 0;
    size_t vl;
    journal_key(buf, len, sec, "\n", &vl, &n); /* no key is named "\n": counts them all */
    return n;
}

/* a and b (n values of a key, or one text a and the list b) are the same
 * numbers, spelt otherwise: 1 (0.1 and 1e-1) */
static int same_numbers(const char *a, size_t al, char *const *b, int nb)
{
    char *copy = malloc(al + 1), *save = NULL;
    if (!copy)
        return 0;
    memcpy(copy, a, al);
    copy[al] = '\0';
    int i = 0, same = 1;
    for (char *t = strtok_r(copy, ",", &save); same && t; t = strtok_r(NULL, ",", &save), i++) {
        char *e1, *e2;
        t = gw_str_trim(t);
        if (i >= nb) {
            same = 0;
            break;
        }
        double x = gw_strtod(t, &e1), y = gw_strtod(b[i], &e2);
        same = e1 != t && !*e1 && e2 != b[i] && !*e2 && x == y;
    }
    free(copy);
    return same && i == nb;
}

/* An existing journal of another config: name the first key whose place or
 * value differs from cfg's (journals that record their keys: "# grid" and
 * "# param" lines). GW_OK when it cannot tell. */
static int changed_keys(const gw_sweep_config *cfg, const char *buf, size_t len, const char *dir, gw_err *err)
{
    static const char *const fix = "remove the journal or choose another output to start this one";
    const int ng = journal_nkeys(buf, len, "grid "), np = journal_nkeys(buf, len, "param ");
    if (ng == 0)
        return GW_OK; /* a journal before these lines */
    for (int sec = 0; sec < 2; sec++) {
        const gw_sweep_key *keys = sec ? cfg->params : cfg->grid;
        const int n = sec ? cfg->nparams : cfg->ngrid, nj = sec ? np : ng;
        const char *sname = sec ? "param " : "grid ", *what = sec ? "[params]" : "[grid]";
        for (int i = 0; i < n; i++) {
            size_t vl = 0;
            int at = 0;
            const char *v = journal_key(buf, len, sname, keys[i].name, &vl, &at);
            if (!v)
                return gw_err_set(err, GW_EINVAL, "%s: this directory holds another sweep: %s %s is not in the "
                                  "config of its journal; %s", dir, what, keys[i].name, fix);
            /* the config's values as the journal writes them */
            size_t cl = 0;
            for (int j = 0; j < keys[i].nvalues; j++)
                cl += strlen(keys[i].values[j]) + (j ? 2 : 0);
            char *c = malloc(cl + 1), *q = c;
            if (!c)
                return gw_err_set(err, GW_ENOMEM, "%s: out of memory", dir);
            for (int j = 0; j < keys[i].nvalues; j++)
                q += gw_snprintf(q, cl + 1 - (size_t)(q - c), "%s%s", j ? ", " : "", keys[i].values[j]);
            const int same = vl == cl && memcmp(v, c, cl) == 0;
            const int ci = (int)(cl < 160 ? cl : 160), vi = (int)(vl < 160 ? vl : 160);
            int rc = GW_OK;
            if (!same && same_numbers(v, vl, keys[i].values, keys[i].nvalues))
                rc = gw_err_set(err, GW_EINVAL, "%s: this directory holds another sweep: %s %s = %.*s%s here, %.*s%s "
                                "in its journal, the same numbers spelt otherwise (rows and hashes hold the values as "
                                "spelt): spell them as the journal does to resume, or %s", dir, what, keys[i].name,
                                ci, c, ci < (int)cl ? "..." : "", vi, v, vi < (int)vl ? "..." : "", fix);
            else if (!same)
                rc = gw_err_set(err, GW_EINVAL, "%s: this directory holds another sweep: %s %s = %.*s%s here, %.*s%s "
                                "in its journal; %s", dir, what, keys[i].name, ci, c, ci < (int)cl ? "..." : "", vi,
                                v, vi < (int)vl ? "..." : "", fix);
            else if (at != i)
                rc = gw_err_set(err, GW_EINVAL, "%s: this directory holds another sweep: its journal has the %s "
                                "keys in another order (%s is key %d here, %d there; %s): restore the journal's "
                                "order to resume, or %s", dir, what, keys[i].name, i + 1, at + 1,
                                sec ? "each row's config hash is over the [params] in order"
                                    : "the case numbers would name other combinations", fix);
            free(c);
            if (rc != GW_OK)
                return rc;
        }
        if (nj > n)
            return gw_err_set(err, GW_EINVAL, "%s: this directory holds another sweep: its journal has %d %s keys, "
                              "the config %d; %s", dir, nj, what, n, fix);
    }
    return GW_OK;
}

/* The content hash that ends a journal's "# input KEY = VALUE fnv1a64 HEX"
 * line [line, end): 16 lowercase hex digits, no more, no less (strtoull took
 * " 0x12", "-1" and a shorter hash). *at: where " fnv1a64 " starts. GW_EINVAL
 * naming the journal's line when it is not so. */
static int input_line_hash(const char *path, long lineno, const char *line, const char *end, const char **at,
                           unsigned long long *h, gw_err *err)
{
    const char *f = NULL;
    for (const char *q = line; q + 9 <= end; q++)
        if (memcmp(q, " fnv1a64 ", 9) == 0)
            f = q;
    if (f && gw_fnv1a64_parse(f + 9, (size_t)(end - f - 9), h)) {
        *at = f;
        return GW_OK;
    }
    const int n = (int)(end - line) < 200 ? (int)(end - line) : 200;
    return gw_err_set(err, GW_EINVAL, "%s:%ld: '# input %.*s' does not end with ' fnv1a64 ' and the file's content "
                      "hash in 16 hex digits (an edited journal): restore the line, or remove the journal to rerun "
                      "its cases", path, lineno, n, line);
}

/* An existing journal of another config: when one of its "# input" lines
 * names a file of this config whose content differs, say so (a resumed sweep
 * of the same config over a changed sample was "another sweep (different
 * config)", naming neither the file nor the change). */
static int changed_input(const gw_sweep_config *cfg, const char *buf, size_t len, const char *path,
                         const char *dir, gw_err *err)
{
    const char *p = memchr(buf, '\n', len);
    long lineno = 1;
    while (p && (size_t)(p + 1 - buf) < len && strncmp(p + 1, "# input ", 8) == 0) {
        const char *line = p + 9, *end = memchr(line, '\n', len - (size_t)(line - buf)), *at = NULL;
        if (!end)
            break;
        unsigned long long was;
        int rc = input_line_hash(path, ++lineno, line, end, &at, &was, err);
        if (rc != GW_OK)
            return rc;
        for (int i = 0; i < cfg->ninputs; i++) {
            const struct gw_sweep_input *in = &cfg->inputs[i];
            size_t kl = strlen(in->key), vl = strlen(in->value);
            if ((size_t)(at - line) == kl + 3 + vl && strncmp(line, in->key, kl) == 0 &&
                strncmp(line + kl, " = ", 3) == 0 && strncmp(line + kl + 3, in->value, vl) == 0 &&
                was != in->hash)
                return gw_err_set(err, GW_EINVAL, "%s: %s '%s' changed since the sweep in it started (content "
                                  "fnv1a64 %016llx in its journal, now %016llx): its finished cases ran on the "
                                  "old file; restore it, or choose another output", dir, in->key, in->value,
                                  was, in->hash);
        }
        p = end;
    }
    return GW_OK;
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
    if (cfg->ngrid == 0) {
        gw_sweep_config_free(cfg);
        return gw_err_set(err, GW_EINVAL, "%s: the [grid] section is empty or missing", path);
    }
    if (base && (rc = resolve_paths(cfg, base, path, err)) != GW_OK) {
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
        const int file = names_file(cfg, cfg->grid[i].name);
        for (int j = 0; j < cfg->grid[i].nvalues; j++) {
            h = fnv64(h, cfg->grid[i].values[j]);
            if (file)
                h = fnv64_file(h, cfg->grid[i].values[j], &nomem);
        }
    }
    for (int i = 0; i < cfg->nparams; i++) {
        h = fnv64(fnv64(h, cfg->params[i].name), cfg->params[i].values[0]);
        if (names_file(cfg, cfg->params[i].name))
            h = fnv64_file(h, cfg->params[i].values[0], &nomem);
    }
    if (nomem) {
        gw_sweep_config_free(cfg);
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory reading the files it names", path);
    }
    cfg->hash = h;
    return find_inputs(path, cfg, err);
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

int gw_sweep_case(const gw_sweep_config *cfg, long k, const char **names, const char **values)
{
    if (k < 0 || k >= cfg->ncases)
        return GW_EINVAL;
    for (int i = cfg->ngrid - 1; i >= 0; i--) {
        names[i] = cfg->grid[i].name;
        values[i] = cfg->grid[i].values[k % cfg->grid[i].nvalues];
        k /= cfg->grid[i].nvalues;
    }
    for (int i = 0; i < cfg->nparams; i++) {
        names[cfg->ngrid + i] = cfg->params[i].name;
        values[cfg->ngrid + i] = cfg->params[i].values[0];
    }
    return GW_OK;
}

static unsigned fnv32(const char *s, size_t n)
{
    unsigned h = 2166136261u;
    for (size_t i = 0; i < n; i++) {
        h ^= (unsigned char)s[i];
        h *= 16777619u;
    }
    return h;
}

unsigned long long gw_sweep_case_hash(const gw_sweep_config *cfg, long k)
{
    const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
    if (gw_sweep_case(cfg, k, names, values) != GW_OK)
        return 0;
    return gw_case_config_hash(cfg->model, cfg->ngrid + cfg->nparams, names, values);
}

int gw_sweep_format_row(const gw_sweep_config *cfg, long k, const double *out, int ncol,
                        unsigned long long read_hash, char *buf, size_t n)
{
    const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
    gw_sweep_case(cfg, k, names, values);
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
static long check_line(const char *line, size_t len, long ncases)
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

/* A journal row as read: its case, text (without ",checksum\n") and line. */
typedef struct jrow {
    long k;
    const char *s;
    size_t len;
    long line;
} jrow;

static int jrow_cmp(const void *pa, const void *pb)
{
    const jrow *a = pa, *b = pb;
    if (a->k != b->k)
        return a->k < b->k ? -1 : 1;
    return (a->line > b->line) - (a->line < b->line);
}

/* Why a complete line that check_line refused is no row of this sweep. */
static const char *journal_line_fault(const char *line, size_t len, long ncases)
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
static const char *row_grid_fault(const gw_sweep_config *cfg, long k, const char *line, size_t len)
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
static const char *row_hash_fault(const gw_sweep_config *cfg, long k, const char *s, size_t len, int live,
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

int gw_sweep_row_check(const gw_sweep_config *cfg, const char *row, gw_err *err)
{
    char msg[1024];
    size_t len = strlen(row);
    char *end;
    long k = strtol(row, &end, 10);
    if (end == row || *end != ',' || k < 0 || k >= cfg->ncases || len < 10)
        return gw_err_set(err, GW_EINVAL, "sweep: a row that is not one of this sweep's: %.40s", row);
    const char *why = row_hash_fault(cfg, k, row, len - 10, 1, msg, sizeof msg);
    if (why)
        return gw_err_set(err, GW_EINVAL, "%s: its row is not kept; restore the file and rerun to resume (the "
                          "rows before are kept), or start a new sweep", why);
    return GW_OK;
}

/* The journal or table: a regular file only (gw_input_read), NULL with errno set
 * (ENOENT when absent). */
static char *slurp(const char *path, size_t *len, gw_err *err)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        gw_err_set(err, GW_EIO, "%s: cannot read: %s", path, strerror(errno));
        return NULL;
    }
    char *buf = NULL;
    int rc = gw_input_read(path, "sweep journal", GW_SWEEP_JOURNAL_MAX, &buf, len, err);
    if (rc != GW_OK) {
        /* what it is (a FIFO, a directory) is in err: it said "Invalid argument";
         * ENOMEM tells the caller it was memory, not the journal */
        errno = rc == GW_ENOMEM ? ENOMEM : EINVAL;
        return NULL;
    }
    return buf;
}

/* A new journal, whole (its head and input lines) or not at all, and never
 * over one another sweep made meanwhile: written under a temporary name and
 * linked into place, which fails when the name exists. The atomic write
 * before renamed over it: two sweeps started at once into one directory each
 * made a journal, the second replaced the first's, and the first appended its
 * rows to a file no longer in the directory and wrote its table from the
 * other sweep's rows (exit 0 for both). */
static int journal_create(const char *path, const char *text, int *fdp, gw_err *err)
{
    char tmp[4200];
    *fdp = -1;
    if (gw_snprintf(tmp, sizeof tmp, "%s.new.%ld.XXXXXX", path, (long)getpid()) >= (int)sizeof tmp)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", path);
    int fd = mkstemp(tmp);
    if (fd < 0)
        return gw_err_set(err, GW_EIO, "%s: cannot create: %s", path, strerror(errno));
    fchmod(fd, gw_new_file_mode(path));
    /* locked before it has its name: another sweep that finds it finds it
     * locked (a sweep that locked it first would refuse it as another
     * config's, and this one then find it locked: neither ran) */
    const size_t n = strlen(text);
    int bad = flock(fd, LOCK_EX) != 0 || write(fd, text, n) != (ssize_t)n || fsync(fd) != 0 ||
              fcntl(fd, F_SETFL, O_APPEND) != 0;
    int e = errno, placed = 0;
    if (!bad && link(tmp, path) == 0) {
        placed = 1;
    } else if (!bad && errno != EEXIST) {
        placed = rename(tmp, path) == 0; /* a file system without hard links: by rename, as before */
        bad = !placed;
        e = errno;
    }
    unlink(tmp);
    if (placed) {
        *fdp = fd;
        return GW_OK;
    }
    close(fd); /* another sweep made it meanwhile (EEXIST), or a failure */
    return bad ? gw_err_set(err, GW_EIO, "%s: cannot create: %s", path, strerror(e ? e : EIO)) : GW_OK;
}

static int journal_check(const char *path, const char *dir, const char *head, const gw_sweep_config *cfg,
                         char *done, long *ndone, int fd, gw_err *err);

int gw_sweep_out_inputs_check(const char *dir, const gw_sweep_config *cfg, gw_err *err)
{
    /* an input file of the sweep that is its journal or table: the table would
     * replace it (a sample named results.csv in DIR, exit 0 before; the
     * config itself named DIR/results.csv, or a link to it, until the
     * twenty-first pass) */
    static const char *const outs[] = {"journal.csv", "results.csv", NULL};
    if (!dir || !cfg)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_out_inputs_check: %s is NULL", !dir ? "dir" : "cfg");
    if (cfg->path && gw_outset_check_input(dir, outs, cfg->path, "sweep CONFIG", err) != GW_OK)
        return GW_EINVAL;
    for (int i = 0; i < cfg->ninputs; i++)
        if (gw_outset_check_input(dir, outs, cfg->inputs[i].value, "sweep", err) != GW_OK)
            return GW_EINVAL;
    return GW_OK;
}

int gw_sweep_journal_scan(const char *dir, const gw_sweep_config *cfg, char *done, long *ndone, gw_err *err)
{
    int fd = -1;
    int rc = gw_sweep_journal_open(dir, cfg, done, ndone, &fd, err);
    if (fd >= 0)
        close(fd);
    return rc;
}

int gw_sweep_journal_open(const char *dir, const gw_sweep_config *cfg, char *done, long *ndone, int *fdp,
                          gw_err *err)
{
    char path[4096];
    *ndone = 0;
    *fdp = -1;
    if (gw_path_join(path, sizeof path, dir, "journal.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", dir);
    /* the table goes beside the journal once every case has run: a directory
     * or a FIFO of its name failed the sweep (exit 1) after all its cases */
    char tpath[4096];
    if (gw_path_join(tpath, sizeof tpath, dir, "results.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", dir);
    if (gw_out_file_check(tpath, "sweep table", err) != GW_OK)
        return GW_EINVAL;
    if (gw_sweep_out_inputs_check(dir, cfg, err) != GW_OK)
        return GW_EINVAL;
    char head[96];
    gw_snprintf(head, sizeof head, GW_SWEEP_JOURNAL_HEAD "\n", cfg->hash);
    struct stat st;
    if (stat(path, &st) != 0 && errno == ENOENT) {
        char *in = input_lines(cfg); /* a new journal: the config, and what its files held */
        size_t hl = strlen(head), il = in ? strlen(in) : 0;
        char *text = in ? malloc(hl + il + 1) : NULL;
        if (!text) {
            free(in);
            return gw_err_set(err, GW_ENOMEM, "%s: out of memory", path);
        }
        memcpy(text, head, hl);
        memcpy(text + hl, in, il + 1);
        int rc = journal_create(path, text, fdp, err);
        free(text);
        free(in);
        if (rc != GW_OK)
            return rc;
    }
    /* One sweep at a time in a directory: the journal is locked from here
     * until the sweep ends (the lock goes with the process, kill -9 too).
     * Two sweeps of one config at once each ran every case and journaled it
     * twice; a second sweep's scan could cut a row the first was appending
     * as a torn one. What is read, checked and cut below is read under it. */
    if (*fdp < 0 && stat(path, &st) == 0 && S_ISREG(st.st_mode)) {
        int fd = open(path, O_RDWR | O_APPEND | O_CLOEXEC | O_NONBLOCK);
        if (fd < 0)
            return gw_err_set(err, GW_EIO, "%s: cannot open for appending: %s", path, strerror(errno));
        if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int e = errno;
            close(fd);
            if (e == EWOULDBLOCK)
                return gw_err_set(err, GW_EINVAL, "%s: another sweep is running in this directory (its journal.csv "
                                  "is locked by that process): wait for it to end, or choose another output", dir);
            return gw_err_set(err, GW_EIO, "%s: cannot lock: %s", path, strerror(e));
        }
        *fdp = fd;
    }
    int rc = journal_check(path, dir, head, cfg, done, ndone, *fdp, err);
    if (rc != GW_OK && *fdp >= 0) {
        close(*fdp);
        *fdp = -1;
    }
    return rc;
}

/* The format of a journal's first line "# granwave sweep journal HASH" (16
 * lowercase hex digits, as GW_SWEEP_JOURNAL_HEAD writes it), then nothing
 * (format 1, the first) or ", format N" (N a decimal number with no leading
 * zero, no sign) and the line's end: 1 with *fmt and *hash; 2 when the line
 * starts as a granwave journal's but goes on otherwise (a format no granwave
 * this one knows of writes, or an edited head); 0 when it does not start so
 * (not a granwave sweep journal). */
static int journal_head_format(const char *buf, size_t len, long *fmt, unsigned long *hash)
{
    static const char pre[] = "# granwave sweep journal ";
    const size_t pl = sizeof pre - 1;
    if (len < pl || memcmp(buf, pre, pl) != 0)
        return 0;
    const char *nl = memchr(buf, '\n', len);
    const char *p = buf + pl, *end = nl ? nl : buf + len;
    unsigned long h = 0;
    for (int i = 0; i < 16; i++, p++) {
        if (p >= end || !((*p >= '0' && *p <= '9') || (*p >= 'a' && *p <= 'f')))
            return 2;
        h = h << 4 | (unsigned long)(*p <= '9' ? *p - '0' : *p - 'a' + 10);
    }
    *hash = h;
    if (p == end) {
        /* a head without its newline is no journal a sweep made (it writes
         * the head and its lines whole): not format 1 */
        if (!nl)
            return 2;
        *fmt = 1;
        return 1;
    }
    static const char fsep[] = ", format ";
    const size_t fl = sizeof fsep - 1;
    if ((size_t)(end - p) < fl + 1 || memcmp(p, fsep, fl) != 0)
        return 2;
    p += fl;
    if (*p < '1' || *p > '9' || end - p > 9) /* up to 9 digits: no overflow, and no format a sweep writes */
        return 2;
    long n = 0;
    for (; p < end; p++) {
        if (*p < '0' || *p > '9')
            return 2;
        n = 10 * n + (*p - '0');
    }
    /* "format 1" was never written (format 1 had no suffix) */
    if (n < 2 || !nl)
        return 2;
    *fmt = n;
    return 1;
}

/* The journal's first line for a message: at most n - 1 bytes, each byte
 * that is not printable ASCII as '?', "..." when cut. */
static void journal_first_line(const char *buf, size_t len, char *out, size_t n)
{
    const char *nl = memchr(buf, '\n', len);
    size_t l = nl ? (size_t)(nl - buf) : len, w = 0;
    const int cut = l > n - 4;
    if (cut)
        l = n - 4;
    for (size_t i = 0; i < l; i++)
        out[w++] = buf[i] >= 0x20 && buf[i] < 0x7f ? buf[i] : '?';
    if (cut)
        out[w++] = '.', out[w++] = '.', out[w++] = '.';
    out[w] = '\0';
}

/* The journal at path, read (under the caller's lock on fd) and checked;
 * a torn last row cut. */
static int journal_check(const char *path, const char *dir, const char *head, const gw_sweep_config *cfg,
                         char *done, long *ndone, int fd, gw_err *err)
{
    size_t len = 0;
    char *buf = slurp(path, &len, err);
    if (!buf) /* a FIFO, a directory, gone: named in err; or out of memory */
        return errno == ENOMEM ? GW_ENOMEM : GW_EINVAL;
    struct stat a, b;
    if (fd < 0 || fstat(fd, &a) != 0 || stat(path, &b) != 0 || a.st_dev != b.st_dev || a.st_ino != b.st_ino) {
        free(buf);
        return gw_err_set(err, GW_EIO, "%s: replaced while the sweep opened it: rerun", path);
    }
    /* The format before the one read here (GW_SWEEP_JOURNAL_FORMAT), before
     * rows carried their case config hash and the hash of the file they read:
     * "# granwave sweep journal HASH" alone. Its rows cannot be told from rows
     * pasted from a sweep with other [params]. A later format, or a head no
     * granwave writes, is said as such: both were refused as "another sweep
     * (different config)", a journal of this very config included, naming
     * neither the file nor its format. */
    long fmt = 0;
    unsigned long jhash = 0;
    const int head_kind = journal_head_format(buf, len, &fmt, &jhash);
    if (head_kind == 1 && fmt == 1) {
        char other[96] = "";
        if (jhash != cfg->hash)
            gw_snprintf(other, sizeof other, ", of another config (%016lx; this one is %016lx)", jhash, cfg->hash);
        free(buf);
        return gw_err_set(err, GW_EINVAL, "%s: a journal of an earlier granwave, whose rows do not record the "
                          "config they ran under (format 1%s; granwave %s reads format %d only, as a row pasted from "
                          "another sweep could not be told in format 1): finish the sweep with the granwave that "
                          "started it, or remove the journal to rerun its cases", path, other, gw_version(),
                          GW_SWEEP_JOURNAL_FORMAT);
    }
    if (head_kind == 1 && fmt > GW_SWEEP_JOURNAL_FORMAT) {
        free(buf);
        return gw_err_set(err, GW_EINVAL, "%s: a sweep journal of format %ld, newer than granwave %s's "
                          "format %d: resume it with the granwave that wrote it, or choose another output (the "
                          "journal is left as it is)", path, fmt, gw_version(), GW_SWEEP_JOURNAL_FORMAT);
    }
    if (head_kind == 2) {
        char first[128];
        journal_first_line(buf, len, first, sizeof first);
        const char *nl = memchr(buf, '\n', len);
        /* a journal whose line ends a program converted: no row's checksum
         * (over the row and its LF) holds either */
        const int crlf = nl && nl > buf && nl[-1] == '\r';
        free(buf);
        return gw_err_set(err, GW_EINVAL, "%s: a sweep journal of a format granwave %s does not know (its first line "
                          "'%s'%s; this granwave writes and reads format %d): remove it or choose another output (the "
                          "journal is left as it is)", path, gw_version(), first,
                          crlf ? ", its lines ending in CR LF where a sweep writes LF" : "", GW_SWEEP_JOURNAL_FORMAT);
    }
    if (strncmp(buf, "# granwave sweep journal ", 25) != 0 || strncmp(buf, head, strlen(head)) != 0) {
        int rc = strncmp(buf, "# granwave sweep journal ", 25) == 0 ? changed_input(cfg, buf, len, path, dir, err)
                                                                      : GW_OK;
        const int ours = strncmp(buf, "# granwave sweep journal ", 25) == 0;
        if (rc == GW_OK && ours)
            rc = changed_keys(cfg, buf, len, dir, err);
        free(buf);
        if (rc != GW_OK)
            return rc;
        if (!ours) /* an empty, cut or converted file said "another sweep (different config)" */
            return gw_err_set(err, GW_EINVAL, "%s: not a granwave sweep journal (its first line is not '# granwave "
                              "sweep journal HASH'); remove it or choose another output", path);
        return gw_err_set(err, GW_EINVAL,
                          "%s: this directory holds another sweep (different config); remove it or choose another output",
                          dir);
    }
    size_t good = strlen(head), pos = good;
    long inl = 1;
    while (pos < len && strncmp(buf + pos, "# input ", 8) == 0) { /* the journal's input lines */
        const char *nl = memchr(buf + pos, '\n', len - pos), *at = NULL;
        if (!nl)
            break;
        unsigned long long was;
        if (input_line_hash(path, ++inl, buf + pos + 8, nl, &at, &was, err) != GW_OK) {
            free(buf);
            return GW_EINVAL;
        }
        pos = good = (size_t)(nl - buf) + 1;
    }
    while (pos < len && (strncmp(buf + pos, "# grid ", 7) == 0 || strncmp(buf + pos, "# param ", 8) == 0)) {
        const char *nl = memchr(buf + pos, '\n', len - pos); /* the config's keys (input_lines) */
        if (!nl)
            break;
        pos = good = (size_t)(nl - buf) + 1;
    }
    long line = 1;
    for (size_t q = 0; q < pos; q++)
        line += buf[q] == '\n';
    /* Rows are appended whole (one write each), so only the last line can be
     * torn (no newline: kill -9, a full disk); it is cut and its case reruns.
     * A complete line that is not a row of this sweep was edited or pasted by
     * hand: the scan stopped there and cut it and every row after it, so the
     * finished cases behind an edited value were dropped and rerun, silently.
     * It is refused now, naming the line, and the journal is left as it is. */
    jrow *rows = NULL;
    long nrows = 0, caprows = 0;
    int rc = GW_OK;
    while (pos < len && rc == GW_OK) {
        const char *nl = memchr(buf + pos, '\n', len - pos);
        size_t l = nl ? (size_t)(nl - (buf + pos)) + 1 : len - pos;
        long k = check_line(buf + pos, l, cfg->ncases);
        char hmsg[1024];
        const char *why = k < 0 ? journal_line_fault(buf + pos, l, cfg->ncases) : row_grid_fault(cfg, k, buf + pos, l);
        if (k >= 0 && !why)
            why = row_hash_fault(cfg, k, buf + pos, l - 10, 0, hmsg, sizeof hmsg);
        if (k >= 0 && !why) {
            if (nrows == caprows) {
                long nc = caprows ? 2 * caprows : 1024;
                jrow *t = realloc(rows, (size_t)nc * sizeof *t);
                if (!t) {
                    rc = gw_err_set(err, GW_ENOMEM, "%s: out of memory", path);
                    break;
                }
                rows = t, caprows = nc;
            }
            rows[nrows++] = (jrow){k, buf + pos, l - 10, line};
            good = pos + l;
        } else if (!nl) {
            break; /* a torn last row: cut below */
        } else {
            rc = gw_err_set(err, GW_EINVAL, "%s:%ld: %s: the journal was edited by hand (a torn row can only be the "
                            "last line, without its newline); delete that line to rerun its case, or choose another "
                            "output", path, line, why);
        }
        pos += l;
        line++;
    }
    /* A case journaled twice with different numbers (rows pasted from another
     * journal): which is right cannot be told; copies of one row are harmless. */
    if (rc == GW_OK && nrows > 1) {
        qsort(rows, (size_t)nrows, sizeof *rows, jrow_cmp);
        for (long i = 1; i < nrows && rc == GW_OK; i++)
            if (rows[i].k == rows[i - 1].k &&
                (rows[i].len != rows[i - 1].len || memcmp(rows[i].s, rows[i - 1].s, rows[i].len) != 0))
                rc = gw_err_set(err, GW_EINVAL, "%s:%ld: case %ld is journaled twice with different results (lines "
                                "%ld and %ld): delete the wrong one, or choose another output", path, rows[i].line,
                                rows[i].k, rows[i - 1].line, rows[i].line);
    }
    for (long i = 0; rc == GW_OK && i < nrows; i++) {
        if (!done[rows[i].k])
            (*ndone)++;
        done[rows[i].k] = 1;
    }
    free(rows);
    free(buf);
    if (rc != GW_OK)
        return rc;
    if (good < len && ftruncate(fd, (off_t)good) != 0)
        return gw_err_set(err, GW_EIO, "%s: cannot cut a torn row: %s", path, strerror(errno));
    return GW_OK;
}

int gw_sweep_journal_append(int fd, const char *row, double *synced_ms, gw_err *err)
{
    size_t n = strlen(row);
    ssize_t w = write(fd, row, n);
    if (w != (ssize_t)n)
        return gw_err_set(err, GW_EIO, "sweep journal: write failed: %s", strerror(errno));
    const double now = gw_clock_ms();
    if (!synced_ms || now - *synced_ms >= GW_SWEEP_SYNC_MS)
        return gw_sweep_journal_sync(fd, synced_ms, err);
    return GW_OK;
}

int gw_sweep_journal_sync(int fd, double *synced_ms, gw_err *err)
{
    if (fsync(fd) != 0)
        return gw_err_set(err, GW_EIO, "sweep journal: fsync failed: %s", strerror(errno));
    if (synced_ms)
        *synced_ms = gw_clock_ms();
    return GW_OK;
}

typedef struct row_ref {
    long k;
    const char *s;
    size_t len;
} row_ref;

static int cmp_rows(const void *a, const void *b)
{
    long x = ((const row_ref *)a)->k, y = ((const row_ref *)b)->k;
    return (x > y) - (x < y);
}

int gw_sweep_write_table(const char *dir, const gw_sweep_config *cfg, const gw_sweep_model *m, gw_err *err)
{
    char path[4096];
    if (gw_path_join(path, sizeof path, dir, "journal.csv") != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", dir);
    size_t len = 0;
    char *buf = slurp(path, &len, err);
    if (!buf)
        return errno == ENOMEM ? GW_ENOMEM : GW_EIO;
    row_ref *rows = calloc((size_t)cfg->ncases + 1, sizeof *rows);
    char *seen = calloc((size_t)cfg->ncases + 1, 1);
    long nr = 0;
    for (size_t pos = 0; rows && seen && pos < len;) {
        const char *nl = memchr(buf + pos, '\n', len - pos);
        size_t l = nl ? (size_t)(nl - (buf + pos)) + 1 : len - pos;
        long k = check_line(buf + pos, l, cfg->ncases);
        if (k >= 0 && !seen[k]) {
            seen[k] = 1;
            rows[nr++] = (row_ref){k, buf + pos, l - 10}; /* drop ",checksum\n" */
        }
        pos += l;
    }
    int rc = GW_OK;
    char head[96];
    gw_snprintf(head, sizeof head, GW_SWEEP_JOURNAL_HEAD "\n", cfg->hash);
    const int other = strncmp(buf, head, strlen(head)) != 0;
    if (!rows || !seen) {
        rc = gw_err_set(err, GW_ENOMEM, "sweep: out of memory");
    } else if (other || nr != cfg->ncases) {
        /* the table is of this sweep's journal, every case once: a journal
         * replaced meanwhile gave a table of another sweep's rows, exit 0 */
        rc = other
                 ? gw_err_set(err, GW_EIO, "%s: replaced by another sweep's journal while this sweep ran: no table "
                              "written (this sweep's rows are not in it)", path)
                 : gw_err_set(err, GW_EIO, "%s: lost rows while the sweep ran (%ld of its %ld cases in it): no table "
                              "written; rerun to resume", path, nr, cfg->ncases);
    } else {
        qsort(rows, (size_t)nr, sizeof *rows, cmp_rows);
        gw_afile f;
        if (gw_path_join(path, sizeof path, dir, "results.csv") != GW_OK)
            rc = gw_err_set(err, GW_EINVAL, "%s: path too long", dir);
        else if ((rc = gw_afile_open(&f, path, err)) == GW_OK) {
            gw_fprintf(f.fp, "# granwave %s sweep, model %s, config %016lx, %ld of %ld cases\n", gw_version(),
                    cfg->model, cfg->hash, nr, cfg->ncases);
            for (int i = 0; i < cfg->nparams; i++)
                gw_fprintf(f.fp, "# param %s = %s\n", cfg->params[i].name, cfg->params[i].values[0]);
            for (int i = 0; i < cfg->ninputs; i++) /* what the cases' files held */
                gw_fprintf(f.fp, "# input %s = %s fnv1a64 %016llx\n", cfg->inputs[i].key, cfg->inputs[i].value,
                        cfg->inputs[i].hash);
            /* the grid itself: a reader can tell a missing or edited row */
            for (int i = 0; i < cfg->ngrid; i++) {
                gw_fprintf(f.fp, "# grid %s = ", cfg->grid[i].name);
                for (int j = 0; j < cfg->grid[i].nvalues; j++)
                    gw_fprintf(f.fp, "%s%s", j ? ", " : "", cfg->grid[i].values[j]);
                fputc('\n', f.fp);
            }
            gw_fprintf(f.fp, "case");
            for (int i = 0; i < cfg->ngrid; i++)
                gw_fprintf(f.fp, ",%s", cfg->grid[i].name);
            for (int i = 0; i < m->ncolumns; i++)
                gw_fprintf(f.fp, ",%s", m->columns[i]);
            gw_fprintf(f.fp, ",case_config_fnv1a64"); /* the hashes that end each row */
            if (cfg->read_key)
                gw_fprintf(f.fp, ",%s_fnv1a64", cfg->read_key);
            fputc('\n', f.fp);
            for (long i = 0; i < nr; i++) {
                fwrite(rows[i].s, 1, rows[i].len, f.fp);
                fputc('\n', f.fp);
            }
            rc = gw_afile_commit(&f, err);
        }
    }
    free(rows);
    free(seen);
    free(buf);
    return rc;
}
