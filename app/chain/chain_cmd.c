/*
 * chain_cmd.c: `granwave chain`, one column collision (docs/physics.md 1.1-1.4).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_cli.h"
#include "chain_options.h"
#include "chain_model.h"
#include "chain_wall.h"

static const char *chain_summary =
    "One collision of a column of N beads with a wall (Falcon et al. 1998, eq. F.11):\n"
    "Hertz contacts, beads initially touching and moving at v_imp toward the wall.\n"
    "Reports the peak wall force, its time, the contact time tau_N, the force\n"
    "oscillation period, detachment, restitution and the energy error. SI units.";

cJSON *chain_result_json(const chain_cli *c, const gw_chain_result *r, double wall_ms)
{
    const gw_chain_params *p = &c->params;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "version", gw_version());
    cJSON_AddNumberToObject(o, "n", p->n);
    cJSON_AddNumberToObject(o, "v_imp", p->v_imp);
    cJSON_AddStringToObject(o, "solver", c->solver);
    cJSON_AddNumberToObject(o, "f_max", r->f_max);
    cJSON_AddNumberToObject(o, "tau_max", r->tau_max);
    cJSON_AddNumberToObject(o, "tau_n", r->tau_n);
    cJSON_AddNumberToObject(o, "period", r->period);
    cJSON_AddNumberToObject(o, "n_maxima", r->n_maxima);
    cJSON_AddNumberToObject(o, "energy_error", r->energy_error);
    cJSON_AddItemToObject(o, "final_velocities", gw_json_doubles(r->final_v, r->n));
    cJSON_AddItemToObject(o, "detach_times", gw_json_doubles(r->detach_t, r->n));
    cJSON_AddItemToObject(o, "velocities_at_tau_n", gw_json_doubles(r->v_tau_n, r->n));
    cJSON_AddNumberToObject(o, "n_s", r->n_s);
    cJSON_AddNumberToObject(o, "cluster", r->cluster);
    cJSON_AddNumberToObject(o, "e_rel_over_e_k", r->e_rel_over_e_k);
    cJSON_AddNumberToObject(o, "eps_eff", r->eps_eff);
    cJSON_AddNumberToObject(o, "eps_col", r->eps_col);
    cJSON_AddNumberToObject(o, "wall_contacts", r->wall_contacts);
    cJSON_AddNumberToObject(o, "overlap_max_rel", r->overlap_max_rel);
    /* bead 1's chatter on a sensor body, as a sweep's chatter column */
    cJSON_AddNumberToObject(o, "chatter", chain_result_chatter_value(r));
    cJSON_AddBoolToObject(o, "converged", r->converged);
    cJSON_AddBoolToObject(o, "wall_done", r->wall_done);
    /* why the wall's side is not done (the warning line's reason), null when done */
    if (r->wall_pending)
        cJSON_AddStringToObject(o, "wall_pending", r->wall_pending);
    else
        cJSON_AddNullToObject(o, "wall_pending");
    cJSON_AddNumberToObject(o, "t_end", r->t_end);
    cJSON_AddNumberToObject(o, "events", (double)r->n_events);
    cJSON_AddNumberToObject(o, "missed_events", (double)r->missed_events);
    cJSON_AddNumberToObject(o, "steps", (double)r->stats.steps);
    cJSON_AddNumberToObject(o, "rhs_evals", (double)r->stats.rhs_evals);
    cJSON_AddNumberToObject(o, "jac_evals", (double)r->stats.jac_evals);
    cJSON_AddNumberToObject(o, "restarts", (double)r->stats.restarts);
    cJSON_AddNumberToObject(o, "wall_time_ms", wall_ms);
    cJSON *th = cJSON_AddObjectToObject(o, "closed_forms");
    cJSON_AddNumberToObject(th, "tau_1", gw_chain_tau1(p->mass, p->kwall, p->v_imp));
    cJSON_AddNumberToObject(th, "f_max_1", gw_chain_fmax1(p->mass, p->kwall, p->v_imp));
    cJSON_AddNumberToObject(th, "t_q", gw_chain_tq_theory(p->mass, p->k, p->v_imp));
    cJSON_AddNumberToObject(th, "k_c", gw_chain_kc(p->k));
    cJSON *settings = chain_cli_settings_json(c);
    chain_cli_settings_run(settings, r);
    cJSON_AddItemToObject(o, "settings", settings);
    return o;
}

/* The provenance header of the --out files: the settings as run. */
/* every file chain --out may write: what a run does not write of these is an
 * earlier run's, removed when this run's files are placed (gw_outset) */
static const char *const chain_files[] = {"chain_wall_force.csv", "chain_beads.csv", "chain.h5", "chain.json",
                                          "chain_failure.json", NULL};

static char *run_header(const chain_cli *c, const gw_chain_result *r, int argc, char **argv)
{
    cJSON *o = chain_cli_settings_json(c);
    chain_cli_settings_run(o, r);
    char *h = gw_cli_provenance("chain", argc, argv, o);
    cJSON_Delete(o);
    /* the column and the impact velocity, defaults included: a trace whose
     * command line left them out recorded neither */
    cJSON *run = cJSON_CreateObject();
    cJSON_AddNumberToObject(run, "n", c->params.n);
    cJSON_AddNumberToObject(run, "v_imp", c->params.v_imp);
    h = gw_cli_provenance_add(h, "run", run);
    cJSON_Delete(run);
    return h;
}

static void print_text(const chain_cli *c, const gw_chain_result *r)
{
    const gw_chain_params *p = &c->params;
    printf("granwave %s chain: n = %d, v_imp = %g m/s, solver %s\n", gw_version(), p->n,
           p->v_imp, c->solver);
    printf("  m = %.6g kg, k = %.6g N/m^1.5, K = %.6g N/m^1.5\n", p->mass, p->k, p->kwall);
    char fm[32], tm[32], tn[32], per[32], ee[32], ec[32]; /* NaN (held by gravity, no period): n/a */
    printf("  F_max      %s N at tau_max = %s us\n", gw_cli_num(fm, sizeof fm, "%.6g", r->f_max),
           gw_cli_num(tm, sizeof tm, "%.6g", r->tau_max * 1e6));
    printf("  tau_N      %s us (wall contacts: %d)\n", gw_cli_num(tn, sizeof tn, "%.6g", r->tau_n * 1e6),
           r->wall_contacts);
    printf("  period P   %s us (%d maxima)\n", gw_cli_num(per, sizeof per, "%.6g", r->period * 1e6),
           r->n_maxima);
    printf("  eps_eff    %s   eps_col %s   E_rel/E_K %.6g\n", gw_cli_num(ee, sizeof ee, "%.6g", r->eps_eff),
           gw_cli_num(ec, sizeof ec, "%.6g", r->eps_col), r->e_rel_over_e_k);
    printf("  N_s        %d (cluster of %d)\n", r->n_s, r->cluster);
    printf("  energy     max relative error %.3g\n", r->energy_error);
    printf("  solver     %ld steps, %ld rhs evaluations, %ld restarts\n", r->stats.steps,
           r->stats.rhs_evals, r->stats.restarts);
}

/* Progress lines on stderr, once a run has lasted CHAIN_PROGRESS_MS (as
 * `granwave drop`): a collision takes from milliseconds to hours (--n 1000
 * under cvode bdf about 160 s) and said nothing until its end. */
#define CHAIN_PROGRESS_MS 2000.0

typedef struct chain_progress {
    gw_cli_progress p;
    char header[160];
    int n;
    double t_expect, t_max; /* the run's, from its first report */
    gw_cli_column col;      /* the phases' paces, and the column's end (end) */
    chain_column_end end;   /* kept by the run before each report (chain_collide_progress_end) */
} chain_progress;

static void chain_progress_report(void *ctx, double t, double t_expect, double t_max)
{
    chain_progress *cp = ctx;
    cp->t_expect = t_expect;
    cp->t_max = t_max;
    if (!cp->header[0]) {
        double sc;
        const char *u = gw_cli_time_unit(t_expect, &sc);
        snprintf(cp->header, sizeof cp->header, "granwave chain: %d bead%s, the collision expected to last about "
                 "%.4g %s (t-max %.4g %s)", cp->n, cp->n == 1 ? "" : "s", t_expect * sc, u, t_max * sc, u);
        cp->p.header = cp->header;
    }
    cp->col.t_end = cp->end.t_end;
    cp->col.t_meet = cp->end.t_meet;
    gw_cli_progress_time(&cp->p, &cp->col, t, t_expect, t_max, 0);
}

/* --n's range is the memory's (gw_chain_params_validate); the column's work
 * holds a whole collision to N = 1414 (chain_column_work_check: N^2 times the
 * share of the collision run at most GW_CHAIN_STUDY_WORK_MAX), which the help
 * said nowhere, printing "in [1, 50000000]" alone */
#define CHAIN_N_HELP                                                                                                  \
    "number of beads, in [1, 50000000] as parsed, and at most 1414 over a whole collision: the column's work, N^2 "   \
    "times the share of the collision the run covers, is held to 2e6 (a short t-max runs more beads) [1]"

int gw_cmd_chain(int argc, char **argv)
{
    chain_cli c;
    gw_opt opts[CHAIN_CLI_NOPTS + 4];
    chain_cli_options(&c, opts);
    c.out_names = chain_files;
    chain_cli_out_help(opts, "write chain_wall_force.csv, chain_beads.csv, chain.json (and chain.h5 with HDF5) into DIR");
    long n = 1;
    double vimp = 0.3;
    int quiet = 0;
    opts[CHAIN_CLI_NOPTS] = (gw_opt){.name = "n", .kind = GW_OPT_LONG, .dest = &n, .metavar = "N",
                                     .help = CHAIN_N_HELP, .lo = 1, .hi = 50000000};
    opts[CHAIN_CLI_NOPTS + 1] = (gw_opt){.name = "vimp", .kind = GW_OPT_DOUBLE, .dest = &vimp,
                                         .metavar = "V", .help = "impact velocity, m/s [0.3]",
                                         .lo = GW_CHAIN_VIMP_MIN, .hi = GW_CHAIN_VIMP_MAX};
    opts[CHAIN_CLI_NOPTS + 2] = (gw_opt){.name = "quiet", .kind = GW_OPT_FLAG, .dest = &quiet,
                                         .help = "no progress lines (a run that lasts 2 s or more reports on stderr)"};
    opts[CHAIN_CLI_NOPTS + 3] = (gw_opt){0};
    int done = chain_cli_parse("chain", "granwave chain [options]", chain_summary, opts, argc, argv);
    if (done >= 0)
        return done;
    gw_err err = {{0}};
    c.params.n = (int)n;
    c.params.v_imp = vimp;
    gw_chain *chain = NULL;
    /* --out was tried by the resolution; it is made only when there is
     * something to write (a run refused by the model leaves nothing) */
    int rrc = chain_cli_resolve(&c, opts, "chain", &err);
    if (rrc != GW_OK) {
        chain_cli_free(&c);
        return chain_cli_fail_rc(rrc, err.msg);
    }
    gw_chain_trace tr;
    gw_chain_trace_init(&tr, 0);
    if (c.out) {
        c.run.sample = gw_chain_trace_sample;
        c.run.sample_ctx = &tr;
    }
    /* damping with nothing to act on, and the run's bounds (samples, trace,
     * steps, memory), before anything is allocated */
    if (chain_damping_check(&c.params, &err) != GW_OK || gw_chain_run_check(&c.params, &c.run, &err) != GW_OK) {
        gw_cli_study_error(gw_chain_setup_params(), "chain", GW_EINVAL, &err); /* "NAME: ..." -> "chain --NAME: ..." */
        fprintf(stderr, "granwave %s\n", err.msg);
        chain_cli_free(&c);
        return 2;
    }
    int crc = gw_chain_create(&c.params, &chain, &err);
    if (crc != GW_OK) {
        chain_cli_free(&c);
        return chain_cli_fail_rc(crc, err.msg); /* out of memory: exit 1, not bad input */
    }
    gw_chain_trace_init(&tr, c.params.n);
    gw_chain_result r;
    chain_progress prog = {.n = c.params.n};
    gw_cli_progress_init(&prog.p, "  ", "", CHAIN_PROGRESS_MS);
    prog.p.after_ms = gw_cli_progress_ms(CHAIN_PROGRESS_MS);
    gw_cli_column_init(&prog.col, c.params.n, !c.run.solver || c.run.solver == gw_solver_cvode);
    double t0 = gw_clock_ms();
    int rc = chain_collide_progress_end(chain, &c.run, quiet ? NULL : chain_progress_report, &prog,
                                        quiet ? NULL : &prog.end, &r, &err);
    double wall_ms = gw_clock_ms() - t0;
    if (rc == GW_OK && !quiet) /* the last line, at the run's end (none for a run under 2 s) */
        gw_cli_progress_time(&prog.p, &prog.col, r.t_end, prog.t_expect, prog.t_max, 1);
    int code = 0;
    if (rc == GW_OK) /* held by gravity: what its warning calls undecided is null in JSON, n/a in the text */
        gw_chain_result_held_blank(&r);
    if (rc != GW_OK) {
        /* the library's run messages start "chain: " already */
        fprintf(stderr, "granwave %s%s\n", strncmp(err.msg, "chain: ", 7) == 0 ? "" : "chain: ", err.msg);
        code = rc == GW_EINVAL ? 2 : 1;
        /* keep what was computed: the trace up to the failure and its state; not
         * after an out-of-memory error (one line, nothing written: the trace
         * then ends where memory did, not where the solver failed) */
        if (c.out && code == 1 && rc != GW_ENOMEM) {
            char *hdr = run_header(&c, &r, argc, argv);
            char path[4096];
            gw_err werr = {{0}};
            cJSON *o = chain_result_json(&c, &r, wall_ms);
            cJSON_AddStringToObject(o, "error", err.msg);
            gw_outset set; /* the earlier run's chain.json goes: these are this run's files */
            memset(&set, 0, sizeof set);
            char made[4096] = ""; /* the first directory of --out this run creates */
            if ((!hdr && gw_err_set(&werr, GW_ENOMEM, "out of memory") != GW_OK) ||
                gw_cli_outset_begin(&set, c.out, chain_files, made, sizeof made, &werr) != GW_OK ||
                gw_chain_trace_write(&tr, c.out, "chain", hdr, &werr) != GW_OK ||
                gw_path_join(path, sizeof path, c.out, "chain_failure.json") != GW_OK ||
                gw_json_write(path, o, &werr) != GW_OK || gw_outset_commit(&set, &werr) != GW_OK) {
                gw_cli_outset_end(&set, c.out, made, 0);
                fprintf(stderr, "granwave chain --out: %s\n", werr.msg);
            } else {
                gw_cli_outset_end(&set, c.out, made, 1);
                char q[GW_CLI_PATH_TEXT];
                fprintf(stderr, "granwave chain: state at t = %.9g s and the trace so far are in %s\n", r.t_end,
                        gw_cli_path(q, sizeof q, c.out));
            }
            cJSON_Delete(o);
            free(hdr);
        }
    } else {
        /* results at t_max, not final, or an overlap beyond the radius: the
         * library's text (out of memory for it: none), said on stderr and
         * listed in chain.json and --json */
        char *w = NULL;
        if (chain_damping_zero_warnings(&c.params, 0, 1, &w) == GW_OK &&
            chain_damping_small_warning(&c.params, c.run.sp.rtol, &w) == GW_OK &&
            chain_drag_small_warnings(&c.params, c.run.sp.rtol, &w) == GW_OK &&
            gw_chain_result_warnings(&r, &w) == GW_OK && chain_energy_warning(r.energy_error, r.run_dt, &c.run, &w) == GW_OK &&
            c.out) /* the stored trace stopped at its bound while the run went on */
            (void)chain_trace_cut_warnings(&tr, r.t_end, "--dt-out", &w);
        if (c.out) {
            char *hdr = run_header(&c, &r, argc, argv);
            char path[4096];
            cJSON *o = chain_result_json(&c, &r, wall_ms);
            gw_cli_json_warnings(o, w);
            gw_outset set; /* all of this run's files, or (a write failed) the earlier run's as they were */
            memset(&set, 0, sizeof set);
            char made[4096] = ""; /* the first directory of --out this run creates, taken back on a failure */
            if ((!hdr && gw_err_set(&err, GW_ENOMEM, "out of memory") != GW_OK) ||
                gw_cli_outset_begin(&set, c.out, chain_files, made, sizeof made, &err) != GW_OK ||
                gw_chain_trace_write(&tr, c.out, "chain", hdr, &err) != GW_OK ||
                gw_path_join(path, sizeof path, c.out, "chain.json") != GW_OK ||
                gw_json_write(path, o, &err) != GW_OK || gw_outset_commit(&set, &err) != GW_OK) {
                gw_cli_outset_end(&set, c.out, made, 0);
                fprintf(stderr, "granwave chain --out: %s\n", err.msg);
                code = 1;
            } else
                gw_cli_outset_end(&set, c.out, made, 1);
            cJSON_Delete(o);
            free(hdr);
        }
        if (code == 0)
            gw_cli_warnings("chain", w);
        if (code == 0) {
            if (c.json) {
                cJSON *o = chain_result_json(&c, &r, wall_ms);
                gw_cli_json_warnings(o, w);
                code = gw_cli_json_stdout("chain", o);
                cJSON_Delete(o);
            } else {
                print_text(&c, &r);
            }
        }
        free(w);
    }
    gw_chain_result_free(&r);
    gw_chain_trace_free(&tr);
    gw_chain_free(chain);
    chain_cli_free(&c);
    return code;
}
