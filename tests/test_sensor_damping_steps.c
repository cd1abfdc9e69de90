/*
 * test_sensor_damping_steps.c: the sensor body's step bound and its damping
 * (issue 18, the thirty-fourth session).
 *
 * The plan estimated the steps cvode and arkode take on a sensor body at 20 a
 * radian of its undamped frequency over the whole collision, whatever its
 * damping: a critically damped 1e-9 kg body on 1e12 N/m was refused as 1.06e8
 * steps where cvode bdf takes 7,244. A damped ring decays in 1/(zeta omega),
 * and bdf and arkode dirk (the body implicit) follow it only until it is
 * below the tolerance after each contact event; from zeta = 0.2 the estimate
 * is now 4 (n + 1) events of per_rad ln(1/tol) / zeta steps (capped by the
 * undamped one). Below 0.2, and for the explicit methods, whose stability
 * holds them to the ring whatever the damping, the undamped estimate stays.
 *
 * Asserted, at rtol = atol = 1e-12 on a 5-bead column:
 *   - the plan's estimate (chain_run_steps) within a factor [0.5, 20] of the
 *     steps the solver reports: bdf on 1e-9 kg, 1e12 N/m at zeta 0.25, 0.5, 1,
 *     2 (measured 6.8, 3.6, 1.8, 0.99); dirk at 0.25 and 1 (4.1, 1.1); bdf on
 *     1e-5 kg at zeta 0 and 0.02 (the undamped estimate, 2.9 and 15);
 *   - an explicit method is not helped by the damping: arkode erk on 1e-5 kg
 *     takes at least half its undamped steps when critically damped
 *     (measured 332,998 against 157,591), within [1, 20] of the estimate (3.2);
 *   - the critically damped 1e-9 kg body runs under bdf and reads the rigid
 *     wall's F_max within 1e-4 (measured 1.21e-5: the body's spring gives way
 *     by F/k_s; the same at 1e-7 kg) and tau_N within 1e-5;
 *   - the undamped 1e-9 kg body, and one damped at 0.1 of critical, are still
 *     refused (1.06e8 steps estimated; bdf took 6.7 million steps, 40 s, at
 *     0.02 of critical), naming sensor-stiffness.
 * On the code before 13 of its counted checks fail: the six damped runs on
 * 1e-9 kg, refused as 1.06e8 steps (each counted as a failed collision and a
 * failed ratio), and the critically damped body's run (its F_max and tau_N
 * checks not reached).
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

/* Run; *steps the solver's, *est the plan's estimate; GW_OK or the failure
 * (counted by test_collide) */
static int run_counted(const char *solver, const char *method, double m, double k, double zeta, long *steps,
                       double *est, gw_chain_result *r)
{
    gw_chain_params p = sensor_params(m, k, zeta);
    gw_chain_run_opts o = test_opts(solver, method);
    gw_err err = {{0}};
    *est = NAN;
    *steps = -1;
    chain_run_steps(&p, &o, est, &err);
    int rc = test_collide(&p, &o, r);
    if (rc == GW_OK)
        *steps = r->stats.steps;
    return rc;
}

static void ratio_check(const char *solver, const char *method, double m, double k, double zeta, double lo, double hi)
{
    long steps;
    double est;
    gw_chain_result r;
    char what[256];
    snprintf(what, sizeof what, "%s %s, %g kg on %g N/m at %g of critical: the estimate within [%g, %g] of the "
             "steps taken", solver, method, m, k, zeta, lo, hi);
    if (run_counted(solver, method, m, k, zeta, &steps, &est, &r) == GW_OK) {
        printf("  (%s %s, %g kg, zeta %g: %ld steps, estimated %.4g, ratio %.3g)\n", solver, method, m, zeta, steps,
               est, est / (double)steps);
        gw_test_true(est >= lo * (double)steps && est <= hi * (double)steps, what);
        gw_chain_result_free(&r);
    } else {
        gw_test_true(0, what);
    }
}

int main(void)
{
    /* the damped estimate against bdf and dirk */
    const double zetas[] = {0.25, 0.5, 1, 2};
    for (int i = 0; i < 4; i++)
        ratio_check("cvode", "bdf", 1e-9, 1e12, zetas[i], 0.5, 20);
    ratio_check("arkode", "dirk", 1e-9, 1e12, 0.25, 0.5, 20);
    ratio_check("arkode", "dirk", 1e-9, 1e12, 1, 0.5, 20);
    /* light damping keeps the undamped estimate, conservative */
    ratio_check("cvode", "bdf", 1e-5, 1e12, 0, 1, 20);
    ratio_check("cvode", "bdf", 1e-5, 1e12, 0.02, 1, 20);

    /* an explicit method: its stability holds it whatever the damping */
    long s0 = -1, s1 = -1;
    double est0, est1;
    gw_chain_result r;
    if (run_counted("arkode", "erk", 1e-5, 1e12, 0, &s0, &est0, &r) == GW_OK)
        gw_chain_result_free(&r);
    if (run_counted("arkode", "erk", 1e-5, 1e12, 1, &s1, &est1, &r) == GW_OK)
        gw_chain_result_free(&r);
    printf("  (arkode erk, 1e-5 kg: %ld steps undamped, %ld critically damped, estimated %.4g)\n", s0, s1, est1);
    gw_test_true(s0 > 0 && s1 >= 0.5 * (double)s0, "erk critically damped takes at least half its undamped steps");
    gw_test_true(s1 > 0 && est1 >= (double)s1 && est1 <= 20.0 * (double)s1,
                 "erk critically damped: the (undamped) estimate within [1, 20] of its steps");

    /* the critically damped 1e-9 kg body runs and reads the rigid wall */
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    gw_chain_params p0 = sensor_params(0, 0, 0), p1 = sensor_params(1e-9, 1e12, 1);
    gw_chain_result r0, r1;
    int ok0 = test_collide(&p0, &o, &r0) == GW_OK;
    gw_chain *c = NULL;
    gw_err err = {{0}};
    int rc = gw_chain_create(&p1, &c, &err);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, &o, &r1, &err);
    gw_chain_free(c);
    if (rc != GW_OK)
        printf("  (1e-9 kg critically damped: %s)\n", err.msg);
    gw_test_true(rc == GW_OK, "a critically damped 1e-9 kg sensor body on 1e12 N/m runs under cvode bdf");
    if (rc == GW_OK && ok0) {
        printf("  (F_max %.12g N on the body, %.12g N on the rigid wall: %.3g relative; %ld steps)\n", r1.f_max,
               r0.f_max, r1.f_max / r0.f_max - 1, r1.stats.steps);
        gw_test_rel(r1.f_max, r0.f_max, 1e-4, "critically damped 1e-9 kg body: F_max = the rigid wall's");
        gw_test_rel(r1.tau_n, r0.tau_n, 1e-5, "critically damped 1e-9 kg body: tau_N = the rigid wall's");
        gw_chain_result_free(&r1);
    }
    if (ok0)
        gw_chain_result_free(&r0);

    /* the undamped one, and one damped below 0.2 of critical, still refused */
    const double refused[] = {0, 0.1};
    for (int i = 0; i < 2; i++) {
        gw_chain_params pu = sensor_params(1e-9, 1e12, refused[i]);
        memset(&err, 0, sizeof err);
        rc = gw_chain_run_check(&pu, &o, &err);
        printf("  (1e-9 kg at %g of critical: %s)\n", refused[i], err.msg);
        char what[160];
        snprintf(what, sizeof what, "a 1e-9 kg body on 1e12 N/m at %g of critical refused, naming sensor-stiffness",
                 refused[i]);
        gw_test_true(rc == GW_EINVAL && strstr(err.msg, "sensor-stiffness:") != NULL, what);
    }
    return gw_test_summary("test_sensor_damping_steps");
}
