/*
 * test_library_hostile46.c: the forty-sixth hostile pass over the library's C
 * interface (docs/library.md "The contract of every call"), at the settling
 * record of a sample built in memory (gw_layer_settled). The file reader
 * holds a settings line to the material's ranges (G in [1e-3, 1e15] Pa, nu
 * in [0, 0.499999], phi in [0, 90) deg, rho in [1e-6, 1e6] kg/m^3, g in
 * (0, 1e4] m/s^2, all finite), its mass law to the header's and its clump
 * mass to the header's; a record set in memory (recorded = 1) was taken as
 * it was, so that:
 *   - a NaN, zero, negative or infinite modulus, density or gravity, or a
 *     Poisson ratio of 1, gave a load ratio of NaN, inf, 0 or -40
 *     (gw_layer_settled_load_ratio) and a refusal telling the pile "carries
 *     nan times" (or -40 times) its weight; under other_settling the impact
 *     ran with that text as its warning;
 *   - a NaN, negative or 100-degree friction passed the friction bound (a
 *     NaN compares false) with a warning only;
 *   - a mass law of 7 was told "mass-law disc against the impact's disc",
 *     a clump mass of 9 passed without a word;
 *   - the porosity, the DEM step and the pile hash took each of them, and
 *     gw_layer_sample_write wrote the sample.
 * Each row spoils the record of test_three_discs one way (a control row
 * records the impact's own material, another a different material within
 * the ranges); each entry point that takes a sample is one case in its own
 * child process (test_child.h): gw_layer_impact_check refuses (GW_EINVAL)
 * naming the field ("settled.FIELD"), gw_layer_impact (other_settling 1)
 * gives the same status and message, gw_layer_impact_settled_check
 * (other_settling 1) refuses with the same message, the load ratio, the
 * porosity and the DEM step are NaN, the pile hash 0, and the writer
 * refuses naming the same and leaves no file. The controls pass every call.
 * Also gw_chain_memory_check on a bead count outside [1, 5e7]: n = -1 and 0
 * passed (the sizes of a negative column are below any limit) and n = INT_MIN
 * was refused as needing 4.4e11 GB, "at most 0 beads here"; each is now
 * refused as gw_chain_params_validate refuses it, naming n (a control of 1
 * and 2e6 beads passes, 3e6 under cvode is still the memory refusal).
 * And gw_layer_sample_write's header, as the readers take it back: a header
 * "settings: not json", a settings line without its material's keys, with a
 * modulus of -5, two settings lines, a settings line over 65536 characters or
 * a carriage return inside a line was written (text and HDF5) and the file
 * then refused by gw_layer_sample_read; each is now refused (GW_EINVAL naming
 * the header's line) and no file is left. Controls (no settings line, a
 * layer-make settings line of the sample's material, a "settled: ...
 * converged 0" line, a line ending in CR) are written and read back, the
 * record as written.
 * And the impact's material given to the public settling, rest and gap
 * checks: a gravity of NaN, inf, -1 or 1e300 (gw_layer_params_validate and
 * the run refuse each) passed gw_layer_impact_settled_check under
 * other_settling ("against the impact's nan"), gw_layer_impact_rest_check,
 * gave a load ratio of inf or 9.81e-300, and g = 1e300 was told by
 * gw_layer_impact_fall_check and _gap_check that vi is too slow for the
 * default gap: each now refuses naming gravity and its range, as the
 * validation does (the load ratio NaN); 9.81 and 0 pass.
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

enum { F_G, F_NU, F_PHI, F_RHO, F_GRAV, F_LAW, F_CLUMP, F_NONE };

typedef struct rec_row {
    const char *label;
    int field;         /* F_*: the record's field spoiled (F_NONE: the control) */
    double v;          /* its value (an int field: cast) */
    const char *named; /* in every refusal (NULL: the row passes) */
} rec_row;

static const rec_row rows[] = {
    {"the impact's own material (control)", F_NONE, 0, NULL},
    {"another material within the ranges (control)", F_NU, 0.3, NULL},
    {"shear modulus NaN", F_G, NAN, "settled.shear_modulus = nan Pa is outside [0.001, 1e+15]"},
    {"shear modulus 0", F_G, 0, "settled.shear_modulus = 0 Pa"},
    {"shear modulus -1e9", F_G, -1e9, "settled.shear_modulus = -1e+09 Pa"},
    {"shear modulus inf", F_G, INFINITY, "settled.shear_modulus = inf Pa"},
    {"Poisson ratio 1", F_NU, 1, "settled.poisson = 1 is outside [0, 0.499999]"},
    {"Poisson ratio NaN", F_NU, NAN, "settled.poisson = nan"},
    {"friction NaN", F_PHI, NAN, "settled.friction_deg = nan deg is outside [0, 90)"},
    {"friction -30 deg", F_PHI, -30, "settled.friction_deg = -30 deg"},
    {"friction 90 deg (open end)", F_PHI, 90, "settled.friction_deg = 90 deg"},
    {"density 0", F_RHO, 0, "settled.density = 0 kg/m^3 is outside [1e-06, 1e+06]"},
    {"gravity 0 (open end)", F_GRAV, 0, "settled.gravity = 0 m/s^2 is outside (0, 10000]"},
    {"gravity NaN", F_GRAV, NAN, "settled.gravity = nan m/s^2"},
    {"mass law 7", F_LAW, 7, "settled.mass_law = 7 where the sample's mass_law is 0"},
    {"mass law sphere on a disc sample", F_LAW, GW_LAYER_MASS_SPHERE, "settled.mass_law = 1"},
    {"clump mass 9", F_CLUMP, 9, "settled.clump_mass = 9 where the sample's clump_mass is 0"},
    {"clump mass union on a sum sample", F_CLUMP, GW_LAYER_CLUMP_MASS_UNION, "settled.clump_mass = 1"},
};
#define NROWS (sizeof rows / sizeof rows[0])

static const rec_row *row; /* the row of the case the next child runs */
static char dir[64];

/* the three discs recording the default material's settling, spoiled by the row */
static gw_layer_sample hand(void)
{
    gw_layer_sample s = test_three_discs();
    const gw_layer_params lp = gw_layer_params_default();
    s.settled = (gw_layer_settled){.recorded = 1, .shear_modulus = lp.shear_modulus, .poisson = lp.poisson,
                                   .friction_deg = lp.friction_deg, .density = lp.density, .gravity = lp.gravity,
                                   .mass_law = lp.mass_law, .clump_mass = -1};
    double *f[5] = {&s.settled.shear_modulus, &s.settled.poisson, &s.settled.friction_deg, &s.settled.density,
                    &s.settled.gravity};
    if (row->field <= F_GRAV)
        *f[row->field] = row->v;
    else if (row->field == F_LAW)
        s.settled.mass_law = (int)row->v;
    else if (row->field == F_CLUMP)
        s.settled.clump_mass = (int)row->v;
    return s;
}

static gw_layer_impact_params impact(void)
{
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.t_max = 1e-4;
    ip.other_settling = 1; /* a record away from rest runs with a warning: the record's own fault is refused */
    return ip;
}

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
    gw_layer_sample s = hand();
    gw_layer_impact_params ip = impact();
    gw_err e = {{0}};
    EXPECT(as_row(gw_layer_impact_check(&s, &ip, &e), &e));
    return 0;
}

static int c_run(void)
{
    gw_layer_sample s = hand();
    gw_layer_impact_params ip = impact();
    gw_layer_params lp = gw_layer_params_default();
    gw_solver_params sp = gw_solver_params_default();
    gw_layer_impact_result res;
    gw_err ec = {{0}}, er = {{0}};
    const int rc = gw_layer_impact_check(&s, &ip, &ec);
    const int rr = gw_layer_impact(&s, &lp, &ip, gw_solver_verlet, &sp, &res, &er);
    if (rr == GW_OK)
        gw_layer_impact_result_free(&res);
    EXPECT(as_row(rr, &er));
    EXPECT(rr == rc && strcmp(ec.msg, er.msg) == 0);
    return 0;
}

static int c_settled(void)
{
    gw_layer_sample s = hand();
    gw_layer_impact_params ip = impact();
    gw_layer_params lp = gw_layer_params_default();
    gw_err e = {{0}}, ec = {{0}};
    char w[768];
    (void)gw_layer_impact_check(&s, &ip, &ec);
    const int rc = gw_layer_impact_settled_check(&s, &lp, 1, "s", w, sizeof w, &e);
    EXPECT(as_row(rc, &e));
    if (row->named && strcmp(e.msg, ec.msg) != 0)
        printf("message '%s', the check's '%s'\n", e.msg, ec.msg);
    return 0;
}

/* the load ratio: NaN for a refused record; for the controls q of the
 * header's law, [G/(1 - nu)]_impact / [G/(1 - nu)]_settled (same weights) */
static int c_ratio(void)
{
    gw_layer_sample s = hand();
    gw_layer_params lp = gw_layer_params_default();
    const double q = gw_layer_settled_load_ratio(&s, &lp);
    const double want = (1 - s.settled.poisson) / (1 - lp.poisson);
    if (row->named ? !isnan(q) : !(fabs(q - want) < 1e-12))
        printf("load ratio %g (want %g)\n", q, row->named ? NAN : want);
    return 0;
}

static int c_porosity_dt(void)
{
    gw_layer_sample s = hand();
    gw_layer_impact_params ip = impact();
    gw_layer_params lp = gw_layer_params_default();
    const double p = gw_layer_sample_porosity(&s), dt = gw_layer_impact_dem_dt(&s, &lp, &ip);
    if (row->named ? !isnan(p) : !(p >= 0 && p <= 1))
        printf("porosity %g\n", p);
    if (row->named ? !isnan(dt) : !(dt > 0))
        printf("dem_dt %g\n", dt);
    return 0;
}

static int c_pile_hash(void)
{
    gw_layer_sample s = hand();
    const unsigned long long h = gw_layer_sample_pile_hash(&s);
    if (row->named ? h != 0 : h == 0)
        printf("pile hash %016llx\n", h);
    return 0;
}

static int c_write(void)
{
    gw_layer_sample s = hand();
    char path[128];
    struct stat st;
    snprintf(path, sizeof path, "%s/w%d.txt", dir, (int)(row - rows));
    gw_err e = {{0}};
    EXPECT(as_row(gw_layer_sample_write(&s, path, NULL, &e), &e));
    EXPECT((stat(path, &st) == 0) == (row->named == NULL)); /* nothing written when refused */
    unlink(path);
    return 0;
}

/* gw_chain_memory_check on a bead count: its message like
 * gw_chain_params_validate's, or the memory refusal, or GW_OK */
static int memory_n(int n, const char *want)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = n;
    gw_err e = {{0}}, ev = {{0}};
    const int rc = gw_chain_memory_check(&p, gw_solver_cvode, 0, &e);
    if (!want) {
        EXPECT(rc == GW_OK);
        return 0;
    }
    EXPECT(refused(rc, &e, want));
    if (n < 1 || n > 50000000) { /* the validation's own words */
        EXPECT(gw_chain_params_validate(&p, &ev) == GW_EINVAL);
        EXPECT(strcmp(e.msg, ev.msg) == 0);
    }
    return 0;
}

static int c_mem_neg1(void) { return memory_n(-1, "n: number of beads must be >= 1, got -1"); }
static int c_mem_zero(void) { return memory_n(0, "n: number of beads must be >= 1, got 0"); }
static int c_mem_intmin(void) { return memory_n(-2147483647 - 1, "got -2147483648"); }
static int c_mem_6e7(void) { return memory_n(60000000, "n: 60000000 beads exceed the supported 5e7"); }
static int c_mem_one(void) { return memory_n(1, NULL); }
static int c_mem_2e6(void) { return memory_n(2000000, NULL); }
static int c_mem_3e6(void) { return memory_n(3000000, "GB for its state"); }

typedef struct hdr_row {
    const char *label;
    const char *header; /* NULL: the long settings line (built) */
    const char *named;  /* in the refusal (NULL: written and read back) */
    int recorded;       /* the record read back (a control) */
} hdr_row;

#define MAT "\"shear-modulus\":4e10,\"poisson\":0.25,\"friction\":30,\"density\":2650,\"gravity\":9.81,\"mass-law\":\"disc\""
static const hdr_row hdrs[] = {
    {"no settings line (control)", "made by hand\nsecond line", NULL, 0},
    {"the sample's material (control)", "made by hand\nsettings: {" MAT "}", NULL, 1},
    {"a settled line, converged 0 (control)", "settled: t = 1 s, E_k = 1 J, converged 0", NULL, 0},
    {"a line ending in CR (control)", "one\r\nsettings: {" MAT "}\r", NULL, 1},
    {"settings not JSON", "settings: not json", "header line 1: layer-make's settings line is not a JSON object", 0},
    {"settings without its keys", "x\nsettings: {\"material\":{}}", "header line 2: layer-make's settings line lacks", 0},
    {"a modulus of -5", "settings: {\"shear-modulus\":-5,\"poisson\":0.25,\"friction\":30,\"density\":2650,"
                        "\"gravity\":9.81,\"mass-law\":\"disc\"}", "outside the material's range: shear-modulus", 0},
    {"a sphere record on a disc sample", "settings: {\"shear-modulus\":4e10,\"poisson\":0.25,\"friction\":30,"
                                         "\"density\":2650,\"gravity\":9.81,\"mass-law\":\"sphere\"}", "mass law sphere", 0},
    {"two settings lines", "settings: {" MAT "}\n  settings: {" MAT "}", "header line 2: a second settings line", 0},
    {"a settings line of 70000 characters", NULL, "header line 1: a settings line longer than 65536", 0},
    {"a CR inside a line", "one\rtwo", "header line 1: a carriage return inside the line", 0},
};
#define NHDRS (sizeof hdrs / sizeof hdrs[0])
static const hdr_row *hrow;
static const char *hext; /* ".txt" or ".h5" */

static int c_header(void)
{
    gw_layer_sample s = test_three_discs();
    char path[128], *big = NULL;
    const char *header = hrow->header;
    if (!header) {
        big = malloc(70100);
        if (!big)
            return 1;
        strcpy(big, "settings: {\"x\":\"");
        memset(big + 16, 'a', 70000);
        strcpy(big + 70016, "\"}");
        header = big;
    }
    snprintf(path, sizeof path, "%s/h%d%s", dir, (int)(hrow - hdrs), hext);
    gw_err e = {{0}};
    const int rc = gw_layer_sample_write(&s, path, header, &e);
    free(big);
    struct stat st;
    if (hrow->named) {
        EXPECT(refused(rc, &e, hrow->named));
        EXPECT(stat(path, &st) != 0); /* nothing written */
        return 0;
    }
    EXPECT(rc == GW_OK);
    gw_layer_sample t;
    memset(&t, 0, sizeof t);
    const int rr = gw_layer_sample_read(path, &t, &e);
    if (rr != GW_OK)
        printf("read back: %d %s\n", rr, e.msg);
    EXPECT(rr == GW_OK);
    EXPECT(t.settled.recorded == hrow->recorded);
    EXPECT(!hrow->recorded || (t.settled.shear_modulus == 4e10 && t.settled.friction_deg == 30));
    gw_layer_sample_free(&t);
    unlink(path);
    return 0;
}

static const double gravities[] = {NAN, INFINITY, -1, 1e300, 9.81, 0};
static double grav;

/* the checks given the impact's material lp with gravity grav (g too) */
static int c_gravity(void)
{
    gw_layer_sample s = test_three_discs();
    gw_layer_params lp = gw_layer_params_default();
    lp.gravity = grav;
    s.settled = (gw_layer_settled){.recorded = 1, .shear_modulus = lp.shear_modulus, .poisson = lp.poisson,
                                   .friction_deg = lp.friction_deg, .density = lp.density, .gravity = 9.81,
                                   .mass_law = lp.mass_law, .clump_mass = -1};
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    ip.t_max = 1;
    const int bad = !(grav >= 0 && grav <= 1e4);
    gw_err e = {{0}}, ev = {{0}};
    char w[768];
    const int vrc = gw_layer_params_validate(&lp, &ev);
    EXPECT((vrc != GW_OK) == bad);
    const int rs = gw_layer_impact_settled_check(&s, &lp, 1, "s", w, sizeof w, &e);
    if (bad) {
        EXPECT(refused(rs, &e, "gravity (m/s^2)") && strcmp(e.msg, ev.msg) == 0);
    } else {
        EXPECT(rs == GW_OK);
    }
    const int rr = gw_layer_impact_rest_check(&s, &lp, "s", &e);
    if (bad) {
        EXPECT(refused(rr, &e, "gravity (m/s^2)") && strcmp(e.msg, ev.msg) == 0);
    }
    (void)rr; /* (a pile without floor load under gravity may be refused: not this check's subject) */
    const double q = gw_layer_settled_load_ratio(&s, &lp);
    EXPECT(bad ? isnan(q) : !isnan(q));
    EXPECT((gw_layer_impact_fall_check(&ip, grav, &e) != GW_OK) == bad);
    if (bad)
        EXPECT(refused(GW_EINVAL, &e, "gravity (m/s^2)"));
    EXPECT((gw_layer_impact_gap_check(&s, &ip, grav, &e) != GW_OK) == bad);
    if (bad)
        EXPECT(refused(GW_EINVAL, &e, "gravity (m/s^2)"));
    return 0;
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/gw_hostile46.XXXXXX");
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    static const child_row calls[] = {
        {"gw_layer_impact_check", c_check},
        {"gw_layer_impact", c_run},
        {"gw_layer_impact_settled_check", c_settled},
        {"gw_layer_settled_load_ratio", c_ratio},
        {"gw_layer_sample_porosity and gw_layer_impact_dem_dt", c_porosity_dt},
        {"gw_layer_sample_pile_hash", c_pile_hash},
        {"gw_layer_sample_write", c_write},
    };
    int nfail = 0, ncases = 0;
    for (size_t r = 0; r < NROWS; r++)
        for (size_t c = 0; c < sizeof calls / sizeof calls[0]; c++) {
            row = &rows[r];
            child_casef(calls[c].fn, &nfail, &ncases, "%s: %s", rows[r].label, calls[c].label);
        }
    static const child_row mem[] = {
        {"gw_chain_memory_check: n = -1", c_mem_neg1},
        {"gw_chain_memory_check: n = 0", c_mem_zero},
        {"gw_chain_memory_check: n = INT_MIN", c_mem_intmin},
        {"gw_chain_memory_check: n = 6e7", c_mem_6e7},
        {"gw_chain_memory_check: n = 1 (control)", c_mem_one},
        {"gw_chain_memory_check: n = 2e6 (control)", c_mem_2e6},
        {"gw_chain_memory_check: n = 3e6, the memory bound (control)", c_mem_3e6},
    };
    for (size_t k = 0; k < sizeof mem / sizeof mem[0]; k++)
        child_case(mem[k].label, mem[k].fn, &nfail, &ncases);
    for (size_t k = 0; k < sizeof gravities / sizeof gravities[0]; k++) {
        grav = gravities[k];
        child_casef(c_gravity, &nfail, &ncases, "the impact's gravity %g at the settling, rest and gap checks", grav);
    }
#if GW_HAVE_HDF5
    static const char *const exts[] = {".txt", ".h5"};
#else
    static const char *const exts[] = {".txt"};
#endif
    for (size_t x = 0; x < sizeof exts / sizeof exts[0]; x++)
        for (size_t k = 0; k < NHDRS; k++) {
            hrow = &hdrs[k], hext = exts[x];
            child_casef(c_header, &nfail, &ncases, "gw_layer_sample_write (%s) header: %s", hext, hdrs[k].label);
        }
    rmdir(dir);
    return child_cases_end(nfail, ncases);
}
