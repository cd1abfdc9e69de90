/*
 * fuzz_params.c: libFuzzer target over the parameter tables (gw_param.h) of
 * every study of the library (gw_study.h). No physics is run: only the
 * tables' setting, checking, formatting, JSON, copy and clear.
 *
 * Input: byte 0 picks the study (modulo gw_study_count()); the rest is lines
 * "NAME=VALUE" (split at '\n' or NUL), each set with gw_param_set on a struct
 * initialised from the table's defaults; a line without '=' writes its bytes
 * raw into the number field (double, int, long, flag, choice) of the row
 * picked by its first byte, as a caller writing the struct directly would, and
 * gw_param_check must then refuse it or accept it; a line starting with '#'
 * sets the row picked by its second byte from the double in its next 8 bytes
 * (gw_param_set_double).
 *
 * Asserted (abort otherwise), ASan/UBSan/LSan watching for the rest:
 *   - gw_param_set returns GW_OK, or GW_EINVAL (GW_ENOMEM) with a message that
 *     names the parameter ("NAME: ..." with the row's name, or "unknown
 *     parameter '...'" for a name that is no row), and a refused value leaves
 *     the row as it was (its text unchanged);
 *   - after a success the struct passes gw_param_check (the value is in its
 *     range), and the row's text set again gives the same text (round trip);
 *   - gw_param_json of any struct that passed the check is an object with one
 *     member per input row, gw_param_copy of it prints the same JSON, and
 *     gw_param_clear frees every owned field (LSan).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gw_param.h"
#include "gw_study.h"

static void fail_if(int bad)
{
    if (bad)
        abort();
}

static int is_number_row(const gw_param *p)
{
    return p->type == GW_PARAM_DOUBLE || p->type == GW_PARAM_INT || p->type == GW_PARAM_LONG ||
           p->type == GW_PARAM_FLAG || p->type == GW_PARAM_CHOICE || p->type == GW_PARAM_COUNT;
}

static size_t field_size(const gw_param *p)
{
    return p->type == GW_PARAM_DOUBLE || p->type == GW_PARAM_COUNT ? sizeof(double) : p->type == GW_PARAM_LONG ? sizeof(long) : sizeof(int);
}

/* the message names the row, or says the name is unknown */
static void check_message(const gw_param *t, const char *name, const gw_err *e)
{
    const gw_param *p = gw_param_find(t, name);
    fail_if(!e->msg[0]);
    if (!p) {
        fail_if(strncmp(e->msg, "unknown parameter '", 19) != 0 && strstr(e->msg, "a result") == NULL);
        return;
    }
    size_t n = strlen(p->name);
    fail_if(strncmp(e->msg, p->name, n) != 0 || e->msg[n] != ':');
}

static void set_line(const gw_param *t, void *obj, char *line)
{
    char *eq = strchr(line, '=');
    *eq = '\0';
    const char *name = line, *value = eq + 1;
    const gw_param *p = gw_param_find(t, name);
    char before[4096] = "", after[4096] = "", again[4096] = "";
    if (p && gw_param_is_input(p))
        gw_param_format(p, obj, before, sizeof before);
    gw_err e = {{0}};
    int rc = gw_param_set(t, obj, name, value, &e);
    if (rc == GW_ENOMEM)
        return;
    if (rc != GW_OK) {
        fail_if(rc != GW_EINVAL);
        check_message(t, name, &e);
        if (p && gw_param_is_input(p)) { /* refused: the row is unchanged */
            gw_param_format(p, obj, after, sizeof after);
            fail_if(strcmp(before, after) != 0);
        }
        return;
    }
    fail_if(!p || !gw_param_is_input(p));
    gw_err c = {{0}};
    fail_if(gw_param_check(t, obj, &c) != GW_OK); /* the value is in its range */
    /* round trip: the row's text set again reads back the same */
    if (gw_param_format(p, obj, after, sizeof after) > 0 && p->type != GW_PARAM_TEXT) {
        fail_if(gw_param_set(t, obj, p->name, after, &e) != GW_OK);
        fail_if(gw_param_format(p, obj, again, sizeof again) < 0 || strcmp(after, again) != 0);
    }
}

/* raw bytes into a number field: the check accepts or refuses, never crashes */
static void raw_line(const gw_param *t, int nrows, void *obj, const uint8_t *b, size_t n)
{
    if (n < 1 || nrows == 0)
        return;
    const gw_param *p = &t[b[0] % nrows];
    if (!is_number_row(p))
        return;
    unsigned char *f = (unsigned char *)obj + p->offset;
    size_t sz = field_size(p);
    memset(f, 0, sz);
    memcpy(f, b + 1, n - 1 < sz ? n - 1 : sz);
    gw_err e = {{0}};
    int rc = gw_param_check(t, obj, &e);
    fail_if(rc != GW_OK && (rc != GW_EINVAL || !e.msg[0]));
    if (rc != GW_OK) { /* put the default back so that the struct stays valid */
        gw_param row[2] = {*p, GW_PARAM_END};
        memset(f, 0, sz);
        fail_if(gw_param_init(row, obj, NULL) != GW_OK);
    }
}

static void double_line(const gw_param *t, int nrows, void *obj, const uint8_t *b, size_t n)
{
    double v;
    if (n < 2 + sizeof v || nrows == 0)
        return;
    const gw_param *p = &t[b[1] % nrows];
    memcpy(&v, b + 2, sizeof v);
    gw_err e = {{0}};
    int rc = gw_param_set_double(t, obj, p->name, v, &e);
    if (rc == GW_OK) {
        fail_if(gw_param_check(t, obj, &e) != GW_OK);
    } else {
        fail_if(rc != GW_EINVAL);
        check_message(t, p->name, &e);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1 || gw_study_count() < 1)
        return 0;
    const gw_study *s = gw_study_get(data[0] % gw_study_count());
    const gw_param *t = s->params();
    const int nrows = gw_param_count(t);
    void *obj = calloc(1, s->params_size), *copy = calloc(1, s->params_size);
    char *buf = malloc(size);
    if (!obj || !copy || !buf)
        goto out;
    fail_if(s->init(obj) != GW_OK);
    memcpy(buf, data + 1, size - 1);
    buf[size - 1] = '\0';
    for (size_t i = 0; i < size - 1;) {
        size_t len = 0;
        while (i + len < size - 1 && buf[i + len] != '\n' && buf[i + len] != '\0')
            len++;
        buf[i + len] = '\0';
        char *line = buf + i;
        if (len > 0 && line[0] == '#')
            double_line(t, nrows, obj, (const uint8_t *)data + 1 + i, len);
        else if (strchr(line, '='))
            set_line(t, obj, line);
        else
            raw_line(t, nrows, obj, (const uint8_t *)data + 1 + i, len);
        i += len + 1;
    }
    /* the struct is valid here: JSON, copy and clear */
    gw_err e = {{0}};
    fail_if(gw_param_check(t, obj, &e) != GW_OK);
    cJSON *j = gw_param_json(t, obj);
    if (j) {
        int inputs = 0;
        for (int k = 0; k < nrows; k++)
            inputs += gw_param_is_input(&t[k]);
        fail_if(!cJSON_IsObject(j) || cJSON_GetArraySize(j) != inputs);
        if (gw_param_copy(t, s->params_size, copy, obj, &e) == GW_OK) {
            cJSON *jc = gw_param_json(t, copy);
            char *a = cJSON_PrintUnformatted(j), *b = jc ? cJSON_PrintUnformatted(jc) : NULL;
            fail_if(a && b && strcmp(a, b) != 0);
            cJSON_free(a);
            cJSON_free(b);
            cJSON_Delete(jc);
            s->clear(copy);
        }
        cJSON_Delete(j);
    }
out:
    if (obj)
        s->clear(obj);
    free(obj);
    free(copy);
    free(buf);
    return 0;
}
