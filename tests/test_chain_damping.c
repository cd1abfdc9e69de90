/*
 * test_chain_damping.c: viscoelastic damping (docs/physics.md 1.5).
 *  - Calibration: the Hunt-Crossley alpha and Kuwabara-Kono gamma found for a
 *    target restitution e give a single bead on the wall that restitution to
 *    1e-3 (the issue asks 1 %; Brent converges to ~1e-10).
 *  - Viscoelastic restitution falls with the impact velocity (same constant,
 *    v = 0.1, 0.3, 1 m/s): a velocity-independent damping would not.
 *  - Kuwabara-Kono e = 0.9: eps_eff (F.7) decreases with N (the experiment's
 *    trend, Fig. 11 of the paper) over N = 1, 2, 5, 10, 20, 40.
 *  - The damped wall force is never negative (30-bead column). The plateau
 *    decay is printed for the record: this damping does not reproduce it.
 *  - The damped plateau is the dissipative-shock value. Mass and momentum
 *    conservation across a front that leaves the beads at rest in uniform
 *    compression (F = k d^(3/2)) give the front speed c = 2R (k/m)^(2/5)
 *    v^(1/5) and the wall force F_p = m^(3/5) k^(2/5) v^(6/5), whatever the
 *    damping constant. Kuwabara-Kono (e = 0.5, 0.2) and Hunt-Crossley
 *    (e = 0.5): the mean wall force over each tenth of the contact from the
 *    2nd to the 7th lies within 1.5 % of F_p, so contact damping cannot make
 *    the plateau decay.
 */
#include <math.h>

#include "chain_test_util.h"
#include "gw_test.h"


static const char *model_name(gw_chain_damping model)
{
    return model == GW_DAMP_KUWABARA_KONO ? "Kuwabara-Kono" : "Hunt-Crossley";
}

/* One bead at 0.3 m/s with model's constant calibrated to restitution e;
 * asserts the calibration and returns its code. */
static int calibrated(gw_chain_damping model, double e, const gw_chain_run_opts *o,
                      gw_chain_params *p)
{
    *p = test_params(1, 0.3);
    p->damping = model;
    double cst = NAN;
    gw_err err = {{0}};
    int rc = gw_chain_calibrate(p, o, e, &cst, &err);
    char what[800];
    snprintf(what, sizeof what, "%s calibration to e = %.1f succeeded (%s)", model_name(model), e,
             rc ? err.msg : "ok");
    gw_test_true(rc == GW_OK, what);
    if (model == GW_DAMP_KUWABARA_KONO)
        p->gamma = cst;
    else
        p->alpha = cst;
    return rc;
}

typedef struct peaks {
    double fmin, f_prev2, f_prev1, first, second, last;
    int count;
} peaks;

static int track(void *ctx, double t, const double *y, double f, int is_event)
{
    (void)t;
    (void)y;
    (void)is_event;
    peaks *pk = ctx;
    if (f < pk->fmin)
        pk->fmin = f;
    if (pk->f_prev1 > pk->f_prev2 && pk->f_prev1 >= f && pk->f_prev1 > 0) {
        pk->count++;
        if (pk->count == 1)
            pk->first = pk->f_prev1;
        if (pk->count == 2)
            pk->second = pk->f_prev1;
        pk->last = pk->f_prev1;
    }
    pk->f_prev2 = pk->f_prev1;
    pk->f_prev1 = f;
    return 0;
}

/* Mean wall force over tenth j (0-based) of [0, t_end] from a trace
 * (trapezoids between samples, linear interpolation at the tenth's ends). */
static double tenth_mean(const gw_chain_trace *tr, double t_end, int j)
{
    double a = t_end * j / 10.0, b = t_end * (j + 1) / 10.0, sum = 0.0;
    for (size_t i = 1; i < tr->len; i++) {
        double t0 = tr->t[i - 1], t1 = tr->t[i];
        if (t1 <= a || t0 >= b || t1 <= t0)
            continue;
        double s0 = t0 < a ? a : t0, s1 = t1 > b ? b : t1;
        double slope = (tr->f[i] - tr->f[i - 1]) / (t1 - t0);
        double f0 = tr->f[i - 1] + slope * (s0 - t0), f1 = tr->f[i - 1] + slope * (s1 - t0);
        sum += 0.5 * (f0 + f1) * (s1 - s0);
    }
    return sum / (b - a);
}

/* The damped 30-bead plateau against the dissipative-shock force F_p. */
static void plateau_checks(const gw_chain_run_opts *o)
{
    const struct {
        gw_chain_damping model;
        double e;
    } cases[] = {{GW_DAMP_KUWABARA_KONO, 0.5}, {GW_DAMP_KUWABARA_KONO, 0.2}, {GW_DAMP_HUNT_CROSSLEY, 0.5}};
    char what[800];
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        gw_chain_params p;
        if (calibrated(cases[c].model, cases[c].e, o, &p) != GW_OK)
            continue;
        const char *name = model_name(p.damping);
        p.n = 30;
        gw_chain_trace tr;
        gw_chain_trace_init(&tr, p.n);
        gw_chain_run_opts oo = *o;
        oo.sample = gw_chain_trace_sample;
        oo.sample_ctx = &tr;
        gw_chain_result r = {0};
        int ok = test_collide(&p, &oo, &r) == GW_OK;
        snprintf(what, sizeof what, "%s e = %.1f, N = 30: collision ran", name, cases[c].e);
        gw_test_true(ok, what);
        if (ok) {
            double fp = pow(p.mass, 0.6) * pow(p.k, 0.4) * pow(p.v_imp, 1.2);
            double lo = 1e300, hi = 0.0;
            for (int j = 1; j <= 6; j++) {
                double f = tenth_mean(&tr, r.tau_n, j);
                lo = f < lo ? f : lo;
                hi = f > hi ? f : hi;
            }
            snprintf(what, sizeof what,
                     "%s e = %.1f, N = 30: wall force over tenths 2-7 of the contact %.2f to %.2f N, "
                     "dissipative-shock F_p = %.2f N",
                     name, cases[c].e, lo, hi, fp);
            gw_test_true(fabs(lo / fp - 1) < 0.015 && fabs(hi / fp - 1) < 0.015, what);
        }
        gw_chain_result_free(&r);
        gw_chain_trace_free(&tr);
    }
}

int main(void)
{
    char what[800];
    const double targets[] = {0.9, 0.7};
    for (int model = 1; model <= 2; model++)
        for (int i = 0; i < 2; i++) {
            gw_chain_params p;
            gw_chain_run_opts o = test_opts("cvode", "bdf");
            calibrated(model, targets[i], &o, &p);
            snprintf(what, sizeof what, "%s constant %.6g: bead restitution at 0.3 m/s",
                     model_name(model), model == GW_DAMP_KUWABARA_KONO ? p.gamma : p.alpha);
            gw_test_rel(test_bead_e(p, 0.3), targets[i], 1e-3, what);
            double e1 = test_bead_e(p, 0.1), e3 = test_bead_e(p, 0.3), e10 = test_bead_e(p, 1.0);
            snprintf(what, sizeof what, "%s: restitution falls with velocity (%.4f, %.4f, %.4f at 0.1, 0.3, 1 m/s)",
                     model_name(model), e1, e3, e10);
            gw_test_true(e1 > e3 && e3 > e10, what);
        }

    gw_chain_params p;
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    if (calibrated(GW_DAMP_KUWABARA_KONO, 0.9, &o, &p) != GW_OK)
        return 1;
    const int ns[] = {1, 2, 5, 10, 20, 40};
    double prev = 2.0;
    int mono = 1;
    char list[256] = "";
    for (size_t k = 0; k < sizeof ns / sizeof ns[0]; k++) {
        p.n = ns[k];
        gw_chain_result r;
        if (test_collide(&p, &o, &r) != GW_OK)
            return 1;
        mono &= r.eps_eff < prev;
        prev = r.eps_eff;
        size_t len = strlen(list);
        snprintf(list + len, sizeof list - len, " %d:%.4f", ns[k], r.eps_eff);
        gw_chain_result_free(&r);
    }
    snprintf(what, sizeof what, "Kuwabara-Kono e = 0.9: eps_eff decreases with N (%s)", list);
    gw_test_true(mono, what);

    /* Plateau: ratio of the last to the second wall-force maximum, damped vs
     * the same column without damping. */
    double ratio[2];
    double fmin = 1e300;
    int count[2];
    for (int damped = 0; damped < 2; damped++) {
        gw_chain_params q = p;
        q.n = 30;
        if (!damped)
            q.damping = GW_DAMP_NONE;
        peaks pk = {1e300, 0, 0, 0, 0, 0, 0};
        gw_chain_run_opts oo = o;
        oo.sample = track;
        oo.sample_ctx = &pk;
        gw_chain_result r;
        if (test_collide(&q, &oo, &r) != GW_OK)
            return 1;
        gw_chain_result_free(&r);
        ratio[damped] = pk.last / pk.second;
        count[damped] = pk.count;
        if (damped)
            fmin = pk.fmin;
    }
    gw_test_true(fmin >= 0, "damped wall force never negative");
    snprintf(what, sizeof what,
             "N = 30 plateau, last/second wall-force maximum: %.4f with damping (%d maxima), %.4f without (%d maxima)",
             ratio[1], count[1], ratio[0], count[0]);
    /* Measured, not asserted: with Kuwabara-Kono e = 0.9 the model's plateau is
     * not more decaying than without damping (maxima 54.3 -> 50.5 N against
     * 57.9 -> 51.1 N); the experiment's decaying plateau is not reproduced by
     * this damping (reported in docs/column.md). */
    printf("INFO: %s\n", what);

    plateau_checks(&o);
    return gw_test_summary("test_chain_damping");
}
