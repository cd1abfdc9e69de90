/*
 * test_sweep_journal_close.c: a sweep's journal closed frees the copy kept
 * of it (issue 18). A journal opened by gw_sweep_journal_open_at is checked
 * before each row against a copy of what the sweep wrote into it (its text
 * at the open and each row since: a rewrite in place, `> journal.csv`, is
 * found and the journal kept whole as journal.kept.csv). The copies sit in
 * 16 slots by descriptor and were freed only at exit, so a process that
 * opened journals in turn, each closed, kept them all: the 17th journal held
 * at once with another descriptor got no slot and went unchecked (its
 * rewrite taken, rows appended into the other content). gw_sweep_journal_close
 * (gw_sweep_impl.h, what `granwave sweep` closes its journal with) frees the
 * slot. Here 24 journals in turn, each on a descriptor of its own (each
 * closed number then taken by /dev/null, as a process's other files would), each cut to nothing after
 * its first row: every one is found written into and kept (GW_EIO,
 * restored 2, journal.kept.csv holding the row), and each descriptor is
 * closed. With gw_sweep_journal_close a plain close() (the code before),
 * journals 17 to 24 are taken as they are: 16 of its 96 checks fail.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gw_common.h"
#include "gw_sweep.h"
#include "gw_sweep_impl.h"
#include "gw_test.h"

#define NJOURNALS 24

static const char *const cols[] = {"y"};

static int has_key(const char *name)
{
    return strcmp(name, "a") == 0;
}

static int run(int nk, const char *const *names, const char *const *values, double *out,
               unsigned long long *read_hash, gw_err *err)
{
    (void)nk, (void)names, (void)values, (void)read_hash, (void)err;
    out[0] = 1;
    return GW_OK;
}

static const gw_sweep_model fake = {"fake", 1, cols, has_key, run, NULL, NULL, NULL, NULL, NULL, NULL};

int main(void)
{
    const gw_sweep_model *models[] = {&fake};
    gw_sweep_config cfg;
    const gw_sweep_model *m = NULL;
    gw_err err = {{0}};
    char base[] = "/tmp/gw_journal_close_XXXXXX";
    if (!mkdtemp(base) ||
        gw_sweep_config_read_string("[sweep]\nmodel = fake\n[grid]\na = 1, 2\n", "fake.ini", models, 1, &cfg, &m,
                                    &err) != GW_OK) {
        GW_TEST_OK(0, "set up: %s", err.msg);
        return gw_test_summary("test_sweep_journal_close");
    }
    int held[NJOURNALS];
    const int null = open("/dev/null", O_RDONLY | O_CLOEXEC);
    for (int j = 0; j < NJOURNALS; j++) {
        char dir[256], path[300], kept[300], row[512];
        snprintf(dir, sizeof dir, "%s/s%02d", base, j);
        snprintf(path, sizeof path, "%s/journal.csv", dir);
        snprintf(kept, sizeof kept, "%s/journal.kept.csv", dir);
        held[j] = -1;
        char done[2] = {0, 0};
        long ndone = 0;
        int fd = -1, dirfd = -1, restored = 0;
        const double y = 1;
        int rc = mkdir(dir, 0700) == 0 ? gw_sweep_journal_open_at(dir, &cfg, done, &ndone, &fd, &dirfd, &err)
                                       : GW_EIO;
        if (rc == GW_OK)
            rc = gw_sweep_format_row(&cfg, 0, &y, 1, 0, row, sizeof row);
        if (rc == GW_OK)
            rc = gw_sweep_journal_append(fd, row, NULL, &err);
        GW_TEST_OK(rc == GW_OK, "journal %d: opened (descriptor %d) and a row appended: %s", j + 1, fd,
                   rc == GW_OK ? "ok" : err.msg);
        if (rc != GW_OK)
            continue;
        /* rewritten in place: the same file, cut to nothing */
        const int t = open(path, O_WRONLY | O_TRUNC);
        if (t >= 0)
            close(t);
        rc = gw_sweep_journal_held(dirfd, &fd, dir, &restored, &err);
        GW_TEST_OK(rc == GW_EIO && restored == 2 && strstr(err.msg, "written into"),
                   "journal %d: its rewrite found (status %d, restored %d: %s)", j + 1, rc, restored,
                   rc == GW_OK ? "taken as it is" : err.msg);
        struct stat st;
        GW_TEST_OK(stat(kept, &st) == 0 && (size_t)st.st_size > strlen(row),
                   "journal %d: kept whole as journal.kept.csv (%lld bytes)", j + 1,
                   stat(kept, &st) == 0 ? (long long)st.st_size : -1LL);
        gw_sweep_journal_close(fd);
        errno = 0;
        const int closed = fcntl(fd, F_GETFD) == -1 && errno == EBADF;
        GW_TEST_OK(closed, "journal %d: its descriptor %d (the kept file's) closed", j + 1, fd);
        held[j] = dup2(null, fd); /* its number taken: the next journal's descriptor another */
        close(dirfd);
        unlink(path);
        unlink(kept);
        rmdir(dir);
    }
    for (int j = 0; j < NJOURNALS; j++)
        if (held[j] >= 0)
            close(held[j]);
    close(null);
    gw_sweep_journal_close(-1); /* nothing */
    rmdir(base);
    gw_sweep_config_free(&cfg);
    return gw_test_summary("test_sweep_journal_close");
}
