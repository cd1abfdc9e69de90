/*
 * test_sensor_damping_steps.c: the sensor body's step bound and its damping
 * (issue 18, the thirty-fourth and thirty-seventh sessions).
 *
 * Before a run the plan estimates the steps cvode and arkode take on a sensor
 * body and refuses estimates above 1e8. The estimate was piecewise in the
 * damping ratio zeta: under bdf and dirk the undamped one (20 a radian over
 * the whole collision) below 0.2 of critical and a decay count from 0.2, with
 * nothing for the collision's own steps. Measured on 1e12 N/m at 1e-12, n =
 * 5: bdf's estimate was 70.6, 250 and 2670 times its steps on 1e-7 kg at 0.1,
 * 0.15 and 0.2 (the body's ratio, counted with the contact's stiffness, is
 * 0.199997 there), so a 1e-9 kg body at 0.1 (16,895 steps) was refused; and
 * it was below the steps taken at 2 and 10 (0.41 to 0.99), as dirk's (0.13 to
 * 0.96). arkode erk kept the undamped estimate whatever the damping: 0.18 of
 * its steps at 10 of critical (17.9 million steps, 65 s, on 1e-6 kg), and its
 * drag estimate 0.056 on 1e-5 kg at rtol 1e-8. The estimate is now continuous
 * in zeta (chain_collide_plan.c, sensor_steps): the collision's steps at the
 * largest step plus the ring's, for bdf and dirk each contact event's ring
 * decaying at zeta omega until below the tolerance (with bdf's stability
 * wedge and its following the lightly damped ring), for erk and adams the
 * body's fastest mode.
 *
 * The thirty-eighth session: dirk's and imex's estimate was U, far above
 * their steps (dirk 25 to 5,700 times, refusing a 1e-9 kg body it runs in
 * 18,589 steps; imex 12 to 233 times), and dirk failed its error test on a
 * stiff overdamped body (1e-7 kg at 10 of critical, 1e-9 kg from 3), where
 * beyond 100 of critical its steps grew past the estimate. dirk's estimate is
 * now capped at 16 times the floor of its ring count with a term in the
 * overdamped fast root, imex's falls as omega^-1/2 (chain_collide_plan.c),
 * and arkode's implicit methods are allowed 30 failed error tests a step.
 *
 * The forty-sixth session: at rtol 1e-6 to 1e-10 the estimate was loose or
 * below the steps taken over a grid of runs (chain_collide_plan.c has the
 * table); 22 of those runs are asserted below, the estimate over the steps
 * before and now (steps taken in brackets):
 *   bdf  1e-7 kg undamped, 1e-8 (1,370)       1,230   8.56
 *   bdf  1e-7 kg 0.05, 1e-8 (1,368)           105     4.62
 *   bdf  1e-8 kg 0.05, 1e-8 (2,793)           52.2    2.53
 *   bdf  1e-6 kg undamped, 1e-6 (587)         572     3.29
 *   bdf  1e-6 kg 0.05, 1e-6 (631)             108     3.02
 *   bdf  1e-3 kg 0.05, 1e-8 (6,584)           0.566   1.07
 *   bdf  0.1 kg undamped, 1e-8 (2,685)        0.638   1.17
 *   bdf  0.01 kg 0.05, 1e-6 (1,457)           0.523   2.06
 *   bdf  0.01 kg 10, 1e-6 (818)               0.84    1.28
 *   bdf  1e-9 kg 0.05, 1e-10 (999,746)        0.456   1.03
 *   bdf  0.1 kg undamped, 1e-10 (5,691)       0.749   1.53
 *   dirk 1e-6 kg undamped, 1e-8 (671)         34.1    4.13
 *   dirk 1e-4 kg undamped, 1e-8 (590)         38.1    3.92
 *   dirk 1e-9 kg 0.05, 1e-8 (11,059)          0.771   1.29
 *   dirk 1e-6 kg 10, 1e-8 (2,373)             0.802   1.10
 *   dirk 1e-7 kg undamped, 1e-10 (3,231)      22.1    7.28
 *   dirk 1e-9 kg undamped, 1e-6 (54,445)      0.326   1.67
 *   dirk 1e-8 kg 10, 1e-6 (22,366)            0.171   2.30
 *   dirk 1e-4 kg undamped, 1e-6 (196)         54.5    5.44
 *   imex 1e-7 kg 1, 1e-6 (3,040)              42      19.0
 *   imex 1e-5 kg 10, 1e-6 (2,845)             28.2    12.6
 *   erk  0.1 kg 0.05, 1e-10 (965)             0.577   4.58
 *
 * Asserted, at rtol = atol = 1e-12 (some cases at 1e-8) on a 5-bead column:
 *   - the plan's estimate (chain_run_steps) within [1, 20] of the steps the
 *     solver reports over a grid of masses (1e-9, 1e-7, 1e-5 kg on 1e12 N/m;
 *     erk also 1e-3 kg on 1e9 N/m up to 1000 of critical) and damping ratios
 *     (0 to 10) for bdf, dirk, erk and adams, each run allowed; dirk also
 *     undamped (1e-9 kg; 1e-7 kg at 1e-8), at 0.01 and on stiff overdamped
 *     bodies (1e-7 kg at 10, 1e-9 kg at 5 and 100), imex at 1e-8 (1e-9 and
 *     1e-5 kg undamped, 1e-7 kg at 10); dirk's F_max on 1e-7 kg at 10 of
 *     critical within 1e-8 of bdf's;
 *   - the estimate continuous in zeta: over 1e-3 to 100 of critical in steps
 *     of 0.5 %, each estimate within 20 % of the one before, per backend
 *     (bdf's and dirk's jumped 160 times at 0.2);
 *   - arkode erk's drag check refuses a 1e-6 kg body at 10 of critical
 *     (measured 17.9 million steps, 65 s), naming sensor-damping;
 *   - the critically damped 1e-9 kg body runs under bdf and reads the rigid
 *     wall's F_max within 1e-4 and tau_N within 1e-5; the undamped 1e-9 kg
 *     body is still refused, naming sensor-stiffness.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "chain_model.h"
#include "chain_test_util.h"
#include "gw_test.h"

static const double V29 = 0.23853; /* sqrt(2 g 2.9 mm), m/s */

static gw_chain_params sensor_params(double m, double k, double zeta)
{
    gw_chain_params p = test_params(5, V29);
    if (m > 0) {
        p.sensor.mass = m;
        p.sensor.stiffness = k;
        p.sensor.damping = zeta * 2 * sqrt(m * k);
    }
    return p;
}

/* The plan's estimate of p's run under solver/method at tol (NAN when refused) */
static double estimate(const char *solver, const char *method, double tol, const gw_chain_params *p)
{
    gw_chain_run_opts o = test_opts(solver, method);
    o.sp.rtol = o.sp.atol = tol;
    gw_err err = {{0}};
    double est = NAN;
    if (chain_run_steps(p, &o, &est, &err) != GW_OK)
        return NAN;
    return est;
}

/* Run and compare the estimate with the steps taken: one counted check (a
 * refused or failed run is a failed collision and a failed ratio). */
static void ratio_check(const char *solver, const char *method, double m, double k, double zeta, double tol)
{
    gw_chain_params p = sensor_params(m, k, zeta);
    gw_chain_run_opts o = test_opts(solver, method);
    o.sp.rtol = o.sp.atol = tol;
    const double est = estimate(solver, method, tol, &p);
    gw_chain_result r;
    long steps = -1;
    if (test_collide(&p, &o, &r) == GW_OK) {
        steps = r.stats.steps;
        gw_chain_result_free(&r);
    }
    GW_TEST_OK(steps > 0 && est >= (double)steps && est <= 20.0 * (double)steps,
               "%s %s, %g kg on %g N/m at %g of critical, tol %g: estimate %.4g over %ld steps taken = %.3g, "
               "within [1, 20]", solver, method, m, k, zeta, tol, est, steps, est / (double)steps);
}

/* The estimate over zeta from 1e-3 to 100 of critical in steps of 0.5 %:
 * each within 20 % of the one before (no jump; its steepest continuous part,
 * the explicit methods' overdamped fast root zeta + sqrt(zeta^2 - 1) just
 * above critical, changes by 10.3 % there; the jump at 0.2 was 160 times) */
static void continuity_check(const char *solver, const char *method, double m)
{
    double worst = 0, at = 0, prev = NAN;
    int compared = 0;
    for (double z = 1e-3; z <= 100; z *= 1.005) {
        gw_chain_params p = sensor_params(m, 1e12, z);
        const double e = estimate(solver, method, 1e-12, &p);
        if (!isnan(e) && !isnan(prev)) { /* refused: the runs allowed are compared */
            compared++;
            const double d = fabs(log(e / prev));
            if (!(d <= worst)) {
                worst = d;
                at = z;
            }
        }
        prev = e;
    }
    GW_TEST_OK(compared >= 1000 && worst <= log(1.2), "%s %s, %g kg on 1e12 N/m: the estimate continuous in zeta "
               "over [1e-3, 100] (%d steps of 0.5 %% compared; the largest change %.3g times, at %.4g)", solver, method,
               m, compared, exp(worst), at);
}

int main(void)
{
    /* bdf: masses 1e-9 to 1e-5 kg, zeta 0 to 10 (bdf follows the ring below
     * about 0.15: 1,016,686 steps on 1e-9 kg at 0.05, 3.7 s) */
    const double bdf9[] = {0.05, 0.1, 0.15, 0.2, 0.5, 1, 2, 10};
    for (int i = 0; i < 8; i++)
        ratio_check("cvode", "bdf", 1e-9, 1e12, bdf9[i], 1e-12);
    const double bdf7[] = {0.1, 0.15, 0.2, 1, 10};
    for (int i = 0; i < 5; i++)
        ratio_check("cvode", "bdf", 1e-7, 1e12, bdf7[i], 1e-12);
    const double bdf5[] = {0, 0.05, 0.1, 0.2, 10};
    for (int i = 0; i < 5; i++)
        ratio_check("cvode", "bdf", 1e-5, 1e12, bdf5[i], 1e-12);
    /* dirk steps over the damped ring */
    const double dirk9[] = {0.05, 0.1, 0.2, 1, 2};
    for (int i = 0; i < 5; i++)
        ratio_check("arkode", "dirk", 1e-9, 1e12, dirk9[i], 1e-12);
    ratio_check("arkode", "dirk", 1e-7, 1e12, 0.1, 1e-12);
    ratio_check("arkode", "dirk", 1e-7, 1e12, 1, 1e-12);
    const double dirk5[] = {0.05, 1, 10};
    for (int i = 0; i < 3; i++)
        ratio_check("arkode", "dirk", 1e-5, 1e12, dirk5[i], 1e-12);
    /* the explicit methods, held to the body's fastest mode */
    const double erk5[] = {0, 0.1, 1, 2};
    for (int i = 0; i < 4; i++)
        ratio_check("arkode", "erk", 1e-5, 1e12, erk5[i], 1e-12);
    ratio_check("arkode", "erk", 1e-5, 1e12, 1, 1e-8);
    const double erk3[] = {10, 100, 1000};
    for (int i = 0; i < 3; i++)
        ratio_check("arkode", "erk", 1e-3, 1e9, erk3[i], 1e-12);
    const double adams5[] = {0.1, 1, 2};
    for (int i = 0; i < 3; i++)
        ratio_check("cvode", "adams", 1e-5, 1e12, adams5[i], 1e-12);
    /* dirk steps over the undamped and barely damped ring (its estimate was
     * U: refused on 1e-9 kg, 18,589 steps; 1,160 times 1,451 steps at 1e-8
     * on 1e-7 kg; 96 times on 1e-9 kg at 0.01) */
    ratio_check("arkode", "dirk", 1e-9, 1e12, 0, 1e-12);
    ratio_check("arkode", "dirk", 1e-7, 1e12, 0, 1e-8);
    ratio_check("arkode", "dirk", 1e-9, 1e12, 0.01, 1e-12);
    /* dirk on a stiff overdamped body ran out of its 7 failed error tests
     * (1e-7 kg at 10, 1e-9 kg from 3 of critical); 100 of critical on 1e-9
     * kg takes 30,602 steps (the estimate had 20,370) */
    ratio_check("arkode", "dirk", 1e-7, 1e12, 10, 1e-12);
    ratio_check("arkode", "dirk", 1e-9, 1e12, 5, 1e-12);
    ratio_check("arkode", "dirk", 1e-9, 1e12, 100, 1e-12);
    /* imex steps over the ring, more slowly on a faster one (its estimate, U,
     * was 233, 61 and 33.5 times the steps taken) */
    ratio_check("arkode", "imex", 1e-9, 1e12, 0, 1e-8);
    ratio_check("arkode", "imex", 1e-7, 1e12, 10, 1e-8);
    ratio_check("arkode", "imex", 1e-5, 1e12, 0, 1e-8);

    /* The forty-sixth session: at looser tolerances the estimate was loose
     * or below the steps taken. Measured estimate / steps before over the
     * grid (bdf, dirk, imex, erk; rtol 1e-6, 1e-8, 1e-10; 1e-9 to 0.1 kg on
     * 1e12 N/m; 0, 0.05, 1 and 10 of critical), those runs now asserted in
     * [1, 20]: bdf stepped over a fast ring the collision excites below the
     * tolerance (1,230 times on 1e-7 kg undamped at 1e-8, 105 at 0.05, 572 on
     * 1e-6 kg at 1e-6) and followed a slow one with the collision's own steps
     * uncounted (0.52 to 0.97 on 1e-3 to 0.1 kg); dirk's undamped cap was 16
     * floors at any tolerance (30 to 38 at 1e-8, 22 at 1e-10) and at 1e-6 it
     * takes 45,000 to 66,000 steps on 1e-9 kg (0.13 to 0.33); imex at 1e-6 on
     * 1e-7 kg at critical 42; bdf following a 1e-9 kg body at 0.05 of
     * critical past its decay count at 1e-10 (0.456); erk on a 0.1 kg body at
     * 0.05 of critical at 1e-10 (0.577). */
    ratio_check("cvode", "bdf", 1e-7, 1e12, 0, 1e-8);
    ratio_check("cvode", "bdf", 1e-7, 1e12, 0.05, 1e-8);
    ratio_check("cvode", "bdf", 1e-8, 1e12, 0.05, 1e-8);
    ratio_check("cvode", "bdf", 1e-6, 1e12, 0, 1e-6);
    ratio_check("cvode", "bdf", 1e-6, 1e12, 0.05, 1e-6);
    ratio_check("cvode", "bdf", 1e-3, 1e12, 0.05, 1e-8);
    ratio_check("cvode", "bdf", 0.1, 1e12, 0, 1e-8);
    ratio_check("cvode", "bdf", 0.01, 1e12, 0.05, 1e-6);
    ratio_check("cvode", "bdf", 0.01, 1e12, 10, 1e-6);
    ratio_check("cvode", "bdf", 1e-9, 1e12, 0.05, 1e-10);
    ratio_check("cvode", "bdf", 0.1, 1e12, 0, 1e-10);
    ratio_check("arkode", "dirk", 1e-6, 1e12, 0, 1e-8);
    ratio_check("arkode", "dirk", 1e-4, 1e12, 0, 1e-8);
    ratio_check("arkode", "dirk", 1e-9, 1e12, 0.05, 1e-8);
    ratio_check("arkode", "dirk", 1e-6, 1e12, 10, 1e-8);
    ratio_check("arkode", "dirk", 1e-7, 1e12, 0, 1e-10);
    ratio_check("arkode", "dirk", 1e-9, 1e12, 0, 1e-6);
    ratio_check("arkode", "dirk", 1e-8, 1e12, 10, 1e-6);
    ratio_check("arkode", "dirk", 1e-4, 1e12, 0, 1e-6);
    ratio_check("arkode", "imex", 1e-7, 1e12, 1, 1e-6);
    ratio_check("arkode", "imex", 1e-5, 1e12, 10, 1e-6);
    ratio_check("arkode", "erk", 0.1, 1e12, 0.05, 1e-10);

    /* no jump in zeta */
    continuity_check("cvode", "bdf", 1e-7);
    continuity_check("arkode", "dirk", 1e-7);
    continuity_check("arkode", "erk", 1e-5);
    continuity_check("cvode", "adams", 1e-5);
    continuity_check("arkode", "imex", 1e-5);

    /* erk's drag check: 1e-6 kg at 10 of critical took 17.9 million steps */
    gw_err err = {{0}};
    gw_chain_params pd = sensor_params(1e-6, 1e12, 10);
    gw_chain_run_opts oe = test_opts("arkode", "erk");
    int rc = gw_chain_run_check(&pd, &oe, &err);
    printf("  (erk, 1e-6 kg at 10 of critical: %s)\n", rc == GW_OK ? "allowed" : err.msg);
    gw_test_true(rc == GW_EINVAL && strstr(err.msg, "sensor-damping:") != NULL,
                 "arkode erk on a 1e-6 kg body at 10 of critical refused, naming sensor-damping");

    /* dirk on the overdamped 1e-7 kg body (10 of critical) reads bdf's F_max
     * (measured 4e-11 apart at n = 5; the run failed before) */
    {
        gw_chain_params pz = sensor_params(1e-7, 1e12, 10);
        gw_chain_run_opts ob = test_opts("cvode", "bdf"), od = test_opts("arkode", "dirk");
        gw_chain_result rb, rd;
        if (test_collide(&pz, &ob, &rb) == GW_OK) {
            if (test_collide(&pz, &od, &rd) == GW_OK) {
                gw_test_rel(rd.f_max, rb.f_max, 1e-8, "arkode dirk on 1e-7 kg at 10 of critical: F_max = cvode bdf's");
                gw_chain_result_free(&rd);
            }
            gw_chain_result_free(&rb);
        }
    }

    /* the critically damped 1e-9 kg body runs and reads the rigid wall */
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    gw_chain_params p0 = sensor_params(0, 0, 0), p1 = sensor_params(1e-9, 1e12, 1);
    gw_chain_result r0, r1;
    int ok0 = test_collide(&p0, &o, &r0) == GW_OK;
    gw_chain *c = NULL;
    memset(&err, 0, sizeof err);
    rc = gw_chain_create(&p1, &c, &err);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, &o, &r1, &err);
    gw_chain_free(c);
    if (rc != GW_OK)
        printf("  (1e-9 kg critically damped: %s)\n", err.msg);
    gw_test_true(rc == GW_OK, "a critically damped 1e-9 kg sensor body on 1e12 N/m runs under cvode bdf");
    if (rc == GW_OK && ok0) {
        gw_test_rel(r1.f_max, r0.f_max, 1e-4, "critically damped 1e-9 kg body: F_max = the rigid wall's");
        gw_test_rel(r1.tau_n, r0.tau_n, 1e-5, "critically damped 1e-9 kg body: tau_N = the rigid wall's");
        gw_chain_result_free(&r1);
    }
    if (ok0)
        gw_chain_result_free(&r0);

    /* the undamped one still refused */
    gw_chain_params pu = sensor_params(1e-9, 1e12, 0);
    memset(&err, 0, sizeof err);
    rc = gw_chain_run_check(&pu, &o, &err);
    printf("  (1e-9 kg undamped: %s)\n", err.msg);
    gw_test_true(rc == GW_EINVAL && strstr(err.msg, "sensor-stiffness:") != NULL,
                 "an undamped 1e-9 kg body on 1e12 N/m refused, naming sensor-stiffness");
    return gw_test_summary("test_sensor_damping_steps");
}
