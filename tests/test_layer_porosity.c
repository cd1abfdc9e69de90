/*
 * test_layer_porosity.c: gw_layer_sample_porosity (layer_sample_porosity.c),
 * 1 - A / |W|, A the area of the union of the discs within the window W =
 * [0.1, 0.9] width x [0.1, 0.8] h, h = max(y + r), against references computed
 * here another way:
 *
 *  1. Lattices of discs that do not overlap (square and hexagonal, 10 to 1000
 *     columns, spacing 2 r + gap), where A is the sum over the discs of
 *     |disc ∩ W|, each from the closed form of a disc cut by a quadrant
 *     (inclusion-exclusion over the window's corners). Tolerance 1e-10: the
 *     two are exact up to rounding (sums of 1e6 terms of 1e-16 relative
 *     error). Also against the lattice's own porosity 1 - pi r^2 / cell,
 *     within the window's edge effect: a window that cuts the lattice
 *     anywhere differs from it by at most the area of the cells it crosses,
 *     2 (w + h) (2 a) / (w h) for cells of diameter a = spacing x sqrt(2)
 *     (at most 0.4% for 300 columns, 0.12% for 1000). The grid of before
 *     read a 1000 x 1000 square lattice of porosity 0.217 as 0.333.
 *  2. Random samples of overlapping discs (1 to 60, radii spanning 100,
 *     coincident pairs, discs inside others, discs across the window's edges
 *     and larger than it): against stratified sampling, one random point in
 *     each cell of a 1500 x 1500 grid. Its error has standard deviation at
 *     most sqrt(N_b) / 2 cells, N_b the cells the union's boundary crosses,
 *     at most the sum over the circles of (4 perimeter / cell side + 4) plus
 *     that of the window: tolerance 6 of those.
 *  3. The stored 300-disc sample (data/measured/layer_diagram_8000): discs
 *     that touch with overlaps of about 0.002 R, no three sharing a point, so
 *     that A = sum |disc ∩ W| less the pairwise lenses, up to the lenses of
 *     pairs cut by the window's edges (the tolerance, with 1e-12); and its
 *     header (layer-make's porosity, on the 600 x 600 grid) within the
 *     reader's 2e-3.
 * Before the exact area (the 600 x 600 grid) lattices alias and the grid's
 * sampling error (up to 5e-4) is above the tolerances of 2 and 3.
 * 1 and 2 measure the union's area of any discs (layer_sample_porosity_of,
 * which gw_layer_sample_porosity runs once the sample passes the limits
 * every sample is held to: overlapping discs and a sample without rm are no
 * sample, NaN since session 43); 3 the public call.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "gw_layer.h"
#include "layer_impl.h" /* layer_sample_porosity_of: the union's area of any discs */
#include "gw_test.h"

#ifndef GW_SOURCE_DIR
#define GW_SOURCE_DIR "."
#endif

static double uniform(uint64_t *st)
{
    return (double)(gw_test_xorshift(st) >> 11) / 9007199254740992.0;
}

/* integral of sqrt(r^2 - y^2) over [-r, y] */
static double half_chord_int(double y, double r)
{
    y = fmax(-r, fmin(r, y));
    return (y * sqrt(fmax(0, r * r - y * y)) + r * r * asin(y / r)) / 2 + M_PI * r * r / 4;
}

/* |{x < a, y < b} ∩ disc(0, 0, r)| by integrating over y the chord's part left of a */
static double quadrant(double a, double b, double r)
{
    const double bb = fmin(b, r);
    if (bb <= -r || a <= -r)
        return 0;
    if (a >= r)
        return 2 * half_chord_int(bb, r);
    const double ys = sqrt(r * r - a * a);
    double s = 0; /* |y| >= ys: chord [-c, c] wholly left of a (a > 0) or wholly right (a < 0) */
    if (a > 0) {
        s += 2 * half_chord_int(fmin(bb, -ys), r);
        if (bb > ys)
            s += 2 * (half_chord_int(bb, r) - half_chord_int(ys, r));
    }
    if (bb > -ys) { /* |y| < ys: the chord from -c to a */
        const double top = fmin(bb, ys);
        s += a * (top + ys) + half_chord_int(top, r) - half_chord_int(-ys, r);
    }
    return s;
}

/* |disc ∩ [x0, x1] x [y0, y1]| */
static double disc_in_box(double xc, double yc, double r, double x0, double x1, double y0, double y1)
{
    if (xc - r >= x0 && xc + r <= x1 && yc - r >= y0 && yc + r <= y1)
        return M_PI * r * r;
    return quadrant(x1 - xc, y1 - yc, r) - quadrant(x0 - xc, y1 - yc, r) - quadrant(x1 - xc, y0 - yc, r) +
           quadrant(x0 - xc, y0 - yc, r);
}

static void window(const gw_layer_sample *s, double w[4])
{
    double h = 0;
    for (int i = 0; i < s->n; i++)
        h = fmax(h, s->y[i] + s->r[i]);
    w[0] = 0.1 * s->width, w[1] = 0.9 * s->width, w[2] = 0.1 * h, w[3] = 0.8 * h;
}

/* 1 - sum |disc ∩ W| / |W|: the porosity of discs that do not overlap */
static double porosity_apart(const gw_layer_sample *s)
{
    double w[4], a = 0;
    window(s, w);
    for (int i = 0; i < s->n; i++)
        a += disc_in_box(s->x[i], s->y[i], s->r[i], w[0], w[1], w[2], w[3]);
    return 1 - a / ((w[1] - w[0]) * (w[3] - w[2]));
}

/* A lattice of nc columns and rows (hex: rows shifted by half a spacing,
 * sqrt(3)/2 apart), radius r, spacing d; returns the lattice's porosity. */
static double lattice(gw_layer_sample *s, int nc, int hex, double r, double d)
{
    const double dy = hex ? d * sqrt(3) / 2 : d;
    s->n = nc * nc, s->width = nc * d + (hex ? d / 2 : 0);
    for (int j = 0; j < nc; j++)
        for (int i = 0; i < nc; i++) {
            const int k = j * nc + i;
            s->x[k] = d / 2 + i * d + (hex && j % 2 ? d / 2 : 0);
            s->y[k] = r + 1e-4 * r + j * dy, s->r[k] = r;
        }
    return 1 - M_PI * r * r / (d * dy);
}

static double lens(double d, double r1, double r2)
{
    if (d >= r1 + r2)
        return 0;
    if (d <= fabs(r1 - r2))
        return M_PI * fmin(r1, r2) * fmin(r1, r2);
    const double a1 = acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1));
    const double a2 = acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2));
    return r1 * r1 * (a1 - sin(2 * a1) / 2) + r2 * r2 * (a2 - sin(2 * a2) / 2);
}

/* Stratified sampling of the union over W, G x G cells; *tol: 6 times the
 * bound of its standard deviation (see the file's comment). */
static double porosity_sampled(const gw_layer_sample *s, int G, uint64_t *st, double *tol)
{
    double w[4];
    window(s, w);
    const double dx = (w[1] - w[0]) / G, dy = (w[3] - w[2]) / G, cs = fmax(dx, dy);
    float *off = malloc(2 * (size_t)G * G * sizeof *off); /* each cell's point, in cells */
    unsigned char *cov = calloc((size_t)G * G, 1);
    if (!off || !cov) {
        free(off), free(cov);
        *tol = 0;
        return NAN;
    }
    for (size_t q = 0; q < 2 * (size_t)G * G; q++)
        off[q] = (float)uniform(st);
    for (int i = 0; i < s->n; i++) { /* the cells of each disc's bounding box */
        const double r = s->r[i];
        const int ka = (int)fmax(0, floor((s->x[i] - r - w[0]) / dx)), kb = (int)fmin(G - 1, floor((s->x[i] + r - w[0]) / dx));
        const int ja = (int)fmax(0, floor((s->y[i] - r - w[2]) / dy)), jb = (int)fmin(G - 1, floor((s->y[i] + r - w[2]) / dy));
        for (int j = ja; j <= jb; j++)
            for (int k = ka; k <= kb; k++) {
                const size_t q = (size_t)j * G + k;
                const double ex = w[0] + (k + off[2 * q]) * dx - s->x[i], ey = w[2] + (j + off[2 * q + 1]) * dy - s->y[i];
                cov[q] |= ex * ex + ey * ey <= r * r;
            }
    }
    long hit = 0;
    for (size_t q = 0; q < (size_t)G * G; q++)
        hit += cov[q];
    free(off), free(cov);
    double nb = 2 * 2 * ((w[1] - w[0]) + (w[3] - w[2])) / cs + 4;
    for (int i = 0; i < s->n; i++)
        nb += 2 * 2 * M_PI * s->r[i] / cs + 4;
    *tol = 6 * sqrt(nb) / 2 / ((double)G * G);
    return 1 - (double)hit / ((double)G * G);
}

static void lattices(double *b, int cap)
{
    const int cols[] = {10, 37, 100, 300, 1000};
    int fine = 0, cases = 0, near = 0;
    for (int c = 0; c < 5; c++)
        for (int hex = 0; hex <= 1; hex++)
            for (int g = 0; g < 2; g++) {
                const int nc = cols[c];
                if (nc * nc > cap)
                    continue;
                const double r = 0.325, d = 2 * r * (g ? 1.05 : 1.0005);
                gw_layer_sample s = {.x = b, .y = b + cap, .r = b + 2 * (size_t)cap};
                const double bulk = lattice(&s, nc, hex, r, d);
                const double p = layer_sample_porosity_of(&s), ref = porosity_apart(&s);
                double w[4];
                window(&s, w);
                const double ww = w[1] - w[0], wh = w[3] - w[2], edge = 2 * (ww + wh) * 2 * d * sqrt(2) / (ww * wh);
                cases++;
                fine += fabs(p - ref) <= 1e-10;
                near += fabs(p - bulk) <= edge;
                if (fabs(p - ref) > 1e-10 || fabs(p - bulk) > edge)
                    printf("  %s lattice %d x %d, spacing %.4g r: %.10f, clipped discs %.10f, lattice %.6f "
                           "(edge effect <= %.2g)\n", hex ? "hexagonal" : "square", nc, nc, d / r, p, ref, bulk, edge);
                if (nc == 1000 && !hex && g == 0)
                    gw_test_abs(p, bulk, 2e-3, "square lattice 1000 x 1000: its porosity 1 - pi r^2 / d^2, within 2e-3 "
                                "(the grid of before: 0.333)");
            }
    char what[160];
    snprintf(what, sizeof what, "%d lattices (square, hexagonal; 10 to 1000 columns): the sum of the clipped discs' "
             "areas within 1e-10", cases);
    gw_test_true(fine == cases, what);
    snprintf(what, sizeof what, "%d lattices: the lattice's porosity within the window's edge effect", cases);
    gw_test_true(near == cases, what);
}

static void random_unions(double *b, uint64_t *st)
{
    int ok = 0, cases = 0, empties = 0;
    for (int c = 0; c < 60; c++) {
        gw_layer_sample s = {.width = 1 + 5 * uniform(st), .x = b, .y = b + 100, .r = b + 200};
        s.n = 1 + (int)(60 * uniform(st));
        const double rlo = s.width * (c % 3 == 0 ? 0.05 : 0.01), span = pow(100, uniform(st));
        for (int i = 0; i < s.n; i++) {
            s.r[i] = rlo * pow(span, uniform(st));
            s.x[i] = s.width * uniform(st), s.y[i] = s.width * uniform(st);
            if (i > 0 && uniform(st) < 0.1) /* a coincident copy, or a disc inside another */
                s.x[i] = s.x[i - 1], s.y[i] = s.y[i - 1], s.r[i] = s.r[i - 1] * (uniform(st) < 0.5 ? 1 : 0.5);
        }
        double tol;
        const double p = layer_sample_porosity_of(&s), ref = porosity_sampled(&s, 2500, st, &tol);
        /* a window that holds no disc measures nothing: NaN (1 before the
         * forty-sixth session, layer-make --n 1's "porosity 1") */
        double w[4];
        window(&s, w);
        int empty = 1;
        for (int i = 0; i < s.n; i++)
            empty &= !(s.x[i] + s.r[i] > w[0] && s.x[i] - s.r[i] < w[1] && s.y[i] + s.r[i] > w[2] &&
                       s.y[i] - s.r[i] < w[3]);
        cases++;
        empties += empty;
        ok += empty ? isnan(p) && ref == 1 : fabs(p - ref) <= tol;
        if (getenv("GW_TEST_VERBOSE"))
            printf("  random %d n %d diff %.3g tol %.3g\n", c, s.n, p - ref, tol);
        if (fabs(p - ref) > tol)
            printf("  random sample %d (n = %d): %.8f, sampled %.8f (tolerance %.2g)\n", c, s.n, p, ref, tol);
    }
    gw_test_true(ok == cases, "60 random samples of overlapping discs: the stratified sampling's value within 6 "
                 "bounds of its deviation (NaN where the window holds no disc)");
    gw_test_true(empties > 0 && empties < cases, "the random samples include windows that hold no disc");
}

static void stored_sample(void)
{
    const char *path = GW_SOURCE_DIR "/data/measured/layer_diagram_8000/sample.txt";
    gw_layer_sample s;
    gw_err err = {{0}};
    if (gw_layer_sample_read(path, &s, &err) != GW_OK) {
        gw_test_true(0, err.msg);
        return;
    }
    double w[4], a = 0, cut = 0;
    window(&s, w);
    for (int i = 0; i < s.n; i++) {
        a += disc_in_box(s.x[i], s.y[i], s.r[i], w[0], w[1], w[2], w[3]);
        const int ci = disc_in_box(s.x[i], s.y[i], s.r[i], w[0], w[1], w[2], w[3]) != M_PI * s.r[i] * s.r[i];
        for (int j = 0; j < i; j++) {
            const double l = lens(hypot(s.x[i] - s.x[j], s.y[i] - s.y[j]), s.r[i], s.r[j]);
            const int cj = disc_in_box(s.x[j], s.y[j], s.r[j], w[0], w[1], w[2], w[3]) != M_PI * s.r[j] * s.r[j];
            const int inside = disc_in_box(s.x[j], s.y[j], s.r[j], w[0], w[1], w[2], w[3]) > 0 &&
                               disc_in_box(s.x[i], s.y[i], s.r[i], w[0], w[1], w[2], w[3]) > 0;
            if (ci || cj)
                cut += l;
            else if (inside)
                a -= l;
        }
    }
    const double area = (w[1] - w[0]) * (w[3] - w[2]), ref = 1 - a / area, tol = cut / area + 1e-12;
    const double p = gw_layer_sample_porosity(&s);
    printf("  %s: %.12f, discs less lenses %.12f (tolerance %.2g), header %.6f\n", path, p, ref, tol, s.porosity);
    gw_test_abs(p, ref, tol, "the stored 300-disc sample: its discs' clipped areas less their lenses");
    gw_test_abs(p, s.porosity, 2e-3, "the stored 300-disc sample: its header's porosity within the reader's 2e-3");
    gw_layer_sample_free(&s);
}

int main(void)
{
    uint64_t st = 0x9e3779b97f4a7c15ull;
    const int cap = 1000 * 1000;
    double *b = malloc(3 * (size_t)cap * sizeof *b);
    if (!b)
        return 1;
    lattices(b, cap);
    random_unions(b, &st);
    stored_sample();
    free(b);
    return gw_test_summary("test_layer_porosity");
}
