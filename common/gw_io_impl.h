/*
 * gw_io_impl.h (private to the library, not installed): what the parts of the
 * file layer share: the atomic file's (gw_io_afile.c) signal hold, symbolic
 * link target, umask and open status, used by the output sets
 * (gw_io_outset.c), the output locations' checks (gw_io_paths.c) and the
 * inputs (gw_io_input.c); the inputs' file kind, used by the checks; the
 * open set's staging of a committed file (gw_io_outset.c); and the table of
 * temporaries a signal handler removes (gw_io_temps.c); and the refusal of
 * an input that grew while it was read (gw_io_grew), which the text sample
 * reader (layer_sample.c) shares.
 */
#ifndef GW_IO_IMPL_H
#define GW_IO_IMPL_H

#include <sys/types.h>

#include "gw_common.h"

/* The signals whose default action ends the process and that a user or the
 * system sends a run (the terminal's, kill's, timers', the CPU limit's):
 * SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM,
 * SIGPROF and SIGXCPU, *n of them. The file layer holds them while it
 * places files (gw_io_sig_hold) and gw_temps_on_signals handles them. Before
 * the fifty-first pass this was SIGINT, SIGTERM and SIGHUP alone: `kill
 * -USR1` or SIGALRM left layer-impact's staged snapshot_0.vtk.tmp.HOST.PID.X
 * and the --out it had made. */
const int *gw_io_end_signals(size_t *n);

/* The signals of gw_io_end_signals held on this thread (the mask before in old, a
 * sigset_t; *masked set when it was), and given back. */
void gw_io_sig_hold(unsigned char *old, int *masked);
void gw_io_sig_release(unsigned char *old, int *masked);

/* GW_EINVAL for the symbolic link path whose target cannot be used (e: the
 * errno of resolving it; ENOENT: it leads to nothing), naming the target. */
int gw_io_link_refused(const char *path, const char *what, int e, gw_err *err);

/* GW_EINVAL when dir names the file system's root directory, by any
 * spelling ("/", "//.", "/tmp/..", a link to it): a run's files would go
 * among the system's, and the set's commit would remove any of its names
 * the run did not write from "/" (chain --out / as root wrote chain.json
 * and its traces there). The one rule of every --out (gw_out_check) and of
 * every output set (gw_outset_begin); GW_OK otherwise (a dir not there). */
int gw_io_root_refused(const char *dir, const char *what, gw_err *err);

/* The file a write to path replaces (path, or a symbolic link's target) into
 * out (n bytes); GW_EINVAL for a link to nothing or a path too long. */
int gw_io_write_target(const char *path, char *out, size_t n, const char *what, gw_err *err);

/* path made absolute without changing what it names: its nearest existing
 * ancestor resolved (realpath), the names below it appended as written ("."
 * dropped, ".." taking one back), into out (n bytes); -1 when that fails
 * (too long, a loop of links, no permission). For comparing a path still to
 * be made with another. */
int gw_io_path_canon(const char *path, char *out, size_t n);

/* gw_out_file_check for a file the run writes once it has made its --out
 * directory out: path directly in out, which is still to make, passes when
 * its name does, is none of names (NULL-terminated, the run's own files in
 * out; NULL: none) and out could be made (gw_out_check); every other path is
 * gw_out_file_check's (out NULL: that alone). GW_EINVAL with one line naming
 * what. */
int gw_io_out_file_check_in(const char *path, const char *out, const char *const *names, const char *what,
                            gw_err *err);

/* What a write adds to a file's path for its temporary on this host and in
 * this process (gw_afile_open: ".tmp.HOST.PID.XXXXXX", HOST at most 24
 * characters): a path this much below PATH_MAX can be written; one nearer
 * failed at mkstemp, after the run's work. */
size_t gw_io_temp_suffix_len(void);

/* A name beside path of the temporaries' form ("PATH.tmp.HOST.PID.xxxxxx",
 * xxxxxx: seq in base 36), for a file the output set keeps aside while it is
 * placed (gw_io_outset.c): removed at the next write of path when a kill -9
 * left it, as a temporary is. The name may be taken (link(2) then says EEXIST:
 * try the next seq). 0, or -1 when it does not fit in n bytes. */
int gw_io_side_name(const char *path, unsigned long seq, char *out, size_t n);

/* The process's umask, read without changing it where the OS allows. */
mode_t gw_io_current_umask(void);

/* The status of a failed open of errno e: GW_ENOMEM or GW_EIO. */
int gw_io_status(int e);

/* What a file of mode m is, for a message ("a FIFO", "a directory", ...). */
const char *gw_io_file_kind(mode_t m);

/* The refusal (GW_EINVAL) of an input path (what: its name in messages) that
 * gave more bytes than the size its fstat said at open (size): it grew while
 * it was read, or it is no file on disk (a /proc file says 0 bytes and gives
 * many: /proc/self/pagemap, 256 GiB, was read until memory ran out). The
 * readers of whole inputs (gw_input_read, gw_fnv1a64_file_max) read at most
 * size + 1 bytes. */
int gw_io_grew(const char *what, const char *path, unsigned long long size, gw_err *err);

/* gw_path_join with its refusal told (GW_EINVAL): an empty dir as
 * "WHAT: the directory is empty ('' names none; '.' is this one)", a path
 * that does not fit n as "DIR: path too long" (an empty dir given to the
 * journal, the sweep's table, the chain's traces and the statistics' files
 * was refused as "path too long"). what NULL: "dir". */
int gw_io_path_join(char *buf, size_t n, const char *dir, const char *name, const char *what, gw_err *err);

/* gw_fnv1a64_file_max going on from the hash h0 of what came before (its
 * bytes hashed after them): the sweep config's hash, which holds the bytes
 * of the files it names after their names. */
int gw_io_fnv1a64_file_from(unsigned long long h0, const char *path, const char *what, unsigned long long max,
                            int text, unsigned long long *h, gw_err *err);

/* gw_io_hash_memo.c: the content hashes of the files a pass reads again and
 * again (a sweep's sample, once for each of its cases), kept while each file
 * is, as stat says, the one that was hashed: its device, inode, size,
 * modification and status-change times (to the nanosecond) the same. A
 * write to the file changes its status-change time, which no call sets back
 * (touch -d sets the modification time and moves the status-change one to
 * now), and a file put in its place is another inode. A hash is kept only
 * when both times were older than GW_HASH_MEMO_SETTLE_S seconds when the
 * hash began (a file written within the clock's tick of the hash could be
 * written again in that tick with the times unchanged: it is hashed again at
 * each call until it is older) and when the file's stat was the same before
 * and after the hash (a file written while it was hashed). A file stamped by
 * a clock other than this machine's (a network file system's server) is
 * trusted as far as its times move on at each write. Not thread-safe: one
 * memo per pass. */
#define GW_HASH_MEMO_SETTLE_S 2
typedef struct gw_hash_memo {
    struct gw_hash_seen {
        char *path;
        dev_t dev;
        ino_t ino;
        long long size, mtime_s, mtime_ns, ctime_s, ctime_ns;
        unsigned long long hash;
    } *seen;
    long n, cap;
    long hashed; /* the hashes fn made through the memo (what the tests count) */
} gw_hash_memo;
/* The hash function a memo calls (a model's gw_sweep_input_rule: its
 * reader's rules and the hash in one pass). */
typedef int (*gw_hash_memo_fn)(const char *path, unsigned long long *h, gw_err *err);
/* path's hash into *h: the memo's when path is as stat saw it when the memo
 * kept it, else fn's (its status and message as fn set them; GW_OK kept when
 * it may be). m NULL: fn's, always. A memo that cannot grow (out of memory)
 * keeps nothing more: fn's hash is still given. */
int gw_io_hash_memo(gw_hash_memo *m, const char *path, gw_hash_memo_fn fn, unsigned long long *h, gw_err *err);
/* Frees what m keeps, and zeroes it (NULL: nothing). */
void gw_io_hash_memo_free(gw_hash_memo *m);

/* A temporary made (path) for gw_temps_remove to find until it is placed
 * or removed (gw_io_temps.c): the slot taken, or -1 when no slot could be
 * had (out of memory for a new block of the table; the caller then removes
 * the temporary and fails: a temporary a signal could not remove is never
 * kept); gw_temps_drop forgets it (by its path; nothing for a path not
 * there). A handler that interrupts an add
 * skips the slot (not yet filled: the temporary stays, as before), one that
 * interrupts a drop after the file's rename or unlink finds its name gone. */
int gw_temps_add(const char *path);
void gw_temps_drop(const char *path);
/* The same for a temporary in the directory dirfd (an output set's, held
 * open until the set closes; -1: none): the handler removes it by its last
 * name in dirfd (unlinkat), so it finds it in that directory wherever it was
 * moved, and removes nothing under the path, which may name another
 * directory by then. gw_temps_unbind: the temporaries still bound to dirfd
 * fall back to their paths (called before dirfd is closed). */
int gw_temps_add_at(const char *path, int dirfd);
void gw_temps_unbind(int dirfd);
/* The directory path, which this process made from made (a prefix of path
 * naming the shallowest directory it made), for gw_temps_remove to take back
 * after the temporaries: each directory from path up to made is removed if
 * empty, path only while it is the same directory (device and inode) as when
 * added. gw_temps_drop(path) forgets it. -1: not added (made not a prefix
 * of path, path not a directory, no slot). */
int gw_temps_add_dirs(const char *path, const char *made);
/* gw_mkdir_p(path), and into made (n bytes) the shallowest directory of path
 * that this call created ("" when path existed, or on a failure, which takes
 * back what it made), handed to the signal handler's table (gw_temps_add_dirs):
 * a run that then fails or is refused takes it back with gw_temps_unmake(path,
 * made), empty, where a bare gw_mkdir_p left it (chain, drop, dispersion,
 * falcon, wavespeed, softwall and layer-stats --out NEW, on a write that
 * failed: an empty NEW, up to three levels of them for --out NEW/a/b). */
int gw_mkdir_made(const char *path, char *made, size_t n, gw_err *err);
/* Forget path (gw_temps_drop) and remove now what the handler would: the
 * empty directories from path up to made. */
void gw_temps_unmake(const char *path, const char *made);

/* The placing of an output set (gw_outset_commit), a critical section for
 * the handler of gw_temps_on_signals: a signal that comes meanwhile, on any
 * thread, is recorded and not acted on, and the last placer's end sends it
 * again to the process (the handler then removes the temporaries and ends
 * it), once the set is wholly placed or wholly put back. begin: 0, or -1 when
 * the process is ending on a signal already (nothing may be placed then). */
int gw_temps_placing_begin(void);
void gw_temps_placing_end(void);

/* Keep f's fsynced temporary in the set open on this thread instead of
 * renaming it: 1 staged, 0 no set open, -1 out of memory. */
int gw_outset_stage(gw_afile *f);
/* An output set is open on this thread: 1, else 0 */
int gw_outset_active(void);
/* gw_afile.held for a file gw_afile_open made outside a set, in a directory
 * it holds itself (closed at the commit or abort); 1: the caller's
 * (gw_afile_openat) */
#define AFILE_OWN_DIR 2

/* The directory the set open on this thread holds, when the temporary tmp
 * just made (open as fd) is in it (the same file under its last name there),
 * for gw_temps_add_at; -1 otherwise (no set, a temporary beside a link's
 * target elsewhere, a directory moved before the temporary was made). */
int gw_outset_temp_dir(const char *tmp, int fd);

/* The rule for the names a run makes (gw_io_paths.c; gw_common.h, the output
 * checks): a component of path that does not exist yet and holds a control
 * character is refused, naming what. NULL: GW_OK. The checks of output
 * locations apply it before a run, and the writers at their open
 * (gw_afile_open, gw_afile_openat: the same rule for a C caller that writes
 * without the checks); _at: path relative to the directory at (AT_FDCWD: the
 * working directory). */
int gw_io_new_name_check(const char *path, const char *what, gw_err *err);
int gw_io_new_name_check_at(int at, const char *path, const char *what, gw_err *err);

#endif
