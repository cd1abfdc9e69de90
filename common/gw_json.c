/*
 * gw_json.c: JSON output through cJSON (arrays of numbers, printing, atomic files).
 * Numbers are printed exactly: the shortest of %.15g, %.16g, %.17g that reads
 * back as the same double (cJSON's own printer stops at 15 digits when they
 * read back within one ulp, so a JSON value could differ in its last bit from
 * the same value in an HDF5 or CSV file: alpha_r 8.73474671993196 against
 * 8.734746719931962). Integers, and NaN and infinities as null, as cJSON.
 * Text is printed as UTF-8, which JSON requires (RFC 8259): a byte of a key or
 * string that is not part of a well-formed UTF-8 sequence (a file name in
 * Latin-1, a stray byte of a table's comment) is printed as U+FFFD, so a
 * strict parser reads every output; valid UTF-8 is printed as given.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_common.h"
#include "gw_locale.h"

/* Failed allocations of cJSON in this thread (see gw_json_failures): thread
 * state, as a cJSON object is built and printed by one thread. */
static _Thread_local unsigned long json_failures;

static void *json_malloc(size_t n)
{
    void *p = malloc(n);
    if (!p)
        json_failures++;
    return p;
}

/* cJSON's allocator, installed when the library is loaded (before any cJSON
 * call of the program: cJSON_InitHooks is not thread-safe). */
__attribute__((constructor)) static void json_hooks(void)
{
    cJSON_Hooks h = {.malloc_fn = json_malloc, .free_fn = free};
    cJSON_InitHooks(&h);
}

unsigned long gw_json_failures(void)
{
    return json_failures;
}

void gw_json_failures_clear(void)
{
    json_failures = 0;
}

cJSON *gw_json_doubles(const double *v, int n)
{
    if (!v && n > 0)
        return NULL;
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; a && i < n; i++) {
        cJSON *x = cJSON_CreateNumber(v[i]);
        if (!x || !cJSON_AddItemToArray(a, x)) {
            cJSON_Delete(x);
            cJSON_Delete(a);
            return NULL;
        }
    }
    return a;
}

cJSON *gw_json_ints(const int *v, int n)
{
    return cJSON_CreateIntArray(v, n);
}

cJSON *gw_json_bools(const int *v, int n)
{
    if (!v && n > 0) /* no values: NULL, as gw_json_doubles and gw_json_ints (it read v[0]: SIGSEGV) */
        return NULL;
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; a && i < n; i++) {
        cJSON *b = cJSON_CreateBool(v[i] != 0);
        if (!b || !cJSON_AddItemToArray(a, b)) {
            cJSON_Delete(b);
            cJSON_Delete(a);
            return NULL;
        }
    }
    return a;
}

/* Every finite non-integer number of o (in place) as a raw node holding its
 * exact text; 0 on out of memory. */
static int exact_numbers(cJSON *o)
{
    for (cJSON *c = o; c; c = c->next) {
        if (c->child && !exact_numbers(c->child))
            return 0;
        if (!cJSON_IsNumber(c))
            continue;
        const double v = c->valuedouble;
        if (!isfinite(v) || (fabs(v) < 2147483647.0 && v == (double)c->valueint))
            continue; /* cJSON's null and integers */
        char buf[40];
        for (int digits = 15; digits <= 17; digits++) {
            gw_snprintf(buf, sizeof buf, "%.*g", digits, v);
            if (gw_strtod(buf, NULL) == v)
                break;
        }
        char *t = malloc(strlen(buf) + 1);
        if (!t)
            return 0;
        memcpy(t, buf, strlen(buf) + 1);
        c->type = cJSON_Raw;
        c->valuestring = t;
    }
    return 1;
}

size_t gw_utf8_len(const char *text)
{
    if (!text)
        return 0;
    const unsigned char *s = (const unsigned char *)text, c = s[0];
    if (c < 0x80)
        return 1;
    size_t n = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
    unsigned char lo = 0x80, hi = 0xbf; /* the second byte's range */
    if (c == 0xe0)
        lo = 0xa0;
    else if (c == 0xed)
        hi = 0x9f;
    else if (c == 0xf0)
        lo = 0x90;
    else if (c == 0xf4)
        hi = 0x8f;
    for (size_t i = 1; i < n; i++)
        if (s[i] < (i == 1 ? lo : 0x80) || s[i] > (i == 1 ? hi : 0xbf))
            return 0;
    return n;
}

/* *text as valid UTF-8 (in place: a new malloc'd string when a byte had to
 * become U+FFFD; *text freed unless owned is 0). 0 on out of memory. */
static int utf8_fix(char **text, int owned)
{
    const unsigned char *t = (const unsigned char *)*text;
    size_t bad = 0, len = 0;
    for (size_t k; t[len]; len += k ? k : 1)
        bad += (k = gw_utf8_len((const char *)t + len)) == 0;
    if (!bad)
        return 1;
    char *u = malloc(len + 2 * bad + 1), *w = u;
    if (!u)
        return 0;
    for (size_t i = 0, k; i < len; i += k ? k : 1) {
        if ((k = gw_utf8_len((const char *)t + i)) != 0) {
            memcpy(w, t + i, k);
            w += k;
        } else {
            memcpy(w, "\xef\xbf\xbd", 3); /* U+FFFD */
            w += 3;
        }
    }
    *w = '\0';
    if (owned)
        free(*text);
    *text = u;
    return 1;
}

/* Every key and string of o (in place) as valid UTF-8; 0 on out of memory. */
static int utf8_text(cJSON *o)
{
    for (cJSON *c = o; c; c = c->next) {
        if (c->child && !utf8_text(c->child))
            return 0;
        if (c->string) {
            const int owned = !(c->type & cJSON_StringIsConst);
            char *k = c->string;
            if (!utf8_fix(&k, owned))
                return 0;
            if (k != c->string) {
                c->string = k;
                c->type &= ~cJSON_StringIsConst; /* now the node's own */
            }
        }
        if (cJSON_IsString(c) && c->valuestring && !utf8_fix(&c->valuestring, 1))
            return 0;
    }
    return 1;
}

char *gw_json_string(const cJSON *o, int formatted)
{
    if (json_failures)
        return NULL; /* o may lack a member cJSON could not allocate */
    cJSON *d = cJSON_Duplicate(o, 1); /* a copy is converted */
    char *s = d && exact_numbers(d) && utf8_text(d) ? (formatted ? cJSON_Print(d) : cJSON_PrintUnformatted(d))
                                                     : NULL;
    cJSON_Delete(d);
    return s;
}

int gw_json_print(const cJSON *o, FILE *fp)
{
    if (!o || !fp) /* no object is no out of memory (it said GW_ENOMEM) */
        return GW_EINVAL;
    char *s = gw_json_string(o, 1);
    if (!s)
        return GW_ENOMEM;
    errno = 0;
    int bad = fputs(s, fp) < 0 || fputc('\n', fp) == EOF || fflush(fp) != 0;
    /* the failed write's errno for the caller's message: the flush above
     * empties the buffer, so a later fflush of fp succeeds with ferror set and
     * no errno (a closed pipe was reported as "Input/output error") */
    const int e = bad ? (errno ? errno : EIO) : 0;
    free(s);
    if (bad)
        errno = e;
    return bad ? GW_EIO : GW_OK;
}

int gw_json_write(const char *path, const cJSON *o, gw_err *err)
{
    if (!path || !o) /* "(null): out of memory" before */
        return gw_err_set(err, GW_EINVAL, "gw_json_write: %s is NULL", !path ? "path" : "o");
    char *s = gw_json_string(o, 1);
    if (!s)
        return gw_err_set(err, GW_ENOMEM, "%s: out of memory", path);
    gw_afile f;
    int rc = gw_afile_open(&f, path, err);
    if (rc == GW_OK) {
        fputs(s, f.fp);
        fputc('\n', f.fp);
        rc = gw_afile_commit(&f, err);
    }
    free(s);
    return rc;
}
