/*
 * chain_drop.c: the whole drop of a column on the sensor (gw_chain.h, "the whole
 * drop"; physics.md 1.1, 1.2, 1.5).
 *
 * Equations: the column of chain_model.c (F.11) with gravity g toward the sensor,
 *   m_i x_i'' = F_i - F_(i-1) + m_i g,   F_(-1) = F = wall (sensor) force,
 * optionally with Kuwabara-Kono or Hunt-Crossley damping. Released from rest with
 * bead 1 at height h, the column falls freely (no contact force, every bead at
 * the same acceleration g), so at the first contact, t = 0, every bead moves at
 * v_imp = sqrt(2 g h) after t_fall = sqrt(2 h / g); the gaps are those of the
 * release. From there the solver layer integrates to t_max.
 *
 * Peaks without sampling: the falling zeros, with bead 1 on the sensor, of the
 * chain's force-maximum root (gw_chain_force_max_root: a function with the sign
 * of dF/dt, F the force the sensor reads, chain_model.c) are the maxima of F(t).
 * The drop once added a rate function of its own, written for the Hertz sensor
 * (x = x_1, v = v_1): with a sensor body it marked bead 1's turning point, where
 * the reading was 3.4 % below its peak (N = 2, 3 g on 2e9 N/m), and with a
 * viscoelastic sheet the overlap's maximum (7e-5 below). A zero where the force
 * is clamped at 0 is not a maximum and is dropped by the condition F > 0.
 *
 * Energy ledger: E = kinetic + elastic (2/5) k d^(5/2) + gravity (-m g x, x = 0
 * at the first contact) + dissipated (integrated as a state), checked at every
 * sample and event against E(0). Units: SI (m, s, kg, N, J).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"
#include "chain_model.h"
#include "gw_locale.h"
#include "gw_number_impl.h"

gw_chain_drop_params gw_chain_drop_params_default(void)
{
    gw_chain_drop_params p;
    memset(&p, 0, sizeof p);
    p.chain = gw_chain_params_default();
    p.chain.gravity = 9.81;
    p.height = 5.1e-3;
    p.t_max = 10e-3;
    p.peak_threshold = 0.7;
    return p;
}

/* The fall from h to the first contact is free fall in closed form (v_imp =
 * sqrt(2 g h), t_fall = sqrt(2 h / g)); friction of the beads on their guide
 * would slow it (0.01 N on a 2.1 g bead: 0.227 m/s at h = 5.1 mm, not 0.316),
 * and 0.05 N holds a bead that weighs 0.021 N. It acted only after the first
 * contact: refused, as drop.md says the drop has no guide friction. */
int gw_chain_drop_guide_check(double coulomb, double viscous, gw_err *err)
{
    if (coulomb > 0 || viscous > 0)
        return gw_err_set(err, GW_EINVAL, "%s: the drop's fall to the first contact is free fall (v_imp = sqrt(2 g "
                          "h), in closed form), which friction on the guide would slow: not modelled in the drop "
                          "(granwave chain runs a collision with it)", coulomb > 0 ? "guide-friction"
                                                                                 : "guide-viscous");
    return GW_OK;
}

int gw_chain_drop_params_validate(const gw_chain_drop_params *p, gw_err *err)
{
    if (!p)
        return gw_err_set(err, GW_EINVAL, "gw_chain_drop_params_validate: p is NULL");
    int rc;
    if ((rc = gw_check_range(p->height, "height (m)", GW_CHAIN_DROP_H_MIN, GW_CHAIN_DROP_H_MAX, err)) != GW_OK)
        return rc;
    if ((rc = gw_check_range(p->chain.gravity, "gravity (m/s^2)", GW_CHAIN_DROP_G_MIN, 1e4, err)) != GW_OK)
        return rc;
    if ((rc = gw_check_range(p->t_max, "t-max (s)", GW_CHAIN_DROP_T_MIN, GW_CHAIN_DROP_T_MAX, err)) != GW_OK)
        return rc;
    if ((rc = gw_check_range(p->peak_threshold, "peak-threshold (N)", 0, INFINITY, err)) != GW_OK)
        return rc;
    if ((rc = gw_chain_drop_guide_check(p->chain.guide.coulomb, p->chain.guide.viscous, err)) != GW_OK)
        return rc;
    for (int i = 0; p->gaps && i < p->chain.n - 1; i++)
        if (!(p->gaps[i] >= 0 && p->gaps[i] <= GW_CHAIN_DROP_GAP_MAX)) {
            char xs[32], hs[32];
            return gw_err_set(err, GW_EINVAL, "gap %d (m): %s is outside [0, %s]", i + 1,
                              gw_num_text(xs, sizeof xs, p->gaps[i]), gw_num_bound(hs, sizeof hs, GW_CHAIN_DROP_GAP_MAX, 1));
        }
    gw_chain_params q = p->chain;
    q.v_imp = sqrt(2.0 * q.gravity * p->height);
    return gw_chain_params_validate(&q, err);
}

/* The drop's system: the chain's, with the rate function R appended. */
typedef struct drop_sys {
    const gw_chain *c;
    const gw_system *cs;
    gw_system sys;
    int n;
} drop_sys;

static int drop_roots(double t, const double *y, double *g, void *P)
{
    drop_sys *d = P;
    return d->cs->roots(t, y, g, d->cs->params);
}

static int drop_rhs(double t, const double *y, double *yd, void *P)
{
    const drop_sys *d = P;
    return d->cs->rhs(t, y, yd, d->cs->params);
}

static int drop_rhs_ex(double t, const double *y, double *yd, void *P)
{
    const drop_sys *d = P;
    return d->cs->rhs_ex(t, y, yd, d->cs->params);
}

static int drop_rhs_im(double t, const double *y, double *yd, void *P)
{
    const drop_sys *d = P;
    return d->cs->rhs_im(t, y, yd, d->cs->params);
}

static int drop_jac(double t, const double *y, const double *f, gw_band *J, void *P)
{
    const drop_sys *d = P;
    return d->cs->jac(t, y, f, J, d->cs->params);
}

/* Run state of the drop loop. */
typedef struct drop_state {
    const drop_sys *d;
    const gw_chain_drop_params *p;
    const gw_chain_run_opts *o;
    gw_chain_drop_result *r;
    int n;
    unsigned char *closed; /* [n]: 0 = sensor, k = beads k, k+1 */
    double dtol;           /* overlap below which a contact counts as open, m */
    int in_episode;        /* bead 1 on the sensor */
    int cap_peaks, cap_impacts;
    /* the current episode */
    double ep_start, ep_vin, ep_fmax, ep_tfmax, ep_fsample, ep_tsample;
    int ep_peaks, ep_cluster, ep_cluster_sample, ep_index;
    double t_end1, t_start2; /* end of the first episode, start of the second (NaN) */
    const gw_solver_type *type; /* the backend (the blow-up's advice) */
    double wg;               /* the largest work gravity has done so far, J */
    double t_sampled;        /* time of the last row given to o->sample (-inf: none) */
    /* progress (gw_chain_drop_run_progress): output samples of both passes */
    gw_progress_fn progress;
    void *pctx;
    double dt_out;           /* s, the drop's sampling */
    long total, next, step, base; /* base: samples before the pass under way */
    double reported_ms;      /* gw_clock_ms of the last report */
    int canceled;            /* the callback asked to stop */
    /* the column's lowest momentum toward the sensor in the first impact,
     * and 1 once it turned back toward it after the impact had turned it
     * away: gravity, not the damping, then holds bead 1 (chain_fell_back, as
     * chain_collide.c's held_by_gravity) */
    double q_min;
    int fell_back;
    /* the time past which bead 1 still on the sensor in its first contact
     * makes the first collision's plan refuse the run (a column held on the
     * wall by gravity, chain_collide_drop_held_t; INFINITY: never) */
    double t_held;
} drop_state;

/* Wall time after which the run reports even short of a hundredth of its
 * samples: a hundredth of `drop --n 1000 --t-max 1` took minutes, and the
 * program's display, which prints once a run has lasted 2 s, said nothing
 * for all that time (it cannot print what it is not told). */
#define DROP_PROGRESS_EVERY_MS 500.0

/* Report the pass under way at t (its own clock, from 0): done = base +
 * t / dt_out, about every hundredth of total or every DROP_PROGRESS_EVERY_MS
 * of wall time, whichever comes first (and at total). 1 when the callback
 * asks to stop. */
static int drop_progress(drop_state *st, double t)
{
    if (!st->progress)
        return 0;
    long done = st->base + (long)floor(t / st->dt_out + 1e-9);
    if (done > st->total)
        done = st->total;
    double now = gw_clock_ms();
    if (done < st->next && now - st->reported_ms < DROP_PROGRESS_EVERY_MS)
        return 0;
    st->reported_ms = now;
    st->next = done + st->step;
    if (st->progress(st->pctx, done, st->total) != 0)
        st->canceled = 1;
    return st->canceled;
}

/* The first collision's pass: progress only, the chain's result unchanged
 * (its sample callback observes; 1, a stop, ends it). */
static int first_progress(void *ctx, double t, const double *y, double f_wall, int is_event)
{
    (void)y, (void)f_wall, (void)is_event;
    return drop_progress(ctx, t);
}

/* The contacts as a peak reports them, into out[n]: the sensor's by its
 * episode flag, a bead pair's by its overlap, closed at overlap >= -dtol. The
 * root flags flip at zero overlap: beads the wave has not reached yet touch at
 * an overlap of 0 (or its precursor's 1e-15 m) that rounding makes -1e-21 m in
 * one run and not in another, so the flags gave the N = 40 drop's fourth peak
 * cluster 40 under cvode and 12 under arkode (and 40 or 15 at another peak
 * between rtol 1e-12 and 1e-13). */
static void contacts_of(const drop_state *st, const double *y, unsigned char *out)
{
    out[0] = st->closed[0];
    for (int k = 1; k < st->n; k++)
        out[k] = y[2 * k] - y[2 * k - 2] >= -st->dtol;
}

static int cluster_of(const drop_state *st, const double *y)
{
    if (!st->closed[0])
        return 0;
    int cl = 1;
    while (cl < st->n && y[2 * cl] - y[2 * cl - 2] >= -st->dtol)
        cl++;
    return cl;
}

static void episode_start(drop_state *st, double t, const double *y)
{
    st->in_episode = 1;
    st->ep_start = t;
    st->ep_vin = y[1];
    st->ep_fmax = st->ep_fsample = -1.0;
    st->ep_tfmax = st->ep_tsample = NAN;
    st->ep_peaks = 0;
    st->ep_cluster = st->ep_cluster_sample = 0;
    st->ep_index = -1;
    if (++st->r->n_episodes == 2)
        st->t_start2 = t;
}

/* The current episode as an impact record (appended on its first peak, or at
 * its end when it reached the threshold without a located peak). */
static int episode_record(drop_state *st)
{
    gw_chain_drop_result *r = st->r;
    if (st->ep_index >= 0)
        return GW_OK;
    if (r->n_impacts == st->cap_impacts) {
        int cap = st->cap_impacts ? 2 * st->cap_impacts : 64;
        gw_chain_drop_impact *ni = realloc(r->impacts, (size_t)cap * sizeof *ni);
        if (!ni)
            return GW_ENOMEM;
        r->impacts = ni;
        st->cap_impacts = cap;
    }
    st->ep_index = r->n_impacts++;
    gw_chain_drop_impact *im = &r->impacts[st->ep_index];
    im->t_start = st->ep_start;
    im->v_in = st->ep_vin;
    im->t_end = im->v_out = NAN;
    im->f_max = 0;
    im->t_fmax = NAN;
    im->n_peaks = 0;
    im->cluster = 0;
    im->located = 1;
    im->chatter = NAN; /* not run again (drop_chatter) */
    return GW_OK;
}

static void episode_sync(drop_state *st)
{
    if (st->ep_index < 0)
        return;
    gw_chain_drop_impact *im = &st->r->impacts[st->ep_index];
    im->n_peaks = st->ep_peaks;
    if (st->ep_peaks > 0) {
        im->f_max = st->ep_fmax;
        im->t_fmax = st->ep_tfmax;
        im->cluster = st->ep_cluster;
        im->located = 1;
    } else {
        im->f_max = st->ep_fsample;
        im->t_fmax = st->ep_tsample;
        im->cluster = st->ep_cluster_sample;
        im->located = 0;
    }
}

/* End of the episode at t (end == 0: still in contact at t_max). */
static int episode_end(drop_state *st, double t, const double *y, int end)
{
    if (!st->in_episode)
        return GW_OK;
    st->in_episode = 0;
    if (end && isnan(st->t_end1))
        st->t_end1 = t;
    /* the force at the episode's end (the located event's state, observed
     * only after this): a sensor body's reading k_s x_s + c v_s still rises
     * as bead 1 leaves, so the episode's largest force is there, no peak is
     * located inside it and its f_max was the last sample before the end
     * (drop --n 3 --sensor-mass 1e-4 --sensor-stiffness 1e3: 0.714172 N at
     * --dt-out 1e-6, 0.714384 at 3e-7). The start is observed after
     * episode_start, as every event's state */
    const double f = gw_chain_wall_force(st->d->c, y);
    if (f > st->ep_fsample) {
        st->ep_fsample = f;
        st->ep_tsample = t;
        st->ep_cluster_sample = cluster_of(st, y);
    }
    int rc = GW_OK;
    if (st->ep_index < 0 && st->ep_fsample >= st->p->peak_threshold && st->ep_fsample > 0)
        rc = episode_record(st);
    if (rc == GW_OK && st->ep_index >= 0) {
        episode_sync(st);
        gw_chain_drop_impact *im = &st->r->impacts[st->ep_index];
        im->t_end = end ? t : NAN;
        im->v_out = end ? y[1] : NAN;
    }
    return rc;
}

static int peak_add(drop_state *st, double t, const double *y, double f)
{
    gw_chain_drop_result *r = st->r;
    const int n = st->n;
    int rc = episode_record(st);
    if (rc != GW_OK)
        return rc;
    if (r->n_peaks == st->cap_peaks) {
        int cap = st->cap_peaks ? 2 * st->cap_peaks : 256;
        gw_chain_drop_peak *np = realloc(r->peaks, (size_t)cap * sizeof *np);
        if (np)
            r->peaks = np;
        unsigned char *nc = realloc(r->peak_contacts, (size_t)cap * (size_t)n);
        if (nc)
            r->peak_contacts = nc;
        if (!np || !nc)
            return GW_ENOMEM;
        st->cap_peaks = cap;
    }
    int cl = cluster_of(st, y);
    r->peaks[r->n_peaks] = (gw_chain_drop_peak){.t = t, .f = f, .impact = st->ep_index, .cluster = cl};
    contacts_of(st, y, r->peak_contacts + (size_t)r->n_peaks * (size_t)n);
    r->n_peaks++;
    st->ep_peaks++;
    if (f > st->ep_fmax) {
        st->ep_fmax = f;
        st->ep_tfmax = t;
        st->ep_cluster = cl;
    }
    if (!(f <= r->f_max)) { /* the first peak replaces the NaN of none */
        r->f_max = f;
        r->t_fmax = t;
    }
    episode_sync(st);
    return GW_OK;
}

/* Contact flags from the state, for transitions the root finders did not report
 * (see chain_collide.c, reconcile); the sensor's also open and close episodes. */
static int reconcile(drop_state *st, double t, const double *y)
{
    for (int k = 0; k < st->n; k++) {
        /* the sensor's contact by its gap (bead 1 less a sensor body's
         * displacement or a plastic dent), as its root: bead 1's position
         * alone, still inside the wall's plane where a damped body was slow
         * to come back, reopened the contact as bead 1 left and counted a
         * second impact (drop --n 2 --sensor-mass 1 --sensor-stiffness 1e6
         * --sensor-damping 1e3: n_impacts 2, the second "leaving" at -0.227
         * m/s) */
        double dd = k == 0 ? gw_chain_wall_gap(st->d->c, y) : y[2 * k] - y[2 * k - 2];
        if (!st->closed[k] && dd > st->dtol) {
            st->closed[k] = 1;
            st->r->missed_events++;
            if (k == 0)
                episode_start(st, t, y);
        } else if (st->closed[k] && dd < -st->dtol) {
            st->closed[k] = 0;
            st->r->missed_events++;
            if (k == 0) {
                int rc = episode_end(st, t, y, 1);
                if (rc != GW_OK)
                    return rc;
            }
        }
    }
    return GW_OK;
}

static int observe(drop_state *st, double t, const double *y, int is_event)
{
    gw_chain_drop_result *r = st->r;
    double f = gw_chain_wall_force(st->d->c, y);
    if (st->in_episode && f > st->ep_fsample) {
        st->ep_fsample = f;
        st->ep_tsample = t;
        st->ep_cluster_sample = cluster_of(st, y);
    }
    gw_chain_energy e;
    gw_chain_energy_of(st->d->c, y, &e);
    double err = chain_energy_rel_error(st->d->c, &e, r->e0, &st->wg);
    if (err > r->energy_error)
        r->energy_error = err;
    r->e_end = e;
    /* an event found exactly at an output time is observed by the root and by
     * the output, in the same state: one row (the trace held the row at
     * 2.51e-4 s twice; dF/dt from the files divided by zero there) */
    if (st->o->sample && t != st->t_sampled) {
        st->t_sampled = t;
        return st->o->sample(st->o->sample_ctx, t, y, f, is_event);
    }
    return 0;
}

/* Roots at t: contacts, then the state check, then the sensor, then peaks. */
static int on_roots(drop_state *st, double t, const double *y, const int *roots)
{
    gw_chain_drop_result *r = st->r;
    const int n = st->n;
    int wall = 0, rc;
    for (int k = 0; k < n; k++) {
        if (roots[k] == 0)
            continue;
        r->n_events++;
        if (roots[k] < 0 && st->closed[k]) {
            st->closed[k] = 0;
            if (k == 0)
                wall = -1;
        } else if (roots[k] > 0 && !st->closed[k]) {
            st->closed[k] = 1;
            if (k == 0)
                wall = 1;
        }
    }
    if (wall > 0)
        episode_start(st, t, y);
    else if (wall < 0 && (rc = episode_end(st, t, y, 1)) != GW_OK)
        return rc;
    if ((rc = reconcile(st, t, y)) != GW_OK)
        return rc;
    int im = gw_chain_force_max_root(st->d->c);
    if (roots[im] != 0)
        r->n_events++;
    if (roots[im] < 0 && st->in_episode && gw_chain_wall_gap(st->d->c, y) > 0) {
        double f = gw_chain_wall_force(st->d->c, y);
        if (f > 0 && f >= st->p->peak_threshold)
            return peak_add(st, t, y, f);
    }
    return GW_OK;
}

/* The first collision by the chain's own code, from the same state, until the
 * chain's end (every contact open, every pair separating) or, under gravity, at
 * the latest half way through bead 1's first flight: the chain's end may
 * otherwise never come, or only after bead 1 fell back on the sensor. */
static gw_chain_run_opts first_opts(const gw_chain_drop_params *p, const gw_chain_run_opts *o, drop_state *st,
                                    const double *y0)
{
    gw_chain_run_opts o1 = *o;
    o1.sample = st->progress ? first_progress : NULL;
    o1.sample_ctx = st;
    o1.dt_out = 0;
    o1.t_max = isnan(st->t_start2) ? p->t_max : 0.5 * (st->t_end1 + st->t_start2);
    o1.y0 = y0;
    return o1;
}

static int first_collision(const gw_chain *c, const gw_chain_drop_params *p,
                           const gw_chain_run_opts *o, const double *y0, drop_state *st,
                           gw_chain_drop_result *r, gw_err *err)
{
    gw_chain_run_opts o1 = first_opts(p, o, st, y0);
    int rc = chain_collide_drop(c, &o1, !isnan(st->t_start2), &r->first, err);
    r->first_status = rc;
    /* bead 1 never back on the sensor: the first collision ran to t_max, and ended
     * there unless the chain's end came first */
    r->first_cut = rc == GW_ELIMIT || (rc == GW_OK && isnan(st->t_start2) && !r->first.converged);
    return rc == GW_ELIMIT ? GW_OK : rc;
}

/* The run's hooks (gw_solver_drive). A sample callback's stop (> 0) ends the
 * run without an error, its failure (< 0) is the run's. */
static int drop_observed(drop_state *st, double t, const double *y, int is_event, gw_err *err)
{
    /* the first collision runs at least to the end of bead 1's first
     * contact: past t_held still in it, its plan refuses the run, which the
     * whole drop to t_max ran before (drop --n 1500: 27 s of CPU, then exit 2) */
    if (t > st->t_held && isnan(st->t_end1)) {
        gw_chain_run_opts o1 = *st->o;
        o1.dt_out = 0;
        o1.t_max = st->p->t_max;
        int hr = chain_collide_drop_held_refuse(st->d->c, &o1, err);
        if (hr != GW_OK)
            return hr;
        st->t_held = INFINITY;
    }
    int sr = observe(st, t, y, is_event);
    if (sr < 0)
        return gw_err_set(err, sr, "drop: the sample callback failed at t = %.9g s: %s", t, gw_strerror(sr));
    return sr > 0 ? GW_DRIVE_STOP : GW_DRIVE_ON;
}

static int drop_failed(int rc, gw_err *err)
{
    return rc == GW_ENOMEM ? gw_err_set(err, rc, "drop: out of memory for the peaks") : rc;
}

static int drop_root(void *ctx, double t, double *y, const int *roots, gw_err *err)
{
    drop_state *st = ctx;
    int rc = on_roots(st, t, y, roots);
    if (rc != GW_OK)
        return drop_failed(rc, err);
    rc = drop_observed(st, t, y, 1, err);
    return rc == GW_DRIVE_ON && chain_roots_need_reset(st->d->c, t, y, roots) ? GW_DRIVE_RESET : rc;
}

static int drop_output(void *ctx, double t, double *y, gw_err *err)
{
    drop_state *st = ctx;
    int rc = reconcile(st, t, y);
    rc = rc != GW_OK ? drop_failed(rc, err) : drop_observed(st, t, y, 0, err);
    return rc == GW_DRIVE_ON && drop_progress(st, t) ? GW_DRIVE_STOP : rc;
}

/* Record whether the column's momentum, turned away from the sensor by the
 * first impact, came back toward it while bead 1 was still on the sensor. */
static void first_impact_momentum(drop_state *st, const double *y)
{
    if (!st->in_episode || st->r->n_episodes != 1 || st->fell_back)
        return;
    double m;
    const double q = chain_momentum(st->d->c, y, &m);
    st->fell_back = chain_fell_back(&st->q_min, q, m * st->d->c->scale[1]);
}

static int drop_after(void *ctx, double t, const double *y, gw_err *err)
{
    drop_state *st = ctx;
    first_impact_momentum(st, y);
    if (chain_blown_up(st->d->c, y, st->r->energy_error, st->type, "drop", t, err) != GW_OK)
        return GW_ESOLVER;
    if (st->o->energy_tol > 0 && st->r->energy_error > st->o->energy_tol)
        return gw_err_set(err, GW_EENERGY, "drop: relative energy error %.3g exceeds the limit %.3g at t = %.9g s",
                          st->r->energy_error, st->o->energy_tol, t);
    return GW_DRIVE_ON;
}

static int drop_loop(drop_state *st, gw_solver *s, double *y, int *roots, gw_err *err)
{
    gw_chain_drop_result *r = st->r;
    double t = 0.0;
    int rc = drop_observed(st, t, y, 0, err);
    if (rc == GW_DRIVE_ON) {
        gw_drive drive = {.t_end = st->p->t_max, .dt_out = st->o->dt_out > 0 ? st->o->dt_out : 1e-6,
                          .k_out = 1, .what = "drop", .on_root = drop_root, .on_output = drop_output,
                          .after = drop_after, .ctx = st};
        rc = gw_solver_drive(s, &drive, &t, y, roots, err);
    } else if (rc == GW_DRIVE_STOP) {
        rc = GW_OK;
    }
    r->t_end = t;
    r->open_at_t_max = st->in_episode;
    if (st->in_episode) { /* still on the sensor: the episode counts as it stands */
        int rc2 = episode_end(st, t, y, 0);
        if (rc == GW_OK && rc2 != GW_OK)
            rc = gw_err_set(err, rc2, "drop: out of memory for the impacts");
    }
    /* Bead 1 stopped inside its first impact by a contact damping far above
     * critical (drop --damping kk --gamma 1e14, hc --alpha 1e8): the run said
     * "raise --t-max", naming nothing, though no t-max ends that impact. It
     * is the collision that granwave chain fails on (exit 1, the damping
     * named): the drop's first, whose tau_N and restitution are undecided at
     * any t-max; the same failure here, for every caller of the drop. A bead
     * that came to rest after a bounce is not this (its impacts are final),
     * nor one whose column gravity turned back onto the sensor (chain under
     * the same gravity warns "gravity holds the column" and exits 0). */
    if (rc == GW_OK && r->open_at_t_max && r->n_episodes == 1 && !st->fell_back && t >= st->p->t_max &&
        chain_damping_holds(gw_chain_get_params(st->d->c), y[1], st->d->c->scale[1]))
        rc = chain_damping_held_error(gw_chain_get_params(st->d->c), "drop", "sensor", t, "in its first impact, "
                                      "and it never rebounds (an overdamped contact: a longer t-max does not end it)",
                                      "", err);
    return rc;
}

int gw_chain_drop_run(const gw_chain_drop_params *p, const gw_chain_run_opts *o,
                      gw_chain_drop_result *r, gw_err *err)
{
    return gw_chain_drop_run_progress(p, o, NULL, NULL, r, err);
}

int chain_drop_work_check(const gw_chain_params *p, double t_max, gw_err *err)
{
    gw_chain_params w = *p;
    w.v_imp = chain_speed_scale(p);
    const double t_col = chain_collision_length(&w, NULL);
    return chain_column_work_check(p->n, fmin(t_max, t_col), t_col, "the first collision", "n", "t-max", err);
}

static int drop_run(const gw_chain_drop_params *p, const gw_chain_run_opts *o, gw_progress_fn progress, void *pctx,
                    int rerun, gw_chain_drop_result *r, gw_err *err);

int gw_chain_drop_run_progress(const gw_chain_drop_params *p, const gw_chain_run_opts *o, gw_progress_fn progress,
                               void *pctx, gw_chain_drop_result *r, gw_err *err)
{
    return drop_run(p, o, progress, pctx, 0, r, err);
}

/* The drop's own chatter on a sensor body (gw_chain_drop_result's
 * chatter_kind): as chain's (chain_collide.c, chatter_spread), over its
 * contact episodes. drop --n 3 --sensor-mass 1e-4 --sensor-stiffness 1e3 made
 * 44 in 10 ms without a word; its impacts' F_max moved by 6.1e-8 (the first)
 * to 9.8e-6 (the 21st) between rtol 1e-12 and 1e-13, their v_out by up to
 * 1.1e-5 m/s. A run with GW_CHAIN_CHATTER_CONTACTS episodes or more is run
 * again when its steps times bodies are at most GW_CHAIN_CHATTER_WORK (the
 * drop alone: its first collision is chain's and checked there), sp the
 * run's resolved solver settings and type its backend; each impact gets the
 * relative change of its F_max (1: absent from the other run), the result
 * the largest. */
static void drop_chatter(const gw_chain_drop_params *p, const gw_chain_run_opts *o, const gw_chain *c,
                         const gw_solver_type *type, const gw_solver_params *sp, gw_chain_drop_result *r)
{
    r->chatter_kind = GW_CHAIN_CHATTER_NONE;
    r->chatter_spread = 0;
    if (gw_chain_sensor_index(c) < 0)
        return;
    r->chatter_rerun = type == gw_solver_rk4 ? GW_CHAIN_RERUN_STEP : GW_CHAIN_RERUN_TOL;
    if (r->n_episodes < GW_CHAIN_CHATTER_CONTACTS)
        return;
    /* rk4's rerun at half the step costs twice the drop's steps (the first
     * collision is not run again), known before it is made: made up to
     * GW_CHAIN_DROP_CHATTER_RK4_WORK (about 11 s of CPU at most), the whole
     * run then about 3 times the run without it. The tolerances' rerun's cost is not known before it
     * is made: bounded as chain's. */
    const double work_max = type == gw_solver_rk4 ? GW_CHAIN_DROP_CHATTER_RK4_WORK : GW_CHAIN_CHATTER_WORK;
    if (!((double)r->stats.steps * r->n <= work_max)) {
        r->chatter_kind = GW_CHAIN_CHATTER_COSTLY;
        return;
    }
    gw_chain_run_opts o2 = *o;
    o2.sample = NULL;
    o2.sample_ctx = NULL;
    o2.sp = *sp;
    char how[96], flags[80];
    chain_chatter_rerun(type, r->run_dt, &o2.sp, how, sizeof how, flags, sizeof flags);
    gw_chain_drop_result r2;
    gw_err e2 = {{0}};
    if (drop_run(p, &o2, NULL, NULL, 1, &r2, &e2) != GW_OK) {
        r->chatter_kind = GW_CHAIN_CHATTER_FAILED;
        gw_chain_drop_result_free(&r2);
        return;
    }
    double spread = 0;
    for (int j = 0; j < r->n_impacts; j++) {
        gw_chain_drop_impact *im = &r->impacts[j];
        im->chatter = j < r2.n_impacts && im->f_max > 0 ? fabs(im->f_max - r2.impacts[j].f_max) / im->f_max : 1.0;
        spread = fmax(spread, im->chatter);
    }
    if (r2.n_impacts > r->n_impacts || r2.n_episodes != r->n_episodes)
        spread = fmax(spread, 1.0);
    if (spread > GW_CHAIN_CHATTER_SPREAD) {
        r->chatter_kind = GW_CHAIN_CHATTER_MOVED;
        r->chatter_spread = spread;
    }
    gw_chain_drop_result_free(&r2);
}

static int drop_run(const gw_chain_drop_params *p, const gw_chain_run_opts *o, gw_progress_fn progress, void *pctx,
                    int rerun, gw_chain_drop_result *r, gw_err *err)
{
    if (r) /* NULL refused as gw_chain_collide does (it was dereferenced: SIGSEGV) */
        memset(r, 0, sizeof *r);
    if (!p || !o || !r)
        return gw_err_set(err, GW_EINVAL, "gw_chain_drop_run: %s is NULL", !p ? "p" : !o ? "o" : "r");
    /* no peak at or above the threshold: both NaN (JSON null), as t_fmax was;
     * an f_max of 0 read as a measured force of a sensor that saw 72 N (drop
     * --n 2 --peak-threshold 1e9) */
    r->f_max = NAN;
    r->t_fmax = NAN;
    int rc = gw_chain_drop_params_validate(p, err);
    if (rc == GW_OK) /* before anything is allocated */
        rc = gw_chain_memory_check(&p->chain, o->solver, o->sp.method, err);
    if (rc == GW_OK) { /* and the column's work (chain_drop_work_check) */
        gw_chain_params w = p->chain;
        w.v_imp = sqrt(2.0 * p->chain.gravity * p->height);
        rc = chain_drop_work_check(&w, p->t_max, err);
    }
    if (rc != GW_OK)
        return rc;
    const int n = p->chain.n;
    const double g = p->chain.gravity;
    gw_chain_params q = p->chain;
    q.v_imp = sqrt(2.0 * g * p->height);
    r->n = n;
    r->v_imp = q.v_imp;
    r->t_fall = sqrt(2.0 * p->height / g);

    gw_chain *c = NULL;
    gw_solver *s = NULL;
    drop_sys d;
    memset(&d, 0, sizeof d);
    drop_state st = {.d = &d, .p = p, .o = o, .r = r, .n = n, .t_end1 = NAN, .t_start2 = NAN, .t_sampled = -INFINITY,
                     .t_held = INFINITY,
                     .progress = progress, .pctx = pctx, .dt_out = o->dt_out > 0 ? o->dt_out : 1e-6};
    /* the drop over t_max, then its first collision again by the chain's own
     * code (first_collision), at most as long: nearly as much work again (43
     * and 49 % of the wall time in two runs of the 300-bead drop over the
     * default 10 ms, whose first collision lasts it through). Both passes in
     * one count, the second's end reported as the total when it stops earlier. */
    st.total = 2 * (long)floor(p->t_max / st.dt_out + 1e-9);
    st.step = st.total / 100 > 0 ? st.total / 100 : 1;
    st.next = st.step;
    st.reported_ms = gw_clock_ms();
    double *y = NULL, *y0 = NULL;
    int *roots = NULL;
    if ((rc = gw_chain_create(&q, &c, err)) != GW_OK)
        goto done;
    d.c = c;
    d.cs = gw_chain_system(c);
    d.n = n;
    d.sys = *d.cs;
    d.sys.params = &d;
    d.sys.rhs = drop_rhs;
    /* the chain's rhs by ranges reads the chain as its params, not this
     * system's: kept, CVODE Adams and ARKode ERK called it with the drop's
     * params (a crash, granwave drop --solver cvode --method adams) */
    d.sys.rhs_range = NULL;
    d.sys.rhs_halo = 0;
    d.sys.rhs_ex = d.cs->rhs_ex ? drop_rhs_ex : NULL;
    d.sys.rhs_im = d.cs->rhs_im ? drop_rhs_im : NULL;
    d.sys.jac = d.cs->jac ? drop_jac : NULL;
    d.sys.roots = drop_roots;
    const long dim = d.sys.dim;
    y = malloc(2 * (size_t)dim * sizeof *y);
    y0 = y + dim;
    roots = calloc((size_t)d.sys.nroots, sizeof *roots);
    st.closed = calloc((size_t)n, 1);
    if (!y || !roots || !st.closed) {
        rc = gw_err_set(err, GW_ENOMEM, "drop: out of memory for %d beads", n);
        goto done;
    }
    /* the state at the first contact: bead 1 touching, the others above it */
    gw_chain_initial_state(c, y);
    for (int i = 1; i < n; i++)
        y[2 * i] = y[2 * i - 2] - (p->gaps ? p->gaps[i - 1] : 0.0);
    memcpy(y0, y, (size_t)dim * sizeof *y);

    double m0 = gw_chain_bead_mass(c, 0);
    st.dtol = 1e-9 * gw_chain_dmax1(m0, q.kwall, q.v_imp);
    for (int k = 0; k < n; k++)
        st.closed[k] = (k == 0 ? gw_chain_wall_gap(c, y) : y[2 * k] - y[2 * k - 2]) >= 0;
    gw_chain_energy e;
    gw_chain_energy_of(c, y, &e);
    r->e0 = e.total;
    r->e_end = e;
    episode_start(&st, 0.0, y);

    gw_solver_params sp = o->sp;
    /* as gw_chain_collide: no step may hold a whole contact; the fastest contacts
     * of the drop are those of the first collision (relative speeds up to about
     * 2 v_imp, the top beads leaving at < 2 v_imp and returning at that speed) */
    if (!(sp.dt_max > 0))
        sp.dt_max = 0.25 * chain_contact_tau_min(&q, 2 * q.v_imp); /* the wall's too */
    const gw_solver_type *type = o->solver ? o->solver : gw_solver_cvode;
    if (type == gw_solver_rk4 && !(sp.dt > 0))
        sp.dt = chain_rk4_default_dt(&q, o->steps_per_tc);
    /* the drop runs to t_max whatever happens: its steps bounded over t_max
     * (the default RK4 step makes about 4e5 over 10 ms) */
    /* the step taken (every backend at most dt_max, rk4's steps ending at the
     * samples of drop_loop), beside the dt given: chain_collide.c's record */
    const double dt_out_run = o->dt_out > 0 ? o->dt_out : 1e-6;
    r->run_dt_given = o->sp.dt > 0 ? o->sp.dt : 0.0;
    r->run_dt = type == gw_solver_rk4 ? fmin(fmin(sp.dt, sp.dt_max), dt_out_run)
                                      : sp.dt > 0 ? fmin(sp.dt, sp.dt_max) : sp.dt;
    r->run_dt_max = sp.dt_max;
    /* and the first collision's own bounds (not known before: at most t_max) */
    gw_chain_run_opts o1 = first_opts(p, o, &st, y0);
    if ((rc = chain_drag_steps_check(&q, type, &sp, &o->sp, o->steps_per_tc, p->t_max, p->t_max, "t-max", err)) !=
            GW_OK ||
        (rc = chain_steps_check(type, &sp, &o->sp, p->t_max, "t-max", err)) != GW_OK ||
        (rc = chain_sensor_steps_check(&q, type, &sp, p->t_max, "t-max", err)) != GW_OK ||
        (rc = chain_ring_explicit_check(&q, type, &sp, p->t_max, "t-max", err)) != GW_OK ||
        (rc = chain_collide_drop_check(c, &o1, err)) != GW_OK)
        goto done;
    if (!rerun) /* the rerun of the chatter check runs no first collision */
        st.t_held = chain_collide_drop_held_t(c, &o1);
    st.type = type;
    if ((rc = gw_solver_create(type, &d.sys, &sp, 0.0, y, &s, err)) != GW_OK)
        goto done;
    rc = chain_step_limit_named(drop_loop(&st, s, y, roots, err), s, &sp, err);
    gw_solver_get_stats(s, &r->stats);
    st.base = st.total / 2;
    if (rc == GW_OK && !st.canceled && !rerun)
        rc = first_collision(c, p, o, y0, &st, r, err);
    if (rc == GW_OK && !st.canceled && !rerun)
        drop_chatter(p, o, c, type, &sp, r);
    if (rc == GW_OK && !st.canceled && progress && st.next < st.total + st.step &&
        progress(pctx, st.total, st.total) != 0) /* the last report: the first collision may end early */
        st.canceled = 1;
    if (rc == GW_OK && st.canceled && st.base == 0)
        rc = gw_err_set(err, GW_ECANCELED, "drop: stopped by the progress callback at t = %.9g s", r->t_end);
    else if (rc == GW_OK && st.canceled)
        rc = gw_err_set(err, GW_ECANCELED, "drop: stopped by the progress callback after the drop to t = %.9g s, "
                        "in the run of its first collision (the chain's own)", r->t_end);
done:
    gw_solver_free(s);
    gw_chain_free(c);
    free(y);
    free(roots);
    free(st.closed);
    return rc;
}

void gw_chain_drop_result_free(gw_chain_drop_result *r)
{
    if (!r)
        return;
    gw_chain_result_free(&r->first);
    free(r->peaks);
    free(r->peak_contacts);
    free(r->impacts);
    r->peaks = NULL;
    r->peak_contacts = NULL;
    r->impacts = NULL;
    r->n_peaks = r->n_impacts = 0;
}

int gw_chain_drop_impact_rises(const gw_chain_drop_result *r)
{
    /* a result filled by hand with a count and no array (read through NULL:
     * SIGSEGV) holds no impacts, as one of a count below 2 */
    if (!r || !r->impacts)
        return 0;
    int rises = 0;
    for (int j = 1; j < r->n_impacts; j++)
        rises += r->impacts[j].f_max > r->impacts[j - 1].f_max * (1.0 + GW_CHAIN_DROP_RISE_REL);
    return rises;
}
