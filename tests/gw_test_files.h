/*
 * gw_test_files.h: the file helpers the C tests share (they had their own
 * copies of slurp, write_file and a byte-flipping copy). No physics here: these
 * make the files a test hands to the library and read back what it wrote.
 * Failures are returned (NULL, -1, 0), never fatal: the test's own check says
 * what was expected.
 */
#ifndef GW_TEST_FILES_H
#define GW_TEST_FILES_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The whole file, NUL-terminated, in a buffer the caller frees; its length in
 * *len (len may be NULL). NULL when it cannot be opened or memory runs out. */
static inline char *gw_test_slurp(const char *path, long *len)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    size_t cap = 1 << 16, n = 0, got;
    char *b = malloc(cap);
    while (b && (got = fread(b + n, 1, cap - n - 1, fp)) > 0) {
        n += got;
        if (cap - n < 2) {
            char *nb = realloc(b, cap *= 2);
            if (!nb)
                free(b);
            b = nb;
        }
    }
    fclose(fp);
    if (b)
        b[n] = '\0';
    if (b && len)
        *len = (long)n;
    return b;
}

/* The file made (or truncated) to hold n bytes; 0, or -1 when a call failed. */
static inline int gw_test_write_bytes(const char *path, const void *bytes, size_t n)
{
    FILE *fp = fopen(path, "wb");
    if (!fp)
        return -1;
    int ok = fwrite(bytes, 1, n, fp) == n;
    return fclose(fp) == 0 && ok ? 0 : -1;
}

static inline int gw_test_write_text(const char *path, const char *text)
{
    return gw_test_write_bytes(path, text, strlen(text));
}

static inline int gw_test_file_exists(const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (fp)
        fclose(fp);
    return fp != NULL;
}

/* 1 when the file holds exactly text. */
static inline int gw_test_file_is(const char *path, const char *text)
{
    long n = 0;
    char *b = gw_test_slurp(path, &n);
    int same = b && (size_t)n == strlen(text) && memcmp(b, text, (size_t)n) == 0;
    free(b);
    return same;
}

/* The first n bytes of from (all when n < 0) copied to to, byte flip_at (when
 * within them) with its lowest bit flipped: a file cut short or damaged in one
 * byte. Returns the bytes copied. */
static inline long gw_test_copy_prefix(const char *from, const char *to, long n, long flip_at)
{
    FILE *in = fopen(from, "rb"), *out = fopen(to, "wb");
    long k = 0;
    int c;
    while (in && out && (n < 0 || k < n) && (c = getc(in)) != EOF) {
        putc(k == flip_at ? c ^ 0x01 : c, out);
        k++;
    }
    if (in)
        fclose(in);
    if (out)
        fclose(out);
    return k;
}

#endif
