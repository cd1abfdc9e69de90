/*
 * gw_sweep_inputs.c: the files a sweep config names: relative paths taken
 * from the config's directory, the regular files the model reads (a layer
 * sample) hashed when the config is read (FNV-1a 64 of their bytes), checked
 * unchanged before a case's row is kept (hashed again only when stat finds
 * them changed: gw_io_hash_memo), and never one of the sweep's own
 * outputs (DIR/journal.csv, DIR/results.csv). No units.
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

#include "gw_param.h"
#include "gw_sweep.h"
#include "gw_locale.h"
#include "gw_sweep_impl.h"

/* The directory of the config file at path, absolute (realpath of the part
 * before its last '/', "." without one); NULL with err set when it cannot be
 * found. */
char *gw_sweep_config_dir(const char *path, int *status, gw_err *err)
{
    const char *slash = strrchr(path, '/');
    char *dir = slash ? malloc((size_t)(slash - path) + 2) : gw_sweep_strdup(".");
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
int gw_sweep_resolve_paths(gw_sweep_config *cfg, const char *base, const char *path, gw_err *err)
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
                char *written = gw_sweep_strdup(keys[i].values[j]);
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

/* The registered rules: written by the models' constructors alone, before
 * main (one thread), read after. */
#define RULES_MAX 8
/* A table of one kind of rule by model: the function held as void (*)(void),
 * the one function pointer type any other converts to and back from */
typedef void (*any_rule)(void);
typedef struct rule_table {
    struct {
        const char *model;
        any_rule fn;
    } r[RULES_MAX];
    int n;
} rule_table;
static rule_table input_rules, value_rules;

static void rule_set(rule_table *t, const char *model, any_rule fn)
{
    if (!model)
        return;
    for (int i = 0; i < t->n; i++)
        if (strcmp(t->r[i].model, model) == 0) {
            t->r[i].fn = fn;
            return;
        }
    if (t->n < RULES_MAX) {
        t->r[t->n].model = model;
        t->r[t->n++].fn = fn;
    }
}

static any_rule rule_of(const rule_table *t, const char *model)
{
    for (int i = 0; model && i < t->n; i++)
        if (strcmp(t->r[i].model, model) == 0)
            return t->r[i].fn;
    return NULL;
}

void gw_sweep_input_rule_set(const char *model, gw_sweep_input_rule fn)
{
    rule_set(&input_rules, model, (any_rule)fn);
}

gw_sweep_input_rule gw_sweep_input_rule_of(const char *model)
{
    return (gw_sweep_input_rule)rule_of(&input_rules, model);
}

void gw_sweep_value_rule_set(const char *model, gw_sweep_value_rule fn)
{
    rule_set(&value_rules, model, (any_rule)fn);
}

gw_sweep_value_rule gw_sweep_value_rule_of(const char *model)
{
    return (gw_sweep_value_rule)rule_of(&value_rules, model);
}

/* the models' rules over their finished rows (gw_sweep_rows_rule), held as
 * the other rules are: by the models' constructors, before main */
static struct {
    const char *model;
    const gw_sweep_rows_rule *rule;
} rows_rules[RULES_MAX];
static int n_rows_rules;

void gw_sweep_rows_rule_set(const char *model, const gw_sweep_rows_rule *rule)
{
    if (!model)
        return;
    for (int i = 0; i < n_rows_rules; i++)
        if (strcmp(rows_rules[i].model, model) == 0) {
            rows_rules[i].rule = rule;
            return;
        }
    if (n_rows_rules < RULES_MAX) {
        rows_rules[n_rows_rules].model = model;
        rows_rules[n_rows_rules++].rule = rule;
    }
}

const gw_sweep_rows_rule *gw_sweep_rows_rule_of(const char *model)
{
    for (int i = 0; model && i < n_rows_rules; i++)
        if (strcmp(rows_rules[i].model, model) == 0)
            return rows_rules[i].rule;
    return NULL;
}

/* value (of key read_key) through its model's rules when it names something */
static int input_readable(const gw_sweep_config *cfg, const char *value, gw_err *e)
{
    struct stat sb;
    const gw_sweep_input_rule fn = gw_sweep_input_rule_of(cfg->model);
    if (!fn || stat(value, &sb) != 0)
        return GW_OK;
    return fn(value, NULL, e);
}

/* The content hash of input value (key: what it is, for a message) into *h:
 * through its model's rule, which reads it once (a file it refuses read up to
 * its fault), or bounded (gw_fnv1a64_file) for a model without one. */
static int input_hash(const gw_sweep_config *cfg, const char *key, const char *value, unsigned long long *h,
                      gw_err *e)
{
    const gw_sweep_input_rule fn = gw_sweep_input_rule_of(cfg->model);
    return fn ? fn(value, h, e) : gw_fnv1a64_file(value, key, h, e);
}

int gw_sweep_inputs_readable(const gw_sweep_config *cfg, const char *path, gw_err *err)
{
    if (!cfg->read_key || !gw_sweep_input_rule_of(cfg->model))
        return GW_OK;
    for (int s = 0; s < 2; s++) {
        const gw_sweep_key *keys = s ? cfg->params : cfg->grid;
        const int nk = s ? cfg->nparams : cfg->ngrid;
        for (int i = 0; i < nk; i++) {
            if (!gw_sweep_names_file(cfg, keys[i].name))
                continue;
            for (int j = 0; j < keys[i].nvalues; j++) {
                gw_err e = {{0}};
                const int rc = input_readable(cfg, keys[i].values[j], &e);
                if (rc == GW_OK)
                    continue;
                /* the rule's text names the key itself ("sample: P is a
                 * FIFO", "sample 'P': ..."): said once */
                const size_t kl = strlen(keys[i].name);
                const int named = strncmp(e.msg, keys[i].name, kl) == 0 && (e.msg[kl] == ':' || e.msg[kl] == ' ');
                return gw_err_set(err, rc == GW_ENOMEM || rc == GW_EUNSUPPORTED ? rc : GW_EINVAL, "%s: [%s] %s%s%s",
                                  path ? path : "sweep", s ? "params" : "grid", named ? "" : keys[i].name,
                                  named ? "" : ": ", e.msg);
            }
        }
    }
    return GW_OK;
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
    int rc = input_hash(cfg, "sweep", value, &fh, &e);
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
int gw_sweep_names_file(const gw_sweep_config *cfg, const char *name)
{
    return cfg->read_key && strcmp(cfg->read_key, name) == 0;
}

/* A grid value that names a file, as the duplicate search sorts it. */
typedef struct file_id {
    dev_t dev;
    ino_t ino;
    long idx;
} file_id;

static int file_id_cmp(const void *pa, const void *pb)
{
    const file_id *a = pa, *b = pb;
    if (a->dev != b->dev)
        return a->dev < b->dev ? -1 : 1;
    if (a->ino != b->ino)
        return a->ino < b->ino ? -1 : 1;
    return (a->idx > b->idx) - (a->idx < b->idx);
}

/* Grid key k (its values files the cases read) names no file twice. The
 * reader refuses a value listed twice, also in another spelling ('1, 1.0'),
 * but file names were compared as text: 's.txt, ./s.txt', an absolute path,
 * 'sub/../s.txt' or a link to the same sample ran each case twice (exit 0).
 * Files are compared by identity (device and inode, links followed); values
 * naming nothing are left to the check that names them. GW_OK, GW_EINVAL
 * (the first pair in list order), GW_ENOMEM. */
static int grid_files_distinct(const char *path, const gw_sweep_key *k, gw_err *err)
{
    file_id *f = malloc((size_t)(k->nvalues ? k->nvalues : 1) * sizeof *f);
    if (!f)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", path);
    long m = 0, best_i = -1, best_j = -1;
    for (long q = 0; q < k->nvalues; q++) {
        struct stat st;
        if (stat(k->values[q], &st) == 0)
            f[m++] = (file_id){st.st_dev, st.st_ino, q};
    }
    qsort(f, (size_t)m, sizeof *f, file_id_cmp);
    for (long q = 1, head = 0; q < m; q++) { /* a run of one file, by index: its head the first listed */
        if (f[q].dev != f[head].dev || f[q].ino != f[head].ino)
            head = q;
        else if (q == head + 1 && (best_i < 0 || f[q].idx < best_i))
            best_i = f[q].idx, best_j = f[head].idx;
    }
    free(f);
    if (best_i < 0)
        return GW_OK;
    return gw_err_set(err, GW_EINVAL, "%s: [grid] %s: '%s' and '%s' in the list are the same file (each case would "
                      "run twice)", path, k->name, k->values[best_j], k->values[best_i]);
}

int gw_sweep_find_inputs(const char *path, gw_sweep_config *cfg, gw_err *err)
{
    long cap = 0;
    int rc = GW_OK;
    for (int i = 0; rc == GW_OK && i < cfg->ngrid; i++)
        for (int j = 0; rc == GW_OK && gw_sweep_names_file(cfg, cfg->grid[i].name) && j < cfg->grid[i].nvalues; j++)
            rc = add_input(cfg, cfg->grid[i].name, cfg->grid[i].values[j], &cap);
    for (int i = 0; rc == GW_OK && i < cfg->nparams; i++)
        if (gw_sweep_names_file(cfg, cfg->params[i].name))
            rc = add_input(cfg, cfg->params[i].name, cfg->params[i].values[0], &cap);
    if (rc != GW_OK) {
        gw_sweep_config_free(cfg);
        return gw_err_set(err, rc, "%s: out of memory", path);
    }
    for (int i = 0; rc == GW_OK && i < cfg->ngrid; i++)
        if (gw_sweep_names_file(cfg, cfg->grid[i].name))
            rc = grid_files_distinct(path, &cfg->grid[i], err);
    if (rc != GW_OK)
        gw_sweep_config_free(cfg);
    return rc;
}

int gw_sweep_inputs_check(const gw_sweep_config *cfg, gw_err *err)
{
    if (!cfg)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_inputs_check: cfg is NULL");
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
    return gw_sweep_case_inputs_check_memo(cfg, k, NULL, err);
}

int gw_sweep_case_inputs_check_memo(const gw_sweep_config *cfg, long k, gw_hash_memo *memo, gw_err *err)
{
    if (!cfg)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_case_inputs_check: cfg is NULL");
    const int rc = gw_sweep_config_check(cfg, err);
    if (rc != GW_OK)
        return rc;
    for (int i = 0; i < cfg->ninputs; i++) {
        const struct gw_sweep_input *in = &cfg->inputs[i];
        if (!case_reads(cfg, k, in))
            continue;
        unsigned long long fh = 0;
        gw_err e = {{0}};
        /* the reader's rules with the hash, in one pass: a file replaced by
         * a sparse 200 GB one while the sweep ran was hashed whole after the
         * next case. Through the memo, a file stat finds as it was when it
         * was last hashed is not read again: a sample was hashed after each
         * of its cases, 1.5 ms per MiB each */
        const gw_sweep_input_rule fn = gw_sweep_input_rule_of(cfg->model);
        if ((fn ? gw_io_hash_memo(memo, in->value, fn, &fh, &e) : input_hash(cfg, in->key, in->value, &fh, &e)) !=
            GW_OK)
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

int gw_sweep_out_inputs_check(const char *dir, const gw_sweep_config *cfg, gw_err *err)
{
    /* an input file of the sweep that is its journal or table: the table would
     * replace it (a sample named results.csv in DIR, exit 0 before; the
     * config itself named DIR/results.csv, or a link to it, until the
     * twenty-first pass) */
    static const char *const outs[] = {"journal.csv", "results.csv", NULL};
    if (!dir || !cfg)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_out_inputs_check: %s is NULL", !dir ? "dir" : "cfg");
    if (!dir[0]) /* it passed, as the journal's and the table's calls refuse it */
        return gw_err_set(err, GW_EINVAL, "sweep directory: the directory is empty ('' names none; '.' is this one)");
    const int shape = gw_sweep_config_check(cfg, err); /* inputs counted without their array: SIGSEGV before */
    if (shape != GW_OK)
        return shape;
    if (cfg->path && gw_outset_check_input(dir, outs, cfg->path, "sweep CONFIG", err) != GW_OK)
        return GW_EINVAL;
    for (int i = 0; i < cfg->ninputs; i++)
        if (gw_outset_check_input(dir, outs, cfg->inputs[i].value, "sweep", err) != GW_OK)
            return GW_EINVAL;
    return GW_OK;
}

int gw_sweep_number_check(const struct gw_param *p, const char *value, gw_err *err)
{
    if (!p || !value)
        return GW_OK;
    switch (p->type) {
    case GW_PARAM_DOUBLE: {
        double v;
        return gw_param_set_value(p, &v, value, err);
    }
    case GW_PARAM_LONG: {
        long v;
        return gw_param_set_value(p, &v, value, err);
    }
    case GW_PARAM_INT:
    case GW_PARAM_FLAG:
    case GW_PARAM_CHOICE: {
        int v;
        return gw_param_set_value(p, &v, value, err);
    }
    default:
        return GW_OK;
    }
}
