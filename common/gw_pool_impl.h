/*
 * gw_pool_impl.h: the worker pool's thread count (gw_pool.c), inside the
 * library only: a study's progress schedules the work left over the threads
 * that will run it (chain/chain_watch.c), the count gw_cases_run starts.
 */
#ifndef GW_POOL_IMPL_H
#define GW_POOL_IMPL_H

/* The threads gw_cases_run(n, jobs, ...) runs n cases on: jobs, or one per
 * online CPU when jobs <= 0 (at most 1024), never more than n; 1 when n <= 1. */
int gw_pool_threads(long n, int jobs);

#endif
