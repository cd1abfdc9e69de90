/*
 * test_library_left46.c: library calls the forty-sixth pass left (docs/library.md
 * "The contract of every call"), each case in its own child process
 * (test_child.h):
 *   - gw_layer_make_result_warnings refused a result filled by hand
 *     (converged -3, an E_k of NaN, ...) with GW_EINVAL and no word of which
 *     field: gw_layer_make_result_check now names the field, its value and
 *     its range ("gw_layer_make_result: ke_final = nan J is outside [0,
 *     inf)"), and the warnings refuse exactly what it refuses, nothing added.
 *     An untrimmed top of NaN or inf (it printed "lies at inf R_m") is refused
 *     too. Controls: an unsettled result as layer-make fills one, a fall
 *     energy of -1 (not counted), an unknown ke_limit of 0, a settled result
 *     with a NaN E_k and t_max, and two real pluviations pass.
 *   - A spring of a sample built in memory with a displacement u of NaN or
 *     +-inf passed gw_layer_impact_settled_check (other_settling 0 and 1),
 *     gw_layer_impact_check and gw_layer_impact under zero_springs (the run
 *     took the sample), the porosity, the DEM step and the pile hash, where
 *     the readers and the writer refuse it: each now refuses it naming the
 *     spring and "displacement u = nan m" (the porosity and the step NaN, the
 *     hash 0). Its neighbours in the record (a, b) are held the same way
 *     (a = -1, b = 3, a = b refused by each). Controls: u = 0 and u = -3
 *     (a sign is a direction) pass under zero_springs.
 *   - gw_layer_sample_read on a text sample that grows while it is read (a
 *     hook on fstat appends a comment line right after each look at the
 *     file's size, as a process appending to it would): it read on to the
 *     end, whatever was added; now it reads at most the size at open and one
 *     byte more, and refuses the file (GW_EINVAL naming it and the size), the
 *     sample left zeroed. Controls: the same file read without the hook, and
 *     with the comment appended before it is opened, read with a content
 *     hash that is gw_fnv1a64 of its bytes.
 *   - HDF5 samples (an HDF5 build): an HDF5 signature and 8 MiB of written
 *     zeros (no hole), a sample granwave wrote with 8 MiB of written zeros
 *     after its end, and one cut short, were hashed whole (the bytes read,
 *     /proc/self/io's rchar, over 8 MiB) before the HDF5 library refused
 *     them; gw_layer_sample_read and gw_sweep_config_read now refuse each
 *     naming the superblock, having read under 1 MiB. Controls: the sample as
 *     written, with 8 KiB of sparse zeros after its end (as cp
 *     --sparse=always leaves one), and with 64 KiB of written zeros after it
 *     are read. (Session 42) A sample whose superblock's end-of-file address
 *     was edited to 64 MiB, written zeros up to there (the superblock's
 *     checksum then wrong), and the same with the checksum made right and
 *     all after the root header zeroed passed those rules (sizes, "OHDR" at
 *     the root) and were hashed whole, 64 MiB a time, before HDF5 refused
 *     them (a sweep's config took them): HDF5 itself now opens the file and
 *     loads the root's and datasets x, y, r's headers first, refused under
 *     1 MiB read naming the checksum or dataset x.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "granwave.h"
#include "layer_test_util.h"
#include "gw_test_cases.h"
#include "test_child.h"

static char dir[64];

/* ---- 1 gw_layer_make_result_check ---- */

enum { R_CONV, R_TOP, R_KE, R_LOAD, R_LIMIT, R_JUDGE, R_FALL, R_TMAX, R_NULL };
typedef struct res_row {
    const char *label;
    int field;
    double v;
    const char *named; /* in the check's message (NULL: passes) */
} res_row;

static const res_row res_rows[] = {
    {"converged -3", R_CONV, -3, "gw_layer_make_result: converged = -3 is neither 0 (not settled) nor 1"},
    {"converged 2", R_CONV, 2, "gw_layer_make_result: converged = 2 is neither"},
    {"untrimmed_top_rm NaN", R_TOP, NAN, "gw_layer_make_result: untrimmed_top_rm = nan R_m is outside [0, inf)"},
    {"untrimmed_top_rm inf", R_TOP, INFINITY, "gw_layer_make_result: untrimmed_top_rm = inf R_m is outside"},
    {"untrimmed_top_rm -1", R_TOP, -1, "gw_layer_make_result: untrimmed_top_rm = -1 R_m is outside [0, inf)"},
    {"ke_final NaN", R_KE, NAN, "gw_layer_make_result: ke_final = nan J is outside [0, inf)"},
    {"ke_final -1", R_KE, -1, "gw_layer_make_result: ke_final = -1 J is outside [0, inf)"},
    {"ke_final inf", R_KE, INFINITY, "gw_layer_make_result: ke_final = inf J is outside [0, inf)"},
    {"floor_load NaN", R_LOAD, NAN, "gw_layer_make_result: floor_load = nan is outside [0, inf)"},
    {"floor_load -0.5", R_LOAD, -0.5, "gw_layer_make_result: floor_load = -0.5 is outside [0, inf)"},
    {"ke_limit NaN", R_LIMIT, NAN, "gw_layer_make_result: ke_limit = nan J is outside [0, inf)"},
    {"ke_limit -1", R_LIMIT, -1, "gw_layer_make_result: ke_limit = -1 J is outside [0, inf)"},
    {"t_judge inf", R_JUDGE, INFINITY, "gw_layer_make_result: t_judge = inf s is outside [0, inf)"},
    {"t_judge NaN", R_JUDGE, NAN, "gw_layer_make_result: t_judge = nan s is outside [0, inf)"},
    {"fall_energy NaN", R_FALL, NAN, "gw_layer_make_result: fall_energy = nan J is not a number"},
    {"t_max NaN", R_TMAX, NAN, "gw_layer_make_result: t_max = nan s is outside (0, inf)"},
    {"t_max 0", R_TMAX, 0, "gw_layer_make_result: t_max = 0 s is outside (0, inf)"},
    {"t_max -inf", R_TMAX, -INFINITY, "gw_layer_make_result: t_max = -inf s is outside (0, inf)"},
    {"r NULL", R_NULL, 0, "gw_layer_make_result_check: r is NULL"},
    /* controls */
    {"as layer-make fills one (control)", R_KE, 10, NULL},
    {"fall_energy -1, not counted (control)", R_FALL, -1, NULL},
    {"ke_limit 0, unknown (control)", R_LIMIT, 0, NULL},
    {"an untrimmed top at 5 R_m (control)", R_TOP, 5, NULL},
};
#define NRES (sizeof res_rows / sizeof res_rows[0])
static const res_row *rrow;

static int c_result(void)
{
    gw_layer_make_result r = test_unsettled_make_result();
    double t_max = 2;
    double *f[7] = {NULL, &r.untrimmed_top_rm, &r.ke_final, &r.floor_load, &r.ke_limit, &r.t_judge, &r.fall_energy};
    if (rrow->field == R_CONV)
        r.converged = (int)rrow->v;
    else if (rrow->field == R_TMAX)
        t_max = rrow->v;
    else if (rrow->field != R_NULL)
        *f[rrow->field] = rrow->v;
    const gw_layer_make_result *rp = rrow->field == R_NULL ? NULL : &r;
    gw_err e = {{0}};
    const int rc = gw_layer_make_result_check(rp, t_max, &e);
    char *list = NULL;
    const int rw = rp ? gw_layer_make_result_warnings(rp, t_max, "o.txt", &list) : GW_EINVAL;
    if (!rrow->named) {
        if (rc != GW_OK || e.msg[0])
            printf("control: status %d '%s'\n", rc, e.msg);
        EXPECT(rc == GW_OK && rw == GW_OK && list); /* the warning said, as before */
        free(list);
        return 0;
    }
    EXPECT(test_refused_or_ok(rc, &e, rrow->named));
    if (rw != GW_EINVAL || list)
        printf("the warnings: status %d, list '%s' (wanted GW_EINVAL and nothing)\n", rw, list ? list : "(null)");
    free(list);
    return 0;
}

/* a settled result states none of its numbers: a NaN E_k and t_max pass;
 * real pluviations' results pass (one settled, one stopped before its
 * verdict), the check's err left empty */
static int c_result_real(void)
{
    gw_layer_make_result r = test_unsettled_make_result();
    gw_err e = {{0}};
    r.converged = 1, r.ke_final = NAN, r.floor_load = NAN;
    EXPECT(gw_layer_make_result_check(&r, NAN, &e) == GW_OK && !e.msg[0]);
    gw_layer_params lp = gw_layer_params_default();
    gw_layer_make_params mp = gw_layer_make_params_default();
    gw_layer_sample s;
    mp.n = 10, mp.width_rm = 4, mp.t_max = 3; /* settles at 2.9 s */
    EXPECT(gw_layer_make(&lp, &mp, &s, &r, &e) == GW_OK && r.converged == 1);
    EXPECT(gw_layer_make_result_check(&r, mp.t_max, &e) == GW_OK && !e.msg[0]);
    gw_layer_sample_free(&s);
    mp.t_max = 0.05;
    EXPECT(gw_layer_make(&lp, &mp, &s, &r, &e) == GW_OK && r.converged == 0);
    EXPECT(gw_layer_make_result_check(&r, mp.t_max, &e) == GW_OK && !e.msg[0]);
    gw_layer_sample_free(&s);
    return 0;
}

/* ---- 2 a spring's record in memory ---- */

typedef struct spr_row {
    const char *label;
    int a, b;
    double u;
    const char *named; /* NULL: passes (under zero_springs) */
} spr_row;

static const spr_row spr_rows[] = {
    {"u NaN", 0, 1, NAN, "sample 's': spring at index 0: spring 0 1: displacement u = nan m is not a finite number"},
    {"u inf", 0, 1, INFINITY, "spring at index 0: spring 0 1: displacement u = inf m is not a finite number"},
    {"u -inf", 1, GW_LAYER_SPRING_BOTTOM, -INFINITY,
     "spring at index 0: spring 1 bottom: displacement u = -inf m is not a finite number"},
    {"a -1 (its neighbour)", -1, 1, 0, "spring at index 0: spring -1 1: the pair must be two particles in [0, 3)"},
    {"b 3 (its neighbour)", 0, 3, 0, "spring at index 0: spring 0 3: the pair must be two particles in [0, 3)"},
    {"a = b (its neighbour)", 1, 1, 0, "spring at index 0: spring 1 1: the pair must be two particles"},
    {"u 0 (control)", 0, 1, 0, NULL},
    {"u -3, a direction (control)", 1, 2, -3, NULL},
};
#define NSPR (sizeof spr_rows / sizeof spr_rows[0])
static const spr_row *srow;
static gw_layer_spring spring_of_row;

static gw_layer_sample spring_sample(void)
{
    gw_layer_sample s = test_three_discs();
    spring_of_row = (gw_layer_spring){srow->a, srow->b, srow->u};
    s.springs = &spring_of_row, s.n_springs = 1;
    return s;
}

static int as_spring(int rc, const gw_err *e)
{
    return test_refused_or_ok(rc, e, srow->named);
}

static int c_spring_settled(void)
{
    gw_layer_sample s = spring_sample();
    gw_layer_params lp = gw_layer_params_default();
    gw_err e = {{0}};
    char w[768];
    for (int other = 0; other <= 1; other++)
        EXPECT(as_spring(gw_layer_impact_settled_check(&s, &lp, other, "s", w, sizeof w, &e), &e));
    return 0;
}

/* under zero_springs the check and the run: the same refusal (the run took
 * the NaN spring), the controls checked and run */
static int c_spring_zero(void)
{
    gw_layer_sample s = spring_sample();
    gw_layer_params lp = gw_layer_params_default();
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    gw_solver_params sp = gw_solver_params_default();
    ip.t_max = 1e-4, ip.zero_springs = 1;
    gw_err ec = {{0}}, er = {{0}};
    const int rc = gw_layer_impact_check(&s, &ip, &ec);
    EXPECT(as_spring(rc, &ec));
    gw_layer_impact_result res;
    const int rr = gw_layer_impact(&s, &lp, &ip, gw_solver_verlet, &sp, &res, &er);
    if (rr == GW_OK)
        gw_layer_impact_result_free(&res);
    EXPECT(as_spring(rr, &er));
    EXPECT(!srow->named || strcmp(ec.msg, er.msg) == 0);
    return 0;
}

static int c_spring_numbers(void)
{
    gw_layer_sample s = spring_sample();
    gw_layer_params lp = gw_layer_params_default();
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.zero_springs = 1; /* (the discs touch: a spring's contact is not this row's subject) */
    const double p = gw_layer_sample_porosity(&s), dt = gw_layer_impact_dem_dt(&s, &lp, &ip);
    const unsigned long long h = gw_layer_sample_pile_hash(&s);
    if (srow->named ? !isnan(p) || !isnan(dt) || h != 0 : !(p >= 0 && p <= 1) || !(dt > 0) || h == 0)
        printf("porosity %g, dem_dt %g, pile hash %016llx\n", p, dt, h);
    return 0;
}

/* ---- 3 a text sample growing while it is read ---- */

/* The file whose every fstat appends a comment line after the size is
 * taken, as a process appending to it between the reader's look at its size
 * and its reads (grow_on 0: none). fstat is this program's: the library is
 * linked in statically and calls it; the real one is the C library's. */
static char grow_path[128];
static dev_t grow_dev;
static ino_t grow_ino;
static int grow_on;
static const char grow_line[] = "# appended while it was read\n";

static void grow_after(dev_t dev, ino_t ino)
{
    if (!grow_on || dev != grow_dev || ino != grow_ino)
        return;
    const int fd = open(grow_path, O_WRONLY | O_APPEND);
    if (fd >= 0) {
        if (write(fd, grow_line, sizeof grow_line - 1) < 0)
            grow_on = 0;
        close(fd);
    }
}

int fstat(int fd, struct stat *st)
{
    int (*real)(int, struct stat *);
    void *sym = dlsym(RTLD_NEXT, "fstat");
    memcpy(&real, &sym, sizeof real);
    const int rc = real ? real(fd, st) : -1;
    if (rc == 0)
        grow_after(st->st_dev, st->st_ino);
    return rc;
}

int fstat64(int fd, struct stat64 *st)
{
    int (*real)(int, struct stat64 *);
    void *sym = dlsym(RTLD_NEXT, "fstat64");
    memcpy(&real, &sym, sizeof real);
    const int rc = real ? real(fd, st) : -1;
    if (rc == 0)
        grow_after(st->st_dev, st->st_ino);
    return rc;
}

/* the three discs written as a text sample into path */
static int write_three(const char *path)
{
    gw_layer_sample s = test_three_discs();
    gw_err e = {{0}};
    const int rc = gw_layer_sample_write(&s, path, "three discs", &e);
    if (rc != GW_OK)
        printf("write %s: %s\n", path, e.msg);
    return rc == GW_OK;
}

/* the FNV-1a 64 of a file's bytes */
static unsigned long long file_hash(const char *path)
{
    unsigned long long h = GW_FNV1A64_INIT;
    unsigned char b[4096];
    size_t got;
    FILE *f = fopen(path, "rb");
    while (f && (got = fread(b, 1, sizeof b, f)) > 0)
        h = gw_fnv1a64(h, b, got);
    if (f)
        fclose(f);
    return h;
}

static int c_text_grows(void)
{
    snprintf(grow_path, sizeof grow_path, "%s/grow.txt", dir);
    EXPECT(write_three(grow_path));
    struct stat st;
    EXPECT(stat(grow_path, &st) == 0);
    const long long size0 = (long long)st.st_size;
    grow_dev = st.st_dev, grow_ino = st.st_ino, grow_on = 1;
    gw_layer_sample s;
    gw_err e = {{0}};
    const int rc = gw_layer_sample_read(grow_path, &s, &e);
    grow_on = 0;
    EXPECT(stat(grow_path, &st) == 0 && st.st_size > size0); /* the hook did append */
    char want[320];
    /* the size the reader took: after the hook's first append (gw_input_open's fstat) */
    snprintf(want, sizeof want, "sample: %s: more bytes than the %lld its size said when it was opened", grow_path,
             size0 + (long long)sizeof grow_line - 1);
    EXPECT(refused(rc, &e, want));
    EXPECT(s.n == 0 && !s.x && !s.springs && s.content_hash == 0);
    unlink(grow_path);
    return 0;
}

/* controls: the sample as written, and with the comment line appended before
 * it is opened: read, the content hash that of the file's bytes */
static int c_text_controls(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/still.txt", dir);
    EXPECT(write_three(path));
    for (int k = 0; k < 2; k++) {
        if (k == 1) {
            FILE *f = fopen(path, "a");
            EXPECT(f && fputs(grow_line, f) >= 0 && fclose(f) == 0);
        }
        gw_layer_sample s;
        gw_err e = {{0}};
        const int rc = gw_layer_sample_read(path, &s, &e);
        if (rc != GW_OK)
            printf("read %s: %s\n", path, e.msg);
        EXPECT(rc == GW_OK && s.n == 3 && s.content_hash == file_hash(path));
        gw_layer_sample_free(&s);
    }
    unlink(path);
    return 0;
}

/* ---- 4 HDF5 samples: their superblock before their bytes are hashed ---- */

static int append_zeros(const char *path, long n, int sparse)
{
    if (sparse) {
        struct stat st;
        return stat(path, &st) == 0 && truncate(path, st.st_size + n) == 0;
    }
    FILE *f = fopen(path, "ab");
    static const char z[65536];
    for (long k = 0; f && k < n; k += (long)sizeof z)
        if (fwrite(z, 1, n - k < (long)sizeof z ? (size_t)(n - k) : sizeof z, f) == 0)
            break;
    return f && fclose(f) == 0;
}

enum { H_SIG_ZEROS, H_ZEROS_AFTER, H_CUT, H_SB_EOF, H_SB_RESUMMED, H_AS_WRITTEN, H_SPARSE_AFTER, H_FEW_ZEROS };
typedef struct h5_row {
    const char *label;
    int kind;
    const char *named; /* NULL: read */
} h5_row;

static const h5_row h5_rows[] = {
    {"an HDF5 signature and 8 MiB of written zeros", H_SIG_ZEROS, "HDF5 file without metadata checksums (superblock "
                                                                  "version 0)"},
    {"a sample and 8 MiB of written zeros after its end", H_ZEROS_AFTER, "bytes follow it: not a sample granwave"},
    {"a sample cut short", H_CUT, "its HDF5 superblock says the file ends at byte"},
    /* (session 42) the superblock and root header copied, its end-of-file
     * address edited to 64 MiB, written zeros up to there: past the checks of
     * sizes and the root's "OHDR", hashed whole before HDF5 refused the
     * superblock's checksum; then with the checksum made right again and all
     * after the root header zeroed (the datasets' headers gone) */
    {"its superblock's end edited to 64 MiB, written zeros up to there", H_SB_EOF, "corrupt or truncated HDF5 "
                                                                                   "file"},
    {"the same with the superblock's checksum made right, all after the root header zeroed", H_SB_RESUMMED,
     "HDF5 dataset 'x' unreadable"},
    {"the sample as written (control)", H_AS_WRITTEN, NULL},
    {"8 KiB of sparse zeros after its end, as cp --sparse=always may leave (control)", H_SPARSE_AFTER, NULL},
    {"64 KiB of written zeros after its end (control)", H_FEW_ZEROS, NULL},
};
#define NH5 (sizeof h5_rows / sizeof h5_rows[0])
static const h5_row *hrow;

/* HDF5's metadata checksum (Jenkins' lookup3, the file format
 * specification's; exported by libhdf5, not in its headers) */
uint32_t H5_checksum_metadata(const void *data, size_t len, uint32_t initval);

/* path's version 2 or 3 superblock given an end-of-file address of eof, its
 * checksum left as it was (resum 0) or made right (1); with resum, the bytes
 * after the root group's object header (a version 2 header) zeroed up to the
 * file's old end, then written zeros up to eof: 1, or 0 on a failure */
static int h5_superblock_eof(const char *path, unsigned long long eof, int resum)
{
    static unsigned char b[65536];
    struct stat st;
    FILE *f = fopen(path, "r+b");
    if (!f || stat(path, &st) != 0 || st.st_size > (off_t)sizeof b || fread(b, 1, sizeof b, f) < 64 || (b[8] != 2 && b[8] != 3) || b[9] != 8) {
        if (f)
            fclose(f);
        return 0;
    }
    for (int k = 0; k < 8; k++) /* little-endian, after base and extension */
        b[28 + k] = (unsigned char)(eof >> (8 * k));
    size_t end = 0;
    if (resum) {
        const uint32_t c = H5_checksum_metadata(b, 44, 0);
        memcpy(b + 44, &c, 4); /* (x86: little-endian, as the file) */
        unsigned long long root = 0;
        for (int k = 7; k >= 0; k--)
            root = root << 8 | b[36 + k];
        /* "OHDR", version, flags, [times 16], [phase 4], chunk size (1 << (flags & 3) bytes), chunk, checksum */
        size_t at = (size_t)root + 6, w = (size_t)1 << (b[root + 5] & 3), size = 0;
        if (root + 64 > sizeof b || memcmp(b + root, "OHDR", 4) != 0) {
            fclose(f);
            return 0;
        }
        at += (b[root + 5] & 0x20 ? 16 : 0) + (b[root + 5] & 0x10 ? 4 : 0);
        for (size_t k = w; k-- > 0;)
            size = size << 8 | b[at + k];
        end = at + w + size + 4;
        if (end >= (size_t)st.st_size || end >= sizeof b) {
            fclose(f);
            return 0;
        }
        memset(b + end, 0, (size_t)st.st_size - end);
    }
    const size_t n = resum ? (size_t)st.st_size : 48;
    const int ok = fseek(f, 0, SEEK_SET) == 0 && fwrite(b, 1, n, f) == n;
    if (fclose(f) != 0 || !ok)
        return 0;
    return stat(path, &st) == 0 && append_zeros(path, (long)(eof - (unsigned long long)st.st_size), 0);
}

/* the row's file into path: GW_OK or a failure said */
static int h5_file(const char *path)
{
    static const unsigned char sig[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
    if (hrow->kind == H_SIG_ZEROS) {
        FILE *f = fopen(path, "wb");
        if (!f || fwrite(sig, 1, 8, f) != 8 || fclose(f) != 0)
            return 0;
        return append_zeros(path, 8L << 20, 0);
    }
    gw_layer_sample s = test_three_discs();
    gw_err e = {{0}};
    if (gw_layer_sample_write(&s, path, NULL, &e) != GW_OK) {
        printf("write %s: %s\n", path, e.msg);
        return 0;
    }
    struct stat st;
    switch (hrow->kind) {
    case H_ZEROS_AFTER:
        return append_zeros(path, 8L << 20, 0);
    case H_CUT:
        return stat(path, &st) == 0 && truncate(path, st.st_size - 100) == 0;
    case H_SB_EOF:
    case H_SB_RESUMMED:
        return h5_superblock_eof(path, 64ULL << 20, hrow->kind == H_SB_RESUMMED);
    case H_SPARSE_AFTER:
        return append_zeros(path, 8192, 1);
    case H_FEW_ZEROS:
        return append_zeros(path, 65536, 0);
    default:
        return 1;
    }
}

static int c_h5_read(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/h%d.h5", dir, (int)(hrow - h5_rows));
    EXPECT(h5_file(path));
    gw_layer_sample s;
    gw_err e = {{0}};
    const long long r0 = test_bytes_read();
    const int rc = gw_layer_sample_read(path, &s, &e);
    const long long got = test_bytes_read() - r0;
    if (!hrow->named) {
        if (rc != GW_OK)
            printf("read %s: %s\n", path, e.msg);
        EXPECT(rc == GW_OK && s.n == 3 && s.x[1] == 0.5);
        gw_layer_sample_free(&s);
    } else {
        if (rc != GW_EFORMAT || !strstr(e.msg, path) || !strstr(e.msg, hrow->named))
            printf("status %d '%s' (wanted GW_EFORMAT naming '%s')\n", rc, e.msg, hrow->named);
        EXPECT(r0 < 0 || got < (1LL << 20)); /* refused before it was hashed: under 1 MiB read */
    }
    unlink(path);
    return 0;
}

/* a sweep naming the sample: refused (or taken) before its bytes are hashed */
static int c_h5_sweep(void)
{
    char path[128], ini[160], text[512];
    snprintf(path, sizeof path, "%s/w%d.h5", dir, (int)(hrow - h5_rows));
    snprintf(ini, sizeof ini, "%s/w%d.ini", dir, (int)(hrow - h5_rows));
    EXPECT(h5_file(path));
    snprintf(text, sizeof text, "[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = %s\nt-max = 0.002\n",
             path);
    FILE *f = fopen(ini, "w");
    EXPECT(f && fputs(text, f) >= 0 && fclose(f) == 0);
    const gw_sweep_model *layer[] = {&gw_layer_sweep_model}, *m = NULL;
    gw_sweep_config cfg;
    gw_err e = {{0}};
    const long long r0 = test_bytes_read();
    const int rc = gw_sweep_config_read(ini, layer, 1, &cfg, &m, &e);
    const long long got = test_bytes_read() - r0;
    if (rc == GW_OK)
        gw_sweep_config_free(&cfg);
    if (!hrow->named) {
        if (rc != GW_OK)
            printf("config: %s\n", e.msg);
        EXPECT(rc == GW_OK);
    } else {
        if (rc == GW_OK || !strstr(e.msg, hrow->named))
            printf("status %d '%s' (wanted a refusal naming '%s')\n", rc, e.msg, hrow->named);
        EXPECT(r0 < 0 || got < (1LL << 20));
    }
    unlink(path);
    unlink(ini);
    return 0;
}

int main(void)
{
    if (test_scratch_dir(dir, sizeof dir, "left46") != 0)
        return 1;
    int nfail = 0, ncases = 0;
    for (size_t r = 0; r < NRES; r++) {
        rrow = &res_rows[r];
        child_casef(c_result, &nfail, &ncases, "gw_layer_make_result_check: %s", rrow->label);
    }
    child_case("gw_layer_make_result_check: a settled result, two real pluviations (controls)", c_result_real, &nfail,
               &ncases);
    static const child_row spr_calls[] = {
        {"gw_layer_impact_settled_check (other_settling 0, 1)", c_spring_settled},
        {"gw_layer_impact_check and gw_layer_impact under zero_springs", c_spring_zero},
        {"gw_layer_sample_porosity, gw_layer_impact_dem_dt, gw_layer_sample_pile_hash", c_spring_numbers},
    };
    for (size_t r = 0; r < NSPR; r++)
        for (size_t c = 0; c < sizeof spr_calls / sizeof spr_calls[0]; c++) {
            srow = &spr_rows[r];
            child_casef(spr_calls[c].fn, &nfail, &ncases, "spring %s: %s", srow->label, spr_calls[c].label);
        }
    child_case("gw_layer_sample_read: a text sample appended to while it is read", c_text_grows, &nfail, &ncases);
    child_case("gw_layer_sample_read: the text sample still, and appended before it is opened (controls)",
               c_text_controls, &nfail, &ncases);
#if GW_HAVE_HDF5
    for (size_t r = 0; r < NH5; r++) {
        hrow = &h5_rows[r];
        child_casef(c_h5_read, &nfail, &ncases, "gw_layer_sample_read: %s", hrow->label);
        child_casef(c_h5_sweep, &nfail, &ncases, "gw_sweep_config_read: %s", hrow->label);
    }
#else
    (void)c_h5_read, (void)c_h5_sweep, (void)NH5;
    printf("(no HDF5 in this build: its samples' cases skipped)\n");
#endif
    rmdir(dir);
    return child_cases_end(nfail, ncases);
}
