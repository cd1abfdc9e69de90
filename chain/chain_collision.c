/*
 * chain_collision.c: one column collision as a library call
 * (gw_chain_study.h): resolve a gw_chain_setup, run gw_chain_collide (physics.md
 * 1.1, eq. F.11), keep the series when asked, and set the closed forms of the
 * run's parameters beside the results:
 *   tau_1 = (4/5) B(2/5, 1/2) (5m/(4K))^(2/5) v^(-1/5)          (F.2)
 *   d_max = (5 m v^2 / (4K))^(2/5),  F_max(1) = K d_max^(3/2)    (F.13)
 *   T_q = 2 (m/k)^(2/5) v^(-1/5)                                 (F.17, F.29)
 *   K_c = (tau_c/4)^(5/2) (5k/4)                                 (F.22)
 * The table of the results names every field for the Python module.
 * SI units: s, m, kg, N, J, m/s.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_model.h"
#include "chain_setup_rows.h"
#include "chain_wall.h"

#define OFF(f) offsetof(gw_chain_collision, f)

static const gw_param collision_fields[] = {
    RI("n", r.n, "number of beads"),
    RD("v_imp", v_imp, "m/s", "impact velocity"),
    RD("f_max", r.f_max, "N", "largest wall force"),
    RD("tau_max", r.tau_max, "s", "time of f_max"),
    RD("tau_n", r.tau_n, "s", "time bead 1 leaves the wall for the last time (contact duration)"),
    RD("period", r.period, "s", "mean spacing of wall-force maxima (NaN if fewer than 2)"),
    RI("n_maxima", r.n_maxima, "wall-force maxima seen"),
    RD("energy_error", r.energy_error, "", "max |E(t) - E(0)| / E(0) over samples and events"),
    RD("e0", r.e0, "J", "initial energy"),
    RA("final_velocities", r.final_v, "m/s", "n", NULL, "bead velocities at the end (toward the wall > 0)"),
    RA("detach_times", r.detach_t, "s", "n", NULL, "last opening of a contact of each bead"),
    RA("velocities_at_tau_n", r.v_tau_n, "m/s", "n", NULL, "bead velocities at tau_n"),
    RD("impulse", r.impulse, "N s", "integral of the wall force over the run"),
    RI("n_s", r.n_s, "beads leaving from the top before the cluster"),
    RI("cluster", r.cluster, "beads in contact with bead 1 when it left the wall"),
    RD("e_rel_over_e_k", r.e_rel_over_e_k, "", "relative kinetic energy E_rel/E_K at tau_n (F.20)"),
    RD("eps_eff", r.eps_eff, "", "momentum restitution of the column (F.7)"),
    RD("eps_col", r.eps_col, "", "energy restitution of the column (F.30)"),
    RI("wall_contacts", r.wall_contacts, "separate wall contacts (> 1: re-contact)"),
    RD("overlap_max_rel", r.overlap_max_rel, "", "largest contact overlap over the run, in bead radii (> 1: warned)"),
    RD("chatter", chatter, "", "bead 1's chatter on a sensor body: 0 none, the eps_eff spread a rerun measured, -1 not run again (costly), -2 the rerun failed"),
    RF("converged", r.converged, "1: all contacts open and separating at t_end"),
    RF("wall_done", r.wall_done, "1: bead 1 off the wall and separating at t_end (f_max, tau_n final)"),
    {.name = "wall_pending", .type = GW_PARAM_TEXT, .offset = OFF(r.wall_pending), .unit = "",
     .help = "wall_done 0: what kept the wall's contact going at t_end (None: done)"},
    RD("t_end", r.t_end, "s", "end of the run"),
    RD("t_max", r.run_t_max, "s", "time limit the run used (default 20 (n T_q + tau_1 + t_s), t_s the column's ride on a sensor spring; where a default run that went on stopped)"),
    RD("dt_out", r.run_dt_out, "s", "sampling interval the run used (default tau_1/200)"),
    RD("dt", r.run_dt, "s", "step the run used: RK4's (default T_c/400, at most dt_max and dt_out), cvode's and arkode's first (0: their own)"),
    RD("dt_given", r.run_dt_given, "s", "the dt given (0: none); dt differs when it was above dt_max or rk4's dt_out"),
    RD("dt_max", r.run_dt_max, "s", "largest step the run allowed (default a quarter of the shortest contact)"),
    RD("rtol", r.run_rtol, "", "relative tolerance the run used (cvode, arkode; NaN under rk4: no error test)"),
    RD("atol", r.run_atol, "", "absolute tolerance the run used (cvode, arkode; NaN under rk4: no error test)"),
    RL("events", r.n_events, "contact events located"),
    RL("missed_events", r.missed_events, "contact changes found from the state, not a root"),
    RL("steps", r.stats.steps, "solver steps"),
    RL("rhs_evals", r.stats.rhs_evals, "right-hand side evaluations"),
    RL("jac_evals", r.stats.jac_evals, "Jacobian evaluations"),
    RL("restarts", r.stats.restarts, "solver restarts (at events)"),
    RD("mass", mass, "kg", "bead mass (bead 1 with radii)"),
    RD("k", k, "N/m^1.5", "bead-bead Hertz coefficient"),
    RD("kwall", kwall, "N/m^1.5", "bead-wall Hertz coefficient K"),
    RD("radius", radius, "m", "bead radius (bead 1 with radii)"),
    RD("tau_1", tau_1, "s", "closed form: one bead's contact time on this wall (F.2)"),
    RD("d_max_1", d_max_1, "m", "closed form: one bead's largest overlap"),
    RD("f_max_1", f_max_1, "N", "closed form: one bead's largest wall force (F.13)"),
    RD("t_q", t_q, "s", "closed form: deformation-wave time 2 (m/k)^(2/5) v^(-1/5) (F.17, F.29)"),
    RD("k_c", k_c, "N/m^1.5", "closed form: critical wall coefficient K_c (F.22)"),
    RD("gamma", gamma, "N s/m^1.5", "Kuwabara-Kono constant run (calibrated with restitution; 0: none)"),
    RD("alpha", alpha, "s/m", "Hunt-Crossley constant run (calibrated with restitution; 0: none)"),
    RD("wall_time_ms", wall_time_ms, "ms", "wall-clock time of the collision"),
    RI("trace_len", trace_len, "samples in the series (trace = 1)"),
    RA("t", t, "s", "trace_len", NULL, "sample times"),
    RA("f_wall", f_wall, "N", "trace_len", NULL, "wall force"),
    RA("x", x, "m", "trace_len", "n", "bead displacements toward the wall, bead 1 first"),
    RA("v", v, "m/s", "trace_len", "n", "bead velocities toward the wall, bead 1 first"),
    GW_PARAM_WARNINGS(OFF(warnings)),
    GW_PARAM_END};

const gw_param *gw_chain_collision_fields(void)
{
    return collision_fields;
}

void gw_chain_collision_free(gw_chain_collision *out)
{
    if (!out)
        return;
    gw_chain_result_free(&out->r);
    free(out->t);
    free(out->f_wall);
    free(out->x);
    free(out->v);
    free(out->warnings);
    out->warnings = NULL;
    out->t = out->f_wall = out->x = out->v = NULL;
    out->trace_len = 0;
}

int gw_chain_collision_run(const gw_chain_setup *s, gw_chain_collision *out, gw_err *err)
{
    /* a single run: what acts only on bead contacts is refused on one bead, as
     * by granwave chain (a sweep's case, run by the progress variant, keeps it) */
    if (s && out && s->n == 1 && chain_one_body_check(s, 1, err) != GW_OK) {
        memset(out, 0, sizeof *out);
        return GW_EINVAL;
    }
    return chain_collision_run_progress(s, out, NULL, NULL, err);
}

int chain_collision_run_progress(const gw_chain_setup *s, gw_chain_collision *out, gw_chain_progress_fn progress,
                                 void *pctx, gw_err *err)
{
    if (out) /* emptied on every refusal, a NULL setup's too (docs/library.md) */
        memset(out, 0, sizeof *out);
    if (!s || !out)
        return gw_err_set(err, GW_EINVAL, "gw_chain_collision_run: %s is NULL", !s ? "setup" : "out");
    gw_chain_resolved res;
    gw_chain *c = NULL;
    gw_chain_trace tr;
    gw_chain_trace_init(&tr, 0);
    int rc = gw_chain_setup_resolve(s, &res, err);
    if (rc == GW_OK)
        rc = chain_damping_check(&res.params, err);
    if (rc == GW_OK) { /* the run's bounds (samples, trace, steps, memory) before anything is allocated */
        gw_chain_run_opts o = res.run;
        o.sample = s->trace ? gw_chain_trace_sample : NULL;
        rc = gw_chain_run_check(&res.params, &o, err);
    }
    if (rc == GW_OK)
        rc = gw_chain_create(&res.params, &c, err);
    if (rc != GW_OK) {
        gw_chain_resolved_free(&res);
        return rc;
    }
    const gw_chain_params *p = &res.params;
    out->v_imp = p->v_imp;
    out->mass = p->mass;
    out->k = p->k;
    out->kwall = p->kwall;
    out->radius = p->radius;
    out->tau_1 = gw_chain_tau1(p->mass, p->kwall, p->v_imp);
    out->d_max_1 = gw_chain_dmax1(p->mass, p->kwall, p->v_imp);
    out->f_max_1 = gw_chain_fmax1(p->mass, p->kwall, p->v_imp);
    out->t_q = gw_chain_tq_theory(p->mass, p->k, p->v_imp);
    out->k_c = gw_chain_kc(p->k);
    out->gamma = p->gamma; /* as the JSON's settings.model: the restitution's calibration */
    out->alpha = p->alpha;
    if (s->trace) {
        gw_chain_trace_init(&tr, p->n);
        res.run.sample = gw_chain_trace_sample;
        res.run.sample_ctx = &tr;
    }
    double t0 = gw_clock_ms();
    rc = gw_chain_collide_progress(c, &res.run, progress, pctx, &out->r, err);
    out->wall_time_ms = gw_clock_ms() - t0;
    if (rc == GW_OK) /* held by gravity: what its warning calls undecided is NaN */
        gw_chain_result_held_blank(&out->r);
    out->chatter = chain_result_chatter_value(&out->r);
    if (s->trace) { /* hand the series over (also after a failure: the run so far) */
        out->trace_len = (int)tr.len;
        out->t = tr.t;
        out->f_wall = tr.f;
        out->x = tr.x;
        out->v = tr.v;
        if (tr.len > (size_t)2147483647) {
            gw_chain_collision_free(out);
            rc = gw_err_set(err, GW_ENOMEM, "trace: more than 2^31 samples (raise dt-out)");
        }
    }
    if (rc == GW_OK && ((rc = chain_damping_zero_warnings(p, 0, 1, &out->warnings)) != GW_OK ||
                        (rc = chain_damping_small_warning(p, res.run.sp.rtol, &out->warnings)) != GW_OK ||
                        (rc = chain_drag_small_warnings(p, res.run.sp.rtol, &out->warnings)) != GW_OK ||
                        (rc = gw_chain_result_warnings(&out->r, &out->warnings)) != GW_OK ||
                        (rc = chain_energy_warning(out->r.energy_error, out->r.run_dt, &res.run, &out->warnings)) != GW_OK))
        rc = gw_err_set(err, rc, "chain: out of memory");
    gw_chain_free(c);
    gw_chain_resolved_free(&res);
    return rc;
}
