/*
 * test_library_hostile.c: the thirty-sixth hostile pass over the library's C
 * interface (docs/library.md "The contract of every call"): the calls a user
 * can make that test_hostile_api, test_null_calls and test_layer_null_calls do
 * not reach, given NULL where a pointer is written or read, NaN, infinities,
 * 1e308, subnormals and negative counts in their numbers, and names that are
 * no file of a directory. What the pass found, each checked here:
 *   - SIGSEGV, or an abort under AddressSanitizer: gw_parse_long and
 *     gw_parse_int_range given NULL for the result, gw_fnv1a64_parse NULL,
 *     gw_err_set a NULL format, gw_fit_power NULL, gw_stats_diagram_make a
 *     negative count (malloc of SIZE_MAX), gw_chain_rk4_study_apply NULL,
 *     gw_chain_study_speeds_check NULL, gw_layer_solve_point NULL results,
 *     gw_layer_impact_step_check a NULL sp, gw_layer_write_vtk a NULL layer,
 *     gw_layer_write_pvd NULL lists;
 *   - GW_OK with a wrong or meaningless value: gw_fit_linear through a NaN
 *     point gave slope 0, through one abscissa slope NaN; the column's run
 *     options dt_out, t_max, energy_tol, front_threshold, steps_per_tc NaN or
 *     negative ran as their defaults; gw_chain_rk4_study_apply with a speed of
 *     NaN or 0 set dt_out to NaN or inf; the work bound passed 9.2e18:9.2e18
 *     (cancellation) and 5:1; the falcon sizes -5:9.2e18; the trace bound a
 *     NaN span or dt-out; gw_sheet_apply a law outside the enum (run as the
 *     layer law) and a NaN yield (run as the sheet's own); the fall check a
 *     NaN gravity (as none); gw_layer_impact_step_check a NULL ip; the B.28
 *     binary loss of r = -5 that of r = 5; gw_stats_diagram_make a NaN
 *     criterion; gw_outset_begin the name "../F", whose commit removes F
 *     beside the directory;
 *   - a wrong message: gw_json_write(path, NULL) said "out of memory" (and
 *     gw_json_print GW_ENOMEM); gw_chain_trace_check of 2^31 beads "about 0 GB".
 * Neighbours that held are checked too (controls: a valid call still gives its
 * value), and two threads running collisions on two chains give the answers
 * they give alone. Every case runs in its own child process with a time limit:
 * a crash or a leak (LeakSanitizer in the sanitizer build) fails that case,
 * and so does anything the library prints.
 */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "granwave.h"
#include "test_child.h"

static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* ---- common: parsing, hashes, messages, fits ---- */

static int parse_long_null_out(void)
{
    gw_err e = {{0}};
    EXPECT(refused(gw_parse_long("5", "n", 0, 9, NULL, &e), &e, "out is NULL"));
    long a = 7, b = 7;
    EXPECT(refused(gw_parse_int_range("1:5", "n", 0, 9, NULL, &b, &e), &e, "a is NULL"));
    EXPECT(refused(gw_parse_int_range("3", "n", 0, 9, &a, NULL, &e), &e, "b is NULL"));
    EXPECT(a == 7 && b == 7);
    return 0;
}

static int parse_long_control(void)
{
    gw_err e = {{0}};
    long v = 0, a = 0, b = 0;
    EXPECT(gw_parse_long("5", "n", 0, 9, &v, &e) == GW_OK && v == 5);
    EXPECT(refused(gw_parse_long("99999999999999999999", "n", LONG_MIN, LONG_MAX, &v, &e), &e, "n: "));
    EXPECT(gw_parse_int_range("2:4", "n", 0, 9, &a, &b, &e) == GW_OK && a == 2 && b == 4);
    return 0;
}

static int hash_parse_null(void)
{
    unsigned long long h = 5;
    char hex[16];
    memset(hex, 'a', sizeof hex); /* 16 digits, no NUL within the size */
    EXPECT(gw_fnv1a64_parse(NULL, 16, &h) == 0 && h == 5);
    EXPECT(gw_fnv1a64_parse(hex, 16, NULL) == 0);
    EXPECT(gw_fnv1a64_parse(hex, 16, &h) == 1 && h == 0xaaaaaaaaaaaaaaaaULL);
    EXPECT(gw_fnv1a64_parse(hex, 15, &h) == 0);
    return 0;
}

static int err_set_null_format(void)
{
    gw_err e = {{0}};
    EXPECT(gw_err_set(&e, GW_EINVAL, NULL) == GW_EINVAL);
    EXPECT(strlen(e.msg) < sizeof e.msg && !strchr(e.msg, '\n'));
    EXPECT(gw_err_set(NULL, GW_EIO, NULL) == GW_EIO);
    return 0;
}

static int fit_nan_point(void)
{
    const double x[3] = {1, 2, 3}, y[3] = {1, NAN, 3}, xi[3] = {1, INFINITY, 3};
    gw_linfit f = {.c1 = 42};
    EXPECT(gw_fit_linear(x, y, 3, &f) == GW_EINVAL && isnan(f.c1) && isnan(f.c0));
    f.c1 = 42;
    EXPECT(gw_fit_linear(xi, x, 3, &f) == GW_EINVAL && isnan(f.c1));
    return 0;
}

static int fit_one_abscissa(void)
{
    const double x[3] = {2, 2, 2}, y[3] = {1, 2, 3};
    gw_linfit f = {.c1 = 42};
    EXPECT(gw_fit_linear(x, y, 3, &f) == GW_EINVAL && isnan(f.c1));
    return 0;
}

static int fit_power_null(void)
{
    gw_linfit f;
    EXPECT(gw_fit_power(NULL, NULL, 3, &f) == GW_EINVAL);
    const double x[2] = {1, 2};
    EXPECT(gw_fit_power(x, x, 2, NULL) == GW_EINVAL);
    return 0;
}

static int fit_control(void)
{
    /* y = 1 + 2x exactly, and y = 3 x^0.2 through logs: within rounding */
    const double x[4] = {1, 2, 3, 5}, y[4] = {3, 5, 7, 11};
    double yp[4];
    for (int i = 0; i < 4; i++)
        yp[i] = 3 * pow(x[i], 0.2);
    gw_linfit f;
    EXPECT(gw_fit_linear(x, y, 4, &f) == GW_OK && fabs(f.c1 - 2) < 1e-12 && fabs(f.c0 - 1) < 1e-12);
    EXPECT(gw_fit_power(x, yp, 4, &f) == GW_OK && fabs(f.c1 - 0.2) < 1e-12 && fabs(exp(f.c0) - 3) < 1e-12);
    EXPECT(gw_fit_linear(x, y, 1, &f) == GW_EINVAL);
    return 0;
}

/* A path of this process under /tmp (builds running the test at once). */
static const char *tmp_path(char *buf, size_t n, const char *name)
{
    snprintf(buf, n, "/tmp/gw_library_hostile.%ld.%s", (long)getpid(), name);
    return buf;
}

static int json_null_object(void)
{
    char pb[256];
    const char *path = tmp_path(pb, sizeof pb, "null.json");
    unlink(path);
    gw_err e = {{0}};
    EXPECT(refused(gw_json_write(path, NULL, &e), &e, "o is NULL"));
    EXPECT(!strstr(e.msg, "memory") && !exists(path));
    EXPECT(gw_json_print(NULL, stdout) == GW_EINVAL);
    return 0;
}

static int struct_size_names(void)
{
    EXPECT(gw_struct_size("gw_err") == sizeof(gw_err));
    EXPECT(gw_struct_size(NULL) == 0 && gw_struct_size("") == 0 && gw_struct_size("gw_err ") == 0);
    EXPECT(gw_struct_size("GW_ERR") == 0 && gw_struct_size("gw_no_such") == 0);
    const char *s = gw_strerror(INT_MIN), *t = gw_strerror(1);
    EXPECT(s && t && !strchr(s, '\n') && !strchr(t, '\n'));
    return 0;
}

static int outset_names(void)
{
    char db[256], bb[256], up1[256];
    const char *dir = tmp_path(db, sizeof db, "set"), *beside = tmp_path(bb, sizeof bb, "beside");
    snprintf(up1, sizeof up1, "../%s", beside + strlen("/tmp/"));
    gw_err e = {{0}};
    FILE *f = fopen(beside, "w");
    EXPECT(f && fputs("kept\n", f) >= 0 && fclose(f) == 0);
    gw_outset s;
    const char *up[] = {"a.csv", up1, NULL}, *empty[] = {"", NULL}, *dot[] = {"..", NULL};
    int rc = gw_outset_begin(&s, dir, up, &e);
    if (rc == GW_OK) /* the commit removed the name the run did not write */
        gw_outset_commit(&s, &e);
    const int kept = exists(beside);
    unlink(beside);
    EXPECT(refused(rc, &e, "is not a file name"));
    EXPECT(strstr(e.msg, up1));
    EXPECT(kept);
    rc = gw_outset_begin(&s, dir, empty, &e);
    if (rc == GW_OK)
        gw_outset_abort(&s);
    EXPECT(refused(rc, &e, "is not a file name"));
    rc = gw_outset_begin(&s, dir, dot, &e);
    if (rc == GW_OK)
        gw_outset_abort(&s);
    EXPECT(refused(rc, &e, "is not a file name"));
    const char *ok[] = {"a.csv", NULL}; /* control */
    EXPECT(gw_outset_begin(&s, dir, ok, &e) == GW_OK);
    gw_outset_abort(&s);
    return 0;
}

/* ---- statistics ---- */

static int diagram_negative_count(void)
{
    gw_stats_diagram d;
    const double x[2] = {1, 2};
    gw_err e = {{0}};
    EXPECT(refused(gw_stats_diagram_make(-3, x, x, x, x, 0.75, &d, &e), &e, "-3 cells"));
    gw_stats_diagram_free(&d);
    EXPECT(refused(gw_stats_diagram_make(INT_MIN, x, x, x, x, 0.75, &d, &e), &e, "cells"));
    gw_stats_diagram_free(&d);
    return 0;
}

/* Four cells (R_b/R_m 1, 2 x H/R_m 1, 2), every share 1: no crossing. */
static int diagram_criterion_and_pen(void)
{
    const double x[4] = {1, 1, 2, 2}, h[4] = {1, 2, 1, 2}, s[4] = {1, 1, 1, 1}, pen[4] = {0.1, 0.1, 0.1, 0.1};
    gw_stats_diagram d;
    gw_err e = {{0}};
    EXPECT(refused(gw_stats_diagram_make(4, x, h, s, pen, NAN, &d, &e), &e, "criterion"));
    gw_stats_diagram_free(&d);
    EXPECT(refused(gw_stats_diagram_make(4, x, h, s, pen, 1.5, &d, &e), &e, "criterion"));
    gw_stats_diagram_free(&d);
    /* gw_stats.h: "pen may be NULL" (it was refused naming pen) */
    int rc = gw_stats_diagram_make(4, x, h, s, NULL, 0.75, &d, &e);
    gw_stats_diagram_free(&d);
    EXPECT(rc == GW_OK);
    EXPECT(gw_stats_diagram_make(4, x, h, s, pen, 0.75, &d, &e) == GW_OK); /* control */
    gw_stats_diagram_free(&d);
    return 0;
}

static int binary_loss_ratio(void)
{
    EXPECT(isnan(gw_stats_binary_loss(-5, 0)) && isnan(gw_stats_binary_loss(0, 1)));
    EXPECT(isnan(gw_stats_binary_loss(NAN, 0)));
    /* control: m = r^2 = 25, B.28 4m/(1+m)^2; m <= 1: 1 */
    EXPECT(fabs(gw_stats_binary_loss(5, 0) - 100.0 / 676.0) < 1e-15 && gw_stats_binary_loss(0.5, 0) == 1);
    return 0;
}

/* ---- the column ---- */

static int rk4_apply_hostile(void)
{
    gw_chain_run_opts o = gw_chain_run_opts_default();
    const gw_chain_params p = gw_chain_params_default();
    EXPECT(gw_chain_rk4_study_apply(NULL, &p, 1e-6, 0.3, 0) == 0);
    EXPECT(gw_chain_rk4_study_apply(&o, NULL, 1e-6, 0.3, 0) == 0);
    const double bad[] = {NAN, INFINITY, 0, -0.3};
    for (int i = 0; i < 4; i++) {
        o = gw_chain_run_opts_default();
        EXPECT(gw_chain_rk4_study_apply(&o, &p, 1e-6, bad[i], 0) == 0 && o.dt_out == 0 && o.solver == gw_solver_cvode);
    }
    /* control: the dt_out of the target, tau_1/10 at 0.3 m/s */
    o = gw_chain_run_opts_default();
    const int m = gw_chain_rk4_study_apply(&o, &p, 1e-6, 0.3, 0);
    EXPECT(m > 0 && o.solver == gw_solver_rk4 && fabs(o.dt_out - gw_chain_tau1(p.mass, p.kwall, 0.3) / 10) <= 0);
    return 0;
}

static int speeds_and_sizes(void)
{
    gw_err e = {{0}};
    EXPECT(refused(gw_chain_study_speeds_check(NULL, 3, 0, &e), &e, "v is NULL"));
    EXPECT(refused(gw_chain_falcon_sizes_check(-5, LONG_MAX, &e), &e, "n: "));
    EXPECT(refused(gw_chain_falcon_sizes_check(9, 3, &e), &e, "n: "));
    EXPECT(gw_chain_falcon_sizes_check(1, 20, &e) == GW_OK); /* control */
    return 0;
}

static int work_bound(void)
{
    gw_err e = {{0}};
    EXPECT(refused(gw_chain_study_work_check(LONG_MAX, LONG_MAX, 1, &e), &e, "n: "));
    EXPECT(refused(gw_chain_study_work_check(5, 1, 1, &e), &e, "n: 5:1"));
    EXPECT(refused(gw_chain_study_work_check(-100, 5, 1, &e), &e, "n: "));
    /* controls: sum N^2 over 1..100 = 338350 <= 2e6; over 1..200 = 2686700 > 2e6 */
    EXPECT(gw_chain_study_work_check(1, 100, 1, &e) == GW_OK);
    EXPECT(refused(gw_chain_study_work_check(1, 200, 1, &e), &e, "2.69e+06 bead^2"));
    return 0;
}

static int trace_bound(void)
{
    gw_err e = {{0}};
    EXPECT(refused(gw_chain_trace_check(INT_MAX, 1e-3, 1e-6, 0, &e), &e, "n: "));
    EXPECT(!strstr(e.msg, "about 0 GB"));
    EXPECT(refused(gw_chain_trace_check(5, NAN, 1e-6, 0, &e), &e, "gw_chain_trace_check"));
    EXPECT(refused(gw_chain_trace_check(5, 1e-3, NAN, 0, &e), &e, "gw_chain_trace_check"));
    EXPECT(refused(gw_chain_trace_check(5, 1e-3, -1, 0, &e), &e, "gw_chain_trace_check"));
    EXPECT(refused(gw_chain_trace_check(-5, 1e-3, 1e-6, 0, &e), &e, "gw_chain_trace_check"));
    EXPECT(gw_chain_trace_check(5, 1e-3, 1e-6, 22, &e) == GW_OK); /* control */
    return 0;
}

static int sheet_apply_hostile(void)
{
    gw_err e = {{0}};
    gw_chain_params p = gw_chain_params_default();
    const gw_material *steel = gw_material_find("steel");
    const gw_sheet *pvc = gw_sheet_find("pvc");
    EXPECT(steel && pvc);
    gw_layer_law *l = NULL;
    int rc = gw_sheet_apply(pvc, (gw_sheet_law)77, -1, -1, steel, steel, &p, &l, &e);
    gw_layer_law_free(l);
    EXPECT(refused(rc, &e, "sheet-law"));
    l = NULL;
    rc = gw_sheet_apply(pvc, GW_SHEET_MATERIAL, NAN, -1, steel, steel, &p, &l, &e);
    gw_layer_law_free(l);
    EXPECT(refused(rc, &e, "sheet-yield"));
    l = NULL;
    rc = gw_sheet_apply(pvc, GW_SHEET_MATERIAL, -1, INFINITY, steel, steel, &p, &l, &e);
    gw_layer_law_free(l);
    EXPECT(refused(rc, &e, "sheet-loss"));
    l = NULL;
    rc = gw_sheet_apply(pvc, GW_SHEET_HERTZ, -1, -1, NULL, steel, &p, &l, &e);
    gw_layer_law_free(l);
    EXPECT(refused(rc, &e, "bead is NULL"));
    l = NULL; /* control: the fitted law's K_eff */
    EXPECT(gw_sheet_apply(pvc, GW_SHEET_FITTED, -1, -1, steel, steel, &p, &l, &e) == GW_OK && l == NULL);
    EXPECT(p.kwall == gw_sheet_kwall(pvc, p.mass) && p.kwall > 0);
    return 0;
}

/* A run option that is NaN or negative is refused naming it (it ran as the
 * default); 0 still is the default. */
static int run_opts_numbers(void)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 2;
    gw_chain *c = NULL;
    gw_err e = {{0}};
    EXPECT(gw_chain_create(&p, &c, &e) == GW_OK);
    const char *names[] = {"dt_out", "t_max", "energy_tol", "front_threshold", "steps_per_tc"};
    const double bad[] = {NAN, -1, INFINITY};
    int failed = 0;
    for (int k = 0; k < 5 && !failed; k++)
        for (int i = 0; i < 3 && !failed; i++) {
            gw_chain_run_opts o = gw_chain_run_opts_default();
            double *f[] = {&o.dt_out, &o.t_max, &o.energy_tol, &o.front_threshold, &o.steps_per_tc};
            *f[k] = bad[i];
            if (k == 4)
                o.solver = gw_solver_rk4;
            gw_chain_result r;
            const int rc = gw_chain_collide(c, &o, &r, &e);
            gw_chain_result_free(&r);
            failed = !refused(rc, &e, names[k]);
            if (!failed)
                failed = !refused(gw_chain_run_check(&p, &o, &e), &e, names[k]);
        }
    gw_chain_run_opts o = gw_chain_run_opts_default(); /* control: F.13 for N = 1... of two beads, the run's own */
    gw_chain_result r;
    const int rc = gw_chain_collide(c, &o, &r, &e);
    const double f = r.f_max;
    gw_chain_result_free(&r);
    gw_chain_free(c);
    EXPECT(!failed);
    EXPECT(rc == GW_OK && f > 0 && isfinite(f));
    return 0;
}

/* ---- the layer ---- */

static int solve_point_null(void)
{
    gw_err e = {{0}};
    double d = 0, f = 0;
    EXPECT(refused(gw_layer_solve_point(1, 0.3, 0.5, NULL, &f, &e), &e, "dhat is NULL"));
    EXPECT(refused(gw_layer_solve_point(1, 0.3, 0.5, &d, NULL, &e), &e, "fhat is NULL"));
    EXPECT(refused(gw_layer_solve_point(NAN, 0.3, 0.5, &d, &f, &e), &e, "layer law"));
    EXPECT(gw_layer_solve_point(1, 0.3, 0.5, &d, &f, &e) == GW_OK && d > 0 && f > 0); /* control */
    return 0;
}

static int step_and_fall_checks(void)
{
    gw_err e = {{0}};
    const gw_layer_impact_params ip = gw_layer_impact_params_default();
    const gw_solver_params sp = gw_solver_params_default();
    EXPECT(refused(gw_layer_impact_step_check(NULL, gw_solver_verlet, &sp, &e), &e, "ip is NULL"));
    EXPECT(refused(gw_layer_impact_step_check(&ip, gw_solver_verlet, NULL, &e), &e, "sp is NULL"));
    EXPECT(refused(gw_layer_impact_fall_check(&ip, NAN, &e), &e, "gravity"));
    EXPECT(refused(gw_layer_impact_fall_check(&ip, -INFINITY, &e), &e, "gravity"));
    EXPECT(gw_layer_impact_fall_check(&ip, 9.81, &e) == GW_OK); /* control: the default gap */
    EXPECT(gw_layer_impact_step_check(&ip, gw_solver_verlet, &sp, &e) == GW_OK);
    return 0;
}

static int writers_null(void)
{
    char vb[256], pb[256];
    const char *vtk = tmp_path(vb, sizeof vb, "vtk"), *pvd = tmp_path(pb, sizeof pb, "pvd");
    unlink(vtk);
    unlink(pvd);
    gw_err e = {{0}};
    EXPECT(refused(gw_layer_write_vtk(NULL, vtk, "t", &e), &e, "L is NULL"));
    EXPECT(refused(gw_layer_write_pvd(pvd, 1, NULL, NULL, &e), &e, "files is NULL"));
    EXPECT(refused(gw_layer_write_pvd(pvd, -1, NULL, NULL, &e), &e, "n < 0"));
    const char *files[1] = {"a.vtk"};
    const double t[1] = {NAN};
    EXPECT(refused(gw_layer_write_pvd(pvd, 1, files, t, &e), &e, "time not finite"));
    EXPECT(!exists(vtk) && !exists(pvd));
    const double t1[1] = {1e-3}; /* control */
    EXPECT(gw_layer_write_pvd(pvd, 1, files, t1, &e) == GW_OK && exists(pvd));
    unlink(pvd);
    return 0;
}

/* gw_layer_rings with a negative count is a no-op (it asked realloc for
 * SIZE_MAX bytes: an abort under ASan); 4 rings still get their values. */
static int rings_negative_count(void)
{
    gw_layer_params p = gw_layer_params_default();
    gw_layer_body b[2] = {{.x = 0.1, .y = 0.1, .r = 1e-2}, {.x = 0.3, .y = 0.1, .r = 1e-2}};
    gw_layer *L = NULL;
    gw_err e = {{0}};
    EXPECT(gw_layer_create(&p, 2, b, &L, &e) == GW_OK);
    double kin[4] = {7, 7, 7, 7}, st[4] = {7, 7, 7, 7}, co[4] = {7, 7, 7, 7};
    gw_layer_rings(L, 0.2, 0.1, 0.05, -3, kin, st, co);
    const int untouched = kin[0] == 7 && st[0] == 7 && co[0] == 7;
    /* control: both discs 0.1 m from the centre, in ring 2, at rest and apart */
    gw_layer_rings(L, 0.2, 0.1, 0.05, 4, kin, st, co);
    gw_layer_free(L);
    EXPECT(untouched);
    EXPECT(kin[2] == 0 && st[2] == 0 && co[2] == 0);
    return 0;
}

/* A wall-force trace with a NaN sample is no spectrum (every bin was NaN and
 * the peak a meaningless bin, GW_OK); the same trace without it has its peak
 * at the sine's frequency. */
static int spectrum_nan_force(void)
{
    gw_chain_trace t;
    gw_chain_trace_init(&t, 1);
    const double f = 20e3, dt = 1e-6, x[2] = {0, 0}; /* 20 kHz sampled at 1 MHz, 1000 samples */
    for (int k = 0; k < 1000; k++)
        gw_chain_trace_sample(&t, k * dt, x, k == 300 ? NAN : sin(2 * M_PI * f * k * dt), 0);
    gw_chain_spectrum sp;
    gw_err e = {{0}};
    const int rc = gw_chain_wall_spectrum(&t, 0, 999 * dt, 0, 0, 0, &sp, &e);
    gw_chain_spectrum_free(&sp);
    t.f[300] = sin(2 * M_PI * f * 300 * dt);
    const int ok = gw_chain_wall_spectrum(&t, 0, 999 * dt, 0, 0, 0, &sp, &e);
    const double peak = sp.f_peak;
    gw_chain_spectrum_free(&sp);
    gw_chain_trace_free(&t);
    EXPECT(rc == GW_EINVAL);
    /* the peak within a bin of the zero-padded spectrum, 1/(8 T) = 125 Hz */
    EXPECT(ok == GW_OK && fabs(peak - f) < 250);
    return 0;
}

/* ---- two threads, two chains: each the answer it gives alone ---- */

typedef struct {
    int n;
    double f_max, tau_n;
    int rc;
} one_run;

static void *collide_one(void *arg)
{
    one_run *r = arg;
    gw_chain_params p = gw_chain_params_default();
    p.n = r->n;
    gw_chain *c = NULL;
    gw_err e = {{0}};
    r->rc = gw_chain_create(&p, &c, &e);
    if (r->rc == GW_OK) {
        gw_chain_run_opts o = gw_chain_run_opts_default();
        gw_chain_result res;
        r->rc = gw_chain_collide(c, &o, &res, &e);
        r->f_max = res.f_max, r->tau_n = res.tau_n;
        gw_chain_result_free(&res);
    }
    gw_chain_free(c);
    return NULL;
}

/* gw_chain_drop_params_validate: a subnormal height or t-max passed (0, 1]
 * and the drop failed later as "the solution blew up"; the program's table
 * refused them (below 1e-6). 1e-6 itself is valid. */
static int drop_subnormal(void)
{
    gw_err e = {0};
    gw_chain_drop_params p = gw_chain_drop_params_default();
    EXPECT(gw_chain_drop_params_validate(&p, &e) == GW_OK);
    p.height = 4.9e-324;
    EXPECT(refused(gw_chain_drop_params_validate(&p, &e), &e, "height"));
    p.height = 1e-6;
    EXPECT(gw_chain_drop_params_validate(&p, &e) == GW_OK);
    p.t_max = 4.9e-324;
    EXPECT(refused(gw_chain_drop_params_validate(&p, &e), &e, "t-max"));
    p.t_max = 1e-7;
    EXPECT(refused(gw_chain_drop_params_validate(&p, &e), &e, "t-max"));
    p.t_max = 1e-6;
    EXPECT(gw_chain_drop_params_validate(&p, &e) == GW_OK);
    return 0;
}

static int two_threads(void)
{
    one_run alone[2] = {{3, 0, 0, -1}, {5, 0, 0, -1}}, both[2] = {{3, 0, 0, -1}, {5, 0, 0, -1}};
    collide_one(&alone[0]);
    collide_one(&alone[1]);
    pthread_t t[2];
    for (int k = 0; k < 2; k++)
        EXPECT(pthread_create(&t[k], NULL, collide_one, &both[k]) == 0);
    for (int k = 0; k < 2; k++)
        pthread_join(t[k], NULL);
    for (int k = 0; k < 2; k++)
        EXPECT(alone[k].rc == GW_OK && both[k].rc == GW_OK && both[k].f_max == alone[k].f_max &&
               both[k].tau_n == alone[k].tau_n);
    return 0;
}

/* ---- the thirty-seventh pass ---- */

/* gw_check_range with a NaN bound took it as none (every finite x passed);
 * lo > hi likewise is no range. Refused naming the bound, whatever x; the
 * list parser's bounds too. Controls: a range still checks. */
static int check_range_bounds(void)
{
    gw_err e = {{0}};
    EXPECT(refused(gw_check_range(1, "a", NAN, 2, &e), &e, "lo is NaN"));
    EXPECT(strstr(e.msg, "a: "));
    EXPECT(refused(gw_check_range(1, "a", 0, NAN, &e), &e, "hi is NaN"));
    EXPECT(refused(gw_check_range(1e300, "a", -NAN, NAN, &e), &e, "lo is NaN"));
    EXPECT(refused(gw_check_range(1, "a", 5, 2, &e), &e, "lo > hi"));
    double *v = (double *)&e;
    int n = 7;
    EXPECT(refused(gw_parse_double_list_in("1,2", "l", NAN, 5, 0, &v, &n, &e), &e, "lo is NaN"));
    EXPECT(v == NULL && n == 0);
    EXPECT(refused(gw_parse_double_list_in("1,2", "l", 0, NAN, 0, &v, &n, &e), &e, "hi is NaN"));
    /* controls */
    EXPECT(gw_check_range(1, "a", 0, 2, &e) == GW_OK && gw_check_range(2, "a", 2, 2, &e) == GW_OK);
    EXPECT(gw_check_range(1, "a", -INFINITY, INFINITY, &e) == GW_OK);
    EXPECT(refused(gw_check_range(3, "a", 0, 2, &e), &e, "a: 3 is outside [0, 2]"));
    EXPECT(refused(gw_check_range(3, NULL, 0, 2, &e), &e, "value: 3"));
    EXPECT(gw_parse_double_list_in("1,2", "l", 0, 5, 0, &v, &n, &e) == GW_OK && n == 2 && v[1] == 2);
    free(v);
    /* every caller still works: a column, a drop, a layer's parameters */
    gw_chain_params p = gw_chain_params_default();
    gw_chain *c = NULL;
    EXPECT(gw_chain_create(&p, &c, &e) == GW_OK);
    gw_chain_free(c);
    gw_chain_drop_params d = gw_chain_drop_params_default();
    EXPECT(gw_chain_drop_params_validate(&d, &e) == GW_OK);
    gw_layer_params lp = gw_layer_params_default();
    EXPECT(gw_layer_params_validate(&lp, &e) == GW_OK);
    return 0;
}

/* An output set begun again while open: it was zeroed before the refusal,
 * its staged file lost, and the thread's set left pointing at it: every later
 * begin on the thread was refused ("already open") and every commit said "no
 * output set open". Now refused untouched: its commit places its file. */
static int outset_begin_again(void)
{
    char db[256];
    const char *dir = tmp_path(db, sizeof db, "again");
    char path[300];
    snprintf(path, sizeof path, "%s/a.csv", dir);
    gw_err e = {{0}};
    EXPECT(gw_mkdir_p(dir, &e) == GW_OK);
    unlink(path);
    const char *names[] = {"a.csv", NULL};
    gw_outset s, t;
    EXPECT(gw_outset_begin(&s, dir, names, &e) == GW_OK);
    gw_afile f;
    EXPECT(gw_afile_open(&f, path, &e) == GW_OK && fputs("1\n", f.fp) >= 0 && gw_afile_commit(&f, &e) == GW_OK);
    const int again = gw_outset_begin(&s, dir, names, &e);
    const int agained = refused(again, &e, "open on this thread");
    const int committed = gw_outset_commit(&s, &e);
    gw_outset_abort(&s);
    const int placed = exists(path);
    /* the thread takes a new set afterwards */
    const int next = gw_outset_begin(&t, dir, names, &e);
    gw_outset_abort(&t);
    unlink(path);
    rmdir(dir);
    EXPECT(agained);
    EXPECT(committed == GW_OK && placed);
    EXPECT(next == GW_OK);
    return 0;
}

/* An empty dir: the commit's paths "DIR/NAME" were "/NAME", and it removed
 * the set's names not written from the root directory. Refused naming dir. A
 * commit or abort of a struct that is not this thread's open set (zeroed,
 * 0xff: a refused begin's garbage) is refused or ignored, never read. */
static int outset_empty_and_garbage(void)
{
    gw_err e = {{0}};
    gw_outset s;
    const char *names[] = {"gw_library_hostile_never.csv", NULL};
    const int rc = gw_outset_begin(&s, "", names, &e);
    if (rc == GW_OK)
        gw_outset_abort(&s);
    EXPECT(refused(rc, &e, "dir is empty"));
    memset(&s, 0xff, sizeof s);
    EXPECT(gw_outset_commit(&s, &e) == GW_EIO && strstr(e.msg, "no output set open"));
    gw_outset_abort(&s);
    memset(&s, 0, sizeof s);
    EXPECT(gw_outset_commit(&s, &e) == GW_EIO);
    gw_outset_abort(&s);
    char db[256]; /* control: the thread still takes a set, "." too */
    EXPECT(gw_outset_begin(&s, tmp_path(db, sizeof db, "garbage"), names, &e) == GW_OK);
    gw_outset_abort(&s);
    return 0;
}

/* A sweep model's case given a negative count ran the defaults (GW_OK, a
 * row for no case asked); a NULL name crashed the layer model (SIGSEGV) and
 * was quoted "(null)" by the chain's; a key given twice ran its last value.
 * Refused naming what, in the models' run, check and part calls. */
static int sweep_pairs(void)
{
    gw_err e = {{0}};
    double out[64];
    unsigned long long h = 0;
    const char *nm[] = {"n", "vimp"}, *vl[] = {"3", "0.3"};
    EXPECT(refused(gw_chain_sweep_run_part(-1, nm, vl, out, &h, NULL, NULL, &e), &e, "nkeys: -1"));
    EXPECT(refused(gw_chain_sweep_run_part(INT_MIN, NULL, NULL, out, &h, NULL, NULL, &e), &e, "nkeys"));
    EXPECT(refused(gw_layer_sweep_run_part(-1, nm, vl, out, &h, NULL, NULL, &e), &e, "nkeys: -1"));
    EXPECT(refused(gw_chain_sweep_model.check(-2, nm, vl, &e), &e, "nkeys: -2"));
    EXPECT(refused(gw_layer_sweep_model.check(-2, nm, vl, &e), &e, "nkeys: -2"));
    const char *nul[] = {NULL}, *one[] = {"3"}, *nn[] = {"n"}, *nulv[] = {NULL};
    EXPECT(refused(gw_layer_sweep_run_part(1, nul, one, out, &h, NULL, NULL, &e), &e, "names[0] is NULL"));
    EXPECT(refused(gw_layer_sweep_model.check(1, nul, one, &e), &e, "names[0] is NULL"));
    EXPECT(refused(gw_chain_sweep_run_part(1, nul, one, out, &h, NULL, NULL, &e), &e, "names[0] is NULL"));
    EXPECT(refused(gw_chain_sweep_run_part(1, nn, nulv, out, &h, NULL, NULL, &e), &e, "values[0] is NULL"));
    const char *twice[] = {"n", "n"}, *tv[] = {"3", "4"}, *dash[] = {"dt-out", "dt_out"}, *dv[] = {"1e-6", "2e-6"};
    EXPECT(refused(gw_chain_sweep_run_part(2, twice, tv, out, &h, NULL, NULL, &e), &e, "n: given twice"));
    EXPECT(refused(gw_chain_sweep_model.check(2, dash, dv, &e), &e, "dt_out: given twice"));
    /* control: each key once runs, in either order, to one row */
    const char *mn[] = {"vimp", "n"}, *lv[] = {"0.3", "3"};
    EXPECT(gw_chain_sweep_run_part(2, nm, vl, out, &h, NULL, NULL, &e) == GW_OK);
    double row[64];
    memcpy(row, out, sizeof row);
    EXPECT(gw_chain_sweep_run_part(2, mn, lv, out, &h, NULL, NULL, &e) == GW_OK);
    EXPECT(memcmp(row, out, (size_t)gw_chain_sweep_model.ncolumns * sizeof *out) == 0);
    return 0;
}

/* gw_stats_write_files(NULL, dir): the first writer read the NULL analysis
 * (SIGSEGV), after making dir. Refused naming A, nothing made. */
static int stats_write_null(void)
{
    char db[256];
    const char *dir = tmp_path(db, sizeof db, "stats");
    rmdir(dir);
    gw_err e = {{0}};
    EXPECT(refused(gw_stats_write_files(NULL, dir, &e), &e, "A is NULL"));
    EXPECT(!exists(dir));
    return 0;
}

/* A layer grid's x check (x = 0, 1e-300: one block position, one impact run
 * as two groups) covered only the samples the check pass keeps in memory (up
 * to 1e5 particles): on a larger sample both cases passed. A row of 100001
 * touching discs on the floor (one particle high, at rest): the second x is
 * refused naming x and both values, as on a 1000-disc row (control). */
static int big_sample_row(const char *path, int n)
{
    const double r = 0.01;
    gw_layer_sample s;
    memset(&s, 0, sizeof s);
    s.n = n, s.width = 2 * r * n, s.rm = r, s.volume_ratio = 1, s.porosity = NAN;
    s.x = malloc(3 * (size_t)n * sizeof *s.x); /* one block, as gw_layer_sample_free frees it */
    if (!s.x)
        return GW_ENOMEM;
    s.y = s.x + n, s.r = s.x + 2 * n;
    for (int i = 0; i < n; i++)
        s.x[i] = (2 * i + 1) * r, s.y[i] = r, s.r[i] = r;
    gw_err e = {{0}};
    const int rc = gw_layer_sample_write(&s, path, NULL, &e);
    gw_layer_sample_free(&s);
    return rc;
}

static int x_check_on(const char *path, gw_err *e)
{
    char cfg[512];
    snprintf(cfg, sizeof cfg, "[sweep]\nmodel = layer\n[grid]\nx = 0, 1e-300\n[params]\nsample = %s\n", path);
    const gw_sweep_model *models[] = {&gw_layer_sweep_model}, *m = NULL;
    gw_sweep_config c;
    int rc = gw_sweep_config_read_string(cfg, "cfg", models, 1, &c, &m, e);
    void *memo = NULL;
    for (long k = 0; rc == GW_OK && k < c.ncases; k++) {
        const char *nm[16], *vl[16];
        if ((rc = gw_sweep_case(&c, k, nm, vl)) == GW_OK)
            rc = gw_sweep_case_check(m, &memo, c.ngrid + c.nparams, nm, vl, e);
    }
    if (m)
        gw_sweep_checks_end(m, memo);
    gw_sweep_config_free(&c);
    return rc;
}

static int x_check_large_sample(void)
{
    char bb[256], sb[256];
    const char *big = tmp_path(bb, sizeof bb, "big.txt"), *small = tmp_path(sb, sizeof sb, "small.txt");
    gw_err e = {{0}};
    EXPECT(big_sample_row(big, 100001) == GW_OK && big_sample_row(small, 1000) == GW_OK);
    const int rs = x_check_on(small, &e);
    const int ok_small = refused(rs, &e, "x: 0 and 1e-300 m put the block at one position");
    const int rb = x_check_on(big, &e);
    const int ok_big = refused(rb, &e, "x: 0 and 1e-300 m put the block at one position");
    unlink(big);
    unlink(small);
    EXPECT(ok_small);
    EXPECT(ok_big && strstr(e.msg, "width 2000.02 m"));
    return 0;
}

int main(void)
{
    static const child_row cases[] = {
        {"gw_parse_long/int_range: NULL result", parse_long_null_out},
        {"gw_parse_long/int_range: control", parse_long_control},
        {"gw_fnv1a64_parse: NULL, 16 digits without a NUL", hash_parse_null},
        {"gw_err_set: NULL format", err_set_null_format},
        {"gw_fit_linear: a NaN or inf point", fit_nan_point},
        {"gw_fit_linear: one abscissa", fit_one_abscissa},
        {"gw_fit_power: NULL", fit_power_null},
        {"gw_fit_linear/power: control", fit_control},
        {"gw_json_write/print: NULL object", json_null_object},
        {"gw_struct_size/gw_strerror: unknown names and codes", struct_size_names},
        {"gw_outset_begin: names that are no file of the directory", outset_names},
        {"gw_stats_diagram_make: a negative count", diagram_negative_count},
        {"gw_stats_diagram_make: NaN criterion, pen NULL", diagram_criterion_and_pen},
        {"gw_stats_binary_loss: a ratio not > 0", binary_loss_ratio},
        {"gw_chain_rk4_study_apply: NULL and a speed not > 0", rk4_apply_hostile},
        {"gw_chain_study_speeds_check/falcon_sizes_check", speeds_and_sizes},
        {"gw_chain_study_work_check: huge and reversed ranges", work_bound},
        {"gw_chain_trace_check: 2^31 beads, NaN, negative", trace_bound},
        {"gw_sheet_apply: law 77, NaN yield, inf loss, NULL bead", sheet_apply_hostile},
        {"gw_chain_collide/run_check: run options NaN, -1, inf", run_opts_numbers},
        {"gw_layer_solve_point: NULL results", solve_point_null},
        {"gw_layer_impact_step_check/fall_check: NULL, NaN gravity", step_and_fall_checks},
        {"gw_layer_write_vtk/pvd: NULL, n < 0, NaN time", writers_null},
        {"gw_layer_rings: a negative count", rings_negative_count},
        {"gw_chain_wall_spectrum: a NaN force sample", spectrum_nan_force},
        {"gw_chain_drop_params_validate: subnormal height and t-max", drop_subnormal},
        {"two threads, two chains", two_threads},
        {"gw_check_range/parse_double_list_in: NaN bounds, lo > hi", check_range_bounds},
        {"gw_outset_begin: the open set begun again", outset_begin_again},
        {"gw_outset_begin/commit/abort: an empty dir, zeroed and 0xff sets", outset_empty_and_garbage},
        {"sweep models: negative nkeys, NULL names, a key twice", sweep_pairs},
        {"gw_stats_write_files: a NULL analysis", stats_write_null},
        {"layer sweep check: x = 0, 1e-300 on a 100001-disc sample", x_check_large_sample},
    };
    return child_cases_run(cases, sizeof cases / sizeof cases[0]);
}
