/*
 * sweep_cmd.h: the program's `granwave sweep CONFIG` (sweep_cmd.c) over the
 * sweep models the program links (gw_sweep.h).
 */
#ifndef SWEEP_CMD_H
#define SWEEP_CMD_H

#include "gw_sweep.h"
#include "gw_sweep_impl.h"

/* The `granwave sweep` command over the given models; parts (may be NULL, an
 * entry NULL) the run of each that reports its part, for progress lines that
 * see inside the cases; weighs (may be NULL, an entry NULL) each one's cost
 * of a case before it runs, for their time left (gw_sweep_weigh). */
int gw_cmd_sweep(int argc, char **argv, const gw_sweep_model *const *models, const gw_sweep_run_part_fn *parts,
                 const gw_sweep_weigh *const *weighs, int nmodels);

#endif
