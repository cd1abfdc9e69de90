/*
 * test_library_hostile50.c: the fiftieth hostile pass over the library's C
 * interface (docs/library.md "The contract of every call"): every number of
 * the column's, the run options', the dispersion's, the layer's, the impact's
 * and the pluviation's parameter structs set in turn to NaN, +-inf, -1, -0, a
 * subnormal, 1e-200, 1e200 and DBL_MAX (every int member to -1, INT_MIN,
 * INT_MAX, 2 and 3), each checked and run. What it found, each checked here:
 *   - gw_chain_params_validate passed columns whose scales are no doubles:
 *     v_imp 1e200 m/s failed at the run as "solver: scale[0] = inf", a mass of
 *     1.8e308 kg as "solver: dt_max must be >= 0, got inf", k = 1.8e308 was
 *     refused as "dt-max: a step of 0 s ... fewer beads" (tau_1's 4 K
 *     overflowed to inf); 1000 beads of 1e306 kg carry an energy of inf J.
 *     The closed forms tau_1 and d_max no longer overflow where their value
 *     is a double, and the column's overlap, energy, force, T_c and step
 *     scales must each be a normal double, else GW_EINVAL naming v_imp, mass,
 *     k, kwall. Control: a mass of 1.8e308 kg runs, F_max as m^(3/5).
 *   - k = 1.8e308 N/m^1.5 with the default kwall (left after session 43) was
 *     still refused as "dt-max: a step of 2.86e-125 s needs about 1.22e+120
 *     steps ... fewer beads or a shorter run": now named k, with the range
 *     of k within the steps' bound (its top end passes, 10 % above it is
 *     refused), by the check and the run, under cvode and rk4.
 *   - the run options took subnormals: t_max 4.9e-324 s "blew up" under
 *     cvode and arkode ("lower dt-max, rtol or atol"), steps_per_tc 4.9e-324
 *     made rk4's step inf ("solver: dt must be >= 0, got inf"); and
 *     gw_chain_run_check passed rtol NaN and atol -1, refused only when the
 *     run started. Each refused by the check naming the member; t_max 1e-200
 *     passes (control).
 *   - a first step sp.dt of 1.8e308 s failed every cvode and arkode run at
 *     its first output ("Trouble interpolating at tout ... too far back"): a
 *     first step above dt_max is now dt_max; F_max is the default run's.
 *   - a subnormal yield pressure (4.9e-324 Pa) ran as a wall of no strength,
 *     a subnormal sensor mass was refused naming the sensor's stiffness; the
 *     range-checked members (gravity, damping constants, wall, sensor, guide)
 *     refuse a subnormal naming it, 0 passes.
 *   - gw_layer_impact with sp.dt NaN, -1 or -inf (verlet) ran as the
 *     automatic step with GW_OK, and dt_max NaN and rtol NaN failed only at
 *     the solver's set-up after the layer was built; a verlet dt above dt-out
 *     was told "a dt that divides it such as -inf s": gw_layer_impact_step_check
 *     refuses each naming it and named dt-out itself as a divisor (since
 *     session 46 such a step runs: the samples are read between the steps;
 *     since session 48 up to GW_LAYER_DT_MAX, 1 s, the bound of the
 *     program's --dt: a verlet dt of 1e200 s passed the library).
 *   - yes/no members other than 0 and 1 ran as 1 with GW_OK: the impact's
 *     full, remove_walls, other_settling, zero_springs, the layer's no_events
 *     and potential_from_start, the pluviation's clumps, the dispersion's
 *     fftw_measure: each refused naming it.
 *   - the impact took any rb-rm > 0 (1e-310 failed at the solver's set-up as
 *     "scale[245] = inf", 1e-200 ran a block of 3e-201 m): held to its row's
 *     [1e-6, 1e6].
 *   - gw_layer_make took rm 1e-200 m ("give dt -nan or less"), 1e200 m
 *     ("solver: scale[120] = inf"), a width-rm of 1e200 (refused after the
 *     settling as a sample wider than 1e6 R_m) and a height-rm of NaN, -1 or
 *     inf (the whole pile kept, as 0), a ke-threshold of 1e200 or 4.9e-324
 *     and a t-max of 4.9e-324 s (run, unsettled): each refused before any
 *     work, naming it, as the make table's rows do.
 *   - gw_chain_disp_params_validate passed f0 4.9e-324 N (the overlap d0 0 m:
 *     "solver: scale[0] = 0") and a subnormal dt_sample (rk4's step 0: "rk4:
 *     the fixed step dt must be set"): each refused naming it.
 *   - gw_solver_params.use_jac took any int as 1 (-1, 2, INT_MIN ran with
 *     GW_OK): gw_chain_run_check and the solver's create refuse it naming
 *     use_jac (the forty-third session, after the pass); 0 and 1 agree.
 * Each case runs in its own child process (test_child.h); the refusal
 * naming k, the run's status and F_max are gw_test_cases.h's (shared with
 * test_stiffness_named).
 */
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "granwave.h"
#include "gw_test_cases.h"
#include "layer_test_util.h"
#include "test_child.h"

/* ------------------------------------------------------ the column's scales ---- */

static int c_chain_scales(void)
{
    gw_err e = {0};
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    p.v_imp = 1e200;
    EXPECT(refused(gw_chain_params_validate(&p, &e), &e, "v_imp, mass, k, kwall"));
    EXPECT(strstr(e.msg, "kinetic energy is inf J") != NULL);
    /* 1000 beads of 1e306 kg at 1 m/s: each 5e305 J, their sum inf */
    p = gw_chain_params_default();
    p.n = 1000;
    p.mass = 1e306;
    p.v_imp = 1;
    EXPECT(refused(gw_chain_params_validate(&p, &e), &e, "kinetic energy is inf J"));
    return 0;
}

static int c_closed_forms_overflow(void)
{
    /* tau_1 = 2.94 (5 m / 4 K)^(2/5) v^(-1/5) and d_max = (5 m v^2 / 4 K)^(2/5),
     * where 4 K or v^2 is beyond the doubles and the value is not */
    const double c = gw_chain_tau1(1, 1, 1) / pow(1.25, 0.4);
    const double t = gw_chain_tau1(1, DBL_MAX, 1), want_t = c * pow(1.25 / DBL_MAX, 0.4);
    EXPECT(t > 0 && fabs(t / want_t - 1) < 1e-12);
    const double d = gw_chain_dmax1(2e-3, 1e10, 1e200), want_d = pow(1.25 * 2e-3 / 1e10, 0.4) * pow(1e200, 0.8);
    EXPECT(isfinite(d) && fabs(d / want_d - 1) < 1e-12);
    /* controls: ordinary values as before, a rigid wall's 0, v = 0's 0 */
    EXPECT(gw_chain_dmax1(2e-3, 1e10, 0.3) == pow(5.0 * 2e-3 * 0.3 * 0.3 / (4.0 * 1e10), 0.4));
    EXPECT(gw_chain_tau1(2e-3, INFINITY, 0.3) == 0 && gw_chain_dmax1(2e-3, 1e10, 0) == 0);
    return 0;
}

/* F_max of a 3-bead steel column of bead mass m (0: the default), or -1 */
static double column_fmax(double m, gw_chain_run_opts o)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    if (m > 0)
        p.mass = m;
    return test_chain_fmax(&p, &o);
}

/* control: a mass of 1.8e308 kg runs (the column is scale-free), F ~ m^(3/5) */
static int c_heavy_control(void)
{
    const gw_chain_run_opts o = gw_chain_run_opts_default();
    const double f0 = column_fmax(0, o), f1 = column_fmax(DBL_MAX, o);
    const double m0 = gw_chain_params_default().mass;
    EXPECT(f0 > 60 && f1 > 0);
    EXPECT(fabs(f1 / (f0 * (pow(DBL_MAX, 0.6) / pow(m0, 0.6))) - 1) < 1e-6);
    return 0;
}

/* k = 1.8e308 N/m^1.5 with the default kwall (left after session 43): refused
 * as "dt-max: a step of 2.86e-125 s needs about 1.22e+120 steps ... fewer
 * beads or a shorter run", the step derived from k; now named k with the
 * range within the steps' bound, whose top end runs the check and 10 % above
 * it does not. Controls: k and kwall both 1e200 pass (the column is
 * scale-free); a step given is still the step's refusal; a wall of kwall
 * 1.8e308, whose contact is the shortest, is not put on k (it was told to
 * take k above 3.9e290 before k's cause was checked). */
static int c_k_huge_named(void)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    p.k = DBL_MAX;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    double hi = 0;
    EXPECT(test_stiffness_refused(&p, &o, "k", &hi) && hi < 1e40 && hi > p.kwall);
    /* the run itself refuses it the same way (the chain's own kc, each k) */
    gw_err e = {0};
    const int rc = test_chain_run_status(&p, &o, &e);
    EXPECT(refused(rc, &e, "k: 1.79769e+308 N/m^1.5 is outside ["));
    /* the range's top end runs the check, 10 % above it is refused naming k */
    p.k = hi;
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_OK);
    p.k = 1.1 * hi;
    double hi2 = 0;
    EXPECT(test_stiffness_refused(&p, &o, "k", &hi2) && hi2 == hi);
    /* rk4's own step as well */
    p.k = DBL_MAX;
    o.solver = gw_solver_rk4;
    EXPECT(test_stiffness_refused(&p, &o, "k", &hi2));
    /* controls: k and kwall both 1e200 pass; a dt_max given is its own refusal */
    o = gw_chain_run_opts_default();
    p.k = p.kwall = 1e200;
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_OK);
    p = gw_chain_params_default();
    p.n = 3;
    o.sp.dt_max = 1e-15;
    EXPECT(refused(gw_chain_run_check(&p, &o, &e), &e, "dt-max: a step of 1e-15 s"));
    /* and a wall of kwall 1.8e308 (its contact the shortest) does not blame k:
     * kwall is named (session 45; "dt-max: a step of" before, test_stiffness_named) */
    o = gw_chain_run_opts_default();
    o.dt_out = 1e-6;
    p.kwall = DBL_MAX;
    EXPECT(refused(gw_chain_run_check(&p, &o, &e), &e, "kwall: ") && strncmp(e.msg, "k: ", 3) != 0);
    return 0;
}

/* ------------------------------------------------------ the run options ---- */

static int c_opts_subnormal(void)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    gw_err e = {0};
    const char *const backends[] = {"cvode", "arkode", "rk4"};
    for (int b = 0; b < 3; b++) {
        gw_chain_run_opts o = gw_chain_run_opts_default();
        o.solver = gw_solver_type_find(backends[b]);
        o.t_max = 4.9e-324;
        EXPECT(refused(gw_chain_run_check(&p, &o, &e), &e, "gw_chain_run_opts.t_max") && strstr(e.msg, "subnormal"));
        o.t_max = 0;
        o.steps_per_tc = 4.9e-324;
        EXPECT(refused(gw_chain_run_check(&p, &o, &e), &e, "gw_chain_run_opts.steps_per_tc"));
        o.steps_per_tc = 0;
        o.sp.rtol = NAN;
        EXPECT(refused(gw_chain_run_check(&p, &o, &e), &e, "gw_chain_run_opts.sp.rtol"));
        o.sp.rtol = 1e-10;
        o.sp.atol = -1;
        EXPECT(refused(gw_chain_run_check(&p, &o, &e), &e, "gw_chain_run_opts.sp.atol"));
    }
    /* the run itself refuses it too (it failed with "blew up" under cvode) */
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.t_max = 1e-310;
    const int rc = test_chain_run_status(&p, &o, &e);
    EXPECT(refused(rc, &e, "gw_chain_run_opts.t_max"));
    /* control: a normal t_max however small passes the check */
    o.t_max = 1e-200;
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_OK);
    return 0;
}

static int c_first_step_huge(void)
{
    const double f0 = column_fmax(0, gw_chain_run_opts_default());
    const char *const backends[] = {"cvode", "arkode"};
    for (int b = 0; b < 2; b++) {
        gw_chain_run_opts o = gw_chain_run_opts_default();
        o.solver = gw_solver_type_find(backends[b]);
        o.sp.dt = DBL_MAX;
        const double f = column_fmax(0, o);
        EXPECT(f > 0 && fabs(f - f0) < 1e-6 * f0);
    }
    return 0;
}

/* sp.use_jac other than 0 and 1 ran as 1 with GW_OK (-1, 2, INT_MIN): refused
 * by gw_chain_run_check and the run naming it; 0 and 1 run alike (control) */
static int c_use_jac(void)
{
    const int bad[] = {-1, 2, INT_MIN};
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    for (int i = 0; i < 3; i++) {
        gw_chain_run_opts o = gw_chain_run_opts_default();
        o.solver = gw_solver_cvode;
        o.sp.use_jac = bad[i];
        gw_err e = {0};
        EXPECT(gw_chain_run_check(&p, &o, &e) == GW_EINVAL && strstr(e.msg, "use_jac"));
        /* the run refuses it too */
        EXPECT(test_chain_run_status(&p, &o, &e) == GW_EINVAL && strstr(e.msg, "use_jac"));
    }
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.solver = gw_solver_cvode;
    const double f1 = column_fmax(0, o);
    o.sp.use_jac = 0;
    const double f0 = column_fmax(0, o);
    EXPECT(f1 > 0 && fabs(f0 - f1) < 1e-6 * f1);
    return 0;
}

static int c_chain_subnormal_ranges(void)
{
    const double sub = 4.9e-324;
    gw_err e = {0};
    const char *const names[] = {"wall yield_pressure", "sensor mass", "guide coulomb", "gravity", "gamma"};
    for (int i = 0; i < 5; i++) {
        gw_chain_params p = gw_chain_params_default();
        p.n = 2;
        switch (i) {
        case 0:
            p.wall.yield_pressure = sub;
            break;
        case 1:
            p.sensor.mass = sub;
            p.sensor.stiffness = 1e7;
            break;
        case 2:
            p.guide.coulomb = sub;
            break;
        case 3:
            p.gravity = -sub;
            break;
        default:
            p.damping = GW_DAMP_KUWABARA_KONO;
            p.gamma = sub;
        }
        const int rc = gw_chain_params_validate(&p, &e);
        if (!refused(rc, &e, names[i]) || !strstr(e.msg, "subnormal")) {
            printf("%s subnormal: %d %s\n", names[i], rc, e.msg);
            return 1;
        }
    }
    /* control: each 0 (off) passes */
    gw_chain_params p = gw_chain_params_default();
    p.damping = GW_DAMP_KUWABARA_KONO;
    EXPECT(gw_chain_params_validate(&p, &e) == GW_OK);
    return 0;
}

/* ------------------------------------------------------ the layer impact ---- */

static int c_layer_steps(void)
{
    const gw_layer_impact_params ip = gw_layer_impact_params_default();
    gw_err e = {0};
    const double bad[] = {NAN, -1, -INFINITY, INFINITY, 1e-310};
    for (int i = 0; i < 5; i++) {
        gw_solver_params sp = gw_solver_params_default();
        sp.dt = bad[i];
        EXPECT(refused(gw_layer_impact_step_check(&ip, gw_solver_verlet, &sp, &e), &e, "dt: "));
        sp = gw_solver_params_default();
        sp.dt_max = bad[i];
        EXPECT(refused(gw_layer_impact_step_check(&ip, gw_solver_verlet, &sp, &e), &e, "dt-max: "));
    }
    gw_solver_params sp = gw_solver_params_default();
    sp.rtol = NAN;
    EXPECT(refused(gw_layer_impact_step_check(&ip, gw_solver_verlet, &sp, &e), &e, "rtol: nan"));
    /* a step given that dt-out is not a multiple of (verlet 3e-6 s), or above
     * dt-out (rk4 1e-4 s): refused until session 46, run now (the samples off
     * the steps read between them: test_dt_out_bitwise) */
    sp = gw_solver_params_default();
    sp.dt = 3e-6;
    EXPECT(gw_layer_impact_step_check(&ip, gw_solver_verlet, &sp, &e) == GW_OK);
    sp.dt = 1e-4;
    EXPECT(gw_layer_impact_step_check(&ip, gw_solver_rk4, &sp, &e) == GW_OK);
    /* a step above GW_LAYER_DT_MAX (1 s, layer-impact --dt's bound): 1e200 s
     * was told "such as -inf s", then "such as 2e-05 s", and passed from
     * session 46 to 48, as did 2 s, which the program refused; 1 s passes
     * (control), under verlet and rk4 */
    const gw_solver_type *const fixed[] = {gw_solver_verlet, gw_solver_rk4};
    for (int k = 0; k < 2; k++) {
        sp = gw_solver_params_default();
        sp.dt = 1e200;
        EXPECT(refused(gw_layer_impact_step_check(&ip, fixed[k], &sp, &e), &e, "dt: 1e+200 s is above 1 s"));
        sp.dt = 2;
        EXPECT(refused(gw_layer_impact_step_check(&ip, fixed[k], &sp, &e), &e, "dt: 2 s is above 1 s"));
        sp.dt = GW_LAYER_DT_MAX;
        EXPECT(gw_layer_impact_step_check(&ip, fixed[k], &sp, &e) == GW_OK);
    }
    /* controls: the automatic step and a step that divides dt-out */
    sp = gw_solver_params_default();
    EXPECT(gw_layer_impact_step_check(&ip, gw_solver_verlet, &sp, &e) == GW_OK);
    sp.dt = 1e-5;
    EXPECT(gw_layer_impact_step_check(&ip, gw_solver_verlet, &sp, &e) == GW_OK);
    return 0;
}

/* the whole run with a verlet dt of NaN: refused, where it ran as the automatic step */
static int c_layer_impact_dt_nan(void)
{
    gw_layer_sample s = test_three_discs();
    gw_layer_params lp = gw_layer_params_default();
    lp.width = s.width;
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.t_max = 1e-3;
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = NAN;
    gw_layer_impact_result r;
    memset(&r, 0, sizeof r);
    gw_err e = {0};
    const int rc = gw_layer_impact(&s, &lp, &ip, gw_solver_verlet, &sp, &r, &e);
    gw_layer_impact_result_free(&r);
    EXPECT(refused(rc, &e, "dt: nan"));
    return 0;
}

static int c_layer_flags(void)
{
    gw_layer_sample s = test_three_discs();
    gw_err e = {0};
    const char *const names[] = {"full", "remove-walls", "other-settling", "zero-springs"};
    for (int i = 0; i < 4; i++)
        for (int v = -1; v <= 2; v += 3) {
            gw_layer_impact_params ip = gw_layer_impact_params_default();
            int *f[] = {&ip.full, &ip.remove_walls, &ip.other_settling, &ip.zero_springs};
            *f[i] = v;
            EXPECT(refused(gw_layer_impact_check(&s, &ip, &e), &e, names[i]) && strstr(e.msg, "not a flag"));
        }
    gw_layer_params lp = gw_layer_params_default();
    lp.no_events = 2;
    EXPECT(refused(gw_layer_params_validate(&lp, &e), &e, "no_events"));
    lp = gw_layer_params_default();
    lp.potential_from_start = -1;
    EXPECT(refused(gw_layer_params_validate(&lp, &e), &e, "potential_from_start"));
    /* controls: 0 and 1 pass */
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.full = ip.remove_walls = ip.zero_springs = 1;
    EXPECT(gw_layer_impact_check(&s, &ip, &e) == GW_OK);
    lp = gw_layer_params_default();
    lp.no_events = lp.potential_from_start = 1;
    EXPECT(gw_layer_params_validate(&lp, &e) == GW_OK);
    return 0;
}

static int c_layer_rb_rm(void)
{
    gw_layer_sample s = test_three_discs();
    gw_err e = {0};
    const double bad[] = {1e-310, 1e-200, 1e-7, 1e200};
    for (int i = 0; i < 4; i++) {
        gw_layer_impact_params ip = gw_layer_impact_params_default();
        ip.rb_rm = bad[i];
        EXPECT(refused(gw_layer_impact_check(&s, &ip, &e), &e, "rb-rm"));
    }
    gw_layer_impact_params ip = gw_layer_impact_params_default(); /* control: the row's ends */
    ip.rb_rm = 1e-6;
    EXPECT(gw_layer_impact_check(&s, &ip, &e) == GW_OK);
    return 0;
}

/* ------------------------------------------------------ the pluviation ---- */

static int c_layer_make_ranges(void)
{
    const gw_layer_params lp = gw_layer_params_default();
    const char *const names[] = {"rm",     "rm",     "width-rm",     "height-rm",    "height-rm",
                                 "height-rm", "clumps", "ke-threshold", "ke-threshold", "t-max"};
    for (int i = 0; i < 10; i++) {
        gw_layer_make_params mp = gw_layer_make_params_default();
        mp.n = 10;
        mp.width_rm = 8;
        mp.t_max = 0.05;
        switch (i) {
        case 0:
            mp.rm = 1e-200;
            break;
        case 1:
            mp.rm = 1e200;
            break;
        case 2:
            mp.width_rm = 1e200;
            break;
        case 3:
            mp.height_rm = NAN;
            break;
        case 4:
            mp.height_rm = -1;
            break;
        case 5:
            mp.height_rm = INFINITY;
            break;
        case 6:
            mp.clumps = 2;
            break;
        case 7:
            mp.ke_threshold = 1e200;
            break;
        case 8:
            mp.ke_threshold = 4.9e-324;
            break;
        default:
            mp.t_max = 4.9e-324;
        }
        gw_layer_sample s;
        gw_layer_make_result r;
        memset(&r, 0, sizeof r);
        gw_err e = {0};
        const int rc = gw_layer_make(&lp, &mp, &s, &r, &e);
        gw_layer_sample_free(&s);
        if (!refused(rc, &e, names[i]) || r.steps != 0) {
            printf("case %d: %d steps\n", i, (int)r.steps);
            return 1;
        }
    }
    /* control: the small pile settles for its 0.05 s */
    gw_layer_make_params mp = gw_layer_make_params_default();
    mp.n = 10;
    mp.width_rm = 8;
    mp.t_max = 0.05;
    gw_layer_sample s;
    gw_layer_make_result r;
    gw_err e = {0};
    EXPECT(gw_layer_make(&lp, &mp, &s, &r, &e) == GW_OK && s.n == 10);
    gw_layer_sample_free(&s);
    return 0;
}

/* ------------------------------------------------------ the dispersion ---- */

static int c_dispersion(void)
{
    gw_err e = {0};
    gw_chain_disp_params p = gw_chain_disp_params_default();
    p.f0 = 4.9e-324;
    EXPECT(refused(gw_chain_disp_params_validate(&p, &e), &e, "f0: 4.94066e-324 N"));
    p = gw_chain_disp_params_default();
    p.dt_sample = 1e-310;
    EXPECT(refused(gw_chain_disp_params_validate(&p, &e), &e, "dt-out: 1e-310") && strstr(e.msg, "subnormal"));
    p = gw_chain_disp_params_default();
    p.fftw_measure = 2;
    EXPECT(refused(gw_chain_disp_params_validate(&p, &e), &e, "fftw_measure"));
    p = gw_chain_disp_params_default(); /* control */
    p.fftw_measure = 1;
    EXPECT(gw_chain_disp_params_validate(&p, &e) == GW_OK);
    return 0;
}

static const child_row rows[] = {
    {"chain: v_imp 1e200 and 1000 beads of 1e306 kg named (energy inf)", c_chain_scales},
    {"closed forms: tau_1 at K = 1.8e308 and d_max at v = 1e200 are their values", c_closed_forms_overflow},
    {"chain: a mass of 1.8e308 kg runs, F_max as m^0.6 (control)", c_heavy_control},
    {"chain: k = 1.8e308 with the default kwall named k with its range (was dt-max)", c_k_huge_named},
    {"run options: subnormal t_max and steps_per_tc, rtol NaN, atol -1 refused by the check", c_opts_subnormal},
    {"cvode, arkode: a first step of 1.8e308 s runs as the default", c_first_step_huge},
    {"solver: sp.use_jac -1, 2, INT_MIN refused by the check and the run; 0 and 1 agree", c_use_jac},
    {"chain params: subnormal yield pressure, sensor mass, guide, gravity, gamma", c_chain_subnormal_ranges},
    {"layer step check: dt, dt_max NaN/-1/-inf/inf/subnormal, rtol NaN, dt 2 and 1e200; any dt-out passes",
     c_layer_steps},
    {"layer impact: a verlet dt of NaN refused (ran as the automatic step)", c_layer_impact_dt_nan},
    {"layer: yes/no members other than 0 and 1 refused", c_layer_flags},
    {"layer impact: rb-rm outside [1e-6, 1e6] refused", c_layer_rb_rm},
    {"layer make: rm, width-rm, height-rm, clumps, ke-threshold, t-max outside their rows refused", c_layer_make_ranges},
    {"dispersion: f0 of a subnormal d0, a subnormal dt-out, fftw_measure 2", c_dispersion},
};

int main(void)
{
    return child_cases_run(rows, sizeof rows / sizeof rows[0]);
}
