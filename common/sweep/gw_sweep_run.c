/*
 * gw_sweep_run.c: the cases of a sweep config run in memory on the worker pool
 * (gw_pool.h), every case checked first. No physics; each case builds its own
 * model and solver (one SUNDIALS context per solver, hence per thread).
 */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "gw_sweep.h"
#include "gw_sweep_impl.h"
#include "gw_locale.h"
#include "gw_pool_impl.h"

double gw_memory_available(const char **what)
{
    const long pages = sysconf(_SC_PHYS_PAGES), psize = sysconf(_SC_PAGESIZE);
    double avail = pages > 0 && psize > 0 ? (double)pages * (double)psize : INFINITY;
    const char *w = "physical memory";
    struct rlimit rl;
    if (getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && (double)rl.rlim_cur < avail)
        avail = (double)rl.rlim_cur, w = "ulimit -v";
    if (getrlimit(RLIMIT_DATA, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && (double)rl.rlim_cur < avail)
        avail = (double)rl.rlim_cur, w = "ulimit -d";
    if (what)
        *what = w;
    return avail;
}

/* (b, k) ranks after (b2, k2) among the largest estimates: a smaller b, or
 * the same b of a later case (a heap's root is the one ranked last) */
static int topk_before(double b2, long k2, double b, long k)
{
    return b < b2 || (b == b2 && k > k2);
}

typedef struct top_pair {
    double b;
    long k;
} top_pair;

static int top_cmp(const void *pa, const void *pb)
{
    const top_pair *a = pa, *c = pb;
    return a->b > c->b ? -1 : a->b < c->b ? 1 : (a->k > c->k) - (a->k < c->k);
}

/* pair i ranks after pair j: top_cmp's order */
static int top_after(const double *top, const long *topk, long i, long j)
{
    return top_cmp(&(top_pair){top[i], topk[i]}, &(top_pair){top[j], topk[j]}) > 0;
}

static void top_swap(double *top, long *topk, long i, long j)
{
    const double tb = top[i];
    const long tk = topk[i];
    top[i] = top[j], topk[i] = topk[j];
    top[j] = tb, topk[j] = tk;
}

/* the subtree at i of the first n pairs made a heap again: each pair ranked
 * no earlier than its children (the root is the pair ranked last) */
static void top_sift(double *top, long *topk, long i, long n)
{
    for (;;) {
        long c = 2 * i + 1;
        if (c >= n)
            break;
        if (c + 1 < n && top_after(top, topk, c + 1, c))
            c++;
        if (!top_after(top, topk, c, i))
            break;
        top_swap(top, topk, i, c);
        i = c;
    }
}

void gw_sweep_top_heapsort(double *top, long *topk, long n)
{
    /* in place, O(n log n): the quadratic insertion sort that stood here
     * when the pairs had no memory would take hours for a million jobs */
    for (long i = n / 2 - 1; i >= 0; i--)
        top_sift(top, topk, i, n);
    for (long end = n - 1; end > 0; end--) {
        top_swap(top, topk, 0, end);
        top_sift(top, topk, 0, end);
    }
}

void gw_sweep_top_sort(double *top, long *topk, long n)
{
    top_pair *t = malloc((size_t)(n > 0 ? n : 1) * sizeof *t);
    if (!t) { /* no memory for the pairs: in place */
        gw_sweep_top_heapsort(top, topk, n);
        return;
    }
    for (long i = 0; i < n; i++)
        t[i] = (top_pair){top[i], topk[i]};
    qsort(t, (size_t)n, sizeof *t, top_cmp);
    for (long i = 0; i < n; i++)
        top[i] = t[i].b, topk[i] = t[i].k;
    free(t);
}

int gw_sweep_memory_check(const gw_sweep_config *cfg, const gw_sweep_model *m, long jobs, int processes,
                          long *most, gw_err *err)
{
    if (!cfg || !m)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_memory_check: %s is NULL", !cfg ? "cfg" : "m");
    /* processes is a flag (0 threads, 1 processes): -1 was taken as true */
    if (processes != 0 && processes != 1)
        return gw_err_set(err, GW_EINVAL, "processes: %d is not 0 (threads) or 1 (processes)", processes);
    int rc = gw_sweep_config_check(cfg, err);
    if (rc != GW_OK)
        return rc;
    if (most)
        *most = cfg->ncases;
    if (!m->memory || cfg->ncases <= 0)
        return GW_OK;
    if (jobs <= 0)
        jobs = gw_pool_cpus();
    if (jobs > cfg->ncases)
        jobs = cfg->ncases;
    /* the jobs largest estimates, in decreasing order (jobs <= 4096) */
    double *top = malloc((size_t)jobs * sizeof *top);
    long *topk = malloc((size_t)jobs * sizeof *topk);
    if (!top || !topk) {
        free(top);
        free(topk);
        return gw_err_set(err, GW_ENOMEM, "sweep: out of memory");
    }
    long ntop = 0;
    const int nk = cfg->ngrid + cfg->nparams;
    for (long k = 0; k < cfg->ncases && rc == GW_OK; k++) {
        const char *names[2 * GW_SWEEP_MAX_KEYS], *vals[2 * GW_SWEEP_MAX_KEYS];
        double b = 0;
        gw_sweep_case(cfg, k, names, vals);
        if ((rc = m->memory(nk, names, vals, &b, err)) != GW_OK) {
            char tmp[sizeof err->msg];
            gw_snprintf(tmp, sizeof tmp, "%s", err ? err->msg : "");
            gw_err_set(err, rc, "case %ld: %s", k, tmp);
            break;
        }
        /* kept as a heap whose root is the smallest kept estimate (the
         * latest case among equal ones): an insertion into a sorted array
         * moved up to jobs entries per case, and a layer grid of 1.2e6 cases
         * checked for jobs = 1e6 (every case's estimate growing) ran for
         * minutes where jobs = 4 took 9 s */
        if (ntop == jobs && !(b > top[0]))
            continue;
        long i = ntop < jobs ? ntop++ : 0;
        if (i > 0) { /* sift up the new leaf */
            for (; i > 0 && topk_before(top[(i - 1) / 2], topk[(i - 1) / 2], b, k); i = (i - 1) / 2)
                top[i] = top[(i - 1) / 2], topk[i] = topk[(i - 1) / 2];
        } else if (ntop > 1 || ntop == jobs) { /* the root replaced: sift down */
            for (;;) {
                long c = 2 * i + 1;
                if (c >= ntop)
                    break;
                if (c + 1 < ntop && topk_before(top[c], topk[c], top[c + 1], topk[c + 1]))
                    c++;
                if (!topk_before(b, k, top[c], topk[c]))
                    break;
                top[i] = top[c], topk[i] = topk[c];
                i = c;
            }
        }
        top[i] = b, topk[i] = k;
    }
    /* the kept estimates in decreasing order, the first case first among equal ones */
    gw_sweep_top_sort(top, topk, ntop);
    if (rc == GW_OK) {
        /* one case within this process's limits; the jobs together within
         * them too, or within the physical memory when they are processes
         * (each with its own limits) */
        const char *what = "", *what_all = "physical memory";
        const double one = gw_memory_available(&what);
        double all = one;
        if (processes) {
            const long pages = sysconf(_SC_PHYS_PAGES), psize = sysconf(_SC_PAGESIZE);
            all = pages > 0 && psize > 0 ? (double)pages * (double)psize : INFINITY;
        } else {
            what_all = what;
        }
        double sum = 0;
        long fit = 0;
        for (long i = 0; i < ntop; i++) {
            sum += top[i];
            if (sum <= 0.8 * all && top[0] <= 0.8 * one)
                fit = i + 1;
        }
        if (most)
            *most = fit;
        if (fit == 0)
            rc = gw_err_set(err, GW_EINVAL, "case %ld needs about %.3g GB alone, above 80 %% of the %.3g GB "
                            "available (%s): no number of jobs fits", topk[0], top[0] / 1e9, one / 1e9, what);
        else if (fit < ntop)
            rc = gw_err_set(err, GW_EINVAL, "jobs: %ld cases at once need about %.3g GB (the largest, case %ld, "
                            "%.3g GB), above 80 %% of the %.3g GB available (%s): at most %ld jobs", ntop,
                            sum / 1e9, topk[0], top[0] / 1e9, all / 1e9, what_all, fit);
    }
    free(top);
    free(topk);
    return rc;
}

int gw_sweep_size_check(const gw_sweep_config *cfg, const gw_sweep_model *m, gw_err *err)
{
    if (!cfg || !m)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_size_check: %s is NULL", !cfg ? "cfg" : "m");
    const int rc = gw_sweep_config_check(cfg, err);
    if (rc != GW_OK)
        return rc;
    const double row = gw_sweep_row_bound(cfg, m->ncolumns);
    /* need: the journal read back and the table built from it, while the
     * sweep still holds its copy of what it wrote (gw_sweep_journal.c: a
     * journal rewritten in place is kept from it) */
    const double journal = row * (double)cfg->ncases, need = (2 * row + 48) * (double)cfg->ncases;
    const char *what = "";
    const double avail = gw_memory_available(&what);
    if (journal > (double)GW_SWEEP_JOURNAL_MAX)
        return gw_err_set(err, GW_EINVAL, "the grid has %ld cases: its journal (up to %.0f bytes a row) would reach "
                          "%.3g GB, above the %.3g GB a sweep reads back to resume and to write its table: split the "
                          "grid into sweeps of at most %.0f cases", cfg->ncases, row, journal / 1e9,
                          (double)GW_SWEEP_JOURNAL_MAX / 1e9, floor((double)GW_SWEEP_JOURNAL_MAX / row));
    if (need > 0.8 * avail)
        return gw_err_set(err, GW_EINVAL, "the grid has %ld cases: its journal read back and the table built from it "
                          "need about %.3g GB (%.0f bytes a case), above 80 %% of the %.3g GB available (%s): split "
                          "the grid into sweeps of at most %.0f cases", cfg->ncases, need / 1e9, 2 * row + 48,
                          avail / 1e9, what, floor(0.8 * avail / (2 * row + 48)));
    return GW_OK;
}

typedef struct sweep_ctx {
    const gw_sweep_config *cfg;
    const gw_sweep_model *m;
    double *values;
} sweep_ctx;

static int run_one(void *arg, long k, gw_err *err)
{
    const sweep_ctx *s = arg;
    const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
    gw_sweep_case(s->cfg, k, names, values);
    int rc = s->m->run(s->cfg->ngrid + s->cfg->nparams, names, values, s->values + k * s->m->ncolumns, NULL, err);
    if (rc != GW_OK) {
        char tmp[sizeof err->msg];
        gw_snprintf(tmp, sizeof tmp, "%s", err->msg);
        if (!tmp[0]) /* a caller's model that failed without a word: "case 3: " */
            gw_snprintf(tmp, sizeof tmp, "model %s's run failed (%s, status %d) and gave no message",
                        s->m->name ? s->m->name : "(unnamed)", gw_strerror(rc), rc);
        gw_err_set(err, rc, "case %ld: %s", k, tmp);
    }
    return rc;
}

int gw_sweep_case_check(const gw_sweep_model *m, void **memo, int nkeys, const char *const *names,
                        const char *const *values, gw_err *err)
{
    if (!m)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_case_check: m is NULL");
    gw_err e = {{0}};
    const int rc = m->check_memo ? m->check_memo(memo, nkeys, names, values, &e)
                 : m->check      ? m->check(nkeys, names, values, &e)
                                 : GW_OK;
    if (rc == GW_OK)
        return GW_OK;
    if (!e.msg[0]) /* a caller's model that refused without a word */
        gw_err_set(&e, rc, "model %s's check refused the case (%s, status %d) and gave no message",
                   m->name ? m->name : "(unnamed)", gw_strerror(rc), rc);
    if (err)
        *err = e;
    return rc;
}

void gw_sweep_checks_end(const gw_sweep_model *m, void *memo)
{
    if (!m)
        return;
    if (m->memo_free)
        m->memo_free(memo);
}

int gw_sweep_model_check(const char *call, const gw_sweep_config *cfg, const gw_sweep_model *m, int run,
                         gw_err *err)
{
    const char *name = m->name ? m->name : "(unnamed)";
    if (m->ncolumns < 1)
        return gw_err_set(err, GW_EINVAL, "%s: model %s: ncolumns %d (its result columns: at least 1)", call, name,
                          m->ncolumns);
    /* before its columns are read: a longer count than its array */
    if (cfg->ncolumns > 0 && cfg->ncolumns != m->ncolumns)
        return gw_err_set(err, GW_EINVAL, "%s: model %s writes %d result columns, its config's %d (a config read "
                          "with another model)", call, name, m->ncolumns, cfg->ncolumns);
    if (!m->columns)
        return gw_err_set(err, GW_EINVAL, "%s: model %s: columns is NULL (ncolumns %d)", call, name, m->ncolumns);
    for (int j = 0; j < m->ncolumns; j++)
        if (!m->columns[j])
            return gw_err_set(err, GW_EINVAL, "%s: model %s: columns[%d] is NULL (ncolumns %d)", call, name, j,
                              m->ncolumns);
    if (run && !m->run)
        return gw_err_set(err, GW_EINVAL, "%s: model %s: run is NULL", call, name);
    return GW_OK;
}

int gw_sweep_check_pass(const gw_sweep_config *cfg, const gw_sweep_model *m, gw_progress_fn progress, void *pctx,
                        char **warnings, gw_err *err)
{
    if (!cfg || !m)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_check_pass: %s is NULL", !cfg ? "cfg" : "m");
    int rc = gw_sweep_config_check(cfg, err);
    if (rc != GW_OK || (!m->check && !m->check_memo))
        return rc;
    const int nk = cfg->ngrid + cfg->nparams;
    void *memo = NULL; /* the model's, over this pass (a layer sample read once) */
    for (long k = 0; k < cfg->ncases; k++) {
        if (progress && k > 0 && k % 1000 == 0 && progress(pctx, k, cfg->ncases) != 0) {
            gw_sweep_checks_end(m, memo);
            return gw_err_set(err, GW_ECANCELED, "the check pass was stopped at case %ld of %ld", k, cfg->ncases);
        }
        const char *names[2 * GW_SWEEP_MAX_KEYS], *vals[2 * GW_SWEEP_MAX_KEYS];
        gw_sweep_case(cfg, k, names, vals);
        if ((rc = gw_sweep_case_check(m, &memo, nk, names, vals, err)) != GW_OK) {
            gw_sweep_checks_end(m, memo);
            return gw_sweep_case_refused(cfg, m, k, rc, err);
        }
    }
    /* the pass's verdict over its cases as a whole: its warnings, or a
     * refusal of the config (a chain key of no effect on any case), whose one
     * line the model appended */
    char *w = NULL;
    if (memo && m->memo_warnings && (rc = m->memo_warnings(memo, &w)) != GW_OK) {
        if (rc == GW_EINVAL && w)
            gw_err_set(err, GW_EINVAL, "%.*s", (int)strcspn(w, "\n"), w);
        else
            rc = gw_err_set(err, GW_ENOMEM, "out of memory");
    }
    gw_sweep_checks_end(m, memo);
    if (rc == GW_OK && w && warnings) {
        gw_sweep_warnings_keys(m, w);
        if ((rc = gw_sweep_warnings_append(warnings, w)) != GW_OK)
            gw_err_set(err, rc, "out of memory");
    }
    free(w);
    return rc;
}

int gw_sweep_case_check_pass(const gw_sweep_model *m, int nkeys, const char *const *names,
                             const char *const *values, char **warnings, gw_err *err)
{
    if (!m)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_case_check_pass: m is NULL");
    if (nkeys < 0 || nkeys > GW_SWEEP_MAX_KEYS)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_case_check_pass: nkeys: %d is outside [0, %d]", nkeys,
                          GW_SWEEP_MAX_KEYS);
    if (nkeys > 0 && (!names || !values))
        return gw_err_set(err, GW_EINVAL, "gw_sweep_case_check_pass: %s is NULL", !names ? "names" : "values");
    /* a config of one case, its pairs its [params] (a key twice is the
     * model's check's refusal, as in any case of a sweep) */
    gw_sweep_config cfg;
    memset(&cfg, 0, sizeof cfg);
    char *one[GW_SWEEP_MAX_KEYS];
    for (int i = 0; i < nkeys; i++) {
        one[i] = (char *)values[i];
        cfg.params[i].name = (char *)names[i];
        cfg.params[i].values = &one[i];
        cfg.params[i].nvalues = 1;
    }
    for (int i = 0; i < nkeys; i++)
        if (!names[i] || !values[i])
            return gw_err_set(err, GW_EINVAL, "gw_sweep_case_check_pass: %s[%d] is NULL",
                              !names[i] ? "names" : "values", i);
    cfg.nparams = nkeys;
    cfg.model = (char *)m->name;
    cfg.read_key = m->read_key;
    cfg.ncases = 1;
    return gw_sweep_check_pass(&cfg, m, NULL, NULL, warnings, err);
}

int gw_sweep_check_warnings(const gw_sweep_config *cfg, const gw_sweep_model *m, char **list)
{
    if (!cfg || !m || !list)
        return GW_EINVAL;
    return gw_sweep_check_pass(cfg, m, NULL, NULL, list, NULL);
}

static int same_key(const char *a, const char *b)
{
    for (; *a && *b; a++, b++)
        if (*a != *b && !((*a == '_' || *a == '-') && (*b == '_' || *b == '-')))
            return 0;
    return *a == *b;
}

/* same_key over the first n bytes of a against the whole of b */
static int same_key_n(const char *a, size_t n, const char *b)
{
    for (size_t i = 0; i < n; i++, b++)
        if (!*b || (a[i] != *b && !((a[i] == '_' || a[i] == '-') && (*b == '_' || *b == '-'))))
            return 0;
    return *b == 0;
}


int gw_sweep_case_refused(const gw_sweep_config *cfg, const gw_sweep_model *m, long k, int rc, gw_err *err)
{
    if (!err)
        return rc;
    char tmp[sizeof err->msg];
    gw_snprintf(tmp, sizeof tmp, "%s", err->msg);
    const size_t len = strcspn(tmp, ":");
    const char *key = NULL;
    for (int i = 0; cfg && tmp[len] == ':' && i < cfg->nparams && !key; i++)
        if (cfg->params[i].name && same_key_n(tmp, len, cfg->params[i].name))
            key = cfg->params[i].name;
    long other = -1;
    if (key && m && cfg->ncases > 1 && rc == GW_EINVAL) { /* (out of memory is no key's fault) */
        /* the cases before k passed; past them, at most 1000 are tried */
        const char *names[2 * GW_SWEEP_MAX_KEYS], *vals[2 * GW_SWEEP_MAX_KEYS];
        void *memo = NULL;
        gw_err scratch = {0};
        for (long j = k > 0 ? 0 : 1; j < cfg->ncases && j <= k + 1000 && other < 0; j++) {
            if (j == k)
                continue;
            gw_sweep_case(cfg, j, names, vals);
            if (gw_sweep_case_check(m, &memo, cfg->ngrid + cfg->nparams, names, vals, &scratch) == GW_OK)
                other = j;
        }
        gw_sweep_checks_end(m, memo);
    }
    if (other >= 0)
        return gw_err_set(err, rc, "case %ld: %s (case %ld takes it: a [params] key holds for every case, so the "
                          "cases it fits go in a sweep of their own)", k, tmp, other);
    return gw_err_set(err, rc, "case %ld: %s", k, tmp);
}

int gw_sweep_pairs_check(const char *call, int nk, const char *const *names, const char *const *values,
                         gw_err *err)
{
    if (nk < 0)
        return gw_err_set(err, GW_EINVAL, "%s: nkeys: %d is negative", call, nk);
    if (nk > 0 && (!names || !values))
        return gw_err_set(err, GW_EINVAL, "%s: %s is NULL", call, !names ? "names" : "values");
    for (int i = 0; i < nk; i++) {
        if (!names[i] || !values[i])
            return gw_err_set(err, GW_EINVAL, "%s: %s[%d] is NULL", call, !names[i] ? "names" : "values", i);
        for (int j = 0; j < i; j++)
            if (names[j] && same_key(names[j], names[i]))
                return gw_err_set(err, GW_EINVAL, "%s: given twice, pairs %d and %d ('%s' and '%s'): one value "
                                  "a key", names[i], j, i, values[j], values[i]);
    }
    return GW_OK;
}

int gw_sweep_run(const gw_sweep_config *cfg, const gw_sweep_model *m, int jobs, gw_progress_fn progress,
                 void *pctx, double *values, gw_err *err)
{
    return gw_sweep_run_warned(cfg, m, jobs, progress, pctx, values, NULL, err);
}

int gw_sweep_run_warned(const gw_sweep_config *cfg, const gw_sweep_model *m, int jobs, gw_progress_fn progress,
                        void *pctx, double *values, char **warnings, gw_err *err)
{
    if (!cfg || !m || !values) /* as gw_sweep_run_text (they were dereferenced: SIGSEGV) */
        return gw_err_set(err, GW_EINVAL, "gw_sweep_run: %s is NULL", !cfg ? "cfg" : !m ? "m" : "values");
    /* a config filled by hand with more cases than its grid ran its first
     * cases again (GW_OK), one with a key of no values divided by zero */
    int crc = gw_sweep_config_check(cfg, err);
    if (crc == GW_OK)
        crc = gw_sweep_model_check("gw_sweep_run", cfg, m, 1, err);
    if (crc != GW_OK)
        return crc;
    if (jobs < 0 || jobs > GW_SWEEP_JOBS_MAX) /* the range of granwave sweep --jobs */
        return gw_err_set(err, GW_EINVAL, "jobs: %d is outside [0, %d] (0: one per CPU)", jobs, GW_SWEEP_JOBS_MAX);
    for (long k = 0; k < cfg->ncases * m->ncolumns; k++)
        values[k] = NAN;
    /* the sweep's check pass, as the program's (its warnings, as the
     * program prints them, appended to *warnings) */
    int rc = gw_sweep_check_pass(cfg, m, NULL, NULL, warnings, err);
    if (rc != GW_OK)
        return rc;
    rc = gw_sweep_memory_check(cfg, m, jobs, 0, NULL, err);
    if (rc != GW_OK)
        return rc;
    sweep_ctx s = {cfg, m, values};
    rc = gw_cases_run(cfg->ncases, jobs, run_one, &s, progress, pctx, err);
    long first = 0, n = rc == GW_OK && warnings ? gw_sweep_undecided_rows(m, values, cfg->ncases, &first) : 0;
    if (n > 0)
        (void)gw_sweep_undecided_warning(m, n, cfg->ncases, first, warnings);
    /* the model's warnings over its rows (a chain case pressed beyond one
     * radius), as the program says them from its table */
    const gw_sweep_rows_rule *rule = rc == GW_OK && warnings ? gw_sweep_rows_rule_of(m->name) : NULL;
    void *acc = rule ? calloc(1, rule->acc_size) : NULL;
    for (long k = 0; acc && k < cfg->ncases; k++)
        rule->row(acc, cfg, k, values + k * m->ncolumns);
    if (acc)
        (void)rule->warnings(acc, cfg, warnings);
    free(acc);
    if (warnings)
        gw_sweep_warnings_keys(m, *warnings);
    return rc;
}
