/*
 * chain_restitution.h (private to the library and its tests): the memo of the
 * damping calibration (chain_restitution.c).
 */
#ifndef GW_CHAIN_RESTITUTION_H
#define GW_CHAIN_RESTITUTION_H

/* Calibrations answered from the memo and calibrations run since the start or
 * the last clear. */
void chain_calibrate_memo_stats(long *hits, long *misses);
/* Forget every stored constant (and the counts). */
void chain_calibrate_memo_clear(void);

#endif
