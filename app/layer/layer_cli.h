/*
 * layer_cli.h (private to app/layer/): the option tables of the layer commands,
 * made from the rows of the library's parameter tables (flags, help, ranges,
 * defaults). layer-impact resolves its options with the library
 * (gw_layer_impact_plan_make), as the `layer` sweep model and Python do.
 * Units: SI, angles in degrees (docs/physics.md 2.1-2.3).
 */
#ifndef GW_LAYER_CLI_H
#define GW_LAYER_CLI_H

#include "gw_cli.h"
#include "gw_layer.h"
#include "gw_layer_study.h"
#include "layer_commands.h"

#define OPT_D(nm, dst, mv, hl, lo_, hi_, open_)                                          \
    (gw_opt) { .name = nm, .kind = GW_OPT_DOUBLE, .dest = dst, .metavar = mv, .help = hl, \
               .lo = lo_, .hi = hi_, .open_lo = open_ }
#define OPT_S(nm, dst, mv, hl)                                                           \
    (gw_opt) { .name = nm, .kind = GW_OPT_STRING, .dest = dst, .metavar = mv, .help = hl }
#define OPT_L(nm, dst, mv, hl, lo_, hi_)                                                 \
    (gw_opt) { .name = nm, .kind = GW_OPT_LONG, .dest = dst, .metavar = mv, .help = hl,   \
               .lo = lo_, .hi = hi_ }

/* Material options shared by layer-make and layer-impact. */
typedef struct layer_mat_cli {
    gw_layer_params lp;
    const char *mass_law;
    const char *clump_mass;
} layer_mat_cli;

/* Number of options layer_mat_options writes. */
#define LAYER_MAT_NOPTS 8

/* Write the material options into o[0 .. LAYER_MAT_NOPTS) from the material
 * rows of table t (layer_setup_rows.h: the impact's or the pluviation's
 * table), their defaults into m; returns LAYER_MAT_NOPTS. mass_law and
 * clump_mass stay NULL when the table has no default (impacts: the sample's). */
int layer_mat_options(const gw_param *t, layer_mat_cli *m, gw_opt *o);

/* GW_OK when every option of o (ended by {0}) came from a table row; GW_EINVAL
 * naming the option otherwise (a bug: a name missing from the table). */
int layer_opts_ok(const gw_opt *o, gw_err *err);

/* The options of one impact (layer-impact without --json and --out). */
typedef struct layer_impact_cli {
    layer_mat_cli m;
    gw_layer_impact_params ip;
    const char *sample, *solver, *method, *out, *until;
    double dt, rtol, atol;
    double rm; /* the sample's R_m, m (from the library's plan) */
    unsigned long long sample_hash; /* its content hash (gw_layer_sample.content_hash) */
    gw_layer_settled settled;  /* its settling's record (recorded 0: none) */
    double settled_q;          /* gw_layer_settled_load_ratio under the impact's material (NaN: none) */
    int sample_springs;        /* the springs the sample carries (gw_layer_sample.n_springs) */
    long rings;
    int json, exact;
    /* resolved by the library (gw_layer_impact_plan_make) */
    const gw_solver_type *type;
    gw_solver_params sp;
} layer_impact_cli;

/* Number of options layer_impact_options writes (materials included). */
#define LAYER_IMPACT_NOPTS (LAYER_MAT_NOPTS + 24)

/* Zero c, fill the defaults and write the impact option table (the rows of
 * gw_layer_impact_setup_params: materials, sample, block, run, solver, flags
 * remove-walls, full and other-settling, until) into
 * o[0 .. LAYER_IMPACT_NOPTS); returns LAYER_IMPACT_NOPTS. The caller appends
 * its own options and the {0} terminator. String options point into argv. */
int layer_impact_options(layer_impact_cli *c, gw_opt *o);

/* The options of one pluviation (layer-make). */
typedef struct layer_make_cli {
    layer_mat_cli m;
    gw_layer_make_params mp;
    long n, seed;
    const char *out, *solver;
    int json;
} layer_make_cli;

/* Number of options layer_make_options writes (materials, --out and --json
 * included). */
#define LAYER_MAKE_NOPTS (LAYER_MAT_NOPTS + 16)

/* Zero c, fill the defaults and write layer-make's option table (the rows of
 * gw_layer_make_setup_params, --json) into o[0 .. LAYER_MAKE_NOPTS); returns
 * LAYER_MAKE_NOPTS. */
int layer_make_options(layer_make_cli *c, gw_opt *o);

#endif
