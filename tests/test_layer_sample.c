/*
 * test_layer_sample.c: pluviation and the sample format (physics.md 2.2), and
 * the impact on a small sample (physics.md 2.3-2.4) on the three backends.
 *
 * - Pluviation is deterministic for a seed: two runs give bitwise identical
 *   positions; another seed gives a different sample.
 * - After settling no overlap exceeds 1 % of R_p (the static Hertz overlap of
 *   a 5 R_m deep pile is ~1e-3 R_p; 1 % would mean particles pushed through
 *   each other).
 * - The sample file round-trips exactly (%.17g); corrupt, truncated, non-finite
 *   and negative-radius files are refused with GW_EFORMAT, a missing file with
 *   GW_EIO.
 * - Impact of a block (R_b = 0.7 R_m, 10 m/s, 20 ms) on the small sample: the
 *   energy ledger
 *   closes to 1e-4 (measured ~1e-6 with ARKode/CVODE, ~1e-5 with RK4, see
 *   test_layer_energy.c); RK4, CVODE and ARKode agree on e = V_r/V_i and on the
 *   penetration within 1e-4 relative.
 * - Impossible parameters are refused: block overlapping the layer (gap < 0),
 *   negative block radius, incidence 90 deg, friction angle 90 deg.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_layer.h"
#include "gw_test.h"

static gw_layer_make_params small(long seed)
{
    gw_layer_make_params m = gw_layer_make_params_default();
    m.n = 40;
    m.width_rm = 16;
    m.seed = seed;
    return m;
}

static int write_file(const char *path, const char *text)
{
    FILE *fp = fopen(path, "w");
    if (!fp)
        return -1;
    fputs(text, fp);
    return fclose(fp);
}

static void bad_files(void)
{
    const char *hdr = "granwave-layer-sample 1\nwidth 5\nrm 0.3\n";
    struct {
        const char *text, *what;
    } cases[] = {
        {"not a sample\n", "corrupt header"},
        {"granwave-layer-sample 1\nwidth 5\nrm 0.3\nn 2\n1 1 0.3\n", "truncated particle list"},
        {"granwave-layer-sample 1\nwidth 5\nrm 0.3\nn 1\n1 nan 0.3\n", "non-finite coordinate"},
        {"granwave-layer-sample 1\nwidth 5\nrm 0.3\nn 1\n1 1 -0.3\n", "negative radius"},
        {"granwave-layer-sample 1\nwidth 5\nrm 0.3\nn 1\n9 1 0.3\n", "particle outside the box"},
        {"granwave-layer-sample 1\nwidth abc\nrm 0.3\nn 1\n1 1 0.3\n", "bad number in the header"},
    };
    (void)hdr;
    const char *path = "test_layer_sample_bad.txt";
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        gw_layer_sample s;
        gw_err err = {{0}};
        write_file(path, cases[i].text);
        int rc = gw_layer_sample_read(path, &s, &err);
        char what[700];
        snprintf(what, sizeof what, "sample refused: %s (%s)", cases[i].what, err.msg);
        gw_test_true(rc == GW_EFORMAT && strstr(err.msg, path) != NULL, what);
    }
    remove(path);
    gw_layer_sample s;
    gw_err err = {{0}};
    gw_test_true(gw_layer_sample_read("no/such/file.txt", &s, &err) == GW_EIO, "missing sample file: GW_EIO");
}

int main(void)
{
    gw_layer_params lp = gw_layer_params_default();
    gw_layer_make_params m = small(7);
    gw_layer_sample a, b, c;
    gw_layer_make_result ra, rb, rc_;
    gw_err err = {{0}};
    int rc = gw_layer_make(&lp, &m, &a, &ra, &err);
    gw_test_true(rc == GW_OK && ra.converged, "pluviation of 40 discs converged");
    gw_layer_make(&lp, &m, &b, &rb, &err);
    m.seed = 8;
    gw_layer_make(&lp, &m, &c, &rc_, &err);
    int same = a.n == b.n, diff = 0;
    for (int i = 0; same && i < a.n; i++)
        same = a.x[i] == b.x[i] && a.y[i] == b.y[i] && a.r[i] == b.r[i];
    for (int i = 0; i < a.n && i < c.n; i++)
        diff |= a.x[i] != c.x[i];
    gw_test_true(same, "pluviation deterministic for a seed (bitwise)");
    gw_test_true(diff, "another seed gives another sample");
    gw_test_abs(ra.max_overlap, 0, 1e-2, "largest overlap after settling (u_n / R_p)");
    printf("porosity %.4f, settled in %.3g s, %.0f ms wall\n", ra.porosity, ra.t_settle, ra.wall_ms);

    const char *path = "test_layer_sample.txt";
    rc = gw_layer_sample_write(&a, path, "test_layer_sample", &err);
    gw_layer_sample d;
    if (rc == GW_OK)
        rc = gw_layer_sample_read(path, &d, &err);
    gw_test_true(rc == GW_OK, "sample written and read back");
    int exact = rc == GW_OK && d.n == a.n && d.width == a.width && d.rm == a.rm;
    for (int i = 0; exact && i < a.n; i++)
        exact = d.x[i] == a.x[i] && d.y[i] == a.y[i] && d.r[i] == a.r[i];
    gw_test_true(exact, "sample round trip is exact");
    remove(path);
    bad_files();

    /* impact on the small sample, three backends */
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.vi = 10;
    ip.rb_rm = 0.7;
    ip.t_max = 0.02;
    const gw_solver_type *types[3] = {gw_solver_rk4, gw_solver_cvode, gw_solver_arkode};
    double en[3] = {NAN, NAN, NAN}, pen[3] = {NAN, NAN, NAN};
    for (int k = 0; k < 3; k++) {
        gw_solver_params sp = gw_solver_params_default();
        sp.dt = 1e-6;
        sp.rtol = sp.atol = 1e-9;
        gw_layer_impact_result r;
        rc = gw_layer_impact(&a, &lp, &ip, types[k], &sp, NULL, &r, &err);
        char what[700];
        snprintf(what, sizeof what, "%s: impact run ok (%s)", gw_solver_type_name(types[k]), err.msg);
        gw_test_true(rc == GW_OK, what);
        if (rc != GW_OK)
            continue;
        snprintf(what, sizeof what, "%s: impact energy ledger closure", gw_solver_type_name(types[k]));
        gw_test_abs(r.energy_error, 0, 1e-4, what);
        printf("  %s: bounced %d e %.8g penetration %.8g m, E_d first contact %.4g, %.0f ms\n",
               gw_solver_type_name(types[k]), r.bounced, r.e, r.penetration,
               r.dissipated_first_contact, r.wall_ms);
        en[k] = r.e;
        pen[k] = r.penetration;
        gw_layer_impact_result_free(&r);
    }
    gw_test_rel(en[1], en[0], 1e-4, "cvode vs rk4: e = V_r/V_i");
    gw_test_rel(en[2], en[0], 1e-4, "arkode vs rk4: e = V_r/V_i");
    gw_test_rel(pen[1], pen[0], 1e-4, "cvode vs rk4: penetration (m)");
    gw_test_rel(pen[2], pen[0], 1e-4, "arkode vs rk4: penetration (m)");

    /* impossible parameters */
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 1e-6;
    gw_layer_impact_result r;
    gw_layer_impact_params bad = ip;
    bad.gap = -0.01;
    gw_test_true(gw_layer_impact(&a, &lp, &bad, gw_solver_rk4, &sp, NULL, &r, &err) == GW_EINVAL &&
                 strstr(err.msg, "gap") != NULL, "block overlapping the layer refused");
    bad = ip;
    bad.rb_rm = -1;
    gw_test_true(gw_layer_impact(&a, &lp, &bad, gw_solver_rk4, &sp, NULL, &r, &err) == GW_EINVAL &&
                 strstr(err.msg, "rb-rm") != NULL, "negative block radius refused");
    bad = ip;
    bad.alpha_deg = 90;
    gw_test_true(gw_layer_impact(&a, &lp, &bad, gw_solver_rk4, &sp, NULL, &r, &err) == GW_EINVAL,
                 "incidence 90 deg refused");
    gw_layer_params lbad = lp;
    lbad.friction_deg = 90;
    gw_test_true(gw_layer_impact(&a, &lbad, &ip, gw_solver_rk4, &sp, NULL, &r, &err) == GW_EINVAL &&
                 strstr(err.msg, "friction") != NULL, "friction angle 90 deg refused");
    gw_layer_body body = {.x = 1, .y = 1, .r = -0.1};
    gw_layer *L = NULL;
    gw_test_true(gw_layer_create(&lp, 1, &body, &L, &err) == GW_EINVAL && L == NULL,
                 "negative particle radius refused");
    gw_layer_sample_free(&a);
    gw_layer_sample_free(&b);
    gw_layer_sample_free(&c);
    gw_layer_sample_free(&d);
    return gw_test_summary("test_layer_sample");
}
