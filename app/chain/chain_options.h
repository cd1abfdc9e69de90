/*
 * chain_options.h (private to app/chain/): the command-line options shared by the
 * chain commands (model, materials, solver), turned into gw_chain_params and
 * gw_chain_run_opts with one validation path.
 */
#ifndef GW_CHAIN_OPTIONS_H
#define GW_CHAIN_OPTIONS_H

#include "gw_cli.h"
#include "gw_chain.h"
#include "chain_commands.h"
#include "gw_chain_study.h"

typedef struct chain_cli {
    /* raw option values */
    double k, kwall, mass, radius, gravity, gamma, alpha;
    double rtol, atol, dt, dt_max, t_max, dt_out, energy_tol, restitution, restitution_v;
    long max_steps;
    int json;
    const char *out;
    const char *const *out_names; /* the files the command writes into out (checked before the run), or NULL */
    const char *material, *wall_material, *damping, *solver, *method, *sheet, *radii;
    double *radii_v, *masses_v, *kc_v; /* owned arrays for --radii */
    /* the sheet as a material, the sensor as a body, guide friction */
    const char *sheet_law;            /* raw --sheet-law (NULL: not given) */
    double sheet_yield, sheet_loss;   /* -1 after resolve when not given */
    double sensor_mass, sensor_stiffness, sensor_damping;
    double guide_friction, guide_viscous;
    int sheets_mode;     /* set by softwall --sheets before resolve: --sheet-law applies to every sheet */
    gw_sheet_law law;    /* resolved --sheet-law */
    gw_layer_law *layer; /* owned: the layer law of --sheet with a layer law */
    /* resolved */
    gw_chain_params params;
    gw_chain_run_opts run;
} chain_cli;

/* Number of options chain_cli_options writes. */
#define CHAIN_CLI_NOPTS 34

/* Fill defaults and write the shared option table into opts[0..CHAIN_CLI_NOPTS). */
void chain_cli_options(chain_cli *c, gw_opt *opts);
/* The --out line of the command's help: the files it writes into DIR. */
void chain_cli_out_help(gw_opt *opts, const char *help);
/* Replace the help line of option name (a command whose default differs from
 * the shared row's, e.g. falcon's solver by accuracy); opts ends with a zeroed
 * entry or is the CHAIN_CLI_NOPTS shared options followed by one. */
void chain_cli_opt_help(gw_opt *opts, const char *name, const char *help);

/* Resolve materials, damping and solver into c->params / c->run (n and v_imp are
 * the caller's). GW_EINVAL with a message naming the option. The sheet options
 * (--sheet-law, --sheet-yield, --sheet-loss) are checked here; with
 * c->sheets_mode the caller applies the law to each sheet (chain_cli_sheet). */
int chain_cli_resolve(chain_cli *c, const gw_opt *opts, const char *cmd, gw_err *err);

/* Apply sheet s under the resolved --sheet-law (and its overrides) to p; the
 * layer law, if any, goes to *layer (caller frees). */
int chain_cli_sheet(const chain_cli *c, const gw_sheet *s, gw_chain_params *p,
                    gw_layer_law **layer, gw_err *err);

/* Free what chain_cli_resolve allocated (safe to call twice). */
void chain_cli_free(chain_cli *c);

/* A JSON object with the model parameters and solver settings of a run. */
cJSON *chain_cli_settings_json(const chain_cli *c);
/* Replace the solver's dt, dt_max, t_max and dt_out of settings (0 = default)
 * with those run r used, defaults resolved: for a command of one run. */
void chain_cli_settings_run(cJSON *settings, const gw_chain_result *r);
/* For a study of many runs (falcon, wavespeed, softwall): the solver's t_max,
 * dt_out, dt and dt_max of settings become the value every one of the nrun
 * runs used, or null where they differ; and settings gets "runs": {"t_max":
 * [...], "dt_out": [...], "dt": [...], "dt_max": [...]}, each run's value in
 * the order of the study's table (docs/formats.md). */
void chain_cli_settings_runs(cJSON *settings, long nrun, const double *t_max, const double *dt_out,
                             const double *dt, const double *dt_max);

/* The JSON object `granwave chain` prints for one collision r run with c's
 * settings (also the drop's first_collision). */
cJSON *chain_result_json(const chain_cli *c, const gw_chain_result *r, double wall_ms);

/* The provenance header (gw_cli_provenance) with the settings of c; caller frees. */
char *chain_cli_header(const chain_cli *c, const char *cmd, int argc, char **argv);

/* Parse argv against opts (NULL-terminated). Returns -1 to go on, or the exit
 * code when the command is done: 0 after printing --help, 2 after one error
 * line. */
int chain_cli_parse(const char *cmd, const char *usage, const char *summary, gw_opt *opts,
                    int argc, char **argv);

/* Append the sweep options --jobs and --quiet at opts[*k] (advances *k) of a
 * study (falcon, wavespeed, softwall), whose --radii row's help then says it
 * is not taken. */
void chain_cli_sweep_opts(gw_opt *opts, int *k, long *jobs, int *quiet);
/* A study's refusal of --radii (chain_cli_fail): exit code 2. */
int chain_cli_study_radii(const char *cmd);

/* Print "granwave CMD: message" and return exit code 2. */
int chain_cli_fail(const char *msg);
/* The same with the exit code of status rc: 1 for a run's failure (a solver,
 * a limit, the energy monitor, memory: the restitution calibration's one-bead
 * collisions), else 2. */
int chain_cli_fail_rc(int rc, const char *msg);
/* The same for a library message "ROW: reason" of status rc: "granwave CMD
 * --ROW: reason", exit 1 for memory (the check's own allocation) and the
 * run's failures, else 2. */
int chain_cli_study_fail(const char *cmd, int rc, const char *msg);

#endif
