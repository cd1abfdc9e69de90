/*
 * chain_rhs_lean.c: the default column's undamped right-hand side (no damping,
 * no wall law, sensor body or guide: chain_model.c's lean path), whole and by
 * ranges. Apart from the model because it is the hot loop, written three ways
 * for the vector units (SSE2 pairs, AVX quads chosen at run time, portable
 * blocks) that must give the same values bit for bit (test_solver_adams_bitwise).
 */
#include <math.h>
#include <string.h>

#include "chain_model.h"

/* ---- undamped right-hand side, written for packed square roots ----
 * Per bead j (docs/physics.md 1.1, F.11), with f_j the force below bead j:
 *   f_0 = K max(x_0, 0)^(3/2) (wall),  f_j = k_(j-1) max(x_j - x_(j-1), 0)^(3/2),
 *   f_n = 0,  dx_j/dt = v_j,  dv_j/dt = g + (f_(j+1) - f_j) / m_j.
 * The clamp max(u, 0) is branch-free, and sqrt(0) = 0 gives the open contact's
 * zero force. Every value is computed with the same operations in the same order
 * as a contact-by-contact loop (k u sqrt(u), then g + (f_above - f_below) / m), so
 * the results do not depend on the path taken. No scratch memory is kept on the
 * chain: it stays read-only and one chain may serve several threads.
 * With SSE2 (every x86-64) one loop handles two beads per iteration: the forces
 * of the next pair are computed with one packed square root while the current
 * pair's accelerations are written, so the other work hides under the square
 * root's throughput. Elsewhere two compiler-vectorised passes per block of beads
 * do the same (forces into a contiguous stack array, then the outputs);
 * -DGW_CHAIN_PORTABLE_RHS selects them on x86 too. */

/* Beads j0 .. j0 + nb - 1 (nb <= LEAN_BLOCK) in two compiler-vectorised
 * passes: the forces f_j0 .. f_(j0+nb) into a stack array, then the outputs.
 * Reads y from x_(j0-1) to x_(j0+nb). The portable right-hand side, and the
 * right-hand side by ranges (chain_rhs_range) where the CPU has no AVX and on
 * the few beads at a range's end the 4-wide loop leaves. */
enum { LEAN_BLOCK = 512 };

static void lean_block(const gw_chain *c, const double *restrict y, double *restrict yd,
                       int j0, int nb, double g, int kinematics)
{
    const int n = c->n;
    double f[LEAN_BLOCK + 1];
    int k0 = 0, k1 = nb; /* f[k] = f_(j0+k) */
    if (j0 == 0) {
        double u = y[0] > 0 ? y[0] : 0.0;
        f[0] = c->kwall * u * sqrt(u);
        k0 = 1;
    }
    if (j0 + nb == n) {
        f[nb] = 0.0;
        k1 = nb - 1;
    }
    const double *restrict x = y + 2 * (size_t)j0;
    const double *restrict kb = c->kc + j0 + k0 - 1; /* kb[k - k0]: contact j0 + k - 1 */
    for (int k = k0; k <= k1; k++) {
        double u = x[2 * k] - x[2 * k - 2];
        u = u > 0 ? u : 0.0;
        f[k] = kb[k - k0] * u * sqrt(u);
    }
    const double *restrict mb = c->minv + j0;
    double *restrict out = yd + 2 * (size_t)j0;
    for (int k = 0; k < nb; k++) {
        out[2 * k] = kinematics ? x[2 * k + 1] : 0.0;
        out[2 * k + 1] = g + (f[k + 1] - f[k]) * mb[k];
    }
}

#if defined(__SSE2__) && !defined(GW_CHAIN_PORTABLE_RHS)
#include <emmintrin.h>

/* f_j for 1 <= j < n, scalar. */
static inline double lean_force(const gw_chain *c, const double *y, int j)
{
    double u = y[2 * j] - y[2 * j - 2];
    u = u > 0 ? u : 0.0;
    return c->kc[j - 1] * u * sqrt(u);
}

/* Beads j0..n-1 one at a time; fb = f_j0, fa1 = f_(j0+1) (or NAN to compute). */
static void lean_tail(const gw_chain *c, const double *y, double *yd, int j0, double fb,
                      double fa1, double g, int kinematics)
{
    const int n = c->n;
    for (int j = j0; j < n; j++) {
        double fa = j + 1 >= n ? 0.0 : (j == j0 && !isnan(fa1)) ? fa1 : lean_force(c, y, j + 1);
        yd[2 * j] = kinematics ? y[2 * j + 1] : 0.0;
        yd[2 * j + 1] = g + (fa - fb) * c->minv[j];
        fb = fa;
    }
}

/* The paired loop; uni (a constant at each call) broadcasts kc[0] and minv[0]
 * instead of streaming the per-contact arrays: a column of equal beads then
 * moves a third less memory per evaluation, with the same values. */
static inline __attribute__((always_inline)) void
lean_rhs_pairs(const gw_chain *c, const double *restrict y, double *restrict yd, double g,
               int kinematics, int uni)
{
    const int n = c->n;
    double u0 = y[0] > 0 ? y[0] : 0.0, f0 = c->kwall * u0 * sqrt(u0);
    const double *restrict kc = c->kc, *restrict m1 = c->minv;
    const __m128d zero = _mm_setzero_pd(), vg = _mm_set1_pd(g);
    const __m128d k1 = _mm_set1_pd(kc[0]), mi1 = _mm_set1_pd(m1[0]);
    const __m128d vmask = kinematics ? _mm_castsi128_pd(_mm_set1_epi32(-1)) : zero;
    __m128d x = _mm_unpacklo_pd(_mm_loadu_pd(y), _mm_loadu_pd(y + 2)); /* x_0, x_1 */
    __m128d fb = _mm_set_pd(lean_force(c, y, 1), f0);                  /* f_0, f_1 */
    int p = 0;
    for (; 2 * p + 3 < n; p++) { /* beads 2p, 2p+1; forces of beads 2p+2, 2p+3 */
        const double *yp = y + 4 * p;
        __m128d xn = _mm_unpacklo_pd(_mm_loadu_pd(yp + 4), _mm_loadu_pd(yp + 6));
        __m128d u = _mm_max_pd(_mm_sub_pd(xn, _mm_shuffle_pd(x, xn, 1)), zero);
        __m128d kv = uni ? k1 : _mm_loadu_pd(kc + 2 * p + 1);
        __m128d fn = _mm_mul_pd(_mm_mul_pd(kv, u), _mm_sqrt_pd(u));
        __m128d fa = _mm_shuffle_pd(fb, fn, 1); /* f_(2p+1), f_(2p+2) */
        __m128d mv = uni ? mi1 : _mm_loadu_pd(m1 + 2 * p);
        __m128d a = _mm_add_pd(vg, _mm_mul_pd(_mm_sub_pd(fa, fb), mv));
        __m128d v = _mm_and_pd(_mm_unpackhi_pd(_mm_loadu_pd(yp), _mm_loadu_pd(yp + 2)), vmask);
        _mm_storeu_pd(yd + 4 * p, _mm_unpacklo_pd(v, a));
        _mm_storeu_pd(yd + 4 * p + 2, _mm_unpackhi_pd(v, a));
        x = xn;
        fb = fn;
    }
    lean_tail(c, y, yd, 2 * p, _mm_cvtsd_f64(fb), _mm_cvtsd_f64(_mm_unpackhi_pd(fb, fb)), g,
              kinematics);
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(GW_CHAIN_PORTABLE_RHS)
#include <immintrin.h>
#define GW_CHAIN_AVX_RHS 1

/* The same loop four beads wide (AVX, no FMA: the same IEEE operations in the
 * same order, so the same values as the SSE2 loop and the scalar one). Each
 * 256-bit register is built from two 128-bit loads of [x, v] pairs (the insert
 * of the upper half is no shuffle), so that x and v come out in bead order
 * with one unpack each; the forces of beads j..j+3 and of j+1..j+4 differ by
 * one lane (a lane swap and one shuffle). Per four beads: one packed square
 * root (4 wide), 7 shuffles where the SSE2 loop makes about 13. */
static inline __attribute__((always_inline, target("avx"))) __m256d
lean_pairs2(const double *a, const double *b) /* [a0 a1 b0 b1] */
{
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(a)), _mm_loadu_pd(b), 1);
}

/* Beads j..j+3 from yq = y + 2j: the forces of beads j+4..j+7 (from the x of
 * beads j+3..j+7 and kq[3..6] = their contacts' k), the accelerations of beads
 * j..j+3 (mq[0..3] = their 1/m) into o[0..7]; *fb holds f_j..f_(j+3) and *v
 * v_j..v_(j+3) on entry, those of j+4..j+7 on return. */
static inline __attribute__((always_inline, target("avx"))) void
lean_quad(const double *yq, const double *kq, const double *mq, double *o, __m256d *fb, __m256d *v,
          __m256d vg, __m256d vmask, __m256d k1, __m256d mi1, int uni)
{
    const __m256d zero = _mm256_setzero_pd();
    __m256d cn = lean_pairs2(yq + 8, yq + 12);  /* x, v of j+4 and j+6 */
    __m256d dn = lean_pairs2(yq + 10, yq + 14); /* x, v of j+5 and j+7 */
    __m256d cp = lean_pairs2(yq + 6, yq + 10);  /* x, v of j+3 and j+5 */
    __m256d xn = _mm256_unpacklo_pd(cn, dn);    /* x_(j+4) .. x_(j+7) */
    __m256d xp = _mm256_unpacklo_pd(cp, cn);    /* x_(j+3) .. x_(j+6) */
    __m256d u = _mm256_max_pd(_mm256_sub_pd(xn, xp), zero);
    __m256d kv = uni ? k1 : _mm256_loadu_pd(kq + 3);
    __m256d fn = _mm256_mul_pd(_mm256_mul_pd(kv, u), _mm256_sqrt_pd(u)); /* f_(j+4) .. */
    __m256d t = _mm256_permute2f128_pd(*fb, fn, 0x21); /* f_(j+2), f_(j+3), f_(j+4), f_(j+5) */
    __m256d fa = _mm256_shuffle_pd(*fb, t, 0x5);       /* f_(j+1) .. f_(j+4) */
    __m256d mv = uni ? mi1 : _mm256_loadu_pd(mq);
    __m256d a = _mm256_add_pd(vg, _mm256_mul_pd(_mm256_sub_pd(fa, *fb), mv));
    __m256d vk = _mm256_and_pd(*v, vmask);
    __m256d lo = _mm256_unpacklo_pd(vk, a); /* v_j a_j, v_(j+2) a_(j+2) */
    __m256d hi = _mm256_unpackhi_pd(vk, a); /* v_(j+1) a_(j+1), v_(j+3) a_(j+3) */
    _mm_storeu_pd(o, _mm256_castpd256_pd128(lo));
    _mm_storeu_pd(o + 2, _mm256_castpd256_pd128(hi));
    _mm_storeu_pd(o + 4, _mm256_extractf128_pd(lo, 1));
    _mm_storeu_pd(o + 6, _mm256_extractf128_pd(hi, 1));
    *v = _mm256_unpackhi_pd(cn, dn);
    *fb = fn;
}

/* n >= 8. The last 4 to 7 beads run through the same code on a copy padded
 * with beads at x = -inf (an open contact: max(-inf, 0) = 0, so f_n = 0 as in
 * the law) and k = 1/m = 0, whose outputs are dropped. */
static inline __attribute__((always_inline, target("avx"))) void
lean_rhs_quads(const gw_chain *c, const double *restrict y, double *restrict yd, double g,
               int kinematics, int uni)
{
    const int n = c->n;
    const double *restrict kc = c->kc, *restrict m1 = c->minv;
    const __m256d vg = _mm256_set1_pd(g);
    const __m256d k1 = _mm256_set1_pd(kc[0]), mi1 = _mm256_set1_pd(m1[0]);
    const __m256d vmask = kinematics ? _mm256_castsi256_pd(_mm256_set1_epi32(-1)) : _mm256_setzero_pd();
    /* f_0 .. f_3, the wall's as a contact with a bead at x = 0 (x_0 - 0 = x_0) */
    const __m256d c0 = lean_pairs2(y, y + 4), d0 = lean_pairs2(y + 2, y + 6);
    const __m256d x0 = _mm256_unpacklo_pd(c0, d0); /* x_0 .. x_3 */
    const __m256d xw = _mm256_shuffle_pd(_mm256_permute2f128_pd(_mm256_setzero_pd(), x0, 0x21), x0, 0x5);
    const __m256d u0 = _mm256_max_pd(_mm256_sub_pd(x0, xw), _mm256_setzero_pd()); /* 0, x_0, x_1, x_2 */
    const __m256d kw = _mm256_set_pd(kc[2], kc[1], kc[0], c->kwall);
    __m256d fb = _mm256_mul_pd(_mm256_mul_pd(kw, u0), _mm256_sqrt_pd(u0));
    __m256d v = _mm256_unpackhi_pd(c0, d0); /* v_0 .. v_3 */
    int j = 0;
    for (; j + 7 < n; j += 4) /* beads j..j+3 */
        lean_quad(y + 2 * j, kc + j, m1 + j, yd + 2 * j, &fb, &v, vg, vmask, k1, mi1, uni);
    /* beads j..n-1 (4 to 7) on a padded copy of beads j..j+11 */
    double yb[24], kb[12], mb[8], ob[16];
    const int r = n - j;
    const __m128d pad = _mm_set_pd(0.0, -INFINITY); /* x, v of a bead past the end */
    for (int i = 0; i < 12; i++) /* pairs: no call to memcpy (4 % of the falcon job) */
        _mm_storeu_pd(yb + 2 * i, i < r ? _mm_loadu_pd(y + 2 * (j + i)) : pad);
    if (!uni) {
        memset(kb, 0, sizeof kb);
        memcpy(kb, kc + j, (size_t)(r - 1) * sizeof *kb);
        memset(mb, 0, sizeof mb);
        memcpy(mb, m1 + j, (size_t)r * sizeof *mb);
    }
    lean_quad(yb, kb, mb, ob, &fb, &v, vg, vmask, k1, mi1, uni);
    if (r > 4)
        lean_quad(yb + 8, kb + 4, mb + 4, ob + 8, &fb, &v, vg, vmask, k1, mi1, uni);
    for (int i = 0; i < r; i++)
        _mm_storeu_pd(yd + 2 * (j + i), _mm_loadu_pd(ob + 2 * i));
    /* clean upper halves before the SSE code that follows (the solver): SSE
     * code run with dirty upper halves ran about 3x slower on a Cascade Lake
     * (the SSE2 loop 8.4 against 3.0 ns per bead) */
    _mm256_zeroupper();
}

/* Beads j0 .. j1 - 1 of a range (j1 - j0 >= 4) four at a time, from the x of
 * bead j0 - 1 (the wall at j0 = 0) to that of bead j1 + 3 at most (a quad
 * for beads j .. j + 3 reads x up to bead j + 7, before the end of the
 * chain); returns the first bead not done (at most 3 left, or the chain's last
 * 4 to 7), which lean_block finishes. */
static inline __attribute__((always_inline, target("avx"))) int
lean_range_quads(const gw_chain *c, const double *restrict y, double *restrict yd, int j0, int j1,
                 double g, int uni)
{
    const double *restrict kc = c->kc, *restrict m1 = c->minv;
    const __m256d vg = _mm256_set1_pd(g), zero = _mm256_setzero_pd();
    const __m256d k1 = _mm256_set1_pd(kc[0]), mi1 = _mm256_set1_pd(m1[0]);
    const __m256d vmask = _mm256_castsi256_pd(_mm256_set1_epi32(-1));
    const double *yq = y + 2 * (size_t)j0;
    const __m256d c0 = lean_pairs2(yq, yq + 4), d0 = lean_pairs2(yq + 2, yq + 6);
    const __m256d x0 = _mm256_unpacklo_pd(c0, d0); /* x_j0 .. x_(j0+3) */
    __m256d xp, kv;                                 /* x_(j0-1) .. x_(j0+2), their contacts' k */
    if (j0 == 0) { /* the wall's as a contact with a bead at x = 0, as lean_rhs_quads */
        xp = _mm256_shuffle_pd(_mm256_permute2f128_pd(zero, x0, 0x21), x0, 0x5);
        kv = _mm256_set_pd(kc[2], kc[1], kc[0], c->kwall);
    } else {
        xp = _mm256_unpacklo_pd(lean_pairs2(yq - 2, yq + 2), c0);
        kv = uni ? k1 : _mm256_loadu_pd(kc + j0 - 1);
    }
    const __m256d u0 = _mm256_max_pd(_mm256_sub_pd(x0, xp), zero);
    __m256d fb = _mm256_mul_pd(_mm256_mul_pd(kv, u0), _mm256_sqrt_pd(u0)); /* f_j0 .. */
    __m256d v = _mm256_unpackhi_pd(c0, d0);                                 /* v_j0 .. */
    int j = j0;
    for (; j + 4 <= j1 && j + 7 < c->n; j += 4)
        lean_quad(y + 2 * (size_t)j, kc + j, m1 + j, yd + 2 * (size_t)j, &fb, &v, vg, vmask, k1, mi1,
                  uni);
    _mm256_zeroupper(); /* before lean_block's SSE code (see lean_rhs_quads) */
    return j;
}

static __attribute__((noinline, target("avx"))) int
lean_range_avx(const gw_chain *c, const double *restrict y, double *restrict yd, int j0, int j1,
               double g)
{
    return c->uniform ? lean_range_quads(c, y, yd, j0, j1, g, 1)
                      : lean_range_quads(c, y, yd, j0, j1, g, 0);
}

static __attribute__((noinline, target("avx"))) void
lean_rhs_avx(const gw_chain *c, const double *restrict y, double *restrict yd, double g, int kinematics)
{
    if (c->uniform)
        lean_rhs_quads(c, y, yd, g, kinematics, 1);
    else
        lean_rhs_quads(c, y, yd, g, kinematics, 0);
}
#endif

void chain_lean_rhs(const gw_chain *c, const double *restrict y, double *restrict yd, double g,
                    int kinematics)
{
#ifdef GW_CHAIN_AVX_RHS
    if (c->rhs_avx && c->n >= 8) {
        lean_rhs_avx(c, y, yd, g, kinematics);
        return;
    }
#endif
    if (c->n < 4) {
        double u0 = y[0] > 0 ? y[0] : 0.0;
        lean_tail(c, y, yd, 0, c->kwall * u0 * sqrt(u0), NAN, g, kinematics);
    } else if (c->uniform) {
        lean_rhs_pairs(c, y, yd, g, kinematics, 1);
    } else {
        lean_rhs_pairs(c, y, yd, g, kinematics, 0);
    }
}
#else
void chain_lean_rhs(const gw_chain *c, const double *y, double *yd, double g, int kinematics)
{
    for (int j0 = 0; j0 < c->n; j0 += LEAN_BLOCK) {
        int nb = c->n - j0 < LEAN_BLOCK ? c->n - j0 : LEAN_BLOCK;
        lean_block(c, y, yd, j0, nb, g, kinematics);
    }
}
#endif

/* Beads j0 .. j1 - 1 of the undamped rhs (chain_rhs_range's beads), the same
 * values as chain_lean_rhs; reads y from bead j0 - 1 to bead j1 + 3. */
void chain_lean_range(const gw_chain *c, const double *restrict y, double *restrict yd, int j0, int j1,
                      double g)
{
#ifdef GW_CHAIN_AVX_RHS
    /* the 4-wide loop (the same values): on a range of the vector passes
     * (256 beads) the two-pass blocks cost about twice as much */
    if (c->rhs_avx && j1 - j0 >= 4 && c->n >= 8)
        j0 = lean_range_avx(c, y, yd, j0, j1, g);
#endif
    for (; j0 < j1; j0 += LEAN_BLOCK) {
        int nb = j1 - j0 < LEAN_BLOCK ? j1 - j0 : LEAN_BLOCK;
        lean_block(c, y, yd, j0, nb, g, 1);
    }
}

/* Whether this CPU runs the 4-wide AVX loop (gw_chain_create sets rhs_avx). */
int chain_lean_avx(void)
{
#ifdef GW_CHAIN_AVX_RHS
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx") != 0;
#else
    return 0;
#endif
}
