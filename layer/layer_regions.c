/*
 * layer_regions.c: the energy ledger restricted to regions (physics.md 2.4:
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
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"

int layer_contact_region_at(const gw_layer *L, const layer_contact *c, const double *y,
                            double un, const double nn[2])
{
    /* (a wall id equal to block_body = -1 books a left-wall contact of a layer
     * without a block as "block": kept as it was) */
    if (layer_body(L, c->a) == L->block_body ||
        (c->b >= 0 ? layer_body(L, c->b) : c->b) == L->block_body)
        return L->reg_n + 1;
    double sa[2], am[2], arm = L->r[c->a] - 0.5 * un;
    layer_disc_xy(L, y, c->a, sa, am);
    double dx = sa[0] + arm * nn[0] - L->reg_cx, dy = sa[1] + arm * nn[1] - L->reg_cy;
    double d2 = (dx * dx + dy * dy) / (L->reg_w * L->reg_w);
    double lim = (double)L->reg_n * L->reg_n;
    return d2 < lim ? (int)sqrt(d2) : L->reg_n;
}

int layer_contact_region(const gw_layer *L, const layer_contact *c, const double *y)
{
    double un, nn[2];
    layer_contact_geometry(L, c, y, &un, nn, NULL);
    return layer_contact_region_at(L, c, y, un, nn);
}

/* Region of body i by its centre of mass. */
static int particle_region(const gw_layer *L, int i, const double *y)
{
    if (i == L->block_body)
        return L->reg_n + 1;
    const double *s = y + 6 * i;
    double d = hypot(s[0] - L->reg_cx, s[1] - L->reg_cy) / L->reg_w;
    return d < L->reg_n ? (int)d : L->reg_n;
}

int gw_layer_set_regions(gw_layer *L, double cx, double cy, double w, int nring, gw_err *err)
{
    if (L->solver)
        return gw_err_set(err, GW_EINVAL, "layer: regions must be set before gw_layer_start");
    if (!isfinite(cx) || !isfinite(cy))
        return gw_err_set(err, GW_EINVAL, "layer regions: centre (%g, %g) m must be finite", cx, cy);
    if (!(w > 0) || !isfinite(w))
        return gw_err_set(err, GW_EINVAL, "layer regions: ring width %g m must be positive", w);
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
    /* before gw_layer_start the list is empty: the tail follows the particles */
    for (int q = 2; q < ntail; q++)
        L->y[n6 + q] = 0;
    L->reg_cx = cx, L->reg_cy = cy, L->reg_w = w, L->reg_n = nring;
    L->ntail = ntail;
    L->cap_y = n6 + ntail;
    L->dim = n6 + L->nc + ntail;
    return GW_OK;
}

int gw_layer_region_count(const gw_layer *L)
{
    return L->reg_n > 0 ? L->reg_n + 2 : 0;
}

void layer_ledger_sum(const gw_layer *L, gw_layer_energy *out, int by_region)
{
    const double *y = L->y;
    for (int i = 0; i < L->nb; i++) { /* bodies */
        const double *s = y + 6 * i;
        gw_layer_energy *e = out + (by_region ? particle_region(L, i, y) : 0);
        double ke = 0.5 * L->m[i] * (s[3] * s[3] + s[4] * s[4]) + 0.5 * L->inertia[i] * s[5] * s[5];
        if (i == L->block_body)
            e->kinetic_block += ke;
        else
            e->kinetic_soil += ke;
        if (!L->fixed[i])
            e->potential += L->m[i] * L->p.gravity * (s[1] - L->y_ref[i]);
    }
    for (int k = 0; k < L->nc; k++) {
        double fn, ft, kt, un, nn[2];
        layer_contact_forces(L, k, y, &fn, &ft, &kt);
        if (!(fn > 0))
            continue;
        layer_contact_geometry(L, &L->c[k], y, &un, nn, NULL);
        gw_layer_energy *e = out + (by_region ? layer_contact_region_at(L, &L->c[k], y, un, nn) : 0);
        e->strain_normal += 0.4 * fn * un;
        e->strain_tangent += ft * ft / (2 * kt);
    }
}

int gw_layer_region_ledger(const gw_layer *L, gw_layer_energy *out)
{
    const int nr = gw_layer_region_count(L);
    if (nr == 0)
        return 0;
    memset(out, 0, (size_t)nr * sizeof *out);
    layer_ledger_sum(L, out, 1);
    const double *tail = L->y + 6 * L->nb + L->nc + 2;
    for (int q = 0; q < nr; q++) {
        gw_layer_energy *e = out + q;
        e->dissipated = tail[2 * q];
        e->mindlin_excess = tail[2 * q + 1];
        e->total = e->kinetic_block + e->kinetic_soil + e->strain_normal + e->strain_tangent +
                   e->mindlin_excess + e->dissipated + e->potential;
    }
    return nr;
}
