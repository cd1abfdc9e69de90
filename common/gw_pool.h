/*
 * gw_pool.h: the one worker pool of granwave (gw_pool.c). n independent cases
 * k = 0 .. n-1 are handed out by a shared counter to a few threads; the first
 * failure is kept, progress goes to the caller's callback one call at a time.
 * Used by the in-memory sweeps (gw_sweep_run), the chain's (v_imp, N) sweeps
 * and the studies on them, and the program's resumable `granwave sweep`.
 * No units: cases are counted.
 */
#ifndef GW_POOL_H
#define GW_POOL_H

#include "gw_common.h"

#include "gw_api.h"

GW_BEGIN_DECLS /* the exported interface, C linkage (gw_api.h) */

/* One case k of a set; GW_OK or a status with a message in err (a case that
 * fails without one is given "case K of N failed (REASON, status S) and gave
 * no message": its status alone was returned with an empty message before
 * session 41). Called from
 * any of the pool's threads, several cases at a time: a case must not write
 * state another case reads (each case builds its own solver, hence its own
 * SUNDIALS context); shared output (a journal) needs the caller's own lock. */
typedef int (*gw_case_fn)(void *ctx, long k, gw_err *err);

/* Run fn(ctx, k) for k = 0 .. n-1 on jobs threads (<= 0: one per online CPU,
 * at most 1024; never more than n; 1: every case on the calling thread, in
 * order). Each case is run at most once, and every case is run when all
 * succeed. progress (may be NULL) is called after every successful case with
 * the number finished so far and n, one call at a time (under the pool's
 * lock), from any of the threads. Stops taking new cases at a failure, and
 * returns the status and message of the lowest case that failed (every case
 * below a failed one was handed out before it and runs to its end: the same
 * failure as on one job, whatever the threads' timing), or when
 * progress returns non-zero (GW_ECANCELED, "canceled by the caller after D of
 * N cases"); cases under way finish first (their results stand, but progress
 * is not called for them). n <= 0: GW_OK at once. If no thread can be
 * started the cases run on the calling thread. */
int gw_cases_run(long n, int jobs, gw_case_fn fn, void *ctx, gw_progress_fn progress, void *pctx,
                 gw_err *err);

GW_END_DECLS

#endif
