/*
 * test_solver_adams_bitwise.c: the two ways CVODE Adams is made cheaper per
 * step on long chains change no bit: a right-hand side given by ranges of
 * components (gw_system.rhs_range) and run queued in the vector passes
 * (gw_sun_nv_rhs, common/solver/gw_nvector.c), and the fixed-point solver
 * without copies (gw_sun_fixed_point, common/solver/gw_sundials.c).
 *
 * The queued right-hand side runs by ranges that trail the operations queued
 * before it by 64 elements (blocks of 512), because a range reads a few
 * elements of y beyond its ends; the operations after it and the norm that ends
 * the pass run on the range with it. If an operation after it writes y, it
 * runs alone after the ones before it instead. Checked here:
 * - a stencil right-hand side reading y from 64 elements before to 63 after
 *   (halo 64, the most allowed) queued among random sums, scalings, copies,
 *   constants and error weights on tuned vectors, against SUNDIALS' own
 *   vectors with the right-hand side called at once: every norm and every
 *   vector bit for bit, lengths 1, 3, 100, 448, 449, 511, 512, 513, 575, 1025,
 *   1500 and 5000 (blocks of 512), with y written after it (the fallback) in some sequences, two
 *   right-hand sides in one pass in others, and the data read directly
 *   (N_VGetArrayPointer) while one is pending;
 * - the chain's lean right-hand side by ranges (ranges of 64 and 512
 *   components, the whole state, and random ranges of 1 to 24 beads: the 4-wide
 *   AVX loop's start and end, ranges too short for it, the chain's both ends)
 *   against its rhs, bit for bit, on a compressed state of 1300 beads (uniform
 *   and with varied masses and stiffnesses), and that a range writes nothing
 *   outside it (its halo is 8 components, what the 4-wide loop reads ahead);
 * - CVODE Adams on a column of 3000 beads hitting the wall (the bench_long
 *   case, 0.5 tc): with rhs_range (queued) and without (the system copied with
 *   rhs_range NULL), the same steps, right-hand sides and final state, bit for
 *   bit;
 * - linear combinations of 3 to 10 terms (queued up to 8, some starting from
 *   the vector they write) among the random operations above;
 * - ARKode ERK (ERKStep, whose stages are queued linear combinations with the
 *   right-hand side by ranges after them, in one pass) on that column (3000
 *   beads, 2 tc, its contact roots on), with rhs_range and without: the same
 *   stop, steps, right-hand sides and final state, bit for bit;
 * - CVODE Adams with gw_sun_fixed_point against SUNDIALS' own fixed-point
 *   solver on that column (400 beads, 2 tc), on SUNDIALS' vectors and on the
 *   tuned ones: the same steps, right-hand sides, nonlinear iterations and
 *   convergence failures and the same final state, bit for bit; also with at
 *   most one iteration per step (every step that needs two fails to converge;
 *   CVODE stops at its limit of 3000 steps, both alike) and with a right-hand side that fails (recoverably) every 29th call.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "gw_chain.h"
#include "gw_sundials.h"
#include "gw_test.h"
#include "gw_test_nvector.h"

enum { NV = 8 };

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static uint64_t next(void) { return gw_test_xorshift(&rng); }
static int pick(int n) { return (int)(next() % (uint64_t)n); }
static double coef(void) { return gw_test_coef(&rng); }
static int same_bits(double x, double y) { return memcmp(&x, &y, sizeof x) == 0; }

/* ydot_i = t + 0.5 y_(i-2) - y_i + 0.25 y_(i+1) + 0.125 y_(i-64) - 0.0625
 * y_(i+63) (terms outside [0, n) left out): reads y within 64 elements of the
 * range */
static long stencil_n;
static void stencil(double t, const double *y, double *yd, long i0, long i1, void *p)
{
    (void)p;
    for (long i = i0; i < i1; i++) {
        double a = t - y[i];
        if (i >= 2)
            a += 0.5 * y[i - 2];
        if (i + 1 < stencil_n)
            a += 0.25 * y[i + 1];
        if (i >= 64)
            a += 0.125 * y[i - 64];
        if (i + 63 < stencil_n)
            a -= 0.0625 * y[i + 63];
        yd[i] = a;
    }
}

typedef struct {
    N_Vector v[NV];
} set;

/* one random element-wise operation on both sets; never writes vector `keep`
 * when keep >= 0 */
static void elementwise(set *s, set *t, int keep)
{
    int z;
    do
        z = pick(NV - 1);
    while (z == keep);
    int op = pick(5), x = pick(NV), y = pick(NV);
    if (op == 4) { /* a linear combination of 3 to 10 terms (queued up to 8) */
        const int nt = 3 + pick(8);
        double c[10];
        N_Vector xs[10], xt[10];
        for (int j = 0; j < nt; j++) {
            int k = pick(NV);
            if (j == 0 && pick(3) == 0) /* starting from z itself, kept when c_0 = 1 */
                k = z;
            c[j] = j == 0 && pick(2) ? 1.0 : coef();
            xs[j] = s->v[k];
            xt[j] = t->v[k];
        }
        N_VLinearCombination(nt, c, xs, s->v[z]);
        N_VLinearCombination(nt, c, xt, t->v[z]);
    } else if (op == 0) {
        double a = coef(), b = pick(3) == 0 ? -a : coef();
        N_VLinearSum(a, s->v[x], b, s->v[y], s->v[z]);
        N_VLinearSum(a, t->v[x], b, t->v[y], t->v[z]);
    } else if (op == 1) {
        double c = pick(2) ? 1.0 : coef();
        N_VScale(c, s->v[x], s->v[z]);
        N_VScale(c, t->v[x], t->v[z]);
    } else if (op == 2) {
        double c = coef();
        N_VConst(c, s->v[z]);
        N_VConst(c, t->v[z]);
    } else { /* error weights from x (w = NV - 2 kept for them) */
        int w = NV - 2;
        if (x == w)
            x = 0;
        const double *xs = N_VGetArrayPointer(s->v[x]);
        double *ws = N_VGetArrayPointer(s->v[w]);
        for (long i = 0; i < N_VGetLength(s->v[x]); i++)
            ws[i] = 1.0 / (1e-6 * fabs(xs[i]) + 1e-3);
        gw_sun_nv_ewt(t->v[x], t->v[w], 1e-6, 1e-3, NULL);
    }
}

/* ydot = f(y) on both sets: at once on SUNDIALS' vectors, queued on the tuned */
static int rhs_both(set *s, set *t, int y, int yd, double tt)
{
    const long n = N_VGetLength(s->v[y]);
    stencil(tt, N_VGetArrayPointer(s->v[y]), N_VGetArrayPointer(s->v[yd]), 0, n, NULL);
    return gw_sun_nv_rhs(tt, t->v[y], t->v[yd], stencil, 64, NULL) == 0 &&
           gw_sun_nv_rhs(tt, t->v[y], t->v[yd], stencil, 65, NULL) == -1;
}

static void run(long n, int seqs, SUNContext ctx, int *fallbacks)
{
    set s, t;
    stencil_n = n;
    for (int k = 0; k < NV; k++) {
        s.v[k] = N_VNew_Serial(n, ctx);
        N_VEnableFusedOps_Serial(s.v[k], SUNTRUE);
        t.v[k] = gw_sun_vector(n, ctx);
        double *a = N_VGetArrayPointer(s.v[k]), *b = N_VGetArrayPointer(t.v[k]);
        for (long i = 0; i < n; i++)
            a[i] = b[i] = (double)(next() >> 11) * 0x1p-53 - 0.5 + (k == NV - 1 ? 1.0 : 0.0);
    }
    int norms_ok = 1, queued_ok = 1;
    for (int q = 0; q < seqs; q++) {
        const int y = pick(NV - 2), yd = (y + 1 + pick(NV - 3)) % (NV - 2);
        const int writes_y = pick(4) == 0, twice = pick(6) == 0, peek = pick(8) == 0;
        for (int k = pick(6); k > 0; k--) /* before it: CVODE's predictor, y = z_0 + c */
            elementwise(&s, &t, -1);
        queued_ok &= rhs_both(&s, &t, y, yd, 0.125 * q);
        if (peek) { /* the data read while it is pending */
            long i = pick((int)n);
            norms_ok &= same_bits(N_VGetArrayPointer(s.v[yd])[i], N_VGetArrayPointer(t.v[yd])[i]);
        }
        for (int k = 1 + pick(5); k > 0; k--) /* after it: the corrector's sums */
            elementwise(&s, &t, writes_y ? -1 : y);
        if (writes_y) {
            N_VLinearSum(0.5, s.v[yd], 1.0, s.v[y], s.v[y]);
            N_VLinearSum(0.5, t.v[yd], 1.0, t.v[y], t.v[y]);
            *fallbacks += 1;
        }
        if (twice) { /* a second one in the same pass: the first runs before it */
            const int y2 = yd, yd2 = y;
            queued_ok &= rhs_both(&s, &t, y2, yd2, 1.0);
            elementwise(&s, &t, y2);
        }
        const int x = pick(NV), w = NV - 1; /* the norm that ends the pass */
        norms_ok &= same_bits(N_VWrmsNorm(s.v[x], s.v[w]), N_VWrmsNorm(t.v[x], t.v[w]));
        for (int k = 0; k < NV; k++)
            if (N_VMaxNorm(s.v[k]) > 1e6) {
                N_VScale(1.0 / 1024.0, s.v[k], s.v[k]);
                N_VScale(1.0 / 1024.0, t.v[k], t.v[k]);
            }
    }
    char what[160];
    snprintf(what, sizeof what, "n = %ld: the right-hand side was queued in all %d sequences", n,
             seqs);
    gw_test_true(queued_ok, what);
    snprintf(what, sizeof what, "n = %ld: every norm ending a pass bit-identical", n);
    gw_test_true(norms_ok, what);
    snprintf(what, sizeof what, "n = %ld: every vector bit-identical after the sequences", n);
    gw_test_true(gw_test_same_vectors(s.v, t.v, NV, n), what);
    for (int k = 0; k < NV; k++) {
        N_VDestroy(s.v[k]);
        N_VDestroy(t.v[k]);
    }
}

/* the chain's rhs_range against its rhs on a compressed state */
static void chain_ranges(int varied)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 1300;
    double *m = NULL, *k = NULL;
    if (varied) {
        m = malloc((size_t)p.n * sizeof *m);
        k = malloc((size_t)p.n * sizeof *k);
        for (int i = 0; i < p.n; i++) {
            m[i] = p.mass * (1.0 + 0.3 * sin(0.7 * i));
            k[i] = p.k * (1.0 + 0.2 * cos(1.3 * i));
        }
        p.masses = m;
        p.kc = k;
    }
    gw_chain *c = NULL;
    gw_err err = {0};
    gw_test_true(gw_chain_create(&p, &c, &err) == GW_OK, "chain of 1300 beads created");
    if (!c)
        return;
    const gw_system *sys = gw_chain_system(c);
    gw_test_true(sys->rhs_range != NULL && sys->rhs_halo == 8,
                 "the undamped column gives its rhs by ranges (halo 8)");
    if (!sys->rhs_range)
        return;
    const long dim = sys->dim;
    double *y = malloc((size_t)dim * sizeof *y), *f = malloc((size_t)dim * sizeof *f),
           *g = malloc((size_t)dim * sizeof *g), *h = malloc((size_t)dim * sizeof *h);
    /* overlaps of both signs (open and closed contacts), the wall compressed */
    for (long j = 0; j < p.n; j++) {
        y[2 * j] = 1e-6 * ((double)j * 0.01 + ((double)(next() >> 11) * 0x1p-53 - 0.3));
        y[2 * j + 1] = (double)(next() >> 11) * 0x1p-53 - 0.5;
    }
    y[0] = 2e-6;
    sys->rhs(0.0, y, f, sys->params);
    char what[120];
    for (long w = 64; w <= 512; w *= 8) {
        memset(g, 0, (size_t)dim * sizeof *g);
        for (long i0 = 0; i0 < dim; i0 += w)
            sys->rhs_range(0.0, y, g, i0, i0 + w < dim ? i0 + w : dim, sys->params);
        snprintf(what, sizeof what, "chain (%s): rhs by ranges of %ld = rhs, bit for bit",
                 varied ? "varied beads" : "uniform", w);
        gw_test_true(memcmp(f, g, (size_t)dim * sizeof *f) == 0, what);
    }
    sys->rhs_range(0.0, y, h, 0, dim, sys->params);
    snprintf(what, sizeof what, "chain (%s): rhs by one range = rhs, bit for bit",
             varied ? "varied beads" : "uniform");
    gw_test_true(memcmp(f, h, (size_t)dim * sizeof *f) == 0, what);
    /* ranges of 1 to 24 beads in random order (the 4-wide loop's start, its
     * last 0 to 3 beads, ranges too short for it, the chain's both ends), the
     * halo beyond each range holding garbage the range must not depend on */
    int ok = 1, writes_out = 0;
    for (int rep = 0; rep < 20; rep++) {
        for (long i0 = 0; i0 < dim;) {
            const long w = 2 * (1 + pick(24)), i1 = i0 + w < dim ? i0 + w : dim;
            for (long i = 0; i < dim; i++)
                h[i] = -1.0 - (double)i;
            sys->rhs_range(0.0, y, h, i0, i1, sys->params);
            ok &= memcmp(f + i0, h + i0, (size_t)(i1 - i0) * sizeof *f) == 0;
            for (long i = 0; i < dim; i++)
                writes_out |= (i < i0 || i >= i1) && h[i] != -1.0 - (double)i;
            i0 = i1;
        }
    }
    snprintf(what, sizeof what, "chain (%s): rhs by ranges of 1 to 24 beads = rhs, bit for bit",
             varied ? "varied beads" : "uniform");
    gw_test_true(ok, what);
    snprintf(what, sizeof what, "chain (%s): a range writes nothing outside it",
             varied ? "varied beads" : "uniform");
    gw_test_true(!writes_out, what);
    free(y);
    free(f);
    free(g);
    free(h);
    gw_chain_free(c);
    free(m);
    free(k);
}

/* One backend on the column hitting the wall from y0 to tend, with or
 * without rhs_range (sys as given) */
static int solve(const gw_solver_type *type, int method, const gw_system *sys, const double *y0, double tend,
                 double *y, gw_solver_stats *st)
{
    gw_solver_params sp = gw_solver_params_default();
    sp.method = method;
    gw_solver *s = NULL;
    gw_err err = {0};
    if (gw_solver_create(type, sys, &sp, 0.0, y0, &s, &err) != GW_OK)
        return -1;
    double t = 0;
    memcpy(y, y0, (size_t)sys->dim * sizeof *y);
    int rc = gw_solver_advance(s, tend, &t, y, NULL);
    gw_solver_get_stats(s, st);
    gw_solver_free(s);
    return rc;
}

/* A 3000-bead column over transits time scales, the right-hand side by ranges
 * against the whole one: the same stop, steps, right-hand sides and final
 * state, bit for bit. CVODE Adams queues its vector passes with the ranges
 * (both runs must reach tend); ARKode ERK queues each stage's linear
 * combination with the right-hand side after it (one pass), the next stage
 * written where the last was read; with root_ok a stop at the same first
 * contact root counts as alike (the root functions read the state between
 * passes). */
static void backend_ranges(const gw_solver_type *type, int method, double transits, int root_ok, const char *name)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 3000;
    gw_chain *c = NULL;
    gw_err err = {0};
    char what[200];
    if (gw_chain_create(&p, &c, &err) != GW_OK) {
        gw_test_true(0, "chain of 3000 beads created");
        return;
    }
    const gw_system *sys = gw_chain_system(c);
    gw_system plain = *sys;
    plain.rhs_range = NULL;
    const long dim = sys->dim;
    double *y0 = malloc((size_t)dim * sizeof *y0), *a = malloc((size_t)dim * sizeof *a),
           *b = malloc((size_t)dim * sizeof *b);
    gw_chain_initial_state(c, y0);
    const double tend = transits * gw_chain_time_scale(&p);
    gw_solver_stats sa, sb;
    int ra = solve(type, method, sys, y0, tend, a, &sa), rb = solve(type, method, &plain, y0, tend, b, &sb);
    snprintf(what, sizeof what, "%s, 3000 beads: both runs stop alike (%s)", name,
             root_ok ? "the end, or the same first contact root" : "the end");
    gw_test_true(ra == rb && (ra == GW_OK || (root_ok && ra == GW_ROOT)), what);
    printf("  steps %ld and %ld, rhs %ld and %ld\n", sa.steps, sb.steps, sa.rhs_evals, sb.rhs_evals);
    snprintf(what, sizeof what, "%s, 3000 beads: the same steps and right-hand sides (more than 20 steps) "
             "queued and not", name);
    gw_test_true(sa.steps == sb.steps && sa.rhs_evals == sb.rhs_evals && sa.steps > 20, what);
    snprintf(what, sizeof what, "%s, 3000 beads: the same final state, bit for bit, queued and not", name);
    gw_test_true(memcmp(a, b, (size_t)dim * sizeof *a) == 0, what);
    free(y0);
    free(a);
    free(b);
    gw_chain_free(c);
}

/* CVODE on a gw_system directly: user data is this */
typedef struct {
    const gw_system *sys;
    long calls;
    int flaky; /* > 0: every flaky-th call fails, recoverably */
} fp_case;

static int fp_rhs(realtype t, N_Vector y, N_Vector f, void *ud)
{
    fp_case *c = ud;
    if (c->flaky > 0 && ++c->calls % c->flaky == 0)
        return 1;
    return c->sys->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(f), c->sys->params);
}

typedef struct {
    long steps, nfe, nni, ncfn;
    int flag;
} fp_stats;

static void quiet(int code, const char *module, const char *function, char *msg, void *ud)
{
    (void)code, (void)module, (void)function, (void)msg, (void)ud;
}

/* CVODE Adams to tend from y0 (into y), with our fixed-point solver or the
 * library's, on tuned vectors or SUNDIALS' */
static fp_stats fp_run(const gw_system *sys, const double *y0, double tend, int maxcor, int flaky,
                       int ours, int tuned, double *y, SUNContext ctx)
{
    fp_stats st = {0, 0, 0, 0, -99};
    fp_case c = {sys, 0, flaky};
    N_Vector v = tuned ? gw_sun_vector(sys->dim, ctx) : N_VNew_Serial(sys->dim, ctx);
    memcpy(N_VGetArrayPointer(v), y0, (size_t)sys->dim * sizeof *y0);
    void *mem = CVodeCreate(CV_ADAMS, ctx);
    SUNNonlinearSolver nls = ours ? gw_sun_fixed_point(v, ctx) : SUNNonlinSol_FixedPoint(v, 0, ctx);
    CVodeInit(mem, fp_rhs, 0.0, v);
    CVodeSetUserData(mem, &c);
    CVodeSStolerances(mem, 1e-10, 1e-16);
    CVodeSetNonlinearSolver(mem, nls);
    CVodeSetMaxNonlinIters(mem, maxcor);
    CVodeSetMaxNumSteps(mem, 3000);
    CVodeSetErrHandlerFn(mem, quiet, NULL); /* the one-iteration case stops at 3000 steps */
    double t = 0;
    st.flag = CVode(mem, tend, v, &t, CV_NORMAL);
    CVodeGetNumSteps(mem, &st.steps);
    CVodeGetNumRhsEvals(mem, &st.nfe);
    CVodeGetNumNonlinSolvIters(mem, &st.nni);
    CVodeGetNumNonlinSolvConvFails(mem, &st.ncfn);
    memcpy(y, N_VGetArrayPointer(v), (size_t)sys->dim * sizeof *y);
    CVodeFree(&mem);
    SUNNonlinSolFree(nls);
    N_VDestroy(v);
    return st;
}

static void fixed_point(void)
{
    SUNContext ctx;
    if (SUNContext_Create(NULL, &ctx) != 0)
        return;
    gw_chain_params p = gw_chain_params_default();
    p.n = 400;
    gw_chain *ch = NULL;
    gw_err err = {0};
    if (gw_chain_create(&p, &ch, &err) != GW_OK) {
        gw_test_true(0, "chain of 400 beads created");
        return;
    }
    const gw_system *sys = gw_chain_system(ch);
    const long dim = sys->dim;
    double *y0 = malloc((size_t)dim * sizeof *y0), *a = malloc((size_t)dim * sizeof *a),
           *b = malloc((size_t)dim * sizeof *b);
    gw_chain_initial_state(ch, y0);
    const double tend = 2.0 * gw_chain_time_scale(&p);
    static const struct {
        int maxcor, flaky;
        const char *what;
    } cases[] = {{3, 0, "default corrector"},
                 {1, 0, "one iteration at most"},
                 {3, 29, "rhs failing every 29th call"}};
    for (int k = 0; k < 3; k++)
        for (int tuned = 0; tuned < 2; tuned++) {
            fp_stats lib = fp_run(sys, y0, tend, cases[k].maxcor, cases[k].flaky, 0, tuned, a, ctx);
            fp_stats our = fp_run(sys, y0, tend, cases[k].maxcor, cases[k].flaky, 1, tuned, b, ctx);
            char what[200];
            printf("  %s, %s vectors: flag %d/%d, steps %ld/%ld, rhs %ld/%ld, iterations "
                   "%ld/%ld, convergence failures %ld/%ld\n",
                   cases[k].what, tuned ? "tuned" : "SUNDIALS'", lib.flag, our.flag, lib.steps,
                   our.steps, lib.nfe, our.nfe, lib.nni, our.nni, lib.ncfn, our.ncfn);
            snprintf(what, sizeof what,
                     "fixed point without copies, %s, %s vectors: the library's flag, steps, "
                     "rhs, iterations and convergence failures",
                     cases[k].what, tuned ? "tuned" : "SUNDIALS'");
            gw_test_true(lib.flag == our.flag && lib.steps == our.steps && lib.nfe == our.nfe &&
                             lib.nni == our.nni && lib.ncfn == our.ncfn && lib.steps > 50 &&
                             (k == 0 || lib.ncfn > 0),
                         what);
            snprintf(what, sizeof what,
                     "fixed point without copies, %s, %s vectors: the same final state, bit for "
                     "bit",
                     cases[k].what, tuned ? "tuned" : "SUNDIALS'");
            gw_test_true(memcmp(a, b, (size_t)dim * sizeof *a) == 0, what);
        }
    free(y0);
    free(a);
    free(b);
    gw_chain_free(ch);
    SUNContext_Free(&ctx);
}

int main(void)
{
    SUNContext ctx;
    if (SUNContext_Create(NULL, &ctx) != 0)
        return 1;
    int fallbacks = 0;
    const long lens[] = {1, 3, 100, 448, 449, 511, 512, 513, 575, 1025, 1500, 5000};
    for (size_t i = 0; i < sizeof lens / sizeof lens[0]; i++)
        run(lens[i], 60, ctx, &fallbacks);
    gw_test_true(fallbacks > 20, "sequences writing y after the right-hand side were run");
    SUNContext_Free(&ctx);
    chain_ranges(0);
    chain_ranges(1);
    backend_ranges(gw_solver_cvode, GW_CVODE_ADAMS, 0.5, 0, "cvode adams");
    backend_ranges(gw_solver_arkode, GW_ARKODE_ERK, 2.0, 1, "arkode erk");
    fixed_point();
    return gw_test_summary("test_solver_adams_bitwise");
}
