/*
 * gw_common.h: status codes, error text, input validation, atomic files, CSV and
 * JSON output helpers, linear fits. Shared by every granwave module.
 *
 * Conventions: every fallible call returns an int status (GW_OK = 0, negative on
 * error). Calls that check user input also fill a gw_err with one line naming the
 * offending input; the program prints that line and exits with code 2.
 */
#ifndef GW_COMMON_H
#define GW_COMMON_H

#include <stddef.h>
#include <stdio.h>

#include <cjson/cJSON.h>

#include "gw_version.h"

#include "gw_api.h"

GW_BEGIN_DECLS /* the exported interface, C linkage (gw_api.h) */

enum {
    GW_OK = 0,
    GW_ROOT = 1,          /* not an error: the solver stopped at an event */
    GW_EINVAL = -1,       /* invalid argument or user input */
    GW_ENOMEM = -2,       /* allocation failed */
    GW_EIO = -3,          /* file could not be read or written */
    GW_ESOLVER = -4,      /* the ODE backend failed; message on the solver */
    GW_EFORMAT = -5,      /* malformed input file */
    GW_EUNSUPPORTED = -6, /* option not available in this backend or build */
    GW_EENERGY = -7,      /* energy monitor threshold exceeded */
    GW_ELIMIT = -8,       /* a run hit its time or step limit before finishing */
    GW_ECANCELED = -9     /* the caller's progress callback asked to stop */
};

/* Progress of a long call: done of total units (cases, collisions) finished.
 * Called from the calling thread or a worker thread, one call at a time (the
 * library serialises them); return 0 to go on, non-zero to stop the call, which
 * then returns GW_ECANCELED after the units under way have finished. */
typedef int (*gw_progress_fn)(void *ctx, long done, long total);

/* Message for a status code (static string, never NULL). */
const char *gw_strerror(int status);

/* Interrupts, for an interpreter calling the library from its main thread (the
 * Python module): a long call in C does not return to the interpreter's own
 * SIGINT handling until it is done, so Ctrl-C was ignored for as long as the run
 * took. gw_interrupt_begin installs a SIGINT handler that asks every run under
 * way in the process to stop: each solver step checks the request and the run
 * returns GW_ECANCELED ("interrupted at t = ... s"; sweeps and studies stop
 * taking cases). gw_interrupt_end restores the handler that was there and
 * returns 1 if SIGINT came in between, else 0. Pairs may nest and overlap
 * across threads: the first begin installs the handler and clears the request,
 * the last end restores it and clears the request. GW_OK, or GW_EIO when the
 * handler could not be installed. Programs that handle signals themselves (the
 * granwave program) never call these. gw_interrupt_pending: 1 while a request
 * is pending (what the steps check). */
int gw_interrupt_begin(void);
int gw_interrupt_end(void);
int gw_interrupt_pending(void);

/* Monotonic wall clock in milliseconds (for run-time reports). */
double gw_clock_ms(void);

/* Library version string, "MAJOR.MINOR.PATCH", and its three numbers: the version
 * of the library linked at run time (GW_VERSION in gw_version.h is the one a
 * program was compiled against). */
const char *gw_version(void);
int gw_version_major(void);
int gw_version_minor(void);
int gw_version_patch(void);

/* One line of error text, filled by calls that validate input. */
typedef struct gw_err {
    char msg[512];
} gw_err;

/* printf-style: store a message in err (may be NULL) and return status. */
int gw_err_set(gw_err *err, int status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* ---- warnings of a result ----
 * A run that ends with results that are not final (a collision cut at t_max,
 * a sample that did not settle, an undecided bounce) still returns GW_OK; the
 * result says why in warning texts that the library builds, each in one place,
 * for every caller: the program prints each as "granwave CMD: warning: TEXT",
 * the Python module issues it as a GranwaveWarning "func: TEXT", a C caller
 * reads it from the result (the studies' outcomes: a field `warnings`). A list
 * of warnings is one malloc'd string of texts, each ending with '\n'; NULL
 * when there are none. Its owner frees it with free(). */

/* Append one text (printf-style, numbers in the "C" locale) to *list. The text
 * is made one line as error messages are (a control character, a newline in a
 * file name say, written \n or \xNN; invalid UTF-8 as \xNN), so that one
 * warning stays one line. GW_OK; GW_ENOMEM (*list unchanged); GW_EINVAL for a
 * NULL list or fmt. */
int gw_warnings_add(char **list, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* ---- validation of numbers (name is the input's name for the message) ---- */

/* Parse a whole string as a finite decimal double (blanks around it; no
 * hexadecimal "0x1p-2", as gw_parse_long takes base 10 alone); GW_EINVAL with
 * a message otherwise. */
int gw_parse_double(const char *s, const char *name, double *out, gw_err *err);
/* Parse a whole string as an integer in [lo, hi]; a text that is no integer
 * is refused naming [lo, hi] ("n: '1.5' is not an integer (give an integer in
 * [1, 100])"; no range when [lo, hi] is every long). lo > hi is the caller's
 * error, named as gw_check_range names it, whatever s (the value was told
 * "outside [10, 0]"). name NULL: "value" (here, in gw_parse_double and
 * gw_parse_int_range; it was printed "(null)", and gw_parse_int_range read it
 * through strlen: SIGSEGV). */
int gw_parse_long(const char *s, const char *name, long lo, long hi, long *out,
                  gw_err *err);
/* Check that x is finite and lo <= x <= hi (use -INFINITY/INFINITY for open).
 * A NaN bound, or lo > hi, is the caller's error: GW_EINVAL naming the bound
 * ("gw_check_range: NAME: ... (lo is NaN)"), whatever x (a NaN bound was taken
 * as none). name NULL: "value". */
int gw_check_range(double x, const char *name, double lo, double hi, gw_err *err);
/* Check that x is finite and strictly positive. */
int gw_check_positive(double x, const char *name, gw_err *err);
/* Parse a comma-separated list of finite doubles into a new array (caller frees).
 * Every item is checked inside the parser (lo <= x <= hi, x > lo when open_lo), so
 * a caller never has to check the items, or name one, after freeing the list. On
 * failure *out is NULL, *n is 0 and the message names the item. A NaN lo or hi,
 * lo > hi or an open_lo other than 0 and 1 is GW_EINVAL naming it, as in
 * gw_check_range (lo > hi told each item "outside [3, 0]", open_lo 2 ran as
 * 1); name NULL: "list". */
int gw_parse_double_list_in(const char *s, const char *name, double lo, double hi,
                            int open_lo, double **out, int *n, gw_err *err);
/* gw_parse_double_list_in with no bounds (any finite number). */
int gw_parse_double_list(const char *s, const char *name, double **out, int *n,
                         gw_err *err);
/* Parse "A:B" or "A" (integers, A <= B, both in [lo, hi]; lo > hi as
 * gw_parse_long). */
int gw_parse_int_range(const char *s, const char *name, long lo, long hi, long *a,
                       long *b, gw_err *err);
/* Strip leading blanks/tabs and trailing blanks/tabs/CR in place; returns the
 * first kept character. */
char *gw_str_trim(char *s);
/* A flag's value in a config or table: 1 for "1"/"true", 0 for "0"/"false"
 * (case-insensitive), -1 otherwise. */
int gw_parse_flag(const char *v);

/* ---- solver tolerances: the one range every command and backend accepts ----
 * Relative and absolute tolerances of the adaptive backends (the absolute one in
 * units of each component's scale). Above 1e-4 the 5-bead Falcon column's peak
 * force is already 0.3 % off (1e-3: 1.8 %, 1e-2: 17 %, 1: the run "succeeds"
 * 60 % off); below 1e-15 a tolerance asks for less than the rounding of a
 * double. */
#define GW_TOL_MIN 1e-15
#define GW_TOL_MAX 1e-4
/* Check rtol and atol against [GW_TOL_MIN, GW_TOL_MAX]; rname and aname name the
 * inputs ("chain --rtol"; NULL: "rtol", "atol"). Used by gw_solver_create and by
 * every command before any work. GW_EINVAL with one line naming the input. */
int gw_solver_tolerances_check(double rtol, double atol, const char *rname, const char *aname,
                               gw_err *err);

/* ---- files ---- */

/* A file written under a temporary name and renamed into place on commit, so a
 * reader sees either the previous file or the complete new one. SIGINT, SIGTERM
 * and SIGHUP are held from open to commit/abort (delivered right after), so an
 * interrupt never leaves a half-written file in place; the temporary is in the
 * table gw_temps_remove empties until it is placed (a program that installed
 * gw_temps_on_signals leaves none behind; only kill -9 can). The temporary
 * is "PATH.tmp.HOST.PID.XXXXXX" in the same directory (a unique name: two
 * writers of one path never share a temporary); the temporaries of PATH that a
 * process of this host no longer running left (kill -9) are removed at the
 * next open of PATH. Every file granwave writes goes through this: text through
 * the stream fp, HDF5 through the temporary's name. */
typedef struct gw_afile {
    FILE *fp;
    char path[4096];
    char tmp[4096 + 64];
    unsigned char oldmask[128]; /* the caller's signal mask (a sigset_t) */
    int masked;
    int named; /* opened by gw_afile_open_named: the caller writes tmp by name */
    int held;  /* path and tmp name files from their rel-th byte on in dirfd: 1 opened by gw_afile_openat
                  (the caller's dirfd), 2 by gw_afile_open outside an output set (its own, closed at the end) */
    int dirfd;
    size_t rel;
} gw_afile;

/* Open path for writing through a temporary file: f->fp is the stream. On
 * failure nothing is created (and f is safe to abort). A symbolic link at path
 * is written through: the temporary goes beside its target, which the commit
 * replaces (f->path), and the link stays; a link to nothing is GW_EINVAL, and
 * so is an empty path. An f open now (opened, not yet committed or aborted) is
 * refused, GW_EINVAL, and left as it is (each of the three opens). */
int gw_afile_open(gw_afile *f, const char *path, gw_err *err);
/* The same for a writer that creates the file itself by name (HDF5's
 * H5Fcreate(f->tmp, H5F_ACC_TRUNC, ...)): f->tmp is an empty file reserving a
 * unique name and f->fp is NULL. The writer closes its own handle before
 * commit; commit fsyncs f->tmp and renames it into place. */
int gw_afile_open_named(gw_afile *f, const char *path, gw_err *err);
/* The same for the file name in the directory dirfd (the caller's, open and
 * held until the commit or abort), whose path dir names it in messages and
 * in the table of temporaries: the file is written in that directory wherever
 * it has been moved or renamed since it was opened (a sweep's table beside its
 * journal). A symbolic link at name is written through (a relative target
 * from the link's directory); no output set takes the file (it is placed at
 * its commit). An empty name is GW_EINVAL, nothing made (it made a temporary
 * before session 41, and its commit failed once the write was done). */
int gw_afile_openat(gw_afile *f, int dirfd, const char *dir, const char *name, gw_err *err);
/* Flush (stream), fsync and rename into place. On failure the temporary is
 * removed and the previous file at path, if any, is left as it was. */
int gw_afile_commit(gw_afile *f, gw_err *err);
/* Discard the temporary file (safe to call on a closed or failed file). */
void gw_afile_abort(gw_afile *f);

/* A set of output files committed together: the files a command writes into
 * its --out directory either all replace the earlier run's, or none do. From
 * gw_outset_begin to gw_outset_commit/abort, every gw_afile this thread
 * commits is fsynced and kept under its temporary name ("staged"), not renamed.
 * gw_outset_commit renames the staged files into place, then removes every
 * name of the set's list that this run did not write (a file of an earlier run
 * beside this run's results would read as one of them). gw_outset_abort (a
 * write failed, or the run was refused) removes the staged temporaries: the
 * directory is left as the earlier run left it. names: every file the command
 * may write into dir, NULL-terminated, each a file name (not empty, ".", ".."
 * nor with a '/': GW_EINVAL); dir not empty (GW_EINVAL: the set's paths
 * would be "/NAME"). Begun again while it is the set open on this thread,
 * s is refused and left as it was (its commit still places its files).
 * gw_outset_commit and gw_outset_abort act only on the set open on this
 * thread: any other struct (never begun, closed, zeroed, garbage) is GW_EIO
 * for commit and nothing for abort, and is not read. Two runs placing their sets in one
 * directory at once place them one after the other (flock on the directory):
 * it holds the last one's files, never some of each. A set may stay open
 * through a long run (layer-impact's snapshots): SIGINT, SIGTERM and SIGHUP
 * are held only while each file is written and while the staged files are
 * placed or removed; a run ended before its commit leaves the earlier run's
 * files as they were, and its staged temporaries only when killed with kill -9
 * or by a signal without gw_temps_on_signals' handler ("NAME.tmp.HOST.PID.XXXXXX",
 * never read as results, removed by the next run's write of NAME). One set per
 * thread. */
typedef struct gw_outset {
    char dir[4096];
    const char *const *names;
    int n, cap;
    char **tmp, **path; /* staged: temporary and final path */
    unsigned char oldmask[128];
    int masked, active;
} gw_outset;

int gw_outset_begin(gw_outset *s, const char *dir, const char *const *names, gw_err *err);
/* GW_EINVAL (one line naming what and both paths) when the file input is one of
 * the set's names in dir (the same file, by device and inode; for a file not
 * made yet, the same directory and name): the run would replace the file it
 * reads, or write two things under one name (what NULL: named "input"). GW_OK
 * otherwise, and for input NULL or "" (no input: a command run without its
 * --wisdom or --sample). dir or names NULL is a caller's error: GW_EINVAL
 * naming it (it was GW_OK, checking nothing, before session 43). */
int gw_outset_check_input(const char *dir, const char *const *names, const char *input, const char *what,
                          gw_err *err);
/* Rename the staged files into place and remove the set's names not written,
 * all or nothing: every earlier file replaced or removed is kept aside first
 * (a hard link beside it, or a rename where no link can be made) until the
 * set is in place. On a failure (a rename, an immutable file: GW_EIO; out of
 * memory: GW_ENOMEM) the message names the file and the OS error, the earlier
 * files are put back, the new ones and the temporaries removed: dir holds
 * what it held before (only a failure to put one back, added to the message
 * with the name it is kept under, or kill -9, can leave less). The set is
 * closed either way. */
int gw_outset_commit(gw_outset *s, gw_err *err);
/* Remove the staged temporaries; the set is closed (safe on a closed set). */
void gw_outset_abort(gw_outset *s);

/* The temporaries of this process not yet placed or removed: an atomic file's
 * from its open to its commit or abort, an output set's staged files until the
 * set is placed or aborted (as many as are open or staged at once: the table
 * grows outside the handler). gw_temps_remove unlinks them all; it is async-signal-safe, for a
 * program's own handler of a signal that ends it. It never touches a file
 * already placed: a staged file renamed into place is no longer under its
 * temporary name. The output set's guarantee holds: a signal that comes while
 * the set is placed is held until the last rename (the calling thread's mask;
 * on another thread, gw_temps_on_signals' handler records it and the placer
 * sends it again once the set is wholly placed or wholly put back), so the
 * directory then holds the complete new set, and before it, the earlier
 * files as they were. */
void gw_temps_remove(void);
/* Install, for SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGUSR1, SIGUSR2, SIGALRM,
 * SIGVTALRM, SIGPROF and SIGXCPU (the signals that end a process by default
 * and that a user or the system sends it) where each has its default action
 * (a signal ignored, or with a handler of the program's, is left as it is), a
 * handler that calls gw_temps_remove and then ends the process by the signal's
 * default action (the exit status still says "killed by SIGINT"); while an
 * output set is placed, on any thread, after it is placed or put back. For programs:
 * the granwave program calls it first; the library never installs it on its
 * own, so a binding (the Python module) keeps its interpreter's handling.
 * GW_OK, or GW_EIO when sigaction failed for one of them. */
int gw_temps_on_signals(void);

/* Write text as comment lines: "# " + each line + "\n" (a final newline in
 * text adds no empty comment; NULL or "" writes nothing). The provenance
 * header of the program's tables goes to files through this. */
void gw_write_comment(FILE *fp, const char *text);

/* Create directory (and parents) if missing. A path that names a missing
 * component and then ".." ("o/../o2" with no o) is GW_EINVAL, nothing made
 * (mkdir -p made o and left it behind). */
int gw_mkdir_p(const char *path, gw_err *err);
/* Join dir and name into buf (size n); GW_EINVAL if it does not fit, or for a
 * NULL buf, dir or name (buf then unchanged; a NULL dir was joined as
 * "(null)/name" with GW_OK, a NULL buf written to), or an empty dir (buf
 * unchanged: "" and "b" gave "/b", a file in the root directory). */
int gw_path_join(char *buf, size_t n, const char *dir, const char *name);
/* Cut the path in buf (at least 2 bytes) to its directory, in place: "a/b" ->
 * "a", "/b" -> "/", "b" -> "." (trailing slashes are the caller's). */
void gw_path_parent(char *buf);

/* Write a string to path atomically. */
int gw_write_text(const char *path, const char *text, gw_err *err);

/* ---- inputs: the one way every input file is opened ----
 * Only a regular file is accepted: the file is opened with O_NONBLOCK and
 * fstat'ed before any read, so a FIFO, a device (/dev/zero), a socket or a
 * directory is refused at once instead of blocking or reading forever. what names
 * the input in the message ("layer-impact --sample"). GW_EINVAL (not a regular
 * file, too large) or GW_EIO (cannot open or read) with one line in err. */

/* Open path for reading ("rb"); on success *out is the stream (caller fcloses),
 * on failure *out is NULL and nothing is open. */
int gw_input_open(const char *path, const char *what, FILE **out, gw_err *err);
/* gw_input_open and close again: for libraries that open the file by name. */
int gw_input_check(const char *path, const char *what, gw_err *err);
/* 1 when the regular file open as fd has a hole before its end (SEEK_HOLE:
 * bytes never written, a sparse file's, read as NUL bytes), the hole's first
 * byte's offset (from 0) in *at (at may be NULL); 0 without one, or where the
 * system cannot tell. The read offset of fd is left as it was. A text input
 * with a hole is binary: its readers refuse it before reading up to it. */
int gw_input_hole(int fd, unsigned long long *at);
/* gw_input_hole, and with bytes not NULL the holes' bytes in all in *bytes
 * (0 without a hole): an HDF5 file may hold holes of its own right (a sample
 * copied with cp --sparse=always or rsync -S keeps its zero runs as holes) */
int gw_input_holes(int fd, unsigned long long *at, unsigned long long *bytes);
/* Read the whole text file, at most max bytes, into a new NUL-terminated buffer
 * (caller frees; *len without the NUL; len may be NULL). A file with a hole
 * (gw_input_hole) is refused (GW_EINVAL) before it is read: a sweep table
 * made a sparse 3 GB file was read into memory (out of memory, exit 1, under
 * a 2 GB limit). A file that gives
 * more bytes than its size at open is refused (GW_EINVAL) after one byte more:
 * it grew while read, or it is no file on disk (a /proc file, 0 bytes: a
 * sweep table linked to /proc/self/pagemap was read until memory ran out). */
int gw_input_read(const char *path, const char *what, size_t max, char **out, size_t *len,
                  gw_err *err);

/* ---- content hashes: what a result ran on ----
 * FNV-1a, 64 bits (offset basis 14695981039346656037, prime 1099511628211),
 * of a file's bytes, printed as 16 lowercase hex digits: a result records the
 * content of its input files besides their names (a file changed later no
 * longer matches). None reads more than a bound: gw_fnv1a64_stream hashes fp
 * from its current position to the end of a regular file of at most
 * GW_INPUT_HASH_MAX bytes, at most its size at the call (GW_EINVAL, *h
 * unchanged, for a stream of no regular file, /dev/zero or a pipe, before a
 * byte is read, for a larger file, and for one that gives more bytes than
 * that size; GW_EIO on a read error);
 * gw_fnv1a64_file_max (h NULL: GW_EINVAL) opens path as an input
 * (gw_input_open: a regular file only) and refuses it (GW_EINVAL, naming it and
 * its size) when it is larger than max bytes, before a byte is read, or when it
 * gives more bytes than that size (it grew while read, or a /proc file: 0
 * bytes, and /proc/self/pagemap gave 256 GiB; 8 KiB more read at most); text 0
 * or 1 (another value is GW_EINVAL naming it, before path is opened; 7 was
 * taken as 1); text 1: a NUL
 * byte refuses it (GW_EFORMAT, naming its line), the read stopped there, so
 * that a text input is checked for binary data in the pass that hashes it.
 * gw_fnv1a64_file is gw_fnv1a64_file_max with max GW_INPUT_HASH_MAX, not text:
 * a sparse 200 GB file was hashed whole (minutes) before its reader refused it. */
#define GW_FNV1A64_INIT 14695981039346656037ULL
#define GW_INPUT_HASH_MAX ((unsigned long long)1 << 32) /* bytes: 4 GiB */
unsigned long long gw_fnv1a64(unsigned long long h, const void *p, size_t n);
int gw_fnv1a64_stream(FILE *fp, unsigned long long *h);
int gw_fnv1a64_file(const char *path, const char *what, unsigned long long *h, gw_err *err);
int gw_fnv1a64_file_max(const char *path, const char *what, unsigned long long max, int text,
                        unsigned long long *h, gw_err *err);
/* The hash of one sweep case's configuration: FNV-1a 64 of "model M\n" and
 * then "NAME = VALUE\n" for each of the n pairs in order (a sweep's grid keys
 * in the config's order with the case's values, then its [params]). A sweep
 * journals it with each row and writes it in its table (column
 * case_config_fnv1a64), so that a row of a sweep with other [params] or
 * another model is told apart from the sweep's own (docs/formats.md). 0 (no
 * hash) for a NULL model, n < 0, or a NULL names, values or pair. */
unsigned long long gw_case_config_hash(const char *model, int n, const char *const *names,
                                       const char *const *values);
/* A hash as results print it: exactly len = 16 lowercase hex digits at p into
 * *h (1), or 0 (another length, another character). */
int gw_fnv1a64_parse(const char *p, size_t len, unsigned long long *h);

/* ---- output locations, checked before any work ----
 * gw_out_check: dir is an existing writable directory, or does not exist and its
 * nearest existing ancestor is a writable directory (it creates nothing; the
 * caller makes the directory with gw_mkdir_p when it has something to write);
 * not the file system's root directory, by any spelling (its files would go
 * among the system's; gw_outset_begin refuses it too).
 * gw_out_file_check: path is absent or a regular file, in an existing writable
 * directory; a symbolic link is checked as the file it leads to (in its
 * directory), and refused when it leads nowhere. GW_EINVAL with one line
 * naming what. */
int gw_out_check(const char *dir, const char *what, gw_err *err);
int gw_out_file_check(const char *path, const char *what, gw_err *err);
/* These checks, gw_out_names_check and gw_mkdir_p refuse a name the run
 * would make that holds a control character (a byte below 0x20, such as a
 * newline or ESC, or 0x7f): a component of the path that does not exist yet,
 * GW_EINVAL with one line naming what, the path and the byte; an existing
 * one (a directory the user made) is written into, as before. */
/* gw_out_names_check: dir and names (NULL-terminated) are not NULL (refused
 * naming the argument), each name is a plain file name (not empty, no '/',
 * not "." or "..") holding no control character unless the file is there
 * (gw_io_new_name_check), and each of the files a run writes into dir
 * that is already there is a regular file or a
 * symbolic link to one: a directory, FIFO, socket or device there (or behind a
 * link, or a link to nothing) is refused before the run, GW_EINVAL with one
 * line naming what and the file. The atomic write refuses them too
 * (gw_afile_open), but only after the run's work. So is a dir whose files,
 * under their temporary names (".tmp.HOST.PID.XXXXXX" longer), would exceed
 * PATH_MAX (mkstemp failed after the run). what NULL: "output", as gw_out_check. */
int gw_out_names_check(const char *dir, const char *const *names, const char *what, gw_err *err);

/* ---- fits (GSL) ---- */

typedef struct gw_linfit {
    double c0, c1;         /* y = c0 + c1 x */
    double c0_err, c1_err; /* standard errors from the scatter about the line */
    double r2;             /* coefficient of determination */
    double max_rel_resid;  /* max |y - fit| / |fit| */
    int n;
} gw_linfit;

/* Least-squares line through (x[i], y[i]), n >= 2 (errors need n >= 3),
 * fitted on x and y scaled by powers of two (any finite magnitudes: points
 * near 1e300 gave NaN with GW_OK before session 41). GW_EINVAL, with every
 * number of *fit NaN, for a NULL pointer, n < 2, a point that is not finite,
 * abscissas all equal, or a slope or intercept beyond the doubles (gw_fit_power
 * also for a value <= 0). GW_ENOMEM. */
int gw_fit_linear(const double *x, const double *y, int n, gw_linfit *fit);

/* Power law y = A x^beta by a line in log-log; c0 = ln A, c1 = beta. */
int gw_fit_power(const double *x, const double *y, int n, gw_linfit *fit);

/* Offset (in bins, within [-1, 1]) of the vertex of the parabola through the
 * logs of three positive samples pm, p0, pp around a peak at p0; 0 when the
 * samples do not bracket a maximum. */
double gw_peak_offset_log(double pm, double p0, double pp);

/* ---- JSON (cJSON) ---- */

/* New JSON array of n doubles (NaN and infinities print as null). NULL on ENOMEM,
 * and for v NULL with n > 0 (each of the three). */
cJSON *gw_json_doubles(const double *v, int n);
cJSON *gw_json_ints(const int *v, int n);
/* New JSON array of n flags: false for 0, true otherwise. NULL on ENOMEM. */
cJSON *gw_json_bools(const int *v, int n);
/* o as JSON text, numbers exact (the shortest %.15g-%.17g that reads back as
 * the same double), formatted or on one line; malloc'd (free it), NULL on out
 * of memory. gw_json_print and gw_json_write print the same way.
 * Also NULL once an allocation of cJSON has failed in the calling thread
 * (gw_json_failures): cJSON's builders drop a member they could not allocate
 * and say so only in a return value the callers rarely read, so a settings
 * record or result could lose a key (a chain header without "wall_material")
 * with exit 0; such an object is now never printed. */
char *gw_json_string(const cJSON *o, int formatted);
/* Length of the well-formed UTF-8 sequence at text (RFC 3629: no overlong
 * form, no surrogate, at most U+10FFFF; 1 for an ASCII byte), 0 when the byte
 * at text starts none. JSON text is UTF-8: gw_json_string prints each such
 * byte of a key or string as U+FFFD. */
size_t gw_utf8_len(const char *text);
/* Allocations of cJSON (every cJSON call in the process goes through
 * granwave's hooks once the library is loaded) that failed in the calling
 * thread since it started or since gw_json_failures_clear. A caller that goes
 * on after an out-of-memory error (an interpreter) clears them before building
 * new objects. */
unsigned long gw_json_failures(void);
void gw_json_failures_clear(void);
/* Print o (indented) with a newline to fp, flushed. GW_OK; GW_EINVAL for a
 * NULL o or fp; GW_ENOMEM (nothing printed); GW_EIO when a write or the flush failed, errno then the failed
 * write's (EPIPE, ENOSPC: the caller reports it, as a later fflush of fp finds
 * the error flag set but no errno). */
int gw_json_print(const cJSON *o, FILE *fp);
/* Write o to path atomically. */
int gw_json_write(const char *path, const cJSON *o, gw_err *err);

GW_END_DECLS

#endif
