/*
 * gw_pool.c: the worker pool (gw_pool.h). Case k is taken by an atomic
 * fetch-and-add on a shared counter, so each k is handed out exactly once; a
 * mutex orders the bookkeeping (the failure kept, count of finished cases,
 * the progress call). The failure kept is the lowest case's: every case below
 * a failed one was handed out before it and runs to its end, so the error a
 * caller gets is the one --jobs 1 gives (it was the first in time: a study
 * failing at N = 5 and 6 named either, by the threads' timing). No physics, no units: cases are counted.
 */
#include <math.h>
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
    long failed_k; /* the case whose failure is kept, -1: none (or a cancel) */
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
        /* a case that failed without a word (its status alone, or a status
         * that is none of the library's) was returned with an empty message:
         * the caller had nothing to show but the status */
        if (rc != GW_OK && !err.msg[0])
            gw_err_set(&err, rc, "case %ld of %ld failed (%s, status %d) and gave no message", k, w->n,
                       gw_strerror(rc), rc);
        pthread_mutex_lock(&w->lock);
        if (rc != GW_OK && (w->status == GW_OK || (w->failed_k >= 0 && k < w->failed_k))) {
            w->status = rc;
            w->err = err;
            w->failed_k = k;
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

int gw_pool_cpus(void)
{
    const long c = sysconf(_SC_NPROCESSORS_ONLN);
    return c > 0 ? (int)(c < 1024 ? c : 1024) : 1;
}

int gw_pool_threads(long n, int jobs)
{
    if (jobs <= 0)
        jobs = gw_pool_cpus();
    if (jobs > n)
        jobs = n > 1 ? (int)n : 1;
    return jobs;
}

void gw_pool_give(double *h, int m, double w)
{
    if (m < 1)
        return;
    const double v = h[0] + w; /* the top (the first free) replaced, sifted down */
    int i = 0;
    for (;;) {
        int c = 2 * i + 1;
        if (c >= m)
            break;
        if (c + 1 < m && h[c + 1] < h[c])
            c++;
        if (!(h[c] < v))
            break;
        h[i] = h[c];
        i = c;
    }
    h[i] = v;
}

void gw_pool_give_each(double *h, int m, long n, double w)
{
    if (m < 1 || n <= 0)
        return;
    double top = h[0];
    for (int k = 1; k < m; k++)
        top = fmax(top, h[k]);
    while (n > 0) {
        if (n >= m && top - h[0] <= w) {
            /* every thread comes free within w of the others: each takes
             * one in turn, the first free first (it is then free no sooner
             * than the last), so whole rounds add to each alike and keep the
             * heap; the rest go one at a time */
            const double add = (double)(n / m) * w;
            for (int k = 0; k < m; k++)
                h[k] += add;
            top += add;
            n %= m;
            continue;
        }
        top = fmax(top, h[0] + w);
        gw_pool_give(h, m, w);
        n--;
    }
}

static int by_end_down(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

double gw_pool_span(double *e, int m, int cpus)
{
    if (m < 1)
        return 0;
    qsort(e, (size_t)m, sizeof *e, by_end_down);
    double t = 0;
    for (int k = 1; k <= m; k++) /* k threads at work from e[k] to e[k - 1] */
        t += (e[k - 1] - (k < m ? e[k] : 0)) * fmax(1.0, (double)k / (cpus > 0 ? cpus : 1));
    return t;
}

void gw_pool_clock_busy(gw_pool_clock *c, int under_way)
{
    if (under_way > c->busy)
        c->busy = under_way;
}

void gw_pool_clock_count(gw_pool_clock *c, double done, int under_way, int cpus)
{
    /* the work done since the last count went on the threads under way since */
    if (done > c->done_hi) {
        c->elapsed += (done - c->done_hi) / fmin(fmax(c->busy, 1), fmax(cpus, 1));
        c->done_hi = done;
    }
    c->busy = under_way;
}

int gw_pool_eta_init(gw_pool_eta *e, long n, int jobs)
{
    memset(e, 0, sizeof *e);
    const int th = gw_pool_threads(n, jobs);
    if (!(e->free_at = malloc((size_t)th * sizeof *e->free_at)))
        return GW_ENOMEM;
    e->threads = th;
    e->cpus = gw_pool_cpus();
    e->n = n > 0 ? n : 0;
    for (int k = 0; k < GW_POOL_ETA_KINDS; k++)
        e->gain[k] = 1.0;
    return GW_OK;
}

void gw_pool_eta_free(gw_pool_eta *e)
{
    if (!e)
        return;
    free(e->free_at);
    free(e->cum);
    free(e->kind);
    e->free_at = NULL;
    e->cum = NULL;
    e->kind = NULL;
}

void gw_pool_eta_begun(gw_pool_eta *e, int under_way)
{
    gw_pool_clock_busy(&e->clock, under_way);
}

static int by_end_up(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Weight sum given to the m threads of heap h as many small cases are by the
 * first-free rule: the threads freest filled up to one level (sorted
 * ascending after, which is a min-heap). */
static void give_level(double *h, int m, double sum)
{
    if (m < 1 || !(sum > 0))
        return;
    qsort(h, (size_t)m, sizeof *h, by_end_up);
    /* the level L with sum over k of max(0, L - h[k]) = sum: the first k + 1
     * threads raised to one level, while it stays below the next one's */
    double acc = 0, level = h[0] + sum;
    for (int k = 0; k < m; k++) {
        acc += h[k];
        level = (sum + acc) / (k + 1);
        if (k + 1 == m || level <= h[k + 1])
            break;
    }
    for (int j = 0; j < m; j++)
        if (h[j] < level)
            h[j] = level;
}

int gw_pool_eta_weigh(gw_pool_eta *e, const double *w, long n)
{
    if (!e || !w || n < 1)
        return GW_OK;
    double *cum = malloc(((size_t)n + 1) * sizeof *cum);
    if (!cum)
        return GW_ENOMEM;
    double sum = 0;
    long known = 0;
    for (long i = 0; i < n; i++)
        if (isfinite(w[i]) && w[i] > 0)
            sum += w[i], known++;
    const double mean = known > 0 ? sum / (double)known : 1.0;
    cum[0] = 0;
    for (long i = 0; i < n; i++)
        cum[i + 1] = cum[i] + (isfinite(w[i]) && w[i] > 0 ? w[i] : mean);
    free(e->cum);
    e->cum = cum;
    e->n = n;
    free(e->kind); /* another set of cases: their kinds given anew */
    e->kind = NULL;
    return GW_OK;
}

double gw_pool_eta_weight(const gw_pool_eta *e, long i)
{
    return e && e->cum && i >= 0 && i < e->n ? e->cum[i + 1] - e->cum[i] : 1.0;
}

int gw_pool_eta_kinds(gw_pool_eta *e, const int *kind, long n)
{
    if (!e || !kind || !e->cum || n != e->n || n < 1)
        return GW_EINVAL;
    for (long i = 0; i < n; i++)
        if (kind[i] < -1 || kind[i] >= GW_POOL_ETA_KINDS)
            return GW_EINVAL;
    int *k = malloc((size_t)n * sizeof *k);
    if (!k)
        return GW_ENOMEM;
    memcpy(k, kind, (size_t)n * sizeof *k);
    free(e->kind);
    e->kind = k;
    return GW_OK;
}

void gw_pool_eta_ended(gw_pool_eta *e, long i, double t)
{
    if (!e || i < 0 || i >= e->n || !isfinite(t) || !(t > 0))
        return;
    const double w = gw_pool_eta_weight(e, i);
    const int k = e->kind ? e->kind[i] : -1;
    e->d_all += t;
    e->w_all += w;
    if (k >= 0) {
        e->kd[k] += t;
        e->kw[k] += w;
    }
    /* each kind's time per weight over all ended cases' (their pace) */
    const double pace = e->d_all / e->w_all;
    for (int j = 0; j < GW_POOL_ETA_KINDS; j++)
        e->gain[j] = e->kw[j] > 0 && e->kd[j] > 0 && pace > 0 ? e->kd[j] / e->kw[j] / pace : 1.0;
}

double gw_pool_eta_weight_learned(const gw_pool_eta *e, long i)
{
    const double w = gw_pool_eta_weight(e, i);
    return e && e->kind && i >= 0 && i < e->n && e->kind[i] >= 0 ? w * e->gain[e->kind[i]] : w;
}

/* The part, the work counted in weight: done and total; the cases under way
 * (wrun, share), those to come: to_come alike ones (cum NULL) or the cases
 * next..n-1 of cum. */
static double eta_part(gw_pool_eta *e, double done, double learned, double total, const double *wrun,
                       const long *irun, const double *share, int nrun, long to_come, long next)
{
    gw_pool_clock_count(&e->clock, done, nrun, e->cpus);
    /* the time elapsed in learned weight: the clock's (its work per thread
     * at work, counted in weight, which only grows) scaled by the work done
     * learned over the work done in weight */
    const double elapsed = e->clock.elapsed * (done > 0 && learned > 0 ? learned / done : 1.0);
    const int th = e->threads;
    double part;
    if (elapsed > 0 && e->free_at && nrun <= th) {
        /* the time left: the cases under way hold their threads for their
         * share left, those to come go to the first thread free */
        for (int k = 0; k < th; k++)
            e->free_at[k] = 0;
        for (int i = 0; i < nrun; i++)
            gw_pool_give(e->free_at, th,
                         (irun ? gw_pool_eta_weight_learned(e, irun[i]) : wrun ? wrun[i] : 1.0) *
                             (1 - fmin(fmax(share[i], 0), 1)));
        if (!e->cum) {
            gw_pool_give_each(e->free_at, th, to_come, 1.0);
        } else {
            long a = next < 0 ? 0 : next;
            if (e->n - a > GW_POOL_ETA_ONE_BY_ONE) {
                const long b = e->n - GW_POOL_ETA_ONE_BY_ONE;
                double sum = 0;
                if (!e->kind)
                    sum = e->cum[b] - e->cum[a];
                else /* each at its kind's pace */
                    for (long i = a; i < b; i++)
                        sum += gw_pool_eta_weight_learned(e, i);
                give_level(e->free_at, th, sum);
                a = b;
            }
            for (long i = a; i < e->n; i++)
                gw_pool_give(e->free_at, th, gw_pool_eta_weight_learned(e, i));
        }
        const double left = gw_pool_span(e->free_at, th, e->cpus);
        part = elapsed / (elapsed + left);
    } else { /* nothing done yet (or no schedule): the share of the work */
        part = total > 0 ? done / total : 0;
    }
    /* held where it would fall (a case under way slower than the ones
     * before): a display whose share fell would read as work undone */
    e->now = fmin(fmax(part, 0), 1);
    e->shown = fmax(e->shown, e->now);
    return e->shown;
}

double gw_pool_eta_part(gw_pool_eta *e, long ended, const double *share, int nrun, long to_come)
{
    double done = (double)ended;
    for (int i = 0; i < nrun; i++)
        done += fmin(fmax(share[i], 0), 1);
    if (to_come < 0)
        to_come = 0;
    const double total = (double)ended + nrun + (double)to_come;
    return eta_part(e, done, done, total, NULL, NULL, share, nrun, to_come, 0);
}

double gw_pool_eta_part_weighed(gw_pool_eta *e, double w_ended, const double *wrun, const double *share, int nrun,
                                long next)
{
    double done = w_ended > 0 ? w_ended : 0, total = done;
    for (int i = 0; i < nrun; i++) {
        done += wrun[i] * fmin(fmax(share[i], 0), 1);
        total += wrun[i];
    }
    if (next < 0)
        next = 0;
    long to_come = 0;
    if (e->cum && next < e->n)
        total += e->cum[e->n] - e->cum[next];
    else if (!e->cum)
        to_come = e->n - next > 0 ? e->n - next : 0;
    return eta_part(e, done, done, total, wrun, NULL, share, nrun, to_come, next);
}

double gw_pool_eta_part_cases(gw_pool_eta *e, double w_ended, const long *irun, const double *share, int nrun,
                              long next)
{
    /* the work done in weight (the clock's) and in learned weight: the
     * cases ended count the same in both (their learned weights sum to
     * their weights, the factors being over their mean pace) */
    double done = w_ended > 0 ? w_ended : 0, learned = done, total = done;
    for (int i = 0; i < nrun; i++) {
        const double w = gw_pool_eta_weight(e, irun[i]), sh = fmin(fmax(share[i], 0), 1);
        done += w * sh;
        learned += gw_pool_eta_weight_learned(e, irun[i]) * sh;
        total += w;
    }
    if (next < 0)
        next = 0;
    long to_come = 0;
    if (e->cum && next < e->n)
        total += e->cum[e->n] - e->cum[next];
    else if (!e->cum)
        to_come = e->n - next > 0 ? e->n - next : 0;
    return eta_part(e, done, learned, total, NULL, irun, share, nrun, to_come, next);
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
    w.failed_k = -1;
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
