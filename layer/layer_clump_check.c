/*
 * layer_clump_check.c: the rule every rigid clump of the layer obeys (type B
 * soil, docs/physics.md 2.2; layer_clumps.c): its members overlap or touch, that
 * is their overlap graph is connected with |x_i - x_j| <= (r_i + r_j)(1 + 1e-9),
 * and there are at most LAYER_CLUMP_MEMBERS of them (the check is quadratic in
 * the members: the bound keeps a hostile sample of one huge body from stalling
 * the reader). Used by the sample reader and writer and by gw_layer_create;
 * also the reader's rule that discs of different bodies overlap by at most
 * 0.05 R_p (layer_overlaps_check);
 * free of the model so that the sample fuzzer links it alone. Also the names
 * of the clump mass laws, which samples and options spell.
 * Units: SI (m).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"

#define CLUMP_TOUCH_TOL 1e-9

int layer_clump_key_cmp(const void *pa, const void *pb)
{
    const layer_clump_key *a = pa, *b = pb;
    if (a->clump != b->clump)
        return a->clump < b->clump ? -1 : 1;
    return (a->i > b->i) - (a->i < b->i);
}

/* 1 when the members m[0 .. k-1] (indices into x, y, r) form one connected
 * overlap-or-touch graph: a search from m[0], O(k^2) (k <= LAYER_CLUMP_MEMBERS).
 * stack: scratch of k ints. */
int layer_members_connected(const double *x, const double *y, const double *r, int *m, int k, int *stack)
{
    /* m[0 .. nseen-1] are reached; the rest wait to be */
    int nseen = 1, top = 0;
    stack[top++] = m[0];
    while (top > 0) {
        int i = stack[--top];
        for (int q = nseen; q < k; q++) {
            int j = m[q];
            if (hypot(x[j] - x[i], y[j] - y[i]) <= (r[i] + r[j]) * (1 + CLUMP_TOUCH_TOL)) {
                m[q] = m[nseen], m[nseen++] = j; /* reorders m: callers only use it as a set */
                stack[top++] = j;
            }
        }
    }
    return nseen == k;
}

int layer_bodies_check(int n, const double *x, const double *y, const double *r, const int *body,
                       const char *what, int status, gw_err *err)
{
    if (!body)
        return GW_OK;
    for (int i = 0; i < n; i++)
        if (body[i] < 0 || body[i] >= n)
            return gw_err_set(err, status, "%s: particle at index %d: body id %d outside [0, %d)", what,
                              i, body[i], n);
    layer_clump_key *k = malloc((size_t)n * sizeof *k);
    int *m = malloc(2 * (size_t)n * sizeof *m);
    if (!k || !m) {
        free(k), free(m);
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory checking %d body ids", what, n);
    }
    for (int i = 0; i < n; i++)
        k[i] = (layer_clump_key){body[i], i};
    qsort(k, (size_t)n, sizeof *k, layer_clump_key_cmp);
    int rc = GW_OK;
    for (int a = 0; a < n && rc == GW_OK;) {
        int b = a;
        while (b < n && k[b].clump == k[a].clump)
            m[b - a] = k[b].i, b++;
        if (b - a > LAYER_CLUMP_MEMBERS)
            rc = gw_err_set(err, status, "%s: body %d has %d particles (at most %d per clump)", what,
                            k[a].clump, b - a, LAYER_CLUMP_MEMBERS);
        else if (b - a > 1 && !layer_members_connected(x, y, r, m, b - a, m + n))
            rc = gw_err_set(err, status, "%s: body %d: its %d particles do not overlap or touch as "
                            "one rigid clump (first at index %d)", what, k[a].clump, b - a, k[a].i);
        a = b;
    }
    free(k), free(m);
    return rc;
}

const char *gw_layer_clump_mass_name(int clump_mass)
{
    return clump_mass == GW_LAYER_CLUMP_MASS_UNION ? "union" : "sum";
}

int gw_layer_clump_mass_parse(const char *name)
{
    for (int c = GW_LAYER_CLUMP_MASS_SUM; c <= GW_LAYER_CLUMP_MASS_UNION; c++)
        if (strcmp(name, gw_layer_clump_mass_name(c)) == 0)
            return c;
    return -1;
}

/* A sample's discs may overlap by what settling leaves (a pluviated sample:
 * 0.002 R_p, 0.006 R_p at most in the stored ones; a softer settling modulus
 * more): above SAMPLE_OVERLAP_MAX R_p (R_p = 2 R_a R_b / (R_a + R_b)) the first
 * step's Hertz force would throw the discs apart and inject energy, so such a
 * sample is refused when read (layer_sample.c). Discs of one clump overlap by
 * construction. */
#define SAMPLE_OVERLAP_MAX 0.05

typedef struct xi {
    double x;
    int i;
} xi;

static int by_x(const void *a, const void *b)
{
    const double xa = ((const xi *)a)->x, xb = ((const xi *)b)->x;
    return (xa > xb) - (xa < xb);
}

/* Pairs found by a sweep over x (each disc against the discs within its radius
 * plus the largest radius to its right): O(n log n) for a packing. */
int layer_overlaps_check(int n, const double *x, const double *y, const double *r, const int *body,
                         const char *what, gw_err *err)
{
    xi *ix = malloc((size_t)n * sizeof *ix);
    if (!ix)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory for the overlap check", what);
    double rmax = 0;
    for (int i = 0; i < n; i++) {
        ix[i] = (xi){x[i], i};
        rmax = fmax(rmax, r[i]);
    }
    qsort(ix, (size_t)n, sizeof *ix, by_x);
    int rc = GW_OK;
    for (int a = 0; a < n && rc == GW_OK; a++) {
        const int i = ix[a].i;
        for (int b = a + 1; b < n && ix[b].x - x[i] <= r[i] + rmax; b++) {
            const int j = ix[b].i;
            if (body && body[i] == body[j])
                continue;
            const double d = hypot(x[j] - x[i], y[j] - y[i]), ov = r[i] + r[j] - d;
            const double rp = 2 * r[i] * r[j] / (r[i] + r[j]);
            if (ov > SAMPLE_OVERLAP_MAX * rp) {
                rc = gw_err_set(err, GW_EFORMAT, "%s: particles %d and %d overlap by %.3g R_p, above %g R_p "
                                "(a settled sample: about 0.002): their contact would inject energy",
                                what, i < j ? i : j, i < j ? j : i, ov / rp, SAMPLE_OVERLAP_MAX);
                break;
            }
        }
    }
    free(ix);
    return rc;
}
