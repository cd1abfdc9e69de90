/*
 * test_library_hostile46b.c: the forty-sixth hostile pass over the library's C
 * interface, second part (docs/library.md "The contract of every call"):
 * calls that took what they should refuse.
 *   - gw_layer_make_result_warnings on a result filled by hand: converged -3
 *     (or 2) was taken as settled (no warning, GW_OK); converged 0 with E_k
 *     below a known threshold and the floor carrying the pile was told
 *     "E_k = 0 J still above --ke-threshold ... (1 J)"; an E_k or a floor
 *     load of NaN was stated as it came. Now converged other than 0 or 1, and
 *     an unsettled verdict with E_k, floor load, t_judge or ke_limit NaN,
 *     infinite or negative, are GW_EINVAL with nothing added, and the verdict
 *     alone is said as such (E_k below the threshold, the floor's load).
 *     Controls: E_k above the threshold, a settled result, and the results
 *     of two real pluviations (one settled, one stopped before its verdict)
 *     are described as before.
 *   - gw_chain_rk4_study_covers(p, -5) and (p, 0) said 1 (a column of no
 *     bead covered); gw_chain_trace_check passed n = 0; gw_chain_memory_check
 *     passed the methods -5, 6 and 11 (sized as an explicit one). Each is now
 *     0 or GW_EINVAL naming the argument (the method's range by
 *     gw_check_range's message); n_max 1 and 40, n = 1, and the six methods
 *     under cvode and arkode pass (cvode with erk too: gw_solver_create's
 *     GW_EUNSUPPORTED, not this check's).
 *   - gw_layer_make's contract on out (layer/gw_layer.h): out is zeroed
 *     whatever the call returns, so a failure after a success leaves it
 *     zeroed (the caller frees a filled sample first; the library cannot tell
 *     its arrays from a caller's).
 * Each case runs in its own child process (test_child.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "granwave.h"
#include "gw_test_cases.h"
#include "test_child.h"

/* the result's warnings refused: GW_EINVAL, nothing added */
static int warnings_refused(const gw_layer_make_result *r)
{
    char *list = NULL;
    const int rc = gw_layer_make_result_warnings(r, 2.0, "o.txt", &list);
    if (rc != GW_EINVAL || list) {
        printf("status %d, list '%s' (wanted GW_EINVAL and nothing)\n", rc, list ? list : "(null)");
        free(list);
        return 0;
    }
    return 1;
}

static int c_conv_neg3(void)
{
    gw_layer_make_result r = test_unsettled_make_result();
    r.converged = -3;
    r.untrimmed_top_rm = 5; /* its warning is not added either */
    EXPECT(warnings_refused(&r));
    return 0;
}

static int c_conv_2(void)
{
    gw_layer_make_result r = test_unsettled_make_result();
    r.converged = 2;
    EXPECT(warnings_refused(&r));
    return 0;
}

static int c_ke_nan(void)
{
    gw_layer_make_result r = test_unsettled_make_result();
    r.ke_final = NAN;
    EXPECT(warnings_refused(&r));
    r.ke_final = -1;
    EXPECT(warnings_refused(&r));
    return 0;
}

static int c_load_nan(void)
{
    gw_layer_make_result r = test_unsettled_make_result();
    r.floor_load = NAN;
    EXPECT(warnings_refused(&r));
    r.floor_load = -1;
    EXPECT(warnings_refused(&r));
    return 0;
}

static int c_limit_judge_bad(void)
{
    gw_layer_make_result r = test_unsettled_make_result();
    r.ke_limit = NAN;
    EXPECT(warnings_refused(&r));
    r.ke_limit = -1;
    EXPECT(warnings_refused(&r));
    r = test_unsettled_make_result();
    r.t_judge = NAN;
    EXPECT(warnings_refused(&r));
    r.t_judge = INFINITY;
    EXPECT(warnings_refused(&r));
    return 0;
}

/* converged 0 though E_k (0 J, then 0.5 J with 0.2 J of fall) lies below the
 * known 1 J and the floor carries the pile: the verdict alone, said as such */
static int c_verdict_alone(void)
{
    gw_layer_make_result r = test_unsettled_make_result();
    r.ke_final = 0;
    char *list = NULL;
    EXPECT(gw_layer_make_result_warnings(&r, 2.0, "o.txt", &list) == GW_OK && list);
    int ok = !strstr(list, "still above") && strstr(list, "its run did not call it settled (converged 0)") &&
             strstr(list, "E_k = 0 J lies below --ke-threshold (1 J)") && strstr(list, "carries 1 of the pile's");
    if (!ok)
        printf("text: %s\n", list);
    free(list);
    EXPECT(ok);
    r.ke_final = 0.5, r.fall_energy = 0.2;
    list = NULL;
    EXPECT(gw_layer_make_result_warnings(&r, 2.0, NULL, &list) == GW_OK && list);
    ok = !strstr(list, "still above") && strstr(list, "E_k = 0.5 J and 0.2 J of grains in flight lies below");
    if (!ok)
        printf("text: %s\n", list);
    free(list);
    EXPECT(ok);
    return 0;
}

/* controls: E_k above the threshold, the floor low, settled, no t_max */
static int c_controls(void)
{
    gw_layer_make_result r = test_unsettled_make_result();
    char *list = NULL;
    EXPECT(gw_layer_make_result_warnings(&r, 2.0, "o.txt", &list) == GW_OK && list &&
           strstr(list, "E_k = 10 J still above --ke-threshold at t-max = 2 s (1 J; raise --t-max)"));
    free(list);
    list = NULL;
    r.ke_final = 0, r.floor_load = 0.2;
    EXPECT(gw_layer_make_result_warnings(&r, 2.0, NULL, &list) == GW_OK && list &&
           strstr(list, "its floor carries 0.2 of the pile's weight") && !strstr(list, "still above"));
    free(list);
    list = NULL;
    r = test_unsettled_make_result();
    r.converged = 1, r.ke_final = NAN; /* a settled result states none of its numbers */
    EXPECT(gw_layer_make_result_warnings(&r, NAN, NULL, &list) == GW_OK && !list);
    r = test_unsettled_make_result();
    r.ke_limit = 0; /* unknown (a result from before ke_limit): E_k named, as before */
    EXPECT(gw_layer_make_result_warnings(&r, 2.0, NULL, &list) == GW_OK && list &&
           strstr(list, "E_k = 10 J still above --ke-threshold at t-max = 2 s (raise --t-max)"));
    free(list);
    list = NULL;
    r.ke_final = 0; /* but not an E_k of 0 (the threshold is positive) */
    EXPECT(gw_layer_make_result_warnings(&r, 2.0, NULL, &list) == GW_OK && list && !strstr(list, "still above") &&
           strstr(list, "E_k = 0 J lies below --ke-threshold and its floor carries 1 of"));
    free(list);
    return 0;
}

/* real pluviations' results pass: one that settles (no warning), one stopped
 * before its verdict (the t_judge text) */
static int c_real_runs(void)
{
    gw_layer_params lp = gw_layer_params_default();
    gw_layer_make_params mp = gw_layer_make_params_default();
    gw_layer_sample s;
    gw_layer_make_result res;
    gw_err e = {{0}};
    mp.n = 10, mp.width_rm = 4, mp.t_max = 3; /* settles at 2.9 s */
    EXPECT(gw_layer_make(&lp, &mp, &s, &res, &e) == GW_OK);
    char *list = NULL;
    EXPECT(res.converged == 1 && gw_layer_make_result_warnings(&res, mp.t_max, NULL, &list) == GW_OK && !list);
    gw_layer_sample_free(&s);
    mp.t_max = 0.05;
    EXPECT(gw_layer_make(&lp, &mp, &s, &res, &e) == GW_OK);
    EXPECT(res.converged == 0 && gw_layer_make_result_warnings(&res, mp.t_max, NULL, &list) == GW_OK && list &&
           strstr(list, "ends before the settling is judged"));
    free(list);
    gw_layer_sample_free(&s);
    return 0;
}

/* gw_layer_make's contract: out zeroed whatever the call returns */
static int c_make_out(void)
{
    gw_layer_params lp = gw_layer_params_default();
    gw_layer_make_params mp = gw_layer_make_params_default();
    gw_layer_sample s;
    gw_layer_make_result res;
    gw_err e = {{0}};
    mp.n = 5, mp.t_max = 0.05;
    EXPECT(gw_layer_make(&lp, &mp, &s, &res, &e) == GW_OK && s.n == 5 && s.x);
    gw_layer_sample keep = s; /* the caller's: freed below, as the contract asks */
    mp.n = 0;
    EXPECT(refused(gw_layer_make(&lp, &mp, &s, &res, &e), &e, "n"));
    EXPECT(s.n == 0 && !s.x && !s.y && !s.r && !s.springs && s.n_springs == 0 && res.converged == 0);
    gw_layer_sample_free(&s); /* a zeroed sample: nothing */
    gw_layer_sample_free(&keep);
    return 0;
}

static int c_covers(void)
{
    const gw_chain_params p = gw_chain_params_default();
    EXPECT(gw_chain_rk4_study_covers(&p, -5) == 0);
    EXPECT(gw_chain_rk4_study_covers(&p, 0) == 0);
    EXPECT(gw_chain_rk4_study_covers(&p, -(1L << 62)) == 0);
    EXPECT(gw_chain_rk4_study_covers(&p, 1) == 1 && gw_chain_rk4_study_covers(&p, 40) == 1); /* controls */
    EXPECT(gw_chain_rk4_study_covers(&p, 41) == 0);
    return 0;
}

static int c_trace_n0(void)
{
    gw_err e = {{0}};
    EXPECT(refused(gw_chain_trace_check(0, 1e-3, 1e-6, 0, &e), &e, "n 0"));
    EXPECT(refused(gw_chain_trace_check(0, 1e-3, 1e-6, 0, &e), &e, "n >= 1"));
    EXPECT(gw_chain_trace_check(1, 1e-3, 1e-6, 6, &e) == GW_OK); /* control */
    return 0;
}

static int c_mem_method(void)
{
    const gw_chain_params p = gw_chain_params_default();
    static const int bad[] = {-5, -1, 6, 11, 1 << 30};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        gw_err e = {{0}};
        char want[64];
        snprintf(want, sizeof want, ": %d is outside [0, 5]", bad[k]);
        EXPECT(refused(gw_chain_memory_check(&p, gw_solver_arkode, bad[k], &e), &e, "method"));
        EXPECT(refused(gw_chain_memory_check(&p, NULL, bad[k], &e), &e, want));
    }
    return 0;
}

static int c_mem_method_controls(void)
{
    const gw_chain_params p = gw_chain_params_default();
    const gw_solver_type *types[] = {NULL, gw_solver_cvode, gw_solver_arkode, gw_solver_rk4};
    for (size_t t = 0; t < sizeof types / sizeof types[0]; t++)
        for (int m = GW_METHOD_DEFAULT; m <= GW_ARKODE_IMEX; m++) {
            gw_err e = {{0}};
            const int rc = gw_chain_memory_check(&p, types[t], m, &e);
            if (rc != GW_OK)
                printf("type %zu method %d: %d %s\n", t, m, rc, e.msg);
            EXPECT(rc == GW_OK);
        }
    return 0;
}

int main(void)
{
    static const child_row rows[] = {
        {"gw_layer_make_result_warnings: converged -3 (with an untrimmed top)", c_conv_neg3},
        {"gw_layer_make_result_warnings: converged 2", c_conv_2},
        {"gw_layer_make_result_warnings: E_k NaN, -1", c_ke_nan},
        {"gw_layer_make_result_warnings: floor load NaN, -1", c_load_nan},
        {"gw_layer_make_result_warnings: ke_limit NaN, -1; t_judge NaN, inf", c_limit_judge_bad},
        {"gw_layer_make_result_warnings: converged 0, E_k below, the floor carrying the pile", c_verdict_alone},
        {"gw_layer_make_result_warnings: E_k above, floor low, settled, unknown limit (controls)", c_controls},
        {"gw_layer_make_result_warnings: two real pluviations (controls)", c_real_runs},
        {"gw_layer_make: out zeroed by a failure after a success (the contract)", c_make_out},
        {"gw_chain_rk4_study_covers: n_max -5, 0, -2^62", c_covers},
        {"gw_chain_trace_check: n = 0", c_trace_n0},
        {"gw_chain_memory_check: method -5, -1, 6, 11, 2^30", c_mem_method},
        {"gw_chain_memory_check: methods 0 to 5 under every backend (controls)", c_mem_method_controls},
    };
    return child_cases_run(rows, sizeof rows / sizeof rows[0]);
}
