/*
 * layer_setup_rows.h (private to layer/): the material rows of the layer's
 * parameter tables (gw_layer_study.h), written once for layer-impact
 * (layer_setup.c: mass law and clump mass default to the sample's) and
 * layer-make (layer_make_study.c: disc, sum). Hertz-Mindlin contacts,
 * physics.md 2.1 (B.1-B.4). It also gives the layer tables' row constructors
 * ROW, CHOICE, FLAG (inputs) and RD, RI, RF (a flag), RL, RA (results), on the includer's
 * OFF(field) (the field's offset in its struct).
 */
#ifndef GW_LAYER_SETUP_ROWS_H
#define GW_LAYER_SETUP_ROWS_H

#include "gw_layer_study.h"

#define ROW(nm, ty, f, un, lo, hi, op, opx, df, mv, hl) GW_PARAM_ROW(nm, ty, OFF(f), un, lo, hi, op, opx, df, mv, hl)
#define CHOICE(nm, f, ch, df, mv, hl) GW_PARAM_CHOICE_ROW(nm, OFF(f), ch, df, mv, hl)
#define FLAG(nm, f, hl) GW_PARAM_FLAG_ROW(nm, OFF(f), hl)
#define RD(nm, f, un, hl) GW_RESULT_ROW(nm, GW_PARAM_DOUBLE, OFF(f), un, hl)
#define RI(nm, f, hl) GW_RESULT_ROW(nm, GW_PARAM_INT, OFF(f), "", hl)
#define RF(nm, f, hl) GW_RESULT_FLAG(nm, OFF(f), hl)
#define RL(nm, f, hl) GW_RESULT_ROW(nm, GW_PARAM_LONG, OFF(f), "", hl)
#define RA(nm, f, un, r, c, names, hl) GW_RESULT_ARRAY(nm, OFF(f), un, r, c, names, hl)

/* mass-law choices in GW_LAYER_MASS_* order, clump-mass in GW_LAYER_CLUMP_MASS_* order */
_Static_assert(GW_LAYER_MASS_DISC == 0 && GW_LAYER_MASS_SPHERE == 1, "mass-law choices disc,sphere");
_Static_assert(GW_LAYER_CLUMP_MASS_SUM == 0 && GW_LAYER_CLUMP_MASS_UNION == 1, "clump-mass choices sum,union");

/* LAW, CLUMP: the defaults of mass-law and clump-mass (NULL: not given);
 * WLAW, WCLUMP: the end of their help, "[disc]", "[sum]" or "[the sample's]".
 * clump-mass is optional (gw_param.h): given or not is told apart at its
 * default's value too (layer-make refuses it given without clumps). */
#define GW_LAYER_MATERIAL_ROWS(LAW, CLUMP, WLAW, WCLUMP) \
    ROW("friction", GW_PARAM_DOUBLE, friction, "deg", 0, 90, 0, 1, "30", "PHI", "friction angle phi, deg in [0, 90) [30]"), \
    ROW("shear-modulus", GW_PARAM_DOUBLE, shear_modulus, "Pa", 1e-3, 1e15, 0, 0, "40e9", "G", "shear modulus, Pa [40e9]"), \
    ROW("poisson", GW_PARAM_DOUBLE, poisson, "", 0, 0.499999, 0, 0, "0.25", "NU", "Poisson ratio [0.25]"), \
    ROW("density", GW_PARAM_DOUBLE, density, "kg/m^3", 1e-6, 1e6, 0, 0, "2650", "RHO", "particle density, kg/m^3 [2650]"), \
    ROW("gravity", GW_PARAM_DOUBLE, gravity, "m/s^2", 0, 1e4, 0, 0, "9.81", "G", "gravity, m/s^2 [9.81]"), \
    ROW("skin", GW_PARAM_DOUBLE, skin, "m", GW_LAYER_SKIN_MIN, 1e6, 0, 0, "0.1", "S", "contact-list skin, m in [1e-15, 1e6] [0.1]"), \
    CHOICE("mass-law", mass_law, "disc,sphere", LAW, "LAW", "disc (unit thickness) or sphere " WLAW), \
    GW_PARAM_OPT_CHOICE_ROW("clump-mass", OFF(clump_mass), "sum,union", CLUMP, "HOW", \
           "clump mass: sum (members added, overlaps twice, as PFC2D) or union (density x the union's area; " \
           "disc law) " WCLUMP),

/* The material rows of setup *s (either setup struct) into gw_layer_params *lp,
 * whose other fields are left as they are. */
#define GW_LAYER_MATERIAL_TO_PARAMS(lp, s)                                     \
    do {                                                                       \
        (lp)->friction_deg = (s)->friction;                                    \
        (lp)->shear_modulus = (s)->shear_modulus;                              \
        (lp)->poisson = (s)->poisson;                                          \
        (lp)->density = (s)->density;                                          \
        (lp)->gravity = (s)->gravity;                                          \
        (lp)->skin = (s)->skin;                                                \
    } while (0)

#endif
