/*
 * gw_sundials.c: callback wrappers between SUNDIALS and gw_system (see header).
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "gw_sundials.h"

int gw_sun_rhs(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    gw_solver *s = ud;
    if (gw_interrupt_pending())
        return -1; /* unrecoverable: gw_solver_advance reports the interrupt */
    return s->sys.rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), s->sys.params);
}

int gw_sun_rhs_queued(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    gw_solver *s = ud;
    if (gw_interrupt_pending())
        return -1; /* unrecoverable: gw_solver_advance reports the interrupt */
    if (s->sys.rhs_range &&
        gw_sun_nv_rhs(t, y, ydot, s->sys.rhs_range, s->sys.rhs_halo, s->sys.params) == 0)
        return 0;
    return s->sys.rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), s->sys.params);
}

/* The fixed-point iteration without its two copies (see gw_sundials.h): the
 * library's solve with m = 0 (SUNDIALS 6.4.1) step by step, with the change
 * between iterates formed as g(y_k) - y_k (the library forms y_(k+1) - y_k
 * after copying g(y_k) into y_(k+1) and y_k aside: the same subtraction of the
 * same values) and g(y_k) handed to the corrector by exchanging the two
 * vectors' data instead of copying it. */
static int fp_swappable(N_Vector a, N_Vector b)
{
    if (N_VGetVectorID(a) != SUNDIALS_NVEC_SERIAL || N_VGetVectorID(b) != SUNDIALS_NVEC_SERIAL)
        return 0;
    const N_VectorContent_Serial ca = a->content, cb = b->content;
    return ca->length == cb->length && ca->own_data && cb->own_data && ca->data != cb->data;
}

static int fp_solve(SUNNonlinearSolver NLS, N_Vector y0, N_Vector ycor, N_Vector w, realtype tol,
                    booleantype call_setup, void *mem)
{
    if (!NLS || !y0 || !ycor || !w || !mem)
        return SUN_NLS_MEM_NULL;
    SUNNonlinearSolverContent_FixedPoint c = NLS->content;
    if (!c->Sys || !c->CTest)
        return SUN_NLS_MEM_NULL;
    if (c->m != 0 || !fp_swappable(ycor, c->gy))
        return SUNNonlinSolSolve_FixedPoint(NLS, y0, ycor, w, tol, call_setup, mem);
    c->niters = 0;
    c->nconvfails = 0;
    for (c->curiter = 0; c->curiter < c->maxiters; c->curiter++) {
        if (c->Sys(ycor, c->gy, mem) != 0)
            break; /* as the library: a failed evaluation is a convergence failure */
        c->niters++;
        N_VLinearSum(1.0, c->gy, -1.0, ycor, c->delta);
        const N_VectorContent_Serial a = ycor->content, b = c->gy->content;
        realtype *d = a->data;
        a->data = b->data;
        b->data = d;
        const int rc = c->CTest(NLS, ycor, c->delta, tol, w, c->ctest_data);
        if (rc == SUN_NLS_SUCCESS)
            return SUN_NLS_SUCCESS;
        if (rc != SUN_NLS_CONTINUE) {
            c->nconvfails++;
            return rc;
        }
    }
    c->nconvfails++;
    return SUN_NLS_CONV_RECVR;
}

SUNNonlinearSolver gw_sun_fixed_point(N_Vector y, SUNContext ctx)
{
    SUNNonlinearSolver NLS = SUNNonlinSol_FixedPoint(y, 0, ctx);
    if (NLS)
        NLS->ops->solve = fp_solve;
    return NLS;
}

int gw_sun_rhs_ex(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    gw_solver *s = ud;
    if (gw_interrupt_pending())
        return -1; /* unrecoverable: gw_solver_advance reports the interrupt */
    return s->sys.rhs_ex(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), s->sys.params);
}

int gw_sun_rhs_im(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    gw_solver *s = ud;
    if (gw_interrupt_pending())
        return -1; /* unrecoverable: gw_solver_advance reports the interrupt */
    return s->sys.rhs_im(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), s->sys.params);
}

int gw_sun_roots(realtype t, N_Vector y, realtype *g, void *ud)
{
    gw_solver *s = ud;
    return s->sys.roots(t, N_VGetArrayPointer(y), g, s->sys.params);
}

int gw_sun_jac(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *ud, N_Vector t1,
               N_Vector t2, N_Vector t3)
{
    (void)t1;
    (void)t2;
    (void)t3;
    gw_solver *s = ud;
    gw_band band;
    SUNMatZero(J);
    band.cols = SM_CONTENT_B(J)->cols;
    band.smu = SM_SUBAND_B(J);
    band.mu = SM_UBAND_B(J);
    band.ml = SM_LBAND_B(J);
    return s->sys.jac(t, N_VGetArrayPointer(y), N_VGetArrayPointer(fy), &band,
                      s->sys.params);
}

void gw_sun_errh(int code, const char *module, const char *function, char *msg, void *ud)
{
    gw_solver *s = ud;
    gw_solver_set_error(s, "%s %s (flag %d): %s", module, function, code, msg);
}

int gw_sun_ewt(N_Vector y, N_Vector w, void *ud)
{
    const gw_solver *s = ud;
    return gw_sun_nv_ewt(y, w, s->p.rtol, s->p.atol, s->sys.scale);
}

double gw_sun_init_step(double dt, double t, double tout)
{
    const double floor = 100 * DBL_EPSILON * fmax(fabs(t), fabs(tout));
    return dt > 0 && dt < floor ? floor : dt;
}

int gw_sun_abstol_positive(N_Vector abstol)
{
    const double *a = N_VGetArrayPointer(abstol);
    for (long i = 0; i < N_VGetLength(abstol); i++)
        if (!(a[i] > 0))
            return 0;
    return 1;
}

N_Vector gw_sun_vector(long n, SUNContext ctx)
{
    N_Vector v = N_VNew_Serial(n, ctx);
    if (v && gw_sun_tune_vector(v) != 0) {
        N_VDestroy(v);
        return NULL;
    }
    return v;
}

N_Vector gw_sun_abstol(const gw_solver *s, SUNContext ctx)
{
    N_Vector v = gw_sun_vector(s->sys.dim, ctx);
    if (!v)
        return NULL;
    double *a = N_VGetArrayPointer(v);
    for (long i = 0; i < s->sys.dim; i++)
        a[i] = s->p.atol * (s->sys.scale ? s->sys.scale[i] : 1.0);
    return v;
}

int gw_sun_band(const gw_solver *s, N_Vector y, SUNContext ctx, SUNMatrix *A,
                SUNLinearSolver *LS)
{
    long n = s->sys.dim;
    if (s->sys.matrix_free) {
        /* no matrix: SUNDIALS forms J v by a difference quotient of the rhs;
         * no preconditioner, the default Krylov dimension (5) */
        *A = NULL;
        *LS = SUNLinSol_SPGMR(y, SUN_PREC_NONE, 0, ctx);
        return *LS ? GW_OK : GW_ENOMEM;
    }
    long mu = s->sys.mu > 0 ? s->sys.mu : n - 1;
    long ml = s->sys.ml > 0 ? s->sys.ml : n - 1;
    if (mu > n - 1)
        mu = n - 1;
    if (ml > n - 1)
        ml = n - 1;
    *A = SUNBandMatrix(n, mu, ml, ctx);
    if (!*A)
        return GW_ENOMEM;
    *LS = SUNLinSol_Band(y, *A, ctx);
    if (!*LS) {
        SUNMatDestroy(*A);
        *A = NULL;
        return GW_ENOMEM;
    }
    return GW_OK;
}

void gw_sun_copy_out(N_Vector v, double *y, long n)
{
    memcpy(y, N_VGetArrayPointer(v), (size_t)n * sizeof *y);
}
