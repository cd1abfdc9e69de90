/*
 * test_library_hostile41.c: the forty-first hostile pass over the library's C
 * interface (docs/library.md "The contract of every call"), at the samples a
 * caller builds in memory and hands to the impact's checks and run. What the
 * pass found, each checked here:
 *   - gw_layer_impact_check took a sample with a particle of a NaN or
 *     infinite x, y or r, a radius <= 0, a centre outside the walls the run
 *     keeps, a clump whose discs do not touch, or a spring the run refuses
 *     (GW_OK), and gw_layer_impact refused it only later, when it built the
 *     layer (gw_layer_create, "position and velocity must be finite", naming
 *     no field) or checked the springs: a sweep's check passed what its run
 *     then stopped on. The check and the run now share one particle check
 *     (layer_particle_check, also gw_layer_create's) and the sample's own
 *     (layer_sample_shape_check): a table of bad particles gets the same
 *     status and message from both, naming the index and the field. The
 *     sample's rm 0 passed the check too (the run refused its block of
 *     radius 0), and a NaN or negative rm or a NaN or infinite width was
 *     told "x: no soil particle lies under the block";
 *   - gw_layer_impact_rest_check read a sample's NULL y or r (SIGSEGV) and
 *     passed a NaN y (GW_OK); gw_layer_impact_settled_check and
 *     gw_layer_settled_load_ratio read a NULL r (SIGSEGV) of a sample with a
 *     settling record;
 *   - gw_layer_create named no field of a NaN velocity or position, and
 *     read NULL bodies for n >= 1 (SIGSEGV).
 * Each refusal has a control: the valid call next to it runs.
 * Every case runs in its own child process (test_child.h): a crash, a
 * sanitizer report or anything printed fails that case.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "granwave.h"
#include "layer_test_util.h"
#include "test_child.h"

/* The three discs of test_three_discs with their own arrays (the rows spoil them). */
typedef struct hand_sample {
    double x[3], y[3], r[3];
    int body[3];
    gw_layer_spring sp[1];
    gw_layer_sample s;
} hand_sample;

static void hand_init(hand_sample *h)
{
    const gw_layer_sample t = test_three_discs();
    memcpy(h->x, t.x, sizeof h->x), memcpy(h->y, t.y, sizeof h->y), memcpy(h->r, t.r, sizeof h->r);
    h->s = t;
    h->s.x = h->x, h->s.y = h->y, h->s.r = h->r;
}

/* A short impact on the hand sample: t_max 1e-4 s (5 samples). */
static gw_layer_impact_params short_impact(void)
{
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.t_max = 1e-4;
    return ip;
}

typedef struct bad_row {
    const char *field; /* what the row spoils */
    int what;          /* 0 x, 1 y, 2 r (of particle 1), 3 body ids {0, 1, 0}, 4 a spring 0-1 of
                          displacement v, 5 the width, 6 rm */
    double v;
    int remove_walls;  /* 1: the run keeps no walls (the centre may lie outside) */
    const char *named; /* in the message; NULL: the row passes both */
} bad_row;

static const bad_row bad_rows[] = {
    {"x NaN", 0, NAN, 0, "particle 1: x = nan m is not a finite number"},
    {"x inf", 0, INFINITY, 0, "particle 1: x = inf m is not a finite number"},
    {"x -inf", 0, -INFINITY, 1, "particle 1: x = -inf m is not a finite number"},
    {"y NaN", 1, NAN, 0, "particle 1: y = nan m is not a finite number"},
    {"y inf", 1, INFINITY, 1, "particle 1: y = inf m is not a finite number"},
    {"r NaN", 2, NAN, 0, "particle 1: r = nan m is not a finite number"},
    {"r inf", 2, INFINITY, 0, "particle 1: r = inf m is not a finite number"},
    {"r 0", 2, 0, 0, "particle 1: radius r = 0 m must be positive"},
    {"r < 0", 2, -0.1, 0, "particle 1: radius r = -0.1 m must be positive"},
    /* (the walls' message before session 43: now the box every sample is
     * held to, as the reader's, walls or none) */
    {"x < 0 inside walls", 0, -0.05, 0, "particle 1: particle outside the box (0 <= x <= 1, y >= 0) beyond the "
                                        "0.02 R overlap tolerance (x = -0.05, y = 0.1, r = 0.1 m)"},
    {"x > width inside walls", 0, 1.05, 0, "particle 1: particle outside the box (0 <= x <= 1, y >= 0) beyond the "
                                           "0.02 R overlap tolerance (x = 1.05, y = 0.1, r = 0.1 m)"},
    {"y < 0 inside walls", 1, -0.05, 0, "particle 1: particle outside the box (0 <= x <= 1, y >= 0) beyond the "
                                        "0.02 R overlap tolerance (x = 0.5, y = -0.05, r = 0.1 m)"},
    {"x < 0, walls removed", 0, -0.05, 1, "particle 1: particle outside the box"},
    {"clump of discs apart", 3, 0, 0, "body 0: its 2 particles do not overlap or touch"},
    {"spring of NaN displacement", 4, NAN, 0, "spring 0 1: displacement u = nan m is not a finite number"},
    /* the header: rm 0 passed the check, the run refused its block of radius
     * 0; the others were "x: no soil particle lies under the block" */
    {"rm 0", 6, 0, 0, "sample 's': rm 0 m must be finite and positive"},
    {"rm NaN", 6, NAN, 0, "sample 's': rm nan m must be finite and positive"},
    {"rm < 0", 6, -0.1, 0, "sample 's': rm -0.1 m must be finite and positive"},
    {"width NaN", 5, NAN, 0, "sample 's': width nan m must be finite and positive"},
    {"width inf", 5, INFINITY, 1, "sample 's': width inf m must be finite and positive"},
};

static void spoil(hand_sample *h, const bad_row *b)
{
    if (b->what == 0)
        h->x[1] = b->v;
    else if (b->what == 1)
        h->y[1] = b->v;
    else if (b->what == 2)
        h->r[1] = b->v;
    else if (b->what == 3) {
        h->body[0] = 0, h->body[1] = 1, h->body[2] = 0; /* discs 0 and 2 are 0.4 m apart, r 0.1 */
        h->s.body = h->body;
    } else if (b->what == 4) {
        h->sp[0] = (gw_layer_spring){0, 1, b->v};
        h->s.springs = h->sp, h->s.n_springs = 1;
    } else if (b->what == 5)
        h->s.width = b->v;
    else
        h->s.rm = b->v;
}

/* The check and the run agree on each bad particle: the same status and the
 * same message, naming the particle's index and its field. Before, the check
 * gave GW_OK for every row and the run refused them later ("particle 1:
 * position and velocity must be finite", or the clump's or the spring's
 * message), or crashed nowhere but agreed on nothing. */
static int check_and_run_agree(void)
{
    gw_layer_params lp = gw_layer_params_default();
    gw_solver_params sp = gw_solver_params_default();
    int bad = 0;
    for (size_t k = 0; k < sizeof bad_rows / sizeof bad_rows[0]; k++) {
        hand_sample h;
        hand_init(&h);
        spoil(&h, &bad_rows[k]);
        gw_layer_impact_params ip = short_impact();
        ip.remove_walls = bad_rows[k].remove_walls;
        gw_err ec = {{0}}, er = {{0}};
        const int rc = gw_layer_impact_check(&h.s, &ip, &ec);
        gw_layer_impact_result res;
        const int rr = gw_layer_impact(&h.s, &lp, &ip, gw_solver_verlet, &sp, &res, &er);
        gw_layer_impact_result_free(&res);
        if (!refused(rc, &ec, bad_rows[k].named) || rr != rc || strcmp(ec.msg, er.msg) != 0) {
            printf("row '%s': check %d '%s', run %d '%s'\n", bad_rows[k].field, rc, ec.msg, rr, er.msg);
            bad++;
        }
    }
    EXPECT(bad == 0);
    /* controls: the sample as built runs; a disc against a wall within the
     * 0.02 r the reader allows runs with the walls removed (a centre outside
     * the box ran so before session 43: now refused as the reader refuses it) */
    hand_sample h;
    hand_init(&h);
    gw_layer_impact_params ip = short_impact();
    gw_err e = {{0}};
    gw_layer_impact_result res;
    EXPECT(gw_layer_impact_check(&h.s, &ip, &e) == GW_OK);
    EXPECT(gw_layer_impact(&h.s, &lp, &ip, gw_solver_verlet, &sp, &res, &e) == GW_OK && res.ns > 0);
    gw_layer_impact_result_free(&res);
    h.x[0] = 0.099;
    ip.remove_walls = 1;
    EXPECT(gw_layer_impact_check(&h.s, &ip, &e) == GW_OK);
    EXPECT(gw_layer_impact(&h.s, &lp, &ip, gw_solver_verlet, &sp, &res, &e) == GW_OK && res.ns > 0);
    gw_layer_impact_result_free(&res);
    return 0;
}

/* The calls that take a sample besides the check read it as the check does:
 * NaN in a particle gives NaN (hash 0) or the check's refusal. */
static int other_sample_calls(void)
{
    gw_layer_params lp = gw_layer_params_default();
    gw_layer_impact_params ip = short_impact();
    hand_sample h;
    hand_init(&h);
    const unsigned long long h0 = gw_layer_sample_pile_hash(&h.s);
    EXPECT(h0 != 0 && gw_layer_impact_dem_dt(&h.s, &lp, &ip) > 0);
    h.x[2] = NAN; /* hashed as any other pile before */
    EXPECT(gw_layer_sample_pile_hash(&h.s) == 0);
    h.x[2] = 0.7;
    EXPECT(gw_layer_sample_pile_hash(&h.s) == h0);
    h.y[2] = INFINITY;
    EXPECT(gw_layer_sample_pile_hash(&h.s) == 0);
    h.y[2] = 0.1, h.s.rm = NAN; /* hashed before, and the discs' step 5e-6 s given */
    EXPECT(gw_layer_sample_pile_hash(&h.s) == 0 && isnan(gw_layer_impact_dem_dt(&h.s, &lp, &ip)));
    h.s.rm = 0.1;
    EXPECT(gw_layer_sample_pile_hash(&h.s) == h0);
    return 0;
}

/* gw_layer_impact_rest_check read the floor's load through a NULL y or r
 * (SIGSEGV) and passed a NaN y (a NaN load is no load above the weight) */
static int rest_check_hand(void)
{
    gw_layer_params lp = gw_layer_params_default();
    gw_err e = {{0}};
    hand_sample h;
    hand_init(&h);
    EXPECT(gw_layer_impact_rest_check(&h.s, &lp, "p", &e) == GW_OK); /* control: the discs rest on the floor */
    h.s.y = NULL;
    EXPECT(refused(gw_layer_impact_rest_check(&h.s, &lp, "p", &e), &e, "y NULL"));
    h.s.y = h.y, h.s.r = NULL;
    EXPECT(refused(gw_layer_impact_rest_check(&h.s, &lp, "p", &e), &e, "r NULL"));
    h.s.r = h.r, h.s.n = 0;
    EXPECT(refused(gw_layer_impact_rest_check(&h.s, &lp, "p", &e), &e, "n = 0"));
    h.s.n = 3, h.y[1] = NAN;
    EXPECT(refused(gw_layer_impact_rest_check(&h.s, &lp, "p", &e), &e, "particle 1: y = nan m"));
    /* control: a disc pressed 1 % of its radius into the floor is a load far
     * above its weight (Hertz), refused as before */
    h.y[1] = 0.099;
    EXPECT(refused(gw_layer_impact_rest_check(&h.s, &lp, "p", &e), &e, "times the weight"));
    return 0;
}

/* gw_layer_impact_settled_check and gw_layer_settled_load_ratio weighed the
 * pile through a NULL r (SIGSEGV) when the sample records a settling */
static int settled_check_hand(void)
{
    gw_layer_params lp = gw_layer_params_default();
    gw_err e = {{0}};
    hand_sample h;
    hand_init(&h);
    h.s.settled = (gw_layer_settled){.recorded = 1, .shear_modulus = lp.shear_modulus, .poisson = lp.poisson,
                                     .friction_deg = lp.friction_deg, .density = lp.density, .gravity = lp.gravity,
                                     .mass_law = lp.mass_law};
    char w[512];
    /* control: the same material, q = 1 */
    EXPECT(fabs(gw_layer_settled_load_ratio(&h.s, &lp) - 1) < 1e-12);
    EXPECT(gw_layer_impact_settled_check(&h.s, &lp, 0, "p", w, sizeof w, &e) == GW_OK && w[0] == '\0');
    h.s.r = NULL;
    EXPECT(isnan(gw_layer_settled_load_ratio(&h.s, &lp)));
    EXPECT(refused(gw_layer_impact_settled_check(&h.s, &lp, 0, "p", w, sizeof w, &e), &e, "r NULL"));
    h.s.r = h.r, h.r[0] = NAN;
    EXPECT(isnan(gw_layer_settled_load_ratio(&h.s, &lp)));
    EXPECT(refused(gw_layer_impact_settled_check(&h.s, &lp, 0, "p", w, sizeof w, &e), &e,
                   "particle 0: r = nan m"));
    return 0;
}

/* gw_layer_create named the particle but not the field: "particle 2:
 * position and velocity must be finite" for a NaN vy; and read NULL bodies
 * (SIGSEGV) */
static int create_names_field(void)
{
    gw_layer_params lp = gw_layer_params_default();
    lp.width = 1;
    gw_layer_body b[3] = {{.x = 0.3, .y = 0.1, .r = 0.1}, {.x = 0.5, .y = 0.1, .r = 0.1},
                          {.x = 0.7, .y = 0.1, .r = 0.1}};
    gw_layer *L = NULL;
    gw_err e = {{0}};
    static const char *const named[] = {"particle 2: vx = nan m/s", "particle 2: vy = nan m/s",
                                        "particle 2: w = nan rad/s"};
    for (int k = 0; k < 3; k++) {
        double *f = k == 0 ? &b[2].vx : k == 1 ? &b[2].vy : &b[2].w;
        *f = NAN;
        EXPECT(refused(gw_layer_create(&lp, 3, b, &L, &e), &e, named[k]) && L == NULL);
        *f = 0;
    }
    EXPECT(refused(gw_layer_create(&lp, 3, NULL, &L, &e), &e, "bodies is NULL") && L == NULL); /* SIGSEGV before */
    b[2].y = -INFINITY;
    EXPECT(refused(gw_layer_create(&lp, 3, b, &L, &e), &e, "particle 2: y = -inf m"));
    b[2].y = 0.1; /* control */
    EXPECT(gw_layer_create(&lp, 3, b, &L, &e) == GW_OK && L && gw_layer_n(L) == 3);
    gw_layer_free(L);
    return 0;
}

int main(void)
{
    static const child_row cases[] = {
        {"gw_layer_impact_check/gw_layer_impact: a table of bad particles, the same refusal from both",
         check_and_run_agree},
        {"gw_layer_sample_pile_hash: a NaN or infinite coordinate, a NaN rm", other_sample_calls},
        {"gw_layer_impact_rest_check: NULL y or r, n 0, a NaN y", rest_check_hand},
        {"gw_layer_impact_settled_check/gw_layer_settled_load_ratio: NULL r, a NaN r", settled_check_hand},
        {"gw_layer_create: the field of a NaN value named, NULL bodies", create_names_field},
    };
    return child_cases_run(cases, sizeof cases / sizeof cases[0]);
}
