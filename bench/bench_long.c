/*
 * bench_long.c: long chains (1e3 .. 1e6 beads), cost per bead-step and memory.
 * Never a pass/fail test: prints measurements.
 *
 * Case: the Falcon column (docs/physics.md 1.1, eq. F.11) of N steel beads
 * (gw_chain_params_default) hitting the wall at v_imp = 0.3 m/s. The compression
 * front runs up the chain at v = 4R/T_q (F.27), one bead per T_q/2 = tc, with
 * tc = (m/k)^(2/5) v_imp^(-1/5) (F.17, C3 = 2); the run stops at a fixed end time
 * transits * tc, so the front crosses about `transits` beads whatever N is and
 * every N does the same physical work per bead.
 *
 * The gw_system is driven directly through gw_solver_advance to the end time,
 * without root functions (gw_chain_collide would locate every contact closing,
 * N root functions per step, and run until every contact opens). Backends:
 * rk4 at the granwave default step dt = tc/400; cvode/adams and arkode/erk at
 * rtol = atol = 1e-10 (granwave defaults; atol is scaled per component by the
 * chain's gw_system.scale); cvode/bdf with the analytic band Jacobian up to
 * --bdf-max beads.
 *
 * Each (N, backend) case runs in a forked child process so that its peak RSS
 * (getrusage ru_maxrss, KiB on Linux) is its own; the child also reports its
 * RSS before creating the chain (the program's baseline), and the parent prints
 * (peak - baseline) / N as bytes per bead. Timings are the best of --reps runs
 * of gw_solver_advance inside the child (solver creation excluded), in CPU time
 * of the child (CLOCK_PROCESS_CPUTIME_ID; the machine is shared); the
 * relative energy error at the end time and the front position (last contact
 * carrying force) are printed as a sanity check that the backends solved the
 * same problem.
 *
 * With --rounds K the backends of one N run in turn K times (rk4, adams, erk,
 * bdf, rk4, ...), each keeping its best child, so that a load on the shared
 * machine falls on all of them alike; step/rk4 is a backend's CPU time per step
 * over rk4's in the same run.
 *
 * The memory bound: before the backends of each N, a STREAM-like triad
 * a = b + s c over vectors of the state's length 2N, rotating through 16 of them
 * (the working set of a solver's step), timed the same way (best of 5 x 2
 * repetitions), gives the cost of streaming one whole state vector once (one
 * read or one write: the triad streams three) in ns per bead; the column
 * streams/step is a backend's cost per step in those units, to compare with the
 * whole-vector reads and writes a step makes (docs/performance.md counts them:
 * RK4 23).
 *
 * Usage: bench_long [--transits T] [--reps R] [--rounds K] [--nmax N]
 *                   [--bdf-max N] [--only BACKEND]
 * Units: SI; times printed in ns per bead-step (CPU time of the advance divided
 * by steps * N).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "gw_chain.h"

typedef struct backend {
    const char *type, *method;
} backend;

static const backend backends[] = {
    {"rk4", "default"}, {"cvode", "adams"}, {"arkode", "erk"}, {"cvode", "bdf"}};

typedef struct case_result {
    int ok;
    double ms;          /* best advance wall time */
    long steps, rhs;
    double energy_err;  /* |E(t_end) - E(0)| / E(0) */
    int front;          /* highest contact index carrying force at t_end */
    long rss0_kib, rss_kib;
    char msg[200];
} case_result;

/* CPU time of this (single-threaded) child, ms: the machine is shared, and wall
 * time would count the time other jobs hold the core. */
static double cpu_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

static long rss_kib(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss;
}

/* Runs in the child: one (N, backend) case, best of reps. */
static void run_case(int n, const backend *b, double transits, int reps, case_result *cr)
{
    memset(cr, 0, sizeof *cr);
    cr->rss0_kib = rss_kib();
    gw_chain_params p = gw_chain_params_default();
    p.n = n;
    gw_chain *c = NULL;
    gw_err err;
    if (gw_chain_create(&p, &c, &err) != GW_OK) {
        snprintf(cr->msg, sizeof cr->msg, "%.190s", err.msg);
        return;
    }
    gw_system sys = *gw_chain_system(c);
    sys.roots = NULL;
    sys.nroots = 0;
    const double tc = gw_chain_time_scale(&p), t_end = transits * tc;
    gw_solver_params sp = gw_solver_params_default();
    sp.method = gw_solver_method_find(b->method);
    if (strcmp(b->type, "rk4") == 0)
        sp.dt = tc / 400;
    sp.max_steps = 100000000L;
    sp.use_jac = 1;
    double *y0 = malloc((size_t)sys.dim * sizeof *y0), *y = malloc((size_t)sys.dim * sizeof *y);
    if (!y0 || !y) {
        snprintf(cr->msg, sizeof cr->msg, "out of memory");
        goto out;
    }
    gw_chain_initial_state(c, y0);
    gw_chain_energy e0, e1;
    gw_chain_energy_of(c, y0, &e0);
    cr->ms = 1e300;
    for (int r = 0; r < reps; r++) {
        gw_solver *s = NULL;
        if (gw_solver_create(gw_solver_type_find(b->type), &sys, &sp, 0.0, y0, &s, &err) != GW_OK) {
            snprintf(cr->msg, sizeof cr->msg, "%.190s", err.msg);
            goto out;
        }
        double t = 0, t0 = cpu_ms();
        int rc = gw_solver_advance(s, t_end, &t, y, NULL);
        double ms = cpu_ms() - t0;
        if (rc != GW_OK) {
            snprintf(cr->msg, sizeof cr->msg, "%.190s", gw_solver_error(s));
            gw_solver_free(s);
            goto out;
        }
        gw_solver_stats st;
        gw_solver_get_stats(s, &st);
        gw_solver_free(s);
        if (ms < cr->ms) {
            cr->ms = ms;
            cr->steps = st.steps;
            cr->rhs = st.rhs_evals;
        }
    }
    gw_chain_energy_of(c, y, &e1);
    cr->energy_err = fabs(e1.total - e0.total) / e0.total;
    cr->front = 0;
    for (int i = 0; i < n - 1; i++)
        if (y[2 * i + 2] - y[2 * i] > 0)
            cr->front = i + 1;
    cr->ok = 1;
out:
    cr->rss_kib = rss_kib();
    free(y0);
    free(y);
    gw_chain_free(c);
}

/* ns per bead of streaming one vector of 2n doubles once (one read or one
 * write), from a triad over 16 rotating vectors; 0 if out of memory. */
static double stream_ns_per_bead(int n)
{
    enum { NVEC = 16 };
    const size_t len = 2 * (size_t)n;
    double *v[NVEC] = {0};
    double best = 0;
    for (int j = 0; j < NVEC; j++)
        if (!(v[j] = malloc(len * sizeof *v[j])))
            goto out;
    for (int j = 0; j < NVEC; j++)
        for (size_t i = 0; i < len; i++)
            v[j][i] = 1e-3 * (double)i + j;
    /* about 0.2 s per timing, at least 3 triads */
    const int reps = 2e8 / (double)len > 3 ? (int)(2e8 / (double)len) : 3;
    best = 1e300;
    for (int r = 0; r < 5; r++) {
        double t0 = cpu_ms();
        for (int k = 0; k < reps; k++) {
            double *restrict a = v[k % NVEC];
            const double *restrict b = v[(k + 5) % NVEC], *restrict c = v[(k + 11) % NVEC];
            for (size_t i = 0; i < len; i++)
                a[i] = b[i] + 0.5 * c[i];
        }
        double ms = (cpu_ms() - t0) / reps;
        if (ms < best)
            best = ms;
    }
    best = best * 1e6 / 3.0 / n;
out:
    for (int j = 0; j < NVEC; j++)
        free(v[j]);
    return best;
}

/* Fork, run the case in the child, read its result through a pipe. */
static int run_forked(int n, const backend *b, double transits, int reps, case_result *cr)
{
    int fd[2];
    if (pipe(fd) != 0)
        return -1;
    fflush(stdout);
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        close(fd[0]);
        case_result r;
        run_case(n, b, transits, reps, &r);
        ssize_t w = write(fd[1], &r, sizeof r);
        _exit(w == (ssize_t)sizeof r ? 0 : 1);
    }
    close(fd[1]);
    ssize_t got = 0, k;
    while (got < (ssize_t)sizeof *cr && (k = read(fd[0], (char *)cr + got, sizeof *cr - (size_t)got)) > 0)
        got += k;
    close(fd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (got != (ssize_t)sizeof *cr) {
        memset(cr, 0, sizeof *cr);
        snprintf(cr->msg, sizeof cr->msg, "child failed (status %d)", status);
    }
    return 0;
}

int main(int argc, char **argv)
{
    double transits = 20;
    int reps = 3, nmax = 1000000, bdf_max = 100000, rounds = 1;
    const char *only = NULL;
    for (int i = 1; i < argc; i += 2) {
        const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
            printf("usage: bench_long [--transits T] [--reps R] [--rounds K] [--nmax N] "
                   "[--bdf-max N] [--only BACKEND]\n"
                   "  cost per bead-step of each backend on a column of 1e3 .. nmax beads\n"
                   "  (1e3, 1e4, 1e5, 1e6), its ratio to RK4's step in the same run, and the\n"
                   "  step in whole-vector streams of a triad timed before each N\n");
            return 0;
        }
        int known = !strcmp(o, "--transits") || !strcmp(o, "--reps") || !strcmp(o, "--nmax") ||
                    !strcmp(o, "--bdf-max") || !strcmp(o, "--rounds") || !strcmp(o, "--only");
        if (!known) {
            fprintf(stderr, "bench_long: unknown option %s\n", o);
            return 2;
        }
        if (!v) {
            fprintf(stderr, "bench_long: %s needs a value\n", o);
            return 2;
        }
        if (!strcmp(o, "--only")) {
            only = v;
            continue;
        }
        char *end;
        double x = strtod(v, &end);
        int is_int = strcmp(o, "--transits") != 0;
        int zero_ok = !strcmp(o, "--bdf-max"); /* 0: no BDF run at any size */
        if (end == v || *end || !(x > 0 || (zero_ok && x == 0)) || x > 1e9 || (is_int && x != (double)(int)x)) {
            fprintf(stderr, "bench_long: %s %s: expected a positive %s\n", o, v,
                    is_int ? "integer" : "number");
            return 2;
        }
        if (!strcmp(o, "--transits"))
            transits = x;
        else if (!strcmp(o, "--reps"))
            reps = (int)x;
        else if (!strcmp(o, "--nmax"))
            nmax = (int)x;
        else if (!strcmp(o, "--bdf-max"))
            bdf_max = (int)x;
        else
            rounds = (int)x;
    }
    gw_chain_params p = gw_chain_params_default();
    printf("granwave %s bench_long: column at v_imp %.2g m/s hitting the wall, end time %g tc "
           "(tc = %.4g s: the front crosses ~%g beads), best of %d x %d rounds\n",
           gw_version(), p.v_imp, transits, gw_chain_time_scale(&p), transits, reps, rounds);
    printf("rk4 dt = tc/400; adaptive rtol = atol = 1e-10; no root functions\n\n");
    printf("%9s %-12s %9s %8s %9s %13s %9s %7s %10s %10s %9s %12s\n", "beads", "backend", "ms",
           "steps", "rhs/step", "ns/bead-step", "energy", "front", "peak MiB", "B/bead", "step/rk4",
           "streams/step");
    const int sizes[] = {1000, 10000, 100000, 1000000};
    enum { NB = sizeof backends / sizeof backends[0] };
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        int n = sizes[s];
        if (n > nmax)
            break;
        const double stream = stream_ns_per_bead(n);
        if (stream > 0)
            printf("%9d triad: one whole-vector stream (2N doubles read or written once) %.3f ns "
                   "per bead, %.1f GB/s\n",
                   n, stream, 16.0 / stream);
        /* the backends in turn, `rounds` times; each keeps its best child */
        case_result best[NB];
        int run[NB] = {0};
        for (int round = 0; round < rounds; round++) {
            for (size_t b = 0; b < NB; b++) {
                char name[32];
                snprintf(name, sizeof name, "%s/%s", backends[b].type, backends[b].method);
                if ((only && !strstr(name, only)) ||
                    (!strcmp(backends[b].method, "bdf") && n > bdf_max))
                    continue;
                case_result cr;
                if (run_forked(n, &backends[b], transits,
                               n >= 1000000 ? (reps > 2 ? 2 : reps) : reps, &cr) != 0) {
                    perror("bench_long: fork");
                    return 1;
                }
                if (!run[b] || (cr.ok && (!best[b].ok || cr.ms < best[b].ms)))
                    best[b] = cr;
                run[b] = 1;
            }
        }
        const double rk4_step =
            run[0] && best[0].ok ? best[0].ms / (double)best[0].steps : 0.0;
        for (size_t b = 0; b < NB; b++) {
            if (!run[b])
                continue;
            char name[32];
            snprintf(name, sizeof name, "%s/%s", backends[b].type, backends[b].method);
            const case_result *cr = &best[b];
            if (!cr->ok) {
                printf("%9d %-12s failed: %s\n", n, name, cr->msg);
                continue;
            }
            printf("%9d %-12s %9.1f %8ld %9.2f %13.2f %9.1e %7d %10.1f %10.0f", n, name, cr->ms,
                   cr->steps, (double)cr->rhs / (double)cr->steps,
                   cr->ms * 1e6 / ((double)cr->steps * n), cr->energy_err, cr->front,
                   cr->rss_kib / 1024.0, (cr->rss_kib - cr->rss0_kib) * 1024.0 / n);
            if (rk4_step > 0)
                printf(" %9.2f", cr->ms / (double)cr->steps / rk4_step);
            else
                printf(" %9s", "-");
            if (stream > 0)
                printf(" %12.1f", cr->ms * 1e6 / ((double)cr->steps * n) / stream);
            printf("\n");
        }
    }
    return 0;
}
