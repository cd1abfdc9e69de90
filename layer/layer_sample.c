/*
 * layer_sample.c: the text sample format of pluviated layers (physics.md 2.2)
 * and its porosity.
 *
 * Format (version 1), documented in gw_layer.h: "key value" header lines, then
 * "n N" and N lines "x y r" in metres. '#' starts a comment line (the writer
 * puts the program version and the command line there). The reader rejects
 * anything else with the file name and line number.
 * Porosity: 1 - (solid area / window area) in the window x in [0.1, 0.9] W,
 * y in [0.1, 0.8] h, h = max(y + r), sampled on a 600 x 600 grid (the wall and
 * free-surface layers are excluded; sampling error ~1e-3).
 * Units: SI (m).
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_layer.h"

void gw_layer_sample_free(gw_layer_sample *s)
{
    if (!s)
        return;
    free(s->x);
    s->x = s->y = s->r = NULL;
    s->n = 0;
}

int gw_layer_sample_write(const gw_layer_sample *s, const char *path, const char *header,
                          gw_err *err)
{
    gw_afile f;
    int rc = gw_afile_open(&f, path, err);
    if (rc != GW_OK)
        return rc;
    fprintf(f.fp, "granwave-layer-sample 1\n");
    if (header) {
        const char *p = header;
        while (*p) {
            const char *e = strchr(p, '\n');
            size_t len = e ? (size_t)(e - p) : strlen(p);
            fprintf(f.fp, "# %.*s\n", (int)len, p);
            p += len + (e ? 1 : 0);
        }
    }
    fprintf(f.fp, "# units: metres; lines after 'n' are: x y r\n");
    fprintf(f.fp, "width %.17g\nrm %.17g\nvolume_ratio %.17g\nporosity %.17g\nseed %ld\n",
            s->width, s->rm, s->volume_ratio, s->porosity, s->seed);
    fprintf(f.fp, "mass_law %s\nn %d\n", s->mass_law == GW_LAYER_MASS_SPHERE ? "sphere" : "disc",
            s->n);
    for (int i = 0; i < s->n; i++)
        fprintf(f.fp, "%.17g %.17g %.17g\n", s->x[i], s->y[i], s->r[i]);
    return gw_afile_commit(&f, err);
}

/* Next non-comment line into buf; 0 at end of file. */
static int next_line(FILE *fp, char *buf, size_t n, int *lineno)
{
    while (fgets(buf, (int)n, fp)) {
        (*lineno)++;
        char *p = buf;
        while (*p == ' ' || *p == '\t')
            p++;
        if (*p == '#' || *p == '\n' || *p == '\r' || *p == 0)
            continue;
        return 1;
    }
    return 0;
}

static int parse_num(const char *s, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(s, &end);
    while (*end == ' ' || *end == '\t' || *end == '\n' || *end == '\r')
        end++;
    return end != s && *end == 0 && errno == 0 && isfinite(*v);
}

int gw_layer_sample_read(const char *path, gw_layer_sample *s, gw_err *err)
{
    memset(s, 0, sizeof *s);
    FILE *fp = fopen(path, "r");
    if (!fp)
        return gw_err_set(err, GW_EIO, "sample '%s': cannot open: %s", path, strerror(errno));
    char buf[1024], key[64], val[512];
    int line = 0, rc = GW_OK, have_w = 0;
    s->mass_law = GW_LAYER_MASS_DISC;
    if (!next_line(fp, buf, sizeof buf, &line) ||
        strncmp(buf, "granwave-layer-sample 1", 23) != 0) {
        fclose(fp);
        return gw_err_set(err, GW_EFORMAT, "sample '%s': line %d: not a granwave layer sample "
                          "(expected 'granwave-layer-sample 1')", path, line);
    }
    long n = -1;
    while (n < 0 && next_line(fp, buf, sizeof buf, &line)) {
        double v;
        if (sscanf(buf, "%63s %511[^\n]", key, val) != 2) {
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %d: expected 'key value'", path, line);
            break;
        }
        if (strcmp(key, "mass_law") == 0) {
            if (strncmp(val, "sphere", 6) == 0)
                s->mass_law = GW_LAYER_MASS_SPHERE;
            else if (strncmp(val, "disc", 4) != 0)
                rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %d: mass_law must be disc or sphere",
                                path, line);
            if (rc != GW_OK)
                break;
            continue;
        }
        if (!parse_num(val, &v)) {
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %d: '%s' is not a finite number",
                            path, line, val);
            break;
        }
        if (strcmp(key, "width") == 0)
            s->width = v, have_w = 1;
        else if (strcmp(key, "rm") == 0)
            s->rm = v;
        else if (strcmp(key, "volume_ratio") == 0)
            s->volume_ratio = v;
        else if (strcmp(key, "porosity") == 0)
            s->porosity = v;
        else if (strcmp(key, "seed") == 0)
            s->seed = (long)v;
        else if (strcmp(key, "n") == 0) {
            if (v < 1 || v > 1e7 || v != floor(v)) {
                rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %d: n = %g must be an integer in [1, 1e7]",
                                path, line, v);
                break;
            }
            n = (long)v;
        } else {
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %d: unknown key '%s'", path, line, key);
            break;
        }
    }
    if (rc == GW_OK && (n < 0 || !have_w || !(s->width > 0) || !(s->rm > 0)))
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': header incomplete (needs positive width, rm, and n)",
                        path);
    if (rc == GW_OK) {
        s->x = malloc(3 * (size_t)n * sizeof *s->x);
        if (!s->x)
            rc = gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for %ld particles", path, n);
        else
            s->y = s->x + n, s->r = s->x + 2 * n;
    }
    for (long i = 0; rc == GW_OK && i < n; i++) {
        char extra[8];
        if (!next_line(fp, buf, sizeof buf, &line)) {
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': truncated: %ld of %ld particles", path, i, n);
            break;
        }
        if (sscanf(buf, "%lf %lf %lf %7s", &s->x[i], &s->y[i], &s->r[i], extra) != 3 ||
            !isfinite(s->x[i]) || !isfinite(s->y[i]) || !isfinite(s->r[i])) {
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %d: expected three finite numbers 'x y r'",
                            path, line);
            break;
        }
        if (!(s->r[i] > 0))
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %d: radius %g m must be positive",
                            path, line, s->r[i]);
        else if (s->x[i] - s->r[i] < -2e-2 * s->r[i] || s->x[i] + s->r[i] > s->width + 2e-2 * s->r[i] ||
                 s->y[i] - s->r[i] < -2e-2 * s->r[i])
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %d: particle outside the box "
                            "(0 <= x <= %g, y >= 0) beyond the 0.02 R overlap tolerance", path, line, s->width);
    }
    if (rc == GW_OK && next_line(fp, buf, sizeof buf, &line))
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %d: data after the %ld particles", path, line, n);
    if (rc == GW_OK && ferror(fp))
        rc = gw_err_set(err, GW_EIO, "sample '%s': read error", path);
    fclose(fp);
    if (rc != GW_OK) {
        gw_layer_sample_free(s);
        return rc;
    }
    s->n = (int)n;
    return GW_OK;
}

double gw_layer_sample_porosity(const gw_layer_sample *s)
{
    double h = 0;
    for (int i = 0; i < s->n; i++)
        h = fmax(h, s->y[i] + s->r[i]);
    const int G = 600;
    double x0 = 0.1 * s->width, x1 = 0.9 * s->width, y0 = 0.1 * h, y1 = 0.8 * h;
    double dx = (x1 - x0) / G, dy = (y1 - y0) / G;
    /* mark covered grid points particle by particle (bounding boxes only) */
    unsigned char *cov = calloc((size_t)G * G, 1);
    if (!cov)
        return NAN;
    for (int i = 0; i < s->n; i++) {
        int ia = (int)floor((s->x[i] - s->r[i] - x0) / dx), ib = (int)ceil((s->x[i] + s->r[i] - x0) / dx);
        int ja = (int)floor((s->y[i] - s->r[i] - y0) / dy), jb = (int)ceil((s->y[i] + s->r[i] - y0) / dy);
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
