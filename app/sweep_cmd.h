/*
 * sweep_cmd.h: the program's `granwave sweep CONFIG` (sweep_cmd.c) over the
 * sweep models the program links (gw_sweep.h).
 */
#ifndef SWEEP_CMD_H
#define SWEEP_CMD_H

#include "gw_sweep.h"

/* The `granwave sweep` command over the given models; parts (may be NULL, an
 * entry NULL) the run of each that reports its part, for progress lines that
 * see inside the cases. */
int gw_cmd_sweep(int argc, char **argv, const gw_sweep_model *const *models, const gw_sweep_run_part_fn *parts,
                 int nmodels);

#endif
