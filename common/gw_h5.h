/*
 * gw_h5.h: HDF5 files built in memory and written as one atomic file. The
 * file is created with the core driver and no backing store, so HDF5 itself
 * never writes to the disk: a full disk or a file-size limit can no longer
 * fail inside H5Fclose (which left the file open in the HDF5 library: a
 * segmentation fault or "HDF5: infinite loop closing library" at exit, and
 * dozens of lines of HDF5's error stack). gw_h5_mem_write takes the file's
 * image and writes it through gw_afile (temporary name, fsync, rename; staged
 * in an open gw_outset), so a write error is the one line "PATH: write failed:
 * OS error" of every other file.
 */
#ifndef GW_H5_H
#define GW_H5_H

#include "gw_common.h"

#if GW_HAVE_HDF5
#include <hdf5.h>

/* An HDF5 file built in memory: the core driver's buffer is ours (file image
 * callbacks) and is written as it is after the file's close. The caller holds
 * the struct, in place, from gw_h5_mem_create to gw_h5_mem_write or
 * gw_h5_mem_abort (HDF5 keeps its address). */
typedef struct gw_h5_mem {
    hid_t file;  /* the open file, -1 once closed */
    void *buf;   /* the core driver's buffer (NULL before its first write) */
    size_t cap;  /* its size (a multiple of the 1 MiB increment) */
    int keep;    /* 1: H5Fclose hands it back instead of freeing it */
    /* HDF5's automatic error handler, replaced from create to write or abort
     * by a silent one that notes a failed allocation (an allocation failing
     * inside HDF5 printed 60 lines of its error stack before granwave's one
     * line), then restored. A caller's own handler (one with client data) is
     * called on from it. */
    H5E_auto2_t old_fn;
    void *old_data;
    int quiet;
    int nomem; /* an HDF5 call failed for want of memory */
} gw_h5_mem;

/* A new empty HDF5 file in memory, to be written to path (the name is only
 * HDF5's label: nothing is created). v18: the 1.8 file format and later
 * (checksummed metadata). m->file, negative on failure (nothing to free). */
hid_t gw_h5_mem_create(gw_h5_mem *m, const char *path, int v18);
/* Write the in-memory file to path atomically and close it (closed and freed
 * in every case). GW_EIO naming path and the OS error. Its memory: the file's
 * size once (the core driver's buffer, written as it is after the close), no
 * copy. */
int gw_h5_mem_write(gw_h5_mem *m, const char *path, gw_err *err);
/* Close an in-memory file without writing it (an error while building it). */
void gw_h5_mem_abort(gw_h5_mem *m);
/* 1 when the error stack holds a failed allocation (major error "resource
 * unavailable"), to say "out of memory" rather than "HDF5 write failed"; for
 * an automatic error handler (H5Eset_auto2), which sees the stack before the
 * next HDF5 call clears it. */
int gw_h5_stack_nomem(hid_t stack);
#endif

#endif
