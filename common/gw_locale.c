/*
 * gw_locale.c: number text in the "C" locale (gw_locale.h). The formatting
 * calls switch this thread to the "C" locale object (uselocale: a thread-local
 * pointer, no lock, no effect on other threads) and back; strtod_l reads with
 * it directly. The object is made once; should that fail (out of memory), the
 * calls run in whatever locale is current, as plain strtod and printf would.
 */
#define _GNU_SOURCE
#include <locale.h>
#include <math.h>
#include <pthread.h>
#include <stdlib.h>

#include "gw_locale.h"

static locale_t c_loc = (locale_t)0;
static pthread_once_t c_once = PTHREAD_ONCE_INIT;

static void make_c_locale(void) { c_loc = newlocale(LC_ALL_MASK, "C", (locale_t)0); }

static locale_t c_locale(void)
{
    pthread_once(&c_once, make_c_locale);
    return c_loc;
}

double gw_strtod(const char *s, char **end)
{
    locale_t c = c_locale();
    return c ? strtod_l(s, end, c) : strtod(s, end);
}

/* this thread in the "C" locale; the locale before (0: none was changed) */
static locale_t enter(void)
{
    locale_t c = c_locale();
    return c ? uselocale(c) : (locale_t)0;
}

static void leave(locale_t old)
{
    if (old)
        uselocale(old);
}

int gw_vsnprintf(char *buf, size_t n, const char *fmt, va_list ap)
{
    locale_t old = enter();
    int k = vsnprintf(buf, n, fmt, ap);
    leave(old);
    return k;
}

int gw_snprintf(char *buf, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int k = gw_vsnprintf(buf, n, fmt, ap);
    va_end(ap);
    return k;
}

const char *gw_num_text(char *buf, size_t n, double x)
{
    for (int digits = 6; digits <= 17; digits++) {
        gw_snprintf(buf, n, "%.*g", digits, x);
        if (!isfinite(x) || gw_strtod(buf, NULL) == x)
            break;
    }
    return buf;
}

int gw_fprintf(FILE *fp, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    locale_t old = enter();
    int k = vfprintf(fp, fmt, ap);
    leave(old);
    va_end(ap);
    return k;
}
