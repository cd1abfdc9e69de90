/*
 * layer_outcome.h (private to layer/): the outcome of one impact read from
 * events on the block (layer_outcome.c; physics.md 2.3, B.16-B.18).
 */
#ifndef GW_LAYER_OUTCOME_H
#define GW_LAYER_OUTCOME_H

#include "gw_layer.h"

typedef struct layer_outcome {
    gw_layer *L;          /* its first-contact watch is frozen at the verdict */
    int until;            /* GW_LAYER_UNTIL_* */
    int contact;          /* the block touches a particle or a wall */
    int rose;             /* v_y turned upward while touching, not yet back to zero */
    int verdict;          /* -1 undecided, 0 no bounce, 1 bounced */
    int gone;             /* 0, or GW_LAYER_GONE_*: the block left the layer for good
                             before a verdict (verdict 0, the run ends there) */
    double t_verdict;     /* s */
    gw_layer_block_event leave; /* the bounce: the block leaving the layer moving up */
    gw_layer_block_extremes at_leave; /* extremes then (first free-flight maximum) */
    int tf;               /* T_f reached: v_y back to zero after the bounce */
    double t_f;
    gw_layer_block_extremes at_end; /* extremes at T_f or at the no-bounce decision */
    double t_touch;       /* the block's first touch of a particle or a wall, s (NaN:
                             none yet; 0 when it touches at the start) */
    double touch_ke;      /* the other bodies' kinetic energy then, J (the state the
                             touch event is dispatched at: the located root, or the
                             DEM step end; 0 at the start; NaN: no touch yet) */
} layer_outcome;

/* Start tracking on layer L (block set, before gw_layer_start). The block
 * touches nothing at t = 0 unless touching (gap 0). */
void layer_outcome_init(layer_outcome *o, gw_layer *L, int until, int touching);

/* The gw_layer_block_fn to pass to gw_layer_watch_block with ctx = o. */
void layer_outcome_event(void *ctx, const gw_layer_block_event *ev);

/* 1 when the run may stop: the outcome asked for by `until` is decided. */
int layer_outcome_done(const layer_outcome *o);

/* Fill the outcome fields of res (bounced, e_n, ..., the _first values,
 * t_f, penetration below y0, the block's height at the touch, the undecided note)
 * from the events seen and the layer's extremes now (the end of the run). */
void layer_outcome_finish(const layer_outcome *o, double y0, double vi, double t_end,
                          int stopped_by_t_max, gw_layer_impact_result *res);

#endif
