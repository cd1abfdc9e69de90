/*
 * chain_setup.c: the inputs of one column collision described once
 * (gw_chain_study.h): the table of gw_chain_setup, and its resolution into the
 * model. Coefficients come from the materials unless given directly:
 *   bead-bead k = (sqrt(2R)/3) E/(1 - nu^2) for equal beads (F.12),
 *   bead-wall K = (4 sqrt(R)/3) [(1-nu_s^2)/E_s + (1-nu_p^2)/E_p]^(-1) (F.3),
 *   mass m = (4/3) pi R^3 rho,
 * a sheet of Table 2 gives K_eff from its measured tau_max(N = 1) (F.2, F.21),
 * and damping constants can be calibrated to a one-bead restitution (physics.md
 * 1.5). Under a sheet law other than fitted the sheet is a wall law from its
 * material constants and thickness (chain_sheets.c: Hertz F.3, bonded layer,
 * Maxwell loss, Thornton plastic p_y = 2.8 Y), the calibration then runs on the
 * bare sensor; the sensor can be a body (mass, N/m spring, N s/m dashpot) and the
 * beads can rub on their guide (Coulomb N, viscous N s/m).
 * SI units: m, kg, s, N, Pa, N/m^1.5.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_setup_rows.h"
#include "gw_locale.h"
#include "chain_wall.h"
#include "gw_chain_study.h"

#define OFF(f) offsetof(gw_chain_setup, f)


static const gw_param setup_params[] = {
    /* the parser's range is the memory's (gw_chain_params_validate); the
     * column's work holds a whole collision to N = 1414
     * (chain_column_work_check), which the help printed nowhere (chain's
     * --n: app/chain/chain_cmd.c, CHAIN_N_HELP) */
    ROW("n", GW_PARAM_LONG, n, "", 1, 50000000, 0, "1", "N",
        "number of beads, in [1, 50000000] as parsed, and at most 1414 over a whole collision: the column's work, "
        "N^2 times the share of the collision the run covers, is held to 2e6 (a short t-max runs more beads) [1]"),
    ROW("vimp", GW_PARAM_DOUBLE, vimp, "m/s", GW_CHAIN_VIMP_MIN, GW_CHAIN_VIMP_MAX, 0, "0.3", "V", "impact velocity, m/s [0.3]"),
    GW_CHAIN_MODEL_ROWS
    ROW("trace", GW_PARAM_FLAG, trace, "", 0, 1, 0, "0", NULL,
        "library: keep the wall force and the bead series (t, f_wall, x, v) [0]"),
    GW_PARAM_END};

const gw_param *gw_chain_setup_params(void)
{
    return setup_params;
}

int gw_chain_setup_init(gw_chain_setup *s)
{
    if (!s)
        return GW_EINVAL;
    memset(s, 0, sizeof *s);
    return gw_param_init(setup_params, s, NULL);
}

void gw_chain_setup_clear(gw_chain_setup *s)
{
    gw_param_clear(setup_params, s);
}

int chain_study_setup_init(void *s, size_t size, gw_chain_setup *col, const gw_param *t)
{
    if (!s)
        return GW_EINVAL;
    memset(s, 0, size);
    int rc = gw_chain_setup_init(col);
    return rc == GW_OK ? gw_param_init(t, s, NULL) : rc;
}

void chain_study_setup_clear(void *s, gw_chain_setup *col, const gw_param *t)
{
    if (!s)
        return;
    gw_param_clear(t, s);
    gw_chain_setup_clear(col);
}

int chain_study_range_check(const gw_param *t, const void *s, const gw_chain_setup *col, int runs, gw_err *err)
{
    int rc = gw_param_check(t, s, err);
    if (rc == GW_OK && col->radii.n > 0)
        rc = gw_err_set(err, GW_EINVAL, "radii: per-bead radii need a fixed N (use the chain study)");
    const gw_param *row = gw_param_find(t, "n");
    if (rc != GW_OK || !row || row->type != GW_PARAM_RANGE)
        return rc;
    const long *n = (const long *)((const char *)s + row->offset);
    return gw_chain_study_work_check(n[0], n[1], runs, err);
}

int gw_chain_study_work_check(long a, long b, int runs, gw_err *err)
{
    if (runs < 1)
        runs = 1;
    if (a < 1 || b < a) /* 5:1 passed with a negative work */
        return gw_err_set(err, GW_EINVAL, "n: %ld:%ld is not a range of column sizes (1 <= A <= B)", a, b);
    /* sum of N^2 for N = a..b as m a^2 + a m (m - 1) + (m - 1) m (2m - 1) / 6
     * with m = b - a + 1: terms >= 0, so no cancellation (S(b) - S(a - 1) gave 0
     * at a = b = 9.2e18 and let the range pass); exact to 1e-16 where b <= 1e5 */
    const double m = (double)b - (double)a + 1, x = (double)a;
    double work = runs * (m * x * x + x * m * (m - 1) + (m - 1) * m * (2 * m - 1) / 6);
    if (work > GW_CHAIN_STUDY_WORK_MAX) {
        /* in 3 digits, or as many as tell it from the bound: 1415:1415 was
         * "2e+06 bead^2 of work ..., above the bound 2e+06" */
        char w[32];
        gw_snprintf(w, sizeof w, "%.3g", work);
        if (!(gw_strtod(w, NULL) > GW_CHAIN_STUDY_WORK_MAX))
            gw_num_text(w, sizeof w, work);
        return gw_err_set(err, GW_EINVAL,
                          "n: %ld:%ld at %d column%s per N is %s bead^2 of work (sum of N^2), above the "
                          "bound %.0e (a column's work grows as N^2; the largest documented study is 2e5)",
                          a, b, runs, runs > 1 ? "s" : "", w, GW_CHAIN_STUDY_WORK_MAX);
    }
    return GW_OK;
}

typedef struct {
    double v;
    int i;
} speed_at;

static int speed_cmp(const void *a, const void *b)
{
    const speed_at *x = a, *y = b;
    return x->v < y->v ? -1 : x->v > y->v ? 1 : (x->i > y->i) - (x->i < y->i);
}

int gw_chain_study_speeds_check(const double *v, int n, int n_speeds, gw_err *err)
{
    /* Sorted by speed then index, each pair of neighbours closer than
     * GW_CHAIN_SPEEDS_REL_MIN is a pair of speeds too close; named by the
     * first item that has such an earlier or nearer one (j), with the first
     * of those (i). Every pair compared (n^2 / 2) took 220 s before the first
     * collision of falcon --n 1:2 with 320000 speeds (the study's work bound
     * takes 4e5). */
    if (n >= 2 && !v) /* it was read (SIGSEGV) */
        return gw_err_set(err, GW_EINVAL, "gw_chain_study_speeds_check: v is NULL");
    if (n < 2)
        return GW_OK;
    speed_at *s = malloc((size_t)n * sizeof *s);
    if (!s)
        return gw_err_set(err, GW_ENOMEM, "vimp: out of memory for %d impact velocities", n);
    for (int k = 0; k < n; k++)
        s[k] = (speed_at){v[k], k};
    qsort(s, (size_t)n, sizeof *s, speed_cmp);
    int i = -1, j = n;
    for (int k = 1; k < n; k++) {
        /* only finite speeds are near one another: an infinite one (a height
         * whose 2 g h overflowed) was within inf of every finite one, named as
         * "within a relative -nan"; the ranges refuse it */
        if (!isfinite(s[k].v) || !isfinite(s[k - 1].v) ||
            !(s[k].v - s[k - 1].v <= GW_CHAIN_SPEEDS_REL_MIN * s[k].v))
            continue;
        const int lo = s[k - 1].i < s[k].i ? s[k - 1].i : s[k].i, hi = s[k - 1].i ^ s[k].i ^ lo;
        if (hi < j)
            i = lo, j = hi;
    }
    free(s);
    if (i < 0)
        return GW_OK;
    const char *what = j >= n_speeds ? "heights" : "vimp", *of = (i >= n_speeds) != (j >= n_speeds) ? " of vimp" : "";
    const int jj = j >= n_speeds ? j - n_speeds + 1 : j + 1, ii = i >= n_speeds ? i - n_speeds + 1 : i + 1;
    if (v[i] == v[j])
        return gw_err_set(err, GW_EINVAL, "%s: item %d gives the impact velocity %.10g m/s of item %d%s: the "
                          "same collisions would run twice and count twice in the fits", what, jj, v[j], ii, of);
    /* two speeds as good as one: the collisions resolve a wave speed to about
     * 1e-10 (default tolerances), and the fits over v_imp then rest on a
     * difference they cannot measure: 0.3 and 0.3 + 1 ulp gave beta -278424
     * and C3 0 with exit 0, a relative 3.3e-9 apart beta 0.179, 3.3e-7 apart
     * 0.1998 (0.2 from speeds far apart) */
    /* each speed in the fewest digits that read back as it (%.17g showed a
     * given 0.3 as 0.29999999999999999 beside 0.3000000001) */
    char vj[32], vi[32];
    return gw_err_set(err, GW_EINVAL, "%s: item %d gives the impact velocity %s m/s, within a relative %.2g of "
                      "item %d%s (%s m/s): the collisions cannot tell them apart (they resolve a wave speed to "
                      "about 1e-10), it would count twice in the fits and their exponent over v_imp rest on the "
                      "difference; give speeds at least a relative %g apart", what, jj, gw_num_text(vj, sizeof vj, v[j]),
                      fabs(v[j] - v[i]) / fmax(v[i], v[j]), ii, of, gw_num_text(vi, sizeof vi, v[i]),
                      GW_CHAIN_SPEEDS_REL_MIN);
}

void gw_chain_resolved_free(gw_chain_resolved *r)
{
    if (!r)
        return;
    free(r->masses);
    free(r->kc);
    gw_layer_law_free(r->layer);
    r->masses = r->kc = NULL;
    r->layer = NULL;
    r->params.masses = r->params.kc = NULL;
    r->params.wall.layer = NULL;
}

/* the name of a choice row's value: its default's when not given ("" when it
 * has none) */
static const char *choice(const gw_chain_setup *s, const char *row, char *buf, size_t n)
{
    const gw_param *p = gw_param_find(setup_params, row);
    if (gw_param_format(p, s, buf, n) <= 0)
        gw_snprintf(buf, n, "%s", p->def ? p->def : "");
    return buf;
}

/* Masses and coefficients from the materials, the sheet and the radii. */
static int resolve_model(const gw_chain_setup *s, gw_chain_resolved *r, gw_err *err)
{
    char name[32];
    gw_chain_params *p = &r->params;
    const gw_material *bm = gw_material_find(choice(s, "material", name, sizeof name));
    if (!bm || isinf(bm->density))
        return gw_err_set(err, GW_EINVAL, "material: unknown or unusable bead material '%s' (known: %s; not rigid)",
                          name, gw_material_names());
    const gw_material *wm = gw_material_find(choice(s, "wall-material", name, sizeof name));
    if (!wm)
        return gw_err_set(err, GW_EINVAL, "wall-material: unknown material '%s' (known: %s)", name,
                          gw_material_names());
    const gw_param *radius_row = gw_param_find(setup_params, "radius");
    const int radius_given = gw_param_given(radius_row, s);
    const double radius = radius_given ? s->radius : gw_strtod(radius_row->def, NULL);
    p->radius = radius;
    p->mass = isnan(s->mass) ? 4.0 / 3.0 * M_PI * pow(radius, 3) * bm->density : s->mass;
    p->k = isnan(s->k) ? gw_hertz_coefficient(radius, bm, radius, bm) : s->k;
    p->kwall = isnan(s->kwall) ? gw_hertz_coefficient(radius, bm, INFINITY, wm) : s->kwall;
    const int wall_material_given = gw_param_given(gw_param_find(setup_params, "wall-material"), s);
    if (!isnan(s->kwall) && wall_material_given)
        return gw_err_set(err, GW_EINVAL, "wall-material: has no effect with kwall (the wall's Hertz coefficient "
                          "is given)");
    /* the wall's material is the sensor's: a sheet lies on it and is the wall;
     * it enters only the bare sensor (sheet none) under a law other than fitted
     * (fitted is K_eff from the measured tau_max, F.2) and a restitution
     * calibrated on the bare sensor under such a law */
    const int fitted = s->sheet_law < 0 || s->sheet_law == GW_SHEET_FITTED;
    if (s->sheet >= 0 && wall_material_given) {
        const gw_sheet *sh = gw_sheet_find(choice(s, "sheet", name, sizeof name));
        if (sh && (fitted || (sh->thickness > 0 && isnan(s->restitution))))
            return gw_err_set(err, GW_EINVAL, "wall-material: has no effect with sheet %s under sheet-law %s (the "
                              "wall is the sheet; the sensor's material enters only sheet none under the laws hertz, "
                              "layer and material)", sh->name, gw_sheet_law_name(fitted ? GW_SHEET_FITTED
                                                                                          : (gw_sheet_law)s->sheet_law));
    }
    /* the bead material gives the mass, k and K (and the sheet laws' bead): with
     * all three given and no law that needs it, it would be ignored */
    const int wall_given = !isnan(s->kwall) || ((s->sheet >= 0 || s->sheets) && fitted);
    if (!isnan(s->mass) && !isnan(s->k) && wall_given && s->radii.n == 0 &&
        gw_param_given(gw_param_find(setup_params, "material"), s))
        return gw_err_set(err, GW_EINVAL, "material: has no effect with mass, k and the wall's coefficient given");
    if (s->radii.n > 0 && radius_given)
        return gw_err_set(err, GW_EINVAL, "radius: has no effect with radii (bead 1's radius is the first of radii)");
    if (s->sheet >= 0) {
        const gw_sheet *sh = gw_sheet_find(choice(s, "sheet", name, sizeof name));
        if (!sh)
            return gw_err_set(err, GW_EINVAL, "sheet: unknown sheet '%s' (%s)", name, SHEETS);
        if (!isnan(s->kwall))
            return gw_err_set(err, GW_EINVAL, "sheet: give either sheet or kwall");
        p->kwall = gw_sheet_kwall(sh, p->mass);
    }
    const int n = p->n;
    if (s->radii.n > 0) {
        if (s->radii.n != n)
            /* it was "2 radii for 1 beads": what was given, and the two ways out */
            return gw_err_set(err, GW_EINVAL, "radii: gives %d radi%s but n is %d%s: give n = %d, or %d radi%s",
                              s->radii.n, s->radii.n == 1 ? "us" : "i", n, n == 1 ? " (1 is the default)" : "",
                              s->radii.n, n, n == 1 ? "us" : "i");
        r->masses = malloc((size_t)n * sizeof *r->masses);
        r->kc = malloc((size_t)n * sizeof *r->kc);
        if (!r->masses || !r->kc)
            return gw_err_set(err, GW_ENOMEM, "radii: out of memory");
        for (int i = 0; i < n; i++) {
            double ri = s->radii.v[i];
            if (!(ri > 0))
                return gw_err_set(err, GW_EINVAL, "radii: radius %d is %g, must be > 0", i + 1, ri);
            r->masses[i] = 4.0 / 3.0 * M_PI * ri * ri * ri * bm->density;
            if (i > 0)
                r->kc[i - 1] = gw_hertz_coefficient(s->radii.v[i - 1], bm, ri, bm);
        }
        if (!isnan(s->mass) || !isnan(s->k))
            return gw_err_set(err, GW_EINVAL, "radii: derives masses and k; drop mass and k");
        p->masses = r->masses;
        p->kc = n > 1 ? r->kc : NULL;
        p->mass = r->masses[0];
        p->radius = s->radii.v[0];
        /* the column's k as its scales see it (T_q, K_c, the time scale): the
         * first contact's, bead 1 on bead 2 (two beads of radius radii[0] alone) */
        p->k = n > 1 ? r->kc[0] : gw_hertz_coefficient(p->radius, bm, p->radius, bm);
        if (isnan(s->kwall) && s->sheet < 0)
            p->kwall = gw_hertz_coefficient(p->radius, bm, INFINITY, wm);
    }
    if (isinf(p->kwall))
        return gw_err_set(err, GW_EINVAL, "wall-material: a rigid wall needs a deformable bead material");
    return GW_OK;
}

/* Damping options that would have no effect. */
static int check_damping(const gw_chain_setup *s, gw_err *err)
{
    int restitution = !isnan(s->restitution);
    if (!isnan(s->gamma)) {
        if (s->damping != GW_DAMP_KUWABARA_KONO)
            return gw_err_set(err, GW_EINVAL, "gamma: has no effect without damping kk");
        if (restitution)
            return gw_err_set(err, GW_EINVAL, "gamma: restitution sets gamma; give one of them");
    }
    if (!isnan(s->alpha)) {
        if (s->damping != GW_DAMP_HUNT_CROSSLEY)
            return gw_err_set(err, GW_EINVAL, "alpha: has no effect without damping hc");
        if (restitution)
            return gw_err_set(err, GW_EINVAL, "alpha: restitution sets alpha; give one of them");
    }
    if (!isnan(s->restitution_v) && !restitution)
        return gw_err_set(err, GW_EINVAL, "restitution-v: has no effect without restitution");
    /* a damping model without its constant is the elastic column (gamma and
     * alpha default to 0): it would run undamped and record the model's name.
     * A constant of 0 given on purpose (a sweep over gamma from 0) is kept. */
    if (s->damping == GW_DAMP_KUWABARA_KONO && isnan(s->gamma) && !restitution)
        return gw_err_set(err, GW_EINVAL, "damping: kk without gamma or restitution has no effect (gamma defaults "
                          "to 0, the elastic column): give gamma or restitution");
    if (s->damping == GW_DAMP_HUNT_CROSSLEY && isnan(s->alpha) && !restitution)
        return gw_err_set(err, GW_EINVAL, "damping: hc without alpha or restitution has no effect (alpha defaults "
                          "to 0, the elastic column): give alpha or restitution");
    return GW_OK;
}

static int resolve_run(const gw_chain_setup *s, gw_chain_run_opts *o, gw_err *err)
{
    char sname[16], mname[16];
    *o = gw_chain_run_opts_default();
    /* the solver rows have no table default: not given (-1, NaN) is cvode,
     * its default method, 1e-12 and the default step, so that a study that
     * picks its own solver (falcon by its accuracy) can tell a row given at
     * the default's value from one not given */
    o->solver = s->solver < 0 ? gw_solver_cvode : gw_solver_type_find(choice(s, "solver", sname, sizeof sname));
    if (s->solver < 0)
        gw_snprintf(sname, sizeof sname, "%s", gw_solver_type_name(o->solver));
    int method = s->method < 0 ? GW_METHOD_DEFAULT : gw_solver_method_find(choice(s, "method", mname, sizeof mname));
    if (s->method < 0)
        gw_snprintf(mname, sizeof mname, "default");
    if (!o->solver || method < 0) /* the table's choices are names the solver layer knows */
        return gw_err_set(err, GW_EINVAL, "solver: unknown solver '%s' or method '%s'", sname, mname);
    int ok = method == GW_METHOD_DEFAULT ||
             (o->solver == gw_solver_cvode && (method == GW_CVODE_BDF || method == GW_CVODE_ADAMS)) ||
             (o->solver == gw_solver_arkode &&
              (method == GW_ARKODE_ERK || method == GW_ARKODE_DIRK || method == GW_ARKODE_IMEX));
    if (!ok)
        return gw_err_set(err, GW_EINVAL, "method: '%s' is not a method of solver %s (cvode: bdf, adams; "
                          "arkode: erk, dirk, imex; rk4: none)", mname, sname);
    /* tolerances of the fixed-step solver would have no effect */
    int rc = gw_solver_tolerances_unused_check(o->solver, setup_params, s, err);
    if (rc != GW_OK)
        return rc;
    o->sp.method = method;
    o->sp.rtol = isnan(s->rtol) ? GW_CHAIN_TOL_DEFAULT : s->rtol;
    o->sp.atol = isnan(s->atol) ? GW_CHAIN_TOL_DEFAULT : s->atol;
    o->sp.dt = isnan(s->dt) ? 0 : s->dt;
    o->sp.dt_max = s->dt_max;
    /* every step is at most dt-max: a first step (rk4's step) given above it
     * ran as dt-max, byte for byte under every solver (--dt 1e-3 --dt-max
     * 1e-6), the settings recording the dt given */
    if (o->sp.dt > 0 && s->dt_max > 0 && o->sp.dt > s->dt_max)
        return gw_err_set(err, GW_EINVAL, "dt: %g s is above dt-max = %g s, the largest step: every step is cut to "
                          "dt-max, so dt would run as dt-max (give dt at most dt-max, or a larger dt-max)", o->sp.dt,
                          s->dt_max);
    o->sp.max_steps = s->max_steps;
    o->t_max = s->t_max;
    o->dt_out = s->dt_out;
    o->energy_tol = s->energy_tol;
    return GW_OK;
}

/* The sheet law, its overrides and the sensor body: options that would have no
 * effect refused. */
static int check_wall(const gw_chain_setup *s, gw_err *err)
{
    int sheet = s->sheet >= 0 || s->sheets, law = s->sheet_law < 0 ? GW_SHEET_FITTED : s->sheet_law;
    if (s->sheet_law >= 0 && !sheet)
        return gw_err_set(err, GW_EINVAL, "sheet-law: has no effect without sheet%s",
                          s->sheets ? "" : " (or softwall's sheets)");
    static const char *const mat_rows[] = {"sheet-yield", "sheet-loss"};
    const double mat[] = {s->sheet_yield, s->sheet_loss};
    for (int i = 0; i < 2; i++) {
        if (!isnan(mat[i]) && law != GW_SHEET_MATERIAL)
            return gw_err_set(err, GW_EINVAL, "%s: has no effect without sheet-law material", mat_rows[i]);
        if (!isnan(mat[i]) && s->sheets)
            return gw_err_set(err, GW_EINVAL, "%s: overrides one sheet's constant; give it with sheet, not sheets",
                              mat_rows[i]);
    }
    if (s->sheet_yield > 0 && s->sheet_yield < 1e5)
        return gw_err_set(err, GW_EINVAL, "sheet-yield: %g Pa is below any solid's yield stress "
                          "(0 = elastic, or >= 1e5 Pa)", s->sheet_yield);
    /* what gw_sheet_apply takes of the overrides under law material: nothing
     * for the bare sensor (sheet none: no thickness, the Hertz wall of the
     * sensor's material), and no loss for a sheet that yields (Thornton
     * elastic-plastic on the Hertz law; the loss is the elastic layer's) */
    if (s->sheet >= 0 && law == GW_SHEET_MATERIAL && (!isnan(s->sheet_yield) || !isnan(s->sheet_loss))) {
        char name[32];
        const gw_sheet *sh = gw_sheet_find(choice(s, "sheet", name, sizeof name));
        const int i = !isnan(s->sheet_yield) ? 0 : 1;
        if (sh && !(sh->thickness > 0))
            return gw_err_set(err, GW_EINVAL, "%s: has no effect with sheet %s (the bare sensor: no sheet to "
                              "yield or to lose energy; its wall is the Hertz half-space of wall-material)",
                              mat_rows[i], sh->name);
        const double y = !isnan(s->sheet_yield) ? s->sheet_yield : sh ? sh->yield : 0;
        if (sh && y > 0 && !isnan(s->sheet_loss))
            return gw_err_set(err, GW_EINVAL, "sheet-loss: has no effect on sheet %s with a yield stress of %g Pa "
                              "(%s; a sheet that yields is Thornton elastic-plastic, the loss is that of the "
                              "elastic layer): give sheet-yield 0 with it", sh->name, y,
                              isnan(s->sheet_yield) ? "the sheet's own" : "sheet-yield");
    }
    int ms = !isnan(s->sensor_mass);
    if (!ms && !isnan(s->sensor_stiffness))
        return gw_err_set(err, GW_EINVAL, "sensor-stiffness: has no effect without sensor-mass");
    if (!ms && !isnan(s->sensor_damping))
        return gw_err_set(err, GW_EINVAL, "sensor-damping: has no effect without sensor-mass");
    if (ms && isnan(s->sensor_stiffness))
        return gw_err_set(err, GW_EINVAL, "sensor-mass: a sensor body needs sensor-stiffness");
    return GW_OK;
}

/* The sheet as a wall law (law other than fitted), a loss the Maxwell arms can
 * give, the sensor body and guide friction on the resolved column. */
/* Contact damping (kk, hc) acts on bead contacts and on a Hertz wall, not on a
 * layer, plastic or viscoelastic wall (gw_chain_wall). One body on such a wall
 * ran as if undamped, with exit 0: chain --damping kk --gamma 1e5 --sheet brass
 * --sheet-law layer gave eps_eff 1.000, and --restitution 0.5 under sheet-law
 * material gave 0.615, the sheet's own. */
static int damping_idle(const gw_chain_params *p)
{
    return p && p->damping != GW_DAMP_NONE && (p->wall.layer || p->wall.yield_pressure > 0 || p->wall.loss > 0);
}

#define DAMPING_WHY "(kk and hc act on bead contacts and on a Hertz wall; this wall dissipates by its own law, which " \
                    "sheet-loss and sheet-yield set)"

int chain_damping_check(const gw_chain_params *p, gw_err *err)
{
    if (!p || p->n != 1 || !damping_idle(p))
        return GW_OK;
    return gw_err_set(err, GW_EINVAL, "damping: has no effect on one bead against a sheet under a layer, plastic "
                      "or viscoelastic law " DAMPING_WHY ": give more beads, sheet-law fitted or hertz, or no damping");
}

/* One body has no bead contact: chain --n 1 --k 1e9 ran with exit 0 and F_max
 * 66.3889 N, as without it (and so did drop --n 1 and drop --block --n 3, whose
 * block is one body); --material glass with --mass and --kwall given changed
 * only that k. A study over N from 1 or a sweep's case of n = 1 keeps them (a
 * key of a grid acts on its other cases). */
int chain_one_body_check(const gw_chain_setup *s, int n_bodies, gw_err *err)
{
    if (!s || n_bodies != 1)
        return GW_OK;
    if (!isnan(s->k))
        return gw_err_set(err, GW_EINVAL, "k: has no effect on one body (n = 1, or a drop's block): k is the "
                          "bead-bead contact's coefficient and one body has no bead contact (the wall's is kwall)");
    const int fitted = s->sheet_law < 0 || s->sheet_law == GW_SHEET_FITTED;
    const int wall_given = !isnan(s->kwall) || ((s->sheet >= 0 || s->sheets) && fitted);
    if (!isnan(s->mass) && wall_given && s->radii.n == 0 &&
        gw_param_given(gw_param_find(setup_params, "material"), s))
        return gw_err_set(err, GW_EINVAL, "material: has no effect on one body (n = 1, or a drop's block) with "
                          "mass and the wall's coefficient given: it would give only k, the bead-bead contact's "
                          "coefficient, and one body has no bead contact");
    return GW_OK;
}

/* A study's sizes from n_lo: its one-bead column ran undamped by its wall's law
 * among damped columns, exit 0 (falcon --n 1:5 --damping kk --sheet brass
 * --sheet-law layer); the single run's rule, chain_damping_check, applied to
 * the study's smallest column. */
int chain_damping_study_check(const gw_chain_params *p, long n_lo, const char *sheet, gw_err *err)
{
    if (!p || n_lo != 1 || !damping_idle(p))
        return GW_OK;
    return gw_err_set(err, GW_EINVAL, "damping: has no effect on the study's one-bead column (n from 1) against "
                      "%s%s under a layer, plastic or viscoelastic law " DAMPING_WHY ": it would run undamped among "
                      "damped columns: give sizes from 2, sheet-law fitted or hertz, or no damping",
                      sheet ? "sheet " : "a sheet", sheet ? sheet : "");
}

static int apply_wall(const gw_chain_setup *s, gw_chain_resolved *r, gw_err *err)
{
    char name[32];
    gw_chain_params *p = &r->params;
    if (s->sheet >= 0 && r->law != GW_SHEET_FITTED) {
        const gw_material *bm = gw_material_find(choice(s, "material", name, sizeof name));
        const gw_material *wm = gw_material_find(choice(s, "wall-material", name, sizeof name));
        const gw_sheet *sh = gw_sheet_find(choice(s, "sheet", name, sizeof name));
        double y = r->law == GW_SHEET_MATERIAL && !isnan(s->sheet_yield) ? s->sheet_yield : -1;
        double l = r->law == GW_SHEET_MATERIAL && !isnan(s->sheet_loss) ? s->sheet_loss : -1;
        int rc = gw_sheet_apply(sh, r->law, y, l, bm, wm, p, &r->layer, err);
        if (rc != GW_OK) {
            char tmp[sizeof err->msg];
            gw_snprintf(tmp, sizeof tmp, "%s", err->msg);
            return gw_err_set(err, rc, "sheet: %s: %s", sh->name, tmp);
        }
    }
    if (p->wall.loss > 0) { /* a loss the Maxwell arms cannot give is refused here, by name */
        chain_wall_law wl;
        if (chain_wall_law_init(&wl, p, err) != GW_OK) {
            char tmp[sizeof err->msg];
            gw_snprintf(tmp, sizeof tmp, "%s", err->msg);
            return gw_err_set(err, GW_EINVAL, "sheet-loss: %s", tmp);
        }
    }
    if (!isnan(s->sensor_mass)) {
        p->sensor.mass = s->sensor_mass;
        p->sensor.stiffness = s->sensor_stiffness;
        p->sensor.damping = isnan(s->sensor_damping) ? 0 : s->sensor_damping;
    }
    p->guide.coulomb = s->guide_friction;
    p->guide.viscous = s->guide_viscous;
    return GW_OK;
}

int gw_chain_setup_resolve(const gw_chain_setup *s, gw_chain_resolved *r, gw_err *err)
{
    if (!s || !r) {
        if (r)
            memset(r, 0, sizeof *r);
        return gw_err_set(err, GW_EINVAL, "gw_chain_setup_resolve: %s is NULL", !s ? "s" : "r");
    }
    memset(r, 0, sizeof *r);
    int rc = gw_param_check(setup_params, s, err);
    if (rc != GW_OK)
        return rc;
    gw_chain_params *p = &r->params;
    *p = gw_chain_params_default();
    p->n = (int)s->n;
    p->v_imp = s->vimp;
    if ((rc = resolve_model(s, r, err)) != GW_OK)
        return rc;
    p->gravity = s->gravity;
    p->damping = (gw_chain_damping)s->damping;
    p->gamma = isnan(s->gamma) ? 0 : s->gamma;
    p->alpha = isnan(s->alpha) ? 0 : s->alpha;
    if ((rc = check_damping(s, err)) != GW_OK ||
        (rc = resolve_run(s, &r->run, err)) != GW_OK ||
        (rc = gw_solver_tolerances_check(r->run.sp.rtol, r->run.sp.atol, "rtol", "atol", err)) != GW_OK ||
        (rc = gw_chain_params_validate(p, err)) != GW_OK ||
        (rc = check_wall(s, err)) != GW_OK)
        return rc;
    r->law = s->sheet_law < 0 ? GW_SHEET_FITTED : (gw_sheet_law)s->sheet_law;
    if (!isnan(s->restitution)) {
        if (s->restitution >= 1)
            return gw_err_set(err, GW_EINVAL, "restitution: %g must be below 1", s->restitution);
        if (p->damping == GW_DAMP_NONE)
            return gw_err_set(err, GW_EINVAL, "restitution: needs damping kk or hc");
        gw_chain_params q = *p;
        if (!isnan(s->restitution_v))
            q.v_imp = s->restitution_v;
        if (r->law != GW_SHEET_FITTED && (s->sheet >= 0 || s->sheets)) {
            /* a sheet as a material: the beads' damping calibrated on the bare sensor */
            char name[32];
            const gw_material *bm = gw_material_find(choice(s, "material", name, sizeof name));
            const gw_material *wm = gw_material_find(choice(s, "wall-material", name, sizeof name));
            q.kwall = gw_hertz_coefficient(p->radius, bm, INFINITY, wm);
        }
        double cst = 0;
        if ((rc = gw_chain_calibrate(&q, &r->run, s->restitution, &cst, err)) != GW_OK)
            return rc;
        if (p->damping == GW_DAMP_HUNT_CROSSLEY)
            p->alpha = cst;
        else
            p->gamma = cst;
    }
    return apply_wall(s, r, err);
}
