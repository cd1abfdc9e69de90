/*
 * test_chain_pending_text.c: the column's pending text of a cut run (which
 * contact still acts, "beads 5 and 6 closing, ...") is kept in the run's
 * final_v allocation, after its 4n values. gw_chain_result_warnings read it
 * from any result not converged: a result filled by hand, or copied with its
 * own final_v array of n values, was read past its end (a heap over-read the
 * sanitizer build reports; the release build printed whatever followed).
 * The text is now read only from an allocation a run made, for the n it was
 * made for, until gw_chain_result_free. Checks:
 *  1 a cut run on a soft sensor (n 10, 0.03 kg, 1e4 N/m, t_max 0.2 s) names
 *    its closing pair in its warning;
 *  2 the same result copied with its own final_v of n values (malloc'd to
 *    that size): the warning keeps the generic text, nothing read beyond;
 *  3 a result filled by hand (n 5, its arrays of 5 values, converged 0,
 *    wall done): the generic text;
 *  4 the run's own result with its n changed: the generic text (the text
 *    would sit elsewhere), n restored: the pair named again;
 *  5 after gw_chain_result_free of the run's result, a result pointing at a
 *    new allocation of the same size is not taken for it.
 * On the code before, 3 fails (its warning printed the bytes after the array
 * as the column's text) and valgrind reports reads past the arrays in 2 and 5.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"
#include "gw_test.h"

static char *warn(const gw_chain_result *r)
{
    char *list = NULL;
    if (gw_chain_result_warnings(r, &list) != GW_OK)
        return NULL;
    return list;
}

int main(void)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 10;
    p.sensor.mass = 0.03;
    p.sensor.stiffness = 1e4;
    gw_chain *c = NULL;
    gw_err err = {0};
    GW_TEST_OK(gw_chain_create(&p, &c, &err) == GW_OK, "gw_chain_create: %s", err.msg);
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.t_max = 0.2;
    gw_chain_result r = {0};
    int rc = gw_chain_collide(c, &o, &r, &err);
    GW_TEST_OK(rc == GW_OK && !r.converged && r.n == 10, "cut run: rc %d converged %d (%s)", rc, r.converged,
               err.msg);

    /* 1 the run's own result names its pair */
    char *w = warn(&r);
    GW_TEST_OK(w && strstr(w, "beads ") && strstr(w, "closing"), "1 the cut run names its closing pair: %s",
               w ? w : "(none)");
    free(w);

    /* 2 a copy with its own arrays of n values */
    gw_chain_result cp = r;
    cp.final_v = malloc(10 * sizeof(double));
    memcpy(cp.final_v, r.final_v, 10 * sizeof(double));
    cp.detach_t = cp.v_tau_n = cp.front_t = NULL;
    w = warn(&cp);
    GW_TEST_OK(w && !strstr(w, "beads ") && strstr(w, "had not ended"), "2 a copy with its own final_v: %s",
               w ? w : "(none)");
    free(w);
    free(cp.final_v);

    /* 3 a result filled by hand */
    double v5[5] = {0.1, 0.2, 0.3, 0.4, 0.5};
    gw_chain_result h = {0};
    h.n = 5;
    h.final_v = h.detach_t = h.v_tau_n = v5;
    h.converged = 0;
    h.wall_done = 1;
    h.t_end = 1e-3;
    w = warn(&h);
    GW_TEST_OK(w && strstr(w, "the column's own contacts still closed or closing"), "3 a result by hand: %s",
               w ? w : "(none)");
    free(w);

    /* 4 the run's result with its n changed, then restored */
    r.n = 3;
    w = warn(&r);
    GW_TEST_OK(w && !strstr(w, "beads 5"), "4 n changed to 3: the generic text: %s", w ? w : "(none)");
    free(w);
    r.n = 10;
    w = warn(&r);
    GW_TEST_OK(w && strstr(w, "closing"), "4 n restored: the pair named again: %s", w ? w : "(none)");
    free(w);

    /* 5 after the free, a new allocation is not the run's */
    gw_chain_result_free(&r);
    GW_TEST_OK(r.final_v == NULL, "5 gw_chain_result_free clears final_v");
    gw_chain_result nw = {0};
    nw.n = 10;
    nw.final_v = malloc(10 * sizeof(double));
    for (int i = 0; i < 10; i++)
        nw.final_v[i] = 0;
    nw.converged = 0;
    nw.wall_done = 1;
    nw.t_end = 0.2;
    w = warn(&nw);
    GW_TEST_OK(w && strstr(w, "the column's own contacts still closed or closing"),
               "5 a new array after the free: the generic text: %s", w ? w : "(none)");
    free(w);
    free(nw.final_v);
    gw_chain_free(c);
    return gw_test_summary("test_chain_pending_text");
}
