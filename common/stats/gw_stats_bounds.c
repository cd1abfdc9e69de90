/*
 * gw_stats_bounds.c: what the numbers of one row of a layer sweep table can
 * be, by the definitions of docs/physics.md 2.3 and the energy ledger of 2.4.
 * A row is the outcome of one impact: V_ni = V_i cos(alpha_i) (B.5), and at T_i
 *     e_n = V_nr / V_ni,  e = V_r / V_i,  alpha_r = arccos(V_nr / V_r)   (B.16-B.18)
 * with the bounce criterion (the normal velocity turned upward: V_nr > 0) and
 * V_nr <= V_r (a component of the velocity is no larger than its norm). The
 * reader (gw_stats_table_*.c) checks what a cell is (a number, 0 or 1, never
 * negative where the definition says so); here the rows are checked against
 * one another's columns and the run's settings (alpha_i, V_i, g), which the
 * reader does not know (the caller's defaults).
 *
 * Per column, refused (GW_EFORMAT "path:line: column C: ...": no run writes
 * it, so the row was edited or pasted) or warned of (a run writes it in an
 * unusual case only):
 *   alpha_r, alpha_r_first: refused above 180 deg (arccos' range) in any row,
 *     above 90 deg in a bouncing row (V_nr > 0). The measured 8000-case
 *     diagram reaches 89.994 deg.
 *   e_n, e_n_first: refused where e_n cos(alpha_i) > e (V_nr > V_r), to 1e-9
 *     relative (both are written with 17 digits from one V_nr, V_r: rounding
 *     is 1e-15). e_n above 1 alone is neither refused nor warned of: at
 *     oblique incidence the grains turn tangential momentum into normal (e_n
 *     up to e / cos(alpha_i); Beladjine et al. 2007 measured e_n > 1 at
 *     grazing incidence), and at normal incidence e_n > 1 means e > 1, below.
 *   v_nr, v_nr_first: refused above v_r, v_r_first (the same inequality).
 *   e, e_first: warned of above sqrt(1 + 2 g p / V_i^2 + 2.001e-3): the block
 *     leaves with more kinetic energy than it brought, the work of gravity
 *     over its penetration p and the fall over the gap (at most 0.1 % of the
 *     normal speed, gw_layer_impact_fall_check) included. Only energy the
 *     layer held before the impact can give that, and a sample that rests
 *     (gw_layer_impact_rest_check) holds little, but not none: a warning. The
 *     measured diagram's largest e is 1.0000123, far below (2.5e-5 of the
 *     2.001e-3).
 *   block_loss_first_contact: refused above 1 (to 1e-9): the block's kinetic
 *     energy at the start less its smallest in the first contact, over the
 *     incident one (the start's: omega_i = 0): it cannot lose more than it
 *     had. It may be below 0: the block gains energy falling the gap, and a
 *     grazing first contact may slow it less than that (a run of the
 *     restitution notebook wrote -5.1e-6).
 *   a row that did not bounce (bounced 0, or nan: undecided): in a table of
 *     the format with e_n_first, e_n, e, alpha_r and their _first are nan, as
 *     the model writes them; a number there is refused (a bounced cell
 *     edited from 1 to 0, whose point left the means silently). Tables before
 *     e_n_first carry them in such rows (the measured diagram has 1782): they
 *     are read, and the statistics never use them (gw_stats_groups_make takes
 *     them from bouncing rows only).
 * Units: speeds m/s, angles deg, g m/s^2, penetration m.
 */
#include <math.h>
#include <string.h>

#include "gw_stats.h"
#include "gw_locale.h"
#include "gw_stats_impl.h"

/* the layer's default gravity (gw_layer_params, docs/physics.md 2.1): a table
 * records gravity only when the sweep set it */
#define GRAVITY_DEFAULT 9.81
/* e^2 the fall over the gap may add: (1 + 0.001)^2 - 1, the normal speed's
 * largest change gw_layer_impact_fall_check lets through */
#define FALL_E2 2.001e-3
#define REL 1e-9

static double at(const gw_stats_table *t, long r, int c)
{
    return c >= 0 ? t->val[r * t->ncols + c] : NAN;
}

static int refuse(const gw_stats_table *t, long r, const char *col, const char *what, gw_err *err)
{
    return gw_err_set(err, GW_EFORMAT, "%s:%ld: column %s: %s (case %ld; a row no run writes: edited by hand?)",
                      t->path, t->row_line[r], col, what, t->case_id[r]);
}

/* The columns defined at a rebound only: nan in a row that did not bounce. */
static const char *const at_rebound[] = {"e_n",        "e",        "alpha_r",         "v_nr",
                                         "v_r",        "e_n_first", "e_first",        "alpha_r_first",
                                         "v_nr_first", "v_r_first", "t_leave",        "t_rebound",
                                         "t_f"};
#define NREBOUND ((int)(sizeof at_rebound / sizeof at_rebound[0]))

/* In a row that did not bounce, the six that say a point bounced (e_n, e,
 * alpha_r and their _first): a number there is a bounced cell edited, whose
 * point left the means. The speeds and times (v_nr, v_r, t_leave, ...) are
 * nan there too as the model writes them, but no statistic reads them, and
 * tables made by hand fill them in every row (tests/python's made-up one). */
#define NSAY 8 /* at_rebound[0..2] and [5..7] */
static int check_not_bounced(const gw_stats_table *t, long r, double b, const int *c, gw_err *err)
{
    char what[256];
    for (int j = 0; j < NSAY; j++) {
        if (j == 3 || j == 4)
            continue;
        const double v = at(t, r, c[j]);
        if (c[j] >= 0 && !isnan(v)) {
            gw_snprintf(what, sizeof what, "%.17g in a row that did not bounce (bounced %s): it is defined at a "
                        "rebound only, and a sweep writes nan there", v, isnan(b) ? "nan" : "0");
            return refuse(t, r, at_rebound[j], what, err);
        }
    }
    return GW_OK;
}

static int check_bounced(const gw_stats_table *t, long r, const int *c, double alpha_i, gw_err *err)
{
    char what[384];
    for (int j = 0; j < 2; j++) { /* alpha_r, alpha_r_first: arccos(V_nr / V_r) with V_nr > 0 */
        const int k = j ? 7 : 2;
        const double a = at(t, r, c[k]);
        if (a > 90) {
            gw_snprintf(what, sizeof what, "%.17g deg in a bouncing row: arccos(V_nr/V_r) is below 90 deg when the "
                        "normal velocity turned upward (V_nr > 0)", a);
            return refuse(t, r, at_rebound[k], what, err);
        }
    }
    /* e_n, e, alpha_r (and their _first) are taken together at one instant:
     * all numbers, or all nan (the run ended before T_f). alpha_r is nan
     * alone only where V_r = 0, which a bounce (V_nr > 0) excludes. A nan
     * among numbers left the point out of one mean and in the others. */
    for (int j = 0; j < 2; j++) {
        const int k0 = j ? 5 : 0;
        int knan = -1, knum = -1;
        for (int k = k0; k < k0 + 3; k++)
            if (c[k] >= 0 && isnan(at(t, r, c[k])) && knan < 0)
                knan = k;
            else if (c[k] >= 0 && !isnan(at(t, r, c[k])) && knum < 0)
                knum = k;
        if (knan >= 0 && knum >= 0) {
            gw_snprintf(what, sizeof what, "nan where %s is %.9g in a bouncing row: e_n, e and alpha_r are taken "
                        "together at T_i (all numbers, or all nan when the run ended before it)", at_rebound[knum],
                        at(t, r, c[knum]));
            return refuse(t, r, at_rebound[knan], what, err);
        }
    }
    /* e_n cos(alpha_i) <= e and v_nr <= v_r: V_nr <= V_r */
    const double ca = isfinite(alpha_i) ? cos(alpha_i * M_PI / 180) : NAN;
    for (int j = 0; j < 2; j++) {
        const int ken = j ? 5 : 0, ke = j ? 6 : 1, kvn = j ? 8 : 3, kv = j ? 9 : 4;
        const double en = at(t, r, c[ken]), e = at(t, r, c[ke]), vn = at(t, r, c[kvn]), v = at(t, r, c[kv]);
        if (isfinite(en) && isfinite(e) && isfinite(ca) && en * ca > e * (1 + REL)) {
            gw_snprintf(what, sizeof what, "%.17g exceeds %s / cos(alpha_i) = %.9g (%s %.9g, alpha_i %.9g deg): "
                        "the normal rebound speed e_n V_i cos(alpha_i) would exceed the rebound speed e V_i",
                        en, at_rebound[ke], e / ca, at_rebound[ke], e, alpha_i);
            return refuse(t, r, at_rebound[ken], what, err);
        }
        if (isfinite(vn) && isfinite(v) && vn > v * (1 + REL)) {
            gw_snprintf(what, sizeof what, "%.17g m/s exceeds %s = %.9g m/s: the normal component of the "
                        "rebound velocity would exceed its norm", vn, at_rebound[kv], v);
            return refuse(t, r, at_rebound[kvn], what, err);
        }
    }
    return GW_OK;
}

int gw_stats_table_bounds(const gw_stats_table *t, const gw_stats_defaults *df, char **warnings, gw_err *err)
{
    int c[NREBOUND];
    for (int j = 0; j < NREBOUND; j++)
        c[j] = gw_stats_table_col(t, at_rebound[j]);
    const int cb = gw_stats_table_col(t, "bounced"), cl = gw_stats_table_col(t, "block_loss_first_contact"),
              cp = gw_stats_table_col(t, "penetration");
    /* the format whose model writes nan at rebound-only columns of a row
     * that did not bounce (the reader refuses a table with part of them) */
    const int current = c[5] >= 0;
    long nfast = 0, first = -1;
    double first_e = NAN, first_bound = NAN;
    const char *first_col = "e";
    char what[256];
    for (long r = 0; r < t->nrows; r++) {
        const double b = at(t, r, cb), loss = at(t, r, cl);
        for (int j = 0; j < 2; j++) {
            const int k = j ? 7 : 2;
            const double a = at(t, r, c[k]);
            if (a > 180) {
                gw_snprintf(what, sizeof what, "%.17g deg is outside arccos' range [0, 180] deg", a);
                return refuse(t, r, at_rebound[k], what, err);
            }
        }
        if (loss > 1 + REL) {
            gw_snprintf(what, sizeof what, "%.17g is above 1: the block cannot lose more kinetic energy than it "
                        "brought", loss);
            return refuse(t, r, "block_loss_first_contact", what, err);
        }
        int rc = GW_OK;
        if (b != 1) {
            if (current && (rc = check_not_bounced(t, r, b, c, err)) != GW_OK)
                return rc;
            continue;
        }
        const double alpha_i = gw_stats_table_value(t, r, "alpha", df ? df->alpha : NAN);
        if ((rc = check_bounced(t, r, c, alpha_i, err)) != GW_OK)
            return rc;
        /* the energy bound (a warning): e^2 <= 1 + 2 g p / V_i^2 + FALL_E2 */
        const double vi = gw_stats_table_value(t, r, "vi", df ? df->vi : NAN),
                     g = gw_stats_table_value(t, r, "gravity", GRAVITY_DEFAULT), p = at(t, r, cp);
        const double bound = sqrt(1 + 2 * g * p / (vi * vi) + FALL_E2);
        const double e = at(t, r, c[1]), ef = at(t, r, c[6]);
        const int ke = e > bound * (1 + REL) ? 1 : ef > bound * (1 + REL) ? 6 : -1;
        if (isfinite(bound) && vi > 0 && g >= 0 && ke > 0 && nfast++ == 0) {
            first = r;
            first_col = at_rebound[ke];
            first_e = ke == 1 ? e : ef;
            first_bound = bound;
        }
    }
    if (nfast > 0 && warnings)
        return gw_warnings_add(warnings,
                               "%ld bouncing point(s) left with more kinetic energy than they brought plus the work "
                               "of gravity over their penetration (first: %s:%ld, case %ld, %s = %.6g > sqrt(1 + 2 g "
                               "p / V_i^2 + 2.001e-3) = %.6g): only energy the layer held before the impact can give "
                               "that; check those rows",
                               nfast, t->path, t->row_line[first], t->case_id[first], first_col, first_e, first_bound);
    return GW_OK;
}
