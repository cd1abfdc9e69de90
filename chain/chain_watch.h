/*
 * chain_watch.h: a study's progress within its collisions (chain_watch.c),
 * behind gw_chain_watch_fn (gw_chain_study.h). A study plans its collisions
 * first (chain_watch_plan*: each weighed by its expected steps and samples
 * times its beads), then runs each
 * through chain_watch_collide, which reports at every output sample of the
 * collision and at its end (the share of the work, chain_watch.c).
 * Internal to the library; no units but the weights' (bead-steps).
 */
#ifndef CHAIN_WATCH_H
#define CHAIN_WATCH_H

#include <pthread.h>

#include "gw_chain.h"
#include "gw_chain_study.h"
#include "gw_pool_impl.h"

/* One collision under way (on its thread's stack, listed under the lock). */
typedef struct chain_watch_running {
    struct chain_watch *w;
    double weight, rho;  /* its weight, its expected t_end / t_expect (chain_watch_tail) */
    double x;            /* t / t_expect reached */
    int group;           /* the group of collisions it was planned in (-1: not planned) */
    struct chain_watch_running *next;
} chain_watch_running;

/* One collision planned: its weight, the group of collisions it runs in (a
 * sweep on its threads, or a run of its own on the study's thread). */
typedef struct chain_watch_task {
    double weight;
    int group, begun;
} chain_watch_task;

typedef struct chain_watch {
    gw_chain_watch_fn fn; /* NULL: the watch does nothing (the plain runs) */
    void *ctx;
    pthread_mutex_t lock; /* one report at a time, whatever thread runs a collision */
    long done, total;     /* collisions ended, planned */
    double w_ended;       /* the weight of the collisions ended */
    double w_plan;        /* of those not begun */
    double c_num, c_den;  /* the correction of the expected lengths learnt: sum w r / rho, sum w */
    double shown;         /* the largest share reported */
    chain_watch_running *running;
    int nrun;             /* collisions under way */
    int cpus;             /* the CPUs online (chain_watch_init): threads beyond them share them */
    /* the schedule: the collisions planned in the order they run, each group's threads */
    chain_watch_task *task;
    long ntask, task_cap, first; /* first: the first not begun */
    int *threads;
    int ngroup, group_cap;
    double *slot;         /* scratch: when each thread of a group comes free (a heap) */
    int slot_cap;
    int unplanned;        /* the schedule is not known (out of memory): the share of the work instead */
    gw_pool_clock clock;  /* the time elapsed, in work per busy thread (gw_pool_impl.h) */
    /* the time left scheduled last (time_left walks every collision to come,
     * and a report comes at every sample of a collision): between schedules
     * it runs down with the time elapsed; scheduled again when a collision
     * begins or ends, or a thousandth of the study's work after the last */
    double left_at, elapsed_at, done_at;
    int left_known;
} chain_watch;

/* A collision's weight (its beads times its steps and samples over its
 * expected length, chain_watch.c): what a study plans and `granwave sweep`
 * weighs a chain case by (gw_chain_sweep_weigh); 1 where the plan refuses. */
double chain_watch_weight(const gw_chain_params *p, const gw_chain_run_opts *o);
/* rho(N): a collision of N beads' expected length over its t_expect (the run
 * goes on until every contact is open and separating; chain_watch.c). */
double chain_watch_tail(int n);
/* The share of a collision's work done at x = t / t_expect, its end expected
 * at e t_expect (chain_watch.c's f): under 1 while it runs. */
double chain_watch_share(double x, double e);

/* The part reported (chain_watch.c): the study's time elapsed over its
 * whole time, each measured in work per thread at work: the time elapsed
 * adds the work done over the collisions under way, the time left schedules
 * the work left as the pool hands it out (each collision to the first thread
 * free, in the planned order, group after group). On one thread, the share
 * of the work done. */
/* A watch reporting to fn(ctx) (fn NULL: inactive, every call below a no-op
 * but chain_watch_collide's run). Free with chain_watch_destroy. */
void chain_watch_init(chain_watch *w, gw_chain_watch_fn fn, void *ctx);
void chain_watch_destroy(chain_watch *w);
/* One collision of column p under o to come, run on the calling thread:
 * counted and weighed. w may be NULL. */
void chain_watch_plan(chain_watch *w, const gw_chain_params *p, const gw_chain_run_opts *o);
/* Every collision of a sweep (gw_chain_sweep_n's grid) to come, run on the
 * pool's threads for jobs (gw_cases_run's count). */
void chain_watch_plan_sweep(chain_watch *w, const gw_chain_params *tmpl, const gw_chain_run_opts *o,
                            const double *v, int nv, int n_lo, int n_hi, int jobs);
/* The steps under the two above, by weight (a test drives them): a group of
 * collisions to come on threads threads (>= 1), then each of its collisions. */
void chain_watch_group(chain_watch *w, int threads);
void chain_watch_plan_one(chain_watch *w, double weight);
/* A collision of that weight and rho begun (run on the caller's stack until
 * its end), reaching x = t / t_expect, ended (ok: it ran to its end, and its
 * length teaches the correction); each of the last two reports. */
void chain_watch_begin(chain_watch *w, chain_watch_running *run, double weight, double rho);
void chain_watch_at(chain_watch_running *run, double x);
void chain_watch_end(chain_watch_running *run, int ok);
/* gw_chain_collide of c under o (w NULL or inactive: that alone), reporting to
 * w from the calling thread; p the column's parameters as planned. */
int chain_watch_collide(chain_watch *w, const gw_chain *c, const gw_chain_params *p, const gw_chain_run_opts *o,
                        gw_chain_result *r, gw_err *err);
/* chain_sweep_watch's checks alone (nothing run; res zeroed once the grid's
 * shape passed): a study that runs columns of its own before the sweep
 * (wavespeed's front columns) refuses what the sweep would first. */
int chain_sweep_check(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv, int n_lo,
                      int n_hi, gw_chain_result *res, gw_err *err);
/* The sweep of gw_chain_sweep_n_progress reporting to w (may be NULL; its
 * collisions planned by the caller). */
int chain_sweep_watch(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv, int n_lo,
                      int n_hi, int jobs, gw_progress_fn progress, void *pctx, chain_watch *w,
                      gw_chain_result *res, gw_err *err);

#endif
