/*
 * gw_pool.c: the worker pool (gw_pool.h). Case k is taken by an atomic
 * fetch-and-add on a shared counter, so each k is handed out exactly once; a
 * mutex orders the bookkeeping (first failure, count of finished cases, the
 * progress call). No physics, no units: cases are counted.
 */
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_pool.h"
#include "gw_pool_impl.h"

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
        if (atomic_load(&w->stop))
            break;
        long k = atomic_fetch_add(&w->next, 1);
        if (k >= w->n)
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

int gw_pool_threads(long n, int jobs)
{
    if (jobs <= 0) {
        long c = sysconf(_SC_NPROCESSORS_ONLN);
        jobs = c > 0 ? (int)(c < 1024 ? c : 1024) : 1;
    }
    if (jobs > n)
        jobs = n > 1 ? (int)n : 1;
    return jobs;
}

int gw_cases_run(long n, int jobs, gw_case_fn fn, void *ctx, gw_progress_fn progress, void *pctx,
                 gw_err *err)
{
    if (n <= 0)
        return GW_OK;
    if (!fn)
        return gw_err_set(err, GW_EINVAL, "gw_cases_run: fn is NULL");
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
    jobs = gw_pool_threads(n, jobs);
    pthread_t *th = jobs > 1 ? calloc((size_t)jobs, sizeof *th) : NULL;
    int started = 0;
    /* the threads that started are th[0..started-1]: with one that failed
     * (out of memory for its stack or TLS) before one that started, the join
     * below took the failed slot (SIGSEGV) and left the running worker
     * unjoined, its cases read before they were done (exit 0: "8 of 8
     * collisions had not ended"; tests/test_alloc_failure.sh) */
    for (int j = 0; th && j < jobs; j++)
        if (pthread_create(&th[started], NULL, worker, &w) == 0)
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
