/*
 * gw_io_input.c: the one way inputs are opened: regular files only (a FIFO,
 * device or directory is refused before any read, so nothing can block), and
 * whole files read bounded in size. Separate from the outputs (gw_io_afile.c,
 * gw_io_outset.c, gw_io_paths.c): an input is never written.
 */
#define _GNU_SOURCE /* SEEK_HOLE (gw_input_hole) */
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gw_common.h"
#include "gw_locale.h"
#include "gw_io_impl.h"
#include "gw_io_lines.h"

const char *gw_io_file_kind(mode_t m)
{
    return S_ISFIFO(m) ? "a FIFO" : S_ISCHR(m) ? "a character device" : S_ISBLK(m) ? "a block device"
         : S_ISDIR(m) ? "a directory" : S_ISSOCK(m) ? "a socket" : "not a regular file";
}

int gw_input_open(const char *path, const char *what, FILE **out, gw_err *err)
{
    if (!out)
        return gw_err_set(err, GW_EINVAL, "gw_input_open: out is NULL");
    *out = NULL;
    /* NULL named as NULL (the library's rule; it was "input: empty file name") */
    if (!path)
        return gw_err_set(err, GW_EINVAL, "gw_input_open: path is NULL");
    if (!what)
        what = "input";
    if (!*path)
        return gw_err_set(err, GW_EINVAL, "%s: empty file name", what);
    /* O_NONBLOCK: opening a FIFO without a writer would block until one comes */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) {
        int e = errno;
        return gw_err_set(err, gw_io_status(e), "%s: %s: cannot open: %s", what, path, strerror(e));
    }
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return gw_err_set(err, GW_EIO, "%s: %s: cannot read: %s", what, path, strerror(e));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return gw_err_set(err, GW_EINVAL, "%s: %s is %s; give a regular file", what, path,
                          gw_io_file_kind(st.st_mode));
    }
    int fl = fcntl(fd, F_GETFL);
    if (fl != -1)
        fcntl(fd, F_SETFL, fl & ~O_NONBLOCK);
    FILE *fp = fdopen(fd, "rb");
    if (!fp) {
        int e = errno;
        close(fd);
        return gw_err_set(err, gw_io_status(e), "%s: %s: cannot open: %s", what, path, strerror(e));
    }
    *out = fp;
    return GW_OK;
}

int gw_input_check(const char *path, const char *what, gw_err *err)
{
    if (!path)
        return gw_err_set(err, GW_EINVAL, "gw_input_check: path is NULL");
    FILE *fp = NULL;
    int rc = gw_input_open(path, what, &fp, err);
    if (fp)
        fclose(fp);
    return rc;
}

int gw_input_read(const char *path, const char *what, size_t max, char **out, size_t *len,
                  gw_err *err)
{
    if (!out)
        return gw_err_set(err, GW_EINVAL, "gw_input_read: out is NULL");
    *out = NULL;
    if (len)
        *len = 0;
    if (!path)
        return gw_err_set(err, GW_EINVAL, "gw_input_read: path is NULL");
    FILE *fp = NULL;
    int rc = gw_input_open(path, what, &fp, err);
    if (rc != GW_OK)
        return rc;
    struct stat st;
    if (fstat(fileno(fp), &st) != 0) {
        const int e = errno;
        fclose(fp);
        return gw_err_set(err, GW_EIO, "%s: %s: cannot read: %s", what, path, strerror(e));
    }
    unsigned long long hole = 0;
    if ((unsigned long long)st.st_size <= (unsigned long long)max && gw_input_hole(fileno(fp), &hole)) {
        fclose(fp);
        return gw_err_set(err, GW_EINVAL, "%s: %s: %llu bytes, and its bytes from %llu on are a hole (never written, "
                          "read as NUL bytes: a sparse file): not text", what, path,
                          (unsigned long long)st.st_size, hole + 1);
    }
    if ((unsigned long long)st.st_size > (unsigned long long)max) {
        fclose(fp);
        return gw_err_set(err, GW_EINVAL, "%s: '%s' is larger than %zu bytes", what, path, max);
    }
    /* its size and one byte more: a file that gives more grew while it was
     * read, or is no file on disk (a /proc file's 0 bytes gave 256 GiB, read
     * until memory ran out) */
    const size_t size = st.st_size > 0 ? (size_t)st.st_size : 0, cap = size + 1;
    size_t n = 0, got;
    char *buf = malloc(cap + 1);
    while (buf && n < cap && (got = fread(buf + n, 1, cap - n, fp)) > 0)
        n += got;
    int bad = ferror(fp);
    fclose(fp);
    if (!buf)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory reading '%s'", what, path);
    if (bad || n > size) {
        free(buf);
        return n > size ? gw_io_grew(what, path, size, err)
                        : gw_err_set(err, GW_EIO, "%s: cannot read '%s'", what, path);
    }
    buf[n] = '\0';
    *out = buf;
    if (len)
        *len = n;
    return GW_OK;
}

int gw_input_hole(int fd, unsigned long long *at)
{
    return gw_input_holes(fd, at, NULL);
}

int gw_input_holes(int fd, unsigned long long *at, unsigned long long *bytes)
{
    if (bytes)
        *bytes = 0;
#ifdef SEEK_HOLE
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size <= 0)
        return 0;
    const off_t was = lseek(fd, 0, SEEK_CUR);
    if (was < 0)
        return 0;
    /* hole after data after hole: one extent a turn, at most the file's
     * blocks (a million turns for 4 GiB of 4 KiB blocks, well under a second) */
    off_t pos = 0;
    int found = 0;
    while (pos < st.st_size) {
        const off_t hole = lseek(fd, pos, SEEK_HOLE);
        if (hole < 0 || hole >= st.st_size)
            break;
        if (!found && at)
            *at = (unsigned long long)hole;
        found = 1;
        if (!bytes)
            break;
        off_t data = lseek(fd, hole, SEEK_DATA);
        if (data < 0 || data > st.st_size) /* ENXIO: a hole to the end */
            data = st.st_size;
        *bytes += (unsigned long long)(data - hole);
        pos = data;
    }
    lseek(fd, was, SEEK_SET);
    return found;
#else
    (void)fd, (void)at;
    return 0;
#endif
}

int gw_io_grew(const char *what, const char *path, unsigned long long size, gw_err *err)
{
    return gw_err_set(err, GW_EINVAL, "%s: %s: more bytes than the %llu its size said when it was opened: it grew "
                      "while it was read, or it is no file on disk (a /proc file); read it again once it is written",
                      what, path, size);
}

long gw_input_unended_line(const char *text, size_t len, long first, size_t *start)
{
    if (start)
        *start = 0;
    if (!text || len == 0 || text[len - 1] == '\n' || text[len - 1] == '\r')
        return 0;
    size_t s = len;
    while (s > 0 && text[s - 1] != '\n')
        s--;
    long line = first;
    for (size_t q = 0; q < s; q++)
        line += text[q] == '\n';
    if (start)
        *start = s;
    return line;
}
