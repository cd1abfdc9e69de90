/*
 * gw_param.h: each parameter described once.
 *
 * A table of gw_param rows (ended by a row whose name is NULL) describes the
 * fields of one parameter struct: name, type, offset in the struct, unit,
 * accepted range, default and one line of help. The name is the command-line
 * flag without "--" (Python keywords write '-' as '_'). From the table come the
 * struct's defaults (gw_param_init), setting a field by name with its type and
 * range checked (gw_param_set: the message names the parameter, never a
 * position on a command line), the settings of a run as JSON (gw_param_json),
 * and the Python module's keywords, checks and help.
 *
 * Result structs have tables too: their rows are read-only, and arrays
 * (GW_PARAM_DARRAY, GW_PARAM_IARRAY, GW_PARAM_FARRAY) name their dimensions: rows and cols are
 * each a number ("8") or the name of an int row of the same table ("ns").
 *
 * Numbers in the units the row gives (SI; angles in degrees where the unit says
 * so). All calls are reentrant; tables are const and static.
 */
#ifndef GW_PARAM_H
#define GW_PARAM_H

#include <stddef.h>

#include "gw_common.h"

#include "gw_api.h"

GW_BEGIN_DECLS /* the exported interface, C linkage (gw_api.h) */

typedef enum gw_param_type {
    GW_PARAM_DOUBLE = 0, /* double; NaN = not given (when the row has no default) */
    GW_PARAM_INT = 1,    /* int */
    GW_PARAM_LONG = 2,   /* long */
    GW_PARAM_FLAG = 3,   /* int 0 or 1; text "1", "0", "true", "false". A result
                            flag may also be -1: undecided (the program's JSON
                            true, false, null; Python True, False, None) */
    GW_PARAM_CHOICE = 4, /* int: index into choices ("none,kk,hc"); -1 = not given */
    GW_PARAM_TEXT = 5,   /* char *, owned by the struct (gw_param_clear frees it);
                            NULL = not given */
    GW_PARAM_LIST = 6,   /* gw_param_list, owned; text "a,b,c"; empty = not given
                            (text "none") */
    GW_PARAM_RANGE = 7,  /* long[2] {a, b}, a <= b; text "A:B" or "A" */
    GW_PARAM_DARRAY = 8, /* result: double *, rows x cols, row-major */
    GW_PARAM_IARRAY = 9, /* result: int *, rows x cols */
    GW_PARAM_FARRAY = 10, /* result: int * of flags 0 or 1, rows x cols (Python: a
                            bool array, as the JSON's true/false); -1 where the
                            row's help says undecided (JSON null, Python a
                            masked array, masked there) */
    GW_PARAM_COUNT = 11  /* a count a struct holds as a double (its field's type
                            is fixed by the ABI): set and read as a double row
                            ("30", "30.0", "3e1"; NaN = not given), and taken
                            only when a whole number within [min, max], whose
                            ends are whole numbers and are printed as integers
                            ("min-bins: 1.5 is not a whole number (give an
                            integer in [1, 8388606])") */
} gw_param_type;

/* A list of numbers held by a parameter struct (GW_PARAM_LIST). */
typedef struct gw_param_list {
    double *v; /* [n], owned */
    int n;
} gw_param_list;

typedef struct gw_param {
    const char *name;     /* flag name without "--", e.g. "dt-out" */
    gw_param_type type;
    size_t offset;        /* of the field in its struct */
    const char *unit;     /* "m/s", "deg", "" */
    double min, max;      /* accepted numbers (list items and range ends too) */
    int open_min;         /* 1: a number must be > min */
    int open_max;         /* 1: a number must be < max */
    const char *def;      /* default as text, NULL = not given / derived (help says) */
    const char *help;     /* one line */
    const char *choices;  /* GW_PARAM_CHOICE: the names, comma-separated; arrays:
                             the names of the columns (NULL: none) */
    const char *metavar;  /* placeholder in --help ("V") */
    const char *rows;     /* arrays: number of rows, a number or an int row's name;
                             lists (GW_PARAM_LIST): the most items the row takes, a
                             number, or the name of an integer (or range) row of
                             the table: at most that row's value (its maximum for
                             a range; the study checks the count
                             against it; gw_param_set and gw_param_check take that
                             row's maximum, gw_param_set_value INT_MAX); NULL:
                             INT_MAX. A binding reads it to bound what it takes
                             from a caller's sequence (Python's generators) */
    const char *cols;     /* arrays: values per row, likewise (NULL = 1) */
    int optional;         /* 1: the row starts "not given" (GW_PARAM_UNSET_*, NaN,
                             -1; a text row NULL) even
                             when it has a default; def is then the value a run
                             uses when the row is not given (gw_param_resolve),
                             and a value given at the default's value is told
                             apart from none (gw_param_given) */
    int or_zero;          /* 1: a number row takes 0 besides [min, max] (0 is a
                             setting the help names, "0 = ..."; min > 0): the
                             range a caller can give is {0} and [min, max] */
} gw_param;

/* "Not given" in a row that has no default or is optional: double NaN, int
 * and long these (outside every row's range), choice -1, text NULL (a text
 * row's default is then strdup'ed by gw_param_resolve). */
#define GW_PARAM_UNSET_INT (-(int)(~0u >> 1) - 1)     /* INT_MIN (no <limits.h> in this header) */
#define GW_PARAM_UNSET_LONG (-(long)(~0ul >> 1) - 1) /* LONG_MIN */

/* Number of rows of table t. */
int gw_param_count(const gw_param *t);

/* The row called name ('_' matches '-'), or NULL. */
const gw_param *gw_param_find(const gw_param *t, const char *name);

/* 1 for the rows that hold inputs (settable), 0 for result rows. */
int gw_param_is_input(const gw_param *p);

/* Type name ("double", "int", "long", "flag", "choice", "text", "list",
 * "range", "double array", "int array", "flag array", "count"). */
const char *gw_param_type_name(gw_param_type type);

/* Fill obj's fields from t's defaults: a row's def is set as if by gw_param_set;
 * rows without a default get NaN (double), -1 (choice), NULL (text), an empty
 * list, or 0; optional rows get "not given" (NaN, GW_PARAM_UNSET_INT/LONG, -1,
 * NULL).
 * Other bytes of obj are left as they are. GW_EINVAL (message naming the row)
 * only for a table whose default is invalid (a bug). */
int gw_param_init(const gw_param *t, void *obj, gw_err *err);

/* 1 when row p of obj holds a value given by the caller: for an optional row
 * or one without a default, any value but "not given" (the default's value
 * too); for another row, a value other than the default's (a caller who gives
 * the default's value cannot be told from one who gives none there). */
int gw_param_given(const gw_param *p, const void *obj);

/* Set every optional row of obj that is not given to its default (the values
 * a run uses); rows without a default stay not given. GW_EINVAL only for a
 * table whose default is invalid (a bug). */
int gw_param_resolve(const gw_param *t, void *obj, gw_err *err);

/* Set row name of obj from text value, checking it as the row says (number,
 * finite, within [min, max] or (min, max], integer, choice, list items, range).
 * GW_EINVAL with "NAME: reason" in err, obj unchanged; unknown names:
 * GW_EINVAL "unknown parameter 'NAME'"; GW_ENOMEM. */
int gw_param_set(const gw_param *t, void *obj, const char *name, const char *value, gw_err *err);

/* Set one row's value into fieldp, a field of the row's type (double *, long *,
 * int * for int, flag and choice, char ** for text, ...) anywhere, with the
 * checks of gw_param_set: how a command line checks its options by the same
 * rule as the library. Errors as gw_param_set's ("NAME: reason"), *fieldp
 * unchanged. */
int gw_param_set_value(const gw_param *p, void *fieldp, const char *value, gw_err *err);

/* Check every input row of obj as gw_param_set would (for a struct whose
 * fields were written directly): numbers in range (NaN passes when the row has
 * no default: not given), integers, flags 0/1, choice indices, list items,
 * ranges. GW_EINVAL "NAME: reason" for the first bad row. */
int gw_param_check(const gw_param *t, const void *obj, gw_err *err);

/* Set a number row (double, int, long, flag, count) of obj from v with the
 * same checks (an integer or count row needs an integral v). */
int gw_param_set_double(const gw_param *t, void *obj, const char *name, double v, gw_err *err);

/* Current value of row p in obj as text ("" for not given; numbers with 17
 * significant digits; lists comma-separated). Returns the length written,
 * or -1 when buf (size n) is too small, p is a result array or a list row
 * holds a negative count or a count without its values (gw_param_check's
 * refusals; its NULL values were read: SIGSEGV). */
int gw_param_format(const gw_param *p, const void *obj, char *buf, size_t n);

/* A JSON object {name: value} of t's input rows in obj (not given: null;
 * choices by name; lists as arrays; ranges as [a, b]; texts whole, of any
 * length: one over 255 bytes was null, as not given). NULL on ENOMEM, and
 * for a row it cannot write as a value gw_param_set could give: a choice
 * index outside its names (it was null, as not given), a flag other than 0
 * and 1 (7 was true), a list of a negative count ([]) or counted without its
 * values (gw_param_check names each); t or obj NULL: NULL (t NULL was {}). */
cJSON *gw_param_json(const gw_param *t, const void *obj);

/* Free what obj's text and list rows own and reset them to not given. */
void gw_param_clear(const gw_param *t, void *obj);

/* Deep copy of the input rows of src into dst (dst's owned fields must be
 * clear); other bytes are copied as they are. GW_ENOMEM (dst then clear);
 * GW_EINVAL when dst and src overlap or size ends before a row of t. */
int gw_param_copy(const gw_param *t, size_t size, void *dst, const void *src, gw_err *err);

/* Row constructors (off: the field's offsetof in its struct). Input rows: a
 * number (lo, hi its range, op/opx 1 for an open end, df the default as text),
 * a choice (ch the names, comma-separated), a flag (default 0). Result rows:
 * a number of type ty, an array of rows x cols (names: its columns or NULL). */
#define GW_PARAM_ROW(nm, ty, off, un, lo, hi, op, opx, df, mv, hl)                                   \
    {.name = nm, .type = ty, .offset = off, .unit = un, .min = lo, .max = hi, .open_min = op,         \
     .open_max = opx, .def = df, .metavar = mv, .help = hl}
#define GW_PARAM_CHOICE_ROW(nm, off, ch, df, mv, hl)                                                 \
    {.name = nm, .type = GW_PARAM_CHOICE, .offset = off, .unit = "", .def = df, .choices = ch,       \
     .metavar = mv, .help = hl}
/* An optional number row (see gw_param.optional): not given until set. */
#define GW_PARAM_OPT_ROW(nm, ty, off, un, lo, hi, op, opx, df, mv, hl)                               \
    {.name = nm, .type = ty, .offset = off, .unit = un, .min = lo, .max = hi, .open_min = op,         \
     .open_max = opx, .def = df, .metavar = mv, .help = hl, .optional = 1}
#define GW_PARAM_OPT_CHOICE_ROW(nm, off, ch, df, mv, hl)                                             \
    {.name = nm, .type = GW_PARAM_CHOICE, .offset = off, .unit = "", .def = df, .choices = ch,       \
     .metavar = mv, .help = hl, .optional = 1}
#define GW_PARAM_FLAG_ROW(nm, off, hl)                                                               \
    {.name = nm, .type = GW_PARAM_FLAG, .offset = off, .unit = "", .min = 0, .max = 1, .def = "0", .help = hl}
#define GW_RESULT_ROW(nm, ty, off, un, hl) {.name = nm, .type = ty, .offset = off, .unit = un, .help = hl}
/* a yes/no result (an int 0 or 1, -1 undecided where the help says so) */
#define GW_RESULT_FLAG(nm, off, hl) GW_RESULT_ROW(nm, GW_PARAM_FLAG, off, "", hl)
#define GW_RESULT_ARRAY(nm, off, un, r, c, names, hl)                                                \
    {.name = nm, .type = GW_PARAM_DARRAY, .offset = off, .unit = un, .rows = r, .cols = c, .choices = names, \
     .help = hl}
#define GW_PARAM_END {0}
/* The row of a result's warnings (gw_common.h, "warnings of a result"): a char *
 * at offset off, its texts one per line, NULL when none. Every study's result
 * table has it; bindings issue each text as a warning. */
#define GW_PARAM_WARNINGS(off)                                                                     \
    {.name = "warnings", .type = GW_PARAM_TEXT, .offset = (off), .unit = "",                       \
     .help = "why results are not final: the texts the program prints as warnings, one per line " \
             "(NULL when none; Python: a list of str, empty when none)"}

GW_END_DECLS

#endif
