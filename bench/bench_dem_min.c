/*
 * bench_dem_min.c: the leanest DEM step we can write for the Bourrier layer
 * (docs/physics.md 2.1, eqs. B.1-B.4), as a cost bound for granwave's layer
 * impacts. Measurement only, never run by ctest.
 *
 * Reads a granwave text sample (layer/gw_layer.h, version 1), adds the block
 * of the default impact (R_b = R_m at the box centre, 1e-6 m above the first
 * particle under it, v = (0, -20) m/s, as layer_impact.c), builds the contact
 * list once (every pair with a gap below the skin 0.1 m, O(n^2), plus the
 * three walls for every disc closer than the skin) and runs N steps over that
 * fixed list. Contact c between discs a, b, n the unit normal from a to b,
 * t = (-n_y, n_x), u = R_a + R_b - |x_b - x_a| (wall: R_a - distance):
 *   F_n = K_n u^(3/2), K_n = 2 sqrt(2 R_p) G / (3 (1 - nu))            (B.1, B.3)
 *   K_t = k_t F_n^(1/3) = k_t K_n^(1/3) u^(1/2)   (no cube root needed)  (B.4)
 *   v_t = (v_b - v_a).t - w_a R_a - w_b R_b, dF_t = K_t v_t dt, |F_t| <= tan(phi) F_n
 *   R_p = 2 R_a R_b / (R_a + R_b), R_p = R_a on a wall; disc masses pi r^2 rho,
 *   I = m r^2 / 2; gravity 9.81 m/s^2 along -y. G = 40 GPa, nu = 0.25,
 *   phi = 30 deg, rho = 2650 kg/m^3.
 * Two integrators, structure of arrays, no function calls inside the step
 * loops (K_t from sqrt(u) instead of cbrt(F_n)):
 *   verlet: velocity Verlet (kick, drift, forces with the half-step velocities,
 *           kick), the tangential force incremented by K_t v_t dt and clamped
 *           to the cap, as explicit DEM codes do; dt 1e-5 s.
 *   rk4:    classic RK4 over (x, y, theta, v_x, v_y, omega, F_t), with
 *           dF_t/dt = K_t v_t while sticking and tan(phi) dF_n/dt while sliding
 *           on the cap (granwave's law without its margin and events); dt 1e-6 s.
 * Output: ns per disc-step (discs = sample + block) for each integrator, the
 * median over the repetitions of the per-repetition time (clock_gettime,
 * CLOCK_PROCESS_CPUTIME_ID: CPU time, as the bench script's /usr/bin/time).
 * Every repetition restarts from the same initial state. Units: SI.
 *
 * Usage: bench_dem_min SAMPLE [--steps N (1000)] [--reps R (9)]
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct dem {
    int n, np, nw;      /* discs, pair contacts, wall contacts */
    double width;
    double *x, *y, *th, *vx, *vy, *w, *r, *minv, *iinv; /* [n] */
    double *fx, *fy, *tq;                               /* [n] */
    int *pa, *pb;                                       /* [np] */
    double *pkn, *pkt, *pft;                            /* [np] K_n, k_t K_n^(1/3), F_t */
    int *wa;                                            /* [nw] */
    double *wnx, *wny, *wc, *wkn, *wkt, *wft;           /* [nw] normal out of the box, n.x at the wall */
} dem;

static double *dalloc(size_t n)
{
    double *p = calloc(n ? n : 1, sizeof *p);
    if (!p) {
        fprintf(stderr, "bench_dem_min: out of memory\n");
        exit(2);
    }
    return p;
}

static const double GW_PI = 3.14159265358979323846;
static const double G = 40e9, NU = 0.25, RHO = 2650, GRAV = 9.81, SKIN = 0.1;

static double kn_of(double rp)
{
    return 2.0 * sqrt(2.0 * rp) * G / (3.0 * (1.0 - NU));
}

static double ktf_of(double rp)
{
    return 2.0 * cbrt(3.0 * G * G * (1.0 - NU) * rp) / (2.0 - NU);
}

/* Reads a version 1 text sample into xs, ys, rs (malloc'd); returns n, or -1. */
static int read_sample(const char *path, double *width, double *rm, double **xs, double **ys, double **rs)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char line[1100];
    int n = -1, k = 0;
    *width = *rm = 0;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#' || line[0] == '\n' || line[0] == '\r')
            continue;
        if (n < 0) {
            if (strncmp(line, "granwave-layer-sample", 21) == 0 && strtol(line + 21, NULL, 10) != 1)
                break; /* clump samples (version 2) are not supported */
            sscanf(line, "width %lf", width);
            sscanf(line, "rm %lf", rm);
            if (sscanf(line, "n %d", &n) == 1) {
                if (n < 1 || n > 10000000)
                    break;
                *xs = dalloc((size_t)n);
                *ys = dalloc((size_t)n);
                *rs = dalloc((size_t)n);
            }
            continue;
        }
        if (k < n && sscanf(line, "%lf %lf %lf", &(*xs)[k], &(*ys)[k], &(*rs)[k]) == 3)
            k++;
    }
    fclose(f);
    return (n > 0 && k == n && *width > 0 && *rm > 0) ? n : -1;
}

static void build(dem *d, int ns, const double *xs, const double *ys, const double *rs, double rm)
{
    /* the default impact's block (layer_impact.c) */
    const double rb = rm, xc = 0.5 * d->width;
    double yb = -INFINITY;
    for (int i = 0; i < ns; i++) {
        double dx = xs[i] - xc, reach = rb + rs[i];
        if (fabs(dx) < reach && ys[i] + sqrt(reach * reach - dx * dx) > yb)
            yb = ys[i] + sqrt(reach * reach - dx * dx);
    }
    const int n = d->n = ns + 1;
    double *all = dalloc(12 * (size_t)n);
    d->x = all, d->y = all + n, d->th = all + 2 * n, d->vx = all + 3 * n, d->vy = all + 4 * n;
    d->w = all + 5 * n, d->r = all + 6 * n, d->minv = all + 7 * n, d->iinv = all + 8 * n;
    d->fx = all + 9 * n, d->fy = all + 10 * n, d->tq = all + 11 * n;
    for (int i = 0; i < n; i++) {
        d->x[i] = i < ns ? xs[i] : xc;
        d->y[i] = i < ns ? ys[i] : yb + 1e-6;
        d->r[i] = i < ns ? rs[i] : rb;
        double m = GW_PI * d->r[i] * d->r[i] * RHO;
        d->minv[i] = 1 / m;
        d->iinv[i] = 2 / (m * d->r[i] * d->r[i]);
    }
    d->vy[ns] = -20;
    int cap = 8 * n;
    d->pa = malloc((size_t)cap * sizeof *d->pa);
    d->pb = malloc((size_t)cap * sizeof *d->pb);
    d->np = 0;
    for (int a = 0; a < n; a++)
        for (int b = a + 1; b < n; b++) {
            double dx = d->x[b] - d->x[a], dy = d->y[b] - d->y[a];
            if (hypot(dx, dy) - d->r[a] - d->r[b] >= SKIN)
                continue;
            if (d->np == cap) {
                cap *= 2;
                d->pa = realloc(d->pa, (size_t)cap * sizeof *d->pa);
                d->pb = realloc(d->pb, (size_t)cap * sizeof *d->pb);
            }
            if (!d->pa || !d->pb)
                exit(2);
            d->pa[d->np] = a, d->pb[d->np] = b, d->np++;
        }
    d->pkn = dalloc((size_t)d->np), d->pkt = dalloc((size_t)d->np), d->pft = dalloc((size_t)d->np);
    for (int c = 0; c < d->np; c++) {
        double ra = d->r[d->pa[c]], rbb = d->r[d->pb[c]], rp = 2 * ra * rbb / (ra + rbb);
        d->pkn[c] = kn_of(rp);
        d->pkt[c] = ktf_of(rp) * cbrt(d->pkn[c]);
    }
    d->wa = malloc(3 * (size_t)n * sizeof *d->wa);
    double *wall = dalloc(6 * 3 * (size_t)n);
    d->wnx = wall, d->wny = wall + 3 * n, d->wc = wall + 6 * n;
    d->wkn = wall + 9 * n, d->wkt = wall + 12 * n, d->wft = wall + 15 * n;
    d->nw = 0;
    const double nx[3] = {-1, 1, 0}, ny[3] = {0, 0, -1}, cc[3] = {0, d->width, 0};
    for (int i = 0; d->wa && i < n; i++)
        for (int q = 0; q < 3; q++) {
            double dist = cc[q] - (nx[q] * d->x[i] + ny[q] * d->y[i]);
            if (dist - d->r[i] >= SKIN)
                continue;
            int k = d->nw++;
            d->wa[k] = i, d->wnx[k] = nx[q], d->wny[k] = ny[q], d->wc[k] = cc[q];
            d->wkn[k] = kn_of(d->r[i]);
            d->wkt[k] = ktf_of(d->r[i]) * cbrt(d->wkn[k]);
        }
}

static double now_cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* N velocity-Verlet steps of size h over the fixed list. */
static void run_verlet(dem *d, long steps, double h)
{
    const int n = d->n, np = d->np, nw = d->nw;
    const double mu = tan(30 * GW_PI / 180), hh = 0.5 * h;
    double *restrict x = d->x, *restrict y = d->y, *restrict th = d->th;
    double *restrict vx = d->vx, *restrict vy = d->vy, *restrict w = d->w;
    double *restrict fx = d->fx, *restrict fy = d->fy, *restrict tq = d->tq;
    const double *restrict r = d->r, *restrict minv = d->minv, *restrict iinv = d->iinv;
    const int *restrict pa = d->pa, *restrict pb = d->pb, *restrict wa = d->wa;
    const double *restrict pkn = d->pkn, *restrict pkt = d->pkt;
    const double *restrict wnx = d->wnx, *restrict wny = d->wny, *restrict wc = d->wc;
    const double *restrict wkn = d->wkn, *restrict wkt = d->wkt;
    double *restrict pft = d->pft, *restrict wft = d->wft;
    for (long s = 0; s < steps; s++) {
        for (int i = 0; i < n; i++) { /* kick (forces of the previous step), drift */
            vx[i] += hh * fx[i] * minv[i];
            vy[i] += hh * (fy[i] * minv[i] - GRAV);
            w[i] += hh * tq[i] * iinv[i];
            x[i] += h * vx[i];
            y[i] += h * vy[i];
            th[i] += h * w[i];
            fx[i] = fy[i] = tq[i] = 0;
        }
        for (int c = 0; c < np; c++) {
            const int a = pa[c], b = pb[c];
            double dx = x[b] - x[a], dy = y[b] - y[a], dd = sqrt(dx * dx + dy * dy);
            double u = r[a] + r[b] - dd;
            if (!(u > 0)) {
                pft[c] = 0;
                continue;
            }
            double nx = dx / dd, ny = dy / dd, su = sqrt(u), fn = pkn[c] * u * su;
            double vt = -(vx[b] - vx[a]) * ny + (vy[b] - vy[a]) * nx - w[a] * r[a] - w[b] * r[b];
            double ft = pft[c] + pkt[c] * su * vt * h, cap = mu * fn;
            ft = ft > cap ? cap : ft < -cap ? -cap : ft;
            pft[c] = ft;
            double gx = -fn * nx - ft * ny, gy = -fn * ny + ft * nx;
            fx[a] += gx, fy[a] += gy, tq[a] += ft * r[a];
            fx[b] -= gx, fy[b] -= gy, tq[b] += ft * r[b];
        }
        for (int c = 0; c < nw; c++) {
            const int a = wa[c];
            double nx = wnx[c], ny = wny[c], u = r[a] - (wc[c] - (nx * x[a] + ny * y[a]));
            if (!(u > 0)) {
                wft[c] = 0;
                continue;
            }
            double su = sqrt(u), fn = wkn[c] * u * su;
            double vt = vx[a] * ny - vy[a] * nx - w[a] * r[a];
            double ft = wft[c] + wkt[c] * su * vt * h, cap = mu * fn;
            ft = ft > cap ? cap : ft < -cap ? -cap : ft;
            wft[c] = ft;
            fx[a] += -fn * nx - ft * ny, fy[a] += -fn * ny + ft * nx, tq[a] += ft * r[a];
        }
        for (int i = 0; i < n; i++) { /* kick */
            vx[i] += hh * fx[i] * minv[i];
            vy[i] += hh * (fy[i] * minv[i] - GRAV);
            w[i] += hh * tq[i] * iinv[i];
        }
    }
}

/* RK4 state: 6 per disc (x, y, th, vx, vy, w, each an array of n) + F_t per
 * contact (pairs, then walls). rates into k; s = state read. */
typedef struct rk {
    double *s0, *s, *k, *acc; /* [dim] each */
    int dim;
} rk;

/* N classic RK4 steps over the fixed list; everything of the right-hand side
 * is written out four times via one inner block executed per stage. */
static void run_rk4(dem *d, rk *R, long steps, double h)
{
    const int n = d->n, np = d->np, nw = d->nw, dim = R->dim;
    const double mu = tan(30 * GW_PI / 180);
    const double *restrict r = d->r, *restrict minv = d->minv, *restrict iinv = d->iinv;
    const int *restrict pa = d->pa, *restrict pb = d->pb, *restrict wa = d->wa;
    const double *restrict pkn = d->pkn, *restrict pkt = d->pkt;
    const double *restrict wnx = d->wnx, *restrict wny = d->wny, *restrict wc = d->wc;
    const double *restrict wkn = d->wkn, *restrict wkt = d->wkt;
    double *restrict y0 = R->s0, *restrict ys = R->s, *restrict k = R->k, *restrict acc = R->acc;
    static const double cs[4] = {0.5, 0.5, 1.0, 0.0}, wt[4] = {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6};
    for (long st = 0; st < steps; st++) {
        for (int q = 0; q < dim; q++)
            ys[q] = y0[q], acc[q] = 0;
        for (int stage = 0; stage < 4; stage++) {
            const double *X = ys, *Y = ys + n, *VX = ys + 3 * n, *VY = ys + 4 * n, *W = ys + 5 * n;
            const double *FT = ys + 6 * n;
            double *KX = k, *KY = k + n, *KT = k + 2 * n, *KVX = k + 3 * n, *KVY = k + 4 * n, *KW = k + 5 * n;
            double *KF = k + 6 * n;
            for (int i = 0; i < n; i++) {
                KX[i] = VX[i], KY[i] = VY[i], KT[i] = W[i];
                KVX[i] = KVY[i] = KW[i] = 0;
            }
            for (int c = 0; c < np; c++) {
                const int a = pa[c], b = pb[c];
                double dx = X[b] - X[a], dy = Y[b] - Y[a], dd = sqrt(dx * dx + dy * dy);
                double u = r[a] + r[b] - dd;
                if (!(u > 0)) {
                    KF[c] = 0;
                    continue;
                }
                double nx = dx / dd, ny = dy / dd, su = sqrt(u), fn = pkn[c] * u * su;
                double rvx = VX[b] - VX[a], rvy = VY[b] - VY[a];
                double vt = -rvx * ny + rvy * nx - W[a] * r[a] - W[b] * r[b];
                double und = -(rvx * nx + rvy * ny), re = pkt[c] * su * vt, cap = mu * fn;
                double f = FT[c], sg = f > 0 ? 1 : f < 0 ? -1 : (re >= 0 ? 1 : -1);
                double rc = sg * mu * 1.5 * pkn[c] * su * und;
                KF[c] = (f * sg >= cap && sg * re > sg * rc) ? rc : re;
                double ft = f > cap ? cap : f < -cap ? -cap : f;
                double gx = -fn * nx - ft * ny, gy = -fn * ny + ft * nx;
                KVX[a] += gx, KVY[a] += gy, KW[a] += ft * r[a];
                KVX[b] -= gx, KVY[b] -= gy, KW[b] += ft * r[b];
            }
            for (int c = 0; c < nw; c++) {
                const int a = wa[c];
                double nx = wnx[c], ny = wny[c], u = r[a] - (wc[c] - (nx * X[a] + ny * Y[a]));
                if (!(u > 0)) {
                    KF[np + c] = 0;
                    continue;
                }
                double su = sqrt(u), fn = wkn[c] * u * su;
                double vt = VX[a] * ny - VY[a] * nx - W[a] * r[a], und = VX[a] * nx + VY[a] * ny;
                double re = wkt[c] * su * vt, cap = mu * fn, f = FT[np + c];
                double sg = f > 0 ? 1 : f < 0 ? -1 : (re >= 0 ? 1 : -1);
                double rc = sg * mu * 1.5 * wkn[c] * su * und;
                KF[np + c] = (f * sg >= cap && sg * re > sg * rc) ? rc : re;
                double ft = f > cap ? cap : f < -cap ? -cap : f;
                KVX[a] += -fn * nx - ft * ny, KVY[a] += -fn * ny + ft * nx, KW[a] += ft * r[a];
            }
            for (int i = 0; i < n; i++) {
                KVX[i] *= minv[i];
                KVY[i] = KVY[i] * minv[i] - GRAV;
                KW[i] *= iinv[i];
            }
            const double c1 = cs[stage] * h, c2 = wt[stage] * h;
            for (int q = 0; q < dim; q++) {
                acc[q] += c2 * k[q];
                ys[q] = y0[q] + c1 * k[q];
            }
        }
        for (int q = 0; q < dim; q++)
            y0[q] += acc[q];
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: bench_dem_min SAMPLE [--steps N] [--reps R]\n");
        return 2;
    }
    long steps = 1000;
    int reps = 9;
    for (int i = 2; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--steps") == 0)
            steps = strtol(argv[i + 1], NULL, 10);
        else if (strcmp(argv[i], "--reps") == 0)
            reps = (int)strtol(argv[i + 1], NULL, 10);
    }
    if (steps < 1 || reps < 1 || reps > 1000) {
        fprintf(stderr, "bench_dem_min: --steps and --reps must be positive (reps <= 1000)\n");
        return 2;
    }
    double width, rm, *xs = NULL, *ys = NULL, *rs = NULL;
    int ns = read_sample(argv[1], &width, &rm, &xs, &ys, &rs);
    if (ns < 0) {
        fprintf(stderr, "bench_dem_min: %s: not a readable version 1 granwave text sample\n", argv[1]);
        return 2;
    }
    dem d = {.width = width};
    build(&d, ns, xs, ys, rs, rm);
    const int n = d.n;
    int closed = 0;
    for (int c = 0; c < d.np; c++)
        closed += hypot(d.x[d.pb[c]] - d.x[d.pa[c]], d.y[d.pb[c]] - d.y[d.pa[c]]) < d.r[d.pa[c]] + d.r[d.pb[c]];
    printf("bench_dem_min: %s: %d discs (sample %d + block), %d pair contacts listed (%d closed), "
           "%d wall contacts listed, skin %g m\n", argv[1], n, ns, d.np, closed, d.nw, SKIN);
    /* initial state, restored before every repetition */
    const size_t dn = (size_t)n;
    double *init = dalloc(12 * dn);
    memcpy(init, d.x, 12 * dn * sizeof *init);
    double *med = dalloc((size_t)reps), res[2], check[2];
    const char *name[2] = {"verlet", "rk4"};
    const double hstep[2] = {1e-5, 1e-6};
    rk R = {.dim = 6 * n + d.np + d.nw};
    R.s0 = dalloc((size_t)R.dim), R.s = dalloc((size_t)R.dim), R.k = dalloc((size_t)R.dim);
    R.acc = dalloc((size_t)R.dim);
    for (int m = 0; m < 2; m++) {
        for (int q = 0; q < reps; q++) {
            memcpy(d.x, init, 12 * dn * sizeof *init);
            memset(d.pft, 0, (size_t)d.np * sizeof *d.pft);
            memset(d.wft, 0, (size_t)d.nw * sizeof *d.wft);
            /* RK4 state: x, y, th, vx, vy, w (as in dem), then F_t */
            memcpy(R.s0, init, 6 * dn * sizeof *init);
            memset(R.s0 + 6 * n, 0, (size_t)(d.np + d.nw) * sizeof *R.s0);
            double t0 = now_cpu();
            if (m == 0)
                run_verlet(&d, steps, hstep[m]);
            else
                run_rk4(&d, &R, steps, hstep[m]);
            med[q] = now_cpu() - t0;
        }
        qsort(med, (size_t)reps, sizeof *med, cmp_double);
        res[m] = 1e9 * med[reps / 2] / ((double)n * (double)steps);
        const double *yy = m == 0 ? d.y : R.s0 + n;
        check[m] = 0;
        for (int i = 0; i < n; i++)
            check[m] += yy[i];
        printf("  %-6s dt %g s: %ld steps x %d reps, CPU per rep min %.4g / median %.4g / max %.4g s\n",
               name[m], hstep[m], steps, reps, med[0], med[reps / 2], med[reps - 1]);
    }
    printf("  (check: sum of y after the last rep %.9g m verlet, %.9g m rk4)\n", check[0], check[1]);
    /* cross-check of the two step codes: verlet at rk4's dt over the same steps */
    memcpy(d.x, init, 12 * dn * sizeof *init);
    memset(d.pft, 0, (size_t)d.np * sizeof *d.pft);
    memset(d.wft, 0, (size_t)d.nw * sizeof *d.wft);
    run_verlet(&d, steps, hstep[1]);
    double dmax = 0, vmax = 0;
    for (int i = 0; i < n; i++) {
        dmax = fmax(dmax, hypot(d.x[i] - R.s0[i], d.y[i] - R.s0[n + i]));
        vmax = fmax(vmax, hypot(d.vx[i] - R.s0[3 * n + i], d.vy[i] - R.s0[4 * n + i]));
    }
    printf("  verlet at dt %g s against rk4 after %ld steps: largest position difference %.3g m, "
           "velocity %.3g m/s (block v_y %.6g / %.6g m/s)\n", hstep[1], steps, dmax, vmax, d.vy[n - 1],
           R.s0[5 * n - 1]);
    for (int m = 0; m < 2; m++)
        printf("BOUND %s %.4g ns/disc-step\n", name[m], res[m]);
    free(init), free(med), free(R.s0), free(R.s), free(R.k), free(R.acc);
    free(d.x), free(d.pa), free(d.pb), free(d.pkn), free(d.pkt), free(d.pft), free(d.wa), free(d.wnx);
    free(xs), free(ys), free(rs);
    return 0;
}
