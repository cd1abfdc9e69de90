/*
 * layer_settled.c: does the pile rest under the impact's material? The sample
 * keeps the overlaps its pile settled with, and, when layer-make wrote it, the
 * material, gravity and clump mass it settled under (gw_layer_settled, read
 * from its settings line). A Hertz contact carries F = K_n u^(3/2) with
 * K_n ~ G/(1 - nu) (physics.md 2.1, B.3), so a pile at rest under
 * (G, nu, rho, g, mass law, clump mass)_s has overlaps u ~ (m g / K_n)^(2/3);
 * under the impact's (...)_i they carry
 *   q = [G/(1 - nu)]_i / [G/(1 - nu)]_s x W_s / W_i
 * of the weight they carried at rest (W: the pile's weight, the sum of its
 * bodies' masses times g under each law: a disc's m(r), a clump's members
 * added (sum) or its union's area times rho (union); the union of a clump's
 * overlapping members weighs less than their sum). q < 1: the pile sags into
 * the impact, q > 1: it springs up; either way the impact measures the pile's
 * own motion as well as the block's.
 *
 * The thresholds: a Hertz drop from overlap x d to the rest overlap d
 * (x = q^(2/3)) turns E_rest [(5/2)(1 - x) - (1 - x^(5/2))] into motion, E_rest
 * the strain energy at rest: 0.19 E_rest at q = 1.5 (the floor-load bound the
 * impact already held, LAYER_FLOOR_LOAD_MAX) and 0.24 at q = 0.5. Measured on
 * 40-disc piles (seed 1) left alone under the default material: the soil's
 * kinetic energy in the first 5 ms is 0.5-2 J on piles settled under it
 * (their tangential forces start at zero), 1.4 J at q = 0.75, 6.4 J at
 * q = 0.38, 15 J at q = 0.1 and 19 J at q = 0.038; the default block at
 * 2 m/s then gives e_n 20-27 % below the same pile settled again under the
 * impact's material at q = 0.038-0.19 (4 % on the pile settled at g = 1),
 * 7.5 % at 0.38, and 0.2-5.4 % at 0.75-1.13, where settling a matched pile
 * again alone changes it by 1.5 % (at 20 m/s the block's 176 kJ drown the
 * pile's joules: e_n within 0.0035 at q <= 0.38). Outside [0.5, 1.5] the
 * impact is refused unless asked for (other_settling).
 *
 * Friction: the tangential forces start at zero, so a pile leans on the
 * friction it settled with only once it sags, and with less of it the pile
 * may flow. How much less a pile bears depends on the pile. Left alone for
 * 100 ms (verlet, the default block resting on it at 0.01 m/s; layer-make
 * --seed 1 at the default 30 degrees and width, potential energy lost):
 *   300 discs: at 30 degrees 204 J; at 19.2 (tan 0.603 of tan 30) it rests
 *     too (21 J of soil motion at 30 ms at both); it flows at 17.5 (711 J
 *     and 64 J of motion, growing);
 *   600 discs: 2.1 kJ at 30 (the motion decays to 75 J); at 19.2 it flows:
 *     37 kJ, its motion growing to 9.1 kJ;
 *   1000 discs: 5.9 kJ by 300 ms at 30 and 10.3 kJ at 27 (0.883), the motion
 *     decaying to 88 and 68 J; at 24 (0.771) it flows, 80 kJ and growing; at
 *     19.2, 190 kJ and 27 kJ of motion, collapsing while a 2 m/s block
 *     (1.8 kJ) would be in it.
 * A bound taken from one pile (0.6 of the tangent, from the 300-disc pile)
 * let the taller ones collapse under a warning, so the only bound that holds
 * for every pile is the settling's own friction: a lower one is refused
 * (GW_LAYER_SETTLED_FRICTION_MIN = 1, to a relative 1e-9) unless
 * other_settling, which runs it with a warning.
 * Any other difference is a warning: q not 1, another mass law or clump mass
 * (q then from the total weights, the bodies' shares differ), a higher
 * friction.
 * Units: SI (Pa, kg/m^3, m/s^2), angles in degrees.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"
#include "gw_locale.h"
#include "gw_number_impl.h"

/* The clump mass law the sample's bodies settled under: the settings line's,
 * else the sample's own clump_mass line. */
static int settled_clump_mass(const gw_layer_sample *smp)
{
    return smp->settled.clump_mass >= 0 ? smp->settled.clump_mass : smp->clump_mass;
}

/* The weight of the sample's clumps as unions under lp (their masses as
 * gw_layer_create sets them; a one-disc clump weighs its disc), N: *w;
 * GW_OK, or gw_layer_create's status and message in err. */
static int union_weight(const gw_layer_sample *smp, const gw_layer_params *lp, double *w, gw_err *err)
{
    gw_layer_params p = *lp;
    p.clump_mass = GW_LAYER_CLUMP_MASS_UNION;
    p.width = smp->width;
    gw_layer_body *b = calloc((size_t)smp->n, sizeof *b);
    char *seen = calloc((size_t)smp->n, 1);
    gw_layer *L = NULL;
    int rc = b && seen ? GW_OK : gw_err_set(err, GW_ENOMEM, "out of memory weighing the sample's clumps");
    for (int i = 0; rc == GW_OK && i < smp->n; i++)
        b[i] = (gw_layer_body){.x = smp->x[i], .y = smp->y[i], .r = smp->r[i], .clump = smp->body[i] + 1};
    if (rc == GW_OK)
        rc = gw_layer_create(&p, smp->n, b, &L, err);
    *w = 0;
    for (int i = 0; rc == GW_OK && i < smp->n; i++) {
        const int k = gw_layer_body_of(L, i);
        if (!seen[k]++)
            *w += gw_layer_particle_mass(L, i) * lp->gravity;
    }
    gw_layer_free(L);
    free(b);
    free(seen);
    return rc;
}

/* q of the header comment for smp under lp into *q (NaN: nothing recorded);
 * GW_OK, or the status of weighing union clumps (err: why). */
/* lp with the material a sample's settling record gives (its contact law,
 * density, mass law and gravity): the pile as layer-make settled it */
static gw_layer_params settling_material(const gw_layer_params *lp, const gw_layer_settled *st)
{
    gw_layer_params sp = *lp;
    sp.shear_modulus = st->shear_modulus;
    sp.poisson = st->poisson;
    sp.density = st->density;
    sp.gravity = st->gravity;
    sp.mass_law = st->mass_law;
    return sp;
}

static int load_ratio(const gw_layer_sample *smp, const gw_layer_params *lp, double *q, gw_err *err)
{
    *q = NAN;
    if (!smp->settled.recorded)
        return GW_OK;
    const gw_layer_settled *st = &smp->settled;
    const gw_layer_params sp = settling_material(lp, st); /* for its masses */
    double ws = 0, wi = 0;
    for (int i = 0; i < smp->n; i++) {
        ws += gw_layer_mass(&sp, smp->r[i]);
        wi += gw_layer_mass(lp, smp->r[i]);
    }
    ws *= st->gravity;
    wi *= lp->gravity;
    /* a clump pile whose clump mass differs: the union side weighed as such
     * (both union: the union's areas cancel, as the discs' do; without
     * clumps the law is moot) */
    const int cs = settled_clump_mass(smp), ci = lp->clump_mass;
    int rc = GW_OK;
    if (smp->body && cs != ci)
        rc = cs == GW_LAYER_CLUMP_MASS_UNION ? union_weight(smp, &sp, &ws, err) : union_weight(smp, lp, &wi, err);
    const double kr = (lp->shear_modulus / (1 - lp->poisson)) / (st->shear_modulus / (1 - st->poisson));
    if (rc == GW_OK)
        *q = wi > 0 ? kr * ws / wi : INFINITY;
    return rc;
}

double gw_layer_settled_load_ratio(const gw_layer_sample *smp, const gw_layer_params *lp)
{
    gw_err e = {{0}};
    /* (a NULL r was read: SIGSEGV; a NaN gravity gave inf, a gravity of
     * 1e300 9.81e-300: the impact's material as the run holds it) */
    if (smp && lp && layer_sample_shape_check(smp, "s", &e) == GW_OK && gw_layer_params_validate(lp, &e) == GW_OK)
        return layer_settled_load_ratio(smp, lp);
    return NAN;
}

double layer_settled_load_ratio(const gw_layer_sample *smp, const gw_layer_params *lp)
{
    double q = NAN;
    gw_err e = {{0}};
    load_ratio(smp, lp, &q, &e);
    return q;
}

/* Append "NAME A UNIT against the impact's B" to the list in buf when a != b. */
static void differ(char *buf, size_t n, const char *name, double a, double b, const char *unit)
{
    if (a == b)
        return;
    const size_t k = strlen(buf);
    char as[40], bs[40];
    gw_snprintf(buf + k, n - k, "%s%s %s%s against the impact's %s", k ? ", " : "", name,
                gw_num_text(as, sizeof as, a), unit, gw_num_text(bs, sizeof bs, b));
}

/* The impact's friction coefficient over the settling's (1 when the same;
 * an infinity for a pile settled without friction, which leaned on none). */
static double friction_ratio(double settled_deg, double impact_deg)
{
    if (settled_deg == impact_deg)
        return 1;
    const double ts = tan(settled_deg * M_PI / 180), ti = tan(impact_deg * M_PI / 180);
    return ts > 0 ? ti / ts : INFINITY;
}

int gw_layer_impact_settled_check(const gw_layer_sample *smp, const gw_layer_params *lp, int other_settling,
                                  const char *name, char *warning, size_t n, gw_err *err)
{
    if (warning && n > 0)
        warning[0] = '\0';
    if (!smp || !lp)
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_settled_check: %s is NULL", !smp ? "s" : "lp");
    /* the pile was weighed through a NULL r (SIGSEGV) */
    const int src = layer_sample_shape_check(smp, name ? name : "s", err);
    if (src != GW_OK)
        return src;
    /* the impact's material as the run holds it: a NaN gravity was told
     * "against the impact's nan" and run under other_settling */
    const int prc = gw_layer_params_validate(lp, err);
    if (prc != GW_OK)
        return prc;
    double q;
    return layer_settled_check_q(smp, lp, other_settling, name, warning, n, &q, err);
}

/* A pile layer-make recorded as settled (converged 1) whose floor, under the
 * material it settled with, carries less than LAYER_FLOOR_LOAD_MIN of its
 * weight: it was in the air or bouncing when written, which layer-make before
 * session 38 called settled (--n 20 --ke-threshold 0.1 to 1: a floor load of
 * 0; layer-impact ran it with nothing said). The text into buf (n bytes),
 * else nothing. A warning, as for a pile written with converged 0 (below): the
 * file holds positions only, and a hand-written pile resting on the floor at
 * y = r carries nothing either. Only a pile whose settled line says converged
 * 1 and whose settings line gives its material is judged (settled_converged,
 * settled.recorded): a hand-written sample or one built in memory is a
 * geometry, its discs at y = r carrying nothing. */
/* The upward force (N) the side walls' friction exerts on the sample's pile
 * under lp's material and the friction angle it settled with (deg) through the tangential springs it keeps against the left
 * and right walls, as an impact loads them (layer_springs_load: F_t = K_t u_t,
 * B.4 at R_p = r, clipped to tan(phi) F_n), along t = (-n_y, n_x): the disc
 * gets F_t n_x upward. */
double layer_sample_wall_hold(const gw_layer_sample *smp, const gw_layer_params *lp, double friction_deg)
{
    return layer_sample_side_hold(smp, lp, friction_deg, 0);
}

double layer_sample_side_hold(const gw_layer_sample *smp, const gw_layer_params *lp, double friction_deg, int side)
{
    const double tp = tan(friction_deg * M_PI / 180);
    double up = 0;
    for (int k = 0; smp->springs && k < smp->n_springs; k++) {
        const int a = smp->springs[k].a, wall = smp->springs[k].b;
        if (a < 0 || a >= smp->n || (wall != GW_LAYER_SPRING_LEFT && wall != GW_LAYER_SPRING_RIGHT) ||
            (side != 0 && wall != side))
            continue;
        const double ra = smp->r[a];
        const double un = wall == GW_LAYER_SPRING_LEFT ? ra - smp->x[a] : ra - (smp->width - smp->x[a]);
        if (!(un > 0))
            continue;
        const double kn = gw_layer_kn(lp, ra), kt = gw_layer_kt_factor(lp, ra) * cbrt(kn) * sqrt(un);
        const double cap = tp * kn * un * sqrt(un), ft = fmax(-cap, fmin(cap, kt * smp->springs[k].u));
        up += wall == GW_LAYER_SPRING_LEFT ? -ft : ft;
    }
    return up;
}

static void floor_unsettled(const gw_layer_sample *smp, const gw_layer_params *lp, char *buf, size_t n)
{
    if (!smp->settled.recorded || !smp->settled_converged)
        return;
    const gw_layer_params sp = settling_material(lp, &smp->settled); /* the load layer-make judged */
    double f, w;
    layer_floor_load(&sp, smp->n, smp->y, smp->r, sizeof *smp->y, &f, &w);
    char ls[40];
    /* (a floor carrying less, the side walls' friction holding the rest: a pile
     * at rest in a narrow box, as layer-make calls it settled: layer_sample_wall_hold) */
    if (w > 0 && f < LAYER_FLOOR_LOAD_MIN * w &&
        !layer_load_rests(f, layer_sample_wall_hold(smp, &sp, smp->settled.friction_deg), w))
        gw_snprintf(buf, n, "the sample did not settle: its floor carries %.3g of the pile's weight under the "
                    "material it settled with (at rest: about 1; below %s the pile was in the air or bouncing when "
                    "written, though its settled line says converged 1, as a layer-make before session 38 wrote "
                    "such piles): it starts at rest there, so the outcome holds the pile's own motion as well as "
                    "the block's; make it again", f / w, gw_num_bound(ls, sizeof ls, LAYER_FLOOR_LOAD_MIN, 0));
}

int layer_settled_check_q(const gw_layer_sample *smp, const gw_layer_params *lp, int other_settling,
                          const char *name, char *warning, size_t n, double *q_out, gw_err *err)
{
    if (warning && n > 0)
        warning[0] = '\0';
    *q_out = NAN;
    /* a pile written before it settled (its "settled:" line says converged
     * 0): the file keeps positions, not velocities, so the run starts it at
     * rest where it was moving, grains in the air among them. Measured on
     * the 40-disc pile of seed 1 cut at t-max 0.3, 1, 2 and 3 s (settled:
     * 4.74 s), the default impact gave e_n 0.476, 0.360, 0.0024 and 0.055
     * against 0.149, penetration 0.625 m against 0.0129 at 0.3 s (a block
     * falling through the pile's cloud), with exit 0 and nothing said. A
     * warning, not a refusal: layer-make's own exit is 0 with its warning,
     * and a pile cut late is nearly at rest (the default 20 discs of seed 3
     * stop at 14.6 J, 26 times the threshold). */
    char unsettled[512] = "";
    if (smp->settled.unsettled)
        gw_snprintf(unsettled, sizeof unsettled, "the sample did not settle (its settled line says converged 0: "
                    "layer-make's t-max came first): it was written in motion, grains perhaps in the air, and starts "
                    "at rest there, so the outcome holds the pile's own motion as well as the block's; make it again "
                    "with a longer t-max");
    else
        floor_unsettled(smp, lp, unsettled, sizeof unsettled);
    if (!smp->settled.recorded) { /* hand-written, older, or in memory: nothing to compare */
        if (warning && n > 0)
            gw_snprintf(warning, n, "%s", unsettled);
        return GW_OK;
    }
    const gw_layer_settled *st = &smp->settled;
    char nm[300] = "", at[48] = "";
    if (name)
        gw_snprintf(nm, sizeof nm, " '%s'", name);
    if (st->line > 0)
        gw_snprintf(at, sizeof at, ", line %ld", st->line);
    double q;
    gw_err e = {{0}};
    int rc = load_ratio(smp, lp, &q, &e);
    if (rc != GW_OK) /* its clumps could not be weighed as unions */
        return gw_err_set(err, rc, "sample%s: weighing its clumps: %s", nm, e.msg);
    *q_out = q;
    const int cs = settled_clump_mass(smp);
    const int law = st->mass_law != lp->mass_law, fric = st->friction_deg != lp->friction_deg;
    const int clump = smp->body && cs != lp->clump_mass; /* without clumps the clump mass is moot */
    if (!law && !clump && !fric && fabs(q - 1) <= 1e-9) { /* the same rest: nothing else to say */
        if (warning && n > 0)
            gw_snprintf(warning, n, "%s", unsettled);
        return GW_OK;
    }
    char diff[512] = "";
    differ(diff, sizeof diff, "shear-modulus", st->shear_modulus, lp->shear_modulus, " Pa");
    differ(diff, sizeof diff, "poisson", st->poisson, lp->poisson, "");
    differ(diff, sizeof diff, "density", st->density, lp->density, " kg/m^3");
    differ(diff, sizeof diff, "gravity", st->gravity, lp->gravity, " m/s^2");
    differ(diff, sizeof diff, "friction", st->friction_deg, lp->friction_deg, " deg");
    if (law) {
        const size_t k = strlen(diff);
        gw_snprintf(diff + k, sizeof diff - k, "%smass-law %s against the impact's %s", k ? ", " : "",
                    st->mass_law == GW_LAYER_MASS_SPHERE ? "sphere" : "disc",
                    lp->mass_law == GW_LAYER_MASS_SPHERE ? "sphere" : "disc");
    }
    if (clump) {
        const size_t k = strlen(diff);
        gw_snprintf(diff + k, sizeof diff - k, "%sclump-mass %s against the impact's %s", k ? ", " : "",
                    gw_layer_clump_mass_name(cs), gw_layer_clump_mass_name(lp->clump_mass));
    }
    const int away = !(q >= GW_LAYER_SETTLED_LOAD_MIN && q <= GW_LAYER_SETTLED_LOAD_MAX);
    const double mu = friction_ratio(st->friction_deg, lp->friction_deg);
    const int flows = mu < GW_LAYER_SETTLED_FRICTION_MIN * (1 - 1e-9);
    const char *motion = q < 1 ? "sags into the impact" : "springs up into the impact";
    /* no gravity in the impact (q infinite): no weight to weigh the load
     * against. It said "its contacts carry inf times the weight" and offered
     * other-settling, which the floor check then refuses for a pile whose
     * floor carries a load, whatever the flag (layer_impact.c: the strain is
     * all released); a pile touching nothing (cut in the air) it runs */
    if (away && !other_settling && !isfinite(q)) {
        double f, w;
        char gs[40];
        layer_floor_load(lp, smp->n, smp->y, smp->r, sizeof *smp->y, &f, &w);
        return gw_err_set(err, GW_EINVAL, "sample%s: it settled with %s (its settings line%s): without gravity in "
                          "the impact its contacts hold the forces of its settling with no weight to carry, so the "
                          "pile springs apart into the impact; give the gravity it was made with (%s m/s^2)%s", nm,
                          diff, at, gw_num_text(gs, sizeof gs, st->gravity),
                          f > 0 ? " (other-settling does not run a pile whose floor carries a load without gravity)"
                                : ", or other-settling to run it anyway (the result then records a warning)");
    }
    /* the bounds as a value given back is taken (gw_num_bound): the
     * settling's friction 30.0000001 printed by %g as 30, which was refused */
    char qlo[40], qhi[40], fmin[40], fis[40];
    gw_num_bound(qlo, sizeof qlo, GW_LAYER_SETTLED_LOAD_MIN, 0);
    gw_num_bound(qhi, sizeof qhi, GW_LAYER_SETTLED_LOAD_MAX, 1);
    gw_num_bound(fmin, sizeof fmin, st->friction_deg, 0);
    if (away && !other_settling)
        return gw_err_set(err, GW_EINVAL, "sample%s: it settled with %s (its settings line%s): under the impact's "
                          "material its contacts carry %.3g times the weight they carried at rest (at least %s, at "
                          "most %s), so the pile %s and the run measures its motion too; give the settling's "
                          "values, or other-settling to run it anyway (the result then records a warning)", nm,
                          diff, at, q, qlo, qhi, motion);
    if (flows && !other_settling)
        return gw_err_set(err, GW_EINVAL, "sample%s: it settled with %s (its settings line%s): the impact's "
                          "friction coefficient tan(%g deg) is %.3g of the settling's tan(%g deg), and a pile leaning "
                          "on friction it no longer has may flow (how far below depends on the pile); give the "
                          "settling's friction (%s deg) or more, settle the pile at this one (layer-make --friction "
                          "%s), or other-settling to run it anyway", nm, diff, at, lp->friction_deg, mu,
                          st->friction_deg, fmin, gw_num_text(fis, sizeof fis, lp->friction_deg));
    if (!warning || n == 0)
        return GW_OK;
    char slide[160] = "";
    if (flows)
        gw_snprintf(slide, sizeof slide, "; its friction coefficient is %.3g of the settling's (run by "
                    "other-settling): the pile may flow on it", mu);
    if (away)
        gw_snprintf(warning, n, "the sample settled with %s: its contacts carry %.3g times the weight they carried "
                    "at rest (outside [%s, %s], run by other-settling): the pile %s%s, and the outcome holds its "
                    "motion as well as the block's", diff, q, qlo, qhi, motion, slide);
    else if (flows)
        gw_snprintf(warning, n, "the sample settled with %s: its contacts carry %.3g times the weight they carried "
                    "at rest (within [%s, %s])%s, and the outcome holds its motion as well as the block's", diff, q,
                    qlo, qhi, slide);
    else if (fabs(q - 1) > 1e-9)
        gw_snprintf(warning, n, "the sample settled with %s: its contacts carry %.3g times the weight they carried "
                    "at rest (within [%s, %s]): the pile %s a little%s", diff, q, qlo, qhi, motion, slide);
    else
        gw_snprintf(warning, n, "the sample settled with %s: its contacts carry its weight as at rest%s", diff,
                    slide[0] ? slide : law || clump ? ", though its bodies' shares of it differ" : "");
    if (unsettled[0]) { /* both said, the material's first */
        const size_t k = strlen(warning);
        gw_snprintf(warning + k, n - k, "; %s", unsettled);
    }
    return GW_OK;
}
