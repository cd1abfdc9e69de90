/*
 * layer_make.c: pluviation of a 2D sample (docs/physics.md 2.2).
 *
 * Radii: uniform in radius on [R_min, R_max], R_max = V^(1/3) R_min (V the
 * largest/smallest volume ratio), mean R_m: R_min = 2 R_m / (1 + V^(1/3)).
 * Particles start without overlap on a jittered grid of pitch 2.2 R_max above
 * the bottom of a box of width W with rigid walls, at rest, and fall under
 * gravity (the model of layer_model.c: Hertz-Mindlin, B.1-B.4, friction phi)
 * until the total kinetic energy is below ke_threshold * M_total g R_m, the
 * floor carrying the pile (LAYER_FLOOR_LOAD_MIN to LAYER_FLOOR_LOAD_MAX times
 * its weight).
 * Settling needs dissipation the paper's contact law does not have at low
 * speeds, so the normal contacts carry Hunt-Crossley damping (alpha, s/m) while
 * settling: the sample is a geometry, the damping is not used by impacts.
 * Optional speed-up: settle with G * modulus_factor, then relax with the true G
 * (same damping) until the threshold is met again.
 * Deterministic for a seed: splitmix64 (Steele, Lea, Flood 2014) drives all
 * random draws; the integration is RK4 with a fixed step (no contact events;
 * the contact list checked at the steps' ends and F_t of open contacts zeroed
 * after every step, so that the sample does not depend on the skin: layer_sim.c).
 * The sample keeps the settled pile's tangential springs (gw_layer_spring:
 * the last settling's contacts, layer_springs_take), so that an impact starts
 * from the forces the pile rests on (before, from zero: the pile sagged).
 * Type B soil (clumps = 1): n rigid clumps instead of n discs. Each clump draws
 * its equivalent radius R_eq from the discs' grading (same curve), its aspect
 * ratio uniform in [1, aspect_max] ([1, 4] by default) and its orientation uniform in [0, pi); its shape is
 * a row of overlapping discs (layer_clumps.c). The clumps start at rest, packed
 * row by row by their bounding boxes (gap 0.1 R_max) from the bottom of the box,
 * and settle like the discs; the trim to height_rm removes whole clumps.
 * Units: SI.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "layer_impl.h"
#include "gw_locale.h"
#include "gw_number_impl.h"

typedef struct splitmix64 {
    unsigned long long s;
} splitmix64;

static unsigned long long sm_next(splitmix64 *g)
{
    unsigned long long z = (g->s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1) with 53 random bits. */
static double sm_uniform(splitmix64 *g)
{
    return (double)(sm_next(g) >> 11) * 0x1.0p-53;
}

gw_layer_make_params gw_layer_make_params_default(void)
{
    gw_layer_make_params m;
    memset(&m, 0, sizeof m);
    m.n = 300;
    m.rm = 0.325;
    m.volume_ratio = 10;
    m.width_rm = 50;
    m.seed = 1;
    m.ke_threshold = 1e-5;
    m.t_max = 6;
    m.damping = 0.3;
    m.modulus_factor = 1;
    m.dt = 2e-5;
    m.solver = gw_solver_rk4; /* verlet at 2e-5 s left seed 2 unsettled after 6 s */
    m.aspect_max = 4;
    return m;
}

/* A box in which a clump drawn cannot lie flat: clumps_initial lays a clump
 * on its side when its bounding box fits between the walls with a gap of
 * 0.1 R_max on each side, and stands it on end otherwise; clumps standing on
 * end in a box narrower than they are long topple, jam across it and lean on
 * both walls. `layer-make --clumps --width-rm 4 --n 20` (the longest clump
 * 5.11 R_m at the defaults) ended unsettled at t-max 6 s for seeds 1 and 2,
 * the floor carrying 6.57 and 0.054 of the weight (wedged clumps pressing it,
 * or held off it by the walls); in boxes of 5.2, 5.6, 6 and 7 R_m the same 20
 * clumps settled for seeds 1 to 4 (floors 0.75 to 1.14 of the weight). A
 * clump's length 2 A r grows with its R_eq and aspect ratio A
 * (layer_clump_shape); the draw is seeded and does not depend on the box
 * (clump_draw: the same clumps at every width), so the bound is the longest
 * clump the seed's n draws give, lying flat, plus the two gaps: the width at
 * which the initial lay-out puts every clump flat (it was the longest any
 * draw could give, R_eq = R_max at the largest aspect ratio, 5.38 R_m at the
 * defaults: `--n 1`, one clump 2.31 R_m long at seed 1, was refused below
 * 5.39). The width named is rounded up to three digits. */
#define CLUMP_FLAT_GAPS 0.2 /* R_max: the lay-out's gap of 0.1 R_max on each side */

/* The next clump of the seeded draw g: its R_eq (m) from the grading
 * [rmin, rmax], its aspect ratio in [1, aspect_max], its angle in [0, pi). */
static void clump_draw(splitmix64 *g, double rmin, double rmax, double aspect_max, double *req, double *aspect,
                       double *angle)
{
    *req = rmin + (rmax - rmin) * sm_uniform(g);
    *aspect = 1 + (aspect_max - 1) * sm_uniform(g);
    *angle = M_PI * sm_uniform(g);
}

/* The length (m) of a clump of R_eq req and aspect ratio aspect lying flat. */
static double clump_flat_length(double req, double aspect)
{
    double ox[LAYER_CLUMP_MAX], oy[LAYER_CLUMP_MAX], r[LAYER_CLUMP_MAX];
    const int k = layer_clump_shape(req, aspect, 0, ox, oy, r);
    double x0 = INFINITY, x1 = -INFINITY;
    for (int q = 0; q < k; q++)
        x0 = fmin(x0, ox[q] - r[q]), x1 = fmax(x1, ox[q] + r[q]);
    return x1 - x0;
}

static int check_clump_flat(const gw_layer_make_params *m, gw_err *err)
{
    /* the grading as clumps_initial computes it, to the bit */
    const double cv = cbrt(m->volume_ratio), rmin = 2 * m->rm / (1 + cv), rmax = cv * rmin;
    splitmix64 g = {(unsigned long long)m->seed}; /* clumps_initial's draw */
    double len = 0, lreq = 0, lasp = 1;
    int lj = 0;
    for (int j = 0; j < m->n; j++) {
        double req, aspect, angle;
        clump_draw(&g, rmin, rmax, m->aspect_max, &req, &aspect, &angle);
        const double l = clump_flat_length(req, aspect);
        if (l > len)
            len = l, lreq = req, lasp = aspect, lj = j;
    }
    const double need = len + CLUMP_FLAT_GAPS * rmax;
    if (m->width_rm * m->rm >= need)
        return GW_OK;
    /* the smallest width of three digits at or above need / R_m, read back */
    const double v = need / m->rm, p = pow(10, floor(log10(v)) - 2);
    char wb[40], wt[40];
    double c = ceil(v / p) * p;
    for (int i = 0; i < 4; i++, c += p) {
        gw_snprintf(wb, sizeof wb, "%.3g", c);
        if (gw_strtod(wb, NULL) * m->rm >= need)
            break;
    }
    return gw_err_set(err, GW_EINVAL, "width-rm: a box of %s R_m is narrower than the longest clump drawn lies flat "
                      "in (clump %d of %d at seed %ld: %.3g R_m long, R_eq %.3g R_m, aspect ratio %.3g, with a gap "
                      "of 0.1 R_max each side: %.4g R_m): the clumps stand on end, topple and wedge across the box; "
                      "give --width-rm %s or more, or a smaller --aspect-max", gw_num_text(wt, sizeof wt, m->width_rm),
                      lj + 1, m->n, m->seed, len / m->rm, lreq / m->rm, lasp, need / m->rm, wb);
}

/* v rounded up to four significant digits: a bound printed as one to give */
static double ceil_sig4(double v)
{
    const double e = pow(10, floor(log10(v)) - 3);
    return ceil(v / e) * e;
}

static int check_make(const gw_layer_make_params *m, gw_err *err)
{
    int rc;
    if (m->n < 1 || m->n > 1000000)
        return gw_err_set(err, GW_EINVAL, "n: %d particles is outside [1, 1e6]", m->n);
    /* rm, width-rm and height-rm within the rows of the make table (the
     * ranges the sample's reader holds a sample to), clumps a flag: rm 1e-200
     * m was told "give dt -nan or less", 1e200 m failed at the solver's set-up
     * ("scale[120] = inf"), 1.8e308 m named the box width; width-rm 1e200 was
     * refused only after its settling ("width 3.25e+199 m is above 1e+06
     * R_m"); a height-rm of NaN, -1 or inf kept the whole pile (as 0) and
     * clumps = -1 or 2 made clumps, a ke-threshold of 1e200 or 4.9e-324 and a
     * t-max of 4.9e-324 s ran, with GW_OK (the fiftieth pass) */
    if ((rc = gw_check_positive(m->rm, "rm (mean radius, m)", err)) != GW_OK ||
        (rc = gw_check_range(m->rm, "rm (mean radius, m)", GW_LAYER_MAKE_RM_MIN, GW_LAYER_MAKE_RM_MAX, err)) !=
            GW_OK ||
        (rc = isfinite(m->width_rm) && m->width_rm <= 1e6
              ? GW_OK
              : gw_err_set(err, GW_EINVAL, "width-rm: %g R_m is outside (0, 1e+06]", m->width_rm)) != GW_OK ||
        (rc = gw_check_range(m->height_rm, "height-rm", 0, 1e6, err)) != GW_OK ||
        (rc = m->clumps == 0 || m->clumps == 1
              ? GW_OK
              : gw_err_set(err, GW_EINVAL, "clumps: %d is not a flag (0: discs, 1: clumps)", m->clumps)) != GW_OK ||
        (rc = gw_check_range(m->volume_ratio, "volume-ratio", 1, 1e6, err)) != GW_OK ||
        (rc = gw_check_positive(m->ke_threshold, "ke-threshold", err)) != GW_OK ||
        (rc = gw_check_range(m->ke_threshold, "ke-threshold", DBL_MIN, 1, err)) != GW_OK ||
        (rc = gw_check_positive(m->t_max, "t-max (s)", err)) != GW_OK ||
        (rc = gw_check_range(m->t_max, "t-max (s)", DBL_MIN, 1e4, err)) != GW_OK ||
        (rc = gw_check_range(m->damping, "damping (s/m)", 0, 1e3, err)) != GW_OK ||
        (rc = gw_check_range(m->modulus_factor, "modulus-factor", GW_LAYER_MODULUS_FACTOR_MIN, 1, err)) != GW_OK ||
        (rc = gw_check_positive(m->dt, "dt (s)", err)) != GW_OK ||
        (rc = m->solver == gw_solver_verlet || m->solver == gw_solver_rk4 ? GW_OK
              : gw_err_set(err, GW_EINVAL, "solver: pluviation takes verlet or rk4")) != GW_OK ||
        (rc = gw_check_range(m->aspect_max, "aspect-max", 1, 4, err)) != GW_OK)
        return rc;
    if (m->t_max / m->dt > 1e9) /* a bound on the steps before anything is allocated */
        return gw_err_set(err, GW_EINVAL, "dt: a step of %g s takes %.3g steps to t-max = %g s, more than 1e9 "
                          "(raise dt or lower t-max)", m->dt, m->t_max / m->dt, m->t_max);
    double rmax = m->rm * 2 * cbrt(m->volume_ratio) / (1 + cbrt(m->volume_ratio));
    /* the bound said "narrower than one particle" from 2.2 R_m down, where
     * one disc of --volume-ratio 1 (2 R_m across) fits, and printed 2.0000001
     * as "2": the rule and the value given, as they are */
    if (m->width_rm * m->rm < 2.2 * rmax)
        return gw_err_set(err, GW_EINVAL, "width-rm: %.9g R_m is narrower than 1.1 times the largest particle's "
                          "diameter (%.4g R_m at volume-ratio %g): give at least %.4g", m->width_rm,
                          2 * rmax / m->rm, m->volume_ratio, ceil_sig4(2.2 * rmax / m->rm));
    return m->clumps ? check_clump_flat(m, err) : GW_OK;
}

/* The step against the pile's shortest contact: two of the smallest discs
 * meeting at the fastest fall speed, from the top of the initial pile to the
 * floor, v = sqrt(2 g h_top), last for the Hertz time (the formula of
 * gw_layer_impact_dem_dt, reduced mass m/2, K_n at R_p = R_min)
 *     tau = 0.8 B(2/5, 1/2) (5 m / (8 K_n))^(2/5) v^(-1/5)
 * An explicit step above tau / SETTLE_STEPS_MIN resolves no contact: RK4 and
 * verlet blow up near tau (rm = 1.2e-4 m at the default 2e-5 s ran for
 * minutes in chopped steps; verlet stopped on a non-finite state). The default
 * pile (rm 0.325 m) has tau / dt = 51 at 2e-5 s, rm = 1e-3 m 2.8 (it settles, overlaps below 1e-3 R_p). */
#define SETTLE_STEPS_MIN 2

/* v rounded down to two significant digits (a suggested step that passes). */
static double floor_2digits(double v)
{
    const double p = pow(10, floor(log10(v)) - 1);
    return floor(v / p) * p;
}

static int check_step(const gw_layer_params *lp, const gw_layer_make_params *m, const gw_layer_body *b, int n,
                      gw_err *err)
{
    double rmin = INFINITY, top = 0;
    for (int i = 0; i < n; i++)
        rmin = fmin(rmin, b[i].r), top = fmax(top, b[i].y + b[i].r);
    const double v = sqrt(2 * lp->gravity * top), ms = 0.5 * gw_layer_mass(lp, rmin), K = gw_layer_kn(lp, rmin);
    const double beta = tgamma(0.4) * tgamma(0.5) / tgamma(0.9); /* B(2/5, 1/2) */
    const double tau = 0.8 * beta * pow(1.25 * ms / K, 0.4) * pow(v, -0.2);
    if (!(m->dt <= tau / SETTLE_STEPS_MIN))
        return gw_err_set(err, GW_EINVAL, "dt: a step of %g s is above 1/%d of the shortest contact of the pile "
                          "(%.3g s: discs of %.3g m meeting at the fall speed %.3g m/s): the settling would "
                          "resolve no contact; give dt %.2g or less", m->dt, SETTLE_STEPS_MIN, tau, rmin, v,
                          floor_2digits(tau / SETTLE_STEPS_MIN));
    return GW_OK;
}

/* Overlap / R_p of discs i and j, R_p = 2 r_i r_j / (r_i + r_j); 0 when they
 * belong to one clump (their overlap is the clump's shape). */
static double pair_overlap(const gw_layer_body *b, int i, int j)
{
    if (b[i].clump > 0 && b[i].clump == b[j].clump)
        return 0;
    double d = hypot(b[j].x - b[i].x, b[j].y - b[i].y), rp = 2 * b[i].r * b[j].r / (b[i].r + b[j].r);
    return (b[i].r + b[j].r - d) / rp;
}

/* The overlap / R_p of discs i and j, marking both in touch (may be NULL)
 * when they touch. */
static double pair_touch(const gw_layer_body *b, int i, int j, unsigned char *touch)
{
    const double ov = pair_overlap(b, i, j);
    if (touch && ov > 0)
        touch[i] = touch[j] = 1;
    return ov;
}

/* Largest overlap / R_p between discs of different bodies and against the
 * walls; touch (n, may be NULL) gets 1 for each disc that overlaps a wall or
 * a disc of another body. The pairs come from a grid of cells of side 2 R_max
 * (layer_grid_build: two discs that overlap lie in neighbouring cells), so the
 * work is linear in n: every pair was compared before, 34.8 s for 64000 discs.
 * Only when the grid cannot be had (out of memory, a position not finite) are
 * all pairs compared, which gives the same value. */
/* A grid of cells of side at least 2 R_max over the centres of the n discs b
 * (layer_grid_build: two discs that overlap lie in neighbouring cells, and a
 * disc that meets another falling straight down lies at most one column
 * away); 0 when it cannot be had (out of memory, a position not finite). */
static int disc_grid(const gw_layer_body *b, int n, layer_grid *g)
{
    double rmax = 0;
    for (int i = 0; i < n; i++)
        rmax = fmax(rmax, b[i].r);
    double *c = malloc(2 * (size_t)(n > 0 ? n : 1) * sizeof *c);
    for (int i = 0; c && i < n; i++)
        c[2 * i] = b[i].x, c[2 * i + 1] = b[i].y;
    const int ok = c && layer_grid_build(g, n, c, c + 1, 2, 2 * rmax) == GW_OK;
    free(c);
    return ok;
}

static double overlaps_in(const gw_layer_body *b, int n, double width, unsigned char *touch, const layer_grid *g);

static double max_overlap(const gw_layer_body *b, int n, double width, unsigned char *touch)
{
    layer_grid g = {0};
    const double maxov = overlaps_in(b, n, width, touch, disc_grid(b, n, &g) ? &g : NULL);
    layer_grid_free(&g);
    return maxov;
}

/* max_overlap over the grid g (NULL: every pair compared) */
static double overlaps_in(const gw_layer_body *b, int n, double width, unsigned char *touch, const layer_grid *g)
{
    double maxov = 0;
    for (int i = 0; i < n; i++) {
        const double wall = fmax(fmax((b[i].r - b[i].y) / b[i].r, (b[i].r - b[i].x) / b[i].r),
                                 (b[i].r - (width - b[i].x)) / b[i].r);
        maxov = fmax(maxov, wall);
        if (touch)
            touch[i] = wall > 0;
    }
    if (!g) {
        for (int i = 0; i < n; i++)
            for (int j = i + 1; j < n; j++)
                maxov = fmax(maxov, pair_touch(b, i, j, touch));
        return maxov;
    }
    for (int i = 0; i < n; i++) {
        const long cx = g->cell[i] % g->nx, cy = g->cell[i] / g->nx;
        for (long ky = cy - 1; ky <= cy + 1; ky++)
            for (long kx = cx - 1; kx <= cx + 1; kx++) {
                if (ky < 0 || ky >= g->ny || kx < 0 || kx >= g->nx)
                    continue;
                for (int q = g->start[ky * g->nx + kx]; q < g->start[ky * g->nx + kx + 1]; q++)
                    if (g->idx[q] > i)
                        maxov = fmax(maxov, pair_touch(b, i, g->idx[q], touch));
            }
    }
    return maxov;
}

/* The drop d of disc i onto disc j (m; d stays as it is when j is not below
 * it, is i itself or of i's clump). */
static double drop_onto(const gw_layer_body *b, int i, int j, double d)
{
    const double dx = b[j].x - b[i].x, rs = b[i].r + b[j].r;
    if (j == i || (b[i].clump > 0 && b[j].clump == b[i].clump) || !(fabs(dx) < rs) || !(b[j].y < b[i].y))
        return d;
    return fmin(d, b[i].y - b[j].y - sqrt(rs * rs - dx * dx));
}

/* How far disc i of b falls straight down before it meets the floor or a disc
 * of another body (m): over the grid g's cells at or below its own in its
 * column and the two beside it, or over every disc without a grid. */
static double drop_of(const gw_layer_body *b, int n, int i, const layer_grid *g)
{
    double d = b[i].y - b[i].r;
    if (!g) {
        for (int j = 0; j < n; j++)
            d = drop_onto(b, i, j, d);
        return d > 0 ? d : 0;
    }
    const long cx = g->cell[i] % g->nx, cy = g->cell[i] / g->nx;
    for (long ky = cy; ky >= 0; ky--)
        for (long kx = cx - 1; kx <= cx + 1; kx++) {
            if (kx < 0 || kx >= g->nx)
                continue;
            for (int q = g->start[ky * g->nx + kx]; q < g->start[ky * g->nx + kx + 1]; q++)
                d = drop_onto(b, i, g->idx[q], d);
        }
    return d > 0 ? d : 0;
}

/* The energy (J) the bodies of the n discs b that touch nothing (no wall, no
 * disc of another body) will have gained when they land: under gravity they
 * are in flight, m g times the shortest straight drop of their discs (a clump
 * by the sum of its discs' masses). The count stops once it reaches budget
 * (the pile is not settled then, whatever the rest). -1 for out of memory. */
static double airborne(const gw_layer_params *lp, const gw_layer_body *b, int n, double budget)
{
    int cmax = 0;
    for (int i = 0; i < n; i++)
        cmax = b[i].clump > cmax ? b[i].clump : cmax;
    unsigned char *touch = malloc((size_t)n + (size_t)cmax + 1), *held = touch ? touch + n : NULL;
    double *cm = malloc(2 * ((size_t)cmax + 1) * sizeof *cm), *cd = cm ? cm + cmax + 1 : NULL;
    if (!touch || !cm) {
        free(touch), free(cm);
        return -1;
    }
    layer_grid g = {0}; /* one grid for the contacts and the drops */
    const int grid = disc_grid(b, n, &g);
    overlaps_in(b, n, lp->width, touch, grid ? &g : NULL);
    for (int c = 0; c <= cmax; c++)
        held[c] = 0, cm[c] = 0, cd[c] = INFINITY;
    for (int i = 0; i < n; i++) /* a clump touches through any of its discs */
        if (b[i].clump > 0 && touch[i])
            held[b[i].clump] = 1;
    double e = 0;
    for (int i = 0; i < n && e < budget; i++) {
        const int c = b[i].clump;
        if (touch[i] || (c > 0 && held[c]))
            continue;
        const double m = gw_layer_mass(lp, b[i].r), d = drop_of(b, n, i, grid ? &g : NULL);
        if (c > 0)
            cm[c] += m, cd[c] = fmin(cd[c], d);
        else
            e += m * lp->gravity * d;
    }
    for (int c = 1; c <= cmax && e < budget; c++)
        if (cm[c] > 0)
            e += cm[c] * lp->gravity * cd[c];
    layer_grid_free(&g);
    free(touch), free(cm);
    return e;
}

/* The positions of the n particles of L into b. */
static void take_positions(const gw_layer *L, int n, gw_layer_body *b)
{
    for (int i = 0; i < n; i++) {
        double s[6];
        gw_layer_particle(L, i, s);
        b[i].x = s[0], b[i].y = s[1];
    }
}

/* Settle bodies b (positions updated, velocities zeroed) with the given G.
 * Returns the simulated time in *t and the final kinetic energy in *ke. */
#define SETTLE_CHUNK LAYER_SETTLE_CHUNK /* s: the energy is looked at every chunk */
#define SETTLE_CHUNKS_MIN 10 /* chunks before the pile may be called settled */
/* (successive checks for a pile the side walls help hold: LAYER_WALL_CALM_CHECKS, layer_impl.h) */
#define SETTLE_WALL_CALM_CHECKS LAYER_WALL_CALM_CHECKS

/* When settle() may first call the pile settled: SETTLE_CHUNKS_MIN chunks, and
 * the lowest body's free fall t_land = sqrt(2 gap / g) to the floor. */
static double settle_judge(const gw_layer_params *lp, int n, const gw_layer_body *b)
{
    double gap = INFINITY;
    for (int i = 0; i < n; i++)
        gap = fmin(gap, b[i].y - b[i].r);
    const double t_land = gap > 0 ? sqrt(2 * gap / lp->gravity) : 0;
    return fmax(SETTLE_CHUNKS_MIN * SETTLE_CHUNK, t_land);
}

/* The tangential springs of the last settle() (layer_springs_take): each
 * settle replaces them, so that they are those of the positions written. */
typedef struct make_springs {
    gw_layer_spring *s;
    int n;
} make_springs;

/* The springs of L's contacts at the n settled positions b into ks. */
static int keep_springs(const gw_layer *L, double width, int n, const gw_layer_body *b, make_springs *ks,
                        gw_err *err)
{
    free(ks->s);
    ks->s = NULL;
    ks->n = 0;
    double *x = malloc(3 * (size_t)n * sizeof *x);
    if (!x)
        return gw_err_set(err, GW_ENOMEM, "layer-make: out of memory");
    for (int i = 0; i < n; i++)
        x[i] = b[i].x, x[n + i] = b[i].y, x[2 * n + i] = b[i].r;
    int rc = layer_springs_take(L, x, x + n, x + 2 * n, width, &ks->s, &ks->n);
    free(x);
    return rc == GW_OK ? GW_OK : gw_err_set(err, rc, "layer-make: out of memory");
}

/* A pile whose floor carries f of its weight w (N) outside [LAYER_FLOOR_LOAD_MIN,
 * LAYER_FLOOR_LOAD_MAX] w (layer_impl.h) is at rest when the side walls'
 * friction makes up the difference: the floor and the side walls together
 * carry between LAYER_FLOOR_LOAD_MIN and LAYER_FLOOR_LOAD_MAX times the weight
 * (layer_side_walls_fy: their contact forces in L's state, upward), as a pile
 * whose centre of mass does not accelerate does (their sum is its weight). In
 * the air or at the top of a bounce neither carries anything; swinging on its
 * contacts, the floor's excess is not the walls'. Narrow clump piles within
 * CLUMP_ASPECT_MAX ended unsettled at t-max 6 s, E_k 1e-4 to 1e-2 of the
 * threshold, only for want of this:
 * `layer-make --clumps --width-rm 6 --n 60` seeds 1 and 2, floors at 0.447 and
 * 0.203 of the weight and the side walls holding 0.539 and 0.811 of it (0.985
 * and 1.014 together). The walls hold down as well as up: a pile thrown up
 * by its landing and caught by the walls' friction on its way back rests
 * pressed onto its floor, the walls pulling it down. `--clumps --width-rm 6
 * --n 40 --seed 3` (and `--width-rm 8 --n 80 --seed 1`) ended unsettled at
 * t-max with E_k 1e-2 of the threshold from 2.5 s on, the floor at 1.60 of the
 * weight (1.56) and the walls at -0.60 (0.999 together, steady from 2.5 to
 * 6 s): at rest, refused for the floor's load alone. */
static int held_by_walls(const gw_layer *L, double f, double w)
{
    return layer_load_rests(f, layer_side_walls_fy(L, L->y), w);
}

/* The share of the kinetic energy (translation and rotation) that the one
 * body (clump or disc) of L with the most holds, in [0, 1] (0: nothing
 * moves). A pile that did not settle is told apart from one grain moving on a
 * pile at rest: `--clumps --width-rm 6 --n 40 --seed 4` from 3 s on has its
 * centre of mass within 3 mm (0.1 mm from 4.3 s), its floor at 2.25 of its
 * weight and its walls at -1.25 (together 0.999 at the median), and a median
 * 0.82 of its E_k in its last clump dropped, which rolls to and fro on the
 * pile's top until 6.41 s (settled then, at t-max 8). */
static double top_grain_share(const gw_layer *L)
{
    double sum = 0, top = 0;
    for (int q = 0; q < L->nb; q++) {
        const double *z = L->y + 6 * q;
        const double k = 0.5 * (L->m[q] * (z[3] * z[3] + z[4] * z[4]) + L->inertia[q] * z[5] * z[5]);
        sum += k, top = fmax(top, k);
    }
    return sum > 0 ? top / sum : 0;
}

static int settle(const gw_layer_params *lp, const gw_layer_make_params *m, double t0, double t_max, int n,
                  gw_layer_body *b, double thr, double *t, double *ke, int *conv,
                  long *steps, long *rebuilds, double *top_share, make_springs *ks, gw_err *err)
{
    gw_layer *L = NULL;
    int rc = gw_layer_create(lp, n, b, &L, err);
    if (rc != GW_OK)
        return rc;
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = m->dt;
    /* the steps of one chunk (an advance call): the solver's default bound,
     * 1e7 per call, failed every dt at or below 1e-9 s in the first chunk,
     * after 1e7 steps and naming no input, where the validation's bound on
     * the whole settling (1e9 steps to t-max) let the run through */
    const double chunk_steps = ceil(fmin(SETTLE_CHUNK, t_max) / m->dt) + 2;
    if (chunk_steps > (double)sp.max_steps)
        sp.max_steps = (long)chunk_steps;
    rc = gw_layer_start(L, m->solver, &sp, err);
    *conv = 0;
    /* the lowest body falls freely for t_land = sqrt(2 gap / g) before anything
     * touches: a kinetic energy below the threshold before then is a pile still
     * in the air (g = 1e-9 m/s^2 had E_k below it at 0.1 s and called the
     * initial grid settled) */
    double gap = INFINITY;
    for (int i = 0; i < n; i++)
        gap = fmin(gap, b[i].y - b[i].r);
    const double t_land = gap > 0 ? sqrt(2 * gap / lp->gravity) : 0;
    const double chunk = SETTLE_CHUNK;
    /* chunks of 0.01 s, the last one ending at t_max (a t_max below one chunk
     * ran no step at all) */
    int calm = 0; /* successive checks passed (SETTLE_WALL_CALM_CHECKS) */
    for (int k = 1; rc == GW_OK && (k - 1) * chunk < t_max * (1 - 1e-12); k++) {
        const double tk = fmin(k * chunk, t_max);
        rc = gw_layer_advance(L, tk, err);
        gw_layer_energy e;
        gw_layer_energy_of(L, &e);
        *ke = e.kinetic_soil + e.kinetic_block;
        *t = tk;
        /* done and total in chunks of the whole settling (t0 before this phase) */
        if (rc == GW_OK && m->progress &&
            m->progress(m->progress_ctx, lround((t0 + tk) / chunk), (long)ceil(m->t_max / chunk - 1e-9)) != 0) {
            rc = gw_err_set(err, GW_ECANCELED, "stopped by the progress callback at t = %.4g s of settling", t0 + tk);
            break;
        }
        int passed = 0, on_floor = 0; /* the rest rules; the floor alone carrying the pile */
        if (k >= SETTLE_CHUNKS_MIN && tk >= t_land && *ke < thr) {
            /* and resting on the floor: a pile still swinging on its contacts
             * has a small E_k at its turning points, where its floor carries
             * many times its weight (`--n 1` was called settled with 26.2
             * times, `--n 5 --width-rm 50` with 1.55, and layer-impact refused
             * both samples), or, at the top of a bounce, little of it (`--n 20
             * --ke-threshold 0.1` to 1 with 0, the pile in the air, 0.01 with
             * 0.47: LAYER_FLOOR_LOAD_MIN) */
            take_positions(L, n, b);
            double f, w;
            layer_floor_load(lp, n, &b[0].y, &b[0].r, sizeof *b, &f, &w);
            /* (a floor carrying less than LAYER_FLOOR_LOAD_MIN or more than
             * LAYER_FLOOR_LOAD_MAX: the side walls' friction holding the rest
             * up or pulling the pile down, as in a narrow box, is a pile at
             * rest too, the two carrying its weight: held_by_walls) */
            on_floor = f >= LAYER_FLOOR_LOAD_MIN * w && !(f > LAYER_FLOOR_LOAD_MAX * w);
            const int rests = on_floor || held_by_walls(L, f, w);
            /* and the bodies in flight counted with the energy they will
             * land with: a disc at the top of a bounce has E_k near 0 too
             * (`--n 1` was next caught 3 mm above the floor, 26 J of fall
             * against a threshold of 0.028 J) */
            const double fall = rests ? airborne(lp, b, n, thr - *ke) : -1;
            passed = fall >= 0 && *ke + fall < thr;
        }
        calm = passed ? calm + 1 : 0;
        if (passed && (on_floor || calm >= SETTLE_WALL_CALM_CHECKS)) {
            *conv = 1;
            break;
        }
    }
    if (rc == GW_OK) /* the grain that moves most and its share of E_k there */
        *top_share = top_grain_share(L);
    if (rc == GW_OK)
        take_positions(L, n, b);
    if (rc == GW_OK) /* the springs the pile leans on there (gw_layer_spring) */
        rc = keep_springs(L, lp->width, n, b, ks, err);
    for (int i = 0; rc == GW_OK && i < n; i++)
        b[i].vx = b[i].vy = b[i].w = 0;
    gw_layer_stats st;
    gw_layer_get_stats(L, &st);
    *steps += st.steps;
    *rebuilds += st.rebuilds;
    gw_layer_free(L);
    return rc;
}

/* The pluviation box: the layer parameters of lp0 with the box of m, all walls,
 * settling damping, no event location (a settling pile chatters: thousands of
 * contact events/s). */
static int box_params(const gw_layer_params *lp0, const gw_layer_make_params *m, gw_layer_params *lp,
                      gw_err *err)
{
    *lp = *lp0;
    lp->width = m->width_rm * m->rm;
    lp->walls = GW_LAYER_WALLS_ALL;
    lp->damping = m->damping;
    lp->potential_from_start = 0;
    lp->no_events = 1;
    return gw_layer_params_validate(lp, err);
}

/* Settle the n discs b (softened by modulus_factor first when it is < 1) until
 * the kinetic energy is below ke_threshold M g R_m; b receives the settled
 * positions. */
/* The kinetic energy below which the n particles b are settled: ke_threshold M g R_m. */
static double settle_threshold(const gw_layer_params *lp, const gw_layer_make_params *m, int n,
                               const gw_layer_body *b)
{
    double mtot = 0;
    for (int i = 0; i < n; i++)
        mtot += gw_layer_mass(lp, b[i].r);
    return m->ke_threshold * mtot * lp->gravity * m->rm;
}

static int settle_all(const gw_layer_params *lp, const gw_layer_make_params *m, int n, gw_layer_body *b,
                      double *t, double *ke, int *conv, gw_layer_make_result *res, make_springs *ks, gw_err *err)
{
    const double thr = settle_threshold(lp, m, n, b);
    res->ke_limit = thr;
    int rc = GW_OK;
    *t = *ke = 0;
    *conv = 0;
    /* (with a soft phase, the relaxation's own chunks come after it) */
    res->t_judge = settle_judge(lp, n, b) + (m->modulus_factor < 1 ? SETTLE_CHUNKS_MIN * SETTLE_CHUNK : 0);
    /* t_max bounds the whole settling (the work bound counts t_max / dt
     * steps): with modulus_factor < 1 the soft phase takes at most half of it
     * and the relaxation the rest (each ran to t_max: --t-max 0.05 settled
     * for 0.1 s, 5000 steps, twice the bound's count) */
    if (m->modulus_factor < 1) {
        gw_layer_params soft = *lp;
        soft.shear_modulus *= m->modulus_factor;
        double ts = 0;
        rc = settle(&soft, m, 0.0, 0.5 * m->t_max, n, b, thr, &ts, ke, conv, &res->steps, &res->rebuilds,
                    &res->ke_top_share, ks, err);
        *t += ts;
        /* the soft pile may sink into a wall: the relaxation cannot start from
         * there (it was refused naming no input, exit 2) */
        for (int i = 0; rc == GW_OK && i < n; i++)
            if (b[i].x < 0 || b[i].x > lp->width || b[i].y < 0)
                rc = gw_err_set(err, GW_ESOLVER, "the pile did not settle: at modulus-factor %g the soft pile sank "
                                "into a wall (particle %d at (%.4g, %.4g) m, box 0 <= x <= %g, y >= 0); raise "
                                "modulus-factor", m->modulus_factor, i, b[i].x, b[i].y, lp->width);
    }
    if (rc == GW_OK) {
        double tr = 0;
        rc = settle(lp, m, *t, m->t_max - *t, n, b, thr, &tr, ke, conv, &res->steps, &res->rebuilds,
                    &res->ke_top_share, ks, err);
        *t += tr;
    }
    return rc;
}

/* A trim to height_rm takes the top of a settled pile away, but the kept
 * particles still hold the overlaps the removed ones' weight pressed into
 * them: `layer-make --seed 1 --height-rm 8` wrote a 91-disc sample whose floor
 * carried 3.37 times its weight, which layer-impact refuses (its strain energy
 * would go into the impact). The kept pile settles again under its own weight
 * (every velocity zero, the same damping and threshold), within what is left of
 * t_max; it is judged after SETTLE_CHUNKS_MIN chunks of it. */
/* A trim to height_rm that took nothing away (the settled pile's top at or
 * below it): the sample is the whole pile, as with height_rm 0; its top (R_m)
 * is kept for the warning (gw_layer_make_result_warnings). */
static void note_untrimmed(const gw_layer_make_params *m, const gw_layer_body *b, int n, gw_layer_make_result *res)
{
    if (!(m->height_rm > 0) || res->n_removed > 0)
        return;
    double top = 0;
    for (int i = 0; i < n; i++)
        top = fmax(top, b[i].y + b[i].r);
    res->untrimmed_top_rm = top / m->rm;
}

static int relax_trimmed(const gw_layer_params *lp, const gw_layer_make_params *m, int n, gw_layer_body *b,
                         double *t, double *ke, int *conv, gw_layer_make_result *res, make_springs *ks,
                         gw_err *err)
{
    const double thr = settle_threshold(lp, m, n, b);
    res->ke_limit = thr; /* the kept pile's */
    res->t_judge = *t + SETTLE_CHUNKS_MIN * SETTLE_CHUNK;
    double tr = 0;
    int rc = settle(lp, m, *t, m->t_max - *t, n, b, thr, &tr, ke, conv, &res->steps, &res->rebuilds,
                    &res->ke_top_share, ks, err);
    *t += tr;
    return rc;
}

/* The sample's header and the result, once out->x, y, r (and body) hold the
 * n settled discs b. */
static void finish(const gw_layer_params *lp, const gw_layer_make_params *m, const gw_layer_body *b,
                   int n, double t, double ke, int conv, double t0, gw_layer_sample *out,
                   gw_layer_make_result *res)
{
    out->n = n;
    out->width = lp->width;
    out->rm = m->rm;
    out->volume_ratio = m->volume_ratio;
    out->seed = m->seed;
    out->mass_law = lp->mass_law;
    out->clump_mass = lp->clump_mass;
    /* the material the pile came to rest under (the true G after a softened
     * start), as the settings line of the file written records it */
    out->settled = (gw_layer_settled){.recorded = 1, .shear_modulus = lp->shear_modulus, .poisson = lp->poisson,
                                      .friction_deg = lp->friction_deg, .density = lp->density,
                                      .gravity = lp->gravity, .mass_law = lp->mass_law,
                                      .clump_mass = lp->clump_mass, .unsettled = !conv};
    out->settled_converged = conv;
    res->max_overlap = max_overlap(b, n, lp->width, NULL);
    out->porosity = layer_sample_porosity_of(out); /* (checked with the sample, settled_readable) */
    res->porosity = out->porosity;
    res->t_settle = t;
    res->ke_final = ke;
    res->converged = conv;
    double f, w;
    layer_floor_load(lp, n, &b[0].y, &b[0].r, sizeof *b, &f, &w);
    res->floor_load = f / w;
    /* the side walls' share as layer-impact's rest check finds it: from the
     * springs the sample keeps against them (layer_sample_wall_hold) */
    res->wall_load = out->springs ? layer_sample_wall_hold(out, lp, lp->friction_deg) / w : 0;
    res->fall_energy = airborne(lp, b, n, INFINITY);
    res->n_discs = n;
    res->wall_ms = gw_clock_ms() - t0;
}

/* Initial clumps: shapes drawn per clump, packed in rows of bounding boxes.
 * Returns the number of discs (members) in *nd, and in tops[j] (tops may be
 * NULL) the top of the rows (m) once clump j is placed; b (NULL: count only)
 * has room for them. Returns the rows' top; stops early (b NULL) once it is
 * above stop (INFINITY: never), the top never falling as clumps are placed. */
static double clumps_initial(const gw_layer_make_params *m, double width, gw_layer_body *b, int *nd, double *tops,
                             double stop)
{
    const double cv = cbrt(m->volume_ratio), rmin = 2 * m->rm / (1 + cv), rmax = cv * rmin;
    const double gap = 0.1 * rmax;
    splitmix64 g = {(unsigned long long)m->seed};
    double cx = gap, ry = gap, rowh = 0;
    int k = 0;
    for (int j = 0; j < m->n; j++) {
        double req, aspect, angle;
        clump_draw(&g, rmin, rmax, m->aspect_max, &req, &aspect, &angle);
        double ox[LAYER_CLUMP_MAX], oy[LAYER_CLUMP_MAX], r[LAYER_CLUMP_MAX];
        int km = 0;
        double x0, x1, y0, y1;
        for (int pass = 0; pass < 2; pass++) { /* too wide for the box: stood upright */
            km = layer_clump_shape(req, aspect, pass ? 0.5 * M_PI : angle, ox, oy, r);
            x0 = y0 = INFINITY, x1 = y1 = -INFINITY;
            for (int q = 0; q < km; q++) {
                x0 = fmin(x0, ox[q] - r[q]), x1 = fmax(x1, ox[q] + r[q]);
                y0 = fmin(y0, oy[q] - r[q]), y1 = fmax(y1, oy[q] + r[q]);
            }
            if (x1 - x0 <= width - 2 * gap)
                break;
        }
        if (cx + (x1 - x0) > width - gap && cx > gap) { /* next row */
            ry += rowh + gap;
            cx = gap, rowh = 0;
        }
        double xc = cx - x0, yc = ry - y0;
        if (xc + x1 > width) /* a clump wider than the box: centred, it settles tilted */
            xc = 0.5 * width;
        for (int q = 0; q < km; q++)
            if (b)
                b[k++] = (gw_layer_body){.x = xc + ox[q], .y = yc + oy[q], .r = r[q], .clump = j + 1};
            else
                k++;
        cx += (x1 - x0) + gap;
        rowh = fmax(rowh, y1 - y0);
        if (tops)
            tops[j] = ry + rowh;
        if (!b && ry + rowh > stop)
            break;
    }
    *nd = k;
    return ry + rowh;
}

/* The settled pile must be a sample the reader takes: discs sunk into a wall
 * (--shear-modulus 1e-3 Pa: through the floor) or into each other beyond the
 * reader's tolerances (0.02 R, 0.05 R_p) were refused only when writing,
 * blaming the output file. GW_ESOLVER (a run that failed, not a bad input);
 * out is freed. */
static int settled_readable(gw_layer_sample *out, gw_err *err)
{
    int rc = layer_sample_readable(out, "settled", err);
    if (rc == GW_OK)
        return GW_OK;
    char why[sizeof err->msg];
    gw_snprintf(why, sizeof why, "%s", err->msg);
    gw_layer_sample_free(out);
    memset(out, 0, sizeof *out);
    return gw_err_set(err, GW_ESOLVER, "the pile did not settle into a valid sample (%s): its contacts are too "
                      "soft for their load (raise shear-modulus, lower density or gravity)", why);
}

/* A clump pile far taller than its box is wide: the clumps start in rows of
 * their bounding boxes (clumps_initial), one or two a row in a box a few
 * grains wide; the top rows fall the rows' height, and the rigid, elongated
 * clumps lean on the walls and wedge between them far more readily than
 * discs. The rule of the discs (COLUMN_ASPECT_MAX) on the rows' top over the
 * box's width, with the clumps' own bound. Measured at the defaults (V 10,
 * aspect-max 4, t-max 6 s, seed 1): `--clumps --width-rm 8 --n 600` (rows
 * 223 m high, 86 times the width; its top falls longer than t-max) and
 * width-rm 4 at n 100 (54 times) and 40 (23 times) ended outside the box (a
 * member disc 2.3 to 2.9 % of its radius into a wall: wedged); every pile
 * measured at most 44 times as high as wide in a box of width-rm 5 or more
 * stayed within 2 %: 8 at n 140 (20 times) settled with a wedged clump 1.9 %
 * into a wall, 8 at n 300 (44 times) 1.8 % at 5.5 s (stopped there after 20
 * minutes of wall time under load); width-rm 5 at n 40 (15
 * times) and 6 at n 30 (8 times) settled (floors carrying 0.67 and 0.76 of the
 * weight), while 6 at n 60 and 80 (16 and 20 times), 5 at n 100 (35 times)
 * and 8 at n 300 ended unsettled, the walls' friction holding 56, 63, 75 and
 * 58 % of the weight (a warning names the floor's load). The bound keeps
 * below the 20 where a wedged clump came within 0.1 % of the reader's 2 %.
 * (A box of 5 R_m or less is now refused first, check_clump_flat; of the piles
 * within the bound that ended unsettled, those whose side walls hold what the
 * floor does not are now settled, held_by_walls.) */
#define CLUMP_ASPECT_MAX 16

/* 1 when the clumps of m start in rows within CLUMP_ASPECT_MAX times the
 * width w (m) of their box */
static int clumps_fit(const gw_layer_make_params *m, double w)
{
    int nd;
    return clumps_initial(m, w, NULL, &nd, NULL, CLUMP_ASPECT_MAX * w) <= CLUMP_ASPECT_MAX * w;
}

/* The width of three significant digits (in R_m) after wr: its text in
 * buf, its value returned (read back from the text, as the flag is read). */
static double width_next(double wr, char *buf, size_t size)
{
    const double step = pow(10, floor(log10(wr)) - 2);
    double v = (floor(wr / step + 1e-6) + 1) * step;
    gw_snprintf(buf, size, "%.3g", v);
    v = gw_strtod(buf, NULL);
    if (!(v > wr)) { /* a decade's edge rounded down: one step further */
        gw_snprintf(buf, size, "%.3g", v + 1.5 * step);
        v = gw_strtod(buf, NULL);
    }
    return v;
}

/* The clumps of m in a box of width w m (tops: their rows' tops, as
 * clumps_initial gives them) refused when the rows stand more than
 * CLUMP_ASPECT_MAX times as high as the box is wide, naming the n and the
 * widths that pass, each checked: the first clumps drawn are the same
 * whatever n; the rows' top is not monotonic in the width (the rows repack:
 * n 1500 in width-rm 30.7 passes, 30.8 not, 30.9 again), so a width is named
 * with the range of three-digit widths above it found to pass, never as "W or
 * more" (which 30.7 would not have been). */
static int check_clump_column(const gw_layer_make_params *m, double w, double *tops, gw_err *err)
{
    const double top = tops[m->n - 1];
    if (top <= CLUMP_ASPECT_MAX * w)
        return GW_OK;
    int fit = 0; /* the most clumps that pass: the first ones whose rows stay within the bound */
    while (fit < m->n && tops[fit] <= CLUMP_ASPECT_MAX * w)
        fit++;
    /* the width: from 0.9 of the estimate of an aspect falling as 1/w^2 (rows
     * of w / size clumps: a top as 1/w), up the widths of three digits to
     * the first that passes, W; then every one from W to hi (1.25 W, at most
     * 50 widths on) checked, W moved above any refused (the search ends at
     * the flag's bound, 1e6 R_m: then no width is named) */
    char wt[40], wb[40] = "", wn[40], wh[40] = "";
    const double wmax = 1e6;
    double wr = width_next(fmax(w / m->rm, 0.9 * w / m->rm * sqrt(top / (CLUMP_ASPECT_MAX * w))), wn, sizeof wn);
    while (wr <= wmax && !wb[0]) {
        while (wr <= wmax && !clumps_fit(m, wr * m->rm))
            wr = width_next(wr, wn, sizeof wn);
        if (wr > wmax)
            break;
        const double lo = wr;
        gw_snprintf(wb, sizeof wb, "%s", wn);
        double hi = fmin(1.25 * lo, wmax);
        for (int k = 0; k < 50; k++) {
            const double nx = width_next(wr, wn, sizeof wn);
            if (nx > hi)
                break;
            wr = nx;
            gw_snprintf(wh, sizeof wh, "%s", wn);
            if (!clumps_fit(m, wr * m->rm)) { /* refused above W: search again above it */
                wb[0] = wh[0] = '\0';
                wr = width_next(wr, wn, sizeof wn);
                break;
            }
        }
        if (wb[0] && !wh[0]) /* W the flag's bound itself */
            gw_snprintf(wh, sizeof wh, "%s", wb);
    }
    char widen[160] = "";
    if (wb[0])
        gw_snprintf(widen, sizeof widen, ", or widen the box to --width-rm %s (each width of three digits from %s to %s "
                    "passes; the rows repack as the width changes: one below or above may not)", wb, wb, wh);
    return gw_err_set(err, GW_EINVAL, "n: %d clumps in a box of --width-rm %s start in rows %.4g m high (their "
                      "bounding boxes packed from the floor), %.4g times as high as the box is wide, above %d: a "
                      "pile so tall in a box so narrow does not settle; lower --n to %d%s", m->n,
                      gw_num_text(wt, sizeof wt, m->width_rm), top, top / w, CLUMP_ASPECT_MAX, fit, widen);
}

/* t0: gw_clock_ms() at the start of gw_layer_make (for res->wall_ms). */
static int make_clumps(const gw_layer_params *lp0, const gw_layer_make_params *m, double t0,
                       gw_layer_sample *out, gw_layer_make_result *res, gw_err *err)
{
    gw_layer_params lp;
    int rc = box_params(lp0, m, &lp, err);
    if (rc != GW_OK)
        return rc;
    /* the member discs counted first (the shapes drawn, nothing stored): the
     * work bound of check_work on them (--clumps --n 100000 ran on for hours as
     * the discs' pluviation did) before anything is allocated (the library's
     * n = 1e6 held 6e6 bodies, 336 MB, before it was refused) */
    int nd = 0;
    double *tops = malloc((size_t)m->n * sizeof *tops);
    if (!tops)
        return gw_err_set(err, GW_ENOMEM, "layer-make: out of memory");
    clumps_initial(m, lp.width, NULL, &nd, tops, INFINITY);
    const double steps = m->t_max / m->dt;
    if (steps * nd > 1e10)
        rc = gw_err_set(err, GW_EINVAL, "n: %d clumps (%d discs) over %.3g steps to t-max = %g s are about %.3g "
                        "particle-steps, more than 1e10: lower n to %.0f, or t-max, or raise dt", m->n, nd, steps,
                        m->t_max, steps * nd, floor(1e10 / steps * m->n / nd));
    else
        rc = check_clump_column(m, lp.width, tops, err);
    free(tops);
    if (rc != GW_OK)
        return rc;
    gw_layer_body *b = calloc((size_t)nd, sizeof *b);
    if (!b)
        return gw_err_set(err, GW_ENOMEM, "layer-make: out of memory");
    clumps_initial(m, lp.width, b, &nd, NULL, INFINITY);
    double t, ke;
    int conv;
    if ((rc = check_step(&lp, m, b, nd, err)) != GW_OK) {
        free(b);
        return rc;
    }
    make_springs ks = {0};
    rc = settle_all(&lp, m, nd, b, &t, &ke, &conv, res, &ks, err);
    /* keep the clumps lying wholly below height_rm R_m; ids renumbered 0.. */
    int kept = 0, nbody = 0;
    for (int a = 0; rc == GW_OK && a < nd;) {
        int e = a;
        double top = 0;
        while (e < nd && b[e].clump == b[a].clump)
            top = fmax(top, b[e].y + b[e].r), e++;
        if (!(m->height_rm > 0) || top <= m->height_rm * m->rm) {
            for (int q = a; q < e; q++) {
                b[kept] = b[q];
                b[kept++].clump = nbody + 1; /* 0 is "no clump" in a gw_layer_body */
            }
            nbody++;
        } else {
            res->n_removed++;
        }
        a = e;
    }
    if (rc == GW_OK && kept == 0)
        rc = gw_err_set(err, GW_EINVAL, "height-rm: no clump lies below %g R_m", m->height_rm);
    if (rc == GW_OK)
        note_untrimmed(m, b, kept, res);
    if (rc == GW_OK && res->n_removed > 0)
        rc = relax_trimmed(&lp, m, kept, b, &t, &ke, &conv, res, &ks, err);
    if (rc == GW_OK) {
        out->x = malloc(3 * (size_t)kept * sizeof *out->x);
        out->body = malloc((size_t)kept * sizeof *out->body);
        if (!out->x || !out->body)
            rc = gw_err_set(err, GW_ENOMEM, "layer-make: out of memory");
    }
    if (rc != GW_OK) {
        free(ks.s);
        free(b);
        gw_layer_sample_free(out);
        memset(out, 0, sizeof *out);
        return rc;
    }
    out->y = out->x + kept;
    out->r = out->x + 2 * kept;
    for (int i = 0; i < kept; i++) {
        out->x[i] = b[i].x, out->y[i] = b[i].y, out->r[i] = b[i].r;
        out->body[i] = b[i].clump - 1;
    }
    out->springs = ks.s, out->n_springs = ks.n; /* the last settle's: the kept clumps' indices */
    finish(&lp, m, b, kept, t, ke, conv, t0, out, res);
    free(b);
    res->n_bodies = nbody;
    return settled_readable(out, err);
}

/* A pile far taller than its box is wide cannot be pluviated: it starts as a
 * lattice ceil(n / ncol) rows high and ncol columns wide, its top rows fall
 * the height of the lattice, and in a box a few particles wide the discs wedge
 * between the walls, locking in forces many times the pile's weight (a floor
 * carrying 0.17 to 5.1 times it, or a disc pressed into a wall beyond the
 * reader's 0.02 R: a force near 19 MN, seven times the weight of the whole
 * pile). The lattice's height over the box's width is bounded: measured at
 * the defaults (V 10, t-max 12 s), 300 discs in a box of width-rm 4, 5 (seeds
 * 1 and 2) and 6, one column at 225, 180 and 150 times its width, ended
 * outside the box (a disc 2.0 to 3.5 % of its radius into a wall); 300 in
 * width-rm 6.1 and 8 (two columns, 75 and 56 times) settled (1.4 and 0.6 %),
 * and every pile measured at most 99 times as high as wide (400 in width-rm
 * 6.1, 100 in 5 and 6, 300 in 7, 10 and 12) stayed within 1.5 %, settled or
 * not (a narrow pile may end unsettled, its floor's load named: a warning). */
#define COLUMN_ASPECT_MAX 100

/* The lattice of n discs at pitch p in a box of width w (m): its columns
 * (as gw_layer_make lays them) and its height over w. */
static int lattice_columns(double w, double p)
{
    return (int)(w / p) > 0 ? (int)(w / p) : 1;
}

static double lattice_aspect(int n, double w, double p)
{
    const int ncol = lattice_columns(w, p);
    return ceil((double)n / ncol) * p / w;
}

/* The narrowest box (m) whose lattice of n discs at pitch p is at most
 * COLUMN_ASPECT_MAX times as high as wide: ncol columns fill widths in
 * [ncol p, (ncol + 1) p), at the height ceil(n / ncol) p. The aspect never
 * rises with the width (within a count of columns the height holds while the
 * width grows; a column more never adds a row), so every wider box passes
 * too: check_column's "--width-rm W or more" holds, unlike the clumps' rows
 * (check_clump_column). */
static double column_width_min(int n, double p)
{
    for (long c = 1;; c++) {
        const double w = fmax((double)c * p, ceil((double)n / c) * p / COLUMN_ASPECT_MAX);
        if (w < (double)(c + 1) * p)
            return w;
    }
}

/* The disc lattice of n discs at pitch p in the box of m (width w m) refused
 * when it stands more than COLUMN_ASPECT_MAX times as high as the box is wide,
 * naming the n and the width that pass. */
static int check_column(const gw_layer_make_params *m, int n, double w, double p, gw_err *err)
{
    const double aspect = lattice_aspect(n, w, p);
    if (aspect <= COLUMN_ASPECT_MAX)
        return GW_OK;
    const int ncol = lattice_columns(w, p);
    const double nmax = (double)ncol * floor(COLUMN_ASPECT_MAX * w / p);
    char wt[40], wb[40];
    /* (the width a hair above the bound, so that the text read back passes) */
    gw_num_bound(wb, sizeof wb, column_width_min(n, p) * (1 + 1e-9) / m->rm, 0);
    return gw_err_set(err, GW_EINVAL, "n: %d particles in a box of --width-rm %s start as a lattice %.0f rows high "
                      "and %d column%s wide (pitch %.3g m), %.4g times as high as the box is wide, above %d: a pile "
                      "so tall in a box so narrow wedges between the walls as it falls and does not settle; lower "
                      "--n to %.0f, or widen the box to --width-rm %s or more", n,
                      gw_num_text(wt, sizeof wt, m->width_rm), ceil((double)n / ncol), ncol, ncol > 1 ? "s" : "", p,
                      aspect, COLUMN_ASPECT_MAX, nmax, wb);
}

/* The pluviation's work bounded before the run, as an impact's
 * (layer_impact.c): steps to t-max x (particles + listed pairs) at most 1e10
 * particle-steps. The pairs are counted on the initial grid (pitch p, ncol
 * columns; a pair is listed within R_a + R_b + skin, at most 2 r_max + skin):
 * about n/2 (2k+1) min(ncol, 2k+1) pairs, k = floor((2 r_max + skin)/p); the
 * settled pile lists more. Unbounded before: --n 100000 at the defaults took
 * up to 3e10 particle-steps (hours, no line said so), --rm 1e-3 --n 3000 with
 * the 0.1 m skin listed 1.7e6 pairs and ran 500 steps in more than 30 s of the
 * 3e5 to t-max; --rm 1e-3 --n 24000 held 2.3 GB of pairs. */
static int check_work(const gw_layer_make_params *m, int n, int ncol, double pitch, double rmax, double skin,
                      gw_err *err)
{
    const double k = floor((2 * rmax + skin) / pitch), nrow = ceil((double)n / ncol);
    const double listed = 0.5 * n * (fmin(nrow, 2 * k + 1) * fmin(ncol, 2 * k + 1) - 1);
    const double steps = m->t_max / m->dt, work = steps * (n + listed);
    if (work <= 1e10 && listed <= 1e7) /* a listed pair holds about 170 B (2.3 GB for 1.3e7) */
        return GW_OK;
    if (listed > 8.0 * n)
        return gw_err_set(err, GW_EINVAL, "skin: %g m lists about %.3g pairs of the %d particles (%.3g steps to t-max, %.3g "
                          "particle-steps; at most 1e10, and 1e7 pairs): lower the skin toward R_m = %g m",
                          skin, listed, n, steps, work, m->rm);
    return gw_err_set(err, GW_EINVAL, "n: %d particles over %.3g steps to t-max = %g s are about %.3g particle-steps, "
                      "more than 1e10: lower n to %.0f, or t-max, or raise dt", n, steps, m->t_max, work,
                      floor(1e10 / (steps * (1 + listed / n))));
}

int gw_layer_make(const gw_layer_params *lp0, const gw_layer_make_params *m,
                  gw_layer_sample *out, gw_layer_make_result *res, gw_err *err)
{
    if (!m || !out || !res) {
        if (out)
            memset(out, 0, sizeof *out);
        if (res)
            memset(res, 0, sizeof *res);
        return gw_err_set(err, GW_EINVAL, "gw_layer_make: %s is NULL", !m ? "mp" : !out ? "out" : "res");
    }
    memset(out, 0, sizeof *out);
    memset(res, 0, sizeof *res);
    int rc = check_make(m, err);
    if (rc != GW_OK)
        return rc;
    double t0 = gw_clock_ms();
    if (m->clumps)
        return make_clumps(lp0, m, t0, out, res, err);
    gw_layer_params lp;
    if ((rc = box_params(lp0, m, &lp, err)) != GW_OK)
        return rc;
    int n = m->n;
    const double cv = cbrt(m->volume_ratio), rmin = 2 * m->rm / (1 + cv), rmax = cv * rmin;
    gw_layer_body *b = calloc((size_t)n, sizeof *b);
    if (!b)
        return gw_err_set(err, GW_ENOMEM, "layer-make: out of memory");
    splitmix64 g = {(unsigned long long)m->seed};
    const double pitch = 2.2 * rmax, jit = 0.05 * rmax;
    const int ncol = lattice_columns(lp.width, pitch);
    const double x0 = 0.5 * (lp.width - ncol * pitch) + 0.5 * pitch;
    for (int i = 0; i < n; i++) {
        int row = i / ncol, col = i % ncol;
        b[i].r = rmin + (rmax - rmin) * sm_uniform(&g);
        b[i].x = x0 + col * pitch + jit * (2 * sm_uniform(&g) - 1);
        b[i].y = 0.5 * pitch + row * pitch + jit * (2 * sm_uniform(&g) - 1);
    }
    double t, ke;
    int conv;
    if ((rc = check_step(&lp, m, b, n, err)) != GW_OK ||
        (rc = check_work(m, n, ncol, pitch, rmax, lp.skin, err)) != GW_OK ||
        (rc = check_column(m, n, lp.width, pitch, err)) != GW_OK) {
        free(b);
        return rc;
    }
    make_springs ks = {0};
    rc = settle_all(&lp, m, n, b, &t, &ke, &conv, res, &ks, err);
    if (rc == GW_OK) {
        out->x = malloc(3 * (size_t)n * sizeof *out->x);
        if (!out->x)
            rc = gw_err_set(err, GW_ENOMEM, "layer-make: out of memory");
    }
    if (rc != GW_OK) {
        free(ks.s);
        free(b);
        memset(out, 0, sizeof *out);
        return rc;
    }
    if (m->height_rm > 0) { /* trim to the box height, then relax the kept pile (relax_trimmed) */
        int kept = 0;
        for (int i = 0; i < n; i++)
            if (b[i].y + b[i].r <= m->height_rm * m->rm)
                b[kept++] = b[i];
        if (kept == 0) {
            free(ks.s);
            free(b);
            free(out->x);
            memset(out, 0, sizeof *out);
            return gw_err_set(err, GW_EINVAL, "height-rm: no particle lies below %g R_m", m->height_rm);
        }
        res->n_removed = n - kept;
        n = kept;
        note_untrimmed(m, b, n, res);
        if (res->n_removed > 0 && (rc = relax_trimmed(&lp, m, n, b, &t, &ke, &conv, res, &ks, err)) != GW_OK) {
            free(ks.s);
            free(b);
            free(out->x);
            memset(out, 0, sizeof *out);
            return rc;
        }
    }
    out->y = out->x + n;
    out->r = out->x + 2 * n;
    for (int i = 0; i < n; i++)
        out->x[i] = b[i].x, out->y[i] = b[i].y, out->r[i] = b[i].r;
    out->springs = ks.s, out->n_springs = ks.n; /* the last settle's: after a trim, the kept discs' */
    finish(&lp, m, b, n, t, ke, conv, t0, out, res);
    free(b);
    res->n_bodies = n;
    return settled_readable(out, err);
}

