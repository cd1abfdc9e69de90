/*
 * gw_io.c: atomic files (temporary name, fsync, rename; as a stream, or as a
 * temporary path for writers that create the file by name, such as HDF5;
 * through a symbolic link: its target is replaced, the link kept),
 * comment lines for file headers, directories, paths, and
 * the one way inputs are opened: regular files only (a FIFO, device or directory
 * is refused before any read, so nothing can block), reads bounded in size.
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <pthread.h>
#include <time.h>
#include <unistd.h>

#include "gw_common.h"
#include "gw_locale.h"

_Static_assert(sizeof(sigset_t) <= sizeof(((gw_afile *)0)->oldmask), "sigset_t does not fit");
_Static_assert(sizeof(sigset_t) <= sizeof(((gw_outset *)0)->oldmask), "sigset_t does not fit");

/* SIGINT, SIGTERM and SIGHUP held on this thread (the mask before in old,
 * *masked set when it was), and given back */
static void sig_hold(unsigned char *old, int *masked)
{
    sigset_t s;
    sigemptyset(&s);
    sigaddset(&s, SIGINT);
    sigaddset(&s, SIGTERM);
    sigaddset(&s, SIGHUP);
    *masked = pthread_sigmask(SIG_BLOCK, &s, (sigset_t *)(void *)old) == 0;
}

static void sig_release(unsigned char *old, int *masked)
{
    if (*masked)
        pthread_sigmask(SIG_SETMASK, (sigset_t *)(void *)old, NULL);
    *masked = 0;
}

static void hold_signals(gw_afile *f) { sig_hold(f->oldmask, &f->masked); }
static void release_signals(gw_afile *f) { sig_release(f->oldmask, &f->masked); }

/* GW_EINVAL for the symbolic link path whose target cannot be used (e: the
 * errno of resolving it; ENOENT: it leads to nothing), naming the target. */
static int link_refused(const char *path, const char *what, int e, gw_err *err)
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
 * GW_EINVAL for a link to nothing (as gw_out_check refuses for a directory). */
static int write_target(const char *path, char *out, size_t n, const char *what, gw_err *err)
{
    struct stat st;
    if (lstat(path, &st) != 0 || !S_ISLNK(st.st_mode)) {
        if (strlen(path) >= n)
            return gw_err_set(err, GW_EINVAL, "%s: path too long", path);
        gw_snprintf(out, n, "%s", path);
        return GW_OK;
    }
    char real[PATH_MAX];
    if (!realpath(path, real))
        return link_refused(path, what, errno, err);
    if (strlen(real) >= n)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", real);
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

/* The temporaries of path that a writer on this host left when it was killed
 * (kill -9): "BASE.tmp.HOST.PID.XXXXXX" whose PID is no process (kill(PID, 0):
 * ESRCH). A writer alive (this process included), another host's temporary
 * (a shared file system) and other names are left alone. */
static void remove_stale_temporaries(const char *path, const char *host)
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
    DIR *d = opendir(dir);
    if (!d)
        return;
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
static mode_t current_umask(void)
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
    return 0666 & ~current_umask();
}

/* The status of a failed open: out of memory (the stream's buffer, the
 * kernel's) is a run failure, not a file to blame. */
static int io_status(int e)
{
    return e == ENOMEM ? GW_ENOMEM : GW_EIO;
}

int gw_afile_open(gw_afile *f, const char *path, gw_err *err)
{
    if (!f || !path)
        return gw_err_set(err, GW_EINVAL, "gw_afile_open: %s is NULL", !f ? "f" : "path");
    memset(f, 0, sizeof *f);
    hold_signals(f);
    int rc = write_target(path, f->path, sizeof f->path, path, err);
    if (rc != GW_OK) { /* nothing made: give the signals back */
        release_signals(f);
        return rc;
    }
    path = f->path; /* the temporary beside the file it replaces */
    char host[32];
    host_token(host, sizeof host);
    remove_stale_temporaries(path, host);
    gw_snprintf(f->tmp, sizeof f->tmp, "%s.tmp.%s.%ld.XXXXXX", path, host, (long)getpid());
    int fd = mkstemp(f->tmp);
    if (fd < 0) {
        f->tmp[0] = '\0';
        int e = errno;
        release_signals(f);
        return gw_err_set(err, io_status(e), "%s: cannot create: %s", path, strerror(e));
    }
    /* mkstemp made it 0600: the permissions a shell's > would give (the
     * replaced file's, or 0666 less the umask) */
    fchmod(fd, gw_new_file_mode(path));
    f->fp = fdopen(fd, "w");
    if (!f->fp) {
        int e = errno;
        close(fd);
        unlink(f->tmp);
        f->tmp[0] = '\0';
        release_signals(f);
        return gw_err_set(err, io_status(e), "%s: cannot open: %s", path, strerror(e));
    }
    return GW_OK;
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

/* The output set open on this thread (gw_outset_begin), or NULL. */
static _Thread_local gw_outset *cur_set;

/* Keep f's fsynced temporary in the open set instead of renaming it: 1 staged,
 * 0 no set open, -1 out of memory (the temporary is then removed). */
static int stage(gw_afile *f)
{
    gw_outset *s = cur_set;
    if (!s)
        return 0;
    if (s->n == s->cap) {
        int cap = s->cap ? 2 * s->cap : 16;
        char **t = realloc(s->tmp, (size_t)cap * sizeof *t);
        if (t)
            s->tmp = t;
        char **p = t ? realloc(s->path, (size_t)cap * sizeof *p) : NULL;
        if (p)
            s->path = p;
        if (!t || !p)
            return -1;
        s->cap = cap;
    }
    char *t = strdup(f->tmp), *p = strdup(f->path);
    if (!t || !p) {
        free(t);
        free(p);
        return -1;
    }
    s->tmp[s->n] = t;
    s->path[s->n] = p;
    s->n++;
    return 1;
}

/* The end of a commit once the temporary is complete and fsynced: staged in
 * the open set, or renamed into place. */
static int place(gw_afile *f, int *saved)
{
    int st = stage(f);
    if (st < 0) {
        *saved = ENOMEM;
        return -1;
    }
    if (st == 0 && rename(f->tmp, f->path) != 0) {
        *saved = errno ? errno : EIO;
        return -1;
    }
    return 0;
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
    if (bad)
        unlink(f->tmp);
    f->tmp[0] = '\0';
    f->named = 0;
    release_signals(f);
    return bad ? gw_err_set(err, GW_EIO, "%s: write failed: %s", f->path, strerror(saved)) : GW_OK;
}

int gw_afile_commit(gw_afile *f, gw_err *err)
{
    if (!f)
        return gw_err_set(err, GW_EINVAL, "gw_afile_commit: f is NULL");
    if (f->named && !f->fp && f->tmp[0])
        return commit_named(f, err);
    if (!f->fp) {
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
        saved = errno ? errno : EIO;
    }
    else if (fflush(f->fp) != 0 || fsync(fileno(f->fp)) != 0)
        bad = 1, saved = errno ? errno : EIO;
    errno = 0;
    if (fclose(f->fp) != 0 && !bad)
        bad = 1, saved = errno ? errno : EIO;
    f->fp = NULL;
    if (bad || place(f, &saved) != 0) {
        unlink(f->tmp);
        f->tmp[0] = '\0';
        release_signals(f);
        return gw_err_set(err, GW_EIO, "%s: write failed: %s", f->path, strerror(saved));
    }
    f->tmp[0] = '\0';
    release_signals(f);
    return GW_OK;
}

void gw_afile_abort(gw_afile *f)
{
    if (!f)
        return;
    if (f->fp) {
        fclose(f->fp);
        f->fp = NULL;
    }
    if (f->tmp[0]) {
        unlink(f->tmp);
        f->tmp[0] = '\0';
    }
    f->named = 0;
    release_signals(f);
}

int gw_outset_begin(gw_outset *s, const char *dir, const char *const *names, gw_err *err)
{
    if (!s || !dir || !names)
        return gw_err_set(err, GW_EINVAL, "gw_outset_begin: %s is NULL", !s ? "s" : !dir ? "dir" : "names");
    memset(s, 0, sizeof *s);
    if (cur_set)
        return gw_err_set(err, GW_EINVAL, "%s: an output set is already open on this thread", dir);
    if (gw_snprintf(s->dir, sizeof s->dir, "%s", dir) >= (int)sizeof s->dir)
        return gw_err_set(err, GW_EINVAL, "%s: output path too long", dir);
    s->names = names;
    s->active = 1;
    cur_set = s;
    return GW_OK;
}

int gw_outset_check_input(const char *dir, const char *const *names, const char *input, const char *what,
                          gw_err *err)
{
    struct stat in, st;
    if (!dir || !names || !input || !*input)
        return GW_OK;
    if (stat(input, &in) != 0) { /* a file still to make (wisdom): the same directory and name */
        char d[4096];
        if (gw_snprintf(d, sizeof d, "%s", input) >= (int)sizeof d)
            return GW_OK;
        const char *slash = strrchr(input, '/'), *base = slash ? slash + 1 : input;
        gw_path_parent(d);
        if (stat(d, &in) != 0 || stat(dir, &st) != 0 || in.st_dev != st.st_dev || in.st_ino != st.st_ino)
            return GW_OK;
        for (int k = 0; names[k]; k++)
            if (strcmp(base, names[k]) == 0)
                return gw_err_set(err, GW_EINVAL, "%s: '%s' is the file this run writes as %s/%s: give another "
                                  "--out or another name", what, input, dir, names[k]);
        return GW_OK;
    }
    for (int k = 0; names[k]; k++) {
        char p[4096 + 256];
        if (gw_snprintf(p, sizeof p, "%s/%s", dir, names[k]) < (int)sizeof p && stat(p, &st) == 0 &&
            st.st_dev == in.st_dev && st.st_ino == in.st_ino)
            return gw_err_set(err, GW_EINVAL, "%s: '%s' is the file this run writes as %s: give another --out "
                              "or move the input", what, input, p);
    }
    return GW_OK;
}

static void outset_close(gw_outset *s)
{
    for (int i = 0; i < s->n; i++) {
        free(s->tmp[i]);
        free(s->path[i]);
    }
    free(s->tmp);
    free(s->path);
    s->tmp = s->path = NULL;
    s->n = s->cap = 0;
    if (cur_set == s)
        cur_set = NULL;
    s->active = 0;
}

/* SIGINT, SIGTERM and SIGHUP held while the staged files are placed: an
 * interrupt then comes after the last rename, never between two */
static void outset_hold(gw_outset *s) { sig_hold(s->oldmask, &s->masked); }
static void outset_release(gw_outset *s) { sig_release(s->oldmask, &s->masked); }

void gw_outset_abort(gw_outset *s)
{
    if (!s)
        return;
    if (!s->active)
        return;
    outset_hold(s);
    for (int i = 0; i < s->n; i++)
        unlink(s->tmp[i]);
    outset_close(s);
    outset_release(s);
}

int gw_outset_commit(gw_outset *s, gw_err *err)
{
    if (!s)
        return gw_err_set(err, GW_EINVAL, "gw_outset_commit: s is NULL");
    if (!s->active)
        return gw_err_set(err, GW_EIO, "%s: no output set open", s->dir);
    int rc = GW_OK;
    outset_hold(s);
    /* two runs into one directory place their sets one after the other, never
     * file by file in turn: the directory holds the last one's files, all */
    int dfd = open(s->dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0)
        flock(dfd, LOCK_EX);
    /* what would stop a rename is found before any: nothing placed then */
    for (int i = 0; rc == GW_OK && i < s->n; i++) {
        struct stat st;
        if (access(s->tmp[i], F_OK) != 0) /* removed meanwhile */
            rc = gw_err_set(err, GW_EIO, "%s: write failed: its temporary %s is gone: %s", s->path[i], s->tmp[i],
                            strerror(errno));
        else if (lstat(s->path[i], &st) == 0 && S_ISDIR(st.st_mode))
            rc = gw_err_set(err, GW_EIO, "%s: write failed: %s", s->path[i], strerror(EISDIR));
    }
    for (int i = 0; rc == GW_OK && i < s->n; i++)
        if (rename(s->tmp[i], s->path[i]) != 0)
            rc = gw_err_set(err, GW_EIO, "%s: write failed: %s", s->path[i], strerror(errno));
    /* an earlier run's file of this set that this run did not write */
    for (int k = 0; rc == GW_OK && s->names && s->names[k]; k++) {
        char p[4096 + 256];
        if (gw_snprintf(p, sizeof p, "%s/%s", s->dir, s->names[k]) >= (int)sizeof p)
            continue;
        struct stat a, b;
        if (lstat(p, &a) != 0)
            continue;
        /* a symbolic link there was written through (gw_afile_open): it is
         * this run's when it leads to a file staged, and stays */
        if (S_ISLNK(a.st_mode) && stat(p, &b) == 0)
            a = b;
        int mine = 0; /* the same file as one staged (whatever the spelling of its path) */
        for (int j = 0; j < s->n && !mine; j++)
            mine = lstat(s->path[j], &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
        if (!mine && unlink(p) != 0 && errno != ENOENT)
            rc = gw_err_set(err, GW_EIO, "%s: cannot remove the earlier run's file: %s", p, strerror(errno));
    }
    if (rc != GW_OK) /* what is not in place is removed (a placed file's temporary name is gone) */
        for (int i = 0; i < s->n; i++)
            unlink(s->tmp[i]);
    if (dfd >= 0)
        close(dfd); /* and its lock */
    outset_close(s);
    outset_release(s);
    return rc;
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

/* gw_mkdir_p's failure: the directories it made (those of buf's components
 * that end in [first, stop)) removed again, deepest first, so that a refused
 * run leaves nothing behind */
static void remove_made(char *buf, size_t first, size_t stop)
{
    if (!first)
        return;
    for (size_t i = stop; i-- > first;)
        if (buf[i] == '/' || buf[i] == '\0') {
            char c = buf[i];
            buf[i] = '\0';
            rmdir(buf);
            buf[i] = c;
        }
}

int gw_mkdir_p(const char *path, gw_err *err)
{
    if (!path)
        return gw_err_set(err, GW_EINVAL, "gw_mkdir_p: path is NULL");
    char buf[4096];
    size_t n = strlen(path);
    if (n == 0 || n >= sizeof buf)
        return gw_err_set(err, GW_EINVAL, "output directory: bad path '%s'", path);
    memcpy(buf, path, n + 1);
    size_t first = 0; /* the end of the first component made here (0: none) */
    for (size_t i = 1; i <= n; i++) {
        if (buf[i] == '/' || buf[i] == '\0') {
            char c = buf[i];
            buf[i] = '\0';
            if (mkdir(buf, 0777) == 0) { /* less the umask, as mkdir -p */
                if (!first)
                    first = i;
            } else if (errno != EEXIST) {
                int e = errno;
                gw_err_set(err, GW_EIO, "%s: cannot create directory: %s", buf, strerror(e));
                remove_made(buf, first, i);
                return GW_EIO;
            }
            buf[i] = c;
        }
    }
    /* what is there instead of a directory, by name: a file, a symbolic link
     * to nothing or a loop of links were all "X: not a directory" */
    struct stat st;
    if (stat(path, &st) != 0) {
        int e = errno;
        if (lstat(path, &st) == 0 && S_ISLNK(st.st_mode))
            return link_refused(path, "output directory", e, err);
        return gw_err_set(err, GW_EINVAL, "output directory: '%s': %s", path, strerror(e));
    }
    if (!S_ISDIR(st.st_mode))
        return gw_err_set(err, GW_EINVAL, "output directory: '%s' exists and is not a directory", path);
    /* made under a umask that leaves its owner no write or search permission
     * (umask 0300 and up): nothing could go into it. Removed again, deepest
     * first, so that a refused run leaves nothing. */
    if (first && access(path, W_OK | X_OK) != 0 && errno == EACCES) {
        mode_t mask = 0777 & ~(st.st_mode & 0777);
        remove_made(buf, first, n + 1);
        return gw_err_set(err, GW_EINVAL, "%s: the directory made under umask %04o cannot be written into "
                          "(its owner needs write and search permission: umask 077 or less)", path,
                          (unsigned)mask);
    }
    return GW_OK;
}

int gw_path_join(char *buf, size_t n, const char *dir, const char *name)
{
    int w = gw_snprintf(buf, n, "%s/%s", dir, name);
    return (w < 0 || (size_t)w >= n) ? GW_EINVAL : GW_OK;
}

void gw_path_parent(char *buf)
{
    if (!buf)
        return;
    char *slash = strrchr(buf, '/');
    if (!slash)
        buf[0] = '.', buf[1] = '\0';
    else if (slash == buf)
        buf[1] = '\0';
    else
        *slash = '\0';
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

double gw_clock_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

static const char *file_kind(mode_t m)
{
    return S_ISFIFO(m) ? "a FIFO" : S_ISCHR(m) ? "a character device" : S_ISBLK(m) ? "a block device"
         : S_ISDIR(m) ? "a directory" : S_ISSOCK(m) ? "a socket" : "not a regular file";
}

int gw_input_open(const char *path, const char *what, FILE **out, gw_err *err)
{
    *out = NULL;
    if (!path || !*path)
        return gw_err_set(err, GW_EINVAL, "%s: empty file name", what);
    /* O_NONBLOCK: opening a FIFO without a writer would block until one comes */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) {
        int e = errno;
        return gw_err_set(err, io_status(e), "%s: %s: cannot open: %s", what, path, strerror(e));
    }
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return gw_err_set(err, GW_EIO, "%s: %s: cannot read: %s", what, path, strerror(e));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return gw_err_set(err, GW_EINVAL, "%s: %s is %s; give a regular file", what, path,
                          file_kind(st.st_mode));
    }
    int fl = fcntl(fd, F_GETFL);
    if (fl != -1)
        fcntl(fd, F_SETFL, fl & ~O_NONBLOCK);
    FILE *fp = fdopen(fd, "rb");
    if (!fp) {
        int e = errno;
        close(fd);
        return gw_err_set(err, io_status(e), "%s: %s: cannot open: %s", what, path, strerror(e));
    }
    *out = fp;
    return GW_OK;
}

int gw_input_check(const char *path, const char *what, gw_err *err)
{
    FILE *fp = NULL;
    int rc = gw_input_open(path, what, &fp, err);
    if (fp)
        fclose(fp);
    return rc;
}

int gw_input_read(const char *path, const char *what, size_t max, char **out, size_t *len,
                  gw_err *err)
{
    if (!out)
        return gw_err_set(err, GW_EINVAL, "gw_input_read: out is NULL");
    *out = NULL;
    if (len)
        *len = 0;
    FILE *fp = NULL;
    int rc = gw_input_open(path, what, &fp, err);
    if (rc != GW_OK)
        return rc;
    struct stat st;
    if (fstat(fileno(fp), &st) == 0 && (unsigned long long)st.st_size > (unsigned long long)max) {
        fclose(fp);
        return gw_err_set(err, GW_EINVAL, "%s: '%s' is larger than %zu bytes", what, path, max);
    }
    size_t cap = st.st_size > 0 ? (size_t)st.st_size + 1 : 4096, n = 0;
    char *buf = malloc(cap + 1);
    while (buf) {
        size_t got = fread(buf + n, 1, cap - n, fp);
        n += got;
        if (got == 0 || n > max)
            break;
        if (n == cap) { /* the file grew since fstat: read on, still bounded by max */
            char *nb = realloc(buf, 2 * cap + 1);
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
    }
    int bad = ferror(fp);
    fclose(fp);
    if (!buf)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory reading '%s'", what, path);
    if (bad || n > max) {
        free(buf);
        return n > max ? gw_err_set(err, GW_EINVAL, "%s: '%s' is larger than %zu bytes", what, path, max)
                       : gw_err_set(err, GW_EIO, "%s: cannot read '%s'", what, path);
    }
    buf[n] = '\0';
    *out = buf;
    if (len)
        *len = n;
    return GW_OK;
}

int gw_out_check(const char *dir, const char *what, gw_err *err)
{
    char buf[4096];
    size_t n = dir ? strlen(dir) : 0;
    if (n == 0 || n >= sizeof buf)
        return gw_err_set(err, GW_EINVAL, "%s: bad path '%s'", what, dir ? dir : "");
    memcpy(buf, dir, n + 1);
    struct stat st;
    int walked = 0;
    /* the directory, or else its nearest existing ancestor, must be a writable directory */
    for (;;) {
        if (stat(buf, &st) == 0) {
            if (!S_ISDIR(st.st_mode))
                return gw_err_set(err, GW_EINVAL, "%s: '%s' exists and is not a directory", what, buf);
            if (access(buf, W_OK | X_OK) != 0)
                return gw_err_set(err, GW_EINVAL, "%s: cannot write into '%s': %s", what, buf,
                                  strerror(errno));
            /* what the mode bits do not say (root under /proc, a read-only mount):
             * a directory made and removed at once where the run will make its own */
            char probe[4096 + 32];
            gw_snprintf(probe, sizeof probe, "%s/.granwave-probe-XXXXXX", buf);
            if (!mkdtemp(probe))
                return gw_err_set(err, GW_EINVAL, "%s: cannot write into '%s': %s", what, buf, strerror(errno));
            rmdir(probe);
            /* directories still to make: under a umask that takes the owner's
             * write or search permission (0300 and up) nothing could go into them */
            mode_t mask = walked && geteuid() != 0 ? current_umask() : 0; /* root writes anyway */
            if (mask & 0300)
                return gw_err_set(err, GW_EINVAL, "%s: '%s' would be made under umask %04o, which leaves no "
                                  "permission to write into it (umask 077 or less)", what, dir, (unsigned)mask);
            return GW_OK;
        }
        walked = 1;
        if (errno != ENOENT)
            return gw_err_set(err, GW_EINVAL, "%s: '%s': %s", what, buf, strerror(errno));
        /* a name that is a symbolic link to nothing is not a directory still to make:
         * mkdir would refuse it after the run, so refuse it now */
        if (lstat(buf, &st) == 0 && S_ISLNK(st.st_mode))
            return link_refused(buf, what, ENOENT, err);
        while (n > 1 && buf[n - 1] == '/')
            buf[--n] = '\0';
        gw_path_parent(buf);
        n = strlen(buf);
    }
}

int gw_out_file_check(const char *path, const char *what, gw_err *err)
{
    char dir[4096];
    size_t n = path ? strlen(path) : 0;
    if (n == 0 || n >= sizeof dir)
        return gw_err_set(err, GW_EINVAL, "%s: bad path '%s'", what, path ? path : "");
    struct stat st;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode))
        return gw_err_set(err, GW_EINVAL, "%s: '%s' is %s; give a regular file", what, path,
                          file_kind(st.st_mode));
    /* a symbolic link is written through (gw_afile_open): its target's
     * directory takes the temporary file; a link to nothing is refused */
    char target[4096];
    int rc = write_target(path, target, sizeof target, what, err);
    if (rc != GW_OK)
        return rc;
    path = target;
    n = strlen(path);
    memcpy(dir, path, n + 1);
    gw_path_parent(dir);
    /* a file is written into an existing directory (nothing makes its parents) */
    if (stat(dir, &st) != 0)
        return gw_err_set(err, GW_EINVAL, "%s: directory '%s' of '%s': %s", what, dir, path, strerror(errno));
    return gw_out_check(dir, what, err);
}

unsigned long long gw_fnv1a64(unsigned long long h, const void *p, size_t n)
{
    if (!p)
        return h;
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++) {
        h ^= b[i];
        h *= 1099511628211ULL;
    }
    return h;
}

unsigned long long gw_case_config_hash(const char *model, int n, const char *const *names,
                                       const char *const *values)
{
    unsigned long long h = gw_fnv1a64(GW_FNV1A64_INIT, "model ", 6);
    h = gw_fnv1a64(gw_fnv1a64(h, model, strlen(model)), "\n", 1);
    for (int i = 0; i < n; i++) {
        h = gw_fnv1a64(gw_fnv1a64(h, names[i], strlen(names[i])), " = ", 3);
        h = gw_fnv1a64(gw_fnv1a64(h, values[i], strlen(values[i])), "\n", 1);
    }
    return h;
}

int gw_fnv1a64_parse(const char *p, size_t len, unsigned long long *h)
{
    if (len != 16)
        return 0;
    unsigned long long v = 0;
    for (size_t i = 0; i < 16; i++) {
        const char c = p[i];
        if (c >= '0' && c <= '9')
            v = v << 4 | (unsigned long long)(c - '0');
        else if (c >= 'a' && c <= 'f')
            v = v << 4 | (unsigned long long)(c - 'a' + 10);
        else
            return 0;
    }
    *h = v;
    return 1;
}

int gw_fnv1a64_stream(FILE *fp, unsigned long long *h)
{
    unsigned char buf[8192]; /* 64 KiB here overflowed a 64 KiB stack (ulimit -s 64) */
    size_t got;
    unsigned long long v = GW_FNV1A64_INIT;
    while ((got = fread(buf, 1, sizeof buf, fp)) > 0)
        v = gw_fnv1a64(v, buf, got);
    if (ferror(fp))
        return GW_EIO;
    *h = v;
    return GW_OK;
}

int gw_fnv1a64_file(const char *path, const char *what, unsigned long long *h, gw_err *err)
{
    FILE *fp = NULL;
    int rc = gw_input_open(path, what, &fp, err);
    if (rc != GW_OK)
        return rc;
    rc = gw_fnv1a64_stream(fp, h);
    fclose(fp);
    return rc == GW_OK ? GW_OK : gw_err_set(err, GW_EIO, "%s: %s: read failed", what, path);
}
