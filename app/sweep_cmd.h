/*
 * sweep_cmd.h: the program's `granwave sweep CONFIG` (sweep_cmd.c) over the
 * sweep models the program links (gw_sweep.h).
 */
#ifndef SWEEP_CMD_H
#define SWEEP_CMD_H

#include "gw_sweep.h"

/* The `granwave sweep` command over the given models. */
int gw_cmd_sweep(int argc, char **argv, const gw_sweep_model *const *models, int nmodels);

#endif
