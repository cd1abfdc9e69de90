/*
 * chain_sweep.c: independent collisions over a grid of (v_imp, N), spread over
 * threads by the worker pool (gw_cases_run, gw_pool.h). Each case builds its own chain and
 * solver (one SUNDIALS context per solver, hence per thread), so cases share
 * nothing but the case counter.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chain_model.h"
#include "chain_wall.h"
#include "chain_watch.h"
#include "gw_chain.h"
#include "gw_locale.h"
#include "gw_pool.h"

/* Steps a whole study may take, summed over its columns: each run is bounded at
 * 1e8 before it starts, but a study of 200 columns each near that bound (rk4 with
 * a stiff sensor body: 2-3 s a column at N = 3, more as N grows) ran for many
 * minutes with nothing refused. RK4 takes 0.26 us a step at N = 3 with a sensor
 * body (measured), so 1e9 steps are a few minutes of CPU; the default falcon study
 * takes about 3.2e5 (measured). */
#define CHAIN_STUDY_STEPS_MAX 1e9

/* The expected steps of every column of the study, added up (*worst: the case
 * with the most). */
static int study_steps(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv, int n_lo,
                       int n_hi, double *total, long *worst, double *worst_steps, gw_err *err)
{
    *total = *worst_steps = 0;
    *worst = 0;
    for (int i = 0; i < nv; i++)
        for (int n = n_lo; n <= n_hi; n++) {
            gw_chain_params p = *tmpl;
            p.n = n;
            p.v_imp = v[i];
            double s;
            int rc = chain_run_steps(&p, o, &s, err);
            if (rc != GW_OK)
                return rc;
            *total += s;
            if (s > *worst_steps) {
                *worst_steps = s;
                *worst = (long)i * (n_hi - n_lo + 1) + (n - n_lo);
            }
        }
    return GW_OK;
}

/* GW_EINVAL when the study's steps add up above CHAIN_STUDY_STEPS_MAX, naming what
 * to change: the sensor body when the study passes without it, else the step the
 * caller gave, else the columns. */
static int study_steps_check(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv,
                             int n_lo, int n_hi, gw_err *err)
{
    double total, most;
    long worst;
    int rc = study_steps(tmpl, o, v, nv, n_lo, n_hi, &total, &worst, &most, err);
    if (rc != GW_OK || total <= CHAIN_STUDY_STEPS_MAX)
        return rc;
    const char *name = "n", *advice = "fewer columns or velocities";
    gw_chain_params bare = *tmpl;
    bare.sensor.mass = bare.sensor.stiffness = bare.sensor.damping = 0;
    double t2, m2;
    long w2;
    gw_err e2 = {{0}};
    int rk4 = o->solver == gw_solver_rk4;
    /* the sensor body's damping alone (the explicit methods' steps follow its
     * decay, chain_drag_steps_check) before its oscillation */
    gw_chain_params undamped = *tmpl;
    undamped.sensor.damping = 0;
    if (tmpl->sensor.damping > 0 && !(rk4 && o->sp.dt > 0) &&
        study_steps(&undamped, o, v, nv, n_lo, n_hi, &t2, &w2, &m2, &e2) == GW_OK && t2 <= CHAIN_STUDY_STEPS_MAX) {
        name = "sensor-damping";
        advice = "cvode with its default method bdf (implicit: its step is not held by the damping), a smaller "
                 "damping, or fewer columns";
    } else if (tmpl->sensor.mass > 0 && tmpl->sensor.stiffness > 0 && !(rk4 && o->sp.dt > 0) &&
        study_steps(&bare, o, v, nv, n_lo, n_hi, &t2, &w2, &m2, &e2) == GW_OK && t2 <= CHAIN_STUDY_STEPS_MAX) {
        name = "sensor-stiffness";
        advice = "a softer or heavier sensor body (its oscillation sets the step), cvode, or fewer columns";
    } else if (rk4 && o->sp.dt > 0) {
        name = "dt";
        advice = "raise it, or fewer columns or velocities";
    } else if (o->sp.dt_max > 0) {
        name = "dt-max";
        advice = "raise it, or fewer columns or velocities";
    }
    const int per_v = n_hi - n_lo + 1;
    return gw_err_set(err, GW_EINVAL, "%s: the study's %ld collisions need about %.3g steps in all (N = %d at %g m/s "
                      "alone about %.3g); at most %.0e a study: %s", name, (long)nv * per_v, total,
                      n_lo + (int)(worst % per_v), v[worst / per_v], most, CHAIN_STUDY_STEPS_MAX, advice);
}

typedef struct sweep {
    const gw_chain_params *tmpl;
    const gw_chain_run_opts *o;
    const double *v;
    int n_lo, per_v;
    gw_chain_result *res;
    chain_watch *watch; /* the study's, or NULL */
} sweep;

static int one(void *arg, long k, gw_err *err)
{
    const sweep *w = arg;
    gw_chain_params p = *w->tmpl;
    p.v_imp = w->v[k / w->per_v];
    p.n = w->n_lo + (int)(k % w->per_v);
    gw_chain *c = NULL;
    gw_err e = {{0}};
    int rc = gw_chain_create(&p, &c, &e);
    if (rc == GW_OK)
        rc = chain_watch_collide(w->watch, c, &p, w->o, &w->res[k], &e);
    gw_chain_free(c);
    if (rc != GW_OK)
        gw_err_set(err, rc, "N = %d, v_imp = %g m/s: %s", p.n, p.v_imp, e.msg);
    return rc;
}

/* Two speeds of a grid as one: equal, or within a relative 1e-12, a
 * difference only printing makes. The chain sweep config's rule for a value
 * listed twice (GW_SWEEP_SAME_REL, gw_sweep_config.c), so that a speed given
 * twice is refused alike by the config, by this call and by Python's
 * granwave.sweep_n. The grid has no fit over its speeds (falcon's 1e-6 rule,
 * gw_chain_study_speeds_check, is its fits'): only a repeat is refused. */
#define CHAIN_SWEEP_SAME_REL 1e-12

typedef struct grid_speed {
    double v;
    int i;
} grid_speed;

static int grid_speed_cmp(const void *pa, const void *pb)
{
    const grid_speed *a = pa, *b = pb;
    const int na = isnan(a->v), nb = isnan(b->v); /* NaN last: an order qsort can keep */
    if (na != nb)
        return na - nb;
    if (!na && a->v != b->v)
        return a->v < b->v ? -1 : 1;
    return (a->i > b->i) - (a->i < b->i);
}

/* GW_EINVAL naming the first repeated speed of v (the pair j < i with i
 * smallest, then j), items counted from 1: `granwave.sweep_n((1, 2), [0.3,
 * 0.3])` ran every collision of the speed twice into two rows of its result.
 * Sorted, so nv speeds cost nv log nv. Speeds not finite are left to their
 * cases' refusal. */
static int sweep_speeds_check(const double *v, int nv, gw_err *err)
{
    if (nv < 2)
        return GW_OK;
    grid_speed *s = malloc((size_t)nv * sizeof *s);
    if (!s)
        return gw_err_set(err, GW_ENOMEM, "gw_chain_sweep_n: out of memory for %d speeds", nv);
    for (int k = 0; k < nv; k++)
        s[k] = (grid_speed){v[k], k};
    qsort(s, (size_t)nv, sizeof *s, grid_speed_cmp);
    int j = -1, i = nv;
    for (int k = 1; k < nv; k++) {
        const double a = s[k - 1].v, b = s[k].v;
        /* only finite speeds repeat: NaN and inf are refused by their
         * cases' own words (gw_chain_params_validate), as falcon leaves them */
        if (!isfinite(a) || !isfinite(b) ||
            !(a == b || fabs(b - a) <= CHAIN_SWEEP_SAME_REL * fmax(fabs(a), fabs(b))))
            continue;
        const int lo = s[k - 1].i < s[k].i ? s[k - 1].i : s[k].i, hi = s[k - 1].i ^ s[k].i ^ lo;
        if (hi < i || (hi == i && lo < j))
            j = lo, i = hi;
    }
    free(s);
    if (j < 0)
        return GW_OK;
    char vj[32], vi[32];
    if (v[i] == v[j])
        return gw_err_set(err, GW_EINVAL, "gw_chain_sweep_n: v: item %d is the impact velocity %s m/s of item %d "
                          "(each of its collisions would run twice)", i + 1, gw_num_text(vi, sizeof vi, v[i]), j + 1);
    return gw_err_set(err, GW_EINVAL, "gw_chain_sweep_n: v: item %d, %s m/s, and item %d, %s m/s, are the same "
                      "impact velocity to 12 digits (each of its collisions would run twice)", i + 1,
                      gw_num_text(vi, sizeof vi, v[i]), j + 1, gw_num_text(vj, sizeof vj, v[j]));
}

/* The grid's checks before any case runs (its arguments, the largest
 * column's bounds at each speed, no speed repeated, the study's steps); res
 * zeroed once the grid's shape passed. */
static int sweep_check(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv, int n_lo,
                       int n_hi, gw_chain_result *res, gw_err *err)
{
    if (!tmpl || !o || !v || !res)
        return gw_err_set(err, GW_EINVAL, "gw_chain_sweep_n: %s is NULL",
                          !tmpl ? "tmpl" : !o ? "o" : !v ? "v" : "res");
    if (nv < 1 || n_lo < 1 || n_hi < n_lo)
        return gw_err_set(err, GW_EINVAL, "gw_chain_sweep_n: empty grid (nv = %d speeds, N = n_lo %d .. n_hi %d)",
                          nv, n_lo, n_hi);
    memset(res, 0, (size_t)nv * (size_t)(n_hi - n_lo + 1) * sizeof *res);
    /* the largest column's bounds (steps, memory, samples grow with n) at each
     * speed before any runs: a study was refused only when its run reached that
     * column (softwall --solver rk4 --dt 1e-12 spent minutes on N = 1 first) */
    for (int i = 0; i < nv; i++) {
        gw_chain_params p = *tmpl;
        p.n = n_hi;
        p.v_imp = v[i];
        int rc = gw_chain_run_check(&p, o, err);
        if (rc != GW_OK)
            return rc;
    }
    int rc = sweep_speeds_check(v, nv, err);
    if (rc != GW_OK)
        return rc;
    return study_steps_check(tmpl, o, v, nv, n_lo, n_hi, err);
}

int chain_sweep_check(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv, int n_lo,
                      int n_hi, gw_chain_result *res, gw_err *err)
{
    return sweep_check(tmpl, o, v, nv, n_lo, n_hi, res, err);
}

/* the grid's cases, checked */
static int sweep_cases(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv, int n_lo,
                       int n_hi, int jobs, gw_progress_fn progress, void *pctx, chain_watch *watch,
                       gw_chain_result *res, gw_err *err)
{
    sweep w = {tmpl, o, v, n_lo, n_hi - n_lo + 1, res, watch};
    return gw_cases_run((long)nv * w.per_v, jobs, one, &w, progress, pctx, err);
}

int chain_sweep_watch(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv, int n_lo,
                      int n_hi, int jobs, gw_progress_fn progress, void *pctx, chain_watch *watch,
                      gw_chain_result *res, gw_err *err)
{
    int rc = sweep_check(tmpl, o, v, nv, n_lo, n_hi, res, err);
    if (rc != GW_OK)
        return rc;
    return sweep_cases(tmpl, o, v, nv, n_lo, n_hi, jobs, progress, pctx, watch, res, err);
}

int gw_chain_sweep_n_progress(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v,
                              int nv, int n_lo, int n_hi, int jobs, gw_progress_fn progress, void *pctx,
                              gw_chain_result *res, gw_err *err)
{
    return chain_sweep_watch(tmpl, o, v, nv, n_lo, n_hi, jobs, progress, pctx, NULL, res, err);
}

int gw_chain_sweep_n(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv,
                     int n_lo, int n_hi, int jobs, int progress, gw_chain_result *res, gw_err *err)
{
    (void)progress; /* the library prints nothing: progress goes through gw_chain_sweep_n_progress */
    return gw_chain_sweep_n_progress(tmpl, o, v, nv, n_lo, n_hi, jobs, NULL, NULL, res, err);
}

/* The grid's cases as a chain sweep's check pass tallies them (a damping
 * model with a constant of 0, a contact damping, sensor dashpot or guide
 * friction below the case's rtol), in its texts and count form ("in 2 of 4
 * cases (the first, case 0)", case k the result's index). The grid said
 * none: the studies on it (falcon, wavespeed, softwall) said them. */
static int sweep_n_warnings(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv,
                            int n_lo, int n_hi, char **list)
{
    const int per_v = n_hi - n_lo + 1;
    const long total = (long)nv * per_v;
    const double rtol = o->sp.rtol; /* the run's own (chain_collide's), as the sweep's case_settings read it */
    int zero = 0, small = 0;
    double small_hi = 0;
    chain_drag_cases drag = {0, 0, 0, 0, 0, 0};
    for (long k = 0; k < total; k++) {
        gw_chain_params p = *tmpl;
        p.v_imp = v[k / per_v];
        p.n = n_lo + (int)(k % per_v);
        zero += chain_damping_zero(&p);
        if (chain_damping_small(&p, rtol)) { /* the single run's test */
            const double e = chain_damping_effect(&p);
            small_hi = small++ ? fmax(small_hi, e) : e;
        }
        chain_drag_cases_add(&drag, &p, rtol, k);
    }
    int rc = chain_damping_zero_warnings(NULL, zero, (int)total, list);
    rc = rc == GW_OK ? chain_damping_small_cases_warning(small, (int)total, small_hi, list) : rc;
    return rc == GW_OK ? chain_drag_cases_warnings(&drag, total, list) : rc;
}

int gw_chain_sweep_n_warned(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv,
                            int n_lo, int n_hi, int jobs, gw_progress_fn progress, void *pctx, gw_chain_result *res,
                            char **warnings, gw_err *err)
{
    int rc = sweep_check(tmpl, o, v, nv, n_lo, n_hi, res, err);
    if (rc != GW_OK) /* a grid refused: nothing appended (as gw_sweep_run_warned's check pass) */
        return rc;
    /* the check pass's warnings, before the cases run: kept when one fails */
    if (warnings && sweep_n_warnings(tmpl, o, v, nv, n_lo, n_hi, warnings) != GW_OK)
        return gw_err_set(err, GW_ENOMEM, "gw_chain_sweep_n: out of memory");
    return sweep_cases(tmpl, o, v, nv, n_lo, n_hi, jobs, progress, pctx, NULL, res, err);
}
