/*
 * test_sweep_check_pass.c: the sweep's check pass is one call,
 * gw_sweep_check_pass, and one case's check is that pass over the sweep of
 * the one case (gw_sweep_case_check_pass), so their verdicts agree:
 *  - one-case chain sweeps, refused and passing: gw_sweep_case_check_pass of
 *    the case's pairs, gw_sweep_check_pass of the config read from text and
 *    gw_sweep_run_warned give the same status and message (n = 1 with k
 *    1e9 is refused by the pass as a whole, "k: has no effect on one body
 *    (n = 1) in any case"; gw_sweep_case_check alone passes it: the case's
 *    check, not the pass's, which Python's sweep_case_check ran before);
 *  - k with a grid of n = 1, 2 passes (k acts on two beads), with n = 1 in
 *    every case is refused naming 2 of 2 cases;
 *  - the pass's warnings are gw_sweep_run_warned's first lines (a dt above
 *    the step the cases take), *warnings untouched on a refusal;
 *  - progress is called before case 1000 of 1100 (done 1000, total 1100)
 *    and its stop is GW_ECANCELED naming the case;
 *  - NULL and out-of-range arguments are GW_EINVAL naming them.
 * It does not build on the code before (both calls are new). There one
 * case's check was gw_sweep_case_check's, which disagreed with the sweep's
 * run on 4 of the 7 one-case sweeps here: n = 1 with k passed (2), and the
 * case's refusals lacked "case 0: " (2). Under 1 s.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"
#include "gw_sweep.h"
#include "gw_test.h"

static const gw_sweep_model *const models[] = {&gw_chain_sweep_model};

static int read_config(const char *text, gw_sweep_config *cfg)
{
    const gw_sweep_model *m = NULL;
    gw_err e = {{0}};
    memset(cfg, 0, sizeof *cfg);
    const int rc = gw_sweep_config_read_string(text, "t", models, 1, cfg, &m, &e);
    if (rc != GW_OK)
        printf("config not read: %s\n", e.msg);
    return rc;
}

typedef struct one_case {
    const char *label;
    int nkeys;
    const char *names[4], *values[4];
    int refused;      /* 1: the pass refuses it */
    const char *said; /* the refusal's beginning */
} one_case;

static const one_case cases[] = {
    {"n 1, k 1e9 (the config as a whole)", 2, {"n", "k"}, {"1", "1e9"}, 1, "k: has no effect on one body"},
    {"n 1, vimp 0.3, k 1e9", 3, {"n", "vimp", "k"}, {"1", "0.3", "1e9"}, 1, "k: has no effect on one body"},
    {"n 3, rk4, rtol 1e-8 (the case's check)", 3, {"n", "solver", "rtol"}, {"3", "rk4", "1e-8"}, 1,
     "case 0: rtol: has no effect"},
    {"n 2, gamma 1e3 without its damping", 2, {"n", "gamma"}, {"2", "1e3"}, 1, "case 0: gamma: has no effect"},
    {"n 2, vimp 0.3 (passes)", 2, {"n", "vimp"}, {"2", "0.3"}, 0, ""},
    {"n 2, k 1e9 (passes: k acts)", 2, {"n", "k"}, {"2", "1e9"}, 0, ""},
    {"n 1, kwall 1e9 (passes)", 2, {"n", "kwall"}, {"1", "1e9"}, 0, ""},
};

static void one_case_agrees(const one_case *c)
{
    const gw_sweep_model *m = &gw_chain_sweep_model;
    char text[512];
    int len = snprintf(text, sizeof text, "[sweep]\nmodel = chain\n[grid]\n%s = %s\n[params]\n", c->names[0],
                       c->values[0]);
    for (int i = 1; i < c->nkeys; i++)
        len += snprintf(text + len, sizeof text - (size_t)len, "%s = %s\n", c->names[i], c->values[i]);
    gw_err e1 = {{0}}, e2 = {{0}}, e3 = {{0}};
    const int r1 = gw_sweep_case_check_pass(m, c->nkeys, c->names, c->values, NULL, &e1);
    gw_sweep_config cfg;
    if (read_config(text, &cfg) != GW_OK) {
        gw_test_true(0, c->label);
        return;
    }
    const int r2 = gw_sweep_check_pass(&cfg, m, NULL, NULL, NULL, &e2);
    double out[64];
    const int r3 = gw_sweep_run_warned(&cfg, m, 1, NULL, NULL, out, NULL, &e3);
    gw_sweep_config_free(&cfg);
    GW_TEST_OK(r1 == (c->refused ? GW_EINVAL : GW_OK) && strncmp(e1.msg, c->said, strlen(c->said)) == 0,
               "%s: the one case's pass: %d '%s'", c->label, r1, e1.msg);
    GW_TEST_OK(r2 == r1 && strcmp(e2.msg, e1.msg) == 0, "%s: the one-case sweep's pass: %d '%s'", c->label, r2,
               e2.msg);
    GW_TEST_OK(r3 == r1 && (!c->refused || strcmp(e3.msg, e1.msg) == 0), "%s: the sweep's run: %d '%s'", c->label,
               r3, e3.msg);
}

static int stop_at(void *ctx, long done, long total)
{
    long *seen = ctx;
    seen[0]++;
    seen[1] = done;
    seen[2] = total;
    return (int)seen[3];
}

int main(void)
{
    const gw_sweep_model *m = &gw_chain_sweep_model;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        one_case_agrees(&cases[i]);

    /* the case's check alone passes n = 1, k = 1e9: what the pass adds */
    {
        const char *names[] = {"n", "k"}, *values[] = {"1", "1e9"};
        void *memo = NULL;
        gw_err e = {{0}};
        const int rc = gw_sweep_case_check(m, &memo, 2, names, values, &e);
        gw_sweep_checks_end(m, memo);
        GW_TEST_OK(rc == GW_OK, "gw_sweep_case_check alone passes n 1, k 1e9 (a case's check): %d", rc);
    }

    /* k over a grid: refused only where no case acts on it */
    {
        gw_sweep_config cfg;
        gw_err e = {{0}};
        int rc = read_config("[sweep]\nmodel = chain\n[grid]\nn = 1, 2\n[params]\nk = 1e9\n", &cfg);
        rc = rc == GW_OK ? gw_sweep_check_pass(&cfg, m, NULL, NULL, NULL, &e) : rc;
        gw_sweep_config_free(&cfg);
        GW_TEST_OK(rc == GW_OK, "n 1, 2 with k 1e9 passes (k acts on two beads): %d '%s'", rc, e.msg);
        rc = read_config("[sweep]\nmodel = chain\n[grid]\nvimp = 0.2, 0.3\n[params]\nn = 1\nk = 1e9\n", &cfg);
        rc = rc == GW_OK ? gw_sweep_check_pass(&cfg, m, NULL, NULL, NULL, &e) : rc;
        gw_sweep_config_free(&cfg);
        GW_TEST_OK(rc == GW_EINVAL && strstr(e.msg, "in any case (2 of 2 cases; the first, case 0)"),
                   "n 1 in every case with k 1e9 refused: %d '%s'", rc, e.msg);
    }

    /* the pass's warnings are the run's first lines; untouched on a refusal */
    {
        gw_sweep_config cfg;
        gw_err e = {{0}};
        char *w = NULL, *wr = NULL;
        int rc = read_config("[sweep]\nmodel = chain\n[grid]\nn = 2, 3\n[params]\nsolver = rk4\ndt = 1e-3\n", &cfg);
        rc = rc == GW_OK ? gw_sweep_check_pass(&cfg, m, NULL, NULL, &w, &e) : rc;
        double out[2 * 64];
        const int rr = gw_sweep_run_warned(&cfg, m, 1, NULL, NULL, out, &wr, &e);
        gw_sweep_config_free(&cfg);
        GW_TEST_OK(rc == GW_OK && rr == GW_OK && w && strstr(w, "dt") && wr && strncmp(wr, w, strlen(w)) == 0,
                   "dt 1e-3 under rk4: the pass's warnings '%s' begin the run's", w ? w : "(none)");
        char *kept = w;
        rc = read_config("[sweep]\nmodel = chain\n[grid]\nn = 1\n[params]\nk = 1e9\n", &cfg);
        rc = rc == GW_OK ? gw_sweep_check_pass(&cfg, m, NULL, NULL, &w, &e) : rc;
        gw_sweep_config_free(&cfg);
        GW_TEST_OK(rc == GW_EINVAL && w == kept, "a refusal leaves *warnings as it was");
        free(w);
        free(wr);
    }

    /* progress before case 1000, and its stop */
    {
        gw_sweep_config cfg;
        gw_err e = {{0}};
        long seen[4] = {0, 0, 0, 0};
        int rc = read_config("[sweep]\nmodel = chain\n[grid]\nn = 2:1101\n[params]\nvimp = 0.3\n", &cfg);
        rc = rc == GW_OK ? gw_sweep_check_pass(&cfg, m, stop_at, seen, NULL, &e) : rc;
        GW_TEST_OK(rc == GW_OK && seen[0] == 1 && seen[1] == 1000 && seen[2] == 1100,
                   "1100 cases: progress once, 1000 of 1100 (%ld calls, %ld of %ld): %d", seen[0], seen[1], seen[2],
                   rc);
        seen[3] = 1;
        rc = gw_sweep_check_pass(&cfg, m, stop_at, seen, NULL, &e);
        gw_sweep_config_free(&cfg);
        GW_TEST_OK(rc == GW_ECANCELED && strstr(e.msg, "stopped at case 1000 of 1100"), "a stop: %d '%s'", rc,
                   e.msg);
    }

    /* NULL and bad arguments named */
    {
        const char *names[] = {"n", NULL}, *values[] = {"2", "3"}, *twice[] = {"n", "n"};
        const struct {
            const char *label, *said;
            int nkeys;
            const char *const *names, *const *values;
        } bad[] = {
            {"nkeys -1", "nkeys: -1 is outside [0, 32]", -1, names, values},
            {"nkeys 33", "nkeys: 33 is outside [0, 32]", 33, names, values},
            {"names[1] NULL", "names[1] is NULL", 2, names, values},
            {"values NULL", "values is NULL", 1, names, NULL},
            {"a key twice", "given twice", 2, twice, values},
        };
        gw_err e = {{0}};
        int rc = gw_sweep_check_pass(NULL, m, NULL, NULL, NULL, &e);
        GW_TEST_OK(rc == GW_EINVAL && strstr(e.msg, "cfg is NULL"), "cfg NULL: '%s'", e.msg);
        for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
            memset(&e, 0, sizeof e);
            rc = gw_sweep_case_check_pass(m, bad[i].nkeys, bad[i].names, bad[i].values, NULL, &e);
            GW_TEST_OK(rc == GW_EINVAL && strstr(e.msg, bad[i].said), "%s: '%s'", bad[i].label, e.msg);
        }
    }
    return gw_test_summary("test_sweep_check_pass");
}
