/*
 * test_library_left52.c: what the forty-fifth session's helpers left in the
 * library (session 45, issue 18), each case in its own child process
 * (test_child.h):
 *   - the side walls' rule of a layer sample with no settling record was
 *     judged by gw_layer_impact_check (and gw_layer_impact_dem_dt, which
 *     takes it) under the default material (G = 40e9 Pa) while
 *     gw_layer_impact judged it under its own lp: a row of 5 discs resting on
 *     its floor under G = 40e9 and run with G = 4e9 and side_walls left (its
 *     floor carrying 0.1 of its weight there) was refused by the run and got
 *     a step from dem_dt; the row resting under 4e9 (its floor carrying 10
 *     of its weight under 40e9) ran and got NaN. gw_layer_impact_check_with
 *     takes the run's lp and refuses with the run's message, byte for byte;
 *     dem_dt takes it.
 *   - gw_input_open, gw_input_check, gw_input_read, gw_fnv1a64_file and
 *     gw_fnv1a64_file_max named a NULL path "input: empty file name": each
 *     names itself and path NULL (the library's NULL rule); "" keeps its
 *     words (control).
 *   - a drop result filled by hand with chatter kind MOVED and a NaN spread
 *     was warned "changed the impacts' F_max by up to nan" (a negative one
 *     "up to -0.5"): the spread is said unknown.
 *   - gw_layer_impact_plan_make(NULL, &p) left p as it was (the "writes
 *     nothing" exception), and a plan declared without a value, refused and
 *     freed, freed what its bytes pointed at: p is emptied on every refusal.
 *     gw_layer_make_plan wrote its outputs through NULL (SIGSEGV): refused
 *     naming them.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "granwave.h"
#include "test_child.h"

/* new in session 45: weak, so that the test links against a library without
 * it (and fails there) */
int gw_layer_impact_check_with(const gw_layer_sample *s, const gw_layer_params *lp,
                               const gw_layer_impact_params *ip, gw_err *err) __attribute__((weak));

/* ------------------------------------------------- the side walls' material ---- */

#define N 5
#define R 0.1

static double xs[N], ys[N], rs[N];

/* A row of 5 discs 0.05 m from each wall, resting on its floor under a
 * material of shear modulus g_rest (Pa): each floor overlap carries its
 * disc's weight there. No record of its settling. */
static gw_layer_sample row(double g_rest)
{
    gw_layer_params lp = gw_layer_params_default();
    lp.shear_modulus = g_rest;
    const double kn = gw_layer_kn(&lp, R), mg = gw_layer_mass(&lp, R) * lp.gravity;
    const double uf = pow(mg / kn, 2.0 / 3.0);
    for (int i = 0; i < N; i++) {
        rs[i] = R;
        ys[i] = R - uf;
        xs[i] = 0.05 + R + i * 2 * R;
    }
    gw_layer_sample s;
    memset(&s, 0, sizeof s);
    s.n = N, s.x = xs, s.y = ys, s.r = rs, s.rm = R, s.volume_ratio = 1, s.porosity = NAN;
    s.width = xs[N - 1] + R + 0.05;
    return s;
}

static gw_layer_impact_params left_walls(void)
{
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.side_walls = GW_LAYER_SIDES_LEFT;
    ip.t_max = 0.02;
    return ip;
}

/* gw_layer_impact of s under lp with ip: its status and message */
static int run(const gw_layer_sample *s, const gw_layer_params *lp, const gw_layer_impact_params *ip, char *msg,
               size_t n)
{
    gw_solver_params sp = gw_solver_params_default();
    gw_layer_impact_result res;
    gw_err e = {{0}};
    const int rc = gw_layer_impact(s, lp, ip, gw_solver_verlet, &sp, &res, &e);
    gw_layer_impact_result_free(&res);
    snprintf(msg, n, "%s", rc == GW_OK ? "" : e.msg);
    return rc;
}

/* the row resting under 40e9, run with 4e9: the run refuses (its floor
 * carries 0.1 of the weight); the check with the run's lp refuses with the
 * run's message, and dem_dt under that lp is NaN (a step before) */
static int c_walls_soft_run(void)
{
    const gw_layer_sample s = row(40e9);
    const gw_layer_impact_params ip = left_walls();
    gw_layer_params lp = gw_layer_params_default();
    lp.shear_modulus = 4e9;
    char mr[1024], mc[1024];
    const int rr = run(&s, &lp, &ip, mr, sizeof mr);
    EXPECT(rr == GW_EINVAL && strstr(mr, "side-walls: left: the sample's pile does not rest on its floor alone") &&
           strstr(mr, "the floor carries 0.1 of its weight"));
    const double dt = gw_layer_impact_dem_dt(&s, &lp, &ip);
    if (!isnan(dt))
        printf("dem_dt under 4e9: %g s, a step for an impact the run refuses\n", dt);
    EXPECT(isnan(dt));
    EXPECT(gw_layer_impact_check_with != NULL);
    gw_err e = {{0}};
    const int rc = gw_layer_impact_check_with(&s, &lp, &ip, &e);
    snprintf(mc, sizeof mc, "%s", e.msg);
    EXPECT(rc == rr && strcmp(mc, mr) == 0);
    /* control: under the material it rests with, the run's rule passes it,
     * the check too, and dem_dt gives a step */
    const gw_layer_params lp0 = gw_layer_params_default();
    memset(&e, 0, sizeof e);
    EXPECT(gw_layer_impact_check_with(&s, &lp0, &ip, &e) == GW_OK && gw_layer_impact_check(&s, &ip, &e) == GW_OK);
    EXPECT(gw_layer_impact_dem_dt(&s, &lp0, &ip) > 0);
    return 0;
}

/* the row resting under 4e9, run with 4e9: the run passes the side walls'
 * rule (and runs); the check with the run's lp passes, and dem_dt gives the
 * step (NaN before: the default material's floor carried 10 of the weight) */
static int c_walls_soft_rest(void)
{
    const gw_layer_sample s = row(4e9);
    const gw_layer_impact_params ip = left_walls();
    gw_layer_params lp = gw_layer_params_default();
    lp.shear_modulus = 4e9;
    char mr[1024];
    const int rr = run(&s, &lp, &ip, mr, sizeof mr);
    EXPECT(rr == GW_OK);
    const double dt = gw_layer_impact_dem_dt(&s, &lp, &ip);
    if (!(dt > 0 && isfinite(dt)))
        printf("dem_dt under 4e9: %g, no step for an impact the run runs\n", dt);
    EXPECT(dt > 0 && isfinite(dt));
    EXPECT(gw_layer_impact_check_with != NULL);
    gw_err e = {{0}};
    EXPECT(gw_layer_impact_check_with(&s, &lp, &ip, &e) == GW_OK);
    /* control: the check without a material judges under the default one, as
     * it says (gw_layer_impact under the default lp refuses alike) */
    memset(&e, 0, sizeof e);
    const gw_layer_params lp0 = gw_layer_params_default();
    const int rc0 = gw_layer_impact_check(&s, &ip, &e);
    EXPECT(rc0 == GW_EINVAL && strstr(e.msg, "side-walls: left: "));
    EXPECT(run(&s, &lp0, &ip, mr, sizeof mr) == rc0 && strcmp(mr, e.msg) == 0);
    /* NULL lp named; a NaN gravity refused as the run's material is */
    memset(&e, 0, sizeof e);
    EXPECT(gw_layer_impact_check_with(&s, NULL, &ip, &e) == GW_EINVAL &&
           strcmp(e.msg, "gw_layer_impact_check_with: lp is NULL") == 0);
    lp.gravity = NAN;
    memset(&e, 0, sizeof e);
    EXPECT(gw_layer_impact_check_with(&s, &lp, &ip, &e) == GW_EINVAL && strstr(e.msg, "gravity"));
    return 0;
}

/* ------------------------------------------------------------ NULL paths ---- */

static int said(int rc, const gw_err *e, const char *msg)
{
    if (rc == GW_EINVAL && strcmp(e->msg, msg) == 0)
        return 1;
    printf("rc %d, '%s' (wanted '%s')\n", rc, e->msg, msg);
    return 0;
}

static int c_null_paths(void)
{
    gw_err e = {{0}};
    unsigned long long h = 7;
    EXPECT(said(gw_fnv1a64_file_max(NULL, "x", 100, 0, &h, &e), &e, "gw_fnv1a64_file_max: path is NULL") && h == 7);
    EXPECT(said(gw_fnv1a64_file(NULL, "x", &h, &e), &e, "gw_fnv1a64_file: path is NULL") && h == 7);
    EXPECT(said(gw_input_check(NULL, "x", &e), &e, "gw_input_check: path is NULL"));
    FILE *fp = stdin;
    EXPECT(said(gw_input_open(NULL, "x", &fp, &e), &e, "gw_input_open: path is NULL") && fp == NULL);
    char *text = (char *)&e;
    size_t len = 9;
    EXPECT(said(gw_input_read(NULL, "x", 100, &text, &len, &e), &e, "gw_input_read: path is NULL") && !text &&
           len == 0);
    /* control: an empty name keeps its words, naming the input */
    EXPECT(said(gw_input_check("", "x", &e), &e, "x: empty file name"));
    EXPECT(said(gw_fnv1a64_file_max("", "x", 100, 0, &h, &e), &e, "x: empty file name"));
    return 0;
}

/* ------------------------------------------------- a drop's unknown spread ---- */

/* the chatter's line of a drop result of kind MOVED and spread v */
static int chatter_line(double v, char *out, size_t n)
{
    gw_chain_drop_result dr;
    memset(&dr, 0, sizeof dr);
    dr.n = 3, dr.n_impacts = 5, dr.n_episodes = 40, dr.chatter_kind = GW_CHAIN_CHATTER_MOVED;
    dr.chatter_spread = v;
    char *list = NULL;
    const int rc = gw_chain_drop_result_warnings(&dr, &list);
    const char *l = list ? strstr(list, "bead 1 chattered") : NULL;
    const char *end = l ? strchr(l, '\n') : NULL;
    snprintf(out, n, "%.*s", l ? (int)(end ? end - l : (long)strlen(l)) : 0, l ? l : "");
    free(list);
    gw_chain_drop_result_free(&dr);
    return rc;
}

static int c_drop_spread_unknown(void)
{
    char l[2048];
    EXPECT(chatter_line(NAN, l, sizeof l) == GW_OK && l[0] && !strstr(l, "nan") && strstr(l, "unknown") &&
           strstr(l, "not a number"));
    EXPECT(chatter_line(-0.5, l, sizeof l) == GW_OK && l[0] && !strstr(l, "-0.5") && strstr(l, "unknown") &&
           strstr(l, "negative"));
    /* control: a spread measured is said */
    EXPECT(chatter_line(1e-3, l, sizeof l) == GW_OK && strstr(l, "by up to 0.001 of their value") &&
           !strstr(l, "unknown"));
    return 0;
}

/* ------------------------------------------------------ plans refused ---- */

static int all_zero(const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++)
        if (b[i])
            return 0;
    return 1;
}

static int c_plan_emptied(void)
{
    gw_layer_impact_plan p;
    memset(&p, 0xA5, sizeof p); /* a plan declared without a value */
    gw_err e = {{0}};
    EXPECT(said(gw_layer_impact_plan_make(NULL, &p, &e), &e, "gw_layer_impact_plan_make: s is NULL"));
    EXPECT(all_zero(&p, sizeof p));
    gw_layer_impact_plan_free(&p); /* freed what 0xA5... pointed at before */
    /* a setup refused (no sample) empties it too (control: it did) */
    gw_layer_impact_setup s;
    EXPECT(gw_layer_impact_setup_init(&s) == GW_OK);
    memset(&p, 0xA5, sizeof p);
    EXPECT(gw_layer_impact_plan_make(&s, &p, &e) == GW_EINVAL && all_zero(&p, sizeof p));
    gw_layer_impact_plan_free(&p);
    gw_layer_impact_setup_clear(&s);
    /* gw_layer_make_plan's outputs */
    gw_layer_make_setup m;
    EXPECT(gw_layer_make_setup_init(&m) == GW_OK);
    gw_layer_params lp;
    gw_layer_make_params mp;
    EXPECT(said(gw_layer_make_plan(&m, NULL, &mp, &e), &e, "gw_layer_make_plan: lp is NULL"));
    EXPECT(said(gw_layer_make_plan(&m, &lp, NULL, &e), &e, "gw_layer_make_plan: mp is NULL"));
    EXPECT(said(gw_layer_make_plan(NULL, &lp, &mp, &e), &e, "gw_layer_make_plan: s is NULL"));
    EXPECT(gw_layer_make_plan(&m, &lp, &mp, &e) == GW_OK); /* control */
    gw_layer_make_setup_clear(&m);
    return 0;
}

static const child_row rows[] = {
    {"side walls: a row at rest under 40e9 run with 4e9 is refused by the check with the run's lp, with the run's "
     "message; dem_dt NaN (a step before)",
     c_walls_soft_run},
    {"side walls: a row at rest under 4e9 run with 4e9 passes the check with the run's lp; dem_dt a step (NaN "
     "before)",
     c_walls_soft_rest},
    {"NULL paths named as NULL ('input: empty file name')", c_null_paths},
    {"a drop's MOVED chatter of a NaN or negative spread said unknown ('up to nan')", c_drop_spread_unknown},
    {"gw_layer_impact_plan_make empties its plan on every refusal; gw_layer_make_plan's NULL outputs refused",
     c_plan_emptied},
};

int main(void)
{
    return child_cases_run(rows, sizeof rows / sizeof rows[0]);
}
