/*
 * layer_test_util.h: a synthetic impact result for the crowns' tests: ns samples
 * every dt s over nr rings, the series zero, for the test to fill, and its free;
 * a small pile settled by layer-make for the tests that run impacts on one;
 * and three discs in a row, a sample built in memory for the hostile tests
 * (test_library_hostile39, test_library_leftovers41, test_library_left43).
 */
#ifndef GW_LAYER_TEST_UTIL_H
#define GW_LAYER_TEST_UTIL_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_layer.h"
#include "gw_layer_study.h"

static inline gw_layer_impact_result test_crowns_result(int nr, int ns, double dt)
{
    gw_layer_impact_result r;
    memset(&r, 0, sizeof r);
    r.ns = ns;
    r.nrings = nr;
    r.e_incident = 1;
    r.t = malloc((size_t)ns * sizeof *r.t);
    r.ring_strain = calloc((size_t)ns * (size_t)nr, sizeof *r.ring_strain);
    r.ring_kin = calloc((size_t)ns * (size_t)nr, sizeof *r.ring_kin);
    r.peak_strain_t = malloc(3 * (size_t)nr * sizeof *r.peak_strain_t);
    if (!r.t || !r.ring_strain || !r.ring_kin || !r.peak_strain_t)
        abort(); /* a test without memory has nothing to say */
    r.peak_kin_t = r.peak_strain_t + nr;
    r.ring_r = r.peak_strain_t + 2 * nr;
    for (int k = 0; k < ns; k++)
        r.t[k] = k * dt;
    return r;
}

/* What test_crowns_result and gw_layer_crowns allocated. */
static inline void test_crowns_result_free(gw_layer_impact_result *r)
{
    free(r->t);
    free(r->ring_strain);
    free(r->ring_kin);
    free(r->peak_strain_t);
    free(r->xcorr_delay);
}

/* A pile settled by layer-make into path, from settings given as name, value
 * pairs ("out" is path): GW_OK, or the first failing call's code with err
 * set. The sample's disc count in *n when n is not NULL. */
static inline int test_make_pile(const char *path, int npairs, const char *const pairs[][2], int *n, gw_err *err)
{
    gw_layer_make_setup m;
    gw_layer_make_setup_init(&m);
    const gw_param *t = gw_layer_make_setup_params();
    int rc = gw_param_set(t, &m, "out", path, err);
    for (int i = 0; rc == GW_OK && i < npairs; i++)
        rc = gw_param_set(t, &m, pairs[i][0], pairs[i][1], err);
    if (rc == GW_OK) {
        gw_layer_make_outcome mo;
        rc = gw_layer_make_run(&m, &mo, err);
        if (rc == GW_OK) {
            if (n)
                *n = mo.sample.n;
            gw_layer_make_outcome_free(&mo);
        }
    }
    gw_layer_make_setup_clear(&m);
    return rc;
}

/* Three discs of radius 0.1 m at y = 0.1 m, x = 0.3, 0.5, 0.7 m, in a box 1 m
 * wide: a sample built in memory (no springs, no bodies, porosity unknown),
 * its arrays static, for a test to spoil one field at a time. */
static inline gw_layer_sample test_three_discs(void)
{
    static double x[3] = {0.3, 0.5, 0.7}, y[3] = {0.1, 0.1, 0.1}, r[3] = {0.1, 0.1, 0.1};
    gw_layer_sample s;
    memset(&s, 0, sizeof s);
    s.n = 3, s.width = 1, s.rm = 0.1, s.volume_ratio = 1, s.porosity = NAN;
    s.x = x, s.y = y, s.r = r;
    return s;
}

#endif
