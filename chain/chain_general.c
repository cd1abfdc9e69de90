/*
 * chain_general.c: the column model with the options beyond the papers' model
 * (issue 19): a wall contact law (chain_wall.c), the force sensor as a body and
 * friction of the beads on their guide.
 *
 *   wall overlap  D = x_0 - x_s,  force F(D, D', internal states)   (chain_wall.c)
 *   beads         m_i x_i'' = F_i - F_(i-1) + m_i g - (f_c tanh(v_i/v_reg) + c_g v_i),
 *                 F_(-1) = F (the wall), contact damping as chain_model.c
 *   sensor body   M_s x_s'' = F - k_s x_s - c_s x_s';  it reads k_s x_s + c_s x_s'
 *   ledger        dE_d/dt = c_s x_s'^2 + sum_i (f_c tanh(v_i/v_reg) + c_g v_i) v_i
 *                 + contact damping;  dW/dt = F D' for a plastic or viscoelastic wall,
 *                 whose recoverable part (Thornton's unloading energy; for the
 *                 Maxwell arms, each arm's spring at the overlap carrying its force)
 *                 is counted as elastic and the rest as dissipated
 *   plastic wall  D_max follows D through a C^1 ramp (see dtrack in chain_model.h),
 *                 carried as its excess E = D_max - D >= 0 (E' = D_max' - D')
 *   viscoelastic  dq_j/dt = f_U'(D) D' - q_j/tau_j
 * State layout after the beads (each only when present): E_d, W, x_s, v_s,
 * E = D_max - D, q_1..q_m. Roots: D (less a plastic dent), the contacts, D', v_s (sensor).
 * Units: SI (m, s, kg, N, J).
 */
#include <math.h>
#include <string.h>

#include "chain_model.h"

static double wall_overlap(const gw_chain *c, const double *y)
{
    return c->i_sens >= 0 ? y[0] - y[c->i_sens] : y[0];
}

static double wall_overlap_rate(const gw_chain *c, const double *y)
{
    return c->i_sens >= 0 ? y[1] - y[c->i_sens + 1] : y[1];
}

/* The plastic wall's largest overlap D_max, from its excess E = D_max - D
 * (the state). On first loading D tracks D_max exactly, the law's kink
 * between its loading and unloading branches (Thornton: stiffness pi p_y R
 * below against 1.5 F_m/(D_max - D_p) above, several times more). Carried as
 * D_max itself, the implicit methods' difference quotients stepped off the
 * kink on both sides at once: D up onto the loading branch, D_max up onto
 * the unloading one, a Jacobian whose sum along the tracking (D and D_max
 * moving together) was 2 pi p_y R - 1.5 F_m/(D_max - D_p), of the wrong sign,
 * where the force grows by pi p_y R. Newton then failed in 45 % of arkode
 * dirk's step attempts (chain --n 30 --sheet brass --sheet-law material:
 * 118,640 steps in 216,866 attempts, 156,430 convergence failures, each with
 * a Jacobian formed anew; drop: 178,655 steps, 23 s, bdf 20,236). With E a
 * state, an increment of any other state moves D and D_max together, along
 * the loading branch, and E's rate is 0 on the tracking, so Newton moves
 * along the branch the solution follows: 3,110 steps (drop 5,525, 0.6 s).
 * E stays exactly 0 on first loading, where D_max carried apart drifted from
 * D by rounding. */
static double wall_dmax(const gw_chain *c, const double *y)
{
    return wall_overlap(c, y) + y[c->i_dmax];
}

/* Contact force of the wall in the general model; *kd = dF/dD, *kv = dF/dD'
 * (Jacobian), the dissipated power of contact damping added to *pd. */
double chain_general_wall_force(const gw_chain *c, const double *y, double *kd, double *kv,
                                 double *pd)
{
    const chain_wall_law *w = &c->wl;
    double d = wall_overlap(c, y), dd = wall_overlap_rate(c, y), f = 0.0;
    *kd = *kv = 0.0;
    if (w->plastic)
        return gw_thornton_force(&w->th, d, wall_dmax(c, y), kd, NULL, NULL);
    if (w->narms > 0) {
        double k;
        f = w->w_inf * chain_wall_elastic(w, d, &k);
        for (int j = 0; j < w->narms; j++)
            f += w->w[j] * y[c->i_q + j];
        if (f > 0) {
            *kd = w->w_inf * k;
            return f;
        }
        return 0.0;
    }
    if (!(d > 0))
        return 0.0;
    if (w->layer || c->p.damping == GW_DAMP_NONE)
        return chain_wall_elastic(w, d, kd);
    double p0 = 0.0;
    f = damped_force(c, c->kwall, c->gwall, d, dd, &p0);
    *pd += p0;
    return f;
}

double chain_guide_force(const gw_chain *c, double v, double *dfdv)
{
    const gw_chain_guide *g = &c->p.guide;
    double th = g->coulomb > 0 ? tanh(v / c->vreg) : 0.0;
    if (dfdv)
        *dfdv = g->coulomb / c->vreg * (1.0 - th * th) + g->viscous;
    return g->coulomb * th + g->viscous * v;
}

enum { PART_ALL = 0, PART_EX = 1, PART_IM = 2 };

static void general_rhs(const gw_chain *c, const double *y, double *yd, int part)
{
    const int n = c->n;
    for (long i = 0; i < c->sys.dim; i++)
        yd[i] = 0.0;
    if (part != PART_IM) {
        for (int i = 0; i < n; i++) {
            yd[2 * i] = y[2 * i + 1];
            yd[2 * i + 1] = c->p.gravity;
        }
        if (part == PART_EX)
            return;
    }
    /* The sensor body's x_s' = v_s with its forces in the implicit part: the
     * body is the system's fastest oscillator, sqrt(k_s/M) up to 3e10 rad/s,
     * and split in two (x_s explicit, v_s implicit) it held arkode imex to
     * steps within that oscillation, which it then amplified (--n 3
     * --sensor-mass 1e-7 --sensor-stiffness 1e14: 9.2 million steps, 225 s,
     * F_max 2e-6 above the rest; dirk, all implicit, 10,000 steps). */
    if (c->i_sens >= 0)
        yd[c->i_sens] = y[c->i_sens + 1];
    double pd = 0.0, kd, kv;
    double fw = chain_general_wall_force(c, y, &kd, &kv, &pd);
    yd[1] -= fw * c->minv[0];
    for (int i = 0; i < n - 1; i++) {
        double d = y[2 * i + 2] - y[2 * i];
        if (!(d > 0))
            continue;
        double f;
        if (c->p.damping == GW_DAMP_NONE)
            f = c->kc[i] * d * sqrt(d);
        else
            f = damped_force(c, c->kc[i], c->gam[i], d, y[2 * i + 3] - y[2 * i + 1], &pd);
        yd[2 * i + 1] += f * c->minv[i];
        yd[2 * i + 3] -= f * c->minv[i + 1];
    }
    if (c->p.guide.coulomb > 0 || c->p.guide.viscous > 0)
        for (int i = 0; i < n; i++) {
            double v = y[2 * i + 1], fr = chain_guide_force(c, v, NULL);
            yd[2 * i + 1] -= fr * c->minv[i];
            pd += fr * v;
        }
    double dd = wall_overlap_rate(c, y);
    if (c->i_sens >= 0) {
        const gw_chain_sensor *s = &c->p.sensor;
        double xs = y[c->i_sens], vs = y[c->i_sens + 1];
        yd[c->i_sens + 1] += (fw - s->stiffness * xs - s->damping * vs) / s->mass;
        pd += s->damping * vs * vs;
    }
    if (c->i_work >= 0)
        yd[c->i_work] = fw * dd;
    if (c->i_dmax >= 0) {
        /* E' = D_max' - D'. Loading: D_max follows D, switched on by a C^1
         * ramp over D in [D_max - 2 dtrack, D_max - dtrack] (E in [dtrack,
         * 2 dtrack]). Tracking (E = 0) then sits inside the ramp's flat top,
         * not at its edge: where it was at the edge, the implicit methods'
         * difference quotients (an increment of D_max, 1.5e-8 of its scale)
         * saw a slope of -dd 6x(1 - x)/dtrack that the rate does not have on
         * the other side, and Newton contracted by only 1/(1 + gamma slope)
         * an iteration: arkode dirk crawled at steps of about 1e-10 s (n = 1,
         * --sheet-yield 1e6: about 8 minutes by its progress lines, erk 252
         * steps), cvode bdf took 180,000 steps. On the top s = 1 exactly, so
         * E' is 0 exactly.
         * What Newton still fails on (drop --n 30 --sheet brass --sheet-law
         * material under dirk: 1,781 convergence failures in 6,452 attempts,
         * a Hertz sheet 569 in 4,481) is the switch-on itself: E's rate goes
         * from -D' to 0 within dtrack of E, in dtrack/D', about 1e-9 s on
         * the drop's first reload (D'/dtrack about 8e8 /s by how E settled
         * there), against steps of 1e-7 s; a step that enters the ramp
         * meets a slope of that size that a Jacobian formed outside it
         * lacks, and is cut until it resolves the switch. 1,250 of the
         * failures come after steps that end on the ramp or within 10 dtrack
         * above it. Measured and not taken:
         *  - s = x^2 or x (a simple root where E settles, dtrack, instead of
         *    x^2 (3 - 2x)'s double root, which E approaches as 1/t): dirk
         *    1,001 and 901 failures, but cvode bdf 61,069 and 41,052 steps
         *    (19,669) on the kink left at that root (x^2: the five
         *    solvers' F_max 7.1e-8 N apart);
         *  - a smooth ramp whose root is inside it (s = 1 - v^2 (14 v - 8 v^2
         *    - 5), v = (E - dtrack/2)/dtrack): dirk 986, bdf 20,391, but
         *    arkode erk 30,725 steps (8,272): settling at a rate of
         *    1.5 D'/dtrack holds an explicit method to it;
         *  - an event at the ramp's entry: 987 with s = x^2 (the failing
         *    steps are those that cross it, before any root is seen);
         *  - dtrack 1e-5 to 1e-3 of the overlap scale: 1,185 to 1,055, F_max
         *    moved by -1.1e-5 to +8.4e-4 N; 1e-7: bdf 86,740 steps;
         *  - five Newton iterations instead of ARKode's three (a setting of
         *    every implicit run): 814 failures, 4,955 steps.
         * F_max's own bias from dtrack is about -1.2e-6 N at 1e-6 (erk:
         * 55.7903931 at 1e-7 and 1e-8, 55.7903919 at 1e-6). */
        double s = 0.0;
        if (dd > 0) {
            double x = (2.0 * c->dtrack - y[c->i_dmax]) / c->dtrack;
            x = x < 0 ? 0.0 : x > 1 ? 1.0 : x;
            s = x * x * (3.0 - 2.0 * x);
        }
        yd[c->i_dmax] = dd * s - dd;
    }
    if (c->wl.narms > 0) {
        double k;
        chain_wall_elastic(&c->wl, wall_overlap(c, y), &k);
        for (int j = 0; j < c->wl.narms; j++)
            yd[c->i_q + j] = k * dd - y[c->i_q + j] / c->wl.tau[j];
    }
    if (c->i_diss >= 0)
        yd[c->i_diss] = pd;
}

int chain_general_rhs(double t, const double *y, double *yd, void *P)
{
    (void)t;
    general_rhs(P, y, yd, PART_ALL);
    return 0;
}

int chain_general_rhs_ex(double t, const double *y, double *yd, void *P)
{
    (void)t;
    general_rhs(P, y, yd, PART_EX);
    return 0;
}

int chain_general_rhs_im(double t, const double *y, double *yd, void *P)
{
    (void)t;
    general_rhs(P, y, yd, PART_IM);
    return 0;
}

int chain_general_roots(double t, const double *y, double *g, void *P)
{
    const gw_chain *c = P;
    const int n = c->n;
    g[0] = gw_chain_wall_gap(c, y);
    for (int i = 0; i < n - 1; i++)
        g[1 + i] = y[2 * i + 2] - y[2 * i];
    g[n] = c->i_sens >= 0 ? wall_overlap_rate(c, y) : chain_force_rate(c, t, y);
    if (c->i_sens >= 0)
        g[n + 1] = chain_force_rate(c, t, y);
    return 0;
}

double gw_chain_wall_contact_force(const gw_chain *c, const double *y)
{
    if (!c || !y)
        return NAN;
    if (!c->general)
        return gw_chain_wall_force(c, y);
    /* a NaN overlap, rate, largest overlap or Maxwell arm: NaN (the open
     * contact's 0 N was returned, a plausible force) */
    if (isnan(wall_overlap(c, y)) || isnan(wall_overlap_rate(c, y)) || (c->wl.plastic && isnan(wall_dmax(c, y))))
        return NAN;
    for (int j = 0; j < c->wl.narms; j++)
        if (isnan(y[c->i_q + j]))
            return NAN;
    double kd, kv, pd = 0.0;
    return chain_general_wall_force(c, y, &kd, &kv, &pd);
}

double gw_chain_wall_gap(const gw_chain *c, const double *y)
{
    if (!c || !y)
        return NAN;
    if (!c->general)
        return y[0];
    double d = wall_overlap(c, y);
    if (c->wl.plastic) {
        double dp;
        gw_thornton_force(&c->wl.th, d, wall_dmax(c, y), NULL, &dp, NULL);
        return d - dp;
    }
    return d;
}

double gw_chain_wall_gap_rate(const gw_chain *c, const double *y)
{
    if (!c || !y)
        return NAN;
    return c->general ? wall_overlap_rate(c, y) : y[1];
}

int gw_chain_force_max_root(const gw_chain *c)
{
    if (!c)
        return -1;
    return c->n + (c->i_sens >= 0);
}

long gw_chain_sensor_index(const gw_chain *c)
{
    if (!c)
        return -1;
    return c->i_sens;
}

double gw_chain_momentum(const gw_chain *c, const double *y)
{
    if (!c || !y)
        return NAN;
    double p = 0.0;
    for (int i = 0; i < c->n; i++)
        p += c->m[i] * y[2 * i + 1];
    if (c->i_sens >= 0)
        p += c->p.sensor.mass * y[c->i_sens + 1];
    return p;
}

/* Energy still stored in the wall (recoverable on unloading). */
static double wall_stored_energy(const gw_chain *c, const double *y)
{
    const chain_wall_law *w = &c->wl;
    double d = wall_overlap(c, y), u;
    if (w->plastic) {
        gw_thornton_force(&w->th, d, wall_dmax(c, y), NULL, NULL, &u);
        return u;
    }
    u = w->w_inf * chain_wall_elastic_energy(w, d);
    for (int j = 0; j < w->narms; j++) /* each arm's spring at the overlap that carries its force */
        u += w->w[j] * chain_wall_elastic_energy(w, chain_wall_elastic_overlap(w, fabs(y[c->i_q + j])));
    return u;
}

void chain_general_energy(const gw_chain *c, const double *y, gw_chain_energy *e)
{
    double ke, el, pg, dis = c->i_diss >= 0 ? y[c->i_diss] : 0.0;
    chain_beads_energy(c, y, &ke, &el, &pg);
    if (c->i_work >= 0) {
        double u = wall_stored_energy(c, y);
        el += u;
        dis += y[c->i_work] - u;
    } else {
        el += chain_wall_elastic_energy(&c->wl, wall_overlap(c, y));
    }
    if (c->i_sens >= 0) {
        double xs = y[c->i_sens], vs = y[c->i_sens + 1];
        ke += 0.5 * c->p.sensor.mass * vs * vs;
        el += 0.5 * c->p.sensor.stiffness * xs * xs;
    }
    e->kinetic = ke;
    e->elastic = el;
    e->gravity = pg;
    e->dissipated = dis;
    e->total = ke + el + pg + dis;
}

