/*
 * test_sensor_chatter.c: a column on a light sensor body.
 * 1. Bead 1 chattering on a 1e-4 kg body on 1e3 N/m (about 60 wall contacts)
 *    amplifies the integration's error: eps_eff moved by 5e-3 with dt-out and
 *    with the tolerances (0.9923 by default, 0.9894 at dt-out 3e-8), with no
 *    word. The result's warnings now name the chatter (its wall contacts) and
 *    the eps_eff of a rerun at tolerances 10 times tighter beside the run's,
 *    whose difference is the spread measured; a column on a rigid sensor, and
 *    a body whose rerun agrees, say nothing. The kind and the spread are the
 *    result's public members chatter_kind and chatter_spread (they were kept
 *    in a hidden tail after the velocities, freed with them).
 * 2. The stored trace's bound (5 GB of files) was checked before the run over
 *    the collision's expected length, but a default run that has not ended
 *    there goes on (up to 50 default t-max) and stored every row: with the
 *    bound lowered (chain_trace_limit_set) to rows that the check passes, the
 *    trace now stops at the bound, the run goes on to its end, and the warning
 *    says where the trace stops and names --dt-out.
 * 3. falcon's stored force traces (N = 7, 15, 30) were bounded the same way
 *    and cut there without a word: with the bound lowered below the N = 7
 *    trace's rows, the study's warnings say where it stops (none at the 5 GB
 *    bound, where the whole trace is kept).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_test_util.h"
#include "chain_model.h"
#include "chain_wall.h"
#include "gw_chain_study.h"
#include "gw_param.h"
#include "gw_test.h"

static int run(gw_chain_params p, gw_chain_run_opts *o, gw_chain_result *r, char **w)
{
    gw_chain *c = NULL;
    gw_err err = {{0}};
    if (gw_chain_create(&p, &c, &err) != GW_OK)
        return -1;
    int rc = gw_chain_collide(c, o, r, &err);
    if (rc == GW_OK && w)
        rc = gw_chain_result_warnings(r, w);
    if (rc != GW_OK)
        fprintf(stderr, "run: %s\n", err.msg);
    gw_chain_free(c);
    return rc;
}

static gw_chain_params sensor(int n, double m, double k)
{
    gw_chain_params p = test_params(n, 0.3);
    p.sensor.mass = m;
    p.sensor.stiffness = k;
    return p;
}

/* the eps_eff of the rerun the warning gives ("gave eps_eff X against Y") */
static double rerun_eps(const char *w)
{
    const char *s = w ? strstr(w, "gave eps_eff ") : NULL;
    return s ? strtod(s + 13, NULL) : NAN;
}

/* falcon --n 6:7 --heights none on a 1e-3 kg body, its N = 7 trace kept (C
 * only: setup.traces); GW_OK or the run's code */
static int falcon_traces(gw_chain_falcon_outcome *o)
{
    const gw_param *t = gw_chain_falcon_setup_params();
    gw_chain_falcon_setup s;
    gw_err err = {{0}};
    int rc = gw_chain_falcon_setup_init(&s);
    const char *set[][2] = {{"n", "6:7"},           {"vimp", "0.3"}, {"heights", "none"},
                            {"sensor_mass", "1e-3"}, {"sensor_stiffness", "1e3"}, {"jobs", "1"}};
    for (size_t i = 0; rc == GW_OK && i < sizeof set / sizeof set[0]; i++)
        rc = gw_param_set(t, &s, set[i][0], set[i][1], &err);
    s.traces = 1;
    if (rc == GW_OK)
        rc = gw_chain_falcon_run(&s, NULL, NULL, o, &err);
    if (rc != GW_OK)
        printf("  falcon: %s\n", err.msg);
    gw_chain_falcon_setup_clear(&s);
    return rc;
}

int main(void)
{
    /* 1: the chatter */
    gw_chain_result r;
    char *w = NULL;
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    GW_TEST_OK(run(sensor(5, 1e-4, 1e3), &o, &r, &w) == GW_OK, "chatter: the run");
    GW_TEST_OK(r.converged && r.wall_contacts >= 20, "chatter: bead 1 chattered (%d wall contacts)",
                 r.wall_contacts);
    GW_TEST_OK(w && strstr(w, "chattered on the sensor body") && strstr(w, "wall contact closed"),
                 "chatter: the warning names the chatter");
    char cnt[32];
    snprintf(cnt, sizeof cnt, "closed %d times", r.wall_contacts);
    GW_TEST_OK(w && strstr(w, cnt), "chatter: the warning gives the run's %d wall contacts", r.wall_contacts);
    const double e_rerun = rerun_eps(w);
    /* the rerun at rtol = atol = 1e-13, run here: its eps_eff is the warning's */
    gw_chain_run_opts o13 = o;
    o13.sp.rtol = o13.sp.atol = 1e-13;
    gw_chain_result r13;
    GW_TEST_OK(run(sensor(5, 1e-4, 1e3), &o13, &r13, NULL) == GW_OK, "chatter: the run at 1e-13");
    gw_test_rel(e_rerun, r13.eps_eff, 1e-5, "chatter: the warning's rerun eps_eff is the run at 1e-13's");
    GW_TEST_OK(fabs(r13.eps_eff - r.eps_eff) > 1e-4,
                 "chatter: the spread is real (eps_eff %.6g at 1e-12, %.6g at 1e-13)", r.eps_eff, r13.eps_eff);
    /* the kind and spread are the result's public members (they were kept in
     * a hidden tail of the velocities' allocation, read by internal calls) */
    GW_TEST_OK(r.chatter_kind == GW_CHAIN_CHATTER_MOVED, "chatter: the result's chatter_kind is MOVED (%d)",
               r.chatter_kind);
    gw_test_rel(r.chatter_spread, fabs(r13.eps_eff - r.eps_eff), 1e-6,
                "chatter: the result's chatter_spread is |eps_eff - the rerun's|");
    gw_chain_result_free(&r13);
    gw_chain_result_free(&r);
    GW_TEST_OK(r.chatter_kind == GW_CHAIN_CHATTER_MOVED && chain_result_chatter_value(&r) == r.chatter_spread,
               "chatter: the kind and spread outlive gw_chain_result_free (members, not the freed tail): %g",
               chain_result_chatter_value(&r));
    /* a result filled by hand: its members are what it says */
    gw_chain_result hand = {.n = 1, .chatter_kind = GW_CHAIN_CHATTER_COSTLY};
    GW_TEST_OK(chain_result_chatter_value(&hand) == -1, "a result filled by hand, kind COSTLY: chatter -1 (%g)",
               chain_result_chatter_value(&hand));
    free(w);
    w = NULL;

    /* a rigid sensor (one wall contact) and a chatter whose rerun agrees: nothing */
    GW_TEST_OK(run(test_params(5, 0.3), &o, &r, &w) == GW_OK && !(w && strstr(w, "chattered")) &&
                   r.chatter_kind == GW_CHAIN_CHATTER_NONE && r.chatter_spread == 0,
                 "rigid sensor: no chatter warning, chatter_kind NONE");
    gw_chain_result_free(&r);
    free(w);
    w = NULL;
    GW_TEST_OK(run(sensor(2, 1e-4, 1e3), &o, &r, &w) == GW_OK && r.wall_contacts >= 10 &&
                     !(w && strstr(w, "chattered")),
                 "2 beads on the body: %d wall contacts, a rerun that agrees, no warning", r.wall_contacts);
    gw_chain_result_free(&r);
    free(w);
    w = NULL;

    /* 2: the stored trace past its bound. n = 3 on a 1e-3 kg body: the check
     * covers the expected length (the ride on the spring included), about
     * 49,000 rows; the run goes on to about 76,000. */
    const int n = 3;
    double rows = 0;
    const double per_row = (2.0 * n + 2) * (GW_HAVE_HDF5 ? 28.0 : 20.0);
    gw_chain_run_opts ot = test_opts("cvode", "bdf");
    gw_chain_trace full;
    gw_chain_trace_init(&full, n);
    ot.sample = gw_chain_trace_sample;
    ot.sample_ctx = &full;
    GW_TEST_OK(run(sensor(n, 1e-3, 1e3), &ot, &r, &w) == GW_OK, "trace: the run at the 5 GB bound");
    const double t_end = r.t_end, eps = r.eps_eff;
    GW_TEST_OK(full.len > 1000 && full.t[full.len - 1] == t_end && !chain_trace_cut(&full, t_end),
                 "trace: unbounded, %zu rows to its end", full.len);
    gw_chain_result_free(&r);
    free(w);
    w = NULL;
    rows = floor(0.8 * (double)full.len);

    chain_trace_limit_set(rows * per_row);
    gw_chain_trace tr;
    gw_chain_trace_init(&tr, n);
    ot.sample_ctx = &tr;
    gw_err err = {{0}};
    gw_chain_params pc = sensor(n, 1e-3, 1e3);
    GW_TEST_OK(gw_chain_run_check(&pc, &ot, &err) == GW_OK, "trace: the check before the run passes %g rows%s%s",
               rows, err.msg[0] ? ": " : "", err.msg);
    GW_TEST_OK(run(sensor(n, 1e-3, 1e3), &ot, &r, &w) == GW_OK, "trace: the run at a bound of %g rows", rows);
    GW_TEST_OK(tr.len == (size_t)rows, "trace: stops at the bound (%zu rows)", tr.len);
    GW_TEST_OK(r.t_end == t_end && r.eps_eff == eps, "trace: the run goes on to the same end and eps_eff");
    GW_TEST_OK(memcmp(tr.t, full.t, tr.len * sizeof *tr.t) == 0 &&
                     memcmp(tr.x, full.x, tr.len * (size_t)n * sizeof *tr.x) == 0,
                 "trace: its rows are the unbounded trace's first");
    char *tw = NULL;
    GW_TEST_OK(chain_trace_cut_warnings(&tr, r.t_end, "--dt-out", &tw) == GW_OK && tw &&
                     strstr(tw, "stored trace stops at t = ") && strstr(tw, "--dt-out"),
                 "trace: the warning says where it stops, naming --dt-out");
    char *tw0 = NULL;
    GW_TEST_OK(chain_trace_cut_warnings(&full, t_end, "--dt-out", &tw0) == GW_OK && !tw0,
                 "trace: none for the whole trace");
    free(tw);
    free(tw0);
    chain_trace_limit_set(0);
    gw_chain_result_free(&r);
    free(w);
    gw_chain_trace_free(&tr);
    gw_chain_trace_free(&full);

    /* 3: falcon's N = 7 trace at the 5 GB bound (whole), then below its rows */
    gw_chain_falcon_outcome fo;
    int frc = falcon_traces(&fo);
    const size_t flen = frc == GW_OK && fo.ntrace == 1 ? fo.trace[0].tr.len : 0;
    GW_TEST_OK(frc == GW_OK && fo.ntrace == 1 && flen > 1000, "falcon: the N = 7 trace, %zu rows", flen);
    GW_TEST_OK(frc == GW_OK && !(fo.warnings && strstr(fo.warnings, "stored trace stops")),
               "falcon: no cut trace at the 5 GB bound");
    gw_chain_falcon_outcome_free(&fo);
    const double frows = floor(0.8 * (double)flen);
    chain_trace_limit_set(frows * (2.0 * 7 + 2) * (GW_HAVE_HDF5 ? 28.0 : 20.0));
    frc = falcon_traces(&fo);
    GW_TEST_OK(frc == GW_OK && fo.ntrace == 1 && fo.trace[0].tr.len == (size_t)frows,
               "falcon: the trace stops at a bound of %g rows", frows);
    const char *fw = frc == GW_OK && fo.warnings ? strstr(fo.warnings, "the stored trace stops at t = ") : NULL;
    GW_TEST_OK(fw && strstr(fw, "rows of 7 beads") && strstr(fw, "--dt-out"),
               "falcon: the warning says where the N = 7 trace stops, naming --dt-out: %.120s", fw ? fw : "(none)");
    gw_chain_falcon_outcome_free(&fo);
    chain_trace_limit_set(0);
    return gw_test_summary("test_sensor_chatter");
}
