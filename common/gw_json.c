/*
 * gw_json.c: JSON output through cJSON (arrays of numbers, printing, atomic files).
 */
#include <stdlib.h>

#include "gw_common.h"

cJSON *gw_json_doubles(const double *v, int n)
{
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

int gw_json_print(const cJSON *o, FILE *fp)
{
    char *s = cJSON_Print(o);
    if (!s)
        return GW_ENOMEM;
    int bad = fputs(s, fp) < 0 || fputc('\n', fp) == EOF || fflush(fp) != 0;
    free(s);
    return bad ? GW_EIO : GW_OK;
}

int gw_json_write(const char *path, const cJSON *o, gw_err *err)
{
    char *s = cJSON_Print(o);
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
