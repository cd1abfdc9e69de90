/*
 * test_rk4_refusals.c: rk4's refusals of a dt and a contact stiffness that
 * are wrong together, its drop's chatter rerun, and the run's tolerances as
 * members of the result (left after the forty-fifth session).
 *   - Under rk4 a dt given too small for any k together with a k too stiff
 *     for it was refused as the dt-max's, which was not given
 *     (o.solver = gw_solver_rk4; o.sp.dt = 1e-13; p.k = 1e30: "dt-max: a
 *     step of 5.73783e-14 s needs about 6.1e+08 steps ... the default largest
 *     step is a quarter of the shortest contact"); kwall 1e30 at that dt was
 *     the default dt-out's ("dt-out: the default tau_1/200 = 1.73939e-15
 *     s"), and with a dt-max given the dt alone was named. Both are named now
 *     in one line, the dt first ("named in the order dt, k, kwall"): the dt
 *     "needs at least about N steps over the collision at any k", and k "is
 *     too stiff for that dt", with the largest k that keeps the dt as the
 *     step. That k is then refused as the dt's alone, with at least N steps.
 *     Over every combination of dt (none, 1e-9, 1e-13), dt_max (none, 1e-9),
 *     k and kwall (default, 1e30, 1e-30) no refusal names a dt-max that was
 *     not given (3 of the 54 did). Controls: the dt alone (1e-13, default k)
 *     and k alone (1e30, no dt) are refused as before.
 *   - rk4's drop rerun (half the step: twice the drop's steps, known before
 *     it is made) was bounded at 1e7 steps times bodies: drop --n 3
 *     --sensor-mass 1e-6 --sensor-stiffness 1e5 (6.0e6 steps times 3) was
 *     left unmeasured (chatter_kind COSTLY). Measured, its rerun takes 1.25 s
 *     of CPU (at most about 11 s at the new bound, 5e7): it is run again now.
 *   - The run's rtol and atol were kept in a hidden buffer after final_v:
 *     gw_chain_result.run_rtol and run_atol now hold them (cvode and arkode:
 *     the values run, gw_chain_run_opts_default's 1e-10; NaN under rk4), a drop's in its
 *     first collision (r.first). These do not compile before.
 * Each case runs in its own child process (test_child.h); every check is
 * counted (CHECK goes on after a failure).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"
#include "gw_test_cases.h"
#include "test_child.h"

static int n_bad;

/* a check that goes on after a failure (the case fails at its end) */
#define CHECK(cond)                                                                                   \
    do {                                                                                              \
        if (!(cond)) {                                                                                \
            printf("%s:%d: expected %s\n", __FILE__, __LINE__, #cond);                               \
            n_bad++;                                                                                  \
        }                                                                                             \
    } while (0)

static gw_chain_run_opts rk4(double dt, double dt_max)
{
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.solver = gw_solver_rk4;
    o.sp.dt = dt;
    o.sp.dt_max = dt_max;
    return o;
}

static int check_msg(const gw_chain_params *p, const gw_chain_run_opts *o, gw_err *e)
{
    memset(e, 0, sizeof *e);
    return gw_chain_run_check(p, o, e);
}

/* the number after KEY in s, or NaN */
static double after(const char *s, const char *key)
{
    const char *a = strstr(s, key);
    return a ? strtod(a + strlen(key), NULL) : NAN;
}

static int c_dt_and_k(void)
{
    gw_chain_params p = test_chain_column(1e30, 0);
    gw_chain_run_opts o = rk4(1e-13, 0);
    gw_err e;
    const int rc = check_msg(&p, &o, &e);
    CHECK(rc == GW_EINVAL && strncmp(e.msg, "dt: a step of 1e-13 s needs at least about ", 43) == 0);
    CHECK(strstr(e.msg, "at any k (") && strstr(e.msg, "raise it; and k: 1e+30 N/m^1.5 is too stiff for that dt"));
    CHECK(!strstr(e.msg, "dt-max") && strstr(e.msg, "named in the order dt, k, kwall"));
    const double least = after(e.msg, "needs at least about "), k_dt = after(e.msg, "k up to ");
    CHECK(least > 1e8 && k_dt > 1e20 && k_dt < 1e30);
    if (n_bad)
        printf("'%s'\n", e.msg);
    /* that k is the dt's alone, at least the least steps said */
    gw_chain_params q = test_chain_column(k_dt, 0);
    const int rc2 = check_msg(&q, &o, &e);
    CHECK(rc2 == GW_EINVAL && strncmp(e.msg, "dt: a step of 1e-13 s needs about ", 34) == 0 && !strstr(e.msg, "k:"));
    CHECK(after(e.msg, "needs about ") >= least * (1 - 1e-3));
    /* the run refuses it the same way */
    gw_chain *c = NULL;
    gw_err e2 = {{0}};
    check_msg(&p, &o, &e);
    CHECK(gw_chain_create(&p, &c, &e2) == GW_OK);
    gw_chain_result r;
    memset(&r, 0, sizeof r);
    CHECK(gw_chain_collide(c, &o, &r, &e2) == GW_EINVAL && strcmp(e2.msg, e.msg) == 0);
    gw_chain_result_free(&r);
    gw_chain_free(c);
    return n_bad;
}

static int c_dt_and_kwall(void)
{
    /* kwall 1e30 at dt 1e-13 was the default dt-out's */
    gw_chain_params p = test_chain_column(0, 1e30);
    gw_chain_run_opts o = rk4(1e-13, 0);
    gw_err e;
    CHECK(check_msg(&p, &o, &e) == GW_EINVAL && strncmp(e.msg, "dt: a step of 1e-13 s", 21) == 0);
    CHECK(strstr(e.msg, "at any kwall (") && strstr(e.msg, "and kwall: 1e+30 N/m^1.5 is too stiff for that dt"));
    CHECK(!strstr(e.msg, "dt-out") && !strstr(e.msg, "dt-max"));
    if (n_bad)
        printf("'%s'\n", e.msg);
    return n_bad;
}

static int c_dt_max_given(void)
{
    /* with a dt-max given the dt alone was named (k 1e30 left out) */
    gw_chain_params p = test_chain_column(1e30, 0);
    gw_chain_run_opts o = rk4(1e-13, 1e-9);
    gw_err e;
    CHECK(check_msg(&p, &o, &e) == GW_EINVAL && strncmp(e.msg, "dt: a step of 1e-13 s", 21) == 0);
    CHECK(strstr(e.msg, "and k: 1e+30 N/m^1.5 is too stiff for that dt"));
    CHECK(strstr(e.msg, "the dt-max given (1e-09 s)") && !strstr(e.msg, " ... "));
    if (n_bad)
        printf("'%s'\n", e.msg);
    return n_bad;
}

static int c_soft_wall(void)
{
    /* k 1e30 on a wall of kwall 1e-30 at dt 1e-9: the dt-max's (not given) */
    gw_chain_params p = test_chain_column(1e30, 1e-30);
    gw_chain_run_opts o = rk4(1e-9, 0);
    gw_err e;
    CHECK(check_msg(&p, &o, &e) == GW_EINVAL && strncmp(e.msg, "dt-max", 6) != 0);
    CHECK(strstr(e.msg, "k: 1e+30 N/m^1.5 is too stiff for that dt") != NULL);
    if (n_bad)
        printf("'%s'\n", e.msg);
    return n_bad;
}

/* every combination: no refusal names a dt-max not given, and every one fits
 * its line (no elision) */
static int c_matrix(void)
{
    const double dts[] = {0, 1e-9, 1e-13}, dtms[] = {0, 1e-9}, ks[] = {0, 1e30, 1e-30};
    int wrong = 0, cut = 0, n = 0;
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 2; b++)
            for (int c = 0; c < 3; c++)
                for (int d = 0; d < 3; d++) {
                    gw_chain_params p = test_chain_column(ks[c], ks[d]);
                    gw_chain_run_opts o = rk4(dts[a], dtms[b]);
                    gw_err e;
                    if (check_msg(&p, &o, &e) == GW_OK)
                        continue;
                    n++;
                    if (!(dtms[b] > 0) && strstr(e.msg, "dt-max")) {
                        wrong++;
                        printf("dt %g, dt_max %g, k %g, kwall %g: '%.200s'\n", dts[a], dtms[b], p.k, p.kwall, e.msg);
                    }
                    cut += strstr(e.msg, " ... ") != NULL;
                }
    CHECK(n == 43 && wrong == 0);
    CHECK(cut == 0);
    return n_bad;
}

static int c_controls(void)
{
    gw_err e;
    /* the dt alone, at the default k */
    gw_chain_params p = test_chain_column(0, 0);
    gw_chain_run_opts o = rk4(1e-13, 0);
    CHECK(check_msg(&p, &o, &e) == GW_EINVAL && strncmp(e.msg, "dt: a step of 1e-13 s needs about ", 34) == 0 &&
          !strstr(e.msg, "k:"));
    /* k alone, no dt: its range */
    p = test_chain_column(1e30, 0);
    o = rk4(0, 0);
    CHECK(check_msg(&p, &o, &e) == GW_EINVAL && strncmp(e.msg, "k: 1e+30 N/m^1.5 is outside [", 29) == 0);
    /* k 1e30 on a wall of 1e30 runs at dt 1e-13 (the contacts' quarter the step) */
    p = test_chain_column(1e30, 1e30);
    o = rk4(1e-13, 0);
    CHECK(check_msg(&p, &o, &e) == GW_OK);
    return n_bad;
}

static gw_chain_drop_params drop_of(int n)
{
    gw_chain_drop_params p = gw_chain_drop_params_default();
    p.chain.n = n;
    p.chain.sensor.mass = 1e-6;
    p.chain.sensor.stiffness = 1e5;
    return p;
}

static int c_drop_rerun(void)
{
    gw_chain_drop_params p = drop_of(3);
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.solver = gw_solver_rk4;
    gw_chain_drop_result r;
    gw_err e = {{0}};
    CHECK(gw_chain_drop_run(&p, &o, &r, &e) == GW_OK);
    /* 6.0e6 steps times 3 beads: run again (COSTLY before), every impact measured */
    CHECK(r.stats.steps > 5e6 && r.stats.steps * 3.0 > 1e7 && r.stats.steps * 3.0 <= GW_CHAIN_DROP_CHATTER_RK4_WORK);
    CHECK(r.chatter_kind != GW_CHAIN_CHATTER_COSTLY && r.chatter_kind != GW_CHAIN_CHATTER_FAILED);
    int measured = 0;
    for (int j = 0; j < r.n_impacts; j++)
        measured += isfinite(r.impacts[j].chatter);
    CHECK(r.n_impacts > 10 && measured == r.n_impacts);
    if (n_bad)
        printf("kind %d, steps %ld, %d of %d impacts measured\n", r.chatter_kind, r.stats.steps, measured,
               r.n_impacts);
    gw_chain_drop_result_free(&r);
    return n_bad;
}

#ifndef GW_TEST_BEFORE
static int c_tolerances(void)
{
    gw_chain_params p = test_chain_column(0, 0);
    gw_chain *c = NULL;
    gw_err e = {{0}};
    CHECK(gw_chain_create(&p, &c, &e) == GW_OK);
    const struct {
        const gw_solver_type *type;
        double rtol, atol, want_r, want_a;
    } runs[] = {{gw_solver_cvode, 0, 0, 1e-10, 1e-10}, /* the struct's default */
                {gw_solver_cvode, 1e-9, 1e-11, 1e-9, 1e-11},
                {gw_solver_arkode, 1e-8, 1e-10, 1e-8, 1e-10},
                {gw_solver_rk4, 0, 0, NAN, NAN}};
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        gw_chain_run_opts o = gw_chain_run_opts_default();
        o.solver = runs[i].type;
        if (runs[i].rtol > 0) {
            o.sp.rtol = runs[i].rtol;
            o.sp.atol = runs[i].atol;
        }
        gw_chain_result r;
        memset(&r, 0, sizeof r);
        CHECK(gw_chain_collide(c, &o, &r, &e) == GW_OK);
        if (isnan(runs[i].want_r))
            CHECK(isnan(r.run_rtol) && isnan(r.run_atol));
        else
            CHECK(r.run_rtol == runs[i].want_r && r.run_atol == runs[i].want_a);
        gw_chain_result_free(&r);
    }
    gw_chain_free(c);
    /* a drop's, in its first collision */
    gw_chain_drop_params d = drop_of(2);
    d.chain.sensor.mass = 0; /* a rigid sensor */
    d.chain.sensor.stiffness = 0;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.sp.rtol = 1e-10;
    o.sp.atol = 1e-13;
    gw_chain_drop_result r;
    CHECK(gw_chain_drop_run(&d, &o, &r, &e) == GW_OK);
    CHECK(r.first.run_rtol == 1e-10 && r.first.run_atol == 1e-13);
    gw_chain_drop_result_free(&r);
    return n_bad;
}
#endif

static const child_row rows[] = {
    {"rk4 dt 1e-13 with k 1e30: the dt and k named (was the dt-max's, not given); k up to the value said is the dt's "
     "alone; the run says the same",
     c_dt_and_k},
    {"rk4 dt 1e-13 with kwall 1e30: the dt and kwall named (was the default dt-out's)", c_dt_and_kwall},
    {"rk4 dt 1e-13, dt_max 1e-9, k 1e30: k named beside the dt and the dt-max given (the dt alone before)",
     c_dt_max_given},
    {"rk4 dt 1e-9, k 1e30 on kwall 1e-30: k named (was the dt-max's)", c_soft_wall},
    {"rk4 over 54 combinations (43 refused) of dt, dt_max, k, kwall: no dt-max named unless given; every line whole",
     c_matrix},
    {"controls: the dt alone and k alone as before; k and kwall 1e30 at dt 1e-13 pass", c_controls},
    {"rk4 drop of 3 beads on 1e-6 kg, 1e5 N/m: run again (was COSTLY above 1e7), every impact measured",
     c_drop_rerun},
#ifndef GW_TEST_BEFORE
    {"the run's rtol and atol: run_rtol, run_atol (cvode default and given, arkode, rk4 NaN, a drop's first)",
     c_tolerances},
#endif
};

int main(void)
{
    return child_cases_run(rows, sizeof rows / sizeof rows[0]);
}
