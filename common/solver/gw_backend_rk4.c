/*
 * gw_backend_rk4.c: classic fixed-step fourth-order Runge-Kutta, written here as
 * an independent cross-check of the SUNDIALS backends.
 *
 * Events: after every step the root functions are compared with their sign at
 * the start of the step. A component that changed sign is located by the
 * Illinois (modified regula falsi) method on the step length h, each trial being
 * a full RK4 step from the start of the step, so the located event lies on the
 * RK4 solution itself. The integrator lands just past the earliest root (on the
 * new-sign side, within a time tolerance of 1e-12 dt), which is where a restart
 * puts the model. Components that are exactly zero are inactive until they move
 * away from zero (the same convention as CVODE's and ARKode's root finders).
 * The last step before tout is shortened to land on tout exactly.
 * With gw_system.roots_at_step_end a root is reported at the end of the step in
 * which it changed sign (as verlet does), so the step grid does not depend on the
 * roots, and gw_system.project (if any) runs after every step, before the roots.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_solver_impl.h"

#ifdef __SSE2__
#include <emmintrin.h>
#endif

typedef struct rk4_impl {
    double t;
    double *y, *ynew, *ytry, *k1, *k2, *k3, *k4, *tmp;
    double *g, *g0, *gtry; /* g at step end, step start, trial */
    signed char *sign; /* reference sign of each root function, 0 = inactive */
    double *sgn;       /* sign[k] as a double, for the scan at each step's end */
    int ninactive;     /* how many sign[k] are 0 (the end of a step looks at them only then) */
    double *ymem, *gmem; /* the allocations (y and ynew, g and g0 swap places) */
    long steps, rhs_evals, root_evals;
} rk4_impl;

static void rk4_destroy(gw_solver *s)
{
    rk4_impl *r = s->impl;
    if (!r)
        return;
    free(r->ymem);
    free(r->gmem);
    free(r->sign);
    free(r);
    s->impl = NULL;
}

/* One RK4 step of length h from (t, y0) into out (y0, out and the stage
 * arrays are distinct, hence restrict: the loops vectorise without alias checks).
 * Also compiled for AVX (chosen when the program loads; AVX without FMA does the
 * same IEEE operations, so the same numbers): half the instructions per element. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx", "default")))
#endif
static int rk4_step(gw_solver *s, double t, const double *restrict y0, double h,
                    double *restrict out)
{
    rk4_impl *r = s->impl;
    const long n = s->sys.dim;
    void *P = s->sys.params;
    double *restrict tmp = r->tmp, *restrict k1 = r->k1, *restrict k2 = r->k2;
    double *restrict k3 = r->k3, *restrict k4 = r->k4;
    const double h2 = 0.5 * h, h6 = h / 6.0;
    int rc;
    if ((rc = s->sys.rhs(t, y0, k1, P)) != 0)
        return rc;
    for (long i = 0; i < n; i++)
        tmp[i] = y0[i] + h2 * k1[i];
    if ((rc = s->sys.rhs(t + 0.5 * h, tmp, k2, P)) != 0)
        return rc;
    for (long i = 0; i < n; i++)
        tmp[i] = y0[i] + h2 * k2[i];
    if ((rc = s->sys.rhs(t + 0.5 * h, tmp, k3, P)) != 0)
        return rc;
    for (long i = 0; i < n; i++)
        tmp[i] = y0[i] + h * k3[i];
    if ((rc = s->sys.rhs(t + h, tmp, k4, P)) != 0)
        return rc;
    for (long i = 0; i < n; i++)
        out[i] = y0[i] + h6 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    r->rhs_evals += 4;
    return 0;
}

static int rk4_roots(gw_solver *s, double t, const double *y, double *g)
{
    rk4_impl *r = s->impl;
    r->root_evals++;
    return s->sys.roots(t, y, g, s->sys.params);
}

/* After sign[] changed: its copy in doubles, and how many are inactive (0). */
static void signs_changed(rk4_impl *r, int nr)
{
    int z = 0;
    for (int k = 0; k < nr; k++) {
        z += r->sign[k] == 0;
        r->sgn[k] = r->sign[k];
    }
    r->ninactive = z;
}

static void rk4_init_signs(gw_solver *s)
{
    rk4_impl *r = s->impl;
    for (int k = 0; k < s->sys.nroots; k++)
        r->sign[k] = (signed char)gw_sgn(r->g0[k]);
    signs_changed(r, s->sys.nroots);
}

/* Did any component cross (gw_root_crossed for some k)? For a sign s of +-1,
 * sgn(g) != s exactly when !(s g > 0) (s g is exact; NaN compares false), so
 * one vectorised pass without branches tells, and a step without events
 * (nearly every step of a column, whose every contact has a root function)
 * costs about one instruction per root. */
static int any_crossed(const rk4_impl *r, const double *restrict g, int nr)
{
    const double *restrict sg = r->sgn;
    int k = 0, any = 0;
#ifdef __SSE2__
    const __m128d zero = _mm_setzero_pd();
    __m128d acc = zero; /* lanes of all ones where crossed */
    for (; k + 2 <= nr; k += 2) {
        __m128d s2 = _mm_loadu_pd(sg + k);
        __m128d on = _mm_cmpneq_pd(s2, zero);
        __m128d kept = _mm_cmpgt_pd(_mm_mul_pd(s2, _mm_loadu_pd(g + k)), zero); /* false for NaN */
        acc = _mm_or_pd(acc, _mm_andnot_pd(kept, on));
    }
    any = _mm_movemask_pd(acc);
#endif
    for (; k < nr; k++)
        any |= (sg[k] != 0) & !(sg[k] * g[k] > 0);
    return any != 0;
}

static int rk4_create(gw_solver *s, double t0, const double *y0, gw_err *err)
{
    if (!(s->p.dt > 0))
        return gw_err_set(err, GW_EINVAL, "rk4: the fixed step dt must be set (> 0)");
    if (s->p.method != GW_METHOD_DEFAULT)
        return gw_err_set(err, GW_EUNSUPPORTED, "rk4: method '%s' not offered",
                          gw_solver_method_name(s->p.method));
    rk4_impl *r = calloc(1, sizeof *r);
    if (!r)
        return gw_err_set(err, GW_ENOMEM, "rk4: out of memory");
    s->impl = r;
    const size_t n = (size_t)s->sys.dim, nr = (size_t)s->sys.nroots;
    r->y = r->ymem = malloc(8 * n * sizeof *r->y);
    r->g = r->gmem = malloc((4 * nr + 1) * sizeof *r->g);
    r->sign = calloc(nr + 1, 1);
    if (!r->y || !r->g || !r->sign) {
        rk4_destroy(s);
        return gw_err_set(err, GW_ENOMEM, "rk4: out of memory");
    }
    r->ynew = r->y + n;
    r->ytry = r->y + 2 * n;
    r->k1 = r->y + 3 * n;
    r->k2 = r->y + 4 * n;
    r->k3 = r->y + 5 * n;
    r->k4 = r->y + 6 * n;
    r->tmp = r->y + 7 * n;
    r->g0 = r->g + nr;
    r->gtry = r->g + 2 * nr;
    r->sgn = r->g + 3 * nr;
    memcpy(r->y, y0, n * sizeof *y0);
    r->t = t0;
    if (nr > 0) {
        if (rk4_roots(s, t0, r->y, r->g0) != 0) {
            rk4_destroy(s);
            return gw_err_set(err, GW_ESOLVER, "rk4: root function failed at t0");
        }
        rk4_init_signs(s);
    }
    return GW_OK;
}

/* Does component k differ from its reference sign in g (crossed or hit zero)? */
static int crossed(const rk4_impl *r, const double *g, int k)
{
    return gw_root_crossed(r->sign, g, k);
}

/* The bracket's crossed end *hi lies on a zero of component k, where the
 * secant cannot move and bisection would halve [lo, hi] down to htol (some 25
 * trial steps). If g is still on the old side htol before it, the root is
 * within htol: *done. Otherwise g stays zero over an interval, and the end
 * moves to that point for the search of the interval's start. */
static int rk4_zero_end(gw_solver *s, int k, double lo, double *hi, double *ghi, double htol,
                        int *done)
{
    rk4_impl *r = s->impl;
    const double cl = *hi - htol;
    int rc;
    *done = 0;
    if (cl <= lo) {
        *done = 1;
        return 0;
    }
    if ((rc = rk4_step(s, r->t, r->y, cl, r->ytry)) != 0)
        return rc;
    if ((rc = rk4_roots(s, r->t + cl, r->ytry, r->gtry)) != 0)
        return rc;
    const double gl = r->gtry[k] * r->sign[k];
    if (gl > 0) {
        *done = 1;
        return 0;
    }
    *hi = cl;
    *ghi = gl;
    return 0;
}

/* Locate the earliest root inside the step (t, t + h] in which some component
 * crossed (r->g holds g at the step end, r->g0 at its start). Sets *hland to a
 * step length just past the earliest root. */
static int rk4_locate(gw_solver *s, double h, double *hland)
{
    rk4_impl *r = s->impl;
    const int nr = s->sys.nroots;
    const double htol = fmax(1e-12 * s->p.dt, 4 * DBL_EPSILON * fabs(r->t + h));
    double best = h;
    int rc;
    for (int k = 0; k < nr; k++) {
        if (!crossed(r, r->g, k))
            continue;
        double lo = 0.0, hi = best;
        double glo = r->g0[k] * r->sign[k]; /* > 0 on the old side */
        double ghi;
        if (hi == h) {
            ghi = r->g[k] * r->sign[k];
        } else {
            if ((rc = rk4_step(s, r->t, r->y, hi, r->ytry)) != 0)
                return rc;
            if ((rc = rk4_roots(s, r->t + hi, r->ytry, r->gtry)) != 0)
                return rc;
            if (!crossed(r, r->gtry, k))
                continue; /* this component's root lies after the current best */
            ghi = r->gtry[k] * r->sign[k];
        }
        int side = 0, zero_checked = 0;
        if (ghi == 0 && !zero_checked++) {
            int done = 0;
            if ((rc = rk4_zero_end(s, k, lo, &hi, &ghi, htol, &done)) != 0)
                return rc;
            if (done) {
                best = hi;
                continue;
            }
        }
        for (int it = 0; it < 200 && hi - lo > htol; it++) {
            double c = (glo > 0 && ghi < 0) ? hi - ghi * (hi - lo) / (ghi - glo)
                                            : 0.5 * (lo + hi);
            if (!(c > lo && c < hi))
                c = 0.5 * (lo + hi);
            if ((rc = rk4_step(s, r->t, r->y, c, r->ytry)) != 0)
                return rc;
            if ((rc = rk4_roots(s, r->t + c, r->ytry, r->gtry)) != 0)
                return rc;
            double gc = r->gtry[k] * r->sign[k];
            if (gc > 0) { /* Illinois: halve the stale end's value */
                lo = c;
                glo = gc;
                if (side == -1)
                    ghi *= 0.5;
                side = -1;
            } else {
                hi = c;
                ghi = gc;
                if (gc == 0 && !zero_checked++) {
                    int done = 0;
                    if ((rc = rk4_zero_end(s, k, lo, &hi, &ghi, htol, &done)) != 0)
                        return rc;
                    if (done)
                        break;
                }
                if (side == 1)
                    glo *= 0.5;
                side = 1;
            }
        }
        best = hi;
    }
    *hland = best;
    return 0;
}

/* A peek at p in the step from r->t that ends at tend (its end state in
 * r->ynew): that state when p is the end within rounding, else a step of
 * p - r->t; the solver where it was. GW_SOLVER_PEEK. */
static int rk4_peek(gw_solver *s, rk4_impl *r, double p, double tend, double *t, double *y)
{
    const long n = s->sys.dim;
    const double *yp = r->ynew;
    if (fabs(tend - p) > 1e-9 * s->p.dt) {
        if (rk4_step(s, r->t, r->y, p - r->t, r->ytry) != 0) {
            gw_solver_set_error(s, "rk4: model callback failed at t = %.9g s", p);
            return GW_ESOLVER;
        }
        yp = r->ytry;
    }
    s->peek = 0;
    r->steps--; /* (made again at the next call; its evaluations were made) */
    *t = p;
    memcpy(y, yp, (size_t)n * sizeof *y);
    return GW_SOLVER_PEEK;
}

static int rk4_advance(gw_solver *s, double tout, double *t, double *y, int *roots)
{
    rk4_impl *r = s->impl;
    const long n = s->sys.dim;
    const int nr = s->sys.nroots;
    const double dt = s->p.dt;
    long taken = 0;
    int rc = 0;
    if (tout < r->t) { /* a fixed-step method runs forward only: it returned GW_OK where it stood */
        gw_solver_set_error(s, "rk4: tout = %.9g s is before the solver's time %.9g s (rk4 runs forward only)",
                            tout, r->t);
        return GW_EINVAL;
    }
    while (r->t < tout) {
        double h = tout - r->t;
        if (h > dt)
            h = (h < dt * (1 + 1e-9)) ? h : dt;
        if (taken++ >= s->p.max_steps) {
            gw_solver_set_error(s, "rk4: more than %ld steps before t = %.9g s at t = %.9g s",
                                s->p.max_steps, tout, r->t);
            rc = GW_ELIMIT;
            break;
        }
        if ((rc = gw_solver_interrupted(s, r->t)) != 0)
            break;
        if ((rc = rk4_step(s, r->t, r->y, h, r->ynew)) != 0)
            break;
        r->steps++;
        /* the step's end time, landing on tout within rounding */
        const double tend = (r->t + h >= tout || tout - (r->t + h) < 1e-9 * dt) ? tout : r->t + h;
        const int at_end = s->sys.roots_at_step_end;
        if (at_end && s->sys.project && (rc = s->sys.project(tend, h, r->ynew, NULL, s->sys.params)) != 0)
            break;
        /* a peek in this step (gw_solver_set_peek), the step and its root
         * not taken: the state there by a step of rk4 from the step's start
         * (what a stop there gave), and the step made again at the next call
         * (the same values: the run does not see the peek) */
        const double p = s->peek;
        int peek = p > r->t && p < tout && p <= tend + 1e-9 * dt;
        if (nr > 0) {
            if ((rc = rk4_roots(s, r->t + h, r->ynew, r->g)) != 0)
                break;
            if (any_crossed(r, r->g, nr)) {
                double hl = h;
                if (!at_end) {
                    if ((rc = rk4_locate(s, h, &hl)) != 0)
                        break;
                    peek = peek && p <= r->t + hl;
                    if (!peek && (rc = rk4_step(s, r->t, r->y, hl, r->ynew)) != 0)
                        break;
                    if (!peek && (rc = rk4_roots(s, r->t + hl, r->ynew, r->g)) != 0)
                        break;
                }
                if (peek)
                    return rk4_peek(s, r, p, tend, t, y);
                r->t = at_end ? tend : (hl == h && r->t + h >= tout) ? tout : r->t + hl;
                memcpy(r->y, r->ynew, (size_t)n * sizeof *y);
                memcpy(r->g0, r->g, (size_t)nr * sizeof *r->g);
                for (int k = 0; k < nr; k++) {
                    int c = crossed(r, r->g, k);
                    if (roots)
                        roots[k] = c ? -r->sign[k] : 0;
                    if (c || r->sign[k] == 0)
                        r->sign[k] = (signed char)gw_sgn(r->g[k]);
                }
                signs_changed(r, nr);
                *t = r->t;
                memcpy(y, r->y, (size_t)n * sizeof *y);
                return GW_ROOT;
            }
            if (peek) /* (no root in the step; the roots' references as they were) */
                return rk4_peek(s, r, p, tend, t, y);
            double *g0 = r->g0; /* g becomes the next step's g0 (no copy) */
            r->g0 = r->g;
            r->g = g0;
            if (r->ninactive > 0) {
                for (int k = 0; k < nr; k++)
                    if (r->sign[k] == 0)
                        r->sign[k] = (signed char)gw_sgn(r->g0[k]);
                signs_changed(r, nr);
            }
        }
        if (peek)
            return rk4_peek(s, r, p, tend, t, y);
        r->t = tend;
        double *y0 = r->y; /* the step's end becomes the next step's start (no copy) */
        r->y = r->ynew;
        r->ynew = y0;
    }
    *t = r->t;
    memcpy(y, r->y, (size_t)n * sizeof *y);
    if (rc == GW_ELIMIT || rc == GW_ECANCELED)
        return rc;
    if (rc != 0) {
        gw_solver_set_error(s, "rk4: model callback failed (code %d) at t = %.9g s", rc, r->t);
        return GW_ESOLVER;
    }
    /* a fixed step has no error test to fail on a rate of NaN or infinity
     * (cvode and arkode stop on it): the state handed back is checked, once
     * per call, so that such a rate is never returned as a result */
    for (long i = 0; i < n; i++)
        if (!isfinite(r->y[i])) {
            gw_solver_set_error(s, "rk4: the state is not finite (component %ld is %g) at t = %.9g s: "
                                   "the model's rates gave NaN or infinity in the steps before",
                                i, r->y[i], r->t);
            return GW_ESOLVER;
        }
    return GW_OK;
}

static int rk4_reset(gw_solver *s, double t, const double *y)
{
    rk4_impl *r = s->impl;
    r->t = t;
    memcpy(r->y, y, (size_t)s->sys.dim * sizeof *y);
    if (s->sys.nroots > 0) {
        if (rk4_roots(s, t, r->y, r->g0) != 0) {
            gw_solver_set_error(s, "rk4: root function failed at t = %.9g s", t);
            return GW_ESOLVER;
        }
        rk4_init_signs(s);
    }
    return GW_OK;
}

static void rk4_stats(const gw_solver *s, gw_solver_stats *st)
{
    const rk4_impl *r = s->impl;
    st->steps = r->steps;
    st->rhs_evals = r->rhs_evals;
    st->root_evals = r->root_evals;
}

static const gw_solver_type rk4_type = {"rk4", rk4_create, rk4_advance, rk4_reset,
                                        rk4_stats, rk4_destroy, NULL};
const gw_solver_type *const gw_solver_rk4 = &rk4_type;
