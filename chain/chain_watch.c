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
 */
#include <math.h>
#include <string.h>

#include "chain_collide_impl.h"
#include "chain_model.h"
#include "chain_watch.h"

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
 * its expected length, each costing O(n), per t_expect. The steps are rk4's
 * own; an adaptive method's follow the beads' contact time T_c (the plan's
 * dt_max is the stiffest contact's, the wall's too: by it softwall's 20 short
 * columns on the rigid steel wall weighed far more than their share of its
 * time, and its lines said 35 % done at 2 s of a 19 s study). 1 where the
 * plan refuses (the run then fails at once, with its message). */
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
    w->w_plan += weight(p, o);
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

/* The study's correction c of the expected lengths (1 before a collision ended). */
static double correction(const chain_watch *w)
{
    return w->c_den > 0 ? w->c_num / w->c_den : 1.0;
}

/* The caller's report, under the lock: the share of the expected work done. */
static void report(chain_watch *w)
{
    const double c = correction(w);
    double done = w->w_ended, total = w->w_ended + w->w_plan;
    for (const chain_watch_running *r = w->running; r; r = r->next) {
        done += r->weight * chain_watch_share(r->x, c * r->rho);
        total += r->weight;
    }
    /* held where a longer correction would take it back: a display whose
     * share fell would read as work undone */
    const double part = total > 0 ? fmin(fmax(done / total, 0), 1) : 0;
    w->shown = fmax(w->shown, part);
    w->fn(w->ctx, w->done, w->total, w->shown);
}

static void at_sample(void *ctx, double t, double t_expect, double t_max)
{
    (void)t_max;
    chain_watch_running *r = ctx;
    const double x = t_expect > 0 ? fmax(t / t_expect, 0) : 0;
    pthread_mutex_lock(&r->w->lock);
    r->x = x;
    report(r->w);
    pthread_mutex_unlock(&r->w->lock);
}

int chain_watch_collide(chain_watch *w, const gw_chain *c, const gw_chain_params *p, const gw_chain_run_opts *o,
                        gw_chain_result *r, gw_err *err)
{
    if (!w || !w->fn)
        return gw_chain_collide(c, o, r, err);
    chain_watch_running run = {.w = w, .weight = weight(p, o), .rho = chain_watch_tail(p->n)};
    pthread_mutex_lock(&w->lock); /* from planned to under way */
    w->w_plan = fmax(w->w_plan - run.weight, 0);
    run.next = w->running;
    w->running = &run;
    pthread_mutex_unlock(&w->lock);
    int rc = gw_chain_collide_progress(c, o, at_sample, &run, r, err);
    pthread_mutex_lock(&w->lock);
    for (chain_watch_running **q = &w->running; *q; q = &(*q)->next)
        if (*q == &run) {
            *q = run.next;
            break;
        }
    /* its length against the expected one: the study's correction */
    w->w_ended += run.weight;
    if (rc == GW_OK && run.x > 0) {
        w->c_num += run.weight * run.x / run.rho;
        w->c_den += run.weight;
    }
    w->done++;
    report(w);
    pthread_mutex_unlock(&w->lock);
    return rc;
}
