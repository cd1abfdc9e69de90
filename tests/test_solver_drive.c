/*
 * test_solver_drive.c: the solver layer's driver (gw_solver_drive, common/
 * gw_solver.c) on a bouncing ball, whose bounce times are known in closed form.
 *
 * A ball falls from height h0 = 1 m at rest under g = 9.81 m/s^2 (y' = v,
 * v' = -g, root y = 0 falling); at each bounce the hook reverses the velocity
 * with restitution e = 0.5 and asks for a restart (GW_DRIVE_RESET). Bounce k
 * (k = 1, 2, ...) comes at
 *   t_1 = sqrt(2 h0 / g),  t_(k+1) = t_k + 2 e^k v_1 / g,  v_1 = g t_1.
 * Checked, with CVODE (rtol 1e-12) and RK4 (dt 1e-4 s, events located):
 * - the first five bounce times to 1e-8 relative (the root finder's precision;
 *   a driver that did not restart after the velocity jump, or restarted from
 *   the state before the hook, would miss the second bounce by far);
 * - the output times: on_output is called exactly at k dt_out (bit for bit),
 *   and as often as there are output times before the end;
 * - GW_DRIVE_STOP from after: the run ends at the fourth bounce (GW_OK, t = t_4);
 * - GW_DRIVE_YIELD: the driver returns GW_ROOT at the third bounce without
 *   restarting, and a second call (after the caller's restart) goes on to t_end;
 * - a hook's error (negative status) is returned with its message;
 * - a backend failure (max_steps too small) is reported with the "what" prefix.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gw_solver.h"
#include "gw_test.h"

static const double G = 9.81, H0 = 1.0, E = 0.5, T_END = 1.32; /* before the bounces pile up at 3 t_1 = 1.355 s */

static int ball_rhs(double t, const double *y, double *yd, void *P)
{
    (void)t, (void)P;
    yd[0] = y[1];
    yd[1] = -G;
    return 0;
}

static int ball_roots(double t, const double *y, double *g, void *P)
{
    (void)t, (void)P;
    g[0] = y[0];
    return 0;
}

static double bounce_time(int k) /* k >= 1 */
{
    double t1 = sqrt(2 * H0 / G), v1 = G * t1, t = t1;
    for (int j = 1; j < k; j++)
        t += 2 * pow(E, j) * v1 / G;
    return t;
}

typedef struct run {
    int bounces, outputs, yield_at, stop_at, fail_at;
    double tb[16];
    int out_exact; /* every output time equal to k dt_out */
    double dt_out;
} run;

static int on_root(void *ctx, double t, double *y, const int *roots, gw_err *err)
{
    run *r = ctx;
    if (roots[0] >= 0)
        return GW_DRIVE_ON; /* (a rising zero: not a bounce) */
    if (r->bounces < 16)
        r->tb[r->bounces] = t;
    r->bounces++;
    if (r->fail_at && r->bounces == r->fail_at)
        return gw_err_set(err, GW_EINVAL, "hook failed at bounce %d", r->bounces);
    if (r->yield_at && r->bounces == r->yield_at)
        return GW_DRIVE_YIELD;
    y[0] = 0;
    y[1] = -E * y[1];
    return GW_DRIVE_RESET;
}

static int on_output(void *ctx, double t, double *y, gw_err *err)
{
    (void)y, (void)err;
    run *r = ctx;
    r->outputs++;
    if (t != (double)r->outputs * r->dt_out && t != T_END)
        r->out_exact = 0;
    return GW_DRIVE_ON;
}

static int after(void *ctx, double t, const double *y, gw_err *err)
{
    (void)t, (void)y, (void)err;
    const run *r = ctx;
    return r->stop_at && r->bounces >= r->stop_at ? GW_DRIVE_STOP : GW_DRIVE_ON;
}

static int drive(const gw_solver_type *type, run *r, double t_end, double *t, double *y, gw_solver **sp,
                 long max_steps, gw_err *err)
{
    static gw_system sys = {.dim = 2, .nroots = 1, .rhs = ball_rhs, .roots = ball_roots};
    gw_solver_params p = {.rtol = 1e-12, .atol = 1e-14, .dt = type == gw_solver_rk4 ? 1e-4 : 0,
                          .max_steps = max_steps};
    gw_solver *s = NULL;
    int rc = gw_solver_create(type, &sys, &p, *t, y, &s, err);
    if (rc != GW_OK)
        return rc;
    int roots[1];
    r->dt_out = 0.05;
    r->out_exact = 1;
    gw_drive d = {.t_end = t_end, .dt_out = r->dt_out, .k_out = 1, .what = "ball", .on_root = on_root,
                  .on_output = on_output, .after = after, .ctx = r};
    rc = gw_solver_drive(s, &d, t, y, roots, err);
    if (rc == GW_ROOT && sp) { /* the caller's restart after a yield, then on */
        y[0] = 0;
        y[1] = -E * y[1];
        gw_solver_reset(s, *t, y);
        rc = gw_solver_drive(s, &d, t, y, roots, err);
        *sp = NULL;
    }
    gw_solver_free(s);
    return rc;
}

int main(void)
{
    const gw_solver_type *types[2] = {gw_solver_cvode, gw_solver_rk4};
    const char *names[2] = {"cvode", "rk4"};
    char what[800];
    for (int b = 0; b < 2; b++) {
        gw_err err = {0};
        double y[2] = {H0, 0}, t = 0;
        run r = {0};
        int rc = drive(types[b], &r, T_END, &t, y, NULL, 100000, &err);
        snprintf(what, sizeof what, "%s: the run reaches t_end (rc %d, %s)", names[b], rc, err.msg);
        gw_test_true(rc == GW_OK && t == T_END, what);
        for (int k = 1; k <= 5; k++) {
            snprintf(what, sizeof what, "%s: bounce %d time", names[b], k);
            gw_test_rel(r.tb[k - 1], bounce_time(k), 1e-8, what);
        }
        snprintf(what, sizeof what, "%s: %d outputs at exactly k dt_out (26 multiples of 0.05 s and t_end = 1.32 s)", names[b], r.outputs);
        gw_test_true(r.outputs == 27 && r.out_exact, what);

        /* STOP from after, at the fourth bounce */
        y[0] = H0, y[1] = 0, t = 0;
        run r2 = {.stop_at = 4};
        rc = drive(types[b], &r2, T_END, &t, y, NULL, 100000, &err);
        snprintf(what, sizeof what, "%s: after's stop ends the run at bounce 4", names[b]);
        gw_test_true(rc == GW_OK && r2.bounces == 4, what);
        snprintf(what, sizeof what, "%s: stopped at t_4", names[b]);
        gw_test_rel(t, bounce_time(4), 1e-8, what);

        /* YIELD at the third bounce, then on */
        y[0] = H0, y[1] = 0, t = 0;
        run r3 = {.yield_at = 3};
        gw_solver *dummy = (gw_solver *)&r3;
        rc = drive(types[b], &r3, T_END, &t, y, &dummy, 100000, &err);
        snprintf(what, sizeof what, "%s: a yield hands back, the caller's restart goes on to t_end", names[b]);
        gw_test_true(rc == GW_OK && t == T_END && dummy == NULL, what);
        snprintf(what, sizeof what, "%s: bounce 5 after the yield", names[b]);
        gw_test_rel(r3.tb[4], bounce_time(5), 1e-8, what);

        /* a hook's error */
        y[0] = H0, y[1] = 0, t = 0;
        run r4 = {.fail_at = 2};
        rc = drive(types[b], &r4, T_END, &t, y, NULL, 100000, &err);
        snprintf(what, sizeof what, "%s: the hook's error is returned (%s)", names[b], err.msg);
        gw_test_true(rc == GW_EINVAL && strstr(err.msg, "bounce 2") != NULL, what);

        /* a backend failure */
        y[0] = H0, y[1] = 0, t = 0;
        run r5 = {0};
        rc = drive(types[b], &r5, T_END, &t, y, NULL, 3, &err);
        snprintf(what, sizeof what, "%s: a solver failure names the run (%s)", names[b], err.msg);
        gw_test_true(rc < 0 && rc != GW_EINVAL && strncmp(err.msg, "ball: ", 6) == 0, what);
    }
    return gw_test_summary("test_solver_drive");
}
