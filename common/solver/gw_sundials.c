/*
 * gw_sundials.c: callback wrappers between SUNDIALS and gw_system (see header).
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "gw_hermite.h"
#include "gw_sundials.h"
#include "gw_locale.h"

int gw_sun_rhs(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    gw_solver *s = ud;
    if (gw_interrupt_pending())
        return -1; /* unrecoverable: gw_solver_advance reports the interrupt */
    return s->sys.rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), s->sys.params);
}

int gw_sun_rhs_queued(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    gw_solver *s = ud;
    if (gw_interrupt_pending())
        return -1; /* unrecoverable: gw_solver_advance reports the interrupt */
    if (s->sys.rhs_range &&
        gw_sun_nv_rhs(t, y, ydot, s->sys.rhs_range, s->sys.rhs_halo, s->sys.params) == 0)
        return 0;
    return s->sys.rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), s->sys.params);
}

/* The fixed-point iteration without its two copies (see gw_sundials.h): the
 * library's solve with m = 0 (SUNDIALS 6.4.1) step by step, with the change
 * between iterates formed as g(y_k) - y_k (the library forms y_(k+1) - y_k
 * after copying g(y_k) into y_(k+1) and y_k aside: the same subtraction of the
 * same values) and g(y_k) handed to the corrector by exchanging the two
 * vectors' data instead of copying it. */
static int fp_swappable(N_Vector a, N_Vector b)
{
    if (N_VGetVectorID(a) != SUNDIALS_NVEC_SERIAL || N_VGetVectorID(b) != SUNDIALS_NVEC_SERIAL)
        return 0;
    const N_VectorContent_Serial ca = a->content, cb = b->content;
    return ca->length == cb->length && ca->own_data && cb->own_data && ca->data != cb->data;
}

static int fp_solve(SUNNonlinearSolver NLS, N_Vector y0, N_Vector ycor, N_Vector w, realtype tol,
                    booleantype call_setup, void *mem)
{
    if (!NLS || !y0 || !ycor || !w || !mem)
        return SUN_NLS_MEM_NULL;
    SUNNonlinearSolverContent_FixedPoint c = NLS->content;
    if (!c->Sys || !c->CTest)
        return SUN_NLS_MEM_NULL;
    if (c->m != 0 || !fp_swappable(ycor, c->gy))
        return SUNNonlinSolSolve_FixedPoint(NLS, y0, ycor, w, tol, call_setup, mem);
    c->niters = 0;
    c->nconvfails = 0;
    for (c->curiter = 0; c->curiter < c->maxiters; c->curiter++) {
        if (c->Sys(ycor, c->gy, mem) != 0)
            break; /* as the library: a failed evaluation is a convergence failure */
        c->niters++;
        N_VLinearSum(1.0, c->gy, -1.0, ycor, c->delta);
        const N_VectorContent_Serial a = ycor->content, b = c->gy->content;
        realtype *d = a->data;
        a->data = b->data;
        b->data = d;
        const int rc = c->CTest(NLS, ycor, c->delta, tol, w, c->ctest_data);
        if (rc == SUN_NLS_SUCCESS)
            return SUN_NLS_SUCCESS;
        if (rc != SUN_NLS_CONTINUE) {
            c->nconvfails++;
            return rc;
        }
    }
    c->nconvfails++;
    return SUN_NLS_CONV_RECVR;
}

SUNNonlinearSolver gw_sun_fixed_point(N_Vector y, SUNContext ctx)
{
    SUNNonlinearSolver NLS = SUNNonlinSol_FixedPoint(y, 0, ctx);
    if (NLS)
        NLS->ops->solve = fp_solve;
    return NLS;
}

int gw_sun_rhs_ex(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    gw_solver *s = ud;
    if (gw_interrupt_pending())
        return -1; /* unrecoverable: gw_solver_advance reports the interrupt */
    return s->sys.rhs_ex(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), s->sys.params);
}

int gw_sun_rhs_im(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    gw_solver *s = ud;
    if (gw_interrupt_pending())
        return -1; /* unrecoverable: gw_solver_advance reports the interrupt */
    return s->sys.rhs_im(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), s->sys.params);
}

int gw_sun_roots(realtype t, N_Vector y, realtype *g, void *ud)
{
    gw_solver *s = ud;
    return s->sys.roots(t, N_VGetArrayPointer(y), g, s->sys.params);
}

int gw_sun_jac(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *ud, N_Vector t1,
               N_Vector t2, N_Vector t3)
{
    (void)t1;
    (void)t2;
    (void)t3;
    gw_solver *s = ud;
    gw_band band;
    SUNMatZero(J);
    band.cols = SM_CONTENT_B(J)->cols;
    band.smu = SM_SUBAND_B(J);
    band.mu = SM_UBAND_B(J);
    band.ml = SM_LBAND_B(J);
    return s->sys.jac(t, N_VGetArrayPointer(y), N_VGetArrayPointer(fy), &band,
                      s->sys.params);
}

/* The band's order (gw_system.lead0, nlead): position p of the matrix holds
 * state band_state(p); band_pos is its inverse. */
static long band_state(const gw_system *sys, long p)
{
    if (p < sys->nlead)
        return sys->lead0 + p;
    if (p < sys->lead0 + sys->nlead)
        return p - sys->nlead;
    return p;
}

static long band_pos(const gw_system *sys, long i)
{
    if (i >= sys->lead0 && i < sys->lead0 + sys->nlead)
        return i - sys->lead0;
    if (i < sys->lead0)
        return i + sys->nlead;
    return i;
}

int gw_sun_band_ordered(const gw_system *sys)
{
    return !sys->matrix_free && (sys->nlead > 0 || (sys->nledger > 0 && !sys->jac));
}

/* Difference quotients of the rhs in the band's order: the columns mu + ml + 1
 * apart share one evaluation (each row in the band of at most one of them),
 * each column's increment sqrt(eps) max(|y_i|, scale_i). The ledgers' rows
 * stay zero. The rhs is the implicit part's under arkode's imex. */
int gw_sun_jac_ordered(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *ud, N_Vector t1, N_Vector t2,
                       N_Vector t3)
{
    gw_solver *s = ud;
    const gw_system *sys = &s->sys;
    if (gw_interrupt_pending())
        return -1;
    const gw_rhs_fn rhs = s->p.method == GW_ARKODE_IMEX && sys->rhs_im ? sys->rhs_im : sys->rhs;
    const long n = sys->dim, mu = SM_UBAND_B(J), ml = SM_LBAND_B(J), rows = n - sys->nledger;
    const long w = mu + ml + 1 < n ? mu + ml + 1 : n;
    const double *y0 = N_VGetArrayPointer(y), *f0 = N_VGetArrayPointer(fy);
    double *yp = N_VGetArrayPointer(t1), *fp = N_VGetArrayPointer(t2), *inc = N_VGetArrayPointer(t3);
    const double srur = sqrt(DBL_EPSILON);
    SUNMatZero(J);
    memcpy(yp, y0, (size_t)n * sizeof *yp);
    for (long g = 0; g < w; g++) {
        for (long p = g; p < n; p += w) {
            const long i = band_state(sys, p);
            const double sc = sys->scale && sys->scale[i] > 0 ? sys->scale[i] : 1.0;
            const double h = srur * fmax(fabs(y0[i]), sc);
            yp[i] = y0[i] + (y0[i] < 0 ? -h : h);
            inc[p] = yp[i] - y0[i]; /* the increment as stored */
        }
        const int rc = rhs(t, yp, fp, sys->params);
        if (rc != 0)
            return rc;
        for (long p = g; p < n; p += w) {
            yp[band_state(sys, p)] = y0[band_state(sys, p)];
            realtype *col = SM_COLUMN_B(J, p);
            const long r0 = p - mu > 0 ? p - mu : 0, r1 = p + ml < rows - 1 ? p + ml : rows - 1;
            for (long r = r0; r <= r1; r++) {
                const long k = band_state(sys, r);
                SM_COLUMN_ELEMENT_B(col, r, p) = (fp[k] - f0[k]) / inc[p];
            }
        }
    }
    return 0;
}

/* The band solver on the band's order: b taken into it, x out of it. */
typedef struct ordered_ls {
    SUNLinearSolver band;
    N_Vector bp, xp;
    const gw_system *sys;
} ordered_ls;

static SUNLinearSolver_Type ordered_type(SUNLinearSolver S)
{
    (void)S;
    return SUNLINEARSOLVER_DIRECT;
}

static SUNLinearSolver_ID ordered_id(SUNLinearSolver S)
{
    (void)S;
    return SUNLINEARSOLVER_CUSTOM;
}

static int ordered_initialize(SUNLinearSolver S)
{
    return SUNLinSolInitialize(((ordered_ls *)S->content)->band);
}

static int ordered_setup(SUNLinearSolver S, SUNMatrix A)
{
    return SUNLinSolSetup(((ordered_ls *)S->content)->band, A);
}

static int ordered_solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, realtype tol)
{
    ordered_ls *o = S->content;
    const long n = o->sys->dim;
    const double *bv = N_VGetArrayPointer(b);
    double *bp = N_VGetArrayPointer(o->bp), *xp = N_VGetArrayPointer(o->xp), *xv = N_VGetArrayPointer(x);
    for (long i = 0; i < n; i++)
        bp[band_pos(o->sys, i)] = bv[i];
    const int rc = SUNLinSolSolve(o->band, A, o->xp, o->bp, tol);
    if (rc != SUNLS_SUCCESS)
        return rc;
    for (long i = 0; i < n; i++)
        xv[i] = xp[band_pos(o->sys, i)];
    return SUNLS_SUCCESS;
}

static sunindextype ordered_lastflag(SUNLinearSolver S)
{
    return SUNLinSolLastFlag(((ordered_ls *)S->content)->band);
}

static int ordered_space(SUNLinearSolver S, long *lrw, long *liw)
{
    const ordered_ls *o = S->content;
    const int rc = SUNLinSolSpace(o->band, lrw, liw);
    *lrw += 2 * o->sys->dim;
    return rc;
}

static int ordered_free(SUNLinearSolver S)
{
    if (!S)
        return SUNLS_SUCCESS;
    ordered_ls *o = S->content;
    if (o) {
        if (o->band)
            SUNLinSolFree(o->band);
        if (o->bp)
            N_VDestroy(o->bp);
        if (o->xp)
            N_VDestroy(o->xp);
        free(o);
    }
    S->content = NULL;
    SUNLinSolFreeEmpty(S);
    return SUNLS_SUCCESS;
}

static SUNLinearSolver ordered_solver(const gw_system *sys, N_Vector y, SUNMatrix A, SUNContext ctx)
{
    SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
    ordered_ls *o = S ? calloc(1, sizeof *o) : NULL;
    if (!o) {
        if (S)
            SUNLinSolFreeEmpty(S);
        return NULL;
    }
    S->content = o;
    S->ops->gettype = ordered_type;
    S->ops->getid = ordered_id;
    S->ops->initialize = ordered_initialize;
    S->ops->setup = ordered_setup;
    S->ops->solve = ordered_solve;
    S->ops->lastflag = ordered_lastflag;
    S->ops->space = ordered_space;
    S->ops->free = ordered_free;
    o->sys = sys;
    o->band = SUNLinSol_Band(y, A, ctx);
    o->bp = N_VClone(y);
    o->xp = N_VClone(y);
    if (!o->band || !o->bp || !o->xp) {
        ordered_free(S);
        return NULL;
    }
    return S;
}

void gw_sun_errh(int code, const char *module, const char *function, char *msg, void *ud)
{
    gw_solver *s = ud;
    gw_solver_set_error(s, "%s %s (flag %d): %s", module, function, code, msg);
}

int gw_sun_ewt(N_Vector y, N_Vector w, void *ud)
{
    const gw_solver *s = ud;
    return gw_sun_nv_ewt(y, w, s->p.rtol, s->p.atol, s->sys.scale);
}

double gw_sun_init_step(double dt, double dt_max, double t, double tout)
{
    const double floor = 100 * DBL_EPSILON * fmax(fabs(t), fabs(tout));
    /* never above the largest step, which bounds every step: a first step of
     * 1.8e308 s under a dt_max overflowed the solvers' own bound (h / hmax)
     * and every run failed at its first output, "Trouble interpolating at
     * tout ... too far back" (the fiftieth pass; 1e200 was taken as dt_max) */
    if (dt_max > 0 && dt > dt_max)
        dt = dt_max;
    return dt > 0 && dt < floor ? floor : dt;
}

int gw_sun_abstol_positive(N_Vector abstol)
{
    const double *a = N_VGetArrayPointer(abstol);
    for (long i = 0; i < N_VGetLength(abstol); i++)
        if (!(a[i] > 0))
            return 0;
    return 1;
}

N_Vector gw_sun_vector(long n, SUNContext ctx)
{
    N_Vector v = N_VNew_Serial(n, ctx);
    if (v && gw_sun_tune_vector(v) != 0) {
        N_VDestroy(v);
        return NULL;
    }
    return v;
}

N_Vector gw_sun_abstol(const gw_solver *s, SUNContext ctx)
{
    N_Vector v = gw_sun_vector(s->sys.dim, ctx);
    if (!v)
        return NULL;
    double *a = N_VGetArrayPointer(v);
    for (long i = 0; i < s->sys.dim; i++)
        a[i] = s->p.atol * (s->sys.scale ? s->sys.scale[i] : 1.0);
    return v;
}

int gw_sun_band(const gw_solver *s, N_Vector y, SUNContext ctx, SUNMatrix *A,
                SUNLinearSolver *LS)
{
    long n = s->sys.dim;
    if (s->sys.matrix_free) {
        /* no matrix: SUNDIALS forms J v by a difference quotient of the rhs;
         * no preconditioner, the default Krylov dimension (5) */
        *A = NULL;
        *LS = SUNLinSol_SPGMR(y, SUN_PREC_NONE, 0, ctx);
        return *LS ? GW_OK : GW_ENOMEM;
    }
    long mu = s->sys.mu > 0 ? s->sys.mu : n - 1;
    long ml = s->sys.ml > 0 ? s->sys.ml : n - 1;
    if (mu > n - 1)
        mu = n - 1;
    if (ml > n - 1)
        ml = n - 1;
    *A = SUNBandMatrix(n, mu, ml, ctx);
    if (!*A)
        return GW_ENOMEM;
    *LS = s->sys.nlead > 0 ? ordered_solver(&s->sys, y, *A, ctx) : SUNLinSol_Band(y, *A, ctx);
    if (!*LS) {
        SUNMatDestroy(*A);
        *A = NULL;
        return GW_ENOMEM;
    }
    return GW_OK;
}

void gw_sun_copy_out(N_Vector v, double *y, long n)
{
    memcpy(y, N_VGetArrayPointer(v), (size_t)n * sizeof *y);
}

int gw_sun_failed(gw_solver *s, const char *name, const char *flag_name, int too_much_work, double tret)
{
    char msg[sizeof s->errmsg];
    gw_snprintf(msg, sizeof msg, "%s", s->errmsg);
    gw_solver_set_error(s, "%s failed at t = %.9g s (%s): %s", name, tret, flag_name, msg[0] ? msg : "no message");
    return too_much_work ? GW_ELIMIT : GW_ESOLVER;
}

void gw_sun_peek_start(gw_sun_peek *k, double t)
{
    k->tlast = t;
    k->root_last = 0;
    k->pend = 0;
    k->have0 = 0;
    k->want = 0;
    k->got = 0;
    k->rec = 0;
    k->nend = 0;
    k->lost = 0;
}

void gw_sun_peek_free(gw_sun_peek *k)
{
    N_Vector *v[] = {&k->yp, &k->y0, &k->d0, &k->d1, &k->ym, &k->fm};
    for (size_t i = 0; i < sizeof v / sizeof *v; i++)
        if (*v[i])
            N_VDestroy(*v[i]), *v[i] = NULL;
    for (long i = 0; i < k->nvec; i++) {
        N_VDestroy(k->yend[i]);
        N_VDestroy(k->fend[i]);
    }
    free(k->tend), free(k->yend), free(k->fend), free(k->fok);
    k->tend = NULL, k->yend = k->fend = NULL, k->fok = NULL;
    k->nend = k->cap = k->nvec = 0;
}

int gw_sun_peek_pending(gw_solver *s, gw_sun_peek *k, double *t, double *y, int *roots)
{
    const int root = k->pend == 2;
    k->pend = 0;
    *k->t = k->pend_t;
    *t = *k->t;
    gw_sun_copy_out(k->y, y, s->sys.dim);
    if (!root)
        return GW_OK;
    return k->st->root_info(s, roots);
}

/* Room for the kept end i (i <= k->nend): the arrays grown and its two
 * vectors made when needed. GW_OK, GW_ELIMIT past GW_SUN_PEEK_END_BYTES,
 * GW_ENOMEM (what was kept stays). */
static int end_room(gw_sun_peek *k, long i, long dim)
{
    const size_t per_end = 2 * (size_t)dim * sizeof(double);
    if ((size_t)i >= GW_SUN_PEEK_END_BYTES / per_end)
        return GW_ELIMIT;
    if (i >= k->cap) {
        const long cap = k->cap ? 2 * k->cap : 16;
        double *tend = realloc(k->tend, (size_t)cap * sizeof *tend);
        if (tend)
            k->tend = tend;
        N_Vector *yend = tend ? realloc(k->yend, (size_t)cap * sizeof *yend) : NULL;
        if (yend)
            k->yend = yend;
        N_Vector *fend = yend ? realloc(k->fend, (size_t)cap * sizeof *fend) : NULL;
        if (fend)
            k->fend = fend;
        unsigned char *fok = fend ? realloc(k->fok, (size_t)cap * sizeof *fok) : NULL;
        if (!fok)
            return GW_ENOMEM;
        k->fok = fok;
        k->cap = cap;
    }
    if (i < k->nvec)
        return GW_OK;
    k->yend[i] = N_VClone(k->y);
    k->fend[i] = k->yend[i] ? N_VClone(k->y) : NULL;
    if (!k->fend[i]) {
        if (k->yend[i])
            N_VDestroy(k->yend[i]);
        return GW_ENOMEM;
    }
    k->nvec = i + 1;
    return GW_OK;
}

void gw_sun_peek_catch(gw_solver *s, gw_sun_peek *k, double t, N_Vector y)
{
    const double p = k->want;
    if (!(p > 0) && !k->rec)
        return;
    long nst = 0;
    double tn = 0, hnext = 0, hu = 0;
    k->st->where(s, &nst, &tn, &hnext, &hu);
    /* (a restart's first root check: its time tn, the peek after it) */
    if (p > 0 && hu > 0 && p >= tn - hu && p <= tn && k->st->dky(s, p, 0, k->yp) == 0) {
        k->got = 1;
        k->got_t = p;
        k->want = 0;
    }
    /* a step's end (the root function at the step's end, its state there):
     * kept from the last one before the peek on, every one after it (none
     * after one that could not be kept: the ends kept are consecutive) */
    if (!k->rec || k->lost || t != tn || !(hu > 0) || (k->nend > 0 && !(tn > k->tend[k->nend - 1])))
        return;
    const long i = k->want > 0 ? 0 : k->nend; /* before the peek: only the last end */
    const int rc = end_room(k, i, s->sys.dim);
    if (rc != GW_OK) {
        k->lost = rc;
        k->lost_t = tn;
        return;
    }
    N_VScale(1.0, y, k->yend[i]);
    k->tend[i] = tn;
    k->fok[i] = 0; /* (its rate when a peek reads it: end_rate) */
    k->nend = i + 1;
}

/* The rate at the kept end i (the system's rhs there, once): 1, or 0 when the
 * rhs failed. */
static int end_rate(gw_solver *s, gw_sun_peek *k, long i)
{
    if (!k->fok[i])
        k->fok[i] = s->sys.rhs(k->tend[i], N_VGetArrayPointer(k->yend[i]), N_VGetArrayPointer(k->fend[i]),
                               s->sys.params) == 0;
    return k->fok[i];
}

/* The state at p into k->yp: the one read in the step that held it during the
 * call (gw_sun_peek_catch), else the dense output within the last step; a p
 * before it (a call towards tout of several steps, from t0 where the state was
 * k->y0 and its rate k->d0, have0 1; have0 2: the rate unknown) in its own
 * step, between the kept ends around it (a quartic). GW_OK; GW_ELIMIT or
 * GW_ENOMEM when p lies past the ends kept (gw_sun_peek.lost), GW_ESOLVER when
 * the system's rate failed at a kept end: the message on the solver, nothing
 * read (a cubic over the steps between would be a silent loss of accuracy). */
static int peek_state(gw_solver *s, gw_sun_peek *k, double p)
{
    if (k->got && k->got_t == p) {
        k->got = 0;
        return GW_OK;
    }
    const int have0 = k->have0;
    const double t0 = k->t0;
    long nst = 0;
    double tn = 0, hnext = 0, hu = 0;
    k->st->where(s, &nst, &tn, &hnext, &hu);
    if ((p >= tn - hu && p <= tn) || !have0) {
        k->st->dky(s, fmin(tn, fmax(tn - hu, p)), 0, k->yp);
        return GW_OK;
    }
    /* the ends kept are those of consecutive steps up to the last before the
     * one that could not be kept: p past them and before the last step is in
     * a step whose ends are not known */
    const double kept = k->nend > 0 ? k->tend[k->nend - 1] : t0;
    if (k->lost && p > kept) {
        const char *name = k->st->name;
        if (k->lost == GW_ELIMIT)
            gw_solver_set_error(s, "%s: the sample at t = %.9g s is past the step ends kept for it (%ld, up to "
                                "t = %.9g s; the limit of %zu MiB of kept states and rates, GW_SUN_PEEK_END_BYTES, "
                                "was reached at t = %.9g s): sample fewer steps after the one before",
                                name, p, k->nend, kept, GW_SUN_PEEK_END_BYTES >> 20, k->lost_t);
        else
            gw_solver_set_error(s, "%s: the sample at t = %.9g s is past the step ends kept for it (%ld, up to "
                                "t = %.9g s): out of memory for the end at t = %.9g s",
                                name, p, k->nend, kept, k->lost_t);
        return k->lost;
    }
    /* the Hermite's ends: the kept steps' ends around p (gw_sun_peek_catch),
     * else the call's start and the last step's */
    double ta = t0, tb = tn - hu;
    const double *y0 = N_VGetArrayPointer(k->y0), *d0 = N_VGetArrayPointer(k->d0);
    const double *yb = NULL, *fb = NULL;
    long ia = -1, ib = -1;
    for (long i = 0; i < k->nend; i++) {
        if (k->tend[i] <= p && k->tend[i] > ta)
            ta = k->tend[i], ia = i;
        if (k->tend[i] >= p && k->tend[i] < tb)
            tb = k->tend[i], ib = i;
    }
    for (int e = 0; e < 2; e++) {
        const long i = e ? ib : ia;
        if (i >= 0 && !end_rate(s, k, i)) {
            gw_solver_set_error(s, "%s: the sample at t = %.9g s: the system's rate failed at the end of its "
                                "step, t = %.9g s", k->st->name, p, k->tend[i]);
            return GW_ESOLVER;
        }
    }
    if (ia >= 0)
        y0 = N_VGetArrayPointer(k->yend[ia]), d0 = N_VGetArrayPointer(k->fend[ia]);
    if (ib >= 0)
        yb = N_VGetArrayPointer(k->yend[ib]), fb = N_VGetArrayPointer(k->fend[ib]);
    const int have = ta > t0 ? 1 : have0;
    const double t1 = tb, H = t1 - ta, u = H > 0 ? (p - ta) / H : 1;
    if (!yb) {
        k->st->dky(s, t1, 0, k->yp);
        k->st->dky(s, t1, 1, k->d1);
    } else {
        memcpy(N_VGetArrayPointer(k->yp), yb, (size_t)s->sys.dim * sizeof *yb);
        memcpy(N_VGetArrayPointer(k->d1), fb, (size_t)s->sys.dim * sizeof *fb);
    }
    double w[4];
    gw_hermite(u, H, w);
    double *yp = N_VGetArrayPointer(k->yp), *d1 = N_VGetArrayPointer(k->d1);
    const long n = s->sys.dim;
    if (have != 1) {
        for (long i = 0; i < n; i++)
            yp[i] = (1 - u) * y0[i] + u * yp[i];
        return GW_OK;
    }
    /* a quartic: the cubic plus c th^2 (1 - th)^2, whose c gives the system's
     * rate at th = 2/3 of the interval (as ARKode's dense output of degree 4
     * is made from its cubic): an error of fifth order in H, not fourth */
    double *ym = N_VGetArrayPointer(k->ym), *fm = N_VGetArrayPointer(k->fm);
    double wm[4], dm[4];
    const double um = 2.0 / 3;
    gw_hermite(um, H, wm);
    gw_hermite_rate(um, H, dm);
    for (long i = 0; i < n; i++)
        ym[i] = wm[0] * y0[i] + wm[1] * d0[i] + wm[2] * yp[i] + wm[3] * d1[i];
    const int quartic = H > 0 && s->sys.rhs(ta + um * H, ym, fm, s->sys.params) == 0;
    const double q = u * u * (1 - u) * (1 - u), dq = -4.0 / (27 * H); /* th^2 (1 - th)^2 and its rate at 2/3 */
    for (long i = 0; i < n; i++) {
        double c = 0;
        if (quartic)
            c = (fm[i] - (dm[0] * y0[i] + dm[1] * d0[i] + dm[2] * yp[i] + dm[3] * d1[i])) / dq;
        yp[i] = w[0] * y0[i] + w[1] * d0[i] + w[2] * yp[i] + w[3] * d1[i] + c * q;
    }
    return GW_OK;
}

int gw_sun_advance_peek(gw_solver *s, gw_sun_peek *k, double tout, double *t, double *y, int *roots)
{
    const gw_sun_stepper *st = k->st;
    const double p = s->peek;
    N_Vector *v[] = {&k->yp, &k->y0, &k->d0, &k->d1, &k->ym, &k->fm};
    for (size_t i = 0; i < sizeof v / sizeof *v; i++)
        if (!*v[i] && !(*v[i] = N_VClone(k->y))) {
            gw_solver_set_error(s, "%s: out of memory for the state at t = %.9g s", st->name, p);
            return GW_ENOMEM;
        }
    if ((k->pend == 1 && k->pend_tout != tout) || (k->pend == 2 && k->pend_t > tout))
        k->pend = 0;
    if (k->pend && p > k->pend_t)
        return gw_sun_peek_pending(s, k, t, y, roots);
    int rc = GW_OK;
    if (k->pend) { /* another peek before the return held back */
        rc = peek_state(s, k, p);
    } else {
        int flag = st->prepare(s, tout);
        if (flag < 0)
            return st->failed(s, flag, *k->t);
        for (long steps = 0;; steps++) {
            if (s->p.max_steps > 0 && steps >= s->p.max_steps) {
                gw_solver_set_error(s, "%s failed at t = %.9g s (%s): more than %ld steps towards t = %.9g s",
                                    st->name, *k->t, st->too_much, s->p.max_steps, tout);
                return GW_ELIMIT;
            }
            long nst = 0;
            double tn = 0, hcur = 0, hu = 0;
            const int started = st->where(s, &nst, &tn, &hcur, &hu);
            if (!started)
                nst = 0, tn = *k->t, hcur = 0;
            /* the step tried next (failed tests only shorten it) after a
             * return at tout or of one step; after a root return the step
             * taken, which the next may outgrow by the backend's factor */
            const double grow = k->root_last ? st->grow(s, nst) : 1;
            /* p already in the last step (a call towards tout went past it):
             * a one-step call searches the rest of the step for roots, as one
             * towards tout does short of tout, and returns without a step */
            /* without roots the mode changes only where the call returns
             * (the steps and the output at tout are the same): one step at a
             * time, so that p is read in the step that passed it (no root
             * function keeps the ends of a call's steps) */
            const int roots_on = s->sys.nroots > 0;
            const int normal = !started ? roots_on && st->first_normal(s, tout)
                                        : tn >= tout || (roots_on && p > tn && tn + grow * hcur >= tout);
            k->have0 = 0;
            k->t0 = tn;
            if (p > tn) {
                if (started && st->dky(s, tn, 0, k->y0) == 0 && st->dky(s, tn, 1, k->d0) == 0) {
                    k->have0 = 1;
                } else {
                    N_VScale(1.0, k->y, k->y0);
                    k->have0 = st->start_rate && st->start_rate(s, tn, k->y0, k->d0) ? 1 : 2;
                }
            }
            if (started && p <= k->tlast) { /* searched, in the last step: no call */
                rc = peek_state(s, k, p);
                break;
            }
            double tret = *k->t;
            k->want = p, k->got = 0, k->rec = normal, k->nend = 0, k->lost = 0;
            flag = st->evolve(s, tout, &tret, !normal);
            k->want = 0, k->rec = 0;
            k->tlast = tret;
            if (flag < 0) {
                *k->t = tret;
                *t = tret;
                gw_sun_copy_out(k->y, y, s->sys.dim);
                return st->failed(s, flag, tret);
            }
            k->root_last = flag == 1;
            if (p <= tret) {
                if (normal || flag == 1) {
                    k->pend = flag == 1 ? 2 : 1;
                    k->pend_t = tret;
                    k->pend_tout = tout;
                }
                rc = peek_state(s, k, p);
                break;
            }
            if (flag == 1 || normal) {
                k->pend = flag == 1 ? 2 : 1;
                k->pend_t = tret;
                k->pend_tout = tout;
                return gw_sun_peek_pending(s, k, t, y, roots);
            }
        }
    }
    s->peek = 0;
    if (rc != GW_OK) /* (the peek disarmed, *t and y as they were, a return held back kept) */
        return rc;
    *k->t = p;
    *t = p;
    gw_sun_copy_out(k->yp, y, s->sys.dim);
    return GW_SOLVER_PEEK;
}
