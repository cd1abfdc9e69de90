/*
 * gw_sweep_journal.c: the append-only journal of a sweep (DIR/journal.csv):
 * created whole, locked while the sweep runs, checked and its torn last row
 * cut when a sweep resumes, appended a row at a time. A journal row is complete
 * only with its trailing FNV-1a checksum and newline, so a row torn by kill -9
 * is detected and dropped on the next run; rows are appended with one write()
 * each (a kill loses none: the row is in the kernel's cache once write()
 * returns) and the journal is fsynced at most every GW_SWEEP_SYNC_MS and at the
 * sweep's end, so a power cut loses at most the rows of that interval, which
 * the rerun runs again. An fsync per row made a 0.32 ms case cost 3.7 ms.
 * No units.
 */
#define _GNU_SOURCE /* O_PATH (gw_sweep_dir_open) */
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <dirent.h>
#include <stdio.h>
#include <sys/file.h>
#include <sys/sysmacros.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "gw_sweep.h"
#include "gw_locale.h"
#include "gw_sweep_impl.h"
#include "gw_io_impl.h"

/* A journal row as read: its case, text (without ",checksum\n") and line. */
typedef struct jrow {
    long k;
    const char *s;
    size_t len;
    long line;
} jrow;

static int jrow_cmp(const void *pa, const void *pb)
{
    const jrow *a = pa, *b = pb;
    if (a->k != b->k)
        return a->k < b->k ? -1 : 1;
    return (a->line > b->line) - (a->line < b->line);
}

/* The bytes a journal is read in: the buffer grows as they come, never to the
 * size fstat claims at once (a 10 GB sparse journal had 10 GB allocated and
 * read before a byte was looked at) */
#define SLURP_CHUNK ((size_t)1 << 20)

size_t gw_sweep_journal_bound(const gw_sweep_config *cfg)
{
    if (!cfg || cfg->ncolumns <= 0 || cfg->ncases <= 0)
        return GW_SWEEP_JOURNAL_MAX;
    /* the head: its lines, the "# grid" and "# param" lines (every name and
     * value), the "# input" lines (the read_key values again, and a hash) */
    double head = 4096.0 + GW_SWEEP_BUILD_MAX;
    for (int s = 0; s < 2; s++) {
        const gw_sweep_key *keys = s ? cfg->params : cfg->grid;
        const int nk = s ? cfg->nparams : cfg->ngrid;
        for (int i = 0; i < nk; i++)
            for (int j = 0; keys[i].values && j < keys[i].nvalues; j++)
                head += 2.0 * ((double)strlen(keys[i].name) + (keys[i].values[j] ? strlen(keys[i].values[j]) : 0) +
                               64.0);
    }
    /* each case's row twice over (a row run again after its first copy was
     * torn by a kill is one more), and the head twice */
    const double b = 2.0 * head + 2.0 * gw_sweep_row_bound(cfg, cfg->ncolumns) * (double)cfg->ncases + SLURP_CHUNK;
    return b < (double)GW_SWEEP_JOURNAL_MAX ? (size_t)b : GW_SWEEP_JOURNAL_MAX;
}

char *gw_sweep_slurp(const char *path, size_t max, size_t *len, gw_err *err)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        gw_err_set(err, GW_EIO, "%s: cannot read: %s", path, strerror(errno));
        return NULL;
    }
    FILE *fp = NULL;
    int rc = gw_input_open(path, "sweep journal", &fp, err);
    if (rc != GW_OK) {
        /* what it is (a FIFO, a directory) is in err: it said "Invalid argument";
         * ENOMEM tells the caller it was memory, not the journal */
        errno = rc == GW_ENOMEM ? ENOMEM : EINVAL;
        return NULL;
    }
    char *buf = gw_sweep_slurp_fd(fileno(fp), path, max, len, err);
    const int e = errno;
    fclose(fp);
    errno = e;
    return buf;
}

/* the refusal of a journal's NUL byte (line, byte at: the first), buf freed;
 * taking says the caller takes a zeroed end (other bytes came after this one) */
static char *slurp_nul(char *buf, const char *path, long line, size_t at, int taking, gw_err *err)
{
    gw_err_set(err, GW_EINVAL, "sweep journal '%s': line %ld (byte %zu): a NUL byte, which no journal holds (binary "
               "data, or a file whose end a crash left zeroed%s); move it away to start the sweep afresh", path, line,
               at, taking ? ": here inside a line, or with other bytes after it" : "");
    free(buf);
    errno = EINVAL;
    return NULL;
}

/* 1 when one of the n bytes at p is not NUL */
static int memchr_nonzero(const char *p, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (p[i])
            return 1;
    return 0;
}

char *gw_sweep_slurp_fd(int fd, const char *path, size_t max, size_t *len, gw_err *err)
{
    return gw_sweep_slurp_fd_zeros(fd, path, max, len, NULL, err);
}

char *gw_sweep_slurp_fd_zeros(int fd, const char *path, size_t max, size_t *len, size_t *zeros, gw_err *err)
{
    struct stat st;
    if (zeros)
        *zeros = 0;
    errno = 0;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        gw_err_set(err, GW_EIO, "%s: cannot read: %s", path, strerror(errno ? errno : EIO));
        errno = EIO;
        return NULL;
    }
    if (max > GW_SWEEP_JOURNAL_MAX)
        max = GW_SWEEP_JOURNAL_MAX;
    if ((unsigned long long)st.st_size > (unsigned long long)max) {
        gw_err_set(err, GW_EINVAL, "sweep journal '%s' is %llu bytes, more than this sweep's journal can hold (%zu "
                   "bytes, its head and every case's row twice over): not its journal; move it away to start the "
                   "sweep afresh", path, (unsigned long long)st.st_size, max);
        errno = EINVAL;
        return NULL;
    }
    char *buf = NULL;
    size_t n = 0, cap = 0;
    /* a zeroed end (zeros given): the text's bytes kept (n), then the NUL
     * bytes after its last newline read past them into buf + n, counted in
     * nz; z_line and z_at the first NUL's line and byte, for the refusal of a
     * byte other than NUL after it */
    size_t nz = 0, z_at = 0;
    long z_line = 0;
    int in_zeros = 0;
    for (;;) {
        if (n + SLURP_CHUNK + 1 > cap) {
            /* doubled, never past what max needs */
            size_t nc = cap ? 2 * cap : SLURP_CHUNK + 1;
            if (nc > max + SLURP_CHUNK + 1)
                nc = max + SLURP_CHUNK + 1;
            if (nc < n + SLURP_CHUNK + 1)
                nc = n + SLURP_CHUNK + 1;
            char *nb = realloc(buf, nc);
            if (!nb) {
                free(buf);
                gw_err_set(err, GW_ENOMEM, "sweep journal: out of memory reading '%s'", path);
                errno = ENOMEM;
                return NULL;
            }
            buf = nb;
            cap = nc;
        }
        errno = 0;
        const ssize_t r = pread(fd, buf + n, SLURP_CHUNK, (off_t)(n + nz));
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0) {
            const int e = errno;
            free(buf);
            gw_err_set(err, GW_EIO, "%s: cannot read: %s", path, strerror(e));
            errno = EIO;
            return NULL;
        }
        if (r == 0)
            break;
        /* a NUL byte: C strings end there, and the rows after it were
         * misread (cut off as a torn row, or the journal refused as edited);
         * NUL bytes alone after the last newline, a power cut's zeroed end,
         * are counted for the caller to cut when it takes them (zeros) */
        size_t got = (size_t)r;
        if (!in_zeros) {
            const char *z = memchr(buf + n, '\0', got);
            if (z) {
                z_line = 1;
                for (const char *q = buf; q < z; q++)
                    z_line += *q == '\n';
                z_at = (size_t)(z - buf) + 1;
                in_zeros = zeros && z > buf && z[-1] == '\n';
                const size_t keep = (size_t)(z - (buf + n)); /* the text before it */
                n += keep, got -= keep;                    /* the rest: at buf + n */
            }
            if (z && !in_zeros)
                return slurp_nul(buf, path, z_line, z_at, zeros != NULL, err);
        }
        if (in_zeros) { /* got bytes at buf + n, after the kept text: zeros all */
            if (memchr_nonzero(buf + n, got))
                return slurp_nul(buf, path, z_line, z_at, 1, err);
            nz += got;
            if (n + nz > max) { /* grown since fstat */
                free(buf);
                gw_err_set(err, GW_EINVAL, "sweep journal '%s' is more than %zu bytes, more than this sweep's "
                           "journal can hold: not its journal; move it away to start the sweep afresh", path, max);
                errno = EINVAL;
                return NULL;
            }
            continue;
        }
        n += (size_t)r;
        if (n > max) { /* grown since fstat */
            free(buf);
            gw_err_set(err, GW_EINVAL, "sweep journal '%s' is more than %zu bytes, more than this sweep's journal "
                       "can hold: not its journal; move it away to start the sweep afresh", path, max);
            errno = EINVAL;
            return NULL;
        }
    }
    buf[n] = '\0';
    *len = n;
    if (zeros)
        *zeros = nz;
    return buf;
}

int gw_sweep_dir_open(const char *dir)
{
    int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
#ifdef O_PATH
    if (fd < 0 && errno == EACCES) /* a directory one may write and search but not list (mode 0300) */
        fd = open(dir, O_PATH | O_DIRECTORY | O_CLOEXEC);
#endif
    return fd;
}

int gw_sweep_dir_held(int dirfd, const char *dir, gw_err *err)
{
    if (!dir)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_dir_held: dir is NULL");
    struct stat st;
    if (fstat(dirfd, &st) != 0)
        return gw_err_set(err, GW_EIO, "%s: the sweep's directory: %s", dir, strerror(errno));
    if (st.st_nlink == 0) /* rmdir drops a directory's last link: a moved one keeps it */
        return gw_err_set(err, GW_EIO, "%s: the sweep's directory was removed while the sweep ran (or moved to "
                          "another file system, which copies it): its journal went with it, no table written; "
                          "rerun to run its cases again (a copy of the journal resumes them)", dir);
    return GW_OK;
}

/* ---- what the sweep wrote: its journal's copy, for checking and keeping ----
 * A journal rewritten in place while the sweep ran (`> DIR/journal.csv`, an
 * editor writing into the file, a tool that cuts it) is the same file: its
 * name and inode checks passed, the sweep appended its rows to the other
 * content (or to nothing) and found the rows lost only at the end. The sweep
 * now keeps what it wrote into its journal (the text read at the open and
 * each row appended since) beside the descriptor, and before each row checks
 * that the file holds it: its size the bytes the sweep wrote (a cut, a
 * rewrite of another length, a line added by another program), and, while
 * its times are those the sweep's own last write left, its last
 * JOURNAL_TAIL bytes; its times changed by anyone else (a rewrite of the same
 * length), the whole file compared. A file found otherwise is another's
 * content: the journal is kept whole from the copy (journal_keep), the file
 * never written again. The copy is the journal's size in memory
 * (gw_sweep_size_check counts it); the check per row is one fstat and one
 * read of JOURNAL_TAIL bytes. Kept by descriptor (the callers' API passes
 * the descriptor alone), with the file's device and inode: a descriptor
 * closed and reused for another file is not taken for the journal.
 *
 * The window between that check and the row's write: a file written into
 * there (an editor's save, `: >`, `echo >>`) had the row appended to it, and
 * the times the sweep recorded after its own write covered the other write
 * too; a rewrite of the same length outside the last JOURNAL_TAIL bytes was
 * then found only by the table's check at the end ("lost rows"), and any
 * other at the next row, the row of this one in the file. The file's events
 * are watched (inotify, on the descriptor's file wherever its name went):
 * the check empties their queue before it reads the file, and after the
 * row's write the queue must hold that write's one IN_MODIFY and nothing
 * else; anything more (another's open, write, close, truncation, attribute
 * change) makes the sweep's recorded times unknown, so the check that
 * follows (gw_sweep_journal_held, which the sweep calls right after each
 * row too) compares the whole file. A writer that opened the file before
 * the check and writes inside the window without closing it adds only an
 * IN_MODIFY, merged with the sweep's by the kernel (a same-length edit
 * outside the last JOURNAL_TAIL bytes was found only at the end): after the
 * row's write the sweep asks whether any other open file holds the journal
 * (a write lease, taken and given back at once, is refused while one does:
 * others_open), before it reads the queue, so such a writer either still
 * holds it (the whole file compared) or closed it (its IN_CLOSE_WRITE in the
 * queue). Events found in the queue at the check before a row (another's,
 * since the sweep read it after its last write) compare the whole file too:
 * a write in the same clock tick as the sweep's leaves the times as they
 * were; opens alone do not (an open changes no byte: shadow_events). Without inotify (its limits reached), the check is as before; where
 * a lease cannot be taken (another user's journal, a file system without
 * leases), by the events alone. */
#define JOURNAL_TAIL 4096
#define NSHADOWS 16
#define JOURNAL_EVENTS (IN_MODIFY | IN_ATTRIB | IN_OPEN | IN_CLOSE_WRITE | IN_MOVE_SELF | IN_DELETE_SELF)
typedef struct jshadow {
    int used, fd;
    dev_t dev;
    ino_t ino;
    char *text; /* what the journal should hold */
    size_t len, cap;
    struct timespec mtim, ctim; /* the file's after the sweep's last write (times_ok) */
    int times_ok;
    int ifd; /* inotify descriptor watching the journal's file; -1: none */
    int readers_only; /* the others holding the file found read-only (others_write), no open since */
} jshadow;
static jshadow shadows[NSHADOWS];
static pthread_mutex_t shadows_lock = PTHREAD_MUTEX_INITIALIZER;

static void shadow_free(jshadow *h)
{
    if (h->used && h->ifd >= 0)
        close(h->ifd);
    free(h->text);
    memset(h, 0, sizeof *h);
    h->ifd = -1;
}

/* the journal's file (fd's, wherever its name went) watched for events, on
 * a new queue: h->ifd, or -1 when inotify cannot (its limits) */
static void shadow_watch(jshadow *h, int fd)
{
    if (h->ifd >= 0)
        close(h->ifd);
    h->readers_only = 0;
    char link[64];
    gw_snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    h->ifd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (h->ifd >= 0 && inotify_add_watch(h->ifd, link, JOURNAL_EVENTS) < 0) {
        close(h->ifd);
        h->ifd = -1;
    }
}

/* The events queued on h's watch, read and dropped: -1 without a watch (or a
 * read that failed), else the number of events, in *opens those that are an
 * open alone (IN_OPEN), and in *modify_only 1 when they are exactly one
 * IN_MODIFY (the sweep's own row) besides such opens. An open among them
 * (or a queue that cannot be read) drops h->readers_only: who opened is not
 * known. An open alone changes no byte and no time of the file (a write
 * through the opened descriptor is an IN_MODIFY of its own, a cut too, a
 * close after writing an IN_CLOSE_WRITE), so it does not make the next
 * check compare the whole file: a viewer that reopens the journal (a `watch
 * cat`, an editor's reload) made one whole compare per open, its bytes read
 * again per reopen (see test_journal_reader). The opener is looked up
 * again (others_write) at the next row while it holds the file; a write
 * through a shared mapping, which sends no event, is found there, as a
 * writer that held the file before. */
static int shadow_events(jshadow *h, int *modify_only, int *opens)
{
    *modify_only = 0;
    *opens = 0;
    h->readers_only = h->readers_only && h->ifd >= 0;
    if (h->ifd < 0)
        return -1;
    int n = 0, mods = 0, open_only = 0;
    _Alignas(struct inotify_event) char buf[4096];
    for (;;) {
        const ssize_t r = read(h->ifd, buf, sizeof buf);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0 && errno == EAGAIN)
            break;
        if (r <= 0) {
            h->readers_only = 0;
            return -1;
        }
        for (ssize_t at = 0; at + (ssize_t)sizeof(struct inotify_event) <= r;) {
            const struct inotify_event *e = (const struct inotify_event *)(buf + at);
            n++;
            if (e->mask & (IN_OPEN | IN_Q_OVERFLOW))
                h->readers_only = 0;
            mods += (e->mask & ~(uint32_t)IN_ISDIR) == IN_MODIFY;
            open_only += (e->mask & ~(uint32_t)IN_ISDIR) == IN_OPEN;
            at += (ssize_t)sizeof *e + e->len;
        }
    }
    *opens = open_only;
    *modify_only = mods == 1 && n - open_only == 1;
    return n;
}

/* 1 when an open file other than fd's holds the journal's file open (a
 * reader's or a writer's, in this process or another), 0 when none does, -1
 * when that cannot be told. Asked with a write lease, which the kernel
 * refuses (EAGAIN) while another open file holds the file, given back at
 * once: an open by another in between waits for the give-back (the break
 * is signalled with SIGURG, ignored by default, instead of SIGIO, whose
 * default ends the process). */
static int others_open(int fd)
{
    if (fcntl(fd, F_SETSIG, SIGURG) != 0)
        return -1;
    if (fcntl(fd, F_SETLEASE, F_WRLCK) != 0)
        return errno == EAGAIN || errno == EBUSY ? 1 : -1;
    (void)fcntl(fd, F_SETLEASE, F_UNLCK);
    return 0;
}

/* 1 when the holder found in /proc/PID/fd/NAME (of the journal's file) may
 * write it: opened for writing, or its flags unreadable */
static int fd_writes(const char *pid, const char *name)
{
    char path[96];
    gw_snprintf(path, sizeof path, "/proc/%s/fdinfo/%s", pid, name);
    FILE *fi = fopen(path, "re");
    if (!fi)
        return 1;
    char line[128];
    unsigned long flags = O_RDWR;
    int got = 0;
    while (!got && fgets(line, sizeof line, fi))
        got = sscanf(line, "flags: %lo", &flags) == 1;
    fclose(fi);
    return !got || (flags & O_ACCMODE) != O_RDONLY;
}

/* 1 when process pid (a /proc entry's name) maps the journal's file shared
 * (a writable mapping, or one mprotect may make writable: no event is sent
 * for writes through it), or its maps cannot be read (EACCES passed over
 * where unknown_ok, as for its descriptors); else 0, with *found counted up
 * for each private mapping */
static int maps_write(const char *pid, dev_t dev, ino_t ino, int unknown_ok, int *found)
{
    char path[64];
    gw_snprintf(path, sizeof path, "/proc/%s/maps", pid);
    FILE *fm = fopen(path, "re");
    if (!fm)
        return errno != ENOENT && (errno != EACCES || !unknown_ok);
    char line[512];
    int w = 0;
    while (!w && fgets(line, sizeof line, fm)) {
        char perms[8];
        unsigned maj, min;
        unsigned long long in;
        if (sscanf(line, "%*x-%*x %7s %*x %x:%x %llu", perms, &maj, &min, &in) == 4 && in == (unsigned long long)ino &&
            maj == major(dev) && min == minor(dev)) {
            w = perms[3] != 'p';
            ++*found;
        }
        if (!strchr(line, '\n')) /* a path longer than the line: the rest skipped */
            for (int c; (c = getc(fm)) != EOF && c != '\n';)
                ;
    }
    fclose(fm);
    return w;
}

/* 1 when an open file other than fd may write the journal's file, 0 when
 * every other holder found reads it only (and one at least was found: the
 * lease said one holds it). A walk of /proc: each process's descriptors to
 * the file (their flags in fdinfo: read-only or not) and its shared
 * mappings. A process whose descriptors cannot be read (another user's)
 * is passed over when the file gives no write permission beyond its owner
 * (it could not have opened it for writing, root aside), else the answer is
 * 1, as when /proc cannot be read. Made once per open of the file the watch
 * sees (gw_sweep_journal_append), not per row: a reader holding the journal
 * made the check after each row compare the whole file (a row's write read
 * the whole journal: 449 MB read over a sweep of 2000 cases).
 * A holder outside the sweep's PID namespace (the sweep in a container, the
 * holder on the host or in another container) is not in this /proc (one in
 * a namespace below the sweep's is listed): the lease still says the file
 * is held, none is found, and the answer is 1, so while it holds the journal
 * each row's check compares the whole file, as for any holder before the
 * walk: 1200 one-bead cases run under `unshare --pid --fork --mount-proc`
 * with a reader outside pread 161 MB, against 10.1 MB with the reader in
 * the sweep's namespace. That is slower, never a miss, and it is not fixed: no
 * kernel call tells another namespace's descriptors' access modes. A lock
 * query (F_GETLK, F_OFD_GETLK, /proc/locks) sees locks alone, which a reader
 * does not take; a read lease, which the kernel refuses while any open file
 * may write the file, is refused for the sweep's own read-write descriptor
 * (and on a read-only one beside it, the sweep's own being open for
 * writing); and a write lease, asked on any descriptor, is refused for any
 * other holder, reader or writer, which is what others_open asks. */
static int others_write(int fd)
{
    struct stat js;
    DIR *p = fstat(fd, &js) == 0 ? opendir("/proc") : NULL;
    if (!p)
        return 1;
    const int others_may_write = (js.st_mode & (S_IWGRP | S_IWOTH)) != 0;
    char self[24];
    gw_snprintf(self, sizeof self, "%ld", (long)getpid());
    int found = 0, w = 0;
    const struct dirent *e;
    while (!w && (e = readdir(p)) != NULL) {
        if (e->d_name[0] < '1' || e->d_name[0] > '9' || strspn(e->d_name, "0123456789") != strlen(e->d_name))
            continue;
        char path[64];
        gw_snprintf(path, sizeof path, "/proc/%s/fd", e->d_name);
        DIR *d = opendir(path);
        if (!d) {
            w = errno != ENOENT && (errno != EACCES || others_may_write);
            continue;
        }
        const struct dirent *f;
        while (!w && (f = readdir(d)) != NULL) {
            struct stat st;
            if (f->d_name[0] == '.' || fstatat(dirfd(d), f->d_name, &st, 0) != 0 || st.st_dev != js.st_dev ||
                st.st_ino != js.st_ino)
                continue;
            if (strcmp(e->d_name, self) == 0 && strtol(f->d_name, NULL, 10) == fd)
                continue; /* the sweep's own */
            found++;
            w = fd_writes(e->d_name, f->d_name);
        }
        closedir(d);
        if (!w)
            w = maps_write(e->d_name, js.st_dev, js.st_ino, !others_may_write, &found);
    }
    closedir(p);
    return w || found == 0;
}

/* the file's times as the sweep left them, when its size is len (else
 * unknown: the next check compares it whole) */
static void shadow_times(jshadow *h, int fd)
{
    struct stat st;
    h->times_ok = fstat(fd, &st) == 0 && (unsigned long long)st.st_size == (unsigned long long)h->len;
    if (h->times_ok)
        h->mtim = st.st_mtim, h->ctim = st.st_ctim;
}

/* the copy of fd's journal, NULL when there is none (a descriptor the sweep
 * did not open through gw_sweep_journal_open_at, or closed and reused for
 * another file: that entry dropped). Entries do not move: the caller uses
 * it without the lock (one thread at a time per journal: the caller's). */
static jshadow *shadow_get(int fd)
{
    struct stat st;
    jshadow *r = NULL;
    const int known = fd >= 0 && fstat(fd, &st) == 0;
    pthread_mutex_lock(&shadows_lock);
    for (int i = 0; i < NSHADOWS && !r; i++)
        if (shadows[i].used && shadows[i].fd == fd) {
            if (known && shadows[i].dev == st.st_dev && shadows[i].ino == st.st_ino)
                r = &shadows[i];
            else
                shadow_free(&shadows[i]);
        }
    pthread_mutex_unlock(&shadows_lock);
    return r;
}

/* text (len bytes, taken over) recorded as what the journal fd holds;
 * without a free entry (16 journals open in one process) it is not kept, and
 * that journal is checked by its name alone, as before */
static void shadow_set(int fd, char *text, size_t len)
{
    struct stat st;
    jshadow *h = NULL;
    if (fstat(fd, &st) != 0) {
        free(text);
        return;
    }
    pthread_mutex_lock(&shadows_lock);
    for (int i = 0; i < NSHADOWS; i++)
        if (shadows[i].used && shadows[i].fd == fd)
            shadow_free(&shadows[i]);
    for (int i = 0; i < NSHADOWS && !h; i++)
        if (!shadows[i].used)
            h = &shadows[i];
    if (h) {
        *h = (jshadow){.used = 1, .fd = fd, .dev = st.st_dev, .ino = st.st_ino, .text = text, .len = len, .cap = len,
                       .ifd = -1};
        shadow_watch(h, fd);
        shadow_times(h, fd);
    } else {
        free(text);
    }
    pthread_mutex_unlock(&shadows_lock);
}

/* the copy of *fd's journal now that of nfd (a journal put back or kept) */
static void shadow_move(jshadow *h, int nfd)
{
    struct stat st;
    pthread_mutex_lock(&shadows_lock);
    for (int i = 0; i < NSHADOWS; i++)
        if (shadows[i].used && shadows[i].fd == nfd && &shadows[i] != h)
            shadow_free(&shadows[i]);
    if (fstat(nfd, &st) == 0) {
        h->fd = nfd, h->dev = st.st_dev, h->ino = st.st_ino;
        shadow_watch(h, nfd);
        shadow_times(h, nfd);
    } else {
        shadow_free(h);
    }
    pthread_mutex_unlock(&shadows_lock);
}

static void shadow_drop(jshadow *h)
{
    pthread_mutex_lock(&shadows_lock);
    shadow_free(h);
    pthread_mutex_unlock(&shadows_lock);
}

void gw_sweep_journal_close(int fd)
{
    if (fd < 0)
        return;
    /* by descriptor alone: the file may be gone from its name, or be another
     * file's under it; the entry is this descriptor's whatever it holds */
    pthread_mutex_lock(&shadows_lock);
    for (int i = 0; i < NSHADOWS; i++)
        if (shadows[i].used && shadows[i].fd == fd)
            shadow_free(&shadows[i]);
    pthread_mutex_unlock(&shadows_lock);
    close(fd);
}

static int ts_same(struct timespec a, struct timespec b)
{
    return a.tv_sec == b.tv_sec && a.tv_nsec == b.tv_nsec;
}

/* 1 when the journal fd no longer holds what the sweep wrote (h), its size
 * in *size; 0 when it does; -1 when that cannot be told (fstat failed) */
static int shadow_differs(jshadow *h, int fd, long long *size)
{
    struct stat st;
    int one, opens;
    /* the events so far, read and dropped: the sweep's own row's were read
     * after its write (gw_sweep_journal_append), so any here are another's,
     * and the whole file is read below (a write in the clock tick of the
     * sweep's left the times as they were); opens alone change nothing
     * (shadow_events) and leave the check at the tail */
    const int nev = shadow_events(h, &one, &opens);
    if (nev != 0 && h->ifd >= 0 && nev != opens)
        h->times_ok = 0; /* the queue unreadable, or another's events since the sweep's write: compared whole */
    if (fstat(fd, &st) != 0)
        return -1;
    *size = (long long)st.st_size;
    if ((unsigned long long)st.st_size != (unsigned long long)h->len)
        return 1;
    const int same_times = h->times_ok && ts_same(st.st_mtim, h->mtim) && ts_same(st.st_ctim, h->ctim);
    size_t pos = same_times && h->len > JOURNAL_TAIL ? h->len - JOURNAL_TAIL : 0;
    char buf[JOURNAL_TAIL];
    while (pos < h->len) {
        const size_t want = h->len - pos < sizeof buf ? h->len - pos : sizeof buf;
        const ssize_t r = pread(fd, buf, want, (off_t)pos);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0 || memcmp(buf, h->text + pos, (size_t)r) != 0)
            return 1; /* cut meanwhile, or other bytes */
        pos += (size_t)r;
    }
    if (!same_times) /* touched, or written with the same bytes: the sweep's still */
        shadow_times(h, fd);
    return 0;
}

/* n bytes of buf written to fd whole: 0, or -1 with errno set. A short
 * write (a disk that fills inside a row: write() returns the bytes it took,
 * errno untouched) is continued, so that the write that fails says why: the
 * sweep said "write failed: Success" on a full disk, leaving a torn row. */
static int write_all(int fd, const char *buf, size_t n)
{
    size_t off = 0;
    while (off < n) {
        const ssize_t w = write(fd, buf + off, n - off);
        if (w < 0 && errno == EINTR)
            continue;
        if (w < 0)
            return -1;
        if (w == 0) { /* nothing taken and no error: no room */
            errno = ENOSPC;
            return -1;
        }
        off += (size_t)w;
    }
    return 0;
}

/* A new journal, whole (its head and input lines) or not at all, and never
 * over one another sweep made meanwhile: written under a temporary name and
 * linked into place, which fails when the name exists. The atomic write
 * before renamed over it: two sweeps started at once into one directory each
 * made a journal, the second replaced the first's, and the first appended its
 * rows to a file no longer in the directory and wrote its table from the
 * other sweep's rows (exit 0 for both). path names the journal for messages
 * (DIR/journal.csv); name is the file's name in dfd (journal.csv, or the
 * name a journal replaced mid-sweep is kept under). *fdp -1 and GW_OK when
 * the name was taken. */
static int journal_create_as(int dfd, const char *path, const char *name, const char *text, int *fdp, gw_err *err)
{
    char tmp[4200];
    *fdp = -1;
    const size_t rel = strlen(path) - strlen("journal.csv"); /* tmp + rel: its name in dfd */
    int fd = -1, e = EEXIST;
    long seq = (long)(gw_clock_ms() * 1e3) % 1000000; /* a unique name, as mkstemp's, made in dfd */
    for (int tries = 0; fd < 0 && e == EEXIST && tries < 1000; tries++, seq = (seq + 7919) % 1000000) {
        if (gw_snprintf(tmp, sizeof tmp, "%s.new.%ld.%06ld", path, (long)getpid(), seq) >= (int)sizeof tmp)
            return gw_err_set(err, GW_EINVAL, "%s: path too long", path);
        fd = openat(dfd, tmp + rel, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        e = fd < 0 ? errno : 0;
    }
    if (fd < 0)
        return gw_err_set(err, GW_EIO, "%s: cannot create: %s", path, strerror(e));
    /* a signal now removes it (the program's handler, gw_io_temps.c), by its
     * name in dfd: in the sweep's directory wherever that was moved */
    gw_temps_add_at(tmp, dfd);
    fchmod(fd, gw_new_file_mode(path));
    /* locked before it has its name: another sweep that finds it finds it
     * locked (a sweep that locked it first would refuse it as another
     * config's, and this one then find it locked: neither ran) */
    const size_t n = strlen(text);
    int bad = flock(fd, LOCK_EX) != 0 || write_all(fd, text, n) != 0 || fsync(fd) != 0 ||
              fcntl(fd, F_SETFL, O_APPEND) != 0;
    e = errno;
    int placed = 0;
    if (!bad && linkat(dfd, tmp + rel, dfd, name, 0) == 0) {
        placed = 1;
    } else if (!bad && errno != EEXIST) {
        /* a file system without hard links: by rename, as before, only
         * while the name is free (a journal kept aside never replaces a file) */
        struct stat st;
        if (fstatat(dfd, name, &st, AT_SYMLINK_NOFOLLOW) != 0 && errno == ENOENT) {
            placed = renameat(dfd, tmp + rel, dfd, name) == 0;
            bad = !placed;
            e = errno;
        }
    }
    unlinkat(dfd, tmp + rel, 0);
    gw_temps_drop(tmp);
    if (placed) {
        *fdp = fd;
        return GW_OK;
    }
    close(fd); /* another sweep made it meanwhile (EEXIST), or a failure */
    return bad ? gw_err_set(err, GW_EIO, "%s: cannot create: %s", path, strerror(e ? e : EIO)) : GW_OK;
}

static int journal_create(int dfd, const char *path, const char *text, int *fdp, gw_err *err)
{
    return journal_create_as(dfd, path, "journal.csv", text, fdp, err);
}

/* The sweep's journal (held open in *fdp) kept whole under a free name in
 * dirfd, DIR/journal.kept.csv (journal.kept.2.csv, ... when taken), made as
 * a journal is (locked, linked into place, never over a file), *fdp then
 * the kept file's (*kept 1): its name (journal.csv) holds another file now
 * (written 0), or the journal's own file holds another content (written 1:
 * rewritten in place, cut or added to; *size its bytes now), either left as
 * it is. What is kept is what the sweep wrote (its copy h), or, without one,
 * what the file held open holds. GW_EIO with the message the caller says. */
static int journal_keep(int dirfd, int *fdp, const char *dir, const char *path, jshadow *h, int written,
                        long long size, int *kept, gw_err *err)
{
    size_t len = 0;
    char *text = h ? h->text : gw_sweep_slurp_fd(*fdp, path, GW_SWEEP_JOURNAL_MAX, &len, err);
    if (!text)
        return errno == ENOMEM ? GW_ENOMEM : GW_EIO;
    if (h)
        len = h->len;
    char name[64];
    int nfd = -1, rc = GW_OK;
    /* journal_create_as writes a text up to its NUL */
    char *z = h ? malloc(len + 1) : text;
    if (!z)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory keeping the sweep's journal", path);
    if (h) {
        memcpy(z, text, len);
        z[len] = '\0';
    }
    for (int i = 1; i <= 1000 && nfd < 0 && rc == GW_OK; i++) {
        if (i == 1)
            gw_snprintf(name, sizeof name, "journal.kept.csv");
        else
            gw_snprintf(name, sizeof name, "journal.kept.%d.csv", i);
        rc = journal_create_as(dirfd, path, name, z, &nfd, err);
    }
    free(z);
    char what[200];
    if (written)
        gw_snprintf(what, sizeof what, "was written into while the sweep ran (rewritten in place, cut or added to: "
                    "it holds %lld bytes%s where the sweep wrote %zu)", size,
                    size == (long long)len ? " of other content" : "", len);
    else
        gw_snprintf(what, sizeof what, "was replaced by another file while the sweep ran");
    if (rc == GW_OK && nfd < 0)
        rc = gw_err_set(err, GW_EIO, "%s: cannot keep this sweep's journal: %s/journal.kept.csv to "
                        "journal.kept.1000.csv are all taken", path, dir);
    if (rc != GW_OK) {
        char why[sizeof err->msg];
        gw_snprintf(why, sizeof why, "%s", err ? err->msg : "a failure");
        return gw_err_set(err, rc == GW_ENOMEM ? GW_ENOMEM : GW_EIO, "%s %s, and this sweep's journal could not "
                          "be kept beside it (%s): its rows since are lost, the %s is left as it is", path, what,
                          why, written ? "file" : "other file");
    }
    close(*fdp);
    *fdp = nfd;
    if (h)
        shadow_move(h, nfd);
    *kept = 1;
    if (written)
        return gw_err_set(err, GW_EIO, "%s %s: this sweep's journal is kept whole as %s/%s, the file left as it "
                          "is", path, what, dir, name);
    return gw_err_set(err, GW_EIO, "%s %s (an editor saving through a rename?): this sweep's journal is kept "
                      "whole as %s/%s, the other file left as it is", path, what, dir, name);
}

static int journal_check(const char *path, int dfd, const char *dir, const char *head, const gw_sweep_config *cfg,
                         char *done, long *ndone, int fd, size_t *torn, int *torn_head, gw_err *err);

/* The journal removed from the sweep's directory while the sweep ran (`rm
 * DIR/journal.csv`): the sweep went on appending its rows to a file in no
 * directory, ran every case left and then exited 1 ("cannot read: No such
 * file or directory"), its rows lost with the file. It is put back now, at
 * the next row, whole (its head and every row so far, read through the
 * held descriptor), by journal_create: locked, linked into place only while
 * the name is free; moved away within the directory alike.
 * A journal replaced by another file (an editor saving through a rename, a
 * copy moved over it) was found only by the table's check at the end, the
 * cases after the swap run for nothing, their rows in a file in no directory
 * or under the name the editor gave the old one: now it is kept whole under a
 * new name (journal_keep) at once, the other file left as it is, and the
 * caller told (*restored 2, GW_EIO) to stop. The journal's own file written
 * into (found by its copy, jshadow above) is kept alike, from the copy. */
int gw_sweep_journal_held(int dirfd, int *fdp, const char *dir, int *restored, gw_err *err)
{
    if (restored)
        *restored = 0;
    if (!fdp || !dir)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_journal_held: %s is NULL", !fdp ? "fd" : "dir");
    struct stat a, b;
    if (fstat(*fdp, &a) != 0)
        return gw_err_set(err, GW_EIO, "%s/journal.csv: %s", dir, strerror(errno));
    char path[4200];
    if (gw_io_path_join(path, sizeof path, dir, "journal.csv", "sweep directory", err) != GW_OK)
        return GW_EINVAL;
    /* what the sweep wrote into it (none: a descriptor not opened by
     * gw_sweep_journal_open_at, checked by its name alone) */
    jshadow *h = shadow_get(*fdp);
    /* its name, followed as the sweep opened it (a symbolic link to the
     * journal is the journal), and the file holding what the sweep wrote */
    if (fstatat(dirfd, "journal.csv", &b, 0) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino) {
        long long size = 0;
        if (!h || shadow_differs(h, *fdp, &size) != 1)
            return GW_OK;
        if (gw_sweep_dir_held(dirfd, dir, err) != GW_OK)
            return GW_EIO;
        int kept = 0;
        const int rc = journal_keep(dirfd, fdp, dir, path, h, 1, size, &kept, err);
        if (kept && restored)
            *restored = 2;
        return rc;
    }
    if (gw_sweep_dir_held(dirfd, dir, err) != GW_OK) /* the directory removed, the journal with it */
        return GW_EIO;
    int named = fstatat(dirfd, "journal.csv", &b, AT_SYMLINK_NOFOLLOW) == 0;
    if (!named && errno != ENOENT)
        return GW_OK; /* cannot be told (the directory not searchable now): left to the table's check */
    /* A free name may be an editor's save under way: the journal renamed to
     * a backup (journal.csv~) or removed, the new file written next. Put back
     * at once, the journal took the name first and the editor then wrote its
     * text into the sweep's file, over the rows since it read it. The name is
     * watched a moment (GW_SWEEP_GRACE_MS, once per such event): a file that
     * comes is a replacement, kept apart from. */
    for (double t0 = gw_clock_ms(); !named && gw_clock_ms() - t0 < GW_SWEEP_GRACE_MS;) {
        nanosleep(&(struct timespec){.tv_sec = 0, .tv_nsec = 2000000L}, NULL);
        named = fstatat(dirfd, "journal.csv", &b, AT_SYMLINK_NOFOLLOW) == 0;
    }
    if (named && fstatat(dirfd, "journal.csv", &b, 0) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino)
        return GW_OK; /* moved back meanwhile */
    if (!named) { /* removed, or moved away: put back, with what the sweep wrote */
        size_t len = 0;
        char *text = NULL;
        if (h && (text = malloc(h->len + 1)) != NULL) {
            memcpy(text, h->text, h->len);
            text[len = h->len] = '\0';
        } else if (h) {
            return gw_err_set(err, GW_ENOMEM, "%s: out of memory putting the journal back", path);
        } else if (!(text = gw_sweep_slurp_fd(*fdp, path, GW_SWEEP_JOURNAL_MAX, &len, err))) {
            return errno == ENOMEM ? GW_ENOMEM : GW_EIO;
        }
        if (len == 0 || text[len - 1] != '\n') {
            free(text);
            return GW_OK; /* a torn last row: left to the table's check */
        }
        int nfd = -1;
        const int rc = journal_create(dirfd, path, text, &nfd, err);
        free(text);
        if (rc != GW_OK)
            return rc;
        if (nfd >= 0) {
            close(*fdp);
            *fdp = nfd;
            /* the new file checked as the old one was: one written into
             * later (an editor's save that deleted the journal and wrote its
             * text more than GW_SWEEP_GRACE_MS after) is found at the next
             * row, not appended to */
            if (h)
                shadow_move(h, nfd);
            if (restored)
                *restored = 1;
            return GW_OK;
        }
        /* the name taken meanwhile: another file's */
    }
    int kept = 0;
    const int rc = journal_keep(dirfd, fdp, dir, path, h, 0, 0, &kept, err);
    if (kept && restored)
        *restored = 2;
    return rc;
}

static int journal_find(const char *path, int dfd, const char *dir, const gw_sweep_config *cfg, char *done,
                        long *ndone, int *fdp, int *exists, size_t *torn, int *torn_head, gw_err *err);

int gw_sweep_journal_scan(const char *dir, const gw_sweep_config *cfg, char *done, long *ndone, gw_err *err)
{
    int fd = -1;
    int rc = gw_sweep_journal_open(dir, cfg, done, ndone, &fd, err);
    if (fd >= 0)
        close(fd);
    return rc;
}

/* The journal of a sweep in dir as a resume takes it (fdp, torn NULL: made
 * when absent, its torn last row cut, kept open and locked in *fdp), or as
 * `sweep --check` reads it (torn set: nothing made or cut, *torn the bytes a
 * resume would cut, *torn_head 1 when they are a line of the head, *exists 0
 * when there is none; read under a shared lock and closed). One path for
 * both: the same checks, the same refusals. The directory is opened once and
 * the journal found, made and read through it (kept in *dirfdp when given):
 * a directory moved meanwhile is the sweep's still. */
static int journal_access(const char *dir, const gw_sweep_config *cfg, char *done, long *ndone, int *fdp,
                          int *dirfdp, int *exists, size_t *torn, int *torn_head, gw_err *err)
{
    if (dirfdp)
        *dirfdp = -1;
    if (!dir || !cfg || !done || !ndone) {
        if (ndone)
            *ndone = 0;
        if (fdp)
            *fdp = -1;
        return gw_err_set(err, GW_EINVAL, "sweep journal: %s is NULL", !dir ? "dir" : !cfg ? "cfg" : !done ? "done" : "ndone");
    }
    char path[4096];
    int fd = -1;
    *ndone = 0;
    if (fdp)
        *fdp = -1;
    /* a config filled by hand (33 grid keys, inputs counted without their
     * array) was read past its struct or through NULL (SIGSEGV) by the
     * journal's scan, open and resume check before session 34 */
    const int shape = gw_sweep_config_check(cfg, err);
    if (shape != GW_OK)
        return shape;
    if (fdp)
        *fdp = -1;
    if (exists)
        *exists = 1;
    const int jrc = gw_io_path_join(path, sizeof path, dir, "journal.csv", "sweep directory", err);
    if (jrc != GW_OK)
        return jrc;
    const int dfd = gw_sweep_dir_open(dir);
    if (dfd < 0 && torn && errno == ENOENT) { /* a check before the first run: nothing in it */
        *exists = 0;
        *torn = 0;
        return GW_OK;
    }
    if (dfd < 0)
        return gw_err_set(err, GW_EIO, "%s: cannot open the sweep's directory: %s", dir, strerror(errno));
    int rc = journal_find(path, dfd, dir, cfg, done, ndone, &fd, exists, torn, torn_head, err);
    if ((rc != GW_OK || !fdp) && fd >= 0) {
        close(fd);
        fd = -1;
    }
    if (fdp)
        *fdp = fd;
    if (rc == GW_OK && dirfdp && fd >= 0) {
        /* a sweep's: what its journal holds kept, checked before each row */
        size_t len = 0;
        char *text = gw_sweep_slurp_fd(fd, path, gw_sweep_journal_bound(cfg), &len, err);
        if (!text) {
            close(fd);
            close(dfd);
            *fdp = -1;
            return errno == ENOMEM ? GW_ENOMEM : GW_EIO;
        }
        shadow_set(fd, text, len);
        *dirfdp = dfd;
    } else {
        close(dfd);
    }
    return rc;
}

/* journal_access in the directory dfd, open */
static int journal_find(const char *path, int dfd, const char *dir, const gw_sweep_config *cfg, char *done,
                        long *ndone, int *fdp, int *exists, size_t *torn, int *torn_head, gw_err *err)
{
    struct stat st;
    int fd = -1;
    /* the table goes beside the journal once every case has run: a directory
     * or a FIFO of its name failed the sweep (exit 1) after all its cases */
    char tpath[4096];
    if (gw_io_path_join(tpath, sizeof tpath, dir, "results.csv", "sweep directory", err) != GW_OK)
        return GW_EINVAL;
    if (gw_out_file_check(tpath, "sweep table", err) != GW_OK)
        return GW_EINVAL;
    if (gw_sweep_out_inputs_check(dir, cfg, err) != GW_OK)
        return GW_EINVAL;
    char head[96];
    gw_snprintf(head, sizeof head, GW_SWEEP_JOURNAL_HEAD "\n", cfg->hash);
    const int absent = fstatat(dfd, "journal.csv", &st, 0) != 0 && errno == ENOENT;
    if (torn && absent) { /* a run would start it: nothing done */
        *exists = 0;
        *torn = 0;
        return GW_OK;
    }
    if (absent) {
        /* a new journal: the config, the build that computes its rows, and
         * what its files held */
        char *in = gw_sweep_head_lines(cfg);
        char bline[GW_SWEEP_BUILD_MAX + 16];
        gw_snprintf(bline, sizeof bline, "# build %s\n", gw_sweep_build());
        size_t hl = strlen(head), bl = strlen(bline), il = in ? strlen(in) : 0;
        char *text = in ? malloc(hl + bl + il + 1) : NULL;
        if (!text) {
            free(in);
            return gw_err_set(err, GW_ENOMEM, "%s: out of memory", path);
        }
        memcpy(text, head, hl);
        memcpy(text + hl, bline, bl);
        memcpy(text + hl + bl, in, il + 1);
        int rc = journal_create(dfd, path, text, &fd, err);
        free(text);
        free(in);
        if (rc != GW_OK)
            return rc;
    }
    /* One sweep at a time in a directory: the journal is locked from here
     * until the sweep ends (the lock goes with the process, kill -9 too).
     * Two sweeps of one config at once each ran every case and journaled it
     * twice; a second sweep's scan could cut a row the first was appending
     * as a torn one. What is read, checked and cut below is read under it.
     * A check opens it as a resume would (for appending: a journal a resume
     * cannot append to is refused alike), writes nothing, and shares its lock
     * with other checks. */
    if (fd < 0 && fstatat(dfd, "journal.csv", &st, 0) == 0 && S_ISREG(st.st_mode)) {
        fd = openat(dfd, "journal.csv", O_RDWR | O_APPEND | O_CLOEXEC | O_NONBLOCK);
        if (fd < 0)
            return gw_err_set(err, GW_EIO, "%s: cannot open for appending: %s", path, strerror(errno));
        if (flock(fd, (torn ? LOCK_SH : LOCK_EX) | LOCK_NB) != 0) {
            const int e = errno;
            close(fd);
            if (e == EWOULDBLOCK)
                return gw_err_set(err, GW_EINVAL, "%s: another sweep is running in this directory (its journal.csv "
                                  "is locked by that process): wait for it to end, or choose another output", dir);
            return gw_err_set(err, GW_EIO, "%s: cannot lock: %s", path, strerror(e));
        }
    }
    *fdp = fd;
    return journal_check(path, dfd, dir, head, cfg, done, ndone, fd, torn, torn_head, err);
}

int gw_sweep_journal_open(const char *dir, const gw_sweep_config *cfg, char *done, long *ndone, int *fdp,
                          gw_err *err)
{
    return journal_access(dir, cfg, done, ndone, fdp, NULL, NULL, NULL, NULL, err);
}

int gw_sweep_journal_open_at(const char *dir, const gw_sweep_config *cfg, char *done, long *ndone, int *fdp,
                             int *dirfdp, gw_err *err)
{
    if (!fdp || !dirfdp) {
        if (dirfdp)
            *dirfdp = -1;
        if (fdp)
            *fdp = -1;
        return gw_err_set(err, GW_EINVAL, "gw_sweep_journal_open_at: %s is NULL", !fdp ? "fd" : "dirfd");
    }
    return journal_access(dir, cfg, done, ndone, fdp, dirfdp, NULL, NULL, NULL, err);
}

int gw_sweep_journal_resume_check(const char *dir, const gw_sweep_config *cfg, char *done, long *ndone, int *exists,
                                  size_t *torn, int *torn_head, gw_err *err)
{
    int e = 0, h = 0;
    size_t t = 0;
    int rc = journal_access(dir, cfg, done, ndone, NULL, NULL, &e, &t, &h, err);
    if (exists)
        *exists = e;
    if (torn)
        *torn = t;
    if (torn_head)
        *torn_head = h;
    return rc;
}

/* The fields of build line a (al bytes) that differ from b's (bl bytes; fields: the
 * text between ", "), the version and the commit always, into out: the part
 * of two builds' names a message needs. */
static void build_diff(const char *a, size_t al, const char *b, size_t bl, char *out, size_t n)
{
    size_t w = 0;
    out[0] = '\0';
    const char *pa = a, *ea = a + al, *pb = b, *eb = b + bl;
    for (int i = 0; pa < ea || pb < eb; i++) {
        const char *na = pa, *nb = pb;
        while (na < ea && !(na + 1 < ea && na[0] == ',' && na[1] == ' '))
            na++;
        while (nb < eb && !(nb + 1 < eb && nb[0] == ',' && nb[1] == ' '))
            nb++;
        const int same = na - pa == nb - pb && memcmp(pa, pb, (size_t)(na - pa)) == 0;
        if ((i < 2 || !same) && pa < ea && w + 2 < n)
            w += (size_t)gw_snprintf(out + w, n - w, "%s%.*s", w ? ", " : "", (int)(na - pa), pa);
        if (w >= n)
            w = n - 1;
        pa = na < ea ? na + 2 : ea;
        pb = nb < eb ? nb + 2 : eb;
    }
}

/* The journal's second line, "# build ..." (from *pos, after its first):
 * this build's, *pos then past it; else GW_EINVAL naming the journal and
 * both builds (what differs between them). A journal resumes under the
 * build that started it only: its rows are checked for their form, byte for
 * byte, but another build may hold other numbers in that form, and the table
 * would mix the two. */
static int build_check(const char *path, const char *buf, size_t len, size_t *pos, gw_err *err)
{
    static const char pre[] = "# build ";
    const size_t pl = sizeof pre - 1;
    const char *line = buf + *pos, *nl = memchr(line, '\n', len - *pos);
    if (!nl || (size_t)(nl - line) < pl || memcmp(line, pre, pl) != 0)
        return gw_err_set(err, GW_EINVAL, "%s:2: not the '# build' line a journal of format %d has there (the build "
                          "that computed its rows): the journal was edited or cut; remove it to rerun its cases, "
                          "or choose another output", path, GW_SWEEP_JOURNAL_FORMAT);
    const char *mine = gw_sweep_build(), *theirs = line + pl;
    const size_t tl = (size_t)(nl - theirs);
    if (tl == strlen(mine) && memcmp(theirs, mine, tl) == 0) {
        *pos = (size_t)(nl - buf) + 1;
        return GW_OK;
    }
    char was[200], now[200];
    build_diff(theirs, tl, mine, strlen(mine), was, sizeof was);
    build_diff(mine, strlen(mine), theirs, tl, now, sizeof now);
    return gw_err_set(err, GW_EINVAL, "%s: a journal of another granwave build (its rows: %s; this one: %s): finish "
                      "the sweep with the build that started it, or remove the journal to rerun its cases (rows of "
                      "two builds are not mixed: the same form may hold other numbers)", path, was, now);
}

/* The journal's "# grid" and "# param" lines, buf[at, end), against those
 * its config writes (gw_sweep_head_lines): the journal's first line holds the
 * config's hash, so a journal of this config holds these very lines, and a
 * line that differs was edited by hand ("# param t-max = 2e-4" under a hash
 * of 1e-4: the rows ran at 1e-4, the head said 2e-4, and it was resumed and
 * checked as it was). Fewer lines pass: a torn head is cut (below) and its
 * sweep resumed, its rows after the lines it kept. */
static int head_keys_check(const gw_sweep_config *cfg, const char *buf, size_t at, size_t end, const char *path,
                           gw_err *err)
{
    char *want = gw_sweep_head_lines(cfg);
    if (!want)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", path);
    const char *w = want;
    while (strncmp(w, "# input ", 8) == 0) /* the input lines: checked before, by their files */
        w = strchr(w, '\n') + 1;
    long line = 1;
    for (size_t q = 0; q < at; q++)
        line += buf[q] == '\n';
    int rc = GW_OK;
    for (size_t p = at; p < end && rc == GW_OK; line++) {
        const char *nl = memchr(buf + p, '\n', end - p);
        const size_t l = (size_t)(nl - (buf + p)), wl = *w ? strcspn(w, "\n") : 0;
        if (!*w || wl != l || memcmp(w, buf + p, l) != 0) {
            char was[128];
            if (*w)
                gw_snprintf(was, sizeof was, "'%.*s%s'", (int)(wl < 100 ? wl : 100), w, wl > 100 ? "..." : "");
            else
                gw_snprintf(was, sizeof was, "none: its keys end before");
            rc = gw_err_set(err, GW_EINVAL, "%s:%ld: '%.*s%s' is not the line this sweep's config writes there "
                            "(%s), and the journal's first line holds that config's hash: the journal was edited by "
                            "hand; put the line back as the config gives it, or choose another output", path, line,
                            (int)(l < 100 ? l : 100), buf + p, l > 100 ? "..." : "", was);
        }
        p += l + 1;
        w += *w ? wl + 1 : 0;
    }
    free(want);
    return rc;
}

/* The journal at path, read (under the caller's lock on fd) and checked;
 * a torn last line cut (torn NULL) or its bytes counted in *torn, *torn_head
 * 1 when it is a line of the head (# input, # grid, # param), not a row. */
static int journal_check(const char *path, int dfd, const char *dir, const char *head, const gw_sweep_config *cfg,
                         char *done, long *ndone, int fd, size_t *torn, int *torn_head, gw_err *err)
{
    size_t len = 0, zeros = 0;
    /* through the journal opened (fd), or what is there instead named; its
     * zeroed end (NUL bytes alone after its last newline: a power cut's, which
     * ext4's delayed allocation leaves) taken and cut as a torn row is (it was
     * refused as binary data, the journal to be moved away by hand) */
    const size_t max = gw_sweep_journal_bound(cfg);
    char *buf = fd >= 0 ? gw_sweep_slurp_fd_zeros(fd, path, max, &len, &zeros, err)
                        : gw_sweep_slurp(path, max, &len, err);
    if (!buf) /* a FIFO, a directory, gone: named in err; or out of memory */
        return errno == ENOMEM ? GW_ENOMEM : GW_EINVAL;
    struct stat a, b;
    if (fd < 0 || fstat(fd, &a) != 0 || fstatat(dfd, "journal.csv", &b, 0) != 0 || a.st_dev != b.st_dev ||
        a.st_ino != b.st_ino) {
        free(buf);
        return gw_err_set(err, GW_EIO, "%s: replaced while the sweep opened it: rerun", path);
    }
    /* The format before the one read here (GW_SWEEP_JOURNAL_FORMAT), before
     * rows carried their case config hash and the hash of the file they read:
     * "# granwave sweep journal HASH" alone. Its rows cannot be told from rows
     * pasted from a sweep with other [params]. A later format, or a head no
     * granwave writes, is said as such: both were refused as "another sweep
     * (different config)", a journal of this very config included, naming
     * neither the file nor its format. */
    long fmt = 0;
    unsigned long jhash = 0;
    const int head_kind = gw_sweep_head_format(buf, len, &fmt, &jhash);
    if (head_kind == 1 && fmt < GW_SWEEP_JOURNAL_FORMAT) {
        /* format 2 rows record their config, not the build that computed
         * them: every build that wrote one is an earlier granwave's */
        char other[96] = "";
        if (jhash != cfg->hash)
            gw_snprintf(other, sizeof other, ", of another config (%016lx; this one is %016lx)", jhash, cfg->hash);
        free(buf);
        return gw_err_set(err, GW_EINVAL, "%s: a journal of an earlier granwave, whose rows do not record %s "
                          "(format %ld%s; granwave %s reads format %d only, as %s): finish the sweep with the "
                          "granwave that started it, or remove the journal to rerun its cases", path,
                          fmt == 1 ? "the config they ran under" : "the build that computed them", fmt, other,
                          gw_version(), GW_SWEEP_JOURNAL_FORMAT,
                          fmt == 1 ? "a row pasted from another sweep could not be told in format 1"
                                   : "rows of another build may hold other numbers in the same form");
    }
    if (head_kind == 1 && fmt > GW_SWEEP_JOURNAL_FORMAT) {
        free(buf);
        return gw_err_set(err, GW_EINVAL, "%s: a sweep journal of format %ld, newer than granwave %s's "
                          "format %d: resume it with the granwave that wrote it, or choose another output (the "
                          "journal is left as it is)", path, fmt, gw_version(), GW_SWEEP_JOURNAL_FORMAT);
    }
    if (head_kind == 2) {
        char first[128];
        gw_sweep_head_first_line(buf, len, first, sizeof first);
        const char *nl = memchr(buf, '\n', len);
        /* a journal whose line ends a program converted: no row's checksum
         * (over the row and its LF) holds either */
        const int crlf = nl && nl > buf && nl[-1] == '\r';
        free(buf);
        return gw_err_set(err, GW_EINVAL, "%s: a sweep journal of a format granwave %s does not know (its first line "
                          "'%s'%s; this granwave writes and reads format %d): remove it or choose another output (the "
                          "journal is left as it is)", path, gw_version(), first,
                          crlf ? ", its lines ending in CR LF where a sweep writes LF" : "", GW_SWEEP_JOURNAL_FORMAT);
    }
    if (strncmp(buf, "# granwave sweep journal ", 25) != 0 || strncmp(buf, head, strlen(head)) != 0) {
        int rc = strncmp(buf, "# granwave sweep journal ", 25) == 0 ? gw_sweep_head_changed_input(cfg, buf, len, path, dir, err)
                                                                      : GW_OK;
        const int ours = strncmp(buf, "# granwave sweep journal ", 25) == 0;
        if (rc == GW_OK && ours)
            rc = gw_sweep_head_changed_keys(cfg, buf, len, dir, err);
        free(buf);
        if (rc != GW_OK)
            return rc;
        if (!ours) /* an empty, cut or converted file said "another sweep (different config)" */
            return gw_err_set(err, GW_EINVAL, "%s: not a granwave sweep journal (its first line is not '# granwave "
                              "sweep journal HASH'); remove it or choose another output", path);
        return gw_err_set(err, GW_EINVAL,
                          "%s: this directory holds another sweep (different config); remove it or choose another output",
                          dir);
    }
    size_t good = strlen(head), pos = good;
    int rc = build_check(path, buf, len, &pos, err);
    if (rc != GW_OK) {
        free(buf);
        return rc;
    }
    good = pos;
    long inl = 2;
    while (pos < len && strncmp(buf + pos, "# input ", 8) == 0) { /* the journal's input lines */
        const char *nl = memchr(buf + pos, '\n', len - pos), *at = NULL;
        if (!nl)
            break;
        unsigned long long was;
        if (gw_sweep_head_input_hash(path, ++inl, buf + pos + 8, nl, &at, &was, err) != GW_OK) {
            free(buf);
            return GW_EINVAL;
        }
        pos = good = (size_t)(nl - buf) + 1;
    }
    const size_t keys_at = pos;
    while (pos < len && (strncmp(buf + pos, "# grid ", 7) == 0 || strncmp(buf + pos, "# param ", 8) == 0)) {
        const char *nl = memchr(buf + pos, '\n', len - pos); /* the config's keys (input_lines) */
        if (!nl)
            break;
        pos = good = (size_t)(nl - buf) + 1;
    }
    long line = 1;
    for (size_t q = 0; q < pos; q++)
        line += buf[q] == '\n';
    if (pos > keys_at && (rc = head_keys_check(cfg, buf, keys_at, pos, path, err)) != GW_OK) {
        free(buf);
        return rc;
    }
    /* Rows are appended whole (one write each), so only the last line can be
     * torn (no newline: kill -9, a full disk); it is cut and its case reruns.
     * A complete line that is not a row of this sweep was edited or pasted by
     * hand: the scan stopped there and cut it and every row after it, so the
     * finished cases behind an edited value were dropped and rerun, silently.
     * It is refused now, naming the line, and the journal is left as it is. */
    jrow *rows = NULL;
    long nrows = 0, caprows = 0;
    while (pos < len && rc == GW_OK) {
        const char *nl = memchr(buf + pos, '\n', len - pos);
        size_t l = nl ? (size_t)(nl - (buf + pos)) + 1 : len - pos;
        long k = gw_sweep_line_case(buf + pos, l, cfg->ncases);
        char hmsg[1024];
        const char *why = k < 0 ? gw_sweep_line_fault(buf + pos, l, cfg->ncases) : gw_sweep_row_grid_fault(cfg, k, buf + pos, l);
        if (k >= 0 && !why)
            why = gw_sweep_row_hash_fault(cfg, k, buf + pos, l - 10, 0, hmsg, sizeof hmsg);
        if (k >= 0 && !why)
            why = gw_sweep_row_values_fault(cfg, k, buf + pos, l, hmsg, sizeof hmsg);
        if (k >= 0 && !why) {
            if (nrows == caprows) {
                long nc = caprows ? 2 * caprows : 1024;
                jrow *t = realloc(rows, (size_t)nc * sizeof *t);
                if (!t) {
                    rc = gw_err_set(err, GW_ENOMEM, "%s: out of memory", path);
                    break;
                }
                rows = t, caprows = nc;
            }
            rows[nrows++] = (jrow){k, buf + pos, l - 10, line};
            good = pos + l;
        } else if (!nl) {
            break; /* a torn last row: cut below */
        } else {
            rc = gw_err_set(err, GW_EINVAL, "%s:%ld: %s: the journal was edited by hand (a torn row can only be the "
                            "last line, without its newline); delete that line to rerun its case, or choose another "
                            "output", path, line, why);
        }
        pos += l;
        line++;
    }
    /* A case journaled twice with different numbers (rows pasted from another
     * journal): which is right cannot be told; copies of one row are harmless. */
    if (rc == GW_OK && nrows > 1) {
        qsort(rows, (size_t)nrows, sizeof *rows, jrow_cmp);
        for (long i = 1; i < nrows && rc == GW_OK; i++)
            if (rows[i].k == rows[i - 1].k &&
                (rows[i].len != rows[i - 1].len || memcmp(rows[i].s, rows[i - 1].s, rows[i].len) != 0))
                rc = gw_err_set(err, GW_EINVAL, "%s:%ld: case %ld is journaled twice with different results (lines "
                                "%ld and %ld): delete the wrong one, or choose another output", path, rows[i].line,
                                rows[i].k, rows[i - 1].line, rows[i].line);
    }
    for (long i = 0; rc == GW_OK && i < nrows; i++) {
        if (!done[rows[i].k])
            (*ndone)++;
        done[rows[i].k] = 1;
    }
    free(rows);
    /* a torn line of the head ("# param vi": the head is written whole, so
     * only an edit or a damaged disk leaves one), not a row, which begins with
     * its case number: cut alike, but no case to run again */
    const int head_torn = good < len && buf[good] == '#';
    free(buf);
    if (rc != GW_OK)
        return rc;
    if (torn) {
        *torn = len - good + zeros;
        if (torn_head)
            *torn_head = head_torn ? 1 : zeros && good == len ? 2 : 0;
        return GW_OK;
    }
    if (good < len + zeros && ftruncate(fd, (off_t)good) != 0)
        return gw_err_set(err, GW_EIO, "%s: cannot cut a torn row: %s", path, strerror(errno));
    return GW_OK;
}

int gw_sweep_journal_append(int fd, const char *row, double *synced_ms, gw_err *err)
{
    if (!row)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_journal_append: row is NULL");
    const size_t n = strlen(row);
    /* A row is one line with its newline: one without it was written as it
     * was and the next row joined it (a line no resume takes: the sweep
     * refused its own journal), one holding a newline wrote two lines, an
     * empty one a line of nothing; each refused, nothing written. */
    const char *nl = memchr(row, '\n', n);
    if (n < 2 || nl != row + n - 1)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_journal_append: row '%s' is not one line ending in a newline "
                          "(%s)", row, n == 0 ? "empty" : !nl ? "no newline" : nl == row ? "an empty line" :
                          "a newline inside it");
    jshadow *h = shadow_get(fd);
    if (h && h->len + n > h->cap) { /* room in the journal's copy first: the row written is in it */
        const size_t cap = h->len + n > 2 * h->cap ? h->len + n : 2 * h->cap;
        char *t = realloc(h->text, cap);
        if (!t)
            return gw_err_set(err, GW_ENOMEM, "sweep journal: out of memory for its copy (%zu bytes)", cap);
        h->text = t, h->cap = cap;
    }
    if (write_all(fd, row, n) != 0) { /* a torn row then: cut by the resume, its case run again */
        const int e = errno;
        if (h) /* what the file holds now is not known: checked by its name alone */
            shadow_drop(h);
        return gw_err_set(err, GW_EIO, "sweep journal: write failed: %s", strerror(e));
    }
    if (h) {
        memcpy(h->text + h->len, row, n);
        h->len += n;
        /* the file's events since the check before this row (shadow_differs
         * emptied the queue): this write's one IN_MODIFY and nothing else,
         * or another wrote, cut or opened it meanwhile, and the times now
         * are not the sweep's alone: the next check (gw_sweep_journal_held)
         * compares the whole file */
        int one, opens;
        const int others = others_open(fd); /* before the queue is read: see JOURNAL_TAIL */
        const int nev = shadow_events(h, &one, &opens);
        /* others holding it: readers alone (a `tail -f`, a viewer) cannot
         * write inside the window, so the whole file is compared only while
         * one may write. Who holds it is looked up in /proc after the queue
         * was read (an open later is in the queue before its descriptor is
         * in /proc: found at the next check) and kept until the next open
         * the watch sees (shadow_events); without a watch, never kept. */
        int writers = others;
        if (others == 1 && h->ifd >= 0) {
            if (!h->readers_only)
                h->readers_only = !others_write(fd);
            writers = !h->readers_only;
        }
        if ((nev >= 0 && !one) || writers == 1)
            h->times_ok = 0;
        else
            shadow_times(h, fd); /* without a watch: a same-length write meanwhile looks like this one's */
    }
    /* a time of the last fsync that is none (NaN: never synced again) or
     * after now (never GW_SWEEP_SYNC_MS old) is taken as long past */
    const double now = gw_clock_ms(), age = synced_ms ? now - *synced_ms : NAN;
    if (!(age >= 0 && age < GW_SWEEP_SYNC_MS))
        return gw_sweep_journal_sync(fd, synced_ms, err);
    return GW_OK;
}

int gw_sweep_journal_sync(int fd, double *synced_ms, gw_err *err)
{
    if (fsync(fd) != 0)
        return gw_err_set(err, GW_EIO, "sweep journal: fsync failed: %s", strerror(errno));
    if (synced_ms)
        *synced_ms = gw_clock_ms();
    return GW_OK;
}
