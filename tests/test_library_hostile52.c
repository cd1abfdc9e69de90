/*
 * test_library_hostile52.c: the fifty-second hostile pass over the library's
 * C interface (docs/library.md "The contract of every call"): the details
 * the fifty-first left, and the entry points added since (the chatter
 * members of the chain's and the drop's results, gw_solver_set_peek, the
 * impact's side_walls) and the least tested calls. About 350 calls (every
 * study's choice and flag rows written directly with indices outside their
 * names and 7; a list of a negative count; sweep tables without a name; the
 * bounded hash with text flags 7, -1, 2, INT_MIN; the journal, the sweep
 * table, the trace and the statistics' files given ""; the peek behind, at
 * and beyond the solver's time, subnormal and NaN; the drop's parameters
 * NaN, +-inf, -0, subnormal, 1e300; hand results of chatter kinds 99 and
 * INT_MIN freed twice; the chain's, the drop's and the impact's sample and
 * progress callbacks returning 1, 7, -1, -999, INT_MIN, INT_MAX; solvers
 * of dimension 0 and -1, failing rhs and root functions, NaN rates; the
 * uncalled getters and checks given NULL, -1, 99 and NaN). What it found:
 *   - gw_param_json wrote a choice index outside its names as null (a value
 *     given recorded as none), a flag of 7 as true and a list of a negative
 *     count as []: it is NULL for each, as gw_param_format is -1 (the
 *     refusals are gw_param_check's, which names the row). A NULL table
 *     was written {}: NULL too.
 *   - gw_stats_table_parse with a NULL (or "") name named nothing in its
 *     messages (":1: lines end in CR alone"): "<table>:1: ...", as the
 *     parsers say "value" for a NULL name.
 *   - gw_fnv1a64_file_max took a text flag of 7 (and -1) as yes: GW_EINVAL
 *     naming text, before the file is opened.
 *   - the journal, the sweep's table and the chain's traces given an empty
 *     directory "" refused it as "path too long" (the table's
 *     gw_sweep_write_table as "cannot open the sweep's directory: No such
 *     file or directory"), gw_sweep_out_inputs_check passed it): each
 *     names an empty directory now.
 *   - gw_chain_trace_write given a NULL header read it through strlen in the
 *     HDF5 writer (SIGSEGV, the CSV files written): refused naming it. A stem
 *     "" wrote _wall_force.csv, _beads.csv and the hidden .h5: refused.
 *   - gw_chain_collide told a caller's sample callback failing (-1) as
 *     "chain: the trace at t = ...: invalid input", a trace the caller never
 *     asked for: "the sample callback failed at t = ...", as the drop says
 *     (the stored trace's own failure keeps its words).
 * Each case runs in its own child process (test_child.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "granwave.h"
#include "test_child.h"

/* ------------------------------------------------------ gw_param_json ---- */

static int choice_count(const char *c)
{
    int n = 1;
    for (; c && *c; c++)
        n += *c == ',';
    return n;
}

/* every study's choice and flag rows (and list rows) set outside their
 * values: the JSON refused (NULL) where gw_param_check names the row */
static int c_param_json_outside(void)
{
    int rows = 0;
    for (int i = 0; i < gw_study_count(); i++) {
        const gw_study *st = gw_study_get(i);
        EXPECT(st != NULL);
        const gw_param *t = st->params();
        void *obj = calloc(1, st->params_size);
        EXPECT(obj && st->init(obj) == GW_OK);
        cJSON *j0 = gw_param_json(t, obj); /* control: the defaults */
        EXPECT(j0 != NULL);
        cJSON_Delete(j0);
        for (int k = 0; t[k].name; k++) {
            const gw_param *p = &t[k];
            char *f = (char *)obj + p->offset;
            gw_err e = {{0}};
            if (p->type == GW_PARAM_CHOICE) {
                int keep = *(int *)f;
                *(int *)f = choice_count(p->choices); /* one past the last name */
                EXPECT(gw_param_check(t, obj, &e) == GW_EINVAL && strstr(e.msg, p->name));
                cJSON *j = gw_param_json(t, obj);
                if (j) {
                    printf("%s %s: choice %d written %s\n", st->name, p->name, *(int *)f,
                           cJSON_PrintUnformatted(cJSON_GetObjectItemCaseSensitive(j, p->name)));
                    return 1;
                }
                *(int *)f = 0; /* control: the first name, by name */
                j = gw_param_json(t, obj);
                const cJSON *v = j ? cJSON_GetObjectItemCaseSensitive(j, p->name) : NULL;
                EXPECT(cJSON_IsString(v) && strncmp(v->valuestring, p->choices, strlen(v->valuestring)) == 0);
                cJSON_Delete(j);
                *(int *)f = keep;
                rows++;
            } else if (p->type == GW_PARAM_FLAG) {
                int keep = *(int *)f;
                *(int *)f = 7;
                EXPECT(gw_param_check(t, obj, &e) == GW_EINVAL && strstr(e.msg, "is not a flag"));
                cJSON *j = gw_param_json(t, obj);
                if (j) {
                    printf("%s %s: flag 7 written %s\n", st->name, p->name,
                           cJSON_PrintUnformatted(cJSON_GetObjectItemCaseSensitive(j, p->name)));
                    return 1;
                }
                *(int *)f = 1; /* control */
                j = gw_param_json(t, obj);
                EXPECT(j && cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(j, p->name)));
                cJSON_Delete(j);
                *(int *)f = keep;
                rows++;
            } else if (p->type == GW_PARAM_LIST) {
                gw_param_list *l = (gw_param_list *)f;
                gw_param_list keep = *l;
                double v[1] = {1};
                l->v = v;
                l->n = -2;
                EXPECT(gw_param_check(t, obj, &e) == GW_EINVAL && strstr(e.msg, "negative count"));
                cJSON *j = gw_param_json(t, obj);
                if (j) {
                    printf("%s %s: a list of -2 items written %s\n", st->name, p->name,
                           cJSON_PrintUnformatted(cJSON_GetObjectItemCaseSensitive(j, p->name)));
                    return 1;
                }
                l->n = 1; /* control */
                j = gw_param_json(t, obj);
                const cJSON *a = j ? cJSON_GetObjectItemCaseSensitive(j, p->name) : NULL;
                EXPECT(cJSON_IsArray(a) && cJSON_GetArraySize(a) == 1);
                cJSON_Delete(j);
                *l = keep;
                rows++;
            }
        }
        st->clear(obj);
        free(obj);
    }
    EXPECT(rows >= 10);
    /* a NULL table was written {} (settings of no rows) */
    const gw_study *st = gw_study_find("chain");
    void *obj = calloc(1, st->params_size);
    EXPECT(obj && st->init(obj) == GW_OK);
    EXPECT(gw_param_json(NULL, obj) == NULL && gw_param_json(st->params(), NULL) == NULL);
    st->clear(obj);
    free(obj);
    return 0;
}

/* ------------------------------------------------------ sweep tables ---- */

static int c_table_parse_no_name(void)
{
    gw_err e = {{0}};
    gw_stats_table t;
    const char *const names[] = {NULL, ""};
    for (int k = 0; k < 2; k++) {
        EXPECT(gw_stats_table_parse("# a\rcase,n\r0,1\r", names[k], &t, &e) == GW_EFORMAT);
        EXPECT(strncmp(e.msg, "<table>:1: lines end in CR alone", 32) == 0);
        EXPECT(gw_stats_table_parse("# only a comment\n", names[k], &t, &e) == GW_EFORMAT);
        EXPECT(strncmp(e.msg, "<table>:2: no header line", 25) == 0);
        EXPECT(gw_stats_table_parse("case,bounced\n", names[k], &t, &e) == GW_EFORMAT);
        EXPECT(strncmp(e.msg, "<table>:1: header has no column", 31) == 0);
    }
    /* control: a name given is the messages' */
    EXPECT(gw_stats_table_parse("# only a comment\n", "hand.csv", &t, &e) == GW_EFORMAT);
    EXPECT(strncmp(e.msg, "hand.csv:2: no header line", 26) == 0);
    return 0;
}

/* ------------------------------------------------------ the bounded hash ---- */

static int c_hash_text_flag(void)
{
    char dir[] = "/tmp/gw_hostile52.XXXXXX", path[64];
    EXPECT(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/a.txt", dir);
    FILE *fp = fopen(path, "wb");
    EXPECT(fp && fwrite("ab\n\0cd\n", 1, 7, fp) == 7 && fclose(fp) == 0);
    const int bad[] = {7, -1, 2, INT_MIN, INT_MAX};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        gw_err e = {{0}};
        unsigned long long h = 42;
        EXPECT(refused(gw_fnv1a64_file_max(path, "input", 100, bad[k], &h, &e), &e, "text is"));
        EXPECT(strstr(e.msg, "not a flag (0 or 1)") && h == 42);
    }
    /* controls: 1 reads the NUL as binary (line 2), 0 hashes the 7 bytes */
    gw_err e = {{0}};
    unsigned long long h = 42;
    EXPECT(gw_fnv1a64_file_max(path, "input", 100, 1, &h, &e) == GW_EFORMAT && strstr(e.msg, "line 2"));
    EXPECT(gw_fnv1a64_file_max(path, "input", 100, 0, &h, &e) == GW_OK);
    EXPECT(h == gw_fnv1a64(GW_FNV1A64_INIT, "ab\n\0cd\n", 7));
    unlink(path);
    rmdir(dir);
    return 0;
}

/* ------------------------------------------------------ empty directories ---- */

static const char cfg_text[] = "[sweep]\nmodel = chain\n[grid]\nn = 1:2\n[params]\nt-max = 1e-3\n";

static int c_empty_dir_sweep(void)
{
    int nm;
    const gw_sweep_model *const *ms = gw_sweep_models(&nm);
    gw_sweep_config cfg;
    const gw_sweep_model *m = NULL;
    gw_err e = {{0}};
    memset(&cfg, 0, sizeof cfg);
    EXPECT(gw_sweep_config_read_string(cfg_text, "t", ms, nm, &cfg, &m, &e) == GW_OK);
    char done[4] = {0};
    long nd = 5;
    int fd = 7, dfd = 7;
    EXPECT(refused(gw_sweep_journal_open("", &cfg, done, &nd, &fd, &e), &e, "the directory is empty"));
    EXPECT(fd == -1 && !strstr(e.msg, "too long"));
    EXPECT(refused(gw_sweep_journal_open_at("", &cfg, done, &nd, &fd, &dfd, &e), &e, "the directory is empty"));
    EXPECT(refused(gw_sweep_write_table("", &cfg, m, &e), &e, "the directory is empty"));
    EXPECT(!strstr(e.msg, "No such file"));
    EXPECT(refused(gw_sweep_out_inputs_check("", &cfg, &e), &e, "the directory is empty")); /* GW_OK */
    /* control: a directory too long for a path is still "path too long" */
    char lng[5000];
    memset(lng, 'd', sizeof lng - 1);
    lng[sizeof lng - 1] = '\0';
    EXPECT(refused(gw_sweep_journal_open(lng, &cfg, done, &nd, &fd, &e), &e, "path too long"));
    gw_sweep_config_free(&cfg);
    return 0;
}

static int c_empty_dir_trace(void)
{
    double t[3] = {0, 1, 2}, f[3] = {1, 2, 3};
    gw_chain_trace tr = {.n = 0, .len = 3, .cap = 3, .t = t, .f = f};
    gw_err e = {{0}};
    EXPECT(refused(gw_chain_trace_write(&tr, "", "x", "h", &e), &e, "dir is empty"));
    EXPECT(!strstr(e.msg, "too long"));
    char dir[] = "/tmp/gw_hostile52t.XXXXXX", path[64];
    EXPECT(mkdtemp(dir) != NULL);
    /* an empty stem wrote _wall_force.csv and .h5 */
    EXPECT(refused(gw_chain_trace_write(&tr, dir, "", "h", &e), &e, "gw_chain_trace_write: stem is empty"));
    snprintf(path, sizeof path, "%s/_wall_force.csv", dir);
    struct stat st;
    EXPECT(stat(path, &st) != 0);
    /* a NULL header: the HDF5 writer's strlen read it (SIGSEGV), after the CSV */
    EXPECT(refused(gw_chain_trace_write(&tr, dir, "n", NULL, &e), &e, "gw_chain_trace_write: header is NULL"));
    snprintf(path, sizeof path, "%s/n_wall_force.csv", dir);
    EXPECT(stat(path, &st) != 0);
    /* control: into a directory made */
    EXPECT(gw_chain_trace_write(&tr, dir, "x", "h", &e) == GW_OK);
    snprintf(path, sizeof path, "%s/x_wall_force.csv", dir);
    EXPECT(stat(path, &st) == 0);
    unlink(path);
    snprintf(path, sizeof path, "%s/x.h5", dir);
    unlink(path);
    rmdir(dir);
    return 0;
}

static int c_empty_dir_stats(void)
{
    gw_stats_analysis A;
    memset(&A, 0, sizeof A);
    gw_err e = {{0}};
    const int rc = gw_stats_write_files(&A, "", &e);
    EXPECT(rc == GW_EINVAL && !strstr(e.msg, "too long") && !strchr(e.msg, '\n'));
    return 0;
}

/* ------------------------------------------------------ the peek ---- */

static int rhs_decay(double t, const double *y, double *yd, void *p)
{
    (void)t, (void)p;
    yd[0] = -y[0];
    return 0;
}

/* a peek behind, at and beyond the solver's time, subnormal, NaN: never a
 * failure, the advance's own end reached at its tout (no fault found; held) */
static int c_peek_times(void)
{
    const gw_solver_type *types[2] = {gw_solver_cvode, gw_solver_rk4};
    const double peeks[] = {0.5, 1.0, 1.0 - 1e-16, 5.0, 4.9e-324, NAN, INFINITY, -1.0};
    for (int i = 0; i < 2; i++)
        for (size_t k = 0; k < sizeof peeks / sizeof peeks[0]; k++) {
            gw_system sys;
            memset(&sys, 0, sizeof sys);
            sys.dim = 1;
            sys.rhs = rhs_decay;
            gw_solver_params p = gw_solver_params_default();
            p.dt = 1e-3;
            double y[1] = {1}, t = 0;
            gw_solver *s = NULL;
            gw_err e = {{0}};
            EXPECT(gw_solver_create(types[i], &sys, &p, 0, y, &s, &e) == GW_OK);
            EXPECT(gw_solver_advance(s, 1.0, &t, y, NULL) == GW_OK && t == 1.0);
            const int armed = gw_solver_set_peek(s, peeks[k]);
            EXPECT(armed == (peeks[k] > 0 && isfinite(peeks[k])));
            int rc = gw_solver_advance(s, 2.0, &t, y, NULL);
            if (rc == GW_SOLVER_PEEK) { /* only a peek ahead of t */
                EXPECT(peeks[k] > 1.0 && t == peeks[k]);
                rc = gw_solver_advance(s, 2.0, &t, y, NULL);
            }
            EXPECT(rc == GW_OK && t == 2.0 && fabs(y[0] - exp(-2.0)) < 1e-6);
            gw_solver_free(s);
        }
    EXPECT(gw_solver_set_peek(NULL, 1.0) == 0);
    return 0;
}

/* ------------------------------------------------------ the chatter members ---- */

static int c_chatter_hand(void)
{
    const int kinds[] = {99, INT_MIN, -1};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        gw_chain_drop_result dr;
        memset(&dr, 0, sizeof dr);
        dr.n = 3, dr.n_impacts = 5, dr.chatter_kind = kinds[k], dr.chatter_spread = NAN;
        char *list = NULL;
        EXPECT(gw_chain_drop_result_warnings(&dr, &list) == GW_OK && !list);
        EXPECT(gw_chain_drop_impact_rises(&dr) == 0);
        dr.n_impacts = 0;
        gw_chain_drop_result_free(&dr);
        gw_chain_drop_result_free(&dr);
        gw_chain_result cr;
        memset(&cr, 0, sizeof cr);
        cr.converged = 1, cr.chatter_kind = kinds[k];
        EXPECT(gw_chain_result_warnings(&cr, &list) == GW_OK && !list);
        gw_chain_result_free(&cr);
        gw_chain_result_free(&cr);
    }
    return 0;
}

/* ------------------------------------------------------ callbacks ---- */

static int cb_ret, cb_count;
static int sample_cb(void *ctx, double t, const double *y, double f, int is_event)
{
    (void)ctx, (void)t, (void)y, (void)f, (void)is_event;
    return ++cb_count >= 3 ? cb_ret : 0;
}

/* a caller's sample callback failing (-1, -999, INT_MIN) was told "chain: the
 * trace at t = ...: invalid input", a trace the caller never asked for */
static int c_sample_cb_named(void)
{
    const int rets[] = {-1, -999, INT_MIN};
    const gw_solver_type *types[2] = {gw_solver_cvode, gw_solver_rk4};
    for (size_t k = 0; k < sizeof rets / sizeof rets[0]; k++)
        for (int i = 0; i < 2; i++) {
            gw_chain_params p = gw_chain_params_default();
            p.n = 3;
            gw_chain *c = NULL;
            gw_err e = {{0}};
            EXPECT(gw_chain_create(&p, &c, &e) == GW_OK);
            gw_chain_run_opts o = gw_chain_run_opts_default();
            o.solver = types[i];
            o.sample = sample_cb;
            cb_ret = rets[k], cb_count = 0;
            gw_chain_result r;
            EXPECT(gw_chain_collide(c, &o, &r, &e) == rets[k]);
            EXPECT(strncmp(e.msg, "chain: the sample callback failed at t = ", 41) == 0 && !strstr(e.msg, "trace"));
            gw_chain_result_free(&r);
            /* control: a stop (> 0) ends the run without an error, as documented */
            cb_ret = 1, cb_count = 0;
            memset(&e, 0, sizeof e);
            EXPECT(gw_chain_collide(c, &o, &r, &e) == GW_OK && e.msg[0] == '\0');
            gw_chain_result_free(&r);
            gw_chain_free(c);
        }
    return 0;
}

static const child_row rows[] = {
    {"gw_param_json: a choice outside its names, a flag of 7, a list of -2 items, a NULL table refused (null, "
     "true, [], {})",
     c_param_json_outside},
    {"gw_stats_table_parse: a NULL or empty name is '<table>' (':1: ...')", c_table_parse_no_name},
    {"gw_fnv1a64_file_max: a text flag other than 0 and 1 refused (7 was yes)", c_hash_text_flag},
    {"journal and sweep table: an empty dir named as such ('path too long')", c_empty_dir_sweep},
    {"gw_chain_trace_write: an empty dir named ('path too long'), stem '' and header NULL (SIGSEGV) refused",
     c_empty_dir_trace},
    {"gw_stats_write_files: an empty dir refused in one line", c_empty_dir_stats},
    {"gw_solver_set_peek: behind, at, beyond t, subnormal, NaN (held)", c_peek_times},
    {"chatter members: kinds outside the enum said nothing, results freed twice (held)", c_chatter_hand},
    {"gw_chain_collide: a caller's sample callback failing named as such ('the trace at t')", c_sample_cb_named},
};

int main(void)
{
    return child_cases_run(rows, sizeof rows / sizeof rows[0]);
}
