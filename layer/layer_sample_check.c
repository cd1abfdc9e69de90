/*
 * layer_sample_check.c: the checks a layer sample (docs/physics.md 2.2) passes
 * when it is read (text or HDF5) and before it is written: the header fields
 * (width, rm, volume_ratio, porosity, seed, mass laws), each particle (finite,
 * its radius within [1e-3, 1e3] R_m, inside the box), the bodies of a clump
 * sample (layer_bodies_check, layer_clump_check.c), the grading (each
 * equivalent radius within [rm / V^(1/3), rm V^(1/3)], V the header's
 * volume_ratio), the box (a packing more than one body high reaches each wall
 * within 1.5 body sizes) and the header's porosity (within 2e-3 of the
 * particles' own, gw_layer_sample_porosity, layer_sample_porosity.c).
 * Areas: a disc pi r^2; two discs at distance d share the lens
 * r1^2 (a1 - sin(2 a1) / 2) + r2^2 (a2 - sin(2 a2) / 2), cos a1 =
 * (d^2 + r1^2 - r2^2) / (2 d r1); a clump's area is bounded by its members'
 * areas less their lenses (Bonferroni, Hunter).
 * Units: SI (m, m^2).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_sample_impl.h"
#include "gw_locale.h"
#include "gw_number_impl.h"

/* Up to 40 characters of untrusted text for a message, non-printables as '?'. */
const char *layer_sample_shown(const char *s, char out[48])
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
int layer_sample_header_check(const gw_layer_sample *s, const char *path, int status, gw_err *err)
{
    if (!isfinite(s->width) || !(s->width > 0))
        return gw_err_set(err, status, "sample '%s': width %g m must be finite and positive", path, s->width);
    if (!isfinite(s->rm) || !(s->rm > 0))
        return gw_err_set(err, status, "sample '%s': rm %g m must be finite and positive", path, s->rm);
    char ls[40], hs[40];
    if (!(s->rm >= SAMPLE_RM_MIN && s->rm <= SAMPLE_RM_MAX))
        return gw_err_set(err, status, "sample '%s': rm %g m is outside [%s, %s] m (layer-make's rm range)",
                          path, s->rm, gw_num_bound(ls, sizeof ls, SAMPLE_RM_MIN, 0),
                          gw_num_bound(hs, sizeof hs, SAMPLE_RM_MAX, 1));
    if (!(s->width <= SAMPLE_EXTENT_RM * s->rm))
        return gw_err_set(err, status, "sample '%s': width %g m is above %s R_m (R_m = %g m)", path, s->width,
                          gw_num_bound(hs, sizeof hs, SAMPLE_EXTENT_RM, 1), s->rm);
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

/* x, y and r finite, r > 0: the message names the field. */
static int particle_form(double x, double y, double r, const char *path, const char *where, int status, gw_err *err)
{
    static const char *const name[3] = {"x", "y", "r"};
    const double v[3] = {x, y, r};
    for (int k = 0; k < 3; k++)
        if (!isfinite(v[k]))
            return gw_err_set(err, status, "sample '%s': %s: %s = %g m is not a finite number", path, where,
                              name[k], v[k]);
    if (!(r > 0))
        return gw_err_set(err, status, "sample '%s': %s: radius r = %g m must be positive", path, where, r);
    return GW_OK;
}

/* One particle: finite, r > 0 and within [1e-3, 1e3] R_m, inside the box
 * (0 <= x <= width, 0 <= y <= 1e6 R_m) up to the 0.02 R overlap that settling
 * under gravity leaves against the walls; the message names the field. where:
 * "line 12", "particle at index 3" (HDF5) or "particle 3" (in memory). The
 * one particle check of the readers, the writers and every call that takes a
 * sample built in memory (layer_sample_limits_check). */
int layer_sample_particle_check(double width, double rm, double x, double y, double r, const char *path,
                          const char *where, int status, gw_err *err)
{
    int rc = particle_form(x, y, r, path, where, status, err);
    if (rc != GW_OK)
        return rc;
    char ls[40], hs[40];
    if (!(r >= SAMPLE_R_LO * rm && r <= SAMPLE_R_HI * rm))
        return gw_err_set(err, status, "sample '%s': %s: radius %g m is outside [%s, %s] R_m (R_m = %g m)",
                          path, where, r, gw_num_bound(ls, sizeof ls, SAMPLE_R_LO, 0),
                          gw_num_bound(hs, sizeof hs, SAMPLE_R_HI, 1), rm);
    if (x - r < -2e-2 * r || x + r > width + 2e-2 * r || y - r < -2e-2 * r)
        return gw_err_set(err, status, "sample '%s': %s: particle outside the box (0 <= x <= %s, y >= 0) "
                          "beyond the 0.02 R overlap tolerance (x = %g, y = %g, r = %g m)", path, where,
                          gw_num_bound(hs, sizeof hs, width, 1), x, y, r);
    if (!(y <= SAMPLE_EXTENT_RM * rm))
        return gw_err_set(err, status, "sample '%s': %s: y = %g m is above %s R_m (R_m = %g m)", path, where, y,
                          gw_num_bound(hs, sizeof hs, SAMPLE_EXTENT_RM, 1), rm);
    return GW_OK;
}

/* The form of a sample, what must hold before any of it is read: n in
 * [1, SAMPLE_NMAX] with its arrays, width and rm finite and positive, each
 * particle finite with r > 0, body ids in [0, n), each spring's pair in range
 * and its displacement finite (n_springs >= 0, its array when above 0). */
int layer_sample_form_check(const gw_layer_sample *s, const char *path, int status, gw_err *err)
{
    if (s->n < 1 || s->n > SAMPLE_NMAX || !s->x || !s->y || !s->r)
        return gw_err_set(err, status, "sample '%s': n = %d particles%s%s%s (in [1, %ld], with x, y and r)",
                          path, s->n, s->x ? "" : ", x NULL", s->y ? "" : ", y NULL", s->r ? "" : ", r NULL",
                          SAMPLE_NMAX);
    /* the box and the block's scale (rb-rm R_m): an rm of 0 passed the
     * impact's check and the run refused its block of radius 0; a NaN or
     * negative rm, or a NaN or infinite width, was told "x: no soil particle
     * lies under the block" */
    if (!isfinite(s->width) || !(s->width > 0))
        return gw_err_set(err, status, "sample '%s': width %g m must be finite and positive", path, s->width);
    if (!isfinite(s->rm) || !(s->rm > 0))
        return gw_err_set(err, status, "sample '%s': rm %g m must be finite and positive", path, s->rm);
    char where[48];
    for (int i = 0; i < s->n; i++) {
        gw_snprintf(where, sizeof where, "particle %d", i);
        const int rc = particle_form(s->x[i], s->y[i], s->r[i], path, where, status, err);
        if (rc != GW_OK)
            return rc;
    }
    for (int i = 0; s->body && i < s->n; i++)
        if (s->body[i] < 0 || s->body[i] >= s->n)
            return gw_err_set(err, status, "sample '%s': particle %d: body id %d is outside [0, %d)", path, i,
                              s->body[i], s->n);
    if (s->n_springs < 0)
        return gw_err_set(err, status, "sample '%s': n_springs = %d is negative", path, s->n_springs);
    if (s->n_springs > 0 && !s->springs)
        return gw_err_set(err, status, "sample '%s': n_springs = %d with springs NULL", path, s->n_springs);
    /* each spring's record whole, its displacement with its pair: a NaN u
     * passed here (the settling check, the porosity, the pile's hash took
     * it, and an impact under zero_springs ran it) where every reader and
     * the writer refuse it */
    for (int k = 0; k < s->n_springs; k++) {
        const int rc = layer_spring_form_check(s, k, path, NULL, status, err);
        if (rc != GW_OK)
            return rc;
    }
    return GW_OK;
}

/* The limits every sample is held to, read from a file, written or built in
 * memory: its form (layer_sample_form_check), the header's fields
 * (layer_sample_header_check), each particle (layer_sample_particle_check:
 * its radius's scale, inside the box), the clumps of a clump sample
 * (layer_bodies_check), and no two particles of different bodies deep
 * inside each other (layer_overlaps_check). Before session 43 a sample built
 * in memory was held to its form only: a disc outside the box, of a radius
 * of 1e6 R_m, or two discs at one place ran (the overlap injecting energy)
 * or had a porosity, where the same sample written to a file was refused. */
int layer_sample_limits_check(const gw_layer_sample *s, const char *path, int status, gw_err *err)
{
    int rc = layer_sample_form_check(s, path, status, err);
    if (rc == GW_OK)
        rc = layer_sample_header_check(s, path, status, err);
    if (rc == GW_OK)
        rc = layer_settled_record_check(s, path, status, err);
    char where[48];
    for (int i = 0; i < s->n && rc == GW_OK; i++) {
        gw_snprintf(where, sizeof where, "particle %d", i);
        rc = layer_sample_particle_check(s->width, s->rm, s->x[i], s->y[i], s->r[i], path, where, status, err);
    }
    if (rc != GW_OK)
        return rc;
    char what[4200];
    gw_snprintf(what, sizeof what, "sample '%s'", path);
    if ((rc = layer_bodies_check(s->n, s->x, s->y, s->r, s->body, what, status, err)) != GW_OK)
        return rc;
    rc = layer_overlaps_check(s->n, s->x, s->y, s->r, s->body, what, err);
    return rc == GW_EFORMAT ? status : rc; /* (the message is the check's) */
}

int layer_sample_shape_check(const gw_layer_sample *s, const char *path, gw_err *err)
{
    return layer_sample_limits_check(s, path, GW_EINVAL, err);
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
    char w[64], fs[40];
    return gw_err_set(err, status, "sample '%s': %s: %.6g m leaves %.6g m between the %s wall and the packing, "
                      "more than %s particle sizes (%.6g m): a packing more than one particle high fills its box "
                      "(its particles span x in [%.6g, %.6g] m; was the width edited?)", path,
                      hdr_where(src, K_WIDTH, "width", w), s->width, gap, lo >= s->width - hi ? "left" : "right",
                      gw_num_bound(fs, sizeof fs, fill, 1), size, lo, hi);
}

/* The header's porosity (NaN: absent, not checked) against the particles'
 * own: the header records the porosity layer-make measured with
 * gw_layer_sample_porosity on the particles and box it wrote, so a granwave
 * sample matches it to the bit. The tolerance, 2e-3, takes that value rounded
 * to 4 decimals (layer-make's stdout: 5e-5) and the samples written before
 * the porosity was the exact area (a 600 x 600 grid until session 21: within
 * 2.9e-4 of the exact value on the 7 stored samples, 5.4e-4 of a 4800 x 4800
 * grid over 23 samples). Since it is exact, a regular lattice reads its own
 * porosity (the grid aliased on them). A header porosity of other particles
 * or of another box (0.2 for layer-make's 0.19562, a width widened) is
 * refused. */
static int check_porosity(const gw_layer_sample *s, const char *path, const hdr_src *src, int status, gw_err *err)
{
    if (isnan(s->porosity))
        return GW_OK;
    const double tol = 2e-3, p = layer_sample_porosity_of(s);
    /* no disc in the window (a pile of one or two discs): nothing to check
     * the header's against (earlier versions wrote 1 for it) */
    char w[64], ts[40];
    if (isnan(p) && layer_sample_window_empty(s)) {
        /* ... and earlier versions wrote 1 there. Any other value measured
         * discs in the window, which these particles leave empty: one disc
         * of a made pile lifted 50 m (the window's h with it) passed the
         * check where 5 m was refused, and the pile ran as settled */
        if (fabs(1.0 - s->porosity) <= tol)
            return GW_OK;
        return gw_err_set(err, status, "sample '%s': %s: %.6g, but its particles and width leave the window (x in "
                          "[0.1, 0.9] W, y in [0.1, 0.8] h) without a disc: the header is not these particles' (a "
                          "hand-made sample may leave porosity out)", path, hdr_where(src, K_POR, "porosity", w),
                          s->porosity);
    }
    if (isnan(p)) /* an allocation failed */
        return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory measuring its porosity", path);
    if (fabs(p - s->porosity) <= tol)
        return GW_OK;
    return gw_err_set(err, status, "sample '%s': %s: %.6g, but its particles and width give %.6g (window x in "
                      "[0.1, 0.9] W, y in [0.1, 0.8] h), more than %s apart: the header is not these particles' "
                      "(a hand-made sample may leave porosity out)", path, hdr_where(src, K_POR, "porosity", w),
                      s->porosity, p, gw_num_bound(ts, sizeof ts, tol, 1));
}

/* The checks that need the whole sample: its bodies, its grading, its box,
 * then its porosity (after the box: a widened width changes both). */
int layer_sample_whole_check(const gw_layer_sample *s, const char *path, const hdr_src *src, int status, gw_err *err)
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

int layer_sample_check(const gw_layer_sample *s, const char *path, const hdr_src *src, int status, gw_err *err)
{
    int rc = layer_sample_header_check(s, path, status, err);
    if (rc != GW_OK)
        return rc;
    if (s->n < 1 || s->n > SAMPLE_NMAX || !s->x || !s->y || !s->r)
        return gw_err_set(err, status, "sample '%s': n = %d must be in [1, %ld] with coordinates",
                          path, s->n, SAMPLE_NMAX);
    char where[48];
    for (int i = 0; i < s->n && rc == GW_OK; i++) {
        gw_snprintf(where, sizeof where, "particle at index %d", i);
        rc = layer_sample_particle_check(s->width, s->rm, s->x[i], s->y[i], s->r[i], path, where, status, err);
    }
    return rc == GW_OK ? layer_sample_whole_check(s, path, src, status, err) : rc;
}

int layer_sample_readable(const gw_layer_sample *s, const char *what, gw_err *err)
{
    int rc = layer_sample_check(s, what, NULL, GW_EFORMAT, err);
    if (rc == GW_OK)
        rc = layer_sample_limits_check(s, what, GW_EFORMAT, err);
    return rc == GW_OK ? layer_springs_check(s, what, NULL, GW_EFORMAT, err) : rc;
}
