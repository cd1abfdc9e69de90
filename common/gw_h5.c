/*
 * gw_h5.c: HDF5 files built in memory (core driver, no backing store) and
 * written through gw_afile as one image (gw_h5.h).
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "gw_h5.h"

#if GW_HAVE_HDF5
hid_t gw_h5_mem_create(const char *path, int v18)
{
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    if (fapl < 0)
        return -1;
    hid_t file = -1;
    /* grown 1 MiB at a time; backing_store 0: nothing is written on close */
    if (H5Pset_fapl_core(fapl, (size_t)1 << 20, 0) >= 0 &&
        (!v18 || H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_LATEST) >= 0))
        file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
    H5Pclose(fapl);
    return file;
}

/* 1 when HDF5 opens the image (read-only, in memory). */
static int image_opens(const void *img, size_t n)
{
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    hid_t f = -1;
    if (fapl >= 0 && H5Pset_fapl_core(fapl, (size_t)1 << 20, 0) >= 0 &&
        H5Pset_file_image(fapl, (void *)img, n) >= 0) {
        H5E_BEGIN_TRY { f = H5Fopen("granwave-image-check", H5F_ACC_RDONLY, fapl); } H5E_END_TRY;
    }
    if (f >= 0)
        H5Fclose(f);
    if (fapl >= 0)
        H5Pclose(fapl);
    return f >= 0;
}

/* The image as a reader will open it. HDF5 1.10 clears the superblock's
 * status flags in the image (byte 11 of a version 2 or 3 superblock: 0x01,
 * write access, while the file is open) without recomputing the superblock's
 * checksum, so the image of a 1.8-format file fails "incorrect metadata
 * checksum" (measured with 1.10.8). When the image as given does not open, the
 * byte the checksum was computed over is put back; the image is written only
 * if it then opens. 0 ok, -1 no readable image. */
static int image_fix(unsigned char *img, size_t n)
{
    if (image_opens(img, n))
        return 0;
    if (n > 48 && img[8] >= 2 && img[8] <= 3 && img[11] == 0) {
        img[11] = 0x01;
        if (image_opens(img, n))
            return 0;
        img[11] = 0;
    }
    return -1;
}

int gw_h5_mem_write(hid_t file, const char *path, gw_err *err)
{
    ssize_t n = H5Fflush(file, H5F_SCOPE_LOCAL) < 0 ? -1 : H5Fget_file_image(file, NULL, 0);
    void *img = n > 0 ? malloc((size_t)n) : NULL;
    int rc = GW_OK;
    if (n <= 0)
        rc = gw_err_set(err, GW_EIO, "%s: HDF5 could not make the file's image", path);
    else if (!img)
        rc = gw_err_set(err, GW_ENOMEM, "%s: out of memory for the HDF5 image (%zd bytes)", path, n);
    else if (H5Fget_file_image(file, img, (size_t)n) != n)
        rc = gw_err_set(err, GW_EIO, "%s: HDF5 could not make the file's image", path);
    H5Fclose(file); /* in memory: closing cannot fail on the disk */
    if (rc == GW_OK && image_fix(img, (size_t)n) != 0)
        rc = gw_err_set(err, GW_EIO, "%s: HDF5 made an image of the file that it cannot read back", path);
    if (rc == GW_OK) {
        gw_afile f;
        if ((rc = gw_afile_open(&f, path, err)) == GW_OK) {
            errno = 0; /* one large write: its own errno (the stream's flush after it has none) */
            if (fwrite(img, 1, (size_t)n, f.fp) != (size_t)n) {
                int e = errno ? errno : EIO;
                gw_afile_abort(&f);
                rc = gw_err_set(err, GW_EIO, "%s: write failed: %s", path, strerror(e));
            } else {
                rc = gw_afile_commit(&f, err);
            }
        }
    }
    free(img);
    return rc;
}
#endif
