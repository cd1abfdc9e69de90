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
};

struct gw_solver {
    const gw_solver_type *type;
    gw_system sys;
    gw_solver_params p;
    long restarts;
    char errmsg[1024];
    void *impl;
};

/* Record an error message on the solver (printf-style). */
void gw_solver_set_error(gw_solver *s, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

#endif
