/*
 * layer_contacts.c: the Verlet contact list of the layer, built with a cell
 * list (docs/physics.md 2.1 for the coefficients K_n (B.3) and K_t/F_n^(1/3) (B.4)).
 *
 * A pair is listed when its gap is below the skin s: |x_a - x_b| < R_a + R_b + s
 * (disc-disc, cells of side 2 R_max + s) or R_a + s beyond the wall distance. No
 * listed-out pair can touch before some particle has moved s/2, which is the
 * rebuild root of layer_model.c. R_p = 2 R_a R_b / (R_a + R_b) for two discs,
 * R_a against a wall. A rebuild changes the state dimension (one F_t per listed
 * contact); F_t of pairs listed before and after is carried over, and so is
 * what the DEM step keeps of them (un_last, tscr; layer_dem.c). Discs of one
 * rigid clump are never listed against each other (layer_clumps.c).
 * Units: SI.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"
#include "gw_locale.h"

static int contact_cmp(const void *pa, const void *pb)
{
    const layer_contact *a = pa, *b = pb;
    if (a->a != b->a)
        return a->a < b->a ? -1 : 1;
    return (a->b > b->b) - (a->b < b->b);
}

static int push(layer_contact **c, int *nc, int *cap, int a, int b)
{
    if (*nc == *cap) {
        int nc2 = *cap ? 2 * *cap : 256;
        layer_contact *t = realloc(*c, (size_t)nc2 * sizeof *t);
        if (!t)
            return GW_ENOMEM;
        *c = t;
        *cap = nc2;
    }
    (*c)[*nc].a = a;
    (*c)[*nc].b = b;
    (*nc)++;
    return GW_OK;
}

/* The most pairs a list may hold: 8 a particle (a packing with a skin below
 * the particles' size lists about 3) and at least 1e7. The skin is in metres:
 * the default 0.1 m on a sample of 1 mm grains listed every pair within 0.1 m,
 * about 1e4 per grain (20000 such grains: 2e8 pairs, some 40 GB with the
 * per-contact state), and the list grew until the allocation failed (exit 1
 * after the memory was gone) or the kernel killed the process, before the
 * impact's bound on its work could name the skin. A pair takes about 200 B
 * with its state: 1e7 pairs are 2 GB. */
#define LAYER_PAIRS_MIN_BOUND 10000000L
#define PAIRS_TOO_MANY 1 /* pairs_cells' status past the bound (GW_ codes are <= 0) */

static long pairs_most(int n)
{
    const long per = 8L * ((long)n + 1);
    return per > LAYER_PAIRS_MIN_BOUND ? per : LAYER_PAIRS_MIN_BOUND;
}

/* Candidate pairs by a cell list over the bounding box of the particles;
 * PAIRS_TOO_MANY when they pass pairs_most, before more is allocated. */
static int pairs_cells(const gw_layer *L, layer_contact **c, int *nc, int *cap)
{
    const long most = pairs_most(L->n);
    const int n = L->n;
    const double *y = L->x_list, s = L->p.skin; /* disc positions */
    layer_grid g;
    int rc = layer_grid_build(&g, n, y, y + 1, 2, 2 * L->rmax + s);
    if (rc != GW_OK)
        return rc;
    const long nx = g.nx, ny = g.ny;
    for (int i = 0; i < n && rc == GW_OK; i++) {
        long cx = g.cell[i] % nx, cy = g.cell[i] / nx;
        /* every loop stops at a failed push: the break left the cells after it
         * to go on, and a push that then succeeded reset rc, so one failed
         * allocation dropped a pair from the list without a word (the run
         * then refused itself as "skin: 0.1 m is too small", exit 2) */
        for (long ky = cy - 1; ky <= cy + 1 && rc == GW_OK; ky++) {
            if (ky < 0 || ky >= ny)
                continue;
            for (long kx = cx - 1; kx <= cx + 1 && rc == GW_OK; kx++) {
                if (kx < 0 || kx >= nx)
                    continue;
                long kc = ky * nx + kx;
                for (int q = g.start[kc]; q < g.start[kc + 1] && rc == GW_OK; q++) {
                    int j = g.idx[q];
                    if (j <= i)
                        continue;
                    int bi = layer_body(L, i), bj = layer_body(L, j);
                    if (bi == bj || (L->fixed[bi] && L->fixed[bj]))
                        continue;
                    double dx = y[2 * j] - y[2 * i], dy = y[2 * j + 1] - y[2 * i + 1];
                    double lim = L->r[i] + L->r[j] + s;
                    if (dx * dx + dy * dy < lim * lim)
                        rc = *nc < most ? push(c, nc, cap, i, j) : PAIRS_TOO_MANY;
                }
            }
        }
    }
    layer_grid_free(&g);
    return rc;
}

/* The explicit DEM step (verlet) checks the list only at the ends of its
 * steps: a particle that moves more than about a quarter of the skin in one
 * step can bring a pair into contact that the list does not hold, and the
 * step then runs without that contact's force (measured on the default
 * impact: --skin 1e-5 m changed e_n_first in the 6th digit, 1e-7 m the
 * penetration by 0.4 % and tripled the ledger's error). Refused when the next
 * list finds such a pair overlapping: the time, the pair, the overlap and the
 * skin that would have held it (40 times the largest step of a particle). */
static int missed_contact(const gw_layer *L, const layer_contact *c, double un, gw_err *err)
{
    double vmax = 0;
    for (int b = 0; b < L->nb; b++) {
        const double *s = L->y + 6 * b, v = sqrt(s[3] * s[3] + s[4] * s[4]) + fabs(s[5]) * L->brad[b];
        vmax = v > vmax ? v : vmax;
    }
    const double step = vmax * L->sp.dt;
    char who[80];
    if (c->b >= 0 && (c->a == L->block || c->b == L->block))
        gw_snprintf(who, sizeof who, "the block and particle %d", c->a == L->block ? c->b : c->a);
    else if (c->b >= 0)
        gw_snprintf(who, sizeof who, "particles %d and %d", c->a, c->b);
    else
        gw_snprintf(who, sizeof who, "particle %d and the %s wall", c->a,
                 c->b == LAYER_LEFT ? "left" : c->b == LAYER_RIGHT ? "right" : "bottom");
    return gw_err_set(err, GW_EINVAL,
                      "skin: %g m is too small for this run: at t = %.9g s %s overlapped by %.3g m without being "
                      "on the contact list of the step before (a particle moves up to %.3g m in a step of %g s, "
                      "the list is checked only at the steps' ends); raise --skin to %.2g m or more",
                      L->p.skin, L->t, who, un, step, L->sp.dt, 40 * step > 2 * L->p.skin ? 40 * step : 2 * L->p.skin);
}

int layer_contacts_build(gw_layer *L, gw_err *err)
{
    const int n = L->n;
    const double s = L->p.skin;
    layer_contact *c = NULL;
    int nc = 0, cap = 0;
    for (int i = 0; i < n; i++) {
        double arm[2];
        layer_disc_xy(L, L->y, i, L->x_list + 2 * i, arm);
    }
    int rc = pairs_cells(L, &c, &nc, &cap);
    for (int i = 0; i < n && rc == GW_OK; i++) {
        if (L->fixed[layer_body(L, i)])
            continue;
        const double x = L->x_list[2 * i], yy = L->x_list[2 * i + 1], r = L->r[i];
        if ((L->p.walls & GW_LAYER_WALL_LEFT) && x - r < s)
            rc = push(&c, &nc, &cap, i, LAYER_LEFT);
        if (rc == GW_OK && (L->p.walls & GW_LAYER_WALL_RIGHT) && L->p.width - x - r < s)
            rc = push(&c, &nc, &cap, i, LAYER_RIGHT);
        if (rc == GW_OK && (L->p.walls & GW_LAYER_WALL_BOTTOM) && yy - r < s)
            rc = push(&c, &nc, &cap, i, LAYER_BOTTOM);
    }
    if (rc == PAIRS_TOO_MANY) {
        free(c);
        return gw_err_set(err, GW_EINVAL, "skin: %g m lists more than %ld pairs of the %d particles (at most 8 a "
                          "particle, or 1e7; the largest radius is %g m): lower the skin toward the particles' size",
                          s, pairs_most(n), n, L->rmax);
    }
    if (rc != GW_OK) {
        free(c);
        return rc == GW_ELIMIT
                   ? gw_err_set(err, rc, "layer: the particles spread over an extent too large for "
                                "double precision: no contact list")
                   : gw_err_set(err, rc, "layer: out of memory building the contact list");
    }
    if (nc > 1)
        qsort(c, (size_t)nc, sizeof *c, contact_cmp);
    for (int k = 0; k < nc; k++) {
        double ra = L->r[c[k].a], rb = c[k].b >= 0 ? L->r[c[k].b] : 0;
        double rp = c[k].b >= 0 ? 2 * ra * rb / (ra + rb) : ra;
        c[k].qa = layer_body(L, c[k].a);
        c[k].qb = c[k].b >= 0 ? layer_body(L, c[k].b) : c[k].b;
        c[k].ra = ra, c[k].rb = rb;
        c[k].kn = gw_layer_kn(&L->p, rp);
        c[k].kts = gw_layer_kt_factor(&L->p, rp) * cbrt(c[k].kn);
    }
    const int nb = L->nb;
    long dim = 6L * nb + nc + L->ntail;
    double *ny = malloc((size_t)dim * sizeof *ny), *nsc = malloc((size_t)dim * sizeof *nsc);
    int *roots = malloc((2 * (size_t)nc + (size_t)n + 3) * sizeof *roots); /* + 2 watch roots */
    long *drift = malloc((size_t)dim * sizeof *drift);
    double *un_last = calloc((size_t)nc + 1, sizeof *un_last);
    double *wake = calloc((size_t)nc + 1, sizeof *wake); /* all awake */
    double *travel = calloc((size_t)nb + 1, sizeof *travel);
    int *tix = malloc((2 * (size_t)nc + 2) * sizeof *tix);
    layer_tscr *tscr = calloc((size_t)nc + 1, sizeof *tscr);
    double *geo = malloc((4 * (size_t)nc + 4) * sizeof *geo);
    double *snap = malloc(((size_t)nc + 1) * LAYER_SNAP_W * sizeof *snap);
    int *dem_act = malloc(((size_t)nc + 1) * sizeof *dem_act);
    double *dem_w = malloc(((size_t)nc + 1) * LAYER_DEM_W * sizeof *dem_w);
    layer_pkc *pk_c = malloc(((size_t)nc + 1) * sizeof *pk_c);
    if (!ny || !nsc || !roots || !drift || !un_last || !tscr || !geo || !snap || !wake || !travel || !tix ||
        !dem_act || !dem_w || !pk_c) {
        free(c), free(ny), free(nsc), free(roots), free(drift), free(un_last), free(tscr), free(snap);
        free(geo), free(wake), free(travel), free(tix), free(dem_act), free(dem_w), free(pk_c);
        return gw_err_set(err, GW_ENOMEM, "layer: out of memory for %d contacts", nc);
    }
    memcpy(ny, L->y, 6 * (size_t)nb * sizeof *ny);
    for (int k = 0; k < nc; k++) {
        ny[6 * nb + k] = 0;
        const layer_contact *old = L->nc > 0 ? bsearch(&c[k], L->c, (size_t)L->nc, sizeof *c,
                                                       contact_cmp) : NULL;
        if (!old && L->stepend && L->listed) { /* a pair in contact that the last list did not hold */
            double un, nn[2];
            layer_contact_geometry(L, &c[k], L->y, &un, nn, NULL);
            if (un > 0) {
                int rc2 = missed_contact(L, &c[k], un, err);
                free(c), free(ny), free(nsc), free(roots), free(drift), free(un_last), free(tscr), free(snap);
                free(geo), free(wake), free(travel), free(tix), free(dem_act), free(dem_w), free(pk_c);
                return rc2;
            }
        }
        if (old) {
            ny[6 * nb + k] = L->y[6 * nb + (old - L->c)];
            /* DEM mode: what the last rhs found of the contact (its overlap,
             * K_t, 1/K_t and region) is the next step's start: kept, not
             * recomputed (a recomputed 1/K_t differs in the last bit from the
             * drift's) */
            un_last[k] = L->un_last[old - L->c];
            tscr[k] = L->tscr[old - L->c];
        }
    }
    memcpy(ny + 6 * nb + nc, L->y + 6 * nb + L->nc, (size_t)L->ntail * sizeof *ny);
    free(L->y), free(L->scale), free(L->c), free(L->roots), free(L->drift), free(L->un_last);
    free(L->tscr), free(L->snap), free(L->geo), free(L->wake), free(L->travel);
    free(L->tix), free(L->dem_act), free(L->dem_w), free(L->pk_c);
    L->pk_c = pk_c;
    L->pk_valid = 0; /* (the kept start's contacts were the old list's) */
    L->dem_act = dem_act;
    L->dem_w = dem_w;
    for (int k = 0; k < nc; k++)
        tix[2 * k] = c[k].qa, tix[2 * k + 1] = c[k].b >= 0 ? c[k].qb : nb;
    L->wake = wake;
    L->travel = travel;
    L->tix = tix;
    L->tscr = tscr;
    L->geo = geo;
    L->geo_valid = L->geo_pos = L->geo_peek = 0;
    L->snap = snap;
    L->stamp++;
    L->drift = drift;
    L->un_last = un_last;
    L->y = ny;
    L->scale = nsc;
    L->roots = roots;
    L->c = c;
    L->nc = nc;
    L->cap_c = cap;
    L->cap_y = dim;
    layer_system_fill(L);
    L->st.rebuilds++;
    L->st.contacts_listed = nc;
    L->listed = 1;
    return GW_OK;
}
