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
 * evaluation of the roots (in DEM mode every step end), with the block's
 * dv_y/dt from its listed contacts; the largest v_y is then located between
 * the evaluations around it (vy_max_located: the cubic through v_y and
 * dv_y/dt at both ends, cut at the opening of the block's last contact,
 * after which the flight is exact), so that T_i does not sit on the step
 * grid (docs/outcomes.md).
 * Units: SI.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"

int gw_layer_watch_block(gw_layer *L, gw_layer_block_fn fn, void *ctx, gw_err *err)
{
    if (!L)
        return gw_err_set(err, GW_EINVAL, "gw_layer_watch_block: L is NULL");
    if (L->block_body < 0)
        return gw_err_set(err, GW_EINVAL, "layer: the block watch needs a block (gw_layer_set_block)");
    if (L->solver)
        return gw_err_set(err, GW_EINVAL, "layer: the block watch must be set before gw_layer_start");
    L->watch = 1;
    L->gone = 0;
    L->fc.target = -1;
    L->watch_fn = fn;
    L->watch_ctx = ctx;
    memset(L->probe, 0, sizeof L->probe);
    L->ext = (gw_layer_block_extremes){.vy_max = -INFINITY, .y_min = INFINITY,
                                       .t_vy_max = NAN, .t_y_min = NAN, .vx_at_vy_max = NAN};
    for (int q = 0; q < 3; q++)
        L->vb_t[q] = L->vb_vy[q] = L->vb_ay[q] = L->vb_vx[q] = L->vb_gc[q] = NAN;
    return GW_OK;
}

/* The largest v_y located between the evaluations around the largest one
 * (L->vb_*), into (t, v_y, v_x) of *ex. Between two evaluations a < b with
 * dv_y/dt > 0 at a and < 0 at b, v_y is the cubic with the values and slopes
 * of both ends (Hermite), and its largest value is where its slope, a
 * quadratic, falls through zero. Where the block's last contact opens between
 * them (the largest overlap through 0, linearly, at t_o), the flight from t_o
 * is exact, v_y = v_y(b) + g (b - t), dv_y/dt = -g, and b moves to t_o: the
 * force of the opening contact falls to 0 within the step, and across a whole
 * fast step (10 us) the cubic would not follow it. */
static void vy_max_located(const gw_layer *L, gw_layer_block_extremes *ex)
{
    double t[3], v[3], a[3], vx[3], gc[3];
    for (int q = 0; q < 3; q++)
        t[q] = L->vb_t[q], v[q] = L->vb_vy[q], a[q] = L->vb_ay[q], vx[q] = L->vb_vx[q], gc[q] = L->vb_gc[q];
    const double g = L->p.gravity;
    /* the bracket: after the largest evaluation while v_y still rises there */
    const int lo = a[1] > 0 ? 1 : 0, hi = lo + 1;
    if (isnan(t[lo]) || isnan(t[hi]) || !(t[lo] < t[hi]) || !(a[lo] >= 0) || !(a[hi] <= 0))
        return; /* not bracketed: the largest evaluation stands */
    double tb = t[hi], vb = v[hi], ab = a[hi];
    if (gc[lo] >= 0 && gc[hi] < 0) { /* free flight from t_o */
        const double to = t[lo] + gc[lo] / (gc[lo] - gc[hi]) * (tb - t[lo]);
        if (to > t[lo] && to < tb)
            vb = v[hi] + g * (tb - to), tb = to, ab = -g;
    }
    /* on s in [0, 1] over h = tb - t_lo: slope / h = A s^2 + B s + C */
    const double h = tb - t[lo], dv = (vb - v[lo]) / h;
    const double A = 3 * a[lo] + 3 * ab - 6 * dv, B = -4 * a[lo] - 2 * ab + 6 * dv, C = a[lo];
    /* the root where the slope goes from + to - (2 A s + B < 0 there), from
     * the form without cancellation: q = -(B + sign(B) sqrt(B^2 - 4 A C)) / 2,
     * roots q / A and C / q (C / q alone when A vanishes) */
    const double disc = B * B - 4 * A * C;
    if (!(disc >= 0))
        return;
    const double q = -0.5 * (B + (B < 0 ? -sqrt(disc) : sqrt(disc)));
    const double r1 = q != 0 ? C / q : NAN, r2 = A != 0 ? q / A : NAN;
    const int ok1 = r1 >= 0 && r1 <= 1 && 2 * A * r1 + B <= 0, ok2 = r2 >= 0 && r2 <= 1 && 2 * A * r2 + B <= 0;
    if (!ok1 && !ok2)
        return;
    double s = ok1 ? r1 : r2;
    const double s2 = s * s, s3 = s2 * s;
    const double vm = (2 * s3 - 3 * s2 + 1) * v[lo] + (s3 - 2 * s2 + s) * h * a[lo] + (-2 * s3 + 3 * s2) * vb +
                      (s3 - s2) * h * ab;
    if (!(vm >= v[1]) || !isfinite(vm))
        return;
    ex->t_vy_max = t[lo] + s * h;
    ex->vy_max = vm;
    /* v_x linearly between the interval's ends: at t_o it is the flight's,
     * v_x(b), which gravity does not change */
    ex->vx_at_vy_max = vx[lo] + s * (vx[hi] - vx[lo]);
}

void gw_layer_block_extremes_get(const gw_layer *L, gw_layer_block_extremes *ex)
{
    if (!L || !ex) {
        if (ex)
            memset(ex, 0, sizeof *ex);
        return;
    }
    if (L->watch) {
        *ex = L->ext;
        if (ex->n > 0)
            vy_max_located(L, ex);
    } else {
        *ex = (gw_layer_block_extremes){.vy_max = NAN, .t_vy_max = NAN, .vx_at_vy_max = NAN,
                                        .y_min = NAN, .t_y_min = NAN, .n = 0};
    }
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

/* The block has left the layer for good (GW_LAYER_BLOCK_GONE, gw_layer.h) in
 * state y (touching: one of its contacts closed, the floor's among them):
 * GW_LAYER_GONE_* or 0. Every other body is bounded by its disc (or clump)
 * radius brad about its centre, and its points move at most |w| brad faster
 * than its centre. Only with a wall missing (never in the walled box: runs
 * with all walls are unchanged), O(bodies) per evaluation.
 *  - Without the floor, touching nothing: below every other body's lowest
 *    point moving down at least as fast as any of their points, or beyond
 *    the left or right side of them all (that wall missing) moving away at
 *    least as fast: with the same gravity on every body and no wall on the
 *    block's side, nothing can reach it again.
 *  - With the floor kept, beyond a missing side wall: by geometry alone, the
 *    block's whole body beyond where that wall would be (x = 0 or the width)
 *    and beyond every other body's extent (so out of contact with every
 *    disc; the floor its only possible contact), whether it still moves or
 *    lies on the floor. Until session 44 the rule asked it to move away at
 *    least as fast as every other body: a block that came to rest on the
 *    floor beyond the layer was never declared gone and ran to t-max
 *    undecided, and one rolling away inside the box was declared gone at once. */
static int block_gone(const gw_layer *L, const double *y, int touching)
{
    const int w = L->p.walls, bb = L->block_body, floor = (w & GW_LAYER_WALL_BOTTOM) != 0;
    const double *s = y + 6 * bb, rb = L->brad[bb];
    double lo = INFINITY, vlo = INFINITY, left = INFINITY, vleft = INFINITY, right = -INFINITY, vright = -INFINITY;
    for (int b = 0; b < L->nb; b++) {
        if (b == bb)
            continue;
        const double *q = y + 6 * b, spin = fabs(q[5]) * L->brad[b];
        lo = fmin(lo, q[1] - L->brad[b]), vlo = fmin(vlo, q[4] - spin);
        left = fmin(left, q[0] - L->brad[b]), vleft = fmin(vleft, q[3] - spin);
        right = fmax(right, q[0] + L->brad[b]), vright = fmax(vright, q[3] + spin);
    }
    if (floor) {
        if (!(w & GW_LAYER_WALL_LEFT) && s[0] + rb < fmin(left, 0.0))
            return GW_LAYER_GONE_LEFT;
        if (!(w & GW_LAYER_WALL_RIGHT) && s[0] - rb > fmax(right, L->p.width))
            return GW_LAYER_GONE_RIGHT;
        return 0;
    }
    if (touching)
        return 0;
    if (s[1] + rb < lo && s[4] < 0 && s[4] <= vlo)
        return GW_LAYER_GONE_BELOW;
    if (!(w & GW_LAYER_WALL_LEFT) && s[0] + rb < left && s[3] < 0 && s[3] <= vleft)
        return GW_LAYER_GONE_LEFT;
    if (!(w & GW_LAYER_WALL_RIGHT) && s[0] - rb > right && s[3] > 0 && s[3] >= vright)
        return GW_LAYER_GONE_RIGHT;
    return 0;
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
    /* the block's dv_y/dt, for the largest v_y between evaluations: from its
     * contacts while one of them is closed (gc > 0: the same overlaps as
     * layer_body_contact_fy's); without, the sum of no forces, +0, and
     * dv_y/dt = -g to the bit (a block in flight: 47 % of the evaluations of
     * the --exact default impact to 3 ms). Not only at the evaluations that
     * enter vb_*: an evaluation becomes vb_*[0] when the next one is a new
     * largest v_y, which it cannot know, and its state is gone by then. */
    const double fy = gc > 0 ? layer_body_contact_fy(L, y, bb, all ? NULL : L->wblk, L->nwblk) : 0;
    const double ay = L->fixed[bb] ? 0 : fy * L->minv[bb] - L->p.gravity;
    L->probe[0] = L->probe[1];
    L->probe[1] = (layer_probe){.t = t, .g = {w[0], w[1]}, .x = s[0], .y = s[1], .vx = s[3], .vy = s[4], .ay = ay};
    gw_layer_block_extremes *e = &L->ext;
    if (s[4] > e->vy_max) {
        /* the evaluation before it in time brackets the new largest value; the
         * one after is still to come */
        const layer_probe *pv = &L->probe[0];
        const int before = e->n > 0 && pv->t < t;
        L->vb_t[0] = before ? pv->t : NAN, L->vb_vy[0] = pv->vy, L->vb_ay[0] = pv->ay, L->vb_vx[0] = pv->vx;
        L->vb_gc[0] = pv->g[1];
        L->vb_t[1] = t, L->vb_vy[1] = s[4], L->vb_ay[1] = ay, L->vb_vx[1] = s[3], L->vb_gc[1] = gc;
        L->vb_t[2] = NAN;
        e->vy_max = s[4];
        e->t_vy_max = t;
        e->vx_at_vy_max = s[3];
    } else if (t > L->vb_t[1] && !(t >= L->vb_t[2])) { /* the earliest after it */
        L->vb_t[2] = t, L->vb_vy[2] = s[4], L->vb_ay[2] = ay, L->vb_vx[2] = s[3], L->vb_gc[2] = gc;
    } else if (t < L->vb_t[1] && !(t <= L->vb_t[0])) { /* the latest before it */
        L->vb_t[0] = t, L->vb_vy[0] = s[4], L->vb_ay[0] = ay, L->vb_vx[0] = s[3], L->vb_gc[0] = gc;
    }
    if (s[1] < e->y_min) {
        e->y_min = s[1];
        e->t_y_min = t;
    }
    e->n++;
    if (L->fc.target >= 0)
        first_contact(L, t, y);
    int gone;
    if (!L->gone && (L->p.walls & GW_LAYER_WALLS_ALL) != GW_LAYER_WALLS_ALL && (gone = block_gone(L, y, gc >= 0))) {
        /* reported once, at this evaluation (no root: nothing to locate, the
         * state only moves further away) */
        L->gone = 1;
        const gw_layer_block_event ev = {.kind = GW_LAYER_BLOCK_GONE, .dir = gone, .t = t, .x = s[0], .y = s[1],
                                         .vx = s[3], .vy = s[4], .located = 0};
        if (L->watch_fn)
            L->watch_fn(L->watch_ctx, &ev);
    }
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
