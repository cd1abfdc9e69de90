/*
 * gw_io_paths.c: output locations: directories made (gw_mkdir_p, and removed
 * again when the run is refused), paths joined and cut to their directory,
 * and the checks made before any work that a run's outputs can be written
 * where it was told (gw_out_check, gw_out_file_check: a writable directory or
 * one that can be made, a regular file or none, a symbolic link that leads
 * somewhere; gw_out_names_check: the files a run writes into its directory
 * are regular files or none). Separate from the writes themselves (gw_io_afile.c): these run
 * before a run, or make the place its files go.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gw_common.h"
#include "gw_locale.h"
#include "gw_io_impl.h"

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

/* GW_EINVAL when a component of path that does not exist is followed, later
 * in path, by "..": "o/../o2" with no o. mkdir -p makes o to walk through it
 * and leaves it behind (a stray empty directory, on success and on refusal);
 * the path names o2 only through a directory that is not there, so it is
 * refused before anything is made, naming what and the missing component. */
static int dotdot_after_missing(const char *path, const char *what, gw_err *err)
{
    char buf[4096];
    size_t n = strlen(path);
    if (n >= sizeof buf)
        return GW_OK; /* (the callers refuse it as too long) */
    memcpy(buf, path, n + 1);
    size_t missing = 0; /* the end of the first missing component (0: none yet) */
    for (size_t i = 0, start = 0; i <= n; i++) {
        if (buf[i] != '/' && buf[i] != '\0')
            continue;
        const size_t len = i - start;
        if (len == 2 && buf[start] == '.' && buf[start + 1] == '.' && missing) {
            buf[missing] = '\0';
            return gw_err_set(err, GW_EINVAL, "%s: '%s': '%s' does not exist and '..' follows it; give the path "
                              "without '..' after a directory still to make", what, path, buf);
        }
        if (!missing && len > 0 && !(len == 1 && buf[start] == '.')) {
            char c = buf[i];
            struct stat st;
            buf[i] = '\0';
            if (stat(buf, &st) != 0 && errno == ENOENT)
                missing = i;
            buf[i] = c;
        }
        start = i + 1;
    }
    return GW_OK;
}

/* a path empty, or of N bytes that its buffer of CAP cannot hold: refused
 * saying which, the reason before the path (a long path is cut in the middle
 * of the message; "bad path '...'" alone, its reason cut away, said nothing) */
static int path_length_refused(const char *what, const char *path, size_t n, size_t cap, gw_err *err)
{
    if (n == 0)
        return gw_err_set(err, GW_EINVAL, "%s: empty path", what);
    return gw_err_set(err, GW_EINVAL, "%s: the path is %zu bytes long, more than the %zu a path may hold: '%s'", what,
                      n, cap - 1, path);
}

/* The one rule for the names a run makes: no control character (a byte below
 * 0x20, such as a newline or ESC, or 0x7f). Such a name breaks every listing,
 * log and one-line message that shows it, and the pvd writer refuses it
 * (gw_layer_write_pvd); gw_out_file_check("/tmp/x\n") and layer-make --out
 * 'o<ESC>k.txt' wrote one (session 42). A component of path that holds one and
 * does not exist yet (the file, or a directory still to make) is refused,
 * naming what, the path and the byte; one that exists already (a directory
 * the user made) is written into, as before, its name quoted in messages and
 * headers. GW_OK otherwise. */
static long ctrl_byte(const char *s, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if ((unsigned char)s[i] < 0x20 || (unsigned char)s[i] == 0x7f)
            return (long)i;
    return -1;
}

int gw_io_new_name_check_at(int at, const char *path, const char *what, gw_err *err)
{
    if (!path)
        return GW_OK; /* (the callers refuse it) */
    what = what ? what : "output";
    const size_t n = strlen(path);
    char buf[4096];
    if (n >= sizeof buf || ctrl_byte(path, n) < 0)
        return GW_OK;
    memcpy(buf, path, n + 1);
    for (size_t i = 0, start = 0; i <= n; i++) {
        if (buf[i] != '/' && buf[i] != '\0')
            continue;
        const long b = ctrl_byte(buf + start, i - start);
        if (b >= 0) {
            char c = buf[i];
            struct stat st;
            buf[i] = '\0';
            const int there = fstatat(at, buf, &st, AT_SYMLINK_NOFOLLOW) == 0;
            buf[i] = c;
            if (!there)
                return gw_err_set(err, GW_EINVAL, "%s: '%s': the name it would make, '%.*s', holds a control "
                                  "character (byte 0x%02x at %ld of the path): give a name of printable characters",
                                  what, path, (int)(i - start), path + start,
                                  (unsigned)(unsigned char)buf[start + (size_t)b], (long)(start + (size_t)b) + 1);
        }
        start = i + 1;
    }
    return GW_OK;
}

int gw_io_new_name_check(const char *path, const char *what, gw_err *err)
{
    return gw_io_new_name_check_at(AT_FDCWD, path, what, err);
}

int gw_mkdir_p(const char *path, gw_err *err)
{
    if (!path)
        return gw_err_set(err, GW_EINVAL, "gw_mkdir_p: path is NULL");
    char buf[4096];
    size_t n = strlen(path);
    if (n == 0 || n >= sizeof buf)
        return path_length_refused("output directory", path, n, sizeof buf, err);
    if (dotdot_after_missing(path, "output directory", err) != GW_OK ||
        gw_io_new_name_check(path, "output directory", err) != GW_OK)
        return GW_EINVAL;
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
            return gw_io_link_refused(path, "output directory", e, err);
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

/* Into made: the shallowest directory of path (or path itself) that does not
 * exist yet, "" when path exists (or is too long to look at). */
static void first_missing(const char *path, char *made, size_t n)
{
    char p[4096];
    struct stat st;
    made[0] = '\0';
    if (gw_snprintf(p, sizeof p, "%s", path) >= (int)sizeof p)
        return;
    for (;;) {
        if (stat(p, &st) == 0)
            return;
        gw_snprintf(made, n, "%s", p);
        char *sl = strrchr(p, '/');
        while (sl && sl > p && sl[1] == '\0') { /* trailing slashes */
            *sl = '\0';
            sl = strrchr(p, '/');
        }
        if (!sl || sl == p)
            return;
        *sl = '\0';
    }
}

int gw_mkdir_made(const char *path, char *made, size_t n, gw_err *err)
{
    if (!made || n == 0)
        return gw_err_set(err, GW_EINVAL, "gw_mkdir_made: made is %s", made ? "empty" : "NULL");
    made[0] = '\0';
    if (!path)
        return gw_mkdir_p(path, err);
    first_missing(path, made, n);
    const int rc = gw_mkdir_p(path, err);
    if (rc != GW_OK)
        made[0] = '\0'; /* gw_mkdir_p took back what it made */
    else if (made[0])
        (void)gw_temps_add_dirs(path, made); /* no slot (out of memory): a signal leaves it */
    return rc;
}

int gw_path_join(char *buf, size_t n, const char *dir, const char *name)
{
    /* an empty dir is no directory: "" and "b" were joined as "/b", a file in
     * the root directory (gw_sweep_journal_open, gw_sweep_write_table,
     * gw_chain_trace_write and gw_stats_write_files build their paths here) */
    if (!buf || !dir || !name || !dir[0])
        return GW_EINVAL;
    int w = gw_snprintf(buf, n, "%s/%s", dir, name);
    return (w < 0 || (size_t)w >= n) ? GW_EINVAL : GW_OK;
}

int gw_io_path_join(char *buf, size_t n, const char *dir, const char *name, const char *what, gw_err *err)
{
    if (!what)
        what = "dir";
    if (dir && !dir[0])
        return gw_err_set(err, GW_EINVAL, "%s: the directory is empty ('' names none; '.' is this one)", what);
    if (gw_path_join(buf, n, dir, name) != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", dir ? dir : "(no directory)");
    return GW_OK;
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

int gw_io_root_refused(const char *dir, const char *what, gw_err *err)
{
    struct stat d, r;
    if (!dir || stat(dir, &d) != 0 || stat("/", &r) != 0 || d.st_dev != r.st_dev || d.st_ino != r.st_ino)
        return GW_OK;
    return gw_err_set(err, GW_EINVAL, "%s: '%s' is the file system's root directory: give a directory of the "
                      "run's own (its files would go among the system's)", what ? what : "output", dir);
}

/* gw_out_check, for a directory of the run's files (root_ok 0) or the
 * directory of one file named in full (root_ok 1: layer-make --out /s.txt is
 * that one file, not a set of the run's files in "/") */
static int out_dir_check(const char *dir, const char *what, int root_ok, gw_err *err)
{
    if (!what) /* (printed as "(null)") */
        what = "output";
    char buf[4096];
    size_t n = dir ? strlen(dir) : 0;
    if (n == 0 || n >= sizeof buf)
        return path_length_refused(what, dir, n, sizeof buf, err);
    if (dotdot_after_missing(dir, what, err) != GW_OK || gw_io_new_name_check(dir, what, err) != GW_OK ||
        (!root_ok && gw_io_root_refused(dir, what, err) != GW_OK))
        return GW_EINVAL;
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
            mode_t mask = walked && geteuid() != 0 ? gw_io_current_umask() : 0; /* root writes anyway */
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
            return gw_io_link_refused(buf, what, ENOENT, err);
        while (n > 1 && buf[n - 1] == '/')
            buf[--n] = '\0';
        gw_path_parent(buf);
        n = strlen(buf);
    }
}

int gw_out_check(const char *dir, const char *what, gw_err *err)
{
    return out_dir_check(dir, what, 0, err);
}

/* GW_EINVAL when target (the file path writes, gw_io_write_target) belongs to
 * another user in a sticky directory (/tmp): its rename then fails after the
 * run ("Operation not permitted", exit 1), in an output set after the set's
 * other files were placed */
static int sticky_refused(const char *path, const char *target, const char *what, gw_err *err)
{
    char d[4096];
    struct stat st, ds;
    const uid_t me = geteuid();
    if (me == 0 || stat(target, &st) != 0 || gw_snprintf(d, sizeof d, "%s", target) >= (int)sizeof d)
        return GW_OK;
    gw_path_parent(d);
    if (stat(d, &ds) == 0 && (ds.st_mode & S_ISVTX) && st.st_uid != me && ds.st_uid != me)
        return gw_err_set(err, GW_EINVAL, "%s: '%s' belongs to another user in the sticky directory '%s': this run "
                          "cannot replace it", what, path, d);
    return GW_OK;
}

/* GW_EINVAL when target (the file path writes) is the file the process's
 * standard output or standard error writes to (one inode; a link such as
 * /dev/stdout, /proc/self/fd/1 or a hard link leads there too): the run's
 * rename would replace it, and its summary and warnings, written after,
 * went to the replaced file and were lost with exit 0 (`chain --out d >
 * d/chain.json`, `layer-make --out /dev/stdout > s.txt`; the fifty-first
 * pass). A stream that is closed or no regular file is no such file. */
static int std_stream_refused(const char *path, const char *target, const char *what, gw_err *err)
{
    struct stat st, ss;
    if (stat(target, &st) != 0 || !S_ISREG(st.st_mode))
        return GW_OK;
    static const char *const names[] = {"standard output", "standard error"};
    for (int fd = 1; fd <= 2; fd++)
        if (fstat(fd, &ss) == 0 && S_ISREG(ss.st_mode) && ss.st_dev == st.st_dev && ss.st_ino == st.st_ino)
            return gw_err_set(err, GW_EINVAL, "%s: '%s' is the file this run's %s is written to: the run would "
                              "replace it, and what it prints there would be lost; give another file or send "
                              "the %s elsewhere", what, path, names[fd - 1], names[fd - 1]);
    return GW_OK;
}

static int temp_name_fits(const char *path, const char *dir, const char *what, gw_err *err);

int gw_out_file_check(const char *path, const char *what, gw_err *err)
{
    if (!what) /* (printed as "(null)") */
        what = "output";
    char dir[4096];
    size_t n = path ? strlen(path) : 0;
    if (n == 0 || n >= sizeof dir)
        return path_length_refused(what, path, n, sizeof dir, err);
    if (gw_io_new_name_check(path, what, err) != GW_OK)
        return GW_EINVAL;
    struct stat st;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode))
        return gw_err_set(err, GW_EINVAL, "%s: '%s' is %s; give a regular file", what, path,
                          gw_io_file_kind(st.st_mode));
    /* a symbolic link is written through (gw_afile_open): its target's
     * directory takes the temporary file; a link to nothing is refused */
    char target[4096];
    int rc = gw_io_write_target(path, target, sizeof target, what, err);
    if (rc == GW_OK)
        rc = sticky_refused(path, target, what, err);
    if (rc == GW_OK)
        rc = std_stream_refused(path, target, what, err);
    if (rc != GW_OK)
        return rc;
    path = target;
    n = strlen(path);
    memcpy(dir, path, n + 1);
    gw_path_parent(dir);
    /* a file is written into an existing directory (nothing makes its parents) */
    if (stat(dir, &st) != 0)
        return gw_err_set(err, GW_EINVAL, "%s: directory '%s' of '%s': %s", what, dir, path, strerror(errno));
    rc = out_dir_check(dir, what, 1, err);
    return rc == GW_OK ? temp_name_fits(path, dir, what, err) : rc;
}

/* A file written after the run has made its --out directory (dispersion
 * --wisdom od/w --out od, od not there yet): refused as "directory 'od' of
 * 'od/w': No such file or directory" before session 44, though the run makes
 * od before it writes the file. A path whose directory is missing and is out
 * itself (the same path once made, by gw_io_path_canon) is checked as far as
 * it can be before out is there: its name (no control byte; short enough,
 * with the temporary's suffix, for NAME_MAX and PATH_MAX) and out as
 * gw_out_check checks it, and not one of names (the files the run writes
 * into out: --wisdom od/dispersion.json --out od would overwrite the run's
 * own; gw_outset_check_input tells them by the directory's inode, which a
 * directory still to make has not). Any other path, and a directory that is
 * a symbolic link to nothing, as gw_out_file_check (a directory that exists
 * nowhere and is not out stays refused). */
int gw_io_out_file_check_in(const char *path, const char *out, const char *const *names, const char *what,
                            gw_err *err)
{
    char dir[4096], cd[4096], co[4096];
    const size_t n = path ? strlen(path) : 0;
    if (!out || !*out || n == 0 || n >= sizeof dir)
        return gw_out_file_check(path, what, err);
    memcpy(dir, path, n + 1);
    gw_path_parent(dir);
    struct stat st;
    if (stat(dir, &st) == 0 || errno != ENOENT || lstat(dir, &st) == 0 ||
        gw_io_path_canon(dir, cd, sizeof cd) != 0 || gw_io_path_canon(out, co, sizeof co) != 0 || strcmp(cd, co) != 0)
        return gw_out_file_check(path, what, err);
    what = what ? what : "output";
    const char *slash = strrchr(path, '/'), *base = slash ? slash + 1 : path;
    for (int k = 0; names && names[k]; k++)
        if (strcmp(base, names[k]) == 0)
            return gw_err_set(err, GW_EINVAL, "%s: '%s' is the file this run writes as %s/%s: give another --out or "
                              "another name", what, path, out, names[k]);
    if (gw_io_new_name_check(path, what, err) != GW_OK || out_dir_check(out, what, 0, err) != GW_OK)
        return GW_EINVAL;
    return temp_name_fits(path, dir, what, err);
}

/* path quoted for a one-line message: itself, or its first and last 48
 * characters around "..." (a path near PATH_MAX filled the message's 512
 * bytes and cut off the reason after it) */
static const char *path_cut(const char *path, char *buf, size_t n)
{
    const size_t len = strlen(path);
    if (len <= 100)
        return path;
    gw_snprintf(buf, n, "%.48s...%s", path, path + len - 48);
    return buf;
}

/* GW_EINVAL when file p (in dir), written under its temporary name
 * (gw_io_temp_suffix_len more), would reach PATH_MAX: mkstemp then failed
 * with ENAMETOOLONG after the run's work (exit 1, the directories made left
 * empty; chain --out with a path of 4060 characters, whose own length passed) */
static int temp_fits(const char *p, const char *dir, const char *name, const char *what, gw_err *err)
{
    const size_t len = strlen(p), more = gw_io_temp_suffix_len();
    if (len + more < PATH_MAX)
        return GW_OK;
    char cut[128];
    return gw_err_set(err, GW_EINVAL, "%s: '%s' (%zu characters) is too long a path for the run's files: %s, "
                      "written first as %s.tmp.HOST.PID.XXXXXX (%zu more characters), would exceed PATH_MAX "
                      "(%d); give a shorter path", what, path_cut(dir, cut, sizeof cut), strlen(dir), name, name,
                      more, (int)PATH_MAX);
}

/* GW_EINVAL when the file path (in dir), written under its temporary name,
 * would not fit: its last component with the temporary's suffix above the
 * directory's NAME_MAX, or the whole above PATH_MAX. Checked before the run:
 * dispersion --wisdom with a 240-character name ran, then said "cannot
 * create: File name too long" and saved nothing. */
static int temp_name_fits(const char *path, const char *dir, const char *what, gw_err *err)
{
    const char *slash = strrchr(path, '/'), *name = slash ? slash + 1 : path;
    const long max = pathconf(dir, _PC_NAME_MAX);
    const size_t len = strlen(name), more = gw_io_temp_suffix_len(), lim = max > 0 ? (size_t)max : 255;
    if (len + more > lim) {
        char cut[128];
        return gw_err_set(err, GW_EINVAL, "%s: '%s' (%zu characters) is too long a name: the file is written "
                          "first as NAME.tmp.HOST.PID.XXXXXX (%zu more characters), above the %zu its directory "
                          "takes; give a name of at most %zu characters", what, path_cut(name, cut, sizeof cut), len,
                          more, lim, lim > more ? lim - more : 0);
    }
    return temp_fits(path, dir, name, what, err);
}

int gw_out_names_check(const char *dir, const char *const *names, const char *what, gw_err *err)
{
    what = what ? what : "output"; /* as gw_out_check; "(null): ..." before session 34 */
    /* NULL was GW_OK: no directory and no list checked nothing (session 42) */
    if (!dir || !names)
        return gw_err_set(err, GW_EINVAL, "gw_out_names_check: %s is NULL", !dir ? "dir" : "names");
    for (int k = 0; names[k]; k++) {
        char p[4096 + 256], target[4096];
        struct stat st;
        /* a plain file name, in dir: "a/../b", "..", "" or "x/y" named a file
         * elsewhere, or dir itself, and passed (session 42) */
        if (!*names[k] || strchr(names[k], '/') || strcmp(names[k], ".") == 0 || strcmp(names[k], "..") == 0)
            return gw_err_set(err, GW_EINVAL, "%s: names[%d] '%s' is not a plain file name (no '/', not '', '.' "
                              "or '..')", what, k, names[k]);
        if (gw_snprintf(p, sizeof p, "%s/%s", dir, names[k]) >= (int)sizeof p) {
            char cut[128];
            return gw_err_set(err, GW_EINVAL, "%s: '%s' (%zu characters): path too long for %s", what,
                              path_cut(dir, cut, sizeof cut), strlen(dir), names[k]);
        }
        if (temp_fits(p, dir, names[k], what, err) != GW_OK || gw_io_new_name_check(p, what, err) != GW_OK)
            return GW_EINVAL;
        if (lstat(p, &st) != 0) /* nothing there (or no directory yet): the run makes it */
            continue;
        int rc = gw_io_write_target(p, target, sizeof target, what, err);
        if (rc != GW_OK)
            return rc;
        /* a link: the temporary goes beside its target */
        if (strcmp(target, p) != 0 && temp_fits(target, p, names[k], what, err) != GW_OK)
            return GW_EINVAL;
        if ((rc = sticky_refused(p, target, what, err)) != GW_OK ||
            (rc = std_stream_refused(p, target, what, err)) != GW_OK)
            return rc;
    }
    return GW_OK;
}

int gw_io_path_canon(const char *path, char *out, size_t n)
{
    char buf[4096], rest[4096] = "", real[PATH_MAX];
    size_t len = path ? strlen(path) : 0;
    if (len == 0 || len >= sizeof buf)
        return -1;
    memcpy(buf, path, len + 1);
    /* the nearest existing ancestor resolved; the names below it kept as written */
    while (!realpath(buf, real)) {
        if (errno != ENOENT)
            return -1;
        while (len > 1 && buf[len - 1] == '/')
            buf[--len] = '\0';
        const char *slash = strrchr(buf, '/'), *base = slash ? slash + 1 : buf;
        char tmp[4096];
        if (gw_snprintf(tmp, sizeof tmp, "%s%s%s", base, *rest ? "/" : "", rest) >= (int)sizeof tmp)
            return -1;
        memcpy(rest, tmp, strlen(tmp) + 1);
        gw_path_parent(buf);
        len = strlen(buf);
    }
    if (gw_snprintf(out, n, "%s", strcmp(real, "/") == 0 ? "" : real) >= (int)n)
        return -1;
    char *save = NULL;
    for (char *c = strtok_r(rest, "/", &save); c; c = strtok_r(NULL, "/", &save)) {
        size_t k = strlen(out);
        if (strcmp(c, ".") == 0)
            continue;
        if (strcmp(c, "..") == 0) {
            char *s = strrchr(out, '/');
            if (s)
                *s = '\0';
            continue;
        }
        if (gw_snprintf(out + k, n - k, "/%s", c) >= (int)(n - k))
            return -1;
    }
    if (!*out)
        gw_snprintf(out, n, "/");
    return 0;
}
