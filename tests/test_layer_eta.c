/*
 * test_layer_eta.c: a layer sweep case's part of its run, whose ~L s left a
 * sweep's progress line draws from (1 - P) / P of the time elapsed (issue
 * 18). The part was the case's output samples over those up to t-max, but an
 * impact ends at T_f, when the block's v_y is back to zero after its rebound:
 * T_f = 0.31 s of the 2 s t-max for a 40-disc pile hit at 20 m/s, so until a
 * case ended a sweep's time left was an upper bound, about 6 times the true
 * one. The block leaves the layer early (1.6 ms) and then flies under gravity,
 * its v_y back to zero in v_y / g: the part is now the run's simulated time
 * over that end expected. Measured without a clock: a verlet run has a fixed
 * step, so its work is its simulated time; the share of the run done at the
 * part's j-th call (sample j every, t = j every dt_out) is t / t_end.
 *  1 the default impact (verlet, vi 20 m/s) on a 40-disc pile: where the
 *    true share passes 10, 25 and 50 %, the time left the part implies is
 *    within 15 % of the true one ((1 - S) / S); about 7 times it before;
 *  2 at a tenth of the run the part is above 5 % (1.5 % before);
 *  3 the part is in [0, 1] at every call, and about a thousand calls over t-max;
 *  4 a full run (to t-max 0.4 s, past T_f) is t / t-max at every call (its
 *    end is t-max, not the flight's);
 *  5 the results are those of the run without a part, bit for bit.
 * About 3 s of CPU.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_layer.h"
#include "gw_layer_study.h"
#include "gw_sweep.h"
#include "gw_test.h"
#include "layer_test_util.h"

#define NCALLS_MAX 4096
typedef struct parts {
    int n;
    double x[NCALLS_MAX];
} parts;

static void on_part(void *ctx, double x)
{
    parts *p = ctx;
    if (p->n < NCALLS_MAX)
        p->x[p->n] = x;
    p->n++;
}

/* the index of a column of the layer model's rows */
static int column(const char *name)
{
    const gw_sweep_model *m = &GW_LAYER_SWEEP_MODEL;
    for (int i = 0; i < m->ncolumns; i++)
        if (strcmp(m->columns[i], name) == 0)
            return i;
    return -1;
}

int main(void)
{
    char path[] = "/tmp/gw_test_layer_eta_XXXXXX";
    int fd = mkstemp(path);
    if (fd >= 0)
        close(fd);
    gw_err err = {{0}};
    static const char *const pile[][2] = {{"n", "40"}, {"seed", "1"}};
    int rc = test_make_pile(path, 2, pile, NULL, &err);
    GW_TEST_OK(rc == GW_OK, "a 40-disc pile (%s)", err.msg);
    const int c_tend = column("t_end"), c_tf = column("t_f");
    GW_TEST_OK(c_tend >= 0 && c_tf >= 0, "the layer model's columns t_end and t_f");
    if (rc != GW_OK || c_tend < 0 || c_tf < 0) {
        unlink(path);
        return gw_test_summary("test_layer_eta");
    }
    /* every = total / 1000 samples between calls, total = t-max / dt-out + 1
     * (the defaults: 2 s, 2e-5 s) */
    const double t_max = 2, dt_out = 2e-5;
    const long total = (long)ceil(t_max / dt_out - 1e-9) + 1, every = total / 1000;
    const char *names[] = {"sample", "full"};
    const char *values[] = {path, "0"};
    double out[64], plain[64];
    static parts p, pf;
    rc = gw_layer_sweep_run_part(1, names, values, out, NULL, on_part, &p, &err);
    GW_TEST_OK(rc == GW_OK, "the default impact with a part (%s)", err.msg);
    int rc2 = gw_layer_sweep_run_part(1, names, values, plain, NULL, NULL, NULL, &err);
    GW_TEST_OK(rc == GW_OK && rc2 == GW_OK &&
               memcmp(out, plain, (size_t)GW_LAYER_SWEEP_MODEL.ncolumns * sizeof *out) == 0,
               "its row is that of the run without a part, bit for bit");
    if (rc == GW_OK) {
        const double t_end = out[c_tend];
        printf("# default impact: t_end %.6g s (T_f %.6g s), %d calls of the part\n", t_end, out[c_tf], p.n);
        int inside = p.n > 10 && p.n <= NCALLS_MAX;
        for (int j = 0; inside && j < p.n; j++)
            inside = p.x[j] >= 0 && p.x[j] <= 1;
        GW_TEST_OK(inside, "the part in [0, 1] at each of its %d calls (about t_end / t-max of a thousand)", p.n);
        const double marks[] = {0.10, 0.25, 0.50};
        int mk = 0;
        for (int j = 0; j < p.n && j < NCALLS_MAX && mk < 3; j++) {
            const double tj = (double)j * (double)every * dt_out, share = tj / t_end, x = p.x[j];
            if (share < marks[mk])
                continue;
            const double ratio = x > 0 ? (1 - x) / x / ((1 - share) / share) : INFINITY;
            printf("# at t = %.4g s: run done %.3f, part %.4f: time left %.2f of the true one\n", tj, share, x,
                   ratio);
            GW_TEST_OK(ratio > 1 / 1.15 && ratio < 1.15,
                       "past %.0f %% of the run (t = %.4g s of %.4g): the part %.4f gives a time left %.2f of the "
                       "true one (within 15 %%)", 100 * marks[mk], tj, t_end, x, ratio);
            if (mk == 0)
                GW_TEST_OK(x > 0.05, "at a tenth of the run the part is above 5 %% (%.4f; t / t-max %.4f)", x,
                           tj / t_max);
            mk++;
        }
        GW_TEST_OK(mk == 3, "the run's calls reach half of it (%d marks of 3)", mk);
    }
    /* a full run ends at t-max: its part is its simulated time over t-max */
    const char *fnames[] = {"sample", "full", "t-max"};
    const char *fvalues[] = {path, "1", "0.4"};
    rc = gw_layer_sweep_run_part(3, fnames, fvalues, out, NULL, on_part, &pf, &err);
    GW_TEST_OK(rc == GW_OK, "a full impact to t-max 0.4 s (past T_f) with a part (%s)", err.msg);
    if (rc == GW_OK) {
        const long ftotal = (long)ceil(0.4 / dt_out - 1e-9) + 1, fevery = ftotal / 1000 > 1 ? ftotal / 1000 : 1;
        double worst = 0;
        for (int j = 0; j < pf.n && j < NCALLS_MAX; j++)
            worst = fmax(worst, fabs(pf.x[j] - (double)j * (double)fevery * dt_out / 0.4));
        GW_TEST_OK(pf.n >= 900 && worst < 1e-3, "a full run's part is t / t-max at its %d calls (worst %.3g; its flight would say t / T_f)", pf.n,
                   worst);
    }
    unlink(path);
    return gw_test_summary("test_layer_eta");
}
