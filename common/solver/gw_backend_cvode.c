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
    gw_sun_peek pk;       /* a peek (gw_solver_set_peek): gw_sun_advance_peek's state */
    double h0_given;      /* the first step given at this start (0: CVODE's estimate) */
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
    gw_sun_peek_free(&c->pk);
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

static const gw_sun_stepper cv_stepper;

/* CVODE's root function: the system's, and after each step a peek asked for
 * during the call read in the step that holds it (gw_sun_peek_catch). */
static int cv_roots(realtype t, N_Vector y, realtype *g, void *ud)
{
    gw_solver *s = ud;
    cv_impl *c = s->impl;
    gw_sun_peek_catch(s, &c->pk, t, y);
    return gw_sun_roots(t, y, g, ud);
}

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
    c->pk.st = &cv_stepper;
    c->pk.y = c->y;
    c->pk.t = &c->t;
    gw_sun_peek_start(&c->pk, t0);
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
        CV_TRY(CVodeRootInit(c->mem, s->sys.nroots, cv_roots), "CVodeRootInit");
    return GW_OK;
}

/* A failed CVode call: the solver's message, GW_ELIMIT or GW_ESOLVER
 * (gw_sun_failed). */
static int cv_failed(gw_solver *s, int flag, double tret)
{
    char name[64];
    cv_flag_name(flag, name, sizeof name);
    return gw_sun_failed(s, "cvode", name, flag == CV_TOO_MUCH_WORK, tret);
}

/* The first advance after the set-up: the step given, which knows tout. */
static int cv_first_step(gw_solver *s, cv_impl *c, double tout)
{
    if (!c->first_step)
        return CV_SUCCESS;
    c->first_step = 0;
    c->h0_given = gw_sun_init_step(s->p.dt, s->p.dt_max, c->t, tout);
    return CVodeSetInitStep(c->mem, c->h0_given);
}

/* CVodeReInit leaves the linear solver's counters; its interface zeroes them
 * when the next CVode call sets it up again. cv_carry's comparison missed
 * that, and the Jacobians of every segment but the last went uncounted: chain
 * --n 30 --sheet brass --sheet-law material reported 3 over 86 restarts, where
 * CVODE forms one at each restart's first step. Before that call. */
static void cv_jac_carry(cv_impl *c)
{
    if (c->jac_pending && c->LS) {
        long v = 0;
        CVodeGetNumJacEvals(c->mem, &v);
        c->base.jac_evals += v;
    }
    c->jac_pending = 0;
}

/* The stepper's calls for gw_sun_advance_peek. */
static int cv_where(gw_solver *s, long *nst, double *tn, double *hnext, double *hlast)
{
    cv_impl *c = s->impl;
    CVodeGetNumSteps(c->mem, nst);
    CVodeGetCurrentTime(c->mem, tn);
    CVodeGetCurrentStep(c->mem, hnext);
    CVodeGetLastStep(c->mem, hlast);
    return *nst > 0;
}

static int cv_dky(gw_solver *s, double t, int k, N_Vector v)
{
    cv_impl *c = s->impl;
    return CVodeGetDky(c->mem, t, k, v);
}

static int cv_prepare(gw_solver *s, double tout)
{
    cv_impl *c = s->impl;
    int flag = cv_first_step(s, c, tout);
    if (flag >= 0)
        cv_jac_carry(c);
    return flag;
}

static int cv_evolve(gw_solver *s, double tout, double *tret, int one_step)
{
    cv_impl *c = s->impl;
    int flag = CVode(c->mem, tout, c->y, tret, one_step ? CV_ONE_STEP : CV_NORMAL);
    return flag < 0 ? flag : flag == CV_ROOT_RETURN;
}

static int cv_root_info(gw_solver *s, int *roots)
{
    cv_impl *c = s->impl;
    CVodeGetRootInfo(c->mem, c->rootinfo);
    if (roots)
        memcpy(roots, c->rootinfo, (size_t)s->sys.nroots * sizeof *roots);
    return GW_ROOT;
}

/* the step CVODE tries next (CVodeGetCurrentStep: failed tests only shorten
 * it) is its hprime after a return at tout or in CV_ONE_STEP mode; after a
 * root return it is the step last taken, and the next may grow by CVODE's
 * largest factor. No getter gives hprime there (CVodeGetCurrentStep,
 * CVodeGetLastStep and CVodeGetIntegratorStats give the step taken), so this
 * relies on CVODE 6.4's growth limits (ETAMX1 1e4 on a start's first step,
 * ETAMX2 and ETAMX3 10 after; taken as 1e4 over the first 10 steps): a larger
 * growth would take a step that reaches tout in CV_ONE_STEP mode, whose root
 * search then passes tout (the run would differ from the one without the peek
 * in a root's bracket, not fail). */
static double cv_grow(gw_solver *s, long nst)
{
    (void)s;
    return nst <= 10 ? 1e4 : 10;
}

/* A restart's first step estimated is at most a tenth of the way to tout
 * (cvHin's bound): its first call is one step unless a first step given may
 * reach tout. */
static int cv_first_normal(gw_solver *s, double tout)
{
    cv_impl *c = s->impl;
    return c->h0_given >= 0.5 * (tout - c->t) || tout - c->t <= 1e-9 * fabs(tout);
}

static const gw_sun_stepper cv_stepper = {"cvode", "CV_TOO_MUCH_WORK", cv_where, cv_dky, cv_prepare, cv_evolve,
                                          cv_failed, cv_root_info, cv_grow, cv_first_normal, NULL};

/* An advance towards tout with a peek p before it (gw_solver_set_peek),
 * gw_sun_advance_peek: the CVode calls an advance to tout makes without it,
 * CV_NORMAL towards tout, taken one step at a time (CV_ONE_STEP) while the
 * next step cannot reach tout, so that the interpolation at p is in the step
 * that passed it. A step that may reach tout is taken in CV_NORMAL mode, whose
 * root search ends at tout (CV_ONE_STEP's at the step's end: a root there was
 * located on another bracket). The return that call makes (tout reached, a
 * root after p) is held back and given at the next call. Stopping at p
 * instead (CVode towards p) changed the run: another first step after each
 * restart (CVODE's estimate knows tout), another root bracket, and the
 * restart the layer makes at an output where a contact changed. arkode reads
 * the same way (ark_advance), with ARKode's limits. A system without roots
 * is taken one step at a time up to the step that passes p (no root function
 * keeps the ends of a CV_NORMAL call's steps; the steps and the output at tout
 * are the same in both modes): given a first step reaching tout, its first
 * call went towards tout and a peek was a cubic over its steps, off by 2 on
 * test_solver_peek_far's oscillator. */
static int cv_advance(gw_solver *s, double tout, double *t, double *y, int *roots)
{
    cv_impl *c = s->impl;
    if (s->peek > c->t && s->peek < tout)
        return gw_sun_advance_peek(s, &c->pk, tout, t, y, roots);
    if ((c->pk.pend == 1 && c->pk.pend_tout == tout) || (c->pk.pend == 2 && c->pk.pend_t <= tout))
        return gw_sun_peek_pending(s, &c->pk, t, y, roots);
    c->pk.pend = 0;
    double tret = c->t;
    if (fabs(tout - c->t) <= 1e-13 * fmax(fabs(tout), fabs(c->t))) {
        *t = c->t;
        gw_sun_copy_out(c->y, y, s->sys.dim);
        return GW_OK;
    }
    int flag = cv_first_step(s, c, tout);
    if (flag == CV_SUCCESS)
        cv_jac_carry(c);
    if (flag == CV_SUCCESS)
        flag = CVode(c->mem, tout, c->y, &tret, CV_NORMAL);
    c->pk.tlast = tret;
    c->t = tret;
    *t = tret;
    gw_sun_copy_out(c->y, y, s->sys.dim);
    c->pk.root_last = flag == CV_ROOT_RETURN;
    if (flag == CV_ROOT_RETURN) {
        CVodeGetRootInfo(c->mem, c->rootinfo);
        if (roots)
            memcpy(roots, c->rootinfo, (size_t)s->sys.nroots * sizeof *roots);
        return GW_ROOT;
    }
    if (flag >= 0)
        return GW_OK;
    return cv_failed(s, flag, tret);
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
    c->h0_given = 0;
    gw_sun_peek_start(&c->pk, t);
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
