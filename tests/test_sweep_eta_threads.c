/*
 * test_sweep_eta_threads.c: `granwave sweep`'s time left on several threads
 * (issue 18), without a clock. A sweep runs its cases on J threads, but once
 * fewer cases are left than threads the last run alone, and there the work
 * goes at a fraction of the pace so far. Its progress line's time left is
 * (1 - P) / P of the time elapsed; by the share of the cases done (P before),
 * five alike cases on 2 threads said 0.57 of the true time left at 90 % of the
 * sweep (the fifth case alone) and 0.81 at 10 %.
 *
 * The sweep's part (gw_pool_eta, gw_pool_impl.h, what app/sweep_cmd.c's line
 * calls) is driven here as the pool drives it, in work units: each thread
 * does one unit of a case's work per unit of time, k threads at work on c
 * CPUs each at min(1, c / k) of that pace (threads beyond the CPUs share
 * them), each thread takes the next case as its own ends, and a case under
 * way reports the share of its work done (its part over the cases' typical
 * end, sweep_part); the part is taken after every step, as the sweep's
 * ticker and each case's end do. The true time left is counted in those
 * units; where the true time passes 10, 25, 50, 75 and 90 % of the sweep's,
 * the time left the part implies is within 10 % of it, the part never
 * decreases and ends at 1. Sweeps: 5 and 3 alike cases on 2 threads (the last
 * alone), 7 on 3 threads on 2 CPUs (three threads sharing two CPUs, then one
 * case alone at a whole CPU's pace), 41 on 2 threads, 40 on 4 threads on 2
 * CPUs; on one thread, where the part is the share of the work, a control.
 * Cases of unequal cost counted alike, by their count (a chain sweep of
 * N = 100..400 by 50, its cost as N^2, in the grid's order on 2 threads,
 * read 0.21 to 0.47 of the true time left: the short cases first), so the
 * sweep now weighs each case before it runs (gw_pool_eta_weigh, its model's
 * expected cost) and counts the work in weight (gw_pool_eta_part_weighed):
 * chain-like sweeps (cost N^2) in either order on 1 and 2 threads, 25 short
 * cases then a long one, cases of costs 1 to 9 on 3 threads on 2 CPUs, 6000
 * cases (the first filled level) with a long last one, the weights the costs
 * in another unit; each within 10 % (2 % on one thread). A case that ends
 * within a step hands the rest of the step to the next case. And the
 * schedule's steps: 1000 cases given to 3 threads at once as one at a time,
 * 3 threads sharing 2 CPUs.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gw_common.h"
#include "gw_pool_impl.h"
#include "gw_test.h"

#define MAX_REC 200000
#define MAX_CASES 6000
#define MAX_THREADS 8

typedef struct rec {
    long n;
    double t[MAX_REC], part[MAX_REC];
} rec;

/* Thread j takes case *next (its work from 0), and the estimator hears of the
 * cases now under way. */
static void case_begin(gw_pool_eta *e, int j, int threads, int *idx, double *u, int *on, int *next)
{
    idx[j] = (*next)++;
    u[j] = 0;
    on[j] = 1;
    int under_way = 0;
    for (int i = 0; i < threads; i++)
        under_way += on[i];
    gw_pool_eta_begun(e, under_way);
}

/* Cases of cost cost[0..n-1] (work units) on threads threads on cpus CPUs,
 * run in steps of a 4000th of the whole work; checks the time left the
 * part implies at the marks within tol. weight (NULL: the cases alike, the
 * part by their count) the weights the sweep knows before the cases run
 * (gw_pool_eta_weigh), the part then by them (gw_pool_eta_part_weighed). */
static void sweep_w(const char *name, const double *cost, const double *weight, int n, int threads, int cpus,
                    double tol)
{
    static rec r;
    memset(&r, 0, sizeof r);
    gw_pool_eta e;
    if (gw_pool_eta_init(&e, n, threads) != GW_OK) {
        GW_TEST_OK(0, "%s: gw_pool_eta_init", name);
        return;
    }
    e.cpus = cpus; /* the machine's, here the sweep's own */
    GW_TEST_OK(e.threads == threads, "%s: the pool's threads (%d)", name, e.threads);
    if (weight)
        GW_TEST_OK(gw_pool_eta_weigh(&e, weight, n) == GW_OK, "%s: weighed", name);
    double w_ended = 0;
    double work = 0;
    for (int k = 0; k < n; k++)
        work += cost[k];
    const double step = work / 4000;
    double u[MAX_THREADS] = {0}, now = 0, last_end = 0;
    int idx[MAX_THREADS], on[MAX_THREADS] = {0}, next = 0, monotone = 1;
    long ended = 0;
    for (;;) {
        int busy = 0;
        for (int j = 0; j < threads; j++) { /* a thread free takes the next case */
            if (!on[j] && next < n)
                case_begin(&e, j, threads, idx, u, on, &next);
            busy += on[j];
        }
        if (!busy)
            break;
        const double pace = fmin(1.0, (double)cpus / busy);
        double share[MAX_THREADS], wrun[MAX_THREADS];
        int nrun = 0;
        for (int j = 0; j < threads; j++) {
            /* the step's work: a case that ends within it hands what is
             * left of it to the next case (none idles until the step ends) */
            double budget = step * pace;
            while (on[j] && budget > 0) {
                const double take = fmin(budget, cost[idx[j]] - u[j]);
                u[j] += take;
                budget -= take;
                if (u[j] < cost[idx[j]])
                    break;
                on[j] = 0;
                ended++;
                w_ended += gw_pool_eta_weight(&e, idx[j]);
                last_end = fmax(last_end, now + (step * pace - budget) / pace);
                if (next < n)
                    case_begin(&e, j, threads, idx, u, on, &next);
            }
            if (on[j]) {
                wrun[nrun] = gw_pool_eta_weight(&e, idx[j]);
                share[nrun++] = u[j] / cost[idx[j]];
            }
        }
        now += step;
        const double part = weight ? gw_pool_eta_part_weighed(&e, w_ended, wrun, share, nrun, next)
                                   : gw_pool_eta_part(&e, ended, share, nrun, n - next);
        if (r.n > 0 && part < r.part[r.n - 1])
            monotone = 0;
        if (r.n < MAX_REC) {
            r.t[r.n] = now;
            r.part[r.n] = part;
            r.n++;
        }
    }
    gw_pool_eta_free(&e);
    const double end = last_end; /* the last case's end, within the last step */
    GW_TEST_OK(r.n > 0 && r.part[r.n - 1] == 1.0, "%s: the part ends at 1 (%.4f)", name, r.n ? r.part[r.n - 1] : 0);
    GW_TEST_OK(monotone, "%s: the part never decreases", name);
    const double marks[] = {0.10, 0.25, 0.50, 0.75, 0.90};
    int m = 0;
    for (long i = 0; i < r.n && m < 5; i++) {
        if (r.t[i] < marks[m] * end || !(r.part[i] > 0))
            continue;
        const double est = r.t[i] * (1 - r.part[i]) / r.part[i], truth = end - r.t[i];
        GW_TEST_OK(fabs(est / truth - 1) <= tol,
                   "%s: at %.0f %% of its time (part %.3f) the time left %.3f of the true one (within %.0f %%)", name,
                   100 * marks[m], r.part[i], est / truth, 100 * tol);
        m++;
    }
    GW_TEST_OK(m == 5, "%s: every mark reached (%d)", name, m);
}

static void sweep(const char *name, const double *cost, int n, int threads, int cpus, double tol)
{
    sweep_w(name, cost, NULL, n, threads, cpus, tol);
}

static void alike(const char *name, int n, int threads, int cpus)
{
    static double c[MAX_CASES];
    for (int k = 0; k < n; k++)
        c[k] = 1;
    sweep(name, c, n, threads, cpus, 0.10);
}

/* Cases of unequal cost, weighed by it before they run (gw_pool_eta_weigh):
 * the costs given as the weights times scale (a weight's unit is its
 * model's: only the ratios count) */
static void weighed(const char *name, const double *cost, int n, int threads, int cpus, double scale, double tol)
{
    static double w[MAX_CASES];
    for (int k = 0; k < n; k++)
        w[k] = cost[k] / scale;
    sweep_w(name, cost, w, n, threads, cpus, tol);
}

int main(void)
{
    alike("5 cases on 2 threads", 5, 2, 2);
    alike("3 cases on 2 threads", 3, 2, 2);
    alike("7 cases on 3 threads, 2 CPUs", 7, 3, 2);
    alike("41 cases on 2 threads", 41, 2, 2);
    alike("40 cases on 4 threads, 2 CPUs", 40, 4, 2);
    alike("4 cases on one thread", 4, 1, 2); /* the share of the work (a control) */
    /* cases of unequal cost, their weights known (issue 18): a chain sweep of
     * N = 10..150 by 10 (its cost as N^2) in the grid's order, the short cases
     * first, on one thread, on 2, and the costliest first on 2; 25 short
     * cases then one long one (N = 1..25, 150) on one thread; 20 cases of
     * costs 1 to 9 in a cycle on 3 threads on 2 CPUs; 6000 cases (more than
     * GW_POOL_ETA_ONE_BY_ONE: the first of them filled level) of costs 1
     * and 5 in turn, a last one of 3000, on 4 threads on 2 CPUs. Alike, by
     * their count, these read 0.03 to 0.7 of the true time left. */
    {
        static double c[MAX_CASES];
        for (int k = 0; k < 15; k++)
            c[k] = (10.0 * (k + 1)) * (10.0 * (k + 1));
        weighed("chain N = 10..150 on one thread, weighed", c, 15, 1, 2, 7.0, 0.02);
        weighed("chain N = 10..150 on 2 threads, weighed", c, 15, 2, 2, 0.01, 0.10);
        for (int k = 0; k < 15; k++)
            c[k] = (10.0 * (15 - k)) * (10.0 * (15 - k));
        weighed("chain N = 150..10 on 2 threads, weighed", c, 15, 2, 2, 1.0, 0.10);
        for (int k = 0; k < 25; k++)
            c[k] = (k + 1.0) * (k + 1.0);
        c[25] = 150.0 * 150.0;
        weighed("chain N = 1..25, 150 on one thread, weighed", c, 26, 1, 2, 3.0, 0.02);
        for (int k = 0; k < 20; k++)
            c[k] = 1 + k % 9;
        weighed("20 cases of 1 to 9 on 3 threads, 2 CPUs, weighed", c, 20, 3, 2, 1.0, 0.10);
        for (int k = 0; k < 6000; k++)
            c[k] = k % 2 ? 5 : 1;
        c[5999] = 3000;
        weighed("6000 cases, the last long, on 4 threads, 2 CPUs, weighed", c, 6000, 4, 2, 1.0, 0.10);
        /* weights not known (NaN, 0) count as the mean of the others */
        double w[4] = {2, NAN, 0, 4};
        gw_pool_eta e;
        if (gw_pool_eta_init(&e, 4, 1) == GW_OK && gw_pool_eta_weigh(&e, w, 4) == GW_OK) {
            GW_TEST_OK(gw_pool_eta_weight(&e, 1) == 3 && gw_pool_eta_weight(&e, 2) == 3 && gw_pool_eta_weight(&e, 3) == 4 &&
                           gw_pool_eta_weight(&e, 7) == 1,
                       "weights not known counted as the mean of the others (%g, %g)", gw_pool_eta_weight(&e, 1),
                       gw_pool_eta_weight(&e, 2));
            /* on one thread, case 0 ended and case 1 half done: (2 + 1.5) of 12 */
            const double sh = 0.5, wr = gw_pool_eta_weight(&e, 1);
            const double part = gw_pool_eta_part_weighed(&e, 2, &wr, &sh, 1, 2);
            GW_TEST_OK(fabs(part - 3.5 / 12) < 1e-12, "one thread: the part the weight done over the whole, %.6f (%.6f)",
                       part, 3.5 / 12);
        } else {
            GW_TEST_OK(0, "weights not known: set up");
        }
        gw_pool_eta_free(&e);
    }
    /* the schedule's own steps: n alike cases given in whole rounds as one
     * at a time would, and the span with threads sharing the CPUs */
    {
        double a[3] = {0.2, 0.7, 0.5}, b[3] = {0.2, 0.7, 0.5}; /* heaps: a one at a time, b at once */
        for (int k = 0; k < 1000; k++)
            gw_pool_give(a, 3, 1.0);
        gw_pool_give_each(b, 3, 1000, 1.0);
        const double sa = gw_pool_span(a, 3, 3), sb = gw_pool_span(b, 3, 3);
        GW_TEST_OK(sa == sb && fabs(sa - 334.2) < 1e-9, "1000 cases on 3 threads free at 0.2, 0.7, 0.5: %.9g and %.9g (334.2)",
                   sa, sb);
        double h[3] = {0, 0, 0};
        gw_pool_give_each(h, 3, 3, 1.0);
        /* three threads on 2 CPUs, each at 2/3 of a CPU's pace: 1.5 */
        GW_TEST_OK(fabs(gw_pool_span(h, 3, 2) - 1.5) < 1e-12, "3 alike cases on 3 threads on 2 CPUs: %.6g (1.5)",
                   gw_pool_span(h, 3, 2));
    }
    return gw_test_summary("test_sweep_eta_threads");
}
