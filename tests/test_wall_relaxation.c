/*
 * test_wall_relaxation.c: the shortest relaxation time of a viscoelastic
 * wall's Maxwell arms (the thirty-third session; issue 18).
 *
 * gw_chain_wall's tau_min and tau_max were checked in [0, 1e3] s only: arms of
 * 1e-300 s (settable from C alone) ran, as a wall relaxed at once, whatever
 * the loss asked: one bead on it rebounds elastically. A relaxation faster
 * than the atomic vibrations (0.01-1 ps) is no viscoelastic relaxation of a
 * solid, and below about 1e-20 s it is shorter than the spacing of doubles at
 * the collision's times. A time above 0 and below GW_CHAIN_WALL_TAU_MIN
 * (1e-12 s) is now refused by gw_chain_params_validate (gw_chain_create, the
 * drop), naming the arm and the range; 0 still gives the default arms.
 * The physics behind the bound, measured here: a band of arms far below the
 * contact's time (10 us to 1 ms) is relaxed through the contact and gives it
 * no loss, where the default band gives the loss asked.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "chain_model.h"
#include "chain_test_util.h"
#include "gw_test.h"

/* rk4's default step (as planned) of the last visco_on call on rk4 */
static double visco_dt_last = NAN;

/* gw_chain_create's status for a viscoelastic wall of loss 0.3 and arms
 * [a, b], N = 1; with a chain, one collision under cvode: *eps its eps_eff,
 * *f its F_max. */
static int visco_on(const gw_solver_type *solver, double a, double b, gw_err *e, double *eps, double *f);

static int visco(double a, double b, gw_err *e, double *eps, double *f)
{
    return visco_on(NULL, a, b, e, eps, f);
}

/* the same on a given solver (NULL: the default, CVODE) */
static int visco_on(const gw_solver_type *solver, double a, double b, gw_err *e, double *eps, double *f)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 1;
    p.wall.loss = 0.3;
    p.wall.tau_min = a;
    p.wall.tau_max = b;
    gw_chain *c = NULL;
    memset(e, 0, sizeof *e);
    *eps = *f = NAN;
    int rc = gw_chain_create(&p, &c, e);
    if (rc == GW_OK) {
        gw_chain_run_opts o = gw_chain_run_opts_default();
        if (solver)
            o.solver = solver;
        double dt_max = NAN;
        gw_err e2 = {{0}};
        visco_dt_last = NAN;
        if (solver == gw_solver_rk4 && chain_run_step(&p, &o, &visco_dt_last, &dt_max, &e2) != GW_OK)
            visco_dt_last = NAN;
        gw_chain_result r = {0};
        rc = gw_chain_collide(c, &o, &r, e);
        *eps = r.eps_eff;
        *f = r.f_max;
        gw_chain_result_free(&r);
    }
    gw_chain_free(c);
    return rc;
}

static gw_chain_params visco_params(double a, double b, double radius)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 1;
    p.wall.loss = 0.3;
    p.wall.tau_min = a;
    p.wall.tau_max = b;
    if (radius > 0) { /* a steel bead of that radius on steel */
        const gw_material *st = gw_material_find("steel");
        p.radius = radius;
        p.mass = 4.0 / 3.0 * M_PI * pow(radius, 3) * st->density;
        p.k = gw_hertz_coefficient(radius, st, radius, st);
        p.kwall = gw_hertz_coefficient(radius, st, INFINITY, st);
    }
    return p;
}

static int run_one(const gw_chain_params *p, const gw_chain_run_opts *o, gw_chain_result *r, gw_err *e)
{
    gw_chain *c = NULL;
    memset(r, 0, sizeof *r);
    int rc = gw_chain_create(p, &c, e);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, o, r, e);
    gw_chain_free(c);
    return rc;
}

/* rk4 at its default step against cvode bdf at 1e-12 on the wall with arms
 * [a, b] under one steel bead of the radius (0: the default 4 mm): F_max
 * within 1e-6 relative (measured 6.3e-8 at most), eps_eff within 1e-6 */
static int visco_rk4_vs_bdf(double a, double b, double radius, gw_err *e)
{
    gw_chain_params p = visco_params(a, b, radius);
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    gw_chain_result r0, r1;
    int rc = run_one(&p, &o, &r0, e);
    gw_test_true(rc == GW_OK, "cvode bdf on the arms runs");
    gw_chain_run_opts o4 = gw_chain_run_opts_default();
    o4.solver = gw_solver_rk4;
    double dt = NAN, dt_max = NAN;
    gw_err e2 = {{0}};
    if (chain_run_step(&p, &o4, &dt, &dt_max, &e2) == GW_OK)
        printf("  (arms %g..%g s, bead radius %g m: rk4's default step %.6g s)\n", a, b, radius > 0 ? radius : p.radius, dt);
    const int rc4 = run_one(&p, &o4, &r1, e);
    if (rc4 != GW_OK)
        printf("  (rk4: %s)\n", e->msg);
    if (rc == GW_OK && rc4 == GW_OK) {
        printf("  (F_max rk4 %.12g N, bdf %.12g N: %.2g relative; eps_eff %.10g, %.10g)\n", r1.f_max, r0.f_max,
               r1.f_max / r0.f_max - 1, r1.eps_eff, r0.eps_eff);
        gw_test_rel(r1.f_max, r0.f_max, 1e-6, "rk4's F_max on fast arms = cvode bdf's");
        gw_test_abs(r1.eps_eff, r0.eps_eff, 1e-6, "rk4's eps_eff on fast arms = cvode bdf's");
    }
    gw_chain_result_free(&r0);
    gw_chain_result_free(&r1);
    return rc4;
}

/* rk4 on the arms [a, b] at a given step, the contacts' T_c/400 (*dt) */
static int visco_rk4_dt(double a, double b, double *dt, gw_err *e)
{
    gw_chain_params p = visco_params(a, b, 0);
    *dt = gw_chain_step_scale(&p) / 400.0;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.solver = gw_solver_rk4;
    o.sp.dt = *dt;
    gw_chain_result r;
    memset(e, 0, sizeof *e);
    int rc = run_one(&p, &o, &r, e);
    gw_chain_result_free(&r);
    return rc;
}

int main(void)
{
    gw_err e;
    double eps, f, eps0, f0;
    /* refused, naming the arm, its time and the range */
    int rc = visco(1e-300, 1e-300, &e, &eps, &f);
    gw_test_true(rc == GW_EINVAL, "arms of 1e-300 s refused (they ran as a wall relaxed at once)");
    gw_test_true(strstr(e.msg, "wall tau_min (s): a Maxwell arm of 1e-300 s") && strstr(e.msg, "[1e-12, 1e3] s"),
                 "the refusal names tau_min, its 1e-300 s and the range [1e-12, 1e3] s");
    printf("  (%s)\n", e.msg);
    rc = visco(0, 1e-300, &e, &eps, &f);
    gw_test_true(rc == GW_EINVAL && strstr(e.msg, "wall tau_max (s): a Maxwell arm of 1e-300 s"),
                 "tau_max of 1e-300 s under the default tau_min refused naming tau_max");
    rc = visco(4.9e-324, 1e-3, &e, &eps, &f);
    gw_test_true(rc == GW_EINVAL && strstr(e.msg, "wall tau_min"), "a subnormal tau_min refused");
    rc = visco(9.9e-13, 1e-10, &e, &eps, &f);
    gw_test_true(rc == GW_EINVAL && strstr(e.msg, "wall tau_min"), "tau_min 9.9e-13 s, just below the bound, refused");
    rc = visco(1e-15, 1e-13, &e, &eps, &f);
    gw_test_true(rc == GW_EINVAL, "arms of 1e-15 to 1e-13 s refused");
    /* the bound itself runs: arms far below the contact are relaxed through it,
     * so the loss asked is not felt (one bead rebounds elastically) */
    rc = visco(1e-12, 1e-10, &e, &eps, &f);
    gw_test_true(rc == GW_OK, "arms of 1e-12 to 1e-10 s run");
    rc = visco(0, 0, &e, &eps0, &f0);
    gw_test_true(rc == GW_OK, "the default arms run");
    printf("  (loss 0.3: eps_eff %.6f, F_max %.4f N with arms 1e-12..1e-10 s; %.6f, %.4f N with the default "
           "1e-5..1e-3 s)\n", eps, f, eps0, f0);
    gw_test_true(eps > 0.9999 && eps < 1 + 1e-9, "arms far below the contact: no loss felt (eps_eff -> 1)");
    gw_test_true(eps0 < 0.9, "the default band covers the contact: the loss is felt (eps_eff < 0.9)");
    /* 0 is the default band, bit for bit the same as given */
    double eps1, f1;
    rc = visco(1e-5, 1e-3, &e, &eps1, &f1);
    gw_test_true(rc == GW_OK && eps1 == eps0 && f1 == f0, "tau 0 is the default arms 1e-5 to 1e-3 s, bit for bit");
    /* rk4's default step followed the contacts, not the arms: arms of 1e-8 s
     * (and of 1e-7 s under a 4 cm bead, whose contact step is 1.56e-7 s) blew
     * up. RK4 is stable on a relaxation of time tau while h < 2.79 tau; the
     * default step is now also at most the fastest arm's tau
     * (chain_rk4_default_dt), only where that is shorter than the contacts'
     * step. Measured F_max against cvode bdf at 1e-12: 6.3e-8 relative (1e-8
     * to 1e-6 s, the default 4 mm bead; 1e-7 to 1e-5 s, 4 cm), 7.4e-10 (one arm of 1e-7
     * s, 4 cm); eps_eff within 4.6e-8 */
    rc = visco_rk4_vs_bdf(1e-8, 1e-6, 0, &e);
    gw_test_true(rc == GW_OK, "rk4 with arms of 1e-8 to 1e-6 s runs (it blew up at the contacts' step)");
    rc = visco_rk4_vs_bdf(1e-7, 1e-5, 0.04, &e);
    gw_test_true(rc == GW_OK, "rk4 with arms of 1e-7 to 1e-5 s under a 4 cm bead runs");
    rc = visco_rk4_vs_bdf(1e-7, 1e-7, 0.04, &e);
    gw_test_true(rc == GW_OK, "rk4 with one arm of 1e-7 s under a 4 cm bead runs");
    /* a step given is the user's: at the contacts' step the arms still blow
     * up, and the advice names them */
    double dt_c = 0;
    rc = visco_rk4_dt(1e-8, 1e-6, &dt_c, &e);
    printf("  (rk4, arms 1e-8..1e-6 s at the contacts' step %.6g s: %s)\n", dt_c, e.msg);
    gw_test_true(rc == GW_ESOLVER && strstr(e.msg, "the wall's Maxwell arms (the fastest 1e-08 s)"),
                 "rk4 at a given step of the contacts' T_c/400 with arms of 1e-8 s: a solver error naming the "
                 "wall's Maxwell arms and the fastest");
    /* runs whose arms are slower than the contacts' step keep it bit for bit */
    rc = visco_on(gw_solver_rk4, 0, 0, &e, &eps1, &f1);
    gw_test_true(rc == GW_OK && fabs(eps1 / eps0 - 1) < 1e-3, "rk4 with the default arms runs, eps_eff as cvode's");
    double eps2, f2;
    rc = visco_rk4_dt(1e-5, 1e-3, &dt_c, &e);
    gw_test_true(rc == GW_OK, "rk4 at a given T_c/400 with the default arms runs");
    rc = visco_on(gw_solver_rk4, 1e-5, 1e-3, &e, &eps2, &f2);
    gw_test_true(rc == GW_OK && eps2 == eps1 && f2 == f1 && visco_dt_last == dt_c,
                 "rk4's default step under the default arms is the contacts' T_c/400, bit for bit");
    return gw_test_summary("test_wall_relaxation");
}
