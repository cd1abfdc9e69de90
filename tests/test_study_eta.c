/*
 * test_study_eta.c: a study's share of the work done, the progress lines'
 * "P% of the work" whose ~L s left is (1 - P) / P of the time elapsed
 * (issue 18). A collision runs past its expected length t_expect until every
 * contact is open and separating (by 0.58 to 1.93 of it over N = 1 to 300;
 * chain_watch.c); counted whole at t_expect, the collisions under way said
 * 100 % for the rest of their run. Measured without a clock: a falcon study of N = 1..60 on
 * one thread (the collisions in order), its work each collision's solver steps
 * times its beads (falcon_runs.csv's steps: each step costs O(N)), the true
 * share done at each collision's end against the part the watch reported
 * then. Where the true share passes 10 %, 25 % and 50 %, the time left the
 * part implies ((1 - P) / P of the work done, at a steady pace) is within 15 %
 * of the true one ((1 - S) / S) (0.93 to 0.96, before and now: the weights
 * per t_expect follow the work; these pass before, and guard the weights).
 * Columns of N = 199 and 200 run to 1.56 t_expect: while they run, the part
 * stays under 99.5 % (0.979: a tenth of a collision's work is in its tail,
 * spread over it; it was 100 % from t_expect on, which fails before).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gw_chain_study.h"
#include "gw_test.h"

typedef struct at_ends {
    long last_done;
    double part[1024]; /* part[k]: the part reported as the k-th collision ended */
    double running;    /* the largest part reported while the last collision ran */
} at_ends;

static void watch(void *ctx, long done, long total, double part)
{
    at_ends *a = ctx;
    if (done != a->last_done && done > 0 && done < 1024)
        a->part[done] = part;
    if (done < total && part > a->running)
        a->running = part;
    a->last_done = done;
}

int main(void)
{
    gw_err err = {{0}};
    gw_chain_falcon_setup f;
    gw_chain_falcon_setup_init(&f);
    const gw_param *t = gw_chain_falcon_setup_params();
    int rc = gw_param_set(t, &f, "n", "1:60", &err) | gw_param_set(t, &f, "heights", "none", &err) |
             gw_param_set(t, &f, "solver", "cvode", &err) | gw_param_set(t, &f, "jobs", "1", &err);
    GW_TEST_OK(rc == GW_OK, "falcon setup (%s)", err.msg);
    static at_ends a;
    gw_chain_falcon_outcome o;
    rc = gw_chain_falcon_run_watch(&f, NULL, NULL, watch, &a, &o, &err);
    GW_TEST_OK(rc == GW_OK && o.ncase == 60, "falcon --n 1:60 with a watch runs (%s)", err.msg);
    if (rc == GW_OK && o.ncase == 60) {
        double total = 0, done = 0;
        for (int k = 0; k < o.ncase; k++)
            total += o.steps[k] * (k + 1); /* N = k + 1 at one velocity */
        const double marks[] = {0.10, 0.25, 0.50};
        int m = 0;
        for (int k = 0; k < o.ncase && m < 3; k++) {
            done += o.steps[k] * (k + 1);
            const double share = done / total, part = a.part[k + 1];
            if (share < marks[m])
                continue;
            const double ratio = (1 - part) / part / ((1 - share) / share);
            printf("# at N = %d: work done %.3f, part reported %.3f: time left %.2f of the true one\n", k + 1,
                   share, part, ratio);
            GW_TEST_OK(ratio > 1 / 1.15 && ratio < 1.15,
                       "past %.0f %% of the work (N = %d, %.3f done): the part %.3f gives a time left %.2f of the "
                       "true one (within 15 %%)", 100 * marks[m], k + 1, share, part, ratio);
            m++;
        }
    }
    gw_chain_falcon_outcome_free(&o);
    /* two columns of 199 and 200 beads at once (about 1.2 s each): they run
     * to 1.56 t_expect, and the part said 100 % for the last third of their
     * runs */
    static at_ends b;
    rc = gw_param_set(t, &f, "n", "199:200", &err) | gw_param_set(t, &f, "jobs", "2", &err);
    if (rc == GW_OK)
        rc = gw_chain_falcon_run_watch(&f, NULL, NULL, watch, &b, &o, &err);
    GW_TEST_OK(rc == GW_OK && o.ncase == 2, "falcon --n 199:200 with a watch runs (%s)", err.msg);
    if (rc == GW_OK) {
        printf("# N = 199, 200 at once: the largest part while they ran %.3f\n", b.running);
        GW_TEST_OK(b.running > 0.5 && b.running < 0.995, "N = 199, 200 at once: the part stays under 99.5 %% "
                   "while they run (largest %.3f; above a half: they are counted within)", b.running);
        GW_TEST_OK(b.last_done == 2 && b.part[2] == 1.0, "and is 1 at their end (%.3f)", b.part[2]);
    }
    gw_chain_falcon_outcome_free(&o);
    gw_chain_falcon_setup_clear(&f);
    return gw_test_summary("test_study_eta");
}
