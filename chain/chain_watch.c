/*
 * chain_watch.c: a study's progress within its collisions (chain_watch.h).
 * A falcon study of 500 columns under cvode on a sensor body said nothing
 * until its first collision ended, and wavespeed only per tenth of its
 * collisions: a display that must speak at a bounded interval needs to know
 * where the collisions under way are. Each collision reports through the
 * single run's own progress (gw_chain_collide_progress: t, t_expect at every
 * output sample); the watch adds up, under one lock, the work of the
 * collisions ended and the parts done of those under way, and hands the share
 * done to the caller's gw_chain_watch_fn.
 *
 * A collision's weight w is its expected steps and samples (the plan that
 * bounds it) over its expected length t_expect, times its beads: the work
 * grows as N^2 over a falcon study's columns, so a count of collisions would
 * put the first half of the columns at half the work. Measured, a whole
 * collision's wall time follows w (its wall time per bead and t_expect even
 * falls by a third from N = 20 to 200), so w counts a collision ended whole.
 *
 * But a collision runs past t_expect until every contact is open and
 * separating, by a ratio r = t_end / t_expect that grows with N (measured
 * under cvode bdf at v_imp 0.3, steel on steel, alike at any speed without
 * gravity: 0.58 at N = 1, 0.84 at 3, 1.00 at 10, 1.08 at 20, 1.21 at 50, 1.29
 * at 100 and 150, 1.56 at 200, 1.93 at 300, 1.27 at 400; 5.3 at 80; a pvc
 * wall 1.5 at N = 10, the t-max at 50), and the tail goes fast: a 400-bead
 * column spent 0.6 s of its 12.6 s past t_expect (5 %). Counted whole at
 * t_expect, the collisions under way said 100 % for the rest of their run
 * (two 200-bead columns at once: from t_expect on, a third of their time).
 * So a collision under way at x = t / t_expect counts
 *     f(x) = (1 - TAIL) min(x / B, 1) + TAIL (x - B) / (max(E, 1.25 x) - B) [x > B],
 * E = c rho(N) its expected end, B = min(E, 1) the end of its bulk,
 * rho(N) = 1 + 0.1 log2(N / 10) in [0.5, 2] (the fit of the ratios above), c
 * the study's own correction learnt from its collisions ended (the mean of
 * r / rho weighed by w; 1 before any), TAIL a tenth of its work spread over
 * its simulated time from B to its expected end, and past that end expected
 * to go on a quarter longer than it has (where it ends is not known): f
 * stays under 1 until the collision ends. The share done is
 *     part = (sum_ended w + sum_running w f(x)) / sum_all w.
 * A correction that grows takes a share back; the share reported is held at
 * its largest instead (the time left then grows with the time elapsed).
 *
 * The part reported is not that share of the work but the share of the
 * study's time, which the display's time left ((1 - part) / part of the time
 * elapsed) needs: a study runs its sweeps on J threads, but once fewer
 * collisions are left than threads the last run alone (falcon --n 400:402 on
 * 2 threads: its third column after the first two; wavespeed's front
 * columns, falcon's traces after the sweep, on one thread), and there the
 * work goes at a fraction of the pace so far: by the share of the work, the
 * time left was 0.44 to 0.64 of the true one over the first three quarters
 * of the study (measured in each thread's CPU time). So with every thread at the same pace, time is
 * counted in work per thread at work (at most one per CPU online: threads
 * beyond the CPUs share them): the time elapsed
 *     T_e = sum over reports of (work done since the last) / min(collisions under way, CPUs),
 * and the time left T_l the end of the work left scheduled as the pool hands
 * it out: each collision under way holds its thread for its weight times
 * 1 - f(x), each collision to come, in the planned order, goes to the first
 * thread free (of its group's threads, gw_pool_threads), the threads of a
 * group beyond the CPUs sharing them, and each group (a sweep, then a run on
 * the study's own thread, ...) begins when the one before has ended. part = T_e / (T_e + T_l); on one thread T_e is the work
 * done and T_l the work left: the share of the work as before. The clock and
 * the schedule's steps are the pool's (gw_pool_impl.h), which `granwave
 * sweep`'s line schedules its cases with too (gw_pool_eta).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_collide_impl.h"
#include "chain_model.h"
#include "chain_watch.h"
#include "gw_pool_impl.h"

/* A tenth of a collision's work is in its tail (5 % measured at N = 400),
 * which is expected to go on a quarter longer than it has once past its
 * expected end */
#define CHAIN_WATCH_TAIL 0.1
#define CHAIN_WATCH_PAST 1.25

double chain_watch_share(double x, double e)
{
    if (!(x > 0))
        return 0;
    const double bulk = fmin(e, 1.0); /* where the bulk of the work ends: t_expect, or the end if sooner */
    const double end = fmax(e, CHAIN_WATCH_PAST * x); /* > bulk when x > bulk */
    double f = (1 - CHAIN_WATCH_TAIL) * fmin(x / bulk, 1.0);
    if (x > bulk)
        f += CHAIN_WATCH_TAIL * (x - bulk) / (end - bulk);
    return fmin(f, 1.0);
}

double chain_watch_tail(int n)
{
    const double rho = 1 + 0.1 * log2((n > 0 ? n : 1) / 10.0);
    return fmin(fmax(rho, 0.5), 2.0);
}

void chain_watch_init(chain_watch *w, gw_chain_watch_fn fn, void *ctx)
{
    memset(w, 0, sizeof *w);
    w->fn = fn;
    w->ctx = ctx;
    w->cpus = gw_pool_cpus();
    pthread_mutex_init(&w->lock, NULL);
}

void chain_watch_destroy(chain_watch *w)
{
    if (!w)
        return;
    pthread_mutex_destroy(&w->lock);
    free(w->task);
    free(w->threads);
    free(w->slot);
    w->task = NULL;
    w->threads = NULL;
    w->slot = NULL;
}

/* Room for n doubles of scratch (a group's threads, or the collisions under
 * way); 0 when out of memory (the schedule is then not known). */
static int slot_room(chain_watch *w, long n)
{
    if (n <= w->slot_cap)
        return 1;
    double *s = realloc(w->slot, (size_t)n * sizeof *s);
    if (!s)
        return 0;
    w->slot = s;
    w->slot_cap = (int)n;
    return 1;
}

void chain_watch_group(chain_watch *w, int threads)
{
    if (!w || !w->fn || w->unplanned)
        return;
    if (threads < 1)
        threads = 1;
    if (w->ngroup == w->group_cap) {
        int cap = w->group_cap ? 2 * w->group_cap : 8;
        int *g = realloc(w->threads, (size_t)cap * sizeof *g);
        if (!g) {
            w->unplanned = 1;
            return;
        }
        w->threads = g;
        w->group_cap = cap;
    }
    if (!slot_room(w, threads)) {
        w->unplanned = 1;
        return;
    }
    w->threads[w->ngroup++] = threads;
}

void chain_watch_plan_one(chain_watch *w, double weight)
{
    if (!w || !w->fn)
        return;
    w->total++;
    w->w_plan += weight;
    if (w->unplanned)
        return;
    if (w->ngroup == 0) /* planned outside a group: a run of its own */
        chain_watch_group(w, 1);
    if (w->ntask == w->task_cap && !w->unplanned) {
        long cap = w->task_cap ? 2 * w->task_cap : 64;
        chain_watch_task *t = realloc(w->task, (size_t)cap * sizeof *t);
        if (t) {
            w->task = t;
            w->task_cap = cap;
        } else {
            w->unplanned = 1;
        }
    }
    if (!w->unplanned)
        w->task[w->ntask++] = (chain_watch_task){.weight = weight, .group = w->ngroup - 1, .begun = 0};
}

/* An adaptive method's steps per T_c, the beads' contact time: cvode bdf at
 * its default tolerance (1e-12) took 103,733 steps over 629 T_c at n = 200
 * (165 a T_c; rk4 takes 400 by default). Only the ratio between a study's
 * collisions matters, and they all run one method. */
#define CHAIN_WATCH_STEPS_PER_TC 165.0

/* The weight of one collision: its beads times its steps and samples over
 * its expected length, each costing O(n), per t_expect. The steps are rk4's
 * own; an adaptive method's follow the beads' contact time T_c (the plan's
 * dt_max is the stiffest contact's, the wall's too: by it softwall's 20 short
 * columns on the rigid steel wall weighed far more than their share of its
 * time, and its lines said 35 % done at 2 s of a 19 s study). 1 where the
 * plan refuses (the run then fails at once, with its message). */
double chain_watch_weight(const gw_chain_params *p, const gw_chain_run_opts *o)
{
    collide_plan pl;
    gw_err e = {{0}};
    if (chain_collide_plan_make(p, o, &pl, &e) != GW_OK)
        return 1;
    double step = pl.type == gw_solver_rk4 ? chain_plan_step(&pl) : pl.tc / CHAIN_WATCH_STEPS_PER_TC;
    double w = p->n * pl.t_expect * (1 / step + (pl.dt_out > 0 ? 1 / pl.dt_out : 0));
    return w > 0 && isfinite(w) ? w : 1;
}

void chain_watch_plan(chain_watch *w, const gw_chain_params *p, const gw_chain_run_opts *o)
{
    if (!w || !w->fn)
        return;
    chain_watch_group(w, 1); /* on the study's own thread, after what was planned before */
    chain_watch_plan_one(w, chain_watch_weight(p, o));
}

void chain_watch_plan_sweep(chain_watch *w, const gw_chain_params *tmpl, const gw_chain_run_opts *o,
                            const double *v, int nv, int n_lo, int n_hi, int jobs)
{
    if (!w || !w->fn || nv < 1 || n_hi < n_lo)
        return;
    chain_watch_group(w, gw_pool_threads((long)nv * (n_hi - n_lo + 1), jobs));
    for (int i = 0; i < nv; i++)
        for (int n = n_lo; n <= n_hi; n++) {
            gw_chain_params p = *tmpl;
            p.n = n;
            p.v_imp = v[i];
            chain_watch_plan_one(w, chain_watch_weight(&p, o));
        }
}

/* The study's correction c of the expected lengths (1 before a collision ended). */
static double correction(const chain_watch *w)
{
    return w->c_den > 0 ? w->c_num / w->c_den : 1.0;
}

/* The time left, in work per thread: the collisions under way hold their
 * threads for what is left of their work (weight times 1 - f), those to come
 * go, in order, to the first thread free of their group, a group begins when
 * the one before has ended. Under the lock; -1 where the schedule is not known. */
static double time_left(chain_watch *w, double c)
{
    if (w->unplanned)
        return -1;
    int g = w->first < w->ntask ? w->task[w->first].group : w->ngroup; /* the group now */
    int m = 0;
    for (const chain_watch_running *r = w->running; r; r = r->next, m++)
        if (r->group >= 0 && r->group < g)
            g = r->group;
    double left = 0;
    long i = w->first;
    for (int grp = g; grp < w->ngroup || (grp == g && m > 0); grp++) {
        int th = grp < w->ngroup ? w->threads[grp] : 1;
        if (grp == g && m > th)
            th = m;
        if (!slot_room(w, th))
            return -1;
        for (int k = 0; k < th; k++)
            w->slot[k] = 0;
        if (grp == g) /* the collisions under way hold threads of this group */
            for (const chain_watch_running *r = w->running; r; r = r->next)
                gw_pool_give(w->slot, th, r->weight * (1 - chain_watch_share(r->x, c * r->rho)));
        for (; i < w->ntask && w->task[i].group <= grp; i++)
            if (!w->task[i].begun)
                gw_pool_give(w->slot, th, w->task[i].weight);
        left += gw_pool_span(w->slot, th, w->cpus);
    }
    return left;
}

/* The caller's report, under the lock: the share of the study's time. */
static void report(chain_watch *w)
{
    const double c = correction(w);
    double done = w->w_ended, total = w->w_ended + w->w_plan;
    for (const chain_watch_running *r = w->running; r; r = r->next) {
        done += r->weight * chain_watch_share(r->x, c * r->rho);
        total += r->weight;
    }
    /* the time elapsed: the work done since the last report went on the
     * collisions under way since, each on its thread */
    gw_pool_clock_count(&w->clock, done, w->nrun, w->cpus);
    double left;
    if (w->left_known && done - w->done_at < 1e-3 * total) {
        left = fmax(w->left_at - (w->clock.elapsed - w->elapsed_at), 0);
    } else {
        left = time_left(w, c);
        w->left_at = left;
        w->elapsed_at = w->clock.elapsed;
        w->done_at = done;
        w->left_known = left >= 0;
    }
    double part;
    if (left >= 0 && w->clock.elapsed > 0)
        part = w->clock.elapsed / (w->clock.elapsed + left);
    else /* nothing done yet, or no schedule: the share of the work */
        part = total > 0 ? done / total : 0;
    /* held where a longer correction would take it back: a display whose
     * share fell would read as work undone */
    part = fmin(fmax(part, 0), 1);
    w->shown = fmax(w->shown, part);
    w->fn(w->ctx, w->done, w->total, w->shown);
}

void chain_watch_begin(chain_watch *w, chain_watch_running *run, double weight, double rho)
{
    memset(run, 0, sizeof *run);
    run->w = w;
    run->weight = weight;
    run->rho = rho;
    run->group = -1; /* not planned */
    pthread_mutex_lock(&w->lock); /* from planned to under way */
    w->w_plan = fmax(w->w_plan - weight, 0);
    if (!w->unplanned && w->first < w->ntask) {
        /* the one planned of its weight in the group now (the pool hands its
         * cases out in order, but two threads may take theirs in either order
         * to here), else the first to come */
        long k = w->first;
        for (long i = w->first; i < w->ntask && w->task[i].group == w->task[w->first].group; i++)
            if (!w->task[i].begun && w->task[i].weight == weight) {
                k = i;
                break;
            }
        w->task[k].begun = 1;
        run->group = w->task[k].group;
        while (w->first < w->ntask && w->task[w->first].begun)
            w->first++;
    }
    run->next = w->running;
    w->running = run;
    w->nrun++;
    w->left_known = 0; /* the schedule changed */
    gw_pool_clock_busy(&w->clock, w->nrun);
    pthread_mutex_unlock(&w->lock);
}

void chain_watch_at(chain_watch_running *run, double x)
{
    pthread_mutex_lock(&run->w->lock);
    run->x = x;
    report(run->w);
    pthread_mutex_unlock(&run->w->lock);
}

void chain_watch_end(chain_watch_running *run, int ok)
{
    chain_watch *w = run->w;
    pthread_mutex_lock(&w->lock);
    for (chain_watch_running **q = &w->running; *q; q = &(*q)->next)
        if (*q == run) {
            *q = run->next;
            break;
        }
    w->nrun--;
    w->left_known = 0; /* the schedule changed */
    /* its length against the expected one: the study's correction */
    w->w_ended += run->weight;
    if (ok && run->x > 0) {
        w->c_num += run->weight * run->x / run->rho;
        w->c_den += run->weight;
    }
    w->done++;
    report(w);
    pthread_mutex_unlock(&w->lock);
}

static void at_sample(void *ctx, double t, double t_expect, double t_max)
{
    (void)t_max;
    chain_watch_at(ctx, t_expect > 0 ? fmax(t / t_expect, 0) : 0);
}

int chain_watch_collide(chain_watch *w, const gw_chain *c, const gw_chain_params *p, const gw_chain_run_opts *o,
                        gw_chain_result *r, gw_err *err)
{
    if (!w || !w->fn)
        return gw_chain_collide(c, o, r, err);
    chain_watch_running run;
    chain_watch_begin(w, &run, chain_watch_weight(p, o), chain_watch_tail(p->n));
    int rc = gw_chain_collide_progress(c, o, at_sample, &run, r, err);
    chain_watch_end(&run, rc == GW_OK);
    return rc;
}
