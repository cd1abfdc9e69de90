/*
 * test_layer_sweep_memo.c: the layer sweep model's check (the check pass of
 * `granwave sweep`, and `sweep --check`) reads and checks each sample file
 * once and keeps it, keyed by the path and the hash of the file's bytes, in
 * a memo the caller holds over the pass (gw_sweep_case_check,
 * gw_sweep_checks_end; layer_sweep_model.c). The memo must never hide a
 * change:
 *  - a sample rewritten in place between two checks, with the same size and
 *    its modification time set back (the same inode, size and mtime: what a
 *    memo keyed by file identity would take for the same file), is refused
 *    (its porosity header edited: 0.183 -> 0.283), then accepted when
 *    restored; replaced by a FIFO, refused without blocking;
 *  - two samples in one grid (a good one and one whose width was edited) are
 *    each checked, alternately, and a fifth file evicts the oldest kept;
 *  - every verdict and message equals gw_layer_impact_setup_check's (the
 *    check without the memo) over 24 cases: block sizes, heights and
 *    abscissae, some outside the box.
 * A guard: it passes on the code before (which read every case's file).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gw_layer.h"
#include "gw_layer_study.h"
#include "gw_param.h"
#include "gw_sweep.h"
#include "gw_test.h"
#include "gw_test_files.h"

#ifndef GW_SOURCE_DIR
#define GW_SOURCE_DIR "."
#endif
#define MEMO_FILES_FOR_TEST 6 /* more than the memo's 4 slots */

/* Write bytes over the file in place (same inode), keeping its mtime. */
static int overwrite(const char *path, const char *bytes, long len)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return -1;
    FILE *f = fopen(path, "r+b");
    if (!f)
        return -1;
    int ok = fwrite(bytes, 1, (size_t)len, f) == (size_t)len;
    ok &= fclose(f) == 0;
    const struct timespec t[2] = {st.st_atim, st.st_mtim};
    return ok && utimensat(AT_FDCWD, path, t, 0) == 0 ? 0 : -1;
}

/* The model's check of one case (sample, x, rb-rm, height-rm), through the
 * memo *memo of the pass (as the sweep's check pass calls it). */
static int model_check(void **memo, const char *sample, const char *x, const char *rb, const char *h, gw_err *err)
{
    const char *names[] = {"sample", "x", "rb-rm", "height-rm"}, *values[] = {sample, x, rb, h};
    memset(err, 0, sizeof *err);
    return gw_sweep_case_check(&gw_layer_sweep_model, memo, 4, names, values, err);
}

/* The same case through gw_layer_impact_setup_check (no memo), its status as the model maps it. */
static int plain_check(const char *sample, const char *x, const char *rb, const char *h, gw_err *err)
{
    gw_layer_impact_setup s;
    memset(err, 0, sizeof *err);
    int rc = gw_layer_impact_setup_init(&s);
    const char *names[] = {"sample", "x", "rb-rm", "height-rm"}, *values[] = {sample, x, rb, h};
    for (int i = 0; rc == GW_OK && i < 4; i++)
        rc = gw_param_set(gw_layer_impact_setup_params(), &s, names[i], values[i], err);
    if (rc == GW_OK)
        rc = gw_layer_impact_setup_check(&s, err);
    gw_layer_impact_setup_clear(&s);
    return rc == GW_OK || rc == GW_ENOMEM ? rc : GW_EINVAL;
}

int main(void)
{
    char dir[] = "/tmp/gw_sweep_memo_XXXXXX";
    if (!mkdtemp(dir))
        return 1;
    char a[64], b[64], fifo[64], other[MEMO_FILES_FOR_TEST][64];
    snprintf(a, sizeof a, "%s/a.txt", dir), snprintf(b, sizeof b, "%s/b.txt", dir);
    snprintf(fifo, sizeof fifo, "%s/fifo.txt", dir);
    long len;
    char *good = gw_test_slurp(GW_SOURCE_DIR "/data/measured/layer_diagram_8000/sample.txt", &len);
    if (!good || gw_test_write_bytes(a, good, (size_t)len) != 0)
        return 1;
    gw_err err;
    void *memo = NULL; /* one pass of checks over every case below */

    /* 1. rewritten in place: same size, same inode, mtime set back */
    gw_test_true(model_check(&memo, a, "0", "1", "0", &err) == GW_OK, "a.txt (the stored sample) passes");
    gw_test_true(memo != NULL, "the pass's memo holds what it read (the caller's, not the library's)");
    char *bad = malloc((size_t)len + 1), *p;
    memcpy(bad, good, (size_t)len + 1);
    p = strstr(bad, "\nporosity 0.1");
    if (!p)
        return 1;
    p[12] = '2'; /* porosity 0.18309... -> 0.28309... */
    struct stat s0, s1;
    stat(a, &s0);
    gw_test_true(overwrite(a, bad, len) == 0, "a.txt rewritten in place");
    stat(a, &s1);
    gw_test_true(s0.st_ino == s1.st_ino && s0.st_size == s1.st_size &&
                 s0.st_mtim.tv_sec == s1.st_mtim.tv_sec && s0.st_mtim.tv_nsec == s1.st_mtim.tv_nsec,
                 "the same inode, size and modification time");
    int rc = model_check(&memo, a, "0", "1", "0", &err);
    gw_test_true(rc == GW_EINVAL && strstr(err.msg, "a.txt") && strstr(err.msg, "porosity"),
                 "then refused: its porosity header is no longer its particles'");
    printf("  %s\n", err.msg);
    overwrite(a, good, len);
    gw_test_true(model_check(&memo, a, "0", "1", "0", &err) == GW_OK, "restored: passes again");
    /* replaced by a FIFO: refused, not blocking (the hash opens regular files only) */
    if (mkfifo(fifo, 0600) == 0) {
        rc = model_check(&memo, fifo, "0", "1", "0", &err);
        gw_test_true(rc == GW_EINVAL && strstr(err.msg, "fifo.txt"), "a FIFO of a sample's name: refused");
    }

    /* 2. two samples in one grid, alternately; then more files than the memo keeps */
    p = strstr(good, "\nwidth 16.25");
    if (!p)
        return 1;
    memcpy(bad, good, (size_t)len + 1);
    bad[p - good + 7] = '9'; /* width 16.25 -> 96.25: the packing no longer fills the box */
    gw_test_write_bytes(b, bad, (size_t)len);
    int alt = 0;
    for (int k = 0; k < 6; k++) {
        const int ra = model_check(&memo, a, "0", "1", "0", &err);
        const int rb = model_check(&memo, b, "0", "1", "0", &err);
        alt += ra == GW_OK && rb == GW_EINVAL && strstr(err.msg, "b.txt") && strstr(err.msg, "width");
    }
    gw_test_true(alt == 6, "a grid over a.txt and b.txt (width edited): each checked, 6 times alternately");
    int each = 0;
    /* the good ones each another pile: the last radius 0.2528140(7)1904... with its
     * 8th decimal 6, 5, 4 (1e-8 to 3e-8 m smaller); copies of a.txt are its pile,
     * which the pass refuses to see under two names */
    char *near = malloc((size_t)len + 1);
    if (!near || good[len - 11] != '7')
        return 1;
    for (int k = 0; k < MEMO_FILES_FOR_TEST; k++) {
        snprintf(other[k], sizeof other[k], "%s/c%d.txt", dir, k);
        memcpy(near, good, (size_t)len + 1);
        near[len - 11] = (char)('6' - k / 2);
        gw_test_write_bytes(other[k], k % 2 ? bad : near, (size_t)len);
    }
    free(near);
    for (int round = 0; round < 2; round++)
        for (int k = 0; k < MEMO_FILES_FOR_TEST; k++)
            each += model_check(&memo, other[k], "0", "1", "0", &err) == (k % 2 ? GW_EINVAL : GW_OK);
    gw_test_true(each == 2 * MEMO_FILES_FOR_TEST, "6 files, twice round (more than the memo keeps): each its verdict");

    /* 3. the memo's verdicts and messages are the plain check's */
    const char *xs[] = {"0", "5", "-7.9", "40"}, *rbs[] = {"1", "10", "30"}, *hs[] = {"0", "8"};
    int same = 0, cases = 0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 2; k++) {
                gw_err e1, e2;
                const int r1 = model_check(&memo, a, xs[i], rbs[j], hs[k], &e1), r2 = plain_check(a, xs[i], rbs[j], hs[k], &e2);
                cases++;
                same += r1 == r2 && strcmp(e1.msg, e2.msg) == 0;
                if (r1 != r2 || strcmp(e1.msg, e2.msg) != 0)
                    printf("  x %s rb-rm %s height-rm %s: %d '%s' / plain %d '%s'\n", xs[i], rbs[j], hs[k], r1, e1.msg,
                           r2, e2.msg);
            }
    gw_test_true(same == cases, "24 cases: the same status and message as gw_layer_impact_setup_check");

    gw_sweep_checks_end(&gw_layer_sweep_model, memo);
    for (int k = 0; k < MEMO_FILES_FOR_TEST; k++)
        remove(other[k]);
    remove(a), remove(b), remove(fifo), rmdir(dir);
    free(good), free(bad);
    return gw_test_summary("test_layer_sweep_memo");
}
