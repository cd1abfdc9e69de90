/*
 * fuzz_layer_sample.c: libFuzzer target for the layer sample reader
 * (layer/layer_sample.c). The input is written to a temporary file that
 * gw_layer_sample_read opens, so the text parser and, in builds with HDF5, the
 * HDF5 reader (inputs that start with the HDF5 signature) are both exercised.
 * Every input must give either
 *  - a sample that keeps the reader's promises (1 <= n <= 1e7, finite
 *    coordinates, r > 0, inside the box), whose porosity is in [0, 1], and that
 *    the text writer writes and the reader reads back bit for bit, or
 *  - an error with a message naming the file and an empty sample;
 * never a crash, a leak or undefined behaviour (built with ASan + UBSan).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_layer.h"

/* Per-process temporary files (libFuzzer harness state, not library state). */
static char in_path[64], out_path[80];

static void remove_files(void)
{
    remove(in_path);
    remove(out_path);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    const char *dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    snprintf(in_path, sizeof in_path, "%s/gw_fuzz_sample_XXXXXX", dir);
    int fd = mkstemp(in_path);
    if (fd < 0)
        abort();
    close(fd);
    snprintf(out_path, sizeof out_path, "%s.out.txt", in_path);
    atexit(remove_files);
    return 0;
}

static int same(const gw_layer_sample *a, const gw_layer_sample *b)
{
    if (a->n != b->n || memcmp(&a->width, &b->width, sizeof a->width) != 0 ||
        memcmp(&a->rm, &b->rm, sizeof a->rm) != 0 || a->seed != b->seed || a->mass_law != b->mass_law ||
        memcmp(&a->volume_ratio, &b->volume_ratio, sizeof a->volume_ratio) != 0 ||
        memcmp(&a->porosity, &b->porosity, sizeof a->porosity) != 0)
        return 0;
    size_t bytes = (size_t)a->n * sizeof(double);
    return memcmp(a->x, b->x, bytes) == 0 && memcmp(a->y, b->y, bytes) == 0 && memcmp(a->r, b->r, bytes) == 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *fp = fopen(in_path, "wb");
    if (!fp || fwrite(data, 1, size, fp) != size || fclose(fp) != 0)
        abort();
    gw_layer_sample s, b;
    gw_err err = {{0}};
    int rc = gw_layer_sample_read(in_path, &s, &err);
    if (rc != GW_OK) {
        if (!strstr(err.msg, in_path) || s.x || s.n != 0)
            abort(); /* an error names the file and leaves an empty sample */
        return 0;
    }
    if (s.n < 1 || s.n > 10000000 || !(s.width > 0) || !(s.rm > 0))
        abort();
    for (int i = 0; i < s.n; i++)
        if (!(s.r[i] > 0) || !(s.x[i] - s.r[i] >= -2e-2 * s.r[i]) ||
            !(s.x[i] + s.r[i] <= s.width + 2e-2 * s.r[i]) || !(s.y[i] - s.r[i] >= -2e-2 * s.r[i]))
            abort();
    double phi = gw_layer_sample_porosity(&s);
    if (phi == phi && !(phi >= 0 && phi <= 1)) /* NaN only when the grid degenerates */
        abort();
    if (gw_layer_sample_write(&s, out_path, "fuzz", &err) != GW_OK ||
        gw_layer_sample_read(out_path, &b, &err) != GW_OK || !same(&s, &b))
        abort(); /* what the reader accepts, the writer must reproduce exactly */
    gw_layer_sample_free(&b);
    gw_layer_sample_free(&s);
    return 0;
}
