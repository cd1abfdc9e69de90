/*
 * chain_sweep_model.c: the chain as a sweep model. A case's keys are the options
 * of `granwave chain` (n, vimp, kwall, damping, solver, ...), parsed and
 * validated by the same code as the command; the row holds the collision's
 * observables (SI units).
 */
#include <stdlib.h>
#include <string.h>

#include "gw_cli.h"
#include "chain_options.h"
#include "gw_sweep.h"

static const char *const columns[] = {"f_max", "tau_max", "tau_n", "period", "eps_eff", "eps_col",
                                      "e_rel_over_e_k", "n_s", "energy_error", "steps", "converged"};

typedef struct case_opts {
    chain_cli c;
    gw_opt opts[CHAIN_CLI_NOPTS + 3];
    long n;
    double vimp;
} case_opts;

static void case_init(case_opts *co)
{
    chain_cli_options(&co->c, co->opts);
    co->n = 1;
    co->vimp = 0.3;
    co->opts[CHAIN_CLI_NOPTS] = (gw_opt){.name = "n", .kind = GW_OPT_LONG, .dest = &co->n, .lo = 1, .hi = 50000000};
    co->opts[CHAIN_CLI_NOPTS + 1] = (gw_opt){.name = "vimp", .kind = GW_OPT_DOUBLE, .dest = &co->vimp, .lo = 0, .hi = GW_CHAIN_VIMP_MAX, .open_lo = 1};
    co->opts[CHAIN_CLI_NOPTS + 2] = (gw_opt){0};
}

static int has_key(const char *name)
{
    case_opts co;
    case_init(&co);
    if (strcmp(name, "json") == 0 || strcmp(name, "out") == 0)
        return 0;
    return gw_cli_find(co.opts, name) != NULL;
}

/* Parse and resolve the case into co (argv built from the pairs). */
static int prepare(case_opts *co, int nk, const char *const *names, const char *const *values, gw_err *err)
{
    case_init(co);
    char **argv = malloc(2 * (size_t)nk * sizeof *argv);
    char *buf = malloc(2 * (size_t)nk * 72);
    int rc = argv && buf ? GW_OK : gw_err_set(err, GW_ENOMEM, "out of memory");
    for (int i = 0; rc == GW_OK && i < nk; i++) {
        snprintf(buf + 72 * (2 * i), 72, "--%s", names[i]);
        argv[2 * i] = buf + 72 * (2 * i);
        argv[2 * i + 1] = (char *)values[i];
    }
    int help = 0, npos = 0;
    const char *pos[1];
    if (rc == GW_OK)
        rc = gw_cli_parse("chain", co->opts, 2 * nk, argv, &help, pos, 0, &npos, err);
    free(argv);
    free(buf);
    if (rc == GW_OK) {
        co->c.params.n = (int)co->n;
        co->c.params.v_imp = co->vimp;
        rc = chain_cli_resolve(&co->c, co->opts, "chain", err);
    }
    return rc == GW_OK ? GW_OK : GW_EINVAL;
}

static int check(int nk, const char *const *names, const char *const *values, gw_err *err)
{
    case_opts co;
    int rc = prepare(&co, nk, names, values, err);
    chain_cli_free(&co.c);
    return rc;
}

static int run(int nk, const char *const *names, const char *const *values, double *out, gw_err *err)
{
    case_opts co;
    int rc = prepare(&co, nk, names, values, err);
    gw_chain *c = NULL;
    gw_chain_result r;
    memset(&r, 0, sizeof r);
    if (rc == GW_OK)
        rc = gw_chain_create(&co.c.params, &c, err);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, &co.c.run, &r, err);
    if (rc == GW_OK) {
        double v[] = {r.f_max, r.tau_max, r.tau_n, r.period, r.eps_eff, r.eps_col, r.e_rel_over_e_k,
                      r.n_s, r.energy_error, (double)r.stats.steps, r.converged};
        memcpy(out, v, sizeof v);
    }
    gw_chain_result_free(&r);
    gw_chain_free(c);
    chain_cli_free(&co.c);
    return rc;
}

const gw_sweep_model gw_chain_sweep_model = {"chain", (int)(sizeof columns / sizeof columns[0]), columns,
                                             has_key, run, check};
