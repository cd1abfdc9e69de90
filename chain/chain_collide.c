/*
 * chain_collide.c: one column-wall collision and its observables (docs/physics.md 1.3,
 * 1.4): the run itself, its events and what it measures. The plan it runs
 * with and the bounds checked before it (chain_collide_plan.c) are separate:
 * they hold no state of a run and are shared with the checks made before
 * anything is allocated (gw_chain_run_check, the sweeps' chain_run_steps).
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
#include "chain_collide_impl.h"
#include "gw_locale.h"
#include "gw_global.h"

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
                                caller's next impact (chain_collide_drop) */
    int watch_fall;          /* gravity, no guide friction and not a drop's
                                collision: held_by_gravity applies */
    double q_min;            /* the beads' lowest momentum toward the wall so far, kg m/s (chain_fell_back) */
    int held;                /* the column fell back on the wall (held_by_gravity) */
    gw_chain_progress_fn progress; /* gw_chain_collide_progress's, or NULL */
    void *pctx;
    chain_column_end *end;   /* chain_collide_progress_end's, or NULL */
    gw_drive *drive;         /* the run's drive (its end and sampling move on when the run goes on) */
    double t_default;        /* the default t_max, 20 expected lengths, when no t_max was given; else 0, s */
    double t_bound;          /* how far a default run goes on (chain_extend_bound), s */
    double dt_ext;           /* its sampling past the default t_max, s */
} run_state;

/* The final_v allocations a run made (they hold the column's pending text
 * after their 4n values), until gw_chain_result_free: the text is read only
 * from these. A result filled by hand, or copied with its own final_v array of
 * n values, has no such room, and reading past it was a heap over-read; its
 * warning keeps the generic text. A table of the live results' pointers, under
 * a fork-safe lock (a forked child keeps its parent's table). */
static gw_forklock made_lock = GW_FORKLOCK(NULL);
typedef struct made_run {
    const double *v; /* final_v */
    int n;           /* its beads: the text after 4n values */
} made_run;
static made_run *made;
static size_t n_made, cap_made;

static void made_add(const double *v, int n)
{
    gw_forklock_take(&made_lock);
    if (n_made == cap_made) {
        size_t cap = cap_made ? 2 * cap_made : 16;
        made_run *m = realloc(made, cap * sizeof *m);
        if (m)
            made = m, cap_made = cap;
    }
    if (n_made < cap_made) /* out of memory: the text is not kept, the generic one said */
        made[n_made++] = (made_run){v, n};
    gw_forklock_give(&made_lock);
}

/* whether v is one of the runs' allocations, made for n beads (n < 0: any);
 * removed too when drop */
static int made_find(const double *v, int n, int drop)
{
    int found = 0;
    gw_forklock_take(&made_lock);
    for (size_t k = n_made; k-- > 0;)
        if (made[k].v == v) {
            found = n < 0 || made[k].n == n;
            if (drop)
                made[k] = made[--n_made];
            break;
        }
    gw_forklock_give(&made_lock);
    return found;
}

/* Steps a whole run may take: the plan bounds them at 1e8 over the expected
 * length, and a run that goes on past it (a default t_max is 20 expected lengths:
 * an overdamped bead held on the wall under rk4 ran 5e8 steps) stops here. */
#define CHAIN_RUN_STEPS_MAX 2e8

/* A run at the default t_max that has not ended there goes on (extend_run):
 * at most this many samples past it, and at most CHAIN_EXTEND_VALUES values of
 * a stored trace (2 n + 2 a row: 1 GB of doubles), and 50 default t_max in
 * all (the trace's values when a sample callback takes the rows: --out, a
 * trace; --n 40 --sensor-mass 1e-3 --sensor-stiffness 1e3, whose beads 23 and 24
 * meet at 10.67 s, stopped at 7.98 s by it without one). Past the default t_max the run samples at dt_max (the cvode and arkode
 * step bound, a quarter of the shortest contact; rk4 at dt_out), so these rows
 * bound its steps there as well: 5e6 free-flight steps of a 10-bead column,
 * about 10 s of CPU. */
#define CHAIN_EXTEND_ROWS 5e6
#define CHAIN_EXTEND_VALUES 1.25e8
#define CHAIN_EXTEND_FACTOR 50.0

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

/* The column's end as its state says it (chain_collide_progress_end): with
 * bead 1 off the wall and every contact between beads open (overlap x_(k+1) -
 * x_k <= 0), the beads fly freely (a uniform gravity leaves their relative
 * speeds alone) and the run ends once its last closing pair (closing at w =
 * v_(k+1) - v_k > 0 over a gap g) has met, at t + g / w, and parted, a binary
 * Hertz contact of the pair's reduced mass at w later (gw_chain_tau1); now,
 * when no pair closes. While bead 1 is on the wall or a contact closed, the end
 * stays what it was (a collision within the flight), unknown (0) before the
 * first flight. chain --n 600 ended at 113.7 ms, 7.6 times its expected 15.0
 * ms, its last pair meeting at 1.5e-5 m/s: said from about 17 ms on. */
static void column_end(const run_state *st, double t, const double *y, double f_wall)
{
    if (f_wall > 0 || st->closed[0])
        return;
    const gw_chain *c = st->c;
    double meet = -INFINITY, w_meet = 0;
    int k_meet = 0;
    for (int k = 1; k < st->n; k++) {
        const double d = y[2 * k] - y[2 * k - 2], w = y[2 * k + 1] - y[2 * k - 1];
        if (d > 0 || st->closed[k])
            return;
        if (w > 0 && t + -d / w > meet) {
            meet = t + -d / w;
            w_meet = w;
            k_meet = k;
        }
    }
    if (!k_meet) {
        st->end->t_meet = 0;
        st->end->t_end = t;
        return;
    }
    const double m0 = c->m[k_meet - 1], m1 = c->m[k_meet],
                 tau = gw_chain_tau1(m0 * m1 / (m0 + m1), c->kc[k_meet - 1], w_meet);
    st->end->t_meet = meet;
    st->end->t_end = meet + (isfinite(tau) ? tau : 0.0);
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
    if (st->end) /* the column's end as its state says it, before the report */
        column_end(st, t, y, f);
    if (st->progress) /* where the run is (gw_chain_collide_progress) */
        st->progress(st->pctx, t, st->t_expect, st->t_max);
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
static const char reading_rising[] = "bead 1 left the wall, the sensor's reading still rising";


static const char *wall_pending(const run_state *st, const double *y, double dtol)
{
    /* a run cut in bead 1's flight whose return is the caller's next impact
     * (chain_collide_drop): bead 1 off the wall is done whatever its
     * velocity. The drop cuts its first collision half way through that
     * flight, where bead 1 turns: its velocity there is zero but for the
     * integration's error, +4.3e-11 m/s (cvode at 1e-12, "still at the wall")
     * or -1.3e-12 (1e-13, done) for N = 40 at h = 5.1 mm. */
    if (st->closed[0] || gw_chain_wall_gap(st->c, y) > dtol)
        return "bead 1 still at the wall";
    long is = gw_chain_sensor_index(st->c);
    /* Off the wall: on a sensor body the gap closes whenever the body swings
     * toward bead 1 faster than the bead leaves, which says nothing while the
     * bead is beyond the swing (the gap's rate made --n 10 --sensor-mass 0.03
     * --sensor-stiffness 1e4, bead 1 12 mm beyond a swing of 0.26 mm, say
     * "bead 1 still at the wall" at t-max, and kept its run going): there the
     * bead's own velocity and the swing decide, below. */
    if (is < 0 && !st->flight_cut && gw_chain_wall_gap_rate(st->c, y) > 0)
        return "bead 1 off the wall but moving back toward it";
    if (is >= 0) {
        const gw_chain_sensor *s = &gw_chain_get_params(st->c)->sensor;
        double xs = y[is], vs = y[is + 1], a = sqrt(xs * xs + s->mass * vs * vs / s->stiffness);
        if (y[1] > 0 || y[0] > -a)
            return "bead 1 off the wall but within the sensor body's swing";
        /* the reading k_s x_s (+ c_s v_s) still rising: its largest value, F_max,
         * comes after bead 1 left (a 1000 kg sensor on 1e12 N/m ended at 20.7 N,
         * rising, of a peak near J omega = 40 N) */
        if (vs > 0)
            return reading_rising;
    }
    return NULL;
}

static int wall_finished(const run_state *st, const double *y, double dtol)
{
    return wall_pending(st, y, dtol) == NULL;
}

/* A contact k >= 1 whose flag is still closed, with its beads overlapping and
 * separating, that opens before the run's end at its present rate (d / -w,
 * a lower bound under no force but the contact's). Such a contact no longer acts
 * (contact_acting) but its opening, its beads' detach time, is still to come:
 * a run that stopped at the first output after the contact stopped acting
 * dropped it, so the detach time depended on where the samples fell (--n 5
 * --kwall 1e4: bead 1's 0.016876 s at the default sampling, the wall's
 * 0.016636 s at --dt-out 1e-8, the run ending 4.6e-8 s before the opening).
 * Separating at a resolved speed (vtol, resolved_speed): two beads that leave
 * together part at the integration's error, and waiting for that opening made
 * the run's end move with the sampling (--n 2 --k 1e3 --kwall 1e14 under
 * arkode: t_end 0.0145 to 0.0162 s over four samplings). */
static int opening_ahead(const run_state *st, double t, const double *y, int k, double vtol)
{
    const double d = y[2 * k] - y[2 * k - 2], w = y[2 * k + 1] - y[2 * k - 1];
    return st->closed[k] && d > 0 && -w > vtol && t + d / -w < st->t_max;
}

/* The wall's side done (wall_pending), and every contact between beads open
 * and not closing (by its events and by its geometry, so that a contact the
 * root finder missed still counts) at a resolved speed (contact_acting): 1.
 * 2 when that holds but a contact's opening is still ahead (opening_ahead):
 * the run goes on to the opening's located root, so that the detach times are
 * events' times and never the samples'. 0 otherwise. */
static int finished(const run_state *st, double t, const double *y, double dtol)
{
    if (!wall_finished(st, y, dtol))
        return 0;
    const double vtol = resolved_speed(st);
    int ahead = 0;
    for (int k = 1; k < st->n; k++) {
        if (contact_acting(st, y, k, vtol))
            return 0;
        ahead |= opening_ahead(st, t, y, k, vtol);
    }
    return ahead ? 2 : 1;
}

/* What keeps the column's own side of a run cut at t_max going, into buf
 * (size bytes; "" when nothing does): the contact that acts (contact_acting), a
 * closed one first, else the pair that meets first (its beads close at w over a
 * gap g: they meet at t + g / w, the bodies in free flight; about, a guide's
 * friction aside), and how many more act. The run's warning names it: it said
 * "the column's own contacts still closed or closing", or "bead 1 still at the
 * wall" with bead 1 12 mm beyond the sensor body's swing and the pair of beads
 * 5 and 6 closing at 0.5 mm/s (--n 10 --sensor-mass 0.03 --sensor-stiffness 1e4). */
/* Returns the picked contact's meeting time (t when closed; NaN when none acts). */
static double column_pending(const run_state *st, double t, const double *y, char *buf, size_t size)
{
    const double vtol = resolved_speed(st);
    int count = 0, pick = 0, pick_closed = 0;
    double pick_meet = INFINITY;
    for (int k = 1; k < st->n; k++) {
        if (!contact_acting(st, y, k, vtol))
            continue;
        count++;
        const double d = y[2 * k] - y[2 * k - 2], w = y[2 * k + 1] - y[2 * k - 1];
        const int closed = st->closed[k] || d > st->dtol;
        const double meet = closed ? t : w > 0 ? t + fmax(0.0, -d) / w : INFINITY;
        if ((closed && !pick_closed) || (!pick_closed && meet < pick_meet) || !pick) {
            pick = k;
            pick_closed = closed;
            pick_meet = meet;
        }
    }
    if (buf)
        buf[0] = '\0';
    if (!pick || !buf)
        return pick ? pick_meet : NAN;
    int len = pick_closed ? gw_snprintf(buf, size, "bead %d still against bead %d", pick, pick + 1)
              : isfinite(pick_meet) ? gw_snprintf(buf, size, "beads %d and %d closing, to meet at about t = %.4g s",
                                                  pick, pick + 1, pick_meet)
                                    : gw_snprintf(buf, size, "beads %d and %d closing", pick, pick + 1);
    if (count > 1 && len > 0 && (size_t)len < size)
        gw_snprintf(buf + len, size - (size_t)len, ", and %d more of the column's contacts closed or closing",
                    count - 1);
    return pick_meet;
}

/* A default run (no t_max given) that has not ended by its t_max, 20 expected
 * lengths, goes on: another 20 lengths at a time, while contacts act, up to
 * st->t_bound (chain_extend_bound), sampled at st->dt_ext from there. The
 * collision's length is not bounded by its expected length: beads that leave
 * a soft sensor spring out of order meet again after the ride (--n 10
 * --sensor-mass 0.03 --sensor-stiffness 1e4 cut at the default 0.148 s, its
 * beads 5 and 6 meeting at 0.278 s; --n 5 --sensor-mass 0.01
 * --sensor-stiffness 1e4 at 0.093 s, ending at 1.36 s, 291 expected
 * lengths), as does a light bead between heavy ones on a rigid wall (--n 3
 * --radii 4e-3,1e-3,4e-3: cut at 2.5 ms, ends at 4.8 ms). 1 when it goes on. */
static int extend_run(run_state *st, double t, const double *y)
{
    if (!(st->t_default > 0) || !st->drive || !(t < st->t_bound))
        return 0;
    /* Nothing but beads in free flight that meet after the bound (their
     * relative motion is uniform, gravity acting on all alike; not under a
     * guide's friction), bead 1 off the wall and beyond a sensor body's swing
     * (its reading may still rise): the run stops here, not at the bound
     * (--n 20 --sensor-mass 0.1 --sensor-stiffness 1e3 ran on to 20.5 s, its
     * beads 17 and 18 to meet at 758 s) */
    const gw_chain_params *p = gw_chain_get_params(st->c);
    const char *wp = wall_pending(st, y, st->dtol);
    if ((!wp || wp == reading_rising) && !(p->guide.coulomb > 0 || p->guide.viscous > 0) &&
        !(column_pending(st, t, y, NULL, 0) <= st->t_bound))
        return 0; /* (NaN: no contact of the column acts, only the sensor's reading
                   * still rising: a critically damped 1e-5 kg body on 1e12 N/m ran
                   * on to the bound, 0.16 s and 14 million erk steps, to end as it was) */
    st->t_max = fmin(st->t_bound, t + st->t_default);
    st->drive->t_end = st->t_max;
    if (st->dt_ext > st->drive->dt_out) {
        st->drive->dt_out = st->dt_ext;
        st->drive->k_out = (long)floor(t / st->dt_ext) + 1;
    }
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

int gw_chain_result_held_blank(gw_chain_result *r)
{
    if (!r || r->wall_pending != chain_held_pending)
        return 0;
    r->f_max = r->tau_max = r->tau_n = r->eps_eff = r->eps_col = NAN;
    for (int i = 0; r->final_v && i < r->n; i++)
        r->final_v[i] = NAN;
    return 1;
}

/* A sample callback's answer as the drive's: a stop (> 0) ends the run without
 * an error, a failure (< 0: the trace's growth out of memory) is the run's. It
 * was taken for a stop, so a trace that could not grow ended the run as if it
 * were complete: exit 0 with F_max 0 and the beads' initial velocities as their
 * final ones (tests/test_alloc_failure.sh). */
static int sampled(const run_state *st, int sr, int go_on, double t, gw_err *err)
{
    /* a caller's own callback failing was told "the trace at t = ...: invalid
     * input", a trace the caller had not asked for: the callback named */
    if (sr < 0 && st->o->sample == gw_chain_trace_sample)
        return gw_err_set(err, sr, "chain: the trace at t = %.9g s: %s", t, gw_strerror(sr));
    if (sr < 0)
        return gw_err_set(err, sr, "chain: the sample callback failed at t = %.9g s: %s", t, gw_strerror(sr));
    return sr > 0 ? GW_DRIVE_STOP : go_on;
}

/* The column falls back onto the wall before its collision has ended: the
 * beads' momentum q = sum m_i v_i (positive toward the wall), which the wall
 * turned negative, is back at >= 0. Then not every bead moves away from the
 * wall, so the collision has not ended (physics.md 1.2: every contact open and
 * separating, bead 1 moving off the wall), and it cannot end before the wall
 * pushes again: off the wall only gravity changes q (the contacts between beads
 * cancel in it), and gravity raises it. What follows is a new impact of the
 * whole column, not the end of this one: the run stops there, undecided
 * (chain_held_pending), instead of bouncing on to t_max (softwall --n 17
 * --gravity 1e4: 6 to 40 s, then a failure). Needs gravity; guide friction
 * (which can slow beads toward the wall) and the drop's collision (whose
 * bounces are its subject) are not watched. */
double chain_momentum(const gw_chain *c, const double *y, double *mass)
{
    double q = 0, m = 0;
    for (int i = 0; i < gw_chain_get_params(c)->n; i++) {
        q += gw_chain_bead_mass(c, i) * y[2 * i + 1];
        m += gw_chain_bead_mass(c, i);
    }
    if (mass)
        *mass = m;
    return q;
}

int chain_fell_back(double *q_min, double q, double q_scale)
{
    const int fell = *q_min < -1e-3 * q_scale && q >= 0;
    if (q < *q_min)
        *q_min = q;
    return fell;
}

static int held_by_gravity(run_state *st, const double *y)
{
    if (!st->watch_fall)
        return 0;
    double m;
    const double q = chain_momentum(st->c, y, &m);
    return chain_fell_back(&st->q_min, q, m * st->v_scale);
}

/* What to change when a run reaches CHAIN_RUN_STEPS_MAX, by the solver it ran:
 * "use cvode" was given to cvode runs too (issue 18). rk4's fixed step and the
 * explicit methods' stability-bound steps are what cvode bdf lengthens; bdf
 * (and arkode's implicit methods) take their step from the tolerances. */
const char *chain_cap_advice(const gw_solver_type *type, int method)
{
    const gw_solver_type *t = type ? type : gw_solver_cvode;
    const char *used = gw_solver_method_used(t, method);
    if (t == gw_solver_rk4)
        return "use cvode (bdf: it lengthens its step where nothing moves fast)";
    if (used && (strcmp(used, "adams") == 0 || strcmp(used, "erk") == 0))
        return "use cvode with its default method bdf (implicit: a stiff sensor body, drag or contact does not "
               "hold its step)";
    return "loosen rtol and atol (this run already steps implicitly): something keeps ringing, a sensor body or "
           "a light bead between heavy ones";
}

/* The run's hooks (gw_solver_drive): at a root the contact flags and the
 * observation; at an output time the flags brought in line with the geometry
 * (reconcile) and the observation; after either the energy monitor and the end. */
static int collide_root(void *ctx, double t, double *y, const int *roots, gw_err *err)
{
    run_state *st = ctx;
    on_roots(st, t, y, roots);
    return sampled(st, observe(st, t, y, 1), chain_roots_need_reset(st->c, t, y, roots) ? GW_DRIVE_RESET : GW_DRIVE_ON,
                   t, err);
}

static int collide_output(void *ctx, double t, double *y, gw_err *err)
{
    run_state *st = ctx;
    int wall_closed = st->closed[0];
    reconcile(st, t, y);
    if (wall_closed && !st->closed[0])
        on_wall_open(st, t, y);
    return sampled(st, observe(st, t, y, 0), GW_DRIVE_ON, t, err);
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
                              "ended (expected by about %.3g s); at most %.0e a run: lower t-max, or %s",
                              ss.steps, t, st->t_expect, CHAIN_RUN_STEPS_MAX,
                              chain_cap_advice(st->type, st->o->sp.method));
    }
    if (st->o->energy_tol > 0 && r->energy_error > st->o->energy_tol)
        return gw_err_set(err, GW_EENERGY, "chain: relative energy error %.3g exceeds the limit %.3g at t = %.9g s",
                          r->energy_error, st->o->energy_tol, t);
    const int fin = finished(st, t, y, st->dtol);
    if (fin == 1) {
        r->converged = 1;
        return GW_DRIVE_STOP;
    }
    if (held_by_gravity(st, y)) {
        st->held = 1;
        return GW_DRIVE_STOP;
    }
    if (t >= st->t_max) {
        if (fin == 2) { /* ended but for an opening that did not come by t_max */
            r->converged = 1;
            return GW_DRIVE_STOP;
        }
        if (!isfinite(r->tau_n)) {
            /* A guide's friction that stops the bead inside its overlap
             * holds it there: the Hertz force pushes it out against a drag
             * (the Coulomb term regularised: coulomb / v_reg near rest) and
             * the overlap creeps back without end (--guide-viscous 100 or
             * --guide-friction 1 at --vimp 1e-3 said only this, whatever
             * t-max, naming no input): name the guide as the cause when
             * the bead has stopped (a t-max that cuts the collision short
             * leaves it moving) */
            const gw_chain_params *p = gw_chain_get_params(st->c);
            const int stopped = chain_bead_stopped(y[1], st->v_scale);
            if ((p->guide.coulomb > 0 || p->guide.viscous > 0) && stopped)
                return gw_err_set(err, GW_ELIMIT, "chain: bead 1 still on the wall at t_max = %.6g s: the guide's "
                                  "friction (guide-friction %g N, guide-viscous %g N s/m) stopped it inside its "
                                  "overlap, which creeps back without end (an overdamped contact; a longer t-max "
                                  "does not end it): lower guide-friction or guide-viscous, or raise the impact "
                                  "speed", st->t_max, p->guide.coulomb, p->guide.viscous);
            /* so does a contact damping far above critical (--damping hc
             * --alpha 1e8, kk --gamma 1e14: the same line, naming nothing) */
            if (chain_damping_holds(p, y[1], st->v_scale))
                return chain_damping_held_error(p, "chain", "wall", st->t_max, "from which it creeps back (an "
                                                "overdamped contact)", ", or raise the impact speed", err);
            return gw_err_set(err, GW_ELIMIT, "chain: bead 1 still on the wall at t_max = %.6g s", st->t_max);
        }
        return extend_run(st, t, y) ? GW_DRIVE_ON : GW_DRIVE_STOP;
    }
    return GW_DRIVE_ON;
}

/* The chain's parameters with its own per-bead masses and contact
 * coefficients (gw_chain_create keeps them, not the caller's arrays), as the
 * plan sees them */
static gw_chain_params own_params(const gw_chain *c)
{
    gw_chain_params pc = *gw_chain_get_params(c);
    pc.masses = c->m;
    pc.kc = pc.n > 1 ? c->kc : NULL;
    return pc;
}

double chain_collide_drop_held_t(const gw_chain *c, const gw_chain_run_opts *o)
{
    const gw_chain_params pc = own_params(c);
    return chain_collide_held_t(&pc, o);
}

int chain_collide_drop_held_refuse(const gw_chain *c, const gw_chain_run_opts *o, gw_err *err)
{
    const gw_chain_params pc = own_params(c);
    return chain_collide_held_refuse(&pc, o, err);
}

static int collide_run(const gw_chain *c, const gw_chain_run_opts *o, int drop, int flight_cut, int rerun,
                       gw_chain_progress_fn progress, void *pctx, chain_column_end *end, gw_chain_result *r,
                       gw_err *err);
static void chatter_spread(const gw_chain *c, const gw_chain_run_opts *o, int drop, int flight_cut,
                           const collide_plan *pl, gw_chain_result *r);

int gw_chain_collide(const gw_chain *c, const gw_chain_run_opts *o, gw_chain_result *r,
                     gw_err *err)
{
    return collide_run(c, o, 0, 0, 0, NULL, NULL, NULL, r, err);
}

int gw_chain_collide_progress(const gw_chain *c, const gw_chain_run_opts *o, gw_chain_progress_fn progress,
                              void *pctx, gw_chain_result *r, gw_err *err)
{
    return collide_run(c, o, 0, 0, 0, progress, pctx, NULL, r, err);
}

int chain_collide_progress_end(const gw_chain *c, const gw_chain_run_opts *o, gw_chain_progress_fn progress,
                               void *pctx, chain_column_end *end, gw_chain_result *r, gw_err *err)
{
    if (end)
        *end = (chain_column_end){0, 0};
    return collide_run(c, o, 0, 0, 0, progress, pctx, end, r, err);
}

int chain_collide_drop(const gw_chain *c, const gw_chain_run_opts *o, int flight_cut, gw_chain_result *r,
                       gw_err *err)
{
    return collide_run(c, o, 1, flight_cut, 0, NULL, NULL, NULL, r, err);
}

int chain_collide_drop_check(const gw_chain *c, const gw_chain_run_opts *o, gw_err *err)
{
    const gw_chain_params pc = own_params(c); /* as collide_run plans */
    return chain_collide_plan_early(&pc, o, err);
}

static int collide_run(const gw_chain *c, const gw_chain_run_opts *o, int drop, int flight_cut, int rerun,
                       gw_chain_progress_fn progress, void *pctx, chain_column_end *end, gw_chain_result *r,
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
    const gw_chain_params pc = own_params(c);
    int prc = chain_collide_plan_make(&pc, o, &pl, err);
    if (prc != GW_OK)
        return prc;
    /* the velocities' arrays, then the column's pending text (chain_result_column_pending) */
    r->final_v = calloc(1, 4 * (size_t)n * sizeof *r->final_v + CHAIN_PENDING_TEXT + CHAIN_CHATTER_TEXT);
    double *y = malloc((size_t)sys->dim * sizeof *y);
    int *roots = calloc((size_t)sys->nroots, sizeof *roots);
    run_state st = {.c = c, .o = o, .r = r, .n = n, .t_sampled = -INFINITY, .flight_cut = flight_cut,
                    .progress = progress, .pctx = pctx, .end = end,
                    .closed = calloc((size_t)n, 1),
                    .last_open = malloc((size_t)n * sizeof(double)),
                    .fc_prev = calloc(3 * (size_t)n, sizeof(double))};
    int rc = GW_OK;
    gw_solver *s = NULL;
    if (!r->final_v || !y || !roots || !st.closed || !st.last_open || !st.fc_prev) {
        rc = gw_err_set(err, GW_ENOMEM, "chain: out of memory for %d beads", n);
        goto done;
    }
    made_add(r->final_v, n);
    /* the run's tolerances (rk4: none) */
    r->run_rtol = pl.type == gw_solver_rk4 ? NAN : pl.sp.rtol;
    r->run_atol = pl.type == gw_solver_rk4 ? NAN : pl.sp.atol;
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
    st.watch_fall = !drop && p->gravity > 0 && !(p->guide.coulomb > 0 || p->guide.viscous > 0);
    st.q_min = 0;

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
    /* every backend steps at most dt_max (gw_solver_create), rk4's steps end at
     * the samples (gw_backend_rk4.c): record the step taken, beside the dt
     * given (--dt 1e-3 ran as the automatic dt_max 6.6e-6 s, and rk4's --dt 1e-3
     * at --dt-out 1e-6 as --dt 1e-6, while the settings said 1e-3) */
    r->run_dt_given = o->sp.dt > 0 ? o->sp.dt : 0.0;
    r->run_dt = chain_plan_step(&pl);
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
    if ((rc = sampled(&st, observe(&st, t, y, 0), GW_DRIVE_ON, t, err)) < 0)
        goto done;
    if (rc == GW_DRIVE_STOP) {
        rc = GW_OK;
        goto stopped;
    }
    gw_drive drive = {.t_end = t_max, .dt_out = dt_out, .k_out = 1, .on_root = collide_root,
                      .on_output = collide_output, .after = collide_after, .ctx = &st};
    st.drive = &drive;
    if (!(o->t_max > 0) && !drop) { /* the default t_max: the run goes on past it (extend_run) */
        st.t_default = t_max;
        st.dt_ext = type == gw_solver_rk4 ? dt_out : fmax(dt_out, sp.dt_max);
        st.t_bound = chain_extend_bound(t_max, st.dt_ext, n, o->sample != NULL);
    }
    rc = chain_step_limit_named(gw_solver_drive(s, &drive, &t, y, roots, err), s, &pl.sp, err);
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
    r->run_t_max = st.t_max; /* where a default run that went on stopped (extend_run) */
    r->wall_pending = r->converged ? NULL : st.held ? chain_held_pending : wall_pending(&st, y, st.dtol);
    r->wall_done = r->wall_pending == NULL;
    if (!r->converged && !st.held)
        column_pending(&st, t, y, (char *)(r->final_v + 4 * (size_t)n), CHAIN_PENDING_TEXT);
    finish_result(&st, y);
    gw_solver_get_stats(s, &r->stats);
    if (rc == GW_OK && !rerun && (r->converged || drop))
        chatter_spread(c, o, drop, flight_cut, &pl, r);
done:
    gw_solver_free(s);
    free(y);
    free(roots);
    free(st.closed);
    free(st.last_open);
    free(st.fc_prev);
    return rc;
}

double chain_extend_bound(double t_default, double dt_ext, int n, int stored)
{
    /* a run that stores nothing holds O(n) whatever its length: its rows bound its steps only */
    const double rows = stored ? fmin(CHAIN_EXTEND_ROWS, CHAIN_EXTEND_VALUES / (2.0 * n + 2)) : CHAIN_EXTEND_ROWS;
    return t_default + fmin((CHAIN_EXTEND_FACTOR - 1) * t_default, rows * dt_ext);
}

/* Bead 1 that chatters on a light sensor body (its wall contact closing and
 * opening again many times: 61 times at --n 5 --sensor-mass 1e-4
 * --sensor-stiffness 1e3) amplifies any difference between two runs: the
 * integration's error and the rounding of the located roots' times, which the
 * output times move (CVODE locates a root from its last return), so that
 * eps_eff was 0.9923 by default, 0.9947 at --dt-out 1.5e-6 and 0.9894 at 3e-8,
 * and 0.9945, 0.9985, 0.9968, 0.9923, 0.9943 and 0.9965 at rtol = atol = 1e-8,
 * 1e-10, 1e-11, 1e-12, 1e-13 and 1e-14 (at 1e-14, four samplings agreed within
 * 1.5e-4). No sampling decides it: the result is one of the chatter's outcomes.
 * A run with GW_CHAIN_CHATTER_CONTACTS wall contacts or more is run again, cheap
 * ones (steps times beads at most GW_CHAIN_CHATTER_WORK; the rerun costs about 1.3
 * times the run) with rtol and atol 10 times tighter (rk4: half its step), and
 * a difference of eps_eff above GW_CHAIN_CHATTER_SPREAD is said in the result's
 * warnings with both values (chain_result_chatter), its kind and spread in the
 * result's chatter_kind and chatter_spread. A chatter whose rerun
 * agrees (--n 2 --sensor-mass 1e-4 --sensor-stiffness 1e3: 24 contacts) says
 * nothing. A costly one is not run again (--n 3 --sensor-mass 1e-7
 * --sensor-stiffness 1e3: 6707 contacts, 4.8 million steps, 76 s on a loaded
 * machine) but said to be unmeasured, naming what to change: it returned
 * without a word before. A study or sweep counts its columns' kinds into one
 * line. A drop's first collision (drop) is checked alike, its rerun the drop's
 * own (cut where the first was: flight_cut); it ends at the drop's next
 * impact, so its contacts are rarely more than one (the drop's own chatter,
 * over its impacts, is chain_drop.c's). */

/* where the chatter's text is kept, after the pending text */
static char *chatter_text(const gw_chain_result *r)
{
    return (char *)(r->final_v + 4 * (size_t)r->n) + CHAIN_PENDING_TEXT;
}

int chain_result_tolerances(const gw_chain_result *r, double *rtol, double *atol)
{
    if (!r)
        return 0;
    *rtol = r->run_rtol;
    *atol = r->run_atol;
    return r->run_rtol > 0 && r->run_atol > 0;
}

int chain_chatter_looser(double rtol, double atol)
{
    return !(rtol >= 10 * GW_TOL_MIN * (1 - 1e-9) && atol >= 10 * GW_TOL_MIN * (1 - 1e-9));
}

void chain_chatter_rerun(const gw_solver_type *type, double step, gw_solver_params *sp, char *how, size_t how_size,
                         char *flags, size_t flags_size)
{
    if (type == gw_solver_rk4) {
        sp->dt = 0.5 * step;
        gw_snprintf(how, how_size, "rk4's step halved, %g s", sp->dt);
        gw_snprintf(flags, flags_size, "--dt %g (half the step)", sp->dt);
    } else {
        /* 10 times tighter where both can be: at the floor GW_TOL_MIN neither
         * could, and the rerun of rtol = atol = 1e-15 was the run itself, bit
         * for bit, its chatter "none" (chain --n 3 --sensor-mass 1e-4
         * --sensor-stiffness 1e3 --rtol 1e-15 --atol 1e-15: chatter 0 and no
         * word, where 1e-14 against 1e-15 moved eps_eff by 1.35e-6); one at
         * the floor (rtol 1e-15, atol 1e-12) was run again changing the other
         * alone. Then both are 10 times looser (at most GW_TOL_MAX): the
         * spread measured is the looser run's, a bound on this one's */
        const int tighter = !chain_chatter_looser(sp->rtol, sp->atol);
        const double f = tighter ? 0.1 : 10.0;
        sp->rtol = fmin(fmax(f * sp->rtol, GW_TOL_MIN), GW_TOL_MAX);
        sp->atol = fmin(fmax(f * sp->atol, GW_TOL_MIN), GW_TOL_MAX);
        gw_snprintf(how, how_size, "rtol %g, atol %g%s", sp->rtol, sp->atol,
                    tighter ? "" : " (10 times looser: 1e-15 is the floor)");
        gw_snprintf(flags, flags_size, "--rtol %g --atol %g", sp->rtol, sp->atol);
    }
}

static void chatter_spread(const gw_chain *c, const gw_chain_run_opts *o, int drop, int flight_cut,
                           const collide_plan *pl, gw_chain_result *r)
{
    const int n = r->n;
    char *text = chatter_text(r);
    text[0] = '\0';
    r->chatter_kind = GW_CHAIN_CHATTER_NONE;
    r->chatter_spread = 0;
    if (gw_chain_sensor_index(c) < 0 || r->wall_contacts < GW_CHAIN_CHATTER_CONTACTS)
        return;
    gw_chain_run_opts o2 = *o;
    o2.sample = NULL;
    o2.sample_ctx = NULL;
    o2.sp = pl->sp; /* the plan's step bounds, and the tolerances tightened */
    char how[96], flags[80], ending[CHAIN_CHATTER_TEXT];
    chain_chatter_rerun(pl->type, chain_plan_step(pl), &o2.sp, how, sizeof how, flags, sizeof flags);
    /* a costly run is not run again (--n 3 --sensor-mass 1e-7 --sensor-stiffness 1e3:
     * 6707 contacts, 4.8 million steps, a minute), and says so */
    const double work = (double)r->stats.steps * n;
    if (!(work <= GW_CHAIN_CHATTER_WORK)) {
        r->chatter_kind = GW_CHAIN_CHATTER_COSTLY;
        gw_snprintf(ending, sizeof ending, "so that the final velocities and the restitution move with dt-out and "
                    "the tolerances, and this run (%.3g steps times %d beads, above the %.3g a rerun is made "
                    "within) was not run again to measure by how much: compare a run at %s; a stiffer, heavier or "
                    "damped sensor body (--sensor-stiffness, --sensor-mass, --sensor-damping) chatters less",
                    (double)r->stats.steps, n, GW_CHAIN_CHATTER_WORK, flags);
        chain_chatter_text(text, CHAIN_CHATTER_TEXT, r->wall_contacts, "", ending);
        return;
    }
    gw_chain_result r2;
    gw_err e2 = {{0}};
    const int rc = collide_run(c, &o2, drop, flight_cut, 1, NULL, NULL, NULL, &r2, &e2);
    const double d = fabs(r2.eps_eff - r->eps_eff);
    /* a drop's first collision ends where the drop cut it (converged 0): its rerun agrees or not alike */
    if (rc == GW_OK && (r2.converged || drop) && !(d > GW_CHAIN_CHATTER_SPREAD)) {
        gw_chain_result_free(&r2);
        return;
    }
    r->chatter_kind = rc == GW_OK ? GW_CHAIN_CHATTER_MOVED : GW_CHAIN_CHATTER_FAILED;
    r->chatter_spread = rc == GW_OK ? d : 0;
    char where[112];
    gw_snprintf(where, sizeof where, "; %d at %s", r2.wall_contacts, how);
    if (rc == GW_OK)
        gw_snprintf(ending, sizeof ending, "and a rerun there gave eps_eff %.6g against %.6g, tau_N %.6g s against "
                    "%.6g s: the final velocities and the restitution are uncertain by that much, and move with "
                    "dt-out and the tolerances", r2.eps_eff, r->eps_eff, r2.tau_n, r->tau_n);
    else
        gw_snprintf(ending, sizeof ending, "and its rerun at %s failed (%s), the spread unmeasured", how, e2.msg);
    chain_chatter_text(text, CHAIN_CHATTER_TEXT, r->wall_contacts, rc == GW_OK ? where : "", ending);
    gw_chain_result_free(&r2);
}

const char *chain_result_chatter(const gw_chain_result *r)
{
    if (!r || !r->final_v || r->n < 1 || !made_find(r->final_v, r->n, 0))
        return "";
    const char *text = chatter_text(r);
    return memchr(text, '\0', CHAIN_CHATTER_TEXT) ? text : "";
}

double chain_chatter_value(int kind, double spread)
{
    return kind == GW_CHAIN_CHATTER_MOVED ? spread : kind == GW_CHAIN_CHATTER_COSTLY ? -1.0
                                                   : kind == GW_CHAIN_CHATTER_FAILED ? -2.0 : 0.0;
}

double chain_result_chatter_value(const gw_chain_result *r)
{
    return r ? chain_chatter_value(r->chatter_kind, r->chatter_spread) : 0.0;
}

const char *chain_result_column_pending(const gw_chain_result *r)
{
    if (!r || !r->final_v || r->n < 1 || r->converged || !made_find(r->final_v, r->n, 0))
        return "";
    const char *text = (const char *)(r->final_v + 4 * (size_t)r->n);
    return memchr(text, '\0', CHAIN_PENDING_TEXT) ? text : "";
}

void gw_chain_result_free(gw_chain_result *r)
{
    if (!r)
        return;
    if (r->final_v)
        made_find(r->final_v, -1, 1);
    free(r->final_v);
    r->final_v = r->detach_t = r->v_tau_n = r->front_t = NULL;
}

int chain_step_limit_named(int rc, const gw_solver *s, const gw_solver_params *sp, gw_err *err)
{
    const char *m = s ? gw_solver_error(s) : "";
    if (rc != GW_ELIMIT || !err || !sp || !m[0] || !strstr(err->msg, m))
        return rc;
    char first[sizeof err->msg];
    gw_snprintf(first, sizeof first, "%s", err->msg);
    return gw_err_set(err, rc, "%s (the step limit max-steps = %ld steps between two outputs or events: raise "
                      "--max-steps)", first, sp->max_steps);
}
