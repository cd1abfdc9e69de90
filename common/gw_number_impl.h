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
    int whole; /* 1: a count (whole numbers): its bounds printed as integers */
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

/* A value's text as a refusal quotes it, into buf (n bytes, 80 at least):
 * whole up to 40 characters; a longer one (2**1100's 332 digits, given from
 * Python or on the command line) by its first 20 characters and its length,
 * QUOTE around the part shown ("'" or ""), so that the refusal stays one
 * short line naming the input. Returns buf. */
const char *gw_text_shown(char *buf, size_t n, const char *s, const char *quote);

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

/* Whether the number strtod read from s up to end is written in hexadecimal
 * ("0x1p-2", " -0X.8P1"): an 'x' or 'X' among its characters. Numbers in text
 * are decimal, as integers are (base 10): the options (gw_parse_double_in)
 * and the data files (gw_data_number) refuse one. */
int gw_num_is_hex(const char *s, const char *end);

/* A number of a data file, the whole of the field s (a text sample's header
 * values, particles and springs; a layer-stats table's cells and params),
 * by the rule of the program's options: decimal, no hexadecimal. nan and inf
 * are numbers here (*v set), for the caller to judge by its format.
 * GW_DATA_NUMBER (*v set), GW_DATA_NONE (empty, other text, characters after
 * the number), GW_DATA_HEX (hexadecimal, which strtod reads: a table's
 * 0x1p-2 was read as 0.25 where `--vimp 0x1p-2` is refused) or GW_DATA_HUGE
 * (beyond a double: 1e999; *v the infinity). The callers name the file, the
 * line and the field (gw_data_number_why gives the words of a refusal). */
enum { GW_DATA_NUMBER = 0, GW_DATA_NONE = 1, GW_DATA_HEX = 2, GW_DATA_HUGE = 3 };
int gw_data_number(const char *s, double *v);
/* "not a number", "not a decimal number (no hexadecimal, as the program's
 * options)", "not a finite number" for gw_data_number's codes ("" for
 * GW_DATA_NUMBER). */
const char *gw_data_number_why(int code);

#endif
