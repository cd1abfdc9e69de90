/*
 * chain_material.h (private to chain/): the check of a material a caller
 * hands to a contact law (gw_hertz_coefficient, gw_layer_law_create,
 * gw_sheet_apply). gw_material is a public struct a C caller may fill by hand;
 * its fields were never checked, so a Young modulus of 0 or below, NaN, or a
 * Poisson ratio outside (-1, 0.5] gave a law (a layer law stiffer than steel
 * for E = -2e11 Pa, one of no force for E = 0) or a "rigid" Hertz coefficient
 * (INFINITY) with GW_OK.
 */
#ifndef GW_CHAIN_MATERIAL_H
#define GW_CHAIN_MATERIAL_H

#include "gw_chain.h"

/* 1 when m has a Young modulus in (0, INFINITY] (INFINITY: rigid) and a
 * Poisson ratio in (-1, 0.5]; 0 otherwise (and for NULL). */
int chain_material_ok(const gw_material *m);
/* GW_OK, or GW_EINVAL naming what ("bead material"), the material's name and
 * the field: "bead material 'x': Young modulus -2e+11 Pa is not in (0, inf]". */
int chain_material_check(const gw_material *m, const char *what, gw_err *err);

#endif
