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
    memset(d, 0, sizeof *d);
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

double gw_stats_b31_eval(const gw_stats_b31 *p, double x)
{
    double T = p->tan_gamma, K = p->a_over_b * T, u = x - p->beta;
    double r = sqrt(u * u + K * x * x);
    double g = u > 0 ? K * x * x / (r + u) : r - u;
    return p->offset + g / (2 * T);
}

void gw_stats_b31_min(const gw_stats_b31 *p, double *x_min, double *f_min)
{
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

/* One trust-region run from start; fills t (cost = sum of squares). */
static int b31_run(b31_problem *pb, const gw_stats_b31 *start, int p, b31_try *t)
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
        int st = gsl_multifit_nlinear_driver(500, 1e-12, 1e-12, 0.0, NULL, NULL, &info, w);
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

static int b31_fit(const double *x, const double *h, int n, const gw_stats_b31 *start, int free_mask,
                   gw_stats_b31_fit *fit, gw_err *err)
{
    int p = popcount4(free_mask & 15);
    if (p == 0)
        return gw_err_set(err, GW_EINVAL, "B.31 fit: no free parameter");
    if (n < p)
        return gw_err_set(err, GW_EINVAL, "B.31 fit: %d boundary point(s) for %d free parameter(s)", n, p);
    if (!(start->tan_gamma > 0) || !(start->a_over_b > 0) || !isfinite(start->beta) ||
        !isfinite(start->offset))
        return gw_err_set(err, GW_EINVAL, "B.31 fit: start needs a/b > 0, tan(gamma) > 0, finite beta and offset");
    /* starts for beta: fractions of the x of the lowest point (the minimum of
     * B.31 is at x = 2 beta / (1 + K), so beta near half of it), a/b from the
     * depth of that minimum above the offset */
    int lo = 0;
    for (int i = 1; i < n; i++)
        if (h[i] < h[lo])
            lo = i;
    static const double frac[] = {0.5, 0.3, 0.7, 0.9, 0.15};
    b31_problem pb = {.x = x, .h = h, .n = n, .mask = free_mask & 15};
    b31_try best = {.cost = INFINITY}, t;
    int any = 0;
    for (size_t s = 0; s < sizeof frac / sizeof frac[0]; s++) {
        gw_stats_b31 st = *start;
        if (pb.mask & GW_STATS_B31_BETA)
            st.beta = frac[s] * x[lo];
        if ((pb.mask & GW_STATS_B31_AB) && st.beta > 0 && h[lo] - st.offset > 0)
            st.a_over_b = (h[lo] - st.offset) / st.beta;
        if (b31_run(&pb, &st, p, &t) != GW_OK)
            continue;
        if (t.converged && (!best.converged || t.cost < best.cost)) {
            best = t;
            any = 1;
        }
        if (!(pb.mask & GW_STATS_B31_BETA))
            break; /* the starts differ only in beta */
    }
    if (!any)
        return gw_err_set(err, GW_EINVAL, "B.31 fit: no start converged (%d points)", n);
    fit->p = best.p;
    fit->free_mask = pb.mask;
    fit->n = n;
    fit->dof = n - p;
    fit->iterations = best.iterations;
    fit->converged = 1;
    fit->rms = sqrt(best.cost / n);
    double s2 = fit->dof > 0 ? best.cost / fit->dof : NAN;
    double sd[4];
    for (int k = 0; k < p; k++)
        sd[k] = sqrt(s2 * best.cov[k * 4 + k]);
    int k = 0, kb = -1, ka = -1;
    if (pb.mask & GW_STATS_B31_OFFSET)
        fit->err.offset = sd[k++];
    if (pb.mask & GW_STATS_B31_BETA)
        fit->err.beta = sd[kb = k++];
    if (pb.mask & GW_STATS_B31_AB)
        fit->err.a_over_b = fit->p.a_over_b * sd[ka = k++]; /* d(a/b) = (a/b) d ln(a/b) */
    if (pb.mask & GW_STATS_B31_TANG)
        fit->err.tan_gamma = fit->p.tan_gamma * sd[k++];
    fit->corr_beta_ab = kb >= 0 && ka >= 0
                            ? best.cov[kb * 4 + ka] / sqrt(best.cov[kb * 4 + kb] * best.cov[ka * 4 + ka])
                            : NAN;
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
    memset(fit, 0, sizeof *fit);
    gsl_error_handler_t *old = gw_gsl_quiet_begin();
    const int rc = b31_fit(x, h, n, start, free_mask, fit, err);
    gw_gsl_quiet_end(old);
    return rc;
}
