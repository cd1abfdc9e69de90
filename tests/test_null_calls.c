/*
 * test_null_calls.c: the exported calls of the column's module (gw_chain.h,
 * gw_chain_study.h), the solver layer (gw_solver.h), the sweep statistics
 * (gw_stats.h), the sweep (gw_sweep.h) and the input files (gw_common.h) given NULL for their pointer arguments, all at once, each in a
 * child process, so that a crash fails its check and not the test. A call
 * that returns a status returns GW_EINVAL and names the argument ("NAME: ARG
 * is NULL"); an accessor returns NaN (a number), -1 (an index), 0 (a count),
 * NULL or the default it was given; a void call does nothing, or fills what
 * it was given with NaN or zeros. gw_chain_trace_init and gw_thornton_init
 * dereferenced it (SIGSEGV), and so did the others here but gw_solver_error
 * (which returned a pointer into nothing): the twenty-ninth hostile pass gave
 * NULL one argument at a time. The sweep's calls (gw_sweep_*, 14) and the
 * input files' (gw_input_open, gw_fnv1a64_stream, gw_case_config_hash)
 * crashed the same way until the twenty-fifth session of stage 2 (17 of 17
 * fail on the code before it); the layer's (gw_layer_*):
 * test_layer_null_calls.c; one NULL among valid arguments: test_hostile_api.c and
 * tests/python/test_hostile_twentyninth_py.py.
 */
#include <math.h>
#include <string.h>

#include "gw_chain.h"
#include "gw_chain_study.h"
#include "gw_solver.h"
#include "gw_stats.h"
#include "gw_sweep.h"
#include "gw_test.h"
#include "gw_test_calls.h"


static int c_gw_thornton_init(void)
{
    gw_thornton_init(NULL, 1e11, 1e-3, 1e8); return 1;
}

static int c_gw_chain_trace_init(void)
{
    gw_chain_trace_init(NULL, 3); return 1;
}

static int c_gw_hertz_coefficient(void)
{
    return isnan(gw_hertz_coefficient(1e-3, NULL, INFINITY, NULL));
}

static int c_gw_sheet_kwall(void)
{
    return isnan(gw_sheet_kwall(NULL, 1e-3));
}

static int c_gw_layer_law_create(void)
{
    gw_err e = {{0}}; return gw_layer_law_create(1e-3, gw_material_find("steel"), 1e-3, 1e9, 0.3, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_law_create: out is NULL");
}

static int c_gw_layer_law_hertz_k(void)
{
    return isnan(gw_layer_law_hertz_k(NULL));
}

static int c_gw_layer_law_thickness(void)
{
    return isnan(gw_layer_law_thickness(NULL));
}

static int c_gw_thornton_force(void)
{
    return isnan(gw_thornton_force(NULL, 1e-6, 0, NULL, NULL, NULL));
}

static int c_gw_chain_params_validate(void)
{
    gw_err e = {{0}}; return gw_chain_params_validate(NULL, &e) == GW_EINVAL && gw_test_said(&e, "p is NULL");
}

static int c_gw_sheet_apply(void)
{
    gw_err e = {{0}}; return gw_sheet_apply(NULL, GW_SHEET_FITTED, 0, 0, NULL, NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "s is NULL");
}

static int c_gw_chain_bead_mass(void)
{
    return isnan(gw_chain_bead_mass(NULL, 0));
}

static int c_gw_chain_initial_state(void)
{
    gw_chain_initial_state(NULL, NULL); return 1;
}

static int c_gw_chain_energy_of(void)
{
    gw_chain_energy en; gw_chain_energy_of(NULL, NULL, NULL); gw_chain_energy_of(NULL, NULL, &en); return isnan(en.total);
}

static int c_gw_chain_wall_force(void)
{
    return isnan(gw_chain_wall_force(NULL, NULL));
}

static int c_gw_chain_wall_contact_force(void)
{
    return isnan(gw_chain_wall_contact_force(NULL, NULL));
}

static int c_gw_chain_wall_gap(void)
{
    return isnan(gw_chain_wall_gap(NULL, NULL));
}

static int c_gw_chain_wall_gap_rate(void)
{
    return isnan(gw_chain_wall_gap_rate(NULL, NULL));
}

static int c_gw_chain_force_max_root(void)
{
    return gw_chain_force_max_root(NULL) == -1;
}

static int c_gw_chain_sensor_index(void)
{
    return gw_chain_sensor_index(NULL) == -1;
}

static int c_gw_chain_momentum(void)
{
    return isnan(gw_chain_momentum(NULL, NULL));
}

static int c_gw_chain_rk4_study_covers(void)
{
    return gw_chain_rk4_study_covers(NULL, 10) == 0;
}

static int c_gw_chain_memory_check(void)
{
    gw_err e = {{0}}; return gw_chain_memory_check(NULL, NULL, 0, &e) == GW_EINVAL && gw_test_said(&e, "p is NULL");
}

static int c_gw_chain_run_check(void)
{
    gw_err e = {{0}}; return gw_chain_run_check(NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "p is NULL");
}

static int c_gw_chain_time_scale(void)
{
    return isnan(gw_chain_time_scale(NULL));
}

static int c_gw_chain_step_scale(void)
{
    return isnan(gw_chain_step_scale(NULL));
}

static int c_gw_chain_trace_sample(void)
{
    return gw_chain_trace_sample(NULL, 0, NULL, 0, 0) == GW_EINVAL;
}

static int c_gw_chain_calibrate(void)
{
    gw_err e = {{0}}; return gw_chain_calibrate(NULL, NULL, 0.5, NULL, &e) == GW_EINVAL && gw_test_said(&e, "p is NULL");
}

static int c_gw_chain_disp_dt_sample(void)
{
    return isnan(gw_chain_disp_dt_sample(NULL));
}

static int c_gw_chain_disp_params_validate(void)
{
    gw_err e = {{0}}; return gw_chain_disp_params_validate(NULL, &e) == GW_EINVAL && gw_test_said(&e, "p is NULL");
}

static int c_gw_chain_wall_spectrum(void)
{
    gw_err e = {{0}}; return gw_chain_wall_spectrum(NULL, 0, 1, 0, 0, 0, NULL, &e) == GW_EINVAL && gw_test_said(&e, "sp is NULL");
}

static int c_gw_chain_drop_params_validate(void)
{
    gw_err e = {{0}}; return gw_chain_drop_params_validate(NULL, &e) == GW_EINVAL && gw_test_said(&e, "p is NULL");
}

static int c_gw_chain_drop_impact_rises(void)
{
    return gw_chain_drop_impact_rises(NULL) == 0;
}

static int c_gw_chain_setup_resolve(void)
{
    gw_err e = {{0}}; return gw_chain_setup_resolve(NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "s is NULL");
}

static int c_gw_chain_falcon_analyse(void)
{
    return gw_chain_falcon_analyse(NULL, 0.3, NULL, 1, 3, NULL) == GW_EINVAL;
}

static int c_gw_chain_dispersion_solver(void)
{
    gw_err e = {{0}}; return gw_chain_dispersion_solver(NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "s is NULL");
}

static int c_gw_chain_drop_setup_gaps(void)
{
    gw_err e = {{0}}; return gw_chain_drop_setup_gaps(NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "s is NULL");
}

static int c_gw_chain_drop_block_params(void)
{
    gw_chain_drop_block_params(NULL); return 1;
}

static int c_gw_solver_create(void)
{
    gw_err e = {{0}}; return gw_solver_create(NULL, NULL, NULL, 0, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "out is NULL");
}

static int c_gw_solver_advance(void)
{
    return gw_solver_advance(NULL, 1, NULL, NULL, NULL) == GW_EINVAL;
}

static int c_gw_solver_reset(void)
{
    return gw_solver_reset(NULL, 0, NULL) == GW_EINVAL;
}

static int c_gw_solver_drive(void)
{
    gw_err e = {{0}}; return gw_solver_drive(NULL, NULL, NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "s is NULL");
}

static int c_gw_solver_get_stats(void)
{
    gw_solver_stats st; memset(&st, 0xff, sizeof st); gw_solver_get_stats(NULL, NULL); gw_solver_get_stats(NULL, &st); return st.steps == 0;
}

static int c_gw_solver_get_type(void)
{
    return gw_solver_get_type(NULL) == NULL;
}

static int c_gw_solver_error(void)
{
    const char *m = gw_solver_error(NULL); return m && strlen(m) > 0;
}

static int c_gw_stats_table_parse(void)
{
    gw_err e = {{0}}, e2 = {{0}}; gw_stats_table t; return gw_stats_table_parse(NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "t is NULL") && gw_stats_table_parse(NULL, NULL, &t, &e2) == GW_EINVAL && gw_test_said(&e2, "text is NULL");
}

static int c_gw_stats_table_col(void)
{
    return gw_stats_table_col(NULL, NULL) == -1;
}

static int c_gw_stats_table_key(void)
{
    return gw_stats_table_key(NULL, NULL) == -1;
}

static int c_gw_stats_table_param(void)
{
    return gw_stats_table_param(NULL, NULL) == NULL;
}

static int c_gw_stats_table_value(void)
{
    return gw_stats_table_value(NULL, 0, NULL, 7.0) == 7.0;
}

static int c_gw_stats_table_same(void)
{
    return gw_stats_table_same(NULL, 0, 0, 0) == 0;
}

static int c_gw_stats_moment_of(void)
{
    gw_stats_moment m; gw_stats_moment_of(NULL, 3, NULL); gw_stats_moment_of(NULL, 3, &m); return m.n == 0;
}

static int c_gw_stats_groups_make(void)
{
    gw_err e = {{0}}; return gw_stats_groups_make(NULL, 0.5, NULL, &e) == GW_EINVAL && gw_test_said(&e, "t is NULL");
}

static int c_gw_stats_diagram_make(void)
{
    gw_err e = {{0}}; return gw_stats_diagram_make(3, NULL, NULL, NULL, NULL, 0.5, NULL, &e) == GW_EINVAL && gw_test_said(&e, "d is NULL");
}

static int c_gw_stats_b31_eval(void)
{
    return isnan(gw_stats_b31_eval(NULL, 1.0));
}

static int c_gw_stats_b31_min(void)
{
    double x = 0, f = 0; gw_stats_b31_min(NULL, NULL, NULL); gw_stats_b31_min(NULL, &x, &f); return isnan(x) && isnan(f);
}

static int c_gw_stats_b31_fit_points(void)
{
    gw_err e = {{0}}; return gw_stats_b31_fit_points(NULL, NULL, 3, NULL, 0, NULL, &e) == GW_EINVAL && gw_test_said(&e, "fit is NULL");
}

static int c_gw_stats_fit_parse(void)
{
    gw_err e = {{0}}; return gw_stats_fit_parse(NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "s is NULL");
}

static int c_gw_stats_analyse(void)
{
    gw_err e = {{0}}; return gw_stats_analyse(NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "s is NULL");
}

static int c_gw_stats_json(void)
{
    return gw_stats_json(NULL, 0) == NULL;
}

static int c_gw_stats_group_row(void)
{
    double row[GW_STATS_GROUP_NCOLS]; gw_stats_group_row(NULL, NULL); gw_stats_group_row(NULL, row); return isnan(row[0]) && isnan(row[GW_STATS_GROUP_NCOLS - 1]);
}

static int c_gw_utf8_len(void)
{
    return gw_utf8_len(NULL) == 0;
}

static int c_gw_sweep_case_check(void)
{
    gw_err e = {{0}}; return gw_sweep_case_check(NULL, NULL, 1, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_case_check: m is NULL");
}

static int c_gw_sweep_check_pass(void)
{
    gw_err e = {{0}}; return gw_sweep_check_pass(NULL, NULL, NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_check_pass: cfg is NULL");
}

static int c_gw_sweep_case_check_pass(void)
{
    gw_err e = {{0}}; return gw_sweep_case_check_pass(NULL, 1, NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_case_check_pass: m is NULL");
}

static int c_gw_sweep_checks_end(void)
{
    gw_sweep_checks_end(NULL, NULL); return 1;
}

static int c_gw_sweep_case(void)
{
    return gw_sweep_case(NULL, 0, NULL, NULL) == GW_EINVAL;
}

static int c_gw_sweep_format_row(void)
{
    return gw_sweep_format_row(NULL, 0, NULL, 1, 0, NULL, 16) == GW_EINVAL;
}

static int c_gw_sweep_case_hash(void)
{
    return gw_sweep_case_hash(NULL, 0) == 0;
}

static int c_gw_sweep_row_check(void)
{
    gw_err e = {{0}}; return gw_sweep_row_check(NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_row_check: cfg is NULL");
}

static int c_gw_sweep_journal_scan(void)
{
    gw_err e = {{0}}; long nd = 7; return gw_sweep_journal_scan(NULL, NULL, NULL, &nd, &e) == GW_EINVAL && nd == 0 && gw_test_said(&e, "dir is NULL");
}

static int c_gw_sweep_journal_open(void)
{
    gw_err e = {{0}}; int fd = 3; return gw_sweep_journal_open(NULL, NULL, NULL, NULL, &fd, &e) == GW_EINVAL && fd == -1 && gw_test_said(&e, "dir is NULL");
}

static int c_gw_sweep_journal_open_at(void)
{
    gw_err e = {{0}}; int fd = 3, dfd = 3;
    return gw_sweep_journal_open_at(NULL, NULL, NULL, NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "fd is NULL") &&
           gw_sweep_journal_open_at(NULL, NULL, NULL, NULL, &fd, &dfd, &e) == GW_EINVAL && fd == -1 && dfd == -1 &&
           gw_test_said(&e, "dir is NULL");
}

static int c_gw_sweep_dir_held(void)
{
    gw_err e = {{0}}; return gw_sweep_dir_held(-1, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_dir_held: dir is NULL");
}
static int c_gw_sweep_journal_held(void)
{
    gw_err e = {{0}};
    int back = 7;
    return gw_sweep_journal_held(-1, NULL, "d", &back, &e) == GW_EINVAL && back == 0 &&
           gw_test_said(&e, "gw_sweep_journal_held: fd is NULL");
}

static int c_gw_sweep_write_table(void)
{
    gw_err e = {{0}}; return gw_sweep_write_table(NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_write_table: dir is NULL") &&
           gw_sweep_write_table_at(-1, NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_write_table_at: dir is NULL");
}

static int c_gw_sweep_journal_resume_check(void)
{
    gw_err e = {{0}}; return gw_sweep_journal_resume_check(NULL, NULL, NULL, NULL, NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "dir is NULL");
}

static int c_gw_sweep_inputs_check(void)
{
    gw_err e = {{0}}; return gw_sweep_inputs_check(NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_inputs_check: cfg is NULL");
}

static int c_gw_sweep_case_inputs_check(void)
{
    gw_err e = {{0}}; return gw_sweep_case_inputs_check(NULL, 0, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_case_inputs_check: cfg is NULL");
}

static int c_gw_sweep_journal_append(void)
{
    gw_err e = {{0}}; return gw_sweep_journal_append(-1, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_journal_append: row is NULL");
}

static int c_gw_sweep_memory_check(void)
{
    gw_err e = {{0}}; return gw_sweep_memory_check(NULL, NULL, 1, 0, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_memory_check: cfg is NULL");
}

static int c_gw_sweep_size_check(void)
{
    gw_err e = {{0}}; return gw_sweep_size_check(NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_size_check: cfg is NULL");
}

/* the thirty-fifth pass's calls: the run with its warnings, the cases that
 * did not end and their warning */
static int c_gw_sweep_run_warned(void)
{
    gw_err e = {{0}}; return gw_sweep_run_warned(NULL, NULL, 1, NULL, NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_sweep_run: cfg is NULL");
}

static int c_gw_sweep_undecided(void)
{
    long first = -1;
    return gw_sweep_undecided_rows(NULL, NULL, 3, &first) == 0 && first == -1 && gw_sweep_undecided_rows(NULL, NULL, 3, NULL) == 0 &&
           gw_sweep_undecided_warning(NULL, 1, 1, 0, NULL) == GW_OK;
}

static int c_gw_input_open(void)
{
    gw_err e = {{0}}; return gw_input_open(NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_input_open: out is NULL");
}

static int c_gw_fnv1a64_stream(void)
{
    return gw_fnv1a64_stream(NULL, NULL) == GW_EINVAL;
}

static int c_gw_case_config_hash(void)
{
    return gw_case_config_hash(NULL, 1, NULL, NULL) == 0;
}

/* the sweep model's run with its part (session 30): out, then names */
static int c_gw_chain_sweep_run_part(void)
{
    gw_err e = {{0}}, f = {{0}};
    double out[16];
    return gw_chain_sweep_run_part(1, NULL, NULL, NULL, NULL, NULL, NULL, &e) == GW_EINVAL &&
           gw_test_said(&e, "gw_chain_sweep_run_part: out is NULL") &&
           gw_chain_sweep_run_part(1, NULL, NULL, out, NULL, NULL, NULL, &f) == GW_EINVAL &&
           gw_test_said(&f, "gw_chain_sweep_run_part: names is NULL");
}

static const gw_test_call calls[] = {
    {"gw_thornton_init", c_gw_thornton_init},
    {"gw_chain_trace_init", c_gw_chain_trace_init},
    {"gw_hertz_coefficient", c_gw_hertz_coefficient},
    {"gw_sheet_kwall", c_gw_sheet_kwall},
    {"gw_layer_law_create", c_gw_layer_law_create},
    {"gw_layer_law_hertz_k", c_gw_layer_law_hertz_k},
    {"gw_layer_law_thickness", c_gw_layer_law_thickness},
    {"gw_thornton_force", c_gw_thornton_force},
    {"gw_chain_params_validate", c_gw_chain_params_validate},
    {"gw_sheet_apply", c_gw_sheet_apply},
    {"gw_chain_bead_mass", c_gw_chain_bead_mass},
    {"gw_chain_initial_state", c_gw_chain_initial_state},
    {"gw_chain_energy_of", c_gw_chain_energy_of},
    {"gw_chain_wall_force", c_gw_chain_wall_force},
    {"gw_chain_wall_contact_force", c_gw_chain_wall_contact_force},
    {"gw_chain_wall_gap", c_gw_chain_wall_gap},
    {"gw_chain_wall_gap_rate", c_gw_chain_wall_gap_rate},
    {"gw_chain_force_max_root", c_gw_chain_force_max_root},
    {"gw_chain_sensor_index", c_gw_chain_sensor_index},
    {"gw_chain_momentum", c_gw_chain_momentum},
    {"gw_chain_rk4_study_covers", c_gw_chain_rk4_study_covers},
    {"gw_chain_memory_check", c_gw_chain_memory_check},
    {"gw_chain_run_check", c_gw_chain_run_check},
    {"gw_chain_time_scale", c_gw_chain_time_scale},
    {"gw_chain_step_scale", c_gw_chain_step_scale},
    {"gw_chain_trace_sample", c_gw_chain_trace_sample},
    {"gw_chain_calibrate", c_gw_chain_calibrate},
    {"gw_chain_disp_dt_sample", c_gw_chain_disp_dt_sample},
    {"gw_chain_disp_params_validate", c_gw_chain_disp_params_validate},
    {"gw_chain_wall_spectrum", c_gw_chain_wall_spectrum},
    {"gw_chain_drop_params_validate", c_gw_chain_drop_params_validate},
    {"gw_chain_drop_impact_rises", c_gw_chain_drop_impact_rises},
    {"gw_chain_setup_resolve", c_gw_chain_setup_resolve},
    {"gw_chain_falcon_analyse", c_gw_chain_falcon_analyse},
    {"gw_chain_dispersion_solver", c_gw_chain_dispersion_solver},
    {"gw_chain_drop_setup_gaps", c_gw_chain_drop_setup_gaps},
    {"gw_chain_drop_block_params", c_gw_chain_drop_block_params},
    {"gw_solver_create", c_gw_solver_create},
    {"gw_solver_advance", c_gw_solver_advance},
    {"gw_solver_reset", c_gw_solver_reset},
    {"gw_solver_drive", c_gw_solver_drive},
    {"gw_solver_get_stats", c_gw_solver_get_stats},
    {"gw_solver_get_type", c_gw_solver_get_type},
    {"gw_solver_error", c_gw_solver_error},
    {"gw_stats_table_parse", c_gw_stats_table_parse},
    {"gw_stats_table_col", c_gw_stats_table_col},
    {"gw_stats_table_key", c_gw_stats_table_key},
    {"gw_stats_table_param", c_gw_stats_table_param},
    {"gw_stats_table_value", c_gw_stats_table_value},
    {"gw_stats_table_same", c_gw_stats_table_same},
    {"gw_stats_moment_of", c_gw_stats_moment_of},
    {"gw_stats_groups_make", c_gw_stats_groups_make},
    {"gw_stats_diagram_make", c_gw_stats_diagram_make},
    {"gw_stats_b31_eval", c_gw_stats_b31_eval},
    {"gw_stats_b31_min", c_gw_stats_b31_min},
    {"gw_stats_b31_fit_points", c_gw_stats_b31_fit_points},
    {"gw_stats_fit_parse", c_gw_stats_fit_parse},
    {"gw_stats_analyse", c_gw_stats_analyse},
    {"gw_stats_json", c_gw_stats_json},
    {"gw_stats_group_row", c_gw_stats_group_row},
    {"gw_utf8_len", c_gw_utf8_len},
    {"gw_sweep_case_check", c_gw_sweep_case_check},
    {"gw_sweep_check_pass", c_gw_sweep_check_pass},
    {"gw_sweep_case_check_pass", c_gw_sweep_case_check_pass},
    {"gw_sweep_checks_end", c_gw_sweep_checks_end},
    {"gw_sweep_case", c_gw_sweep_case},
    {"gw_sweep_format_row", c_gw_sweep_format_row},
    {"gw_sweep_case_hash", c_gw_sweep_case_hash},
    {"gw_sweep_row_check", c_gw_sweep_row_check},
    {"gw_sweep_journal_scan", c_gw_sweep_journal_scan},
    {"gw_sweep_journal_open", c_gw_sweep_journal_open},
    {"gw_sweep_journal_open_at", c_gw_sweep_journal_open_at},
    {"gw_sweep_dir_held", c_gw_sweep_dir_held},
    {"gw_sweep_journal_held", c_gw_sweep_journal_held},
    {"gw_sweep_write_table", c_gw_sweep_write_table},
    {"gw_sweep_journal_resume_check", c_gw_sweep_journal_resume_check},
    {"gw_sweep_inputs_check", c_gw_sweep_inputs_check},
    {"gw_sweep_case_inputs_check", c_gw_sweep_case_inputs_check},
    {"gw_sweep_journal_append", c_gw_sweep_journal_append},
    {"gw_sweep_memory_check", c_gw_sweep_memory_check},
    {"gw_sweep_size_check", c_gw_sweep_size_check},
    {"gw_sweep_run_warned", c_gw_sweep_run_warned},
    {"gw_sweep_undecided_rows", c_gw_sweep_undecided},
    {"gw_input_open", c_gw_input_open},
    {"gw_fnv1a64_stream", c_gw_fnv1a64_stream},
    {"gw_case_config_hash", c_gw_case_config_hash},
    {"gw_chain_sweep_run_part", c_gw_chain_sweep_run_part},
};

int main(void)
{
    gw_test_each_call(calls, sizeof calls / sizeof calls[0]);
    return gw_test_summary("test_null_calls");
}
