/*
 * test_layer_null_calls.c: the exported calls of the layer's module (gw_layer.h,
 * gw_layer_study.h) given NULL for all of their pointer arguments at once, each
 * in a child process, as test_null_calls.c does for the column, the solver
 * layer and the sweep statistics. A call that returns a status returns
 * GW_EINVAL and names the argument ("gw_layer_impact: s is NULL"); an accessor
 * returns NaN (a number), -1 (an index) or 0 (a count); a void call does
 * nothing, or fills what it was given with NaN (a particle's or a body's state,
 * a ledger, the rings) or zeros (the stats, the block's extremes). All 39
 * calls here were killed by SIGSEGV on the code before (the twenty-fifth
 * session of stage 2); the layer's other 30 calls that take pointers did not
 * crash given NULL everywhere then either.
 */
#include <math.h>
#include <string.h>

#include "gw_layer.h"
#include "gw_layer_study.h"
#include "gw_test.h"
#include "gw_test_calls.h"


static int c_gw_layer_params_validate(void)
{
    gw_err e = {{0}}; return gw_layer_params_validate(NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_params_validate: p is NULL");
}

static int c_gw_layer_kn(void)
{
    return isnan(gw_layer_kn(NULL, 1e-3));
}

static int c_gw_layer_kt_factor(void)
{
    return isnan(gw_layer_kt_factor(NULL, 1e-3));
}

static int c_gw_layer_mass(void)
{
    return isnan(gw_layer_mass(NULL, 1e-3));
}

static int c_gw_layer_inertia(void)
{
    return isnan(gw_layer_inertia(NULL, 1e-3));
}

static int c_gw_layer_clump_mass_parse(void)
{
    return gw_layer_clump_mass_parse(NULL) == -1;
}

static int c_gw_layer_advance(void)
{
    gw_err e = {{0}}; return gw_layer_advance(NULL, 1.0, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_advance: L is NULL");
}

static int c_gw_layer_set_event_hook(void)
{
    gw_layer_set_event_hook(NULL, NULL, NULL); return 1;
}

static int c_gw_layer_watch_block(void)
{
    gw_err e = {{0}}; return gw_layer_watch_block(NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_watch_block: L is NULL");
}

static int c_gw_layer_block_extremes_get(void)
{
    gw_layer_block_extremes ex; memset(&ex, 0xff, sizeof ex); gw_layer_block_extremes_get(NULL, NULL); gw_layer_block_extremes_get(NULL, &ex); return ex.n == 0;
}

static int c_gw_layer_get_stats(void)
{
    gw_layer_stats st; memset(&st, 0xff, sizeof st); gw_layer_get_stats(NULL, NULL); gw_layer_get_stats(NULL, &st); return st.steps == 0 && st.rebuilds == 0;
}

static int c_gw_layer_n(void)
{
    return gw_layer_n(NULL) == 0;
}

static int c_gw_layer_time(void)
{
    return isnan(gw_layer_time(NULL));
}

static int c_gw_layer_particle(void)
{
    double s[6] = {0}; gw_layer_particle(NULL, 0, NULL); gw_layer_particle(NULL, 0, s); return isnan(s[0]) && isnan(s[5]);
}

static int c_gw_layer_radius(void)
{
    return isnan(gw_layer_radius(NULL, 0));
}

static int c_gw_layer_particle_mass(void)
{
    return isnan(gw_layer_particle_mass(NULL, 0));
}

static int c_gw_layer_particle_inertia(void)
{
    return isnan(gw_layer_particle_inertia(NULL, 0));
}

static int c_gw_layer_body_count(void)
{
    return gw_layer_body_count(NULL) == 0;
}

static int c_gw_layer_body_of(void)
{
    return gw_layer_body_of(NULL, 0) == -1;
}

static int c_gw_layer_body_state(void)
{
    double s[6] = {0}; gw_layer_body_state(NULL, 0, NULL); gw_layer_body_state(NULL, 0, s); return isnan(s[0]) && isnan(s[5]);
}

static int c_gw_layer_contact_count(void)
{
    return gw_layer_contact_count(NULL, 0) == 0;
}

static int c_gw_layer_set_block(void)
{
    gw_layer_set_block(NULL, 0); return 1;
}

static int c_gw_layer_energy_of(void)
{
    gw_layer_energy e = {0}; gw_layer_energy_of(NULL, NULL); gw_layer_energy_of(NULL, &e); return isnan(e.kinetic_block) && isnan(e.total);
}

static int c_gw_layer_energy_initial(void)
{
    return isnan(gw_layer_energy_initial(NULL));
}

static int c_gw_layer_set_regions(void)
{
    gw_err e = {{0}}; return gw_layer_set_regions(NULL, 0, 0, 1, 3, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_set_regions: L is NULL");
}

static int c_gw_layer_region_count(void)
{
    return gw_layer_region_count(NULL) == 0;
}

static int c_gw_layer_ledgers(void)
{
    gw_layer_energy e = {0}; return gw_layer_ledgers(NULL, NULL, NULL) == 0 && gw_layer_ledgers(NULL, &e, NULL) == 0 && isnan(e.total);
}

static int c_gw_layer_region_ledger(void)
{
    return gw_layer_region_ledger(NULL, NULL) == 0;
}

static int c_gw_layer_rings(void)
{
    double k[2] = {0}, s[2] = {0}, c[2] = {0}; gw_layer_rings(NULL, 0, 0, 1, 2, NULL, NULL, NULL); gw_layer_rings(NULL, 0, 0, 1, 2, k, s, c); return isnan(k[1]) && isnan(s[1]) && isnan(c[1]);
}

static int c_gw_layer_make(void)
{
    gw_err e = {{0}}; return gw_layer_make(NULL, NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_make: mp is NULL");
}

static int c_gw_layer_sample_porosity(void)
{
    return isnan(gw_layer_sample_porosity(NULL));
}

static int c_gw_layer_impact_check(void)
{
    gw_err e = {{0}}; return gw_layer_impact_check(NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_impact_check: s is NULL");
}

static int c_gw_layer_impact_check_with(void)
{
    gw_err e = {{0}}; return gw_layer_impact_check_with(NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_impact_check_with: s is NULL");
}

static int c_gw_layer_impact_fall_check(void)
{
    gw_err e = {{0}}; return gw_layer_impact_fall_check(NULL, 9.81, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_impact_fall_check: ip is NULL");
}

static int c_gw_layer_impact_gap_check(void)
{
    gw_err e = {{0}}; return gw_layer_impact_gap_check(NULL, NULL, 9.81, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_impact_gap_check: s is NULL");
}

static int c_gw_layer_impact_rest_check(void)
{
    gw_err e = {{0}}; return gw_layer_impact_rest_check(NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_impact_rest_check: s is NULL");
}

static int c_gw_layer_impact_dem_dt(void)
{
    return isnan(gw_layer_impact_dem_dt(NULL, NULL, NULL));
}

static int c_gw_layer_impact(void)
{
    gw_err e = {{0}}; return gw_layer_impact(NULL, NULL, NULL, NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_impact: s is NULL");
}

static int c_gw_layer_impact_write_h5(void)
{
    gw_err e = {{0}}; return gw_layer_impact_write_h5(NULL, NULL, NULL, &e) == GW_EINVAL && gw_test_said(&e, "gw_layer_impact_write_h5: res is NULL");
}

static int c_gw_layer_crowns(void)
{
    return gw_layer_crowns(NULL) == GW_EINVAL;
}

/* the sweep model's run with its part (session 30): out, then names */
static int c_gw_layer_sweep_run_part(void)
{
    gw_err e = {{0}}, f = {{0}};
    double out[64];
    return gw_layer_sweep_run_part(1, NULL, NULL, NULL, NULL, NULL, NULL, &e) == GW_EINVAL &&
           gw_test_said(&e, "gw_layer_sweep_run_part: out is NULL") &&
           gw_layer_sweep_run_part(1, NULL, NULL, out, NULL, NULL, NULL, &f) == GW_EINVAL &&
           gw_test_said(&f, "gw_layer_sweep_run_part: names is NULL");
}

static const gw_test_call calls[] = {
    {"gw_layer_params_validate", c_gw_layer_params_validate},
    {"gw_layer_kn", c_gw_layer_kn},
    {"gw_layer_kt_factor", c_gw_layer_kt_factor},
    {"gw_layer_mass", c_gw_layer_mass},
    {"gw_layer_inertia", c_gw_layer_inertia},
    {"gw_layer_clump_mass_parse", c_gw_layer_clump_mass_parse},
    {"gw_layer_advance", c_gw_layer_advance},
    {"gw_layer_set_event_hook", c_gw_layer_set_event_hook},
    {"gw_layer_watch_block", c_gw_layer_watch_block},
    {"gw_layer_block_extremes_get", c_gw_layer_block_extremes_get},
    {"gw_layer_get_stats", c_gw_layer_get_stats},
    {"gw_layer_n", c_gw_layer_n},
    {"gw_layer_time", c_gw_layer_time},
    {"gw_layer_particle", c_gw_layer_particle},
    {"gw_layer_radius", c_gw_layer_radius},
    {"gw_layer_particle_mass", c_gw_layer_particle_mass},
    {"gw_layer_particle_inertia", c_gw_layer_particle_inertia},
    {"gw_layer_body_count", c_gw_layer_body_count},
    {"gw_layer_body_of", c_gw_layer_body_of},
    {"gw_layer_body_state", c_gw_layer_body_state},
    {"gw_layer_contact_count", c_gw_layer_contact_count},
    {"gw_layer_set_block", c_gw_layer_set_block},
    {"gw_layer_energy_of", c_gw_layer_energy_of},
    {"gw_layer_energy_initial", c_gw_layer_energy_initial},
    {"gw_layer_set_regions", c_gw_layer_set_regions},
    {"gw_layer_region_count", c_gw_layer_region_count},
    {"gw_layer_ledgers", c_gw_layer_ledgers},
    {"gw_layer_region_ledger", c_gw_layer_region_ledger},
    {"gw_layer_rings", c_gw_layer_rings},
    {"gw_layer_make", c_gw_layer_make},
    {"gw_layer_sample_porosity", c_gw_layer_sample_porosity},
    {"gw_layer_impact_check", c_gw_layer_impact_check},
    {"gw_layer_impact_check_with", c_gw_layer_impact_check_with},
    {"gw_layer_impact_fall_check", c_gw_layer_impact_fall_check},
    {"gw_layer_impact_gap_check", c_gw_layer_impact_gap_check},
    {"gw_layer_impact_rest_check", c_gw_layer_impact_rest_check},
    {"gw_layer_impact_dem_dt", c_gw_layer_impact_dem_dt},
    {"gw_layer_impact", c_gw_layer_impact},
    {"gw_layer_impact_write_h5", c_gw_layer_impact_write_h5},
    {"gw_layer_crowns", c_gw_layer_crowns},
    {"gw_layer_sweep_run_part", c_gw_layer_sweep_run_part},
};

int main(void)
{
    gw_test_each_call(calls, sizeof calls / sizeof calls[0]);
    return gw_test_summary("test_layer_null_calls");
}
