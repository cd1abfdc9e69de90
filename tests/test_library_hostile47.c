/*
 * test_library_hostile47.c: the forty-seventh hostile pass over the library's
 * C interface (docs/library.md "The contract of every call"): the snapshot
 * writers, a count sum, the closed forms and the boundary fit.
 *   - gw_layer_write_vtk wrote its title as given into the format's one-line
 *     header: a newline in it made the file's third line the title's rest
 *     where VTK's readers want "ASCII"; a NULL title was written "(null)";
 *     a title cut at 120 bytes could end inside a UTF-8 character. The title
 *     is now one line (\n, \r, \t, \xHH as in messages), cut between
 *     characters, and a NULL title refused naming it, nothing written.
 *   - gw_layer_write_pvd wrote file names into an XML attribute as given: a
 *     '"', '&' or '<' made the collection no XML. They are written as
 *     entities; a name with a control character or a byte of no whole UTF-8
 *     character (no XML file holds them) is refused naming the snapshot,
 *     nothing written. Controls: plain and UTF-8 names as before.
 *   - gw_chain_falcon_speeds summed its two counts in an int: INT_MAX + 1
 *     overflowed (undefined; the sanitizer's report) and a wrapped total was
 *     told "no impact velocity (vimp and heights both empty)". A total above
 *     INT_MAX is refused naming n_vimp + n_heights; gw_chain_falcon_run
 *     summed its lists' counts before its range check the same way.
 *   - The closed forms of one bead on a wall (gw_chain_tau1, _dmax1, _fmax1)
 *     and gw_chain_tq_theory gave finite values outside their domain (a
 *     negative mass and K: their ratio is positive; v = -1 the overlap and
 *     force of +1 where tau_1 was NaN; a mass of 0 a zero overlap);
 *     gw_sheet_kwall a negative wall coefficient for a negative mass;
 *     gw_chain_disp_omega inf for a mass of 0. Each is NaN now, as
 *     gw_chain_kc of a negative k. Controls: the forms against their laws
 *     (the peak's elastic energy (2/5) K d^(5/2) equal to (1/2) m v^2, F =
 *     K d^(3/2), the sheet's tau_1/2 its measured tau_max(N = 1), K_eff in
 *     proportion to m).
 *   - gw_stats_b31_fit_points took a free_mask with bits of no parameter (-1,
 *     0xff: as its low four); refused naming it. Control: the fit of test
 *     points as before.
 *   - gw_param_set_double on a row that takes no number (a choice, a list, a
 *     range, a text) said so only for a value inside the row's [min, max]:
 *     "material: 1 is outside [0, 0]", "sample: 5 is outside [0, 0]",
 *     "radii: 1e+09 is outside [1e-06, 1]". Each value is now refused as
 *     "ROW: takes a KIND, not a number". Control: number rows as before.
 *   - gw_sweep_journal_append wrote a row without its newline (the next row
 *     joined it: a line no resume takes), one holding a newline (two lines)
 *     and an empty one; each is refused, nothing written. A last fsync's time
 *     (synced_ms) of NaN or after now was never synced again; it is taken as
 *     long past. Control: a row synced just now is not synced again.
 *   - gw_chain_trace_write formatted each file's name into 512 bytes and cut
 *     it there: a stem of 501 characters wrote "xstem_wall_forc" with GW_OK.
 *     The names are built in the path's room; a stem the path cannot hold is
 *     refused before any file is written. Control: a plain stem.
 *   - gw_layer_sample_format_check(NULL) was refused as
 *     "gw_layer_sample_out_check: path is NULL", naming another call.
 *   - gw_sweep_memory_check kept the jobs largest estimates by insertion
 *     into a sorted array: jobs = 1e6 over a layer grid of 1.2e6 cases ran
 *     for minutes (killed at 300 s; 5.4 s now, jobs = 4 took 6 s). A guard
 *     only (no check here may time a run): the check's answers at 1 to 1e6
 *     jobs.
 * Each case runs in its own child process (test_child.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "granwave.h"
#include "layer_test_util.h"
#include "test_child.h"

static char dir[64];

static void path_of(char *buf, size_t n, const char *name)
{
    snprintf(buf, n, "%s/%s", dir, name);
}

/* the file's text (caller frees), NULL when it is not there */
static char *slurp(const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    char *buf = calloc(1 << 16, 1);
    size_t got = buf ? fread(buf, 1, (1 << 16) - 1, fp) : 0;
    (void)got;
    fclose(fp);
    return buf;
}

/* the n-th line (from 1) of text into out, without its newline */
static int line_of(const char *text, int n, char *out, size_t size)
{
    const char *p = text;
    for (int i = 1; i < n && p; i++) {
        p = strchr(p, '\n');
        p = p ? p + 1 : NULL;
    }
    if (!p)
        return 0;
    size_t len = strcspn(p, "\n");
    if (len >= size)
        return 0;
    memcpy(out, p, len);
    out[len] = '\0';
    return 1;
}

/* ---------------------------------------------------------------- VTK ---- */

static gw_layer *three_discs(void)
{
    gw_layer_body b[3] = {
        {.x = 0.5, .y = 0.3, .r = 0.3}, {.x = 1.2, .y = 0.3, .r = 0.3}, {.x = 0.85, .y = 0.9, .r = 0.3}};
    gw_layer_params p = gw_layer_params_default();
    gw_layer *L = NULL;
    gw_err e = {0};
    if (gw_layer_create(&p, 3, b, &L, &e) != GW_OK)
        printf("gw_layer_create: %s\n", e.msg);
    return L;
}

/* the snapshot of title: GW_OK, its second line wanted (the title's part
 * before " (granwave"), its third "ASCII" and the points' count after */
static int vtk_title(const char *title, const char *want)
{
    gw_layer *L = three_discs();
    EXPECT(L);
    char path[128], line[512];
    path_of(path, sizeof path, "t.vtk");
    gw_err e = {0};
    const int rc = gw_layer_write_vtk(L, path, title, &e);
    gw_layer_free(L);
    if (rc != GW_OK) {
        printf("status %d: %s\n", rc, e.msg);
        return 1;
    }
    char *text = slurp(path);
    unlink(path);
    EXPECT(text);
    int ok = line_of(text, 2, line, sizeof line);
    char *mark = ok ? strstr(line, " (granwave ") : NULL;
    if (mark)
        *mark = '\0';
    if (!mark || strcmp(line, want) != 0) {
        printf("title line '%s', wanted '%s'\n", line, want);
        free(text);
        return 1;
    }
    ok = line_of(text, 3, line, sizeof line) && strcmp(line, "ASCII") == 0 && line_of(text, 8, line, sizeof line) &&
         strcmp(line, "POINTS 3 double") == 0;
    free(text);
    EXPECT(ok);
    return 0;
}

static int c_vtk_title_newline(void)
{
    return vtk_title("run 1\nrun 2\r\tend", "run 1\\nrun 2\\r\\tend");
}

static int c_vtk_title_escape(void)
{
    return vtk_title("a\x1b[31mred", "a\\x1b[31mred");
}

/* "a" and 100 two-byte characters: 201 bytes, cut at 120 inside the 60th */
static int c_vtk_title_utf8_cut(void)
{
    char title[256] = "a", want[256] = "a";
    for (int i = 0; i < 100; i++)
        strcat(title, "\xc3\xa9");
    for (int i = 0; i < 59; i++)
        strcat(want, "\xc3\xa9");
    return vtk_title(title, want);
}

static int c_vtk_title_plain(void) /* control */
{
    return vtk_title("layer impact, t = 0", "layer impact, t = 0");
}

static int c_vtk_title_null(void)
{
    gw_layer *L = three_discs();
    EXPECT(L);
    char path[128];
    path_of(path, sizeof path, "n.vtk");
    gw_err e = {0};
    const int rc = gw_layer_write_vtk(L, path, NULL, &e);
    gw_layer_free(L);
    EXPECT(refused(rc, &e, "title is NULL"));
    EXPECT(access(path, F_OK) != 0);
    return 0;
}

/* ---------------------------------------------------------------- PVD ---- */

static int pvd_written(const char *name, const char *attr)
{
    char path[128], want[512];
    path_of(path, sizeof path, "s.pvd");
    const char *files[2] = {"snapshot_0.vtk", name};
    const double times[2] = {0, 0.25};
    gw_err e = {0};
    const int rc = gw_layer_write_pvd(path, 2, files, times, &e);
    if (rc != GW_OK) {
        printf("status %d: %s\n", rc, e.msg);
        return 1;
    }
    char *text = slurp(path);
    unlink(path);
    EXPECT(text);
    snprintf(want, sizeof want, "    <DataSet timestep=\"0.25\" group=\"\" part=\"0\" file=\"%s\"/>\n", attr);
    const int ok = strstr(text, want) != NULL && strstr(text, "file=\"snapshot_0.vtk\"/>\n") != NULL;
    if (!ok)
        printf("pvd '%s' has no line '%s'\n", text, want);
    free(text);
    return ok ? 0 : 1;
}

static int c_pvd_entities(void)
{
    return pvd_written("a&b<\"c\">'d'.vtk", "a&amp;b&lt;&quot;c&quot;&gt;&apos;d&apos;.vtk");
}

static int c_pvd_plain(void) /* control */
{
    return pvd_written("snapshot_end.vtk", "snapshot_end.vtk");
}

static int c_pvd_utf8(void) /* control: a UTF-8 name as it is */
{
    return pvd_written("caf\xc3\xa9/end.vtk", "caf\xc3\xa9/end.vtk");
}

static int pvd_refused(const char *name, const char *what)
{
    char path[128];
    path_of(path, sizeof path, "r.pvd");
    const char *files[2] = {"snapshot_0.vtk", name};
    const double times[2] = {0, 0.25};
    gw_err e = {0};
    const int rc = gw_layer_write_pvd(path, 2, files, times, &e);
    EXPECT(refused(rc, &e, "snapshot 1"));
    EXPECT(refused(rc, &e, what));
    EXPECT(access(path, F_OK) != 0);
    return 0;
}

static int c_pvd_newline(void)
{
    return pvd_refused("b\n.vtk", "a control character at byte 2");
}

static int c_pvd_latin1(void)
{
    return pvd_refused("caf\xe9.vtk", "no whole UTF-8 character at byte 4");
}

/* ------------------------------------------------------------- counts ---- */

static int speeds_overflow(int nv, int nh)
{
    double vimp[1] = {0.3}, heights[1] = {5.1}, v[2], h[2];
    gw_err e = {0};
    const int rc = gw_chain_falcon_speeds(vimp, nv, heights, nh, 9.81, v, h, &e);
    EXPECT(refused(rc, &e, "n_vimp + n_heights"));
    return 0;
}

static int c_speeds_max_max(void)
{
    return speeds_overflow(INT_MAX, INT_MAX);
}

static int c_speeds_max_one(void)
{
    return speeds_overflow(INT_MAX, 1);
}

static int c_speeds_one_max(void)
{
    return speeds_overflow(1, INT_MAX);
}

static int c_speeds_control(void)
{
    double vimp[1] = {0.3}, heights[1] = {5.1}, v[2], h[2];
    gw_err e = {0};
    EXPECT(gw_chain_falcon_speeds(vimp, 1, heights, 1, 9.81, v, h, &e) == GW_OK);
    EXPECT(v[0] == 0.3 && isnan(h[0]) && h[1] == 5.1);
    EXPECT(fabs(v[1] - sqrt(2 * 9.81 * 5.1e-3)) <= 1e-15);
    return 0;
}

static int c_falcon_run_counts(void)
{
    gw_chain_falcon_setup s;
    EXPECT(gw_chain_falcon_setup_init(&s) == GW_OK);
    const int keep = s.heights.n;
    s.heights.n = INT_MAX;
    gw_chain_falcon_outcome o = {0};
    gw_err e = {0};
    const int rc = gw_chain_falcon_run(&s, NULL, NULL, &o, &e);
    s.heights.n = keep;
    gw_chain_falcon_outcome_free(&o);
    gw_chain_falcon_setup_clear(&s);
    EXPECT(refused(rc, &e, "heights"));
    return 0;
}

/* -------------------------------------------------------- closed forms ---- */

static int c_closed_forms_domain(void)
{
    const double bad[][3] = {{-1, -1, 0.3}, {0, 1e9, 0.3}, {1e-3, 1e9, -1}, {1e-3, -1e9, 0.3}, {1e-3, 0, 0.3},
                             {NAN, 1e9, 0.3}, {1e-3, NAN, 0.3}, {1e-3, 1e9, NAN}, {INFINITY, 1e9, 0.3}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const double m = bad[i][0], K = bad[i][1], v = bad[i][2];
        const double t = gw_chain_tau1(m, K, v), d = gw_chain_dmax1(m, K, v), f = gw_chain_fmax1(m, K, v),
                     q = gw_chain_tq_theory(m, K, v);
        if (!isnan(t) || !isnan(d) || !isnan(f) || !isnan(q)) {
            printf("m %g K %g v %g: tau1 %g dmax1 %g fmax1 %g t_q %g (wanted NaN)\n", m, K, v, t, d, f, q);
            return 1;
        }
    }
    return 0;
}

/* steel bead of 1 mm on a Hertz wall: the peak's elastic energy is the
 * kinetic one, F = K d^(3/2), tau_1 = 2.943 (5 m / 4 K)^(2/5) v^(-1/5) */
static int c_closed_forms_laws(void)
{
    const double m = 3.27e-5, K = 1.33e10;
    for (double v = 1e-3; v < 10; v *= 7.3) {
        const double d = gw_chain_dmax1(m, K, v), f = gw_chain_fmax1(m, K, v), t = gw_chain_tau1(m, K, v);
        EXPECT(fabs(0.4 * K * pow(d, 2.5) - 0.5 * m * v * v) <= 1e-12 * 0.5 * m * v * v);
        EXPECT(fabs(f - K * pow(d, 1.5)) <= 1e-12 * f);
        EXPECT(fabs(t - gw_chain_tau_constant() * pow(1.25 * m / K, 0.4) * pow(v, -0.2)) <= 1e-12 * t);
        const double tq = 2 * pow(m / K, 0.4) * pow(v, -0.2);
        EXPECT(fabs(gw_chain_tq_theory(m, K, v) - tq) <= 1e-12 * tq);
    }
    EXPECT(fabs(gw_chain_tau_constant() - 2.9432) <= 1e-4); /* (4/5) B(2/5, 1/2) */
    EXPECT(gw_chain_dmax1(m, K, 0) == 0 && isinf(gw_chain_tau1(m, K, 0))); /* at rest: the forms' limits */
    return 0;
}

static int c_sheet_kwall_domain(void)
{
    const gw_sheet *s = gw_sheet_find("brass");
    EXPECT(s);
    const double bad[] = {-1, 0, -0.0, NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        if (!isnan(gw_sheet_kwall(s, bad[i]))) {
            printf("gw_sheet_kwall(brass, %g) = %g (wanted NaN)\n", bad[i], gw_sheet_kwall(s, bad[i]));
            return 1;
        }
    return 0;
}

/* control: every sheet's K_eff gives its measured tau_max(N = 1) as tau_1 / 2
 * at v = sqrt(2 g 2.9 mm), and grows in proportion to m */
static int c_sheet_kwall_law(void)
{
    const double m = 3.27e-5, v = sqrt(2 * GW_CHAIN_G_EARTH * 2.9e-3);
    int seen = 0;
    for (int i = 0; i < gw_sheet_count(); i++) {
        const gw_sheet *s = gw_sheet_get(i);
        if (!s || !(s->tau_max1_us > 0))
            continue;
        const double K = gw_sheet_kwall(s, m);
        EXPECT(K > 0);
        EXPECT(fabs(0.5 * gw_chain_tau1(m, K, v) - 1e-6 * s->tau_max1_us) <= 1e-12 * 1e-6 * s->tau_max1_us);
        EXPECT(fabs(gw_sheet_kwall(s, 2 * m) - 2 * K) <= 1e-14 * K);
        seen++;
    }
    EXPECT(seen >= 3);
    return 0;
}

static int c_disp_omega(void)
{
    EXPECT(isnan(gw_chain_disp_omega(1e6, 0, 1)));
    EXPECT(isnan(gw_chain_disp_omega(1e6, -1, 1)));
    EXPECT(isnan(gw_chain_disp_omega(-1e6, 1e-3, 1)));
    EXPECT(isnan(gw_chain_disp_omega(1e6, NAN, 1)));
    /* control: the zone edge qa = pi at 2 sqrt(kappa/m) */
    EXPECT(fabs(gw_chain_disp_omega(1e6, 1e-3, acos(-1.0)) - 2 * sqrt(1e9)) <= 1e-12 * 2 * sqrt(1e9));
    return 0;
}

/* ------------------------------------------------------------- B.31 fit ---- */

static const double fx[6] = {1, 1.5, 2, 3, 4, 5}, fh[6] = {9, 4.2, 3.1, 2.6, 2.7, 3};
static const gw_stats_b31 fstart = {.offset = 0, .beta = 1, .a_over_b = 1, .tan_gamma = 1};

static int fit_refused(int mask, const char *what)
{
    gw_stats_b31_fit f;
    gw_err e = {0};
    const int rc = gw_stats_b31_fit_points(fx, fh, 6, &fstart, mask, &f, &e);
    EXPECT(refused(rc, &e, what));
    return 0;
}

static int c_fit_mask_all_bits(void)
{
    return fit_refused(-1, "free_mask 0xffffffff");
}

static int c_fit_mask_byte(void)
{
    return fit_refused(0xff, "free_mask 0xff");
}

static int c_fit_mask_high(void)
{
    return fit_refused(16 | GW_STATS_B31_BETA | GW_STATS_B31_AB, "free_mask 0x16");
}

static int c_fit_control(void)
{
    gw_stats_b31_fit f;
    gw_err e = {0};
    EXPECT(gw_stats_b31_fit_points(fx, fh, 6, &fstart, GW_STATS_B31_BETA | GW_STATS_B31_AB, &f, &e) == GW_OK);
    EXPECT(f.converged && f.p.beta >= 0 && f.p.beta <= 1 && f.p.a_over_b > 0 && isfinite(f.rms));
    /* the fitted curve's residuals: their rms as reported */
    double ss = 0;
    for (int i = 0; i < 6; i++) {
        const double r = gw_stats_b31_eval(&f.p, fx[i]) - fh[i];
        ss += r * r;
    }
    EXPECT(fabs(sqrt(ss / 6) - f.rms) <= 1e-9 * (1 + f.rms));
    return 0;
}

/* ------------------------------------------------- gw_param_set_double ---- */

/* each v refused as the row's kind: "ROW: takes a KIND, not a number" */
static int set_double_refused(const gw_param *t, void *obj, const char *row, const char *kind, const double *vs,
                              int nv)
{
    char want[128];
    snprintf(want, sizeof want, "%s: takes a %s, not a number", row, kind);
    for (int i = 0; i < nv; i++) {
        gw_err e = {0};
        const int rc = gw_param_set_double(t, obj, row, vs[i], &e);
        if (!refused(rc, &e, want)) {
            printf("  (v = %g)\n", vs[i]);
            return 1;
        }
    }
    return 0;
}

/* set_double_refused over a setup of kind k (made, then cleared) */
typedef enum { SETUP_CHAIN, SETUP_FALCON, SETUP_IMPACT } setup_kind;

static int set_double_case(setup_kind k, const char *row, const char *kind, const double *vs, int nv)
{
    union {
        gw_chain_setup chain;
        gw_chain_falcon_setup falcon;
        gw_layer_impact_setup impact;
    } s;
    const gw_param *t = NULL;
    switch (k) {
    case SETUP_CHAIN: EXPECT(gw_chain_setup_init(&s.chain) == GW_OK); t = gw_chain_setup_params(); break;
    case SETUP_FALCON:
        EXPECT(gw_chain_falcon_setup_init(&s.falcon) == GW_OK);
        t = gw_chain_falcon_setup_params();
        break;
    case SETUP_IMPACT:
        EXPECT(gw_layer_impact_setup_init(&s.impact) == GW_OK);
        t = gw_layer_impact_setup_params();
        break;
    }
    const int rc = set_double_refused(t, &s, row, kind, vs, nv);
    switch (k) {
    case SETUP_CHAIN: gw_chain_setup_clear(&s.chain); break;
    case SETUP_FALCON: gw_chain_falcon_setup_clear(&s.falcon); break;
    case SETUP_IMPACT: gw_layer_impact_setup_clear(&s.impact); break;
    }
    return rc;
}

static int c_set_double_choice(void)
{
    return set_double_case(SETUP_CHAIN, "material", "choice", (const double[]){0, 1, 1e9}, 3);
}

static int c_set_double_list(void)
{
    return set_double_case(SETUP_CHAIN, "radii", "list", (const double[]){0, 1e-3, 1e9}, 3);
}

static int c_set_double_range(void)
{
    return set_double_case(SETUP_FALCON, "n", "range", (const double[]){5, 1e12}, 2);
}

static int c_set_double_text(void)
{
    return set_double_case(SETUP_IMPACT, "sample", "text", (const double[]){0, 5}, 2);
}

static int c_set_double_numbers(void) /* control: the number rows take their numbers */
{
    gw_chain_setup s;
    EXPECT(gw_chain_setup_init(&s) == GW_OK);
    gw_err e = {0};
    const gw_param *t = gw_chain_setup_params();
    int ok = gw_param_set_double(t, &s, "vimp", 0.25, &e) == GW_OK && s.vimp == 0.25 &&
             gw_param_set_double(t, &s, "n", 7, &e) == GW_OK && s.n == 7 &&
             gw_param_set_double(t, &s, "trace", 1, &e) == GW_OK && s.trace == 1 &&
             refused(gw_param_set_double(t, &s, "vimp", 1e9, &e), &e, "vimp: 1e+09 is outside");
    gw_chain_setup_clear(&s);
    EXPECT(ok);
    return 0;
}

/* -------------------------------------------------- the journal's append ---- */

static long file_size(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

/* each row refused naming why, the file as it was; then a row of its own */
static int c_append_not_one_line(void)
{
    char path[128];
    path_of(path, sizeof path, "journal.csv");
    const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    EXPECT(fd >= 0);
    const char *rows[] = {"0,0.1,1,2,0123456789abcdef,01234567", "0,0.1\n1,2\n", "", "\n"};
    const char *why[] = {"(no newline)", "(a newline inside it)", "(empty)", "(an empty line)"};
    int bad = 0;
    for (int i = 0; i < 4 && !bad; i++) {
        gw_err e = {0};
        bad = !refused(gw_sweep_journal_append(fd, rows[i], NULL, &e), &e, why[i]) || file_size(path) != 0;
    }
    gw_err e = {0};
    const int rc = bad ? GW_OK : gw_sweep_journal_append(fd, "0,0.1,1\n", NULL, &e);
    close(fd);
    char *text = slurp(path);
    unlink(path);
    EXPECT(!bad && rc == GW_OK && text && strcmp(text, "0,0.1,1\n") == 0);
    free(text);
    return 0;
}

/* a last fsync's time that is NaN or after now is no time: the row synced
 * (the time then now's), where a NaN was never synced again */
static int c_append_sync_time(void)
{
    char path[128];
    path_of(path, sizeof path, "journal.csv");
    const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    EXPECT(fd >= 0);
    const double odd[] = {NAN, 1e300, -INFINITY};
    int ok = 1;
    for (int i = 0; i < 3 && ok; i++) {
        double t = odd[i];
        gw_err e = {0};
        const double before = gw_clock_ms();
        ok = gw_sweep_journal_append(fd, "1,0.2,3\n", &t, &e) == GW_OK && t >= before && t <= gw_clock_ms();
        if (!ok)
            printf("synced_ms %g: now %g (at %g)\n", odd[i], t, before);
    }
    /* control: synced just now, not again */
    double t = gw_clock_ms();
    const double t0 = t;
    gw_err e = {0};
    ok = ok && gw_sweep_journal_append(fd, "2,0.3,4\n", &t, &e) == GW_OK && t == t0;
    close(fd);
    unlink(path);
    EXPECT(ok);
    return 0;
}

/* ------------------------------------------------------ the trace's names ---- */

/* a one-bead trace of 20 samples written under stem into a fresh dir: the
 * status, and in *names the directory's entries as "a|b|c" sorted */
static int trace_written(const char *stem, char *names, size_t n, gw_err *e)
{
    char sub[128];
    path_of(sub, sizeof sub, "tr");
    mkdir(sub, 0700);
    gw_chain_trace tr;
    gw_chain_trace_init(&tr, 1);
    const double y[2] = {0, 0};
    for (int k = 0; k < 20; k++)
        gw_chain_trace_sample(&tr, k * 1e-6, y, 1.0, 0);
    const int rc = gw_chain_trace_write(&tr, sub, stem, "a header", e);
    gw_chain_trace_free(&tr);
    char cmd[512];
    snprintf(cmd, sizeof cmd, "ls %s | sort | tr '\\n' '|'; rm -rf %s", sub, sub);
    FILE *p = popen(cmd, "r");
    names[0] = '\0';
    if (p) {
        size_t got = fread(names, 1, n - 1, p);
        names[got] = '\0';
        pclose(p);
    }
    return rc;
}

/* 501 characters ("./" 248 times and "xstem"): the wall force was written as
 * "xstem_wall_forc" with GW_OK (the name cut at 512 bytes) */
static int c_trace_long_stem(void)
{
    char stem[600] = "", names[512];
    for (int i = 0; i < 248; i++)
        strcat(stem, "./");
    strcat(stem, "xstem");
    gw_err e = {0};
    EXPECT(trace_written(stem, names, sizeof names, &e) == GW_OK);
    const char *want = GW_HAVE_HDF5 ? "xstem.h5|xstem_beads.csv|xstem_wall_force.csv|"
                                    : "xstem_beads.csv|xstem_wall_force.csv|";
    if (strcmp(names, want) != 0) {
        printf("files '%s', wanted '%s'\n", names, want);
        return 1;
    }
    return 0;
}

/* a stem the path cannot hold: refused naming it, nothing written (the
 * files were written under names cut at 512 bytes) */
static int c_trace_stem_beyond_path(void)
{
    static char stem[4200];
    stem[0] = '\0';
    for (int i = 0; i < 2040; i++)
        strcat(stem, "./");
    strcat(stem, "x");
    char names[512];
    gw_err e = {0};
    const int rc = trace_written(stem, names, sizeof names, &e);
    EXPECT(refused(rc, &e, "output path too long for the trace's file"));
    if (names[0]) {
        printf("files '%s' written\n", names);
        return 1;
    }
    return 0;
}

static int c_trace_plain_stem(void) /* control */
{
    char names[512];
    gw_err e = {0};
    EXPECT(trace_written("chain", names, sizeof names, &e) == GW_OK);
    EXPECT(strcmp(names, GW_HAVE_HDF5 ? "chain.h5|chain_beads.csv|chain_wall_force.csv|"
                                      : "chain_beads.csv|chain_wall_force.csv|") == 0);
    return 0;
}

static int c_format_check_null(void)
{
    gw_err e = {0};
    EXPECT(refused(gw_layer_sample_format_check(NULL, &e), &e, "gw_layer_sample_format_check: path is NULL"));
    EXPECT(refused(gw_layer_sample_out_check(NULL, "out", &e), &e, "gw_layer_sample_out_check: path is NULL"));
    return 0;
}

/* ----------------------------------------------------- the memory check ---- */

/* A guard (the fault was time: a layer grid of 1.2e6 cases checked for jobs =
 * 1e6 ran for minutes, the largest estimates kept by insertion into a sorted
 * array; they are kept in a heap now): over 6200 cases of three discs, given
 * in an order whose estimates rise and fall, the check at jobs 1, 7, 900,
 * 6200 and 1e6 gives the jobs that fit and names the largest case as the
 * estimates sorted here do. */
typedef struct est_at {
    double b;
    long k;
} est_at;

static int est_cmp(const void *pa, const void *pb)
{
    const est_at *a = pa, *c = pb;
    return a->b > c->b ? -1 : a->b < c->b ? 1 : (a->k > c->k) - (a->k < c->k);
}

static int c_memory_check_jobs(void)
{
    char path[128];
    path_of(path, sizeof path, "three.txt");
    gw_layer_sample smp = test_three_discs();
    gw_err e = {0};
    EXPECT(gw_layer_sample_write(&smp, path, NULL, &e) == GW_OK);
    int nm = 0;
    const gw_sweep_model *const *ms = gw_sweep_models(&nm), *m = NULL;
    for (int i = 0; i < nm; i++)
        if (strcmp(ms[i]->name, "layer") == 0)
            m = ms[i];
    EXPECT(m && m->memory);
    char text[1024];
    snprintf(text, sizeof text, "[sweep]\nmodel = layer\n[grid]\nrb-rm = 16, 1, 1.5, 2, 2.5, 3, 3.5, 4, 4.5, 5, "
             "5.5, 6, 6.5, 7, 7.5, 8, 8.5, 9, 9.5, 10, 10.5, 11, 11.5, 12, 12.5, 13, 13.5, 14, 14.5, 15, 15.5\n"
             "rings = 1:200\n[params]\nsample = %s\nt-max = 0.01\n", path);
    gw_sweep_config cfg = {0};
    const gw_sweep_model *got = NULL;
    EXPECT(gw_sweep_config_read_string(text, "grid", &m, 1, &cfg, &got, &e) == GW_OK);
    EXPECT(cfg.ncases == 6200);
    /* the reference: every case's estimate, sorted by size then case, and
     * the jobs whose largest estimates fit 80 % of the memory available */
    static est_at est[6200];
    const int nk = cfg.ngrid + cfg.nparams;
    for (long k = 0; k < 6200; k++) {
        const char *names[2 * GW_SWEEP_MAX_KEYS], *vals[2 * GW_SWEEP_MAX_KEYS];
        gw_sweep_case(&cfg, k, names, vals);
        est[k].k = k;
        EXPECT(m->memory(nk, names, vals, &est[k].b, &e) == GW_OK);
    }
    qsort(est, 6200, sizeof est[0], est_cmp);
    const char *what = "";
    const double avail = gw_memory_available(&what);
    const long jobs[] = {1, 7, 900, 6200, 1000000};
    int ok = est[0].b > est[6199].b; /* estimates that differ */
    for (int i = 0; i < 5 && ok; i++) {
        const long n = jobs[i] < 6200 ? jobs[i] : 6200;
        long fit = 0;
        double sum = 0;
        for (long j = 0; j < n; j++) {
            sum += est[j].b;
            if (sum <= 0.8 * avail && est[0].b <= 0.8 * avail)
                fit = j + 1;
        }
        long most = -1;
        e.msg[0] = '\0';
        const int rc = gw_sweep_memory_check(&cfg, m, jobs[i], 0, &most, &e);
        char largest[64];
        snprintf(largest, sizeof largest, "(the largest, case %ld,", est[0].k);
        ok = most == fit && (fit == n ? rc == GW_OK : rc == GW_EINVAL && strstr(e.msg, largest) != NULL);
        if (!ok)
            printf("jobs %ld: status %d, most %ld (wanted %ld, %s): %s\n", jobs[i], rc, most, fit, largest, e.msg);
    }
    gw_sweep_config_free(&cfg);
    unlink(path);
    EXPECT(ok);
    return 0;
}

static const child_row rows[] = {
    {"vtk title with a newline, CR and tab: one line", c_vtk_title_newline},
    {"vtk title with an escape sequence: one line", c_vtk_title_escape},
    {"vtk title cut between UTF-8 characters", c_vtk_title_utf8_cut},
    {"vtk plain title (control)", c_vtk_title_plain},
    {"vtk NULL title refused, nothing written", c_vtk_title_null},
    {"pvd name with & < > \" ': entities", c_pvd_entities},
    {"pvd plain name (control)", c_pvd_plain},
    {"pvd UTF-8 name (control)", c_pvd_utf8},
    {"pvd name with a newline refused", c_pvd_newline},
    {"pvd Latin-1 name refused", c_pvd_latin1},
    {"falcon speeds INT_MAX + INT_MAX", c_speeds_max_max},
    {"falcon speeds INT_MAX + 1", c_speeds_max_one},
    {"falcon speeds 1 + INT_MAX", c_speeds_one_max},
    {"falcon speeds 1 + 1 (control)", c_speeds_control},
    {"falcon run with heights.n INT_MAX", c_falcon_run_counts},
    {"closed forms outside their domain: NaN", c_closed_forms_domain},
    {"closed forms against their laws (control)", c_closed_forms_laws},
    {"sheet K_eff of a mass not > 0: NaN", c_sheet_kwall_domain},
    {"sheet K_eff against tau_max(N = 1) (control)", c_sheet_kwall_law},
    {"dispersion omega of a mass not > 0: NaN", c_disp_omega},
    {"B.31 fit mask -1", c_fit_mask_all_bits},
    {"B.31 fit mask 0xff", c_fit_mask_byte},
    {"B.31 fit mask with bit 16", c_fit_mask_high},
    {"B.31 fit of test points (control)", c_fit_control},
    {"set_double on a choice row", c_set_double_choice},
    {"set_double on a list row", c_set_double_list},
    {"set_double on a range row", c_set_double_range},
    {"set_double on a text row", c_set_double_text},
    {"set_double on number rows (control)", c_set_double_numbers},
    {"journal append of a row that is not one line", c_append_not_one_line},
    {"journal append with a last fsync of NaN, 1e300, -inf", c_append_sync_time},
    {"trace written under a stem of 501 characters", c_trace_long_stem},
    {"trace stem beyond the path's room refused", c_trace_stem_beyond_path},
    {"trace under a plain stem (control)", c_trace_plain_stem},
    {"sample format check of NULL named as itself", c_format_check_null},
    {"memory check at jobs 1 to 1e6 against the sorted estimates (guard)", c_memory_check_jobs},
};

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/gw_hostile47.XXXXXX");
    if (!mkdtemp(dir)) {
        printf("mkdtemp failed\n");
        return 1;
    }
    const int rc = child_cases_run(rows, sizeof rows / sizeof rows[0]);
    rmdir(dir);
    return rc;
}
