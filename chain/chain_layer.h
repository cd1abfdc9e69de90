/*
 * chain_layer.h (private to the library and its tests): the memo of the layer
 * laws (chain_layer.c): one gw_layer_law per distinct set of inputs in a
 * process, shared by reference.
 */
#ifndef GW_CHAIN_LAYER_H
#define GW_CHAIN_LAYER_H

/* Idle laws kept at most (the least recently used freed first). */
#define CHAIN_LAYER_MEMO_IDLE 256

/* Laws built and creates answered with a law the memo held, since the start or
 * the last clear; laws the memo holds now (referenced or idle). */
void chain_layer_memo_stats(long *built, long *shared, int *laws);
/* Keep at most keep idle laws from now on (>= 0; the idle laws beyond are freed
 * now); returns the bound before. keep < 0: only return it. For the tests. */
int chain_layer_memo_keep(int keep);
/* Free every idle law (nobody's reference) and zero the counts; referenced laws
 * stay with their holders. */
void chain_layer_memo_clear(void);

#endif
