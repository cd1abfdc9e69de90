/*
 * layer_clumps.c: rigid bodies of the layer, type B soil (docs/physics.md 2.2:
 * "rigid clumps of discs, quasi-rectangular, aspect ratio uniform in [1, 4]").
 *
 * A body is a set of member discs i at fixed offsets o_i from its centre of mass
 * in the body frame; at orientation theta the member centre is
 *   x_i = X + R(theta) o_i,  v_i = V + omega e_z x (R(theta) o_i).
 * Mass and inertia, clump_mass = sum (members under the mass law of layer_create.c):
 *   M = sum m_i,  X = sum m_i x_i / M,  I = sum (I_i + m_i |x_i - X|^2),
 * the area (volume) shared by overlapping members counted twice: the mass law
 * is per disc, and the double count is what a clump of PFC2D balls does too.
 * clump_mass = union (disc law): the clump is the members' union U of unit
 * thickness, M = rho |U|, X its centroid, I = rho int_U |x - X|^2 dA, each
 * integral computed column by column (union_moments): on a vertical line the
 * union is a union of chords, merged exactly, and the columns add up by the
 * midpoint rule with UNION_COLUMNS columns (relative error ~1e-6, test_layer_clumps).
 * A disc alone is a body with o = 0; a layer without clumps keeps the disc-only
 * code path (bid = off = NULL), bit for bit the model before clumps existed.
 * Members of one clump must overlap or touch (their contact graph connected,
 * |x_i - x_j| <= (r_i + r_j)(1 + 1e-9)), at most LAYER_CLUMP_MEMBERS of them
 * (the check is quadratic in the members: a bound keeps a hostile sample of
 * one huge body from stalling the reader); contacts are only listed between discs
 * of different bodies (layer_contacts.c).
 * Pluviation shapes (layer_make.c): a row of k discs of radius r, centre
 * spacing d, gives a quasi-rectangle of aspect ratio a = 1 + (k - 1) d / (2 r);
 * k = 1 + ceil(1.5 (a - 1)) keeps d <= 4 r / 3 (neighbours overlap by at least
 * r / 3, so the outline stays close to a rectangle), and r is set so that the
 * clump's area (union of the discs) equals pi R_eq^2: the equivalent radius
 * R_eq follows the discs' grading curve.
 * Units: SI (m, kg, kg m^2, rad).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"

void layer_disc_xy(const gw_layer *L, const double *y, int i, double p[2], double arm[2])
{
    if (!L->off) {
        p[0] = y[6 * i], p[1] = y[6 * i + 1];
        arm[0] = arm[1] = 0;
        return;
    }
    const double *s = y + 6 * L->bid[i];
    const double ox = L->off[2 * i], oy = L->off[2 * i + 1];
    if (ox == 0 && oy == 0) {
        arm[0] = arm[1] = 0;
    } else {
        double c = cos(s[2]), sn = sin(s[2]);
        arm[0] = c * ox - sn * oy;
        arm[1] = sn * ox + c * oy;
    }
    p[0] = s[0] + arm[0], p[1] = s[1] + arm[1];
}

enum { UNION_COLUMNS = 8192 };

/* Moments of the union of k discs (x, y, r), centres taken relative to
 * (x[m[0]], y[m[0]]): mom = {area, int x dA, int y dA, int (x^2 + y^2) dA}.
 * iv is scratch for 2k doubles. */
static void union_moments(const gw_layer_body *b, const int *m, int k, double *iv, double mom[4])
{
    const double x0 = b[m[0]].x, y0 = b[m[0]].y;
    double lo = INFINITY, hi = -INFINITY;
    for (int j = 0; j < k; j++) {
        lo = fmin(lo, b[m[j]].x - x0 - b[m[j]].r);
        hi = fmax(hi, b[m[j]].x - x0 + b[m[j]].r);
    }
    const double dx = (hi - lo) / UNION_COLUMNS;
    mom[0] = mom[1] = mom[2] = mom[3] = 0;
    for (int c = 0; c < UNION_COLUMNS; c++) {
        const double x = lo + (c + 0.5) * dx;
        int ni = 0;
        for (int j = 0; j < k; j++) { /* the chords on this column, sorted by their start */
            const double u = x - (b[m[j]].x - x0), r = b[m[j]].r;
            if (u * u >= r * r)
                continue;
            const double h = sqrt(r * r - u * u), yc = b[m[j]].y - y0;
            int at = ni++;
            while (at > 0 && iv[2 * (at - 1)] > yc - h) {
                iv[2 * at] = iv[2 * (at - 1)], iv[2 * at + 1] = iv[2 * (at - 1) + 1];
                at--;
            }
            iv[2 * at] = yc - h, iv[2 * at + 1] = yc + h;
        }
        for (int a = 0; a < ni;) { /* merge overlapping chords, then integrate exactly in y */
            double y1 = iv[2 * a], y2 = iv[2 * a + 1];
            while (++a < ni && iv[2 * a] <= y2)
                y2 = fmax(y2, iv[2 * a + 1]);
            const double len = y2 - y1;
            mom[0] += len * dx;
            mom[1] += x * len * dx;
            mom[2] += 0.5 * (y2 * y2 - y1 * y1) * dx;
            mom[3] += (x * x * len + (y2 * y2 * y2 - y1 * y1 * y1) / 3.0) * dx;
        }
    }
}

/* clump_mass = union: overwrite the mass, centre (cx) and inertia (iu) of every
 * body with more than one member by the union's moments. */
static int union_fill(gw_layer *L, const gw_layer_body *b, const int *cnt, double *cx, double *iu, gw_err *err)
{
    const int n = L->n, nb = L->nb;
    int *start = malloc(2 * ((size_t)nb + 1) * sizeof *start), *mem = malloc((size_t)n * sizeof *mem);
    double *iv = malloc(2 * LAYER_CLUMP_MEMBERS * sizeof *iv);
    if (!start || !mem || !iv) {
        free(start), free(mem), free(iv);
        return gw_err_set(err, GW_ENOMEM, "layer: out of memory for %d bodies", nb);
    }
    int *pos = start + nb + 1;
    start[0] = 0;
    for (int q = 0; q < nb; q++)
        pos[q] = start[q + 1] = start[q] + cnt[q];
    for (int i = n - 1; i >= 0; i--) /* members of q in mem[start[q] ..], in index order */
        mem[--pos[L->bid[i]]] = i;
    for (int q = 0; q < nb; q++) {
        if (cnt[q] < 2)
            continue;
        const int *mq = mem + start[q];
        double mom[4];
        union_moments(b, mq, cnt[q], iv, mom);
        const double gx = mom[1] / mom[0], gy = mom[2] / mom[0];
        L->m[q] = L->p.density * mom[0];
        cx[2 * q] = b[mq[0]].x + gx, cx[2 * q + 1] = b[mq[0]].y + gy;
        iu[q] = L->p.density * (mom[3] - mom[0] * (gx * gx + gy * gy));
    }
    free(start), free(mem), free(iv);
    return GW_OK;
}

/* The disc-only set-up, unchanged from before clumps. */
static void discs_fill(gw_layer *L, const gw_layer_body *b)
{
    const gw_layer_params *p = &L->p;
    for (int i = 0; i < L->n; i++) {
        L->m[i] = gw_layer_mass(p, b[i].r);
        L->inertia[i] = gw_layer_inertia(p, b[i].r);
        L->brad[i] = b[i].r;
        L->fixed[i] = b[i].fixed != 0;
        L->minv[i] = L->fixed[i] ? 0 : 1.0 / L->m[i];
        L->iinv[i] = L->fixed[i] ? 0 : 1.0 / L->inertia[i];
        L->y_ref[i] = p->potential_from_start ? b[i].y : 0.0;
        double *s = L->y + 6 * i;
        s[0] = b[i].x;
        s[1] = b[i].y;
        s[2] = 0;
        s[3] = L->fixed[i] ? 0 : b[i].vx;
        s[4] = L->fixed[i] ? 0 : b[i].vy;
        s[5] = L->fixed[i] ? 0 : b[i].w;
    }
}

int layer_bodies_build(gw_layer *L, const gw_layer_body *b, gw_err *err)
{
    const int n = L->n;
    const gw_layer_params *p = &L->p;
    layer_clump_key *k = malloc((size_t)n * sizeof *k);
    int *grp = malloc(3 * (size_t)n * sizeof *grp); /* [n] first member, [2n] scratch */
    double *xyr = malloc(3 * (size_t)n * sizeof *xyr);
    if (!k || !grp || !xyr) {
        free(k), free(grp), free(xyr);
        return gw_err_set(err, GW_ENOMEM, "layer: out of memory for %d particles", n);
    }
    int nk = 0, multi = 0, rc = GW_OK;
    for (int i = 0; i < n; i++) {
        grp[i] = i; /* first member of i's clump (i itself for a lone disc) */
        xyr[i] = b[i].x, xyr[n + i] = b[i].y, xyr[2 * n + i] = b[i].r;
        if (b[i].clump > 0)
            k[nk++] = (layer_clump_key){b[i].clump, i};
    }
    qsort(k, (size_t)nk, sizeof *k, layer_clump_key_cmp);
    for (int a = 0; a < nk && rc == GW_OK;) {
        int q = a, *m = grp + n;
        while (q < nk && k[q].clump == k[a].clump) {
            grp[k[q].i] = k[a].i; /* sorted by index within a clump: k[a] is the first */
            m[q - a] = k[q].i;
            q++;
        }
        multi |= q - a > 1;
        if (q - a > LAYER_CLUMP_MEMBERS)
            rc = gw_err_set(err, GW_EINVAL, "clump %d has %d particles (at most %d)", k[a].clump, q - a,
                            LAYER_CLUMP_MEMBERS);
        else if (q - a > 1 && !layer_members_connected(xyr, xyr + n, xyr + 2 * n, m, q - a, m + (q - a)))
            rc = gw_err_set(err, GW_EINVAL, "clump %d: its %d particles do not overlap or touch as one "
                            "rigid body", k[a].clump, q - a);
        a = q;
    }
    free(k), free(xyr);
    if (rc != GW_OK || !multi) {
        free(grp);
        if (rc == GW_OK) {
            L->nb = n;
            discs_fill(L, b);
        }
        return rc;
    }
    L->bid = malloc((size_t)n * sizeof *L->bid);
    L->off = malloc(2 * (size_t)n * sizeof *L->off);
    if (!L->bid || !L->off) {
        free(grp);
        return gw_err_set(err, GW_ENOMEM, "layer: out of memory for %d particles", n);
    }
    int nb = 0;
    for (int i = 0; i < n; i++) /* bodies numbered by their first member */
        L->bid[i] = grp[i] == i ? nb++ : L->bid[grp[i]];
    L->nb = nb;
    free(grp);
    double *cx = calloc(2 * (size_t)nb, sizeof *cx);
    int *cnt = calloc((size_t)nb, sizeof *cnt);
    if (!cx || !cnt) {
        free(cx), free(cnt);
        return gw_err_set(err, GW_ENOMEM, "layer: out of memory for %d bodies", nb);
    }
    for (int q = 0; q < nb; q++)
        L->m[q] = L->inertia[q] = L->brad[q] = 0, L->fixed[q] = 0;
    for (int i = 0; i < n; i++) {
        int q = L->bid[i];
        double mi = gw_layer_mass(p, b[i].r);
        L->m[q] += mi;
        cx[2 * q] += mi * b[i].x, cx[2 * q + 1] += mi * b[i].y;
        L->fixed[q] |= b[i].fixed != 0;
        cnt[q]++;
    }
    for (int q = 0; q < nb; q++)
        cx[2 * q] /= L->m[q], cx[2 * q + 1] /= L->m[q];
    double *iu = NULL;
    if (p->clump_mass == GW_LAYER_CLUMP_MASS_UNION) {
        int rc = (iu = calloc((size_t)nb, sizeof *iu)) ? union_fill(L, b, cnt, cx, iu, err)
                 : gw_err_set(err, GW_ENOMEM, "layer: out of memory for %d bodies", nb);
        if (rc != GW_OK) {
            free(cx), free(cnt), free(iu);
            return rc;
        }
    }
    for (int i = n - 1; i >= 0; i--) { /* downwards: the first member's velocity wins */
        int q = L->bid[i];
        if (cnt[q] == 1) /* a lone disc: its centre exactly, not m x / m */
            cx[2 * q] = b[i].x, cx[2 * q + 1] = b[i].y;
        double ox = b[i].x - cx[2 * q], oy = b[i].y - cx[2 * q + 1];
        L->off[2 * i] = ox, L->off[2 * i + 1] = oy;
        double mi = gw_layer_mass(p, b[i].r);
        L->inertia[q] += gw_layer_inertia(p, b[i].r) + mi * (ox * ox + oy * oy);
        L->brad[q] = fmax(L->brad[q], hypot(ox, oy) + b[i].r);
        double *s = L->y + 6 * q;
        s[0] = cx[2 * q], s[1] = cx[2 * q + 1], s[2] = 0;
        s[3] = b[i].vx, s[4] = b[i].vy, s[5] = b[i].w;
    }
    for (int q = 0; q < nb; q++) {
        double *s = L->y + 6 * q;
        if (iu && cnt[q] > 1)
            L->inertia[q] = iu[q];
        if (L->fixed[q])
            s[3] = s[4] = s[5] = 0;
        L->minv[q] = L->fixed[q] ? 0 : 1.0 / L->m[q];
        L->iinv[q] = L->fixed[q] ? 0 : 1.0 / L->inertia[q];
        L->y_ref[q] = p->potential_from_start ? s[1] : 0.0;
    }
    free(cx), free(cnt), free(iu);
    return GW_OK;
}

int gw_layer_body_count(const gw_layer *L)
{
    if (!L)
        return 0;
    return L->nb;
}

int gw_layer_body_of(const gw_layer *L, int i)
{
    if (!L || i < 0 || i >= L->n)
        return -1;
    return layer_body(L, i);
}

void gw_layer_body_state(const gw_layer *L, int k, double s[6])
{
    if (!L || !s || k < 0 || k >= L->nb) { /* no such body */
        for (int q = 0; s && q < 6; q++)
            s[q] = NAN;
        return;
    }
    memcpy(s, L->y + 6 * k, 6 * sizeof *s);
}

void gw_layer_particle(const gw_layer *L, int i, double s[6])
{
    if (!L || !s || i < 0 || i >= L->n) { /* no such particle */
        for (int q = 0; s && q < 6; q++)
            s[q] = NAN;
        return;
    }
    if (!L->off) {
        memcpy(s, L->y + 6 * i, 6 * sizeof *s);
        return;
    }
    const double *sb = L->y + 6 * L->bid[i];
    double arm[2];
    layer_disc_xy(L, L->y, i, s, arm);
    s[2] = sb[2];
    s[3] = sb[3] - sb[5] * arm[1];
    s[4] = sb[4] + sb[5] * arm[0];
    s[5] = sb[5];
}

/* Area of k discs of radius 1 in a row at centre spacing d <= 2, minus the
 * lenses of neighbours: the union's area when d >= 1; for d < 1 (aspect ratios
 * in (5/3, 2)) second neighbours overlap too and this overestimates the union
 * by a few per cent, so R_eq is then a little smaller than drawn. */
static double row_area(int k, double d)
{
    double lens = 2 * acos(0.5 * d) - 0.5 * d * sqrt(fmax(0, 4 - d * d));
    return M_PI + (k - 1) * (M_PI - lens);
}

int layer_clump_shape(double req, double aspect, double angle, double *ox, double *oy, double *r)
{
    int k = aspect > 1 ? 1 + (int)ceil(1.5 * (aspect - 1)) : 1;
    double d = k > 1 ? 2 * (aspect - 1) / (k - 1) : 0; /* spacing in member radii */
    double rr = req * sqrt(M_PI / row_area(k, d));
    double c = cos(angle), s = sin(angle);
    for (int j = 0; j < k; j++) {
        double u = (j - 0.5 * (k - 1)) * d * rr;
        ox[j] = c * u, oy[j] = s * u, r[j] = rr;
    }
    return k;
}
