/*
 * fuzz_sweep_journal.c: libFuzzer target for the sweep journal reader (the
 * resume of `granwave sweep`: gw_sweep_journal_scan) and the table written
 * from it (gw_sweep_write_table). The input is the journal's text after its
 * head: the first byte chooses whether the head of the target's config
 * ("# granwave sweep journal HASH, format 3" and the "# build" line of this
 * build) is put before the rest (odd)
 * or not (even: the rest is the whole file). Rows carry a checksum, so the
 * seed corpus holds journals with valid rows (written by this target when
 * GW_FUZZ_SEEDS names a directory). Any input must give a scan or an error
 * with a message; never a crash, a leak or undefined behaviour.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gw_sweep.h"
#include "gw_sweep_impl.h"

static int has_key(const char *name)
{
    return strcmp(name, "n") == 0 || strcmp(name, "vimp") == 0 || strcmp(name, "k") == 0;
}

static const char *const cols[] = {"a", "b"};
static const gw_sweep_model model = {"chain", 2, cols, has_key, NULL, NULL, NULL, NULL, NULL, NULL, NULL};
static const char config[] = "[sweep]\nmodel = chain\n[grid]\nn = 1, 2, 3\nvimp = 0.1, 0.2\n[params]\nk = 5\n";
static gw_sweep_config cfg;
static char dir[64], journal[128];

static void put(const char *head, const uint8_t *data, size_t size)
{
    FILE *f = fopen(journal, "wb");
    if (!f)
        abort();
    if (head)
        fputs(head, f);
    fwrite(data, 1, size, f);
    fclose(f);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    const gw_sweep_model *const models[] = {&model};
    const gw_sweep_model *m = NULL;
    gw_err err;
    if (gw_sweep_config_read_string(config, "fuzz.ini", models, 1, &cfg, &m, &err) != GW_OK) {
        fprintf(stderr, "fuzz_sweep_journal: %s\n", err.msg);
        abort();
    }
    snprintf(dir, sizeof dir, "/tmp/gw-fuzz-journal-%ld", (long)getpid());
    mkdir(dir, 0700);
    snprintf(journal, sizeof journal, "%s/journal.csv", dir);
    const char *seeds = getenv("GW_FUZZ_SEEDS");
    if (seeds) { /* journals with valid rows: all cases, some, a torn last row */
        char row[4096], text[65536], name[4200];
        for (int s = 0; s < 3; s++) {
            size_t w = 0;
            text[w++] = 1;
            for (long k = 0; k < cfg.ncases - (s == 1 ? 2 : 0); k++) {
                double out[2] = {1.5 * (double)k, s == 2 && k == 1 ? NAN : -2.25};
                gw_sweep_format_row(&cfg, k, out, 2, 0, row, sizeof row);
                w += (size_t)snprintf(text + w, sizeof text - w, "%s", row);
            }
            if (s == 2)
                w -= 5; /* a torn last row */
            snprintf(name, sizeof name, "%s/journal%d", seeds, s);
            FILE *f = fopen(name, "wb");
            if (f) {
                fwrite(text, 1, w, f);
                fclose(f);
            }
        }
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    char head[96 + GW_SWEEP_BUILD_MAX];
    snprintf(head, sizeof head, GW_SWEEP_JOURNAL_HEAD "\n# build %s\n", cfg.hash, gw_sweep_build());
    put(data[0] & 1 ? head : NULL, data + 1, size - 1);
    char done[64] = {0};
    long ndone = 0;
    gw_err err = {{0}};
    int rc = gw_sweep_journal_scan(dir, &cfg, done, &ndone, &err);
    if (rc != GW_OK && strlen(err.msg) == 0)
        abort(); /* an error must always come with a message */
    if (rc == GW_OK && ndone == cfg.ncases) {
        if (gw_sweep_write_table(dir, &cfg, &model, &err) != GW_OK && strlen(err.msg) == 0)
            abort();
    }
    char p[160];
    snprintf(p, sizeof p, "%s/results.csv", dir);
    unlink(p);
    unlink(journal);
    return 0;
}
