/*
 * chain_layer.c: a sphere pressed on an elastic layer bonded to a rigid base (a
 * sheet glued on the force sensor), frictionless on top, for any ratio of contact
 * radius to thickness.
 *
 * Surface displacement of a layer of thickness h (Young E, Poisson nu) bonded to a
 * rigid base, under an axisymmetric pressure p(r) with Hankel transform
 * P(xi) = int_0^a p(r) r J0(xi r) dr:
 *   w(r) = (2 (1 - nu^2)/E) int_0^inf P(xi) C(xi h) J0(xi r) dxi,
 *   C(t) = (2 k sinh 2t - 4t) / (2 k cosh 2t + 1 + k^2 + 4 t^2),   k = 3 - 4 nu
 * (C -> 1: half-space; C ~ t (1 - 2nu) / (2 (1 - nu)^2) for t -> 0: the thin layer is
 * a Winkler foundation of modulus M/h, M = E (1 - nu)/((1 + nu)(1 - 2 nu))). The
 * sphere's own compliance is a half-space's, so with 1/E* = (1-nu^2)/E + (1-nu_s^2)/E_s
 * the combined kernel is 1 - lam Q(xi h), Q = 1 - C, lam = E* (1 - nu^2)/E.
 * Writing P(xi) = int_0^a g(t) cos(xi t) dt (p = 0 beyond a, F = 2 pi int_0^a g), the
 * condition w = d - r^2/(2R) for r < a becomes, after Abel inversion, a Fredholm
 * equation of the second kind (Lebedev & Ufliand 1958; Hayes et al. 1972):
 *   g(t) - (2 lam/pi) int_0^a g(s) int_0^inf Q(xi h) cos(xi s) cos(xi t) dxi ds
 *        = (E* / pi) (d - t^2/R).
 * With t = a tau, alpha = a/h, q(x) = int_0^inf Q(u) cos(u x) du, the kernel is
 * (lam alpha/pi) [q(alpha (tau - sigma)) + q(alpha (tau + sigma))]. Splitting
 * g = (E* / pi)(d g1 - (a^2/R) g2) (right-hand sides 1 and tau^2), the smooth edge
 * g(a) = 0 gives d = (a^2/R) g2(1)/g1(1) and F = 2 E* a (d I1 - (a^2/R) I2),
 * I_i = int_0^1 g_i. Half-space (Q = 0): d = a^2/R, F = (4/3) E* a^3/R (Hertz).
 * Dimensionless: d = dhat h^2/R, F = Fhat E* h^3/R.
 * Numerics: q tabulated once per law (Gauss-Legendre panels in u, GSL), Nystrom on
 * Gauss-Legendre nodes with GSL's LU for alpha on a log grid, then ln F against
 * ln d interpolated by a monotone cubic (Fritsch-Carlson) and resampled on a uniform
 * ln d grid for constant-time evaluation; below the grid (a < 1e-3 h) Hertz times
 * 1 + b0 sqrt(R d)/h matched at the first node, above it a power law with the end
 * slope. The stored energy U(d) = int_0^d F is integrated from the interpolant.
 * Limits (tests/test_chain_walls.c): thick (a << h): F/F_Hertz = 1 + (2 q(0)/pi) chi
 * + O(chi^2), chi = sqrt(R d)/h (the bonded-layer coefficient 1.133 of Dimitriadis
 * et al. 2002 for nu = 1/2); thin (a >> h, nu < 1/2): F = pi R M d^2/h (Johnson 1985,
 * section 5.9).
 * Sharing: a process builds each law once per distinct set of inputs and hands
 * out references to it (the memo below; gw_layer_law_free drops one).
 * Units: SI (m, Pa, N, J).
 */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_linalg.h>

#include "chain_layer.h"
#include "chain_material.h"
#include "gw_chain.h"
#include "gw_global.h"

#define Q_UMAX 40.0    /* Q(u) ~ u^2 e^(-2u): below 1e-30 beyond */
#define Q_PANEL 0.25   /* width of a Gauss-Legendre panel in u */
#define Q_NODES 16     /* nodes per panel */
#define Q_DX 0.01      /* spacing of the q(x) table */
#define ALPHA_LO 1e-3  /* smallest a/h solved: F/F_Hertz - 1 ~ 1e-3 */
#define N_ALPHA 72     /* alpha samples */
#define N_GRID 256     /* uniform ln d nodes of the law */

/* Every input the law depends on, as given (compared bit for bit): sphere radius,
 * thickness, layer Young and Poisson, sphere Young and Poisson. */
#define LAYER_KEY 6
typedef struct layer_key {
    double v[LAYER_KEY];
} layer_key;

struct gw_layer_law {
    double radius, thickness, young, poisson, estar, lambda;
    double dscale, fscale; /* h^2/R (m), E* h^3/R (N) */
    double s0, ds;         /* ln dhat of node 0 and the spacing */
    double y[N_GRID], yp[N_GRID], ucum[N_GRID]; /* ln Fhat, d ln Fhat / d ln dhat, Uhat */
    double la[N_GRID];     /* ln alpha at the nodes (contact radius) */
    double b0;             /* below node 0: Fhat = (4/3) dhat^(3/2) (1 + b0 sqrt(dhat)) */
    double alpha_max;
    /* the memo's (below), under memo_lock */
    layer_key key;
    int refs;                  /* references handed out and not yet freed */
    int building;              /* 1 while the creating thread builds the tables */
    struct gw_layer_law *next; /* the memo's list, most recently used first */
};

static double layer_q_integrand(double u, double kap)
{
    double e2 = exp(-2.0 * u), e4 = e2 * e2;
    double c = (kap * (1.0 - e4) - 4.0 * u * e2) / (kap * (1.0 + e4) + (1.0 + kap * kap + 4.0 * u * u) * e2);
    return 1.0 - c;
}

typedef struct qtab {
    int nx;
    double *q; /* q(j Q_DX), j = 0..nx-1 */
} qtab;

static int qtab_build(double poisson, double xmax, qtab *t, gw_err *err)
{
    const double kap = 3.0 - 4.0 * poisson;
    const int npan = (int)(Q_UMAX / Q_PANEL), nu = npan * Q_NODES;
    t->nx = (int)ceil(xmax / Q_DX) + 4;
    t->q = malloc((size_t)t->nx * sizeof *t->q);
    double *u = malloc(2 * (size_t)nu * sizeof *u), *wq = u ? u + nu : NULL;
    gsl_integration_glfixed_table *gl = gsl_integration_glfixed_table_alloc(Q_NODES);
    if (!t->q || !u || !gl) {
        free(u);
        gsl_integration_glfixed_table_free(gl);
        return gw_err_set(err, GW_ENOMEM, "layer law: out of memory");
    }
    for (int p = 0; p < npan; p++)
        for (int i = 0; i < Q_NODES; i++) {
            double x, w;
            gsl_integration_glfixed_point(p * Q_PANEL, (p + 1) * Q_PANEL, (size_t)i, &x, &w, gl);
            u[p * Q_NODES + i] = x;
            wq[p * Q_NODES + i] = w * layer_q_integrand(x, kap);
        }
    for (int j = 0; j < t->nx; j++) {
        double x = j * Q_DX, s = 0.0;
        for (int i = 0; i < nu; i++)
            s += wq[i] * cos(u[i] * x);
        t->q[j] = s;
    }
    free(u);
    gsl_integration_glfixed_table_free(gl);
    return GW_OK;
}

/* q(x) by cubic Lagrange interpolation; q is even, so q(-dx) = q(dx). */
static double qtab_eval(const qtab *t, double x)
{
    x = fabs(x);
    double s = x / Q_DX;
    int j = (int)s;
    if (j > t->nx - 3)
        j = t->nx - 3;
    double f = s - j;
    double qm = j > 0 ? t->q[j - 1] : t->q[1], q0 = t->q[j], q1 = t->q[j + 1], q2 = t->q[j + 2];
    return q0 + 0.5 * f * (q1 - qm + f * (2.0 * qm - 5.0 * q0 + 4.0 * q1 - q2 + f * (3.0 * (q0 - q1) + q2 - qm)));
}

/* Nystrom solution at one alpha with n nodes: dhat, Fhat. */
static int solve_alpha(const qtab *t, double alpha, double lam, int n, double *dhat, double *fhat,
                       gw_err *err)
{
    gsl_integration_glfixed_table *gl = gsl_integration_glfixed_table_alloc((size_t)n);
    gsl_matrix *A = gsl_matrix_alloc((size_t)n, (size_t)n);
    gsl_vector *b1 = gsl_vector_alloc((size_t)n), *b2 = gsl_vector_alloc((size_t)n);
    gsl_permutation *perm = gsl_permutation_alloc((size_t)n);
    double *tau = malloc(2 * (size_t)n * sizeof *tau), *w = tau ? tau + n : NULL;
    int rc = GW_OK, sign = 0;
    if (!gl || !A || !b1 || !b2 || !perm || !tau) {
        rc = gw_err_set(err, GW_ENOMEM, "layer law: out of memory");
        goto done;
    }
    for (int i = 0; i < n; i++)
        gsl_integration_glfixed_point(0.0, 1.0, (size_t)i, &tau[i], &w[i], gl);
    const double c = lam * alpha / M_PI;
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++) {
            double k = c * (qtab_eval(t, alpha * (tau[i] - tau[j])) + qtab_eval(t, alpha * (tau[i] + tau[j])));
            gsl_matrix_set(A, (size_t)i, (size_t)j, (i == j) - k * w[j]);
        }
        gsl_vector_set(b1, (size_t)i, 1.0);
        gsl_vector_set(b2, (size_t)i, tau[i] * tau[i]);
    }
    gsl_error_handler_t *old = gw_gsl_quiet_begin();
    int st = gsl_linalg_LU_decomp(A, perm, &sign);
    if (st == 0)
        st = gsl_linalg_LU_svx(A, perm, b1);
    if (st == 0)
        st = gsl_linalg_LU_svx(A, perm, b2);
    gw_gsl_quiet_end(old);
    if (st != 0) {
        rc = gw_err_set(err, GW_ESOLVER, "layer law: singular Nystrom system at a/h = %g", alpha);
        goto done;
    }
    double g1e = 1.0, g2e = 1.0, i1 = 0.0, i2 = 0.0;
    for (int j = 0; j < n; j++) {
        double k = c * (qtab_eval(t, alpha * (1.0 - tau[j])) + qtab_eval(t, alpha * (1.0 + tau[j])));
        double g1 = gsl_vector_get(b1, (size_t)j), g2 = gsl_vector_get(b2, (size_t)j);
        g1e += k * w[j] * g1;
        g2e += k * w[j] * g2;
        i1 += w[j] * g1;
        i2 += w[j] * g2;
    }
    double rho = g2e / g1e;
    *dhat = alpha * alpha * rho;
    *fhat = 2.0 * alpha * alpha * alpha * (rho * i1 - i2);
    if (!(*dhat > 0) || !(*fhat > 0))
        rc = gw_err_set(err, GW_ESOLVER, "layer law: no contact solution at a/h = %g", alpha);
done:
    gsl_integration_glfixed_table_free(gl);
    gsl_matrix_free(A);
    gsl_vector_free(b1);
    gsl_vector_free(b2);
    gsl_permutation_free(perm);
    free(tau);
    return rc;
}

static int nodes_for(double alpha)
{
    int n = 16 + (int)ceil(12.0 * alpha);
    return n > 640 ? 640 : n;
}

int gw_layer_solve_point(double alpha, double poisson, double lambda, double *dhat,
                         double *fhat, gw_err *err)
{
    if (!dhat || !fhat) /* they were written through (SIGSEGV) */
        return gw_err_set(err, GW_EINVAL, "gw_layer_solve_point: %s is NULL", !dhat ? "dhat" : "fhat");
    if (!(alpha > 0 && alpha <= 100) || !(poisson >= 0 && poisson <= 0.5) ||
        !(lambda >= 0 && lambda <= 1))
        return gw_err_set(err, GW_EINVAL, "layer law: a/h in (0, 100], Poisson ratio in [0, 0.5], "
                                          "compliance share in [0, 1] (got %g, %g, %g)",
                          alpha, poisson, lambda);
    /* fhat ~ (4/3) alpha^3 and dhat ~ alpha^2 (Hertz, a << h): below
     * GW_LAYER_ALPHA_MIN fhat is no normal double. alpha = 1e-300 failed as
     * "no contact solution" (fhat underflowed to 0), naming no input. */
    if (alpha < GW_LAYER_ALPHA_MIN)
        return gw_err_set(err, GW_EINVAL, "gw_layer_solve_point: alpha (a/h) = %g is below %g: fhat (about "
                          "(4/3) alpha^3) would fall below the normal doubles; give alpha in [%g, 100]", alpha,
                          GW_LAYER_ALPHA_MIN, GW_LAYER_ALPHA_MIN);
    qtab t = {0, NULL};
    int rc = qtab_build(poisson, 2.0 * alpha + 0.1, &t, err);
    if (rc == GW_OK)
        rc = solve_alpha(&t, alpha, lambda, nodes_for(alpha), dhat, fhat, err);
    free(t.q);
    return rc;
}

/* Fritsch-Carlson slopes of a monotone increasing sequence (x, y), n >= 2. */
static void pchip_slopes(const double *x, const double *y, int n, double *m)
{
    for (int k = 1; k < n - 1; k++) {
        double h0 = x[k] - x[k - 1], h1 = x[k + 1] - x[k];
        double d0 = (y[k] - y[k - 1]) / h0, d1 = (y[k + 1] - y[k]) / h1;
        m[k] = d0 * d1 > 0 ? 3.0 * (h0 + h1) / ((2.0 * h1 + h0) / d0 + (h1 + 2.0 * h0) / d1) : 0.0;
    }
    m[0] = (y[1] - y[0]) / (x[1] - x[0]);
    m[n - 1] = (y[n - 1] - y[n - 2]) / (x[n - 1] - x[n - 2]);
}

static double hermite(double y0, double y1, double m0, double m1, double h, double f, double *dy)
{
    double f2 = f * f, f3 = f2 * f;
    if (dy)
        *dy = ((6 * f2 - 6 * f) * y0 + (3 * f2 - 4 * f + 1) * h * m0 + (6 * f - 6 * f2) * y1 +
               (3 * f2 - 2 * f) * h * m1) / h;
    return (2 * f3 - 3 * f2 + 1) * y0 + (f3 - 2 * f2 + f) * h * m0 + (3 * f2 - 2 * f3) * y1 +
           (f3 - f2) * h * m1;
}

/* ln Fhat and its slope at s = ln dhat. */
static double law_eval(const gw_layer_law *l, double s, double *slope)
{
    double x = (s - l->s0) / l->ds;
    if (x <= 0) { /* Hertz with the first-order (linear in chi) correction */
        double c = l->b0 * exp(0.5 * s);
        *slope = 1.5 + 0.5 * c / (1.0 + c);
        return log(4.0 / 3.0) + 1.5 * s + log1p(c);
    }
    if (x >= N_GRID - 1) {
        *slope = l->yp[N_GRID - 1];
        return l->y[N_GRID - 1] + l->yp[N_GRID - 1] * (s - l->s0 - (N_GRID - 1) * l->ds);
    }
    int j = (int)x;
    return hermite(l->y[j], l->y[j + 1], l->yp[j], l->yp[j + 1], l->ds, x - j, slope);
}

/* int exp(y(s) + s) ds over [a, b] inside one interval (4-point Gauss-Legendre). */
static double law_segment_energy(const gw_layer_law *l, double a, double b)
{
    static const double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
    static const double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
    double s = 0.0, sl;
    for (int i = 0; i < 4; i++) {
        double x = 0.5 * (a + b) + 0.5 * (b - a) * gx[i];
        s += gw[i] * exp(law_eval(l, x, &sl) + x);
    }
    return 0.5 * (b - a) * s;
}

/* The tables of l for these inputs (validated); l's other fields untouched. */
static int layer_build(gw_layer_law *l, double radius, const gw_material *bead, double thickness, double young,
                       double poisson, gw_err *err)
{
    double cl = (1.0 - poisson * poisson) / young;
    double cs = isinf(bead->young) ? 0.0 : (1.0 - bead->poisson * bead->poisson) / bead->young;
    l->radius = radius;
    l->thickness = thickness;
    l->young = young;
    l->poisson = poisson;
    l->estar = 1.0 / (cl + cs);
    l->lambda = cl / (cl + cs);
    l->dscale = thickness * thickness / radius;
    l->fscale = l->estar * thickness * thickness * thickness / radius;
    /* contact radii up to twice the sphere radius (beyond, the sphere is buried in
     * the layer and the small-strain geometry has long lost meaning), at most 40 h */
    l->alpha_max = fmin(40.0, fmax(2.0, 2.0 * radius / thickness));
    qtab t = {0, NULL};
    double al[N_ALPHA], xd[N_ALPHA], yf[N_ALPHA], m[N_ALPHA], ma[N_ALPHA];
    int rc = qtab_build(poisson, 2.0 * l->alpha_max + 0.1, &t, err);
    for (int k = 0; rc == GW_OK && k < N_ALPHA; k++) {
        al[k] = ALPHA_LO * pow(l->alpha_max / ALPHA_LO, (double)k / (N_ALPHA - 1));
        double dh, fh;
        rc = solve_alpha(&t, al[k], l->lambda, nodes_for(al[k]), &dh, &fh, err);
        xd[k] = log(dh);
        yf[k] = log(fh);
        if (rc == GW_OK && k > 0 && !(xd[k] > xd[k - 1] && yf[k] > yf[k - 1]))
            rc = gw_err_set(err, GW_ESOLVER, "layer law: force not increasing with the overlap at a/h = %g", al[k]);
        al[k] = log(al[k]);
    }
    free(t.q);
    if (rc != GW_OK)
        return rc;
    pchip_slopes(xd, yf, N_ALPHA, m);
    pchip_slopes(xd, al, N_ALPHA, ma);
    l->s0 = xd[0];
    l->ds = (xd[N_ALPHA - 1] - xd[0]) / (N_GRID - 1);
    for (int j = 0, k = 0; j < N_GRID; j++) {
        double s = l->s0 + j * l->ds;
        if (j == N_GRID - 1)
            s = xd[N_ALPHA - 1];
        while (k < N_ALPHA - 2 && s > xd[k + 1])
            k++;
        double h = xd[k + 1] - xd[k], f = (s - xd[k]) / h;
        l->y[j] = hermite(yf[k], yf[k + 1], m[k], m[k + 1], h, f, &l->yp[j]);
        l->la[j] = hermite(al[k], al[k + 1], ma[k], ma[k + 1], h, f, NULL);
    }
    /* below node 0 (a/h < 1e-3): Hertz times 1 + b0 sqrt(dhat), matched at node 0 */
    double d0 = exp(l->s0);
    l->b0 = (exp(l->y[0]) / (4.0 / 3.0 * d0 * sqrt(d0)) - 1.0) / sqrt(d0);
    l->ucum[0] = 4.0 / 3.0 * (0.4 * d0 * d0 * sqrt(d0) + l->b0 * d0 * d0 * d0 / 3.0);
    for (int j = 1; j < N_GRID; j++)
        l->ucum[j] = l->ucum[j - 1] + law_segment_energy(l, l->s0 + (j - 1) * l->ds, l->s0 + j * l->ds);
    return GW_OK;
}

/* ---- memo ----
 * One law object per distinct set of inputs in a process: a create with the
 * inputs of a law the memo holds returns that object with one more reference,
 * and gw_layer_law_free drops one. A law nobody references stays in the memo,
 * idle, for a later create (a sweep case's check frees its law before the case
 * runs); at most CHAIN_LAYER_MEMO_IDLE idle laws are kept (8.3 kB each), the least
 * recently used freed first. A law being built is in the memo as such: a
 * create of the same inputs in another thread waits for it (the condition
 * variable) instead of building it again, and builds it itself if that build
 * failed (only successes are kept). The lock is never held during a build,
 * and a fork waits for it (pthread_atfork, as gw_global.h's); the child drops
 * the laws other threads were building (it has not those threads). */

static struct {
    gw_layer_law *head; /* every law handed out or idle, most recently used first */
    long built, shared; /* creates that built a law, creates answered from the memo */
    int keep;           /* idle laws kept at most */
} memo = {NULL, 0, 0, CHAIN_LAYER_MEMO_IDLE};
static pthread_cond_t memo_built = PTHREAD_COND_INITIALIZER;

static void memo_fork_child(void)
{
    for (gw_layer_law **pp = &memo.head; *pp;) {
        gw_layer_law *l = *pp;
        if (l->building) { /* its builder is a thread of the parent */
            *pp = l->next;
            free(l);
        } else
            pp = &l->next;
    }
    pthread_cond_init(&memo_built, NULL);
}

static gw_forklock memo_lock = GW_FORKLOCK(memo_fork_child);

/* Unlink l from the list (under the lock). */
static void memo_unlink(gw_layer_law *l)
{
    for (gw_layer_law **pp = &memo.head; *pp; pp = &(*pp)->next)
        if (*pp == l) {
            *pp = l->next;
            return;
        }
}

static void memo_to_front(gw_layer_law *l)
{
    memo_unlink(l);
    l->next = memo.head;
    memo.head = l;
}

/* Free the idle laws beyond the keep most recently used (under the lock). */
static void memo_trim(int keep)
{
    int idle = 0;
    for (gw_layer_law **pp = &memo.head; *pp;) {
        gw_layer_law *l = *pp;
        if (l->refs == 0 && !l->building && ++idle > keep) {
            *pp = l->next;
            free(l);
        } else
            pp = &l->next;
    }
}

void chain_layer_memo_stats(long *built, long *shared, int *laws)
{
    gw_forklock_take(&memo_lock);
    int n = 0;
    for (const gw_layer_law *l = memo.head; l; l = l->next)
        n++;
    *built = memo.built;
    *shared = memo.shared;
    *laws = n;
    gw_forklock_give(&memo_lock);
}

void chain_layer_memo_clear(void)
{
    gw_forklock_take(&memo_lock);
    memo_trim(0);
    memo.built = memo.shared = 0;
    gw_forklock_give(&memo_lock);
}

int chain_layer_memo_keep(int keep)
{
    gw_forklock_take(&memo_lock);
    int old = memo.keep;
    if (keep >= 0) {
        memo.keep = keep;
        memo_trim(keep);
    }
    gw_forklock_give(&memo_lock);
    return old;
}

int gw_layer_law_create(double radius, const gw_material *bead, double thickness, double young,
                        double poisson, gw_layer_law **out, gw_err *err)
{
    if (!out)
        return gw_err_set(err, GW_EINVAL, "gw_layer_law_create: out is NULL");
    *out = NULL;
    int rc;
    if ((rc = gw_check_range(radius, "layer law: sphere radius (m)", 1e-6, 1.0, err)) != GW_OK ||
        (rc = gw_check_range(thickness, "layer law: thickness (m)", 1e-7, 1.0, err)) != GW_OK ||
        (rc = gw_check_range(young, "layer law: Young modulus (Pa)", 1e3, 1e13, err)) != GW_OK ||
        (rc = gw_check_range(poisson, "layer law: Poisson ratio", 0.0, 0.5, err)) != GW_OK)
        return rc;
    if ((rc = chain_material_check(bead, "layer law: sphere material", err)) != GW_OK)
        return rc;
    layer_key k;
    const double v[LAYER_KEY] = {radius, thickness, young, poisson, bead->young, bead->poisson};
    memcpy(k.v, v, sizeof v);
    gw_forklock_take(&memo_lock);
    gw_layer_law *l;
    for (;;) {
        for (l = memo.head; l && memcmp(&l->key, &k, sizeof k) != 0; l = l->next)
            ;
        if (!l || !l->building)
            break;
        pthread_cond_wait(&memo_built, &memo_lock.mutex); /* another thread builds it */
    }
    if (l) {
        l->refs++;
        memo.shared++;
        memo_to_front(l);
        gw_forklock_give(&memo_lock);
        *out = l;
        return GW_OK;
    }
    l = calloc(1, sizeof *l);
    if (!l) {
        gw_forklock_give(&memo_lock);
        return gw_err_set(err, GW_ENOMEM, "layer law: out of memory");
    }
    l->key = k;
    l->refs = 1;
    l->building = 1;
    l->next = memo.head;
    memo.head = l;
    gw_forklock_give(&memo_lock);

    rc = layer_build(l, radius, bead, thickness, young, poisson, err);

    gw_forklock_take(&memo_lock);
    l->building = 0;
    if (rc == GW_OK)
        memo.built++;
    else
        memo_unlink(l);
    pthread_cond_broadcast(&memo_built);
    gw_forklock_give(&memo_lock);
    if (rc != GW_OK) {
        free(l);
        return rc;
    }
    *out = l;
    return GW_OK;
}

void gw_layer_law_free(gw_layer_law *l)
{
    if (!l)
        return;
    gw_forklock_take(&memo_lock);
    if (l->refs > 0 && --l->refs == 0) {
        memo_to_front(l);
        memo_trim(memo.keep);
    }
    gw_forklock_give(&memo_lock);
}

double gw_layer_law_force(const gw_layer_law *l, double d, double *stiffness)
{
    if (!l || isnan(d)) { /* NULL was read (SIGSEGV), a NaN overlap gave 0 N */
        if (stiffness)
            *stiffness = NAN;
        return NAN;
    }
    if (!(d > 0)) {
        if (stiffness)
            *stiffness = 0.0;
        return 0.0;
    }
    double sl, f = l->fscale * exp(law_eval(l, log(d / l->dscale), &sl));
    if (stiffness)
        *stiffness = f * sl / d;
    return f;
}

double gw_layer_law_energy(const gw_layer_law *l, double d)
{
    if (!l || isnan(d))
        return NAN;
    if (!(d > 0))
        return 0.0;
    double s = log(d / l->dscale), u;
    double x = (s - l->s0) / l->ds;
    if (x <= 0) {
        double dh = exp(s);
        u = 4.0 / 3.0 * (0.4 * dh * dh * sqrt(dh) + l->b0 * dh * dh * dh / 3.0);
    } else if (x >= N_GRID - 1) {
        double se = l->s0 + (N_GRID - 1) * l->ds, p1 = l->yp[N_GRID - 1] + 1.0;
        u = l->ucum[N_GRID - 1] + exp(l->y[N_GRID - 1] + se) * expm1(p1 * (s - se)) / p1;
    } else {
        int j = (int)x;
        u = l->ucum[j] + law_segment_energy(l, l->s0 + j * l->ds, s);
    }
    return u * l->fscale * l->dscale;
}

double gw_layer_law_overlap(const gw_layer_law *l, double f)
{
    if (!l || isnan(f))
        return NAN;
    if (!(f > 0))
        return 0.0;
    double target = log(f / l->fscale), lo = l->s0 - 40.0, hi = l->s0 + N_GRID * l->ds + 40.0, sl;
    for (int it = 0; it < 200 && hi - lo > 1e-14 * fabs(hi); it++) {
        double mid = 0.5 * (lo + hi);
        if (law_eval(l, mid, &sl) < target)
            lo = mid;
        else
            hi = mid;
    }
    return l->dscale * exp(0.5 * (lo + hi));
}

double gw_layer_law_contact_radius(const gw_layer_law *l, double d)
{
    if (!l || isnan(d))
        return NAN;
    if (!(d > 0))
        return 0.0;
    double s = log(d / l->dscale), x = (s - l->s0) / l->ds;
    if (x <= 0) /* Hertz side: a = sqrt(R d) */
        return sqrt(l->radius * d);
    if (x >= N_GRID - 1)
        return l->thickness * exp(l->la[N_GRID - 1]);
    int j = (int)x;
    double f = x - j;
    return l->thickness * exp((1 - f) * l->la[j] + f * l->la[j + 1]);
}

double gw_layer_law_hertz_k(const gw_layer_law *l)
{
    if (!l)
        return NAN;
    return 4.0 / 3.0 * l->estar * sqrt(l->radius);
}

double gw_layer_law_thickness(const gw_layer_law *l)
{
    if (!l)
        return NAN;
    return l->thickness;
}
