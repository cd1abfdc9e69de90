/*
 * chain_restitution.c: calibration of the viscoelastic damping constant from a
 * target restitution coefficient (docs/physics.md 1.5).
 *
 * A single bead hits the wall at v: e(c) = -v_f / v with c the Hunt-Crossley
 * alpha (s/m; F = K d^(3/2) (1 + 1.5 alpha d')) or the Kuwabara-Kono gamma
 * (N s/m^1.5 of bead contacts; the wall uses gamma K/k). e(c) falls
 * monotonically from 1 at c = 0; the root of e(c) - e_target is bracketed by
 * doubling from the small-damping estimate (Hunt-Crossley: e ~ 1 - alpha v),
 * at most up to GW_CHAIN_ALPHA_MAX / GW_CHAIN_GAMMA_MAX (a target that needs
 * more is refused, GW_EINVAL), and solved with GSL's Brent method to 1e-10 relative in e. The bead hits the
 * Hertz wall kwall on a rigid sensor, without guide friction: a sheet law, sensor
 * body or guide of the parameters is left out of the calibration.
 *
 * The calibration is of the contact, not of the run: it takes the run's backend
 * and its accuracy (solver, method, rtol, atol, dt, dt-max, max-steps, RK4 steps
 * per T_c) but its own end time, sampling and no energy limit, so that the
 * column's t-max, dt-out, energy-tol or initial state neither change the
 * constant nor end a one-bead collision early (a t-max shorter than the contact
 * was taken for an overdamped contact, "raise restitution").
 *
 * Memo: the constant depends on nothing but the one-bead problem below (the
 * values calib_key lists) and the target, so a process keeps the last
 * CALIB_MEMO of them and returns a stored constant for the same key, bit for
 * bit the one a fresh calibration gives (a sweep checked each case and then
 * ran it, calibrating twice per case for a few distinct calibrations: 20,000
 * chain cases with 50 distinct ones took 6 min to check). Only successes are
 * kept. The lock is held for the look-up and the store alone, never during a
 * calibration, and a fork waits for it (pthread_atfork, as gw_global.h's).
 */
#include <math.h>
#include <pthread.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "chain_restitution.h"
#include "gw_chain.h"
#include "gw_global.h"
#include "gw_locale.h"

typedef struct calib {
    gw_chain_params bead; /* the one-bead problem, constant 0 */
    gw_chain_run_opts o;  /* its run: the caller's backend and accuracy only */
    double target;
    int rc;
    gw_err *err;
} calib;

/* The one-bead problem of column p: bead 1 (p's mass and radius) on the Hertz
 * wall kwall of a rigid sensor, no guide, the damping constant left to set. */
static gw_chain_params bead_params(const gw_chain_params *p)
{
    gw_chain_params b = *p;
    b.n = 1;
    b.masses = NULL;
    b.kc = NULL;
    /* the contact damping is calibrated on the Hertz wall kwall alone */
    memset(&b.wall, 0, sizeof b.wall);
    memset(&b.sensor, 0, sizeof b.sensor);
    memset(&b.guide, 0, sizeof b.guide);
    if (b.damping == GW_DAMP_HUNT_CROSSLEY)
        b.alpha = 0;
    else
        b.gamma = 0;
    return b;
}

/* Its run: the caller's backend and accuracy; its own end time (0: 20 times the
 * bead's collision), sampling (0: tau_1/200), no energy limit, no initial state,
 * sample callback or front. */
static gw_chain_run_opts bead_opts(const gw_chain_run_opts *o)
{
    gw_chain_run_opts r = gw_chain_run_opts_default();
    r.solver = o->solver ? o->solver : gw_solver_cvode;
    r.sp = o->sp;
    r.steps_per_tc = o->steps_per_tc;
    return r;
}

static double bead_restitution(double cst, void *ctx)
{
    calib *cb = ctx;
    gw_chain_params p = cb->bead;
    if (p.damping == GW_DAMP_HUNT_CROSSLEY)
        p.alpha = cst;
    else
        p.gamma = cst;
    gw_chain *c = NULL;
    gw_chain_result r;
    memset(&r, 0, sizeof r);
    int rc = gw_chain_create(&p, &c, cb->err);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, &cb->o, &r, cb->err);
    /* a bead still on the wall at the end of its own run, 20 times its
     * collision: the contact is overdamped before e reaches the target (this
     * ended as a failed run, exit 2 with "chain: bead 1 still on the wall",
     * naming no input; taking it as e = 0 would calibrate the constant at which
     * the bead just stays within t_max, not e). Any other limit (max-steps, the
     * steps bound) is the run's failure, not an e of 0: "max-steps 3" was taken
     * for an overdamped contact, "raise restitution". */
    int stuck = rc == GW_ELIMIT && r.t_end >= r.run_t_max && !isfinite(r.tau_n);
    if (stuck)
        rc = GW_OK; /* e = 0 for the bracket; the root is checked below */
    double e = rc == GW_OK ? (stuck ? 0.0 : -r.final_v[0] / p.v_imp) : NAN;
    if (rc != GW_OK && cb->rc == GW_OK)
        cb->rc = rc;
    gw_chain_result_free(&r);
    gw_chain_free(c);
    return e - cb->target;
}

/* ---- memo ---- */

#define CALIB_MEMO 256
#define CALIB_KEY 20

/* Every value the calibration depends on, as doubles (no padding, no pointer):
 * the target, the bead problem (bead_params) and its run (bead_opts). A field
 * added to gw_chain_params or to gw_chain_run_opts's run must enter here. */
typedef struct calib_key {
    double v[CALIB_KEY];
} calib_key;

static int solver_id(const gw_solver_type *t)
{
    return t == gw_solver_cvode ? 0 : t == gw_solver_arkode ? 1 : t == gw_solver_rk4 ? 2 : t == gw_solver_verlet ? 3 : 4;
}

static calib_key key_of(const calib *cb)
{
    const gw_chain_params *b = &cb->bead;
    const gw_chain_run_opts *o = &cb->o;
    calib_key k;
    memset(&k, 0, sizeof k);
    const double v[] = {cb->target, (double)b->damping, (double)b->n, b->v_imp, b->mass, b->k, b->kwall, b->radius,
                        b->gravity, b->gamma, b->alpha, (double)solver_id(o->solver), (double)o->sp.method,
                        o->sp.rtol, o->sp.atol, o->sp.dt, o->sp.dt_max, (double)o->sp.max_steps,
                        (double)o->sp.use_jac, o->steps_per_tc};
    _Static_assert(sizeof v / sizeof v[0] == CALIB_KEY, "calib_key holds every value");
    memcpy(k.v, v, sizeof v);
    return k;
}

static struct {
    calib_key key[CALIB_MEMO];
    double constant[CALIB_MEMO];
    int used, next;
    long hits, misses;
} memo;
static gw_forklock memo_lock = GW_FORKLOCK(NULL);

/* 1 and *constant when key is stored. The keys are compared as bytes: equal
 * doubles with other bits (-0 and 0, NaNs) are a miss, never a wrong hit. */
static int memo_find(const calib_key *k, double *constant)
{
    gw_forklock_take(&memo_lock);
    int found = 0;
    for (int i = 0; i < memo.used && !found; i++)
        if (memcmp(&memo.key[i], k, sizeof *k) == 0) {
            *constant = memo.constant[i];
            found = 1;
        }
    if (found)
        memo.hits++;
    else
        memo.misses++;
    gw_forklock_give(&memo_lock);
    return found;
}

static void memo_store(const calib_key *k, double constant)
{
    gw_forklock_take(&memo_lock);
    int i;
    for (i = 0; i < memo.used; i++) /* another thread may have stored it meanwhile */
        if (memcmp(&memo.key[i], k, sizeof *k) == 0)
            break;
    if (i == memo.used) {
        i = memo.next;
        memo.next = (memo.next + 1) % CALIB_MEMO;
        if (memo.used < CALIB_MEMO)
            memo.used++;
    }
    memo.key[i] = *k;
    memo.constant[i] = constant;
    gw_forklock_give(&memo_lock);
}

void chain_calibrate_memo_stats(long *hits, long *misses)
{
    gw_forklock_take(&memo_lock);
    *hits = memo.hits;
    *misses = memo.misses;
    gw_forklock_give(&memo_lock);
}

void chain_calibrate_memo_clear(void)
{
    gw_forklock_take(&memo_lock);
    memo.used = memo.next = 0;
    memo.hits = memo.misses = 0;
    gw_forklock_give(&memo_lock);
}

/* A run's failure inside the calibration, named as the calibration's (the
 * backend's message and time kept, the code kept: a solver failure stays one);
 * a refused input of the run (its plan's bounds) keeps its own name. */
static int calib_failed(const calib *cb, gw_err *err)
{
    if (cb->rc == GW_EINVAL) /* a bound of the run's plan, naming its input (dt-max, dt-out) */
        return cb->rc;
    char tmp[sizeof err->msg];
    gw_snprintf(tmp, sizeof tmp, "%s", err->msg);
    return gw_err_set(err, cb->rc, "restitution: calibrating the damping on one bead at %g m/s: %s", cb->bead.v_imp,
                      tmp);
}

static int calibrate(calib *cb, double *constant, gw_err *err);

int gw_chain_calibrate(const gw_chain_params *p, const gw_chain_run_opts *o, double e_target,
                       double *constant, gw_err *err)
{
    if (!p || !o || !constant)
        return gw_err_set(err, GW_EINVAL, "gw_chain_calibrate: %s is NULL", !p ? "p" : !o ? "o" : "constant");
    if (p->damping != GW_DAMP_HUNT_CROSSLEY && p->damping != GW_DAMP_KUWABARA_KONO)
        return gw_err_set(err, GW_EINVAL, "restitution: choose a damping model (kk or hc) to calibrate");
    if (!(e_target > 0 && e_target < 1))
        return gw_err_set(err, GW_EINVAL, "restitution: target %g must be in (0, 1)", e_target);
    calib cb = {bead_params(p), bead_opts(o), e_target, GW_OK, err};
    calib_key k = key_of(&cb);
    double c = NAN;
    if (memo_find(&k, &c)) {
        *constant = c;
        return GW_OK;
    }
    int rc = calibrate(&cb, &c, err);
    if (rc == GW_OK) {
        memo_store(&k, c);
        *constant = c;
    }
    return rc;
}

static int calibrate(calib *cb, double *constant, gw_err *err)
{
    const gw_chain_params *p = &cb->bead;
    const double e_target = cb->target;
    /* small-damping estimates: HC e ~ 1 - alpha v; KK by dimensional analysis
     * gamma ~ (1 - e) sqrt(m k) (m v^2/k)^(-1/10)... use a time-scale guess */
    double lo = 0.0, hi = p->damping == GW_DAMP_HUNT_CROSSLEY
                              ? (1 - e_target) / p->v_imp
                              : (1 - e_target) * p->k * gw_chain_time_scale(p);
    /* the bracket stops at the largest accepted constant (gw_chain.h) */
    int hc = p->damping == GW_DAMP_HUNT_CROSSLEY;
    double cmax = hc ? GW_CHAIN_ALPHA_MAX : GW_CHAIN_GAMMA_MAX;
    hi = fmin(hi, cmax);
    double fhi = bead_restitution(hi, cb);
    for (int i = 0; i < 80 && cb->rc == GW_OK && fhi > 0 && hi < cmax; i++) {
        lo = hi;
        hi = fmin(2 * hi, cmax);
        fhi = bead_restitution(hi, cb);
    }
    if (cb->rc != GW_OK)
        return calib_failed(cb, err);
    if (fhi > 0 && hi >= cmax)
        return gw_err_set(err, GW_EINVAL, "restitution: e = %g at %g m/s needs %s above %g %s, the largest accepted "
                          "(an overdamped contact; raise restitution-v or restitution)",
                          e_target, p->v_imp, hc ? "alpha" : "gamma", cmax, hc ? "s/m" : "N s/m^1.5");
    if (!(fhi <= 0))
        return gw_err_set(err, GW_ESOLVER, "restitution: could not bracket e = %g", e_target);
    gsl_function F = {bead_restitution, cb};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s)
        return gw_err_set(err, GW_ENOMEM, "restitution: out of memory");
    gsl_error_handler_t *old = gw_gsl_quiet_begin();
    int status = gsl_root_fsolver_set(s, &F, lo, hi), it = 0;
    double root = NAN;
    do {
        status = gsl_root_fsolver_iterate(s);
        root = gsl_root_fsolver_root(s);
        double a = gsl_root_fsolver_x_lower(s), b = gsl_root_fsolver_x_upper(s);
        if (status == GSL_SUCCESS)
            status = gsl_root_test_interval(a, b, 0.0, 1e-10);
    } while (status == GSL_CONTINUE && ++it < 200 && cb->rc == GW_OK);
    gw_gsl_quiet_end(old);
    gsl_root_fsolver_free(s);
    if (cb->rc != GW_OK)
        return calib_failed(cb, err);
    if (status != GSL_SUCCESS)
        return gw_err_set(err, GW_ESOLVER, "restitution: Brent iteration failed (%s)", gsl_strerror(status));
    /* the root must give e: where e falls to the bead staying on the wall first
     * (an overdamped contact) the bracket closes on that jump, not on e */
    double e_root = bead_restitution(root, cb) + e_target;
    if (cb->rc != GW_OK)
        return calib_failed(cb, err);
    if (!(fabs(e_root - e_target) <= 1e-3 * e_target))
        return gw_err_set(err, GW_EINVAL, "restitution: e = %g at %g m/s is not reached: from %s = %g %s on the bead "
                          "stays on the wall (an overdamped contact) while e is still above it; raise restitution",
                          e_target, p->v_imp, hc ? "alpha" : "gamma", root, hc ? "s/m" : "N s/m^1.5");
    *constant = root;
    return GW_OK;
}
