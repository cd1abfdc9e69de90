/*
 * chain_warnings.c: the warning texts of the column's runs and studies, each
 * written once (gw_common.h, "warnings of a result"). A run that ended with
 * results that are not final (a collision cut at t_max, physics.md 1.2: every
 * contact open and every pair separating; a dispersion spectrum without a
 * ridge, 1.6) returns GW_OK and its result says why here. The program prints
 * these texts as "granwave CMD: warning: TEXT", the Python module issues them
 * as GranwaveWarning, a C caller reads them from the outcome's `warnings`.
 * Parameters are named as the program's flags (--t-max), as the library's
 * other texts for the user (the layer's undecided outcome) do.
 */
#include <math.h>
#include <string.h>

#include "gw_chain.h"
#include "gw_chain_study.h"
#include "chain_model.h"
#include "chain_wall.h"
#include "gw_locale.h"

const char chain_held_pending[] = "held by gravity: the column fell back onto the wall before its collision ended";

/* Beyond an overlap of one radius the beads would have passed through each
 * other's centres: the numbers are those of the Hertz law outside its range
 * (chain --vimp 1000 --mass 1e3 --k 1e3 --kwall 1e3 pressed 281 m into the
 * wall with a 4 mm bead and said nothing). */
static int overlap_warning(const gw_chain_result *r, char **list)
{
    if (!(r->overlap_max_rel > 1))
        return GW_OK;
    return gw_warnings_add(list,
                           "the largest contact overlap was %.3g bead radii: the Hertz law holds for overlaps much "
                           "smaller than the radius, and these results are the law's far outside its range (a lower "
                           "--vimp or --gravity, or stiffer or lighter beads)",
                           r->overlap_max_rel);
}

int chain_damping_zero(const gw_chain_params *p)
{
    return p && ((p->damping == GW_DAMP_KUWABARA_KONO && p->gamma == 0) ||
                 (p->damping == GW_DAMP_HUNT_CROSSLEY && p->alpha == 0));
}

int chain_bead_stopped(double v, double v_scale)
{
    return fabs(v) < 1e-3 * v_scale;
}

/* 1 when p's contact damping is kk or hc with its constant above 0 */
static int damping_on(const gw_chain_params *p)
{
    return p && (p->damping == GW_DAMP_KUWABARA_KONO || p->damping == GW_DAMP_HUNT_CROSSLEY) &&
           !chain_damping_zero(p);
}

/* "damping kk, gamma G N s/m^1.5" (hc: alpha in s/m) into buf: the damping
 * named in the held chain's failure and the drop's at-rest warning */
static const char *damping_named(char *buf, size_t n, const gw_chain_params *p)
{
    const int kk = p->damping == GW_DAMP_KUWABARA_KONO;
    gw_snprintf(buf, n, "damping %s, %s %g %s", kk ? "kk" : "hc", kk ? "gamma" : "alpha", kk ? p->gamma : p->alpha,
                kk ? "N s/m^1.5" : "s/m");
    return buf;
}

int chain_damping_holds(const gw_chain_params *p, double v1, double v_scale)
{
    return damping_on(p) && chain_bead_stopped(v1, v_scale);
}

int chain_damping_held_error(const gw_chain_params *p, const char *who, const char *wall, double t_max,
                             const char *why, const char *advice, gw_err *err)
{
    char named[128];
    return gw_err_set(err, GW_ELIMIT, "%s: bead 1 still on the %s at t_max = %.6g s: the contact damping (%s) "
                      "stopped it inside its overlap, %s: lower %s%s", who, wall, t_max,
                      damping_named(named, sizeof named, p), why,
                      p->damping == GW_DAMP_KUWABARA_KONO ? "gamma" : "alpha", advice ? advice : "");
}

/* chain --damping kk --gamma 0 ran the elastic column, recorded damping kk
 * and said nothing (the forty-fourth pass) */
int chain_damping_zero_warnings(const gw_chain_params *p, int zero, int total, char **list)
{
    if (p) {
        if (!chain_damping_zero(p))
            return GW_OK;
        const int kk = p->damping == GW_DAMP_KUWABARA_KONO;
        const char *c = kk ? "gamma" : "alpha";
        return gw_warnings_add(list, "--damping %s with --%s 0 is no damping: the results are those of --damping none "
                               "(give --%s above 0, or --restitution)", kk ? "kk" : "hc", c, c);
    }
    if (zero <= 0)
        return GW_OK;
    return gw_warnings_add(list, "damping kk with gamma 0, or hc with alpha 0, is no damping: %d of %d cases, whose rows "
                           "are those of damping none", zero, total);
}

/* The damping's predicted relative effect on the restitution at p's impact
 * speed (physics.md 1.5): Hunt-Crossley's 1 - e is about alpha v;
 * Kuwabara-Kono's about gamma v / (k d_max) (Schwager and Poeschel's 1.153 A
 * (3k/2m)^(2/5) v^(1/5) with gamma = 3/2 A k, d_max the Hertz overlap
 * gw_chain_dmax1: 0.99 gamma v / (k d_max)), the larger of the wall's
 * contact (gamma K/k on K, at mass m) and the beads' (gamma on k, at m/2).
 * 0 when p does not damp. */
double chain_damping_effect(const gw_chain_params *p)
{
    if (!damping_on(p) || !(p->v_imp > 0))
        return 0;
    const double v = p->v_imp;
    if (p->damping == GW_DAMP_HUNT_CROSSLEY)
        return p->alpha * v;
    double e = 0;
    const double dw = gw_chain_dmax1(p->mass, p->kwall, v); /* the wall's: gamma K/k over K */
    if (dw > 0)
        e = p->gamma * v / (p->k * dw);
    const double db = p->n > 1 ? gw_chain_dmax1(0.5 * p->mass, p->k, v) : NAN;
    if (db > 0)
        e = fmax(e, p->gamma * v / (p->k * db));
    return e;
}

/* chain --damping kk --gamma 1e-30 ran the elastic column and said nothing
 * (the forty-eighth pass): a damping whose predicted effect is below the
 * solver's relative tolerance cannot change a digit the run resolves. */
int chain_damping_small(const gw_chain_params *p, double rtol)
{
    const double e = chain_damping_effect(p);
    return e > 0 && rtol > 0 && e < rtol;
}

int chain_damping_small_warning(const gw_chain_params *p, double rtol, char **list)
{
    if (!chain_damping_small(p, rtol))
        return GW_OK;
    const double e = chain_damping_effect(p);
    char named[128];
    const int kk = p->damping == GW_DAMP_KUWABARA_KONO;
    return gw_warnings_add(list, "the contact damping (%s) has no effect: its predicted relative effect on the "
                           "restitution, %s = %.3g, is below the solver's rtol %g, and the results are those of "
                           "--damping none (give a larger --%s, or a --restitution further below 1)",
                           damping_named(named, sizeof named, p), kk ? "gamma v_imp/(k d_max)" : "alpha v_imp", e,
                           rtol, kk ? "gamma" : "alpha");
}

int chain_damping_small_study_warning(const gw_chain_params *p, double rtol, const double *v, int nv, char **list)
{
    if (!p || !v || nv < 1)
        return GW_OK;
    gw_chain_params q = *p; /* at the study's largest speed, bead contacts counted: its largest effect */
    q.v_imp = v[0];
    for (int i = 1; i < nv; i++)
        q.v_imp = fmax(q.v_imp, v[i]);
    q.n = 2;
    return chain_damping_small_warning(&q, rtol, list);
}

int chain_damping_small_cases_warning(int n, int total, double hi, char **list)
{
    if (n <= 0)
        return GW_OK;
    return gw_warnings_add(list, "the contact damping has no effect in %d of %d cases: its predicted relative effect "
                           "on the restitution (kk: gamma v_imp/(k d_max), hc: alpha v_imp; at most %.3g there) is "
                           "below the case's rtol, and their rows are those of damping none", n, total, hi);
}

/* The sensor body's dashpot and the guide's friction had no "no effect"
 * check: chain --sensor-damping 1e-12 ran the undamped sensor and said
 * nothing. Their scales (cli.md, "no effect"): the dashpot's damping ratio
 * zeta = c / (2 sqrt(k_s m_s)), measured above the relative change of eps_eff
 * it gives (one steel bead at 0.3 m/s, m_s 1e-2 kg: k_s 1e7, 0.19 zeta; k_s
 * 1e10, 7e-4 zeta); the guide's friction its impulse over the collision's
 * expected length t_col against the lightest bead's momentum, (F_c/v + c_g)
 * t_col / m, its work against the impact energy (measured 0.3 to 0.4 of it on
 * one bead, cli.md's table). 0 when absent. */
double chain_sensor_damping_effect(const gw_chain_params *p)
{
    if (!p || !(p->sensor.mass > 0) || !(p->sensor.stiffness > 0) || !(p->sensor.damping > 0))
        return 0;
    return p->sensor.damping / (2 * sqrt(p->sensor.stiffness * p->sensor.mass));
}

double chain_guide_effect(const gw_chain_params *p)
{
    if (!p || !(p->guide.coulomb > 0 || p->guide.viscous > 0) || p->n < 1)
        return 0;
    gw_chain_params q = *p; /* the time scales at the plan's speed (chain_collide_plan.c) */
    q.v_imp = chain_speed_scale(p);
    if (!(q.v_imp > 0))
        return 0;
    double m = p->mass;
    for (int i = 0; p->masses && i < p->n; i++)
        m = i ? fmin(m, p->masses[i]) : p->masses[0];
    const double t = chain_collision_length(&q, NULL);
    if (!(m > 0) || !(t > 0))
        return 0;
    return (fmax(p->guide.coulomb, 0) / q.v_imp + fmax(p->guide.viscous, 0)) * t / m;
}

void chain_drag_tally_add(chain_drag_tally *t, const gw_chain_params *p)
{
    if (!t || !p)
        return;
    const double z = chain_sensor_damping_effect(p), g = chain_guide_effect(p);
    if (z > 0)
        t->sensor_hi = t->n_sensor++ ? fmax(t->sensor_hi, z) : z;
    if (g > 0)
        t->guide_hi = t->n_guide++ ? fmax(t->guide_hi, g) : g;
    t->damping = p->sensor.damping;
    t->coulomb = p->guide.coulomb;
    t->viscous = p->guide.viscous;
}

int chain_drag_tally_warnings(const chain_drag_tally *t, double rtol, char **list)
{
    if (!t || !(rtol > 0))
        return GW_OK;
    char over[96] = ""; /* a study's: the largest effect over its columns */
    int rc = GW_OK;
    if (t->n_sensor > 0 && t->sensor_hi < rtol) {
        if (t->n_sensor > 1)
            gw_snprintf(over, sizeof over, " (the largest over the study's %d columns)", t->n_sensor);
        rc = gw_warnings_add(list, "the sensor body's dashpot (--sensor-damping %g N s/m) has no effect: its damping "
                             "ratio c/(2 sqrt(k_s m_s)) = %.3g%s is below the solver's rtol %g, and the results are "
                             "those of --sensor-damping 0 (give a larger --sensor-damping)", t->damping, t->sensor_hi,
                             over, rtol);
    }
    over[0] = '\0';
    if (rc == GW_OK && t->n_guide > 0 && t->guide_hi < rtol) {
        if (t->n_guide > 1)
            gw_snprintf(over, sizeof over, " (the largest over the study's %d columns)", t->n_guide);
        rc = gw_warnings_add(list, "the guide's friction (--guide-friction %g N, --guide-viscous %g N s/m) has no "
                             "effect: its predicted relative effect on the impact, (F_c/v + c_g) t_col/m = %.3g%s, is "
                             "below the solver's rtol %g, and the results are those of a column without friction "
                             "(give a larger --guide-friction or --guide-viscous)", t->coulomb, t->viscous,
                             t->guide_hi, over, rtol);
    }
    return rc;
}

int chain_drag_small_warnings(const gw_chain_params *p, double rtol, char **list)
{
    if (!p)
        return GW_OK;
    chain_drag_tally t = {0};
    chain_drag_tally_add(&t, p);
    return chain_drag_tally_warnings(&t, rtol, list);
}

int chain_drag_small_study_warnings(const gw_chain_params *p, double rtol, const double *v, int nv, int n_lo,
                                    int n_hi, char **list)
{
    if (!p || !v || nv < 1 || n_lo < 1 || n_hi < n_lo)
        return GW_OK;
    chain_drag_tally t = {0};
    for (int i = 0; i < nv; i++)
        for (int n = n_lo; n <= n_hi; n++) {
            gw_chain_params q = *p; /* each column of the study: its size and speed */
            q.v_imp = v[i];
            q.n = n;
            chain_drag_tally_add(&t, &q);
        }
    return chain_drag_tally_warnings(&t, rtol, list);
}

/* A sweep's case: its dashpot and its friction each tallied when present
 * and below the case's rtol (the single run's test) */
void chain_drag_cases_add(chain_drag_cases *c, const gw_chain_params *p, double rtol, long k)
{
    if (!c || !p || !(rtol > 0))
        return;
    const double z = chain_sensor_damping_effect(p), g = chain_guide_effect(p);
    if (z > 0 && z < rtol) {
        if (c->sensor++ == 0)
            c->sensor_first = k, c->sensor_hi = z;
        c->sensor_hi = fmax(c->sensor_hi, z);
    }
    if (g > 0 && g < rtol) {
        if (c->guide++ == 0)
            c->guide_first = k, c->guide_hi = g;
        c->guide_hi = fmax(c->guide_hi, g);
    }
}

int chain_drag_cases_warnings(const chain_drag_cases *c, long total, char **list)
{
    if (!c)
        return GW_OK;
    int rc = GW_OK;
    if (c->sensor > 0)
        rc = gw_warnings_add(list, "the sensor body's dashpot has no effect in %ld of %ld cases (the first, case %ld): "
                             "its damping ratio c/(2 sqrt(k_s m_s)), at most %.3g there, is below the case's rtol, "
                             "and their rows are those of --sensor-damping 0 (give a larger --sensor-damping)",
                             c->sensor, total, c->sensor_first, c->sensor_hi);
    if (rc == GW_OK && c->guide > 0)
        rc = gw_warnings_add(list, "the guide's friction has no effect in %ld of %ld cases (the first, case %ld): its "
                             "predicted relative effect on the impact, (F_c/v + c_g) t_col/m, at most %.3g there, is "
                             "below the case's rtol, and their rows are those of a column without friction (give a "
                             "larger --guide-friction or --guide-viscous)", c->guide, total, c->guide_first,
                             c->guide_hi);
    return rc;
}

/* A dt given above the step the run could take ran at that step: the
 * results are the step's (chain --dt 1e-3 byte for byte those of the
 * automatic dt-max 6.6e-6 s); refusing would refuse the dt that earlier
 * commands passed, so the run goes on and says so (the settings' dt is the
 * step taken, dt_given the one given). A study or a sweep says it once, with
 * how many of its runs it concerns (falcon, wavespeed, softwall and the
 * sweeps recorded dt_given and said nothing). */
void chain_dt_tally_add(chain_dt_tally *t, double given, double taken, double dt_max)
{
    t->total++;
    if (!(given > 0 && taken < given))
        return;
    if (t->over == 0) {
        t->given_lo = t->given_hi = given;
        t->taken_lo = t->taken_hi = taken;
    }
    t->given_lo = fmin(t->given_lo, given);
    t->given_hi = fmax(t->given_hi, given);
    t->taken_lo = fmin(t->taken_lo, taken);
    t->taken_hi = fmax(t->taken_hi, taken);
    t->at_out += taken < dt_max; /* rk4: its steps end at the samples */
    t->over++;
}

void chain_dt_tally_overlap(chain_dt_tally *t, double overlap_rel)
{
    if (!(overlap_rel > 1))
        return;
    t->overlap_hi = t->overlap_over == 0 ? overlap_rel : fmax(t->overlap_hi, overlap_rel);
    t->overlap_over++;
}

/* A run's chatter on a sensor body (its chatter_kind) into t */
static void tally_chatter(chain_dt_tally *t, const gw_chain_result *r)
{
    const int kind = r->chatter_kind;
    if (kind <= GW_CHAIN_CHATTER_NONE || kind > GW_CHAIN_CHATTER_FAILED)
        return;
    t->chatter[kind]++;
    t->chatter_contacts = r->wall_contacts > t->chatter_contacts ? r->wall_contacts : t->chatter_contacts;
    if (kind == GW_CHAIN_CHATTER_MOVED)
        t->chatter_spread = fmax(t->chatter_spread, r->chatter_spread);
    if (kind == GW_CHAIN_CHATTER_COSTLY)
        t->chatter_work = fmax(t->chatter_work, (double)r->stats.steps * r->n);
}

void chain_dt_tally_results(chain_dt_tally *t, const gw_chain_result *res, long n)
{
    for (long i = 0; res && i < n; i++) {
        chain_dt_tally_add(t, res[i].run_dt_given, res[i].run_dt, res[i].run_dt_max);
        chain_dt_tally_overlap(t, res[i].overlap_max_rel);
        tally_chatter(t, &res[i]);
    }
}

void chain_chatter_text(char *buf, size_t size, int contacts, const char *where, const char *ending)
{
    gw_snprintf(buf, size, "bead 1 chattered on the sensor body (its wall contact closed %d times%s): the chatter "
                "amplifies the integration's error, %s", contacts, where ? where : "", ending ? ending : "");
}

/* The runs of a study whose bead 1 chattered on the sensor body, in one line
 * with their count (each said its own in the single run's warnings, which a
 * study dropped: falcon, wavespeed and softwall ran the cheap ones again and
 * said nothing of what the reruns measured, nor of the costly ones). first:
 * "" or "; the first, case K" of a sweep; moved, costly, failed: the counts
 * by kind; rerun: what the moved ones' reruns changed (CHAIN_RERUN_* bits:
 * a study under cvode was told "(rk4: half the step)" too), rtol and atol
 * their tolerances where one setting (0: not known). GW_OK or GW_ENOMEM. */
static void rerun_words(char *buf, size_t size, int rerun, double rtol, double atol)
{
    const char *rk4 = rerun & CHAIN_RERUN_STEP ? "under rk4: half the step" : "";
    if (!(rerun & (CHAIN_RERUN_TOL | CHAIN_RERUN_LOOSE))) {
        gw_snprintf(buf, size, "half rk4's step");
        return;
    }
    if (rtol > 0 && atol > 0) { /* one setting: the reruns' values, as the single run names them */
        gw_solver_params sp = gw_solver_params_default();
        sp.rtol = rtol;
        sp.atol = atol;
        char how[96], flags[80];
        chain_chatter_rerun(gw_solver_cvode, 0, &sp, how, sizeof how, flags, sizeof flags);
        if (chain_chatter_looser(rtol, atol))
            gw_snprintf(buf, size, "rtol %g, atol %g (10 times looser: 1e-15 is the floor%s%s)", sp.rtol, sp.atol,
                        rk4[0] ? "; " : "", rk4);
        else
            gw_snprintf(buf, size, "10 times tighter tolerances (rtol %g, atol %g%s%s)", sp.rtol, sp.atol,
                        rk4[0] ? "; " : "", rk4);
        return;
    }
    const int tight = (rerun & CHAIN_RERUN_TOL) != 0, loose = (rerun & CHAIN_RERUN_LOOSE) != 0;
    const char *why = tight && loose ? "10 times looser where one was at the 1e-15 floor"
                    : loose          ? "one was at the 1e-15 floor"
                                     : "";
    gw_snprintf(buf, size, "10 times %s tolerances%s%s%s%s%s", tight ? "tighter" : "looser",
                why[0] || rk4[0] ? " (" : "", why, why[0] && rk4[0] ? "; " : "", rk4, why[0] || rk4[0] ? ")" : "");
}

int chain_chatter_cases_warning(long moved, long costly, long failed, long total, int contacts, double spread,
                                double work, int rerun, double rtol, double atol, const char *what, const char *first,
                                char **list)
{
    const long n = moved + costly + failed;
    if (n <= 0)
        return GW_OK;
    char a[224] = "", b[200] = "", c[64] = "", up[48] = "", words[160];
    if (contacts > 0) /* a sweep's rows hold no count of contacts */
        gw_snprintf(up, sizeof up, "up to %d wall contacts", contacts);
    rerun_words(words, sizeof words, rerun, rtol, atol);
    if (moved > 0)
        gw_snprintf(a, sizeof a, "; in %ld a rerun at %s moved eps_eff by up to %.3g", moved, words, spread);
    if (costly > 0 && work > 0)
        gw_snprintf(b, sizeof b, "; %ld too costly to run again (up to %.3g steps times beads, above %.3g), their "
                    "spread unmeasured", costly, work, GW_CHAIN_CHATTER_WORK);
    else if (costly > 0) /* a sweep's rows: the steps alone */
        gw_snprintf(b, sizeof b, "; %ld too costly to run again (steps times beads above %.3g), their spread "
                    "unmeasured", costly, GW_CHAIN_CHATTER_WORK);
    if (failed > 0)
        gw_snprintf(c, sizeof c, "; %ld whose rerun failed", failed);
    return gw_warnings_add(list,
                           "bead 1 chattered on the sensor body in %ld of %ld %s (%s%s%s)%s%s%s: "
                           "the chatter amplifies the integration's error, and their final velocities, restitution "
                           "and tau_N, and what is fitted over them, move with dt-out and the tolerances; a "
                           "stiffer, heavier or damped sensor body (--sensor-stiffness, --sensor-mass, "
                           "--sensor-damping) chatters less",
                           n, total, what, up, up[0] && first[0] ? "; " : "", first[0] ? first + 2 : "", a, b, c);
}

static int tally_chatter_warning(const chain_dt_tally *t, const char *what, char **list)
{
    /* the tolerances' reruns 10 times looser where one is at the 1e-15 floor (chain_chatter_rerun) */
    const int tol = t->rtol > 0 && t->atol > 0 && chain_chatter_looser(t->rtol, t->atol) ? CHAIN_RERUN_LOOSE
                                                                                            : CHAIN_RERUN_TOL;
    const int rerun = !t->solver ? tol | CHAIN_RERUN_STEP : t->solver == gw_solver_rk4 ? CHAIN_RERUN_STEP : tol;
    return chain_chatter_cases_warning(t->chatter[GW_CHAIN_CHATTER_MOVED], t->chatter[GW_CHAIN_CHATTER_COSTLY],
                                       t->chatter[GW_CHAIN_CHATTER_FAILED], t->total, t->chatter_contacts,
                                       t->chatter_spread, t->chatter_work, rerun, t->rtol, t->atol, what, "", list);
}

/* The runs of a study pressed beyond one radius (overlap_warning's line, with
 * how many of them): `falcon --n 1:3 --mass 1000 --radius 1e-5` reached 309
 * radii, as chain does on its one run, and said nothing. first: "" or the
 * first of them ("; the first, case 4" of a sweep). */
static int overlap_many_warning(double hi, long n, long total, const char *what, const char *first, char **list)
{
    return gw_warnings_add(list,
                           "the largest contact overlap was %.3g bead radii (%ld of %ld %s beyond one radius%s): the "
                           "Hertz law holds for overlaps much smaller than the radius, and their results are the "
                           "law's far outside its range (a lower --vimp or --gravity, or stiffer or lighter beads)",
                           hi, n, total, what, first);
}

static int tally_overlap_warning(const chain_dt_tally *t, const char *what, char **list)
{
    if (t->overlap_over <= 0)
        return GW_OK;
    return overlap_many_warning(t->overlap_hi, t->overlap_over, t->total, what, "", list);
}

/* A sweep's cases pressed beyond one radius (their rows' overlap_max_rel
 * above 1): `granwave chain` warns of its one run, a chain sweep wrote such
 * rows and said nothing (the forty-eighth pass) */
int chain_overlap_cases_warning(long n, long total, double hi, long first, char **list)
{
    if (n <= 0)
        return GW_OK;
    char f[48];
    gw_snprintf(f, sizeof f, "; the first, case %ld", first);
    return overlap_many_warning(hi, n, total, "cases", f, list);
}

/* A sweep's cases whose relative energy error passed GW_CHAIN_ENERGY_WARN
 * with energy-tol off (chain_energy_warning's, which a sweep case lost: its
 * row's energy_error alone said it) */
int chain_energy_cases_warning(long n, long total, double hi, long first, char **list)
{
    if (n <= 0)
        return GW_OK;
    return gw_warnings_add(list, "the relative energy error reached %.3g (%.3g %%, above %g) in %ld of %ld cases (the "
                           "first, case %ld; their energy_error column) with energy-tol off: their tolerances are "
                           "too loose to trust their numbers: tighten rtol and atol (rk4: lower dt), or set "
                           "energy-tol to stop at a bound", hi, 100 * hi, GW_CHAIN_ENERGY_WARN, n, total, first);
}

/* "A s" or "A to B s" */
static void span(char *buf, size_t size, double lo, double hi)
{
    if (lo == hi)
        gw_snprintf(buf, size, "%g", lo);
    else
        gw_snprintf(buf, size, "%g to %g", lo, hi);
}

static int dt_tally_line(const chain_dt_tally *t, const char *name, const char *what, char **list);

int chain_dt_tally_warnings(const chain_dt_tally *t, const char *name, const char *what, char **list)
{
    if (!t || !name)
        return GW_OK;
    int rc = dt_tally_line(t, name, what, list);
    rc = rc == GW_OK ? tally_overlap_warning(t, what, list) : rc;
    return rc == GW_OK ? tally_chatter_warning(t, what, list) : rc;
}

static int dt_tally_line(const chain_dt_tally *t, const char *name, const char *what, char **list)
{
    if (t->over <= 0)
        return GW_OK;
    /* a sweep's table holds the dt given (its key), the studies' settings the steps taken */
    const int sweep = name[0] != '-';
    const int all_out = t->at_out == t->over, some_out = t->at_out > 0;
    const char *out = sweep ? "dt-out" : "--dt-out"; /* the names the reader gave */
    char bound[32];
    gw_snprintf(bound, sizeof bound, "%s%s%s", all_out ? "" : "dt-max", some_out && !all_out ? " or " : "",
                some_out ? out : "");
    const char *why = all_out ? "rk4's steps end at the samples"
                    : some_out ? "a quarter of the shortest contact unless given; rk4's steps end at the samples"
                               : "a quarter of the shortest contact unless given";
    if (t->total == 1 && !sweep) /* one run: the text of chain and drop */
        return gw_warnings_add(list,
                               "%s %g s is above %s = %g s, the longest step the run takes (%s): it ran at that "
                               "step, the dt its settings record (dt_given: %g s)",
                               name, t->given_hi, bound, t->taken_hi, why, t->given_hi);
    char given[64], taken[64];
    span(given, sizeof given, t->given_lo, t->given_hi);
    span(taken, sizeof taken, t->taken_lo, t->taken_hi);
    return gw_warnings_add(list,
                           "%s %s s is above the longest step that %d of %d %s take (%s = %s s, %s): they %s at that "
                           "step, %s (dt_given: %s s)",
                           name, given, t->over, t->total, what, bound, taken, why, sweep ? "run" : "ran",
                           sweep ? "while the table records the dt given" : "the dt their settings record", given);
}

/* the one run's line (chain, drop) */
static int dt_warning(double given, double taken, double dt_max, char **list)
{
    chain_dt_tally t = {0};
    chain_dt_tally_add(&t, given, taken, dt_max);
    return chain_dt_tally_warnings(&t, "--dt", "runs", list);
}

int gw_chain_result_warnings(const gw_chain_result *r, char **list)
{
    if (!r)
        return GW_OK;
    int rc = dt_warning(r->run_dt_given, r->run_dt, r->run_dt_max, list);
    if (rc == GW_OK)
        rc = overlap_warning(r, list);
    const char *chatter = chain_result_chatter(r); /* a converged run's: "" otherwise */
    if (rc == GW_OK && chatter[0])
        rc = gw_warnings_add(list, "%s", chatter);
    if (rc != GW_OK || r->converged)
        return rc;
    if (r->wall_pending == chain_held_pending) /* a longer run does not decide it */
        return gw_warnings_add(list,
                               "gravity holds the column: its momentum, turned away from the wall by the impact, "
                               "was back toward it at t = %.6g s, before the collision ended: F_max, tau_N, the "
                               "final velocities and the restitution are undecided, those at that time; raise "
                               "--vimp or lower --gravity", r->t_end);
    /* the wall's side (wall_pending) and the column's contact that still acts
     * (chain_result_column_pending), each when it keeps the run going */
    const char *col = chain_result_column_pending(r);
    const char *wall = r->wall_done ? "" : r->wall_pending ? r->wall_pending : "bead 1 still at the wall";
    if (r->wall_done && !col[0])
        col = "the column's own contacts still closed or closing";
    return gw_warnings_add(list,
                           "the collision had not ended at t_max = %.6g s (%s%s%s): %s are those at t_max; raise --t-max",
                           r->t_end, wall, wall[0] && col[0] ? "; " : "", col,
                           r->wall_done ? "the final velocities, eps_eff, eps_col and N_s"
                                        : "F_max, tau_N, the final velocities and the restitution");
}

/* a count no study gives ("9 of 5 collisions", a negative total): written as
 * given with GW_OK before the thirty-ninth pass */
static int counts_bad(int unfinished, int total)
{
    return unfinished < 0 || total < 0 || unfinished > total;
}

int gw_chain_unfinished_warnings(int unfinished, int total, char **list)
{
    if (counts_bad(unfinished, total))
        return GW_EINVAL;
    if (unfinished == 0)
        return GW_OK;
    return gw_warnings_add(list,
                           "%d of %d collisions had not ended at t_max (a contact still closed or closing): their "
                           "tau_N, restitution and what is fitted over them are those at t_max; raise --t-max",
                           unfinished, total);
}

int chain_held_warnings(int held, int total, const char *left_out, const char *undecided, char **list)
{
    if (held <= 0)
        return GW_OK;
    const int u = undecided && *undecided;
    return gw_warnings_add(list,
                           "%d of %d collisions were held by gravity (the column fell back onto the wall before its "
                           "collision ended): their F_max, tau_max, tau_N and restitution are undecided, those at "
                           "that time, and %s leave them out%s%s; raise --vimp or lower --gravity",
                           held, total, left_out, u ? "; undecided: " : "", u ? undecided : "");
}

void chain_list_speed(char *buf, size_t size, int *count, double v)
{
    size_t len = strlen(buf);
    if (len + 32 >= size) { /* room for one more and the mark */
        if (len + 6 < size && (len < 3 || strcmp(buf + len - 3, "...") != 0))
            gw_snprintf(buf + len, size - len, ", ...");
        return;
    }
    gw_snprintf(buf + len, size - len, "%s%.4g", *count ? ", " : "", v);
    (*count)++;
}

int gw_chain_softwall_warnings(int unfinished, int total, char **list)
{
    if (counts_bad(unfinished, total))
        return GW_EINVAL;
    if (unfinished == 0) /* F_max and tau_max: the wall's contact, the column's own may still be busy */
        return GW_OK;
    return gw_warnings_add(list,
                           "%d of %d collisions were still at the wall at t_max: their F_max and tau_max may not "
                           "be final; raise --t-max",
                           unfinished, total);
}

int gw_chain_dispersion_warnings(const gw_chain_disp_result *r, char **list)
{
    if (!r)
        return GW_OK;
    if (r->n_resolved == 0) /* the ridge error is NaN (JSON null): say why */
        return gw_warnings_add(list, "no wavenumber resolved: the spectrum shows no ridge (an --f0 so small that it "
                                     "underflows, a --dt-out too fine for --t-samples, or a --min-bins near "
                                     "half of --t-samples)");
    if (!isnan(r->c0_measured))
        return GW_OK;
    /* c0_measured (and c0_rel_err) NaN, JSON null, said nowhere: the
     * long-wave fit needs three resolved wavenumbers at qa <= 0.5, which a
     * short record (--dt-out 1e-6 at 512 samples: resolved from qa = 1.47)
     * or a short ring (n = 8: qa >= 0.785) does not give */
    int small = 0;
    for (int k = 0; r->qa && k < r->nq; k++)
        small += r->qa[k] <= 0.5;
    if (small < 3)
        return gw_warnings_add(list, "the long-wave speed c0 is undecided (c0_measured and c0_rel_err null): its "
                                     "fit needs 3 resolved wavenumbers at qa <= 0.5, and the chain's wavenumbers hold "
                                     "%d there; give more beads (--n)", small);
    return gw_warnings_add(list, "the long-wave speed c0 is undecided (c0_measured and c0_rel_err null): its fit "
                                 "needs 3 resolved wavenumbers at qa <= 0.5, and the ridge is resolved from qa = %.4g "
                                 "up; give a longer record (more --t-samples, or a larger --dt-out) or a lower "
                                 "--min-bins", r->qa_resolved_min);
}

int gw_chain_drop_result_warnings(const gw_chain_drop_result *r, char **list)
{
    return chain_drop_warnings(r, NULL, NULL, list);
}

/* The drop's chatter on a sensor body (gw_chain_drop_result's chatter_kind),
 * in chain's one text; o the run's settings (NULL: the rerun named by its
 * rule, rk4's or the tolerances') */
static int drop_chatter_warning(const gw_chain_drop_result *r, const gw_chain_run_opts *o, char **list)
{
    const int kind = r->chatter_kind;
    if (kind <= GW_CHAIN_CHATTER_NONE || kind > GW_CHAIN_CHATTER_FAILED)
        return GW_OK;
    /* what was done for the method used, as the studies' line says it (the
     * library's call, o NULL, said "10 times tighter tolerances (under rk4:
     * half the step)" under either): the result's chatter_rerun */
    const int step = o ? o->solver == gw_solver_rk4 : r->chatter_rerun == GW_CHAIN_RERUN_STEP;
    char how[96] = "10 times tighter tolerances (rtol and atol)", flags[96] = "10 times tighter --rtol and --atol";
    if (o) {
        gw_solver_params sp = o->sp;
        chain_chatter_rerun(o->solver ? o->solver : gw_solver_cvode, r->run_dt, &sp, how, sizeof how, flags,
                            sizeof flags);
    } else if (r->chatter_rerun < GW_CHAIN_RERUN_NONE || r->chatter_rerun > GW_CHAIN_RERUN_STEP) {
        /* a result filled by hand whose chatter_rerun is none of
         * GW_CHAIN_RERUN_*: it was worded with the tolerances' rule (99,
         * INT_MIN), a rerun the result does not record */
        gw_snprintf(how, sizeof how, "a setting the result does not name (its chatter_rerun, %d, is invalid)",
                    r->chatter_rerun);
        gw_snprintf(flags, sizeof flags, "another setting (the result's chatter_rerun, %d, is invalid)",
                    r->chatter_rerun);
    } else if (step && r->run_dt > 0 && isfinite(r->run_dt)) {
        gw_solver_params sp = gw_solver_params_default();
        chain_chatter_rerun(gw_solver_rk4, r->run_dt, &sp, how, sizeof how, flags, sizeof flags);
    } else if (step) {
        /* a result filled by hand whose run_dt is no step: it was halved into
         * "compare a run at --dt nan (half the step)" (-1: --dt -0.5, 0: --dt
         * 0, inf: "rk4's step halved, inf s") */
        char dt[32];
        gw_num_text(dt, sizeof dt, r->run_dt);
        gw_snprintf(how, sizeof how, "rk4's step halved (the result's run_dt, %s, is not a step)", dt);
        gw_snprintf(flags, sizeof flags, "--dt half the drop's rk4 step (its run_dt, %s, is not one)", dt);
    } else {
        /* the tolerances' values (10 times looser at the 1e-15 floor), as the
         * program's line names them: the drop's first collision ran at the
         * drop's tolerances and keeps them (chain_result_tolerances); a
         * result that holds none (filled by hand) keeps the rule's words */
        gw_solver_params sp = gw_solver_params_default();
        if (chain_result_tolerances(&r->first, &sp.rtol, &sp.atol))
            chain_chatter_rerun(gw_solver_cvode, r->run_dt, &sp, how, sizeof how, flags, sizeof flags);
    }
    /* the first collision ends half way to bead 1's second contact, which is
     * the drop's next impact: its own check counts one contact (1 in each of
     * 30 drops of 3 beads over sensor masses 1e-6 to 1e-1 kg and stiffnesses
     * 1e3 to 1e8 N/m, up to 1291 episodes; chain's run under the same gravity
     * counts the drop's episodes as its wall contacts: 44, 206, 12, 38, 11, 5),
     * and the chatter is checked here, over the impacts (the first impact's
     * F_max moved by at most 1.6e-7 in their reruns) */
    char where[160], ending[512], text[CHAIN_CHATTER_TEXT + 160];
    gw_snprintf(where, sizeof where, " in %.6g ms; the first collision ends half way to the second, its check seeing "
                "one contact: the chatter is the drop's, checked over its impacts", r->t_end * 1e3);
    const char *less = "a stiffer, heavier or damped sensor body (--sensor-stiffness, --sensor-mass, --sensor-damping) "
                       "chatters less";
    if (kind == GW_CHAIN_CHATTER_COSTLY)
        gw_snprintf(ending, sizeof ending, "so that the impacts, their peaks and the energy ledger move with dt-out "
                    "and the tolerances, and this drop (%.3g steps times %d bodies, above the %.3g a rerun %s) was "
                    "not run again to measure by how much: compare a run at %s; %s",
                    (double)r->stats.steps, r->n, step ? GW_CHAIN_DROP_CHATTER_RK4_WORK : GW_CHAIN_CHATTER_WORK,
                    step ? "at half rk4's step, twice the drop's steps, is made within" : "is made within", flags,
                    less);
    else if (kind == GW_CHAIN_CHATTER_MOVED && !(r->chatter_spread >= 0))
        /* a result filled by hand (a NaN or negative spread was said "up to
         * nan"): the rerun moved them, by how much is not recorded */
        gw_snprintf(ending, sizeof ending, "and a rerun at %s changed the impacts' F_max by an amount the result "
                    "does not record (its chatter_spread is %s, not a spread): the impacts, their peaks and the "
                    "energy ledger are uncertain by an unknown amount, and move with dt-out and the tolerances; %s",
                    how, isnan(r->chatter_spread) ? "not a number" : "negative", less);
    else if (kind == GW_CHAIN_CHATTER_MOVED && r->chatter_spread >= 1)
        gw_snprintf(ending, sizeof ending, "and a rerun at %s gave other impacts (their count or contact episodes "
                    "differ): the impacts, their peaks and the energy ledger are one of the chatter's outcomes, "
                    "and move with dt-out and the tolerances (each impact's chatter: the change of its F_max); %s",
                    how, less);
    else if (kind == GW_CHAIN_CHATTER_MOVED)
        gw_snprintf(ending, sizeof ending, "and a rerun at %s changed the impacts' F_max by up to %.3g of their "
                    "value (each impact's chatter): the impacts, their peaks and the energy ledger are uncertain "
                    "by that much, and move with dt-out and the tolerances; %s", how, r->chatter_spread, less);
    else
        gw_snprintf(ending, sizeof ending, "and its rerun at %s failed, the spread unmeasured; %s", how, less);
    chain_chatter_text(text, sizeof text, r->n_episodes, where, ending);
    return gw_warnings_add(list, "%s", text);
}

/* Bead 1 at rest on the sensor at the run's end: the column's kinetic energy
 * below a millionth of e0 (the drop's 1/2 M v_imp^2), its speeds a thousandth
 * of v_imp as chain_bead_stopped's. A bead that came to rest after its
 * bounces (drop --damping kk --gamma 1e6), or that gravity turned back onto
 * the sensor in its first impact (hc --alpha 1e3), was told "raise --t-max",
 * which never ends that contact. */
static int drop_at_rest(const gw_chain_drop_result *r)
{
    return r->open_at_t_max && r->e0 > 0 && r->e_end.kinetic < 1e-6 * r->e0;
}

int chain_drop_warnings(const gw_chain_drop_result *r, const gw_chain_params *p, const gw_chain_run_opts *o,
                        char **list)
{
    if (!r)
        return GW_OK;
    int rc = dt_warning(r->run_dt_given, r->run_dt, r->run_dt_max, list);
    if (rc == GW_OK)
        rc = overlap_warning(&r->first, list); /* the first collision, the drop's hardest */
    const char *first = chain_result_chatter(&r->first); /* the first collision's, checked as chain's */
    if (rc == GW_OK && first[0])
        rc = gw_warnings_add(list, "the first collision: %s", first);
    if (rc == GW_OK)
        rc = drop_chatter_warning(r, o, list);
    if (rc != GW_OK || !(r->first_cut || r->open_at_t_max))
        return rc;
    if (drop_at_rest(r)) {
        char damp[160] = "", named[128];
        if (damping_on(p))
            gw_snprintf(damp, sizeof damp, ", the contact damping (%s) having taken its rebound",
                        damping_named(named, sizeof named, p));
        return gw_warnings_add(list, "bead 1 was at rest on the sensor at t_max = %.6g s%s: its weight holds it "
                               "there, and no t-max ends that contact (the last impact's t_end and v_out are NaN, "
                               "its peaks final)%s", r->t_end, damp,
                               r->first_cut ? "; the first collision never ended: its tau_N and restitution are "
                                              "those at t_max" : "");
    }
    /* NaN in the result, null in the program's JSON: "NaN" is what the result holds for every caller */
    return gw_warnings_add(list, "the run was cut at t_max = %.6g s: %s%s%s; raise --t-max", r->t_end,
                           r->first_cut ? "the first collision had not ended (its F_max, tau_N and restitution are "
                                          "those at t_max)" : "",
                           r->first_cut && r->open_at_t_max ? "; " : "",
                           r->open_at_t_max ? "bead 1 was still on the sensor (the last impact's t_end and v_out are "
                                              "NaN, its peaks those so far)" : "");
}

/* Of a steel column on a steel wall (the default), max_disagreement measured
 * over --vimp 0.01 to 5 (the same at every speed: Hertz scaling): N = 3..8
 * 0.006, 5..12 0.014, 8..12 0.009, 5..20 0.034, 5..40 0.098, 20..60 0.108,
 * 5..80 0.112, 100..120 0.115 (4R/T_q drifting down in long columns,
 * physics.md 1.3); kk restitution 0.9 0.031 and 0.3 0.110, hc 0.5 0.170
 * (N = 5..20). Twice the long columns' drift: beyond it the estimators
 * measure different things (a soft wall's columns below N_d 0.64, a wall
 * stiffer than the bead contacts over N = 8..12 0.29, hc 0.2 0.43). */
#define WS_DISAGREE_MAX 0.2
/* rms residual of tau_N about its line, over T_q: steel on steel 0.03 over
 * N = 8..12 and 5..20, 0.19 over 5..40 (its curvature); on a rigid wall
 * (the --wall-material rigid steel column) 0.88 over 8..12, 0.73 over
 * 5..20: tau_N jumps by about T_q from size to size */
#define WS_TQ_SCATTER_MAX 0.5

int chain_wavespeed_warnings(const gw_chain_wavespeed_outcome *o, const gw_chain_params *p, const chain_ws_cause *c,
                             char **list)
{
    if (!o)
        return GW_OK;
    /* period null (and c2, beta_period with it) at speeds whose columns were
     * not held (the held columns' warning names those): said by the text
     * only, the JSON and Python had null and no reason */
    char list_v[128] = "";
    int n_list = 0;
    for (int iv = 0; iv < o->nv; iv++) {
        if (!isnan(o->period[iv]))
            continue;
        int held = 0;
        for (int j = 0; j < o->nn; j++)
            held |= o->held[iv * o->nn + j];
        if (!held)
            chain_list_speed(list_v, sizeof list_v, &n_list, o->v_imp[iv]);
    }
    int rc = GW_OK;
    if (n_list && o->n_max < 10)
        rc = gw_warnings_add(list, "the wall-force period is not measured (period, c2 and beta_period null): it is "
                             "read on columns of 10 beads or more, and the longest here has %d; give --n up to 10 "
                             "or more", o->n_max);
    else if (n_list)
        rc = gw_warnings_add(list, "the wall-force period is not measured at v_imp = %s m/s (period null, and c2 "
                             "and beta_period with it): no column of %d to %d beads showed two wall-force maxima",
                             list_v, o->n_min > 10 ? o->n_min : 10, o->n_max);
    if (rc != GW_OK || !c || c->iv < 0 || !(o->max_disagreement > WS_DISAGREE_MAX))
        return rc;
    const int iv = c->iv;
    char why[512];
    if (c->soft && c->plateau < 0)
        gw_snprintf(why, sizeof why, "the wall is soft (K = %.3g N/m^1.5, below K_c = %.3g) and every column is "
                    "below its saturation number N_d: F_max still grows, %.4g N at N = %d to %.4g N at N = %d, so "
                    "tau_N measures the wall more than the wave; by F.8, N_d >= %d beads (tau_max(%d)/T_q), run "
                    "the fit over columns from N_d (granwave softwall locates it)",
                    p->kwall, c->k_c, c->f_lo, o->n_min, c->f_hi, o->n_max, c->n_d_min, o->n_max);
    else if (c->soft)
        gw_snprintf(why, sizeof why, "the wall is soft (K = %.3g N/m^1.5, below K_c = %.3g) and the columns "
                    "N = %d..%d lie below its saturation number N_d = %d, where F_max is still growing: tau_N "
                    "measures the wall more than the wave there; give --n from %d", p->kwall, c->k_c, o->n_min,
                    c->plateau - 1, c->plateau, c->plateau);
    else if (c->tq_scatter > WS_TQ_SCATTER_MAX && p->sensor.mass > 0)
        /* not the wall's stiffness: --sensor-mass 1e-3 --sensor-stiffness 1e6
         * over N = 8..12 scatters by 0.94 T_q on the default steel wall
         * (K/k = 1.41, 0.03 without the body), and the text said "as on a
         * wall much stiffer than the bead contacts, K/k = 1.41" */
        gw_snprintf(why, sizeof why, "tau_N is not a line over N = %d..%d (its rms residual is %.2g T_q: the last "
                    "contact opens at times that jump from size to size) with the sensor as a body under the wall "
                    "(--sensor-mass %.3g kg on --sensor-stiffness %.3g N/m, its own period %.3g T_q), which moves "
                    "with the column; 4R/T_q is that scatter's: measure the wave speed on the rigid sensor (no "
                    "--sensor-mass)", o->n_min, o->n_max, c->tq_scatter, p->sensor.mass, p->sensor.stiffness,
                    2.0 * M_PI * sqrt(p->sensor.mass / p->sensor.stiffness) / o->t_q[iv]);
    else if (c->tq_scatter > WS_TQ_SCATTER_MAX)
        gw_snprintf(why, sizeof why, "tau_N is not a line over N = %d..%d (its rms residual is %.2g T_q: the last "
                    "contact opens at times that jump from size to size, as on a wall much stiffer than the bead "
                    "contacts, K/k = %.3g), so 4R/T_q is that scatter's; fit over more sizes",
                    o->n_min, o->n_max, c->tq_scatter, p->kwall / p->k);
    else if (p->damping == GW_DAMP_KUWABARA_KONO || p->damping == GW_DAMP_HUNT_CROSSLEY)
        gw_snprintf(why, sizeof why, "the contact damping (damping %s) weakens the front along the column, and "
                    "each estimator reads it at another place", p->damping == GW_DAMP_KUWABARA_KONO ? "kk" : "hc");
    else
        gw_snprintf(why, sizeof why, "the cause is not one the study recognises (not a soft wall's columns below "
                    "N_d, nor a scattered tau_N)");
    return gw_warnings_add(list, "the front-speed estimators disagree by %.3g (max_disagreement; at v_imp = %g m/s "
                           "4R/T_q %.4g, front %.4g, group/sqrt(3/2) %.4g m/s), beyond %.2g (twice the 0.115 of a "
                           "steel column on a steel wall up to N = 120): %s", o->max_disagreement, o->v_imp[iv], o->v_tq[iv],
                           o->v_front[iv], o->v_group_front[iv], WS_DISAGREE_MAX, why);
}

/* chain --n 20 --rtol 1e-4 --atol 1e-4 ended with a relative energy error of
 * 0.6 % and said nothing while energy-tol was off (its default). The bound:
 * the default tolerances give 5.4e-10 (chain --n 20, rtol 1e-12), and the
 * layer's runs 3.4e-5 (rk4) and 1.4e-6 (CVODE); 1e-3 (0.1 %) stands 30 times
 * above the largest of them and below what a loose tolerance gives (6e-3 at
 * rtol = atol = 1e-4, 9.9e-4 at 1e-5). rk4's line names the step the run
 * took (run_dt), not the dt given: a run given --dt 1e-9 that ran at
 * 3.35e-13 s was told "the rk4 step dt = 1e-09 s is too coarse". */
int chain_energy_warning(double energy_error, double run_dt, const gw_chain_run_opts *o, char **list)
{
    if (!o || o->energy_tol > 0 || !(energy_error > GW_CHAIN_ENERGY_WARN))
        return GW_OK;
    const char *name = o->solver ? gw_solver_type_name(o->solver) : "cvode";
    if (name && strcmp(name, "rk4") == 0)
        return gw_warnings_add(list, "the relative energy error reached %.3g (%.3g %%, above %g): the rk4 step dt = "
                               "%g s is too coarse to trust the run's numbers: lower --dt, or set --energy-tol to "
                               "stop at a bound", energy_error, 100 * energy_error, GW_CHAIN_ENERGY_WARN,
                               run_dt > 0 ? run_dt : o->sp.dt);
    return gw_warnings_add(list, "the relative energy error reached %.3g (%.3g %%, above %g) at rtol = %g, atol = %g: "
                           "the tolerances are too loose to trust the run's numbers: tighten --rtol and --atol, or "
                           "set --energy-tol to stop at a bound", energy_error, 100 * energy_error,
                           GW_CHAIN_ENERGY_WARN, o->sp.rtol, o->sp.atol);
}
