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

/* HDF5 is called by one thread at a time: every section of the library that
 * calls HDF5 (the sample's read and write, the chain trace's and the impact's
 * .h5 files) holds this lock from its first HDF5 call to its last, including
 * the swap of HDF5's error handler. HDF5 built without --enable-threadsafe
 * (HDF5's own default) has no lock of its own, and its error handler and
 * identifier tables are process-wide; a thread-safe build serialises its API
 * calls anyway, so the lock costs nothing there. Recursive; a gw_forklock
 * (gw_global.h): a fork waits for the section under way. */
void gw_h5_lock(void);
void gw_h5_unlock(void);

/* A section of HDF5 calls, as every caller in the library makes one: the lock
 * taken, HDF5's automatic error handler (process-wide, or per thread in a
 * thread-safe HDF5) saved and replaced by fn with data (fn NULL: nothing
 * printed; granwave reports through gw_err, naming the file), and at the end
 * the caller's handler put back and the lock given. */
typedef struct gw_h5_section {
    H5E_auto2_t fn;
    void *data;
} gw_h5_section;
void gw_h5_enter(gw_h5_section *sec, H5E_auto2_t fn, void *data);
void gw_h5_leave(gw_h5_section *sec);
/* The end of a section whose read failed: automatic error printing stays off
 * in this thread and, once, in the exiting one (gw_h5_quiet_at_exit). */
void gw_h5_leave_failed_read(gw_h5_section *sec);

/* After a failed read: HDF5 1.10 can lose track of a block of a corrupt file
 * and then prints "HDF5: infinite loop closing library" and a line of
 * "FL,FL,..." to stderr when the process exits, unless automatic error
 * printing is off in the thread that exits. That setting is per thread in a
 * thread-safe HDF5, so turning it off in the reading thread left the main
 * thread's on: a corrupt sample read on any other thread (a Python
 * ThreadPoolExecutor, a program's worker) printed at exit. This registers,
 * once, an atexit handler that turns the printing off in the exiting thread;
 * it runs before HDF5's own (registered at HDF5's first call, earlier). */
void gw_h5_quiet_at_exit(void);
#endif

#endif
