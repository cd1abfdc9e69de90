/*
 * gw_solver.h: the ODE solver layer shared by every granwave model.
 *
 * A model describes itself with a gw_system (right-hand side, optional banded
 * Jacobian, root functions, dimension, parameters) and hands it to a solver built
 * on one backend: CVODE (BDF or Adams), ARKode (ERK, DIRK or IMEX ARK), the
 * fixed-step RK4 written here as an independent cross-check, or the fixed-step
 * velocity Verlet (kick-drift-kick) of explicit DEM codes. The first three locate
 * roots of the event functions and stop there, so a model can restart the
 * integration exactly at contact openings and closings (the Hertz force is only
 * C^1 at zero overlap; restarting there restores the methods' order). Verlet
 * reports a root at the end of the step in which it changed sign, unlocated:
 * one right-hand side evaluation per step, as in DEM codes.
 *
 * Units are the model's (granwave models use SI).
 */
#ifndef GW_SOLVER_H
#define GW_SOLVER_H

#include "gw_common.h"

#include "gw_api.h"

GW_BEGIN_DECLS /* the exported interface, C linkage (gw_api.h) */

/* Right-hand side dy/dt = f(t, y). Return 0 on success, > 0 for a recoverable
 * failure (the adaptive backends retry with a smaller step), < 0 to stop. */
typedef int (*gw_rhs_fn)(double t, const double *y, double *ydot, void *params);

/* The right-hand side on components i0 <= i < i1 only (gw_system.rhs_range):
 * ydot[i] for those i, bit for bit as rhs computes them, reading y only in
 * [i0 - rhs_halo, i1 + rhs_halo) and writing nothing else. It cannot fail. */
typedef void (*gw_rhs_range_fn)(double t, const double *y, double *ydot, long i0, long i1,
                                void *params);

/* Event (root) functions g_k(t, y), k = 0..nroots-1. Same return convention. */
typedef int (*gw_root_fn)(double t, const double *y, double *g, void *params);

/* Projection after a step of length h (verlet backend; rk4 with
 * roots_at_step_end, ydot then NULL: it carries no rates): y is the end state.
 * The model may change y in place (e.g. zero the history of a contact that
 * opened) and correct ydot, the rates the next step starts from (e.g. the
 * rates at the end state where the rhs saw the predicted state on the other
 * side of a discontinuity of the rates). Same return convention as the rhs. */
typedef int (*gw_project_fn)(double t, double h, double *y, double *ydot, void *params);

/* Drift of the model's own position-like components (verlet backend): called
 * in every step after the coordinates have drifted, with ph the state at the
 * half step (velocities v(t + h/2), coordinates at t; its GW_DRIFT_MODEL
 * components are not defined) and y the state whose coordinates are at
 * t + h and whose GW_DRIFT_MODEL components still hold their values at t. The
 * model advances those in place (e.g. the incremental tangential force of a
 * contact, F_t += K_t v_t(t + h/2) h, and the ledgers it feeds); the rhs then
 * sees them at t + h. Same return convention as the rhs. */
typedef int (*gw_drift_fn)(double t, double h, const double *ph, double *y, void *params);

/* drift[i] of a component the model advances itself (gw_drift_fn). */
#define GW_DRIFT_MODEL (-2L)

/* Banded Jacobian storage as SUNDIALS lays it out: column j, row i with
 * -ml <= i - j <= mu. Use gw_band_set to write entries; all entries start at 0. */
typedef struct gw_band {
    double **cols;
    long smu; /* storage upper bandwidth */
    long mu, ml;
} gw_band;

static inline void gw_band_set(gw_band *J, long i, long j, double v)
{
    J->cols[j][J->smu + i - j] = v;
}

/* Fill the banded Jacobian df/dy at (t, y); f = f(t, y) is given. */
typedef int (*gw_jac_fn)(double t, const double *y, const double *f, gw_band *J,
                         void *params);

typedef struct gw_system {
    long dim;            /* number of state components */
    gw_rhs_fn rhs;       /* full right-hand side (required) */
    gw_rhs_fn rhs_ex;    /* IMEX split, non-stiff part (optional) */
    gw_rhs_fn rhs_im;    /* IMEX split, stiff part; rhs = rhs_ex + rhs_im */
    gw_jac_fn jac;       /* banded Jacobian of rhs (optional: finite differences) */
    long mu, ml;         /* Jacobian half-bandwidths (implicit methods need them) */
    int matrix_free;     /* 1: no useful band (mu, ml and jac ignored): the implicit
                            methods (cvode bdf, arkode dirk, imex) solve their Newton
                            systems with GMRES on difference-quotient Jacobian-vector
                            products, one rhs per iteration, no matrix; 0: a band
                            matrix of dim x (2 mu + ml + 1) from the Jacobian or
                            mu + ml + 1 rhs evaluations, LU-factored (dense when the
                            band is the whole system: dim^3 work per factorisation) */
    /* The band's order (cvode bdf, arkode dirk and imex): states [lead0, lead0 +
     * nlead) come first in the band matrix and its solves, the others after
     * them in their own order; the last nledger states of that order are
     * ledgers (integrals of rates that no rate depends on, e.g. an energy
     * dissipated by every contact), their rows left out of the matrix (their
     * Newton iterates follow the others' one iteration behind). A few states
     * appended after a long chain that couple only to its first ones (a sensor
     * body under bead 1) then keep the band narrow, where in the states' own
     * order they make it the whole system. mu and ml are the half-bandwidths
     * in the band's order. nlead > 0 needs jac NULL: the Jacobian is formed by
     * difference quotients in that order (mu + ml + 1 rhs evaluations).
     * nlead = nledger = 0: the states' own order. */
    long lead0, nlead, nledger;
    gw_root_fn roots;    /* event functions (optional) */
    int nroots;
    const double *scale; /* typical magnitude of each component, or NULL (= 1):
                            absolute tolerance of component i is atol * scale[i];
                            each finite and > 0 (gw_solver_create refuses others) */
    void *params;        /* passed to every callback, owned by the model */
    /* Second-order structure, used by the verlet backend (required there, ignored
     * by the others): drift[i] = j >= 0 says dy_i/dt = y_j (a coordinate and its
     * velocity); drift[i] = -1 marks every other component, whose rate the rhs
     * gives (velocities, forces carried as state, integrated ledgers);
     * drift[i] = GW_DRIFT_MODEL a component that drift_fn advances. */
    const long *drift;
    gw_project_fn project; /* after each verlet step, and each rk4 step when
                              roots_at_step_end is set (optional) */
    int roots_at_step_end; /* rk4: 1 reports a root at the end of the step in which
                              it changed sign, unlocated, as verlet does (the step
                              grid stays k dt whatever the roots), and calls project
                              after every step; 0 locates roots (cvode and arkode
                              always locate, verlet never) */
    gw_drift_fn drift_fn;  /* required when some drift[i] == GW_DRIFT_MODEL */
    /* Optional, for a system whose rhs is local (component i depends on y only
     * within rhs_halo <= 64 components of i): the same rhs by ranges of
     * components, i0 and i1 multiples of 64 (i1 = dim for the last). CVODE Adams
     * then runs it block by block in one pass with the vector operations queued
     * around it (gw_nvector.c), so y and ydot are not streamed through memory
     * once more each; results are bit-identical to rhs. NULL: rhs only. */
    gw_rhs_range_fn rhs_range;
    long rhs_halo;
} gw_system;

/* Backend variants. */
enum {
    GW_METHOD_DEFAULT = 0,
    GW_CVODE_BDF = 1,
    GW_CVODE_ADAMS = 2,
    GW_ARKODE_ERK = 3,
    GW_ARKODE_DIRK = 4,
    GW_ARKODE_IMEX = 5
};

typedef struct gw_solver_params {
    double rtol;       /* relative tolerance (adaptive backends) */
    double atol;       /* absolute tolerance, multiplied by gw_system.scale[i] */
    double dt;         /* RK4 step (at most dt_max); the run's first step for adaptive backends
                          (0 = auto; a restart after an event estimates its own) */
    double dt_max;     /* largest step (0 = unlimited) */
    long max_steps;    /* internal steps allowed per gw_solver_advance call */
    int method;        /* GW_METHOD_DEFAULT or a backend variant above */
    int use_jac;       /* use gw_system.jac when present (else finite differences) */
} gw_solver_params;

/* rtol 1e-10, atol 1e-10, dt 0 (RK4 needs it set), max_steps 1e7, default method. */
gw_solver_params gw_solver_params_default(void);

typedef struct gw_solver gw_solver;
typedef struct gw_solver_type gw_solver_type;

/* The backends: const singleton tables. */
extern const gw_solver_type *const gw_solver_cvode;
extern const gw_solver_type *const gw_solver_arkode;
extern const gw_solver_type *const gw_solver_rk4;
extern const gw_solver_type *const gw_solver_verlet;

/* Backend by name ("cvode", "arkode", "rk4", "verlet"); NULL if unknown. */
const gw_solver_type *gw_solver_type_find(const char *name);
const char *gw_solver_type_name(const gw_solver_type *type);
/* The tolerances are cvode's and arkode's: for a fixed-step backend (rk4,
 * verlet), GW_EINVAL "rtol: has no effect with the fixed-step NAME solver ..."
 * when row rtol or atol of table t differs in obj from the row's default
 * (NaN when the row has none: not given); GW_OK otherwise. A NULL type, t
 * or obj is refused (GW_EINVAL naming it) whatever the backend. */
struct gw_param;
int gw_solver_tolerances_unused_check(const gw_solver_type *type, const struct gw_param *t, const void *obj,
                                      gw_err *err);
/* Backend variant by name ("bdf", "adams", "erk", "dirk", "imex"); -1 if unknown. */
int gw_solver_method_find(const char *name);
const char *gw_solver_method_name(int method);
/* The variant a backend runs for method (GW_METHOD_DEFAULT resolved: cvode
 * "bdf", arkode "erk"; "none" for rk4 and verlet), for provenance; "unknown"
 * for no backend or a variant the backend has not (cvode with erk). */
const char *gw_solver_method_used(const gw_solver_type *type, int method);

typedef struct gw_solver_stats {
    long steps;      /* internal steps taken (all restarts summed) */
    long rhs_evals;  /* right-hand side evaluations */
    long jac_evals;  /* Jacobian evaluations */
    long root_evals; /* root function evaluations */
    long restarts;   /* gw_solver_reset calls */
} gw_solver_stats;

/* Create a solver for sys at (t0, y0). sys and its params must outlive the solver;
 * y0 is copied. Returns GW_EINVAL (bad tolerances or step, a t0 or y0 that is
 * not finite, message in err),
 * GW_EUNSUPPORTED (variant not offered by the backend, e.g. IMEX without a split),
 * GW_ESOLVER (backend setup failed, message in err). *out is NULL on failure. */
int gw_solver_create(const gw_solver_type *type, const gw_system *sys,
                     const gw_solver_params *p, double t0, const double *y0,
                     gw_solver **out, gw_err *err);

/* Integrate towards tout. Returns GW_OK with *t == tout, GW_ROOT when an event
 * stopped it at *t (rootsfound[k] = +1 for a rising and -1 for a falling zero of
 * g_k, 0 for components without a root; rootsfound may be NULL), or GW_ESOLVER /
 * GW_ELIMIT with the backend's message and the time in gw_solver_error(). After a
 * failure *t and y hold the last successful state. A tout that is not finite,
 * or for the fixed-step rk4 and verlet (forward only) one before the solver's
 * time, is GW_EINVAL (message in gw_solver_error(), nothing integrated). */
int gw_solver_advance(gw_solver *s, double tout, double *t, double *y,
                      int *rootsfound);

/* A peek (cvode, arkode, rk4 and verlet): the next gw_solver_advance towards a tout after tpeek
 * makes the steps and finds the roots that the advance to tout makes without
 * it, and returns GW_SOLVER_PEEK with *t = tpeek and y the state interpolated
 * there as soon as they pass tpeek (a root before it is returned first,
 * GW_ROOT, and the peek stays armed; restarts keep it). The advance to tout
 * goes on at the next call, which returns what it would have. An output
 * between the times a run stops at, without a stop that would change the
 * run (cvode, arkode: interpolated in the step that passed tpeek; rk4: a step of
 * rk4 from the start of the step that holds tpeek, the step then made again;
 * verlet: the step that holds tpeek taken, the state there a cubic Hermite
 * between its ends for the drifts and their velocities, a line for the other
 * components; a root that step found is returned by the next call). Returns 1
 * when armed, 0 when the backend has none (nothing armed); tpeek <= 0 disarms.
 * cvode and arkode keep the ends of the steps after a peek, so that a later
 * peek before a return held back is read in its own step, up to 256 MiB of
 * states and rates: a peek past them fails with GW_ELIMIT (GW_ENOMEM when
 * memory ran out first) naming the limit, the peek disarmed, *t and y as they
 * were, the return held back given by the next advance (never a value
 * interpolated over several steps). */
enum { GW_SOLVER_PEEK = 2 };
int gw_solver_set_peek(gw_solver *s, double tpeek);

/* Restart the integration at (t, y), discarding the step history. GW_EINVAL
 * (message in gw_solver_error()) for a t that is not finite. */
int gw_solver_reset(gw_solver *s, double t, const double *y);

/* The rates (sys.dim entries) the next step starts from, when the backend
 * carries them from step to step, else NULL. verlet: f of its last rhs
 * evaluation, at the end of the last step with the predicted velocities (or at
 * the start), which a new solver created at the same (t, y) would not
 * reproduce when rates depend on velocities: a model that re-creates the
 * solver mid-run (a new dimension) and hands these back from its first rhs
 * call keeps the trajectory the run without the re-creation takes. */
const double *gw_solver_rates(const gw_solver *s);

/* ------------------------------------------------------------------ driver --
 * The loop every model runs around gw_solver_advance: integrate to output
 * times, stop at roots and let the model act there, restart, and end when the
 * model says so or at t_end. A hook returns
 *   GW_DRIVE_ON     go on, the solver as it is (y unchanged),
 *   GW_DRIVE_RESET  restart the solver from (t, y) (y may have been changed, or
 *                   the right-hand side changes there), then go on,
 *   GW_DRIVE_STOP   end the run: gw_solver_drive returns GW_OK,
 *   GW_DRIVE_YIELD  hand back: gw_solver_drive returns GW_ROOT without
 *                   restarting (the caller may rebuild the system),
 * or a negative gw status with err set, which gw_solver_drive returns. */
enum { GW_DRIVE_ON = 0, GW_DRIVE_STOP = 1, GW_DRIVE_YIELD = 2, GW_DRIVE_RESET = 3 };

typedef struct gw_drive {
    double t_end;     /* the run ends here at the latest */
    double dt_out;    /* output times k dt_out, k = k_out, k_out + 1, ...; 0: t_end only */
    long k_out;       /* in/out: index of the next output time (>= 1) */
    const char *what; /* prefix of the solver's messages ("drop"); NULL: none */
    int (*on_root)(void *ctx, double t, double *y, const int *roots, gw_err *err);
    int (*on_output)(void *ctx, double t, double *y, gw_err *err); /* t exactly the output time */
    int (*after)(void *ctx, double t, const double *y, gw_err *err); /* after every root or output */
    void *ctx;        /* the hooks' (any may be NULL) */
} gw_drive;

/* Run s from (*t, y) as d says; *t and y follow the run. Returns GW_OK (t_end
 * reached or a hook stopped), GW_ROOT (a hook yielded; roots holds the roots),
 * the solver's failure (GW_ESOLVER, GW_ELIMIT: "what: backend message", which
 * names the time) or a hook's negative status. roots: sys.nroots entries.
 * GW_EINVAL naming the field for a t_end that is not finite (NaN returned
 * GW_OK having run nothing) or a dt_out NaN, infinite or negative. */
int gw_solver_drive(gw_solver *s, gw_drive *d, double *t, double *y, int *roots, gw_err *err);

void gw_solver_get_stats(const gw_solver *s, gw_solver_stats *st);
/* Last error message ("" if none). Owned by the solver. */
const char *gw_solver_error(const gw_solver *s);
const gw_solver_type *gw_solver_get_type(const gw_solver *s);
/* Free; NULL is a no-op. */
void gw_solver_free(gw_solver *s);

GW_END_DECLS

#endif
