/*
 * layer_springs.c: a sample's tangential springs (gw_layer_spring) and the
 * layer: from the settling's last state into the sample (layer_springs_take,
 * layer_make.c) and from the sample into an impact's first contact list
 * (layer_springs_pend, layer_springs_load; layer_impact.c, gw_layer_start in
 * layer_sim.c). docs/physics.md 2.1, eqs. B.2-B.4.
 *
 * The state holds each contact's elastic tangential force F_t; a sample the
 * displacement u = F_t / K_t, K_t = (k_t K_n^(1/3)) u_n^(1/2) (B.4), taken at
 * the overlap of the positions written (layer_spring_overlap, the reader's),
 * of the force the model uses (the state clamped to the cap tan(phi) F_n).
 * An impact starts a listed contact from F_t = K_t u with its own K_t,
 * clipped to its own cap (layer_sample_springs.c says why).
 * Units: SI (m, N).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"

int layer_springs_take(const gw_layer *L, const double *x, const double *y, const double *r, double width,
                       gw_layer_spring **out, int *nout)
{
    *out = NULL;
    *nout = 0;
    const double *f = L->y + 6 * L->nb;
    int m = 0;
    for (int k = 0; k < L->nc; k++)
        m += f[k] != 0;
    if (m == 0)
        return GW_OK;
    gw_layer_spring *sp = malloc((size_t)m * sizeof *sp);
    if (!sp)
        return GW_ENOMEM;
    int j = 0;
    for (int k = 0; k < L->nc; k++) {
        const layer_contact *c = &L->c[k];
        /* (the block's contacts only where there is a block: without one
         * L->block is -1, LAYER_LEFT, and every left-wall spring was left out
         * of layer-make's samples) */
        if (f[k] == 0 || (L->block >= 0 && (c->a == L->block || c->b == L->block)))
            continue;
        /* the overlap of the positions written (the reader's), K_t and the cap
         * there: the force used (the state clamped to the cap) as u_t */
        const double un = layer_spring_overlap(x, y, r, width, c->a, c->b);
        if (!(un > 0))
            continue;
        const double kt = c->kts * sqrt(un), cap = layer_cap(L->tan_phi, c->kn, un);
        const double ft = fmax(-cap, fmin(cap, f[k]));
        if (!(kt > 0) || ft == 0)
            continue;
        sp[j++] = (gw_layer_spring){.a = c->a, .b = c->b, .u = ft / kt};
    }
    if (j == 0) {
        free(sp);
        return GW_OK;
    }
    *out = sp;
    *nout = j;
    return GW_OK;
}

int layer_springs_pend(gw_layer *L, const gw_layer_spring *sp, int n)
{
    free(L->spr);
    L->spr = NULL;
    L->nspr = 0;
    if (n <= 0)
        return GW_OK;
    L->spr = malloc((size_t)n * sizeof *L->spr);
    if (!L->spr)
        return GW_ENOMEM;
    for (int k = 0; k < n; k++)
        L->spr[k] = layer_spring_sorted(sp[k]);
    qsort(L->spr, (size_t)n, sizeof *L->spr, layer_spring_cmp);
    L->nspr = n;
    return GW_OK;
}

void layer_springs_load(gw_layer *L)
{
    if (!L->spr)
        return;
    double *f = L->y + 6 * L->nb;
    for (int k = 0; k < L->nc; k++) {
        const layer_contact *c = &L->c[k];
        const gw_layer_spring key = {.a = c->a, .b = c->b};
        const gw_layer_spring *q = bsearch(&key, L->spr, (size_t)L->nspr, sizeof key, layer_spring_cmp);
        if (!q)
            continue;
        double un, nn[2];
        layer_contact_geometry(L, c, L->y, &un, nn, NULL);
        if (!(un > 0))
            continue;
        const double kt = c->kts * sqrt(un), cap = layer_cap(L->tan_phi, c->kn, un);
        f[k] = fmax(-cap, fmin(cap, kt * q->u));
    }
    free(L->spr);
    L->spr = NULL;
    L->nspr = 0;
    L->stamp++;
}
