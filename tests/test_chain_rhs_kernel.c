/*
 * test_chain_rhs_kernel.c: the undamped column's right-hand side (chain_model.c:
 * the 4-wide AVX loop where the CPU has AVX, the 2-wide SSE2 loop otherwise) is
 * bit-identical to the contact-by-contact law of docs/physics.md 1.1 (F.11),
 * written here in plain scalar C in the same order of operations:
 *   f_0 = K max(x_0, 0)^(3/2) = K u sqrt(u),  f_j = k_(j-1) u sqrt(u), u = max(x_j - x_(j-1), 0),
 *   dx_j/dt = v_j,  dv_j/dt = g + (f_(j+1) - f_j) (1 / m_j),  f_n = 0;
 * and the implicit part (rhs_im) the same forces with g = 0 and dx/dt = 0.
 * Every chain length from 1 to 40 (every tail of both loops and every start),
 * and 1000 to 1003 beads; equal beads (the loops' broadcast constants) and
 * unequal masses and coefficients (the streamed arrays); about half the
 * contacts open, the wall contact open and closed; with and without gravity.
 * Each kernel the machine can run is checked (the AVX one only where the CPU
 * has AVX). A lane or shuffle off by one, a contact's k or a bead's 1/m taken
 * from its neighbour, or an open contact given a force changes some value.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chain_model.h"
#include "gw_chain.h"
#include "gw_test.h"

static uint64_t rng = 0x9e3779b97f4a7c15ULL;

static double uniform01(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1.0p-53;
}

/* The law in scalar C; km[i] = k_i (contact i between beads i and i+1), mi[i] = m_i. */
static void reference(int n, double kwall, const double *km, const double *mi, double g, int kinematics,
                      const double *y, double *yd)
{
    double u = y[0] > 0 ? y[0] : 0.0, fb = kwall * u * sqrt(u);
    for (int j = 0; j < n; j++) {
        double fa = 0.0;
        if (j + 1 < n) {
            double d = y[2 * j + 2] - y[2 * j];
            d = d > 0 ? d : 0.0;
            fa = km[j] * d * sqrt(d);
        }
        yd[2 * j] = kinematics ? y[2 * j + 1] : 0.0;
        yd[2 * j + 1] = g + (fa - fb) * (1.0 / mi[j]);
        fb = fa;
    }
}

/* Returns the number of values that differ (bitwise) over all cases. */
static long check(int n, int uniform, double gravity, int kernel, int *cases)
{
    double *mass = malloc((size_t)n * sizeof *mass), *kc = malloc((size_t)(n + 1) * sizeof *kc);
    double *y = malloc((size_t)2 * n * sizeof *y), *yd = malloc((size_t)2 * n * sizeof *yd);
    double *ref = malloc((size_t)2 * n * sizeof *ref);
    gw_chain_params p = gw_chain_params_default();
    p.n = n;
    p.gravity = gravity;
    for (int i = 0; i < n; i++) {
        mass[i] = uniform ? p.mass : p.mass * (0.5 + uniform01());
        kc[i] = uniform ? p.k : p.k * (0.5 + uniform01());
    }
    if (!uniform) {
        p.masses = mass;
        p.kc = kc;
    }
    gw_chain *c = NULL;
    gw_err err = {{0}};
    long bad = 0;
    if (gw_chain_create(&p, &c, &err) != GW_OK) {
        printf("FAIL: n = %d: %s\n", n, err.msg);
        bad = 1;
        goto out;
    }
    c->rhs_avx = kernel;
    const gw_system *s = gw_chain_system(c);
    for (int trial = 0; trial < 4; trial++) {
        /* positions: each gap closed (overlap up to 1e-6 m) or open, bead 0 on or off the wall */
        double x = (trial & 1 ? 1.0 : -1.0) * 1e-6 * uniform01();
        for (int i = 0; i < n; i++) {
            y[2 * i] = x;
            y[2 * i + 1] = 0.3 * (uniform01() - 0.5);
            x += 1e-6 * (uniform01() - (trial < 2 ? 0.5 : 0.1)); /* trials 2, 3: mostly closed */
        }
        for (int im = 0; im < 2; im++) {
            memset(yd, 0xff, (size_t)2 * n * sizeof *yd);
            if (im)
                s->rhs_im(0.0, y, yd, s->params);
            else
                s->rhs(0.0, y, yd, s->params);
            reference(n, p.kwall, kc, mass, im ? 0.0 : gravity, !im, y, ref);
            for (int i = 0; i < 2 * n; i++)
                bad += memcmp(&yd[i], &ref[i], sizeof ref[i]) != 0;
            ++*cases;
        }
    }
out:
    gw_chain_free(c);
    free(mass);
    free(kc);
    free(y);
    free(yd);
    free(ref);
    return bad;
}

int main(void)
{
    int kernels = 1;
#ifdef __x86_64__
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx"))
        kernels = 2;
#endif
    const char *name[] = {"SSE2 (or portable)", "AVX"};
    for (int kernel = 0; kernel < kernels; kernel++) {
        int sizes[44], ns = 0;
        for (int n = 1; n <= 40; n++)
            sizes[ns++] = n;
        for (int n = 1000; n <= 1003; n++)
            sizes[ns++] = n;
        for (int uniform = 0; uniform < 2; uniform++) {
            for (int gr = 0; gr < 2; gr++) {
                long bad = 0;
                int cases = 0;
                for (int k = 0; k < ns; k++)
                    bad += check(sizes[k], uniform, gr ? 9.81 : 0.0, kernel, &cases);
                char what[200];
                snprintf(what, sizeof what,
                         "%s kernel, %s beads, gravity %s: rhs and rhs_im bit-identical to the scalar law "
                         "(%d evaluations, N = 1..40 and 1000..1003; %ld values differ)",
                         name[kernel], uniform ? "equal" : "unequal", gr ? "9.81" : "0", cases, bad);
                gw_test_true(bad == 0, what);
            }
        }
    }
    return gw_test_summary("test_chain_rhs_kernel");
}
