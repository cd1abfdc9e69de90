/*
 * layer_regions.c: the energy ledger restricted to regions (docs/physics.md 2.4:
 * "every term can be restricted to a region D"; eqs. B.7-B.14).
 *
 * The regions partition the system: rings k = 0 .. nring-1 of width w around a
 * centre (distance in [k w, (k+1) w)), then "outside" (beyond the last ring),
 * then "block" (the block particle and every contact it takes part in).
 * Kinetic and potential energy are booked by body centre (a disc's centre, a
 * clump's centre of mass), strain energy and
 * the two integrated terms (friction dissipation E_d, Mindlin stiffness work
 * W_K) by contact point. E_d and W_K are path integrals, so each region has its
 * own pair of state components, integrated with the rest of the ODE system from
 * the contact power of layer_model.c. The regional ledgers add up to the global
 * ledger (to rounding), which the tests check.
 * Units: SI (m, J).
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"
#include "gw_number_impl.h"

int layer_contact_region_at(const gw_layer *L, const layer_contact *c, const double *y,
                            double un, const double nn[2])
{
    /* (a wall id equal to block_body = -1 books a left-wall contact of a layer
     * without a block as "block": kept as it was) */
    double sa[2], am[2], arm = L->r[c->a] - 0.5 * un;
    layer_disc_xy(L, y, c->a, sa, am);
    return layer_contact_region_pt(L, c, sa[0] + arm * nn[0], sa[1] + arm * nn[1]);
}

int layer_contact_region(const gw_layer *L, const layer_contact *c, const double *y)
{
    double un, nn[2];
    layer_contact_geometry(L, c, y, &un, nn, NULL);
    return layer_contact_region_at(L, c, y, un, nn);
}


int gw_layer_set_regions(gw_layer *L, double cx, double cy, double w, int nring, gw_err *err)
{
    if (!L)
        return gw_err_set(err, GW_EINVAL, "gw_layer_set_regions: L is NULL");
    if (L->solver)
        return gw_err_set(err, GW_EINVAL, "layer: regions must be set before gw_layer_start");
    if (!isfinite(cx) || !isfinite(cy))
        return gw_err_set(err, GW_EINVAL, "layer regions: centre (%g, %g) m must be finite", cx, cy);
    if (!(w > 0) || !isfinite(w))
        return gw_err_set(err, GW_EINVAL, "layer regions: ring width %g m must be positive", w);
    /* A subnormal width (4.9e-324 m) was taken: 1/w^2 overflowed to inf, a
     * disc at the centre fell in ring 0 * inf = NaN (cast to a ring index).
     * The program's rule for a subnormal, and a width whose square is no
     * normal double (below 1.4917e-154 m) refused with it: every ring
     * lookup divides by w^2. A subnormal centre is a coordinate of 0 m in
     * effect (cx, cy are where a run computed its impact): taken. */
    if (w < DBL_MIN) {
        const gw_num_range r = {0, INFINITY, 1, 0, 0, 0};
        return gw_num_subnormal_refused("layer regions", "ring width w", &r, err);
    }
    if (!(w * w >= DBL_MIN))
        return gw_err_set(err, GW_EINVAL, "layer regions: ring width w = %g m is too small: its square is no normal "
                          "double (give a width of at least 1.49167e-154 m)", w);
    if (nring < 1 || nring > 10000)
        return gw_err_set(err, GW_EINVAL, "layer regions: %d rings (1 .. 10000)", nring);
    const long n6 = 6L * L->nb;
    int ntail = 2 + 2 * (nring + 2);
    double *y = realloc(L->y, (size_t)(n6 + ntail) * sizeof *y);
    if (!y)
        return gw_err_set(err, GW_ENOMEM, "layer regions: out of memory");
    L->y = y;
    double *sc = realloc(L->scale, (size_t)(n6 + ntail) * sizeof *sc);
    if (!sc)
        return gw_err_set(err, GW_ENOMEM, "layer regions: out of memory");
    L->scale = sc;
    long *dr = realloc(L->drift, (size_t)(n6 + ntail) * sizeof *dr);
    if (!dr)
        return gw_err_set(err, GW_ENOMEM, "layer regions: out of memory");
    L->drift = dr;
    /* before gw_layer_start the list is empty: the tail follows the particles */
    for (int q = 2; q < ntail; q++)
        L->y[n6 + q] = 0;
    L->reg_cx = cx, L->reg_cy = cy, L->reg_w = w, L->reg_n = nring;
    L->reg_iw2 = 1 / (w * w);
    L->stamp++;
    L->ntail = ntail;
    L->cap_y = n6 + ntail;
    L->dim = n6 + L->nc + ntail;
    return GW_OK;
}

int gw_layer_region_count(const gw_layer *L)
{
    if (!L)
        return 0;
    return L->reg_n > 0 ? L->reg_n + 2 : 0;
}

/* Add body i's kinetic energy ke and potential energy pe into e. */
static inline void body_add(const gw_layer *L, int i, double ke, double pe, gw_layer_energy *e)
{
    if (i == L->block_body)
        e->kinetic_block += ke;
    else
        e->kinetic_soil += ke;
    if (!L->fixed[i])
        e->potential += pe;
}

void layer_ledger_sum(const gw_layer *L, gw_layer_energy *global, gw_layer_energy *regions)
{
    const double *snap = layer_snapshot(L);
    for (int i = 0; i < L->nb; i++) { /* bodies */
        const double *s = L->y + 6 * i;
        const double ke = 0.5 * L->m[i] * (s[3] * s[3] + s[4] * s[4]) + 0.5 * L->inertia[i] * s[5] * s[5];
        const double pe = L->m[i] * L->p.gravity * (s[1] - L->y_ref[i]);
        if (global)
            body_add(L, i, ke, pe, global);
        if (regions)
            body_add(L, i, ke, pe, regions + L->snap_breg[i]);
    }
    /* DEM mode, discs only: the regions the step found at these positions */
    const int dem_q = L->dem && !L->off && L->geo_pos && L->tan_phi > 0;
    for (int k = 0; k < L->nc; k++) {
        const double *o = snap + LAYER_SNAP_W * k;
        if (!(o[LAYER_SNAP_FN] > 0))
            continue;
        double sn = 0.4 * o[LAYER_SNAP_FN] * o[LAYER_SNAP_UN];
        double st = o[LAYER_SNAP_FT] * o[LAYER_SNAP_FT] / (2 * o[LAYER_SNAP_KT]);
        if (global)
            global->strain_normal += sn, global->strain_tangent += st;
        if (regions) {
            gw_layer_energy *e = regions + (dem_q ? L->tscr[k].q
                                                  : layer_contact_region_pt(L, &L->c[k], o[LAYER_SNAP_PX],
                                                                            o[LAYER_SNAP_PY]));
            e->strain_normal += sn, e->strain_tangent += st;
        }
    }
}

static void ledger_total(gw_layer_energy *e)
{
    e->total = e->kinetic_block + e->kinetic_soil + e->strain_normal + e->strain_tangent +
               e->mindlin_excess + e->dissipated + e->potential;
}

/* The ledger's integrated terms (E_d, W_K, then per region) from the state's
 * tail into e (may be NULL) and the nr regions, and their totals. */
static void ledger_tail(const gw_layer *L, gw_layer_energy *e, gw_layer_energy *regions, int nr)
{
    const double *tail = L->y + 6 * L->nb + L->nc;
    /* tail_work: the tail holds E_st + W_K, and e and regions E_st already */
    if (e) {
        e->dissipated = tail[0];
        e->mindlin_excess = L->tail_work ? tail[1] - e->strain_tangent : tail[1];
        ledger_total(e);
    }
    for (int q = 0; q < nr; q++) {
        regions[q].dissipated = tail[2 + 2 * q];
        regions[q].mindlin_excess = L->tail_work ? tail[3 + 2 * q] - regions[q].strain_tangent : tail[3 + 2 * q];
        ledger_total(regions + q);
    }
}

int gw_layer_ledgers(const gw_layer *L, gw_layer_energy *e, gw_layer_energy *regions)
{
    if (!L) { /* no layer: no regions, a ledger of NaN */
        if (e) {
            e->kinetic_block = e->kinetic_soil = e->strain_normal = e->strain_tangent = NAN;
            e->mindlin_excess = e->dissipated = e->potential = e->total = NAN;
        }
        return 0;
    }
    const int nr = regions ? gw_layer_region_count(L) : 0;
    if (e)
        memset(e, 0, sizeof *e);
    if (nr > 0)
        memset(regions, 0, (size_t)nr * sizeof *regions);
    layer_ledger_sum(L, e, nr > 0 ? regions : NULL);
    ledger_tail(L, e, regions, nr);
    return nr;
}

/* layer_ledgers_rings' body: a static function, because GCC gives the ifunc
 * of an external function's target clones default visibility whatever
 * -fvisibility says (libgranwave.so exported layer_ledgers_rings and its
 * resolver; test_install_api) */
LAYER_HOT static int ledgers_rings(const gw_layer *L, gw_layer_energy *e, gw_layer_energy *regions, double cx,
                                   double cy, double w, int nring, double *kin, double *strain, double *coord,
                                   double *diss)
{
    /* the rings are the regions 0 .. nring - 1 (same centre, width and count) */
    const int rings_regions = L->reg_n > 0 && cx == L->reg_cx && cy == L->reg_cy && w == L->reg_w &&
                              nring == L->reg_n;
    const int regs = e && rings_regions;
    const int dem_q = L->dem && !L->off && L->geo_pos && L->tan_phi > 0;
    gw_layer *M = (gw_layer *)L; /* scratch only */
    const size_t need = (size_t)nring + (size_t)L->n;
    if (regs && dem_q && M->ring_cap < need) {
        int *b = realloc(M->ring_np, need * sizeof *b);
        if (b)
            M->ring_np = b, M->ring_cap = need;
    }
    /* the rings' E_d: ledger_tail's regional dissipated, from the state's tail */
    const double *tail = L->y + 6 * L->nb + L->nc;
    for (int q = 0; diss && q < nring; q++)
        diss[q] = rings_regions ? tail[2 + 2 * q] : NAN;
    if (!regs || !dem_q || M->ring_cap < need) { /* the two passes */
        int nr = gw_layer_ledgers(L, e, regions);
        gw_layer_rings(L, cx, cy, w, nring, kin, strain, coord);
        return nr;
    }
    /* one pass: gw_layer_ledgers's and gw_layer_rings's sums, in their order
     * and with their arithmetic (the rings are the regions 0 .. nring - 1) */
    const int nr = regions ? gw_layer_region_count(L) : 0;
    memset(e, 0, sizeof *e);
    if (regions)
        memset(regions, 0, (size_t)nr * sizeof *regions);
    /* the snapshot's numbers (layer_snapshot), from the step's geometry */
    const double *y = L->y, *fts = y + 6 * L->nb, tp = L->tan_phi;
    int *np = M->ring_np, *rk = np + nring;
    for (int k = 0; k < nring; k++)
        kin[k] = strain[k] = coord[k] = 0, np[k] = 0;
    /* the global ledger's sums in registers (the same additions in the same
     * order as body_add and the contacts' +=, so the same numbers): through e
     * every += was a load and a store the next one waited for */
    double kb = 0, ks = 0, pot = 0, sn_sum = 0, st_sum = 0;
    const int bb = L->block_body, blk = L->block, nb = L->nb, nc = L->nc;
    const double grav = L->p.gravity, *mass = L->m, *inert = L->inertia, *yref = L->y_ref;
    const unsigned char *fixed = L->fixed;
    const int same = L->snap_stamp == L->stamp;
    for (int i = 0; i < nb; i++) { /* bodies (discs: body i is disc i) */
        const double *s = y + 6 * i;
        const double ke = 0.5 * mass[i] * (s[3] * s[3] + s[4] * s[4]) + 0.5 * inert[i] * s[5] * s[5];
        const double pe = mass[i] * grav * (s[1] - yref[i]);
        const int q = same ? L->snap_breg[i] : (M->snap_breg[i] = layer_body_region_near(L, i, y, L->snap_breg[i]));
        if (i == bb)
            kb += ke;
        else
            ks += ke;
        if (!fixed[i])
            pot += pe;
        if (regions) {
            gw_layer_energy *r = regions + q;
            if (i == bb)
                r->kinetic_block += ke;
            else
                r->kinetic_soil += ke;
            if (!fixed[i])
                r->potential += pe;
        }
        if (i != bb && q < nring)
            kin[q] += ke;
        rk[i] = i == blk || q >= nring ? -1 : q;
        if (rk[i] >= 0)
            np[rk[i]]++;
    }
    const layer_contact *cs = L->c;
    const layer_tscr *tscr = L->tscr;
    for (int k = 0; k < nc; k++) {
        const layer_contact *c = cs + k;
        const double *g = L->geo + 4 * k, un = g[0], su = g[1];
        if (!(un > 0))
            continue;
        const double fn = c->kn * un * su, cap = tp * fn, f = fts[k], kt = c->kts * su;
        if (!(fn > 0))
            continue;
        const double ft = f > cap ? cap : f < -cap ? -cap : f;
        const double sn = 0.4 * fn * un, st = ft * ft / (2 * kt);
        const int q = tscr[k].q;
        sn_sum += sn, st_sum += st;
        if (regions)
            regions[q].strain_normal += sn, regions[q].strain_tangent += st;
        int rq = q < nring ? q : -1;
        if (q > nring) { /* the block's contacts by their point */
            const double arm = c->ra - 0.5 * un;
            rq = layer_ring_of(y[6 * c->a] + arm * g[2] - cx, y[6 * c->a + 1] + arm * g[3] - cy, w, nring);
        }
        if (rq >= 0)
            strain[rq] += sn + st;
        if (rk[c->a] >= 0)
            coord[rk[c->a]] += 1;
        if (c->b >= 0 && rk[c->b] >= 0)
            coord[rk[c->b]] += 1;
    }
    e->kinetic_block = kb, e->kinetic_soil = ks, e->potential = pot;
    e->strain_normal = sn_sum, e->strain_tangent = st_sum;
    for (int k = 0; k < nring; k++)
        coord[k] = np[k] > 0 ? coord[k] / np[k] : NAN;
    ledger_tail(L, e, regions, nr);
    return nr;
}

int layer_ledgers_rings(const gw_layer *L, gw_layer_energy *e, gw_layer_energy *regions, double cx, double cy,
                        double w, int nring, double *kin, double *strain, double *coord, double *diss)
{
    return ledgers_rings(L, e, regions, cx, cy, w, nring, kin, strain, coord, diss);
}

int gw_layer_region_ledger(const gw_layer *L, gw_layer_energy *out)
{
    return gw_layer_ledgers(L, NULL, out);
}
