/*
 * chain_wall.h (private to chain/): the wall's contact law as the chain model
 * evaluates it (chain_wall.c): Hertz or bonded layer elastic law, optionally
 * elastic-plastic (Thornton) or viscoelastic (generalized Maxwell, Lee-Radok).
 */
#ifndef GW_CHAIN_WALL_H
#define GW_CHAIN_WALL_H

#include "gw_chain.h"

typedef struct chain_wall_law {
    double k;                  /* Hertz coefficient (elastic law without a layer) */
    const gw_layer_law *layer; /* elastic law of a layer, or NULL */
    double scale;              /* factor on the elastic law: E_U / E'(band centre) */
    int plastic;
    gw_thornton th;
    int narms;                 /* viscoelastic Maxwell arms (0: elastic) */
    double w_inf;              /* relaxed share E_inf / E_U */
    double w[GW_WALL_MAX_ARMS], tau[GW_WALL_MAX_ARMS];
} chain_wall_law;

/* Set up from p (validated). GW_EINVAL when the loss cannot be reached by the
 * arms (message names the wall's loss). */
int chain_wall_law_init(chain_wall_law *w, const gw_chain_params *p, gw_err *err);
/* Unrelaxed elastic force at overlap d > 0 and its derivative. */
double chain_wall_elastic(const chain_wall_law *w, double d, double *kd);
/* Stored energy of the unrelaxed elastic law at overlap d. */
double chain_wall_elastic_energy(const chain_wall_law *w, double d);
/* Overlap at which the unrelaxed elastic force is f. */
double chain_wall_elastic_overlap(const chain_wall_law *w, double f);
/* Number of Maxwell arms between tau_min and tau_max (one per decade). */
int chain_wall_arms(const gw_chain_wall *wall, double *tau_min, double *tau_max);
/* GW_EINVAL naming damping when p's contact damping has nothing to act on: one
 * body (n = 1, a drop's block) on a layer, plastic or viscoelastic wall, which
 * the damping leaves to its own law (chain_setup.c). A single run's check: a
 * study over a range of N has bead contacts from N = 2. */
int chain_damping_check(const gw_chain_params *p, gw_err *err);
/* 1 when p's damping model has a constant of 0 (kk with gamma 0, hc with
 * alpha 0): no damping at all, the column of damping none. Kept (a sweep over
 * gamma from 0), as restitution 1 is not (refused), but said: a run, study or
 * sweep that names a damping model and damps nothing warns, on stderr and in
 * its warnings. */
int chain_damping_zero(const gw_chain_params *p);
/* 1 when p's contact damping (kk or hc, its constant above 0) is on and bead
 * 1, at velocity v1, has stopped (|v1| below a thousandth of the velocity
 * scale v_scale): a contact damping far above critical holds it inside its
 * overlap, which no longer t-max ends (chain --damping kk --gamma 1e14; the
 * drop's first impact alike). */
int chain_damping_holds(const gw_chain_params *p, double v1, double v_scale);
/* 1 when |v| is below a thousandth of v_scale: bead 1 stopped */
int chain_bead_stopped(double v, double v_scale);
/* The failure of a run whose bead 1 the contact damping holds (GW_ELIMIT, as
 * chain's): "WHO: bead 1 still on the WALL at t_max = T s: the contact damping
 * (damping kk, gamma G N s/m^1.5) stopped it inside its overlap, WHY: lower
 * gamma[ADVICE]" (hc: alpha in s/m). One text for the chain and the drop. */
int chain_damping_held_error(const gw_chain_params *p, const char *who, const char *wall, double t_max,
                             const char *why, const char *advice, gw_err *err);
/* Its warning for a run or a study of p's one damping (nothing when p damps,
 * or is NULL), or for zero of a sweep's total cases (p NULL); GW_OK or
 * GW_ENOMEM (gw_warnings_add). */
int chain_damping_zero_warnings(const gw_chain_params *p, int zero, int total, char **list);
/* The predicted relative effect of p's contact damping on the restitution
 * at its v_imp (kk: gamma v_imp/(k d_max), hc: alpha v_imp; 0 undamped), and
 * the warning of a run whose damping is predicted below its rtol (nothing
 * otherwise), or of n of a sweep's total cases (hi: the largest effect among
 * them). GW_OK or GW_ENOMEM. */
double chain_damping_effect(const gw_chain_params *p);
int chain_damping_small(const gw_chain_params *p, double rtol);
int chain_damping_small_warning(const gw_chain_params *p, double rtol, char **list);
/* The same for a study over nv speeds v (falcon, wavespeed): p at the
 * largest of them, its bead contacts counted. */
int chain_damping_small_study_warning(const gw_chain_params *p, double rtol, const double *v, int nv, char **list);
int chain_damping_small_cases_warning(int n, int total, double hi, char **list);
/* The sensor body's dashpot (its damping ratio) and the guide's friction
 * (its impulse over the collision against the lightest bead's momentum):
 * their predicted relative effects (0 when absent), and the warnings of a
 * run where one is below its rtol. GW_OK or GW_ENOMEM. */
double chain_sensor_damping_effect(const gw_chain_params *p);
double chain_guide_effect(const gw_chain_params *p);
int chain_drag_small_warnings(const gw_chain_params *p, double rtol, char **list);
/* The same rule for a study's columns (falcon, wavespeed, softwall: they
 * said nothing of --sensor-damping 1e-12 before session 43): each column's
 * effects tallied (chain_drag_tally_add: the largest of each, over the
 * columns where the option acts), and a warning when even the largest is
 * below rtol, naming how many columns; a single run's warning is a tally of
 * one (chain_drag_small_warnings). _study_warnings: the columns of sizes
 * n_lo..n_hi at each of nv speeds v from p. GW_OK or GW_ENOMEM. */
typedef struct chain_drag_tally {
    int n_sensor, n_guide;        /* columns where each acts */
    double sensor_hi, guide_hi;   /* the largest effect of each */
    double damping, coulomb, viscous; /* the options, as given */
} chain_drag_tally;
void chain_drag_tally_add(chain_drag_tally *t, const gw_chain_params *p);
int chain_drag_tally_warnings(const chain_drag_tally *t, double rtol, char **list);
int chain_drag_small_study_warnings(const gw_chain_params *p, double rtol, const double *v, int nv, int n_lo,
                                    int n_hi, char **list);
/* The same rule over a sweep's cases (a chain sweep given sensor-damping =
 * 1e-12 on a 1e-2 kg, 1e7 N/m sensor ran in silence before session 44): each
 * case's effects against its own rtol (chain_drag_cases_add, k the case's
 * index), and one warning line for each of the two, counting the cases where
 * it has no effect among total, the largest such effect and the first such
 * case. GW_OK or GW_ENOMEM. */
typedef struct chain_drag_cases {
    long sensor, guide;             /* cases where each has no effect */
    long sensor_first, guide_first; /* the first of them */
    double sensor_hi, guide_hi;     /* the largest effect among them */
} chain_drag_cases;
void chain_drag_cases_add(chain_drag_cases *c, const gw_chain_params *p, double rtol, long k);
int chain_drag_cases_warnings(const chain_drag_cases *c, long total, char **list);
/* A run's energy error above GW_CHAIN_ENERGY_WARN with energy_tol off (0):
 * a warning naming the error and the solver's rtol and atol (rk4: its step),
 * the integration too loose to trust the column's numbers. Nothing when
 * energy_tol is on (the run stops at it instead). GW_OK or GW_ENOMEM. */
#define GW_CHAIN_ENERGY_WARN 1e-3
int chain_energy_warning(double energy_error, double run_dt, const gw_chain_run_opts *o, char **list);
/* A sweep's n of total cases (the first, case first) whose rows say an
 * overlap beyond one radius (hi: the largest, in radii), or an energy error
 * above GW_CHAIN_ENERGY_WARN with energy-tol off (hi: the largest): the
 * single run's warnings, one line over the cases; nothing for n <= 0. */
int chain_overlap_cases_warning(long n, long total, double hi, long first, char **list);
int chain_energy_cases_warning(long n, long total, double hi, long first, char **list);
/* r's chatter on a sensor body as a number (a sweep's chatter column, chain
 * --json "chatter"): 0 none (or a rerun that agreed within 1e-6), the change
 * of eps_eff a rerun at tighter tolerances measured, -1 a run too costly to
 * run again (its spread unmeasured), -2 one whose rerun failed. */
double chain_result_chatter_value(const gw_chain_result *r);
/* A chatter's kind (GW_CHAIN_CHATTER_*) and spread as that number (a drop's
 * own, gw_chain_drop_result's chatter_kind and chatter_spread). */
double chain_chatter_value(int kind, double spread);
/* A stored trace that stopped at its bound (5 GB of files) while the run went
 * on past its last row (chain_trace_cut, chain_trace.c): a warning giving where
 * it stops and naming dt_name (NULL: "--dt-out"); nothing when not cut. */
int chain_trace_cut_warnings(const gw_chain_trace *tr, double t_end, const char *dt_name, char **list);
/* The same rule over a study's sizes from n_lo (falcon, wavespeed, softwall):
 * GW_EINVAL naming damping when n_lo is 1 and p's wall (any n) is such a wall;
 * sheet (may be NULL) names the wall in the message. */
int chain_damping_study_check(const gw_chain_params *p, long n_lo, const char *sheet, gw_err *err);
/* GW_EINVAL naming k, or material, when a single run's setup s gives one body
 * (n_bodies = 1: chain --n 1, a drop of one bead or its block) what acts only on
 * bead contacts: k (the bead-bead coefficient), or the bead material where it
 * would give k alone (mass and the wall's coefficient given, no radii). A
 * study's or a sweep's one-bead column keeps them: they act on its other
 * columns or cases (chain_setup.c). */
struct gw_chain_setup;
int chain_one_body_check(const struct gw_chain_setup *s, int n_bodies, gw_err *err);

#endif
