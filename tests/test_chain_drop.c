/*
 * test_chain_drop.c: the whole drop (gw_chain_drop_run; physics.md 1.1, 1.2, 1.5).
 * Steel beads, R = 4 mm, h = 5.1 mm (v_imp = sqrt(2 g h) = 0.3163 m/s), CVODE
 * BDF at rtol = atol = 1e-12 unless said otherwise.
 *  1. Undamped, N = 1 and 10: the drop's first impact (its own integration:
 *     largest peak, its time, end of the contact) equals `granwave chain` at
 *     v_imp without gravity to 1e-3 (gravity acts during the collision: measured
 *     4.4e-4 on F_max, 1.4e-4 on tau_max, 4.7e-4 on the contact time of N = 10),
 *     equals chain with the same gravity to 1e-7 (two integrations of one ODE),
 *     and first_collision is chain's result with gravity itself (1e-12).
 *  2. Undamped single bead: it leaves at v_imp (energy at x = 0 is kinetic
 *     only), flies 2 v/g and hits again with the same force (1e-6).
 *  3. Peaks do not depend on the sampling: Kuwabara-Kono (e = 0.5 at v_imp),
 *     N = 20 over 18 ms, sampled every 1 us and every 7.3 us: same impacts and
 *     peaks, times and forces within 1e-6. ARKode and RK4 find the same impacts
 *     (forces within 1e-4; measured 1e-8 and 2e-6).
 *  4. The signature of the paper's Fig. 12: in that column's sequence of impact
 *     forces a later impact is at least twice the one before it (the column
 *     does not bounce as one block), while a single bead and a rigid block (one
 *     bead of the column's mass, same contact law and damping constant) dropped
 *     the same way give strictly decreasing impact forces over >= 5 impacts.
 *  5. The energy ledger (kinetic + elastic + gravity + dissipated) closes to
 *     1e-7 of the drop's energy in every run (measured <= 6e-9 at 1e-12); the
 *     single damped bead, at rest after 0.1 s, has dissipated all of it (1e-3:
 *     what is left is the static compression under its weight).
 *  6. Gaps: with 0.1 mm between the beads, bead 1 hits the sensor alone (its
 *     first peak equals a single bead's to 1e-7) and every bead's momentum
 *     reaches the sensor as its own impact (>= N impacts in 2 ms).
 *  7. Bad parameters are refused with GW_EINVAL naming the input.
 */
#include <math.h>
#include <string.h>

#include "chain_test_util.h"
#include "gw_test.h"

#define H 5.1e-3
#define G 9.81

static gw_chain_drop_params drop_params(int n, double t_max)
{
    gw_chain_drop_params p = gw_chain_drop_params_default();
    p.chain.n = n;
    p.chain.gravity = G;
    p.height = H;
    p.t_max = t_max;
    p.peak_threshold = 0.01 * gw_chain_fmax1(p.chain.mass, p.chain.kwall, sqrt(2 * G * H));
    return p;
}

static int run(const gw_chain_drop_params *p, const gw_chain_run_opts *o, gw_chain_drop_result *r,
               const char *what)
{
    gw_err err = {{0}};
    int rc = gw_chain_drop_run(p, o, r, &err);
    if (rc != GW_OK)
        printf("FAIL: %s: %s\n", what, err.msg);
    gw_test_true(rc == GW_OK, what);
    char buf[160];
    snprintf(buf, sizeof buf, "%s: energy ledger closes to 1e-7 (got %.3g)", what, r->energy_error);
    gw_test_true(rc == GW_OK && r->energy_error < 1e-7, buf);
    return rc;
}

static void first_collision(int n)
{
    double v = sqrt(2 * G * H);
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    gw_chain_drop_params p = drop_params(n, 1e-3);
    gw_chain_drop_result r;
    char what[160];
    snprintf(what, sizeof what, "undamped drop N = %d", n);
    if (run(&p, &o, &r, what) != GW_OK || r.n_impacts < 1) {
        gw_test_true(0, "the first impact exists");
        gw_chain_drop_result_free(&r);
        return;
    }
    gw_chain_params q = test_params(n, v), qg = q;
    qg.gravity = G;
    gw_chain_result c0, cg;
    memset(&c0, 0, sizeof c0);
    memset(&cg, 0, sizeof cg);
    int ok = test_collide(&q, &o, &c0) == GW_OK && test_collide(&qg, &o, &cg) == GW_OK;
    gw_test_true(ok && c0.wall_contacts == 1 && cg.wall_contacts == 1, "chain: one wall contact");
    if (ok) {
        const gw_chain_drop_impact *im = &r.impacts[0];
        snprintf(what, sizeof what, "N = %d: drop F_max = chain's at sqrt(2gh), no gravity", n);
        gw_test_rel(im->f_max, c0.f_max, 1e-3, what);
        snprintf(what, sizeof what, "N = %d: drop tau_max = chain's, no gravity", n);
        gw_test_rel(im->t_fmax, c0.tau_max, 1e-3, what);
        snprintf(what, sizeof what, "N = %d: drop contact time = chain's tau_N, no gravity", n);
        gw_test_rel(im->t_end, c0.tau_n, 1e-3, what);
        snprintf(what, sizeof what, "N = %d: drop F_max = chain's with gravity", n);
        gw_test_rel(im->f_max, cg.f_max, 1e-7, what);
        snprintf(what, sizeof what, "N = %d: drop tau_max = chain's with gravity", n);
        gw_test_rel(im->t_fmax, cg.tau_max, 1e-7, what);
        snprintf(what, sizeof what, "N = %d: drop contact time = chain's with gravity", n);
        gw_test_rel(im->t_end, cg.tau_n, 1e-7, what);
        snprintf(what, sizeof what, "N = %d: first_collision is chain's (F_max)", n);
        gw_test_rel(r.first.f_max, cg.f_max, 1e-12, what);
        snprintf(what, sizeof what, "N = %d: first_collision is chain's (tau_N)", n);
        gw_test_rel(r.first.tau_n, cg.tau_n, 1e-12, what);
        snprintf(what, sizeof what, "N = %d: first_collision is chain's (eps_eff)", n);
        gw_test_rel(r.first.eps_eff, cg.eps_eff, 1e-12, what);
    }
    gw_chain_result_free(&c0);
    gw_chain_result_free(&cg);
    gw_chain_drop_result_free(&r);
}

static void elastic_bounce(void)
{
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    gw_chain_drop_params p = drop_params(1, 0.07);
    gw_chain_drop_result r;
    if (run(&p, &o, &r, "undamped single bead over 70 ms") == GW_OK && r.n_impacts >= 2) {
        const gw_chain_drop_impact *a = &r.impacts[0], *b = &r.impacts[1];
        gw_test_rel(-a->v_out, r.v_imp, 1e-6, "single bead leaves at v_imp");
        gw_test_rel(b->t_start - a->t_end, -2 * a->v_out / G, 1e-6, "flight time 2 v / g");
        gw_test_rel(b->v_in, r.v_imp, 1e-6, "second impact at v_imp");
        gw_test_rel(b->f_max, a->f_max, 1e-6, "second impact force = first");
        gw_test_true(r.n_impacts == 2, "two impacts in 70 ms (2 t_fall = 64.5 ms)");
    } else {
        gw_test_true(0, "two impacts");
    }
    gw_chain_drop_result_free(&r);
}

static int same_impacts(const gw_chain_drop_result *a, const gw_chain_drop_result *b, double tol,
                        const char *what)
{
    char buf[200];
    int ok = a->n_impacts == b->n_impacts;
    double worst = 0;
    for (int j = 0; ok && j < a->n_impacts; j++) {
        worst = fmax(worst, fabs(a->impacts[j].f_max - b->impacts[j].f_max) / a->impacts[j].f_max);
        worst = fmax(worst, fabs(a->impacts[j].t_fmax - b->impacts[j].t_fmax) / a->impacts[j].t_fmax);
    }
    snprintf(buf, sizeof buf, "%s: %d / %d impacts, forces and times within %.3g (tol %.3g)", what,
             a->n_impacts, b->n_impacts, worst, tol);
    gw_test_true(ok && worst <= tol, buf);
    return ok;
}

/* Strictly decreasing impact forces over at least min impacts. */
static void monotone(const gw_chain_drop_result *r, int min, const char *what)
{
    int dec = r->n_impacts >= min;
    for (int j = 1; j < r->n_impacts; j++)
        dec &= r->impacts[j].f_max < r->impacts[j - 1].f_max;
    char buf[200];
    snprintf(buf, sizeof buf, "%s: %d impacts, forces strictly decreasing (%.4g N ... %.4g N)", what,
             r->n_impacts, r->n_impacts ? r->impacts[0].f_max : NAN,
             r->n_impacts ? r->impacts[r->n_impacts - 1].f_max : NAN);
    gw_test_true(dec, buf);
}

static void damped(void)
{
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    gw_chain_drop_params p = drop_params(20, 18e-3);
    p.chain.damping = GW_DAMP_KUWABARA_KONO;
    gw_chain_params q = p.chain;
    q.n = 1;
    q.v_imp = sqrt(2 * G * H); /* with gravity, as `granwave drop --restitution` */
    gw_err err = {{0}};
    int rc = gw_chain_calibrate(&q, &o, 0.5, &p.chain.gamma, &err);
    gw_test_true(rc == GW_OK, "Kuwabara-Kono calibrated to e = 0.5 at v_imp");
    if (rc != GW_OK)
        return;
    gw_chain_drop_result r1, r2, ra, rk;
    o.dt_out = 1e-6;
    run(&p, &o, &r1, "damped N = 20, dt_out 1 us");
    o.dt_out = 7.3e-6;
    run(&p, &o, &r2, "damped N = 20, dt_out 7.3 us");
    if (same_impacts(&r1, &r2, 1e-6, "sampling 1 us / 7.3 us")) {
        int ok = r1.n_peaks == r2.n_peaks;
        double worst = 0;
        for (int j = 0; ok && j < r1.n_peaks; j++) {
            worst = fmax(worst, fabs(r1.peaks[j].f - r2.peaks[j].f) / r1.peaks[j].f);
            worst = fmax(worst, fabs(r1.peaks[j].t - r2.peaks[j].t) / r1.peaks[j].t);
            ok &= r1.peaks[j].cluster == r2.peaks[j].cluster;
        }
        char buf[160];
        snprintf(buf, sizeof buf, "sampling 1 us / 7.3 us: %d / %d peaks, same clusters, within %.3g",
                 r1.n_peaks, r2.n_peaks, worst);
        gw_test_true(ok && worst <= 1e-6, buf);
    }
    o = test_opts("arkode", "erk");
    run(&p, &o, &ra, "damped N = 20, ARKode");
    same_impacts(&r1, &ra, 1e-4, "CVODE / ARKode");
    o = test_opts("rk4", "default");
    run(&p, &o, &rk, "damped N = 20, RK4");
    same_impacts(&r1, &rk, 1e-4, "CVODE / RK4");

    /* the signature: a high impact among decreasing ones */
    double rise = 0;
    for (int j = 1; j < r1.n_impacts; j++)
        rise = fmax(rise, r1.impacts[j].f_max / r1.impacts[j - 1].f_max);
    char buf[160];
    snprintf(buf, sizeof buf, "column N = 20: %d impacts, largest ratio to the previous impact %.3g >= 2",
             r1.n_impacts, rise);
    gw_test_true(r1.n_impacts >= 4 && rise >= 2, buf);

    /* one bead, and one rigid block of the column's mass, dropped the same way */
    gw_chain_drop_result rb, rB;
    o = test_opts("cvode", "bdf");
    gw_chain_drop_params pb = p;
    pb.chain.n = 1;
    pb.t_max = 0.1;
    if (run(&pb, &o, &rb, "single damped bead over 0.1 s") == GW_OK) {
        monotone(&rb, 5, "single bead");
        gw_test_rel(rb.e_end.dissipated, rb.e0, 1e-3, "single bead at rest: all of e0 dissipated");
    }
    pb.chain.mass = 20 * p.chain.mass;
    pb.t_max = 0.2;
    if (run(&pb, &o, &rB, "rigid block (20 bead masses) over 0.2 s") == GW_OK)
        monotone(&rB, 5, "rigid block");
    gw_chain_drop_result_free(&rb);
    gw_chain_drop_result_free(&rB);
    gw_chain_drop_result_free(&r1);
    gw_chain_drop_result_free(&r2);
    gw_chain_drop_result_free(&ra);
    gw_chain_drop_result_free(&rk);
}

static void gaps(void)
{
    const int n = 4;
    double gap[3] = {1e-4, 1e-4, 1e-4};
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    gw_chain_drop_params p = drop_params(n, 2e-3);
    p.gaps = gap;
    gw_chain_drop_result r;
    if (run(&p, &o, &r, "undamped N = 4 with 0.1 mm gaps") == GW_OK && r.n_impacts >= 1) {
        gw_chain_params q = test_params(1, r.v_imp);
        q.gravity = G;
        gw_chain_result c1;
        memset(&c1, 0, sizeof c1);
        if (test_collide(&q, &o, &c1) == GW_OK)
            gw_test_rel(r.impacts[0].f_max, c1.f_max, 1e-7, "gapped column: bead 1 hits alone");
        gw_chain_result_free(&c1);
        char buf[120];
        snprintf(buf, sizeof buf, "gapped column: %d impacts in 2 ms >= N = %d", r.n_impacts, n);
        gw_test_true(r.n_impacts >= n, buf);
    }
    gw_chain_drop_result_free(&r);
}

static void refused(gw_chain_drop_params p, const char *word, const char *what)
{
    gw_err err = {{0}};
    gw_chain_drop_result r;
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    int rc = gw_chain_drop_run(&p, &o, &r, &err);
    char buf[700];
    snprintf(buf, sizeof buf, "%s refused naming '%s': %s", what, word, err.msg);
    gw_test_true(rc == GW_EINVAL && strstr(err.msg, word) != NULL, buf);
    gw_chain_drop_result_free(&r);
}

int main(void)
{
    first_collision(1);
    first_collision(10);
    elastic_bounce();
    damped();
    gaps();
    gw_chain_drop_params p = drop_params(3, 1e-3);
    double bad_gap[2] = {1e-4, -1e-4};
    gw_chain_drop_params q = p;
    q.height = -1e-3;
    refused(q, "height", "negative height");
    q = p;
    q.t_max = 0;
    refused(q, "t-max", "t_max = 0");
    q.t_max = 50;
    refused(q, "t-max", "t_max = 50 s");
    q = p;
    q.chain.gravity = 0;
    refused(q, "gravity", "no gravity");
    q = p;
    q.gaps = bad_gap;
    refused(q, "gap", "a negative gap");
    q = p;
    q.peak_threshold = NAN;
    refused(q, "peak-threshold", "NaN threshold");
    return gw_test_summary("test_chain_drop");
}
