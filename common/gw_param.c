/*
 * gw_param.c: parameter tables (gw_param.h): defaults, setting by name with
 * type and range checks, text and JSON of the values. No physics here; units
 * are the rows' (SI).
 */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_param.h"
#include "gw_locale.h"
#include "gw_number_impl.h"

int gw_param_count(const gw_param *t)
{
    int n = 0;
    while (t && t[n].name)
        n++;
    return n;
}

/* name equal to row, '_' in name matching '-' in row */
static int same_name(const char *row, const char *name)
{
    for (; *row && *name; row++, name++)
        if (*row != *name && !(*row == '-' && *name == '_'))
            return 0;
    return *row == *name;
}

const gw_param *gw_param_find(const gw_param *t, const char *name)
{
    for (int i = 0; name && t && t[i].name; i++)
        if (same_name(t[i].name, name))
            return &t[i];
    return NULL;
}

int gw_param_is_input(const gw_param *p)
{
    return p && p->type != GW_PARAM_DARRAY && p->type != GW_PARAM_IARRAY && p->type != GW_PARAM_FARRAY;
}

const char *gw_param_type_name(gw_param_type type)
{
    static const char *const names[] = {"double", "int", "long", "flag", "choice",
                                        "text", "list", "range", "double array", "int array",
                                        "flag array", "count"};
    return (unsigned)type < sizeof names / sizeof names[0] ? names[type] : "unknown";
}

static void *field(void *obj, const gw_param *p)
{
    return (char *)obj + p->offset;
}

static const void *cfield(const void *obj, const gw_param *p)
{
    return (const char *)obj + p->offset;
}

/* The bytes a row's field takes in its struct. */
static size_t param_field_size(const gw_param *p)
{
    switch (p->type) {
    case GW_PARAM_DOUBLE:
    case GW_PARAM_COUNT: return sizeof(double);
    case GW_PARAM_LONG: return sizeof(long);
    case GW_PARAM_TEXT: return sizeof(char *);
    case GW_PARAM_LIST: return sizeof(gw_param_list);
    case GW_PARAM_RANGE: return 2 * sizeof(long);
    case GW_PARAM_DARRAY: return sizeof(double *);
    case GW_PARAM_IARRAY:
    case GW_PARAM_FARRAY: return sizeof(int *);
    default: return sizeof(int); /* INT, FLAG, CHOICE */
    }
}

/* an optional int or long row's field f at "not given" */
static int unset(const gw_param *p, const void *f)
{
    return p->optional && ((p->type == GW_PARAM_INT && *(const int *)f == GW_PARAM_UNSET_INT) ||
                           (p->type == GW_PARAM_LONG && *(const long *)f == GW_PARAM_UNSET_LONG));
}

/* One end x of row p's range as its refusals print it: a count's in full
 * (8388606, where %g's six digits gave 8.3886e+06), a real's rounded toward
 * the inside (gw_num_bound: the printed end is taken when given back). */
static char *row_end(char *buf, size_t n, const gw_param *p, double x, int upper)
{
    if (p->type == GW_PARAM_COUNT && isfinite(x) && fabs(x) < 9.0e15) {
        gw_snprintf(buf, n, "%.0f", upper ? floor(x) : ceil(x));
        return buf;
    }
    return gw_num_bound(buf, n, x, upper);
}

/* within [min, max], "(" / ")" for open ends, or 0 for an or_zero row;
 * messages "(0, 1000]", "> 0", "[1e-09, 0.01] (or 0)" */
static int range_bad(const gw_param *p, double x, gw_err *err, const char *what)
{
    if (x >= p->min && x <= p->max && !(p->open_min && !(x > p->min)) && !(p->open_max && !(x < p->max)))
        return GW_OK;
    if (p->or_zero && x == 0)
        return GW_OK;
    const char *zero = p->or_zero ? " (or 0)" : "";
    char xs[32], ls[32], hs[32]; /* the ends as numbers the range holds (5.09684e+07 was above it) */
    gw_num_text(xs, sizeof xs, x);
    row_end(ls, sizeof ls, p, p->min, 0);
    row_end(hs, sizeof hs, p, p->max, 1);
    if (!isfinite(p->max))
        return gw_err_set(err, GW_EINVAL, "%s: %s%s must be %s %s%s", p->name, what, xs,
                          p->open_min ? ">" : ">=", ls, zero);
    return gw_err_set(err, GW_EINVAL, "%s: %s%s is outside %s%s, %s%s%s", p->name, what, xs,
                      p->open_min ? "(" : "[", ls, hs, p->open_max ? ")" : "]", zero);
}

/* index of value in the comma-separated choices, -1 if absent */
static int choice_index(const char *choices, const char *value)
{
    size_t len = strlen(value);
    int i = 0;
    for (const char *c = choices; c && *c; i++) {
        const char *e = strchr(c, ',');
        size_t n = e ? (size_t)(e - c) : strlen(c);
        if (n == len && strncmp(c, value, n) == 0)
            return i;
        if (!e)
            break;
        c = e + 1;
    }
    return -1;
}

static int choice_count(const char *choices)
{
    int n = choices && *choices ? 1 : 0;
    for (const char *c = choices; c && *c; c++)
        n += *c == ',';
    return n;
}

/* the name of choice i into buf */
static int choice_name(const char *choices, int i, char *buf, size_t n)
{
    const char *c = choices;
    for (int k = 0; c && k < i; k++) {
        c = strchr(c, ',');
        if (c)
            c++;
    }
    if (!c || i < 0)
        return -1;
    const char *e = strchr(c, ',');
    size_t len = e ? (size_t)(e - c) : strlen(c);
    if (len + 1 > n)
        return -1;
    memcpy(buf, c, len);
    buf[len] = '\0';
    return (int)len;
}

/* The values row p takes (its range, open ends and or_zero), for the words
 * of a subnormal's refusal (gw_number_impl.h). */
static gw_num_range row_range(const gw_param *p)
{
    return (gw_num_range){p->min, p->max, p->open_min, p->open_max, p->or_zero, p->type == GW_PARAM_COUNT};
}

/* A subnormal double (nonzero, below DBL_MIN in magnitude): the text path
 * (gw_parse_double_in) refuses it, so a value set as a double or written into
 * the struct is refused too, with the same words: every accepted value can be
 * given again as the text gw_param_format and gw_param_json write. The
 * refusal names the values the row takes (it said "give 0 or a larger value"
 * of rows that do not take 0). */
static int subnormal_bad(const gw_param *p, double v, gw_err *err, const char *what)
{
    if (v == 0 || !(fabs(v) < DBL_MIN))
        return GW_OK;
    char text[96];
    const gw_num_range r = row_range(p);
    gw_snprintf(text, sizeof text, "%s%.17g", what, v);
    return gw_num_subnormal_refused(p->name, text, &r, err);
}

/* The integers an int or long row takes: [*lo, *hi] (its open ends moved in,
 * an int row's within int) */
static void int_bounds(const gw_param *p, long *lo, long *hi)
{
    *lo = p->min <= (double)LONG_MIN ? LONG_MIN : (long)ceil(p->min) + (p->open_min && p->min == ceil(p->min));
    *hi = p->max >= (double)LONG_MAX ? LONG_MAX : (long)floor(p->max) - (p->open_max && p->max == floor(p->max));
    if (p->type == GW_PARAM_INT) {
        *lo = *lo < INT_MIN ? INT_MIN : *lo;
        *hi = *hi > INT_MAX ? INT_MAX : *hi;
    }
}

/* A count row's value v (in its range) that is no whole number: "NAME: '1.5'
 * is not a whole number (give an integer in [1, 8388606])", text the value as
 * given (NULL: v printed). A count held as a double took 1.5 bins before. */
static int count_bad(const gw_param *p, double v, const char *text, gw_err *err)
{
    if (v == floor(v))
        return GW_OK;
    long lo, hi; /* the whole numbers the row takes */
    int_bounds(p, &lo, &hi);
    char give[96], xs[80];
    gw_int_give(give, sizeof give, lo, hi, p->or_zero);
    if (text)
        return gw_err_set(err, GW_EINVAL, "%s: %s is not a whole number%s", p->name,
                          gw_text_shown(xs, sizeof xs, text, "'"), give);
    return gw_err_set(err, GW_EINVAL, "%s: %s is not a whole number%s", p->name, gw_num_text(xs, sizeof xs, v), give);
}

static int set_number(const gw_param *p, void *obj, double v, const char *text, gw_err *err)
{
    /* a row that takes no number said so only when v lay in its [min, max]:
     * gw_param_set_double(chain, "material", 1) was told "1 is outside [0,
     * 0]", and 0 "takes a choice, not a number" */
    if (p->type != GW_PARAM_DOUBLE && p->type != GW_PARAM_FLAG && p->type != GW_PARAM_INT &&
        p->type != GW_PARAM_LONG && p->type != GW_PARAM_COUNT)
        return gw_err_set(err, GW_EINVAL, "%s: takes a %s, not a number", p->name, gw_param_type_name(p->type));
    if (!isfinite(v))
        return gw_err_set(err, GW_EINVAL, "%s: must be a finite number, got %g", p->name, v);
    int rc = subnormal_bad(p, v, err, "");
    if (rc != GW_OK)
        return rc;
    rc = range_bad(p, v, err, "");
    if (rc != GW_OK)
        return rc;
    switch (p->type) {
    case GW_PARAM_DOUBLE:
        *(double *)field(obj, p) = v;
        return GW_OK;
    case GW_PARAM_COUNT:
        if ((rc = count_bad(p, v, text, err)) != GW_OK)
            return rc;
        *(double *)field(obj, p) = v;
        return GW_OK;
    case GW_PARAM_FLAG:
        if (v != 0 && v != 1) { /* as given: 0.9999999999 was "1 is not a flag" */
            char vs[32];
            return gw_err_set(err, GW_EINVAL, "%s: %s is not a flag (0 or 1)", p->name, gw_num_text(vs, sizeof vs, v));
        }
        *(int *)field(obj, p) = (int)v;
        return GW_OK;
    case GW_PARAM_INT:
    case GW_PARAM_LONG:
        if (v != floor(v) || fabs(v) > (p->type == GW_PARAM_INT ? (double)INT_MAX : 9.0e18)) {
            long lo, hi; /* the integers the row takes, as the text path names them (gw_parse_long_in) */
            int_bounds(p, &lo, &hi);
            char give[96];
            gw_int_give(give, sizeof give, lo, hi, p->or_zero);
            char xs[80];
            if (text)
                return gw_err_set(err, GW_EINVAL, "%s: %s is not an integer%s", p->name,
                                  gw_text_shown(xs, sizeof xs, text, "'"), give);
            return gw_err_set(err, GW_EINVAL, "%s: %s is not an integer%s", p->name, gw_num_text(xs, sizeof xs, v),
                              give);
        }
        if (p->type == GW_PARAM_INT)
            *(int *)field(obj, p) = (int)v;
        else
            *(long *)field(obj, p) = (long)v;
        return GW_OK;
    default:
        return gw_err_set(err, GW_EINVAL, "%s: takes a %s, not a number", p->name, gw_param_type_name(p->type));
    }
}

static int set_integer_text(const gw_param *p, void *obj, const char *value, gw_err *err)
{
    long lo, hi, v;
    int_bounds(p, &lo, &hi);
    const int rc = gw_parse_long_in(value, p->name, lo, hi, p->or_zero, &v, err); /* 0 besides the range: or_zero */
    if (rc != GW_OK)
        return rc;
    if (p->type == GW_PARAM_INT)
        *(int *)field(obj, p) = (int)v;
    else
        *(long *)field(obj, p) = v;
    return GW_OK;
}

/* The most items list row p of table t takes (gw_param.rows): its number, or
 * the maximum of the integer or range row of t it names (INT_MAX without t);
 * INT_MAX when none (the count is an int) */
static long list_most(const gw_param *t, const gw_param *p)
{
    if (!p->rows)
        return INT_MAX;
    char *end;
    long m = strtol(p->rows, &end, 10);
    if (end == p->rows) { /* a row's name */
        const gw_param *r = gw_param_find(t, p->rows);
        return r && (r->type == GW_PARAM_INT || r->type == GW_PARAM_LONG || r->type == GW_PARAM_RANGE ||
                     r->type == GW_PARAM_COUNT) && r->max >= 0 && r->max <= INT_MAX
                   ? (long)r->max
                   : INT_MAX;
    }
    return *end || m < 0 || m > INT_MAX ? INT_MAX : m;
}

static int set_text(const gw_param *t, const gw_param *p, void *obj, const char *value, gw_err *err)
{
    switch (p->type) {
    case GW_PARAM_DOUBLE:
    case GW_PARAM_COUNT: { /* a count as a real ("30.0" as Python's 30.0 gives it), then whole */
        double v;
        const gw_num_range r = row_range(p);
        int rc = gw_parse_double_in(value, p->name, &r, &v, err);
        return rc == GW_OK ? set_number(p, obj, v, value, err) : rc;
    }
    case GW_PARAM_INT:
    case GW_PARAM_LONG:
        return set_integer_text(p, obj, value, err);
    case GW_PARAM_FLAG: {
        int f = gw_parse_flag(value);
        if (f < 0) {
            char shown[80];
            return gw_err_set(err, GW_EINVAL, "%s: %s is not a flag (1, 0, true, false)", p->name,
                              gw_text_shown(shown, sizeof shown, value, "'"));
        }
        *(int *)field(obj, p) = f;
        return GW_OK;
    }
    case GW_PARAM_CHOICE: {
        int i = choice_index(p->choices, value);
        if (i < 0) {
            char list[512];
            gw_snprintf(list, sizeof list, "%s", p->choices ? p->choices : "");
            for (char *c = list; *c; c++)
                if (*c == ',')
                    *c = ' ';
            char shown[80];
            return gw_err_set(err, GW_EINVAL, "%s: unknown value %s (%s)", p->name,
                              gw_text_shown(shown, sizeof shown, value, "'"), list);
        }
        *(int *)field(obj, p) = i;
        return GW_OK;
    }
    case GW_PARAM_TEXT: {
        if (!*value)
            return gw_err_set(err, GW_EINVAL, "%s: empty value", p->name);
        char *copy = strdup(value);
        if (!copy)
            return gw_err_set(err, GW_ENOMEM, "%s: out of memory", p->name);
        char **dst = field(obj, p);
        free(*dst);
        *dst = copy;
        return GW_OK;
    }
    case GW_PARAM_LIST: {
        double *v = NULL;
        int n = 0;
        if (strcmp(value, "none") == 0) { /* an empty list: not given */
            gw_param_list *l = field(obj, p);
            free(l->v);
            l->v = NULL;
            l->n = 0;
            return GW_OK;
        }
        /* the row's most items, counted before anything is parsed or allocated */
        long most = list_most(t, p);
        long items = 1;
        for (const char *c = value; *c; c++)
            items += *c == ',';
        if (items > most)
            return gw_err_set(err, GW_EINVAL, "%s: %ld items, at most %ld", p->name, items, most);
        const gw_num_range r = row_range(p);
        int rc = gw_parse_double_list_range(value, p->name, &r, &v, &n, err);
        if (rc != GW_OK)
            return rc;
        for (int k = 0; p->open_max && k < n; k++) /* the parser's upper end is closed */
            if (!(v[k] < p->max)) {
                char xs[32], hs[32]; /* the item (the bound was printed as the item) */
                gw_num_text(xs, sizeof xs, v[k]);
                free(v);
                return gw_err_set(err, GW_EINVAL, "%s: item %d is %s, must be < %s", p->name, k + 1, xs,
                                  gw_num_bound(hs, sizeof hs, p->max, 1));
            }
        gw_param_list *l = field(obj, p);
        free(l->v);
        l->v = v;
        l->n = n;
        return GW_OK;
    }
    case GW_PARAM_RANGE: {
        long a, b;
        long lo = (long)p->min, hi = (long)p->max;
        int rc = gw_parse_int_range(value, p->name, lo, hi, &a, &b, err);
        if (rc != GW_OK)
            return rc;
        long *r = field(obj, p);
        r[0] = a;
        r[1] = b;
        return GW_OK;
    }
    default:
        return gw_err_set(err, GW_EINVAL, "%s: a result, not a parameter", p->name);
    }
}

/* The NULL table or name of a set call, named with the call ("unknown parameter
 * 'n'" for a NULL table, "unknown parameter '(null)'" for a NULL name, where
 * every other entry point names the argument); GW_OK when both are given. */
static int set_args_check(const char *call, const gw_param *t, const char *name, gw_err *err)
{
    if (!t || !name)
        return gw_err_set(err, GW_EINVAL, "%s: %s is NULL", call, !t ? "table" : "name");
    return GW_OK;
}

int gw_param_set(const gw_param *t, void *obj, const char *name, const char *value, gw_err *err)
{
    int arc = set_args_check("gw_param_set", t, name, err);
    if (arc != GW_OK)
        return arc;
    const gw_param *p = gw_param_find(t, name);
    if (!p)
        return gw_err_set(err, GW_EINVAL, "unknown parameter '%s'", name ? name : "(null)");
    if (!value)
        return gw_err_set(err, GW_EINVAL, "%s: no value", p->name);
    if (!obj)
        return gw_err_set(err, GW_EINVAL, "gw_param_set: obj is NULL (setting %s)", p->name);
    return set_text(t, p, obj, value, err);
}

int gw_param_set_value(const gw_param *p, void *fieldp, const char *value, gw_err *err)
{
    if (!p) /* "(null): a result, not a parameter" before the forty-ninth pass */
        return gw_err_set(err, GW_EINVAL, "gw_param_set_value: p is NULL");
    if (!gw_param_is_input(p))
        return gw_err_set(err, GW_EINVAL, "%s: a result, not a parameter", p->name);
    if (!value)
        return gw_err_set(err, GW_EINVAL, "%s: no value", p->name);
    if (!fieldp)
        return gw_err_set(err, GW_EINVAL, "gw_param_set_value: fieldp is NULL (setting %s)", p->name);
    gw_param row = *p; /* the same row with its field at fieldp */
    row.offset = 0;
    return set_text(NULL, &row, fieldp, value, err);
}

int gw_param_set_double(const gw_param *t, void *obj, const char *name, double v, gw_err *err)
{
    int arc = set_args_check("gw_param_set_double", t, name, err);
    if (arc != GW_OK)
        return arc;
    const gw_param *p = gw_param_find(t, name);
    if (!p)
        return gw_err_set(err, GW_EINVAL, "unknown parameter '%s'", name ? name : "(null)");
    if (!obj)
        return gw_err_set(err, GW_EINVAL, "gw_param_set_double: obj is NULL (setting %s)", p->name);
    return set_number(p, obj, v, NULL, err);
}

int gw_param_check(const gw_param *t, const void *obj, gw_err *err)
{
    if (!t || !obj)
        return gw_err_set(err, GW_EINVAL, "gw_param_check: %s is NULL", !t ? "table" : "obj");
    for (int i = 0; t && t[i].name; i++) {
        const gw_param *p = &t[i];
        const void *f = cfield(obj, p);
        int rc = GW_OK;
        switch (p->type) {
        case GW_PARAM_DOUBLE:
        case GW_PARAM_COUNT: {
            double v = *(const double *)f;
            if (isnan(v) && (!p->def || p->optional))
                break;
            if (!isfinite(v))
                return gw_err_set(err, GW_EINVAL, "%s: must be a finite number, got %g", p->name, v);
            rc = subnormal_bad(p, v, err, "");
            if (rc == GW_OK)
                rc = range_bad(p, v, err, "");
            if (rc == GW_OK && p->type == GW_PARAM_COUNT)
                rc = count_bad(p, v, NULL, err);
            break;
        }
        case GW_PARAM_INT:
            if (!unset(p, f))
                rc = range_bad(p, *(const int *)f, err, "");
            break;
        case GW_PARAM_LONG:
            if (!unset(p, f))
                rc = range_bad(p, (double)*(const long *)f, err, "");
            break;
        case GW_PARAM_FLAG:
            if (*(const int *)f != 0 && *(const int *)f != 1)
                rc = gw_err_set(err, GW_EINVAL, "%s: %d is not a flag (0 or 1)", p->name, *(const int *)f);
            break;
        case GW_PARAM_CHOICE: {
            int c = *(const int *)f;
            if ((c < 0 && p->def && !p->optional) || c >= choice_count(p->choices))
                rc = gw_err_set(err, GW_EINVAL, "%s: choice %d is not one of %s", p->name, c, p->choices);
            break;
        }
        case GW_PARAM_LIST: {
            const gw_param_list *l = f;
            if (l->n < 0 || (l->n > 0 && !l->v)) {
                rc = gw_err_set(err, GW_EINVAL, "%s: a list of %d items %s", p->name, l->n,
                                l->n < 0 ? "(a negative count)" : "without its values (v is NULL)");
                break;
            }
            if (l->n > list_most(t, p)) {
                rc = gw_err_set(err, GW_EINVAL, "%s: %d items, at most %ld", p->name, l->n, list_most(t, p));
                break;
            }
            for (int k = 0; k < l->n && rc == GW_OK; k++) {
                char what[32];
                gw_snprintf(what, sizeof what, "item %d is ", k + 1);
                rc = !isfinite(l->v[k]) ? gw_err_set(err, GW_EINVAL, "%s: item %d is not finite", p->name, k + 1)
                     : subnormal_bad(p, l->v[k], err, what) != GW_OK ? GW_EINVAL
                                                                       : range_bad(p, l->v[k], err, what);
            }
            break;
        }
        case GW_PARAM_RANGE: {
            const long *r = f;
            rc = range_bad(p, (double)r[0], err, "");
            if (rc == GW_OK)
                rc = range_bad(p, (double)r[1], err, "");
            if (rc == GW_OK && r[0] > r[1])
                rc = gw_err_set(err, GW_EINVAL, "%s: range %ld:%ld is empty (start > end)", p->name, r[0], r[1]);
            break;
        }
        default: break;
        }
        if (rc != GW_OK)
            return rc;
    }
    return GW_OK;
}

int gw_param_init(const gw_param *t, void *obj, gw_err *err)
{
    if (!t || !obj)
        return gw_err_set(err, GW_EINVAL, "gw_param_init: %s is NULL", !t ? "table" : "obj");
    for (int i = 0; t && t[i].name; i++) {
        const gw_param *p = &t[i];
        void *f = field(obj, p);
        switch (p->type) {
        case GW_PARAM_DOUBLE:
        case GW_PARAM_COUNT: *(double *)f = NAN; break;
        case GW_PARAM_INT: *(int *)f = p->optional ? GW_PARAM_UNSET_INT : 0; break;
        case GW_PARAM_FLAG: *(int *)f = 0; break;
        case GW_PARAM_LONG: *(long *)f = p->optional ? GW_PARAM_UNSET_LONG : 0; break;
        case GW_PARAM_CHOICE: *(int *)f = -1; break;
        case GW_PARAM_TEXT: *(char **)f = NULL; break;
        case GW_PARAM_LIST: memset(f, 0, sizeof(gw_param_list)); break;
        case GW_PARAM_RANGE: ((long *)f)[0] = ((long *)f)[1] = 0; break;
        case GW_PARAM_DARRAY: *(double **)f = NULL; break;
        case GW_PARAM_IARRAY:
        case GW_PARAM_FARRAY: *(int **)f = NULL; break;
        }
        if (p->def && !p->optional && gw_param_is_input(p)) {
            int rc = set_text(t, p, obj, p->def, err);
            if (rc != GW_OK)
                return rc;
        }
    }
    return GW_OK;
}

int gw_param_given(const gw_param *p, const void *obj)
{
    if (!p || !obj || !gw_param_is_input(p))
        return 0;
    const void *f = cfield(obj, p);
    if (p->optional || !p->def) {
        switch (p->type) {
        case GW_PARAM_DOUBLE:
        case GW_PARAM_COUNT: return !isnan(*(const double *)f);
        case GW_PARAM_INT: return !unset(p, f) && (p->optional || *(const int *)f != 0);
        case GW_PARAM_LONG: return !unset(p, f) && (p->optional || *(const long *)f != 0);
        case GW_PARAM_FLAG: return *(const int *)f != 0;
        case GW_PARAM_CHOICE: return *(const int *)f >= 0;
        case GW_PARAM_TEXT: return *(char *const *)f != NULL;
        case GW_PARAM_LIST: return ((const gw_param_list *)f)->n > 0;
        case GW_PARAM_RANGE: return ((const long *)f)[0] != 0 || ((const long *)f)[1] != 0;
        default: return 0;
        }
    }
    /* a row with a default: given when its value is not the default's (both as
     * gw_param_format writes them) */
    char a[512], b[512];
    if (p->type == GW_PARAM_TEXT || p->type == GW_PARAM_LIST)
        return gw_param_format(p, obj, a, sizeof a) != 0 && strcmp(a, p->def) != 0;
    union {
        double d;
        int i;
        long l;
        long r[2];
    } u;
    memset(&u, 0, sizeof u);
    gw_param row = *p;
    row.offset = 0;
    return gw_param_set_value(p, &u, p->def, NULL) != GW_OK || gw_param_format(p, obj, a, sizeof a) < 0 ||
           gw_param_format(&row, &u, b, sizeof b) < 0 || strcmp(a, b) != 0;
}

int gw_param_resolve(const gw_param *t, void *obj, gw_err *err)
{
    if (!t || !obj)
        return gw_err_set(err, GW_EINVAL, "gw_param_resolve: %s is NULL", !t ? "table" : "obj");
    for (int i = 0; t[i].name; i++) {
        const gw_param *p = &t[i];
        if (!p->optional || !p->def || !gw_param_is_input(p) || gw_param_given(p, obj))
            continue;
        int rc = set_text(t, p, obj, p->def, err);
        if (rc != GW_OK)
            return rc;
    }
    return GW_OK;
}

int gw_param_format(const gw_param *p, const void *obj, char *buf, size_t n)
{
    if (!p || !obj || !buf || n == 0)
        return -1;
    const void *f = cfield(obj, p);
    int w = -1;
    buf[0] = '\0';
    switch (p->type) {
    case GW_PARAM_DOUBLE:
    case GW_PARAM_COUNT:
        w = isnan(*(const double *)f) ? 0 : gw_snprintf(buf, n, "%.17g", *(const double *)f);
        break;
    case GW_PARAM_INT:
    case GW_PARAM_FLAG: w = unset(p, f) ? 0 : gw_snprintf(buf, n, "%d", *(const int *)f); break;
    case GW_PARAM_LONG: w = unset(p, f) ? 0 : gw_snprintf(buf, n, "%ld", *(const long *)f); break;
    case GW_PARAM_CHOICE:
        w = *(const int *)f < 0 ? 0 : choice_name(p->choices, *(const int *)f, buf, n);
        break;
    case GW_PARAM_TEXT: {
        const char *s = *(char *const *)f;
        w = gw_snprintf(buf, n, "%s", s ? s : "");
        break;
    }
    case GW_PARAM_LIST: {
        const gw_param_list *l = f;
        /* a list counted without its values, or a negative count (gw_param_check
         * refuses both): its NULL v was read (SIGSEGV) */
        if (l->n < 0 || (l->n > 0 && !l->v))
            return -1;
        w = 0;
        for (int i = 0; i < l->n && w >= 0 && (size_t)w < n; i++)
            w += gw_snprintf(buf + w, n - (size_t)w, "%s%.17g", i ? "," : "", l->v[i]);
        break;
    }
    case GW_PARAM_RANGE: {
        const long *r = f;
        w = gw_snprintf(buf, n, "%ld:%ld", r[0], r[1]);
        break;
    }
    default: return -1;
    }
    return w < 0 || (size_t)w >= n ? -1 : w;
}

cJSON *gw_param_json(const gw_param *t, const void *obj)
{
    if (!t || !obj) /* a NULL table was written {}: settings of no rows */
        return NULL;
    cJSON *o = cJSON_CreateObject();
    for (int i = 0; o && t && t[i].name; i++) {
        const gw_param *p = &t[i];
        const void *f = cfield(obj, p);
        cJSON *v = NULL;
        char buf[256];
        switch (p->type) {
        case GW_PARAM_DOUBLE:
        case GW_PARAM_COUNT:
            v = isfinite(*(const double *)f) ? cJSON_CreateNumber(*(const double *)f) : cJSON_CreateNull();
            break;
        case GW_PARAM_INT:
            v = unset(p, f) ? cJSON_CreateNull() : cJSON_CreateNumber(*(const int *)f);
            break;
        case GW_PARAM_LONG:
            v = unset(p, f) ? cJSON_CreateNull() : cJSON_CreateNumber((double)*(const long *)f);
            break;
        case GW_PARAM_FLAG:
            /* a flag of 7 was written true, as 1 (gw_param_check refuses it) */
            if (*(const int *)f != 0 && *(const int *)f != 1) {
                cJSON_Delete(o);
                return NULL;
            }
            v = cJSON_CreateBool(*(const int *)f);
            break;
        case GW_PARAM_CHOICE:
            /* an index outside the names (99 of "rk4,cvode,arkode") was
             * written null, as not given: refused as gw_param_format's -1 */
            if (*(const int *)f >= 0 && gw_param_format(p, obj, buf, sizeof buf) < 0) {
                cJSON_Delete(o);
                return NULL;
            }
            v = *(const int *)f >= 0 ? cJSON_CreateString(buf) : cJSON_CreateNull();
            break;
        case GW_PARAM_TEXT: {
            /* the text as held: it went through a buffer of 256 bytes, and a
             * longer one (a sample's path of 300 characters) was written null,
             * a value given recorded as none */
            const char *s = *(char *const *)f;
            v = s && s[0] ? cJSON_CreateString(s) : cJSON_CreateNull();
            break;
        }
        case GW_PARAM_LIST: {
            const gw_param_list *l = f;
            /* a negative count was written [] (gw_param_format: -1) */
            if (l->n < 0) {
                cJSON_Delete(o);
                return NULL;
            }
            v = l->n ? gw_json_doubles(l->v, l->n) : cJSON_CreateNull();
            break;
        }
        case GW_PARAM_RANGE: {
            const long *r = f;
            double ab[2] = {(double)r[0], (double)r[1]};
            v = gw_json_doubles(ab, 2);
            break;
        }
        default: continue;
        }
        if (!v || !cJSON_AddItemToObject(o, p->name, v)) {
            cJSON_Delete(v);
            cJSON_Delete(o);
            return NULL;
        }
    }
    return o;
}

void gw_param_clear(const gw_param *t, void *obj)
{
    for (int i = 0; obj && t && t[i].name; i++) {
        void *f = field(obj, &t[i]);
        if (t[i].type == GW_PARAM_TEXT) {
            free(*(char **)f);
            *(char **)f = NULL;
        } else if (t[i].type == GW_PARAM_LIST) {
            gw_param_list *l = f;
            free(l->v);
            l->v = NULL;
            l->n = 0;
        }
    }
}

int gw_param_copy(const gw_param *t, size_t size, void *dst, const void *src, gw_err *err)
{
    if (!dst || !src)
        return gw_err_set(err, GW_EINVAL, "gw_param_copy: %s is NULL", !dst ? "dst" : "src");
    /* dst over src: the detach below cleared src's own texts and lists (they
     * leaked, and the copy had none) */
    const char *d = dst, *sc = src;
    if (d < sc + size && sc < d + size)
        return gw_err_set(err, GW_EINVAL, "gw_param_copy: dst and src overlap (a copy needs another struct)");
    for (int i = 0; t && t[i].name; i++)
        if (t[i].offset + param_field_size(&t[i]) > size)
            return gw_err_set(err, GW_EINVAL, "gw_param_copy: size %zu is below the table's row '%s' (offset %zu)",
                              size, t[i].name, t[i].offset);
    memcpy(dst, src, size);
    for (int i = 0; t && t[i].name; i++) { /* detach, then duplicate what src owns */
        void *f = field(dst, &t[i]);
        if (t[i].type == GW_PARAM_TEXT)
            *(char **)f = NULL;
        else if (t[i].type == GW_PARAM_LIST)
            memset(f, 0, sizeof(gw_param_list));
    }
    for (int i = 0; t && t[i].name; i++) {
        const void *s = cfield(src, &t[i]);
        void *f = field(dst, &t[i]);
        if (t[i].type == GW_PARAM_TEXT && *(char *const *)s) {
            if (!(*(char **)f = strdup(*(char *const *)s)))
                goto nomem;
        } else if (t[i].type == GW_PARAM_LIST && ((const gw_param_list *)s)->n > 0 && ((const gw_param_list *)s)->v) {
            const gw_param_list *ls = s;
            gw_param_list *ld = f;
            if (!(ld->v = malloc((size_t)ls->n * sizeof *ld->v)))
                goto nomem;
            memcpy(ld->v, ls->v, (size_t)ls->n * sizeof *ld->v);
            ld->n = ls->n;
        }
    }
    return GW_OK;
nomem:
    gw_param_clear(t, dst);
    return gw_err_set(err, GW_ENOMEM, "out of memory copying parameters");
}
