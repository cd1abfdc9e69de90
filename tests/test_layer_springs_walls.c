/*
 * test_layer_springs_walls.c: the tangential springs a settled pile is saved
 * with (layer_springs_take, as layer-make keeps them) hold the forces the live
 * model had at that moment, wall by wall, and a layer started from them
 * (layer_springs_pend, gw_layer_start: layer_springs_load) rests under the
 * same forces.
 *
 * 14 polydisperse discs (R 0.2 to 0.4 m) and, as a second case, 7 two-disc
 * clumps settle for 1.5 s in a box 1.3 m wide (friction 30 deg, Hunt-Crossley
 * alpha 0.3 s/m, rk4 at 2e-5 s, as layer-make settles): a column leaning on
 * both side walls. Asserted, for each case:
 *  - both side walls carry closed contacts with a tangential force (else the
 *    case tests nothing), and every such contact of the left, right and bottom
 *    walls has a spring;
 *  - the upward force of each wall's springs, F_t = K_t u (the contact's K_t
 *    at the saved overlap, the reader's), equals the live model's
 *    (layer_side_walls_fy's law, F_t the state clamped to its cap; the normal
 *    force of a side wall is horizontal) within 1e-9 of the pile's weight, and
 *    the floor's horizontal friction force likewise: the positions are the
 *    live ones to the bit, so only rounding of u = F_t / K_t parts them (1e-16
 *    relative);
 *  - a layer built from the saved positions with those springs, started at
 *    rest, has layer_side_walls_fy equal to the live one within 1e-9 of the
 *    weight, and every body's acceleration from its right-hand side equal to
 *    the live state's at rest (velocities zeroed) within 1e-9 g: it starts the
 *    impact in the equilibrium it settled in.
 * Before, the left wall's springs were never saved (the block index -1 of a
 * layer without a block is LAYER_LEFT): the left wall's sum and the layer
 * started from the springs missed that wall's friction (measured: the discs'
 * side walls held 2.31 of the weight started from the springs against 0.263
 * live, a body's acceleration off by 33 g; the clumps' 0.055 against 0.156,
 * 0.44 g), and the pile started out of equilibrium (8 of the 20 checks fail).
 * Runs in about 1.5 s.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_layer.h"
#include "gw_test.h"
#include "layer_impl.h"

#define NDISC 14
#define WIDTH 1.3

/* The live used F_t of contact k (state clamped to its cap; the held branch
 * at the cap gives the cap) and its overlap. */
static double live_ft(const gw_layer *L, int k, double *un)
{
    const layer_contact *c = &L->c[k];
    double nn[2];
    layer_contact_geometry(L, c, L->y, un, nn, NULL);
    if (!(*un > 0))
        return 0;
    const double cap = layer_cap(L->tan_phi, c->kn, *un), f = L->y[6 * L->nb + k];
    const int held = L->tmode_on && L->tmode && L->tmode[k] == 1;
    return held ? (f > 0 ? cap : -cap) : fmax(-cap, fmin(cap, f));
}

/* The live force along each wall of L's state (up on the left and right
 * walls, +x on the floor: t = (-n_y, n_x)), as layer_side_walls_fy sums it:
 * the side walls' normal force is horizontal. */
static void wall_sums(const gw_layer *L, double out[3])
{
    out[0] = out[1] = out[2] = 0;
    for (int k = 0; k < L->nc; k++) {
        const layer_contact *c = &L->c[k];
        if (c->b >= 0)
            continue;
        double un;
        const double ft = live_ft(L, k, &un);
        out[c->b == LAYER_LEFT ? 0 : c->b == LAYER_RIGHT ? 1 : 2] += c->b == LAYER_LEFT ? -ft : ft;
    }
}

/* Rhs accelerations (vx', vy', w' of every body) of L's state with its
 * velocities zeroed into acc [3 nb]. */
static int rest_acc(gw_layer *L, double *acc)
{
    double *y = malloc((size_t)L->dim * sizeof *y), *yd = malloc((size_t)L->dim * sizeof *yd);
    int rc = y && yd ? GW_OK : GW_ENOMEM;
    if (rc == GW_OK) {
        memcpy(y, L->y, (size_t)L->dim * sizeof *y);
        for (int i = 0; i < L->nb; i++)
            y[6 * i + 3] = y[6 * i + 4] = y[6 * i + 5] = 0;
        rc = L->sys.rhs(L->t, y, yd, L);
        for (int i = 0; rc == GW_OK && i < L->nb; i++)
            acc[3 * i] = yd[6 * i + 3], acc[3 * i + 1] = yd[6 * i + 4], acc[3 * i + 2] = yd[6 * i + 5];
    }
    free(y);
    free(yd);
    return rc;
}

static void run(int clumps)
{
    const char *name = clumps ? "clumps" : "discs";
    gw_layer_params p = gw_layer_params_default();
    p.width = WIDTH, p.walls = GW_LAYER_WALLS_ALL, p.damping = 0.3;
    p.potential_from_start = 0;
    gw_layer_body b[NDISC] = {{0}};
    for (int i = 0; i < NDISC; i++) { /* a zigzag column, radii 0.2 to 0.4 m */
        const double r = 0.2 + 0.2 * fmod(0.37 * i * i + 0.11 * i, 1.0);
        if (clumps && i % 2 == 1) { /* the clump's second disc, beside the first */
            b[i] = (gw_layer_body){.x = b[i - 1].x + 0.5 * (b[i - 1].r + 0.3), .y = b[i - 1].y, .r = 0.3,
                                   .clump = i / 2 + 1};
            continue;
        }
        b[i] = (gw_layer_body){.x = 0.42 + 0.1 * (i % 3), .y = 0.45 + 0.85 * i, .r = r,
                               .clump = clumps ? i / 2 + 1 : 0};
    }
    gw_err err = {{0}};
    gw_layer *L = NULL, *L2 = NULL;
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 2e-5;
    int rc = gw_layer_create(&p, NDISC, b, &L, &err);
    if (rc == GW_OK)
        rc = gw_layer_start(L, gw_solver_rk4, &sp, &err);
    if (rc == GW_OK)
        rc = gw_layer_advance(L, 4.0, &err);
    gw_layer_spring *spr = NULL;
    int nspr = 0;
    double x[NDISC], y[NDISC], r[NDISC];
    for (int i = 0; rc == GW_OK && i < NDISC; i++) {
        double pt[2], arm[2];
        layer_disc_xy(L, L->y, i, pt, arm);
        x[i] = pt[0], y[i] = pt[1], r[i] = L->r[i];
    }
    if (rc == GW_OK)
        rc = layer_springs_take(L, x, y, r, WIDTH, &spr, &nspr);
    double w = 0;
    for (int i = 0; rc == GW_OK && i < L->nb; i++)
        w += p.gravity / L->minv[i];
    /* per wall (left, right, bottom): the live force along the wall (up for
     * the side walls, +x for the floor), the springs', contacts with F_t,
     * those with a spring */
    double live[3] = {0}, saved[3] = {0};
    int nlive[3] = {0}, nsaved[3] = {0};
    for (int k = 0; rc == GW_OK && k < L->nc; k++) {
        const layer_contact *c = &L->c[k];
        if (c->b >= 0)
            continue;
        const int wi = c->b == LAYER_LEFT ? 0 : c->b == LAYER_RIGHT ? 1 : 2;
        const double sg = c->b == LAYER_LEFT ? -1 : 1; /* t = (-n_y, n_x): up is n_x; the floor's +x is -n_y = 1 */
        double un;
        const double ft = live_ft(L, k, &un);
        if (ft == 0)
            continue;
        live[wi] += sg * ft, nlive[wi]++;
        const gw_layer_spring key = {.a = c->a, .b = c->b};
        for (int q = 0; q < nspr; q++)
            if (spr[q].a == key.a && spr[q].b == key.b) {
                saved[wi] += sg * fmin(layer_cap(L->tan_phi, c->kn, un), fmax(-layer_cap(L->tan_phi, c->kn, un),
                                                                                c->kts * sqrt(un) * spr[q].u));
                nsaved[wi]++;
            }
    }
    const char *wn[3] = {"left wall", "right wall", "floor"};
    char what[200];
    gw_layer_energy e;
    if (rc == GW_OK)
        gw_layer_energy_of(L, &e);
    printf("  %s: weight %.6g N, %d springs, E_k %.3g J\n", name, w, nspr, rc == GW_OK ? e.kinetic_soil : NAN);
    for (int i = 0; rc == GW_OK && i < 3; i++) {
        printf("    %s: %d contacts with F_t, %d springs; live %.9g, saved %.9g of the weight\n", wn[i], nlive[i],
               nsaved[i], live[i] / w, saved[i] / w);
        if (i < 2) {
            snprintf(what, sizeof what, "%s: the %s carries a contact with friction (the case tests it)", name, wn[i]);
            gw_test_true(nlive[i] > 0 && fabs(live[i]) > 1e-3 * w, what);
        }
        snprintf(what, sizeof what, "%s: every contact of the %s with F_t has a saved spring", name, wn[i]);
        gw_test_true(nsaved[i] == nlive[i], what);
        snprintf(what, sizeof what, "%s: the %s's saved springs hold its live force within 1e-9 of the weight",
                 name, wn[i]);
        gw_test_true(fabs(saved[i] - live[i]) <= 1e-9 * w, what);
    }
    /* a layer from the saved positions and springs, at rest */
    gw_layer_body b2[NDISC];
    for (int i = 0; i < NDISC; i++)
        b2[i] = (gw_layer_body){.x = x[i], .y = y[i], .r = r[i], .clump = b[i].clump};
    if (rc == GW_OK)
        rc = gw_layer_create(&p, NDISC, b2, &L2, &err);
    if (rc == GW_OK)
        rc = layer_springs_pend(L2, spr, nspr);
    if (rc == GW_OK)
        rc = gw_layer_start(L2, gw_solver_rk4, &sp, &err);
    double a1[3 * NDISC], a2[3 * NDISC];
    if (rc == GW_OK)
        rc = rest_acc(L, a1);
    if (rc == GW_OK)
        rc = rest_acc(L2, a2);
    if (rc == GW_OK) {
        double w1[3], w2[3];
        wall_sums(L, w1);
        wall_sums(L2, w2);
        const double s1 = w1[0] + w1[1], s2 = w2[0] + w2[1];
        double worst = 0;
        for (int i = 0; i < L->nb; i++) {
            /* (w' over g per radius of gyration ~ the disc: compared as r w' / g) */
            const double rr = L->r[0];
            worst = fmax(worst, fmax(fabs(a1[3 * i] - a2[3 * i]), fabs(a1[3 * i + 1] - a2[3 * i + 1])) / p.gravity);
            worst = fmax(worst, rr * fabs(a1[3 * i + 2] - a2[3 * i + 2]) / p.gravity);
        }
        printf("    side walls: live %.9g, started from the springs %.9g of the weight; largest acceleration "
               "difference %.3g g\n", s1 / w, s2 / w, worst);
        snprintf(what, sizeof what, "%s: a layer started from the springs has the side walls' live force within "
                 "1e-9 of the weight", name);
        gw_test_true(fabs(s1 - s2) <= 1e-9 * w, what);
        snprintf(what, sizeof what, "%s: a layer started from the springs has the live accelerations at rest "
                 "within 1e-9 g", name);
        gw_test_true(worst <= 1e-9, what);
    }
    if (rc != GW_OK) {
        printf("  %s: run failed: %s\n", name, err.msg);
        gw_test_true(0, "the case ran");
    }
    free(spr);
    gw_layer_free(L);
    gw_layer_free(L2);
}

int main(void)
{
    run(0);
    run(1);
    return gw_test_summary("test_layer_springs_walls");
}
