/*
 * chain_test_util.h: run one chain collision on a named backend for the tests.
 */
#ifndef GW_CHAIN_TEST_UTIL_H
#define GW_CHAIN_TEST_UTIL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"
#include "gw_chain_study.h"
#include "gw_test.h"

/* Solver settings per backend used across the tests: tight enough that the
 * backends' errors are well below every tolerance asserted. */
static inline gw_chain_run_opts test_opts(const char *solver, const char *method)
{
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.solver = gw_solver_type_find(solver);
    o.sp.method = gw_solver_method_find(method);
    o.sp.rtol = 1e-12;
    o.sp.atol = 1e-12;
    return o;
}

/* Collide; a setup or solver failure is a test failure, counted (it was only
 * printed: test_chain_walls' stiff light sensor, past the sensor's step bound
 * since it was set, skipped its five checks with the test passing), reported
 * with the library's message. */
static inline int test_collide(const gw_chain_params *p, const gw_chain_run_opts *o,
                               gw_chain_result *r)
{
    gw_chain *c = NULL;
    gw_err err = {{0}};
    int rc = gw_chain_create(p, &c, &err);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, o, r, &err);
    gw_chain_free(c);
    if (rc != GW_OK) {
        char what[640];
        snprintf(what, sizeof what, "collision n = %d failed: %s", p->n, err.msg);
        gw_test_true(0, what);
    }
    return rc;
}

static inline gw_chain_params test_params(int n, double v)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = n;
    p.v_imp = v;
    return p;
}

/* One bead hitting the wall at v under p (cvode bdf, tight): its restitution
 * -v_out / v, NaN when the run failed. */
static inline double test_bead_e(gw_chain_params p, double v)
{
    p.n = 1;
    p.v_imp = v;
    gw_chain_run_opts o = test_opts("cvode", "bdf");
    gw_chain_result r;
    double e = test_collide(&p, &o, &r) == GW_OK ? -r.final_v[0] / v : NAN;
    gw_chain_result_free(&r);
    return e;
}

/* A setup initialised and set from NULL-terminated name/value pairs, row by
 * row through the study's table: GW_OK or the first refusal (err). The caller
 * clears s either way. */
static inline int test_setup_kv(gw_chain_setup *s, const char *const *kv, gw_err *err)
{
    gw_chain_setup_init(s);
    int rc = GW_OK;
    for (int i = 0; kv[i] && rc == GW_OK; i += 2)
        rc = gw_param_set(gw_chain_setup_params(), s, kv[i], kv[i + 1], err);
    return rc;
}

#endif
