/*
 * test_layer_dem_skin.c: the fast mode's run (the verlet backend, layer_dem.c)
 * does not depend on the contact list's skin, to the last bit, when discs
 * close gaps of many steps' travel at high speed (docs/layer.md, "Fast and
 * exact modes"; docs/performance.md).
 *
 * The DEM step lets a listed contact that is open at both ends of a step
 * sleep until its two discs may have travelled its gap (drift_discs): with a
 * large skin every pair is listed from the start and its closure is found by
 * waking it; with a small skin the pair enters the list at a rebuild shortly
 * before it touches. 48 discs (radii 0.25 to 0.35 m, 0.9 m apart on a grid,
 * gaps 0.2 to 0.4 m) in a walled box without gravity, velocities up to 40 m/s
 * (0.4 mm a step of 10 us), friction 30 deg, energy regions set (the drift's
 * common path), 3000 steps; skins 0.02 m (a rebuild every few steps), 0.5 m
 * and 1e3 m (every pair listed once: about 1100 contacts). Asserted: every
 * disc's state, the ledger and the regional ledgers equal bit for bit across
 * the three skins, and the discs collided (friction dissipated energy). A
 * sleep bound too loose by a factor 3 (contacts
 * woken a few steps late) fails the equalities. Runs in about a second.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gw_layer.h"
#include "gw_test.h"

#define N 48
#define NREG 4

typedef struct run {
    double s[N][6];
    gw_layer_energy e, reg[NREG + 2];
    gw_layer_stats st;
    int ok;
} run;

static unsigned long lcg = 12345;
static double urand(void)
{
    lcg = lcg * 6364136223846793005UL + 1442695040888963407UL;
    return (double)(lcg >> 11) / 9007199254740992.0;
}

static void one(const gw_layer_body *b, double skin, run *out)
{
    gw_layer_params p = gw_layer_params_default();
    p.gravity = 0, p.width = 8 * 0.9 + 0.9, p.friction_deg = 30, p.skin = skin;
    gw_layer *L = NULL;
    gw_err err = {{0}};
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 1e-5;
    out->ok = gw_layer_create(&p, N, b, &L, &err) == GW_OK &&
              gw_layer_set_regions(L, 0.5 * p.width, 2.5, 1.0, NREG, &err) == GW_OK &&
              gw_layer_start(L, gw_solver_verlet, &sp, &err) == GW_OK && gw_layer_advance(L, 0.03, &err) == GW_OK;
    if (!out->ok)
        printf("  skin %g m: run failed: %s\n", skin, err.msg);
    for (int i = 0; out->ok && i < N; i++)
        gw_layer_particle(L, i, out->s[i]);
    if (out->ok) {
        gw_layer_ledgers(L, &out->e, out->reg);
        gw_layer_get_stats(L, &out->st);
    }
    gw_layer_free(L);
}

int main(void)
{
    gw_layer_body b[N];
    memset(b, 0, sizeof b);
    for (int i = 0; i < N; i++) { /* 8 x 6 grid, 0.9 m apart; random radii and velocities */
        b[i].r = 0.25 + 0.1 * urand();
        b[i].x = 0.9 + 0.9 * (i % 8);
        b[i].y = 0.9 + 0.9 * (i / 8);
        const double v = 40 * urand(), a = 2 * M_PI * urand();
        b[i].vx = v * cos(a), b[i].vy = v * sin(a), b[i].w = 20 * (urand() - 0.5);
    }
    const double skins[3] = {0.02, 0.5, 1e3};
    static run r[3];
    for (int k = 0; k < 3; k++)
        one(b, skins[k], &r[k]);
    gw_test_true(r[0].ok && r[1].ok && r[2].ok, "the three runs (skins 0.02, 0.5, 1e3 m) complete");
    if (!(r[0].ok && r[1].ok && r[2].ok))
        return gw_test_summary("test_layer_dem_skin");
    for (int k = 0; k < 3; k++)
        printf("  skin %g m: %ld list rebuilds, %ld contacts listed at the end, E_d %.9g J, ledger total %.9g J\n",
               skins[k], r[k].st.rebuilds, r[k].st.contacts_listed, r[k].e.dissipated, r[k].e.total);
    gw_test_true(r[0].e.dissipated > 1e-3 * r[0].e.total,
                 "the discs collided and slid (friction dissipated more than 1e-3 of the energy)");
    gw_test_true(r[2].st.contacts_listed > 20 * N, "the 1e3 m skin lists every pair (more than 20 contacts a disc)");
    gw_test_true(r[0].st.rebuilds > 10 * r[2].st.rebuilds, "the 0.02 m skin rebuilds the list often");
    for (int k = 1; k < 3; k++) {
        char what[160];
        int same = 1;
        for (int i = 0; i < N; i++)
            same &= memcmp(r[k].s[i], r[0].s[i], sizeof r[0].s[i]) == 0;
        snprintf(what, sizeof what, "skin %g m: every disc's state equals the 0.02 m skin's bit for bit", skins[k]);
        gw_test_true(same, what);
        snprintf(what, sizeof what, "skin %g m: the ledger and the %d regional ledgers equal bit for bit", skins[k],
                 NREG + 2);
        gw_test_true(memcmp(&r[k].e, &r[0].e, sizeof r[0].e) == 0 && memcmp(r[k].reg, r[0].reg, sizeof r[0].reg) == 0,
                     what);
    }
    return gw_test_summary("test_layer_dem_skin");
}
