/*
 * test_library_hostile49.c: the forty-ninth hostile pass over the library's
 * C interface (docs/library.md "The contract of every call"): the solver
 * settings of a collision's run options, and the parameter tables' set calls
 * given NULL.
 *   - gw_chain_run_opts.sp.dt and sp.dt_max, whose 0 is the default as for
 *     dt_out or t_max, ran as that default when negative, NaN or -inf: rk4
 *     with a dt of -1, NaN or -inf, and every backend with a dt_max of -1 or
 *     NaN, gave GW_OK (gw_chain_collide, gw_chain_drop_run, the calibration's
 *     bead runs); cvode and arkode refused a dt of -1 at their create, after
 *     gw_chain_run_check had passed it. gw_chain_run_check, gw_chain_collide
 *     and gw_chain_drop_run now refuse each naming the member. Controls: 0
 *     (the default) and a finite dt run.
 *   - gw_param_set and gw_param_set_double given a NULL table said "unknown
 *     parameter 'n'", a NULL name "unknown parameter '(null)'", and
 *     gw_param_set_value a NULL row "(null): a result, not a parameter":
 *     each now names the call and the argument, as every other entry point.
 *   - gw_chain_params_validate took a subnormal v_imp, mass, k, kwall or
 *     radius (and masses[i], kc[i]) and a v_imp of 1e-160 m/s or below
 *     (steel), whose overlap scale underflows to 0: gw_chain_create then
 *     failed as "solver: scale[0] = 0 must be finite and > 0", naming no
 *     input. Each is refused naming the field. Control: v_imp 1e-150 and a
 *     mass of 1e-300 kg still run (the column is scale-free down there).
 *   - gw_sheet_law_name gave "?" for a value outside the enum, where the
 *     other enums' names say "unknown": "unknown" now.
 * Each case runs in its own child process (test_child.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "granwave.h"
#include "test_child.h"

/* ------------------------------------------ a collision's solver settings ---- */

/* The values a "0: default" step member must refuse. */
static const double bad_steps[] = {-1.0, NAN, -INFINITY};
#define N_BAD (sizeof bad_steps / sizeof bad_steps[0])

/* run options of backend name with member dt (which 0) or dt_max (1) set to v */
static gw_chain_run_opts opts_with(const char *name, int which, double v)
{
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.solver = gw_solver_type_find(name);
    if (which == 0)
        o.sp.dt = v;
    else
        o.sp.dt_max = v;
    return o;
}

static const char *const member[] = {"gw_chain_run_opts.sp.dt:", "gw_chain_run_opts.sp.dt_max:"};

/* every backend, both members, each bad value: run_check and collide refuse */
static int collide_steps(int which)
{
    const char *const backends[] = {"rk4", "cvode", "arkode"};
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    gw_chain *c = NULL;
    gw_err e = {0};
    EXPECT(gw_chain_create(&p, &c, &e) == GW_OK);
    for (size_t b = 0; b < 3; b++)
        for (size_t i = 0; i < N_BAD; i++) {
            gw_chain_run_opts o = opts_with(backends[b], which, bad_steps[i]);
            EXPECT(refused(gw_chain_run_check(&p, &o, &e), &e, member[which]));
            gw_chain_result r;
            memset(&r, 0, sizeof r);
            const int rc = gw_chain_collide(c, &o, &r, &e);
            gw_chain_result_free(&r);
            if (!refused(rc, &e, member[which])) {
                printf("%s %s = %g: status %d (%s)\n", backends[b], member[which], bad_steps[i], rc, e.msg);
                gw_chain_free(c);
                return 1;
            }
        }
    gw_chain_free(c);
    return 0;
}

static int c_collide_dt(void)
{
    return collide_steps(0);
}

static int c_collide_dt_max(void)
{
    return collide_steps(1);
}

static int c_drop_steps(void)
{
    for (int which = 0; which < 2; which++)
        for (size_t i = 0; i < N_BAD; i++) {
            gw_chain_drop_params p = gw_chain_drop_params_default();
            p.t_max = 1e-4;
            gw_chain_run_opts o = opts_with("rk4", which, bad_steps[i]);
            gw_chain_drop_result r;
            memset(&r, 0, sizeof r);
            gw_err e = {0};
            const int rc = gw_chain_drop_run(&p, &o, &r, &e);
            gw_chain_drop_result_free(&r);
            EXPECT(refused(rc, &e, member[which]));
        }
    return 0;
}

static int c_calibrate_dt(void) /* the bead runs of the calibration are collisions */
{
    gw_chain_params p = gw_chain_params_default();
    p.damping = GW_DAMP_HUNT_CROSSLEY;
    gw_chain_run_opts o = opts_with("rk4", 0, -1.0);
    double constant = -7;
    gw_err e = {0};
    EXPECT(refused(gw_chain_calibrate(&p, &o, 0.5, &constant, &e), &e, member[0]));
    return 0;
}

/* control: 0 (the defaults) and a finite dt run, rk4 at dt = T_c/400 as by default */
static int c_steps_control(void)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    gw_chain *c = NULL;
    gw_err e = {0};
    EXPECT(gw_chain_create(&p, &c, &e) == GW_OK);
    gw_chain_run_opts o = opts_with("rk4", 0, 0.0);
    gw_chain_result r0, r1;
    memset(&r0, 0, sizeof r0);
    memset(&r1, 0, sizeof r1);
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_OK);
    EXPECT(gw_chain_collide(c, &o, &r0, &e) == GW_OK);
    o.sp.dt = gw_chain_step_scale(&p) / 400.0;
    EXPECT(gw_chain_collide(c, &o, &r1, &e) == GW_OK);
    const double f0 = r0.f_max, f1 = r1.f_max;
    gw_chain_result_free(&r0);
    gw_chain_result_free(&r1);
    gw_chain_free(c);
    EXPECT(f0 > 60 && f0 < 75);          /* 3 steel beads at 0.3 m/s: about 68 N */
    EXPECT(fabs(f1 - f0) <= 1e-9 * f0); /* the default step given by hand */
    return 0;
}

/* ------------------------------------------------ the set calls given NULL ---- */

static int c_set_nulls(void)
{
    const gw_param *t = gw_chain_setup_params();
    gw_chain_setup s;
    EXPECT(gw_chain_setup_init(&s) == GW_OK);
    gw_err e = {0};
    EXPECT(refused(gw_param_set(NULL, &s, "n", "3", &e), &e, "gw_param_set: table is NULL"));
    EXPECT(refused(gw_param_set(t, &s, NULL, "3", &e), &e, "gw_param_set: name is NULL"));
    EXPECT(refused(gw_param_set_double(NULL, &s, "vimp", 0.3, &e), &e, "gw_param_set_double: table is NULL"));
    EXPECT(refused(gw_param_set_double(t, &s, NULL, 0.3, &e), &e, "gw_param_set_double: name is NULL"));
    EXPECT(refused(gw_param_set_value(NULL, &s.n, "3", &e), &e, "gw_param_set_value: p is NULL"));
    EXPECT(s.n == 1); /* nothing written */
    /* control: an unknown name is still said so, a known one set */
    EXPECT(refused(gw_param_set(t, &s, "bogus", "3", &e), &e, "unknown parameter 'bogus'"));
    EXPECT(gw_param_set(t, &s, "n", "3", &e) == GW_OK && s.n == 3);
    gw_chain_setup_clear(&s);
    return 0;
}

/* ------------------------------------ a column's scales below the doubles ---- */

static int c_model_subnormal(void)
{
    const double sub = 4.9e-324;
    const struct {
        const char *name;
        size_t off;
    } f[] = {{"v_imp", offsetof(gw_chain_params, v_imp)}, {"mass", offsetof(gw_chain_params, mass)},
             {"k (", offsetof(gw_chain_params, k)},         {"kwall", offsetof(gw_chain_params, kwall)},
             {"radius", offsetof(gw_chain_params, radius)}};
    gw_err e = {0};
    for (size_t i = 0; i < sizeof f / sizeof f[0]; i++) {
        gw_chain_params p = gw_chain_params_default();
        p.n = 2;
        *(double *)((char *)&p + f[i].off) = sub;
        gw_chain *c = NULL;
        const int rc = gw_chain_create(&p, &c, &e);
        gw_chain_free(c);
        if (!refused(rc, &e, f[i].name) || !strstr(e.msg, "subnormal")) {
            printf("%s subnormal: status %d (%s)\n", f[i].name, rc, e.msg);
            return 1;
        }
    }
    double masses[2] = {1e-3, sub}, kc[1] = {sub};
    gw_chain_params p = gw_chain_params_default();
    p.n = 2;
    p.masses = masses;
    EXPECT(refused(gw_chain_params_validate(&p, &e), &e, "masses[1]") && strstr(e.msg, "subnormal"));
    p.masses = NULL;
    p.kc = kc;
    EXPECT(refused(gw_chain_params_validate(&p, &e), &e, "kc[0]") && strstr(e.msg, "subnormal"));
    return 0;
}

/* run a 3-bead steel column at v_imp with mass m (0: the default); GW_OK and f_max, or the status */
static int column_at(double v_imp, double m, double *f_max, gw_err *e)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    p.v_imp = v_imp;
    if (m > 0)
        p.mass = m;
    gw_chain *c = NULL;
    int rc = gw_chain_create(&p, &c, e);
    gw_chain_result r;
    memset(&r, 0, sizeof r);
    gw_chain_run_opts o = gw_chain_run_opts_default();
    if (rc == GW_OK)
        rc = gw_chain_collide(c, &o, &r, e);
    *f_max = r.f_max;
    gw_chain_result_free(&r);
    gw_chain_free(c);
    return rc;
}

static int c_vimp_underflow(void)
{
    gw_err e = {0};
    double f;
    EXPECT(refused(column_at(1e-160, 0, &f, &e), &e, "v_imp (impact velocity, m/s): 1e-160"));
    EXPECT(strstr(e.msg, "overlap scale of 0 m") != NULL);
    EXPECT(refused(column_at(1e-300, 0, &f, &e), &e, "v_imp (impact velocity, m/s): 1e-300"));
    return 0;
}

/* control: F_max of a Hertz column scales as v^(6/5) (F.13): from 0.3 m/s to
 * 1e-150 m/s and at a mass of 1e-300 kg (F ~ m^(3/5)) the runs hold it */
static int c_scale_free_control(void)
{
    gw_err e = {0};
    double f0, f1, f2;
    EXPECT(column_at(0.3, 0, &f0, &e) == GW_OK);
    EXPECT(column_at(1e-150, 0, &f1, &e) == GW_OK);
    EXPECT(fabs(f1 / (f0 * pow(1e-150 / 0.3, 1.2)) - 1) < 1e-3);
    const double m = gw_chain_params_default().mass;
    EXPECT(column_at(0.3, 1e-300, &f2, &e) == GW_OK);
    EXPECT(fabs(f2 / (f0 * pow(1e-300 / m, 0.6)) - 1) < 1e-3);
    return 0;
}

/* ------------------------------------------------ a sheet law's name ---- */

static int c_sheet_law_name(void)
{
    EXPECT(strcmp(gw_sheet_law_name((gw_sheet_law)-1), "unknown") == 0);
    EXPECT(strcmp(gw_sheet_law_name((gw_sheet_law)4), "unknown") == 0);
    EXPECT(strcmp(gw_solver_method_name(-1), "unknown") == 0); /* the other enums' word */
    EXPECT(strcmp(gw_sheet_law_name(GW_SHEET_MATERIAL), "material") == 0); /* control */
    return 0;
}

static const child_row rows[] = {
    {"collide: sp.dt -1, NaN, -inf refused (rk4, cvode, arkode)", c_collide_dt},
    {"collide: sp.dt_max -1, NaN, -inf refused (rk4, cvode, arkode)", c_collide_dt_max},
    {"drop: sp.dt and sp.dt_max -1, NaN, -inf refused", c_drop_steps},
    {"calibrate: an rk4 dt of -1 refused", c_calibrate_dt},
    {"collide: dt 0 and dt given run (control)", c_steps_control},
    {"param set calls: a NULL table, name or row named", c_set_nulls},
    {"chain params: subnormal v_imp, mass, k, kwall, radius, masses[i], kc[i]", c_model_subnormal},
    {"chain params: v_imp 1e-160 and 1e-300 (overlap scale 0) named", c_vimp_underflow},
    {"sheet law name outside the enum: unknown (as the other enums)", c_sheet_law_name},
    {"chain: v_imp 1e-150 and mass 1e-300 run, F_max as v^1.2 and m^0.6 (control)", c_scale_free_control},
};

int main(void)
{
    return child_cases_run(rows, sizeof rows / sizeof rows[0]);
}
