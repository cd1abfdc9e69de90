/*
 * test_chain_cap_advice.c: what a column's run that reaches the cap of 2e8
 * steps is told to change, by the solver it ran (issue 18, the thirty-second
 * pass). The one message said "use cvode" to every run, cvode's own included:
 * a Python run under cvode adams reached the cap after about 9 minutes and
 * was told to use cvode. Reaching the cap takes minutes, so the advice is
 * asserted here, for every solver and method, through chain_cap_advice,
 * which the cap's message prints:
 *   rk4 -> use cvode; cvode adams and arkode erk (explicit in the forces)
 *   -> cvode's bdf; cvode bdf (the default) and arkode dirk and imex
 *   (implicit) -> looser tolerances, never "use cvode".
 */
#include <stdio.h>
#include <string.h>

#include "chain_model.h"
#include "gw_solver.h"
#include "gw_test.h"

static int has(const char *s, const char *part) { return s && strstr(s, part) != NULL; }

int main(void)
{
    const char *a;
    a = chain_cap_advice(gw_solver_rk4, GW_METHOD_DEFAULT);
    gw_test_true(has(a, "use cvode") && !has(a, "loosen"), "rk4: use cvode");
    a = chain_cap_advice(gw_solver_cvode, GW_CVODE_ADAMS);
    gw_test_true(has(a, "bdf") && has(a, "default method") && !has(a, "loosen"), "cvode adams: its bdf");
    a = chain_cap_advice(gw_solver_arkode, GW_ARKODE_ERK);
    gw_test_true(has(a, "bdf") && !has(a, "loosen"), "arkode erk: cvode bdf");
    const struct { const gw_solver_type *const *t; int m; const char *what; } implicit[] = {
        {&gw_solver_cvode, GW_METHOD_DEFAULT, "cvode (bdf by default)"},
        {&gw_solver_cvode, GW_CVODE_BDF, "cvode bdf"},
        {&gw_solver_arkode, GW_ARKODE_DIRK, "arkode dirk"},
        {&gw_solver_arkode, GW_ARKODE_IMEX, "arkode imex"},
    };
    for (size_t i = 0; i < sizeof implicit / sizeof *implicit; i++) {
        char what[96];
        a = chain_cap_advice(*implicit[i].t, implicit[i].m);
        snprintf(what, sizeof what, "%s: looser tolerances, not 'use cvode'", implicit[i].what);
        gw_test_true(has(a, "loosen rtol and atol") && !has(a, "use cvode"), what);
    }
    /* arkode's default method is erk (explicit): told to use cvode's bdf */
    a = chain_cap_advice(gw_solver_arkode, GW_METHOD_DEFAULT);
    gw_test_true(has(a, "bdf") && !has(a, "loosen"), "arkode (erk by default): cvode bdf");
    return gw_test_summary("test_chain_cap_advice");
}
