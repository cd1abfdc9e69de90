/*
 * gw_solver_impl.h: what a backend implements (private to common/). Adding a
 * backend is one file defining a gw_solver_type table.
 */
#ifndef GW_SOLVER_IMPL_H
#define GW_SOLVER_IMPL_H

#include "gw_solver.h"

struct gw_solver_type {
    const char *name;
    /* Set up backend state in s->impl from s->sys, s->p, (t0, y0). */
    int (*create)(gw_solver *s, double t0, const double *y0, gw_err *err);
    int (*advance)(gw_solver *s, double tout, double *t, double *y, int *roots);
    int (*reset)(gw_solver *s, double t, const double *y);
    void (*stats)(const gw_solver *s, gw_solver_stats *st);
    void (*destroy)(gw_solver *s);
    /* The rates the next step starts from (gw_solver_rates), or NULL: a
     * backend that keeps none between steps leaves it unset. */
    const double *(*rates)(const gw_solver *s);
};

struct gw_solver {
    const gw_solver_type *type;
    gw_system sys;
    gw_solver_params p;
    long restarts;
    double peek; /* gw_solver_set_peek's time, 0: none */
    char errmsg[1024];
    void *impl;
};

/* Sign of x (-1, 0, 1), and whether root function k has left its reference
 * sign (crossed or hit zero; sign 0 = inactive until it moves away from zero):
 * the root convention of the fixed-step backends. */
static inline int gw_sgn(double x)
{
    return (x > 0) - (x < 0);
}

static inline int gw_root_crossed(const signed char *sign, const double *g, int k)
{
    return sign[k] != 0 && gw_sgn(g[k]) != sign[k];
}

/* Record an error message on the solver (printf-style). */
void gw_solver_set_error(gw_solver *s, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* GW_ECANCELED with "BACKEND: interrupted (SIGINT) at t = T s" on the solver
 * when SIGINT came under gw_interrupt_begin (gw_common.h), else 0: checked
 * before each step of the fixed-step backends and after a SUNDIALS failure
 * (their rhs, gw_sun_rhs, fails once the request is pending). */
int gw_solver_interrupted(gw_solver *s, double t);

#endif
