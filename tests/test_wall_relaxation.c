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

#include "chain_test_util.h"
#include "gw_test.h"

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
        gw_chain_result r = {0};
        rc = gw_chain_collide(c, &o, &r, e);
        *eps = r.eps_eff;
        *f = r.f_max;
        gw_chain_result_free(&r);
    }
    gw_chain_free(c);
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
    /* rk4's default step follows the contacts, not the arms: arms of 1e-8 s
     * blow up, and the advice names them (it named "a contact, the sensor
     * body, damping or friction" only); the default arms run on rk4 */
    rc = visco_on(gw_solver_rk4, 1e-8, 1e-6, &e, &eps, &f);
    printf("  (rk4, arms 1e-8..1e-6 s: %s)\n", e.msg);
    gw_test_true(rc == GW_ESOLVER && strstr(e.msg, "the wall's Maxwell arms (the fastest 1e-08 s)"),
                 "rk4 with arms of 1e-8 s: a solver error naming the wall's Maxwell arms and the fastest");
    rc = visco_on(gw_solver_rk4, 0, 0, &e, &eps1, &f1);
    gw_test_true(rc == GW_OK && fabs(eps1 / eps0 - 1) < 1e-3, "rk4 with the default arms runs, eps_eff as cvode's");
    return gw_test_summary("test_wall_relaxation");
}
