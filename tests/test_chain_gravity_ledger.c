/*
 * test_chain_gravity_ledger.c: the energy ledger of a column carried by its
 * weight (gravity 1e4 m/s^2, v_imp 1e-9 m/s: the weight, not the impact,
 * sets the motion) closes on CVODE as on ARKode.
 *
 * Before: `granwave chain --n 30 --gravity 1e4 --vimp 1e-9` read a relative
 * energy error of 2.3e-4 under CVODE (ARKode 4e-10), all of it at the first
 * event, t = 8.1e-13 s: the ledger divided |E - E0| by E0 plus the work
 * gravity had done so far, 2e-18 J there, where the run's energy is 0.1 J;
 * and the solvers' absolute tolerances were scaled by the overlap and speed
 * at v_imp (1e-21 m/s for a column ringing at 2 m/s), costing CVODE 6.8e5
 * steps. Now the ledger's scale is at least the energy at the column's speed
 * scale (the speed whose wall collision peaks at the column's weight), the
 * scale of the tolerances too.
 *
 * Asserted for N = 3, 10 and 30 on CVODE BDF, CVODE Adams and ARKode ERK (rtol
 * and atol 1e-12), to t = 0.1 ms: the largest relative energy error is below
 * 1e-7 (the old CVODE BDF runs: 1.7e-5 at N = 10, 2.3e-4 at N = 30, both at
 * t < 4e-12 s), and a run with energy_tol 1e-7 is not stopped by it (it ends,
 * or reaches t_max with bead 1 on the wall). Without gravity nothing changes (the
 * scale is E0, test_chain_energy).
 */
#include <stdio.h>

#include "chain_test_util.h"
#include "gw_test.h"

int main(void)
{
    static const char *solvers[][2] = {{"cvode", "bdf"}, {"cvode", "adams"}, {"arkode", "erk"}};
    const int ns[] = {3, 10, 30};
    char what[800];
    for (size_t k = 0; k < sizeof ns / sizeof ns[0]; k++)
        for (size_t s = 0; s < sizeof solvers / sizeof solvers[0]; s++) {
            gw_chain_params p = test_params(ns[k], 1e-9);
            p.gravity = 1e4;
            gw_chain_run_opts o = test_opts(solvers[s][0], solvers[s][1]);
            o.t_max = 1e-4; /* the old error came within the first picoseconds */
            o.energy_tol = 1e-7;
            gw_chain *c = NULL;
            gw_err err = {{0}};
            gw_chain_result r;
            memset(&r, 0, sizeof r);
            int rc = gw_chain_create(&p, &c, &err);
            if (rc == GW_OK)
                rc = gw_chain_collide(c, &o, &r, &err);
            /* GW_ELIMIT: still on the wall at t_max (a column held by its weight) */
            snprintf(what, sizeof what, "%s/%s N=%d gravity 1e4 v_imp 1e-9: the run is not stopped by energy_tol "
                     "1e-7 (rc %d: %s)", solvers[s][0], solvers[s][1], ns[k], rc, err.msg);
            gw_test_true(rc == GW_OK || rc == GW_ELIMIT, what);
            snprintf(what, sizeof what, "%s/%s N=%d gravity 1e4 v_imp 1e-9: energy error %.3g < 1e-7 (%ld steps)",
                     solvers[s][0], solvers[s][1], ns[k], r.energy_error, (long)r.stats.steps);
            gw_test_true(r.energy_error < 1e-7, what);
            gw_chain_result_free(&r);
            gw_chain_free(c);
        }
    return gw_test_summary("test_chain_gravity_ledger");
}
