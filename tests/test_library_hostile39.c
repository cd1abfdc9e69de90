/*
 * test_library_hostile39.c: the thirty-ninth hostile pass over the library's
 * C interface (docs/library.md "The contract of every call"), at the public
 * structs a caller fills by hand with fields that do not agree, and at calls
 * made out of order, that the earlier passes (test_hostile_api,
 * test_null_calls, test_library_hostile, test_library_hostile38) did not
 * reach. What the pass found, each checked here:
 *   - a gw_sweep_config filled by hand: a grid key of no values divided by
 *     zero in gw_sweep_case (SIGFPE, also through gw_sweep_case_hash and
 *     gw_sweep_format_row), more keys than the struct holds or a NULL array
 *     were read; a case count above the grid's ran its first cases again and
 *     one below it ran part of the grid, both GW_OK; inputs counted without
 *     their array crashed gw_sweep_inputs_check;
 *   - gw_case_config_hash read a NULL name or value of its pairs (SIGSEGV);
 *   - a gw_chain_trace filled by hand: gw_chain_wall_spectrum and
 *     gw_chain_trace_write read len rows of NULL arrays (SIGSEGV), the writer
 *     took a NULL trace (SIGSEGV) and printed a NULL dir as "(null)", and a
 *     trace with len above cap was written and sampled past its arrays;
 *   - gw_layer_start copied its solver settings from a NULL sp and
 *     gw_solver_create read them from a NULL p (SIGSEGV); gw_layer_advance
 *     to a NaN time ran nothing and returned GW_OK at t = 0, to an earlier
 *     time GW_OK where it stood (as rk4's solver did before the thirty-eighth
 *     pass); gw_layer_set_block kept a particle index the layer has not, which
 *     the block watch then took;
 *   - a gw_layer_sample built in memory: gw_layer_impact, gw_layer_impact_check
 *     and gw_layer_impact_dem_dt read NULL coordinates (SIGSEGV), and a body
 *     id outside [0, n) was written past the run's arrays (heap overflow
 *     under the sanitizer); a gw_layer_impact_result filled by hand:
 *     gw_layer_crowns and gw_layer_impact_write_h5 read series it had not
 *     (SIGSEGV), and gw_layer_impact_result_warnings read a settling or
 *     undecided text without its NUL on into the fields after it;
 *   - gw_chain_unfinished_warnings and gw_chain_softwall_warnings wrote
 *     "9 of 5 collisions ..." with GW_OK;
 *   - a gw_stats_table filled by hand: gw_stats_groups_make read rows of
 *     NULL arrays or more grid keys than the struct holds (SIGSEGV) and took
 *     a negative row count as "out of memory" (GW_ENOMEM, naming nothing);
 *   - gw_check_positive named a NULL name "(null)" where gw_check_range says
 *     "value".
 * Each refusal has a control: the valid call next to it still gives its
 * value (the grid's case values, a spectrum's peak at the sine's frequency, a
 * layer advanced to its time, the warning's text). Every case runs in its own
 * child process (test_child.h): a crash, a sanitizer report or anything
 * printed fails that case.
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
#include "layer_test_util.h"
#include "test_child.h"


/* ---- sweep configs filled by hand ---- */

static const char cfg_text[] = "[sweep]\nmodel = chain\n[grid]\nn = 1:3\nvimp = 0.1, 0.2\n[params]\nt-max = 1e-3\n";

static int read_cfg(gw_sweep_config *cfg, const gw_sweep_model **m)
{
    int nm;
    const gw_sweep_model *const *ms = gw_sweep_models(&nm);
    gw_err e = {{0}};
    memset(cfg, 0, sizeof *cfg);
    return gw_sweep_config_read_string(cfg_text, "t", ms, nm, cfg, m, &e) == GW_OK && cfg->ncases == 6 ? 0 : 1;
}

static int sweep_case_shape(void)
{
    gw_sweep_config cfg;
    const gw_sweep_model *m = NULL;
    EXPECT(read_cfg(&cfg, &m) == 0);
    const char *names[64], *values[64];
    char buf[4096];
    double out[256] = {0};
    /* a key of no values (SIGFPE before), or of -1 values */
    const int nv = cfg.grid[1].nvalues;
    cfg.grid[1].nvalues = 0;
    EXPECT(gw_sweep_case(&cfg, 3, names, values) == GW_EINVAL);
    EXPECT(gw_sweep_case_hash(&cfg, 3) == 0);
    EXPECT(gw_sweep_format_row(&cfg, 2, out, m->ncolumns, 0, buf, sizeof buf) == GW_EINVAL);
    cfg.grid[1].nvalues = -1;
    EXPECT(gw_sweep_case(&cfg, 3, names, values) == GW_EINVAL);
    cfg.grid[1].nvalues = nv;
    /* more keys than the struct holds (SIGFPE before), a NULL array (SIGSEGV) */
    const int ng = cfg.ngrid;
    cfg.ngrid = GW_SWEEP_MAX_KEYS + 1;
    EXPECT(gw_sweep_case(&cfg, 1, names, values) == GW_EINVAL);
    cfg.ngrid = ng;
    char **v0 = cfg.grid[0].values;
    cfg.grid[0].values = NULL;
    EXPECT(gw_sweep_case(&cfg, 1, names, values) == GW_EINVAL);
    cfg.grid[0].values = v0;
    /* control: case 5 is n = 3, vimp = 0.2, then the param */
    EXPECT(gw_sweep_case(&cfg, 5, names, values) == GW_OK);
    EXPECT(strcmp(names[0], "n") == 0 && strcmp(values[0], "3") == 0 && strcmp(values[1], "0.2") == 0 &&
           strcmp(values[2], "1e-3") == 0);
    gw_sweep_config_free(&cfg);
    return 0;
}

static int sweep_run_ncases(void)
{
    gw_sweep_config cfg;
    const gw_sweep_model *m = NULL;
    EXPECT(read_cfg(&cfg, &m) == 0);
    double *res = calloc((size_t)16 * (size_t)m->ncolumns, sizeof *res);
    EXPECT(res != NULL);
    gw_err e = {{0}};
    /* 7 ran case 6 as case 0 again, 2 ran a third of the grid: both GW_OK before */
    const long bad[] = {7, 2, -1};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        cfg.ncases = bad[i];
        EXPECT(refused(gw_sweep_run(&cfg, m, 1, NULL, NULL, res, &e), &e, "ncases"));
        EXPECT(refused(gw_sweep_size_check(&cfg, m, &e), &e, "ncases"));
        EXPECT(refused(gw_sweep_memory_check(&cfg, m, 1, 0, NULL, &e), &e, "ncases"));
    }
    cfg.ncases = 6;
    EXPECT(gw_sweep_size_check(&cfg, m, &e) == GW_OK); /* control */
    free(res);
    gw_sweep_config_free(&cfg);
    return 0;
}

static int sweep_inputs_without_array(void)
{
    gw_sweep_config cfg;
    const gw_sweep_model *m = NULL;
    EXPECT(read_cfg(&cfg, &m) == 0);
    gw_err e = {{0}};
    cfg.ninputs = 3; /* and inputs NULL: SIGSEGV before */
    EXPECT(refused(gw_sweep_inputs_check(&cfg, &e), &e, "inputs"));
    cfg.ninputs = -2;
    EXPECT(refused(gw_sweep_case_inputs_check(&cfg, 0, &e), &e, "inputs"));
    cfg.ninputs = 0;
    EXPECT(gw_sweep_inputs_check(&cfg, &e) == GW_OK); /* control */
    gw_sweep_config_free(&cfg);
    return 0;
}

static int case_hash_null_pair(void)
{
    const char *names[2] = {"n", NULL}, *values[2] = {"3", "0.2"};
    EXPECT(gw_case_config_hash("chain", 2, names, values) == 0); /* SIGSEGV before */
    names[1] = "vimp";
    values[0] = NULL;
    EXPECT(gw_case_config_hash("chain", 2, names, values) == 0);
    values[0] = "3";
    /* control: the hash of the pairs is the sweep's own of that case */
    gw_sweep_config cfg;
    const gw_sweep_model *m = NULL;
    EXPECT(read_cfg(&cfg, &m) == 0);
    const char *n3[3] = {"n", "vimp", "t-max"}, *v3[3] = {"3", "0.2", "1e-3"};
    const unsigned long long h = gw_case_config_hash("chain", 3, n3, v3);
    EXPECT(h != 0 && h == gw_sweep_case_hash(&cfg, 5));
    gw_sweep_config_free(&cfg);
    return 0;
}

/* ---- traces filled by hand ---- */

static int trace_hand_filled(void)
{
    gw_err e = {{0}};
    gw_chain_spectrum sp;
    gw_chain_trace tr = {0};
    tr.len = 100; /* no arrays: SIGSEGV before */
    EXPECT(refused(gw_chain_wall_spectrum(&tr, 0, 1, 0, 0, 0, &sp, &e), &e, "not a trace"));
    gw_chain_spectrum_free(&sp);
    char dir[] = "/tmp/gw_hostile39.XXXXXX";
    EXPECT(mkdtemp(dir) != NULL);
    tr.n = 2;
    tr.len = 5;
    EXPECT(refused(gw_chain_trace_write(&tr, dir, "x", "h", &e), &e, "not a trace"));
    EXPECT(refused(gw_chain_trace_write(NULL, dir, "x", "h", &e), &e, "tr is NULL"));
    double t[3] = {0, 1, 2}, f[3] = {1, 2, 3};
    gw_chain_trace short3 = {.n = 0, .len = 1000, .cap = 3, .t = t, .f = f}; /* read past its arrays */
    EXPECT(refused(gw_chain_trace_write(&short3, dir, "x", "h", &e), &e, "len 1000, cap 3"));
    const double y[2] = {0, 0};
    EXPECT(gw_chain_trace_sample(&short3, 3, y, 1, 0) == GW_EINVAL && short3.len == 1000);
    gw_chain_trace ok3 = {.n = 0, .len = 3, .cap = 3, .t = t, .f = f};
    EXPECT(refused(gw_chain_trace_write(&ok3, NULL, "x", "h", &e), &e, "dir is NULL"));
    /* nothing was written by the refusals; control: a good trace writes its file */
    char path[256];
    snprintf(path, sizeof path, "%s/x_wall_force.csv", dir);
    struct stat st;
    EXPECT(stat(path, &st) != 0);
    EXPECT(gw_chain_trace_write(&ok3, dir, "x", "h", &e) == GW_OK && stat(path, &st) == 0);
    unlink(path);
    snprintf(path, sizeof path, "%s/x.h5", dir);
    unlink(path);
    rmdir(dir);
    /* control: a 50 Hz sine sampled at 1 kHz for 1 s peaks at 50 Hz */
    enum { N = 1001 };
    static double tt[N], ff[N];
    for (int i = 0; i < N; i++)
        tt[i] = i * 1e-3, ff[i] = sin(2 * M_PI * 50 * tt[i]);
    gw_chain_trace sine = {.n = 0, .len = N, .cap = N, .t = tt, .f = ff};
    EXPECT(gw_chain_wall_spectrum(&sine, 0, 1, 0, 0, 0, &sp, &e) == GW_OK);
    EXPECT(fabs(sp.f_peak - 50) < 0.5);
    gw_chain_spectrum_free(&sp);
    return 0;
}

/* ---- the layer out of order ---- */

static gw_layer *two_discs(void)
{
    gw_layer_params p = gw_layer_params_default();
    gw_layer_body b[2];
    memset(b, 0, sizeof b);
    for (int i = 0; i < 2; i++)
        b[i].r = 0.05, b[i].x = p.width / 2 + 0.3 * i, b[i].y = 0.05;
    gw_layer *L = NULL;
    gw_err e = {{0}};
    return gw_layer_create(&p, 2, b, &L, &e) == GW_OK ? L : NULL;
}

static int layer_start_null(void)
{
    gw_err e = {{0}};
    gw_layer *L = two_discs();
    EXPECT(L != NULL);
    EXPECT(refused(gw_layer_start(L, gw_solver_cvode, NULL, &e), &e, "sp is NULL")); /* SIGSEGV before */
    gw_solver_params sp = gw_solver_params_default();
    EXPECT(refused(gw_layer_start(NULL, gw_solver_cvode, &sp, &e), &e, "L is NULL"));
    /* the solver layer alike */
    static const double y0[2] = {1, 0};
    const gw_system *sys = NULL;
    gw_chain_params cp = gw_chain_params_default();
    gw_chain *c = NULL;
    EXPECT(gw_chain_create(&cp, &c, &e) == GW_OK);
    sys = gw_chain_system(c);
    gw_solver *s = NULL;
    (void)y0;
    double *y = calloc((size_t)sys->dim, sizeof *y);
    EXPECT(y != NULL);
    EXPECT(refused(gw_solver_create(gw_solver_cvode, sys, NULL, 0, y, &s, &e), &e, "p is NULL") && s == NULL);
    EXPECT(gw_solver_create(gw_solver_cvode, sys, &sp, 0, y, &s, &e) == GW_OK); /* control */
    gw_solver_free(s);
    free(y);
    gw_chain_free(c);
    /* control: started, the layer runs */
    EXPECT(gw_layer_start(L, gw_solver_cvode, &sp, &e) == GW_OK);
    EXPECT(gw_layer_advance(L, 1e-4, &e) == GW_OK && gw_layer_time(L) == 1e-4);
    gw_layer_free(L);
    return 0;
}

static int layer_advance_times(void)
{
    gw_err e = {{0}};
    gw_layer *L = two_discs();
    EXPECT(L != NULL);
    gw_solver_params sp = gw_solver_params_default();
    EXPECT(gw_layer_start(L, gw_solver_cvode, &sp, &e) == GW_OK);
    /* NaN: GW_OK at t = 0 before; earlier: GW_OK where it stood */
    EXPECT(refused(gw_layer_advance(L, NAN, &e), &e, "tout nan"));
    EXPECT(refused(gw_layer_advance(L, INFINITY, &e), &e, "tout inf"));
    EXPECT(gw_layer_advance(L, 2e-4, &e) == GW_OK && gw_layer_time(L) == 2e-4);
    EXPECT(refused(gw_layer_advance(L, 1e-4, &e), &e, "before the layer's own time"));
    EXPECT(gw_layer_time(L) == 2e-4);
    /* control: its own time again is nothing to do, a later one is reached */
    EXPECT(gw_layer_advance(L, 2e-4, &e) == GW_OK);
    EXPECT(gw_layer_advance(L, 3e-4, &e) == GW_OK && gw_layer_time(L) == 3e-4);
    gw_layer_free(L);
    return 0;
}

static int layer_block_out_of_range(void)
{
    gw_err e = {{0}};
    gw_layer *L = two_discs();
    EXPECT(L != NULL);
    gw_layer_set_block(L, 99); /* kept before, and the watch took it */
    EXPECT(refused(gw_layer_watch_block(L, NULL, NULL, &e), &e, "needs a block"));
    gw_layer_set_block(L, -7);
    EXPECT(refused(gw_layer_watch_block(L, NULL, NULL, &e), &e, "needs a block"));
    gw_layer_set_block(L, 1); /* control */
    EXPECT(gw_layer_watch_block(L, NULL, NULL, &e) == GW_OK);
    gw_layer_free(L);
    return 0;
}

/* ---- samples and impact results filled by hand ---- */

static int impact_sample_hand(void)
{
    gw_err e = {{0}};
    gw_layer_params lp = gw_layer_params_default();
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    gw_solver_params sp = gw_solver_params_default();
    gw_layer_impact_result r;
    gw_layer_sample s = test_three_discs();
    s.y = NULL; /* read: SIGSEGV before */
    EXPECT(refused(gw_layer_impact(&s, &lp, &ip, gw_solver_cvode, &sp, &r, &e), &e, "y NULL"));
    gw_layer_impact_result_free(&r);
    EXPECT(refused(gw_layer_impact_check(&s, &ip, &e), &e, "y NULL"));
    s = test_three_discs();
    s.r = NULL;
    EXPECT(isnan(gw_layer_impact_dem_dt(&s, &lp, &ip)));
    s = test_three_discs();
    int body[3] = {0, 99, -5}; /* written past the run's arrays before */
    s.body = body;
    EXPECT(refused(gw_layer_impact(&s, &lp, &ip, gw_solver_cvode, &sp, &r, &e), &e, "body id 99"));
    gw_layer_impact_result_free(&r);
    body[1] = 1;
    EXPECT(refused(gw_layer_impact_check(&s, &ip, &e), &e, "body id -5"));
    /* control: the sample as built passes the check, and its step is the same
     * with a body per disc given or not */
    s = test_three_discs();
    EXPECT(gw_layer_impact_check(&s, &ip, &e) == GW_OK);
    const double dt = gw_layer_impact_dem_dt(&s, &lp, &ip);
    int own[3] = {0, 1, 2};
    s.body = own;
    EXPECT(dt > 0 && gw_layer_impact_dem_dt(&s, &lp, &ip) == dt && gw_layer_impact_check(&s, &ip, &e) == GW_OK);
    return 0;
}

static int impact_result_hand(void)
{
    gw_err e = {{0}};
    gw_layer_impact_result r;
    memset(&r, 0, sizeof r);
    r.ns = r.cap = 10, r.nrings = 4; /* no series: SIGSEGV before */
    EXPECT(gw_layer_crowns(&r) == GW_EINVAL);
    char dir[] = "/tmp/gw_hostile39r.XXXXXX", path[64];
    EXPECT(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/impact.h5", dir);
    const int rc = gw_layer_impact_write_h5(&r, path, "h", &e);
    EXPECT(rc == GW_EUNSUPPORTED || refused(rc, &e, "10 samples, 4 rings"));
    struct stat st;
    EXPECT(stat(path, &st) != 0);
    r.ns = -1, r.nrings = 0;
    EXPECT(gw_layer_crowns(&r) == GW_EINVAL);
    /* control: a zeroed result has nothing to analyse */
    memset(&r, 0, sizeof r);
    EXPECT(gw_layer_crowns(&r) == GW_OK);
    rmdir(dir);
    return 0;
}

static int impact_warning_texts(void)
{
    gw_layer_impact_result r;
    memset(&r, 0, sizeof r);
    memset(r.settling, 'B', sizeof r.settling); /* no NUL within the field */
    memset(r.undecided, 'A', sizeof r.undecided);
    r.energy_error = r.settled_load_ratio = 0.1; /* the fields after them: no zero byte */
    char *list = NULL;
    EXPECT(gw_layer_impact_result_warnings(&r, &list) == GW_OK && list);
    /* each text is its field, no more: "B"x768 "\n" "A"x320 "\n" (it read on) */
    EXPECT(strlen(list) == sizeof r.settling + sizeof r.undecided + 2);
    EXPECT(list[sizeof r.settling] == '\n' && list[sizeof r.settling + 1] == 'A');
    free(list);
    /* control: terminated texts as written */
    strcpy(r.settling, "settled elsewhere");
    strcpy(r.undecided, "undecided");
    list = NULL;
    EXPECT(gw_layer_impact_result_warnings(&r, &list) == GW_OK && strcmp(list, "settled elsewhere\nundecided\n") == 0);
    free(list);
    return 0;
}

/* ---- warning counts ---- */

static int warning_counts(void)
{
    char *list = NULL;
    EXPECT(gw_chain_unfinished_warnings(9, 5, &list) == GW_EINVAL && list == NULL); /* "9 of 5" before */
    EXPECT(gw_chain_unfinished_warnings(-1, 5, &list) == GW_EINVAL && list == NULL);
    EXPECT(gw_chain_unfinished_warnings(1, -5, &list) == GW_EINVAL && list == NULL);
    EXPECT(gw_chain_softwall_warnings(3, 2, &list) == GW_EINVAL && list == NULL);
    EXPECT(gw_chain_softwall_warnings(-3, -2, &list) == GW_EINVAL && list == NULL);
    /* control */
    EXPECT(gw_chain_unfinished_warnings(0, 5, &list) == GW_OK && list == NULL);
    EXPECT(gw_chain_unfinished_warnings(2, 5, &list) == GW_OK && list && strncmp(list, "2 of 5 collisions", 17) == 0);
    free(list);
    return 0;
}

/* ---- stats tables filled by hand ---- */

static int stats_table_hand(void)
{
    gw_err e = {{0}};
    gw_stats_groups g;
    gw_stats_table t;
    memset(&t, 0, sizeof t);
    t.nrows = 5, t.ngrid = 2, t.ncols = 3; /* no arrays: SIGSEGV before */
    for (int k = 0; k < 2; k++)
        t.grid_name[k] = k ? "alpha" : "rb_rm";
    EXPECT(refused(gw_stats_groups_make(&t, 0.5, &g, &e), &e, "without their arrays"));
    gw_stats_groups_free(&g);
    memset(&t, 0, sizeof t);
    t.nrows = -5; /* "out of memory" (GW_ENOMEM) before */
    EXPECT(refused(gw_stats_groups_make(&t, 0.5, &g, &e), &e, "-5 rows"));
    gw_stats_groups_free(&g);
    memset(&t, 0, sizeof t);
    t.ngrid = 1000; /* past grid_name[32]: SIGSEGV before */
    EXPECT(refused(gw_stats_groups_make(&t, 0.5, &g, &e), &e, "1000 grid keys"));
    gw_stats_groups_free(&g);
    EXPECT(gw_stats_table_same(&t, 0, 0, 0) == 0);
    /* control: a zeroed table has no groups */
    memset(&t, 0, sizeof t);
    EXPECT(gw_stats_groups_make(&t, 0.5, &g, &e) == GW_OK && g.n == 0);
    gw_stats_groups_free(&g);
    return 0;
}

/* the table's accessors on tables filled by hand (the lead, from what the
 * library pass reported): 1000 grid keys or params overran grid_name[32] and
 * param_name[32] (a stack buffer overflow under the sanitizer), columns
 * counted without their names and a row without its values: SIGSEGV */
static int stats_table_accessors_hand(void)
{
    gw_stats_table t;
    memset(&t, 0, sizeof t);
    t.ngrid = 1000, t.nparams = 1000;
    EXPECT(gw_stats_table_key(&t, "vi") == -1 && gw_stats_table_param(&t, "vi") == NULL);
    memset(&t, 0, sizeof t);
    t.ncols = 5; /* no col_name */
    EXPECT(gw_stats_table_col(&t, "e_n") == -1);
    memset(&t, 0, sizeof t);
    t.nrows = 3, t.ngrid = 1;
    t.grid_name[0] = "vi"; /* no grid_num */
    EXPECT(gw_stats_table_value(&t, 1, "vi", 7.5) == 7.5);
    /* control: the same table with its values reads them */
    double num[3] = {10, 20, 30};
    t.grid_num = num;
    EXPECT(gw_stats_table_key(&t, "vi") == 0 && gw_stats_table_value(&t, 1, "vi", 7.5) == 20);
    return 0;
}

/* gw_layer_sample_porosity on a sample counting discs without their arrays
 * (the lead, from the library pass's report): a NULL read (SIGSEGV) */
static int porosity_hand(void)
{
    gw_layer_sample s = test_three_discs();
    const double p = gw_layer_sample_porosity(&s);
    EXPECT(p > 0 && p < 1); /* control */
    s.x = NULL;
    EXPECT(isnan(gw_layer_sample_porosity(&s)));
    s = test_three_discs();
    s.r = NULL;
    EXPECT(isnan(gw_layer_sample_porosity(&s)));
    return 0;
}

static int check_positive_null_name(void)
{
    gw_err e = {{0}};
    EXPECT(gw_check_positive(-1, NULL, &e) == GW_EINVAL && strncmp(e.msg, "value: ", 7) == 0); /* "(null): " */
    EXPECT(gw_check_positive(2, NULL, &e) == GW_OK);
    EXPECT(gw_check_positive(0, "x", &e) == GW_EINVAL && strncmp(e.msg, "x: ", 3) == 0);
    return 0;
}

int main(void)
{
    static const child_row cases[] = {
        {"gw_sweep_case: a config of a key of no values, too many keys, a NULL array", sweep_case_shape},
        {"gw_sweep_run/size/memory checks: a case count not the grid's", sweep_run_ncases},
        {"gw_sweep_inputs_check: inputs counted without their array", sweep_inputs_without_array},
        {"gw_case_config_hash: a NULL name or value", case_hash_null_pair},
        {"gw_chain_wall_spectrum/trace_write/trace_sample: traces filled by hand", trace_hand_filled},
        {"gw_layer_start/gw_solver_create: NULL settings", layer_start_null},
        {"gw_layer_advance: NaN, infinite and earlier times", layer_advance_times},
        {"gw_layer_set_block: a particle the layer has not", layer_block_out_of_range},
        {"gw_layer_impact/_check/_dem_dt: samples filled by hand", impact_sample_hand},
        {"gw_layer_crowns/gw_layer_impact_write_h5: results filled by hand", impact_result_hand},
        {"gw_layer_impact_result_warnings: texts without their NUL", impact_warning_texts},
        {"gw_chain_unfinished/softwall_warnings: counts beyond the total", warning_counts},
        {"gw_stats_groups_make: tables filled by hand", stats_table_hand},
        {"gw_stats_table_key/param/col/value: tables filled by hand", stats_table_accessors_hand},
        {"gw_layer_sample_porosity: a sample without its arrays", porosity_hand},
        {"gw_check_positive: a NULL name", check_positive_null_name},
    };
    return child_cases_run(cases, sizeof cases / sizeof cases[0]);
}
