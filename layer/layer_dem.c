/*
 * layer_dem.c: the explicit DEM step of the layer (docs/physics.md 2.1, 2.4; eqs.
 * B.2, B.7-B.14): the incremental Mindlin law advanced as a coordinate of the
 * verlet step (gw_drift_fn), and the ledger it feeds.
 *
 * In DEM mode (the verlet backend) the elastic tangential force F_t of every
 * listed contact is not integrated from its rate: like a position it is
 * stretched by the half-step velocities, after the coordinates have drifted,
 * and the rhs then applies it at the end of the step:
 *   v_t = v_t(t + h/2) with the normal at the mid-step positions
 *         x(t + h/2) = x(t) + (h/2) v(t + h/2),
 *   K_m = the mean of K_t = k_t K_n^(1/3) u_n^(1/2) over the step with u_n
 *         linear in time between its values at the start and the end
 *         (mean_kt: K_s, K_e the two ends' K_t; a contact that closes or opens
 *         in the step is stiff only for the part of it where u_n > 0),
 *   F_trial = F_s + K_m v_t h,   F_e = F_trial clamped to [-C, C],
 *   C = tan(phi) K_n u_e^(3/2) (0 when the contact is open at the end).
 * The books of the step follow from the rate forms of layer_model.c,
 *   dE_d/dt = F_t (v_t - (dF_t/dt)/K_t),  dW_K/dt = F_t^2 (dK_t/dt) / (2 K_t^2),
 * written at the midpoint of the step:
 *   dE_d = Fbar (v_t h - (F_e - F_s)/K_m) = Fbar (F_trial - F_e)/K_m, Fbar =
 *          (F_s + F_e)/2: zero while sticking, the cap times the slip otherwise;
 *   dW_K = F_e^2 (1/K_m - 1/K_e)/2 + F_s^2 (1/K_s - 1/K_m)/2 (an open end's
 *          term is 0: its F is 0).
 * With them, the work the two half kicks do through the contact, v_t h Fbar,
 * equals dE_d + dE_st + dW_K to second order in h, where E_st = F_t^2/(2 K_t):
 * the ledger closure measures the step's error, the kinetic side included, as
 * for the normal force. Why not the rate form with the kicks: F_t's rate then
 * depends on the predicted end velocities, which is an explicit trapezoid for
 * a stiff tangential spring; measured on the default impact, the closure grows
 * with the friction angle (2.6e-2 at 85 deg, 1.9e-3 at 30 deg, dt = 1e-5 s)
 * and decreases only as dt^2 to dt^3 from there.
 * A contact that opens ends the step with F_t = 0 (C = 0): its stored energy
 * goes to dE_d and W_K through the same formulas. The increments of E_d and W_K (and of
 * the contact's region) are added to the state after the step's last kick
 * (layer_dem_project), since the kicks rewrite the kicked tail.
 * Units: SI.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"

/* Tangential relative velocity of a disc-only contact at the mid-step state,
 * from ph (start positions x, half-step velocities v): the normal of the mid
 * positions x + (h/2) v, also when the contact is open there. */
static inline double disc_vt(const layer_contact *c, const double *ph, double hh)
{
    const double *sa = ph + 6 * c->qa;
    double rx = -sa[3], ry = -sa[4];
    if (c->b >= 0) { /* a pair (the common case, tested first); v_t = -r_x n_y + r_y n_x - w_a R_a - w_b R_b */
        const double *sb = ph + 6 * c->qb;
        double dx = (sb[0] + hh * sb[3]) - (sa[0] + hh * sa[3]);
        double dy = (sb[1] + hh * sb[4]) - (sa[1] + hh * sa[4]), d = sqrt(dx * dx + dy * dy);
        rx += sb[3], ry += sb[4];
        double w = -sa[5] * c->ra - sb[5] * c->rb;
        return d > 0 ? (-rx * dy + ry * dx) / d + w : -rx + w; /* coincident: n = (0, 1) */
    }
    switch (c->b) {
    case LAYER_LEFT: /* n = (-1, 0) */
        return -ry - sa[5] * c->ra;
    case LAYER_RIGHT: /* n = (1, 0) */
        return ry - sa[5] * c->ra;
    default: /* LAYER_BOTTOM, n = (0, -1) */
        return rx - sa[5] * c->ra;
    }
}

/* Overlap and unit normal (a -> b) of a disc-only contact in state y; for a
 * pair farther apart than R_a + R_b the overlap, less than 0 (the gap, which
 * the drift's sleep needs: drift_discs), without the normal (n = (0, 1)). */
static inline double disc_geometry(const layer_contact *c, const double *y, double width, double n[2])
{
    const double *sa = y + 6 * c->qa;
    if (c->b >= 0) { /* a pair (the common case, tested first) */
        const double *sb = y + 6 * c->qb;
        double dx = sb[0] - sa[0], dy = sb[1] - sa[1], d2 = dx * dx + dy * dy, rs = c->ra + c->rb;
        double d = sqrt(d2);
        if (!(d2 < rs * rs)) {
            n[0] = 0, n[1] = 1;
            return rs - d;
        }
        if (d > 0) {
            double id = 1 / d;
            n[0] = dx * id, n[1] = dy * id;
        } else
            n[0] = 0, n[1] = 1;
        return rs - d;
    }
    return layer_wall_overlap(c->b, c->ra, sa, width, n);
}

/* The signed overlap of a disc-only contact in state y (negative: the gap),
 * with hypot (disc_geometry's rounding differs). Only for the steps where the
 * contact closes or opens. */
static double disc_overlap(const layer_contact *c, const double *y, double width)
{
    const double *sa = y + 6 * c->qa;
    switch (c->b) {
    case LAYER_LEFT:
        return c->ra - sa[0];
    case LAYER_RIGHT:
        return c->ra - (width - sa[0]);
    case LAYER_BOTTOM:
        return c->ra - sa[1];
    default: {
        const double *sb = y + 6 * c->qb;
        return c->ra + c->rb - hypot(sb[0] - sa[0], sb[1] - sa[1]);
    }
    }
}

/* The mean tangential stiffness of a step, K_m = k_ts <sqrt(u_n)>, with u_n
 * linear in time from us to ue (signed overlaps: negative is open; K_s =
 * k_ts sqrt(us), K_e = k_ts sqrt(ue) for the closed ends):
 *   closed at both ends:  K_m = (2/3) (K_s^2 + K_s K_e + K_e^2) / (K_s + K_e),
 *   closing (us <= 0):    K_m = (2/3) K_e ue / (ue - us),
 *   opening (ue <= 0):    K_m = (2/3) K_s us / (us - ue),
 * the integral of K_t over the part of the step the contact is closed, over h.
 * K_t grows as the square root of the overlap, so near a closure the
 * harmonic mean of K_s and K_e is not the step's: a contact that closed just
 * before the previous step's end has K_s -> 0 and the harmonic mean 2 K_s -> 0
 * (no stiffness for one step), and the closing step itself took K_e over the
 * whole step, where the contact is closed only for its last ue / (ue - us)
 * part. Either is an error in F_t of order K v_t h that depends on where the
 * touch falls in the step. */
static inline double mean_kt(double ks, double ke, double us, double ue)
{
    if (ks > 0 && ke > 0)
        return (2.0 / 3.0) * (ks * ks + ks * ke + ke * ke) / (ks + ke);
    if (ke > 0)
        return (2.0 / 3.0) * ke * (us < 0 ? ue / (ue - us) : 1);
    if (ks > 0)
        return (2.0 / 3.0) * ks * (ue < 0 ? us / (us - ue) : 1);
    return 0;
}

/* The forces of a closed disc-only contact in state y (layer_contact_force in
 * mode LAYER_FT_FAST or LAYER_FT_NONE; nn its normal, fel its elastic F_n, f
 * its F_t state), with the approach speed u_n' along nn for the normal
 * damping alpha (s/m) in *und: 0 when alpha is 0, where the damping and its
 * power (F_n - F_el) u_n' vanish. */
static inline layer_cforce disc_force(const layer_contact *c, const double *y, const double nn[2], double su,
                                      double fel, double f, double alpha, double tp, int mode, double *und)
{
    *und = 0;
    if (alpha > 0) {
        const double *sa = y + 6 * c->qa;
        double rx = -sa[3], ry = -sa[4];
        if (c->b >= 0)
            rx += y[6 * c->qb + 3], ry += y[6 * c->qb + 4];
        *und = -(rx * nn[0] + ry * nn[1]);
    }
    return layer_contact_force(c, su, fel, *und, 0, f, alpha, tp, 0, mode);
}

/* drift_discs's second pass: for the n contacts a step works on, from u_n
 * (u), K_s (ks) and k_ts (kts), sqrt(u_n), 1/K_e, K_m (mean_kt's closed-at-both-
 * ends form, the same operations, written out: a call of mean_kt, with its
 * branches, is not vectorised) and 1/K_m, as if closed at both ends (the
 * others' numbers are not read). A function of its own: inside drift_discs
 * GCC did not vectorise the loop. */
LAYER_HOT static void drift_stiffness(int n, const double *restrict u, const double *restrict ks,
                                      const double *restrict kts, double *restrict su, double *restrict ike,
                                      double *restrict km, double *restrict ikm)
{
    for (int j = 0; j < n; j++) {
        const double s = ks[j], r = sqrt(u[j] > 0 ? u[j] : 0), ke = kts[j] * r;
        const double m = (2.0 / 3.0) * (s * s + s * ke + ke * ke) / (s + ke);
        su[j] = r;
        ike[j] = 1 / ke;
        km[j] = m;
        ikm[j] = 1 / m;
    }
}

/* The drift of a disc-only layer, fused with its force pass: per contact the
 * end geometry, the tangential step and its books, then the end forces the
 * rhs would compute (Hertz, the damping at the predicted velocities, F_t as
 * the cap allows: layer_contact_force), summed per body into L->facc with the
 * rhs's arithmetic, so that layer_dem_rhs only assembles them (bit-identical
 * to its own pass). Only with friction (layer_dem_drift returns before it
 * without): the force calls pass LAYER_FT_FAST. */
LAYER_HOT static void drift_discs(gw_layer *L, double h, const double *ph, double *y)
{
    const int nb = L->nb, nc = L->nc;
    const double tp = L->tan_phi, alpha = L->p.damping, width = L->p.width;
    const double hh = 0.5 * h;
    double *restrict fe = y + 6L * nb, *restrict book = L->dem_book, *restrict rate = L->dem_rate,
                     *restrict fa = L->facc;
    double *restrict geo = L->geo, *restrict un_last = L->un_last, pd = 0, ed_sum = 0, ek_sum = 0;
    layer_tscr *restrict tscr = L->tscr;
    const layer_contact *cs = L->c;
    const int reg = L->reg_n > 0;
    memset(fa, 0, 3 * (size_t)nb * sizeof *fa);
    memset(rate, 0, (size_t)L->ntail * sizeof *rate);
    /* the common case has a path of its own: no damping (alpha 0, the impacts:
     * F_n = F_el, no damping power) and regions set; see below. Its loop
     * invariants in locals: the stores through the double arrays below may
     * alias L's fields for the compiler, which then reloaded them per contact */
    const int lean = !(alpha > 0) && reg;
    const int nreg = L->reg_n;
    const double rcx = L->reg_cx, rcy = L->reg_cy, riw2 = L->reg_iw2;
    /* Open contacts asleep: in a step a disc's centre moves by h v, v its
     * half-step velocity, which rounded is at most 2 h |v| <= 2 h (|v_x| +
     * |v_y|), summed into travel[i]. A contact found open at both ends of a
     * step with a gap g sleeps until the travel of its two discs has grown by
     * 0.99 g (less 1e-9 of its reach: the rounding of g and of the sums): it
     * is open at every step end before, where this loop would only write its
     * zeros again, and what reads geo of an open contact reads only its sign,
     * so the sleep changes no number. A velocity that is not finite makes
     * the travel sums NaN or infinite, and the comparison wakes the contact. */
    double *restrict travel = L->travel, *restrict wake = L->wake;
    const int *restrict tix = L->tix;
    const double h2 = 2 * h;
    for (int i = 0; i < nb; i++) {
        const double *s = ph + 6 * i;
        travel[i] += h2 * (fabs(s[3]) + fabs(s[4]));
    }
    /* Three passes, so that the divider's long chains of each contact (the
     * square roots and divisions of its geometry, v_t and stiffnesses) overlap
     * with other contacts' instead of stalling the force pass: 1. the
     * geometry and v_t of the awake contacts, gathered; 2. their stiffnesses
     * as if closed at both ends, over arrays (vectorised); 3. the tangential
     * step, the books and the forces, in the order of the list (the sums are
     * the single loop's, bit for bit). */
    const size_t sw = (size_t)nc + 1;
    int *restrict act = L->dem_act, na = 0;
    double *restrict wvt = L->dem_w, *restrict wu = wvt + sw, *restrict wks = wu + sw, *restrict wkts = wks + sw,
                     *restrict wsu = wkts + sw, *restrict wike = wsu + sw, *restrict wkm = wike + sw,
                     *restrict wikm = wkm + sw;
    for (int k = 0; k < nc; k++) {
        /* a contact closed at the step's start is awake: only the open-at-both-
         * ends path puts a contact to sleep, and it writes un_last = 0 (the
         * travel sums only grow between list rebuilds, which wake every
         * contact), so the closed ones, nearly all of a packed layer's, skip
         * the test and its four loads */
        const double ul = un_last[k];
        double tr = 0;
        if (!(ul > 0)) {
            tr = travel[tix[2 * k]] + travel[tix[2 * k + 1]];
            if (tr < wake[k])
                continue;
        }
        const layer_contact *c = cs + k;
        double nn[2];
        const double ue = disc_geometry(c, y, width, nn);
        if (!(ue > 0) && !(ul > 0)) {
            /* open at both ends (about half the listed contacts): what the general
             * path below does with its zeros (su, K_e, F_el, F_t all 0) */
            double *g = geo + 4 * k;
            g[0] = ue, g[1] = 0, g[2] = nn[0], g[3] = nn[1];
            un_last[k] = 0;
            fe[k] = 0;
            /* the gap -u_e: a pair's |x_b - x_a| - R_a - R_b (the negation is exact) */
            const double rs = c->ra + c->rb, gap = -ue;
            wake[k] = tr + (0.99 * gap - 1e-9 * rs); /* (not above tr: awake) */
            continue;
        }
        double *g = geo + 4 * k;
        g[0] = ue, g[2] = nn[0], g[3] = nn[1];
        act[na] = k;
        wvt[na] = disc_vt(c, ph, hh);
        wu[na] = ue;
        wks[na] = ul > 0 ? tscr[k].kt : 0;
        wkts[na] = c->kts;
        na++;
    }
    /* 2. (a contact not closed at both ends gets numbers pass 3 does not read) */
    drift_stiffness(na, wu, wks, wkts, wsu, wike, wkm, wikm);
    for (int j = 0; j < na; j++) {
        const int k = act[j];
        const layer_contact *c = cs + k;
        const double ul = un_last[k], ue = wu[j], *g0 = geo + 4 * k, nn[2] = {g0[2], g0[3]};
        const layer_tscr ts = tscr[k];
        if (lean && ue > 0 && ul > 0 && ts.kt > 0 && ts.ikt > 0 && ts.q >= 0) {
            /* closed at both ends with K_s, 1/K_s and the region known: the general
             * path below with its tests resolved (the same operations in the same
             * order, so the same numbers); the damping's zero terms (F_n - F_el) u_n'
             * are not added (adding +0 to the sums changes none of them) */
            const double kn = c->kn, kts = c->kts, ra = c->ra;
            const double su = wsu[j], ke = kts * su, fel = kn * ue * su;
            if (fel > 0 && ke > 0) {
                const int qa = c->qa, qb = c->qb, q0 = ts.q;
                const double iks = ts.ikt;
                const double ike = wike[j], km = wkm[j], ikm = wikm[j];
                geo[4 * k + 1] = su; /* (the first pass wrote the rest) */
                un_last[k] = ue;
                const double vt = wvt[j];
                const double cap = tp * kn * ue * su;
                const double f0 = fe[k], ftr = f0 + vt * h * km;
                const double f1 = ftr > cap ? cap : ftr < -cap ? -cap : ftr;
                const double ed = ftr == f1 ? 0 : 0.5 * (f0 + f1) * (ftr - f1) * ikm;
                const double ek = 0.5 * (f1 * f1 * (ikm - ike) + f0 * f0 * (iks - ikm));
                ed_sum += ed;
                ek_sum += ek;
                double *bk = book + 2 + 2 * q0; /* (one address: the two adds pair) */
                bk[0] += ed;
                bk[1] += ek;
                fe[k] = f1;
                /* the forces, without damping (alpha 0) */
                const layer_cforce o = layer_contact_force(c, su, fel, 0, 0, f1, 0, tp, 0, LAYER_FT_FAST);
                const double fn = o.fn, ft = o.ft;
                /* the contact's region: layer_contact_region_near written out */
                const double arm = ra - 0.5 * ue;
                const double px = y[6 * qa] + arm * nn[0], py = y[6 * qa + 1] + arm * nn[1];
                int q = -1;
                /* (a region below nreg is never the block's: layer_contact_region_pt
                 * gives its contacts nreg + 1, and a contact keeps its q0 only here) */
                if (q0 < nreg) {
                    const double dx = px - rcx, dy = py - rcy, d2 = (dx * dx + dy * dy) * riw2;
                    if ((double)q0 * q0 <= d2 && d2 < (double)(q0 + 1) * (q0 + 1))
                        q = q0;
                }
                tscr[k].kt = ke;
                tscr[k].ikt = ike;
                tscr[k].q = q >= 0 ? q : layer_contact_region_pt(L, c, px, py);
                const double fx = -fn * nn[0] - ft * nn[1], fy = -fn * nn[1] + ft * nn[0];
                double *da = fa + 3 * qa;
                da[0] += fx, da[1] += fy, da[2] += ft * ra;
                if (c->b >= 0) {
                    double *db = fa + 3 * qb;
                    db[0] -= fx, db[1] -= fy, db[2] += ft * c->rb;
                }
                continue;
            }
        }
        const int closed0 = un_last[k] > 0;
        const int q0 = closed0 ? tscr[k].q : -1;
        const double iks = closed0 ? tscr[k].ikt : 0; /* 1/K_s, 0 when open */
        const double ks = closed0 ? tscr[k].kt : 0;
        const double su = ue > 0 ? sqrt(ue) : 0, ke = c->kts * su;
        const double fel = ue > 0 ? c->kn * ue * su : 0;
        /* 1/K_e, K_m the step's mean stiffness (mean_kt) and 1/K_m */
        double ike = 0, ikm = 0, km = 0;
        if (ke > 0 && closed0) {
            ike = 1 / ke;
            km = mean_kt(ks, ke, un_last[k], ue);
            ikm = 1 / km;
        } else if (ke > 0) { /* closing: the start's gap from the start positions */
            ike = 1 / ke;
            km = mean_kt(0, ke, disc_overlap(c, ph, width), ue);
            ikm = 1 / km;
        } else if (closed0) { /* opening */
            km = mean_kt(ks, 0, un_last[k], disc_overlap(c, y, width));
            ikm = 1 / km;
        }
        geo[4 * k + 1] = su;
        un_last[k] = fel > 0 ? ue : 0; /* as the rhs sets it */
        double f1 = 0;
        if (iks > 0 || ike > 0) { /* the tangential step (see the file's head) */
            const double vt = wvt[j];
            const double cap = ue > 0 ? tp * c->kn * ue * su : 0;
            const double f0 = fe[k], ftr = f0 + vt * h * km;
            f1 = ftr > cap ? cap : ftr < -cap ? -cap : ftr;
            const double ed = ftr == f1 ? 0 : 0.5 * (f0 + f1) * (ftr - f1) * ikm;
            /* W_K: the kicks' work Fbar v_t h less dE_d and the change of F_t^2/(2 K_t),
             * F_e^2 (1/K_m - 1/K_e)/2 + F_s^2 (1/K_s - 1/K_m)/2 (an open end's F is 0) */
            const double ek = 0.5 * ((ike > 0 ? f1 * f1 * (ikm - ike) : 0) + (iks > 0 ? f0 * f0 * (iks - ikm) : 0));
            ed_sum += ed;
            ek_sum += ek;
            if (reg) {
                int q = q0 >= 0 ? q0 : layer_contact_region(L, c, y);
                book[2 + 2 * q] += ed;
                book[3 + 2 * q] += ek;
            }
        }
        fe[k] = f1;
        if (!(fel > 0))
            continue;
        double und;
        const layer_cforce o = disc_force(c, y, nn, su, fel, f1, alpha, tp, LAYER_FT_FAST, &und);
        const double fn = o.fn, ft = o.ft;
        pd += (fn - fel) * und;
        tscr[k].kt = ke;
        tscr[k].ikt = ike;
        if (reg) {
            const double arm = c->ra - 0.5 * ue;
            int q = layer_contact_region_near(L, c, y[6 * c->qa] + arm * nn[0], y[6 * c->qa + 1] + arm * nn[1],
                                              q0);
            tscr[k].q = q;
            rate[2 + 2 * q] += (fn - fel) * und;
        }
        const double fx = -fn * nn[0] - ft * nn[1], fy = -fn * nn[1] + ft * nn[0];
        double *da = fa + 3 * c->qa;
        da[0] += fx, da[1] += fy, da[2] += ft * c->ra;
        if (c->b >= 0) {
            double *db = fa + 3 * c->qb;
            db[0] -= fx, db[1] -= fy, db[2] += ft * c->rb;
        }
    }
    book[0] += ed_sum; /* (book is zero here: the drift's caller cleared it) */
    book[1] += ek_sum;
    rate[0] = pd;
    L->geo_valid = 1;
}

/* Keep the start of the step (t - h, t] that holds the peek (gw_layer.pk_y,
 * pk_c): ph and the predicted end y as the drift gets them, the contacts' F_t
 * and what the last rhs found of them. */
static void layer_dem_peek_keep(gw_layer *L, double t, double h, const double *ph, const double *y)
{
    const size_t nb6 = 6 * (size_t)L->nb;
    memcpy(L->pk_y, ph, nb6 * sizeof *ph);
    memcpy(L->pk_y + nb6, y, nb6 * sizeof *y);
    const double *fe = y + nb6;
    for (int k = 0; k < L->nc; k++) {
        const layer_tscr ts = L->tscr[k];
        L->pk_c[k] = (layer_pkc){fe[k], L->un_last[k], ts.kt, ts.ikt, ts.q};
    }
    L->pk_t0 = t - h, L->pk_h = h;
    L->pk_valid = 1;
}

int layer_dem_drift(double t, double h, const double *ph, double *y, void *P)
{
    gw_layer *L = P;
    const int nb = L->nb, nc = L->nc;
    const double tp = L->tan_phi, hh = 0.5 * h;
    double *ym = L->ymid, *book = L->dem_book;
    memset(book, 0, (size_t)L->ntail * sizeof *book);
    if (!(tp > 0))
        return 0;
    if (L->peek > t - h && L->peek <= t + 1e-9 * h) /* a sample in this step (layer_dem_peek) */
        layer_dem_peek_keep(L, t, h, ph, y);
    if (!L->off) { /* (the mid positions computed per contact, as below) */
        drift_discs(L, h, ph, y);
        return 0;
    }
    for (int i = 0; i < nb; i++) { /* mid-step positions, half-step velocities */
        const double *s = ph + 6 * i;
        double *m = ym + 6 * i;
        m[3] = s[3], m[4] = s[4], m[5] = s[5];
        m[0] = s[0] + hh * s[3], m[1] = s[1] + hh * s[4], m[2] = s[2] + hh * s[5];
    }
    double *fe = y + 6L * nb; /* F_t at the step's start, advanced in place */
    for (int k = 0; k < nc; k++) { /* clumps: the rhs (layer_model.c) does the forces */
        const layer_contact *c = &L->c[k];
        double ue, nn[2], um;
        layer_contact_geometry(L, c, y, &ue, nn, NULL);
        const double ks = L->un_last[k] > 0 ? L->tscr[k].kt : 0;
        const double su = ue > 0 ? sqrt(ue) : 0, ke = c->kts * su;
        if (!(ks > 0) && !(ke > 0)) {
            fe[k] = 0; /* open at both ends (F_s is 0: zeroed when it opened) */
            continue;
        }
        const double vt = layer_contact_vt(L, c, ym, &um);
        double us = L->un_last[k], ns[2]; /* the start's gap of a closing contact: the start positions */
        if (!(ks > 0))
            layer_contact_geometry(L, c, ph, &us, ns, NULL);
        const double km = mean_kt(ks, ke, us, ue); /* (an opening's ue is the end's gap) */
        const double cap = ue > 0 ? tp * c->kn * ue * su : 0;
        const double f0 = fe[k], ftr = f0 + km * vt * h;
        const double f1 = ftr > cap ? cap : ftr < -cap ? -cap : ftr;
        fe[k] = f1;
        double ed = 0.5 * (f0 + f1) * (ftr - f1) / km;
        /* W_K as in drift_discs; K_t is not defined at an open end, where F is 0 */
        double ek = 0.5 * ((ke > 0 ? f1 * f1 * (1 / km - 1 / ke) : 0) + (ks > 0 ? f0 * f0 * (1 / ks - 1 / km) : 0));
        book[0] += ed;
        book[1] += ek;
        if (L->reg_n > 0) {
            int q = L->un_last[k] > 0 ? L->tscr[k].q : layer_contact_region(L, c, y);
            book[2 + 2 * q] += ed;
            book[3 + 2 * q] += ek;
        }
    }
    return 0;
}

/* The tangential step of contact k from the step's start kept in pc over hp,
 * the drift's own arithmetic (drift_discs's general path for discs, the clump
 * loop of layer_dem_drift otherwise): php the start positions with the
 * partial step's half-step velocities, yp its end positions, ymp its mid
 * positions (clumps). F_t at the end in *f1, the books added into book. */
static void peek_contact(const gw_layer *L, int k, const layer_pkc *pc, double hp, const double *php,
                         const double *yp, const double *ymp, double *book, double *f1)
{
    const layer_contact *c = L->c + k;
    const double tp = L->tan_phi, width = L->p.width;
    const int closed0 = pc->u > 0;
    const double ks = closed0 ? pc->kt : 0, f0 = pc->f;
    double iks = closed0 ? pc->ikt : 0; /* (1/K_s: the clumps' rhs keeps K_s only) */
    double ue, nn[2], vt, km = 0, ikm = 0, ike = 0;
    if (!L->off)
        ue = disc_geometry(c, yp, width, nn);
    else
        layer_contact_geometry(L, c, yp, &ue, nn, NULL);
    const double su = ue > 0 ? sqrt(ue) : 0, ke = c->kts * su;
    *f1 = 0;
    if (!L->off) {
        if (ke > 0 && closed0) {
            ike = 1 / ke;
            km = mean_kt(ks, ke, pc->u, ue);
            ikm = 1 / km;
        } else if (ke > 0) {
            ike = 1 / ke;
            km = mean_kt(0, ke, disc_overlap(c, php, width), ue);
            ikm = 1 / km;
        } else if (closed0) {
            km = mean_kt(ks, 0, pc->u, disc_overlap(c, yp, width));
            ikm = 1 / km;
        }
        if (!(iks > 0) && !(ike > 0))
            return;
        vt = disc_vt(c, php, 0.5 * hp);
    } else {
        if (!(ks > 0) && !(ke > 0))
            return;
        double um, us = pc->u, ns[2];
        vt = layer_contact_vt(L, c, ymp, &um);
        if (!(ks > 0))
            layer_contact_geometry(L, c, php, &us, ns, NULL);
        km = mean_kt(ks, ke, us, ue);
        ikm = 1 / km;
        ike = ke > 0 ? 1 / ke : 0;
        iks = ks > 0 ? 1 / ks : 0;
    }
    const double cap = ue > 0 ? tp * c->kn * ue * su : 0;
    const double ftr = f0 + vt * hp * km;
    *f1 = ftr > cap ? cap : ftr < -cap ? -cap : ftr;
    const double ed = ftr == *f1 ? 0 : 0.5 * (f0 + *f1) * (ftr - *f1) * ikm;
    const double ek = 0.5 * ((ike > 0 ? *f1 * *f1 * (ikm - ike) : 0) + (iks > 0 ? f0 * f0 * (iks - ikm) : 0));
    book[0] += ed;
    book[1] += ek;
    if (L->reg_n > 0) {
        const int q = pc->q >= 0 && closed0 ? pc->q : layer_contact_region(L, c, yp);
        book[2 + 2 * q] += ed;
        book[3 + 2 * q] += ek;
    }
}

void layer_dem_peek(gw_layer *L, double t)
{
    const double h = L->pk_h, hp = t - L->pk_t0;
    /* the step's end itself (the solver hands it back within 1e-9 of a step):
     * its own state; a start kept for another step: nothing to do */
    if (!L->dem || !L->pk_valid || !(L->tan_phi > 0) || !(hp > 0) || !(hp < h) ||
        fabs(L->pk_t0 + h - t) <= 1e-9 * h)
        return;
    const int nb = L->nb, nc = L->nc, nt = L->ntail;
    const size_t nb6 = 6 * (size_t)nb;
    /* the partial step's bodies from the kept ph (x0, v0 + (h/2) a0) and
     * predicted end (v0 + h a0): its half-step velocities v0 + (hp/2) a0,
     * its end and mid positions x0 + hp v, x0 + (hp/2) v */
    const double *ph = L->pk_y, *ye = ph + nb6, r = hp / h;
    double *php = L->pk_y + 2 * nb6, *yp = php + nb6, *book = yp + nb6, *ymp = L->ymid;
    for (int i = 0; i < nb; i++)
        for (int j = 0; j < 3; j++) {
            const size_t q = 6 * (size_t)i + (size_t)j, u = q + 3;
            const double dv = ye[u] - ph[u], v = ph[u] - (1 - r) * dv;
            php[q] = ph[q], php[u] = v;
            yp[q] = ph[q] + hp * v, yp[u] = v + r * dv;
            ymp[q] = ph[q] + 0.5 * hp * v, ymp[u] = v;
        }
    memset(book, 0, (size_t)nt * sizeof *book);
    double *fe = L->y + nb6, *tail = fe + nc;
    for (int k = 0; k < nc; k++)
        peek_contact(L, k, L->pk_c + k, hp, php, yp, ymp, book, fe + k);
    /* the tail: the line between the step's ends less its share of the
     * step's books (the kicks' part, the normal damping's, stays a line) */
    for (int q = 0; q < nt; q++)
        tail[q] += book[q] - r * L->dem_book[q];
    L->stamp++;
}

int layer_dem_project(double t, double h, double *y, double *ydot, void *P)
{
    (void)t, (void)h, (void)ydot;
    gw_layer *L = P;
    double *tail = y + 6L * L->nb + L->nc;
    for (int q = 0; q < L->ntail; q++)
        tail[q] += L->dem_book[q];
    L->stamp++;
    return 0;
}

int layer_dem_carried(gw_layer *L, const double *y, double *yd)
{
    const int nb = L->nb;
    const size_t nb6 = 6 * (size_t)nb;
    L->dem_carry = 0;
    memcpy(yd, L->dem_f, nb6 * sizeof *yd);
    memset(yd + nb6, 0, (size_t)L->nc * sizeof *yd);
    memcpy(yd + nb6 + L->nc, L->dem_f + nb6, (size_t)L->ntail * sizeof *yd);
    if (!L->off) { /* the geometry the snapshot reads (as drift_discs writes it) */
        for (int k = 0; k < L->nc; k++) {
            double *g = L->geo + 4 * k, nn[2];
            const double ue = disc_geometry(&L->c[k], y, L->p.width, nn);
            g[0] = ue, g[1] = ue > 0 ? sqrt(ue) : 0, g[2] = nn[0], g[3] = nn[1];
        }
        L->geo_pos = 1;
    }
    return 0;
}

/* The rhs of a disc-only layer in DEM mode (layer_model.c's, B.1-B.4): Hertz
 * normal force, the tangential force F_t of the state (layer_dem_drift's, used
 * as the Coulomb cap allows), gravity; after a drift the forces are
 * drift_discs's of the same state, only assembled here. F_t's rate
 * is 0 (the drift advances it); the ledger tail gets the normal damping power
 * only (the tangential books are layer_dem_drift's). */
int layer_dem_rhs(double t, const double *y, double *yd, void *P)
{
    (void)t;
    gw_layer *L = P;
    if (L->dem_carry) /* the first call after a list rebuild */
        return layer_dem_carried(L, y, yd);
    const int n = L->nb;
    const double g = L->p.gravity, tp = L->tan_phi, alpha = L->p.damping, width = L->p.width;
    double pd = 0;
    double *rtail = L->reg_n > 0 ? yd + 6 * n + L->nc + 2 : NULL, *un_last = L->un_last;
    if (L->geo_valid) { /* drift_discs computed the forces at this state */
        L->geo_valid = 0;
        const double *fa = L->facc;
        for (int i = 0; i < n; i++) {
            const double *s = y + 6 * i;
            double *d = yd + 6 * i;
            if (L->fixed[i]) {
                d[0] = d[1] = d[2] = d[3] = d[4] = d[5] = 0;
                continue;
            }
            d[0] = s[3], d[1] = s[4], d[2] = s[5];
            d[3] = fa[3 * i] * L->minv[i];
            d[4] = fa[3 * i + 1] * L->minv[i] - g;
            d[5] = fa[3 * i + 2] * L->iinv[i];
        }
        memset(yd + 6 * n, 0, (size_t)L->nc * sizeof *yd);
        memcpy(yd + 6 * n + L->nc, L->dem_rate, (size_t)L->ntail * sizeof *yd);
        L->geo_pos = 1;
        return 0;
    }
    layer_tscr *tscr = L->tscr; /* at a (re)start: the rhs's own pass */
    for (int q = 0; rtail && q < 2 * (L->reg_n + 2); q++)
        rtail[q] = 0;
    for (int i = 0; i < n; i++) {
        const double *s = y + 6 * i;
        double *d = yd + 6 * i;
        d[0] = s[3], d[1] = s[4], d[2] = s[5];
        d[3] = d[4] = d[5] = 0;
    }
    for (int k = 0; k < L->nc; k++) {
        const layer_contact *c = &L->c[k];
        double un, su, nn[2];
        yd[6 * n + k] = 0;
        double *gk = L->geo + 4 * k; /* kept: the snapshot reads it */
        un = disc_geometry(c, y, width, nn);
        su = un > 0 ? sqrt(un) : 0;
        gk[0] = un, gk[1] = su, gk[2] = nn[0], gk[3] = nn[1];
        const double fel = un > 0 ? c->kn * un * su : 0;
        if (!(fel > 0)) { /* open, or F_n underflows */
            un_last[k] = 0;
            continue;
        }
        un_last[k] = un;
        double und;
        const layer_cforce o = disc_force(c, y, nn, su, fel, y[6 * n + k], alpha, tp,
                                          tp > 0 ? LAYER_FT_FAST : LAYER_FT_NONE, &und);
        const double fn = o.fn, ft = o.ft;
        pd += (fn - fel) * und;
        if (tp > 0) {
            tscr[k].kt = c->kts * su;
            tscr[k].ikt = 1 / tscr[k].kt;
        }
        if (rtail) {
            const double arm = c->ra - 0.5 * un;
            int q = layer_contact_region_pt(L, c, y[6 * c->qa] + arm * nn[0], y[6 * c->qa + 1] + arm * nn[1]);
            tscr[k].q = q;
            rtail[2 * q] += (fn - fel) * und;
        }
        const double fx = -fn * nn[0] - ft * nn[1], fy = -fn * nn[1] + ft * nn[0];
        double *da = yd + 6 * c->qa;
        da[3] += fx, da[4] += fy, da[5] += ft * c->ra;
        if (c->b >= 0) {
            double *db = yd + 6 * c->qb;
            db[3] -= fx, db[4] -= fy, db[5] += ft * c->rb;
        }
    }
    layer_rhs_finish(L, yd, n, g, pd, 0);
    L->geo_pos = 1;
    return 0;
}
