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

/* Accepted Hertz coefficients, N/m^1.5: the stiffest real contact (diamond on
 * diamond, R = 1 m) has k ~ 1e12, the softest sheet of Table 2 K_eff ~ 1e6. */
#define GW_CHAIN_K_MIN 1e3
#define GW_CHAIN_K_MAX 1e14

typedef struct gw_chain_setup {
    long n;               /* beads [1] */
    double vimp;          /* impact velocity toward the wall, m/s [0.3] */
    int material;         /* bead material (choice) [steel] */
    double radius;        /* bead radius, m [4e-3] */
    int wall_material;    /* wall material, a half-space (choice) [steel] */
    int sheet;            /* sheet of Table 2 on the wall (choice) [-1: none given] */
    gw_param_list radii;  /* per-bead radii, m, bead 1 first [empty] */
    double k, kwall, mass;/* direct coefficients, N/m^1.5, kg [NaN: from materials] */
    double gravity;       /* toward the wall, m/s^2 [0] */
    int damping;          /* none, kk, hc (choice) [none] */
    double gamma, alpha;  /* damping constants [NaN: not given = 0] */
    double restitution;   /* calibrate gamma/alpha to this one-bead restitution [NaN: off] */
    double restitution_v; /* impact velocity of the calibration, m/s [NaN: vimp] */
    int solver;           /* cvode, arkode, rk4 (choice) [cvode] */
    int method;           /* default, bdf, adams, erk, dirk, imex (choice) [default] */
    double rtol, atol;    /* tolerances [1e-12] */
    double dt, dt_max;    /* s [0: auto, unlimited] */
    long max_steps;       /* steps between outputs [1e7] */
    double t_max;         /* s [0: 20 (n T_q + tau_1)] */
    double dt_out;        /* sampling interval, s [0: tau_1/200] */
    double energy_tol;    /* stop when the energy error exceeds it [0: off] */
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
    gw_chain_params params; /* params.masses/kc point into the arrays below */
    gw_chain_run_opts run;
    double *masses, *kc;    /* owned (per-bead radii) */
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
} gw_chain_collision;

/* The table of gw_chain_collision's results. */
const gw_param *gw_chain_collision_fields(void);

/* Resolve s and run the collision into out (zeroed first; free with
 * gw_chain_collision_free, also after a failure: out then holds what was
 * computed). Returns GW_OK, GW_EINVAL (setup), GW_ENOMEM, or the failure of
 * gw_chain_collide (GW_ESOLVER, GW_ELIMIT, GW_EENERGY) with its message. */
int gw_chain_collision_run(const gw_chain_setup *s, gw_chain_collision *out, gw_err *err);
void gw_chain_collision_free(gw_chain_collision *out);

#endif
