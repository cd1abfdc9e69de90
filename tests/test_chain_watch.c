/*
 * test_chain_watch.c: a study's progress within its collisions
 * (gw_chain_falcon_run_watch, gw_chain_wavespeed_run_watch,
 * gw_chain_softwall_run_watch; issue 18). On 3 threads:
 *  - the watch is never called twice at once (a flag set inside it), and it
 *    is called within the collisions (many more calls than collisions);
 *  - done counts up to total, every collision of the study (wavespeed's front
 *    columns, softwall's 20 rigid-wall columns), part stays in [0, 1], never
 *    decreases (to 1e-12: sums of weights), and ends at 1;
 *  - the per-collision gw_progress_fn keeps its contract (falcon: once per
 *    collision, done 1..ncase; softwall: once per wall);
 *  - the results are those of the study without a watch, bit for bit.
 */
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>

#include "gw_chain_study.h"
#include "gw_test.h"

typedef struct seen {
    atomic_int inside;   /* 1 while a call runs */
    int overlaps;        /* calls that found another under way */
    long calls, last_done, total, bad_total, done_back;
    double part, part_back, part_out; /* last part; the largest decrease; the largest step out of [0, 1] */
} seen;

static void watch(void *ctx, long done, long total, double part)
{
    seen *s = ctx;
    if (atomic_exchange(&s->inside, 1))
        s->overlaps++;
    if (s->calls++ == 0)
        s->total = total;
    s->bad_total += total != s->total;
    if (done < s->last_done)
        s->done_back++;
    if (s->part - part > s->part_back)
        s->part_back = s->part - part;
    if (part < 0 || part > 1)
        s->part_out = fmax(s->part_out, fmax(-part, part - 1));
    s->last_done = done;
    s->part = part;
    atomic_store(&s->inside, 0);
}

typedef struct counts {
    long calls, bad; /* bad: a done that is not the previous plus one */
    long last;
} counts;

static int per_case(void *ctx, long done, long total)
{
    counts *c = ctx;
    (void)total;
    c->bad += done != c->last + 1;
    c->last = done;
    c->calls++;
    return 0;
}

static void check_seen(const seen *s, const char *study, long total)
{
    GW_TEST_OK(s->overlaps == 0, "%s: never two watch calls at once (%d overlaps in %ld calls)", study, s->overlaps,
               s->calls);
    GW_TEST_OK(s->calls >= 10 * total, "%s: called within the collisions (%ld calls, %ld collisions)", study,
               s->calls, total);
    GW_TEST_OK(s->total == total && s->bad_total == 0, "%s: total %ld in every call (the study's %ld)", study,
               s->total, total);
    GW_TEST_OK(s->last_done == total && s->done_back == 0, "%s: done up to %ld, never back (last %ld)", study, total,
               s->last_done);
    GW_TEST_OK(s->part_out == 0 && s->part_back <= 1e-12, "%s: part in [0, 1] and never back (out by %g, back %g)",
               study, s->part_out, s->part_back);
    gw_test_abs(s->part, 1.0, 1e-9, "part at the end");
}

static int same(const double *a, const double *b, int n)
{
    return memcmp(a, b, (size_t)n * sizeof *a) == 0;
}

int main(void)
{
    gw_err err = {{0}};
    /* falcon: N = 20..28 at 0.3 m/s under cvode, 3 threads */
    {
        gw_chain_falcon_setup f;
        gw_chain_falcon_setup_init(&f);
        const gw_param *t = gw_chain_falcon_setup_params();
        int rc = gw_param_set(t, &f, "n", "20:28", &err) | gw_param_set(t, &f, "heights", "none", &err) |
                 gw_param_set(t, &f, "solver", "cvode", &err) | gw_param_set(t, &f, "jobs", "3", &err);
        GW_TEST_OK(rc == GW_OK, "falcon setup (%s)", err.msg);
        seen s = {0};
        counts c = {0};
        gw_chain_falcon_outcome a, b;
        rc = gw_chain_falcon_run_watch(&f, per_case, &c, watch, &s, &a, &err);
        GW_TEST_OK(rc == GW_OK, "falcon with a watch runs (%s)", err.msg);
        if (rc == GW_OK) {
            check_seen(&s, "falcon", a.ncase);
            GW_TEST_OK(c.calls == a.ncase && c.bad == 0, "falcon: progress once per collision, 1..%d (%ld calls)",
                       a.ncase, c.calls);
            rc = gw_chain_falcon_run(&f, NULL, NULL, &b, &err);
            GW_TEST_OK(rc == GW_OK && same(a.f_max, b.f_max, a.ncase) && same(a.tau_n, b.tau_n, a.ncase) &&
                           same(a.t_q, b.t_q, a.nv),
                       "falcon: F_max, tau_N and T_q those without a watch, bit for bit");
            gw_chain_falcon_outcome_free(&b);
        }
        gw_chain_falcon_outcome_free(&a);
        /* a NULL watch is the plain run */
        rc = gw_chain_falcon_run_watch(&f, NULL, NULL, NULL, NULL, &a, &err);
        GW_TEST_OK(rc == GW_OK && a.ncase == 9, "falcon: a NULL watch runs (%d collisions)", a.ncase);
        gw_chain_falcon_outcome_free(&a);
        gw_chain_falcon_setup_clear(&f);
    }
    /* wavespeed: N = 10..14 at two speeds, and a front column at each */
    {
        gw_chain_wavespeed_setup w;
        gw_chain_wavespeed_setup_init(&w);
        const gw_param *t = gw_chain_wavespeed_setup_params();
        int rc = gw_param_set(t, &w, "n", "10:14", &err) | gw_param_set(t, &w, "vimp", "0.3,0.5", &err) |
                 gw_param_set(t, &w, "jobs", "3", &err);
        GW_TEST_OK(rc == GW_OK, "wavespeed setup (%s)", err.msg);
        seen s = {0};
        gw_chain_wavespeed_outcome a, b;
        rc = gw_chain_wavespeed_run_watch(&w, NULL, NULL, watch, &s, &a, &err);
        GW_TEST_OK(rc == GW_OK, "wavespeed with a watch runs (%s)", err.msg);
        if (rc == GW_OK) {
            check_seen(&s, "wavespeed", (long)a.ncase + a.nv);
            rc = gw_chain_wavespeed_run(&w, NULL, NULL, &b, &err);
            GW_TEST_OK(rc == GW_OK && same(a.v_tq, b.v_tq, a.nv) && same(a.v_front, b.v_front, a.nv),
                       "wavespeed: 4R/T_q and v_front those without a watch, bit for bit");
            gw_chain_wavespeed_outcome_free(&b);
        }
        gw_chain_wavespeed_outcome_free(&a);
        gw_chain_wavespeed_setup_clear(&w);
    }
    /* softwall: N = 1..6 on the default wall, after the rigid wall's 20 */
    {
        gw_chain_softwall_setup w;
        gw_chain_softwall_setup_init(&w);
        const gw_param *t = gw_chain_softwall_setup_params();
        int rc = gw_param_set(t, &w, "n", "1:6", &err) | gw_param_set(t, &w, "jobs", "3", &err);
        GW_TEST_OK(rc == GW_OK, "softwall setup (%s)", err.msg);
        seen s = {0};
        counts c = {0};
        gw_chain_softwall_outcome a, b;
        rc = gw_chain_softwall_run_watch(&w, per_case, &c, watch, &s, &a, &err);
        GW_TEST_OK(rc == GW_OK, "softwall with a watch runs (%s)", err.msg);
        if (rc == GW_OK) {
            check_seen(&s, "softwall", 20L + a.ncase);
            GW_TEST_OK(c.calls == a.nw && c.bad == 0, "softwall: progress once per wall (%ld calls, %d walls)",
                       c.calls, a.nw);
            rc = gw_chain_softwall_run(&w, NULL, NULL, &b, &err);
            GW_TEST_OK(rc == GW_OK && same(a.f_max, b.f_max, a.ncase) && same(a.tau_max, b.tau_max, a.ncase),
                       "softwall: F_max and tau_max those without a watch, bit for bit");
            gw_chain_softwall_outcome_free(&b);
        }
        gw_chain_softwall_outcome_free(&a);
        gw_chain_softwall_setup_clear(&w);
    }
    return gw_test_summary("test_chain_watch");
}
