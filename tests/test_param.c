/*
 * test_param.c: parameter tables (gw_param.h) and the column collision as a
 * library call (gw_chain_study.h).
 *
 *  - The table's defaults are the model's: a default setup resolves to
 *    gw_chain_params_default() (steel beads, R = 4 mm, steel wall: m, k, K
 *    equal to the last bit, since both come from F.12, F.3 and 4/3 pi R^3 rho).
 *  - Setting by name checks type and range and names the parameter: every
 *    refusal is GW_EINVAL, its message starts with the row's name and never
 *    mentions a command line ("--"), and the struct is unchanged.
 *  - Text round trip: a double set from its %.17g text reads back bit-equal.
 *  - Result tables: every array's dimensions name an int row or a number.
 *  - Physical ranges: gamma <= 1e14, alpha <= 1e8, energy-tol <= 1 (gw_chain.h);
 *    Hunt-Crossley's calibrated alpha v is the same at 1e-3 and 10 m/s (its
 *    scale invariance, 1e-6 relative: the Brent tolerance), so a target that
 *    needs alpha above the bound is refused; a study over N within
 *    sum N^2 x columns <= 2e6 (exact ends 181 and 182); dispersion min-bins
 *    within T/2 - 2.
 *  - One collision through the table: N = 1, v = 0.3 m/s, F_max and tau_max
 *    against the closed forms F.13, F.21 to 1e-6 (the integration at
 *    rtol = 1e-12 is ~1e-9 accurate), and a glass bead's mass
 *    4/3 pi R^3 2500 kg/m^3 to 1e-15.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_test_util.h"
#include "gw_chain_study.h"
#include "gw_test.h"

static void refused(const char *name, const char *value, const char *what)
{
    gw_chain_setup s, before;
    gw_chain_setup_init(&s);
    memcpy(&before, &s, sizeof s);
    gw_err err = {{0}};
    int rc = gw_param_set(gw_chain_setup_params(), &s, name, value, &err);
    const gw_param *p = gw_param_find(gw_chain_setup_params(), name);
    size_t len = p ? strlen(p->name) : 0;
    char msg[640];
    snprintf(msg, sizeof msg, "%s = '%s' refused naming it, no '--' (%s): %s", name, value, what, err.msg);
    gw_test_true(rc == GW_EINVAL && (!p || (strncmp(err.msg, p->name, len) == 0 && err.msg[len] == ':')) &&
                     !strstr(err.msg, "--") && memcmp(&s, &before, sizeof s) == 0,
                 msg);
    gw_chain_setup_clear(&s);
}

/* a setup resolving to GW_EINVAL with a message naming row */
static void resolve_refused(const char *const *kv, const char *row)
{
    gw_chain_setup s;
    gw_err err = {{0}};
    int rc = test_setup_kv(&s, kv, &err);
    gw_chain_resolved r;
    memset(&r, 0, sizeof r); /* freed below whether or not the resolution ran */
    if (rc == GW_OK)
        rc = gw_chain_setup_resolve(&s, &r, &err);
    gw_chain_resolved_free(&r);
    gw_chain_setup_clear(&s);
    char msg[640];
    snprintf(msg, sizeof msg, "resolve refuses, naming %s: %s", row, err.msg);
    gw_test_true(rc == GW_EINVAL && strncmp(err.msg, row, strlen(row)) == 0 && !strstr(err.msg, "--"), msg);
}

static void check_result_table(const gw_param *t, const char *what)
{
    int ok = 1;
    for (int i = 0; t[i].name; i++) {
        if (gw_param_is_input(&t[i]))
            continue;
        const char *dims[2] = {t[i].rows, t[i].cols};
        for (int d = 0; d < 2; d++) {
            if (!dims[d] || strspn(dims[d], "0123456789") == strlen(dims[d]))
                continue;
            const gw_param *q = gw_param_find(t, dims[d]);
            if (!q || q->type != GW_PARAM_INT) {
                printf("  %s: %s dimension '%s' is not an int row\n", what, t[i].name, dims[d]);
                ok = 0;
            }
        }
        ok &= t[i].rows != NULL;
    }
    char msg[128];
    snprintf(msg, sizeof msg, "%s: every array's dimensions are int rows or numbers", what);
    gw_test_true(ok, msg);
}

/* Blanks around a number (the sixteenth session of stage 2): strtod and strtol
 * skip them before the number, and ' 5' was 5 while '5 ' was "not an integer"
 * (and '0.3 ,0.5' not a list where '0.3, 0.5' was). Both sides are now alike
 * (6 of these 11 checks fail on 68a27d7). */
static void blanks_around_numbers(void)
{
    gw_err err = {{0}};
    long n = 0;
    double x = 0;
    gw_test_true(gw_parse_long(" 5", "n", 1, 10, &n, &err) == GW_OK && n == 5, "' 5' is 5");
    gw_test_true(gw_parse_long("5 ", "n", 1, 10, &n, &err) == GW_OK && n == 5, "'5 ' is 5");
    gw_test_true(gw_parse_long("5\t", "n", 1, 10, &n, &err) == GW_OK && n == 5, "'5\\t' is 5");
    gw_test_true(gw_parse_long("5\n", "n", 1, 10, &n, &err) == GW_EINVAL, "'5\\n' is not an integer (a newline)");
    gw_test_true(gw_parse_double("\n0.3", "vimp", &x, &err) == GW_EINVAL, "'\\n0.3' is not a number (a newline)");
    gw_test_true(gw_parse_double("0.3 ", "vimp", &x, &err) == GW_OK && x == 0.3, "'0.3 ' is 0.3");
    gw_test_true(gw_parse_long("5 x", "n", 1, 10, &n, &err) == GW_EINVAL, "'5 x' is not an integer");
    gw_test_true(gw_parse_long(" ", "n", 1, 10, &n, &err) == GW_EINVAL, "' ' is not an integer");
    gw_test_true(gw_parse_double("0.3 0.5", "vimp", &x, &err) == GW_EINVAL, "'0.3 0.5' is not a number");
    double *v = NULL;
    int nv = 0;
    gw_test_true(gw_parse_double_list("0.3 , 0.5 ", "vimp", &v, &nv, &err) == GW_OK && nv == 2 && v[0] == 0.3 &&
                     v[1] == 0.5,
                 "'0.3 , 0.5 ' is the list 0.3, 0.5");
    free(v);
    long a = 0, b = 0;
    gw_test_true(gw_parse_int_range(" 2 : 7 ", "n", 1, 100, &a, &b, &err) == GW_OK && a == 2 && b == 7,
                 "' 2 : 7 ' is 2:7");
}

int main(void)
{
    blanks_around_numbers();
    const gw_param *t = gw_chain_setup_params();
    gw_chain_setup s;
    gw_test_true(gw_chain_setup_init(&s) == GW_OK, "defaults from the table are accepted by the table");
    gw_err err = {{0}};
    gw_test_true(gw_param_check(t, &s, &err) == GW_OK, "the default setup passes gw_param_check");
    gw_test_true(s.n == 1 && s.vimp == 0.3 && isnan(s.rtol) && s.solver < 0 && s.max_steps == 10000000 &&
                     s.sheet == -1 && isnan(s.k) && s.radii.n == 0,
                 "defaults: n 1, vimp 0.3, solver and rtol not given, max-steps 1e7, no sheet, k from the materials");

    gw_chain_resolved r;
    gw_test_true(gw_chain_setup_resolve(&s, &r, &err) == GW_OK, "the default setup resolves");
    gw_chain_params d = gw_chain_params_default();
    gw_test_true(r.params.mass == d.mass && r.params.k == d.k && r.params.kwall == d.kwall &&
                     r.params.radius == d.radius && r.params.v_imp == d.v_imp && r.params.n == d.n,
                 "default setup = gw_chain_params_default() (m, k, K, R, v, n bit-equal)");
    gw_test_true(r.run.solver == gw_solver_cvode && r.run.sp.rtol == 1e-12 && r.run.sp.atol == 1e-12,
                 "default run: cvode at rtol = atol = 1e-12 (as granwave chain)");
    gw_chain_resolved_free(&r);

    /* names with '_' for '-', choices by name, text round trip */
    gw_test_true(gw_param_set(t, &s, "dt_out", "1e-7", &err) == GW_OK && s.dt_out == 1e-7, "dt_out sets dt-out");
    gw_test_true(gw_param_set(t, &s, "material", "glass", &err) == GW_OK && s.material == 3,
                 "material glass (index 3 of the bead materials: rigid is a wall only)");
    double x = 0.1 + 0.2;
    char buf[64], back[64];
    snprintf(buf, sizeof buf, "%.17g", x);
    gw_param_set(t, &s, "vimp", buf, &err);
    gw_param_format(gw_param_find(t, "vimp"), &s, back, sizeof back);
    gw_test_true(s.vimp == x && strcmp(buf, back) == 0, "vimp: %.17g text round trip is bit-equal");
    gw_test_true(gw_param_set_double(t, &s, "n", 7, &err) == GW_OK && s.n == 7, "n = 7 by number");
    gw_param_set(t, &s, "vimp", "0.3", &err);

    /* refusals name the parameter */
    refused("vimp", "0", "open lower bound");
    refused("vimp", "2000", "above 1e3 m/s");
    refused("vimp", "nan", "not finite");
    refused("vimp", "fast", "not a number");
    refused("n", "2.5", "not an integer");
    refused("n", "0", "below 1");
    refused("rtol", "1e-3", "looser than GW_TOL_MAX");
    refused("material", "unobtainium", "unknown choice");
    refused("damping", "viscous", "unknown choice");
    refused("radii", "4e-3,0", "an item out of range");
    refused("trace", "maybe", "not a flag");
    refused("bogus", "1", "unknown parameter");
    gw_chain_setup t2;
    gw_chain_setup_init(&t2);
    gw_test_true(gw_param_set_double(t, &t2, "n", 2.5, &err) == GW_EINVAL && strncmp(err.msg, "n:", 2) == 0,
                 "n = 2.5 by number refused naming n");
    gw_chain_setup_clear(&t2);

    resolve_refused((const char *[]){"material", "rigid", NULL}, "material");
    resolve_refused((const char *[]){"gamma", "3", NULL}, "gamma");
    resolve_refused((const char *[]){"n", "3", "radii", "4e-3,3e-3", NULL}, "radii");
    resolve_refused((const char *[]){"sheet", "brass", "kwall", "1e9", NULL}, "sheet");
    resolve_refused((const char *[]){"solver", "rk4", "method", "bdf", NULL}, "method");
    resolve_refused((const char *[]){"restitution", "0.9", NULL}, "restitution");

    /* physical ranges of the damping constants and the energy limit (gw_chain.h) */
    char num[64];
    snprintf(num, sizeof num, "%.17g", GW_CHAIN_GAMMA_MAX);
    gw_test_true(gw_param_set(t, &s, "gamma", num, &err) == GW_OK, "gamma = GW_CHAIN_GAMMA_MAX (1e14) accepted");
    snprintf(num, sizeof num, "%.17g", GW_CHAIN_ALPHA_MAX);
    gw_test_true(gw_param_set(t, &s, "alpha", num, &err) == GW_OK, "alpha = GW_CHAIN_ALPHA_MAX (1e8) accepted");
    gw_param_set(t, &s, "gamma", "nan", &err); /* back to not given (the default) */
    gw_chain_setup_clear(&s);
    gw_chain_setup_init(&s);
    refused("gamma", "1.0000001e14", "above 1e14 N s/m^1.5 (overdamped)");
    refused("gamma", "1e300", "overflows the force");
    refused("alpha", "1.0000001e8", "above 1e8 s/m (overdamped)");
    refused("energy-tol", "1.5", "above the whole energy");
    refused("energy-tol", "1e300", "acts as off");
    /* Hunt-Crossley's restitution depends on alpha v alone (the force
     * k d^1.5 (1 + 1.5 alpha d') with d ~ v^(4/5), t ~ v^(-1/5)): the bound on
     * alpha is one on the slowest calibration. e = 0.01 calibrates to the same
     * alpha v at 1e-3 and 10 m/s (to the Brent tolerance, 1e-6 relative), so it
     * needs alpha = 66.7 / v: 6.7e8 s/m at 1e-7 m/s is refused naming restitution. */
    double av[2] = {NAN, NAN}, vs[2] = {1e-3, 10};
    for (int i = 0; i < 2; i++) {
        gw_chain_setup h;
        gw_chain_setup_init(&h);
        snprintf(num, sizeof num, "%g", vs[i]);
        gw_param_set(t, &h, "damping", "hc", &err);
        gw_param_set(t, &h, "restitution", "0.01", &err);
        gw_param_set(t, &h, "restitution-v", num, &err);
        if (gw_chain_setup_resolve(&h, &r, &err) == GW_OK)
            av[i] = r.params.alpha * vs[i];
        gw_chain_resolved_free(&r);
        gw_chain_setup_clear(&h);
    }
    gw_test_rel(av[0], av[1], 1e-6, "HC: e = 0.01 needs the same alpha v at 1e-3 and 10 m/s");
    gw_test_true(av[0] > 10 && av[0] * 1e7 > GW_CHAIN_ALPHA_MAX, "so e = 0.01 at 1e-7 m/s needs alpha above the bound");
    resolve_refused((const char *[]){"damping", "hc", "restitution", "0.01", "restitution-v", "1e-7", NULL},
                    "restitution");

    /* the work of a study over N: sum of N^2 x columns per N <= 2e6; sum_1^181
     * N^2 = 1992991, sum_1^182 = 2026115 */
    gw_test_true(gw_chain_study_work_check(1, 181, 1, &err) == GW_OK &&
                     gw_chain_study_work_check(1, 182, 1, &err) == GW_EINVAL && strncmp(err.msg, "n:", 2) == 0,
                 "study work: N = 1..181 accepted, 1..182 refused naming n");
    gw_test_true(gw_chain_study_work_check(1, 40, 9, &err) == GW_OK &&
                     gw_chain_study_work_check(1, 100, 5, &err) == GW_OK &&
                     gw_chain_study_work_check(1, 100, 6, &err) == GW_EINVAL,
                 "study work: softwall --sheets 1:40 (9 walls) and falcon 1:100 at 5 speeds run, 6 speeds not");
    gw_chain_falcon_setup fs;
    gw_chain_falcon_setup_init(&fs);
    gw_chain_falcon_outcome fo;
    double t0 = gw_clock_ms();
    int frc = gw_param_set(gw_chain_falcon_setup_params(), &fs, "n", "1:100000", &err);
    if (frc == GW_OK)
        frc = gw_chain_falcon_run(&fs, NULL, NULL, &fo, &err);
    char fmsg[640];
    snprintf(fmsg, sizeof fmsg, "falcon study N = 1..100000 refused naming n before any run: %s", err.msg);
    gw_test_true(frc == GW_EINVAL && strncmp(err.msg, "n:", 2) == 0 && gw_clock_ms() - t0 < 1e4, fmsg);
    gw_chain_falcon_outcome_free(&fo);
    gw_chain_falcon_setup_clear(&fs);

    /* dispersion: a ridge is looked for below T/2 - 1 bins; min-bins above
     * T/2 - 2 would resolve nothing */
    gw_chain_disp_params dp = gw_chain_disp_params_default();
    dp.t_samples = 64;
    dp.min_bins = 30;
    int ok30 = gw_chain_disp_params_validate(&dp, &err) == GW_OK;
    dp.min_bins = 30.5;
    gw_test_true(ok30 && gw_chain_disp_params_validate(&dp, &err) == GW_EINVAL && strstr(err.msg, "min-bins"),
                 "dispersion: min-bins 30 accepted at 64 samples, 30.5 refused naming min-bins");
    /* min-bins is a count the ABI holds as a double (a GW_PARAM_COUNT row):
     * 1.5 bins ran as a ridge from 2 bins up; now refused by the model, by
     * gw_param_set, gw_param_set_double and gw_param_check, and "30.0" (as
     * Python's 30.0 gives it) taken as 30; its range printed as integers */
    dp.min_bins = 1.5;
    const int model_refused = gw_chain_disp_params_validate(&dp, &err) == GW_EINVAL &&
                              strstr(err.msg, "min-bins: 1.5 is not a whole number") != NULL;
    dp.min_bins = 2;
    gw_test_true(model_refused && gw_chain_disp_params_validate(&dp, &err) == GW_OK,
                 "dispersion model: min-bins 1.5 refused as not a whole number, 2 accepted");
    const gw_param *dt = gw_chain_dispersion_setup_params(), *mb = gw_param_find(dt, "min-bins");
    gw_chain_dispersion_setup ds;
    gw_chain_dispersion_setup_init(&ds);
    gw_test_true(mb && mb->type == GW_PARAM_COUNT && strcmp(gw_param_type_name(mb->type), "count") == 0,
                 "dispersion setup: min-bins is a count row");
    gw_err e1 = {{0}}, e2 = {{0}}, e3 = {{0}}, e4 = {{0}};
    const int set_15 = gw_param_set(dt, &ds, "min-bins", "1.5", &e1);
    const int setd_15 = gw_param_set_double(dt, &ds, "min-bins", 30.5, &e2);
    const int set_30 = gw_param_set(dt, &ds, "min-bins", "30.0", &e3);
    gw_test_true(set_15 == GW_EINVAL && strcmp(e1.msg, "min-bins: '1.5' is not a whole number (give an integer in "
                                                       "[1, 8388606])") == 0 &&
                     setd_15 == GW_EINVAL && strstr(e2.msg, "min-bins: 30.5 is not a whole number") == e2.msg &&
                     set_30 == GW_OK && ds.min_bins == 30,
                 "dispersion setup: min-bins '1.5' and 30.5 refused naming min-bins, '30.0' taken as 30");
    const int set_big = gw_param_set(dt, &ds, "min-bins", "8388607", &e4);
    gw_test_true(set_big == GW_EINVAL && strcmp(e4.msg, "min-bins: 8388607 is outside [1, 8388606]") == 0, e4.msg);
    ds.min_bins = 2.5; /* written directly, as a C caller may */
    gw_test_true(gw_param_check(dt, &ds, &err) == GW_EINVAL && strstr(err.msg, "min-bins: 2.5 is not a whole number"),
                 "dispersion setup: min_bins 2.5 written into the struct refused by gw_param_check");
    ds.min_bins = 8;
    gw_test_true(gw_param_check(dt, &ds, &err) == GW_OK, "dispersion setup: min_bins 8 written into the struct passes");
    gw_chain_dispersion_setup_clear(&ds);

    cJSON *js = gw_param_json(t, &s);
    int keys = 0;
    for (int i = 0; t[i].name; i++)
        keys += cJSON_GetObjectItemCaseSensitive(js, t[i].name) != NULL;
    gw_test_true(js && keys == gw_param_count(t), "settings JSON has every row of the table");
    cJSON_Delete(js);
    gw_chain_setup_clear(&s);

    check_result_table(gw_chain_collision_fields(), "column collision");

    /* one collision through the table */
    gw_chain_setup_init(&s);
    gw_param_set(t, &s, "trace", "1", &err);
    gw_chain_collision c;
    int rc = gw_chain_collision_run(&s, &c, &err);
    gw_test_true(rc == GW_OK, "collision N = 1 runs");
    if (rc == GW_OK) {
        gw_test_rel(c.r.f_max, c.f_max_1, 1e-6, "N = 1: F_max = closed form (F.13)");
        gw_test_rel(c.r.tau_max, 0.5 * c.tau_1, 1e-6, "N = 1: tau_max = tau_1/2 (F.21)");
        gw_test_rel(c.f_max_1, gw_chain_fmax1(d.mass, d.kwall, 0.3), 1e-15, "closed form of the defaults");
        double fmax = 0;
        for (int i = 0; i < c.trace_len; i++)
            fmax = fmax > c.f_wall[i] ? fmax : c.f_wall[i];
        gw_test_rel(fmax, c.r.f_max, 1e-3, "trace: the sampled wall force peaks at F_max (within the sampling)");
    }
    gw_chain_collision_free(&c);
    gw_param_set(t, &s, "material", "glass", &err);
    gw_param_set(t, &s, "trace", "0", &err);
    gw_test_true(gw_chain_setup_resolve(&s, &r, &err) == GW_OK, "glass beads resolve");
    gw_test_rel(r.params.mass, 4.0 / 3.0 * M_PI * pow(4e-3, 3) * 2500, 1e-15, "glass bead mass 4/3 pi R^3 rho");
    gw_chain_resolved_free(&r);
    gw_chain_setup_clear(&s);
    return gw_test_summary("test_param");
}
