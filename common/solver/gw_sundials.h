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
#include <sundials/sundials_nonlinearsolver.h>

#include "gw_solver_impl.h"

int gw_sun_rhs(realtype t, N_Vector y, N_Vector ydot, void *ud);
/* gw_sun_rhs for a solver whose system has rhs_range, for SUNDIALS code that
 * touches vector data only through the vector's ops (CVODE Adams with its
 * fixed-point corrector; not the linear solvers, whose difference quotients
 * read f(y) through a data pointer taken before the call): the rhs is queued
 * with the pending vector operations (gw_sun_nv_rhs) when it can be, else
 * called at once. */
int gw_sun_rhs_queued(realtype t, N_Vector y, N_Vector ydot, void *ud);
int gw_sun_rhs_ex(realtype t, N_Vector y, N_Vector ydot, void *ud);
int gw_sun_rhs_im(realtype t, N_Vector y, N_Vector ydot, void *ud);
int gw_sun_roots(realtype t, N_Vector y, realtype *g, void *ud);
int gw_sun_jac(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *ud,
               N_Vector t1, N_Vector t2, N_Vector t3);
/* Whether the band matrix follows the system's band order (gw_system.lead0,
 * nlead, nledger): then gw_sun_band's solver takes the right-hand side into
 * that order and the Jacobian is gw_sun_jac_ordered's (set as the jac fn). */
int gw_sun_band_ordered(const gw_system *sys);
int gw_sun_jac_ordered(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *ud, N_Vector t1, N_Vector t2,
                       N_Vector t3);
void gw_sun_errh(int code, const char *module, const char *function, char *msg,
                 void *ud);

/* SUNDIALS' fixed-point nonlinear solver (m = 0, no acceleration) whose
 * solve makes neither of the library's two whole-vector copies per iteration
 * (the previous iterate, and g(y) into the iterate): the change between
 * iterates is formed as g(y_k) - y_k, and g(y_k) becomes the iterate by
 * exchanging the data of the two serial vectors. The same values in the same
 * vectors as the library's solve, bit for bit, with one vector less streamed
 * and written per iteration (CVODE Adams). Falls back to the library's solve
 * for vectors it cannot exchange. NULL on allocation failure. */
SUNNonlinearSolver gw_sun_fixed_point(N_Vector y, SUNContext ctx);

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

/* Queue ydot = f(t, y), given by ranges of components (gw_rhs_range_fn,
 * reading y within halo <= 64 elements of each range), with the pending
 * operations of gw_nvector.c; it then runs block by block in their pass.
 * 0 if queued; -1 (nothing done) if y or ydot is not a tuned vector, they
 * differ in length or share data, or the halo is out of range. */
int gw_sun_nv_rhs(double t, N_Vector y, N_Vector ydot, gw_rhs_range_fn f, long halo,
                  void *params);

/* Error weights w_i = 1 / (rtol |y_i| + atol scale_i) in one pass (the values
 * SUNDIALS' vector-tolerance path computes in four passes); ud is the gw_solver.
 * Only for solvers whose atol scale_i are all > 0 (gw_sun_abstol_positive): the
 * denominator is then positive and needs no check. Returns 0. */
int gw_sun_ewt(N_Vector y, N_Vector w, void *ud);

/* Failed error tests allowed per step: with a first step the caller gave (each
 * failure cuts the step at most tenfold, so 30 reach 1e-30 of it: cv_create
 * says why), and the solvers' own default, put back at a restart, which
 * estimates its own step. arkode's implicit methods (dirk, imex) are allowed
 * GW_SUN_ARK_IMPLICIT_ERR_FAILS on their own steps too: on a stiff overdamped
 * mode their embedded estimate is poor at h lambda of about 5 to 10, and
 * seven cuts of the step did not reach below it (arkode dirk on a 1e-7 kg
 * sensor body on 1e12 N/m at 10 of critical, c_s/M = 6.3e10 /s, failed its
 * error test at h = 6.7e-11 s after 0.07 ms; 1e-9 kg from 3 of critical,
 * 1e-6 kg from 30); allowed 30 it ran in 10,317 steps. A run that succeeds
 * takes the same steps either way (the count only ends a run). */
enum { GW_SUN_GIVEN_STEP_ERR_FAILS = 30, GW_SUN_OWN_STEP_ERR_FAILS = 7, GW_SUN_ARK_IMPLICIT_ERR_FAILS = 30 };

/* The first step of a run from t toward its first output time tout: the step
 * given (dt > 0), but at least 100 units of rounding of the larger of |t| and
 * |tout|, CVODE's own lower bound for a step it estimates (HLB_FACTOR * uround *
 * max(|t0|, |tout|)); 0 (dt not given) stays 0. The backends set it at their
 * first advance, when tout is known. Below it:
 * - at t > 0 a step does not move t (t + dt == t): restarted at an event with
 *   the chain's --dt 1e-300, CVODE stepped in place at t = 5.03e-5 s for good
 *   (the sixteenth session of stage 2);
 * - at t = 0, SUNDIALS' difference-quotient Jacobian (the column's general
 *   model, whose wall has states of its own, has no analytic one) perturbs the
 *   state by about 1000 h uround N |f| over the error weights, which for h below
 *   about 1e-290 s falls out of the normal doubles: every Newton iteration of
 *   bdf and dirk failed and chain --sheet pvc --sheet-law material --dt 1e-300
 *   exited 1 at t = 0 ("the corrector convergence test failed repeatedly").
 * The raised step is one the solver could have estimated itself; the result
 * is the default run's to the tolerances (test_chain_limits). A step above
 * dt_max (> 0) is lowered to it. */
double gw_sun_init_step(double dt, double dt_max, double t, double tout);

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

/* A failed CVode or ARKode call at tret: "NAME failed at t = T s (FLAG):
 * message" on the solver (the message the solver's error handler left there,
 * or "no message"); returns GW_ELIMIT when too_much_work (the flag is the
 * backend's TOO_MUCH_WORK: the step limit), else GW_ESOLVER. */
int gw_sun_failed(gw_solver *s, const char *name, const char *flag_name, int too_much_work, double tret);

/* A read-through sample (gw_solver_set_peek) under CVODE or ARKode, one driver
 * for both: the backend's calls passed in (gw_sun_stepper), its state kept in
 * a gw_sun_peek inside the backend's own. */
typedef struct gw_sun_stepper {
    const char *name;     /* "cvode", "arkode": the messages' */
    const char *too_much; /* the backend's name of the step limit's flag */
    /* the step count, the current time, the step to be tried next and the
     * step last taken; returns 1 once a step was taken since the set-up or
     * the last restart, else 0 */
    int (*where)(gw_solver *s, long *nst, double *tn, double *hnext, double *hlast);
    /* the k-th derivative of the dense output at t into v: the backend's flag (0 done) */
    int (*dky)(gw_solver *s, double t, int k, N_Vector v);
    /* before the first call of an advance (the first step given): a flag < 0 failed */
    int (*prepare)(gw_solver *s, double tout);
    /* one call towards tout, in one-step mode or not, its return time in
     * *tret: the backend's flag when < 0 (failed), 1 a root, 0 otherwise */
    int (*evolve)(gw_solver *s, double tout, double *tret, int one_step);
    int (*failed)(gw_solver *s, int flag, double tret); /* a failed call: its message, GW_ESOLVER or GW_ELIMIT */
    int (*root_info)(gw_solver *s, int *roots);         /* the roots found, into roots: GW_ROOT */
    /* after a root return, how much the next step may grow over the step
     * taken (nst the step count); no step since the start: whether the first
     * call is made towards tout (not one step) */
    double (*grow)(gw_solver *s, long nst);
    int (*first_normal)(gw_solver *s, double tout);
    /* the rate at a start (t, y) into f: 1 given, 0 unknown (NULL: unknown) */
    int (*start_rate)(gw_solver *s, double t, N_Vector y, N_Vector f);
} gw_sun_stepper;

typedef struct gw_sun_peek {
    const gw_sun_stepper *st;
    N_Vector y;  /* the backend's state */
    double *t;   /* the backend's time */
    /* the state at the peek, the one at the start of a call towards tout and
     * both derivatives (a peek before the last of its steps, cubic Hermite) */
    N_Vector yp, y0, d0, d1;
    N_Vector ym, fm; /* the Hermite's state and rate at 2/3 of its interval */
    int have0;        /* y0 at t0 kept for the Hermite: 1 with its rate d0, 2 without */
    double t0;
    int pend;         /* held back: 1 tout reached (pend_t = pend_tout), 2 a root at pend_t */
    double pend_t, pend_tout;
    double tlast;     /* the time the backend last returned (roots searched up to it) */
    int root_last;    /* the last return was a root, no restart since */
    /* a state read at the peek during a call, in the step that held it (the
     * backend's root function, gw_sun_peek_catch): want the peek asked for
     * during the call, got 1 with yp the state at got_t */
    double want, got_t;
    int got;
    /* the ends of the steps of a call towards tout (rec 1), from the last
     * one before the peek on: their times, states and rates, so that a later
     * peek before the return held back is read in its own step. The arrays
     * grow as the call's steps are taken (cap entries, the vectors of the
     * first nvec made and kept for the next calls), up to
     * GW_SUN_PEEK_END_BYTES of kept states and rates; past it, or when memory
     * runs out, lost is set (GW_ELIMIT, GW_ENOMEM) with lost_t the first end
     * not kept, no end is kept after it, and a later peek that would need it
     * fails (no cubic over several steps: a silent loss of accuracy) */
    int rec;
    long nend, cap, nvec;
    double *tend;
    N_Vector *yend, *fend;
    unsigned char *fok; /* fend[i] computed */
    int lost;
    double lost_t;
} gw_sun_peek;
/* The bytes of step ends (a state and a rate each) one call may keep for its
 * peeks: 256 MiB, 16 ends of a system of 2^20 components, 8 million ends of
 * a 2-component oscillator. */
#define GW_SUN_PEEK_END_BYTES ((size_t)256 << 20)

/* The driver's state at a start (the set-up or a restart at t). */
void gw_sun_peek_start(gw_sun_peek *k, double t);
/* Free the driver's vectors. */
void gw_sun_peek_free(gw_sun_peek *k);
/* A return held back by a peek, now given (gw_sun_advance_peek). */
int gw_sun_peek_pending(gw_solver *s, gw_sun_peek *k, double *t, double *y, int *roots);
/* An advance towards tout with the peek s->peek before it (the comments on
 * cv_advance in gw_backend_cvode.c and ark_advance in gw_backend_arkode.c say
 * how and why): GW_SOLVER_PEEK with the state there, or the return the
 * advance would have made before it. A peek in a step whose ends were not kept
 * (gw_sun_peek.lost: GW_SUN_PEEK_END_BYTES reached, GW_ELIMIT; out of memory,
 * GW_ENOMEM) or whose end's rate failed (GW_ESOLVER) fails with the message on
 * the solver: the peek disarmed, *t and y as they were, a return held back
 * given at the next call. */
int gw_sun_advance_peek(gw_solver *s, gw_sun_peek *k, double tout, double *t, double *y, int *roots);
/* From the backend's root function, called after each step it takes (and in
 * its root search, (t, y) its arguments): the peek asked for during the call,
 * read from the dense output of the step just taken when that step holds it,
 * and the step's end kept (gw_sun_peek.rec). */
void gw_sun_peek_catch(gw_solver *s, gw_sun_peek *k, double t, N_Vector y);

#endif
