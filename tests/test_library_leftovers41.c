/*
 * test_library_leftovers41.c: what the last sessions left in the library's
 * public calls (docs/library.md "The contract of every call"), each case in
 * its own child process (test_child.h):
 *   - gw_chain_falcon_analyse refused a NULL argument, N < 1, n_lo > n_hi
 *     and n_hi = INT_MAX with GW_EINVAL and no word (it has no error
 *     argument): gw_chain_falcon_analyse_check names each, in one line, and
 *     the analysis refuses exactly those (its fit untouched).
 *   - numbers in data files read with strtod took hexadecimal (a text
 *     sample's "0x1p-2" was 0.25, in its header, its particles and its
 *     springs; a layer-stats table's cells and params alike), where the
 *     program's options refuse it: each is refused naming the file, the line
 *     and the field (GW_EFORMAT). Control: the same files in decimal.
 *   - gw_layer_advance(L, 1e300) ran for as long as the solver's step limit
 *     let it (verlet at 1e-5 s: 1e7 steps, then again after every event);
 *     a tout more than 1e4 s ahead, or a fixed step's count or work past
 *     1e9 steps or 1e10 particle-steps, is refused before any step (the
 *     layer's time unchanged). Control: a short advance runs.
 *   - gw_layer_rings with a width of 0, -1, NaN or inf filled zeros or NaN
 *     without a word: gw_layer_rings_check names w, and the void call fills
 *     NaN. Control: a width of 0.25 m counts the discs' contacts.
 *   - gw_fnv1a64_stream read /dev/zero for 4 GiB before refusing it: a
 *     stream of no regular file is refused before a byte is read (under
 *     1 MiB, /proc/self/io). Control: a regular file from its start and from
 *     its middle, as FNV-1a 64 of its bytes.
 *   - (an HDF5 build) a hand-made superblock claiming an end of 64 MiB in
 *     front of 64 MiB of written zeros agreed with its size and was hashed
 *     whole before HDF5 refused it: refused at open, naming the root group
 *     the superblock points to, under 1 MiB read. Control: a sample
 *     gw_layer_sample_write wrote is read.
 *   - gw_solver_drive with a NaN t_end returned GW_OK having run nothing, a
 *     NaN dt_out ran as 0: each is GW_EINVAL naming the field. Control: a
 *     decay y' = -y driven to t = 1 with outputs every 0.25 s ends at
 *     exp(-1) to 1e-6.
 *   - gw_chain_wall_spectrum took a NaN dt as "the median spacing" and a NaN
 *     or infinite f_min as no peak (f_peak NaN, GW_OK): each is GW_EINVAL
 *     naming it. Control: a 1 kHz sine sampled every 10 us over 20 ms peaks
 *     at 1 kHz to 1 %.
 * Built with -DGW_TEST_BEFORE, the new checks are given the parent's
 * behaviour (the status of the old call, no message) so that the test can
 * run against the code before.
 */
#define _GNU_SOURCE
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "granwave.h"
#include "gw_test_cases.h"
#include "layer_test_util.h"
#include "test_child.h"

#ifdef GW_TEST_BEFORE
/* the parent's behaviour: the call's status, no message */
static int gw_chain_falcon_analyse_check(const gw_chain_params *p, const gw_chain_result *res, int n_lo, int n_hi,
                                         const gw_chain_falcon_fit *a, gw_err *err)
{
    gw_chain_falcon_fit f;
    (void)a, (void)err;
    return n_hi - n_lo > 64 ? GW_EINVAL : gw_chain_falcon_analyse(p, 0.3, res, n_lo, n_hi, a ? &f : NULL);
}
static int gw_layer_rings_check(const gw_layer *L, double cx, double cy, double w, int nring, const double *kinetic,
                                const double *strain, const double *coord, gw_err *err)
{
    (void)L, (void)cx, (void)cy, (void)w, (void)nring, (void)kinetic, (void)strain, (void)coord, (void)err;
    return GW_OK;
}
#endif

static char dir[64];

static int write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    return f && fputs(text, f) >= 0 && fclose(f) == 0;
}

/* ------------------------------------------------------ falcon analyse ---- */

static gw_chain_result fres[8];

static int falcon_named(const gw_chain_params *p, const gw_chain_result *res, int n_lo, int n_hi, int with_a,
                        const char *what)
{
    gw_chain_falcon_fit a;
    memset(&a, 0x5a, sizeof a);
    gw_err e = {0};
    EXPECT(refused(gw_chain_falcon_analyse_check(p, res, n_lo, n_hi, with_a ? &a : NULL, &e), &e, what));
    EXPECT(strstr(e.msg, "gw_chain_falcon_analyse") != NULL);
    /* the analysis refuses the same, a untouched */
    EXPECT(gw_chain_falcon_analyse(p, 0.3, res, n_lo, n_hi, with_a ? &a : NULL) == GW_EINVAL);
    const unsigned char *b = (const unsigned char *)&a;
    for (size_t i = 0; i < sizeof a; i++)
        EXPECT(b[i] == 0x5a);
    return 0;
}

static int c_falcon_null(void)
{
    gw_chain_params p = gw_chain_params_default();
    EXPECT(falcon_named(NULL, fres, 1, 3, 1, "p is NULL") == 0);
    EXPECT(falcon_named(&p, NULL, 1, 3, 1, "res is NULL") == 0);
    EXPECT(falcon_named(&p, fres, 1, 3, 0, "a is NULL") == 0);
    return 0;
}

static int c_falcon_sizes(void)
{
    gw_chain_params p = gw_chain_params_default();
    EXPECT(falcon_named(&p, fres, 0, 3, 1, "n_lo = 0") == 0);
    EXPECT(falcon_named(&p, fres, -3, -1, 1, "n_lo = -3") == 0);
    EXPECT(falcon_named(&p, fres, 5, 3, 1, "n_lo = 5 > n_hi = 3") == 0);
    EXPECT(falcon_named(&p, fres, 1, INT_MAX, 1, "n_hi = 2147483647") == 0);
    return 0;
}

static int c_falcon_control(void)
{
    gw_chain_params p = gw_chain_params_default();
    gw_chain_result res[4];
    memset(res, 0, sizeof res);
    for (int n = 1; n <= 4; n++)
        res[n - 1].tau_n = 4e-5 + (n - 1) * 2.5e-5, res[n - 1].f_max = 1;
    gw_err e = {0};
    gw_chain_falcon_fit a;
    EXPECT(gw_chain_falcon_analyse_check(&p, res, 1, 4, &a, &e) == GW_OK && e.msg[0] == '\0');
    EXPECT(gw_chain_falcon_analyse(&p, 0.3, res, 1, 4, &a) == GW_OK);
    EXPECT(fabs(a.fit.c1 - 2.5e-5) <= 1e-12 * 2.5e-5 && a.n_decided == 4);
    return 0;
}

/* ---------------------------------------------- hexadecimal in data files ---- */


/* three discs in a box 1 m wide, in text; TOKEN (when given) replaced by BY */
static const char sample_text[] = "granwave-layer-sample 1\n"
                                  "width 1\n"
                                  "rm 0.1\n"
                                  "volume_ratio 1\n"
                                  "n 3\n"
                                  "0.3 0.1 0.1\n"
                                  "0.5 0.1 0.1\n"
                                  "0.7 0.125 0.1\n";

static int sample_with(const char *path, const char *token, const char *by)
{
    char text[1024];
    const char *at = token ? strstr(sample_text, token) : NULL;
    if (token && !at)
        return 0;
    if (!at)
        return write_text(path, sample_text);
    snprintf(text, sizeof text, "%.*s%s%s", (int)(at - sample_text), sample_text, by, at + strlen(token));
    return write_text(path, text);
}

static int hex_refused(const char *token, const char *by, const char *line, const char *field)
{
    char path[128];
    snprintf(path, sizeof path, "%s/hex.txt", dir);
    EXPECT(sample_with(path, token, by));
    gw_layer_sample s;
    gw_err e = {0};
    const int rc = gw_layer_sample_read(path, &s, &e);
    if (rc != GW_EFORMAT || !strstr(e.msg, path) || !strstr(e.msg, line) || !strstr(e.msg, field) ||
        !strstr(e.msg, "not a decimal number")) {
        printf("status %d, '%s' (wanted GW_EFORMAT naming %s, %s and 'not a decimal number')\n", rc, e.msg, line,
               field);
        if (rc == GW_OK)
            gw_layer_sample_free(&s);
        return 1;
    }
    unlink(path);
    return 0;
}

/* the sample's TOKEN written BY, refused naming the line and the field */
typedef struct hex_row {
    const char *label, *token, *by, *line, *field;
} hex_row;

static const hex_row hex_rows[] = {
    {"text sample: hexadecimal width", "width 1\n", "width 0x1p0\n", "line 2", "width '0x1p0'"},
    {"text sample: hexadecimal x", "0.5 0.1 0.1", "0x1p-1 0.1 0.1", "line 7", "x '0x1p-1' of particle 2"},
    {"text sample: hexadecimal y", "0.7 0.125 0.1", "0.7 0x1p-3 0.1", "line 8", "y '0x1p-3' of particle 3"},
    {"text sample: hexadecimal r", "0.3 0.1 0.1", "0.3 0.1 0X.CCCCCCCCCCCD0P-3", "line 6", "r '0X.CCCCCCCCCCCD0P-3'"},
};
static const hex_row *hexr;

static int c_hex(void)
{
    return hex_refused(hexr->token, hexr->by, hexr->line, hexr->field);
}

static int c_hex_control(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/dec.txt", dir);
    EXPECT(sample_with(path, NULL, NULL));
    gw_layer_sample s;
    gw_err e = {0};
    const int rc = gw_layer_sample_read(path, &s, &e);
    if (rc != GW_OK)
        printf("read: %s\n", e.msg);
    EXPECT(rc == GW_OK && s.n == 3 && s.width == 1 && s.x[1] == 0.5 && s.y[2] == 0.125);
    gw_layer_sample_free(&s);
    unlink(path);
    return 0;
}

/* a layer-stats table as a sweep writes one (four cases over rb-rm and
 * height-rm), its param vi, rb-rm of case 2 and e_n of case 1 given */
static int table_with(const char *path, const char *param, const char *rb, const char *col)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return 0;
    fprintf(f, "# param vi = %s\ncase,rb-rm,height-rm,point,x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,"
            "penetration,penetration_rm,dissipated_first_contact,block_loss_first_contact,energy_error,"
            "wave_speed,t_end,steps\n", param);
    for (int k = 0; k < 4; k++)
        fprintf(f, "%d,%s,%d,0,0,%d,%s,0.3,10,20,2.4,6,0.1,0.5,0.001,0.5,1e-06,nan,0.01,100\n", k,
                k == 2 ? rb : "1.5", 3 + 3 * k, k < 2, k == 1 ? col : "0.3");
    return fclose(f) == 0;
}

static int table_case(const char *param, const char *rb, const char *col, const char *named)
{
    char path[128];
    snprintf(path, sizeof path, "%s/t.csv", dir);
    EXPECT(table_with(path, param, rb, col));
    gw_stats_table t;
    gw_err e = {0};
    const int rc = gw_stats_table_read(path, &t, &e);
    if (!named) {
        if (rc != GW_OK)
            printf("table read: %s\n", e.msg);
        EXPECT(rc == GW_OK && t.nrows == 4);
        gw_stats_table_free(&t);
    } else {
        if (rc != GW_EFORMAT || !strstr(e.msg, path) || !strstr(e.msg, named) ||
            !strstr(e.msg, "not a decimal number")) {
            printf("status %d, '%s' (wanted GW_EFORMAT naming %s and 'not a decimal number')\n", rc, e.msg, named);
            if (rc == GW_OK)
                gw_stats_table_free(&t);
            return 1;
        }
    }
    unlink(path);
    return 0;
}

/* the table with its param vi, rb-rm of case 2 and e_n of case 1 as given:
 * refused naming NAMED, or read (NULL: the control) */
typedef struct table_row {
    const char *label, *param, *rb, *col, *named;
} table_row;

static const table_row table_rows[] = {
    {"layer-stats table: hexadecimal param", "0x14", "2", "0.3", ":1: param vi: '0x14'"},
    {"layer-stats table: hexadecimal grid cell", "20", "0x1p1", "0.3", ":5: grid key rb-rm: '0x1p1'"},
    {"layer-stats table: hexadecimal column cell", "20", "2", "0x1.3333333333333p-2", ":4: column e_n"},
    {"layer-stats table in decimal (control)", "20", "2", "0.3", NULL},
};
static const table_row *tabr;

static int c_table(void)
{
    return table_case(tabr->param, tabr->rb, tabr->col, tabr->named);
}

/* --------------------------------------------------------- layer advance ---- */

/* three discs at rest on the floor of a box 1 m wide, started (gw_test_cases.h) */
static gw_layer *three_started(const gw_solver_type *type, double dt)
{
    return test_three_layer(0, type, dt);
}

static int advance_refused(const gw_solver_type *type, double dt, double tout, const char *what)
{
    gw_layer *L = three_started(type, dt);
    EXPECT(L != NULL);
    gw_err e = {0};
    const int rc = gw_layer_advance(L, tout, &e);
    const int ok = test_refused_or_ok(rc, &e, what) && gw_layer_time(L) == 0;
    if (!ok)
        printf("t = %g s after the call\n", gw_layer_time(L));
    gw_layer_free(L);
    EXPECT(ok);
    return 0;
}

/* the layer started with a solver at a step, advanced to tout: refused naming WHAT, t still 0 */
typedef struct advance_row {
    const char *label;
    const gw_solver_type *const *type; /* the library's solver variable (not a constant) */
    double dt, tout;
    const char *what;
} advance_row;

static const advance_row advance_rows[] = {
    {"layer advance to 1e300 s (verlet)", &gw_solver_verlet, 1e-5, 1e300, "tout 1e+300 s"},
    {"layer advance to 1e300 s (cvode)", &gw_solver_cvode, 0, 1e300, "more than the 10000 s one call advances"},
    {"layer advance 2e4 s ahead (rk4)", &gw_solver_rk4, 1e-3, 2e4, "more than the 10000 s one call advances"},
    /* rk4 at 1e-9 s to 2 s: 2e9 steps */
    {"layer advance of 2e9 rk4 steps", &gw_solver_rk4, 1e-9, 2, "2e+09 rk4 steps"},
};
static const advance_row *advr;

static int c_advance(void)
{
    return advance_refused(*advr->type, advr->dt, advr->tout, advr->what);
}

static int c_advance_control(void)
{
    gw_layer *L = three_started(gw_solver_verlet, 1e-5);
    EXPECT(L != NULL);
    gw_err e = {0};
    const int rc = gw_layer_advance(L, 1e-3, &e);
    const double t = gw_layer_time(L);
    gw_layer_stats st;
    gw_layer_get_stats(L, &st);
    gw_layer_free(L);
    if (rc != GW_OK)
        printf("advance: %s\n", e.msg);
    EXPECT(rc == GW_OK && fabs(t - 1e-3) <= 1e-15 && st.steps >= 99 && st.steps <= 101);
    return 0;
}

/* ----------------------------------------------------------------- rings ---- */

static int rings_refused(double w)
{
    gw_layer *L = three_started(gw_solver_verlet, 1e-5);
    EXPECT(L != NULL);
    double k[4], s[4], c[4];
    gw_err e = {0};
    char what[64];
    snprintf(what, sizeof what, "ring width w = %g m", w);
    const int ok = test_refused_or_ok(gw_layer_rings_check(L, 0.5, 0.1, w, 4, k, s, c, &e), &e, what);
    gw_layer_rings(L, 0.5, 0.1, w, 4, k, s, c);
    gw_layer_free(L);
    EXPECT(ok);
    for (int i = 0; i < 4; i++)
        EXPECT(isnan(k[i]) && isnan(s[i]) && isnan(c[i]));
    return 0;
}

typedef struct rings_row {
    const char *label;
    double w;
} rings_row;

static const rings_row rings_rows[] = {
    {"rings of width 0", 0}, {"rings of width -1", -1}, {"rings of width NaN", NAN}, {"rings of width inf", INFINITY},
};
static const rings_row *ringr;

static int c_rings(void)
{
    return rings_refused(ringr->w);
}

static int c_rings_control(void)
{
    gw_layer *L = three_started(gw_solver_verlet, 1e-5);
    EXPECT(L != NULL);
    double k[4], s[4], c[4];
    gw_err e = {0};
    EXPECT(gw_layer_rings_check(L, 0.5, 0.1, 0.15, 4, k, s, c, &e) == GW_OK && e.msg[0] == '\0');
    gw_layer_rings(L, 0.5, 0.1, 0.15, 4, k, s, c);
    gw_layer_free(L);
    /* the middle disc in ring 0, the outer two at 0.2 m in ring 1; each on
     * the floor, no disc touching another (1e-9 m apart): 1 contact each */
    if (!(k[0] == 0 && k[1] == 0 && c[0] == 1 && c[1] == 1 && isnan(c[2]) && isnan(c[3])))
        printf("kinetic %g %g, coordination %g %g %g %g\n", k[0], k[1], c[0], c[1], c[2], c[3]);
    EXPECT(k[0] == 0 && k[1] == 0 && c[0] == 1 && c[1] == 1 && isnan(c[2]) && isnan(c[3])); /* no disc: 0 / 0 */
    return 0;
}

/* -------------------------------------------------------- stream hashes ---- */

static int c_stream_dev_zero(void)
{
    FILE *f = fopen("/dev/zero", "rb");
    EXPECT(f != NULL);
    unsigned long long h = 7;
    const long long r0 = test_bytes_read();
    const int rc = gw_fnv1a64_stream(f, &h);
    const long long got = test_bytes_read() - r0;
    fclose(f);
    if (rc != GW_EINVAL || h != 7 || (r0 >= 0 && got >= (1LL << 20)))
        printf("status %d, h %llx, %lld bytes read\n", rc, h, got);
    EXPECT(rc == GW_EINVAL && h == 7);
    EXPECT(r0 < 0 || got < (1LL << 20));
    return 0;
}

static int c_stream_control(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/h.bin", dir);
    EXPECT(write_text(path, "granular\nmatter\n"));
    unsigned long long h = 0, want = GW_FNV1A64_INIT, want2 = GW_FNV1A64_INIT;
    const char *text = "granular\nmatter\n";
    for (const char *p = text; *p; p++)
        want = (want ^ (unsigned char)*p) * 1099511628211ULL;
    for (const char *p = text + 9; *p; p++)
        want2 = (want2 ^ (unsigned char)*p) * 1099511628211ULL;
    FILE *f = fopen(path, "rb");
    EXPECT(f != NULL);
    int rc = gw_fnv1a64_stream(f, &h);
    EXPECT(rc == GW_OK && h == want);
    EXPECT(fseek(f, 9, SEEK_SET) == 0);
    rc = gw_fnv1a64_stream(f, &h);
    fclose(f);
    unlink(path);
    EXPECT(rc == GW_OK && h == want2);
    return 0;
}

/* ------------------------------------------------- hand-made HDF5 sample ---- */

#if GW_HAVE_HDF5
/* a version 2 superblock (8-byte addresses) claiming an end at byte size,
 * its root group at byte 48, then written zeros up to size */
static int c_h5_root_zeros(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/z.h5", dir);
    unsigned char sb[48];
    memset(sb, 0, sizeof sb);
    static const unsigned char sig[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
    memcpy(sb, sig, 8);
    sb[8] = 2, sb[9] = 8, sb[10] = 8;
    const unsigned long long size = 64ULL << 20;
    for (int k = 0; k < 8; k++) {
        sb[20 + k] = 0xff;                               /* no extension */
        sb[28 + k] = (unsigned char)(size >> (8 * k));   /* end of file */
        sb[36 + k] = (unsigned char)(48ULL >> (8 * k)); /* the root group */
    }
    FILE *f = fopen(path, "wb");
    EXPECT(f && fwrite(sb, 1, sizeof sb, f) == sizeof sb);
    static const char z[65536];
    for (unsigned long long k = sizeof sb; k < size; k += sizeof z)
        EXPECT(fwrite(z, 1, size - k < sizeof z ? (size_t)(size - k) : sizeof z, f) > 0);
    EXPECT(fclose(f) == 0);
    gw_layer_sample s;
    gw_err e = {0};
    const long long r0 = test_bytes_read();
    const int rc = gw_layer_sample_read(path, &s, &e);
    const long long got = test_bytes_read() - r0;
    unlink(path);
    if (rc != GW_EFORMAT || !strstr(e.msg, "root group at byte 48") || (r0 >= 0 && got >= (1LL << 20)))
        printf("status %d, '%s', %lld bytes read\n", rc, e.msg, got);
    EXPECT(rc == GW_EFORMAT && strstr(e.msg, path) && strstr(e.msg, "root group at byte 48"));
    EXPECT(r0 < 0 || got < (1LL << 20));
    return 0;
}

static int c_h5_control(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/w.h5", dir);
    gw_layer_sample s = test_three_discs(); /* layer_test_util.h */
    gw_err e = {0};
    EXPECT(gw_layer_sample_write(&s, path, NULL, &e) == GW_OK);
    gw_layer_sample t;
    const int rc = gw_layer_sample_read(path, &t, &e);
    unlink(path);
    if (rc != GW_OK)
        printf("read: %s\n", e.msg);
    EXPECT(rc == GW_OK && t.n == 3 && t.x[1] == 0.5);
    gw_layer_sample_free(&t);
    return 0;
}
#endif

/* ------------------------------------------------------- solver drive ---- */

static int decay(double t, const double *y, double *f, void *ctx)
{
    (void)t, (void)ctx;
    f[0] = -y[0];
    return 0;
}

static int drive(double t_end, double dt_out, double *y_end, long *outputs, gw_err *e)
{
    static gw_system sys = {.dim = 1, .rhs = decay};
    gw_solver_params p = gw_solver_params_default();
    p.rtol = p.atol = 1e-9;
    double t = 0, y[1] = {1};
    gw_solver *s = NULL;
    int rc = gw_solver_create(gw_solver_cvode, &sys, &p, t, y, &s, e);
    if (rc != GW_OK)
        return rc;
    gw_drive d = {.t_end = t_end, .dt_out = dt_out};
    rc = gw_solver_drive(s, &d, &t, y, NULL, e);
    *y_end = y[0];
    *outputs = d.k_out - 1;
    gw_solver_free(s);
    return rc;
}

static int c_drive_nan(void)
{
    double y;
    long k;
    gw_err e = {0};
    EXPECT(refused(drive(NAN, 0.1, &y, &k, &e), &e, "t_end = nan"));
    EXPECT(refused(drive(INFINITY, 0.1, &y, &k, &e), &e, "t_end = inf"));
    EXPECT(refused(drive(1, NAN, &y, &k, &e), &e, "dt_out = nan"));
    EXPECT(refused(drive(1, -0.25, &y, &k, &e), &e, "dt_out = -0.25"));
    return 0;
}

static int c_drive_control(void)
{
    double y;
    long k;
    gw_err e = {0};
    const int rc = drive(1, 0.25, &y, &k, &e);
    if (rc != GW_OK)
        printf("drive: %s\n", e.msg);
    EXPECT(rc == GW_OK && fabs(y - exp(-1.0)) <= 1e-6 && k == 4);
    return 0;
}

/* ------------------------------------------------------ wall spectrum ---- */

static double sp_t[2001], sp_f[2001];

static int spectrum(double dt, double f_min, gw_chain_spectrum *sp, gw_err *e)
{
    for (int k = 0; k < 2001; k++)
        sp_t[k] = k * 1e-5, sp_f[k] = 1 + sin(2 * M_PI * 1e3 * sp_t[k]);
    gw_chain_trace tr = {.n = 0, .len = 2001, .cap = 2001, .t = sp_t, .f = sp_f};
    return gw_chain_wall_spectrum(&tr, 0, 0.02, dt, f_min, 0, sp, e);
}

static int c_spectrum_nan(void)
{
    gw_chain_spectrum sp;
    gw_err e = {0};
    EXPECT(refused(spectrum(NAN, 0, &sp, &e), &e, "dt = nan"));
    EXPECT(refused(spectrum(1e-5, NAN, &sp, &e), &e, "f_min = nan"));
    EXPECT(refused(spectrum(1e-5, INFINITY, &sp, &e), &e, "f_min = inf"));
    return 0;
}

static int c_spectrum_control(void)
{
    gw_chain_spectrum sp;
    gw_err e = {0};
    const int rc = spectrum(1e-5, 0, &sp, &e);
    if (rc != GW_OK)
        printf("spectrum: %s\n", e.msg);
    const double f = sp.f_peak;
    gw_chain_spectrum_free(&sp);
    EXPECT(rc == GW_OK && fabs(f - 1e3) <= 10);
    return 0;
}

#define ROWS(t) (sizeof(t) / sizeof((t)[0]))
/* each table's rows over its one body, then the control after it */
#define TABLE_CASES(t, cur, body)                                                                                  \
    for (size_t r = 0; r < ROWS(t); r++) {                                                                         \
        cur = &(t)[r];                                                                                              \
        child_casef(body, &nfail, &ncases, "%s", cur->label);                                                      \
    }

static const child_row falcon_rows[] = {
    {"falcon analyse check: a NULL p, res or a named", c_falcon_null},
    {"falcon analyse check: N = 0, negative, reversed, INT_MAX named", c_falcon_sizes},
    {"falcon analyse check of a linear tau_N (control)", c_falcon_control},
};
static const child_row rest_rows[] = {
    {"stream hash of /dev/zero", c_stream_dev_zero},
    {"stream hash of a regular file (control)", c_stream_control},
    {"solver drive to a NaN or infinite t_end, a NaN or negative dt_out", c_drive_nan},
    {"solver drive of a decay with outputs (control)", c_drive_control},
    {"wall spectrum of a NaN dt, a NaN or infinite f_min", c_spectrum_nan},
    {"wall spectrum of a 1 kHz sine (control)", c_spectrum_control},
#if GW_HAVE_HDF5
    {"HDF5 superblock claiming 64 MiB in front of 64 MiB of zeros", c_h5_root_zeros},
    {"HDF5 sample as written (control)", c_h5_control},
#endif
};

int main(void)
{
    if (test_scratch_dir(dir, sizeof dir, "left41") != 0)
        return 1;
    int nfail = 0, ncases = 0;
    for (size_t r = 0; r < ROWS(falcon_rows); r++)
        child_case(falcon_rows[r].label, falcon_rows[r].fn, &nfail, &ncases);
    TABLE_CASES(hex_rows, hexr, c_hex)
    child_case("text sample in decimal (control)", c_hex_control, &nfail, &ncases);
    TABLE_CASES(table_rows, tabr, c_table)
    TABLE_CASES(advance_rows, advr, c_advance)
    child_case("layer advance by 1 ms (control)", c_advance_control, &nfail, &ncases);
    TABLE_CASES(rings_rows, ringr, c_rings)
    child_case("rings of width 0.15 m (control)", c_rings_control, &nfail, &ncases);
    for (size_t r = 0; r < ROWS(rest_rows); r++)
        child_case(rest_rows[r].label, rest_rows[r].fn, &nfail, &ncases);
    rmdir(dir);
    return child_cases_end(nfail, ncases);
}
