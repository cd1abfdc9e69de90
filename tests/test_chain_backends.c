/*
 * test_chain_backends.c: the three backends agree on a 7-bead column (issue:
 * F_max and tau_N to 1e-5 relative), and on the discrete observables (N_s,
 * cluster, number of wall contacts) exactly. Every variant is compared with
 * CVODE BDF; the measured spread is ~1e-9, so 1e-5 fails only on a real
 * disagreement (a missed event shifts tau_N by percents).
 */
#include "chain_test_util.h"
#include "gw_test.h"

int main(void)
{
    const char *solvers[][2] = {{"cvode", "bdf"}, {"cvode", "adams"}, {"arkode", "erk"},
                                {"arkode", "dirk"}, {"arkode", "imex"}, {"rk4", "default"}};
    gw_chain_params p = test_params(7, 0.3);
    gw_chain_result ref;
    gw_chain_run_opts o0 = test_opts("cvode", "bdf");
    if (test_collide(&p, &o0, &ref) != GW_OK)
        return 1;
    char what[160];
    for (size_t s = 1; s < sizeof solvers / sizeof solvers[0]; s++) {
        gw_chain_run_opts o = test_opts(solvers[s][0], solvers[s][1]);
        gw_chain_result r;
        if (test_collide(&p, &o, &r) != GW_OK) {
            gw_test_failures++;
            gw_chain_result_free(&r);
            continue;
        }
        snprintf(what, sizeof what, "%s/%s vs cvode/bdf: F_max", solvers[s][0], solvers[s][1]);
        gw_test_rel(r.f_max, ref.f_max, 1e-5, what);
        snprintf(what, sizeof what, "%s/%s vs cvode/bdf: tau_N", solvers[s][0], solvers[s][1]);
        gw_test_rel(r.tau_n, ref.tau_n, 1e-5, what);
        snprintf(what, sizeof what, "%s/%s vs cvode/bdf: tau_max", solvers[s][0], solvers[s][1]);
        gw_test_rel(r.tau_max, ref.tau_max, 1e-5, what);
        snprintf(what, sizeof what, "%s/%s vs cvode/bdf: top bead final velocity", solvers[s][0], solvers[s][1]);
        gw_test_rel(r.final_v[6], ref.final_v[6], 1e-5, what);
        snprintf(what, sizeof what, "%s/%s: same N_s (%d), cluster (%d), wall contacts (%d)",
                 solvers[s][0], solvers[s][1], ref.n_s, ref.cluster, ref.wall_contacts);
        gw_test_true(r.n_s == ref.n_s && r.cluster == ref.cluster &&
                         r.wall_contacts == ref.wall_contacts, what);
        gw_chain_result_free(&r);
    }
    gw_chain_result_free(&ref);
    return gw_test_summary("test_chain_backends");
}
