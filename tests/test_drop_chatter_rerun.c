/*
 * test_drop_chatter_rerun.c: the drop's chatter on a sensor body through the
 * library (left after the forty-fourth session).
 *   - gw_chain_drop_result_warnings named the rerun in one text for both
 *     solvers, "10 times tighter tolerances (under rk4: half the step)": it
 *     now says what was done for the method used, from the result's
 *     chatter_rerun (rk4: "--dt X (half the step)"; cvode: the tolerances,
 *     no rk4), as the studies' line does. Under cvode it said "10 times
 *     tighter tolerances (rtol and atol)" without their values, the drop
 *     result holding no rtol (left in session 45): it names them now, "a
 *     rerun at rtol 1e-13, atol 1e-13", as the program's line does (the
 *     first collision keeps the run's tolerances after its texts); a copy
 *     whose first collision is the caller's own keeps the rule's words.
 *   - rk4's rerun at half the step costs twice the drop's steps, known before
 *     it is made: a drop of 3 beads on 1e-4 kg and 1e3 N/m (9.8e5 steps, 44
 *     episodes) was left unmeasured ("chatter" -1, above the 1e6 steps times
 *     bodies of chain's bound); it is run again up to 1e7 (5e7 from session 46; 0.13 s of CPU,
 *     the rerun 0.25 s), every impact's chatter measured (within 6.4e-8: no
 *     warning). Above it (1e-6 kg on 1e5 N/m with 10 beads: 6e6 steps times
 *     10) it is not, and the warning says why (twice the drop's steps) and
 *     names --dt; the bound is 5e7 from session 46 (3 beads there, 1.8e7,
 *     are run again: the rerun 1.25 s of CPU).
 * Each case runs in its own child process (test_child.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"
#include "test_child.h"

/* the drop of 3 beads on a sensor body of mass m (kg) and stiffness k (N/m),
 * under cvode at the program's tolerances or rk4; 0 or says why */
static int drop_of(int n, double m, double k, int rk4, gw_chain_drop_result *r, char **w)
{
    gw_chain_drop_params p = gw_chain_drop_params_default();
    p.chain.n = n;
    p.chain.sensor.mass = m;
    p.chain.sensor.stiffness = k;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.sp.rtol = o.sp.atol = 1e-12;
    if (rk4)
        o.solver = gw_solver_rk4;
    gw_err e = {0};
    *w = NULL;
    if (gw_chain_drop_run(&p, &o, r, &e) != GW_OK) {
        printf("drop on %g kg, %g N/m: %s\n", m, k, e.msg);
        return 1;
    }
    if (gw_chain_drop_result_warnings(r, w) != GW_OK) {
        printf("warnings failed\n");
        return 1;
    }
    return 0;
}

static int drop_on(double m, double k, int rk4, gw_chain_drop_result *r, char **w)
{
    return drop_of(3, m, k, rk4, r, w);
}

static int c_cvode_named(void)
{
    gw_chain_drop_result r;
    char *w = NULL;
    EXPECT(drop_on(1e-4, 1e3, 0, &r, &w) == 0);
    const char *s = w ? w : "";
    /* the rerun's values, as the program's line names them (session 45: the
     * library said "10 times tighter tolerances (rtol and atol)", the drop
     * result holding no rtol) */
    if (!(r.chatter_kind == GW_CHAIN_CHATTER_MOVED && strstr(s, "a rerun at rtol 1e-13, atol 1e-13 changed") &&
          !strstr(s, "rk4")))
        printf("kind %d, warnings '%s'\n", r.chatter_kind, s);
    EXPECT(r.chatter_kind == GW_CHAIN_CHATTER_MOVED && strstr(s, "a rerun at rtol 1e-13, atol 1e-13 changed"));
    EXPECT(!strstr(s, "rk4"));
    EXPECT(r.chatter_rerun == GW_CHAIN_RERUN_TOL);
    /* a copy whose first collision is the caller's own (final_v not the
     * library's) reads nothing past its array; the tolerances are members
     * since session 46 (run_rtol, run_atol: kept by a copy), and a result
     * holding none (0, filled by hand) keeps the rule's words */
    gw_chain_drop_result c = r;
    double v[3] = {0, 0, 0};
    c.first.final_v = v;
    EXPECT(c.first.run_rtol == 1e-12 && c.first.run_atol == 1e-12);
    c.first.run_rtol = c.first.run_atol = 0;
    char *w2 = NULL;
    EXPECT(gw_chain_drop_result_warnings(&c, &w2) == GW_OK);
    if (!w2 || !strstr(w2, "a rerun at 10 times tighter tolerances (rtol and atol) changed"))
        printf("copy: '%s'\n", w2 ? w2 : "");
    EXPECT(w2 && strstr(w2, "a rerun at 10 times tighter tolerances (rtol and atol) changed"));
    free(w2);
    free(w);
    gw_chain_drop_result_free(&r);
    return 0;
}

static int c_rk4_run_again(void)
{
    gw_chain_drop_result r;
    char *w = NULL;
    EXPECT(drop_on(1e-4, 1e3, 1, &r, &w) == 0);
    double most = 0;
    int measured = 0;
    for (int j = 0; j < r.n_impacts; j++) {
        measured += isfinite(r.impacts[j].chatter);
        most = fmax(most, r.impacts[j].chatter);
    }
    if (!(r.chatter_kind == GW_CHAIN_CHATTER_NONE && measured == r.n_impacts))
        printf("rk4: kind %d, %d of %d impacts measured, up to %.3g, steps %ld, warnings '%.120s'\n",
               r.chatter_kind, measured, r.n_impacts, most, r.stats.steps, w ? w : "");
    EXPECT(r.n_episodes >= GW_CHAIN_CHATTER_CONTACTS && r.n_impacts > 10);
    EXPECT(r.chatter_kind != GW_CHAIN_CHATTER_COSTLY && measured == r.n_impacts);
    EXPECT(r.chatter_kind == GW_CHAIN_CHATTER_NONE && most <= GW_CHAIN_CHATTER_SPREAD);
    EXPECT(!w || !strstr(w, "chattered"));
    EXPECT(r.chatter_rerun == GW_CHAIN_RERUN_STEP);
    free(w);
    gw_chain_drop_result_free(&r);
    return 0;
}

static int c_rk4_costly_named(void)
{
    gw_chain_drop_result r;
    char *w = NULL;
    EXPECT(drop_of(10, 1e-6, 1e5, 1, &r, &w) == 0);
    const char *s = w ? w : "";
    if (!strstr(s, "twice the drop's steps"))
        printf("rk4 costly: kind %d, steps %ld, '%.400s'\n", r.chatter_kind, r.stats.steps, s);
    EXPECT(r.chatter_kind == GW_CHAIN_CHATTER_COSTLY);
    EXPECT(strstr(s, "compare a run at --dt ") && strstr(s, "(half the step)"));
    EXPECT(strstr(s, "twice the drop's steps") && !strstr(s, "rtol"));
    /* the step named is half the run's */
    const char *d = strstr(s, "--dt ");
    EXPECT(d && fabs(strtod(d + 5, NULL) / (0.5 * r.run_dt) - 1) < 1e-5);
    free(w);
    gw_chain_drop_result_free(&r);
    return 0;
}

static const child_row rows[] = {
    {"drop cvode on 1e-4 kg: the library's warning names the rerun's rtol and atol (was the rule's words), no rk4; "
     "a copy keeps the rule's words",
     c_cvode_named},
    {"drop rk4 on 1e-4 kg: run again at half the step (was -1), every impact measured, no warning", c_rk4_run_again},
    {"drop rk4 of 10 beads on 1e-6 kg, 1e5 N/m (costly): the library's warning names --dt, half the step, and why",
     c_rk4_costly_named},
};

int main(void)
{
    return child_cases_run(rows, sizeof rows / sizeof rows[0]);
}
