/*
 * chain_setup_rows.h (private to chain/): the rows of a column's model and
 * solver parameters (gw_chain_study.h), written once and expanded into every
 * table that holds a gw_chain_setup: gw_chain_setup_params (chain_setup.c)
 * and the falcon study's table (chain_falcon_study.c). It also gives the chain
 * tables' row constructors ROW, CHOICE (inputs: no open upper ends) and RD, RI,
 * RF (a flag), RL, RA (results), on the includer's OFF(field) (the field's offset in its
 * struct). Units SI.
 */
#ifndef GW_CHAIN_SETUP_ROWS_H
#define GW_CHAIN_SETUP_ROWS_H

#include "gw_chain_study.h"

#define ROW(nm, ty, f, un, lo, hi, op, df, mv, hl) GW_PARAM_ROW(nm, ty, OFF(f), un, lo, hi, op, 0, df, mv, hl)
#define CHOICE(nm, f, ch, df, mv, hl) GW_PARAM_CHOICE_ROW(nm, OFF(f), ch, df, mv, hl)
#define RD(nm, f, un, hl) GW_RESULT_ROW(nm, GW_PARAM_DOUBLE, OFF(f), un, hl)
#define RI(nm, f, hl) GW_RESULT_ROW(nm, GW_PARAM_INT, OFF(f), "", hl)
#define RF(nm, f, hl) GW_RESULT_FLAG(nm, OFF(f), hl)
#define RL(nm, f, hl) GW_RESULT_ROW(nm, GW_PARAM_LONG, OFF(f), "", hl)
#define RA(nm, f, un, r, c, hl) GW_RESULT_ARRAY(nm, OFF(f), un, r, c, NULL, hl)
/* the same result rows of a field of struct T, for the files whose tables
 * hold several structs (chain_wave_study.c, chain_softwall_study.c) */
#define RDT(T, nm, f, un, hl) GW_RESULT_ROW(nm, GW_PARAM_DOUBLE, offsetof(T, f), un, hl)
#define RIT(T, nm, f, hl) GW_RESULT_ROW(nm, GW_PARAM_INT, offsetof(T, f), "", hl)
#define RAT(T, nm, f, un, r, c, hl) GW_RESULT_ARRAY(nm, offsetof(T, f), un, r, c, NULL, hl)

#define MATERIALS "steel,rigid,brass,aluminium,glass,pmma,pvc"
/* the beads' choices: rigid (infinite density) is a wall only */
#define BEAD_MATERIALS "steel,brass,aluminium,glass,pmma,pvc"
#define SHEETS "none,brass,tape,pvc,pmma,cardboard2,beech,cardboard1,rubber"
#define SHEET_LAWS "fitted,hertz,layer,material"

/* The order of the damping choices is that of gw_chain_damping. */
_Static_assert(GW_DAMP_NONE == 0 && GW_DAMP_KUWABARA_KONO == 1 && GW_DAMP_HUNT_CROSSLEY == 2,
               "damping choices none,kk,hc follow gw_chain_damping");
_Static_assert(GW_SHEET_FITTED == 0 && GW_SHEET_HERTZ == 1 && GW_SHEET_LAYER == 2 && GW_SHEET_MATERIAL == 3,
               "sheet-law choices fitted,hertz,layer,material follow gw_sheet_law");

/* material .. guide-viscous: the options every chain command shares, in this
 * order; the drop's table (chain_drop_study.c) replaces the gravity, t-max and
 * dt-out rows by its own (other defaults, ranges and help). */
/* The column's rows with the help of solver, dt and dt-out given: a study that
 * picks its own solver (falcon by its accuracy) states its own defaults. */
#define GW_CHAIN_MODEL_ROWS_HELP(solver_help, dt_help, dtout_help) \
    GW_CHAIN_MATERIAL_ROWS \
    ROW("gravity", GW_PARAM_DOUBLE, gravity, "m/s^2", 0, 1e4, 0, "0", "G", "gravity toward the wall, m/s^2 [0 = off]"), \
    GW_CHAIN_SOLVER_ROWS_HELP(solver_help, dt_help) \
    ROW("t-max", GW_PARAM_DOUBLE, t_max, "s", 0, 1e6, 0, "0", "T", \
        "stop after T seconds, in [0, 1e6] [0 = 20 (n T_q + tau_1), of the heaviest bead, + 20 pi sqrt((n m + M)/k_s) " \
        "on a sensor body, going on while contacts still act, up to 50 times that]"), \
    ROW("dt-out", GW_PARAM_DOUBLE, dt_out, "s", 0, 1, 0, "0", "DT", dtout_help), \
    GW_CHAIN_ENERGY_ROW \
    GW_CHAIN_WALL_ROWS

#define GW_CHAIN_SOLVER_HELP "cvode, arkode or rk4 [cvode]"
#define GW_CHAIN_DT_HELP "RK4 step, s, in [0, 1] [0 = T_c/400]; initial step for cvode/arkode"
#define GW_CHAIN_MODEL_ROWS \
    GW_CHAIN_MODEL_ROWS_HELP(GW_CHAIN_SOLVER_HELP, GW_CHAIN_DT_HELP, \
                             "sampling interval for traces, energy and F_max, s, in [0, 1] [0 = tau_1/200]")

/* material .. mass */
/* material, radius and wall-material are optional (gw_param.h): given at
 * their defaults' values too, they are refused where they have no effect */
#define GW_CHAIN_MATERIAL_ROWS \
    GW_PARAM_OPT_CHOICE_ROW("material", OFF(material), BEAD_MATERIALS, "steel", "NAME", \
           "bead material (steel, brass, aluminium, glass, pmma, pvc) [steel]"), \
    /* a micron to a metre: below, masses of 1e-300 m beads underflow to 0 */ \
    GW_PARAM_OPT_ROW("radius", GW_PARAM_DOUBLE, OFF(radius), "m", 1e-6, 1, 0, 0, "4e-3", "R", \
                     "bead radius, m, in [1e-6, 1] [4e-3]"), \
    GW_PARAM_OPT_CHOICE_ROW("wall-material", OFF(wall_material), MATERIALS, "steel", "NAME", \
           "wall material, a half-space (steel, rigid, brass, aluminium, glass, pmma, pvc) [steel]"), \
    CHOICE("sheet", sheet, SHEETS, NULL, "NAME", \
           "wall: a sheet of the paper's Table 2 with its fitted K_eff (none, brass, tape, pvc, pmma, " \
           "cardboard2, beech, cardboard1, rubber)"), \
    /* one radius a bead: at most n (chain_resolve checks the count) */ \
    {.name = "radii", .type = GW_PARAM_LIST, .offset = OFF(radii), .unit = "m", .min = 1e-6, .max = 1, \
     .rows = "n", .metavar = "R,R..", .help = "per-bead radii, m, bead 1 first (masses and contact k from the material)"}, \
    ROW("k", GW_PARAM_DOUBLE, k, "N/m^1.5", GW_CHAIN_K_MIN, GW_CHAIN_K_MAX, 0, NULL, "K", \
        "bead-bead Hertz coefficient, N/m^1.5, in [1e3, 1e14] [from material, F.12]"), \
    ROW("kwall", GW_PARAM_DOUBLE, kwall, "N/m^1.5", GW_CHAIN_K_MIN, GW_CHAIN_K_MAX, 0, NULL, "K", \
        "bead-wall Hertz coefficient, N/m^1.5, in [1e3, 1e14] [from materials, F.3]"), \
    /* from the lightest bead the radius row and the materials give (pmma at 1e-6 m, \
     * 4.9e-15 kg): below, (0, 1e3] took 3e-308 kg, whose contact (1e-126 s) left a \
     * step of 0 and a refusal naming dt-max, not mass (test_frontend_parity) */ \
    ROW("mass", GW_PARAM_DOUBLE, mass, "kg", 1e-15, 1e3, 0, NULL, "M", "bead mass, kg, in [1e-15, 1e3] [4/3 pi R^3 rho]"),

/* damping .. max-steps */
#define GW_CHAIN_SOLVER_ROWS GW_CHAIN_SOLVER_ROWS_HELP(GW_CHAIN_SOLVER_HELP, GW_CHAIN_DT_HELP)
#define GW_CHAIN_SOLVER_ROWS_HELP(solver_help, dt_help) \
    CHOICE("damping", damping, "none,kk,hc", "none", "MODEL", \
           "none, kk (Kuwabara-Kono; with gamma or restitution) or hc (Hunt-Crossley; with alpha or restitution) " \
           "[none]"), \
    ROW("gamma", GW_PARAM_DOUBLE, gamma, "N s/m^1.5", 0, GW_CHAIN_GAMMA_MAX, 0, NULL, "G", \
        "Kuwabara-Kono constant of bead contacts, N s/m^1.5, in [0, 1e14] [0]"), \
    ROW("alpha", GW_PARAM_DOUBLE, alpha, "s/m", 0, GW_CHAIN_ALPHA_MAX, 0, NULL, "A", \
        "Hunt-Crossley constant, s/m, in [0, 1e8] [0]"), \
    GW_PARAM_ROW("restitution", GW_PARAM_DOUBLE, OFF(restitution), "", 0, 1, 1, 1, NULL, "E", \
        "calibrate gamma/alpha so one bead on the wall rebounds with E (a sheet under sheet-law hertz: on the bare sensor), in (0, 1)"), \
    ROW("restitution-v", GW_PARAM_DOUBLE, restitution_v, "m/s", GW_CHAIN_VIMP_MIN, GW_CHAIN_VIMP_MAX, 0, NULL, "V", \
        "impact velocity of that calibration, m/s [v_imp]"), \
    CHOICE("solver", solver, "cvode,arkode,rk4", NULL, "NAME", solver_help), \
    CHOICE("method", method, "default,bdf,adams,erk,dirk,imex", NULL, "NAME", \
           "cvode: bdf|adams; arkode: erk|dirk|imex [bdf / erk]"), \
    ROW("rtol", GW_PARAM_DOUBLE, rtol, "", GW_TOL_MIN, GW_TOL_MAX, 0, NULL, "R", "relative tolerance [1e-12]"), \
    ROW("atol", GW_PARAM_DOUBLE, atol, "", GW_TOL_MIN, GW_TOL_MAX, 0, NULL, "A", \
        "absolute tolerance in units of the overlap and velocity scales (at v_imp, or at the speed the " \
        "column's weight rings at when gravity sets a larger one) [1e-12]"), \
    ROW("dt", GW_PARAM_DOUBLE, dt, "s", 0, 1, 0, NULL, "DT", dt_help), \
    /* 0 is not "unlimited": the run caps the step at a quarter of the shortest \
     * binary contact at 2 v_imp (chain_collide_plan.c, chain_drop.c; the settings \
     * record it), which the help said nothing of until the fifteenth pass */ \
    ROW("dt-max", GW_PARAM_DOUBLE, dt_max, "s", 0, 1, 0, "0", "DT", \
        "largest step, s, in [0, 1] [0 = a quarter of the shortest binary contact time at 2 v_imp]"), \
    ROW("max-steps", GW_PARAM_LONG, max_steps, "", 1, 1e12, 0, "10000000", "N", \
        "internal steps allowed between outputs [1e7]"),

/* The relative energy error |E - E_0| / E_0 of the ledger (kinetic + elastic +
 * gravity + dissipated, physics.md 1.5) closes to ~1e-9 at the default
 * tolerances; a limit of 1 (the whole energy) is the loosest that still means
 * something, above it the check acts as off, which 0 already says (the layer's
 * energy-tol has the same range). */
#define GW_CHAIN_ENERGY_ROW \
    ROW("energy-tol", GW_PARAM_DOUBLE, energy_tol, "", 0, 1, 0, "0", "E", \
        "abort when the relative energy error exceeds E, in [0, 1] [0 = off]"),

/* The sheet as a material, the sensor as a body, guide friction (chain_wall.c,
 * chain_general.c). Rows without a default are "not given": the sheet's own
 * constants, a rigid sensor. */
#define GW_CHAIN_WALL_ROWS \
    CHOICE("sheet-law", sheet_law, SHEET_LAWS, NULL, "LAW", \
           "how --sheet becomes a wall: fitted (Hertz K_eff from the measured tau_max(N=1)), hertz, " \
           "layer (bonded elastic layer) or material (layer with the sheet's loss; Thornton plastic " \
           "for a sheet with a yield stress) [fitted]"), \
    ROW("sheet-yield", GW_PARAM_DOUBLE, sheet_yield, "Pa", 0, 1e10, 0, NULL, "Y", \
        "yield stress of the sheet with --sheet-law material, Pa (0 = elastic) [the sheet's]"), \
    ROW("sheet-loss", GW_PARAM_DOUBLE, sheet_loss, "", 0, 2, 0, NULL, "T", \
        "loss factor tan(delta) of the sheet with --sheet-law material (0 = elastic) [the sheet's]"), \
    ROW("sensor-mass", GW_PARAM_DOUBLE, sensor_mass, "kg", 1e-7, 1e3, 0, NULL, "M", \
        "the sensor as a body: mass under the wall contact, kg, in [1e-7, 1e3] [rigid sensor]"), \
    ROW("sensor-stiffness", GW_PARAM_DOUBLE, sensor_stiffness, "N/m", 1e3, 1e14, 0, NULL, "K", \
        "stiffness of the sensor body, N/m, in [1e3, 1e14]"), \
    ROW("sensor-damping", GW_PARAM_DOUBLE, sensor_damping, "N s/m", 0, 1e9, 0, NULL, "C", \
        "damping of the sensor body, N s/m, in [0, 1e9] [0]"), \
    ROW("guide-friction", GW_PARAM_DOUBLE, guide_friction, "N", 0, 1, 0, "0", "F", \
        "Coulomb friction of each bead on its guide, N, in [0, 1] [0]"), \
    ROW("guide-viscous", GW_PARAM_DOUBLE, guide_viscous, "N s/m", 0, 100, 0, "0", "C", \
        "viscous friction of each bead on its guide, N s/m, in [0, 100] [0]"),

/* A study's setup that holds a column setup (its member col) besides its own
 * rows t: zeroed, the column's defaults, then t's; and the reverse. size is
 * the study struct's. */
int chain_study_setup_init(void *s, size_t size, gw_chain_setup *col, const gw_param *t);
void chain_study_setup_clear(void *s, gw_chain_setup *col, const gw_param *t);
/* The check of a study over a range of N: s's rows as t says (gw_param_check),
 * no per-bead radii in its column setup col, and the study's work, runs columns
 * at each N of t's range row "n", within GW_CHAIN_STUDY_WORK_MAX
 * (gw_chain_study.h). GW_EINVAL naming the row. */
int chain_study_range_check(const gw_param *t, const void *s, const gw_chain_setup *col, int runs, gw_err *err);

/* The most impact velocities (vimp and heights rows, gw_param.rows) of a study
 * over a range of N: each runs at least one column of at least one bead, one
 * bead^2 of the study's work, so GW_CHAIN_STUDY_WORK_MAX (2e6) bounds them */
#define SPEEDS_MOST "2000000"

#endif
