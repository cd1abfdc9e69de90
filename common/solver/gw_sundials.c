/*
 * gw_sundials.c: callback wrappers between SUNDIALS and gw_system (see header).
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_band.h>

#include "gw_sundials.h"

int gw_sun_rhs(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    gw_solver *s = ud;
    if (gw_interrupt_pending())
        return -1; /* unrecoverable: gw_solver_advance reports the interrupt */
    return s->sys.rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), s->sys.params);
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

double gw_sun_init_step(double dt, double t)
{
    const double floor = 100 * DBL_EPSILON * fabs(t);
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
