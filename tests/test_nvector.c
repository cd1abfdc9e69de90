/*
 * test_nvector.c: granwave's compiled vector kernels (common/solver/gw_nvector.c)
 * against SUNDIALS' own serial kernels, bit for bit.
 *
 * The kernels replace the serial N_Vector's ops; sums, scalings, constants,
 * scaled additions and error weights are queued and run later, block by block,
 * fused with the next weighted norm. None of this may change a single bit:
 * each element must see the same operations in the same order. Checked here on
 * two sets of vectors, one with SUNDIALS' ops and one tuned, driven through the
 * same random sequences (seeded) of:
 * - predictor triangles of every order 1..12, some followed by an extra sum so
 *   that the queue is not a triangle, some with a vector repeated;
 * - linear sums with every aliasing (z = x, z = y, distinct) and coefficients
 *   1, -1, equal, opposite and general; scalings by 1 (a copy), -1 and others;
 * - weighted RMS and L2 norms, dot products, max norms taken while operations are
 *   pending (the fused path) and compared as doubles, bit for bit;
 * - reads and writes through N_VGetArrayPointer while operations are pending;
 * - linear combinations of 1 to 20 terms (queued up to 16, z among the terms
 *   or not) and constants; scaled additions Z_j = a_j x + Y_j
 *   in place and not (CVODE's correction of its Nordsieck array); error weights
 *   queued (gw_sun_nv_ewt) against the direct formula, with and without scales;
 * - a vector destroyed while a sum into it is pending (run under the sanitizer
 *   build too: a queue that outlived the vector would write freed memory).
 * Lengths 1, 511, 512, 513, 5000 and 9000 (blocks are 512 elements; scaled
 * additions are queued from 8192).
 * Then CVODE itself (Adams, fixed-point corrector, as granwave runs it) and
 * ARKode's ERK (Cash-Karp, as granwave runs it) on 1000 and 10000 uncoupled
 * oscillators, once on SUNDIALS' vectors and once on the tuned ones: the same
 * steps and the same final state, bit for bit (the error weights through
 * CVodeWFtolerances / ERKStepWFtolerances, queued on the tuned vectors).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "gw_sundials.h"
#include "gw_test.h"
#include "gw_test_nvector.h"

enum { NV = 14 };

static uint64_t rng = 88172645463325252ull;
static uint64_t next(void) { return gw_test_xorshift(&rng); }
static int pick(int n) { return (int)(next() % (uint64_t)n); }
static double coef(void) { return gw_test_coef(&rng); }

typedef struct {
    N_Vector v[NV];
} set;

static int same_bits(double x, double y) { return memcmp(&x, &y, sizeof x) == 0; }

/* one random step on both sets; returns 0 when a reduction differed */
static int step(set *s, set *t, long n)
{
    int op = pick(12);
    int ok = 1;
    if (op <= 2) { /* the predictor, sometimes spoiled */
        int q = 1 + pick(12), base = pick(NV - q);
        int spoil = pick(4);
        for (int k = 1; k <= q; k++)
            for (int j = q; j >= k; j--) {
                int a = base + j - 1, b = base + j;
                if (spoil == 0 && k == q)
                    b = a; /* x += x */
                N_VLinearSum(1.0, s->v[a], 1.0, s->v[b], s->v[a]);
                N_VLinearSum(1.0, t->v[a], 1.0, t->v[b], t->v[a]);
            }
        if (spoil == 1) {
            N_VLinearSum(1.0, s->v[base], 1.0, s->v[base + 1], s->v[base]);
            N_VLinearSum(1.0, t->v[base], 1.0, t->v[base + 1], t->v[base]);
        }
    } else if (op <= 4) { /* a linear sum with some aliasing */
        int x = pick(NV), y = pick(NV), z = pick(3) == 0 ? x : pick(2) ? y : pick(NV);
        double a = coef(), b = pick(3) == 0 ? (pick(2) ? a : -a) : coef();
        N_VLinearSum(a, s->v[x], b, s->v[y], s->v[z]);
        N_VLinearSum(a, t->v[x], b, t->v[y], t->v[z]);
    } else if (op == 5) {
        int x = pick(NV), z = pick(2) ? x : pick(NV);
        double c = pick(2) ? 1.0 : coef();
        N_VScale(c, s->v[x], s->v[z]);
        N_VScale(c, t->v[x], t->v[z]);
    } else if (op == 6) { /* reductions with pending work */
        int x = pick(NV), w = NV - 1;
        ok &= same_bits(N_VWrmsNorm(s->v[x], s->v[w]), N_VWrmsNorm(t->v[x], t->v[w]));
        ok &= same_bits(N_VWL2Norm(s->v[x], s->v[w]), N_VWL2Norm(t->v[x], t->v[w]));
        ok &= same_bits(N_VDotProd(s->v[x], s->v[w]), N_VDotProd(t->v[x], t->v[w]));
        ok &= same_bits(N_VMaxNorm(s->v[x]), N_VMaxNorm(t->v[x]));
    } else if (op == 7) { /* the data read and written directly */
        int x = pick(NV);
        long i = pick((int)n);
        double *ps = N_VGetArrayPointer(s->v[x]), *pt = N_VGetArrayPointer(t->v[x]);
        ok &= same_bits(ps[i], pt[i]);
        ps[i] = pt[i] = 0.25 * ps[i] + 1.0;
    } else if (op == 8) { /* 1 to 20 terms (queued up to 16), z among them or not */
        enum { T = 20 };
        int z = pick(NV - 1), m = pick(4) ? 1 + pick(8) : 1 + pick(T);
        double c[T];
        int xi[T];
        N_Vector xs[T], xt[T];
        for (int k = 0; k < m; k++) {
            c[k] = k == 0 && pick(4) == 0 ? 1.0 : coef();
            xi[k] = pick(5) == 0 ? z : pick(NV);
            xs[k] = s->v[xi[k]];
            xt[k] = t->v[xi[k]];
        }
        N_VLinearCombination(m, c, xs, s->v[z]);
        N_VLinearCombination(m, c, xt, t->v[z]);
    } else if (op == 9) {
        int z = pick(NV - 1);
        double c = coef();
        N_VConst(c, s->v[z]);
        N_VConst(c, t->v[z]);
    } else if (op == 10) { /* Z_j = a_j x + Y_j, in place (CVODE) or into others */
        int m = 1 + pick(6), base = pick(NV - 1 - m), x = pick(NV - 1), other = pick(2);
        double a[6];
        N_Vector ys[6], zs[6], yt[6], zt[6];
        for (int j = 0; j < m; j++) {
            a[j] = coef();
            int y = base + j, z = other ? pick(NV - 1) : y;
            ys[j] = s->v[y], zs[j] = s->v[z], yt[j] = t->v[y], zt[j] = t->v[z];
        }
        N_VScaleAddMulti(m, a, s->v[x], ys, zs);
        N_VScaleAddMulti(m, a, t->v[x], yt, zt);
    } else { /* error weights from x into w (w != x, the weights' vector kept positive) */
        int x = pick(NV - 2), w = NV - 2, scaled = pick(2);
        double rtol = 1e-6, atol = 1e-3;
        const double *sc = scaled ? N_VGetArrayPointer(s->v[NV - 1]) : NULL;
        const double *xs = N_VGetArrayPointer(s->v[x]);
        double *ws = N_VGetArrayPointer(s->v[w]);
        for (long i = 0; i < n; i++)
            ws[i] = 1.0 / (rtol * fabs(xs[i]) + atol * (sc ? sc[i] : 1.0));
        /* the tuned set: queued behind whatever is pending, scales read at the run */
        ok &= gw_sun_nv_ewt(t->v[x], t->v[w], rtol, atol,
                            scaled ? N_VGetArrayPointer(t->v[NV - 1]) : NULL) == 0;
    }
    return ok;
}

static void run(long n, int steps, SUNContext ctx)
{
    set s, t;
    for (int k = 0; k < NV; k++) {
        s.v[k] = N_VNew_Serial(n, ctx);
        N_VEnableFusedOps_Serial(s.v[k], SUNTRUE);
        t.v[k] = gw_sun_vector(n, ctx);
        double *a = N_VGetArrayPointer(s.v[k]), *b = N_VGetArrayPointer(t.v[k]);
        for (long i = 0; i < n; i++)
            a[i] = b[i] = (double)(next() >> 11) * 0x1p-53 - 0.5 + (k == NV - 1 ? 1.0 : 0.0);
    }
    int red_ok = 1;
    for (int i = 0; i < steps; i++) {
        int o = step(&s, &t, n);
        red_ok &= o;
        /* keep the values finite (NaN's sign under c x and -x differs, and
         * overflow would hide differences): scale large vectors down */
        for (int k = 0; k < NV; k++)
            if (N_VMaxNorm(s.v[k]) > 1e6) {
                N_VScale(1.0 / 1024.0 / 1024.0, s.v[k], s.v[k]);
                N_VScale(1.0 / 1024.0 / 1024.0, t.v[k], t.v[k]);
            }
    }
    char what[120];
    snprintf(what, sizeof what, "n = %ld: %d random steps, every reduction bit-identical", n,
             steps);
    gw_test_true(red_ok, what);
    snprintf(what, sizeof what, "n = %ld: every vector bit-identical after them", n);
    gw_test_true(gw_test_same_vectors(s.v, t.v, NV, n), what);

    /* a vector destroyed with a sum into it pending, then more work */
    N_Vector tmp = N_VClone(t.v[0]);
    N_VScale(1.0, t.v[1], tmp);
    N_VLinearSum(1.0, tmp, 1.0, t.v[2], tmp);
    N_VDestroy(tmp);
    N_VLinearSum(1.0, t.v[3], 1.0, t.v[4], t.v[3]);
    N_VLinearSum(1.0, s.v[3], 1.0, s.v[4], s.v[3]);
    snprintf(what, sizeof what, "n = %ld: a destroyed vector's pending work ran before it went",
             n);
    gw_test_true(gw_test_same_vectors(s.v, t.v, NV, n), what);
    for (int k = 0; k < NV; k++) {
        N_VDestroy(s.v[k]);
        N_VDestroy(t.v[k]);
    }
}

/* x_i' = v_i, v_i' = -w_i^2 x_i, w_i from 1 to 3 */
static int osc(realtype t, N_Vector y, N_Vector f, void *ud)
{
    (void)t;
    (void)ud;
    const double *yd = N_VGetArrayPointer(y);
    double *fd = N_VGetArrayPointer(f);
    const long m = N_VGetLength(y) / 2;
    for (long i = 0; i < m; i++) {
        double w = 1.0 + 2.0 * (double)i / (double)m;
        fd[2 * i] = yd[2 * i + 1];
        fd[2 * i + 1] = -w * w * yd[2 * i];
    }
    return 0;
}

/* error weights at rtol = atol = 1e-10: queued on tuned vectors, else direct */
static int ewt(N_Vector y, N_Vector w, void *ud)
{
    (void)ud;
    if (gw_sun_nv_ewt(y, w, 1e-10, 1e-10, NULL) == 0)
        return 0;
    const double *yd = N_VGetArrayPointer(y);
    double *wd = N_VGetArrayPointer(w);
    for (long i = 0; i < N_VGetLength(y); i++)
        wd[i] = 1.0 / (1e-10 * fabs(yd[i]) + 1e-10 * 1.0);
    return 0;
}

/* CVODE Adams to t = 10 on y; returns the steps taken (-1 on failure) */
static long adams(N_Vector y, SUNContext ctx)
{
    void *mem = CVodeCreate(CV_ADAMS, ctx);
    SUNNonlinearSolver nls = SUNNonlinSol_FixedPoint(y, 0, ctx);
    long steps = -1;
    realtype t = 0.0;
    if (mem && nls && CVodeInit(mem, osc, 0.0, y) == CV_SUCCESS &&
        CVodeWFtolerances(mem, ewt) == CV_SUCCESS &&
        CVodeSetNonlinearSolver(mem, nls) == CV_SUCCESS && CVodeSetMaxNumSteps(mem, 100000) == CV_SUCCESS &&
        CVode(mem, 10.0, y, &t, CV_NORMAL) == CV_SUCCESS)
        CVodeGetNumSteps(mem, &steps);
    CVodeFree(&mem);
    SUNNonlinSolFree(nls);
    return steps;
}

/* ARKode's ERK (Cash-Karp, granwave's table) to t = 10 on y; returns the steps
 * taken (-1 on failure). Each step ends with two queued linear combinations
 * and the error's norm, run as one pass on the tuned vectors. */
static long erk(N_Vector y, SUNContext ctx)
{
    void *mem = ERKStepCreate(osc, 0.0, y, ctx);
    long steps = -1;
    realtype t = 0.0;
    if (mem && ERKStepWFtolerances(mem, ewt) == ARK_SUCCESS &&
        ERKStepSetTableName(mem, "ARKODE_CASH_KARP_6_4_5") == ARK_SUCCESS &&
        ERKStepSetMaxNumSteps(mem, 100000) == ARK_SUCCESS &&
        ERKStepEvolve(mem, 10.0, y, &t, ARK_NORMAL) == ARK_SUCCESS)
        ERKStepGetNumSteps(mem, &steps);
    ERKStepFree(&mem);
    return steps;
}

static void solver_check(long n, SUNContext ctx, long (*solve)(N_Vector, SUNContext), const char *name)
{
    N_Vector a = N_VNew_Serial(n, ctx), b = gw_sun_vector(n, ctx);
    N_VEnableFusedOps_Serial(a, SUNTRUE);
    double *ad = N_VGetArrayPointer(a), *bd = N_VGetArrayPointer(b);
    for (long i = 0; i < n; i++)
        ad[i] = bd[i] = i % 2 ? 0.0 : 1.0;
    long sa = solve(a, ctx);
    long sb = solve(b, ctx);
    char what[120];
    snprintf(what, sizeof what, "%s, n = %ld: the same steps on both vectors (more than 100)", name, n);
    gw_test_true(sa > 100 && sa == sb, what);
    snprintf(what, sizeof what, "%s, n = %ld: the same final state, bit for bit", name, n);
    gw_test_true(memcmp(N_VGetArrayPointer(a), N_VGetArrayPointer(b), (size_t)n * sizeof(double)) == 0, what);
    N_VDestroy(a);
    N_VDestroy(b);
}

int main(void)
{
    SUNContext ctx;
    if (SUNContext_Create(NULL, &ctx) != 0)
        return 1;
    const long lens[] = {1, 511, 512, 513, 5000, 9000};
    for (size_t i = 0; i < sizeof lens / sizeof lens[0]; i++)
        run(lens[i], lens[i] > 5000 ? 1500 : 4000, ctx);
    solver_check(2000, ctx, adams, "cvode adams");
    solver_check(20000, ctx, adams, "cvode adams");
    solver_check(2000, ctx, erk, "arkode erk");
    solver_check(20000, ctx, erk, "arkode erk");
    SUNContext_Free(&ctx);
    return gw_test_summary("test_nvector");
}
