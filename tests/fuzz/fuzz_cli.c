/*
 * fuzz_cli.c: libFuzzer target for the command-line validation layer
 * (gw_cli_parse with number, range and list parsing). The input is split at NUL
 * bytes into argv; every outcome must be success or GW_EINVAL with a message.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gw_cli.h"
#include "gw_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *buf = malloc(size + 1);
    char *argv[64];
    int argc = 0;
    if (!buf)
        return 0;
    memcpy(buf, data, size);
    buf[size] = '\0';
    for (size_t i = 0; i <= size && argc < 64;) {
        argv[argc++] = buf + i;
        i += strlen(buf + i) + 1;
    }
    long n = 1, jobs = 0;
    double v = 0.3, k = 1;
    int json = 0, help = 0, npos = 0;
    const char *s = NULL, *pos[2];
    gw_opt opts[] = {
        {.name = "n", .kind = GW_OPT_LONG, .dest = &n, .lo = 1, .hi = 50000000},
        {.name = "vimp", .kind = GW_OPT_DOUBLE, .dest = &v, .lo = 0, .hi = 1e3, .open_lo = 1},
        {.name = "k", .kind = GW_OPT_DOUBLE, .dest = &k, .lo = 0, .hi = INFINITY, .open_lo = 1},
        {.name = "jobs", .kind = GW_OPT_LONG, .dest = &jobs, .lo = 0, .hi = 1024},
        {.name = "solver", .kind = GW_OPT_STRING, .dest = &s},
        {.name = "json", .kind = GW_OPT_FLAG, .dest = &json},
        {0}};
    gw_err err;
    err.msg[0] = '\0';
    int rc = gw_cli_parse("fuzz", opts, argc, argv, &help, pos, 2, &npos, &err);
    if (rc != GW_OK && (rc != GW_EINVAL || !err.msg[0]))
        abort();
    if (rc == GW_OK && (!(v > 0) || !isfinite(v) || n < 1 || !(k > 0)))
        abort(); /* accepted values must satisfy their declared ranges */
    double *list = NULL;
    int nl = 0;
    long a, b;
    if (argc > 0) {
        if (gw_parse_double_list(argv[0], "list", &list, &nl, &err) == GW_OK) {
            for (int i = 0; i < nl; i++)
                if (!isfinite(list[i]))
                    abort();
            free(list);
        }
        if (gw_parse_int_range(argv[0], "range", -10, 1000000, &a, &b, &err) == GW_OK && a > b)
            abort();
    }
    free(buf);
    return 0;
}
