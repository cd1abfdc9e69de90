/*
 * gw_interrupt.c: a SIGINT that stops the runs under way (gw_common.h,
 * gw_interrupt_begin). The request is one lock-free atomic flag: the handler
 * sets it (async-signal-safe), each solver step reads it (a relaxed load, no
 * measurable cost). Begin/end pairs are counted under a mutex; the first
 * installs the handler, the last puts back the one it found. A child forked
 * while a pair is open (another thread's call under way) starts with none: the
 * handler found is put back and the count and request cleared, where the child
 * kept this handler for good (Ctrl-C did nothing in it, Python never saw it).
 */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <string.h>

#include "gw_common.h"
#include "gw_global.h"

static atomic_int requested;
static int depth;
static struct sigaction saved;

static void fork_child(void)
{
    if (depth > 0)
        sigaction(SIGINT, &saved, NULL);
    depth = 0;
    atomic_store(&requested, 0);
}

static gw_forklock lock = GW_FORKLOCK(fork_child);

static void on_sigint(int sig)
{
    (void)sig;
    atomic_store_explicit(&requested, 1, memory_order_relaxed);
}

int gw_interrupt_pending(void)
{
    return atomic_load_explicit(&requested, memory_order_relaxed);
}

int gw_interrupt_begin(void)
{
    int rc = GW_OK;
    gw_forklock_take(&lock);
    if (depth == 0) {
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_sigint;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESTART; /* reads and writes under way go on */
        atomic_store(&requested, 0);
        if (sigaction(SIGINT, &sa, &saved) != 0)
            rc = GW_EIO;
    }
    if (rc == GW_OK)
        depth++;
    gw_forklock_give(&lock);
    return rc;
}

int gw_interrupt_end(void)
{
    gw_forklock_take(&lock);
    int was = gw_interrupt_pending();
    if (depth > 0 && --depth == 0) {
        sigaction(SIGINT, &saved, NULL);
        atomic_store(&requested, 0);
    }
    gw_forklock_give(&lock);
    return was;
}
