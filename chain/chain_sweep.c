/*
 * chain_sweep.c: independent collisions over a grid of (v_imp, N), spread over
 * threads. Each case builds its own chain and solver (one SUNDIALS context per
 * solver, hence per thread), so cases share nothing but the work counter.
 */
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_chain.h"

typedef struct sweep {
    const gw_chain_params *tmpl;
    const gw_chain_run_opts *o;
    const double *v;
    int nv, n_lo, n_hi, ncase, progress;
    gw_chain_result *res;
    atomic_int next, done, failed;
    pthread_mutex_t lock;
    int first_rc;
    gw_err first_err;
    double t0;
} sweep;

static void *worker(void *arg)
{
    sweep *w = arg;
    const int per_v = w->n_hi - w->n_lo + 1;
    for (;;) {
        int k = atomic_fetch_add(&w->next, 1);
        if (k >= w->ncase || atomic_load(&w->failed))
            break;
        gw_chain_params p = *w->tmpl;
        p.v_imp = w->v[k / per_v];
        p.n = w->n_lo + k % per_v;
        gw_chain *c = NULL;
        gw_err err = {{0}};
        int rc = gw_chain_create(&p, &c, &err);
        if (rc == GW_OK)
            rc = gw_chain_collide(c, w->o, &w->res[k], &err);
        gw_chain_free(c);
        if (rc != GW_OK) {
            pthread_mutex_lock(&w->lock);
            if (!atomic_load(&w->failed)) {
                w->first_rc = rc;
                gw_err_set(&w->first_err, rc, "N = %d, v_imp = %g m/s: %s", p.n, p.v_imp, err.msg);
                atomic_store(&w->failed, 1);
            }
            pthread_mutex_unlock(&w->lock);
            break;
        }
        int d = atomic_fetch_add(&w->done, 1) + 1;
        if (w->progress && (d % (w->ncase / 10 + 1) == 0 || d == w->ncase)) {
            double el = (gw_clock_ms() - w->t0) / 1e3;
            pthread_mutex_lock(&w->lock);
            fprintf(stderr, "  %d/%d collisions, %.1f s elapsed, ~%.1f s left\n", d, w->ncase,
                    el, el / d * (w->ncase - d));
            pthread_mutex_unlock(&w->lock);
        }
    }
    return NULL;
}

int gw_chain_sweep_n(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v,
                     int nv, int n_lo, int n_hi, int jobs, int progress, gw_chain_result *res,
                     gw_err *err)
{
    if (nv < 1 || n_lo < 1 || n_hi < n_lo)
        return gw_err_set(err, GW_EINVAL, "sweep: empty grid");
    sweep w;
    memset(&w, 0, sizeof w);
    w.tmpl = tmpl;
    w.o = o;
    w.v = v;
    w.nv = nv;
    w.n_lo = n_lo;
    w.n_hi = n_hi;
    w.ncase = nv * (n_hi - n_lo + 1);
    w.progress = progress;
    w.res = res;
    w.t0 = gw_clock_ms();
    memset(res, 0, (size_t)w.ncase * sizeof *res);
    pthread_mutex_init(&w.lock, NULL);
    if (jobs <= 0) {
        long c = sysconf(_SC_NPROCESSORS_ONLN);
        jobs = c > 0 ? (int)c : 1;
    }
    if (jobs > w.ncase)
        jobs = w.ncase;
    pthread_t *th = calloc((size_t)jobs, sizeof *th);
    int started = 0;
    for (int j = 0; th && j < jobs; j++)
        if (pthread_create(&th[j], NULL, worker, &w) == 0)
            started++;
    if (started == 0)
        worker(&w);
    for (int j = 0; j < started; j++)
        pthread_join(th[j], NULL);
    free(th);
    pthread_mutex_destroy(&w.lock);
    if (atomic_load(&w.failed)) {
        if (err)
            *err = w.first_err;
        return w.first_rc;
    }
    return GW_OK;
}
