/*
 * layer_outcome.c: the outcome of one impact (physics.md 2.3) read from events
 * on the block (gw_layer_watch_block, layer_watch.c), never from output
 * samples, so that it does not depend on --dt-out.
 *
 * Events: VN+ / VN- (the block's normal velocity v_y turns upward / downward
 * through zero), TOUCH+ (the first contact closes), TOUCH- (the last contact
 * opens: free flight). The normal is the vertical (the layer's surface).
 *   - Bounced (verdict 1), the local criterion of 2.3 with the block leaving:
 *     the first TOUCH- with v_y > 0.
 *   - No bounce (verdict 0): v_y turned upward while the block touched the
 *     layer (VN+) and came back to zero (VN-) before the block left: its
 *     rebound ended inside the layer.
 *   - Fell off the layer (verdict 0, gone = GW_LAYER_GONE_*): before either,
 *     the block left the layer for good (GW_LAYER_BLOCK_GONE: below its lowest
 *     point, or beyond a side, with no wall there, touching nothing and moving
 *     away; over the floor, beyond where a missing side wall would be and
 *     every other body, moving or at rest; only with a wall missing). It never left its contacts moving up and never
 *     will: not a bounce by the rule above, decided, but not the no-bounce
 *     either (its rebound did not end inside the layer): reported apart
 *     (fell_off), and the run ends there.
 *   - Undecided (verdict -1): the run ended before any of these (the block still
 *     going down, falling, sliding, or at rest without v_y changing sign).
 *   - T_i and T_f: after the bounce, T_f is the first VN- (v_y back to zero,
 *     under gravity unless a grain pushes it); T_i the time of the largest
 *     v_y up to T_f. Reflected velocities at T_i (B.16-B.18):
 *         V_nr = v_y(T_i),  V_r = |v(T_i)|,  e_n = V_nr / V_ni,  e = V_r / V_i,
 *         alpha_r = arccos(V_nr / V_r)
 *     (V_ni = V_i cos alpha_i). Undecided (NaN) when the run ends before T_f.
 *   - First free-flight maximum (granwave before the definition above): the
 *     same quantities at the largest v_y up to the bounce event, before any
 *     later kick from ejected grains (e_n_first, e_first, alpha_r_first).
 *   - Penetration: the largest downward displacement of the block's centre
 *     below y0, its height at the touch (the caller passes the start lowered
 *     by the gap), up to the end of the outcome (T_f, the no-bounce decision,
 *     or the end of the run when undecided).
 * Units: SI, angles in degrees.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "layer_impl.h"
#include "gw_locale.h"
#include "layer_outcome.h"

void layer_outcome_init(layer_outcome *o, gw_layer *L, int until, int touching)
{
    memset(o, 0, sizeof *o);
    o->L = L;
    o->until = until;
    o->contact = touching;
    o->verdict = -1;
    o->t_verdict = o->t_f = NAN;
    o->t_touch = o->touch_ke = touching ? 0 : NAN;
}

/* The kinetic energy of every body but the block in L's state (the ledger's
 * kinetic_soil), J. */
static double soil_kinetic(const gw_layer *L)
{
    double ke = 0;
    for (int b = 0; b < L->nb; b++) {
        if (b == L->block_body)
            continue;
        const double *s = L->y + 6 * b;
        ke += 0.5 * L->m[b] * (s[3] * s[3] + s[4] * s[4]) + 0.5 * L->inertia[b] * s[5] * s[5];
    }
    return ke;
}

void layer_outcome_event(void *ctx, const gw_layer_block_event *ev)
{
    layer_outcome *o = ctx;
    if (ev->kind == GW_LAYER_BLOCK_GONE) {
        if (o->verdict < 0) {
            o->verdict = 0;
            o->gone = ev->dir;
            o->t_verdict = ev->t;
            gw_layer_block_extremes_get(o->L, &o->at_end);
            layer_watch_first_contact_freeze(o->L);
        }
        return;
    }
    if (ev->kind == GW_LAYER_BLOCK_TOUCH) {
        o->contact = ev->dir > 0;
        if (ev->dir > 0 && isnan(o->t_touch)) {
            o->t_touch = ev->t;
            o->touch_ke = soil_kinetic(o->L);
        }
        if (ev->dir < 0 && o->verdict < 0 && ev->vy > 0) {
            o->verdict = 1;
            o->t_verdict = ev->t;
            o->leave = *ev;
            gw_layer_block_extremes_get(o->L, &o->at_leave);
            layer_watch_first_contact_freeze(o->L);
        }
        return;
    }
    if (ev->dir > 0) { /* v_y turns upward: only a contact can do that */
        o->rose = o->contact;
        return;
    }
    if (o->verdict == 1 && !o->tf) { /* back to zero after the bounce: T_f */
        o->tf = 1;
        o->t_f = ev->t;
        gw_layer_block_extremes_get(o->L, &o->at_end);
    } else if (o->verdict < 0 && o->rose && o->contact) { /* rebound over inside the layer */
        o->verdict = 0;
        o->t_verdict = ev->t;
        gw_layer_block_extremes_get(o->L, &o->at_end);
        layer_watch_first_contact_freeze(o->L);
    }
    o->rose = 0;
}

int layer_outcome_done(const layer_outcome *o)
{
    if (o->until == GW_LAYER_UNTIL_VERDICT)
        return o->verdict >= 0;
    return o->verdict == 0 || (o->verdict == 1 && o->tf);
}

/* V_nr, V_r, e_n, e, alpha_r at the largest v_y of ex. */
static void reflected(const gw_layer_block_extremes *ex, double v_ni, double vi, double *v_nr,
                      double *v_r, double *e_n, double *e, double *alpha_r, double *t)
{
    *v_nr = ex->vy_max;
    *v_r = hypot(ex->vx_at_vy_max, ex->vy_max);
    *e_n = *v_nr / v_ni;
    *e = *v_r / vi;
    *alpha_r = *v_r > 0 ? acos(fmin(1, *v_nr / *v_r)) * 180 / M_PI : NAN;
    *t = ex->t_vy_max;
}

void layer_outcome_finish(const layer_outcome *o, double y0, double vi, double t_end,
                          int stopped_by_t_max, gw_layer_impact_result *res)
{
    gw_layer_block_extremes now;
    gw_layer_block_extremes_get(o->L, &now);
    res->bounced = o->verdict;
    res->fell_off = o->gone;
    res->t_f = o->t_f;
    res->t_leave = o->verdict == 1 ? o->leave.t : NAN;
    res->v_nr = res->v_r = res->e_n = res->e = res->alpha_r_deg = res->t_rebound = NAN;
    res->v_nr_first = res->v_r_first = res->e_n_first = res->e_first = NAN;
    res->alpha_r_first_deg = res->t_rebound_first = NAN;
    res->undecided[0] = '\0';
    if (o->verdict == 1) {
        reflected(&o->at_leave, res->v_ni, vi, &res->v_nr_first, &res->v_r_first, &res->e_n_first,
                  &res->e_first, &res->alpha_r_first_deg, &res->t_rebound_first);
        if (o->tf)
            reflected(&o->at_end, res->v_ni, vi, &res->v_nr, &res->v_r, &res->e_n, &res->e,
                      &res->alpha_r_deg, &res->t_rebound);
    }
    /* the lowest point up to the end of the outcome */
    const gw_layer_block_extremes *pe = (o->verdict == 0 || o->tf) ? &o->at_end : &now;
    res->penetration = y0 - fmin(y0, pe->y_min);
    const gw_layer_params *lp = gw_layer_get_params(o->L);
    double s[6];
    gw_layer_particle(o->L, gw_layer_n(o->L) - 1, s);
    if (o->verdict < 0 && stopped_by_t_max) {
        gw_snprintf(res->undecided, sizeof res->undecided,
                 "bounce undecided: the run ended at t-max = %.6g s before the block left the layer "
                 "moving up or its rebound ended inside it (block %s, v_y = %.4g m/s); raise --t-max",
                 t_end, o->contact ? "touching the layer" : "in free flight", s[4]);
    } else if (o->verdict == 1 && !o->tf && stopped_by_t_max) {
        double g = lp->gravity;
        if (!o->contact && s[4] > 0 && g > 0)
            gw_snprintf(res->undecided, sizeof res->undecided,
                     "e_n, e, alpha_r undecided: the run ended at t-max = %.6g s before the block's "
                     "normal velocity was back to zero (T_f, about %.4g s in free flight from here); "
                     "raise --t-max (e_n_first is the first free-flight maximum)", t_end, t_end + s[4] / g);
        else if (!o->contact && s[4] > 0 && !(g > 0)) /* no gravity: the flight never turns */
            gw_snprintf(res->undecided, sizeof res->undecided,
                     "e_n, e, alpha_r undecided: without gravity the block flies on (v_y = %.4g m/s at "
                     "t-max = %.6g s) and T_f never comes; e_n_first, the first free-flight maximum, is the "
                     "rebound's", s[4], t_end);
        else
            gw_snprintf(res->undecided, sizeof res->undecided,
                     "e_n, e, alpha_r undecided: the run ended at t-max = %.6g s before the block's "
                     "normal velocity was back to zero (T_f); raise --t-max (e_n_first is the first "
                     "free-flight maximum)", t_end);
    }
}
