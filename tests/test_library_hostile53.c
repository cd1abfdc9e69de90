/*
 * test_library_hostile53.c: the fifty-third hostile pass over the library's
 * C interface (docs/library.md "The contract of every call"), aimed at the
 * entry points added since the fifty-second (gw_chain_sweep_n_warned,
 * gw_sweep_write_table_warned, gw_chain_drop_result's chatter_rerun,
 * gw_layer_impact_check_with, the column's work bound) and at what the
 * forty-fifth session left ("granwave.sweep_n((1, 2), [0.3, 0.3]) runs a
 * speed twice"). About 120 calls: the grid's speeds repeated, near (1 ulp,
 * 1e-12, 1e-9 apart), NaN, inf, negative, nv 0, -1, INT_MIN, the range
 * reversed and at INT_MAX, the three grid calls each; the table's warnings
 * given control bytes, escape sequences, broken UTF-8, empty lines, no
 * final newline, a NULL list; hand drop results of chatter_rerun 99,
 * INT_MIN and STEP with run_dt NaN, -1, 0, inf, 1e-300; the side walls'
 * check with lp NaN, inf, NULL. What it found:
 *   - gw_chain_sweep_n, _progress and _warned ran a speed given twice (or two
 *     speeds the same to 12 digits) twice, into two rows of the result;
 *     falcon refuses them (gw_chain_study_speeds_check) and a chain sweep's
 *     config refuses a value listed twice: each call refuses it naming v and
 *     both items (the config's rule: equal, or within a relative 1e-12),
 *     nothing run, nothing appended to the warnings.
 *   - gw_sweep_write_table_warned wrote a caller's warning lines raw into
 *     the table: a CR, an escape sequence (ESC [31m) or a byte of no UTF-8
 *     character went through to the "# warning:" line that layer-stats says
 *     to a terminal. Each line is written as gw_warnings_add makes one
 *     (\r, \x1b, \xff).
 *   - gw_chain_drop_result_warnings of a hand result whose chatter is rerun
 *     at half rk4's step (GW_CHAIN_RERUN_STEP) and whose run_dt is no step
 *     said "compare a run at --dt nan (half the step)" (-1: "--dt -0.5", 0:
 *     "--dt 0", inf: "rk4's step halved, inf s"): the step is said not
 *     recorded.
 *   - gw_chain_study_work_check said a range just above its bound in 3
 *     digits, as the bound: "n: 1415:1415 at 1 column per N is 2e+06 bead^2
 *     of work ..., above the bound 2e+06" (granwave.sweep_n((1415, 1415),
 *     ...)): in the digits that tell it from the bound (2002225).
 * Each case runs in its own child process (test_child.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "granwave.h"
#include "gw_sweep.h"
#include "gw_test_cases.h"
#include "test_child.h"

/* ----------------------------------------------- the grid's speeds ---- */

enum { CALL_PLAIN, CALL_PROGRESS, CALL_WARNED };

/* the grid N = 1..2 over v (nv speeds) by one of the three calls; *w the
 * warnings list (CALL_WARNED), res of nv * 2 results, freed here */
static int grid(int call, const double *v, int nv, char **w, gw_err *e)
{
    gw_chain_params p = gw_chain_params_default();
    gw_chain_run_opts o = gw_chain_run_opts_default();
    gw_chain_result res[8];
    memset(res, 0xA5, sizeof res); /* zeroed by the call once the grid's shape passed */
    int rc = call == CALL_PLAIN      ? gw_chain_sweep_n(&p, &o, v, nv, 1, 2, 1, 0, res, e)
             : call == CALL_PROGRESS ? gw_chain_sweep_n_progress(&p, &o, v, nv, 1, 2, 1, NULL, NULL, res, e)
                                     : gw_chain_sweep_n_warned(&p, &o, v, nv, 1, 2, 1, NULL, NULL, res, w, e);
    for (int i = 0; i < 2 * nv && i < 8; i++) {
        if (rc != GW_OK && res[i].stats.steps != 0) { /* a refused grid runs nothing */
            printf("call %d: refused, but case %d took %ld steps\n", call, i, (long)res[i].stats.steps);
            return -999;
        }
        gw_chain_result_free(&res[i]);
    }
    return rc;
}

/* each call refuses v, its message ending in want, nothing appended */
static int refused_all(const double *v, int nv, const char *want)
{
    for (int call = CALL_PLAIN; call <= CALL_WARNED; call++) {
        gw_err e = {{0}};
        char *w = NULL;
        const int rc = grid(call, v, nv, &w, &e);
        const char *at = strstr(e.msg, "gw_chain_sweep_n: v: ");
        if (rc != GW_EINVAL || !at || strcmp(at + strlen("gw_chain_sweep_n: v: "), want) != 0 || w) {
            printf("call %d, nv %d: status %d, message '%s', warnings '%s' (want '... %s')\n", call, nv, rc, e.msg,
                   w ? w : "(none)", want);
            free(w);
            return 1;
        }
    }
    return 0;
}

static int c_grid_speed_twice(void)
{
    const double v[] = {0.3, 0.3};
    EXPECT(refused_all(v, 2, "item 2 is the impact velocity 0.3 m/s of item 1 (each of its collisions would run "
                             "twice)") == 0);
    const double w[] = {0.2, 0.4, 0.4, 0.2}; /* the first repeat by its later item: items 2 and 3 */
    EXPECT(refused_all(w, 4, "item 3 is the impact velocity 0.4 m/s of item 2 (each of its collisions would run "
                             "twice)") == 0);
    const double x[] = {0.5, 0.2, 0.5};
    EXPECT(refused_all(x, 3, "item 3 is the impact velocity 0.5 m/s of item 1 (each of its collisions would run "
                             "twice)") == 0);
    return 0;
}

static int c_grid_speed_near(void)
{
    const double v[] = {0.3, 0.30000000000000004}; /* 1 ulp apart */
    EXPECT(refused_all(v, 2, "item 2, 0.30000000000000004 m/s, and item 1, 0.3 m/s, are the same impact velocity "
                             "to 12 digits (each of its collisions would run twice)") == 0);
    const double w[] = {1.0, 0.7, 1.0 + 5e-13};
    EXPECT(refused_all(w, 3, "item 3, 1.0000000000005 m/s, and item 1, 1 m/s, are the same impact velocity to 12 "
                             "digits (each of its collisions would run twice)") == 0);
    return 0;
}

/* controls: speeds a relative 1e-9 apart are two speeds (the grid has no fit
 * over them), each call runs them; a NaN speed, nv 0 and -1 and the range
 * reversed keep their own refusals */
static int c_grid_distinct_control(void)
{
    const double v[] = {0.3, 0.3 * (1 + 1e-9)};
    for (int call = CALL_PLAIN; call <= CALL_WARNED; call++) {
        gw_err e = {{0}};
        char *w = NULL;
        EXPECT(grid(call, v, 2, &w, &e) == GW_OK);
        free(w);
    }
    gw_chain_params p = gw_chain_params_default();
    gw_chain_run_opts o = gw_chain_run_opts_default();
    gw_chain_result res[4];
    gw_err e = {{0}};
    const double bad[] = {NAN, NAN};
    EXPECT(gw_chain_sweep_n_warned(&p, &o, bad, 2, 1, 2, 1, NULL, NULL, res, NULL, &e) == GW_EINVAL &&
           !strstr(e.msg, "item 2") && strstr(e.msg, "nan"));
    const double inf[] = {INFINITY, INFINITY};
    EXPECT(gw_chain_sweep_n_warned(&p, &o, inf, 2, 1, 2, 1, NULL, NULL, res, NULL, &e) == GW_EINVAL &&
           !strstr(e.msg, "item 2"));
    const int nvs[] = {0, -1, INT_MIN};
    for (int i = 0; i < 3; i++)
        EXPECT(gw_chain_sweep_n_warned(&p, &o, v, nvs[i], 1, 2, 1, NULL, NULL, res, NULL, &e) == GW_EINVAL &&
               strstr(e.msg, "empty grid"));
    EXPECT(gw_chain_sweep_n_warned(&p, &o, v, 1, 3, 2, 1, NULL, NULL, res, NULL, &e) == GW_EINVAL &&
           strstr(e.msg, "empty grid"));
    return 0;
}

/* ------------------------------------------- the table's warnings ---- */

static const char *const one_columns[] = {"y"};

static int one_has(const char *name)
{
    return strcmp(name, "a") == 0;
}

static int one_run(int nk, const char *const *names, const char *const *values, double *out, unsigned long long *h,
                   gw_err *err)
{
    (void)nk;
    (void)names;
    (void)h;
    (void)err;
    out[0] = 2 * atof(values[0]);
    return GW_OK;
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *b = calloc(1, 1 << 16);
    if (b)
        fread(b, 1, (1 << 16) - 1, f);
    fclose(f);
    return b;
}

/* the model as the table's writer is given it: ncolumns and columns set
 * after the config was read (ncol 1, one_columns: as read); zero: a zeroed
 * config journaled */
static int t_ncol = 1, t_zero = 0;
static const char *const *t_columns = one_columns;

/* a sweep of the model "one" over a = 1, 2 journaled by hand in a new
 * directory, its table written with warnings; *table what it holds (NULL:
 * none written) */
static int table_with(const char *warnings, char **table, char **rows_w, gw_err *e)
{
    char dir[] = "/tmp/gw_hostile53.XXXXXX";
    if (!mkdtemp(dir))
        return -1;
    gw_sweep_model m;
    memset(&m, 0, sizeof m);
    m.name = "one";
    m.ncolumns = 1;
    m.columns = one_columns;
    m.has_key = one_has;
    m.run = one_run;
    const gw_sweep_model *models[1] = {&m}, *got = NULL;
    gw_sweep_config cfg;
    memset(&cfg, 0, sizeof cfg);
    int rc = t_zero ? GW_OK
                    : gw_sweep_config_read_string("[sweep]\nmodel = one\n[grid]\na = 1, 2\n", "one.ini", models, 1,
                                                  &cfg, &got, e);
    char done[2] = {0, 0};
    long ndone = 0;
    int fd = -1, dfd = -1;
    if (rc == GW_OK)
        rc = gw_sweep_journal_open_at(dir, &cfg, done, &ndone, &fd, &dfd, e);
    double synced = 0;
    for (long k = 0; rc == GW_OK && k < cfg.ncases; k++) {
        char row[512];
        const double out = 2.0 * (double)(k + 1);
        rc = gw_sweep_format_row(&cfg, k, &out, 1, 0, row, sizeof row);
        if (rc == GW_OK)
            rc = gw_sweep_journal_append(fd, row, &synced, e);
    }
    m.ncolumns = t_ncol;
    m.columns = t_columns;
    if (rc == GW_OK)
        rc = gw_sweep_write_table_warned(dfd, dir, &cfg, &m, warnings, rows_w, e);
    char path[600];
    snprintf(path, sizeof path, "%s/results.csv", dir);
    *table = slurp(path);
    unlink(path);
    snprintf(path, sizeof path, "%s/journal.csv", dir);
    unlink(path);
    rmdir(dir);
    if (fd >= 0)
        close(fd);
    if (dfd >= 0)
        close(dfd);
    gw_sweep_config_free(&cfg);
    return rc;
}

/* the table's warning lines, one line each, control bytes and bytes of no
 * UTF-8 character escaped as gw_warnings_add escapes them */
static int c_table_warnings_escaped(void)
{
    char *t = NULL, *rw = NULL;
    gw_err e = {{0}};
    EXPECT(table_with("a\rb\n\x1b[31mred\x1b[0m\nbad \xff byte\ttab\n\nlast without newline", &t, &rw, &e) == GW_OK);
    EXPECT(t != NULL);
    const int ok = strstr(t, "# warning: a\\rb\n# warning: \\x1b[31mred\\x1b[0m\n# warning: bad \\xff byte\\ttab\n"
                             "# warning: last without newline\ncase,a,y,") != NULL;
    int raw = 0;
    for (const char *c = t; *c; c++)
        raw += (*c != '\n' && (unsigned char)*c < 0x20) || (unsigned char)*c == 0xff;
    if (!ok || raw) {
        printf("%d raw bytes; table:\n%s\n", raw, t);
        return 1;
    }
    free(t);
    free(rw);
    return 0;
}

/* controls: plain lines and UTF-8 kept byte for byte; a NULL list writes
 * none; the rows' warnings NULL kept NULL (no row undecided) */
static int c_table_warnings_control(void)
{
    char *t = NULL, *rw = NULL;
    gw_err e = {{0}};
    EXPECT(table_with("plain line\nµm and ° kept\n", &t, &rw, &e) == GW_OK && t);
    EXPECT(strstr(t, "# warning: plain line\n# warning: µm and ° kept\ncase,a,y,") != NULL);
    EXPECT(rw == NULL);
    free(t);
    EXPECT(table_with(NULL, &t, &rw, &e) == GW_OK && t && !strstr(t, "# warning:"));
    free(t);
    return 0;
}

/* a model of no columns, of another count than its config's, and a config
 * naming no model: refused naming them, no table (columns NULL: SIGSEGV;
 * ncolumns 0 and -1 wrote a header of fewer cells than its rows; a zeroed
 * config a table of "model (null)") */
static int c_table_model_refused(void)
{
    static const char *const three[] = {"y", "z", "w"};
    static const struct {
        int ncol, zero;
        const char *const *cols;
        const char *msg;
    } rows[] = {
        {1, 0, NULL, "gw_sweep_write_table: model one: columns is NULL (ncolumns 1)"},
        {0, 0, one_columns, "gw_sweep_write_table: model one: ncolumns 0 (its result columns: at least 1)"},
        {-1, 0, one_columns, "gw_sweep_write_table: model one: ncolumns -1 (its result columns: at least 1)"},
        {INT_MIN, 0, one_columns, "gw_sweep_write_table: model one: ncolumns -2147483648 (its result columns: at "
                                  "least 1)"},
        {3, 0, three, "gw_sweep_write_table: model one writes 3 result columns, its config's 1 (a config read "
                      "with another model)"},
        {1, 1, one_columns, "gw_sweep_write_table: the config names no model (cfg->model NULL)"},
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        t_ncol = rows[i].ncol;
        t_columns = rows[i].cols;
        t_zero = rows[i].zero;
        char *t = NULL, *rw = NULL;
        gw_err e = {{0}};
        const int rc = table_with("w\n", &t, &rw, &e);
        if (rc != GW_EINVAL || strcmp(e.msg, rows[i].msg) != 0 || t) {
            printf("row %zu: status %d, '%s', table %s\n", i, rc, e.msg, t ? t : "(none)");
            return 1;
        }
    }
    return 0;
}

/* a hand model given to gw_sweep_run: run NULL, columns NULL, ncolumns 0,
 * -1, another count than its config's: refused naming them, values
 * untouched (run NULL was SIGSEGV, ncolumns -1 wrote before values) */
static int c_sweep_run_model_refused(void)
{
    static const char *const two[] = {"y", "z"};
    static const struct {
        int ncol, null_run;
        const char *const *cols;
        const char *msg;
    } rows[] = {
        {1, 1, one_columns, "gw_sweep_run: model one: run is NULL"},
        {1, 0, NULL, "gw_sweep_run: model one: columns is NULL (ncolumns 1)"},
        {0, 0, one_columns, "gw_sweep_run: model one: ncolumns 0 (its result columns: at least 1)"},
        {-1, 0, one_columns, "gw_sweep_run: model one: ncolumns -1 (its result columns: at least 1)"},
        {2, 0, two, "gw_sweep_run: model one writes 2 result columns, its config's 1 (a config read with another "
                    "model)"},
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        gw_sweep_model m;
        memset(&m, 0, sizeof m);
        m.name = "one";
        m.ncolumns = 1;
        m.columns = one_columns;
        m.has_key = one_has;
        m.run = one_run;
        const gw_sweep_model *models[1] = {&m}, *got = NULL;
        gw_sweep_config cfg;
        memset(&cfg, 0, sizeof cfg);
        gw_err e = {{0}};
        EXPECT(gw_sweep_config_read_string("[sweep]\nmodel = one\n[grid]\na = 1, 2\n", "one.ini", models, 1, &cfg,
                                           &got, &e) == GW_OK);
        m.ncolumns = rows[i].ncol;
        m.columns = rows[i].cols;
        if (rows[i].null_run)
            m.run = NULL;
        double buf[8] = {42, 42, 42, 42, 42, 42, 42, 42};
        char *w = NULL;
        const int rc = gw_sweep_run_warned(&cfg, &m, 1, NULL, NULL, buf + 4, &w, &e);
        gw_sweep_config_free(&cfg);
        int kept = 1;
        for (int j = 0; j < 8; j++)
            kept &= buf[j] == 42;
        if (rc != GW_EINVAL || strcmp(e.msg, rows[i].msg) != 0 || !kept || w) {
            printf("row %zu: status %d, '%s', values %s\n", i, rc, e.msg, kept ? "kept" : "written");
            return 1;
        }
    }
    return 0;
}

/* control: the model as read runs, both cases' values written */
static int c_sweep_run_model_control(void)
{
    gw_sweep_model m;
    memset(&m, 0, sizeof m);
    m.name = "one";
    m.ncolumns = 1;
    m.columns = one_columns;
    m.has_key = one_has;
    m.run = one_run;
    const gw_sweep_model *models[1] = {&m}, *got = NULL;
    gw_sweep_config cfg;
    memset(&cfg, 0, sizeof cfg);
    gw_err e = {{0}};
    EXPECT(gw_sweep_config_read_string("[sweep]\nmodel = one\n[grid]\na = 1, 2\n", "one.ini", models, 1, &cfg,
                                       &got, &e) == GW_OK);
    double v[2] = {0, 0};
    EXPECT(gw_sweep_run(&cfg, &m, 1, NULL, NULL, v, &e) == GW_OK && v[0] == 2 && v[1] == 4);
    gw_sweep_config_free(&cfg);
    return 0;
}

/* ------------------------------------------ the drop's chatter rerun ---- */

static int c_drop_rerun_step_unknown(void)
{
    const double dts[] = {NAN, -1, 0, INFINITY, -INFINITY};
    const char *shown[] = {"nan", "-1", "0", "inf", "-inf"};
    for (int i = 0; i < 5; i++) {
        char *w = test_drop_said(GW_CHAIN_RERUN_STEP, dts[i]);
        char want[160];
        snprintf(want, sizeof want, "compare a run at --dt half the drop's rk4 step (its run_dt, %s, is not one); ",
                 shown[i]);
        if (!w || !strstr(w, want) || strstr(w, "(half the step)")) {
            printf("run_dt %g: %s\n", dts[i], w ? w : "(none)");
            free(w);
            return 1;
        }
        free(w);
    }
    return 0;
}

/* controls: a step recorded is halved as before (1e-300 too: a step); the
 * tolerances' rule for TOL; chatter_rerun outside the enum (99, INT_MIN)
 * said invalid (session 48) */
static int c_drop_rerun_control(void)
{
    char *w = test_drop_said(GW_CHAIN_RERUN_STEP, 1e-9);
    EXPECT(w && strstr(w, "compare a run at --dt 5e-10 (half the step); "));
    free(w);
    w = test_drop_said(GW_CHAIN_RERUN_STEP, 1e-300);
    EXPECT(w && strstr(w, "compare a run at --dt 5e-301 (half the step); "));
    free(w);
    w = test_drop_said(GW_CHAIN_RERUN_TOL, NAN);
    EXPECT(w && strstr(w, "compare a run at 10 times tighter --rtol and --atol; ") && !strstr(w, "run_dt"));
    free(w);
    /* chatter_rerun outside the enum (99, INT_MIN) is said invalid, not worded
     * with the tolerances' rule (session 48, test_library_chain_silent) */
    const int others[] = {99, INT_MIN};
    for (int i = 0; i < 2; i++) {
        w = test_drop_said(others[i], NAN);
        EXPECT(w && strstr(w, "is invalid") && !strstr(w, "tighter") && !strstr(w, "run_dt"));
        free(w);
    }
    return 0;
}

/* ------------------------------------------ the studies' work bound ---- */

/* a range just above the bound is said in the digits that tell it from the
 * bound (1415:1415 was "2e+06 bead^2 of work ..., above the bound 2e+06");
 * far above it in 3 digits, as docs/reliability.md quotes (control) */
static int c_work_bound_digits(void)
{
    gw_err e = {{0}};
    EXPECT(gw_chain_study_work_check(1415, 1415, 1, &e) == GW_EINVAL &&
           strstr(e.msg, "n: 1415:1415 at 1 column per N is 2002225 bead^2 of work (sum of N^2), above the bound "
                         "2e+06"));
    EXPECT(gw_chain_study_work_check(1000, 1001, 1, &e) == GW_EINVAL &&
           strstr(e.msg, "is 2002001 bead^2 of work"));
    EXPECT(gw_chain_study_work_check(1, 100000, 5, &e) == GW_EINVAL &&
           strstr(e.msg, "n: 1:100000 at 5 columns per N is 1.67e+15 bead^2 of work"));
    EXPECT(gw_chain_study_work_check(1414, 1414, 1, &e) == GW_OK);
    return 0;
}

/* falcon's one column size: the pair suggested within the work bound
 * (1415:1415 was told "e.g. 1414:1415", refused by the bound, and "granwave
 * chain --n 1415", refused by the column's); below it as before (control) */
static int c_falcon_one_size_advice(void)
{
    gw_err e = {{0}};
    EXPECT(gw_chain_falcon_sizes_check(1415, 1415, &e) == GW_EINVAL &&
           strstr(e.msg, "give at least two sizes, e.g. 999:1000, the largest pair the studies' work bound holds at "
                         "one velocity (one column of 1415 beads is above the column's work bound too: granwave "
                         "chain --n runs up to 1414 over a whole collision)"));
    gw_err w = {{0}};
    EXPECT(gw_chain_study_work_check(999, 1000, 1, &w) == GW_OK);
    EXPECT(gw_chain_falcon_sizes_check(1001, 1001, &e) == GW_EINVAL &&
           strstr(e.msg, "e.g. 999:1000, the largest pair") && strstr(e.msg, "granwave chain --n 1001)"));
    EXPECT(gw_chain_falcon_sizes_check(1000, 1000, &e) == GW_EINVAL &&
           strstr(e.msg, "e.g. 999:1000 (one column's collision: granwave chain --n 1000)"));
    EXPECT(gw_chain_falcon_sizes_check(5, 5, &e) == GW_EINVAL &&
           strstr(e.msg, "e.g. 4:5 (one column's collision: granwave chain --n 5)"));
    EXPECT(gw_chain_falcon_sizes_check(1, 1, &e) == GW_EINVAL && strstr(e.msg, "e.g. 1:2 (one column's"));
    /* at falcon's default 5 speeds the pair is one the bound holds at 5
     * (999:1000 is 9.99e6 there: the advice was refused by the next check) */
    EXPECT(gw_chain_falcon_sizes_check_at(1415, 1415, 5, &e) == GW_EINVAL &&
           strstr(e.msg, "e.g. 446:447, the largest pair the studies' work bound holds at 5 velocities"));
    EXPECT(gw_chain_study_work_check(446, 447, 5, &w) == GW_OK && gw_chain_study_work_check(447, 448, 5, &w) != GW_OK);
    EXPECT(gw_chain_falcon_sizes_check_at(1000, 1000, 5, &e) == GW_EINVAL && strstr(e.msg, "e.g. 446:447, the"));
    EXPECT(gw_chain_falcon_sizes_check_at(5, 5, 5, &e) == GW_EINVAL && strstr(e.msg, "e.g. 4:5 (one column's"));
    EXPECT(gw_chain_falcon_sizes_check_at(1415, 1415, 1, &e) == GW_EINVAL && strstr(e.msg, "e.g. 999:1000, the"));
    return 0;
}

/* ---------------------------------------------- the side walls' lp ---- */

/* controls (no fault found): gw_layer_impact_check_with with lp NULL, a NaN
 * or infinite gravity, density or shear modulus refused naming it, before
 * the sample is read (a sample of NULL arrays) */
static int c_check_with_lp_control(void)
{
    gw_layer_sample s;
    memset(&s, 0, sizeof s);
    s.n = 5; /* its arrays NULL: read, it would crash */
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    gw_err e = {{0}};
    EXPECT(gw_layer_impact_check_with(&s, NULL, &ip, &e) == GW_EINVAL && strstr(e.msg, "lp is NULL"));
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (int i = 0; i < 3; i++) {
        gw_layer_params lp = gw_layer_params_default();
        lp.gravity = bad[i];
        EXPECT(gw_layer_impact_check_with(&s, &lp, &ip, &e) == GW_EINVAL && strstr(e.msg, "gravity"));
        lp = gw_layer_params_default();
        lp.density = bad[i];
        EXPECT(gw_layer_impact_check_with(&s, &lp, &ip, &e) == GW_EINVAL && strstr(e.msg, "density"));
        lp = gw_layer_params_default();
        lp.shear_modulus = bad[i];
        EXPECT(gw_layer_impact_check_with(&s, &lp, &ip, &e) == GW_EINVAL && strstr(e.msg, "shear"));
    }
    return 0;
}

int main(void)
{
    static const child_row rows[] = {
        {"grid: a speed twice", c_grid_speed_twice},
        {"grid: two speeds the same to 12 digits", c_grid_speed_near},
        {"grid: distinct speeds, bad grids (control)", c_grid_distinct_control},
        {"table: warnings escaped", c_table_warnings_escaped},
        {"table: warnings kept (control)", c_table_warnings_control},
        {"table: a model of no columns, a config of no model", c_table_model_refused},
        {"sweep run: a hand model of no run or columns", c_sweep_run_model_refused},
        {"sweep run: the model as read (control)", c_sweep_run_model_control},
        {"drop: rk4 rerun of no step", c_drop_rerun_step_unknown},
        {"drop: rerun (control)", c_drop_rerun_control},
        {"work bound: its digits", c_work_bound_digits},
        {"falcon: one column size's advice", c_falcon_one_size_advice},
        {"layer: check_with's lp (control)", c_check_with_lp_control},
    };
    return child_cases_run(rows, sizeof rows / sizeof rows[0]);
}
