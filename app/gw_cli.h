/*
 * gw_cli.h: the program's option parser (gw_cli.c): options described by
 * gw_opt tables, parsed from argv, with --help from the same table; and what
 * the program adds to its outputs (gw_cli_out.c): the provenance header and
 * the progress lines. Used by the commands; not one of the library's public
 * headers (not installed).
 */
#ifndef GW_CLI_H
#define GW_CLI_H

#include <stdio.h>

#include "gw_common.h"

/* ---- command-line options ---- */

struct gw_param; /* gw_param.h */

/* GW_OPT_COUNT: a count held as a double (a library field of that type,
 * min-bins): a real as GW_OPT_DOUBLE's ("30", "30.0", "3e1", as Python's
 * keyword gives it), taken only when a whole number in [lo, hi] (whole
 * ends), its range printed as integers and its help's kind "integer". */
typedef enum { GW_OPT_FLAG, GW_OPT_DOUBLE, GW_OPT_LONG, GW_OPT_STRING, GW_OPT_COUNT } gw_opt_kind;

typedef struct gw_opt {
    const char *name;    /* option "--name" */
    gw_opt_kind kind;
    void *dest;          /* int* (flag), double* (double, count), long*, const char** */
    const char *metavar; /* shown in --help, e.g. "N" */
    const char *help;    /* one line, with units and default */
    double lo, hi;       /* accepted range for numbers (inclusive) */
    int open_lo;         /* 1: value must be > lo */
    int open_hi;         /* 1: value must be < hi */
    int seen;            /* set by the parser */
    const struct gw_param *param; /* NULL, or the parameter-table row (gw_param.h)
                                     that checks the value, by the library's rule
                                     (gw_param_set_value): dest is then a field of
                                     the row's type, or for a choice or text row
                                     a const char * pointing into argv */
} gw_opt;

/* Parse argv[0..argc) against opts (terminated by name == NULL). Accepts
 * "--name value" and "--name=value"; "--help"/"-h" sets *help; "--" ends the
 * options (every argument after it is positional, "--help" too); "--json"
 * with --help makes *help GW_CLI_HELP_JSON. Positional
 * arguments go to pos (at most maxpos; more is an error). Returns GW_EINVAL with
 * a message naming the option on unknown options, missing or bad values, and on
 * an option given twice ("CMD --NAME: given twice"; --help may repeat). */
int gw_cli_parse(const char *cmd, gw_opt *opts, int argc, char **argv, int *help,
                 const char **pos, int maxpos, int *npos, gw_err *err);
/* The option of table row p (gw_param.h) writing into dest: name, metavar,
 * help, range and kind from the row (double -> GW_OPT_DOUBLE into a double,
 * count -> GW_OPT_COUNT into a double, long -> GW_OPT_LONG into a long, flag -> GW_OPT_FLAG into an int, choice and
 * text -> GW_OPT_STRING into a const char *), the value checked by the row; the
 * row's default is written into dest (a choice or text default as the row's
 * static text, NULL when it has none; an optional row's "not given": NaN,
 * GW_PARAM_UNSET_LONG, NULL). Int rows are not supported (GW_EINVAL, a table
 * bug). */
int gw_cli_opt_param(const struct gw_param *p, void *dest, gw_opt *o, gw_err *err);
/* gw_cli_parse's *help when --json came with --help (in either order; for a
 * table without a --json option too, where --json alone stays unknown) */
#define GW_CLI_HELP_JSON 2
/* the help line of --help, which every command has */
#define GW_CLI_HELP_TEXT "show this help and exit"
/* Print usage and every option's help (help: gw_cli_parse's *help), a
 * number option with a bound with its range: its text's ("in [1e-6, 1]"), or
 * where the text states none, the parser's put in before the default's
 * brackets (", in [1, 50000000] [1]"). With
 * help GW_CLI_HELP_JSON, one JSON object on stdout instead, from the same
 * table: {"command", "usage", "summary", "options": [{"name", "metavar",
 * "kind" (flag, number, integer, text, choice), "unit" (the row's), "range"
 * (as the help line prints it, "[1e-6, 1]"), "min", "max" (the accepted bounds),
 * "default" (as the help prints it, else the row's; a flag's false),
 * "choices", "help" (the text help's line)}]}, --help last (docs/cli.md).
 * Returns the exit status:
 * 0, or 1 when the JSON could not be printed (gw_cli_json_stdout). */
int gw_cli_help(FILE *fp, const char *cmd, const char *usage, const char *summary, const gw_opt *opts, int help);
/* The option named name, or NULL. */
const gw_opt *gw_cli_find(const gw_opt *opts, const char *name);

/* ---- provenance: the header of every output (gw_cli_out.c) ----
 * Every table, trace, sample and HDF5 "run" attribute the commands write starts
 * with the same text, built here only:
 *   granwave VERSION
 *   command: granwave CMD ARG1 ARG2 ...
 *   settings: {"one-line":"JSON of every setting, defaults included"}
 * Text files carry it as comment lines (gw_write_comment, gw_common.h); the
 * library takes it as a string from the program. All return a new string the
 * caller frees, NULL when out of memory. */

/* "granwave CMD ARG1 ARG2 ...": argv as a POSIX shell (bash, sh) reads it back,
 * one line: arguments with blanks, quotes or other special characters in single
 * quotes, those with control characters (a newline) in $'...'. */
char *gw_cli_command_line(const char *cmd, int argc, char **argv);
/* The header above; settings NULL: no settings line. */
char *gw_cli_provenance(const char *cmd, int argc, char **argv, const struct cJSON *settings);
/* hdr + "\nKEY: " + value as one-line JSON. Takes hdr (freed; NULL in, NULL
 * out); value NULL returns hdr unchanged. */
char *gw_cli_provenance_add(char *hdr, const char *key, const struct cJSON *value);
/* Newlines of text replaced by sep in place (the one-line "# " header of the
 * falcon, wavespeed and layer-impact tables); returns text. */
char *gw_cli_one_line(char *text, char sep);

/* ---- progress lines on stderr (gw_cli_out.c) ----
 * One line per report: "PREFIXd/n UNIT[ (b done before)], R UNIT/s, E s
 * elapsed, ~L s left". Pass gw_cli_progress_report and the display as the
 * library's gw_progress_fn and its context; it never asks to stop. */
typedef struct gw_cli_progress {
    const char *prefix;  /* start of each line: "sweep: ", "  " */
    const char *unit;    /* what is counted: "cases", "collisions" */
    long before;         /* units finished by an earlier run (< 0: not shown) */
    double every_ms;     /* > 0: a line at most every every_ms; 0: every tenth */
    double after_ms;     /* > 0: no line before the run has lasted after_ms, the
                            last one included: a shorter run says nothing (a
                            single run whose length varies a thousandfold) */
    int quiet;           /* 1: print nothing */
    const char *header;  /* NULL, or a line printed once before the first report
                            (a refusal before any run then stays one line) */
    FILE *fp;            /* stderr */
    double t0, last;     /* gw_clock_ms at init and at the last line */
} gw_cli_progress;

/* The environment variable that sets every progress display's delay and
 * period, in ms, for tests and scripts whose output must not depend on the
 * machine's speed: 0 prints at once (every_ms and after_ms 0: a line each
 * tenth of a count, each report of a run or study), a large value (1e9) never
 * before the run's end (and then nothing where after_ms applies). Unset: the
 * commands' own (2 s, layer-make's 3 s). */
#define GW_CLI_PROGRESS_ENV "GW_PROGRESS_MS"
/* Read GW_CLI_PROGRESS_ENV once, before any command runs: 0 when unset or a
 * number of ms >= 0; -1, with one line on stderr naming it, when malformed
 * (the program then exits 2). */
int gw_cli_progress_env(void);
/* The delay or period ms a command asks for, or GW_CLI_PROGRESS_ENV's value
 * when set: every display's every_ms and after_ms are taken through it. */
double gw_cli_progress_ms(double ms);
/* A display starting now, writing to stderr, before = -1, not quiet;
 * every_ms through gw_cli_progress_ms. */
void gw_cli_progress_init(gw_cli_progress *p, const char *prefix, const char *unit, double every_ms);
/* gw_progress_fn: a line after the last unit and when due; returns 0. */
int gw_cli_progress_report(void *ctx, long done, long total);
/* A column's time left (granwave chain's progress lines). The run's cost is
 * not spread evenly over its simulated time x = t / t_expect: measured on
 * chain --n 200, 400 and 600 (CPU per unit of x against the first half's),
 * cvode's BDF runs 3.2, 4.6 and 5.4 times slower while the column's top opens
 * (x 0.5 to 0.65: a restart at each opening), 1.1, 1.7 and 2.0 times as it
 * eases (to x 0.8), at 0.55 to 0.6 of the first half's pace to the wall's
 * release (x 1.05), 0.75 to 0.9 during it (to x 1.15), and once every contact
 * is open at 0.05 to 0.07; rk4 and arkode's erk keep within 0.88 to 1.1 of it
 * throughout. And the run goes on past t_expect until its last closing pair
 * has met and parted, which no prior says: 1.2 to 7.6 times t_expect at N =
 * 50 to 600 (chain --n 600: 113.7 ms against 15.0 ms expected), known once
 * the column flies free (t_end, from its state). The time left sums the x
 * left in each phase (gw_cli_column_starts) times the first half's measured
 * pace times the phase's weight (cvode's: 3.2 sqrt(N / 200), 1.1 (N /
 * 200)^0.6, 0.57, 0.82, 0.06); in the free flight, once it has run 0.05 of x,
 * its own measured pace. */
#define GW_CLI_COLUMN_PHASES 6
typedef struct gw_cli_column {
    int n;        /* beads */
    int restarts; /* 1: cvode (the weights above); 0: rk4, arkode (even) */
    double t_end; /* > 0: the run's end as the column's state says it, s (every
                     contact open, bead 1 off the wall: the last closing pair's
                     meeting plus its contact, or now when none closes); 0 while
                     contacts act */
    double t_meet;                    /* that pair's meeting, s (0: none) */
    double el0[GW_CLI_COLUMN_PHASES]; /* s elapsed when x entered each phase (< 0 before) */
    double x0[GW_CLI_COLUMN_PHASES];  /* and x then */
    double el_free, x_free;           /* s elapsed and x when t_end was first known (< 0 before) */
} gw_cli_column;
/* Where each phase of x starts (the last runs on to any x). */
extern const double gw_cli_column_starts[GW_CLI_COLUMN_PHASES];
/* Until the column's state says its end, the line's time left runs to x =
 * GW_CLI_COLUMN_END_GUESS (the ends at N = 50 to 400 ran from 1.21 to 1.93
 * times t_expect, and 7.6 at N = 600) and says so: "~L s left or more". */
#define GW_CLI_COLUMN_END_GUESS 1.3
void gw_cli_column_init(gw_cli_column *c, int n, int restarts);
/* Record that the run is at x after el s (every report: the phases' starts,
 * and the free flight's once t_end > 0). */
void gw_cli_column_note(gw_cli_column *c, double el, double x);
/* The time left, s, from x after el s to x_end (0 when x_end <= x; NaN before
 * any time or x has passed). */
double gw_cli_column_left(const gw_cli_column *c, double el, double x, double x_end);
/* Progress of one run in simulated time, whose length is known only roughly
 * (a collision: gw_chain_progress_fn's t, t_expect, t_max, s). One line when
 * due ("PREFIXt = T ms of ~E ms expected (P%), X s elapsed, ~L s left"; past
 * t_expect "... (P%, t-max M ms), X s elapsed, at most ~L s left"), or, last 1,
 * the run's end at t ("... (P%): ended, X s elapsed"); at t = 0, no pace yet,
 * the line ends at "X s elapsed" without L. With a column (col not NULL, noted
 * at every call) L is gw_cli_column_left's: to its t_end once known ("~L s
 * left (the last closing pair meets at about T ms)"), before that to
 * GW_CLI_COLUMN_END_GUESS times t_expect ("~L s left or more"), and past that
 * with contacts still acting the t-max line. Due: the first at
 * after_ms, then every max(every_ms, a twentieth of the time elapsed) up to
 * GW_CLI_PROGRESS_GAP_MAX_MS, so an hours-long run says where it is without a
 * line every few seconds, nor goes silent for minutes. */
void gw_cli_progress_time(gw_cli_progress *p, gw_cli_column *col, double t, double t_expect, double t_max, int last);
/* A study's first progress line (falcon, wavespeed, softwall), ms after its
 * start, and the shortest gap between two: as a single run's. */
#define GW_CLI_STUDY_PROGRESS_MS 2000.0
/* The longest gap between two lines of a run or a study (gw_cli_progress_time,
 * gw_cli_progress_part), ms: a twentieth of the time elapsed, but a line at
 * least every 30 s however long the run has lasted. */
#define GW_CLI_PROGRESS_GAP_MAX_MS 30000.0
/* The gap due after el_ms of run: max(every_ms, el_ms / 20), at most
 * GW_CLI_PROGRESS_GAP_MAX_MS (or every_ms if that is longer). */
double gw_cli_progress_gap(const gw_cli_progress *p, double el_ms);
/* A study's progress within its collisions (gw_chain_watch_fn's done, total,
 * part): "PREFIXk/n UNIT, P% of the work, E s elapsed, ~L s left" (without
 * ", ~L s left" while part is 0: no work measured, no time left to give), the
 * header before the first, each line one write. Due as gw_cli_progress_time's: the
 * first once every_ms has passed, then every gw_cli_progress_gap; last 1: the
 * line now, at 100%. Not locked: the caller calls it one call at a time (the
 * study's lock, then the main thread once the study has returned). */
void gw_cli_progress_part(gw_cli_progress *p, long done, long total, double part, int last);
/* gw_cli_progress_part as a study's gw_chain_watch_fn (ctx the display). */
void gw_cli_progress_watch(void *ctx, long done, long total, double part);
/* The unit a simulated length t (s) prints in, "s", "ms" or "us", and into
 * *scale that unit's count in 1 s: one choice for every progress line. */
const char *gw_cli_time_unit(double t, double *scale);

/* A number for a text output: v printed with fmt (one conversion of a double)
 * into buf, or "n/a" where v is not finite, the JSON's null (a period from one
 * maximum, a spread of one value): one spelling in every command's text. */
#define GW_CLI_NA "n/a"
const char *gw_cli_num(char *buf, size_t n, const char *fmt, double v);

/* A study's setup (table t) from the command line: every option of argv that is
 * a row of t is set from its text with the table's checks (the command's own
 * parse ran first with the same names and ranges). GW_EINVAL "CMD --NAME: ...". */
int gw_cli_study_setup(const struct gw_param *t, void *setup, const gw_opt *opts, int argc, char **argv,
                       const char *cmd, gw_err *err);
/* A library message "NAME: reason" as "CMD --NAME: reason" when NAME is a row of t,
 * else "CMD: NAME: reason", but as it is when it names CMD already ("CMD: reason"). */
int gw_cli_study_error(const struct gw_param *t, const char *cmd, int rc, gw_err *err);
/* A result's warnings (gw_common.h, "warnings of a result"; may be NULL), the
 * library's texts: each on stderr as "granwave CMD: warning: TEXT". */
void gw_cli_warnings(const char *cmd, const char *list);
/* The same texts as the array "warnings" of o (empty when list is NULL or
 * empty), so that a script reading --json or an --out JSON file sees what
 * stderr said (layer-impact's and layer-stats' JSON, Python's results). */
void gw_cli_json_warnings(struct cJSON *o, const char *list);
/* o (a command's --json result; NULL when it could not be built) printed on
 * stdout: 0, or 1 after "granwave CMD: out of memory for the JSON result" on
 * stderr when it could not be printed whole (nothing is printed then), or 1
 * after gw_cli_stdout_failed when stdout could not be written. */
int gw_cli_json_stdout(const char *cmd, const struct cJSON *o);
/* stdout could not be written (errno e of the failed write; 0: unknown, said
 * as EIO): "granwave[ CMD]: stdout: write failed: REASON" on stderr, stdout's
 * error flag cleared (said once, by the writer that saw the errno: the
 * program's last check of stdout then finds nothing new); returns 1. */
int gw_cli_stdout_failed(const char *cmd, int e);
/* A failure's message on stderr as "granwave CMD: MSG", or "granwave MSG"
 * when MSG already names the command ("layer-impact: out of memory ...", the
 * parser's "layer-impact --vi: ..."), so that no line says it twice. */
void gw_cli_error(const char *cmd, const char *msg);
/* "granwave CMD: out of memory" on stderr; returns 1 (a run failure, not bad
 * input: the command line was not read wrong). */
int gw_cli_nomem(const char *cmd);
/* A path the program echoes (a file written, a directory), as one line
 * (gw_one_line: a newline in an --out name printed \n, not a raw line
 * break); into buf (n bytes, GW_CLI_PATH_TEXT holds any), returns buf. */
#define GW_CLI_PATH_TEXT 4096
const char *gw_cli_path(char *buf, size_t n, const char *path);


/* --out made only as far as needed and taken back on a refusal:
 * gw_cli_mkdir_out makes path (gw_mkdir_p) and puts into made the shallowest
 * directory it created ("" when path existed); gw_cli_unmake removes the empty
 * directories from path up to made. */
int gw_cli_mkdir_out(const char *path, char *made, size_t n, gw_err *err);
void gw_cli_unmake(const char *path, const char *made);
/* An output set in --out dir, dir made first (gw_cli_mkdir_out; s zeroed,
 * made "" on a failure, which leaves nothing made), and its end:
 * gw_cli_outset_end aborts the set (nothing after its commit) and, unless
 * placed (the commit succeeded), removes the empty directories the begin made,
 * as a refused run leaves none. Every command's --out set goes through the
 * pair: chain, drop, dispersion, falcon and wavespeed left an empty --out
 * NEW (NEW/a/b: three) when a write failed (a full disk, ulimit -f), which
 * layer-impact alone took back. */
int gw_cli_outset_begin(gw_outset *s, const char *dir, const char *const *names, char *made, size_t n,
                        gw_err *err);
void gw_cli_outset_end(gw_outset *s, const char *dir, const char *made, int placed);

#endif
