/*
 * test_library_chain_silent.c: silent wrong answers and late refusals of the
 * column (chain) through the library, left for the forty-eighth session:
 *   - gw_chain_wall_force of a state whose overlap is NaN returned 0 N, the
 *     open contact's value (`!(x > 0)`), and so did
 *     gw_chain_wall_contact_force under every general wall (plastic,
 *     viscoelastic, damped, on a sensor body), and gw_chain_energy_of its
 *     elastic energy 0 J: NaN now, the open contact's 0 kept for a real
 *     open state (control).
 *   - gw_chain_run_check passed v_imp inf (and NaN, a mass inf) that
 *     gw_chain_create refuses: the column is checked first, naming the field.
 *   - gw_chain_drop_result_warnings of a hand result whose chatter_rerun is
 *     none of GW_CHAIN_RERUN_* (99, INT_MIN, -1, 3) worded the rerun with the
 *     tolerances' rule ("compare a run at 10 times tighter --rtol and
 *     --atol"): it says the value is invalid.
 *   - rk4 with a dt given on a wall too soft (kwall 1e-30, bead 1 overlapping
 *     it by 3.6e10 m): "dt: ... raise it", which cannot help (rk4's step is at
 *     most a quarter of the bead contact, still 5e16 steps); with dt 1e-15
 *     and k 1e30 too, kwall was not named. kwall is named now, with its
 *     range; a dt that raising cannot help alone is said so; a dt that it can
 *     keeps "raise it" (control).
 * Each case runs in its own child process (test_child.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "granwave.h"
#include "gw_test_cases.h"
#include "test_child.h"

/* ------------------------------------------------ a NaN state's force ---- */

enum { W_HERTZ, W_KK, W_PLASTIC, W_LOSS, W_SENSOR, W_N };
static const char *const wall_name[W_N] = {"hertz", "kk damping", "plastic", "viscoelastic", "sensor body"};

static gw_chain *column(int kind)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    if (kind == W_KK) {
        p.damping = GW_DAMP_KUWABARA_KONO;
        p.gamma = 1e3;
    } else if (kind == W_PLASTIC) {
        p.wall.yield_pressure = 1e9;
    } else if (kind == W_LOSS) {
        p.wall.loss = 0.1;
    } else if (kind == W_SENSOR) {
        p.sensor.mass = 1e-3;
        p.sensor.stiffness = 1e9;
    }
    gw_chain *c = NULL;
    gw_err e = {{0}};
    if (gw_chain_create(&p, &c, &e) != GW_OK) {
        printf("%s: %s\n", wall_name[kind], e.msg);
        return NULL;
    }
    return c;
}

/* The forces and energies of the column of KIND (column()) at its initial
 * state with bead 1's overlap X0 and, where SET_V1, its rate V1: all NaN wanted (the sensor
 * force only where the wall is not the sensor's, which X0 does not reach).
 * The faults said, counted. */
static int nan_said(int kind, double x0, int set_v1, double v1, const char *what)
{
    gw_chain *c = column(kind);
    if (!c)
        return 1;
    const long dim = gw_chain_system(c)->dim;
    double *y = calloc((size_t)dim, sizeof *y);
    if (!y) {
        gw_chain_free(c);
        return 1;
    }
    gw_chain_initial_state(c, y);
    y[0] = x0;
    if (set_v1)
        y[1] = v1;
    gw_chain_energy en;
    gw_chain_energy_of(c, y, &en);
    const double f = gw_chain_wall_contact_force(c, y), fs = gw_chain_wall_force(c, y);
    int bad = 0;
    if (!isnan(f) || !isnan(en.total) || !isnan(en.elastic) || (kind != W_SENSOR && !isnan(fs))) {
        printf("%s, %s: contact force %g, sensor force %g, energy %g, elastic %g (NaN wanted)\n", wall_name[kind],
               what, f, fs, en.total, en.elastic);
        bad = 1;
    }
    free(y);
    gw_chain_free(c);
    return bad;
}

/* bead 1's overlap NaN (and, where it has one, the sensor's position
 * with it): the contact force and the energies NaN under every wall */
static int c_nan_overlap(void)
{
    int bad = 0;
    for (int kind = 0; kind < W_N; kind++)
        bad += nan_said(kind, NAN, 0, 0.0, "overlap NaN");
    return bad;
}

/* the overlap closed and its rate NaN: NaN */
static int c_nan_rate(void)
{
    int bad = 0;
    for (int kind = 0; kind < W_N; kind++)
        bad += nan_said(kind, 1e-7, 1, NAN, "v_1 NaN");
    return bad;
}

/* control: an open contact is 0 N, a closed one kwall x^(3/2) */
static int c_open_closed_control(void)
{
    for (int kind = 0; kind < W_N; kind++) {
        gw_chain *c = column(kind);
        EXPECT(c);
        const long dim = gw_chain_system(c)->dim;
        double *y = calloc((size_t)dim, sizeof *y);
        EXPECT(y);
        gw_chain_initial_state(c, y);
        for (int i = 0; i < 3; i++) /* every bead 1 um off the wall, no contact closed */
            y[2 * i] = -1e-6 * (i + 1);
        EXPECT(gw_chain_wall_contact_force(c, y) == 0.0);
        gw_chain_energy en;
        gw_chain_energy_of(c, y, &en);
        EXPECT(isfinite(en.total) && en.elastic == 0.0);
        if (kind == W_HERTZ) {
            y[0] = 1e-7;
            y[1] = 0;
            const double want = gw_chain_get_params(c)->kwall * 1e-7 * sqrt(1e-7);
            EXPECT(fabs(gw_chain_wall_force(c, y) - want) <= 1e-12 * want);
        }
        free(y);
        gw_chain_free(c);
    }
    return 0;
}

/* ------------------------------------------------ the run's check ---- */

static int c_run_check_column(void)
{
    const double bad[] = {INFINITY, -INFINITY, NAN, 0.0, -1.0};
    gw_chain_run_opts o = gw_chain_run_opts_default();
    for (int i = 0; i < 5; i++) {
        gw_chain_params p = gw_chain_params_default();
        p.v_imp = bad[i];
        gw_err e = {{0}};
        const int rc = gw_chain_run_check(&p, &o, &e);
        if (rc != GW_EINVAL || !strstr(e.msg, "v_imp")) {
            printf("v_imp %g: rc %d, '%s'\n", bad[i], rc, e.msg);
            return 1;
        }
    }
    gw_chain_params p = gw_chain_params_default();
    p.mass = INFINITY;
    gw_err e = {{0}};
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_EINVAL && strstr(e.msg, "mass"));
    return 0;
}

static int c_run_check_control(void)
{
    gw_chain_params p = gw_chain_params_default();
    gw_chain_run_opts o = gw_chain_run_opts_default();
    gw_err e = {{0}};
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_OK);
    p.v_imp = GW_CHAIN_VIMP_MAX;
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_OK);
    return 0;
}

/* ------------------------------------------- a drop's rerun of no kind ---- */

static int c_drop_rerun_invalid(void)
{
    const int bad[] = {99, INT_MIN, -1, GW_CHAIN_RERUN_STEP + 1, INT_MAX};
    for (int i = 0; i < 5; i++) {
        char *w = test_drop_said(bad[i], NAN);
        char want[96];
        snprintf(want, sizeof want, "chatter_rerun, %d, is invalid", bad[i]);
        if (!w || !strstr(w, want) || strstr(w, "tighter") || strstr(w, "--dt")) {
            printf("chatter_rerun %d: %s\n", bad[i], w ? w : "(none)");
            free(w);
            return 1;
        }
        free(w);
    }
    return 0;
}

static int c_drop_rerun_control(void)
{
    char *w = test_drop_said(GW_CHAIN_RERUN_TOL, NAN);
    EXPECT(w && strstr(w, "compare a run at 10 times tighter --rtol and --atol; ") && !strstr(w, "invalid"));
    free(w);
    return 0;
}

/* ------------------------------------------------ rk4 on a soft wall ---- */

static int rk4_check(double dt, double k, double kwall, gw_err *e)
{
    gw_chain_params p = test_chain_column(k, kwall);
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.solver = gw_solver_rk4;
    o.sp.dt = dt;
    return gw_chain_run_check(&p, &o, e);
}

static int c_rk4_soft_wall(void)
{
    /* the brief's two columns: dt 1e-9 on kwall 1e-30, and dt, k, kwall all wrong */
    const double dts[] = {1e-9, 1e-15}, ks[] = {0, 1e30};
    for (int i = 0; i < 2; i++) {
        gw_err e = {{0}};
        const int rc = rk4_check(dts[i], ks[i], 1e-30, &e);
        if (rc != GW_EINVAL || strncmp(e.msg, "kwall: 1e-30 ", 13) != 0 || strstr(e.msg, "raise it")) {
            printf("dt %g, k %g: rc %d, '%s'\n", dts[i], ks[i], rc, e.msg);
            return 1;
        }
    }
    /* without a dt, under rk4 and cvode: kwall, not k (which was told to go
     * below 1.6e-18 to match the wall) */
    gw_err e = {{0}};
    EXPECT(rk4_check(0, 0, 1e-30, &e) == GW_EINVAL && strncmp(e.msg, "kwall: 1e-30 ", 13) == 0);
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    p.kwall = 1e-30;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    EXPECT(gw_chain_run_check(&p, &o, &e) == GW_EINVAL && strncmp(e.msg, "kwall: 1e-30 ", 13) == 0);
    return 0;
}

/* a dt that raising cannot help alone (k 1e30 on the default wall: rk4's step
 * at most 5.7e-14 s, 6.1e8 steps) is not told "raise it" */
static int c_rk4_dt_cannot_help(void)
{
    gw_err e = {{0}};
    EXPECT(rk4_check(1e-15, 1e30, 0, &e) == GW_EINVAL);
    if (strncmp(e.msg, "dt: ", 4) != 0 || strstr(e.msg, "raise it") || !strstr(e.msg, "cannot help alone")) {
        printf("'%s'\n", e.msg);
        return 1;
    }
    return 0;
}

/* controls: a dt too small on the default column is still told "raise it",
 * and a moderately soft wall passes */
static int c_rk4_control(void)
{
    gw_err e = {{0}};
    EXPECT(rk4_check(1e-15, 0, 0, &e) == GW_EINVAL && strncmp(e.msg, "dt: ", 4) == 0 && strstr(e.msg, "raise it"));
    EXPECT(rk4_check(1e-9, 0, 1e3, &e) == GW_OK);
    EXPECT(rk4_check(1e-7, 0, 1, &e) == GW_OK);
    return 0;
}

int main(void)
{
    static const child_row rows[] = {
        {"state: overlap NaN", c_nan_overlap},
        {"state: rate NaN", c_nan_rate},
        {"state: open and closed (control)", c_open_closed_control},
        {"run check: the column's fields", c_run_check_column},
        {"run check: the default (control)", c_run_check_control},
        {"drop: chatter_rerun invalid", c_drop_rerun_invalid},
        {"drop: chatter_rerun TOL (control)", c_drop_rerun_control},
        {"rk4: a soft wall named", c_rk4_soft_wall},
        {"rk4: a dt raising cannot help", c_rk4_dt_cannot_help},
        {"rk4: dt and soft walls (control)", c_rk4_control},
    };
    return child_cases_run(rows, sizeof rows / sizeof rows[0]);
}
