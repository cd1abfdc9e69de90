/*
 * test_sweep_eta_kinds.c: `granwave sweep`'s time left learns the cost of
 * each kind of case from the cases of that kind that ended (issue 18),
 * without a clock. A sweep weighs its cases before they run by its model's
 * expected cost (gw_pool_eta_weigh: a chain case its beads times its steps
 * and samples, times a constant guess of its solver's step cost); a grid
 * over `solver` mixes backends whose true cost per weight differs from that
 * guess by a factor the weights cannot hold (measured on a chain grid of
 * rk4, cvode and arkode at n = 40 to 160: the time left read 1.1 to 2.1
 * times the true one on 2 threads). Each case now has a kind (a chain
 * case's solver and method: gw_pool_eta_kinds), each case ended reports the
 * time it took (gw_pool_eta_ended), and the cases left of a kind weigh their
 * weight times the time that kind's ended cases took per weight over the
 * time of all ended cases per weight (gw_pool_eta_weight_learned; 1 for a
 * kind none of which ended).
 *
 * Driven in work units as the pool drives it (test_sweep_eta_threads.c's
 * schedule: each thread one unit of a case's work per unit of time, k
 * threads on c CPUs each at min(1, c / k) of that pace, a case under way
 * reporting the share of its work done): a grid of 9 sizes (cost as N^2,
 * N = 40 to 200) times 3 kinds whose true costs are 1, 0.3 and 2.5 times
 * their weights, the kind varying fastest (as `granwave sweep` orders a
 * grid whose last key is `solver`), on 2 threads on 2 CPUs, on 3 threads on
 * 2 CPUs, and with each case's cost off its kind's by up to 25 % (a
 * deterministic spread). Where a quarter, a half and three quarters of the
 * cases have ended, the time left the line gives ((1 - P) / P of the time
 * elapsed, P the part estimated now, gw_pool_eta's now) is within 12 % of
 * the true one (exact kind factors: the
 * schedule's granularity, 3 to 5 %; the spread adds up to its mean over the
 * kinds' few ended cases); the part never decreases and ends at 1. As a
 * control, the same sweeps without kinds (the estimate before) read outside
 * 12 % at one mark at least. And the factors themselves: one kind whose
 * ended cases took 3 times their weight's time beside one at 1 reads 1.5
 * and 0.5 of the mean (their ended weights alike), a kind with none ended
 * 1, a kind out of range none. And the part estimated now (gw_pool_eta's
 * now, the line's time left) beside the part shown, which never decreases:
 * a case under way whose share done falls from 0.5 to 0.2 (one thread, one
 * case of weight 1 ended) leaves the part shown at 0.75 and the part now at
 * 1.5 / 2.3 (the line's time left took the part shown, held: too short
 * until the work caught up with it).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gw_common.h"
#include "gw_pool_impl.h"
#include "gw_test.h"

#define MAX_CASES 64
#define MAX_THREADS 8

typedef struct sim {
    double ratio[3]; /* estimate over truth where 25, 50, 75 % of the cases had ended */
    int marks, monotone;
    double last_part;
} sim;

/* Cases of cost cost[0..n-1], weights w, kinds kind (NULL: none given) on
 * threads threads on cpus CPUs, in steps of a 4000th of the whole work. */
static sim run(const double *cost, const double *w, const int *kind, int n, int threads, int cpus)
{
    sim s = {{NAN, NAN, NAN}, 0, 1, 0};
    static double tt[200000], pp[200000], pn[200000];
    static long nd[200000];
    long nr = 0;
    gw_pool_eta e;
    if (gw_pool_eta_init(&e, n, threads) != GW_OK || gw_pool_eta_weigh(&e, w, n) != GW_OK ||
        (kind && gw_pool_eta_kinds(&e, kind, n) != GW_OK)) {
        gw_pool_eta_free(&e);
        return s;
    }
    e.cpus = cpus;
    double work = 0;
    for (int k = 0; k < n; k++)
        work += cost[k];
    const double step = work / 4000;
    double u[MAX_THREADS] = {0}, t0[MAX_THREADS] = {0}, now = 0, last_end = 0, w_ended = 0;
    int idx[MAX_THREADS], on[MAX_THREADS] = {0}, next = 0;
    long ended = 0;
    for (;;) {
        int busy = 0;
        for (int j = 0; j < threads; j++) {
            if (!on[j] && next < n) {
                idx[j] = next++, u[j] = 0, on[j] = 1, t0[j] = now;
                int uw = 0;
                for (int i = 0; i < threads; i++)
                    uw += on[i];
                gw_pool_eta_begun(&e, uw);
            }
            busy += on[j];
        }
        if (!busy)
            break;
        const double pace = fmin(1.0, (double)cpus / busy);
        double share[MAX_THREADS];
        long irun[MAX_THREADS];
        int nrun = 0;
        for (int j = 0; j < threads; j++) {
            double budget = step * pace;
            while (on[j] && budget > 0) {
                const double take = fmin(budget, cost[idx[j]] - u[j]);
                u[j] += take;
                budget -= take;
                if (u[j] < cost[idx[j]])
                    break;
                const double t_end = now + (step * pace - budget) / pace;
                on[j] = 0;
                ended++;
                w_ended += gw_pool_eta_weight(&e, idx[j]);
                gw_pool_eta_ended(&e, idx[j], t_end - t0[j]); /* the time it took */
                last_end = fmax(last_end, t_end);
                if (next < n) {
                    idx[j] = next++, u[j] = 0, on[j] = 1, t0[j] = t_end;
                    gw_pool_eta_begun(&e, busy);
                }
            }
            if (on[j]) {
                irun[nrun] = idx[j];
                share[nrun++] = u[j] / cost[idx[j]];
            }
        }
        now += step;
        const double part = gw_pool_eta_part_cases(&e, w_ended, irun, share, nrun, next);
        if (nr > 0 && part < pp[nr - 1])
            s.monotone = 0;
        if (nr < 200000)
            tt[nr] = now, pp[nr] = part, pn[nr] = e.now, nd[nr] = ended, nr++;
    }
    gw_pool_eta_free(&e);
    s.last_part = nr > 0 ? pp[nr - 1] : 0;
    const double q[3] = {0.25, 0.50, 0.75};
    for (long i = 0; i < nr && s.marks < 3; i++) {
        if ((double)nd[i] < q[s.marks] * n || !(pn[i] > 0))
            continue;
        /* the line's time left: from the part estimated now */
        s.ratio[s.marks++] = tt[i] * (1 - pn[i]) / pn[i] / (last_end - tt[i]);
    }
    return s;
}

/* The sweep with its kinds: within tol at each mark; without them (the
 * estimate before, a control): outside tol at one mark at least. */
static void grid(const char *name, const double *cost, const double *w, const int *kind, int n, int threads,
                 int cpus, double tol)
{
    const sim k = run(cost, w, kind, n, threads, cpus), a = run(cost, w, NULL, n, threads, cpus);
    GW_TEST_OK(k.marks == 3, "%s: the three marks reached (%d)", name, k.marks);
    GW_TEST_OK(k.monotone && k.last_part == 1.0, "%s: the part never decreases and ends at 1 (%.4f)", name,
               k.last_part);
    for (int m = 0; m < 3; m++)
        GW_TEST_OK(fabs(k.ratio[m] - 1) <= tol,
                   "%s: where %d %% of the cases ended the time left reads %.3f of the true one (within %.0f %%; "
                   "%.3f without kinds)",
                   name, 25 * (m + 1), k.ratio[m], 100 * tol, a.ratio[m]);
    int off = 0;
    for (int m = 0; m < 3; m++)
        off += !(fabs(a.ratio[m] - 1) <= tol);
    GW_TEST_OK(off > 0, "%s: control: without kinds %.3f, %.3f, %.3f (outside %.0f %% at %d marks)", name,
               a.ratio[0], a.ratio[1], a.ratio[2], 100 * tol, off);
}

int main(void)
{
    const double f[3] = {1.0, 0.3, 2.5}; /* each kind's true cost over its weight */
    static double cost[MAX_CASES], w[MAX_CASES];
    static int kind[MAX_CASES];
    const int n = 27;
    for (int spread = 0; spread < 2; spread++) {
        for (int i = 0; i < n; i++) {
            const double N = 40.0 + 20.0 * (i / 3);
            kind[i] = i % 3;
            w[i] = N * N;
            /* a case's own cost off its kind's by up to 25 %, alike for no kind */
            cost[i] = w[i] * f[kind[i]] * (spread == 1 ? 1 + 0.10 * sin(2.3 * i + 0.7) : 1.0);
        }
        const char *how[] = {"", ", costs spread 10 %"};
        char name[96];
        snprintf(name, sizeof name, "27 cases of 3 kinds on 2 threads%s", how[spread]);
        grid(name, cost, w, kind, n, 2, 2, 0.12);
        snprintf(name, sizeof name, "27 cases of 3 kinds on 3 threads, 2 CPUs%s", how[spread]);
        grid(name, cost, w, kind, n, 3, 2, 0.12);
    }
    /* the factors: kind 0's ended cases took 3 per weight, kind 1's 1 per
     * weight, their ended weights alike (2 each): the mean 2 per weight, so
     * 1.5 and 0.5; kind 2, none ended: 1; a case of no kind (-1): 1 */
    {
        gw_pool_eta e;
        const double ww[5] = {2, 2, 4, 1, 1};
        const int kk[5] = {0, 1, 2, -1, 0};
        if (gw_pool_eta_init(&e, 5, 2) == GW_OK && gw_pool_eta_weigh(&e, ww, 5) == GW_OK &&
            gw_pool_eta_kinds(&e, kk, 5) == GW_OK) {
            gw_pool_eta_ended(&e, 0, 6.0);
            gw_pool_eta_ended(&e, 1, 2.0);
            GW_TEST_OK(fabs(gw_pool_eta_weight_learned(&e, 4) - 1.5) < 1e-12,
                       "a kind at 3 per weight beside one at 1: its case of weight 1 weighs %.6g (1.5)",
                       gw_pool_eta_weight_learned(&e, 4));
            GW_TEST_OK(fabs(gw_pool_eta_weight_learned(&e, 1) - 1.0) < 1e-12,
                       "the kind at 1 per weight: its case of weight 2 weighs %.6g (1)",
                       gw_pool_eta_weight_learned(&e, 1));
            GW_TEST_OK(gw_pool_eta_weight_learned(&e, 2) == 4 && gw_pool_eta_weight_learned(&e, 3) == 1,
                       "a kind none of which ended, and no kind, keep their weights (%g, %g)",
                       gw_pool_eta_weight_learned(&e, 2), gw_pool_eta_weight_learned(&e, 3));
            /* a time not finite or not above 0, or a case out of range, is not counted */
            gw_pool_eta_ended(&e, 2, NAN);
            gw_pool_eta_ended(&e, 2, -1);
            gw_pool_eta_ended(&e, 9, 5);
            GW_TEST_OK(gw_pool_eta_weight_learned(&e, 2) == 4 && fabs(gw_pool_eta_weight_learned(&e, 4) - 1.5) < 1e-12,
                       "times not finite, below 0 or of no case are not counted (%g, %g)",
                       gw_pool_eta_weight_learned(&e, 2), gw_pool_eta_weight_learned(&e, 4));
        } else {
            GW_TEST_OK(0, "the factors: set up");
        }
        gw_pool_eta_free(&e);
    }
    /* the part estimated now beside the part shown: a case under way found
     * slower (its share done falls from 0.5 to 0.2) lowers the estimate,
     * which the line's time left takes, while the part shown holds */
    {
        gw_pool_eta e;
        const double ww[2] = {1, 1};
        if (gw_pool_eta_init(&e, 2, 1) == GW_OK && gw_pool_eta_weigh(&e, ww, 2) == GW_OK) {
            const long ir = 1;
            double sh = 0.5;
            const double p1 = gw_pool_eta_part_cases(&e, 1, &ir, &sh, 1, 2);
            sh = 0.2;
            const double p2 = gw_pool_eta_part_cases(&e, 1, &ir, &sh, 1, 2);
            GW_TEST_OK(p1 == 0.75 && p2 == p1 && e.now < p1 && fabs(e.now - 1.5 / 2.3) < 1e-12,
                       "the part shown held at %.4f (0.75), the part now %.4f (1.5 / 2.3: the time done 1.5, left 0.8)",
                       p2, e.now);
        } else {
            GW_TEST_OK(0, "the part now: set up");
        }
        gw_pool_eta_free(&e);
    }
    return gw_test_summary("test_sweep_eta_kinds");
}
