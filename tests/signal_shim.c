/*
 * signal_shim.c: an LD_PRELOAD library that delivers a signal on a thread of
 * its own in the middle of a chosen rename, to test that an output set is
 * placed all or nothing when a signal is handled on a thread other than the
 * one placing it (tests/test_outset_signal.sh, issue 18). Not linked into
 * anything; glibc only.
 *
 * Environment:
 *   GW_SIGNAL_AT=K:SIG  before the K-th call to rename (from 1, every thread),
 *                       a new thread with SIGINT, SIGTERM and SIGHUP unblocked
 *                       raises signal SIG on itself, so that the process's
 *                       handler runs there while the caller (which holds
 *                       them) waits in rename; the caller joins it, then
 *                       renames. A handler that ends the process ends it
 *                       there, between two renames.
 *   GW_SIGNAL_FSYNC=K:SIG  the same before the K-th call to fsync (the K-th
 *                       file of a run made durable: an output set's staged
 *                       temporaries exist by then), after GW_SIGNAL_RUN;
 *                       SIG 0: GW_SIGNAL_RUN only, no signal.
 *   GW_SIGNAL_RUN=CMD   a shell command run (system) just before that signal
 *                       (tests/test_out_moved_signal.sh: "mv D D.old && mkdir
 *                       D", --out moved under the run).
 *   GW_SIGNAL_COUNT=FILE at exit, write "rename N" and "fsync N" (the calls
 *                       made) to FILE.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static atomic_long renames, fsyncs;

static void *raiser(void *arg)
{
    sigset_t s;
    sigemptyset(&s);
    sigaddset(&s, SIGINT);
    sigaddset(&s, SIGTERM);
    sigaddset(&s, SIGHUP);
    pthread_sigmask(SIG_UNBLOCK, &s, NULL); /* the new thread has the caller's mask */
    raise(*(int *)arg);
    return NULL;
}

/* signal SIG raised on a thread of its own, which the caller waits for */
static void signal_on_thread(int sig)
{
    pthread_t t;
    if (pthread_create(&t, NULL, raiser, &sig) == 0)
        pthread_join(t, NULL);
}

typedef int rename_fn(const char *, const char *);
typedef int fsync_fn(int);

int fsync(int fd)
{
    const long n = atomic_fetch_add(&fsyncs, 1) + 1;
    const char *at = getenv("GW_SIGNAL_FSYNC"), *cmd = getenv("GW_SIGNAL_RUN");
    long k = 0;
    int sig = 0;
    if (at && sscanf(at, "%ld:%d", &k, &sig) == 2 && k == n && sig >= 0) {
        if (cmd && system(cmd) != 0)
            fprintf(stderr, "signal_shim: '%s' failed\n", cmd);
        if (sig > 0)
            signal_on_thread(sig);
    }
    fsync_fn *real;
    void *sym = dlsym(RTLD_NEXT, "fsync");
    memcpy(&real, &sym, sizeof real);
    return real(fd);
}

int rename(const char *from, const char *to)
{
    const long n = atomic_fetch_add(&renames, 1) + 1;
    const char *at = getenv("GW_SIGNAL_AT");
    long k = 0;
    int sig = 0;
    if (at && sscanf(at, "%ld:%d", &k, &sig) == 2 && k == n && sig > 0)
        signal_on_thread(sig);
    rename_fn *real;
    void *sym = dlsym(RTLD_NEXT, "rename");
    memcpy(&real, &sym, sizeof real);
    return real(from, to);
}

__attribute__((destructor)) static void report(void)
{
    const char *path = getenv("GW_SIGNAL_COUNT");
    FILE *f = path ? fopen(path, "w") : NULL;
    if (f) {
        fprintf(f, "rename %ld\nfsync %ld\n", atomic_load(&renames), atomic_load(&fsyncs));
        fclose(f);
    }
}
