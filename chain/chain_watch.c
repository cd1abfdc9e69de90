/*
 * chain_watch.c: a study's progress within its collisions (chain_watch.h).
 * A falcon study of 500 columns under cvode on a sensor body said nothing
 * until its first collision ended, and wavespeed only per tenth of its
 * collisions: a display that must speak at a bounded interval needs to know
 * where the collisions under way are. Each collision reports through the
 * single run's own progress (gw_chain_collide_progress: t, t_expect at every
 * output sample); the watch adds up, under one lock, the weights of the
 * collisions ended and the parts done of those under way, and hands the sum
 * to the caller's gw_chain_watch_fn. A collision's weight is its expected
 * steps and samples (the plan that bounds it) times its beads: the work grows
 * as N^2 over a falcon study's columns, so a count of collisions would put
 * the first half of the columns at half the work.
 */
#include <math.h>
#include <string.h>

#include "chain_collide_impl.h"
#include "chain_model.h"
#include "chain_watch.h"

void chain_watch_init(chain_watch *w, gw_chain_watch_fn fn, void *ctx)
{
    memset(w, 0, sizeof *w);
    w->fn = fn;
    w->ctx = ctx;
    pthread_mutex_init(&w->lock, NULL);
}

void chain_watch_destroy(chain_watch *w)
{
    if (w)
        pthread_mutex_destroy(&w->lock);
}

/* An adaptive method's steps per T_c, the beads' contact time: cvode bdf at
 * its default tolerance (1e-12) took 103,733 steps over 629 T_c at n = 200
 * (165 a T_c; rk4 takes 400 by default). Only the ratio between a study's
 * collisions matters, and they all run one method. */
#define CHAIN_WATCH_STEPS_PER_TC 165.0

/* The weight of one collision: its beads times its steps and samples over
 * its expected length, each costing O(n). The steps are rk4's own; an
 * adaptive method's follow the beads' contact time T_c (the plan's dt_max is
 * the stiffest contact's, the wall's too: by it softwall's 20 short columns
 * on the rigid steel wall weighed far more than their share of its time,
 * and its lines said 35 % done at 2 s of a 19 s study). 1 where the plan
 * refuses (the run then fails at once, with its message). */
static double weight(const gw_chain_params *p, const gw_chain_run_opts *o)
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
    w->total++;
    w->w_total += weight(p, o);
}

void chain_watch_plan_sweep(chain_watch *w, const gw_chain_params *tmpl, const gw_chain_run_opts *o,
                            const double *v, int nv, int n_lo, int n_hi)
{
    for (int i = 0; w && w->fn && i < nv; i++)
        for (int n = n_lo; n <= n_hi; n++) {
            gw_chain_params p = *tmpl;
            p.n = n;
            p.v_imp = v[i];
            chain_watch_plan(w, &p, o);
        }
}

/* The caller's report, under the lock: the part of the planned work done. */
static void report(chain_watch *w)
{
    double part = w->w_total > 0 ? (w->w_done + w->w_run) / w->w_total : 0;
    w->fn(w->ctx, w->done, w->total, fmin(fmax(part, 0), 1));
}

/* One collision under way: its weight and the part of it reported so far. */
typedef struct running {
    chain_watch *w;
    double weight, frac;
} running;

static void at_sample(void *ctx, double t, double t_expect, double t_max)
{
    (void)t_max;
    running *r = ctx;
    /* past its expected length a collision counts as whole until it ends (it
     * ends at 1.25 t_expect at N = 250, at most at t_max) */
    double f = t_expect > 0 ? fmin(fmax(t / t_expect, 0), 1) : 0;
    pthread_mutex_lock(&r->w->lock);
    r->w->w_run += r->weight * (f - r->frac);
    r->frac = f;
    report(r->w);
    pthread_mutex_unlock(&r->w->lock);
}

int chain_watch_collide(chain_watch *w, const gw_chain *c, const gw_chain_params *p, const gw_chain_run_opts *o,
                        gw_chain_result *r, gw_err *err)
{
    if (!w || !w->fn)
        return gw_chain_collide(c, o, r, err);
    running run = {.w = w, .weight = weight(p, o)};
    int rc = gw_chain_collide_progress(c, o, at_sample, &run, r, err);
    pthread_mutex_lock(&w->lock);
    w->w_run -= run.weight * run.frac;
    w->w_done += run.weight;
    w->done++;
    report(w);
    pthread_mutex_unlock(&w->lock);
    return rc;
}
