/*
 * test_layer_h5.c: impact.h5 holds the same numbers as the in-memory result
 * (layer_h5.c), bit for bit, and is written atomically.
 *
 * A block (R_b = R_m) hits a row of 8 discs resting on the bottom wall at
 * 5 m/s; the result is written with gw_layer_impact_write_h5 and read back with
 * the HDF5 C API: t, ledger (8 columns), block (4 columns), ring_strain and
 * ring_r, the cross-correlation delays and the ring spectra must equal the
 * result's arrays exactly (memcmp), the attribute e_n too; no temporary file is left; an unwritable path gives GW_EIO and leaves
 * nothing. Without HDF5 the writer must return GW_EUNSUPPORTED.
 */
#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_layer.h"
#include "gw_test.h"
#if GW_HAVE_HDF5
#include <hdf5.h>

static int read_all(hid_t f, const char *name, double *out)
{
    hid_t ds = H5Dopen2(f, name, H5P_DEFAULT);
    if (ds < 0)
        return -1;
    int rc = H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out) < 0 ? -1 : 0;
    H5Dclose(ds);
    return rc;
}

/* Rows (first extent) of dataset name, -1 if absent. */
static long rows_of(hid_t f, const char *name)
{
    hid_t ds = H5Dopen2(f, name, H5P_DEFAULT);
    if (ds < 0)
        return -1;
    hid_t sp = H5Dget_space(ds);
    hsize_t dims[2] = {0, 0};
    long n = H5Sget_simple_extent_dims(sp, dims, NULL) >= 1 ? (long)dims[0] : -1;
    H5Sclose(sp);
    H5Dclose(ds);
    return n;
}
#endif

int main(void)
{
    double x[8], y[8], r[8];
    for (int i = 0; i < 8; i++)
        x[i] = 0.6 + 0.65 * i, y[i] = 0.325, r[i] = 0.325;
    gw_layer_sample s = {.n = 8, .width = 5.8, .rm = 0.325, .volume_ratio = 1, .porosity = 0.3,
                         .seed = 1, .mass_law = GW_LAYER_MASS_DISC, .x = x, .y = y, .r = r};
    gw_layer_params lp = gw_layer_params_default();
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.vi = 5;
    ip.x = 0.6 + 0.65 * 3 - 2.9; /* over disc 3 */
    ip.t_max = 0.004;
    ip.nrings = 4;
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 1e-6;
    gw_layer_impact_result res;
    gw_err err = {{0}};
    int rc = gw_layer_impact(&s, &lp, &ip, gw_solver_rk4, &sp, &res, &err);
    if (rc != GW_OK)
        printf("impact: %s\n", err.msg);
    gw_test_true(rc == GW_OK && res.ns > 10, "impact on a row of discs");
    char path[] = "/tmp/gw_test_layer_h5_XXXXXX";
    gw_test_true(mkdtemp(path) != NULL, "temporary directory");
    char file[256];
    snprintf(file, sizeof file, "%s/impact.h5", path);
    rc = gw_layer_impact_write_h5(&res, file, "test run", &err);
#if GW_HAVE_HDF5
    gw_test_true(rc == GW_OK, "impact.h5 written");
    int ntmp = 0; /* the temporary is impact.h5.tmp.XXXXXX (gw_afile_open_named) */
    DIR *d = opendir(path);
    for (struct dirent *e; d && (e = readdir(d));)
        ntmp += strncmp(e->d_name, "impact.h5.tmp", 13) == 0;
    if (d)
        closedir(d);
    gw_test_true(ntmp == 0, "no temporary file left");
    size_t ns = (size_t)res.ns, nr = (size_t)res.nrings;
    double *buf = malloc(8 * ns * nr * sizeof *buf + 64 * ns * sizeof *buf);
    hid_t f = H5Fopen(file, H5F_ACC_RDONLY, H5P_DEFAULT);
    gw_test_true(f >= 0, "impact.h5 opens");
    gw_test_true(read_all(f, "t", buf) == 0 && memcmp(buf, res.t, ns * sizeof *buf) == 0,
                 "t equals the result bit for bit");
    int same = read_all(f, "ledger", buf) == 0;
    for (size_t k = 0; same && k < ns; k++) {
        const gw_layer_energy *e = &res.ledger[k];
        double v[8] = {e->kinetic_block, e->kinetic_soil, e->strain_normal, e->strain_tangent,
                       e->mindlin_excess, e->dissipated, e->potential, e->total};
        same = memcmp(buf + 8 * k, v, sizeof v) == 0;
    }
    gw_test_true(same, "ledger (8 columns) equals the result bit for bit");
    gw_test_true(read_all(f, "block", buf) == 0 && memcmp(buf, res.block, 4 * ns * sizeof *buf) == 0,
                 "block series equals the result");
    gw_test_true(read_all(f, "ring_strain", buf) == 0 &&
                     memcmp(buf, res.ring_strain, ns * nr * sizeof *buf) == 0,
                 "ring_strain equals the result");
    gw_test_true(read_all(f, "ring_r", buf) == 0 && memcmp(buf, res.ring_r, nr * sizeof *buf) == 0,
                 "ring_r equals the result");
    const size_t nf = (size_t)res.spec_len;
    gw_test_true(res.xcorr_delay && nf > 2 && read_all(f, "xcorr_delay", buf) == 0 &&
                     memcmp(buf, res.xcorr_delay, (nr - 1) * sizeof *buf) == 0 && read_all(f, "xcorr_rho", buf) == 0 &&
                     memcmp(buf, res.xcorr_rho, (nr - 1) * sizeof *buf) == 0,
                 "xcorr_delay and xcorr_rho (issue 19) equal the result");
    /* one entry per ring pair, as the JSON's and Python's (it had nrings, the last NaN) */
    gw_test_true(rows_of(f, "xcorr_delay") == (long)nr - 1 && rows_of(f, "xcorr_rho") == (long)nr - 1,
                 "xcorr_delay and xcorr_rho hold nrings - 1 ring pairs");
    gw_test_true(nf > 2 && read_all(f, "spec_strain", buf) == 0 &&
                     memcmp(buf, res.spec_strain, nf * nr * sizeof *buf) == 0 &&
                     read_all(f, "spec_kinetic", buf) == 0 && memcmp(buf, res.spec_kin, nf * nr * sizeof *buf) == 0,
                 "ring spectra spec_strain, spec_kinetic [nf x nrings] equal the result");
    gw_test_true(nf > 2 && read_all(f, "spec_freq", buf) == 0 && buf[0] == 0 && buf[nf - 1] == (nf - 1) * res.spec_df,
                 "spec_freq = l spec_df");
    double en = NAN;
    hid_t at = H5Aopen(f, "e_n", H5P_DEFAULT);
    if (at >= 0) {
        H5Aread(at, H5T_NATIVE_DOUBLE, &en);
        H5Aclose(at);
    }
    gw_test_true(memcmp(&en, &res.e_n, sizeof en) == 0, "attribute e_n equals the result");
    H5Fclose(f);
    free(buf);
    rc = gw_layer_impact_write_h5(&res, "/nonexistent-dir/impact.h5", "x", &err);
    gw_test_true(rc == GW_EIO && access("/nonexistent-dir", F_OK) != 0,
                 "unwritable path: GW_EIO, nothing left");
    remove(file);
#else
    gw_test_true(rc == GW_EUNSUPPORTED, "no HDF5: GW_EUNSUPPORTED");
#endif
    rmdir(path);
    gw_layer_impact_result_free(&res);
    return gw_test_summary("test_layer_h5");
}
