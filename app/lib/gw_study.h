/*
 * gw_study.h: the index of libgranwave's studies, for bindings (the Python
 * module) that drive every study the same way: allocate params_size bytes,
 * init (defaults from the table), set by name (gw_param_set), run into
 * fields_size bytes, read the results through the fields table, free, clear.
 *
 *   study           inputs (table)                       results (table)
 *   "chain"         gw_chain_setup                       gw_chain_collision
 *   "falcon"        gw_chain_falcon_setup                gw_chain_falcon_outcome
 *   "wavespeed"     gw_chain_wavespeed_setup             gw_chain_wavespeed_outcome
 *   "softwall"      gw_chain_softwall_setup              gw_chain_softwall_outcome
 *   "dispersion"    gw_chain_dispersion_setup            gw_chain_dispersion_outcome
 *   "drop"          gw_chain_drop_setup                  gw_chain_drop_outcome
 *   "layer-make"    gw_layer_make_setup                  gw_layer_make_outcome
 *   "layer-impact"  gw_layer_impact_setup                gw_layer_impact_outcome
 *   "layer-stats"   gw_stats_setup                       gw_stats_outcome
 *                   (init gives the layer model's defaults to the statistics)
 *
 * The sweep models (gw_sweep.h) are listed too, for gw_sweep_config_read_string
 * and gw_sweep_run. All tables and entries are static and const.
 */
#ifndef GW_STUDY_H
#define GW_STUDY_H

#include "gw_param.h"
#include "gw_sweep.h"

#include "gw_api.h"

GW_BEGIN_DECLS /* the exported interface, C linkage (gw_api.h) */

typedef struct gw_study {
    const char *name;        /* the program's command ("chain", "layer-impact") */
    const char *summary;     /* one line */
    const gw_param *(*params)(void); /* inputs: rows named as the command's flags */
    size_t params_size;      /* bytes of the input struct */
    int (*init)(void *setup);          /* defaults; GW_OK */
    void (*clear)(void *setup);        /* free what the inputs own */
    const gw_param *(*fields)(void); /* results */
    size_t fields_size;      /* bytes of the result struct */
    /* Run: out zeroed first, free it with free_out also after a failure;
     * a NULL setup or out is refused (GW_EINVAL) writing nothing, as every
     * call that refuses a NULL argument (docs/library.md): out then holds
     * what the caller put there (free it only when that was zeroes).
     * progress may be NULL; studies without progress ignore it. */
    int (*run)(const void *setup, void *out, gw_progress_fn progress, void *pctx, gw_err *err);
    void (*free_out)(void *out);
} gw_study;

/* The study called name, or NULL. */
const gw_study *gw_study_find(const char *name);
/* Study i (0 .. count-1) or NULL; count with gw_study_count. */
const gw_study *gw_study_get(int i);
int gw_study_count(void);

/* The warnings of a run's results out (the study's result struct, after its
 * run returned GW_OK): why results are not final, one text per line, each
 * ending with '\n' (gw_common.h, "warnings of a result"), or NULL when there
 * are none. The texts the program prints after "granwave NAME: warning: " and
 * Python issues as GranwaveWarning. Owned by out (valid until free_out). */
const char *gw_study_warnings(const gw_study *st, const void *out);

/* The sweep models of `granwave sweep` (chain, layer): *n of them. */
const gw_sweep_model *const *gw_sweep_models(int *n);

/* Parse a sweep config given as text (the INI format of gw_sweep.h; name for
 * messages; [sweep] out is not needed) and run every case in memory
 * (gw_sweep_run): *values gets ncases x ncolumns numbers (free with gw_free),
 * *model the model that ran them. Cases in the order of gw_sweep_case (last
 * grid key fastest). GW_EINVAL for the config or a case's value ("case K:
 * ..."), a failing run's status, GW_ECANCELED; *values is then NULL. */
int gw_sweep_run_text(const char *text, const char *name, int jobs, gw_progress_fn progress, void *pctx,
                      double **values, long *ncases, const gw_sweep_model **model, gw_err *err);

/* gw_sweep_run_text, and the sweep's warnings in *warnings (may be NULL:
 * none kept): the lines the program's sweep prints, each ending with '\n'
 * (the check pass's, then the cases that did not end: gw_sweep_run_warned),
 * NULL when none or when the sweep failed; free with gw_free. */
int gw_sweep_run_text_warned(const char *text, const char *name, int jobs, gw_progress_fn progress, void *pctx,
                             double **values, long *ncases, const gw_sweep_model **model, char **warnings,
                             gw_err *err);

/* The check pass of the sweep a config given as text describes (the config
 * read as gw_sweep_run_text reads it), without running a case: the same
 * refusals, GW_EINVAL "case K: ..." or the config's line, as
 * gw_sweep_run_text gives before its first case (gw_sweep_check_pass), and
 * *warnings (may be NULL: none kept) the pass's lines, each ending with '\n',
 * NULL when none or on failure; free with gw_free. Nothing is run or
 * written; the memory of the cases at once (jobs) is not checked. */
int gw_sweep_check_text(const char *text, const char *name, char **warnings, gw_err *err);

/* Free memory the library allocated for the caller (gw_sweep_run_text). */
void gw_free(void *p);

/* sizeof(gw_param) and sizeof(gw_study), for bindings that mirror them. */
size_t gw_param_row_size(void);
size_t gw_study_size(void);

GW_END_DECLS

#endif
