/*
 * gw_io_afile.c: atomic files: a file written under a temporary name beside
 * its path ("PATH.tmp.HOST.PID.XXXXXX"), fsynced and renamed into place, so a
 * reader sees the previous file or the complete new one; as a stream, or as a
 * temporary path for writers that create the file by name (HDF5); through a
 * symbolic link its target is replaced and the link kept; by name in a
 * directory the caller holds open, which may be moved meanwhile
 * (gw_afile_openat: a sweep's table); SIGINT, SIGTERM and
 * SIGHUP held from open to commit, the temporary in the table a signal
 * handler empties (gw_io_temps.c) until it is placed; the temporaries a
 * killed writer left removed at the next open. Also gw_write_text and the
 * comment lines of file headers. Separate from the output sets (gw_io_outset.c), which stage these
 * files and place them together, and from the checks of output locations
 * made before a run (gw_io_paths.c).
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <pthread.h>
#include <time.h>
#include <unistd.h>

#include "gw_common.h"
#include "gw_locale.h"
#include "gw_global.h"
#include "gw_io_impl.h"

_Static_assert(sizeof(sigset_t) <= sizeof(((gw_afile *)0)->oldmask), "sigset_t does not fit");

/* The signals that end the process (gw_io_end_signals) held on this thread
 * (the mask before in old, *masked set when it was), and given back */
void gw_io_sig_hold(unsigned char *old, int *masked)
{
    sigset_t s;
    size_t n;
    const int *sigs = gw_io_end_signals(&n);
    sigemptyset(&s);
    for (size_t k = 0; k < n; k++)
        sigaddset(&s, sigs[k]);
    *masked = pthread_sigmask(SIG_BLOCK, &s, (sigset_t *)(void *)old) == 0;
}

void gw_io_sig_release(unsigned char *old, int *masked)
{
    if (*masked)
        pthread_sigmask(SIG_SETMASK, (sigset_t *)(void *)old, NULL);
    *masked = 0;
}

/* The gw_afile structs open now (opened and not yet committed or aborted),
 * by address, so that an open on one of them is refused before it touches
 * it. An open on an open file zeroed it: its temporary stayed on disk, an
 * orphan in the signals' table, and the signal mask it had saved was the
 * one the first open had set, so the commit left SIGINT, SIGTERM and SIGHUP
 * blocked in the thread for good (Ctrl-C did nothing after). Only addresses
 * are compared: a struct never opened is never read. */
static struct {
    const gw_afile **v;
    size_t n, cap;
} opened;
static gw_forklock opened_lock = GW_FORKLOCK(NULL);

static int afile_is_open(const gw_afile *f)
{
    int found = 0;
    gw_forklock_take(&opened_lock);
    for (size_t i = 0; i < opened.n && !found; i++)
        found = opened.v[i] == f;
    gw_forklock_give(&opened_lock);
    return found;
}

/* f is open now (out of memory: not recorded, the check is then skipped) */
static void afile_opened(const gw_afile *f)
{
    gw_forklock_take(&opened_lock);
    if (opened.n == opened.cap) {
        const size_t cap = opened.cap ? 2 * opened.cap : 16;
        const gw_afile **v = realloc(opened.v, cap * sizeof *v);
        if (v)
            opened.v = v, opened.cap = cap;
    }
    if (opened.n < opened.cap)
        opened.v[opened.n++] = f;
    gw_forklock_give(&opened_lock);
}

static void afile_closed(const gw_afile *f)
{
    gw_forklock_take(&opened_lock);
    for (size_t i = 0; i < opened.n; i++)
        if (opened.v[i] == f) {
            opened.v[i] = opened.v[--opened.n];
            break;
        }
    gw_forklock_give(&opened_lock);
}

static int refuse_open(const gw_afile *f, const char *call, gw_err *err)
{
    return gw_err_set(err, GW_EINVAL, "%s: f is open on '%s' (not yet committed or aborted): commit or abort it "
                      "before opening it again", call, f->path);
}

static void hold_signals(gw_afile *f) { gw_io_sig_hold(f->oldmask, &f->masked); }
static void release_signals(gw_afile *f) { gw_io_sig_release(f->oldmask, &f->masked); }

/* GW_EINVAL for the symbolic link path whose target cannot be used (e: the
 * errno of resolving it; ENOENT: it leads to nothing), naming the target. */
int gw_io_link_refused(const char *path, const char *what, int e, gw_err *err)
{
    char target[4096];
    ssize_t k = readlink(path, target, sizeof target - 1);
    target[k > 0 ? k : 0] = '\0';
    if (e == ENOENT)
        return gw_err_set(err, GW_EINVAL, "%s: '%s' is a symbolic link to '%s', which does not exist", what, path,
                          target);
    return gw_err_set(err, GW_EINVAL, "%s: '%s' is a symbolic link to '%s': %s", what, path, target, strerror(e));
}

/* The file a write to path replaces: path itself, or the file a symbolic link
 * there leads to (the rename of an atomic write would put a regular file in
 * place of the link and leave its target as it was: layer-make --out LINK).
 * GW_EINVAL for a link to nothing (as gw_out_check refuses for a directory),
 * and for a file there that is not a regular file: the rename would put the
 * run's file in place of a FIFO, a socket or a device node (as root, an
 * output DIR/chain.json linked to a /dev/null made with mknod turned that
 * device node into a regular file), and fails after the run on a directory. */
int gw_io_write_target(const char *path, char *out, size_t n, const char *what, gw_err *err)
{
    /* "" names no file: gw_afile_open made its temporary in the working
     * directory and the commit failed ("write failed: No such file or
     * directory") once the work was done */
    if (!*path)
        return gw_err_set(err, GW_EINVAL, "%s: an empty path names no file", what && *what ? what : "output");
    struct stat st;
    const int there = lstat(path, &st) == 0;
    if (!there || !S_ISLNK(st.st_mode)) {
        if (strlen(path) >= n)
            return gw_err_set(err, GW_EINVAL, "%s: path too long", path);
        if (there && !S_ISREG(st.st_mode))
            return gw_err_set(err, GW_EINVAL, "%s: '%s' is %s; an output replaces only a regular file", what,
                              path, gw_io_file_kind(st.st_mode));
        gw_snprintf(out, n, "%s", path);
        return GW_OK;
    }
    char real[PATH_MAX];
    if (!realpath(path, real))
        return gw_io_link_refused(path, what, errno, err);
    if (strlen(real) >= n)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", real);
    if (stat(real, &st) == 0 && !S_ISREG(st.st_mode))
        return gw_err_set(err, GW_EINVAL, "%s: '%s' is a symbolic link to '%s', which is %s; an output replaces "
                          "only a regular file", what, path, real, gw_io_file_kind(st.st_mode));
    gw_snprintf(out, n, "%s", real);
    return GW_OK;
}

/* This host's name as it goes into temporaries' names: letters, digits and
 * '-', at most 24 ("host" when none is left). */
static void host_token(char *out, size_t n)
{
    char h[256] = "";
    size_t k = 0;
    if (gethostname(h, sizeof h - 1) != 0)
        h[0] = '\0';
    for (const char *c = h; *c && k + 1 < n && k < 24; c++)
        if ((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') || *c == '-')
            out[k++] = *c;
    out[k] = '\0';
    if (k == 0)
        gw_snprintf(out, n, "host");
}

size_t gw_io_temp_suffix_len(void)
{
    char host[32], buf[96];
    host_token(host, sizeof host);
    return (size_t)gw_snprintf(buf, sizeof buf, ".tmp.%s.%ld.XXXXXX", host, (long)getpid());
}

int gw_io_side_name(const char *path, unsigned long seq, char *out, size_t n)
{
    static const char digits[] = "0123456789abcdefghijklmnopqrstuvwxyz";
    char host[32], tag[7];
    host_token(host, sizeof host);
    for (int k = 5; k >= 0; k--, seq /= 36)
        tag[k] = digits[seq % 36];
    tag[6] = '\0';
    const int w = gw_snprintf(out, n, "%s.tmp.%s.%ld.%s", path, host, (long)getpid(), tag);
    return w < 0 || (size_t)w >= n ? -1 : 0;
}

/* The temporaries of path that a writer on this host left when it was killed
 * (kill -9): "BASE.tmp.HOST.PID.XXXXXX" whose PID is no process (kill(PID, 0):
 * ESRCH). A writer alive (this process included), another host's temporary
 * (a shared file system) and other names are left alone. */
static void remove_stale_temporaries(int at, const char *path, const char *host)
{
    char dir[4096];
    const char *slash = strrchr(path, '/'), *base = slash ? slash + 1 : path;
    if (gw_snprintf(dir, sizeof dir, "%s", path) >= (int)sizeof dir)
        return;
    gw_path_parent(dir);
    char prefix[512];
    if (gw_snprintf(prefix, sizeof prefix, "%s.tmp.%s.", base, host) >= (int)sizeof prefix)
        return;
    const size_t plen = strlen(prefix);
    const int dfd = openat(at, dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC); /* at: AT_FDCWD, or a held directory */
    DIR *d = dfd >= 0 ? fdopendir(dfd) : NULL;
    if (!d) {
        if (dfd >= 0)
            close(dfd);
        return;
    }
    for (struct dirent *e; (e = readdir(d)) != NULL;) {
        if (strncmp(e->d_name, prefix, plen) != 0)
            continue;
        char *end;
        errno = 0;
        long pid = strtol(e->d_name + plen, &end, 10);
        if (errno || end == e->d_name + plen || pid <= 0 || *end != '.' || strlen(end + 1) != 6 ||
            pid == (long)getpid())
            continue;
        if (kill((pid_t)pid, 0) == 0 || errno != ESRCH)
            continue;
        unlinkat(dirfd(d), e->d_name, 0);
    }
    closedir(d);
}

/* The process's umask, read without changing it (/proc/self/status,
 * "Umask:", Linux 4.7 and later); elsewhere set to 077 and back under a lock
 * (a file another thread creates in between is then only more private). */
mode_t gw_io_current_umask(void)
{
    FILE *fp = fopen("/proc/self/status", "re");
    if (fp) {
        char line[256];
        unsigned v = 0;
        int got = 0;
        while (!got && fgets(line, sizeof line, fp))
            got = strncmp(line, "Umask:", 6) == 0 && sscanf(line + 6, "%o", &v) == 1;
        fclose(fp);
        if (got)
            return (mode_t)(v & 0777);
    }
    static pthread_mutex_t mu = PTHREAD_MUTEX_INITIALIZER;
    pthread_mutex_lock(&mu);
    mode_t m = umask(077);
    umask(m);
    pthread_mutex_unlock(&mu);
    return m & 0777;
}

mode_t gw_new_file_mode(const char *replaces)
{
    struct stat st;
    if (replaces && stat(replaces, &st) == 0 && S_ISREG(st.st_mode))
        return st.st_mode & 0777;
    return 0666 & ~gw_io_current_umask();
}

/* The status of a failed open: out of memory (the stream's buffer, the
 * kernel's) is a run failure, not a file to blame. */
int gw_io_status(int e)
{
    return e == ENOMEM ? GW_ENOMEM : GW_EIO;
}

/* The temporary removed, and forgotten by the signals' table */
static void discard(gw_afile *f)
{
    if (f->held)
        unlinkat(f->dirfd, f->tmp + f->rel, 0);
    else
        unlink(f->tmp);
    gw_temps_drop(f->tmp);
    f->tmp[0] = '\0';
}

/* The directory gw_afile_open held for its file closed, once the temporary
 * is placed or removed and out of the signals' table (a number the table
 * still held could name another directory after the close) */
static void release_dir(gw_afile *f)
{
    if (f->held == AFILE_OWN_DIR && f->dirfd >= 0)
        close(f->dirfd);
    if (f->held == AFILE_OWN_DIR) {
        f->held = 0;
        f->dirfd = -1;
    }
}

/* A file written outside an output set (layer-make --out FILE, a wisdom
 * file) holds its own directory from the open to the commit, so that a
 * directory moved, removed or replaced meanwhile (mv D D.old; mkdir D) is
 * told from the one it was made in. Before, its temporary was known by its
 * path alone: a signal then removed whatever had that name in the new D and
 * left the temporary in D.old, and the commit failed with "No such file or
 * directory" and left it there too. The temporary is now bound to the held
 * directory in the signals' table and removed there, and the commit places
 * the file only when path still names that directory. Only a temporary made
 * in the directory itself is taken: beside a link's target elsewhere, by its
 * path as before. 1 held, 0 not (no read access to the directory: by path). */
static int hold_own_dir(gw_afile *f, int fd)
{
    char dir[4096];
    gw_snprintf(dir, sizeof dir, "%s", f->path);
    gw_path_parent(dir);
    const int dfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd < 0)
        return 0;
    const char *slash = strrchr(f->path, '/');
    const size_t rel = slash ? (size_t)(slash - f->path) + 1 : 0;
    struct stat a, b;
    if (fstat(fd, &a) != 0 || fstatat(dfd, f->tmp + rel, &b, AT_SYMLINK_NOFOLLOW) != 0 || a.st_dev != b.st_dev ||
        a.st_ino != b.st_ino) {
        close(dfd);
        return 0;
    }
    f->held = AFILE_OWN_DIR;
    f->dirfd = dfd;
    f->rel = rel;
    return 1;
}

/* f's own held directory is still the one its path names: 1, else 0 */
static int own_dir_in_place(const gw_afile *f)
{
    char dir[4096];
    gw_snprintf(dir, sizeof dir, "%s", f->path);
    gw_path_parent(dir);
    struct stat a, b;
    return fstat(f->dirfd, &a) == 0 && stat(dir, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

/* The end of an open, f's temporary just made as fd: in the signals' table
 * (bound to the directory bind, -1: by its path; one the table could not
 * take, out of memory, is not kept), given the permissions mode and a
 * stream. On failure the temporary is removed and the signals given back. */
static int adopt_temp(gw_afile *f, int fd, int bind, mode_t mode, gw_err *err)
{
    if (gw_temps_add_at(f->tmp, bind) < 0) {
        close(fd);
        discard(f);
        release_dir(f);
        release_signals(f);
        return gw_err_set(err, GW_ENOMEM, "%s: cannot create: %s", f->path, strerror(ENOMEM));
    }
    fchmod(fd, mode);
    f->fp = fdopen(fd, "w");
    if (!f->fp) {
        const int e = errno;
        close(fd);
        discard(f);
        release_dir(f);
        release_signals(f);
        return gw_err_set(err, gw_io_status(e), "%s: cannot open: %s", f->path, strerror(e));
    }
    afile_opened(f);
    return GW_OK;
}

int gw_afile_open(gw_afile *f, const char *path, gw_err *err)
{
    if (!f || !path)
        return gw_err_set(err, GW_EINVAL, "gw_afile_open: %s is NULL", !f ? "f" : "path");
    if (afile_is_open(f))
        return refuse_open(f, "gw_afile_open", err);
    /* the rule the output checks apply before a run (a name to make that
     * holds a control character), here for every writer: a C caller of
     * gw_layer_sample_write, gw_json_write or this call itself wrote
     * "/tmp/x\n" without any check (session 42) */
    memset(f, 0, sizeof *f); /* (safe to abort after a refusal) */
    if (gw_io_new_name_check(path, "output", err) != GW_OK)
        return GW_EINVAL;
    hold_signals(f);
    int rc = gw_io_write_target(path, f->path, sizeof f->path, path, err);
    if (rc != GW_OK) { /* nothing made: give the signals back */
        release_signals(f);
        return rc;
    }
    path = f->path; /* the temporary beside the file it replaces */
    char host[32];
    host_token(host, sizeof host);
    remove_stale_temporaries(AT_FDCWD, path, host);
    gw_snprintf(f->tmp, sizeof f->tmp, "%s.tmp.%s.%ld.XXXXXX", path, host, (long)getpid());
    int fd = mkstemp(f->tmp);
    if (fd < 0) {
        f->tmp[0] = '\0';
        int e = errno;
        release_signals(f);
        return gw_err_set(err, gw_io_status(e), "%s: cannot create: %s", path, strerror(e));
    }
    /* a signal that ends the program removes it (gw_temps_on_signals): in an
     * output set's directory, through the set's handle on it, and outside a
     * set through the file's own, wherever it is moved. mkstemp made it 0600:
     * the permissions a shell's > would give (the replaced file's, or 0666
     * less the umask) */
    const int bind = gw_outset_active() ? gw_outset_temp_dir(f->tmp, fd) : hold_own_dir(f, fd) ? f->dirfd : -1;
    return adopt_temp(f, fd, bind, gw_new_file_mode(path), err);
}

int gw_afile_open_named(gw_afile *f, const char *path, gw_err *err)
{
    int rc = gw_afile_open(f, path, err);
    if (rc != GW_OK)
        return rc;
    /* the writer creates f->tmp again by name (HDF5 truncates it): the empty
     * file made by mkstemp only reserves the unique name */
    fclose(f->fp);
    f->fp = NULL;
    f->named = 1;
    return GW_OK;
}

/* name in the directory dfd (shown as dir) followed through symbolic links
 * to the file a write replaces, into rel (n bytes): a relative target from
 * the link's own directory, an absolute one as it is (the *at calls take an
 * absolute name as it is). GW_EINVAL for a link to nothing or a file that is
 * not a regular file there, as gw_io_write_target. */
static int at_target(int dfd, const char *dir, const char *name, char *rel, size_t n, gw_err *err)
{
    if (gw_snprintf(rel, n, "%s", name) >= (int)n)
        return gw_err_set(err, GW_EINVAL, "%s/%s: path too long", dir, name);
    for (int hops = 0;; hops++) {
        struct stat st;
        if (fstatat(dfd, rel, &st, AT_SYMLINK_NOFOLLOW) != 0) {
            const int e = errno;
            if (e == ENOENT && hops == 0)
                return GW_OK; /* made by the commit */
            return hops ? gw_err_set(err, GW_EINVAL, "%s/%s: a symbolic link to '%s', %s", dir, name, rel,
                                     e == ENOENT ? "which does not exist" : strerror(e))
                        : gw_err_set(err, gw_io_status(e), "%s/%s: %s", dir, name, strerror(e));
        }
        if (!S_ISLNK(st.st_mode))
            return S_ISREG(st.st_mode) ? GW_OK
                                       : gw_err_set(err, GW_EINVAL, "%s/%s: '%s' is %s; an output replaces only a "
                                                    "regular file", dir, name, rel, gw_io_file_kind(st.st_mode));
        char t[4096];
        const ssize_t k = hops < 40 ? readlinkat(dfd, rel, t, sizeof t - 1) : -1;
        if (k < 0)
            return gw_err_set(err, GW_EINVAL, "%s/%s: a symbolic link that cannot be followed: %s", dir, name,
                              strerror(hops < 40 ? errno : ELOOP));
        t[k] = '\0';
        const char *slash = strrchr(rel, '/');
        const size_t keep = t[0] == '/' || !slash ? 0 : (size_t)(slash - rel) + 1;
        if (keep + (size_t)k >= n)
            return gw_err_set(err, GW_EINVAL, "%s/%s: path too long", dir, name);
        memcpy(rel + keep, t, (size_t)k + 1);
    }
}

int gw_afile_openat(gw_afile *f, int dirfd, const char *dir, const char *name, gw_err *err)
{
    if (!f || !dir || !name)
        return gw_err_set(err, GW_EINVAL, "gw_afile_openat: %s is NULL", !f ? "f" : !dir ? "dir" : "name");
    if (afile_is_open(f))
        return refuse_open(f, "gw_afile_openat", err);
    /* "" names no file, as gw_afile_open says: the temporary was made in the
     * directory and the caller's whole write ran before the commit failed
     * ("DIR/: write failed: No such file or directory") */
    if (!*name)
        return gw_err_set(err, GW_EINVAL, "%s: an empty name names no file", dir);
    memset(f, 0, sizeof *f);
    if (gw_io_new_name_check_at(dirfd, name, "output", err) != GW_OK) /* as gw_afile_open */
        return GW_EINVAL;
    hold_signals(f);
    char rel[4096];
    int rc = at_target(dirfd, dir, name, rel, sizeof rel, err);
    const int shown = rc != GW_OK ? 0
                      : rel[0] == '/' ? gw_snprintf(f->path, sizeof f->path, "%s", rel)
                                      : gw_snprintf(f->path, sizeof f->path, "%s/%s", dir, rel);
    if (rc == GW_OK && (shown < 0 || (size_t)shown >= sizeof f->path))
        rc = gw_err_set(err, GW_EINVAL, "%s/%s: path too long", dir, name);
    if (rc != GW_OK) {
        release_signals(f);
        return rc;
    }
    f->held = 1;
    f->dirfd = dirfd;
    f->rel = strlen(f->path) - strlen(rel); /* the name in dirfd, of path and of tmp */
    char host[32];
    host_token(host, sizeof host);
    remove_stale_temporaries(dirfd, rel, host);
    /* a unique temporary of mkstemp's form, made in the held directory */
    struct timespec ts;
    clock_gettime(CLOCK_REALTIME, &ts);
    unsigned long seq = (unsigned long)ts.tv_nsec ^ ((unsigned long)ts.tv_sec << 20);
    int fd = -1, e = EEXIST;
    for (int tries = 0; fd < 0 && e == EEXIST && tries < 1000; tries++, seq += 7919) {
        if (gw_io_side_name(f->path, seq, f->tmp, sizeof f->tmp) != 0) {
            e = ENAMETOOLONG;
            break;
        }
        fd = openat(dirfd, f->tmp + f->rel, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        e = fd < 0 ? errno : 0;
    }
    if (fd < 0) {
        f->tmp[0] = '\0';
        release_signals(f);
        return gw_err_set(err, gw_io_status(e), "%s: cannot create: %s", f->path, strerror(e));
    }
    /* as gw_afile_open; one made in the held directory itself is removed there
     * by its name, wherever that directory was moved (a sweep's table) */
    struct stat st; /* the permissions of the file it replaces, or a shell's > */
    const mode_t mode = fstatat(dirfd, rel, &st, 0) == 0 && S_ISREG(st.st_mode) ? st.st_mode & 0777
                                                                               : 0666 & ~gw_io_current_umask();
    return adopt_temp(f, fd, strchr(f->tmp + f->rel, '/') ? -1 : dirfd, mode, err);
}

/* The end of a commit once the temporary is complete and fsynced: staged in
 * the open set, or renamed into place. */
static int place(gw_afile *f, int *saved)
{
    if (f->held == AFILE_OWN_DIR && !own_dir_in_place(f)) {
        *saved = -1; /* the directory moved: told by the caller */
        return -1;
    }
    int st = f->held ? 0 : gw_outset_stage(f);
    if (st < 0) {
        *saved = ENOMEM;
        return -1;
    }
    if (st == 0 && (f->held ? renameat(f->dirfd, f->tmp + f->rel, f->dirfd, f->path + f->rel)
                            : rename(f->tmp, f->path)) != 0) {
        *saved = errno ? errno : EIO;
        return -1;
    }
    if (st == 0) /* placed; a staged one stays in the table, the set's now */
        gw_temps_drop(f->tmp);
    return 0;
}

/* The end of a commit: on failure (bad, saved the errno, or -1 when the
 * file's own directory was moved) the temporary removed; the directory and
 * the signals given back */
static int commit_end(gw_afile *f, int bad, int saved, gw_err *err)
{
    afile_closed(f);
    if (bad)
        discard(f);
    f->tmp[0] = '\0';
    f->named = 0;
    release_dir(f);
    release_signals(f);
    if (bad && saved < 0)
        return gw_err_set(err, GW_EIO, "%s: the directory was moved, removed or replaced while the run went on: "
                          "nothing written (the file was made in the directory that path named when it began)",
                          f->path);
    return bad ? gw_err_set(err, GW_EIO, "%s: write failed: %s", f->path, strerror(saved)) : GW_OK;
}

/* fsync a file the caller wrote by name, then rename it into place. */
static int commit_named(gw_afile *f, gw_err *err)
{
    errno = 0;
    int fd = open(f->tmp, O_RDONLY);
    int bad = fd < 0 || fsync(fd) != 0;
    int saved = bad ? (errno ? errno : EIO) : 0;
    if (fd >= 0)
        close(fd);
    if (!bad && place(f, &saved) != 0)
        bad = 1;
    return commit_end(f, bad, saved, err);
}

int gw_afile_commit(gw_afile *f, gw_err *err)
{
    if (!f)
        return gw_err_set(err, GW_EINVAL, "gw_afile_commit: f is NULL");
    if (f->named && !f->fp && f->tmp[0])
        return commit_named(f, err);
    if (!f->fp) {
        afile_closed(f);
        release_dir(f);
        release_signals(f);
        return gw_err_set(err, GW_EIO, "%s: file not open", f->path);
    }
    /* errno is only meaningful right after the call that failed: a stream whose
     * error flag was set by an earlier fwrite reports EIO, never "Success" */
    errno = 0;
    int bad = 0, saved = 0;
    if (ferror(f->fp)) { /* an earlier write failed: flushing again gives its errno */
        bad = 1;
        fflush(f->fp);
        saved = errno;
        /* unless the stream dropped what it failed to write (the failure then
         * hit a whole buffer, and the flush has nothing to say): one byte
         * more at the end of the temporary, removed below, fails as the
         * writes did. ledger.csv over ulimit -f said "Input/output error" or
         * "File too large" by where its 4 kB buffers fell (a sample path 19
         * bytes longer in its header). A write past the size limit raised
         * SIGXFSZ at the first failure, so the probe's is ignored too. */
        const int fd = fileno(f->fp);
        const off_t end = saved ? -1 : lseek(fd, 0, SEEK_END);
        const char zero = 0;
        if (!saved)
            saved = end >= 0 && pwrite(fd, &zero, 1, end) < 0 && errno ? errno : EIO;
    }
    else if (fflush(f->fp) != 0 || fsync(fileno(f->fp)) != 0)
        bad = 1, saved = errno ? errno : EIO;
    errno = 0;
    if (fclose(f->fp) != 0 && !bad)
        bad = 1, saved = errno ? errno : EIO;
    f->fp = NULL;
    if (!bad && place(f, &saved) != 0)
        bad = 1;
    return commit_end(f, bad, saved, err);
}

void gw_afile_abort(gw_afile *f)
{
    if (!f)
        return;
    afile_closed(f);
    if (f->fp) {
        fclose(f->fp);
        f->fp = NULL;
    }
    if (f->tmp[0])
        discard(f);
    f->named = 0;
    release_dir(f);
    release_signals(f);
}

void gw_write_comment(FILE *fp, const char *text)
{
    if (!fp)
        return;
    for (const char *p = text; p && *p;) {
        const char *nl = strchr(p, '\n');
        size_t len = nl ? (size_t)(nl - p) : strlen(p);
        gw_fprintf(fp, "# %.*s\n", (int)len, p);
        p += len + (nl != NULL);
    }
}

int gw_write_text(const char *path, const char *text, gw_err *err)
{
    if (!path || !text)
        return gw_err_set(err, GW_EINVAL, "gw_write_text: %s is NULL", !path ? "path" : "text");
    gw_afile f;
    int rc = gw_afile_open(&f, path, err);
    if (rc != GW_OK)
        return rc;
    fputs(text, f.fp);
    return gw_afile_commit(&f, err);
}
