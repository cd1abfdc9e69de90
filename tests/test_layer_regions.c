/*
 * test_layer_regions.c: the energy ledger restricted to regions (docs/physics.md 2.4,
 * "every term can be restricted to a region D"; layer_regions.c).
 *
 * A frictional pile of 16 discs (phi = 30 deg; the bottom row starts up to 5 mm
 * into the bottom wall, so the pile jumps) is hit by a larger block disc thrown
 * down at 5 m/s; 3 rings of width 0.2 m around (0.45, 0.7) m, then "outside",
 * then "block".
 * - Every ledger term summed over the regions equals the global term within
 *   1e-12 of A at every sample (the regions partition particles and contacts;
 *   the integrated E_d and W_K of the regions add up to the global ones to
 *   rounding, as their rates are the same sums).
 * - The regions do not touch the dynamics: with RK4 (fixed step) the particle
 *   states are bit-identical with and without regions.
 * - The block's own contacts dissipate (E_d > 0 in region "block"), and no
 *   region has E_d below -1e-12 A.
 * - Bad region parameters are refused (width <= 0, NaN centre, 0 rings), and
 *   setting regions after gw_layer_start is refused.
 */
#include <math.h>
#include <string.h>

#include "gw_layer.h"
#include "gw_test.h"

#define NB 17

static gw_layer *pile(void)
{
    gw_layer_params p = gw_layer_params_default();
    p.width = 1.0;
    p.friction_deg = 30;
    p.skin = 0.02;
    p.potential_from_start = 1;
    gw_layer_body b[NB];
    for (int i = 0; i < 16; i++) {
        int row = i / 4, col = i % 4;
        b[i] = (gw_layer_body){.x = 0.13 + 0.245 * col + 0.01 * row, .y = 0.09 + 0.2 * row,
                               .r = 0.08 + 0.015 * ((i * 7) % 5) / 4.0};
    }
    b[16] = (gw_layer_body){.x = 0.45, .y = 0.95, .r = 0.12, .vx = 1.0, .vy = -5.0};
    gw_layer *L = NULL;
    gw_err err = {{0}};
    if (gw_layer_create(&p, NB, b, &L, &err) != GW_OK)
        printf("create: %s\n", err.msg);
    gw_layer_set_block(L, 16);
    return L;
}

int main(void)
{
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 1e-6;
    gw_err err = {{0}};
    gw_layer *A = pile(), *B = pile();
    gw_test_true(gw_layer_set_regions(A, 0.45, 0.7, 0.2, 3, &err) == GW_OK, "regions set");
    gw_test_true(gw_layer_region_count(A) == 5, "3 rings + outside + block");
    gw_test_true(gw_layer_region_count(B) == 0, "no regions by default");
    int rc = gw_layer_start(A, gw_solver_rk4, &sp, &err);
    if (rc == GW_OK)
        rc = gw_layer_start(B, gw_solver_rk4, &sp, &err);
    gw_test_true(rc == GW_OK, "start");
    gw_test_true(gw_layer_set_regions(A, 0.45, 0.7, 0.2, 3, &err) == GW_EINVAL,
                 "regions after start refused");
    double e0 = gw_layer_energy_initial(A), worst = 0, dmin = 0;
    int same = 1;
    gw_layer_energy g, r[5];
    for (int k = 1; k <= 60 && rc == GW_OK; k++) {
        rc = gw_layer_advance(A, 0.05 * k / 60, &err);
        if (rc == GW_OK)
            rc = gw_layer_advance(B, 0.05 * k / 60, &err);
        gw_layer_energy_of(A, &g);
        gw_layer_region_ledger(A, r);
        double s[8] = {0};
        for (int q = 0; q < 5; q++) {
            s[0] += r[q].kinetic_block, s[1] += r[q].kinetic_soil, s[2] += r[q].strain_normal;
            s[3] += r[q].strain_tangent, s[4] += r[q].mindlin_excess, s[5] += r[q].dissipated;
            s[6] += r[q].potential, s[7] += r[q].total;
            dmin = fmin(dmin, r[q].dissipated / e0);
        }
        double gg[8] = {g.kinetic_block, g.kinetic_soil, g.strain_normal, g.strain_tangent,
                        g.mindlin_excess, g.dissipated, g.potential, g.total};
        for (int j = 0; j < 8; j++)
            worst = fmax(worst, fabs(s[j] - gg[j]) / e0);
        for (int i = 0; i < NB; i++) {
            double sa[6], sb[6];
            gw_layer_particle(A, i, sa);
            gw_layer_particle(B, i, sb);
            same &= memcmp(sa, sb, sizeof sa) == 0;
        }
    }
    if (rc != GW_OK)
        printf("run failed: %s\n", err.msg);
    gw_test_true(rc == GW_OK, "0.05 s run");
    printf("  A = %g J, E_d = %g J: ring0 %g, ring1 %g, ring2 %g, outside %g, block %g\n", e0,
           g.dissipated, r[0].dissipated, r[1].dissipated, r[2].dissipated, r[3].dissipated,
           r[4].dissipated);
    gw_test_abs(worst, 0, 1e-12, "regions add up to the global ledger (per term, / A)");
    gw_test_true(same, "regions leave the RK4 trajectory bit-identical");
    gw_test_true(g.dissipated > 0 && r[4].dissipated > 0, "the block's contacts dissipate");
    gw_test_true(dmin > -1e-12, "no region has negative dissipation");
    gw_layer_free(A);
    gw_layer_free(B);

    gw_layer *C = pile();
    gw_test_true(gw_layer_set_regions(C, 0.45, 0.7, 0, 3, &err) == GW_EINVAL, "ring width 0 refused");
    gw_test_true(gw_layer_set_regions(C, NAN, 0.7, 0.2, 3, &err) == GW_EINVAL, "NaN centre refused");
    gw_test_true(gw_layer_set_regions(C, 0.45, 0.7, 0.2, 0, &err) == GW_EINVAL, "0 rings refused");
    gw_test_true(gw_layer_region_count(C) == 0, "a refused call leaves no regions");
    gw_layer_free(C);
    return gw_test_summary("test_layer_regions");
}
