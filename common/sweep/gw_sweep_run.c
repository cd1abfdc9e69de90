/*
 * gw_sweep_run.c: independent cases run in memory on threads (gw_sweep.h): a
 * shared case counter, the first failure kept, progress reported to the
 * caller's callback one call at a time. No physics; each case builds its own
 * model and solver (one SUNDIALS context per solver, hence per thread).
 */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_sweep.h"

typedef struct pool {
    long n;
    gw_case_fn fn;
    void *ctx;
    gw_progress_fn progress;
    void *pctx;
    atomic_long next;
    atomic_int stop;
    long done;
    int status;
    gw_err err;
    pthread_mutex_t lock;
} pool;

static void *worker(void *arg)
{
    pool *w = arg;
    for (;;) {
        long k = atomic_fetch_add(&w->next, 1);
        if (k >= w->n || atomic_load(&w->stop))
            break;
        gw_err err = {{0}};
        int rc = w->fn(w->ctx, k, &err);
        pthread_mutex_lock(&w->lock);
        if (rc != GW_OK && w->status == GW_OK) {
            w->status = rc;
            w->err = err;
        }
        if (rc == GW_OK) {
            w->done++;
            if (w->progress && w->status == GW_OK && w->progress(w->pctx, w->done, w->n) != 0) {
                w->status = GW_ECANCELED;
                gw_err_set(&w->err, GW_ECANCELED, "canceled by the caller after %ld of %ld cases", w->done, w->n);
            }
        }
        if (w->status != GW_OK)
            atomic_store(&w->stop, 1);
        pthread_mutex_unlock(&w->lock);
    }
    return NULL;
}

int gw_cases_run(long n, int jobs, gw_case_fn fn, void *ctx, gw_progress_fn progress, void *pctx,
                 gw_err *err)
{
    if (n <= 0)
        return GW_OK;
    pool w;
    memset(&w, 0, sizeof w);
    w.n = n;
    w.fn = fn;
    w.ctx = ctx;
    w.progress = progress;
    w.pctx = pctx;
    atomic_init(&w.next, 0);
    atomic_init(&w.stop, 0);
    pthread_mutex_init(&w.lock, NULL);
    if (jobs <= 0) {
        long c = sysconf(_SC_NPROCESSORS_ONLN);
        jobs = c > 0 ? (int)(c < 1024 ? c : 1024) : 1;
    }
    if (jobs > n)
        jobs = (int)n;
    pthread_t *th = jobs > 1 ? calloc((size_t)jobs, sizeof *th) : NULL;
    int started = 0;
    for (int j = 0; th && j < jobs; j++)
        if (pthread_create(&th[j], NULL, worker, &w) == 0)
            started++;
    if (started == 0) /* one job, or no thread could start: run here */
        worker(&w);
    for (int j = 0; j < started; j++)
        pthread_join(th[j], NULL);
    free(th);
    pthread_mutex_destroy(&w.lock);
    if (w.status != GW_OK && err)
        *err = w.err;
    return w.status;
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
    int rc = s->m->run(s->cfg->ngrid + s->cfg->nparams, names, values, s->values + k * s->m->ncolumns, err);
    if (rc != GW_OK) {
        char tmp[sizeof err->msg];
        snprintf(tmp, sizeof tmp, "%s", err->msg);
        gw_err_set(err, rc, "case %ld: %s", k, tmp);
    }
    return rc;
}

int gw_sweep_run(const gw_sweep_config *cfg, const gw_sweep_model *m, int jobs, gw_progress_fn progress,
                 void *pctx, double *values, gw_err *err)
{
    const int nk = cfg->ngrid + cfg->nparams;
    for (long k = 0; k < cfg->ncases * m->ncolumns; k++)
        values[k] = NAN;
    for (long k = 0; m->check && k < cfg->ncases; k++) {
        const char *names[2 * GW_SWEEP_MAX_KEYS], *vals[2 * GW_SWEEP_MAX_KEYS];
        gw_sweep_case(cfg, k, names, vals);
        int rc = m->check(nk, names, vals, err);
        if (rc != GW_OK) {
            char tmp[sizeof err->msg];
            snprintf(tmp, sizeof tmp, "%s", err ? err->msg : "");
            return gw_err_set(err, rc, "case %ld: %s", k, tmp);
        }
    }
    sweep_ctx s = {cfg, m, values};
    return gw_cases_run(cfg->ncases, jobs, run_one, &s, progress, pctx, err);
}
