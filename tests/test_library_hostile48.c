/*
 * test_library_hostile48.c: the forty-eighth hostile pass over the library's
 * C interface (docs/library.md "The contract of every call"): a sweep table's
 * settings against the model's rows, least-squares lines of any magnitude,
 * failures without a message in the worker pool and the sweep, a drop result
 * filled by hand.
 *   - layer-stats held a table's settings (its grid cells and "# param"
 *     lines) to a domain of its own (rb-rm > 0, vi > 0, ...), which took
 *     values no sweep of the layer runs: rb-rm = 1e308, vi = 1e308, density
 *     1e7, a subnormal height 1e-320, points = 2147483648, point = 1.5, and
 *     analysed them (exit 0, Python alike). The layer model now registers
 *     the rule of its own rows (gw_sweep_value_rule: the impact's and the
 *     placement's, as a case sets them) and the reader holds every setting
 *     to it: GW_EFORMAT naming the line, the key and the row's range.
 *     Controls: the rows' closed ends are taken; a hand table without the
 *     sweep's first line (model layer assumed) is held alike.
 *   - gw_fit_linear summed squares of the points as given: abscissas near
 *     1e300 gave a NaN line with GW_OK, ordinates near 1e300 infinite errors
 *     and r2 NaN, abscissas near 1e-160 a slope off by 1e-5 and an infinite
 *     error, and a slope beyond the doubles inf with GW_OK. The fit now runs
 *     on the points scaled by powers of two (the same numbers, bit for bit,
 *     for ordinary points) and refuses a line the doubles cannot hold.
 *   - gw_cases_run returned a case's failure with an empty message when the
 *     case gave none (its status alone, or a status none of the library's);
 *     gw_sweep_run with a caller's model that failed or refused silently
 *     said "case 2: ". Each now says which case, the status and that the
 *     case (or the model's run or check) gave no message. Control: a case's
 *     own message is kept as it was.
 *   - gw_afile_openat took an empty name: it made its temporary in the
 *     directory, and the commit failed once the caller's write was done
 *     ("DIR/: write failed: No such file or directory"). Refused at the open
 *     as gw_afile_open refuses an empty path, nothing made. Control: a plain
 *     name written and committed.
 *   - Values refused just outside a closed end were printed with %g,
 *     rounded onto the end they are outside of: a criterion of 1.0000001
 *     "1 is not in (0, 1]" (gw_stats_groups_make, gw_stats_diagram_make),
 *     falcon's gravity 10000.0000001 "10000 ... is outside [0, 10000]", a
 *     Poisson ratio 0.5000001 "0.5 is not in (-1, 0.5]", a flag
 *     0.9999999999 "1 is not a flag". They are shown as given (gw_num_text), as the
 *     parameter rows' refusals show them.
 *   - gw_chain_drop_impact_rises read a hand-filled result's impacts through
 *     NULL (SIGSEGV) when it had a count and no array: 0 rises now, as for a
 *     count below 2. Control: three impacts of 1, 2, 1.5 N give one rise.
 * Each case runs in its own child process (test_child.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

#include "granwave.h"
#include "test_child.h"

/* ------------------------------------------------ a table's settings ---- */

static const char *const table_head =
    "case,rb-rm,height-rm,point,x_impact,bounced,e_n,e,alpha_r,penetration,penetration_rm,"
    "block_loss_first_contact\n";

/* A hand table (no sweep line): the "# param" lines params (may be ""),
 * then two rows of rb-rm rb, height-rm h and points 0 and p1. */
static char *table_text(const char *params, const char *rb, const char *h, const char *p1)
{
    char *t = malloc(2048);
    if (t)
        snprintf(t, 2048,
                 "%s%s0,%s,%s,0,0.0,1,0.5,0.6,10,0.01,0.1,0.3\n"
                 "1,%s,%s,%s,0.1,1,0.7,0.8,20,0.02,0.2,0.4\n",
                 params, table_head, rb, h, rb, h, p1);
    return t;
}

/* the table parsed: its status, with its message in *e */
static int parse(const char *params, const char *rb, const char *h, const char *p1, gw_err *e)
{
    char *text = table_text(params, rb, h, p1);
    if (!text)
        return GW_ENOMEM;
    gw_stats_table t;
    memset(&t, 0, sizeof t);
    const int rc = gw_stats_table_parse(text, "hand.csv", &t, e);
    gw_stats_table_free(&t);
    free(text);
    return rc;
}

/* refused as a value no sweep runs: GW_EFORMAT, one line, naming the line,
 * the key and each of what */
static int not_run(int rc, const gw_err *e, const char *line, const char *key, const char *range)
{
    if (rc != GW_EFORMAT || !strstr(e->msg, line) || !strstr(e->msg, key) || !strstr(e->msg, range) ||
        !strstr(e->msg, "is not a value a sweep runs") || strchr(e->msg, '\n')) {
        printf("status %d, message '%s' (wanted GW_EFORMAT naming %s, %s, %s)\n", rc, e->msg, line, key, range);
        return 0;
    }
    return 1;
}

/* a hand table's settings refused as no sweep runs them: its "# param"
 * lines, rb-rm, height-rm and the second row's point, then the line, the key
 * and the range the refusal names */
typedef struct setting_row {
    const char *label, *params, *rb, *h, *p1, *line, *key, *range;
} setting_row;

static const setting_row setting_rows[] = {
    {"table: grid rb-rm 1e308", "", "1e308", "2", "1", "hand.csv:2:", "grid key rb-rm", "[1e-06, 1e+06]"},
    {"table: grid rb-rm 1e-7", "", "1e-7", "2", "1", "hand.csv:2:", "grid key rb-rm", "[1e-06, 1e+06]"},
    {"table: grid height-rm 1e-320 (subnormal)", "", "1", "1e-320", "1", "hand.csv:2:", "grid key height-rm",
     "too small"},
    {"table: grid height-rm 2e6", "", "1", "2e6", "1", "hand.csv:2:", "grid key height-rm", "[0, 1e+06]"},
    {"table: grid point 1.5", "", "1", "2", "1.5", "hand.csv:3:", "grid key point", "not an integer"},
    {"table: param vi 1e308", "# param vi = 1e308\n", "1", "2", "1", "hand.csv:1:", "param vi", "(0, 1000]"},
    {"table: param density 1e7", "# param density = 1e7\n", "1", "2", "1", "hand.csv:1:", "param density",
     "[1e-06, 1e+06]"},
    {"table: param points 2147483648", "# param points = 2147483648\n", "1", "2", "1", "hand.csv:1:",
     "param points", "[1, 1000000000]"},
    /* refused before too, now in the row's words */
    {"table: param alpha 90", "# param alpha = 90\n", "1", "2", "1", "hand.csv:1:", "param alpha", "[0, 90)"},
    /* the sweep's first line names the layer model */
    {"table with the sweep's line: param vi 2000", "# granwave 0.1.0 sweep, model layer\n# param vi = 2000\n", "1",
     "2", "1", "hand.csv:2:", "param vi", "(0, 1000]"},
};
static const setting_row *setr;

static int c_setting(void)
{
    gw_err e = {0};
    EXPECT(not_run(parse(setr->params, setr->rb, setr->h, setr->p1, &e), &e, setr->line, setr->key, setr->range));
    return 0;
}

static int c_ends_taken(void) /* control: the rows' closed ends */
{
    gw_err e = {0};
    int rc = parse("# param vi = 1000\n# param density = 1e-6\n# param alpha = 0\n", "1e6", "0", "1", &e);
    if (rc != GW_OK)
        printf("status %d: %s\n", rc, e.msg);
    EXPECT(rc == GW_OK);
    rc = parse("# param density = 1e6\n", "1e-6", "1e6", "1", &e);
    if (rc != GW_OK)
        printf("status %d: %s\n", rc, e.msg);
    EXPECT(rc == GW_OK);
    return 0;
}

/* ------------------------------------------------------------ fits ---- */

static const double fx[4] = {1, 2, 3, 4}, fy[4] = {2.1, 3.9, 6.2, 7.8};

static int fit_of(double xs, double ys, gw_linfit *f)
{
    double x[4], y[4];
    for (int i = 0; i < 4; i++) {
        x[i] = fx[i] * xs;
        y[i] = fy[i] * ys;
    }
    return gw_fit_linear(x, y, 4, f);
}

static int close_to(double a, double b, double rel)
{
    return isfinite(a) && isfinite(b) && fabs(a - b) <= rel * fabs(b);
}

/* the fit of (x xs, y ys) is the plain fit's line scaled: c1 ys/xs, c0 ys,
 * its errors alike, the same r2 */
static int fit_scaled(double xs, double ys)
{
    gw_linfit p, f;
    EXPECT(fit_of(1, 1, &p) == GW_OK);
    const int rc = fit_of(xs, ys, &f);
    if (rc != GW_OK || !close_to(f.c1, p.c1 * (ys / xs), 1e-12) || !close_to(f.c0, p.c0 * ys, 1e-12) ||
        !close_to(f.c1_err, p.c1_err * (ys / xs), 1e-12) || !close_to(f.c0_err, p.c0_err * ys, 1e-12) ||
        !close_to(f.r2, p.r2, 1e-12)) {
        printf("x * %g, y * %g: status %d, c0 %.17g c1 %.17g errors %.17g %.17g r2 %.17g (plain: %.17g %.17g "
               "%.17g %.17g %.17g)\n", xs, ys, rc, f.c0, f.c1, f.c0_err, f.c1_err, f.r2, p.c0, p.c1, p.c0_err,
               p.c1_err, p.r2);
        return 1;
    }
    return 0;
}

/* points (x xs, y ys) whose fit is the plain one's scaled */
typedef struct fit_row {
    const char *label;
    double xs, ys;
} fit_row;

static const fit_row fit_rows[] = {
    {"fit: abscissas near 1e300", 1e300, 1},
    {"fit: ordinates near 1e300", 1, 1e300},
    {"fit: abscissas near 1e-160", 1e-160, 1},
    {"fit: abscissas near 1e-100, ordinates near 1e200", 1e-100, 1e200}, /* a slope near 1.9e300 */
};
static const fit_row *fitr;

static int c_fit(void)
{
    return fit_scaled(fitr->xs, fitr->ys);
}

static int c_fit_beyond(void) /* a slope of about 1e320: refused, every number NaN */
{
    gw_linfit f;
    const int rc = fit_of(1e-320, 1e300, &f);
    EXPECT(rc == GW_EINVAL);
    EXPECT(isnan(f.c0) && isnan(f.c1) && isnan(f.c0_err) && isnan(f.c1_err) && isnan(f.r2));
    return 0;
}

static int c_fit_exact(void) /* control: a power of two changes nothing but the scale, bit for bit */
{
    gw_linfit p, f;
    EXPECT(fit_of(1, 1, &p) == GW_OK);
    EXPECT(fit_of(0x1p-40, 0x1p+30, &f) == GW_OK);
    EXPECT(f.c1 == ldexp(p.c1, 70) && f.c0 == ldexp(p.c0, 30) && f.r2 == p.r2 &&
           f.max_rel_resid == p.max_rel_resid && f.c1_err == ldexp(p.c1_err, 70));
    /* the least-squares line of these points: slope 19.4/10, intercept 0.15 */
    EXPECT(fabs(p.c1 - 1.94) < 1e-14 && fabs(p.c0 - 0.15) < 1e-14);
    return 0;
}

/* -------------------------------------------------- silent failures ---- */

static int case_silent(void *ctx, long k, gw_err *err)
{
    (void)ctx;
    (void)err;
    return k == 2 ? GW_EINVAL : GW_OK;
}

static int case_seven(void *ctx, long k, gw_err *err)
{
    (void)ctx;
    (void)err;
    return k == 1 ? 7 : GW_OK;
}

static int case_says(void *ctx, long k, gw_err *err)
{
    (void)ctx;
    return k == 3 ? gw_err_set(err, GW_EIO, "disk gone at %ld", k) : GW_OK;
}

static int c_pool_silent(void)
{
    for (int jobs = 1; jobs <= 2; jobs++) {
        gw_err e = {0};
        const int rc = gw_cases_run(6, jobs, case_silent, NULL, NULL, NULL, &e);
        if (rc != GW_EINVAL || !strstr(e.msg, "case 2 of 6") || !strstr(e.msg, "no message")) {
            printf("jobs %d: status %d, message '%s'\n", jobs, rc, e.msg);
            return 1;
        }
    }
    return 0;
}

static int c_pool_other_status(void)
{
    gw_err e = {0};
    const int rc = gw_cases_run(4, 1, case_seven, NULL, NULL, NULL, &e);
    if (rc != 7 || !strstr(e.msg, "case 1 of 4") || !strstr(e.msg, "status 7")) {
        printf("status %d, message '%s'\n", rc, e.msg);
        return 1;
    }
    return 0;
}

static int c_pool_message_kept(void) /* control */
{
    gw_err e = {0};
    const int rc = gw_cases_run(6, 2, case_says, NULL, NULL, NULL, &e);
    EXPECT(rc == GW_EIO && strcmp(e.msg, "disk gone at 3") == 0);
    return 0;
}

static const char *const mine_columns[] = {"y"};

static int mine_has(const char *name)
{
    return strcmp(name, "a") == 0;
}

/* runs a = 1 and 2, fails a = 3 without a word */
static int mine_run(int nk, const char *const *names, const char *const *values, double *out,
                    unsigned long long *h, gw_err *err)
{
    (void)nk;
    (void)names;
    (void)h;
    (void)err;
    out[0] = atof(values[0]);
    return out[0] > 2.5 ? GW_EINVAL : GW_OK;
}

/* refuses a = 6 without a word */
static int mine_check(int nk, const char *const *names, const char *const *values, gw_err *err)
{
    (void)nk;
    (void)names;
    (void)err;
    return atof(values[0]) > 5 ? GW_EINVAL : GW_OK;
}

static int mine_sweep(const char *grid, gw_err *e)
{
    gw_sweep_model m;
    memset(&m, 0, sizeof m);
    m.name = "mine";
    m.ncolumns = 1;
    m.columns = mine_columns;
    m.has_key = mine_has;
    m.run = mine_run;
    m.check = mine_check;
    const gw_sweep_model *models[1] = {&m}, *got = NULL;
    char text[256];
    snprintf(text, sizeof text, "[sweep]\nmodel = mine\n[grid]\na = %s\n", grid);
    gw_sweep_config cfg;
    memset(&cfg, 0, sizeof cfg);
    int rc = gw_sweep_config_read_string(text, "mine.ini", models, 1, &cfg, &got, e);
    double v[8];
    if (rc == GW_OK)
        rc = gw_sweep_run(&cfg, &m, 1, NULL, NULL, v, e);
    gw_sweep_config_free(&cfg);
    return rc;
}

static int c_sweep_run_silent(void)
{
    gw_err e = {0};
    const int rc = mine_sweep("1,2,3", &e);
    if (rc != GW_EINVAL || !strstr(e.msg, "case 2:") || !strstr(e.msg, "model mine") ||
        !strstr(e.msg, "no message")) {
        printf("status %d, message '%s'\n", rc, e.msg);
        return 1;
    }
    return 0;
}

static int c_sweep_check_silent(void)
{
    gw_err e = {0};
    const int rc = mine_sweep("1,6", &e);
    if (rc != GW_EINVAL || !strstr(e.msg, "case 1") || !strstr(e.msg, "model mine's check") ||
        !strstr(e.msg, "no message")) {
        printf("status %d, message '%s'\n", rc, e.msg);
        return 1;
    }
    return 0;
}

/* ----------------------------------------------------- afile at dir ---- */

/* the entries of directory path but . and .. (-1: cannot read it) */
static int entries(const char *path)
{
    DIR *d = opendir(path);
    if (!d)
        return -1;
    int n = 0;
    for (struct dirent *e; (e = readdir(d));)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    closedir(d);
    return n;
}

static int c_openat_empty_name(void)
{
    char dir[] = "/tmp/gw_hostile48.XXXXXX";
    EXPECT(mkdtemp(dir));
    const int fd = open(dir, O_RDONLY | O_DIRECTORY);
    gw_afile f;
    memset(&f, 0, sizeof f);
    gw_err e = {0};
    const int rc = gw_afile_openat(&f, fd, dir, "", &e);
    const int n = entries(dir);
    gw_afile_abort(&f);
    close(fd);
    rmdir(dir);
    EXPECT(refused(rc, &e, "an empty name names no file") && strstr(e.msg, dir));
    EXPECT(n == 0); /* no temporary made */
    return 0;
}

static int c_openat_plain(void) /* control: a name written and committed */
{
    char dir[] = "/tmp/gw_hostile48.XXXXXX", path[64];
    EXPECT(mkdtemp(dir));
    const int fd = open(dir, O_RDONLY | O_DIRECTORY);
    gw_afile f;
    memset(&f, 0, sizeof f);
    gw_err e = {0};
    int rc = gw_afile_openat(&f, fd, dir, "t.txt", &e);
    if (rc == GW_OK) {
        fputs("row\n", f.fp);
        rc = gw_afile_commit(&f, &e);
    }
    snprintf(path, sizeof path, "%s/t.txt", dir);
    char buf[16] = "";
    FILE *fp = fopen(path, "r");
    if (fp) {
        if (!fgets(buf, sizeof buf, fp))
            buf[0] = '\0';
        fclose(fp);
    }
    const int n = entries(dir);
    unlink(path);
    close(fd);
    rmdir(dir);
    if (rc != GW_OK)
        printf("status %d: %s\n", rc, e.msg);
    EXPECT(rc == GW_OK && strcmp(buf, "row\n") == 0 && n == 1);
    return 0;
}

/* ------------------------------------------ values shown as given ---- */

/* GW_EINVAL whose message holds want (the value with its digits) */
static int shown(int rc, const gw_err *e, const char *want)
{
    if (rc != GW_EINVAL || !strstr(e->msg, want)) {
        printf("status %d, message '%s' (wanted GW_EINVAL with '%s')\n", rc, e->msg, want);
        return 0;
    }
    return 1;
}

static int c_shown_criterion(void)
{
    gw_stats_table t;
    memset(&t, 0, sizeof t);
    gw_err e = {0};
    char *text = table_text("", "1", "2", "1");
    EXPECT(text && gw_stats_table_parse(text, "hand.csv", &t, &e) == GW_OK);
    free(text);
    gw_stats_groups gs;
    memset(&gs, 0, sizeof gs);
    const int rc = gw_stats_groups_make(&t, 1.0000001, &gs, &e);
    gw_stats_groups_free(&gs);
    gw_stats_table_free(&t);
    EXPECT(shown(rc, &e, "criterion: 1.0000001 is not in (0, 1]"));
    const double x[4] = {1, 1, 2, 2}, h[4] = {1, 2, 1, 2}, share[4] = {1, 0, 1, 0};
    gw_stats_diagram d;
    memset(&d, 0, sizeof d);
    const int rd = gw_stats_diagram_make(4, x, h, share, NULL, 1.0000001, &d, &e);
    gw_stats_diagram_free(&d);
    EXPECT(shown(rd, &e, "criterion: 1.0000001 is not in (0, 1]"));
    return 0;
}

static int c_shown_gravity(void)
{
    const double vimp[1] = {0.3};
    double v[1], hmm[1];
    gw_err e = {0};
    const int rc = gw_chain_falcon_speeds(vimp, 1, NULL, 0, 10000.0000001, v, hmm, &e);
    EXPECT(shown(rc, &e, "gravity: 10000.0000001 m/s^2 is outside [0, 10000]"));
    return 0;
}

static int c_shown_poisson(void)
{
    gw_material m = *gw_material_find("steel");
    m.poisson = 0.5000001;
    gw_layer_law *law = NULL;
    gw_err e = {0};
    const int rc = gw_layer_law_create(0.004, &m, 1e-3, 1e9, 0.3, &law, &e);
    gw_layer_law_free(law);
    EXPECT(shown(rc, &e, "Poisson ratio 0.5000001 is not in (-1, 0.5]"));
    return 0;
}

static int c_shown_flag(void)
{
    gw_chain_setup s;
    EXPECT(gw_chain_setup_init(&s) == GW_OK);
    gw_err e = {0};
    const int rc = gw_param_set_double(gw_chain_setup_params(), &s, "trace", 0.9999999999, &e);
    gw_chain_setup_clear(&s);
    EXPECT(shown(rc, &e, "trace: 0.9999999999 is not a flag"));
    return 0;
}

/* ---------------------------------------------------- drop result ---- */

static int c_rises_no_array(void)
{
    gw_chain_drop_result r;
    memset(&r, 0, sizeof r);
    r.n_impacts = 5;
    EXPECT(gw_chain_drop_impact_rises(&r) == 0);
    r.n_impacts = INT_MAX;
    EXPECT(gw_chain_drop_impact_rises(&r) == 0);
    return 0;
}

static int c_rises_control(void)
{
    gw_chain_drop_impact im[3];
    memset(im, 0, sizeof im);
    im[0].f_max = 1;
    im[1].f_max = 2;
    im[2].f_max = 1.5;
    gw_chain_drop_result r;
    memset(&r, 0, sizeof r);
    r.impacts = im;
    r.n_impacts = 3;
    EXPECT(gw_chain_drop_impact_rises(&r) == 1);
    return 0;
}

static const child_row rows[] = {
    {"table: the rows' closed ends taken (control)", c_ends_taken},
    {"fit: a slope beyond the doubles refused", c_fit_beyond},
    {"fit: powers of two exact, the line of test points (control)", c_fit_exact},
    {"pool: a case failing without a message", c_pool_silent},
    {"pool: a case returning status 7", c_pool_other_status},
    {"pool: a case's own message kept (control)", c_pool_message_kept},
    {"sweep: a model's run failing without a message", c_sweep_run_silent},
    {"sweep: a model's check refusing without a message", c_sweep_check_silent},
    {"afile at a directory: an empty name", c_openat_empty_name},
    {"afile at a directory: a plain name (control)", c_openat_plain},
    {"criterion 1.0000001 shown as given (groups, diagram)", c_shown_criterion},
    {"falcon gravity 10000.0000001 shown as given", c_shown_gravity},
    {"a Poisson ratio 0.5000001 shown as given", c_shown_poisson},
    {"a flag set to 0.9999999999 shown as given", c_shown_flag},
    {"drop: impacts counted without their array", c_rises_no_array},
    {"drop: rises of 1, 2, 1.5 N (control)", c_rises_control},
};

int main(void)
{
    int nfail = 0, ncases = 0;
    for (size_t r = 0; r < sizeof setting_rows / sizeof setting_rows[0]; r++) {
        setr = &setting_rows[r];
        child_casef(c_setting, &nfail, &ncases, "%s", setr->label);
    }
    child_case(rows[0].label, rows[0].fn, &nfail, &ncases); /* the control after them */
    for (size_t r = 0; r < sizeof fit_rows / sizeof fit_rows[0]; r++) {
        fitr = &fit_rows[r];
        child_casef(c_fit, &nfail, &ncases, "%s", fitr->label);
    }
    for (size_t r = 1; r < sizeof rows / sizeof rows[0]; r++)
        child_case(rows[r].label, rows[r].fn, &nfail, &ncases);
    return child_cases_end(nfail, ncases);
}
