/*
 * test_layer_watch_force.c: the block watch's dv_y/dt (layer_body_contact_fy,
 * which places the largest v_y between evaluations: T_i) is the right-hand
 * side's, in every mode the right-hand side has (layer_impl.h:
 * layer_contact_force, the one force law both call).
 *
 * A block of radius 0.5 m dropped at 3 m/s onto a row of 12 discs (R = 0.325
 * m) lying on the bottom wall, friction 30 deg, Hunt-Crossley damping alpha =
 * 0.5 s/m (both terms of the law in play), to 6 ms in 50 us samples: discs
 * with the exact mode's law (rk4 stopping at the contact and stick/slip
 * roots: held branches), discs and block as two-disc clumps with that law,
 * and clumps in DEM mode (verlet: the fast law, F_t the state clamped to the
 * cap). At every sample where the block touches a disc, the watch's dv_y/dt
 * at the state, layer_body_contact_fy / m - g, is asserted equal to the block's
 * dv_y/dt from the right-hand side (layer_rhs) within 1e-12 of g (the same
 * sums in the same order: equal to the bit), and at least 10 such samples per
 * case. A guard: the watch wrote the law out again before (R1 of the
 * nineteenth session's reread) and agreed; this fails when the two part
 * (leaving out the damping in either gives differences of order 1 g).
 * Runs in about a second.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gw_layer.h"
#include "gw_test.h"
#include "layer_impl.h"

#define NROW 12
#define R 0.325

/* Run one case; *n_touch the samples with the block in contact, *worst the
 * largest |watch - rhs| of dv_y/dt there over g. */
static int run(int clumps, const gw_solver_type *type, double dt, int *n_touch, double *worst)
{
    gw_layer_params p = gw_layer_params_default();
    p.damping = 0.5, p.width = 2 * R * NROW * (clumps ? 2 : 1) + 0.5;
    gw_layer_body b[2 * NROW + 2] = {{0}};
    int n = 0;
    for (int i = 0; i < NROW; i++) { /* the row, on the bottom wall; a clump: two touching discs */
        const double x0 = 0.25 + R + 2 * R * (clumps ? 2 * i : i);
        b[n++] = (gw_layer_body){.x = x0, .y = R, .r = R, .clump = clumps ? i + 1 : 0};
        if (clumps)
            b[n++] = (gw_layer_body){.x = x0 + 2 * R, .y = R, .r = R, .clump = i + 1};
    }
    int t = 0; /* the disc below the block: the nearest to the middle */
    for (int i = 1; i < n; i++)
        t = fabs(b[i].x - 0.5 * p.width) < fabs(b[t].x - 0.5 * p.width) ? i : t;
    const double xb = b[t].x + 0.05, yb = R + sqrt((R + 0.5 + 1e-4) * (R + 0.5 + 1e-4) - 0.05 * 0.05);
    const int block = n;
    b[n++] = (gw_layer_body){.x = xb, .y = yb, .r = 0.5, .vy = -3, .clump = clumps ? NROW + 1 : 0};
    if (clumps)
        b[n++] = (gw_layer_body){.x = xb, .y = yb + 0.9, .r = 0.5, .vy = -3, .clump = NROW + 1};
    gw_layer *L = NULL;
    gw_err err = {{0}};
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = dt;
    int rc = gw_layer_create(&p, n, b, &L, &err);
    if (rc == GW_OK) {
        gw_layer_set_block(L, block);
        rc = gw_layer_watch_block(L, NULL, NULL, &err);
    }
    if (rc == GW_OK)
        rc = gw_layer_start(L, type, &sp, &err);
    *n_touch = 0, *worst = 0;
    double *yd = NULL;
    for (int k = 1; rc == GW_OK && k <= 120; k++) {
        rc = gw_layer_advance(L, k * 5e-5, &err);
        if (rc != GW_OK)
            break;
        const int bb = L->block_body;
        const double fy = layer_body_contact_fy(L, L->y, bb, NULL, 0);

        if (fy == 0)
            continue; /* in flight */
        double *ny = realloc(yd, (size_t)L->dim * sizeof *yd);
        if (!ny) {
            rc = GW_ENOMEM;
            break;
        }
        yd = ny;
        rc = L->sys.rhs(L->t, L->y, yd, L);
        const double aw = fy * L->minv[bb] - p.gravity, d = fabs(aw - yd[6 * bb + 4]) / p.gravity;
        *worst = isnan(d) || d > *worst ? d : *worst;
        ++*n_touch;
    }
    if (rc != GW_OK)
        printf("  run failed: %s\n", err.msg);
    free(yd);
    gw_layer_free(L);
    return rc;
}

int main(void)
{
    static const struct {
        const char *name;
        int clumps;
        int verlet;
    } cases[3] = {{"discs, exact law (rk4, events)", 0, 0},
                  {"clumps, exact law (rk4, events)", 1, 0},
                  {"clumps, fast law (verlet)", 1, 1}};
    for (int i = 0; i < 3; i++) {
        int nt = 0;
        double worst = NAN;
        const int ok =
            run(cases[i].clumps, cases[i].verlet ? gw_solver_verlet : gw_solver_rk4, 1e-6, &nt, &worst) == GW_OK;
        printf("  %s: %d samples in contact, largest |watch - rhs| %.3g g\n", cases[i].name, nt, worst);
        char what[160];
        snprintf(what, sizeof what, "%s: the block touches the row at 10 samples or more", cases[i].name);
        gw_test_true(ok && nt >= 10, what);
        snprintf(what, sizeof what, "%s: the watch's dv_y/dt is the rhs's within 1e-12 g", cases[i].name);
        gw_test_true(ok && worst <= 1e-12, what);
    }
    return gw_test_summary("test_layer_watch_force");
}
