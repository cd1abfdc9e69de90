/*
 * bench_chain.c: performance of the chain model and the solver backends.
 * Never a pass/fail test: prints measurements, as ratios where possible, since
 * the machines are noisy. Times are thread CPU times (CLOCK_THREAD_CPUTIME_ID).
 *
 *  1. RHS cost: ns per bead per evaluation of the model's right-hand side
 *     (through gw_system, state interleaved [x, v]; median of 7 timings), against
 *     a loop measured in the same run: a plain scalar loop over separate x and v
 *     arrays computing only the Hertz forces k d sqrt(d) (branch d > 0) and
 *     accelerations (no kinematics, no function pointer). Ratio = RHS / loop.
 *  2. Per backend, a 40-bead column at v_imp = 0.3 m/s with the default chain
 *     tolerances: wall time, steps, RHS evaluations, ns per bead-step, the
 *     fraction of the time spent in the RHS, and F_max / tau_N error against a
 *     tight reference (RK4 with dt = T_c / 3200).
 *  3. A flop-count bound for the RHS (see hardware_bound below): the largest of
 *     flops / measured flop rate, sqrt / measured packed-sqrt rate, and a
 *     memory-only loop with the model's loads and stores; printed as a fraction
 *     of the RHS.
 * Usage: bench_chain [reps] [rhs]   ("rhs": parts 1 and 3 only)
 * The program uses only the public API, so the same source built against an
 * older library measures that library (old/new comparisons in one run).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "gw_chain.h"

static volatile double sink;

/* This thread's CPU time, ms: the machine is shared, and wall time would count
 * the time other jobs hold the core. */
static double cpu_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double bound_loop(int n, const double *x, double *a, double k, double m1, int reps)
{
    double t0 = cpu_ms();
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
    return (cpu_ms() - t0) * 1e6 / ((double)reps * n);
}

/* ---- 3. flop-count bound ----
 * Per bead and RHS evaluation the model does 5 floating-point operations
 * (d = x_(i+1) - x_i; k * d * sqrt(d): 2 multiplications; F_i - F_(i-1);
 * times 1/m) and one square root; the kinematic half (dx/dt = v) is a copy.
 * Bounds, each measured in this run with the same compiler flags:
 *   flops: 5 / (rate of a tight loop of independent multiply-adds, 8 chains)
 *   sqrt:  1 / (rate of a tight loop of independent square roots, L1-resident)
 *   memory: a loop with the model's loads and stores (x, v, 1/m, k in; dx/dt,
 *           dv/dt out: 48 bytes per bead) and no square root or branch
 * The hardware bound is the largest of the three (they can overlap); the
 * fraction printed is bound / measured RHS time. */
static double flop_ns(void)
{
    volatile double vb = 0.999999, vc = 1e-6;
    double b = vb, c = vc;
    double a0 = 1, a1 = 2, a2 = 3, a3 = 4, a4 = 5, a5 = 6, a6 = 7, a7 = 8;
    const long it = 20000000;
    double best = 1e300;
    for (int rep = 0; rep < 5; rep++) {
        double t0 = cpu_ms();
        for (long i = 0; i < it; i++) {
            a0 = a0 * b + c;
            a1 = a1 * b + c;
            a2 = a2 * b + c;
            a3 = a3 * b + c;
            a4 = a4 * b + c;
            a5 = a5 * b + c;
            a6 = a6 * b + c;
            a7 = a7 * b + c;
        }
        best = fmin(best, cpu_ms() - t0);
    }
    sink += a0 + a1 + a2 + a3 + a4 + a5 + a6 + a7;
    return best * 1e6 / (16.0 * it); /* ns per flop */
}

static double sqrt_ns(void)
{
    enum { L = 1024 };
    static double v[L];
    for (int i = 0; i < L; i++)
        v[i] = 1e-6 * (1 + i);
    const int it = 20000;
    double best = 1e300;
    for (int rep = 0; rep < 5; rep++) {
        double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
        double t0 = cpu_ms();
        for (int r = 0; r < it; r++) {
            for (int i = 0; i < L; i += 4) {
                s0 += sqrt(v[i]);
                s1 += sqrt(v[i + 1]);
                s2 += sqrt(v[i + 2]);
                s3 += sqrt(v[i + 3]);
            }
            v[r & (L - 1)] += 1e-20; /* keep the loop from being hoisted */
        }
        best = fmin(best, cpu_ms() - t0);
        sink += s0 + s1 + s2 + s3;
    }
    return best * 1e6 / ((double)it * L); /* ns per square root */
}

/* Packed square roots: out[i] = sqrt(in[i]) over an L1-resident contiguous array,
 * a loop gcc vectorises (with -fno-math-errno): the hardware's sqrt throughput
 * at this build's vector width (SSE2: 2 doubles, -march=native: up to 8). */
static double psqrt_ns(void)
{
    enum { L = 1024 };
    static double v[L], w[L];
    for (int i = 0; i < L; i++)
        v[i] = 1e-6 * (1 + i);
    const int it = 20000;
    double best = 1e300;
    for (int rep = 0; rep < 5; rep++) {
        double t0 = cpu_ms();
        for (int r = 0; r < it; r++) {
            for (int i = 0; i < L; i++)
                w[i] = sqrt(v[i]);
            v[r & (L - 1)] += w[(r * 7) & (L - 1)] * 1e-30; /* keep the loop from being hoisted */
        }
        best = fmin(best, cpu_ms() - t0);
        sink += w[L / 2];
    }
    return best * 1e6 / ((double)it * L); /* ns per square root */
}

static double mem_ns(int n, const double *y, double *yd, const double *m1, const double *kc, int reps)
{
    double best = 1e300;
    for (int rep = 0; rep < 5; rep++) {
        double t0 = cpu_ms();
        for (int r = 0; r < reps; r++) {
            for (int i = 0; i < n - 1; i++) {
                yd[2 * i] = y[2 * i + 1];
                yd[2 * i + 1] = (y[2 * i + 2] - y[2 * i]) * kc[i] * m1[i];
            }
            sink += yd[n];
        }
        best = fmin(best, cpu_ms() - t0);
    }
    return best * 1e6 / ((double)reps * n);
}

/* Median of 7 timings of reps RHS evaluations, ns per bead. */
static double rhs_ns(const gw_system *sys, int n, const double *y, double *yd, int reps)
{
    double t[7];
    for (int rep = 0; rep < 7; rep++) {
        double t0 = cpu_ms();
        for (int r = 0; r < reps; r++) {
            sys->rhs(0, y, yd, sys->params);
            sink += yd[n];
        }
        t[rep] = cpu_ms() - t0;
    }
    qsort(t, 7, sizeof t[0], cmp_double);
    return t[3] * 1e6 / ((double)reps * n);
}

static int hardware_bound(int reps)
{
    double fl = flop_ns(), sq = sqrt_ns(), psq = psqrt_ns();
    printf("\n3. flop-count bound: 5 flops + 1 sqrt per bead per RHS; tight loops here: "
           "%.3f ns/flop (%.2f Gflop/s), %.3f ns/sqrt scalar, %.3f ns/sqrt packed\n",
           fl, 1 / fl, sq, psq);
    printf("%10s %9s %9s %9s %9s %9s %9s %10s\n", "beads", "RHS", "flops", "psqrt", "memory",
           "bound", "fraction", "Gflop/s");
    const int sizes[] = {40, 1000, 10000, 100000, 1000000};
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
        double *m1 = malloc((size_t)n * sizeof *m1), *kc = malloc((size_t)n * sizeof *kc);
        for (int i = 0; i < n; i++) {
            y[2 * i] = 1e-6 * (1 + 0.01 * i);
            y[2 * i + 1] = 0.1;
            m1[i] = 1 / p.mass;
            kc[i] = p.k;
        }
        int rr = (int)fmax(4, reps * 40.0 / n);
        sys->rhs(0, y, yd, sys->params);
        double rhs = rhs_ns(sys, n, y, yd, rr);
        double mem = mem_ns(n, y, yd, m1, kc, rr);
        double bound = fmax(fmax(5 * fl, psq), mem);
        printf("%10d %9.3f %9.3f %9.3f %9.3f %9.3f %8.0f%% %10.2f\n", n, rhs, 5 * fl, psq, mem, bound,
               100 * bound / rhs, 5 / rhs);
        free(y);
        free(yd);
        free(m1);
        free(kc);
        gw_chain_free(c);
    }
    printf("(ns per bead per RHS evaluation; fraction = bound / RHS; Gflop/s = 5 flops / RHS)\n");
    return 0;
}

int main(int argc, char **argv)
{
    int reps = 2000;
    if (argc > 1) {
        char *end;
        long r = strtol(argv[1], &end, 10);
        if (end == argv[1] || *end || r < 1 || r > 100000000) {
            fprintf(stderr, "bench_chain: REPS '%s' is not a positive integer\n", argv[1]);
            return 2;
        }
        reps = (int)r;
    }
    if (argc > 3 || (argc > 2 && strcmp(argv[2], "rhs") != 0)) {
        fprintf(stderr, "bench_chain: usage: bench_chain [REPS [rhs]]\n");
        return 2;
    }
    int rhs_only = argc > 2;
    printf("granwave %s bench_chain (reps %d)\n\n1. right-hand side, ns per bead per evaluation "
           "(median of 7)\n", gw_version(), reps);
    printf("%10s %12s %12s %8s\n", "beads", "model RHS", "scalar loop", "ratio");
    const int sizes[] = {40, 1000, 10000, 100000, 1000000};
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
        int rr = (int)fmax(20, reps * 40.0 / n);
        sys->rhs(0, y, yd, sys->params); /* warm-up: first touch of yd, caches */
        double model = rhs_ns(sys, n, y, yd, rr);
        bound_loop(n, x, a, p.k, 1 / p.mass, 1);
        double bound = bound_loop(n, x, a, p.k, 1 / p.mass, rr);
        printf("%10d %12.3f %12.3f %8.2f\n", n, model, bound, model / bound);
        free(y);
        free(yd);
        free(x);
        free(a);
        gw_chain_free(c);
    }

    if (rhs_only)
        return hardware_bound(reps);
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
    double t0 = cpu_ms();
    for (int r = 0; r < 200000; r++) {
        sys->rhs(0, y, yd, sys->params);
        sink += yd[3];
    }
    double rhs_ms = (cpu_ms() - t0) / 200000;
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
            double s0 = cpu_ms();
            if (gw_chain_collide(c, &o, &r, &err) != GW_OK) {
                fprintf(stderr, "%s\n", err.msg);
                return 1;
            }
            best = fmin(best, cpu_ms() - s0);
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
    return hardware_bound(reps);
}
