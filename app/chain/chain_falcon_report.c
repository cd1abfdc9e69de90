/*
 * chain_falcon_report.c: the markdown report of `granwave falcon`. Each granwave
 * number (from the runs) is set beside the closed forms (F.2, F.13, F.17, F.27)
 * and the paper's measured values (docs/physics.md 1.7, quoted here with their
 * conditions), with the relative difference. Velocities are matched to the
 * paper's drop heights by h_mm; rows whose condition was not run are omitted.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_falcon.h"

enum { Q_FMAX, Q_TAUMAX, Q_PERIOD, Q_TAU1, Q_TQ, Q_TQ20, Q_TAUN1, Q_TAUN40, Q_SPEED, Q_SPEED20 };

typedef struct paper_ref {
    int q;
    double h_mm;
    double exp, exp_err; /* experiment (NaN if none) and its uncertainty (0: none) */
    double sim;          /* paper's simulation (NaN if none) */
    const char *what, *unit;
    double unit_scale;   /* SI -> unit */
} paper_ref;

/* Falcon et al. 1998, as listed in docs/physics.md 1.7 (rigid wall, steel beads). */
static const paper_ref refs[] = {
    {Q_FMAX, 5.1, 69.0, 0.05 * 69.0, NAN, "F_max (N = 1..40)", "N", 1},
    {Q_FMAX, 3.1, 51.8, 0, NAN, "F_max", "N", 1},
    {Q_TAUMAX, 5.1, 17.8, 0.5, NAN, "tau_max", "us", 1e6},
    {Q_PERIOD, 3.1, 32.4, 1.0, NAN, "period P", "us", 1e6},
    {Q_PERIOD, 5.1, 31.2, 1.0, NAN, "period P", "us", 1e6},
    {Q_TAU1, 5.1, 35.5, 0, NAN, "tau_1 (N = 1 contact time)", "us", 1e6},
    {Q_TQ20, 5.1, 25.5, 0, NAN, "T_q (fit over N <= 20)", "us", 1e6},
    {Q_TQ20, 2.9, 28.6, 0, NAN, "T_q (fit over N <= 20)", "us", 1e6},
    {Q_TQ, 5.1, 25.5, 0, NAN, "T_q (slope of tau_N)", "us", 1e6},
    {Q_TQ, 2.9, 28.6, 0, NAN, "T_q (slope of tau_N)", "us", 1e6},
    {Q_TAUN1, 5.1, 35.0, 0, NAN, "collision time N = 1", "us", 1e6},
    {Q_TAUN40, 5.1, 1.04, 0, NAN, "collision time N = 40", "ms", 1e3},
    {Q_SPEED, 1.9, 557, 0, 583, "wave speed 4R/T_q", "m/s", 1},
    {Q_SPEED, 3.1, 586, 0, 613, "wave speed 4R/T_q", "m/s", 1},
    {Q_SPEED, 5.1, 628, 0, 644, "wave speed 4R/T_q", "m/s", 1},
    {Q_SPEED20, 1.9, 557, 0, 583, "wave speed 4R/T_q (N <= 20)", "m/s", 1},
    {Q_SPEED20, 3.1, 586, 0, 613, "wave speed 4R/T_q (N <= 20)", "m/s", 1},
    {Q_SPEED20, 5.1, 628, 0, 644, "wave speed 4R/T_q (N <= 20)", "m/s", 1},
};

static int find_h(const falcon *f, double h)
{
    for (int i = 0; i < f->o.nv; i++)
        if (fabs(f->o.h_mm[i] - h) < 1e-9)
            return i;
    return -1;
}

/* Model value and closed form of quantity q at velocity index iv (SI). */
static void model_value(const falcon *f, int q, int iv, double *val, double *closed)
{
    const gw_chain_falcon_outcome *o = &f->o;
    *closed = NAN;
    *val = NAN;
    switch (q) {
    case Q_FMAX: *val = o->f_max_mean[iv]; *closed = o->f_max_1_theory[iv]; break;
    case Q_TAUMAX: *val = o->tau_max_mean[iv]; *closed = o->tau_1_theory[iv] / 2; break;
    case Q_PERIOD: *val = o->period_mean[iv]; break;
    case Q_TAU1:
        if (f->n_lo <= 1) *val = o->tau_n[falcon_case(f, iv, 1)];
        *closed = o->tau_1_theory[iv];
        break;
    case Q_TQ: *val = o->t_q[iv]; *closed = o->t_q_theory[iv]; break;
    case Q_TQ20: *val = o->t_q_n20[iv]; *closed = o->t_q_theory[iv]; break;
    case Q_TAUN1:
        if (f->n_lo <= 1) *val = o->tau_n[falcon_case(f, iv, 1)];
        *closed = o->tau_1_theory[iv];
        break;
    case Q_TAUN40:
        if (f->n_lo <= 40 && f->n_hi >= 40) *val = o->tau_n[falcon_case(f, iv, 40)];
        break;
    case Q_SPEED: *val = o->wave_speed[iv]; *closed = o->wave_speed_theory[iv]; break;
    case Q_SPEED20: *val = o->wave_speed_n20[iv]; *closed = o->wave_speed_theory[iv]; break;
    }
}

static void fmt(char *b, size_t n, double x, const char *spec)
{
    if (isfinite(x))
        snprintf(b, n, spec, x);
    else
        snprintf(b, n, "-");
}

static void write_comparison(const falcon *f, FILE *fp)
{
    fprintf(fp, "## granwave against the paper\n\n"
                "Paper values are the measurements of docs/physics.md 1.7 (experiment) and the paper's own\n"
                "simulation where it gives one. `model - exp` is relative to the experiment; `within`\n"
                "says whether the model lies inside the stated experimental uncertainty (or 5 %% where\n"
                "none is given).\n\n"
                "| quantity | h (mm) | granwave | closed form | paper exp. | paper sim. | model - exp | model - sim | within exp. |\n"
                "|---|---|---|---|---|---|---|---|---|\n");
    for (size_t k = 0; k < sizeof refs / sizeof refs[0]; k++) {
        const paper_ref *r = &refs[k];
        int iv = find_h(f, r->h_mm);
        if (iv < 0 || ((r->q == Q_TQ20 || r->q == Q_SPEED20) && f->n_hi <= 20))
            continue; /* the N <= 20 rows repeat the full fit then */
        double val, closed;
        model_value(f, r->q, iv, &val, &closed);
        if (!isfinite(val))
            continue;
        double v = val * r->unit_scale, c = closed * r->unit_scale;
        double tol = r->exp_err > 0 ? r->exp_err : 0.05 * r->exp;
        char sv[32], sc[32], se[48], ss[32], sd[32], sm[32];
        fmt(sv, sizeof sv, v, "%.4g");
        fmt(sc, sizeof sc, c, "%.4g");
        if (r->exp_err > 0)
            snprintf(se, sizeof se, "%.4g +- %.2g", r->exp, r->exp_err);
        else
            snprintf(se, sizeof se, "%.4g", r->exp);
        fmt(ss, sizeof ss, r->sim, "%.4g");
        fmt(sd, sizeof sd, 100 * (v - r->exp) / r->exp, "%+.1f %%");
        fmt(sm, sizeof sm, 100 * (v - r->sim) / r->sim, "%+.1f %%");
        fprintf(fp, "| %s (%s) | %.1f | %s | %s | %s | %s | %s | %s | %s |\n", r->what, r->unit, r->h_mm,
                sv, sc, se, ss, sd, sm, fabs(v - r->exp) <= tol ? "yes" : "no");
    }
    fprintf(fp, "\n");
}

static void write_velocity_table(const falcon *f, FILE *fp)
{
    fprintf(fp, "## Per impact velocity\n\n"
                "T_q and the intercept come from the GSL line tau_N = T_q (N - 1) + tau_1 over N = %d..%d\n"
                "(standard errors from the scatter); `T_q (N<=20)` is the same fit over N <= 20, the range\n"
                "of the paper's fits. Closed forms: F_max(1) (F.13), tau_1 (F.2), T_q = 2 (m/k)^(2/5)\n"
                "v^(-1/5) and v = 4R/T_q (F.17, F.27). P is the mean spacing of wall-force maxima for N >= 10.\n\n"
                "| h (mm) | v_imp (m/s) | F_max mean [min, max] (N) | F_max(1) F.13 (N) | tau_max mean (us) | P (us) "
                "| T_q fit (us) | T_q (N<=20) (us) | T_q F.17 (us) | intercept (us) | tau_1 F.2 (us) "
                "| v = 4R/T_q (m/s) | v (N<=20) | v F.27 (m/s) | r^2 |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
            f->n_lo, f->n_hi);
    const gw_chain_falcon_outcome *o = &f->o;
    for (int iv = 0; iv < o->nv; iv++) {
        char h[16];
        fmt(h, sizeof h, o->h_mm[iv], "%.1f");
        fprintf(fp, "| %s | %.4f | %.2f [%.2f, %.2f] | %.2f | %.2f | %.2f | %.3f +- %.3f | %.3f | %.3f | %.2f +- %.2f "
                    "| %.2f | %.1f | %.1f | %.1f | %.6f |\n",
                h, o->v_imp[iv], o->f_max_mean[iv], o->f_max_min[iv], o->f_max_max[iv], o->f_max_1_theory[iv],
                o->tau_max_mean[iv] * 1e6, o->period_mean[iv] * 1e6, o->t_q[iv] * 1e6, o->t_q_err[iv] * 1e6,
                o->t_q_n20[iv] * 1e6, o->t_q_theory[iv] * 1e6, o->tau_fit_intercept[iv] * 1e6,
                o->tau_fit_intercept_err[iv] * 1e6, o->tau_1_theory[iv] * 1e6, o->wave_speed[iv],
                o->wave_speed_n20[iv], o->wave_speed_theory[iv], o->r2[iv]);
    }
    if (o->n_held > 0) /* left out of the numbers above (nan: too few decided columns) */
        fprintf(fp, "\n%d of the %d collisions were held by gravity (the column fell back onto the wall before "
                    "its collision ended): their values are those of that time, undecided, and the fits, means "
                    "and extremes above leave them out; their rows below are marked (held).\n",
                o->n_held, o->ncase);
    fprintf(fp, "\n");
}

static void write_detachment(const falcon *f, FILE *fp)
{
    fprintf(fp, "## Detachment and energy redistribution (v_imp = %.4f m/s)\n\n"
                "Final velocities are signed (positive toward the wall). eps_eff (F.7) and eps_col\n"
                "(F.30) use the final velocities; E_rel/E_K (F.20) is taken at tau_N. The paper finds\n"
                "the top beads leaving faster than v_imp and the bottom ones slower, and E_rel/E_K\n"
                "growing with N.\n\n"
                "| N | tau_N (us) | N_s | cluster | v_top/v_imp | v_bead1/v_imp | eps_eff | eps_col | E_rel/E_K | energy error |\n"
                "|---|---|---|---|---|---|---|---|---|---|\n",
            f->o.v_imp[0]);
    const gw_chain_falcon_outcome *o = &f->o;
    const double v0 = o->v_imp[0];
    const int show[] = {1, 2, 3, 5, 7, 10, 15, 20, 30, 40};
    for (size_t k = 0; k < sizeof show / sizeof show[0]; k++) {
        int n = show[k];
        if (n < f->n_lo || n > f->n_hi)
            continue;
        int c = falcon_case(f, 0, n), b1 = falcon_bead_row(f, 0, n);
        fprintf(fp, "| %d%s | %.3f | %d | %d | %.4f | %.4f | %.6f | %.9f | %.4f | %.1e |\n", n,
                o->held[c] ? " (held)" : "",
                o->tau_n[c] * 1e6, (int)o->n_s[c], (int)o->cluster[c], o->final_v[b1 + n - 1] / v0,
                o->final_v[b1] / v0, o->eps_eff[c], o->eps_col[c], o->e_rel_over_e_k[c], o->energy_error[c]);
    }
    int up = 0, steps = 0;
    for (int n = f->n_lo + 1; n <= f->n_hi; n++) {
        int c = falcon_case(f, 0, n), b = falcon_case(f, 0, n - 1);
        if (o->held[c] || o->held[b]) /* undecided */
            continue;
        up += o->e_rel_over_e_k[c] > o->e_rel_over_e_k[b];
        steps++;
    }
    fprintf(fp, "\nE_rel/E_K increases from N to N+1 in %d of %d steps.\n\n", up, steps);
}

int falcon_write_report(const falcon *f, const char *path, gw_err *err)
{
    gw_afile a;
    int rc = gw_afile_open(&a, path, err);
    if (rc != GW_OK)
        return rc;
    FILE *fp = a.fp;
    const gw_chain_params *p = &f->c.params;
    double kc = gw_chain_kc(p->k);
    fprintf(fp, "# Falcon column: granwave %s against Falcon et al. (1998)\n\n", gw_version());
    fprintf(fp, "Model (F.11): N beads of mass m = %.6g kg (%s, R = %.4g m), bead-bead k = %.6g N/m^1.5 (F.12),\n"
                "wall K = %.6g N/m^1.5 (F.3, %s wall); K_c = %.4g N/m^1.5 (F.22), so the wall is %s.\n"
                "No gravity%s, no dissipation%s. ",
            p->mass, f->c.material, p->radius, p->k, p->kwall, f->c.wall_material, kc,
            p->kwall > kc ? "rigid (K > K_c)" : "soft (K <= K_c)", p->gravity > 0 ? " (off: gravity on)" : "",
            p->damping != GW_DAMP_NONE ? " (off: damping on)" : "");
    if (f->o.accuracy > 0)
        fprintf(fp, "Solver: rk4, events as roots, dt = T_c/%g (T_c = (m/k)^(2/5) v_imp^(-1/5)),\n"
                    "chosen for F_max and tau_N within %.1e relative (measured convergence study).\n",
                (double)f->o.steps_per_tc, f->o.accuracy);
    else if (f->c.run.solver == gw_solver_rk4 || strcmp(f->c.solver, "rk4") == 0) /* no error test: no tolerance */
        fprintf(fp, "Solver: rk4, fixed step (no error test; each collision's dt in falcon_runs.csv).\n");
    else
        fprintf(fp, "Solver: %s (%s), rtol %.1e, atol %.1e.\n", f->c.solver, f->c.method,
                f->c.run.sp.rtol, f->c.run.sp.atol);
    fprintf(fp, "%d collisions (N = %d..%d at %d velocities) in %.2f s of wall time.\n\n",
            f->o.ncase, f->n_lo, f->n_hi, f->o.nv, f->o.wall_time_s);
    fprintf(fp, "The paper's simulations use m = 2.05e-3 kg; the material mass 4/3 pi R^3 rho is\n"
                "2.104e-3 kg (used here unless --mass is given). Drop heights map to v_imp = sqrt(2 g h)\n"
                "with g = 9.81 m/s^2 (1.9 mm gives 0.193 m/s where the paper's Table 1 lists 0.191).\n\n");
    write_comparison(f, fp);
    write_velocity_table(f, fp);
    write_detachment(f, fp);
    return gw_afile_commit(&a, err);
}
