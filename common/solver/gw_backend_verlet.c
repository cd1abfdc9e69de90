/*
 * gw_backend_verlet.c: fixed-step velocity Verlet (kick-drift-kick), the
 * second-order symplectic step of explicit DEM codes, for systems that state
 * their second-order structure in gw_system.drift.
 *
 * The components split into drifts q (dq_i/dt = y[drift[i]]) and kicks p
 * (every other component: velocities, forces carried as state, integrated
 * ledgers; their rates come from the rhs). One step of length h, with
 * f = rhs(t, q, p) kept from the end of the previous step:
 *     p' = p + (h/2) f_p;   q += h v(p');   f = rhs(t + h, q, p' + (h/2) f_p);
 *     p = p' + (h/2) f_p (the new f).
 * For q'' = a(q) this is velocity Verlet: symplectic, second order, one rhs
 * evaluation per step. Rates that also depend on p (tangential contact forces
 * carried as state, their velocities, damping, integrated ledgers) are
 * evaluated at the predicted end-of-step p (the old rates carried over the
 * second half step) rather than at the half-step p of plain velocity Verlet:
 * the half-step p lags by h/2, which makes plain velocity Verlet first order
 * for such rates (measured on the default layer impact: ledger closure 1.6e-2
 * at dt = 1e-5 s, halving with dt). After each
 * step gw_system.project (optional) may change y (zero the history of a
 * contact that opened) and correct the rates f it left with (gw_project_fn):
 * no extra rhs evaluation.
 * Components marked GW_DRIFT_MODEL are neither kicked nor drifted here: the
 * model's gw_system.drift_fn advances them after the drift, from the half-step
 * velocities (the incremental contact law of DEM codes: a tangential spring
 * stretched by v_t(t + h/2) h is a coordinate of the step like a position,
 * which keeps its energy exchange with the kicks second order and free of
 * drift), and the rhs sees their end values.
 * Roots: g is evaluated at every step end; a component that changed sign is
 * reported at the end of that step (GW_ROOT, rootsfound as in the other
 * backends), not located inside it. Components exactly zero are inactive until
 * they move away from zero. Every step is dt, so the states do not depend on
 * where the outputs fall; a step that ends within 1e-9 dt of tout is reported
 * at tout, and only a remainder shorter than a step (a tout off the step grid)
 * is taken as one shorter step. A peek (gw_solver_set_peek) reads a state
 * between two steps without a step of its own: the step that holds it is taken
 * as without it and the state at the peek interpolated from the step's two ends
 * (verlet_peek_state), so the steps do not depend on where the samples fall
 * either. Units are the model's.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_hermite.h"
#include "gw_solver_impl.h"

typedef struct verlet_impl {
    double t;
    double *y, *f, *g, *pp; /* pp: y at the half step (kick components) */
    double *kick;       /* 1 for a kick component, 0 for a drift (masks, so the
                           kicks run over the whole contiguous state) */
    long *qi, *qv;      /* drift components and their velocities */
    long nq;
    long bm, bn;        /* block layout (bn > 0): components [0, 2 bm bn) are bn
                           blocks of bm drifts followed by their bm velocities,
                           no later component a drift (the fused loops) */
    long *run, nrun;    /* block layout: the kicks after the blocks as nrun runs
                           [run[2r], run[2r + 1]) (model components skipped) */
    signed char *sign;
    long steps, rhs_evals, root_evals;
    /* a peek (gw_solver_set_peek): the step that holds it is taken and the
     * state there interpolated from the step's two ends (verlet_peek_state),
     * from y0 and f0, y and f at the step's start; a root found by that step
     * is held back (pend, proots) and returned by the next call */
    double *y0, *f0;
    signed char *form;  /* per component: 1 a drift (Hermite with its velocity),
                           2 a drift's velocity (Hermite with its rate), 0 linear */
    int pend, *proots;
    double hsaved;      /* the length of the last step when y0, f0 are its start, else 0 */
} verlet_impl;

static void verlet_destroy(gw_solver *s)
{
    verlet_impl *v = s->impl;
    if (!v)
        return;
    free(v->y);
    free(v->qi);
    free(v->run);
    free(v->sign);
    free(v->y0);
    free(v->form);
    free(v->proots);
    free(v);
    s->impl = NULL;
}

/* f and the root signs at (t, y): the start of an integration. */
static int verlet_restart(gw_solver *s)
{
    verlet_impl *v = s->impl;
    int rc = s->sys.rhs(v->t, v->y, v->f, s->sys.params);
    v->rhs_evals++;
    if (rc != 0)
        return rc;
    if (s->sys.nroots > 0) {
        v->root_evals++;
        if ((rc = s->sys.roots(v->t, v->y, v->g, s->sys.params)) != 0)
            return rc;
        for (int k = 0; k < s->sys.nroots; k++)
            v->sign[k] = (signed char)gw_sgn(v->g[k]);
    }
    return 0;
}

/* Detect the layout of particle models (positions then velocities per body,
 * then kicks only): the step then runs as fused loops without the kick mask or
 * index gathers, with the same arithmetic (bit-identical results). */
static void block_layout(const long *drift, long n, verlet_impl *v)
{
    v->bm = v->bn = 0;
    for (long m = 1; m <= 8 && 2 * m <= n; m++) {
        if (drift[0] != m)
            continue;
        long nb = 0, i = 0;
        for (; i + 2 * m <= n; i += 2 * m) {
            long j = 0;
            for (; j < m && drift[i + j] == i + j + m && drift[i + j + m] == -1; j++)
                ;
            if (j < m)
                break;
            nb++;
        }
        for (long k = i; k < n; k++)
            if (drift[k] >= 0)
                return;
        v->bm = m, v->bn = nb;
        return;
    }
}

static int verlet_create(gw_solver *s, double t0, const double *y0, gw_err *err)
{
    if (!(s->p.dt > 0))
        return gw_err_set(err, GW_EINVAL, "verlet: the fixed step dt must be set (> 0)");
    if (s->p.method != GW_METHOD_DEFAULT)
        return gw_err_set(err, GW_EUNSUPPORTED, "verlet: method '%s' not offered",
                          gw_solver_method_name(s->p.method));
    if (!s->sys.drift)
        return gw_err_set(err, GW_EUNSUPPORTED, "verlet: the model gives no second-order "
                          "structure (gw_system.drift)");
    const long n = s->sys.dim;
    for (long i = 0; i < n; i++) {
        long j = s->sys.drift[i];
        if (j < GW_DRIFT_MODEL || j >= n || (j >= 0 && s->sys.drift[j] != -1))
            return gw_err_set(err, GW_EINVAL, "verlet: drift[%ld] = %ld is not a kick component", i, j);
        if (j == GW_DRIFT_MODEL && !s->sys.drift_fn)
            return gw_err_set(err, GW_EINVAL, "verlet: drift[%ld] is the model's but gw_system.drift_fn "
                              "is not set", i);
    }
    verlet_impl *v = calloc(1, sizeof *v);
    if (!v)
        return gw_err_set(err, GW_ENOMEM, "verlet: out of memory");
    s->impl = v;
    const size_t nr = (size_t)s->sys.nroots;
    v->y = malloc((4 * (size_t)n + nr + 1) * sizeof *v->y);
    v->qi = malloc(2 * (size_t)n * sizeof *v->qi);
    v->sign = calloc(nr + 1, 1);
    v->y0 = malloc(2 * (size_t)n * sizeof *v->y0);
    v->form = calloc((size_t)n, 1);
    v->proots = calloc(nr + 1, sizeof *v->proots);
    if (!v->y || !v->qi || !v->sign || !v->y0 || !v->form || !v->proots) {
        verlet_destroy(s);
        return gw_err_set(err, GW_ENOMEM, "verlet: out of memory for %ld components", n);
    }
    v->f = v->y + n;
    v->pp = v->y + 2 * n;
    v->kick = v->y + 3 * n;
    v->g = v->y + 4 * n;
    v->qv = v->qi + n;
    v->f0 = v->y0 + n;
    for (long i = 0; i < n; i++) {
        v->kick[i] = s->sys.drift[i] == -1;
        if (s->sys.drift[i] >= 0) {
            v->qi[v->nq] = i;
            v->qv[v->nq++] = s->sys.drift[i];
            v->form[i] = 1;
            v->form[s->sys.drift[i]] = 2;
        }
    }
    block_layout(s->sys.drift, n, v);
    if (v->bn > 0) {
        v->run = malloc((2 * (size_t)(n - 2 * v->bm * v->bn) + 2) * sizeof *v->run);
        if (!v->run) {
            verlet_destroy(s);
            return gw_err_set(err, GW_ENOMEM, "verlet: out of memory for %ld components", n);
        }
        for (long i = 2 * v->bm * v->bn; i < n;) {
            if (s->sys.drift[i] != -1) {
                i++;
                continue;
            }
            long e = i;
            while (e < n && s->sys.drift[e] == -1)
                e++;
            v->run[2 * v->nrun] = i, v->run[2 * v->nrun + 1] = e;
            v->nrun++;
            i = e;
        }
    }
    memcpy(v->y, y0, (size_t)n * sizeof *y0);
    v->t = t0;
    if (verlet_restart(s) != 0) {
        verlet_destroy(s);
        return gw_err_set(err, GW_ESOLVER, "verlet: model callback failed at t0 = %.9g s", t0);
    }
    return GW_OK;
}

/* One kick-drift-kick step of length h. */
static int verlet_step(gw_solver *s, double h)
{
    verlet_impl *v = s->impl;
    double *restrict y = v->y, *restrict pp = v->pp;
    const double *restrict f = v->f, *restrict kick = v->kick;
    const long n = s->sys.dim;
    const double hh = 0.5 * h;
    long i0 = 0; /* first component of the generic loops */
    if (v->bn > 0) { /* fused: half kick of the velocities, drift, predicted end */
        const long m = v->bm;
        i0 = 2 * m * v->bn;
        if (m == 3) { /* (x, y, angle) bodies: the loop below written out, its
                         statements side by side so that the compiler pairs them */
            for (long b = 0; b < i0; b += 6) {
                const double d3 = hh * f[b + 3], d4 = hh * f[b + 4], d5 = hh * f[b + 5];
                const double p3 = y[b + 3] + d3, p4 = y[b + 4] + d4, p5 = y[b + 5] + d5;
                const double q0 = y[b], q1 = y[b + 1], q2 = y[b + 2];
                pp[b + 3] = p3, pp[b + 4] = p4, pp[b + 5] = p5;
                y[b + 3] = p3 + d3, y[b + 4] = p4 + d4, y[b + 5] = p5 + d5;
                pp[b] = q0, pp[b + 1] = q1, pp[b + 2] = q2;
                y[b] = q0 + h * p3, y[b + 1] = q1 + h * p4, y[b + 2] = q2 + h * p5;
            }
        } else {
            for (long b = 0; b < i0; b += 2 * m)
                for (long j = 0; j < m; j++) {
                    long q = b + j, u = q + m;
                    double d = hh * f[u];
                    pp[u] = y[u] + d;
                    y[u] = pp[u] + d;
                    pp[q] = y[q];
                    y[q] += h * pp[u];
                }
        }
        for (long r = 0; r < v->nrun; r++)
            for (long i = v->run[2 * r]; i < v->run[2 * r + 1]; i++) {
                double d = hh * f[i];
                pp[i] = y[i] + d;
                y[i] = pp[i] + d;
            }
    } else {
        for (long i = 0; i < n; i++) { /* half kick; y holds the predicted end */
            double d = kick[i] * hh * f[i];
            pp[i] = y[i] + d;
            y[i] = pp[i] + d;
        }
        for (long k = 0; k < v->nq; k++) /* drift with the half-step velocities */
            y[v->qi[k]] = pp[v->qi[k]] + h * pp[v->qv[k]];
    }
    int rc = s->sys.drift_fn ? s->sys.drift_fn(v->t + h, h, pp, y, s->sys.params) : 0;
    if (rc != 0)
        return rc;
    rc = s->sys.rhs(v->t + h, y, v->f, s->sys.params);
    v->rhs_evals++;
    if (rc != 0)
        return rc;
    if (v->bn > 0) {
        const long m = v->bm;
        if (m == 3) /* as in the first half kick */
            for (long b = 0; b < i0; b += 6) {
                const double v3 = pp[b + 3] + hh * f[b + 3], v4 = pp[b + 4] + hh * f[b + 4];
                const double v5 = pp[b + 5] + hh * f[b + 5];
                y[b + 3] = v3, y[b + 4] = v4, y[b + 5] = v5;
            }
        else
            for (long b = 0; b < i0; b += 2 * m)
                for (long j = b + m; j < b + 2 * m; j++)
                    y[j] = pp[j] + hh * f[j];
        for (long r = 0; r < v->nrun; r++)
            for (long i = v->run[2 * r]; i < v->run[2 * r + 1]; i++)
                y[i] = pp[i] + hh * f[i];
    } else {
        for (long i = 0; i < n; i++) /* second half kick (a blend: drifts keep y) */
            y[i] = kick[i] * (pp[i] + hh * f[i]) + (1 - kick[i]) * y[i];
    }
    v->steps++;
    return s->sys.project ? s->sys.project(v->t + h, h, y, v->f, s->sys.params) : 0;
}

/* The state at p in the step of length h that ended at v->t (its start y0,
 * f0): the end itself when p is there within rounding, else a cubic Hermite
 * between the two ends for the drifts (their velocities the slopes) and their
 * velocities (their rates the slopes; the kicks are the trapezoid of those
 * rates), and a straight line for the other components (the model's, the
 * ledgers: their rates are not all in f, the projection adds to them). The
 * states are the method's, second order; the Hermite adds an error of fourth
 * order in h, the line one of second order, so a sample read here is as
 * accurate as one the run stopped at, and the run does not see it. */
static void verlet_peek_state(const gw_solver *s, const verlet_impl *v, double p, double h, double *y)
{
    const long n = s->sys.dim;
    if (fabs(v->t - p) <= 1e-9 * s->p.dt || !(h > 0)) {
        memcpy(y, v->y, (size_t)n * sizeof *y);
        return;
    }
    const double th = (p - (v->t - h)) / h, u = 1 - th;
    double w[4];
    gw_hermite(th, h, w);
    const double h00 = w[0], h10 = w[1], h01 = w[2], h11 = w[3];
    const double *y0 = v->y0, *f0 = v->f0, *y1 = v->y, *f1 = v->f;
    for (long i = 0; i < n; i++) {
        if (v->form[i] == 1) {
            const long j = s->sys.drift[i];
            y[i] = h00 * y0[i] + h10 * y0[j] + h01 * y1[i] + h11 * y1[j];
        } else if (v->form[i] == 2) {
            y[i] = h00 * y0[i] + h10 * f0[i] + h01 * y1[i] + h11 * f1[i];
        } else {
            y[i] = u * y0[i] + th * y1[i];
        }
    }
}

static int verlet_advance(gw_solver *s, double tout, double *t, double *y, int *roots)
{
    verlet_impl *v = s->impl;
    const long n = s->sys.dim;
    const int nr = s->sys.nroots;
    const double dt = s->p.dt;
    long taken = 0;
    int rc = 0, found = 0;
    const double p0 = s->peek;
    if (p0 > 0 && v->hsaved > 0 && p0 > v->t - v->hsaved && p0 <= v->t + 1e-9 * dt && p0 < tout) {
        /* another peek in the step that held the last one (samples finer than
         * the steps): read there, nothing taken */
        s->peek = 0;
        verlet_peek_state(s, v, p0, v->hsaved, y);
        *t = p0;
        return GW_SOLVER_PEEK;
    }
    if (v->pend) { /* the root of the step that held the last peek */
        v->pend = 0;
        for (int k = 0; roots && k < nr; k++)
            roots[k] = v->proots[k];
        *t = v->t;
        memcpy(y, v->y, (size_t)n * sizeof *y);
        return GW_ROOT;
    }
    if (tout < v->t) { /* a fixed-step method runs forward only: it returned GW_OK where it stood */
        gw_solver_set_error(s, "verlet: tout = %.9g s is before the solver's time %.9g s (verlet runs forward "
                            "only)", tout, v->t);
        return GW_EINVAL;
    }
    while (v->t < tout && !found) {
        /* the step is dt itself whenever tout lies a step away or more (within
         * 1e-9 dt): landing on a sample time with h = tout - t, a value a few
         * ulps off dt that depends on where the samples fall, changed the
         * trajectory in the last bits with --dt-out, and a chaotic layer impact
         * grew that to 3e-4 in e_n by its take-off at 0.25 s. Only a remainder
         * shorter than a step (a t_max off the grid) gives a shorter step */
        double h = tout - v->t;
        h = h >= dt * (1 - 1e-9) ? dt : h;
        if (taken++ >= s->p.max_steps) {
            gw_solver_set_error(s, "verlet: more than %ld steps before t = %.9g s at t = %.9g s",
                                s->p.max_steps, tout, v->t);
            rc = GW_ELIMIT;
            break;
        }
        if ((rc = gw_solver_interrupted(s, v->t)) != 0)
            break;
        const double tend = (v->t + h >= tout || tout - (v->t + h) < 1e-9 * dt) ? tout : v->t + h;
        /* a peek in this step (gw_solver_set_peek): the step is taken as
         * without it (the same arithmetic: the run does not see the peek),
         * its start kept for the interpolation */
        const double p = s->peek;
        const int peek = p > v->t && p < tout && p <= tend + 1e-9 * dt;
        if (peek) {
            memcpy(v->y0, v->y, (size_t)n * sizeof *y);
            memcpy(v->f0, v->f, (size_t)n * sizeof *y);
        }
        v->hsaved = 0;
        if ((rc = verlet_step(s, h)) != 0)
            break;
        v->t = tend;
        v->hsaved = peek ? h : 0;
        if (nr > 0) {
            v->root_evals++;
            if ((rc = s->sys.roots(v->t, v->y, v->g, s->sys.params)) != 0)
                break;
            for (int k = 0; k < nr; k++) {
                int c = gw_root_crossed(v->sign, v->g, k);
                if (roots)
                    roots[k] = c ? -v->sign[k] : 0;
                if (peek)
                    v->proots[k] = c ? -v->sign[k] : 0;
                found |= c;
                if (c || v->sign[k] == 0)
                    v->sign[k] = (signed char)gw_sgn(v->g[k]);
            }
        }
        if (peek) {
            s->peek = 0;
            v->pend = found;
            verlet_peek_state(s, v, p, h, y);
            *t = p;
            return GW_SOLVER_PEEK;
        }
    }
    *t = v->t;
    memcpy(y, v->y, (size_t)n * sizeof *y);
    if (rc == GW_ELIMIT || rc == GW_ECANCELED)
        return rc;
    if (rc != 0) {
        gw_solver_set_error(s, "verlet: model callback failed (code %d) at t = %.9g s", rc, v->t);
        return GW_ESOLVER;
    }
    return found ? GW_ROOT : GW_OK;
}

static int verlet_reset(gw_solver *s, double t, const double *y)
{
    verlet_impl *v = s->impl;
    v->t = t;
    v->pend = 0;
    v->hsaved = 0;
    memcpy(v->y, y, (size_t)s->sys.dim * sizeof *y);
    if (verlet_restart(s) != 0) {
        gw_solver_set_error(s, "verlet: model callback failed at t = %.9g s", t);
        return GW_ESOLVER;
    }
    return GW_OK;
}

static void verlet_stats(const gw_solver *s, gw_solver_stats *st)
{
    const verlet_impl *v = s->impl;
    st->steps = v->steps;
    st->rhs_evals = v->rhs_evals;
    st->root_evals = v->root_evals;
}

static const double *verlet_rates(const gw_solver *s)
{
    const verlet_impl *v = s->impl;
    return v->f;
}

static const gw_solver_type verlet_type = {"verlet", verlet_create, verlet_advance, verlet_reset,
                                           verlet_stats, verlet_destroy, verlet_rates};
const gw_solver_type *const gw_solver_verlet = &verlet_type;
