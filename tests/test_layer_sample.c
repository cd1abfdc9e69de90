/*
 * test_layer_sample.c: pluviation and the sample format (docs/physics.md 2.2), and
 * the impact on a small sample (docs/physics.md 2.3-2.4) on the three backends.
 *
 * - Pluviation is deterministic for a seed: two runs give bitwise identical
 *   positions; another seed gives a different sample.
 * - After settling no overlap exceeds 1 % of R_p (the static Hertz overlap of
 *   a 5 R_m deep pile is ~1e-3 R_p; 1 % would mean particles pushed through
 *   each other).
 * - The sample file round-trips exactly (%.17g); corrupt, truncated, non-finite
 *   and negative-radius files are refused with GW_EFORMAT, a missing file with
 *   GW_EIO. Each of the hand-made bad text files of bad_files (empty, binary,
 *   n = 1e12, n mismatch, NaN/inf, trailing garbage, over-long line, NUL byte,
 *   duplicate key, ...) is refused with a message naming the file and the line
 *   where one applies; CRLF line ends read the same values as LF; a seed beyond
 *   2^53 round-trips exactly (it used to go through a double).
 * - HDF5 (builds with it): text -> h5 -> text round trip with bit-identical
 *   doubles and header; the format is told by content (an HDF5 file named .txt,
 *   a text file named .h5); truncated, metadata-corrupted, checksum-less,
 *   foreign and inconsistent (length mismatch, NaN) HDF5 files are refused with
 *   GW_EFORMAT naming the file. Without HDF5, writing .h5 is GW_EUNSUPPORTED.
 * - The reader's overlap check (a grid of cells; it was a sweep over x,
 *   quadratic in a column of discs) finds the same first pair (i, j) as a
 *   brute-force check over all pairs, on jittered packings of discs of radii
 *   spread over 1:20 with one or two discs moved onto others, and accepts the
 *   packings without them.
 * - Impact of a block (R_b = 0.7 R_m, 10 m/s, 20 ms) on the small sample: the
 *   energy ledger
 *   closes to 1e-4 (measured ~1e-6 with ARKode/CVODE, ~1e-5 with RK4, see
 *   test_layer_energy.c); RK4, CVODE and ARKode all see the take-off (the
 *   block watch's roots, located by each backend) and agree on e = V_r/V_i at
 *   the first free-flight maximum and on the penetration within 1e-4 relative.
 * - Impossible parameters are refused: block overlapping the layer (gap < 0),
 *   negative block radius, incidence 90 deg, friction angle 90 deg.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_layer.h"
#include "gw_test_overlap.h"
#include "gw_test.h"
#include "gw_test_files.h"
#if GW_HAVE_HDF5
#include <hdf5.h>
#endif

static gw_layer_make_params small(long seed)
{
    gw_layer_make_params m = gw_layer_make_params_default();
    m.n = 40;
    m.width_rm = 16;
    m.seed = seed;
    return m;
}

/* Bitwise equality of two samples (header and coordinates). */
static int same_sample(const gw_layer_sample *a, const gw_layer_sample *b)
{
    if (a->n != b->n || a->seed != b->seed || a->mass_law != b->mass_law ||
        memcmp(&a->width, &b->width, sizeof a->width) || memcmp(&a->rm, &b->rm, sizeof a->rm) ||
        memcmp(&a->volume_ratio, &b->volume_ratio, sizeof a->volume_ratio) ||
        memcmp(&a->porosity, &b->porosity, sizeof a->porosity))
        return 0;
    size_t k = (size_t)a->n * sizeof(double);
    return !memcmp(a->x, b->x, k) && !memcmp(a->y, b->y, k) && !memcmp(a->r, b->r, k);
}

/* rc == GW_EFORMAT, the message names the file and contains want (may be NULL). */
static void refused(const char *path, const char *want, const char *what)
{
    gw_layer_sample s;
    gw_err err = {{0}};
    int rc = gw_layer_sample_read(path, &s, &err);
    char line[800];
    snprintf(line, sizeof line, "refused: %s [%s]", what, err.msg);
    gw_test_true(rc == GW_EFORMAT && strstr(err.msg, path) && (!want || strstr(err.msg, want)) && !s.x &&
                 s.n == 0, line);
    gw_layer_sample_free(&s);
}

/* The hand-fed inputs of the hardening issue, each with the line it must name. */
static void bad_text_inputs(void)
{
    const char *path = "test_layer_sample_bad2.txt";
    const char *H = "granwave-layer-sample 1\nwidth 5\nrm 0.3\n";
    char buf[4096];
    struct {
        const char *body, *want, *what;
    } cases[] = {
        {"n 1e12\n1 1 0.3\n", "line 4", "huge n (1e12)"},
        {"n 99999999999999999999999\n1 1 0.3\n", "line 4", "n beyond every integer type"},
        {"n 2.5\n1 1 0.3\n", "line 4", "fractional n"},
        {"n 0\n", "line 4", "n = 0"},
        {"n 1\n1 1 0.3\n2 1 0.3\n", "line 6", "more particle lines than n"},
        {"n 1\n1 inf 0.3\n", "line 5", "infinite coordinate"},
        {"n 1\n1 1 nan\n", "line 5", "NaN radius"},
        {"n 1\n1 1 1e999\n", "line 5", "radius overflowing to inf"},
        {"n 1\n1 1 0\n", "line 5", "zero radius"},
        {"n 1\n1 1 0.3 junk\n", "line 5", "trailing garbage after x y r"},
        {"n 1\n1 1 0.3x\n", "line 5", "garbage glued to a number"},
        {"n 1\n1 1\n", "line 5", "two numbers instead of three"},
        {"n 1 junk\n1 1 0.3\n", "line 4", "trailing garbage after n"},
        {"seed 1.5\nn 1\n1 1 0.3\n", "line 4", "non-integer seed"},
        {"seed 99999999999999999999\nn 1\n1 1 0.3\n", "line 4", "seed out of range"},
        {"mass_law spherex\nn 1\n1 1 0.3\n", "line 4", "mass law with trailing characters"},
        {"width 6\nn 1\n1 1 0.3\n", "line 4", "duplicate key"},
        {"volume_ratio 0.5\nn 1\n1 1 0.3\n", "volume_ratio", "volume ratio below 1"},
        {"porosity 2\nn 1\n1 1 0.3\n", "porosity", "porosity above 1"},
        {"colour red\nn 1\n1 1 0.3\n", "line 4", "unknown key"},
        {"n 1\n1 1 0.3\r\r\n", "line 5", "stray CR before CRLF"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        snprintf(buf, sizeof buf, "%s%s", H, cases[i].body);
        gw_test_write_text(path, buf);
        refused(path, cases[i].want, cases[i].what);
    }
    gw_test_write_text(path, "");
    refused(path, "empty", "empty file");
    gw_test_write_text(path, "\n# only a comment\n\n");
    refused(path, "empty", "only comments and blank lines");
    gw_test_write_bytes(path, "\x7f" "ELF\x02\x01\x01\0\0\0\xff\xfe\n\x01", 15);
    refused(path, "line 1", "binary junk");
    gw_test_write_text(path, "granwave-layer-sample 3\nwidth 5\nrm 0.3\nn 1\n1 1 0.3\n");
    refused(path, "version", "format version 3");
    /* version 2 (clump samples) needs the body column */
    gw_test_write_text(path, "granwave-layer-sample 2\nwidth 5\nrm 0.3\nn 1\n1 1 0.3\n");
    refused(path, "body", "format version 2 without the body column");
    gw_test_write_text(path, "granwave-layer-sample 2\nwidth 5\nrm 0.3\nn 1\n1 1 0.3 0.5\n");
    refused(path, "body", "format version 2 with a body id that is not an integer");
    gw_test_write_text(path, "granwave-layer-sample 12\nwidth 5\nrm 0.3\nn 1\n1 1 0.3\n");
    refused(path, "version", "format version 12 (was read as 1)");
    const char nul[] = "granwave-layer-sample 1\nwidth 5\nrm 0.3\nn 1\n1 1 0.3\0 9 9\n";
    gw_test_write_bytes(path, nul, sizeof nul - 1);
    refused(path, "line 5", "NUL byte hiding trailing data");
    int w = snprintf(buf, sizeof buf, "%sn 1\n1 1 0.3", H);
    memset(buf + w, ' ', 1500);
    snprintf(buf + w + 1500, sizeof buf - (size_t)w - 1500, "junk\n");
    gw_test_write_text(path, buf);
    refused(path, "line 5", "1500-character line (trailing junk used to be cut off)");
    w = snprintf(buf, sizeof buf, "granwave-layer-sample 1\nwidth 5");
    memset(buf + w, ' ', 600);
    snprintf(buf + w + 600, sizeof buf - (size_t)w - 600, "9\nrm 0.3\nn 1\n1 1 0.3\n");
    gw_test_write_text(path, buf);
    refused(path, "line 2", "header value with garbage after 600 blanks");

    /* CRLF and long comments are fine and give the same values as LF */
    gw_layer_sample a, b;
    gw_err err = {{0}};
    gw_test_write_text(path, "granwave-layer-sample 1\r\n# c\r\nwidth 5\r\nrm 0.3\r\nseed 9000000000000000001\r\n"
                     "mass_law sphere\r\nn 2\r\n1 1 0.3\r\n2.5 0.4 0.35\r\n");
    int rc = gw_layer_sample_read(path, &a, &err);
    char big[3000];
    memset(big, 'c', sizeof big);
    big[0] = '#';
    big[sizeof big - 1] = '\0';
    snprintf(buf, sizeof buf, "granwave-layer-sample 1\n%s\nwidth 5\nrm 0.3\nseed 9000000000000000001\n"
             "mass_law sphere\nn 2\n1 1 0.3\n2.5 0.4 0.35\n", big);
    gw_test_write_text(path, buf);
    int rc2 = rc == GW_OK ? gw_layer_sample_read(path, &b, &err) : -1;
    gw_test_true(rc == GW_OK && rc2 == GW_OK && same_sample(&a, &b) && a.seed == 9000000000000000001L &&
                 a.mass_law == GW_LAYER_MASS_SPHERE && a.n == 2 && a.r[1] == 0.35,
                 "CRLF file reads the same values as LF (and a 3000-character comment is skipped)");
    if (rc == GW_OK) {
        rc = gw_layer_sample_write(&a, path, NULL, &err);
        gw_layer_sample_free(&b);
        rc = rc == GW_OK ? gw_layer_sample_read(path, &b, &err) : rc;
        gw_test_true(rc == GW_OK && b.seed == 9000000000000000001L, "seed 9000000000000000001 (> 2^53) round-trips");
        a.x[0] = NAN;
        remove(path);
        gw_test_true(gw_layer_sample_write(&a, path, NULL, &err) == GW_EINVAL && !gw_test_file_exists(path),
                     "writer refuses a NaN coordinate and writes nothing");
    }
    gw_layer_sample_free(&a);
    gw_layer_sample_free(&b);
    remove(path);
}

#if GW_HAVE_HDF5
/* Make an inconsistent copy of a valid HDF5 sample with the HDF5 API. */
static int h5_edit(const char *path, int what)
{
    hid_t f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT);
    if (f < 0)
        return -1;
    int rc = 0;
    if (what == 0) { /* y one value short */
        H5Ldelete(f, "y", H5P_DEFAULT);
        double v[1] = {1};
        hsize_t dim = 1;
        hid_t sp = H5Screate_simple(1, &dim, NULL);
        hid_t d = H5Dcreate2(f, "y", H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        rc = d < 0 || H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0;
        H5Dclose(d);
        H5Sclose(sp);
    } else { /* NaN as the first x */
        hid_t d = H5Dopen2(f, "x", H5P_DEFAULT), sp = H5Dget_space(d);
        hsize_t start = 0, count = 1;
        double v = NAN;
        hid_t mem = H5Screate_simple(1, &count, NULL);
        H5Sselect_hyperslab(sp, H5S_SELECT_SET, &start, NULL, &count, NULL);
        rc = H5Dwrite(d, H5T_NATIVE_DOUBLE, mem, sp, H5P_DEFAULT, &v) < 0;
        H5Sclose(mem);
        H5Sclose(sp);
        H5Dclose(d);
    }
    return H5Fclose(f) < 0 || rc ? -1 : 0;
}

static void hdf5_samples(const gw_layer_sample *a)
{
    const char *t1 = "test_layer_sample_h5a.txt", *h = "test_layer_sample_h5.h5",
               *t2 = "test_layer_sample_h5b.txt", *bad = "test_layer_sample_bad.h5",
               *hx = "test_layer_sample_h5_named.txt", *th = "test_layer_sample_text_named.h5";
    gw_layer_sample s1, s2, s3;
    gw_err err = {{0}};
    int rc = gw_layer_sample_write(a, t1, "first", &err);
    rc = rc == GW_OK ? gw_layer_sample_read(t1, &s1, &err) : rc;
    rc = rc == GW_OK ? gw_layer_sample_write(&s1, h, "granwave test\nsecond line", &err) : rc;
    rc = rc == GW_OK ? gw_layer_sample_read(h, &s2, &err) : rc;
    rc = rc == GW_OK ? gw_layer_sample_write(&s2, t2, "first", &err) : rc;
    rc = rc == GW_OK ? gw_layer_sample_read(t2, &s3, &err) : rc;
    char what[700];
    snprintf(what, sizeof what, "text -> h5 -> text: every step ok (%s)", err.msg);
    gw_test_true(rc == GW_OK, what);
    if (rc != GW_OK)
        return;
    gw_test_true(same_sample(a, &s1) && same_sample(&s1, &s2) && same_sample(&s2, &s3),
                 "text -> h5 -> text: header and coordinates bit-identical");
    FILE *p = fopen(t1, "rb"), *q = fopen(t2, "rb");
    int c, d, eq = p && q;
    while (eq && ((c = getc(p)) != EOF) | ((d = getc(q)) != EOF))
        eq = c == d;
    if (p)
        fclose(p);
    if (q)
        fclose(q);
    gw_test_true(eq, "text -> h5 -> text: the two text files are byte-identical");
    FILE *hf = fopen(h, "rb");
    unsigned char sig[8] = {0};
    gw_test_true(hf && fread(sig, 1, 8, hf) == 8 && memcmp(sig, "\x89HDF\r\n\x1a\n", 8) == 0,
                 "a .h5 sample is an HDF5 file (signature)");
    if (hf)
        fclose(hf);
    gw_layer_sample_free(&s3);
    long size = gw_test_copy_prefix(h, hx, -1, -1);
    rc = gw_layer_sample_read(hx, &s3, &err);
    gw_test_true(rc == GW_OK && same_sample(&s2, &s3), "an HDF5 sample named .txt is read as HDF5 (by content)");
    gw_layer_sample_free(&s3);
    gw_test_copy_prefix(t1, th, -1, -1);
    rc = gw_layer_sample_read(th, &s3, &err);
    gw_test_true(rc == GW_OK && same_sample(&s1, &s3), "a text sample named .h5 is read as text (by content)");
    gw_layer_sample_free(&s3);

    /* truncated and corrupted copies */
    const long cuts[] = {8, 9, 100, size / 2, size - 1};
    for (size_t k = 0; k < sizeof cuts / sizeof cuts[0]; k++) {
        gw_test_copy_prefix(h, bad, cuts[k], -1);
        snprintf(what, sizeof what, "HDF5 sample truncated to %ld of %ld bytes", cuts[k], size);
        refused(bad, "HDF5", what);
    }
    gw_test_copy_prefix(h, bad, -1, 20); /* in the superblock, under its checksum */
    refused(bad, "checksum", "HDF5 superblock with one bit flipped");
    gw_test_copy_prefix(h, bad, -1, 60); /* in the root object header */
    refused(bad, "HDF5", "HDF5 root object header with one bit flipped");
    gw_test_copy_prefix(h, bad, -1, -1);
    gw_test_true(h5_edit(bad, 0) == 0, "made an HDF5 sample with y one value short");
    refused(bad, "dataset 'y' has 1 values, n = ", "HDF5 datasets of different lengths");
    gw_test_copy_prefix(h, bad, -1, -1);
    gw_test_true(h5_edit(bad, 1) == 0, "made an HDF5 sample with x[0] = NaN");
    refused(bad, "particle at index 0", "HDF5 sample with a NaN coordinate");
    hid_t f = H5Fcreate(bad, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT); /* superblock 0 */
    H5Fclose(f);
    refused(bad, "checksums", "HDF5 file in the 1.6 format (no metadata checksums)");
    /* the format of granwave's own outputs other than samples (impact.h5): the
     * refusal says it is no sample granwave wrote, not only how to rewrite it */
    refused(bad, "not a sample granwave wrote", "HDF5 file in the 1.6 format: named as no granwave sample");
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_libver_bounds(fapl, H5F_LIBVER_LATEST, H5F_LIBVER_LATEST);
    f = H5Fcreate(bad, H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
    H5Fclose(f);
    H5Pclose(fapl);
    refused(bad, "not a granwave layer sample", "HDF5 file that is not a sample");
    gw_layer_sample_free(&s1);
    gw_layer_sample_free(&s2);
    remove(t1), remove(t2), remove(h), remove(bad), remove(hx), remove(th);
}
#else
static void hdf5_samples(const gw_layer_sample *a)
{
    gw_err err = {{0}};
    const char *h = "test_layer_sample_nohdf5.h5";
    gw_test_true(gw_layer_sample_write(a, h, NULL, &err) == GW_EUNSUPPORTED && strstr(err.msg, "HDF5") &&
                 !gw_test_file_exists(h), "no HDF5 in this build: writing .h5 is GW_EUNSUPPORTED, nothing written");
}
#endif

static void bad_files(void)
{
    const char *hdr = "granwave-layer-sample 1\nwidth 5\nrm 0.3\n";
    struct {
        const char *text, *what;
    } cases[] = {
        {"not a sample\n", "corrupt header"},
        {"granwave-layer-sample 1\nwidth 5\nrm 0.3\nn 2\n1 1 0.3\n", "truncated particle list"},
        {"granwave-layer-sample 1\nwidth 5\nrm 0.3\nn 1\n1 nan 0.3\n", "non-finite coordinate"},
        {"granwave-layer-sample 1\nwidth 5\nrm 0.3\nn 1\n1 1 -0.3\n", "negative radius"},
        {"granwave-layer-sample 1\nwidth 5\nrm 0.3\nn 1\n9 1 0.3\n", "particle outside the box"},
        {"granwave-layer-sample 1\nwidth abc\nrm 0.3\nn 1\n1 1 0.3\n", "bad number in the header"},
    };
    (void)hdr;
    const char *path = "test_layer_sample_bad.txt";
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        gw_layer_sample s;
        gw_err err = {{0}};
        gw_test_write_text(path, cases[i].text);
        int rc = gw_layer_sample_read(path, &s, &err);
        char what[700];
        snprintf(what, sizeof what, "sample refused: %s (%s)", cases[i].what, err.msg);
        gw_test_true(rc == GW_EFORMAT && strstr(err.msg, path) != NULL, what);
    }
    remove(path);
    gw_layer_sample s;
    gw_err err = {{0}};
    gw_test_true(gw_layer_sample_read("no/such/file.txt", &s, &err) == GW_EIO, "missing sample file: GW_EIO");
}

static unsigned long long rnd_state = 12345;
static double RND(void)
{
    rnd_state = rnd_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rnd_state >> 11) / 9007199254740992.0;
}

/* The overlap check against all pairs: 24 packings of 400 discs on a jittered
 * grid (radii 0.025 .. 0.5 of the 1 m cell, one disc of 2 m in some), each
 * read as written (accepted: no pair overlaps by 0.05 R_p) and with one or
 * two discs moved onto others (refused naming the first pair in index order,
 * as a brute-force search finds it). */
static void overlap_pairs(void)
{
    enum { G = 20, N = G * G };
    static double x[N], y[N], r[N];
    const char *path = "test_layer_sample_ov.txt";
    int agree = 0, accepted = 0;
    for (int t = 0; t < 24; t++) {
        for (int k = 0; k < N; k++) {
            const double u = RND();
            r[k] = 0.025 + 0.475 * u * RND();
            x[k] = 3.0 * (k % G) + 1.5 + (1.0 - r[k]) * (2 * RND() - 1) * 0.9;
            y[k] = 3.0 * (k / G) + 1.5 + (1.0 - r[k]) * (2 * RND() - 1) * 0.9;
        }
        if (t % 3 == 1) { /* a disc of 1.4 m at its cell's centre */
            const int k = (t * 37) % N;
            r[k] = 1.4, x[k] = 3.0 * (k % G) + 1.5, y[k] = 3.0 * (k / G) + 1.5;
        }
        const int moves = t % 4 == 0 ? 0 : 1 + t % 2;
        for (int m = 0; m < moves; m++) {
            int a = (int)(RND() * N);
            int b = (int)(RND() * N);
            if (a == b)
                b = (b + 1) % N;
            x[b] = x[a] + 0.5 * r[a] * (2 * RND() - 1);
            y[b] = y[a] + 0.5 * r[a] * (2 * RND() - 1);
            if (y[b] < r[b])
                y[b] = r[b];
            if (x[b] < r[b] || x[b] > 3.0 * G - r[b])
                x[b] = x[a];
        }
        int fi = -1, fj = -1;
        for (int i = 0; i < N && fi < 0; i++)
            for (int j = i + 1; j < N; j++) {
                double ov = r[i] + r[j] - hypot(x[j] - x[i], y[j] - y[i]), rp = 2 * r[i] * r[j] / (r[i] + r[j]);
                if (ov > 0.05 * rp) {
                    fi = i, fj = j;
                    break;
                }
            }
        FILE *fp = fopen(path, "w");
        if (!fp)
            continue;
        fprintf(fp, "granwave-layer-sample 1\nwidth %d\nrm 0.5\nn %d\n", 3 * G, N);
        for (int k = 0; k < N; k++)
            fprintf(fp, "%.17g %.17g %.17g\n", x[k], y[k], r[k]);
        fclose(fp);
        gw_layer_sample s;
        gw_err err = {{0}};
        int rc = gw_layer_sample_read(path, &s, &err);
        char want[64];
        snprintf(want, sizeof want, "particles %d and %d overlap", fi, fj);
        if (fi < 0 ? rc == GW_OK : rc == GW_EFORMAT && strstr(err.msg, want) != NULL)
            agree++;
        else
            printf("  packing %d: brute force %d, %d; reader rc %d: %s\n", t, fi, fj, rc, err.msg);
        accepted += fi < 0 && rc == GW_OK;
        gw_layer_sample_free(&s);
    }
    remove(path);
    char what[120];
    snprintf(what, sizeof what, "overlap check = brute force on 24 packings (%d accepted as they should)", accepted);
    gw_test_true(agree == 24 && accepted >= 6, what);
}

int main(void)
{
    gw_layer_params lp = gw_layer_params_default();
    gw_layer_make_params m = small(8);
    gw_layer_sample a, b, c;
    gw_layer_make_result ra, rb, rc_;
    gw_err err = {{0}};
    int rc = gw_layer_make(&lp, &m, &a, &ra, &err);
    gw_test_true(rc == GW_OK && ra.converged, "pluviation of 40 discs converged");
    gw_layer_make(&lp, &m, &b, &rb, &err);
    m.seed = 9;
    gw_layer_make(&lp, &m, &c, &rc_, &err);
    int same = a.n == b.n, diff = 0;
    for (int i = 0; same && i < a.n; i++)
        same = a.x[i] == b.x[i] && a.y[i] == b.y[i] && a.r[i] == b.r[i];
    for (int i = 0; i < a.n && i < c.n; i++)
        diff |= a.x[i] != c.x[i];
    gw_test_true(same, "pluviation deterministic for a seed (bitwise)");
    gw_test_true(diff, "another seed gives another sample");
    gw_test_abs(ra.max_overlap, 0, 1e-2, "largest overlap after settling (u_n / R_p)");
    /* the same pairs and formula: equal to rounding (the grid's pairs in another order) */
    gw_test_rel(ra.max_overlap, gw_test_max_overlap(&a), 1e-12, "largest overlap = every pair compared");
    printf("porosity %.4f, settled in %.3g s, %.0f ms wall\n", ra.porosity, ra.t_settle, ra.wall_ms);

    const char *path = "test_layer_sample.txt";
    rc = gw_layer_sample_write(&a, path, "test_layer_sample", &err);
    gw_layer_sample d;
    if (rc == GW_OK)
        rc = gw_layer_sample_read(path, &d, &err);
    gw_test_true(rc == GW_OK, "sample written and read back");
    int exact = rc == GW_OK && d.n == a.n && d.width == a.width && d.rm == a.rm;
    for (int i = 0; exact && i < a.n; i++)
        exact = d.x[i] == a.x[i] && d.y[i] == a.y[i] && d.r[i] == a.r[i];
    gw_test_true(exact, "sample round trip is exact");
    remove(path);
    bad_files();
    bad_text_inputs();
    overlap_pairs();
    hdf5_samples(&a);

    /* impact on the small sample, three backends */
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.vi = 10;
    ip.rb_rm = 0.7;
    ip.t_max = 0.02;
    ip.until = GW_LAYER_UNTIL_VERDICT; /* to the take-off: T_f lies beyond t_max */
    const gw_solver_type *types[3] = {gw_solver_rk4, gw_solver_cvode, gw_solver_arkode};
    double en[3] = {NAN, NAN, NAN}, pen[3] = {NAN, NAN, NAN};
    for (int k = 0; k < 3; k++) {
        gw_solver_params sp = gw_solver_params_default();
        sp.dt = 1e-6;
        sp.rtol = sp.atol = 1e-9;
        gw_layer_impact_result r;
        rc = gw_layer_impact(&a, &lp, &ip, types[k], &sp, &r, &err);
        char what[700];
        snprintf(what, sizeof what, "%s: impact run ok (%s)", gw_solver_type_name(types[k]), err.msg);
        gw_test_true(rc == GW_OK, what);
        if (rc != GW_OK)
            continue;
        snprintf(what, sizeof what, "%s: impact energy ledger closure", gw_solver_type_name(types[k]));
        gw_test_abs(r.energy_error, 0, 1e-4, what);
        printf("  %s: bounced %d e_first %.8g penetration %.8g m, E_d first contact %.4g, %.0f ms\n",
               gw_solver_type_name(types[k]), r.bounced, r.e_first, r.penetration,
               r.dissipated_first_contact, r.wall_ms);
        snprintf(what, sizeof what, "%s: the block bounces (take-off located by the block watch)",
                 gw_solver_type_name(types[k]));
        gw_test_true(r.bounced == 1, what);
        en[k] = r.e_first;
        pen[k] = r.penetration;
        gw_layer_impact_result_free(&r);
    }
    gw_test_rel(en[1], en[0], 1e-4, "cvode vs rk4: e_first = V_r/V_i at the first free-flight maximum");
    gw_test_rel(en[2], en[0], 1e-4, "arkode vs rk4: e_first = V_r/V_i at the first free-flight maximum");
    gw_test_rel(pen[1], pen[0], 1e-4, "cvode vs rk4: penetration (m)");
    gw_test_rel(pen[2], pen[0], 1e-4, "arkode vs rk4: penetration (m)");

    /* impossible parameters */
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 1e-6;
    gw_layer_impact_result r;
    gw_layer_impact_params bad = ip;
    bad.gap = -0.01;
    gw_test_true(gw_layer_impact(&a, &lp, &bad, gw_solver_rk4, &sp, &r, &err) == GW_EINVAL &&
                 strstr(err.msg, "gap") != NULL, "block overlapping the layer refused");
    bad = ip;
    bad.rb_rm = -1;
    gw_test_true(gw_layer_impact(&a, &lp, &bad, gw_solver_rk4, &sp, &r, &err) == GW_EINVAL &&
                 strstr(err.msg, "rb-rm") != NULL, "negative block radius refused");
    bad = ip;
    bad.alpha_deg = 90;
    gw_test_true(gw_layer_impact(&a, &lp, &bad, gw_solver_rk4, &sp, &r, &err) == GW_EINVAL,
                 "incidence 90 deg refused");
    gw_layer_params lbad = lp;
    lbad.friction_deg = 90;
    gw_test_true(gw_layer_impact(&a, &lbad, &ip, gw_solver_rk4, &sp, &r, &err) == GW_EINVAL &&
                 strstr(err.msg, "friction") != NULL, "friction angle 90 deg refused");
    gw_layer_body body = {.x = 1, .y = 1, .r = -0.1};
    gw_layer *L = NULL;
    gw_test_true(gw_layer_create(&lp, 1, &body, &L, &err) == GW_EINVAL && L == NULL,
                 "negative particle radius refused");
    gw_layer_sample_free(&a);
    gw_layer_sample_free(&b);
    gw_layer_sample_free(&c);
    gw_layer_sample_free(&d);
    return gw_test_summary("test_layer_sample");
}
