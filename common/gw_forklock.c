/*
 * gw_forklock.c: the library's process-wide locks, safe across fork()
 * (gw_global.h). One pthread_atfork handler set serves every lock: before a
 * fork it takes each lock registered so far (so no other thread is inside a
 * section when the process is copied), after it releases them in the parent,
 * and in the child runs each lock's reset of the state it guards and makes the
 * lock anew (the child's thread has a new id: a lock taken before the fork is
 * not its own). A lock is registered at its first take.
 *
 * Before, each of the five locks carried its own copy of this set-up, and one
 * (the FFTW planner's, as gw_xcorr_create and gw_xcorr_free took it) was taken
 * without registering its handlers when no other call had registered them.
 *
 * Deadlock: no thread holds two of these locks at once, so the order the
 * handlers take them in does not matter; the registry's own lock is taken
 * only to register (before the lock is taken) and around the fork.
 */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdatomic.h>

#include "gw_global.h"

static pthread_mutex_t registry = PTHREAD_MUTEX_INITIALIZER;
static gw_forklock *head;
static pthread_once_t handlers_once = PTHREAD_ONCE_INIT;

static void make(gw_forklock *l)
{
    pthread_mutexattr_t a;
    pthread_mutexattr_init(&a);
    if (l->recursive)
        pthread_mutexattr_settype(&a, PTHREAD_MUTEX_RECURSIVE);
    pthread_mutex_init(&l->mutex, &a);
    pthread_mutexattr_destroy(&a);
}

static void fork_prepare(void)
{
    pthread_mutex_lock(&registry);
    for (gw_forklock *l = head; l; l = l->next)
        pthread_mutex_lock(&l->mutex);
}

static void fork_parent(void)
{
    for (gw_forklock *l = head; l; l = l->next)
        pthread_mutex_unlock(&l->mutex);
    pthread_mutex_unlock(&registry);
}

static void fork_child(void)
{
    for (gw_forklock *l = head; l; l = l->next) {
        if (l->child)
            l->child(); /* one thread here: the state first, then the lock */
        make(l);
    }
    pthread_mutex_init(&registry, NULL);
}

static void handlers_init(void)
{
    pthread_atfork(fork_prepare, fork_parent, fork_child);
}

/* first take: make the lock (recursive when asked) and list it for the
 * handlers, under the registry's lock so that a fork sees it whole */
static void enlist(gw_forklock *l)
{
    pthread_once(&handlers_once, handlers_init);
    pthread_mutex_lock(&registry);
    if (!atomic_load_explicit(&l->listed, memory_order_relaxed)) {
        if (l->recursive)
            make(l);
        l->next = head;
        head = l;
        atomic_store_explicit(&l->listed, 1, memory_order_release);
    }
    pthread_mutex_unlock(&registry);
}

void gw_forklock_take(gw_forklock *l)
{
    if (!atomic_load_explicit(&l->listed, memory_order_acquire))
        enlist(l);
    pthread_mutex_lock(&l->mutex);
}

void gw_forklock_give(gw_forklock *l)
{
    pthread_mutex_unlock(&l->mutex);
}
