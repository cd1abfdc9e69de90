/*
 * layer_stats.h (private to layer/ and its tests): the Bourrier analyses of a
 * layer sweep table (docs/physics.md 2.3 statistics, 2.5 bouncing-occurrence
 * diagram, binary-impact formula B.24-B.28, boundary model B.31), used by
 * `granwave layer-stats` (layer_stats.c).
 *
 * The input is OUT/results.csv of `granwave sweep` with model = layer: '#'
 * comment lines (among them "# param NAME = VALUE" for the fixed parameters),
 * then the header "case,<grid keys>,x_impact,bounced,e_n,...", then one row per
 * case. The grid keys are the columns between `case` and `x_impact`; `point`
 * (impact-point index) is the one grid key that does not define a group.
 *
 * Units: lengths of the diagram in R_m (R_b/R_m, H/R_m, penetration_rm), angles
 * in degrees as in the table, energies as fractions of the incident energy.
 * Errors: GW_EIO (file), GW_EFORMAT ("path:line: ..."), GW_ENOMEM, GW_EINVAL;
 * a failed call leaves its output zeroed (nothing to free).
 */
#ifndef GW_LAYER_STATS_H
#define GW_LAYER_STATS_H

#include "gw_common.h"

#define GW_LAYER_RESULTS_MAX_KEYS 32

/* A layer sweep table. Grid values are kept as the strings of the config
 * (grouping compares strings) and as numbers (NaN when not numeric). Model
 * cells are numbers; "nan"/"inf" are accepted (a case may leave a quantity
 * undefined). */
typedef struct gw_layer_results {
    char path[4096];
    int ngrid;                                    /* grid keys */
    char *grid_name[GW_LAYER_RESULTS_MAX_KEYS];
    int ncols;                                    /* model columns */
    char **col_name;                              /* [ncols] */
    long nrows;
    long *case_id;                                /* [nrows] */
    char **grid_value;                            /* [nrows * ngrid], owned */
    double *grid_num;                             /* [nrows * ngrid] */
    double *val;                                  /* [nrows * ncols] */
    int nparams;                                  /* "# param" lines */
    char *param_name[GW_LAYER_RESULTS_MAX_KEYS];
    char *param_value[GW_LAYER_RESULTS_MAX_KEYS];
} gw_layer_results;

/* Columns layer-stats needs; a table without one of them is refused. */
extern const char *const gw_layer_results_required[];
extern const int gw_layer_results_nrequired;

/* Read a table (file) or parse one held in memory (text; name is used in the
 * messages). GW_EIO when the file cannot be read; GW_EFORMAT naming
 * "path:line" for a missing header or required column, a wrong number of
 * cells, a non-numeric model cell or case number, `bounced` other than 0, 1
 * or NaN, no data rows, a case number that appears twice, a row with bounced 1
 * and a non-finite e_n, e or alpha_r (tables with the column e_n_first: a row
 * with bounced 1 and a non-finite e_n_first, e_first or alpha_r_first; its e_n,
 * e, alpha_r may be NaN, a rebound cut before T_f). A FIFO, device or directory is refused
 * (GW_EFORMAT) without reading it. */
int gw_layer_results_read(const char *path, gw_layer_results *t, gw_err *err);
int gw_layer_results_parse(const char *text, const char *name, gw_layer_results *t,
                           gw_err *err);
void gw_layer_results_free(gw_layer_results *t);

/* Index of model column name, or -1. */
int gw_layer_results_col(const gw_layer_results *t, const char *name);
/* Index of grid key name, or -1. */
int gw_layer_results_key(const gw_layer_results *t, const char *name);
/* Value of fixed parameter name ("# param" line), or NULL. */
const char *gw_layer_results_param(const gw_layer_results *t, const char *name);
/* Numeric value of quantity name for row i: the grid value if name is a grid
 * key, else the "# param" value, else dflt. */
double gw_layer_results_value(const gw_layer_results *t, long i, const char *name, double dflt);

/* Mean and sample standard deviation (divisor n - 1; NaN for n < 2) of the
 * finite values. */
typedef struct gw_layer_moment {
    int n;
    double mean, std;
} gw_layer_moment;

void gw_layer_moment_of(const double *v, int n, gw_layer_moment *m);

/* One group: the rows sharing every grid value except `point`, ordered by
 * point (then case). e_n, e and alpha_r need a rebound: their moments are over
 * the bouncing rows (bounced = 1); the others are over every row. */
typedef struct gw_layer_group {
    long first;           /* row whose grid values name the group */
    int n;                /* rows (impact points) */
    long *rows;           /* [n] row indices, by point */
    int n_valid;          /* rows with bounced 0 or 1 (decided) */
    int n_bounced;
    /* Undecided rows (bounced NaN: the run ended before the verdict) count as
     * not bounced in share, the share of points that bounced before the end of
     * their run (the meaning of the share of tables made before undecided
     * outcomes existed); share_decided leaves them out; share_high counts them
     * as bounced. The verdict is certain when no outcome of the undecided
     * points could change it. */
    double share;         /* n_bounced / n */
    double share_decided; /* n_bounced / n_valid (NaN if none valid) */
    double share_high;    /* (n_bounced + n - n_valid) / n */
    int bouncing;         /* global verdict: share >= criterion */
    int verdict_certain;  /* share >= criterion or share_high < criterion */
    gw_layer_moment e_n, e, alpha_r, penetration, penetration_rm, block_loss, dissipated;
    /* the first free-flight maximum (columns e_n_first, e_first, alpha_r_first
     * when the table has them; n = 0 otherwise), over the bouncing rows */
    gw_layer_moment e_n_first, e_first, alpha_r_first;
    gw_layer_moment rebound_energy; /* e^2 (the block's rebound kinetic energy over the
                                       incident one, translation), 0 for a point that does
                                       not bounce; over every valid row */
    double energy_error_max;
    /* spread of the impact points: max - min x_impact (m), and in R_m with R_m
     * = penetration / penetration_rm of the group's first row where both are
     * finite and positive (NaN otherwise). The paper's 100 points 0.05 m apart
     * span 5 m; a few points at that spacing hit one spot of the surface. */
    double x_span, x_span_rm;
    /* convergence with the number of points (Fig. 10): over the first k points
     * (k = 1..n), the mean over the bouncing ones among them and the share */
    double *run_e_n, *run_e, *run_share; /* [n] (run_share: as share) */
    int k_stable_e;       /* smallest k after which the running mean of e stays
                             within 5 % of the final mean (0 if undefined) */
} gw_layer_group;

typedef struct gw_layer_groups {
    double criterion;
    int nkeys;                          /* grouping keys (grid keys but point) */
    int key[GW_LAYER_RESULTS_MAX_KEYS]; /* their grid indices */
    int point_key;                      /* grid index of point, or -1 */
    int n;
    gw_layer_group *g;                  /* in order of first case */
} gw_layer_groups;

/* Group the rows and compute every group's statistics. criterion in (0, 1]. */
int gw_layer_groups_make(const gw_layer_results *t, double criterion, gw_layer_groups *gs,
                         gw_err *err);
void gw_layer_groups_free(gw_layer_groups *gs);

/* ---- bouncing-occurrence diagram (docs/physics.md 2.5) ---- */

enum {
    GW_LAYER_BND_CROSS = 0, /* the verdict changes from bouncing to not along H */
    GW_LAYER_BND_ABOVE = 1, /* every H bounces: H* above the grid */
    GW_LAYER_BND_BELOW = 2, /* no H bounces: H* below the grid */
    GW_LAYER_BND_INVERTED = 3 /* only not-bouncing -> bouncing changes */
};

/* The boundary in one R_b/R_m column. Bouncing lies below the boundary. The
 * crossing is the lowest pair of neighbouring heights (h_lo bouncing, h_hi
 * not); H* is placed where the bounce share, interpolated linearly in H
 * between them, equals the criterion:
 *     H* = h_lo + (s_lo - S) / (s_lo - s_hi) (h_hi - h_lo).
 * changes > 1 flags a column where the verdict changes more than once. */
typedef struct gw_layer_boundary_pt {
    double x;            /* R_b/R_m */
    int kind;            /* GW_LAYER_BND_* */
    double h;            /* H* / R_m (NaN unless CROSS) */
    double h_lo, h_hi, s_lo, s_hi;
    int changes;
    double penetration_rm; /* mean of the two bracketing cells (NaN unless CROSS) */
} gw_layer_boundary_pt;

typedef struct gw_layer_diagram {
    double criterion;
    int nx, nh;
    double *xs, *hs;       /* sorted distinct R_b/R_m and H/R_m */
    double *share;         /* [nx * nh], share[i * nh + j]; NaN where no cell */
    double *pen;           /* [nx * nh] mean penetration_rm */
    gw_layer_boundary_pt *pts; /* [nx] */
    int ncross;
    double r_crit;         /* largest x with every column up to it all-bouncing
                              (NaN if the first column is not) */
    double r_crit_upper;   /* the next x (first column with a non-bouncing cell;
                              NaN if none) */
    double r_min, h_min;   /* crossing with the lowest H* (NaN if none) */
    double penetration_rm; /* mean over the crossings' bracketing cells */
} gw_layer_diagram;

/* Build the diagram from n cells (x, h, share, mean penetration_rm; pen may
 * be NULL). Cells with h <= 0 (the full sample) or a NaN share are skipped.
 * GW_EINVAL for duplicate cells or fewer than 2 distinct x or h. */
int gw_layer_diagram_make(int n, const double *x, const double *h, const double *share,
                          const double *pen, double criterion, gw_layer_diagram *d,
                          gw_err *err);
void gw_layer_diagram_free(gw_layer_diagram *d);

/* ---- boundary model B.31 ---- */

/* f(x) = offset + (x - beta)/(2 T) (sqrt(1 + (a T/b) x^2/(x - beta)^2) - 1),
 * T = tan gamma, offset = delta* / (2 R_m), evaluated as the positive root of
 * its quadratic, f = offset + (sqrt(u^2 + K x^2) - u) / (2 T) with u = x - beta
 * and K = (a/b) T: equal to B.31 for x > beta and continued below beta (where
 * B.31 taken literally changes sign) by the steep branch ~ |u| / T that is the
 * diagram's vertical asymptote. Minimum at x = 2 beta / (1 + K), value
 * offset + (a/b) beta / (1 + K). */
typedef struct gw_layer_b31 {
    double offset;    /* delta* / (2 R_m) */
    double beta;
    double a_over_b;  /* a/b: a = (pi/2) rho_b V_i^2, b dissipation per area */
    double tan_gamma;
} gw_layer_b31;

double gw_layer_b31_eval(const gw_layer_b31 *p, double x);
/* Position and value of the minimum. */
void gw_layer_b31_min(const gw_layer_b31 *p, double *x_min, double *f_min);

/* Parameters to fit (the others stay at their start values). */
enum { GW_LAYER_B31_OFFSET = 1, GW_LAYER_B31_BETA = 2, GW_LAYER_B31_AB = 4,
       GW_LAYER_B31_TANG = 8 };

typedef struct gw_layer_b31_fit {
    gw_layer_b31 p;       /* fitted (fixed ones as given) */
    gw_layer_b31 err;     /* standard errors (0 for fixed; NaN when dof = 0) */
    double corr_beta_ab;  /* correlation of beta and ln(a/b) when both free */
    int free_mask, n, dof, iterations, converged;
    double rms;           /* root-mean-square residual, R_m */
    double x_min, h_min;  /* minimum of the fitted curve */
} gw_layer_b31_fit;

/* Nonlinear least squares (gsl_multifit_nlinear, trust region with
 * Levenberg-Marquardt steps) of B.31 to n boundary points (x, h), unweighted.
 * a/b and tan gamma are fitted as logarithms (kept positive), beta and the
 * offset as they are. Several starts for beta (fractions of the x of the
 * lowest point); the best converged one is kept. Standard errors from the
 * covariance scaled by the residual variance (chi^2 / dof). GW_EINVAL when
 * n < number of free parameters or no start converges. */
int gw_layer_b31_fit_points(const double *x, const double *h, int n, const gw_layer_b31 *start,
                            int free_mask, gw_layer_b31_fit *fit, gw_err *err);

/* Binary-impact fraction of the block's kinetic energy lost to a target at
 * rest (B.24-B.28): 4 m / (1 + m)^2 with mass ratio m = r^2 (discs) or r^3
 * (spheres), r = R_b/R_m. */
double gw_layer_binary_loss(double r, int sphere);

/* ---- the layer-stats command (layer_stats.c, layer_stats_out.c) ---- */

typedef struct layer_stats_binary {
    double rb_rm, alpha;    /* R_b/R_m, incidence (deg) */
    gw_layer_moment loss;   /* block_loss_first_contact over the rows */
    double disc, sphere;    /* gw_layer_binary_loss */
} layer_stats_binary;

typedef struct layer_stats_diagram {
    int *groups, ngroups;   /* group indices in this diagram */
    int ok;                 /* the diagram could be built */
    char reason[512];
    gw_layer_diagram d;
    double offset;          /* delta* / (2 R_m) used by the fit */
    const char *offset_source;
    double a;               /* (pi/2) rho V_i^2, J/m^3 per unit thickness */
    int fit_ok;
    char fit_reason[512];
    gw_layer_b31_fit fit;
} layer_stats_diagram;

typedef struct layer_stats_run {
    const char *input;
    char *cmdline;
    double gamma_deg, delta_rm; /* delta_rm NaN: from the measured penetration */
    int fit_mask;
    gw_layer_results t;
    gw_layer_groups gs;
    layer_stats_binary *bin;
    int nbin;
    int (*walls)[2];        /* pairs of groups: walls kept, walls removed */
    int nwalls;
    layer_stats_diagram *dia;
    int ndia;
} layer_stats_run;

void layer_stats_run_free(layer_stats_run *R);
/* Everything as JSON (full = 0: the header and the diagrams only). */
cJSON *layer_stats_json(const layer_stats_run *R, int full);
/* The --out files, each atomically. */
int layer_stats_write_files(const layer_stats_run *R, const char *dir, gw_err *err);

#endif
