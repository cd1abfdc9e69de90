/*
 * gw_solver.c: backend-independent part of the solver layer (lookup, argument
 * checks, dispatch, error text). The tolerance range [GW_TOL_MIN, GW_TOL_MAX]
 * (gw_common.h) is checked here, for every backend and every command.
 */
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "gw_param.h"
#include "gw_locale.h"
#include "gw_number_impl.h"
#include "gw_solver_impl.h"

gw_solver_params gw_solver_params_default(void)
{
    gw_solver_params p;
    p.rtol = 1e-10;
    p.atol = 1e-10;
    p.dt = 0.0;
    p.dt_max = 0.0;
    p.max_steps = 10000000L;
    p.method = GW_METHOD_DEFAULT;
    p.use_jac = 1;
    return p;
}

const gw_solver_type *gw_solver_type_find(const char *name)
{
    const gw_solver_type *const all[] = {gw_solver_cvode, gw_solver_arkode,
                                         gw_solver_rk4, gw_solver_verlet};
    if (!name)
        return NULL;
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++)
        if (strcmp(all[i]->name, name) == 0)
            return all[i];
    return NULL;
}

const char *gw_solver_type_name(const gw_solver_type *type)
{
    return type ? type->name : "(none)";
}

static const struct {
    const char *name;
    int method;
} method_names[] = {{"default", GW_METHOD_DEFAULT}, {"bdf", GW_CVODE_BDF},
                    {"adams", GW_CVODE_ADAMS},       {"erk", GW_ARKODE_ERK},
                    {"dirk", GW_ARKODE_DIRK},        {"imex", GW_ARKODE_IMEX}};

int gw_solver_method_find(const char *name)
{
    for (size_t i = 0; i < sizeof method_names / sizeof method_names[0]; i++)
        if (name && strcmp(method_names[i].name, name) == 0)
            return method_names[i].method;
    return -1;
}

const char *gw_solver_method_name(int method)
{
    for (size_t i = 0; i < sizeof method_names / sizeof method_names[0]; i++)
        if (method_names[i].method == method)
            return method_names[i].name;
    return "unknown";
}

const char *gw_solver_method_used(const gw_solver_type *type, int method)
{
    if (type == gw_solver_rk4 || type == gw_solver_verlet)
        return "none";
    /* no backend, or a variant the backend has not: what would run is not
     * known (NULL and 0 said "bdf", cvode with erk "erk") */
    const int cv = type == gw_solver_cvode, ark = type == gw_solver_arkode;
    if (method == GW_METHOD_DEFAULT && (cv || ark))
        return gw_solver_method_name(cv ? GW_CVODE_BDF : GW_ARKODE_ERK);
    if ((cv && (method == GW_CVODE_BDF || method == GW_CVODE_ADAMS)) ||
        (ark && (method == GW_ARKODE_ERK || method == GW_ARKODE_DIRK || method == GW_ARKODE_IMEX)))
        return gw_solver_method_name(method);
    return "unknown";
}

int gw_solver_tolerances_check(double rtol, double atol, const char *rname, const char *aname,
                               gw_err *err)
{
    char xs[32], ls[32], hs[32];
    rname = rname ? rname : "rtol"; /* NULL names: "(null): ..." before session 34 */
    aname = aname ? aname : "atol";
    gw_num_bound(ls, sizeof ls, GW_TOL_MIN, 0);
    gw_num_bound(hs, sizeof hs, GW_TOL_MAX, 1);
    if (!(rtol >= GW_TOL_MIN && rtol <= GW_TOL_MAX)) /* also refuses NaN */
        return gw_err_set(err, GW_EINVAL, "%s: %s is outside [%s, %s]", rname, gw_num_text(xs, sizeof xs, rtol),
                          ls, hs);
    if (!(atol >= GW_TOL_MIN && atol <= GW_TOL_MAX))
        return gw_err_set(err, GW_EINVAL, "%s: %s is outside [%s, %s]", aname, gw_num_text(xs, sizeof xs, atol),
                          ls, hs);
    return GW_OK;
}

int gw_solver_tolerances_unused_check(const gw_solver_type *type, const struct gw_param *t, const void *obj,
                                      gw_err *err)
{
    /* a NULL table or object has no rows to check: it was GW_OK, as if the
     * tolerances were not given; every backend refuses it now */
    if (!type || !t || !obj)
        return gw_err_set(err, GW_EINVAL, "gw_solver_tolerances_unused_check: %s is NULL",
                          !type ? "type" : !t ? "t" : "obj");
    if (type != gw_solver_rk4 && type != gw_solver_verlet)
        return GW_OK;
    static const char *const rows[2] = {"rtol", "atol"};
    for (int k = 0; k < 2; k++) {
        const gw_param *p = gw_param_find(t, rows[k]);
        if (!p || p->type != GW_PARAM_DOUBLE)
            continue;
        if (gw_param_given(p, obj))
            return gw_err_set(err, GW_EINVAL, "%s: has no effect with the fixed-step %s solver (the tolerances "
                              "are cvode's and arkode's)", p->name, type->name);
    }
    return GW_OK;
}

void gw_solver_set_error(gw_solver *s, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    gw_vsnprintf(s->errmsg, sizeof s->errmsg, fmt, ap);
    va_end(ap);
}

int gw_solver_create(const gw_solver_type *type, const gw_system *sys,
                     const gw_solver_params *p, double t0, const double *y0,
                     gw_solver **out, gw_err *err)
{
    if (!out)
        return gw_err_set(err, GW_EINVAL, "gw_solver_create: out is NULL");
    *out = NULL;
    if (!type)
        return gw_err_set(err, GW_EINVAL, "solver: unknown backend");
    if (!p) /* (its tolerances were read: SIGSEGV) */
        return gw_err_set(err, GW_EINVAL, "gw_solver_create: p is NULL");
    if (!sys || !sys->rhs || sys->dim <= 0 || !y0)
        return gw_err_set(err, GW_EINVAL, "solver: system has no right-hand side or dimension");
    if (sys->nroots < 0 || (sys->nroots > 0 && !sys->roots))
        return gw_err_set(err, GW_EINVAL, "solver: root count without root function");
    if (sys->lead0 < 0 || sys->nlead < 0 || sys->nledger < 0 || sys->lead0 > sys->dim - sys->nlead ||
        sys->nledger > sys->dim)
        return gw_err_set(err, GW_EINVAL, "solver: band order (lead0 %ld, nlead %ld, nledger %ld) outside the %ld states",
                          sys->lead0, sys->nlead, sys->nledger, sys->dim);
    if (sys->nlead > 0 && sys->jac)
        return gw_err_set(err, GW_EINVAL, "solver: a band order with leading states needs jac NULL (difference "
                          "quotients in that order)");
    int rc = gw_solver_tolerances_check(p->rtol, p->atol, "solver: rtol", "solver: atol", err);
    if (rc != GW_OK)
        return rc;
    if (!(p->dt >= 0) || !isfinite(p->dt))
        return gw_err_set(err, GW_EINVAL, "solver: dt must be >= 0, got %g", p->dt);
    if (!(p->dt_max >= 0) || !isfinite(p->dt_max))
        return gw_err_set(err, GW_EINVAL, "solver: dt_max must be >= 0, got %g", p->dt_max);
    if (p->max_steps <= 0)
        return gw_err_set(err, GW_EINVAL, "solver: max_steps must be positive");
    if (p->use_jac != 0 && p->use_jac != 1) /* -1, 2 or INT_MIN ran as 1 */
        return gw_err_set(err, GW_EINVAL, "solver: use_jac must be 0 or 1, got %d", p->use_jac);
    for (long i = 0; i < sys->dim; i++)
        if (!isfinite(y0[i]))
            return gw_err_set(err, GW_EINVAL, "solver: initial state component %ld is not finite", i);
    /* a NaN or infinite start ran: rk4 "reached" any time with GW_OK and the
     * state untouched, cvode and arkode failed at t = nan */
    if (!isfinite(t0))
        return gw_err_set(err, GW_EINVAL, "solver: t0 = %g is not a finite time", t0);
    /* a component's scale is its absolute tolerance's factor: 0 gave cvode an
     * absolute tolerance of 0 (a failure at t = 0), NaN or a negative one ran
     * on rk4 unread */
    for (long i = 0; sys->scale && i < sys->dim; i++)
        if (!(sys->scale[i] > 0) || !isfinite(sys->scale[i]))
            return gw_err_set(err, GW_EINVAL, "solver: scale[%ld] = %g must be finite and > 0 (the component's "
                              "typical magnitude)", i, sys->scale[i]);

    gw_solver *s = calloc(1, sizeof *s);
    if (!s)
        return gw_err_set(err, GW_ENOMEM, "solver: out of memory");
    s->type = type;
    s->sys = *sys;
    s->p = *p;
    /* dt_max is the largest step for every backend: a fixed step above it runs at
     * dt_max (a chain's plan caps its step at a quarter of the shortest contact
     * so that no step holds a whole contact; rk4 and verlet ran at dt regardless) */
    if ((type == gw_solver_rk4 || type == gw_solver_verlet) && p->dt_max > 0 && p->dt_max < p->dt)
        s->p.dt = p->dt_max;
    rc = type->create(s, t0, y0, err);
    if (rc != GW_OK) {
        free(s);
        return rc;
    }
    *out = s;
    return GW_OK;
}

int gw_solver_interrupted(gw_solver *s, double t)
{
    if (!gw_interrupt_pending())
        return 0;
    gw_solver_set_error(s, "%s: interrupted (SIGINT) at t = %.9g s", s->type->name, t);
    return GW_ECANCELED;
}

int gw_solver_advance(gw_solver *s, double tout, double *t, double *y, int *rootsfound)
{
    if (!s || !t || !y)
        return GW_EINVAL;
    s->errmsg[0] = '\0';
    if (!isfinite(tout)) { /* rk4 returned GW_OK at its own time (*t != tout), cvode a convergence failure */
        gw_solver_set_error(s, "%s: tout = %g is not a finite time", s->type->name, tout);
        return GW_EINVAL;
    }
    int rc = s->type->advance(s, tout, t, y, rootsfound);
    if (rc < 0 && rc != GW_ECANCELED && gw_solver_interrupted(s, *t)) /* CVODE or ARKode: their rhs failed */
        rc = GW_ECANCELED;
    return rc;
}

int gw_solver_reset(gw_solver *s, double t, const double *y)
{
    if (!s || !y)
        return GW_EINVAL;
    /* a restart at a time that is not finite: the next advance failed far
     * from here (or, with rk4, "reached" its target with GW_OK) */
    if (!isfinite(t)) {
        gw_solver_set_error(s, "%s: reset at t = %g, not a finite time", s->type->name, t);
        return GW_EINVAL;
    }
    s->restarts++;
    return s->type->reset(s, t, y);
}

int gw_solver_set_peek(gw_solver *s, double tpeek)
{
    if (!s || (s->type != gw_solver_cvode && s->type != gw_solver_arkode && s->type != gw_solver_rk4 &&
               s->type != gw_solver_verlet) || !(tpeek > 0) || !isfinite(tpeek)) {
        if (s)
            s->peek = 0;
        return 0;
    }
    s->peek = tpeek;
    return 1;
}

const double *gw_solver_rates(const gw_solver *s)
{
    return s && s->type->rates ? s->type->rates(s) : NULL;
}

static int drive_failed(gw_solver *s, const gw_drive *d, int rc, gw_err *err)
{
    return d->what ? gw_err_set(err, rc, "%s: %s", d->what, gw_solver_error(s))
                   : gw_err_set(err, rc, "%s", gw_solver_error(s));
}

int gw_solver_drive(gw_solver *s, gw_drive *d, double *t, double *y, int *roots, gw_err *err)
{
    if (!s || !d || !t || !y)
        return gw_err_set(err, GW_EINVAL, "gw_solver_drive: %s is NULL", !s ? "s" : !d ? "d" : !t ? "t" : "y");
    /* a NaN t_end returned GW_OK having run nothing, a NaN dt_out ran as 0
     * (no output before t_end): neither is a choice the drive offers */
    if (isnan(d->t_end) || isinf(d->t_end))
        return gw_err_set(err, GW_EINVAL, "gw_solver_drive: t_end = %g s is not a finite time", d->t_end);
    if (isnan(d->dt_out) || isinf(d->dt_out) || d->dt_out < 0)
        return gw_err_set(err, GW_EINVAL, "gw_solver_drive: dt_out = %g s must be finite and >= 0 (0: t_end only)",
                          d->dt_out);
    if (d->k_out < 1)
        d->k_out = 1;
    while (*t < d->t_end) {
        /* output times as multiples of dt_out (no sum of steps drifting) */
        double tnext = d->dt_out > 0 ? fmin((double)d->k_out * d->dt_out, d->t_end) : d->t_end;
        int rc = gw_solver_advance(s, tnext, t, y, roots);
        if (rc < 0)
            return drive_failed(s, d, rc, err);
        if (rc == GW_SOLVER_PEEK) /* (gw_solver_set_peek) no output, the solver as it is */
            return rc;
        int act;
        if (rc == GW_ROOT) {
            act = d->on_root ? d->on_root(d->ctx, *t, y, roots, err) : GW_DRIVE_RESET;
        } else {
            /* tnext was reached: the backends may return within rounding of it
             * (a target within 1e-13 of the solver's time is not integrated to) */
            *t = tnext;
            d->k_out++;
            act = d->on_output ? d->on_output(d->ctx, *t, y, err) : GW_DRIVE_ON;
        }
        if (act == GW_DRIVE_RESET) {
            if ((rc = gw_solver_reset(s, *t, y)) != GW_OK)
                return drive_failed(s, d, rc, err);
            act = GW_DRIVE_ON;
        }
        if (act < 0)
            return act;
        if (act == GW_DRIVE_STOP)
            return GW_OK;
        if (act == GW_DRIVE_YIELD)
            return GW_ROOT;
        act = d->after ? d->after(d->ctx, *t, y, err) : GW_DRIVE_ON;
        if (act < 0)
            return act;
        if (act == GW_DRIVE_STOP)
            return GW_OK;
    }
    return GW_OK;
}

void gw_solver_get_stats(const gw_solver *s, gw_solver_stats *st)
{
    if (!st)
        return;
    if (!s) { /* no solver: no steps */
        memset(st, 0, sizeof *st);
        return;
    }
    memset(st, 0, sizeof *st);
    s->type->stats(s, st);
    st->restarts = s->restarts;
}

const char *gw_solver_error(const gw_solver *s)
{
    if (!s)
        return "no solver";
    return s->errmsg;
}

const gw_solver_type *gw_solver_get_type(const gw_solver *s)
{
    if (!s)
        return NULL;
    return s->type;
}

void gw_solver_free(gw_solver *s)
{
    if (!s)
        return;
    if (s->type && s->type->destroy)
        s->type->destroy(s);
    free(s);
}
