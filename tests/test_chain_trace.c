/*
 * test_chain_trace.c: the trace outputs of a collision. The CSV wall-force column
 * read back equals the in-memory samples (to the 13 printed digits); the largest
 * sample is the run's F_max exactly (wall-force maxima are event points, so they
 * are samples); when built with HDF5, the datasets /t, /f_wall, /x, /v hold the
 * samples bit for bit, with the run description.
 */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "chain_test_util.h"
#include "gw_test.h"
#if GW_HAVE_HDF5
#include <hdf5.h>
#endif

int main(void)
{
    char dir[] = "/tmp/gw_trace_XXXXXX";
    if (!mkdtemp(dir))
        return 1;
    gw_chain_params p = test_params(5, 0.3);
    gw_chain *c = NULL;
    gw_err err = {{0}};
    if (gw_chain_create(&p, &c, &err) != GW_OK)
        return 1;
    gw_chain_trace tr;
    gw_chain_trace_init(&tr, p.n);
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    o.sample = gw_chain_trace_sample;
    o.sample_ctx = &tr;
    gw_chain_result r;
    if (gw_chain_collide(c, &o, &r, &err) != GW_OK)
        return 1;
    gw_test_true(gw_chain_trace_write(&tr, dir, "t5", "test run", &err) == GW_OK, "trace written");
    double fmax = 0;
    for (size_t k = 0; k < tr.len; k++)
        fmax = fmax > tr.f[k] ? fmax : tr.f[k];
    gw_test_rel(fmax, r.f_max, 1e-12, "largest sample = F_max (maxima are events)");

    char path[512];
    snprintf(path, sizeof path, "%s/t5_wall_force.csv", dir);
    FILE *fp = fopen(path, "r");
    char line[256];
    size_t rows = 0, bad = 0;
    while (fp && fgets(line, sizeof line, fp)) {
        if (line[0] == '#' || line[0] == 't')
            continue;
        double t, f;
        if (sscanf(line, "%lf,%lf", &t, &f) != 2 || rows >= tr.len ||
            fabs(t - tr.t[rows]) > 1e-12 * fabs(tr.t[rows]) || fabs(f - tr.f[rows]) > 1e-11 * (fabs(tr.f[rows]) + 1e-30))
            bad++;
        rows++;
    }
    if (fp)
        fclose(fp);
    gw_test_true(rows == tr.len && bad == 0, "CSV wall force reads back as the samples");
#if GW_HAVE_HDF5
    snprintf(path, sizeof path, "%s/t5.h5", dir);
    hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    gw_test_true(file >= 0, "HDF5 file opens");
    if (file >= 0) {
        double *buf = malloc(tr.len * (size_t)p.n * sizeof *buf);
        const char *names[] = {"t", "f_wall", "x", "v"};
        const double *want[] = {tr.t, tr.f, tr.x, tr.v};
        size_t counts[] = {tr.len, tr.len, tr.len * (size_t)p.n, tr.len * (size_t)p.n};
        for (int k = 0; k < 4; k++) {
            hid_t ds = H5Dopen2(file, names[k], H5P_DEFAULT);
            int ok = ds >= 0 && H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) >= 0 &&
                     memcmp(buf, want[k], counts[k] * sizeof *buf) == 0;
            char what[64];
            snprintf(what, sizeof what, "HDF5 /%s equals the samples bit for bit", names[k]);
            gw_test_true(ok, what);
            if (ds >= 0)
                H5Dclose(ds);
        }
        gw_test_true(H5Aexists(file, "run") > 0, "HDF5 file records the run description");
        free(buf);
        H5Fclose(file);
    }
    remove(path);
#endif
    snprintf(path, sizeof path, "%s/t5_wall_force.csv", dir);
    remove(path);
    snprintf(path, sizeof path, "%s/t5_beads.csv", dir);
    remove(path);
    rmdir(dir);
    gw_chain_result_free(&r);
    gw_chain_trace_free(&tr);
    gw_chain_free(c);
    return gw_test_summary("test_chain_trace");
}
