/*
 * layer_h5.c: the time series of one impact as one HDF5 file (impact.h5), the
 * same numbers as ledger.csv and crowns.csv (docs/physics.md 2.4-2.5, B.7-B.14).
 *
 * Datasets (SI units, attribute "units" on each; "columns" where a dataset has
 * named columns):
 *   t [ns] (s); ledger [ns x 8] (J: kinetic_block, kinetic_soil, strain_normal,
 *   strain_tangent, mindlin_excess, dissipated, potential, total);
 *   block [ns x 4] (x, y in m, vx, vy in m/s);
 *   ring_strain, ring_kinetic, ring_dissipated [ns x nrings] (J),
 *   ring_coordination [ns x nrings] (contacts per particle); ring_r [nrings] (m);
 *   peak_strain_t, peak_kinetic_t [nrings] (s, NaN: no peak);
 *   xcorr_delay [nrings - 1] (s, cross-correlation delay from ring k to k + 1,
 *   NaN: pair not used), xcorr_rho [nrings - 1] (normalised correlation peak), one
 *   per ring pair as the JSON's and Python's;
 *   spec_freq [nf] (Hz), spec_strain, spec_kinetic [nf x nrings] (J^2/Hz, one-
 *   sided power spectral density per ring, layer_crowns.c); the xcorr and spec
 *   datasets are absent when the run had fewer than 4 evenly spaced samples.
 * Root attributes: "run" (version, command line, settings) and the scalar
 * results (e_n, e, wave_speed, wave_speed_xcorr, wave_speed_xcorr_err, ...; bounced is NaN when undecided, e_n, e,
 * alpha_r NaN until T_f; e_n_first, e_first, alpha_r_first, t_rebound_first:
 * the first free-flight maximum; t_rebound, t_f, t_leave in s). Written under a temporary name and renamed
 * into place, so an interrupted run leaves no partial file.
 */
#define _POSIX_C_SOURCE 200809L
#include <fcntl.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include <string.h>

#include "gw_layer.h"
#include "layer_impl.h"

#if GW_HAVE_HDF5
#include <hdf5.h>
#include "gw_h5.h"

static int put_string_attr(hid_t obj, const char *name, const char *value)
{
    hid_t ts = H5Tcopy(H5T_C_S1);
    H5Tset_size(ts, strlen(value) + 1);
    hid_t as = H5Screate(H5S_SCALAR);
    hid_t at = H5Acreate2(obj, name, ts, as, H5P_DEFAULT, H5P_DEFAULT);
    int bad = at < 0 || H5Awrite(at, ts, value) < 0;
    if (at >= 0)
        H5Aclose(at);
    H5Sclose(as);
    H5Tclose(ts);
    return bad;
}

static int put_double_attr(hid_t obj, const char *name, double v)
{
    hid_t as = H5Screate(H5S_SCALAR);
    hid_t at = H5Acreate2(obj, name, H5T_NATIVE_DOUBLE, as, H5P_DEFAULT, H5P_DEFAULT);
    int bad = at < 0 || H5Awrite(at, H5T_NATIVE_DOUBLE, &v) < 0;
    if (at >= 0)
        H5Aclose(at);
    H5Sclose(as);
    return bad;
}

static int put(hid_t file, const char *name, const double *data, hsize_t rows, hsize_t cols,
               const char *units, const char *columns)
{
    hsize_t dims[2] = {rows, cols};
    hid_t space = H5Screate_simple(cols > 0 ? 2 : 1, dims, NULL);
    hid_t ds = H5Dcreate2(file, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    int bad = ds < 0 || H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0;
    if (!bad)
        bad = put_string_attr(ds, "units", units) || (columns && put_string_attr(ds, "columns", columns));
    if (ds >= 0)
        H5Dclose(ds);
    H5Sclose(space);
    return bad;
}

/* The ledger is written as it is held: gw_layer_energy is its 8 columns,
 * in order, as 8 doubles (it was copied into an array of ns x 8 first: 8 MB
 * more at 130,000 samples) */
_Static_assert(sizeof(gw_layer_energy) == 8 * sizeof(double) && offsetof(gw_layer_energy, total) == 7 * sizeof(double),
               "gw_layer_energy: 8 doubles, total last");

/* The file of r; with take (r itself), each of r's series freed once it is in
 * the file's image (layer_impact_write_h5_release). */
static int write_h5(const gw_layer_impact_result *r, gw_layer_impact_result *take, const char *path,
                    const char *header, gw_err *err)
{
    if (!r || !path)
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_write_h5: %s is NULL", !r ? "res" : "path");
    if (layer_result_shape(r, 1, err) != GW_OK)
        return GW_EINVAL;
    const size_t ns = (size_t)r->ns, nr = (size_t)r->nrings, nf = r->xcorr_delay ? (size_t)r->spec_len : 0;
    double *freq = malloc((nf + 1) * sizeof *freq);
    if (!freq)
        return gw_err_set(err, GW_ENOMEM, "impact.h5: out of memory");
    for (size_t l = 0; l < nf; l++)
        freq[l] = (double)l * r->spec_df;
    /* our message names the file; HDF5's own error stack would add dozens of lines */
    gw_h5_section sec; /* HDF5 and its error handler, one thread at a time (gw_h5.h) */
    gw_h5_enter(&sec, NULL, NULL);
    gw_h5_mem mem;
    hid_t file = gw_h5_mem_create(&mem, path, 0); /* in memory, written as one image (gw_h5.h) */
    int bad = file < 0;
    if (!bad) {
        bad = put(file, "t", r->t, ns, 0, "s", NULL) ||
              put(file, "ledger", (const double *)(const void *)r->ledger, ns, 8, "J",
                  "kinetic_block,kinetic_soil,strain_normal,strain_tangent,mindlin_excess,"
                  "dissipated,potential,total") ||
              put(file, "block", r->block, ns, 4, "m, m, m/s, m/s", "x,y,vx,vy");
        if (take) { /* in the image now */
            free(take->t), free(take->ledger), free(take->block);
            take->t = NULL, take->ledger = NULL, take->block = NULL;
        }
        bad = bad || put(file, "ring_strain", r->ring_strain, ns, nr, "J", NULL) ||
              put(file, "ring_kinetic", r->ring_kin, ns, nr, "J", NULL) ||
              put(file, "ring_dissipated", r->ring_diss, ns, nr, "J", NULL) ||
              put(file, "ring_coordination", r->ring_coord, ns, nr, "contacts per particle", NULL);
        if (take) { /* one block, owned by ring_kin */
            free(take->ring_kin);
            take->ring_kin = take->ring_strain = take->ring_coord = take->ring_diss = NULL;
            take->ns = take->cap = 0;
        }
        bad = bad || put(file, "ring_r", r->ring_r, nr, 0, "m", NULL) ||
              put(file, "peak_strain_t", r->peak_strain_t, nr, 0, "s", NULL) ||
              put(file, "peak_kinetic_t", r->peak_kin_t, nr, 0, "s", NULL) ||
              put_string_attr(file, "run", header ? header : "") ||
              put_double_attr(file, "e_n", r->e_n) || put_double_attr(file, "e", r->e) ||
              put_double_attr(file, "penetration", r->penetration) ||
              put_double_attr(file, "energy_error", r->energy_error) ||
              put_double_attr(file, "wave_speed", r->wave_speed) ||
              put_double_attr(file, "dissipated_first_contact", r->dissipated_first_contact) ||
              put_double_attr(file, "bounced", r->bounced < 0 ? NAN : r->bounced) ||
              put_double_attr(file, "alpha_r", r->alpha_r_deg) ||
              put_double_attr(file, "t_rebound", r->t_rebound) || put_double_attr(file, "t_f", r->t_f) ||
              put_double_attr(file, "t_leave", r->t_leave) ||
              put_double_attr(file, "e_n_first", r->e_n_first) || put_double_attr(file, "e_first", r->e_first) ||
              put_double_attr(file, "alpha_r_first", r->alpha_r_first_deg) ||
              put_double_attr(file, "t_rebound_first", r->t_rebound_first) ||
              put_double_attr(file, "wave_speed_xcorr", r->wave_speed_xcorr) ||
              put_double_attr(file, "wave_speed_xcorr_err", r->wave_speed_xcorr_err);
        if (!bad && nf > 0)
            bad = put(file, "xcorr_delay", r->xcorr_delay, nr - 1, 0, "s", NULL) ||
                  put(file, "xcorr_rho", r->xcorr_rho, nr - 1, 0, "1", NULL) ||
                  put(file, "spec_freq", freq, nf, 0, "Hz", NULL) ||
                  put(file, "spec_strain", r->spec_strain, nf, nr, "J^2/Hz", NULL) ||
                  put(file, "spec_kinetic", r->spec_kin, nf, nr, "J^2/Hz", NULL);
    }
    free(freq);
    int rc = GW_OK;
    if (bad) {
        int nomem = mem.nomem;
        if (file >= 0)
            gw_h5_mem_abort(&mem);
        rc = nomem ? gw_err_set(err, GW_ENOMEM, "%s: out of memory", path)
                   : gw_err_set(err, GW_EIO, "%s: cannot write the HDF5 file", path);
    } else {
        rc = gw_h5_mem_write(&mem, path, err); /* fsync, then the rename makes it visible */
    }
    gw_h5_leave(&sec);
    return rc;
}

int gw_layer_impact_write_h5(const gw_layer_impact_result *r, const char *path, const char *header,
                             gw_err *err)
{
    return write_h5(r, NULL, path, header, err);
}

int layer_impact_write_h5_release(gw_layer_impact_result *r, const char *path, const char *header, gw_err *err)
{
    return write_h5(r, r, path, header, err);
}
#else
int gw_layer_impact_write_h5(const gw_layer_impact_result *r, const char *path, const char *header,
                             gw_err *err)
{
    if (!r || !path)
        return gw_err_set(err, GW_EINVAL, "gw_layer_impact_write_h5: %s is NULL", !r ? "res" : "path");
    (void)r, (void)header;
    return gw_err_set(err, GW_EUNSUPPORTED, "%s: this build has no HDF5", path);
}

int layer_impact_write_h5_release(gw_layer_impact_result *r, const char *path, const char *header, gw_err *err)
{
    return gw_layer_impact_write_h5(r, path, header, err);
}
#endif
