/*
 * gw_backend_cvode.c: CVODE backend. BDF with a band linear solver (analytic
 * banded Jacobian when the system has one; matrix-free GMRES for a system
 * flagged matrix_free, gw_solver.h) or Adams-Moulton with fixed-point
 * iteration. Roots are located by CVODE's own root finder; gw_solver_reset
 * re-initialises CVODE at the event so the multistep history restarts there.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cvode/cvode.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "gw_sundials.h"
#include "gw_locale.h"

typedef struct cv_impl {
    SUNContext ctx;
    void *mem;
    N_Vector y;
    N_Vector abstol;
    SUNMatrix A;
    SUNLinearSolver LS;
    SUNNonlinearSolver NLS;
    int *rootinfo;
    double t;
    gw_solver_stats base; /* counters accumulated over re-initialisations */
    int first_step;       /* a first step given, set at the first advance (gw_sun_init_step) */
    int jac_pending;      /* re-initialised: the Jacobians counted so far are carried at the next
                             advance (cv_advance says why) */
} cv_impl;

static void cv_raw_stats(const cv_impl *c, gw_solver_stats *st)
{
    long v = 0;
    memset(st, 0, sizeof *st);
    CVodeGetNumSteps(c->mem, &v);
    st->steps = v;
    CVodeGetNumRhsEvals(c->mem, &v);
    st->rhs_evals = v;
    if (c->LS) {
        CVodeGetNumJacEvals(c->mem, &v);
        st->jac_evals = v;
    }
    if (c->rootinfo) {
        CVodeGetNumGEvals(c->mem, &v);
        st->root_evals = v;
    }
}

/* CVodeReInit zeroes some counters: carry whatever dropped into the base.
 * The Jacobians' count drops later (cv_advance). */
static void cv_carry(cv_impl *c, const gw_solver_stats *before)
{
    gw_solver_stats after;
    cv_raw_stats(c, &after);
    if (after.steps < before->steps)
        c->base.steps += before->steps;
    if (after.rhs_evals < before->rhs_evals)
        c->base.rhs_evals += before->rhs_evals;
    if (after.root_evals < before->root_evals)
        c->base.root_evals += before->root_evals;
}

static void cv_destroy(gw_solver *s)
{
    cv_impl *c = s->impl;
    if (!c)
        return;
    if (c->mem)
        CVodeFree(&c->mem);
    if (c->LS)
        SUNLinSolFree(c->LS);
    if (c->NLS)
        SUNNonlinSolFree(c->NLS);
    if (c->A)
        SUNMatDestroy(c->A);
    if (c->abstol)
        N_VDestroy(c->abstol);
    if (c->y)
        N_VDestroy(c->y);
    if (c->ctx)
        SUNContext_Free(&c->ctx);
    free(c->rootinfo);
    free(c);
    s->impl = NULL;
}

/* CVodeGetReturnFlagName returns a malloc'ed string: copy it and free it. */
static void cv_flag_name(int flag, char *buf, size_t len)
{
    char *name = CVodeGetReturnFlagName(flag);
    gw_snprintf(buf, len, "%s", name ? name : "unknown flag");
    free(name);
}

/* A setup call's flag for a failed allocation (CVODE's own, or its linear
 * solver interface's): out of memory, exit 1 "out of memory", not a solver
 * failure. */
static int cv_nomem(int flag)
{
    return flag == CV_MEM_FAIL || flag == CVLS_MEM_FAIL;
}

#define CV_TRY(call, what)                                                           \
    do {                                                                             \
        int flag_ = (call);                                                          \
        if (flag_ < 0) {                                                             \
            char name_[64];                                                          \
            cv_flag_name(flag_, name_, sizeof name_);                                \
            int rc_ = cv_nomem(flag_) ? GW_ENOMEM : GW_ESOLVER;                      \
            gw_err_set(err, rc_, rc_ == GW_ENOMEM ? "cvode: %s: out of memory (%s)"  \
                                                  : "cvode: %s failed: %s",          \
                       what, name_);                                                 \
            cv_destroy(s);                                                           \
            return rc_;                                                              \
        }                                                                            \
    } while (0)

static int cv_create(gw_solver *s, double t0, const double *y0, gw_err *err)
{
    int method = s->p.method == GW_METHOD_DEFAULT ? GW_CVODE_BDF : s->p.method;
    if (method != GW_CVODE_BDF && method != GW_CVODE_ADAMS)
        return gw_err_set(err, GW_EUNSUPPORTED, "cvode: method '%s' not offered (use bdf or adams)",
                          gw_solver_method_name(s->p.method));
    cv_impl *c = calloc(1, sizeof *c);
    if (!c)
        return gw_err_set(err, GW_ENOMEM, "cvode: out of memory");
    s->impl = c;
    if (SUNContext_Create(NULL, &c->ctx) != 0) {
        cv_destroy(s);
        return gw_err_set(err, GW_ENOMEM, "cvode: out of memory (SUNContext_Create)"); /* its only failure */
    }
    c->y = gw_sun_vector(s->sys.dim, c->ctx);
    c->abstol = gw_sun_abstol(s, c->ctx);
    if (s->sys.nroots > 0)
        c->rootinfo = calloc((size_t)s->sys.nroots, sizeof *c->rootinfo);
    if (!c->y || !c->abstol || (s->sys.nroots > 0 && !c->rootinfo)) {
        cv_destroy(s);
        return gw_err_set(err, GW_ENOMEM, "cvode: out of memory");
    }
    memcpy(N_VGetArrayPointer(c->y), y0, (size_t)s->sys.dim * sizeof *y0);
    c->t = t0;
    c->mem = CVodeCreate(method == GW_CVODE_BDF ? CV_BDF : CV_ADAMS, c->ctx);
    if (!c->mem) {
        cv_destroy(s);
        return gw_err_set(err, GW_ENOMEM, "cvode: out of memory (CVodeCreate)"); /* its only failure */
    }
    CV_TRY(CVodeSetErrHandlerFn(c->mem, gw_sun_errh, s), "CVodeSetErrHandlerFn");
    /* Adams touches the vectors only through their ops: a right-hand side by
     * ranges runs queued, in one pass with the corrector's vector operations */
    CV_TRY(CVodeInit(c->mem,
                     method == GW_CVODE_ADAMS && s->sys.rhs_range ? gw_sun_rhs_queued : gw_sun_rhs,
                     t0, c->y),
           "CVodeInit");
    CV_TRY(CVodeSetUserData(c->mem, s), "CVodeSetUserData");
    /* error weights from gw_sun_ewt: the values CVodeSVtolerances gives with
     * the abstol vector, in one pass instead of four per step */
    if (gw_sun_abstol_positive(c->abstol)) {
        CV_TRY(CVodeWFtolerances(c->mem, gw_sun_ewt), "CVodeWFtolerances");
        CV_TRY(CVodeSetUserData(c->mem, s), "CVodeSetUserData");
    } else {
        CV_TRY(CVodeSVtolerances(c->mem, s->p.rtol, c->abstol), "CVodeSVtolerances");
    }
    CV_TRY(CVodeSetMaxNumSteps(c->mem, s->p.max_steps), "CVodeSetMaxNumSteps");
    if (s->p.dt > 0) {
        c->first_step = 1; /* CVodeSetInitStep at the first advance, which knows tout */
        /* a first step given is cut by at most 10 a failed error test, and CVODE
         * gives up after 7: chain --sheet pvc --sheet-law material --dt 1e-6 (a
         * value in the row's range) failed at t = 0 with h = 1e-12, where the
         * step CVODE estimates runs. 30 reach 1e-30 of the step given. */
        CV_TRY(CVodeSetMaxErrTestFails(c->mem, GW_SUN_GIVEN_STEP_ERR_FAILS), "CVodeSetMaxErrTestFails");
    }
    if (s->p.dt_max > 0)
        CV_TRY(CVodeSetMaxStep(c->mem, s->p.dt_max), "CVodeSetMaxStep");
    if (method == GW_CVODE_BDF) {
        if (gw_sun_band(s, c->y, c->ctx, &c->A, &c->LS) != GW_OK) {
            cv_destroy(s);
            return gw_err_set(err, GW_ENOMEM, "cvode: out of memory for the band matrix");
        }
        CV_TRY(CVodeSetLinearSolver(c->mem, c->LS, c->A), "CVodeSetLinearSolver");
        if (gw_sun_band_ordered(&s->sys))
            CV_TRY(CVodeSetJacFn(c->mem, gw_sun_jac_ordered), "CVodeSetJacFn");
        else if (s->p.use_jac && s->sys.jac && !s->sys.matrix_free)
            CV_TRY(CVodeSetJacFn(c->mem, gw_sun_jac), "CVodeSetJacFn");
    } else {
        c->NLS = gw_sun_fixed_point(c->y, c->ctx);
        if (!c->NLS) {
            cv_destroy(s);
            return gw_err_set(err, GW_ENOMEM, "cvode: out of memory for the fixed-point solver");
        }
        CV_TRY(CVodeSetNonlinearSolver(c->mem, c->NLS), "CVodeSetNonlinearSolver");
    }
    if (s->sys.nroots > 0)
        CV_TRY(CVodeRootInit(c->mem, s->sys.nroots, gw_sun_roots), "CVodeRootInit");
    return GW_OK;
}

static int cv_advance(gw_solver *s, double tout, double *t, double *y, int *roots)
{
    cv_impl *c = s->impl;
    double tret = c->t;
    if (fabs(tout - c->t) <= 1e-13 * fmax(fabs(tout), fabs(c->t))) {
        *t = c->t;
        gw_sun_copy_out(c->y, y, s->sys.dim);
        return GW_OK;
    }
    int flag = CV_SUCCESS;
    if (c->first_step) {
        c->first_step = 0;
        flag = CVodeSetInitStep(c->mem, gw_sun_init_step(s->p.dt, s->p.dt_max, c->t, tout));
    }
    /* CVodeReInit leaves the linear solver's counters; its interface zeroes
     * them when the next CVode call sets it up again. cv_carry's comparison
     * missed that, and the Jacobians of every segment but the last went
     * uncounted: chain --n 30 --sheet brass --sheet-law material reported 3
     * over 86 restarts, where CVODE forms one at each restart's first step */
    if (flag == CV_SUCCESS && c->jac_pending && c->LS) {
        long v = 0;
        CVodeGetNumJacEvals(c->mem, &v);
        c->base.jac_evals += v;
    }
    c->jac_pending = 0;
    if (flag == CV_SUCCESS)
        flag = CVode(c->mem, tout, c->y, &tret, CV_NORMAL);
    c->t = tret;
    *t = tret;
    gw_sun_copy_out(c->y, y, s->sys.dim);
    if (flag == CV_ROOT_RETURN) {
        CVodeGetRootInfo(c->mem, c->rootinfo);
        if (roots)
            memcpy(roots, c->rootinfo, (size_t)s->sys.nroots * sizeof *roots);
        return GW_ROOT;
    }
    if (flag >= 0)
        return GW_OK;
    char msg[sizeof s->errmsg], name[64];
    gw_snprintf(msg, sizeof msg, "%s", s->errmsg);
    cv_flag_name(flag, name, sizeof name);
    gw_solver_set_error(s, "cvode failed at t = %.9g s (%s): %s", tret, name,
                        msg[0] ? msg : "no message");
    return flag == CV_TOO_MUCH_WORK ? GW_ELIMIT : GW_ESOLVER;
}

static int cv_reset(gw_solver *s, double t, const double *y)
{
    cv_impl *c = s->impl;
    memcpy(N_VGetArrayPointer(c->y), y, (size_t)s->sys.dim * sizeof *y);
    c->t = t;
    gw_solver_stats before;
    cv_raw_stats(c, &before);
    int flag = CVodeReInit(c->mem, t, c->y);
    cv_carry(c, &before);
    c->jac_pending = 1;
    c->first_step = 0;
    /* dt is the run's initial step; a restart at an event estimates its own, as
     * one without dt does. Given again there, a dt far above the events' scale
     * (chain --n 6 --dt 1e-5, dt-max 6.6e-6) made CVODE look for roots that are
     * exactly 0 at the restart (a contact not yet reached by the wave) 0.1 dt
     * ahead, on an extrapolation: a contact opened at every step of 4e-12 s and
     * the run took minutes instead of 0.04 s. */
    if (flag >= 0 && s->p.dt > 0)
        flag = CVodeSetInitStep(c->mem, 0.0);
    if (flag >= 0 && s->p.dt > 0) /* CVODE's own limit again, with its own step */
        flag = CVodeSetMaxErrTestFails(c->mem, GW_SUN_OWN_STEP_ERR_FAILS);
    if (flag < 0) {
        char name[64];
        cv_flag_name(flag, name, sizeof name);
        gw_solver_set_error(s, "cvode: CVodeReInit at t = %.9g s failed: %s", t, name);
        return GW_ESOLVER;
    }
    return GW_OK;
}

static void cv_stats(const gw_solver *s, gw_solver_stats *st)
{
    const cv_impl *c = s->impl;
    cv_raw_stats(c, st);
    st->steps += c->base.steps;
    st->rhs_evals += c->base.rhs_evals;
    st->jac_evals += c->base.jac_evals;
    st->root_evals += c->base.root_evals;
}

static const gw_solver_type cvode_type = {"cvode", cv_create, cv_advance, cv_reset,
                                          cv_stats, cv_destroy, NULL};
const gw_solver_type *const gw_solver_cvode = &cvode_type;
