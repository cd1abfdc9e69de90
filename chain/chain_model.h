/*
 * chain_model.h (private to chain/): the column model's object, shared by the
 * default model (chain_model.c) and the general model with wall laws, the sensor
 * body and guide friction (chain_general.c). Equations in those files.
 */
#ifndef GW_CHAIN_MODEL_H
#define GW_CHAIN_MODEL_H

#include <math.h>

#include "chain_wall.h"

struct gw_chain {
    gw_chain_params p;
    int n;
    double *m, *minv, *kc, *gam; /* masses [n], 1/m [n], k [n-1], gamma [n-1] */
    double kwall, gwall;         /* wall coefficient and its KK constant */
    int uniform;                 /* every kc equal and every minv equal: the lean
                                    loop reads kc[0] and minv[0] only */
    int rhs_avx;                 /* the undamped right-hand side's 4-wide AVX loop
                                    (the CPU has AVX; same values as the SSE2 loop) */
    double *scale;               /* [dim] */
    double e_scale;              /* the energy at the column's speed scale when
                                    gravity sets it above v_imp (sum m v_s^2 / 2,
                                    chain_speed_scale), else 0: the energy
                                    ledger's least scale (chain_energy_rel_error) */
    gw_system sys;
    int general;                 /* any wall law, sensor body or guide option */
    chain_wall_law wl;
    long i_diss, i_work, i_sens, i_dmax, i_q; /* state indices, -1 when absent; i_dmax
                                                 holds the plastic wall's D_max - D */
    double vreg;                 /* Coulomb regularisation speed, m/s */
    double *work;                /* [2 dim] scratch of the force-rate root (chain_force_rate) */
    double dtrack;               /* plastic wall: D_max follows D (dD_max/dt = D' s(x)
                                    for D' > 0, s = x^2 (3 - 2x), x = (D - D_max +
                                    2 dtrack)/dtrack clipped to [0, 1]; the state is
                                    E = D_max - D) so that the switch between
                                    unloading and reloading is C^1, not a jump the
                                    corrector chatters on; a reloading D_max runs
                                    ahead of D by < dtrack, and tracking (D = D_max)
                                    lies on the ramp's flat top, where the implicit
                                    methods' difference quotients see no slope */
};

/* Contact force and dissipated power for overlap d > 0 and rate dd = d'. */
static inline double damped_force(const gw_chain *c, double k, double gam, double d,
                                  double dd, double *pdiss)
{
    double sd = sqrt(d), fel = k * d * sd, f;
    if (c->p.damping == GW_DAMP_KUWABARA_KONO)
        f = fel + gam * sd * dd;
    else
        f = fel * (1.0 + 1.5 * c->p.alpha * dd);
    if (f < 0)
        f = 0;
    *pdiss += (fel - f) * (-dd);
    return f;
}

/* The default model's undamped right-hand side (chain_rhs_lean.c): whole
 * (kinematics 0: the forces' part only, for the implicit split), by beads
 * [j0, j1), and whether the CPU runs its AVX loop. */
void chain_lean_rhs(const gw_chain *c, const double *y, double *yd, double g, int kinematics);
void chain_lean_range(const gw_chain *c, const double *y, double *yd, int j0, int j1, double g);
int chain_lean_avx(void);
/* The bead count's range, [1, 5e7] (gw_chain_params_validate's first rule,
 * and gw_chain_memory_check's, whose sizes hold for such a count only: n =
 * INT_MIN was told it needs 4.4e11 GB, "at most 0 beads", n = -1 passed). */
int chain_n_check(int n, gw_err *err);
/* 1 when p is a column gw_chain_time_scale and gw_chain_step_scale have a
 * value for (chain_model.c), else 0 (their NaN, the RK4 study's not covered) */
int chain_scales_domain(const gw_chain_params *p);

/* General model (chain_general.c). */
double chain_general_wall_force(const gw_chain *c, const double *y, double *kd, double *kv, double *pd);
double chain_guide_force(const gw_chain *c, double v, double *dfdv);
int chain_general_rhs(double t, const double *y, double *yd, void *P);
int chain_general_rhs_ex(double t, const double *y, double *yd, void *P);
int chain_general_rhs_im(double t, const double *y, double *yd, void *P);
int chain_general_roots(double t, const double *y, double *g, void *P);
/* A function of the state with the sign of dF/dt, F the force the sensor reads
 * (gw_chain_wall_force), continuous through contact changes: the chain's root
 * gw_chain_force_max_root, whose falling zeros with the wall contact closed are
 * the maxima of F. See chain_model.c. */
double chain_force_rate(const gw_chain *c, double t, const double *y);
/* 1 when the roots reported at state (t, y) (gw_solver_advance's) need the
 * solver restarted: one of them marks a change in the model's smoothness (a
 * contact opening or closing, the overlap rate that switches a plastic wall's
 * tracking), or an event function is exactly 0 there. 0 when only the
 * force-maximum root (gw_chain_force_max_root) fell or rose: the model is as
 * smooth there as on either side. See chain_model.c. */
int chain_roots_need_reset(const gw_chain *c, double t, const double *y, const int *roots);
void chain_general_energy(const gw_chain *c, const double *y, gw_chain_energy *e);
/* The beads' own energies at state Y: kinetic, Hertz elastic of the bead
 * contacts, gravitational (the walls and sensor are the caller's). */
void chain_beads_energy(const gw_chain *c, const double *y, double *ke, double *el, double *pg);

/* The decay rates c/m, 1/s, of the column's linear drags, each on the body it
 * slows (r[CHAIN_DRAG_SENSOR]: the sensor body's damping c_s/M; the guide's
 * viscous and regularised Coulomb friction and the contact damping at the
 * binary overlap: on the lightest bead); 0 where there is none.
 * chain_drag_flag names the option that sets each. */
enum { CHAIN_DRAG_SENSOR, CHAIN_DRAG_GUIDE_VISCOUS, CHAIN_DRAG_GUIDE_COULOMB, CHAIN_DRAG_CONTACT, CHAIN_DRAG_N };
extern const char *const chain_drag_flag[CHAIN_DRAG_N];
void chain_drag_rates(const gw_chain_params *p, double r[CHAIN_DRAG_N]);

/* RK4's default step, s: gw_chain_step_scale(p) / steps_per_tc (400 when
 * <= 0), and at most c_s/M's inverse, within RK4's stability on the sensor
 * body's drag (chain_collide_plan.c). */
double chain_rk4_default_dt(const gw_chain_params *p, double steps_per_tc);

/* A drag decays at rate r: the explicit methods (cvode adams, arkode erk)
 * hold their step within their stability on it, about r t_len steps (the
 * stiff ones, cvode bdf and arkode dirk and imex, step over it), and RK4's
 * default step is set by it where it is the shortest. Counted over t_len,
 * or t_run (the run's t-max) for a guide friction that stops a bead within
 * t_len (bead 1 then stays on the wall to t-max). Bounded at 1e8 before the
 * run; GW_EINVAL naming the drag's option (chain_drag_flag) and the solver
 * to use otherwise. given holds the steps the caller asked for (rk4: a dt
 * given is chain_steps_check's). */
int chain_drag_steps_check(const gw_chain_params *p, const gw_solver_type *type, const gw_solver_params *sp,
                           const gw_solver_params *given, double steps_per_tc, double t_len, double t_run,
                           const char *over, gw_err *err);

/* What the run cap's message (a run past 2e8 steps, chain_collide.c) advises
 * for a run of type with method (GW_METHOD_DEFAULT resolved): rk4 "use
 * cvode", cvode adams and arkode erk its bdf, the implicit methods looser
 * tolerances. A static text. */
const char *chain_cap_advice(const gw_solver_type *type, int method);

/* cvode and arkode follow a sensor body's oscillation (omega = sqrt((k_s + the
 * stiffness of bead 1's contact)/M)) at 7 to 37 steps a radian at 1e-12
 * (measured; fewer at looser tolerances of sp): 20 omega t_len steps there,
 * bounded at 1e8 before the run; GW_EINVAL naming sensor-stiffness. rk4: GW_OK
 * (its step is chain_steps_check's). */
int chain_sensor_steps_check(const gw_chain_params *p, const gw_solver_type *type, const gw_solver_params *sp,
                             double t_len, const char *over, gw_err *err);

/* cvode adams and arkode erk on a sensor body that rings far faster than the
 * collision: held to its ring by their stability (about 2.3 steps a radian
 * for erk, 5.2 for adams, whatever the tolerance), whose errors they leave
 * undamped in it. Beyond 5e5 radians of sqrt((k_s + the contact's
 * stiffness)/M) over t_len, for a ring more than 1e3 times the beads'
 * shortest contact's pi/tau, GW_EINVAL naming sensor-stiffness and the implicit
 * methods (chain_collide_plan.c gives the measurements); GW_OK for the
 * implicit methods and rk4. */
int chain_ring_explicit_check(const gw_chain_params *p, const gw_solver_type *type, const gw_solver_params *sp,
                              double t_len, const char *over, gw_err *err);

/* The beads' momentum toward the wall at state y, kg m/s; *mass (may be
 * NULL) their total mass, kg. */
double chain_momentum(const gw_chain *c, const double *y, double *mass);
/* A column fallen back onto the wall, watched from one state to the next: 1
 * when q, its momentum toward the wall, is at or above 0 after it was below
 * -1e-3 q_scale (turned away by the impact beyond the solver's noise about
 * rest: arkode dirk's momentum of a bead an overdamped contact stopped
 * crossed 0 by 1e-12 of its scale, and read as a fall back, where cvode's
 * stayed positive); *q_min: the lowest q so far (start at 0). q_scale: the
 * column's mass times its speed scale. */
int chain_fell_back(double *q_min, double q, double q_scale);

/* A collision's wall_pending (gw_chain_result) when the run stopped because the
 * column fell back onto the wall before its collision ended (chain_collide.c,
 * held_by_gravity); its warning (chain_warnings.c) names gravity and vimp. */
extern const char chain_held_pending[];

/* Room for the column's pending text kept after a result's velocity arrays
 * (gw_chain_collide allocates final_v with 4 n doubles and this many bytes). */
#define CHAIN_PENDING_TEXT 192
/* What kept the column's own contacts from ending a run cut at t_max ("bead 3
 * still against bead 4", "beads 5 and 6 closing, to meet at about t = 0.278 s",
 * and how many more act); "" when nothing did, or for a result that converged or
 * that gw_chain_collide did not fill. Valid until gw_chain_result_free. */
const char *chain_result_column_pending(const gw_chain_result *r);
/* Room for the chatter's text after the pending text (CHAIN_CHATTER_TEXT
 * bytes): bead 1 that chattered on a sensor body and the spread a rerun at
 * tighter tolerances measured (chain_collide.c, chatter_spread); "" when none.
 * Its kind and spread are the result's chatter_kind and chatter_spread. */
#define CHAIN_CHATTER_TEXT 512
const char *chain_result_chatter(const gw_chain_result *r);
/* The tolerances the collision r ran at into *rtol, *atol (its run_rtol and
 * run_atol): 1, or 0 where they are not both positive (rk4's NaN, a result
 * filled by hand). The drop's library warning names its chatter's rerun by
 * them: its first collision ran at the drop's (chain_drop.c). */
int chain_result_tolerances(const gw_chain_result *r, double *rtol, double *atol);
/* The one text of bead 1's chatter on a sensor body into buf: "bead 1
 * chattered on the sensor body (its wall contact closed CONTACTS times WHERE):
 * the chatter amplifies the integration's error, ENDING" (where "" or, say,
 * "over the drop"; ending the run's: a rerun's spread, or why none). */
void chain_chatter_text(char *buf, size_t size, int contacts, const char *where, const char *ending);
/* The rerun of a chattering run, for its text: "rtol R, atol A" (how) and
 * "--rtol R --atol A" (flags), or rk4's step halved ("rk4's step halved, DT
 * s", "--dt DT (half the step)"); the tighter settings into *sp. */
void chain_chatter_rerun(const gw_solver_type *type, double step, gw_solver_params *sp, char *how, size_t how_size,
                         char *flags, size_t flags_size);
/* How far a run at the default t_max t_default (20 expected lengths) goes on
 * when it has not ended there (chain_collide.c, extend_run), sampled at dt_ext
 * past it, for n beads: t_default plus at most 49 t_default, 5e6 samples and,
 * stored (a sample callback), 1.25e8 values of the trace (2 n + 2 a sample), s. */
double chain_extend_bound(double t_default, double dt_ext, int n, int stored);

/* A collision stopped so (its wall_pending is chain_held_pending): its values
 * are those of that time, and the studies leave it out of what they derive. */
static inline int chain_result_held(const gw_chain_result *r)
{
    return r->wall_pending == chain_held_pending;
}

/* The warning of a study with held of its total collisions stopped so
 * (chain_held_pending), appended to *list; nothing when held is 0. left_out
 * names what the study derives without them ("the fits over N"); undecided
 * (NULL or "": nothing) what they leave without enough decided columns ("T_q
 * at v_imp = 0.3 m/s (fewer than two decided columns)"). GW_OK or GW_ENOMEM.
 * Their unfinished count includes them: the studies' "raise --t-max" warning
 * counts the others only. */
int chain_held_warnings(int held, int total, const char *left_out, const char *undecided, char **list);
/* The first size of the F_max plateau of the columns r[0..n_hi-n_lo] (sizes
 * n_lo..n_hi), by the soft-wall study's rule (N_d, or the first size run when
 * the plateau reaches back to it); -1 when F_max is not on a plateau by n_hi
 * or held columns leave it undecided. */
int chain_plateau_first(const gw_chain_result *r, int n_lo, int n_hi, double tol);
/* Why the wave-speed estimators may disagree, at the speed where they
 * disagree most (chain_wave_study.c fills it, chain_wavespeed_warnings words
 * it): iv that speed (-1: none decided); soft 1 when the wall is softer than
 * K_c and columns lie below the F_max plateau (plateau its first size, -1 not
 * reached by n_hi; f_lo, f_hi F_max of the shortest and longest column;
 * n_d_min the F.8 bound ceil(tau_max(n_hi)/T_q) at the analytic T_q);
 * tq_scatter the rms residual of tau_N about its line over T_q. */
struct gw_chain_wavespeed_outcome;
typedef struct chain_ws_cause {
    int iv, soft, plateau, n_d_min;
    double f_lo, f_hi, k_c, tq_scatter;
} chain_ws_cause;
/* The wave-speed study's own warnings, appended to *list: the period null at
 * speeds whose columns were not held (none of 10 beads or more, or none with
 * two wall-force maxima), and estimators disagreeing beyond what a rigid wall
 * shows, naming the cause c where known. GW_OK or GW_ENOMEM. */
int chain_wavespeed_warnings(const struct gw_chain_wavespeed_outcome *o, const gw_chain_params *p, const chain_ws_cause *c,
                             char **list);
/* gw_chain_drop_result_warnings with the drop's column p (NULL: not named):
 * a bead 1 at rest on the sensor at t_max (the column's kinetic energy below
 * a millionth of e0, bead 1 stopped as chain_bead_stopped has it) is held
 * there by its weight, and no t-max ends its last contact: said so, naming p's
 * contact damping (which took its rebound), instead of "raise --t-max". The
 * drop's chatter on a sensor body (chatter_kind) names its rerun by o's solver
 * and tolerances (NULL: by the rule, rk4's step or the tolerances). */
int chain_drop_warnings(const gw_chain_drop_result *r, const gw_chain_params *p, const gw_chain_run_opts *o,
                        char **list);
/* Runs whose step was below the dt given (gw_chain_result's run_dt under
 * run_dt_given: above dt_max, or rk4's dt_out), tallied over the runs of one
 * command, a study or a sweep, so that one warning line says how many: a
 * thousand-case study gave none, and one a run would flood stderr. */
typedef struct chain_dt_tally {
    double given_lo, given_hi; /* the dt given of the runs above their step, s */
    double taken_lo, taken_hi; /* the steps they took, s */
    int over, total;           /* runs above their step, of the runs tallied */
    int at_out;                /* of over, those whose step was rk4's dt_out (below dt_max) */
    int overlap_over;          /* runs whose largest overlap passed the bead radius */
    double overlap_hi;         /* the largest of their overlaps, in bead radii */
    int chatter[4];            /* runs by their chatter's kind (GW_CHAIN_CHATTER_*; [0] unused) */
    int chatter_contacts;      /* the most wall contacts of a chattering run */
    double chatter_spread;     /* the largest spread a rerun measured */
    double chatter_work;       /* the largest work of a run too costly to run again */
    const gw_solver_type *solver; /* the runs' solver (the reruns' wording: rk4's step or the
                                     tolerances), set by the study; NULL: not known */
    double rtol, atol;         /* the runs' tolerances, set by the study (the reruns' values:
                                  10 times looser at the 1e-15 floor); 0: not known */
} chain_dt_tally;
/* One run into t: given the dt given (0: none), taken the step it took,
 * dt_max its largest step (s). t starts zeroed. */
void chain_dt_tally_add(chain_dt_tally *t, double given, double taken, double dt_max);
/* The run's or runs' one warning line appended to *list, nothing when none
 * ran above its step: name is the dt's name for the reader ("--dt" of a
 * command, whose settings record the step taken; a sweep's key "dt", whose
 * table records the dt given), what the runs ("collisions", "cases"; a single run, total 1, says
 * "the run"). GW_OK or GW_ENOMEM. */
int chain_dt_tally_warnings(const chain_dt_tally *t, const char *name, const char *what, char **list);
/* The tally of the collisions res[0..n-1] (their run_dt_given, run_dt,
 * run_dt_max) added to t. */
void chain_dt_tally_results(chain_dt_tally *t, const gw_chain_result *res, long n);
/* A run's largest contact overlap (overlap_max_rel, bead radii) into t, whose
 * warnings then also say how many of its runs passed one radius (chain and
 * drop say it of their one run; falcon, wavespeed and softwall said nothing
 * of collisions pressed 300 radii deep). chain_dt_tally_results adds it. */
void chain_dt_tally_overlap(chain_dt_tally *t, double overlap_rel);
/* Runs whose bead 1 chattered on a sensor body, in one line with their count
 * (chain_dt_tally_warnings says it of a study's tally, a sweep of its rows'
 * chatter column): moved, costly, failed by kind (GW_CHAIN_CHATTER_*) of total
 * runs named what, the most wall contacts, the largest spread measured and
 * the largest work not run again; first "" or "; the first, case K". The
 * reruns of the moved ones, bits: CHAIN_RERUN_TOL (10 times tighter
 * tolerances), CHAIN_RERUN_LOOSE (10 times looser: a tolerance at the 1e-15
 * floor, chain_chatter_rerun), CHAIN_RERUN_STEP (rk4's step halved); rtol and
 * atol the moved runs' own tolerances where they are one setting (their
 * reruns' values named), else 0. A study at rtol = atol = 1e-15, whose reruns
 * were made at 1e-14, said "10 times tighter tolerances" (session 45). */
enum { CHAIN_RERUN_TOL = 1, CHAIN_RERUN_STEP = 2, CHAIN_RERUN_BOTH = 3, CHAIN_RERUN_LOOSE = 4 };
int chain_chatter_cases_warning(long moved, long costly, long failed, long total, int contacts, double spread,
                                double work, int rerun, double rtol, double atol, const char *what, const char *first,
                                char **list);
/* Whether chain_chatter_rerun makes the tolerances rtol, atol 10 times looser
 * (one of them at the floor GW_TOL_MIN) rather than tighter */
int chain_chatter_looser(double rtol, double atol);

/* Append speed v to the list in buf ("0.3, 6.16"; "..." once it is full),
 * counting in *count. */
void chain_list_speed(char *buf, size_t size, int *count, double v);

/* rc, and err's message naming max-steps when rc is the solver's own step
 * limit (GW_ELIMIT from s: more than sp->max_steps steps between two outputs
 * or events), which the backends' texts ("mxstep steps taken before reaching
 * tout", "rk4: more than 5 steps before ...") said without naming the input
 * (chain --max-steps 5, drop, the studies and Python alike). A limit of the
 * run's own (t_max, its step bound: their own texts) is left as it is. */
int chain_step_limit_named(int rc, const gw_solver *s, const gw_solver_params *sp, gw_err *err);

/* GW_ESOLVER when the run has blown up (a step too long for the stiffest
 * contact): a state not finite, or a relative energy error above 1; the message
 * starts "WHO: the solution blew up at t = ..." and says which. GW_OK otherwise.
 * The energy monitor alone misses it: a NaN error never exceeds the largest so
 * far. */
int chain_blown_up(const gw_chain *c, const double *y, double energy_error, const gw_solver_type *type,
                   const char *who, double t, gw_err *err);

/* The relative energy error of column c's energies e against the initial
 * total e0 (J): |E - e0| over the energy the run has held, e0 plus the largest
 * work gravity has done on the column so far (*wg, J, updated: max of
 * -e->gravity, 0 at the start), and at least c->e_scale. Without gravity the
 * scale is e0 itself, bit for bit. Over e0 alone, a column set on the wall
 * slowly under gravity (v_imp 1e-6 m/s, where gravity puts 1e8 times e0 into
 * motion) read an error of 1e-8 of its energy as 1 and was stopped as blown
 * up; over e0 + wg alone, its first steps, before gravity had done any work,
 * read an error of 4.6e-22 J as 2.3e-4 (--n 30 --gravity 1e4 --vimp 1e-9,
 * CVODE at t = 8.1e-13 s, where the run's energy is 0.1 J). */
double chain_energy_rel_error(const gw_chain *c, const gw_chain_energy *e, double e0, double *wg);
/* The speed the column's time scales and the states' tolerance scales are
 * taken at: v_imp, or under gravity the larger speed whose wall collision
 * peaks at the column's weight (chain_model.c). */
double chain_speed_scale(const gw_chain_params *p);

/* The shortest binary contact time tau_1 (gw_chain_tau1) at relative speed v over
 * the column's contacts: every pair of beads (reduced mass, its coefficient) and
 * bead 1 on the wall (on the sensor body: their reduced mass). */
double chain_contact_tau_min(const gw_chain_params *p, double v);

/* The period, s, at which the column's fastest bead rings on its contacts when
 * they carry the largest force the column's energy can make (chain_model.c);
 * INFINITY without contacts. Over the collision's expected length it counts the
 * oscillations cvode and arkode follow: a light bead held between the wall and
 * heavy beads rings for the whole of their contact (chain_collide_plan.c);
 * *fastest (may be NULL) is that bead's index. */
double chain_ring_period(const gw_chain_params *p, int *fastest);

/* cvode's and arkode's work over a light bead that heavy beads hold (per-bead
 * masses only: radii), bounded before the run
 * (chain_collide_plan.c): the oscillations of chain_ring_period over t_len seconds
 * at about 260 steps each (rtol 1e-12; (tol/1e-12)^-0.11 at tol = the looser of
 * rtol and atol), times the beads, at most 2e7 when they are more than 100 per
 * bead transit (2n + 1 over the collision's expected length t_col, s, the
 * plan's n 2 T_c + tau_1 as chain_held_check takes it); GW_EINVAL naming radii
 * and "... over OVER (about T s)". rk4 and equal beads (p->masses NULL or all
 * the same): GW_OK. Called by the collision's plan (gw_chain_run_check, so
 * chain, sweeps, studies and Python), not the drop. */
int chain_ring_check(const gw_chain_params *p, const gw_solver_type *type, const gw_solver_params *sp,
                     double t_len, double t_col, const char *over, gw_err *err);

/* A column that gravity holds on the wall (g t_col > v_imp: gravity takes back
 * the impact speed within the collision's expected length t_col) bounces on it
 * until t_max: its samples at the finer of dt_out and tau1/200 over t_max,
 * times the beads, at most 1e7 (chain_collide_plan.c); GW_EINVAL naming gravity,
 * vimp and t-max otherwise. Called by the collision's plan. */
int chain_held_check(const gw_chain_params *p, double t_max, double t_col, double tau1, double dt_out, gw_err *err);

/* Samples over the collision's expected length t_expect at dt_out: more than
 * 3e6 and more than 1e4 per bead transit (2n + 1 over the collision) is
 * GW_EINVAL naming dt-out (given: 1 when the caller chose it, 0 for the
 * default tau_1/200) and the interval that passes (chain_collide_plan.c);
 * over names the span ("the collision"), why (NULL: a stiff wall on soft
 * contacts) says what makes the default's collision long. */
int chain_sampling_check(int n, double t_expect, double dt_out, int given, const char *over, const char *why,
                         gw_err *err);

/* One column's work (chain_collide_plan.c): N^2 times the share of its
 * collision the run covers (t_expect / t_col, at most 1: the collision's
 * expected length t_col as the plan and the progress line take it) at most
 * GW_CHAIN_STUDY_WORK_MAX, the studies' bound (N = 1414 over a whole
 * collision); GW_EINVAL "NAME: a column of N beads over OVER (about T s) is W
 * bead^2 of work ...: lower NAME[, or T_MAX_NAME to run only the collision's
 * start]" otherwise. name is the caller's parameter for N ("n" in the plan,
 * so chain, drop, sweeps and Python; "column-n" in dispersion's column),
 * t_max_name the one that cuts the run (NULL: none). Checked by the plan
 * before a run allocates, and by dispersion's column before it creates one. */
int chain_column_work_check(long n, double t_expect, double t_col, const char *over, const char *name,
                            const char *t_max_name, gw_err *err);
/* The drop's column's work (chain_drop.c): its first collision over the
 * t_max followed after the first contact, p the column arriving at its impact
 * speed (p->v_imp = sqrt(2 g h)), named n and t-max: drop --n 100000 ran for
 * days. The drop study checks it before the written trace's bound (so that
 * --out does not turn it into "run without storing it"), the run before it
 * allocates. */
int chain_drop_work_check(const gw_chain_params *p, double t_max, gw_err *err);
/* The run's steps bounded before it starts (chain_collide_plan.c): the RK4 step
 * (the smaller of dt and dt_max), or cvode's and arkode's largest step dt_max,
 * may need at most 1e8 steps over t_len seconds; GW_EINVAL naming dt or
 * dt-max ("... over OVER (about T s)") otherwise; given holds the steps the caller
 * asked for (0: the run's default), which the advice follows. */
int chain_steps_check(const gw_solver_type *type, const gw_solver_params *sp, const gw_solver_params *given,
                      double t_len, const char *over, gw_err *err);

/* The steps a run of column p is expected to take over its collision, from the
 * same plan as gw_chain_run_check (GW_EINVAL and its message when that refuses):
 * the collision's expected length over the RK4 step, or over cvode's and
 * arkode's largest step and at least 2 a radian of a sensor body's oscillation
 * and the steps a drag holds an explicit method to (chain_drag_steps_check).
 * Studies add them up over their columns (chain_sweep.c). */
int chain_run_steps(const gw_chain_params *p, const gw_chain_run_opts *o, double *steps, gw_err *err);

/* The step a run of column p takes (*dt, its result's run_dt) and its
 * largest step (*dt_max, run_dt_max), s, from the same plan as
 * gw_chain_run_check (GW_EINVAL and its message when that refuses), before
 * it runs: a sweep says which of its cases run at a step below their dt. */
int chain_run_step(const gw_chain_params *p, const gw_chain_run_opts *o, double *dt, double *dt_max, gw_err *err);

/* gw_chain_collide for the drop's first collision: a column falling back on
 * the wall is not stopped as held (the drop follows its bounces: chain_collide.c,
 * held_by_gravity). flight_cut 1: a run whose t_max falls in bead 1's flight
 * after it left the wall, its return being the caller's next impact (cut half
 * way through that flight): bead 1 off the wall counts as done (wall_done, the
 * warnings) whatever the sign of its velocity, which at the flight's midpoint
 * is zero but for the integration's error. */
int chain_collide_drop(const gw_chain *c, const gw_chain_run_opts *o, int flight_cut, gw_chain_result *r,
                       gw_err *err);
/* The bounds chain_collide_drop will check on its plan that do not depend on
 * the t_max it is given (o's t_max, the drop's, is an upper bound), checked
 * before the drop runs: its first collision's plan (a light bead ringing
 * between heavy ones, chain_ring_check; the sampling, the steps) refused the
 * run only after the whole drop, about 23 s for --n 3 --radii
 * 4e-3,1e-6,4e-3. GW_EINVAL naming the bound. */
int chain_collide_drop_check(const gw_chain *c, const gw_chain_run_opts *o, gw_err *err);
/* The first collision's bound of a column held on the wall by gravity
 * (chain_collide_held_t, on the chain's own masses): the t beyond which its
 * t_max is refused (INFINITY: not held), and that refusal at o's t_max. The
 * drop's first collision runs to at least the end of bead 1's first contact:
 * a drop whose bead 1 is still on the sensor past that t is refused there,
 * not after the whole drop (drop --n 1500: 27 s of CPU). */
double chain_collide_drop_held_t(const gw_chain *c, const gw_chain_run_opts *o);
int chain_collide_drop_held_refuse(const gw_chain *c, const gw_chain_run_opts *o, gw_err *err);

/* Half the period of the column's mass and a sensor body's M on the sensor's
 * spring, pi sqrt((sum m + M) / k_s), s: the time a column heavier than the
 * body rides the spring (the bead contacts and the wall's are stiff beside a
 * soft spring, so the column moves as one on it); 0 on a rigid sensor. Measured
 * at n = 3 (6.3 g) on 1e3 N/m: bead 1's last wall contact ended at 7.893 ms
 * against 7.894 ms on 1e-7 kg, at 0.57 to 0.97 of it on 1e-4 to 3e-2 kg (the
 * run's end, the beads' own contacts parted, up to 15 times later: within the
 * default t_max's 20; beads leaving nearly together that meet again later
 * still are not counted: n = 10 on 0.03 kg and 1e4 N/m ends at 39 times it);
 * a body of 0.1 kg and more sends the column back at
 * once, and the run ends at its reading's peak, a quarter of its period, half
 * of this time. */
double chain_sensor_carry_time(const gw_chain_params *p);

/* The collision's expected length, s: n bead-to-bead transits of 2 T_c (the
 * largest T_c = (m/k)^(2/5) v^(-1/5) over the contacts, each with the heavier
 * of its two beads), the wall contact time tau_1 (F.2) of the heaviest bead
 * (for equal beads gw_chain_time_scale and bead 1's tau_1) and the
 * column's ride on a sensor body's spring (chain_sensor_carry_time; 0 on a
 * rigid sensor). The default t_max is 20 of it (chain_collide_plan.c); the
 * column's largest T_c in *tc (may be NULL). Before the ride was counted, a
 * column on a soft sensor spring (--n 3 --sensor-mass 1e-7 --sensor-stiffness
 * 1e3, 7.9 ms) was cut at the default t-max 2.2 ms with eps_eff -0.64. */
double chain_collision_length(const gw_chain_params *p, double *tc);

/* The drop's fall to the first contact is free fall in closed form: guide
 * friction (Coulomb or viscous, N and N s/m per bead) would slow it and is
 * refused, GW_EINVAL naming guide-friction or guide-viscous (chain_drop.c). */
int gw_chain_drop_guide_check(double coulomb, double viscous, gw_err *err);

/* gw_chain_collision_run with progress(pctx, ...) (may be NULL) at every
 * sample and event of the collision (gw_chain_collide_progress): the same
 * results, bit for bit (a sweep case's progress, chain_sweep_model.c). */
struct gw_chain_setup;
struct gw_chain_collision;
int chain_collision_run_progress(const struct gw_chain_setup *s, struct gw_chain_collision *out,
                                 gw_chain_progress_fn progress, void *pctx, gw_err *err);

/* A collision's end as the column's state says it, updated before each
 * progress report (chain_collide_progress_end; granwave chain's lines): once
 * bead 1 is off the wall and every contact open, t_end is when the last
 * closing pair will have met (t_meet) and parted, or the time then when none
 * closes; both 0 before (the run's own end often comes well past its expected
 * length: chain --n 600 at 7.6 times it). */
typedef struct chain_column_end {
    double t_end;  /* s; 0 while unknown */
    double t_meet; /* s; 0 when no pair closes */
} chain_column_end;
/* gw_chain_collide_progress that also keeps *end (may be NULL) as above: the
 * same results, bit for bit (the end is read from the state, never fed back). */
int chain_collide_progress_end(const gw_chain *c, const gw_chain_run_opts *o, gw_chain_progress_fn progress,
                               void *pctx, chain_column_end *end, gw_chain_result *r, gw_err *err);

/* chain_trace.c: a gw_chain_trace as the calls that read it need it (tr
 * given, n >= 0, len <= cap, t and f given when len > 0, x and v too when n >
 * 0): GW_OK, or GW_EINVAL "CALL: ..." naming the fields. */
int chain_trace_check(const gw_chain_trace *tr, const char *call, gw_err *err);
/* The stored trace's bound, 5 GB of files (gw_chain_trace_check before the run;
 * gw_chain_trace_sample stores no row past it during the run): bytes <= 0
 * restores 5e9. For tests, which reach it in a small run; not thread-safe. */
void chain_trace_limit_set(double bytes);
/* The rows of n beads within that bound. */
double chain_trace_rows_max(int n);
/* 1 when tr holds that many rows and its last is before t_end: the run went on
 * past the rows stored (a default run that has not ended goes on past its
 * expected length, which the check before the run covers). */
int chain_trace_cut(const gw_chain_trace *tr, double t_end);

#endif
