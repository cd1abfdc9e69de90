/*
 * sweep_cmd.c: `granwave sweep CONFIG`, a grid of independent cases (gw_sweep.h).
 *
 * Serial runs use one thread per core (the worker pool, gw_pool.h); under mpirun (OpenMPI) rank 0 is the only
 * writer and hands out cases one at a time (dynamic load balancing: cases differ
 * a lot in cost) to the other ranks. Finished cases go to DIR/journal.csv as they
 * complete; a rerun with the same config skips them, so a sweep killed by
 * SIGINT, SIGTERM or kill -9 resumes without losing finished cases. At the end
 * DIR/results.csv holds one row per case sorted by case number, identical
 * whichever way the cases were run.
 */
#define _POSIX_C_SOURCE 200809L
#include <fcntl.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <sys/stat.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "gw_cli.h"
#include "gw_locale.h"
#include "gw_pool_impl.h"
#include "gw_sweep_impl.h"
#include "sweep_cmd.h"
#if GW_HAVE_MPI
#include <mpi.h>
#endif

#define ROW_MAX 8192

static volatile sig_atomic_t stop_requested;

static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
    signal(SIGINT, SIG_DFL); /* a second signal ends the program at once */
    signal(SIGTERM, SIG_DFL);
}

typedef struct sweep_run {
    const gw_sweep_config *cfg;
    const gw_sweep_model *m;
    long *todo;
    long ntodo, ndone0;
    long done;
    int fd, failed;
    int dirfd; /* the sweep's directory, held from the journal's open to the end */
    const char *out; /* its name */
    double synced_ms; /* gw_clock_ms of the journal's last fsync */
    gw_err err;
    /* Cases whose run failed on their own (a solver failure, an energy
     * error above --energy-tol, a step limit): the sweep stopped at the
     * first one, so a grid with one such point never ran the cases after it
     * and never got its table (leaving the point out of the grid made it
     * another sweep, its journal unusable). The other cases run and are
     * journaled now; these are counted, the first named, and no table is
     * written (it holds every case). */
    long nfailed, first_failed;
    gw_err fail_err;
    /* The journal's name found holding another file (gw_sweep_journal_held):
     * this sweep's journal kept whole beside it (s->fd now that file's), its
     * message in kept_err; no case is handed out after it, the rows of those
     * under way go on into the kept file, and the sweep exits 1. */
    int kept;
    gw_err kept_err;
    pthread_mutex_t lock; /* the journal: one row appended at a time; the progress lines */
    /* the inputs' hashes from one case's check to the next (under the lock,
     * or by the only writer, as the journal) */
    gw_hash_memo inputs_memo;
    gw_cli_progress prog;
    atomic_long running;  /* cases under way (threads; under MPI handed out and not back) */
    /* Threads, with progress lines: the model's run that reports its part
     * (NULL: the cases are not seen inside), and a slot per case under way
     * where it is stored */
    gw_sweep_run_part_fn run_part;
    struct case_slot *slots;
    long nslots;
    double end_sum; /* the last part of the cases ended (their typical end), summed */
    long end_n;
    /* the time left scheduled over the pool's threads (sweep_part), and the
     * share done of each case under way, scratch for it */
    gw_pool_eta eta;
    double *share;
    /* The cases' weights (gw_sweep_weigh: each case's cost as its model
     * expects it, w[i] of todo[i]; NULL: alike), the weight of the cases
     * ended, the first case not yet begun (threads: the pool hands them out
     * in order) */
    const gw_sweep_weigh *weigh;
    double *w;
    double w_ended;
    long next_i;
    /* each case's kind (kind[i] of todo[i], its model's: the time left learns
     * each kind's cost from its ended cases, gw_pool_eta_kinds; NULL: one
     * kind), and the place of each case under way (scratch) */
    int *kind;
    long *irun;
    /* MPI: rank r's case (its place in todo, -1: none) since rank_t0[r] (ms);
     * the time the cases ended took over their weight (the pace a case under
     * way is taken to go at); the schedule over the ranks in use (mpi_eta:
     * the ranks, 0 without it) */
    long *rank_i;
    double *rank_t0;
    double pace_ms, pace_w;
    int mpi_eta;
} sweep_run;

/* A case under way: its part (gw_sweep_part_fn's x, in millionths; -1 none
 * yet), stored by the thread running it at each of its output samples with a
 * relaxed store, read by the ticker: nothing else is added to a case's run. */
typedef struct case_slot {
    atomic_int busy;
    atomic_long x_micro;
    atomic_long i; /* the case's place in todo (its weight) */
} case_slot;

static void case_part(void *pctx, double x)
{
    case_slot *c = pctx;
    if (x >= 0 && x < 1e6)
        atomic_store_explicit(&c->x_micro, (long)(x * 1e6), memory_order_relaxed);
}

/* A free slot for case k of todo starting (NULL: none, or no slots). */
static case_slot *slot_take(const sweep_run *s, long k)
{
    for (long i = 0; i < s->nslots; i++)
        if (!atomic_exchange(&s->slots[i].busy, 1)) {
            atomic_store(&s->slots[i].x_micro, -1);
            atomic_store(&s->slots[i].i, k);
            return &s->slots[i];
        }
    return NULL;
}

/* The part of the sweep done, for its line: the share of its time, as a
 * study's on several threads (gw_pool_eta: time counted in work per thread at
 * work, the cases left scheduled over the pool's threads as it hands them
 * out, threads beyond the CPUs sharing them, so the last cases, run on fewer
 * threads, count at their own pace; on one thread the share of the work).
 * The cases weigh what their model expects of them (s->w, weigh_cases; alike
 * without): the cases ended count whole, and those under way by
 * their parts, each over the part the cases ended reached at their end (their
 * typical end: an impact ends at T_f, long before its t-max; 1 before any
 * ended); one near or past that end is expected to go on a tenth longer than
 * it has, so that a case under way never counts whole (counted whole, a chain
 * sweep said 100 % and ~0 s left while its last case ran). Called at every
 * line due or not (the time elapsed is counted as the work goes). Caller
 * holds s->lock. */
static double sweep_part(sweep_run *s, long done)
{
    const double end = s->end_n > 0 && s->end_sum > 0 ? s->end_sum / (double)s->end_n : 1.0;
    int nrun = 0;
    for (long i = 0; i < s->nslots; i++) {
        const long x = atomic_load_explicit(&s->slots[i].x_micro, memory_order_relaxed);
        if (atomic_load(&s->slots[i].busy)) {
            s->irun[nrun] = atomic_load(&s->slots[i].i);
            s->share[nrun++] = x > 0 ? 1e-6 * (double)x / fmax(end, 1.1e-6 * (double)x) : 0;
        }
    }
    /* cases of unequal cost: counted by their weights (gw_pool_eta_weigh),
     * the cases left of a kind at the pace its ended cases went at */
    if (s->eta.cum)
        return gw_pool_eta_part_cases(&s->eta, s->w_ended, s->irun, s->share, nrun, s->next_i);
    return gw_pool_eta_part(&s->eta, done, s->share, nrun, s->ntodo - done - nrun);
}

#if GW_HAVE_MPI
/* The part under MPI (rank 0 hands out the cases one at a time, in order):
 * as sweep_part, scheduled over the ranks that run cases, but a case under
 * way is not seen inside: its share is the time it has run over the time
 * its learned weight (gw_pool_eta_weight_learned: its kind's pace) takes at
 * the pace of the cases ended (their time over their weight; 0 before any),
 * expected to go on a tenth longer than it has once past it. The cases alike
 * (no weights) weigh 1 each. Caller is the master. */
static double mpi_part(sweep_run *s, int size)
{
    const double now = gw_clock_ms(), pace = s->pace_w > 0 ? s->pace_ms / s->pace_w : 0;
    int nrun = 0;
    for (int r = 1; r < size && nrun < s->eta.threads; r++) {
        if (s->rank_i[r] < 0)
            continue;
        const double wr = gw_pool_eta_weight_learned(&s->eta, s->rank_i[r]);
        const double x = pace > 0 ? (now - s->rank_t0[r]) / (pace * wr) : 0;
        s->irun[nrun] = s->rank_i[r];
        s->share[nrun++] = x / fmax(1.0, 1.1 * x);
    }
    return gw_pool_eta_part_cases(&s->eta, s->w_ended, s->irun, s->share, nrun, s->next_i);
}
#endif

/* The sweep's line when its cases are seen inside (threads): "sweep: k/n
 * cases[ (b done before)], J under way, P% of the work, E s elapsed[, ~L s
 * left]", as the studies' (the time left from P at the pace so far). Due
 * every gw_cli_progress_gap, and at the last case (last). Caller holds
 * s->lock. */
static void sweep_line(sweep_run *s, int last)
{
    gw_cli_progress *p = &s->prog;
    const double now = gw_clock_ms(), el_ms = now - p->t0;
    if (p->quiet)
        return;
    const long done = s->done + s->nfailed;
#if GW_HAVE_MPI
    const double part = last ? 1.0 : s->mpi_eta ? mpi_part(s, s->mpi_eta) : sweep_part(s, done);
#else
    const double part = last ? 1.0 : sweep_part(s, done);
#endif
    const double el = el_ms / 1e3;
    if (!last && now - p->last < gw_cli_progress_gap(p, el_ms))
        return;
    char line[320], before[64] = "", left[64] = "";
    if (p->before > 0)
        snprintf(before, sizeof before, " (%ld done before)", p->before);
    /* the time left from the part estimated now, not the part shown: held
     * where the estimate fell (cases found slower than their kind's weight
     * said, gw_pool_eta_ended), the shown part gave too short a time left
     * until the work caught up with it */
    const double est = !last && s->eta.now > 0 ? s->eta.now : part;
    if (est > 0)
        snprintf(left, sizeof left, ", ~%.1f s left", el / est * (1.0 - est));
    snprintf(line, sizeof line, "%s%ld/%ld %s%s, %ld under way, %.1f%% of the work, %.1f s elapsed%s\n", p->prefix,
             done, s->ntodo, p->unit, before, last ? 0L : atomic_load(&s->running), 100.0 * part, el, left);
    fputs(line, p->fp); /* one write: the ticker's and a worker's lines never mix */
    fflush(p->fp);
    p->last = now;
}

/* The sweep's sign of life between cases: a case may run for minutes (a layer
 * impact in exact mode, a column of hundreds of beads), and the lines came
 * only as cases ended. Due as the studies' (gw_cli_progress_gap: 2 s, then a
 * twentieth of the time elapsed, at most 30 s), from the one display: with
 * cases done the usual line (its rate and time left), before the first
 * "sweep: 0/N cases, J under way, E s elapsed". Caller holds s->lock, or is
 * the only thread (the MPI master). */
static void sweep_tick(sweep_run *s)
{
    if (s->slots || s->mpi_eta) {
        sweep_line(s, 0);
        return;
    }
    gw_cli_progress *p = &s->prog;
    const double now = gw_clock_ms(), el_ms = now - p->t0;
    if (p->quiet || now - p->last < gw_cli_progress_gap(p, el_ms))
        return;
    const long done = s->done + s->nfailed, running = atomic_load(&s->running);
    if (done > 0) { /* due there too: at least every_ms since the last line */
        gw_cli_progress_report(p, done, s->ntodo);
        return;
    }
    char line[256];
    if (p->before > 0)
        snprintf(line, sizeof line, "%s0/%ld %s (%ld done before), %ld under way, %.1f s elapsed\n", p->prefix,
                 s->ntodo, p->unit, p->before, running, el_ms / 1e3);
    else
        snprintf(line, sizeof line, "%s0/%ld %s, %ld under way, %.1f s elapsed\n", p->prefix, s->ntodo, p->unit,
                 running, el_ms / 1e3);
    fputs(line, p->fp);
    fflush(p->fp);
    p->last = now;
}

/* A case's own failure, after which the sweep goes on with the others (a bad
 * value, a file that cannot be read or no memory stop it). */
static int case_failure(int rc)
{
    return rc == GW_ESOLVER || rc == GW_EENERGY || rc == GW_ELIMIT;
}

/* Record a case's own failure (caller holds the lock or is the only writer). */
static void case_failed(sweep_run *s, long k, const gw_err *err)
{
    if (s->nfailed++ == 0 || k < s->first_failed) {
        s->first_failed = k;
        s->fail_err = *err;
    }
}

static int run_case(const sweep_run *s, long k, char *row, case_slot *slot, gw_err *err)
{
    const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
    double out[64];
    if (s->m->ncolumns > 64)
        return gw_err_set(err, GW_EINVAL, "model %s has %d columns (at most 64)", s->m->name, s->m->ncolumns);
    gw_sweep_case(s->cfg, k, names, values);
    unsigned long long read_hash = 0; /* the bytes of the sample the case read */
    const int nk = s->cfg->ngrid + s->cfg->nparams;
    int rc = slot && s->run_part ? s->run_part(nk, names, values, out, &read_hash, case_part, slot, err)
                                 : s->m->run(nk, names, values, out, &read_hash, err);
    if (rc != GW_OK) {
        char tmp[sizeof err->msg];
        snprintf(tmp, sizeof tmp, "%s", err->msg);
        return gw_err_set(err, rc, "case %ld: %s", k, tmp);
    }
    return gw_sweep_format_row(s->cfg, k, out, s->m->ncolumns, read_hash, row, ROW_MAX);
}

/* The journal put back when it was removed from the sweep's directory (said
 * once a time in one line, with --quiet too), or kept aside when its name
 * holds another file now (s->kept: the sweep stops taking cases; rc GW_OK,
 * the row goes on into the kept file); rc set on a failure. Once kept, the
 * kept file is the journal, under its own name: not checked again. */
static void journal_put_back(sweep_run *s, gw_err *err, int *rc)
{
    int back = 0;
    if (s->kept) {
        *rc = GW_OK;
        return;
    }
    *rc = gw_sweep_journal_held(s->dirfd, &s->fd, s->out, &back, err);
    if (back == 2) {
        s->kept = 1;
        s->kept_err = *err;
        *rc = GW_OK;
    }
    char q[GW_CLI_PATH_TEXT];
    if (back == 1)
        fprintf(stderr, "granwave sweep: warning: %s/journal.csv was removed while the sweep ran: put back with "
                "its %ld row%s; the sweep goes on\n", gw_cli_path(q, sizeof q, s->out), s->ndone0 + s->done,
                s->ndone0 + s->done == 1 ? "" : "s");
}

/* The kept journal's message (s->kept_err) with the row at which the file
 * was found written into: "before" the row was written (it went into the
 * kept journal) or "as" it was written (into the file, then kept with it). */
static void kept_at_row(sweep_run *s, const char *when, const char *row)
{
    char tmp[sizeof s->kept_err.msg];
    snprintf(tmp, sizeof tmp, "%s", s->kept_err.msg);
    gw_err_set(&s->kept_err, GW_EIO, "%s (found %s the row of case %ld was written)", tmp, when,
               strtol(row, NULL, 10));
}

/* Append a finished row to the journal (caller holds the lock or is the only
 * writer). */
static int journal(sweep_run *s, const char *row, gw_err *err)
{
    /* the files the case read (a layer sample) still hold what the sweep
     * started with: a sample edited mid-sweep gave rows of both, silently */
    int rc = gw_sweep_case_inputs_check_memo(s->cfg, strtol(row, NULL, 10), &s->inputs_memo, err);
    /* and the case read them as they were: a case that read the sample while
     * it was changed, and ended after it was restored, passed the check above */
    if (rc == GW_OK)
        rc = gw_sweep_row_check(s->cfg, row, err);
    /* and the directory is still there, wherever it was moved: removed, the
     * rows would go into a journal that is in no directory */
    if (rc == GW_OK)
        rc = gw_sweep_dir_held(s->dirfd, s->out, err);
    /* and its journal is still there: removed (rm DIR/journal.csv), every
     * row went on into a file in no directory and was lost at the end */
    const int was_kept = s->kept;
    if (rc == GW_OK)
        journal_put_back(s, err, &rc);
    if (s->kept && !was_kept)
        kept_at_row(s, "before", row);
    if (rc == GW_OK && (rc = gw_sweep_journal_append(s->fd, row, &s->synced_ms, err)) != GW_OK) {
        /* said naming the journal, and what a rerun does with it (a full
         * disk: the row torn inside, cut by the resume) */
        const char *why = strncmp(err->msg, "sweep journal: ", 15) == 0 ? err->msg + 15 : err->msg;
        char tmp[sizeof err->msg];
        snprintf(tmp, sizeof tmp, "%s", why);
        gw_err_set(err, rc, "%s/%s: %s: its %ld rows before are kept, no table written; rerun to resume", s->out,
                   s->kept ? "the kept journal" : "journal.csv", tmp, s->ndone0 + s->done);
    }
    if (rc == GW_OK)
        s->done++;
    /* and the journal held what the sweep wrote up to this row: a file
     * written into between the check above and the row's write (an editor's
     * save, `: >`) had the row appended to it and was found at the next row,
     * or only at the end ("lost rows") when it kept its length; checked now,
     * it is kept at this row, and no case is handed out after it */
    if (rc == GW_OK && !s->kept) {
        journal_put_back(s, err, &rc);
        if (s->kept)
            kept_at_row(s, "as", row);
    }
    return rc;
}

/* One case on the worker pool (gw_pool.h): run, then journal the row. */
static int pool_case(void *ctx, long i, gw_err *err)
{
    sweep_run *s = ctx;
    char *row = malloc(ROW_MAX);
    if (!row)
        return gw_err_set(err, GW_ENOMEM, "case %ld: out of memory", s->todo[i]);
    case_slot *slot = slot_take(s, i);
    const long under_way = atomic_fetch_add(&s->running, 1) + 1;
    const double t_begin = gw_clock_ms();
    if (slot) { /* the threads at work since the last line: the time elapsed (sweep_part) */
        pthread_mutex_lock(&s->lock);
        if (i + 1 > s->next_i)
            s->next_i = i + 1;
        gw_pool_eta_begun(&s->eta, (int)under_way);
        pthread_mutex_unlock(&s->lock);
    }
    int rc = run_case(s, s->todo[i], row, slot, err);
    const double took = gw_clock_ms() - t_begin; /* its run alone: not the wait for the lock below */
    pthread_mutex_lock(&s->lock);
    /* the slot freed with the case counted ended, under the lock the
     * ticker's lines take: never counted both ways */
    const long x = slot ? atomic_load_explicit(&slot->x_micro, memory_order_relaxed) : -1;
    if (slot) {
        atomic_store(&slot->busy, 0);
        s->w_ended += gw_pool_eta_weight(&s->eta, i);
    }
    atomic_fetch_sub(&s->running, 1);
    if (rc == GW_OK) {
        if (x > 0) /* where its part ended: the cases' typical end (sweep_part) */
            s->end_sum += 1e-6 * (double)x, s->end_n++;
        if (slot) /* the time it took: its kind's pace (sweep_part) */
            gw_pool_eta_ended(&s->eta, i, took);
        rc = journal(s, row, err);
    } else if (case_failure(rc)) {
        case_failed(s, s->todo[i], err), rc = GW_OK;
    }
    pthread_mutex_unlock(&s->lock);
    free(row);
    return rc;
}

/* The pool's progress callback: the program's progress line, and stop taking
 * cases once SIGINT or SIGTERM came (the cases under way finish and are
 * journaled). */
static int pool_progress(void *ctx, long done, long total)
{
    sweep_run *s = ctx;
    pthread_mutex_lock(&s->lock); /* the ticker's lines too */
    if (s->slots)
        sweep_line(s, done >= total);
    else
        gw_cli_progress_report(&s->prog, done, total);
    const int stop = stop_requested != 0 || s->kept; /* the journal replaced: no case more */
    pthread_mutex_unlock(&s->lock);
    return stop;
}

/* The ticker thread of a threaded sweep: sweep_tick every 100 ms until the
 * pool has returned. */
typedef struct ticker {
    sweep_run *s;
    atomic_int stop;
} ticker;

static void *tick_loop(void *arg)
{
    ticker *t = arg;
    while (!atomic_load(&t->stop)) {
        nanosleep(&(struct timespec){.tv_sec = 0, .tv_nsec = 100000000L}, NULL);
        pthread_mutex_lock(&t->s->lock);
        if (!atomic_load(&t->stop))
            sweep_tick(t->s);
        pthread_mutex_unlock(&t->s->lock);
    }
    return NULL;
}

static void run_threads(sweep_run *s, long jobs)
{
    gw_err err = {{0}};
    if (!s->prog.quiet && s->run_part && s->ntodo > 0) { /* a slot for each thread of the pool */
        s->nslots = gw_pool_threads(s->ntodo, (int)jobs); /* gw_cases_run's count: every case has one */
        if (gw_pool_eta_init(&s->eta, s->ntodo, (int)jobs) == GW_OK &&
            (s->share = malloc((size_t)s->nslots * sizeof *s->share)) &&
            (s->irun = malloc((size_t)s->nslots * sizeof *s->irun)) &&
            (s->slots = calloc((size_t)s->nslots, sizeof *s->slots))) {
            for (long i = 0; i < s->nslots; i++) {
                atomic_init(&s->slots[i].busy, 0);
                atomic_init(&s->slots[i].x_micro, -1);
                atomic_init(&s->slots[i].i, -1);
            }
            if (s->w && gw_pool_eta_weigh(&s->eta, s->w, s->ntodo) == GW_OK && s->kind) /* else alike */
                gw_pool_eta_kinds(&s->eta, s->kind, s->ntodo); /* out of memory: one kind */
        } else {
            s->nslots = 0; /* without them: the lines as before */
        }
    }
    ticker t = {.s = s};
    atomic_init(&t.stop, 0);
    pthread_t th;
    /* no ticker (no thread to spare): the lines as cases end, as before */
    const int ticking = !s->prog.quiet && pthread_create(&th, NULL, tick_loop, &t) == 0;
    int rc = stop_requested ? GW_ECANCELED
                            : gw_cases_run(s->ntodo, (int)jobs, pool_case, s, pool_progress, s, &err);
    if (ticking) {
        atomic_store(&t.stop, 1);
        pthread_join(th, NULL);
    }
    free(s->slots);
    free(s->share);
    free(s->irun);
    gw_pool_eta_free(&s->eta);
    s->slots = NULL;
    s->share = NULL;
    s->irun = NULL;
    s->nslots = 0;
    if (rc != GW_OK && rc != GW_ECANCELED) {
        s->failed = rc;
        s->err = err;
    }
}

#if GW_HAVE_MPI
enum { TAG_READY = 1, TAG_ROW = 2, TAG_FAIL = 3, TAG_WORK = 4 };

/* Wait for a request without taking a core: Open MPI's blocking calls (receive,
 * broadcast, barrier) busy-poll, so a rank waiting on rank 0's journal check or
 * table write, or on its next case, would spin at 100 % CPU and slow the ranks
 * sharing its core. Test for about 100 us (a reply to a finished case comes
 * within that), then sleep, 20 us at first and doubling to 1 ms. */
static void mpi_idle_wait(MPI_Request *req, MPI_Status *st, sweep_run *ticks)
{
    int flag = 0;
    double t0 = gw_clock_ms();
    long nap = 20000;
    for (int spins = 0; MPI_Test(req, &flag, st) == MPI_SUCCESS && !flag; spins++) {
        if (spins < 1000 && gw_clock_ms() - t0 < 0.1)
            continue;
        nanosleep(&(struct timespec){.tv_sec = 0, .tv_nsec = nap}, NULL);
        if (nap < 1000000)
            nap *= 2;
        if (ticks) /* the master, waiting on its workers' cases: the sweep's sign of life */
            sweep_tick(ticks);
    }
}

/* The master's schedule for its lines (mpi_part), when it can be made: the
 * ranks but the master run the cases; on one node they share its CPUs, over
 * several each has its own. */
static void mpi_eta_start(sweep_run *s, int size)
{
    if (s->prog.quiet || s->ntodo < 1 || size < 2)
        return;
    const char *local = getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
    s->rank_i = malloc((size_t)size * sizeof *s->rank_i);
    s->rank_t0 = malloc((size_t)size * sizeof *s->rank_t0);
    s->share = malloc((size_t)size * sizeof *s->share);
    s->irun = malloc((size_t)size * sizeof *s->irun);
    if (!s->rank_i || !s->rank_t0 || !s->share || !s->irun ||
        gw_pool_eta_init(&s->eta, s->ntodo, size - 1) != GW_OK)
        return; /* without it: the lines of the rate at which cases end, as before */
    if (!(local && atol(local) == size))
        s->eta.cpus = s->eta.threads;
    for (int r = 0; r < size; r++)
        s->rank_i[r] = -1;
    if (s->w && gw_pool_eta_weigh(&s->eta, s->w, s->ntodo) == GW_OK && s->kind)
        gw_pool_eta_kinds(&s->eta, s->kind, s->ntodo);
    s->mpi_eta = size;
}

static void mpi_eta_end(sweep_run *s)
{
    gw_pool_eta_free(&s->eta);
    free(s->rank_i);
    free(s->rank_t0);
    free(s->share);
    free(s->irun);
    s->rank_i = NULL, s->rank_t0 = NULL, s->share = NULL, s->irun = NULL;
    s->mpi_eta = 0;
}

/* A line of the master: the schedule's, or the rate's without it. */
static void mpi_line(sweep_run *s)
{
    if (s->mpi_eta)
        sweep_line(s, s->done + s->nfailed >= s->ntodo);
    else
        gw_cli_progress_report(&s->prog, s->done + s->nfailed, s->ntodo);
}

static void mpi_master(sweep_run *s, int size)
{
    char *buf = malloc(ROW_MAX + 16);
    int active = size - 1;
    long next = 0;
    mpi_eta_start(s, size);
    while (active > 0 && buf) {
        MPI_Status st;
        /* Wait without spinning (mpi_idle_wait): an idle master would take a
         * core from the workers (bench/README_layer.md). */
        MPI_Request req;
        MPI_Irecv(buf, ROW_MAX + 16, MPI_CHAR, MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &req);
        mpi_idle_wait(&req, &st, s);
        if (st.MPI_TAG == TAG_ROW || st.MPI_TAG == TAG_FAIL)
            atomic_fetch_sub(&s->running, 1);
        const int src = st.MPI_SOURCE;
        if (s->mpi_eta && src > 0 && src < size && s->rank_i[src] >= 0) { /* its case ended: weighed */
            const double wr = gw_pool_eta_weight(&s->eta, s->rank_i[src]);
            s->w_ended += wr;
            if (st.MPI_TAG == TAG_ROW) { /* the pace: of the cases run to their end, and of their kind */
                s->pace_ms += gw_clock_ms() - s->rank_t0[src], s->pace_w += wr;
                gw_pool_eta_ended(&s->eta, s->rank_i[src], gw_clock_ms() - s->rank_t0[src]);
            }
            s->rank_i[src] = -1;
        }
        gw_err err = {{0}};
        if (st.MPI_TAG == TAG_ROW) {
            int rc = journal(s, buf, &err);
            if (rc == GW_OK)
                mpi_line(s);
            if (rc != GW_OK && !s->failed) {
                s->failed = rc;
                s->err = err;
            }
        } else if (st.MPI_TAG == TAG_FAIL && buf[0] == 'C') { /* the case's own failure: go on */
            long k = strtol(buf + 1, NULL, 10);
            const char *msg = strchr(buf + 1, ' ');
            gw_err_set(&err, GW_ESOLVER, "%s", msg ? msg + 1 : buf + 1);
            case_failed(s, k, &err);
            mpi_line(s);
        } else if (st.MPI_TAG == TAG_FAIL && !s->failed) {
            s->failed = buf[0] == 'I' ? GW_EINVAL : GW_ESOLVER;
            gw_err_set(&s->err, s->failed, "%s", buf + 1);
        }
        long k = -1;
        if (next < s->ntodo && !s->failed && !stop_requested && !s->kept) {
            k = s->todo[next++];
            const long under_way = atomic_fetch_add(&s->running, 1) + 1;
            if (s->mpi_eta && src > 0 && src < size) {
                s->rank_i[src] = next - 1;
                s->rank_t0[src] = gw_clock_ms();
                s->next_i = next;
                gw_pool_eta_begun(&s->eta, (int)under_way);
            }
        } else {
            active--;
        }
        MPI_Send(&k, 1, MPI_LONG, st.MPI_SOURCE, TAG_WORK, MPI_COMM_WORLD);
    }
    free(buf);
    mpi_eta_end(s);
}

static void mpi_worker(sweep_run *s)
{
    char *row = malloc(ROW_MAX + 16);
    char dummy = 0;
    MPI_Send(&dummy, 1, MPI_CHAR, 0, TAG_READY, MPI_COMM_WORLD);
    for (;;) {
        long k;
        MPI_Request req;
        MPI_Irecv(&k, 1, MPI_LONG, 0, TAG_WORK, MPI_COMM_WORLD, &req);
        mpi_idle_wait(&req, MPI_STATUS_IGNORE, NULL);
        if (k < 0 || !row)
            break;
        gw_err err = {{0}};
        int rc = run_case(s, k, row, NULL, &err);
        if (rc == GW_OK) {
            MPI_Send(row, (int)strlen(row) + 1, MPI_CHAR, 0, TAG_ROW, MPI_COMM_WORLD);
        } else {
            if (case_failure(rc))
                snprintf(row, ROW_MAX, "C%ld %s", k, err.msg);
            else
                snprintf(row, ROW_MAX, "%c%s", rc == GW_EINVAL ? 'I' : 'F', err.msg);
            MPI_Send(row, (int)strlen(row) + 1, MPI_CHAR, 0, TAG_FAIL, MPI_COMM_WORLD);
        }
    }
    free(row);
}
#endif

static const char *summary =
    "Run every case of the grid in CONFIG (an INI file: [sweep] model/out, [grid]\n"
    "keys with lists or A:B ranges, [params] fixed keys; keys are the model command's\n"
    "options). Resumable: finished cases are journaled in OUT/journal.csv and skipped\n"
    "on a rerun; OUT/results.csv gets one row per case, sorted. Under mpirun, rank 0\n"
    "writes and hands out cases to the other ranks; otherwise one thread per core.";

/* A refusal or failure in one line, "granwave sweep: ..." (a message that
 * names the command itself, "sweep: ", "sweep --jobs: ", "sweep CONFIG: ",
 * "sweep journal: ", "sweep table: ", as it is). Any message starting
 * "sweep" was taken for one: a config or --out named sweep.ini, sweeps/ or
 * sweep_out/ lost the command's name ("granwave sweep_out/journal.csv: ..."). */
static void say_error(const gw_err *err)
{
    static const char *const own[] = {"sweep: ", "sweep --", "sweep CONFIG: ", "sweep journal: ", "sweep table: "};
    const char *m = err->msg;
    int named = 0;
    for (size_t i = 0; i < sizeof own / sizeof own[0] && !named; i++)
        named = strncmp(m, own[i], strlen(own[i])) == 0;
    fprintf(stderr, named ? "granwave %s\n" : "granwave sweep: %s\n", m);
}

/* What a run would do now, after `--check` read the journal in out: start,
 * resume (ndone of ncases done; a torn last row of torn bytes cut and its case
 * run again, or a torn line of the head, torn_head 1, or a zeroed end,
 * torn_head 2, cut), or write the table
 * only. */
static void check_report(const char *out_given, long ncases, int exists, long ndone, size_t torn, int torn_head)
{
    char out[GW_CLI_PATH_TEXT];
    gw_cli_path(out, sizeof out, out_given);
    if (!exists) {
        printf("sweep: %s: no journal yet: a run starts all %ld cases\n", out, ncases);
        return;
    }
    printf("sweep: %s/journal.csv: %ld of %ld cases done", out, ndone, ncases);
    if (ndone < ncases)
        printf(", %ld to run on a resume", ncases - ndone);
    if (torn && torn_head == 2)
        printf("; its zeroed end (%zu NUL byte%s after its last line, a power cut's) is cut then, no case to run "
               "again for it", torn, torn == 1 ? "" : "s");
    else if (torn && torn_head)
        printf("; the torn last line of its head (%zu byte%s) is cut then, no case to run again for it", torn,
               torn == 1 ? "" : "s");
    else if (torn)
        printf("; its torn last row (%zu byte%s) is cut then and its case run again", torn, torn == 1 ? "" : "s");
    printf(ndone == ncases ? ": a rerun writes the table only\n" : "\n");
}

/* Where the sweep's directory (held open in dirfd) is now, when out no
 * longer names it (moved or renamed while the sweep ran): 1 and its path in
 * where (n bytes; Linux's /proc/self/fd tells it); 0 when out names it still,
 * or it was removed (gw_sweep_dir_held says so). */
static int dir_moved(const char *out, int dirfd, char *where, size_t n)
{
    struct stat a, b;
    if (dirfd < 0 || fstat(dirfd, &a) != 0 || a.st_nlink == 0)
        return 0;
    if (stat(out, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino)
        return 0;
    char link[64];
    snprintf(link, sizeof link, "/proc/self/fd/%d", dirfd);
    const ssize_t k = readlink(link, where, n - 1);
    if (k > 0 && where[0] == '/')
        where[k] = '\0';
    else
        snprintf(where, n, "the directory it was moved to (this system does not tell its path)");
    return 1;
}

/* The cases to run weighed before they run, for the progress lines' time
 * left (s->w, by the model's gw_sweep_weigh; left NULL, the cases alike, for
 * a model without one, above SWEEP_WEIGH_MAX cases, or out of memory). By
 * the share of the cases, a sweep of unequal cases (a chain over n = 150 to
 * 300, the costliest last) said 0.34 to 0.86 of its true time left. */
#define SWEEP_WEIGH_MAX 1000000L
static void weigh_cases(sweep_run *s, const gw_sweep_config *cfg, const gw_sweep_weigh *wg)
{
    if (!wg || !wg->weight || s->ntodo < 1 || s->ntodo > SWEEP_WEIGH_MAX ||
        !(s->w = malloc((size_t)s->ntodo * sizeof *s->w)))
        return;
    s->kind = malloc((size_t)s->ntodo * sizeof *s->kind); /* NULL: the cases of one kind */
    const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
    void *memo = NULL;
    for (long i = 0; i < s->ntodo; i++) {
        gw_sweep_case(cfg, s->todo[i], names, values);
        int kind = -1;
        s->w[i] = wg->weight(&memo, cfg->ngrid + cfg->nparams, names, values, &kind);
        if (s->kind)
            s->kind[i] = kind;
    }
    if (wg->memo_free)
        wg->memo_free(memo);
}

/* A refusal's exit code: 2 for the config or a case (bad input), 1 when the
 * check itself ran out of memory (a run failure: the input is not at fault). */
static int exit_code(int rc)
{
    return rc == GW_ENOMEM ? 1 : 2;
}

/* the check pass's progress (gw_sweep_check_pass), said as it goes */
static int check_progress(void *ctx, long done, long total)
{
    gw_cli_progress_report(ctx, done, total);
    return 0;
}

int gw_cmd_sweep(int argc, char **argv, const gw_sweep_model *const *models, const gw_sweep_run_part_fn *parts,
                 const gw_sweep_weigh *const *weighs, int nmodels)
{
    const char *out = NULL;
    long jobs = 0;
    int quiet = 0, help = 0, npos = 0, check_only = 0;
    const char *pos[1] = {NULL};
    char cq[GW_CLI_PATH_TEXT], wq[GW_CLI_PATH_TEXT]; /* a path as printed (gw_cli_path) */
    gw_opt opts[] = {
        {.name = "out", .kind = GW_OPT_STRING, .dest = &out, .metavar = "DIR", .help = "output directory [config's [sweep] out]"},
        {.name = "jobs", .kind = GW_OPT_LONG, .dest = &jobs, .metavar = "J", .help = "threads without MPI [0 = one per CPU]", .lo = 0, .hi = GW_SWEEP_JOBS_MAX},
        {.name = "check", .kind = GW_OPT_FLAG, .dest = &check_only, .help = "validate the config and every case, read the journal as a resume would; write nothing"},
        {.name = "quiet", .kind = GW_OPT_FLAG, .dest = &quiet, .help = "no progress lines"},
        {0}};
    gw_err err = {{0}};
    int rank = 0, size = 1, use_mpi = 0;
#if GW_HAVE_MPI
    use_mpi = getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMI_SIZE");
    if (use_mpi) {
        MPI_Init(NULL, NULL);
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        MPI_Comm_size(MPI_COMM_WORLD, &size);
    }
#endif
    int code = 0;
    gw_sweep_config cfg;
    memset(&cfg, 0, sizeof cfg);
    const gw_sweep_model *m = NULL;
    sweep_run s;
    memset(&s, 0, sizeof s);
    s.fd = -1;
    s.dirfd = -1;
    int rc = GW_OK;
    char *done = NULL;
    char *check_warn = NULL, *rows_warn = NULL; /* the sweep's warnings, said and written into its table */
    if (gw_cli_parse("sweep", opts, argc, argv, &help, pos, 1, &npos, &err) != GW_OK) {
        code = 2;
    } else if (help) {
        if (rank == 0)
            code = gw_cli_help(stdout, "sweep", "granwave sweep CONFIG [--out DIR] [options]", summary, opts, help);
        goto finish;
    } else if (npos != 1) {
        gw_err_set(&err, GW_EINVAL, "a config file is required (see granwave sweep --help)");
        code = 2;
    } else if (use_mpi && size > 1 && gw_cli_find(opts, "jobs")->seen) {
        /* every rank decides alike (the same arguments): no broadcast needed */
        gw_err_set(&err, GW_EINVAL, "sweep --jobs: has no effect under mpirun with %d ranks (each rank but the "
                   "writer runs one case at a time: choose the ranks with mpirun -np)", size);
        code = 2;
    } else if ((rc = gw_sweep_config_read(pos[0], models, nmodels, &cfg, &m, &err)) != GW_OK) {
        code = exit_code(rc);
    } else if (!out && !(out = cfg.out)) {
        gw_err_set(&err, GW_EINVAL, "%s: no output directory ([sweep] out or --out)", pos[0]);
        code = 2;
    }
    /* The output location before a case is checked: a grid of 90000 layer
     * cases took 25 s to be refused for --out naming a file ("X: not a
     * directory", also for a symbolic link to nothing). --check too: the
     * config's out is part of what it validates. */
    if (code == 0 && rank == 0) {
        char what[4200];
        if (out == cfg.out)
            snprintf(what, sizeof what, "sweep: %s: [sweep] out", pos[0]);
        else
            snprintf(what, sizeof what, "sweep --out");
        static const char *const sweep_files[] = {"journal.csv", "results.csv", NULL};
        if (gw_out_check(out, what, &err) != GW_OK || gw_out_names_check(out, sweep_files, what, &err) != GW_OK)
            code = 2;
        /* and no input of the sweep (the config, a sample) is its journal or
         * table there: before, a config named DIR/results.csv ran and was
         * replaced by the table (exit 0), and --check passed a sample there */
        else if (gw_sweep_out_inputs_check(out, &cfg, &err) != GW_OK)
            code = 2;
    }
    /* The journal and table of the whole grid fit, before a case is checked */
    if (code == 0 && rank == 0 && (rc = gw_sweep_size_check(&cfg, m, &err)) != GW_OK) {
        fprintf(stderr, "granwave sweep: %s: %s\n", gw_cli_path(cq, sizeof cq, pos[0]), err.msg);
        err.msg[0] = '\0';
        code = exit_code(rc);
    }
    /* Validate every case before running anything (bad values exit 2). */
    if (code == 0 && rank == 0 && m->check) {
        /* a layer case is checked in about 0.2 to 0.6 ms (its sample read):
         * a grid of 1e5 cases takes a minute, 1e9 days; say so as it goes */
        gw_cli_progress chk;
        gw_cli_progress_init(&chk, "sweep: checked ", "cases", 2000);
        chk.quiet = quiet;
        /* the library's pass, as gw_sweep_run's and Python's: its refusals
         * (a case, or the config as a whole: a chain key of no effect on any
         * case) and what the cases will run other than given (a chain case's
         * dt above its step), one line over the pass */
        char *warn = NULL;
        if ((rc = gw_sweep_check_pass(&cfg, m, check_progress, &chk, &warn, &err)) != GW_OK)
            code = exit_code(rc);
        gw_cli_warnings("sweep", warn);
        check_warn = warn; /* the table's "# warning:" lines too */
        if (code)
            fprintf(stderr, "granwave sweep: %s: %s\n", gw_cli_path(cq, sizeof cq, pos[0]), err.msg);
        err.msg[0] = '\0';
    }
    /* The cases under way at once hold their memory together: bounded before
     * anything is made (the workers: --jobs threads, or the MPI ranks but the
     * writer on this node) */
    if (code == 0 && rank == 0) {
        long most = 0, workers = jobs;
        const char *local = getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
        if (use_mpi && size > 1)
            workers = local && atol(local) > 1 ? atol(local) - 1 : size - 1;
        if ((rc = gw_sweep_memory_check(&cfg, m, workers, use_mpi && size > 1, &most, &err)) != GW_OK) {
            code = exit_code(rc);
            if (strncmp(err.msg, "jobs: ", 6) == 0 && use_mpi && size > 1)
                fprintf(stderr, "granwave sweep: %s: the MPI ranks: %s (mpirun -np %ld or fewer)\n",
                        gw_cli_path(cq, sizeof cq, pos[0]),
                        err.msg + 6, most + 1);
            else if (strncmp(err.msg, "jobs: ", 6) == 0)
                fprintf(stderr, "granwave sweep --jobs: %s%s\n", err.msg + 6,
                        jobs == 0 ? " (--jobs 0 is one per CPU)" : "");
            else
                fprintf(stderr, "granwave sweep: %s: %s\n", gw_cli_path(cq, sizeof cq, pos[0]), err.msg);
            err.msg[0] = '\0';
        }
    }
    /* --check: and what a resume would do with the journal there, read by
     * the resume's own code (its refusals, the same exit codes), nothing
     * written: `--check` said "is valid" beside another config's journal,
     * which the run then refused */
    if (code == 0 && check_only && rank == 0) {
        long ndone = 0;
        int exists = 0, torn_head = 0;
        size_t torn = 0;
        if (!(done = calloc((size_t)cfg.ncases, 1)))
            code = 1, gw_err_set(&err, GW_ENOMEM, "out of memory");
        else if ((rc = gw_sweep_journal_resume_check(out, &cfg, done, &ndone, &exists, &torn, &torn_head, &err)) != GW_OK)
            code = rc == GW_EIO ? 1 : exit_code(rc);
        if (code == 0) {
            printf("sweep: %s is valid: model %s, %ld cases\n", gw_cli_path(cq, sizeof cq, pos[0]), cfg.model,
                   cfg.ncases);
            check_report(out, cfg.ncases, exists, ndone, torn, torn_head);
        }
    }
    if (check_only) { /* every rank to the end: a refusal of rank 0 included (the other ranks wait there) */
        if (code != 0 && rank == 0 && err.msg[0])
            say_error(&err);
        goto finish;
    }
    if (code == 0 && rank == 0) {
        done = calloc((size_t)cfg.ncases, 1);
        s.todo = malloc((size_t)cfg.ncases * sizeof *s.todo);
        if (!done || !s.todo)
            code = 1, gw_err_set(&err, GW_ENOMEM, "out of memory");
        else if (gw_mkdir_p(out, &err) != GW_OK ||
                 (rc = gw_sweep_journal_open_at(out, &cfg, done, &s.ndone0, &s.fd, &s.dirfd, &err)) != GW_OK)
            code = rc == GW_EIO ? 1 : exit_code(rc); /* the journal stays open, and locked, until the sweep ends */
        s.out = out;
    }
    if (code == 0 && rank == 0) {
        for (long k = 0; k < cfg.ncases; k++)
            if (!done[k])
                s.todo[s.ntodo++] = k;
    }
#if GW_HAVE_MPI
    if (use_mpi) { /* the other ranks wait here, idle, while rank 0 checks the journal */
        MPI_Request req;
        MPI_Ibcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD, &req);
        mpi_idle_wait(&req, MPI_STATUS_IGNORE, NULL);
    }
#endif
    if (code == 0) {
        s.cfg = &cfg;
        s.m = m;
        for (int i = 0; i < nmodels; i++)
            if (models[i] == m) {
                s.run_part = parts ? parts[i] : NULL;
                s.weigh = weighs ? weighs[i] : NULL;
            }
        if (rank == 0 && !quiet)
            weigh_cases(&s, &cfg, s.weigh);
        gw_cli_progress_init(&s.prog, "sweep: ", "cases", 2000);
        s.prog.before = s.ndone0;
        s.prog.quiet = quiet;
        atomic_init(&s.running, 0);
        pthread_mutex_init(&s.lock, NULL);
        signal(SIGINT, on_signal);
        signal(SIGTERM, on_signal);
        if (rank == 0 && !quiet)
            fprintf(stderr, "sweep: %ld cases, %ld already done, %ld to run on %s\n", cfg.ncases, s.ndone0, s.ntodo,
                    use_mpi && size > 1 ? "MPI ranks" : "threads");
#if GW_HAVE_MPI
        if (use_mpi && size > 1) {
            if (rank == 0)
                mpi_master(&s, size);
            else
                mpi_worker(&s);
        } else
#endif
            if (rank == 0)
            run_threads(&s, jobs);
        pthread_mutex_destroy(&s.lock);
        /* the directory as it is now: out, or where it was moved meanwhile */
        char where[4200];
        const int moved = rank == 0 && dir_moved(out, s.dirfd, where, sizeof where);
        const char *now = moved ? where : out;
        /* the journal still there, whatever ended the sweep: removed or
         * replaced after its last row, a stop or a failed case said "rerun to
         * resume" and the rerun found the rows gone, or another file's */
        if (rank == 0 && !s.kept) {
            gw_err e2 = {{0}};
            journal_put_back(&s, &e2, &rc);
            if (rc != GW_OK && !s.failed)
                s.failed = rc, s.err = e2;
        }
        if (rank == 0) {
            if (s.kept) {
                /* the rows are in the kept file: a rerun as it is reads
                 * the other file, which may hold fewer of them, or none
                 * (cut to nothing: the rerun refuses it, naming it) */
                gw_err_set(&err, GW_EIO, "%s; the sweep stopped taking cases after %ld new: %ld of its %ld cases "
                           "are journaled there; to resume with them, move it over journal.csv and rerun (a rerun "
                           "as it is reads the file now named journal.csv)", s.kept_err.msg, s.done,
                           s.ndone0 + s.done, cfg.ncases);
                code = 1;
            } else if (s.failed) {
                err = s.err;
                code = s.failed == GW_EINVAL ? 2 : 1;
            } else if (stop_requested) {
                if (moved)
                    fprintf(stderr, "sweep: interrupted after %ld new cases; %s was moved to %s while the sweep "
                            "ran: move it back and rerun the same command to resume (or rerun with --out %s)\n",
                            s.done, gw_cli_path(cq, sizeof cq, out), gw_cli_path(wq, sizeof wq, where), wq);
                else
                    fprintf(stderr, "sweep: interrupted after %ld new cases; rerun the same command to resume\n",
                            s.done);
                code = 130;
            } else if (s.nfailed) {
                gw_err_set(&err, GW_ESOLVER, "sweep: %ld of the %ld cases run failed (the first, %s); %ld of the "
                           "sweep's %ld cases are journaled in %s/journal.csv, no table written (it holds every "
                           "case): rerun to retry the failed cases", s.nfailed, s.ntodo, s.fail_err.msg,
                           s.ndone0 + s.done, cfg.ncases, now);
                code = 1;
            } else if (gw_sweep_journal_sync(s.fd, &s.synced_ms, &err) != GW_OK ||
                       gw_sweep_write_table_warned(s.dirfd, now, &cfg, m, check_warn, &rows_warn, &err) != GW_OK) {
                code = 1;
            } else {
                /* the cases that did not end (the chain's converged 0: a
                 * collision held by gravity or cut at t-max), with --quiet
                 * too, then the model's rule over the rows (a chain case
                 * pressed beyond one radius, a large energy error, a
                 * chatter): one line each over the cases, of the journal's
                 * rows (a resume's and the MPI ranks' too), as the table's
                 * "# warning:" lines write them */
                gw_cli_warnings("sweep", rows_warn);
                /* finished where the directory went: said even with --quiet */
                if (moved)
                    fprintf(stderr, "granwave sweep: warning: %s was moved while the sweep ran: its journal and "
                            "table are in %s\n", gw_cli_path(cq, sizeof cq, out), gw_cli_path(wq, sizeof wq, where));
                if (!quiet)
                {
                    char q[GW_CLI_PATH_TEXT];
                    fprintf(stderr, "sweep: %ld cases in %.1f s; table %s/results.csv\n", s.done,
                            (gw_clock_ms() - s.prog.t0) / 1e3, gw_cli_path(q, sizeof q, now));
                }
            }
        }
    }
    if (code != 0 && code != 130 && rank == 0 && err.msg[0])
        say_error(&err);
finish:
    if (s.fd >= 0) { /* after the table: the journal's lock held to the end */
        gw_err e2; /* rows since the last fsync (a stop, a failure) made durable too */
        if (rank == 0 && s.done > 0 && gw_sweep_journal_sync(s.fd, NULL, &e2) != GW_OK && code == 0) {
            fprintf(stderr, "granwave sweep: %s\n", e2.msg);
            code = 1;
        }
        gw_sweep_journal_close(s.fd); /* and the copy of it kept for its checks */
    }
    if (s.dirfd >= 0)
        close(s.dirfd);
    free(done);
    free(check_warn);
    free(rows_warn);
    free(s.todo);
    gw_io_hash_memo_free(&s.inputs_memo);
    free(s.w);
    free(s.kind);
    gw_sweep_config_free(&cfg);
#if GW_HAVE_MPI
    if (use_mpi) { /* idle while rank 0 writes the table: MPI_Finalize's own wait spins */
        MPI_Request req;
        MPI_Ibarrier(MPI_COMM_WORLD, &req);
        mpi_idle_wait(&req, MPI_STATUS_IGNORE, NULL);
        MPI_Finalize();
    }
#endif
    return code;
}
