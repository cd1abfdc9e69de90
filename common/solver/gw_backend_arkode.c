/*
 * gw_backend_arkode.c: ARKode backend. Variants:
 *   erk  - explicit Cash-Karp 5(4)6 (default; no linear algebra), through
 *          ERKStep, ARKode's explicit-only stepper: each stage is one fused
 *          linear combination y_n + h sum a_ij f_j and a step makes 6 right-hand
 *          side evaluations, where ARKStep with an empty implicit table forms
 *          each stage in two passes and makes 7 (measured 25 % less CPU per
 *          step on a 1e4-bead column, same accuracy). Higher-order
 *          tables (Verner 8(5)6) take steps so long that ARKode's degree-5
 *          Hermite dense output, which places roots and outputs, limits the
 *          accuracy: measured on a 7-bead column at rtol 1e-12, energy error
 *          1.9e-7 with Verner against 5.8e-10 with Cash-Karp.
 *   dirk - implicit ARK5(4)8L[2]SA DIRK table with a band linear solver and the
 *          system's analytic banded Jacobian when it has one,
 *   imex - ARK5(4)8L[2]SA additive pair: rhs_ex explicit, rhs_im implicit (band
 *          solver, finite-difference Jacobian of rhs_im).
 *   A system flagged matrix_free (gw_solver.h) gets matrix-free GMRES instead
 *   of the band solver in dirk and imex.
 * Roots by ARKode's root finder; gw_solver_reset calls ERKStepReset or
 * ARKStepReset.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>

#include "gw_sundials.h"
#include "gw_locale.h"

typedef struct ark_impl {
    SUNContext ctx;
    void *mem;
    N_Vector y, abstol;
    SUNMatrix A;
    SUNLinearSolver LS;
    int *rootinfo;
    double t;
    int erk;        /* mem is an ERKStep (the erk method), else an ARKStep */
    int first_step; /* a first step given, set at the first advance (gw_sun_init_step) */
    gw_sun_peek pk;  /* a peek (gw_solver_set_peek): gw_sun_advance_peek's state */
    int fresh;       /* no step since the set-up or the last reset (the first step not yet taken) */
} ark_impl;

/* ARKStepGetReturnFlagName returns a malloc'ed string: copy it and free it. */
static void ark_flag_name(int flag, char *buf, size_t len)
{
    char *name = ARKStepGetReturnFlagName(flag);
    gw_snprintf(buf, len, "%s", name ? name : "unknown flag");
    free(name);
}

static void ark_destroy(gw_solver *s)
{
    ark_impl *a = s->impl;
    if (!a)
        return;
    if (a->mem && a->erk)
        ERKStepFree(&a->mem);
    else if (a->mem)
        ARKStepFree(&a->mem);
    if (a->LS)
        SUNLinSolFree(a->LS);
    if (a->A)
        SUNMatDestroy(a->A);
    if (a->abstol)
        N_VDestroy(a->abstol);
    if (a->y)
        N_VDestroy(a->y);
    gw_sun_peek_free(&a->pk);
    if (a->ctx)
        SUNContext_Free(&a->ctx);
    free(a->rootinfo);
    free(a);
    s->impl = NULL;
}

static int ark_roots(realtype t, N_Vector y, realtype *g, void *ud);

/* Configure the created ERKStep memory (erk): the same settings as
 * ark_configure through ERKStep's calls; returns the failing call's name or NULL. */
static const char *erk_configure(gw_solver *s, ark_impl *a, int *flag)
{
#define ERK_CHECK(call)                                                              \
    if ((*flag = (call)) < 0)                                                        \
        return #call;
    ERK_CHECK(ERKStepSetErrHandlerFn(a->mem, gw_sun_errh, s));
    ERK_CHECK(ERKStepSetUserData(a->mem, s));
    if (gw_sun_abstol_positive(a->abstol)) {
        ERK_CHECK(ERKStepWFtolerances(a->mem, gw_sun_ewt));
        ERK_CHECK(ERKStepSetUserData(a->mem, s));
    } else {
        ERK_CHECK(ERKStepSVtolerances(a->mem, s->p.rtol, a->abstol));
    }
    ERK_CHECK(ERKStepSetMaxNumSteps(a->mem, s->p.max_steps));
    if (s->p.dt > 0) { /* a first step given: cut as far as needed (cv_create says why) */
        a->first_step = 1; /* ERKStepSetInitStep at the first advance, which knows tout */
        ERK_CHECK(ERKStepSetMaxErrTestFails(a->mem, GW_SUN_GIVEN_STEP_ERR_FAILS));
    }
    if (s->p.dt_max > 0)
        ERK_CHECK(ERKStepSetMaxStep(a->mem, s->p.dt_max));
    ERK_CHECK(ERKStepSetTableName(a->mem, "ARKODE_CASH_KARP_6_4_5"));
    if (s->sys.nroots > 0)
        ERK_CHECK(ERKStepRootInit(a->mem, s->sys.nroots, ark_roots));
#undef ERK_CHECK
    return NULL;
}

/* Configure the created ARKStep memory; returns the failing call's name or NULL. */
static const char *ark_configure(gw_solver *s, ark_impl *a, int method, int *flag)
{
#define ARK_CHECK(call)                                                              \
    if ((*flag = (call)) < 0)                                                        \
        return #call;
    ARK_CHECK(ARKStepSetErrHandlerFn(a->mem, gw_sun_errh, s));
    ARK_CHECK(ARKStepSetUserData(a->mem, s));
    /* error weights from gw_sun_ewt (the values of ARKStepSVtolerances, one pass) */
    if (gw_sun_abstol_positive(a->abstol)) {
        ARK_CHECK(ARKStepWFtolerances(a->mem, gw_sun_ewt));
        ARK_CHECK(ARKStepSetUserData(a->mem, s));
    } else {
        ARK_CHECK(ARKStepSVtolerances(a->mem, s->p.rtol, a->abstol));
    }
    ARK_CHECK(ARKStepSetMaxNumSteps(a->mem, s->p.max_steps));
    if (s->p.dt > 0) {
        a->first_step = 1;
        ARK_CHECK(ARKStepSetMaxErrTestFails(a->mem, GW_SUN_GIVEN_STEP_ERR_FAILS));
    } else { /* ARKStep: dirk or imex (gw_sundials.h says why) */
        ARK_CHECK(ARKStepSetMaxErrTestFails(a->mem, GW_SUN_ARK_IMPLICIT_ERR_FAILS));
    }
    if (s->p.dt_max > 0)
        ARK_CHECK(ARKStepSetMaxStep(a->mem, s->p.dt_max));
    if (method == GW_ARKODE_ERK) {
        ARK_CHECK(ARKStepSetTableName(a->mem, "ARKODE_DIRK_NONE", "ARKODE_CASH_KARP_6_4_5"));
    } else {
        if (gw_sun_band(s, a->y, a->ctx, &a->A, &a->LS) != GW_OK) {
            *flag = ARK_MEM_FAIL;
            return "the band matrix";
        }
        ARK_CHECK(ARKStepSetLinearSolver(a->mem, a->LS, a->A));
        if (gw_sun_band_ordered(&s->sys))
            ARK_CHECK(ARKStepSetJacFn(a->mem, gw_sun_jac_ordered));
        if (method == GW_ARKODE_DIRK) {
            ARK_CHECK(ARKStepSetTableName(a->mem, "ARKODE_ARK548L2SA_DIRK_8_4_5",
                                          "ARKODE_ERK_NONE"));
            if (!gw_sun_band_ordered(&s->sys) && s->p.use_jac && s->sys.jac && !s->sys.matrix_free)
                ARK_CHECK(ARKStepSetJacFn(a->mem, gw_sun_jac));
        } else {
            ARK_CHECK(ARKStepSetTableName(a->mem, "ARKODE_ARK548L2SA_DIRK_8_4_5",
                                          "ARKODE_ARK548L2SA_ERK_8_4_5"));
        }
    }
    if (s->sys.nroots > 0)
        ARK_CHECK(ARKStepRootInit(a->mem, s->sys.nroots, ark_roots));
#undef ARK_CHECK
    return NULL;
}

static const gw_sun_stepper ark_stepper;

static int ark_create(gw_solver *s, double t0, const double *y0, gw_err *err)
{
    int method = s->p.method == GW_METHOD_DEFAULT ? GW_ARKODE_ERK : s->p.method;
    if (method != GW_ARKODE_ERK && method != GW_ARKODE_DIRK && method != GW_ARKODE_IMEX)
        return gw_err_set(err, GW_EUNSUPPORTED,
                          "arkode: method '%s' not offered (use erk, dirk or imex)",
                          gw_solver_method_name(s->p.method));
    if (method == GW_ARKODE_IMEX && (!s->sys.rhs_ex || !s->sys.rhs_im))
        return gw_err_set(err, GW_EUNSUPPORTED,
                          "arkode: imex needs a model with an explicit/implicit split");
    ark_impl *a = calloc(1, sizeof *a);
    if (!a)
        return gw_err_set(err, GW_ENOMEM, "arkode: out of memory");
    s->impl = a;
    if (SUNContext_Create(NULL, &a->ctx) != 0) {
        ark_destroy(s);
        return gw_err_set(err, GW_ENOMEM, "arkode: out of memory (SUNContext_Create)"); /* its only failure */
    }
    a->y = gw_sun_vector(s->sys.dim, a->ctx);
    a->abstol = gw_sun_abstol(s, a->ctx);
    if (s->sys.nroots > 0)
        a->rootinfo = calloc((size_t)s->sys.nroots, sizeof *a->rootinfo);
    if (!a->y || !a->abstol || (s->sys.nroots > 0 && !a->rootinfo)) {
        ark_destroy(s);
        return gw_err_set(err, GW_ENOMEM, "arkode: out of memory");
    }
    memcpy(N_VGetArrayPointer(a->y), y0, (size_t)s->sys.dim * sizeof *y0);
    a->t = t0;
    a->pk.st = &ark_stepper;
    a->pk.y = a->y;
    a->pk.t = &a->t;
    gw_sun_peek_start(&a->pk, t0);
    a->fresh = 1;
    a->erk = method == GW_ARKODE_ERK;
    /* ERKStep touches the vectors only through their ops: a right-hand side
     * by ranges runs queued, in one pass with the stage's linear combination */
    if (a->erk)
        a->mem = ERKStepCreate(s->sys.rhs_range ? gw_sun_rhs_queued : gw_sun_rhs, t0, a->y,
                               a->ctx);
    else if (method == GW_ARKODE_DIRK)
        a->mem = ARKStepCreate(NULL, gw_sun_rhs, t0, a->y, a->ctx);
    else
        a->mem = ARKStepCreate(gw_sun_rhs_ex, gw_sun_rhs_im, t0, a->y, a->ctx);
    if (!a->mem) {
        ark_destroy(s);
        return gw_err_set(err, GW_ENOMEM, "arkode: out of memory (%sCreate)", /* its only failure */
                          a->erk ? "ERKStep" : "ARKStep");
    }
    int flag = 0;
    const char *failed =
        a->erk ? erk_configure(s, a, &flag) : ark_configure(s, a, method, &flag);
    if (failed) {
        /* a failed allocation (ARKODE's own or its linear solver interface's):
         * out of memory, not a solver failure */
        int rc = flag == ARK_MEM_FAIL || flag == ARKLS_MEM_FAIL ? GW_ENOMEM : GW_ESOLVER;
        if (rc == GW_ENOMEM)
            gw_err_set(err, rc, "arkode: out of memory (%s)", failed);
        else
            gw_err_set(err, rc, "arkode: %s failed (flag %d)", failed, flag);
        ark_destroy(s);
        return rc;
    }
    return GW_OK;
}

/* ERKStep's or ARKStep's call, whichever the memory is. */
static int ark_evolve(ark_impl *a, double tout, double *tret, int itask)
{
    return a->erk ? ERKStepEvolve(a->mem, tout, a->y, tret, itask) : ARKStepEvolve(a->mem, tout, a->y, tret, itask);
}

static int ark_dky(ark_impl *a, double t, int k, N_Vector v)
{
    return a->erk ? ERKStepGetDky(a->mem, t, k, v) : ARKStepGetDky(a->mem, t, k, v);
}

/* The step count, the current time, the step to be tried next (after a root
 * return: the step last taken, ARKode's own) and the step last taken. */
static void ark_where(const ark_impl *a, long *nst, double *tn, double *hcur, double *hlast)
{
    if (a->erk) {
        ERKStepGetNumSteps(a->mem, nst);
        ERKStepGetCurrentTime(a->mem, tn);
        ERKStepGetCurrentStep(a->mem, hcur);
        ERKStepGetLastStep(a->mem, hlast);
    } else {
        ARKStepGetNumSteps(a->mem, nst);
        ARKStepGetCurrentTime(a->mem, tn);
        ARKStepGetCurrentStep(a->mem, hcur);
        ARKStepGetLastStep(a->mem, hlast);
    }
}

/* A failed Evolve call: the solver's message, GW_ELIMIT or GW_ESOLVER (gw_sun_failed). */
static int ark_failed(gw_solver *s, int flag, double tret)
{
    char name[64];
    ark_flag_name(flag, name, sizeof name);
    return gw_sun_failed(s, "arkode", name, flag == ARK_TOO_MUCH_WORK, tret);
}

/* The first advance after the set-up: the step given, which knows tout. */
static int ark_first_step(gw_solver *s, ark_impl *a, double tout)
{
    if (!a->first_step)
        return ARK_SUCCESS;
    a->first_step = 0;
    const double h0 = gw_sun_init_step(s->p.dt, s->p.dt_max, a->t, tout);
    return a->erk ? ERKStepSetInitStep(a->mem, h0) : ARKStepSetInitStep(a->mem, h0);
}

/* A root return: the roots found, read from the stepper, into roots. */
static int ark_root_info(gw_solver *s, ark_impl *a, int *roots)
{
    if (a->erk)
        ERKStepGetRootInfo(a->mem, a->rootinfo);
    else
        ARKStepGetRootInfo(a->mem, a->rootinfo);
    if (roots)
        memcpy(roots, a->rootinfo, (size_t)s->sys.nroots * sizeof *roots);
    return GW_ROOT;
}

/* The stepper's calls for gw_sun_advance_peek. */
static int ark_where_peek(gw_solver *s, long *nst, double *tn, double *hnext, double *hlast)
{
    ark_impl *a = s->impl;
    ark_where(a, nst, tn, hnext, hlast);
    return !a->fresh;
}

static int ark_dky_peek(gw_solver *s, double t, int k, N_Vector v)
{
    return ark_dky(s->impl, t, k, v);
}

static int ark_prepare(gw_solver *s, double tout)
{
    return ark_first_step(s, s->impl, tout);
}

static int ark_evolve_peek(gw_solver *s, double tout, double *tret, int one_step)
{
    ark_impl *a = s->impl;
    int flag = ark_evolve(a, tout, tret, one_step ? ARK_ONE_STEP : ARK_NORMAL);
    if (flag < 0)
        return flag;
    a->fresh = 0;
    return flag == ARK_ROOT_RETURN;
}

static int ark_root_info_peek(gw_solver *s, int *roots)
{
    return ark_root_info(s, s->impl, roots);
}

/* After a root return ARKode's next step may grow by its largest factor over
 * the step taken (1e4 on the first step after a start, 20 after: its
 * defaults, not set here), so 1e4 is allowed for. */
static double ark_grow(gw_solver *s, long nst)
{
    (void)s, (void)nst;
    return 1e4;
}

/* A start's first call (after the set-up or a reset) is towards tout when
 * the system has roots: ARKode's first step after a reset is the step the
 * last one chose (its estimate is not made again unless an initial step is
 * set: ARKStepReset keeps h0u), not bounded by the way to tout (measured:
 * 3.9e-5 s where tout was 2e-5 s ahead), and one taken in ARK_ONE_STEP mode
 * past tout searched its roots beyond it. Without roots the mode changes
 * only where the call returns (the steps and the output at tout are the
 * same): one step. */
static int ark_first_normal(gw_solver *s, double tout)
{
    (void)tout;
    return s->sys.nroots > 0;
}

/* A start: the rate from the system's rhs. */
static int ark_start_rate(gw_solver *s, double t, N_Vector y, N_Vector f)
{
    return !s->sys.rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(f), s->sys.params);
}

static const gw_sun_stepper ark_stepper = {"arkode", "ARK_TOO_MUCH_WORK", ark_where_peek, ark_dky_peek, ark_prepare,
                                           ark_evolve_peek, ark_failed, ark_root_info_peek, ark_grow,
                                           ark_first_normal, ark_start_rate};

/* ARKode's root function: the system's, and after each step a peek asked for
 * during the call read in the step that holds it (gw_sun_peek_catch). */
static int ark_roots(realtype t, N_Vector y, realtype *g, void *ud)
{
    gw_solver *s = ud;
    ark_impl *a = s->impl;
    gw_sun_peek_catch(s, &a->pk, t, y);
    return gw_sun_roots(t, y, g, ud);
}

/* An advance towards tout; with a peek p before it (gw_solver_set_peek),
 * gw_sun_advance_peek as cvode's (cv_advance's comment says why): the Evolve
 * calls an advance to tout makes without it, ARK_NORMAL towards tout, taken
 * one step at a time (ARK_ONE_STEP) while the next step cannot reach tout;
 * a step that may reach tout is taken in ARK_NORMAL mode, whose root search
 * ends at tout, and that call's return is held back and given at the next
 * call. The step that may reach tout: the one ARKode will try next
 * (ERKStepGetCurrentStep; failed tests only shorten it), after a root return
 * the step taken times ark_grow; a start's first call is towards tout
 * (ark_first_normal). Such a call may take several steps, and ARKode's dense
 * output covers only the last (ARKStepGetDky refuses a t before it, whatever
 * the interpolant's type or degree; setting either changes the outputs at
 * tout and the roots, which are interpolated): the state at p is read by the
 * root function in the step that holds it (gw_sun_peek_catch), and the ends
 * of the call's later steps are kept for a later peek before the return held
 * back (a quartic in its own step), all of them up to GW_SUN_PEEK_END_BYTES
 * (a peek past the ends kept fails: a cubic Hermite over several steps was
 * 4.6e-3 off on test_solver_peek's oscillator, erk, and 271 on
 * test_solver_peek_far's, when only 16 were kept). Stopping at p instead
 * changed the run: e_n by 7.6e-8 at --dt-out 3e-5 on the 40-disc pile of
 * `layer-make --n 40` (test_dt_out_bitwise). */
static int ark_advance(gw_solver *s, double tout, double *t, double *y, int *roots)
{
    ark_impl *a = s->impl;
    if (s->peek > a->t && s->peek < tout)
        return gw_sun_advance_peek(s, &a->pk, tout, t, y, roots);
    if ((a->pk.pend == 1 && a->pk.pend_tout == tout) || (a->pk.pend == 2 && a->pk.pend_t <= tout))
        return gw_sun_peek_pending(s, &a->pk, t, y, roots);
    a->pk.pend = 0;
    double tret = a->t;
    if (fabs(tout - a->t) <= 1e-13 * fmax(fabs(tout), fabs(a->t))) {
        *t = a->t;
        gw_sun_copy_out(a->y, y, s->sys.dim);
        return GW_OK;
    }
    int flag = ark_first_step(s, a, tout);
    if (flag == ARK_SUCCESS)
        flag = ark_evolve(a, tout, &tret, ARK_NORMAL);
    a->pk.tlast = tret;
    a->t = tret;
    *t = tret;
    gw_sun_copy_out(a->y, y, s->sys.dim);
    if (flag >= 0)
        a->fresh = 0;
    a->pk.root_last = flag == ARK_ROOT_RETURN;
    if (flag == ARK_ROOT_RETURN) {
        return ark_root_info(s, a, roots);
    }
    if (flag >= 0)
        return GW_OK;
    return ark_failed(s, flag, tret);
}

static int ark_reset(gw_solver *s, double t, const double *y)
{
    ark_impl *a = s->impl;
    memcpy(N_VGetArrayPointer(a->y), y, (size_t)s->sys.dim * sizeof *y);
    a->t = t;
    int flag = a->erk ? ERKStepReset(a->mem, t, a->y) : ARKStepReset(a->mem, t, a->y);
    a->first_step = 0;
    a->fresh = 1;
    gw_sun_peek_start(&a->pk, t);
    if (flag >= 0 && s->p.dt > 0) /* the run's initial step only (cv_reset says why) */
        flag = a->erk ? ERKStepSetInitStep(a->mem, 0.0) : ARKStepSetInitStep(a->mem, 0.0);
    if (flag >= 0 && s->p.dt > 0) /* ARKode's own limit again, with its own step */
        flag = a->erk ? ERKStepSetMaxErrTestFails(a->mem, GW_SUN_OWN_STEP_ERR_FAILS)
                      : ARKStepSetMaxErrTestFails(a->mem, GW_SUN_ARK_IMPLICIT_ERR_FAILS);
    if (flag < 0) {
        char name[64];
        ark_flag_name(flag, name, sizeof name);
        gw_solver_set_error(s, "arkode: %sReset at t = %.9g s failed: %s", a->erk ? "ERKStep" : "ARKStep",
                            t, name);
        return GW_ESOLVER;
    }
    return GW_OK;
}

static void ark_stats(const gw_solver *s, gw_solver_stats *st)
{
    const ark_impl *a = s->impl;
    long v = 0, fe = 0, fi = 0;
    if (a->erk) {
        ERKStepGetNumSteps(a->mem, &v);
        st->steps = v;
        ERKStepGetNumRhsEvals(a->mem, &fe);
        st->rhs_evals = fe;
        if (a->rootinfo) {
            ERKStepGetNumGEvals(a->mem, &v);
            st->root_evals = v;
        }
        return;
    }
    ARKStepGetNumSteps(a->mem, &v);
    st->steps = v;
    ARKStepGetNumRhsEvals(a->mem, &fe, &fi);
    st->rhs_evals = fe + fi;
    if (a->LS) {
        ARKStepGetNumJacEvals(a->mem, &v);
        st->jac_evals = v;
    }
    if (a->rootinfo) {
        ARKStepGetNumGEvals(a->mem, &v);
        st->root_evals = v;
    }
}

static const gw_solver_type arkode_type = {"arkode", ark_create, ark_advance, ark_reset,
                                           ark_stats, ark_destroy, NULL};
const gw_solver_type *const gw_solver_arkode = &arkode_type;
