/*
 * gw_io.c: atomic files (temporary name, fsync, rename), directories, paths.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <pthread.h>
#include <time.h>
#include <unistd.h>

#include "gw_common.h"

_Static_assert(sizeof(sigset_t) <= sizeof(((gw_afile *)0)->oldmask), "sigset_t does not fit");

static void hold_signals(gw_afile *f)
{
    sigset_t s;
    sigemptyset(&s);
    sigaddset(&s, SIGINT);
    sigaddset(&s, SIGTERM);
    sigaddset(&s, SIGHUP);
    f->masked = pthread_sigmask(SIG_BLOCK, &s, (sigset_t *)(void *)f->oldmask) == 0;
}

static void release_signals(gw_afile *f)
{
    if (f->masked)
        pthread_sigmask(SIG_SETMASK, (sigset_t *)(void *)f->oldmask, NULL);
    f->masked = 0;
}

int gw_afile_open(gw_afile *f, const char *path, gw_err *err)
{
    memset(f, 0, sizeof *f);
    hold_signals(f);
    if (strlen(path) >= sizeof f->path)
        return gw_err_set(err, GW_EINVAL, "%s: path too long", path);
    snprintf(f->path, sizeof f->path, "%s", path);
    snprintf(f->tmp, sizeof f->tmp, "%s.tmp.XXXXXX", path);
    int fd = mkstemp(f->tmp);
    if (fd < 0) {
        f->tmp[0] = '\0';
        int e = errno;
        release_signals(f);
        return gw_err_set(err, GW_EIO, "%s: cannot create: %s", path, strerror(e));
    }
    fchmod(fd, 0644);
    f->fp = fdopen(fd, "w");
    if (!f->fp) {
        int e = errno;
        close(fd);
        unlink(f->tmp);
        f->tmp[0] = '\0';
        release_signals(f);
        return gw_err_set(err, GW_EIO, "%s: cannot open: %s", path, strerror(e));
    }
    return GW_OK;
}

int gw_afile_commit(gw_afile *f, gw_err *err)
{
    if (!f->fp) {
        release_signals(f);
        return gw_err_set(err, GW_EIO, "%s: file not open", f->path);
    }
    int bad = ferror(f->fp) || fflush(f->fp) != 0 || fsync(fileno(f->fp)) != 0;
    int saved = errno;
    if (fclose(f->fp) != 0)
        bad = 1;
    f->fp = NULL;
    if (bad || rename(f->tmp, f->path) != 0) {
        if (!bad)
            saved = errno;
        unlink(f->tmp);
        f->tmp[0] = '\0';
        release_signals(f);
        return gw_err_set(err, GW_EIO, "%s: write failed: %s", f->path, strerror(saved));
    }
    f->tmp[0] = '\0';
    release_signals(f);
    return GW_OK;
}

void gw_afile_abort(gw_afile *f)
{
    if (f->fp) {
        fclose(f->fp);
        f->fp = NULL;
    }
    if (f->tmp[0]) {
        unlink(f->tmp);
        f->tmp[0] = '\0';
    }
    release_signals(f);
}

int gw_mkdir_p(const char *path, gw_err *err)
{
    char buf[4096];
    size_t n = strlen(path);
    if (n == 0 || n >= sizeof buf)
        return gw_err_set(err, GW_EINVAL, "output directory: bad path '%s'", path);
    memcpy(buf, path, n + 1);
    for (size_t i = 1; i <= n; i++) {
        if (buf[i] == '/' || buf[i] == '\0') {
            char c = buf[i];
            buf[i] = '\0';
            if (mkdir(buf, 0755) != 0 && errno != EEXIST)
                return gw_err_set(err, GW_EIO, "%s: cannot create directory: %s", buf,
                                  strerror(errno));
            buf[i] = c;
        }
    }
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISDIR(st.st_mode))
        return gw_err_set(err, GW_EIO, "%s: not a directory", path);
    return GW_OK;
}

int gw_path_join(char *buf, size_t n, const char *dir, const char *name)
{
    int w = snprintf(buf, n, "%s/%s", dir, name);
    return (w < 0 || (size_t)w >= n) ? GW_EINVAL : GW_OK;
}

int gw_write_text(const char *path, const char *text, gw_err *err)
{
    gw_afile f;
    int rc = gw_afile_open(&f, path, err);
    if (rc != GW_OK)
        return rc;
    fputs(text, f.fp);
    return gw_afile_commit(&f, err);
}

double gw_clock_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}
