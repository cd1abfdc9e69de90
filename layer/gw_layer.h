/*
 * gw_layer.h: the 2D granular layer of Bourrier et al. (2008) (docs/physics.md
 * section 2): Hertz-Mindlin discs with Coulomb friction in a box with rigid walls,
 * integrated as one ODE system through the granwave solver layer; pluviated
 * samples; block impacts with an energy ledger and a crowns (shock-wave) analysis.
 *
 * Units: SI everywhere (m, s, kg, N, J, rad; angles given in degrees where the
 * name says _deg). The box spans 0 <= x <= width, gravity acts along -y, the
 * bottom wall is y = 0.
 *
 * State vector of a gw_layer (dimension 6 n_b + n_c + 2, rebuilt with the contact
 * list): per rigid body k: x, y, theta, vx, vy, omega of its centre of mass
 * (6 k .. 6 k + 5); per listed contact c: its tangential elastic force F_t
 * (6 n_b + c); then the dissipated energy E_d and the Mindlin stiffness-variation
 * work W_K (see layer_model.c). A body is one disc (type A soil; then n_b = n and
 * body k is particle k) or a rigid clump of discs (type B, layer_clumps.c).
 *
 * Errors: every fallible call returns GW_OK or a negative gw status and fills a
 * gw_err naming the offending input. A failed call leaves no half-built object
 * (*out is NULL) and no half-written file.
 */
#ifndef GW_LAYER_H
#define GW_LAYER_H

#include "gw_common.h"
#include "gw_solver.h"

#include "gw_api.h"

GW_BEGIN_DECLS /* the exported interface, C linkage (gw_api.h) */

/* ---------------------------------------------------------------- model ---- */

enum { GW_LAYER_MASS_DISC = 0, GW_LAYER_MASS_SPHERE = 1 };
/* Mass of a rigid clump (gw_layer_params.clump_mass, layer_clumps.c). */
enum { GW_LAYER_CLUMP_MASS_SUM = 0, GW_LAYER_CLUMP_MASS_UNION = 1 };

/* Wall bits for gw_layer_params.walls. */
enum { GW_LAYER_WALL_LEFT = 1, GW_LAYER_WALL_RIGHT = 2, GW_LAYER_WALL_BOTTOM = 4,
       GW_LAYER_WALLS_ALL = 7 };

/* The smallest contact-list skin, m. The rebuild test compares squared
 * distances with (skin/2)^2 less a margin (layer_model.c): below about 1e-154 m
 * that square underflows to 0, no particle ever crosses it, the list is never
 * rebuilt, and the discs fell through each other (layer-make --skin 1e-300: a
 * NaN porosity blamed on "contacts too soft for their load"). A femtometre is
 * far below any disc (R_m >= 1e-5 m) and far above the underflow; a run whose
 * particles outrun a small skin is refused by the rebuild's own check. */
#define GW_LAYER_SKIN_MIN 1e-15

typedef struct gw_layer_params {
    double shear_modulus; /* G, Pa [40e9] */
    double poisson;       /* nu, in [0, 0.5) [0.25] */
    double friction_deg;  /* phi, deg in [0, 90) [30] */
    double density;       /* kg/m^3 [2650] */
    double gravity;       /* m/s^2 along -y [9.81] */
    double width;         /* box width 2L, m (walls at x = 0 and x = width) [16.25] */
    int walls;            /* GW_LAYER_WALL_* mask [all] */
    int mass_law;         /* GW_LAYER_MASS_DISC (unit thickness, m = rho pi R^2,
                             I = m R^2 / 2) or _SPHERE (m = 4/3 rho pi R^3,
                             I = 2/5 m R^2) [disc] */
    int clump_mass;       /* GW_LAYER_CLUMP_MASS_SUM: a clump weighs the sum of its
                             members (overlaps counted twice, as PFC2D clumps);
                             _UNION: density x the area of the members' union
                             (disc mass law only) [sum] */
    double damping;       /* Hunt-Crossley normal damping alpha, s/m [0 = none, as
                             the paper]; used to settle pluviated samples */
    double skin;          /* Verlet skin of the contact list, m, in
                             [GW_LAYER_SKIN_MIN, 1e6] [0.1] */
    int no_events;        /* 1: do not stop at contact openings/closings and
                             stick/slip switches: faster, lower order; used for
                             pluviation. With rk4 and no block watch the list
                             rebuild is then checked at the steps' ends (as
                             verlet does) and F_t of open contacts zeroed after
                             every step: the run does not depend on the skin [0] */
    int potential_from_start; /* 1: gravitational energy measured from the initial
                                 positions (A = initial kinetic + strain energy);
                                 0: from y = 0 [0] */
} gw_layer_params;

gw_layer_params gw_layer_params_default(void);

/* Check a parameter set; GW_EINVAL with a message naming the parameter. */
int gw_layer_params_validate(const gw_layer_params *p, gw_err *err);

/* Hertz normal coefficient K_n (B.3) and Mindlin factor k_t with
 * K_t = k_t F_n^(1/3) (B.4) for the mean radius R_p (m); NaN for p NULL or
 * R_p negative or NaN (k_t was negative there before session 34). */
double gw_layer_kn(const gw_layer_params *p, double rp);
double gw_layer_kt_factor(const gw_layer_params *p, double rp);
/* Mass (kg) and moment of inertia (kg m^2) of a particle of radius r. */
double gw_layer_mass(const gw_layer_params *p, double r);
double gw_layer_inertia(const gw_layer_params *p, double r);
/* "disc (unit thickness)" or "sphere"; "sum" or "union"; "unknown" for a
 * value that is none of them (before session 34 it was named "disc" or "sum",
 * the law a run does not take). */
const char *gw_layer_mass_law_name(int mass_law);
const char *gw_layer_clump_mass_name(int clump_mass);
/* The GW_LAYER_CLUMP_MASS_* that gw_layer_clump_mass_name names ("sum",
 * "union"), -1 for any other string. */
int gw_layer_clump_mass_parse(const char *name);

/* One particle's initial state. fixed = 1 freezes it (infinite mass, no motion).
 * clump = 0: the disc is a body of its own. clump = k > 0: all particles with
 * the same k form one rigid clump (type B soil): mass and moment of inertia as
 * gw_layer_params.clump_mass says (sum: over the members, parallel-axis terms
 * included, the area shared by overlapping members counted twice; union: of
 * the members' union), its velocity and spin at the centre
 * of mass are the vx, vy, w of its first member, and it is fixed when any
 * member is. */
typedef struct gw_layer_body {
    double x, y, r;    /* m */
    double vx, vy, w;  /* m/s, rad/s */
    int fixed;
    int clump;
} gw_layer_body;

typedef struct gw_layer gw_layer;

/* Build a layer of n particles (copied). Validates the parameters, bodies
 * (not NULL), each particle's x, y, r, vx, vy and w (finite; r > 0; the
 * centre inside the walls p keeps), GW_EINVAL "particle I: FIELD = V ..."
 * naming its index and field, and the clump ids (>= 0; members of a clump
 * must overlap or touch each other: connected; at most 64 members). */
int gw_layer_create(const gw_layer_params *p, int n, const gw_layer_body *bodies,
                    gw_layer **out, gw_err *err);
void gw_layer_free(gw_layer *L);

/* Build the contact list, the state and a solver of the given backend at t = 0.
 * Must be called once before gw_layer_advance. The solver is re-created by
 * every contact-list rebuild. L or sp NULL: GW_EINVAL naming it. */
int gw_layer_start(gw_layer *L, const gw_solver_type *type, const gw_solver_params *sp,
                   gw_err *err);

/* Integrate to tout. Stops at contact openings/closings (roots of the overlaps)
 * and restarts the solver there; when a particle has moved more than half the
 * skin since the last list, rebuilds the contact list, resizes the state and
 * re-creates the solver. GW_ESOLVER/GW_ELIMIT with the solver's message in err;
 * the layer then holds the last good state. A tout that is not finite, or
 * before the layer's time, is GW_EINVAL (the layer unchanged). One call is
 * bounded as the program's runs are: a tout more than 1e4 s after the layer's
 * time (layer-make's longest t-max), or a fixed step (verlet, rk4) taking
 * more than 1e9 steps or 1e10 particle-steps (steps times particles and
 * listed contacts) to it, is GW_EINVAL before any step (the layer unchanged;
 * advance in parts); an adaptive backend past those counts within the call
 * stops with GW_ELIMIT naming them (gw_layer_advance(L, 1e300) ran for
 * hours). */
int gw_layer_advance(gw_layer *L, double tout, gw_err *err);

/* Called at every contact event found by the solver's root finder: dir = +1
 * when contact (a, b) closes (u_n rises through 0), -1 when it opens; b < 0 is a
 * wall (-1 left, -2 right, -3 bottom). Events of particles crossing the skin
 * are not reported. */
typedef void (*gw_layer_event_fn)(void *ctx, double t, int a, int b, int dir);
void gw_layer_set_event_hook(gw_layer *L, gw_layer_event_fn fn, void *ctx);

/* Block watch: event functions on the block (the particle marked by
 * gw_layer_set_block), so that an impact's outcome is read from events on the
 * block, never from output samples. Two functions join the layer's roots:
 *   GW_LAYER_BLOCK_VN:    the block's normal (vertical) velocity v_y;
 *   GW_LAYER_BLOCK_TOUCH: the largest overlap u_n of the block's listed
 *                         contacts, walls included (negative: free flight).
 * fn is called at each of their zero crossings with dir = +1 (rising: v_y
 * turns upward; the first contact closes) or -1 (v_y turns downward; the last
 * contact opens), the time and the block's state there. With the located
 * backends (rk4, cvode, arkode) the solver stops at the root and ev is the
 * state there; with verlet (roots reported at the end of the step, not
 * located) the time and state are interpolated linearly inside that step from
 * the block's own state at the step's two ends. Watch roots change nothing in
 * the run: neither the projection nor a solver restart follows them. Several
 * crossings in one step are reported in time order.
 * The running extremes of the block (largest v_y, lowest centre) are taken
 * over every state the event functions are evaluated at: each step end, and
 * with the located backends also the root finder's trial points (states of
 * the same solution).
 * Must be called before gw_layer_start, after gw_layer_set_block; GW_EINVAL
 * otherwise (the layer unchanged). fn may be NULL (extremes only). */
/* GW_LAYER_BLOCK_GONE is no root: reported once, at the first evaluation of
 * the event functions at which the block has left the layer for good; dir =
 * GW_LAYER_GONE_*. Without the bottom wall, touching nothing and moving away
 * from every other body at least as fast as any of their points: below the
 * lowest point of them all, or beyond a side of them without that side's wall.
 * With the bottom wall, by geometry alone (session 44): its whole body beyond
 * where a missing side wall would be (x = 0 or the width) and beyond every
 * other body, so touching none of them, moving or at rest on the floor. Only
 * a layer with a wall missing can see it. */
enum { GW_LAYER_BLOCK_VN = 0, GW_LAYER_BLOCK_TOUCH = 1, GW_LAYER_BLOCK_GONE = 2 };
enum { GW_LAYER_GONE_BELOW = 1, GW_LAYER_GONE_LEFT = 2, GW_LAYER_GONE_RIGHT = 3 };
typedef struct gw_layer_block_event {
    int kind;             /* GW_LAYER_BLOCK_VN, _TOUCH or _GONE */
    int dir;              /* +1 rising, -1 falling through zero (_GONE: GW_LAYER_GONE_*) */
    double t;             /* s */
    double x, y, vx, vy;  /* block centre (m) and velocity (m/s) at t */
    int located;          /* 1: solver-located root; 0: interpolated in a verlet step */
} gw_layer_block_event;
typedef void (*gw_layer_block_fn)(void *ctx, const gw_layer_block_event *ev);
int gw_layer_watch_block(gw_layer *L, gw_layer_block_fn fn, void *ctx, gw_err *err);

typedef struct gw_layer_block_extremes {
    double vy_max, t_vy_max, vx_at_vy_max; /* largest v_y so far (m/s), when (s), v_x then */
    double y_min, t_y_min;                 /* lowest block centre so far (m), when (s) */
    int n;                                 /* states seen */
} gw_layer_block_extremes;
/* The running extremes since gw_layer_start (n = 0 without a watch). */
void gw_layer_block_extremes_get(const gw_layer *L, gw_layer_block_extremes *ex);

typedef struct gw_layer_stats {
    long steps, rhs_evals, events, rebuilds, contacts_listed, projections, zeno_guards;
} gw_layer_stats;
void gw_layer_get_stats(const gw_layer *L, gw_layer_stats *st);

int gw_layer_n(const gw_layer *L);
double gw_layer_time(const gw_layer *L);
/* Current state of particle i: centre x, y, its body's theta, the velocity
 * vx, vy of the disc centre, its body's omega. */
void gw_layer_particle(const gw_layer *L, int i, double s[6]);
double gw_layer_radius(const gw_layer *L, int i);
/* Mass (kg) and moment of inertia about its centre of mass (kg m^2) of the
 * rigid body particle i belongs to. */
double gw_layer_particle_mass(const gw_layer *L, int i);
double gw_layer_particle_inertia(const gw_layer *L, int i);
/* Rigid bodies: their number (n without clumps), the body of particle i, and
 * body k's state x, y, theta, vx, vy, omega at its centre of mass. */
int gw_layer_body_count(const gw_layer *L);
int gw_layer_body_of(const gw_layer *L, int i);
void gw_layer_body_state(const gw_layer *L, int k, double s[6]);
/* The layer's parameters: NULL for a NULL L. */
const gw_layer_params *gw_layer_get_params(const gw_layer *L);
/* Number of closed contacts (u_n > 0) of particle i, walls included. */
int gw_layer_contact_count(const gw_layer *L, int i);
/* Mark particle i as the block: its kinetic energy is booked as E_k,b. An i
 * outside [0, n) marks none (-1: the way to unmark). */
void gw_layer_set_block(gw_layer *L, int i);

/* Energy ledger (B.7-B.14), J. */
typedef struct gw_layer_energy {
    double kinetic_block;   /* (1/2) M V^2 + (1/2) I w^2 of the block */
    double kinetic_soil;    /* same summed over the other particles */
    double strain_normal;   /* sum (2/5) K_n u_n^(5/2) */
    double strain_tangent;  /* sum F_t^2 / (2 K_t) */
    double mindlin_excess;  /* W_K: tangential strain work not in F_t^2/(2K_t) */
    double dissipated;      /* E_d: friction sliding (+ normal damping if on) */
    double potential;       /* sum m g (y - y_ref) */
    double total;           /* sum of all of the above */
} gw_layer_energy;

void gw_layer_energy_of(const gw_layer *L, gw_layer_energy *e);
/* Initial total A (set by gw_layer_start). */
double gw_layer_energy_initial(const gw_layer *L);

/* Energy regions (docs/physics.md 2.4): rings k = 0 .. nring-1 of width w (m)
 * around (cx, cy) (distance in [k w, (k+1) w)), region nring = outside the
 * rings, region nring + 1 = the block and its contacts. Kinetic and potential
 * energy go by particle centre, strain energy, friction dissipation and W_K by
 * contact point; dissipation and W_K are integrated per region as part of the
 * ODE state. Must be called before gw_layer_start (GW_EINVAL otherwise; the
 * layer is unchanged on failure). cx, cy finite; w finite, a normal double
 * whose square is one too (w >= 1.49167e-154 m: a subnormal is refused as
 * the program's options refuse one); nring in [1, 10000]. */
int gw_layer_set_regions(gw_layer *L, double cx, double cy, double w, int nring, gw_err *err);
/* Number of regions (nring + 2, or 0 when none were set). */
int gw_layer_region_count(const gw_layer *L);
/* Ledger per region into out[gw_layer_region_count(L)]; the regions add up to
 * gw_layer_energy_of. Returns the number of regions filled. */
/* gw_layer_energy_of into *e and gw_layer_region_ledger into regions in one
 * pass over the contacts (either may be NULL); returns the region count
 * written (0 without regions or with regions = NULL). */
int gw_layer_ledgers(const gw_layer *L, gw_layer_energy *e, gw_layer_energy *regions);
int gw_layer_region_ledger(const gw_layer *L, gw_layer_energy *out);

/* Per-ring energies around (cx, cy): ring k holds distances [k w, (k+1) w).
 * Kinetic energy by particle centre (block excluded), strain energy (normal +
 * tangential state function) by contact point, coordination = contacts with
 * u_n > 0 counted per particle / particles. Arrays of nring entries (nring
 * <= 0: nothing done). What gw_layer_rings_check refuses (a width w not
 * finite or <= 0, a centre not finite, L or an array NULL) fills the arrays
 * given with NaN: this call has no error argument (a width of 0 gave zeros,
 * every particle outside the rings, and NaN gave NaN, without a word). */
void gw_layer_rings(const gw_layer *L, double cx, double cy, double w, int nring,
                    double *kinetic, double *strain, double *coord);
/* The arguments of gw_layer_rings, each refusal one line naming it: GW_OK, or
 * GW_EINVAL for L NULL, cx or cy not finite, w not finite or <= 0 ("ring
 * width w = 0 m must be finite and > 0"), nring < 0, or an array NULL when
 * nring > 0. */
int gw_layer_rings_check(const gw_layer *L, double cx, double cy, double w, int nring, const double *kinetic,
                         const double *strain, const double *coord, gw_err *err);

/* Write a VTK legacy POLYDATA snapshot: points with radius, velocity, omega
 * (one vertex cell each); contacts with u_n > 0 as lines carrying F_n and F_t;
 * field data TIME (s); units in the title line. The title (not NULL) is
 * written as one line, a control character as \n or \xHH as in messages,
 * cut between characters at 120 bytes (a newline in it broke the format). */
int gw_layer_write_vtk(const gw_layer *L, const char *path, const char *title,
                       gw_err *err);
/* Write a ParaView collection (.pvd) of n snapshot files (names relative to
 * the .pvd's directory, UTF-8; '&', '<', '>', '"' and '\'' written as XML
 * entities) at times[k] s. GW_EINVAL naming the snapshot, nothing written,
 * for a name holding a control character or a byte of no whole UTF-8
 * character (no XML file holds them) and a time that is not finite. */
int gw_layer_write_pvd(const char *path, int n, const char *const *files, const double *times, gw_err *err);

/* -------------------------------------------------------------- samples ---- */

/* The material and gravity a pile settled under, as layer-make's settings
 * line records them (a "# settings: {...}" comment of a text sample, the
 * "settings: " line of an HDF5 sample's header attribute; both dialects, the
 * program's "material" object and the library's flat rows). recorded = 0: not
 * recorded (a hand-written sample, a file from before the settings line, a
 * sample built in memory, a settings line without material): the fields are
 * then unused and no check compares them. --modulus-factor settles with
 * F x G, then relaxes with G: G is recorded. A record set in memory
 * (recorded 1) is held by every call that takes the sample to what the
 * reader holds a settings line to (G, nu, phi, rho, g finite and within the
 * material's ranges, g > 0; mass_law the sample's; clump_mass the sample's
 * or -1): GW_EINVAL "sample 's': settled.FIELD ..." (before session 46 it was
 * taken as set: a NaN modulus gave a load ratio of NaN). */
typedef struct gw_layer_settled {
    int recorded;          /* 1: the fields below were read */
    double shear_modulus;  /* G, Pa */
    double poisson;        /* nu */
    double friction_deg;   /* phi, deg */
    double density;        /* kg/m^3 */
    double gravity;        /* m/s^2, > 0 (pluviation needs gravity) */
    int mass_law;          /* GW_LAYER_MASS_* */
    long line;             /* the settings line of a text sample (0: HDF5, or not recorded) */
    int clump_mass;        /* GW_LAYER_CLUMP_MASS_* the clumps settled under (the program's
                              material.clump_mass, the library's clump-mass); -1: the line
                              does not say (the sample's own clump_mass line applies).
                              Appended: a struct zeroed by an older caller reads sum */
    int unsettled;         /* 1: the pile did not settle: layer-make's "settled:" line says
                              converged 0 (text and HDF5 samples, also without a settings
                              line; gw_layer_make's sample when it did not converge). Its
                              positions are a pile in motion, grains in the air among them;
                              an impact on it warns (gw_layer_impact_settled_check). Kept in
                              the struct's padding after clump_mass (its size is unchanged);
                              0 in a struct zeroed by an older caller: nothing said */
} gw_layer_settled;

/* The tangential (Mindlin/Coulomb) spring of one contact of a settled pile,
 * which the pile leans on at rest: layer-make keeps every closed contact's
 * (gw_layer_make), a sample file carries them in an optional section, and an
 * impact starts its contacts from them (gw_layer_impact). Without them every
 * contact's F_t starts at zero and the pile sags into the impact until
 * friction builds up again (1000 discs: 5.9 kJ of potential energy lost in
 * 100 ms, the default block at 0.01 m/s on it). */
enum { GW_LAYER_SPRING_LEFT = -1, GW_LAYER_SPRING_RIGHT = -2, GW_LAYER_SPRING_BOTTOM = -3 };
typedef struct gw_layer_spring {
    int a, b;   /* the contact: particles a < b (indices into the sample), or particle a
                   against a wall b (GW_LAYER_SPRING_LEFT, _RIGHT, _BOTTOM) */
    double u;   /* the spring's elastic tangential displacement u_t = F_t / K_t, m: the
                   geometry of the spring, as the positions are the overlaps' (F_t along
                   t = (-n_y, n_x), n from a to b; the same value whichever disc is a).
                   An impact turns it into F_t = K_t u_t with its own K_t (B.4) and
                   clips that to its own Coulomb bound tan(phi) F_n: a friction below the
                   settling's starts those contacts sliding. At rest |u_t| <= tan(phi)
                   u_n (2 - nu) / (3 (1 - nu)), u_n the overlap (the bound F_t = tan(phi)
                   F_n through B.3, B.4: it does not depend on G or R_p) */
} gw_layer_spring;

/* A pluviated sample: positions and radii of settled soil particles. */
typedef struct gw_layer_sample {
    int n;
    double width;        /* box width, m */
    double rm;           /* mean radius R_m, m */
    double volume_ratio; /* largest / smallest particle volume */
    double porosity;     /* as measured by layer-make (gw_layer_sample_porosity);
                            NaN: unknown (read from a file without it; not written) */
    long seed;           /* the pluviation's seed, >= 0 (a record, not used by a run) */
    int mass_law;
    int clump_mass;      /* GW_LAYER_CLUMP_MASS_*, the law the clumps settled under */
    double *x, *y, *r;   /* [n], m; owned by the sample */
    int *body;           /* [n] rigid-body id of each particle in [0, n), or NULL
                            (every particle a disc); owned by the sample */
    unsigned long long content_hash; /* FNV-1a 64 of the file's bytes (gw_fnv1a64),
                            set by gw_layer_sample_read; 0 for a sample not read
                            from a file */
    gw_layer_settled settled; /* the settling's material (gw_layer_sample_read, gw_layer_make);
                                 recorded 0 when unknown. Appended: older callers that zero
                                 the struct get "not recorded" */
    int n_springs;              /* contacts whose tangential spring the sample carries; 0: none
                                   (an impact starts every F_t at zero, as before ABI 2) */
    gw_layer_spring *springs;   /* [n_springs], owned by the sample (NULL when none); each
                                   pair at most once, in contact (u_n > 0), discs of
                                   different bodies. ABI 2 */
    int settled_converged;      /* 1: layer-make's "settled:" line says converged 1 (text and HDF5
                                   samples; gw_layer_make's sample when it converged); 0: no such
                                   line, or converged 0 (settled.unsettled). An impact on a pile so
                                   marked whose floor carries less than half its weight under its
                                   recorded material warns that it did not settle. ABI 3 */
} gw_layer_sample;

void gw_layer_sample_free(gw_layer_sample *s);
/* sizeof(gw_layer_sample) in this library: a caller that lays the struct out
 * itself (a ctypes mirror) checks its own size against it before passing one
 * to gw_layer_sample_read, which writes the whole struct (a mirror without the
 * appended settled record was written 72 bytes past its end). */
size_t gw_layer_sample_size(void);

/* Text sample format (version 1), one record per line (LF or CRLF), '#' starts
 * a comment line, blank lines are skipped, lines other than comments are at
 * most 1024 characters:
 *   granwave-layer-sample 1
 *   width W          (m, > 0; required)
 *   rm R             (m, > 0; required)
 *   volume_ratio V   (>= 1; 0 when absent = unknown)
 *   porosity P       (in [0, 1], within 2e-3 of the particles' own; optional)
 *   seed S           (integer >= 0)
 *   mass_law disc|sphere   [disc]
 *   clump_mass sum|union   [sum; optional, written only for union]
 *   n N              (integer in [1, 1e7]; last header line)
 * then N lines "x y r" (m), each key at most once, nothing after the value.
 * Version 2 (written for clump samples, type B soil) is the same with a 4th
 * column: "x y r body", body an integer id in [0, N); particles sharing an id
 * form one rigid clump and must overlap or touch (members connected within
 * 1e-9 of the sum of radii), at most 64 per clump. Version 1 files read with
 * body = NULL. Either version may end with the springs (gw_layer_spring):
 *   springs M        (integer in [0, 8 (n + 1)])
 * then M lines "a b u": particle indices a and b (or a wall: left, right,
 * bottom) and the displacement u (m); without the section n_springs = 0.
 * HDF5 sample (format version 1, builds with HDF5): root attributes format =
 * "granwave-layer-sample", format_version = 1, granwave_version, width, rm,
 * volume_ratio, porosity (double), seed (integer), mass_law ("disc"/"sphere"),
 * clump_mass ("sum"/"union"; optional, written only for union),
 * n (integer), units and header (strings); datasets x, y, r of n doubles (m),
 * and for clump samples an integer dataset body (read when present, same
 * checks as the text column); the springs as datasets spring_a, spring_b
 * (integers, a wall GW_LAYER_SPRING_*) and spring_u (m) of M values, all
 * three or none.
 *
 * Write: HDF5 when path ends in .h5 or .hdf5 (GW_EUNSUPPORTED in a build
 * without HDF5), text otherwise; atomically (temporary name, then rename).
 * GW_EINVAL (nothing written) when s fails the reader's checks; header (may be
 * NULL) goes into comment lines / the "header" attribute. s->settled is not
 * written: a header's "settings: {JSON}" line records it (layer-make's does),
 * and a file without one reads back as "not recorded".
 * Read: the format is told by content (HDF5 signature), not by name. Every field
 * is checked the same way in both formats: finite, r > 0, inside the box
 * (0 <= x <= width, y >= 0, up to 0.02 r), n within limits and matching the
 * data, and a header that is the particles' (the grading of rm and
 * volume_ratio, a width the packing fills when it is more than one particle
 * high, a porosity within 2e-3 of gw_layer_sample_porosity's), and last the
 * springs (each pair once, of different bodies, in contact at the file's
 * positions, finite, within the recorded settling's Coulomb bound to 1e-3;
 * the writer checks them too, GW_EINVAL). GW_EFORMAT
 * (GW_EIO: unreadable; GW_EUNSUPPORTED: HDF5 file in a build without HDF5) with a message naming the file and the line or particle; s is
 * then empty (safe to free). The settling's record s->settled comes from the
 * header's settings line (a comment "# settings: {JSON}" in text, a line
 * "settings: {JSON}" of the HDF5 "header" attribute), the one line layer-make
 * writes there: absent, or JSON without material keys, reads recorded = 0; a
 * second such line, or one that is not a JSON object, or material values of
 * the wrong type, missing or outside the material rows' ranges, are
 * GW_EFORMAT naming the file and line (an altered file: remove the line to
 * read the sample as hand-written). The writer holds its header to what the
 * readers take back (since session 46; before, such files were written and
 * then refused): at most one settings line (after blanks), JSON the record's
 * parse takes against s, at most 65536 characters; no line over 1 MiB and no
 * carriage return inside a line (one before its newline is read as CR LF);
 * GW_EINVAL "sample 'PATH': header line K: ...", nothing written. HDF5 files are opened only in the 1.8 format or
 * later (metadata checksums; libhdf5 can crash on corrupt files without them).
 * HDF5's own error printing is silenced during both calls (under the
 * library's HDF5 lock: calls from several threads run one at a time) and
 * stays off after a failed HDF5 read, in the reading thread and in the thread
 * that exits the process (HDF5 1.10 prints at exit after some corrupt files). */
int gw_layer_sample_write(const gw_layer_sample *s, const char *path, const char *header,
                          gw_err *err);
int gw_layer_sample_read(const char *path, gw_layer_sample *s, gw_err *err);
/* GW_EUNSUPPORTED when path asks for HDF5 (.h5, .hdf5) and this build has no
 * HDF5; GW_EINVAL when path cannot be written as a sample (it names a FIFO,
 * device or directory, or its directory is missing or not writable; see
 * gw_out_file_check): lets a command refuse before a long run. GW_OK otherwise. */
int gw_layer_sample_format_check(const char *path, gw_err *err);
/* The same check, its messages naming `what` (the keyword or flag that gave the
 * path: "out" for layer-make, whose refusals said "sample: ..." where the
 * program's flag is --out and Python's keyword out; NULL: "sample"). */
int gw_layer_sample_out_check(const char *path, const char *what, gw_err *err);

/* Pluviation (docs/physics.md 2.2). */
/* The smallest modulus_factor a pluviation takes (the table's row and
 * gw_layer_make's check alike). */
#define GW_LAYER_MODULUS_FACTOR_MIN 1e-9
/* The mean radius R_m a pluviation takes, m (the make table's row; the
 * fiftieth pass held gw_layer_make to it: 1e-200 and 1e200 m failed later
 * naming no input). */
#define GW_LAYER_MAKE_RM_MIN 1e-5
#define GW_LAYER_MAKE_RM_MAX 1e3

typedef struct gw_layer_make_params {
    int n;                 /* particles [300] */
    double rm;             /* mean radius R_m, m [0.325] */
    double volume_ratio;   /* largest/smallest volume [10] */
    double width_rm;       /* box width in R_m [50] */
    long seed;             /* PRNG seed [1] */
    double ke_threshold;   /* stop when E_k < ke_threshold * m_total g R_m [1e-5] */
    double t_max;          /* give up after t_max s of simulated time [6] */
    double damping;        /* Hunt-Crossley alpha while settling, s/m [0.3] */
    double modulus_factor; /* settle with G * factor, then relax with true G, in
                              [GW_LAYER_MODULUS_FACTOR_MIN, 1] [1] */
    double dt;             /* fixed step, s [2e-5] */
    const gw_solver_type *solver; /* rk4 or verlet (explicit DEM), contact events
                                     not located either way [gw_solver_rk4] */
    double height_rm;      /* > 0: after settling keep only the particles lying
                              wholly below height_rm R_m (the box height H of
                              docs/physics.md 2.2) [0 = keep all] */
    int clumps;            /* 1: type B soil, n rigid clumps (layer_clumps.c) [0] */
    double aspect_max;     /* clumps: aspect ratio uniform in [1, aspect_max],
                              aspect_max in [1, 4]; 1 gives one-disc grains [4] */
    /* progress (may be NULL) [NULL]: called with progress_ctx after every 0.01 s
     * of simulated settling, done = the settled time in hundredths of a second,
     * total = t_max in the same unit (the pile usually settles before); a
     * non-zero return stops the pluviation (GW_ECANCELED) */
    gw_progress_fn progress;
    void *progress_ctx;
} gw_layer_make_params;

gw_layer_make_params gw_layer_make_params_default(void);

typedef struct gw_layer_make_result {
    double porosity;
    double t_settle;      /* simulated time, s */
    double ke_final;      /* J */
    double max_overlap;   /* largest u_n / R_p at the end */
    int converged;        /* the kinetic energy, with the fall of the grains in flight (touching
                             nothing: m g times their straight drop), went below the threshold
                             (ke_limit), the floor carrying 0.5 to 1.5 times the pile's weight
                             (or the floor and the side walls together, at 20 successive
                             checks 0.01 s apart: wall_load) */
    double wall_ms;
    long steps, rebuilds;
    int n_removed;        /* particles (clumps: grains) above height_rm R_m taken away */
    int n_bodies, n_discs; /* grains and discs in the sample */
    double t_judge;       /* s: the settling is judged from here on (0.1 s of settling, and the
                             lowest particle's free fall to the floor): a t_max below it cannot converge */
    double untrimmed_top_rm; /* height_rm > 0 that took nothing away: the settled pile's top in R_m
                                (at or below height_rm; the sample is the whole pile); else 0 */
    double floor_load;    /* the floor's Hertz forces over the pile's weight at the end (at rest:
                             about 1; gw_layer_impact_rest_check refuses above 1.5) */
    double fall_energy;   /* J: what the grains in flight at the end (touching nothing) land with */
    double ke_limit;      /* J: the threshold ke_threshold M g R_m the verdict held E_k + fall_energy
                             below (M: the sample's mass, after a trim) */
    double wall_load;     /* the side walls' friction (upward; negative: pulling down) over the pile's
                             weight at the end, from the springs the sample keeps against them: a pile
                             rests when floor_load or floor_load + wall_load lies in [0.5, 1.5] (the
                             rule gw_layer_impact_rest_check applies) */
    double ke_top_share;  /* the share of ke_final the one grain (clump or disc) that moves most
                             holds at the end, in [0, 1] (0: none moves). Near 1 on a pile that
                             did not settle: one grain rolling or rocking on a pile at rest (the
                             did-not-settle warning says so from 0.5 on) */
} gw_layer_make_result;

/* Pluviate a sample (lp: material, friction; width and mass law are taken from
 * mp / lp). Deterministic for a seed: a splitmix64 generator draws the radii
 * (uniform in radius between R_min and R_max = V^(1/3) R_min, mean R_m) and the
 * jitter of the initial grid. With mp->clumps (type B soil) it draws per clump
 * the equivalent radius from the same grading, the aspect ratio (uniform in
 * [1, aspect_max]) and the orientation; out->body then holds the clump of each disc and
 * out->n counts discs (res->n_bodies the clumps). A disc grid more than 100
 * times as high as the box is wide is refused (GW_EINVAL) before any work.
 * *out and *res are overwritten: zeroed first, whatever the call then returns
 * (a failure leaves them zeroed). A sample still holding the arrays of an
 * earlier gw_layer_make or gw_layer_sample_read must be freed
 * (gw_layer_sample_free) before it is passed as out again, else they leak:
 * nothing in the struct says who owns its arrays (one built in memory points
 * at its caller's), so the call never frees them. */
int gw_layer_make(const gw_layer_params *lp, const gw_layer_make_params *mp,
                  gw_layer_sample *out, gw_layer_make_result *res, gw_err *err);
/* The warnings of a pluviation, appended to *list (gw_warnings_add,
 * gw_common.h): one that did not settle (converged 0: t_max, s, the run's,
 * below t_judge, or at t_max E_k still above the threshold, the floor carrying
 * less than 0.5 or more than 1.5 of the pile's weight, or both, each said;
 * a wall_load other than 0 is named with the floor's and their sum, which
 * the bounds then apply to, and a pile within them by the walls' share with
 * E_k below the threshold is told it still rocks (20 successive checks);
 * a ke_limit of 0 is taken as unknown: E_k (above 0) named above the
 * threshold unless the floor's load is above 1.5; out, may be NULL,
 * the file the sample was written to, named in the text), and a height_rm
 * that took nothing away (untrimmed_top_rm > 0). Nothing else. An unsettled
 * r whose E_k (with the grains in flight) lies below ke_limit (or is 0, the
 * limit unknown) and whose floor carries 0.5 to 1.5 of the weight says just
 * that: the run did
 * not call it settled (it was told "E_k = 0 J still above"). The texts
 * `granwave layer-make` prints and Python issues. GW_OK or GW_ENOMEM;
 * GW_EINVAL, nothing added, for a result no run gives (filled by hand):
 * one gw_layer_make_result_check refuses, which names why. */
int gw_layer_make_result_warnings(const gw_layer_make_result *r, double t_max, const char *out, char **list);
/* Whether r (with t_max, s, the run's) could come from gw_layer_make, as
 * gw_layer_make_result_warnings takes it: GW_OK, or GW_EINVAL with one line
 * naming the field, its value and its range ("gw_layer_make_result: ke_final =
 * nan J is outside [0, inf) ..."): r NULL, converged other than 0 or 1 (-3 was
 * taken as settled), untrimmed_top_rm NaN, infinite or negative, or an
 * unsettled r with ke_final, floor_load, ke_limit or t_judge NaN, infinite or
 * negative, fall_energy NaN, or a t_max not positive and finite. A settled r
 * is held to converged and untrimmed_top_rm alone (its warnings state no other
 * number). */
int gw_layer_make_result_check(const gw_layer_make_result *r, double t_max, gw_err *err);

/* Porosity of the sample in the window x in [0.1, 0.9] W, y in [0.1, 0.8] h,
 * with h = max(y + r): 1 - (area of the union of the discs in the window) /
 * (window area), the area exact up to rounding (Green's theorem on the
 * union's boundary; before session 21 a 600 x 600 sampling grid, which
 * aliased on lattices). In [0, 1]; NaN when the window is empty (width or h
 * not positive and finite), no disc reaches into it (1 before session 46),
 * the sample counts discs without its x, y or r,
 * holds a disc of a coordinate not finite or a radius not > 0 (such a disc
 * was left out before session 34: the porosity of the others), fails any
 * other limit the sample reader applies (n above 1e7, a radius outside
 * [1e-3, 1e3] R_m, a disc outside the box or deep inside another: a number
 * before session 43), or an allocation fails. */
double gw_layer_sample_porosity(const gw_layer_sample *s);

/* --------------------------------------------------------------- impact ---- */

typedef struct gw_layer_impact_params {
    double rb_rm;       /* block radius in R_m [1] */
    double vi;          /* incident speed, m/s [20] */
    double alpha_deg;   /* incidence from the normal, deg in [0, 90) [0] */
    double x;           /* impact abscissa from the box centre, m [0] */
    double height_rm;   /* layer height kept mobile, in R_m [0 = all] */
    double gap;         /* initial gap between block and target particle, m [1e-6] */
    double t_max;       /* s [2] */
    double dt_out;      /* sampling interval, s [2e-5] */
    double ring_width;  /* crown width d_c, m [2 R_m] */
    int nrings;         /* crowns [12] */
    int full;           /* 1: run to t_max even after the outcome is decided [0] */
    int until;          /* GW_LAYER_UNTIL_REBOUND: stop once the rebound is complete
                           (T_f, physics.md 2.3) or the block is found not to bounce;
                           GW_LAYER_UNTIL_VERDICT: stop once the bounce verdict is
                           decided (e_n, e, alpha_r then NaN) [rebound] */
    int remove_walls;   /* 1: no left/right/bottom walls from the impact on [0] */
    int side_walls;     /* GW_LAYER_SIDES_*: the side walls the impact keeps over its
                           floor (a pile leaning on its walls refused without one,
                           and with remove_walls any but both) [GW_LAYER_SIDES_BOTH] */
    double energy_tol;  /* > 0: stop with GW_ESOLVER when the ledger closure
                           |sum - A|/A exceeds it at a sample [0 = off] */
    /* on_sample (may be NULL) [NULL]: called with sample_ctx at every recorded
     * sample k (the layer's state at res->t[k], s) with final = 0, and once more
     * after the last step with final = 1 and k = ns - 1 (the end state, the same
     * as the last sample's). When the run fails after it started (solver,
     * energy or step limit), it is called once with final = 2 and the state
     * where the run stopped, k = the last sample; its return is then ignored.
     * The layer is read-only there (gw_layer_particle, gw_layer_radius, ...);
     * the block is particle gw_layer_n(L) - 1. A non-zero return (a gw status)
     * stops the run with that status; res is then freed as after any failure.
     * The run itself is unchanged by the hook. */
    int (*on_sample)(void *sample_ctx, const gw_layer *L, int k, int final);
    void *sample_ctx;
    int other_settling; /* 1: run a sample whose recorded settling (gw_layer_settled)
                           leaves its pile away from rest under this impact's material
                           (gw_layer_impact_settled_check), with a warning [0: refused] */
    int zero_springs;   /* 1: start every contact's tangential spring at zero, as from a sample
                           without springs (a peer whose input carries none, such as a LAMMPS
                           data file, is compared like with like) [0: from the sample's
                           springs, gw_layer_spring] */
} gw_layer_impact_params;

gw_layer_impact_params gw_layer_impact_params_default(void);
/* gw_layer_impact_params.side_walls: both side walls (the default, 0), the left
 * or the right one alone, or none (the floor kept in each). */
enum { GW_LAYER_SIDES_BOTH = 0, GW_LAYER_SIDES_LEFT = 1, GW_LAYER_SIDES_RIGHT = 2, GW_LAYER_SIDES_NONE = 3 };
enum { GW_LAYER_UNTIL_REBOUND = 0, GW_LAYER_UNTIL_VERDICT = 1 };
/* "rebound" or "verdict" ("unknown" for another value: "rebound" before
 * session 34); and back (-1 for any other string). */
const char *gw_layer_until_name(int until);
int gw_layer_until_parse(const char *name);

/* Time series recorded every dt_out (allocated by the run, freed with
 * gw_layer_impact_result_free). */
/* "below its lowest point", "beyond its left side", "beyond its right side"
 * for GW_LAYER_GONE_*, "no" for 0 (gw_layer_impact_result.fell_off). */
const char *gw_layer_fell_off_name(int fell_off);

typedef struct gw_layer_impact_result {
    /* Outcome, from events on the block (layer_outcome.c documents the rules). */
    int bounced;            /* 1: the block left the layer moving up; 0: its normal
                               velocity turned upward and came back to zero while it
                               still touched the layer; -1: undecided (the run ended
                               before either) */
    int fell_off;           /* 0, or GW_LAYER_GONE_* (then bounced = 0): the block left
                               the layer for good (gw_layer_watch_block) before a
                               verdict, and the run ended there */
    double v_ni;            /* V_i cos alpha_i, m/s */
    double v_nr, v_r, e_n, e, alpha_r_deg; /* at T_i, the largest v_y up to T_f
                                              (physics.md 2.3, B.16-B.18); NaN unless
                                              bounced and T_f reached */
    double t_rebound;       /* T_i, s (NaN as e_n) */
    double t_f;             /* T_f: v_y back to zero after the bounce, s (NaN if not reached) */
    double t_leave;         /* the bounce event: the block leaves moving up, s (NaN) */
    double v_nr_first, v_r_first, e_n_first, e_first, alpha_r_first_deg, t_rebound_first;
                            /* the same at the first free-flight maximum: the largest
                               v_y up to t_leave (NaN unless bounced) */
    double penetration;     /* largest downward displacement of the block centre below
                               its height at the touch (the start lowered by the gap)
                               up to the end of the outcome, m */
    char undecided[320];    /* why the run ended with an undecided outcome ("" if
                               none, or when --until verdict stopped it on purpose) */
    double energy_error;    /* max |sum - A| / A over the run */
    double e_incident;      /* (1/2) M V_i^2, J */
    /* First contact (docs/physics.md 2.5): from the touch to the smallest block
     * kinetic energy while the block touches the target particle (sampled every
     * dt_out). */
    double t_first_contact; /* its end, s */
    double dissipated_first_contact; /* E_d / E_incident at its end */
    double dissipated_first_contact_block; /* the part of it at the block's contacts */
    double block_loss_first_contact; /* (E_kb(0) - E_kb) / E_incident at its end
                                        (binary analogy B.24-B.28) */
    double contact_angle_deg; /* angle between the incident velocity and the
                                 block-target contact normal, deg (0: head-on) */
    double t_contact_open;  /* time the block-target contact opened (NaN: not by the verdict), s */
    double dissipated_contact_open; /* E_d / E_incident then */
    double block_loss_contact_open; /* (E_kb(0) - E_kb) / E_incident then: the
                                       binary impact's loss (B.28) for every r,
                                       where block_loss_first_contact, at the
                                       block's smallest energy, is 1 for a block
                                       that rebounds from its target (r <= 1) */
    double wave_speed, wave_speed_err;      /* from strain-energy peaks, m/s */
    double wave_speed_kin, wave_speed_kin_err; /* from kinetic-energy peaks */
    int wave_rings;         /* rings in the strain fit */
    /* Crown delays by FFT cross-correlation (layer_crowns.c): of the sample-to-
     * sample changes of neighbouring rings' total (strain + kinetic) energy, for
     * rings k >= 1; speed = sum of ring spacings / sum of delays, error from the
     * scatter of the delays; NaN with fewer than 2 ring pairs. m/s. */
    double wave_speed_xcorr, wave_speed_xcorr_err;
    int xcorr_gaps;         /* ring pairs used */
    double t_end;
    double impact_x, impact_y; /* ring centre, m */
    double block_mass, wall_ms;
    double dt;              /* fixed step used (verlet, rk4), s; 0 for cvode/arkode */
    int n_mobile, n_frozen;
    gw_layer_stats stats;
    /* series */
    int ns, cap;            /* samples held; room for (grown by the run, up to ceil(t_max / dt_out) + 2) */
    double *t;              /* [ns] */
    gw_layer_energy *ledger;/* [ns] */
    double *block;          /* [ns * 4]: x, y, vx, vy */
    int nrings;
    double *ring_kin, *ring_strain, *ring_coord; /* [ns * nrings] */
    double *ring_diss;      /* [ns * nrings] friction dissipation per ring, J */
    gw_layer_energy *regions; /* [nrings + 2] region ledger at the last sample:
                                 rings, outside, block (gw_layer_region_ledger) */
    double *peak_strain_t, *peak_kin_t;          /* [nrings] (NaN when none) */
    double *ring_r;                              /* [nrings] mid radius, m */
    /* One allocation owned by xcorr_delay (NULL when the analysis had fewer than
     * 4 evenly spaced samples): */
    double *xcorr_delay;    /* [nrings] delay from ring k to ring k + 1, s (NaN: pair unused) */
    double *xcorr_rho;      /* [nrings] normalised correlation peak of that pair (NaN: unused) */
    int spec_len;           /* frequencies of the ring spectra, f_l = l spec_df */
    double spec_df;         /* Hz */
    double *spec_strain, *spec_kin; /* [spec_len * nrings] one-sided power spectral
                                       density of each ring's strain-energy increase
                                       and kinetic energy (gw_xcorr_psd), J^2/Hz */
    const char *method;     /* the solver variant run, default resolved ("adams" for
                               cvode, "erk" for arkode, "none" for verlet and rk4;
                               static text), for the provenance */
    char settling[768];     /* the sample settled under another material, gravity or mass
                               law than the impact's, or did not settle
                               (gw_layer_impact_settled_check's warning; "" when the
                               same or not recorded) */
    double settled_load_ratio; /* q of gw_layer_settled_load_ratio for the sample under the
                                  impact's material (1: at rest as settled; NaN: the sample
                                  records no settling) */
    double slump_ke;        /* with a side wall taken away (side_walls other than both):
                               the pile's kinetic energy when the block first touches
                               it, J, read at the touch event (the located root, or
                               the DEM step it falls in; the pile slumping on its open
                               side meanwhile; any dt_out the same);
                               NaN with both side walls, or when the block touched
                               nothing. Above GW_LAYER_SLUMP_WARN of e_incident the
                               result warns (gw_layer_impact_result_warnings) */
} gw_layer_impact_result;

/* The share of the impact's energy (e_incident) the pile's slump may reach,
 * as kinetic energy before the block arrives, with a side wall taken away,
 * before the result warns that the block hits a pile already in motion
 * (gw_layer_impact_result.slump_ke). Measured (session 46) on the 27 piles of
 * 47 that run without their more loaded wall: the fall rule (the block at most 0.1 %
 * faster at the touch) lets it arrive by t = 1.0e-4 V_i s at the latest,
 * and by then a block of R_m meets at most 1.5e-3 of its energy in the
 * slump (at V_i 1 to 200 m/s), a block of 0.1 R_m up to 0.15;
 * `layer-make --n 20 --width-rm 8` without its left wall at --rb-rm 0.02
 * --vi 5 --gap 2.4e-3: 0.626 J at the touch against 4.4 J, 0.14. At the
 * default gap the touch comes at once, the slump next to nothing (8.2e-6 J
 * at 2e-7 s on that pile). */
#define GW_LAYER_SLUMP_WARN 0.1

void gw_layer_impact_result_free(gw_layer_impact_result *r);

/* Check impact parameters against a sample (block radius, speed, incidence,
 * gap >= 0, block inside the box, ...): GW_EINVAL naming the input. The
 * sample as the run takes it is checked first, by the run's own checks, so
 * that the two never disagree: its form (gw_layer_sample_pile_hash lists it),
 * each particle's x, y and r finite and r > 0 (GW_EINVAL "sample 's':
 * particle I: FIELD = V m ..." naming the index and the field), its clumps
 * connected and its springs (unless ip->zero_springs) as the sample reader
 * takes them. Before session 35 a particle of a NaN or infinite coordinate or
 * radius passed the check and was refused by the run only. Since session 43
 * the sample is held to every limit the reader applies (n in [1, 1e7], rm and
 * width within their scales, each radius within [1e-3, 1e3] R_m, each disc
 * inside the box to 0.02 r and at most 1e6 R_m high, no two discs more than
 * 0.05 R_p inside each other), walls or none, the message naming the field
 * and the index. The walls' rule is that one: a disc may reach 0.02 r beyond
 * the box's side or floor (the overlap settling leaves against a wall), its
 * centre then inside the walls the run keeps; 0.03 r beyond is refused, with
 * the walls or without (until session 44 the check also held the centres to
 * the walls, which the box rule already does). gw_layer_impact_rest_check,
 * gw_layer_impact_gap_check, gw_layer_impact_dem_dt,
 * gw_layer_impact_settled_check and gw_layer_impact take the same check, with
 * the same message; gw_layer_impact takes it once a run. With ip->side_walls
 * other than both (the floor kept), it refuses as gw_layer_impact and the
 * study's setup do (since session 45; before, the run and the setup only) a
 * pile that does not rest on its floor alone (0.5 to 1.5 of its weight) or
 * that leans on a wall taken away (that wall's normal and friction forces'
 * resultant above the pile's weight: a pile wedged between its walls), with
 * GW_EINVAL "side-walls: ...", judged under the material and gravity the
 * sample records it settled with, else the default material: this check has
 * no material, and a sample without a settling record run under another
 * (gw_layer_impact with lp's shear modulus at 4e9 Pa) is judged under lp by
 * the run. gw_layer_impact_check_with takes the run's lp and judges the side
 * walls as the run does, with the run's message (lp NULL: GW_EINVAL naming
 * it; lp held to gw_layer_params_validate first); gw_layer_impact_dem_dt
 * takes it (NaN where it refuses; before session 45 the default material's
 * verdict). The setup's check (gw_layer_impact_setup_check) judges under the
 * setup's material. */
int gw_layer_impact_check(const gw_layer_sample *s, const gw_layer_impact_params *ip,
                          gw_err *err);
int gw_layer_impact_check_with(const gw_layer_sample *s, const gw_layer_params *lp,
                               const gw_layer_impact_params *ip, gw_err *err);

/* The block falls the gap under gravity g (m/s^2) before it touches: its
 * normal speed at contact is sqrt(V_ni^2 + 2 g gap). The outcome (e_n, e,
 * alpha_r, E_incident, the Froude number, the penetration)
 * takes V_i as given, so the fall may change the normal speed by at most
 * 0.1 %: GW_EINVAL "gap: ..." naming the largest gap that passes, or, at the
 * default gap (ip->gap at gw_layer_impact_params_default's value, which the
 * struct cannot tell from a gap set to that value), "vi: ... too slow for the
 * default gap ..." naming the smallest speed. The setup
 * (gw_layer_impact_setup: the program, a sweep's case, Python) knows whether
 * the gap was given, and gives a gap given at 1e-6 m the gap's refusal. */
/* g is held to gravity's range [0, 1e4] m/s^2 first (gw_layer_params_validate's
 * rule and message; before session 46 g = 1e300 was told vi is too slow). */
int gw_layer_impact_fall_check(const gw_layer_impact_params *ip, double g, gw_err *err);

/* The gap's checks: gw_layer_impact_fall_check, then the sideways drift. The
 * block is lowered vertically onto its target at x but flies along the
 * incidence, so it meets the layer gap tan(alpha) off x: at most 1e-3 R_m of
 * the sample s, else GW_EINVAL "gap: ..." naming the largest gap that passes.
 * Last, the block must be able to cross the gap (at its speed vi, gravity
 * added) before ip->t_max: GW_EINVAL "t-max: ..."
 * naming its arrival time (a run that ended first measured nothing and
 * recorded a penetration of 0). */
int gw_layer_impact_gap_check(const gw_layer_sample *s, const gw_layer_impact_params *ip, double g,
                              gw_err *err);

/* The sample s rests under the impact's contacts and gravity lp: its floor
 * contacts' Hertz force at t = 0 is at most 1.5 times the pile's weight (a
 * settled pile: at most 1). A pile settled with another material, density,
 * gravity or mass law holds strain energy that the impact would release:
 * GW_EINVAL "sample 'name': ..." naming the values (name may be NULL), and
 * other-settling when the sample records a settling that explains the load.
 * gw_layer_impact runs it with ip->other_settling, which allows the load the
 * recorded settling explains, 1.5 q times the weight (q of
 * gw_layer_settled_load_ratio, when above 1); a sample without a record, or
 * a load beyond that (a pile that did not settle), stays refused. A sample
 * of gw_layer_impact_check's form, with finite particles, comes first
 * (GW_EINVAL naming the field or the particle: a NULL y was read before). */
/* lp is held to gw_layer_params_validate first, as the run holds it (since
 * session 46: a NaN gravity passed), here and in
 * gw_layer_impact_settled_check; gw_layer_settled_load_ratio is then NaN. */
int gw_layer_impact_rest_check(const gw_layer_sample *s, const gw_layer_params *lp, const char *name,
                               gw_err *err);

/* The sample's recorded settling (s->settled) against the impact's material
 * lp. Under lp the overlaps the pile settled with carry
 *   q = [G/(1 - nu)]_lp / [G/(1 - nu)]_settled x W_settled / W_lp
 * of the weight they carried at rest (Hertz K_n ~ G/(1 - nu), B.3; W the
 * pile's weight, its bodies' masses times g under each mass law and clump
 * mass; the equilibrium overlap scales as (m g / K_n)^(2/3)): q < 1 and the
 * pile sags into the impact, q > 1 and it springs up. Outside
 * [GW_LAYER_SETTLED_LOAD_MIN, GW_LAYER_SETTLED_LOAD_MAX], or with a friction
 * coefficient tan(phi) below GW_LAYER_SETTLED_FRICTION_MIN times the
 * settling's (the pile leans on friction it no longer has and flows),
 * GW_EINVAL "sample 'name': ..." naming the values, unless other_settling;
 * then, and for any other difference (q not 1 within 1e-9, another mass law
 * or clump mass, another friction angle), GW_OK with the warning text in
 * warning[n] ("" when the same, or nothing is recorded: hand-written samples
 * pass as before). A pile that did not settle (s->settled.unsettled, with or
 * without a record; or s->settled_converged with a record whose floor carries
 * less than half the pile's weight under the recorded material: a pile in the
 * air an older layer-make called settled) is a warning too, after the material's. When its clumps cannot be weighed as unions (out of
 * memory), gw_layer_create's status, "sample 'name': weighing its clumps: ...". The
 * thresholds (docs/cli.md, layer-impact; layer_settled.c has the numbers):
 * the Hertz drop from overlap q^(2/3) d to d releases about 0.19 of the
 * strain energy at rest at q = 1.5 and 0.24 at q = 0.5; measured on a 40-disc
 * pile left alone under the default material, the first 5 ms give 0.5-2 J of
 * soil motion matched, 6.4 J at q = 0.38 and 19 J at q = 0.038. A lower
 * friction is refused whatever the ratio (GW_LAYER_SETTLED_FRICTION_MIN 1):
 * the 300-disc pile settled at 30 degrees rests at 19.2, the 600-disc one
 * flows there (37 kJ of potential energy in 100 ms), the 1000-disc one at
 * 24 (layer_settled.c). A sample of gw_layer_impact_check's form, with finite
 * particles, comes first (GW_EINVAL; a NULL r was read before session 35). */
#define GW_LAYER_SETTLED_LOAD_MIN 0.5
#define GW_LAYER_SETTLED_LOAD_MAX 1.5
#define GW_LAYER_SETTLED_FRICTION_MIN 1.0
int gw_layer_impact_settled_check(const gw_layer_sample *s, const gw_layer_params *lp, int other_settling,
                                  const char *name, char *warning, size_t n, gw_err *err);
/* q above for the sample s under lp; NaN when s->settled is not recorded (or
 * out of memory weighing union clumps, or s is no sample a run takes: NULL
 * arrays, a particle not finite), an infinity when lp has no gravity. */
double gw_layer_settled_load_ratio(const gw_layer_sample *s, const gw_layer_params *lp);

/* The verlet step gw_layer_impact takes when sp->dt is 0: the Hertz contact
 * time of the two smallest discs meeting at V_i, tau = (4/5) B(2/5, 1/2)
 * (5 M / (4 K_n))^(2/5) V_i^(-1/5) with the reduced mass M = m/2, over GW_LAYER_DEM_STEPS,
 * rounded down to GW_LAYER_DEM_BASE / k (k >= 1, never above the base),
 * whatever ip->dt_out: the run's checks are every 2 GW_LAYER_DEM_BASE, on the
 * step grid, and a sample off the steps is read between two steps without
 * changing the run (gw_solver_set_peek), so the trajectory, hence the outcome,
 * does not depend on dt_out. (Until session 45 the step was the largest
 * divisor of a dt_out it did not divide, and the outcome moved with dt_out.)
 * s. NaN for a sample or an impact that
 * gw_layer_impact_check refuses (before session 43 the sample's form only: a
 * disc outside the box or two discs at one place got a step) or a radius not
 * finite and > 0 (a NaN radius gave the other discs' step before session 34). */
#define GW_LAYER_DEM_STEPS 100
#define GW_LAYER_DEM_BASE 1e-5
double gw_layer_impact_dem_dt(const gw_layer_sample *s, const gw_layer_params *lp,
                              const gw_layer_impact_params *ip);

/* 1 when dt_out is k dt for an integer k >= 1, to a relative 1e-9. */
int gw_layer_impact_dt_divides(double dt, double dt_out);

/* The longest step an impact is given (sp->dt), s: the bound of
 * layer-impact --dt (its option row's), far above any contact time
 * (microseconds); gw_layer_impact_step_check refuses a longer one. */
#define GW_LAYER_DT_MAX 1.0

/* The solver's step and tolerances of an impact: GW_EINVAL naming sp->dt or
 * sp->dt_max when not 0 or a normal finite number > 0, sp->dt above
 * GW_LAYER_DT_MAX (until session 48 a verlet step of 1e200 s passed the
 * library, which the program refused), or a tolerance every backend refuses. A step given need not divide ip->dt_out nor be shorter:
 * the samples off the steps are read between two steps (verlet, rk4), and
 * the outcome is the same step's at a dt_out it divides, bit for bit (until
 * session 46 verlet's dt had to divide dt_out, GW_EINVAL "dt-out: ...", and
 * rk4's could not be above it, "dt: ..."). gw_layer_impact checks it, as the
 * setup's resolution does. */
int gw_layer_impact_step_check(const gw_layer_impact_params *ip, const gw_solver_type *type,
                               const gw_solver_params *sp, gw_err *err);

/* One block impact on a sample (docs/physics.md 2.3). Writes no files: a caller
 * that wants snapshots (the program's VTK files, the study's arrays) takes them
 * in ip->on_sample. GW_EINVAL names the input (block overlapping the layer,
 * block outside the box, bad parameters, a pile not at rest under lp:
 * gw_layer_impact_rest_check, gw_layer_impact_settled_check with
 * ip->other_settling, whose warning goes into res->settling). */
int gw_layer_impact(const gw_layer_sample *s, const gw_layer_params *lp,
                    const gw_layer_impact_params *ip, const gw_solver_type *type,
                    const gw_solver_params *sp, gw_layer_impact_result *res, gw_err *err);
/* The warnings of an impact, appended to *list as gw_layer_make_result_warnings:
 * a sample settled under another material (res->settling), then an outcome
 * that is undecided (res->undecided); nothing else. */
int gw_layer_impact_result_warnings(const gw_layer_impact_result *r, char **list);

/* Write res's time series (ledger, block, rings, peaks) and scalar results to
 * path as HDF5 (layer_h5.c documents the layout), atomically. GW_EUNSUPPORTED
 * in a build without HDF5, GW_EIO when the file cannot be written (nothing is
 * left behind). */
int gw_layer_impact_write_h5(const gw_layer_impact_result *res, const char *path,
                             const char *header, gw_err *err);

/* Crown analysis on res's ring series: peak times per ring and the wave speed
 * by a linear fit (GSL) of ring radius against peak time; the delays between
 * neighbouring rings by FFT cross-correlation, their wave speed, and each
 * ring's power spectra. Fills the peak, wave-speed, xcorr and spectrum fields
 * of res (allocating xcorr_delay, freed by gw_layer_impact_result_free).
 * GW_ENOMEM when the FFT buffers cannot be allocated (xcorr fields then NaN,
 * nothing allocated). */
int gw_layer_crowns(gw_layer_impact_result *res);

/* The `layer` model of `granwave sweep` (layer_sweep_model.c): keys are the
 * options of layer-impact plus point, points and spacing; one row per impact.
 * (struct gw_sweep_model is defined in gw_sweep.h.) */
struct gw_sweep_model;
extern const struct gw_sweep_model gw_layer_sweep_model;
#define GW_LAYER_SWEEP_MODEL gw_layer_sweep_model
/* The model's run with part(pctx, x) (gw_sweep_part_fn, may be NULL) about a
 * thousand times over the case's impact: x its simulated time over the end
 * expected, t + v_y / g while the block rises under gravity (T_f, when v_y is
 * back to zero), else t-max (before it rises, until verdict, full, no
 * gravity); x in [0, 1]. The results are the run's, bit for bit. */
int gw_layer_sweep_run_part(int nkeys, const char *const *names, const char *const *values, double *out,
                            unsigned long long *read_hash, void (*part)(void *pctx, double x), void *pctx,
                            gw_err *err);

/* The hash of what a run reads from sample s: n, the box width, rm,
 * mass_law, clump_mass, the settling record (gw_layer_settled, but its line)
 * and the particles as a set of bodies, each a set of discs (x, y, r; no body
 * column: each disc a body of its own), doubles by their bits with -0 as 0
 * (layer_sample_pile.c gives the formula). Not the file's bytes
 * (content_hash): a sample's comments record the command that made it, so a
 * copy, or layer-make run twice with the same seed and options, hashes the
 * file differently and the pile the same; nor the order in which the file
 * lists the particles, nor the numbers it gives its clumps, which change a
 * run only to rounding (the summation order of the contact forces); but the
 * same discs grouped into other clumps are another pile. Nor the records a
 * run does not read (seed, porosity, volume_ratio). 0 for s NULL, for a
 * sample no run takes (every limit gw_layer_impact_check holds its sample to,
 * the reader's: n < 1 or above 1e7, x, y or r NULL, a particle of x, y or r
 * not finite or r <= 0 (hashed before session 35), a body id outside [0, n),
 * a negative n_springs, springs counted without their array or a spring's
 * pair out of range (before session 34 such a sample was read through its
 * NULL arrays or hashed as another one); rm or width outside their scales, a
 * radius outside [1e-3, 1e3] R_m, a disc outside the box beyond 0.02 r or
 * above 1e6 R_m, a clump not connected, two discs more than 0.05 R_p inside
 * each other (hashed, the form alone checked, before session 44)), or out of
 * memory (gathering the bodies of a clump sample, 9 bytes a particle, or the
 * overlap check's grid); never fails otherwise. */
unsigned long long gw_layer_sample_pile_hash(const gw_layer_sample *s);

GW_END_DECLS

#endif
