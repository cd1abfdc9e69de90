/*
 * chain_collide.c: one column-wall collision and its observables (docs/physics.md 1.3,
 * 1.4).
 *
 * The integration stops at every root of the chain's event functions (wall
 * contact x_0 = 0, contact overlaps d_i = 0, the wall force's rate, v_0 undamped) and
 * restarts the solver there, so contact times are exact and the methods keep
 * their order between contact changes. Observables:
 *   f_max, tau_max  largest wall force and its time (its maxima are the falling
 *                   zeros of the force-rate root, chain_force_rate, with x_0 > 0)
 *   tau_n           last time bead 1 leaves the wall (x_0 -> 0 from above)
 *   period          mean spacing of successive wall-force maxima
 *   eps_eff (F.7), eps_col (F.30), E_rel/E_K at tau_n (F.20, mass-weighted)
 *   detach_t[i]     last opening of a contact of bead i (wall counts for bead 1)
 *   n_s             n minus the beads still in contact with bead 1 at tau_n
 * Units: SI.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"
#include "chain_model.h"

gw_chain_run_opts gw_chain_run_opts_default(void)
{
    gw_chain_run_opts o;
    memset(&o, 0, sizeof o);
    o.solver = gw_solver_cvode;
    o.sp = gw_solver_params_default();
    return o;
}

/* Measured (bench_falcon_accuracy, RK4 with events as roots, dt = T_c/M, against
 * CVODE BDF at 1e-12, N = 1..40 at three v_imp): the worst relative error, on
 * F_max, is 4.0e-6 at M = 16 and falls as M^-2.5 (7.2e-7 at 32, 1.3e-7 at 64),
 * not M^-4: every contact closing restarts the method on the d^(3/2) force, whose
 * expansion is not smooth at the restart. tau_N errors are smaller. A factor 2
 * margin covers the scatter between N. */
int gw_chain_rk4_steps_per_tc(double rel_acc)
{
    if (!(rel_acc >= GW_CHAIN_RK4_ACCURACY_MIN && rel_acc <= GW_CHAIN_RK4_ACCURACY_MAX))
        return 0;
    double m = 16.0 * pow(4.0e-6 / (0.5 * rel_acc), 1.0 / 2.5);
    return m < 16 ? 16 : (int)ceil(m);
}

int gw_chain_rk4_study_covers(const gw_chain_params *p, long n_max)
{
    int general = p->wall.layer || p->wall.yield_pressure > 0 || p->wall.loss > 0 || p->sensor.mass > 0 ||
                  p->guide.coulomb > 0 || p->guide.viscous > 0;
    return !(p->damping != GW_DAMP_NONE || p->gravity != 0 || n_max > 40 || general);
}

int gw_chain_rk4_study_apply(gw_chain_run_opts *run, const gw_chain_params *p, double rel_acc, double vmax,
                             int keep_dt_out)
{
    int m = gw_chain_rk4_steps_per_tc(rel_acc);
    if (m <= 0)
        return 0;
    run->solver = gw_solver_rk4;
    run->sp.method = GW_METHOD_DEFAULT;
    run->steps_per_tc = m;
    if (!keep_dt_out)
        run->dt_out = gw_chain_tau1(p->mass, p->kwall, vmax) / 10;
    return m;
}

typedef struct run_state {
    const gw_chain *c;
    const gw_chain_run_opts *o;
    gw_chain_result *r;
    int n;
    char *closed;    /* [n]: 0 = wall, 1+i = contact i */
    double *last_open;
    double dtol;     /* overlap below which a contact counts as open, m */
    double v_scale;  /* the states' velocity scale (chain_speed_scale), m/s */
    double vtol_tol; /* the solver tolerances' floor of resolved_speed, relative */
    double t_first_max, t_last_max;
    double t_prev, f_prev;   /* previous observation (wall force) */
    double *fc_prev;         /* [3n] contact forces, overlaps and their rates at the
                                previous observation */
    double t_max;            /* the run's time limit, s */
    double t_expect;         /* the collision's expected length, s (collide_plan) */
    const gw_solver *s;      /* for its step count */
    const gw_solver_type *type; /* the backend (the blow-up's advice) */
    double wg;               /* the largest work gravity has done so far, J */
    double t_sampled;        /* time of the last row given to o->sample (-inf: none) */
    int flight_cut;          /* t_max falls in bead 1's flight, its return the
                                caller's next impact (chain_collide_flight_cut) */
} run_state;

/* Steps a whole run may take: the plan bounds them at 1e8 over the expected
 * length, and a run that goes on past it (a default t_max is 20 expected lengths:
 * an overdamped bead held on the wall under rk4 ran 5e8 steps) stops here. */
#define CHAIN_RUN_STEPS_MAX 2e8

/* Elastic force of contact k (0 = wall, k = contact between beads k-1, k). */
static double contact_force(const run_state *st, const double *y, int k)
{
    if (k == 0)
        return gw_chain_wall_contact_force(st->c, y);
    double d = y[2 * k] - y[2 * k - 2];
    const gw_chain_params *p = gw_chain_get_params(st->c);
    return d > 0 ? (p->kc ? p->kc[k - 1] : p->k) * d * sqrt(d) : 0.0;
}

/* Where the cubic Hermite interpolant of an overlap over one observation
 * interval (d0, rate v0 at its start; d1, v1 at its end; h its length) first
 * reaches target, as a fraction of the interval: d0 < target <= d1. */
static double hermite_cross(double h, double d0, double v0, double d1, double v1, double target)
{
    double lo = 0, hi = 1;
    for (int it = 0; it < 60 && hi - lo > 1e-15; it++) {
        double s = 0.5 * (lo + hi), s2 = s * s, s3 = s2 * s;
        double p = (2 * s3 - 3 * s2 + 1) * d0 + (s3 - 2 * s2 + s) * h * v0 + (-2 * s3 + 3 * s2) * d1 +
                   (s3 - s2) * h * v1;
        if (p >= target)
            hi = s;
        else
            lo = s;
    }
    return hi;
}

/* First crossing of the front threshold by each contact. Between beads the
 * overlap d and its rate are in the state at both observations, so the
 * crossing of d^(3/2) k = threshold is found on their cubic Hermite
 * interpolant (error O(h^4): v_front moved by 2.2e-6 between the default
 * sampling and --dt-out 1e-7 with a linear interpolation of the force, by
 * 1e-10 with this); the wall contact (any wall law) by linear interpolation of
 * its force. */
static void track_front(run_state *st, double t, const double *y)
{
    double thr = st->o->front_threshold;
    const gw_chain_params *p = gw_chain_get_params(st->c);
    double *d_prev = st->fc_prev + st->n, *v_prev = st->fc_prev + 2 * st->n;
    for (int k = 0; k < st->n; k++) {
        double f = contact_force(st, y, k);
        double d = k ? y[2 * k] - y[2 * k - 2] : 0, v = k ? y[2 * k + 1] - y[2 * k - 1] : 0;
        if (isnan(st->r->front_t[k]) && f >= thr) {
            double f0 = st->fc_prev[k], h = t - st->t_prev;
            if (!(f > f0 && h > 0))
                st->r->front_t[k] = t;
            else if (k == 0)
                st->r->front_t[k] = st->t_prev + (thr - f0) / (f - f0) * h;
            else {
                double d_thr = cbrt(thr / (p->kc ? p->kc[k - 1] : p->k));
                d_thr *= d_thr; /* (thr/k)^(2/3) */
                st->r->front_t[k] = st->t_prev + hermite_cross(h, d_prev[k], v_prev[k], d, v, d_thr) * h;
            }
        }
        st->fc_prev[k] = f;
        d_prev[k] = d;
        v_prev[k] = v;
    }
}

/* Momentum toward the wall of the beads and the sensor body, kg m/s. */
static double momentum(const gw_chain *c, const double *y)
{
    double q = 0;
    for (int i = 0; i < gw_chain_get_params(c)->n; i++)
        q += gw_chain_bead_mass(c, i) * y[2 * i + 1];
    long is = gw_chain_sensor_index(c);
    if (is >= 0)
        q += gw_chain_get_params(c)->sensor.mass * y[is + 1];
    return q;
}

/* The largest overlap of the contacts in state y (the wall's as its gap,
 * gw_chain_wall_gap) over the bead radius, kept in the result. */
static void overlap_track(run_state *st, const double *y)
{
    const double radius = gw_chain_get_params(st->c)->radius;
    double d = gw_chain_wall_gap(st->c, y);
    for (int k = 1; k < st->n; k++)
        d = fmax(d, y[2 * k] - y[2 * k - 2]);
    if (radius > 0 && d / radius > st->r->overlap_max_rel)
        st->r->overlap_max_rel = d / radius;
}

static int observe(run_state *st, double t, const double *y, int is_event)
{
    gw_chain_result *r = st->r;
    double f = gw_chain_wall_force(st->c, y);
    if (t > st->t_prev) /* trapezoidal impulse on the wall */
        r->impulse += 0.5 * (f + st->f_prev) * (t - st->t_prev);
    if (r->front_t)
        track_front(st, t, y);
    st->t_prev = t;
    st->f_prev = f;
    if (f > r->f_max) {
        r->f_max = f;
        r->tau_max = t;
    }
    overlap_track(st, y);
    gw_chain_energy e;
    gw_chain_energy_of(st->c, y, &e);
    double err = chain_energy_rel_error(st->c, &e, r->e0, &st->wg);
    if (err > r->energy_error)
        r->energy_error = err;
    /* an event found exactly at an output time is observed twice, by the root
     * and by the output, in the same state: one row (a drop's trace held the
     * row at 2.51e-4 s twice, and dF/dt from the files divided by zero) */
    if (st->o->sample && t != st->t_sampled) {
        st->t_sampled = t;
        return st->o->sample(st->o->sample_ctx, t, y, f, is_event);
    }
    return 0;
}

/* Bring the contact flags in line with the geometry. The root finders of CVODE
 * and ARKode treat a function that is exactly zero at a restart as inactive and
 * re-activate it without a report when it moves away from zero, so a contact
 * that opens with d = 0 exactly and closes again in the next step is not
 * reported; the same holds for a contact touched within a single step. Such
 * transitions are taken from the state here (their times are then only known
 * to the sampling interval) and counted in missed_events. */
static void reconcile(run_state *st, double t, const double *y)
{
    for (int k = 0; k < st->n; k++) {
        double d = k == 0 ? gw_chain_wall_gap(st->c, y) : y[2 * k] - y[2 * k - 2];
        if (!st->closed[k] && d > st->dtol) {
            st->closed[k] = 1;
            st->r->missed_events++;
            if (k == 0)
                st->r->wall_contacts++;
        } else if (st->closed[k] && d < -st->dtol) {
            st->closed[k] = 0;
            st->last_open[k] = t;
            st->r->missed_events++;
        }
    }
}

/* The relative speed of two beads below which the integration does not
 * resolve it, m/s. Beads that leave together (eps near 1, two equal beads on a
 * stiff wall) separate or close at the integration's error, and the sign of
 * that difference changed with the stop times of the sampling: --n 2 --k 1e3
 * --kwall 1e14 --t-max 0.02 ended at tau_N with --dt-out 7e-9 and ran to t-max
 * "still closing" with 6.7e-9 (beads at -0.300000000306 and -0.300000000303
 * m/s). The velocities' error shows in the energy's: over 4 samplings times
 * cvode bdf at rtol = atol = 1e-12, 1e-10, 1e-8, 1e-6, adams, arkode and rk4,
 * the pair's final relative speed was at most 3.1 times the run's relative
 * energy error times the speed scale (arkode at 1e-12), and at most 64 times
 * max(rtol, atol) (bdf at 1e-10). A closing pair is followed from 30 times the
 * former or 1e3 times the latter (cvode, arkode: rk4's tolerances are not its
 * error), whichever is larger, and always from 1e-3 of the speed scale: a
 * column whose beads meet again closes at a fair part of v_imp (a light bead
 * above a heavy one: --radii 1e-2,1e-3, 0.55 v_imp). */
static double resolved_speed(const run_state *st)
{
    return st->v_scale * fmin(1e-3, fmax(30.0 * st->r->energy_error, st->vtol_tol));
}

/* Contact k (between beads k-1 and k, k >= 1) still acting at state y: closed
 * (its flag, or its overlap above dtol) or its beads closing, and the relative
 * speed it can still take up or give back, from its approach w and its stored
 * energy E_c = 2/5 k d^(5/2) (w^2 + 2 E_c / mu, mu the pair's reduced mass),
 * resolved (above vtol). Below it, nothing the pair still does changes a
 * velocity by more than the integration's error. */
static int contact_acting(const run_state *st, const double *y, int k, double vtol)
{
    const double d = y[2 * k] - y[2 * k - 2], w = y[2 * k + 1] - y[2 * k - 1];
    if (!st->closed[k] && !(d > st->dtol) && !(w > 0))
        return 0;
    const double m1 = gw_chain_bead_mass(st->c, k - 1), m2 = gw_chain_bead_mass(st->c, k),
                 kc = st->c->kc[k - 1], ec = d > 0 ? 0.4 * kc * d * d * sqrt(d) : 0.0,
                 wc = w > 0 ? w : 0.0;
    return wc * wc + 2.0 * ec * (m1 + m2) / (m1 * m2) > vtol * vtol;
}

static void on_wall_open(run_state *st, double t, const double *y)
{
    gw_chain_result *r = st->r;
    const int n = st->n;
    r->tau_n = t;
    /* the cluster: the contacts above bead 1 that still act (contact_acting; a
     * contact held at the integration's error is open, whichever way its
     * flag was left) */
    int cl = 1;
    const double vtol = resolved_speed(st);
    while (cl < n && st->closed[cl] && contact_acting(st, y, cl, vtol))
        cl++;
    r->cluster = cl;
    r->n_s = n - cl;
    double mv = 0, msum = 0;
    for (int i = 0; i < n; i++) {
        double m = gw_chain_bead_mass(st->c, i);
        r->v_tau_n[i] = y[2 * i + 1];
        mv += m * y[2 * i + 1];
        msum += m;
    }
    double vg = mv / msum, erel = 0, ek = 0;
    for (int i = 0; i < n; i++) {
        double m = gw_chain_bead_mass(st->c, i), v = y[2 * i + 1];
        erel += m * (v - vg) * (v - vg);
        ek += m * v * v;
    }
    r->e_rel_over_e_k = ek > 0 ? erel / ek : 0.0;
}

/* Handle the roots reported at time t: contacts first, then the state check,
 * then the wall, so the cluster at tau_N sees up-to-date contact flags. */
static void on_roots(run_state *st, double t, const double *y, const int *roots)
{
    gw_chain_result *r = st->r;
    const int n = st->n;
    int wall_opened = 0;
    for (int k = n - 1; k >= 0; k--) {
        if (roots[k] == 0)
            continue;
        r->n_events++;
        int open = roots[k] < 0;
        if (open && st->closed[k]) {
            st->last_open[k] = t;
            st->closed[k] = 0;
            wall_opened |= k == 0;
        } else if (!open && !st->closed[k]) {
            st->closed[k] = 1;
            if (k == 0)
                r->wall_contacts++;
        }
    }
    int wall_was_closed = st->closed[0];
    reconcile(st, t, y);
    if (wall_opened || (wall_was_closed && !st->closed[0]))
        on_wall_open(st, t, y);
    int im = gw_chain_force_max_root(st->c); /* dF/dt falls through 0: force maximum */
    if (roots[im] < 0 && gw_chain_wall_gap(st->c, y) > 0 && gw_chain_wall_force(st->c, y) > 0) {
        r->n_events++;
        if (r->n_maxima == 0)
            st->t_first_max = t;
        st->t_last_max = t;
        r->n_maxima++;
    }
}

/* Bead 1 off the wall and separating from it; with a sensor body (which
 * oscillates on its spring, x_s between -A and A, A^2 = x_s^2 + m_s v_s^2 / k_s,
 * A falling with its damping) also moving away and beyond its reach. */
/* What keeps the wall's side of the run from its end at state y: NULL when
 * nothing does (bead 1 off the wall, separating and beyond a sensor body's
 * reach, the reading no longer rising), else the reason, as the warnings say it. */
static const char *wall_pending(const run_state *st, const double *y, double dtol)
{
    /* a run cut in bead 1's flight whose return is the caller's next impact
     * (chain_collide_flight_cut): bead 1 off the wall is done whatever its
     * velocity. The drop cuts its first collision half way through that
     * flight, where bead 1 turns: its velocity there is zero but for the
     * integration's error, +4.3e-11 m/s (cvode at 1e-12, "still at the wall")
     * or -1.3e-12 (1e-13, done) for N = 40 at h = 5.1 mm. */
    int moving_in = !st->flight_cut && gw_chain_wall_gap_rate(st->c, y) > 0;
    if (st->closed[0] || moving_in || gw_chain_wall_gap(st->c, y) > dtol)
        return "bead 1 still at the wall";
    long is = gw_chain_sensor_index(st->c);
    if (is >= 0) {
        const gw_chain_sensor *s = &gw_chain_get_params(st->c)->sensor;
        double xs = y[is], vs = y[is + 1], a = sqrt(xs * xs + s->mass * vs * vs / s->stiffness);
        if (y[1] > 0 || y[0] > -a)
            return "bead 1 off the wall but within the sensor body's swing";
        /* the reading k_s x_s (+ c_s v_s) still rising: its largest value, F_max,
         * comes after bead 1 left (a 1000 kg sensor on 1e12 N/m ended at 20.7 N,
         * rising, of a peak near J omega = 40 N) */
        if (vs > 0)
            return "bead 1 left the wall, the sensor's reading still rising";
    }
    return NULL;
}

static int wall_finished(const run_state *st, const double *y, double dtol)
{
    return wall_pending(st, y, dtol) == NULL;
}

/* The wall's side done (wall_pending), and every contact between beads open
 * and not closing (by its events and by its geometry, so that a contact the
 * root finder missed still counts) at a resolved speed (contact_acting). */
static int finished(const run_state *st, const double *y, double dtol)
{
    if (!wall_finished(st, y, dtol))
        return 0;
    const double vtol = resolved_speed(st);
    for (int k = 1; k < st->n; k++)
        if (contact_acting(st, y, k, vtol))
            return 0;
    return 1;
}

static void finish_result(run_state *st, const double *y)
{
    gw_chain_result *r = st->r;
    const int n = st->n;
    double p_f = 0, p_i = 0, e_f = 0, e_i = 0;
    double v0 = gw_chain_get_params(st->c)->v_imp;
    for (int i = 0; i < n; i++) {
        double m = gw_chain_bead_mass(st->c, i), v = y[2 * i + 1];
        r->final_v[i] = v;
        p_f += m * v;
        p_i += m * v0;
        e_f += m * v * v;
        e_i += m * v0 * v0;
        double a = i > 0 ? st->last_open[i] : st->last_open[0];      /* below */
        double b = i < n - 1 ? st->last_open[i + 1] : -INFINITY;    /* above */
        double d = fmax(a, b);
        r->detach_t[i] = isfinite(d) ? d : NAN;
    }
    r->eps_eff = -p_f / p_i;
    r->eps_col = sqrt(e_f / e_i);
    r->period = r->n_maxima >= 2 ? (st->t_last_max - st->t_first_max) / (r->n_maxima - 1)
                                 : NAN;
}

/* A sample callback's answer as the drive's: a stop (> 0) ends the run without
 * an error, a failure (< 0: the trace's growth out of memory) is the run's. It
 * was taken for a stop, so a trace that could not grow ended the run as if it
 * were complete: exit 0 with F_max 0 and the beads' initial velocities as their
 * final ones (tests/test_alloc_failure.sh). */
static int sampled(int sr, int go_on, double t, gw_err *err)
{
    if (sr < 0)
        return gw_err_set(err, sr, "chain: the trace at t = %.9g s: %s", t, gw_strerror(sr));
    return sr > 0 ? GW_DRIVE_STOP : go_on;
}

/* The run's hooks (gw_solver_drive): at a root the contact flags and the
 * observation; at an output time the flags brought in line with the geometry
 * (reconcile) and the observation; after either the energy monitor and the end. */
static int collide_root(void *ctx, double t, double *y, const int *roots, gw_err *err)
{
    run_state *st = ctx;
    on_roots(st, t, y, roots);
    return sampled(observe(st, t, y, 1), GW_DRIVE_RESET, t, err);
}

static int collide_output(void *ctx, double t, double *y, gw_err *err)
{
    run_state *st = ctx;
    int wall_closed = st->closed[0];
    reconcile(st, t, y);
    if (wall_closed && !st->closed[0])
        on_wall_open(st, t, y);
    return sampled(observe(st, t, y, 0), GW_DRIVE_ON, t, err);
}

static int collide_after(void *ctx, double t, const double *y, gw_err *err)
{
    run_state *st = ctx;
    gw_chain_result *r = st->r;
    if (chain_blown_up(st->c, y, r->energy_error, st->type, "chain", t, err) != GW_OK)
        return GW_ESOLVER;
    if (st->s) {
        gw_solver_stats ss;
        gw_solver_get_stats(st->s, &ss);
        if (ss.steps > CHAIN_RUN_STEPS_MAX)
            return gw_err_set(err, GW_ELIMIT, "chain: %ld steps taken by t = %.9g s and the collision has not "
                              "ended (expected by about %.3g s); at most %.0e a run: lower t-max, or use cvode "
                              "(it lengthens its step where nothing moves fast)", ss.steps, t, st->t_expect, CHAIN_RUN_STEPS_MAX);
    }
    if (st->o->energy_tol > 0 && r->energy_error > st->o->energy_tol)
        return gw_err_set(err, GW_EENERGY, "chain: relative energy error %.3g exceeds the limit %.3g at t = %.9g s",
                          r->energy_error, st->o->energy_tol, t);
    if (finished(st, y, st->dtol)) {
        r->converged = 1;
        return GW_DRIVE_STOP;
    }
    if (t >= st->t_max) {
        if (!isfinite(r->tau_n))
            return gw_err_set(err, GW_ELIMIT, "chain: bead 1 still on the wall at t_max = %.6g s", st->t_max);
        return GW_DRIVE_STOP;
    }
    return GW_DRIVE_ON;
}

/* 1e8 steps: minutes at n = 3; the default RK4 step T_c/400 makes about 800 n
 * over a collision, so columns up to 1.25e5 beads (a day of CPU already) */
int chain_steps_check(const gw_solver_type *type, const gw_solver_params *sp, const gw_solver_params *given,
                      double t_len, const char *over, gw_err *err)
{
    const double max_steps_run = 1e8;
    const double step = type == gw_solver_rk4 ? fmin(sp->dt, sp->dt_max) : sp->dt_max;
    const int is_dt = type == gw_solver_rk4 && sp->dt <= sp->dt_max;
    /* a step the run chose itself resolves the stiffest contact (or the sensor
     * body's oscillation): "raise it" would be wrong advice there */
    const int chosen = is_dt ? !(given->dt > 0) : !(given->dt_max > 0);
    if (!(t_len / step <= max_steps_run))
        return gw_err_set(err, GW_EINVAL, "%s: a step of %g s needs about %.3g steps over %s (about %.3g s); "
                          "at most %.0e: %s", is_dt ? "dt" : "dt-max", step, t_len / step, over, t_len, max_steps_run,
                          !chosen ? "raise it"
                          : is_dt ? "the default step resolves the stiffest contact or the sensor body's oscillation "
                                    "(a longer one loses the run): use cvode or arkode"
                                  : "the default largest step is a quarter of the shortest contact (a longer one can "
                                    "step over a contact): fewer beads or a shorter run");
    return GW_OK;
}

int chain_sensor_steps_check(const gw_chain_params *p, const gw_solver_type *type, double t_len, const char *over,
                             gw_err *err)
{
    if (!(p->sensor.mass > 0 && p->sensor.stiffness > 0) || type == gw_solver_rk4)
        return GW_OK; /* rk4: its step is bounded by chain_steps_check */
    const double omega = sqrt(p->sensor.stiffness / p->sensor.mass), steps = 2.0 * omega * t_len;
    if (!(steps <= 1e8))
        return gw_err_set(err, GW_EINVAL, "sensor-stiffness: a sensor body oscillating at %.3g rad/s (sqrt(k_s/M)) "
                          "needs about %.3g steps over %s (about %.3g s; 2 a radian at least, measured 2-9); at "
                          "most 1e+08: a softer or heavier sensor body, or a shorter run", omega, steps, over, t_len);
    return GW_OK;
}

/* Bytes a run of column p allocates, by what gw_chain_create, gw_chain_collide
 * (or the drop) and the backend hold: the model's and the result's per-bead
 * arrays (about 14 doubles a bead; the force-rate root's scratch of 2 dim doubles,
 * touched only by the general model's central difference, is within the margin
 * the measured sizes below leave), the solver's vectors over the state (dim =
 * 2n + a few: rk4 10 of them with its root values, cvode and arkode about 24 with
 * their histories and stages, arkode's implicit methods 34) and, for the implicit
 * methods (cvode bdf, arkode dirk and imex), three band matrices of dim x (smu +
 * ml + 1) doubles (the Jacobian, its saved copy and the factor workspace). The
 * band is 2 above and 3 below the diagonal, except with a sensor body or a wall
 * with its own states (plastic, viscoelastic, layer): those states couple every
 * bead, the Jacobian is full (dim x (2 dim - 1)), and memory grows as n^2.
 * Measured peak resident sizes at n = 1e6 (t-max 1e-9 s): 218 B a bead for rk4,
 * 637 cvode bdf, 295 adams, 381 arkode erk, 810 dirk; 200 MB at n = 1000 with a
 * sensor body (cvode). The estimate is an upper bound for each. */
static int implicit_method(const gw_solver_type *t, int method)
{
    const char *used = gw_solver_method_used(t, method);
    return t != gw_solver_rk4 && (strcmp(used, "bdf") == 0 || strcmp(used, "dirk") == 0 || strcmp(used, "imex") == 0);
}

static double memory_bytes(const gw_chain_params *p, const gw_solver_type *type, int method)
{
    const double n = p->n;
    const int full = p->sensor.mass > 0 || p->wall.layer || p->wall.yield_pressure > 0 || p->wall.loss > 0;
    const double dim = 2 * n + 8;
    const gw_solver_type *t = type ? type : gw_solver_cvode;
    const int implicit = implicit_method(t, method);
    double vectors = t == gw_solver_rk4 ? 10 : implicit && t != gw_solver_cvode ? 34 : 24;
    double bytes = 8 * (14 * n + vectors * dim);
    if (implicit) {
        double ldim = full ? 2 * dim - 1 : fmin(dim - 1, 5) + 3 + 1;
        bytes += 3 * 8 * dim * ldim + 8 * dim;
    }
    return bytes;
}

/* The most beads within GW_CHAIN_MEMORY_MAX (memory_bytes grows with n). */
static long memory_n_ok(const gw_chain_params *p, const gw_solver_type *type, int method)
{
    gw_chain_params q = *p;
    long lo = 0, hi = (long)p->n + 1;
    while (hi - lo > 1) {
        long mid = lo + (hi - lo) / 2;
        q.n = (int)mid;
        if (memory_bytes(&q, type, method) <= GW_CHAIN_MEMORY_MAX)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

int gw_chain_memory_check(const gw_chain_params *p, const gw_solver_type *type, int method, gw_err *err)
{
    const double limit = GW_CHAIN_MEMORY_MAX;
    double need = memory_bytes(p, type, method);
    if (need <= limit)
        return GW_OK;
    long lo = memory_n_ok(p, type, method);
    const gw_solver_type *t = type ? type : gw_solver_cvode;
    const int full = p->sensor.mass > 0 || p->wall.layer || p->wall.yield_pressure > 0 || p->wall.loss > 0;
    return gw_err_set(err, GW_EINVAL,
                      "n: a column of %d beads needs about %.3g GB for its state and the %s (%s) solver's workspace%s, "
                      "above the %.3g GB limit: at most %ld beads here", p->n, need / 1e9, gw_solver_type_name(t),
                      gw_solver_method_used(t, method),
                      full && implicit_method(t, method)
                          ? " (a full Jacobian: the sensor body or the wall's own states couple every bead; rk4 or "
                            "arkode erk need none)"
                          : "",
                      limit / 1e9, lo);
}

/* What a collision of p with o will run with (t_max, dt_out, the steps), and the
 * bounds on its steps, memory, samples and stored trace, checked before anything
 * is allocated, in that order: at the defaults the bound that trips at the fewest
 * beads is named (rk4: steps from 1.25e5 beads, memory from 7.9e6, samples from
 * 7e6; cvode: memory from 2.3e6, samples from 7e6, steps from 1.3e7). */
/* v rounded down to two significant digits (a suggested bound that passes). */
static double floor_2digits(double v)
{
    const double p = pow(10, floor(log10(v)) - 1);
    return floor(v / p) * p;
}

typedef struct collide_plan {
    double tc, tau1, t_max, dt_out, t_expect;
    gw_solver_params sp;
    const gw_solver_type *type;
} collide_plan;

/* A light bead held by heavy ones rings on its contacts all the time they
 * hold it, and cvode and arkode follow every oscillation: the run stops and
 * restarts at each maximum and minimum of the wall force, and BDF starts again
 * at order 1 there. Measured (cvode bdf at rtol 1e-12, --n 2 --radii 1e-3,X):
 * 258 to 266 steps per oscillation of chain_ring_period over the expected
 * length at X = 1e-2, 3e-2, 0.1 and 1 (1.7e4 to 1.7e7 steps); fewer at looser
 * tolerances, as (tol / 1e-12)^-0.11 (99 at 1e-8, 58 at 1e-6), adams 113 and
 * arkode's erk 133 at 1e-12. --radii 1e-3,1 took 17.1 million steps and 45 s
 * of CPU (2.6 us a step). The plan bounds these steps times the beads at 2e7
 * (about 30 s of CPU) when the ringing is not the column's own: more than
 * RING_RATIO_MAX oscillations per bead transit (2n + 1 of them over the
 * collision's expected length, whatever the run's length t_len). Equal beads
 * would ring 0.37 to 0.61 times per transit (n = 1 to 1000, gravity, sheets),
 * mixed radii of ratio 2 to 20 up to 13; a bead of 1e-3 m under 3e-2, 0.1 and
 * 1 m 67, 407 and 12900 times, 3e-5 m between two of 4e-3 m 564 (within the
 * bound: 3.1e6 bead-steps). Equal beads are not checked: a wall far
 * stiffer than their contacts (--n 10 --k 1e3 --kwall 1e14) has bead 1 bounce
 * between the two (9 wall contacts, 1.26e6 steps), not held ringing. rk4's
 * steps are the fixed step's, bounded by chain_steps_check. The drop does not
 * call it: its calibration is not this one (drop --n 2 --radii 1e-3,1 took
 * 929331 steps over its 10 ms, 5.8 s, where this would estimate 1.4e7). */
#define RING_RATIO_MAX 100.0
#define RING_WORK_MAX 2e7
#define RING_STEPS_PER_OSC 260.0

int chain_ring_check(const gw_chain_params *p, const gw_solver_type *type, const gw_solver_params *sp,
                     double t_len, double t_col, const char *over, gw_err *err)
{
    if (type == gw_solver_rk4 || !p->masses)
        return GW_OK;
    /* the run passes the chain's own masses (gw_chain_create fills them for
     * equal beads too): --n 10 --k 1e3 --kwall 1e14 --dt-out 1e-7 was refused
     * at the run as "bead 1 is 1 times lighter than bead 1" */
    int equal = 1;
    for (int i = 1; i < p->n && equal; i++)
        equal = p->masses[i] == p->masses[0];
    if (equal)
        return GW_OK;
    int f = 0;
    const double n = p->n, tr = chain_ring_period(p, &f), osc = t_len / tr;
    double tol = fmax(sp->rtol, sp->atol);
    if (!(tol > 0))
        tol = 1e-12;
    const double per_osc = RING_STEPS_PER_OSC * pow(fmin(tol, 1.0) / 1e-12, -0.11);
    const double work = n * per_osc * osc;
    /* the ringing against the column's own scale: its collision's expected
     * length t_col (whatever t_len) */
    if (!(t_col / tr > RING_RATIO_MAX * (2 * n + 1)) || !(work > RING_WORK_MAX))
        return GW_OK;
    int h = 0;
    for (int i = 1; i < p->n; i++)
        if (p->masses[i] > p->masses[h])
            h = i;
    return gw_err_set(err, GW_EINVAL,
                      "radii: bead %d (%.3g kg) is %.3g times lighter than bead %d (%.3g kg) and rings every %.3g s "
                      "while the heavy beads hold it, about %.3g oscillations over %s (about %.3g s): about %.3g "
                      "bead-steps of %s (%.0f steps an oscillation), above the bound %.0e (about 30 s): use rk4 (its "
                      "fixed step is bounded on its own) or closer radii",
                      f + 1, p->masses[f], p->masses[h] / p->masses[f], h + 1, p->masses[h], tr, osc, over, t_len,
                      work, gw_solver_type_name(type), per_osc, RING_WORK_MAX);
}

/* A column that gravity holds on the wall: when gravity takes back the impact
 * speed within the collision's expected length (g t_e > v_imp), the beads
 * leaving the wall fall back before the column has separated, and the run goes
 * on to t_max with bead 1 bouncing on the wall and the top contacts chattering,
 * cvode restarting at each of their events. Measured (steel, cvode at 1e-12,
 * default t-max and dt-out): the collision ended at g t_e / v_imp = 0.009 to
 * 0.15 (n = 10, 40; g = 9.81, 100; v_imp 0.3 to 0.03) and never at 0.35 and
 * above. The cost of such a run is its samples and steps, each O(n): 0.4 to
 * 1.6 us a bead-sample at the default sampling tau_1/200 (steps 1 to 3.4 per
 * sample: n = 300, g = 100, v_imp = 1e-3 ran 16715 steps and 17189 samples in
 * 1.9 s up to t = 3e-3 s, about 100 s to its default t-max of 0.152 s; n = 40,
 * g = 100, v_imp = 1e-3 407013 steps, 126228 samples, 8 s; profiled again:
 * 7728 contact events and 446 force maxima over its 29 ms, about 200 a
 * contact, each a real collision of beads bouncing under their weight (18 at
 * a relative speed below 1e-9 m/s, none within 1e-7 s of the contact's
 * previous event: no chattering), each a restart of BDF at order 1, about 95
 * steps a restart, 780k steps, half the CPU in the band LU; adams took 1.2 s,
 * arkode's erk 0.6 s, bdf 5.1 s). The steps follow
 * the contacts, not the sampling: the estimate counts samples at the finer of
 * dt-out and tau_1/200, times the beads, over t_max, bounded at 1e7 (about 4
 * to 16 s) whatever t_max was given. */
#define HELD_WORK_MAX 1e7

/* The longest t_max the bound admits for a held column (INFINITY when gravity
 * does not hold it), rounded down to two digits. */
static double held_t_lim(const gw_chain_params *p, double t_col, double tau1, double dt_out)
{
    if (!(p->gravity > 0) || !(p->gravity * t_col > p->v_imp))
        return INFINITY;
    return floor_2digits(HELD_WORK_MAX / p->n * fmin(dt_out, tau1 / 200.0));
}

int chain_held_check(const gw_chain_params *p, double t_max, double t_col, double tau1, double dt_out, gw_err *err)
{
    if (!isfinite(held_t_lim(p, t_col, tau1, dt_out)))
        return GW_OK;
    const double dt = fmin(dt_out, tau1 / 200.0), samples = t_max / dt, work = p->n * samples;
    if (!(work > HELD_WORK_MAX))
        return GW_OK;
    return gw_err_set(err, GW_EINVAL,
                      "gravity: %g m/s^2 takes back the impact speed (vimp %g m/s) in %.3g s, within the collision's "
                      "expected %.3g s: the column stays on the wall, bouncing on it, and the run goes on to t-max "
                      "%.3g s, about %.3g samples of %.3g s times %d beads, above the bound %.0e (about 15 s): lower "
                      "t-max to %g s or less, raise vimp or lower gravity",
                      p->gravity, p->v_imp, p->v_imp / p->gravity, t_col, t_max, samples, dt, p->n, HELD_WORK_MAX,
                      held_t_lim(p, t_col, tau1, dt_out));
}

/* Every sample costs a fixed part (the drive's stop, the root functions, the
 * observation) besides its O(n): about 0.6 us at n = 2. The default dt-out,
 * tau_1/200 of bead 1 on the wall, gives about 185 samples per bead transit of
 * an ordinary column (200 over the wall contact, 2n + 1 transits of 2 T_c);
 * a wall far stiffer than the bead contacts makes tau_1 tiny against the
 * column's own length (--n 2 --k 1e3 --kwall 1e14: tau_1 = 0.87 us over a
 * collision of 28 ms, dt-out 4.4 ns, 6.4e6 samples). Sampling finer than 1e4
 * a bead transit and more than 3e6 samples over the collision (about 2 s at
 * n = 2; rk4 on --radii 1e-3,1, 1.8e6 samples, ran in 1.6 s) is refused, naming dt-out and the interval that passes; the large
 * counts of long columns (200 + 370 n at the defaults) come from their length,
 * not their sampling, and stay bounded by the plan's 1e9. */
#define SAMPLING_MAX 3e6
#define SAMPLING_PER_TRANSIT_MAX 1e4

int chain_sampling_check(int n, double t_expect, double dt_out, int given, gw_err *err)
{
    const double samples = t_expect / dt_out, transits = 2.0 * n + 1;
    if (!(samples > SAMPLING_MAX) || !(samples / transits > SAMPLING_PER_TRANSIT_MAX))
        return GW_OK;
    /* the interval that passes, rounded up to two digits */
    const double lim = t_expect / fmax(SAMPLING_MAX, SAMPLING_PER_TRANSIT_MAX * transits),
                 q = pow(10, floor(log10(lim)) - 1);
    return gw_err_set(err, GW_EINVAL,
                      "dt-out: %s%g s gives about %.3g samples over the collision (about %.3g s), %.3g per bead "
                      "transit of %d beads; at most %.0e when above %.0e a transit: raise dt-out to %.2g s or more%s",
                      given ? "" : "the default tau_1/200 = ", dt_out, samples, t_expect, samples / transits, n,
                      SAMPLING_MAX, SAMPLING_PER_TRANSIT_MAX, ceil(lim / q) * q,
                      given ? "" : " (the wall's contact is far shorter than the column's: a stiff wall on soft contacts)");
}

static int collide_plan_make(const gw_chain_params *p0, const gw_chain_run_opts *o, collide_plan *pl, gw_err *err)
{
    gw_chain_params q = *p0; /* the time scales at chain_speed_scale; p0 itself for the rest */
    q.v_imp = chain_speed_scale(p0);
    const gw_chain_params *p = &q;
    const int n = p->n;
    const double m0 = p->masses ? p->masses[0] : p->mass;
    memset(pl, 0, sizeof *pl);
    pl->type = o->solver ? o->solver : gw_solver_cvode;
    pl->tau1 = gw_chain_tau1(m0, p->kwall, p->v_imp);
    pl->dt_out = o->dt_out > 0 ? o->dt_out : pl->tau1 / 200.0;
    /* The collision's expected length: n bead-to-bead transits of 2 T_c plus
     * the wall contact, each on the scale of the heaviest bead it can involve
     * (chain_column_scales; bead 1's for equal beads). Bead 1's alone made a
     * light bead under a heavy one end at the default t-max still on the wall
     * (--radii 5e-4,1e-2: t-max 0.197 ms, the collision 0.248 ms, exit 1). */
    double tc_col = 0, tau1_col = 0;
    chain_column_scales(p, &tc_col, &tau1_col);
    const double t_col = n * 2.0 * tc_col + tau1_col; /* the ring, held and t-max bounds' too */
    pl->tc = tc_col;
    pl->t_max = o->t_max > 0 ? o->t_max : 20.0 * t_col;
    /* Every sample costs O(n) (energy, contacts): bound the samples over the
     * collision's expected length (or t_max when shorter). The
     * default dt-out gives about 100 n + 200 of them; checked before the run. */
    pl->t_expect = fmin(pl->t_max, t_col);
    int rc;
    pl->sp = o->sp;
    /* The root finders compare signs at step ends only: a step longer than half a
     * contact could step over a whole contact. Contacts last at least about the
     * binary contact time at twice v_imp, so cap the step at a quarter of it. */
    if (!(pl->sp.dt_max > 0))
        pl->sp.dt_max = 0.25 * chain_contact_tau_min(p, 2 * p->v_imp); /* the wall's too */
    pl->type = o->solver ? o->solver : gw_solver_cvode;
    /* the step resolves the stiffest contact (a small bead between large ones was
     * taken at bead 1's scale and blew up) and a sensor body's oscillation */
    if (pl->type == gw_solver_rk4 && !(pl->sp.dt > 0))
        pl->sp.dt = gw_chain_step_scale(p) / (o->steps_per_tc > 0 ? o->steps_per_tc : 400.0);
    /* and at least t_expect / step steps of O(n) each: bounded before the run
     * (the RK4 step, or the largest step of cvode/arkode) */
    /* Steps and samples grow about as n, memory as n (n^2 with a full Jacobian):
     * when several trip, the one that passes the fewest beads is named. */
    const double max_samples = 1e9, step = pl->type == gw_solver_rk4 ? fmin(pl->sp.dt, pl->sp.dt_max) : pl->sp.dt_max;
    gw_err e[3] = {{{0}}};
    double n_ok[3] = {INFINITY, INFINITY, INFINITY};
    if (chain_steps_check(pl->type, &pl->sp, &o->sp, pl->t_expect, "the collision", &e[0]) != GW_OK)
        n_ok[0] = n * 1e8 / (pl->t_expect / step);
    /* cvode and arkode follow a sensor body's oscillation too (8 s for 0.1 ms at
     * 1e-7 kg on 1e14 N/m, 5.8e7 steps) */
    if ((rc = chain_sensor_steps_check(p, pl->type, pl->t_expect, "the collision", err)) != GW_OK)
        return rc;
    if (gw_chain_memory_check(p, pl->type, pl->sp.method, &e[1]) != GW_OK)
        n_ok[1] = memory_n_ok(p, pl->type, pl->sp.method);
    if (!(pl->t_expect / pl->dt_out <= max_samples)) {
        gw_err_set(&e[2], GW_EINVAL, "dt-out: %g s gives about %.3g samples over the collision (about %.3g s); "
                   "at most %.0e: raise dt-out", pl->dt_out, pl->t_expect / pl->dt_out, pl->t_expect, max_samples);
        n_ok[2] = n * max_samples / (pl->t_expect / pl->dt_out);
    }
    int worst = -1;
    for (int i = 0; i < 3; i++)
        if (isfinite(n_ok[i]) && (worst < 0 || n_ok[i] < n_ok[worst]))
            worst = i;
    if (worst >= 0)
        return gw_err_set(err, GW_EINVAL, "%s", e[worst].msg);
    /* cvode and arkode follow a light bead that heavy beads hold, all the time
     * they hold it (chain_ring_check) */
    if ((rc = chain_ring_check(p, pl->type, &pl->sp, pl->t_expect, t_col, "the collision", err)) != GW_OK)
        return rc;
    /* A stored trace (gw_chain_trace_sample) keeps t, the wall force and every
     * bead's x and v at each sample and event (about 4 events per bead): bound
     * it before the run (--n 1000 --dt-out 1e-9 grew toward 400 GB; written,
     * 28 B a value, 1000 beads at the default dt-out came to 8 GB of files). */
    if (o->sample == gw_chain_trace_sample &&
        (rc = gw_chain_trace_check(n, pl->t_expect, pl->dt_out, 4.0 * n + 2, err)) != GW_OK)
        return rc;
    /* sampling far finer than the column's own scale (chain_sampling_check;
     * after the stored trace's bound, which names what --out would write) */
    if ((rc = chain_sampling_check(n, pl->t_expect, pl->dt_out, o->dt_out > 0, err)) != GW_OK)
        return rc;
    /* A run that does not end (a column held on the wall by gravity and damping,
     * a sensor body still ringing) goes on to t_max: the bounds above hold over
     * the expected collision, an explicit --t-max far beyond it must meet them too
     * (--t-max 1e6 ran 1e11 steps, hours, with nothing said). The default t_max is
     * 20 expected lengths, so it stays within 20 times the bounds. */
    if (o->t_max > 0 && pl->t_max > pl->t_expect) {
        const double t_lim = fmin(1e8 * step, max_samples * pl->dt_out);
        if (!(pl->t_max <= t_lim))
            return gw_err_set(err, GW_EINVAL, "t-max: %g s would take about %.3g steps of %g s and %.3g samples "
                              "of %g s if the collision has not ended by then; at most 1e+08 steps and 1e+09 samples: "
                              "lower t-max to %g s or less", pl->t_max, pl->t_max / step, step,
                              pl->t_max / pl->dt_out, pl->dt_out,
                              /* one that passes the held column's bound too (chain_held_check) */
                              fmin(floor_2digits(t_lim), held_t_lim(p0, t_col, pl->tau1,
                                                                    pl->dt_out)));
        if ((rc = chain_sensor_steps_check(p, pl->type, pl->t_max, "t-max", err)) != GW_OK)
            return rc;
        if (o->sample == gw_chain_trace_sample) {
            gw_err te = {{0}};
            if (gw_chain_trace_check(n, pl->t_max, pl->dt_out, 4.0 * n + 2, &te) != GW_OK)
                return gw_err_set(err, GW_EINVAL, "t-max: %g s would store about %.3g samples of %d beads if the "
                                  "collision has not ended by then, above the 5 GB limit of the written trace: lower "
                                  "t-max or raise dt-out", pl->t_max, pl->t_max / pl->dt_out + 1, n);
        }
    }
    /* A column that gravity holds on the wall runs to t_max (chain_held_check) */
    if ((rc = chain_held_check(p0, pl->t_max, t_col, pl->tau1, pl->dt_out, err)) != GW_OK)
        return rc;
    return GW_OK;
}

int gw_chain_run_check(const gw_chain_params *p, const gw_chain_run_opts *o, gw_err *err)
{
    collide_plan pl;
    return collide_plan_make(p, o, &pl, err);
}

int chain_run_steps(const gw_chain_params *p, const gw_chain_run_opts *o, double *steps, gw_err *err)
{
    collide_plan pl;
    int rc = collide_plan_make(p, o, &pl, err);
    if (rc != GW_OK)
        return rc;
    const double step = pl.type == gw_solver_rk4 ? fmin(pl.sp.dt, pl.sp.dt_max) : pl.sp.dt_max;
    double s = pl.t_expect / step;
    if (pl.type != gw_solver_rk4 && p->sensor.mass > 0 && p->sensor.stiffness > 0)
        s = fmax(s, 2.0 * sqrt(p->sensor.stiffness / p->sensor.mass) * pl.t_expect);
    *steps = s;
    return GW_OK;
}

static int collide_run(const gw_chain *c, const gw_chain_run_opts *o, int flight_cut, gw_chain_result *r,
                       gw_err *err);

int gw_chain_collide(const gw_chain *c, const gw_chain_run_opts *o, gw_chain_result *r,
                     gw_err *err)
{
    return collide_run(c, o, 0, r, err);
}

int chain_collide_flight_cut(const gw_chain *c, const gw_chain_run_opts *o, gw_chain_result *r, gw_err *err)
{
    return collide_run(c, o, 1, r, err);
}

static int collide_run(const gw_chain *c, const gw_chain_run_opts *o, int flight_cut, gw_chain_result *r,
                       gw_err *err)
{
    if (r)
        memset(r, 0, sizeof *r);
    if (!c || !o || !r)
        return gw_err_set(err, GW_EINVAL, "gw_chain_collide: %s is NULL", !c ? "c" : !o ? "o" : "r");
    const gw_chain_params *p = gw_chain_get_params(c);
    const gw_system *sys = gw_chain_system(c);
    const int n = p->n;
    memset(r, 0, sizeof *r);
    r->n = n;
    collide_plan pl;
    /* the plan sees the chain's own per-bead masses and contact coefficients
     * (gw_chain_create keeps them, not the caller's arrays) */
    gw_chain_params pc = *p;
    pc.masses = c->m;
    pc.kc = n > 1 ? c->kc : NULL;
    int prc = collide_plan_make(&pc, o, &pl, err);
    if (prc != GW_OK)
        return prc;
    r->final_v = calloc(4 * (size_t)n, sizeof *r->final_v);
    double *y = malloc((size_t)sys->dim * sizeof *y);
    int *roots = calloc((size_t)sys->nroots, sizeof *roots);
    run_state st = {.c = c, .o = o, .r = r, .n = n, .t_sampled = -INFINITY, .flight_cut = flight_cut,
                    .closed = calloc((size_t)n, 1),
                    .last_open = malloc((size_t)n * sizeof(double)),
                    .fc_prev = calloc(3 * (size_t)n, sizeof(double))};
    int rc = GW_OK;
    gw_solver *s = NULL;
    if (!r->final_v || !y || !roots || !st.closed || !st.last_open || !st.fc_prev) {
        rc = gw_err_set(err, GW_ENOMEM, "chain: out of memory for %d beads", n);
        goto done;
    }
    r->detach_t = r->final_v + n;
    r->v_tau_n = r->final_v + 2 * n;
    if (o->front_threshold > 0) {
        r->front_t = r->final_v + 3 * n;
        for (int k = 0; k < n; k++)
            r->front_t[k] = NAN;
    }
    r->tau_n = r->tau_max = NAN;
    if (o->y0)
        memcpy(y, o->y0, (size_t)sys->dim * sizeof *y);
    else
        gw_chain_initial_state(c, y);
    for (int k = 0; k < n; k++) { /* touching (overlap 0) counts as closed */
        st.closed[k] = (k == 0 ? y[0] : y[2 * k] - y[2 * k - 2]) >= 0;
        st.last_open[k] = -INFINITY;
    }
    r->wall_contacts = st.closed[0];

    const double dt_out = pl.dt_out, t_max = pl.t_max;
    /* the first contact's position scale, gw_chain_dmax1 at the column's
     * speed scale (gw_chain_create set it) */
    st.dtol = 1e-9 * c->scale[0];
    st.v_scale = c->scale[1];
    gw_solver_params sp = pl.sp;
    const gw_solver_type *type = pl.type;
    st.vtol_tol = type == gw_solver_rk4 ? 0.0 : 1e3 * fmax(sp.rtol, sp.atol);
    r->run_t_max = t_max;
    r->run_dt_out = dt_out;
    /* rk4 steps at the smaller of dt and dt_max (gw_backend_rk4.c): record that */
    r->run_dt = type == gw_solver_rk4 ? fmin(sp.dt, sp.dt_max) : sp.dt;
    r->run_dt_max = sp.dt_max;

    gw_chain_energy e;
    gw_chain_energy_of(c, y, &e);
    r->e0 = e.total;
    double p0 = momentum(c, y);
    if ((rc = gw_solver_create(type, sys, &sp, 0.0, y, &s, err)) != GW_OK)
        goto done;
    double t = 0.0;
    st.t_max = t_max;
    st.t_expect = pl.t_expect;
    st.s = s;
    st.type = type;
    if ((rc = sampled(observe(&st, t, y, 0), GW_DRIVE_ON, t, err)) < 0)
        goto done;
    if (rc == GW_DRIVE_STOP) {
        rc = GW_OK;
        goto stopped;
    }
    gw_drive drive = {.t_end = t_max, .dt_out = dt_out, .k_out = 1, .on_root = collide_root,
                      .on_output = collide_output, .after = collide_after, .ctx = &st};
    rc = gw_solver_drive(s, &drive, &t, y, roots, err);
stopped:
    r->t_end = t;
    /* The wall's impulse from the momentum balance d/dt (sum m_i v_i + M_s v_s) =
     * M g - F (F the force the sensor reads), exact where nothing else acts: the
     * trapezoid over the observations moved with --dt-out (the mean wall force of
     * wavespeed's group speed by 2.7e-5 at 2e-6 s, 7.6e-4 at 1e-5 s). With guide
     * friction, whose impulse is not tracked, the trapezoid stays. */
    if (!(p->guide.coulomb > 0 || p->guide.viscous > 0)) {
        double mg = 0;
        for (int i = 0; i < n; i++)
            mg += gw_chain_bead_mass(c, i) * p->gravity;
        r->impulse = p0 - momentum(c, y) + mg * t;
    }
    r->wall_pending = r->converged ? NULL : wall_pending(&st, y, st.dtol);
    r->wall_done = r->wall_pending == NULL;
    finish_result(&st, y);
    gw_solver_get_stats(s, &r->stats);
done:
    gw_solver_free(s);
    free(y);
    free(roots);
    free(st.closed);
    free(st.last_open);
    free(st.fc_prev);
    return rc;
}

void gw_chain_result_free(gw_chain_result *r)
{
    if (!r)
        return;
    free(r->final_v);
    r->final_v = r->detach_t = r->v_tau_n = r->front_t = NULL;
}
