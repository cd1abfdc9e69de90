/*
 * test_layer_regions_noblock.c: a library layer with energy regions and no
 * block. Its block_body is -1, which is also the body code a left-wall
 * contact carries (qb = b, LAYER_LEFT = -1), so layer_contact_region_pt put
 * every left-wall contact in the block's region (nring + 1). Found by the
 * forty-first session (the same clash had left every left-wall spring out of
 * layer-make's samples).
 *
 * Two discs of radius 0.3 m in a box of width 2 m, one pressed 1e-4 m into the
 * left wall (x = 0.2999), one into the right wall (x = 1.7001), at the same
 * height; rings of width 0.5 m around (1, 0.3), one ring. Both contact points
 * lie about 1 m from the centre, outside the ring: region 1. Checks, right
 * after gw_layer_start, for this pair and for one with the left disc pressed
 * twice as far:
 *  1 three regions, and the walls' contacts hold strain energy;
 *  2 the block's region (2) holds none of it;
 *  3 region 1 (outside the ring) holds the whole layer's strain energy, to
 *    1e-12 relative, and the regions add up to it.
 * On the code before, 2 and 3 fail for both pairs (the left wall's energy in
 * the block's region).
 */
#include <math.h>
#include <stdio.h>

#include "gw_layer.h"
#include "gw_test.h"

static void one(double xl, double xr, const char *what)
{
    gw_layer_params p = gw_layer_params_default();
    p.width = 2.0, p.walls = GW_LAYER_WALLS_ALL;
    p.gravity = 0;
    gw_layer_body b[2] = {{.x = xl, .y = 0.3, .r = 0.3}, {.x = xr, .y = 0.3, .r = 0.3}};
    gw_err err = {{0}};
    gw_layer *L = NULL;
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 1e-6;
    int rc = gw_layer_create(&p, 2, b, &L, &err);
    if (rc == GW_OK)
        rc = gw_layer_set_regions(L, 1.0, 0.3, 0.5, 1, &err);
    if (rc == GW_OK)
        rc = gw_layer_start(L, gw_solver_rk4, &sp, &err);
    GW_TEST_OK(rc == GW_OK, "%s: layer set up: %s", what, err.msg);
    if (rc != GW_OK) {
        gw_layer_free(L);
        return;
    }
    gw_layer_energy e, reg[3];
    const int nreg = gw_layer_ledgers(L, &e, reg);
    GW_TEST_OK(nreg == 3, "%s: 3 regions (1 ring, outside, block): %d", what, nreg);
    if (nreg == 3) {
        const double total = e.strain_normal + e.strain_tangent;
        GW_TEST_OK(total > 0, "%s: the walls' contacts hold strain energy: %g J", what, total);
        GW_TEST_OK(reg[2].strain_normal == 0 && reg[2].strain_tangent == 0,
                   "%s: the block's region holds no strain energy (no block): %g J", what,
                   reg[2].strain_normal + reg[2].strain_tangent);
        const double sum = reg[0].strain_normal + reg[1].strain_normal + reg[2].strain_normal;
        GW_TEST_OK(fabs(sum - e.strain_normal) <= 1e-12 * e.strain_normal &&
                       fabs(reg[1].strain_normal - e.strain_normal) <= 1e-12 * e.strain_normal,
                   "%s: outside the ring holds the whole strain energy: %g of %g J (ring %g, block %g)", what,
                   reg[1].strain_normal, e.strain_normal, reg[0].strain_normal, reg[2].strain_normal);
    }
    gw_layer_free(L);
}

int main(void)
{
    one(0.2999, 1.7001, "both walls pressed 1e-4 m");
    one(0.2998, 1.7001, "the left wall pressed 2e-4 m");
    return gw_test_summary("test_layer_regions_noblock");
}
