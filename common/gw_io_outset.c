/*
 * gw_io_outset.c: output sets: the files a command writes into its --out
 * directory, committed together. While a set is open on a thread, each atomic
 * file (gw_io_afile.c) it commits is staged under its temporary name; the
 * set's commit renames them all into place under a lock on the directory and
 * removes the earlier run's files of the set this run did not write, all or
 * nothing (the earlier files kept aside until the set is in place, and put
 * back when a step fails); its abort removes the staged temporaries. The staged temporaries stay in the table a
 * signal handler empties (gw_io_temps.c) until they are placed or removed, so
 * a program ended by SIGINT before its commit leaves --out as it was.
 * Separate from the atomic file: one file needs no set, and a set outlives
 * its files.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gw_common.h"
#include "gw_locale.h"
#include "gw_io_impl.h"

_Static_assert(sizeof(sigset_t) <= sizeof(((gw_outset *)0)->oldmask), "sigset_t does not fit");

/* The output set open on this thread (gw_outset_begin), or NULL. */
static _Thread_local gw_outset *cur_set;

/* The directory the open set was begun in, held open: its temporaries are
 * made there by name (gw_afile_open), so when --out is moved, removed or
 * replaced while the run goes on (mv D D.old; mkdir D, or a link), they are
 * in a directory the set's path no longer names. Before, the commit said
 * "its temporary ... is gone" and the abort, removing by name, left them in
 * D.old. The commit now says what happened, and the temporaries are removed
 * through this handle too, by the signal handler as well (each is bound to it
 * in the handler's table: gw_outset_temp_dir, gw_temps_add_at). Kept per
 * thread beside cur_set (the gw_outset struct is the caller's, its layout
 * public). -1: none (no directory yet: opened at the set's first file). */
static _Thread_local int cur_dirfd = -1;

/* What the set's --out path names now is the directory it was begun in:
 * 1, or 0 (moved, removed or replaced meanwhile), or 1 when it cannot tell
 * (no directory held: none at the begin nor at the first file). */
static int same_dir(const gw_outset *s)
{
    struct stat a, b;
    if (cur_set != s || cur_dirfd < 0 || fstat(cur_dirfd, &a) != 0)
        return 1;
    return stat(s->dir, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

/* A staged temporary removed: by name, and by its own name in the directory
 * the set was begun in, wherever that went (a name of the temporaries' form,
 * with this host, process and 6 random characters: no other file has it; a
 * temporary made beside a link's target elsewhere is simply not there) */
static void remove_temp(const gw_outset *s, const char *tmp)
{
    unlink(tmp);
    const char *slash = strrchr(tmp, '/');
    if (cur_set == s && cur_dirfd >= 0)
        unlinkat(cur_dirfd, slash ? slash + 1 : tmp, 0);
}

int gw_outset_active(void) { return cur_set != NULL; }

int gw_outset_temp_dir(const char *tmp, int fd)
{
    if (!cur_set || !tmp || fd < 0)
        return -1;
    if (cur_dirfd < 0) /* the directory made since the begin (falcon, wavespeed): held from its first file */
        cur_dirfd = open(cur_set->dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    const char *slash = strrchr(tmp, '/');
    struct stat a, b;
    if (cur_dirfd < 0 || fstat(fd, &a) != 0 ||
        fstatat(cur_dirfd, slash ? slash + 1 : tmp, &b, AT_SYMLINK_NOFOLLOW) != 0 || a.st_dev != b.st_dev ||
        a.st_ino != b.st_ino)
        return -1;
    return cur_dirfd;
}

/* Keep f's fsynced temporary in the open set instead of renaming it: 1 staged,
 * 0 no set open, -1 out of memory (the temporary is then removed). */
int gw_outset_stage(gw_afile *f)
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

int gw_outset_begin(gw_outset *s, const char *dir, const char *const *names, gw_err *err)
{
    if (!s || !dir || !names)
        return gw_err_set(err, GW_EINVAL, "gw_outset_begin: %s is NULL", !s ? "s" : !dir ? "dir" : "names");
    /* s open already: refused untouched (it was zeroed first, which lost its
     * staged files and left this thread's set pointing at a closed struct:
     * every later begin on the thread was refused, every commit said "no
     * output set open") */
    if (cur_set == s)
        return gw_err_set(err, GW_EINVAL, "gw_outset_begin: s is the output set open on this thread (in %s): "
                          "commit or abort it first", s->dir);
    memset(s, 0, sizeof *s);
    /* "" is no directory: the commit's paths "DIR/NAME" were "/NAME", and it
     * removed the set's names not written from the root directory */
    if (!dir[0])
        return gw_err_set(err, GW_EINVAL, "gw_outset_begin: dir is empty (give a directory, \".\" for the working "
                          "one)");
    /* each name one file of dir: the commit removes every name of the list
     * the run did not write, and "../x" removed a file beside dir ("" and "."
     * named dir itself) */
    for (int k = 0; names[k]; k++)
        if (!names[k][0] || strchr(names[k], '/') || strcmp(names[k], ".") == 0 || strcmp(names[k], "..") == 0)
            return gw_err_set(err, GW_EINVAL, "gw_outset_begin: name %d '%s' is not a file name in %s", k, names[k],
                              dir);
    if (cur_set)
        return gw_err_set(err, GW_EINVAL, "%s: an output set is already open on this thread", dir);
    if (gw_io_root_refused(dir, "gw_outset_begin: dir", err) != GW_OK)
        return GW_EINVAL;
    if (gw_snprintf(s->dir, sizeof s->dir, "%s", dir) >= (int)sizeof s->dir)
        return gw_err_set(err, GW_EINVAL, "%s: output path too long", dir);
    s->names = names;
    s->active = 1;
    cur_set = s;
    cur_dirfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC); /* -1 when it is still to be made */
    return GW_OK;
}

int gw_outset_check_input(const char *dir, const char *const *names, const char *input, const char *what,
                          gw_err *err)
{
    struct stat in, st;
    /* dir and names are the set's: NULL is a caller's error, refused naming
     * it (GW_OK before session 43, as if nothing were written); input NULL
     * or "" is a command without that input (no --wisdom, no --sample) */
    if (!dir || !names)
        return gw_err_set(err, GW_EINVAL, "gw_outset_check_input: %s is NULL", !dir ? "dir" : "names");
    if (!input || !*input)
        return GW_OK;
    what = what ? what : "input"; /* as gw_input_check; "(null): ..." before session 34 */
    if (stat(input, &in) != 0) { /* a file still to make (wisdom): the same directory and name */
        char d[4096];
        if (gw_snprintf(d, sizeof d, "%s", input) >= (int)sizeof d)
            return GW_OK;
        const char *slash = strrchr(input, '/'), *base = slash ? slash + 1 : input;
        gw_path_parent(d);
        /* nor the directory the run makes, or one above it (dispersion --wisdom
         * W --out W: the run made W a directory, then could not save W) */
        char ci[4096], cd[4096];
        if (gw_io_path_canon(input, ci, sizeof ci) == 0 && gw_io_path_canon(dir, cd, sizeof cd) == 0) {
            size_t k = strlen(ci);
            if (strncmp(cd, ci, k) == 0 && (cd[k] == '\0' || cd[k] == '/' || strcmp(ci, "/") == 0))
                return gw_err_set(err, GW_EINVAL, "%s: '%s' is %s the run makes for --out '%s': give another "
                                  "--out or another name", what, input, cd[k] ? "a directory above the one" :
                                  "the directory", dir);
        }
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
    if (cur_set == s) {
        cur_set = NULL;
        gw_temps_unbind(cur_dirfd); /* a file still open in the set: by its path from here */
        if (cur_dirfd >= 0)
            close(cur_dirfd);
        cur_dirfd = -1;
    }
    s->active = 0;
}

/* SIGINT, SIGTERM and SIGHUP held on this thread while the staged files are
 * placed: an interrupt then comes after the last rename, never between two.
 * Another thread may take them meanwhile: the placing is also a critical
 * section for the handler (gw_temps_placing_begin) */
static void outset_hold(gw_outset *s) { gw_io_sig_hold(s->oldmask, &s->masked); }
static void outset_release(gw_outset *s) { gw_io_sig_release(s->oldmask, &s->masked); }

void gw_outset_abort(gw_outset *s)
{
    /* only the set open on this thread: a struct never begun, closed, or
     * garbage (a refused begin's) is left alone without reading it */
    if (!s || s != cur_set || !s->active)
        return;
    outset_hold(s);
    for (int i = 0; i < s->n; i++) {
        remove_temp(s, s->tmp[i]);
        gw_temps_drop(s->tmp[i]);
    }
    outset_close(s);
    outset_release(s);
}

/* What placing the set did to one name, to be undone when a later step fails:
 * the earlier file kept aside under a side name (gw_io_side_name), by a hard
 * link (it stays in place for readers meanwhile) or, where no hard link can
 * be made (a file system without them; Linux's protected_hardlinks for a
 * file of another user), by a rename; and whether the staged file was
 * renamed into place. */
enum { ASIDE_NONE, ASIDE_LINK, ASIDE_MOVED };
typedef struct aside {
    const char *path; /* the name in --out */
    char *bak;        /* the earlier file's side name (how != ASIDE_NONE) */
    int how, placed;
    dev_t dev;        /* the file placed (placed): the names not written are told from it */
    ino_t ino;
} aside;

/* The earlier file at a->path (if any) kept aside: by a hard link when link
 * is set and the file system allows it, else by a rename (the name is then
 * free). 0 (a->how ASIDE_NONE when nothing is there), or the errno of the
 * failure (an immutable or append-only file, chattr +i / +a: EPERM; ENOMEM;
 * ENAMETOOLONG); nothing is kept aside then. */
static int keep_aside(aside *a, int link_first, unsigned long *seq)
{
    struct stat st;
    a->how = ASIDE_NONE;
    if (lstat(a->path, &st) != 0)
        return 0; /* nothing there (or what is there the rename will tell) */
    char name[4096 + 128];
    int e = EEXIST;
    for (int tries = 0; tries < 64 && a->how == ASIDE_NONE; tries++) {
        if (gw_io_side_name(a->path, (*seq)++, name, sizeof name) != 0)
            return ENAMETOOLONG;
        if (link_first && link(a->path, name) == 0)
            a->how = ASIDE_LINK;
        else if (link_first && errno == EEXIST)
            continue;
        /* rename would replace a file of that name: only onto a free one (the
         * names carry this process's id: no other process makes them) */
        else if (lstat(name, &st) == 0)
            continue;
        else if (rename(a->path, name) == 0)
            a->how = ASIDE_MOVED;
        else
            return errno;
    }
    if (a->how == ASIDE_NONE)
        return e;
    if (!(a->bak = strdup(name))) {
        if (a->how == ASIDE_LINK ? unlink(name) : rename(name, a->path)) { /* the name stays: removed next run */ }
        a->how = ASIDE_NONE;
        return ENOMEM;
    }
    return 0;
}

/* After a failed step: what the set did put back as it was, the last step
 * first (a name renamed into place twice comes back to the earliest file).
 * A name that cannot be put back is added to err's message, its earlier file
 * then left under its side name. */
static void undo(aside *a, int n, aside *rm, int nrm, gw_err *err)
{
    for (int k = nrm + n; k-- > 0;) {
        aside *x = k >= n ? &rm[k - n] : &a[k];
        const int restore = x->how == ASIDE_MOVED || (x->placed && x->how == ASIDE_LINK);
        int r = 0;
        if (restore)
            r = rename(x->bak, x->path);
        else if (x->placed) /* no earlier file: the new one goes */
            r = unlink(x->path);
        else if (x->how == ASIDE_LINK) /* still in place: only its second name goes */
            r = unlink(x->bak);
        if (r != 0) {
            const int e = errno;
            char first[sizeof err->msg];
            gw_snprintf(first, sizeof first, "%s", err->msg);
            if (restore)
                gw_err_set(err, GW_EIO, "%s; %s could not be put back (%s): the earlier file is %s", first, x->path,
                           strerror(e), x->bak);
            else if (x->placed)
                gw_err_set(err, GW_EIO, "%s; the new %s could not be removed: %s", first, x->path, strerror(e));
        }
        if (r == 0 || restore)
            x->how = ASIDE_NONE; /* nothing aside left to remove (or the only copy, kept) */
    }
}

int gw_outset_commit(gw_outset *s, gw_err *err)
{
    if (!s)
        return gw_err_set(err, GW_EINVAL, "gw_outset_commit: s is NULL");
    if (s != cur_set || !s->active) /* s->dir is read only for the set open here (a 0xff struct: no NUL) */
        return gw_err_set(err, GW_EIO, "gw_outset_commit: s is no output set open on this thread (begun and "
                          "not yet committed or aborted)");
    int rc = GW_OK;
    gw_err own = {{0}};
    if (!err) /* undo adds to the message */
        err = &own;
    outset_hold(s);
    /* two runs into one directory place their sets one after the other, never
     * file by file in turn: the directory holds the last one's files, all */
    int dfd = open(s->dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0)
        flock(dfd, LOCK_EX);
    /* from here a signal another thread takes waits for the set
     * (gw_io_temps.c); not while the lock is awaited: another run may hold it */
    const int placing = gw_temps_placing_begin() == 0;
    if (!placing)
        rc = gw_err_set(err, GW_EIO, "%s: the output files were not placed: the program is ending on a signal",
                        s->dir);
    /* what would stop a rename is found before any: nothing placed then */
    if (rc == GW_OK && s->n > 0 && !same_dir(s))
        rc = gw_err_set(err, GW_EIO, "%s: the output directory was moved, removed or replaced while the run went "
                        "on: nothing placed (its files were made in the directory it named when the run began)",
                        s->dir);
    for (int i = 0; rc == GW_OK && i < s->n; i++) {
        struct stat st;
        if (access(s->tmp[i], F_OK) != 0) /* removed meanwhile */
            rc = gw_err_set(err, GW_EIO, "%s: write failed: its temporary %s is gone: %s", s->path[i], s->tmp[i],
                            strerror(errno));
        else if (lstat(s->path[i], &st) == 0 && S_ISDIR(st.st_mode))
            rc = gw_err_set(err, GW_EIO, "%s: write failed: %s", s->path[i], strerror(EISDIR));
    }
    /* All or nothing, as far as POSIX allows: every earlier file this set
     * replaces or removes is kept aside first, and a rename that fails
     * part-way (an immutable file, a name made a directory meanwhile, an I/O
     * error) puts back the earlier files, removes the new ones and the
     * temporaries, and says which file and why. Before, the files renamed
     * before the failing one stayed: --out held a mix of two runs. */
    int nn = 0;
    while (s->names && s->names[nn])
        nn++;
    aside *a = rc == GW_OK ? calloc((size_t)s->n + (size_t)nn + 1, sizeof *a) : NULL, *rm = a ? a + s->n : NULL;
    int nrm = 0;
    char (*rmpath)[4096 + 256] = rc == GW_OK && a && nn ? calloc((size_t)nn, sizeof *rmpath) : NULL;
    if (rc == GW_OK && (!a || (nn && !rmpath)))
        rc = gw_err_set(err, GW_ENOMEM, "%s: out of memory placing the output files", s->dir);
    unsigned long seq = 0;
    for (int i = 0; rc == GW_OK && i < s->n; i++) {
        a[i].path = s->path[i];
        const int e = keep_aside(&a[i], 1, &seq);
        if (e)
            rc = gw_err_set(err, gw_io_status(e), "%s: write failed: the earlier file cannot be replaced: %s",
                            s->path[i], strerror(e));
    }
    for (int i = 0; rc == GW_OK && i < s->n; i++) {
        if (rename(s->tmp[i], s->path[i]) != 0)
            rc = gw_err_set(err, GW_EIO, "%s: write failed: %s", s->path[i], strerror(errno));
        else
            a[i].placed = 1;
    }
    for (int i = 0; rc == GW_OK && i < s->n; i++) { /* once each (an lstat per name and file was n^2 calls) */
        struct stat st;
        const int got = lstat(s->path[i], &st) == 0;
        a[i].dev = got ? st.st_dev : 0;
        a[i].ino = got ? st.st_ino : 0;
    }
    /* an earlier run's file of this set that this run did not write: moved
     * aside, and removed once the set is in place */
    for (int k = 0; rc == GW_OK && k < nn; k++) {
        char *p = rmpath[k];
        if (gw_snprintf(p, sizeof rmpath[k], "%s/%s", s->dir, s->names[k]) >= (int)sizeof rmpath[k])
            continue;
        struct stat sa, sb;
        if (lstat(p, &sa) != 0)
            continue;
        /* a symbolic link there was written through (gw_afile_open): it is
         * this run's when it leads to a file staged, and stays */
        if (S_ISLNK(sa.st_mode) && stat(p, &sb) == 0)
            sa = sb;
        int mine = 0; /* the same file as one staged (whatever the spelling of its path) */
        for (int j = 0; j < s->n && !mine; j++)
            mine = a[j].ino != 0 && sa.st_dev == a[j].dev && sa.st_ino == a[j].ino;
        if (mine)
            continue;
        rm[nrm].path = p;
        const int e = keep_aside(&rm[nrm++], 0, &seq);
        if (e)
            rc = gw_err_set(err, gw_io_status(e), "%s: cannot remove the earlier run's file: %s", p, strerror(e));
    }
    if (rc != GW_OK && a)
        undo(a, s->n, rm, nrm, err);
    for (int k = 0; a && k < s->n + nrm; k++) { /* placed, or put back: the side names go */
        if (a[k].how != ASIDE_NONE)
            unlink(a[k].bak);
        free(a[k].bak);
    }
    free(a);
    free(rmpath);
    if (rc != GW_OK) /* what is not in place is removed (a placed file's temporary name is gone) */
        for (int i = 0; i < s->n; i++)
            remove_temp(s, s->tmp[i]);
    for (int i = 0; i < s->n; i++) /* placed or removed: nothing for a signal to remove */
        gw_temps_drop(s->tmp[i]);
    if (dfd >= 0)
        close(dfd); /* and its lock */
    outset_close(s);
    outset_release(s);
    if (placing) /* the signal that came meanwhile, if any, ends the program now */
        gw_temps_placing_end();
    return rc;
}
