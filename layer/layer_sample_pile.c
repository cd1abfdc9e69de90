/*
 * layer_sample_pile.c: the identity of the pile a sample holds
 * (gw_layer_sample_pile_hash), by which the sweep's check pass refuses a grid
 * listing one pile under two names (layer_sweep_model.c, pile_note).
 *
 * A run reads from a sample its box (n, width, rm), its mass law and clump
 * mass, its settling record (gw_layer_settled) and its particles, these as a
 * set: listed in another order, or with the clumps numbered otherwise, they
 * run the same impact but for the order in which the contact forces are
 * summed. Measured on the 300-disc pile (layer-make --n 300 --seed 1) and a
 * shuffled listing of it, the default impact: e_n, e, the penetration, t_f and
 * the 6108 steps alike to the bit; 102 of the 196 numbers of its JSON differ,
 * by at most 2.9e-9 relative (a ring's strain of 2.5 J), energy_error
 * 3.337568881406913e-05 against 3.337568881390644e-05; on a pile of 60 clumps
 * (layer-make --n 60 --clumps --seed 4) listed shuffled and renumbered, the
 * steps, the penetration and energy_error alike, e_n and t_f within 4e-14
 * relative, a ring's strain of 42 J within 1e-3 J. So the pile is hashed
 * as a multiset of bodies, each a multiset of discs (x, y, r; m):
 *   e_i = mix(FNV-1a 64 of x_i, y_i, r_i)                 (a disc, -0 as 0)
 *   B_b = mix(sum over the discs i of body b of e_i)       (a body)
 *   H   = FNV-1a 64 of (n, width, rm, mass_law, clump_mass, the settling
 *         record, sum over the bodies b of B_b[, S])
 *   S   = sum over the springs (a, b, u) of mix(FNV-1a 64 of
 *         (mix(e_a + e_b), u)), e_b of a wall the mix of its id's hash
 * (S only for a sample with springs, so that a pile without them keeps its
 * hash; a spring changes the impact as a particle does, and follows its two
 * discs, whatever their indices or order)
 * sums modulo 2^64, which do not depend on the order of their terms. mix
 * (below) is a bijection whose output bits each depend on all its input bits,
 * so that B_b is not linear in the e_i: the same discs grouped into other
 * clumps give other B_b (clumps {a, b}, {c} against {a}, {b, c}), and the
 * identity is that of the bodies, not only of the discs. A sample without a
 * body column is a pile of bodies of one disc each, as one whose column
 * gives each disc its own id.
 * Cost: O(n), one pass over the particles and, with a body column, one over
 * the bodies (9 bytes a particle, freed before returning).
 */
#include <stdlib.h>

#include "layer_impl.h"

/* One double into an FNV-1a 64 hash, -0 as 0 (the same value written "-0"). */
static unsigned long long hash_double(unsigned long long h, double v)
{
    v = v == 0 ? 0.0 : v;
    return gw_fnv1a64(h, &v, sizeof v);
}

static unsigned long long hash_long(unsigned long long h, long v)
{
    return gw_fnv1a64(h, &v, sizeof v);
}

/* Xor-shifts and multiplications by an odd constant (2^64 over the golden
 * ratio), each invertible: a bijection of 64-bit words. FNV-1a alone would not
 * do under a sum: its low output bits depend on its input's low bits alone. */
static unsigned long long mix(unsigned long long h)
{
    h ^= h >> 32;
    h *= 0x9e3779b97f4a7c15ULL;
    h ^= h >> 29;
    h *= 0x9e3779b97f4a7c15ULL;
    h ^= h >> 32;
    return h;
}

static unsigned long long disc_hash(const gw_layer_sample *s, int i)
{
    unsigned long long h = hash_double(GW_FNV1A64_INIT, s->x[i]);
    h = hash_double(h, s->y[i]);
    return mix(hash_double(h, s->r[i]));
}

/* The sum of the bodies' B_b into *sum; GW_ENOMEM when the bodies of a clump
 * sample cannot be gathered. Body ids in [0, n) (layer_sample_form_check). */
static int bodies_sum(const gw_layer_sample *s, unsigned long long *sum)
{
    *sum = 0;
    if (!s->body) {
        for (int i = 0; i < s->n; i++)
            *sum += mix(disc_hash(s, i));
        return GW_OK;
    }
    unsigned long long *acc = calloc((size_t)s->n, sizeof *acc);
    unsigned char *has = calloc((size_t)s->n, 1);
    if (!acc || !has) {
        free(acc);
        free(has);
        return GW_ENOMEM;
    }
    for (int i = 0; i < s->n; i++)
        acc[s->body[i]] += disc_hash(s, i), has[s->body[i]] = 1;
    for (int b = 0; b < s->n; b++)
        if (has[b])
            *sum += mix(acc[b]);
    free(acc);
    free(has);
    return GW_OK;
}

/* The sum over the springs of mix(FNV-1a 64 of (mix(e_a + e_b), u)), e_b of a
 * wall its id's hash: a spring is known by the discs it joins, not by their
 * indices, and the two in either order are one contact (gw_layer_spring). */
static unsigned long long springs_sum(const gw_layer_sample *s)
{
    unsigned long long sum = 0;
    for (int k = 0; k < s->n_springs; k++) {
        const gw_layer_spring *q = &s->springs[k]; /* pairs in range (layer_sample_shape_check) */
        const unsigned long long eb = q->b >= 0 ? disc_hash(s, q->b) : mix(hash_long(GW_FNV1A64_INIT, q->b));
        sum += mix(hash_double(mix(disc_hash(s, q->a) + eb), q->u));
    }
    return sum;
}

int layer_sample_pile_hash(const gw_layer_sample *s, unsigned long long *out)
{
    *out = 0;
    if (!s)
        return GW_OK;
    /* a sample no run takes is no pile: its x, y or r NULL was read (SIGSEGV),
     * a body id outside [0, n) hashed as a body of its own and springs counted
     * without their array as none, each the hash of another sample. Since
     * session 44 every limit of the shared check (layer_sample_limits_check,
     * which each call that takes a sample applies), not the form alone: a
     * disc outside the box, an rm of 1e-7 m or two discs at one place had a
     * hash, which a caller could key results on, of a sample refused by
     * every run, by the writer and by the reader */
    const int rc = layer_sample_limits_check(s, "s", GW_EINVAL, NULL);
    if (rc != GW_OK)
        return rc == GW_ENOMEM ? GW_ENOMEM : GW_EINVAL;
    unsigned long long sum = 0;
    if (bodies_sum(s, &sum) != GW_OK)
        return GW_ENOMEM;
    unsigned long long h = GW_FNV1A64_INIT;
    h = hash_long(h, s->n);
    h = hash_double(h, s->width);
    h = hash_double(h, s->rm);
    h = hash_long(h, s->mass_law);
    h = hash_long(h, s->clump_mass);
    const gw_layer_settled *st = &s->settled;
    h = hash_long(h, st->recorded);
    if (st->recorded) { /* not its line: where the record sits in the file does not reach a run */
        h = hash_double(h, st->shear_modulus);
        h = hash_double(h, st->poisson);
        h = hash_double(h, st->friction_deg);
        h = hash_double(h, st->density);
        h = hash_double(h, st->gravity);
        h = hash_long(h, st->mass_law);
        h = hash_long(h, st->clump_mass);
    }
    h = gw_fnv1a64(h, &sum, sizeof sum);
    if (s->n_springs > 0) { /* none: the hash of a sample before springs */
        const unsigned long long ss = springs_sum(s);
        h = gw_fnv1a64(h, &ss, sizeof ss);
    }
    *out = h;
    return GW_OK;
}

unsigned long long gw_layer_sample_pile_hash(const gw_layer_sample *s)
{
    unsigned long long h = 0;
    return layer_sample_pile_hash(s, &h) == GW_OK ? h : 0;
}
