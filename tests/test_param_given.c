/*
 * test_param_given.c: a value given at its default's value is told apart from
 * none, where the difference decides a refusal ("has no effect").
 *
 * The rule before: a row was "given" when its value differed from the
 * default's, so the default's value given explicitly passed silently where any
 * other value was refused: `dispersion --column-n 5 --n 1024`,
 * `dispersion --solver cvode --steps-per-sample 16`, `dispersion --vimp 0.3`
 * without a column, `layer-make --aspect-max 4` or `--clump-mass sum`
 * without clumps, `chain --radii ... --radius 4e-3`, `chain --kwall K
 * --wall-material steel` (and the bead material with mass, k, kwall; the
 * wall's with a fitted sheet), `layer-stats --fit
 * ...,tan_gamma --gamma-deg 0.2`, `layer-stats --fit beta,a_over_b` on a
 * table without a diagram (while `--fit a_over_b,beta` was refused: a text
 * row judged by its text). And dispersion's column-n accepted 0 in the
 * library (Python) while the program refused it.
 *
 * Asserted, through the library (gw_param_set, as Python and the program set
 * a given value): (1) the optional rows' states: init leaves them not given
 * (NaN, GW_PARAM_UNSET_LONG, -1), gw_param_check passes them, gw_param_format
 * writes "", gw_param_json null, gw_param_given tells a set default from none,
 * gw_param_resolve gives the defaults; (2) each refusal above, at the default's
 * value, with the row named; (3) not given and given at the default run alike:
 * the dispersion study's ridge and the chain's collision bit for bit.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_chain_study.h"
#include "gw_layer_study.h"
#include "gw_param.h"
#include "gw_stats.h"
#include "gw_test.h"

/* set name = value in obj by table t; returns the call's code */
static int set(const gw_param *t, void *obj, const char *name, const char *value)
{
    gw_err e = {{0}};
    int rc = gw_param_set(t, obj, name, value, &e);
    if (rc != GW_OK)
        printf("  set %s=%s: %s\n", name, value, e.msg);
    return rc;
}

/* the error of a refused run starts with "row:" */
static void refused(int rc, const gw_err *e, const char *row, const char *what)
{
    char head[64];
    snprintf(head, sizeof head, "%s:", row);
    char msg[700];
    snprintf(msg, sizeof msg, "%s: refused naming %s (rc %d, '%s')", what, row, rc, e->msg);
    gw_test_true(rc == GW_EINVAL && strncmp(e->msg, head, strlen(head)) == 0, msg);
}

static void states(void)
{
    const gw_param *t = gw_chain_dispersion_setup_params();
    gw_chain_dispersion_setup s;
    gw_test_true(gw_chain_dispersion_setup_init(&s) == GW_OK, "dispersion setup init");
    const gw_param *n = gw_param_find(t, "n"), *col = gw_param_find(t, "column-n"), *f0 = gw_param_find(t, "f0"),
                   *ends = gw_param_find(t, "ends"), *fm = gw_param_find(t, "fftw-measure");
    gw_test_true(n->optional && col->optional && f0->optional && ends->optional && !fm->optional,
                 "the one-mode rows are optional, fftw-measure is not");
    gw_test_true(s.n == GW_PARAM_UNSET_LONG && s.column_n == GW_PARAM_UNSET_LONG && isnan(s.f0) && s.ends == -1,
                 "init: not given (GW_PARAM_UNSET_LONG, NaN, -1)");
    gw_err e = {{0}};
    gw_test_true(gw_param_check(t, &s, &e) == GW_OK, "check passes rows not given");
    char buf[64] = "x";
    gw_test_true(gw_param_format(n, &s, buf, sizeof buf) == 0 && buf[0] == '\0', "format: '' when not given");
    cJSON *j = gw_param_json(t, &s);
    gw_test_true(j && cJSON_IsNull(cJSON_GetObjectItem(j, "n")) && cJSON_IsNull(cJSON_GetObjectItem(j, "column-n")),
                 "json: null when not given");
    cJSON_Delete(j);
    gw_test_true(!gw_param_given(n, &s) && !gw_param_given(col, &s), "given: 0 before any set");
    gw_test_true(set(t, &s, "n", "1024") == GW_OK && gw_param_given(n, &s), "given: 1 set at the default's value");
    gw_test_true(!gw_param_given(fm, &s), "a row with a default: not given at the default's value");
    gw_chain_dispersion_setup r = s;
    gw_test_true(gw_param_resolve(t, &r, &e) == GW_OK, "resolve");
    gw_test_true(r.n == 1024 && r.f0 == 10 && r.t_samples == 2048 && r.steps_per_sample == 16 && r.seed == 1 &&
                     r.min_bins == 8 && r.amp == 1e-3 && r.dt_out == 0 && r.ends == 0 && r.vimp == 0.3,
                 "resolve: the defaults");
    gw_test_true(r.column_n == GW_PARAM_UNSET_LONG, "resolve: a row without a default stays not given");
    /* a C caller's direct write counts as given, as a set does */
    gw_chain_dispersion_setup d;
    gw_chain_dispersion_setup_init(&d);
    d.amp = 1e-3;
    gw_test_true(gw_param_given(gw_param_find(t, "amp"), &d), "a field written directly is given");
    /* column-n: 0 is outside its range in the library as on the command line */
    gw_test_true(gw_param_set(t, &d, "column-n", "0", &e) == GW_EINVAL && strstr(e.msg, "column-n: 0") != NULL,
                 "column-n 0 refused by the library");
    gw_chain_dispersion_setup_clear(&d);
    gw_chain_dispersion_setup_clear(&s);
}

static int disp_run(gw_chain_dispersion_setup *s, gw_chain_dispersion_outcome *o, gw_err *e)
{
    memset(o, 0, sizeof *o);
    int rc = gw_chain_dispersion_run(s, o, e);
    gw_chain_dispersion_setup_clear(s);
    return rc;
}

static void dispersion(void)
{
    const gw_param *t = gw_chain_dispersion_setup_params();
    gw_chain_dispersion_setup s;
    gw_chain_dispersion_outcome o;
    gw_err e = {{0}};
    static const struct {
        const char *row, *value;
    } mode_rows[] = {{"n", "1024"}, {"f0", "10"},  {"ends", "periodic"}, {"t-samples", "2048"},
                     {"dt-out", "0"}, {"steps-per-sample", "16"}, {"amp", "1e-3"}, {"seed", "1"},
                     {"min-bins", "8"}};
    for (size_t i = 0; i < sizeof mode_rows / sizeof mode_rows[0]; i++) {
        gw_chain_dispersion_setup_init(&s);
        set(t, &s, "column-n", "5");
        set(t, &s, mode_rows[i].row, mode_rows[i].value);
        char what[96];
        snprintf(what, sizeof what, "dispersion column-n 5, %s at its default", mode_rows[i].row);
        int rc = disp_run(&s, &o, &e);
        refused(rc, &e, mode_rows[i].row, what);
        gw_chain_dispersion_outcome_free(&o);
    }
    gw_chain_dispersion_setup_init(&s);
    set(t, &s, "vimp", "0.3");
    int rc = disp_run(&s, &o, &e);
    refused(rc, &e, "vimp", "dispersion vimp 0.3 without column-n");
    gw_chain_dispersion_outcome_free(&o);
    gw_chain_dispersion_setup_init(&s);
    set(t, &s, "solver", "cvode");
    set(t, &s, "steps-per-sample", "16");
    rc = disp_run(&s, &o, &e);
    refused(rc, &e, "steps-per-sample", "dispersion cvode with steps-per-sample 16");
    gw_chain_dispersion_outcome_free(&o);

    /* not given and given at the defaults: the same run, bit for bit */
    gw_chain_dispersion_outcome a, b;
    gw_chain_dispersion_setup_init(&s);
    set(t, &s, "n", "64");
    set(t, &s, "t-samples", "128");
    int ra = disp_run(&s, &a, &e);
    gw_chain_dispersion_setup_init(&s);
    set(t, &s, "n", "64");
    set(t, &s, "t-samples", "128");
    for (size_t i = 0; i < sizeof mode_rows / sizeof mode_rows[0]; i++)
        if (strcmp(mode_rows[i].row, "n") != 0 && strcmp(mode_rows[i].row, "t-samples") != 0)
            set(t, &s, mode_rows[i].row, mode_rows[i].value);
    int rb = disp_run(&s, &b, &e);
    int same = ra == GW_OK && rb == GW_OK && a.r.nq == b.r.nq && a.r.nq > 0 && a.r.dt_step == b.r.dt_step;
    for (int q = 0; same && q < a.r.nq; q++)
        same = memcmp(&a.r.omega_ridge[q], &b.r.omega_ridge[q], sizeof(double)) == 0;
    gw_test_true(same, "dispersion: rows not given and given at their defaults give the same ridge bit for bit");
    gw_chain_dispersion_outcome_free(&a);
    gw_chain_dispersion_outcome_free(&b);
}

static void layer_make(void)
{
    const gw_param *t = gw_layer_make_setup_params();
    static const char *const rows[][2] = {{"aspect-max", "4"}, {"clump-mass", "sum"}};
    for (int i = 0; i < 2; i++) {
        gw_layer_make_setup s;
        gw_layer_make_setup_init(&s);
        set(t, &s, rows[i][0], rows[i][1]);
        gw_layer_params lp;
        gw_layer_make_params mp;
        gw_err e = {{0}};
        char what[96];
        snprintf(what, sizeof what, "layer-make %s %s without clumps", rows[i][0], rows[i][1]);
        refused(gw_layer_make_plan(&s, &lp, &mp, &e), &e, rows[i][0], what);
        /* with clumps, accepted, and the plan is the defaults' */
        set(t, &s, "clumps", "1");
        gw_test_true(gw_layer_make_plan(&s, &lp, &mp, &e) == GW_OK && mp.aspect_max == 4 &&
                         lp.clump_mass == GW_LAYER_CLUMP_MASS_SUM,
                     "layer-make with clumps: given at the default, planned as the default");
        gw_layer_make_setup_clear(&s);
    }
    gw_layer_make_setup s;
    gw_layer_make_setup_init(&s);
    gw_layer_params lp;
    gw_layer_make_params mp;
    gw_err e = {{0}};
    set(t, &s, "clumps", "1");
    gw_test_true(gw_layer_make_plan(&s, &lp, &mp, &e) == GW_OK && mp.aspect_max == 4 &&
                     lp.clump_mass == GW_LAYER_CLUMP_MASS_SUM,
                 "layer-make clumps, the rows not given: the defaults 4 and sum");
    gw_layer_make_setup_clear(&s);
}

static void chain_radius(void)
{
    const gw_param *t = gw_chain_setup_params();
    gw_chain_setup s;
    gw_chain_resolved r;
    gw_err e = {{0}};
    gw_chain_setup_init(&s);
    set(t, &s, "radii", "4e-3,4e-3,4e-3");
    set(t, &s, "radius", "4e-3");
    memset(&r, 0, sizeof r);
    refused(gw_chain_setup_resolve(&s, &r, &e), &e, "radius", "chain radii with radius 4e-3");
    gw_chain_resolved_free(&r);
    gw_chain_setup_clear(&s);
    /* the materials at steel, where they have no effect */
    gw_chain_setup_init(&s);
    set(t, &s, "kwall", "1e10");
    set(t, &s, "wall-material", "steel");
    memset(&r, 0, sizeof r);
    refused(gw_chain_setup_resolve(&s, &r, &e), &e, "wall-material", "chain kwall with wall-material steel");
    gw_chain_resolved_free(&r);
    gw_chain_setup_clear(&s);
    gw_chain_setup_init(&s);
    set(t, &s, "mass", "2e-3");
    set(t, &s, "k", "1e10");
    set(t, &s, "kwall", "1e10");
    set(t, &s, "material", "steel");
    memset(&r, 0, sizeof r);
    refused(gw_chain_setup_resolve(&s, &r, &e), &e, "material", "chain mass, k, kwall with material steel");
    gw_chain_resolved_free(&r);
    gw_chain_setup_clear(&s);
    gw_chain_setup_init(&s);
    set(t, &s, "sheet", "brass");
    set(t, &s, "wall-material", "steel");
    memset(&r, 0, sizeof r);
    refused(gw_chain_setup_resolve(&s, &r, &e), &e, "wall-material", "chain sheet brass (fitted) with wall-material steel");
    gw_chain_resolved_free(&r);
    gw_chain_setup_clear(&s);
    /* not given and given at 4e-3: the same column */
    gw_chain_resolved a, b;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    gw_chain_setup_init(&s);
    int ra = gw_chain_setup_resolve(&s, &a, &e);
    set(t, &s, "radius", "4e-3");
    set(t, &s, "material", "steel");
    set(t, &s, "wall-material", "steel");
    int rb = gw_chain_setup_resolve(&s, &b, &e);
    gw_test_true(ra == GW_OK && rb == GW_OK && a.params.radius == 4e-3 && a.params.mass == b.params.mass &&
                     a.params.k == b.params.k && a.params.kwall == b.params.kwall,
                 "chain: radius and materials not given resolve as 4e-3 and steel given");
    gw_chain_resolved_free(&a);
    gw_chain_resolved_free(&b);
    gw_chain_setup_clear(&s);
}

static void stats_gamma(void)
{
    const gw_param *t = gw_stats_setup_params();
    gw_stats_setup s;
    gw_stats_setup_init(&s);
    set(t, &s, "input", "/nonexistent/results.csv");
    set(t, &s, "fit", "beta,a_over_b,tan_gamma");
    set(t, &s, "gamma-deg", "0.2");
    gw_stats_analysis A;
    gw_err e = {{0}};
    refused(gw_stats_analyse(&s, &A, &e), &e, "gamma-deg", "layer-stats tan_gamma fitted, gamma-deg 0.2");
    gw_stats_analysis_free(&A);
    gw_stats_setup_clear(&s);
}

/* A sweep table of 4 cases over rb-rm alone: no bouncing diagram (that needs
 * rb-rm and height-rm), so the B.31 options have no effect on it. */
static int write_flat_table(const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fprintf(f, "# param vi = 20\ncase,rb-rm,point,x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,"
               "penetration_rm,dissipated_first_contact,block_loss_first_contact,energy_error,wave_speed,t_end,"
               "steps\n");
    for (int k = 0; k < 4; k++)
        fprintf(f, "%d,%g,%d,0,%d,0.5,0.6,10,20,10,12,0.6,1.5,0.001,0.6,1e-6,nan,0.01,100\n", k, 1 + (k / 2) * 0.5,
                k % 2, k % 2);
    return fclose(f);
}

/* layer-stats' fit: an optional text row. Before, it was judged by its text:
 * "beta,a_over_b" given on a table without a diagram ran silently while
 * "a_over_b,beta" (the same fit) was refused as having no effect. */
static void stats_fit(void)
{
    const gw_param *t = gw_stats_setup_params(), *fit = gw_param_find(t, "fit");
    gw_stats_setup s;
    gw_stats_setup_init(&s);
    gw_test_true(fit && fit->optional && fit->type == GW_PARAM_TEXT && fit->def && strcmp(fit->def, "beta,a_over_b") == 0,
                 "layer-stats fit: an optional text row, default beta,a_over_b");
    gw_test_true(s.fit == NULL && !gw_param_given(fit, &s), "fit: init leaves it not given (NULL)");
    char buf[64] = "x";
    gw_test_true(gw_param_format(fit, &s, buf, sizeof buf) == 0 && buf[0] == '\0', "fit: format '' when not given");
    cJSON *j = gw_param_json(t, &s);
    gw_test_true(j && cJSON_IsNull(cJSON_GetObjectItem(j, "fit")), "fit: json null when not given");
    cJSON_Delete(j);
    gw_err e = {{0}};
    gw_stats_setup r;
    gw_test_true(gw_param_copy(t, sizeof r, &r, &s, &e) == GW_OK && gw_param_resolve(t, &r, &e) == GW_OK &&
                     r.fit && strcmp(r.fit, "beta,a_over_b") == 0 && r.fit != fit->def,
                 "fit: resolve gives an owned copy of the default");
    gw_param_clear(t, &r);
    gw_test_true(set(t, &s, "fit", "beta,a_over_b") == GW_OK && gw_param_given(fit, &s),
                 "fit: given at the default's text is given");
    gw_stats_setup_clear(&s);

    char path[] = "/tmp/gw_param_given_XXXXXX";
    int fd = mkstemp(path);
    if (fd < 0 || write_flat_table(path) != 0) {
        gw_test_true(0, "write the table without a diagram");
        return;
    }
    close(fd);
    const char *fits[] = {NULL, "beta,a_over_b", "a_over_b,beta", "beta,a_over_b,offset"};
    for (size_t k = 0; k < sizeof fits / sizeof fits[0]; k++) {
        gw_stats_setup_init(&s);
        s.defaults = (gw_stats_defaults){1, 0, 20, 2650};
        set(t, &s, "input", path);
        if (fits[k])
            set(t, &s, "fit", fits[k]);
        gw_stats_analysis A;
        gw_err ea = {{0}};
        int rc = gw_stats_analyse(&s, &A, &ea);
        char what[160];
        snprintf(what, sizeof what, "layer-stats without a diagram, fit %s", fits[k] ? fits[k] : "not given");
        if (fits[k])
            refused(rc, &ea, "fit", what);
        else
            gw_test_true(rc == GW_OK && A.fit_mask == (GW_STATS_B31_BETA | GW_STATS_B31_AB) && !A.fit_given, what);
        gw_stats_analysis_free(&A);
        gw_stats_setup_clear(&s);
    }
    unlink(path);
}

int main(void)
{
    states();
    dispersion();
    layer_make();
    chain_radius();
    stats_gamma();
    stats_fit();
    return gw_test_summary("test_param_given");
}
