/*
 * test_layer_contact.c: contact laws of the 2D layer against closed forms
 * (docs/physics.md 1.3, 2.1, 2.5), on the three backends.
 *
 * 1. Two equal discs head-on, no friction, no gravity: the relative coordinate
 *    obeys m_eff u'' = -K_n u^(3/2), m_eff = m/2, so the contact lasts
 *    tau = (4/5) B(2/5, 1/2) (5 m_eff / (4 K_n))^(2/5) v_rel^(-1/5) (F.2 with the
 *    reduced mass) and the relative velocity is reversed exactly (no dissipation).
 *    Tolerance 1e-6 on both: contact times come from the root finder, RK4 at
 *    tau/1000 has a global error ~ (dt/tau)^4 ~ 1e-12, CVODE/ARKode run at 1e-10.
 * 2. Binary impact of a block (radius r R) on one free disc at rest, head-on:
 *    elastic, momentum conserved -> V_bf/V_bi = (r^2 - 1)/(r^2 + 1) for disc
 *    masses (B.24, p = 2). Tolerance 1e-6 (same reasoning).
 * 3. A disc on the bottom wall under gravity with Hunt-Crossley damping settles
 *    to the static Hertz overlap (m g / K_n)^(2/3), K_n with R_p = R (B.3).
 *    Tolerance 1e-6: after 30 damping times the residual is far below it.
 * 4. A frictional disc sliding on the bottom wall (phi = 30 deg) decelerates at
 *    g tan(phi) until it rolls (at t = v0 / (3 g tan phi) for a disc): measured
 *    between 10 ms and 40 ms. Tolerance 1e-5 (the tangential force rides the cap
 *    up to integration error).
 * 5. Oblique binary impact of two equal discs with friction (phi = 30 deg), the
 *    contact normal at theta from the block's velocity. Rigid-body Coulomb
 *    impact (the tangential effective mass of two discs, I = m R^2 / 2, is
 *    m_t = m_eff / 3 = m / 6; elastic normal impulse P_n = m v cos theta):
 *    for tan theta > 6 mu the contact slides throughout and friction takes
 *    (1/6) (sin^2 theta - (sin theta - 6 mu cos theta)^2) of the block's
 *    energy; for tan theta < 6 mu the contact sticks, the rigid loss
 *    (1/6) sin^2 theta is all the tangential relative energy, and Mindlin's
 *    elastic tangential spring can only hand part of it back, so the loss
 *    lies below it. Checked: theta = 75 deg (slides) within 1 % of the
 *    formula (the only difference is the short elastic build-up of F_t before
 *    it reaches the cap: measured 0.4 % low); theta = 45 deg between 0.7 and 1
 *    times the sticking bound (measured 0.88). Without the discs' rotation
 *    (m_t = m_eff) the contact would stick at 75 deg and lose 3x less; a wrong
 *    cap changes the sliding loss in proportion to mu. This is the physics of
 *    the first-contact friction loss in the layer (docs/layer.md: 9 % at 45 deg).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_layer.h"
#include "gw_test.h"

typedef struct ev {
    double t_close, t_open;
} ev;

static void hook(void *ctx, double t, int a, int b, int dir)
{
    (void)a, (void)b;
    ev *e = ctx;
    if (dir > 0 && isnan(e->t_close))
        e->t_close = t;
    if (dir < 0)
        e->t_open = t;
}

static gw_solver_params solver_params(const gw_solver_type *type, double dt)
{
    gw_solver_params sp = gw_solver_params_default();
    sp.rtol = 1e-10;
    sp.atol = 1e-10;
    if (type == gw_solver_rk4)
        sp.dt = dt;
    return sp;
}

static gw_layer_params free_params(void)
{
    gw_layer_params p = gw_layer_params_default();
    p.gravity = 0;
    p.walls = 0;
    p.width = 10;
    p.friction_deg = 0;
    return p;
}

static void head_on(const gw_solver_type *type)
{
    char what[800];
    const char *nm = gw_solver_type_name(type);
    gw_layer_params p = free_params();
    const double R = 0.1, v = 1.0;
    gw_layer_body b[2] = {{.x = 5 - R - 1e-4, .y = 1, .r = R, .vx = v},
                          {.x = 5 + R + 1e-4, .y = 1, .r = R, .vx = -v}};
    gw_layer *L = NULL;
    gw_err err = {{0}};
    gw_layer_create(&p, 2, b, &L, &err);
    double m = gw_layer_mass(&p, R), K = gw_layer_kn(&p, R), meff = m / 2, vrel = 2 * v;
    double c = 0.8 * exp(lgamma(0.4) + lgamma(0.5) - lgamma(0.9));
    double tau = c * pow(5 * meff / (4 * K), 0.4) * pow(vrel, -0.2);
    ev e = {NAN, NAN};
    gw_layer_set_event_hook(L, hook, &e);
    gw_solver_params sp = solver_params(type, tau / 1000);
    int rc = gw_layer_start(L, type, &sp, &err);
    if (rc == GW_OK)
        rc = gw_layer_advance(L, 2e-4 / v + 1.5 * tau, &err);
    snprintf(what, sizeof what, "%s: head-on run ok (%s)", nm, err.msg);
    gw_test_true(rc == GW_OK, what);
    snprintf(what, sizeof what, "%s: two-disc Hertz contact time (s)", nm);
    gw_test_rel(e.t_open - e.t_close, tau, 1e-6, what);
    double s0[6], s1[6];
    gw_layer_particle(L, 0, s0);
    gw_layer_particle(L, 1, s1);
    snprintf(what, sizeof what, "%s: restitution of the relative velocity", nm);
    gw_test_rel((s1[3] - s0[3]) / vrel, 1.0, 1e-6, what);
    gw_layer_free(L);
}

static void binary(const gw_solver_type *type, double ratio)
{
    char what[800];
    const char *nm = gw_solver_type_name(type);
    gw_layer_params p = free_params();
    p.friction_deg = 30;
    const double R = 0.1, Rb = ratio * R, v = 5.0;
    gw_layer_body b[2] = {{.x = 5, .y = 2, .r = R},
                          {.x = 5, .y = 2 + R + Rb + 1e-5, .r = Rb, .vy = -v}};
    gw_layer *L = NULL;
    gw_err err = {{0}};
    gw_layer_create(&p, 2, b, &L, &err);
    gw_layer_set_block(L, 1);
    double K = gw_layer_kn(&p, 2 * R * Rb / (R + Rb));
    double mb = gw_layer_mass(&p, Rb), ms = gw_layer_mass(&p, R);
    double tau = 2.94 * pow(5 * (mb * ms / (mb + ms)) / (4 * K), 0.4) * pow(v, -0.2);
    gw_solver_params sp = solver_params(type, tau / 1000);
    int rc = gw_layer_start(L, type, &sp, &err);
    if (rc == GW_OK)
        rc = gw_layer_advance(L, 1e-5 / v + 2 * tau, &err);
    snprintf(what, sizeof what, "%s: binary run ok (%s)", nm, err.msg);
    gw_test_true(rc == GW_OK, what);
    double s[6];
    gw_layer_particle(L, 1, s);
    double r2 = ratio * ratio;
    snprintf(what, sizeof what, "%s: binary impact V_bf/V_bi, r = %g (B.24, disc masses)", nm,
             ratio);
    gw_test_rel(s[4] / -v, (r2 - 1) / (r2 + 1), 1e-6, what);
    gw_layer_free(L);
}

static void settle(void)
{
    gw_layer_params p = gw_layer_params_default();
    p.width = 1;
    p.damping = 50;
    const double R = 0.1;
    gw_layer_body b = {.x = 0.5, .y = R, .r = R};
    gw_layer *L = NULL;
    gw_err err = {{0}};
    gw_layer_create(&p, 1, &b, &L, &err);
    gw_solver_params sp = solver_params(gw_solver_rk4, 2e-6);
    int rc = gw_layer_start(L, gw_solver_rk4, &sp, &err);
    if (rc == GW_OK)
        rc = gw_layer_advance(L, 0.1, &err);
    gw_test_true(rc == GW_OK, "settle run ok");
    double s[6];
    gw_layer_particle(L, 0, s);
    double ust = pow(gw_layer_mass(&p, R) * p.gravity / gw_layer_kn(&p, R), 2.0 / 3.0);
    gw_test_rel(R - s[1], ust, 1e-6, "disc on the bottom wall: static Hertz overlap (m)");
    gw_layer_free(L);
}

static void slide(const gw_solver_type *type)
{
    char what[800];
    gw_layer_params p = gw_layer_params_default();
    p.width = 10;
    const double R = 0.1, v0 = 1.0;
    double ust = pow(gw_layer_mass(&p, R) * p.gravity / gw_layer_kn(&p, R), 2.0 / 3.0);
    gw_layer_body b = {.x = 1, .y = R - ust, .r = R, .vx = v0};
    gw_layer *L = NULL;
    gw_err err = {{0}};
    gw_layer_create(&p, 1, &b, &L, &err);
    gw_solver_params sp = solver_params(type, 2e-6);
    int rc = gw_layer_start(L, type, &sp, &err);
    double s1[6], s2[6];
    if (rc == GW_OK)
        rc = gw_layer_advance(L, 0.01, &err);
    gw_layer_particle(L, 0, s1);
    if (rc == GW_OK)
        rc = gw_layer_advance(L, 0.04, &err);
    gw_layer_particle(L, 0, s2);
    snprintf(what, sizeof what, "%s: slide run ok (%s)", gw_solver_type_name(type), err.msg);
    gw_test_true(rc == GW_OK, what);
    snprintf(what, sizeof what, "%s: sliding deceleration = g tan(phi) (m/s^2)",
             gw_solver_type_name(type));
    gw_test_rel((s1[3] - s2[3]) / 0.03, p.gravity * tan(M_PI / 6), 1e-5, what);
    gw_layer_free(L);
}

static void oblique(const gw_solver_type *type, double theta_deg)
{
    char what[800];
    const char *nm = gw_solver_type_name(type);
    gw_layer_params p = free_params();
    p.friction_deg = 30;
    const double R = 0.1, v = 5.0, th = theta_deg * M_PI / 180, mu = tan(M_PI / 6), d = 2 * R + 1e-5;
    gw_layer_body b[2] = {{.x = 5, .y = 2, .r = R},
                          {.x = 5 + d * sin(th), .y = 2 + d * cos(th), .r = R, .vy = -v}};
    gw_layer *L = NULL;
    gw_err err = {{0}};
    gw_layer_create(&p, 2, b, &L, &err);
    gw_layer_set_block(L, 1);
    double m = gw_layer_mass(&p, R), K = gw_layer_kn(&p, R);
    double tau = 2.94 * pow(5 * (m / 2) / (4 * K), 0.4) * pow(v, -0.2);
    gw_solver_params sp = solver_params(type, tau / 2000);
    int rc = gw_layer_start(L, type, &sp, &err);
    if (rc == GW_OK)
        rc = gw_layer_advance(L, 1e-5 / v + 3 * tau, &err);
    snprintf(what, sizeof what, "%s: oblique impact at %g deg runs (%s)", nm, theta_deg, err.msg);
    gw_test_true(rc == GW_OK, what);
    gw_layer_energy e;
    gw_layer_energy_of(L, &e);
    double loss = e.dissipated / (0.5 * m * v * v), sn = sin(th), cs = cos(th);
    if (tan(th) > 6 * mu) {
        double slide = (sn * sn - pow(sn - 6 * mu * cs, 2)) / 6;
        snprintf(what, sizeof what, "%s: %g deg slides throughout: friction loss / E_i against the rigid "
                 "Coulomb impact", nm, theta_deg);
        gw_test_rel(loss, slide, 0.01, what);
    } else {
        double stick = sn * sn / 6;
        printf("  %s: %g deg sticks: friction loss %.4f of E_i, rigid sticking loss %.4f\n", nm, theta_deg,
               loss, stick);
        snprintf(what, sizeof what, "%s: %g deg: friction loss within [0.7, 1] of the rigid sticking "
                 "loss sin^2/6", nm, theta_deg);
        gw_test_true(loss > 0.7 * stick && loss <= stick, what);
    }
    gw_layer_free(L);
}

int main(void)
{
    const gw_solver_type *types[3] = {gw_solver_rk4, gw_solver_cvode, gw_solver_arkode};
    for (int i = 0; i < 3; i++) {
        head_on(types[i]);
        binary(types[i], 2.0);
        binary(types[i], 0.5);
        slide(types[i]);
    }
    for (int i = 0; i < 2; i++) {
        oblique(types[i], 45);
        oblique(types[i], 75);
    }
    settle();
    return gw_test_summary("test_layer_contact");
}
