/*
 * layer_warnings.c: the warning texts of the layer's runs, each written once
 * (gw_common.h, "warnings of a result"): a pluviation that did not settle
 * (physics.md 2.2: E_k below the threshold, judged once the pile has landed),
 * a pluviation whose --height-rm took nothing away, an impact on a sample
 * settled under another material or gravity (layer_settled.c builds its
 * text), and an impact whose outcome is undecided (2.3; the text is built where the outcome is,
 * layer_outcome.c, as the result's `undecided`). The program prints
 * them as "granwave CMD: warning: TEXT", the Python module issues them as
 * GranwaveWarning, a C caller reads them from the outcome's `warnings`.
 * Parameters are named as the program's flags (--t-max). Units: s, J.
 */
#include <math.h>
#include <string.h>

#include "gw_layer.h"
#include "layer_impl.h"
#include "layer_plan_run.h"
#include "gw_locale.h"

/* Whether r could come from gw_layer_make: converged 0 or 1, an untrimmed
 * top finite and not negative (0: none) and, for an unsettled pile, the
 * numbers its warning states finite (or an unknown ke_limit of 0) and not
 * negative, with the run's t_max positive and finite. A result filled by hand
 * was read as it was: converged -3 counted as settled, an E_k of NaN was
 * "still above the threshold". (fall_energy is -1 when a run could not count
 * the grains in flight: out of memory; any other sign is taken as it comes.)
 * Each refusal names the field, its value and the range it is held to, as
 * the sample's checks name theirs (the warnings' refusal named nothing: the
 * call has no error argument). */
static int make_field_check(const char *field, double v, const char *unit, gw_err *err)
{
    if (v >= 0 && v < INFINITY)
        return GW_OK;
    char vs[40];
    return gw_err_set(err, GW_EINVAL, "gw_layer_make_result: %s = %s%s is outside [0, inf) (a finite number, not "
                      "negative: gw_layer_make gives no other)", field, gw_num_text(vs, sizeof vs, v), unit);
}

int gw_layer_make_result_check(const gw_layer_make_result *r, double t_max, gw_err *err)
{
    if (!r)
        return gw_err_set(err, GW_EINVAL, "gw_layer_make_result_check: r is NULL");
    if (r->converged != 0 && r->converged != 1)
        return gw_err_set(err, GW_EINVAL, "gw_layer_make_result: converged = %d is neither 0 (not settled) nor 1 "
                          "(settled)", r->converged);
    int rc = make_field_check("untrimmed_top_rm", r->untrimmed_top_rm, " R_m", err);
    if (rc != GW_OK || r->converged) /* a settled result states none of the numbers below */
        return rc;
    static const char *const names[4] = {"ke_final", "floor_load", "ke_limit", "t_judge"};
    static const char *const units[4] = {" J", "", " J", " s"};
    const double v[4] = {r->ke_final, r->floor_load, r->ke_limit, r->t_judge};
    for (int k = 0; k < 4 && rc == GW_OK; k++)
        rc = make_field_check(names[k], v[k], units[k], err);
    if (rc != GW_OK)
        return rc;
    char vs[40];
    if (isnan(r->fall_energy))
        return gw_err_set(err, GW_EINVAL, "gw_layer_make_result: fall_energy = nan J is not a number (-1: the "
                          "grains in flight not counted)");
    /* the side walls' share, either sign, counted with the floor's */
    if (!isfinite(r->wall_load))
        return gw_err_set(err, GW_EINVAL, "gw_layer_make_result: wall_load = %s is not a finite number (the side "
                          "walls' share of the weight, either sign; 0 without)", gw_num_text(vs, sizeof vs, r->wall_load));
    /* the moving grain's share of E_k (0 in a result filled before it was added) */
    if (!(r->ke_top_share >= 0 && r->ke_top_share <= 1))
        return gw_err_set(err, GW_EINVAL, "gw_layer_make_result: ke_top_share = %s is outside [0, 1] (the share of "
                          "ke_final the grain that moves most holds)", gw_num_text(vs, sizeof vs, r->ke_top_share));
    /* the run's t_max, never NaN: it printed "t-max = nan s" */
    if (!(t_max > 0 && t_max < INFINITY))
        return gw_err_set(err, GW_EINVAL, "gw_layer_make_result: t_max = %s s is outside (0, inf) (the run's, "
                          "which the warning of an unsettled result states)", gw_num_text(vs, sizeof vs, t_max));
    return GW_OK;
}

int gw_layer_make_result_warnings(const gw_layer_make_result *r, double t_max, const char *out, char **list)
{
    /* before any text: nothing added (gw_layer_make_result_check names why) */
    if (r && gw_layer_make_result_check(r, t_max, NULL) != GW_OK)
        return GW_EINVAL;
    if (r && r->untrimmed_top_rm > 0) { /* --height-rm asked a trim that took nothing away */
        int rc = gw_warnings_add(list,
                                 "--height-rm took nothing away: the settled pile's top lies at %.4g R_m, at or "
                                 "below the height asked, so the sample is the whole pile, as with 0 (give a "
                                 "height below the top to trim it)",
                                 r->untrimmed_top_rm);
        if (rc != GW_OK)
            return rc;
    }
    if (r && r->n_discs > 0 && isnan(r->porosity)) { /* the window held no disc (layer_sample_porosity_of) */
        int rc = gw_warnings_add(list,
                                 "the porosity is not measured (null): its window, x in [0.1, 0.9] W and y in "
                                 "[0.1, 0.8] h, holds no disc of the %d settled (raise --n for a pile that fills it)",
                                 r->n_discs);
        if (rc != GW_OK)
            return rc;
    }
    if (!r || r->converged)
        return GW_OK;
    const char *sep = out ? "; written to " : "", *path = out ? out : "", *end = out ? " with 'converged 0'" : "";
    if (t_max < r->t_judge) /* it could not settle: not "E_k above the threshold" */
        return gw_warnings_add(list,
                               "the sample did not settle: t-max = %g s ends before the settling is judged (from t = "
                               "%.3g s, once the pile has landed: raise --t-max)%s%s%s",
                               t_max, r->t_judge, sep, path, end);
    /* what held the pile at t_max, each cause said (both when both): E_k with
     * the fall of the grains in flight still above the threshold, or the
     * floor not carrying the pile (in the air or bouncing below
     * LAYER_FLOOR_LOAD_MIN of its weight, swinging on its contacts above
     * LAYER_FLOOR_LOAD_MAX). A result without ke_limit (0: filled before it
     * was added) names E_k whenever the floor's load is not above the bound,
     * as before. One where neither holds (grains in flight the run could not
     * count, or filled by hand) says so: it was told "E_k = 0 J still above
     * --ke-threshold (1 J)". */
    const double ld = r->floor_load, fall = r->fall_energy > 0 ? r->fall_energy : 0;
    /* the side walls' share counts with the floor's (layer_load_rests, the
     * rule layer-make settles by and layer-impact's rest check applies): a
     * pile its walls help hold was told "its floor carries 2.25 times the
     * pile's weight (... layer-impact refuses above 1.5)", the walls pulling
     * down 1.24 of it and layer-impact taking the sample (`layer-make --clumps
     * --width-rm 6 --n 40 --seed 4 --t-max 4.7`) */
    const double wl = r->wall_load, both = ld + wl;
    const int walls = wl != 0, rests = layer_load_rests(ld, wl, 1);
    const int low = !rests && (walls ? both : ld) < LAYER_FLOOR_LOAD_MIN;
    const int high = !rests && (walls ? both : ld) > LAYER_FLOOR_LOAD_MAX;
    /* resting by the walls' share alone: the floor's own load out of the bounds */
    const int by_walls = rests && !layer_load_rests(ld, 0, 1);
    const int known = r->ke_limit > 0;
    /* (unknown: no E_k of 0 is above a threshold, which is positive) */
    const int above = known ? !(r->ke_final + fall < r->ke_limit) : !high && r->ke_final + fall > 0;
    char ek[200] = "", on_floor[400] = "", lim[48] = "";
    if (known)
        gw_snprintf(lim, sizeof lim, "%.4g J", r->ke_limit);
    if (above && r->fall_energy > 0)
        gw_snprintf(ek, sizeof ek, "E_k = %.4g J and %.4g J of grains in flight (touching nothing) still above "
                    "--ke-threshold at t-max = %g s", r->ke_final, r->fall_energy, t_max);
    else if (above)
        gw_snprintf(ek, sizeof ek, "E_k = %.4g J still above --ke-threshold at t-max = %g s", r->ke_final, t_max);
    if (low && walls)
        gw_snprintf(on_floor, sizeof on_floor, "its floor carries %.3g of the pile's weight and its side walls "
                    "%.3g (together %.3g; at rest: about 1; below %g the pile is in the air or bouncing)", ld, wl,
                    both, LAYER_FLOOR_LOAD_MIN);
    else if (high && walls)
        gw_snprintf(on_floor, sizeof on_floor, "its floor carries %.3g times the pile's weight and its side walls "
                    "%.3g (together %.3g; at rest: about 1; layer-impact refuses a floor above %g unless the floor "
                    "and the side walls together carry %g to %g of the weight)", ld, wl, both,
                    LAYER_FLOOR_LOAD_MAX, LAYER_FLOOR_LOAD_MIN, LAYER_FLOOR_LOAD_MAX);
    else if (low)
        gw_snprintf(on_floor, sizeof on_floor, "its floor carries %.3g of the pile's weight (at rest: about 1; "
                    "below %g the pile is in the air or bouncing, or the side walls' friction holds a column far "
                    "taller than wide)", ld, LAYER_FLOOR_LOAD_MIN);
    else if (high)
        gw_snprintf(on_floor, sizeof on_floor, "its floor carries %.3g times the pile's weight (at rest: about 1; "
                    "layer-impact refuses above %g)", ld, LAYER_FLOOR_LOAD_MAX);
    char fell[64] = ""; /* the grains' fall, when below the threshold with E_k */
    if (r->fall_energy > 0)
        gw_snprintf(fell, sizeof fell, " and %.4g J of grains in flight", r->fall_energy);
    if (!ek[0] && by_walls) /* E_k below the threshold, floor and walls carrying the pile: still rocking */
        return gw_warnings_add(list, "the sample did not settle: at t-max = %g s E_k = %.4g J%s lies below "
                               "--ke-threshold%s%s%s and its floor carries %.3g of the pile's weight and its side "
                               "walls %.3g (together %.3g: at rest, %g to %g, which layer-impact's check asks), but "
                               "a pile its walls help hold is called settled only once it passes these rules at %d "
                               "successive checks %g s apart, and this one still rocks between its walls (raise "
                               "--t-max)%s%s%s", t_max, r->ke_final, fell, known ? " (" : "", lim, known ? ")" : "",
                               ld, wl, both, LAYER_FLOOR_LOAD_MIN, LAYER_FLOOR_LOAD_MAX, LAYER_WALL_CALM_CHECKS,
                               LAYER_SETTLE_CHUNK, sep, path, end);
    if (!ek[0] && !on_floor[0]) /* E_k below the threshold, the floor carrying the pile: the verdict alone */
        return gw_warnings_add(list, "the sample did not settle: its run did not call it settled (converged 0), "
                               "though at t-max = %g s E_k = %.4g J%s lies below --ke-threshold%s%s%s and its floor "
                               "carries %.3g of the pile's weight (at rest: about 1; raise --t-max)%s%s%s", t_max,
                               r->ke_final, fell, known ? " (" : "", lim, known ? ")" : "", ld, sep, path, end);
    /* E_k above the threshold on supports that carry the pile, most of it in
     * one grain: one clump (or disc) rolling or rocking on a pile at rest, not
     * a pile that did not settle (`--clumps --width-rm 6 --n 40 --seed 4
     * --t-max 6`: a median 0.82 of E_k in its last clump from 3 s on, the
     * pile's centre of mass still, settled at 6.41 s; ke_top_share, layer_make.c) */
    if (!on_floor[0] && ek[0] && r->ke_top_share >= 0.5 && rests)
        return gw_warnings_add(list, "the sample did not settle: %s%s%s%s, %.2g of it in the one grain that moves "
                               "most, while %s carry %.3g of the pile's weight (at rest: about 1): one clump or disc "
                               "still rolling or rocking on a pile at rest (raise --t-max)%s%s%s", ek,
                               known ? " (" : "", lim, known ? ")" : "", r->ke_top_share,
                               walls ? "its floor and side walls" : "its floor", walls ? both : ld, sep, path, end);
    if (!on_floor[0])
        return gw_warnings_add(list, "the sample did not settle: %s (%s%sraise --t-max)%s%s%s", ek, lim,
                               known ? "; " : "", sep, path, end);
    if (ek[0])
        return gw_warnings_add(list, "the sample did not settle: %s%s%s%s, and %s (raise --t-max)%s%s%s", ek,
                               known ? " (" : "", lim, known ? ")" : "", on_floor, sep, path, end);
    /* E_k and the grains' fall below the threshold: the floor alone held the pile */
    return gw_warnings_add(list, "the sample did not settle: at t-max = %g s %s, E_k = %.4g J%s%s%s%s%s (raise "
                           "--t-max)%s%s%s", t_max, on_floor, r->ke_final, fell, known ? " below --ke-threshold" : "",
                           known ? " (" : "", lim, known ? ")" : "", sep, path, end);
}

const char *gw_layer_fell_off_name(int fell_off)
{
    switch (fell_off) {
    case GW_LAYER_GONE_BELOW: return "below its lowest point";
    case GW_LAYER_GONE_LEFT: return "beyond its left side";
    case GW_LAYER_GONE_RIGHT: return "beyond its right side";
    default: return fell_off ? "unknown" : "no";
    }
}

int gw_layer_impact_result_warnings(const gw_layer_impact_result *r, char **list)
{
    if (!r)
        return GW_OK;
    /* a sample settled under another material or gravity (layer_settled.c) */
    /* each text within its field: one filled by hand without its NUL was read
     * on into the fields after it */
    int rc = r->settling[0] ? gw_warnings_add(list, "%.*s", (int)sizeof r->settling, r->settling) : GW_OK;
    /* a block that left the layer for good (layer_outcome.c): decided, its own
     * verdict; never "raise --t-max" (it ran to t-max before, falling on) */
    /* a pile slumping on the side whose wall was taken away, its kinetic
     * energy at the block's touch a large share of the impact's
     * (gw_layer_impact_result.slump_ke; 0 in a result filled by hand) */
    if (rc == GW_OK && r->slump_ke > GW_LAYER_SLUMP_WARN * r->e_incident)
        rc = gw_warnings_add(list, "the pile was slumping when the block arrived: with a side wall taken away its "
                             "kinetic energy at the block's touch was %.3g J, %.3g of the impact's %.3g J (above "
                             "%g): the block hit a pile in motion, not at rest (keep both side walls, or give a "
                             "shorter gap, a faster or a larger block)", r->slump_ke, r->slump_ke / r->e_incident, r->e_incident,
                             GW_LAYER_SLUMP_WARN);
    if (rc == GW_OK && r->fell_off > 0)
        rc = gw_warnings_add(list, "the block fell off the layer (%s, no wall there, beyond every other body and "
                             "touching none of them): bounced false, no rebound; the run ended at t = %.6g s",
                             gw_layer_fell_off_name(r->fell_off), r->t_end);
    if (rc != GW_OK || !r->undecided[0]) /* decided, or stopped at the verdict on purpose */
        return rc;
    return gw_warnings_add(list, "%.*s", (int)sizeof r->undecided, r->undecided);
}

int layer_energy_warning(const gw_layer_impact_result *res, const gw_layer_impact_params *ip,
                         const gw_solver_type *type, const gw_solver_params *sp, char **list)
{
    if (!res || !ip || !sp || ip->energy_tol > 0 || !(res->energy_error > GW_LAYER_ENERGY_WARN))
        return GW_OK;
    const char *name = type ? gw_solver_type_name(type) : NULL;
    if (!name || strcmp(name, "rk4") == 0 || strcmp(name, "verlet") == 0)
        return gw_warnings_add(list, "the relative energy error reached %.3g (%.3g %%, above %g) at the %s step dt = "
                               "%g s: too coarse to trust the run's numbers: lower dt, or set energy-tol to stop at "
                               "a bound", res->energy_error, 100 * res->energy_error, GW_LAYER_ENERGY_WARN,
                               name ? name : "solver's", sp->dt);
    return gw_warnings_add(list, "the relative energy error reached %.3g (%.3g %%, above %g) at rtol = %g, atol = %g: "
                           "the tolerances are too loose to trust the run's numbers: tighten rtol and atol, or set "
                           "energy-tol to stop at a bound", res->energy_error, 100 * res->energy_error,
                           GW_LAYER_ENERGY_WARN, sp->rtol, sp->atol);
}
