/*
 * gw_sweep.h: grids of independent cases described by an INI config file, run
 * resumably (an append-only journal of complete, checksummed rows) by threads or
 * MPI ranks, gathered into one table sorted by case number.
 *
 * Config format (parsed with libinih; '#' or ';' comments):
 *   [sweep]
 *   model = chain              ; which model runs the cases
 *   out = results/my_sweep     ; output directory (or --out DIR), from the config's directory
 *   [grid]                     ; every combination of these values is a case
 *   n = 1:40                   ; integer range A:B, or a comma list
 *   vimp = 0.1, 0.2, 0.3
 *   [params]                   ; the same for every case
 *   solver = rk4
 * Keys of [grid] and [params] are the model command's option names (for the
 * chain: the options of `granwave chain`, without the leading --). Case numbers
 * run over the grid with the last grid key varying fastest.
 */
#ifndef GW_SWEEP_H
#define GW_SWEEP_H

#include "gw_common.h"
#include "gw_pool.h"

#include "gw_api.h"

GW_BEGIN_DECLS /* the exported interface, C linkage (gw_api.h) */

#define GW_SWEEP_MAX_KEYS 32
#define GW_SWEEP_CONFIG_MAX (1L << 20) /* bytes: a config is read whole, bounded */
#define GW_SWEEP_JOURNAL_MAX ((size_t)1 << 34) /* bytes of a journal read back (resume, table) */
#define GW_SWEEP_JOBS_MAX 4096          /* threads of one sweep (--jobs, gw_sweep_run) */
/* A journal's first line (the config's hash): "format 3", a second line
 * "# build ..." naming the build that computes its rows, rows that end with
 * their case config hash and read hash. Format 2 had no build line, format 1
 * no hashes in its rows: both are refused (docs/formats.md). */
#define GW_SWEEP_JOURNAL_HEAD "# granwave sweep journal %016lx, format 3"
/* The number in GW_SWEEP_JOURNAL_HEAD: a journal of another format (an
 * earlier one, a later granwave's) is refused naming both formats. */
#define GW_SWEEP_JOURNAL_FORMAT 3

typedef struct gw_sweep_key {
    char *name;
    char **values; /* grid values (strings as given), or one value for params */
    int nvalues;
    int line;      /* config line, for messages */
} gw_sweep_key;

typedef struct gw_sweep_config {
    char *path; /* the config file as given to gw_sweep_config_read (NULL from a string): an input too */
    char *model;
    char *out;
    gw_sweep_key grid[GW_SWEEP_MAX_KEYS];
    int ngrid;
    gw_sweep_key params[GW_SWEEP_MAX_KEYS];
    int nparams;
    long ncases;
    unsigned long hash; /* of the normalised config: a journal belongs to one config */
    const char *read_key; /* the model's read_key (NULL: rows carry no read hash) */
    /* The values of the model's read_key (a layer sample; the values of
     * other keys are text, whatever files they happen to name) that name a
     * regular file: their content hash (gw_fnv1a64) when the config was read. Written to the journal and
     * the table ("# input KEY = VALUE fnv1a64 HEX"); a resumed sweep whose
     * file changed is refused naming it, and gw_sweep_inputs_check finds a
     * change while the sweep runs. */
    int ninputs;
    struct gw_sweep_input {
        const char *key, *value; /* point into grid / params */
        unsigned long long hash;
    } *inputs;
    /* The model's result columns (gw_sweep_model.ncolumns; 0: not known, as
     * in a config filled by hand): a journal row must carry exactly these
     * many numbers to be resumed. */
    int ncolumns;
} gw_sweep_config;

/* A model that runs one case: name/value pairs in, ncolumns numbers out. The
 * pairs (nkeys of them; the chain's and the layer's run, check, memory,
 * check_memo and run_part alike): nkeys >= 0, no name or value NULL, no key
 * twice ('_' and '-' one): GW_EINVAL naming nkeys, names[i] or the key
 * otherwise (a negative count ran the defaults, a NULL name crashed the layer
 * model, a key twice ran its last value). */
typedef struct gw_sweep_model {
    const char *name;
    int ncolumns;
    const char *const *columns;
    /* Is name an option of this model? (unknown keys are refused at parse time) */
    int (*has_key)(const char *name);
    /* Run a case. Returns GW_OK, GW_EINVAL (bad value: message names it) or a
     * run failure. read_hash (may be NULL): the content hash (gw_fnv1a64) of
     * the bytes of the file named by read_key that the case read (models with
     * a read_key). */
    int (*run)(int nkeys, const char *const *names, const char *const *values, double *out,
               unsigned long long *read_hash, gw_err *err);
    /* Validate a case without running it (may be NULL). */
    int (*check)(int nkeys, const char *const *names, const char *const *values, gw_err *err);
    /* The peak memory a case holds while it runs, bytes, estimated from its
     * values without running it (may be NULL: not estimated). GW_EINVAL for a
     * bad value (as check). */
    int (*memory)(int nkeys, const char *const *names, const char *const *values, double *bytes, gw_err *err);
    /* The key whose value names the one file a case reads (the layer's
     * "sample"), NULL when the cases read none. Each row then records the
     * hash of the bytes its case read (run's read_hash), checked against the
     * sweep's hash of that file before the row is kept: a case that read the
     * file while it was changed, and finished after it was restored, passed
     * the check of the file after the case. */
    const char *read_key;
    /* check with a memo that the caller keeps over one pass of checks (may be
     * NULL: check is used), so that a model reads a file the cases share once:
     * *memo is NULL at the pass's first call, and the caller hands it to
     * memo_free (NULL-safe) when the pass ends; one pass, one thread. The
     * verdicts and messages are check's. */
    int (*check_memo)(void **memo, int nkeys, const char *const *names, const char *const *values, gw_err *err);
    void (*memo_free)(void *memo);
    /* The warnings of a pass of check_memo over the sweep's cases (may be
     * NULL: none), called with its memo before memo_free: lines appended to
     * *list (gw_warnings_add), each saying how many of the cases checked it
     * concerns (a chain case whose dt is above the step it will take), one
     * line for a thousand cases, not one each. GW_OK or GW_ENOMEM; GW_EINVAL
     * when the pass refuses the config as a whole (a chain key of no effect on
     * any case: k where every case is one body), its one line appended to
     * *list being the refusal's text. */
    int (*memo_warnings)(const void *memo, char **list);
} gw_sweep_model;

/* A case's progress while it runs, for a display of the sweep: x, the share
 * of the case done on its model's own scale (a chain case: its collision's
 * simulated time over its expected length; a layer case: its simulated time
 * over the end its block's flight gives, or t-max), from the thread that runs
 * the case, at most about once per output sample; x may pass 1 (a collision
 * longer than expected) or end below it (an impact ended before the end
 * expected). It must return at once. */
typedef void (*gw_sweep_part_fn)(void *pctx, double x);
/* A model's run that reports its part (gw_chain_sweep_run_part,
 * gw_layer_sweep_run_part): the model's run, its results bit for bit, with
 * part(pctx, x) as it goes (part may be NULL). */
typedef int (*gw_sweep_run_part_fn)(int nkeys, const char *const *names, const char *const *values, double *out,
                                    unsigned long long *read_hash, gw_sweep_part_fn part, void *pctx, gw_err *err);

/* Check case k of a pass over a model's cases (check_memo with *memo when the
 * model has it, else check; GW_OK when it has neither). gw_sweep_checks_end
 * frees the memo when the pass ends. */
int gw_sweep_case_check(const gw_sweep_model *m, void **memo, int nkeys, const char *const *names,
                        const char *const *values, gw_err *err);
void gw_sweep_checks_end(const gw_sweep_model *m, void *memo);

/* The sweep's check pass over cfg's cases, before any case runs: the one
 * pass of `granwave sweep` (and its --check), gw_sweep_run(_warned) and
 * gw_sweep_write_table's warnings. The config's shape (gw_sweep_config_check),
 * then every case through gw_sweep_case_check with one memo, the first refused
 * GW_EINVAL (or its status) "case K: MSG" (gw_sweep_case_refused: a [params]
 * key another case takes says so), then the pass's verdict over its cases as
 * a whole (m->memo_warnings): a refusal of the config, GW_EINVAL with its one
 * line (a chain key of no effect on any case: "k: has no effect on one body
 * (n = 1) in any case ..."), or its warnings, appended to *warnings (may be
 * NULL: none kept; a gw_warnings_add list, the config's keys named as its
 * keys, gw_sweep_warnings_keys). GW_OK when the model has no check. progress
 * (may be NULL) is called before case k for k a positive multiple of 1000
 * (done k of ncases); non-zero stops the pass, GW_ECANCELED. On failure
 * *warnings is as it was; GW_ENOMEM for the warnings' memory. */
int gw_sweep_check_pass(const gw_sweep_config *cfg, const gw_sweep_model *m, gw_progress_fn progress, void *pctx,
                        char **warnings, gw_err *err);

/* One case's check as a sweep of that one case checks it: gw_sweep_check_pass
 * over the config of one case whose [params] are the nkeys pairs (each a
 * config's text of one value), so its verdict is a one-case sweep's, the
 * refusals of the config as a whole included (gw_sweep_case_check alone
 * passed chain n = 1, k = 1e9, which a sweep of that case refuses: k has no
 * effect on one body in any case). A refusal is "case 0: MSG" as the sweep
 * says it, or the config's line. nkeys outside [0, GW_SWEEP_MAX_KEYS], m,
 * names, values or one of the pairs NULL: GW_EINVAL naming it. */
int gw_sweep_case_check_pass(const gw_sweep_model *m, int nkeys, const char *const *names,
                             const char *const *values, char **warnings, gw_err *err);


/* Parse path. Errors (exit code 2 material): unreadable file, syntax error or
 * unknown section/key with "path:line: ..." in err, empty grid values, a grid
 * larger than 1e9 cases. models/nmodels: the known models. The paths the
 * config names ([sweep] out, the values of the model's read_key) are taken
 * from the config file's own directory when relative (absolute ones are
 * kept): cfg holds them absolute (the config's directory, symbolic links
 * resolved, then the value as written), so the same config reads the same
 * files from any working directory and its journal and table record them.
 * A relative read_key value that names nothing there: GW_EINVAL "path: [grid]
 * sample = S: no such file /DIR/S (...)". A file whose last line holding a
 * key or a value has no newline after it (LF, or the CR of a CR LF) may be
 * cut short inside that value: GW_EINVAL "path:line: the file ends inside
 * this line ...". */
int gw_sweep_config_read(const char *path, const gw_sweep_model *const *models, int nmodels,
                         gw_sweep_config *cfg, const gw_sweep_model **model, gw_err *err);
/* The same from a string (name is used in messages; relative paths stay as
 * written: the caller's working directory), bounded as a file is: a text
 * longer than GW_SWEEP_CONFIG_MAX bytes is GW_EINVAL. The text may end
 * without a newline. */
int gw_sweep_config_read_string(const char *text, const char *name, const gw_sweep_model *const *models,
                                int nmodels, gw_sweep_config *cfg, const gw_sweep_model **model, gw_err *err);
void gw_sweep_config_free(gw_sweep_config *cfg);

/* The name/value pairs of case k (grid values, then params). names/values must
 * hold ngrid + nparams entries; they point into cfg. */
int gw_sweep_case(const gw_sweep_config *cfg, long k, const char **names, const char **values);

/* One journal row into buf: "k,<grid values>,<numbers>,<case config hash>\n"
 * then, when cfg->read_key is set, ",<read hash>" before the ",<checksum>\n"
 * (hashes as 16 hex digits: gw_sweep_case_hash, and read_hash, the content
 * hash of the file the case read). GW_EINVAL for a NULL pointer, ncol < 0, a
 * case k the config has not (k < 0 or k >= ncases), or a row longer than n. */
int gw_sweep_format_row(const gw_sweep_config *cfg, long k, const double *out, int ncol,
                        unsigned long long read_hash, char *buf, size_t n);

/* The hash of case k's configuration (gw_case_config_hash over the model,
 * the case's grid values and the [params]): the same for a case of any sweep
 * that runs it with the same values, another one when [params] or the model
 * differ. */
unsigned long long gw_sweep_case_hash(const gw_sweep_config *cfg, long k);

/* A finished row (gw_sweep_format_row) may be journaled: its case config hash
 * is case k's, and the hash of the file it read is the one the sweep started
 * with (cfg->inputs). GW_EINVAL "case K read sample 'S' with content fnv1a64
 * A, but the sweep's ... is B ..." otherwise. */
int gw_sweep_row_check(const gw_sweep_config *cfg, const char *row, gw_err *err);

/* Read DIR/journal.csv: done[k] = 1 for every complete row with a valid checksum.
 * A torn last line (no newline or bad checksum) is cut off the file, and so
 * is a zeroed end (NUL bytes alone after the last newline: a power cut's); a
 * NUL byte anywhere else is refused (GW_EINVAL naming its line). A new
 * journal gets the config's hash, its input lines and its keys ("# grid" and
 * "# param" lines); an existing one of another config is refused (GW_EINVAL),
 * naming the input file whose content changed when its "# input" line says
 * so, else the first key whose value or place differs. A row whose case config hash is
 * not its case's (a row of a sweep with other [params]), or whose read hash is
 * not the sweep's file's, is refused naming the journal, the line and both
 * hashes; so is a journal of the format before rows carried these hashes. */
int gw_sweep_journal_scan(const char *dir, const gw_sweep_config *cfg, char *done, long *ndone,
                          gw_err *err);
/* The sweep's input files in DIR under the names of its outputs (journal.csv,
 * results.csv): the config file itself (cfg->path) and the files the
 * model's read_key names (cfg->inputs). The table would replace such a file
 * when the sweep ends (a config DIR/results.csv ran, exit 0, and was gone),
 * the journal be refused as not one. GW_EINVAL "sweep CONFIG: 'P' is the file
 * this run writes as DIR/results.csv: ..." (or "sweep: ..." for a sample);
 * the same file under another name (a symbolic or hard link) counts. A DIR
 * not made yet holds nothing. gw_sweep_journal_open checks it too. */
int gw_sweep_out_inputs_check(const char *dir, const gw_sweep_config *cfg, gw_err *err);
/* The same, and the journal kept open for appending in *fd (-1 on failure),
 * locked (flock) until it is closed: one sweep at a time in a directory. A
 * new journal is linked into place whole, never over one made meanwhile.
 * A journal locked by another process: GW_EINVAL "DIR: another sweep is
 * running in this directory ...", before anything is read or cut. */
int gw_sweep_journal_open(const char *dir, const gw_sweep_config *cfg, char *done, long *ndone, int *fd,
                          gw_err *err);
/* The same, and DIR held open in *dirfd (O_DIRECTORY; -1 on failure) until
 * the caller closes it: DIR was opened once and its journal found, made and
 * read through it, and the sweep's table goes there (gw_sweep_write_table_at),
 * so a DIR moved or renamed while the sweep runs keeps its journal and gets
 * its table wherever it went. GW_EIO when DIR cannot be opened. */
int gw_sweep_journal_open_at(const char *dir, const gw_sweep_config *cfg, char *done, long *ndone, int *fd,
                             int *dirfd, gw_err *err);
/* GW_OK while the directory dirfd (a sweep's, held open; dir names it in the
 * message) is in the file system, wherever it was moved; GW_EIO when it was
 * removed (or moved to another file system, which copies it and removes it):
 * the rows journaled since went with it. */
int gw_sweep_dir_held(int dirfd, const char *dir, gw_err *err);
/* The sweep's journal *fd (open and locked, in the directory dirfd held open;
 * dir names it) still in that directory under its name (journal.csv, or a
 * symbolic link to it). Removed from it while the sweep ran (or moved away),
 * it is put back whole under its name (locked, only while the name is free),
 * *fd becomes the new file's (the old one closed) and *restored 1, GW_OK.
 * Its name holding another file now (replaced: an editor saving through a
 * rename, a copy moved over it), the journal is kept whole under a free name
 * beside it, DIR/journal.kept.csv (journal.kept.2.csv, ... when taken),
 * made as a journal is, *fd becomes that file's and *restored 2, and GW_EIO
 * "DIR/journal.csv was replaced by another file while the sweep ran ...:
 * this sweep's journal is kept whole as DIR/journal.kept.csv, the other file
 * left as it is": the caller stops taking cases (the rows of those under way
 * go on into *fd). The other file is never written. A journal opened by
 * gw_sweep_journal_open_at is also checked to hold what the sweep wrote into
 * it (the text at the open and every row gw_sweep_journal_append wrote since,
 * kept in memory beside the descriptor): its size, its last 4096 bytes, and
 * the whole file when its times are not those the sweep's last write left.
 * Found written into (rewritten in place: `> DIR/journal.csv`, an editor
 * writing into the file; cut; a line added by another program), the journal
 * is kept alike from that copy, *restored 2, GW_EIO "DIR/journal.csv was
 * written into while the sweep ran (...): this sweep's journal is kept whole
 * as DIR/journal.kept.csv, the file left as it is". A journal put back is
 * checked alike, so a file written into it later (an editor's save that
 * deleted the journal and wrote its text after GW_SWEEP_GRACE_MS) is found
 * at the next row, never appended to. GW_EIO (*restored 0) also when the
 * journal cannot be read, written back or kept. */
int gw_sweep_journal_held(int dirfd, int *fd, const char *dir, int *restored, gw_err *err);
/* What a resume would find (`granwave sweep CONFIG --check`): DIR/journal.csv
 * read and checked by the code of gw_sweep_journal_open, with its refusals
 * (another config's journal, one edited by hand, of another format, a row of
 * other [params] or of a changed input file, a FIFO or a directory of its
 * name, a journal another sweep holds locked: GW_EINVAL naming the journal or
 * DIR; GW_EIO when it cannot be opened for appending), but nothing created,
 * cut or written: done[k] = 1 and *ndone as a resume would skip them,
 * *exists (may be NULL) 0 when there is no journal yet (then *ndone = 0),
 * *torn (may be NULL) the bytes of a torn last line a resume would cut: a
 * row, whose case runs again, or, *torn_head (may be NULL) 1, a line of the
 * journal's head (# input, # grid, # param lines), which holds no case, or 2,
 * a zeroed end (NUL bytes alone after its last newline, as a power cut leaves
 * it), which holds none either. Read under a shared lock, closed on return. */
int gw_sweep_journal_resume_check(const char *dir, const gw_sweep_config *cfg, char *done, long *ndone, int *exists,
                                  size_t *torn, int *torn_head, gw_err *err);

/* Every input file of cfg still has the content it had when cfg was read:
 * GW_OK, or GW_EINVAL "KEY 'VALUE' changed ... (content fnv1a64 A when the
 * sweep started, now B)" (or cannot be read any more). A sweep calls it before
 * it journals each finished row, so no row of a changed file is kept. */
int gw_sweep_inputs_check(const gw_sweep_config *cfg, gw_err *err);
/* The same for the input files case k reads (its own grid values and the
 * params; k < 0: every input). Checking every file of the grid after every
 * case read each of a grid's samples once per case: 18 samples x 50 speeds
 * (15 kB samples, t-max 1e-5) took 1.4 to 1.5 s against 1.0 to 1.1 s for one
 * sample, the extra time growing with the samples' size and number. */
int gw_sweep_case_inputs_check(const gw_sweep_config *cfg, long k, gw_err *err);

/* Append one row to DIR/journal.csv with a single write (and to the copy
 * gw_sweep_journal_held checks the file against, when the journal was opened
 * by gw_sweep_journal_open_at: GW_ENOMEM, nothing written, when the copy
 * cannot grow); fsync it when
 * *synced_ms (gw_clock_ms of the last fsync, updated; NULL: every row) is
 * GW_SWEEP_SYNC_MS old or more, or is no such time (NaN, or after now). A
 * killed process loses no written row; a power
 * cut at most the rows of the last GW_SWEEP_SYNC_MS, which a rerun runs again.
 * A row is one line ending in its newline (gw_sweep_format_row's): GW_EINVAL,
 * nothing written, for another (no newline, a newline inside, empty).
 * The journal's file is watched (inotify, where its limits allow): a write,
 * open, cut or attribute change by anyone between gw_sweep_journal_held's
 * check and this row's write makes the next gw_sweep_journal_held compare
 * the whole file (the times after this write are not the sweep's alone); a
 * sweep calls gw_sweep_journal_held right after each row too, so such a file
 * is kept at that row. */
#define GW_SWEEP_SYNC_MS 250.0
int gw_sweep_journal_append(int fd, const char *row, double *synced_ms, gw_err *err);
/* fsync the journal now (the sweep's end, or a stop): *synced_ms updated. */
int gw_sweep_journal_sync(int fd, double *synced_ms, gw_err *err);

/* Write DIR/results.csv (header, rows sorted by case) atomically from the journal. */
int gw_sweep_write_table(const char *dir, const gw_sweep_config *cfg, const gw_sweep_model *m,
                         gw_err *err);
/* The same in the directory dirfd held open (gw_sweep_journal_open_at; dir
 * names it in messages): its journal read and its table written there,
 * wherever it was moved. */
int gw_sweep_write_table_at(int dirfd, const char *dir, const gw_sweep_config *cfg, const gw_sweep_model *m,
                            gw_err *err);
/* The same with the sweep's warnings in the table, one "# warning: TEXT"
 * line each after the "# grid" lines (docs/formats.md): first each line of
 * warnings (a gw_warnings_add list, may be NULL: the check pass's, as the
 * caller said them, m->memo_warnings with gw_sweep_warnings_keys), then the
 * rows' (the cases that did not end, column converged 0, and the model's
 * rule over its rows, as gw_sweep_run_warned gives them), taken from the
 * journal's rows, so a resumed sweep's table is an uninterrupted one's byte
 * for byte. The rows' lines written are appended to *rows_warnings (may be
 * NULL) for the caller to say. gw_sweep_write_table(_at) write the rows'
 * alone. Each warning line is written as gw_warnings_add makes one (a
 * control character \r, \t or \xHH; a CR or an escape sequence went into
 * the table raw). A model of no columns (ncolumns < 1, columns or one of
 * them NULL) or of another count than its config's, and a config naming no
 * model, are GW_EINVAL naming them, nothing written (columns NULL: SIGSEGV). */
int gw_sweep_write_table_warned(int dirfd, const char *dir, const gw_sweep_config *cfg, const gw_sweep_model *m,
                                const char *warnings, char **rows_warnings, gw_err *err);

/* ---- running cases in memory (gw_sweep_run.c) ---- */

/* The memory this process may use, bytes: the smallest of the physical memory
 * and the address-space and data limits (ulimit -v, ulimit -d); *what names
 * the one that binds ("physical memory", "ulimit -v", "ulimit -d"). */
double gw_memory_available(const char **what);

/* The cases that run at once hold their memory together: with jobs workers
 * (<= 0: one per online CPU, never more than the cases), the jobs largest
 * estimates of m->memory over every case of cfg must sum to at most 80 % of
 * gw_memory_available (the rest for the program, its libraries and the
 * threads' stacks); processes != 0: the workers are processes on one node
 * (MPI ranks), each under its own limits, so the largest case is held to 80 %
 * of this process's limits and the sum to 80 % of the physical memory. GW_OK (also when the model has no estimate); GW_EINVAL with
 * "jobs: J cases at once need about X GB (the largest, case K, Y GB), above
 * 80 % of the Z GB available (W): at most M jobs" (or, when a single case does
 * not fit, "case K needs about Y GB alone ...: no number of jobs fits"); *most (may be NULL) gets the
 * most jobs that fit (0: none). A bad value: GW_EINVAL "case K: ...";
 * processes other than 0 or 1: GW_EINVAL naming it. */
int gw_sweep_memory_check(const gw_sweep_config *cfg, const gw_sweep_model *m, long jobs, int processes,
                          long *most, gw_err *err);

/* The journal and the table of cfg's sweep fit: the longest row model m can
 * write (its grid values, ncolumns numbers of at most 24 characters, the
 * hashes and the checksum) times the cases must stay within
 * GW_SWEEP_JOURNAL_MAX (the journal is read back whole to resume and to
 * write the table), and twice that with the writer's bookkeeping (48 bytes
 * a case) within 80 % of gw_memory_available (the journal read back beside
 * the copy a sweep keeps of what it wrote, gw_sweep_journal_held). A grid of 1e9 chain cases (about 330
 * GB of journal) was checked case by case for 80 minutes, ran, and could
 * never be read back. GW_OK, or GW_EINVAL "the grid has C cases: ...". */
int gw_sweep_size_check(const gw_sweep_config *cfg, const gw_sweep_model *m, gw_err *err);

/* gw_cases_run and gw_case_fn, the worker pool these run on: gw_pool.h. */

/* Every case of cfg run by model m in memory, no files: first every case is
 * checked (m->check, when the model has one: a bad value is refused before any
 * run) and the memory of jobs cases at once bounded (gw_sweep_memory_check),
 * then run on jobs threads (0: one per CPU; GW_EINVAL "jobs: ..." outside
 * [0, GW_SWEEP_JOBS_MAX]). values[k * m->ncolumns + j] receives column j
 * of case k (NaN for cases not run). GW_EINVAL / the first failing run's status
 * with "case K: message" in err; GW_ECANCELED when progress asked to stop.
 * A model whose run is NULL (called: SIGSEGV), of ncolumns below 1 (-1 wrote
 * before values), columns NULL or of another count than its config's is
 * GW_EINVAL "gw_sweep_run: model NAME: ...", nothing run. */
int gw_sweep_run(const gw_sweep_config *cfg, const gw_sweep_model *m, int jobs, gw_progress_fn progress,
                 void *pctx, double *values, gw_err *err);

/* gw_sweep_run, and the sweep's warnings appended to *warnings (a list of
 * gw_warnings_add, freed by the caller; NULL: none kept), the program's
 * lines: the check pass's (m->memo_warnings: a chain dt above the step the
 * cases take, layer cases on a sample settled under another material or not
 * settled), then the cases that did not end (gw_sweep_undecided_rows), then
 * the model's over its rows (a chain case's overlap beyond one radius, its
 * energy error above 1e-3 with energy-tol off; gw_sweep_rows_rule). */
int gw_sweep_run_warned(const gw_sweep_config *cfg, const gw_sweep_model *m, int jobs, gw_progress_fn progress,
                        void *pctx, double *values, char **warnings, gw_err *err);

/* The cases of values (ncases rows of m->ncolumns) whose column "converged"
 * is 0, the chain's collisions that did not end (held on the wall by gravity:
 * their undecided values NaN; cut at t_max: those at t_max), *first (may be
 * NULL) the first of them; 0 for a model without that column. */
long gw_sweep_undecided_rows(const gw_sweep_model *m, const double *values, long ncases, long *first);

/* The warning for n such cases of total, the first case first, appended to
 * *list (nothing when n <= 0): the one text of the program's sweep and of
 * gw_sweep_run_warned. GW_OK, GW_ENOMEM, or GW_EINVAL (nothing appended) for
 * n above total or a first case outside [0, total). */
int gw_sweep_undecided_warning(const gw_sweep_model *m, long n, long total, long first, char **list);

GW_END_DECLS

#endif
