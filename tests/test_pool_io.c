/*
 * test_pool_io.c: the program's shared machinery, no physics.
 *  - The worker pool (gw_pool.h): with 1 and 2 threads every case k = 0 .. n-1
 *    runs exactly once and progress counts 1, 2, ..., n (one call at a time);
 *    1 thread runs the cases in order; the lowest failing case's status and
 *    message are returned with any number of threads (37 failing slowly, 38 at
 *    once on the other thread: 37, as on one thread; the first failure in time
 *    was kept before) and no case starts after the failure is seen beyond the
 *    one the other thread may already hold; a progress callback asking to stop gives
 *    GW_ECANCELED after exactly D cases (1 thread) or D + 1 at most (2).
 *  - The atomic file (gw_afile, gw_io_afile.c): a commit replaces the old file, which
 *    stays readable until then; a failed write (the file-size limit standing in
 *    for a full disk) leaves neither the file nor a temporary, and an older
 *    file untouched; the named mode used by the HDF5 writers commits and aborts
 *    the same way; SIGINT is held from open to commit.
 *  - The provenance header and comment lines (gw_cli_out.c, gw_write_comment)
 *    have the exact text the CLI tests and notebooks read.
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "gw_cli.h"
#include "gw_pool.h"
#include "gw_test.h"
#include "gw_test_files.h"

/* ---------------------------------------------------------------- pool --- */

#define NCASE 2000

typedef struct cases {
    atomic_int count[NCASE];
    atomic_long order[NCASE]; /* order[i] = the i-th case started */
    atomic_long started;
    long fail_at[2];          /* cases that fail (-1: none) */
    long slow_at;             /* a case that takes 0.2 s (-1: none) */
    long last_done;           /* progress: the previous done */
    int progress_ok;          /* done went 1, 2, 3, ... and total was NCASE */
    long stop_at;             /* progress asks to stop at this done (0: never) */
    atomic_int in_progress;   /* callers inside progress at once */
} cases;

static void cases_init(cases *c)
{
    memset(c, 0, sizeof *c);
    for (int k = 0; k < NCASE; k++) {
        atomic_init(&c->count[k], 0);
        atomic_init(&c->order[k], -1);
    }
    atomic_init(&c->started, 0);
    atomic_init(&c->in_progress, 0);
    c->fail_at[0] = c->fail_at[1] = -1;
    c->slow_at = -1;
    c->progress_ok = 1;
}

static int one_case(void *ctx, long k, gw_err *err)
{
    cases *c = ctx;
    long i = atomic_fetch_add(&c->started, 1);
    if (i < NCASE)
        atomic_store(&c->order[i], k);
    atomic_fetch_add(&c->count[k], 1);
    /* a little work, so that two threads interleave */
    volatile double s = 0;
    for (int j = 0; j < 2000; j++)
        s += j * 1e-9;
    if (k == c->slow_at)
        nanosleep(&(struct timespec){.tv_sec = 0, .tv_nsec = 200000000L}, NULL);
    if (k == c->fail_at[0] || k == c->fail_at[1])
        return gw_err_set(err, GW_ESOLVER, "case %ld failed", k);
    return GW_OK;
}

static int count_progress(void *ctx, long done, long total)
{
    cases *c = ctx;
    if (atomic_fetch_add(&c->in_progress, 1) != 0)
        c->progress_ok = 0; /* two calls at once */
    if (done != c->last_done + 1 || total != NCASE)
        c->progress_ok = 0;
    c->last_done = done;
    atomic_fetch_sub(&c->in_progress, 1);
    return c->stop_at > 0 && done >= c->stop_at;
}

static long runs(cases *c, long *twice)
{
    long n = 0;
    *twice = 0;
    for (int k = 0; k < NCASE; k++) {
        int m = atomic_load(&c->count[k]);
        n += m;
        *twice += m > 1;
    }
    return n;
}

static void test_pool(int jobs)
{
    char what[160];
    static cases c; /* 24 kB: off the stack */
    gw_err err = {{0}};
    long twice;

    cases_init(&c);
    int rc = gw_cases_run(NCASE, jobs, one_case, &c, count_progress, &c, &err);
    int once = 1;
    for (int k = 0; k < NCASE; k++)
        once &= atomic_load(&c.count[k]) == 1;
    snprintf(what, sizeof what, "jobs %d: GW_OK and every one of %d cases run exactly once", jobs, NCASE);
    gw_test_true(rc == GW_OK && once, what);
    snprintf(what, sizeof what, "jobs %d: progress 1, 2, ..., %d of %d, one call at a time", jobs, NCASE, NCASE);
    gw_test_true(c.progress_ok && c.last_done == NCASE, what);
    if (jobs == 1) {
        int in_order = 1;
        for (long i = 0; i < NCASE; i++)
            in_order &= atomic_load(&c.order[i]) == i;
        gw_test_true(in_order, "jobs 1: cases run in order on the calling thread");
    }

    /* the first failure stops the pool; later cases do not start */
    cases_init(&c);
    c.fail_at[0] = 37;
    c.fail_at[1] = 38;
    memset(&err, 0, sizeof err);
    rc = gw_cases_run(NCASE, jobs, one_case, &c, NULL, NULL, &err);
    long n = runs(&c, &twice);
    int below = 1;
    for (int k = 0; k < 37; k++)
        below &= atomic_load(&c.count[k]) == 1;
    snprintf(what, sizeof what, "jobs %d: a failing case returns its status and message", jobs);
    gw_test_true(rc == GW_ESOLVER && strcmp(err.msg, "case 37 failed") == 0, what);
    if (jobs == 1)
        gw_test_true(n == 38 && strcmp(err.msg, "case 37 failed") == 0,
                     "jobs 1: cases 0..37 run, the first failure (37) kept, 38 never run");
    snprintf(what, sizeof what, "jobs %d: after the failure at most %d more case(s) (ran %ld)", jobs, jobs - 1, n);
    gw_test_true(below && twice == 0 && n >= 38 && n <= 38 + (jobs - 1), what);

    /* the lowest failing case kept, not the first in time: 37 fails after
     * 0.2 s, 38 at once on the other thread (a study's error named N = 6 or
     * N = 5 by the threads' timing) */
    cases_init(&c);
    c.fail_at[0] = 37;
    c.fail_at[1] = 38;
    c.slow_at = 37;
    memset(&err, 0, sizeof err);
    rc = gw_cases_run(NCASE, jobs, one_case, &c, NULL, NULL, &err);
    n = runs(&c, &twice);
    snprintf(what, sizeof what, "jobs %d: 37 failing slowly, 38 at once: case 37's failure kept (got '%.40s')",
             jobs, err.msg);
    gw_test_true(rc == GW_ESOLVER && strcmp(err.msg, "case 37 failed") == 0, what);
    snprintf(what, sizeof what, "jobs %d: and at most %d case(s) after 37 (ran %ld)", jobs, jobs - 1, n);
    gw_test_true(twice == 0 && n >= 38 && n <= 38 + (jobs - 1), what);

    /* cancellation from the progress callback */
    cases_init(&c);
    c.stop_at = 5;
    memset(&err, 0, sizeof err);
    rc = gw_cases_run(NCASE, jobs, one_case, &c, count_progress, &c, &err);
    n = runs(&c, &twice);
    snprintf(what, sizeof what, "jobs %d: progress returning non-zero gives GW_ECANCELED after 5 cases", jobs);
    gw_test_true(rc == GW_ECANCELED && strstr(err.msg, "after 5 of 2000 cases") != NULL, what);
    snprintf(what, sizeof what, "jobs %d: canceled: %ld cases run, none twice (5..%d)", jobs, n, 5 + jobs - 1);
    gw_test_true(twice == 0 && n >= 5 && n <= 5 + jobs - 1, what);

    /* nothing to do, and more threads than cases */
    cases_init(&c);
    rc = gw_cases_run(0, jobs, one_case, &c, count_progress, &c, &err);
    gw_test_true(rc == GW_OK && atomic_load(&c.started) == 0, "n = 0: GW_OK, no case run");
    rc = gw_cases_run(3, 64, one_case, &c, NULL, NULL, &err);
    n = runs(&c, &twice);
    gw_test_true(rc == GW_OK && n == 3 && twice == 0, "64 threads asked for 3 cases: each once");
}

/* ------------------------------------------------------------ files --- */

static char dir[64];

/* Number of entries of dir whose name starts with prefix. */
static int count_named(const char *prefix)
{
    DIR *d = opendir(dir);
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d)))
        n += strncmp(e->d_name, prefix, strlen(prefix)) == 0;
    if (d)
        closedir(d);
    return n;
}

static int sigint_held(void)
{
    sigset_t s;
    pthread_sigmask(SIG_BLOCK, NULL, &s);
    return sigismember(&s, SIGINT);
}

static void test_afile(void)
{
    char path[128];
    gw_err err = {{0}};
    gw_afile f;
    snprintf(path, sizeof path, "%s/out.csv", dir);

    /* a commit replaces the old file; until then readers see the old one */
    gw_test_true(gw_write_text(path, "old\n", &err) == GW_OK &&
                     gw_test_file_is(path, "old\n"), "first version written");
    gw_test_true(gw_afile_open(&f, path, &err) == GW_OK, "open over an existing file");
    gw_test_true(sigint_held(), "SIGINT held while the file is open");
    fputs("new\n", f.fp);
    fflush(f.fp);
    gw_test_true(gw_test_file_is(path, "old\n") && count_named("out.csv.tmp.") == 1,
                 "before commit: the old file intact, the new one under a temporary name");
    gw_test_true(gw_afile_commit(&f, &err) == GW_OK, "commit");
    gw_test_true(gw_test_file_is(path, "new\n") && count_named("out.csv.tmp.") == 0,
                 "after commit: the new content, no temporary left");
    gw_test_true(!sigint_held(), "SIGINT released after commit");

    /* a write that fails (the file-size limit, as a full disk would) */
    struct rlimit old_lim, lim;
    getrlimit(RLIMIT_FSIZE, &old_lim);
    signal(SIGXFSZ, SIG_IGN); /* EFBIG instead of the signal */
    gw_test_true(gw_afile_open(&f, path, &err) == GW_OK, "open for a write that will fail");
    lim = old_lim;
    lim.rlim_cur = 4096;
    setrlimit(RLIMIT_FSIZE, &lim);
    for (int i = 0; i < 2000; i++)
        fputs("0123456789\n", f.fp);
    int rc = gw_afile_commit(&f, &err);
    setrlimit(RLIMIT_FSIZE, &old_lim);
    signal(SIGXFSZ, SIG_DFL);
    gw_test_true(rc == GW_EIO && strstr(err.msg, "write failed") != NULL, "a failed write: GW_EIO, 'write failed'");
    gw_test_true(gw_test_file_is(path, "new\n") && count_named("out.csv.tmp.") == 0,
                 "a failed write: the previous file untouched, no temporary left");
    gw_test_true(!sigint_held(), "SIGINT released after a failed commit");

    /* the same failure with no previous file: nothing at all */
    char fresh[128];
    snprintf(fresh, sizeof fresh, "%s/fresh.csv", dir);
    signal(SIGXFSZ, SIG_IGN);
    gw_test_true(gw_afile_open(&f, fresh, &err) == GW_OK, "open a new file");
    setrlimit(RLIMIT_FSIZE, &lim);
    for (int i = 0; i < 2000; i++)
        fputs("0123456789\n", f.fp);
    rc = gw_afile_commit(&f, &err);
    setrlimit(RLIMIT_FSIZE, &old_lim);
    signal(SIGXFSZ, SIG_DFL);
    gw_test_true(rc == GW_EIO && count_named("fresh.csv") == 0, "a failed new file: no file, no temporary");

    /* abort */
    gw_test_true(gw_afile_open(&f, fresh, &err) == GW_OK, "open, then abort");
    fputs("never\n", f.fp);
    gw_afile_abort(&f);
    gw_test_true(count_named("fresh.csv") == 0 && !sigint_held(), "abort: no file, no temporary, SIGINT released");

    /* a missing directory: nothing created, signals released */
    char bad[128];
    snprintf(bad, sizeof bad, "%s/missing/x.csv", dir);
    rc = gw_afile_open(&f, bad, &err);
    gw_afile_abort(&f);
    gw_test_true(rc == GW_EIO && count_named("missing") == 0 && !sigint_held(), "open in a missing directory: GW_EIO");
    char *longp = malloc(5000);
    memset(longp, 'a', 4999);
    longp[4999] = '\0';
    rc = gw_afile_open(&f, longp, &err);
    free(longp);
    gw_test_true(rc == GW_EINVAL && !sigint_held(), "a path too long: GW_EINVAL and SIGINT not left held");

    /* named mode (the HDF5 writers): the writer creates f.tmp itself */
    char h5[128];
    snprintf(h5, sizeof h5, "%s/run.h5", dir);
    gw_test_true(gw_write_text(h5, "old h5\n", &err) == GW_OK, "an older run.h5");
    gw_test_true(gw_afile_open_named(&f, h5, &err) == GW_OK && f.fp == NULL && f.tmp[0] &&
                     count_named("run.h5.tmp.") == 1,
                 "named: no stream, a unique temporary name reserved");
    FILE *fp = fopen(f.tmp, "w"); /* as H5Fcreate(f.tmp, H5F_ACC_TRUNC, ...) does */
    fputs("new h5\n", fp);
    fclose(fp);
    gw_test_true(gw_test_file_is(h5, "old h5\n"), "named: the old file intact before commit");
    gw_test_true(gw_afile_commit(&f, &err) == GW_OK && gw_test_file_is(h5, "new h5\n") &&
                     count_named("run.h5.tmp.") == 0,
                 "named: commit replaces the file, no temporary left");
    gw_test_true(gw_afile_open_named(&f, h5, &err) == GW_OK, "named: open again");
    fp = fopen(f.tmp, "w");
    fputs("half", fp);
    fclose(fp);
    gw_afile_abort(&f); /* the writer failed */
    gw_test_true(gw_test_file_is(h5, "new h5\n") && count_named("run.h5.tmp.") == 0 && !sigint_held(),
                 "named: abort removes the temporary, the old file stays");
    gw_test_true(gw_afile_open_named(&f, h5, &err) == GW_OK, "named: open, temporary lost");
    unlink(f.tmp);
    rc = gw_afile_commit(&f, &err);
    gw_test_true(rc == GW_EIO && gw_test_file_is(h5, "new h5\n") && !sigint_held(),
                 "named: a temporary that vanished fails the commit, the old file stays");

    unlink(path);
    unlink(h5);
}

/* A set of output files (gw_outset): placed together or not at all, the
 * set's names a run does not write removed at the commit. */
static void test_outset(void)
{
    char a[128], b[128], stale[128];
    gw_err err = {{0}};
    gw_outset set;
    static const char *const names[] = {"a.csv", "b.csv", "stale.csv", NULL};
    snprintf(a, sizeof a, "%s/a.csv", dir);
    snprintf(b, sizeof b, "%s/b.csv", dir);
    snprintf(stale, sizeof stale, "%s/stale.csv", dir);
    gw_write_text(a, "old a\n", &err);
    gw_write_text(b, "old b\n", &err);
    gw_write_text(stale, "old stale\n", &err);

    /* staged: a commit of one file does not place it until the set's commit */
    gw_test_true(gw_outset_begin(&set, dir, names, &err) == GW_OK && !sigint_held(),
                 "outset: begin (signals not held through a long run)");
    gw_test_true(gw_write_text(a, "new a\n", &err) == GW_OK && gw_test_file_is(a, "old a\n") &&
                     count_named("a.csv.tmp.") == 1,
                 "outset: a committed file is staged under its temporary name, the old one in place");
    gw_outset nested;
    gw_test_true(gw_outset_begin(&nested, dir, names, &err) == GW_EINVAL, "outset: one set per thread");
    gw_outset_abort(&set);
    gw_test_true(gw_test_file_is(a, "old a\n") && count_named("a.csv.tmp.") == 0 &&
                     gw_test_file_is(stale, "old stale\n"),
                 "outset: abort removes the staged files, the earlier ones stay");

    gw_test_true(gw_outset_begin(&set, dir, names, &err) == GW_OK, "outset: begin again");
    gw_test_true(gw_write_text(a, "new a\n", &err) == GW_OK && gw_write_text(b, "new b\n", &err) == GW_OK &&
                     gw_test_file_is(a, "old a\n") && gw_test_file_is(b, "old b\n"),
                 "outset: two files staged");
    gw_test_true(gw_outset_commit(&set, &err) == GW_OK && gw_test_file_is(a, "new a\n") &&
                     gw_test_file_is(b, "new b\n") &&
                     access(stale, F_OK) != 0 && count_named("a.csv.tmp.") + count_named("b.csv.tmp.") == 0 &&
                     !sigint_held(),
                 "outset: commit places both and removes the set's name this run did not write");
    gw_test_true(gw_write_text(a, "after\n", &err) == GW_OK && gw_test_file_is(a, "after\n"),
                 "outset: after the commit a file is placed at once again");

    gw_test_true(gw_outset_begin(&set, dir, names, &err) == GW_OK && gw_write_text(a, "lost\n", &err) == GW_OK,
                 "outset: one file staged");
    for (int i = 0; i < set.n; i++)
        unlink(set.tmp[i]);
    gw_test_true(gw_outset_commit(&set, &err) == GW_EIO && strstr(err.msg, "a.csv") && gw_test_file_is(a, "after\n") &&
                     gw_test_file_is(b, "new b\n"),
                 "outset: a staged temporary gone fails the commit naming the file, nothing placed or removed");
    unlink(a);
    unlink(b);
}

/* ------------------------------------------------------- provenance --- */

static void test_provenance(void)
{
    char *argv[] = {"--n", "5", "--out", "dir with blank"};
    cJSON *s = cJSON_CreateObject();
    cJSON_AddNumberToObject(s, "k", 1.5);
    cJSON_AddStringToObject(s, "solver", "cvode");
    char want[256];
    snprintf(want, sizeof want,
             "granwave %s\ncommand: granwave chain --n 5 --out 'dir with blank'\nsettings: {\"k\":1.5,\"solver\":\"cvode\"}",
             gw_version());
    char *h = gw_cli_provenance("chain", 4, argv, s);
    gw_test_true(h && strcmp(h, want) == 0, "provenance: version, command line, one-line settings");
    cJSON *d = cJSON_CreateObject();
    cJSON_AddNumberToObject(d, "height", 0.1);
    h = gw_cli_provenance_add(h, "drop", d);
    gw_test_true(h && strncmp(h, want, strlen(want)) == 0 && strcmp(h + strlen(want), "\ndrop: {\"height\":0.1}") == 0,
                 "provenance_add: one more 'key: JSON' line");
    free(h);
    h = gw_cli_provenance("layer-make", 0, NULL, NULL);
    snprintf(want, sizeof want, "granwave %s\ncommand: granwave layer-make", gw_version());
    gw_test_true(h && strcmp(h, want) == 0, "provenance without settings: two lines");
    snprintf(want, sizeof want, "granwave %s;command: granwave layer-make", gw_version());
    gw_test_true(h && strcmp(gw_cli_one_line(h, ';'), want) == 0, "one_line joins the lines with the separator");
    free(h);
    h = gw_cli_command_line("layer-stats", 2, argv);
    gw_test_true(h && strcmp(h, "granwave layer-stats --n 5") == 0, "command line");
    free(h);
    cJSON_Delete(s);
    cJSON_Delete(d);

    char path[128];
    snprintf(path, sizeof path, "%s/comment.txt", dir);
    FILE *fp = fopen(path, "w");
    gw_write_comment(fp, "granwave 1\ncommand: x\n");
    gw_write_comment(fp, NULL);
    gw_write_comment(fp, "last");
    fclose(fp);
    gw_test_true(gw_test_file_is(path, "# granwave 1\n# command: x\n# last\n"),
                 "comment lines: '# ' per line, no empty one");
    unlink(path);
}

int main(void)
{
    test_pool(1);
    test_pool(2);
    snprintf(dir, sizeof dir, "/tmp/gw_test_pool_io_XXXXXX");
    if (!mkdtemp(dir)) {
        gw_test_true(0, "temporary directory");
        return gw_test_summary("test_pool_io");
    }
    test_afile();
    test_outset();
    test_provenance();
    rmdir(dir);
    return gw_test_summary("test_pool_io");
}
