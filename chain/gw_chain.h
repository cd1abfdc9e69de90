/*
 * gw_chain.h: the 1D column of beads hitting a wall (Falcon et al. 1998), its
 * materials and closed forms, one collision run with its observables, and the
 * studies built on it (the Falcon rigid-wall study).
 *
 * Model (docs/physics.md 1.1, eq. F.11): N point masses, x_i the displacement of bead i
 * (bead 1 = wall bead) from its initial position, positive toward the wall; at
 * t = 0 every contact just touches and every bead moves at v_imp toward the wall.
 * Contact i (beads i, i+1) has overlap d_i = x_(i+1) - x_i and force
 * F_i = k_i d_i^(3/2) for d_i > 0, else 0; the wall force is F_0 = K x_1^(3/2).
 * Optional gravity g (toward the wall) and viscoelastic damping (docs/physics.md 1.5).
 * SI units throughout: m, s, kg, N, N/m^1.5.
 */
#ifndef GW_CHAIN_H
#define GW_CHAIN_H

#include "gw_common.h"
#include "gw_solver.h"

#include "gw_api.h"

GW_BEGIN_DECLS /* the exported interface, C linkage (gw_api.h) */

/* ---- materials and closed forms (docs/physics.md 1.2, 1.3) ---- */

typedef struct gw_material {
    const char *name;
    double young;   /* Pa (INFINITY for an ideal rigid body) */
    double poisson; /* - */
    double density; /* kg/m^3 */
} gw_material;

/* Material by name ("steel", "rigid", ...); NULL if unknown. */
const gw_material *gw_material_find(const char *name);
/* Comma-separated list of known material names (static string). */
const char *gw_material_names(void);

/* Hertz coefficient of two spheres: k = (4/3) E* sqrt(R_eff), N/m^1.5; a radius of
 * INFINITY is a plane. (F.12) for equal spheres, (F.3) for sphere on plane. NaN
 * for a NULL material, one whose Young modulus is not in (0, INFINITY] or whose
 * Poisson ratio is not in (-1, 0.5], or a radius not > 0 (they gave INFINITY, a
 * rigid contact). */
double gw_hertz_coefficient(double r1, const gw_material *m1, double r2,
                            const gw_material *m2);

/* (4/5) B(2/5, 1/2) = 2.94322..., the constant of (F.2), from GSL's Beta. */
double gw_chain_tau_constant(void);
/* Single bead on a wall of stiffness K: contact time (F.2), peak overlap, peak
 * force (F.13) and its time tau_1/2 (F.21). These and gw_chain_tq_theory are
 * NaN outside their domain: m in (0, inf), K (k) in (0, inf], v in [0, inf]
 * (a negative m and K gave finite values, v = -1 the overlap of +1). A rigid
 * wall, K = inf, gives the limits: tau_1 = 0, d_max = 0, F_max = inf for v > 0
 * (0 at v = 0; F_max was NaN before session 42). */
double gw_chain_tau1(double m, double K, double v);
double gw_chain_dmax1(double m, double K, double v);
double gw_chain_fmax1(double m, double K, double v);
/* Analytic deformation-wave time T_q = 2 (m/k)^(2/5) v^(-1/5) (F.17 with C3 = 2),
 * and speed v = 4R/T_q (F.27). */
double gw_chain_tq_theory(double m, double k, double v);
/* Critical wall coefficient K_c = (tau_c/4)^(5/2) (5k/4) (F.22), tau_c = 2.943;
 * NaN for k negative or NaN (a negative K_c before session 34). */
double gw_chain_kc(double k);

/* Sheets of the paper's Table 2 (soft walls; names: none, brass, tape, pvc,
 * pmma, cardboard2, beech, cardboard1, rubber), with the material constants of
 * the sheet model (handbook values; sources in docs/sheets.md). */
typedef struct gw_sheet {
    const char *name;
    double tau_max1_us;  /* measured tau_max(N = 1), us, at h = 2.9 mm */
    double n_d, n_d_err; /* measured saturation number */
    /* fields below: the material model (chain_sheets.c); "none" has thickness 0 */
    double thickness;    /* m (Table 2) */
    double tau_max_nd_us, tau_max_nd_err_us; /* measured tau_max(N = N_d), us */
    const char *material; /* what the constants describe */
    double young;        /* storage modulus at kHz, Pa */
    double poisson;      /* - */
    double yield;        /* yield stress, Pa; > 0: elastic-plastic (Thornton) */
    double loss;         /* loss factor tan(delta); > 0: viscoelastic */
} gw_sheet;

/* How a sheet becomes a wall law (chain_sheets.c). */
typedef enum {
    GW_SHEET_FITTED = 0,  /* Hertz K_eff fitted to the measured tau_max(N = 1) */
    GW_SHEET_HERTZ = 1,   /* Hertz half-space of the sheet's material */
    GW_SHEET_LAYER = 2,   /* elastic layer of the sheet's thickness bonded on the sensor */
    GW_SHEET_MATERIAL = 3 /* LAYER with the sheet's loss (viscoelastic), or, for a sheet
                             with a yield stress, Thornton elastic-plastic on HERTZ */
} gw_sheet_law;

/* Limit contact pressure of the Thornton law from a yield stress: p_y = 2.8 Y (the
 * fully plastic mean pressure, Tabor's constraint factor; Johnson 1985, 6.2). */
#define GW_SHEET_TABOR 2.8

/* Law by name ("fitted", "hertz", "layer", "material"); -1 if unknown. The
 * name of a law: "unknown" for a value outside the enum ("?" before the
 * forty-ninth pass), as the other enums' names. */
int gw_sheet_law_find(const char *name);
const char *gw_sheet_law_name(gw_sheet_law law);

int gw_sheet_count(void);
const gw_sheet *gw_sheet_get(int i);
const gw_sheet *gw_sheet_find(const char *name);
/* Effective wall coefficient of a sheet for beads of mass m (N/m^1.5): the
 * Hertz K whose single-bead tau_max = tau_1/2 (F.2, F.21) equals the measured
 * tau_max(N = 1) at v_imp = sqrt(2 g 2.9 mm). NaN for a NULL sheet and an m
 * not finite and > 0 (a negative m gave a negative K). */
double gw_sheet_kwall(const gw_sheet *s, double m);

/* ---- thin elastic layer on a rigid base (chain_layer.c) ----
 * Sphere (radius R, material bead) pressed on a layer of thickness h, Young E,
 * Poisson nu, bonded to a rigid base, frictionless on top: the axisymmetric
 * contact solved as a Fredholm equation (Nystrom) for contact radii a from 1e-3 h
 * to min(40 h, max(2 h, 2R)) and tabulated as F(d); Hertz for a << h, the
 * Winkler foundation F = pi R M d^2/h, M = E(1-nu)/((1+nu)(1-2nu)), for a >> h. */
typedef struct gw_layer_law gw_layer_law;

/* Build the law (about 0.1-0.5 s), or return the process's law of the same
 * inputs (radius, thickness, E, nu, the sphere's Young modulus and Poisson
 * ratio, compared bit for bit) with one more reference: a law is built once per
 * distinct set of inputs, and up to 256 laws nobody references are kept for a
 * later create. GW_EINVAL (radius in [1e-6, 1] m, h in [1e-7, 1] m, E in
 * [1e3, 1e13] Pa, nu in [0, 0.5]; the sphere's material with a Young modulus in
 * (0, INFINITY] and a Poisson ratio in (-1, 0.5]), GW_ENOMEM, GW_ESOLVER. The law is read-only
 * and may be shared by threads. */
int gw_layer_law_create(double radius, const gw_material *bead, double thickness, double young,
                        double poisson, gw_layer_law **out, gw_err *err);
/* Drop the reference a create gave (each create is paired with one free, in any
 * order across holders and threads); NULL is nothing. */
void gw_layer_law_free(gw_layer_law *l);
/* Each of these four is NaN for l NULL or a NaN d or f (before session 34 they
 * read NULL, SIGSEGV, and gave 0 for NaN, no contact).
 * Force (N) at overlap d (m), 0 for d <= 0; *stiffness = dF/dd (may be NULL). */
double gw_layer_law_force(const gw_layer_law *l, double d, double *stiffness);
/* Stored energy int_0^d F (J). */
double gw_layer_law_energy(const gw_layer_law *l, double d);
/* Overlap (m) at which the force is f (N); 0 for f <= 0. */
double gw_layer_law_overlap(const gw_layer_law *l, double f);
/* Contact radius a (m) at overlap d. */
double gw_layer_law_contact_radius(const gw_layer_law *l, double d);
/* (4/3) E* sqrt(R): the Hertz coefficient of the same sphere on a half-space of
 * the layer's material (the law's thick-layer limit), N/m^1.5. */
double gw_layer_law_hertz_k(const gw_layer_law *l);
double gw_layer_law_thickness(const gw_layer_law *l);
/* One dimensionless solution: contact radius alpha = a/h in [1e-100, 100]
 * (GW_LAYER_ALPHA_MIN: below it fhat ~ (4/3) alpha^3 is no normal double;
 * smaller alpha is refused naming alpha, GW_EINVAL), layer Poisson ratio in
 * [0, 0.5], share lambda in [0, 1] of the layer in the contact compliance
 * (1 for a rigid sphere): dhat = d R/h^2, fhat = F R/(E* h^3). */
#define GW_LAYER_ALPHA_MIN 1e-100
int gw_layer_solve_point(double alpha, double poisson, double lambda, double *dhat,
                         double *fhat, gw_err *err);

/* ---- elastic-perfectly plastic contact (Thornton 1997; chain_wall.c) ----
 * Hertz F = (4/3) E* sqrt(R) d^(3/2) until the peak pressure reaches the limit
 * p_y (d_y = R (pi p_y/(2E*))^2, F_y = (4/3) E* sqrt(R) d_y^(3/2)); beyond, the
 * pressure is capped: F = F_y + pi p_y R (d - d_y) (so F <= pi p_y R d). Unloading
 * from (d_m, F_m) is Hertzian with the radius R_p = (4 E* / (3 F_m)) ((2 F_m + F_y)/
 * (2 pi p_y))^(3/2) from the residual overlap d_p = d_m - (3 F_m / (4 E* sqrt(R_p)))^(2/3). */
typedef struct gw_thornton {
    double estar, radius, p_y; /* Pa, m, Pa */
    double d_y, f_y;           /* m, N */
} gw_thornton;

/* t from E* (Pa), the radius R (m) and the yield pressure p_y (Pa); t NULL: nothing.
 * Any of the three not finite and > 0: every force of t is NaN. */
void gw_thornton_init(gw_thornton *t, double estar, double radius, double p_y);
/* Force at overlap d after a largest overlap dmax (the force uses max(d, dmax)):
 * *stiffness dF/dd, *residual d_p, *energy the elastic energy recovered on
 * unloading from d (each may be NULL). t NULL, d or dmax NaN: NaN, and NaN
 * into each (a NaN overlap gave 0 N before session 34). */
double gw_thornton_force(const gw_thornton *t, double d, double dmax, double *stiffness,
                         double *residual, double *energy);
/* Work of loading from 0 to dmax, J; 0 for dmax <= 0, NaN for t NULL (read
 * before session 34: SIGSEGV) or dmax NaN (0 J before). */
double gw_thornton_loading_work(const gw_thornton *t, double dmax);

/* ---- model ---- */

typedef enum {
    GW_DAMP_NONE = 0,
    GW_DAMP_KUWABARA_KONO = 1, /* F = k d^1.5 + gamma d^0.5 d' */
    GW_DAMP_HUNT_CROSSLEY = 2  /* F = k d^1.5 (1 + 1.5 alpha d') */
} gw_chain_damping;

/* Wall contact law beyond the Hertz spring (chain_wall.c). kwall stays the
 * nominal Hertz coefficient: with a layer, that of a half-space of the sheet's
 * material (it sets the time scales and the default step limits). Contact damping
 * (kk, hc) acts on a Hertz wall as before, not on a layer, plastic or viscoelastic
 * wall, which dissipate by their own law. */
typedef struct gw_chain_wall {
    const gw_layer_law *layer; /* non-NULL: elastic law F(d) of a bonded layer instead
                                  of kwall d^(3/2) (caller-owned, outlives the chain) */
    double yield_pressure;     /* > 0: Thornton elastic-plastic wall with the limit
                                  pressure p_y (Pa) on the Hertz law, E* = 3 kwall/
                                  (4 sqrt(radius)); not with a layer or loss */
    double loss;               /* > 0: viscoelastic wall, loss factor tan(delta) at
                                  the band centre (see tau_min) */
    double tau_min, tau_max;   /* relaxation times of the Maxwell arms, s, one per
                                  decade between them (0: 1e-5 and 1e-3); each 0
                                  or in [GW_CHAIN_WALL_TAU_MIN, 1e3] */
} gw_chain_wall;

/* The shortest relaxation time a wall's Maxwell arm may have, s: a picosecond,
 * the scale of the atomic vibrations (0.01-1 ps) below which a solid's
 * relaxation is no viscoelastic one. An arm far faster than the contact (10 us
 * to 1 ms) is relaxed through it and gives it no loss (arms at 1e-12 to 1e-10 s
 * and tan(delta) 0.3: one bead rebounds at 0.99999); one of 1e-300 s, below the
 * spacing of doubles at the collision's times (about 1e-20 s), ran as a wall
 * relaxed at once whatever the loss asked. gw_chain_params_validate refuses a
 * time above 0 and below it, naming the arm. */
#define GW_CHAIN_WALL_TAU_MIN 1e-12

/* The force sensor as a body: a mass on a spring (and dashpot) to the ground,
 * under the wall contact; it reads the force through its spring and dashpot,
 * k_s x_s + c_s v_s. Off when mass == 0. */
typedef struct gw_chain_sensor {
    double mass;      /* kg, > 0 to switch the sensor body on */
    double stiffness; /* N/m, > 0 with a mass */
    double damping;   /* N s/m, >= 0 */
} gw_chain_sensor;

/* Friction of every bead on its guide (the tube): a force against its velocity,
 * coulomb tanh(v/v_reg) + viscous v. */
typedef struct gw_chain_guide {
    double coulomb; /* N per bead */
    double viscous; /* N s/m per bead */
    double v_reg;   /* regularisation speed of the Coulomb term, m/s (0: 1e-3 v_imp) */
} gw_chain_guide;

#define GW_WALL_MAX_ARMS 7

typedef struct gw_chain_params {
    int n;                 /* number of beads, >= 1 */
    double v_imp;          /* impact velocity toward the wall, m/s, > 0 */
    double mass;           /* bead mass, kg (when masses == NULL) */
    double k;              /* bead-bead Hertz coefficient (when kc == NULL) */
    double kwall;          /* bead-wall Hertz coefficient K, > 0 */
    double radius;         /* bead radius, m (wave speed 4R/T_q, outputs) */
    const double *masses;  /* optional per-bead masses [n], caller-owned */
    const double *kc;      /* optional per-contact coefficients [n-1], caller-owned */
    double gravity;        /* m/s^2 toward the wall; 0 = off (default) */
    gw_chain_damping damping;
    double gamma;          /* Kuwabara-Kono constant of bead-bead contacts,
                              N s/m^1.5; the wall uses gamma * kwall / k */
    double alpha;          /* Hunt-Crossley constant, s/m (all contacts) */
    /* Fields below are off when zero (gw_chain_params_default): the wall is then
     * the Hertz spring kwall on a rigid sensor and the beads move freely. */
    gw_chain_wall wall;     /* contact law of the wall (a sheet) */
    gw_chain_sensor sensor; /* the force sensor as a body */
    gw_chain_guide guide;   /* friction of the beads on their guide */
} gw_chain_params;

/* Impact velocities every chain command accepts, m/s: [GW_CHAIN_VIMP_MIN,
 * GW_CHAIN_VIMP_MAX] (beyond the top, the Hertz overlaps exceed the bead radius
 * long before; below a nanometre per second the solvers' error weights
 * underflow near 1e-160 m/s, and nothing physical is left to measure). Drop
 * heights, mm: [GW_CHAIN_HEIGHT_MIN_MM, v_max^2 / (2 g)]. */
#define GW_CHAIN_VIMP_MIN 1e-9
#define GW_CHAIN_VIMP_MAX 1e3
/* v = sqrt(2 g h) = 1.0003e-9 m/s at 9.81 m/s^2: the smallest drop height
 * (VIMP_MIN^2 / 2 g = 5.0968e-17 mm) rounded up, so that every height of the
 * row falls at a speed chain takes (5e-17 mm ran falcon at 9.9e-10 m/s, a
 * speed chain --vimp refuses) */
#define GW_CHAIN_HEIGHT_MIN_MM 5.1e-17
/* Earth's gravity, m/s^2: the fall of a drop height when the run has no
 * gravity of its own (gw_chain_falcon_speeds), the paper's 2.9 mm drop of
 * softwall and of the sheets' K_eff, the drop's default gravity. */
#define GW_CHAIN_G_EARTH 9.81
/* The largest drop height, mm: GW_CHAIN_VIMP_MAX at GW_CHAIN_G_EARTH. */
#define GW_CHAIN_HEIGHT_MAX_MM (GW_CHAIN_VIMP_MAX * GW_CHAIN_VIMP_MAX / (2 * GW_CHAIN_G_EARTH * 1e-3))

/* Largest damping constants (docs/physics.md 1.5). Hunt-Crossley's restitution
 * depends on alpha v alone (measured with gw_chain_calibrate: e = 0.5 at
 * alpha v = 0.955, e = 0.1 at 6.67, e = 0.01 at 66.7, the same at 1e-3, 0.3 and
 * 100 m/s), so alpha <= 1e8 s/m holds every constant that calibrates e >= 0.01 at
 * speeds down to 1e-6 m/s; measured constants of solids are 0.01-10 s/m.
 * Kuwabara-Kono's depends on g = gamma v^(1/5) / (k^(3/5) m^(2/5)) (e = 0.01 at
 * g = 15.6, steel at 1e-3 and 0.3 m/s), so over the table's k <= 1e14 N/m^1.5
 * and m <= 1e3 kg, e >= 0.01 at v >= 1e-6 m/s needs gamma <= 1.6e12; 1e14 leaves
 * a factor 60. gamma/k = (3/2) A is the material's dissipative time A, which is
 * then at least 0.7 s at the stiffest contact against contact times of us to ms.
 * Beyond both the contact is overdamped (the bead stays on the wall) and larger
 * numbers only overflow the force (gamma 1e50 failed at t = 0 before). */
#define GW_CHAIN_GAMMA_MAX 1e14
#define GW_CHAIN_ALPHA_MAX 1e8

/* Stainless steel beads of the experiment: R = 4 mm, E = 21.6e10 Pa,
 * nu = 0.276, rho = 7850 kg/m^3 (m = 4/3 pi R^3 rho), steel wall, n = 1,
 * v_imp = 0.3 m/s, no gravity, no damping. */
gw_chain_params gw_chain_params_default(void);

/* Check every field; GW_EINVAL with a message naming the field. */
int gw_chain_params_validate(const gw_chain_params *p, gw_err *err);

/* Set p->kwall and p->wall for sheet s under law, for the beads of p (radius,
 * mass) of material bead; wall is the material of the bare sensor (sheet "none"
 * and the Hertz time scale). yield and loss override the sheet's constants when
 * >= 0 (0: none), each finite. A layer law is created into *layer (caller frees with
 * gw_layer_law_free after the runs; NULL when none). GW_EINVAL (also for a law
 * outside gw_sheet_law, a NULL pointer, a bead or wall material, or the sheet's
 * own under a law that uses it, whose Young modulus is not in (0, INFINITY] or
 * Poisson ratio not in (-1, 0.5]), GW_ENOMEM, GW_ESOLVER with a message. */
int gw_sheet_apply(const gw_sheet *s, gw_sheet_law law, double yield, double loss,
                   const gw_material *bead, const gw_material *wall, gw_chain_params *p,
                   gw_layer_law **layer, gw_err *err);

typedef struct gw_chain gw_chain;

/* Build the ODE system for p (validated; p's arrays are copied). */
int gw_chain_create(const gw_chain_params *p, gw_chain **out, gw_err *err);
void gw_chain_free(gw_chain *c);

/* The gw_system handed to solvers. State layout, interleaved so the Jacobian is
 * banded (mu = 2, ml = 3): y[2i] = x_i, y[2i+1] = v_i (i = 0..n-1, bead 1 is
 * i = 0), then y[2n] = dissipated energy when damping is on.
 * Root functions: g[0] = x_0 (wall contact), g[1+i] = d_i (contact i,
 * i = 0..n-2), g[n] = v_0 (extrema of the wall force).
 * With the options of gw_chain_wall, gw_chain_sensor and gw_chain_guide (the
 * "general" model), the state continues after the beads with, each only when
 * present: the dissipated energy (damping, sensor dashpot or guide friction), the
 * work done on a plastic or viscoelastic wall, the sensor x_s, v_s, the largest
 * overlap of a plastic wall, one Maxwell-arm force per relaxation time of a
 * viscoelastic wall. Then g[0] = gw_chain_wall_gap, g[n] = v_0 - v_s and, with a
 * sensor body, g[n+1] = v_s. The implicit methods order the states after the
 * dissipated energy before the beads (gw_system.lead0, nlead): they couple only
 * to bead 1, and the Jacobian stays banded (finite differences); the
 * dissipated energy is a ledger (nledger). */
/* The column's system and parameters: NULL for a NULL c. */
const gw_system *gw_chain_system(const gw_chain *c);
const gw_chain_params *gw_chain_get_params(const gw_chain *c);
double gw_chain_bead_mass(const gw_chain *c, int i);
/* Initial state: all x = 0, all v = v_imp (dissipated energy 0). */
void gw_chain_initial_state(const gw_chain *c, double *y);

typedef struct gw_chain_energy {
    double kinetic, elastic, gravity, dissipated, total; /* J */
} gw_chain_energy;

/* Energies of state y; gravity is the potential -sum m g x. With a plastic or
 * viscoelastic wall the work done on the wall is integrated as a state; its part
 * still stored in the wall is counted as elastic, the rest as dissipated (their
 * sum, and so the total, is exact). The sensor's kinetic and spring energies are
 * in kinetic and elastic. A state holding a NaN gives NaN in every member. */
void gw_chain_energy_of(const gw_chain *c, const double *y, gw_chain_energy *e);
/* Force the sensor reads (N) in state y: the contact force on a rigid sensor,
 * the force through the sensor's spring and dashpot when it is a body. NaN for
 * a NaN in the states it reads (never the open contact's 0). */
double gw_chain_wall_force(const gw_chain *c, const double *y);
/* Force of the bead-wall contact (N); NaN for a NaN in the states it reads. */
double gw_chain_wall_contact_force(const gw_chain *c, const double *y);
/* The wall contact's opening function (> 0 while closed): x_0 - x_s, less the
 * residual dent of a plastic wall. y[0] for the default wall. */
double gw_chain_wall_gap(const gw_chain *c, const double *y);
/* Its rate v_0 - v_s (y[1] for the default wall). */
double gw_chain_wall_gap_rate(const gw_chain *c, const double *y);
/* Root index whose falling zero, with the wall contact closed, marks a maximum of
 * the force the sensor reads (n, or n + 1 with a sensor body): a function with
 * the sign of dF/dt (v_0, the overlap rate or v_s where F follows the overlap or
 * the sensor's spring alone; with damping or a viscoelastic wall, the rate of F
 * itself). */
int gw_chain_force_max_root(const gw_chain *c);
/* State index of the sensor's position (its velocity follows), -1 without. */
long gw_chain_sensor_index(const gw_chain *c);
/* Momentum of the beads and the sensor body, kg m/s (toward the wall > 0). */
double gw_chain_momentum(const gw_chain *c, const double *y);

/* ---- one collision ---- */

/* Called at every sample and event: time, state, wall force. Non-zero stops. */
typedef int (*gw_chain_sample_fn)(void *ctx, double t, const double *y, double f_wall,
                                  int is_event);

/* The run's options. dt_out, t_max, energy_tol, front_threshold and
 * steps_per_tc are each a finite number >= 0 (0: the default or off): the run
 * (gw_chain_collide, gw_chain_run_check) refuses any other with GW_EINVAL
 * naming the member. */
typedef struct gw_chain_run_opts {
    const gw_solver_type *solver; /* default CVODE */
    gw_solver_params sp;          /* dt == 0 for rk4: T_c / steps_per_tc, see below */
    double dt_out;     /* sampling interval, s; 0 = tau_1/200 (energy and F_max) */
    double t_max;      /* give up after this time, s; 0 = 20 (n T_q + tau_1), T_q and tau_1 of the heaviest bead,
                        * + 20 pi sqrt((sum m + M)/k_s) on a sensor body (the column riding its spring); a
                        * run at that default that has not ended there goes on while contacts act, up to
                        * 50 times it (5e6 samples at dt_max past it at most), and records where it stopped
                        * as its run_t_max */
    double energy_tol; /* stop with GW_EENERGY when the relative energy error
                          exceeds this (0 = off) */
    gw_chain_sample_fn sample;
    void *sample_ctx;
    double front_threshold; /* N; > 0: record when each contact's force first
                               reaches it (result front_t): between beads on
                               the cubic Hermite interpolant of the overlap
                               between observations, at the wall linearly */
    double steps_per_tc; /* rk4 with sp.dt == 0: dt = T_c / steps_per_tc, T_c the
                            chain's time scale (gw_chain_time_scale) of this run's
                            v_imp; 0 = 400 (and at most a sensor body's M/c_s
                            and a viscoelastic wall's fastest arm tau_min) */
    const double *y0;    /* optional initial state [dim] (caller-owned), e.g. a
                            column with gaps; NULL = gw_chain_initial_state. The
                            contacts start closed where the overlap is >= 0. The
                            restitutions (F.7, F.30) still take v_imp as the
                            incoming velocity of every bead. */
} gw_chain_run_opts;

gw_chain_run_opts gw_chain_run_opts_default(void);

/* RK4 steps per time scale T_c (for gw_chain_run_opts.steps_per_tc) that keep
 * F_max and tau_N of an undamped column (N <= 40, no gravity) within the relative
 * error rel_acc of a converged solution, sampling every tau_1/10 or coarser.
 * From the convergence study bench/bench_falcon_accuracy (see chain_collide_plan.c).
 * Returns 0 when rel_acc is outside [GW_CHAIN_RK4_ACCURACY_MIN, _MAX] =
 * [1e-9, 1e-2] (use an adaptive backend). */
#define GW_CHAIN_RK4_ACCURACY_MIN 1e-9
#define GW_CHAIN_RK4_ACCURACY_MAX 1e-2
int gw_chain_rk4_steps_per_tc(double rel_acc);
/* Whether that study covers the column p run up to n_max beads: undamped, no
 * gravity, N <= 40, a Hertz wall on a rigid sensor (no sheet layer, yield or
 * loss), no guide friction. 1 or 0. The falcon study picks its solver by an
 * accuracy target only there (gw_chain_falcon_run and `granwave falcon`).
 * 0 for a NULL p, an n_max below 1 (no column: -5 was covered) and a p that
 * is no column (gw_chain_time_scale: a NaN mass was covered). */
int gw_chain_rk4_study_covers(const gw_chain_params *p, long n_max);
/* The study's choice into run: RK4 (default method) with
 * M = gw_chain_rk4_steps_per_tc(rel_acc) steps per T_c and, unless keep_dt_out,
 * samples every tau_1/10 of the fastest impact vmax (F_max and tau_N are
 * events; samples feed the energy check). Returns M, or 0 (run unchanged) when
 * rel_acc is outside [1e-9, 1e-2], run or p is NULL, or (without keep_dt_out)
 * vmax is not a finite speed > 0. */
int gw_chain_rk4_study_apply(gw_chain_run_opts *run, const gw_chain_params *p, double rel_acc, double vmax,
                             int keep_dt_out);

typedef struct gw_chain_result {
    int n;
    double f_max;        /* largest wall force, N */
    double tau_max;      /* time of f_max, s */
    double tau_n;        /* time bead 1 leaves the wall for the last time, s */
    double period;       /* mean spacing of wall-force maxima, s (NaN if < 2) */
    int n_maxima;        /* wall-force maxima seen */
    double energy_error; /* max |E(t) - E(0)| / E(0) over samples and events */
    double e0;           /* initial energy, J */
    double *final_v;     /* [n] velocities at the end, m/s (toward wall > 0) */
    double *detach_t;    /* [n] last opening of a contact of bead i, s */
    double *v_tau_n;     /* [n] velocities at tau_n */
    double *front_t;     /* [n] first time contact i-1 (i = 0: the wall) carries
                            front_threshold; NaN if never; NULL if not asked */
    double impulse;      /* integral of the wall force over the run, N s */
    int n_s;             /* beads leaving from the top before the cluster */
    int cluster;         /* beads in contact with bead 1 when it left the wall */
    double e_rel_over_e_k; /* (F.20) at tau_n */
    double eps_eff;      /* (F.7) with final velocities */
    double eps_col;      /* (F.30) */
    int wall_contacts;   /* number of separate wall contacts (> 1: re-contact) */
    int converged;       /* 1: all contacts open and separating at t_end */
    double t_end;
    long n_events;
    long missed_events;  /* contact changes found from the state, not a root */
    gw_solver_stats stats;
    int wall_done;       /* 1: at t_end bead 1 is off the wall, separating from it and beyond
                            a sensor body's reach (f_max, tau_max, tau_n are final; the
                            column's own contacts may still be busy: converged 0) */
    const char *wall_pending; /* wall_done 0: why, as a phrase ("bead 1 still at the
                                 wall", ...; static storage); NULL when wall_done */
    /* The run's settings as used, defaults resolved (for the provenance):
     * t_max and dt_out in s; dt the RK4 step or the initial step asked of
     * cvode/arkode (0 = their own choice), s; dt_max the largest step, s. */
    double run_t_max, run_dt_out, run_dt, run_dt_max;
    /* The dt the caller gave (0: none), s. run_dt is the step the run took: a
     * dt above dt_max runs at dt_max (every backend; cvode and arkode take it
     * as their first step), and rk4's steps end at the samples, so a dt above
     * dt_out runs at dt_out; the warnings say so when they differ. */
    double run_dt_given;
    /* The largest overlap of any contact (the wall's elastic one included) at
     * the samples and events, over the bead radius (gw_chain_params.radius):
     * the Hertz law assumes it much below 1, and above 1 the results are the
     * law's outside its range (gw_chain_result_warnings says so). */
    double overlap_max_rel;
    /* Bead 1's chatter on a sensor body (its wall contact closing
     * GW_CHAIN_CHATTER_CONTACTS times or more, which amplifies the
     * integration's error): chatter_kind one of GW_CHAIN_CHATTER_* (NONE also
     * for a rigid wall, fewer contacts, or a rerun that agreed within
     * GW_CHAIN_CHATTER_SPREAD), chatter_spread |eps_eff - the rerun's| when
     * MOVED (the rerun at 10 times tighter tolerances, rk4: half the step),
     * else 0. The warnings say it (gw_chain_result_warnings). */
    int chatter_kind;
    double chatter_spread;
    /* The run's relative and absolute tolerances as used (cvode, arkode:
     * gw_chain_run_opts.sp.rtol and atol, 1e-10 in its default); NaN
     * under rk4, a fixed step with no error test. The drop's chatter line
     * names its rerun's values from its first collision's (0 in a result
     * filled by hand: the line says "10 times tighter tolerances"). Kept in a
     * hidden buffer after final_v before the forty-sixth session. */
    double run_rtol, run_atol;
} gw_chain_result;

/* gw_chain_result's chatter_kind */
enum {
    GW_CHAIN_CHATTER_NONE,   /* no chatter, or a rerun that agreed within GW_CHAIN_CHATTER_SPREAD */
    GW_CHAIN_CHATTER_MOVED,  /* a rerun at tighter tolerances moved eps_eff by chatter_spread */
    GW_CHAIN_CHATTER_COSTLY, /* not run again: steps times beads above GW_CHAIN_CHATTER_WORK */
    GW_CHAIN_CHATTER_FAILED  /* its rerun failed: the spread unmeasured */
};
#define GW_CHAIN_CHATTER_CONTACTS 10 /* wall contacts from which a run on a sensor body is checked */
#define GW_CHAIN_CHATTER_SPREAD 1e-6 /* the change of eps_eff from which a rerun is said */
#define GW_CHAIN_CHATTER_WORK 1e6    /* steps times beads up to which a chattering run is run again */
/* gw_chain_drop_result's chatter_rerun: how the drop's chatter is run again */
enum {
    GW_CHAIN_RERUN_NONE, /* not checked (no sensor body, or the run stopped early) */
    GW_CHAIN_RERUN_TOL,  /* rtol and atol 10 times tighter (cvode, arkode) */
    GW_CHAIN_RERUN_STEP  /* rk4's step halved (run_dt / 2) */
};
/* the drop's steps times bodies up to which rk4 runs it again (twice the
 * drop's steps): its rerun about 11 s of CPU at most at the bound (measured
 * 1.1e-7 s a step of one bead, 1.05e-7 of three, 2.7e-7 of thirty: 1.1e-7 s
 * a step and body at most, a step of one bead); 1e7 before the forty-sixth session, which left drop --n 3
 * --sensor-mass 1e-6 --sensor-stiffness 1e5 (1.8e7, its rerun 1.25 s)
 * unmeasured */
#define GW_CHAIN_DROP_CHATTER_RK4_WORK 5e7

/* Run one collision from the initial state until every contact is open and every
 * pair separates (or t_max). Returns GW_OK, or GW_ESOLVER / GW_ELIMIT /
 * GW_EENERGY with a message (backend message and time) in err; r is then
 * partially filled and must still be freed. */
int gw_chain_collide(const gw_chain *c, const gw_chain_run_opts *o,
                     gw_chain_result *r, gw_err *err);
/* Where a collision is: t the time reached, s; t_expect the collision's
 * expected length (n bead-to-bead transits and the wall contact, on the
 * heaviest bead's scales; t_max when shorter), s; t_max the run's limit, s.
 * A run often goes on past t_expect (every contact open and separating comes
 * after bead 1 leaves the wall): t / t_expect then exceeds 1. */
typedef void (*gw_chain_progress_fn)(void *ctx, double t, double t_expect, double t_max);
/* gw_chain_collide with progress(pctx, ...) (may be NULL) at every sample and
 * event, in the run's order; the results are those of gw_chain_collide (the
 * callback cannot stop the run: a caller that must stops through o->sample). */
int gw_chain_collide_progress(const gw_chain *c, const gw_chain_run_opts *o, gw_chain_progress_fn progress,
                              void *pctx, gw_chain_result *r, gw_err *err);
void gw_chain_result_free(gw_chain_result *r);
/* The warnings of a collision, appended to *list (gw_warnings_add,
 * gw_common.h): one that had not ended at t_max (converged 0: which results
 * are those at t_max, and why: wall_pending, or the column's own contacts),
 * and one whose largest overlap exceeded the bead radius (overlap_max_rel > 1:
 * the Hertz law used outside its range); nothing otherwise. The text
 * `granwave chain` prints and Python issues. GW_OK or GW_ENOMEM. */
int gw_chain_result_warnings(const gw_chain_result *r, char **list);
/* A collision held by gravity (wall_pending the held text: the column fell back
 * onto the wall before its collision ended, the warning "gravity holds the
 * column"): the values that warning calls undecided, F_max (and its time
 * tau_max), tau_N, the final velocities and the restitution eps_eff, eps_col,
 * set to NaN, as every undecided value (the program's JSON null and text
 * "n/a", Python's nan). They were those at the stop, which moved with the
 * sampling (--n 2 --gravity 1e3 --vimp 0.01: eps_eff -0.0058 by default, -0.467
 * at --dt-out 7e-6). Returns 1 when r was held (and is now so), else 0 (r NULL:
 * 0); the warnings (gw_chain_result_warnings) are the same before and after. */
int gw_chain_result_held_blank(gw_chain_result *r);

/* Characteristic time (m/k)^(2/5) v^(-1/5) of the chain, s (m and k those of
 * bead 1 and its upper contact). These two are NaN, and
 * gw_chain_rk4_study_covers is 0, for p NULL or no column: n outside
 * [1, 5e7], a mass or bead-bead coefficient not positive and finite, kwall
 * not above 0, v_imp not positive and finite (before session 42 masses
 * {1, -1, NaN} had a step scale of 1.47e-4 s and n = 0 a time scale). */
double gw_chain_time_scale(const gw_chain_params *p);
/* The time scale the steps resolve, s: T_c (gw_chain_time_scale) of a uniform
 * column; shorter when a contact is (unequal beads, a light sensor body: each
 * contact's binary contact time against that of two beads 1) or when the sensor
 * body oscillates faster (1/omega = sqrt(M/k_s)). The default RK4 step is 1/400
 * of it. */
double gw_chain_step_scale(const gw_chain_params *p);

/* ---- traces (wall force and bead trajectories) ---- */

typedef struct gw_chain_trace {
    int n;
    size_t len, cap;
    double *t, *f, *x, *v; /* x, v: len rows of n */
} gw_chain_trace;

/* An empty trace of n beads (nothing allocated yet); tr NULL: nothing. */
void gw_chain_trace_init(gw_chain_trace *tr, int n);
/* gw_chain_sample_fn storing every sample (ctx = gw_chain_trace*) up to the
 * bound of gw_chain_trace_check (5 GB of files for tr->n beads): the rows past
 * it are not stored and the run goes on (a default run that has not ended by
 * its expected length goes on past it; the program warns where the trace stops). */
int gw_chain_trace_sample(void *ctx, double t, const double *y, double f_wall,
                          int is_event);
void gw_chain_trace_free(gw_chain_trace *tr);
/* Bound a trace before the run that stores it: about span/dt_out samples plus
 * `events` event rows, each holding t, the wall force and every bead's x and v
 * (8 B a value in memory; written, 20 B a value as CSV and 8 B as HDF5). GW_OK
 * when its files stay within 5 GB (1.4 GB in memory, and as much again for the
 * HDF5 file's buffer while it is written); else GW_EINVAL naming
 * dt-out and a value that passes, or n when the events alone exceed it;
 * GW_EINVAL naming every argument for n below 1 (0 passed), span or events
 * negative, dt-out not positive, or any of them not finite. */
int gw_chain_trace_check(int n, double span, double dt_out, double events, gw_err *err);

/* The memory a run of column p needs with solver type (NULL: cvode) and method
 * (the model's and result's arrays, the solver's vectors and, for cvode bdf and
 * arkode dirk/imex, its band matrices) is bounded before anything is allocated at
 * GW_CHAIN_MEMORY_MAX bytes (2 GiB): GW_EINVAL "n: a column of N beads needs
 * about X GB ...: at most M beads here" otherwise. A bead count outside
 * [1, 5e7] is GW_EINVAL naming n as gw_chain_params_validate does (before
 * session 46 n = -1 passed and n = INT_MIN was told it needs 4.4e11 GB); a
 * method outside GW_METHOD_DEFAULT .. GW_ARKODE_IMEX is GW_EINVAL naming
 * method and that range (-5 and 11 passed); a variant the backend has not
 * (cvode with erk) is left to gw_solver_create (GW_EUNSUPPORTED). */
#define GW_CHAIN_MEMORY_MAX 2147483648.0
int gw_chain_memory_check(const gw_chain_params *p, const gw_solver_type *type, int method, gw_err *err);
/* Every bound gw_chain_collide checks before its run, in order, from p and o
 * alone (nothing allocated): the column itself (gw_chain_params_validate, as
 * gw_chain_create checks it: v_imp inf passed before session 48), samples
 * (dt-out), the stored trace, steps (dt or dt-max), memory (n). GW_OK or
 * GW_EINVAL naming the parameter. */
int gw_chain_run_check(const gw_chain_params *p, const gw_chain_run_opts *o, gw_err *err);
/* Write DIR/<stem>_wall_force.csv and DIR/<stem>_beads.csv (and DIR/<stem>.h5 when
 * built with HDF5); header lines record version and parameters. A trace with
 * tr->n == 0 (a copy whose bead series are to be left out) writes the wall force
 * only: no _beads.csv and no x, v datasets. A NULL dir, stem or header (the
 * HDF5 file's run attribute read it: SIGSEGV), dir "" or stem "" is GW_EINVAL
 * naming it, nothing written (stem "" wrote .h5 and _wall_force.csv). */
int gw_chain_trace_write(const gw_chain_trace *tr, const char *dir, const char *stem,
                         const char *header, gw_err *err);

/* ---- damping calibration (chain_restitution.c) ---- */

/* Damping constant (alpha for Hunt-Crossley, gamma for Kuwabara-Kono, chosen by
 * p->damping) such that one bead (p's mass, k and radius) hitting the Hertz wall
 * kwall at p->v_imp rebounds with restitution e_target in (0, 1). Runs one-bead
 * collisions with o's backend and accuracy (solver, sp, steps_per_tc); o's
 * t_max, dt_out, energy_tol, y0, sample and front_threshold are the column's and
 * are not used (the bead's own end time, 20 times its collision, and sampling).
 * The last 256 distinct calibrations of the process are kept: the same inputs
 * give the stored constant, bit for bit, at no cost (thread-safe).
 * GW_EINVAL for a bad target, no damping model or a target the contact cannot
 * reach (overdamped); a failure of a one-bead run is returned with its code and
 * message, prefixed "restitution: calibrating ...". */
int gw_chain_calibrate(const gw_chain_params *p, const gw_chain_run_opts *o,
                       double e_target, double *constant, gw_err *err);

/* ---- sweeps over N and v_imp (threaded) ---- */

/* Run one collision for every (v[iv], N) with n_lo <= N <= n_hi, using the
 * template tmpl (its n and v_imp are replaced) and run options o (no sample
 * callback). res must hold nv * (n_hi - n_lo + 1) results, index
 * iv * (n_hi - n_lo + 1) + (N - n_lo); free each with gw_chain_result_free.
 * A speed given twice (equal, or within a relative 1e-12: the chain sweep
 * config's rule for a value listed twice) is GW_EINVAL naming v and both
 * items, nothing run: each of its collisions would run twice.
 * jobs threads (<= 0: one per online CPU; the worker pool of gw_pool.h).
 * progress is ignored (kept for source compatibility: the library prints
 * nothing; for progress pass a callback to gw_chain_sweep_n_progress). On the
 * first failing case returns its status and message (naming N and v_imp); all
 * results are still allocated and must be freed. */
int gw_chain_sweep_n(const gw_chain_params *tmpl, const gw_chain_run_opts *o,
                     const double *v, int nv, int n_lo, int n_hi, int jobs,
                     int progress, gw_chain_result *res, gw_err *err);
/* The same with progress reported to the caller (gw_progress_fn, may be NULL:
 * nothing printed); a non-zero return from it stops the sweep (GW_ECANCELED). */
int gw_chain_sweep_n_progress(const gw_chain_params *tmpl, const gw_chain_run_opts *o,
                              const double *v, int nv, int n_lo, int n_hi, int jobs,
                              gw_progress_fn progress, void *pctx, gw_chain_result *res,
                              gw_err *err);
/* The same, with the grid's "no effect" warnings appended to *warnings (a
 * gw_warnings_add list, freed by the caller; NULL: none kept), as a chain
 * sweep's check pass gives them (gw_sweep_run_warned), one line each over
 * the grid's cases, the case k the result's index iv * (n_hi - n_lo + 1) +
 * (N - n_lo): a damping kk with gamma 0 or hc with alpha 0 ("is no damping:
 * 4 of 4 cases"), a contact damping, sensor dashpot or guide friction whose
 * predicted effect is below o's rtol ("the sensor body's dashpot has no
 * effect in 2 of 4 cases (the first, case 0): ..."). Appended once the grid
 * passed its checks, before its cases run (a case that fails keeps them); a
 * grid refused appends nothing. gw_chain_sweep_n and _progress give none. */
int gw_chain_sweep_n_warned(const gw_chain_params *tmpl, const gw_chain_run_opts *o, const double *v, int nv,
                            int n_lo, int n_hi, int jobs, gw_progress_fn progress, void *pctx, gw_chain_result *res,
                            char **warnings, gw_err *err);

/* ---- dispersion (chain_dispersion.c) ---- */

/* Small-amplitude dispersion of a precompressed Hertz chain (docs/physics.md 1.6):
 * n identical beads (mass m, Hertz coefficient k) under static force f0, overlap
 * d0 = (f0/k)^(2/3) on every contact, linear stiffness
 * kappa = (3/2) k^(2/3) f0^(1/3), omega(q) = 2 sqrt(kappa/m) |sin(q a/2)|,
 * a = 2R - d0. The chain starts at equilibrium with small random velocities, is
 * integrated by the solver layer, its bead velocities are sampled at uniform
 * times and the space-time power spectrum |V(q, omega)|^2 (FFTW r2c, Hann window
 * in time) gives the ridge omega(q). SI units; wavenumbers in lattice units q a
 * (rad per bead). */

typedef enum {
    GW_CHAIN_DISP_PERIODIC = 0, /* bead n-1 touches bead 0; q a = 2 pi j / n */
    GW_CHAIN_DISP_FIXED = 1     /* beads 0 and n-1 touch fixed rigid neighbours (same
                             contact law); standing modes q a = pi j / (n + 1) */
} gw_chain_disp_ends;

typedef struct gw_chain_disp_params {
    int n;                /* beads, >= 8 */
    double f0;            /* static precompression, N, > 0 (d0 < radius) */
    double mass;          /* bead mass, kg */
    double k;             /* bead-bead Hertz coefficient, N/m^1.5 */
    double radius;        /* bead radius, m (spacing a = 2R - d0) */
    gw_chain_disp_ends ends;
    double amp;           /* rms overlap perturbation of the initial velocities
                             relative to d0, in (0, 0.1] (linear regime) */
    unsigned long seed;   /* random mode phases of the initial velocities (every
                             mode gets the same amplitude; deterministic) */
    int t_samples;        /* velocity samples in time, even, >= 64 */
    double dt_sample;     /* sampling interval, s; 0 = pi / (1.25 omega_c), i.e.
                             omega_c at 80 % of the Nyquist frequency */
    int steps_per_sample; /* RK4 steps per sampling interval (fixed step) */
    double min_bins;      /* a ridge is resolved when its frequency is at least
                             this many frequency bins (2 pi / T) above zero; a
                             whole number (a count the ABI holds as a double) in
                             [1, t_samples/2 - 2]: the ridge is looked for in the
                             bins below t_samples/2 - 1 (the last bins of the
                             one-sided spectrum have no neighbour to refine the
                             peak), so a larger value resolves nothing */
    int fftw_measure;     /* 1: plan with FFTW_MEASURE, 0: FFTW_ESTIMATE */
} gw_chain_disp_params;

/* Smallest amp: the perturbation, amp d0 on overlaps of d0, is resolved only
 * well above d0's rounding (2.2e-16 d0). Measured against amp 1e-3 (n 1024,
 * 16 and 64 fixed, rk4 and cvode): 1e-13 moves the ridge by 6e-6 at most, 1e-15
 * by 1 to 2 %, 1e-16 by 5 to 14 % (exit 0 before), 1e-20 leaves no ridge. */
#define GW_CHAIN_DISP_AMP_MIN 1e-12

/* Largest min_bins of any run: t_samples/2 - 2 at the largest t_samples, 2^24. */
#define GW_CHAIN_DISP_MIN_BINS_MAX ((double)((1 << 23) - 2))

/* Steel beads of gw_chain_params_default, n = 1024, f0 = 10 N, periodic,
 * amp = 1e-3, seed 1, 2048 samples, dt_sample 0 (auto), 16 RK4 steps per sample,
 * min_bins 8, FFTW_ESTIMATE. */
gw_chain_disp_params gw_chain_disp_params_default(void);

/* Check every field; GW_EINVAL with a message naming the field by its option
 * name in `granwave dispersion` (--n, --f0, --t-samples, ...). */
/* The sampling interval, s: dt_sample when > 0, the default pi / (1.25
 * omega_c) when it is 0; NaN for a NULL p and a dt_sample that is NaN,
 * negative or infinite (refused by gw_chain_disp_params_validate as dt-out). */
double gw_chain_disp_dt_sample(const gw_chain_disp_params *p);

int gw_chain_disp_params_validate(const gw_chain_disp_params *p, gw_err *err);

/* Linear contact stiffness kappa = (3/2) k^(2/3) f0^(1/3), N/m; NaN for k or
 * f0 negative or NaN (a negative f0 gave a negative kappa before session 34). */
double gw_chain_disp_kappa(double k, double f0);
/* omega(q) = 2 sqrt(kappa/m) |sin(qa/2)|, rad/s, for qa in rad per bead; NaN
 * for kappa negative or NaN and for m not > 0 (m = 0 gave inf). */
double gw_chain_disp_omega(double kappa, double m, double qa);

typedef struct gw_chain_disp_result {
    int nq;               /* wavenumbers reported (j = 1..nq) */
    double *qa;           /* [nq] q a, rad per bead */
    double *omega_ridge;  /* [nq] frequency of maximum power, rad/s (parabolic
                             interpolation of log power over three bins) */
    double *omega_theory; /* [nq] docs/physics.md 1.6 */
    double *ridge_power;  /* [nq] power at the ridge bin */
    int *resolved;        /* [nq] 1 when the ridge counts (see min_bins) */
    int n_omega;          /* frequency bins 0 .. t_samples/2 */
    double d_omega;       /* bin spacing 2 pi / (t_samples dt_sample), rad/s */
    double *power;        /* [nq * n_omega] |V(q_j, omega_l)|^2 (q and -q summed),
                             row j-1, m^2/s^2 (unnormalised FFT) */
    double d0, kappa, a;  /* m, N/m, m */
    double omega_c_theory, omega_c_measured, omega_c_rel_err; /* rad/s, -, - */
    double omega_edge;    /* highest frequency where the q-summed power is above
                             1e-3 of its peak, rad/s (a second cutoff estimate) */
    double ridge_max_rel_err; /* max |ridge - theory| / theory, resolved q */
    int n_resolved;
    double qa_resolved_min, qa_resolved_max;
    double c0_theory;     /* a sqrt(kappa/m), m/s */
    double c0_measured;   /* a * intercept of a line through omega/(qa) against
                             (qa)^2 over resolved qa <= 0.5 (NaN if < 3 points) */
    double max_overlap_dev; /* max |d - d0| / d0 over contacts and samples */
    double dt_sample, dt_step, t_total; /* s */
    double integrate_ms, fft_ms;
    gw_solver_stats stats;
} gw_chain_disp_result;

/* The warning of a dispersion run whose spectrum resolved no wavenumber
 * (n_resolved 0: the ridge error is NaN), appended to *list as
 * gw_chain_result_warnings. */
int gw_chain_dispersion_warnings(const gw_chain_disp_result *r, char **list);

/* Integrate the chain with solver type (NULL: rk4) and settings sp, then
 * transform and extract the ridge. rk4 steps at dt_sample / steps_per_sample
 * (sp->dt ignored); sp->method GW_METHOD_DEFAULT means adams for cvode and erk
 * for arkode (the linear chain is not stiff); bdf and dirk use a band solver
 * with a finite-difference Jacobian and are refused for periodic ends
 * (GW_EUNSUPPORTED: the ring's Jacobian is not banded). r is zeroed first; free
 * it with gw_chain_disp_result_free, also after a failure (arrays may then be
 * NULL). Returns GW_EINVAL (parameters), GW_ENOMEM, GW_EUNSUPPORTED,
 * GW_ESOLVER / GW_ELIMIT (backend message and time in err). */
int gw_chain_disp_run(const gw_chain_disp_params *p, const gw_solver_type *solver,
                      const gw_solver_params *sp, gw_chain_disp_result *r, gw_err *err);
/* The same with progress(pctx, k, t_samples) (may be NULL) after each of the
 * t_samples velocity samples is integrated (the transform after the last
 * takes about a tenth of the run: 0.5 of 4.5 s at n 8192); non-zero stops the run: GW_ECANCELED, r as after a
 * failure. */
int gw_chain_disp_run_progress(const gw_chain_disp_params *p, const gw_solver_type *solver,
                               const gw_solver_params *sp, gw_progress_fn progress, void *pctx,
                               gw_chain_disp_result *r, gw_err *err);
void gw_chain_disp_result_free(gw_chain_disp_result *r);

/* Power spectrum of a column's wall force (the plateau oscillation, 1/P). */
typedef struct gw_chain_spectrum {
    int len;         /* bins 0 .. len-1 */
    double df;       /* bin spacing, Hz */
    double *freq;    /* [len] Hz */
    double *power;   /* [len] |dt sum_i w_i (F_i - mean) e^(-2 pi i f t_i)|^2, N^2 s^2 */
    double f_peak;   /* dominant peak of f^2 power (the spectrum of dF/dt, which
                        the contact's envelope does not dominate) above f_min,
                        Hz, refined by a parabola through its log */
    double f_min;    /* lowest frequency searched, Hz */
    double dt;       /* uniform resampling interval, s */
    int samples;     /* uniform samples in [t0, t1] (before zero padding) */
} gw_chain_spectrum;

/* Resample tr->f linearly onto t0 + i dt in [t0, t1] (events make the trace
 * non-uniform), remove the mean, apply a Hann window, zero-pad 8x and take the
 * r2c FFT. dt <= 0: the median trace spacing; f_min <= 0: 4 / (t1 - t0) (above
 * the envelope of the contact). GW_EINVAL for fewer than 16 samples, a force
 * not finite in [t0, t1], a bad interval, or a dt or f_min NaN or infinite
 * (naming it), GW_ENOMEM. sp is zeroed first; free with gw_chain_spectrum_free. */
int gw_chain_wall_spectrum(const gw_chain_trace *tr, double t0, double t1, double dt,
                           double f_min, int fftw_measure, gw_chain_spectrum *sp,
                           gw_err *err);
void gw_chain_spectrum_free(gw_chain_spectrum *sp);

/* ---- the whole drop (chain_drop.c) ----
 * The column released from rest with bead 1 at a height h above the sensor, under
 * gravity g toward the sensor, followed from the first contact (t = 0) through
 * the first collision, detachment, free flight and the bounces that follow, up to
 * t_max. The fall before t = 0 is uniform acceleration with no contact force, so
 * the state at t = 0 is exact: every bead moves at v_imp = sqrt(2 g h) and the
 * gaps are those of the release (physics.md 1.2). Definitions (time origin at the
 * first contact; F = gw_chain_wall_force, the force the sensor reads):
 *   contact episode  a maximal interval with x_1 > 0 (bead 1 overlaps the sensor),
 *                    bounded by located roots of x_1
 *   peak             a local maximum of F: a located falling root of the rate
 *                    function R with R = dF/dt / sqrt(x_1) (undamped, Hunt-Crossley)
 *                    or sqrt(x_1) dF/dt (Kuwabara-Kono), the acceleration of bead 1
 *                    taken from the equations of motion, with F > 0 and
 *                    F >= peak_threshold
 *   impact           a contact episode whose largest force is >= peak_threshold;
 *                    its f_max is its largest peak
 * so that neither depends on the output sampling. */

typedef struct gw_chain_drop_params {
    gw_chain_params chain; /* the column; chain.v_imp is replaced by sqrt(2 g h),
                              chain.gravity = g > 0 */
    double height;         /* fall of bead 1 to the sensor, m,
                              [GW_CHAIN_DROP_H_MIN, GW_CHAIN_DROP_H_MAX] */
    const double *gaps;    /* [n-1] initial gaps between beads i and i+1, m, in
                              [0, GW_CHAIN_DROP_GAP_MAX], caller-owned; NULL = touching */
    double t_max;          /* time followed after the first contact, s,
                              [GW_CHAIN_DROP_T_MIN, GW_CHAIN_DROP_T_MAX] */
    double peak_threshold; /* N, >= 0 (see peak and impact above) */
} gw_chain_drop_params;

/* the lower ends are the program's (the study table's rows): a subnormal
 * height or t-max passed (0, ...] and failed later as "the solution blew up" */
#define GW_CHAIN_DROP_H_MIN 1e-6   /* m */
#define GW_CHAIN_DROP_H_MAX 1.0    /* m: 4.4 m/s at the sensor on Earth */
#define GW_CHAIN_DROP_GAP_MAX 0.1  /* m */
#define GW_CHAIN_DROP_T_MIN 1e-6   /* s */
#define GW_CHAIN_DROP_T_MAX 1.0    /* s */
#define GW_CHAIN_DROP_G_MIN 1e-3   /* m/s^2 */

/* The chain defaults (steel, R = 4 mm) with g = 9.81 m/s^2, h = 5.1 mm, touching
 * beads, t_max = 10 ms, peak_threshold = 0.7 N (1 % of F_max(1) at that h). */
gw_chain_drop_params gw_chain_drop_params_default(void);
/* Check every field (and the column's); GW_EINVAL with a message naming it. */
int gw_chain_drop_params_validate(const gw_chain_drop_params *p, gw_err *err);

typedef struct gw_chain_drop_impact {
    double t_start, t_end; /* s; t_end NaN when still in contact at t_max */
    double f_max, t_fmax;  /* largest peak of the episode, N, and its time, s */
    double v_in, v_out;    /* velocity of bead 1 at start and end, m/s (toward the
                              sensor > 0; v_out NaN while in contact) */
    int n_peaks;           /* peaks of the episode */
    int cluster;           /* beads joined to the sensor by closed contacts at f_max */
    int located;           /* 1: f_max is a located peak; 0: no peak was located
                              (a sensor body's reading still rising as bead 1
                              leaves), f_max is the largest of the samples and
                              of the force at the contact's end event */
    double chatter;        /* the drop's chatter check (gw_chain_drop_result's
                              chatter_kind): |f_max - the rerun's| / f_max of this
                              impact in a rerun at tighter tolerances, 1 when the
                              rerun has no such impact; NaN when not run again */
} gw_chain_drop_impact;

typedef struct gw_chain_drop_peak {
    double t, f;   /* s, N */
    int impact;    /* index into impacts */
    int cluster;   /* beads 1..cluster joined to the sensor by closed contacts */
} gw_chain_drop_peak;

typedef struct gw_chain_drop_result {
    int n;
    double v_imp, t_fall;   /* sqrt(2 g h), m/s; sqrt(2 h / g), s */
    gw_chain_result first;  /* the first collision, by gw_chain_collide from the
                               same state with the same settings (its own default
                               sampling, tau_1/200), as `granwave chain` reports it;
                               it ends at the chain's end (every contact open, every
                               pair separating) or at the latest half way between
                               bead 1 leaving the sensor and touching it again
                               (converged = 0 then) */
    int first_status;       /* GW_OK, or GW_ELIMIT when t_max ended it early */
    gw_chain_drop_peak *peaks;
    unsigned char *peak_contacts; /* [n_peaks * n]: contact k closed at peak j is
                                     peak_contacts[j n + k] (k = 0: the sensor,
                                     k >= 1: beads k and k+1) */
    int n_peaks;
    gw_chain_drop_impact *impacts;
    int n_impacts;          /* episodes reaching peak_threshold */
    int n_episodes;         /* every contact episode of bead 1 with the sensor */
    double f_max, t_fmax;   /* largest peak of the run (NaN, NaN: no peak) */
    gw_chain_energy e_end;  /* ledger at t_end (gravity potential -m g x, x = 0 at
                               the first contact) */
    double e0;              /* energy at t = 0, J (n m g h for touching beads) */
    double energy_error;    /* max |E(t) - e0| / e0 over samples and events */
    double t_end;
    long n_events, missed_events;
    gw_solver_stats stats;
    double run_dt, run_dt_max; /* the step the run used (rk4: at most dt_max and dt_out;
                                  cvode, arkode: their first, 0 when their own)
                                  and its step cap, s: the defaults resolved */
    double run_dt_given;       /* the dt given (0: none), s; above run_dt: warned */
    int first_cut;          /* 1: t_max came before the first collision's end (it
                               ran to t_max): its results are those at t_max */
    int open_at_t_max;      /* 1: bead 1 still on the sensor at t_end: the last
                               episode is open (t_end, v_out NaN; its peaks and
                               f_max those so far) */
    /* Bead 1's chatter on a sensor body over the drop: GW_CHAIN_CHATTER_CONTACTS
     * contact episodes or more on a sensor body amplify the integration's
     * error (drop --n 3 --sensor-mass 1e-4 --sensor-stiffness 1e3: 44 in
     * 10 ms, the impacts' F_max moving by 6e-8 at the first and 1e-5 at the
     * 21st between rtol 1e-12 and 1e-13). Checked as gw_chain_result's
     * (chatter_kind GW_CHAIN_CHATTER_*, the rerun at 10 times tighter
     * tolerances, rk4: half the step, when the drop's steps times bodies are
     * at most GW_CHAIN_CHATTER_WORK), the spread the largest of the impacts'
     * chatter (MOVED above GW_CHAIN_CHATTER_SPREAD; else 0). Under rk4 the
     * rerun (half the step) costs twice the drop's steps, known before it is
     * made, and is made up to GW_CHAIN_DROP_CHATTER_RK4_WORK steps times
     * bodies (drop --n 3 --sensor-mass 1e-4 --sensor-stiffness 1e3 --solver
     * rk4: 9.8e5 steps, 0.13 s of CPU, its rerun 1.95e6 steps and 0.25 s;
     * --sensor-mass 1e-6 --sensor-stiffness 1e5: 6.0e6 steps, the rerun 1.2e7
     * steps and 1.25 s).
     * chatter_rerun: how it is (or would be) run again, GW_CHAIN_RERUN_*, set
     * with the sensor body (gw_chain_drop_result_warnings names it). */
    int chatter_kind;
    double chatter_spread;
    int chatter_rerun;
} gw_chain_drop_result;

/* Impacts whose largest force exceeds the previous impact's by more than
 * GW_CHAIN_DROP_RISE_REL of it. Two impacts equal in exact arithmetic (a lone
 * elastic bead bouncing) differ by the integration's error, 1e-10 to 1e-9: counted
 * as they fell, cvode gave 4 rises in 5 impacts and rk4 none. 0 for r NULL or
 * r->impacts NULL (a result filled by hand: read through NULL before session 41). */
#define GW_CHAIN_DROP_RISE_REL 1e-6
int gw_chain_drop_impact_rises(const gw_chain_drop_result *r);
/* Run the drop with run options o (solver and its settings, dt_out = signal
 * sampling, 0 = 1 us; energy_tol; sample callback, called at every sample and
 * event; o->t_max and o->y0 are ignored, p->t_max rules). r is zeroed first and
 * must be freed with gw_chain_drop_result_free, also after a failure. Returns
 * GW_OK, GW_EINVAL (parameters), GW_ENOMEM, GW_ESOLVER / GW_ELIMIT / GW_EENERGY
 * with the backend's message and the time in err (r then holds what was
 * measured up to the failure). GW_ELIMIT too, naming the damping and its
 * constant, when a contact damping far above critical held bead 1 inside its
 * first impact to t_max (as gw_chain_collide fails on that collision). */
int gw_chain_drop_run(const gw_chain_drop_params *p, const gw_chain_run_opts *o,
                      gw_chain_drop_result *r, gw_err *err);
/* The same with progress(pctx, done, total) (may be NULL) in output samples of
 * the run's two passes: the drop over t_max (t / dt_out), then its first
 * collision run again by the chain's code (gw_chain_collide; at most t_max more,
 * about as much work again), total = 2 t_max / dt_out; called at most about
 * every hundredth of total, and once with done = total at the end (the first
 * collision's pass may end early). A non-zero return stops the run there:
 * GW_ECANCELED "drop: stopped by the progress callback ...", r holding what
 * was measured. */
int gw_chain_drop_run_progress(const gw_chain_drop_params *p, const gw_chain_run_opts *o, gw_progress_fn progress,
                               void *pctx, gw_chain_drop_result *r, gw_err *err);
void gw_chain_drop_result_free(gw_chain_drop_result *r);
/* The warning of a drop cut at t_max (first_cut: inside the first collision;
 * open_at_t_max: bead 1 still on the sensor), appended to *list as
 * gw_chain_result_warnings; nothing otherwise. A column at rest at t_max
 * (kinetic energy below a millionth of e0) is said to be held on the sensor
 * by its weight, which no t-max ends, instead of "raise --t-max" (the drop
 * study's text also names the contact damping). */
int gw_chain_drop_result_warnings(const gw_chain_drop_result *r, char **list);

/* ---- the chain as a sweep model (chain_sweep_model.c, see gw_sweep.h) ---- */

struct gw_sweep_model;
extern const struct gw_sweep_model gw_chain_sweep_model;
/* The model's run with part(pctx, x) (gw_sweep_part_fn, may be NULL) at every
 * output sample and event of the case's collision: x the share of its work
 * done by its simulated time, under 1 (a tenth of it in the tail the run goes
 * on past t_expect until every contact is open and separating). The results
 * are the run's, bit for bit. */
int gw_chain_sweep_run_part(int nkeys, const char *const *names, const char *const *values, double *out,
                            unsigned long long *read_hash, void (*part)(void *pctx, double x), void *pctx,
                            gw_err *err);

GW_END_DECLS

#endif
