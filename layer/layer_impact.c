/*
 * layer_impact.c: one block impact on a pluviated layer (docs/physics.md 2.3, 2.4;
 * eqs. B.5-B.18).
 *
 * Set-up: the block is a disc of radius R_b = rb_rm R_m (same density and mass
 * law as the soil) centred at x_c = W/2 + x, lowered vertically until it is
 * `gap` above the first soil particle under it (the target), with velocity
 * V_i (sin alpha, -cos alpha) and no spin:  V_ni = V_i cos alpha,
 * V_ti = V_i sin alpha (B.5, B.6). With height_rm > 0, particles more than
 * height_rm R_m below the surface (max of y + r) are frozen (infinite mass), as
 * in the paper's reduced heights; remove_walls takes the three walls away at
 * the start of the impact (docs/physics.md 2.5, bottom-wall study). Gravitational energy is measured from the
 * initial positions, so A = (1/2) M V_i^2 + the initial strain energy.
 * Outcome (bounce verdict, T_i, T_f, e_n = V_nr / V_ni, e = V_r / V_i,
 * alpha_r = arccos(V_nr / V_r), B.16-B.18, the first free-flight maximum, the
 * penetration) from events on the block, never from the samples
 * (layer_outcome.c documents the rules). The run stops once the outcome that
 * `until` asks for is decided (the next sample ends it), or at t_max (always
 * at t_max with `full`, for the crowns). First contact: until the first sample
 * (every dt_out) at which the block-target overlap is back to <= 0; E_d then
 * over (1/2) M V_i^2 (sampled, so identical on every backend up to dt_out).
 * Crowns: rings of width d_c centred on the initial block-target contact point
 * (layer_crowns.c).
 * Integration: any backend; verlet (explicit DEM, the program's default) with
 * dt = 0 takes gw_layer_impact_dem_dt. The caller's on_sample hook sees the
 * layer at every recorded sample and at the end (the study's snapshots,
 * layer_setup.c), reading only.
 * Units: SI.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"
#include "gw_locale.h"
#include "layer_outcome.h"

gw_layer_impact_params gw_layer_impact_params_default(void)
{
    gw_layer_impact_params p;
    memset(&p, 0, sizeof p);
    p.rb_rm = 1;
    p.vi = 20;
    p.alpha_deg = 0;
    p.x = 0;
    p.height_rm = 0;
    p.gap = 1e-6;
    p.t_max = 2.0; /* past T_f of the default impact, 0.42 s (layer_setup.c) */
    p.dt_out = 2e-5;
    p.ring_width = 0; /* 0: 2 R_m */
    p.nrings = 12;
    return p;
}

const char *gw_layer_until_name(int until)
{
    return until == GW_LAYER_UNTIL_VERDICT ? "verdict" : until == GW_LAYER_UNTIL_REBOUND ? "rebound" : "unknown";
}

int gw_layer_until_parse(const char *name)
{
    return !name ? -1 : strcmp(name, "rebound") == 0 ? GW_LAYER_UNTIL_REBOUND
                      : strcmp(name, "verdict") == 0 ? GW_LAYER_UNTIL_VERDICT : -1;
}

void gw_layer_impact_result_free(gw_layer_impact_result *r)
{
    if (!r)
        return;
    free(r->t);
    free(r->ledger);
    free(r->block);
    free(r->ring_kin);
    free(r->peak_strain_t);
    free(r->regions);
    free(r->xcorr_delay); /* the crowns' cross-correlation and spectra */
    memset(r, 0, sizeof *r);
}

/* The level below which a particle's centre is frozen: height_rm R_m under
 * the surface (the largest y + r); -inf with height_rm 0 (all mobile). */
static double freeze_level(const gw_layer_sample *smp, double height_rm, double *top_out)
{
    double top = 0;
    for (int i = 0; i < smp->n; i++)
        top = fmax(top, smp->y[i] + smp->r[i]);
    if (top_out)
        *top_out = top;
    return height_rm > 0 ? top - height_rm * smp->rm : -INFINITY;
}

/* The particles height_rm freezes, in fixed[n]: those whose centre lies
 * below y_freeze, and every member of a clump with one such member (a clump
 * is rigid: gw_layer_create freezes it whole, layer_clumps.c). Returns how
 * many, -1 out of memory. The counts of the result are these: before, a clump
 * sample's counted each disc by its own centre (21 mobile of 42 where one
 * clump of 2 discs moved). */
static int frozen_set(const gw_layer_sample *smp, double y_freeze, unsigned char *fixed)
{
    const int n = smp->n;
    unsigned char *body_fixed = smp->body ? calloc((size_t)n, 1) : NULL;
    if (smp->body && !body_fixed)
        return -1;
    for (int i = 0; i < n; i++) {
        fixed[i] = smp->y[i] < y_freeze;
        if (body_fixed && fixed[i])
            body_fixed[smp->body[i]] = 1; /* ids in [0, n): the sample reader's rule */
    }
    int nf = 0;
    for (int i = 0; i < n; i++) {
        if (body_fixed)
            fixed[i] = body_fixed[smp->body[i]];
        nf += fixed[i];
    }
    free(body_fixed);
    return nf;
}

/* The least height_rm that leaves one particle (or clump) mobile: a body is
 * mobile when its lowest member's centre lies at or above the freeze level,
 * top - height_rm R_m. -1 out of memory. */
static double least_mobile_height(const gw_layer_sample *smp, double top)
{
    const int n = smp->n;
    double *lo = malloc((size_t)n * sizeof *lo), best = -INFINITY;
    if (!lo)
        return -1;
    for (int i = 0; i < n; i++)
        lo[i] = INFINITY;
    for (int i = 0; i < n; i++) {
        const int k = smp->body ? smp->body[i] : i;
        lo[k] = fmin(lo[k], smp->y[i]);
    }
    for (int k = 0; k < n; k++)
        if (lo[k] < INFINITY)
            best = fmax(best, lo[k]);
    free(lo);
    return (top - best) / smp->rm;
}

/* v rounded up to 4 significant digits: a bound a message gives, that the
 * value printed passes */
/* x over the incident energy e: NaN (null, n/a) when e is no positive normal
 * double. An impact speed whose (1/2) M V_i^2 underflows (--gap 0 --vi
 * 1e-300, a block set down on the layer) gave E_d / E_incident = NaN and a
 * block loss of -inf, printed "-nan" and "-inf" in the text where the JSON
 * said null. */
static double over_incident(double x, double e)
{
    return e >= DBL_MIN ? x / e : NAN;
}

static double ceil4(double v)
{
    if (!(v > 0) || !isfinite(v))
        return v;
    const double step = pow(10, floor(log10(v)) - 3);
    return ceil(v / step * (1 + 1e-12)) * step;
}

static const char *side_walls_name(int s)
{
    return s == GW_LAYER_SIDES_BOTH ? "both" : s == GW_LAYER_SIDES_LEFT ? "left" : s == GW_LAYER_SIDES_RIGHT ? "right"
           : s == GW_LAYER_SIDES_NONE ? "none" : "unknown";
}

/* The walls an impact keeps (GW_LAYER_WALL_* mask): none with remove_walls,
 * else the floor and the side walls of side_walls. */
static int impact_walls(const gw_layer_impact_params *ip)
{
    if (ip->remove_walls)
        return 0;
    const int s = ip->side_walls;
    return GW_LAYER_WALL_BOTTOM | (s == GW_LAYER_SIDES_BOTH || s == GW_LAYER_SIDES_LEFT ? GW_LAYER_WALL_LEFT : 0) |
           (s == GW_LAYER_SIDES_BOTH || s == GW_LAYER_SIDES_RIGHT ? GW_LAYER_WALL_RIGHT : 0);
}

/* The force (N) the side wall side (GW_LAYER_SPRING_LEFT or _RIGHT) exerts on
 * the pile of smp under lp's material: its contacts' Hertz normal forces
 * (horizontal, *fn) and their friction through the springs the sample keeps
 * against it (vertical, upward, *ft: layer_sample_side_hold at friction_deg). */
static void side_wall_force(const gw_layer_sample *smp, const gw_layer_params *lp, double friction_deg, int side,
                            double *fn, double *ft)
{
    *fn = 0;
    for (int i = 0; i < smp->n; i++) {
        const double u = side == GW_LAYER_SPRING_LEFT ? smp->r[i] - smp->x[i] : smp->r[i] - (smp->width - smp->x[i]);
        if (u > 0)
            *fn += gw_layer_kn(lp, smp->r[i]) * u * sqrt(u);
    }
    *ft = smp->springs ? layer_sample_side_hold(smp, lp, friction_deg, side) : 0;
}

/* A pile the impact keeps without a side wall must rest on its floor alone
 * and must not lean on the wall taken away. One whose side walls help hold it
 * (their friction carrying part of its weight, or pulling it down onto a floor
 * that carries more than it: the narrow clump piles layer-make calls settled
 * by the walls' share) falls apart at t = 0 once a wall is gone, the block
 * hitting a collapsing pile: the floor alone within [LAYER_FLOOR_LOAD_MIN,
 * LAYER_FLOOR_LOAD_MAX] of the weight (layer_load_rests without walls)
 * passes. The floor's share alone passed a pile wedged between its walls:
 * `layer-make --clumps --width-rm 6 --n 40 --seed 1` rests with its floor at
 * 1.01 of its weight and its walls' friction at +0.26 (left) and -0.31
 * (right), but its walls push it with 2.20 and 2.50 times its weight; without
 * the right wall its strain energy (1845 J) went into motion, 5457 J of
 * kinetic energy at 0.05 s against 1.1 J with both walls (a block of 0.2 R_m
 * at 0.5 m/s; seeds 2 to 4 push with 3.7 to 4.3). A wall taken away must carry
 * at most LAYER_SIDE_WALL_LOAD_MAX of the weight (its normal and friction
 * forces' resultant): the stored 300-disc pile's walls push with 0.24 and 0.26
 * of its weight, a loosely settled 40-disc pile's right wall 0.51 (piles of
 * discs at rest against a wall, their face slumping without it as any free
 * face of a pile does: the stored pile's E_k was 0.11 mm of its weight at
 * 5 ms, seed 1's clump pile's 1.36 mm, 58 % of its strain energy gone), and
 * pass. Judged under the
 * material and gravity the pile settled with when its sample records them
 * (the loads it rests with, whatever the impact's material: a material the
 * pile did not settle with is the rest and settling checks' to refuse), else
 * under lp's, or the default material when lp is NULL (gw_layer_impact_check,
 * which has no material). Refused, naming side-walls and the shares. */
int layer_side_walls_rest_check(const gw_layer_sample *smp, const gw_layer_params *lp,
                                const gw_layer_impact_params *ip, gw_err *err)
{
    if (ip->remove_walls || ip->side_walls == GW_LAYER_SIDES_BOTH)
        return GW_OK;
    gw_layer_params m = lp ? *lp : gw_layer_params_default();
    if (!lp)
        m.mass_law = smp->mass_law;
    double phi = m.friction_deg;
    if (smp->settled.recorded) {
        m.shear_modulus = smp->settled.shear_modulus;
        m.poisson = smp->settled.poisson;
        m.density = smp->settled.density;
        m.gravity = smp->settled.gravity;
        m.mass_law = smp->settled.mass_law;
        phi = smp->settled.friction_deg;
    }
    if (!(m.gravity > 0))
        return GW_OK;
    double f, w;
    layer_floor_load(&m, smp->n, smp->y, smp->r, sizeof *smp->y, &f, &w);
    if (!(w > 0))
        return GW_OK;
    const char *gone = ip->side_walls == GW_LAYER_SIDES_LEFT ? "its right wall"
                       : ip->side_walls == GW_LAYER_SIDES_RIGHT ? "its left wall" : "its side walls";
    if (!layer_load_rests(f, 0, w)) {
        const double hold = smp->springs ? layer_sample_wall_hold(smp, &m, phi) : 0;
        return gw_err_set(err, GW_EINVAL, "side-walls: %s: the sample's pile does not rest on its floor alone (at "
                          "t = 0 the floor carries %.3g of its weight and the side walls %.3g; at rest on the floor: "
                          "%g to %g): its side walls help hold it, and without %s it is not at rest (give side-walls "
                          "both, or a sample settled on its floor)", side_walls_name(ip->side_walls), f / w, hold / w,
                          LAYER_FLOOR_LOAD_MIN, LAYER_FLOOR_LOAD_MAX, gone);
    }
    for (int k = 0; k < 2; k++) {
        const int side = k == 0 ? GW_LAYER_SPRING_LEFT : GW_LAYER_SPRING_RIGHT;
        if (ip->side_walls == (k == 0 ? GW_LAYER_SIDES_LEFT : GW_LAYER_SIDES_RIGHT))
            continue; /* kept */
        double fn, ft;
        side_wall_force(smp, &m, phi, side, &fn, &ft);
        if (hypot(fn, ft) > LAYER_SIDE_WALL_LOAD_MAX * w)
            return gw_err_set(err, GW_EINVAL, "side-walls: %s: the sample's pile leans on its %s wall (at t = 0 it "
                              "pushes the pile with %.3g of its weight and its friction carries %.3g, while the floor "
                              "carries %.3g; a wall taken away may carry at most %g): the pile is wedged between its "
                              "walls, and without %s it is not at rest (give side-walls both, or a sample settled in "
                              "a wider box)", side_walls_name(ip->side_walls), k == 0 ? "left" : "right", fn / w,
                              ft / w, f / w, LAYER_SIDE_WALL_LOAD_MAX, gone);
    }
    return GW_OK;
}

/* gw_layer_impact_check's rules with the side walls judged under lp (NULL:
 * the default material), lp as the run takes it: its width the sample's, its
 * walls the impact's (gw_layer_impact's copy of lp). */
static int impact_check(const gw_layer_sample *smp, const gw_layer_params *lp, const gw_layer_impact_params *p,
                        gw_err *err)
{
    /* the limits every sample is held to (the reader's: a disc outside the
     * box, of a radius 1e6 R_m, or two at one place ran before session 43) */
    int rc = layer_sample_shape_check(smp, "s", err);
    if (rc == GW_OK)
        rc = layer_impact_params_check(smp, p, err);
    if (rc != GW_OK || !lp)
        /* the side walls kept, as the run and the setup judge them (the
         * setup's check and gw_layer_impact applied it, this check did not
         * until session 45): under the sample's recorded settling, else the
         * default material */
        return rc == GW_OK ? layer_side_walls_rest_check(smp, NULL, p, err) : rc;
    gw_layer_params m = *lp;
    m.width = smp->width;
    m.walls = impact_walls(p);
    return layer_side_walls_rest_check(smp, &m, p, err);
}

int gw_layer_impact_check(const gw_layer_sample *smp, const gw_layer_impact_params *p, gw_err *err)
{
    if (!smp || !p)
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_check: %s is NULL", !smp ? "s" : "ip");
    return impact_check(smp, NULL, p, err);
}

int gw_layer_impact_check_with(const gw_layer_sample *smp, const gw_layer_params *lp, const gw_layer_impact_params *p,
                               gw_err *err)
{
    if (!smp || !lp || !p)
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_check_with: %s is NULL", !smp ? "s" : !lp ? "lp" : "ip");
    /* the impact's material as the run holds it (gw_layer_impact_rest_check's
     * rule: a NaN gravity would judge no pile) */
    const int rc = gw_layer_params_validate(lp, err);
    return rc == GW_OK ? impact_check(smp, lp, p, err) : rc;
}

int layer_impact_params_check(const gw_layer_sample *smp, const gw_layer_impact_params *p, gw_err *err)
{
    /* The sample as the run builds its layer from it (gw_layer_create) is the
     * shared check's (layer_sample_limits_check), one rule per property: each
     * disc inside the box to 0.02 r, walls or none, so its centre inside the
     * walls gw_layer_create keeps; its clumps connected. (Until session 44 a
     * second loop held the centres to the walls exactly and the clumps were
     * checked again: neither could refuse what the shared check passed.) Its
     * springs as the run starts them: a NaN spring was refused by the run
     * only (a sweep's check passed the cases its run stopped on). */
    int rc;
    if (!p->zero_springs && smp->n_springs != 0 && (rc = layer_springs_check(smp, "s", NULL, GW_EINVAL, err)) != GW_OK)
        return rc;
    if (!(p->rb_rm > 0) || !isfinite(p->rb_rm))
        return gw_err_set(err, GW_EINVAL, "rb-rm: block radius %g R_m must be positive", p->rb_rm);
    /* and within the row's [1e-6, 1e6] (the radii a sample's discs may have,
     * 1e-3 to 1e3 R_m, and a block far beyond both): 1e-310 failed at the
     * solver's set-up ("scale[245] = inf"), 4.9e-324 as "particle 40: radius
     * r = 0 m", 1e-200 ran a block of 3e-201 m (the fiftieth pass) */
    if ((rc = gw_check_range(p->rb_rm, "rb-rm (block radius, R_m)", 1e-6, 1e6, err)) != GW_OK)
        return rc;
    /* (1 km/s: beyond it the grains' sound speed is near and Hertz contacts
     * are no model; the verlet step falls as V_i^(-1/5)) */
    if ((rc = gw_check_positive(p->vi, "vi (incident speed, m/s)", err)) != GW_OK ||
        (rc = gw_check_range(p->vi, "vi (incident speed, m/s)", 0, 1e3, err)) != GW_OK)
        return rc;
    char as[32]; /* as given: -1e-7 was "-1e-07", 89.99999999 inside */
    if (!(p->alpha_deg >= 0 && p->alpha_deg < 90))
        return gw_err_set(err, GW_EINVAL, "alpha: incidence %s deg is outside [0, 90)",
                          gw_num_text(as, sizeof as, p->alpha_deg));
    if (!(p->gap >= 0) || !isfinite(p->gap))
        return gw_err_set(err, GW_EINVAL, "gap: %g m < 0 puts the block inside the layer (overlapping)",
                          p->gap);
    if (p->gap > 1e3)
        return gw_err_set(err, GW_EINVAL, "gap: %g m is above 1000 m (start the block closer and "
                          "give its speed)", p->gap);
    if ((rc = gw_check_range(p->x, "x (impact abscissa, m)", -1e6, 1e6, err)) != GW_OK ||
        (rc = gw_check_range(p->height_rm, "height-rm", 0, 1e6, err)) != GW_OK ||
        (rc = gw_check_positive(p->t_max, "t-max (s)", err)) != GW_OK ||
        (rc = gw_check_positive(p->dt_out, "dt-out (s)", err)) != GW_OK ||
        (rc = gw_check_range(p->ring_width, "ring-width (m)", 0, 1e6, err)) != GW_OK ||
        (rc = gw_check_range(p->energy_tol, "energy-tol", 0, 1, err)) != GW_OK)
        return rc;
    /* every ring lookup divides by the width's square: a width whose square
     * is no normal double was refused only by the regions' setup, naming
     * "layer regions", not the input (--ring-width 1e-160) */
    if (p->ring_width > 0 && !(p->ring_width * p->ring_width >= DBL_MIN))
        return gw_err_set(err, GW_EINVAL, "ring-width: %g m is too small: its square is no normal double (give 0 "
                          "for 2 R_m, or a width of at least 1.49167e-154 m)", p->ring_width);
    if (p->until != GW_LAYER_UNTIL_REBOUND && p->until != GW_LAYER_UNTIL_VERDICT)
        return gw_err_set(err, GW_EINVAL, "until: %d is neither rebound (0) nor verdict (1)", p->until);
    /* the yes/no members: -1, 2 or INT_MIN ran as 1 with GW_OK, where until
     * names its two values (the fiftieth pass) */
    const struct {
        const char *name;
        int v;
    } fl[] = {{"full", p->full}, {"remove-walls", p->remove_walls}, {"other-settling", p->other_settling},
              {"zero-springs", p->zero_springs}};
    for (size_t i = 0; i < sizeof fl / sizeof fl[0]; i++)
        if (fl[i].v != 0 && fl[i].v != 1)
            return gw_err_set(err, GW_EINVAL, "%s: %d is not a flag (0 or 1)", fl[i].name, fl[i].v);
    if (p->nrings < 1 || p->nrings > 1000)
        return gw_err_set(err, GW_EINVAL, "rings: %d is outside [1, 1000]", p->nrings);
    if (p->side_walls < GW_LAYER_SIDES_BOTH || p->side_walls > GW_LAYER_SIDES_NONE)
        return gw_err_set(err, GW_EINVAL, "side-walls: %d is none of both (0), left (1), right (2), none (3)",
                          p->side_walls);
    /* remove-walls takes every wall away, the floor too: no side wall is left
     * to keep */
    if (p->remove_walls && p->side_walls != GW_LAYER_SIDES_BOTH)
        return gw_err_set(err, GW_EINVAL, "side-walls: %s is given with remove-walls, which takes every wall away "
                          "(the floor too): give one or the other", side_walls_name(p->side_walls));
    if (p->t_max / p->dt_out > 2e6)
        return gw_err_set(err, GW_EINVAL, "dt-out: %g s gives more than 2e6 samples up to t-max", p->dt_out);
    /* the series are held in memory (alloc_series): time, ledger (8), block (4)
     * and 4 per ring at each sample (12 rings: 488 B a sample, the 2e6 samples
     * take 0.98 GB); written with --out (crowns, spectra, HDF5) they take about
     * 25 B a value (24.8 measured with 200 rings). Refused before allocating
     * when the files would pass 5 GB (1.6 GB of series): the 2.1 GB bound on
     * memory before let --rings 1000 --t-max 0.5 --dt-out 8e-6 through, about
     * 6.3 GB of files */
    const double nsamp = ceil(p->t_max / p->dt_out) + 2, values = nsamp * (13.0 + 4.0 * p->nrings);
    if (values * 25.0 > 5e9)
        return gw_err_set(err, GW_EINVAL, "dt-out: %.0f samples x %d rings need %.3g GB of series and about %.3g GB "
                          "of files with --out, above the 5 GB limit (raise dt-out, lower t-max or rings)", nsamp,
                          p->nrings, values * 8 / 1e9, values * 25 / 1e9);
    const double rb = p->rb_rm * smp->rm, xc = 0.5 * smp->width + p->x;
    if (2 * rb > smp->width) { /* rb-rm as given: 4.0000001 was shown as 4, half the box */
        char rs[32];
        return gw_err_set(err, GW_EINVAL, "rb-rm: a block of radius %s R_m (%g m) is wider than the box "
                          "(%g m)", gw_num_text(rs, sizeof rs, p->rb_rm), rb, smp->width);
    }
    if (xc - rb < 0 || xc + rb > smp->width) { /* x as given: 1.2999999 was shown as 1.3 */
        char xs[32];
        return gw_err_set(err, GW_EINVAL, "x: block of radius %g m at x = %s m from the centre "
                          "does not fit in the box of width %g m", rb, gw_num_text(xs, sizeof xs, p->x), smp->width);
    }
    /* The block must have a particle under it: its target, on which it is
     * lowered (gw_layer_impact). This was found only by the run: a sweep's
     * check passed a grid whose abscissa missed a sparse layer, ran and
     * journaled the cases before it, then stopped (exit 2), and the program
     * said "x:", not "--x:" */
    int under = 0;
    for (int i = 0; i < smp->n && !under; i++)
        under = fabs(smp->x[i] - xc) < rb + smp->r[i];
    if (!under)
        return gw_err_set(err, GW_EINVAL, "x: no soil particle lies under the block (radius %g m) at x = %g m from "
                          "the centre: it would fall past the layer", rb, p->x);
    /* a mobile layer reaching below every particle's centre freezes none: the
     * run of height-rm 0, silently (the rule gw_layer_impact freezes by) */
    if (p->height_rm > 0 && smp->n > 0) {
        double top = 0, ymin = INFINITY;
        const double yf = freeze_level(smp, p->height_rm, &top);
        for (int i = 0; i < smp->n; i++)
            ymin = fmin(ymin, smp->y[i]);
        if (!(ymin < yf))
            return gw_err_set(err, GW_EINVAL, "height-rm: a mobile layer of %g R_m reaches below every particle's "
                              "centre (the lowest lies %.4g R_m under the surface): no particle is frozen, as with "
                              "0 (give less than %.4g, or 0 for all mobile)", p->height_rm,
                              (top - ymin) / smp->rm, (top - ymin) / smp->rm);
        /* and one that holds no particle (no clump) whole freezes all: the
         * block hit a rigid bed, exit 0 (--height-rm 1 on a 40-disc pile: 0
         * mobile, e_n 0.965 against 0.153 on the pile) */
        unsigned char *fixed = malloc((size_t)smp->n);
        const int nf = fixed ? frozen_set(smp, yf, fixed) : -1;
        free(fixed);
        const double hmin = nf == smp->n ? least_mobile_height(smp, top) : 0;
        if (nf < 0 || hmin < 0)
            return gw_err_set(err, GW_ENOMEM, "height-rm: out of memory for %d particles", smp->n);
        if (nf == smp->n)
            return gw_err_set(err, GW_EINVAL, "height-rm: a mobile layer of %g R_m holds no %s: every particle "
                              "is frozen and the block would hit a rigid bed (give at least %.4g, or 0 for all "
                              "mobile)", p->height_rm, smp->body ? "clump whole" : "particle's centre", ceil4(hmin));
    }
    return GW_OK;
}

/* Whether a block of incident speed vi at alpha_deg falling gap under g meets
 * the layer at most 0.1 % faster than its normal speed (the fall check). */
static int fall_passes(double vi, double alpha_deg, double gap, double g)
{
    const double vn = vi * cos(alpha_deg * M_PI / 180), vc = sqrt(vn * vn + 2 * g * gap);
    return !(g > 0) || gap == 0 || vc <= 1.001 * vn;
}

/* x rounded to 3 significant digits, up (dir > 0) or down, into buf; more
 * digits while the text does not pass the fall check as vi (is_vi) or as
 * gap: the value named in a refusal runs when given as printed (0.099 m/s
 * at the default gap was told "lower gap to 1e-06 m", the gap it had). */
static const char *passing_text(char *buf, size_t n, double x, int dir, int is_vi, const gw_layer_impact_params *ip,
                                double g)
{
    for (int d = 3; d <= 17; d++) {
        const double e = pow(10, floor(log10(x)) - (d - 1));
        const double y = (dir > 0 ? ceil(x / e) : floor(x / e)) * e;
        gw_snprintf(buf, n, "%.*g", d, y);
        const double t = gw_strtod(buf, NULL);
        if (is_vi ? fall_passes(t, ip->alpha_deg, ip->gap, g) : fall_passes(ip->vi, ip->alpha_deg, t, g))
            return buf;
    }
    gw_snprintf(buf, n, "%.17g", x);
    return buf;
}

/* A gap at the default's value, taken as not given: the struct cannot tell a
 * gap set to it from one left at it (the setup knows, layer_setup.c). */
static int gap_at_default(const gw_layer_impact_params *ip)
{
    return ip->gap == gw_layer_impact_params_default().gap;
}

int gw_layer_impact_fall_check(const gw_layer_impact_params *ip, double g, gw_err *err)
{
    if (!ip)
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_fall_check: ip is NULL");
    return layer_impact_fall_rule(ip, g, gap_at_default(ip), err);
}

int layer_impact_fall_rule(const gw_layer_impact_params *ip, double g, int gap_default, gw_err *err)
{
    /* gravity's own range, gw_layer_params_validate's rule (a NaN g passed
     * as no gravity; g = 1e300, which the run refuses, was told "vi: ... too
     * slow for the default gap") */
    const int grc = gw_check_range(g, "gravity (m/s^2)", 0, 1e4, err);
    if (grc != GW_OK)
        return grc;
    /* --gap 1 --vi 1 arrived at 4.54 m/s: e_n 0.86 and e 1.83 over V_i = 1,
     * a penetration of 1.06 m counted from the start, against e_n 0.179 and
     * 0.064 m for the same impact given as --vi 4.54 */
    const double vn = ip->vi * cos(ip->alpha_deg * M_PI / 180), vc = sqrt(vn * vn + 2 * g * ip->gap);
    if (fall_passes(ip->vi, ip->alpha_deg, ip->gap, g))
        return GW_OK;
    const double k = 1.001 * 1.001 - 1; /* vc <= 1.001 vn: 2 g gap <= k vn^2 */
    char gs[32], vs[32];
    passing_text(gs, sizeof gs, k * vn * vn / (2 * g), -1, 0, ip, g);
    passing_text(vs, sizeof vs, sqrt(2 * g * ip->gap / k) / cos(ip->alpha_deg * M_PI / 180), 1, 1, ip, g);
    /* the default gap (1 um, not given): the speed is what the caller gave,
     * and the refusal is of it, naming the default and the smallest speed
     * that runs with it (it said "gap: falling 1e-06 m ... lower gap", of a
     * gap never given). A gap given, at the default's value too, is the
     * gap's refusal (--gap 1e-6 was told "the default gap" until session 44) */
    /* an oblique incidence is a driver of the normal speed as much as vi
     * (--alpha 89.9 at 20 m/s meets the layer at 0.035 m/s normal speed, and
     * the refusal named vi only): name alpha, and the largest incidence that
     * runs at this speed when one does */
    char at[64] = "", al[96] = "";
    if (ip->alpha_deg != 0) {
        char as[32];
        gw_snprintf(at, sizeof at, " at incidence alpha %s deg", gw_num_text(as, sizeof as, ip->alpha_deg));
        const double c = sqrt(2 * g * ip->gap / k) / ip->vi; /* cos(alpha) at least this */
        if (c < 1)
            gw_snprintf(al, sizeof al, ", an incidence alpha of at most %.10g deg", floor(acos(c) * 180 / M_PI * 1e4) / 1e4);
        else
            gw_snprintf(al, sizeof al, " (no incidence alpha runs at this vi)");
    }
    if (gap_default) {
        char vis[32];
        return gw_err_set(err, GW_EINVAL, "vi: %s m/s%s is too slow for the default gap of %g m: "
                          "falling it (g = %g m/s^2) the block meets the layer at %.4g m/s normal speed, not %.4g "
                          "(+%.2g %%, at most 0.1 %%: e_n, e, E_incident and the penetration take V_i as given): "
                          "give vi at least %s m/s with the default gap%s, or a gap of at most %s m (0: the block "
                          "starts touching the layer)", gw_num_text(vis, sizeof vis, ip->vi), at, ip->gap, g, vc, vn,
                          100 * (vc / vn - 1), vs, al, gs);
    }
    return gw_err_set(err, GW_EINVAL, "gap: falling %g m (g = %g m/s^2), the block meets the layer at %.4g m/s "
                      "normal speed, not %.4g (+%.2g %%, at most 0.1 %%: e_n, e, E_incident and the penetration "
                      "take V_i as given)%s: lower gap to %s m, or give vi the speed at contact (at least %s m/s "
                      "with this gap)%s", ip->gap, g, vc, vn, 100 * (vc / vn - 1), at, gs, vs, al);
}

/* The block must be able to reach the layer before the run ends. Its gap is
 * the surface distance to its target, which no contact can close faster than
 * the block's speed: at least t = 2 gap / (v + sqrt(v^2 + 2 g gap)) (v the
 * incident speed, g at most adding to it), whatever the incidence and the
 * target's place. A t-max at or before that ran with exit 0 and measured
 * nothing: the bounce undecided but the penetration written 0 (a number, not
 * null), which a sweep's table carried into layer-stats' penetration means
 * (--t-max 1e-8, or --gap 0.03 --t-max 0.001 at 20 m/s: no contact). */
static int impact_reach_check(const gw_layer_impact_params *p, double g, gw_err *err)
{
    const double v = p->vi;
    if (!(p->gap > 0) || !(v > 0) || !isfinite(p->t_max) || !(g >= 0))
        return GW_OK; /* no gap to cross; the other checks name the speed and gravity */
    const double t_reach = 2 * p->gap / (v + sqrt(v * v + 2 * g * p->gap));
    if (p->t_max > t_reach)
        return GW_OK;
    return gw_err_set(err, GW_EINVAL, "t-max: %g s ends before the block can reach the layer (its gap of %g m "
                      "takes at least %.4g s at %g m/s, g = %g m/s^2): nothing would be measured; raise t-max "
                      "above %.4g s or lower gap", p->t_max, p->gap, t_reach, v, g, t_reach);
}

int gw_layer_impact_gap_check(const gw_layer_sample *smp, const gw_layer_impact_params *p, double g,
                              gw_err *err)
{
    if (!smp || !p)
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_gap_check: %s is NULL", !smp ? "s" : "ip");
    /* (its rm, read below: a NaN rm passed every gap before session 43) */
    const int rc = layer_sample_shape_check(smp, "s", err);
    return rc == GW_OK ? layer_impact_gap_rules(smp, p, g, gap_at_default(p), err) : rc;
}

int layer_impact_gap_rules(const gw_layer_sample *smp, const gw_layer_impact_params *p, double g, int gap_default,
                           gw_err *err)
{
    const int rc = layer_impact_fall_rule(p, g, gap_default, err);
    if (rc != GW_OK)
        return rc;
    /* The block is lowered vertically onto its target at x, then sent along
     * the incidence: over the gap it drifts gap tan(alpha) sideways and meets
     * the layer off x (without gravity no fall bound holds the gap: --gravity
     * 0 --alpha 60 --gap 1 landed 1.73 m, 5.3 R_m, away, on another particle,
     * while the contact angle and the crowns were the target's). At most
     * 1e-3 R_m (the default 1 um gap drifts 3.7e-6 m at 75 deg). */
    const double drift = p->gap * tan(p->alpha_deg * M_PI / 180);
    if (drift > 1e-3 * smp->rm)
        return gw_err_set(err, GW_EINVAL, "gap: at alpha = %g deg the block drifts gap tan(alpha) = %.3g m "
                          "(%.3g R_m) sideways before it touches and meets the layer off x (at most 1e-3 R_m): "
                          "lower gap to %.3g m", p->alpha_deg, drift, drift / smp->rm,
                          1e-3 * smp->rm / tan(p->alpha_deg * M_PI / 180));
    return impact_reach_check(p, g, err);
}

void layer_floor_load(const gw_layer_params *lp, int n, const double *y, const double *r, size_t stride, double *f,
                      double *w)
{
    const char *py = (const char *)y, *pr = (const char *)r;
    *f = *w = 0;
    for (int i = 0; i < n; i++, py += stride, pr += stride) {
        double ri, yi;
        memcpy(&ri, pr, sizeof ri), memcpy(&yi, py, sizeof yi);
        const double u = ri - yi;
        *w += gw_layer_mass(lp, ri) * lp->gravity;
        if (u > 0)
            *f += gw_layer_kn(lp, ri) * u * sqrt(u);
    }
}

int layer_load_rests(double f, double walls, double w)
{
    const double s = f + walls;
    return (f >= LAYER_FLOOR_LOAD_MIN * w && f <= LAYER_FLOOR_LOAD_MAX * w) ||
           (s >= LAYER_FLOOR_LOAD_MIN * w && s <= LAYER_FLOOR_LOAD_MAX * w);
}

int gw_layer_impact_rest_check(const gw_layer_sample *smp, const gw_layer_params *lp, const char *name,
                               gw_err *err)
{
    if (!smp || !lp)
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_rest_check: %s is NULL", !smp ? "s" : "lp");
    /* the impact's material as the run holds it (a NaN or infinite gravity
     * passed: no floor load is above a NaN weight) */
    const int prc = gw_layer_params_validate(lp, err);
    if (prc != GW_OK)
        return prc;
    /* the floor's load was read through a NULL y or r (SIGSEGV), and a NaN y
     * gave a NaN load, passed as none above the weight */
    const int rc = layer_sample_shape_check(smp, name ? name : "s", err);
    if (rc != GW_OK)
        return rc;
    return layer_rest_check(smp, lp, 0, name, layer_settled_load_ratio(smp, lp), err);
}

int layer_rest_check(const gw_layer_sample *smp, const gw_layer_params *lp, int other_settling, const char *name,
                     double q, gw_err *err)
{
    /* A settled pile rests on the floor: the floor's Hertz forces carry its
     * weight, less what the side walls hold by friction (0.97 to 1.006 of it
     * on the stored 300-disc samples, 0.88 in a 12 R_m box). The sample keeps
     * the overlaps, not the material: a pile settled softer, heavier or under
     * more gravity than the impact's contacts presses the floor harder than
     * its weight at t = 0, and its excess strain energy goes off into the
     * impact (settled at G = 4e9 Pa and hit at the default 4e10: 9.7 times the
     * weight, 16930 J of strain instead of 1693, 860 J of soil motion in the
     * first 3 ms against 15). Above LAYER_FLOOR_LOAD_MAX times the weight,
     * refused; layer-make settles until its pile is below it. The weight
     * counts clumps with the sum of their members' masses (at least the
     * union's), so no union sample is refused for its mass law.
     * other-settling runs a pile whose recorded settling puts it away from
     * rest (gw_layer_impact_settled_check, which records the warning): its
     * contacts carry q times the weight they carried at rest, so the floor's
     * load it explains, up to LAYER_FLOOR_LOAD_MAX q, is allowed too (the
     * flag lifted the settling check alone, and the pile settled at G = 4e9
     * was refused here, q = 10, whatever the user asked). A load beyond that
     * is a pile that did not settle, which no flag runs. */
    double f, w;
    layer_floor_load(lp, smp->n, smp->y, smp->r, sizeof *smp->y, &f, &w);
    /* A pile in a narrow box may rest pressed onto its floor by the side
     * walls' friction, which its springs keep (layer-make calls it settled
     * when the floor and the walls together carry its weight: held_by_walls):
     * `layer-make --clumps --width-rm 6 --n 40 --seed 3` rests with 1.60 of
     * its weight on the floor and the walls pulling down 0.60 of it. Its
     * floor's excess is the walls', at t = 0 as at rest, not strain released
     * into the impact: the two together are held to within the bound of
     * its weight (with both side walls in the impact, which hold it). */
    const int sides = (lp->walls & GW_LAYER_WALL_LEFT) && (lp->walls & GW_LAYER_WALL_RIGHT);
    const double hold = sides && smp->springs ? layer_sample_wall_hold(smp, lp, lp->friction_deg) : 0;
    if (f > LAYER_FLOOR_LOAD_MAX * w && w > 0 && layer_load_rests(f, hold, w))
        return GW_OK;
    const double allowed = q > 1 ? LAYER_FLOOR_LOAD_MAX * q : LAYER_FLOOR_LOAD_MAX; /* NaN: 1.5 */
    /* (no gravity in the impact: q infinite, nothing to weigh the load
     * against, refused whatever the flag: the pile's strain is all released) */
    if (!(f > LAYER_FLOOR_LOAD_MAX * w) || (other_settling && w > 0 && !(f > allowed * w)))
        return GW_OK;
    char nm[300] = "";
    if (name)
        gw_snprintf(nm, sizeof nm, " '%s'", name);
    /* what to do: other-settling when the recorded settling explains the load
     * (nothing added for a sample without a record run without the flag: the
     * message holds a path and the values, within gw_err's 512 bytes) */
    char todo[160] = "";
    const int rec = smp->settled.recorded;
    if (!rec && other_settling)
        gw_snprintf(todo, sizeof todo, "; other-settling does not apply: no settings line");
    else if (rec && !(w > 0) && other_settling)
        gw_snprintf(todo, sizeof todo, "; other-settling does not run a pile without gravity");
    else if (rec && other_settling)
        gw_snprintf(todo, sizeof todo, "; other-settling allows %.3g (1.5 q, q = %.3g from its settings line): it "
                    "did not settle", allowed, q);
    else if (rec && q > 1)
        gw_snprintf(todo, sizeof todo, ", or other-settling to run it (up to %.3g, 1.5 q)", allowed);
    else if (rec)
        gw_snprintf(todo, sizeof todo, "; its settings line gives q = %.3g: it did not settle", q);
    if (!(w > 0))
        return gw_err_set(err, GW_EINVAL, "sample%s: its floor contacts hold %.3g N of Hertz force at t = 0 and "
                          "gravity is %g: the pile was settled under gravity and its strain energy would be "
                          "released into the impact (give the gravity it was made with%s)", nm, f, lp->gravity,
                          todo);
    /* the side walls' share named with the floor's when they hold any (the
     * rule: layer_load_rests) */
    char sides_txt[96] = "", rest[40] = " (a settled pile: at most 1)";
    if (hold != 0) {
        gw_snprintf(sides_txt, sizeof sides_txt, " and its side walls %.3g (together %.3g; at rest: %g to %g),",
                    hold / w, (f + hold) / w, LAYER_FLOOR_LOAD_MIN, LAYER_FLOOR_LOAD_MAX);
        rest[0] = '\0';
    }
    return gw_err_set(err, GW_EINVAL, "sample%s: at t = 0 its floor carries %.3g times the weight of the pile%s "
                      "with shear-modulus %g Pa, poisson %g, density %g kg/m^3, gravity %g m/s^2 and mass-law %s%s: "
                      "it was settled with another material or gravity, or did not settle (its header records "
                      "layer-make's settings and 'converged'), and its excess strain energy would go into the "
                      "impact; give those values%s", nm, f / w, sides_txt, lp->shear_modulus, lp->poisson,
                      lp->density, lp->gravity, lp->mass_law == GW_LAYER_MASS_SPHERE ? "sphere" : "disc", rest, todo);
}

double gw_layer_impact_dem_dt(const gw_layer_sample *s, const gw_layer_params *lp,
                              const gw_layer_impact_params *ip)
{
    /* any sample or impact the run refuses (gw_layer_impact_check: before
     * session 43 the sample's form only, and a disc outside the box, two discs
     * at one place got a step, a speed of 0 an infinite one; its side walls
     * under lp since session 45, under the default material before) */
    if (!s || !lp || !ip || gw_layer_impact_check_with(s, lp, ip, NULL) != GW_OK)
        return NAN;
    return layer_impact_dem_dt(s, lp, ip);
}

double layer_impact_dem_dt(const gw_layer_sample *s, const gw_layer_params *lp, const gw_layer_impact_params *ip)
{
    double rmin = INFINITY;
    for (int i = 0; i < s->n; i++) {
        if (!(s->r[i] > 0) || !isfinite(s->r[i])) /* fmin passed over a NaN radius: the others' step */
            return NAN;
        rmin = fmin(rmin, s->r[i]);
    }
    rmin = fmin(rmin, ip->rb_rm * s->rm);
    const double ms = 0.5 * gw_layer_mass(lp, rmin), K = gw_layer_kn(lp, rmin);
    const double beta = tgamma(0.4) * tgamma(0.5) / tgamma(0.9); /* B(2/5, 1/2) */
    double tau = 0.8 * beta * pow(1.25 * ms / K, 0.4) * pow(ip->vi, -0.2);
    /* a divisor of GW_LAYER_DEM_BASE, whatever dt_out: sampling every multiple
     * of it lands on step ends and leaves the trajectory unchanged. A step
     * above the base was rounded to a multiple of it, which the default dt_out
     * (2e-5 s) need not be: a slow impact on a soft pile (vi 0.3 m/s, G 4e9 Pa)
     * took 6e-5 s steps, cut in three at every sample, and its e_n was 0.92397
     * at dt-out 2e-5 against 0.92362 at 6e-5 */
    double dt = tau / GW_LAYER_DEM_STEPS, b = GW_LAYER_DEM_BASE;
    if (!(dt > 0) || !isfinite(dt))
        return dt;
    /* whatever dt_out: the samples off the steps are read between two steps
     * (layer_advance_peek), the run's checks every 2e-5 s on the step grid
     * (check_interval). It was made a divisor of dt_out, so that every
     * sample ended a step, and the outcome moved with dt-out: e_n_first
     * 0.1493427 at --dt-out 1e-6 (steps of 1e-6 s) against 0.1493279 at the
     * default 2e-5 (1e-5 s) on the 40-disc pile of `layer-make --n 40` to
     * t-max 0.01 s, now bit for bit (test_dt_out_bitwise) */
    return b / ceil(b / dt);
}

int gw_layer_impact_dt_divides(double dt, double dt_out)
{
    /* relative: the ratio of 2e-5 to 1e-12 is 20000000.000000004 in doubles.
     * Within it, what is left of a sample interval after k steps is a rounding
     * error (the backends land on a sample within 1e-9 of a step) */
    const double q = dt_out / dt, k = nearbyint(q);
    return dt > 0 && k >= 1 && fabs(q - k) <= 1e-9 * k;
}

int gw_layer_impact_step_check(const gw_layer_impact_params *ip, const gw_solver_type *type,
                               const gw_solver_params *sp, gw_err *err)
{
    /* NULL ip passed (GW_OK, nothing checked), NULL sp was read (SIGSEGV) */
    if (!ip || !sp)
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_step_check: %s is NULL", !ip ? "ip" : "sp");
    /* the solver's steps, 0 the automatic step or no limit: a dt of NaN, -1 or
     * -inf failed every "> 0" and ran as the automatic step with GW_OK (the
     * chain's run options refuse them since the forty-ninth pass), an inf or
     * subnormal dt was told to give "a dt that divides it such as -inf s" or
     * "0 s", a dt_max of NaN failed only at the solver's set-up; and the
     * tolerances every backend's create refuses, after the layer was built
     * (the fiftieth pass) */
    const struct {
        const char *name;
        double v;
    } st[] = {{"dt", sp->dt}, {"dt-max", sp->dt_max}};
    for (size_t i = 0; i < 2; i++)
        if (!(isfinite(st[i].v) && st[i].v >= 0) || (st[i].v > 0 && st[i].v < DBL_MIN))
            return gw_err_set(err, GW_EINVAL, "%s: %g s is not 0 (%s) or a normal finite number > 0", st[i].name,
                              st[i].v, i ? "no limit" : "the automatic step");
    /* the program's bound (its --dt row): a verlet step of 1e200 s passed
     * here before, where the program refused it */
    if (sp->dt > GW_LAYER_DT_MAX)
        return gw_err_set(err, GW_EINVAL, "dt: %g s is above %g s (GW_LAYER_DT_MAX, the longest step an impact takes)",
                          sp->dt, GW_LAYER_DT_MAX);
    int trc = gw_solver_tolerances_check(sp->rtol, sp->atol, "rtol", "atol", err);
    if (trc != GW_OK)
        return trc;
    /* A fixed step given that dt_out is not a multiple of, or longer than
     * dt_out, runs as the step given: the samples off the steps are read
     * between two steps (layer_advance_peek), the checks on the step grid
     * (check_interval), so the run is the one at a dt_out it divides, bit
     * for bit (test_dt_out_bitwise). Until session 46 verlet refused a dt
     * that did not divide dt_out (the step before every sample had been
     * shortened to land on it until session 45), and rk4 a dt above dt_out
     * (it landed on every sample, and --exact --dt 1e-4 at the default dt-out
     * 2e-5 ran steps of 2e-5 s while the settings recorded 1e-4) */
    (void)type;
    return GW_OK;
}

/* The series' first room: SERIES_CAP0 samples (or cap_max when fewer), grown
 * by series_room as the run goes. They were reserved whole up front, ceil(t_max
 * / dt_out) + 2 samples: --t-max 40 at the default dt-out reserved 2,000,002
 * samples (0.98 GB at 12 rings) and failed under ulimit -v 800000 ("out of
 * memory for 2000002 samples") a run on the pile of `layer-make --n 40` under
 * --gravity 0.5 that stops at 2.6 s, 130,000 samples. */
#define SERIES_CAP0 4096

static int alloc_series(gw_layer_impact_result *r, int cap, int nr)
{
    r->cap = cap;
    r->nrings = nr;
    r->t = malloc((size_t)cap * sizeof *r->t);
    r->ledger = malloc((size_t)cap * sizeof *r->ledger);
    r->block = malloc(4 * (size_t)cap * sizeof *r->block);
    r->ring_kin = malloc(4 * (size_t)cap * (size_t)nr * sizeof *r->ring_kin);
    r->peak_strain_t = malloc((3 * (size_t)nr + LAYER_CROWN_GRID) * sizeof *r->peak_strain_t);
    if (!r->t || !r->ledger || !r->block || !r->ring_kin || !r->peak_strain_t)
        return GW_ENOMEM;
    r->ring_strain = r->ring_kin + (size_t)cap * nr;
    r->ring_coord = r->ring_kin + 2 * (size_t)cap * nr;
    r->ring_diss = r->ring_kin + 3 * (size_t)cap * nr;
    r->regions = calloc((size_t)nr + 2, sizeof *r->regions);
    if (!r->regions)
        return GW_ENOMEM;
    r->peak_kin_t = r->peak_strain_t + nr;
    r->ring_r = r->peak_strain_t + 2 * nr;
    return GW_OK;
}

/* Room for one more sample in r's series: when full, their room doubled, up to
 * cap_max (the run's ceil(t_max / dt_out) + 2 samples, which the parameters'
 * check bounds: gw_layer_impact_check). The rings' four series stay one block
 * owned by ring_kin (gw_layer_impact_result_free, layer_h5.c), each at its
 * offset of cap samples: strain, coordination and dissipation move up to
 * theirs, the highest first. GW_ENOMEM when the room cannot grow; r is then
 * as it was (each array grown so far is larger, not shorter, than r->cap
 * says), its samples kept, for the caller to free; GW_ELIMIT when r holds
 * cap_max samples already. */
static int series_room(gw_layer_impact_result *r, int cap_max)
{
    if (r->ns < r->cap)
        return GW_OK;
    if (r->cap >= cap_max)
        return GW_ELIMIT; /* not reached: a run takes at most cap_max samples */
    const int cap = r->cap > cap_max / 2 ? cap_max : 2 * r->cap;
    const size_t nr = (size_t)r->nrings, n = (size_t)r->ns, old = (size_t)r->cap, nc = (size_t)cap;
    double *t = realloc(r->t, nc * sizeof *t);
    if (!t)
        return GW_ENOMEM;
    r->t = t;
    gw_layer_energy *ledger = realloc(r->ledger, nc * sizeof *ledger);
    if (!ledger)
        return GW_ENOMEM;
    r->ledger = ledger;
    double *block = realloc(r->block, 4 * nc * sizeof *block);
    if (!block)
        return GW_ENOMEM;
    r->block = block;
    double *rings = realloc(r->ring_kin, 4 * nc * nr * sizeof *rings);
    if (!rings)
        return GW_ENOMEM;
    for (size_t a = 3; a >= 1; a--)
        memmove(rings + a * nc * nr, rings + a * old * nr, n * nr * sizeof *rings);
    r->ring_kin = rings;
    r->ring_strain = rings + nc * nr;
    r->ring_coord = rings + 2 * nc * nr;
    r->ring_diss = rings + 3 * nc * nr;
    r->cap = cap;
    return GW_OK;
}

/* The interval of the checks (the outcome decided, the energy closure).
 * cvode, arkode, rk4 and verlet, which read the samples between two checks on
 * the way (layer_advance_peek), whatever dt_out: cvode and arkode every 2e-5 s,
 * rk4 every 20 steps (2e-5 s at its default 1e-6 s), verlet every 2e-5 s (its
 * automatic step divides it) or, a step given, every 2 steps; their outcome is then the same at every dt_out,
 * bit for bit (test_dt_out_bitwise). A backend without peeks: the default
 * sampling interval (2e-5 s) or dt_out when
 * finer; a fixed step's multiple when the step divides dt_out (a check off
 * the step grid would add a shorter step and change the trajectory), dt_out
 * itself (no check between samples) when it does not. For a fixed step the
 * interval is at least as many steps as the default sampling holds at the
 * default step (verlet 2 of 1e-5 s on the default pile, rk4 20 of 1e-6 s), so
 * a problem scaled in time with its step and dt_out is checked at the same
 * steps (test_layer_invariance: lengths x 4 with rk4's step x 4 and dt_out
 * 8e-5 had been checked every 5 steps, the original never, and the exact
 * mode's outcome moved by up to 3e-6 relative). */
static double check_interval(double dt_out, const gw_solver_type *type, double step, int given)
{
    const int fixed = type == gw_solver_verlet || type == gw_solver_rk4;
    const double base = fixed && step > 0 ? fmax(2e-5, step * (type == gw_solver_rk4 ? 20 : 2)) : 2e-5;
    /* the samples between the checks are peeks (layer_advance_peek): the
     * checks on the step grid whatever dt-out (rk4 at a step that did not
     * divide dt-out was checked at its samples alone, and read its crowns
     * from them) */
    if (layer_can_peek(type)) {
        /* rk4: 20 steps, which scale with a problem scaled in time
         * (test_layer_invariance); 2e-5 itself when within rounding of it,
         * the default sampling's times (k 2e-5) */
        /* verlet: the automatic step, 2e-5 s (2 GW_LAYER_DEM_BASE, a
         * multiple of it: the default sampling's checks, so that the default
         * run is the one it was); a step given, 2 steps (the default's at
         * 1e-5 s), which scale with a problem scaled in time as rk4's 20 */
        double ref = fixed && step > 0 ? 20 * step : 2e-5;
        if (type == gw_solver_verlet)
            ref = step > 0 && given ? 2 * step : 2 * GW_LAYER_DEM_BASE;
        return fabs(ref - 2e-5) <= 1e-9 * 2e-5 ? 2e-5 : ref;
    }
    if (!(dt_out > base))
        return dt_out;
    if (fixed) {
        if (!(step > 0) || !gw_layer_impact_dt_divides(step, dt_out))
            return dt_out;
        return fmin(dt_out, step * fmax(1, floor(base / step * (1 + 1e-9))));
    }
    return base;
}

/* The ledger's closure |E - A| / A now into r->energy_error (its largest). */
static void check_energy(gw_layer_impact_result *r, const gw_layer *L)
{
    gw_layer_energy e;
    gw_layer_energy_of(L, &e);
    const double A = gw_layer_energy_initial(L), x = fabs(e.total - A) / A;
    if (x > r->energy_error)
        r->energy_error = x;
}

/* Record one sample; returns the block's vertical velocity. Its ledger's
 * closure is taken into r->energy_error when energy: not at a sample read on
 * the way between two checks (layer_advance_peek), whose state is
 * interpolated, so that energy_error is taken where the run stops whatever
 * dt_out (--solver cvode --dt-out 7e-6 on the 40-disc pile of `layer-make
 * --n 40` took its samples' and read 1.41879066e-6 against 1.41879065e-6 at
 * the default; test_dt_out_bitwise). */
static double record(gw_layer_impact_result *r, gw_layer *L, int block, double w,
                     const double *strain0, int energy)
{
    int k = r->ns++;
    r->t[k] = gw_layer_time(L);
    double *kin = r->ring_kin + (size_t)k * r->nrings, *str = r->ring_strain + (size_t)k * r->nrings;
    /* (the regions' ledgers are read once, at the end of the run) */
    layer_ledgers_rings(L, &r->ledger[k], NULL, r->impact_x, r->impact_y, w, r->nrings, kin, str,
                        r->ring_coord + (size_t)k * r->nrings, r->ring_diss + (size_t)k * r->nrings);
    double s[6];
    gw_layer_particle(L, block, s);
    r->block[4 * k] = s[0], r->block[4 * k + 1] = s[1];
    r->block[4 * k + 2] = s[3], r->block[4 * k + 3] = s[4];
    for (int q = 0; strain0 && q < r->nrings; q++)
        str[q] -= strain0[q];
    double A = gw_layer_energy_initial(L);
    double e = fabs(r->ledger[k].total - A) / A;
    if (energy && e > r->energy_error)
        r->energy_error = e;
    return s[4];
}

/* The rings' strain and kinetic series at the run's checks, for the crowns
 * (layer_crowns_series), when --dt-out is coarser than the checks: the wave
 * speeds came from the written samples, and a coarse --dt-out left them null
 * (98 m/s by the strain peaks on the 40-disc pile of `layer-make --n 40` at
 * the default 2e-5 s, null at 5e-3 s). The checks lie on the grid j h (h the
 * check interval, 2e-5 s on the default step grid, whatever dt-out), so the
 * series is the default sampling's, value for value. Point j is kept when j
 * is a multiple of stride; full at cap_max points, every other one is dropped
 * and stride doubled (an even series of bounded size). No point is kept after
 * the first at or after T_f (the first impact, all the crowns read). */
typedef struct crown_series {
    double *t;                /* [cap] */
    /* one block [2 nr + 2 cap nr]: room for the crowns' delays and correlations,
     * then strain [cap * nr], then kin [cap * nr] (the layout of the result's
     * xcorr_delay block, so that the analysis turns the series into the spectra
     * in place: layer_crowns_series) */
    double *buf, *kin, *strain;
    double *scratch;          /* [2 nr]: the rings' coordination and dissipation */
    int n, cap, cap_max, nr;
    long stride;
    int closed;
} crown_series;

static void crown_series_free(crown_series *c)
{
    free(c->t), free(c->buf), free(c->scratch);
    memset(c, 0, sizeof *c);
}

/* Room for one more point (thinning when full); GW_ENOMEM. */
static int crown_room(crown_series *c)
{
    const size_t nr = (size_t)c->nr;
    if (c->n == c->cap_max) {
        int m = 0;
        for (int i = 0; i < c->n; i += 2, m++) {
            c->t[m] = c->t[i];
            memmove(c->kin + (size_t)m * nr, c->kin + (size_t)i * nr, nr * sizeof *c->kin);
            memmove(c->strain + (size_t)m * nr, c->strain + (size_t)i * nr, nr * sizeof *c->strain);
        }
        c->n = m;
        c->stride *= 2;
        return GW_OK;
    }
    if (c->n < c->cap)
        return GW_OK;
    const int cap = c->cap < 1024 ? (c->cap_max < 1024 ? c->cap_max : 1024)
                    : c->cap < c->cap_max / 2 ? 2 * c->cap : c->cap_max;
    double *t = realloc(c->t, (size_t)cap * sizeof *t);
    if (t)
        c->t = t;
    double *b = t ? realloc(c->buf, (2 + 2 * (size_t)cap) * nr * sizeof *b) : NULL;
    if (!b)
        return GW_ENOMEM;
    c->buf = b;
    c->strain = b + 2 * nr;
    /* the kinetic rows move up past the strain's new room */
    memmove(c->strain + (size_t)cap * nr, c->strain + (size_t)c->cap * nr, (size_t)c->n * nr * sizeof *b);
    c->kin = c->strain + (size_t)cap * nr;
    c->cap = cap;
    return GW_OK;
}

/* Point j of the grid (time t): the rings' values kin, strain when given (a
 * sample just recorded), else read from L as record() does. */
static int crown_point(crown_series *c, const gw_layer_impact_result *r, const layer_outcome *oc, gw_layer *L,
                       long j, double w, const double *strain0, const double *kin, const double *strain)
{
    if (c->closed || j % c->stride != 0)
        return GW_OK;
    if (crown_room(c) != GW_OK)
        return GW_ENOMEM;
    if (j % c->stride != 0) /* thinned just now */
        return GW_OK;
    const size_t nr = (size_t)c->nr;
    double *ck = c->kin + (size_t)c->n * nr, *cs = c->strain + (size_t)c->n * nr;
    c->t[c->n] = gw_layer_time(L);
    if (kin) {
        memcpy(ck, kin, nr * sizeof *ck);
        memcpy(cs, strain, nr * sizeof *cs);
    } else {
        gw_layer_energy e;
        layer_ledgers_rings(L, &e, NULL, r->impact_x, r->impact_y, w, c->nr, ck, cs, c->scratch,
                            c->scratch + nr);
        for (size_t q = 0; q < nr; q++)
            cs[q] -= strain0[q];
    }
    c->closed = oc->verdict == 1 && oc->tf && c->t[c->n] >= oc->t_f;
    c->n++;
    return GW_OK;
}

int gw_layer_impact(const gw_layer_sample *smp, const gw_layer_params *lp0,
                    const gw_layer_impact_params *ip, const gw_solver_type *type,
                    const gw_solver_params *sp, gw_layer_impact_result *res, gw_err *err)
{
    return layer_impact_run(smp, lp0, ip, type, sp, NULL, res, err);
}

int layer_impact_run(const gw_layer_sample *smp, const gw_layer_params *lp0, const gw_layer_impact_params *ip,
                     const gw_solver_type *type, const gw_solver_params *sp, const layer_settling_found *found,
                     gw_layer_impact_result *res, gw_err *err)
{
    if (!smp || !lp0 || !ip || !type || !sp || !res) {
        if (res)
            memset(res, 0, sizeof *res);
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact: %s is NULL",
                          !smp ? "s" : !lp0 ? "lp" : !ip ? "ip" : !type ? "type" : !sp ? "sp" : "res");
    }
    memset(res, 0, sizeof *res);
    /* the sample checked once (layer_sample_shape_check; a plan's, found
     * given, by the reader that read it), then the rules of
     * gw_layer_impact_check, gw_layer_impact_gap_check, the step and the
     * settling on it: each of those took the O(n) check again, 3 times a
     * call of gw_layer_impact and 6 a run of the program until session 44,
     * the overlap grid built each time */
    int rc = found ? GW_OK : layer_sample_shape_check(smp, "s", err);
    if (rc == GW_OK)
        rc = layer_impact_params_check(smp, ip, err);
    if (rc == GW_OK)
        rc = layer_impact_gap_rules(smp, ip, lp0->gravity, gap_at_default(ip), err);
    if (rc == GW_OK)
        rc = gw_layer_impact_step_check(ip, type, sp, err);
    /* (a sample built in memory: gw_layer_impact_check holds its springs to
     * the reader's checks; a NaN was clipped to the cap, an index beyond the
     * sample ignored, in silence) */
    if (rc != GW_OK)
        return rc;
    const int n = smp->n;
    const double rm = smp->rm, rb = ip->rb_rm * rm, xc = 0.5 * smp->width + ip->x;
    gw_layer_params lp = *lp0;
    lp.width = smp->width;
    lp.potential_from_start = 1;
    lp.no_events = 0;
    lp.walls = impact_walls(ip);
    if ((rc = layer_side_walls_rest_check(smp, &lp, ip, err)) != GW_OK)
        return rc;
    double yb = -INFINITY;
    int target = -1;
    for (int i = 0; i < n; i++) {
        double dx = smp->x[i] - xc, reach = rb + smp->r[i];
        if (fabs(dx) < reach) {
            double yy = smp->y[i] + sqrt(reach * reach - dx * dx);
            if (yy > yb)
                yb = yy, target = i;
        }
    }
    if (target < 0)
        return gw_err_set(err, GW_EINVAL, "x: no soil particle under the block at x = %g m", ip->x);
    yb += ip->gap;
    gw_layer_body *b = calloc((size_t)n + 1, sizeof *b);
    if (!b)
        return gw_err_set(err, GW_ENOMEM, "layer-impact: out of memory");
    unsigned char *fixed = malloc((size_t)n);
    if (!fixed || (res->n_frozen = frozen_set(smp, freeze_level(smp, ip->height_rm, NULL), fixed)) < 0) {
        free(fixed);
        free(b);
        res->n_frozen = 0;
        return gw_err_set(err, GW_ENOMEM, "layer-impact: out of memory");
    }
    for (int i = 0; i < n; i++) {
        b[i] = (gw_layer_body){.x = smp->x[i], .y = smp->y[i], .r = smp->r[i]};
        b[i].fixed = fixed[i]; /* a clump with a frozen member is frozen whole */
        b[i].clump = smp->body ? smp->body[i] + 1 : 0;
    }
    free(fixed);
    res->n_mobile = n - res->n_frozen;
    const double al = ip->alpha_deg * M_PI / 180;
    b[n] = (gw_layer_body){.x = xc, .y = yb, .r = rb, .vx = ip->vi * sin(al), .vy = -ip->vi * cos(al)};
    gw_layer *L = NULL;
    rc = gw_layer_create(&lp, n + 1, b, &L, err);
    free(b);
    if (rc != GW_OK)
        return rc;
    gw_layer_set_block(L, n);
    /* the springs the pile leans on (the sample's indices are the layer's; the
     * block, n, has none): the first contact list starts from them, turned into
     * this material's forces and clipped to its Coulomb bound (layer_springs_load) */
    if (!ip->zero_springs && smp->n_springs > 0 && layer_springs_pend(L, smp->springs, smp->n_springs) != GW_OK) {
        gw_layer_free(L);
        return gw_err_set(err, GW_ENOMEM, "layer-impact: out of memory for %d springs", smp->n_springs);
    }
    const double w = ip->ring_width > 0 ? ip->ring_width : 2 * rm;
    {
        double dx = xc - smp->x[target], dy = yb - smp->y[target], d = hypot(dx, dy);
        res->impact_x = smp->x[target] + smp->r[target] * dx / d;
        res->impact_y = smp->y[target] + smp->r[target] * dy / d;
        /* obliquity of the first contact: incident velocity against the normal */
        double vn = -(sin(ip->alpha_deg * M_PI / 180) * dx - cos(ip->alpha_deg * M_PI / 180) * dy) / d;
        res->contact_angle_deg = acos(fmax(-1, fmin(1, vn))) * 180 / M_PI;
    }
    layer_outcome oc;
    layer_outcome_init(&oc, L, ip->until, ip->gap == 0);
    rc = gw_layer_set_regions(L, res->impact_x, res->impact_y, w, ip->nrings, err);
    if (rc == GW_OK)
        rc = gw_layer_watch_block(L, layer_outcome_event, &oc, err);
    if (rc == GW_OK && target >= 0)
        layer_watch_first_contact(L, target);
    if (rc != GW_OK) {
        gw_layer_free(L);
        return rc;
    }
    res->block_mass = gw_layer_particle_mass(L, n);
    res->e_incident = 0.5 * res->block_mass * ip->vi * ip->vi;
    res->v_ni = ip->vi * cos(al);
    /* First contact (docs/physics.md 2.5): from the touch to the block's smallest
     * kinetic energy while it still touches the target particle, the phase in
     * which the block hands its energy over. The contact itself may last longer
     * (the target pushes the block back); the dissipation up to the opening is
     * reported separately. Both are read at every step end by the block watch
     * (layer_watch_first_contact), not at the samples: read at the samples,
     * dissipated_first_contact moved by 5 % between --dt-out 1e-5 and 1e-4 s on
     * the same trajectory, and a contact shorter than three samples had none. */
    gw_solver_params spu = *sp;
    if (type == gw_solver_verlet && !(spu.dt > 0)) {
        spu.dt = layer_impact_dem_dt(smp, &lp, ip);
        /* a block so small that its mass, and with it the shortest contact
         * time, underflows (--rb-rm 1e-300): the step came out 0 and the
         * solver's set-up said "verlet: the fixed step dt must be set" */
        if (!(spu.dt >= DBL_MIN)) {
            gw_layer_free(L);
            return gw_err_set(err, GW_EINVAL, "rb-rm: a block of %g R_m makes the automatic step (the shortest "
                              "contact time / 100) %g s: its mass underflows; a larger block", ip->rb_rm, spu.dt);
        }
    }
    res->dt = type == gw_solver_verlet || type == gw_solver_rk4 ? spu.dt : 0;
    rc = gw_layer_start(L, type, &spu, err);
    if (rc != GW_OK) {
        gw_layer_free(L);
        return rc;
    }
    res->method = gw_solver_method_used(type, L->sp.method); /* cvode: adams unless asked */
    /* a fixed step is bounded by the work it takes to t-max, once the contact
     * list is built and before the series are allocated: steps x (particles +
     * listed contacts) at most 1e10 (the default impact to T_f takes 1.3e7
     * particle-steps, its exact mode 1.3e8) and at most 1e9 steps. The listed
     * contacts count because the skin is in metres: on a sample of R_m =
     * 3.25e-5 m the default 0.1 m lists all 45,000 pairs of 300 discs, 24 s of
     * CPU per ms simulated, a 45-minute default impact that a bound on the
     * particles alone let through */
    gw_layer_stats st0;
    gw_layer_get_stats(L, &st0);
    const double per_step = (double)(n + 1) + (double)st0.contacts_listed;
    const double work = res->dt > 0 ? ip->t_max / res->dt * per_step : 0;
    if (rc == GW_OK && res->dt > 0 && (ip->t_max / res->dt > 1e9 || work > 1e10)) {
        gw_layer_free(L);
        /* the automatic verlet step comes from the materials (--density 1e-6
         * gave 1.7e-9 s), not from a dt the user gave: "raise dt" misled */
        const int autodt = type == gw_solver_verlet && !(sp->dt > 0);
        return gw_err_set(err, GW_EINVAL, "%s: %s of %g s takes %.3g steps of %d particles and %ld listed "
                          "contacts to t-max = %g s, %.3g particle-steps, more than 1e10 (%s%s)",
                          autodt ? "t-max" : "dt", autodt ? "the automatic step (the shortest contact time / 100)"
                          : "a step", res->dt, ip->t_max / res->dt, n + 1, st0.contacts_listed, ip->t_max, work,
                          autodt ? "lower t-max" : "raise dt, lower t-max",
                          st0.contacts_listed > 8L * (n + 1) ? " or the skin" : "");
    }
    /* the settling recorded in the sample against this material: refused far
     * from rest (unless other_settling), else its warning kept in the result;
     * found by the plan (gw_layer_impact_run, the program's layer-impact:
     * layer_plan_run.h), or here, once: a run checked it
     * twice and weighed a union-clump pile under clump-mass sum five times */
    double q = NAN; /* NaN: nothing recorded */
    if (rc == GW_OK && found) {
        q = found->q;
        gw_snprintf(res->settling, sizeof res->settling, "%s", found->warning);
    } else if (rc == GW_OK && (rc = layer_settled_check_q(smp, &lp, ip->other_settling, NULL, res->settling,
                                                          sizeof res->settling, &q, err)) != GW_OK) {
        gw_layer_free(L);
        return rc;
    }
    res->settled_load_ratio = q;
    if (rc == GW_OK && !found && (rc = layer_rest_check(smp, &lp, ip->other_settling, NULL, q, err)) != GW_OK) {
        gw_layer_free(L);
        return rc;
    }
    /* the run's samples at most; their room grows as it goes (series_room) */
    const int cap = (int)ceil(ip->t_max / ip->dt_out) + 2;
    double *strain0 = malloc((size_t)ip->nrings * 3 * sizeof *strain0);
    if (!strain0 || alloc_series(res, cap < SERIES_CAP0 ? cap : SERIES_CAP0, ip->nrings) != GW_OK) {
        free(strain0);
        gw_layer_free(L);
        gw_layer_impact_result_free(res);
        return gw_err_set(err, GW_ENOMEM, "layer-impact: out of memory for %d samples", cap < SERIES_CAP0 ? cap
                          : SERIES_CAP0);
    }
    for (int k = 0; k < ip->nrings; k++)
        res->ring_r[k] = (k + 0.5) * w;
    const double h = check_interval(ip->dt_out, type, res->dt, sp->dt > 0);
    /* checks between samples, or (cvode, arkode, rk4) samples between checks, read on the
     * way without a stop (layer_advance_peek) */
    const int peek = layer_can_peek(type) && fabs(h - ip->dt_out) > 1e-9 * h;
    const int grid = h < ip->dt_out * (1 - 1e-9) || peek;
    /* the crowns from the checks when the samples are coarser, else from the
     * samples (a finer dt-out resolves them better) */
    const int crowns_checks = h < ip->dt_out * (1 - 1e-9);
    crown_series crowns = {.t = NULL, .buf = NULL, .kin = NULL, .strain = NULL, .scratch = NULL, .n = 0, .cap = 0,
                           .cap_max = 0, .nr = ip->nrings, .stride = 1, .closed = 0};
    /* at most 2^22 values (33.5 MB; 167,772 points of 12 rings, 3.4 s at
     * 2e-5 s: every check of a first impact within the default t-max of 2 s
     * at the default rings) at every ring count: 2096 points at 1000 rings,
     * at least 1048 over the first impact, so a first impact up to 0.58 s
     * long (the 40-disc pile's: 0.306 s) still gives a crown's crossing at
     * 580 m/s (1.1 ms) the two sampling intervals the speeds need
     * (layer_crowns.c). It was 2^24 (134 MB, 13 s), then 4096
     * points above 511 rings (8.2e6 values, 65 MB, at 1000 rings); the
     * crowns' analysis turns the series into its spectra in place
     * (layer_crowns_series) where it added about as much again: on the pile
     * of `layer-make --n 40` at --dt-out 1e-2, --rings 1000 peaked at 262 MB,
     * then 134, now 43 MB (its speeds moved by 0.3 % of their errors), and
     * --rings 100 under --gravity 0.5 (T_f 2.6 s) at 252 MB, then 70 MB
     * (test_crowns_series_bound) */
    crowns.cap_max = 2 * (int)((double)(1 << 21) / (1 + 2.0 * ip->nrings));
    if (rc == GW_OK && crowns_checks && !(crowns.scratch = malloc(2 * (size_t)ip->nrings * sizeof *crowns.scratch)))
        rc = gw_err_set(err, GW_ENOMEM, "layer-impact: out of memory for the crowns' series");
    double t0 = gw_clock_ms();
    if (rc == GW_OK) {
        gw_layer_rings(L, res->impact_x, res->impact_y, w, ip->nrings, strain0 + ip->nrings,
                       strain0, strain0 + 2 * ip->nrings);
        record(res, L, n, w, strain0, 1);
        if (crowns_checks &&
            crown_point(&crowns, res, &oc, L, 0, w, strain0, res->ring_kin, res->ring_strain) != GW_OK)
            rc = gw_err_set(err, GW_ENOMEM, "layer-impact: out of memory for the crowns' series");
        if (rc == GW_OK && ip->on_sample && (rc = ip->on_sample(ip->sample_ctx, L, 0, 0)) != GW_OK)
            gw_err_set(err, rc, "layer-impact: the sample hook stopped the run at t = 0");
    }
    int cut = 0; /* the run reached t_max */
    int done = 0; /* the outcome was decided at a check between two samples */
    long jc = 1;  /* the next check, at t = jc h */
    for (int k = 1; rc == GW_OK && k < cap; k++) {
        double tk = fmin(k * ip->dt_out, ip->t_max);
        /* the run stops at the check after the outcome is decided, every h
         * (the default sampling interval, on the step grid), whatever dt-out:
         * it stopped at the first sample after it, so --dt-out 0.2 ran the
         * default impact (T_f 0.306 s) to t_end 0.4 s and read energy_error
         * at its samples alone (1.6e-5 against 3.4e-5 at the default), and
         * --until verdict (the verdict at 1.56 ms) ran to 0.2 s. The last
         * sample is then taken at that check. The checks lie at j h, and a
         * sample on one of them (within 1e-9 h) stops the solver at j h, as
         * the default sampling does (k h): they were at the last sample plus
         * h, summed, and a sample at k dt_out, so cvode's stops (where the
         * layer projects the state cvode interpolates and restarts cvode from
         * it when a contact changes: layer_on_output) moved by a rounding
         * with dt-out (e_n by 4.2e-12 at --dt-out 0.2 on the 40-disc pile of
         * `layer-make --n 40`; now bit for bit). A dt-out that is no multiple
         * of h still stops cvode between the checks (e_n 1.2e-9 at 3e-5) */
        long jk = -1;    /* the check this sample falls on */
        int peeked = 0;  /* the sample is between two checks (layer_can_peek), read on the way */
        while (rc == GW_OK && !done) {
            double tj = tk;
            int check = 0;
            if (grid) {
                const double tg = (double)jc * h;
                if (tg < tk - 1e-9 * h) {
                    tj = tg, check = 1;
                } else if (tg <= tk + 1e-9 * h && jk < 0) {
                    jk = jc++, tj = tk < ip->t_max ? tg : tk;
                } else if (peek && tk < ip->t_max) {
                    /* no stop at tk: cvode's stops there changed the run
                     * (e_n by 1.2e-9 at --dt-out 3e-5, 5.0e-8 at 1e-5 on
                     * the 40-disc pile of `layer-make --n 40`, and t_end
                     * was the sample's after the outcome) */
                    rc = layer_advance_peek(L, tk, fmin(tg, ip->t_max), err);
                    peeked = 1;
                    break;
                }
            }
            rc = gw_layer_advance(L, tj, err);
            if (rc != GW_OK || !check)
                break;
            if (crowns_checks && crown_point(&crowns, res, &oc, L, jc, w, strain0, NULL, NULL) != GW_OK) {
                rc = gw_err_set(err, GW_ENOMEM, "layer-impact: out of memory for the crowns' series");
                break;
            }
            jc++;
            check_energy(res, L);
            if (ip->energy_tol > 0 && res->energy_error > ip->energy_tol)
                break; /* said below, at this time */
            done = !ip->full && layer_outcome_done(&oc);
        }
        if (rc != GW_OK)
            break;
        const double tnow = gw_layer_time(L); /* tk, or the check that ended the run */
        if ((rc = series_room(res, cap)) != GW_OK) {
            if (rc == GW_ENOMEM)
                gw_err_set(err, rc, "layer-impact: out of memory for %d samples at t = %.9g s",
                           res->cap > cap / 2 ? cap : 2 * res->cap, tnow);
            else
                gw_err_set(err, rc, "layer-impact: more than %d samples at t = %.9g s", cap, tnow);
            break;
        }
        record(res, L, n, w, strain0, !peeked);
        const size_t last = (size_t)(res->ns - 1) * (size_t)res->nrings;
        if (crowns_checks && jk >= 0 && crown_point(&crowns, res, &oc, L, jk, w, strain0, res->ring_kin + last,
                                   res->ring_strain + last) != GW_OK) {
            rc = gw_err_set(err, GW_ENOMEM, "layer-impact: out of memory for the crowns' series");
            break;
        }
        if (ip->on_sample && (rc = ip->on_sample(ip->sample_ctx, L, res->ns - 1, 0)) != GW_OK) {
            gw_err_set(err, rc, "layer-impact: the sample hook stopped the run at t = %.9g s", tnow);
            break;
        }
        if (ip->energy_tol > 0 && res->energy_error > ip->energy_tol) {
            double sb[6];
            gw_layer_particle(L, n, sb);
            rc = gw_err_set(err, GW_ESOLVER, "energy monitor: ledger closure %.3g exceeds energy-tol %g "
                            "at t = %.9g s (block at (%.6g, %.6g) m, velocity (%.6g, %.6g) m/s); "
                            "reduce dt or the tolerances", res->energy_error, ip->energy_tol, tnow,
                            sb[0], sb[1], sb[3], sb[4]);
            break;
        }
        if (done || (!peeked && !ip->full && layer_outcome_done(&oc)))
            break; /* the outcome is decided: events on the block, not these samples */
        if (tk >= ip->t_max) {
            cut = 1;
            break;
        }
    }
    free(strain0);
    free(crowns.scratch);
    crowns.scratch = NULL;
    if (rc == GW_OK) /* the regions' ledgers at the last sample */
        gw_layer_ledgers(L, NULL, res->regions);
    res->wall_ms = gw_clock_ms() - t0;
    res->t_end = gw_layer_time(L);
    gw_layer_get_stats(L, &res->stats);
    if (rc == GW_OK && ip->on_sample && (rc = ip->on_sample(ip->sample_ctx, L, res->ns - 1, 1)) != GW_OK)
        gw_err_set(err, rc, "layer-impact: the sample hook stopped the run at its end");
    if (rc != GW_OK && rc != GW_EINVAL && ip->on_sample && res->ns > 0)
        (void)ip->on_sample(ip->sample_ctx, L, res->ns - 1, 2); /* the state at the failure */
    if (rc != GW_OK) {
        gw_layer_free(L);
        gw_layer_impact_result_free(res);
        crown_series_free(&crowns);
        return rc;
    }
    /* the penetration counts from the touch, not from the start: measured from
     * yb it held the gap (--gap 0.04 at 20 m/s: 0.0571 m against 0.0171 at
     * the default 1e-6 m on a 40-disc sample) */
    layer_outcome_finish(&oc, yb - ip->gap, ip->vi, res->t_end, cut && !layer_outcome_done(&oc), res);
    /* A pile without one of its side walls slumps from t = 0 on its open
     * side (every pile does some: layer_side_walls_rest_check); its kinetic
     * energy when the block arrives is read at the touch event, whatever
     * dt-out (GW_LAYER_SLUMP_WARN, gw_layer.h, gives the measurements). */
    res->slump_ke = !ip->remove_walls && ip->side_walls != GW_LAYER_SIDES_BOTH ? oc.touch_ke : NAN;
    /* The first-contact values are frozen at the verdict (layer_outcome.c):
     * read up to the end of the run, they depended on where it stopped, the
     * first sample after the verdict. A block that did not bounce and still
     * rested on its target gave t_contact_open = t_end and
     * dissipated_contact_open 0.510, 0.518 and 0.537 at --dt-out 1e-5, 1e-4
     * and 1e-3 (the contact opened at 5.53 ms, after the verdict at 5.35 ms).
     * A contact that had not opened by then (or by the end of an undecided
     * run) has no opening: NaN (null), where t_end stood in for it */
    const layer_first_contact *fc = &L->fc;
    double t_open = fc->t_open, ed_open = fc->ed_open, kb_open = fc->kb_open;
    /* undecided (NaN) when fewer than three step ends fell in the contact, so
     * that its smallest block energy is not bracketed; and when the run ended
     * at t-max, undecided, before the contact opened: its smallest block
     * energy so far is not the contact's (--t-max 6e-8, 1e-8 s into the
     * contact at 20 m/s, gravity still speeding the block up against the
     * contact's first force: "ends at 5e-05 ms", the touch itself, a block
     * loss of -4.9e-8, under rk4, cvode and arkode) */
    double t_min, kb_min, ed_min, edb_min;
    layer_watch_first_contact_min(L, &t_min, &kb_min, &ed_min, &edb_min);
    const int cut_inside = cut && !layer_outcome_done(&oc) && isnan(fc->t_open);
    if (fc->n_touch < 3 || cut_inside)
        t_min = kb_min = ed_min = edb_min = NAN;
    res->t_first_contact = t_min;
    res->dissipated_first_contact = over_incident(ed_min, res->e_incident);
    res->dissipated_first_contact_block = over_incident(edb_min, res->e_incident);
    res->block_loss_first_contact = over_incident(res->ledger[0].kinetic_block - kb_min, res->e_incident);
    res->t_contact_open = t_open;
    res->dissipated_contact_open = over_incident(ed_open, res->e_incident);
    res->block_loss_contact_open = over_incident(res->ledger[0].kinetic_block - kb_open, res->e_incident);
    gw_layer_free(L);
    /* the crowns from the checks' series when dt-out is coarser (crown_series) */
    rc = crowns_checks ? layer_crowns_series(res, crowns.t, &crowns.buf, crowns.cap, crowns.n)
              : layer_crowns_series(res, NULL, NULL, 0, 0);
    crown_series_free(&crowns);
    if (rc != GW_OK) {
        gw_layer_impact_result_free(res);
        return gw_err_set(err, rc, "layer-impact: out of memory for the crowns analysis");
    }
    return GW_OK;
}
