/*
 * layer_sample_porosity.c: the porosity of a layer sample (docs/physics.md
 * 2.2), 1 - A / (w_x w_y), A the area of the union of the discs within the
 * window x in [x0, x1] = [0.1, 0.9] W, y in [y0, y1] = [0.1, 0.8] h,
 * h = max(y + r) (the wall and free-surface layers are excluded).
 *
 * A is computed exactly (to rounding), by Green's theorem: A = closed integral
 * of x dy along the boundary of (union of discs) ∩ window, traversed
 * counter-clockwise. That boundary is made of
 *  - the arcs of each circle that lie inside the window and inside no other
 *    disc: on the arc theta in [a, b] of the circle (xi, yi, r), with x
 *    measured from the window's centre xc,
 *      integral x dy = (xi - xc) r (sin b - sin a) + r^2 / 2 (b - a + (sin 2b - sin 2a) / 2);
 *  - the covered parts of the window's edges: the right edge, run upwards,
 *    gives (x1 - xc) L_right, the left one, run downwards, -(x0 - xc) L_left
 *    (L: their lengths covered by the union of the discs' chords), the
 *    horizontal edges nothing (dy = 0).
 * A circle's arc inside another disc j at distance d is the angle
 * 2 acos((d^2 + r^2 - r_j^2) / (2 d r)) about the direction to j; a circle
 * inside another (d <= r_j - r) has no boundary arc (of two equal coincident
 * circles, the later one). The window cuts the arc where x > x1, about
 * theta = 0, of half-angle acos((x1 - xi) / r), and likewise at the other
 * three sides.
 *
 * Unlike a sampling grid (600 x 600 points until the twenty-first session,
 * which aliased on regular lattices of small particles: a 1000 x 1000 square
 * lattice of porosity 0.217 read 0.333), the value does not depend on how the
 * particles line up with anything. The neighbours come from the grid of cells
 * of side 2 R_max that the overlap check of every read sample builds
 * (layer_grid_build, layer_clump_check.c), each disc against the discs of the
 * 3 x 3 cells around its own: the same pairs, so the cost is of that check's
 * order (O(n) for a packing of like discs; 0.14 ms on the 300-disc sample,
 * the grid took 0.37 ms).
 * Units: SI (m, m^2); the porosity is a fraction, in [0, 1].
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"

#define TWO_PI (2 * M_PI)

typedef struct arc_set {
    double *lo, *hi; /* excluded angle intervals, in [0, 2 pi] */
    int n, cap, all; /* all: the whole circle is excluded */
} arc_set;

static int arcs_push(arc_set *s, double lo, double hi)
{
    if (s->n == s->cap) {
        const int cap = s->cap ? 2 * s->cap : 32;
        double *l = realloc(s->lo, (size_t)cap * sizeof *l);
        if (!l)
            return GW_ENOMEM;
        s->lo = l;
        double *h = realloc(s->hi, (size_t)cap * sizeof *h);
        if (!h)
            return GW_ENOMEM;
        s->hi = h, s->cap = cap;
    }
    s->lo[s->n] = lo, s->hi[s->n] = hi, s->n++;
    return GW_OK;
}

/* Exclude the arc centred on angle c of half-angle phi (>= pi: all of it),
 * split at 0 = 2 pi when it wraps. */
static int arcs_exclude(arc_set *s, double c, double phi)
{
    if (!(phi < M_PI)) {
        s->all = 1;
        return GW_OK;
    }
    if (!(phi > 0))
        return GW_OK;
    double lo = fmod(c - phi, TWO_PI);
    if (lo < 0)
        lo += TWO_PI;
    const double hi = lo + 2 * phi;
    if (hi <= TWO_PI)
        return arcs_push(s, lo, hi);
    int rc = arcs_push(s, lo, TWO_PI);
    return rc == GW_OK ? arcs_push(s, 0, hi - TWO_PI) : rc;
}

/* Half-angle of the arc of a circle of radius r beyond a line at distance
 * t from its centre (t >= r: none, t <= -r: all of it). */
static double beyond(double t, double r)
{
    const double c = t / r;
    return c >= 1 ? 0 : c <= -1 ? M_PI : acos(c);
}

static int cmp_lo(const void *pa, const void *pb)
{
    const double a = *(const double *)pa, b = *(const double *)pb;
    return (a > b) - (a < b);
}

/* The integral of x dy over the arcs of circle (xc, r) not excluded by s
 * (x measured from the window's centre). The intervals are sorted by their
 * start (as pairs, in one scratch array of 2 n). */
static double arcs_integral(arc_set *s, double *pairs, double xi, double r)
{
    if (s->all)
        return 0;
    for (int k = 0; k < s->n; k++)
        pairs[2 * k] = s->lo[k], pairs[2 * k + 1] = s->hi[k];
    qsort(pairs, (size_t)s->n, 2 * sizeof *pairs, cmp_lo);
    double sum = 0, at = 0; /* at: the end of the excluded angles so far */
    for (int k = 0; k <= s->n; k++) {
        const double lo = k < s->n ? pairs[2 * k] : TWO_PI;
        if (lo > at)
            sum += xi * r * (sin(lo) - sin(at)) + r * r / 2 * (lo - at + (sin(2 * lo) - sin(2 * at)) / 2);
        if (k < s->n)
            at = fmax(at, pairs[2 * k + 1]);
    }
    return sum;
}

/* The length of the window's vertical edge x = e, y in [y0, y1], that the
 * discs cover (the union of their chords); scratch: 2 m doubles. */
static double edge_covered(const double *x, const double *y, const double *r, const int *in, int m, double e,
                           double y0, double y1, double *scratch)
{
    int k = 0;
    for (int q = 0; q < m; q++) {
        const int i = in[q];
        const double t = x[i] - e;
        if (!(fabs(t) < r[i]))
            continue;
        const double c = sqrt((r[i] - t) * (r[i] + t));
        const double lo = fmax(y[i] - c, y0), hi = fmin(y[i] + c, y1);
        if (lo < hi)
            scratch[2 * k] = lo, scratch[2 * k + 1] = hi, k++;
    }
    qsort(scratch, (size_t)k, 2 * sizeof *scratch, cmp_lo);
    double len = 0, a = y0, b = y0; /* the current run [a, b] */
    for (int q = 0; q < k; q++) {
        if (scratch[2 * q] > b)
            len += b - a, a = scratch[2 * q], b = scratch[2 * q];
        b = fmax(b, scratch[2 * q + 1]);
    }
    return len + (b - a);
}

/* Exclude from circle i the arcs outside the window and inside its
 * neighbours (the discs in the 3 x 3 cells around its own). */
static int circle_arcs(const double *x, const double *y, const double *r, const int *in, const layer_grid *g,
                       int q, const double win[4], arc_set *s)
{
    const int i = in[q];
    const double xi = x[i], yi = y[i], ri = r[i];
    int rc = arcs_exclude(s, 0, beyond(win[1] - xi, ri));
    if (rc == GW_OK)
        rc = arcs_exclude(s, M_PI, beyond(xi - win[0], ri));
    if (rc == GW_OK)
        rc = arcs_exclude(s, M_PI / 2, beyond(win[3] - yi, ri));
    if (rc == GW_OK)
        rc = arcs_exclude(s, 1.5 * M_PI, beyond(yi - win[2], ri));
    const long cx = g->cell[q] % g->nx, cy = g->cell[q] / g->nx;
    for (long ky = cy - 1; ky <= cy + 1 && rc == GW_OK && !s->all; ky++)
        for (long kx = cx - 1; kx <= cx + 1 && rc == GW_OK && !s->all; kx++) {
            if (ky < 0 || ky >= g->ny || kx < 0 || kx >= g->nx)
                continue;
            const long kc = ky * g->nx + kx;
            for (int p = g->start[kc]; p < g->start[kc + 1] && rc == GW_OK && !s->all; p++) {
                const int j = in[g->idx[p]];
                if (j == i)
                    continue;
                const double dx = x[j] - xi, dy = y[j] - yi, rj = r[j], d = hypot(dx, dy);
                if (d >= ri + rj || (d <= ri - rj && !(d == 0 && ri == rj)))
                    continue; /* apart, or j inside i */
                if (d <= rj - ri) { /* i inside j; of two equal coincident circles, the later one */
                    s->all = ri < rj || d > 0 || g->idx[p] < q;
                    continue;
                }
                const double c = (d * d + ri * ri - rj * rj) / (2 * d * ri);
                rc = arcs_exclude(s, atan2(dy, dx), acos(fmax(-1, fmin(1, c))));
            }
        }
    return rc;
}

double gw_layer_sample_porosity(const gw_layer_sample *s)
{
    /* a sample counted without its arrays (filled by hand): NaN, not a NULL
     * read; and any sample the reader would refuse (before session 43 a disc
     * outside the box, or two discs at one place, gave a number) */
    if (!s || layer_sample_limits_check(s, "s", GW_EINVAL, NULL) != GW_OK)
        return NAN;
    return layer_sample_porosity_of(s);
}

int layer_sample_window_empty(const gw_layer_sample *s)
{
    if (!s || s->n < 0 || (s->n > 0 && (!s->x || !s->y || !s->r)))
        return 0;
    double h = 0;
    for (int i = 0; i < s->n; i++)
        h = fmax(h, s->y[i] + s->r[i]);
    const double x0 = 0.1 * s->width, x1 = 0.9 * s->width, y0 = 0.1 * h, y1 = 0.8 * h;
    if (!(x1 > x0) || !(y1 > y0))
        return 0;
    for (int i = 0; i < s->n; i++) /* as layer_sample_porosity_of picks the discs */
        if (s->x[i] + s->r[i] > x0 && s->x[i] - s->r[i] < x1 && s->y[i] + s->r[i] > y0 && s->y[i] - s->r[i] < y1)
            return 0;
    return 1;
}

double layer_sample_porosity_of(const gw_layer_sample *s)
{
    if (!s || s->n < 0 || (s->n > 0 && (!s->x || !s->y || !s->r)))
        return NAN;
    double h = 0;
    for (int i = 0; i < s->n; i++) {
        /* a disc of a NaN or infinite coordinate or a radius not > 0 is no
         * disc: it fell out of the window's test and the porosity of the
         * others was given (a NaN x of 3 discs: 0.548 for 0.322) */
        if (!isfinite(s->x[i]) || !isfinite(s->y[i]) || !isfinite(s->r[i]) || !(s->r[i] > 0))
            return NAN;
        h = fmax(h, s->y[i] + s->r[i]);
    }
    const double x0 = 0.1 * s->width, x1 = 0.9 * s->width, y0 = 0.1 * h, y1 = 0.8 * h;
    const double win[4] = {x0, x1, y0, y1}, xc = (x0 + x1) / 2, area = (x1 - x0) * (y1 - y0);
    if (!(x1 > x0) || !(y1 > y0) || !isfinite(area) || !(area > 0))
        return NAN;
    /* the discs that reach into the window, their centres (x, y) in pairs for the grid */
    int m = 0, *in = malloc((size_t)s->n * sizeof *in);
    double *c = malloc(2 * (size_t)s->n * sizeof *c), rmax = 0;
    if (!in || !c) {
        free(in), free(c);
        return NAN;
    }
    for (int i = 0; i < s->n; i++) {
        const double xi = s->x[i], yi = s->y[i], ri = s->r[i];
        if (xi + ri > x0 && xi - ri < x1 && yi + ri > y0 && yi - ri < y1) {
            in[m] = i, c[2 * m] = xi, c[2 * m + 1] = yi, m++;
            rmax = fmax(rmax, ri);
        }
    }
    /* no disc reaches into the window (layer-make --n 1: the disc off the
     * window's middle 80 % of the width): nothing measured, NaN (it read 1,
     * a pile of nothing, in --json, the text and the sample's header) */
    if (m == 0) {
        free(in), free(c);
        return NAN;
    }
    layer_grid g;
    int rc = layer_grid_build(&g, m, c, c + 1, 2, 2 * rmax);
    free(c);
    double *scratch = malloc(2 * (size_t)m * sizeof *scratch);
    if (rc != GW_OK || !scratch) {
        if (rc == GW_OK)
            layer_grid_free(&g);
        free(in), free(scratch);
        return NAN;
    }
    arc_set a = {0};
    double sum = 0;
    for (int q = 0; q < m && rc == GW_OK; q++) {
        a.n = 0, a.all = 0;
        rc = circle_arcs(s->x, s->y, s->r, in, &g, q, win, &a);
        double *pairs = scratch;
        if (rc == GW_OK && 2 * a.n > 2 * m && !(pairs = malloc(2 * (size_t)a.n * sizeof *pairs)))
            rc = GW_ENOMEM;
        if (rc == GW_OK)
            sum += arcs_integral(&a, pairs, s->x[in[q]] - xc, s->r[in[q]]);
        if (pairs != scratch)
            free(pairs);
    }
    if (rc == GW_OK)
        sum += (x1 - xc) * edge_covered(s->x, s->y, s->r, in, m, x1, y0, y1, scratch) -
               (x0 - xc) * edge_covered(s->x, s->y, s->r, in, m, x0, y0, y1, scratch);
    layer_grid_free(&g);
    free(in), free(scratch), free(a.lo), free(a.hi);
    if (rc != GW_OK || !isfinite(sum))
        return NAN;
    const double p = 1 - sum / area;
    return p < 0 ? 0 : p > 1 ? 1 : p;
}
