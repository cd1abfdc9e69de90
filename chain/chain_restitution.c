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
 */
#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "gw_chain.h"
#include "gw_global.h"

typedef struct calib {
    gw_chain_params p;
    const gw_chain_run_opts *o;
    double target;
    int rc;
    gw_err *err;
} calib;

static double bead_restitution(double cst, void *ctx)
{
    calib *cb = ctx;
    gw_chain_params p = cb->p;
    p.n = 1;
    p.masses = NULL;
    p.kc = NULL;
    /* the contact damping is calibrated on the Hertz wall kwall alone */
    memset(&p.wall, 0, sizeof p.wall);
    memset(&p.sensor, 0, sizeof p.sensor);
    memset(&p.guide, 0, sizeof p.guide);
    if (p.damping == GW_DAMP_HUNT_CROSSLEY)
        p.alpha = cst;
    else
        p.gamma = cst;
    gw_chain *c = NULL;
    gw_chain_result r;
    memset(&r, 0, sizeof r);
    gw_chain_run_opts o = *cb->o;
    o.sample = NULL;
    o.front_threshold = 0;
    int rc = gw_chain_create(&p, &c, cb->err);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, &o, &r, cb->err);
    /* a bead still on the wall at t_max: the contact is overdamped before e
     * reaches the target (this ended as a failed run, exit 2 with "chain: bead 1
     * still on the wall", naming no input; taking it as e = 0 would calibrate
     * the constant at which the bead just stays within t_max, not e) */
    int stuck = rc == GW_ELIMIT;
    if (stuck)
        rc = GW_OK; /* e = 0 for the bracket; the root is checked below */
    double e = rc == GW_OK ? (stuck ? 0.0 : -r.final_v[0] / p.v_imp) : NAN;
    if (rc != GW_OK && cb->rc == GW_OK)
        cb->rc = rc;
    gw_chain_result_free(&r);
    gw_chain_free(c);
    return e - cb->target;
}

int gw_chain_calibrate(const gw_chain_params *p, const gw_chain_run_opts *o, double e_target,
                       double *constant, gw_err *err)
{
    if (p->damping != GW_DAMP_HUNT_CROSSLEY && p->damping != GW_DAMP_KUWABARA_KONO)
        return gw_err_set(err, GW_EINVAL, "restitution: choose a damping model (kk or hc) to calibrate");
    if (!(e_target > 0 && e_target < 1))
        return gw_err_set(err, GW_EINVAL, "restitution: target %g must be in (0, 1)", e_target);
    calib cb = {*p, o, e_target, GW_OK, err};
    /* small-damping estimates: HC e ~ 1 - alpha v; KK by dimensional analysis
     * gamma ~ (1 - e) sqrt(m k) (m v^2/k)^(-1/10)... use a time-scale guess */
    double lo = 0.0, hi = p->damping == GW_DAMP_HUNT_CROSSLEY
                              ? (1 - e_target) / p->v_imp
                              : (1 - e_target) * p->k * gw_chain_time_scale(p);
    /* the bracket stops at the largest accepted constant (gw_chain.h) */
    int hc = p->damping == GW_DAMP_HUNT_CROSSLEY;
    double cmax = hc ? GW_CHAIN_ALPHA_MAX : GW_CHAIN_GAMMA_MAX;
    hi = fmin(hi, cmax);
    double fhi = bead_restitution(hi, &cb);
    for (int i = 0; i < 80 && cb.rc == GW_OK && fhi > 0 && hi < cmax; i++) {
        lo = hi;
        hi = fmin(2 * hi, cmax);
        fhi = bead_restitution(hi, &cb);
    }
    if (cb.rc != GW_OK)
        return cb.rc;
    if (fhi > 0 && hi >= cmax)
        return gw_err_set(err, GW_EINVAL, "restitution: e = %g at %g m/s needs %s above %g %s, the largest accepted "
                          "(an overdamped contact; raise restitution-v or restitution)",
                          e_target, p->v_imp, hc ? "alpha" : "gamma", cmax, hc ? "s/m" : "N s/m^1.5");
    if (!(fhi <= 0))
        return gw_err_set(err, GW_ESOLVER, "restitution: could not bracket e = %g", e_target);
    gsl_function F = {bead_restitution, &cb};
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
    } while (status == GSL_CONTINUE && ++it < 200 && cb.rc == GW_OK);
    gw_gsl_quiet_end(old);
    gsl_root_fsolver_free(s);
    if (cb.rc != GW_OK)
        return cb.rc;
    if (status != GSL_SUCCESS)
        return gw_err_set(err, GW_ESOLVER, "restitution: Brent iteration failed (%s)", gsl_strerror(status));
    /* the root must give e: where e falls to the bead staying on the wall first
     * (an overdamped contact) the bracket closes on that jump, not on e */
    double e_root = bead_restitution(root, &cb) + e_target;
    if (cb.rc != GW_OK)
        return cb.rc;
    if (!(fabs(e_root - e_target) <= 1e-3 * e_target))
        return gw_err_set(err, GW_EINVAL, "restitution: e = %g at %g m/s is not reached: from %s = %g %s on the bead "
                          "stays on the wall (an overdamped contact) while e is still above it; raise restitution",
                          e_target, p->v_imp, hc ? "alpha" : "gamma", root, hc ? "s/m" : "N s/m^1.5");
    *constant = root;
    return GW_OK;
}
