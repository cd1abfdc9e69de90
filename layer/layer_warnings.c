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

#include "gw_layer.h"
#include "layer_impl.h"
#include "gw_locale.h"

int gw_layer_make_result_warnings(const gw_layer_make_result *r, double t_max, const char *out, char **list)
{
    if (r && r->untrimmed_top_rm > 0) { /* --height-rm asked a trim that took nothing away */
        int rc = gw_warnings_add(list,
                                 "--height-rm took nothing away: the settled pile's top lies at %.4g R_m, at or "
                                 "below the height asked, so the sample is the whole pile, as with 0 (give a "
                                 "height below the top to trim it)",
                                 r->untrimmed_top_rm);
        if (rc != GW_OK)
            return rc;
    }
    if (!r || r->converged)
        return GW_OK;
    if (!(t_max > 0 && t_max < INFINITY)) /* the run's t_max, never NaN: it printed "t-max = nan s" */
        return GW_EINVAL;
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
     * as before; so does one where neither holds (an allocation failed). */
    const double ld = r->floor_load;
    const int low = ld < LAYER_FLOOR_LOAD_MIN, high = ld > LAYER_FLOOR_LOAD_MAX;
    const int known = r->ke_limit > 0 && r->ke_limit < INFINITY;
    const int above = known ? !(r->ke_final + r->fall_energy < r->ke_limit) || !(low || high) : !high;
    char ek[200] = "", on_floor[240] = "", lim[48] = "";
    if (known)
        gw_snprintf(lim, sizeof lim, "%.4g J", r->ke_limit);
    if (above && r->fall_energy > 0)
        gw_snprintf(ek, sizeof ek, "E_k = %.4g J and %.4g J of grains in flight (touching nothing) still above "
                    "--ke-threshold at t-max = %g s", r->ke_final, r->fall_energy, t_max);
    else if (above)
        gw_snprintf(ek, sizeof ek, "E_k = %.4g J still above --ke-threshold at t-max = %g s", r->ke_final, t_max);
    if (low)
        gw_snprintf(on_floor, sizeof on_floor, "its floor carries %.3g of the pile's weight (at rest: about 1; "
                    "below %g the pile is in the air or bouncing, or the side walls' friction holds a column far "
                    "taller than wide)", ld, LAYER_FLOOR_LOAD_MIN);
    else if (high)
        gw_snprintf(on_floor, sizeof on_floor, "its floor carries %.3g times the pile's weight (at rest: about 1; "
                    "layer-impact refuses above %g)", ld, LAYER_FLOOR_LOAD_MAX);
    if (!on_floor[0])
        return gw_warnings_add(list, "the sample did not settle: %s (%s%sraise --t-max)%s%s%s", ek, lim,
                               known ? "; " : "", sep, path, end);
    if (ek[0])
        return gw_warnings_add(list, "the sample did not settle: %s%s%s%s, and %s (raise --t-max)%s%s%s", ek,
                               known ? " (" : "", lim, known ? ")" : "", on_floor, sep, path, end);
    char fall[64] = ""; /* E_k and the grains' fall below the threshold: the floor alone held the pile */
    if (r->fall_energy > 0)
        gw_snprintf(fall, sizeof fall, " and %.4g J of grains in flight", r->fall_energy);
    return gw_warnings_add(list, "the sample did not settle: at t-max = %g s %s, E_k = %.4g J%s%s%s%s%s (raise "
                           "--t-max)%s%s%s", t_max, on_floor, r->ke_final, fall, known ? " below --ke-threshold" : "",
                           known ? " (" : "", lim, known ? ")" : "", sep, path, end);
}

int gw_layer_impact_result_warnings(const gw_layer_impact_result *r, char **list)
{
    if (!r)
        return GW_OK;
    /* a sample settled under another material or gravity (layer_settled.c) */
    /* each text within its field: one filled by hand without its NUL was read
     * on into the fields after it */
    int rc = r->settling[0] ? gw_warnings_add(list, "%.*s", (int)sizeof r->settling, r->settling) : GW_OK;
    if (rc != GW_OK || !r->undecided[0]) /* decided, or stopped at the verdict on purpose */
        return rc;
    return gw_warnings_add(list, "%.*s", (int)sizeof r->undecided, r->undecided);
}
