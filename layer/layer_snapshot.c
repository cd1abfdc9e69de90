/*
 * layer_snapshot.c: what is read off the layer's current state for the
 * ledgers and the ring analyses (docs/physics.md 2.4, B.7-B.14): per contact
 * the overlap u_n, the elastic F_n = K_n u_n^(3/2), the used F_t (clamped to
 * the cap F_n tan phi), K_t and the contact point, made once per state
 * (L->stamp); and by ring about a point, the kinetic energy of the bodies,
 * the strain energy 2/5 F_n u_n + F_t^2 / (2 K_t) of the closed contacts and
 * the mean coordination. Separate from the equations of motion
 * (layer_model.c): it reads a state between steps, never within one.
 * Units: SI (m, N, J).
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"
#include "gw_number_impl.h"

const double *layer_snapshot(const gw_layer *L)
{
    if (L->snap_stamp == L->stamp)
        return L->snap;
    gw_layer *M = (gw_layer *)L; /* the cache only */
    const double *y = L->y, tp = L->tan_phi;
    double *xy = M->snap_xy, arm[2];
    if (L->off) {
        for (int i = 0; i < L->n; i++)
            layer_disc_xy(L, y, i, xy + 2 * i, arm);
    } else {
        for (int i = 0; i < L->n; i++)
            xy[2 * i] = y[6 * i], xy[2 * i + 1] = y[6 * i + 1];
    }
    for (int i = 0; L->reg_n > 0 && i < L->nb; i++) /* the last snapshot's region as a hint */
        M->snap_breg[i] = layer_body_region_near(L, i, y, M->snap_breg[i]);
    /* DEM mode, discs only: the last rhs evaluation's geometry is the state's
     * (the same arithmetic; layer_dem.c) */
    const double *geo = L->dem && !L->off && L->geo_pos ? L->geo : NULL;
    for (int k = 0; geo && k < L->nc; k++) {
        const layer_contact *c = &L->c[k];
        const double *g = geo + 4 * k, *pa = xy + 2 * c->a;
        double *o = M->snap + LAYER_SNAP_W * k, un = g[0], su = g[1];
        o[LAYER_SNAP_UN] = o[LAYER_SNAP_FN] = o[LAYER_SNAP_FT] = o[LAYER_SNAP_KT] = 0;
        o[LAYER_SNAP_PX] = pa[0], o[LAYER_SNAP_PY] = pa[1];
        if (!(un > 0))
            continue;
        o[LAYER_SNAP_PX] += (c->ra - 0.5 * un) * g[2];
        o[LAYER_SNAP_PY] += (c->ra - 0.5 * un) * g[3];
        double fn = c->kn * un * su, cap = tp * fn, f = y[6 * L->nb + k];
        o[LAYER_SNAP_UN] = un;
        o[LAYER_SNAP_FN] = fn;
        o[LAYER_SNAP_KT] = c->kts * su;
        o[LAYER_SNAP_FT] = f > cap ? cap : f < -cap ? -cap : f;
    }
    for (int k = 0; !geo && k < L->nc; k++) {
        const layer_contact *c = &L->c[k];
        double *o = M->snap + LAYER_SNAP_W * k;
        const double *pa = xy + 2 * c->a, *pb = c->b >= 0 ? xy + 2 * c->b : pa;
        double nn[2], un = layer_pair_geometry(c, pa, pb, L->p.width, nn);
        o[LAYER_SNAP_UN] = o[LAYER_SNAP_FN] = o[LAYER_SNAP_FT] = o[LAYER_SNAP_KT] = 0;
        o[LAYER_SNAP_PX] = pa[0] + (c->ra - 0.5 * un) * nn[0];
        o[LAYER_SNAP_PY] = pa[1] + (c->ra - 0.5 * un) * nn[1];
        if (!(un > 0))
            continue;
        double su = sqrt(un), fn = c->kn * un * su, cap = tp * fn, f = y[6 * L->nb + k];
        o[LAYER_SNAP_UN] = un;
        o[LAYER_SNAP_FN] = fn;
        o[LAYER_SNAP_KT] = c->kts * su;
        o[LAYER_SNAP_FT] = f > cap ? cap : f < -cap ? -cap : f;
    }
    M->snap_stamp = L->stamp;
    return L->snap;
}

int gw_layer_rings_check(const gw_layer *L, double cx, double cy, double w, int nring, const double *kinetic,
                         const double *strain, const double *coord, gw_err *err)
{
    static const char who[] = "gw_layer_rings";
    if (!L)
        return gw_err_set(err, GW_EINVAL, "%s: L is NULL", who);
    if (!isfinite(cx) || !isfinite(cy))
        return gw_err_set(err, GW_EINVAL, "%s: centre %s = %g m must be finite", who, !isfinite(cx) ? "cx" : "cy",
                          !isfinite(cx) ? cx : cy);
    /* w = 0 put every particle outside the rings (zeros), NaN gave NaN, a
     * negative width counted none: each without a word */
    if (!(w > 0) || !isfinite(w))
        return gw_err_set(err, GW_EINVAL, "%s: ring width w = %g m must be finite and > 0", who, w);
    if (w < DBL_MIN) { /* subnormal: every disc outside the rings, zeros without a word */
        const gw_num_range r = {0, INFINITY, 1, 0, 0, 0};
        return gw_num_subnormal_refused(who, "ring width w", &r, err);
    }
    if (nring < 0)
        return gw_err_set(err, GW_EINVAL, "%s: nring = %d rings must be >= 0", who, nring);
    if (nring > 0 && (!kinetic || !strain || !coord))
        return gw_err_set(err, GW_EINVAL, "%s: %s is NULL (%d rings)", who,
                          !kinetic ? "kinetic" : !strain ? "strain" : "coord", nring);
    return GW_OK;
}

void gw_layer_rings(const gw_layer *L, double cx, double cy, double w, int nring,
                    double *kin, double *strain, double *coord)
{
    if (nring <= 0) /* no ring: a negative count asked realloc for SIZE_MAX bytes (an abort under ASan) */
        return;
    if (gw_layer_rings_check(L, cx, cy, w, nring, kin, strain, coord, NULL) != GW_OK) {
        for (int k = 0; k < nring; k++) {
            if (kin)
                kin[k] = NAN;
            if (strain)
                strain[k] = NAN;
            if (coord)
                coord[k] = NAN;
        }
        return;
    }
    const double *y = L->y, *snap = layer_snapshot(L), *xy = L->snap_xy;
    gw_layer *M = (gw_layer *)L; /* scratch only */
    const size_t need = (size_t)nring + (size_t)L->n;
    if (M->ring_cap < need) {
        int *b = realloc(M->ring_np, need * sizeof *b);
        if (b)
            M->ring_np = b, M->ring_cap = need;
    }
    int *np = M->ring_cap >= need ? M->ring_np : NULL, *rk = np ? np + nring : NULL;
    for (int k = 0; np && k < nring; k++)
        np[k] = 0;
    for (int k = 0; k < nring; k++)
        kin[k] = strain[k] = coord[k] = 0;
    /* ring of a point, or -1 outside the rings */
#define RING(px, py) layer_ring_of((px) - cx, (py) - cy, w, nring)
    /* the rings of the regional ledgers (layer_regions.c): the snapshot has the
     * bodies' (the same arithmetic as ring_of) */
    const int regs = L->reg_n > 0 && cx == L->reg_cx && cy == L->reg_cy && w == L->reg_w &&
                     nring == L->reg_n;
    /* DEM mode, discs only: the contacts' regions the step found at these
     * positions (ring, outside, or block: the block's contacts by their point) */
    const int dem_q = regs && L->dem && !L->off && L->geo_pos && L->tan_phi > 0;
    for (int i = 0; i < L->nb; i++) { /* kinetic energy by body centre */
        if (i == L->block_body)
            continue;
        const double *s = y + 6 * i;
        int k = regs ? (L->snap_breg[i] < nring ? L->snap_breg[i] : -1) : RING(s[0], s[1]);
        if (k >= 0)
            kin[k] += 0.5 * L->m[i] * (s[3] * s[3] + s[4] * s[4]) + 0.5 * L->inertia[i] * s[5] * s[5];
    }
    for (int i = 0; np && i < L->n; i++) { /* coordination: per disc */
        if (i == L->block)
            rk[i] = -1;
        else if (regs && !L->off) /* discs only: disc i is body i */
            rk[i] = L->snap_breg[i] < nring ? L->snap_breg[i] : -1;
        else
            rk[i] = RING(xy[2 * i], xy[2 * i + 1]);
        if (rk[i] >= 0)
            np[rk[i]]++;
    }
    for (int c = 0; np && c < L->nc; c++) {
        const double *o = snap + LAYER_SNAP_W * c;
        if (!(o[LAYER_SNAP_FN] > 0))
            continue;
        int k = dem_q && L->tscr[c].q < nring ? L->tscr[c].q
                : dem_q && L->tscr[c].q == nring ? -1 : RING(o[LAYER_SNAP_PX], o[LAYER_SNAP_PY]);
        if (k >= 0)
            strain[k] += 0.4 * o[LAYER_SNAP_FN] * o[LAYER_SNAP_UN] +
                         o[LAYER_SNAP_FT] * o[LAYER_SNAP_FT] / (2 * o[LAYER_SNAP_KT]);
        /* coordination: each end inside a ring counts once for that ring */
        if (rk[L->c[c].a] >= 0)
            coord[rk[L->c[c].a]] += 1;
        if (L->c[c].b >= 0 && rk[L->c[c].b] >= 0)
            coord[rk[L->c[c].b]] += 1;
    }
#undef RING
    for (int k = 0; k < nring; k++)
        coord[k] = np && np[k] > 0 ? coord[k] / np[k] : NAN;
}

int gw_layer_contact_count(const gw_layer *L, int i)
{
    if (!L)
        return 0;
    const double *snap = layer_snapshot(L);
    int c = 0;
    for (int k = 0; k < L->nc; k++)
        c += (L->c[k].a == i || L->c[k].b == i) && snap[LAYER_SNAP_W * k + LAYER_SNAP_UN] > 0;
    return c;
}
