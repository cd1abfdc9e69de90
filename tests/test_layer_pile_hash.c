/*
 * test_layer_pile_hash.c: the identity of a sample's pile
 * (gw_layer_sample_pile_hash, layer_sample_pile.c) on samples made in memory.
 * A run reads the particles as a set of bodies, each a set of discs, and the
 * box, the mass laws and the settling record; so must the hash:
 *  1 the same discs listed in another order, and clumps listed in another
 *    order and numbered otherwise, hash alike (they hashed apart before);
 *  2 the same discs grouped into other clumps, one x moved by one ulp, one
 *    body moved from one clump to another, the settling record's density, the
 *    box width: each hashes apart;
 *  3 what a run does not read hashes alike: seed, porosity, volume_ratio; -0
 *    as 0; a body column giving each disc its own id as none;
 *  4 NULL gives 0, and so does a sample the sample check refuses (two discs
 *    at one place, a disc 0.1 r into the floor; since session 44: hashed
 *    before, the form alone checked).
 * The samples are piles a run takes (a row of discs on the floor, each
 * touching the next): until session 44 they were discs at random places,
 * deep inside each other, which the hash took.
 * Units: m (the values are arbitrary: only their bits matter).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_layer.h"
#include "gw_test.h"

#define N 64

/* A sample of N discs of random radii on the floor, a row in which each disc
 * overlaps the one before it by a random fraction of 0.002 of their radii'
 * sum (at most 0.006 R_p: a settled pile's, within the sample limits' 0.05
 * R_p, which the hash holds a sample to since session 44), so that any
 * grouping of consecutive discs is a connected clump; clumps of 1 to 3 discs
 * when clumps (ids 0, 1, ...), the settling record set. */
static gw_layer_sample make(uint64_t seed, int clumps)
{
    gw_layer_sample s;
    memset(&s, 0, sizeof s);
    s.n = N, s.width = 2.0, s.rm = 0.01, s.volume_ratio = 2, s.porosity = 0.2, s.seed = 7;
    s.x = malloc(3 * N * sizeof *s.x);
    s.y = s.x + N, s.r = s.x + 2 * N;
    for (int i = 0; i < N; i++) {
        s.r[i] = 0.005 + (double)(gw_test_xorshift(&seed) % 1000) * 1e-5;
        s.y[i] = s.r[i];
        const double f = (double)(gw_test_xorshift(&seed) % 1000) * 2e-6; /* in [0, 0.002) */
        const double d = (s.r[i - (i > 0)] + s.r[i]) * (1 - f), dy = s.y[i] - s.y[i - (i > 0)];
        s.x[i] = i == 0 ? s.r[0] + f : s.x[i - 1] + sqrt(d * d - dy * dy); /* centres d apart */
    }
    if (clumps) {
        s.body = malloc(N * sizeof *s.body);
        for (int i = 0, b = 0; i < N; b++)
            for (int k = 0, m = 1 + (int)(gw_test_xorshift(&seed) % 3); k < m && i < N; k++)
                s.body[i++] = b;
    }
    s.settled = (gw_layer_settled){.recorded = 1, .shear_modulus = 4e10, .poisson = 0.25, .friction_deg = 30,
                                   .density = 2650, .gravity = 9.81, .mass_law = 0, .clump_mass = -1};
    return s;
}

static gw_layer_sample copy(const gw_layer_sample *a)
{
    gw_layer_sample s = *a;
    s.x = malloc(3 * N * sizeof *s.x);
    s.y = s.x + N, s.r = s.x + 2 * N;
    memcpy(s.x, a->x, 3 * N * sizeof *s.x);
    if (a->body) {
        s.body = malloc(N * sizeof *s.body);
        memcpy(s.body, a->body, N * sizeof *s.body);
    }
    return s;
}

static void drop(gw_layer_sample *s)
{
    free(s->x);
    free(s->body);
}

/* a's particles in a shuffled order into s (and its body ids renumbered by a
 * shuffled map when renumber) */
static gw_layer_sample shuffled(const gw_layer_sample *a, uint64_t seed, int renumber)
{
    gw_layer_sample s = copy(a);
    int perm[N], map[N];
    for (int i = 0; i < N; i++)
        perm[i] = map[i] = i;
    for (int i = N - 1; i > 0; i--) {
        int j = (int)(gw_test_xorshift(&seed) % (uint64_t)(i + 1)), t = perm[i];
        perm[i] = perm[j], perm[j] = t;
        j = (int)(gw_test_xorshift(&seed) % (uint64_t)(i + 1)), t = map[i];
        map[i] = map[j], map[j] = t;
    }
    for (int i = 0; i < N; i++) {
        s.x[i] = a->x[perm[i]], s.y[i] = a->y[perm[i]], s.r[i] = a->r[perm[i]];
        if (a->body)
            s.body[i] = renumber ? map[a->body[perm[i]]] : a->body[perm[i]];
    }
    return s;
}

int main(void)
{
    gw_layer_sample d = make(11, 0), c = make(12, 1);
    const unsigned long long hd = gw_layer_sample_pile_hash(&d), hc = gw_layer_sample_pile_hash(&c);
    gw_test_true(hd != 0 && hc != 0 && hd != hc, "two samples: two hashes, not 0");

    /* 1 */
    for (uint64_t k = 1; k <= 3; k++) {
        gw_layer_sample p = shuffled(&d, 100 + k, 0), q = shuffled(&c, 200 + k, 0), r = shuffled(&c, 300 + k, 1);
        GW_TEST_OK(gw_layer_sample_pile_hash(&p) == hd, "discs in shuffled order %d: the same pile", (int)k);
        GW_TEST_OK(gw_layer_sample_pile_hash(&q) == hc, "clumps in shuffled order %d: the same pile", (int)k);
        GW_TEST_OK(gw_layer_sample_pile_hash(&r) == hc, "clumps shuffled and renumbered %d: the same pile", (int)k);
        drop(&p), drop(&q), drop(&r);
    }

    /* 2 */
    gw_layer_sample g = copy(&c);
    for (int i = 0; i < N; i++) /* every clump split in pairs of ids: other groupings of the same discs */
        g.body[i] = i / 2;
    GW_TEST_OK(gw_layer_sample_pile_hash(&g) != hc, "the same discs in other clumps: another pile");
    gw_layer_sample g2 = shuffled(&g, 400, 1);
    GW_TEST_OK(gw_layer_sample_pile_hash(&g2) == gw_layer_sample_pile_hash(&g),
               "that grouping shuffled and renumbered: its own pile again");
    drop(&g2);
    memcpy(g.body, c.body, N * sizeof *g.body);
    int moved = 0; /* the last disc of the first clump of 2 or more moved into the clump after it */
    for (int i = 1; i + 1 < N && !moved; i++)
        if (g.body[i] == g.body[i - 1] && g.body[i + 1] != g.body[i])
            g.body[i] = g.body[i + 1], moved = 1;
    GW_TEST_OK(moved && gw_layer_sample_pile_hash(&g) != hc, "one disc moved into the next clump: another pile");
    drop(&g);
    gw_layer_sample e = copy(&d);
    e.x[N / 2] = nextafter(e.x[N / 2], 1.0);
    GW_TEST_OK(gw_layer_sample_pile_hash(&e) != hd, "one x moved by one ulp: another pile");
    memcpy(e.x, d.x, 3 * N * sizeof *e.x);
    e.settled.density = 2000;
    GW_TEST_OK(gw_layer_sample_pile_hash(&e) != hd, "settled at another density: another pile");
    e.settled = d.settled, e.width = 2.1;
    GW_TEST_OK(gw_layer_sample_pile_hash(&e) != hd, "another box width: another pile");

    /* 3 */
    e.width = d.width, e.seed = 8, e.porosity = 0.3, e.volume_ratio = 3;
    GW_TEST_OK(gw_layer_sample_pile_hash(&e) == hd, "seed, porosity, volume_ratio: not the pile");
    /* (no coordinate of a sample can be 0: a disc there lies outside the box;
     * the settling's friction can) */
    e.settled.friction_deg = 0.0;
    const unsigned long long h0 = gw_layer_sample_pile_hash(&e);
    e.settled.friction_deg = -0.0;
    GW_TEST_OK(h0 != 0 && gw_layer_sample_pile_hash(&e) == h0, "the settling's friction -0 as 0");
    drop(&e);
    gw_layer_sample o = copy(&d);
    o.body = malloc(N * sizeof *o.body);
    for (int i = 0; i < N; i++)
        o.body[i] = N - 1 - i;
    GW_TEST_OK(gw_layer_sample_pile_hash(&o) == hd, "a body column with each disc its own id: as none");
    drop(&o);

    /* 4 */
    gw_test_true(gw_layer_sample_pile_hash(NULL) == 0, "NULL: 0");
    /* and a sample no run takes (session 44: the form alone was checked) */
    gw_layer_sample b = copy(&d);
    b.x[N / 2] = b.x[N / 2 - 1]; /* two discs at one place */
    GW_TEST_OK(gw_layer_sample_pile_hash(&b) == 0, "two discs at one place: 0");
    memcpy(b.x, d.x, 3 * N * sizeof *b.x);
    b.y[3] = 0.9 * b.r[3]; /* 0.1 r into the floor */
    GW_TEST_OK(gw_layer_sample_pile_hash(&b) == 0, "a disc 0.1 r into the floor: 0");
    drop(&b);
    drop(&d), drop(&c);
    return gw_test_summary("test_layer_pile_hash");
}
