/*
 * test_layer_gone_side.c: a block beyond a missing side wall over a floor is
 * declared gone (GW_LAYER_BLOCK_GONE, gw_layer.h; block_gone, layer_watch.c)
 * by geometry alone (session 44): its whole body beyond where the wall would
 * be and beyond every other body (so touching none of them), whether it
 * still moves or lies on the floor, by the watch's rule at the event
 * functions' evaluations, not at the samples. (Session 43's rule asked it to
 * move away at least as fast as every other body: a block at rest on the
 * floor beyond the layer was never gone, one rolling away inside the box was
 * gone at once.)
 *
 * A row of 8 discs (R = 0.325 m) on the floor of a box whose left wall is
 * missing (walls: bottom and right), a block of radius 0.5 m:
 *  1. at rest on the floor beyond where the left wall would be (x = -1 m):
 *     gone (dir GW_LAYER_GONE_LEFT) at the first evaluation, and the outcome
 *     read from the events (layer_outcome.c, as an impact's) bounced 0,
 *     fell_off beyond its left side (before: never gone, to the end);
 *  2. the same with the right wall missing instead, at rest beyond x = width:
 *     gone (right) at once (before: never);
 *  3. on the floor inside the box, 1 m left of the row, rolling left at
 *     2 m/s: not gone until its whole body has passed x = 0 (before: gone at
 *     once, at x = 1 m);
 *  4. the same block rolling right, toward the row, at 0.5 m/s: not gone in
 *     the 20 ms before it could reach the row;
 *  5. dropped at 3 m/s (v_x -1 m/s) onto the left end of the row: it glances
 *     off, lands on the floor and rolls away left: gone (left) once its body
 *     has passed x = 0, at the same time within one step whether the run is
 *     advanced in 50 us or 1 ms samples (rk4 at dt 1e-6 s, the rule looked at
 *     every evaluation of the event functions; it does not wait for a sample);
 *  6. the same drop with the left wall kept (every wall): never gone.
 * Runs in a few seconds.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gw_layer.h"
#include "gw_test.h"
#include "layer_outcome.h"

#define NROW 8
#define R 0.325

typedef struct seen {
    int gone, dir;
    double t, x;
    layer_outcome o; /* the impact's outcome read from the same events (layer_outcome.c) */
    int bounced, fell_off; /* its verdict and fell_off (gw_layer_impact_result) */
} seen;

static void on_event(void *ctx, const gw_layer_block_event *ev)
{
    seen *s = ctx;
    if (ev->kind == GW_LAYER_BLOCK_GONE && !s->gone)
        s->gone = 1, s->dir = ev->dir, s->t = ev->t, s->x = ev->x;
    layer_outcome_event(&s->o, ev);
}

/* One run to t_end in samples of dt_out; the block at (xb, yb) with (vx, vy). */
static int run(int walls, double xb, double yb, double vx, double vy, double t_end, double dt_out, seen *s)
{
    gw_layer_params p = gw_layer_params_default();
    p.width = 2 * R * NROW + 2.0;
    p.walls = walls;
    gw_layer_body b[NROW + 1] = {{0}};
    for (int i = 0; i < NROW; i++) /* the row on the floor, from x = 2 m */
        b[i] = (gw_layer_body){.x = 2.0 + R + 2 * R * i, .y = R, .r = R};
    b[NROW] = (gw_layer_body){.x = xb, .y = yb, .r = 0.5, .vx = vx, .vy = vy, .w = -vx / 0.5};
    gw_layer *L = NULL;
    gw_err err = {{0}};
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 1e-6;
    s->gone = s->dir = 0, s->t = s->x = NAN;
    int rc = gw_layer_create(&p, NROW + 1, b, &L, &err);
    if (rc == GW_OK) {
        gw_layer_set_block(L, NROW);
        layer_outcome_init(&s->o, L, GW_LAYER_UNTIL_REBOUND, 0);
        rc = gw_layer_watch_block(L, on_event, s, &err);
    }
    if (rc == GW_OK)
        rc = gw_layer_start(L, gw_solver_rk4, &sp, &err);
    const long nk = lround(t_end / dt_out);
    for (long k = 1; rc == GW_OK && k <= nk && !s->gone; k++)
        rc = gw_layer_advance(L, k * dt_out, &err);
    if (rc == GW_OK) {
        gw_layer_impact_result res = {0};
        layer_outcome_finish(&s->o, yb, hypot(vx, vy), t_end, 0, &res);
        s->bounced = res.bounced, s->fell_off = res.fell_off;
    }
    if (rc != GW_OK)
        printf("  run failed: %s\n", err.msg);
    gw_layer_free(L);
    return rc;
}

int main(void)
{
    const int side = GW_LAYER_WALL_BOTTOM | GW_LAYER_WALL_RIGHT;
    const double width = 2 * R * NROW + 2.0;
    seen a, a2, a3, b, c, d, e;
    /* 1. at rest on the floor beyond where the left wall would be */
    int rc = run(side, -1.0, 0.5, 0, 0, 0.02, 5e-5, &a);
    printf("  at rest beyond x = 0: gone %d dir %d at t = %.6g s; outcome bounced %d, fell_off %d\n", a.gone, a.dir,
           a.t, a.bounced, a.fell_off);
    gw_test_true(rc == GW_OK && a.gone && a.dir == GW_LAYER_GONE_LEFT && a.t < 1e-4,
                 "a block at rest on the floor beyond where the missing left wall would be: gone (left) at once");
    gw_test_true(rc == GW_OK && a.bounced == 0 && a.fell_off == GW_LAYER_GONE_LEFT,
                 "its outcome: bounced 0, fell_off beyond its left side (the impact's result, layer_outcome.c)");
    /* 2. the right wall missing, at rest beyond x = width */
    rc = run(GW_LAYER_WALL_BOTTOM | GW_LAYER_WALL_LEFT, width + 1.0, 0.5, 0, 0, 0.02, 5e-5, &a2);
    printf("  at rest beyond x = width: gone %d dir %d at t = %.6g s\n", a2.gone, a2.dir, a2.t);
    gw_test_true(rc == GW_OK && a2.gone && a2.dir == GW_LAYER_GONE_RIGHT && a2.t < 1e-4,
                 "a block at rest on the floor beyond where the missing right wall would be: gone (right) at once");
    /* 3. inside the box, rolling away from the row */
    rc = run(side, 1.0, 0.5, -2, 0, 1.0, 1e-3, &a3);
    printf("  rolling away inside the box: gone %d dir %d at t = %.6g s, x = %.6g m\n", a3.gone, a3.dir, a3.t, a3.x);
    gw_test_true(rc == GW_OK && a3.gone && a3.dir == GW_LAYER_GONE_LEFT && a3.x + 0.5 < 0 && a3.x + 0.5 > -1e-3,
                 "a block rolling away inside the box: gone (left) once its whole body has passed x = 0, not before");
    /* 4. rolling toward the row */
    rc = run(side, 1.0, 0.5, 0.5, 0, 0.02, 5e-5, &b);
    printf("  rolling toward the row: gone %d\n", b.gone);
    gw_test_true(rc == GW_OK && !b.gone, "the same block rolling toward the row: not gone");
    /* 5. the drop onto the left end of the row, at two samplings */
    const double x0 = 2.0 + R - 0.35, y0 = R + 0.5 + R + 0.02;
    rc = run(side, x0, y0, -1, -3, 3.0, 5e-5, &c);
    int rc2 = run(side, x0, y0, -1, -3, 3.0, 1e-3, &d);
    printf("  drop at the row's left end: gone %d dir %d at t = %.17g s (x = %.6g m); 1 ms samples: gone %d at "
           "%.17g s\n", c.gone, c.dir, c.t, c.x, d.gone, d.t);
    gw_test_true(rc == GW_OK && c.gone && c.dir == GW_LAYER_GONE_LEFT && c.x + 0.5 < 0 && c.x + 0.5 > -1e-3,
                 "a block glancing off the row's left end onto the floor: gone (left) once beyond x = 0");
    gw_test_true(rc2 == GW_OK && d.gone && d.dir == c.dir && fabs(d.t - c.t) <= 1e-6,
                 "the same at 1 ms samples: gone at the same time within one step of 1e-6 s (the sampling does not "
                 "decide)");
    /* 6. every wall kept */
    rc = run(GW_LAYER_WALLS_ALL, x0, y0, -1, -3, 1.5, 1e-3, &e);
    printf("  with the left wall: gone %d\n", e.gone);
    gw_test_true(rc == GW_OK && !e.gone, "the same drop with the left wall kept: never gone");
    return gw_test_summary("test_layer_gone_side");
}
