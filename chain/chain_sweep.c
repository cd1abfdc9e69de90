/*
 * chain_sweep.c: independent collisions over a grid of (v_imp, N), spread over
 * threads by the worker pool (gw_cases_run, gw_pool.h). Each case builds its own chain and
 * solver (one SUNDIALS context per solver, hence per thread), so cases share
 * nothing but the case counter.
 */
#include <stdio.h>
#include <string.h>

#include "gw_chain.h"
#include "gw_pool.h"

typedef struct sweep {
    const gw_chain_params *tmpl;
    const gw_chain_run_opts *o;
    const double *v;
    int n_lo, per_v;
    gw_chain_result *res;
} sweep;

static int one(void *arg, long k, gw_err *err)
{
    const sweep *w = arg;
    gw_chain_params p = *w->tmpl;
    p.v_imp = w->v[k / w->per_v];
    p.n = w->n_lo + (int)(k % w->per_v);
    gw_chain *c = NULL;
    gw_err e = {{0}};
    int rc = gw_chain_create(&p, &c, &e);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, w->o, &w->res[k], &e);
    gw_chain_free(c);
    if (rc != GW_OK)
        gw_err_set(err, rc, "N = %d, v_imp = %g m/s: %s", p.n, p.v_imp, e.msg);
    return rc;
}

int gw_chain_sweep_n_progress(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v,
                              int nv, int n_lo, int n_hi, int jobs, gw_progress_fn progress, void *pctx,
                              gw_chain_result *res, gw_err *err)
{
    if (nv < 1 || n_lo < 1 || n_hi < n_lo)
        return gw_err_set(err, GW_EINVAL, "sweep: empty grid");
    sweep w = {tmpl, o, v, n_lo, n_hi - n_lo + 1, res};
    long ncase = (long)nv * w.per_v;
    memset(res, 0, (size_t)ncase * sizeof *res);
    /* the largest column's bounds (steps, memory, samples grow with n) at each
     * speed before any runs: a study was refused only when its run reached that
     * column (softwall --solver rk4 --dt 1e-12 spent minutes on N = 1 first) */
    for (int i = 0; i < nv; i++) {
        gw_chain_params p = *tmpl;
        p.n = n_hi;
        p.v_imp = v[i];
        int rc = gw_chain_run_check(&p, o, err);
        if (rc != GW_OK)
            return rc;
    }
    return gw_cases_run(ncase, jobs, one, &w, progress, pctx, err);
}

int gw_chain_sweep_n(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv,
                     int n_lo, int n_hi, int jobs, int progress, gw_chain_result *res, gw_err *err)
{
    (void)progress; /* the library prints nothing: progress goes through gw_chain_sweep_n_progress */
    return gw_chain_sweep_n_progress(tmpl, o, v, nv, n_lo, n_hi, jobs, NULL, NULL, res, err);
}
