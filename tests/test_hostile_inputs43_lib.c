/*
 * test_hostile_inputs43_lib.c: the forty-third hostile pass's bounds, through
 * the library calls (test_hostile_inputs43.sh runs the program's):
 *  - gw_sweep_config_read and gw_sweep_config_read_string (Python's sweep)
 *    on a layer config whose sample is a sparse 200 GB file: GW_EINVAL naming
 *    the file and the 4 GiB limit (the file was hashed whole first);
 *  - gw_sweep_case_inputs_check after the sample, read fine when the sweep
 *    started, was replaced by a sparse 200 GB file: GW_EINVAL "cannot be read
 *    any more" with the limit (it was hashed whole);
 *  - gw_sweep_journal_resume_check on a journal extended to 10 GB (sparse):
 *    GW_EINVAL naming the journal and its size (it was allocated and read).
 * A hang is a failed check: each part runs in a child process killed by
 * SIGALRM after 60 s, "FAIL: ... did not return" (not a timing: each call
 * returns at once), and the parts after it still run.
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
#include "gw_chain.h"
#include "gw_sweep.h"
#include "gw_test.h"
#include "gw_test_calls.h"

static int write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return 0;
    const int ok = fputs(text, f) >= 0;
    return fclose(f) == 0 && ok;
}

/* the layer sweep's config the parts read: two cases on sample */
static void layer_config_text(char *text, size_t n, const char *sample)
{
    snprintf(text, n, "[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = %s\nt-max = 0.002\n", sample);
}

static void part_config(const char *dir)
{
    char big[256], ini[256], text[1024];
    snprintf(big, sizeof big, "%s/big.sample", dir);
    snprintf(ini, sizeof ini, "%s/big.ini", dir);
    const gw_sweep_model *layer[] = {&gw_layer_sweep_model}, *m = NULL;
    gw_sweep_config cfg;
    gw_err e = {{0}};
    /* 1 the config names a sparse 200 GB sample */
    FILE *f = fopen(big, "w");
    const int made = f && fclose(f) == 0 && truncate(big, 200LL << 30) == 0;
    gw_test_true(made, "a sparse 200 GB file");
    layer_config_text(text, sizeof text, big);
    gw_test_true(write_text(ini, text), "the config written");
    int rc = gw_sweep_config_read(ini, layer, 1, &cfg, &m, &e);
    GW_TEST_OK(rc == GW_EINVAL && strstr(e.msg, big) && strstr(e.msg, "214748364800 bytes") &&
                   strstr(e.msg, "4294967296 bytes"),
               "gw_sweep_config_read: a sparse 200 GB sample refused naming it and the limit (%d: %s)", rc, e.msg);
    if (rc == GW_OK)
        gw_sweep_config_free(&cfg);
}

static void part_config_string(const char *dir)
{
    char big[256], text[1024];
    snprintf(big, sizeof big, "%s/big.sample", dir);
    const gw_sweep_model *layer[] = {&gw_layer_sweep_model}, *m = NULL;
    gw_sweep_config cfg;
    gw_err e = {{0}};
    layer_config_text(text, sizeof text, big);
    const int rc = gw_sweep_config_read_string(text, "sweep", layer, 1, &cfg, &m, &e);
    GW_TEST_OK(rc == GW_EINVAL && strstr(e.msg, big) && strstr(e.msg, "4294967296 bytes"),
               "gw_sweep_config_read_string (Python's sweep): the same (%d: %s)", rc, e.msg);
    if (rc == GW_OK)
        gw_sweep_config_free(&cfg);
}

/* 2 a sample fine when the sweep started, replaced by 200 GB of zeros */
static void part_inputs_check(const char *dir)
{
    char small[256], sini[256], text[1024];
    snprintf(small, sizeof small, "%s/small.sample", dir);
    snprintf(sini, sizeof sini, "%s/small.ini", dir);
    const gw_sweep_model *layer[] = {&gw_layer_sweep_model}, *m = NULL;
    gw_sweep_config cfg;
    gw_err e = {{0}};
    gw_test_true(write_text(small, "granwave-layer-sample 1\n"), "a small text file as the sample");
    layer_config_text(text, sizeof text, small);
    gw_test_true(write_text(sini, text), "its config written");
    int rc = gw_sweep_config_read(sini, layer, 1, &cfg, &m, &e);
    GW_TEST_OK(rc == GW_OK && cfg.ninputs == 1, "the config on the small sample is read, its sample an input (%d: %s)",
               rc, rc == GW_OK ? "" : e.msg);
    if (rc != GW_OK)
        return;
    gw_test_true(truncate(small, 200LL << 30) == 0, "the sample made a sparse 200 GB file");
    rc = gw_sweep_case_inputs_check(&cfg, -1, &e);
    GW_TEST_OK(rc == GW_EINVAL && strstr(e.msg, "cannot be read any more") && strstr(e.msg, "4294967296 bytes"),
               "gw_sweep_case_inputs_check: the sample replaced by 200 GB refused with the limit (%d: %s)", rc, e.msg);
    gw_sweep_config_free(&cfg);
}

/* 3 a journal extended to 10 GB */
static void part_journal(const char *dir)
{
    char jdir[256], jini[256], journal[300];
    snprintf(jdir, sizeof jdir, "%s/j", dir);
    snprintf(jini, sizeof jini, "%s/ch.ini", dir);
    snprintf(journal, sizeof journal, "%s/journal.csv", jdir);
    const gw_sweep_model *chain[] = {&gw_chain_sweep_model}, *m = NULL;
    gw_sweep_config cfg;
    gw_err e = {{0}};
    gw_test_true(write_text(jini, "[sweep]\nmodel = chain\n[grid]\nn = 5, 6\n[params]\nsolver = rk4\n") &&
                     mkdir(jdir, 0755) == 0,
                 "a chain config and its directory");
    int rc = gw_sweep_config_read(jini, chain, 1, &cfg, &m, &e);
    GW_TEST_OK(rc == GW_OK, "the chain config is read (%d: %s)", rc, rc == GW_OK ? "" : e.msg);
    if (rc != GW_OK)
        return;
    char done[2] = {0};
    long ndone = -1;
    int fd = -1, exists = 0;
    rc = gw_sweep_journal_open(jdir, &cfg, done, &ndone, &fd, &e);
    GW_TEST_OK(rc == GW_OK && fd >= 0, "a new journal made (%d: %s)", rc, rc == GW_OK ? "" : e.msg);
    if (fd >= 0)
        close(fd);
    gw_test_true(truncate(journal, 10LL << 30) == 0, "the journal extended to 10 GB (sparse)");
    rc = gw_sweep_journal_resume_check(jdir, &cfg, done, &ndone, &exists, NULL, NULL, &e);
    GW_TEST_OK(rc == GW_EINVAL && strstr(e.msg, journal) && strstr(e.msg, "10737418240 bytes"),
               "gw_sweep_journal_resume_check: a 10 GB journal refused naming it and its size (%d: %s)", rc, e.msg);
    gw_sweep_config_free(&cfg);
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0); /* a part killed by SIGALRM keeps the lines it printed */
    char dir[] = "/tmp/gw_hostile43_XXXXXX";
    if (!mkdtemp(dir)) {
        printf("FAIL: mkdtemp\n");
        return 1;
    }
    gw_test_part("the config naming a 200 GB sample", part_config, dir);
    gw_test_part("the config as text naming it", part_config_string, dir);
    gw_test_part("the sample replaced while the sweep runs", part_inputs_check, dir);
    gw_test_part("the 10 GB journal", part_journal, dir);
    static const char *const files[] = {"big.sample", "big.ini", "small.sample", "small.ini", "ch.ini",
                                        "j/journal.csv", NULL};
    char p[300];
    for (int i = 0; files[i]; i++) {
        snprintf(p, sizeof p, "%s/%s", dir, files[i]);
        unlink(p);
    }
    snprintf(p, sizeof p, "%s/j", dir);
    rmdir(p);
    rmdir(dir);
    return gw_test_summary("test_hostile_inputs43_lib");
}
