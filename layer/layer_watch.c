/*
 * layer_watch.c: events on the block (gw_layer_watch_block), from which an
 * impact's outcome is read (physics.md 2.3: the normal velocity vanishing and
 * changing sign, the block leaving the layer, its largest normal velocity).
 *
 * Two event functions join the layer's roots, last:
 *     g_v = v_y of the block                                   (m/s)
 *     g_c = max over the block's listed contacts of u_n        (m; -skin if none)
 * g_c > 0 while the block touches a particle or a wall, < 0 in free flight; it
 * is continuous across contact-list rebuilds, since a touching pair is always
 * listed. With the located backends the solver stops at their roots; with
 * verlet a root is reported at the end of the step that crossed it, and the
 * crossing is placed inside the step by linear interpolation of g between the
 * step's two ends (probe[0], probe[1]):
 *     s = g0 / (g0 - g1),  t* = t0 + s (t1 - t0),  state* = state0 + s (state1 - state0)
 * (time error O(h^2) for a step h, about 1e-11 s at h = 5 us).
 * The running extremes (largest v_y, lowest centre y) are updated at every
 * evaluation of the roots. In DEM mode that is every step end; between step
 * ends a smooth v_y exceeds its largest step-end value by at most
 * |dv_y/dt| h / 2 x (h / tau), tau the contact time (about 1e-6 of the
 * velocity change over a contact for h = tau / 200).
 * Units: SI.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"

int gw_layer_watch_block(gw_layer *L, gw_layer_block_fn fn, void *ctx, gw_err *err)
{
    if (L->block_body < 0)
        return gw_err_set(err, GW_EINVAL, "layer: the block watch needs a block (gw_layer_set_block)");
    if (L->solver)
        return gw_err_set(err, GW_EINVAL, "layer: the block watch must be set before gw_layer_start");
    L->watch = 1;
    L->fc.target = -1;
    L->watch_fn = fn;
    L->watch_ctx = ctx;
    memset(L->probe, 0, sizeof L->probe);
    L->ext = (gw_layer_block_extremes){.vy_max = -INFINITY, .y_min = INFINITY,
                                       .t_vy_max = NAN, .t_y_min = NAN, .vx_at_vy_max = NAN};
    return GW_OK;
}

void gw_layer_block_extremes_get(const gw_layer *L, gw_layer_block_extremes *ex)
{
    if (L->watch)
        *ex = L->ext;
    else
        *ex = (gw_layer_block_extremes){.vy_max = NAN, .t_vy_max = NAN, .vx_at_vy_max = NAN,
                                        .y_min = NAN, .t_y_min = NAN, .n = 0};
}

void layer_watch_first_contact(gw_layer *L, int target)
{
    L->fc = (layer_first_contact){.target = target, .kb_min = INFINITY, .t_min = NAN, .ed_min = NAN,
                                  .edb_min = NAN, .t_open = NAN, .ed_open = NAN, .kb_open = NAN,
                                  .t_last = NAN, .lo = {NAN}, .hi = {NAN}};
}

/* The block's kinetic energy (translation and rotation) in state y, J. */
static double block_kinetic(const gw_layer *L, const double *y)
{
    const int bb = L->block_body;
    const double *s = y + 6 * bb;
    return 0.5 * L->m[bb] * (s[3] * s[3] + s[4] * s[4]) + 0.5 * L->inertia[bb] * s[5] * s[5];
}

/* The first contact at one evaluation of the roots (state y at t). */
void layer_watch_first_contact_freeze(gw_layer *L)
{
    L->fc.frozen = 1;
}

static void first_contact(gw_layer *L, double t, const double *y)
{
    layer_first_contact *f = &L->fc;
    if (f->frozen || !isnan(f->t_open))
        return;
    double pb[2], pt[2], arm[2];
    layer_disc_xy(L, y, L->block, pb, arm);
    layer_disc_xy(L, y, f->target, pt, arm);
    const double ov = L->r[L->block] + L->r[f->target] - hypot(pb[0] - pt[0], pb[1] - pt[1]);
    const double *tail = y + 6 * L->nb + L->nc, ed = tail[0];
    if (ov > 0) {
        const double kb = block_kinetic(L, y);
        const double edb = L->reg_n > 0 ? tail[2 + 2 * (L->reg_n + 1)] : NAN;
        f->n_touch++;
        if (kb < f->kb_min) {
            /* the evaluation before it in time brackets the new smallest value
             * from below; the one after is still to come */
            if (f->n_touch > 1 && f->t_last < t)
                f->lo[0] = f->t_last, f->lo[1] = f->kb_last, f->lo[2] = f->ed_last, f->lo[3] = f->edb_last;
            else
                f->lo[0] = NAN;
            f->hi[0] = NAN;
            f->kb_min = kb;
            f->t_min = t;
            f->ed_min = ed;
            f->edb_min = edb;
        } else if (isnan(f->hi[0]) && t > f->t_min) {
            f->hi[0] = t, f->hi[1] = kb, f->hi[2] = ed, f->hi[3] = edb;
        } else if (t > f->t_min && t < f->hi[0]) {
            f->hi[0] = t, f->hi[1] = kb, f->hi[2] = ed, f->hi[3] = edb;
        } else if (t < f->t_min && (isnan(f->lo[0]) || t > f->lo[0])) {
            f->lo[0] = t, f->lo[1] = kb, f->lo[2] = ed, f->lo[3] = edb;
        }
        f->t_last = t, f->ov_last = ov, f->ed_last = ed, f->kb_last = kb, f->edb_last = edb;
    } else if (f->n_touch > 0 && t > f->t_last) {
        /* opened between the last evaluation that saw it overlapped and this one */
        const double a = f->ov_last / (f->ov_last - ov);
        f->t_open = f->t_last + a * (t - f->t_last);
        f->ed_open = f->ed_last + a * (ed - f->ed_last);
        f->kb_open = f->kb_last + a * (block_kinetic(L, y) - f->kb_last);
    }
}

/* The quadratic through (-1, v[0]), (0, v[1]), (r, v[2]) at u. */
static double quad_at(double r, const double *v, double u)
{
    const double a = (v[2] - v[1] + r * (v[0] - v[1])) / (r * (1 + r)), b = a - (v[0] - v[1]);
    return v[1] + u * (b + a * u);
}

void layer_watch_first_contact_min(const gw_layer *L, double *t, double *kb, double *ed, double *edb)
{
    const layer_first_contact *f = &L->fc;
    *t = f->t_min, *kb = f->kb_min, *ed = f->ed_min, *edb = f->edb_min;
    if (isnan(f->lo[0]) || isnan(f->hi[0]) || !(f->lo[0] < f->t_min && f->t_min < f->hi[0]))
        return;
    /* in units of the step before the smallest value, the evaluations at -1, 0
     * and r; equal steps (the fast mode's) give r = 1 exactly, so that the result
     * does not depend on the step ends' times, whose last bits differ where a
     * sample ends the step (the outcome is the same at every dt-out that is a
     * multiple of the step, to the last bit) */
    const double h0 = f->t_min - f->lo[0];
    double r = (f->hi[0] - f->t_min) / h0;
    if (fabs(r - 1) < 1e-9)
        r = 1;
    const double k[3] = {f->lo[1], f->kb_min, f->hi[1]};
    const double a = (k[2] - k[1] + r * (k[0] - k[1])) / (r * (1 + r)), b = a - (k[0] - k[1]);
    if (!(a > 0) || !isfinite(a))
        return;
    /* the vertex, between the outer two as k[1] is the smallest */
    const double u = fmin(fmax(-b / (2 * a), -1.0), r);
    const double e[3] = {f->lo[2], f->ed_min, f->hi[2]}, eb[3] = {f->lo[3], f->edb_min, f->hi[3]};
    *t = f->t_min + u * h0;
    *kb = fmin(quad_at(r, k, u), f->kb_min);
    *ed = quad_at(r, e, u);
    *edb = quad_at(r, eb, u);
}

void layer_watch_roots(gw_layer *L, double t, const double *y, double *g)
{
    const int bb = L->block_body;
    const double *s = y + 6 * bb;
    double gc = -L->p.skin;
    if (L->wblk_gen != L->st.rebuilds || L->wblk_body != bb || !L->wblk) {
        /* the block's contacts of this list (the roots run every step) */
        int *w = realloc(L->wblk, ((size_t)L->nc + 1) * sizeof *w);
        if (w) {
            L->wblk = w, L->nwblk = 0;
            for (int k = 0; k < L->nc; k++)
                if (L->c[k].qa == bb || L->c[k].qb == bb)
                    w[L->nwblk++] = k;
            L->wblk_gen = L->st.rebuilds, L->wblk_body = bb;
        }
    }
    const int all = !L->wblk || L->wblk_gen != L->st.rebuilds || L->wblk_body != bb;
    for (int j = 0; j < (all ? L->nc : L->nwblk); j++) { /* (all: out of memory for the index) */
        const layer_contact *c = &L->c[all ? j : L->wblk[j]];
        if (c->qa != bb && c->qb != bb)
            continue;
        double un, nn[2];
        layer_contact_geometry(L, c, y, &un, nn, NULL);
        if (un > gc)
            gc = un;
    }
    double *w = g + layer_root_count(L);
    w[0] = s[4];
    w[1] = gc;
    L->probe[0] = L->probe[1];
    L->probe[1] = (layer_probe){.t = t, .g = {w[0], w[1]}, .x = s[0], .y = s[1], .vx = s[3], .vy = s[4]};
    gw_layer_block_extremes *e = &L->ext;
    if (s[4] > e->vy_max) {
        e->vy_max = s[4];
        e->t_vy_max = t;
        e->vx_at_vy_max = s[3];
    }
    if (s[1] < e->y_min) {
        e->y_min = s[1];
        e->t_y_min = t;
    }
    e->n++;
    if (L->fc.target >= 0)
        first_contact(L, t, y);
}

int layer_watch_dispatch(gw_layer *L)
{
    const int w0 = layer_root_count(L);
    int other = 0;
    for (int k = 0; k < w0; k++)
        other |= L->roots[k] != 0;
    if (!L->watch)
        return other;
    gw_layer_block_event ev[2];
    int ne = 0;
    const layer_probe *p0 = &L->probe[0], *p1 = &L->probe[1];
    for (int q = 0; q < 2; q++) {
        if (!L->roots[w0 + q])
            continue;
        gw_layer_block_event *e = &ev[ne++];
        const int dir = L->roots[w0 + q] > 0 ? 1 : -1;
        if (!L->dem) { /* located: the solver stopped just past the root */
            const double *s = L->y + 6 * L->block_body;
            *e = (gw_layer_block_event){.kind = q, .dir = dir, .t = L->t, .x = s[0], .y = s[1],
                                        .vx = s[3], .vy = s[4], .located = 1};
            continue;
        }
        /* verlet: p1 is the step end (L->t), p0 its start */
        double g0 = p0->g[q], g1 = p1->g[q], f = g0 != g1 ? g0 / (g0 - g1) : 1;
        if (!(f >= 0 && f <= 1) || !(p0->t < p1->t))
            f = 1;
        *e = (gw_layer_block_event){.kind = q, .dir = dir, .t = p0->t + f * (p1->t - p0->t),
                                    .x = p0->x + f * (p1->x - p0->x), .y = p0->y + f * (p1->y - p0->y),
                                    .vx = p0->vx + f * (p1->vx - p0->vx),
                                    .vy = p0->vy + f * (p1->vy - p0->vy), .located = 0};
    }
    if (ne == 2 && ev[1].t < ev[0].t) {
        gw_layer_block_event tmp = ev[0];
        ev[0] = ev[1];
        ev[1] = tmp;
    }
    for (int i = 0; L->watch_fn && i < ne; i++)
        L->watch_fn(L->watch_ctx, &ev[i]);
    return other;
}
