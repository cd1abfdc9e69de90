/*
 * gw_nvector.c: compiled vector kernels for SUNDIALS' serial N_Vector.
 *
 * CVODE and ARKode spend most of a long chain's step in vector operations on
 * the state (CVODE Adams' predictor alone is q(q+1)/2 linear sums per step, q up
 * to 12). The distribution's SUNDIALS library may be built without optimisation
 * (Debian 12's 6.4.1 is: every element goes through the stack), so these
 * kernels, compiled with the project's flags, replace the hot entries of each
 * vector's ops table. Clones copy the ops table, so every vector CVODE/ARKode
 * makes from the template inherits them.
 *
 * Semantics are SUNDIALS' (serial N_Vector, 6.x). Each element is computed with
 * the same operations in the same order as the library's kernels, including the
 * cases where z = a (x + y) or a (x - y) is formed for a = +-b, and reductions
 * sum in index order, so results are bit-identical, only faster (vectorised
 * element loops, no per-element calls through the stack). Units: none (pure
 * arithmetic on the state).
 *
 * Linear sums z = a x + b y, scalings z = c x, constants, scaled additions
 * Z_j = a_j x + Y_j and the error weights (gw_sun_nv_ewt) are not run at once
 * but queued; the queue runs at the next other operation on any vector, or
 * when granwave reads a vector's data (N_VGetArrayPointer), block by block:
 * each block of BLK elements goes through every queued operation while it is
 * in the L1 cache. A weighted norm runs the queue block by block and sums each
 * block as it leaves it (CVODE's fixed-point iteration: a sum, a scaling, a
 * copy and a difference, then the difference's norm: one pass instead of
 * five). At the end of a CVODE step this makes one pass where there were
 * three: the correction of the Nordsieck array (q + 1 scaled additions), the
 * next error weights from z_0 and the norm CVODE takes of z_0 with them; the
 * next predictor (q(q+1)/2 sums z_{j-1} += z_j) runs in one pass with the
 * corrector's first sums. A system that gives its right-hand side by ranges
 * of components (gw_system.rhs_range) has it queued too under CVODE Adams
 * (gw_sun_rhs_queued): the state y = z_0 + correction, the right-hand side,
 * the corrector's sums and the norm of the change then run in one pass, the
 * right-hand side one block behind the operations before it (it reads a few
 * elements of y beyond its block), and y and f(y) are not streamed through
 * memory once more each per iterate. Every element still sees the same
 * operations in the same order, so the results are bit-identical
 * (tests/test_nvector.c, tests/test_solver_adams_bitwise.c).
 * The queue is per thread; every op in the table (and the serial ones that
 * touch data, wrapped below) runs it first, and a vector is destroyed only
 * after it.
 */
#include <math.h>
#include <string.h>

#include <nvector/nvector_serial.h>

#include "gw_sundials.h"

/* The element loops are also compiled for AVX (chosen when the program
 * loads, as rk4_step is): AVX without FMA does the same IEEE operations in
 * the same order, so the same numbers, with half the instructions per
 * element; the long linear combinations of an ERK step were bound by
 * instructions, not by memory. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define GW_NV_CLONES __attribute__((target_clones("avx", "default")))
#else
#define GW_NV_CLONES
#endif

#define LEN(v) NV_LENGTH_S(v)
#define DATA(v) NV_DATA_S(v)

/* The queue of pending element-wise operations (see the head of the file):
 * z = a x + b y (linear sums, with the cases of apply below), z = a x
 * (scalings, a copy when a = 1), z = a (constants), the error weights
 * z = 1 / (a |x| + b y) (y the scales, NULL for 1) and at most one
 * right-hand side z = f(a, x) given by ranges (gw_sun_nv_rhs; rhs_at is its
 * place in the queue, -1 for none). */
#ifndef GW_NV_BLK
#define GW_NV_BLK 512
#endif
enum { QMAX = 128, BLK = GW_NV_BLK, RHS_LAG = 64, LC_MAX = 8 };
typedef enum { OP_SUM, OP_SCALE, OP_CONST, OP_EWT, OP_RHS, OP_LC } gw_nv_kind;
typedef struct {
    gw_nv_kind kind;
    realtype a, b;
    const realtype *x, *y;
    realtype *z;
    sunindextype n;
    gw_rhs_range_fn f; /* OP_RHS: f(a, x, z, i0, i1, p) */
    void *p;
    /* OP_LC: z = sum_j c_j X_j, j < nt (keep: the first term is X_0 itself);
     * the terms are copied, as the caller reuses its arrays */
    int nt, keep;
    realtype c[LC_MAX];
    const realtype *X[LC_MAX];
} gw_nv_op;
static _Thread_local gw_nv_op queue[QMAX];
static _Thread_local int queued, rhs_at = -1;

/* Four doubles as one value (GCC's vector extension): one AVX register in the
 * AVX clones, two SSE2 ones elsewhere. Element-wise + and * are the IEEE
 * operations of each lane, in the order written (no contraction: ISO C). */
typedef double gw_v4 __attribute__((vector_size(32)));
#define V4_LOAD(v, p) memcpy(&(v), (p), sizeof(gw_v4)) /* unaligned */
#define V4_STORE(p, v) memcpy((p), &(v), sizeof(gw_v4))

/* z = sum_j c_j X_j on elements [i0, i1), summed in j order per element (as
 * the library), sixteen elements at a time kept in four vector registers while
 * the terms stream in, so z is written once instead of read and written per
 * term. Written with explicit vectors: GCC's own vectorisation of this loop
 * kept the sums on the stack and shuffled lanes (the ERK step's last pass ran
 * at half the speed of its memory traffic). */
static inline __attribute__((always_inline)) void lincomb_range(const gw_nv_op *o,
                                                                sunindextype i0, sunindextype i1)
{
    const int nt = o->nt, keep = o->keep;
    const realtype *x0 = o->X[0], c0 = o->c[0];
    realtype *zd = o->z;
    sunindextype i = i0;
    const gw_v4 vc0 = {c0, c0, c0, c0};
    for (; i + 16 <= i1; i += 16) {
        gw_v4 a0, a1, a2, a3;
        V4_LOAD(a0, x0 + i);
        V4_LOAD(a1, x0 + i + 4);
        V4_LOAD(a2, x0 + i + 8);
        V4_LOAD(a3, x0 + i + 12);
        if (!keep) {
            a0 = vc0 * a0;
            a1 = vc0 * a1;
            a2 = vc0 * a2;
            a3 = vc0 * a3;
        }
        for (int j = 1; j < nt; j++) {
            const realtype *xj = o->X[j] + i, cj = o->c[j];
            const gw_v4 vc = {cj, cj, cj, cj};
            gw_v4 b0, b1, b2, b3;
            V4_LOAD(b0, xj);
            V4_LOAD(b1, xj + 4);
            V4_LOAD(b2, xj + 8);
            V4_LOAD(b3, xj + 12);
            a0 = a0 + vc * b0;
            a1 = a1 + vc * b1;
            a2 = a2 + vc * b2;
            a3 = a3 + vc * b3;
        }
        V4_STORE(zd + i, a0);
        V4_STORE(zd + i + 4, a1);
        V4_STORE(zd + i + 8, a2);
        V4_STORE(zd + i + 12, a3);
    }
    for (; i < i1; i++) {
        realtype acc = keep ? x0[i] : c0 * x0[i];
        for (int j = 1; j < nt; j++)
            acc += o->c[j] * o->X[j][i];
        zd[i] = acc;
    }
}

/* one operation on elements [i0, i1): the same arithmetic, element by element,
 * as the direct kernel (in-place forms alias z with x or y) */
static inline __attribute__((always_inline)) void apply(const gw_nv_op *o, sunindextype i0,
                                                        sunindextype i1)
{
    const realtype a = o->a, b = o->b, *xd = o->x, *yd = o->y;
    realtype *zd = o->z;
    if (o->kind == OP_CONST) {
        for (sunindextype i = i0; i < i1; i++)
            zd[i] = a;
        return;
    }
    if (o->kind == OP_RHS) {
        o->f(a, xd, zd, (long)i0, (long)i1, o->p);
        return;
    }
    if (o->kind == OP_LC) {
        lincomb_range(o, i0, i1);
        return;
    }
    if (o->kind == OP_EWT) { /* error weights, as gw_sun_ewt: y in x, scale in y */
        if (yd)
            for (sunindextype i = i0; i < i1; i++)
                zd[i] = 1.0 / (a * fabs(xd[i]) + b * yd[i]);
        else
            for (sunindextype i = i0; i < i1; i++)
                zd[i] = 1.0 / (a * fabs(xd[i]) + b * 1.0);
        return;
    }
    if (o->kind == OP_SCALE) {
        if (a == 1.0) {
            if (zd != xd)
                memcpy(zd + i0, xd + i0, (size_t)(i1 - i0) * sizeof *zd);
        } else {
            for (sunindextype i = i0; i < i1; i++)
                zd[i] = a * xd[i];
        }
        return;
    }
    if (zd == yd && b == 1.0) {
        for (sunindextype i = i0; i < i1; i++)
            zd[i] += a * xd[i];
    } else if (zd == xd && a == 1.0) {
        for (sunindextype i = i0; i < i1; i++)
            zd[i] += b * yd[i];
    } else if (a == -1.0 && b == 1.0) {
        /* the library forms y - x here, not -(x - y): they differ in the sign
         * of a zero */
        for (sunindextype i = i0; i < i1; i++)
            zd[i] = yd[i] - xd[i];
    } else if (a == b) {
        for (sunindextype i = i0; i < i1; i++)
            zd[i] = a * (xd[i] + yd[i]);
    } else if (a == -b) {
        for (sunindextype i = i0; i < i1; i++)
            zd[i] = a * (xd[i] - yd[i]);
    } else {
        for (sunindextype i = i0; i < i1; i++)
            zd[i] = a * xd[i] + b * yd[i];
    }
}

/* the queued operations k0 <= k < k1 on elements [i0, i1), in order */
GW_NV_CLONES
static void apply_ops(int k0, int k1, sunindextype i0, sunindextype i1)
{
    for (int k = k0; k < k1; k++) {
        sunindextype e = queue[k].n < i1 ? queue[k].n : i1;
        if (e > i0)
            apply(&queue[k], i0, e);
    }
}

static sunindextype queue_length(void)
{
    sunindextype nmax = 0;
    for (int k = 0; k < queued; k++)
        if (queue[k].n > nmax)
            nmax = queue[k].n;
    return nmax;
}

/* Sum of (x w)^2 in index order (one dependent add per element, as the
 * library; partial sums would be faster in cache but change the rounding of
 * the error norms and through them the step sizes). */
static inline __attribute__((always_inline)) realtype
wsqrsum_range(const realtype *xd, const realtype *wd, sunindextype i0, sunindextype i1, realtype s)
{
    for (sunindextype i = i0; i < i1; i++) {
        realtype p = xd[i] * wd[i];
        s += p * p;
    }
    return s;
}

/* The queued operations k0 <= k < k1 (none a right-hand side) on [i0, i1) and
 * the sum of (x w)^2 over [i0, min(i1, n)), SUM_CHUNK elements at a time, each
 * chunk summed after the operations have run on it: the sum's chain of
 * dependent adds (latency-bound, about 4 cycles per element) then overlaps the
 * loads of the next chunk, where summed after a whole block it stalled the
 * pass for as long (ARKode's two norms per step, of its error estimate and of
 * y_n, cost about 5 whole-vector streams per step so). Each element sees the
 * same operations in the same order. */
enum { SUM_CHUNK = 32 };
GW_NV_CLONES
static realtype apply_sum(int k0, int k1, sunindextype i0, sunindextype i1, const realtype *xd,
                          const realtype *wd, sunindextype n, realtype s)
{
    const sunindextype m = n < i1 ? n : i1;
    for (sunindextype i = i0; i < i1; i += SUM_CHUNK) {
        const sunindextype j = i + SUM_CHUNK < i1 ? i + SUM_CHUNK : i1;
        for (int k = k0; k < k1; k++) {
            const sunindextype e = queue[k].n < j ? queue[k].n : j;
            if (e > i)
                apply(&queue[k], i, e);
        }
        if (i < m)
            s = wsqrsum_range(xd, wd, i, j < m ? j : m, s);
    }
    return s;
}

/* The right-hand side queued at r can run in the pass, by ranges that trail
 * the operations queued before it by RHS_LAG elements (a range reads y up to
 * rhs_halo <= RHS_LAG elements beyond its end, which those have then reached),
 * if no operation after it writes y (a range would read y just before its
 * start after those had changed it) and every operation has its length. */
static int rhs_fusable(int r)
{
    const gw_nv_op *o = &queue[r];
    for (int k = 0; k < queued; k++)
        if (queue[k].n != o->n || (k > r && queue[k].z == o->x))
            return 0;
    return 1;
}

/* Runs the queue block by block. With xd, returns s plus the sum of (x w)^2
 * over [0, n) in index order, each range summed as soon as every queued
 * operation has run on it. A right-hand side in the queue runs after the
 * operations before it have run on block b, on the range from where the last
 * one ended to RHS_LAG elements before the end of block b (to the end, at the
 * last block), and the operations after it (and the sum) run on that range
 * with it: per element the same operations in the same order as one by one. */
static realtype run_pass(const realtype *xd, const realtype *wd, sunindextype n, realtype s)
{
    int r = rhs_at;
    if (r >= 0 && !rhs_fusable(r)) { /* what precedes it, then it alone, in passes */
        const sunindextype len = queue_length();
        for (sunindextype i0 = 0; i0 < len; i0 += BLK)
            apply_ops(0, r, i0, i0 + BLK < len ? i0 + BLK : len);
        for (sunindextype i0 = 0; i0 < len; i0 += BLK)
            apply_ops(r, r + 1, i0, i0 + BLK < len ? i0 + BLK : len);
        queued -= r + 1;
        memmove(queue, queue + r + 1, (size_t)queued * sizeof *queue);
        r = rhs_at = -1;
    }
    sunindextype nmax = queue_length();
    if (xd && n > nmax)
        nmax = n;
    const sunindextype lag = r >= 0 ? RHS_LAG : 0;
    /* with a sum, the operations that run on [done, e) run with it
     * (apply_sum), but for a right-hand side */
    const int k_pre = r >= 0 ? r : xd ? 0 : queued, k_sum = r >= 0 ? r + 1 : k_pre;
    sunindextype done = 0; /* [0, done) has seen every operation */
    for (sunindextype i0 = 0; i0 < nmax; i0 += BLK) {
        const sunindextype i1 = i0 + BLK < nmax ? i0 + BLK : nmax, e = i1 == nmax ? nmax : i1 - lag;
        apply_ops(0, k_pre, i0, i1);
        if (r >= 0)
            apply_ops(r, xd ? r + 1 : queued, done, e);
        if (xd)
            s = apply_sum(k_sum, queued, done, e, xd, wd, n, s);
        done = e;
    }
    queued = 0;
    rhs_at = -1;
    return s;
}

/* the whole queue, block by block */
static void run_queue(void)
{
    if (queued != 0)
        run_pass(NULL, NULL, 0, 0.0);
}

#define FLUSH() run_queue()

static void enqueue(gw_nv_op o)
{
    /* a pending right-hand side runs in the pass of what precedes it only if
     * nothing after it writes its input (rhs_fusable): an operation that does
     * (ARKode's next stage, written where the last one was) starts a new pass */
    if (queued == QMAX || (rhs_at >= 0 && (o.kind == OP_RHS || o.z == queue[rhs_at].x)))
        run_queue();
    if (o.kind == OP_RHS)
        rhs_at = queued;
    queue[queued++] = o;
}

static void gw_nv_linearsum(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z)
{
    enqueue((gw_nv_op){.kind = OP_SUM, .a = a, .b = b, .x = DATA(x), .y = DATA(y), .z = DATA(z), .n = LEN(x)});
}

static void gw_nv_const(realtype c, N_Vector z)
{
    enqueue((gw_nv_op){.kind = OP_CONST, .a = c, .z = DATA(z), .n = LEN(z)});
}

static void gw_nv_prod(N_Vector x, N_Vector y, N_Vector z)
{
    FLUSH();
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x), *yd = DATA(y);
    realtype *zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = xd[i] * yd[i];
}

static void gw_nv_div(N_Vector x, N_Vector y, N_Vector z)
{
    FLUSH();
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x), *yd = DATA(y);
    realtype *zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = xd[i] / yd[i];
}

static void gw_nv_scale(realtype c, N_Vector x, N_Vector z)
{
    /* c = 1 is a copy (ARKode's interpolant keeps y_n and f_n every step,
     * CVODE's fixed-point iteration its previous iterate): memcpy, which uses
     * the widest vectors the CPU has */
    enqueue((gw_nv_op){.kind = OP_SCALE, .a = c, .x = DATA(x), .z = DATA(z), .n = LEN(x)});
}

static void gw_nv_abs(N_Vector x, N_Vector z)
{
    FLUSH();
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype *zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = fabs(xd[i]);
}

static void gw_nv_inv(N_Vector x, N_Vector z)
{
    FLUSH();
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype *zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = 1.0 / xd[i];
}

static void gw_nv_addconst(N_Vector x, realtype b, N_Vector z)
{
    FLUSH();
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype *zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = xd[i] + b;
}

static realtype gw_nv_dotprod(N_Vector x, N_Vector y)
{
    FLUSH();
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x), *yd = DATA(y);
    realtype s = 0.0;
    for (sunindextype i = 0; i < n; i++)
        s += xd[i] * yd[i];
    return s;
}

static realtype gw_nv_maxnorm(N_Vector x)
{
    FLUSH();
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype m = 0.0;
    for (sunindextype i = 0; i < n; i++)
        m = fabs(xd[i]) > m ? fabs(xd[i]) : m;
    return m;
}

/* sum of (x w)^2 in index order; pending operations run block by block
 * just before the block is summed, while it is in cache */
static realtype wsqrsum(N_Vector x, N_Vector w)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x), *wd = DATA(w);
    if (queued == 0)
        return wsqrsum_range(xd, wd, 0, n, 0.0);
    return run_pass(xd, wd, n, 0.0);
}

static realtype rsqrt0(realtype x)
{
    return x <= 0.0 ? 0.0 : sqrt(x);
}

static realtype gw_nv_wrmsnorm(N_Vector x, N_Vector w)
{
    return rsqrt0(wsqrsum(x, w) / (realtype)LEN(x));
}

static realtype gw_nv_wl2norm(N_Vector x, N_Vector w)
{
    return rsqrt0(wsqrsum(x, w));
}

static realtype gw_nv_min(N_Vector x)
{
    FLUSH();
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype m = xd[0];
    for (sunindextype i = 1; i < n; i++)
        m = xd[i] < m ? xd[i] : m;
    return m;
}

static realtype gw_nv_l1norm(N_Vector x)
{
    FLUSH();
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype s = 0.0;
    for (sunindextype i = 0; i < n; i++)
        s += fabs(xd[i]);
    return s;
}

static void gw_nv_compare(realtype c, N_Vector x, N_Vector z)
{
    FLUSH();
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype *zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = fabs(xd[i]) >= c ? 1.0 : 0.0;
}

static booleantype gw_nv_invtest(N_Vector x, N_Vector z)
{
    FLUSH();
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype *zd = DATA(z);
    booleantype ok = SUNTRUE;
    for (sunindextype i = 0; i < n; i++) {
        if (xd[i] == 0.0)
            ok = SUNFALSE;
        else
            zd[i] = 1.0 / xd[i];
    }
    return ok;
}

static realtype gw_nv_minquotient(N_Vector num, N_Vector den)
{
    FLUSH();
    const sunindextype n = LEN(num);
    const realtype *nd = DATA(num), *dd = DATA(den);
    realtype m = BIG_REAL;
    for (sunindextype i = 0; i < n; i++)
        if (dd[i] != 0.0 && nd[i] / dd[i] < m)
            m = nd[i] / dd[i];
    return m;
}

/* The library's order when z is also a later term X_j (j > 0): z is first
 * overwritten with c_0 X_0, and that new z is the X_j added later. */
GW_NV_CLONES
static int lincomb_aliased(int nvec, realtype *c, N_Vector *X, N_Vector z)
{
    const sunindextype n = LEN(z);
    realtype *zd = DATA(z);
    if (X[0] == z) {
        if (c[0] != 1.0)
            for (sunindextype i = 0; i < n; i++)
                zd[i] *= c[0];
    } else {
        const realtype *x0 = DATA(X[0]);
        for (sunindextype i = 0; i < n; i++)
            zd[i] = c[0] * x0[i];
    }
    for (int j = 1; j < nvec; j++) {
        const realtype *xj = DATA(X[j]);
        for (sunindextype i = 0; i < n; i++)
            zd[i] += c[j] * xj[i];
    }
    return 0;
}

/* z = sum_j c_j X_j, summed in j order per element (as the library), queued
 * (lincomb_range). */
static int gw_nv_linearcombination(int nvec, realtype *c, N_Vector *X, N_Vector z)
{
    if (nvec < 1) {
        FLUSH();
        return -1;
    }
    if (nvec == 1) {
        gw_nv_scale(c[0], X[0], z);
        return 0;
    }
    if (nvec == 2) {
        gw_nv_linearsum(c[0], X[0], c[1], X[1], z);
        return 0;
    }
    for (int j = 1; j < nvec; j++)
        if (X[j] == z) {
            FLUSH();
            return lincomb_aliased(nvec, c, X, z);
        }
    /* queued: an ERK stage runs in one pass with its right-hand side. First
     * term: X[0] == z with c[0] == 1 starts from z itself. More terms than an
     * op holds: ops of up to LC_MAX - 1 terms more each, from the sum so far
     * in z (stored and read back exactly: the same sums in the same order). */
    gw_nv_op o = {.kind = OP_LC, .z = DATA(z), .n = LEN(z), .keep = X[0] == z && c[0] == 1.0};
    int t = 0;
    for (int j = 0; j < nvec; j++) {
        if (t == LC_MAX) {
            o.nt = t;
            enqueue(o);
            o.keep = 1;
            o.c[0] = 1.0;
            o.X[0] = DATA(z);
            t = 1;
        }
        o.c[t] = c[j];
        o.X[t++] = DATA(X[j]);
    }
    o.nt = t;
    enqueue(o);
    return 0;
}

/* Z_j = a_j x + Y_j. On long vectors (SAM_QUEUED elements and more) queued as
 * nvec linear sums a_j x + 1 Y_j (the same value per element: 1 y is y, and a
 * sum is the same either way round): CVODE corrects its Nordsieck array this
 * way at the end of a step, and queued it runs in one pass with the next error
 * weights and the norm that follows them. Shorter ones stay in cache and run
 * at once, term by term (measured cheaper at 1e3 beads). */
enum { SAM_QUEUED = 8192 };
GW_NV_CLONES
static int gw_nv_scaleaddmulti(int nvec, realtype *a, N_Vector x, N_Vector *Y, N_Vector *Z)
{
    if (nvec < 1)
        return -1;
    const sunindextype n = LEN(x);
    if (nvec == 1 || n >= SAM_QUEUED) {
        for (int j = 0; j < nvec; j++)
            gw_nv_linearsum(a[j], x, 1.0, Y[j], Z[j]);
        return 0;
    }
    FLUSH();
    const realtype *xd = DATA(x);
    for (int j = 0; j < nvec; j++) {
        const realtype *yd = DATA(Y[j]);
        realtype *zd = DATA(Z[j]), aj = a[j];
        for (sunindextype i = 0; i < n; i++)
            zd[i] = aj * xd[i] + yd[i];
    }
    return 0;
}

static int gw_nv_scalevectorarray(int nvec, realtype *c, N_Vector *X, N_Vector *Z)
{
    FLUSH();
    if (nvec < 1)
        return -1;
    for (int j = 0; j < nvec; j++)
        gw_nv_scale(c[j], X[j], Z[j]);
    return 0;
}

static int gw_nv_constvectorarray(int nvec, realtype c, N_Vector *Z)
{
    FLUSH();
    if (nvec < 1)
        return -1;
    for (int j = 0; j < nvec; j++)
        gw_nv_const(c, Z[j]);
    return 0;
}

static int gw_nv_linearsumvectorarray(int nvec, realtype a, N_Vector *X, realtype b, N_Vector *Y,
                                      N_Vector *Z)
{
    FLUSH();
    if (nvec < 1)
        return -1;
    for (int j = 0; j < nvec; j++)
        gw_nv_linearsum(a, X[j], b, Y[j], Z[j]);
    return 0;
}

static int gw_nv_wrmsnormvectorarray(int nvec, N_Vector *X, N_Vector *W, realtype *nrm)
{
    FLUSH();
    if (nvec < 1)
        return -1;
    for (int j = 0; j < nvec; j++)
        nrm[j] = gw_nv_wrmsnorm(X[j], W[j]);
    return 0;
}

/* the serial ops that touch data, run after the queue */
#define AFTER_QUEUE(type, name, params, call)                                        \
    static type name params                                                          \
    {                                                                                \
        FLUSH();                                                                     \
        return call;                                                                 \
    }
#define AFTER_QUEUE_VOID(name, params, call)                                         \
    static void name params                                                          \
    {                                                                                \
        FLUSH();                                                                     \
        call;                                                                        \
    }
AFTER_QUEUE(realtype *, q_getarraypointer, (N_Vector v), N_VGetArrayPointer_Serial(v))
AFTER_QUEUE_VOID(q_setarraypointer, (realtype * d, N_Vector v), N_VSetArrayPointer_Serial(d, v))
AFTER_QUEUE_VOID(q_destroy, (N_Vector v), N_VDestroy_Serial(v))
AFTER_QUEUE(realtype, q_wrmsnormmask, (N_Vector x, N_Vector w, N_Vector id),
            N_VWrmsNormMask_Serial(x, w, id))
AFTER_QUEUE(realtype, q_wsqrsummasklocal, (N_Vector x, N_Vector w, N_Vector id),
            N_VWSqrSumMaskLocal_Serial(x, w, id))
AFTER_QUEUE(booleantype, q_constrmask, (N_Vector c, N_Vector x, N_Vector m),
            N_VConstrMask_Serial(c, x, m))
AFTER_QUEUE(int, q_dotprodmulti, (int nvec, N_Vector x, N_Vector *Y, realtype *d),
            N_VDotProdMulti_Serial(nvec, x, Y, d))
AFTER_QUEUE(int, q_scaleaddmultiva,
            (int nvec, int nsum, realtype *a, N_Vector *X, N_Vector **Y, N_Vector **Z),
            N_VScaleAddMultiVectorArray_Serial(nvec, nsum, a, X, Y, Z))
AFTER_QUEUE(int, q_lincombva, (int nvec, int nsum, realtype *c, N_Vector **X, N_Vector *Z),
            N_VLinearCombinationVectorArray_Serial(nvec, nsum, c, X, Z))
AFTER_QUEUE(int, q_wrmsnormmaskva, (int nvec, N_Vector *X, N_Vector *W, N_Vector id, realtype *nrm),
            N_VWrmsNormMaskVectorArray_Serial(nvec, X, W, id, nrm))
AFTER_QUEUE(int, q_bufpack, (N_Vector x, void *buf), N_VBufPack_Serial(x, buf))
AFTER_QUEUE(int, q_bufunpack, (N_Vector x, void *buf), N_VBufUnpack_Serial(x, buf))
AFTER_QUEUE_VOID(q_print, (N_Vector v), N_VPrint_Serial(v))
AFTER_QUEUE_VOID(q_printfile, (N_Vector v, FILE *f), N_VPrintFile_Serial(v, f))

int gw_sun_nv_ewt(N_Vector y, N_Vector w, double rtol, double atol, const double *scale)
{
    const gw_nv_op o = {.kind = OP_EWT, .a = rtol, .b = atol, .x = DATA(y), .y = scale, .z = DATA(w),
                        .n = LEN(y)};
    if (y->ops->nvlinearsum == gw_nv_linearsum && w->ops->nvlinearsum == gw_nv_linearsum) {
        enqueue(o);
    } else { /* not tuned vectors: at once, after whatever is pending */
        FLUSH();
        apply(&o, 0, o.n);
    }
    return 0;
}

int gw_sun_nv_rhs(double t, N_Vector y, N_Vector ydot, gw_rhs_range_fn f, long halo,
                  void *params)
{
    if (!f || halo < 0 || halo > RHS_LAG || y->ops->nvlinearsum != gw_nv_linearsum ||
        ydot->ops->nvlinearsum != gw_nv_linearsum || LEN(y) != LEN(ydot) || DATA(y) == DATA(ydot))
        return -1;
    gw_nv_op o = {.kind = OP_RHS, .a = t, .x = DATA(y), .z = DATA(ydot), .n = LEN(y), .f = f,
                  .p = params};
    enqueue(o);
    return 0;
}

int gw_sun_tune_vector(N_Vector v)
{
    if (!v || N_VGetVectorID(v) != SUNDIALS_NVEC_SERIAL)
        return -1;
    if (N_VEnableFusedOps_Serial(v, SUNTRUE) != 0)
        return -1;
    N_Vector_Ops o = v->ops;
    o->nvlinearsum = gw_nv_linearsum;
    o->nvconst = gw_nv_const;
    o->nvprod = gw_nv_prod;
    o->nvdiv = gw_nv_div;
    o->nvscale = gw_nv_scale;
    o->nvabs = gw_nv_abs;
    o->nvinv = gw_nv_inv;
    o->nvaddconst = gw_nv_addconst;
    o->nvdotprod = gw_nv_dotprod;
    o->nvmaxnorm = gw_nv_maxnorm;
    o->nvwrmsnorm = gw_nv_wrmsnorm;
    o->nvmin = gw_nv_min;
    o->nvwl2norm = gw_nv_wl2norm;
    o->nvl1norm = gw_nv_l1norm;
    o->nvcompare = gw_nv_compare;
    o->nvinvtest = gw_nv_invtest;
    o->nvminquotient = gw_nv_minquotient;
    o->nvlinearcombination = gw_nv_linearcombination;
    o->nvscaleaddmulti = gw_nv_scaleaddmulti;
    o->nvscalevectorarray = gw_nv_scalevectorarray;
    o->nvconstvectorarray = gw_nv_constvectorarray;
    o->nvlinearsumvectorarray = gw_nv_linearsumvectorarray;
    o->nvwrmsnormvectorarray = gw_nv_wrmsnormvectorarray;
    /* the local reductions feed the same sums */
    o->nvdotprodlocal = gw_nv_dotprod;
    o->nvmaxnormlocal = gw_nv_maxnorm;
    o->nvminlocal = gw_nv_min;
    o->nvl1normlocal = gw_nv_l1norm;
    o->nvinvtestlocal = gw_nv_invtest;
    o->nvminquotientlocal = gw_nv_minquotient;
    o->nvwsqrsumlocal = wsqrsum;
    /* the serial ones that touch data run the queue first (those the vector has) */
    if (o->nvgetarraypointer)
        o->nvgetarraypointer = q_getarraypointer;
    if (o->nvsetarraypointer)
        o->nvsetarraypointer = q_setarraypointer;
    if (o->nvdestroy)
        o->nvdestroy = q_destroy;
    if (o->nvwrmsnormmask)
        o->nvwrmsnormmask = q_wrmsnormmask;
    if (o->nvwsqrsummasklocal)
        o->nvwsqrsummasklocal = q_wsqrsummasklocal;
    if (o->nvconstrmask)
        o->nvconstrmask = q_constrmask;
    if (o->nvdotprodmulti)
        o->nvdotprodmulti = q_dotprodmulti;
    if (o->nvdotprodmultilocal)
        o->nvdotprodmultilocal = q_dotprodmulti;
    if (o->nvscaleaddmultivectorarray)
        o->nvscaleaddmultivectorarray = q_scaleaddmultiva;
    if (o->nvlinearcombinationvectorarray)
        o->nvlinearcombinationvectorarray = q_lincombva;
    if (o->nvbufpack)
        o->nvbufpack = q_bufpack;
    if (o->nvbufunpack)
        o->nvbufunpack = q_bufunpack;
    if (o->nvprint)
        o->nvprint = q_print;
    if (o->nvprintfile)
        o->nvprintfile = q_printfile;
    if (o->nvwrmsnormmaskvectorarray)
        o->nvwrmsnormmaskvectorarray = q_wrmsnormmaskva;
    if (o->nvconstrmasklocal)
        o->nvconstrmasklocal = q_constrmask;
    return 0;
}
