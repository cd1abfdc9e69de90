/*
 * test_b31_global_fit.c: every variant of the B.31 fit (--fit beta,a_over_b
 * with or without offset and tan_gamma) reaches the global minimum of its
 * sum of squares within its box (gw_stats.h: beta in [0, smallest x], a/b in
 * [1e-6, 1e6], tan gamma in [tan 1e-6 deg, tan 89 deg], offset >= 0).
 *
 * The reference is a brute-force grid written here, apart from the library:
 * B.31 in the paper's form (u/(2T)) (sqrt(1 + K x^2/u^2) - 1), evaluated over
 * beta, ln(a/b) and, when free, ln(tan gamma) on a dense grid (below), a free offset
 * set to the mean residual clamped at 0 (exact for a one-variable least
 * squares with a bound). Checked on the measured boundaries of
 * data/measured (the 8000-impact diagram, the full, wide and 210-impact ones,
 * clumps wide) and on 8 noisy synthetic boundaries:
 *  1. the fitted parameters lie in the box;
 *  2. the fit's sum of squares is no larger than the grid's minimum (times
 *     1 + 1e-9): a local minimum above the grid's is a failure;
 *  3. the grid comes within 1 % of the fit (the grid is dense enough to mean
 *     something);
 *  4. the default fit (beta, a/b) on the 8000-impact diagram keeps its
 *     documented values (beta 1.815, a/b 5.428, rms 4.95 R_m);
 *  5. the points given in reverse order give the same sum of squares (1e-9;
 *     the parameters a box edge stops can lie anywhere along a flat valley).
 * Before the global search (a Levenberg-Marquardt run from five starts in
 * beta) the fits with the offset or tan gamma free left the box (beta on the
 * continuation below x, a/b to 4e-10, tan gamma to 3e-13, offsets of -52
 * R_m) and stopped in local minima.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "gw_test.h"
#include "gw_stats.h"

#define AB_LO 1e-6
#define AB_HI 1e6
#define T_LO 1.7453292519943295e-8
#define T_HI 57.289961630759416

/* B.31 as printed, for x >= beta (the limit at x = beta) */
static double b31_here(double x, double off, double beta, double ab, double T)
{
    double u = x - beta, K = ab * T;
    if (u <= 0)
        return off + sqrt(K) * x / (2 * T);
    double e = K * x * x / (u * u);
    return off + u / (2 * T) * (e / (sqrt(1 + e) + 1)); /* sqrt(1 + e) - 1 without cancellation */
}

/* sum of squares with the offset free (clamped mean) or fixed */
static double ssr_here(const double *x, const double *h, int n, double off, int off_free, double beta, double ab,
                       double T)
{
    double g[64];
    double m = 0;
    for (int i = 0; i < n; i++) {
        g[i] = b31_here(x[i], 0, beta, ab, T);
        m += h[i] - g[i];
    }
    if (off_free)
        off = fmax(0, m / n);
    double s = 0;
    for (int i = 0; i < n; i++) {
        double r = off + g[i] - h[i];
        s += r * r;
    }
    return s;
}

/* the brute-force minimum over the box in (beta, ln a/b, ln tan gamma when
 * free): every node of a grid of 41 x (8 per decade) x (8 per decade) (401 x
 * (100 per decade) with tan gamma fixed), then
 * every node of a 17-point-per-axis grid spanning two cells around each of
 * the 5 lowest nodes, then once more around the lowest of those (cells 64
 * times finer than the first grid's) */
typedef struct node {
    double v[3], s;
} node;

static void keep_low(node *best, int nbest, const double *v, double s)
{
    int k = nbest - 1;
    if (!(s < best[k].s))
        return;
    while (k > 0 && best[k - 1].s > s) {
        best[k] = best[k - 1];
        k--;
    }
    best[k].v[0] = v[0], best[k].v[1] = v[1], best[k].v[2] = v[2], best[k].s = s;
}

static double grid_min(const double *x, const double *h, int n, double off, double T0, int mask)
{
    double xlo = x[0];
    for (int i = 1; i < n; i++)
        xlo = fmin(xlo, x[i]);
    const int tfree = (mask & GW_STATS_B31_TANG) != 0, offree = (mask & GW_STATS_B31_OFFSET) != 0;
    double lo[3] = {0, log(AB_LO), tfree ? log(T_LO) : log(T0)}, hi[3] = {xlo, log(AB_HI), tfree ? log(T_HI) : log(T0)};
    int np[3] = {tfree ? 41 : 401, (int)(log10(AB_HI / AB_LO) * (tfree ? 8 : 100)) + 1,
                 tfree ? (int)(log10(T_HI / T_LO) * 8) + 1 : 1};
    double step[3];
    for (int d = 0; d < 3; d++)
        step[d] = np[d] > 1 ? (hi[d] - lo[d]) / (np[d] - 1) : 0;
    enum { NB = 5 };
    node best[NB];
    for (int k = 0; k < NB; k++)
        best[k].s = INFINITY;
    double v[3];
    for (int i = 0; i < np[0]; i++)
        for (int j = 0; j < np[1]; j++)
            for (int l = 0; l < np[2]; l++) {
                v[0] = lo[0] + i * step[0], v[1] = lo[1] + j * step[1], v[2] = lo[2] + l * step[2];
                keep_low(best, NB, v, ssr_here(x, h, n, off, offree, v[0], exp(v[1]), exp(v[2])));
            }
    for (int level = 0; level < 2; level++) {
        node c[NB];
        int nc = level == 0 ? NB : 1;
        for (int k = 0; k < NB; k++)
            c[k] = best[k];
        for (int k = 0; k < nc; k++) {
            if (!(c[k].s < INFINITY))
                continue;
            int m[3];
            double a[3], st[3];
            for (int d = 0; d < 3; d++) {
                m[d] = step[d] > 0 ? 17 : 1;
                a[d] = c[k].v[d] - step[d];
                st[d] = step[d] / 8;
            }
            for (int i = 0; i < m[0]; i++)
                for (int j = 0; j < m[1]; j++)
                    for (int l = 0; l < m[2]; l++) {
                        int idx[3] = {i, j, l};
                        for (int d = 0; d < 3; d++)
                            v[d] = fmin(hi[d], fmax(lo[d], a[d] + idx[d] * st[d]));
                        keep_low(best, NB, v, ssr_here(x, h, n, off, offree, v[0], exp(v[1]), exp(v[2])));
                    }
        }
        for (int d = 0; d < 3; d++)
            step[d] /= 8;
    }
    return best[0].s;
}

static const int masks[] = {GW_STATS_B31_BETA | GW_STATS_B31_AB,
                            GW_STATS_B31_BETA | GW_STATS_B31_AB | GW_STATS_B31_OFFSET,
                            GW_STATS_B31_BETA | GW_STATS_B31_AB | GW_STATS_B31_TANG,
                            GW_STATS_B31_BETA | GW_STATS_B31_AB | GW_STATS_B31_OFFSET | GW_STATS_B31_TANG};
static const char *mask_name[] = {"beta,a_over_b", "+offset", "+tan_gamma", "+offset,tan_gamma"};

static int fails_box, fails_min;

static void check_all(const char *name, const double *x, const double *h, int n, double off)
{
    const double T0 = tan(0.2 * M_PI / 180);
    double xlo = x[0];
    for (int i = 1; i < n; i++)
        xlo = fmin(xlo, x[i]);
    for (int v = 0; v < 4; v++) {
        int mask = masks[v];
        gw_stats_b31 st = {.offset = off, .beta = 1, .a_over_b = 1, .tan_gamma = T0};
        gw_stats_b31_fit f;
        gw_err err = {{0}};
        char what[800];
        int rc = gw_stats_b31_fit_points(x, h, n, &st, mask, &f, &err);
        snprintf(what, sizeof what, "%s %s: fit runs (%s)", name, mask_name[v], rc ? err.msg : "ok");
        gw_test_true(rc == GW_OK, what);
        if (rc != GW_OK)
            continue;
        double s_fit = ssr_here(x, h, n, f.p.offset, 0, f.p.beta, f.p.a_over_b, f.p.tan_gamma);
        int inbox = f.p.beta >= 0 && f.p.beta <= xlo && f.p.a_over_b >= AB_LO * (1 - 1e-12) &&
                    f.p.a_over_b <= AB_HI * (1 + 1e-12) && (!(mask & GW_STATS_B31_OFFSET) || f.p.offset >= 0) &&
                    (!(mask & GW_STATS_B31_TANG) || (f.p.tan_gamma >= T_LO * (1 - 1e-12) &&
                                                      f.p.tan_gamma <= T_HI * (1 + 1e-12)));
        double s_grid = grid_min(x, h, n, off, T0, mask);
        printf("  %-10s %-18s SSR fit %.9g grid %.9g  beta %.6g a/b %.6g tan_gamma %.4g offset %.6g%s\n", name,
               mask_name[v], s_fit, s_grid, f.p.beta, f.p.a_over_b, f.p.tan_gamma, f.p.offset,
               inbox ? "" : "  OUT OF THE BOX");
        snprintf(what, sizeof what, "%s %s: parameters in the box", name, mask_name[v]);
        gw_test_true(inbox, what);
        fails_box += !inbox;
        snprintf(what, sizeof what, "%s %s: SSR %.9g <= the grid's minimum %.9g", name, mask_name[v], s_fit, s_grid);
        int ok = s_fit <= s_grid * (1 + 1e-9) + 1e-12;
        gw_test_true(ok, what);
        fails_min += !ok;
        snprintf(what, sizeof what, "%s %s: the grid comes within 1 %% of the fit", name, mask_name[v]);
        gw_test_true(s_grid <= s_fit * 1.01 + 1e-6, what);
        snprintf(what, sizeof what, "%s %s: the fit's rms is its own sum of squares", name, mask_name[v]);
        gw_test_rel(f.rms * f.rms * n, s_fit, 1e-9, what);
        /* 5: the same points in reverse order */
        double xr[64], hr[64];
        for (int i = 0; i < n; i++)
            xr[i] = x[n - 1 - i], hr[i] = h[n - 1 - i];
        gw_stats_b31_fit g;
        rc = gw_stats_b31_fit_points(xr, hr, n, &st, mask, &g, &err);
        snprintf(what, sizeof what, "%s %s: the same fit in reverse order", name, mask_name[v]);
        gw_test_true(rc == GW_OK && fabs(g.rms - f.rms) <= 1e-9 * f.rms + 1e-12, what);
    }
}

static uint64_t rng = 0x9e3779b97f4a7c15ULL;
static double unif(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

int main(void)
{
    /* measured boundaries (diagram.csv: rb_rm, h_star of the crossings) and
     * offsets (penetration_rm_boundary / 2 of boundary_fit.json) */
    static const double x8[] = {2, 3, 4, 5, 6, 8, 10},
                        h8[] = {20, 18.8, 15.3636364, 14, 12.6363636, 11.375, 9.65};
    static const double xf[] = {1, 1.5, 2, 3, 4, 6, 8}, hf[] = {11, 14, 13.25, 7, 11, 11.8333333, 11.75};
    static const double xw[] = {1.5, 2, 3, 4, 6}, hw[] = {6.5, 10.5, 16.3333333, 16.5, 16.3333333};
    static const double xd[] = {2, 3, 4, 6}, hd[] = {12.3333333, 5.25, 5.25, 13};
    static const double xb[] = {2, 3, 4, 6}, hb[] = {14.5, 14.5, 14.5, 8.25};
    check_all("8000", x8, h8, 7, 0.2724107974631288);
    check_all("full", xf, hf, 7, 0.256217);
    check_all("wide", xw, hw, 5, 0.280851);
    check_all("210", xd, hd, 4, 0.249689);
    check_all("B_wide", xb, hb, 4, 0.21118);

    /* 4: the default fit on the 8000-impact diagram as documented */
    {
        gw_stats_b31 st = {.offset = 0.2724107974631288, .beta = 1, .a_over_b = 1,
                           .tan_gamma = tan(0.2 * M_PI / 180)};
        gw_stats_b31_fit f;
        gw_err err = {{0}};
        gw_test_true(gw_stats_b31_fit_points(x8, h8, 7, &st, masks[0], &f, &err) == GW_OK, "8000 default fit");
        gw_test_abs(f.p.beta, 1.815, 5e-4, "8000 default: beta 1.815 (layer_stats.txt)");
        gw_test_abs(f.p.a_over_b, 5.428, 5e-4, "8000 default: a/b 5.428");
        gw_test_abs(f.rms, 4.95, 5e-3, "8000 default: rms 4.95 R_m");
        gw_test_abs(f.err.beta, 0.11, 5e-3, "8000 default: beta +- 0.11");
        gw_test_true(f.at_bound == 0, "8000 default: inside the box");
    }

    /* synthetic boundaries: B.31 at random parameters of the box's middle,
     * noise of 0.3 to 3 R_m, on grid-like x */
    static const double xs[] = {1.5, 2, 3, 4, 5, 6, 8, 10};
    for (int k = 0; k < 8; k++) {
        double beta = 0.2 + 1.1 * unif(), ab = exp(log(0.5) + unif() * log(40)),
               T = tan((0.05 + 5 * unif()) * M_PI / 180), off = 2 * unif(), sig = 0.3 + 2.7 * unif();
        double h[8];
        for (int i = 0; i < 8; i++) {
            double g = sqrt(-2 * log(1 - unif())) * cos(2 * M_PI * unif());
            h[i] = b31_here(xs[i], off, beta, ab, T) + sig * g;
        }
        char name[32];
        snprintf(name, sizeof name, "syn%d", k);
        check_all(name, xs, h, 8, off);
    }
    printf("  out of the box: %d, above the grid's minimum: %d\n", fails_box, fails_min);
    return gw_test_summary("test_b31_global_fit");
}
