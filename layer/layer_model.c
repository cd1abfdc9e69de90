/*
 * layer_model.c: the Hertz-Mindlin disc layer as an ODE system (docs/physics.md 2.1,
 * 2.4; eqs. B.1-B.4, B.7-B.14).
 *
 * The right-hand side, the roots and the system handed to the solver, and the
 * contacts' kinematics they share. The layer object (parameters, creation,
 * accessors: layer_create.c) and the contact snapshot with the ring sums read
 * off a state (layer_snapshot.c) are separate files: neither is evaluated
 * within a step.
 *
 * Particles i: m_i dv_i/dt = sum of contact forces - m_i g e_y,
 *              I_i dw_i/dt = sum of R_i F_t (torques of tangential forces).
 * Rigid clumps (layer_clumps.c): the sums run over the contacts of all members
 * and act on the body's centre of mass; the torque of a member's contact is
 * (a_i + l_i n) x F = a_i x F + l_i F_t, a_i the arm from the centre of mass to
 * the member's centre (normal force included), and the member's centre moves
 * at V + omega e_z x a_i, which enters u_n's rate and v_t below. In a layer
 * with clumps every contact acts at its contact point, l_i = R_i - u_n/2 (in
 * v_t too), so that the two bodies' torques about any point cancel and angular
 * momentum is conserved; the disc-only layer keeps l_i = R_i as before (its
 * results unchanged bit for bit; the two differ by u_n/R ~ 1e-4 relative).
 * Contact (a, b), n the unit normal from a to b, t = (-n_y, n_x):
 *   u_n = R_a + R_b - |x_b - x_a|  (wall: R_a minus the distance to the wall)
 *   F_n = K_n u_n^(3/2),  K_n = 2 sqrt(2 R_p) G / (3 (1 - nu))          (B.1, B.3)
 *   K_t = 2 (3 G^2 (1 - nu) R_p)^(1/3) / (2 - nu) * F_n^(1/3)            (B.4)
 *   R_p = 2 R_a R_b / (R_a + R_b) for two discs, R_p = R_a against a wall (a wall
 *   is a particle of infinite radius and mass; PFC2D's convention, docs/physics.md 2.1).
 *   v_t = (v_b - v_a).t - w_a R_a - w_b R_b (relative tangential velocity of the
 *   contact points; contact arms taken as the radii; v the disc centres').
 *   Force on a: -F_n n + F_t t, torque R_a F_t; on b the opposite force, torque
 *   R_b F_t.
 * Tangential law (B.2), the state holds the elastic tangential force F_t of every
 * listed contact (not a displacement: K_t changes with F_n, so the incremental
 * law integrates the force):
 *   elastic rate r_e = K_t v_t; cap rate r_c = s tan(phi) dF_n/dt, s = sign(F_t).
 *   The force used is F_t clamped to the cap [-F_n tan phi, F_n tan phi].
 *   Sticking (|F_t| < cap, or at the cap and unloading, s r_e <= s r_c):
 *   dF_t/dt = r_e. Sliding (|F_t| >= cap and s r_e > s r_c): the used force rides
 *   the cap (rate r_c, zero rate relative to the cap), and the state is held a
 *   margin eta = 1e-4 outside it, dF_t/dt = r_c + s lambda (cap (1 + eta) - |F_t|),
 *   lambda = 1e4 /s (0.01 / dt in the exact mode: gw_layer.cap_rate, layer_sim.c).
 *   Why the margin: a state exactly on the cap chatters between
 *   the two branches under the stage perturbations of an adaptive method (the
 *   elastic rate is ~1e8 N/s), which drives its steps to ~1e-14 s. The margin
 *   delays the elastic unloading after a reversal by eta cap / |r_e| (~1e-9 s).
 *   The ledger uses the clamped force and its true rate (r_c at the cap), so
 *   the margin moves no energy. F_t of open contacts is zeroed at the solver's
 *   stops. (DEM mode advances F_t by the incremental law instead, layer_dem.c:
 *   the rate form here serves the exact mode and the other backends.)
 * Energy (B.7-B.14): the contact absorbs the power F_t v_t + F_n du_n/dt. With
 *   E_st = F_t^2 / (2 K_t) the split is
 *   F_t v_t = dE_st/dt + dW_K/dt + dE_d/dt,
 *   dE_d/dt = F_t (v_t - (dF_t/dt)/K_t)       (= -F_t du_t^p, zero when sticking)
 *   dW_K/dt = F_t^2 (dK_t/dt) / (2 K_t^2) = F_t^2 (dF_n/dt) / (6 K_t F_n)
 *   W_K is the part of the incremental tangential strain work (docs/physics.md 2.4:
 *   dE_s = -F_t du_t^e) that the state function F_t^2/(2 K_t) misses because K_t
 *   varies with F_n (the Mindlin law with K_t(F_n) has no potential). E_d and W_K
 *   are integrated as the last two state components, so the ledger
 *   E_kb + E_ks + E_sn + E_st + W_K + E_d + E_p = A closes to integration error.
 * Optional normal damping (pluviation only; the paper has none), Hunt-Crossley:
 *   F = F_n (1 + (3/2) alpha du_n/dt) clamped >= 0; its power goes into E_d. The
 *   Mindlin stiffness and the cap use the elastic F_n.
 * Computation: per-contact constants are set at list build (layer_contacts.c);
 * K_t = k_t F_n^(1/3) = (k_t K_n^(1/3)) u_n^(1/2), the same to rounding, needs no
 * cube root; a layer without clumps takes a disc-only kinematics path (arms =
 * radii) that skips the pairs farther apart than R_a + R_b before any square
 * root. The forces of a closed contact are layer_contact_force (layer_impl.h;
 * the tangential law itself layer_tangential), which every right-hand side
 * and the block watch call. In DEM mode a disc-only layer uses layer_dem_rhs
 * (layer_dem.c) instead.
 * Units: SI (m, s, kg, N, Pa, J).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"

/* Overlap u_n and unit normal n (a -> b) of contact c whose discs are centred
 * at pa and pb (pb unused against a wall); box width w. */
double layer_pair_geometry(const layer_contact *c, const double pa[2], const double pb[2], double w,
                           double n[2])
{
    if (c->b < 0)
        return layer_wall_overlap(c->b, c->ra, pa, w, n);
    double dx = pb[0] - pa[0], dy = pb[1] - pa[1], d = sqrt(dx * dx + dy * dy);
    if (d > 0)
        n[0] = dx / d, n[1] = dy / d;
    else
        n[0] = 0, n[1] = 1;
    return c->ra + c->rb - d;
}

/* Geometry of contact c with the arms of its discs (layer_disc_xy). */
static void geometry_arms(const gw_layer *L, const layer_contact *c, const double *y, double *un,
                          double n[2], double pt[2], double arma[2], double armb[2])
{
    double sa[2], sb[2] = {0, 0};
    layer_disc_xy(L, y, c->a, sa, arma);
    if (c->b >= 0)
        layer_disc_xy(L, y, c->b, sb, armb);
    *un = layer_pair_geometry(c, sa, sb, L->p.width, n);
    if (pt) {
        pt[0] = sa[0] + (c->ra - 0.5 * *un) * n[0];
        pt[1] = sa[1] + (c->ra - 0.5 * *un) * n[1];
    }
}

void layer_contact_geometry(const gw_layer *L, const layer_contact *c, const double *y,
                            double *un, double n[2], double pt[2])
{
    double arma[2], armb[2];
    geometry_arms(L, c, y, un, n, pt, arma, armb);
}

/* Kinematics of contact c: overlap, normal, overlap rate and tangential
 * relative velocity. */
static void contact_kinematics(const gw_layer *L, const layer_contact *c, const double *y,
                               double *un, double n[2], double *und, double *vt,
                               double arma[2], double armb[2], double lev[2])
{
    arma[0] = arma[1] = armb[0] = armb[1] = 0;
    geometry_arms(L, c, y, un, n, NULL, arma, armb);
    const double *sa = y + 6 * layer_body(L, c->a);
    double vax = sa[3], vay = sa[4];
    double vbx = 0, vby = 0, wrb = 0;
    if (c->b >= 0) {
        const double *sb = y + 6 * layer_body(L, c->b);
        vbx = sb[3], vby = sb[4], wrb = sb[5] * L->r[c->b];
        if (L->off) /* velocity of the member's centre */
            vbx -= sb[5] * armb[1], vby += sb[5] * armb[0];
    }
    lev[0] = L->r[c->a];
    lev[1] = c->b >= 0 ? L->r[c->b] : 0;
    if (L->off) { /* with clumps: levers to the contact point */
        vax -= sa[5] * arma[1], vay += sa[5] * arma[0];
        lev[0] -= 0.5 * *un;
        if (c->b >= 0) {
            lev[1] -= 0.5 * *un;
            wrb = y[6 * layer_body(L, c->b) + 5] * lev[1];
        }
    }
    double rx = vbx - vax, ry = vby - vay;
    *und = -(rx * n[0] + ry * n[1]);
    *vt = -rx * n[1] + ry * n[0] - sa[5] * lev[0] - wrb;
}

void layer_contact_rates(const gw_layer *L, const layer_contact *c, const double *y, double *un, double *und,
                         double *vt)
{
    double nn[2], arma[2], armb[2], lev[2];
    contact_kinematics(L, c, y, un, nn, und, vt, arma, armb, lev);
}

/* The vertical force contact k exerts on its body qa (the reverse on qb), N:
 * 0 when it does not press */
static double contact_fy(const gw_layer *L, const double *y, int k, const unsigned char *held, int ftm)
{
    const layer_contact *c = &L->c[k];
    double un, nn[2], und, vt, arma[2], armb[2], lev[2];
    contact_kinematics(L, c, y, &un, nn, &und, &vt, arma, armb, lev);
    const double su = un > 0 ? sqrt(un) : 0, fel = c->kn * un * su;
    if (!(un > 0) || !(fel > 0))
        return 0;
    const layer_cforce o = layer_contact_force(c, su, fel, und, vt, y[6 * L->nb + k], L->p.damping, L->tan_phi,
                                               L->cap_rate, held ? held[k] : ftm);
    return -o.fn * nn[1] + o.ft * nn[0];
}

double layer_body_contact_fy(const gw_layer *L, const double *y, int q, const int *idx, int n_idx)
{
    const unsigned char *held;
    const int ftm = layer_ft_modes(L, &held);
    double fy = 0;
    for (int j = 0; j < (idx ? n_idx : L->nc); j++) {
        const int k = idx ? idx[j] : j;
        const layer_contact *c = &L->c[k];
        if (c->qa != q && c->qb != q)
            continue;
        const double f = contact_fy(L, y, k, held, ftm);
        fy += c->qa == q ? f : -f;
    }
    return fy;
}

double layer_side_walls_fy(const gw_layer *L, const double *y)
{
    const unsigned char *held;
    const int ftm = layer_ft_modes(L, &held);
    double fy = 0;
    for (int k = 0; k < L->nc; k++)
        if (L->c[k].b == LAYER_LEFT || L->c[k].b == LAYER_RIGHT)
            fy += contact_fy(L, y, k, held, ftm);
    return fy;
}

double layer_contact_vt(const gw_layer *L, const layer_contact *c, const double *y, double *un)
{
    double nn[2], und, vt, arma[2], armb[2], lev[2];
    contact_kinematics(L, c, y, un, nn, &und, &vt, arma, armb, lev);
    return vt;
}

/* Kinematics of disc-only contact c (no clumps: body = disc, arms = radii):
 * overlap, normal, overlap rate and tangential relative velocity; 0 when open
 * (the square root is only taken for pairs closer than R_a + R_b). */
static inline int disc_kinematics(const layer_contact *c, const double *y, double width,
                                  double *un, double n[2], double *und, double *vt)
{
    const double *sa = y + 6 * c->qa;
    double rx = -sa[3], ry = -sa[4], wrb = 0;
    switch (c->b) {
    case LAYER_LEFT:
        n[0] = -1, n[1] = 0, *un = c->ra - sa[0];
        break;
    case LAYER_RIGHT:
        n[0] = 1, n[1] = 0, *un = c->ra - (width - sa[0]);
        break;
    case LAYER_BOTTOM:
        n[0] = 0, n[1] = -1, *un = c->ra - sa[1];
        break;
    default: {
        const double *sb = y + 6 * c->qb;
        double dx = sb[0] - sa[0], dy = sb[1] - sa[1], d2 = dx * dx + dy * dy;
        double rs = c->ra + c->rb;
        if (!(d2 < rs * rs))
            return 0;
        double d = sqrt(d2);
        if (d > 0)
            n[0] = dx / d, n[1] = dy / d;
        else
            n[0] = 0, n[1] = 1;
        *un = rs - d;
        rx += sb[3], ry += sb[4], wrb = sb[5] * c->rb;
    }
    }
    if (!(*un > 0))
        return 0;
    *und = -(rx * n[0] + ry * n[1]);
    *vt = -rx * n[1] + ry * n[0] - sa[5] * c->ra - wrb;
    return 1;
}

/* Region of closed contact c (overlap un, normal nn) for the regional ledgers. */
static inline int rhs_region(const gw_layer *L, const layer_contact *c, const double *y, double un,
                             const double nn[2], int clumps)
{
    if (clumps)
        return layer_contact_region_at(L, c, y, un, nn);
    return layer_contact_region_pt(L, c, y[6 * c->qa] + (c->ra - 0.5 * un) * nn[0],
                                   y[6 * c->qa + 1] + (c->ra - 0.5 * un) * nn[1]);
}

static int layer_rhs(double t, const double *y, double *yd, void *P)
{
    (void)t;
    if (((const gw_layer *)P)->dem_carry) /* DEM: the first call after a list rebuild */
        return layer_dem_carried(P, y, yd);
    const gw_layer *L = P;
    const int n = L->nb; /* the state is per body */
    const double g = L->p.gravity, tp = L->tan_phi, alpha = L->p.damping, width = L->p.width;
    const int clumps = L->off != NULL;
    double pd = 0, pk = 0;
    double *rtail = L->reg_n > 0 ? yd + 6 * n + L->nc + 2 : NULL;
    double *un_last = L->un_last;
    layer_tscr *tscr = L->tscr;
    const unsigned char *held;
    const int ftm = layer_ft_modes(L, &held);
    const double cap_rate = L->cap_rate;
    for (int q = 0; rtail && q < 2 * (L->reg_n + 2); q++)
        rtail[q] = 0;
    for (int i = 0; i < n; i++) {
        const double *s = y + 6 * i;
        double *d = yd + 6 * i;
        d[0] = s[3], d[1] = s[4], d[2] = s[5];
        d[3] = d[4] = d[5] = 0; /* forces and torque, scaled below */
    }
    for (int k = 0; k < L->nc; k++) {
        const layer_contact *c = &L->c[k];
        double un = 0, nn[2], und = 0, vt = 0, arma[2], armb[2], lev[2];
        double *fdot = yd + 6 * n + k;
        int closed;
        if (clumps) {
            contact_kinematics(L, c, y, &un, nn, &und, &vt, arma, armb, lev);
            closed = un > 0;
        } else {
            closed = disc_kinematics(c, y, width, &un, nn, &und, &vt);
            lev[0] = c->ra, lev[1] = c->rb;
        }
        double su = closed ? sqrt(un) : 0, fel = c->kn * un * su;
        if (!closed || !(fel > 0)) { /* open, or F_n underflows */
            *fdot = 0;
            un_last[k] = 0;
            continue;
        }
        un_last[k] = un;
        /* the law (layer_contact_force) in each mode's branch, with its books
         * (one test of the mode per contact; the exact mode's first) */
        const double f = y[6 * n + k];
        layer_cforce o;
        if (ftm == LAYER_FT_EXACT) {
            o = layer_contact_force(c, su, fel, und, vt, f, alpha, tp, cap_rate, held ? held[k] : ftm);
            if (alpha > 0)
                pd += (o.fn - fel) * und;
            *fdot = o.rate;
            pd += o.cd;
            pk += o.ck;
            if (rtail) {
                int q = rhs_region(L, c, y, un, nn, clumps);
                rtail[2 * q] += o.cd + (o.fn - fel) * und;
                rtail[2 * q + 1] += o.ck;
            }
        } else if (ftm == LAYER_FT_FAST) { /* DEM: F_t is the step's (layer_dem.c), tangential books there */
            o = layer_contact_force(c, su, fel, und, vt, f, alpha, tp, cap_rate, LAYER_FT_FAST);
            if (alpha > 0)
                pd += (o.fn - fel) * und;
            *fdot = 0;
            tscr[k].kt = c->kts * su;
            if (rtail) {
                int q = rhs_region(L, c, y, un, nn, clumps);
                tscr[k].q = q;
                rtail[2 * q] += (o.fn - fel) * und;
            }
        } else {
            o = layer_contact_force(c, su, fel, und, vt, f, alpha, tp, cap_rate, LAYER_FT_NONE);
            if (alpha > 0)
                pd += (o.fn - fel) * und;
            *fdot = 0;
            if (rtail && alpha > 0)
                rtail[2 * layer_contact_region_at(L, c, y, un, nn)] += (o.fn - fel) * und;
        }
        const double fn = o.fn, ft = o.ft;
        double fx = -fn * nn[0] - ft * nn[1], fy = -fn * nn[1] + ft * nn[0];
        double *da = yd + 6 * c->qa;
        da[3] += fx, da[4] += fy, da[5] += ft * lev[0];
        if (clumps) /* arm x F, normal force included */
            da[5] += arma[0] * fy - arma[1] * fx;
        if (c->b >= 0) {
            double *db = yd + 6 * c->qb;
            db[3] -= fx, db[4] -= fy, db[5] += ft * lev[1];
            if (clumps)
                db[5] -= armb[0] * fy - armb[1] * fx;
        }
    }
    layer_rhs_finish(L, yd, n, g, pd, pk);
    return 0;
}

/* The stepend rebuild root's margin of one particle (layer_roots): half the
 * skin squared less the squared distance (dx, dy) it moved since the list
 * was built, the half skin less the larger of the margin m0 and twice what it
 * moves in a step at its speed |v| + |w| |arm| (body state s, a2 = |arm|^2),
 * the square root only for fast particles; positive at the rebuild, d = 0. */
static inline double layer_rebuild_margin(double half, double m0, double m02, double h0, double dt2, double dx,
                                          double dy, const double *s, double a2)
{
    const double v2 = s[3] * s[3] + s[4] * s[4];
    double hi2 = h0;
    if (v2 + s[5] * s[5] * a2 > 0.25 * m02) { /* |v| + |w| |arm| > m0 / dt2 implies it */
        const double sp = sqrt(v2) + fabs(s[5]) * sqrt(a2);
        if (dt2 * sp > m0) {
            const double hi = half - dt2 * sp > 1e-6 * half ? half - dt2 * sp : 1e-6 * half;
            hi2 = hi * hi;
        }
    }
    return hi2 - dx * dx - dy * dy;
}

/* Roots: the overlap of every listed contact, then (skin/2)^2 - |x_i - x_list|^2
 * per particle (the list must be rebuilt when one of those reaches zero), then
 * with friction |F_t| - F_n tan(phi) per contact: the stick/slip switches are a
 * discontinuity of the right-hand side, and restarting there keeps the methods'
 * order (RK4 stepping across them loses it: ledger error 1e-4 instead of 1e-8). */
static int layer_roots(double t, const double *y, double *g, void *P)
{
    gw_layer *L = P;
    if (L->watch) /* (the only write: the watch's probe and extremes) */
        layer_watch_roots(L, t, y, g);
    /* DEM mode (and rk4 in L->stepend) reports the rebuild root at the end of the step that crossed it
     * (not located): a particle i rebuilds the list at half the skin less a
     * margin for the next step, the larger of 0.05 skin and twice what it
     * moves in a step at its speed (|v| + |w| |arm|) dt, so that no step can
     * bring an unlisted pair into contact; a particle that moves more than
     * 0.25 skin in a step rebuilds at every step (and a contact the list
     * missed all the same is refused at the rebuild: layer_contacts.c). The
     * list's timing does not change the DEM trajectory. */
    const double half = 0.5 * L->p.skin, h = half, dt2 = 2 * L->sp.dt;
    const int r0 = layer_root_rebuild(L), s0 = layer_root_slip(L);
    if (L->stepend) { /* one rebuild root (layer_root_nrebuild): the smallest margin */
        double gmin = 1.0;
        const double m0 = 0.1 * half, m02 = m0 * m0 / (dt2 * dt2), h0 = (half - m0) * (half - m0);
        const int n = L->n;
        const double *xl = L->x_list;
        const unsigned char *fixed = L->fixed;
        const double q02 = 0.25 * m02;
        if (!L->off) { /* discs: particle i is body i, arm = 0 (the terms in |w| |arm| are +0 for a
                          finite w, and left out), the constants out of the loop */
            for (int i = 0; i < n; i++) {
                if (fixed[i])
                    continue;
                const double *s = y + 6 * i;
                const double dx = s[0] - xl[2 * i], dy = s[1] - xl[2 * i + 1];
                const double v2 = s[3] * s[3] + s[4] * s[4];
                double hi2 = h0;
                if (v2 > q02) {
                    const double sp = sqrt(v2);
                    if (dt2 * sp > m0) {
                        const double hi = half - dt2 * sp > 1e-6 * half ? half - dt2 * sp : 1e-6 * half;
                        hi2 = hi * hi;
                    }
                }
                const double gi = hi2 - dx * dx - dy * dy;
                gmin = gi < gmin ? gi : gmin;
            }
        } else { /* clumps: particle i is a disc of body layer_body(L, i) */
            for (int i = 0; i < n; i++) {
                double p[2], arm[2];
                const int b = layer_body(L, i);
                if (fixed[b])
                    continue;
                layer_disc_xy(L, y, i, p, arm);
                const double gi = layer_rebuild_margin(half, m0, m02, h0, dt2, p[0] - xl[2 * i],
                                                       p[1] - xl[2 * i + 1], y + 6 * b,
                                                       arm[0] * arm[0] + arm[1] * arm[1]);
                gmin = gi < gmin ? gi : gmin;
            }
        }
        g[r0] = gmin;
    } else if (L->off) {
        for (int i = 0; i < L->n; i++) {
            double p[2], arm[2];
            layer_disc_xy(L, y, i, p, arm);
            double dx = p[0] - L->x_list[2 * i], dy = p[1] - L->x_list[2 * i + 1];
            g[r0 + i] = L->fixed[layer_body(L, i)] ? 1.0 : h * h - dx * dx - dy * dy;
        }
    } else { /* discs only: particle i is body i */
        for (int i = 0; i < L->n; i++) {
            double dx = y[6 * i] - L->x_list[2 * i], dy = y[6 * i + 1] - L->x_list[2 * i + 1];
            g[r0 + i] = L->fixed[i] ? 1.0 : h * h - dx * dx - dy * dy;
        }
    }
    double un, nn[2];
    if (L->p.no_events)
        return 0;
    for (int k = 0; k < L->nc; k++) {
        layer_contact_geometry(L, &L->c[k], y, &un, nn, NULL);
        g[k] = un;
        if (s0 >= 0) {
            g[s0 + k] = fabs(y[6 * L->nb + k]) - layer_cap(L->tan_phi, L->c[k].kn, un);
        }
    }
    return 0;
}

void layer_system_fill(gw_layer *L)
{
    const int n = L->nb;
    L->dim = 6L * n + L->nc + L->ntail;
    for (int i = 0; i < n; i++) {
        double *s = L->scale + 6 * i;
        s[0] = s[1] = L->u_scale;
        s[2] = L->u_scale / L->brad[i];
        s[3] = s[4] = L->v_scale;
        s[5] = L->v_scale / L->brad[i];
    }
    for (int k = 0; k < L->nc; k++)
        L->scale[6 * n + k] = L->f_scale;
    for (int q = 0; q < L->ntail; q++)
        L->scale[6 * n + L->nc + q] = L->e_scale > 0 ? L->e_scale : 1.0;
    memset(&L->sys, 0, sizeof L->sys);
    L->sys.dim = L->dim;
    L->sys.rhs = L->dem && !L->off ? layer_dem_rhs : layer_rhs;
    L->sys.roots = layer_roots;
    L->sys.nroots = layer_root_count(L) + (L->watch ? 2 : 0);
    L->sys.scale = L->scale;
    L->sys.params = L;
    /* no band: a disc's contacts reach any index, so a band solver would hold
     * and LU-factor the whole dim^2 matrix (dim = 6 n + contacts, about 2700
     * on the 300-disc sample: cvode bdf took minutes per 1e-5 s); the implicit
     * methods go matrix-free (GMRES on Jacobian-vector products) */
    L->sys.matrix_free = 1;
    for (int i = 0; i < n; i++)
        for (int q = 0; q < 6; q++)
            L->drift[6 * i + q] = q < 3 ? 6 * i + q + 3 : -1;
    for (long q = 6L * n; q < L->dim; q++) /* DEM: F_t advanced by layer_dem_drift */
        L->drift[q] = L->dem && L->tan_phi > 0 && q < 6L * n + L->nc ? GW_DRIFT_MODEL : -1;
    L->sys.drift = L->drift;
    L->sys.project = L->dem ? layer_dem_project : L->stepend ? layer_step_project : NULL;
    L->sys.roots_at_step_end = L->stepend;
    L->sys.drift_fn = L->dem ? layer_dem_drift : NULL;
}
