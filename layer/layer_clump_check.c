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

int layer_particle_check(const gw_layer_body *b, int i, int walls, double width, const char *what, gw_err *err)
{
    static const char *const name[6] = {"x", "y", "r", "vx", "vy", "w"};
    static const char *const unit[6] = {"m", "m", "m", "m/s", "m/s", "rad/s"};
    const double v[6] = {b->x, b->y, b->r, b->vx, b->vy, b->w};
    for (int k = 0; k < 6; k++)
        if (!isfinite(v[k]))
            return gw_err_set(err, GW_EINVAL, "%s %d: %s = %g %s is not a finite number", what, i, name[k], v[k],
                              unit[k]);
    if (!(b->r > 0))
        return gw_err_set(err, GW_EINVAL, "%s %d: radius r = %g m must be positive", what, i, b->r);
    if (((walls & GW_LAYER_WALL_LEFT) && b->x < 0) || ((walls & GW_LAYER_WALL_RIGHT) && b->x > width) ||
        ((walls & GW_LAYER_WALL_BOTTOM) && b->y < 0))
        return gw_err_set(err, GW_EINVAL, "%s %d: centre (%g, %g) m outside the walls (0 <= x <= %g, y >= 0)", what,
                          i, b->x, b->y, width);
    return GW_OK;
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
    return clump_mass == GW_LAYER_CLUMP_MASS_UNION ? "union" : clump_mass == GW_LAYER_CLUMP_MASS_SUM ? "sum"
                                                                                                 : "unknown";
}

int gw_layer_clump_mass_parse(const char *name)
{
    if (!name) /* no such rule */
        return -1;
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

/* See layer_impl.h (here beside the overlap check, its first user, which the
 * sample readers' fuzz target builds without the rest of the layer). */
int layer_grid_build(layer_grid *g, int n, const double *px, const double *py, int stride, double h)
{
    memset(g, 0, sizeof *g);
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int i = 0; i < n; i++) {
        const double xi = px[(size_t)i * stride], yi = py[(size_t)i * stride];
        x0 = fmin(x0, xi), x1 = fmax(x1, xi);
        y0 = fmin(y0, yi), y1 = fmax(y1, yi);
    }
    /* a particle far away (a block thrown high) must not blow up the grid:
     * coarsen the cells until their number is linear in n (pairs stay exact);
     * counted in doubles, so that no extent overflows an integer */
    const double ex = x1 - x0, ey = y1 - y0;
    if (n < 1 || !isfinite(ex) || !isfinite(ey) || !(h > 0))
        return GW_ELIMIT;
    const double maxc = 16.0 * n + 64;
    while ((ex / h + 1) * (ey / h + 1) > maxc)
        h *= 2;
    const long nx = (long)(ex / h) + 1, ny = (long)(ey / h) + 1, ncell = nx * ny;
    g->nx = nx, g->ny = ny;
    g->start = calloc((size_t)ncell + 1, sizeof *g->start);
    g->idx = malloc((size_t)n * sizeof *g->idx);
    g->cell = malloc((size_t)n * sizeof *g->cell);
    int *fill = malloc((size_t)ncell * sizeof *fill);
    if (!g->start || !g->idx || !g->cell || !fill) {
        free(fill);
        layer_grid_free(g);
        return GW_ENOMEM;
    }
    for (int i = 0; i < n; i++) {
        long cx = (long)((px[(size_t)i * stride] - x0) / h), cy = (long)((py[(size_t)i * stride] - y0) / h);
        cx = cx < 0 ? 0 : cx >= nx ? nx - 1 : cx;
        cy = cy < 0 ? 0 : cy >= ny ? ny - 1 : cy;
        g->cell[i] = (int)(cy * nx + cx);
        g->start[g->cell[i] + 1]++;
    }
    for (long k = 0; k < ncell; k++)
        g->start[k + 1] += g->start[k];
    memcpy(fill, g->start, (size_t)ncell * sizeof *fill);
    for (int i = 0; i < n; i++)
        g->idx[fill[g->cell[i]]++] = i;
    free(fill);
    return GW_OK;
}

void layer_grid_free(layer_grid *g)
{
    free(g->start), free(g->idx), free(g->cell);
    memset(g, 0, sizeof *g);
}

/* Pairs found on a grid of square cells of side 2 R_max (an overlapping pair
 * lies in neighbouring cells), coarsened until the cells are at most 16 n + 64,
 * each disc against the discs of the 3 x 3 cells around its own: O(n) for a
 * packing of like discs whatever its shape. (A sweep over x was quadratic in
 * the discs of one column: a sample one disc wide and 1e5 high took 23 s, 1e6
 * would take about 40 min.) Reports the first pair (i, j), i < j, in index
 * order, so the message does not depend on the grid. */
int layer_overlaps_check(int n, const double *x, const double *y, const double *r, const int *body,
                         const char *what, gw_err *err)
{
    if (n < 2)
        return GW_OK;
    double rmax = 0;
    for (int i = 0; i < n; i++)
        rmax = fmax(rmax, r[i]);
    layer_grid g; /* positions finite: the readers check every one first */
    int rc = layer_grid_build(&g, n, x, y, 1, 2 * rmax);
    if (rc == GW_ENOMEM)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory for the overlap check", what);
    if (rc != GW_OK)
        return gw_err_set(err, GW_EFORMAT, "%s: positions or radii not finite and positive", what);
    const long nx = g.nx, ny = g.ny;
    const int *start = g.start, *idx = g.idx, *cell = g.cell;
    for (int i = 0; i < n && rc == GW_OK; i++) {
        const long cx = cell[i] % nx, cy = cell[i] / nx;
        int first = -1;
        double worst = 0, rpw = 0;
        for (long ky = cy - 1; ky <= cy + 1; ky++)
            for (long kx = cx - 1; kx <= cx + 1; kx++) {
                if (ky < 0 || ky >= ny || kx < 0 || kx >= nx)
                    continue;
                const long kc = ky * nx + kx;
                for (int q = start[kc]; q < start[kc + 1]; q++) {
                    const int j = idx[q];
                    if (j <= i || (first >= 0 && j > first) || (body && body[i] == body[j]))
                        continue;
                    const double d = hypot(x[j] - x[i], y[j] - y[i]), ov = r[i] + r[j] - d;
                    const double rp = 2 * r[i] * r[j] / (r[i] + r[j]);
                    if (ov > SAMPLE_OVERLAP_MAX * rp)
                        first = j, worst = ov, rpw = rp;
                }
            }
        if (first >= 0)
            rc = gw_err_set(err, GW_EFORMAT, "%s: particles %d and %d overlap by %.3g R_p, above %g R_p "
                            "(a settled sample: about 0.002): their contact would inject energy",
                            what, i, first, worst / rpw, SAMPLE_OVERLAP_MAX);
    }
    layer_grid_free(&g);
    return rc;
}
