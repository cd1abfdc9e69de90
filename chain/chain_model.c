/*
 * chain_model.c: the bead column as an ODE system (docs/physics.md 1.1, eq. F.11).
 *
 *   m_i x_i'' = F_i - F_(i-1) + m_i g,   F_i = k_i d_i^(3/2) [d_i > 0],
 *   d_i = x_(i+1) - x_i,   F_(-1) = F_wall = K x_0^(3/2) [x_0 > 0]   (0-based)
 *
 * Damping (docs/physics.md 1.5), force clamped at >= 0:
 *   Kuwabara-Kono  F = k d^(3/2) + gamma d^(1/2) d'
 *   Hunt-Crossley  F = k d^(3/2) (1 + (3/2) alpha d')
 * The dissipated power sum (F_el - F) (-d') is integrated as an extra state so the
 * energy ledger is closed by integration, not inferred.
 * Energies: kinetic (1/2) m v^2, elastic (2/5) k d^(5/2), gravity -m g x.
 * General model (any option of the wall law, sensor body or guide friction; the
 * default model keeps the lean path of chain_rhs_lean.c, results unchanged; chain_general.c):
 *   wall overlap  D = x_0 - x_s, force F(D, D', internal states) (chain_wall.c)
 *   sensor body   M_s x_s'' = F - k_s x_s - c_s x_s';  it reads k_s x_s + c_s x_s'
 *   guide         m_i x_i'' += -(f_c tanh(v_i/v_reg) + c_g v_i)
 *   ledger        dE_d/dt = c_s x_s'^2 + sum_i (f_c tanh(v_i/v_reg) + c_g v_i) v_i
 *                 (+ contact damping); dW/dt = F D' for a plastic or viscoelastic
 *                 wall (its stored part is the law's recoverable energy)
 * Units: SI (m, s, kg, N, N/m^1.5, J).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chain_model.h"
#include "gw_locale.h"


/* Damped forces: dv/dt from contacts (and dE_d/dt) added to yd or stored. */
static void chain_forces(const gw_chain *c, const double *y, double *yd, int add)
{
    const int n = c->n;
    const double *m1 = c->minv, *kc = c->kc;
    double x0 = y[0];
    double fprev = 0.0;
    double pd = 0.0;
    if (x0 > 0)
        fprev = damped_force(c, c->kwall, c->gwall, x0, y[1], &pd);
    for (int i = 0; i < n; i++) {
        double f = 0.0;
        if (i < n - 1) {
            double d = y[2 * i + 2] - y[2 * i];
            if (d > 0)
                f = damped_force(c, kc[i], c->gam[i], d, y[2 * i + 3] - y[2 * i + 1], &pd);
        }
        double a = (f - fprev) * m1[i];
        yd[2 * i + 1] = add ? yd[2 * i + 1] + a : a;
        fprev = f;
    }
    yd[2 * n] = add ? yd[2 * n] + pd : pd;
}

/* Kinematic part: dx/dt = v, dv/dt = g. */
static void chain_kinematics(const gw_chain *c, const double *y, double *yd)
{
    const double g = c->p.gravity;
    for (int i = 0; i < c->n; i++) {
        yd[2 * i] = y[2 * i + 1];
        yd[2 * i + 1] = g;
    }
    if (c->p.damping != GW_DAMP_NONE)
        yd[2 * c->n] = 0.0;
}

static int chain_rhs(double t, const double *y, double *yd, void *P)
{
    (void)t;
    const gw_chain *c = P;
    if (c->p.damping == GW_DAMP_NONE) {
        chain_lean_rhs(c, y, yd, c->p.gravity, 1);
        return 0;
    }
    chain_kinematics(c, y, yd);
    chain_forces(c, y, yd, 1);
    return 0;
}

/* The undamped rhs on components [i0, i1) (gw_system.rhs_range; i0 even):
 * beads i0/2 .. (i1+1)/2 - 1, the same values as chain_rhs; reads y from
 * bead i0/2 - 1 to bead (i1+1)/2 + 3 (halo 8 components: the 4-wide loop's
 * look-ahead, so that it runs to the range's end). */
static void chain_rhs_range(double t, const double *y, double *yd, long i0, long i1, void *P)
{
    (void)t;
    const gw_chain *c = P;
    chain_lean_range(c, y, yd, (int)(i0 / 2), (int)((i1 + 1) / 2), c->p.gravity);
}

static int chain_rhs_ex(double t, const double *y, double *yd, void *P)
{
    (void)t;
    chain_kinematics(P, y, yd);
    return 0;
}

static int chain_rhs_im(double t, const double *y, double *yd, void *P)
{
    (void)t;
    const gw_chain *c = P;
    if (c->p.damping == GW_DAMP_NONE) {
        chain_lean_rhs(c, y, yd, 0.0, 0);
        return 0;
    }
    for (int i = 0; i < c->n; i++)
        yd[2 * i] = 0.0;
    chain_forces(c, y, yd, 0);
    return 0;
}

/* dF/dd and dF/dd' of one contact (zero when open or clamped). */
static void contact_partials(const gw_chain *c, double k, double gam, double d, double dd,
                             double *fd, double *fv)
{
    *fd = *fv = 0.0;
    if (!(d > 0))
        return;
    double sd = sqrt(d);
    switch (c->p.damping) {
    case GW_DAMP_NONE:
        *fd = 1.5 * k * sd;
        break;
    case GW_DAMP_KUWABARA_KONO:
        if (k * d * sd + gam * sd * dd > 0) {
            *fd = 1.5 * k * sd + 0.5 * gam * dd / sd;
            *fv = gam * sd;
        }
        break;
    case GW_DAMP_HUNT_CROSSLEY:
        if (1.0 + 1.5 * c->p.alpha * dd > 0) {
            *fd = 1.5 * k * sd * (1.0 + 1.5 * c->p.alpha * dd);
            *fv = 1.5 * c->p.alpha * k * d * sd;
        }
        break;
    }
}

/* Banded Jacobian. Row of a_i: F_i depends on (x_i, x_(i+1), v_i, v_(i+1)),
 * F_(i-1) on (x_(i-1), x_i, v_(i-1), v_i). The dissipated-energy row (full) is
 * left out: it does not feed back into the dynamics. */
static int chain_jac(double t, const double *y, const double *f, gw_band *J, void *P)
{
    (void)t;
    (void)f;
    const gw_chain *c = P;
    const int n = c->n;
    double wd, wv; /* partials of the force below bead i (wall or contact i-1) */
    if (c->general) { /* here: a layer or Hertz wall without extra states */
        double pd = 0.0;
        chain_general_wall_force(c, y, &wd, &wv, &pd);
        if (!c->wl.layer)
            contact_partials(c, c->kwall, c->gwall, y[0], y[1], &wd, &wv);
    } else {
        contact_partials(c, c->kwall, c->gwall, y[0], y[1], &wd, &wv);
    }
    const int guide = c->p.guide.coulomb > 0 || c->p.guide.viscous > 0;
    for (int i = 0; i < n; i++) {
        long xi = 2 * i, vi = 2 * i + 1;
        gw_band_set(J, xi, vi, 1.0);
        double cd = 0.0, cv = 0.0;
        if (i < n - 1)
            contact_partials(c, c->kc[i], c->gam[i], y[xi + 2] - y[xi], y[vi + 2] - y[vi],
                             &cd, &cv);
        double m1 = c->minv[i];
        /* a_i = (F_i - F_(i-1)) / m_i */
        gw_band_set(J, vi, xi, -(cd + wd) * m1);
        double gv = 0.0;
        if (guide)
            chain_guide_force(c, y[vi], &gv);
        gw_band_set(J, vi, vi, -(cv + wv + gv) * m1);
        if (i < n - 1) {
            gw_band_set(J, vi, xi + 2, cd * m1);
            gw_band_set(J, vi, vi + 2, cv * m1);
        }
        if (i > 0) {
            gw_band_set(J, vi, xi - 2, wd * m1);
            gw_band_set(J, vi, vi - 2, wv * m1);
        }
        wd = cd;
        wv = cv;
    }
    return 0;
}

static int chain_roots(double t, const double *y, double *g, void *P)
{
    (void)t;
    const gw_chain *c = P;
    const int n = c->n;
    g[0] = y[0];
    for (int i = 0; i < n - 1; i++)
        g[1 + i] = y[2 * i + 2] - y[2 * i];
    g[n] = c->p.damping == GW_DAMP_NONE ? y[1] : chain_force_rate(c, t, y);
    return 0;
}

/* The force-maximum root. Where F is a function of the overlap alone (the
 * undamped Hertz wall, an elastic, layered or plastic wall law) its maxima are
 * the overlap's: R = D' (v_0 for the default wall). A sensor body without
 * damping reads k_s x_s: R = v_s. Otherwise F also depends on the rate or on
 * internal states, and a zero of D' is not where F peaks (Kuwabara-Kono with
 * e = 0.9: the force at D' = 0 is 0.3 % below the peak, which the samples then
 * caught only as closely as --dt-out allowed):
 *   Hunt-Crossley  F = K x^(3/2) (1 + (3/2) alpha v)
 *       R = dF/dt / sqrt(x) = (3/2) K [v (1 + (3/2) alpha v) + alpha x a]
 *   Kuwabara-Kono  F = K x^(3/2) + gamma_w x^(1/2) v
 *       R = sqrt(x) dF/dt = x ((3/2) K v + gamma_w a) + gamma_w v^2 / 2
 * (x = x_0 > 0, else its limit at 0+, v = v_0, a = dv_0/dt from the equations
 * of motion), and for the general model (a damped sensor body, a viscoelastic
 * wall, a damped wall law) R = (F(y + h y') - F(y - h y')) / (2h), the
 * derivative along the motion, with h = 1e-6 of the overlap scale over v_imp
 * (a contact time's 1e-6: truncation and rounding both below 1e-10 of the
 * contact time in the root's position; F_max is second order in it). Where F
 * is clamped at 0 on both sides (the end of a damped contact) R = D', which has
 * the same sign there and no stretch of zeros for the root finders. */
double chain_force_rate(const gw_chain *c, double t, const double *y)
{
    if (!c->general) {
        if (c->p.damping == GW_DAMP_NONE)
            return y[1];
        double x = y[0] > 0 ? y[0] : 0.0, v = y[1], pd = 0.0, fw = 0.0, f1 = 0.0;
        if (x > 0)
            fw = damped_force(c, c->kwall, c->gwall, x, v, &pd);
        if (c->n > 1 && y[2] - y[0] > 0)
            f1 = damped_force(c, c->kc[0], c->gam[0], y[2] - y[0], y[3] - y[1], &pd);
        double a = (f1 - fw) * c->minv[0] + c->p.gravity;
        if (c->p.damping == GW_DAMP_KUWABARA_KONO)
            return x * (1.5 * c->kwall * v + c->gwall * a) + 0.5 * c->gwall * v * v;
        return 1.5 * c->kwall * (v * (1.0 + 1.5 * c->p.alpha * v) + c->p.alpha * x * a);
    }
    if (c->i_sens >= 0 && !(c->p.sensor.damping > 0))
        return y[c->i_sens + 1];
    if (c->i_sens < 0 && c->wl.narms == 0 && (c->wl.plastic || c->wl.layer || c->p.damping == GW_DAMP_NONE))
        return gw_chain_wall_gap_rate(c, y);
    const long dim = c->sys.dim;
    double *yd = c->work, *yp = c->work + dim;
    chain_general_rhs(t, y, yd, (void *)c);
    double h = 1e-6 * c->scale[0] / c->scale[1];
    for (long i = 0; i < dim; i++)
        yp[i] = y[i] + h * yd[i];
    double fp = gw_chain_wall_force(c, yp), cp = gw_chain_wall_contact_force(c, yp);
    for (long i = 0; i < dim; i++)
        yp[i] = y[i] - h * yd[i];
    double fm = gw_chain_wall_force(c, yp), cm = gw_chain_wall_contact_force(c, yp);
    /* bead 1 off the wall: its maxima are not sought (only falling zeros with
     * the contact closed are), and a damped sensor body's reading k_s x_s +
     * c_s x_s' relaxes there as the small difference of two large terms, its
     * rate noise over the body's fast mode c_s/M: the root chattered (drop
     * --sensor-mass 1e-3 --sensor-stiffness 1e9 --sensor-damping 1e8: 1.65e6
     * events in 0.1 ms, a run of hours). The gap's rate, as for a rigid
     * sensor. */
    if ((fp == 0 && fm == 0) || (cp == 0 && cm == 0))
        return gw_chain_wall_gap_rate(c, y);
    return (fp - fm) / (2.0 * h);
}

/* A maximum or minimum of the sensor's reading changes nothing in the model,
 * and restarting the solver there only threw away its history (a multistep
 * method starts again at order 1 from a tiny step). A sensor body rings at
 * sqrt(k_s/M), and its reading's extrema came every half period where the
 * collision's own force is flat: --n 3 --sensor-mass 1e-7 --sensor-stiffness
 * 1e14 under cvode bdf restarted 577,963 times, 26.5 million steps, 80 s.
 * The root finders go on from a root without a restart (the event is located
 * as before). They stop with an error ("root found at and very near t") when
 * an event function is exactly 0 at the root and just after it, which a
 * restart takes as inactive instead: a heavily damped body's force rate, a
 * difference quotient, came out 0 at some of its roots (--sensor-mass 1e-3
 * --sensor-stiffness 1e9 --sensor-damping 1e9 under arkode dirk). Any
 * event function at 0 restarts as before. */
int chain_roots_need_reset(const gw_chain *c, double t, const double *y, const int *roots)
{
    const int n = c->n, im = gw_chain_force_max_root(c);
    for (int k = 0; k < c->sys.nroots; k++)
        if (k != im && roots[k] != 0)
            return 1;
    /* on a plastic wall with no sensor body the force-maximum root is the
     * overlap's rate, whose zero ends D_max's tracking (its rate dd s(x) for
     * dd > 0 only): a kink, restarted at as a contact is */
    if (c->i_dmax >= 0 && c->i_sens < 0 && roots[im] != 0)
        return 1;
    /* the event functions as chain_roots and chain_general_roots give them */
    if (gw_chain_wall_gap(c, y) == 0 || chain_force_rate(c, t, y) == 0)
        return 1;
    for (int k = 1; k < n; k++)
        if (y[2 * k] - y[2 * k - 2] == 0)
            return 1;
    return c->i_sens >= 0 && gw_chain_wall_gap_rate(c, y) == 0;
}

gw_chain_params gw_chain_params_default(void)
{
    gw_chain_params p;
    memset(&p, 0, sizeof p);
    const gw_material *steel = gw_material_find("steel");
    p.n = 1;
    p.v_imp = 0.3;
    p.radius = 4e-3;
    p.mass = 4.0 / 3.0 * M_PI * pow(p.radius, 3) * steel->density;
    p.k = gw_hertz_coefficient(p.radius, steel, p.radius, steel);
    p.kwall = gw_hertz_coefficient(p.radius, steel, INFINITY, steel);
    p.damping = GW_DAMP_NONE;
    return p;
}

int chain_n_check(int n, gw_err *err)
{
    if (n < 1)
        return gw_err_set(err, GW_EINVAL, "n: number of beads must be >= 1, got %d", n);
    if (n > 50000000)
        return gw_err_set(err, GW_EINVAL, "n: %d beads exceed the supported 5e7", n);
    return GW_OK;
}

/* A model value that must be positive and finite, and a normal double: a
 * subnormal mass (4.9e-324 kg) or speed passed gw_check_positive and failed
 * at the run as "solver: scale[0] = 0 must be finite and > 0", naming no
 * input (the parameter rows refuse subnormals as well). */
#define SUBNORMAL_TEXT " (a subnormal number, below 2.2251e-308, the smallest normal double)"
static int model_positive(double x, const char *name, gw_err *err)
{
    int rc = gw_check_positive(x, name, err);
    if (rc == GW_OK && x < DBL_MIN)
        rc = gw_err_set(err, GW_EINVAL, "%s: must be a positive finite number, got %g%s", name, x, SUBNORMAL_TEXT);
    return rc;
}

/* The column's other scales, each a finite normal double: its kinetic energy
 * (sum m v^2 / 2 at the speed scale), bead 1's wall force K x^(3/2) and
 * overlap, and the time scales the run's steps follow (T_c, the step scale).
 * Above or below the doubles, finite inputs failed at the run naming none or
 * another (the fiftieth pass): v_imp 1e200 m/s or a mass of 1.8e308 kg (5 m
 * v^2 overflows) as "solver: scale[0] = inf must be finite" or "solver:
 * dt_max must be >= 0, got inf", k = 1.8e308 as "dt-max: a step of 0 s
 * needs about inf steps ... fewer beads or a shorter run", 1000 beads of
 * 1e306 kg at 1 m/s with an energy of inf J. The scale-free column still runs
 * wherever they are doubles (v_imp 1e-150, masses 1e-300 or 1e200 kg). */
static int chain_scales_check(const gw_chain_params *p, double vs, double xs, gw_err *err)
{
    const double m0 = p->masses ? p->masses[0] : p->mass;
    double e0 = 0;
    for (int i = 0; i < p->n; i++)
        e0 += 0.5 * (p->masses ? p->masses[i] : p->mass) * vs * vs;
    const struct {
        const char *what, *unit;
        double v;
    } s[] = {{"bead 1's overlap scale (5 m v^2 / 4 kwall)^(2/5)", "m", xs},
             {"the column's kinetic energy", "J", e0},
             {"bead 1's wall force scale kwall x^(3/2)", "N", p->kwall * xs * sqrt(xs)},
             {"the bead-bead time scale (m/k)^(2/5) v^(-1/5)", "s", gw_chain_time_scale(p)},
             {"the time scale the steps resolve (gw_chain_step_scale)", "s", gw_chain_step_scale(p)}};
    for (size_t i = 0; i < sizeof s / sizeof s[0]; i++)
        if (!(s[i].v >= DBL_MIN && isfinite(s[i].v)))
            return gw_err_set(err, GW_EINVAL, "v_imp, mass, k, kwall: %s is %g %s (v_imp %g m/s, mass %g kg, k %g "
                              "N/m^1.5, kwall %g N/m^1.5, %d beads), outside the normal doubles (2.2251e-308 to "
                              "1.7977e+308): the column cannot be run in doubles; give values nearer the commands' "
                              "ranges (granwave chain --help)",
                              s[i].what, s[i].v, s[i].unit, p->v_imp, m0, p->kc && p->n > 1 ? p->kc[0] : p->k,
                              p->kwall, p->n);
    return GW_OK;
}

/* A value of a closed range, and a normal double or 0: a subnormal yield
 * pressure (4.9e-324 Pa) ran as a wall of no strength, a subnormal sensor
 * mass was refused as a sensor body ringing at inf rad/s naming the stiffness
 * (the fiftieth pass); the model's positive values were held so in the
 * forty-ninth (model_positive). */
static int model_range(double x, const char *name, double lo, double hi, gw_err *err)
{
    int rc = gw_check_range(x, name, lo, hi, err);
    if (rc == GW_OK && x != 0 && fabs(x) < DBL_MIN)
        rc = gw_err_set(err, GW_EINVAL, "%s: %g is a subnormal number (below 2.2251e-308, the smallest normal "
                        "double): give 0 or a normal number", name, x);
    return rc;
}

int gw_chain_params_validate(const gw_chain_params *p, gw_err *err)
{
    if (!p)
        return gw_err_set(err, GW_EINVAL, "gw_chain_params_validate: p is NULL");
    int rc;
    if ((rc = chain_n_check(p->n, err)) != GW_OK)
        return rc;
    if ((rc = model_positive(p->v_imp, "v_imp (impact velocity, m/s)", err)) != GW_OK)
        return rc;
    if (!p->masses && (rc = model_positive(p->mass, "mass (kg)", err)) != GW_OK)
        return rc;
    if (!p->kc && (rc = model_positive(p->k, "k (bead-bead Hertz coefficient, N/m^1.5)", err)) != GW_OK)
        return rc;
    if ((rc = model_positive(p->kwall, "kwall (wall Hertz coefficient, N/m^1.5)", err)) != GW_OK)
        return rc;
    if ((rc = model_positive(p->radius, "radius (m)", err)) != GW_OK)
        return rc;
    if ((rc = model_range(p->gravity, "gravity (m/s^2)", -1e4, 1e4, err)) != GW_OK)
        return rc;
    for (int i = 0; p->masses && i < p->n; i++)
        if (!(p->masses[i] >= DBL_MIN) || !isfinite(p->masses[i]))
            return gw_err_set(err, GW_EINVAL, "masses[%d]: must be positive and finite%s", i,
                              p->masses[i] > 0 && p->masses[i] < DBL_MIN ? SUBNORMAL_TEXT : "");
    for (int i = 0; p->kc && i < p->n - 1; i++)
        if (!(p->kc[i] >= DBL_MIN) || !isfinite(p->kc[i]))
            return gw_err_set(err, GW_EINVAL, "kc[%d]: must be positive and finite%s", i,
                              p->kc[i] > 0 && p->kc[i] < DBL_MIN ? SUBNORMAL_TEXT : "");
    switch (p->damping) {
    case GW_DAMP_NONE:
        break;
    case GW_DAMP_KUWABARA_KONO:
        if ((rc = model_range(p->gamma, "gamma (Kuwabara-Kono, N s/m^1.5)", 0, GW_CHAIN_GAMMA_MAX, err)) != GW_OK)
            return rc;
        break;
    case GW_DAMP_HUNT_CROSSLEY:
        if ((rc = model_range(p->alpha, "alpha (Hunt-Crossley, s/m)", 0, GW_CHAIN_ALPHA_MAX, err)) != GW_OK)
            return rc;
        break;
    default:
        return gw_err_set(err, GW_EINVAL, "damping: unknown model %d", (int)p->damping);
    }
    const gw_chain_wall *w = &p->wall;
    if ((rc = model_range(w->yield_pressure, "wall yield_pressure (Pa)", 0, 1e12, err)) != GW_OK ||
        (rc = model_range(w->loss, "wall loss (tan delta)", 0, 10, err)) != GW_OK ||
        (rc = model_range(w->tau_min, "wall tau_min (s)", 0, 1e3, err)) != GW_OK ||
        (rc = model_range(w->tau_max, "wall tau_max (s)", 0, 1e3, err)) != GW_OK)
        return rc;
    /* a relaxation time is 0 (the default arms) or physical (gw_chain.h) */
    for (int k = 0; k < 2; k++) {
        const double tau = k ? w->tau_max : w->tau_min;
        if (tau > 0 && tau < GW_CHAIN_WALL_TAU_MIN)
            return gw_err_set(err, GW_EINVAL, "wall %s (s): a Maxwell arm of %g s, faster than any relaxation of a "
                              "solid (atomic vibrations take 0.01-1 ps): give 0 for the default arms (1e-5 to 1e-3 s) "
                              "or a time in [%g, 1e3] s", k ? "tau_max" : "tau_min", tau, GW_CHAIN_WALL_TAU_MIN);
    }
    if (w->yield_pressure > 0 && (w->layer || w->loss > 0))
        return gw_err_set(err, GW_EINVAL, "wall: the plastic law (yield_pressure) works on the Hertz "
                          "law alone, not with a layer or a loss");
    if (w->loss > 0) {
        double a, b;
        chain_wall_arms(w, &a, &b);
        if (!(a <= b) || b / a > 1e6)
            return gw_err_set(err, GW_EINVAL, "wall: relaxation times need tau_min <= tau_max <= 1e6 "
                              "tau_min (got %g, %g s)", a, b);
    }
    const gw_chain_sensor *sn = &p->sensor;
    if ((rc = model_range(sn->mass, "sensor mass (kg)", 0, 1e3, err)) != GW_OK ||
        (rc = model_range(sn->stiffness, "sensor stiffness (N/m)", 0, 1e16, err)) != GW_OK ||
        (rc = model_range(sn->damping, "sensor damping (N s/m)", 0, 1e12, err)) != GW_OK)
        return rc;
    if (sn->mass > 0 && !(sn->stiffness > 0))
        return gw_err_set(err, GW_EINVAL, "sensor stiffness: a sensor body (mass > 0) needs a stiffness > 0");
    if (!(sn->mass > 0) && (sn->stiffness > 0 || sn->damping > 0))
        return gw_err_set(err, GW_EINVAL, "sensor mass: stiffness and damping need a sensor mass > 0");
    const gw_chain_guide *g = &p->guide;
    if ((rc = model_range(g->coulomb, "guide coulomb friction (N)", 0, 1e6, err)) != GW_OK ||
        (rc = model_range(g->viscous, "guide viscous friction (N s/m)", 0, 1e9, err)) != GW_OK ||
        (rc = model_range(g->v_reg, "guide v_reg (m/s)", 0, 1e3, err)) != GW_OK)
        return rc;
    /* The solvers' absolute tolerance is atol times the states' scales
     * (gw_chain_create): bead 1's overlap scale (m/K)^(2/5) v^(4/5) at the
     * column's speed scale. Below the normal doubles it is 0 or loses its
     * digits: v_imp 1e-160 (steel) passed here and failed at the run as
     * "solver: scale[0] = 0 must be finite and > 0", naming no input (the
     * column runs, scale-free, down to 1e-150 m/s; the commands take 1e-9). */
    const double vs = chain_speed_scale(p), xs = gw_chain_dmax1(p->masses ? p->masses[0] : p->mass, p->kwall, vs);
    if (!(xs >= DBL_MIN))
        return gw_err_set(err, GW_EINVAL, "v_imp (impact velocity, m/s): %g gives bead 1 an overlap scale of %g m "
                          "(mass %g kg, kwall %g N/m^1.5), below the normal doubles (2.2251e-308): the solvers' "
                          "error weights underflow; give a faster impact (the commands take at least %g m/s)",
                          p->v_imp, xs, p->masses ? p->masses[0] : p->mass, p->kwall, GW_CHAIN_VIMP_MIN);
    return chain_scales_check(p, vs, xs, err);
}

static int is_general(const gw_chain_params *p)
{
    return p->wall.layer || p->wall.yield_pressure > 0 || p->wall.loss > 0 || p->sensor.mass > 0 ||
           p->guide.coulomb > 0 || p->guide.viscous > 0;
}

/* The column the scales are of: n in [1, 5e7] beads, each mass and bead-bead
 * coefficient positive and finite, a wall coefficient above 0 (inf: rigid)
 * and an impact speed positive and finite, as gw_chain_params_validate asks.
 * Without it the scales were finite for no column: masses {1, -1, NaN} gave
 * a step scale of 1.47e-4 s, n = 0 a time scale, a NaN mass was covered by
 * the RK4 study (session 42). */
static int pos_finite(double x)
{
    return x > 0 && isfinite(x);
}

int chain_scales_domain(const gw_chain_params *p)
{
    if (!p || chain_n_check(p->n, NULL) != GW_OK || !pos_finite(p->v_imp) || !(p->kwall > 0))
        return 0;
    if (p->masses) {
        for (int i = 0; i < p->n; i++)
            if (!pos_finite(p->masses[i]))
                return 0;
    } else if (!pos_finite(p->mass))
        return 0;
    if (p->kc) {
        for (int i = 0; i + 1 < p->n; i++)
            if (!pos_finite(p->kc[i]))
                return 0;
        return p->n > 1 || pos_finite(p->k);
    }
    return pos_finite(p->k);
}

double gw_chain_time_scale(const gw_chain_params *p)
{
    if (!chain_scales_domain(p))
        return NAN;
    double m = p->masses ? p->masses[0] : p->mass;
    double k = p->kc && p->n > 1 ? p->kc[0] : p->k;
    return pow(m / k, 0.4) * pow(p->v_imp, -0.2);
}

/* The column's scales for its expected length (chain_collision_length): the
 * largest bead-to-bead T_c and the heaviest bead's wall contact time */
static void column_scales(const gw_chain_params *p, double *tc, double *tau1)
{
    const double v = p->v_imp, m0 = p->masses ? p->masses[0] : p->mass;
    double t = gw_chain_time_scale(p), mmax = m0;
    if (p->masses)
        for (int i = 0; i < p->n; i++)
            mmax = fmax(mmax, p->masses[i]);
    if (p->masses || p->kc)
        for (int i = 0; i + 1 < p->n; i++) {
            const double a = p->masses ? p->masses[i] : p->mass, b = p->masses ? p->masses[i + 1] : p->mass;
            const double k = p->kc ? p->kc[i] : p->k;
            t = fmax(t, pow(fmax(a, b) / k, 0.4) * pow(v, -0.2));
        }
    *tc = t;
    *tau1 = gw_chain_tau1(mmax, p->kwall, v);
}

double chain_sensor_carry_time(const gw_chain_params *p)
{
    if (!(p->sensor.mass > 0 && p->sensor.stiffness > 0))
        return 0.0;
    double mt = p->sensor.mass;
    for (int i = 0; i < p->n; i++)
        mt += p->masses ? p->masses[i] : p->mass;
    return M_PI * sqrt(mt / p->sensor.stiffness);
}

double chain_collision_length(const gw_chain_params *p, double *tc)
{
    double tc_col = 0, tau1_col = 0;
    column_scales(p, &tc_col, &tau1_col);
    if (tc)
        *tc = tc_col;
    return p->n * 2.0 * tc_col + tau1_col + chain_sensor_carry_time(p);
}

/* The reduced mass of bead 1 on the wall: the bead's own on a rigid sensor, with
 * the sensor's mass M on a sensor body. */
static double wall_reduced_mass(const gw_chain_params *p)
{
    const double m0 = p->masses ? p->masses[0] : p->mass, M = p->sensor.mass;
    return M > 0 ? m0 * M / (m0 + M) : m0;
}

/* The speed the column's scales are taken at: v_imp, or under gravity at
 * least the speed v_g whose binary wall collision peaks at the column's weight
 * W = g sum m (F_max = K (5 m v^2 / (4 K))^(3/5) = W, bead 1's mass m on the
 * wall's K). Below it the column is carried by its weight and its contacts ring
 * at that scale, not at v_imp's. The plan's time scales (chain_collide_plan.c: chain
 * --n 3 --gravity 1e4 --vimp 1e-9 --mass 1e3 --k 1e3 --kwall 1e3 planned t_max
 * 1.2e4 s and a largest step of 33 s from v_imp, and took 1.8e7 steps) and the
 * states' scales of the solvers' absolute tolerance (gw_chain_create: at v_imp
 * 1e-9 the velocities' atol was 1e-21 m/s for a column ringing at 1 m/s, and
 * CVODE's BDF closed the ledger of --n 30 --gravity 1e4 only to 2.3e-4 in 6.8e5
 * steps) are both taken here. Above it (every run where gravity is a
 * correction) v_imp. */
double chain_speed_scale(const gw_chain_params *p)
{
    if (!(p->gravity > 0) || !(p->kwall > 0))
        return p->v_imp;
    const double m0 = p->masses ? p->masses[0] : p->mass;
    double mt = 0;
    for (int i = 0; i < p->n; i++)
        mt += p->masses ? p->masses[i] : p->mass;
    const double w = p->gravity * mt, vg = sqrt(4.0 * p->kwall / (5.0 * m0) * pow(w / p->kwall, 5.0 / 3.0));
    return isfinite(vg) && vg > p->v_imp ? vg : p->v_imp;
}

double chain_energy_rel_error(const gw_chain *c, const gw_chain_energy *e, double e0, double *wg)
{
    if (-e->gravity > *wg)
        *wg = -e->gravity;
    return fabs(e->total - e0) / fmax(e0 + *wg, c->e_scale);
}

int chain_blown_up(const gw_chain *c, const double *y, double energy_error, const gw_solver_type *type,
                   const char *who, double t, gw_err *err)
{
    const long dim = c->sys.dim;
    char what[64] = "";
    for (long i = 0; i < dim && !what[0]; i++)
        if (!isfinite(y[i]))
            gw_snprintf(what, sizeof what, "state %ld of %ld not finite", i, dim);
    if (!what[0] && energy_error > 1)
        gw_snprintf(what, sizeof what, "relative energy error %.3g", energy_error);
    if (!what[0])
        return GW_OK;
    /* the advice is the backend's: an adaptive one is not helped by dt, nor by
     * "use cvode". A viscoelastic wall's arms are time scales too (rk4's
     * default step follows the fastest, chain_rk4_default_dt; a given dt may
     * not): arms of 1e-8 to 1e-6 s blew up with advice that did not name them */
    char arms[96] = "";
    if (c->p.wall.loss > 0)
        gw_snprintf(arms, sizeof arms, "the wall's Maxwell arms (the fastest %.3g s), ",
                    c->p.wall.tau_min > 0 ? c->p.wall.tau_min : 1e-5);
    return gw_err_set(err, GW_ESOLVER, "%s: the solution blew up at t = %.9g s (%s): the step is too long for the "
                      "model's fastest time scale (a contact, the sensor body, %sdamping or friction); %s", who, t,
                      what, arms, type == gw_solver_rk4 ? "lower dt (or dt-max), or use cvode" : "lower dt-max, rtol or atol");
}

double chain_contact_tau_min(const gw_chain_params *p, double v)
{
    const double m0 = p->masses ? p->masses[0] : p->mass;
    /* bead 1 on bead 2 of the same mass (the uniform column's pair) and on the wall */
    double t = gw_chain_tau1(0.5 * m0, p->kc && p->n > 1 ? p->kc[0] : p->k, v);
    if (p->kwall > 0)
        t = fmin(t, gw_chain_tau1(wall_reduced_mass(p), p->kwall, v));
    for (int i = 0; p->masses && i + 1 < p->n; i++) { /* every pair of unequal beads */
        const double a = p->masses[i], b = p->masses[i + 1];
        const double ti = gw_chain_tau1(a * b / (a + b), p->kc ? p->kc[i] : p->k, v);
        if (ti < t * (1 - 1e-12))
            t = ti;
    }
    return t;
}

/* How fast the column's fastest bead rings while its contacts hold it
 * (chain_model.h). The column's kinetic energy at the speed scale, E = sum m
 * v_s^2 / 2, held in one contact of coefficient K makes at most the force
 * K^(2/5) (5 E / 2)^(3/5); bead i is held by its contacts below (the wall's for
 * bead 1) and above (none for the top bead) at most at the force of the softer
 * one, F_i, and rings there at omega_i^2 = (3/2) F_i^(1/3) (K_below^(2/3) +
 * K_above^(2/3)) / m_i (a Hertz contact's stiffness dF/dd at force F is
 * (3/2) K^(2/3) F^(1/3)). The period returned is 2 pi over the largest
 * omega_i, *fastest that bead. Measured: bead 1 of --radii 1e-3,1 (1e9 times
 * lighter than bead 2) rings at 1.52 us (the mean spacing of the wall force's
 * maxima) for 52.8 ms; this gives 1.21 us (F 6.9e5 N; F enters as F^(1/6)). */
double chain_ring_period(const gw_chain_params *p, int *fastest)
{
    const double v = chain_speed_scale(p);
    double e = 0;
    for (int i = 0; i < p->n; i++)
        e += 0.5 * (p->masses ? p->masses[i] : p->mass) * v * v;
    const double fe = pow(2.5 * e, 0.6);
    double w2 = 0;
    if (fastest)
        *fastest = 0;
    for (int i = 0; i < p->n; i++) {
        const double below = i == 0 ? fmax(p->kwall, 0) : p->kc ? p->kc[i - 1] : p->k;
        const double above = i + 1 < p->n ? (p->kc ? p->kc[i] : p->k) : 0;
        const double m = p->masses ? p->masses[i] : p->mass;
        const double f = pow(above > 0 ? fmin(below, above) : below, 0.4) * fe;
        const double wi = 1.5 * cbrt(f) * (cbrt(below * below) + cbrt(above * above)) / m;
        if (wi > w2) {
            w2 = wi;
            if (fastest)
                *fastest = i;
        }
    }
    return w2 > 0 && isfinite(w2) ? 2 * M_PI / sqrt(w2) : INFINITY;
}

double gw_chain_step_scale(const gw_chain_params *p)
{
    if (!chain_scales_domain(p))
        return NAN;
    const double v = p->v_imp, tc = gw_chain_time_scale(p);
    double s = tc;
    /* T_c = (m/k)^(2/5) v^(-1/5) is (2 mu/k)^(2/5) v^(-1/5) of the pair of equal
     * beads (mu = m/2); every other contact scales by its tau_1 */
    const double m0 = p->masses ? p->masses[0] : p->mass;
    const double ref = gw_chain_tau1(0.5 * m0, p->kc && p->n > 1 ? p->kc[0] : p->k, v);
    const double t = chain_contact_tau_min(p, v);
    if (t < ref * (1 - 1e-12))
        s = tc * t / ref;
    /* the sensor body's own oscillation, 1/omega = sqrt(M/k_s) */
    if (p->sensor.mass > 0 && p->sensor.stiffness > 0)
        s = fmin(s, sqrt(p->sensor.mass / p->sensor.stiffness));
    /* relaxation times m/c of the beads' linear drags (chain_drag_rates; the
     * sensor body's drag bounds RK4's step on its own, chain_rk4_default_dt) */
    double r[CHAIN_DRAG_N];
    chain_drag_rates(p, r);
    const double rb = fmax(r[CHAIN_DRAG_GUIDE_VISCOUS] + r[CHAIN_DRAG_GUIDE_COULOMB], r[CHAIN_DRAG_CONTACT]);
    if (rb > 0)
        s = fmin(s, 0.5 / rb);
    return s;
}

const char *const chain_drag_flag[CHAIN_DRAG_N] = {"sensor-damping", "guide-viscous", "guide-friction", "damping"};

void chain_drag_rates(const gw_chain_params *p, double r[CHAIN_DRAG_N])
{
    const double v = p->v_imp, m0 = p->masses ? p->masses[0] : p->mass;
    double m_min = m0;
    for (int i = 0; p->masses && i < p->n; i++)
        m_min = fmin(m_min, p->masses[i]);
    for (int i = 0; i < CHAIN_DRAG_N; i++)
        r[i] = 0;
    if (p->sensor.mass > 0 && p->sensor.damping > 0)
        r[CHAIN_DRAG_SENSOR] = p->sensor.damping / p->sensor.mass;
    /* the guide's viscous friction, its Coulomb friction regularised over v_reg
     * (c = F / v_reg), and the contact damping at the binary overlap (KK: c =
     * gamma sqrt(d), HC: c = 1.5 alpha k d^1.5), on the lightest bead */
    r[CHAIN_DRAG_GUIDE_VISCOUS] = p->guide.viscous / m_min;
    if (p->guide.coulomb > 0)
        r[CHAIN_DRAG_GUIDE_COULOMB] = p->guide.coulomb / (p->guide.v_reg > 0 ? p->guide.v_reg : 1e-3 * v) / m_min;
    const double k = p->kc && p->n > 1 ? p->kc[0] : p->k, d = gw_chain_dmax1(0.5 * m_min, k, v);
    if (p->damping == GW_DAMP_KUWABARA_KONO)
        r[CHAIN_DRAG_CONTACT] = p->gamma * sqrt(d) / m_min;
    else if (p->damping == GW_DAMP_HUNT_CROSSLEY)
        r[CHAIN_DRAG_CONTACT] = 1.5 * p->alpha * k * d * sqrt(d) / m_min;
}

int gw_chain_create(const gw_chain_params *p, gw_chain **out, gw_err *err)
{
    if (!out)
        return gw_err_set(err, GW_EINVAL, "gw_chain_create: out is NULL");
    *out = NULL;
    if (!p)
        return gw_err_set(err, GW_EINVAL, "gw_chain_create: p is NULL");
    int rc = gw_chain_params_validate(p, err);
    if (rc != GW_OK)
        return rc;
    gw_chain *c = calloc(1, sizeof *c);
    const int n = p->n;
    const int general = is_general(p);
    chain_wall_law wl;
    if ((rc = chain_wall_law_init(&wl, p, err)) != GW_OK) {
        free(c);
        return rc;
    }
    long dim = 2L * n, i_diss = -1, i_work = -1, i_sens = -1, i_dmax = -1, i_q = -1;
    if (p->damping != GW_DAMP_NONE || p->sensor.damping > 0 || p->guide.coulomb > 0 || p->guide.viscous > 0)
        i_diss = dim++;
    if (wl.plastic || wl.narms > 0)
        i_work = dim++;
    if (p->sensor.mass > 0) {
        i_sens = dim;
        dim += 2;
    }
    if (wl.plastic)
        i_dmax = dim++;
    if (wl.narms > 0) {
        i_q = dim;
        dim += wl.narms;
    }
    if (c) {
        c->m = malloc((size_t)(4 * n) * sizeof *c->m);
        c->scale = malloc((size_t)dim * sizeof *c->scale);
        c->work = malloc(2 * (size_t)dim * sizeof *c->work);
    }
    if (!c || !c->m || !c->scale || !c->work) {
        gw_chain_free(c);
        return gw_err_set(err, GW_ENOMEM, "chain: out of memory for %d beads", n);
    }
    c->p = *p;
    c->p.masses = NULL;
    c->p.kc = NULL;
    c->n = n;
    c->minv = c->m + n;
    c->kc = c->m + 2 * n;
    c->gam = c->m + 3 * n;
    for (int i = 0; i < n; i++) {
        c->m[i] = p->masses ? p->masses[i] : p->mass;
        c->minv[i] = 1.0 / c->m[i];
    }
    for (int i = 0; i < n - 1; i++) {
        c->kc[i] = p->kc ? p->kc[i] : p->k;
        c->gam[i] = p->gamma * c->kc[i] / (p->kc ? p->kc[0] : p->k);
    }
    c->rhs_avx = chain_lean_avx();
    c->uniform = 1;
    for (int i = 1; i < n; i++)
        c->uniform &= c->minv[i] == c->minv[0] && c->kc[i - 1] == c->kc[0];
    c->kwall = p->kwall;
    c->gwall = p->gamma * p->kwall / (p->kc && n > 1 ? p->kc[0] : p->k);
    /* the states' scales (the solvers' absolute tolerance is atol times these)
     * at the column's speed scale: v_imp, or the speed its weight rings at */
    const double vs = chain_speed_scale(p);
    double xs = gw_chain_dmax1(c->m[0], p->kwall, vs);
    for (int i = 0; i < n; i++) {
        c->scale[2 * i] = xs;
        c->scale[2 * i + 1] = vs;
    }
    double e0 = 0;
    for (int i = 0; i < n; i++)
        e0 += 0.5 * c->m[i] * vs * vs;
    c->e_scale = vs > p->v_imp ? e0 : 0; /* the weight's ringing sets the scale */
    c->general = general;
    c->wl = wl;
    c->i_diss = i_diss;
    c->i_work = i_work;
    c->i_sens = i_sens;
    c->i_dmax = i_dmax;
    c->i_q = i_q;
    c->vreg = p->guide.v_reg > 0 ? p->guide.v_reg : 1e-3 * p->v_imp;
    double fs = p->kwall * xs * sqrt(xs);
    if (i_diss >= 0)
        c->scale[i_diss] = e0;
    if (i_work >= 0)
        c->scale[i_work] = e0;
    if (i_sens >= 0) {
        c->scale[i_sens] = fs / p->sensor.stiffness;
        /* the body reads k_s x_s + c_s v_s: an error in v_s shows c_s times
         * over in the reading, at most fs's at the speed fs / c_s (also the
         * body's own speed where its damping holds it). At v_imp, c_s = 1e9
         * let the reading err by 3e-4 N: arkode erk's F_max was 1.6e-6 above
         * cvode bdf's, bdf's own moved 5e-9 N between atol 1e-12 and 1e-14 */
        c->scale[i_sens + 1] = p->sensor.damping > 0 ? fmin(p->v_imp, fs / p->sensor.damping) : p->v_imp;
    }
    if (i_dmax >= 0)
        c->scale[i_dmax] = xs;
    c->dtrack = 1e-6 * xs;
    for (int j = 0; j < wl.narms; j++)
        c->scale[i_q + j] = fs;

    gw_system *s = &c->sys;
    s->dim = dim;
    s->rhs = general ? chain_general_rhs : chain_rhs;
    s->rhs_ex = general ? chain_general_rhs_ex : chain_rhs_ex;
    s->rhs_im = general ? chain_general_rhs_im : chain_rhs_im;
    s->jac = chain_jac;
    s->mu = 2;
    s->ml = 3;
    if (i_work >= 0 || i_sens >= 0) {
        /* The wall's and the sensor's states (W, x_s, v_s, D_max, q_j: k of
         * them) couple only to bead 1 and each other: ordered before the
         * beads, the band stays narrow (their rows reach bead 1 at k + 1, bead
         * 1's reach them at k + 1), where after the beads it was the whole
         * system (dim^2 memory, dim^3 a factorisation: 40 s at 100 beads on a
         * sensor body under cvode bdf). E_d, whose rate sums every contact, is
         * the ledger after the beads. Finite differences in that order. */
        const long lead0 = i_diss >= 0 ? i_diss + 1 : 2L * n, k = dim - lead0;
        s->jac = NULL;
        s->lead0 = lead0;
        s->nlead = k;
        s->nledger = i_diss >= 0;
        s->mu = k + 1 > 2 ? k + 1 : 2;
        s->ml = k + 1 > 3 ? k + 1 : 3;
    }
    /* the lean rhs is local: by ranges, CVODE Adams runs it in its vector passes */
    if (!general && p->damping == GW_DAMP_NONE && dim == 2L * n) {
        s->rhs_range = chain_rhs_range;
        s->rhs_halo = 8;
    }
    s->roots = general ? chain_general_roots : chain_roots;
    s->nroots = n + 1 + (i_sens >= 0);
    s->scale = c->scale;
    s->params = c;
    *out = c;
    return GW_OK;
}

void gw_chain_free(gw_chain *c)
{
    if (!c)
        return;
    free(c->m);
    free(c->scale);
    free(c->work);
    free(c);
}

const gw_system *gw_chain_system(const gw_chain *c)
{
    /* NULL: NULL (&c->sys of a NULL c was undefined behaviour, a sanitizer report) */
    return c ? &c->sys : NULL;
}

const gw_chain_params *gw_chain_get_params(const gw_chain *c)
{
    /* NULL: NULL (&c->p of a NULL c was undefined behaviour, a sanitizer report) */
    return c ? &c->p : NULL;
}

double gw_chain_bead_mass(const gw_chain *c, int i)
{
    if (!c || i < 0 || i >= c->n) /* no such bead */
        return NAN;
    return c->m[i];
}

void gw_chain_initial_state(const gw_chain *c, double *y)
{
    if (!c || !y)
        return;
    for (int i = 0; i < c->n; i++) {
        y[2 * i] = 0.0;
        y[2 * i + 1] = c->p.v_imp;
    }
    for (long i = 2L * c->n; i < c->sys.dim; i++)
        y[i] = 0.0;
}

double gw_chain_wall_force(const gw_chain *c, const double *y)
{
    if (!c || !y)
        return NAN;
    if (c->general) {
        if (c->i_sens >= 0)
            return c->p.sensor.stiffness * y[c->i_sens] + c->p.sensor.damping * y[c->i_sens + 1];
        return gw_chain_wall_contact_force(c, y);
    }
    double x = y[0];
    /* a NaN state is no state: NaN, never the open contact's plausible 0 N */
    if (isnan(x) || isnan(y[1]))
        return NAN;
    if (!(x > 0))
        return 0.0;
    if (c->p.damping == GW_DAMP_NONE)
        return c->kwall * x * sqrt(x);
    double pd = 0;
    return damped_force(c, c->kwall, c->gwall, x, y[1], &pd);
}

void chain_beads_energy(const gw_chain *c, const double *y, double *ke, double *el, double *pg)
{
    *ke = *el = *pg = 0;
    for (int i = 0; i < c->n; i++) {
        double v = y[2 * i + 1];
        *ke += 0.5 * c->m[i] * v * v;
        *pg -= c->m[i] * c->p.gravity * y[2 * i];
        if (i < c->n - 1) {
            double d = y[2 * i + 2] - y[2 * i];
            if (d > 0)
                *el += 0.4 * c->kc[i] * d * d * sqrt(d);
        }
    }
}

void gw_chain_energy_of(const gw_chain *c, const double *y, gw_chain_energy *e)
{
    if (!e)
        return;
    if (!c || !y) { /* no state: no energy */
        e->kinetic = e->elastic = e->gravity = e->dissipated = e->total = NAN;
        return;
    }
    /* a NaN anywhere in the state: every energy NaN (a NaN overlap fell to the
     * open contact's 0 J, the elastic energy then plausible) */
    for (long i = 0; i < c->sys.dim; i++)
        if (isnan(y[i])) {
            e->kinetic = e->elastic = e->gravity = e->dissipated = e->total = NAN;
            return;
        }
    if (c->general) {
        chain_general_energy(c, y, e);
        return;
    }
    const int n = c->n;
    double ke, el, pg;
    chain_beads_energy(c, y, &ke, &el, &pg);
    if (y[0] > 0)
        el += 0.4 * c->kwall * y[0] * y[0] * sqrt(y[0]);
    e->kinetic = ke;
    e->elastic = el;
    e->gravity = pg;
    e->dissipated = c->p.damping != GW_DAMP_NONE ? y[2 * n] : 0.0;
    e->total = ke + el + pg + e->dissipated;
}
