/*
 * stat_fail_shim.c: an LD_PRELOAD library that makes stat() fail for one
 * file, as it does for a file the caller may not reach (EACCES), on a failing
 * disk (EIO) or through a loop of links (ELOOP), with the buffer left as a
 * failed stat may leave it: here filled as an empty regular file, so that a
 * caller that reads it after the failure acts on it visibly
 * (tests/test_hostile_inputs43.sh). Not linked into anything; glibc only.
 *
 * Environment:
 *   GW_STAT_FAIL=PATH  stat(PATH) (that exact string) fills its buffer as an
 *                      empty regular file and returns -1 with errno EIO.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

typedef int stat_fn(const char *, struct stat *);

/* 1 (the buffer filled, errno EIO) when path is the one to fail */
static int fails(const char *path, void *st, size_t size)
{
    const char *fail = getenv("GW_STAT_FAIL");
    if (!fail || !path || !st || strcmp(path, fail) != 0)
        return 0;
    memset(st, 0, size);
    ((struct stat *)st)->st_mode = S_IFREG | 0644; /* st_mode: the same place in stat and stat64 */
    errno = EIO;
    return 1;
}

int stat(const char *path, struct stat *st)
{
    if (fails(path, st, sizeof *st))
        return -1;
    stat_fn *real;
    void *sym = dlsym(RTLD_NEXT, "stat");
    memcpy(&real, &sym, sizeof real);
    if (!real) {
        errno = ENOSYS;
        return -1;
    }
    return real(path, st);
}

typedef int stat64_fn(const char *, struct stat64 *);

int stat64(const char *path, struct stat64 *st)
{
    if (fails(path, st, sizeof *st))
        return -1;
    stat64_fn *real;
    void *sym = dlsym(RTLD_NEXT, "stat64");
    memcpy(&real, &sym, sizeof real);
    if (!real) {
        errno = ENOSYS;
        return -1;
    }
    return real(path, st);
}
