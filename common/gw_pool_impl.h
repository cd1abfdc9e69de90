/*
 * gw_pool_impl.h: the worker pool's thread count and its schedule (gw_pool.c),
 * inside the library and the program only. A progress display's time left
 * schedules the work left over the threads that will run it, as the pool
 * hands it out: a study's (chain/chain_watch.c, its collisions weighed) and
 * `granwave sweep`'s (app/sweep_cmd.c, gw_pool_eta: its cases weighed by the
 * cost each model expects of them, gw_sweep_weigh, or alike).
 * Time is counted in work per thread at work: every thread under way goes at
 * the same pace, a whole CPU's while they are no more than the CPUs, a share
 * of one beyond (k threads on c CPUs: c / k each).
 */
#ifndef GW_POOL_IMPL_H
#define GW_POOL_IMPL_H

/* The CPUs online (sysconf), in [1, 1024]: 1 where the count is not known. */
int gw_pool_cpus(void);

/* The threads gw_cases_run(n, jobs, ...) runs n cases on: jobs, or one per
 * online CPU when jobs <= 0 (gw_pool_cpus), never more than n; 1 when n <= 1. */
int gw_pool_threads(long n, int jobs);

/* A schedule: free_at[0..m-1], a min-heap (all zeros is one), the time, in
 * work per thread from now, when each of m threads comes free. The first
 * thread free takes a case of work w (gw_pool_give), or n such cases one
 * after another (gw_pool_give_each: n may be large, it takes O(m) while the
 * threads come free within w of each other). */
void gw_pool_give(double *free_at, int m, double w);
void gw_pool_give_each(double *free_at, int m, long n, double w);
/* The time the m threads take to end the work given them, on cpus CPUs:
 * while k threads are at work the work goes at max(1, k / cpus) times the
 * time. Sorts free_at (no longer a heap). */
double gw_pool_span(double *free_at, int m, int cpus);

/* The time elapsed, in work per thread at work: each call adds the work done
 * since the last (done, the work done so far, counted when it grows) over the
 * threads at work since (busy: the most under way, at least 1, at most the
 * CPUs); busy is then the threads under way now. Raise busy as a case begins
 * (gw_pool_clock_busy). All zeros to start. */
typedef struct gw_pool_clock {
    double elapsed; /* work per thread at work */
    double done_hi; /* the most work counted done */
    int busy;       /* the most threads under way since the last count */
} gw_pool_clock;
void gw_pool_clock_busy(gw_pool_clock *c, int under_way);
void gw_pool_clock_count(gw_pool_clock *c, double done, int under_way, int cpus);

/* The progress of n cases of alike work run on the pool (gw_cases_run(n,
 * jobs)): the part of its time done, the time elapsed over the whole time,
 * each in work per thread at work, a case's work 1. The time elapsed counts
 * the work done (the cases ended, and the share done of those under way);
 * the time left is the work left scheduled as the pool hands it out: each
 * case under way holds its thread for its share left, each case to come goes
 * to the first thread free. So the last cases, run on fewer threads than
 * the pool's, count at their own pace. On one thread it is the share of the
 * work done. The part reported never decreases. */
#define GW_POOL_ETA_KINDS 64 /* the kinds of cases told apart (gw_pool_eta_kinds) */
typedef struct gw_pool_eta {
    int threads, cpus;   /* the pool's threads; the CPUs they run on */
    gw_pool_clock clock;
    double shown;        /* the largest part reported */
    double now;          /* the part estimated at the last call, not held (the time left's) */
    double *free_at;     /* scratch: threads doubles */
    /* the cases' weights when known (gw_pool_eta_weigh): cum[i] the weight
     * of cases 0..i-1, n + 1 of them; NULL: the cases alike */
    double *cum;
    long n;
    /* the cases' kinds when known (gw_pool_eta_kinds): kind[i] in [0,
     * GW_POOL_ETA_KINDS) or -1 (none); NULL: one kind. The time the ended
     * cases took and their weight, of each kind (kd, kw) and of all (d_all,
     * w_all), and each kind's factor (gain) from them */
    int *kind;
    double kd[GW_POOL_ETA_KINDS], kw[GW_POOL_ETA_KINDS], gain[GW_POOL_ETA_KINDS], d_all, w_all;
} gw_pool_eta;
/* For gw_cases_run(n, jobs) on this machine's CPUs; GW_ENOMEM (e untouched
 * but zeroed) or GW_OK. Free with gw_pool_eta_free. */
int gw_pool_eta_init(gw_pool_eta *e, long n, int jobs);
void gw_pool_eta_free(gw_pool_eta *e);
/* A case begun, under_way now under way (the clock's busy). */
void gw_pool_eta_begun(gw_pool_eta *e, int under_way);
/* The part now: ended, the cases ended; share[0..nrun-1], the share done of
 * each case under way (in [0, 1)); to_come, the cases not begun. In [0, 1]:
 * the share of the work before any work is counted. */
double gw_pool_eta_part(gw_pool_eta *e, long ended, const double *share, int nrun, long to_come);

/* Cases of unequal cost: their weights known before they run, w[0..n-1] in
 * the order the pool hands them out (case i's cost over the others', any
 * unit: a chain case's bead-steps, a layer case's body-steps). A weight not
 * finite or not above 0 (not known) counts as the mean of the others (1 when
 * none is known). Then the work is counted in weight: the time elapsed adds
 * the weight done (of the cases ended, and each case under way's weight
 * times its share done), and the time left schedules the weight left, each
 * case under way holding its thread for its weight times its share left,
 * each case to come, in order, going to the first thread free. So on one
 * thread the part is the weight done over the whole weight, and the time
 * left the time elapsed times the weight left over the weight done. Of more
 * than GW_POOL_ETA_ONE_BY_ONE cases to come, all but the last that many fill
 * the threads level first (their sum spread as the pool's greedy order
 * spreads many small cases), the last given one at a time. GW_OK, or
 * GW_ENOMEM (e's cases stay alike). */
#define GW_POOL_ETA_ONE_BY_ONE 4096
int gw_pool_eta_weigh(gw_pool_eta *e, const double *w, long n);
/* The weight of case i (1 when the cases are alike, or i outside [0, n)). */
double gw_pool_eta_weight(const gw_pool_eta *e, long i);
/* The part now, cases weighed: w_ended, the weight of the cases ended;
 * wrun[0..nrun-1] and share[0..nrun-1], the weight of each case under way
 * and its share done (in [0, 1)); the cases to come are next..n-1. The same
 * part as gw_pool_eta_part when the cases are alike (weights 1). */
double gw_pool_eta_part_weighed(gw_pool_eta *e, double w_ended, const double *wrun, const double *share, int nrun,
                                long next);

/* Cases of kinds whose cost per weight differs by a factor their weights do
 * not hold (a chain sweep over `solver`: a backend's step costs what its
 * model guesses only roughly, 0.3 to 5 times, and a kind's cases share it):
 * kind[0..n-1], in the pool's order, each in [0, GW_POOL_ETA_KINDS) or -1
 * (of no kind). Each case ended reports the time it took
 * (gw_pool_eta_ended, in any unit, the same for all), and from then on the
 * cases left of a kind count, in the time left, their weight times the
 * kind's factor: the time its ended cases took per weight over the time all
 * ended cases took per weight (1 for a kind none of which ended, and for
 * cases of no kind). The time elapsed still counts the weights (the factor
 * is relative to the pace they went at), so on one thread the time left is
 * the time elapsed times the weight left, each case at its kind's pace, over
 * the weight done. GW_OK, GW_ENOMEM (e's cases of one kind), GW_EINVAL (no
 * weights yet, n not theirs, or a kind out of range: e unchanged). */
int gw_pool_eta_kinds(gw_pool_eta *e, const int *kind, long n);
/* Case i ended after time t (not counted unless finite and above 0, or i
 * outside [0, n)). */
void gw_pool_eta_ended(gw_pool_eta *e, long i, double t);
/* Case i's weight times its kind's factor (gw_pool_eta_weight's without kinds). */
double gw_pool_eta_weight_learned(const gw_pool_eta *e, long i);
/* gw_pool_eta_part_weighed with the cases under way given by their place
 * irun[0..nrun-1] (their weights looked up): the time elapsed counts each
 * by its weight times its share done, the time left by its learned weight
 * times its share left; the cases to come next..n-1 by their learned weights. */
double gw_pool_eta_part_cases(gw_pool_eta *e, double w_ended, const long *irun, const double *share, int nrun,
                              long next);

#endif
