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

/* One collision under way (on its thread's stack, listed under the lock). */
typedef struct chain_watch_running {
    struct chain_watch *w;
    double weight, rho;  /* its weight, its expected t_end / t_expect (chain_watch_tail) */
    double x;            /* t / t_expect reached */
    struct chain_watch_running *next;
} chain_watch_running;

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
} chain_watch;

/* rho(N): a collision of N beads' expected length over its t_expect (the run
 * goes on until every contact is open and separating; chain_watch.c). */
double chain_watch_tail(int n);
/* The share of a collision's work done at x = t / t_expect, its end expected
 * at e t_expect (chain_watch.c's f): under 1 while it runs. */
double chain_watch_share(double x, double e);

/* A watch reporting to fn(ctx) (fn NULL: inactive, every call below a no-op
 * but chain_watch_collide's run). Free with chain_watch_destroy. */
void chain_watch_init(chain_watch *w, gw_chain_watch_fn fn, void *ctx);
void chain_watch_destroy(chain_watch *w);
/* One collision of column p under o to come: counted and weighed. w may be NULL. */
void chain_watch_plan(chain_watch *w, const gw_chain_params *p, const gw_chain_run_opts *o);
/* Every collision of a sweep (gw_chain_sweep_n's grid) to come. */
void chain_watch_plan_sweep(chain_watch *w, const gw_chain_params *tmpl, const gw_chain_run_opts *o,
                            const double *v, int nv, int n_lo, int n_hi);
/* gw_chain_collide of c under o (w NULL or inactive: that alone), reporting to
 * w from the calling thread; p the column's parameters as planned. */
int chain_watch_collide(chain_watch *w, const gw_chain *c, const gw_chain_params *p, const gw_chain_run_opts *o,
                        gw_chain_result *r, gw_err *err);
/* The sweep of gw_chain_sweep_n_progress reporting to w (may be NULL; its
 * collisions planned by the caller). */
int chain_sweep_watch(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv, int n_lo,
                      int n_hi, int jobs, gw_progress_fn progress, void *pctx, chain_watch *w,
                      gw_chain_result *res, gw_err *err);

#endif
