/*
 * test_library_hostile38.c: the thirty-eighth hostile pass over the library's
 * C interface (docs/library.md "The contract of every call"), at the calls
 * the earlier passes (test_hostile_api, test_null_calls, test_library_hostile)
 * did not reach: the sweep's journal rows, the JSON and path helpers, the
 * materials a C caller fills by hand, the wall's Maxwell arms and the solver
 * layer's times. What the pass found, each checked here:
 *   - gw_sweep_format_row for a case the config has not (k = -1, k = ncases)
 *     formatted the grid values and config hash from the arrays gw_sweep_case
 *     had refused to fill (pointers off the stack) and returned GW_OK;
 *   - gw_json_bools(NULL, 3) read v[0] (SIGSEGV; gw_json_doubles and
 *     gw_json_ints return NULL); gw_path_join wrote to a NULL buf (SIGSEGV)
 *     and joined a NULL dir as "(null)/name" with GW_OK;
 *   - a gw_material filled by hand was never checked: gw_layer_law_create
 *     built a law for a sphere of Young modulus -2e11 Pa (stiffer than steel)
 *     or 0 (GW_OK), gw_sheet_apply ran such a bead, or a NaN wall, and
 *     gw_hertz_coefficient gave INFINITY (a rigid contact) for a NaN or
 *     negative modulus, a Poisson ratio of 7 and a radius of -1 or NaN;
 *   - the wall's Maxwell arms with tau_min tau_max below about 1e-324 (each
 *     1e-200 s, within the documented [0, 1e3]) took the band centre as
 *     infinite: every loss was refused as "beyond what 6 Maxwell arm(s) give
 *     (< -nan)", where the arms are scale-free (1e-5 to 1 s gives < 0.211);
 *   - the solver took a NaN or infinite t0 (rk4 then "reached" any time with
 *     GW_OK and the state untouched), and gw_solver_advance a NaN or infinite
 *     tout (rk4: GW_OK with *t not tout; cvode a convergence failure), and
 *     gw_solver_reset a NaN time;
 *   - gw_afile_open (and _openat) on a file open now zeroed it: its temporary
 *     stayed beside the file, and the commit gave back the mask the first open
 *     had set, leaving SIGINT, SIGTERM and SIGHUP blocked in the thread for
 *     good; gw_afile_open("") made its temporary in the working directory and
 *     only the commit failed.
 * And the lead's, from what the pass left: a solver scale of 0, NaN, a
 * negative or an infinite one was taken (cvode failed at t = 0 on an
 * absolute tolerance of 0, rk4 ran on); rk4 asked for a time before its own
 * returned GW_OK where it stood; gw_stats_binary_loss was NaN past r =
 * 1.3e154 (discs) and at infinity, where the loss tends to 0;
 * gw_sweep_undecided_warning wrote "5 of 3 cases" and a first case -1 as
 * given; gw_param_copy onto itself detached the struct's own texts (lost and
 * leaked, GW_OK), and a size short of the table's rows copied past it;
 * gw_thornton_init took a negative yield pressure (a negative force).
 * Each refusal has a control: the valid call next to it still gives its value
 * (a journal row the sweep's own check takes, the Hertz coefficient of steel
 * against its closed form to 1e-15, the layer law's thick-layer limit equal to
 * gw_hertz_coefficient, the oscillator at cos(1) within 1e-9 with rk4). Every case
 * runs in its own child process (test_child.h): a crash, a sanitizer report or
 * anything printed fails that case.
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "granwave.h"
#include "test_child.h"


/* ---- the sweep's journal rows ---- */

static int sweep_row_case_range(void)
{
    static const char text[] = "[sweep]\nmodel = chain\n[grid]\nn = 1:3\nvimp = 0.1, 0.2\n[params]\nt-max = 1e-3\n";
    int nm;
    const gw_sweep_model *const *ms = gw_sweep_models(&nm);
    gw_sweep_config cfg;
    const gw_sweep_model *m = NULL;
    gw_err e = {{0}};
    memset(&cfg, 0, sizeof cfg);
    EXPECT(gw_sweep_config_read_string(text, "t", ms, nm, &cfg, &m, &e) == GW_OK && cfg.ncases == 6);
    double out[256];
    for (int i = 0; i < 256; i++)
        out[i] = 0.25 * i;
    char buf[8192];
    const long bad[] = {-1, 6, LONG_MAX, LONG_MIN};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        memcpy(buf, "untouched", 10);
        EXPECT(gw_sweep_format_row(&cfg, bad[i], out, m->ncolumns, 0, buf, sizeof buf) == GW_EINVAL);
    }
    EXPECT(gw_sweep_format_row(&cfg, 0, out, -1, 0, buf, sizeof buf) == GW_EINVAL);
    /* control: the last case's row, which the sweep's own check takes */
    EXPECT(gw_sweep_format_row(&cfg, 5, out, m->ncolumns, 0, buf, sizeof buf) == GW_OK);
    EXPECT(strncmp(buf, "5,3,0.2,", 8) == 0 && buf[strlen(buf) - 1] == '\n');
    EXPECT(gw_sweep_row_check(&cfg, buf, &e) == GW_OK);
    gw_sweep_config_free(&cfg);
    return 0;
}

/* ---- JSON and paths ---- */

static int json_bools_null(void)
{
    EXPECT(gw_json_bools(NULL, 3) == NULL);
    EXPECT(gw_json_doubles(NULL, 3) == NULL && gw_json_ints(NULL, 3) == NULL); /* as before */
    const int v[3] = {1, 0, -7};
    cJSON *a = gw_json_bools(v, 3);
    char *s = a ? gw_json_string(a, 0) : NULL;
    EXPECT(s && strcmp(s, "[true,false,true]") == 0);
    free(s);
    cJSON_Delete(a);
    return 0;
}

static int path_join_null(void)
{
    char buf[32] = "untouched";
    EXPECT(gw_path_join(buf, sizeof buf, NULL, "b") == GW_EINVAL && strcmp(buf, "untouched") == 0);
    EXPECT(gw_path_join(buf, sizeof buf, "a", NULL) == GW_EINVAL && strcmp(buf, "untouched") == 0);
    EXPECT(gw_path_join(NULL, 16, "a", "b") == GW_EINVAL);
    EXPECT(gw_path_join(buf, sizeof buf, "dir", "name") == GW_OK && strcmp(buf, "dir/name") == 0);
    EXPECT(gw_path_join(buf, 8, "dir", "name") == GW_EINVAL); /* does not fit: as before */
    return 0;
}

/* ---- atomic files: opened again while open, an empty path ---- */

/* entries of dir besides . and .. */
static int entries(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    if (d)
        closedir(d);
    return d ? n : -1;
}

static int sigint_blocked(void)
{
    sigset_t m;
    sigprocmask(SIG_SETMASK, NULL, &m);
    return sigismember(&m, SIGINT);
}

static int read_is(const char *path, const char *want)
{
    char got[64] = "";
    FILE *fp = fopen(path, "r");
    size_t k = fp ? fread(got, 1, sizeof got - 1, fp) : 0;
    got[k] = '\0';
    if (fp)
        fclose(fp);
    return strcmp(got, want) == 0;
}

static int afile_open_again(void)
{
    char dir[64], a[96], b[96];
    snprintf(dir, sizeof dir, "/tmp/gw_hostile38.%ld", (long)getpid());
    EXPECT(mkdir(dir, 0700) == 0);
    snprintf(a, sizeof a, "%s/a.txt", dir);
    snprintf(b, sizeof b, "%s/b.txt", dir);
    EXPECT(!sigint_blocked());
    for (int at = 0; at < 2; at++) {
        const int dfd = open(dir, O_RDONLY | O_DIRECTORY);
        gw_afile f;
        gw_err e = {{0}};
        EXPECT(dfd >= 0);
        EXPECT((at ? gw_afile_openat(&f, dfd, dir, "a.txt", &e) : gw_afile_open(&f, a, &e)) == GW_OK);
        fputs(at ? "second" : "first", f.fp);
        FILE *fp = f.fp;
        /* opened again while open: refused, f as it was (its stream, its temporary) */
        if (!refused(gw_afile_open(&f, b, &e), &e, "is open") ||
            !refused(gw_afile_openat(&f, dfd, dir, "b.txt", &e), &e, "is open"))
            return 1;
        EXPECT(f.fp == fp && strstr(f.path, "a.txt") && f.tmp[0]);
        EXPECT(gw_afile_commit(&f, &e) == GW_OK);
        /* the file placed, no temporary left beside it, the signals given back */
        EXPECT(read_is(a, at ? "second" : "first") && entries(dir) == 1 && !sigint_blocked());
        /* control: committed, it opens again (and aborts, leaving the file) */
        EXPECT(gw_afile_open(&f, b, &e) == GW_OK);
        gw_afile_abort(&f);
        EXPECT(entries(dir) == 1 && !sigint_blocked());
        close(dfd);
    }
    unlink(a);
    rmdir(dir);
    return 0;
}

static int afile_empty_path(void)
{
    char dir[64], cwd[4096];
    snprintf(dir, sizeof dir, "/tmp/gw_hostile38e.%ld", (long)getpid());
    EXPECT(mkdir(dir, 0700) == 0 && getcwd(cwd, sizeof cwd) && chdir(dir) == 0);
    gw_afile f;
    gw_err e = {{0}};
    const int rc = gw_afile_open(&f, "", &e);
    const int n = entries(".");
    gw_afile_abort(rc == GW_OK ? &f : NULL);
    EXPECT(chdir(cwd) == 0);
    rmdir(dir);
    if (!refused(rc, &e, "an empty path names no file"))
        return 1;
    EXPECT(n == 0 && !sigint_blocked()); /* its temporary was made in the working directory */
    return 0;
}

/* ---- materials filled by hand ---- */

static int hertz_invalid_material(void)
{
    const gw_material *steel = gw_material_find("steel"), *rigid = gw_material_find("rigid");
    const gw_material bad[] = {{"nan", NAN, 0.3, 1},   {"neg", -2e11, 0.3, 1}, {"zero", 0, 0.3, 1},
                               {"minf", -INFINITY, 0.3, 1}, {"nu7", 2e11, 7, 1}, {"nunan", 2e11, NAN, 1},
                               {"nu-1", 2e11, -1, 1}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        EXPECT(isnan(gw_hertz_coefficient(4e-3, &bad[i], INFINITY, steel)));
        EXPECT(isnan(gw_hertz_coefficient(4e-3, steel, 4e-3, &bad[i])));
    }
    EXPECT(isnan(gw_hertz_coefficient(-1, steel, INFINITY, steel)));
    EXPECT(isnan(gw_hertz_coefficient(NAN, steel, INFINITY, steel)));
    EXPECT(isnan(gw_hertz_coefficient(4e-3, steel, 0, steel)));
    /* controls: (F.12) and (F.3) from steel's constants; rigid on rigid is rigid */
    const double R = 4e-3, E = steel->young, nu = steel->poisson;
    const double k_ss = 4.0 / 3.0 * E / (2 * (1 - nu * nu)) * sqrt(R / 2), k_sw = 4.0 / 3.0 * E / (1 - nu * nu) * sqrt(R);
    EXPECT(fabs(gw_hertz_coefficient(R, steel, R, steel) / k_ss - 1) < 1e-15);
    EXPECT(fabs(gw_hertz_coefficient(R, steel, INFINITY, rigid) / k_sw - 1) < 1e-15);
    EXPECT(isinf(gw_hertz_coefficient(R, rigid, INFINITY, rigid)));
    /* an auxetic material (nu < 0) is one */
    const gw_material aux = {"aux", 1e9, -0.5, 1};
    EXPECT(fabs(gw_hertz_coefficient(R, &aux, INFINITY, rigid) / (4.0 / 3.0 * 1e9 / 0.75 * sqrt(R)) - 1) < 1e-15);
    return 0;
}

static int layer_law_invalid_bead(void)
{
    const struct {
        gw_material m;
        const char *field;
    } bad[] = {{{"neg", -2e11, 0.3, 1}, "Young modulus"},
               {{"zero", 0, 0.3, 1}, "Young modulus"},
               {{"nan", NAN, 0.3, 1}, "Young modulus"},
               {{"nu15", 2e11, 1.5, 1}, "Poisson ratio"},
               {{"nunan", 2e11, NAN, 1}, "Poisson ratio"}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        gw_layer_law *l = (gw_layer_law *)&bad[i]; /* anything: the call writes NULL */
        gw_err e = {{0}};
        if (!refused(gw_layer_law_create(4e-3, &bad[i].m, 1e-3, 3e9, 0.38, &l, &e), &e, "sphere material"))
            return 1;
        EXPECT(l == NULL && strstr(e.msg, bad[i].field) && strstr(e.msg, bad[i].m.name));
    }
    /* control: a steel sphere's law, its thick-layer limit the Hertz
     * coefficient of the sphere on a half-space of the layer's material */
    const gw_material *steel = gw_material_find("steel"), pvc = {"pvc-like", 3e9, 0.38, 1400};
    gw_layer_law *l = NULL;
    gw_err e = {{0}};
    EXPECT(gw_layer_law_create(4e-3, steel, 1e-3, 3e9, 0.38, &l, &e) == GW_OK && l);
    EXPECT(gw_layer_law_hertz_k(l) == gw_hertz_coefficient(4e-3, steel, INFINITY, &pvc));
    EXPECT(gw_layer_law_force(l, 1e-5, NULL) > 0);
    gw_layer_law_free(l);
    return 0;
}

static int sheet_apply_invalid_material(void)
{
    const gw_material *steel = gw_material_find("steel");
    const gw_sheet *pvc = gw_sheet_find("pvc"), *none = gw_sheet_find("none");
    EXPECT(pvc && none);
    const gw_material neg = {"neg", -2e11, 0.3, 7850}, nanw = {"nanwall", NAN, 0.3, 7850};
    gw_chain_params p = gw_chain_params_default();
    gw_layer_law *law = NULL;
    gw_err e = {{0}};
    if (!refused(gw_sheet_apply(pvc, GW_SHEET_LAYER, -1, -1, &neg, steel, &p, &law, &e), &e, "bead material 'neg'"))
        return 1;
    EXPECT(law == NULL);
    if (!refused(gw_sheet_apply(none, GW_SHEET_HERTZ, -1, -1, steel, &nanw, &p, &law, &e), &e,
                 "wall material 'nanwall': Young modulus nan"))
        return 1;
    /* a sheet filled by hand: its own material under a law that uses it */
    gw_sheet own = *pvc;
    own.young = 0;
    if (!refused(gw_sheet_apply(&own, GW_SHEET_HERTZ, -1, -1, steel, steel, &p, &law, &e), &e, "sheet material"))
        return 1;
    /* controls: the fitted law takes no material; steel on PVC's layer law runs */
    EXPECT(gw_sheet_apply(&own, GW_SHEET_FITTED, -1, -1, steel, steel, &p, &law, &e) == GW_OK && law == NULL);
    EXPECT(p.kwall == gw_sheet_kwall(&own, p.mass));
    EXPECT(gw_sheet_apply(pvc, GW_SHEET_LAYER, -1, -1, steel, steel, &p, &law, &e) == GW_OK && law);
    EXPECT(isfinite(p.kwall) && p.kwall > 0 && p.wall.layer == law);
    gw_chain *c = NULL;
    EXPECT(gw_chain_create(&p, &c, &e) == GW_OK);
    gw_chain_free(c);
    gw_layer_law_free(law);
    return 0;
}

/* ---- the wall's Maxwell arms ---- */

/* gw_chain_create's status and message for a viscoelastic wall of loss tan
 * delta and relaxation times [a, b] (N = 2). */
static int arms(double loss, double a, double b, gw_err *e)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 2;
    p.wall.loss = loss;
    p.wall.tau_min = a;
    p.wall.tau_max = b;
    gw_chain *c = NULL;
    memset(e, 0, sizeof *e);
    int rc = gw_chain_create(&p, &c, e);
    gw_chain_free(c);
    return rc;
}

static int wall_arms_tiny_times(void)
{
    gw_err e1, e2;
    /* arms below GW_CHAIN_WALL_TAU_MIN (a picosecond, the thirty-third
     * session) are refused by name before the band centre is formed */
    EXPECT(arms(0.3, 1e-200, 1e-195, &e1) == GW_EINVAL && !strstr(e1.msg, "nan") &&
           strstr(e1.msg, "wall tau_min (s): a Maxwell arm of 1e-200 s"));
    EXPECT(arms(10, 1e-300, 1e-300, &e1) == GW_EINVAL && !strstr(e1.msg, "nan") && strstr(e1.msg, "[1e-12, 1e3]"));
    /* within the range the arms are scale-free: 1e-12 to 1e-7 s is 1e-5 to 1 s, 6 arms */
    EXPECT(arms(0.3, 1e-12, 1e-7, &e1) == GW_EINVAL && arms(0.3, 1e-5, 1, &e2) == GW_EINVAL);
    EXPECT(!strstr(e1.msg, "nan") && strstr(e1.msg, "6 Maxwell arm(s) give (< 0.211)"));
    EXPECT(strcmp(e1.msg, e2.msg) == 0);
    EXPECT(arms(10, 1e-12, 1e-12, &e1) == GW_EINVAL && arms(10, 1e-3, 1e-3, &e2) == GW_EINVAL);
    EXPECT(!strstr(e1.msg, "nan") && strcmp(e1.msg, e2.msg) == 0 && strstr(e1.msg, "(< 0.98)"));
    /* a loss the arms give is taken at any scale of the range, as at 1e-5 to 1 s */
    EXPECT(arms(0.2, 1e-12, 1e-7, &e1) == GW_OK && arms(0.2, 1e-5, 1, &e2) == GW_OK);
    return 0;
}

/* ---- the solver's times ---- */

static int osc(double t, const double *y, double *yd, void *p)
{
    (void)t;
    (void)p;
    yd[0] = y[1];
    yd[1] = -y[0];
    return 0;
}

/* The oscillator y'' = -y as a system of two states, banded. */
static gw_system osc_system(void)
{
    gw_system sys;
    memset(&sys, 0, sizeof sys);
    sys.dim = 2;
    sys.rhs = osc;
    sys.mu = sys.ml = 1;
    return sys;
}

static int solver_nonfinite_times(void)
{
    static const char *const names[] = {"cvode", "arkode", "rk4"};
    gw_system sys = osc_system();
    const double y0[2] = {1, 0}, bad[] = {NAN, INFINITY, -INFINITY};
    for (int b = 0; b < 3; b++) {
        const gw_solver_type *type = gw_solver_type_find(names[b]);
        gw_solver_params sp = gw_solver_params_default();
        sp.dt = 1e-3;
        for (int i = 0; i < 3; i++) {
            gw_solver *s = (gw_solver *)&sys;
            gw_err e = {{0}};
            if (!refused(gw_solver_create(type, &sys, &sp, bad[i], y0, &s, &e), &e, "t0 = "))
                return 1;
            EXPECT(s == NULL);
        }
        gw_solver *s = NULL;
        gw_err e = {{0}};
        EXPECT(gw_solver_create(type, &sys, &sp, 0, y0, &s, &e) == GW_OK);
        double t = 0, y[2] = {1, 0};
        for (int i = 0; i < 3; i++) {
            EXPECT(gw_solver_advance(s, bad[i], &t, y, NULL) == GW_EINVAL);
            EXPECT(t == 0 && y[0] == 1 && y[1] == 0 && strstr(gw_solver_error(s), "tout = "));
        }
        EXPECT(gw_solver_reset(s, NAN, y) == GW_EINVAL && strstr(gw_solver_error(s), "not a finite time"));
        /* control: the oscillator reaches t = 1 at cos(1), -sin(1) (rk4 at
         * dt = 1e-3 within 1e-9, the adaptive ones at their 1e-10 tolerances
         * within 1e-6) */
        const double tol = b == 2 ? 1e-9 : 1e-6;
        EXPECT(gw_solver_advance(s, 1.0, &t, y, NULL) == GW_OK && t == 1.0);
        EXPECT(fabs(y[0] - cos(1.0)) < tol && fabs(y[1] + sin(1.0)) < tol);
        EXPECT(gw_solver_reset(s, 1.0, y) == GW_OK);
        gw_solver_free(s);
    }
    return 0;
}

/* ---- the lead's, from what the pass left: solver scales, fixed steps
 * backwards, the binary loss at huge ratios, the undecided warning's counts,
 * a parameter copy onto itself ---- */

static int solver_scale_invalid(void)
{
    static const char *const names[] = {"cvode", "arkode", "rk4"};
    gw_system sys = osc_system();
    const double y0[2] = {1, 0};
    const double bad[][2] = {{0, 1}, {1, NAN}, {-1, 1}, {1, INFINITY}};
    for (int b = 0; b < 3; b++) {
        const gw_solver_type *type = gw_solver_type_find(names[b]);
        gw_solver_params sp = gw_solver_params_default();
        sp.dt = 1e-3;
        for (int i = 0; i < 4; i++) {
            gw_solver *s = (gw_solver *)&sys;
            gw_err e = {{0}};
            sys.scale = bad[i];
            if (!refused(gw_solver_create(type, &sys, &sp, 0, y0, &s, &e), &e, "scale["))
                return 1;
            EXPECT(s == NULL);
        }
        /* control: unit scales give the oscillator at t = 1 */
        static const double one[2] = {1, 1};
        sys.scale = one;
        gw_solver *s = NULL;
        gw_err e = {{0}};
        EXPECT(gw_solver_create(type, &sys, &sp, 0, y0, &s, &e) == GW_OK);
        double t = 0, y[2] = {1, 0};
        EXPECT(gw_solver_advance(s, 1.0, &t, y, NULL) == GW_OK && fabs(y[0] - cos(1.0)) < 1e-6);
        gw_solver_free(s);
        sys.scale = NULL;
    }
    return 0;
}

static int fixed_step_backwards(void)
{
    gw_system sys = osc_system();
    const double y0[2] = {1, 0};
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 1e-3;
    gw_solver *s = NULL;
    gw_err e = {{0}};
    EXPECT(gw_solver_create(gw_solver_type_find("rk4"), &sys, &sp, 0, y0, &s, &e) == GW_OK);
    double t = 0, y[2] = {1, 0};
    EXPECT(gw_solver_advance(s, 1.0, &t, y, NULL) == GW_OK && t == 1.0);
    const double y1[2] = {y[0], y[1]};
    /* backwards: refused where it stood (GW_OK with *t = 1 before) */
    EXPECT(gw_solver_advance(s, 0.5, &t, y, NULL) == GW_EINVAL);
    EXPECT(t == 1.0 && y[0] == y1[0] && y[1] == y1[1] && strstr(gw_solver_error(s), "forward only"));
    /* control: the same time again is no step, and on to 2 s still cos(2) */
    EXPECT(gw_solver_advance(s, 1.0, &t, y, NULL) == GW_OK && t == 1.0);
    EXPECT(gw_solver_advance(s, 2.0, &t, y, NULL) == GW_OK && fabs(y[0] - cos(2.0)) < 1e-9);
    gw_solver_free(s);
    return 0;
}

static int binary_loss_huge(void)
{
    /* 4 m / (1 + m)^2 with m = r^2 (discs) or r^3 (spheres): past the
     * overflow of (1 + m)^2 it was NaN, where the loss tends to 0 as 4 / m */
    const double r[] = {1e120, 1e154, 1.4e154, 1e200, 1e300};
    for (size_t i = 0; i < sizeof r / sizeof r[0]; i++) {
        const double l = gw_stats_binary_loss(r[i], 0), m = r[i] * r[i];
        EXPECT(isfinite(l) && l >= 0 && (isinf(m) ? l == 0 : fabs(l - 4 / m) <= 1e-12 * (4 / m)));
        EXPECT(isfinite(gw_stats_binary_loss(r[i], 1)) && gw_stats_binary_loss(r[i], 1) >= 0);
    }
    EXPECT(gw_stats_binary_loss(INFINITY, 0) == 0 && gw_stats_binary_loss(INFINITY, 1) == 0);
    EXPECT(isnan(gw_stats_binary_loss(NAN, 0)) && isnan(gw_stats_binary_loss(-2, 1)));
    /* control: r = 2 (discs, m = 4): 16 / 25; either side of m = 1e100 the
     * two forms agree to 1e-15 */
    EXPECT(fabs(gw_stats_binary_loss(2, 0) - 0.64) < 1e-15 && gw_stats_binary_loss(0.5, 0) == 1.0);
    const double lo = gw_stats_binary_loss(0.99e50, 0), hi = gw_stats_binary_loss(1.01e50, 0);
    EXPECT(fabs(lo * 0.99e50 * 0.99e50 / 4 - 1) < 1e-15 && fabs(hi * 1.01e50 * 1.01e50 / 4 - 1) < 1e-15);
    return 0;
}

static int undecided_counts(void)
{
    int nm;
    const gw_sweep_model *const *ms = gw_sweep_models(&nm);
    EXPECT(nm > 0);
    char *list = NULL;
    /* 5 of 3 cases, a first case before 0 or past the last: refused, nothing written */
    EXPECT(gw_sweep_undecided_warning(ms[0], 5, 3, 0, &list) == GW_EINVAL && list == NULL);
    EXPECT(gw_sweep_undecided_warning(ms[0], 1, 3, -1, &list) == GW_EINVAL && list == NULL);
    EXPECT(gw_sweep_undecided_warning(ms[0], 1, 3, 3, &list) == GW_EINVAL && list == NULL);
    /* control: 2 of 3, the first case 1 */
    EXPECT(gw_sweep_undecided_warning(ms[0], 2, 3, 1, &list) == GW_OK && list && strstr(list, "2 of 3 cases") &&
           strstr(list, "case 1"));
    free(list);
    return 0;
}

static int param_copy_onto_itself(void)
{
    const gw_param *t = gw_layer_make_setup_params();
    gw_layer_make_setup a, b;
    gw_layer_make_setup_init(&a);
    gw_err e = {{0}};
    EXPECT(gw_param_set(t, &a, "out", "pile.h5", &e) == GW_OK && a.out);
    /* onto itself: its own text was detached (lost, leaked) with GW_OK */
    if (!refused(gw_param_copy(t, sizeof a, &a, &a, &e), &e, "overlap"))
        return 1;
    EXPECT(a.out && strcmp(a.out, "pile.h5") == 0);
    /* a size that ends before the table's rows: refused naming the row */
    gw_layer_make_setup_init(&b);
    if (!refused(gw_param_copy(t, 8, &b, &a, &e), &e, "size 8"))
        return 1;
    /* control: a copy of its own */
    EXPECT(gw_param_copy(t, sizeof a, &b, &a, &e) == GW_OK && b.out && b.out != a.out && strcmp(b.out, "pile.h5") == 0);
    gw_layer_make_setup_clear(&a);
    gw_layer_make_setup_clear(&b);
    return 0;
}

static int thornton_invalid(void)
{
    /* a yield pressure, E* or radius not finite and > 0: every force NaN (a
     * negative p_y gave a negative force at GW_OK's void) */
    const double bad[][3] = {{1e11, 1e-3, -1e8}, {1e11, 1e-3, 0}, {1e11, 1e-3, NAN},
                             {0, 1e-3, 1e8},     {1e11, -1e-3, 1e8}, {INFINITY, 1e-3, 1e8}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        gw_thornton th;
        gw_thornton_init(&th, bad[i][0], bad[i][1], bad[i][2]);
        EXPECT(isnan(gw_thornton_force(&th, 1e-6, 1e-6, NULL, NULL, NULL)));
    }
    /* control: below its yield overlap the law is Hertz's, 4/3 E* sqrt(R) d^1.5 */
    gw_thornton th;
    gw_thornton_init(&th, 1e11, 1e-3, 1e9);
    const double d = 1e-3 * th.d_y;
    EXPECT(fabs(gw_thornton_force(&th, d, d, NULL, NULL, NULL) / (4.0 / 3.0 * 1e11 * sqrt(1e-3) * d * sqrt(d)) - 1) <
           1e-14);
    return 0;
}

int main(void)
{
    static const child_row cases[] = {
        {"gw_sweep_format_row: a case the config has not, ncol < 0", sweep_row_case_range},
        {"gw_json_bools: NULL values", json_bools_null},
        {"gw_path_join: NULL buf, dir, name", path_join_null},
        {"gw_afile_open/openat: a file opened again while open", afile_open_again},
        {"gw_afile_open: an empty path", afile_empty_path},
        {"gw_hertz_coefficient: materials and radii no contact has", hertz_invalid_material},
        {"gw_layer_law_create: a sphere material filled by hand", layer_law_invalid_bead},
        {"gw_sheet_apply: bead, wall and sheet materials filled by hand", sheet_apply_invalid_material},
        {"gw_chain_create: Maxwell arms at 1e-200 s", wall_arms_tiny_times},
        {"gw_solver_create/advance/reset: NaN and infinite times", solver_nonfinite_times},
        {"gw_solver_create: scales not finite and > 0", solver_scale_invalid},
        {"gw_solver_advance: rk4 asked to go back", fixed_step_backwards},
        {"gw_stats_binary_loss: ratios past the overflow", binary_loss_huge},
        {"gw_sweep_undecided_warning: counts that cannot be", undecided_counts},
        {"gw_param_copy: onto itself, a size short of the table", param_copy_onto_itself},
        {"gw_thornton_init: a law from values no wall has", thornton_invalid},
    };
    return child_cases_run(cases, sizeof cases / sizeof cases[0]);
}
