/*
 * test_bounded_hash_lib.c: the content hashes' bounds, through the library
 * (test_bounded_hash.sh runs the program's):
 *  - gw_fnv1a64_file on a sparse 200 GB file: GW_EINVAL naming its size and
 *    the 4 GiB bound, before a byte is read (it was hashed whole: minutes);
 *  - gw_fnv1a64_file on /proc/self/pagemap (a regular file of 0 bytes that
 *    gives 256 GiB): GW_EINVAL at once, naming the 0 bytes its size said (it
 *    was read on and on);
 *  - gw_fnv1a64_file_max: a 3000-byte file refused at max 2999 naming its
 *    size, hashed at max 3000 as gw_fnv1a64 of its bytes; text: a NUL byte
 *    on line 3 refused naming the line, the same bytes hashed when not text;
 *  - gw_sweep_config_read on a layer config whose sample is an HDF5
 *    signature and then 4 GiB of sparse zeros: GW_EINVAL naming the hole (the
 *    file was hashed whole, about 20 s, and the config taken);
 *  - gw_sweep_case_inputs_check after the text sample, read fine when the
 *    sweep started, got NUL bytes between its text and a last line: refused
 *    as unreadable naming the NUL's line, in the pass that hashes it (it
 *    was hashed whole and said "changed").
 * A hang is a failed check: each part runs in a child process killed by
 * SIGALRM after 60 s (not a timing: each call returns at once).
 */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gw_common.h"
#include "gw_layer.h"
#include "gw_sweep.h"
#include "gw_test.h"
#include "gw_test_calls.h"

static int write_bytes(const char *path, const void *p, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    const int ok = fwrite(p, 1, n, f) == n;
    return fclose(f) == 0 && ok;
}

static int write_text(const char *path, const char *text)
{
    return write_bytes(path, text, strlen(text));
}

static void part_big(const char *dir)
{
    char big[256];
    snprintf(big, sizeof big, "%s/big.bin", dir);
    FILE *f = fopen(big, "w");
    gw_test_true(f && fclose(f) == 0 && truncate(big, 200LL << 30) == 0, "a sparse 200 GB file");
    unsigned long long h = 7;
    gw_err e = {{0}};
    const int rc = gw_fnv1a64_file(big, "input", &h, &e);
    GW_TEST_OK(rc == GW_EINVAL && h == 7 && strstr(e.msg, big) && strstr(e.msg, "214748364800 bytes") &&
                   strstr(e.msg, "4294967296 bytes"),
               "gw_fnv1a64_file: a sparse 200 GB file refused naming it, its size and the bound (%d: %s)", rc, e.msg);
}

static void part_proc(const char *dir)
{
    (void)dir;
    unsigned long long h = 7;
    gw_err e = {{0}};
    const int rc = gw_fnv1a64_file("/proc/self/pagemap", "input", &h, &e);
    GW_TEST_OK(rc == GW_EINVAL && h == 7 && strstr(e.msg, "/proc/self/pagemap") && strstr(e.msg, "more bytes than the 0"),
               "gw_fnv1a64_file: /proc/self/pagemap refused, more bytes than its size said (%d: %s)", rc, e.msg);
}

static void part_max(const char *dir)
{
    char p[256];
    snprintf(p, sizeof p, "%s/small.bin", dir);
    unsigned char b[3000];
    for (size_t i = 0; i < sizeof b; i++)
        b[i] = (unsigned char)(i * 7 + 1);
    gw_test_true(write_bytes(p, b, sizeof b), "a 3000-byte file");
    unsigned long long h = 7;
    gw_err e = {{0}};
    int rc = gw_fnv1a64_file_max(p, "input", 2999, 0, &h, &e);
    GW_TEST_OK(rc == GW_EINVAL && h == 7 && strstr(e.msg, "3000 bytes") && strstr(e.msg, "2999 bytes"),
               "gw_fnv1a64_file_max: 3000 bytes at max 2999 refused naming both (%d: %s)", rc, e.msg);
    rc = gw_fnv1a64_file_max(p, "input", 3000, 0, &h, &e);
    GW_TEST_OK(rc == GW_OK && h == gw_fnv1a64(GW_FNV1A64_INIT, b, sizeof b),
               "gw_fnv1a64_file_max: at max 3000 the hash of its bytes (%d)", rc);
    static const char text[] = "a\nb\nc\0\0d\n";
    snprintf(p, sizeof p, "%s/nul.txt", dir);
    gw_test_true(write_bytes(p, text, sizeof text - 1), "a text with NUL bytes on its line 3");
    h = 7;
    rc = gw_fnv1a64_file_max(p, "sample", 1000, 1, &h, &e);
    GW_TEST_OK(rc == GW_EFORMAT && h == 7 && strstr(e.msg, p) && strstr(e.msg, "line 3: NUL byte"),
               "gw_fnv1a64_file_max (text): refused naming line 3 (%d: %s)", rc, e.msg);
    rc = gw_fnv1a64_file(p, "input", &h, &e);
    GW_TEST_OK(rc == GW_OK && h == gw_fnv1a64(GW_FNV1A64_INIT, text, sizeof text - 1),
               "gw_fnv1a64_file (not text): the same bytes hashed (%d)", rc);
}

static void layer_config_text(char *text, size_t n, const char *sample)
{
    snprintf(text, n, "[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = %s\nt-max = 0.002\n", sample);
}

static void part_h5_hole(const char *dir)
{
    char s[256], ini[256], text[1024];
    snprintf(s, sizeof s, "%s/hole.h5", dir);
    snprintf(ini, sizeof ini, "%s/hole.ini", dir);
    static const unsigned char sig[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
    gw_test_true(write_bytes(s, sig, sizeof sig) && truncate(s, 4LL << 30) == 0,
                 "an HDF5 signature and sparse zeros to 4 GiB");
    layer_config_text(text, sizeof text, s);
    gw_test_true(write_text(ini, text), "its config written");
    const gw_sweep_model *layer[] = {&gw_layer_sweep_model}, *m = NULL;
    gw_sweep_config cfg;
    gw_err e = {{0}};
    const int rc = gw_sweep_config_read(ini, layer, 1, &cfg, &m, &e);
    GW_TEST_OK(rc == GW_EINVAL && strstr(e.msg, s) && strstr(e.msg, "4294967296 bytes") &&
                   strstr(e.msg, "of them holes"),
               "gw_sweep_config_read: the sample's hole named before it is hashed (%d: %s)", rc,
               rc == GW_OK ? "taken" : e.msg);
    if (rc == GW_OK)
        gw_sweep_config_free(&cfg);
}

static void part_inputs_nul(const char *dir)
{
    char s[256], ini[256], text[1024];
    snprintf(s, sizeof s, "%s/s.txt", dir);
    snprintf(ini, sizeof ini, "%s/s.ini", dir);
    /* a text file past the rules' look: 70 KiB of comment lines, then the
     * sample's line, so that NUL bytes put between them are neither in its
     * first 64 KiB nor in its last 4 KiB */
    FILE *f = fopen(s, "w");
    for (int i = 0; f && i < 1000; i++)
        fprintf(f, "# %070d\n", i);
    gw_test_true(f && fclose(f) == 0, "a 73 kB text file as the sample");
    layer_config_text(text, sizeof text, s);
    gw_test_true(write_text(ini, text), "its config written");
    const gw_sweep_model *layer[] = {&gw_layer_sweep_model}, *m = NULL;
    gw_sweep_config cfg;
    gw_err e = {{0}};
    int rc = gw_sweep_config_read(ini, layer, 1, &cfg, &m, &e);
    GW_TEST_OK(rc == GW_OK && cfg.ninputs == 1, "the config is read, its sample an input (%d: %s)", rc,
               rc == GW_OK ? "" : e.msg);
    if (rc != GW_OK)
        return;
    f = fopen(s, "a");
    for (int i = 0; f && i < 8000; i++)
        fputc(0, f);
    for (int i = 0; f && i < 100; i++)
        fprintf(f, "# %070d\n", i);
    gw_test_true(f && fclose(f) == 0, "8000 NUL bytes and 7 kB of text appended");
    rc = gw_sweep_case_inputs_check(&cfg, -1, &e);
    GW_TEST_OK(rc == GW_EINVAL && strstr(e.msg, "cannot be read any more") && strstr(e.msg, "line 1001: NUL byte"),
               "gw_sweep_case_inputs_check: the NUL bytes refused naming line 1001 (%d: %s)", rc, e.msg);
    gw_sweep_config_free(&cfg);
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0); /* a part killed by SIGALRM keeps the lines it printed */
    char dir[] = "/tmp/gw_bounded_hash_XXXXXX";
    if (!mkdtemp(dir)) {
        printf("FAIL: mkdtemp\n");
        return 1;
    }
    gw_test_part("the 200 GB file", part_big, dir);
    if (access("/proc/self/pagemap", R_OK) == 0)
        gw_test_part("/proc/self/pagemap", part_proc, dir);
    else
        printf("SKIP: /proc/self/pagemap not readable\n");
    gw_test_part("the bound and the text", part_max, dir);
    gw_test_part("the HDF5 sample's hole", part_h5_hole, dir);
    gw_test_part("the NUL bytes put in the sample", part_inputs_nul, dir);
    static const char *const files[] = {"big.bin", "small.bin", "nul.txt", "hole.h5", "hole.ini", "s.txt", "s.ini",
                                        NULL};
    char p[300];
    for (int i = 0; files[i]; i++) {
        snprintf(p, sizeof p, "%s/%s", dir, files[i]);
        unlink(p);
    }
    rmdir(dir);
    return gw_test_summary("test_bounded_hash_lib");
}
