/*
 * chain_collide_impl.h (private to chain/, not installed): what the collision's
 * run (chain_collide.c) takes from its plan (chain_collide_plan.c).
 * Units: SI (s).
 */
#ifndef GW_CHAIN_COLLIDE_IMPL_H
#define GW_CHAIN_COLLIDE_IMPL_H

#include <math.h>

#include "gw_chain.h"

/* What a collision of p with o will run with (t_max, dt_out, the steps), and the
 * bounds on its steps, memory, samples and stored trace, checked before anything
 * is allocated, in that order: at the defaults the bound that trips at the fewest
 * beads is named (rk4: steps from 1.25e5 beads, memory from 7.9e6, samples from
 * 7e6; cvode: memory from 2.3e6, samples from 7e6, steps from 1.3e7). */
typedef struct collide_plan {
    double tc, tau1, t_max, dt_out, t_expect;
    gw_solver_params sp;
    const gw_solver_type *type;
} collide_plan;

/* The step the run of plan pl takes (gw_chain_result's run_dt): every
 * backend steps at most dt_max (gw_solver_create), rk4's steps end at the
 * samples (gw_backend_rk4.c); cvode's and arkode's first step (0: their own). */
static inline double chain_plan_step(const collide_plan *pl)
{
    const gw_solver_params *sp = &pl->sp;
    return pl->type == gw_solver_rk4 ? fmin(fmin(sp->dt, sp->dt_max), pl->dt_out > 0 ? pl->dt_out : INFINITY)
                                     : sp->dt > 0 ? fmin(sp->dt, sp->dt_max) : sp->dt;
}

/* The plan of a collision of p0 with o in pl; GW_EINVAL naming the bound
 * that trips (pl is then partly filled and not to be used). */
int chain_collide_plan_make(const gw_chain_params *p0, const gw_chain_run_opts *o, collide_plan *pl, gw_err *err);
/* The same bounds but those of a run going on to t_max (the explicit t-max's
 * and a column held by gravity's): a run whose t_max is cut shorter later
 * (the drop's first collision) meets these whatever its cut. */
int chain_collide_plan_early(const gw_chain_params *p0, const gw_chain_run_opts *o, gw_err *err);
/* The t_max above which the plan refuses a column held on the wall by gravity
 * (chain_held_check: its samples times beads above the bound), INFINITY when
 * gravity does not hold it; and that refusal at o's t_max (GW_EINVAL, or
 * GW_OK when it passes). The drop stops at the first: its first collision's
 * t_max is at least the end of bead 1's first contact. */
double chain_collide_held_t(const gw_chain_params *p0, const gw_chain_run_opts *o);
int chain_collide_held_refuse(const gw_chain_params *p0, const gw_chain_run_opts *o, gw_err *err);

#endif
