/*
 * test_library_hostile51.c: the fifty-first hostile pass over the library's C
 * interface (docs/library.md "The contract of every call"), at the calls the
 * fiftieth did not reach: the text parsers given NULL names and bounds that
 * are no range, the path join, the parameter tables' format and JSON of
 * fields written directly, the B.31 curve far out and outside its domain, and
 * the fit's list of names. About 250 calls (the parsers with NULL, empty,
 * control-character, hexadecimal, overflowing and subnormal text; a layer
 * handle used before its start, after a failed start and twice; out-of-range
 * particle and body indices; every study's parameter rows written directly
 * with NaN, -0, subnormals, lists without values, ranges 5:1, choices 99 and
 * texts holding control characters; the sweep text with duplicate and
 * reopened sections, a BOM, CR LF and control characters; the interrupt
 * pairs unbalanced; the statistics' closed forms). What it found:
 *   - gw_parse_int_range read a NULL name through strlen when an end was
 *     refused (SIGSEGV); gw_parse_double, gw_parse_long and
 *     gw_parse_double_list wrote it "(null): ...". Each now says "value"
 *     (the list "list"), as gw_check_range.
 *   - gw_parse_long, gw_parse_int_range and gw_parse_double_list_in given
 *     lo > hi told the value "5 is outside [10, 0]" (the input blamed for the
 *     caller's bounds), and gw_parse_double_list_in ran open_lo 2 as 1: each
 *     is refused naming the call and the bounds, as gw_check_range refuses
 *     them.
 *   - gw_path_join joined an empty dir as "/NAME": a file in the root
 *     directory, where the journal, the sweep's table, the chain's traces
 *     and the statistics' files build their paths. GW_EINVAL, buf unchanged.
 *   - gw_param_format read a list row counted without its values (SIGSEGV),
 *     and formatted a negative count as "" (not given); gw_param_check
 *     refuses both, and the format is -1 for both now.
 *   - gw_param_json wrote a text row longer than 255 bytes as null: a
 *     layer-make --out of 289 characters was recorded in the sample's header
 *     as "out": null. Texts are written whole.
 *   - gw_stats_b31_eval was NaN from |x| = 1e154 (u^2 overflowed) where B.31
 *     has a value, and gw_stats_b31_min gave a minimum (2 beta, ...) for
 *     tan gamma 0, where the curve is NaN everywhere, and +-inf for a/b < 0:
 *     both are NaN outside the curves the fit gives (a/b, tan gamma > 0, all
 *     finite), and the value far out is the closed form's.
 *   - gw_stats_fit_parse refused "beta, a_over_b" as "unknown parameter
 *     ' a_over_b'", where every other list takes blanks around its items.
 * Each case runs in its own child process (test_child.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "granwave.h"
#include "test_child.h"

/* ------------------------------------------------------ the parsers ---- */

static int c_parse_null_name(void)
{
    gw_err e = {0};
    long a = 7, b = 7;
    /* an end refused with a NULL name: strlen(NULL) */
    EXPECT(gw_parse_int_range("1:x", NULL, 0, 10, &a, &b, &e) == GW_EINVAL);
    EXPECT(strncmp(e.msg, "value: '1:x' is not a range", 27) == 0);
    EXPECT(gw_parse_int_range("x:1", NULL, 0, 10, &a, &b, &e) == GW_EINVAL && !strstr(e.msg, "(null)"));
    EXPECT(gw_parse_long("x", NULL, 0, 10, &a, &e) == GW_EINVAL && strncmp(e.msg, "value: 'x'", 10) == 0);
    double d = 7;
    EXPECT(gw_parse_double("abc", NULL, &d, &e) == GW_EINVAL && strncmp(e.msg, "value: 'abc'", 12) == 0);
    double *v = NULL;
    int n = 0;
    EXPECT(gw_parse_double_list("1,x", NULL, &v, &n, &e) == GW_EINVAL && strncmp(e.msg, "list: ", 6) == 0);
    EXPECT(v == NULL && n == 0);
    /* control: named, as before */
    EXPECT(gw_parse_int_range("1:x", "n", 0, 10, &a, &b, &e) == GW_EINVAL && strncmp(e.msg, "n: '1:x'", 8) == 0);
    EXPECT(gw_parse_int_range("2:3", NULL, 0, 10, &a, &b, &e) == GW_OK && a == 2 && b == 3);
    return 0;
}

static int c_parse_bounds(void)
{
    gw_err e = {0};
    long a = 7, b = 7;
    EXPECT(refused(gw_parse_long("5", "n", 10, 0, &a, &e), &e, "gw_parse_long: n: the bounds [10, 0] are no range"));
    EXPECT(a == 7);
    EXPECT(refused(gw_parse_int_range("3", "n", 10, 0, &a, &b, &e), &e, "gw_parse_int_range: n: the bounds"));
    EXPECT(refused(gw_parse_int_range("1:3", "n", 10, 0, &a, &b, &e), &e, "(lo > hi)"));
    double *v = NULL;
    int n = 0;
    EXPECT(refused(gw_parse_double_list_in("1,2", "x", 3, 0, 0, &v, &n, &e), &e,
                   "gw_parse_double_list_in: x: the bounds are no range (lo > hi)"));
    EXPECT(refused(gw_parse_double_list_in("1", "x", 0, 3, 2, &v, &n, &e), &e, "open_lo is not a flag"));
    EXPECT(v == NULL && n == 0);
    /* controls: a one-point range, and open_lo 1 and 0 as before */
    EXPECT(gw_parse_long("5", "n", 5, 5, &a, &e) == GW_OK && a == 5);
    EXPECT(gw_parse_int_range("5:5", "n", 5, 5, &a, &b, &e) == GW_OK && a == 5 && b == 5);
    EXPECT(refused(gw_parse_double_list_in("0", "x", 0, 3, 1, &v, &n, &e), &e, "item 1 is 0, outside (0, 3]"));
    EXPECT(gw_parse_double_list_in("0,3", "x", 0, 3, 0, &v, &n, &e) == GW_OK && n == 2 && v[1] == 3);
    free(v);
    return 0;
}

/* ------------------------------------------------------ the path join ---- */

static int c_path_join_empty(void)
{
    char buf[32] = "keep";
    EXPECT(gw_path_join(buf, sizeof buf, "", "journal.csv") == GW_EINVAL);
    EXPECT(strcmp(buf, "keep") == 0);
    /* controls: a directory, ".", "/" */
    EXPECT(gw_path_join(buf, sizeof buf, "out", "journal.csv") == GW_OK && strcmp(buf, "out/journal.csv") == 0);
    EXPECT(gw_path_join(buf, sizeof buf, ".", "a") == GW_OK && strcmp(buf, "./a") == 0);
    EXPECT(gw_path_join(buf, sizeof buf, "/", "a") == GW_OK && strcmp(buf, "//a") == 0);
    return 0;
}

/* ------------------------------------------------------ the parameter tables ---- */

static int c_param_format_list(void)
{
    const gw_study *st = gw_study_find("chain");
    EXPECT(st != NULL);
    void *obj = calloc(1, st->params_size);
    EXPECT(obj && st->init(obj) == GW_OK);
    const gw_param *row = gw_param_find(st->params(), "radii");
    EXPECT(row && row->type == GW_PARAM_LIST);
    gw_param_list *l = (gw_param_list *)((char *)obj + row->offset);
    char buf[128];
    gw_err e = {0};
    l->n = 3; /* counted without its values: read through NULL */
    l->v = NULL;
    EXPECT(gw_param_check(st->params(), obj, &e) == GW_EINVAL);
    EXPECT(gw_param_format(row, obj, buf, sizeof buf) == -1);
    double v[2] = {1e-3, 2e-3};
    l->v = v;
    l->n = -2; /* a negative count: formatted "" (not given) */
    EXPECT(gw_param_check(st->params(), obj, &e) == GW_EINVAL);
    EXPECT(gw_param_format(row, obj, buf, sizeof buf) == -1);
    /* controls: the two radii, and an empty list "" */
    l->n = 2;
    EXPECT(gw_param_format(row, obj, buf, sizeof buf) == 11 && strcmp(buf, "0.001,0.002") == 0);
    l->n = 0;
    l->v = NULL;
    EXPECT(gw_param_format(row, obj, buf, sizeof buf) == 0 && buf[0] == '\0');
    st->clear(obj);
    free(obj);
    return 0;
}

/* the JSON's value of row name in study sname holding text s, or NULL */
static char *json_text(const char *sname, const char *name, const char *s)
{
    const gw_study *st = gw_study_find(sname);
    void *obj = calloc(1, st->params_size);
    char *out = NULL;
    gw_err e = {0};
    if (obj && st->init(obj) == GW_OK && (!s || gw_param_set(st->params(), obj, name, s, &e) == GW_OK)) {
        cJSON *j = gw_param_json(st->params(), obj);
        const cJSON *v = j ? cJSON_GetObjectItemCaseSensitive(j, name) : NULL;
        out = cJSON_IsString(v) ? strdup(v->valuestring) : cJSON_IsNull(v) ? strdup("(json null)") : NULL;
        cJSON_Delete(j);
    }
    if (obj)
        st->clear(obj);
    free(obj);
    return out;
}

static int c_param_json_text(void)
{
    const char *const studies[] = {"layer-impact", "layer-make"};
    const char *const rows[] = {"sample", "out"};
    for (int k = 0; k < 2; k++) {
        char path[400];
        memset(path, 'a', 300);
        path[0] = '/';
        path[300] = '\0';
        char *got = json_text(studies[k], rows[k], path);
        EXPECT(got && strcmp(got, path) == 0);
        free(got);
        /* controls: a short text as before, none as null */
        got = json_text(studies[k], rows[k], "/tmp/s.txt");
        EXPECT(got && strcmp(got, "/tmp/s.txt") == 0);
        free(got);
        got = json_text(studies[k], rows[k], NULL);
        EXPECT(got && strcmp(got, "(json null)") == 0);
        free(got);
    }
    return 0;
}

/* ------------------------------------------------------ the statistics ---- */

static int c_b31_far_out(void)
{
    const gw_stats_b31 p = {0.1, 1.0, 2.0, 0.5}; /* K = (a/b) tan gamma = 1 */
    const double T = 0.5, K = 1.0;
    /* x >> beta: f = offset + x K / ((sqrt(1 + K) + 1) 2 T) */
    const double x = 1e200, want = 0.1 + x * K / ((sqrt(1 + K) + 1) * 2 * T);
    const double f = gw_stats_b31_eval(&p, x);
    EXPECT(isfinite(f) && fabs(f / want - 1) < 1e-14);
    /* x << beta (the steep branch): offset + |x| (sqrt(1 + K) + 1) / (2 T) */
    const double g = gw_stats_b31_eval(&p, -x), want_g = 0.1 + x * (sqrt(1 + K) + 1) / (2 * T);
    EXPECT(isfinite(g) && fabs(g / want_g - 1) < 1e-14);
    EXPECT(gw_stats_b31_eval(&p, DBL_MAX) > 0 && isfinite(gw_stats_b31_eval(&p, 1e300)));
    /* control: an ordinary x, bit for bit the formula as it was */
    const double xs = 2.5, u = xs - p.beta, r = sqrt(u * u + K * xs * xs);
    EXPECT(gw_stats_b31_eval(&p, xs) == p.offset + K * xs * xs / (r + u) / (2 * T));
    return 0;
}

static int c_b31_domain(void)
{
    const gw_stats_b31 bad[] = {{0.1, 1.0, 2.0, 0.0},       {0.1, 1.0, -2.0, 0.5},      {0.1, 1.0, 2.0, -0.5},
                                {0.1, 1.0, INFINITY, 0.5},  {NAN, 1.0, 2.0, 0.5},       {0.1, INFINITY, 2.0, 0.5},
                                {0.1, 1.0, 1e300, 1e300}};
    for (int i = 0; i < 7; i++) {
        double xm = 7, fm = 7;
        gw_stats_b31_min(&bad[i], &xm, &fm);
        if (!isnan(xm) || !isnan(fm) || !isnan(gw_stats_b31_eval(&bad[i], 2.0))) {
            printf("row %d: min (%g, %g), f(2) = %g\n", i, xm, fm, gw_stats_b31_eval(&bad[i], 2.0));
            return 1;
        }
    }
    const gw_stats_b31 p = {0.1, 1.0, 2.0, 0.5};
    EXPECT(isnan(gw_stats_b31_eval(&p, INFINITY)) && isnan(gw_stats_b31_eval(&p, NAN)));
    /* control: the minimum at 2 beta / (1 + K), offset + (a/b) beta / (1 + K) */
    double xm, fm;
    gw_stats_b31_min(&p, &xm, &fm);
    EXPECT(xm == 1.0 && fm == 0.1 + 2.0 * 1.0 / 2.0);
    EXPECT(fabs(gw_stats_b31_eval(&p, xm) - fm) < 1e-15);
    return 0;
}

static int c_fit_blanks(void)
{
    gw_err e = {0};
    int mask = -1;
    const char *const ok[] = {"beta, a_over_b", " beta , a_over_b ", "beta,\ta_over_b", "a_over_b , beta ,offset"};
    const int want[] = {GW_STATS_B31_BETA | GW_STATS_B31_AB, GW_STATS_B31_BETA | GW_STATS_B31_AB,
                        GW_STATS_B31_BETA | GW_STATS_B31_AB,
                        GW_STATS_B31_BETA | GW_STATS_B31_AB | GW_STATS_B31_OFFSET};
    for (int i = 0; i < 4; i++) {
        const int rc = gw_stats_fit_parse(ok[i], &mask, &e);
        if (rc != GW_OK || mask != want[i]) {
            printf("'%s': %d mask %d %s\n", ok[i], rc, mask, e.msg);
            return 1;
        }
    }
    /* controls: an item of blanks alone is empty, a name twice, an unknown
     * name quoted without its blanks */
    EXPECT(refused(gw_stats_fit_parse("beta, ,a_over_b", &mask, &e), &e, "has an empty item"));
    EXPECT(refused(gw_stats_fit_parse("beta, beta", &mask, &e), &e, "'beta' is listed twice"));
    EXPECT(refused(gw_stats_fit_parse("beta, gamma", &mask, &e), &e, "unknown parameter 'gamma'"));
    EXPECT(gw_stats_fit_parse("beta,a_over_b", &mask, &e) == GW_OK && mask == want[0]);
    return 0;
}

static const child_row rows[] = {
    {"parsers: a NULL name is 'value' (gw_parse_int_range read it: SIGSEGV)", c_parse_null_name},
    {"parsers: lo > hi and open_lo 2 are the caller's error, named", c_parse_bounds},
    {"gw_path_join: an empty dir refused (it was '/NAME')", c_path_join_empty},
    {"gw_param_format: a list without its values or of a negative count is -1", c_param_format_list},
    {"gw_param_json: a text over 255 bytes written whole (it was null)", c_param_json_text},
    {"B.31: its value far out (NaN from |x| = 1e154)", c_b31_far_out},
    {"B.31: NaN minimum and value outside a/b, tan gamma > 0", c_b31_domain},
    {"fit: blanks around the names taken", c_fit_blanks},
};

int main(void)
{
    return child_cases_run(rows, sizeof rows / sizeof rows[0]);
}
