/*
 * test_threads.c: every study of the library run from several threads at once
 * gives, bit for bit, what the same call gives alone (docs/library.md,
 * "Threads"). Each study is run through its gw_study entry (the way the
 * Python module drives it) and its result reduced to a digest of every result
 * row but the run times (numbers and arrays as their bytes, texts, the
 * warnings), or of the status and message of a refusal.
 *
 *  1. Serial: each case once, one after another (the reference digests).
 *  2. Different inputs at once: 4 threads each run every case, each thread
 *     starting at another case, so different studies run at the same time.
 *  3. Identical inputs at once: for each case, 4 threads released together
 *     run the same call.
 *  The cases cover chain (undamped, the restitution calibration's memo with
 *  kk and hc, a soft wall sheet: the chain-layer memo), falcon, wavespeed,
 *  softwall, dispersion (a wave packet, a column's wall spectrum), drop,
 *  layer-make (also writing an HDF5 sample), layer-impact (fast and exact, a
 *  text and an HDF5 sample, crowns), layer-stats and refusals; the memos start
 *  empty so the threads race to fill them.
 *  4. In-memory sweeps (gw_sweep_run_text, 2 workers each) from 3 threads.
 *  5. HDF5 samples written by 4 threads at once: each reads back bit for bit
 *     as the same sample written alone; corrupt HDF5 samples read from 4 threads
 *     at once are refused with the message of one read alone, and nothing is
 *     printed (HDF5's error stack goes to stderr unless silenced in the thread
 *     that calls it).
 *     A corrupt HDF5 sample read on a worker thread, then exit: nothing on
 *     stderr (HDF5's "infinite loop closing library" was printed).
 *  6. gw_interrupt_begin/end pairs overlapping on 4 threads: no request is seen
 *     without a SIGINT, and the process's SIGINT handler is the one before.
 */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "granwave.h"
#include "gw_test.h"
#include "gw_test_files.h"

enum { NT = 4 };

/* ---------------------------------------------------------------- digests -- */

typedef struct digest {
    uint64_t h;
    int rc;
    char msg[512];
} digest;

static uint64_t mix(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++) {
        h ^= b[i];
        h *= 1099511628211ULL;
    }
    return h;
}

static int dim_of(const gw_param *t, const void *out, const char *d)
{
    if (!d)
        return 1;
    char *end;
    long v = strtol(d, &end, 10);
    if (*end == '\0')
        return (int)v;
    const gw_param *p = gw_param_find(t, d);
    return p && p->type == GW_PARAM_INT ? *(const int *)((const char *)out + p->offset) : -1;
}

/* Every result row of out, as bytes (doubles bit for bit). */
static uint64_t digest_out(const gw_study *st, const void *out)
{
    const gw_param *t = st->fields();
    uint64_t h = 1469598103934665603ULL;
    for (int i = 0; t[i].name; i++) {
        const gw_param *p = &t[i];
        const char *f = (const char *)out + p->offset;
        if (strstr(p->name, "_ms") || strstr(p->name, "wall_time")) /* run times */
            continue;
        h = mix(h, p->name, strlen(p->name));
        switch (p->type) {
        case GW_PARAM_DOUBLE:
        case GW_PARAM_COUNT: h = mix(h, f, sizeof(double)); break;
        case GW_PARAM_INT:
        case GW_PARAM_FLAG:
        case GW_PARAM_CHOICE: h = mix(h, f, sizeof(int)); break;
        case GW_PARAM_LONG: h = mix(h, f, sizeof(long)); break;
        case GW_PARAM_RANGE: h = mix(h, f, 2 * sizeof(long)); break;
        case GW_PARAM_TEXT: {
            const char *s = *(char *const *)f;
            h = s ? mix(h, s, strlen(s)) : mix(h, "(null)", 6);
            break;
        }
        case GW_PARAM_LIST: {
            const gw_param_list *l = (const gw_param_list *)f;
            h = mix(h, &l->n, sizeof l->n);
            if (l->n > 0 && l->v)
                h = mix(h, l->v, (size_t)l->n * sizeof(double));
            break;
        }
        case GW_PARAM_DARRAY:
        case GW_PARAM_IARRAY:
        case GW_PARAM_FARRAY: {
            int r = dim_of(t, out, p->rows), c = dim_of(t, out, p->cols);
            const void *a = *(void *const *)f;
            size_t each = p->type == GW_PARAM_DARRAY ? sizeof(double) : sizeof(int);
            h = mix(h, &r, sizeof r);
            h = mix(h, &c, sizeof c);
            if (a && r > 0 && c > 0)
                h = mix(h, a, (size_t)r * (size_t)c * each);
            break;
        }
        }
    }
    const char *w = gw_study_warnings(st, out);
    return w ? mix(h, w, strlen(w)) : h;
}

/* ------------------------------------------------------------------ cases -- */

typedef struct tcase {
    const char *study;
    const char *kv[16]; /* name, value, ..., NULL ("@S" the text sample, "@H" the HDF5
                           one, "@T" the stats table, "@O" an HDF5 sample to write) */
} tcase;

static char sample_txt[256], sample_h5[256], table_csv[256], dir[128];

static const tcase cases[] = {
    {"chain", {"n", "5", "vimp", "0.3", NULL}},
    {"chain", {"n", "3", "damping", "kk", "restitution", "0.7", NULL}},
    {"chain", {"n", "2", "damping", "hc", "restitution", "0.6", NULL}},
    {"chain", {"n", "3", "damping", "kk", "restitution", "0.8", "restitution-v", "0.2", NULL}},
    {"chain", {"n", "3", "sheet", "brass", "sheet-law", "layer", NULL}},
    {"chain", {"n", "4", "vimp", "0.2", "trace", "1", NULL}},
    {"falcon", {"n", "1:3", "vimp", "0.3", "heights", "none", NULL}},
    {"wavespeed", {"n", "6:8", "vimp", "0.1,0.3", "jobs", "2", NULL}},
    {"softwall", {"n", "1:3", "vimp", "0.3", "solver", "rk4", "jobs", "2", NULL}},
    {"dispersion", {"n", "32", "f0", "10", NULL}},
    {"dispersion", {"column-n", "4", NULL}},
    {"drop", {"n", "3", "t-max", "0.004", NULL}},
    {"layer-make", {"n", "12", "width-rm", "6", "seed", "2", "t-max", "0.1", NULL}},
    {"layer-impact", {"sample", "@S", "t-max", "0.003", NULL}},
    {"layer-impact", {"sample", "@H", "t-max", "0.003", "rings", "2", NULL}},
    {"layer-impact", {"sample", "@S", "exact", "1", "t-max", "0.0005", NULL}},
    {"layer-stats", {"input", "@T", NULL}},
    {"chain", {"n", "3", "vimp", "2000", NULL}},               /* refused */
    {"layer-impact", {"sample", "/nonexistent/s.txt", NULL}}, /* refused */
};
enum { NCASES = sizeof cases / sizeof cases[0] };

static const char *value_of(const char *v)
{
    if (strcmp(v, "@S") == 0)
        return sample_txt;
    if (strcmp(v, "@H") == 0)
        return sample_h5;
    if (strcmp(v, "@T") == 0)
        return table_csv;
    return v;
}

static void run_case(const tcase *c, digest *d)
{
    memset(d, 0, sizeof *d);
    const gw_study *st = gw_study_find(c->study);
    if (!st) {
        d->rc = -1000;
        snprintf(d->msg, sizeof d->msg, "no study %s", c->study);
        return;
    }
    void *setup = calloc(1, st->params_size), *out = calloc(1, st->fields_size);
    gw_err e = {{0}};
    int rc = setup && out ? st->init(setup) : GW_ENOMEM;
    for (int k = 0; rc == GW_OK && c->kv[k]; k += 2)
        rc = gw_param_set(st->params(), setup, c->kv[k], value_of(c->kv[k + 1]), &e);
    if (rc == GW_OK) {
        rc = st->run(setup, out, NULL, NULL, &e);
        if (rc == GW_OK)
            d->h = digest_out(st, out);
        st->free_out(out);
    }
    d->rc = rc;
    snprintf(d->msg, sizeof d->msg, "%s", rc == GW_OK ? "" : e.msg);
    if (setup)
        st->clear(setup);
    free(setup);
    free(out);
}

static int same(const digest *a, const digest *b)
{
    return a->rc == b->rc && a->h == b->h && strcmp(a->msg, b->msg) == 0;
}

static digest serial[NCASES];

/* ---------------------------------------------------- threads and rounds -- */

static pthread_barrier_t start;

typedef struct job {
    int k;       /* thread */
    int only;    /* -1: every case from case k on; else that case */
    digest got[NCASES];
} job;

static void *worker(void *arg)
{
    job *j = arg;
    pthread_barrier_wait(&start);
    if (j->only >= 0) {
        run_case(&cases[j->only], &j->got[j->only]);
        return NULL;
    }
    for (int i = 0; i < NCASES; i++) {
        int c = (i + j->k * NCASES / NT) % NCASES;
        run_case(&cases[c], &j->got[c]);
    }
    return NULL;
}

/* NT threads at once: their results into jobs[NT] */
static void concurrent_run(job *jobs, int only)
{
    pthread_t t[NT];
    pthread_barrier_init(&start, NULL, NT);
    for (int k = 0; k < NT; k++) {
        jobs[k].k = k;
        jobs[k].only = only;
        pthread_create(&t[k], NULL, worker, &jobs[k]);
    }
    for (int k = 0; k < NT; k++)
        pthread_join(t[k], NULL);
    pthread_barrier_destroy(&start);
}

/* the number of (thread, case) results of jobs unlike the serial ones */
static int compare(const job *jobs, int only)
{
    int bad = 0;
    for (int k = 0; k < NT; k++)
        for (int c = 0; c < NCASES; c++)
            if ((only < 0 || c == only) && !same(&jobs[k].got[c], &serial[c])) {
                printf("  thread %d, case %d (%s %s=%s): rc %d '%s' vs alone rc %d '%s'%s\n", k, c,
                       cases[c].study, cases[c].kv[0], cases[c].kv[1], jobs[k].got[c].rc, jobs[k].got[c].msg,
                       serial[c].rc, serial[c].msg, jobs[k].got[c].h != serial[c].h ? " (results differ)" : "");
                bad++;
            }
    return bad;
}

static int concurrent(int only)
{
    job *jobs = calloc(NT, sizeof *jobs);
    concurrent_run(jobs, only);
    int bad = compare(jobs, only);
    free(jobs);
    return bad;
}

/* ------------------------------------------------------------------ sweeps -- */

static const char *sweep_text =
    "[sweep]\nmodel = chain\n[grid]\nn = 2, 3, 4\nvimp = 0.1, 0.3\n[params]\ndamping = kk\nrestitution = 0.8\n";

typedef struct sweep_job {
    int rc;
    long ncases;
    uint64_t h;
} sweep_job;

static void run_sweep(sweep_job *s)
{
    double *v = NULL;
    const gw_sweep_model *m = NULL;
    gw_err e = {{0}};
    s->rc = gw_sweep_run_text(sweep_text, "t", 2, NULL, NULL, &v, &s->ncases, &m, &e);
    s->h = v && m ? mix(1469598103934665603ULL, v, (size_t)s->ncases * (size_t)m->ncolumns * sizeof(double)) : 0;
    gw_free(v);
}

static void *sweep_worker(void *arg)
{
    pthread_barrier_wait(&start);
    run_sweep(arg);
    return NULL;
}

static void sweeps(void)
{
    sweep_job alone, at[3];
    run_sweep(&alone);
    pthread_t t[3];
    pthread_barrier_init(&start, NULL, 3);
    for (int k = 0; k < 3; k++)
        pthread_create(&t[k], NULL, sweep_worker, &at[k]);
    int bad = 0;
    for (int k = 0; k < 3; k++) {
        pthread_join(t[k], NULL);
        bad += at[k].rc != alone.rc || at[k].ncases != alone.ncases || at[k].h != alone.h;
    }
    pthread_barrier_destroy(&start);
    char what[1200];
    snprintf(what, sizeof what, "3 in-memory sweeps (6 cases, 2 workers each) at once equal the sweep alone "
                                "(rc %d, %ld cases; %d differ)", alone.rc, alone.ncases, bad);
    gw_test_true(alone.rc == GW_OK && alone.ncases == 6 && bad == 0, what);
}

/* ------------------------------------------------------------------- HDF5 -- */

static gw_layer_sample shared_sample;

typedef struct h5_job {
    int k;
    int rc;
    char msg[512];
    const char *read; /* a file to read, or NULL: write one */
} h5_job;

static void h5_path(char *p, size_t n, int k)
{
    snprintf(p, n, "%s/w%d.h5", dir, k);
}

static void *h5_worker(void *arg)
{
    h5_job *j = arg;
    gw_err e = {{0}};
    pthread_barrier_wait(&start);
    if (j->read) {
        gw_layer_sample s;
        j->rc = gw_layer_sample_read(j->read, &s, &e);
        gw_layer_sample_free(&s);
    } else {
        char p[300];
        h5_path(p, sizeof p, j->k);
        j->rc = gw_layer_sample_write(&shared_sample, p, "threads", &e);
    }
    snprintf(j->msg, sizeof j->msg, "%s", j->rc == GW_OK ? "" : e.msg);
    return NULL;
}

/* the samples in files a and b are the same, field by field and bit for bit
 * (the files' bytes differ by HDF5's object times, seconds, when written in
 * different seconds) */
static int same_sample_file(const char *a, const char *b)
{
    gw_layer_sample p, q;
    int ok = gw_layer_sample_read(a, &p, NULL) == GW_OK;
    ok = gw_layer_sample_read(b, &q, NULL) == GW_OK && ok;
    ok = ok && p.n == q.n && p.seed == q.seed && p.mass_law == q.mass_law && p.clump_mass == q.clump_mass &&
         memcmp(&p.width, &q.width, sizeof p.width) == 0 && memcmp(&p.rm, &q.rm, sizeof p.rm) == 0 &&
         memcmp(&p.volume_ratio, &q.volume_ratio, sizeof p.volume_ratio) == 0 &&
         memcmp(&p.porosity, &q.porosity, sizeof p.porosity) == 0 && p.n > 0 &&
         memcmp(p.x, q.x, (size_t)p.n * sizeof *p.x) == 0 && memcmp(p.y, q.y, (size_t)p.n * sizeof *p.y) == 0 &&
         memcmp(p.r, q.r, (size_t)p.n * sizeof *p.r) == 0 && !p.body == !q.body &&
         (!p.body || memcmp(p.body, q.body, (size_t)p.n * sizeof *p.body) == 0);
    gw_layer_sample_free(&p);
    gw_layer_sample_free(&q);
    return ok;
}

static void h5_threads(void)
{
    gw_err e = {{0}};
    if (gw_layer_sample_read(sample_txt, &shared_sample, &e) != GW_OK) {
        gw_test_true(0, "read the text sample for the HDF5 writes");
        return;
    }
    char alone[300];
    h5_path(alone, sizeof alone, 99);
    int rc = gw_layer_sample_write(&shared_sample, alone, "threads", &e);
    h5_job j[NT];
    pthread_t t[NT];
    for (int rep = 0; rep < 1; rep++) {
        pthread_barrier_init(&start, NULL, NT);
        for (int k = 0; k < NT; k++) {
            memset(&j[k], 0, sizeof j[k]);
            j[k].k = k;
            pthread_create(&t[k], NULL, h5_worker, &j[k]);
        }
        int bad = 0;
        for (int k = 0; k < NT; k++) {
            pthread_join(t[k], NULL);
            char p[300];
            h5_path(p, sizeof p, k);
            if (j[k].rc != GW_OK || !same_sample_file(p, alone)) {
                printf("  HDF5 sample %s: rc %d '%s'; unlike %s\n", p, j[k].rc, j[k].msg, alone);
                bad++;
            }
        }
        pthread_barrier_destroy(&start);
        char what[1200];
        snprintf(what, sizeof what, "4 HDF5 samples written at once each read back as the one written alone, "
                                    "bit for bit (round %d: %d differ)", rep, bad);
        gw_test_true(rc == GW_OK && bad == 0, what);
    }
    /* corrupt copies read at once: the refusal of one read alone, each */
    const long cut[NT][2] = {{-1, 20}, {-1, 60}, {100, -1}, {-1, 300}};
    char bad_path[NT][300];
    h5_job ref[NT];
    for (int k = 0; k < NT; k++) {
        snprintf(bad_path[k], sizeof bad_path[k], "%s/bad%d.h5", dir, k);
        gw_test_copy_prefix(alone, bad_path[k], cut[k][0], cut[k][1]);
        gw_layer_sample s;
        memset(&ref[k], 0, sizeof ref[k]);
        ref[k].rc = gw_layer_sample_read(bad_path[k], &s, &e);
        snprintf(ref[k].msg, sizeof ref[k].msg, "%s", ref[k].rc == GW_OK ? "" : e.msg);
        gw_layer_sample_free(&s);
    }
    for (int rep = 0; rep < 3; rep++) {
        pthread_barrier_init(&start, NULL, NT);
        for (int k = 0; k < NT; k++) {
            memset(&j[k], 0, sizeof j[k]);
            j[k].read = bad_path[(k + rep) % NT];
            pthread_create(&t[k], NULL, h5_worker, &j[k]);
        }
        int bad = 0;
        for (int k = 0; k < NT; k++) {
            pthread_join(t[k], NULL);
            const h5_job *r = &ref[(k + rep) % NT];
            if (j[k].rc != r->rc || strcmp(j[k].msg, r->msg) != 0) {
                printf("  corrupt read %d: rc %d '%s' vs alone rc %d '%s'\n", k, j[k].rc, j[k].msg, r->rc, r->msg);
                bad++;
            }
        }
        pthread_barrier_destroy(&start);
        char what[1200];
        snprintf(what, sizeof what, "4 corrupt HDF5 samples read at once are refused as alone (round %d: %d differ)",
                 rep, bad);
        gw_test_true(ref[0].rc == GW_EFORMAT && bad == 0, what);
    }
    gw_layer_sample_free(&shared_sample);
}

/* A corrupt HDF5 sample read on a thread other than the main one, then exit:
 * nothing on stderr. HDF5 1.10 printed "HDF5: infinite loop closing library"
 * and a line of "FL,FL,..." at exit (its error printing is per thread, and was
 * off only in the reading thread): 12 of 62 one-bit corruptions did. Each
 * corruption in its own child process. */
static void *read_quietly(void *arg)
{
    gw_layer_sample s;
    gw_layer_sample_read(arg, &s, NULL);
    gw_layer_sample_free(&s);
    return NULL;
}

static void h5_exit_quiet(void)
{
#ifdef __SANITIZE_THREAD__
    /* ThreadSanitizer does not support a thread started in a child forked from
     * a multi-threaded process (it reports and exits 66): checked without it */
    printf("note: the exit check is skipped under ThreadSanitizer\n");
    return;
#endif
    char good[300], bad[300], errf[300];
    h5_path(good, sizeof good, 98);
    gw_err e = {{0}};
    gw_layer_sample smp;
    int rc = gw_layer_sample_read(sample_txt, &smp, &e);
    rc = rc == GW_OK ? gw_layer_sample_write(&smp, good, "exit", &e) : rc;
    gw_layer_sample_free(&smp);
    int printed = 0, tried = 0;
    for (long off = 97; rc == GW_OK && off < 1200; off += 97) {
        snprintf(bad, sizeof bad, "%s/exit%ld.h5", dir, off);
        snprintf(errf, sizeof errf, "%s/exit%ld.err", dir, off);
        gw_test_copy_prefix(good, bad, -1, off);
        fflush(stdout);
        pid_t pid = fork();
        if (pid == 0) {
            if (!freopen(errf, "w", stderr))
                _exit(3);
            pthread_t t;
            pthread_create(&t, NULL, read_quietly, bad);
            pthread_join(t, NULL);
            exit(0); /* atexit handlers, HDF5's among them, as a program's end runs them */
        }
        int st = 0;
        waitpid(pid, &st, 0);
        FILE *f = fopen(errf, "r");
        long size = -1;
        if (f) {
            fseek(f, 0, SEEK_END);
            size = ftell(f);
            fclose(f);
        }
        tried++;
        if (!WIFEXITED(st) || WEXITSTATUS(st) != 0 || size != 0) {
            printf("  a sample with bit 0 of byte %ld flipped, read on a thread: exit status %d, %ld bytes on "
                   "stderr at exit\n", off, st, size);
            printed++;
        }
    }
    char what[300];
    snprintf(what, sizeof what, "corrupt HDF5 samples read on a thread, then exit: nothing printed (%d of %d "
                                "printed)", printed, tried);
    gw_test_true(rc == GW_OK && tried == 12 && printed == 0, what);
}

/* -------------------------------------------------------------- interrupt -- */

static void *interrupt_worker(void *arg)
{
    int *seen = arg;
    pthread_barrier_wait(&start);
    for (int i = 0; i < 2000; i++) {
        if (gw_interrupt_begin() != GW_OK)
            (*seen)++;
        *seen += gw_interrupt_pending();
        *seen += gw_interrupt_end();
    }
    return NULL;
}

static void interrupts(void)
{
    struct sigaction before, after;
    sigaction(SIGINT, NULL, &before);
    int seen[NT] = {0};
    pthread_t t[NT];
    pthread_barrier_init(&start, NULL, NT);
    for (int k = 0; k < NT; k++)
        pthread_create(&t[k], NULL, interrupt_worker, &seen[k]);
    int total = 0;
    for (int k = 0; k < NT; k++) {
        pthread_join(t[k], NULL);
        total += seen[k];
    }
    pthread_barrier_destroy(&start);
    sigaction(SIGINT, NULL, &after);
    gw_test_true(total == 0, "4 x 2000 overlapping gw_interrupt_begin/end pairs: no request without a SIGINT");
    gw_test_true(after.sa_handler == before.sa_handler && !gw_interrupt_pending(),
                 "after the pairs SIGINT's handler is the one before");
}

/* ------------------------------------------------------------------- main -- */

static const char *table_text =
    "# granwave 0.1.0 sweep, model layer\n"
    "# param vi = 12.5\n"
    "case,rb-rm,height-rm,point,x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,penetration_rm,"
    "dissipated_first_contact,block_loss_first_contact,energy_error,wave_speed,t_end,steps\n"
    "0,2,5,2,0.05,1,0.3,0.4,20,1,1,1,0.3,3,0.1,0.5,1e-7,0,0,0\n"
    "1,2,5,0,-0.15,1,0.1,0.2,10,1,1,1,0.1,1,0.2,0.7,3e-7,0,0,0\n"
    "2,2,5,3,0.15,1,0.5,0.6,60,1,1,1,0.6,6,0.3,0.6,2e-7,0,0,0\n"
    "3,2,5,1,-0.05,0,0.8,0.9,80,1,1,1,0.2,2,0.4,0.6,nan,0,0,0\n"
    "4,2,8,0,0,1,0.2,0.3,5,1,1,1,0.1,1,0,0.4,0,0,0,0\n";

int main(int argc, char **argv)
{
    /* argument "h5": the HDF5 part only (5), for a quick look */
    const int h5_only = argc > 1 && strcmp(argv[1], "h5") == 0;
    snprintf(dir, sizeof dir, "test_threads.%ld", (long)getpid());
    gw_err e = {{0}};
    if (gw_mkdir_p(dir, &e) != GW_OK) {
        printf("FAIL: cannot make %s: %s\n", dir, e.msg);
        return 1;
    }
    snprintf(sample_txt, sizeof sample_txt, "%s/s.txt", dir);
    snprintf(sample_h5, sizeof sample_h5, "%s/s.h5", dir);
    snprintf(table_csv, sizeof table_csv, "%s/table.csv", dir);
    FILE *f = fopen(table_csv, "w");
    if (f) {
        fputs(table_text, f);
        fclose(f);
    }
    /* the sample: one pluviation, written as text and as HDF5 */
    const gw_study *mk = gw_study_find("layer-make");
    gw_layer_make_setup ms;
    gw_layer_make_outcome mo;
    int rc = mk->init(&ms);
    const char *kv[] = {"n", "40", "width-rm", "14", "seed", "4", "out", sample_txt};
    for (int k = 0; rc == GW_OK && k < 8; k += 2)
        rc = gw_param_set(mk->params(), &ms, kv[k], kv[k + 1], &e);
    rc = rc == GW_OK ? mk->run(&ms, &mo, NULL, NULL, &e) : rc;
    mk->free_out(&mo);
    mk->clear(&ms);
    gw_layer_sample s;
    rc = rc == GW_OK ? gw_layer_sample_read(sample_txt, &s, &e) : rc;
    rc = rc == GW_OK ? gw_layer_sample_write(&s, sample_h5, "h5", &e) : rc;
    gw_layer_sample_free(&s);
    if (rc != GW_OK) {
        printf("FAIL: the sample: %s\n", e.msg);
        return 1;
    }

    if (h5_only) {
        h5_exit_quiet(); /* first: no corrupt file read on the main thread yet */
        h5_threads();
        goto done;
    }
    /* 2a. different inputs at once, first of all: the memos of the restitution
     * calibration and of the layer laws are empty and the threads race to fill them */
    job *first = calloc(NT, sizeof *first);
    concurrent_run(first, -1);

    /* 1. serial references */
    for (int c = 0; c < NCASES; c++) {
        double t0 = gw_clock_ms();
        run_case(&cases[c], &serial[c]);
        printf("  case %d alone: %.0f ms\n", c, gw_clock_ms() - t0);
        char what[1200];
        int refusal = c >= NCASES - 2;
        snprintf(what, sizeof what, "alone: case %d (%s %s=%s) %s (rc %d%s%s)", c, cases[c].study, cases[c].kv[0],
                 cases[c].kv[1], refusal ? "refused" : "runs", serial[c].rc, serial[c].msg[0] ? ": " : "",
                 serial[c].msg);
        gw_test_true(refusal ? serial[c].rc == GW_EINVAL || serial[c].rc == GW_EIO : serial[c].rc == GW_OK, what);
    }

    int bad0 = compare(first, -1);
    free(first);
    char what0[1200];
    snprintf(what0, sizeof what0, "4 threads running the %d cases in different orders, memos empty: every result "
                                  "as alone (%d of %d differ)", NCASES, bad0, NT * NCASES);
    gw_test_true(bad0 == 0, what0);
    /* 2b. different inputs at once, memos filled */
    for (int rep = 0; rep < 1; rep++) {
        int bad = concurrent(-1);
        char what[1200];
        snprintf(what, sizeof what, "4 threads running the %d cases in different orders: every result as alone "
                                    "(round %d: %d of %d differ)", NCASES, rep, bad, NT * NCASES);
        gw_test_true(bad == 0, what);
    }
    /* 3. identical inputs at once */
    for (int c = 0; c < NCASES; c++) {
        int bad = concurrent(c);
        char what[1200];
        snprintf(what, sizeof what, "4 threads running case %d (%s %s=%s) at once: %d of %d differ from alone", c,
                 cases[c].study, cases[c].kv[0], cases[c].kv[1], bad, NT);
        gw_test_true(bad == 0, what);
    }
    sweeps();
    h5_exit_quiet(); /* before h5_threads: no corrupt file read on the main thread yet */
    h5_threads();
    interrupts();
done:
    fflush(stdout);
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        printf("note: could not remove %s\n", dir);
    return gw_test_summary("test_threads");
}
