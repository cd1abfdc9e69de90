/*
 * test_study_eta_threads.c: a study's time left on several threads (issue
 * 18), without a clock. A study runs its sweeps on J threads, but once fewer
 * collisions are left than threads the last run alone (falcon --n 400:402
 * on 2 threads: the third column after the first two; wavespeed's front
 * column after its sweep, on one thread), and there the work goes at a
 * fraction of the pace so far. The progress line's time left is (1 - P) / P
 * of the time elapsed: by the share of the work done, P, it was 0.44 to 0.64
 * of the true one over the first three quarters of falcon --n 400:402 on 2
 * threads (measured in each thread's CPU time).
 *
 * The watch is driven here as the pool drives it (chain_watch.h's steps),
 * in work units: every thread does one unit of a collision's work per unit
 * of time, a collision of weight w and expected length rho (t_end /
 * t_expect, chain_watch_tail) does its work as the watch expects it to (nine
 * tenths by x = t / t_expect = min(rho, 1), the rest spread to rho, where it
 * ends), each thread takes the next collision as its own ends (in the planned
 * order), a group of collisions begins when the one before has ended. The
 * true time left is counted in those units; where the true time passes 10,
 * 25, 50, 75 and 90 % of the study's, the time left the part implies is
 * within 10 % of it. Studies: three columns of 400-402 beads on 2 threads;
 * the same with a front column of 402 beads after it on one thread
 * (wavespeed); a sweep of N = 1..60 on 2 threads; softwall's 20 rigid-wall
 * columns then 300-302 beads on 3 threads (4 CPUs); on one thread, where the
 * part is the share of the work (as before), a control; and four columns on
 * 3 threads on 2 CPUs, where threads beyond the CPUs share them (each at 2/3
 * of a CPU's pace while three run).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "chain_watch.h"
#include "gw_test.h"

#define MAX_REC 400000
#define MAX_COL 128

typedef struct log {
    double now;          /* the simulated time, in work units per thread */
    long n;
    double t[MAX_REC], part[MAX_REC];
} log_t;

static void record(void *ctx, long done, long total, double part)
{
    log_t *l = ctx;
    (void)done;
    (void)total;
    if (l->n < MAX_REC) {
        l->t[l->n] = l->now;
        l->part[l->n] = part;
        l->n++;
    }
}

/* x reached after a share u of a collision's work (the watch's profile:
 * 0.9 by min(rho, 1), the tenth left spread from there to rho; all of it by
 * rho when rho <= 1) */
static double x_at(double u, double rho)
{
    const double b = fmin(rho, 1.0);
    if (rho <= b)
        return rho * u;
    return u <= 0.9 ? b * u / 0.9 : b + (u - 0.9) / 0.1 * (rho - b);
}

typedef struct col {
    int n, group;
} col;

/* A study of ncol columns (their beads, their group), groups on threads[g]
 * threads, on cpus CPUs (threads beyond them share them: k threads at work
 * each go at cpus / k of a thread's pace), run in work units; checks the
 * implied time left at the marks. */
static void study(const char *name, const col *c, int ncol, const int *threads, int ngroup, int cpus, double tol)
{
    static log_t l;
    memset(&l, 0, sizeof l);
    chain_watch w;
    chain_watch_init(&w, record, &l);
    w.cpus = cpus; /* the machine's, here the study's own */
    double wt[MAX_COL];
    for (int g = 0, k = 0; g < ngroup; g++) {
        chain_watch_group(&w, threads[g]);
        for (; k < ncol && c[k].group == g; k++) {
            wt[k] = (double)c[k].n * c[k].n; /* beads times steps over t_expect ~ N */
            chain_watch_plan_one(&w, wt[k]);
        }
    }
    double step = 0;
    for (int k = 0; k < ncol; k++)
        step += wt[k];
    step /= 4000; /* the time step: a 4000th of the study's work */
    int next = 0;
    for (int g = 0; g < ngroup; g++) {
        chain_watch_running run[8];
        double u[8];
        int on[8] = {0}, idx[8];
        const int th = threads[g];
        for (;;) {
            int busy = 0;
            for (int j = 0; j < th; j++) { /* a thread free takes the next collision of its group */
                if (!on[j] && next < ncol && c[next].group == g) {
                    idx[j] = next++;
                    u[j] = 0;
                    on[j] = 1;
                    chain_watch_begin(&w, &run[j], wt[idx[j]], chain_watch_tail(c[idx[j]].n));
                }
                busy += on[j];
            }
            if (!busy)
                break;
            l.now += step;
            const double pace = fmin(1.0, (double)cpus / busy); /* threads beyond the CPUs share them */
            for (int j = 0; j < th; j++) {
                if (!on[j])
                    continue;
                u[j] += step * pace;
                const double rho = chain_watch_tail(c[idx[j]].n), share = fmin(u[j] / wt[idx[j]], 1.0);
                chain_watch_at(&run[j], x_at(share, rho));
                if (share >= 1.0) {
                    chain_watch_end(&run[j], 1);
                    on[j] = 0;
                }
            }
        }
    }
    chain_watch_destroy(&w);
    const double end = l.now;
    GW_TEST_OK(l.n > 0 && l.part[l.n - 1] == 1.0, "%s: the part ends at 1 (%.4f)", name, l.n ? l.part[l.n - 1] : 0);
    const double marks[] = {0.10, 0.25, 0.50, 0.75, 0.90};
    int m = 0;
    for (long i = 0; i < l.n && m < 5; i++) {
        if (l.t[i] < marks[m] * end || !(l.part[i] > 0))
            continue;
        const double est = l.t[i] * (1 - l.part[i]) / l.part[i], truth = end - l.t[i];
        GW_TEST_OK(fabs(est / truth - 1) <= tol,
                   "%s: at %.0f %% of its time (part %.3f) the time left %.3f of the true one (within %.0f %%)", name,
                   100 * marks[m], l.part[i], est / truth, 100 * tol);
        m++;
    }
    GW_TEST_OK(m == 5, "%s: every mark reached (%d)", name, m);
}

int main(void)
{
    /* falcon --n 400:402 on 2 threads */
    {
        const col c[] = {{400, 0}, {401, 0}, {402, 0}};
        const int th[] = {2};
        study("N = 400..402 on 2 threads", c, 3, th, 1, 2, 0.10);
    }
    /* wavespeed --n 400:402 on 2 threads: its front column after, on one */
    {
        const col c[] = {{400, 0}, {401, 0}, {402, 0}, {402, 1}};
        const int th[] = {2, 1};
        study("N = 400..402 on 2 threads, a front column after", c, 4, th, 2, 2, 0.10);
    }
    /* falcon --n 1:60 on 2 threads */
    {
        col c[60];
        for (int k = 0; k < 60; k++)
            c[k] = (col){k + 1, 0};
        const int th[] = {2};
        study("N = 1..60 on 2 threads", c, 60, th, 1, 2, 0.10);
    }
    /* softwall --n 300:302 on 3 threads: the rigid wall's 20 columns first */
    {
        col c[23];
        for (int k = 0; k < 20; k++)
            c[k] = (col){k + 1, 0};
        for (int k = 0; k < 3; k++)
            c[20 + k] = (col){300 + k, 1};
        const int th[] = {3, 3};
        study("N = 1..20, then 300..302, on 3 threads", c, 23, th, 2, 4, 0.10);
    }
    /* one thread: the part is the share of the work (a control) */
    {
        const col c[] = {{100, 0}, {150, 0}, {200, 0}};
        const int th[] = {1};
        study("N = 100, 150, 200 on one thread", c, 3, th, 1, 2, 0.10);
    }
    /* 3 threads on 2 CPUs (wavespeed --jobs 3 on this machine): the three
     * share the CPUs, then the fourth runs alone at a whole CPU's pace */
    {
        const col c[] = {{400, 0}, {401, 0}, {402, 0}, {403, 0}};
        const int th[] = {3};
        study("N = 400..403 on 3 threads, 2 CPUs", c, 4, th, 1, 2, 0.10);
    }
    return gw_test_summary("test_study_eta_threads");
}
