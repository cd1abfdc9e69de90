/*
 * test_stiffness_named.c: a contact stiffness the column's run cannot resolve,
 * refused through the library naming the stiffness given (left after the
 * forty-fourth session).
 *   - kwall = 1.8e308 N/m^1.5 was refused under the names of what it sets:
 *     "dt-out: the default tau_1/200 = 8.68e-127 s gives about 8.63e+121
 *     samples" (the default dt-out), "dt-max: a step of 3.78e-125 s" (dt-out
 *     1e-6 s) and rk4's "dt: a step of 1.78e-127 s". Now named kwall with
 *     the range of kwall within the steps' and samples' bounds (its top end
 *     passes the check, 10 % above it is refused), as k was (session 44).
 *   - a dt_max given was not checked against the contacts: k = 1.8e308 with
 *     dt_max 1e-9 passed gw_chain_run_check and failed at its fourth step
 *     (cvode: "the corrector convergence test failed repeatedly", h = 9.6e-16
 *     s); k = 1e30 with it ran on for minutes. A dt_max above the contacts
 *     does not lower the work (the solver resolves each contact under any
 *     cap): k and kwall are held to their ranges at the default cap, naming
 *     them and the dt-max given. Controls: k = 1e28 (the range's top end)
 *     with dt_max 1e-9 runs; a dt_max of 1e-3 s on the default column runs
 *     with the default's F_max.
 *   - rk4 with a dt given left k out (session 45): k = 1.8e308 at dt 1e-9
 *     was refused as "dt-max: a step of 2.86e-125 s needs about 1.22e+120
 *     steps". Named k with its range at that dt and "the dt given (1e-09 s)
 *     does not change that" (kwall alike); the range's top end passes.
 *     Controls: dt 1e-13 (too small for any k) is still refused as the dt's;
 *     k 1e20 at dt 1e-9 runs.
 * Each case runs in its own child process (test_child.h); the refusal
 * naming k or kwall, the run's status and F_max are gw_test_cases.h's
 * (test_library_hostile50 checks them too).
 */
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gw_chain.h"
#include "gw_test_cases.h"
#include "test_child.h"

static int c_kwall_named(void)
{
    const double dt_outs[] = {0, 1e-6};
    for (int s = 0; s < 2; s++)
        for (int i = 0; i < 2; i++) {
            gw_chain_params p = gw_chain_params_default();
            p.n = 3;
            p.kwall = DBL_MAX;
            gw_chain_run_opts o = gw_chain_run_opts_default();
            o.dt_out = dt_outs[i];
            if (s)
                o.solver = gw_solver_rk4;
            double hi = 0, hi2 = 0;
            EXPECT(test_stiffness_refused(&p, &o, "kwall", &hi) && hi > 1e15 && hi < 1e40);
            /* the range's top end passes the check (under the default dt-out,
             * a dt-out that keeps the samples in bound: the default's refusal
             * names dt-out there), 10 % above it is refused naming kwall */
            p.kwall = hi;
            gw_chain_run_opts oh = o;
            if (!(oh.dt_out > 0))
                oh.dt_out = 1e-9;
            gw_err e = {0};
            if (gw_chain_run_check(&p, &oh, &e) != GW_OK)
                printf("kwall %g: '%s'\n", hi, e.msg);
            EXPECT(gw_chain_run_check(&p, &oh, &e) == GW_OK);
            const int rc = gw_chain_run_check(&p, &o, &e);
            EXPECT(rc == GW_OK || (refused(rc, &e, "dt-out: ") && strncmp(e.msg, "kwall: ", 7) != 0));
            p.kwall = 1.1 * hi;
            EXPECT(test_stiffness_refused(&p, &o, "kwall", &hi2) && hi2 == hi);
        }
    /* the run itself refuses it the same way */
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    p.kwall = DBL_MAX;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    gw_err e = {0};
    const int rc = test_chain_run_status(&p, &o, &e);
    EXPECT(refused(rc, &e, "kwall: 1.79769e+308 N/m^1.5 is outside ["));
    return 0;
}

static int c_kwall_controls(void)
{
    /* k = 1.8e308 with the default kwall is still k's; k and kwall both 1e200 pass */
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    p.k = DBL_MAX;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    double hi = 0;
    EXPECT(test_stiffness_refused(&p, &o, "k", &hi));
    p.k = p.kwall = 1e200;
    gw_err e = {0};
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_OK);
    /* a dt-out given too small is still dt-out's (a kwall within its range) */
    p = gw_chain_params_default();
    p.n = 3;
    o.dt_out = 1e-15;
    EXPECT(refused(gw_chain_run_check(&p, &o, &e), &e, "dt-out: "));
    return 0;
}

static int c_dt_max_contacts(void)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    p.k = DBL_MAX;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.sp.dt_max = 1e-9;
    double hi = 0, hi2 = 0;
    EXPECT(test_stiffness_refused(&p, &o, "k", &hi));
    gw_err e = {0};
    gw_chain_run_check(&p, &o, &e);
    EXPECT(strstr(e.msg, "the dt-max given (1e-09 s)") != NULL);
    /* k 1e30 (it ran on for minutes) too, the same range */
    p.k = 1e30;
    EXPECT(test_stiffness_refused(&p, &o, "k", &hi2) && hi2 == hi);
    /* rk4 under the dt_max given as well */
    o.solver = gw_solver_rk4;
    EXPECT(test_stiffness_refused(&p, &o, "k", &hi2));
    /* kwall alike */
    o = gw_chain_run_opts_default();
    o.sp.dt_max = 1e-9;
    o.dt_out = 1e-6;
    p = gw_chain_params_default();
    p.n = 3;
    p.kwall = DBL_MAX;
    EXPECT(test_stiffness_refused(&p, &o, "kwall", &hi2));
    return 0;
}

static int c_dt_max_controls(void)
{
    /* the range's top end with dt_max 1e-9 runs; a dt_max of 1e-3 s on the
     * default column runs with the default's F_max */
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    p.k = 1e28;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.sp.dt_max = 1e-9;
    gw_err e = {0};
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_OK);
    EXPECT(test_chain_fmax(&p, &o) > 0);
    p = gw_chain_params_default();
    p.n = 3;
    o = gw_chain_run_opts_default();
    const double f0 = test_chain_fmax(&p, &o);
    o.sp.dt_max = 1e-3;
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_OK);
    const double f1 = test_chain_fmax(&p, &o);
    EXPECT(f0 > 0 && fabs(f1 / f0 - 1) < 1e-6);
    return 0;
}

static int c_rk4_dt_named(void)
{
    /* rk4 with a dt given: k = 1.8e308 at dt 1e-9 was refused as "dt-max: a
     * step of 2.86e-125 s needs about 1.22e+120 steps ..." (that path left k
     * out); now named k with its range and the dt given, as without a dt */
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    p.k = DBL_MAX;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.solver = gw_solver_rk4;
    o.sp.dt = 1e-9;
    double hi = 0, hi2 = 0;
    EXPECT(test_stiffness_refused(&p, &o, "k", &hi) && hi > 1e20 && hi < 1e40);
    gw_err e = {0};
    gw_chain_run_check(&p, &o, &e);
    EXPECT(strstr(e.msg, "the dt given (1e-09 s) does not change that") != NULL);
    /* the range's top end passes, 10 % above it is refused naming k */
    p.k = hi;
    if (gw_chain_run_check(&p, &o, &e) != GW_OK)
        printf("k %g at dt 1e-9: '%s'\n", hi, e.msg);
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_OK);
    p.k = 1.1 * hi;
    EXPECT(test_stiffness_refused(&p, &o, "k", &hi2) && hi2 == hi);
    /* the run itself refuses it the same way */
    p.k = DBL_MAX;
    const int rc = test_chain_run_status(&p, &o, &e);
    EXPECT(refused(rc, &e, "k: 1.79769e+308 N/m^1.5 is outside ["));
    /* kwall under the dt given names it too */
    p = gw_chain_params_default();
    p.n = 3;
    p.kwall = DBL_MAX;
    o.dt_out = 1e-6;
    EXPECT(test_stiffness_refused(&p, &o, "kwall", &hi2));
    gw_chain_run_check(&p, &o, &e);
    EXPECT(strstr(e.msg, "the dt given (1e-09 s) does not change that") != NULL);
    return 0;
}

static int c_rk4_dt_controls(void)
{
    /* a dt too small for any k is still the dt's; a k within the range at a
     * dt below its contact runs */
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.solver = gw_solver_rk4;
    o.sp.dt = 1e-13;
    gw_err e = {0};
    EXPECT(refused(gw_chain_run_check(&p, &o, &e), &e, "dt: a step of 1e-13 s"));
    o.sp.dt = 1e-9;
    p.k = 1e20;
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_OK);
    EXPECT(test_chain_fmax(&p, &o) > 0);
    return 0;
}

static const child_row rows[] = {
    {"kwall 1.8e308: named kwall with its range (was dt-out, dt-max, rk4's dt), by the check and the run",
     c_kwall_named},
    {"controls: k 1.8e308 named k; k and kwall 1e200 pass; a small dt-out given is dt-out's", c_kwall_controls},
    {"a dt_max given: k 1.8e308 and 1e30, kwall 1.8e308 refused naming them and the dt-max (passed)",
     c_dt_max_contacts},
    {"controls: k 1e28 with dt_max 1e-9 runs; dt_max 1e-3 s runs with the default's F_max", c_dt_max_controls},
    {"rk4 with dt 1e-9: k 1.8e308 named k with its range and the dt given (was dt-max's), by the check and the run; "
     "kwall too",
     c_rk4_dt_named},
    {"controls: rk4 dt 1e-13 still the dt's; k 1e20 at dt 1e-9 runs", c_rk4_dt_controls},
};

int main(void)
{
    return child_cases_run(rows, sizeof rows / sizeof rows[0]);
}
