/*
 * layer_sample.c: the sample files of pluviated layers (docs/physics.md 2.2), text
 * (format versions 1 and 2) and HDF5, and the sample porosity.
 *
 * Text format, documented in gw_layer.h: a magic line, "key value" header lines,
 * then "n N" and N lines "x y r" in metres (version 2, clump samples of type B
 * soil: "x y r body", the rigid-body id; disc samples keep writing version 1,
 * so their files are unchanged). '#' starts a comment line (the
 * writer puts the program version and the command line there). Lines end in LF
 * or CRLF. The reader refuses anything else with the file name and line number,
 * and opens only regular files (gw_input_open: a FIFO or device never blocks it).
 * HDF5 format (when built with HDF5): datasets x, y, r [n] (m), body [n] for
 * clump samples, and the header as attributes of the root group (see
 * gw_layer.h). Body ids are checked by layer_bodies_check (layer_clump_check.c). The reader tells the two
 * apart by the HDF5 signature, not by the file name, and checks the fields of
 * both with the same functions (check_header, check_particle, and check_whole:
 * the bodies, the grading, the box against the packing, the porosity).
 * Porosity: 1 - (solid area / window area) in the window x in [0.1, 0.9] W,
 * y in [0.1, 0.8] h, h = max(y + r), sampled on a 600 x 600 grid (the wall and
 * free-surface layers are excluded; sampling error ~1e-3 on random packings
 * whose particles span 20 cells or more; a regular lattice of smaller ones
 * aliases: a 1000 x 1000 square lattice of porosity 0.217 reads 0.333).
 * Units: SI (m).
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "layer_impl.h"
#include "gw_locale.h"
#if GW_HAVE_HDF5
#include <hdf5.h>
#include "gw_h5.h"
#endif

#define SAMPLE_NMAX 10000000L /* 240 MB of coordinates */
#define SAMPLE_LINE_MAX 1024  /* longest header or particle line; comments may be longer */
#define SAMPLE_MAGIC "granwave-layer-sample"

/* the units attributes of an HDF5 sample: the file's, and each coordinate
 * dataset's (x, y, r); a reader refuses others (h5_units_check) */
#define SAMPLE_H5_UNITS "SI: x, y, r, width, rm in metres"
#define SAMPLE_H5_COLUMN_UNITS "m"
static const unsigned char h5_signature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};

void gw_layer_sample_free(gw_layer_sample *s)
{
    if (!s)
        return;
    free(s->x);
    free(s->body);
    s->x = s->y = s->r = NULL;
    s->body = NULL;
    s->n = 0;
}

/* ------------------------------------------------------------ checks ---- */

/* Up to 40 characters of untrusted text for a message, non-printables as '?'. */
static const char *shown(const char *s, char out[48])
{
    size_t i = 0;
    for (; s[i] && i < 40; i++)
        out[i] = (s[i] >= 0x20 && s[i] < 0x7f) ? s[i] : '?';
    if (s[i]) {
        out[i++] = '.', out[i++] = '.', out[i++] = '.';
    }
    out[i] = '\0';
    return out;
}

/* The scales a sample may have: R_m within the range of layer-make's rm row
 * ([1e-5, 1e3] m), the box at most 1e6 R_m wide and its particles at most
 * 1e6 R_m high (the width-rm and height-rm rows' bound: positions then keep
 * 2e-10 R_m of resolution, far below a contact's overlap), and every radius
 * within [1e-3, 1e3] R_m (layer-make's grading, volume ratio up to 1e6, stays
 * in [0.005, 2] R_m). Outside them a sample is no granular layer of its R_m:
 * a 1e-10 m sample ran for minutes on a step of 1e-11 s, a particle at
 * y = 1e12 m closed the ledger to 0.34 only, and R_m = 1e-300 m failed inside
 * the solver with a message naming no input. */
#define SAMPLE_RM_MIN 1e-5
#define SAMPLE_RM_MAX 1e3
#define SAMPLE_EXTENT_RM 1e6
#define SAMPLE_R_LO 1e-3
#define SAMPLE_R_HI 1e3

/* The header fields every reader and the writers check: width and rm finite
 * and positive, rm and width within the scales above, volume_ratio 0
 * (unknown) or >= 1, porosity NaN (unknown) or in [0, 1], seed >= 0 (the
 * seed the pluviation drew from: a provenance record, checked for form only,
 * as only a new pluviation could check its value). */
static int check_header(const gw_layer_sample *s, const char *path, int status, gw_err *err)
{
    if (!isfinite(s->width) || !(s->width > 0))
        return gw_err_set(err, status, "sample '%s': width %g m must be finite and positive", path, s->width);
    if (!isfinite(s->rm) || !(s->rm > 0))
        return gw_err_set(err, status, "sample '%s': rm %g m must be finite and positive", path, s->rm);
    if (!(s->rm >= SAMPLE_RM_MIN && s->rm <= SAMPLE_RM_MAX))
        return gw_err_set(err, status, "sample '%s': rm %g m is outside [%g, %g] m (layer-make's rm range)",
                          path, s->rm, SAMPLE_RM_MIN, SAMPLE_RM_MAX);
    if (!(s->width <= SAMPLE_EXTENT_RM * s->rm))
        return gw_err_set(err, status, "sample '%s': width %g m is above %g R_m (R_m = %g m)", path, s->width,
                          SAMPLE_EXTENT_RM, s->rm);
    if (!isfinite(s->volume_ratio) || (s->volume_ratio != 0 && !(s->volume_ratio >= 1)))
        return gw_err_set(err, status, "sample '%s': volume_ratio %g must be >= 1", path, s->volume_ratio);
    if (!isnan(s->porosity) && !(s->porosity >= 0 && s->porosity <= 1))
        return gw_err_set(err, status, "sample '%s': porosity %g must be in [0, 1]", path, s->porosity);
    if (s->seed < 0)
        return gw_err_set(err, status, "sample '%s': seed %ld must be >= 0 (layer-make's seeds are in [0, 9e18])",
                          path, s->seed);
    if (s->mass_law != GW_LAYER_MASS_DISC && s->mass_law != GW_LAYER_MASS_SPHERE)
        return gw_err_set(err, status, "sample '%s': unknown mass law %d", path, s->mass_law);
    if (s->clump_mass != GW_LAYER_CLUMP_MASS_SUM && s->clump_mass != GW_LAYER_CLUMP_MASS_UNION)
        return gw_err_set(err, status, "sample '%s': unknown clump mass %d", path, s->clump_mass);
    return GW_OK;
}

/* One particle: finite, r > 0 and within [1e-3, 1e3] R_m, inside the box
 * (0 <= x <= width, 0 <= y <= 1e6 R_m) up to the 0.02 R overlap that settling
 * under gravity leaves against the walls. where: "line 12" or "particle 3". */
static int check_particle(double width, double rm, double x, double y, double r, const char *path,
                          const char *where, int status, gw_err *err)
{
    if (!isfinite(x) || !isfinite(y) || !isfinite(r))
        return gw_err_set(err, status, "sample '%s': %s: x, y, r must be finite numbers (got %g %g %g)",
                          path, where, x, y, r);
    if (!(r > 0))
        return gw_err_set(err, status, "sample '%s': %s: radius %g m must be positive", path, where, r);
    if (!(r >= SAMPLE_R_LO * rm && r <= SAMPLE_R_HI * rm))
        return gw_err_set(err, status, "sample '%s': %s: radius %g m is outside [%g, %g] R_m (R_m = %g m)", path,
                          where, r, SAMPLE_R_LO, SAMPLE_R_HI, rm);
    if (x - r < -2e-2 * r || x + r > width + 2e-2 * r || y - r < -2e-2 * r)
        return gw_err_set(err, status, "sample '%s': %s: particle outside the box (0 <= x <= %g, y >= 0) "
                          "beyond the 0.02 R overlap tolerance", path, where, width);
    if (!(y <= SAMPLE_EXTENT_RM * rm))
        return gw_err_set(err, status, "sample '%s': %s: y = %g m is above %g R_m (R_m = %g m)", path, where, y,
                          SAMPLE_EXTENT_RM, rm);
    return GW_OK;
}

/* The body ids of a clump sample (none: GW_OK), the message naming the sample. */
static int check_bodies(const gw_layer_sample *s, const char *path, int status, gw_err *err)
{
    if (!s->body)
        return GW_OK;
    char what[4200];
    gw_snprintf(what, sizeof what, "sample '%s'", path);
    return layer_bodies_check(s->n, s->x, s->y, s->r, s->body, what, status, err);
}

/* Where a header value came from, for the messages of check_box and
 * check_porosity: a text file's line (line[K] > 0), an HDF5 attribute (h5),
 * or a sample in memory being written (NULL). */
enum { K_WIDTH, K_RM, K_VR, K_POR, K_SEED, K_LAW, K_CMASS, K_N, K_COUNT };
typedef struct hdr_src {
    int h5;
    long line[K_COUNT];
} hdr_src;

static const char *hdr_where(const hdr_src *src, int key, const char *name, char out[64])
{
    if (src && src->h5)
        gw_snprintf(out, 64, "HDF5 attribute '%s'", name);
    else if (src && src->line[key] > 0)
        gw_snprintf(out, 64, "line %ld: header '%s'", src->line[key], name);
    else
        gw_snprintf(out, 64, "header '%s'", name);
    return out;
}

/* Area common to two discs (m^2): the lens where they overlap. */
static double lens_area(double d, double r1, double r2)
{
    if (d >= r1 + r2)
        return 0;
    const double rs = fmin(r1, r2);
    if (d <= fabs(r1 - r2))
        return M_PI * rs * rs;
    const double a1 = acos(fmax(-1, fmin(1, (d * d + r1 * r1 - r2 * r2) / (2 * d * r1))));
    const double a2 = acos(fmax(-1, fmin(1, (d * d + r2 * r2 - r1 * r1) / (2 * d * r2))));
    return r1 * r1 * (a1 - sin(2 * a1) / 2) + r2 * r2 * (a2 - sin(2 * a2) / 2);
}

/* What the header's checks need of the particles, over the bodies (a disc
 * sample: each disc; a clump sample: its members grouped by body id):
 * lo = min(x - r) and hi = max(x + r); size, the largest side of a body's
 * bounding box; area, a lower bound of the bodies' areas summed; and the
 * bounds of their equivalent radii sqrt(area / pi): rsmall, an upper bound of
 * the smallest (a clump's members' areas summed), rbig, a lower bound of the
 * largest (their areas less their pairwise lenses, at least the largest
 * member's), each with a particle of its body (ismall, ibig). For discs all
 * are exact. */
typedef struct body_scan {
    double lo, hi, size, area, rsmall, rbig;
    int ismall, ibig;
} body_scan;

static void scan_body(body_scan *b, int i, double x0, double x1, double y0, double y1, double alo, double ahi)
{
    b->lo = fmin(b->lo, x0), b->hi = fmax(b->hi, x1);
    b->size = fmax(b->size, fmax(x1 - x0, y1 - y0));
    b->area += alo;
    const double rlo = sqrt(alo / M_PI), rhi = sqrt(ahi / M_PI);
    if (rhi < b->rsmall)
        b->rsmall = rhi, b->ismall = i;
    if (rlo > b->rbig)
        b->rbig = rlo, b->ibig = i;
}

/* Bounds of the area of the union of the k member discs m (k <= 64; sum:
 * their areas summed, big: the largest): at least sum less every pairwise lens
 * (Bonferroni) and the largest member; at most sum less the lenses along a
 * spanning tree of the members that holds the largest lenses (Hunter's bound;
 * Prim's algorithm, O(k^2)): for layer-make's rows of equal members that tree
 * is the chain of neighbours, whose bound is the area the clump was drawn with
 * (layer_clump_shape's row_area). */
static void body_area_bounds(const gw_layer_sample *s, const int *m, int k, double sum, double big, double *alo,
                             double *ahi)
{
    double all = 0, tree = 0, best[LAYER_CLUMP_MEMBERS];
    int in[LAYER_CLUMP_MEMBERS] = {0};
    for (int q = 0; q < k; q++)
        for (int p = 0; p < q; p++)
            all += lens_area(hypot(s->x[m[q]] - s->x[m[p]], s->y[m[q]] - s->y[m[p]]), s->r[m[q]], s->r[m[p]]);
    in[0] = 1;
    for (int q = 1; q < k; q++)
        best[q] = lens_area(hypot(s->x[m[q]] - s->x[m[0]], s->y[m[q]] - s->y[m[0]]), s->r[m[q]], s->r[m[0]]);
    for (int added = 1; added < k; added++) {
        int next = -1;
        for (int q = 1; q < k; q++)
            if (!in[q] && (next < 0 || best[q] > best[next]))
                next = q;
        tree += best[next];
        in[next] = 1;
        for (int q = 1; q < k; q++)
            if (!in[q])
                best[q] = fmax(best[q], lens_area(hypot(s->x[m[q]] - s->x[m[next]], s->y[m[q]] - s->y[m[next]]),
                                                  s->r[m[q]], s->r[m[next]]));
    }
    *alo = k == 1 ? sum : fmax(sum - all, big);
    *ahi = k == 1 ? sum : fmin(sum, sum - tree);
}

/* GW_OK or GW_ENOMEM (a clump sample's sort by body id). */
static int scan_bodies(const gw_layer_sample *s, body_scan *b)
{
    *b = (body_scan){.lo = INFINITY, .hi = -INFINITY, .rsmall = INFINITY, .rbig = -INFINITY};
    if (!s->body) {
        for (int i = 0; i < s->n; i++) {
            const double r = s->r[i];
            b->lo = fmin(b->lo, s->x[i] - r), b->hi = fmax(b->hi, s->x[i] + r);
            b->size = fmax(b->size, 2 * r);
            b->area += M_PI * r * r;
            if (r < b->rsmall)
                b->rsmall = r, b->ismall = i;
            if (r > b->rbig)
                b->rbig = r, b->ibig = i;
        }
        return GW_OK;
    }
    layer_clump_key *k = malloc((size_t)s->n * sizeof *k);
    if (!k)
        return GW_ENOMEM;
    for (int i = 0; i < s->n; i++)
        k[i] = (layer_clump_key){s->body[i], i};
    qsort(k, (size_t)s->n, sizeof *k, layer_clump_key_cmp);
    for (int a = 0, e; a < s->n; a = e) { /* members checked <= LAYER_CLUMP_MEMBERS: the lenses are cheap */
        double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY, sum = 0, big = 0;
        int m[LAYER_CLUMP_MEMBERS];
        for (e = a; e < s->n && k[e].clump == k[a].clump; e++) {
            const int i = k[e].i;
            m[e - a] = i;
            x0 = fmin(x0, s->x[i] - s->r[i]), x1 = fmax(x1, s->x[i] + s->r[i]);
            y0 = fmin(y0, s->y[i] - s->r[i]), y1 = fmax(y1, s->y[i] + s->r[i]);
            const double ai = M_PI * s->r[i] * s->r[i];
            sum += ai, big = fmax(big, ai);
        }
        double alo, ahi;
        body_area_bounds(s, m, e - a, sum, big, &alo, &ahi);
        scan_body(b, k[a].i, x0, x1, y0, y1, alo, ahi);
    }
    free(k);
    return GW_OK;
}

/* The header's grading against the particles' sizes: a disc's radius, a
 * clump's equivalent radius (its area's). volume_ratio V (0: unknown) is the
 * largest over the smallest particle volume, and rm the mean radius: the radii
 * then span at most V in volume, and their mean lies between the smallest and
 * the largest, so each radius lies within [rm / V^(1/3), rm V^(1/3)]. Both hold
 * for any sample whose header says what its particles are, layer-make's
 * (graded over [2 rm / (1 + V^(1/3)), V^(1/3) times that]; a clump drawn with
 * equivalent radius R_eq has members' areas summed at least pi R_eq^2 and a
 * union at most that), trimmed ones and hand-made ones alike; a header whose
 * rm was edited (a diameter for the radius) or whose volume_ratio was not the
 * particles' would run silently with a block and rings of the wrong size. A
 * clump's equivalent radius is known within bounds (scan_bodies): it is
 * refused only when the bounds themselves break the rule (a version-2 sample
 * of single-disc bodies with rm edited ran, as discs had before). */
static int check_grading(const gw_layer_sample *s, const body_scan *b, const char *path, int status, gw_err *err)
{
    if (!(s->volume_ratio > 0) || s->n < 1)
        return GW_OK;
    const double tol = 1e-9, cv = cbrt(s->volume_ratio);
    const int lo = b->ismall, hi = b->ibig, cl = s->body != NULL;
    const double span = pow(b->rbig / b->rsmall, 3);
    if (span > s->volume_ratio * (1 + tol))
        return gw_err_set(err, status, "sample '%s': its %s span a volume ratio of %s%.6g (%sparticle %d: %.6g m, "
                          "%sparticle %d: %.6g m), above the header's volume_ratio %.6g (the largest over the "
                          "smallest particle volume)", path, cl ? "bodies' equivalent radii" : "radii",
                          cl ? "at least " : "", span, cl ? "the body of " : "", lo + 1, b->rsmall,
                          cl ? "the body of " : "", hi + 1, b->rbig, s->volume_ratio);
    if (b->rsmall < s->rm / cv * (1 - tol) || b->rbig > s->rm * cv * (1 + tol)) {
        const int small = b->rsmall < s->rm / cv * (1 - tol), i = small ? lo : hi;
        char what[96];
        if (cl)
            gw_snprintf(what, sizeof what, "the body of particle %d's equivalent radius, %s %.6g m, lies outside",
                        i + 1, small ? "at most" : "at least", small ? b->rsmall : b->rbig);
        else
            gw_snprintf(what, sizeof what, "particle %d's radius %.6g m lies outside", i + 1,
                        small ? b->rsmall : b->rbig);
        return gw_err_set(err, status, "sample '%s': %s [%.6g, %.6g] m, rm / volume_ratio^(1/3) to rm x "
                          "volume_ratio^(1/3): the header's rm %.6g m cannot be the mean radius of particles graded "
                          "over a volume ratio of %.6g", path, what, s->rm / cv, s->rm * cv, s->rm, s->volume_ratio);
    }
    return GW_OK;
}

/* The box is the header's width, and a packing fills it: a widened width (a
 * box wider than the pluviation's) ran silently, with the block dropped at
 * the new centre, off the packing's. Bodies of size at most D lying in one row
 * (none above another) between lo and hi cover at most (hi - lo) D; a packing
 * whose bodies cover more is more than one body high, and must reach each
 * wall within 1.5 D. layer-make starts its bottom row at most one pitch
 * (2.2 r_max) plus its jitter (0.05 r_max) from each wall (1.13 D), its clump
 * rows at most one bounding box (up to sqrt(2) D for a clump turned while
 * settling) plus 0.1 r_max from the right wall, and starts a second row only
 * once the first is full; the pile's weight pushes the bottom row outward.
 * Measured gaps: at most 0.51 D over 16 layer-make samples (discs, clumps,
 * trimmed) and 0.001 D over the stored ones. A single row (layer-make with
 * fewer discs than a row holds, a hand-made disc) may leave the box partly
 * empty: its width is not checked. A widening below 1.5 D is not seen. */
static int check_box(const gw_layer_sample *s, const body_scan *b, const char *path, const hdr_src *src,
                     int status, gw_err *err)
{
    const double lo = b->lo, hi = b->hi, size = b->size, area = b->area;
    const double gap = fmax(lo, s->width - hi), fill = 1.5;
    if (!(area > (hi - lo) * size) || !(gap > fill * size))
        return GW_OK;
    char w[64];
    return gw_err_set(err, status, "sample '%s': %s: %.6g m leaves %.6g m between the %s wall and the packing, "
                      "more than %g particle sizes (%.6g m): a packing more than one particle high fills its box "
                      "(its particles span x in [%.6g, %.6g] m; was the width edited?)", path,
                      hdr_where(src, K_WIDTH, "width", w), s->width, gap, lo >= s->width - hi ? "left" : "right",
                      fill, size, lo, hi);
}

/* The header's porosity (NaN: absent, not checked) against the particles'
 * own: the header records the porosity layer-make measured with
 * gw_layer_sample_porosity on the particles and box it wrote, so a granwave
 * sample matches it to the bit. The tolerance, 2e-3, takes that value rounded
 * to 4 decimals (layer-make's stdout: 5e-5) and a finer measurement of a
 * random packing over the same window (the 600 x 600 grid differs from a
 * 4800 x 4800 one by at most 5.4e-4 over 23 samples, the stored ones and
 * layer-make's of 5 to 300 particles). A regular lattice whose particles
 * span fewer than about 20 grid cells aliases on the grid beyond it (8.7e-3
 * at 10 cells a diameter): a hand-made sample may leave porosity out. A header
 * porosity of other particles or of another box (0.2 for layer-make's
 * 0.19558, a width widened) is refused. */
static int check_porosity(const gw_layer_sample *s, const char *path, const hdr_src *src, int status, gw_err *err)
{
    if (isnan(s->porosity))
        return GW_OK;
    const double tol = 2e-3, p = gw_layer_sample_porosity(s);
    if (isnan(p)) /* the grid's allocation failed: the window is never empty here */
        return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory measuring its porosity", path);
    if (fabs(p - s->porosity) <= tol)
        return GW_OK;
    char w[64];
    return gw_err_set(err, status, "sample '%s': %s: %.6g, but its particles and width give %.6g (window x in "
                      "[0.1, 0.9] W, y in [0.1, 0.8] h), more than %g apart: the header is not these particles' "
                      "(a hand-made sample may leave porosity out)", path, hdr_where(src, K_POR, "porosity", w), s->porosity, p, tol);
}

/* The checks that need the whole sample: its bodies, its grading, its box,
 * then its porosity (after the box: a widened width changes both). */
static int check_whole(const gw_layer_sample *s, const char *path, const hdr_src *src, int status, gw_err *err)
{
    int rc = check_bodies(s, path, status, err);
    body_scan b;
    if (rc == GW_OK && scan_bodies(s, &b) != GW_OK)
        rc = gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory sorting %d particles by body", path, s->n);
    if (rc == GW_OK)
        rc = check_grading(s, &b, path, status, err);
    if (rc == GW_OK)
        rc = check_box(s, &b, path, src, status, err);
    return rc == GW_OK ? check_porosity(s, path, src, status, err) : rc;
}

static int check_sample(const gw_layer_sample *s, const char *path, const hdr_src *src, int status, gw_err *err)
{
    int rc = check_header(s, path, status, err);
    if (rc != GW_OK)
        return rc;
    if (s->n < 1 || s->n > SAMPLE_NMAX || !s->x || !s->y || !s->r)
        return gw_err_set(err, status, "sample '%s': n = %d must be in [1, %ld] with coordinates",
                          path, s->n, SAMPLE_NMAX);
    char where[48];
    for (int i = 0; i < s->n && rc == GW_OK; i++) {
        gw_snprintf(where, sizeof where, "particle at index %d", i);
        rc = check_particle(s->width, s->rm, s->x[i], s->y[i], s->r[i], path, where, status, err);
    }
    return rc == GW_OK ? check_whole(s, path, src, status, err) : rc;
}

int layer_sample_readable(const gw_layer_sample *s, const char *what, gw_err *err)
{
    int rc = check_sample(s, what, NULL, GW_EFORMAT, err);
    return rc == GW_OK ? layer_overlaps_check(s->n, s->x, s->y, s->r, s->body, what, err) : rc;
}

/* 1 when the name asks for HDF5 (.h5, .hdf5; any case). */
static int wants_h5(const char *path)
{
    size_t n = strlen(path);
    return (n >= 3 && strcasecmp(path + n - 3, ".h5") == 0) ||
           (n >= 5 && strcasecmp(path + n - 5, ".hdf5") == 0);
}

int gw_layer_sample_out_check(const char *path, const char *what, gw_err *err)
{
    if (!what)
        what = "sample";
    if (wants_h5(path) && !GW_HAVE_HDF5)
        return gw_err_set(err, GW_EUNSUPPORTED, "%s: '%s': HDF5 samples need granwave built with HDF5 "
                          "(GW_WITH_HDF5=ON and libhdf5); give a text name such as sample.txt", what, path);
    /* the place the sample goes, before the run: a FIFO, device or directory of
     * that name, or a missing or read-only directory, is refused */
    int rc = gw_out_file_check(path, what, err);
    if (rc != GW_OK)
        return rc;
    /* an existing file is replaced only when it is a sample (text or HDF5) or
     * empty: a mistyped --out never overwrites someone's data */
    FILE *fp = fopen(path, "rb");
    if (fp) {
        unsigned char head[sizeof SAMPLE_MAGIC - 1] = {0};
        const size_t got = fread(head, 1, sizeof head, fp);
        fclose(fp);
        const int text = got == sizeof head && memcmp(head, SAMPLE_MAGIC, sizeof head) == 0;
        const int h5 = got >= sizeof h5_signature && memcmp(head, h5_signature, sizeof h5_signature) == 0;
        if (got > 0 && !text && !h5)
            return gw_err_set(err, GW_EINVAL, "%s: '%s' exists and is not a granwave sample; refusing to "
                              "overwrite it", what, path);
    }
    /* and a directory that refuses new files whatever its mode says (root in
     * /proc, a read-only mount): the temporary file of the atomic write is
     * made and removed at once, before hours of pluviation */
    gw_afile f;
    gw_err e = {{0}};
    int orc = gw_afile_open(&f, path, &e);
    if (orc == GW_ENOMEM) /* not the place's fault */
        return gw_err_set(err, orc, "%s: '%s': %s", what, path, e.msg);
    if (orc != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: '%s' cannot be written there (%s)", what, path, e.msg);
    gw_afile_abort(&f);
    return GW_OK;
}

int gw_layer_sample_format_check(const char *path, gw_err *err)
{
    return gw_layer_sample_out_check(path, "sample", err);
}

/* ------------------------------------------------------------- text ---- */

static int write_text(const gw_layer_sample *s, const char *path, const char *header, gw_err *err)
{
    gw_afile f;
    int rc = gw_afile_open(&f, path, err);
    if (rc != GW_OK)
        return rc;
    gw_fprintf(f.fp, SAMPLE_MAGIC " %d\n", s->body ? 2 : 1);
    gw_write_comment(f.fp, header);
    gw_fprintf(f.fp, "# units: metres; lines after 'n' are: x y r%s\n", s->body ? " body" : "");
    gw_fprintf(f.fp, "width %.17g\nrm %.17g\nvolume_ratio %.17g\n", s->width, s->rm, s->volume_ratio);
    if (!isnan(s->porosity)) /* NaN: unknown, not written */
        gw_fprintf(f.fp, "porosity %.17g\n", s->porosity);
    gw_fprintf(f.fp, "seed %ld\n", s->seed);
    gw_fprintf(f.fp, "mass_law %s\n", s->mass_law == GW_LAYER_MASS_SPHERE ? "sphere" : "disc");
    if (s->clump_mass == GW_LAYER_CLUMP_MASS_UNION) /* sum, the default, is not written */
        gw_fprintf(f.fp, "clump_mass %s\n", gw_layer_clump_mass_name(s->clump_mass));
    gw_fprintf(f.fp, "n %d\n", s->n);
    for (int i = 0; i < s->n; i++) {
        if (s->body)
            gw_fprintf(f.fp, "%.17g %.17g %.17g %d\n", s->x[i], s->y[i], s->r[i], s->body[i]);
        else
            gw_fprintf(f.fp, "%.17g %.17g %.17g\n", s->x[i], s->y[i], s->r[i]);
    }
    return gw_afile_commit(&f, err);
}

/* A line source: the bytes already read to look for the HDF5 signature, then
 * the stream (so pipes work too). */
typedef struct text_in {
    FILE *fp;
    const char *path;
    unsigned char pre[8];
    size_t npre, ipre;
    long line;
    char buf[SAMPLE_LINE_MAX + 1];
} text_in;

static int text_getc(text_in *t)
{
    return t->ipre < t->npre ? t->pre[t->ipre++] : getc(t->fp);
}

/* Next line that is neither blank nor a comment into t->buf, without its LF or
 * CRLF. 1: a line; 0: end of file; < 0: GW_EFORMAT (NUL byte, line too long)
 * or GW_EIO (read error), with err set. */
static int text_next(text_in *t, gw_err *err)
{
    for (;;) {
        int c, any = 0, lead = 1, comment = 0, nul = 0;
        size_t len = 0;
        while ((c = text_getc(t)) != EOF && c != '\n') {
            any = 1;
            nul |= c == 0;
            if (lead && (c == ' ' || c == '\t'))
                continue;
            if (lead)
                comment = c == '#', lead = 0;
            if (comment)
                continue;
            if (len == SAMPLE_LINE_MAX)
                return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: longer than %d characters",
                                  t->path, t->line + 1, SAMPLE_LINE_MAX);
            t->buf[len++] = (char)c;
        }
        if (c == EOF && ferror(t->fp))
            return gw_err_set(err, GW_EIO, "sample '%s': read error after line %ld: %s", t->path,
                              t->line, strerror(errno));
        if (c == EOF && !any)
            return 0;
        t->line++;
        if (nul)
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: NUL byte (binary data, not a text sample)",
                              t->path, t->line);
        if (len > 0 && t->buf[len - 1] == '\r')
            len--;
        t->buf[len] = '\0';
        if (!comment && len > 0)
            return 1;
    }
}

/* Split s at blanks in place into at most max tokens; returns the token count,
 * max + 1 when there are more. */
static int split(char *s, char **tok, int max)
{
    int k = 0;
    for (;;) {
        while (*s == ' ' || *s == '\t')
            s++;
        if (!*s)
            return k;
        if (k == max)
            return max + 1;
        tok[k++] = s;
        while (*s && *s != ' ' && *s != '\t')
            s++;
        if (*s)
            *s++ = '\0';
    }
}

/* The whole token as a finite double (underflow to a subnormal is fine). */
static int parse_num(const char *s, double *v)
{
    char *end;
    *v = gw_strtod(s, &end);
    return end != s && *end == '\0' && isfinite(*v);
}

static int parse_long(const char *s, long *v)
{
    char *end;
    errno = 0;
    *v = strtol(s, &end, 10);
    return end != s && *end == '\0' && errno == 0;
}

static const char *const header_keys[K_COUNT] = {"width", "rm", "volume_ratio", "porosity",
                                                 "seed", "mass_law", "clump_mass", "n"};

/* Header lines up to and including "n N": fills s, *n, the format version and
 * the line of each key in src (a porosity not given is NaN, unknown). */
static int text_header(text_in *t, gw_layer_sample *s, long *n, int *version, hdr_src *src, gw_err *err)
{
    char *tok[3], show[48];
    int rc = text_next(t, err), seen = 0;
    if (rc <= 0)
        return rc < 0 ? rc : gw_err_set(err, GW_EFORMAT, "sample '%s': empty file, not a granwave layer sample",
                                        t->path);
    /* a UTF-8 byte-order mark (an editor's "save as UTF-8"): skipped, as
     * layer-stats does with its tables; it was refused as "not a granwave layer
     * sample" without a word on the mark */
    if (strncmp(t->buf, "\xEF\xBB\xBF", 3) == 0) {
        memmove(t->buf, t->buf + 3, strlen(t->buf + 3) + 1);
        /* the mark alone on a blank or comment line: text_next took the mark
         * for text and returned the line; the header is on a later line (a
         * mark then blank lines read tok[0] unset: SIGSEGV, found by
         * fuzz_layer_sample) */
        const char *p = t->buf + strspn(t->buf, " \t");
        if ((*p == '\0' || *p == '#') && (rc = text_next(t, err)) <= 0)
            return rc < 0 ? rc : gw_err_set(err, GW_EFORMAT, "sample '%s': empty file, not a granwave layer sample",
                                            t->path);
    }
    int k = split(t->buf, tok, 2);
    if (k < 1 || strcmp(tok[0], SAMPLE_MAGIC) != 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: not a granwave layer sample (expected '"
                          SAMPLE_MAGIC " 1')", t->path, t->line);
    if (k > 2)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: characters after '" SAMPLE_MAGIC " %s'",
                          t->path, t->line, shown(tok[1], show));
    if (k != 2 || (strcmp(tok[1], "1") != 0 && strcmp(tok[1], "2") != 0))
        return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: unsupported format version '%s' "
                          "(this build reads 1 and 2)", t->path, t->line, k == 2 ? shown(tok[1], show) : "");
    *version = tok[1][0] - '0';
    while ((rc = text_next(t, err)) > 0) {
        k = split(t->buf, tok, 2);
        int key = 0;
        while (key < K_COUNT && strcmp(tok[0], header_keys[key]) != 0)
            key++;
        if (key == K_COUNT)
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: unknown key '%s'", t->path, t->line,
                              shown(tok[0], show));
        if (k != 2)
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: expected '%s VALUE'%s", t->path,
                              t->line, header_keys[key], k > 2 ? " and nothing after it" : "");
        if (seen & (1 << key))
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: '%s' given twice", t->path, t->line,
                              header_keys[key]);
        seen |= 1 << key;
        src->line[key] = t->line;
        double v = 0;
        int ok = 1;
        if (key == K_LAW) {
            ok = strcmp(tok[1], "disc") == 0 || strcmp(tok[1], "sphere") == 0;
            s->mass_law = strcmp(tok[1], "sphere") == 0 ? GW_LAYER_MASS_SPHERE : GW_LAYER_MASS_DISC;
        } else if (key == K_CMASS) {
            s->clump_mass = gw_layer_clump_mass_parse(tok[1]);
            ok = s->clump_mass >= 0;
        } else if (key == K_SEED) { /* layer-make's seeds are >= 0: "-1" was taken */
            ok = parse_long(tok[1], &s->seed) && s->seed >= 0;
        } else {
            ok = parse_num(tok[1], &v);
        }
        if (!ok)
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: %s '%s' is not %s", t->path, t->line,
                              header_keys[key], shown(tok[1], show),
                              key == K_LAW ? "disc or sphere" : key == K_CMASS ? "sum or union"
                              : key == K_SEED ? "an integer >= 0" : "a finite number");
        if (key == K_WIDTH)
            s->width = v;
        else if (key == K_RM)
            s->rm = v;
        else if (key == K_VR)
            s->volume_ratio = v;
        else if (key == K_POR)
            s->porosity = v;
        else if (key == K_N) {
            if (!(v >= 1 && v <= SAMPLE_NMAX && v == floor(v)))
                return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: n = %g must be an integer in "
                                  "[1, %ld]", t->path, t->line, v, SAMPLE_NMAX);
            *n = (long)v;
            break;
        }
    }
    if (rc < 0)
        return rc;
    if (!(seen & (1 << K_POR)))
        s->porosity = NAN;
    if (!(seen & (1 << K_N)) || !(seen & (1 << K_WIDTH)) || !(seen & (1 << K_RM)))
        return gw_err_set(err, GW_EFORMAT, "sample '%s': header incomplete after line %ld (needs width, rm "
                          "and then n)", t->path, t->line);
    return check_header(s, t->path, GW_EFORMAT, err);
}

/* Room for cap particles in one block x | y | r (the sample owns s->x only);
 * grows with the file so that a short file claiming a large n costs little. */
static int grow(gw_layer_sample *s, long *cap, long want, int bodies)
{
    long nc = *cap;
    while (nc < want)
        nc = nc ? 2 * nc : 1024;
    if (nc > SAMPLE_NMAX)
        nc = SAMPLE_NMAX;
    if (bodies) {
        int *bd = realloc(s->body, (size_t)nc * sizeof *bd);
        if (!bd)
            return GW_ENOMEM;
        s->body = bd;
    }
    double *b = realloc(s->x, 3 * (size_t)nc * sizeof *b);
    if (!b)
        return GW_ENOMEM;
    /* r first: its new place [2 nc, 2 nc + cap) lies above the old y */
    memmove(b + 2 * nc, b + 2 * *cap, (size_t)*cap * sizeof *b);
    memmove(b + nc, b + *cap, (size_t)*cap * sizeof *b);
    s->x = b, s->y = b + nc, s->r = b + 2 * nc;
    *cap = nc;
    return GW_OK;
}

static int read_text(text_in *t, gw_layer_sample *s, gw_err *err)
{
    long n = 0, cap = 0, i = 0, id = 0;
    int version = 1;
    hdr_src src = {0};
    int rc = text_header(t, s, &n, &version, &src, err);
    const int ncol = version == 2 ? 4 : 3;
    char *tok[4], where[48];
    while (rc == GW_OK && i < n) {
        int got = text_next(t, err);
        if (got <= 0) {
            rc = got < 0 ? got : gw_err_set(err, GW_EFORMAT, "sample '%s': truncated after line %ld: %ld of "
                                            "%ld particles", t->path, t->line, i, n);
            break;
        }
        if (i == cap && grow(s, &cap, i + 1, version == 2) != GW_OK) {
            rc = gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for %ld particles", t->path, n);
            break;
        }
        if (split(t->buf, tok, ncol) != ncol || !parse_num(tok[0], &s->x[i]) ||
            !parse_num(tok[1], &s->y[i]) || !parse_num(tok[2], &s->r[i]) ||
            (ncol == 4 && !parse_long(tok[3], &id))) {
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: expected %s (particle %ld of %ld)",
                            t->path, t->line, ncol == 4 ? "three finite numbers and an integer 'x y r body'"
                            : "three finite numbers 'x y r'", i + 1, n);
            break;
        }
        if (ncol == 4 && (id < 0 || id >= n)) {
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: body id %ld outside [0, %ld)", t->path,
                            t->line, id, n);
            break;
        }
        if (ncol == 4)
            s->body[i] = (int)id;
        gw_snprintf(where, sizeof where, "line %ld", t->line);
        rc = check_particle(s->width, s->rm, s->x[i], s->y[i], s->r[i], t->path, where, GW_EFORMAT, err);
        i++;
    }
    if (rc == GW_OK && (rc = text_next(t, err)) > 0)
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: data after the %ld particles", t->path,
                        t->line, n);
    if (rc != GW_OK)
        return rc;
    if (cap > n) { /* close the gaps of the x | y | r block */
        memmove(s->x + n, s->y, (size_t)n * sizeof *s->x);
        memmove(s->x + 2 * n, s->r, (size_t)n * sizeof *s->x);
        double *b = realloc(s->x, 3 * (size_t)n * sizeof *b);
        if (b)
            s->x = b;
        s->y = s->x + n, s->r = s->x + 2 * n;
    }
    s->n = (int)n;
    return check_whole(s, t->path, &src, GW_EFORMAT, err);
}

/* ------------------------------------------------------------- HDF5 ---- */

#if GW_HAVE_HDF5
/* HDF5 prints its error stack by default. While granwave calls it (a
 * gw_h5_section, gw_h5.h), a handler records the most specific message of the
 * first failure instead (for gw_err). */
typedef struct h5_quiet {
    char why[160];
    int nomem; /* a failed allocation in HDF5: "out of memory" */
} h5_quiet;

static herr_t h5_innermost(unsigned k, const H5E_error2_t *e, void *ctx)
{
    char *why = ctx;
    if (k == 0 && e->desc) {
        gw_snprintf(why, 160, "%s", e->desc);
        for (char *p = why; *p; p++)
            if (*p == '\n' || *p == '\r')
                *p = ' ';
    }
    return 0;
}

static herr_t h5_record(hid_t stack, void *ctx)
{
    h5_quiet *q = ctx;
    char *why = q->why;
    if (gw_h5_stack_nomem(stack))
        q->nomem = 1;
    if (!why[0])
        H5Ewalk2(stack, H5E_WALK_UPWARD, h5_innermost, why);
    if (!why[0])
        gw_snprintf(why, 160, "HDF5 call failed");
    return 0;
}

/* A section of HDF5 calls with h5_record as its handler. */
static void h5_enter(gw_h5_section *sec, h5_quiet *q)
{
    q->why[0] = '\0';
    q->nomem = 0;
    gw_h5_enter(sec, h5_record, q);
}

static int h5_attr_write(hid_t loc, const char *name, hid_t type, const void *v)
{
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = sp < 0 ? -1 : H5Acreate2(loc, name, type, sp, H5P_DEFAULT, H5P_DEFAULT);
    int bad = a < 0 || H5Awrite(a, type, v) < 0;
    if (a >= 0)
        H5Aclose(a);
    if (sp >= 0)
        H5Sclose(sp);
    return bad;
}

/* A fixed-length string attribute; cut at 16 kB, well below the 64 kB an
 * object header can hold, so a long command line cannot fail the write. */
static int h5_attr_write_str(hid_t loc, const char *name, const char *v)
{
    size_t len = strnlen(v, 16384);
    char *copy = malloc(len + 1);
    hid_t t = H5Tcopy(H5T_C_S1);
    int bad = !copy || t < 0 || H5Tset_size(t, len + 1) < 0;
    if (!bad) {
        memcpy(copy, v, len);
        copy[len] = '\0';
        bad = h5_attr_write(loc, name, t, copy);
    }
    free(copy);
    if (t >= 0)
        H5Tclose(t);
    return bad;
}

static int h5_column_write(hid_t f, const char *name, const double *v, int n)
{
    hsize_t dim = (hsize_t)n;
    hid_t sp = H5Screate_simple(1, &dim, NULL);
    hid_t d = sp < 0 ? -1 : H5Dcreate2(f, name, H5T_IEEE_F64LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    int bad = d < 0 || H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0 ||
              h5_attr_write_str(d, "units", SAMPLE_H5_COLUMN_UNITS);
    if (d >= 0)
        H5Dclose(d);
    if (sp >= 0)
        H5Sclose(sp);
    return bad;
}

/* The rigid-body ids of a clump sample as 32-bit integers. */
static int h5_body_write(hid_t f, const int *v, int n)
{
    hsize_t dim = (hsize_t)n;
    hid_t sp = H5Screate_simple(1, &dim, NULL);
    hid_t d = sp < 0 ? -1 : H5Dcreate2(f, "body", H5T_STD_I32LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    int bad = d < 0 || H5Dwrite(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0;
    if (d >= 0)
        H5Dclose(d);
    if (sp >= 0)
        H5Sclose(sp);
    return bad;
}

/* Written under a temporary name through gw_afile (signals held, fsync, rename
 * on commit): HDF5 creates the temporary by name (gw_afile_open_named). The
 * 1.8 file format (superblock 2) puts checksums on all metadata (see read_h5). */
static int write_h5_locked(const gw_layer_sample *s, const char *path, const char *header,
                           const h5_quiet *q, gw_err *err)
{
    int version = 1, n = s->n;
    gw_h5_mem mem;
    hid_t file = gw_h5_mem_create(&mem, path, 1); /* in memory, written as one image (gw_h5.h) */
    int bad = file < 0 || h5_column_write(file, "x", s->x, n) || h5_column_write(file, "y", s->y, n) ||
              h5_column_write(file, "r", s->r, n) || h5_attr_write_str(file, "format", SAMPLE_MAGIC) ||
              h5_attr_write(file, "format_version", H5T_NATIVE_INT, &version) ||
              h5_attr_write_str(file, "granwave_version", gw_version()) ||
              h5_attr_write(file, "width", H5T_NATIVE_DOUBLE, &s->width) ||
              h5_attr_write(file, "rm", H5T_NATIVE_DOUBLE, &s->rm) ||
              h5_attr_write(file, "volume_ratio", H5T_NATIVE_DOUBLE, &s->volume_ratio) ||
              (!isnan(s->porosity) && h5_attr_write(file, "porosity", H5T_NATIVE_DOUBLE, &s->porosity)) ||
              h5_attr_write(file, "seed", H5T_NATIVE_LONG, &s->seed) ||
              h5_attr_write_str(file, "mass_law", s->mass_law == GW_LAYER_MASS_SPHERE ? "sphere" : "disc") ||
              (s->clump_mass == GW_LAYER_CLUMP_MASS_UNION && h5_attr_write_str(file, "clump_mass", gw_layer_clump_mass_name(s->clump_mass))) ||
              h5_attr_write(file, "n", H5T_NATIVE_INT, &n) ||
              h5_attr_write_str(file, "units", SAMPLE_H5_UNITS) ||
              (header && h5_attr_write_str(file, "header", header)) ||
              (s->body && h5_body_write(file, s->body, n));
    int rc = GW_OK;
    if (bad) {
        int nomem = q->nomem;
        if (file >= 0)
            gw_h5_mem_abort(&mem);
        rc = nomem ? gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory", path)
                   : gw_err_set(err, GW_EIO, "sample '%s': HDF5 write failed%s%s", path, q->why[0] ? ": " : "", q->why);
    } else {
        rc = gw_h5_mem_write(&mem, path, err);
    }
    return rc;
}

/* one section of HDF5 calls (gw_h5.h): HDF5 and its error handler, one thread at a time */
static int write_h5(const gw_layer_sample *s, const char *path, const char *header, gw_err *err)
{
    gw_h5_section sec;
    h5_quiet q;
    h5_enter(&sec, &q);
    int rc = write_h5_locked(s, path, header, &q, err);
    gw_h5_leave(&sec);
    return rc;
}

/* A scalar root attribute of class want (H5T_FLOAT also takes integers; a
 * string goes into char[64]) read as memtype: 0 absent, 1 read, -1 malformed. */
static int h5_attr_read(hid_t f, const char *name, H5T_class_t want, hid_t memtype, void *out)
{
    htri_t ex = H5Aexists(f, name);
    if (ex == 0)
        return 0;
    hid_t a = ex > 0 ? H5Aopen(f, name, H5P_DEFAULT) : -1;
    hid_t t = a >= 0 ? H5Aget_type(a) : -1, sp = a >= 0 ? H5Aget_space(a) : -1;
    H5T_class_t cls = t >= 0 ? H5Tget_class(t) : H5T_NO_CLASS;
    int ok = sp >= 0 && H5Sget_simple_extent_npoints(sp) == 1 &&
             (cls == want || (want == H5T_FLOAT && cls == H5T_INTEGER));
    if (ok && want == H5T_STRING) { /* fixed or variable length */
        char *vs = NULL;
        htri_t var = H5Tis_variable_str(t);
        size_t size = H5Tget_size(t);
        hid_t mt = H5Tcopy(H5T_C_S1);
        ok = var >= 0 && mt >= 0 && (var > 0 || (size > 0 && size < 64)) &&
             H5Tset_size(mt, var > 0 ? H5T_VARIABLE : 64) >= 0 && H5Tset_cset(mt, H5Tget_cset(t)) >= 0 &&
             H5Tset_strpad(mt, H5T_STR_NULLTERM) >= 0 && H5Aread(a, mt, var > 0 ? (void *)&vs : out) >= 0;
        if (ok && var > 0) {
            ok = vs && strlen(vs) < 64;
            if (ok)
                memcpy(out, vs, strlen(vs) + 1);
        }
        if (vs)
            H5free_memory(vs);
        if (mt >= 0)
            H5Tclose(mt);
        if (ok)
            ((char *)out)[63] = '\0';
    } else if (ok) {
        ok = H5Aread(a, memtype, out) >= 0;
    }
    if (t >= 0)
        H5Tclose(t);
    if (sp >= 0)
        H5Sclose(sp);
    if (a >= 0)
        H5Aclose(a);
    return ok ? 1 : -1;
}

/* Where the data of dataset name lies: 1 in the file itself (a hard link to a
 * dataset whose layout is compact, contiguous or chunked in this file), 0
 * elsewhere (an external or user-defined link, raw data in external files, a
 * virtual dataset), -1 unknown. Data outside the file would be read through a
 * path the file names: a FIFO there hung the reader, /dev/zero gave zeros,
 * a superblock-0 file there skipped the checksum rule of read_h5, and the
 * sample's content hash (its own bytes) would not cover what was read. */
static int h5_in_file(hid_t f, const char *name, const char **what)
{
    H5L_info_t li;
    *what = "";
    if (H5Lget_info(f, name, &li, H5P_DEFAULT) < 0)
        return -1;
    if (li.type != H5L_TYPE_HARD) {
        *what = li.type == H5L_TYPE_SOFT ? "a soft link" : li.type == H5L_TYPE_EXTERNAL ? "an external link"
                : "a user-defined link";
        return 0;
    }
    hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
    hid_t pl = d >= 0 ? H5Dget_create_plist(d) : -1;
    int in = -1;
    if (pl >= 0) {
        const int next = H5Pget_external_count(pl);
        const H5D_layout_t lay = H5Pget_layout(pl);
        in = next == 0 && (lay == H5D_COMPACT || lay == H5D_CONTIGUOUS || lay == H5D_CHUNKED);
        *what = next != 0 ? "stored in external files" : lay == H5D_VIRTUAL ? "a virtual dataset" : "";
    }
    if (pl >= 0)
        H5Pclose(pl);
    if (d >= 0)
        H5Dclose(d);
    return in;
}

/* The units attribute of loc (the file, or dataset name), when there is one,
 * must be want, the units granwave writes and reads the values in: a sample
 * converted to millimetres with its units attribute saying "mm" ran as metres
 * (a 1000 times larger box, block and particles), exit 0. Absent: the values
 * are taken as SI, as the format says. */
static int h5_units_check(hid_t loc, const char *name, const char *want, const char *path, gw_err *err)
{
    char str[64], show[48];
    const int got = h5_attr_read(loc, "units", H5T_STRING, -1, str);
    if (got == 0 || (got == 1 && strcmp(str, want) == 0))
        return GW_OK;
    char what[96];
    if (got < 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute units of %s%s%s is not one string "
                          "(granwave writes '%s')", path, name ? "dataset '" : "the file", name ? name : "",
                          name ? "'" : "", want);
    if (name)
        gw_snprintf(what, sizeof what, "HDF5 dataset '%s' has units", name);
    else
        gw_snprintf(what, sizeof what, "HDF5 attribute units is");
    return gw_err_set(err, GW_EFORMAT, "sample '%s': %s '%s', not '%s': the values are read in metres, as "
                      "granwave writes them (convert them, and their units)", path, what, shown(str, show), want);
}

/* Dataset name: one dimension of n numbers, read as doubles into v; its units
 * attribute, when it has one, must be units (NULL: not checked). */
static int h5_column_read(hid_t f, const char *name, long n, double *v, const char *units, const char *path,
                          const char *why, gw_err *err)
{
    htri_t ex = H5Lexists(f, name, H5P_DEFAULT);
    const char *where = "";
    const int in = ex > 0 ? h5_in_file(f, name, &where) : -1;
    if (in == 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset '%s' is %s: a sample holds its data in "
                          "the file itself (hard links, no external storage)", path, name, where);
    hid_t d = in > 0 ? H5Dopen2(f, name, H5P_DEFAULT) : -1;
    if (d < 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset '%s' %s%s%s", path, name,
                          ex == 0 ? "missing" : "unreadable", why[0] ? ": " : "", why);
    hid_t sp = H5Dget_space(d), t = H5Dget_type(d);
    hsize_t dim = 0;
    H5T_class_t cls = t >= 0 ? H5Tget_class(t) : H5T_NO_CLASS;
    int shape = sp >= 0 && H5Sget_simple_extent_ndims(sp) == 1 && H5Sget_simple_extent_dims(sp, &dim, NULL) == 1;
    int rc = GW_OK;
    if (!shape || (cls != H5T_FLOAT && cls != H5T_INTEGER))
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset '%s' must be a 1-D array of numbers",
                        path, name);
    else if (dim != (hsize_t)n)
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset '%s' has %llu values, n = %ld", path, name,
                        (unsigned long long)dim, n);
    else if (units && h5_units_check(d, name, units, path, err) != GW_OK)
        rc = GW_EFORMAT;
    else if (H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0)
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset '%s' unreadable: %s", path, name, why);
    if (t >= 0)
        H5Tclose(t);
    if (sp >= 0)
        H5Sclose(sp);
    H5Dclose(d);
    return rc;
}

static int h5_fields(hid_t f, gw_layer_sample *s, const char *path, const char *why, gw_err *err)
{
    char str[64], show[48];
    long long ver = 0, n = 0, seed = 0;
    int got = h5_attr_read(f, "format", H5T_STRING, -1, str);
    if (got < 0 && why[0])
        return gw_err_set(err, GW_EFORMAT, "sample '%s': corrupt HDF5 file (%s)", path, why);
    if (got != 1 || strcmp(str, SAMPLE_MAGIC) != 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 file is not a granwave layer sample (no "
                          "attribute format = '" SAMPLE_MAGIC "')", path);
    if (h5_attr_read(f, "format_version", H5T_INTEGER, H5T_NATIVE_LLONG, &ver) != 1 || ver != 1)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute format_version (%lld) missing or "
                          "unsupported (this build reads 1)", path, ver);
    const struct {
        const char *name;
        double *v;
        int required;
    } num[] = {{"width", &s->width, 1}, {"rm", &s->rm, 1}, {"volume_ratio", &s->volume_ratio, 0},
               {"porosity", &s->porosity, 0}};
    s->porosity = NAN; /* absent: unknown */
    for (size_t k = 0; k < sizeof num / sizeof num[0]; k++) {
        got = h5_attr_read(f, num[k].name, H5T_FLOAT, H5T_NATIVE_DOUBLE, num[k].v);
        if (got < 0 || (got == 0 && num[k].required) || (got == 1 && !isfinite(*num[k].v)))
            return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute '%s' %s", path, num[k].name,
                              got < 0 ? "is not one number" : got == 0 ? "missing" : "is not a finite number");
    }
    /* read twice, signed and unsigned: HDF5 converts an out-of-range integer to
     * the nearest one it can hold, so a uint64 seed above 2^63 was read as
     * 2^63 - 1 and a negative one ran; the two reads agree only in range */
    unsigned long long useed = 0;
    got = h5_attr_read(f, "seed", H5T_INTEGER, H5T_NATIVE_LLONG, &seed);
    if (got == 1)
        got = h5_attr_read(f, "seed", H5T_INTEGER, H5T_NATIVE_ULLONG, &useed);
    if (got < 0 || (got == 1 && (seed < 0 || seed > LONG_MAX || (unsigned long long)seed != useed)))
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute 'seed' is not one integer in [0, %ld] "
                          "(layer-make's seeds are in [0, 9e18])", path, LONG_MAX);
    s->seed = (long)seed;
    got = h5_attr_read(f, "mass_law", H5T_STRING, -1, str);
    if (got < 0 || (got > 0 && strcmp(str, "disc") != 0 && strcmp(str, "sphere") != 0))
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute mass_law '%s' is not disc or sphere",
                          path, got > 0 ? shown(str, show) : "?");
    s->mass_law = got > 0 && strcmp(str, "sphere") == 0 ? GW_LAYER_MASS_SPHERE : GW_LAYER_MASS_DISC;
    got = h5_attr_read(f, "clump_mass", H5T_STRING, -1, str);
    s->clump_mass = got > 0 ? gw_layer_clump_mass_parse(str) : GW_LAYER_CLUMP_MASS_SUM;
    if (got < 0 || s->clump_mass < 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute clump_mass '%s' is not sum or union",
                          path, got > 0 ? shown(str, show) : "?");
    got = h5_attr_read(f, "n", H5T_INTEGER, H5T_NATIVE_LLONG, &n);
    if (got != 1) /* it said "n = 0" for a missing n, a string or a float */
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute 'n' %s", path,
                          got == 0 ? "missing" : "is not one integer");
    if (n < 1 || n > SAMPLE_NMAX)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute n = %lld must be an integer in [1, %ld]",
                          path, n, SAMPLE_NMAX);
    int rc = check_header(s, path, GW_EFORMAT, err);
    if (rc != GW_OK)
        return rc;
    s->x = malloc(3 * (size_t)n * sizeof *s->x);
    if (!s->x)
        return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for %lld particles", path, n);
    s->y = s->x + n, s->r = s->x + 2 * n;
    s->n = (int)n;
    if ((rc = h5_units_check(f, NULL, SAMPLE_H5_UNITS, path, err)) != GW_OK ||
        (rc = h5_column_read(f, "x", (long)n, s->x, SAMPLE_H5_COLUMN_UNITS, path, why, err)) != GW_OK ||
        (rc = h5_column_read(f, "y", (long)n, s->y, SAMPLE_H5_COLUMN_UNITS, path, why, err)) != GW_OK ||
        (rc = h5_column_read(f, "r", (long)n, s->r, SAMPLE_H5_COLUMN_UNITS, path, why, err)) != GW_OK)
        return rc;
    if (H5Lexists(f, "body", H5P_DEFAULT) > 0) { /* a clump sample: ids read as numbers, then checked */
        double *v = malloc((size_t)n * sizeof *v);
        s->body = malloc((size_t)n * sizeof *s->body);
        if (!v || !s->body) {
            free(v);
            return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for %lld body ids", path, n);
        }
        rc = h5_column_read(f, "body", (long)n, v, NULL, path, why, err);
        for (long long i = 0; rc == GW_OK && i < n; i++) {
            if (!(v[i] >= 0 && v[i] < (double)n && v[i] == floor(v[i])))
                rc = gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset 'body': value %g at index %lld is "
                                "not an integer in [0, %lld)", path, v[i], i, n);
            else
                s->body[i] = (int)v[i];
        }
        free(v);
        if (rc != GW_OK)
            return rc;
    }
    const hdr_src src = {.h5 = 1};
    return check_sample(s, path, &src, GW_EFORMAT, err);
}

/* libhdf5 decodes metadata without bounds checks, so a corrupt file can crash
 * it (memory errors found by fuzzing 1.10.8 with superblock-0 files).
 * Superblocks from version 2 on (HDF5 1.8 format and later) come with
 * checksums on all metadata, which HDF5 verifies before decoding: only those
 * files are opened (read_h5, given sb: the superblock version, byte 8 of the file). */
static int read_h5_locked(const char *path, gw_layer_sample *s, const h5_quiet *q, gw_err *err)
{
    int rc;
    /* strong close: H5Fclose also closes what a failed read left open */
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    hid_t f = fapl < 0 || H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG) < 0 ? -1 :
              H5Fopen(path, H5F_ACC_RDONLY, fapl);
    if (f < 0) {
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': corrupt or truncated HDF5 file (%s)", path, q->why);
    } else {
        rc = h5_fields(f, s, path, q->why, err);
        if (H5Fclose(f) < 0 && rc == GW_OK)
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': corrupt HDF5 file (%s)", path, q->why);
    }
    if (fapl >= 0)
        H5Pclose(fapl);
    return rc;
}

static int read_h5(const char *path, int sb, gw_layer_sample *s, gw_err *err)
{
    if (sb < 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': truncated HDF5 file (signature only)", path);
    if (sb < 2)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 file without metadata checksums (superblock "
                          "version %d; write it with the 1.8 format or later, e.g. h5py libver='v108')", path, sb);
    gw_h5_section sec;
    h5_quiet q;
    h5_enter(&sec, &q);
    int rc = read_h5_locked(path, s, &q, err);
    /* a read that failed because an allocation inside HDF5 did (its stack
     * holds a resource error) is out of memory, not a bad sample: the
     * dataset's sizes were checked against n before it was read */
    if (rc != GW_OK && rc != GW_ENOMEM && q.nomem)
        rc = gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory (in HDF5: %s)", path, q.why);
    /* After some corrupt files HDF5 1.10 loses track of a block (a leak inside
     * the library) and at exit prints "infinite loop closing library" unless
     * automatic error printing is off: after a failed read it stays off, here
     * and in the exiting thread (granwave reports HDF5 errors through gw_err). */
    if (rc == GW_OK)
        gw_h5_leave(&sec);
    else
        gw_h5_leave_failed_read(&sec);
    return rc;
}
#endif

/* -------------------------------------------------------- public API ---- */

int gw_layer_sample_write(const gw_layer_sample *s, const char *path, const char *header,
                          gw_err *err)
{
    int rc = gw_layer_sample_format_check(path, err);
    if (rc == GW_OK)
        rc = check_sample(s, path, NULL, GW_EINVAL, err);
    if (rc != GW_OK)
        return rc;
#if GW_HAVE_HDF5
    if (wants_h5(path))
        return write_h5(s, path, header, err);
#endif
    return write_text(s, path, header, err);
}

/* 1 when the file is HDF5: its signature at offset 0 (pre, the first 8
 * bytes) or, after a user block, at 512, 1024, 2048, ... (HDF5 looks there
 * too; a valid sample written by h5py with userblock_size=512 was read as
 * text and refused as "NUL byte"); *sb: the superblock version, the byte
 * after the signature (-1: none). The stream is left at offset 8. */
static int h5_signature_at(FILE *fp, const unsigned char pre[8], int *sb)
{
    if (memcmp(pre, h5_signature, 8) == 0) {
        *sb = getc(fp);
        return fseek(fp, 8, SEEK_SET) == 0;
    }
    int found = 0;
    unsigned char b[9];
    for (long off = 512; off <= (1L << 24) && !found; off *= 2) {
        if (fseek(fp, off, SEEK_SET) != 0 || fread(b, 1, 8, fp) != 8)
            break;
        found = memcmp(b, h5_signature, 8) == 0;
        if (found)
            *sb = getc(fp);
    }
    return fseek(fp, 8, SEEK_SET) == 0 && found;
}

int gw_layer_sample_read(const char *path, gw_layer_sample *s, gw_err *err)
{
    if (!s || !path)
        return gw_err_set(err, GW_EINVAL, "gw_layer_sample_read: %s is NULL", !s ? "s" : "path");
    memset(s, 0, sizeof *s);
    s->mass_law = GW_LAYER_MASS_DISC;
    text_in t = {.path = path};
    /* a regular file only: a FIFO or a device is refused before any read */
    int orc = gw_input_open(path, "sample", &t.fp, err);
    if (orc != GW_OK)
        return orc;
    t.npre = fread(t.pre, 1, sizeof t.pre, t.fp);
    int rc, sb = -1;
    if (t.npre == sizeof t.pre && h5_signature_at(t.fp, t.pre, &sb)) {
        fclose(t.fp);
#if GW_HAVE_HDF5
        rc = read_h5(path, sb, s, err);
#else
        (void)sb;
        rc = gw_err_set(err, GW_EUNSUPPORTED, "sample '%s': an HDF5 file, and this granwave was built "
                        "without HDF5", path);
#endif
    } else {
        rc = read_text(&t, s, err);
        /* the content hash from the same open file: what was read */
        if (rc == GW_OK && (fseek(t.fp, 0, SEEK_SET) != 0 || gw_fnv1a64_stream(t.fp, &s->content_hash) != GW_OK))
            rc = gw_err_set(err, GW_EIO, "sample '%s': cannot read it again for its content hash", path);
        fclose(t.fp);
    }
    if (rc == GW_OK && !s->content_hash) /* an HDF5 sample: read by the library, hashed here */
        rc = gw_fnv1a64_file(path, "sample", &s->content_hash, err);
    if (rc == GW_OK) {
        char what[4200];
        gw_snprintf(what, sizeof what, "sample '%s'", path);
        rc = layer_overlaps_check(s->n, s->x, s->y, s->r, s->body, what, err);
    }
    if (rc != GW_OK) {
        gw_layer_sample_free(s);
        memset(s, 0, sizeof *s);
    }
    return rc;
}

/* ---------------------------------------------------------- porosity ---- */

/* Grid index of coordinate v (cells of size d from v0), clamped to [-1, G] in
 * floating point first, so no value converts out of the int range. */
static int cell_of(double v, double v0, double d, int G, int up)
{
    double q = up ? ceil((v - v0) / d) : floor((v - v0) / d);
    return !(q >= -1) ? -1 : q > G ? G : (int)q; /* NaN: -1 */
}

/* 1 when grid point k of a row (its offset py from the disc's centre) lies in
 * the disc (xi, r): the one test of gw_layer_sample_porosity. */
static int point_in(double x0, double dx, int k, double xi, double py, double r)
{
    double px = x0 + (k + 0.5) * dx - xi;
    return px * px + py * py <= r * r;
}

double gw_layer_sample_porosity(const gw_layer_sample *s)
{
    double h = 0;
    for (int i = 0; i < s->n; i++)
        h = fmax(h, s->y[i] + s->r[i]);
    const int G = 600;
    double x0 = 0.1 * s->width, x1 = 0.9 * s->width, y0 = 0.1 * h, y1 = 0.8 * h;
    double dx = (x1 - x0) / G, dy = (y1 - y0) / G;
    if (!(dx > 0) || !(dy > 0) || !isfinite(dx) || !isfinite(dy))
        return NAN;
    /* mark covered grid points particle by particle, row by row within its
     * bounding box. A grid point is covered when px^2 + py^2 <= r^2 (point_in);
     * px grows with k even as rounded, so the covered points of a row are one
     * run: found from sqrt's estimate widened by 1 point, its ends then set by
     * point_in itself, so the marks are those of testing every point (as
     * before, to the bit) at the cost of a few tests a row: the sample reader
     * measures every sample with a porosity (check_porosity), and a sweep reads
     * its sample once per case (--check of 1000 cases: 3.2 s, 9.8 s testing
     * every point, 3.3 s now) */
    unsigned char *cov = calloc((size_t)G * G, 1);
    if (!cov)
        return NAN;
    const double idx = 1 / dx;
    for (int i = 0; i < s->n; i++) {
        const double xi = s->x[i], yi = s->y[i], ri = s->r[i];
        int ia = cell_of(xi - ri, x0, dx, G, 0), ib = cell_of(xi + ri, x0, dx, G, 1);
        int ja = cell_of(yi - ri, y0, dy, G, 0), jb = cell_of(yi + ri, y0, dy, G, 1);
        ia = ia < 0 ? 0 : ia, ib = ib > G - 1 ? G - 1 : ib;
        const double kc = (xi - x0) * idx - 0.5; /* the grid index of the centre */
        for (int j = ja < 0 ? 0 : ja; j <= jb && j < G && ia <= ib; j++) {
            const double py = y0 + (j + 0.5) * dy - yi, w = sqrt(fmax(0, ri * ri - py * py)) * idx;
            /* the run's ends, estimated, widened by one point (truncation is floor here: >= 0) */
            const double ql = kc - w - 1, qr = kc + w + 1;
            int kl = !(ql > ia) ? ia : ql > ib ? ib : (int)ql, kr = !(qr < ib) ? ib : qr < ia ? ia : (int)qr;
            while (kl <= kr && !point_in(x0, dx, kl, xi, py, ri))
                kl++;
            while (kr >= kl && !point_in(x0, dx, kr, xi, py, ri))
                kr--;
            if (kl > kr)
                continue;
            while (kl > ia && point_in(x0, dx, kl - 1, xi, py, ri))
                kl--;
            while (kr < ib && point_in(x0, dx, kr + 1, xi, py, ri))
                kr++;
            memset(cov + (size_t)j * G + kl, 1, (size_t)(kr - kl + 1));
        }
    }
    long c = 0;
    for (long q = 0; q < (long)G * G; q++)
        c += cov[q];
    free(cov);
    return 1.0 - (double)c / ((double)G * G);
}
