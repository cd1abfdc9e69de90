/*
 * test_chain_closed_forms.c: a single Hertz bead on the wall against the closed
 * forms (docs/physics.md 1.3: F.2, F.13, F.21) on every backend, and the material
 * coefficients (F.12, F.3) against docs/physics.md's values.
 *
 * Tolerances: 1e-4 relative for tau_1 and F_max (issue requirement; the
 * integrations at rtol 1e-12 are ~1e-9 accurate, so a wrong exponent or
 * constant fails by orders of magnitude). docs/physics.md quotes k = 6.9716e9 and
 * K = 9.858e9 rounded: checked to 2e-4 (F.12 gives 6.97089e9, 1.0e-4 below
 * the quoted value) and 1e-4; the mass 2.104e-3 (4 digits, rounding up to
 * 2.4e-4) to 3e-4.
 */
#include "chain_test_util.h"
#include "gw_test.h"

int main(void)
{
    /* (4/5) B(2/5, 1/2) from GSL against the Gamma-function form with libm's
     * tgamma (independent code) to 1e-12. docs/physics.md quotes 2.94322; the exact
     * value is 2.9432752, so the quoted digits are off by 1.9e-5: checked to 3e-5. */
    double c_exact = 0.8 * tgamma(0.4) * tgamma(0.5) / tgamma(0.9);
    gw_test_rel(gw_chain_tau_constant(), c_exact, 1e-12, "tau constant vs (4/5) G(2/5) G(1/2) / G(9/10)");
    gw_test_rel(gw_chain_tau_constant(), 2.94322, 3e-5, "tau constant vs docs/physics.md 2.94322");

    gw_chain_params p = gw_chain_params_default();
    gw_test_rel(p.k, 6.9716e9, 2e-4, "steel k (F.12) vs docs/physics.md");
    gw_test_rel(p.kwall, 9.858e9, 1e-4, "steel-on-steel K (F.3) vs docs/physics.md");
    gw_test_rel(p.mass, 2.104e-3, 3e-4, "steel bead mass 4/3 pi R^3 rho");
    gw_test_rel(gw_chain_kc(p.k), 4.0e9, 0.02, "K_c (F.22) vs docs/physics.md 4.0e9");

    const char *solvers[][2] = {{"cvode", "bdf"}, {"cvode", "adams"}, {"arkode", "erk"},
                                {"arkode", "dirk"}, {"rk4", "default"}};
    const double vs[] = {0.1, 0.3, 1.0};
    for (size_t s = 0; s < sizeof solvers / sizeof solvers[0]; s++)
        for (size_t iv = 0; iv < sizeof vs / sizeof vs[0]; iv++) {
            gw_chain_params q = test_params(1, vs[iv]);
            gw_chain_run_opts o = test_opts(solvers[s][0], solvers[s][1]);
            gw_chain_result r;
            char what[128];
            if (test_collide(&q, &o, &r) == GW_OK) {
                double tau1 = gw_chain_tau1(q.mass, q.kwall, q.v_imp);
                double fmax = gw_chain_fmax1(q.mass, q.kwall, q.v_imp);
                snprintf(what, sizeof what, "%s/%s v=%g: tau_1 (F.2)", solvers[s][0], solvers[s][1], vs[iv]);
                gw_test_rel(r.tau_n, tau1, 1e-4, what);
                snprintf(what, sizeof what, "%s/%s v=%g: F_max (F.13)", solvers[s][0], solvers[s][1], vs[iv]);
                gw_test_rel(r.f_max, fmax, 1e-4, what);
                snprintf(what, sizeof what, "%s/%s v=%g: tau_max = tau_1/2 (F.21)", solvers[s][0], solvers[s][1], vs[iv]);
                gw_test_rel(r.tau_max, 0.5 * tau1, 1e-4, what);
                snprintf(what, sizeof what, "%s/%s v=%g: elastic rebound v_f = -v_imp", solvers[s][0], solvers[s][1], vs[iv]);
                gw_test_rel(r.final_v[0], -vs[iv], 1e-6, what);
            } else {
                gw_test_failures++;
            }
            gw_chain_result_free(&r);
        }
    /* Sheets: K_eff reproduces each sheet's measured tau_max(N = 1) at
     * h = 2.9 mm (the fit inverts F.2 with tau_max = tau_1/2; a wrong exponent
     * or constant in either direction breaks this). */
    for (int i = 0; i < gw_sheet_count(); i++) {
        const gw_sheet *sh = gw_sheet_get(i);
        gw_chain_params q = test_params(1, sqrt(2 * 9.81 * 2.9e-3));
        q.kwall = gw_sheet_kwall(sh, q.mass);
        gw_chain_run_opts o = test_opts("cvode", "bdf");
        gw_chain_result r;
        char what[128];
        snprintf(what, sizeof what, "sheet %s: single-bead tau_max = measured %.1f us", sh->name, sh->tau_max1_us);
        if (test_collide(&q, &o, &r) == GW_OK)
            gw_test_rel(r.tau_max, sh->tau_max1_us * 1e-6, 1e-4, what);
        else
            gw_test_failures++;
        gw_chain_result_free(&r);
    }
    return gw_test_summary("test_chain_closed_forms");
}
