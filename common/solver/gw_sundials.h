/*
 * gw_sundials.h: glue shared by the CVODE and ARKode backends (private): callback
 * wrappers that unpack N_Vectors and forward to the gw_system, the error handler
 * that keeps the backend's message on the solver, and the absolute tolerance vector.
 * The user_data of every SUNDIALS callback is the gw_solver.
 */
#ifndef GW_SUNDIALS_H
#define GW_SUNDIALS_H

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include "gw_solver_impl.h"

int gw_sun_rhs(realtype t, N_Vector y, N_Vector ydot, void *ud);
int gw_sun_rhs_ex(realtype t, N_Vector y, N_Vector ydot, void *ud);
int gw_sun_rhs_im(realtype t, N_Vector y, N_Vector ydot, void *ud);
int gw_sun_roots(realtype t, N_Vector y, realtype *g, void *ud);
int gw_sun_jac(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *ud,
               N_Vector t1, N_Vector t2, N_Vector t3);
void gw_sun_errh(int code, const char *module, const char *function, char *msg,
                 void *ud);

/* Serial vector of length n with SUNDIALS' fused and vector-array operations
 * enabled and the hot operations replaced by gw_nvector.c's compiled kernels
 * (clones inherit both). NULL on allocation failure. */
N_Vector gw_sun_vector(long n, SUNContext ctx);

/* Enable fused operations on a serial vector and install gw_nvector.c's
 * kernels in its ops table. 0 on success, -1 if v is not a serial vector. */
int gw_sun_tune_vector(N_Vector v);

/* The error weights w_i = 1 / (rtol |y_i| + atol scale_i) (scale NULL: 1):
 * queued with gw_nvector.c's pending operations, to run in their pass, when y
 * and w are tuned vectors, else computed at once. Returns 0. */
int gw_sun_nv_ewt(N_Vector y, N_Vector w, double rtol, double atol, const double *scale);

/* Error weights w_i = 1 / (rtol |y_i| + atol scale_i) in one pass (the values
 * SUNDIALS' vector-tolerance path computes in four passes); ud is the gw_solver.
 * Only for solvers whose atol scale_i are all > 0 (gw_sun_abstol_positive): the
 * denominator is then positive and needs no check. Returns 0. */
int gw_sun_ewt(N_Vector y, N_Vector w, void *ud);

/* The initial step for a (re)start at t: the step given (dt > 0), but at least
 * 100 units of rounding of t, CVODE's own lower bound for a step it estimates
 * (HLB_FACTOR * uround * |t|); 0 (dt not given) stays 0. A step below it does
 * not move t (t + dt == t): restarted at an event with the chain's --dt 1e-300,
 * CVODE stepped in place at t = 5.03e-5 s for good (the sixteenth session of
 * stage 2), while its first start at t = 0 took the step as given. */
double gw_sun_init_step(double dt, double t);

/* 1 if every component of the absolute tolerance vector is > 0, else 0. */
int gw_sun_abstol_positive(N_Vector abstol);

/* Vector of atol * scale[i]; NULL on allocation failure. */
N_Vector gw_sun_abstol(const gw_solver *s, SUNContext ctx);

/* Band matrix and band linear solver sized from the system's bandwidths; for a
 * matrix_free system *A = NULL and *LS is GMRES (no preconditioner). */
int gw_sun_band(const gw_solver *s, N_Vector y, SUNContext ctx, SUNMatrix *A,
                SUNLinearSolver *LS);

/* Copy n doubles from an N_Vector. */
void gw_sun_copy_out(N_Vector v, double *y, long n);

#endif
