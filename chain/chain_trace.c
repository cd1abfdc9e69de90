/*
 * chain_trace.c: time series of a collision (wall force, bead positions and
 * velocities) kept in memory and written as CSV, and as HDF5 when built with it,
 * each file atomically (gw_afile). Units: s, N, m, m/s.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"
#include "chain_model.h"
#include "chain_wall.h"
#include "gw_locale.h"
#if GW_HAVE_HDF5
#include <hdf5.h>
#include "gw_h5.h"
#endif

void gw_chain_trace_init(gw_chain_trace *tr, int n)
{
    if (!tr) /* nothing to set: a void call's NULL is a no-op, as the _free calls' */
        return;
    memset(tr, 0, sizeof *tr);
    tr->n = n;
}

int chain_trace_check(const gw_chain_trace *tr, const char *call, gw_err *err)
{
    if (!tr)
        return gw_err_set(err, GW_EINVAL, "%s: tr is NULL", call);
    /* a trace filled by hand: its arrays were read over len rows whatever
     * they held (SIGSEGV for NULL ones), and a sample was stored past cap */
    if (tr->n < 0 || tr->len > tr->cap || (tr->len > 0 && (!tr->t || !tr->f)) ||
        (tr->len > 0 && tr->n > 0 && (!tr->x || !tr->v)))
        return gw_err_set(err, GW_EINVAL, "%s: not a trace (n %d, len %zu, cap %zu, t%s f%s x%s v%s: n >= 0, len <= cap, "
                          "the arrays of len rows given)", call, tr->n, tr->len, tr->cap, tr->t ? "" : " NULL",
                          tr->f ? "" : " NULL", tr->x ? "" : " NULL", tr->v ? "" : " NULL");
    return GW_OK;
}

void gw_chain_trace_free(gw_chain_trace *tr)
{
    if (!tr)
        return;
    free(tr->t);
    free(tr->f);
    free(tr->x);
    free(tr->v);
    memset(tr, 0, sizeof *tr);
}

/* The written trace's bound, bytes (gw_chain_trace_check); a test lowers it
 * (chain_trace_limit_set) to reach it in a small run. */
static double trace_limit = 5e9;

/* CSV "%.12e," is 19-20 B a value (measured 19.8 on drop --n 100); HDF5 8 */
static double trace_per_value(void)
{
    return 20.0 + (GW_HAVE_HDF5 ? 8.0 : 0.0);
}

void chain_trace_limit_set(double bytes)
{
    trace_limit = bytes > 0 ? bytes : 5e9;
}

double chain_trace_rows_max(int n)
{
    return floor(trace_limit / ((2.0 * (n > 0 ? n : 0) + 2) * trace_per_value()));
}

int chain_trace_cut(const gw_chain_trace *tr, double t_end)
{
    return tr && tr->len > 0 && tr->t && (double)tr->len >= chain_trace_rows_max(tr->n) &&
           tr->t[tr->len - 1] < t_end;
}

int chain_trace_cut_warnings(const gw_chain_trace *tr, double t_end, const char *dt_name, char **list)
{
    if (!chain_trace_cut(tr, t_end))
        return GW_OK;
    const double span = tr->t[tr->len - 1];
    return gw_warnings_add(list,
                           "the stored trace stops at t = %.6g s, at its %.3g GB limit (%zu rows of %d beads), "
                           "and the run went on to t = %.6g s (the collision had not ended by its expected length): "
                           "the results are the whole run's, the written trace %.3g of it; raise %s to store it all",
                           span, trace_limit / 1e9, tr->len, tr->n, t_end, t_end > 0 ? span / t_end : 0.0,
                           dt_name ? dt_name : "--dt-out");
}

int gw_chain_trace_sample(void *ctx, double t, const double *y, double f_wall, int is_event)
{
    if (!ctx || !y) /* nowhere to store it, or nothing to store */
        return GW_EINVAL;
    (void)is_event;
    gw_chain_trace *tr = ctx;
    if (chain_trace_check(tr, "gw_chain_trace_sample", NULL) != GW_OK)
        return GW_EINVAL;
    /* Its files within the limit whatever the run's length: the check before
     * the run covers the collision's expected length, and a default run that
     * has not ended there goes on, up to 50 default t-max (chain_extend_bound):
     * the rows past the limit are not stored (chain_trace_cut says so) */
    if ((double)tr->len >= chain_trace_rows_max(tr->n))
        return 0;
    const int n = tr->n;
    if (tr->len == tr->cap) {
        size_t cap = tr->cap ? 2 * tr->cap : 1024;
        double *nt = realloc(tr->t, cap * sizeof *nt);
        if (nt)
            tr->t = nt;
        double *nf = realloc(tr->f, cap * sizeof *nf);
        if (nf)
            tr->f = nf;
        double *nx = realloc(tr->x, cap * (size_t)n * sizeof *nx);
        if (nx)
            tr->x = nx;
        double *nv = realloc(tr->v, cap * (size_t)n * sizeof *nv);
        if (nv)
            tr->v = nv;
        if (!nt || !nf || !nx || !nv)
            return GW_ENOMEM;
        tr->cap = cap;
    }
    tr->t[tr->len] = t;
    tr->f[tr->len] = f_wall;
    for (int i = 0; i < n; i++) {
        tr->x[tr->len * (size_t)n + (size_t)i] = y[2 * i];
        tr->v[tr->len * (size_t)n + (size_t)i] = y[2 * i + 1];
    }
    tr->len++;
    return 0;
}

/* v rounded up to two significant digits (a suggestion that passes). */
static double ceil_2digits(double v)
{
    const double p = pow(10, floor(log10(v)) - 1);
    return ceil(v / p * (1 - 1e-12)) * p;
}

int gw_chain_trace_check(int n, double span, double dt_out, double events, gw_err *err)
{
    /* a NaN passed every bound below (span, dt_out or events NaN: GW_OK), and
     * so did a trace of 0 beads (of no column) */
    if (n < 1 || !(isfinite(span) && span >= 0) || !(isfinite(dt_out) && dt_out > 0) ||
        !(isfinite(events) && events >= 0))
        return gw_err_set(err, GW_EINVAL, "gw_chain_trace_check: n %d, span %g s, dt-out %g s, events %g: not a trace "
                          "(n >= 1; span, events >= 0; dt-out > 0; all finite)", n, span, dt_out, events);
    const double per_value = trace_per_value(), limit = trace_limit;
    const double values = 2.0 * n + 2, rows = span / dt_out + 1 + events;
    const double files = rows * values * per_value;
    if (files <= limit)
        return GW_OK;
    const double free_rows = limit / (values * per_value) - events; /* samples left for dt-out */
    if (free_rows < 16) /* the events and 16 samples: 2^31 beads said "about 0 GB" with no events */
        return gw_err_set(err, GW_EINVAL, "n: the trace of %d beads would write about %.3g GB at any dt-out (its "
                          "contact events and 16 samples), above the %.3g GB limit: run without storing it (the program: "
                          "without --out)", n, (events + 16) * values * per_value / 1e9, limit / 1e9);
    return gw_err_set(err, GW_EINVAL, "dt-out: the trace of %d beads at %g s (about %.3g samples over %.3g s) would "
                      "write about %.3g GB (%.3g GB in memory), above the %.3g GB limit: raise dt-out to %.2g s or more",
                      n, dt_out, rows, span, files / 1e9, rows * values * 8 / 1e9, limit / 1e9,
                      ceil_2digits(span / free_rows));
}

/* DIR/<stem><suffix> into path (4096 bytes). The name was formatted into 512
 * bytes and cut there without a word: a stem of 501 characters ("./" 248
 * times and "xstem") wrote its wall force as "xstem_wall_forc", with GW_OK.
 * GW_EINVAL naming the stem when the name or the path does not fit. */
static int trace_path(char *path, const char *dir, const char *stem, const char *suffix, gw_err *err)
{
    char name[4096];
    if (!dir[0]) /* it was "output path too long for the trace's file" */
        return gw_err_set(err, GW_EINVAL, "gw_chain_trace_write: dir is empty ('' names no directory; '.' is this one)");
    if (gw_snprintf(name, sizeof name, "%s%s", stem, suffix) >= (int)sizeof name ||
        gw_path_join(path, 4096, dir, name) != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: output path too long for the trace's file '%s%s'", dir, stem, suffix);
    return GW_OK;
}

static int write_csv(const gw_chain_trace *tr, const char *dir, const char *stem,
                     const char *header, gw_err *err)
{
    char path[4096];
    gw_afile f;
    int rc;
    if ((rc = trace_path(path, dir, stem, "_wall_force.csv", err)) != GW_OK)
        return rc;
    if ((rc = gw_afile_open(&f, path, err)) != GW_OK)
        return rc;
    gw_write_comment(f.fp, header);
    gw_fprintf(f.fp, "t_s,f_wall_N\n");
    for (size_t k = 0; k < tr->len; k++)
        gw_fprintf(f.fp, "%.12e,%.12e\n", tr->t[k], tr->f[k]);
    if ((rc = gw_afile_commit(&f, err)) != GW_OK)
        return rc;
    if (tr->n == 0) /* wall force only: no bead table (it would hold t_s alone) */
        return GW_OK;

    if ((rc = trace_path(path, dir, stem, "_beads.csv", err)) != GW_OK)
        return rc;
    if ((rc = gw_afile_open(&f, path, err)) != GW_OK)
        return rc;
    gw_write_comment(f.fp, header);
    gw_fprintf(f.fp, "t_s");
    for (int i = 1; i <= tr->n; i++)
        gw_fprintf(f.fp, ",x%d_m", i);
    for (int i = 1; i <= tr->n; i++)
        gw_fprintf(f.fp, ",v%d_m_s", i);
    fputc('\n', f.fp);
    for (size_t k = 0; k < tr->len; k++) {
        gw_fprintf(f.fp, "%.12e", tr->t[k]);
        for (int i = 0; i < tr->n; i++)
            gw_fprintf(f.fp, ",%.12e", tr->x[k * (size_t)tr->n + (size_t)i]);
        for (int i = 0; i < tr->n; i++)
            gw_fprintf(f.fp, ",%.12e", tr->v[k * (size_t)tr->n + (size_t)i]);
        fputc('\n', f.fp);
    }
    return gw_afile_commit(&f, err);
}

#if GW_HAVE_HDF5
static int h5_dataset(hid_t file, const char *name, const double *data, int rank,
                      const hsize_t *dims, const char *units)
{
    hid_t space = H5Screate_simple(rank, dims, NULL);
    hid_t ds = H5Dcreate2(file, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT,
                          H5P_DEFAULT);
    int bad = ds < 0 || H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0;
    if (!bad) {
        hid_t ts = H5Tcopy(H5T_C_S1);
        H5Tset_size(ts, strlen(units) + 1);
        hid_t as = H5Screate(H5S_SCALAR);
        hid_t at = H5Acreate2(ds, "units", ts, as, H5P_DEFAULT, H5P_DEFAULT);
        bad = at < 0 || H5Awrite(at, ts, units) < 0;
        if (at >= 0)
            H5Aclose(at);
        H5Sclose(as);
        H5Tclose(ts);
    }
    if (ds >= 0)
        H5Dclose(ds);
    H5Sclose(space);
    return bad ? GW_EIO : GW_OK;
}

static int write_h5_locked(const gw_chain_trace *tr, const char *dir, const char *stem,
                           const char *header, gw_err *err)
{
    char path[4096];
    int rc = trace_path(path, dir, stem, ".h5", err);
    if (rc != GW_OK)
        return rc;
    /* built in memory, written as one image through gw_afile (gw_h5.h) */
    gw_h5_mem mem;
    hid_t file = gw_h5_mem_create(&mem, path, 0);
    if (file < 0)
        return mem.nomem ? gw_err_set(err, GW_ENOMEM, "%s: out of memory", path)
                             : gw_err_set(err, GW_EIO, "%s: cannot create HDF5 file", path);
    hsize_t d1[1] = {tr->len}, d2[2] = {tr->len, (hsize_t)tr->n};
    if (tr->len > 0) {
        rc = h5_dataset(file, "t", tr->t, 1, d1, "s");
        if (rc == GW_OK)
            rc = h5_dataset(file, "f_wall", tr->f, 1, d1, "N");
        if (rc == GW_OK && tr->n > 0)
            rc = h5_dataset(file, "x", tr->x, 2, d2, "m");
        if (rc == GW_OK && tr->n > 0)
            rc = h5_dataset(file, "v", tr->v, 2, d2, "m/s");
    }
    if (rc == GW_OK) {
        hid_t ts = H5Tcopy(H5T_C_S1);
        H5Tset_size(ts, strlen(header) + 1);
        hid_t as = H5Screate(H5S_SCALAR);
        hid_t at = H5Acreate2(file, "run", ts, as, H5P_DEFAULT, H5P_DEFAULT);
        if (at < 0 || H5Awrite(at, ts, header) < 0)
            rc = GW_EIO;
        if (at >= 0)
            H5Aclose(at);
        H5Sclose(as);
        H5Tclose(ts);
    }
    if (rc != GW_OK) {
        int nomem = mem.nomem;
        gw_h5_mem_abort(&mem);
        return nomem ? gw_err_set(err, GW_ENOMEM, "%s: out of memory", path)
                     : gw_err_set(err, GW_EIO, "%s: HDF5 write failed", path);
    }
    return gw_h5_mem_write(&mem, path, err);
}

/* Under the HDF5 lock (gw_h5.h), with HDF5's error printing off: the message
 * names the file, and HDF5 would print its error stack to stderr (its handler
 * is per thread in a thread-safe HDF5: a new thread's prints). */
static int write_h5(const gw_chain_trace *tr, const char *dir, const char *stem,
                    const char *header, gw_err *err)
{
    gw_h5_section sec;
    gw_h5_enter(&sec, NULL, NULL);
    int rc = write_h5_locked(tr, dir, stem, header, err);
    gw_h5_leave(&sec);
    return rc;
}
#endif

int gw_chain_trace_write(const gw_chain_trace *tr, const char *dir, const char *stem,
                         const char *header, gw_err *err)
{
    int rc = chain_trace_check(tr, "gw_chain_trace_write", err);
    if (rc != GW_OK)
        return rc;
    /* (dir was printed as "(null)", stem read; a NULL header was read through
     * strlen by the HDF5 writer, SIGSEGV, after the CSV files were written) */
    if (!dir || !stem || !header)
        return gw_err_set(err, GW_EINVAL, "gw_chain_trace_write: %s is NULL", !dir ? "dir" : !stem ? "stem" : "header");
    /* an empty stem wrote _wall_force.csv, _beads.csv and the hidden .h5 */
    if (!stem[0])
        return gw_err_set(err, GW_EINVAL, "gw_chain_trace_write: stem is empty (the start of its files' names)");
    char path[4096]; /* the longest of its names first: all of them, or nothing written */
    if ((rc = trace_path(path, dir, stem, "_wall_force.csv", err)) != GW_OK)
        return rc;
    rc = write_csv(tr, dir, stem, header, err);
#if GW_HAVE_HDF5
    if (rc == GW_OK)
        rc = write_h5(tr, dir, stem, header, err);
#endif
    return rc;
}
