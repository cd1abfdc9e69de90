/*
 * test_library_hostile43.c: the forty-third hostile pass over the library's C
 * interface (docs/library.md "The contract of every call"), at the samples a
 * caller builds in memory. The file reader holds a sample to its limits (n in
 * [1, 1e7], rm and width within their scales, each radius within [1e-3, 1e3]
 * R_m, each disc inside the box to 0.02 r and at most 1e6 R_m high, no two
 * discs deeper than 0.05 R_p inside each other); a sample built in memory was
 * held to its form only (finite, r > 0), so that:
 *   - an absurd disc count (n = 2e7 over arrays of 3) was read past its
 *     arrays by the impact's check, its step and the porosity (SIGSEGV);
 *   - a radius of 1e-5 R_m, a disc 1e7 R_m high, an rm of 1e-7 m, a box of
 *     1e7 R_m, a disc outside the box (walls removed) passed the impact's
 *     check and ran, got a step from gw_layer_impact_dem_dt and a porosity;
 *   - two discs at one place, or half a radius inside each other, ran, their
 *     overlap injecting energy into the impact, and had a porosity.
 * Each row spoils the three discs of test_three_discs one way, and each entry
 * point that takes a sample is one case in its own child process
 * (test_child.h: a crash, a sanitizer report or anything printed fails that
 * case alone): gw_layer_impact_check refuses (GW_EINVAL) naming the field and
 * the index, gw_layer_impact gives the same status and message,
 * gw_layer_impact_dem_dt is NaN, gw_layer_sample_porosity NaN,
 * gw_layer_impact_rest_check and gw_layer_impact_gap_check refuse naming the
 * same, gw_layer_sample_write refuses naming the same and writes nothing,
 * and the same sample written to a text file by hand is refused by
 * gw_layer_sample_read with a message naming the same (the file route
 * agrees). A control row (the discs as built) passes every case.
 * Session 44 (one sample check, one rule per property): the walls' rule is
 * the box's, 0.02 r: a disc 0.01 r beyond the left or the right wall passes
 * every call (and runs), 0.03 r beyond is refused by every call, walls kept
 * or removed, with the one message of gw_layer_impact_check, byte for byte
 * (the check held the centres to the walls too, a second rule that never
 * refused what the box passed); gw_layer_impact_settled_check refuses what
 * the others refuse (its check is now its own, the run's body taking the
 * run's) and gw_layer_settled_load_ratio is NaN; gw_layer_sample_pile_hash
 * is 0 for every refused row (it checked the form only and hashed a disc
 * outside the box, an rm of 1e-7 m or two discs at one place), non-zero for
 * the passing ones.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "granwave.h"
#include "layer_test_util.h"
#include "test_child.h"

typedef struct hand_sample {
    double x[3], y[3], r[3];
    gw_layer_sample s;
} hand_sample;

typedef struct bad_row {
    const char *label;
    int what;          /* 0 x, 1 y, 2 r of particle `i`; 3 n; 4 rm; 5 width; -1 none (the control) */
    int i;
    double v;
    int remove_walls;  /* the impact keeps no walls (a disc outside the box is the sample's fault alone) */
    const char *named; /* in the in-memory refusals (NULL: the control, which passes) */
    const char *file;  /* in the reader's refusal of the same sample as a file */
} bad_row;

static const bad_row rows[] = {
    {"the discs as built (control)", -1, 0, 0, 0, NULL, NULL},
    {"n = 2e7 over arrays of 3", 3, 0, 2e7, 0, "n = 20000000 particles (in [1, 10000000]", "20000000"},
    {"r of 1e-5 R_m", 2, 1, 1e-6, 0, "particle 1: radius 1e-06 m is outside [0.001, 1000] R_m",
     "radius 1e-06 m is outside [0.001, 1000] R_m"},
    {"r NaN (a guard)", 2, 2, NAN, 0, "particle 2: r = nan m is not a finite number", "line"},
    {"y 1e7 R_m high", 1, 2, 1e6, 0, "particle 2: y = 1e+06 m is above 1e+06 R_m", "y = 1e+06 m is above 1e+06 R_m"},
    {"x outside the box, walls removed", 0, 2, 2.0, 1, "particle 2: particle outside the box (0 <= x <= 1, y >= 0)",
     "particle outside the box (0 <= x <= 1, y >= 0)"},
    {"two discs at one place", 0, 1, 0.3, 0, "particles 0 and 1 overlap by 2 R_p, above 0.05 R_p",
     "particles 0 and 1 overlap by 2 R_p, above 0.05 R_p"},
    {"two discs half a radius inside each other", 0, 1, 0.45, 0,
     "particles 0 and 1 overlap by 0.5 R_p, above 0.05 R_p", "particles 0 and 1 overlap by 0.5 R_p, above 0.05 R_p"},
    {"rm 1e-7 m", 4, 0, 1e-7, 0, "rm 1e-07 m is outside [1e-05, 1000] m", "rm 1e-07 m is outside [1e-05, 1000] m"},
    {"width 1e7 R_m", 5, 0, 1e6, 1, "width 1e+06 m is above 1e+06 R_m", "width 1e+06 m is above 1e+06 R_m"},
    /* the walls' one rule, the box's 0.02 r (disc 0 at x 0.3, disc 2 at 0.7, r 0.1, box 1 wide) */
    {"disc 0 0.01 r beyond the left wall (passes)", 0, 0, 0.099, 0, NULL, NULL},
    {"disc 2 0.01 r beyond the right wall (passes)", 0, 2, 0.901, 0, NULL, NULL},
    {"disc 2 0.01 r beyond the right wall, walls removed (passes)", 0, 2, 0.901, 1, NULL, NULL},
    {"disc 0 0.03 r beyond the left wall", 0, 0, 0.097, 0,
     "particle 0: particle outside the box (0 <= x <= 1, y >= 0) beyond the 0.02 R overlap tolerance",
     "particle outside the box (0 <= x <= 1, y >= 0)"},
    {"disc 2 0.03 r beyond the right wall", 0, 2, 0.903, 0,
     "particle 2: particle outside the box (0 <= x <= 1, y >= 0) beyond the 0.02 R overlap tolerance",
     "particle outside the box (0 <= x <= 1, y >= 0)"},
    {"disc 2 0.03 r beyond the right wall, walls removed", 0, 2, 0.903, 1,
     "particle 2: particle outside the box (0 <= x <= 1, y >= 0) beyond the 0.02 R overlap tolerance",
     "particle outside the box (0 <= x <= 1, y >= 0)"},
    {"disc 1 0.03 r into the floor", 1, 1, 0.097, 0,
     "particle 1: particle outside the box (0 <= x <= 1, y >= 0) beyond the 0.02 R overlap tolerance",
     "particle outside the box (0 <= x <= 1, y >= 0)"},
};
#define NROWS (sizeof rows / sizeof rows[0])

static const bad_row *row; /* the row of the case the next child runs */
static char dir[64];

static void hand(hand_sample *h)
{
    const gw_layer_sample t = test_three_discs();
    memcpy(h->x, t.x, sizeof h->x), memcpy(h->y, t.y, sizeof h->y), memcpy(h->r, t.r, sizeof h->r);
    h->s = t;
    h->s.x = h->x, h->s.y = h->y, h->s.r = h->r;
    double *col[3] = {h->x, h->y, h->r};
    if (row->what >= 0 && row->what <= 2)
        col[row->what][row->i] = row->v;
    else if (row->what == 3)
        h->s.n = (int)row->v;
    else if (row->what == 4)
        h->s.rm = row->v;
    else if (row->what == 5)
        h->s.width = row->v;
}

static gw_layer_impact_params impact(void)
{
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.t_max = 1e-4;
    ip.remove_walls = row->remove_walls;
    return ip;
}

/* rc and e a refusal naming the row's field, or GW_OK for the control */
static int as_row(int rc, const gw_err *e)
{
    if (!row->named) {
        if (rc != GW_OK)
            printf("control: status %d '%s'\n", rc, e->msg);
        return rc == GW_OK;
    }
    return refused(rc, e, row->named);
}

static int c_check(void)
{
    hand_sample h;
    hand(&h);
    gw_layer_impact_params ip = impact();
    gw_err e = {{0}};
    EXPECT(as_row(gw_layer_impact_check(&h.s, &ip, &e), &e));
    return 0;
}

static int c_run(void)
{
    hand_sample h;
    hand(&h);
    gw_layer_impact_params ip = impact();
    gw_layer_params lp = gw_layer_params_default();
    gw_solver_params sp = gw_solver_params_default();
    gw_layer_impact_result res;
    gw_err ec = {{0}}, er = {{0}};
    const int rc = gw_layer_impact_check(&h.s, &ip, &ec);
    const int rr = gw_layer_impact(&h.s, &lp, &ip, gw_solver_verlet, &sp, &res, &er);
    if (rr == GW_OK)
        gw_layer_impact_result_free(&res);
    EXPECT(as_row(rr, &er));
    EXPECT(rr == rc && strcmp(ec.msg, er.msg) == 0);
    return 0;
}

static int c_dem_dt(void)
{
    hand_sample h;
    hand(&h);
    gw_layer_impact_params ip = impact();
    gw_layer_params lp = gw_layer_params_default();
    const double dt = gw_layer_impact_dem_dt(&h.s, &lp, &ip);
    if (row->named ? !isnan(dt) : !(dt > 0))
        printf("dem_dt %g\n", dt);
    return 0;
}

static int c_porosity(void)
{
    hand_sample h;
    hand(&h);
    const double p = gw_layer_sample_porosity(&h.s);
    if (row->named ? !isnan(p) : !(p >= 0 && p <= 1))
        printf("porosity %g\n", p);
    return 0;
}

/* rc and e the row's refusal with gw_layer_impact_check's message to the
 * byte (ec), or GW_OK for a row that passes */
static int as_check(int rc, const gw_err *e, const gw_err *ec)
{
    if (!as_row(rc, e))
        return 0;
    if (row->named && strcmp(e->msg, ec->msg) != 0) {
        printf("message '%s', the check's '%s'\n", e->msg, ec->msg);
        return 0;
    }
    return 1;
}

static int c_rest_gap(void)
{
    hand_sample h;
    hand(&h);
    gw_layer_impact_params ip = impact();
    gw_layer_params lp = gw_layer_params_default();
    gw_err e = {{0}}, ec = {{0}};
    (void)gw_layer_impact_check(&h.s, &ip, &ec);
    EXPECT(as_check(gw_layer_impact_rest_check(&h.s, &lp, "s", &e), &e, &ec));
    EXPECT(as_check(gw_layer_impact_gap_check(&h.s, &ip, lp.gravity, &e), &e, &ec));
    return 0;
}

/* the settling's checks on a sample recording the default material's settling */
static int c_settled(void)
{
    hand_sample h;
    hand(&h);
    gw_layer_impact_params ip = impact();
    gw_layer_params lp = gw_layer_params_default();
    h.s.settled = (gw_layer_settled){.recorded = 1, .shear_modulus = lp.shear_modulus, .poisson = lp.poisson,
                                     .friction_deg = lp.friction_deg, .density = lp.density, .gravity = lp.gravity,
                                     .mass_law = lp.mass_law, .clump_mass = -1};
    gw_err e = {{0}}, ec = {{0}};
    char w[768];
    (void)gw_layer_impact_check(&h.s, &ip, &ec);
    EXPECT(as_check(gw_layer_impact_settled_check(&h.s, &lp, 0, "s", w, sizeof w, &e), &e, &ec));
    const double q = gw_layer_settled_load_ratio(&h.s, &lp);
    if (row->named ? !isnan(q) : !(fabs(q - 1) < 1e-12))
        printf("load ratio %g\n", q);
    return 0;
}

static int c_pile_hash(void)
{
    hand_sample h;
    hand(&h);
    const unsigned long long hs = gw_layer_sample_pile_hash(&h.s);
    if (row->named ? hs != 0 : hs == 0)
        printf("pile hash %016llx\n", hs);
    return 0;
}

static int c_write(void)
{
    hand_sample h;
    hand(&h);
    char path[128];
    struct stat st;
    snprintf(path, sizeof path, "%s/w%d.txt", dir, (int)(row - rows));
    gw_err e = {{0}};
    EXPECT(as_row(gw_layer_sample_write(&h.s, path, NULL, &e), &e));
    EXPECT((stat(path, &st) == 0) == (row->named == NULL)); /* nothing written when refused */
    unlink(path);
    return 0;
}

/* the same sample as a text file written here, read back */
static int c_file(void)
{
    hand_sample h;
    hand(&h);
    char path[128];
    snprintf(path, sizeof path, "%s/f%d.txt", dir, (int)(row - rows));
    FILE *fp = fopen(path, "w");
    EXPECT(fp != NULL);
    fprintf(fp, "granwave-layer-sample 1\nwidth %.17g\nrm %.17g\nn %d\n", h.s.width, h.s.rm, h.s.n);
    for (int i = 0; i < 3; i++)
        fprintf(fp, "%.17g %.17g %.17g\n", h.x[i], h.y[i], h.r[i]);
    fclose(fp);
    gw_layer_sample s;
    gw_err e = {{0}};
    const int rc = gw_layer_sample_read(path, &s, &e);
    unlink(path);
    if (rc == GW_OK)
        gw_layer_sample_free(&s);
    if (row->named ? rc != GW_EFORMAT || !strstr(e.msg, row->file) : rc != GW_OK)
        printf("read: status %d '%s'\n", rc, e.msg);
    return 0;
}

int main(void)
{
    static const struct {
        const char *what;
        case_fn fn;
    } calls[] = {
        {"gw_layer_impact_check", c_check},
        {"gw_layer_impact (as the check)", c_run},
        {"gw_layer_impact_dem_dt", c_dem_dt},
        {"gw_layer_sample_porosity", c_porosity},
        {"gw_layer_impact_rest_check, gw_layer_impact_gap_check", c_rest_gap},
        {"gw_layer_impact_settled_check, gw_layer_settled_load_ratio", c_settled},
        {"gw_layer_sample_pile_hash", c_pile_hash},
        {"gw_layer_sample_write", c_write},
        {"the file route: gw_layer_sample_read", c_file},
    };
    snprintf(dir, sizeof dir, "/tmp/gw_hostile43.XXXXXX");
    if (!mkdtemp(dir))
        return 1;
    int nfail = 0, ncases = 0;
    for (size_t k = 0; k < NROWS; k++)
        for (size_t c = 0; c < sizeof calls / sizeof calls[0]; c++) {
            char label[200];
            snprintf(label, sizeof label, "%s: %s", rows[k].label, calls[c].what);
            row = &rows[k];
            child_case(label, calls[c].fn, &nfail, &ncases);
        }
    rmdir(dir);
    printf("%d of %d cases failed\n", nfail, ncases);
    return nfail ? 1 : 0;
}
