/*
 * gw_study.c: the index of libgranwave's studies and sweep models (gw_study.h):
 * adapters from the studies' typed calls to one signature. No physics here.
 */
#include <stdlib.h>
#include <string.h>

#include "gw_chain_study.h"
#if GW_HAVE_LAYER
#include "gw_layer_study.h"
#include "gw_stats.h"
#endif
#include "gw_study.h"

static int chain_init(void *s) { return gw_chain_setup_init(s); }
static void chain_clear(void *s) { gw_chain_setup_clear(s); }
static int chain_run(const void *s, void *out, gw_progress_fn progress, void *pctx, gw_err *err)
{
    (void)progress;
    (void)pctx;
    return gw_chain_collision_run(s, out, err);
}
static void chain_free(void *out) { gw_chain_collision_free(out); }

static int falcon_init(void *s) { return gw_chain_falcon_setup_init(s); }
static void falcon_clear(void *s) { gw_chain_falcon_setup_clear(s); }
static int falcon_run(const void *s, void *out, gw_progress_fn progress, void *pctx, gw_err *err)
{
    return gw_chain_falcon_run(s, progress, pctx, out, err);
}
static void falcon_free(void *out) { gw_chain_falcon_outcome_free(out); }

static int ws_init(void *s) { return gw_chain_wavespeed_setup_init(s); }
static void ws_clear(void *s) { gw_chain_wavespeed_setup_clear(s); }
static int ws_run(const void *s, void *out, gw_progress_fn progress, void *pctx, gw_err *err)
{
    return gw_chain_wavespeed_run(s, progress, pctx, out, err);
}
static void ws_free(void *out) { gw_chain_wavespeed_outcome_free(out); }

static int sw_init(void *s) { return gw_chain_softwall_setup_init(s); }
static void sw_clear(void *s) { gw_chain_softwall_setup_clear(s); }
static int sw_run(const void *s, void *out, gw_progress_fn progress, void *pctx, gw_err *err)
{
    return gw_chain_softwall_run(s, progress, pctx, out, err);
}
static void sw_free(void *out) { gw_chain_softwall_outcome_free(out); }

static int disp_init(void *s) { return gw_chain_dispersion_setup_init(s); }
static void disp_clear(void *s) { gw_chain_dispersion_setup_clear(s); }
static int disp_run(const void *s, void *out, gw_progress_fn progress, void *pctx, gw_err *err)
{
    return gw_chain_dispersion_run_progress(s, progress, pctx, out, err);
}
static void disp_free(void *out) { gw_chain_dispersion_outcome_free(out); }

static int drop_init(void *s) { return gw_chain_drop_setup_init(s); }
static void drop_clear(void *s) { gw_chain_drop_setup_clear(s); }
static int drop_run(const void *s, void *out, gw_progress_fn progress, void *pctx, gw_err *err)
{
    return gw_chain_drop_study_run(s, progress, pctx, out, err);
}
static void drop_free(void *out) { gw_chain_drop_outcome_free(out); }

#if GW_HAVE_LAYER
static int impact_init(void *s) { return gw_layer_impact_setup_init(s); }
static void impact_clear(void *s) { gw_layer_impact_setup_clear(s); }
static int impact_run(const void *s, void *out, gw_progress_fn progress, void *pctx, gw_err *err)
{
    return gw_layer_impact_run_progress(s, progress, pctx, out, err);
}
static void impact_free(void *out) { gw_layer_impact_outcome_free(out); }

static int make_init(void *s) { return gw_layer_make_setup_init(s); }
static void make_clear(void *s) { gw_layer_make_setup_clear(s); }
static int make_run(const void *s, void *out, gw_progress_fn progress, void *pctx, gw_err *err)
{
    return gw_layer_make_run_progress(s, progress, pctx, out, err);
}
static void make_free(void *out) { gw_layer_make_outcome_free(out); }

/* The statistics include no model header: the layer model's defaults for the
 * parameters a sweep table leaves out are given here (as app/layer/layer_stats.c
 * does for the command). */
static int stats_init(void *s)
{
    int rc = gw_stats_setup_init(s);
    if (rc != GW_OK)
        return rc;
    const gw_layer_impact_params ip = gw_layer_impact_params_default();
    ((gw_stats_setup *)s)->defaults = (gw_stats_defaults){
        .rb_rm = ip.rb_rm, .alpha = ip.alpha_deg, .vi = ip.vi, .density = gw_layer_params_default().density};
    return rc;
}
static void stats_clear(void *s) { gw_stats_setup_clear(s); }
static int stats_run(const void *s, void *out, gw_progress_fn progress, void *pctx, gw_err *err)
{
    (void)progress;
    (void)pctx;
    return gw_stats_run(s, out, err);
}
static void stats_free(void *out) { gw_stats_outcome_free(out); }
#endif

static const gw_study studies[] = {
    {"chain", "one collision of a column of beads with a wall (Falcon et al. 1998)", gw_chain_setup_params,
     sizeof(gw_chain_setup), chain_init, chain_clear, gw_chain_collision_fields, sizeof(gw_chain_collision),
     chain_run, chain_free},
    {"falcon", "the rigid-wall study of Falcon et al. (1998): N = A..B at each impact velocity",
     gw_chain_falcon_setup_params, sizeof(gw_chain_falcon_setup), falcon_init, falcon_clear,
     gw_chain_falcon_outcome_fields, sizeof(gw_chain_falcon_outcome), falcon_run, falcon_free},
    {"wavespeed", "the deformation-wave speed against v_imp, three ways (Falcon et al. 1998, F.16, F.27)",
     gw_chain_wavespeed_setup_params, sizeof(gw_chain_wavespeed_setup), ws_init, ws_clear,
     gw_chain_wavespeed_outcome_fields, sizeof(gw_chain_wavespeed_outcome), ws_run, ws_free},
    {"softwall", "columns on a soft wall: N_d against F.8, the sheets of Table 2 (Falcon et al. 1998)",
     gw_chain_softwall_setup_params, sizeof(gw_chain_softwall_setup), sw_init, sw_clear,
     gw_chain_softwall_outcome_fields, sizeof(gw_chain_softwall_outcome), sw_run, sw_free},
    {"dispersion", "small-amplitude dispersion of a precompressed Hertz chain (physics.md 1.6)",
     gw_chain_dispersion_setup_params, sizeof(gw_chain_dispersion_setup), disp_init, disp_clear,
     gw_chain_dispersion_outcome_fields, sizeof(gw_chain_dispersion_outcome), disp_run, disp_free},
    {"drop", "the whole drop of a column on the sensor: first collision, flights, later impacts (Fig. 12)",
     gw_chain_drop_setup_params, sizeof(gw_chain_drop_setup), drop_init, drop_clear, gw_chain_drop_outcome_fields,
     sizeof(gw_chain_drop_outcome), drop_run, drop_free},
#if GW_HAVE_LAYER
    {"layer-impact", "one block impact on a 2D granular layer (Bourrier et al. 2008)",
     gw_layer_impact_setup_params, sizeof(gw_layer_impact_setup), impact_init, impact_clear,
     gw_layer_impact_outcome_fields, sizeof(gw_layer_impact_outcome), impact_run, impact_free},
    {"layer-make", "pluviate a 2D granular sample (Bourrier et al. 2008)", gw_layer_make_setup_params,
     sizeof(gw_layer_make_setup), make_init, make_clear, gw_layer_make_outcome_fields,
     sizeof(gw_layer_make_outcome), make_run, make_free},
    {"layer-stats", "statistics and bouncing diagram of a layer sweep table (Bourrier et al. 2008)",
     gw_stats_setup_params, sizeof(gw_stats_setup), stats_init, stats_clear, gw_stats_outcome_fields,
     sizeof(gw_stats_outcome), stats_run, stats_free},
#endif
};
#define NSTUDIES ((int)(sizeof studies / sizeof studies[0]))

int gw_study_count(void)
{
    return NSTUDIES;
}

const gw_study *gw_study_get(int i)
{
    return i >= 0 && i < NSTUDIES ? &studies[i] : NULL;
}

const gw_study *gw_study_find(const char *name)
{
    for (int i = 0; name && i < NSTUDIES; i++)
        if (strcmp(studies[i].name, name) == 0)
            return &studies[i];
    return NULL;
}

const char *gw_study_warnings(const gw_study *st, const void *out)
{
    if (!st || !out)
        return NULL;
    for (const gw_param *f = st->fields(); f && f->name; f++)
        if (f->type == GW_PARAM_TEXT && strcmp(f->name, "warnings") == 0) {
            const char *w;
            memcpy(&w, (const char *)out + f->offset, sizeof w);
            return w && *w ? w : NULL;
        }
    return NULL;
}

static const gw_sweep_model *const models[] = {&gw_chain_sweep_model,
#if GW_HAVE_LAYER
                                               &gw_layer_sweep_model
#endif
};

const gw_sweep_model *const *gw_sweep_models(int *n)
{
    if (n)
        *n = (int)(sizeof models / sizeof models[0]);
    return models;
}

int gw_sweep_run_text(const char *text, const char *name, int jobs, gw_progress_fn progress, void *pctx,
                      double **values, long *ncases, const gw_sweep_model **model, gw_err *err)
{
    return gw_sweep_run_text_warned(text, name, jobs, progress, pctx, values, ncases, model, NULL, err);
}

int gw_sweep_run_text_warned(const char *text, const char *name, int jobs, gw_progress_fn progress, void *pctx,
                             double **values, long *ncases, const gw_sweep_model **model, char **warnings,
                             gw_err *err)
{
    if (warnings)
        *warnings = NULL;
    if (values)
        *values = NULL;
    if (ncases)
        *ncases = 0;
    if (model)
        *model = NULL;
    if (!text || !values || !ncases || !model)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_run_text: %s is NULL",
                          !text ? "text" : !values ? "values" : !ncases ? "ncases" : "model");
    int nm = 0;
    const gw_sweep_model *const *ms = gw_sweep_models(&nm);
    gw_sweep_config cfg;
    memset(&cfg, 0, sizeof cfg);
    int rc = gw_sweep_config_read_string(text, name ? name : "sweep", ms, nm, &cfg, model, err);
    if (rc != GW_OK)
        return rc;
    double *v = malloc((size_t)cfg.ncases * (size_t)(*model)->ncolumns * sizeof *v + 1);
    if (!v) {
        gw_sweep_config_free(&cfg);
        return gw_err_set(err, GW_ENOMEM, "sweep: out of memory for %ld cases", cfg.ncases);
    }
    rc = gw_sweep_run_warned(&cfg, *model, jobs, progress, pctx, v, warnings, err);
    if (rc != GW_OK && warnings) { /* no result, no warnings */
        free(*warnings);
        *warnings = NULL;
    }
    if (rc == GW_OK) {
        *values = v;
        *ncases = cfg.ncases;
    } else {
        free(v);
    }
    gw_sweep_config_free(&cfg);
    return rc;
}

int gw_sweep_check_text(const char *text, const char *name, char **warnings, gw_err *err)
{
    if (warnings)
        *warnings = NULL;
    if (!text)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_check_text: text is NULL");
    int nm = 0;
    const gw_sweep_model *const *ms = gw_sweep_models(&nm), *m = NULL;
    gw_sweep_config cfg;
    memset(&cfg, 0, sizeof cfg);
    int rc = gw_sweep_config_read_string(text, name ? name : "sweep", ms, nm, &cfg, &m, err);
    if (rc != GW_OK)
        return rc;
    rc = gw_sweep_check_pass(&cfg, m, NULL, NULL, warnings, err);
    if (rc != GW_OK && warnings) {
        free(*warnings);
        *warnings = NULL;
    }
    gw_sweep_config_free(&cfg);
    return rc;
}

void gw_free(void *p)
{
    free(p);
}

size_t gw_param_row_size(void)
{
    return sizeof(gw_param);
}

size_t gw_study_size(void)
{
    return sizeof(gw_study);
}
