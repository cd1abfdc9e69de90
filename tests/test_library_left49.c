/*
 * test_library_left49.c: what the forty-ninth library pass left, each part in
 * its own child process (gw_test_part):
 *   - output names: gw_out_file_check, gw_out_check, gw_out_names_check and
 *     gw_mkdir_p took a name to make holding a control character (a newline,
 *     ESC, a tab): each is refused naming the byte, nothing made. Controls: a
 *     plain name, and a directory the user made whose name holds a newline,
 *     written into as before.
 *   - gw_out_names_check(NULL, ...), (dir, NULL) and gw_stats_out_check_input
 *     with a NULL dir or input returned GW_OK: refused naming the argument;
 *     names "a/../b", ".." and "" (no plain file name) passed: refused.
 *     Control: "a.csv" passes.
 *   - gw_chain_fmax1(1, inf, 1) was NaN (K d^(3/2) = inf * 0): the rigid
 *     wall's limit, inf (0 at v = 0); finite K as K^(2/5) (5 m v^2/4)^(3/5).
 *   - gw_chain_step_scale of masses {1, -1, NaN} was 1.47e-4 s, and
 *     gw_chain_time_scale of n = 0 finite: NaN; gw_chain_rk4_study_covers of
 *     a NaN mass was 1: 0. Controls: a uniform column's scales, T_c =
 *     (m/k)^(2/5) v^(-1/5), and the study covering it.
 *   - gw_layer_solve_point(1e-300, ...) failed as GW_ESOLVER "no contact
 *     solution" (fhat ~ (4/3) alpha^3 underflowed): refused naming alpha.
 *     Control: alpha = 1e-100 gives the Hertz limit dhat = alpha^2, fhat =
 *     (4/3) alpha^3.
 * The same source measures the library before (built against it: it has no
 * GW_LAYER_ALPHA_MIN, defined here for that build).
 */
#define _GNU_SOURCE
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "granwave.h"
#include "gw_test.h"
#include "gw_test_calls.h"

#ifndef GW_LAYER_ALPHA_MIN
#define GW_LAYER_ALPHA_MIN 1e-100
#endif

static int there(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0;
}

/* rc is GW_EINVAL and the message holds text */
static int refused(int rc, const gw_err *e, const char *text)
{
    return rc == GW_EINVAL && gw_test_said(e, text);
}

/* ------------------------------------------------------ output names ---- */

static void part_control_names(const char *dir)
{
    static const char *const names[][2] = {{"x\n", "a newline"}, {"o\x1bk.txt", "ESC"}, {"t\tb.csv", "a tab"}};
    char p[1024];
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        gw_err e = {0};
        snprintf(p, sizeof p, "%s/%s", dir, names[i][0]);
        GW_TEST_OK(refused(gw_out_file_check(p, "out", &e), &e, "control character"),
                   "gw_out_file_check: a file name with %s refused naming the control character (%s)", names[i][1],
                   e.msg);
        e = (gw_err){0};
        GW_TEST_OK(refused(gw_out_check(p, "out", &e), &e, "control character"),
                   "gw_out_check: a directory to make with %s refused (%s)", names[i][1], e.msg);
        e = (gw_err){0};
        const char *const list[] = {names[i][0], NULL};
        GW_TEST_OK(refused(gw_out_names_check(dir, list, "out", &e), &e, "control character"),
                   "gw_out_names_check: a name with %s refused (%s)", names[i][1], e.msg);
        e = (gw_err){0};
        GW_TEST_OK(gw_mkdir_p(p, &e) == GW_EINVAL && !there(p),
                   "gw_mkdir_p: a directory with %s refused, nothing made (%s)", names[i][1], e.msg);
    }
    /* a layer-make through the library: the sample's name with an ESC */
    gw_err e = {0};
    snprintf(p, sizeof p, "%s/s\x1bk.txt", dir);
    GW_TEST_OK(refused(gw_layer_sample_out_check(p, "sample", &e), &e, "control character") && !there(p),
               "gw_layer_sample_out_check: a sample name with ESC refused (%s)", e.msg);
    /* controls: a plain name; an existing directory whose name holds a newline */
    e = (gw_err){0};
    snprintf(p, sizeof p, "%s/plain.txt", dir);
    GW_TEST_OK(gw_out_file_check(p, "out", &e) == GW_OK, "control: gw_out_file_check of a plain name (%s)", e.msg);
    char made[256];
    snprintf(made, sizeof made, "%s/nl\nx", dir);
    GW_TEST_OK(mkdir(made, 0700) == 0, "control: a directory nl<newline>x made by the user");
    snprintf(p, sizeof p, "%s/f.txt", made);
    e = (gw_err){0};
    GW_TEST_OK(gw_out_file_check(p, "out", &e) == GW_OK && gw_out_check(made, "out", &e) == GW_OK,
               "control: a file and the directory in the user's nl<newline>x pass (%s)", e.msg);
    const char *const csv[] = {"a.csv", NULL};
    e = (gw_err){0};
    GW_TEST_OK(gw_out_names_check(made, csv, "out", &e) == GW_OK, "control: a.csv in nl<newline>x passes (%s)", e.msg);
}

static void part_null_and_plain(const char *dir)
{
    gw_err e = {0};
    GW_TEST_OK(refused(gw_out_names_check(NULL, NULL, NULL, &e), &e, "dir is NULL"),
               "gw_out_names_check(NULL, NULL): refused naming dir (%s)", e.msg);
    e = (gw_err){0};
    GW_TEST_OK(refused(gw_out_names_check(dir, NULL, NULL, &e), &e, "names is NULL"),
               "gw_out_names_check(dir, NULL): refused naming names (%s)", e.msg);
    e = (gw_err){0};
    GW_TEST_OK(refused(gw_stats_out_check_input(NULL, NULL, &e), &e, "dir is NULL"),
               "gw_stats_out_check_input(NULL, NULL): refused naming dir (%s)", e.msg);
    e = (gw_err){0};
    GW_TEST_OK(refused(gw_stats_out_check_input(dir, NULL, &e), &e, "input is NULL"),
               "gw_stats_out_check_input(dir, NULL): refused naming input (%s)", e.msg);
    static const char *const bad[] = {"a/../b", "..", "", "sub/x.csv"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const char *const list[] = {"ok.csv", bad[i], NULL};
        e = (gw_err){0};
        GW_TEST_OK(refused(gw_out_names_check(dir, list, "out", &e), &e, "not a plain file name"),
                   "gw_out_names_check: name '%s' refused as no plain file name (%s)", bad[i], e.msg);
    }
    const char *const good[] = {"a.csv", "b.json", NULL};
    e = (gw_err){0};
    GW_TEST_OK(gw_out_names_check(dir, good, "out", &e) == GW_OK, "control: a.csv, b.json pass (%s)", e.msg);
}

/* ---------------------------------------------------- numeric helpers ---- */

static void part_fmax1(const char *dir)
{
    (void)dir;
    const double f = gw_chain_fmax1(1, INFINITY, 1), f0 = gw_chain_fmax1(1, INFINITY, 0);
    GW_TEST_OK(isinf(f) && f > 0, "gw_chain_fmax1(1, inf, 1) is the rigid wall's limit inf (got %g)", f);
    GW_TEST_OK(f0 == 0, "gw_chain_fmax1(1, inf, 0) is 0 (got %g)", f0);
    GW_TEST_OK(gw_chain_dmax1(1, INFINITY, 1) == 0 && gw_chain_tau1(1, INFINITY, 1) == 0,
               "control: d_max and tau_1 of a rigid wall are 0");
    /* finite K: F_max = K^(2/5) (5 m v^2 / 4)^(3/5) = K d_max^(3/2) */
    const double m = 2.1e-3, K = 9.86e9, v = 0.3, d = gw_chain_dmax1(m, K, v);
    gw_test_rel(gw_chain_fmax1(m, K, v), pow(K, 0.4) * pow(1.25 * m * v * v, 0.6), 1e-13,
                "control: F_max of steel on steel, closed form");
    gw_test_rel(gw_chain_fmax1(m, K, v), K * d * sqrt(d), 1e-13, "control: F_max = K d_max^(3/2)");
    GW_TEST_OK(isnan(gw_chain_fmax1(-1, INFINITY, 1)) && isnan(gw_chain_fmax1(1, NAN, 1)),
               "control: a negative mass or a NaN K stay NaN");
}

static void part_scales(const char *dir)
{
    (void)dir;
    gw_chain_params p = gw_chain_params_default();
    p.n = 3;
    const double bad[3] = {1, -1, NAN};
    p.masses = bad;
    const double s = gw_chain_step_scale(&p);
    GW_TEST_OK(isnan(s), "gw_chain_step_scale of masses {1, -1, NaN} is NaN (got %g)", s);
    const double nanm[3] = {1, NAN, 1};
    p.masses = nanm;
    GW_TEST_OK(isnan(gw_chain_step_scale(&p)), "gw_chain_step_scale of masses {1, NaN, 1} is NaN");
    GW_TEST_OK(gw_chain_rk4_study_covers(&p, 3) == 0, "gw_chain_rk4_study_covers of a NaN mass is 0");
    p.masses = NULL;
    p.n = 0;
    const double t0 = gw_chain_time_scale(&p);
    GW_TEST_OK(isnan(t0), "gw_chain_time_scale of n = 0 is NaN (got %g)", t0);
    GW_TEST_OK(isnan(gw_chain_step_scale(&p)), "gw_chain_step_scale of n = 0 is NaN");
    p.n = 3;
    p.v_imp = NAN;
    GW_TEST_OK(isnan(gw_chain_time_scale(&p)), "gw_chain_time_scale of v_imp NaN is NaN");
    /* controls: the default column */
    p = gw_chain_params_default();
    p.n = 5;
    const double tc = pow(p.mass / p.k, 0.4) * pow(p.v_imp, -0.2);
    gw_test_rel(gw_chain_time_scale(&p), tc, 1e-14, "control: T_c = (m/k)^(2/5) v^(-1/5)");
    gw_test_rel(gw_chain_step_scale(&p), tc, 1e-14, "control: a uniform column's step scale is T_c");
    GW_TEST_OK(gw_chain_rk4_study_covers(&p, 5) == 1, "control: the study covers the default column");
}

static void part_solve_point(const char *dir)
{
    (void)dir;
    double dh = -1, fh = -1;
    gw_err e = {0};
    const int rc = gw_layer_solve_point(1e-300, 0.3, 1, &dh, &fh, &e);
    GW_TEST_OK(refused(rc, &e, "alpha"), "gw_layer_solve_point(1e-300): refused naming alpha (rc %d: %s)", rc, e.msg);
    e = (gw_err){0};
    GW_TEST_OK(refused(gw_layer_solve_point(1e-101, 0.3, 1, &dh, &fh, &e), &e, "alpha"),
               "gw_layer_solve_point(1e-101): refused naming alpha (%s)", e.msg);
    /* control: the smallest alpha taken, the Hertz limit (a << h) */
    const double a = GW_LAYER_ALPHA_MIN;
    e = (gw_err){0};
    GW_TEST_OK(gw_layer_solve_point(a, 0.3, 1, &dh, &fh, &e) == GW_OK, "control: alpha = 1e-100 solved (%s)",
               e.msg);
    gw_test_rel(dh, a * a, 1e-9, "control: alpha = 1e-100: dhat = alpha^2");
    gw_test_rel(fh, 4.0 / 3.0 * a * a * a, 1e-9, "control: alpha = 1e-100: fhat = (4/3) alpha^3");
}

int main(void)
{
    char dir[] = "/tmp/gw_left49_XXXXXX";
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    gw_test_part("control characters in names to make", part_control_names, dir);
    gw_test_part("NULL arguments and plain names", part_null_and_plain, dir);
    gw_test_part("gw_chain_fmax1 of a rigid wall", part_fmax1, dir);
    gw_test_part("the chain's scales of no column", part_scales, dir);
    gw_test_part("gw_layer_solve_point below 1e-100", part_solve_point, dir);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        printf("note: %s not removed\n", dir);
    return gw_test_summary("test_library_left49");
}
