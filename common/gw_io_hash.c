/*
 * gw_io_hash.c: the content hashes a result records of what it ran on:
 * FNV-1a 64 (offset basis 14695981039346656037, prime 1099511628211) of
 * bytes, a stream or an input file, a sweep case's configuration hash, and a
 * hash read back from its 16 hex digits. Separate from the files: it reads
 * through gw_input_open only.
 */
#define _POSIX_C_SOURCE 200809L /* fileno */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "gw_common.h"
#include "gw_io_impl.h"
unsigned long long gw_fnv1a64(unsigned long long h, const void *p, size_t n)
{
    if (!p)
        return h;
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++) {
        h ^= b[i];
        h *= 1099511628211ULL;
    }
    return h;
}

unsigned long long gw_case_config_hash(const char *model, int n, const char *const *names,
                                       const char *const *values)
{
    /* (no case: the hash of none; n < 0 hashed the model alone) */
    if (!model || n < 0 || (n > 0 && (!names || !values)))
        return 0;
    unsigned long long h = gw_fnv1a64(GW_FNV1A64_INIT, "model ", 6);
    h = gw_fnv1a64(gw_fnv1a64(h, model, strlen(model)), "\n", 1);
    for (int i = 0; i < n; i++)
        if (!names[i] || !values[i]) /* (a NULL pair was read: SIGSEGV) */
            return 0;
    for (int i = 0; i < n; i++) {
        h = gw_fnv1a64(gw_fnv1a64(h, names[i], strlen(names[i])), " = ", 3);
        h = gw_fnv1a64(gw_fnv1a64(h, values[i], strlen(values[i])), "\n", 1);
    }
    return h;
}

int gw_fnv1a64_parse(const char *p, size_t len, unsigned long long *h)
{
    if (len != 16 || !p || !h) /* NULL: no hash (p was read: SIGSEGV) */
        return 0;
    unsigned long long v = 0;
    for (size_t i = 0; i < 16; i++) {
        const char c = p[i];
        if (c >= '0' && c <= '9')
            v = v << 4 | (unsigned long long)(c - '0');
        else if (c >= 'a' && c <= 'f')
            v = v << 4 | (unsigned long long)(c - 'a' + 10);
        else
            return 0;
    }
    *h = v;
    return 1;
}

/* fp hashed from its current position, at most max bytes (*over set when
 * there were more); text: stopped at the first NUL byte (*nul_line its line,
 * counted from 1; 0: none). GW_OK or GW_EIO (a read error). */
static int hash_bounded(FILE *fp, unsigned long long max, int text, unsigned long long *h, int *over,
                        long *nul_line)
{
    unsigned char buf[8192]; /* 64 KiB here overflowed a 64 KiB stack (ulimit -s 64) */
    unsigned long long v = *h, total = 0;
    long line = 1;
    size_t got;
    *over = 0, *nul_line = 0;
    while ((got = fread(buf, 1, sizeof buf, fp)) > 0) {
        if (got > max - total) { /* more than max: refused, the rest never read */
            *over = 1;
            return GW_OK;
        }
        total += got;
        if (text) {
            const unsigned char *z = memchr(buf, 0, got);
            const size_t upto = z ? (size_t)(z - buf) : got;
            for (size_t i = 0; i < upto; i++)
                line += buf[i] == '\n';
            if (z) {
                *nul_line = line;
                return GW_OK;
            }
        }
        v = gw_fnv1a64(v, buf, got);
    }
    if (ferror(fp))
        return GW_EIO;
    *h = v;
    return GW_OK;
}

int gw_fnv1a64_stream(FILE *fp, unsigned long long *h)
{
    if (!fp || !h)
        return GW_EINVAL;
    /* a regular file alone, read up to its size at the call: /dev/zero was
     * read for 4 GiB (the bound) before it was refused, a pipe until it ended */
    struct stat st;
    const int fd = fileno(fp);
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
        return GW_EINVAL;
    const off_t at = ftello(fp);
    const unsigned long long size = st.st_size > 0 ? (unsigned long long)st.st_size : 0;
    if (at < 0 || size > GW_INPUT_HASH_MAX)
        return GW_EINVAL;
    int over;
    long nul;
    unsigned long long v = GW_FNV1A64_INIT;
    const unsigned long long left = (unsigned long long)at < size ? size - (unsigned long long)at : 0;
    const int rc = hash_bounded(fp, left, 0, &v, &over, &nul); /* more than that: it grew, refused */
    if (rc != GW_OK || over)
        return rc != GW_OK ? rc : GW_EINVAL;
    *h = v;
    return GW_OK;
}

int gw_fnv1a64_file_max(const char *path, const char *what, unsigned long long max, int text,
                        unsigned long long *h, gw_err *err)
{
    /* NULL named as NULL (it was "input: empty file name") */
    if (!path || !h)
        return gw_err_set(err, GW_EINVAL, "gw_fnv1a64_file_max: %s is NULL", !path ? "path" : "h");
    /* a yes/no: 7 was taken as yes, as the other yes/no arguments are not */
    if (text != 0 && text != 1)
        return gw_err_set(err, GW_EINVAL, "gw_fnv1a64_file_max: text is %d, not a flag (0 or 1)", text);
    return gw_io_fnv1a64_file_from(GW_FNV1A64_INIT, path, what, max, text, h, err);
}

int gw_io_fnv1a64_file_from(unsigned long long h0, const char *path, const char *what, unsigned long long max,
                            int text, unsigned long long *h, gw_err *err)
{
    FILE *fp = NULL;
    if (!h) /* the file was read and its hash refused as "read failed" (GW_EIO) */
        return gw_err_set(err, GW_EINVAL, "gw_fnv1a64_file: h is NULL");
    if (!what)
        what = "input";
    int rc = gw_input_open(path, what, &fp, err);
    if (rc != GW_OK)
        return rc;
    /* its size before a byte is read: a sparse 200 GB file was hashed whole */
    struct stat st;
    if (fstat(fileno(fp), &st) != 0) {
        fclose(fp);
        return gw_err_set(err, GW_EIO, "%s: %s: read failed", what, path);
    }
    const unsigned long long size = st.st_size > 0 ? (unsigned long long)st.st_size : 0;
    if (size > max) {
        fclose(fp);
        return gw_err_set(err, GW_EINVAL, "%s: %s: %llu bytes, more than the %llu bytes it may have", what, path,
                          size, max);
    }
    int over;
    long nul;
    unsigned long long v = h0;
    rc = hash_bounded(fp, size, text, &v, &over, &nul); /* its size: it may not grow */
    fclose(fp);
    if (rc != GW_OK)
        return gw_err_set(err, GW_EIO, "%s: %s: read failed", what, path);
    if (over) /* /proc/self/pagemap (0 bytes, giving 256 GiB) was read on and on */
        return gw_io_grew(what, path, size, err);
    if (nul)
        return gw_err_set(err, GW_EFORMAT, "%s: %s: line %ld: NUL byte (binary data, not text)", what, path, nul);
    *h = v;
    return GW_OK;
}

int gw_fnv1a64_file(const char *path, const char *what, unsigned long long *h, gw_err *err)
{
    if (!path || !h)
        return gw_err_set(err, GW_EINVAL, "gw_fnv1a64_file: %s is NULL", !path ? "path" : "h");
    return gw_fnv1a64_file_max(path, what, GW_INPUT_HASH_MAX, 0, h, err);
}
