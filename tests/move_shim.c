/*
 * move_shim.c: an LD_PRELOAD library that runs a shell command (moving the
 * sweep's directory, say) right before a chosen row is appended to a sweep
 * journal, to test a sweep whose directory is moved, removed or replaced
 * while it runs at a point of its work, not after a sleep
 * (tests/test_sweep_dir_moved.sh, issue 18). Not linked into anything; glibc
 * and Linux (/proc/self/fd) only.
 *
 * Environment:
 *   GW_MOVE_AT=K     before the K-th write(2) (from 1, every thread) that
 *                    appends to a sweep journal (a row: the head is written
 *                    before the journal is opened for appending), run
 *   GW_MOVE_RUN=CMD  with system(3), once, then write; the command's status
 *                    goes to stderr when it is not 0.
 *   GW_MOVE_COUNT=FILE at exit, write "rows N" (the journal writes seen) to
 *                    FILE.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <fcntl.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static atomic_long rows;

typedef ssize_t write_fn(int, const void *, size_t);

/* fd is open for appending on a file whose name begins "journal.csv": a
 * journal a sweep resumed, or made (its fd is of the name it was written
 * under, "journal.csv.new.PID.XXXXXX", linked to journal.csv, the head
 * written before O_APPEND was set); its directory may have moved since */
static int is_journal(int fd)
{
    const int fl = fcntl(fd, F_GETFL);
    if (fl < 0 || !(fl & O_APPEND))
        return 0;
    char link[64], name[4096];
    snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    const ssize_t n = readlink(link, name, sizeof name - 1);
    if (n <= 0)
        return 0;
    name[n] = '\0';
    const char *slash = strrchr(name, '/');
    return slash && strncmp(slash + 1, "journal.csv", 11) == 0;
}

ssize_t write(int fd, const void *buf, size_t len)
{
    if (fd > 2 && is_journal(fd)) {
        const long n = atomic_fetch_add(&rows, 1) + 1;
        const char *at = getenv("GW_MOVE_AT"), *cmd = getenv("GW_MOVE_RUN");
        if (at && cmd && atol(at) == n) {
            const int st = system(cmd);
            if (st != 0)
                fprintf(stderr, "move_shim: '%s' returned %d\n", cmd, st);
        }
    }
    write_fn *real;
    void *sym = dlsym(RTLD_NEXT, "write");
    memcpy(&real, &sym, sizeof real);
    return real(fd, buf, len);
}

__attribute__((destructor)) static void report(void)
{
    const char *path = getenv("GW_MOVE_COUNT");
    FILE *f = path ? fopen(path, "w") : NULL;
    if (f) {
        fprintf(f, "rows %ld\n", atomic_load(&rows));
        fclose(f);
    }
}
