/*
 * bench_chain.c: performance of the chain model and the solver backends.
 * Never a pass/fail test: prints measurements, as ratios where possible, since
 * the machines are noisy.
 *
 *  1. RHS cost: ns per bead per evaluation of the model's right-hand side
 *     (through gw_system, state interleaved [x, v]), against a bound measured in
 *     the same run: a plain loop over separate x and v arrays computing only the
 *     Hertz forces k d sqrt(d) and accelerations (no kinematics, no function
 *     pointer). Ratio = RHS / bound.
 *  2. Per backend, a 40-bead column at v_imp = 0.3 m/s with the default chain
 *     tolerances: wall time, steps, RHS evaluations, ns per bead-step, the
 *     fraction of the time spent in the RHS, and F_max / tau_N error against a
 *     tight reference (RK4 with dt = T_c / 3200).
 * Usage: bench_chain [reps]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"

static volatile double sink;

static double bound_loop(int n, const double *x, double *a, double k, double m1, int reps)
{
    double t0 = gw_clock_ms();
    for (int r = 0; r < reps; r++) {
        double fprev = x[0] > 0 ? k * x[0] * sqrt(x[0]) : 0;
        for (int i = 0; i < n - 1; i++) {
            double d = x[i + 1] - x[i];
            double f = d > 0 ? k * d * sqrt(d) : 0;
            a[i] = (f - fprev) * m1;
            fprev = f;
        }
        a[n - 1] = -fprev * m1;
        sink += a[n / 2];
    }
    return (gw_clock_ms() - t0) * 1e6 / ((double)reps * n);
}

int main(int argc, char **argv)
{
    int reps = argc > 1 ? atoi(argv[1]) : 2000;
    if (reps < 1)
        reps = 1;
    printf("granwave %s bench_chain (reps %d)\n\n1. right-hand side, ns per bead per evaluation\n", gw_version(), reps);
    printf("%10s %12s %12s %8s\n", "beads", "model RHS", "bound", "ratio");
    const int sizes[] = {40, 1000, 100000};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        int n = sizes[s];
        gw_chain_params p = gw_chain_params_default();
        p.n = n;
        gw_chain *c = NULL;
        gw_err err;
        if (gw_chain_create(&p, &c, &err) != GW_OK) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
        const gw_system *sys = gw_chain_system(c);
        double *y = malloc((size_t)sys->dim * sizeof *y), *yd = malloc((size_t)sys->dim * sizeof *yd);
        double *x = malloc((size_t)n * sizeof *x), *a = malloc((size_t)n * sizeof *a);
        /* a compressed state: every contact loaded (worst case, no branch skips) */
        for (int i = 0; i < n; i++) {
            x[i] = 1e-6 * (1 + 0.01 * i);
            y[2 * i] = x[i];
            y[2 * i + 1] = 0.1;
        }
        int rr = (int)fmax(1, reps * 40.0 / n);
        double t0 = gw_clock_ms();
        for (int r = 0; r < rr; r++) {
            sys->rhs(0, y, yd, sys->params);
            sink += yd[n];
        }
        double model = (gw_clock_ms() - t0) * 1e6 / ((double)rr * n);
        double bound = bound_loop(n, x, a, p.k, 1 / p.mass, rr);
        printf("%10d %12.3f %12.3f %8.2f\n", n, model, bound, model / bound);
        free(y);
        free(yd);
        free(x);
        free(a);
        gw_chain_free(c);
    }

    printf("\n2. 40-bead column, v_imp 0.3 m/s, rtol = atol = 1e-12 (adaptive)\n");
    gw_chain_params p = gw_chain_params_default();
    p.n = 40;
    gw_chain *c = NULL;
    gw_err err;
    gw_chain_create(&p, &c, &err);
    gw_chain_run_opts ref_o = gw_chain_run_opts_default();
    ref_o.solver = gw_solver_rk4;
    ref_o.sp.dt = gw_chain_time_scale(&p) / 3200;
    gw_chain_result ref;
    if (gw_chain_collide(c, &ref_o, &ref, &err) != GW_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    /* RHS time per evaluation at this size, for the fraction-in-RHS column */
    const gw_system *sys = gw_chain_system(c);
    double y[80], yd[80];
    gw_chain_initial_state(c, y);
    for (int i = 0; i < 40; i++)
        y[2 * i] = 1e-6 * (1 + 0.01 * i);
    double t0 = gw_clock_ms();
    for (int r = 0; r < 200000; r++) {
        sys->rhs(0, y, yd, sys->params);
        sink += yd[3];
    }
    double rhs_ms = (gw_clock_ms() - t0) / 200000;
    printf("%-14s %9s %8s %9s %12s %9s %10s %10s\n", "backend", "ms", "steps", "rhs", "ns/bead-step",
           "in RHS", "F_max err", "tau_N err");
    const char *bk[][2] = {{"cvode", "bdf"}, {"cvode", "adams"}, {"arkode", "erk"}, {"arkode", "dirk"},
                           {"arkode", "imex"}, {"rk4", "default"}};
    for (size_t b = 0; b < sizeof bk / sizeof bk[0]; b++) {
        gw_chain_run_opts o = gw_chain_run_opts_default();
        o.solver = gw_solver_type_find(bk[b][0]);
        o.sp.method = gw_solver_method_find(bk[b][1]);
        o.sp.rtol = o.sp.atol = 1e-12;
        gw_chain_result r;
        double best = 1e300;
        for (int k = 0; k < 3; k++) {
            double s0 = gw_clock_ms();
            if (gw_chain_collide(c, &o, &r, &err) != GW_OK) {
                fprintf(stderr, "%s\n", err.msg);
                return 1;
            }
            best = fmin(best, gw_clock_ms() - s0);
            if (k < 2)
                gw_chain_result_free(&r);
        }
        char name[32];
        snprintf(name, sizeof name, "%s/%s", bk[b][0], bk[b][1]);
        printf("%-14s %9.2f %8ld %9ld %12.1f %8.0f%% %10.1e %10.1e\n", name, best, r.stats.steps,
               r.stats.rhs_evals, best * 1e6 / ((double)r.stats.steps * 40),
               100 * r.stats.rhs_evals * rhs_ms / best, fabs(r.f_max - ref.f_max) / ref.f_max,
               fabs(r.tau_n - ref.tau_n) / ref.tau_n);
        gw_chain_result_free(&r);
    }
    gw_chain_result_free(&ref);
    gw_chain_free(c);
    return 0;
}
