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
 * A handler may call no allocator and take no lock, so the table is fixed and
 * file-scope (the one place a handler can reach: an exception to the house
 * rule of no mutable file-scope state), each slot claimed and released by
 * atomic operations. Slots are added and dropped under the signal hold of the
 * file layer (gw_io_sig_hold), so a handler on the same thread never sees a
 * slot half written; a handler on another thread reads a slot's path and its
 * generation before and after the copy and unlinks only a path that did not
 * change meanwhile. The library never installs the handler itself: a program
 * asks for it (gw_temps_on_signals, called by the granwave program first
 * thing); a binding keeps its interpreter's own signal handling.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <signal.h>
#include <stdatomic.h>
#include <string.h>
#include <unistd.h>

#include "gw_common.h"
#include "gw_io_impl.h"

/* The slots: one per temporary at once. A command's output set holds at most
 * 13 files (falcon's) beside the file being written; a temporary that finds
 * the table full is not registered, and a signal then leaves it as kill -9
 * does (the next write of its name removes it). */
#define TEMPS_MAX 64
#define TEMP_PATH_MAX (4096 + 64) /* gw_afile.tmp */
_Static_assert(sizeof(((gw_afile *)0)->tmp) <= TEMP_PATH_MAX, "an atomic file's temporary fits a slot");

enum { SLOT_FREE, SLOT_BUSY, SLOT_LIVE };

typedef struct temp_slot {
    atomic_int state;  /* SLOT_FREE, SLOT_BUSY (being filled or emptied), SLOT_LIVE */
    atomic_uint gen;   /* changed at every fill: a reader's copy is checked against it */
    char path[TEMP_PATH_MAX];
} temp_slot;

static temp_slot slots[TEMPS_MAX];

int gw_temps_add(const char *path)
{
    const size_t n = path ? strlen(path) : 0;
    if (n == 0 || n >= TEMP_PATH_MAX)
        return -1;
    for (int i = 0; i < TEMPS_MAX; i++) {
        int want = SLOT_FREE;
        if (!atomic_compare_exchange_strong(&slots[i].state, &want, SLOT_BUSY))
            continue;
        memcpy(slots[i].path, path, n + 1);
        atomic_fetch_add(&slots[i].gen, 1);
        atomic_store(&slots[i].state, SLOT_LIVE);
        return i;
    }
    return -1;
}

void gw_temps_drop(const char *path)
{
    if (!path || !*path)
        return;
    for (int i = 0; i < TEMPS_MAX; i++) {
        if (atomic_load(&slots[i].state) != SLOT_LIVE || strcmp(slots[i].path, path) != 0)
            continue;
        int want = SLOT_LIVE;
        if (atomic_compare_exchange_strong(&slots[i].state, &want, SLOT_BUSY)) {
            atomic_fetch_add(&slots[i].gen, 1);
            atomic_store(&slots[i].state, SLOT_FREE);
        }
        return;
    }
}

/* Async-signal-safe: atomic loads, a byte copy and unlink(2). A path
 * already renamed into place no longer exists under its temporary name: its
 * unlink fails (ENOENT) and the placed file stays. */
void gw_temps_remove(void)
{
    char copy[TEMP_PATH_MAX];
    for (int i = 0; i < TEMPS_MAX; i++) {
        if (atomic_load(&slots[i].state) != SLOT_LIVE)
            continue;
        const unsigned g = atomic_load(&slots[i].gen);
        size_t k = 0;
        for (; k + 1 < sizeof copy && slots[i].path[k]; k++) /* no memcpy: a byte loop is safe in a handler */
            copy[k] = slots[i].path[k];
        copy[k] = '\0';
        if (atomic_load(&slots[i].state) == SLOT_LIVE && atomic_load(&slots[i].gen) == g)
            unlink(copy);
    }
}

/* The temporaries removed, then the signal's own default action: the process
 * ends killed by the signal (a shell sees 128 + its number), as it did before
 * the handler, only without the temporaries. SA_RESETHAND has put the default
 * back on entry and SA_NODEFER leaves the signal unblocked, so raise() ends
 * the process here. */
static void on_signal(int sig)
{
    const int e = errno;
    gw_temps_remove();
    raise(sig);
    errno = e; /* not reached unless the signal is blocked elsewhere */
}

int gw_temps_on_signals(void)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    int rc = GW_OK;
    for (size_t k = 0; k < sizeof sigs / sizeof sigs[0]; k++) {
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
        for (size_t j = 0; j < sizeof sigs / sizeof sigs[0]; j++) /* one removal at a time */
            if (j != k)
                sigaddset(&sa.sa_mask, sigs[j]);
        sa.sa_flags = SA_RESETHAND | SA_NODEFER;
        if (sigaction(sigs[k], &sa, NULL) != 0)
            rc = GW_EIO;
    }
    return rc;
}
