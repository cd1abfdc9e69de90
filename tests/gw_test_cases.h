/* gw_test_cases.h: the set-up the library's "left over" tests share
 * (test_library_leftovers41, test_library_left46, test_library_left48): each
 * case a child (test_child.h) that builds a small input from the library's
 * defaults, makes one call and expects either its refusal naming a field or,
 * for a control, GW_OK; a scratch directory under /tmp for the files the
 * cases write; the same three discs in a box 1 m wide as a layer; the bytes
 * the process has read. And what other child-case tests wrote twice: an
 * unsettled layer-make result (test_library_hostile46b, test_library_left46);
 * a contact stiffness refused naming it with its range, a column's run status
 * and its F_max (test_library_hostile50, test_stiffness_named); a 3-bead
 * column with k and kwall given, and a costly drop's warnings as its rerun's
 * kind and step say them (test_rk4_refusals, test_library_chain_silent,
 * test_library_hostile53). */
#ifndef GW_TEST_CASES_H
#define GW_TEST_CASES_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "granwave.h"
#include "test_child.h"

/* A call's status against what a row expects: NAMED NULL (a control) wants
 * GW_OK, else says what came ("control: status S 'MESSAGE'"); otherwise a
 * refusal (GW_EINVAL, one line) naming NAMED (test_child.h's refused). 1
 * when it holds. */
static inline int test_refused_or_ok(int rc, const gw_err *e, const char *named)
{
    if (named)
        return refused(rc, e, named);
    if (rc != GW_OK)
        printf("control: status %d '%s'\n", rc, e->msg);
    return rc == GW_OK;
}

/* A scratch directory /tmp/gw_NAME.XXXXXX into dir (n bytes): 0, or -1 with
 * the reason on stderr. */
static inline int test_scratch_dir(char *dir, size_t n, const char *name)
{
    snprintf(dir, n, "/tmp/gw_%s.XXXXXX", name);
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return -1;
    }
    return 0;
}

/* A test's main over a table of cases (child_cases_run) with its scratch
 * directory made first (test_scratch_dir) and removed after, each FILES
 * (NULL-ended, names under it, or NULL) unlinked first. */
static inline int test_cases_in_dir(char *dir, size_t n, const char *name, const child_row *rows, size_t count,
                                    const char *const *files)
{
    if (test_scratch_dir(dir, n, name) != 0)
        return 1;
    const int rc = child_cases_run(rows, count);
    for (size_t k = 0; files && files[k]; k++) {
        char path[512];
        snprintf(path, sizeof path, "%s/%s", dir, files[k]);
        unlink(path);
    }
    rmdir(dir);
    return rc;
}

/* Three discs of radius 0.1 m (less 1e-9 m: no two touch) on the floor of a
 * box 1 m wide, at x = 0.3, 0.5, 0.7 m, the k-th moving at vx = k vx_step
 * (k = 1, 2, 3), from the library's default layer; started with TYPE at step
 * DT (rtol = atol = 1e-6) unless TYPE is NULL. NULL, with the reason on
 * stdout (which fails the case), when a call fails. */
static inline gw_layer *test_three_layer(double vx_step, const gw_solver_type *type, double dt)
{
    gw_layer_params p = gw_layer_params_default();
    p.width = 1;
    gw_layer_body b[3];
    memset(b, 0, sizeof b);
    for (int i = 0; i < 3; i++)
        b[i].x = 0.3 + 0.2 * i, b[i].y = 0.1 - 1e-6, b[i].r = 0.1 - 1e-9, b[i].vx = vx_step * (i + 1);
    gw_layer *L = NULL;
    gw_err e = {0};
    if (gw_layer_create(&p, 3, b, &L, &e) != GW_OK) {
        printf("create: %s\n", e.msg);
        return NULL;
    }
    if (!type)
        return L;
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = dt;
    sp.rtol = sp.atol = 1e-6;
    if (gw_layer_start(L, type, &sp, &e) != GW_OK) {
        printf("start: %s\n", e.msg);
        gw_layer_free(L);
        return NULL;
    }
    return L;
}

/* A sweep configuration TEXT (named "cfg") read with the library's models:
 * its status, the message in *e; the configuration freed. */
static inline int test_config_read(const char *text, gw_err *e)
{
    int nm = 0;
    const gw_sweep_model *const *models = gw_sweep_models(&nm);
    gw_sweep_config cfg;
    memset(&cfg, 0, sizeof cfg);
    const gw_sweep_model *m = NULL;
    const int rc = gw_sweep_config_read_string(text, "cfg", models, nm, &cfg, &m, e);
    gw_sweep_config_free(&cfg);
    return rc;
}

/* bytes this process has read so far (/proc/self/io rchar; -1: unknown) */
static inline long long test_bytes_read(void)
{
    FILE *f = fopen("/proc/self/io", "r");
    long long v = -1;
    char line[128];
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "rchar: %lld", &v) == 1)
            break;
    if (f)
        fclose(f);
    return v;
}

/* an unsettled result as layer-make fills one: E_k 10 J above a threshold of
 * 1 J, the floor carrying the pile, judged from 0.5 s */
static inline gw_layer_make_result test_unsettled_make_result(void)
{
    gw_layer_make_result r;
    memset(&r, 0, sizeof r);
    r.converged = 0, r.t_settle = 1, r.ke_final = 10, r.floor_load = 1, r.ke_limit = 1, r.t_judge = 0.5;
    r.porosity = 0.2;
    return r;
}

/* gw_chain_run_check of p under o refused naming WHO ("k" or "kwall") first,
 * "WHO: ... N/m^1.5 is outside [LO, HI]" with 0 < LO < HI: 1 and HI in *hi;
 * else 0 with the message on stdout (which fails the case) */
static inline int test_stiffness_refused(const gw_chain_params *p, const gw_chain_run_opts *o, const char *who,
                                         double *hi)
{
    gw_err e = {0};
    const int rc = gw_chain_run_check(p, o, &e);
    char pre[16];
    snprintf(pre, sizeof pre, "%s: ", who);
    double lo = 0;
    if (!refused(rc, &e, pre) || strncmp(e.msg, pre, strlen(pre)) != 0 || !strstr(e.msg, "N/m^1.5 is outside [") ||
        sscanf(strstr(e.msg, "outside [") + 9, "%lg, %lg]", &lo, hi) != 2 || !(lo > 0 && lo < *hi)) {
        printf("%s: '%s'\n", who, e.msg);
        return 0;
    }
    return 1;
}

/* the status of gw_chain_collide of the column p under o, its message (its
 * own, cleared before) in *e, the column made and the result freed; a column that cannot be made is
 * said on stdout ("create: MESSAGE", which fails the case) and its status
 * returned */
static inline int test_chain_run_status(const gw_chain_params *p, const gw_chain_run_opts *o, gw_err *e)
{
    gw_chain *c = NULL;
    int rc = gw_chain_create(p, &c, e);
    if (rc != GW_OK) {
        printf("create: %s\n", e->msg);
        return rc;
    }
    gw_chain_result r;
    memset(&r, 0, sizeof r);
    e->msg[0] = '\0'; /* the message is the run's */
    rc = gw_chain_collide(c, o, &r, e);
    gw_chain_result_free(&r);
    gw_chain_free(c);
    return rc;
}

/* F_max of the column p under o, or -1 with the failure on stdout (which
 * fails the case) */
static inline double test_chain_fmax(const gw_chain_params *p, const gw_chain_run_opts *o)
{
    gw_chain *c = NULL;
    gw_err e = {0};
    double f = -1;
    if (gw_chain_create(p, &c, &e) == GW_OK) {
        gw_chain_result r;
        memset(&r, 0, sizeof r);
        if (gw_chain_collide(c, o, &r, &e) == GW_OK)
            f = r.f_max;
        else
            printf("run: %s\n", e.msg);
        gw_chain_result_free(&r);
    } else
        printf("create: %s\n", e.msg);
    gw_chain_free(c);
    return f;
}

/* The default column of 3 beads, with k and kwall where they are > 0. */
static inline gw_chain_params test_chain_column(double k, double kwall)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    if (k > 0)
        p.k = k;
    if (kwall > 0)
        p.kwall = kwall;
    return p;
}

/* The warnings of a drop result made by hand: a costly chatter rerun of kind
 * RERUN at step RUN_DT, 1000 steps of 3 beads to 1 ms. NULL when the call
 * failed; else the caller frees them. */
static inline char *test_drop_said(int rerun, double run_dt)
{
    gw_chain_drop_result r;
    memset(&r, 0, sizeof r);
    r.chatter_kind = GW_CHAIN_CHATTER_COSTLY;
    r.chatter_rerun = rerun;
    r.run_dt = run_dt;
    r.stats.steps = 1000;
    r.n = 3;
    r.t_end = 1e-3;
    char *w = NULL;
    if (gw_chain_drop_result_warnings(&r, &w) != GW_OK)
        return NULL;
    return w;
}


#endif
