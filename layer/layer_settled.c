/*
 * layer_settled.c: does the pile rest under the impact's material? The sample
 * keeps the overlaps its pile settled with, and, when layer-make wrote it, the
 * material and gravity it settled under (gw_layer_settled, read from its
 * settings line). A Hertz contact carries F = K_n u^(3/2) with K_n ~ G/(1 - nu)
 * (physics.md 2.1, B.3), so a pile at rest under (G, nu, rho, g, mass law)_s
 * has overlaps u ~ (m g / K_n)^(2/3); under the impact's (...)_i they carry
 *   q = [G/(1 - nu)]_i / [G/(1 - nu)]_s x W_s / W_i
 * of the weight they carried at rest (W: the pile's weight, sum of m(r) g of
 * its discs under each mass law). q < 1: the pile sags into the impact,
 * q > 1: it springs up; either way the impact measures the pile's own motion
 * as well as the block's.
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
 * impact is refused unless asked for (other_settling); any other difference
 * is a warning: q not 1, another mass law (q then from the total weights,
 * the discs' shares differ), another friction angle (the pile may lean on
 * friction it no longer has: settled at 30 degrees and run at 0, 26 J of
 * soil motion in 30 ms against 2 J).
 * Units: SI (Pa, kg/m^3, m/s^2), angles in degrees.
 */
#include <math.h>
#include <string.h>

#include "layer_impl.h"
#include "gw_locale.h"

double gw_layer_settled_load_ratio(const gw_layer_sample *smp, const gw_layer_params *lp)
{
    if (!smp || !lp || !smp->settled.recorded)
        return NAN;
    const gw_layer_settled *st = &smp->settled;
    gw_layer_params sp = *lp; /* the settling's material, for its masses */
    sp.density = st->density;
    sp.mass_law = st->mass_law;
    double ws = 0, wi = 0;
    for (int i = 0; i < smp->n; i++) {
        ws += gw_layer_mass(&sp, smp->r[i]);
        wi += gw_layer_mass(lp, smp->r[i]);
    }
    ws *= st->gravity;
    wi *= lp->gravity;
    const double kr = (lp->shear_modulus / (1 - lp->poisson)) / (st->shear_modulus / (1 - st->poisson));
    return wi > 0 ? kr * ws / wi : INFINITY;
}

/* Append "NAME A UNIT against the impact's B" to the list in buf when a != b. */
static void differ(char *buf, size_t n, const char *name, double a, double b, const char *unit)
{
    if (a == b)
        return;
    const size_t k = strlen(buf);
    gw_snprintf(buf + k, n - k, "%s%s %g%s against the impact's %g", k ? ", " : "", name, a, unit, b);
}

int gw_layer_impact_settled_check(const gw_layer_sample *smp, const gw_layer_params *lp, int other_settling,
                                  const char *name, char *warning, size_t n, gw_err *err)
{
    if (warning && n > 0)
        warning[0] = '\0';
    if (!smp || !lp)
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_settled_check: %s is NULL", !smp ? "s" : "lp");
    if (!smp->settled.recorded) /* hand-written, older, or in memory: nothing to compare */
        return GW_OK;
    const gw_layer_settled *st = &smp->settled;
    const double q = gw_layer_settled_load_ratio(smp, lp);
    const int law = st->mass_law != lp->mass_law, fric = st->friction_deg != lp->friction_deg;
    if (!law && !fric && fabs(q - 1) <= 1e-9) /* the same rest: nothing to say */
        return GW_OK;
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
    char nm[300] = "", at[48] = "";
    if (name)
        gw_snprintf(nm, sizeof nm, " '%s'", name);
    if (st->line > 0)
        gw_snprintf(at, sizeof at, ", line %ld", st->line);
    const int away = !(q >= GW_LAYER_SETTLED_LOAD_MIN && q <= GW_LAYER_SETTLED_LOAD_MAX);
    const char *motion = q < 1 ? "sags into the impact" : "springs up into the impact";
    if (away && !other_settling)
        return gw_err_set(err, GW_EINVAL, "sample%s: it settled with %s (its settings line%s): under the impact's "
                          "material its contacts carry %.3g times the weight they carried at rest (at least %g, at "
                          "most %g), so the pile %s and the run measures its motion too; give the settling's "
                          "values, or other-settling to run it anyway (the result then records a warning)", nm,
                          diff, at, q, GW_LAYER_SETTLED_LOAD_MIN, GW_LAYER_SETTLED_LOAD_MAX, motion);
    if (!warning || n == 0)
        return GW_OK;
    if (away)
        gw_snprintf(warning, n, "the sample settled with %s: its contacts carry %.3g times the weight they carried "
                    "at rest (outside [%g, %g], run by other-settling): the pile %s, and the outcome holds its "
                    "motion as well as the block's", diff, q, GW_LAYER_SETTLED_LOAD_MIN, GW_LAYER_SETTLED_LOAD_MAX,
                    motion);
    else if (fabs(q - 1) > 1e-9)
        gw_snprintf(warning, n, "the sample settled with %s: its contacts carry %.3g times the weight they carried "
                    "at rest (within [%g, %g]): the pile %s a little%s", diff, q, GW_LAYER_SETTLED_LOAD_MIN,
                    GW_LAYER_SETTLED_LOAD_MAX, motion,
                    fric && lp->friction_deg < st->friction_deg ? ", and may slide on the lower friction" : "");
    else
        gw_snprintf(warning, n, "the sample settled with %s: its contacts carry its weight as at rest%s", diff,
                    fric && lp->friction_deg < st->friction_deg ? ", but it may slide on the lower friction"
                    : law ? ", though its discs' shares of it differ" : "");
    return GW_OK;
}
