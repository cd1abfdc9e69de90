/*
 * fuzz_sweep_config.c: libFuzzer target for the sweep config parser (libinih +
 * gw_sweep_config.c) and the grid expansion and row formatting that follow it. Any
 * input must give either a config or an error message; never a crash, a leak or
 * undefined behaviour (built with ASan + UBSan).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gw_sweep.h"

static int has_key(const char *name)
{
    static const char *const keys[] = {"n", "vimp", "k", "kwall", "solver", "damping", "rtol", "mass"};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        if (strcmp(keys[i], name) == 0)
            return 1;
    return 0;
}

static const char *const cols[] = {"a", "b"};
static const gw_sweep_model model = {"chain", 2, cols, has_key, NULL, NULL, NULL, NULL, NULL, NULL, NULL};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    const gw_sweep_model *const models[] = {&model};
    gw_sweep_config cfg;
    const gw_sweep_model *m = NULL;
    gw_err err;
    if (gw_sweep_config_read_string(text, "fuzz.ini", models, 1, &cfg, &m, &err) == GW_OK) {
        const char *names[2 * GW_SWEEP_MAX_KEYS], *values[2 * GW_SWEEP_MAX_KEYS];
        char row[8192];
        double out[2] = {1.5, -2.25};
        for (long k = 0; k < cfg.ncases && k < 64; k++) {
            gw_sweep_case(&cfg, k, names, values);
            gw_sweep_format_row(&cfg, k, out, 2, 0, row, sizeof row);
        }
        gw_sweep_config_free(&cfg);
    } else if (strlen(err.msg) == 0) {
        abort(); /* an error must always come with a message */
    }
    free(text);
    return 0;
}
