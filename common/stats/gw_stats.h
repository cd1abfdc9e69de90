/*
 * gw_stats.h: statistics of a sweep table (installed with libgranwave): the
 * Bourrier analyses of a layer sweep table (docs/physics.md 2.3 statistics,
 * 2.5 bouncing-occurrence diagram, binary-impact formula B.24-B.28, boundary
 * model B.31), as one library call (gw_stats_run: setup and outcome described
 * by gw_param tables, the study "layer-stats" of gw_study.h) and as the parts
 * it is made of (table reader, groups, diagram, B.31 fit). `granwave
 * layer-stats` (app/layer/layer_stats.c) parses its flags, calls gw_stats_analyse
 * and prints; nothing here prints, parses a command line or exits.
 *
 * The module reads a table and includes no model header: the values of the
 * sweep model's parameters that a table leaves out (neither a grid key nor a
 * "# param" line) are given by the caller (gw_stats_defaults).
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
#ifndef GW_STATS_H
#define GW_STATS_H

#include "gw_common.h"
#include "gw_param.h"

#include "gw_api.h"

GW_BEGIN_DECLS /* the exported interface, C linkage (gw_api.h) */

#define GW_STATS_MAX_KEYS 32

/* A layer sweep table. Grid values are kept as the strings of the config
 * (grouping compares strings) and as numbers (NaN when not numeric). Model
 * cells are numbers; "nan"/"inf" are accepted (a case may leave a quantity
 * undefined). */
typedef struct gw_stats_table {
    char path[4096];
    int ngrid;                                    /* grid keys */
    char *grid_name[GW_STATS_MAX_KEYS];
    int ncols;                                    /* model columns */
    char **col_name;                              /* [ncols] */
    long nrows;
    long *case_id;                                /* [nrows] */
    char **grid_value;                            /* [nrows * ngrid], owned */
    double *grid_num;                             /* [nrows * ngrid] */
    double *val;                                  /* [nrows * ncols] */
    int nparams;                                  /* "# param" lines */
    char *param_name[GW_STATS_MAX_KEYS];
    char *param_value[GW_STATS_MAX_KEYS];
    /* From the sweep's first line "# granwave V sweep, model M, config H, N of
     * C cases": N and C (-1 when the table has no such line, a table made by
     * hand), and its "# grid NAME = v1, v2, ..." lines (tables written since
     * the ninth hostile pass): the grid, in the config's order (NULL when the
     * table lists none). */
    long sweep_rows, sweep_cases;
    char *grid_list[GW_STATS_MAX_KEYS];           /* [ngrid] "v1, v2, ..." */
    /* Tables written since rows carry hashes: the model (first line; "layer"
     * when absent), the trailing columns case_config_fnv1a64 and KEY_fnv1a64
     * (nhash of them, after the model's columns), and the "# input KEY =
     * VALUE fnv1a64 HEX" lines. Each row's case config hash must be the one
     * its grid values and the "# param" lines give (gw_case_config_hash), and
     * its KEY_fnv1a64 the hash of the "# input" line of its file. */
    char model[64];
    int nhash;
    char *hash_name[2];
    unsigned long long *row_hash;                 /* [nrows * nhash] */
    long *row_line;                               /* [nrows] the row's line, for messages */
    int ninputs;
    char **input_key, **input_value;              /* [ninputs] */
    unsigned long long *input_hash;               /* [ninputs] */
    /* FNV-1a 64 of the table's bytes (gw_stats_table_read; 0 and has_content_hash
     * 0 for a table parsed from text): the outputs record it beside the path, so
     * that the table an analysis read can be told from a later version of it */
    unsigned long long content_hash;
    int has_content_hash;
} gw_stats_table;

/* Columns layer-stats needs; a table without one of them is refused. */
extern const char *const gw_stats_table_required[];
extern const int gw_stats_table_nrequired;

/* Read a table (file) or parse one held in memory (text; name is used in the
 * messages). GW_EIO when the file cannot be read; GW_EFORMAT naming
 * "path:line" for a missing header or required column, a wrong number of
 * cells, a non-numeric model cell or case number, `bounced` other than 0, 1
 * or NaN, no data rows, a case number that appears twice, a row with bounced 1
 * and a non-finite e_n, e or alpha_r (tables with the column e_n_first: a row
 * with bounced 1 and a non-finite e_n_first, e_first or alpha_r_first; its e_n,
 * e, alpha_r may be NaN, a rebound cut before T_f). A table whose first line
 * is the sweep's ("N of C cases") must hold every case 0 .. C-1, and N = C
 * (a sweep writes its table when every case has run): a row deleted, a case
 * number beyond C or a header edited is refused naming the first missing case;
 * with the "# grid" lines each row's grid values must be those of its case
 * number. A FIFO, device or directory is refused (GW_EFORMAT) without reading it.
 * A file whose last row has no newline after it (LF, or the CR of a CR LF) was
 * cut short: GW_EFORMAT "path:line: the file ends inside this line ..." (a
 * last comment line may; text given to gw_stats_table_parse may end so). */
int gw_stats_table_read(const char *path, gw_stats_table *t, gw_err *err);
/* name (the table's name in messages, kept in t->path): NULL or "" is
 * "<table>" ("<table>:1: ...", where ":1: ..." named nothing). */
int gw_stats_table_parse(const char *text, const char *name, gw_stats_table *t,
                           gw_err *err);
void gw_stats_table_free(gw_stats_table *t);

/* Index of model column name, or -1. */
int gw_stats_table_col(const gw_stats_table *t, const char *name);
/* 1 when a and b name one key: equal with '-' and '_' taken as one (a sweep
 * reads rb_rm as rb-rm); grid keys and params are looked up this way. */
int gw_stats_same_key(const char *a, const char *b);
/* Index of grid key name ('-' and '_' one), or -1. */
int gw_stats_table_key(const gw_stats_table *t, const char *name);
/* Whether rows ra and rb hold one value of grid key `key`: as numbers when
 * either is one (2 and 2.0, 0 and -0 are one value), else as strings. Groups,
 * diagrams and the walls pairs compare grid values this way. */
int gw_stats_table_same(const gw_stats_table *t, long ra, long rb, int key);
/* Value of fixed parameter name ("# param" line), or NULL. */
const char *gw_stats_table_param(const gw_stats_table *t, const char *name);
/* Numeric value of quantity name for row i: the grid value if name is a grid
 * key, else the "# param" value, else dflt. */
double gw_stats_table_value(const gw_stats_table *t, long i, const char *name, double dflt);

/* Mean and sample standard deviation (divisor n - 1; NaN for n < 2) of the
 * finite values. */
typedef struct gw_stats_moment {
    int n;
    double mean, std;
} gw_stats_moment;

void gw_stats_moment_of(const double *v, int n, gw_stats_moment *m);

/* One group: the rows sharing every grid value except `point`, ordered by
 * point (then case). e_n, e and alpha_r need a rebound: their moments are over
 * the bouncing rows (bounced = 1); the others are over every row. */
typedef struct gw_stats_group {
    long first;           /* row whose grid values name the group */
    int n;                /* rows (impact points) */
    long *rows;           /* [n] row indices, by point */
    int n_valid;          /* rows with bounced 0 or 1 (decided) */
    int n_bounced;
    int n_fell_off;       /* rows whose block fell off the layer (column fell_off 1: decided,
                             bounced 0; 0 for a table without the column) */
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
    /* block_loss and dissipated: of the columns block_loss_first_contact and
     * dissipated_first_contact, the names of every output form */
    gw_stats_moment e_n, e, alpha_r, penetration, penetration_rm, block_loss, dissipated;
    /* the first free-flight maximum (columns e_n_first, e_first, alpha_r_first
     * when the table has them; n = 0 otherwise), over the bouncing rows */
    gw_stats_moment e_n_first, e_first, alpha_r_first;
    gw_stats_moment rebound_energy; /* e^2 (the block's rebound kinetic energy over the
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
} gw_stats_group;

typedef struct gw_stats_groups {
    double criterion;
    int nkeys;                          /* grouping keys (grid keys but point) */
    int key[GW_STATS_MAX_KEYS]; /* their grid indices */
    int point_key;                      /* grid index of point, or -1 */
    int n;
    gw_stats_group *g;                  /* in order of first case */
} gw_stats_groups;

/* Group the rows and compute every group's statistics. criterion in (0, 1]. */
int gw_stats_groups_make(const gw_stats_table *t, double criterion, gw_stats_groups *gs,
                         gw_err *err);
void gw_stats_groups_free(gw_stats_groups *gs);

/* ---- bouncing-occurrence diagram (docs/physics.md 2.5) ---- */

enum {
    GW_STATS_BND_CROSS = 0, /* the verdict changes from bouncing to not along H */
    GW_STATS_BND_ABOVE = 1, /* every H bounces: H* above the grid */
    GW_STATS_BND_BELOW = 2, /* no H bounces: H* below the grid */
    GW_STATS_BND_INVERTED = 3 /* only not-bouncing -> bouncing changes */
};

/* The boundary in one R_b/R_m column. Bouncing lies below the boundary. The
 * crossing is the lowest pair of neighbouring heights (h_lo bouncing, h_hi
 * not); H* is placed where the bounce share, interpolated linearly in H
 * between them, equals the criterion:
 *     H* = h_lo + (s_lo - S) / (s_lo - s_hi) (h_hi - h_lo).
 * changes > 1 flags a column where the verdict changes more than once. */
typedef struct gw_stats_boundary_pt {
    double x;            /* R_b/R_m */
    int kind;            /* GW_STATS_BND_* */
    double h;            /* H* / R_m (NaN unless CROSS) */
    double h_lo, h_hi, s_lo, s_hi;
    int changes;
    double penetration_rm; /* mean of the two bracketing cells (NaN unless CROSS) */
} gw_stats_boundary_pt;

typedef struct gw_stats_diagram {
    double criterion;
    int nx, nh;
    double *xs, *hs;       /* sorted distinct R_b/R_m and H/R_m */
    double *share;         /* [nx * nh], share[i * nh + j]; NaN where no cell */
    double *pen;           /* [nx * nh] mean penetration_rm */
    gw_stats_boundary_pt *pts; /* [nx] */
    int ncross;
    double r_crit;         /* largest x with every column up to it all-bouncing
                              (NaN if the first column is not) */
    double r_crit_upper;   /* the next x (first column with a non-bouncing cell;
                              NaN if none) */
    double r_min, h_min;   /* crossing with the lowest H* (NaN if none) */
    double penetration_rm; /* mean over the crossings' bracketing cells */
} gw_stats_diagram;

/* Build the diagram from n cells (x, h, share, mean penetration_rm; pen may
 * be NULL). Cells with h <= 0 (the full sample) or a NaN share are skipped.
 * GW_EINVAL for duplicate cells, fewer than 2 distinct x or h, a share
 * outside [0, 1] or an x (R_b/R_m) not > 0 (NaN marks no cell), naming it. */
int gw_stats_diagram_make(int n, const double *x, const double *h, const double *share,
                          const double *pen, double criterion, gw_stats_diagram *d,
                          gw_err *err);
void gw_stats_diagram_free(gw_stats_diagram *d);

/* ---- boundary model B.31 ---- */

/* f(x) = offset + (x - beta)/(2 T) (sqrt(1 + (a T/b) x^2/(x - beta)^2) - 1),
 * T = tan gamma, offset = delta* / (2 R_m), evaluated as the positive root of
 * its quadratic, f = offset + (sqrt(u^2 + K x^2) - u) / (2 T) with u = x - beta
 * and K = (a/b) T: equal to B.31 for x > beta and continued below beta (where
 * B.31 taken literally changes sign) by the steep branch ~ |u| / T that is the
 * diagram's vertical asymptote. Minimum at x = 2 beta / (1 + K), value
 * offset + (a/b) beta / (1 + K). */
typedef struct gw_stats_b31 {
    double offset;    /* delta* / (2 R_m) */
    double beta;
    double a_over_b;  /* a/b: a = (pi/2) rho_b V_i^2, b dissipation per area */
    double tan_gamma;
} gw_stats_b31;

/* NaN for p NULL, a/b or tan gamma not > 0, a parameter or x not finite (the
 * curves the fit gives); any finite x has its value (from |x| = 1e154 up it
 * was NaN: u^2 overflowed). */
double gw_stats_b31_eval(const gw_stats_b31 *p, double x);
/* Position and value of the minimum; both NaN where gw_stats_b31_eval is NaN
 * for every x (tan gamma 0 gave a minimum, a/b < 0 one at +-inf). */
void gw_stats_b31_min(const gw_stats_b31 *p, double *x_min, double *f_min);

/* Parameters to fit (the others stay at the values given). */
enum { GW_STATS_B31_OFFSET = 1, GW_STATS_B31_BETA = 2, GW_STATS_B31_AB = 4,
       GW_STATS_B31_TANG = 8 };

typedef struct gw_stats_b31_fit {
    gw_stats_b31 p;       /* fitted (fixed ones as given) */
    gw_stats_b31 err;     /* standard errors (0 for fixed; NaN when dof = 0) */
    double corr_beta_ab;  /* correlation of beta and ln(a/b) */
    int free_mask, n, dof, iterations, converged;
    int at_bound;         /* free parameters on an edge of the box (GW_STATS_B31_* bits) */
    long evaluations;     /* sums of squares evaluated by the search */
    double rms;           /* root-mean-square residual, R_m */
    double x_min, h_min;  /* minimum of the fitted curve */
} gw_stats_b31_fit;

/* Least squares of B.31 to n boundary points (x, h), unweighted: the global
 * minimum of the sum of squared residuals over the box
 *     beta in [0, x_lo] (x_lo the smallest x: B.31 holds for x >= beta),
 *     a/b in [1e-6, 1e6], tan gamma in [tan 1e-6 deg, tan 89 deg],
 *     offset >= 0,
 * the parameters not in free_mask held at start's values (start's free
 * values are not used). beta and a/b are always free. With u = x - beta the
 * model is offset + A (sqrt(u^2 + K x^2) - u), A = 1/(2 tan gamma),
 * K = (a/b) tan gamma: for given (beta, ln K) a free offset and a free A are
 * solved exactly (linear least squares under their bounds), and the sum left,
 * a function of (beta, ln K), is evaluated on a 65 x (8 per decade of K) grid
 * and refined (pattern search) from its 6 lowest local minima; the best is
 * polished by Levenberg-Marquardt (gsl_multifit_nlinear) when that stays in
 * the box. Standard errors from (J^T J)^-1 at the minimum (a/b and tan gamma
 * as logarithms) scaled by chi^2 / dof; at_bound names parameters the box
 * stops (their errors are not those of a free minimum). GW_EINVAL when beta
 * or a/b is not free, free_mask holds another bit than the four above, n <
 * number of free parameters, a point is not finite or x_lo <= 0. */
int gw_stats_b31_fit_points(const double *x, const double *h, int n, const gw_stats_b31 *start,
                            int free_mask, gw_stats_b31_fit *fit, gw_err *err);

/* The binary impact's value (B.24-B.28, a target at rest) of the quantity
 * block_loss_first_contact measures, the fraction of the block's kinetic
 * energy gone at its smallest during the contact: 4 m / (1 + m)^2 with mass
 * ratio m = r^2 (discs) or r^3 (spheres), r = R_b/R_m, for m > 1, where the
 * block goes on forward and its energy is smallest as the contact opens; 1 for
 * m <= 1, where the block stops and rebounds inside the contact. (B.28's
 * 4 m / (1 + m)^2 below m = 1 is the loss at the contact's opening, the
 * impact's block_loss_contact_open; it read 0.64 at r = 0.5 against a measured
 * 1 before this was the binary value of what is measured.) NaN for r not > 0. */
double gw_stats_binary_loss(double r, int sphere);

/* ---- the whole analysis (gw_stats_run.c) ---- */

/* Values of the sweep model's parameters for a table that leaves them out
 * (neither a grid key nor a "# param" line): the model's defaults. The layer
 * model's: rb_rm 1, alpha 0 deg, vi 20 m/s, density 2650 kg/m^3. rb_rm and
 * alpha group the binary table (a NaN one there is refused: GW_EINVAL naming
 * it); vi and density give a = (pi/2) rho V_i^2 of the fit (NaN: a, b NaN). */
typedef struct gw_stats_defaults {
    double rb_rm, alpha, vi, density;
} gw_stats_defaults;

/* The inputs of `granwave layer-stats` (its table: gw_stats_setup_params,
 * rows named as the command's flags; "input" is its positional argument). */
typedef struct gw_stats_setup {
    char *input;        /* the sweep table (results.csv), required, owned */
    double criterion;   /* global verdict: share >= S, in (0, 1] [0.75] */
    char *fit;          /* B.31 parameters to fit, comma-separated among offset,
                           beta, a_over_b, tan_gamma, owned [NULL: not given =
                           beta,a_over_b] */
    double gamma_deg;   /* cone angle gamma, deg in (0, 89] [NaN: not given = 0.2] */
    double delta_rm;    /* delta* / R_m of B.31, [0, 1e6] [NaN: measured] */
    gw_stats_defaults defaults; /* not a table row: set by the caller after
                                   init (init sets NaN) */
} gw_stats_setup;

const gw_param *gw_stats_setup_params(void);
/* Defaults from the table, defaults NaN; free with gw_stats_setup_clear. */
int gw_stats_setup_init(gw_stats_setup *s);
void gw_stats_setup_clear(gw_stats_setup *s);

/* --fit text to a mask of GW_STATS_B31_* (blanks around an item are
 * ignored: "beta, a_over_b"): GW_EINVAL "fit: unknown parameter
 * 'X' (offset, beta, a_over_b, tan_gamma)", "fit: no parameter given", an
 * empty item or a name listed twice, or a list without beta and a_over_b
 * (the analysis has no value to hold either of them at; the offset and
 * tan gamma are held at delta-rm and gamma-deg when not listed). */
int gw_stats_fit_parse(const char *text, int *mask, gw_err *err);

typedef struct gw_stats_binary {
    double rb_rm, alpha;    /* R_b/R_m, incidence (deg) */
    gw_stats_moment loss;   /* block_loss_first_contact over the rows */
    double disc, sphere;    /* gw_stats_binary_loss */
} gw_stats_binary;

/* One bouncing-occurrence diagram (one per combination of the grouping keys
 * other than rb-rm and height-rm) with its B.31 fit. */
typedef struct gw_stats_panel {
    int *groups, ngroups;   /* group indices in this diagram */
    int ok;                 /* the diagram could be built */
    char reason[512];
    gw_stats_diagram d;
    double offset;          /* delta* / (2 R_m) used by the fit */
    const char *offset_source;
    double a;               /* (pi/2) rho V_i^2, J/m^3 per unit thickness */
    int fit_ok;
    char fit_reason[512];
    gw_stats_b31_fit fit;
} gw_stats_panel;

typedef struct gw_stats_analysis {
    const char *input;      /* = t.path */
    char *cmdline;          /* for the outputs' headers; owned, may be NULL */
    double gamma_deg, delta_rm; /* delta_rm NaN: from the measured penetration */
    int gamma_given;            /* gamma-deg was given (its default's value too) */
    int fit_given;              /* fit was given (its default's list too) */
    int fit_mask;
    gw_stats_defaults defaults;
    gw_stats_table t;
    gw_stats_groups gs;
    gw_stats_binary *bin;
    int nbin;
    int (*walls)[2];        /* pairs of groups: walls kept, walls removed */
    int nwalls;
    gw_stats_panel *dia;
    int ndia;
    char *warnings;         /* what the statistics leave out or may change (gw_common.h,
                               "warnings of a result": undecided points, bouncing points
                               without e); owned, NULL: none */
} gw_stats_analysis;

/* Read s->input and compute everything into A (zeroed first; free with
 * gw_stats_analysis_free also after a failure). GW_EINVAL naming the row
 * ("fit: ...", "criterion: ..."), the table reader's GW_EIO / GW_EFORMAT,
 * GW_ENOMEM. A diagram that cannot be built or fitted is no error: its
 * panel says why (ok, fit_ok, reason, fit_reason). */
int gw_stats_analyse(const gw_stats_setup *s, gw_stats_analysis *A, gw_err *err);
void gw_stats_analysis_free(gw_stats_analysis *A);
/* Everything as JSON (full = 0: the header and the diagrams only); the
 * command's --json. NULL on ENOMEM, and for an analysis filled by hand whose
 * counts and arrays do not agree (groups, walls, diagrams counted without
 * their arrays or naming groups or rows it has not; gw_stats_write_files
 * refuses it with GW_EINVAL naming the field, writing nothing; both read it
 * through NULL before session 34). */
cJSON *gw_stats_json(const gw_stats_analysis *A, int full);
/* The files of --out DIR (groups.csv, convergence.csv, binary.csv, walls.csv,
 * diagram.csv, boundary_fit.json), placed together (gw_outset): a write that
 * fails leaves the earlier ones as they were. */
int gw_stats_write_files(const gw_stats_analysis *A, const char *dir, gw_err *err);
/* GW_EINVAL naming both when the table input is one of the files
 * gw_stats_write_files would write into dir (gw_outset_check_input); dir or
 * input NULL is refused naming it. */
int gw_stats_out_check_input(const char *dir, const char *input, gw_err *err);
/* Whether gw_stats_write_files could write into dir, before any work: what
 * gw_out_check says (what names the flag in its message), then a file is made
 * and removed at once in dir, or in its nearest existing ancestor when dir
 * does not exist yet, so that a directory that refuses new files whatever its
 * mode says (root under /proc, a read-only mount) is refused too. GW_EINVAL
 * naming dir; nothing is left behind. */
int gw_stats_out_check(const char *dir, const char *what, gw_err *err);

/* ---- the library call: the analysis as tables (gw_stats_study.c) ---- */

/* Columns of the per-group table (as groups.csv, without group and keys): the
 * JSON's group object flattened, one name per statistic in every form (a
 * moment X of the JSON, {"mean", "std", "n"}, is X_mean, X_std and n_X;
 * docs/formats.md, layer-stats outputs). The moments block_loss and dissipated
 * of gw_stats_group are block_loss_first_contact and dissipated_first_contact
 * there, as the sweep table's columns they average. The counts n_X of the
 * moments other than e and e_first follow the first 36 columns, and the
 * count of rows whose block fell off the layer (n_fell_off) the counts. */
#define GW_STATS_GROUP_COLUMNS                                                                         \
    "n_points,n_valid,n_bounced,bounce_share,bouncing,e_n_mean,e_n_std,e_mean,e_std,alpha_r_mean,"     \
    "alpha_r_std,n_e,penetration_mean,penetration_std,penetration_rm_mean,penetration_rm_std,"         \
    "block_loss_first_contact_mean,block_loss_first_contact_std,dissipated_first_contact_mean,"        \
    "dissipated_first_contact_std,rebound_energy_mean,rebound_energy_std,energy_error_max,k_stable_e," \
    "x_span,x_span_rm,e_n_first_mean,e_n_first_std,e_first_mean,e_first_std,alpha_r_first_mean,"      \
    "alpha_r_first_std,n_e_first,bounce_share_decided,bounce_share_high,verdict_certain,n_e_n,"        \
    "n_alpha_r,n_penetration,n_penetration_rm,n_block_loss_first_contact,n_dissipated_first_contact,"  \
    "n_rebound_energy,n_e_n_first,n_alpha_r_first,n_fell_off"
#define GW_STATS_GROUP_NCOLS 46 /* (the study's field "groups" states it as text: gw_stats_study.c) */
/* One group's row of that table. */
void gw_stats_group_row(const gw_stats_group *g, double row[GW_STATS_GROUP_NCOLS]);

/* The results of gw_stats_run (table gw_stats_outcome_fields): numbers of
 * rows, then tables with named columns (rows x cols, row-major, owned). */
typedef struct gw_stats_outcome {
    gw_stats_analysis a;    /* everything, for C callers */
    long rows;              /* rows of the sweep table */
    double criterion;
    int ngroups, nkeys;
    char *group_keys;       /* the grouping keys' names, comma-separated, owned */
    double *keys;           /* [ngroups x nkeys] their values (NaN: not a number) */
    double *groups;         /* [ngroups x GW_STATS_GROUP_NCOLS] */
    int nconvergence;
    double *convergence;    /* [nconvergence x 10]: running means (Fig. 10) */
    int nbinary;
    double *binary;         /* [nbinary x 7]: first contact against B.24-B.28 */
    int nwalls;
    double *walls;          /* [nwalls x 18]: walls kept / removed side by side */
    int ndiagrams;
    double *diagrams;       /* [ndiagrams x 27]: R_crit, minimum, B.31 fit */
    int ncells;
    double *cells;          /* [ncells x 5]: diagram, rb_rm, height_rm, share, penetration_rm */
    int nboundary;
    double *boundary;       /* [nboundary x 11]: H* per R_b/R_m column */
    /* per diagram, one line each ('\n'-ended; an empty line where the JSON has
     * none), owned: the B.31 fit's offset source (the JSON's fit.offset_source:
     * "fitted", "--delta-rm" or "measured: ...") and why there is no fit (its
     * fit_reason) */
    char *offset_sources, *fit_reasons;
} gw_stats_outcome;

const gw_param *gw_stats_outcome_fields(void);
/* gw_stats_analyse into out->a, then the tables. out zeroed first; free with
 * gw_stats_outcome_free also after a failure. No files are written. */
int gw_stats_run(const gw_stats_setup *s, gw_stats_outcome *out, gw_err *err);
void gw_stats_outcome_free(gw_stats_outcome *out);

GW_END_DECLS

#endif
