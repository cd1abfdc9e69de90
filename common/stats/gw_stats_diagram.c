/*
 * gw_stats_diagram.c: the bouncing-occurrence diagram of docs/physics.md 2.5 and
 * the boundary model B.31.
 *
 * Diagram: cells (x = R_b/R_m, h = H/R_m) carry the bounce share over their
 * impact points; a cell bounces globally when share >= S. In each x column the
 * boundary H* sits between the lowest bouncing cell whose upper neighbour does
 * not bounce, at the height where the share interpolated linearly in H equals
 * S. R_crit is the largest x up to which every column bounces at every H.
 *
 * B.31, with u = x - beta, T = tan(gamma), K = (a/b) T:
 *     f(x) = delta* / (2 R_m) + u/(2T) (sqrt(1 + K x^2/u^2) - 1)
 *          = delta* / (2 R_m) + (sqrt(u^2 + K x^2) - u) / (2T)     (positive root)
 * For u > 0 the second form is evaluated as K x^2 / (sqrt(u^2 + K x^2) + u) / (2T)
 * (no cancellation when K x^2 << u^2). For u >> sqrt(K) x it reduces to
 * (a/b) x^2 / (4 u): tan(gamma) only shapes the curve within about sqrt(K) x of
 * x = beta, and a, b enter only as a/b; see gw_stats_b31_fit_points for what a
 * boundary can and cannot determine.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include "gw_global.h"
#include "gw_locale.h"
#include "gw_stats.h"

/* ---------------------------------------------------------------- diagram --- */

void gw_stats_diagram_free(gw_stats_diagram *d)
{
    if (!d)
        return;
    free(d->xs);
    free(d->hs);
    free(d->share);
    free(d->pen);
    free(d->pts);
    memset(d, 0, sizeof *d);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sorted distinct values of v[keep] into out; returns the count. */
static int distinct(const double *v, const char *keep, int n, double *out)
{
    int m = 0;
    for (int i = 0; i < n; i++)
        if (keep[i])
            out[m++] = v[i];
    qsort(out, (size_t)m, sizeof *out, cmp_double);
    int k = 0;
    for (int i = 0; i < m; i++)
        if (k == 0 || out[i] != out[k - 1])
            out[k++] = out[i];
    return k;
}

static int index_of(const double *v, int n, double x)
{
    const double *p = bsearch(&x, v, (size_t)n, sizeof *v, cmp_double);
    return p ? (int)(p - v) : -1;
}

static double mean2(double a, double b)
{
    if (isfinite(a) && isfinite(b))
        return 0.5 * a + 0.5 * b; /* as 0.5 (a + b), without its overflow near 1e308 */
    return isfinite(a) ? a : b;
}

/* The boundary point of column i. */
static void column_boundary(gw_stats_diagram *d, int i)
{
    gw_stats_boundary_pt *p = &d->pts[i];
    const double S = d->criterion, *s = d->share + (size_t)i * d->nh;
    const double *pen = d->pen + (size_t)i * d->nh;
    *p = (gw_stats_boundary_pt){.x = d->xs[i], .h = NAN, .h_lo = NAN, .h_hi = NAN, .s_lo = NAN,
                                .s_hi = NAN, .penetration_rm = NAN};
    int prev = -1, nyes = 0, nno = 0, found = 0;
    for (int j = 0; j < d->nh; j++) {
        if (isnan(s[j]))
            continue;
        int v = s[j] >= S;
        nyes += v;
        nno += !v;
        if (prev >= 0 && (s[prev] >= S) != v) {
            p->changes++;
            if (!found && !v) { /* bouncing at h[prev], not at h[j] */
                found = 1;
                p->kind = GW_STATS_BND_CROSS;
                p->h_lo = d->hs[prev];
                p->h_hi = d->hs[j];
                p->s_lo = s[prev];
                p->s_hi = s[j];
                p->h = p->h_lo + (p->s_lo - S) / (p->s_lo - p->s_hi) * (p->h_hi - p->h_lo);
                p->penetration_rm = mean2(pen[prev], pen[j]);
            }
        }
        prev = j;
    }
    if (!found)
        p->kind = nno == 0 ? GW_STATS_BND_ABOVE : nyes == 0 ? GW_STATS_BND_BELOW : GW_STATS_BND_INVERTED;
}

int gw_stats_diagram_make(int n, const double *x, const double *h, const double *share,
                          const double *pen, double criterion, gw_stats_diagram *d, gw_err *err)
{
    if (!d)
        return gw_err_set(err, GW_EINVAL, "gw_stats_diagram_make: d is NULL");
    /* pen may be NULL, as gw_stats.h says (it was refused); n < 0 asked
     * malloc for SIZE_MAX bytes (an abort under ASan), a NaN criterion drew a
     * boundary of no cell */
    if (n > 0 && (!x || !h || !share)) {
        memset(d, 0, sizeof *d);
        return gw_err_set(err, GW_EINVAL, "gw_stats_diagram_make: %s is NULL", !x ? "x" : !h ? "h" : "share");
    }
    memset(d, 0, sizeof *d);
    if (n < 0)
        return gw_err_set(err, GW_EINVAL, "diagram: %d cells (a count, >= 0)", n);
    char xs[32]; /* the value as given: 1.0000001 was "1 is not in (0, 1]" */
    if (!(criterion > 0 && criterion <= 1))
        return gw_err_set(err, GW_EINVAL, "criterion: %s is not in (0, 1]", gw_num_text(xs, sizeof xs, criterion));
    /* a share is a fraction of cases and x = R_b/R_m a ratio of radii: a
     * share of 7 or -1 and an x <= 0 drew a boundary of no physical cell */
    for (int i = 0; i < n; i++) {
        char vb[32];
        if (!isnan(share[i]) && !(share[i] >= 0 && share[i] <= 1))
            return gw_err_set(err, GW_EINVAL, "diagram: share[%d] = %s is not in [0, 1]", i,
                              gw_num_text(vb, sizeof vb, share[i]));
        if (!isnan(x[i]) && !(x[i] > 0 && isfinite(x[i])))
            return gw_err_set(err, GW_EINVAL, "diagram: x[%d] (R_b/R_m) = %s is not > 0 and finite", i,
                              gw_num_text(vb, sizeof vb, x[i]));
    }
    d->criterion = criterion;
    char *keep = malloc((size_t)n + 1);
    d->xs = malloc(((size_t)n + 1) * sizeof *d->xs);
    d->hs = malloc(((size_t)n + 1) * sizeof *d->hs);
    if (!keep || !d->xs || !d->hs) {
        free(keep);
        gw_stats_diagram_free(d);
        return gw_err_set(err, GW_ENOMEM, "diagram: out of memory");
    }
    for (int i = 0; i < n; i++)
        keep[i] = isfinite(x[i]) && isfinite(h[i]) && h[i] > 0 && isfinite(share[i]);
    d->nx = distinct(x, keep, n, d->xs);
    d->nh = distinct(h, keep, n, d->hs);
    int rc = GW_OK;
    if (d->nx < 2 || d->nh < 2)
        rc = gw_err_set(err, GW_EINVAL, "diagram: needs at least 2 values of R_b/R_m and of H/R_m > 0 "
                                        "(have %d and %d)", d->nx, d->nh);
    size_t cells = (size_t)d->nx * (size_t)d->nh;
    if (rc == GW_OK) {
        d->share = malloc(cells * sizeof *d->share);
        d->pen = malloc(cells * sizeof *d->pen);
        d->pts = calloc((size_t)d->nx, sizeof *d->pts);
        if (!d->share || !d->pen || !d->pts)
            rc = gw_err_set(err, GW_ENOMEM, "diagram: out of memory");
    }
    for (size_t c = 0; rc == GW_OK && c < cells; c++)
        d->share[c] = d->pen[c] = NAN;
    for (int k = 0; rc == GW_OK && k < n; k++) {
        if (!keep[k])
            continue;
        size_t c = (size_t)index_of(d->xs, d->nx, x[k]) * d->nh + (size_t)index_of(d->hs, d->nh, h[k]);
        if (!isnan(d->share[c]))
            rc = gw_err_set(err, GW_EINVAL, "diagram: two groups at R_b/R_m = %g, H/R_m = %g "
                                            "(another grid key varies)", x[k], h[k]);
        d->share[c] = share[k];
        d->pen[c] = pen ? pen[k] : NAN;
    }
    free(keep);
    if (rc != GW_OK) {
        gw_stats_diagram_free(d);
        return rc;
    }
    double psum = 0;
    int np = 0;
    d->r_crit = d->r_crit_upper = d->r_min = d->h_min = NAN;
    for (int i = 0; i < d->nx; i++) {
        column_boundary(d, i);
        const gw_stats_boundary_pt *p = &d->pts[i];
        if (p->kind == GW_STATS_BND_CROSS) {
            d->ncross++;
            if (!(p->h >= d->h_min)) {
                d->h_min = p->h;
                d->r_min = p->x;
            }
            if (isfinite(p->penetration_rm)) {
                psum += p->penetration_rm;
                np++;
            }
        }
    }
    d->penetration_rm = np ? psum / np : NAN;
    if (np && !isfinite(d->penetration_rm)) { /* a sum beyond 1e308 */
        d->penetration_rm = 0;
        for (int i = 0; i < d->nx; i++)
            if (d->pts[i].kind == GW_STATS_BND_CROSS && isfinite(d->pts[i].penetration_rm))
                d->penetration_rm += d->pts[i].penetration_rm / np;
    }
    int i = 0;
    while (i < d->nx && d->pts[i].kind == GW_STATS_BND_ABOVE)
        d->r_crit = d->xs[i++];
    if (i < d->nx)
        d->r_crit_upper = d->xs[i];
    return GW_OK;
}

/* -------------------------------------------------------------------- B.31 --- */

/* The curves B.31 describes: a/b and tan gamma > 0 (the fit holds them as
 * their logarithms), all four finite. Outside, the minimum was a number of a
 * curve that is NaN everywhere (tan gamma 0: x_min 2 beta) or +-inf (a/b < 0,
 * K = -1), where gw_stats_b31_eval gave NaN */
static int b31_curve(const gw_stats_b31 *p)
{
    return p && isfinite(p->offset) && isfinite(p->beta) && p->a_over_b > 0 && isfinite(p->a_over_b) &&
           p->tan_gamma > 0 && isfinite(p->tan_gamma) && isfinite(p->a_over_b * p->tan_gamma);
}

double gw_stats_b31_eval(const gw_stats_b31 *p, double x)
{
    if (!b31_curve(p) || !isfinite(x))
        return NAN;
    double T = p->tan_gamma, K = p->a_over_b * T, u = x - p->beta;
    double r = sqrt(u * u + K * x * x);
    double g;
    if (isfinite(r) && isfinite(K * x * x))
        g = u > 0 ? K * x * x / (r + u) : r - u;
    else {
        /* u^2 or K x^2 beyond the doubles (|x| from 1e154; the value was NaN
         * where B.31's is a number): the same with x and u scaled by s */
        const double s = fmax(fabs(u), fabs(x)), us = u / s, xs = x / s;
        const double rs = sqrt(us * us + K * xs * xs);
        g = u > 0 ? K * xs * (x / (rs + us)) : s * (rs - us);
    }
    return p->offset + g / (2 * T);
}

void gw_stats_b31_min(const gw_stats_b31 *p, double *x_min, double *f_min)
{
    if (!b31_curve(p) || !x_min || !f_min) {
        if (x_min)
            *x_min = NAN;
        if (f_min)
            *f_min = NAN;
        return;
    }
    double K = p->a_over_b * p->tan_gamma;
    *x_min = 2 * p->beta / (1 + K);
    *f_min = p->offset + p->a_over_b * p->beta / (1 + K);
}

/* Free parameters in this order: offset, beta (as they are), ln(a/b), ln(tan gamma). */
typedef struct b31_problem {
    const double *x, *h;
    int n, mask;
    gw_stats_b31 base;
} b31_problem;

static gw_stats_b31 unpack(const b31_problem *pb, const gsl_vector *th)
{
    gw_stats_b31 p = pb->base;
    size_t k = 0;
    if (pb->mask & GW_STATS_B31_OFFSET)
        p.offset = gsl_vector_get(th, k++);
    if (pb->mask & GW_STATS_B31_BETA)
        p.beta = gsl_vector_get(th, k++);
    if (pb->mask & GW_STATS_B31_AB)
        p.a_over_b = exp(gsl_vector_get(th, k++));
    if (pb->mask & GW_STATS_B31_TANG)
        p.tan_gamma = exp(gsl_vector_get(th, k++));
    return p;
}

static void pack(int mask, const gw_stats_b31 *p, gsl_vector *th)
{
    size_t k = 0;
    if (mask & GW_STATS_B31_OFFSET)
        gsl_vector_set(th, k++, p->offset);
    if (mask & GW_STATS_B31_BETA)
        gsl_vector_set(th, k++, p->beta);
    if (mask & GW_STATS_B31_AB)
        gsl_vector_set(th, k++, log(p->a_over_b));
    if (mask & GW_STATS_B31_TANG)
        gsl_vector_set(th, k++, log(p->tan_gamma));
}

static int b31_residuals(const gsl_vector *th, void *params, gsl_vector *f)
{
    const b31_problem *pb = params;
    gw_stats_b31 p = unpack(pb, th);
    for (int i = 0; i < pb->n; i++) {
        double r = gw_stats_b31_eval(&p, pb->x[i]) - pb->h[i];
        /* a wild trial step (overflow in exp) gets a huge finite residual, so
         * the trust region rejects it instead of the driver failing */
        gsl_vector_set(f, (size_t)i, isfinite(r) ? r : 1e12);
    }
    return GSL_SUCCESS;
}

static int popcount4(int m)
{
    return (m & 1) + (m >> 1 & 1) + (m >> 2 & 1) + (m >> 3 & 1);
}

typedef struct b31_try {
    gw_stats_b31 p;
    double cost;
    int iterations, converged;
    double cov[16];
} b31_try;

/* One trust-region run of at most niter iterations from start (0: none, the
 * covariance at start); fills t (cost = sum of squares). */
static int b31_run(b31_problem *pb, const gw_stats_b31 *start, int p, int niter, b31_try *t)
{
    gsl_multifit_nlinear_parameters fp = gsl_multifit_nlinear_default_parameters();
    fp.trs = gsl_multifit_nlinear_trs_lm;
    gsl_multifit_nlinear_workspace *w =
        gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &fp, (size_t)pb->n, (size_t)p);
    gsl_vector *th = gsl_vector_alloc((size_t)p);
    gsl_matrix *cov = gsl_matrix_alloc((size_t)p, (size_t)p);
    int rc = GW_ENOMEM;
    if (w && th && cov) {
        gsl_multifit_nlinear_fdf fdf = {.f = b31_residuals, .df = NULL, .fvv = NULL,
                                        .n = (size_t)pb->n, .p = (size_t)p, .params = pb};
        pb->base = *start;
        pack(pb->mask, start, th);
        gsl_multifit_nlinear_init(th, &fdf, w);
        int info = 0;
        int st = niter > 0 ? gsl_multifit_nlinear_driver((size_t)niter, 1e-12, 1e-12, 0.0, NULL, NULL, &info, w)
                           : GSL_SUCCESS;
        gsl_vector *res = gsl_multifit_nlinear_residual(w);
        double chi2 = 0;
        gsl_blas_ddot(res, res, &chi2);
        t->p = unpack(pb, gsl_multifit_nlinear_position(w));
        t->cost = chi2;
        t->iterations = (int)gsl_multifit_nlinear_niter(w);
        /* GSL_ENOPROG at an exact fit (zero residuals) is convergence too */
        t->converged = st == GSL_SUCCESS || (st == GSL_ENOPROG && chi2 < 1e-20);
        gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w), 0.0, cov);
        for (int a = 0; a < p; a++)
            for (int b = 0; b < p; b++)
                t->cov[a * 4 + b] = gsl_matrix_get(cov, (size_t)a, (size_t)b);
        rc = isfinite(chi2) ? GW_OK : GW_EINVAL;
    }
    gsl_multifit_nlinear_free(w);
    gsl_vector_free(th);
    gsl_matrix_free(cov);
    return rc;
}

/* The box every fit searches (gw_stats.h): beta in [0, x_lo] (B.31 holds for
 * x >= beta; x_lo the smallest boundary x), a/b in [B31_AB_LO, B31_AB_HI],
 * tan gamma in [B31_T_LO, B31_T_HI] (gamma from 1e-6 to 89 deg, --gamma-deg's
 * range), offset >= 0 (a penetration). */
#define B31_AB_LO 1e-6
#define B31_AB_HI 1e6
#define B31_T_LO 1.7453292519943295e-8 /* tan(1e-6 deg) */
#define B31_T_HI 57.289961630759416    /* tan(89 deg) */

/* The structure the global search uses: with u = x - beta,
 *     f(x) = offset + A phi(x; beta, K),  phi = sqrt(u^2 + K x^2) - u,
 *     A = 1 / (2 tan gamma),  K = (a/b) tan gamma,  a/b = 2 A K.
 * For given (beta, K) the model is linear in offset and A: whichever of them
 * is free is solved exactly (least squares under its bounds), and what is
 * left is a function of (beta, ln K) alone, searched on a grid and refined
 * from each of the grid's local minima. */
typedef struct b31_profile {
    const double *x, *h;
    int n, mask;
    double offset0, T0;  /* the fixed values */
    double xlo;          /* beta's upper bound */
    double lnk_lo, lnk_hi;
    double *phi;         /* [n] scratch */
    long evals;
} b31_profile;

static double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* The sum of squares at (beta, ln K) with the linear parameters solved; p
 * (when not NULL) receives the parameters. */
static double prof_eval(b31_profile *q, double beta, double lnk, gw_stats_b31 *p)
{
    const int n = q->n;
    const double K = exp(lnk);
    double sp = 0, spp = 0, sh = 0, sph = 0;
    q->evals++;
    for (int i = 0; i < n; i++) {
        double x = q->x[i], u = x - beta, r = sqrt(u * u + K * x * x);
        double ph = u > 0 ? K * x * x / (r + u) : r - u;
        q->phi[i] = ph;
        sp += ph, spp += ph * ph, sh += q->h[i], sph += ph * q->h[i];
    }
    const int foff = (q->mask & GW_STATS_B31_OFFSET) != 0, ftan = (q->mask & GW_STATS_B31_TANG) != 0;
    /* A's bounds: tan gamma within its own, and a/b = 2 A K within its own */
    const double alo = fmax(1 / (2 * B31_T_HI), B31_AB_LO / (2 * K)),
                 ahi = fmin(1 / (2 * B31_T_LO), B31_AB_HI / (2 * K));
    double off = q->offset0, A = 1 / (2 * q->T0);
    if (foff && !ftan) {
        off = fmax(0, (sh - A * sp) / n);
    } else if (ftan && !foff) {
        A = clampd(spp > 0 ? (sph - off * sp) / spp : alo, alo, ahi);
    } else if (foff && ftan) {
        /* a convex quadratic in (offset, A) over offset >= 0, alo <= A <= ahi:
         * the free minimum when it lies inside, else the best of the edges,
         * each a clamped one-variable least squares */
        double det = n * spp - sp * sp, best = INFINITY;
        double cand[4][2];
        int nc = 0;
        if (det > 1e-14 * n * spp) {
            double a0 = (n * sph - sp * sh) / det, o0 = (sh - a0 * sp) / n;
            if (o0 >= 0 && a0 >= alo && a0 <= ahi)
                cand[nc][0] = o0, cand[nc++][1] = a0;
        }
        if (nc == 0) {
            cand[nc][0] = 0, cand[nc][1] = clampd(spp > 0 ? sph / spp : alo, alo, ahi), nc++;
            cand[nc][0] = fmax(0, (sh - alo * sp) / n), cand[nc][1] = alo, nc++;
            cand[nc][0] = fmax(0, (sh - ahi * sp) / n), cand[nc][1] = ahi, nc++;
        }
        for (int c = 0; c < nc; c++) {
            double s = 0;
            for (int i = 0; i < n; i++) {
                double r = cand[c][0] + cand[c][1] * q->phi[i] - q->h[i];
                s += r * r;
            }
            if (s < best)
                best = s, off = cand[c][0], A = cand[c][1];
        }
    }
    double s = 0;
    for (int i = 0; i < n; i++) {
        double r = off + A * q->phi[i] - q->h[i];
        s += r * r;
    }
    if (p) {
        p->offset = off;
        p->beta = beta;
        p->tan_gamma = ftan ? 1 / (2 * A) : q->T0;
        p->a_over_b = ftan ? 2 * A * K : K / q->T0;
    }
    return isfinite(s) ? s : INFINITY;
}

/* Hooke and Jeeves' pattern search on (beta, ln K) within the box, from
 * (b, k) with steps (db, dk), down to steps of 1e-13 of the box. */
static double prof_refine(b31_profile *q, double *b, double *k, double db, double dk)
{
    const double tb = 1e-13 * fmax(q->xlo, 1e-300), tk = 1e-13 * (q->lnk_hi - q->lnk_lo);
    double fb = prof_eval(q, *b, *k, NULL);
    double base[2] = {*b, *k};
    for (int guard = 0; guard < 100000 && (db > tb || dk > tk); guard++) {
        /* exploratory moves around base */
        double t[2] = {base[0], base[1]}, ft = fb, step[2] = {db, dk};
        double lo[2] = {0, q->lnk_lo}, hi[2] = {q->xlo, q->lnk_hi};
        for (int d = 0; d < 2; d++)
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                double tr[2] = {t[0], t[1]};
                tr[d] = clampd(t[d] + sgn * step[d], lo[d], hi[d]);
                if (tr[d] == t[d])
                    continue;
                double f = prof_eval(q, tr[0], tr[1], NULL);
                if (f < ft) {
                    ft = f, t[0] = tr[0], t[1] = tr[1];
                    break;
                }
            }
        if (ft < fb) {
            /* pattern moves along the improving direction while they improve */
            for (;;) {
                double pnew[2] = {clampd(2 * t[0] - base[0], 0, q->xlo), clampd(2 * t[1] - base[1], q->lnk_lo, q->lnk_hi)};
                base[0] = t[0], base[1] = t[1], fb = ft;
                double f = prof_eval(q, pnew[0], pnew[1], NULL);
                if (!(f < fb))
                    break;
                t[0] = pnew[0], t[1] = pnew[1], ft = f;
            }
        } else {
            db /= 2, dk /= 2;
        }
    }
    *b = base[0], *k = base[1];
    return fb;
}

static int in_box(const b31_profile *q, const gw_stats_b31 *p)
{
    int ok = p->beta >= 0 && p->beta <= q->xlo && p->a_over_b >= B31_AB_LO && p->a_over_b <= B31_AB_HI;
    if (q->mask & GW_STATS_B31_OFFSET)
        ok = ok && p->offset >= 0;
    if (q->mask & GW_STATS_B31_TANG)
        ok = ok && p->tan_gamma >= B31_T_LO && p->tan_gamma <= B31_T_HI;
    return ok;
}

/* The free parameters lying on an edge of the box (GW_STATS_B31_* bits). */
static int at_bounds(const b31_profile *q, const gw_stats_b31 *p)
{
    int m = 0;
    if (p->beta <= 1e-9 * q->xlo || p->beta >= q->xlo * (1 - 1e-9))
        m |= GW_STATS_B31_BETA;
    if (p->a_over_b <= B31_AB_LO * (1 + 1e-6) || p->a_over_b >= B31_AB_HI * (1 - 1e-6))
        m |= GW_STATS_B31_AB;
    if ((q->mask & GW_STATS_B31_OFFSET) && p->offset <= 0)
        m |= GW_STATS_B31_OFFSET;
    if ((q->mask & GW_STATS_B31_TANG) && (p->tan_gamma <= B31_T_LO * (1 + 1e-6) || p->tan_gamma >= B31_T_HI * (1 - 1e-6)))
        m |= GW_STATS_B31_TANG;
    return m;
}

enum { B31_NB = 65, B31_PER_DECADE = 8, B31_STARTS = 6 };

static int b31_fit(const double *x, const double *h, int n, const gw_stats_b31 *start, int free_mask,
                   gw_stats_b31_fit *fit, gw_err *err)
{
    /* a mask with bits no parameter has (-1, 0xff) was taken as its low four */
    if (free_mask & ~15)
        return gw_err_set(err, GW_EINVAL, "B.31 fit: free_mask %#x holds bits of no parameter (GW_STATS_B31_OFFSET, "
                          "_BETA, _AB and _TANG are 1, 2, 4, 8)", (unsigned)free_mask);
    const int mask = free_mask & 15, p = popcount4(mask);
    if (!(mask & GW_STATS_B31_BETA) || !(mask & GW_STATS_B31_AB))
        return gw_err_set(err, GW_EINVAL, "B.31 fit: beta and a/b must be free (nothing gives them a value to hold)");
    if (n < p)
        return gw_err_set(err, GW_EINVAL, "B.31 fit: %d boundary point(s) for %d free parameter(s)", n, p);
    if (!(mask & GW_STATS_B31_TANG) && !(start->tan_gamma > 0 && start->tan_gamma < INFINITY))
        return gw_err_set(err, GW_EINVAL, "B.31 fit: a fixed tan(gamma) must be finite and > 0");
    if (!(mask & GW_STATS_B31_OFFSET) && !isfinite(start->offset))
        return gw_err_set(err, GW_EINVAL, "B.31 fit: a fixed offset must be finite");
    double xlo = INFINITY;
    for (int i = 0; i < n; i++) {
        if (!isfinite(x[i]) || !isfinite(h[i]))
            return gw_err_set(err, GW_EINVAL, "B.31 fit: boundary point %d is not finite", i + 1);
        xlo = fmin(xlo, x[i]);
    }
    if (!(xlo > 0))
        return gw_err_set(err, GW_EINVAL, "B.31 fit: a boundary point at R_b/R_m = %g (beta lies in [0, R_b/R_m])",
                          xlo);
    b31_profile q = {.x = x, .h = h, .n = n, .mask = mask, .offset0 = start->offset, .T0 = start->tan_gamma,
                     .xlo = xlo};
    if (mask & GW_STATS_B31_TANG)
        q.lnk_lo = log(B31_AB_LO * B31_T_LO), q.lnk_hi = log(B31_AB_HI * B31_T_HI);
    else
        q.lnk_lo = log(B31_AB_LO * q.T0), q.lnk_hi = log(B31_AB_HI * q.T0);
    const int nk = (int)ceil((q.lnk_hi - q.lnk_lo) / log(10) * B31_PER_DECADE) + 1;
    const double db = xlo / (B31_NB - 1), dk = (q.lnk_hi - q.lnk_lo) / (nk - 1);
    double *S = malloc(((size_t)B31_NB * (size_t)nk + (size_t)n) * sizeof *S);
    if (!S)
        return gw_err_set(err, GW_ENOMEM, "B.31 fit: out of memory");
    q.phi = S + (size_t)B31_NB * (size_t)nk;
    for (int i = 0; i < B31_NB; i++)
        for (int j = 0; j < nk; j++)
            S[(size_t)i * nk + j] = prof_eval(&q, i * db, q.lnk_lo + j * dk, NULL);
    /* the grid's local minima (no neighbour lower), best first */
    int si[B31_STARTS], sj[B31_STARTS], ns = 0;
    for (int i = 0; i < B31_NB; i++)
        for (int j = 0; j < nk; j++) {
            double s = S[(size_t)i * nk + j];
            if (!isfinite(s))
                continue;
            int low = 1;
            for (int a = -1; a <= 1 && low; a++)
                for (int b = -1; b <= 1 && low; b++)
                    if ((a || b) && i + a >= 0 && i + a < B31_NB && j + b >= 0 && j + b < nk &&
                        S[(size_t)(i + a) * nk + j + b] < s)
                        low = 0;
            if (!low)
                continue;
            int pos = ns < B31_STARTS ? ns++ : B31_STARTS;
            while (pos > 0 && S[(size_t)si[pos - 1] * nk + sj[pos - 1]] > s) {
                if (pos < B31_STARTS)
                    si[pos] = si[pos - 1], sj[pos] = sj[pos - 1];
                pos--;
            }
            if (pos < B31_STARTS)
                si[pos] = i, sj[pos] = j;
        }
    double bb = NAN, bk = NAN, bs = INFINITY;
    for (int s = 0; s < ns; s++) {
        double b = si[s] * db, k = q.lnk_lo + sj[s] * dk;
        double f = prof_refine(&q, &b, &k, db, dk);
        if (f < bs)
            bs = f, bb = b, bk = k;
    }
    if (!(bs < INFINITY)) {
        free(S);
        return gw_err_set(err, GW_EINVAL, "B.31 fit: no finite sum of squares in the box (%d points)", n);
    }
    gw_stats_b31 best;
    prof_eval(&q, bb, bk, &best);
    /* a last Levenberg-Marquardt polish in all the free parameters, kept when
     * it stays in the box and lowers the sum; the covariance where it ends */
    b31_problem pb = {.x = x, .h = h, .n = n, .mask = mask};
    b31_try t;
    int iters = 0;
    if (b31_run(&pb, &best, p, 500, &t) == GW_OK && t.converged && t.cost <= bs && in_box(&q, &t.p)) {
        best = t.p, bs = t.cost, iters = t.iterations;
    }
    int rc = b31_run(&pb, &best, p, 0, &t);
    free(S);
    if (rc != GW_OK)
        return gw_err_set(err, GW_EINVAL, "B.31 fit: the covariance failed (%d points)", n);
    fit->p = best;
    fit->free_mask = mask;
    fit->at_bound = at_bounds(&q, &best);
    fit->n = n;
    fit->dof = n - p;
    fit->iterations = iters;
    fit->evaluations = q.evals;
    fit->converged = 1;
    fit->rms = sqrt(bs / n);
    double s2 = fit->dof > 0 ? bs / fit->dof : NAN;
    double sd[4];
    for (int k = 0; k < p; k++)
        sd[k] = sqrt(s2 * t.cov[k * 4 + k]);
    int k = 0, kb = -1, ka = -1;
    if (mask & GW_STATS_B31_OFFSET)
        fit->err.offset = sd[k++];
    fit->err.beta = sd[kb = k++];
    fit->err.a_over_b = fit->p.a_over_b * sd[ka = k++]; /* d(a/b) = (a/b) d ln(a/b) */
    if (mask & GW_STATS_B31_TANG)
        fit->err.tan_gamma = fit->p.tan_gamma * sd[k++];
    fit->corr_beta_ab = t.cov[kb * 4 + ka] / sqrt(t.cov[kb * 4 + kb] * t.cov[ka * 4 + ka]);
    gw_stats_b31_min(&fit->p, &fit->x_min, &fit->h_min);
    return GW_OK;
}

/* GSL's default error handler aborts: a boundary at H* near 1e308 R_m (a
 * table with penetrations near the largest double, the offset half their
 * mean) made the QR of the covariance report a rank of 0, and layer-stats
 * died of SIGABRT. Errors are statuses here: such a start does not converge. */
int gw_stats_b31_fit_points(const double *x, const double *h, int n, const gw_stats_b31 *start,
                            int free_mask, gw_stats_b31_fit *fit, gw_err *err)
{
    if (!fit)
        return gw_err_set(err, GW_EINVAL, "gw_stats_b31_fit_points: fit is NULL");
    if (!start || (n > 0 && (!x || !h))) {
        memset(fit, 0, sizeof *fit);
        return gw_err_set(err, GW_EINVAL, "gw_stats_b31_fit_points: %s is NULL", !start ? "start" : !x ? "x" : "h");
    }
    memset(fit, 0, sizeof *fit);
    gsl_error_handler_t *old = gw_gsl_quiet_begin();
    const int rc = b31_fit(x, h, n, start, free_mask, fit, err);
    gw_gsl_quiet_end(old);
    return rc;
}
