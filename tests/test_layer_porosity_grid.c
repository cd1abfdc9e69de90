/*
 * test_layer_porosity_grid.c: gw_layer_sample_porosity (layer_sample_porosity.c) marks,
 * row by row, the run of grid points each disc covers, found from sqrt's
 * estimate and set at its ends by the point test itself. It must give the
 * porosity of testing every grid point of each disc's bounding box (the
 * function before issue 18, written out here) to the bit: layer-make writes
 * that value into every sample's header and the reader compares the header
 * with it (within 2e-3, but a granwave sample matches exactly).
 *
 * Compared with == on 400 random samples (1 to 3000 discs, radii spanning
 * 1 to 1e4 in size: discs far smaller than a grid cell, discs larger than the
 * window, discs across the window's edges, centres on grid points) and on
 * square lattices of 10 to 300 columns (particles of 60 down to 2 grid cells,
 * where the grid aliases). A guard: it passes on the code before; a row
 * search that misses the last point of a run fails it.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "gw_layer.h"
#include "gw_test.h"

static int cell(double v, double v0, double d, int G, int up)
{
    double q = up ? ceil((v - v0) / d) : floor((v - v0) / d);
    return !(q >= -1) ? -1 : q > G ? G : (int)q;
}

/* every grid point of every disc's bounding box tested */
static double porosity_every_point(const gw_layer_sample *s)
{
    double h = 0;
    for (int i = 0; i < s->n; i++)
        h = fmax(h, s->y[i] + s->r[i]);
    const int G = 600;
    double x0 = 0.1 * s->width, x1 = 0.9 * s->width, y0 = 0.1 * h, y1 = 0.8 * h;
    double dx = (x1 - x0) / G, dy = (y1 - y0) / G;
    unsigned char *cov = calloc((size_t)G * G, 1);
    if (!cov)
        return NAN;
    for (int i = 0; i < s->n; i++) {
        int ia = cell(s->x[i] - s->r[i], x0, dx, G, 0), ib = cell(s->x[i] + s->r[i], x0, dx, G, 1);
        int ja = cell(s->y[i] - s->r[i], y0, dy, G, 0), jb = cell(s->y[i] + s->r[i], y0, dy, G, 1);
        for (int j = ja < 0 ? 0 : ja; j <= jb && j < G; j++)
            for (int k = ia < 0 ? 0 : ia; k <= ib && k < G; k++) {
                double px = x0 + (k + 0.5) * dx - s->x[i], py = y0 + (j + 0.5) * dy - s->y[i];
                if (px * px + py * py <= s->r[i] * s->r[i])
                    cov[(size_t)j * G + k] = 1;
            }
    }
    long c = 0;
    for (long q = 0; q < (long)G * G; q++)
        c += cov[q];
    free(cov);
    return 1.0 - (double)c / ((double)G * G);
}

static double uniform(uint64_t *st)
{
    return (double)(gw_test_xorshift(st) >> 11) / 9007199254740992.0;
}

int main(void)
{
    uint64_t st = 0x9e3779b97f4a7c15ull;
    int same = 0, cases = 0, worst = -1;
    double *b = malloc(3 * 90000 * sizeof *b);
    if (!b)
        return 1;
    for (int c = 0; c < 400; c++) {
        gw_layer_sample s = {.width = 1 + 20 * uniform(&st), .x = b, .y = b + 90000, .r = b + 180000};
        s.n = 1 + (int)(3000 * pow(uniform(&st), 3));
        const double rlo = s.width * 1e-4, span = pow(1e4, uniform(&st));
        for (int i = 0; i < s.n; i++) {
            s.r[i] = rlo * pow(span, uniform(&st));
            s.x[i] = s.width * uniform(&st);
            s.y[i] = s.width * uniform(&st);
        }
        if (c % 4 == 0) { /* centres on grid points of the window */
            double h = 0;
            for (int i = 0; i < s.n; i++)
                h = fmax(h, s.y[i] + s.r[i]);
            for (int i = 0; i < s.n; i++) {
                s.x[i] = 0.1 * s.width + ((int)(600 * uniform(&st)) + 0.5) * (0.8 * s.width / 600);
                s.y[i] = fmin(0.1 * h + ((int)(600 * uniform(&st)) + 0.5) * (0.7 * h / 600), h - s.r[i]);
            }
        }
        const double a = gw_layer_sample_porosity(&s), e = porosity_every_point(&s);
        cases++;
        if (a == e)
            same++;
        else if (worst < 0)
            worst = c, printf("  random sample %d (n = %d): %.17g, every point %.17g\n", c, s.n, a, e);
    }
    gw_test_true(same == cases, "400 random samples: the porosity of the row runs equals every point's to the bit");
    same = cases = 0;
    for (int nc = 10; nc <= 300; nc += 10) { /* square lattices, particles of 60 down to 2 grid cells */
        const double r = 0.325, d = 2 * r + 1e-3;
        gw_layer_sample s = {.n = nc * nc, .width = nc * d, .x = b, .y = b + 90000, .r = b + 180000};
        for (int j = 0; j < nc; j++)
            for (int i = 0; i < nc; i++)
                s.x[j * nc + i] = d / 2 + i * d, s.y[j * nc + i] = r + 5e-4 + j * d, s.r[j * nc + i] = r;
        const double a = gw_layer_sample_porosity(&s), e = porosity_every_point(&s);
        cases++;
        same += a == e;
        if (a != e)
            printf("  lattice %d x %d: %.17g, every point %.17g\n", nc, nc, a, e);
    }
    gw_test_true(same == cases, "30 square lattices (10 to 300 columns): the same porosity to the bit");
    free(b);
    return gw_test_summary("test_layer_porosity_grid");
}
