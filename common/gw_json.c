/*
 * gw_json.c: JSON output through cJSON (arrays of numbers, printing, atomic files).
 * Numbers are printed exactly: the shortest of %.15g, %.16g, %.17g that reads
 * back as the same double (cJSON's own printer stops at 15 digits when they
 * read back within one ulp, so a JSON value could differ in its last bit from
 * the same value in an HDF5 or CSV file: alpha_r 8.73474671993196 against
 * 8.734746719931962). Integers, and NaN and infinities as null, as cJSON.
 */
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
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; a && i < n; i++) {
        cJSON *b = cJSON_CreateBool(v[i] != 0);
        if (!b) {
            cJSON_Delete(a);
            return NULL;
        }
        cJSON_AddItemToArray(a, b);
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

char *gw_json_string(const cJSON *o, int formatted)
{
    if (json_failures)
        return NULL; /* o may lack a member cJSON could not allocate */
    cJSON *d = cJSON_Duplicate(o, 1); /* a copy is converted */
    char *s = d && exact_numbers(d) ? (formatted ? cJSON_Print(d) : cJSON_PrintUnformatted(d)) : NULL;
    cJSON_Delete(d);
    return s;
}

int gw_json_print(const cJSON *o, FILE *fp)
{
    char *s = gw_json_string(o, 1);
    if (!s)
        return GW_ENOMEM;
    int bad = fputs(s, fp) < 0 || fputc('\n', fp) == EOF || fflush(fp) != 0;
    free(s);
    return bad ? GW_EIO : GW_OK;
}

int gw_json_write(const char *path, const cJSON *o, gw_err *err)
{
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
