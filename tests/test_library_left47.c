/*
 * test_library_left47.c: library calls the forty-seventh pass left (docs/library.md
 * "The contract of every call"), each returning GW_OK or a value for what it
 * should refuse; each case in its own child process (test_child.h):
 *   - gw_stats_diagram_make took a share of 7 or -1 and an x (R_b/R_m) of 0
 *     or -1 and drew a boundary of them; each is refused naming the cell and
 *     the field. Controls: a 2 x 2 diagram whose crossing is the linear
 *     interpolation of its shares, and a NaN share (no cell) skipped.
 *   - gw_solver_tolerances_unused_check(rk4, table, NULL) was GW_OK (no
 *     object read: the tolerances "not given"); a NULL type, table or object
 *     is refused naming it, whatever the backend. Controls: rk4 with rtol
 *     given refused, cvode with it and rk4 without it GW_OK.
 *   - gw_chain_falcon_analyse was GW_OK for n_lo > n_hi (a fit of no column)
 *     and for sizes below 1 (N = 0 and -3 fitted), and read past res for
 *     n_hi = INT_MAX (its n++ overflowed: SIGSEGV); each is GW_EINVAL, a
 *     untouched. Control: tau_N = tau_1 + (N - 1) T_q fitted to T_q.
 *   - gw_chain_disp_dt_sample gave the automatic interval for a dt_sample of
 *     NaN, -1 or inf (which gw_chain_disp_params_validate refuses); NaN now.
 *     Controls: 0 is the automatic pi / (1.25 omega_c), 2e-6 itself.
 *   - gw_sweep_memory_check took processes -1 (or 7) as true; refused naming
 *     processes. Control: 0 and 1 pass on a small chain grid.
 *   - gw_case_config_hash(model, -1, ...) hashed the model alone; 0 (no
 *     hash). Control: n = 0 is the hash of "model M\n" (FNV-1a 64).
 *   - gw_param_set took a hexadecimal real ("0x1p-2" for vimp, in a list of
 *     falcon's vimp) where an integer row refused "0x3"; numbers in text are
 *     decimal alone, refused naming the row. Controls: "0.25" and " 2.5e-1 ".
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "granwave.h"
#include "test_child.h"

/* ------------------------------------------------------------ diagram ---- */

/* a 2 x 2 diagram (x 1, 2; h 2, 4) with cell c's share or x replaced */
static int diagram(int c, double share, double xv, gw_stats_diagram *d, gw_err *e)
{
    double x[4] = {1, 1, 2, 2}, h[4] = {2, 4, 2, 4}, s[4] = {1, 0.5, 1, 1};
    if (c >= 0) {
        s[c] = share;
        x[c] = xv;
    }
    return gw_stats_diagram_make(4, x, h, s, NULL, 0.75, d, e);
}

static int diagram_refused(int c, double share, double xv, const char *what)
{
    gw_stats_diagram d;
    gw_err e = {0};
    EXPECT(refused(diagram(c, share, xv, &d, &e), &e, what));
    EXPECT(d.xs == NULL && d.share == NULL && d.pts == NULL);
    return 0;
}

static int c_diagram_share_7(void)
{
    return diagram_refused(1, 7, 1, "share[1] = 7 is not in [0, 1]");
}

static int c_diagram_share_neg(void)
{
    return diagram_refused(2, -1, 2, "share[2] = -1 is not in [0, 1]");
}

static int c_diagram_share_inf(void)
{
    return diagram_refused(0, INFINITY, 1, "share[0] = inf");
}

static int c_diagram_x_zero(void)
{
    return diagram_refused(0, 1, 0, "x[0] (R_b/R_m) = 0 is not > 0");
}

static int c_diagram_x_neg(void)
{
    return diagram_refused(3, 1, -1, "x[3] (R_b/R_m) = -1 is not > 0");
}

static int c_diagram_control(void)
{
    gw_stats_diagram d;
    gw_err e = {0};
    EXPECT(diagram(-1, 0, 0, &d, &e) == GW_OK);
    /* x = 1 crosses S = 0.75 between (2, 1) and (4, 0.5): H* = 2 + 0.25/0.5 * 2 */
    const int ok = d.nx == 2 && d.nh == 2 && d.pts[0].kind == GW_STATS_BND_CROSS &&
                   fabs(d.pts[0].h - 3) <= 1e-14 && d.pts[1].kind == GW_STATS_BND_ABOVE;
    gw_stats_diagram_free(&d);
    EXPECT(ok);
    /* a NaN share is no cell: skipped, the column left with one height */
    EXPECT(diagram(3, NAN, 2, &d, &e) == GW_OK && d.nx == 2 && isnan(d.share[3]));
    gw_stats_diagram_free(&d);
    return 0;
}

/* --------------------------------------------------------- tolerances ---- */

static int c_tolerances_null(void)
{
    gw_chain_setup s;
    EXPECT(gw_chain_setup_init(&s) == GW_OK);
    const gw_param *t = gw_chain_setup_params();
    gw_err e = {0};
    int ok = refused(gw_solver_tolerances_unused_check(gw_solver_rk4, t, NULL, &e), &e, "obj is NULL") &&
             refused(gw_solver_tolerances_unused_check(gw_solver_cvode, t, NULL, &e), &e, "obj is NULL") &&
             refused(gw_solver_tolerances_unused_check(gw_solver_rk4, NULL, &s, &e), &e, "t is NULL") &&
             refused(gw_solver_tolerances_unused_check(NULL, t, &s, &e), &e, "type is NULL");
    gw_chain_setup_clear(&s);
    EXPECT(ok);
    return 0;
}

static int c_tolerances_control(void)
{
    gw_chain_setup s;
    EXPECT(gw_chain_setup_init(&s) == GW_OK);
    const gw_param *t = gw_chain_setup_params();
    gw_err e = {0};
    int ok = gw_solver_tolerances_unused_check(gw_solver_rk4, t, &s, &e) == GW_OK &&
             gw_param_set(t, &s, "rtol", "1e-8", &e) == GW_OK &&
             refused(gw_solver_tolerances_unused_check(gw_solver_rk4, t, &s, &e), &e, "rtol: has no effect") &&
             gw_solver_tolerances_unused_check(gw_solver_cvode, t, &s, &e) == GW_OK;
    gw_chain_setup_clear(&s);
    EXPECT(ok);
    return 0;
}

/* ------------------------------------------------------ falcon analyse ---- */

static int falcon_refused(int n_lo, int n_hi)
{
    gw_chain_params p = gw_chain_params_default();
    gw_chain_result res[8];
    memset(res, 0, sizeof res);
    gw_chain_falcon_fit a;
    memset(&a, 0x5a, sizeof a);
    const int rc = gw_chain_falcon_analyse(&p, 0.3, res, n_lo, n_hi, &a);
    if (rc != GW_EINVAL) {
        printf("n %d..%d: status %d (wanted GW_EINVAL)\n", n_lo, n_hi, rc);
        return 1;
    }
    const unsigned char *b = (const unsigned char *)&a;
    for (size_t i = 0; i < sizeof a; i++)
        EXPECT(b[i] == 0x5a);
    return 0;
}

static int c_falcon_reversed(void)
{
    return falcon_refused(5, 3);
}

static int c_falcon_zero(void)
{
    return falcon_refused(0, 3);
}

static int c_falcon_negative(void)
{
    return falcon_refused(-3, -1);
}

/* INT_MAX: the loop's n++ overflowed (and read far past res) */
static int c_falcon_int_max(void)
{
    return falcon_refused(1, 2147483647);
}

static int c_falcon_control(void)
{
    gw_chain_params p = gw_chain_params_default();
    gw_chain_result res[6];
    memset(res, 0, sizeof res);
    const double tau1 = 4e-5, tq = 2.5e-5;
    for (int n = 1; n <= 6; n++) {
        res[n - 1].tau_n = tau1 + (n - 1) * tq;
        res[n - 1].f_max = 10.0 * n;
        res[n - 1].tau_max = 1e-5;
    }
    gw_chain_falcon_fit a;
    EXPECT(gw_chain_falcon_analyse(&p, 0.3, res, 1, 6, &a) == GW_OK);
    EXPECT(a.n_decided == 6 && fabs(a.fit.c1 - tq) <= 1e-12 * tq && fabs(a.fit.c0 - tau1) <= 1e-12 * tau1);
    EXPECT(fabs(a.f_mean - 35) <= 1e-12 * 35 && a.f_min == 10 && a.f_max == 60);
    EXPECT(fabs(a.speed - 4 * p.radius / tq) <= 1e-9 * a.speed);
    return 0;
}

/* ---------------------------------------------------- dispersion step ---- */

static int c_disp_dt_bad(void)
{
    gw_chain_disp_params p = gw_chain_disp_params_default();
    const double bad[] = {NAN, -1, -1e-300, INFINITY, -INFINITY};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        p.dt_sample = bad[i];
        const double dt = gw_chain_disp_dt_sample(&p);
        if (!isnan(dt)) {
            printf("dt_sample %g: %g (wanted NaN)\n", bad[i], dt);
            return 1;
        }
    }
    return 0;
}

static int c_disp_dt_control(void)
{
    gw_chain_disp_params p = gw_chain_disp_params_default();
    gw_err e = {0};
    EXPECT(gw_chain_disp_params_validate(&p, &e) == GW_OK);
    /* automatic: pi / (1.25 omega_c), omega_c = 2 sqrt(kappa / m) the zone edge */
    const double kappa = gw_chain_disp_kappa(p.k, p.f0);
    const double want = acos(-1.0) / (1.25 * 2 * sqrt(kappa / p.mass));
    const double dt = gw_chain_disp_dt_sample(&p);
    EXPECT(fabs(dt - want) <= 1e-12 * want);
    p.dt_sample = 2e-6;
    EXPECT(gw_chain_disp_dt_sample(&p) == 2e-6);
    return 0;
}

/* ------------------------------------------------------- memory check ---- */

static int chain_grid(gw_sweep_config *cfg, const gw_sweep_model **m)
{
    int nm = 0;
    const gw_sweep_model *const *ms = gw_sweep_models(&nm);
    *m = NULL;
    for (int i = 0; i < nm; i++)
        if (strcmp(ms[i]->name, "chain") == 0)
            *m = ms[i];
    EXPECT(*m);
    const gw_sweep_model *got = NULL;
    gw_err e = {0};
    if (gw_sweep_config_read_string("[sweep]\nmodel = chain\n[grid]\nn = 3:5\n[params]\nt-max = 1e-3\n", "grid",
                                    m, 1, cfg, &got, &e) != GW_OK) {
        printf("config: %s\n", e.msg);
        return 1;
    }
    EXPECT(cfg->ncases == 3);
    return 0;
}

static int c_memory_processes(void)
{
    gw_sweep_config cfg = {0};
    const gw_sweep_model *m = NULL;
    if (chain_grid(&cfg, &m) != 0)
        return 1;
    const int bad[] = {-1, 2, 7};
    int ok = 1;
    for (int i = 0; i < 3 && ok; i++) {
        gw_err e = {0};
        ok = refused(gw_sweep_memory_check(&cfg, m, 2, bad[i], NULL, &e), &e, "processes: ");
    }
    gw_sweep_config_free(&cfg);
    EXPECT(ok);
    return 0;
}

static int c_memory_control(void)
{
    gw_sweep_config cfg = {0};
    const gw_sweep_model *m = NULL;
    if (chain_grid(&cfg, &m) != 0)
        return 1;
    gw_err e = {0};
    long most0 = -1, most1 = -1;
    const int ok = gw_sweep_memory_check(&cfg, m, 2, 0, &most0, &e) == GW_OK &&
                   gw_sweep_memory_check(&cfg, m, 2, 1, &most1, &e) == GW_OK && most0 == 3 && most1 == 3;
    if (!ok)
        printf("status: %s (most %ld, %ld)\n", e.msg, most0, most1);
    gw_sweep_config_free(&cfg);
    return ok ? 0 : 1;
}

/* --------------------------------------------------------- case hash ---- */

static int c_hash_negative(void)
{
    const char *names[1] = {"n"}, *vals[1] = {"3"};
    EXPECT(gw_case_config_hash("chain", -1, names, vals) == 0);
    EXPECT(gw_case_config_hash("chain", -1, NULL, NULL) == 0);
    EXPECT(gw_case_config_hash("chain", -2147483647 - 1, names, vals) == 0);
    return 0;
}

static int c_hash_control(void)
{
    const char *names[1] = {"n"}, *vals[1] = {"3"};
    const char *text = "model chain\n";
    const unsigned long long h0 = gw_fnv1a64(GW_FNV1A64_INIT, text, strlen(text));
    EXPECT(gw_case_config_hash("chain", 0, NULL, NULL) == h0);
    const char *text1 = "model chain\nn = 3\n";
    EXPECT(gw_case_config_hash("chain", 1, names, vals) == gw_fnv1a64(GW_FNV1A64_INIT, text1, strlen(text1)));
    return 0;
}

/* ---------------------------------------------------- numbers in text ---- */

static int c_param_hex(void)
{
    gw_chain_setup s;
    EXPECT(gw_chain_setup_init(&s) == GW_OK);
    const gw_param *t = gw_chain_setup_params();
    const double before = s.vimp;
    gw_err e = {0};
    int ok = refused(gw_param_set(t, &s, "vimp", "0x1p-2", &e), &e, "vimp: '0x1p-2' is not a decimal number") &&
             refused(gw_param_set(t, &s, "vimp", " 0X.8P-1", &e), &e, "vimp:") &&
             refused(gw_param_set(t, &s, "n", "0x3", &e), &e, "n: '0x3'") && s.vimp == before;
    gw_chain_setup_clear(&s);
    EXPECT(ok);
    gw_chain_falcon_setup f;
    EXPECT(gw_chain_falcon_setup_init(&f) == GW_OK);
    ok = refused(gw_param_set(gw_chain_falcon_setup_params(), &f, "vimp", "0.3,0x1p-2", &e), &e, "vimp:");
    gw_chain_falcon_setup_clear(&f);
    EXPECT(ok);
    return 0;
}

static int c_param_decimal(void) /* control */
{
    gw_chain_setup s;
    EXPECT(gw_chain_setup_init(&s) == GW_OK);
    const gw_param *t = gw_chain_setup_params();
    gw_err e = {0};
    int ok = gw_param_set(t, &s, "vimp", "0.25", &e) == GW_OK && s.vimp == 0.25 &&
             gw_param_set(t, &s, "vimp", " 2.5e-1 ", &e) == GW_OK && s.vimp == 0.25 &&
             gw_param_set(t, &s, "n", "3", &e) == GW_OK && s.n == 3;
    gw_chain_setup_clear(&s);
    EXPECT(ok);
    return 0;
}

static const child_row rows[] = {
    {"diagram share 7", c_diagram_share_7},
    {"diagram share -1", c_diagram_share_neg},
    {"diagram share inf", c_diagram_share_inf},
    {"diagram x 0", c_diagram_x_zero},
    {"diagram x -1", c_diagram_x_neg},
    {"diagram 2 x 2 and a NaN share (control)", c_diagram_control},
    {"tolerances check with a NULL type, table or object", c_tolerances_null},
    {"tolerances check of rk4 and cvode (control)", c_tolerances_control},
    {"falcon analyse n_lo > n_hi", c_falcon_reversed},
    {"falcon analyse N = 0", c_falcon_zero},
    {"falcon analyse negative sizes", c_falcon_negative},
    {"falcon analyse n_hi = INT_MAX", c_falcon_int_max},
    {"falcon analyse of a linear tau_N (control)", c_falcon_control},
    {"dispersion dt_sample NaN, negative, infinite: NaN", c_disp_dt_bad},
    {"dispersion dt_sample 0 and 2e-6 (control)", c_disp_dt_control},
    {"memory check processes -1, 2, 7", c_memory_processes},
    {"memory check processes 0 and 1 (control)", c_memory_control},
    {"case hash of n < 0", c_hash_negative},
    {"case hash against FNV-1a 64 (control)", c_hash_control},
    {"param set of hexadecimal numbers refused", c_param_hex},
    {"param set of decimal numbers (control)", c_param_decimal},
};

int main(void)
{
    return child_cases_run(rows, sizeof rows / sizeof rows[0]);
}
