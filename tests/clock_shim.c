/*
 * clock_shim.c: an LD_PRELOAD library that makes the monotonic clock count
 * its reads instead of the wall's seconds, so that the tests of the progress
 * lines (which come once a run has lasted 2 s, then every 2 s or more) see
 * them on the run's own steps, whatever the machine's load (issue 18;
 * tests/test_study_progress.sh, test_sweep_eta_weighed.sh,
 * test_hostile_twentyfifth.sh). Every clock the program and the library time
 * their displays by is gw_clock_ms, one clock_gettime(CLOCK_MONOTONIC) read:
 * a drop's sample, a study's watch call within a collision, a sweep's case
 * ended or its ticker's round each read it once or a few times, so with the
 * shim a line due "after 2 s" comes after a number of those reads, the same
 * number on a loaded machine as on an idle one (for a run on one thread).
 * Not linked into anything; glibc only; not for mpirun (its runtime times
 * its own waits by this clock).
 *
 * Environment:
 *   GW_CLOCK_STEP_MS=S  S > 0: each CLOCK_MONOTONIC read (every thread, one
 *                       count) returns the clock of the first read plus S ms
 *                       times the reads made before it; unset or not a
 *                       positive number: the real clock. Other clocks are
 *                       always the real ones.
 *   GW_CLOCK_COUNT=FILE at exit, write "reads N" (the CLOCK_MONOTONIC reads
 *                       made) to FILE.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef int clock_gettime_fn(clockid_t, struct timespec *);

static atomic_long reads;
static atomic_llong start_ns = -1; /* the real clock at the first read, ns */

static clock_gettime_fn *real_clock(void)
{
    clock_gettime_fn *real;
    void *sym = dlsym(RTLD_NEXT, "clock_gettime");
    memcpy(&real, &sym, sizeof real);
    return real;
}

/* GW_CLOCK_STEP_MS in ns, 0 when unset or not a positive number */
static long long step_ns(void)
{
    const char *v = getenv("GW_CLOCK_STEP_MS");
    char *end = NULL;
    const double ms = v ? strtod(v, &end) : 0;
    return v && end != v && *end == '\0' && ms > 0 && ms < 1e9 ? (long long)(ms * 1e6) : 0;
}

int clock_gettime(clockid_t id, struct timespec *ts)
{
    clock_gettime_fn *real = real_clock();
    const long long step = id == CLOCK_MONOTONIC ? step_ns() : 0;
    if (id == CLOCK_MONOTONIC)
        atomic_fetch_add(&reads, 1);
    if (step == 0)
        return real(id, ts);
    long long t0 = atomic_load(&start_ns);
    if (t0 < 0) {
        struct timespec now;
        if (real(id, &now) != 0)
            return -1;
        long long expect = -1;
        (void)atomic_compare_exchange_strong(&start_ns, &expect, (long long)now.tv_sec * 1000000000LL + now.tv_nsec);
        t0 = atomic_load(&start_ns);
    }
    /* the reads before this one, counted once each across the threads */
    static atomic_long stepped;
    const long long t = t0 + step * atomic_fetch_add(&stepped, 1);
    ts->tv_sec = (time_t)(t / 1000000000LL);
    ts->tv_nsec = (long)(t % 1000000000LL);
    return 0;
}

__attribute__((destructor)) static void report(void)
{
    const char *path = getenv("GW_CLOCK_COUNT");
    FILE *f = path ? fopen(path, "w") : NULL;
    if (f) {
        fprintf(f, "reads %ld\n", atomic_load(&reads));
        fclose(f);
    }
}
