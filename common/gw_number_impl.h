/*
 * gw_number_impl.h (private to the library and the program, not installed):
 * the number parser given the range its input takes, so that a value it
 * refuses before any range check (a subnormal: nonzero, below DBL_MIN in
 * magnitude) is refused with the values the input takes, not a generic
 * "give 0 or a larger value" (0 may be outside the range, and "larger" is no
 * range). One rule for the command line's flags, their lists, the parameter
 * tables (a sweep's values, the Python module's keywords) and values written
 * into a struct.
 */
#ifndef GW_NUMBER_IMPL_H
#define GW_NUMBER_IMPL_H

#include <stddef.h>

#include "gw_common.h"

/* An input's values: lo <= x <= hi (x > lo when open_lo, x < hi when
 * open_hi; -INFINITY/INFINITY for no bound), and 0 besides when or_zero. */
typedef struct gw_num_range {
    double lo, hi;
    int open_lo, open_hi, or_zero;
} gw_num_range;

/* The values r takes that are normal doubles or 0, as text into buf (n
 * bytes): "a value in [0.001, 10]", "0 or a value in [2.2251e-308, 1]",
 * "a value >= 2.2251e-308", "0 or a magnitude of at least 2.2251e-308" (r
 * NULL: any finite number). Returns buf. */
char *gw_num_allowed(char *buf, size_t n, const gw_num_range *r);

/* GW_EINVAL "NAME: WHAT is too small in magnitude: nonzero values lie at or
 * above 2.2251e-308, the smallest normal double (give ALLOWED)", ALLOWED as
 * gw_num_allowed gives it. */
int gw_num_subnormal_refused(const char *name, const char *what, const gw_num_range *r, gw_err *err);

/* gw_parse_double, a subnormal refused naming the values r takes (r NULL:
 * any finite number). The range itself is not checked here: the callers
 * check it with their own words. */
int gw_parse_double_in(const char *s, const char *name, const gw_num_range *r, double *out, gw_err *err);

/* gw_parse_double_list_in, its items checked in [r->lo, r->hi] (r->open_lo
 * as its open_lo), a subnormal item refused naming all of r (its open upper
 * end and or_zero too, which the callers that have them check after); r
 * NULL: any finite number. */
int gw_parse_double_list_range(const char *s, const char *name, const gw_num_range *r, double **out, int *n,
                               gw_err *err);

/* x, one end of a range, as text for its messages: %g when the number it
 * reads back is x or lies inside the range (upper 1: x is its upper end, the
 * number <= x; upper 0: its lower end, >= x), else six digits rounded inward
 * (the upper end 5.0968399e7 printed by %g as 5.09684e+07, above it, so that
 * the value a message named was itself refused: now 5.09683e+07). The text
 * read back is accepted where the end is closed. Returns buf. */
char *gw_num_bound(char *buf, size_t n, double x, int upper);

/* " (give an integer in [lo, hi])" ("0 or an integer" when or_zero; empty
 * when [lo, hi] is every long) into buf: the words gw_parse_long_in's
 * refusal of a text that is no integer ends in. Returns buf. */
char *gw_int_give(char *buf, size_t n, long lo, long hi, int or_zero);

/* gw_parse_long, and 0 besides [lo, hi] when or_zero; a text that is no
 * integer (1.5, 1e-310) is refused naming the values the input takes
 * ("'1e-310' is not an integer (give an integer in [1, 100])", "0 or" when
 * or_zero; no range when [lo, hi] is every long), as a real number's
 * refusal of a subnormal names them. */
int gw_parse_long_in(const char *s, const char *name, long lo, long hi, int or_zero, long *out, gw_err *err);

#endif
