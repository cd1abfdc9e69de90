/*
 * gw_grid_probe.c: a C caller of the library's N x v grid and of its older
 * sweep table call, for the tests that compare them with what the program and
 * the Python module give (tests/python/test_sweep_n.py,
 * tests/test_sweep_warnings_table.sh).
 *
 *   gw_grid_probe grid N_LO N_HI V1[,V2...] [NAME=VALUE ...]
 *     the chain study's setup (its table; NAME a row, the flag without "--")
 *     with n = N_LO and vimp = V1, resolved (gw_chain_setup_resolve), run
 *     over the grid by gw_chain_sweep_n_warned on one thread. Prints one line
 *     per case "case IV N f_max tau_n eps_eff steps converged" (%.17g), then
 *     "warning: TEXT" for each line of the grid's warnings and of
 *     gw_chain_unfinished_warnings over the cases that did not end.
 *   gw_grid_probe table CONFIG DIR
 *     DIR/results.csv written again by gw_sweep_write_table from CONFIG (read
 *     by gw_sweep_config_read) and DIR's journal.
 *
 * Exit 0; a refusal or a failed run: its message on stderr, exit 1; bad
 * usage: exit 2.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"
#include "gw_chain_study.h"
#include "gw_study.h"
#include "gw_sweep.h"

static void say(const char *prefix, const char *list)
{
    for (const char *p = list; p && *p;) {
        const size_t len = strcspn(p, "\n");
        printf("%s%.*s\n", prefix, (int)len, p);
        p += len + (p[len] == '\n');
    }
}

static int grid(int argc, char **argv)
{
    const gw_study *st = gw_study_find("chain");
    const gw_param *tab = st ? st->params() : NULL;
    gw_chain_setup s;
    gw_err err = {{0}};
    if (!tab || st->params_size != sizeof s)
        return fprintf(stderr, "gw_grid_probe: the chain study is not gw_chain_setup\n"), 1;
    const int lo = atoi(argv[2]), hi = atoi(argv[3]);
    double v[64];
    int nv = 0;
    char *list = strdup(argv[4]);
    for (char *t = strtok(list, ","); t && nv < 64; t = strtok(NULL, ","))
        v[nv++] = strtod(t, NULL);
    st->init(&s);
    int rc = gw_param_set(tab, &s, "n", argv[2], &err);
    if (rc == GW_OK)
        rc = gw_param_set(tab, &s, "vimp", strtok(list, ","), &err); /* the first speed (the list cut there) */
    free(list);
    for (int i = 5; rc == GW_OK && i < argc; i++) {
        char *eq = strchr(argv[i], '=');
        if (!eq)
            return fprintf(stderr, "gw_grid_probe: '%s' is not NAME=VALUE\n", argv[i]), st->clear(&s), 2;
        *eq = '\0';
        rc = gw_param_set(tab, &s, argv[i], eq + 1, &err);
    }
    gw_chain_resolved r;
    memset(&r, 0, sizeof r);
    if (rc == GW_OK)
        rc = gw_chain_setup_resolve(&s, &r, &err);
    const int nn = hi - lo + 1;
    gw_chain_result *res = rc == GW_OK && nn > 0 && nv > 0 ? calloc((size_t)(nv * nn), sizeof *res) : NULL;
    char *w = NULL;
    if (rc == GW_OK)
        rc = res ? gw_chain_sweep_n_warned(&r.params, &r.run, v, nv, lo, hi, 1, NULL, NULL, res, &w, &err)
                 : gw_err_set(&err, GW_EINVAL, "no grid");
    int unfinished = 0;
    for (int k = 0; rc == GW_OK && k < nv * nn; k++) {
        printf("case %d %d %.17g %.17g %.17g %ld %d\n", k / nn, lo + k % nn, res[k].f_max, res[k].tau_n,
               res[k].eps_eff, res[k].stats.steps, res[k].converged);
        unfinished += !res[k].converged;
    }
    if (rc == GW_OK && unfinished)
        rc = gw_chain_unfinished_warnings(unfinished, nv * nn, &w);
    if (rc == GW_OK)
        say("warning: ", w);
    else
        fprintf(stderr, "gw_grid_probe: %s\n", err.msg);
    free(w);
    for (int k = 0; res && k < nv * nn; k++)
        gw_chain_result_free(&res[k]);
    free(res);
    gw_chain_resolved_free(&r);
    st->clear(&s);
    return rc == GW_OK ? 0 : 1;
}

static int table(char **argv)
{
    int nm = 0;
    const gw_sweep_model *const *models = gw_sweep_models(&nm);
    gw_sweep_config cfg;
    const gw_sweep_model *m = NULL;
    gw_err err = {{0}};
    int rc = gw_sweep_config_read(argv[2], models, nm, &cfg, &m, &err);
    if (rc != GW_OK)
        return fprintf(stderr, "gw_grid_probe: %s\n", err.msg), 1;
    rc = gw_sweep_write_table(argv[3], &cfg, m, &err);
    if (rc != GW_OK)
        fprintf(stderr, "gw_grid_probe: %s\n", err.msg);
    gw_sweep_config_free(&cfg);
    return rc == GW_OK ? 0 : 1;
}

int main(int argc, char **argv)
{
    if (argc >= 5 && strcmp(argv[1], "grid") == 0)
        return grid(argc, argv);
    if (argc == 4 && strcmp(argv[1], "table") == 0)
        return table(argv);
    fprintf(stderr, "usage: gw_grid_probe grid N_LO N_HI V1[,V2...] [NAME=VALUE ...] | table CONFIG DIR\n");
    return 2;
}
