/*
 * test_studies.c: the studies as library calls (gw_chain_study.h,
 * gw_layer_study.h, gw_sweep_run), in C so that the sanitizer build checks
 * their memory handling too.
 *
 *  - A sweep config run in memory: every case equals the single collision
 *    with the same inputs (same code: bit-equal); stopping from the progress
 *    callback returns GW_ECANCELED after the case that asked.
 *  - The Falcon study: per-case results equal gw_chain_sweep_n's (bit-equal),
 *    the fitted T_q is the least-squares slope of tau_N against N - 1
 *    recomputed here (1e-12), F_max spread on the rigid steel wall below 5 %
 *    (physics.md 1.3), v = sqrt(2 g h) for a height.
 *  - The Falcon study's velocities (gw_chain_falcon_speeds, the one rule of
 *    the program, the library and Python): heights fall in the run's gravity
 *    (9.81 when off), to 1e-15; a negative value, a speed given twice, a speed
 *    beyond 1000 m/s and a height whose fall under the run's gravity leaves the
 *    speeds [1e-9, 1000] m/s (5e7 mm at 1e4 m/s^2, 1 mm at 1e-300) refused
 *    by name, by the function and by gw_chain_falcon_run (which ran both).
 *  - Pluviation and an impact on a 30-disc sample: the impact's ledger closes
 *    to 2e-3 (the fast default's bound, tests/test_layer_cli.sh) and the
 *    ledger's components add up to its total (1e-9 of A); snapshots at 5 ms
 *    and past the end hold the block's state of the block series at that
 *    sample and at the last one (the same copy: bit-equal).
 */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_chain_study.h"
#include "gw_layer_study.h"
#include "gw_sweep.h"
#include "gw_test.h"
#include "layer_test_util.h"

static int stop_after_two(void *ctx, long done, long total)
{
    (void)ctx;
    (void)total;
    return done >= 2;
}

static void sweep_in_memory(void)
{
    const char *cfg_text = "[sweep]\nmodel = chain\n[grid]\nn = 1:3\nvimp = 0.2, 0.3\n[params]\nsolver = rk4\n";
    const gw_sweep_model *models[] = {&gw_chain_sweep_model}, *m = NULL;
    gw_sweep_config cfg;
    gw_err err = {{0}};
    int rc = gw_sweep_config_read_string(cfg_text, "test", models, 1, &cfg, &m, &err);
    gw_test_true(rc == GW_OK && cfg.ncases == 6, "sweep config: 3 x 2 cases");
    if (rc != GW_OK)
        return;
    double *v = malloc((size_t)cfg.ncases * (size_t)m->ncolumns * sizeof *v);
    rc = gw_sweep_run(&cfg, m, 2, NULL, NULL, v, &err);
    gw_test_true(rc == GW_OK, "sweep run in memory");
    int same = rc == GW_OK;
    for (long k = 0; same && k < cfg.ncases; k++) {
        gw_chain_setup s;
        gw_chain_setup_init(&s);
        s.n = 1 + k / 2;
        s.vimp = k % 2 ? 0.3 : 0.2;
        gw_param_set(gw_chain_setup_params(), &s, "solver", "rk4", &err);
        gw_chain_collision c;
        same = gw_chain_collision_run(&s, &c, &err) == GW_OK && c.r.f_max == v[k * m->ncolumns] &&
               c.r.tau_n == v[k * m->ncolumns + 2];
        gw_chain_collision_free(&c);
        gw_chain_setup_clear(&s);
    }
    gw_test_true(same, "every case = the single collision (f_max, tau_n bit-equal; last key fastest)");
    rc = gw_sweep_run(&cfg, m, 1, stop_after_two, NULL, v, &err);
    gw_test_true(rc == GW_ECANCELED && !isnan(v[m->ncolumns]) && isnan(v[2 * m->ncolumns]),
                 "progress returning non-zero stops the sweep: GW_ECANCELED, later cases NaN");
    free(v);
    gw_sweep_config_free(&cfg);
}

static void falcon(void)
{
    gw_chain_falcon_setup f;
    gw_chain_falcon_setup_init(&f);
    gw_err err = {{0}};
    const gw_param *t = gw_chain_falcon_setup_params();
    gw_param_set(t, &f, "n", "1:10", &err);
    gw_param_set(t, &f, "heights", "3.1", &err);
    gw_param_set(t, &f, "jobs", "2", &err);
    gw_chain_falcon_outcome o;
    int rc = gw_chain_falcon_run(&f, NULL, NULL, &o, &err);
    gw_test_true(rc == GW_OK && o.nv == 2 && o.nn == 10 && o.rigid, "falcon study: 2 velocities x N = 1..10");
    if (rc == GW_OK) {
        gw_test_rel(o.v_imp[1], sqrt(2 * 9.81 * 3.1e-3), 1e-15, "height 3.1 mm: v = sqrt(2 g h)");
        gw_chain_setup col = f.col;
        col.vimp = o.v_imp[0];
        gw_chain_resolved r;
        gw_chain_setup_resolve(&col, &r, &err);
        r.run.solver = gw_solver_rk4; /* the study's choice at the default accuracy */
        r.run.steps_per_tc = gw_chain_rk4_steps_per_tc(1e-6);
        r.run.dt_out = gw_chain_tau1(r.params.mass, r.params.kwall, fmax(o.v_imp[0], o.v_imp[1])) / 10;
        gw_chain_result res[20];
        int ok = gw_chain_sweep_n_progress(&r.params, &r.run, o.v_imp, 2, 1, 10, 1, NULL, NULL, res, &err) == GW_OK;
        double x[10], y[10], lo = INFINITY, hi = 0;
        for (int k = 0; ok && k < 20; k++)
            ok = res[k].f_max == o.f_max[k] && res[k].tau_n == o.tau_n[k];
        for (int k = 0; k < 10; k++) {
            x[k] = k;
            y[k] = o.tau_n[k];
            lo = fmin(lo, o.f_max[k]);
            hi = fmax(hi, o.f_max[k]);
        }
        for (int k = 0; k < 20; k++)
            gw_chain_result_free(&res[k]);
        gw_chain_resolved_free(&r);
        gw_test_true(ok, "falcon cases = gw_chain_sweep_n's (bit-equal)");
        gw_linfit fit;
        gw_fit_linear(x, y, 10, &fit);
        gw_test_rel(o.t_q[0], fit.c1, 1e-12, "T_q = slope of tau_N against N - 1");
        gw_test_abs((hi - lo) / lo, 0, 0.05, "rigid wall: F_max spread over N = 1..10 below 5 %");
    }
    gw_chain_falcon_outcome_free(&o);
    gw_chain_falcon_setup_clear(&f);
}

static void layer(void)
{
    char path[] = "/tmp/gw_test_studies_XXXXXX";
    int fd = mkstemp(path);
    if (fd >= 0)
        close(fd);
    gw_err err = {{0}};
    static const char *const pile[][2] = {{"n", "30"}, {"width-rm", "10"}, {"seed", "2"}};
    int n = 0;
    int rc = test_make_pile(path, 3, pile, &n, &err);
    gw_test_true(rc == GW_OK && n == 30, "pluviation of 30 discs, sample written");
    gw_layer_impact_setup s;
    gw_layer_impact_setup_init(&s);
    gw_param_set(gw_layer_impact_setup_params(), &s, "sample", path, &err);
    gw_param_set(gw_layer_impact_setup_params(), &s, "t-max", "0.01", &err);
    gw_param_set(gw_layer_impact_setup_params(), &s, "snapshots", "0.005,1", &err);
    gw_layer_impact_outcome o;
    memset(&o, 0, sizeof o);
    if (rc == GW_OK)
        rc = gw_layer_impact_run(&s, &o, &err);
    gw_test_true(rc == GW_OK && o.r.ns > 1 && o.nregions == o.r.nrings + 2, "impact on the sample");
    if (rc == GW_OK) {
        gw_test_abs(o.r.energy_error, 0, 2e-3, "ledger closure below 2e-3 (fast default)");
        double worst = 0;
        for (int k = 0; k < o.r.ns; k++) {
            const gw_layer_energy *e = &o.r.ledger[k];
            double sum = e->kinetic_block + e->kinetic_soil + e->strain_normal + e->strain_tangent +
                         e->mindlin_excess + e->dissipated + e->potential;
            worst = fmax(worst, fabs(sum - e->total) / o.a_total);
        }
        gw_test_abs(worst, 0, 1e-9, "ledger components add up to the total");
        /* snapshots: 5 ms is a sample time (dt_out 2e-5), 1 s is past the end:
         * the block (last particle) there is the block series' sample, bit for bit */
        int k5 = 0;
        while (k5 < o.r.ns && o.r.t[k5] < 0.005 * (1 - 1e-12))
            k5++;
        const int b = o.block_index, np = o.nparticles, last = o.r.ns - 1;
        gw_test_true(o.nsnap == 2 && np == 31 && b == 30 && o.snap_rows == 62 && k5 < o.r.ns,
                     "two snapshots of the 30 discs and the block");
        if (o.nsnap == 2 && np == 31 && k5 < o.r.ns) {
            gw_test_true(o.snap_t[0] == o.r.t[k5] && o.snap_t[1] == o.r.t_end && o.r.t[last] == o.r.t_end,
                         "snapshot times: the sample at 5 ms, the end");
            const double *s5 = o.snap + 6 * (size_t)b, *se = o.snap + 6 * ((size_t)np + b);
            gw_test_true(s5[0] == o.r.block[4 * k5] && s5[1] == o.r.block[4 * k5 + 1] &&
                         s5[4] == o.r.block[4 * k5 + 3] && se[0] == o.r.block[4 * last] &&
                         se[3] == o.r.block[4 * last + 2], "snapshot block = block series (bit-equal)");
        }
    }
    gw_layer_impact_outcome_free(&o);
    gw_layer_impact_setup_clear(&s);
    remove(path);
}

/* msg starts with prefix and holds part */
static int says(const gw_err *e, const char *prefix, const char *part)
{
    return strncmp(e->msg, prefix, strlen(prefix)) == 0 && strstr(e->msg, part) != NULL;
}

/* The falcon study's velocities, one rule for the program, the library and
 * Python (gw_chain_falcon_speeds): the speeds as given, heights as sqrt(2 g h)
 * in the run's gravity (9.81 when off); refusals name the list and the item. */
static void falcon_speeds(void)
{
    const double sp[] = {0.3, 0.5}, h[] = {5.1, 1.9};
    double v[4], hm[4];
    gw_err err = {{0}};
    int rc = gw_chain_falcon_speeds(sp, 2, h, 2, 0, v, hm, &err);
    gw_test_true(rc == GW_OK && v[0] == 0.3 && v[1] == 0.5 && isnan(hm[0]) && isnan(hm[1]) && hm[2] == 5.1 &&
                     hm[3] == 1.9, "speeds as given (h_mm NaN), then the heights");
    gw_test_rel(v[2], sqrt(2 * 9.81 * 5.1e-3), 1e-15, "gravity off: 5.1 mm falls at 9.81, sqrt(2 g h)");
    rc = gw_chain_falcon_speeds(sp, 2, h, 2, 100, v, NULL, &err);
    gw_test_rel(v[3], sqrt(2 * 100 * 1.9e-3), 1e-15, "gravity 100: 1.9 mm falls at 100 (h_mm may be NULL)");
    const double neg[] = {-1}, dup[] = {1, 1}, big[] = {5e7}, one[] = {1}, fast[] = {2000};
    rc = gw_chain_falcon_speeds(sp, 2, neg, 1, 0, v, hm, &err);
    gw_test_true(rc == GW_EINVAL && says(&err, "heights: ", "-1 must be > 0"), "a negative height refused by name");
    rc = gw_chain_falcon_speeds(dup, 2, NULL, 0, 0, v, hm, &err);
    gw_test_true(rc == GW_EINVAL && says(&err, "vimp: item 2 ", "of item 1"), "a speed given twice refused");
    rc = gw_chain_falcon_speeds(fast, 1, NULL, 0, 0, v, hm, &err);
    gw_test_true(rc == GW_EINVAL && says(&err, "vimp: item 1 is 2000, outside [1e-09, 1000]", ""),
                 "a speed beyond the chain commands' bound (the table's message)");
    rc = gw_chain_falcon_speeds(sp, 1, big, 1, 9.81, v, hm, &err);
    gw_test_true(rc == GW_OK, "5e7 mm at 9.81 m/s^2 (990 m/s): inside the table's row");
    rc = gw_chain_falcon_speeds(sp, 1, big, 1, 1e4, v, hm, &err);
    gw_test_true(rc == GW_EINVAL && says(&err, "heights: item 1 is 5e+07 mm: at gravity 10000", "31622.8 m/s"),
                 "5e7 mm at 1e4 m/s^2 falls at 31623 m/s: refused, beyond 1000 m/s");
    rc = gw_chain_falcon_speeds(sp, 1, one, 1, 1e-300, v, hm, &err);
    gw_test_true(rc == GW_EINVAL && says(&err, "heights: item 1 is 1 mm: at gravity 1e-300", "4.47214e-152"),
                 "1 mm at 1e-300 m/s^2 falls at 4.5e-152 m/s: refused, below 1e-9 m/s");
    rc = gw_chain_falcon_speeds(NULL, 0, NULL, 0, 0, v, hm, &err);
    gw_test_true(rc == GW_EINVAL && says(&err, "vimp: no impact velocity", ""), "no velocity refused");
    /* the study itself: the same rule, nothing run */
    gw_chain_falcon_setup f;
    gw_chain_falcon_setup_init(&f);
    const gw_param *t = gw_chain_falcon_setup_params();
    gw_param_set(t, &f, "n", "1:2", &err);
    gw_param_set(t, &f, "heights", "5e7", &err);
    gw_param_set(gw_chain_setup_params(), &f.col, "gravity", "1e4", &err);
    gw_chain_falcon_outcome o;
    rc = gw_chain_falcon_run(&f, NULL, NULL, &o, &err);
    gw_test_true(rc == GW_EINVAL && says(&err, "heights: item 1 is 5e+07 mm", "") && o.v_imp == NULL,
                 "gw_chain_falcon_run refuses --heights 5e7 --gravity 1e4 (ran at 31623 m/s), outcome empty");
    gw_chain_falcon_outcome_free(&o);
    gw_param_set(t, &f, "heights", "5.1", &err);
    gw_param_set(gw_chain_setup_params(), &f.col, "gravity", "100", &err);
    f.accuracy = 0; /* cvode as the column's rows say: under gravity the step study does not apply */
    rc = gw_chain_falcon_run(&f, NULL, NULL, &o, &err);
    gw_test_true(rc == GW_OK && o.nv == 2, "falcon study: heights 5.1 under gravity 100 runs");
    if (rc == GW_OK)
        gw_test_rel(o.v_imp[1], sqrt(2 * 100 * 5.1e-3), 1e-15, "the study's v for 5.1 mm at gravity 100");
    gw_chain_falcon_outcome_free(&o);
    gw_chain_falcon_setup_clear(&f);
}

int main(void)
{
    sweep_in_memory();
    falcon();
    falcon_speeds();
    layer();
    return gw_test_summary("test_studies");
}
