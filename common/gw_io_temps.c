/*
 * gw_io_temps.c: the temporaries this process has made and not yet placed or
 * removed (an atomic file's from its open, gw_io_afile.c; a staged file of an
 * output set until the set is placed, gw_io_outset.c; a new sweep journal's),
 * kept where a signal handler can find them, and the handler a program may
 * install to remove them when SIGINT, SIGTERM or SIGHUP ends it.
 *
 * Before, a program ended by one of these signals while its output set was
 * open (layer-impact's run after its first snapshot, or a command between two
 * files of its set) left the staged temporaries in --out until the next write
 * of the same name removed them, as after kill -9.
 *
 * A handler may call no allocator and take no lock, so the table is
 * file-scope (the one place a handler can reach: an exception to the house
 * rule of no mutable file-scope state), each slot claimed and released by
 * atomic operations. It starts as one block of 64 slots and grows by blocks
 * of 64 made outside the handler (in gw_temps_add, by the thread that needs a
 * slot): a block is filled in before it is linked to the last one by one
 * atomic compare-and-swap, so a handler walking the chain sees it whole or not at all,
 * and blocks are never freed (a handler on another thread may be reading one).
 * Before, the table was one fixed block: the 65th temporary open or staged at
 * once was not registered, and a signal left it (an output set of the library
 * with more than 64 files, or 65 atomic files open at once). The memory kept is
 * the peak number of temporaries at once, about 4 KiB each past the first 64.
 * Slots are added and dropped under the signal hold of the
 * file layer (gw_io_sig_hold), so a handler on the same thread never sees a
 * slot half written; a handler on another thread reads a slot's path and its
 * generation before and after the copy and unlinks only a path that did not
 * change meanwhile. A slot may also hold the descriptor of the directory its
 * temporary is in (an output set's, which the set holds open until it
 * closes, gw_io_outset.c): the handler then removes the temporary by its
 * last name there (unlinkat, async-signal-safe), so a signal after --out was
 * moved or replaced finds it where it went. The library never installs the handler itself: a program
 * asks for it (gw_temps_on_signals, called by the granwave program first
 * thing); a binding keeps its interpreter's own signal handling.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "gw_common.h"
#include "gw_io_impl.h"

/* A handler may only use atomics that take no lock */
_Static_assert(ATOMIC_INT_LOCK_FREE == 2 && ATOMIC_POINTER_LOCK_FREE == 2, "lock-free atomics for the handler");

#define TEMPS_BLOCK 64
#define TEMP_PATH_MAX (4096 + 64) /* gw_afile.tmp */
_Static_assert(sizeof(((gw_afile *)0)->tmp) <= TEMP_PATH_MAX, "an atomic file's temporary fits a slot");

enum { SLOT_FREE, SLOT_BUSY, SLOT_LIVE };

typedef struct temp_slot {
    atomic_int state;  /* SLOT_FREE, SLOT_BUSY (being filled or emptied), SLOT_LIVE */
    atomic_uint gen;   /* changed at every fill: a reader's copy is checked against it */
    atomic_uint hash;  /* of path: a drop compares it first (a set of thousands of files) */
    atomic_int dirfd;  /* the directory it is in, held open by its output set, or -1 (by path) */
    atomic_int made;   /* 0: a temporary file; > 0: path is a directory this process made, made the
                        * length of the shallowest one it made (gw_temps_add_dirs) */
    dev_t dev;         /* a made directory's identity, set before the slot is live */
    ino_t ino;
    char path[TEMP_PATH_MAX];
} temp_slot;

typedef struct temp_block {
    temp_slot slot[TEMPS_BLOCK];
    struct temp_block *_Atomic next; /* NULL, or a block filled in before it was linked */
} temp_block;

static temp_block first;

static unsigned path_hash(const char *p)
{
    uint32_t h = 2166136261u; /* FNV-1a */
    for (; *p; p++)
        h = (h ^ (unsigned char)*p) * 16777619u;
    return h;
}

/* The block after b, made and linked when there is none: NULL when out of
 * memory. Two threads that both link one: the first wins, the other frees its
 * own (never seen by anyone) and takes the winner's. */
static temp_block *next_block(temp_block *b)
{
    temp_block *nx = atomic_load(&b->next);
    if (nx)
        return nx;
    temp_block *nb = malloc(sizeof *nb);
    if (!nb)
        return NULL;
    for (int i = 0; i < TEMPS_BLOCK; i++) {
        atomic_init(&nb->slot[i].state, SLOT_FREE);
        atomic_init(&nb->slot[i].gen, 0u);
        atomic_init(&nb->slot[i].hash, 0u);
        atomic_init(&nb->slot[i].dirfd, -1);
        atomic_init(&nb->slot[i].made, 0);
        nb->slot[i].path[0] = '\0';
    }
    atomic_init(&nb->next, NULL);
    temp_block *want = NULL;
    if (atomic_compare_exchange_strong(&b->next, &want, nb))
        return nb;
    free(nb);
    return want;
}

int gw_temps_add(const char *path) { return gw_temps_add_at(path, -1); }

static int temps_add(const char *path, int dirfd, size_t made, const struct stat *st);

int gw_temps_add_at(const char *path, int dirfd) { return temps_add(path, dirfd, 0, NULL); }

int gw_temps_add_dirs(const char *path, const char *made)
{
    const size_t lm = made ? strlen(made) : 0;
    struct stat st;
    if (!path || lm == 0 || strncmp(path, made, lm) != 0 || (path[lm] != '\0' && path[lm] != '/') ||
        stat(path, &st) != 0 || !S_ISDIR(st.st_mode))
        return -1;
    return temps_add(path, -1, lm, &st);
}

static int temps_add(const char *path, int dirfd, size_t made, const struct stat *st)
{
    const size_t n = path ? strlen(path) : 0;
    if (n == 0 || n >= TEMP_PATH_MAX)
        return -1;
    const unsigned h = path_hash(path);
    int base = 0;
    for (temp_block *b = &first; b; b = next_block(b), base += TEMPS_BLOCK)
        for (int i = 0; i < TEMPS_BLOCK; i++) {
            temp_slot *t = &b->slot[i];
            int want = SLOT_FREE;
            if (atomic_load(&t->state) != SLOT_FREE ||
                !atomic_compare_exchange_strong(&t->state, &want, SLOT_BUSY))
                continue;
            memcpy(t->path, path, n + 1);
            atomic_store(&t->hash, h);
            atomic_store(&t->dirfd, dirfd < 0 ? -1 : dirfd);
            atomic_store(&t->made, (int)made);
            t->dev = st ? st->st_dev : 0;
            t->ino = st ? st->st_ino : 0;
            atomic_fetch_add(&t->gen, 1);
            atomic_store(&t->state, SLOT_LIVE);
            return base + i;
        }
    return -1; /* out of memory for a new block */
}

void gw_temps_drop(const char *path)
{
    if (!path || !*path)
        return;
    const unsigned h = path_hash(path);
    for (temp_block *b = &first; b; b = atomic_load(&b->next))
        for (int i = 0; i < TEMPS_BLOCK; i++) {
            temp_slot *t = &b->slot[i];
            if (atomic_load(&t->state) != SLOT_LIVE || atomic_load(&t->hash) != h || strcmp(t->path, path) != 0)
                continue;
            int want = SLOT_LIVE;
            if (atomic_compare_exchange_strong(&t->state, &want, SLOT_BUSY)) {
                atomic_fetch_add(&t->gen, 1);
                atomic_store(&t->state, SLOT_FREE);
            }
            return;
        }
}

void gw_temps_unbind(int dirfd)
{
    if (dirfd < 0)
        return;
    for (temp_block *b = &first; b; b = atomic_load(&b->next))
        for (int i = 0; i < TEMPS_BLOCK; i++) {
            temp_slot *t = &b->slot[i];
            int want = SLOT_LIVE;
            if (atomic_load(&t->state) != SLOT_LIVE || atomic_load(&t->dirfd) != dirfd ||
                !atomic_compare_exchange_strong(&t->state, &want, SLOT_BUSY))
                continue;
            atomic_store(&t->dirfd, -1);
            atomic_fetch_add(&t->gen, 1);
            atomic_store(&t->state, SLOT_LIVE);
        }
}

/* Async-signal-safe: atomic loads, a byte copy, unlinkat(2) and unlink(2). A
 * path already renamed into place no longer exists under its temporary name:
 * its unlink fails (ENOENT) and the placed file stays. A temporary of an
 * output set is removed by its own name in the directory the set holds open,
 * wherever that directory went: before, the handler removed it by the path
 * it was made under, and a SIGINT, SIGTERM or SIGHUP that came after --out
 * was moved (mv D D.old) or replaced left every staged temporary in D.old and
 * looked for them in whatever D was now. */
/* Then the directories made for them (gw_temps_add_dirs), emptied by the
 * first pass: each removed from the deepest up to the shallowest made, by
 * rmdir (only an empty one goes), the deepest only while it is still the
 * directory that was made (lstat: one moved away and another in its place
 * stays). Before, a command that made --out (layer-impact, whose run
 * stages its snapshots there) and was ended by a signal left it empty. */
static void rmdirs_up(char *copy, size_t len, size_t made)
{
    while (rmdir(copy) == 0) {
        const size_t prev = len;
        while (len > made && copy[len - 1] == '/') /* its trailing slashes, its last name, the slashes before */
            len--;
        while (len > made && copy[len - 1] != '/')
            len--;
        while (len > made && copy[len - 1] == '/')
            len--;
        if (len < made || len == prev || len == 0)
            return;
        copy[len] = '\0';
    }
}

static void remove_made_dir(char *copy, size_t len, size_t made, dev_t dev, ino_t ino)
{
    struct stat st;
    if (lstat(copy, &st) == 0 && S_ISDIR(st.st_mode) && st.st_dev == dev && st.st_ino == ino)
        rmdirs_up(copy, len, made);
}

void gw_temps_unmake(const char *path, const char *made)
{
    char copy[TEMP_PATH_MAX];
    const size_t n = path ? strlen(path) : 0, lm = made ? strlen(made) : 0;
    if (!path)
        return;
    gw_temps_drop(path);
    if (lm == 0 || n >= sizeof copy || strncmp(path, made, lm) != 0)
        return;
    memcpy(copy, path, n + 1);
    rmdirs_up(copy, n, lm);
}

void gw_temps_remove(void)
{
    char copy[TEMP_PATH_MAX];
    for (int dirs = 0; dirs <= 1; dirs++)
    for (temp_block *b = &first; b; b = atomic_load(&b->next))
        for (int i = 0; i < TEMPS_BLOCK; i++) {
            temp_slot *t = &b->slot[i];
            if (atomic_load(&t->state) != SLOT_LIVE || (atomic_load(&t->made) > 0) != dirs)
                continue;
            const unsigned g = atomic_load(&t->gen);
            const int dfd = atomic_load(&t->dirfd);
            const size_t made = (size_t)atomic_load(&t->made);
            const dev_t dev = t->dev;
            const ino_t ino = t->ino;
            size_t k = 0, base = 0;
            for (; k + 1 < sizeof copy && t->path[k]; k++) { /* no memcpy: a byte loop is safe in a handler */
                copy[k] = t->path[k];
                if (copy[k] == '/')
                    base = k + 1;
            }
            copy[k] = '\0';
            if (atomic_load(&t->state) != SLOT_LIVE || atomic_load(&t->gen) != g)
                continue;
            if (dirs)
                remove_made_dir(copy, k, made, dev, ino);
            else if (dfd >= 0)
                unlinkat(dfd, copy + base, 0);
            else
                unlink(copy);
        }
}

/* The placing of output sets as a critical section for the handler.
 * gw_outset_commit holds SIGINT, SIGTERM and SIGHUP on its own thread, but a
 * signal sent to the process is taken by any thread that does not hold it (an
 * OpenMP or pool worker, a thread of the caller): the handler ran there,
 * removed the temporaries not yet renamed and ended the process between two
 * renames, or during the rollback, and --out held some new files, some old,
 * and the earlier files kept aside under their side names. Now one lock-free
 * word holds the number of sets being placed, the signal that came meanwhile
 * (the first; the others end the process as well) and whether the process is
 * ending: a handler that finds a set being placed only records its signal and
 * returns, and the last placer to finish (the set wholly placed or wholly put
 * back) sends it again to the process, whose handler then ends it as before. */
#define PLACING_COUNT 0xffffu      /* sets being placed */
#define PLACING_SIG_SHIFT 16       /* the signal deferred meanwhile (0: none) */
#define PLACING_SIG (0xffu << PLACING_SIG_SHIFT)
#define PLACING_ENDING (1u << 30)  /* a handler is ending the process: place nothing more */
static atomic_uint placing;
static struct sigaction default_action; /* SIG_DFL, filled in before the handler is installed */

/* The temporaries removed, then the signal's own default action: the process
 * ends killed by the signal (a shell sees 128 + its number), as it did before
 * the handler, only without the temporaries. The default is put back here
 * (not by SA_RESETHAND: a signal deferred while a set is placed must find the
 * handler again) and SA_NODEFER leaves the signal unblocked, so raise() ends
 * the process here. */
static void on_signal(int sig)
{
    const int e = errno;
    unsigned s = atomic_load(&placing);
    for (;;) {
        if (!(s & PLACING_ENDING) && (s & PLACING_COUNT)) {
            const unsigned want = (s & PLACING_SIG) ? s : s | (unsigned)sig << PLACING_SIG_SHIFT;
            if (atomic_compare_exchange_weak(&placing, &s, want)) {
                errno = e; /* the placer sends it again when the set is placed or put back */
                return;
            }
        } else if (atomic_compare_exchange_weak(&placing, &s, s | PLACING_ENDING))
            break;
    }
    gw_temps_remove();
    sigaction(sig, &default_action, NULL);
    raise(sig);
    errno = e; /* not reached unless the signal is blocked elsewhere */
}

int gw_temps_placing_begin(void)
{
    unsigned s = atomic_load(&placing);
    for (int waited = 0;;) {
        if (s & PLACING_ENDING) {
            /* a handler on another thread is removing the temporaries and
             * ends the process within microseconds: wait for it rather than
             * exit with another status (bounded: a handler of the program's
             * own that chose not to end it) */
            if (waited++ >= 500)
                return -1;
            struct timespec ts = {0, 10 * 1000 * 1000};
            nanosleep(&ts, NULL);
            s = atomic_load(&placing);
        } else if ((s & PLACING_COUNT) == PLACING_COUNT)
            return -1; /* 65535 sets placed at once: never in practice */
        else if (atomic_compare_exchange_weak(&placing, &s, s + 1))
            return 0;
    }
}

void gw_temps_placing_end(void)
{
    unsigned s = atomic_load(&placing), want;
    int sig;
    do {
        want = s - 1;
        sig = 0;
        if (!(want & PLACING_COUNT)) { /* the last one: the deferred signal is this placer's to send */
            sig = (int)((want & PLACING_SIG) >> PLACING_SIG_SHIFT);
            want &= ~PLACING_SIG;
        }
    } while (!atomic_compare_exchange_weak(&placing, &s, want));
    if (sig) /* to the process: taken by a thread that does not hold it, as the first was */
        kill(getpid(), sig);
}

/* A child forked while a set was placed on another thread has no placer:
 * its signals are not deferred */
static void placing_fork_child(void) { atomic_store(&placing, 0u); }

static void temps_once(void)
{
    memset(&default_action, 0, sizeof default_action);
    default_action.sa_handler = SIG_DFL;
    sigemptyset(&default_action.sa_mask);
    pthread_atfork(NULL, NULL, placing_fork_child);
}

static const int end_signals[] = {SIGHUP,  SIGINT,    SIGQUIT, SIGTERM, SIGUSR1,
                                  SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU};

const int *gw_io_end_signals(size_t *n)
{
    *n = sizeof end_signals / sizeof end_signals[0];
    return end_signals;
}

int gw_temps_on_signals(void)
{
    size_t nsigs;
    const int *sigs = gw_io_end_signals(&nsigs);
    static pthread_once_t once = PTHREAD_ONCE_INIT;
    pthread_once(&once, temps_once);
    int rc = GW_OK;
    for (size_t k = 0; k < nsigs; k++) {
        struct sigaction old;
        if (sigaction(sigs[k], NULL, &old) != 0) {
            rc = GW_EIO;
            continue;
        }
        /* a signal ignored (nohup's SIGHUP, a script's background job's
         * SIGINT) stays ignored, and a handler the program has is its own */
        if ((old.sa_flags & SA_SIGINFO) || old.sa_handler != SIG_DFL)
            continue;
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        for (size_t j = 0; j < nsigs; j++) /* one removal at a time */
            if (j != k)
                sigaddset(&sa.sa_mask, sigs[j]);
        /* SA_RESTART: a deferred signal returns to the thread it came to,
         * whose read or write goes on */
        sa.sa_flags = SA_NODEFER | SA_RESTART;
        if (sigaction(sigs[k], &sa, NULL) != 0)
            rc = GW_EIO;
    }
    return rc;
}
