/*
 * test_library_left48.c: what the forty-eighth library pass left, each case
 * in its own child process (test_child.h):
 *   - gw_layer_write_pvd wrote snapshot times out of order (1, 0) or repeated
 *     (0, 0) as given: refused naming the snapshot, nothing written. A NaN
 *     time (refused before) stays refused. Control: times 0, 0.5, 1 written
 *     in order.
 *   - gw_layer_set_regions took a subnormal ring width (4.9e-324 m: 1/w^2 =
 *     inf) and a width whose square underflows (1e-160 m): each refused
 *     naming the ring width, no regions set; gw_layer_rings_check refuses a
 *     subnormal width too. Control: a width of 0.15 m, three rings, five
 *     regions, and the started layer's kinetic energy is that of its rings
 *     and the region outside them.
 *   - gw_sweep_config_read_string read [params] n = 3:5 (a range) and
 *     [params] n = 3, 5 (a list) as one text, refused only at the first
 *     case's check without a line, and a second [sweep] section after
 *     [grid] set out: each is refused at read naming the line and the key.
 *     Control: a list for radii (a list row) and n = 5 in [params] read.
 *   - gw_chain_get_params(NULL), gw_chain_system(NULL) and
 *     gw_layer_get_params(NULL) took the address of a field of NULL
 *     (undefined behaviour): each is NULL.
 * Built with -DGW_TEST_BEFORE against the library before, which has no
 * gw_layer_rings_check, the check is given that library's behaviour (GW_OK,
 * no message) so that the same source measures the code before.
 */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "granwave.h"
#include "gw_test_cases.h"
#include "test_child.h"

#ifdef GW_TEST_BEFORE
static int gw_layer_rings_check(const gw_layer *L, double cx, double cy, double w, int nring, const double *kinetic,
                                const double *strain, const double *coord, gw_err *err)
{
    (void)L, (void)cx, (void)cy, (void)w, (void)nring, (void)kinetic, (void)strain, (void)coord, (void)err;
    return GW_OK;
}
#endif

static char dir[64];

static int exists(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0;
}

/* -------------------------------------------------------------- pvd ---- */

static int pvd_refused(const double *times, int n, const char *what)
{
    const char *files[3] = {"a.vtk", "b.vtk", "c.vtk"};
    char path[128];
    snprintf(path, sizeof path, "%s/s.pvd", dir);
    unlink(path);
    gw_err e = {0};
    const int rc = gw_layer_write_pvd(path, n, files, times, &e);
    EXPECT(test_refused_or_ok(rc, &e, what));
    EXPECT(!exists(path));
    return 0;
}

static int c_pvd_reversed(void)
{
    const double t[2] = {1, 0};
    return pvd_refused(t, 2, "snapshot 1");
}

static int c_pvd_repeated(void)
{
    const double t[3] = {0, 0.5, 0.5};
    return pvd_refused(t, 3, "snapshot 2");
}

static int c_pvd_nan(void)
{
    const double t[2] = {0, NAN};
    return pvd_refused(t, 2, "snapshot 1");
}

static int c_pvd_control(void)
{
    const char *files[3] = {"a.vtk", "b.vtk", "c.vtk"};
    const double t[3] = {0, 0.5, 1};
    char path[128], text[2048];
    snprintf(path, sizeof path, "%s/s.pvd", dir);
    gw_err e = {0};
    EXPECT(gw_layer_write_pvd(path, 3, files, t, &e) == GW_OK);
    FILE *f = fopen(path, "r");
    EXPECT(f != NULL);
    const size_t got = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[got] = '\0';
    const char *a = strstr(text, "timestep=\"0\""), *b = strstr(text, "timestep=\"0.5\""),
               *c = strstr(text, "timestep=\"1\"");
    EXPECT(a && b && c && a < b && b < c);
    return 0;
}

/* ---------------------------------------------------------- regions ---- */

/* three discs at rest on the floor of a box 1 m wide, moving at 0.1, 0.2 and
 * 0.3 m/s, not started (gw_test_cases.h) */
static gw_layer *three(void)
{
    return test_three_layer(0.1, NULL, 0);
}

static int regions_refused(double w, const char *what)
{
    gw_layer *L = three();
    EXPECT(L != NULL);
    gw_err e = {0};
    const int rc = gw_layer_set_regions(L, 0.5, 0.1, w, 3, &e);
    const int ok = test_refused_or_ok(rc, &e, what) && gw_layer_region_count(L) == 0;
    if (!ok)
        printf("%d regions after the call\n", gw_layer_region_count(L));
    gw_layer_free(L);
    EXPECT(ok);
    return 0;
}

static int c_regions_subnormal(void)
{
    return regions_refused(4.9e-324, "ring width");
}

static int c_regions_underflow(void)
{
    return regions_refused(1e-160, "ring width");
}

static int c_rings_subnormal(void)
{
    gw_layer *L = three();
    EXPECT(L != NULL);
    double kin[3], strain[3], coord[3];
    gw_err e = {0};
    const int rc = gw_layer_rings_check(L, 0.5, 0.1, 4.9e-324, 3, kin, strain, coord, &e);
    gw_layer_free(L);
    EXPECT(refused(rc, &e, "ring width"));
    return 0;
}

static int c_regions_control(void)
{
    gw_layer *L = three();
    EXPECT(L != NULL);
    gw_err e = {0};
    EXPECT(gw_layer_set_regions(L, 0.5, 0.1, 0.15, 3, &e) == GW_OK);
    EXPECT(gw_layer_region_count(L) == 5);
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 1e-5;
    EXPECT(gw_layer_start(L, gw_solver_verlet, &sp, &e) == GW_OK);
    gw_layer_energy tot, reg[5];
    EXPECT(gw_layer_ledgers(L, &tot, reg) == 5);
    /* discs 0.2 m (ring 1), 0 m (ring 0) and 0.2 m (ring 1) from the
     * centre: the rings' kinetic energy adds up to the layer's, none in
     * ring 2 or outside */
    double sum = 0;
    for (int q = 0; q < 5; q++)
        sum += reg[q].kinetic_soil;
    const double total = tot.kinetic_soil;
    gw_layer_free(L);
    EXPECT(total > 0 && fabs(sum - total) <= 1e-12 * total);
    EXPECT(reg[0].kinetic_soil > 0 && reg[1].kinetic_soil > 0 && reg[2].kinetic_soil == 0 && reg[3].kinetic_soil == 0);
    return 0;
}

/* ------------------------------------------------------ sweep config ---- */

static int config_refused(const char *text, const char *what)
{
    gw_err e = {0};
    const int rc = test_config_read(text, &e);
    EXPECT(test_refused_or_ok(rc, &e, what));
    return 0;
}

static int c_config_range(void)
{
    EXPECT(config_refused("[sweep]\nmodel = chain\n[grid]\nvimp = 0.3, 0.4\n[params]\nn = 3:5\n", "cfg:6:") == 0);
    return config_refused("[sweep]\nmodel = chain\n[grid]\nvimp = 0.3, 0.4\n[params]\nn = 3:5\n", "n:");
}

static int c_config_list(void)
{
    EXPECT(config_refused("[sweep]\nmodel = chain\n[grid]\nvimp = 0.3\n[params]\ndt = 1e-7\nn = 3, 5\n", "cfg:7:") ==
           0);
    return config_refused("[sweep]\nmodel = chain\n[grid]\nvimp = 0.3\n[params]\ndt = 1e-7\nn = 3, 5\n", "n:");
}

static int c_config_second_sweep(void)
{
    EXPECT(config_refused("[sweep]\nmodel = chain\n[grid]\nvimp = 0.3, 0.4\n[sweep]\nout = x\n", "cfg:6:") == 0);
    return config_refused("[sweep]\nmodel = chain\n[grid]\nvimp = 0.3, 0.4\n[sweep]\nout = x\n", "'out'");
}

static int c_config_control(void)
{
    int nm = 0;
    const gw_sweep_model *const *models = gw_sweep_models(&nm);
    gw_sweep_config cfg;
    memset(&cfg, 0, sizeof cfg);
    const gw_sweep_model *m = NULL;
    gw_err e = {0};
    const int rc = gw_sweep_config_read_string("[sweep]\nmodel = chain\nout = x\n[grid]\nvimp = 0.3, 0.4\n"
                                               "[params]\nn = 2\nradii = 0.004, 0.005\n",
                                               "cfg", models, nm, &cfg, &m, &e);
    if (rc != GW_OK)
        printf("read: %s\n", e.msg);
    const int ok = rc == GW_OK && cfg.ncases == 2 && cfg.nparams == 2 && cfg.out && strcmp(cfg.out, "x") == 0 &&
                   strcmp(cfg.params[1].values[0], "0.004, 0.005") == 0;
    gw_sweep_config_free(&cfg);
    EXPECT(ok);
    return 0;
}

/* -------------------------------------------------------- accessors ---- */

static int c_accessors_null(void)
{
    EXPECT(gw_chain_get_params(NULL) == NULL);
    EXPECT(gw_chain_system(NULL) == NULL);
    EXPECT(gw_layer_get_params(NULL) == NULL);
    return 0;
}

static int c_accessors_control(void)
{
    gw_layer *L = three();
    EXPECT(L != NULL);
    const gw_layer_params *p = gw_layer_get_params(L);
    const int ok = p && p->width == 1;
    gw_layer_free(L);
    EXPECT(ok);
    return 0;
}

static const child_row rows[] = {
    {"pvd: times 1, 0 refused naming snapshot 1", c_pvd_reversed},
    {"pvd: times 0, 0.5, 0.5 refused naming snapshot 2", c_pvd_repeated},
    {"pvd: a NaN time refused", c_pvd_nan},
    {"pvd: times 0, 0.5, 1 written in order (control)", c_pvd_control},
    {"set_regions: a subnormal ring width refused", c_regions_subnormal},
    {"set_regions: a width whose square underflows refused", c_regions_underflow},
    {"rings check: a subnormal ring width refused", c_rings_subnormal},
    {"set_regions of 0.15 m: the rings' kinetic energy (control)", c_regions_control},
    {"sweep config: [params] n = 3:5 refused at read", c_config_range},
    {"sweep config: [params] n = 3, 5 refused at read", c_config_list},
    {"sweep config: a second [sweep] after [grid] refused", c_config_second_sweep},
    {"sweep config: a list row and a number in [params] (control)", c_config_control},
    {"accessors of NULL: NULL", c_accessors_null},
    {"gw_layer_get_params of a layer (control)", c_accessors_control},
};

int main(void)
{
    static const char *const files[] = {"s.pvd", NULL};
    return test_cases_in_dir(dir, sizeof dir, "left48", rows, sizeof rows / sizeof rows[0], files);
}
