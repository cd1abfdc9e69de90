/*
 * test_chain_walls.c: the wall contact laws beyond the Hertz spring, the sensor
 * as a body and guide friction (issue 19, parts 2-3).
 *
 * Layer law (chain_layer.c), dimensionless d R/h^2 and F R/(E* h^3):
 *   - thick limit: F/F_Hertz -> 1 as a/h -> 0 (1e-3 at a/h = 1e-3), and the first
 *     correction (F/F_H - 1)/chi -> 1.133 for nu = 1/2, chi = sqrt(R d)/h (the
 *     bonded-layer coefficient of Dimitriadis et al. 2002), within 1 %;
 *   - thin limit: F/(pi R M d^2/h) -> 1 (Winkler, Johnson 1985 5.9) for nu = 0.3:
 *     within 0.5 % at a/h = 40 and closer than at a/h = 10;
 *   - the tabulated law: F = dU/dd (U integrated from the table), stiffness = dF/dd,
 *     overlap(force(d)) = d, and the thick-layer limit of a brass sheet = Hertz.
 * Thornton (chain_wall.c): F <= pi p_y R d; Hertz below d_y; the energy lost in a
 * load-unload cycle = loading work - recovered work (quadrature of the unloading
 * curve); a bead's rebound on the plastic wall e^2 = U(d*) / (m v^2/2), with d*
 * from W_L(d*) = m v^2/2 (energy argument, independent of the ODE).
 * Viscoelastic wall: restitution < 1, rising to 1 as the loss falls (1 - e about
 * proportional to the loss); energy ledger closed.
 * Sensor body: a light, stiff, critically damped sensor reproduces the rigid wall
 * (F_max, tau_max, tau_N, eps_eff within 1e-4); momentum ledger (beads + sensor +
 * impulse read) and energy ledger close for a real sensor.
 * Guide friction: energy ledger closed; eps_eff falls with friction.
 */
#include <math.h>
#include <stdio.h>

#include "chain_test_util.h"
#include "gw_test.h"

static const double V29 = 0.23853; /* sqrt(2 g 2.9 mm), m/s */

static void test_layer_limits(void)
{
    gw_err err = {{0}};
    double dh, fh;
    /* thick limit, nu = 1/2, rigid sphere */
    int rc = gw_layer_solve_point(1e-3, 0.5, 1.0, &dh, &fh, &err);
    gw_test_true(rc == GW_OK, "layer point a/h = 1e-3 solves");
    double ratio = fh / (4.0 / 3.0 * dh * sqrt(dh));
    gw_test_abs(ratio, 1.0, 1.5e-3, "layer a/h = 1e-3, nu = 0.5: F/F_Hertz -> 1");
    gw_test_rel((ratio - 1.0) / sqrt(dh), 1.133, 0.01,
                "layer first-order coefficient (F/F_H - 1)/chi, nu = 0.5 (Dimitriadis 2002: 1.133)");
    rc = gw_layer_solve_point(1e-3, 0.38, 1.0, &dh, &fh, &err);
    ratio = fh / (4.0 / 3.0 * dh * sqrt(dh));
    /* Dimitriadis' fit alpha0(nu) = -(1.2876 - 1.4678 nu + 1.3442 nu^2)/(1 - nu) */
    double a0 = -(1.2876 - 1.4678 * 0.38 + 1.3442 * 0.38 * 0.38) / (1 - 0.38);
    gw_test_rel((ratio - 1.0) / sqrt(dh), -2.0 * a0 / M_PI, 0.01,
                "layer first-order coefficient, nu = 0.38 (Dimitriadis' alpha0 fit)");
    /* thin limit, nu = 0.3: Winkler F = pi R M d^2/h, in units F R/(E* h^3) with
     * E* = E/(1 - nu^2): pi M (1 - nu^2)/E dhat^2 */
    double nu = 0.3, mw = (1 - nu) / ((1 + nu) * (1 - 2 * nu)) * (1 - nu * nu), r10, r40;
    gw_layer_solve_point(10.0, nu, 1.0, &dh, &fh, &err);
    r10 = fh / (M_PI * mw * dh * dh);
    rc = gw_layer_solve_point(40.0, nu, 1.0, &dh, &fh, &err);
    gw_test_true(rc == GW_OK, "layer point a/h = 40 solves");
    r40 = fh / (M_PI * mw * dh * dh);
    gw_test_abs(r40, 1.0, 5e-3, "layer a/h = 40, nu = 0.3: F/F_Winkler -> 1");
    gw_test_true(fabs(r40 - 1) < fabs(r10 - 1), "layer: the Winkler limit is approached as a/h grows");
    printf("  (F/F_Winkler = %.5f at a/h = 10, %.5f at a/h = 40)\n", r10, r40);
}

static void test_layer_law(void)
{
    gw_err err = {{0}};
    gw_layer_law *l = NULL;
    const gw_material *steel = gw_material_find("steel");
    int rc = gw_layer_law_create(4e-3, steel, 1.0e-3, 3.0e9, 0.38, &l, &err);
    gw_test_true(rc == GW_OK, "layer law for a 1 mm PVC sheet under a steel bead");
    if (rc != GW_OK)
        return;
    double worst_f = 0, worst_k = 0, worst_d = 0;
    for (double d = 1e-9; d < 3e-4; d *= 1.7) {
        double k, f = gw_layer_law_force(l, d, &k), h = 1e-4 * d;
        double fn = (gw_layer_law_energy(l, d + h) - gw_layer_law_energy(l, d - h)) / (2 * h);
        double kn = (gw_layer_law_force(l, d + h, NULL) - gw_layer_law_force(l, d - h, NULL)) / (2 * h);
        worst_f = fmax(worst_f, fabs(fn - f) / f);
        worst_k = fmax(worst_k, fabs(kn - k) / k);
        worst_d = fmax(worst_d, fabs(gw_layer_law_overlap(l, f) - d) / d);
    }
    gw_test_abs(worst_f, 0, 1e-6, "layer law: F = dU/dd (U from the table) over 1 nm .. 0.3 mm");
    gw_test_abs(worst_k, 0, 1e-6, "layer law: stiffness = dF/dd");
    gw_test_abs(worst_d, 0, 1e-9, "layer law: overlap(force(d)) = d");
    /* stiffer than the half-space of the same material, monotone ratio */
    double kh = gw_layer_law_hertz_k(l), prev = 1.0;
    int mono = 1;
    for (double d = 1e-9; d < 3e-4; d *= 2) {
        double ratio = gw_layer_law_force(l, d, NULL) / (kh * d * sqrt(d));
        mono &= ratio >= prev - 1e-9;
        prev = ratio;
    }
    gw_test_true(mono, "layer law: F/F_Hertz grows with the overlap (the base stiffens the contact)");
    gw_layer_law_free(l);
    /* a thick brass sheet at small load is the Hertz half-space of steel on brass */
    const gw_material *brass = gw_material_find("brass");
    rc = gw_layer_law_create(4e-3, steel, 1.2e-3, brass->young, brass->poisson, &l, &err);
    double kb = gw_hertz_coefficient(4e-3, steel, INFINITY, brass), d = 1e-12;
    gw_test_rel(gw_layer_law_force(l, d, NULL), kb * d * sqrt(d), 2e-4,
                "layer law: brass sheet, d = 1e-12 m (a/h ~ 5e-5): Hertz steel on brass");
    gw_layer_law_free(l);
}

static void test_thornton(void)
{
    const gw_material *steel = gw_material_find("steel"), *brass = gw_material_find("brass");
    double R = 4e-3, K = gw_hertz_coefficient(R, steel, INFINITY, brass), es = 3 * K / (4 * sqrt(R));
    gw_thornton t;
    gw_thornton_init(&t, es, R, 2.8 * 200e6);
    int bounded = 1, hertz = 1;
    for (double d = 1e-9; d < 1e-4; d *= 1.3) {
        double f = gw_thornton_force(&t, d, 0, NULL, NULL, NULL);
        bounded &= f <= M_PI * t.p_y * R * d * (1 + 1e-12);
        if (d <= t.d_y)
            hertz &= fabs(f - K * d * sqrt(d)) <= 1e-12 * f;
    }
    gw_test_true(bounded, "Thornton: F <= pi p_y R d on loading (the pressure cap)");
    gw_test_true(hertz, "Thornton: Hertz below the yield overlap");
    /* cycle to 20 d_y and back: loss = loading work - recovered work */
    double dm = 20 * t.d_y, dp, u;
    double fm = gw_thornton_force(&t, dm, dm, NULL, &dp, &u);
    double wu = 0;
    const int ns = 20000;
    for (int i = 0; i < ns; i++) { /* midpoint rule on the unloading curve */
        double d = dp + (dm - dp) * (i + 0.5) / ns;
        wu += gw_thornton_force(&t, d, dm, NULL, NULL, NULL) * (dm - dp) / ns;
    }
    gw_test_rel(wu, u, 1e-6, "Thornton: recovered work (quadrature) = (2/5) F (d* - d_p)");
    gw_test_true(dp > 0 && gw_thornton_loading_work(&t, dm) > wu,
                 "Thornton: residual dent and energy lost in a cycle beyond yield");
    printf("  (d_y = %.3g m, F_y = %.3g N, F(20 d_y) = %.3g N, loss %.3g of the loading work)\n", t.d_y,
           t.f_y, fm, 1 - wu / gw_thornton_loading_work(&t, dm));
    /* one bead on the plastic wall: e^2 = U(d*)/(m v^2/2), W_L(d*) = m v^2/2 */
    gw_chain_params p = test_params(1, V29);
    p.kwall = K;
    p.wall.yield_pressure = t.p_y;
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    gw_chain_result r;
    if (test_collide(&p, &o, &r) == GW_OK) {
        double ek = 0.5 * p.mass * V29 * V29, lo = 0, hi = 1e-3;
        for (int i = 0; i < 200; i++) {
            double mid = 0.5 * (lo + hi);
            if (gw_thornton_loading_work(&t, mid) < ek)
                lo = mid;
            else
                hi = mid;
        }
        gw_thornton_force(&t, lo, lo, NULL, NULL, &u);
        gw_test_rel(r.eps_eff, sqrt(u / ek), 1e-6, "Thornton wall: one bead's restitution from the energy argument");
        gw_test_abs(r.energy_error, 0, 1e-7, "Thornton wall: energy ledger (work on the wall integrated)");
        printf("  (e = %.6f for p_y = %.3g Pa at %.4f m/s)\n", r.eps_eff, t.p_y, V29);
    }
    gw_chain_result_free(&r);
    /* a column on the plastic wall keeps its ledger */
    p.n = 8;
    if (test_collide(&p, &o, &r) == GW_OK)
        gw_test_abs(r.energy_error, 0, 1e-7, "Thornton wall: energy ledger, N = 8 column");
    gw_chain_result_free(&r);
}

static void test_visco(void)
{
    gw_err err = {{0}};
    gw_layer_law *l = NULL;
    gw_layer_law_create(4e-3, gw_material_find("steel"), 1.0e-3, 3.3e9, 0.37, &l, &err);
    gw_chain_params p = test_params(1, V29);
    p.kwall = gw_layer_law_hertz_k(l);
    p.wall.layer = l;
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    gw_chain_result r;
    double e[4], loss[4] = {0.1, 0.01, 0.001, 0.0};
    for (int i = 0; i < 4; i++) {
        p.wall.loss = loss[i];
        e[i] = test_collide(&p, &o, &r) == GW_OK ? r.eps_eff : NAN;
        if (i == 0)
            gw_test_abs(r.energy_error, 0, 1e-7, "viscoelastic layer: energy ledger (work on the wall integrated)");
        gw_chain_result_free(&r);
        printf("  (loss %g: e = %.8f)\n", loss[i], e[i]);
    }
    gw_test_true(e[0] < e[1] && e[1] < e[2] && e[2] < 1, "viscoelastic wall: e < 1, rising as the loss falls");
    gw_test_abs(e[3], 1.0, 1e-7, "elastic layer (no loss): e = 1");
    double q = (1 - e[1]) / (1 - e[2]);
    gw_test_true(q > 7 && q < 13, "viscoelastic wall: 1 - e about proportional to the loss (ratio 7..13 for 10x)");
    p.n = 6;
    p.wall.loss = 0.05;
    if (test_collide(&p, &o, &r) == GW_OK)
        gw_test_abs(r.energy_error, 0, 1e-7, "viscoelastic layer: energy ledger, N = 6 column");
    gw_chain_result_free(&r);
    gw_layer_law_free(l);
}

/* Momentum ledger: momentum of beads and sensor at the last sample plus the
 * impulse of the force read (trapezoid on the samples), against N m v_imp. */
typedef struct mom_ctx {
    const gw_chain *c;
    double p_last, t_prev, f_prev, impulse;
} mom_ctx;

static int mom_sample(void *ctx, double t, const double *y, double f, int is_event)
{
    (void)is_event;
    mom_ctx *m = ctx;
    if (t > m->t_prev)
        m->impulse += 0.5 * (f + m->f_prev) * (t - m->t_prev);
    m->t_prev = t;
    m->f_prev = f;
    m->p_last = gw_chain_momentum(m->c, y);
    return 0;
}

static double momentum_gap(const gw_chain_params *p, const gw_chain_run_opts *o, gw_chain_result *r)
{
    gw_chain *c = NULL;
    gw_err err = {{0}};
    double gap = NAN;
    if (gw_chain_create(p, &c, &err) == GW_OK) {
        mom_ctx m = {c, 0, 0, 0, 0};
        gw_chain_run_opts oo = *o;
        oo.sample = mom_sample;
        oo.sample_ctx = &m;
        if (gw_chain_collide(c, &oo, r, &err) == GW_OK)
            gap = (m.p_last + m.impulse) / (p->n * p->mass * p->v_imp) - 1.0;
    }
    if (isnan(gap))
        printf("FAIL: %s\n", err.msg);
    gw_chain_free(c);
    return gap;
}

static void test_sensor(void)
{
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    gw_chain_params p = test_params(5, V29);
    gw_chain_result r0, r1;
    int ok = test_collide(&p, &o, &r0) == GW_OK;
    /* light (5e-5 of a bead), stiff (x_s/d ~ 1e-5) and critically damped; 1e-7
     * kg, the program's lightest: 1e-9 kg (the test's before) was refused by
     * the sensor's step bound from 2026-11-30 (1.06e8 steps estimated at 20 a
     * radian of its undamped frequency, where bdf takes about 3000 on the
     * critically damped body), and the five checks below were skipped with
     * the test passing (test_collide only printed its failure then); the
     * bound counts the damping since the thirty-fourth session, and
     * test_sensor_damping_steps runs the 1e-9 kg body */
    p.sensor.mass = 1e-7;
    p.sensor.stiffness = 1e12;
    p.sensor.damping = 2 * sqrt(p.sensor.mass * p.sensor.stiffness);
    ok &= test_collide(&p, &o, &r1) == GW_OK;
    if (ok) {
        gw_test_rel(r1.f_max, r0.f_max, 1e-4, "stiff light sensor: F_max read = rigid wall's");
        gw_test_rel(r1.tau_max, r0.tau_max, 1e-4, "stiff light sensor: tau_max = rigid wall's");
        gw_test_rel(r1.tau_n, r0.tau_n, 1e-4, "stiff light sensor: tau_N = rigid wall's");
        gw_test_rel(r1.eps_eff, r0.eps_eff, 1e-4, "stiff light sensor: eps_eff = rigid wall's");
        gw_test_abs(r1.energy_error, 0, 1e-7, "stiff light sensor: energy ledger with the sensor's dashpot");
    }
    gw_chain_result_free(&r0);
    gw_chain_result_free(&r1);
    /* a real sensor: 3 g on 2e9 N/m, lightly damped (2 % of critical) */
    gw_chain_run_opts oo = o;
    oo.dt_out = 2e-8;
    p.sensor.mass = 3e-3;
    p.sensor.stiffness = 2e9;
    p.sensor.damping = 0.02 * 2 * sqrt(p.sensor.mass * p.sensor.stiffness);
    double gap = momentum_gap(&p, &oo, &r1);
    gw_test_abs(gap, 0, 1e-5, "sensor body: momentum ledger (beads + sensor + impulse read)");
    gw_test_abs(r1.energy_error, 0, 1e-7, "sensor body: energy ledger (sensor kinetic, spring, dashpot)");
    printf("  (sensor 3 g on 2e9 N/m: F_max %.5g N at %.4g us, eps_eff %.6f)\n", r1.f_max, r1.tau_max * 1e6, r1.eps_eff);
    gw_chain_result_free(&r1);
    p.sensor.mass = p.sensor.stiffness = p.sensor.damping = 0;
    gap = momentum_gap(&p, &oo, &r1);
    gw_test_abs(gap, 0, 1e-5, "rigid sensor: momentum ledger (beads + impulse read)");
    gw_chain_result_free(&r1);
}

static void test_guide(void)
{
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    gw_chain_params p = test_params(10, V29);
    gw_chain_result r;
    double e_prev = 2;
    int falls = 1;
    for (int i = 0; i < 3; i++) {
        p.guide.coulomb = i * 0.01;
        p.guide.viscous = i * 0.05;
        if (test_collide(&p, &o, &r) != GW_OK)
            continue;
        falls &= r.eps_eff < e_prev;
        e_prev = r.eps_eff;
        if (i > 0)
            gw_test_abs(r.energy_error, 0, 1e-7, "guide friction: energy ledger");
        printf("  (guide %g N + %g N s/m: eps_eff %.6f)\n", p.guide.coulomb, p.guide.viscous, r.eps_eff);
        gw_chain_result_free(&r);
    }
    gw_test_true(falls, "guide friction: eps_eff falls as the friction grows");
}

int main(void)
{
    test_layer_limits();
    test_layer_law();
    test_thornton();
    test_visco();
    test_sensor();
    test_guide();
    return gw_test_summary("test_chain_walls");
}
