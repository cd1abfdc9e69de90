/*
 * chain_material.c: materials, Hertz coefficients and the single-bead closed forms.
 *
 *   k = (4/3) E* sqrt(R_eff), 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2,
 *   1/R_eff = 1/R1 + 1/R2 (a plane has 1/R = 0)                 (F.12, F.3)
 *   tau_1 = c_tau (5m/(4K))^(2/5) v^(-1/5), c_tau = (4/5) B(2/5, 1/2)   (F.2)
 *   d_max = (5 m v^2 / (4K))^(2/5),  F_max = K d_max^(3/2)        (F.13, F.14)
 *   T_q = 2 (m/k)^(2/5) v^(-1/5)                                 (F.17, F.29)
 *   K_c = (c_tau/4)^(5/2) (5k/4)                                   (F.22)
 *   sheets: K_eff = (5m/4) (c_tau / (2 tau_max1 v^(1/5)))^(5/2), from the
 *   measured tau_max(N = 1) = tau_1/2 (F.21) at v = sqrt(2 g 2.9 mm)
 * Units: Pa, m, kg, m/s, s, N/m^1.5.
 */
#include <math.h>
#include <string.h>

#include <gsl/gsl_sf_gamma.h>

#include "chain_material.h"
#include "gw_chain.h"
#include "gw_locale.h"

/* The experiment's steel is from docs/physics.md; the others are handbook values
 * (room temperature, order-of-magnitude accuracy) for exploring soft walls. */
static const gw_material materials[] = {
    {"steel", 21.6e10, 0.276, 7850.0},
    {"rigid", INFINITY, 0.0, INFINITY},
    {"brass", 1.00e11, 0.34, 8500.0},
    {"aluminium", 7.0e10, 0.33, 2700.0},
    {"glass", 6.3e10, 0.22, 2500.0},
    {"pmma", 3.0e9, 0.37, 1180.0},
    {"pvc", 3.0e9, 0.38, 1400.0},
};

const gw_material *gw_material_find(const char *name)
{
    for (size_t i = 0; name && i < sizeof materials / sizeof materials[0]; i++)
        if (strcmp(materials[i].name, name) == 0)
            return &materials[i];
    return NULL;
}

const char *gw_material_names(void)
{
    return "steel, rigid, brass, aluminium, glass, pmma, pvc";
}

int chain_material_ok(const gw_material *m)
{
    return m && m->young > 0 && m->poisson > -1 && m->poisson <= 0.5; /* NaN fails each */
}

int chain_material_check(const gw_material *m, const char *what, gw_err *err)
{
    if (!m)
        return gw_err_set(err, GW_EINVAL, "%s: no material (NULL)", what);
    const char *name = m->name ? m->name : "(unnamed)";
    char xs[32]; /* the value as given, not rounded onto an end (a Poisson ratio 0.5000001 was "0.5") */
    if (!(m->young > 0))
        return gw_err_set(err, GW_EINVAL, "%s '%s': Young modulus %s Pa is not in (0, inf] (inf: rigid)", what,
                          name, gw_num_text(xs, sizeof xs, m->young));
    if (!(m->poisson > -1 && m->poisson <= 0.5))
        return gw_err_set(err, GW_EINVAL, "%s '%s': Poisson ratio %s is not in (-1, 0.5]", what, name,
                          gw_num_text(xs, sizeof xs, m->poisson));
    return GW_OK;
}

static double compliance(const gw_material *m)
{
    return isinf(m->young) ? 0.0 : (1.0 - m->poisson * m->poisson) / m->young;
}

double gw_hertz_coefficient(double r1, const gw_material *m1, double r2,
                            const gw_material *m2)
{
    /* no material, or one no contact has (a Young modulus not above 0, a
     * Poisson ratio outside (-1, 0.5], NaN), or a radius not above 0: no
     * coefficient (they gave INFINITY, a rigid contact) */
    if (!chain_material_ok(m1) || !chain_material_ok(m2) || !(r1 > 0) || !(r2 > 0))
        return NAN;
    double inv_r = (isinf(r1) ? 0.0 : 1.0 / r1) + (isinf(r2) ? 0.0 : 1.0 / r2);
    double c = compliance(m1) + compliance(m2);
    if (!(inv_r > 0) || !(c > 0))
        return INFINITY;
    return 4.0 / 3.0 / c * sqrt(1.0 / inv_r);
}

double gw_chain_tau_constant(void)
{
    return 0.8 * gsl_sf_beta(0.4, 0.5);
}

/* The closed forms' domain: a mass in (0, inf), a Hertz coefficient in
 * (0, inf] and a speed in [0, inf]. A negative mass with a negative K gave a
 * finite contact time, peak overlap and force (their ratio is positive), a
 * speed of -1 m/s the peak overlap and force of +1 m/s where tau_1 was NaN,
 * and a mass of 0 a zero overlap; each is NaN now, as gw_chain_kc of a
 * negative k. */
static int closed_form_domain(double m, double K, double v)
{
    return m > 0 && isfinite(m) && K > 0 && v >= 0;
}

/* 5 m / (4 K) as written where 4 K and 5 m are doubles (bit for bit as
 * before), else as 1.25 (m / K): a finite K above 4.5e307 made 4 K inf and
 * tau_1 0 s (k = 1.8e308 was refused as "dt-max: a step of 0 s ... fewer
 * beads or a shorter run"), and a mass above 3.6e307 kg 5 m inf (the
 * fiftieth pass). A rigid K = inf still gives 0. */
static double mass_ratio(double m, double K)
{
    return isfinite(4.0 * K) && isfinite(5.0 * m) ? 5.0 * m / (4.0 * K) : 1.25 * (m / K);
}

double gw_chain_tau1(double m, double K, double v)
{
    if (!closed_form_domain(m, K, v))
        return NAN;
    return gw_chain_tau_constant() * pow(mass_ratio(m, K), 0.4) * pow(v, -0.2);
}

double gw_chain_dmax1(double m, double K, double v)
{
    if (!closed_form_domain(m, K, v))
        return NAN;
    const double x = 5.0 * m * v * v / (4.0 * K);
    /* v^2 or 5 m v^2 beyond the doubles, or 4 K: v^(4/5) apart (v_imp 1e200
     * m/s of a steel bead: 1.6e155 m, was inf); an underflow stays 0 (the
     * column's check names it) */
    if (isfinite(x) && isfinite(4.0 * K))
        return pow(x, 0.4);
    return pow(mass_ratio(m, K), 0.4) * pow(v, 0.8);
}

/* F_max = K d_max^(3/2) = K^(2/5) (5 m v^2 / 4)^(3/5): written so, a rigid wall
 * (K = inf) gives the limit, inf for v > 0 and 0 at v = 0 (K d^(3/2) was
 * inf * 0 = NaN there, session 42) */
double gw_chain_fmax1(double m, double K, double v)
{
    if (!closed_form_domain(m, K, v))
        return NAN;
    if (v == 0)
        return 0.0;
    return pow(K, 0.4) * pow(1.25 * m * v * v, 0.6);
}

double gw_chain_tq_theory(double m, double k, double v)
{
    if (!closed_form_domain(m, k, v))
        return NAN;
    return 2.0 * pow(m / k, 0.4) * pow(v, -0.2);
}

double gw_chain_kc(double k)
{
    if (!(k >= 0)) /* a negative k gave a negative K_c */
        return NAN;
    return pow(gw_chain_tau_constant() / 4.0, 2.5) * 1.25 * k;
}

/* Falcon et al. 1998, Table 2 (docs/physics.md 1.7): sheets glued on the sensor,
 * h = 2.9 mm. tau_max(N = 1) is the input of the K_eff fit; N_d and tau_max(N_d)
 * are kept for comparison with the model. The material constants (storage modulus
 * at kHz, Poisson ratio, yield or crushing stress, loss factor) are approximate
 * handbook values, chosen before any comparison with Table 2; docs/sheets.md gives
 * their sources and ranges. The paper does not name the tape: it is modelled as
 * its rigid-PVC backing (the adhesive film neglected). Beech is loaded across the
 * grain; cardboard through its thickness (both strongly anisotropic: an isotropic
 * layer is a rough stand-in). */
static const gw_sheet sheets[] = {
    {"none", 17, 1, 0, 0.0, 17, 0, "no sheet (steel sensor)", 0, 0, 0, 0},
    {"brass", 47.5, 2, 0, 1.2e-3, 46, 0, "brass CuZn37", 100e9, 0.34, 200e6, 0},
    {"tape", 47.5, 4, 0, 0.3e-3, 112, 0, "rigid PVC (tape backing)", 3.0e9, 0.38, 0, 0.02},
    {"pvc", 67.5, 6, 1, 1.0e-3, 171, 19, "rigid PVC", 3.0e9, 0.38, 0, 0.02},
    {"pmma", 69, 8, 1, 1.0e-3, 228, 11, "PMMA", 3.3e9, 0.37, 0, 0.06},
    {"cardboard2", 191, 11, 1, 0.5e-3, 396, 21, "paperboard, through-thickness", 20e6, 0.1, 0, 0.1},
    {"beech", 127.5, 15, 1, 2.0e-3, 468, 26, "beech across the grain", 0.9e9, 0.3, 7e6, 0},
    {"cardboard1", 227, 22, 2, 0.8e-3, 743, 23, "paperboard, through-thickness", 20e6, 0.1, 0, 0.1},
    {"rubber", 221, 28, 4, 1.0e-3, 950, 57, "natural rubber", 4e6, 0.499, 0, 0.1},
};

int gw_sheet_count(void)
{
    return (int)(sizeof sheets / sizeof sheets[0]);
}

const gw_sheet *gw_sheet_get(int i)
{
    return i >= 0 && i < gw_sheet_count() ? &sheets[i] : NULL;
}

const gw_sheet *gw_sheet_find(const char *name)
{
    for (int i = 0; name && i < gw_sheet_count(); i++)
        if (strcmp(sheets[i].name, name) == 0)
            return &sheets[i];
    return NULL;
}

double gw_sheet_kwall(const gw_sheet *s, double m)
{
    /* K_eff is proportional to m: a negative mass gave a negative wall
     * coefficient (-4.3e11 N/m^1.5 at -1 kg on brass), a mass of 0 a wall of
     * no stiffness */
    if (!s || !(m > 0) || !isfinite(m))
        return NAN;
    double v = sqrt(2 * GW_CHAIN_G_EARTH * 2.9e-3);
    return 1.25 * m * pow(gw_chain_tau_constant() / (2e-6 * s->tau_max1_us * pow(v, 0.2)), 2.5);
}
