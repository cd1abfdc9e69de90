/*
 * gw_common.c: status table, error text, version, the monotonic clock,
 * validated number parsing.
 */
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>

#include "gw_common.h"
#include "gw_locale.h"
#include "gw_number_impl.h"

const char *gw_strerror(int status)
{
    switch (status) {
    case GW_OK: return "ok";
    case GW_ROOT: return "stopped at an event";
    case GW_EINVAL: return "invalid input";
    case GW_ENOMEM: return "out of memory";
    case GW_EIO: return "input/output error";
    case GW_ESOLVER: return "ODE solver failure";
    case GW_EFORMAT: return "malformed file";
    case GW_EUNSUPPORTED: return "not supported";
    case GW_EENERGY: return "energy error above threshold";
    case GW_ELIMIT: return "step or time limit reached";
    case GW_ECANCELED: return "canceled by the caller";
    default: return "unknown status";
    }
}

const char *gw_version(void)
{
    return GW_VERSION;
}

int gw_version_major(void)
{
    return GW_VERSION_MAJOR;
}

int gw_version_minor(void)
{
    return GW_VERSION_MINOR;
}

int gw_version_patch(void)
{
    return GW_VERSION_PATCH;
}

double gw_clock_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

/* The message as one line of UTF-8: a control character that a caller's value
 * brought in (a newline, a carriage return, a tab, an escape sequence) is
 * written \n, \r, \t or \xHH, and so is a byte that is no part of a whole UTF-8
 * character (a value cut by the message's bound, a Latin-1 name), so that the text
 * is one line that shows every byte it quotes. A message cut at the end of dst
 * is cut between characters. Backslashes are kept as they are, so a message
 * that quotes another message is escaped once. */
void gw_one_line(char *dst, size_t n, const char *src)
{
    static const char hex[] = "0123456789abcdef";
    size_t o = 0;
    for (const unsigned char *c = (const unsigned char *)src; *c;) {
        size_t want = *c < 0x80 ? 1 : *c >= 0xc2 && *c <= 0xdf ? 2 : *c >= 0xe0 && *c <= 0xef ? 3
                    : *c >= 0xf0 && *c <= 0xf4 ? 4 : 0;
        size_t len = 1;
        while (want > 1 && len < want && (c[len] & 0xc0) == 0x80)
            len++;
        char esc[4];
        const char *piece = (const char *)c;
        size_t plen = len;
        if (*c < 0x20 || *c == 0x7f || want == 0 || len < want) {
            len = 1;
            piece = esc;
            esc[0] = '\\';
            if (*c == '\n' || *c == '\r' || *c == '\t') {
                esc[1] = *c == '\n' ? 'n' : *c == '\r' ? 'r' : 't';
                plen = 2;
            } else {
                esc[1] = 'x';
                esc[2] = hex[*c >> 4];
                esc[3] = hex[*c & 15];
                plen = 4;
            }
        }
        if (o + plen + 1 > n)
            break;
        memcpy(dst + o, piece, plen);
        o += plen;
        c += len;
    }
    dst[o] = '\0';
}

/* The start of a UTF-8 character at or after p (a continuation byte is none). */
static size_t char_start_after(const char *s, size_t p)
{
    while (s[p] && ((unsigned char)s[p] & 0xc0) == 0x80)
        p++;
    return p;
}

/* A message longer than err->msg keeps its start, which names the input ("CMD
 * --NAME: 'VALUE'"), and its end, which says what is wrong with it, with
 * " ... " between: cut at the end, a path near PATH_MAX (4095 bytes) quoted in
 * a message filled all of it, and "granwave dispersion --wisdom: 'hhh...h"
 * said nothing of why. A message of up to 8 KiB is formatted on the stack; a
 * longer one (a value of 100,000 characters) on the heap, and cut at its end
 * as before when that allocation fails. */
int gw_err_set(gw_err *err, int status, const char *fmt, ...)
{
    if (!err)
        return status;
    if (!fmt) /* no message: an empty one (vsnprintf read the NULL: SIGSEGV) */
        fmt = "(no message)";
    char raw_s[8192], line_s[8192], *raw = raw_s, *line = line_s, *raw_h = NULL, *line_h = NULL;
    size_t room = sizeof line_s;
    va_list ap;
    va_start(ap, fmt);
    int want = gw_vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (want >= (int)sizeof raw_s) { /* every byte escaped as \xNN at most */
        raw_h = malloc((size_t)want + 1);
        line_h = malloc(4 * (size_t)want + 1);
        if (raw_h && line_h) {
            raw = raw_h;
            line = line_h;
            room = 4 * (size_t)want + 1;
        }
    }
    va_start(ap, fmt);
    gw_vsnprintf(raw, raw == raw_h ? (size_t)want + 1 : sizeof raw_s, fmt, ap);
    va_end(ap);
    gw_one_line(line, room, raw);
    const size_t len = strlen(line), n = sizeof err->msg;
    if (len < n) {
        memcpy(err->msg, line, len + 1);
    } else {
        static const char gap[] = " ... ";
        size_t head = n / 3, tail = char_start_after(line, len - (n - 1 - head - (sizeof gap - 1)));
        while (head > 0 && ((unsigned char)line[head] & 0xc0) == 0x80) /* line[head] starts a character */
            head--;
        gw_snprintf(err->msg, n, "%.*s%s%s", (int)head, line, gap, line + tail);
    }
    free(raw_h);
    free(line_h);
    return status;
}

int gw_warnings_add(char **list, const char *fmt, ...)
{
    if (!list || !fmt)
        return GW_EINVAL;
    va_list ap;
    va_start(ap, fmt);
    int len = gw_vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (len < 0)
        return GW_EINVAL;
    char *raw = malloc((size_t)len + 1);
    const size_t room = 4 * (size_t)len + 1; /* every byte escaped as \xNN at most */
    char *line = malloc(room);
    const size_t have = *list ? strlen(*list) : 0;
    if (raw && line) {
        va_start(ap, fmt);
        gw_vsnprintf(raw, (size_t)len + 1, fmt, ap);
        va_end(ap);
        gw_one_line(line, room, raw); /* one text, one line, as an error message */
    }
    char *grown = raw && line ? realloc(*list, have + strlen(line) + 2) : NULL;
    if (grown) {
        strcpy(grown + have, line);
        strcat(grown + have, "\n");
        *list = grown;
    }
    free(raw);
    free(line);
    return grown ? GW_OK : GW_ENOMEM;
}

/* A number's text: blanks (spaces, tabs) are allowed around it, on both sides
 * alike ("0.3, 0.5" and "0.3 , 0.5"); before the sixteenth session of stage 2,
 * strtod and strtol took ' 5' as 5 and '5 ' was not an integer. Other white
 * space (a newline, a carriage return) is no part of a number, before it (which
 * strtod would skip) or after it. */
static int number_ends(const char *s, const char *end)
{
    if (end == s)
        return 0;
    for (const char *p = s; p < end && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r' || *p == '\f' ||
                                        *p == '\v'); p++)
        if (*p != ' ' && *p != '\t')
            return 0;
    while (*end == ' ' || *end == '\t')
        end++;
    return *end == '\0';
}

char *gw_num_bound(char *buf, size_t n, double x, int upper)
{
    if (!buf || n == 0)
        return buf;
    /* %g when the value it reads back lies on the range's side of x (x
     * itself, or inside); else the six-digit value one step inside of it
     * (x near a power of ten may need a second step); else every digit */
    double c = x;
    const double step = isfinite(x) && x != 0 ? pow(10.0, floor(log10(fabs(x))) - 5) : 0;
    for (int i = 0; i < 3; i++) {
        gw_snprintf(buf, n, "%g", c);
        const double y = gw_strtod(buf, NULL);
        if (!isfinite(x) || (upper ? y <= x : y >= x))
            return buf;
        c = upper ? y - step : y + step;
    }
    gw_snprintf(buf, n, "%.17g", x);
    return buf;
}

/* Interval [a, b] ("(" / ")" for open ends) as "a value in [a, b]", or
 * ">= a", "< b" when the other end is unbounded, appended to buf. */
static void interval_text(char *buf, size_t n, double a, int open_a, double b, int open_b, int whole)
{
    char as[32], bs[32];
    size_t used = strlen(buf);
    if (whole && fabs(a) < 9007199254740992.0 && fabs(b) < 9007199254740992.0) {
        /* a count's bounds as the whole numbers it takes ([1, 8388606], not
         * 8.3886e+06: the help's and the other refusals' text) */
        gw_snprintf(as, sizeof as, "%.0f", open_a ? floor(a) + 1 : ceil(a));
        gw_snprintf(bs, sizeof bs, "%.0f", open_b ? ceil(b) - 1 : floor(b));
        open_a = open_b = 0;
    } else {
        gw_num_bound(as, sizeof as, a, 0); /* as the range messages print bounds */
        gw_num_bound(bs, sizeof bs, b, 1);
    }
    if (isinf(a) && isinf(b))
        gw_snprintf(buf + used, n - used, "any value");
    else if (isinf(b))
        gw_snprintf(buf + used, n - used, "a value %s %s", open_a ? ">" : ">=", as);
    else if (isinf(a))
        gw_snprintf(buf + used, n - used, "a value %s %s", open_b ? "<" : "<=", bs);
    else if (a == b)
        gw_snprintf(buf + used, n - used, "%s", as);
    else
        gw_snprintf(buf + used, n - used, "a value in %s%s, %s%s", open_a ? "(" : "[", as, bs, open_b ? ")" : "]");
}

char *gw_num_allowed(char *buf, size_t n, const gw_num_range *r)
{
    if (!buf || n == 0)
        return buf;
    buf[0] = '\0';
    const gw_num_range any = {-INFINITY, INFINITY, 0, 0, 0, 0};
    if (!r)
        r = &any;
    const double m = DBL_MIN, lo = r->lo, hi = r->hi;
    /* the parts of [lo, hi] a double holds normally: x <= -m, 0, x >= m */
    const int zero = r->or_zero || ((lo < 0 || (lo == 0 && !r->open_lo)) && (hi > 0 || (hi == 0 && !r->open_hi)));
    const int neg = lo <= -m && !(lo == -m && r->open_lo), pos = hi >= m && !(hi == m && r->open_hi);
    char ms[32];
    gw_snprintf(ms, sizeof ms, "%.5g", m); /* 2.2251e-308: above DBL_MIN, a normal double */
    if (neg && pos) { /* both signs: the range, its magnitudes from m up */
        char range[80] = "";
        if (!isinf(lo) || !isinf(hi)) {
            interval_text(range, sizeof range, lo, r->open_lo, hi, r->open_hi, r->whole);
            memmove(range, range + strlen("a value"), strlen(range) - strlen("a value") + 1);
        }
        gw_snprintf(buf, n, "%sa value%s of magnitude at least %s", zero ? "0 or " : "", range, ms);
        return buf;
    }
    if (neg) /* [lo, min(hi, -m)] */
        interval_text(buf, n, lo, r->open_lo, hi > -m ? -gw_strtod(ms, NULL) : hi, hi > -m ? 0 : r->open_hi, r->whole);
    if (zero) {
        size_t used = strlen(buf);
        gw_snprintf(buf + used, n - used, "%s0", neg ? " or " : "");
    }
    if (pos) { /* [max(lo, m), hi] */
        size_t used = strlen(buf);
        gw_snprintf(buf + used, n - used, "%s", zero ? " or " : "");
        interval_text(buf, n, lo < m ? gw_strtod(ms, NULL) : lo, lo < m ? 0 : r->open_lo, hi, r->open_hi, r->whole);
    }
    if (!neg && !zero && !pos) /* a range of subnormals alone: no input has one */
        gw_snprintf(buf, n, "no value: the range is below %s", ms);
    return buf;
}

int gw_num_subnormal_refused(const char *name, const char *what, const gw_num_range *r, gw_err *err)
{
    char allowed[160];
    return gw_err_set(err, GW_EINVAL, "%s: %s is too small in magnitude: nonzero values lie at or above %.5g, "
                      "the smallest normal double (give %s)", name ? name : "value", what, DBL_MIN,
                      gw_num_allowed(allowed, sizeof allowed, r));
}

/* gw_number_impl.h: a refusal's quote of a number's text (2**1100's 332
 * digits were quoted whole before session 43), a choice's and a flag's too */
const char *gw_text_shown(char *buf, size_t n, const char *s, const char *quote)
{
    const size_t len = strlen(s);
    if (len <= 40)
        gw_snprintf(buf, n, "%s%s%s", quote, s, quote);
    else
        gw_snprintf(buf, n, "%s%.20s...%s (%zu characters)", quote, s, quote, len);
    return buf;
}

int gw_parse_double_in(const char *s, const char *name, const gw_num_range *r, double *out, gw_err *err)
{
    if (!out)
        return gw_err_set(err, GW_EINVAL, "gw_parse_double: out is NULL");
    if (!name) /* as gw_check_range (it was printed "(null)") */
        name = "value";
    if (!s || !*s)
        return gw_err_set(err, GW_EINVAL, "%s: expected a number, got an empty value", name);
    char *end = NULL;
    errno = 0;
    double v = gw_strtod(s, &end);
    if (!number_ends(s, end))
        return gw_err_set(err, GW_EINVAL, "%s: '%s' is not a number", name, s);
    char shown[96];
    if (!isfinite(v) || (errno == ERANGE && fabs(v) >= 1.0))
        return gw_err_set(err, GW_EINVAL, "%s: %s is not a finite number", name, gw_text_shown(shown, sizeof shown, s, "'"));
    /* one rule for numbers in text: decimal, as integers (gw_parse_long_in,
     * base 10) are; strtod's hexadecimal ("0x1p-2") was taken for a real
     * input where "0x3" was refused for an integer */
    if (gw_num_is_hex(s, end))
        return gw_err_set(err, GW_EINVAL, "%s: '%s' is not a decimal number (no hexadecimal, as for integers)",
                          name, s);
    if (errno == ERANGE || (v != 0 && fabs(v) < DBL_MIN)) { /* strtod's underflow: no normal double */
        return gw_num_subnormal_refused(name, gw_text_shown(shown, sizeof shown, s, "'"), r, err);
    }
    *out = v;
    return GW_OK;
}

int gw_num_is_hex(const char *s, const char *end)
{
    return s && end > s && (memchr(s, 'x', (size_t)(end - s)) || memchr(s, 'X', (size_t)(end - s)));
}

int gw_data_number(const char *s, double *v)
{
    double x = 0;
    char *end = NULL;
    if (!s || !*s) {
        if (v)
            *v = 0;
        return GW_DATA_NONE;
    }
    errno = 0;
    x = gw_strtod(s, &end);
    if (v)
        *v = x;
    if (end == s || *end != '\0')
        return GW_DATA_NONE;
    if (gw_num_is_hex(s, end))
        return GW_DATA_HEX;
    if (errno == ERANGE && fabs(x) > 1)
        return GW_DATA_HUGE;
    return GW_DATA_NUMBER;
}

const char *gw_data_number_why(int code)
{
    switch (code) {
    case GW_DATA_NUMBER:
        return "";
    case GW_DATA_HEX:
        return "not a decimal number (no hexadecimal, as the program's options)";
    case GW_DATA_HUGE:
        return "not a finite number";
    default:
        return "not a number";
    }
}

int gw_parse_double(const char *s, const char *name, double *out, gw_err *err)
{
    return gw_parse_double_in(s, name, NULL, out, err);
}

char *gw_int_give(char *buf, size_t n, long lo, long hi, int or_zero)
{
    if (!buf || n == 0)
        return buf;
    buf[0] = '\0';
    if (lo > LONG_MIN || hi < LONG_MAX)
        gw_snprintf(buf, n, " (give %san integer in [%ld, %ld])", or_zero ? "0 or " : "", lo, hi);
    return buf;
}

int gw_parse_long_in(const char *s, const char *name, long lo, long hi, int or_zero, long *out, gw_err *err)
{
    if (!out) /* as gw_parse_double (it was written through: SIGSEGV) */
        return gw_err_set(err, GW_EINVAL, "gw_parse_long: out is NULL");
    if (!name) /* as gw_check_range (it was printed "(null)") */
        name = "value";
    /* bounds that are no range are the caller's error, as gw_check_range's: a
     * value was told "5 is outside [10, 0]", blamed on the input */
    if (lo > hi)
        return gw_err_set(err, GW_EINVAL, "gw_parse_long: %s: the bounds [%ld, %ld] are no range (lo > hi)", name, lo,
                          hi);
    if (!s || !*s)
        return gw_err_set(err, GW_EINVAL, "%s: expected an integer, got an empty value", name);
    char *end = NULL;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (!number_ends(s, end)) {
        /* the values the input takes, as a real number's refusal gives them
         * (1e-310 was "not an integer", naming no range) */
        char give[96];
        return gw_err_set(err, GW_EINVAL, "%s: '%s' is not an integer%s", name, s, gw_int_give(give, sizeof give, lo, hi, or_zero));
    }
    if (or_zero && errno == 0 && v == 0)
        return *out = 0, GW_OK;
    char shown[96];
    if (errno == ERANGE || v < lo || v > hi)
        return gw_err_set(err, GW_EINVAL, "%s: %s is outside [%ld, %ld]", name, gw_text_shown(shown, sizeof shown, s, ""),
                          lo, hi);
    *out = v;
    return GW_OK;
}

int gw_parse_long(const char *s, const char *name, long lo, long hi, long *out, gw_err *err)
{
    return gw_parse_long_in(s, name, lo, hi, 0, out, err);
}

int gw_check_range(double x, const char *name, double lo, double hi, gw_err *err)
{
    if (!name)
        name = "value";
    /* a NaN bound compares false both ways: it was taken as no bound, and any
     * finite x passed (the caller's error, refused naming the bound) */
    if (isnan(lo) || isnan(hi) || lo > hi)
        return gw_err_set(err, GW_EINVAL, "gw_check_range: %s: the bounds [%g, %g] are no range (%s)", name, lo, hi,
                          isnan(lo) ? "lo is NaN" : isnan(hi) ? "hi is NaN" : "lo > hi");
    if (!isfinite(x))
        return gw_err_set(err, GW_EINVAL, "%s: must be finite, got %g", name, x);
    if (x < lo || x > hi)
    {
        char xs[32];
        char ls[32], hs[32];
        return gw_err_set(err, GW_EINVAL, "%s: %s is outside [%s, %s]", name, gw_num_text(xs, sizeof xs, x),
                          gw_num_bound(ls, sizeof ls, lo, 0), gw_num_bound(hs, sizeof hs, hi, 1));
    }
    return GW_OK;
}

int gw_check_positive(double x, const char *name, gw_err *err)
{
    if (!name) /* as gw_check_range ("(null): must be ..." before) */
        name = "value";
    if (!isfinite(x) || !(x > 0))
        return gw_err_set(err, GW_EINVAL, "%s: must be a positive finite number, got %g", name, x);
    return GW_OK;
}

int gw_parse_double_list(const char *s, const char *name, double **out, int *n, gw_err *err)
{
    return gw_parse_double_list_range(s, name, NULL, out, n, err);
}

int gw_parse_double_list_in(const char *s, const char *name, double lo, double hi, int open_lo,
                            double **out, int *n, gw_err *err)
{
    const gw_num_range r = {lo, hi, open_lo, 0, 0, 0};
    return gw_parse_double_list_range(s, name, &r, out, n, err);
}

int gw_parse_double_list_range(const char *s, const char *name, const gw_num_range *r, double **out, int *n,
                               gw_err *err)
{
    const gw_num_range any = {-INFINITY, INFINITY, 0, 0, 0, 0};
    if (!r)
        r = &any;
    const double lo = r->lo, hi = r->hi;
    const int open_lo = r->open_lo;
    if (!out || !n)
        return gw_err_set(err, GW_EINVAL, "gw_parse_double_list: %s is NULL", !out ? "out" : "n");
    *out = NULL;
    *n = 0;
    if (!name) /* as gw_check_range (it was printed "(null)") */
        name = "list";
    if (isnan(lo) || isnan(hi)) /* as gw_check_range: no bound is -INFINITY/INFINITY, never NaN */
        return gw_err_set(err, GW_EINVAL, "gw_parse_double_list_in: %s: the bound %s is NaN", name,
                          isnan(lo) ? "lo" : "hi");
    /* lo > hi, or open_lo other than 0 and 1: the caller's error, as
     * gw_check_range's (every item was told "outside [3, 0]", and open_lo 2
     * ran as 1) */
    if (lo > hi || (open_lo != 0 && open_lo != 1))
        return gw_err_set(err, GW_EINVAL, "gw_parse_double_list_in: %s: %s", name,
                          lo > hi ? "the bounds are no range (lo > hi)" : "open_lo is not a flag (0 or 1)");
    if (!s || !*s)
        return gw_err_set(err, GW_EINVAL, "%s: empty list", name);
    size_t len = strlen(s);
    char *copy = malloc(len + 1);
    double *v = malloc((len / 2 + 2) * sizeof *v);
    if (!copy || !v) {
        free(copy);
        free(v);
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", name);
    }
    memcpy(copy, s, len + 1);
    int count = 0, rc = GW_OK;
    char *p = copy;
    for (;;) {
        char *comma = strchr(p, ',');
        if (comma)
            *comma = '\0';
        if ((rc = gw_parse_double_in(p, name, r, &v[count], err)) != GW_OK)
            break;
        double x = v[count];
        if (x < lo || x > hi || (open_lo && !(x > lo))) {
            char xs[32], ls[32], hs[32];
            gw_num_text(xs, sizeof xs, x);
            gw_num_bound(ls, sizeof ls, lo, 0);
            gw_num_bound(hs, sizeof hs, hi, 1);
            if (open_lo && !isfinite(hi))
                rc = gw_err_set(err, GW_EINVAL, "%s: item %d is %s, must be > %s", name, count + 1, xs, ls);
            else
                rc = gw_err_set(err, GW_EINVAL, "%s: item %d is %s, outside %s%s, %s]", name,
                                count + 1, xs, open_lo ? "(" : "[", ls, hs);
            break;
        }
        count++;
        if (!comma)
            break;
        p = comma + 1;
    }
    free(copy);
    if (rc != GW_OK) {
        free(v);
        return rc;
    }
    *out = v;
    *n = count;
    return GW_OK;
}

int gw_parse_int_range(const char *s, const char *name, long lo, long hi, long *a, long *b,
                       gw_err *err)
{
    /* a NULL name was read by strlen when an end was refused (SIGSEGV) */
    if (!name)
        name = "value";
    if (lo > hi) /* the caller's error, as gw_parse_long's */
        return gw_err_set(err, GW_EINVAL, "gw_parse_int_range: %s: the bounds [%ld, %ld] are no range (lo > hi)", name,
                          lo, hi);
    if (!s || !*s)
        return gw_err_set(err, GW_EINVAL, "%s: empty value", name);
    const char *colon = strchr(s, ':');
    if (!a || !b)
        return gw_err_set(err, GW_EINVAL, "gw_parse_int_range: %s is NULL", !a ? "a" : "b");
    if (!colon) {
        int rc = gw_parse_long(s, name, lo, hi, a, err);
        *b = *a;
        return rc;
    }
    char left[64];
    size_t ln = (size_t)(colon - s);
    if (ln >= sizeof left)
        return gw_err_set(err, GW_EINVAL, "%s: '%s' is not a range A:B (give an integer or a range A:B of "
                          "integers in [%ld, %ld], A <= B)", name, s, lo, hi);
    memcpy(left, s, ln);
    left[ln] = '\0';
    int rc = gw_parse_long(left, name, lo, hi, a, err);
    const int at_end = rc == GW_OK;
    if (rc == GW_OK)
        rc = gw_parse_long(colon + 1, name, lo, hi, b, err);
    if (rc != GW_OK && err) {
        /* an end's refusal ("'3:1' is not an integer") quoted a fragment of the
         * value: quote the whole value given and the form a range takes, then
         * the end's own reason (after its "NAME: ") */
        char why[sizeof err->msg];
        const size_t nl = strlen(name);
        const char *r = strncmp(err->msg, name, nl) == 0 && err->msg[nl] == ':' ? err->msg + nl + 1 : err->msg;
        while (*r == ' ')
            r++;
        gw_snprintf(why, sizeof why, "%s", r);
        return gw_err_set(err, rc, "%s: '%s' is not a range A:B of integers, A <= B (its %s: %s)", name, s,
                          at_end ? "end" : "start", why);
    }
    if (rc == GW_OK && *a > *b)
        rc = gw_err_set(err, GW_EINVAL, "%s: range '%s' is empty (start > end)", name, s);
    return rc;
}

char *gw_str_trim(char *s)
{
    if (!s)
        return NULL;
    while (*s == ' ' || *s == '\t')
        s++;
    size_t n = strlen(s);
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r'))
        s[--n] = '\0';
    return s;
}

int gw_parse_flag(const char *v)
{
    if (!v)
        return -1;
    if (strcmp(v, "1") == 0 || strcasecmp(v, "true") == 0)
        return 1;
    if (strcmp(v, "0") == 0 || strcasecmp(v, "false") == 0)
        return 0;
    return -1;
}
