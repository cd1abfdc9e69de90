/*
 * layer_plan_run.h (internal to the library and the program, not installed):
 * an impact's plan with the settling verdict it found, and the run that takes
 * that verdict instead of finding it again (layer_setup.c, layer_impact.c).
 * The program's layer-impact runs gw_layer_impact itself (its own on_sample
 * hook writes the VTK files and the progress lines): through the public
 * gw_layer_impact_plan_make and gw_layer_impact it checked its sample's
 * settling twice, the plan's check and the run's, and weighed a union-clump
 * pile hit under clump-mass sum for each. gw_layer_impact_plan has no room
 * for the verdict (its layout is the ABI's), so the verdict is kept beside it.
 */
#ifndef GW_LAYER_PLAN_RUN_H
#define GW_LAYER_PLAN_RUN_H

#include "gw_layer.h"
#include "gw_layer_study.h"

/* A run's settling verdict as its plan found it (layer_settling_verdict):
 * the run (layer_impact_run) takes it instead of checking again. */
typedef struct layer_settling_found {
    double q;          /* gw_layer_settled_load_ratio (NaN: nothing recorded) */
    char warning[768]; /* gw_layer_impact_settled_check's warning */
} layer_settling_found;

/* gw_layer_impact_plan_make, and into *found (not NULL) the settling verdict
 * the plan found (set when GW_OK). */
int layer_impact_plan_make_found(const gw_layer_impact_setup *s, gw_layer_impact_plan *p,
                                 layer_settling_found *found, gw_err *err);

/* gw_layer_impact, its sample's settling under lp0 taken from found when the
 * plan found it (found NULL: checked here, once; gw_layer_impact is this with
 * NULL). With found, smp is the plan's sample, as gw_layer_sample_read read
 * it: the shared sample check (layer_sample_limits_check) is the reader's,
 * not taken again; without, taken once here. */
int layer_impact_run(const gw_layer_sample *smp, const gw_layer_params *lp0, const gw_layer_impact_params *ip,
                     const gw_solver_type *type, const gw_solver_params *sp, const layer_settling_found *found,
                     gw_layer_impact_result *res, gw_err *err);

/* A warning into *list (gw_warnings_add) when the crowns of ip (a ring width
 * given, or fewer than 4 rings) around res's impact point leave fewer than 3
 * of rings 1 .. nrings - 1 holding a particle centre of smp: no wave speed can
 * be read (layer_setup.c). */
int layer_crowns_warning(const gw_layer_sample *smp, const gw_layer_impact_params *ip,
                         const gw_layer_impact_result *res, char **list);

/* Bits 1, 2, 4 (strain peaks, kinetic peaks, cross-correlation) for the crown
 * speeds of res nulled as following the pile's slow motion, not the wave
 * (layer_crowns_peaks_locked, layer_crowns_xcorr_locked): "undecided" where
 * the program's text says "unresolved" of a speed the sampling left null. */
unsigned layer_crowns_locked(const gw_layer_impact_result *res);

/* layer_crowns_warning, and into *kinds (NULL: not asked; 0 when it added no
 * line) the rules whose lines it added: GW_LAYER_NULLED_* (gw_layer_study.h) */
int layer_crowns_warning_kinds(const gw_layer_sample *smp, const gw_layer_impact_params *ip,
                               const gw_layer_impact_result *res, char **list, int *kinds);
/* Bits 1, 2, 4 (strain, kinetic, cross-correlation) of the speeds nulled by
 * the resolution rule's error bound alone (standard error at or above half
 * the speed, the sampling resolving it), their values read into c[3] and
 * err[3]: layer_crowns_warning says so (layer_crowns.c). */
unsigned layer_crowns_imprecise(const gw_layer_impact_result *r, double c[3], double err[3]);
/* gw_layer_impact_write_h5, freeing r's series (t, ledger, block and the
 * rings' block) once each is in the file's in-memory image, r->ns and r->cap
 * then 0; r's scalars, peaks, crowns and spectra are kept. For a caller done
 * with the series (the program's --out: its CSVs written before, nothing
 * read of them after): the image holds the same numbers, and with the series
 * kept whole the write held them twice. Freed also after a failure. */
int layer_impact_write_h5_release(gw_layer_impact_result *r, const char *path, const char *header, gw_err *err);

/* A warning into *list when res's energy error is above GW_LAYER_ENERGY_WARN
 * while ip's energy_tol is off (0), naming it and the solver's rtol and atol
 * (rk4, verlet: the step), as the chain's (chain_energy_warning): layer-impact
 * --solver cvode --rtol 1e-4 --atol 1e-4 on a 40-disc pile ended at 1.55 % in
 * silence, where the default runs give 3.4e-5 (rk4) and 1.4e-6 (CVODE). */
#define GW_LAYER_ENERGY_WARN 1e-3
int layer_energy_warning(const gw_layer_impact_result *res, const gw_layer_impact_params *ip,
                         const gw_solver_type *type, const gw_solver_params *sp, char **list);

#endif
