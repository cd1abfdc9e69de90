/*
 * test_side_walls_check.c: one rule for a pile an impact keeps without a side
 * wall (gw_layer_impact_params.side_walls left, right or none; session 45).
 *
 * A row of 5 equal discs (r = 0.1 m) built in memory rests on the floor, each
 * with the overlap that carries its weight (the floor carries 1.00 of the
 * pile's weight), and is pressed between the side walls: the end discs
 * overlap the walls and the discs each other so that each contact pushes with
 * P (one force along the row, the row at rest). Before session 45 the rule
 * was the floor's share alone, which such a pile passes at any P:
 * `layer-make --clumps --width-rm 6 --n 40 --seed 1` rests with its floor at
 * 1.01 of its weight while its walls push with 2.2 and 2.5 times it, and
 * without its right wall its strain energy went into motion (5457 J of
 * kinetic energy at 0.05 s against 1.1 J with both walls). A wall taken away
 * may now carry at most the pile's weight (its normal and friction forces'
 * resultant). And gw_layer_impact_check did not apply the rule at all (the
 * run and the setup did): it now refuses what gw_layer_impact refuses, with
 * the same message.
 *  1 P = 2 W: gw_layer_impact_check refuses left, right and none (GW_EINVAL
 *    "side-walls: left: ... leans on its right wall", right naming the left
 *    wall, none the left first), passes both; gw_layer_impact refuses left
 *    with the check's message, byte for byte.
 *  2 P = 1.2 W is refused, P = 0.8 W passes (the bound 1); the row 0.05 m
 *    away from both walls passes left, right and none.
 *  3 the same row at y = r (the floor carrying nothing: no pile at rest on
 *    its floor alone): gw_layer_impact_check refuses left naming side-walls
 *    and the floor's share, as gw_layer_impact does (the check passed it
 *    before).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gw_layer.h"
#include "gw_test.h"
#include "layer_test_util.h"

#define N 5
#define R 0.1

static double xs[N], ys[N], rs[N];

/* The row pressed by push (times the row's weight; < 0: 0.05 m from each
 * wall, not touching), its discs floor_on (1: carrying their weight, 0: at
 * y = r). */
static gw_layer_sample row(double push, int floor_on)
{
    const gw_layer_params lp = gw_layer_params_default();
    const double kn = gw_layer_kn(&lp, R), mg = gw_layer_mass(&lp, R) * lp.gravity;
    const double uf = floor_on ? pow(mg / kn, 2.0 / 3.0) : 0;
    const double uw = push > 0 ? pow(push * N * mg / kn, 2.0 / 3.0) : 0, gap = push > 0 ? 0 : 0.05;
    for (int i = 0; i < N; i++) {
        rs[i] = R;
        ys[i] = R - uf;
        xs[i] = gap + R - uw + i * (2 * R - uw);
    }
    gw_layer_sample s = test_three_discs();
    s.n = N, s.x = xs, s.y = ys, s.r = rs, s.rm = R;
    s.width = xs[N - 1] + R - uw + gap;
    return s;
}

static int check(const gw_layer_sample *s, int sides, char *msg, size_t n)
{
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.side_walls = sides;
    ip.t_max = 0.05;
    gw_err e = {{0}};
    const int rc = gw_layer_impact_check(s, &ip, &e);
    snprintf(msg, n, "%s", rc == GW_OK ? "" : e.msg);
    return rc;
}

static int run(const gw_layer_sample *s, int sides, char *msg, size_t n)
{
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.side_walls = sides;
    ip.t_max = 0.05;
    const gw_layer_params lp = gw_layer_params_default();
    gw_solver_params sp = gw_solver_params_default();
    gw_layer_impact_result res;
    gw_err e = {{0}};
    const int rc = gw_layer_impact(s, &lp, &ip, gw_solver_verlet, &sp, &res, &e);
    snprintf(msg, n, "%s", rc == GW_OK ? "" : e.msg);
    return rc;
}

int main(void)
{
    char m[1024], mr[1024];
    /* 1 pressed with twice its weight */
    gw_layer_sample s = row(2, 1);
    int rc = check(&s, GW_LAYER_SIDES_LEFT, m, sizeof m);
    GW_TEST_OK(rc == GW_EINVAL && strstr(m, "side-walls: left: ") && strstr(m, "leans on its right wall") &&
                   strstr(m, "pushes the pile with 2 of its weight") && strstr(m, "floor carries 1;"),
               "pressed 2 W, left: the check refuses naming side-walls and the right wall: %d '%s'", rc, m);
    rc = check(&s, GW_LAYER_SIDES_RIGHT, m, sizeof m);
    GW_TEST_OK(rc == GW_EINVAL && strstr(m, "side-walls: right: ") && strstr(m, "leans on its left wall"),
               "pressed 2 W, right: refused naming the left wall: %d '%s'", rc, m);
    rc = check(&s, GW_LAYER_SIDES_NONE, m, sizeof m);
    GW_TEST_OK(rc == GW_EINVAL && strstr(m, "side-walls: none: ") && strstr(m, "leans on its left wall"),
               "pressed 2 W, none: refused: %d '%s'", rc, m);
    rc = check(&s, GW_LAYER_SIDES_BOTH, m, sizeof m);
    GW_TEST_OK(rc == GW_OK, "pressed 2 W, both walls kept: the check passes: %d '%s'", rc, m);
    rc = check(&s, GW_LAYER_SIDES_LEFT, m, sizeof m);
    int rr = run(&s, GW_LAYER_SIDES_LEFT, mr, sizeof mr);
    GW_TEST_OK(rr == GW_EINVAL && rc == rr && strcmp(m, mr) == 0,
               "pressed 2 W, left: gw_layer_impact refuses with the check's message: %d '%s'", rr, mr);

    /* 2 the bound: the weight */
    s = row(1.2, 1);
    rc = check(&s, GW_LAYER_SIDES_LEFT, m, sizeof m);
    GW_TEST_OK(rc == GW_EINVAL && strstr(m, "leans on its right wall"), "pressed 1.2 W, left: refused: %d '%s'",
               rc, m);
    s = row(0.8, 1);
    rc = check(&s, GW_LAYER_SIDES_LEFT, m, sizeof m);
    GW_TEST_OK(rc == GW_OK, "pressed 0.8 W, left: passes: %d '%s'", rc, m);
    s = row(-1, 1);
    int pass = 1;
    for (int k = GW_LAYER_SIDES_LEFT; k <= GW_LAYER_SIDES_NONE; k++)
        pass &= check(&s, k, m, sizeof m) == GW_OK;
    GW_TEST_OK(pass, "the row off both walls: left, right and none pass");

    /* 3 the floor carrying nothing */
    s = row(-1, 0);
    rc = check(&s, GW_LAYER_SIDES_LEFT, m, sizeof m);
    rr = run(&s, GW_LAYER_SIDES_LEFT, mr, sizeof mr);
    GW_TEST_OK(rc == GW_EINVAL && strstr(m, "side-walls: left: ") && strstr(m, "does not rest on its floor alone") &&
                   strstr(m, "the floor carries 0 of its weight"),
               "at y = r, left: the check refuses naming side-walls and the floor: %d '%s'", rc, m);
    GW_TEST_OK(rr == GW_EINVAL && strcmp(m, mr) == 0, "at y = r, left: the run refuses with the same message: %d '%s'",
               rr, mr);
    return gw_test_summary("test_side_walls_check");
}
