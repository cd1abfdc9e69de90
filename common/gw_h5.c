/*
 * gw_h5.c: HDF5 files built in memory (core driver, no backing store) and
 * written through gw_afile as one image (gw_h5.h).
 */
#include <errno.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_global.h"
#include "gw_h5.h"

#if GW_HAVE_HDF5
static gw_forklock h5_lock = GW_FORKLOCK_RECURSIVE;

void gw_h5_lock(void)
{
    gw_forklock_take(&h5_lock);
}

void gw_h5_unlock(void)
{
    gw_forklock_give(&h5_lock);
}

void gw_h5_enter(gw_h5_section *sec, H5E_auto2_t fn, void *data)
{
    gw_h5_lock();
    if (H5Eget_auto2(H5E_DEFAULT, &sec->fn, &sec->data) < 0)
        sec->fn = NULL, sec->data = NULL;
    H5Eset_auto2(H5E_DEFAULT, fn, data);
}

void gw_h5_leave(gw_h5_section *sec)
{
    H5Eclear2(H5E_DEFAULT);
    H5Eset_auto2(H5E_DEFAULT, sec->fn, sec->data);
    gw_h5_unlock();
}

void gw_h5_leave_failed_read(gw_h5_section *sec)
{
    (void)sec;
    H5Eclear2(H5E_DEFAULT);
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    gw_h5_quiet_at_exit();
    gw_h5_unlock();
}

static atomic_int exit_quiet_set;

static void exit_quiet(void)
{
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
}

void gw_h5_quiet_at_exit(void)
{
    if (!atomic_exchange(&exit_quiet_set, 1))
        atexit(exit_quiet);
}

/* The core driver's buffer is ours (file image callbacks): HDF5 grows it as
 * the file grows and, at H5Fclose, hands it back instead of freeing it when
 * gw_h5_mem_write asked to keep it. The closed file's buffer is the file: its
 * first EOA bytes are written, without the copy H5Fget_file_image would make
 * (the peak was twice the file's size) and with the superblock HDF5 writes on
 * a normal close (H5Fget_file_image's copy of a 1.8-format file had its
 * status flags cleared without the checksum recomputed, measured with 1.10.8). */
static void *buf_malloc(size_t size, H5FD_file_image_op_t op, void *udata)
{
    gw_h5_mem *u = udata;
    (void)op;
    void *p = malloc(size ? size : 1);
    if (p && !u->buf)
        u->buf = p, u->cap = size;
    return p;
}
static void *buf_memcpy(void *dest, const void *src, size_t size, H5FD_file_image_op_t op, void *udata)
{
    (void)op, (void)udata;
    if (dest != src)
        memmove(dest, src, size);
    return dest;
}
static void *buf_realloc(void *ptr, size_t size, H5FD_file_image_op_t op, void *udata)
{
    gw_h5_mem *u = udata;
    (void)op;
    void *p = realloc(ptr, size ? size : 1);
    if (p && (ptr == u->buf || !u->buf))
        u->buf = p, u->cap = size;
    return p;
}
static herr_t buf_free(void *ptr, H5FD_file_image_op_t op, void *udata)
{
    gw_h5_mem *u = udata;
    (void)op;
    if (ptr && ptr == u->buf) {
        if (u->keep)
            return 0; /* handed back to gw_h5_mem_write */
        u->buf = NULL, u->cap = 0;
    }
    free(ptr);
    return 0;
}
static void *udata_same(void *udata)
{
    return udata; /* the caller's gw_h5_mem */
}
static herr_t udata_keep(void *udata)
{
    (void)udata;
    return 0;
}

static herr_t find_nomem(unsigned n, const H5E_error2_t *e, void *found)
{
    (void)n;
    /* a resource error, or a failed allocation reported under another major
     * (H5Dread's "memory allocation failed for temporary property value" is
     * H5E_PLIST / H5E_CANTALLOC) */
    if (e->maj_num == H5E_RESOURCE || e->min_num == H5E_CANTALLOC || e->min_num == H5E_NOSPACE)
        *(int *)found = 1;
    return 0;
}

int gw_h5_stack_nomem(hid_t stack)
{
    int found = 0;
    if (H5Ewalk2(stack, H5E_WALK_DOWNWARD, find_nomem, &found) < 0)
        return 0;
    return found;
}

/* The handler while a file is built: a failed allocation noted, nothing
 * printed; a caller's own handler (one with client data: HDF5's default
 * printer has none, and is not H5Eprint2 itself) is called on. */
static herr_t note_nomem(hid_t stack, void *ctx)
{
    gw_h5_mem *m = ctx;
    if (gw_h5_stack_nomem(stack))
        m->nomem = 1;
    if (m->old_fn && m->old_data)
        m->old_fn(stack, m->old_data);
    return 0;
}

hid_t gw_h5_mem_create(gw_h5_mem *m, const char *path, int v18)
{
    memset(m, 0, sizeof *m);
    m->file = -1;
    if (H5Eget_auto2(H5E_DEFAULT, &m->old_fn, &m->old_data) >= 0 && H5Eset_auto2(H5E_DEFAULT, note_nomem, m) >= 0)
        m->quiet = 1;
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    if (fapl < 0) {
        gw_h5_mem_abort(m);
        return -1;
    }
    H5FD_file_image_callbacks_t cb = {buf_malloc, buf_memcpy, buf_realloc, buf_free, udata_same, udata_keep, m};
    /* grown 1 MiB at a time; backing_store 0: nothing is written on close */
    if (H5Pset_fapl_core(fapl, (size_t)1 << 20, 0) >= 0 && H5Pset_file_image_callbacks(fapl, &cb) >= 0 &&
        (!v18 || H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_LATEST) >= 0))
        m->file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
    H5Pclose(fapl);
    if (m->file < 0)
        gw_h5_mem_abort(m);
    return m->file;
}

/* HDF5's error printing as it was before gw_h5_mem_create. */
static void loud(gw_h5_mem *m)
{
    if (m->quiet)
        H5Eset_auto2(H5E_DEFAULT, m->old_fn, m->old_data);
    m->quiet = 0;
}

void gw_h5_mem_abort(gw_h5_mem *m)
{
    if (m->file >= 0)
        H5Fclose(m->file); /* frees the buffer (keep is 0) */
    m->file = -1;
    loud(m);
}

/* HDF5 reads the image in place: its copies of the buffer (into the file
 * access list, the list's copies and the core driver's file) are the buffer
 * itself, never freed; the check opens the file read-only, so nothing writes
 * to it or grows it. (With HDF5's own copies, opening an image of n bytes
 * took two more copies of n.) */
static void *image_same(size_t size, H5FD_file_image_op_t op, void *udata)
{
    const gw_h5_mem *u = udata;
    (void)op;
    return size <= u->cap ? u->buf : NULL;
}
static void *image_grow(void *ptr, size_t size, H5FD_file_image_op_t op, void *udata)
{
    (void)ptr, (void)size, (void)op, (void)udata;
    return NULL; /* read-only: never asked */
}
static herr_t image_keep(void *ptr, H5FD_file_image_op_t op, void *udata)
{
    (void)ptr, (void)op, (void)udata;
    return 0;
}

/* 1 when HDF5 opens the n-byte image (read-only, in memory, in place). */
static int image_opens(void *img, size_t n)
{
    gw_h5_mem u = {.file = -1, .buf = img, .cap = n, .keep = 1};
    H5FD_file_image_callbacks_t cb = {image_same, buf_memcpy, image_grow, image_keep, udata_same, udata_keep, &u};
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    hid_t f = -1;
    if (fapl >= 0 && H5Pset_fapl_core(fapl, (size_t)1 << 20, 0) >= 0 && H5Pset_file_image_callbacks(fapl, &cb) >= 0 &&
        H5Pset_file_image(fapl, img, n) >= 0) {
        H5E_BEGIN_TRY { f = H5Fopen("granwave-image-check", H5F_ACC_RDONLY, fapl); } H5E_END_TRY;
    }
    if (f >= 0)
        H5Fclose(f);
    if (fapl >= 0)
        H5Pclose(fapl);
    return f >= 0;
}

/* The file's length after its close: the end-of-file address its superblock
 * (at offset 0, base address 0) stores, 0 when the image has no superblock of
 * a known version (0-3, HDF5 file format specification). The end of
 * allocation before the close can be larger: space released at the close
 * (measured: 6656 bytes before, 5632 stored, for a layer sample). */
static size_t stored_eof(const unsigned char *b, size_t cap)
{
    static const unsigned char sig[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
    if (cap < 64 || memcmp(b, sig, 8) != 0)
        return 0;
    const int v = b[8];
    const int so = v <= 1 ? b[13] : v <= 3 ? b[9] : 0; /* size of offsets */
    const size_t at = v == 0 ? 24 : v == 1 ? 28 : 12;   /* the base address */
    if (so < 1 || so > 8 || at + 3 * (size_t)so > cap)
        return 0;
    uint64_t base = 0, eof = 0;
    for (int k = so - 1; k >= 0; k--) {
        base = base << 8 | b[at + k];
        eof = eof << 8 | b[at + 2 * (size_t)so + k];
    }
    return base == 0 && eof <= cap ? (size_t)eof : 0;
}

int gw_h5_mem_write(gw_h5_mem *m, const char *path, gw_err *err)
{
    m->keep = 1;
    H5Fclose(m->file); /* in memory: closing cannot fail on the disk */
    m->file = -1;
    const size_t n = m->buf ? stored_eof(m->buf, m->cap) : 0;
    int rc = GW_OK;
    /* the image is written only if HDF5 reads it back as it is */
    if (n == 0 || !image_opens(m->buf, n))
        rc = gw_err_set(err, GW_EIO, "%s: HDF5 could not make an image of the file that it reads back", path);
    if (rc == GW_OK) {
        gw_afile f;
        if ((rc = gw_afile_open(&f, path, err)) == GW_OK) {
            errno = 0; /* one large write: its own errno (the stream's flush after it has none) */
            if (fwrite(m->buf, 1, n, f.fp) != n) {
                int e = errno ? errno : EIO;
                gw_afile_abort(&f);
                rc = gw_err_set(err, GW_EIO, "%s: write failed: %s", path, strerror(e));
            } else {
                rc = gw_afile_commit(&f, err);
            }
        }
    }
    free(m->buf);
    m->buf = NULL, m->cap = 0;
    loud(m);
    return rc;
}
#endif
