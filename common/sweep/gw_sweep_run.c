/*
 * gw_sweep_run.c: the cases of a sweep config run in memory on the worker pool
 * (gw_pool.h), every case checked first. No physics; each case builds its own
 * model and solver (one SUNDIALS context per solver, hence per thread).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_sweep.h"

typedef struct sweep_ctx {
    const gw_sweep_config *cfg;
    const gw_sweep_model *m;
    double *values;
} sweep_ctx;

static int run_one(void *arg, long k, gw_err *err)
{
    const sweep_ctx *s = arg;
    const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
    gw_sweep_case(s->cfg, k, names, values);
    int rc = s->m->run(s->cfg->ngrid + s->cfg->nparams, names, values, s->values + k * s->m->ncolumns, err);
    if (rc != GW_OK) {
        char tmp[sizeof err->msg];
        snprintf(tmp, sizeof tmp, "%s", err->msg);
        gw_err_set(err, rc, "case %ld: %s", k, tmp);
    }
    return rc;
}

int gw_sweep_run(const gw_sweep_config *cfg, const gw_sweep_model *m, int jobs, gw_progress_fn progress,
                 void *pctx, double *values, gw_err *err)
{
    const int nk = cfg->ngrid + cfg->nparams;
    for (long k = 0; k < cfg->ncases * m->ncolumns; k++)
        values[k] = NAN;
    for (long k = 0; m->check && k < cfg->ncases; k++) {
        const char *names[2 * GW_SWEEP_MAX_KEYS], *vals[2 * GW_SWEEP_MAX_KEYS];
        gw_sweep_case(cfg, k, names, vals);
        int rc = m->check(nk, names, vals, err);
        if (rc != GW_OK) {
            char tmp[sizeof err->msg];
            snprintf(tmp, sizeof tmp, "%s", err ? err->msg : "");
            return gw_err_set(err, rc, "case %ld: %s", k, tmp);
        }
    }
    sweep_ctx s = {cfg, m, values};
    return gw_cases_run(cfg->ncases, jobs, run_one, &s, progress, pctx, err);
}
