/*
 * gw_layer_study.h: a block impact on a 2D granular layer as a library call
 * with its parameters described once (gw_param.h).
 *
 * gw_layer_impact_setup holds the inputs of `granwave layer-impact`: the
 * sample file, the materials (Hertz-Mindlin contacts, physics.md 2.1), the
 * block (R_b = rb-rm R_m, V_i, incidence alpha_i; B.5, B.6), the run and the
 * solver (the fast default: verlet with its step from the shortest binary
 * contact time; exact: RK4 stopping at every contact event). Its table
 * (gw_layer_impact_setup_params) gives each field's name (the command's flag;
 * Python keywords write '-' as '_'), unit, range, default and help.
 * gw_layer_impact_run reads the sample, resolves the setup as the command does
 * (the sample's mass law and clump mass unless given) and runs gw_layer_impact;
 * its results (gw_layer_impact_outcome) have a table too, with the time series
 * (ledger B.7-B.14, block, crowns, the crowns' cross-correlation and spectra)
 * as arrays, and, when asked for (snapshots), the particles' states at given
 * times: what `layer-impact --json` prints and its --out files (CSV, VTK) hold.
 *
 * Errors: GW_EINVAL "NAME: reason" naming the parameter; the sample reader's
 * GW_EIO / GW_EFORMAT naming the file; solver failures with their message.
 * SI units, angles in degrees.
 */
#ifndef GW_LAYER_STUDY_H
#define GW_LAYER_STUDY_H

#include "gw_layer.h"
#include "gw_param.h"

#include "gw_api.h"

GW_BEGIN_DECLS /* the exported interface, C linkage (gw_api.h) */

typedef struct gw_layer_impact_setup {
    char *sample;          /* sample file from layer-make (required), owned */
    double friction;       /* phi, deg in [0, 90) [30] */
    double shear_modulus;  /* G, Pa [40e9] */
    double poisson;        /* nu [0.25] */
    double density;        /* kg/m^3 [2650] */
    double gravity;        /* m/s^2 [9.81] */
    double skin;           /* contact-list skin, m [0.1] */
    int mass_law;          /* disc, sphere (choice) [-1: the sample's] */
    int clump_mass;        /* sum, union (choice) [-1: the sample's] */
    double rb_rm;          /* block radius in R_m [1] */
    double vi;             /* incident speed, m/s [20] */
    double alpha;          /* incidence from the normal, deg [0] */
    double x;              /* impact abscissa from the box centre, m [0] */
    double height_rm;      /* mobile layer height in R_m [0 = all] */
    double gap;            /* initial block-target gap, m (optional: NaN not given, so that a
                              gap given at the default's value is told from none) [1e-6] */
    double t_max;          /* s [2] */
    double dt_out;         /* s [2e-5] */
    double ring_width;     /* crown width, m [0 = 2 R_m] */
    long rings;            /* crowns [12] */
    int solver;            /* verlet, rk4, cvode, arkode (choice) [-1: verlet, rk4 if exact] */
    int method;            /* default, bdf, adams, erk, dirk, imex (choice) [default] */
    double dt;             /* fixed step of verlet or rk4, s [0 = auto] */
    int exact;             /* stop at every contact and stick/slip event [0] */
    double rtol, atol;     /* cvode/arkode tolerances [1e-8] */
    double energy_tol;     /* stop when the ledger closure exceeds it [0 = off] */
    int remove_walls;      /* no walls from the impact on [0] */
    int side_walls;        /* both, left, right, none (choice, GW_LAYER_SIDES_*): the side
                              walls kept over the floor [both] */
    int full;              /* run to t-max after the outcome is decided [0] */
    int until;             /* rebound, verdict (choice, GW_LAYER_UNTIL_*; optional: -1 not given) [rebound] */
    gw_param_list snapshots; /* times, s, of particle snapshots (library only, no
                                flag of the command) [none: off] */
    int other_settling;    /* run a sample whose recorded settling leaves its pile away
                              from rest under this material (gw_layer_impact_settled_check),
                              with a warning [0: refused] */
    int zero_springs;      /* start every contact's tangential spring at zero, whatever the
                              sample carries (gw_layer_impact_params.zero_springs) [0] */
} gw_layer_impact_setup;

/* The table of gw_layer_impact_setup (static, NULL-terminated). */
const gw_param *gw_layer_impact_setup_params(void);
/* Defaults from the table; free with gw_layer_impact_setup_clear. GW_OK. */
int gw_layer_impact_setup_init(gw_layer_impact_setup *s);
void gw_layer_impact_setup_clear(gw_layer_impact_setup *s);

/* The energy ledger's columns in gw_layer_energy order (the arrays ledger and
 * regions of gw_layer_impact_outcome hold 8 of them per row). */
#define GW_LAYER_ENERGY_COLUMNS \
    "kinetic_block,kinetic_soil,strain_normal,strain_tangent,mindlin_excess,dissipated,potential,total"

/* One impact: gw_layer_impact's result and what the command derives from it. */
typedef struct gw_layer_impact_outcome {
    gw_layer_impact_result r;
    double rm;             /* the sample's R_m, m */
    double penetration_rm; /* penetration / R_m */
    double froude;         /* V_i / sqrt(2 g R_b) (B.15) */
    double a_total;        /* ledger total at the start, A, J */
    int nregions;          /* rows of regions: nrings + 2 */
    int mass_law;          /* the law used (GW_LAYER_MASS_*) */
    int exact;
    double dt;             /* fixed step used, s (0 for cvode/arkode) */
    char *undecided;       /* r.undecided, NULL when "" (owned) */
    char *warnings;        /* gw_layer_impact_result_warnings of r: the undecided text
                              as a line (owned; NULL: none) */
    int nxcorr;            /* entries of r.xcorr_delay and r.xcorr_rho listed:
                              nrings - 1 (pairs k, k + 1), 0 without the analysis */
    /* Snapshots (setup's snapshots; none by default): snapshot j is the state at
     * the first output sample at or after the j-th time asked for, or the end
     * state when the run ended before it (snap_t says which time it is). */
    int nsnap;             /* snapshots: the number of times asked for */
    int nparticles;        /* particles in each: the sample's discs, then the block */
    int block_index;       /* the block's index among them (nparticles - 1), -1 without snapshots */
    int snap_rows;         /* nsnap * nparticles */
    double *snap_t;        /* [nsnap] s; owns one allocation with snap and particle_r */
    double *snap;          /* [snap_rows][6] per particle x, y (m), theta (rad), vx, vy (m/s),
                              omega (rad/s), as gw_layer_particle */
    double *particle_r;    /* [nparticles] radius, m */
    char *sample_fnv1a64;  /* the sample's content hash (gw_layer_sample.content_hash)
                              as 16 hex digits, owned */
    int crowns_nulled;     /* the rules that nulled a crown speed, each said by a
                              warning: GW_LAYER_NULLED_* bits (0: none) */
} gw_layer_impact_outcome;

/* gw_layer_impact_outcome.crowns_nulled: a crown speed (wave_speed,
 * wave_speed_kinetic, wave_speed_xcorr) left null by the sampling (--dt-out
 * too coarse, or the first impact sampled under 4 times), by the run's end
 * before the wave reached 3 rings, as following the pile's slow motion
 * (locked), or by its scatter (standard error at or above half the speed). */
#define GW_LAYER_NULLED_SAMPLING 1
#define GW_LAYER_NULLED_CUT 2
#define GW_LAYER_NULLED_LOCKED 4
#define GW_LAYER_NULLED_SCATTER 8

/* The table of gw_layer_impact_outcome's results. */
const gw_param *gw_layer_impact_outcome_fields(void);

/* Read s->sample, resolve s and run the impact into out (zeroed first; free
 * with gw_layer_impact_outcome_free also after a failure). No files are written.
 * Returns GW_OK, GW_EINVAL (setup), the sample reader's status, or the run's. */
int gw_layer_impact_run(const gw_layer_impact_setup *s, gw_layer_impact_outcome *out, gw_err *err);
/* The same with progress(pctx, done, total) in output samples (total: the
 * samples up to t-max; the run usually ends earlier, at T_f, with a last call
 * done = total), about a thousand calls; a non-zero return stops the run with
 * GW_ECANCELED (out then freed as after any failure). */
int gw_layer_impact_run_progress(const gw_layer_impact_setup *s, gw_progress_fn progress, void *pctx,
                                 gw_layer_impact_outcome *out, gw_err *err);
void gw_layer_impact_outcome_free(gw_layer_impact_outcome *out);

/* An impact resolved from its setup as gw_layer_impact_run resolves it, for
 * callers that run gw_layer_impact themselves (with their own on_sample hook,
 * as the program does for its VTK files; gw_layer_impact checks the sample's
 * settling again, which the program, through an internal run that takes the
 * plan's verdict, does not): the sample read and checked, the
 * materials (the sample's mass law and clump mass unless given), the impact,
 * the solver and its parameters, options without effect in the combination
 * refused. Free with gw_layer_impact_plan_free, also after a failure. Returns
 * GW_OK or what gw_layer_impact_run would return before running. */
typedef struct gw_layer_impact_plan {
    gw_layer_sample sample;
    gw_layer_params lp;
    gw_layer_impact_params ip;
    const gw_solver_type *type;
    gw_solver_params sp;
} gw_layer_impact_plan;
int gw_layer_impact_plan_make(const gw_layer_impact_setup *s, gw_layer_impact_plan *p, gw_err *err);
void gw_layer_impact_plan_free(gw_layer_impact_plan *p);

/* What gw_layer_impact_run checks before it runs: the rows, the sample (read
 * and checked), the resolution against it (options without effect in the
 * combination refused), and the single run's refusals of other-settling and
 * zero-springs of no effect on that sample (since session 48: they passed
 * here, and the run refused them). GW_OK or the status gw_layer_impact_run
 * would return before running. A sweep's case keeps those two flags where
 * idle (gw_layer_sweep_model's check). */
int gw_layer_impact_setup_check(const gw_layer_impact_setup *s, gw_err *err);
/* The settling verdict gw_layer_impact_run takes on s's sample under s's
 * material, without running: gw_layer_impact_setup_check's checks first (its
 * refusals, the same status and message), then *q (may be NULL) the load
 * ratio the sample's contacts carry under that material against at rest
 * (gw_layer_settled_load_ratio; NaN when the sample records no settling) and
 * warning (n bytes; may be NULL with n 0) the warning the run's result
 * carries (gw_layer_impact_result.settling, gw_layer_impact_settled_check's:
 * "" when none). On failure *q is NaN and warning "". GW_EINVAL for s NULL,
 * or warning NULL with n > 0. */
int gw_layer_impact_setup_settling(const gw_layer_impact_setup *s, double *q, char *warning, size_t n,
                                   gw_err *err);

/* ---- pluviation (physics.md 2.2) ---- */

/* The inputs of `granwave layer-make`: materials (mass law disc, clump mass
 * sum by default) and gw_layer_make_params; out (may be NULL) is the sample
 * file to write. */
typedef struct gw_layer_make_setup {
    double friction, shear_modulus, poisson, density, gravity, skin; /* as gw_layer_impact_setup */
    int mass_law;          /* disc, sphere [disc] */
    int clump_mass;        /* sum, union (choice) [-1: not given = sum] */
    long n;                /* particles (clumps with clumps = 1) [300] */
    double rm;             /* mean radius R_m, m [0.325] */
    double volume_ratio;   /* largest/smallest volume [10] */
    double width_rm;       /* box width in R_m [50] */
    long seed;             /* [1] */
    double ke_threshold;   /* stop when E_k < E M g R_m [1e-5] */
    double t_max;          /* s [6] */
    double damping;        /* Hunt-Crossley alpha while settling, s/m [0.3] */
    double modulus_factor; /* settle with F G [1] */
    double dt;             /* fixed step, s [2e-5] */
    int solver;            /* rk4, verlet (choice) [rk4] */
    double height_rm;      /* keep particles wholly below H R_m [0 = all] */
    int clumps;            /* type B soil [0] */
    double aspect_max;     /* clumps: aspect ratio in [1, A] [NaN: not given = 4] */
    char *out;             /* sample file to write (text, or HDF5 for .h5) [NULL: none], owned */
} gw_layer_make_setup;

const gw_param *gw_layer_make_setup_params(void);
int gw_layer_make_setup_init(gw_layer_make_setup *s);
void gw_layer_make_setup_clear(gw_layer_make_setup *s);

typedef struct gw_layer_make_outcome {
    gw_layer_make_result r;
    gw_layer_sample sample; /* the sample: n discs, x, y, r, body (NULL for discs) */
    double height;          /* max(y + r), m */
    double height_rm;       /* height / R_m */
    char *sample_fnv1a64;   /* with out: the FNV-1a 64 hash of the file written (16 hex
                               digits, owned; what layer-impact records), else NULL */
    char *warnings;         /* gw_layer_make_result_warnings of r (owned; NULL: none) */
} gw_layer_make_outcome;

const gw_param *gw_layer_make_outcome_fields(void);

/* Pluviate (gw_layer_make) and, when s->out is set, write the sample there
 * atomically with the settings in its header. out zeroed first; free with
 * gw_layer_make_outcome_free also after a failure. GW_EINVAL "NAME: reason",
 * GW_EUNSUPPORTED (HDF5 out without HDF5), GW_EIO, the run's status. */
int gw_layer_make_run(const gw_layer_make_setup *s, gw_layer_make_outcome *out, gw_err *err);
/* The same with progress(pctx, done, total) every 0.01 s of simulated settling
 * (gw_layer_make_params.progress: hundredths of a second of t-max); non-zero
 * stops it (GW_ECANCELED). */
int gw_layer_make_run_progress(const gw_layer_make_setup *s, gw_progress_fn progress, void *pctx,
                               gw_layer_make_outcome *out, gw_err *err);
/* The pluviation's parameters from s as gw_layer_make_run resolves and checks
 * them (the out path tried too), for callers that call gw_layer_make and
 * write the sample themselves (the program). GW_EINVAL "NAME: reason". */
int gw_layer_make_plan(const gw_layer_make_setup *s, gw_layer_params *lp, gw_layer_make_params *mp, gw_err *err);
void gw_layer_make_outcome_free(gw_layer_make_outcome *out);

GW_END_DECLS

#endif
