/*
 * test_hash_memo.c: the content hashes a sweep keeps from one case to the
 * next (gw_io_hash_memo, common/gw_io_hash_memo.c). A sweep hashed its
 * sample after each case and again in the check pass of each case (1.5 ms
 * per MiB each); the memo hashes a file once while stat finds it as it was,
 * and a changed file must still be found changed:
 *  - a file older than GW_HASH_MEMO_SETTLE_S s, asked 4 times: hashed once,
 *    each answer gw_fnv1a64 of its bytes;
 *  - the same file edited in place (same size, one byte) and its
 *    modification time set back (utimensat: its status-change time moves
 *    on): hashed again, the new bytes' hash;
 *  - another file of the same size and modification time renamed over it
 *    (another inode): hashed again, its hash;
 *  - a file written just now (within the settle time: a write in the same
 *    clock tick could keep its times): hashed at every call;
 *  - a refused file (the function's error): its status and message given,
 *    nothing kept (asked again: hashed again);
 *  - no memo (NULL): hashed at every call.
 * The first check needs files GW_HASH_MEMO_SETTLE_S s old: the test sleeps
 * that long plus one second.
 */
#define _POSIX_C_SOURCE 200809L
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gw_common.h"
#include "gw_io_impl.h"
#include "gw_test.h"

static long calls; /* the hashes the memo asked for */

static int counted_hash(const char *path, unsigned long long *h, gw_err *err)
{
    calls++;
    return gw_fnv1a64_file(path, "test", h, err);
}

static int refusing_hash(const char *path, unsigned long long *h, gw_err *err)
{
    (void)h;
    calls++;
    return gw_err_set(err, GW_EFORMAT, "sample '%s': refused", path);
}

static int write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    const int ok = fputs(text, f) >= 0;
    return fclose(f) == 0 && ok;
}

static unsigned long long text_hash(const char *text)
{
    return gw_fnv1a64(GW_FNV1A64_INIT, text, strlen(text));
}

/* path's hash through m, and whether fn was called (*hashed) */
static unsigned long long through(gw_hash_memo *m, const char *path, int *hashed)
{
    unsigned long long h = 0;
    gw_err e = {{0}};
    const long before = calls;
    const int rc = gw_io_hash_memo(m, path, counted_hash, &h, &e);
    *hashed = calls > before;
    return rc == GW_OK ? h : 0;
}

int main(void)
{
    char dir[] = "/tmp/gw_hash_memo_XXXXXX";
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    char a[128], b[128], c[128], d[128], fresh[128];
    snprintf(a, sizeof a, "%s/a.txt", dir);
    snprintf(b, sizeof b, "%s/b.txt", dir);
    snprintf(c, sizeof c, "%s/c.txt", dir);
    snprintf(d, sizeof d, "%s/d.txt", dir);
    snprintf(fresh, sizeof fresh, "%s/fresh.txt", dir);
    const char *ta = "# sample a\n0 0 1\n", *tb = "# sample b\n0 0 1\n", *tb2 = "# sample B\n0 0 1\n",
               *tc = "# sample c\n0 0 1\n", *td = "# sample d\n0 0 1\n";
    gw_test_true(write_text(a, ta) && write_text(b, tb) && write_text(c, tc), "three files written");
    sleep(GW_HASH_MEMO_SETTLE_S + 1);
    gw_hash_memo m = {0};
    int hashed, n = 0, right = 1;

    /* 1: asked 4 times, hashed once */
    for (int i = 0; i < 4; i++) {
        right &= through(&m, a, &hashed) == text_hash(ta);
        n += hashed;
    }
    GW_TEST_OK(right && n == 1, "a settled file asked 4 times: hashed %d time(s) (1), its hash each time", n);

    /* 2: edited in place, same size, its modification time set back */
    right = through(&m, b, &hashed) == text_hash(tb);
    struct stat st;
    int fd = open(b, O_WRONLY);
    const int edited = fd >= 0 && fstat(fd, &st) == 0 && pwrite(fd, "B", 1, 9) == 1 &&
                       futimens(fd, (struct timespec[2]){st.st_atim, st.st_mtim}) == 0;
    if (fd >= 0)
        close(fd);
    struct stat st2;
    gw_test_true(edited && stat(b, &st2) == 0 && st2.st_size == st.st_size &&
                 st2.st_mtim.tv_sec == st.st_mtim.tv_sec && st2.st_mtim.tv_nsec == st.st_mtim.tv_nsec,
                 "b edited in place: the same size and modification time");
    const unsigned long long hb = through(&m, b, &hashed);
    GW_TEST_OK(right && hashed && hb == text_hash(tb2),
               "b edited in place (size and mtime kept): hashed again (%d), the new bytes' hash (%d)", hashed,
               hb == text_hash(tb2));

    /* 3: another file of the same size and times renamed over it */
    right = through(&m, c, &hashed) == text_hash(tc);
    struct stat sc;
    const int moved = stat(c, &sc) == 0 && write_text(d, td) &&
                      utimensat(AT_FDCWD, d, (struct timespec[2]){sc.st_atim, sc.st_mtim}, 0) == 0 &&
                      rename(d, c) == 0;
    gw_test_true(moved, "d (same size, c's times) renamed over c");
    const unsigned long long hc = through(&m, c, &hashed);
    GW_TEST_OK(right && hashed && hc == text_hash(td), "another file renamed over c: hashed again (%d), its hash (%d)",
               hashed, hc == text_hash(td));

    /* 4: a file written just now: hashed at every call */
    gw_test_true(write_text(fresh, ta), "a fresh file");
    n = 0;
    for (int i = 0; i < 3; i++) {
        (void)through(&m, fresh, &hashed);
        n += hashed;
    }
    GW_TEST_OK(n == 3, "a file written within the settle time: hashed at every call (%d of 3)", n);

    /* 5: a refused file: the function's status, nothing kept */
    gw_err e = {{0}};
    unsigned long long h = 0;
    long before = calls;
    int rc1 = gw_io_hash_memo(&m, a, refusing_hash, &h, &e); /* a is kept: its hash, no call */
    GW_TEST_OK(rc1 == GW_OK && h == text_hash(ta) && calls == before, "a kept file: its hash without a call");
    char r[128];
    snprintf(r, sizeof r, "%s/r.txt", dir);
    gw_test_true(write_text(r, ta), "r written");
    before = calls;
    rc1 = gw_io_hash_memo(&m, r, refusing_hash, &h, &e);
    const int rc2 = gw_io_hash_memo(&m, r, refusing_hash, &h, &e);
    GW_TEST_OK(rc1 == GW_EFORMAT && rc2 == GW_EFORMAT && calls == before + 2 && strstr(e.msg, "refused"),
               "a refused file: GW_EFORMAT and its message, asked twice: hashed twice (%ld)", calls - before);

    /* 6: no memo */
    n = 0;
    for (int i = 0; i < 2; i++) {
        (void)through(NULL, a, &hashed);
        n += hashed;
    }
    GW_TEST_OK(n == 2, "no memo: hashed at every call (%d of 2)", n);
    gw_io_hash_memo_free(&m);
    gw_io_hash_memo_free(NULL);
    GW_TEST_OK(m.n == 0 && !m.seen, "freed: the memo zeroed");

    unlink(a), unlink(b), unlink(c), unlink(fresh), unlink(r);
    rmdir(dir);
    return gw_test_summary("test_hash_memo");
}
