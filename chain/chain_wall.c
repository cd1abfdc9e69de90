/*
 * chain_wall.c: the wall's contact law beyond the Hertz spring.
 *
 * Elastic law f(d): Hertz K d^(3/2) or a bonded layer (chain_layer.c).
 * Elastic-perfectly plastic (Thornton, J. Appl. Mech. 64, 383 (1997)), on the
 * Hertz law with E* = 3K/(4 sqrt(R)):
 *   d <= d_y = R (pi p_y/(2E*))^2:  F = (4/3) E* sqrt(R) d^(3/2)
 *   loading beyond:                 F = F_y + pi p_y R (d - d_y)     (F <= pi p_y R d)
 *   unloading from (d_m, F_m):      F = (4/3) E* sqrt(R_p) (d - d_p)^(3/2),
 *     R_p = (4 E* / (3 F_m)) ((2 F_m + F_y)/(2 pi p_y))^(3/2),
 *     d_p = d_m - (3 F_m / (4 E* sqrt(R_p)))^(2/3)
 *   recovered energy (2/5) F (d - d_p); dissipated = loading work - recovered.
 * Viscoelastic (generalized Maxwell solid, relaxation modulus
 * E(t) = E_inf + sum_j D e^(-t/tau_j), tau_j one per decade in [tau_min, tau_max]),
 * in Lee-Radok form on the elastic law f_U scaled to the unrelaxed modulus E_U:
 *   F = max(0, w_inf f_U(d) + sum_j w_j q_j),  dq_j/dt = f_U'(d) d' - q_j/tau_j,
 *   w_inf = E_inf/E_U, w_j = D/E_U. D is set so that tan(delta) = E''/E' at the band
 *   centre w_c = 1/sqrt(tau_min tau_max) is the given loss, and f_U = law E_U/E'(w_c):
 *   the law's modulus is the storage modulus at w_c (handbook "dynamic" modulus).
 *   With a layer the scaling in E is exact for a rigid sphere (the layer's share
 *   of the contact compliance is > 0.98 for the polymer sheets on steel).
 * Units: SI (m, N, Pa, s).
 */
#include <math.h>
#include <string.h>

#include "chain_wall.h"

void gw_thornton_init(gw_thornton *t, double estar, double radius, double p_y)
{
    if (!t) /* nothing to set: a void call's NULL is a no-op, as the _free calls' */
        return;
    /* A law from a yield pressure, E* or radius not finite and > 0 is none:
     * its fields NaN, so every force it gives is NaN (a negative p_y gave a
     * negative force, E* = 0 a yield overlap of inf), the wall's own check
     * refuses such values before this */
    if (!(estar > 0 && radius > 0 && p_y > 0) || !isfinite(estar) || !isfinite(radius) || !isfinite(p_y))
        estar = radius = p_y = NAN;
    t->estar = estar;
    t->radius = radius;
    t->p_y = p_y;
    double r = M_PI * p_y / (2.0 * estar);
    t->d_y = radius * r * r;
    t->f_y = 4.0 / 3.0 * estar * sqrt(radius) * t->d_y * sqrt(t->d_y);
}

/* Peak force of loading to dm. */
static double thornton_loading(const gw_thornton *t, double dm)
{
    if (dm <= t->d_y)
        return 4.0 / 3.0 * t->estar * sqrt(t->radius) * dm * sqrt(dm);
    return t->f_y + M_PI * t->p_y * t->radius * (dm - t->d_y);
}

double gw_thornton_force(const gw_thornton *t, double d, double dmax, double *stiffness,
                         double *residual, double *energy)
{
    if (!t || isnan(d) || isnan(dmax)) { /* a NaN overlap fell to the unloaded branch: force 0 */
        if (stiffness)
            *stiffness = NAN;
        if (residual)
            *residual = NAN;
        if (energy)
            *energy = NAN;
        return NAN;
    }
    double dm = d > dmax ? d : dmax, rp = t->radius, dp = 0.0, f = 0.0, kd = 0.0;
    if (dm > t->d_y) {
        double fs = thornton_loading(t, dm);
        rp = 4.0 * t->estar / (3.0 * fs) * pow((2.0 * fs + t->f_y) / (2.0 * M_PI * t->p_y), 1.5);
        dp = dm - pow(3.0 * fs / (4.0 * t->estar * sqrt(rp)), 2.0 / 3.0);
        if (d >= dmax) { /* on the loading curve */
            f = fs;
            kd = M_PI * t->p_y * t->radius;
        }
    }
    if (d > dp && !(dm > t->d_y && d >= dmax)) {
        double u = d - dp, c = 4.0 / 3.0 * t->estar * sqrt(rp);
        f = c * u * sqrt(u);
        kd = 1.5 * c * sqrt(u);
    }
    if (stiffness)
        *stiffness = kd;
    if (residual)
        *residual = dp;
    if (energy)
        *energy = d > dp ? 0.4 * f * (d - dp) : 0.0;
    return f;
}

double gw_thornton_loading_work(const gw_thornton *t, double dmax)
{
    if (!t || isnan(dmax)) /* NULL was read (SIGSEGV), NaN was no loading: 0 J */
        return NAN;
    if (!(dmax > 0))
        return 0.0;
    double c = 4.0 / 3.0 * t->estar * sqrt(t->radius);
    if (dmax <= t->d_y)
        return 0.4 * c * dmax * dmax * sqrt(dmax);
    double x = dmax - t->d_y;
    return 0.4 * t->f_y * t->d_y + t->f_y * x + 0.5 * M_PI * t->p_y * t->radius * x * x;
}

int chain_wall_arms(const gw_chain_wall *wall, double *tau_min, double *tau_max)
{
    double a = wall->tau_min > 0 ? wall->tau_min : 1e-5;
    double b = wall->tau_max > 0 ? wall->tau_max : 1e-3;
    if (tau_min)
        *tau_min = a;
    if (tau_max)
        *tau_max = b;
    int n = 1 + (int)floor(log10(b / a) + 0.5);
    return n < 1 ? 1 : n > GW_WALL_MAX_ARMS ? GW_WALL_MAX_ARMS : n;
}

int chain_wall_law_init(chain_wall_law *w, const gw_chain_params *p, gw_err *err)
{
    memset(w, 0, sizeof *w);
    w->k = p->kwall;
    w->layer = p->wall.layer;
    w->scale = 1.0;
    w->w_inf = 1.0;
    if (p->wall.yield_pressure > 0) {
        w->plastic = 1;
        gw_thornton_init(&w->th, 3.0 * p->kwall / (4.0 * sqrt(p->radius)), p->radius,
                         p->wall.yield_pressure);
    }
    if (p->wall.loss > 0) {
        double a, b;
        int n = chain_wall_arms(&p->wall, &a, &b);
        /* the band centre 1/sqrt(a b) as 1/(sqrt(a) sqrt(b)): a b underflowed to 0
         * below about 1e-162 s each (wc infinite, every sum NaN: "tan(delta) = 10 is
         * beyond what 1 Maxwell arm(s) give (< -nan)", and any loss refused so) */
        double wc = 1.0 / (sqrt(a) * sqrt(b)), s1 = 0.0, s2 = 0.0;
        for (int j = 0; j < n; j++) {
            w->tau[j] = n > 1 ? a * pow(b / a, (double)j / (n - 1)) : a;
            double x = wc * w->tau[j];
            s1 += x * x / (1.0 + x * x);
            s2 += x / (1.0 + x * x);
        }
        double t = p->wall.loss;
        if (!(s2 - t * s1 > 0.02 * s2)) /* D = t/(s2 - t s1) blows up */
            return gw_err_set(err, GW_EINVAL, "wall loss: tan(delta) = %g is beyond what %d Maxwell "
                              "arm(s) give (< %.3g)", t, n, 0.98 * s2 / s1);
        double d = t / (s2 - t * s1), eu = 1.0 + n * d, ec = 1.0 + d * s1;
        w->narms = n;
        w->w_inf = 1.0 / eu;
        for (int j = 0; j < n; j++)
            w->w[j] = d / eu;
        w->scale = eu / ec;
    }
    return GW_OK;
}

double chain_wall_elastic(const chain_wall_law *w, double d, double *kd)
{
    if (!(d > 0)) {
        *kd = 0.0;
        return 0.0;
    }
    double f;
    if (w->layer) {
        f = gw_layer_law_force(w->layer, d, kd);
    } else {
        double sd = sqrt(d);
        f = w->k * d * sd;
        *kd = 1.5 * w->k * sd;
    }
    *kd *= w->scale;
    return f * w->scale;
}

double chain_wall_elastic_energy(const chain_wall_law *w, double d)
{
    if (!(d > 0))
        return 0.0;
    if (w->layer)
        return w->scale * gw_layer_law_energy(w->layer, d);
    return w->scale * 0.4 * w->k * d * d * sqrt(d);
}

double chain_wall_elastic_overlap(const chain_wall_law *w, double f)
{
    if (!(f > 0))
        return 0.0;
    if (w->layer)
        return gw_layer_law_overlap(w->layer, f / w->scale);
    return pow(f / (w->scale * w->k), 2.0 / 3.0);
}
