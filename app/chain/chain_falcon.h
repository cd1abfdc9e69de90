/*
 * chain_falcon.h (private to app/chain/): the Falcon study as the command holds
 * it, shared by the command (chain_falcon.c) and its markdown report
 * (chain_falcon_report.c). Every number comes from the library's
 * gw_chain_falcon_run (the outcome o); c is the command's options, resolved for
 * the settings it reports.
 */
#ifndef GW_CHAIN_FALCON_H
#define GW_CHAIN_FALCON_H

#include "chain_options.h"

typedef struct falcon {
    chain_cli c;
    int n_lo, n_hi;
    gw_chain_falcon_outcome o;
} falcon;

/* The index of collision (velocity iv, column size n) in o's [ncase] arrays. */
static inline int falcon_case(const falcon *f, int iv, int n)
{
    return iv * f->o.nn + (n - f->n_lo);
}

/* The row of bead 1 of collision (iv, n) in o's [nbeads] arrays. */
static inline int falcon_bead_row(const falcon *f, int iv, int n)
{
    long per_v = (long)f->o.nn * (f->n_lo + f->n_hi) / 2, below = (long)(n - f->n_lo) * (f->n_lo + n - 1) / 2;
    return (int)(iv * per_v + below);
}

/* Write the markdown report comparing the runs with the paper and closed forms. */
int falcon_write_report(const falcon *f, const char *path, gw_err *err);

#endif
