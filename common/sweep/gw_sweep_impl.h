/*
 * gw_sweep_impl.h: what the files of the sweep module share and the library
 * does not export (it is built with -fvisibility=hidden; gw_sweep.h is the
 * module's public header). Errors as in gw_sweep.h: GW_EINVAL naming the
 * file, key or line, GW_ENOMEM, GW_EIO.
 */
#ifndef GW_SWEEP_IMPL_H
#define GW_SWEEP_IMPL_H

#include <stddef.h>

#include "gw_sweep.h"
#include "gw_io_impl.h"

/* gw_sweep_run.c: a case's pairs as a model's run, check and memory take
 * them (both models' prepare): nk >= 0, names and values given when nk > 0,
 * no name or value NULL, no key twice ('_' and '-' one, as in a config).
 * GW_EINVAL naming what ("nkeys: -1 is negative", "names[1] is NULL", "n:
 * given twice, pairs 1 and 2"): a negative count ran the defaults, GW_OK; a
 * NULL name crashed the layer model; a key twice ran its last value. */
int gw_sweep_pairs_check(const char *call, int nk, const char *const *names, const char *const *values,
                         gw_err *err);

/* gw_sweep_run.c: a model filled by the caller (gw_sweep.h's model
 * interface) is one the sweep can use: ncolumns at least 1, columns given
 * and none of its first ncolumns NULL, ncolumns the config's when it records
 * one (cfg->ncolumns > 0: its journal's rows hold that many), and with run
 * != 0 its run given. GW_EINVAL "CALL: model NAME: ..." otherwise: run NULL
 * was called (SIGSEGV), columns NULL read (SIGSEGV, the table's header),
 * ncolumns -1 or 0 wrote each case's numbers before or past values and a
 * table whose header had fewer cells than its rows. */
int gw_sweep_model_check(const char *call, const gw_sweep_config *cfg, const gw_sweep_model *m, int run,
                         gw_err *err);

/* gw_sweep_run.c: the warnings of cfg's check pass (gw_sweep_check_pass),
 * appended to *list with its config's keys named, as the program's sweep
 * says them and writes them into its table: GW_OK; a case refused, a key of
 * no effect on any case or no memory: its status, *list unchanged (nothing
 * said). */
int gw_sweep_check_warnings(const gw_sweep_config *cfg, const gw_sweep_model *m, char **list);

/* gw_sweep_rows.c: the warnings of a sweep name its config's keys: "--NAME"
 * in list, NAME a key of m (has_key), written NAME, in place. */
void gw_sweep_warnings_keys(const gw_sweep_model *m, char *list);

/* Append the lines w (a gw_warnings_add list, NULL: none) to *list: GW_OK,
 * GW_ENOMEM (*list as it was). */
int gw_sweep_warnings_append(char **list, const char *w);

/* gw_sweep_run.c: case k's check refused it (rc, err->msg naming the key
 * first, "rtol: has no effect with ..."): err becomes "case k: ...", and when
 * that key is a [params] key another case takes (the cases before k, then at
 * most 1000 after it, checked), the message names that case: [params] hold for
 * every case, so a key that fits only some goes in a sweep of those (a key
 * inert in a case is refused, never run as if it acted). Returns rc. */
int gw_sweep_case_refused(const gw_sweep_config *cfg, const gw_sweep_model *m, long k, int rc, gw_err *err);

/* gw_sweep_run.c: top and topk (n pairs: an estimate, its case) sorted by
 * estimate, decreasing, the first case first among equal ones (the memory
 * check's jobs largest estimates). gw_sweep_top_sort sorts a copy of the
 * pairs with qsort, or, when there is no memory for the copy, calls
 * gw_sweep_top_heapsort: the same order in place, O(n log n), no allocation. */
void gw_sweep_top_sort(double *top, long *topk, long n);
void gw_sweep_top_heapsort(double *top, long *topk, long n);

/* gw_sweep_config.c: a config filled by hand is consistent: grid keys and
 * params within GW_SWEEP_MAX_KEYS, each with a name and at least one value
 * (none NULL), ncases the grid's product (0 for a zeroed config), the inputs
 * given when counted. GW_EINVAL "sweep config: ..." otherwise. */
int gw_sweep_config_check(const gw_sweep_config *cfg, gw_err *err);

/* gw_sweep_config.c: a copy of s (malloc'd), NULL on ENOMEM. */
char *gw_sweep_strdup(const char *s);

/* gw_sweep_inputs.c: gw_sweep_case_inputs_check with the hashes kept in
 * memo (gw_io_hash_memo; NULL: each file hashed again) from one case to the
 * next: a sample stat finds unchanged since its last hash is not read again,
 * a sample written or replaced is (its status-change time or inode moved). */
int gw_sweep_case_inputs_check_memo(const gw_sweep_config *cfg, long k, gw_hash_memo *memo, gw_err *err);

/* gw_sweep_inputs.c: the config's directory (malloc'd; NULL with *status and
 * err set), its relative paths resolved from base, whether key name is the
 * model's read key (its values name files), and the files' hashes. */
char *gw_sweep_config_dir(const char *path, int *status, gw_err *err);
int gw_sweep_resolve_paths(gw_sweep_config *cfg, const char *base, const char *path, gw_err *err);
int gw_sweep_names_file(const gw_sweep_config *cfg, const char *name);
int gw_sweep_find_inputs(const char *path, gw_sweep_config *cfg, gw_err *err);
/* The rules of a model's own reader for the file its read_key names (the
 * layer's: a sample's, layer_sample_file_check), registered by the model
 * under its name (gw_sweep_model.name) from its object's constructor, before
 * main and any thread: the sweep applies them to each such file before it
 * reads a byte of it to hash it (the config's hash, the inputs' hashes, the
 * check after each case), since common/ does not know the models' readers. A
 * sparse 200 GB file named as the sample was hashed whole, for minutes,
 * before the case's reader refused its first byte. GW_OK, or the reader's
 * status and message naming the file. h not NULL: the file is then read whole
 * and its content hash put in *h, in the pass that checks the rest of it
 * (a text sample for a NUL byte anywhere, bounded as the reader is), so that a
 * file the reader would refuse is read once, up to its fault, not hashed whole
 * first (a text sample with 4 GiB of written zeros between its text and a
 * last line). At most 8 models; NULL: none. */
typedef int (*gw_sweep_input_rule)(const char *path, unsigned long long *h, gw_err *err);
void gw_sweep_input_rule_set(const char *model, gw_sweep_input_rule fn);
gw_sweep_input_rule gw_sweep_input_rule_of(const char *model);
/* Every value of cfg's read_key that names something passes its model's
 * gw_sweep_input_rule, before the config hashes it: GW_OK, or
 * GW_EINVAL (GW_ENOMEM, GW_EUNSUPPORTED as the check said) "PATH: [SECTION]
 * KEY: <the check's message>" (path: the config, for the message). Values
 * naming nothing are left to the model's check. */
int gw_sweep_inputs_readable(const gw_sweep_config *cfg, const char *path, gw_err *err);

/* The rule of a model's own parameter rows for one value given as text (the
 * layer's: its impact and placement rows, as gw_param_set takes them in a
 * case), registered as gw_sweep_input_rule is: GW_OK for a value a case of
 * that model takes (and for a name the model has no number row for), or
 * GW_EINVAL "NAME: reason" for one it refuses. layer-stats holds the
 * settings it reads from a table (its grid cells and "# param" lines) to it,
 * so that a table says only what a sweep of that model can have run: it
 * held them to a domain of its own, which took rb-rm = 1e308, vi = 1e308 or
 * a subnormal height that no sweep runs. At most 8 models; NULL: none. */
typedef int (*gw_sweep_value_rule)(const char *name, const char *value, gw_err *err);
void gw_sweep_value_rule_set(const char *model, gw_sweep_value_rule fn);
gw_sweep_value_rule gw_sweep_value_rule_of(const char *model);

/* A model's rule over its finished rows, for the warnings a single run of a
 * case gives that its row alone does not say (a chain case pressed beyond
 * one radius, or ending with a large energy error): acc_size bytes of
 * zeroed tally, row() called on each finished row (case k, its model
 * columns), then warnings() once, lines appended to *list saying how many of
 * the cases each concerns (gw_warnings_add; GW_OK or GW_ENOMEM). The
 * program's sweep calls it on the table it wrote (a resume's rows and MPI
 * ranks' too), gw_sweep_run_warned on its values. Registered by the model's
 * constructor (at most 8 models); NULL: none. */
typedef struct gw_sweep_rows_rule {
    size_t acc_size;
    void (*row)(void *acc, const gw_sweep_config *cfg, long k, const double *row);
    int (*warnings)(const void *acc, const gw_sweep_config *cfg, char **list);
} gw_sweep_rows_rule;
void gw_sweep_rows_rule_set(const char *model, const gw_sweep_rows_rule *rule);
const gw_sweep_rows_rule *gw_sweep_rows_rule_of(const char *model);

/* Whether value is one value that number row p (double, long, int, flag,
 * choice) takes, by gw_param_set_value's checks, nothing set ("n: '3:5' is
 * not an integer"); GW_OK for the other kinds of row (text, list, range:
 * their own readers judge a comma or a colon) and for p NULL. */
struct gw_param;
int gw_sweep_number_check(const struct gw_param *p, const char *value, gw_err *err);

/* gw_sweep_rows.c: a complete journal line's case number (-1: not a row of
 * ncases with a good checksum); why a line is not one of this sweep's rows
 * (static text, or msg filled; NULL: it is). */
long gw_sweep_line_case(const char *line, size_t len, long ncases);
const char *gw_sweep_line_fault(const char *line, size_t len, long ncases);
const char *gw_sweep_row_grid_fault(const gw_sweep_config *cfg, long k, const char *line, size_t len);
const char *gw_sweep_row_hash_fault(const gw_sweep_config *cfg, long k, const char *s, size_t len, int live,
                                    char *msg, size_t n);
const char *gw_sweep_row_values_fault(const gw_sweep_config *cfg, long k, const char *line, size_t len, char *msg,
                                      size_t n);

/* gw_sweep_head.c: a new journal's "# input", "# grid" and "# param" lines
 * (malloc'd, NULL on ENOMEM); an existing journal of another config or
 * format: which key or file differs (GW_OK when it cannot tell), an "# input"
 * line's hash, the first line's format (1 and *fmt, *hash; 2: a head no
 * granwave writes; 0: no granwave journal) and the first line for a message. */
char *gw_sweep_head_lines(const gw_sweep_config *cfg);
int gw_sweep_head_changed_keys(const gw_sweep_config *cfg, const char *buf, size_t len, const char *dir, gw_err *err);
int gw_sweep_head_input_hash(const char *path, long lineno, const char *line, const char *end, const char **at,
                             unsigned long long *h, gw_err *err);
int gw_sweep_head_changed_input(const gw_sweep_config *cfg, const char *buf, size_t len, const char *path,
                                const char *dir, gw_err *err);
int gw_sweep_head_format(const char *buf, size_t len, long *fmt, unsigned long *hash);
void gw_sweep_head_first_line(const char *buf, size_t len, char *out, size_t n);

/* gw_sweep_build.c: the build this process is, as a journal's "# build"
 * line records it (one printable line, at most GW_SWEEP_BUILD_MAX - 1 bytes;
 * the same for every call). */
#define GW_SWEEP_BUILD_MAX 384
const char *gw_sweep_build(void);

/* gw_sweep_journal.c: the journal read whole (a regular file only), in
 * chunks of 1 MiB into a buffer grown as they come, at most max bytes
 * (GW_SWEEP_JOURNAL_MAX at most) and no NUL byte: NULL with errno set (ENOENT
 * absent, ENOMEM, EINVAL for a journal above max or holding a NUL byte, said
 * naming it and its line) and err filled. */
char *gw_sweep_slurp(const char *path, size_t max, size_t *len, gw_err *err);
/* The same through fd (open on a regular file; read from its start, path
 * naming it in messages): a directory moved meanwhile is read still. */
char *gw_sweep_slurp_fd(int fd, const char *path, size_t max, size_t *len, gw_err *err);
/* gw_sweep_slurp_fd, a zeroed end taken (zeros non-NULL): when every byte
 * after the last newline is NUL (and one newline at least comes before them:
 * a power cut's end, which ext4's delayed allocation leaves as zeros), the
 * text up to that newline is returned, *len its bytes, and *zeros the NUL
 * bytes after it (0: none); a NUL anywhere else is refused as by
 * gw_sweep_slurp_fd. The caller cuts them (a resume) or counts them. */
char *gw_sweep_slurp_fd_zeros(int fd, const char *path, size_t max, size_t *len, size_t *zeros, gw_err *err);
/* The most bytes cfg's journal can hold: its head (every name and value,
 * twice over) and twice the longest row (gw_sweep_row_bound) for each case,
 * at most GW_SWEEP_JOURNAL_MAX (also when cfg->ncolumns is not known). A
 * journal above it is not this sweep's. */
size_t gw_sweep_journal_bound(const gw_sweep_config *cfg);
/* gw_sweep_rows.c: the longest journal row of cfg with ncolumns numbers, bytes
 * (its case number, grid values, numbers, hashes and checksum). */
double gw_sweep_row_bound(const gw_sweep_config *cfg, int ncolumns);
/* The sweep's directory opened for the *at calls (O_DIRECTORY, O_CLOEXEC; by
 * O_PATH where it may be searched but not read), -1 with errno set. */
int gw_sweep_dir_open(const char *dir);

/* gw_sweep_journal.c: close a sweep's journal fd (gw_sweep_journal_open_at's)
 * and free the copy of what it holds that the sweep kept beside it (the
 * shadow gw_sweep_journal_held checks the file against). The copies were
 * freed only at exit: a process that opened journals in turn (each closed by
 * close()) kept every copy, and once 16 were held a new journal got none and
 * went unchecked for a rewrite in place. fd < 0: nothing. */
void gw_sweep_journal_close(int fd);

/* A model's case cost, known before it runs, for `granwave sweep`'s time
 * left (app/sweep_cmd.c, gw_pool_eta_weigh): weight returns case's expected
 * run time in the model's own unit (only the ratio between a sweep's cases
 * counts), NaN where it cannot tell (a bad value: the run says so). A pass
 * over the cases keeps *memo (NULL at its first call; one thread), freed by
 * memo_free (NULL-safe; NULL: the model keeps none). Internal: the program's
 * only, neither in gw_sweep_model (a public struct) nor exported. */
typedef struct gw_sweep_weigh {
    double (*weight)(void **memo, int nkeys, const char *const *names, const char *const *values, int *kind);
    void (*memo_free)(void *memo);
} gw_sweep_weigh;
/* weight's *kind (set to -1 first: none): the case's kind, in [0, 64), the
 * cases of one kind sharing a cost per weight the weight does not hold (its
 * backend and method, a layer case's mode): the time left learns each
 * kind's from its ended cases (gw_pool_eta_kinds). GW_SWEEP_KIND gives one
 * from a backend (NULL, cvode, arkode, rk4, verlet, another), its method
 * (GW_METHOD_*, 0 to 5) and a flag (0, 1). */
#define GW_SWEEP_KIND(type, method, flag)                                                                   \
    ((((type) == gw_solver_cvode ? 1 : (type) == gw_solver_arkode ? 2 : (type) == gw_solver_rk4 ? 3       \
       : (type) == gw_solver_verlet ? 4 : 0) * 6 + ((method) >= 0 && (method) < 6 ? (method) : 0)) * 2 +   \
     ((flag) ? 1 : 0))
/* chain/chain_sweep_model.c: chain_watch_weight of the case's column (its
 * beads times its steps and samples over its expected length, as a study's
 * collisions are planned). */
extern const gw_sweep_weigh gw_chain_sweep_weigh;
/* layer/layer_sweep_model.c: the bodies times the steps over the run's
 * expected simulated length (layer_sweep_model.c). */
extern const gw_sweep_weigh gw_layer_sweep_weigh;

/* How long gw_sweep_journal_held watches a journal's free name before it puts
 * the journal back: an editor's save through a rename (the journal renamed
 * to a backup, or removed, and the new file written) takes milliseconds.
 * A save slower than that writes into the journal put back: found at the
 * next row by the check of what the journal holds (gw_sweep_journal_held),
 * which a longer watch would only have delayed. */
#define GW_SWEEP_GRACE_MS 200.0

#endif
