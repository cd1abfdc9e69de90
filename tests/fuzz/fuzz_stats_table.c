/*
 * fuzz_stats_table.c: libFuzzer target for the sweep table reader of
 * `granwave layer-stats` and the whole analysis after it: the input is
 * written to a temporary file and read by gw_stats_analyse (table reader,
 * groups, binary table, walls, diagrams and the B.31 fit), then put into
 * JSON (gw_stats_json) and the library's tables (gw_stats_run). Any input
 * must give either an analysis or an error with a message; never a crash, a
 * leak, an abort or undefined behaviour (built with ASan + UBSan).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_stats.h"

static char path[64];

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!path[0]) /* removed after each input */
        snprintf(path, sizeof path, "/tmp/gw-fuzz-table-%ld.csv", (long)getpid());
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    fwrite(data, 1, size, f);
    fclose(f);
    gw_stats_setup s;
    if (gw_stats_setup_init(&s) != GW_OK)
        abort();
    free(s.input);
    s.input = strdup(path);
    s.defaults = (gw_stats_defaults){1, 0, 20, 2650};
    gw_stats_outcome out;
    gw_err err = {{0}};
    if (gw_stats_run(&s, &out, &err) == GW_OK) {
        cJSON *j = gw_stats_json(&out.a, 1);
        char *txt = j ? cJSON_PrintUnformatted(j) : NULL;
        free(txt);
        cJSON_Delete(j);
    } else if (strlen(err.msg) == 0) {
        abort(); /* an error must always come with a message */
    }
    gw_stats_outcome_free(&out);
    gw_stats_setup_clear(&s);
    unlink(path);
    return 0;
}
