/*
 * chain_sweep_model.c: the chain as a sweep model. A case's keys are the rows
 * of the column's parameter table (gw_chain_setup_params: the options of
 * `granwave chain`, n, vimp, kwall, damping, solver, ...), set and checked by
 * gw_param_set and resolved by gw_chain_setup_resolve as the command's are; no
 * command line is built. The row holds the collision's observables (SI units).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_model.h"
#include "chain_wall.h"
#include "chain_watch.h"
#include "gw_chain_study.h"
#include "gw_locale.h"
#include "gw_sweep.h"
#include "gw_sweep_impl.h"

static const char *const columns[] = {"f_max", "tau_max", "tau_n", "period", "eps_eff", "eps_col",
                                      "e_rel_over_e_k", "n_s", "energy_error", "steps", "converged",
                                      "overlap_max_rel", "chatter"};
enum { COL_ENERGY = 8, COL_OVERLAP = 11, COL_CHATTER = 12 }; /* their places in columns */

static int has_key(const char *name)
{
    const gw_param *p = gw_param_find(gw_chain_setup_params(), name);
    /* trace keeps series in memory: a library option, not a sweep key */
    return p && gw_param_is_input(p) && strcmp(p->name, "trace") != 0;
}

/* One value of a key as a case takes it (gw_sweep_value_rule): a number
 * row's checks (range, integer, no subnormal), which a sweep config's
 * [params] value is read by ('n = 3:5' was refused only at the first case's
 * check); any other row is its reader's. */
static int value_rule(const char *name, const char *value, gw_err *err)
{
    if (!name || !value || !has_key(name))
        return GW_OK;
    return gw_sweep_number_check(gw_param_find(gw_chain_setup_params(), name), value, err);
}

__attribute__((constructor)) static void chain_value_rule(void)
{
    gw_sweep_value_rule_set("chain", value_rule);
}

/* The case's setup from its pairs; GW_EINVAL "NAME: reason" for a bad value. */
static int prepare(gw_chain_setup *s, int nk, const char *const *names, const char *const *values, gw_err *err)
{
    int rc = gw_chain_setup_init(s);
    if (rc == GW_OK)
        rc = gw_sweep_pairs_check("gw_chain_sweep_model", nk, names, values, err);
    for (int i = 0; rc == GW_OK && i < nk; i++)
        rc = has_key(names[i]) ? gw_param_set(gw_chain_setup_params(), s, names[i], values[i], err)
                               : gw_err_set(err, GW_EINVAL, "unknown parameter '%s'", names[i]);
    return rc == GW_OK ? GW_OK : GW_EINVAL;
}

/* What a pass of checks tallies over the cases (the memo), each said in one
 * warning line over the sweep: the dt given above the step the case takes,
 * a damping model with a constant of 0 (chain_damping_zero), and a contact
 * damping, sensor dashpot or guide friction too small to act (the single
 * run's no-effect rules against the case's rtol). */
typedef struct sweep_memo {
    chain_dt_tally dt;
    int zero, total;
    int small;      /* cases whose damping's predicted effect is below their rtol */
    double small_hi; /* the largest such effect */
    long cases;      /* the cases checked so far (the next one's index) */
    long k_one, k_first; /* cases of one body (n = 1) given the key k, the first of them */
    int k_acts;      /* a case of two beads or more given k */
    chain_drag_cases drag; /* the sensor's dashpot and the guide's friction of no effect */
} sweep_memo;

/* tally (may be NULL): the case's dt given against the step it will take, and its damping */
static int check_tally(sweep_memo *tally, int nk, const char *const *names, const char *const *values,
                       gw_err *err)
{
    gw_chain_setup s;
    int rc = prepare(&s, nk, names, values, err);
    if (rc == GW_OK) { /* the resolution's checks too (names, no-effect options), and the run's
                          bounds on steps, memory and samples: a case the run would refuse is
                          refused with the config, before OUT and its journal are made; the
                          plan of these checks gives the step the case will take */
        gw_chain_resolved r;
        double dt, dt_max;
        rc = gw_chain_setup_resolve(&s, &r, err) == GW_OK && chain_damping_check(&r.params, err) == GW_OK &&
                     chain_run_step(&r.params, &r.run, &dt, &dt_max, err) == GW_OK
                 ? GW_OK
                 : GW_EINVAL;
        if (rc == GW_OK && tally) {
            /* k on one body (chain --n 1 --k 1e3 is refused, chain_one_body_check): a
               case of n = 1 keeps it, refused by memo_warnings when no case acts on it */
            int k_given = 0;
            for (int i = 0; i < nk && !k_given; i++)
                k_given = strcmp(names[i], "k") == 0;
            if (k_given && r.params.n == 1 && tally->k_one++ == 0)
                tally->k_first = tally->cases;
            tally->k_acts |= k_given && r.params.n > 1;
            chain_dt_tally_add(&tally->dt, r.run.sp.dt > 0 ? r.run.sp.dt : 0.0, dt, dt_max);
            tally->zero += chain_damping_zero(&r.params);
            tally->total++;
            if (chain_damping_small(&r.params, r.run.sp.rtol)) { /* the single run's test */
                const double e = chain_damping_effect(&r.params);
                tally->small_hi = tally->small++ ? fmax(tally->small_hi, e) : e;
            }
            chain_drag_cases_add(&tally->drag, &r.params, r.run.sp.rtol, tally->cases);
        }
        gw_chain_resolved_free(&r);
    }
    gw_chain_setup_clear(&s);
    if (tally)
        tally->cases++;
    return rc;
}

static int check(int nk, const char *const *names, const char *const *values, gw_err *err)
{
    return check_tally(NULL, nk, names, values, err);
}

/* A pass of checks tallies the cases whose dt is above the step they will
 * take (the memo), for one warning line over the sweep: such a case runs at
 * that step, and its row says nothing of it (granwave sweep warned of none). */
static int check_memo(void **memo, int nk, const char *const *names, const char *const *values, gw_err *err)
{
    if (!*memo && !(*memo = calloc(1, sizeof(sweep_memo))))
        return gw_err_set(err, GW_ENOMEM, "out of memory");
    return check_tally(*memo, nk, names, values, err);
}

static int memo_warnings(const void *memo, char **list)
{
    const sweep_memo *m = memo;
    if (m && m->k_one > 0 && !m->k_acts) /* the single run's refusal (chain_one_body_check) */
        return gw_warnings_add(list, "k: has no effect on one body (n = 1) in any case (%ld of %ld cases; the first, "
                               "case %ld): k is the bead-bead contact's coefficient and one body has no bead "
                               "contact (the wall's is kwall)", m->k_one, m->cases, m->k_first) == GW_OK
                   ? GW_EINVAL
                   : GW_ENOMEM;
    int rc = m ? chain_dt_tally_warnings(&m->dt, "dt", "cases", list) : GW_OK;
    rc = rc == GW_OK && m ? chain_damping_zero_warnings(NULL, m->zero, m->total, list) : rc;
    rc = rc == GW_OK && m ? chain_damping_small_cases_warning(m->small, m->total, m->small_hi, list) : rc;
    return rc == GW_OK && m ? chain_drag_cases_warnings(&m->drag, m->total, list) : rc;
}

/* A case's part: the share of its collision's work done (chain_watch_share,
 * its end expected at rho(N) t_expect). */
typedef struct case_part {
    void (*fn)(void *pctx, double x);
    void *pctx;
    double rho;
} case_part;

static void at_sample(void *ctx, double t, double t_expect, double t_max)
{
    (void)t_max;
    const case_part *cp = ctx;
    if (t_expect > 0)
        cp->fn(cp->pctx, chain_watch_share(t / t_expect, cp->rho));
}

int gw_chain_sweep_run_part(int nk, const char *const *names, const char *const *values, double *out,
                            unsigned long long *read_hash, void (*part)(void *pctx, double x), void *pctx,
                            gw_err *err)
{
    (void)read_hash; /* a chain case reads no file */
    if (!out || (nk > 0 && (!names || !values)))
        return gw_err_set(err, GW_EINVAL, "gw_chain_sweep_run_part: %s is NULL",
                          !out ? "out" : !names ? "names" : "values");
    gw_chain_setup s;
    gw_chain_collision c;
    memset(&c, 0, sizeof c);
    int rc = prepare(&s, nk, names, values, err);
    case_part cp = {.fn = part, .pctx = pctx, .rho = chain_watch_tail(s.n > 1 << 30 ? 1 << 30 : (int)s.n)};
    if (rc == GW_OK)
        rc = chain_collision_run_progress(&s, &c, part ? at_sample : NULL, &cp, err);
    if (rc == GW_OK) {
        const gw_chain_result *r = &c.r;
        double v[] = {r->f_max, r->tau_max, r->tau_n, r->period, r->eps_eff, r->eps_col, r->e_rel_over_e_k,
                      r->n_s, r->energy_error, (double)r->stats.steps, r->converged, r->overlap_max_rel,
                      chain_result_chatter_value(r)};
        memcpy(out, v, sizeof v);
    }
    gw_chain_collision_free(&c);
    gw_chain_setup_clear(&s);
    return rc;
}

static int run(int nk, const char *const *names, const char *const *values, double *out,
               unsigned long long *read_hash, gw_err *err)
{
    return gw_chain_sweep_run_part(nk, names, values, out, read_hash, NULL, NULL, err);
}

/* The single run's warnings that a case's row holds the numbers of, said
 * over the sweep's rows (gw_sweep_rows_rule): the overlap beyond one radius
 * (overlap_max_rel) and the energy error above GW_CHAIN_ENERGY_WARN with
 * energy-tol off (energy_error). A sweep of such cases said neither. */
typedef struct rows_acc {
    long total, over, over_first, energy, energy_first;
    double over_hi, energy_hi;
    long moved, costly, failed, chatter_first; /* bead 1 chattered on the sensor body (chatter column) */
    int rerun;                                  /* the moved ones' reruns (CHAIN_RERUN_* bits: rk4's or the tolerances,
                                                   tighter or looser) */
    double spread_hi;
    double rtol, atol; /* the moved ones' tolerances (under cvode, arkode) while one setting, else -1 */
} rows_acc;

/* Case k's solver, energy-tol and tolerances as its run took them: *rk4 1
 * when it runs rk4 (its chatter's rerun halves the step; the others change
 * the tolerances: 10 times tighter, looser at the 1e-15 floor), *energy_tol
 * 0 when off (the default), *rtol and *atol (0 when the case is not read).
 * Read when a row needs them (a chatter moved, an energy error above the
 * bound). */
static void case_settings(const gw_sweep_config *cfg, long k, int *rk4, double *energy_tol, double *rtol,
                          double *atol)
{
    const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
    *rk4 = 0;
    *energy_tol = 0;
    *rtol = *atol = 0;
    if (!cfg || gw_sweep_case(cfg, k, names, values) != GW_OK)
        return;
    gw_chain_setup s;
    gw_err e = {{0}};
    char name[16] = "";
    if (prepare(&s, cfg->ngrid + cfg->nparams, names, values, &e) == GW_OK) {
        *energy_tol = s.energy_tol;
        *rtol = isnan(s.rtol) ? GW_CHAIN_TOL_DEFAULT : s.rtol; /* as chain_setup.c resolves them */
        *atol = isnan(s.atol) ? GW_CHAIN_TOL_DEFAULT : s.atol;
        if (s.solver >= 0 &&
            gw_param_format(gw_param_find(gw_chain_setup_params(), "solver"), &s, name, sizeof name) > 0)
            *rk4 = strcmp(name, "rk4") == 0;
    }
    gw_chain_setup_clear(&s);
}

static void rows_row(void *acc, const gw_sweep_config *cfg, long k, const double *row)
{
    rows_acc *a = acc;
    a->total++;
    const double ov = row[COL_OVERLAP], ee = row[COL_ENERGY];
    int rk4 = -1; /* (case_settings not read yet) */
    double energy_tol = 0, rtol = 0, atol = 0;
    if (ov > 1) {
        if (a->over++ == 0)
            a->over_first = k, a->over_hi = ov;
        a->over_hi = fmax(a->over_hi, ov);
    }
    /* the chatter column: the spread a rerun measured, -1 not run again, -2 its rerun failed */
    const double ch = row[COL_CHATTER];
    if (ch > 0 || ch == -1 || ch == -2) {
        if (a->moved + a->costly + a->failed == 0)
            a->chatter_first = k;
        a->moved += ch > 0;
        a->costly += ch == -1;
        a->failed += ch == -2;
        if (ch > 0) {
            a->spread_hi = fmax(a->spread_hi, ch);
            case_settings(cfg, k, &rk4, &energy_tol, &rtol, &atol);
            const int looser = rtol > 0 && atol > 0 && chain_chatter_looser(rtol, atol);
            a->rerun |= rk4 ? CHAIN_RERUN_STEP : looser ? CHAIN_RERUN_LOOSE : CHAIN_RERUN_TOL;
            /* the tolerances' values named while the moved cases share them */
            if (!rk4 && (a->rtol == 0 || (a->rtol == rtol && a->atol == atol)))
                a->rtol = rtol, a->atol = atol;
            else if (!rk4)
                a->rtol = a->atol = -1;
        }
    }
    /* a case with energy-tol on stopped at its bound; one below it ran on */
    if (ee > GW_CHAIN_ENERGY_WARN && rk4 < 0)
        case_settings(cfg, k, &rk4, &energy_tol, &rtol, &atol);
    if (ee > GW_CHAIN_ENERGY_WARN && !(energy_tol > 0)) {
        if (a->energy++ == 0)
            a->energy_first = k, a->energy_hi = ee;
        a->energy_hi = fmax(a->energy_hi, ee);
    }
}

static int rows_warnings(const void *acc, const gw_sweep_config *cfg, char **list)
{
    (void)cfg;
    const rows_acc *a = acc;
    int rc = chain_overlap_cases_warning(a->over, a->total, a->over_hi, a->over_first, list);
    rc = rc == GW_OK ? chain_energy_cases_warning(a->energy, a->total, a->energy_hi, a->energy_first, list) : rc;
    char first[80];
    gw_snprintf(first, sizeof first, "; the first, case %ld; their chatter column", a->chatter_first);
    return rc == GW_OK ? chain_chatter_cases_warning(a->moved, a->costly, a->failed, a->total, 0, a->spread_hi, 0,
                                                     a->rerun, fmax(a->rtol, 0), fmax(a->atol, 0), "cases", first,
                                                     list)
                       : rc;
}

static const gw_sweep_rows_rule rows_rule = {sizeof(rows_acc), rows_row, rows_warnings};

__attribute__((constructor)) static void chain_rows_rule(void)
{
    gw_sweep_rows_rule_set("chain", &rows_rule);
}

/* A case's weight before it runs: its column's as a study plans it
 * (chain_watch_weight: its beads times its steps and samples), times the
 * cost of a step of its backend over rk4's, which a study needs not (its
 * collisions all run one backend) but a sweep over `solver` does. Measured
 * (the default methods, v_imp 0.3, one thread, CPU time over the weight):
 * single runs of n = 150 and 250, rk4 1.0 to 1.2e-8 s, cvode 1.5 to 1.6e-7
 * s (12.5 to 15 times), arkode 1.8e-8 to 2.7e-8 s (about 2.5 times); a
 * sweep of n = 40, 80, 120, 160 on each, cvode 10.6 times rk4 (rk4's n = 80
 * runs 4.8 times its expected length). Another backend counts as rk4. NaN
 * for a case its checks refuse. These factors are a prior only: the case's
 * kind (its backend and method) lets the time left take each kind's cost
 * per weight from its cases ended (gw_pool_eta_kinds). */
static double step_cost(const gw_solver_type *t)
{
    return t == gw_solver_cvode ? 10.0 : t == gw_solver_arkode ? 2.5 : 1.0;
}

static double weigh(void **memo, int nk, const char *const *names, const char *const *values, int *kind)
{
    (void)memo;
    gw_chain_setup s;
    gw_err e = {{0}};
    double w = NAN;
    if (kind)
        *kind = -1;
    if (prepare(&s, nk, names, values, &e) == GW_OK) {
        gw_chain_resolved r;
        if (gw_chain_setup_resolve(&s, &r, &e) == GW_OK) {
            const gw_solver_type *t = r.run.solver ? r.run.solver : gw_solver_cvode;
            w = chain_watch_weight(&r.params, &r.run) * step_cost(t);
            if (kind) /* its backend and method: the time left learns their cost (gw_pool_eta_kinds) */
                *kind = GW_SWEEP_KIND(t, r.run.sp.method, 0);
        }
        gw_chain_resolved_free(&r);
    }
    gw_chain_setup_clear(&s);
    return w;
}

const gw_sweep_weigh gw_chain_sweep_weigh = {weigh, NULL};

const gw_sweep_model gw_chain_sweep_model = {"chain", (int)(sizeof columns / sizeof columns[0]), columns,
                                             has_key, run, check, NULL /* memory: not estimated */,
                                             NULL /* read_key: no file */, check_memo, free, memo_warnings};
