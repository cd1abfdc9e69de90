/*
 * gw_chain_study.h: column collisions as library calls with parameters
 * described once (gw_param.h).
 *
 * gw_chain_setup holds the inputs of one collision as `granwave chain` takes
 * them: bead count and impact velocity, materials or direct Hertz coefficients
 * (F.12, F.3), a sheet of the paper's Table 2, damping (physics.md 1.5) and the
 * solver settings. Its table (gw_chain_setup_params) gives each field's name
 * (the flag of `granwave chain`; Python keywords write '-' as '_'), unit, range,
 * default and help. gw_chain_setup_resolve turns a setup into the model's
 * gw_chain_params and gw_chain_run_opts (materials to coefficients, damping
 * calibration to a restitution target) with the checks the command makes;
 * gw_chain_collision_run runs the collision (physics.md 1.1-1.4) and fills a
 * gw_chain_collision, whose table (gw_chain_collision_fields) names its results.
 *
 * Errors: GW_EINVAL with "NAME: reason" naming the parameter; solver failures
 * as gw_chain_collide. SI units: m, s, kg, N, N/m^1.5.
 */
#ifndef GW_CHAIN_STUDY_H
#define GW_CHAIN_STUDY_H

#include "gw_chain.h"
#include "gw_param.h"

#include "gw_api.h"

GW_BEGIN_DECLS /* the exported interface, C linkage (gw_api.h) */

/* Accepted Hertz coefficients, N/m^1.5: the stiffest real contact (diamond on
 * diamond, R = 1 m) has k ~ 1e12, the softest sheet of Table 2 K_eff ~ 1e6. */
#define GW_CHAIN_K_MIN 1e3
#define GW_CHAIN_K_MAX 1e14
/* the column's tolerances when rtol, atol are not given (CVODE, ARKode) */
#define GW_CHAIN_TOL_DEFAULT 1e-12

/* Work of a study over a range of N (falcon, wavespeed, softwall): a column of
 * N beads runs to t_max = 20 (N T_q + tau_1) with steps set by the contact time,
 * so its work grows as N^2 (beads x steps; measured, falcon at 0.316 m/s, one
 * job: N = 100 3.0 s, 200 14 s, 400 39 s). The study's work, the sum of N^2
 * over its range times the columns run at each N (impact speeds, heights or
 * walls), is refused above 2e6 before anything runs: 9x the largest documented
 * study (softwall --sheets --n 1:40, 9 walls x 22140 = 2.0e5, 47 s) and room
 * for falcon --n 1:100 at its five default speeds (1.7e6); at the bound one
 * column of N = 1414, measured 353 s of CPU under cvode (session 45): about
 * N^2.5 from chain --n 400's 16 s of CPU (N^2 gives 3.4 min, N^2.5 6.3 min; the
 * 8 to 15 min estimated before scaled falcon's 39 s, its run to t_max, and was
 * 2.5 times too long). chain --n 600 took 49 s of CPU. The progress line's
 * first estimate ("~L s left" at the pace of its first seconds) is
 * low: between 50 and 70 % of the expected length the run goes 3 to 6
 * times slower than before, and it goes on past the
 * expected length until every pair separates (N = 400: first estimate 9.8 s of
 * CPU, 14.9 s to the expected length, 16.1 s in all; N = 600: 18.9 s, 39.3 s,
 * 48.9 s, t_end 113.8 ms against 15.0 ms expected; N = 1414: about 1300 s of
 * wall time at a 15 % share against 39 min).
 * --n 1:100000 asked for 3e14 (days). One column is held to the same bound
 * over the share of its collision it runs (the plan: chain, drop, sweeps,
 * dispersion's column, Python; since session 45: chain --n 100000 ran for
 * days). */
#define GW_CHAIN_STUDY_WORK_MAX 2e6

/* The work of a study over N = a..b with runs columns at each N (runs < 1
 * counts as 1) against GW_CHAIN_STUDY_WORK_MAX: GW_EINVAL "n: A:B at R
 * columns per N is W bead^2 of work ...", else GW_OK. The studies call it in
 * their check; commands call it before they create --out. */
int gw_chain_study_work_check(long a, long b, int runs, gw_err *err);
/* The impact velocities v[0..n) of a study (falcon: the speeds, then the heights'
 * sqrt(2 g h); wavespeed) are distinct: one given twice ran the same collisions
 * twice and counted them twice in the fits (a spurious standard error with two
 * distinct speeds), and no two lie within GW_CHAIN_SPEEDS_REL_MIN of each
 * other. GW_EINVAL "vimp: ..." (or "heights: ..." for an index >=
 * n_speeds) otherwise. Only finite speeds are compared (a non-finite one is
 * left to the ranges, which refuse it). */
int gw_chain_study_speeds_check(const double *v, int n, int n_speeds, gw_err *err);
/* Two speeds closer than this, relative, are refused by the same check, named
 * as such: the fits over v_imp would rest on their difference (0.3 and the
 * next double gave beta -278424, exit 0). The collisions resolve a wave speed
 * to about 1e-10 at the default tolerances (measured: beta off by about
 * 7e-11 / the relative spread), so a spread of 1e-6 moves beta by 1e-4 at most. */
#define GW_CHAIN_SPEEDS_REL_MIN 1e-6
/* The impact velocities of the falcon study, one rule for the program, the
 * library's gw_chain_falcon_run and Python: v[0..n_vimp) the speeds vimp as
 * given, then v[n_vimp + j] = sqrt(2 g h) of the drop height heights_mm[j] (mm),
 * g = gravity (the run's, m/s^2, the row's [0, 1e4]: NaN, infinite or negative
 * GW_EINVAL "gravity: ...", and a negative n_vimp or n_heights GW_EINVAL naming
 * it, since session 34) when > 0, else GW_CHAIN_G_EARTH; h_mm (may be
 * NULL) the heights, NaN for a speed given directly. v and h_mm hold n_vimp +
 * n_heights. Checks, in this order: at least one velocity (GW_EINVAL "vimp: no
 * impact velocity ..."); each value > 0, vimp first ("vimp: X must be > 0",
 * "heights: X must be > 0"); the speeds in [GW_CHAIN_VIMP_MIN,
 * GW_CHAIN_VIMP_MAX] and the heights in [GW_CHAIN_HEIGHT_MIN_MM,
 * GW_CHAIN_HEIGHT_MAX_MM] ("vimp: item K is X, outside [A, B]", the rows of
 * gw_chain_falcon_setup_params); under another gravity than Earth's, each
 * height's fall within chain's impact speeds [GW_CHAIN_VIMP_MIN,
 * GW_CHAIN_VIMP_MAX] m/s ("heights: item K is H mm: at gravity G m/s^2 it falls
 * to v = ... m/s, outside the impact speeds [..] m/s"); then the velocities
 * distinct (gw_chain_study_speeds_check, which compares finite speeds only). */
int gw_chain_falcon_speeds(const double *vimp, int n_vimp, const double *heights_mm, int n_heights, double gravity,
                           double *v, double *h_mm, gw_err *err);

typedef struct gw_chain_setup {
    long n;               /* beads [1] */
    double vimp;          /* impact velocity toward the wall, m/s [0.3] */
    int material;         /* bead material (choice) [-1: not given = steel] */
    double radius;        /* bead radius, m [NaN: not given = 4e-3] */
    int wall_material;    /* wall material, a half-space (choice) [-1: not given = steel] */
    int sheet;            /* sheet of Table 2 on the wall (choice) [-1: none given] */
    gw_param_list radii;  /* per-bead radii, m, bead 1 first [empty] */
    double k, kwall, mass;/* direct coefficients, N/m^1.5, kg [NaN: from materials] */
    double gravity;       /* toward the wall, m/s^2 [0] */
    int damping;          /* none, kk, hc (choice) [none] */
    double gamma, alpha;  /* damping constants [NaN: not given = 0] */
    double restitution;   /* calibrate gamma/alpha to this one-bead restitution [NaN: off] */
    double restitution_v; /* impact velocity of the calibration, m/s [NaN: vimp] */
    /* the solver rows solver, method, rtol, atol and dt have a "not given"
     * state (-1, NaN), resolved to cvode, its default method, 1e-12 and 0: a
     * study that picks its own solver (falcon by its accuracy target) runs
     * the solver as given when any of them is set, even to that value */
    int solver;           /* cvode, arkode, rk4 (choice) [-1: not given = cvode] */
    int method;           /* default, bdf, adams, erk, dirk, imex (choice) [-1: not given = default] */
    double rtol, atol;    /* tolerances [NaN: not given = GW_CHAIN_TOL_DEFAULT] */
    double dt, dt_max;    /* s [dt NaN: not given = 0; 0: auto: T_c/400 (rk4); dt_max 0: a quarter of the
                           * shortest binary contact at 2 v_imp] */
    long max_steps;       /* steps between outputs [1e7] */
    double t_max;         /* s [0: 20 (n T_q + tau_1), + 20 pi sqrt((sum m + M)/k_s) on a sensor body,
                             going on while contacts act (gw_chain_run_opts.t_max)] */
    double dt_out;        /* sampling interval, s [0: tau_1/200] */
    double energy_tol;    /* stop when the energy error exceeds it [0: off] */
    int sheet_law;        /* fitted, hertz, layer, material (choice) [-1: fitted] */
    double sheet_yield;   /* Pa, with sheet-law material [NaN: the sheet's] */
    double sheet_loss;    /* tan(delta), with sheet-law material [NaN: the sheet's] */
    double sensor_mass;   /* the sensor as a body, kg [NaN: rigid sensor] */
    double sensor_stiffness; /* N/m, needed with sensor_mass [NaN] */
    double sensor_damping;   /* N s/m [NaN: 0] */
    double guide_friction;   /* Coulomb friction per bead, N [0] */
    double guide_viscous;    /* viscous friction per bead, N s/m [0] */
    int sheets;           /* not a table row: set by the softwall study when the
                             sheet law applies to every sheet of Table 2 [0] */
    int trace;            /* library only: keep the wall force and bead series [0] */
} gw_chain_setup;

/* The table of gw_chain_setup (static, NULL-terminated). */
const gw_param *gw_chain_setup_params(void);

/* Defaults from the table; free with gw_chain_setup_clear. GW_OK. */
int gw_chain_setup_init(gw_chain_setup *s);
/* Free what s owns (radii); s then holds no list. */
void gw_chain_setup_clear(gw_chain_setup *s);

/* A setup turned into the model and its run options. */
typedef struct gw_chain_resolved {
    gw_chain_params params; /* params.masses/kc point into the arrays below,
                               params.wall.layer to layer */
    gw_chain_run_opts run;
    double *masses, *kc;    /* owned (per-bead radii) */
    gw_layer_law *layer;    /* owned: the bonded layer of a sheet under law layer
                               or material */
    gw_sheet_law law;       /* the sheet law resolved (fitted when not given) */
} gw_chain_resolved;

/* Materials, sheet and radii to masses and coefficients, damping (calibrated
 * when restitution is set: runs one-bead collisions), solver and method, with
 * the checks of `granwave chain` (unknown or unusable names, options that would
 * have no effect, tolerances). GW_EINVAL "NAME: reason"; GW_ESOLVER from a
 * calibration that fails. r is zeroed first; free it with
 * gw_chain_resolved_free also after a failure. */
int gw_chain_setup_resolve(const gw_chain_setup *s, gw_chain_resolved *r, gw_err *err);
void gw_chain_resolved_free(gw_chain_resolved *r);

/* One collision: the observables of gw_chain_result, the resolved model, the
 * closed forms of its parameters, and (setup trace = 1) the series. */
typedef struct gw_chain_collision {
    gw_chain_result r;
    double v_imp, mass, k, kwall, radius; /* resolved model: m/s, kg, N/m^1.5, m */
    double tau_1, d_max_1, f_max_1;       /* one bead on this wall (F.2, F.13): s, m, N */
    double t_q;                           /* 2 (m/k)^(2/5) v^(-1/5) (F.17, F.29), s */
    double k_c;                           /* K_c (F.22), N/m^1.5 */
    double wall_time_ms;
    int trace_len;                        /* samples in the series */
    double *t, *f_wall;                   /* [trace_len] s, N */
    double *x, *v;                        /* [trace_len * n] m, m/s, bead 1 first */
    double gamma, alpha;                  /* the damping constants run (calibrated with
                                             restitution): N s/m^1.5, s/m */
    char *warnings;                       /* gw_chain_result_warnings of r (owned; NULL: none) */
    double chatter;                       /* r.chatter_kind and r.chatter_spread as chain --json's
                                             "chatter": 0 none, the eps_eff spread a rerun
                                             measured, -1 not run again, -2 the rerun failed */
} gw_chain_collision;

/* The table of gw_chain_collision's results. */
const gw_param *gw_chain_collision_fields(void);

/* Resolve s and run the collision into out (zeroed first; free with
 * gw_chain_collision_free, also after a failure: out then holds what was
 * computed). Returns GW_OK, GW_EINVAL (setup), GW_ENOMEM, or the failure of
 * gw_chain_collide (GW_ESOLVER, GW_ELIMIT, GW_EENERGY) with its message. */
int gw_chain_collision_run(const gw_chain_setup *s, gw_chain_collision *out, gw_err *err);
void gw_chain_collision_free(gw_chain_collision *out);

/* ---- the Falcon rigid-wall study (physics.md 1.3, 1.7) ---- */

/* Per impact velocity: tau_N = T_q (N - 1) + tau_1 (F.4) fitted over all N and
 * over N <= 20 (GSL), wave speed 4R/T_q (F.6) against 2 (k/m)^(2/5) R v^(1/5)
 * (F.27), F_max over N, the mean force period P (N >= 10), closed forms. */
typedef struct gw_chain_falcon_fit {
    gw_linfit fit, fit20;  /* x = N - 1, y = tau_N (s): c1 = T_q, c0 the intercept */
    double f_mean, f_min, f_max, tau_max_mean, period_mean; /* N, N, N, s, s */
    double t_q_theory, tau_1_theory, f_max_1_theory;        /* s, s, N */
    double speed, speed20, speed_theory;                    /* m/s */
    int n_decided, n_decided20; /* columns fitted (over all N, over N <= 20): those not held by
                                   gravity (gw_chain_result.wall_pending "held by gravity: ...") */
} gw_chain_falcon_fit;

/* Analyse the collisions res[0 .. n_hi - n_lo] (N = n_lo .. n_hi) of the column
 * p at impact velocity v into a. A collision held by gravity (its wall_pending
 * "held by gravity: ...": stopped when the column fell back onto the wall, its
 * values those of that time) is left out of every number: the fits, means and
 * extremes are those of the decided columns alone, NaN where fewer than two
 * (a fit) or none (a mean) remain. GW_OK, or GW_ENOMEM (no memory for the fit:
 * a filled, its fits undefined, NaN; it was void, and an allocation that
 * failed gave t_q and the wave speed null with exit 0). GW_EINVAL (a not
 * touched) for a NULL argument, n_lo < 1, n_lo > n_hi or n_hi = INT_MAX: the
 * refusals of gw_chain_falcon_analyse_check, which names the argument (this
 * call has no error argument: its refusals said nothing). */
int gw_chain_falcon_analyse(const gw_chain_params *p, double v, const gw_chain_result *res, int n_lo,
                             int n_hi, gw_chain_falcon_fit *a);
/* The arguments gw_chain_falcon_analyse refuses, each with one line naming
 * it: GW_OK, or GW_EINVAL "gw_chain_falcon_analyse: res is NULL", "...: n_lo
 * = 0: column sizes are bead counts >= 1", "...: n_lo = 5 > n_hi = 3: no
 * column", "...: n_hi = 2147483647 (INT_MAX): ...". a is the fit to be
 * filled (only its being NULL is checked). */
int gw_chain_falcon_analyse_check(const gw_chain_params *p, const gw_chain_result *res, int n_lo, int n_hi,
                                  const gw_chain_falcon_fit *a, gw_err *err);

/* A study's progress within its collisions (the gw_chain_*_run_watch calls),
 * for a display that must speak however long one collision runs: watch(ctx,
 * done, total, part) after every output sample of every collision under way
 * and as each ends, one call at a time (under the study's lock), from the
 * thread running that collision. done and total count the study's
 * collisions (its sweep and its own runs: wavespeed's front columns, falcon's
 * traces, softwall's rigid wall); part (0..1) is the share of the study's
 * expected time elapsed, so that (1 - part) / part of the time elapsed is
 * the time left: each collision weighed by its expected steps and samples
 * times its beads and counted under way by t / t_expect of it (a tenth of it
 * over its tail past t_expect), the time counted in that work per thread at
 * work, the work left scheduled over the threads that will run it (the
 * study's jobs, fewer at a sweep's end, one for the runs after it). On one
 * thread, the share of the expected work done.
 * Called often (every sample): it must return quickly and cannot stop the
 * study (the gw_progress_fn does, per collision). */
typedef void (*gw_chain_watch_fn)(void *ctx, long done, long total, double part);

/* The inputs of `granwave falcon`: the column (its model and solver rows; its n,
 * vimp and trace are not used) and the study's own. */
typedef struct gw_chain_falcon_setup {
    gw_chain_setup col;
    gw_param_list vimp;    /* impact velocities, m/s [0.3] */
    gw_param_list heights; /* drop heights, mm, v = sqrt(2 g h), g = gravity, or 9.81 when 0
                              (gw_chain_falcon_speeds) [1.9,2.9,3.1,5.1] */
    long n[2];             /* column sizes [1:40] */
    double accuracy;       /* relative accuracy of F_max and tau_N for the RK4 step
                              study, used when every solver row of col is at its
                              default (0: col's solver rows as they are) [NaN: not
                              given, 1e-6; a value given, 1e-6 too, is refused where
                              it cannot act (a solver row set, a column outside the
                              step study), as granwave falcon --accuracy] */
    long jobs;             /* threads [0 = one per CPU] */
    int traces;            /* not a row (C only): 1 also runs the traces of N = 7, 15, 30
                              (those <= n[1]) at the first velocity into the outcome's
                              trace[] (granwave falcon --out writes them) [0] */
} gw_chain_falcon_setup;

const gw_param *gw_chain_falcon_setup_params(void);
int gw_chain_falcon_setup_init(gw_chain_falcon_setup *s);
void gw_chain_falcon_setup_clear(gw_chain_falcon_setup *s);

/* One trace of the Falcon study: the collision of N beads at the first
 * velocity, sampled every tau_1/50 of that velocity when the solver was picked
 * by the accuracy target (else at col's dt-out), with what its run used. */
typedef struct gw_chain_falcon_trace {
    int n;                 /* column size: 7, 15 or 30 */
    double v_imp;          /* m/s, the study's first velocity */
    gw_chain_trace tr;     /* t and the wall force; the beads' x and v for N = 7 only
                              (tr.n = 0 for 15 and 30: gw_chain_trace_write then
                              writes the wall force only) */
    double t_max, dt_out, dt, dt_max; /* s, as gw_chain_result's run_* */
} gw_chain_falcon_trace;

#define GW_CHAIN_FALCON_NTRACE 3

typedef struct gw_chain_falcon_outcome {
    int nv, nn, ncase;     /* velocities, column sizes, nv * nn */
    double *v_imp, *h_mm;  /* [nv] m/s; mm (NaN: velocity given directly) */
    double *n;             /* [nn] column sizes */
    /* [nv * nn], velocity-major: case (iv, N) at iv * nn + (N - n_lo) */
    double *f_max, *tau_max, *tau_n, *period, *eps_eff, *eps_col, *e_rel_over_e_k, *n_s, *energy_error;
    double *t_max, *dt_out, *dt, *dt_max; /* [ncase] s: what each collision ran with, defaults resolved
                                             (dt: the RK4 step, 0 for cvode and arkode) */
    /* [nv] per velocity (gw_chain_falcon_fit) */
    double *t_q, *t_q_err, *tau_fit_intercept, *tau_fit_intercept_err, *r2, *tau_fit_max_rel_resid;
    double *t_q_n20, *t_q_n20_err, *wave_speed, *wave_speed_n20, *wave_speed_theory;
    double *t_q_theory, *tau_1_theory, *f_max_1_theory;
    double *f_max_mean, *f_max_min, *f_max_max, *tau_max_mean, *period_mean;
    double k_c;            /* N/m^1.5 (F.22) */
    int rigid;             /* K > K_c */
    double accuracy;       /* the accuracy target used (0: col's solver) */
    double wall_time_s;
    int unfinished;        /* collisions not ended at t_max (gw_chain_result.converged 0):
                              their tau_N, eps and the fits over them are those at t_max */
    /* [ncase] more columns of falcon_runs.csv: wall-force maxima, the cluster,
       solver steps and right-hand side evaluations of each collision */
    double *n_maxima, *cluster, *steps, *rhs_evals;
    double gamma, alpha;   /* the damping constants run (calibrated with restitution) */
    int steps_per_tc;      /* RK4 steps per T_c by the accuracy target (0: col's solver) */
    /* [nbeads] the beads of every collision (falcon_final_velocities.csv), velocity-major,
       then N, then bead 1..N: nbeads = nv * (n_lo + ... + n_hi) */
    int nbeads;
    double *bead_v_imp, *bead_n, *bead; /* m/s; the column size; the bead, 1 = on the wall */
    double *final_v, *detach_t, *v_tau_n; /* m/s (toward the wall > 0) at the end; s, its last
                                             contact opening; m/s at tau_N */
    int ntrace;            /* traces run (setup.traces): N = 7, 15, 30 up to n_hi */
    int trace_failed;      /* 1: a trace's run failed after the study (its error returned;
                              every number above stands, trace[0..ntrace) those done) */
    gw_chain_falcon_trace trace[GW_CHAIN_FALCON_NTRACE];
    char *warnings;        /* gw_chain_unfinished_warnings and the held columns' (owned; NULL: none) */
    /* collisions held by gravity (the column fell back onto the wall before its
       collision ended; counted in unfinished): their values are those of that
       time, undecided, and every fit, mean and extreme per velocity leaves
       them out (NaN where too few decided columns remain: a warning says so) */
    int n_held;            /* of ncase */
    int *held;             /* [ncase] 1: held (velocity-major as f_max) */
} gw_chain_falcon_outcome;

const gw_param *gw_chain_falcon_outcome_fields(void);

/* Run the study: every (v, N) collision on jobs threads, progress per
 * collision (may be NULL), then the analysis per velocity, then with
 * s->traces the traces (gw_chain_falcon_trace, no progress). out zeroed first;
 * free with gw_chain_falcon_outcome_free also after a failure. GW_EINVAL
 * "NAME: reason", a collision's failure ("N = .., v_imp = ..: ..."),
 * GW_ECANCELED, GW_ENOMEM. */
int gw_chain_falcon_run(const gw_chain_falcon_setup *s, gw_progress_fn progress, void *pctx,
                        gw_chain_falcon_outcome *out, gw_err *err);
/* The same with watch(wctx, ...) (may be NULL) within the collisions. */
int gw_chain_falcon_run_watch(const gw_chain_falcon_setup *s, gw_progress_fn progress, void *pctx,
                              gw_chain_watch_fn watch, void *wctx, gw_chain_falcon_outcome *out, gw_err *err);
/* The column sizes a..b of the falcon study: its product at each velocity is
 * the line tau_N = T_q (N - 1) + tau_1 over N (T_q, the wave speed 4R/T_q),
 * which one size does not give (--n 1:1 printed T_q and the speed as nan, exit
 * 0): GW_EINVAL "n: ..." when a == b. gw_chain_falcon_run checks it; the
 * command calls it before it creates --out. */
int gw_chain_falcon_sizes_check(long a, long b, gw_err *err);
/* The same at ncols columns per N (the study's speeds and heights): the pair
 * it suggests for one size is one the work bound holds at that count
 * (gw_chain_falcon_sizes_check is this at 1). */
int gw_chain_falcon_sizes_check_at(long a, long b, int ncols, gw_err *err);
void gw_chain_falcon_outcome_free(gw_chain_falcon_outcome *out);
/* The warning of a study over columns (falcon, wavespeed) with unfinished of
 * its total collisions not ended at t_max, appended to *list
 * (gw_warnings_add); nothing when unfinished is 0. GW_OK or GW_ENOMEM;
 * GW_EINVAL, nothing added, for counts no study has (unfinished or total
 * negative, unfinished above total). */
int gw_chain_unfinished_warnings(int unfinished, int total, char **list);
/* The softwall's: unfinished of total collisions still at the wall at t_max
 * (the same counts refused). */
int gw_chain_softwall_warnings(int unfinished, int total, char **list);

/* ---- the studies of `granwave wavespeed`, `softwall`, `drop`, `dispersion` ----
 * Each: a setup struct with its table (rows named as the command's flags; the
 * column's model and solver rows of gw_chain_setup where the command takes
 * them), _setup_init / _setup_clear, a run (out zeroed first; free it with the
 * outcome's _free also after a failure), and the outcome's table (series as
 * double arrays). Errors GW_EINVAL "NAME: reason", a collision's failure,
 * GW_ECANCELED (progress returned non-zero), GW_ENOMEM. Nothing is printed. */

/* Wave speed against v_imp (physics.md 1.3), three ways: 4R/T_q (F.4, F.6), the
 * time of flight of the compression front, the long-wave group speed c0 of the
 * chain compressed by the mean wall force (1.6) and c0/sqrt(3/2); power-law
 * fits v = A v_imp^beta, A as C3 of (F.16) (F.27: 2); P = C2 (m/k)^(2/5)
 * v_imp^(-1/5) (F.15). m/s, s, N. */
typedef struct gw_chain_wavespeed_setup {
    gw_chain_setup col;   /* model and solver rows (n, vimp, trace unused) */
    gw_param_list vimp;   /* m/s [0.075,0.15,0.3,0.5] */
    long n[2];            /* column sizes of the tau_N fit; n[1] the front column [5:40] */
    double threshold;     /* front threshold / F_max(1) (F.13) [0.1] */
    long jobs;            /* threads [0 = one per CPU] */
} gw_chain_wavespeed_setup;

typedef struct gw_chain_wavespeed_outcome {
    int nv;
    double *v_imp, *v_tq, *v_front, *v_group, *v_group_front; /* [nv] m/s */
    double *t_q, *mean_wall_force, *period;                  /* [nv] s, N, s */
    int nn, ncase;                                           /* column sizes n_min..n_max, nv * nn */
    double *t_max, *dt_out, *dt, *dt_max; /* [ncase] s: each collision of the tau_N sweep, defaults
                                             resolved (dt: the RK4 step, 0 for cvode and arkode) */
    double beta, beta_err, c3, c3_theory;                    /* the 4R/T_q fit */
    double fits[4][4]; /* tq, front, group, group_front x beta, beta_err, prefactor, c3 */
    double c2, beta_period, beta_period_err, max_disagreement, threshold;
    int n_min, n_max;
    double wall_time_s;
    int unfinished;        /* collisions of the tau_N sweep not ended at t_max */
    int fitted;            /* 1: the power-law fits over v_imp are made (two speeds or more); 0: one
                              speed, whose speeds, t_q, period, c2 and max_disagreement stand but whose
                              beta, beta_err, c3, fits and beta_period are NaN (no line through one point) */
    double gamma, alpha;   /* the damping constants run (calibrated with restitution) */
    char *warnings;        /* gw_chain_unfinished_warnings and the held columns' (owned; NULL: none) */
    /* Columns held by gravity (the column fell back onto the wall before its
       collision ended): undecided, and left out of what is derived, as if their
       sizes had not been run: t_q and v_tq fit the decided columns (NaN with
       fewer than two), mean_wall_force, v_group and v_group_front are NaN when
       the longest column was held, v_front when the front's column was held
       before the front had reached every contact it fits (2..N-2: first
       arrivals, which the stop does not change, are kept); the
       fits over v_imp, c2 and max_disagreement leave out the speeds so left
       undecided (NaN with fewer than two decided speeds). A warning says so. */
    int n_held;            /* held collisions: of the tau_N sweep (counted in unfinished) and
                              the nv front columns */
    int *held;             /* [ncase] 1: the tau_N sweep's collision was held [velocity, N] */
    int *front_held;       /* [nv] 1: the front's column was held (v_front NaN unless the front
                              had reached every contact 2..N-2 by then) */
} gw_chain_wavespeed_outcome;

const gw_param *gw_chain_wavespeed_setup_params(void);
int gw_chain_wavespeed_setup_init(gw_chain_wavespeed_setup *s);
void gw_chain_wavespeed_setup_clear(gw_chain_wavespeed_setup *s);
const gw_param *gw_chain_wavespeed_outcome_fields(void);
/* progress per collision of the tau_N sweep (may be NULL). */
int gw_chain_wavespeed_run(const gw_chain_wavespeed_setup *s, gw_progress_fn progress, void *pctx,
                           gw_chain_wavespeed_outcome *out, gw_err *err);
/* The same with watch(wctx, ...) (may be NULL) within the collisions. */
int gw_chain_wavespeed_run_watch(const gw_chain_wavespeed_setup *s, gw_progress_fn progress, void *pctx,
                                 gw_chain_watch_fn watch, void *wctx, gw_chain_wavespeed_outcome *out,
                                 gw_err *err);
void gw_chain_wavespeed_outcome_free(gw_chain_wavespeed_outcome *out);

/* Columns on a soft wall (physics.md 1.3): F_max(N), tau_max(N), the saturation
 * number N_d against ceil(tau_max(N_d)/T_q) (F.8), K_c (F.22); with sheets
 * every sheet of Table 2 under the sheet law, model against measured. */
typedef struct gw_chain_softwall_setup {
    gw_chain_setup col;   /* model and solver rows; kwall [NaN: 1e9 unless a sheet] */
    long n[2];            /* column sizes [1:30] */
    double vimp;          /* m/s [NaN: sqrt(2 g 2.9 mm) = 0.2385] */
    double tol;           /* plateau tolerance of N_d [0.01] */
    int sheets;           /* every sheet of Table 2 [0] */
    long jobs;            /* threads [0] */
} gw_chain_softwall_setup;

/* Columns of the per-sheet table (sheet_table, [nsheet x GW_SOFTWALL_NSHEET_COLS]). */
#define GW_SOFTWALL_SHEET_COLS                                                                        \
    "thickness,n_d_model,n_d_measured,n_d_measured_err,n_d_predicted_f8,tau_max_1_model,"             \
    "tau_max_1_measured,tau_max_nd_model,tau_max_nd_measured,tau_max_nd_measured_err,"                 \
    "tau_max_at_measured_nd_model,f_max_at_measured_nd_over_plateau,n_d_tol_0.01,tau_max_nd_tol_0.01," \
    "n_d_tol_0.02,tau_max_nd_tol_0.02,n_d_tol_0.05,tau_max_nd_tol_0.05,n_d_tol_0.1,tau_max_nd_tol_0.1,"  \
    "f_max_1_model,f_plateau_model,eps_eff_1_model,kwall,a_over_h_1"
#define GW_SOFTWALL_NSHEET_COLS 25

typedef struct gw_chain_softwall_outcome {
    int nw, nn, ncase, nsheet;  /* walls, sizes, nw * nn, sheets compared (0, 1 or nw) */
    double v_imp, k_c, t_q_rigid, tol; /* m/s, N/m^1.5, s */
    int sheet_law;              /* gw_sheet_law */
    double *n;                  /* [nn] */
    double *kwall;              /* [nw] N/m^1.5 */
    int *rigid, *saturated;     /* [nw]; saturated 1, 0, or -1 undecided (held columns) */
    double *f_max, *tau_max;    /* [nw * nn] N, s */
    double *t_max, *dt_out, *dt, *dt_max; /* [nw * nn] s: each collision, defaults resolved (dt: the
                                             RK4 step, 0 for cvode and arkode) */
    double *n_d, *n_d_predicted, *n_d_fixed_point, *f_plateau, *tau_max_at_n_d; /* [nw]; NaN: none */
    double *n_d_at_most;        /* [nw]: n_min > 1 when F_max is on its plateau from n_min on, so
                                   N_d <= n_min and is not located (n_d NaN, saturated 1); NaN otherwise */
    double *sheet_table;        /* [nsheet * GW_SOFTWALL_NSHEET_COLS]; NaN: not defined */
    char *sheet_names, *sheet_materials; /* nsheet items, separated by "," and ";" (a material
                                            label: gw_chain_softwall_sheet_material) */
    double wall_time_s;
    int unfinished;             /* collisions still at the wall at t_max (wall_done 0):
                                   their F_max and tau_max may not be final */
    double gamma, alpha;        /* the damping constants run (calibrated with restitution) */
    char *warnings;             /* gw_chain_softwall_warnings and the held columns' (owned; NULL: none) */
    /* Columns held by gravity (the column fell back onto the wall before its
       collision ended): their F_max and tau_max are those of that time,
       undecided, and each wall's plateau, N_d and F.8 are those of its decided
       columns alone, as if the held sizes had not been run: f_plateau is F_max
       of the longest decided column (NaN: none), N_d is located only where
       decided columns bound it (n_d_at_most when the plateau reaches back to a
       held column; saturated -1, undecided, where held columns leave too
       few decided sizes on it, the longest held or one cutting the walk
       short, a warning calling N_d undecided), and t_q_rigid fits the rigid wall's
       decided columns (NaN with fewer than two, and F.8 with it). */
    int n_held;                 /* held collisions, of ncase (counted in unfinished) */
    int *held;                  /* [nw * nn] 1: held [wall, N] (in the block of rigid: freed with it) */
    int n_held_rigid;           /* of the 20 rigid-wall columns of t_q_rigid */
} gw_chain_softwall_outcome;

const gw_param *gw_chain_softwall_setup_params(void);
int gw_chain_softwall_setup_init(gw_chain_softwall_setup *s);
void gw_chain_softwall_setup_clear(gw_chain_softwall_setup *s);
const gw_param *gw_chain_softwall_outcome_fields(void);
/* progress per wall (may be NULL). */
int gw_chain_softwall_run(const gw_chain_softwall_setup *s, gw_progress_fn progress, void *pctx,
                          gw_chain_softwall_outcome *out, gw_err *err);
/* The same with watch(wctx, ...) (may be NULL) within the collisions. */
int gw_chain_softwall_run_watch(const gw_chain_softwall_setup *s, gw_progress_fn progress, void *pctx,
                                gw_chain_watch_fn watch, void *wctx, gw_chain_softwall_outcome *out,
                                gw_err *err);
void gw_chain_softwall_outcome_free(gw_chain_softwall_outcome *out);
/* The longest material label of one sheet, its NUL included. */
#define GW_SOFTWALL_LABEL_MAX 64
/* Sheet w's material label (field w of sheet_materials) copied into buf: the
 * sheet's material, or "no sheet (M sensor)" for the sheet none under a law
 * other than fitted (the Hertz half-space of the sensor's material M). GW_OK;
 * GW_EINVAL (buf "" when size > 0) when w is not one of out's nsheet sheets or
 * the label does not fit in size (GW_SOFTWALL_LABEL_MAX always does). */
int gw_chain_softwall_sheet_material(const gw_chain_softwall_outcome *out, int w, char *buf, size_t size);

/* Small-amplitude dispersion of a precompressed chain (physics.md 1.6,
 * chain_dispersion.c): ridge omega(q) against 2 sqrt(kappa/m) |sin(qa/2)|,
 * kappa = (3/2) k^(2/3) f0^(1/3); or, with column_n > 0, the wall-force spectrum
 * of one column collision against 1/P (chain_spectrum.c). Steel beads, R = 4 mm.
 * rad/s, Hz, m, N. The rows of one mode (all but solver, method, rtol, atol,
 * fftw_measure) are optional (gw_param.h): init leaves them "not given" (NaN,
 * GW_PARAM_UNSET_LONG, -1) and a run uses the defaults below; one given in the
 * other mode is refused, at its default's value too. */
typedef struct gw_chain_dispersion_setup {
    long n;               /* beads [1024] */
    double f0;            /* precompression, N [10] */
    int ends;             /* periodic, fixed (choice) [periodic] */
    long t_samples;       /* even [2048] */
    double dt_out;        /* sampling interval, s [0: pi / (1.25 omega_c)] */
    long steps_per_sample;/* RK4 steps per sample [16] */
    double amp;           /* rms overlap perturbation / d0 [1e-3] */
    long seed;            /* [1] */
    double min_bins;      /* a count held as a double: a whole number [8] */
    int solver;           /* rk4, cvode, arkode (choice) [-1: rk4; column: cvode] */
    int method;           /* default, adams, bdf, erk, dirk (choice) [-1: default] */
    double rtol, atol;    /* [NaN: 1e-10; column: 1e-12] */
    int fftw_measure;     /* [0: FFTW_ESTIMATE] */
    long column_n;        /* 1..100000: the wall-force spectrum of this column instead [not given: off] */
    double vimp;          /* impact velocity of that column, m/s [0.3] */
} gw_chain_dispersion_setup;

typedef struct gw_chain_dispersion_outcome {
    int column;               /* 0: dispersion (r), 1: column wall spectrum (sp) */
    gw_chain_disp_result r;   /* dispersion: qa, omega_ridge, omega_theory, power, ... */
    double c0_rel_err;        /* |c0_measured / c0_theory - 1| */
    double mass, k, kwall, radius; /* the beads (kwall: column mode), kg, N/m^1.5, m */
    double wall_time_ms;
    /* column mode */
    gw_chain_spectrum sp;     /* freq [Hz], power, f_peak, df, f_min, samples */
    double v_imp, tau_n, period, dt_out, rtol, atol; /* m/s, s, s, s */
    int column_n, n_maxima;
    double inv_period;        /* column mode: 1/P, Hz (NaN: fewer than two maxima) */
    double f_peak_rel_diff;   /* column mode: f_peak P - 1 */
    char *warnings;           /* gw_chain_dispersion_warnings, or the column's gw_chain_result_warnings (owned; NULL: none) */
    /* what ran, resolved from the setup (its defaults filled in): the backend
     * and its settings (method as given, GW_METHOD_DEFAULT when not given;
     * rtol, atol), and in dispersion mode the study's parameters */
    const gw_solver_type *solver;
    gw_solver_params solver_params;
    gw_chain_disp_params params;
} gw_chain_dispersion_outcome;

const gw_param *gw_chain_dispersion_setup_params(void);
int gw_chain_dispersion_setup_init(gw_chain_dispersion_setup *s);
void gw_chain_dispersion_setup_clear(gw_chain_dispersion_setup *s);
const gw_param *gw_chain_dispersion_outcome_fields(void);
/* The solver of s: type and settings (GW_EINVAL "solver: ..", "method: ..",
 * "steps-per-sample: .." given with cvode or arkode). */
int gw_chain_dispersion_solver(const gw_chain_dispersion_setup *s, const gw_solver_type **type,
                               gw_solver_params *sp, gw_err *err);
/* One integration; GW_EUNSUPPORTED for bdf/dirk on periodic ends. */
int gw_chain_dispersion_run(const gw_chain_dispersion_setup *s, gw_chain_dispersion_outcome *out, gw_err *err);
/* The same with progress(pctx, k, total) (may be NULL): the velocity samples
 * integrated of t_samples, or with column_n the output samples (the column's
 * dt_out) of the collision's expected length, held one short of the total past
 * it until the end reports the total. Non-zero stops the call (GW_ECANCELED):
 * at once in dispersion mode, at the collision's end with column_n. */
int gw_chain_dispersion_run_progress(const gw_chain_dispersion_setup *s, gw_progress_fn progress, void *pctx,
                                     gw_chain_dispersion_outcome *out, gw_err *err);
void gw_chain_dispersion_outcome_free(gw_chain_dispersion_outcome *out);

/* The whole drop (chain_drop.c, docs/drop.md): the column released from rest
 * with bead 1 at a height h above the sensor, under gravity g, followed from
 * its first contact (t = 0, v_imp = sqrt(2 g h), t_fall = sqrt(2 h / g)) through
 * the first collision (physics.md 1.1-1.4, as `granwave chain`), detachment,
 * free flight and the later impacts, up to t_max; the sensor signal, every
 * wall-force peak and impact, the energy ledger (kinetic + (2/5) k d^(5/2) per
 * contact - m g x + dissipated). m, s, N, J. */
typedef struct gw_chain_drop_setup {
    gw_chain_setup col;    /* n, model and solver rows; gravity [9.81], t_max
                              [10e-3], dt_out [0: min(1 us, t_max)], trace (bead
                              series x, v) [0]; vimp unused (sqrt(2 g h)) */
    double height;         /* m [5.1e-3] */
    gw_param_list gap;     /* m: one value or n-1, bead 1 first [empty: touching] */
    int block;             /* one rigid body of the column's mass [0] */
    double peak_threshold; /* N [NaN: 1 % of F_max(1) (F.13) at v_imp] */
} gw_chain_drop_setup;

/* Columns of the impacts table ([n_impacts x GW_DROP_NIMPACT_COLS]). */
#define GW_DROP_IMPACT_COLS "t_start,t_end,f_max,t_fmax,v_in,v_out,n_peaks,cluster,located,chatter"
#define GW_DROP_NIMPACT_COLS 10

typedef struct gw_chain_drop_outcome {
    gw_chain_drop_result r;  /* everything the run measured (gw_chain.h) */
    int n, n_column, block;  /* simulated bodies (1 with block), beads of the column */
    double height, gravity, v_imp, t_fall, t_max, dt_out, peak_threshold; /* m, m/s^2, m/s, s, s, s, N */
    double dt, dt_max;       /* the run's step (rk4; 0: adaptive) and step cap, s, resolved */
    double mass, k, kwall, radius, gamma, alpha; /* the resolved model (mass: the block's) */
    int n_gaps;              /* n - 1 with gaps, else 0 */
    double *gaps;            /* [n_gaps] m */
    int impact_rises, impacts_monotone;
    double *wall_peaks;      /* [n_peaks x 2]: t (s), f (N) */
    int *peak_impact, *peak_cluster; /* [n_peaks] */
    int *peak_contacts;      /* [n_peaks x n]: 1 = closed, the sensor first */
    double *impacts;         /* [n_impacts x GW_DROP_NIMPACT_COLS] */
    int n_first;             /* entries of the first collision's arrays (n) */
    double e_kinetic, e_elastic, e_gravity, e_dissipated, e_total; /* ledger at t_end, J */
    double wall_time_ms;
    int trace_len;           /* samples of the signal */
    double *t, *f_wall;      /* [trace_len] s, N: the sensor signal */
    double *x, *v;           /* [trace_len x n] m, m/s (setup trace = 1), else NULL */
    int canceled;            /* 1: stopped by the progress callback (at r.t_end, or in the first collision's own run) */
    char *warnings;          /* gw_chain_drop_result_warnings of r (owned; NULL: none) */
    double chatter;          /* r.chatter_kind and r.chatter_spread as drop --json's "chatter": 0 none,
                                the impacts' largest F_max change a rerun measured, -1 not run again,
                                -2 the rerun failed */
    double first_chatter;    /* the first collision's, as chain's (NaN: not checked, cut at t_max) */
} gw_chain_drop_outcome;

const gw_param *gw_chain_drop_setup_params(void);
int gw_chain_drop_setup_init(gw_chain_drop_setup *s);
void gw_chain_drop_setup_clear(gw_chain_drop_setup *s);
const gw_param *gw_chain_drop_outcome_fields(void);
/* The gaps of s for its n beads ([n-1] m, or *gaps = NULL when touching) with
 * the study's checks of the column's layout (GW_EINVAL "gap: ...", or
 * "block: ..." for block with one bead, which changes nothing); the caller
 * frees. */
int gw_chain_drop_setup_gaps(const gw_chain_drop_setup *s, double **gaps, gw_err *err);
/* The drop's block (block = 1): p, a column of p->n beads, becomes one body of
 * the column's whole mass with bead 1's contact constants (p->masses and
 * p->kc are dropped, not freed: the caller owns them). */
void gw_chain_drop_block_params(gw_chain_params *p);
/* The drop (gw_chain_drop_run) from a setup. progress(ctx, done, total) counts
 * output samples of the drop and of its first collision's own run
 * (gw_chain_drop_run_progress: total = 2 t_max / dt_out), called at most about
 * 100 times (may be NULL); a stop ends the run there and returns GW_ECANCELED
 * (out->canceled = 1, out holding what was measured). */
int gw_chain_drop_study_run(const gw_chain_drop_setup *s, gw_progress_fn progress, void *pctx,
                            gw_chain_drop_outcome *out, gw_err *err);
void gw_chain_drop_outcome_free(gw_chain_drop_outcome *out);

GW_END_DECLS

#endif
