/*
 * chain_test_util.h: run one chain collision on a named backend for the tests.
 */
#ifndef GW_CHAIN_TEST_UTIL_H
#define GW_CHAIN_TEST_UTIL_H

#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"

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

/* Collide; aborts the test program on a setup or solver failure (a failure then
 * is a test failure, reported with the library's message). */
static inline int test_collide(const gw_chain_params *p, const gw_chain_run_opts *o,
                               gw_chain_result *r)
{
    gw_chain *c = NULL;
    gw_err err = {{0}};
    int rc = gw_chain_create(p, &c, &err);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, o, r, &err);
    gw_chain_free(c);
    if (rc != GW_OK)
        printf("FAIL: collision n = %d failed: %s\n", p->n, err.msg);
    return rc;
}

static inline gw_chain_params test_params(int n, double v)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = n;
    p.v_imp = v;
    return p;
}

#endif
