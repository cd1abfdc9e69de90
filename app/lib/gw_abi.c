/*
 * gw_abi.c: the ABI number of the library and the size of each public struct
 * by name (gw_abi.h). The table lists every struct of the installed headers;
 * test_abi fails for one it lacks (gw_struct_size 0) or gives a size the
 * compiler's layout does not (tests/abi/gw_abi.py).
 */
#include "gw_abi.h"

#include <string.h>

#include "gw_chain.h"
#include "gw_chain_study.h"
#include "gw_common.h"
#include "gw_param.h"
#include "gw_solver.h"
#include "gw_stats.h"
#include "gw_study.h"
#include "gw_sweep.h"
#if GW_HAVE_LAYER
#include "gw_layer.h"
#include "gw_layer_study.h"
#endif

typedef struct gw_struct_entry {
    const char *name;
    size_t size;
} gw_struct_entry;

/* by tag: each public struct's tag is its typedef's name, and gw_sweep_input has
 * only the tag */
#define GW_STRUCT(T) { #T, sizeof(struct T) }

static const gw_struct_entry gw_structs[] = {
    /* gw_common.h */
    GW_STRUCT(gw_afile),
    GW_STRUCT(gw_err),
    GW_STRUCT(gw_linfit),
    GW_STRUCT(gw_outset),
    /* gw_solver.h */
    GW_STRUCT(gw_band),
    GW_STRUCT(gw_drive),
    GW_STRUCT(gw_solver_params),
    GW_STRUCT(gw_solver_stats),
    GW_STRUCT(gw_system),
    /* gw_sweep.h */
    GW_STRUCT(gw_sweep_config),
    GW_STRUCT(gw_sweep_input),
    GW_STRUCT(gw_sweep_key),
    GW_STRUCT(gw_sweep_model),
    /* gw_stats.h */
    GW_STRUCT(gw_stats_analysis),
    GW_STRUCT(gw_stats_b31),
    GW_STRUCT(gw_stats_b31_fit),
    GW_STRUCT(gw_stats_binary),
    GW_STRUCT(gw_stats_boundary_pt),
    GW_STRUCT(gw_stats_defaults),
    GW_STRUCT(gw_stats_diagram),
    GW_STRUCT(gw_stats_group),
    GW_STRUCT(gw_stats_groups),
    GW_STRUCT(gw_stats_moment),
    GW_STRUCT(gw_stats_outcome),
    GW_STRUCT(gw_stats_panel),
    GW_STRUCT(gw_stats_setup),
    GW_STRUCT(gw_stats_table),
    /* gw_param.h */
    GW_STRUCT(gw_param),
    GW_STRUCT(gw_param_list),
    /* gw_study.h */
    GW_STRUCT(gw_study),
    /* gw_chain.h */
    GW_STRUCT(gw_chain_disp_params),
    GW_STRUCT(gw_chain_disp_result),
    GW_STRUCT(gw_chain_drop_impact),
    GW_STRUCT(gw_chain_drop_params),
    GW_STRUCT(gw_chain_drop_peak),
    GW_STRUCT(gw_chain_drop_result),
    GW_STRUCT(gw_chain_energy),
    GW_STRUCT(gw_chain_guide),
    GW_STRUCT(gw_chain_params),
    GW_STRUCT(gw_chain_result),
    GW_STRUCT(gw_chain_run_opts),
    GW_STRUCT(gw_chain_sensor),
    GW_STRUCT(gw_chain_spectrum),
    GW_STRUCT(gw_chain_trace),
    GW_STRUCT(gw_chain_wall),
    GW_STRUCT(gw_material),
    GW_STRUCT(gw_sheet),
    GW_STRUCT(gw_thornton),
    /* gw_chain_study.h */
    GW_STRUCT(gw_chain_collision),
    GW_STRUCT(gw_chain_dispersion_outcome),
    GW_STRUCT(gw_chain_dispersion_setup),
    GW_STRUCT(gw_chain_drop_outcome),
    GW_STRUCT(gw_chain_drop_setup),
    GW_STRUCT(gw_chain_falcon_fit),
    GW_STRUCT(gw_chain_falcon_outcome),
    GW_STRUCT(gw_chain_falcon_setup),
    GW_STRUCT(gw_chain_falcon_trace),
    GW_STRUCT(gw_chain_resolved),
    GW_STRUCT(gw_chain_setup),
    GW_STRUCT(gw_chain_softwall_outcome),
    GW_STRUCT(gw_chain_softwall_setup),
    GW_STRUCT(gw_chain_wavespeed_outcome),
    GW_STRUCT(gw_chain_wavespeed_setup),
#if GW_HAVE_LAYER
    /* gw_layer.h */
    GW_STRUCT(gw_layer_block_event),
    GW_STRUCT(gw_layer_block_extremes),
    GW_STRUCT(gw_layer_body),
    GW_STRUCT(gw_layer_energy),
    GW_STRUCT(gw_layer_impact_params),
    GW_STRUCT(gw_layer_impact_result),
    GW_STRUCT(gw_layer_make_params),
    GW_STRUCT(gw_layer_make_result),
    GW_STRUCT(gw_layer_params),
    GW_STRUCT(gw_layer_sample),
    GW_STRUCT(gw_layer_settled),
    GW_STRUCT(gw_layer_spring),
    GW_STRUCT(gw_layer_stats),
    /* gw_layer_study.h */
    GW_STRUCT(gw_layer_impact_outcome),
    GW_STRUCT(gw_layer_impact_plan),
    GW_STRUCT(gw_layer_impact_setup),
    GW_STRUCT(gw_layer_make_outcome),
    GW_STRUCT(gw_layer_make_setup),
#endif
};

int gw_abi_version(void)
{
    return GW_ABI_VERSION;
}

size_t gw_struct_size(const char *name)
{
    if (!name)
        return 0;
    for (size_t i = 0; i < sizeof gw_structs / sizeof gw_structs[0]; i++)
        if (strcmp(gw_structs[i].name, name) == 0)
            return gw_structs[i].size;
    return 0;
}
