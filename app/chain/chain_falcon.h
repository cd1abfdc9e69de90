/*
 * chain_falcon.h (private to app/chain/): the Falcon study's data, shared by the
 * command (chain_falcon.c) and its markdown report (chain_falcon_report.c).
 */
#ifndef GW_CHAIN_FALCON_H
#define GW_CHAIN_FALCON_H

#include "chain_options.h"

typedef struct falcon_vel {
    double v, h_mm;     /* h_mm NaN when v was given directly */
    gw_linfit fit;      /* tau_N against N - 1, all N */
    gw_linfit fit20;    /* N <= 20 */
    double f_mean, f_min, f_max, tau_max_mean, period_mean;
    double t_q_theory, tau_1_theory, f_max_1_theory, speed, speed20, speed_theory;
} falcon_vel;

typedef struct falcon {
    chain_cli c;
    int nv, n_lo, n_hi;
    double *v;
    falcon_vel *fv;
    gw_chain_result *res;
    double wall_s;
    double accuracy; /* > 0: solver picked by this relative accuracy target */
} falcon;

static inline const gw_chain_result *res_at(const falcon *f, int iv, int n)
{
    return &f->res[iv * (f->n_hi - f->n_lo + 1) + (n - f->n_lo)];
}

static inline int falcon_ncase(const falcon *f)
{
    return f->nv * (f->n_hi - f->n_lo + 1);
}

/* Write the markdown report comparing the runs with the paper and closed forms. */
int falcon_write_report(const falcon *f, const char *path, gw_err *err);

#endif
