/*
 * test_forklock.c: the library's fork-safe process-wide locks (gw_global.h,
 * common/gw_forklock.c), which the FFTW planner, GSL's error-handler sections,
 * SIGINT's begin/end pairs and the two memos share.
 *  - A lock's child reset runs in a forked child, before the child takes the
 *    lock (the guarded state is the reset one), and not in the parent.
 *  - A recursive lock is taken twice by one thread, and a fork by the thread
 *    that holds it gives a child that takes it again.
 *  - A lock held by another thread at the fork: the fork waits for it, so the
 *    child takes it at once (the child times out with SIGALRM otherwise).
 *  - The FFTW planner's lock, in a process where gw_xcorr_create and
 *    gw_xcorr_free are the only calls that take it: a child forked while a
 *    thread makes and frees plans makes its own. Before, those two calls took
 *    the lock without registering its fork handlers; a child forked while the
 *    thread held it waited for ever (19 of 20 children on the code before).
 * Forks with another thread running are not in the sanitizer build: GCC 12's
 * libasan takes no lock of its allocator around fork (test_chain_layer_memo).
 */
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gw_global.h"
#include "gw_test.h"
#include "gw_xcorr.h"

static int guarded = 7, resets = 0;
static void reset_guarded(void)
{
    guarded = 0;
    resets++;
}
static gw_forklock plain = GW_FORKLOCK(reset_guarded);
static gw_forklock rec = GW_FORKLOCK_RECURSIVE;

/* fork; the child runs f with a 60 s alarm (a guard against a hang: 5 s could
 * end a child on a loaded machine); 1 when it exited 0 */
static int in_child(int (*f)(void))
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        alarm(60);
        _exit(f() ? 0 : 1);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    return WIFEXITED(st) && WEXITSTATUS(st) == 0;
}

static int child_sees_reset(void)
{
    gw_forklock_take(&plain);
    int ok = guarded == 0 && resets == 1;
    gw_forklock_give(&plain);
    return ok;
}

static int child_takes_rec(void)
{
    gw_forklock_take(&rec);
    gw_forklock_take(&rec);
    gw_forklock_give(&rec);
    gw_forklock_give(&rec);
    return 1;
}

#ifndef __SANITIZE_ADDRESS__ /* the forks beside a running thread (main, below) */
static int child_takes_plain(void)
{
    gw_forklock_take(&plain);
    gw_forklock_give(&plain);
    return 1;
}

static atomic_int spinning;
static void *hold_plain(void *arg)
{
    (void)arg;
    while (atomic_load(&spinning)) {
        gw_forklock_take(&plain);
        usleep(200);
        gw_forklock_give(&plain);
    }
    return NULL;
}

static void *plan_loop(void *arg)
{
    (void)arg;
    while (atomic_load(&spinning)) {
        gw_xcorr *x = NULL;
        gw_err err;
        if (gw_xcorr_create(3000, 0, &x, &err) == GW_OK)
            gw_xcorr_free(x);
    }
    return NULL;
}

static int child_plans(void)
{
    gw_xcorr *x = NULL;
    gw_err err;
    int ok = gw_xcorr_create(1000, 0, &x, &err) == GW_OK;
    gw_xcorr_free(x);
    return ok;
}

/* forks while fn runs in a thread; how many children of n succeeded */
static int forks_during(void *(*fn)(void *), int (*child)(void), int n)
{
    pthread_t t;
    atomic_store(&spinning, 1);
    pthread_create(&t, NULL, fn, NULL);
    int good = 0;
    for (int i = 0; i < n; i++) {
        usleep(300 + 97 * i);
        good += in_child(child);
    }
    atomic_store(&spinning, 0);
    pthread_join(t, NULL);
    return good;
}

#endif

int main(void)
{
    gw_forklock_take(&plain);
    guarded = 7;
    gw_forklock_give(&plain);
    gw_test_true(in_child(child_sees_reset), "the child's reset ran once, before the child took the lock");
    gw_test_true(guarded == 7 && resets == 0, "the parent's state is untouched by the child's reset");

    gw_forklock_take(&rec);
    gw_forklock_take(&rec);
    gw_test_true(in_child(child_takes_rec), "a fork by the thread holding a recursive lock: the child takes it");
    gw_forklock_give(&rec);
    gw_forklock_give(&rec);
    gw_test_true(in_child(child_takes_rec), "the recursive lock, released twice, is free in a child");

#ifdef __SANITIZE_ADDRESS__
    printf("SKIP: forks while another thread runs (the sanitizer's allocator is not fork-safe)\n");
#else
    int n = 20, good = forks_during(plan_loop, child_plans, n);
    printf("children that planned while a thread made and freed plans: %d of %d\n", good, n);
    gw_test_true(good == n, "a child forked while a thread plans FFTs (gw_xcorr_create/free only) plans its own");
    good = forks_during(hold_plain, child_takes_plain, n);
    printf("children that took a lock another thread held at times: %d of %d\n", good, n);
    gw_test_true(good == n, "a child forked while another thread holds a lock takes it");
#endif
    return gw_test_summary("test_forklock");
}
