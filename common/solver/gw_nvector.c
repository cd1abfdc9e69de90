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
 */
#include <math.h>
#include <string.h>

#include <nvector/nvector_serial.h>

#include "gw_sundials.h"

#define LEN(v) NV_LENGTH_S(v)
#define DATA(v) NV_DATA_S(v)

static void gw_nv_linearsum(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x), *yd = DATA(y);
    realtype *zd = DATA(z);
    /* in-place updates alias z with x or y: plain pointers there */
    if (z == y && b == 1.0) {
        for (sunindextype i = 0; i < n; i++)
            zd[i] += a * xd[i];
        return;
    }
    if (z == x && a == 1.0) {
        for (sunindextype i = 0; i < n; i++)
            zd[i] += b * yd[i];
        return;
    }
    if (a == b) {
        for (sunindextype i = 0; i < n; i++)
            zd[i] = a * (xd[i] + yd[i]);
        return;
    }
    if (a == -b) {
        for (sunindextype i = 0; i < n; i++)
            zd[i] = a * (xd[i] - yd[i]);
        return;
    }
    for (sunindextype i = 0; i < n; i++)
        zd[i] = a * xd[i] + b * yd[i];
}

static void gw_nv_const(realtype c, N_Vector z)
{
    const sunindextype n = LEN(z);
    realtype *restrict zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = c;
}

static void gw_nv_prod(N_Vector x, N_Vector y, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x), *yd = DATA(y);
    realtype *zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = xd[i] * yd[i];
}

static void gw_nv_div(N_Vector x, N_Vector y, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x), *yd = DATA(y);
    realtype *zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = xd[i] / yd[i];
}

static void gw_nv_scale(realtype c, N_Vector x, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype *zd = DATA(z);
    /* c = 1 is a copy (ARKode's interpolant keeps y_n and f_n every step):
     * the C library's copy uses the widest vectors the CPU has */
    if (c == 1.0) {
        if (zd != xd)
            memcpy(zd, xd, (size_t)n * sizeof *zd);
        return;
    }
    for (sunindextype i = 0; i < n; i++)
        zd[i] = c * xd[i];
}

static void gw_nv_abs(N_Vector x, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype *zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = fabs(xd[i]);
}

static void gw_nv_inv(N_Vector x, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype *zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = 1.0 / xd[i];
}

static void gw_nv_addconst(N_Vector x, realtype b, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype *zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = xd[i] + b;
}

static realtype gw_nv_dotprod(N_Vector x, N_Vector y)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x), *yd = DATA(y);
    realtype s = 0.0;
    for (sunindextype i = 0; i < n; i++)
        s += xd[i] * yd[i];
    return s;
}

static realtype gw_nv_maxnorm(N_Vector x)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype m = 0.0;
    for (sunindextype i = 0; i < n; i++)
        m = fabs(xd[i]) > m ? fabs(xd[i]) : m;
    return m;
}

/* Weighted sum of squares in index order (one dependent add per element, as
 * the library; partial sums would be faster in cache but change the rounding
 * of the error norms and through them the step sizes). */
static realtype wsqrsum(N_Vector x, N_Vector w)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x), *wd = DATA(w);
    realtype s = 0.0;
    for (sunindextype i = 0; i < n; i++) {
        realtype p = xd[i] * wd[i];
        s += p * p;
    }
    return s;
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
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype m = xd[0];
    for (sunindextype i = 1; i < n; i++)
        m = xd[i] < m ? xd[i] : m;
    return m;
}

static realtype gw_nv_l1norm(N_Vector x)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype s = 0.0;
    for (sunindextype i = 0; i < n; i++)
        s += fabs(xd[i]);
    return s;
}

static void gw_nv_compare(realtype c, N_Vector x, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DATA(x);
    realtype *zd = DATA(z);
    for (sunindextype i = 0; i < n; i++)
        zd[i] = fabs(xd[i]) >= c ? 1.0 : 0.0;
}

static booleantype gw_nv_invtest(N_Vector x, N_Vector z)
{
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

/* z = sum_j c_j X_j, summed in j order per element (as the library). Sixteen
 * elements at a time are kept in registers while the terms stream in, so z is
 * written once instead of read and written per term. */
static int gw_nv_linearcombination(int nvec, realtype *c, N_Vector *X, N_Vector z)
{
    if (nvec < 1)
        return -1;
    if (nvec == 1) {
        gw_nv_scale(c[0], X[0], z);
        return 0;
    }
    if (nvec == 2) {
        gw_nv_linearsum(c[0], X[0], c[1], X[1], z);
        return 0;
    }
    enum { V = 16 };
    const sunindextype n = LEN(z);
    realtype *zd = DATA(z);
    for (int j = 1; j < nvec; j++)
        if (X[j] == z)
            return lincomb_aliased(nvec, c, X, z);
    /* first term: X[0] == z with c[0] == 1 starts from z itself */
    const int keep = X[0] == z && c[0] == 1.0;
    const realtype *x0 = DATA(X[0]);
    sunindextype i = 0;
    for (; i + V <= n; i += V) {
        realtype acc[V];
        for (int k = 0; k < V; k++)
            acc[k] = keep ? x0[i + k] : c[0] * x0[i + k];
        for (int j = 1; j < nvec; j++) {
            const realtype *xj = DATA(X[j]) + i, cj = c[j];
            for (int k = 0; k < V; k++)
                acc[k] += cj * xj[k];
        }
        for (int k = 0; k < V; k++)
            zd[i + k] = acc[k];
    }
    for (; i < n; i++) {
        realtype acc = keep ? x0[i] : c[0] * x0[i];
        for (int j = 1; j < nvec; j++)
            acc += c[j] * DATA(X[j])[i];
        zd[i] = acc;
    }
    return 0;
}

/* Z_j = a_j x + Y_j. */
static int gw_nv_scaleaddmulti(int nvec, realtype *a, N_Vector x, N_Vector *Y, N_Vector *Z)
{
    if (nvec < 1)
        return -1;
    if (nvec == 1) {
        gw_nv_linearsum(a[0], x, 1.0, Y[0], Z[0]);
        return 0;
    }
    const sunindextype n = LEN(x);
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
    if (nvec < 1)
        return -1;
    for (int j = 0; j < nvec; j++)
        gw_nv_scale(c[j], X[j], Z[j]);
    return 0;
}

static int gw_nv_constvectorarray(int nvec, realtype c, N_Vector *Z)
{
    if (nvec < 1)
        return -1;
    for (int j = 0; j < nvec; j++)
        gw_nv_const(c, Z[j]);
    return 0;
}

static int gw_nv_linearsumvectorarray(int nvec, realtype a, N_Vector *X, realtype b, N_Vector *Y,
                                      N_Vector *Z)
{
    if (nvec < 1)
        return -1;
    for (int j = 0; j < nvec; j++)
        gw_nv_linearsum(a, X[j], b, Y[j], Z[j]);
    return 0;
}

static int gw_nv_wrmsnormvectorarray(int nvec, N_Vector *X, N_Vector *W, realtype *nrm)
{
    if (nvec < 1)
        return -1;
    for (int j = 0; j < nvec; j++)
        nrm[j] = gw_nv_wrmsnorm(X[j], W[j]);
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
    return 0;
}
