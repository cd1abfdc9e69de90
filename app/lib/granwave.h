/*
 * granwave.h: the whole public API of libgranwave in one include.
 *
 *   gw_common.h  status codes, gw_err, validation, files, fits, JSON
 *   gw_solver.h  the ODE solver layer (CVODE, ARKode, RK4, Verlet backends)
 *   gw_pool.h    the worker pool: independent cases on threads, progress callback
 *   gw_sweep.h   grids of cases (INI configs) and the sweep model interface
 *   gw_stats.h   statistics of a layer sweep table: groups, bouncing diagram, B.31 fit
 *   gw_param.h   parameter tables: each parameter described once
 *   gw_chain.h   the 1D bead column (Falcon et al. 1998) and its studies
 *   gw_chain_study.h  a column collision from its parameter table
 *   gw_layer.h   the 2D granular layer (Bourrier et al. 2008)
 *   gw_layer_study.h  a block impact from its parameter table
 *   gw_study.h   the index of studies and sweep models (for bindings)
 *   gw_abi.h     gw_abi_version(), gw_struct_size(): the ABI, the structs' sizes
 *   gw_version.h GW_VERSION, GW_VERSION_MAJOR/MINOR/PATCH, GW_ABI_VERSION of these headers
 *
 * Link with pkg-config (pkg-config --cflags --libs granwave) or CMake
 * (find_package(granwave CONFIG), target granwave::granwave). Units are SI.
 */
#ifndef GRANWAVE_H
#define GRANWAVE_H

#include "gw_version.h"
#include "gw_common.h"
#include "gw_pool.h"
#include "gw_solver.h"
#include "gw_sweep.h"
#include "gw_stats.h"
#include "gw_param.h"
#include "gw_chain.h"
#include "gw_chain_study.h"
#include "gw_layer.h"
#include "gw_layer_study.h"
#include "gw_study.h"
#include "gw_abi.h"

#endif
