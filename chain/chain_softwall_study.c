/*
 * chain_softwall_study.c: the soft-wall study as a library call
 * (gw_chain_study.h); `granwave softwall` (chain_softwall.c) prints what it
 * computes.
 *
 * Columns on a soft wall (docs/physics.md 1.3): K_c = (c_tau/4)^(5/2) (5k/4)
 *   (F.22), rigid if K > K_c; N_d the first N from which F_max stays within tol
 *   of the plateau F_max(n_max) (at least SATURATION_RUN sizes, else not
 *   reached; from the first size run when it is above 1: N_d <= that size, not
 *   located); N_d predicted ceil(tau_max(N_d)/T_q) (F.8) and its fixed point;
 *   T_q measured on a steel wall (slope over N = 1..20). Columns held by
 *   gravity on the wall count as sizes not run (analyse). With sheets: each
 *   sheet of Table 2 under the sheet law (chain_sheets.c), model against
 *   measured (h = 2.9 mm).
 * Units: SI (m, s, kg, N, N/m^1.5).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_setup_rows.h"
#include "chain_model.h"
#include "chain_watch.h"
#include "gw_locale.h"

#define SATURATION_RUN 6

/* ---- the table of the inputs ---- */

#define OFF(f) offsetof(gw_chain_softwall_setup, col.f)
#define OWN(f) offsetof(gw_chain_softwall_setup, f)
static const gw_param sw_params[] = {
    {.name = "n", .type = GW_PARAM_RANGE, .offset = OWN(n), .unit = "", .min = 1, .max = 100000, .def = "1:30",
     .metavar = "A:B", .help = "column sizes [1:30]"},
    {.name = "vimp", .type = GW_PARAM_DOUBLE, .offset = OWN(vimp), .unit = "m/s", .min = GW_CHAIN_VIMP_MIN,
     .max = GW_CHAIN_VIMP_MAX, .metavar = "V", .help = "impact velocity, m/s [0.2385 = h 2.9 mm]"},
    {.name = "tol", .type = GW_PARAM_DOUBLE, .offset = OWN(tol), .unit = "", .min = 0, .max = 0.5, .open_min = 1,
     .def = "0.01", .metavar = "F", .help = "plateau tolerance for N_d (fraction) [0.01]"},
    {.name = "sheets", .type = GW_PARAM_FLAG, .offset = OWN(sheets), .unit = "", .min = 0, .max = 1, .def = "0",
     .help = "the paper's sheets (Table 2) with fitted K_eff"},
    {.name = "jobs", .type = GW_PARAM_LONG, .offset = OWN(jobs), .unit = "", .min = 0, .max = 1024, .def = "0",
     .metavar = "J", .help = "threads [0 = one per CPU]"},
    GW_CHAIN_MODEL_ROWS
    GW_PARAM_END};
#undef OFF
#undef OWN

const gw_param *gw_chain_softwall_setup_params(void) { return sw_params; }

int gw_chain_softwall_setup_init(gw_chain_softwall_setup *s)
{
    if (!s)
        return GW_EINVAL;
    return chain_study_setup_init(s, sizeof *s, &s->col, sw_params);
}

void gw_chain_softwall_setup_clear(gw_chain_softwall_setup *s)
{
    if (!s)
        return;
    chain_study_setup_clear(s, &s->col, sw_params);
}

/* ---- the table of the results ---- */

#define RFA(T, nm, f, r, hl) \
    {.name = nm, .type = GW_PARAM_FARRAY, .offset = offsetof(T, f), .unit = "", .rows = r, .help = hl}

#define S gw_chain_softwall_outcome
static const gw_param sw_fields[] = {
    RIT(S, "nw", nw, "walls (1, or the sheets of Table 2)"),
    RIT(S, "nn", nn, "column sizes"),
    RIT(S, "nsheet", nsheet, "sheets compared with the paper (0, 1 or nw)"),
    RDT(S, "v_imp", v_imp, "m/s", "impact velocity"),
    RDT(S, "k_c", k_c, "N/m^1.5", "critical wall coefficient K_c (F.22)"),
    RDT(S, "t_q_rigid", t_q_rigid, "s", "T_q on a steel wall (slope of tau_N, N = 1..20)"),
    RDT(S, "tol", tol, "", "plateau tolerance"),
    RIT(S, "sheet_law", sheet_law, "0 fitted, 1 hertz, 2 layer, 3 material"),
    RAT(S, "n", n, "", "nn", NULL, "column sizes N"),
    RAT(S, "kwall", kwall, "N/m^1.5", "nw", NULL, "wall coefficient K [wall]"),
    RFA(S, "rigid", rigid, "nw", "1: K > K_c [wall]"),
    RFA(S, "saturated", saturated, "nw", "1: F_max reached its plateau within the sizes, 0: not, -1: undecided "
                                         "(held columns leave too few decided sizes on it) [wall]"),
    RAT(S, "f_max", f_max, "N", "nw", "nn", "largest wall force [wall, N]"),
    RAT(S, "tau_max", tau_max, "s", "nw", "nn", "time of f_max [wall, N]"),
    RAT(S, "t_max", t_max, "s", "nw", "nn", "time limit of each collision [wall, N]"),
    RAT(S, "dt_out", dt_out, "s", "nw", "nn", "its sampling interval [wall, N]"),
    RAT(S, "dt", dt, "s", "nw", "nn", "its RK4 step (0: cvode, arkode) [wall, N]"),
    RAT(S, "dt_max", dt_max, "s", "nw", "nn", "its largest step [wall, N]"),
    RAT(S, "n_d", n_d, "", "nw", NULL, "saturation number N_d (NaN: not reached) [wall]"),
    RAT(S, "n_d_predicted", n_d_predicted, "", "nw", NULL, "ceil(tau_max(N_d)/T_q) (F.8) [wall]"),
    RAT(S, "n_d_fixed_point", n_d_fixed_point, "", "nw", NULL, "smallest N >= ceil(tau_max(N)/T_q) [wall]"),
    RAT(S, "f_plateau", f_plateau, "N", "nw", NULL, "F_max of the longest column [wall]"),
    RAT(S, "tau_max_at_n_d", tau_max_at_n_d, "s", "nw", NULL, "tau_max at N_d [wall]"),
    RAT(S, "n_d_at_most", n_d_at_most, "", "nw", NULL,
        "the first size run, when F_max is on its plateau from there (N_d <= it, not located: n_d NaN) [wall]"),
    {.name = "sheet_table", .type = GW_PARAM_DARRAY, .offset = offsetof(S, sheet_table), .unit = "SI",
     .rows = "nsheet", .cols = "25", .choices = GW_SOFTWALL_SHEET_COLS,
     .help = "model against measured per sheet (s, N, m, N/m^1.5; NaN: not defined) [sheet, column]"},
    {.name = "sheet_names", .type = GW_PARAM_TEXT, .offset = offsetof(S, sheet_names), .unit = "",
     .help = "the compared sheets, comma-separated"},
    {.name = "sheet_materials", .type = GW_PARAM_TEXT, .offset = offsetof(S, sheet_materials), .unit = "",
     .help = "what their constants describe, separated by semicolons"},
    RDT(S, "wall_time_s", wall_time_s, "s", "wall-clock time"),
    RIT(S, "unfinished", unfinished, "collisions still at the wall at t_max (their F_max, tau_max may not be final)"),
    RIT(S, "n_held", n_held, "collisions held by gravity (counted in unfinished): undecided, left out of N_d and "
                             "F_plateau"),
    {.name = "held", .type = GW_PARAM_FARRAY, .offset = offsetof(S, held), .unit = "", .rows = "nw", .cols = "nn",
     .help = "1: the collision was held by gravity (the column fell back onto the wall before it ended): its F_max, "
             "tau_max undecided, left out of N_d [wall, N]"},
    RIT(S, "n_held_rigid", n_held_rigid, "of the rigid wall's 20 columns of t_q_rigid, those held by gravity "
                                         "(left out of its fit; NaN with fewer than two decided)"),
    RDT(S, "gamma", gamma, "N s/m^1.5", "Kuwabara-Kono constant run (calibrated with restitution; 0: none)"),
    RDT(S, "alpha", alpha, "s/m", "Hunt-Crossley constant run (calibrated with restitution; 0: none)"),
    GW_PARAM_WARNINGS(offsetof(S, warnings)),
    GW_PARAM_END};
#undef S

const gw_param *gw_chain_softwall_outcome_fields(void) { return sw_fields; }

void gw_chain_softwall_outcome_free(gw_chain_softwall_outcome *out)
{
    if (!out)
        return;
    free(out->n);
    free(out->rigid);
    free(out->sheet_table);
    free(out->sheet_names);
    free(out->sheet_materials);
    free(out->warnings);
    memset(out, 0, sizeof *out);
}

/* ---- soft wall ---- */

typedef struct sw_result {
    int n_d;      /* -1: not saturated within the sizes run, or not located (at_most) */
    int n_d_pred; /* (F.8) at the measured N_d, -1 without N_d */
    int n_d_fix;  /* smallest N >= ceil(tau_max(N)/T_q), -1 if none or if n_lo > 1 meets it */
    int at_most;  /* n_lo > 1 when the plateau reaches back to it: N_d <= n_lo, -1 otherwise */
    int undecided; /* 1: N_d not located because of held columns (the longest, or one that cut the
                      plateau's walk short), which more decided sizes might locate; 0: decided */
    double plateau;
} sw_result;

/* F_max(N) against its plateau, over the decided columns only: a column held
 * by gravity (stopped when it fell back onto the wall, its F_max that of that
 * time) counts as a size not run. The plateau is F_max of the longest decided
 * column; N_d the first size from which the decided F_max stay within tol of
 * it, counted when at least SATURATION_RUN decided sizes lie there (or the
 * plateau reaches back to N = 1). Where the plateau reaches back to a size
 * below which nothing decided was run (n_lo > 1, or a held column), N_d is at
 * most that size, not located. Without held columns, the rule and arithmetic
 * as before. */
static sw_result analyse(const gw_chain_result *r, int n_lo, int n_hi, double tol, double t_q)
{
    sw_result s = {-1, -1, -1, -1, 0, NAN};
    int top = n_hi;
    while (top >= n_lo && chain_result_held(&r[top - n_lo]))
        top--;
    if (top < n_lo) { /* every column held: no plateau */
        s.undecided = 1;
        return s;
    }
    s.plateau = r[top - n_lo].f_max;
    int low = top, on = 0, n = top;
    for (; n >= n_lo; n--) {
        if (chain_result_held(&r[n - n_lo]) || fabs(r[n - n_lo].f_max - s.plateau) > tol * s.plateau)
            break;
        low = n;
        on++;
    }
    /* A plateau that reaches back to n_lo = 1 is N_d = 1 (no column is shorter);
     * one that reaches back to n_lo > 1, or to a held column, began there or
     * before, among sizes not run or not decided: N_d <= that size is all they
     * tell (softwall --kwall 1e9 --n 10:30 said N_d = 10, and --n 1:30 finds 7) */
    const int unknown_below = (n < n_lo && n_lo > 1) || (n >= n_lo && chain_result_held(&r[n - n_lo]));
    if (low == 1)
        s.n_d = 1;
    else if (on < SATURATION_RUN) /* too few sizes on it: undecided when held columns are why (the
                                     longest held, or one ending the walk), else not saturated */
        s.undecided = top < n_hi || (n >= n_lo && chain_result_held(&r[n - n_lo]));
    else if (unknown_below)
        s.at_most = low;
    else
        s.n_d = low;
    if (!isfinite(t_q)) /* the rigid wall's T_q undecided (its columns held): no F.8 */
        return s;
    if (s.n_d > 0)
        s.n_d_pred = (int)ceil(r[s.n_d - n_lo].tau_max / t_q - 1e-9);
    int gap = 0; /* a held column below: the smallest N could be that one */
    for (int m = n_lo; m <= n_hi; m++) {
        if (chain_result_held(&r[m - n_lo])) {
            gap = 1;
            continue;
        }
        if (m >= (int)ceil(r[m - n_lo].tau_max / t_q - 1e-9)) {
            s.n_d_fix = !gap && (m > n_lo || n_lo == 1) ? m : -1; /* at n_lo > 1: smallest among those run only */
            break;
        }
    }
    return s;
}

int chain_plateau_first(const gw_chain_result *r, int n_lo, int n_hi, double tol)
{
    sw_result s = analyse(r, n_lo, n_hi, tol, NAN);
    return s.n_d > 0 ? s.n_d : s.at_most > 0 ? s.at_most : -1;
}

/* Rigid-wall T_q of the beads at v: slope of tau_N over N = 1..20, over the
 * columns not held by gravity (*held of the 20; NaN with fewer than two). */
static gw_chain_params rigid_params(const gw_chain_resolved *rs)
{
    gw_chain_params p = rs->params;
    const gw_material *steel = gw_material_find("steel");
    p.kwall = gw_hertz_coefficient(p.radius, steel, INFINITY, steel);
    memset(&p.wall, 0, sizeof p.wall); /* the bare sensor */
    return p;
}

static int measure_tq(const gw_chain_resolved *rs, double v, int jobs, double *t_q, int *held,
                      chain_dt_tally *dt_tally, chain_watch *watch, gw_err *err)
{
    gw_chain_params p = rigid_params(rs);
    gw_chain_result r[20];
    int rc = chain_sweep_watch(&p, &rs->run, &v, 1, 1, 20, jobs, NULL, NULL, watch, r, err);
    if (rc == GW_OK) /* the steel wall's contact is the stiffest: its dt-max the shortest */
        chain_dt_tally_results(dt_tally, r, 20);
    double x[20], y[20];
    int m = 0;
    *held = 0;
    for (int i = 0; i < 20; i++) {
        if (rc == GW_OK && chain_result_held(&r[i])) {
            (*held)++;
        } else {
            x[m] = i;
            y[m] = r[i].tau_n;
            m++;
        }
        gw_chain_result_free(&r[i]);
    }
    gw_linfit lf;
    if (rc == GW_OK && m >= 2 && gw_fit_linear(x, y, m, &lf) == GW_OK)
        *t_q = lf.c1;
    return rc;
}

/* One sheet's row of the sheet table: model against measured (times in s). */
static void sheet_row(const gw_sheet *sh, const sw_result *sr, const gw_chain_result *r, int n_lo, int n_hi,
                      double t_q, double kwall, const gw_layer_law *layer, double *row)
{
    /* N = 1 and the measured N_d: NaN where that column was held (undecided) */
    int nm = (int)sh->n_d, in = nm >= n_lo && nm <= n_hi && !chain_result_held(&r[nm - n_lo]), k = 0;
    const int one = n_lo == 1 && !chain_result_held(&r[0]);
    row[k++] = sh->thickness > 0 ? sh->thickness : NAN;
    row[k++] = sr->n_d > 0 ? sr->n_d : NAN;
    row[k++] = sh->n_d;
    row[k++] = sh->n_d_err;
    row[k++] = sr->n_d_pred > 0 ? sr->n_d_pred : NAN;
    row[k++] = one ? r[0].tau_max : NAN;
    row[k++] = sh->tau_max1_us * 1e-6;
    row[k++] = sr->n_d > 0 ? r[sr->n_d - n_lo].tau_max : NAN;
    row[k++] = sh->tau_max_nd_us * 1e-6;
    row[k++] = sh->tau_max_nd_err_us * 1e-6;
    /* tolerance-free comparisons at the measured N_d */
    row[k++] = in ? r[nm - n_lo].tau_max : NAN;
    row[k++] = in ? r[nm - n_lo].f_max / sr->plateau : NAN;
    static const double tols[] = {0.01, 0.02, 0.05, 0.1};
    for (int i = 0; i < 4; i++) {
        sw_result x = analyse(r, n_lo, n_hi, tols[i], t_q);
        row[k++] = x.n_d > 0 ? x.n_d : NAN;
        row[k++] = x.n_d > 0 ? r[x.n_d - n_lo].tau_max : NAN;
    }
    row[k++] = one ? r[0].f_max : NAN;
    row[k++] = sr->plateau;
    row[k++] = one ? r[0].eps_eff : NAN;
    row[k++] = kwall;
    /* contact radius over thickness at the single bead's peak force */
    row[k++] = layer && one ? gw_layer_law_contact_radius(layer, gw_layer_law_overlap(layer, r[0].f_max)) /
                                        gw_layer_law_thickness(layer)
                                  : NAN;
}

static int sw_alloc(gw_chain_softwall_outcome *o, int nw, int nn, int nsheet, gw_err *err)
{
    o->nw = nw;
    o->nn = nn;
    o->ncase = nw * nn;
    o->nsheet = nsheet;
    o->n = calloc((size_t)nn + (size_t)nw * (7 + 6 * (size_t)nn), sizeof *o->n);
    o->rigid = calloc(2 * (size_t)nw + (size_t)o->ncase, sizeof *o->rigid); /* rigid, saturated, held */
    o->sheet_table = calloc((size_t)nsheet * GW_SOFTWALL_NSHEET_COLS + 1, sizeof *o->sheet_table);
    o->sheet_names = calloc((size_t)nsheet * 16 + 1, 1);
    o->sheet_materials = calloc((size_t)nsheet * GW_SOFTWALL_LABEL_MAX + 1, 1);
    if (!o->n || !o->rigid || !o->sheet_table || !o->sheet_names || !o->sheet_materials)
        return gw_err_set(err, GW_ENOMEM, "softwall: out of memory");
    o->saturated = o->rigid + nw;
    o->held = o->rigid + 2 * (size_t)nw;
    double *b = o->n + nn;
    double **per_w[] = {&o->kwall, &o->n_d, &o->n_d_predicted, &o->n_d_fixed_point, &o->f_plateau,
                        &o->tau_max_at_n_d, &o->n_d_at_most};
    for (int i = 0; i < 7; i++, b += nw)
        *per_w[i] = b;
    double **per_case[] = {&o->f_max, &o->tau_max, &o->t_max, &o->dt_out, &o->dt, &o->dt_max};
    for (int i = 0; i < 6; i++, b += o->ncase)
        *per_case[i] = b;
    return GW_OK;
}

/* The walls' results into out (after every wall has run). */
static void sw_fill(const gw_chain_softwall_setup *s, const gw_chain_resolved *rs, const gw_chain_result *res,
                    const sw_result *sr, gw_layer_law *const *lay, gw_chain_softwall_outcome *o)
{
    int a = (int)s->n[0], b = (int)s->n[1], nn = o->nn;
    char name[32];
    for (int k = 0; k < nn; k++)
        o->n[k] = a + k;
    for (int w = 0; w < o->nw; w++) {
        const gw_chain_result *rw = res + (size_t)w * nn;
        for (int k = 0; k < nn; k++) {
            o->f_max[w * nn + k] = rw[k].f_max;
            o->tau_max[w * nn + k] = rw[k].tau_max;
            o->t_max[w * nn + k] = rw[k].run_t_max;
            o->dt_out[w * nn + k] = rw[k].run_dt_out;
            o->dt[w * nn + k] = rw[k].run_dt;
            o->dt_max[w * nn + k] = rw[k].run_dt_max;
            o->held[w * nn + k] = chain_result_held(&rw[k]);
        }
        o->rigid[w] = o->kwall[w] > o->k_c;
        /* -1 (JSON null, Python masked): held columns leave it undecided */
        o->saturated[w] = sr[w].n_d > 0 || sr[w].at_most > 0 ? 1 : sr[w].undecided ? -1 : 0;
        o->n_d_at_most[w] = sr[w].at_most > 0 ? sr[w].at_most : NAN;
        o->n_d[w] = sr[w].n_d > 0 ? sr[w].n_d : NAN;
        o->n_d_predicted[w] = sr[w].n_d_pred > 0 ? sr[w].n_d_pred : NAN;
        o->n_d_fixed_point[w] = sr[w].n_d_fix > 0 ? sr[w].n_d_fix : NAN;
        o->f_plateau[w] = sr[w].plateau;
        o->tau_max_at_n_d[w] = sr[w].n_d > 0 ? rw[sr[w].n_d - a].tau_max : NAN;
    }
    /* sheet none under a law other than fitted is the Hertz half-space of the
     * sensor's material: one label for the run, whichever wall it is */
    char wall[32], bare[GW_SOFTWALL_LABEL_MAX];
    if (gw_param_format(gw_param_find(sw_params, "wall-material"), s, wall, sizeof wall) <= 0)
        gw_snprintf(wall, sizeof wall, "steel");
    gw_snprintf(bare, sizeof bare, "no sheet (%s sensor)", wall);
    for (int w = 0; w < o->nsheet; w++) {
        const gw_sheet *sh = s->sheets ? gw_sheet_get(w)
                                       : (gw_param_format(gw_param_find(sw_params, "sheet"), s, name, sizeof name) > 0
                                              ? gw_sheet_find(name)
                                              : NULL);
        if (!sh)
            continue;
        sheet_row(sh, &sr[w], res + (size_t)w * nn, a, b, o->t_q_rigid, o->kwall[w], s->sheets ? lay[w] : rs->layer,
                  o->sheet_table + (size_t)w * GW_SOFTWALL_NSHEET_COLS);
        size_t ln = strlen(o->sheet_names), lm = strlen(o->sheet_materials);
        gw_snprintf(o->sheet_names + ln, 16, "%s%s", w ? "," : "", sh->name);
        gw_snprintf(o->sheet_materials + lm, GW_SOFTWALL_LABEL_MAX, "%s%s", w ? ";" : "",
                    !(sh->thickness > 0) && rs->law != GW_SHEET_FITTED ? bare : sh->material);
    }
}

/* The held columns' warning: those of the walls, and the rigid wall's of T_q
 * (counted apart: the study's total is its walls' columns; the rigid wall's
 * alone when no wall column was held). */
static int sw_held_warnings(const gw_chain_softwall_outcome *o, int held, const char *where, char **list)
{
    char left[160];
    if (held == 0)
        return chain_held_warnings(o->n_held_rigid, 20, "the rigid wall's T_q and F.8's predictions", where, list);
    if (o->n_held_rigid)
        gw_snprintf(left, sizeof left, "N_d, F_plateau and the rigid wall's T_q (%d of whose 20 columns were held "
                    "too)", o->n_held_rigid);
    else
        gw_snprintf(left, sizeof left, "N_d and F_plateau");
    return chain_held_warnings(held, o->ncase, left, where, list);
}

/* What the held columns leave undecided, for their warning: N_d and saturated
 * at the walls where held columns keep the decided ones from locating it, and T_q when
 * fewer than two of the rigid wall's 20 columns were decided ("" when nothing). */
static int sw_held_where(const gw_chain_softwall_outcome *o, int sheets, char *buf, size_t size)
{
    char walls[200] = "";
    int nu = 0;
    for (int w = 0; w < o->nw; w++) {
        if (o->saturated[w] < 0 && sheets) {
            size_t len = strlen(walls);
            if (len + 20 < sizeof walls)
                gw_snprintf(walls + len, sizeof walls - len, "%s%s", nu ? ", " : "", gw_sheet_get(w)->name);
            nu++;
        } else if (o->saturated[w] < 0) {
            nu++;
        }
    }
    gw_snprintf(buf, size, "%s%s%s%s%s", nu ? "N_d" : "", nu && sheets ? " (sheets " : "", walls,
                nu && sheets ? ")" : "", nu ? " and whether F_max saturated (saturated null: too few decided sizes on the plateau)" : "");
    if (!isfinite(o->t_q_rigid) && o->n_held_rigid > 0) {
        size_t len = strlen(buf);
        gw_snprintf(buf + len, size - len, "%sthe rigid wall's T_q and F.8 (%d of its 20 columns held)",
                    nu ? ", " : "", o->n_held_rigid);
    }
    return GW_OK;
}

int gw_chain_softwall_sheet_material(const gw_chain_softwall_outcome *o, int w, char *buf, size_t size)
{
    if (!buf || size == 0)
        return GW_EINVAL;
    buf[0] = '\0';
    if (!o || !o->sheet_materials || w < 0 || w >= o->nsheet)
        return GW_EINVAL;
    const char *m = o->sheet_materials;
    for (int i = 0; i < w; i++) {
        m = strchr(m, ';');
        if (!m)
            return GW_EINVAL; /* fewer labels than sheets: a sheet left out */
        m++;
    }
    size_t len = strcspn(m, ";");
    if (len >= size)
        return GW_EINVAL;
    memcpy(buf, m, len);
    buf[len] = '\0';
    return GW_OK;
}

static int sw_run(const gw_chain_softwall_setup *s, gw_progress_fn progress, void *pctx, chain_watch *watch,
                  gw_chain_softwall_outcome *out, gw_err *err);

int gw_chain_softwall_run(const gw_chain_softwall_setup *s, gw_progress_fn progress, void *pctx,
                          gw_chain_softwall_outcome *out, gw_err *err)
{
    return gw_chain_softwall_run_watch(s, progress, pctx, NULL, NULL, out, err);
}

int gw_chain_softwall_run_watch(const gw_chain_softwall_setup *s, gw_progress_fn progress, void *pctx,
                                gw_chain_watch_fn watch, void *wctx, gw_chain_softwall_outcome *out,
                                gw_err *err)
{
    chain_watch w;
    chain_watch_init(&w, watch, wctx);
    int rc = sw_run(s, progress, pctx, &w, out, err);
    chain_watch_destroy(&w);
    return rc;
}

static int sw_run(const gw_chain_softwall_setup *s, gw_progress_fn progress, void *pctx, chain_watch *watch,
                  gw_chain_softwall_outcome *out, gw_err *err)
{
    if (out) /* emptied on every refusal, a NULL setup's too (docs/library.md) */
        memset(out, 0, sizeof *out);
    if (!s || !out)
        return gw_err_set(err, GW_EINVAL, "gw_chain_softwall_run: %s is NULL", !s ? "setup" : "out");
    int rc = chain_study_range_check(sw_params, s, &s->col, s->sheets ? gw_sheet_count() : 1, err);
    if (rc != GW_OK)
        return rc;
    if (s->sheets && (!isnan(s->col.kwall) || s->col.sheet >= 0))
        return gw_err_set(err, GW_EINVAL, "%s: has no effect with sheets (each sheet of Table 2 is its own wall)",
                          s->col.sheet >= 0 ? "sheet" : "kwall");
    /* the wall material, given at steel too (an optional row), where the wall
     * is a stiffness (kwall, 1e9 by default) or each sheet of Table 2 with its
     * fitted K_eff; under the laws hertz, layer and material the sheet none
     * among them is the Hertz half-space of the sensor's material
     * (gw_sheet_apply), which the wall material sets */
    const int fitted = s->col.sheet_law < 0 || s->col.sheet_law == GW_SHEET_FITTED;
    if (gw_param_given(gw_param_find(sw_params, "wall-material"), s) &&
        ((s->sheets && fitted) || (!s->sheets && s->col.sheet < 0)))
        return gw_err_set(err, GW_EINVAL, "wall-material: has no effect %s",
                          s->sheets ? "with sheets under sheet-law fitted (each sheet of Table 2 is its own wall, "
                                      "sheet none too: its fitted K_eff)"
                                    : "(the wall is kwall, default 1e9 N/m^1.5, or sheets)");
    long a = s->n[0], b = s->n[1];
    if (b - a < 2)
        return gw_err_set(err, GW_EINVAL, "n: need at least 3 column sizes");
    double vimp = isnan(s->vimp) ? sqrt(2 * GW_CHAIN_G_EARTH * 2.9e-3) : s->vimp;
    gw_chain_setup col = s->col; /* shallow: no radii */
    col.n = a;
    col.vimp = vimp;
    col.sheets = s->sheets;
    if (isnan(col.kwall) && !s->sheets && col.sheet < 0)
        col.kwall = 1e9; /* the soft wall of the command */
    int nw = s->sheets ? gw_sheet_count() : 1, per = (int)(b - a + 1);
    int held = 0; /* of the unfinished: stopped as held by gravity (chain_held_pending) */
    gw_chain_resolved rs;
    rc = gw_chain_setup_resolve(&col, &rs, err);
    if (rc != GW_OK) {
        gw_chain_resolved_free(&rs);
        return rc;
    }
    if ((rc = sw_alloc(out, nw, per, s->sheets ? nw : s->col.sheet >= 0, err)) != GW_OK) {
        gw_chain_resolved_free(&rs);
        return rc;
    }
    out->v_imp = vimp;
    out->tol = s->tol;
    out->sheet_law = (int)rs.law;
    out->k_c = gw_chain_kc(rs.params.k);
    out->gamma = rs.params.gamma; /* as the JSON's settings.model */
    out->alpha = rs.params.alpha;
    out->t_q_rigid = NAN;
    gw_chain_result *res = calloc((size_t)nw * (size_t)per, sizeof *res);
    sw_result *sr = calloc((size_t)nw, sizeof *sr);
    gw_layer_law **lay = calloc((size_t)nw, sizeof *lay);
    gw_chain_params *wall = calloc((size_t)nw, sizeof *wall); /* each wall's column */
    double t0 = gw_clock_ms();
    int small = 0; /* cases whose contact damping is predicted below rtol, the largest effect among them */
    double small_hi = 0;
    /* a --dt above the step taken: the rigid wall's 20 columns and the walls'; the chatter's reruns by the solver */
    chain_dt_tally dt_tally = {.solver = rs.run.solver ? rs.run.solver : gw_solver_cvode,
                               .rtol = rs.run.sp.rtol,
                               .atol = rs.run.sp.atol};
    chain_drag_tally drag = {0};   /* the sensor's dashpot and the guide's friction over the walls' columns */
    rc = res && sr && lay && wall ? GW_OK : gw_err_set(err, GW_ENOMEM, "softwall: out of memory");
    char name[32];
    const gw_material *bm = gw_material_find(
        gw_param_format(gw_param_find(sw_params, "material"), s, name, sizeof name) > 0 ? name : "steel");
    const gw_material *wm = gw_material_find(
        gw_param_format(gw_param_find(sw_params, "wall-material"), s, name, sizeof name) > 0 ? name : "steel");
    /* every wall before any run: the study's whole work is planned first (the
     * rigid wall's 20 columns, then each wall's), and a sheet refused is so
     * before minutes of the walls before it */
    for (int w = 0; rc == GW_OK && w < nw; w++) {
        wall[w] = rs.params;
        if (s->sheets)
            rc = gw_sheet_apply(gw_sheet_get(w), rs.law, -1, -1, bm, wm, &wall[w], &lay[w], err);
        if (rc == GW_OK) /* each wall's one-bead column, as the single run's (chain_damping_check) */
            rc = chain_damping_study_check(&wall[w], a, s->sheets ? gw_sheet_get(w)->name : NULL, err);
    }
    if (rc == GW_OK) {
        gw_chain_params rigid = rigid_params(&rs);
        chain_watch_plan_sweep(watch, &rigid, &rs.run, &vimp, 1, 1, 20, (int)s->jobs);
        for (int w = 0; w < nw; w++)
            chain_watch_plan_sweep(watch, &wall[w], &rs.run, &vimp, 1, (int)a, (int)b, (int)s->jobs);
        rc = measure_tq(&rs, vimp, (int)s->jobs, &out->t_q_rigid, &out->n_held_rigid, &dt_tally, watch, err);
    }
    for (int w = 0; rc == GW_OK && w < nw; w++) {
        const gw_chain_params q = wall[w];
        out->kwall[w] = q.kwall;
        rc = chain_sweep_watch(&q, &rs.run, &vimp, 1, (int)a, (int)b, (int)s->jobs, NULL, NULL, watch,
                               res + (size_t)w * per, err);
        if (rc == GW_OK) {
            sr[w] = analyse(res + (size_t)w * per, (int)a, (int)b, s->tol, out->t_q_rigid);
            chain_dt_tally_results(&dt_tally, res + (size_t)w * per, per);
        }
        for (int i = 0; rc == GW_OK && i < per; i++) {
            gw_chain_params qi = q; /* the case's damping at its wall's stiffness and its size (the single run's
                                       test: softwall --damping kk --gamma 1e-8 said nothing of it) */
            qi.n = (int)a + i;
            chain_drag_tally_add(&drag, &qi);
            if (chain_damping_small(&qi, rs.run.sp.rtol)) {
                const double e = chain_damping_effect(&qi);
                small_hi = small++ ? fmax(small_hi, e) : e;
            }
            out->unfinished += !res[(size_t)w * per + i].wall_done; /* F_max, tau_max: the wall's */
            held += chain_result_held(&res[(size_t)w * per + i]);
        }
        if (rc == GW_OK && progress && progress(pctx, w + 1, nw))
            rc = gw_err_set(err, GW_ECANCELED, "softwall: stopped by the progress callback");
    }
    out->wall_time_s = (gw_clock_ms() - t0) / 1e3;
    out->n_held = held;
    if (rc == GW_OK)
        sw_fill(s, &rs, res, sr, lay, out);
    char where[300] = "";
    if (rc == GW_OK)
        rc = sw_held_where(out, s->sheets, where, sizeof where);
    if (rc == GW_OK &&
        ((rc = gw_chain_softwall_warnings(out->unfinished - held, out->ncase, &out->warnings)) != GW_OK ||
         (rc = sw_held_warnings(out, held, where, &out->warnings)) != GW_OK ||
         (rc = chain_dt_tally_warnings(&dt_tally, "--dt", "collisions", &out->warnings)) != GW_OK ||
         (rc = chain_damping_zero_warnings(&rs.params, 0, 1, &out->warnings)) != GW_OK ||
         (rc = chain_damping_small_cases_warning(small, nw * per, small_hi, &out->warnings)) != GW_OK ||
         (rc = chain_drag_tally_warnings(&drag, rs.run.sp.rtol, &out->warnings)) != GW_OK))
        rc = gw_err_set(err, rc, "softwall: out of memory");
    for (int i = 0; res && i < nw * per; i++)
        gw_chain_result_free(&res[i]);
    free(res);
    free(sr);
    for (int w = 0; lay && w < nw; w++)
        gw_layer_law_free(lay[w]);
    free(lay);
    free(wall);
    gw_chain_resolved_free(&rs);
    return rc;
}
