/*
 * gw_global.h: the process-wide state of the libraries granwave uses that is not
 * thread-safe, behind one lock each. Internal to libgranwave (not installed).
 *
 * FFTW's planner (plan creation and destruction, wisdom) must be called by one
 * thread at a time: every FFTW plan the library makes or destroys (the
 * cross-correlation of gw_xcorr.h, the column's wall spectrum, the dispersion
 * study) holds gw_fftw_planner_lock. Two Python threads running
 * granwave.dispersion at once corrupted the heap before (glibc abort, SIGSEGV).
 *
 * GSL's error handler is one global: a call that must not abort on a GSL error
 * turns it off for the section and restores the caller's handler afterwards.
 * Two threads doing that at once could restore each other's handler in the
 * wrong order (a section running under GSL's default handler, which aborts, and
 * the handler left off for good), so the section holds one recursive lock from
 * gw_gsl_quiet_begin to gw_gsl_quiet_end.
 *
 * fork(): each lock is a gw_forklock, taken by one pthread_atfork handler before
 * the fork and released after it (made anew in the child, after the child's
 * reset of the state it guards), so a child never starts with a lock held by a
 * thread it does not have: a child forked while another thread calibrated a
 * restitution or planned an FFT hung for ever at its first one (Python's
 * multiprocessing with the fork start method). No thread holds two of these
 * locks at once, so the order the handlers take them in cannot deadlock.
 */
#ifndef GW_GLOBAL_H
#define GW_GLOBAL_H

#include <pthread.h>
#include <stdatomic.h>

#include <gsl/gsl_errno.h>

/* A process-wide lock safe across fork() (gw_forklock.c). Define it static
 * with GW_FORKLOCK(child) or GW_FORKLOCK_RECURSIVE; child, when not NULL,
 * resets the guarded state in a forked child (one thread, no lock held).
 * mutex is the lock itself, for pthread_cond_wait. */
typedef struct gw_forklock {
    pthread_mutex_t mutex;
    int recursive;
    void (*child)(void);
    atomic_int listed; /* registered with the fork handlers (at the first take) */
    struct gw_forklock *next;
} gw_forklock;
#define GW_FORKLOCK(child) {PTHREAD_MUTEX_INITIALIZER, 0, (child), 0, NULL}
#define GW_FORKLOCK_RECURSIVE {PTHREAD_MUTEX_INITIALIZER, 1, NULL, 0, NULL}
void gw_forklock_take(gw_forklock *l);
void gw_forklock_give(gw_forklock *l);

void gw_fftw_planner_lock(void);
void gw_fftw_planner_unlock(void);

/* Lock, turn GSL's error handler off and return the previous one ... */
gsl_error_handler_t *gw_gsl_quiet_begin(void);
/* ... restore it and unlock. */
void gw_gsl_quiet_end(gsl_error_handler_t *old);

#endif
