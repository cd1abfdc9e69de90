/*
 * test_library_hostile40.c: the fortieth hostile pass over the library's C
 * interface (docs/library.md "The contract of every call"), at the calls the
 * earlier passes (test_hostile_api, test_null_calls, test_library_hostile,
 * test_library_hostile38, test_library_hostile39) did not reach: the pile's
 * hash, a stats analysis filled by hand, the contact laws' closed forms, the
 * names of enum values, the falcon study's speeds and the messages of checks
 * given no name. What the pass found, each checked here:
 *   - gw_layer_sample_pile_hash read a sample's NULL y or r (SIGSEGV), hashed
 *     a body id outside [0, n) as a body of its own (the hash of the sample
 *     with that disc's own id) and springs counted without their array as no
 *     springs; gw_layer_impact_check took springs counted without their array;
 *   - gw_stats_json and gw_stats_write_files read an analysis counting
 *     diagrams, groups, walls or binary rows without their arrays (SIGSEGV);
 *   - gw_thornton_loading_work read a NULL t (SIGSEGV, where
 *     gw_thornton_force gives NaN), and both, with gw_layer_law_force,
 *     _energy, _overlap and _contact_radius (SIGSEGV on NULL), gave 0 for a
 *     NaN overlap, no contact;
 *   - gw_layer_until_name, gw_layer_mass_law_name and gw_layer_clump_mass_name
 *     named a value outside their enum "rebound", "disc (unit thickness)" and
 *     "sum";
 *   - gw_layer_kt_factor of a negative radius was negative (K_n NaN there),
 *     gw_chain_kc of a negative k and gw_chain_disp_kappa of a negative f0
 *     negative stiffnesses;
 *   - gw_chain_falcon_speeds took a NaN gravity as Earth's with GW_OK, an
 *     infinite one as speeds of inf m/s refused "within a relative -nan" of
 *     each other, and a negative count as "vimp and heights both empty";
 *   - gw_solver_tolerances_check, gw_out_names_check and
 *     gw_outset_check_input given no name wrote "(null): ..."; gw_fnv1a64_file
 *     with h NULL read the file and said "read failed" (GW_EIO);
 *   - the sweep journal's scan, open and resume check, gw_sweep_write_table
 *     and gw_sweep_out_inputs_check read a gw_sweep_config of 33 keys or
 *     inputs counted without their array (SIGSEGV) and took a key of no
 *     values or a case count not the grid's (GW_OK), where the sweep's run
 *     and case calls refuse them (gw_sweep_config_check, the thirty-ninth
 *     pass);
 *   - gw_layer_sample_porosity left a disc of a NaN or infinite coordinate or
 *     radius, or of r <= 0, out and gave the porosity of the others, and
 *     gw_layer_impact_dem_dt the step of the others for a NaN radius.
 * Each refusal has a control: the valid call next to it gives its value
 * (the same hash with a body per disc given or not, work = the integral of
 * the force, the fall speed sqrt(2 g h), the scalings of the closed forms).
 * Every case runs in its own child process (test_child.h): a crash, a
 * sanitizer report or anything printed fails that case.
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

/* ---- the pile's hash of a sample built in memory ---- */

static int pile_hash_hand(void)
{
    gw_layer_sample s = test_three_discs();
    const unsigned long long h0 = gw_layer_sample_pile_hash(&s);
    EXPECT(h0 != 0);
    s.y = NULL; /* SIGSEGV before */
    EXPECT(gw_layer_sample_pile_hash(&s) == 0);
    s = test_three_discs();
    s.r = NULL;
    EXPECT(gw_layer_sample_pile_hash(&s) == 0);
    s = test_three_discs();
    int bad[3] = {0, 99, 2}; /* hashed as {0, 1, 2} before: h0 */
    s.body = bad;
    EXPECT(gw_layer_sample_pile_hash(&s) == 0);
    bad[1] = -5;
    EXPECT(gw_layer_sample_pile_hash(&s) == 0);
    int own[3] = {0, 1, 2};
    s.body = own; /* control: a body per disc is the pile without a body column */
    EXPECT(gw_layer_sample_pile_hash(&s) == h0);
    s = test_three_discs();
    s.n_springs = 4; /* no array: h0 before, the pile without springs */
    EXPECT(gw_layer_sample_pile_hash(&s) == 0);
    s.n_springs = -4;
    EXPECT(gw_layer_sample_pile_hash(&s) == 0);
    gw_layer_spring sp[1] = {{1, 7, 1e-7}}; /* particle 7 of 3 (skipped before) */
    s.springs = sp, s.n_springs = 1;
    EXPECT(gw_layer_sample_pile_hash(&s) == 0);
    sp[0].b = GW_LAYER_SPRING_BOTTOM; /* control: a spring on the floor is another pile, hashed */
    const unsigned long long hs = gw_layer_sample_pile_hash(&s);
    EXPECT(hs != 0 && hs != h0);
    sp[0].u = 2e-7;
    EXPECT(gw_layer_sample_pile_hash(&s) != hs && gw_layer_sample_pile_hash(&s) != 0);
    /* the impact's check: springs counted without their array (taken before) */
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    gw_err e = {{0}};
    s = test_three_discs();
    s.n_springs = 2;
    EXPECT(refused(gw_layer_impact_check(&s, &ip, &e), &e, "n_springs = 2 with springs NULL"));
    s.n_springs = 0;
    EXPECT(gw_layer_impact_check(&s, &ip, &e) == GW_OK);
    return 0;
}

/* gw_layer_sample_porosity left such a disc out of the window's test and gave
 * the porosity of the others (0.548 for the three discs' 0.322) */
static int porosity_bad_disc(void)
{
    double x[3] = {0.3, 0.5, 0.7}, y[3] = {0.1, 0.1, 0.1}, r[3] = {0.1, 0.1, 0.1};
    gw_layer_sample s = test_three_discs();
    s.x = x, s.y = y, s.r = r;
    const double p = gw_layer_sample_porosity(&s);
    EXPECT(p > 0 && p < 1);
    const double bad[] = {NAN, INFINITY};
    for (size_t k = 0; k < 2; k++) {
        x[1] = bad[k];
        EXPECT(isnan(gw_layer_sample_porosity(&s)));
        x[1] = 0.5, y[1] = bad[k];
        EXPECT(isnan(gw_layer_sample_porosity(&s)));
        y[1] = 0.1, r[1] = bad[k];
        EXPECT(isnan(gw_layer_sample_porosity(&s)));
        r[1] = 0.1;
    }
    /* the impact's step likewise: a NaN radius gave the others' 5e-6 s */
    gw_layer_params lp = gw_layer_params_default();
    gw_layer_impact_params ip = gw_layer_impact_params_default();
    const double dt = gw_layer_impact_dem_dt(&s, &lp, &ip);
    EXPECT(dt > 0);
    r[1] = NAN;
    EXPECT(isnan(gw_layer_impact_dem_dt(&s, &lp, &ip)));
    r[1] = INFINITY;
    EXPECT(isnan(gw_layer_impact_dem_dt(&s, &lp, &ip)));
    r[1] = 1e-3; /* control: a smaller disc, a shorter step */
    EXPECT(gw_layer_impact_dem_dt(&s, &lp, &ip) < dt);
    r[1] = -0.1;
    EXPECT(isnan(gw_layer_sample_porosity(&s)));
    r[1] = 0;
    EXPECT(isnan(gw_layer_sample_porosity(&s)));
    r[1] = 0.1; /* control: the same discs, the same porosity; one raised, another window and porosity */
    EXPECT(gw_layer_sample_porosity(&s) == p);
    y[1] = 0.3;
    const double q = gw_layer_sample_porosity(&s);
    EXPECT(q > 0 && q < 1 && q != p);
    return 0;
}

/* ---- a stats analysis filled by hand ---- */

static int stats_analysis_hand(void)
{
    gw_err e = {{0}};
    char dir[] = "/tmp/gw_hostile40.XXXXXX", out[64], path[128];
    EXPECT(mkdtemp(dir) != NULL);
    snprintf(out, sizeof out, "%s/o", dir);
    struct stat st;
    static const struct {
        int ndia, ngroups, nwalls, nbin;
        const char *named;
    } bad[] = {{3, 0, 0, 0, "ndia 3"}, {0, 2, 0, 0, "2 groups without their array"},
               {0, 0, 1, 0, "nwalls 1"}, {0, 0, 0, 2, "nbin 2"}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        gw_stats_analysis A;
        memset(&A, 0, sizeof A);
        A.ndia = bad[k].ndia, A.gs.n = bad[k].ngroups, A.nwalls = bad[k].nwalls, A.nbin = bad[k].nbin;
        EXPECT(gw_stats_json(&A, 1) == NULL && gw_stats_json(&A, 0) == NULL); /* SIGSEGV before */
        EXPECT(refused(gw_stats_write_files(&A, out, &e), &e, bad[k].named));
        EXPECT(stat(out, &st) != 0); /* nothing made */
    }
    /* a panel naming a group the analysis has not */
    gw_stats_analysis A;
    memset(&A, 0, sizeof A);
    gw_stats_panel D;
    memset(&D, 0, sizeof D);
    int groups[1] = {5};
    D.groups = groups, D.ngroups = 1;
    A.dia = &D, A.ndia = 1;
    EXPECT(gw_stats_json(&A, 0) == NULL);
    EXPECT(refused(gw_stats_write_files(&A, out, &e), &e, "group 5 is not one of the 0 groups"));
    /* control: a zeroed analysis is an empty one, written whole */
    memset(&A, 0, sizeof A);
    cJSON *j = gw_stats_json(&A, 1);
    EXPECT(j != NULL);
    char *txt = cJSON_PrintUnformatted(j);
    EXPECT(txt && strstr(txt, "\"groups\":[]") && strstr(txt, "\"diagrams\":[]"));
    free(txt);
    cJSON_Delete(j);
    EXPECT(gw_stats_write_files(&A, out, &e) == GW_OK);
    static const char *const files[] = {"groups.csv", "convergence.csv", "binary.csv", "walls.csv", "diagram.csv",
                                        "boundary_fit.json"};
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
        snprintf(path, sizeof path, "%s/%s", out, files[k]);
        EXPECT(stat(path, &st) == 0);
        unlink(path);
    }
    rmdir(out);
    rmdir(dir);
    return 0;
}

/* ---- contact laws: NULL and NaN overlaps ---- */

static int thornton_nan(void)
{
    gw_thornton t;
    gw_thornton_init(&t, 1e11, 1e-3, 1e9);
    EXPECT(isnan(gw_thornton_loading_work(NULL, 1e-6))); /* SIGSEGV before */
    EXPECT(isnan(gw_thornton_loading_work(&t, NAN)));    /* 0 J before */
    double k = 0, dp = 0, u = 0;
    EXPECT(isnan(gw_thornton_force(&t, NAN, 0, &k, &dp, &u)) && isnan(k) && isnan(dp) && isnan(u)); /* 0 N */
    EXPECT(isnan(gw_thornton_force(&t, 1e-6, NAN, NULL, NULL, NULL)));
    /* control: the work of loading is the integral of the loading force, on
     * both sides of the yield overlap d_y (trapezoid, 20000 steps) */
    EXPECT(gw_thornton_loading_work(&t, -1) == 0);
    const double dmax[2] = {0.5 * t.d_y, 6 * t.d_y};
    for (int c = 0; c < 2; c++) {
        enum { M = 20000 };
        double w = 0, f0 = 0;
        for (int i = 1; i <= M; i++) {
            const double d = dmax[c] * i / M, f1 = gw_thornton_force(&t, d, d, NULL, NULL, NULL);
            w += 0.5 * (f0 + f1) * dmax[c] / M;
            f0 = f1;
        }
        const double wl = gw_thornton_loading_work(&t, dmax[c]);
        EXPECT(wl > 0 && fabs(w - wl) < 1e-6 * wl);
    }
    return 0;
}

static int layer_law_nan(void)
{
    EXPECT(isnan(gw_layer_law_force(NULL, 1e-6, NULL))); /* SIGSEGV before, each */
    EXPECT(isnan(gw_layer_law_energy(NULL, 1e-6)));
    EXPECT(isnan(gw_layer_law_overlap(NULL, 1)));
    EXPECT(isnan(gw_layer_law_contact_radius(NULL, 1e-6)));
    const gw_material *steel = gw_material_find("steel");
    EXPECT(steel != NULL);
    gw_layer_law *l = NULL;
    gw_err e = {{0}};
    EXPECT(gw_layer_law_create(4e-3, steel, 1.0e-3, 3.0e9, 0.38, &l, &e) == GW_OK);
    double k = 0;
    EXPECT(isnan(gw_layer_law_force(l, NAN, &k)) && isnan(k)); /* 0 N before, each */
    EXPECT(isnan(gw_layer_law_energy(l, NAN)) && isnan(gw_layer_law_overlap(l, NAN)) &&
           isnan(gw_layer_law_contact_radius(l, NAN)));
    /* control: the overlap of the force at d is d, the energy its integral */
    const double d = 2e-6, f = gw_layer_law_force(l, d, NULL);
    EXPECT(f > 0 && fabs(gw_layer_law_overlap(l, f) - d) < 1e-6 * d);
    enum { M = 4000 };
    double w = 0, f0 = 0;
    for (int i = 1; i <= M; i++) {
        const double f1 = gw_layer_law_force(l, d * i / M, NULL);
        w += 0.5 * (f0 + f1) * d / M;
        f0 = f1;
    }
    const double el = gw_layer_law_energy(l, d);
    EXPECT(el > 0 && fabs(w - el) < 1e-4 * el);
    EXPECT(gw_layer_law_force(l, -1e-6, NULL) == 0 && gw_layer_law_energy(l, 0) == 0);
    gw_layer_law_free(l);
    return 0;
}

/* ---- enum names and closed forms off their domain ---- */

static int enum_names(void)
{
    /* "rebound", "disc (unit thickness)", "sum" before */
    EXPECT(strcmp(gw_layer_until_name(9), "unknown") == 0 && strcmp(gw_layer_until_name(-1), "unknown") == 0);
    EXPECT(strcmp(gw_layer_mass_law_name(7), "unknown") == 0);
    EXPECT(strcmp(gw_layer_clump_mass_name(-1), "unknown") == 0 && gw_layer_clump_mass_parse("unknown") == -1);
    /* control: each value's name, and back */
    EXPECT(gw_layer_until_parse(gw_layer_until_name(GW_LAYER_UNTIL_VERDICT)) == GW_LAYER_UNTIL_VERDICT &&
           gw_layer_until_parse(gw_layer_until_name(GW_LAYER_UNTIL_REBOUND)) == GW_LAYER_UNTIL_REBOUND);
    EXPECT(gw_layer_clump_mass_parse(gw_layer_clump_mass_name(GW_LAYER_CLUMP_MASS_UNION)) ==
           GW_LAYER_CLUMP_MASS_UNION);
    EXPECT(strcmp(gw_layer_mass_law_name(GW_LAYER_MASS_SPHERE), "sphere") == 0 &&
           strcmp(gw_layer_mass_law_name(GW_LAYER_MASS_DISC), "disc (unit thickness)") == 0);
    return 0;
}

static int closed_forms(void)
{
    gw_layer_params lp = gw_layer_params_default();
    EXPECT(isnan(gw_layer_kt_factor(&lp, -1e-3)) && isnan(gw_layer_kn(&lp, -1e-3))); /* k_t < 0 before */
    EXPECT(isnan(gw_chain_kc(-1e9)));                                                /* K_c < 0 before */
    EXPECT(isnan(gw_chain_disp_kappa(1e10, -1)) && isnan(gw_chain_disp_kappa(-1e10, 1)));
    /* control: k_t ~ R_p^(1/3), K_n ~ R_p^(1/2), K_c ~ k, kappa ~ f0^(1/3) */
    const double kt = gw_layer_kt_factor(&lp, 1e-3), kn = gw_layer_kn(&lp, 1e-3);
    EXPECT(kt > 0 && fabs(gw_layer_kt_factor(&lp, 8e-3) / kt - 2) < 1e-12);
    EXPECT(kn > 0 && fabs(gw_layer_kn(&lp, 4e-3) / kn - 2) < 1e-12);
    EXPECT(gw_chain_kc(1e9) > 0 && fabs(gw_chain_kc(2e9) / gw_chain_kc(1e9) - 2) < 1e-12);
    const double ka = gw_chain_disp_kappa(1e10, 1);
    EXPECT(ka > 0 && fabs(gw_chain_disp_kappa(1e10, 8) / ka - 2) < 1e-12);
    return 0;
}

/* ---- the falcon study's speeds ---- */

static int falcon_speeds(void)
{
    gw_err e = {{0}};
    double v[4], h[4];
    const double vi[1] = {0.3}, hm[1] = {5.1};
    /* NaN: Earth's with GW_OK before; inf: "within a relative -nan" */
    EXPECT(refused(gw_chain_falcon_speeds(vi, 1, hm, 1, NAN, v, h, &e), &e, "gravity: nan"));
    EXPECT(refused(gw_chain_falcon_speeds(vi, 1, hm, 1, INFINITY, v, h, &e), &e, "gravity: inf"));
    EXPECT(refused(gw_chain_falcon_speeds(vi, 1, hm, 1, -9.81, v, h, &e), &e, "gravity: -9.81"));
    /* "vimp and heights both empty" before */
    EXPECT(refused(gw_chain_falcon_speeds(vi, -1, hm, 1, 0, v, h, &e), &e, "n_vimp = -1"));
    EXPECT(refused(gw_chain_falcon_speeds(vi, 1, hm, -2, 0, v, h, &e), &e, "n_heights = -2"));
    /* control: the fall sqrt(2 g h), Earth's at 0 */
    EXPECT(gw_chain_falcon_speeds(vi, 1, hm, 1, 0, v, h, &e) == GW_OK);
    EXPECT(v[0] == 0.3 && isnan(h[0]) && h[1] == 5.1 && fabs(v[1] - sqrt(2 * GW_CHAIN_G_EARTH * 5.1e-3)) < 1e-15);
    EXPECT(gw_chain_falcon_speeds(vi, 1, hm, 1, 20, v, h, &e) == GW_OK);
    EXPECT(fabs(v[1] - sqrt(2 * 20 * 5.1e-3)) < 1e-15);
    return 0;
}

/* ---- a sweep config filled by hand, at the journal and the table ---- */

static const char cfg_text[] = "[sweep]\nmodel = chain\n[grid]\nn = 1:3\nvimp = 0.1, 0.2\n[params]\nt-max = 1e-3\n";

/* the journal's scan, open and resume check, the table's writer and the
 * outputs' check read a config of 33 keys or inputs counted without their
 * array past its struct or through NULL (SIGSEGV), and took a key of no
 * values or a case count not the grid's (GW_OK; the table "lost rows") */
static int sweep_journal_hand(void)
{
    int nm;
    const gw_sweep_model *const *ms = gw_sweep_models(&nm);
    char dir[] = "/tmp/gw_hostile40s.XXXXXX", path[64];
    EXPECT(mkdtemp(dir) != NULL);
    for (int mode = 0; mode < 5; mode++) {
        gw_sweep_config cfg;
        const gw_sweep_model *m = NULL;
        gw_err e = {{0}};
        memset(&cfg, 0, sizeof cfg);
        EXPECT(gw_sweep_config_read_string(cfg_text, "t", ms, nm, &cfg, &m, &e) == GW_OK && cfg.ncases == 6);
        const int ng = cfg.ngrid, nv = cfg.grid[1].nvalues;
        const char *named = "";
        if (mode == 0)
            cfg.ngrid = GW_SWEEP_MAX_KEYS + 1, named = "33 grid keys";
        else if (mode == 1)
            cfg.grid[1].nvalues = 0, named = "has 0 values";
        else if (mode == 2)
            cfg.ninputs = 3, named = "3 inputs and no array";
        else if (mode == 3)
            cfg.ncases = 7, named = "ncases 7";
        char done[8] = {0};
        long nd = 5;
        int fd = 7, dfd = 7, ex = 0, th = 0;
        size_t torn = 0;
        if (mode < 4) {
            EXPECT(refused(gw_sweep_journal_scan(dir, &cfg, done, &nd, &e), &e, named) && nd == 0);
            EXPECT(refused(gw_sweep_journal_open(dir, &cfg, done, &nd, &fd, &e), &e, named) && fd == -1);
            EXPECT(refused(gw_sweep_journal_open_at(dir, &cfg, done, &nd, &fd, &dfd, &e), &e, named) && fd == -1);
            EXPECT(refused(gw_sweep_journal_resume_check(dir, &cfg, done, &nd, &ex, &torn, &th, &e), &e, named));
            EXPECT(refused(gw_sweep_out_inputs_check(dir, &cfg, &e), &e, named));
            EXPECT(refused(gw_sweep_write_table(dir, &cfg, m, &e), &e, named));
            snprintf(path, sizeof path, "%s/journal.csv", dir);
            struct stat st;
            EXPECT(stat(path, &st) != 0); /* nothing made */
        } else { /* control: the config as read scans an empty directory */
            EXPECT(gw_sweep_journal_scan(dir, &cfg, done, &nd, &e) == GW_OK && nd == 0);
            EXPECT(gw_sweep_out_inputs_check(dir, &cfg, &e) == GW_OK);
        }
        cfg.ngrid = ng, cfg.grid[1].nvalues = nv, cfg.ninputs = 0;
        gw_sweep_config_free(&cfg);
    }
    rmdir(dir);
    return 0;
}

/* ---- messages of checks given no name, a hash with nowhere to go ---- */

static int unnamed_messages(void)
{
    gw_err e = {{0}};
    /* "(null): ..." before, each */
    EXPECT(refused(gw_solver_tolerances_check(-1, 1e-9, NULL, NULL, &e), &e, "rtol: -1 is outside"));
    EXPECT(refused(gw_solver_tolerances_check(1e-6, -1, NULL, NULL, &e), &e, "atol: -1 is outside"));
    EXPECT(refused(gw_solver_tolerances_check(1e-6, -1, "r", "--atol", &e), &e, "--atol: -1")); /* control */
    char dir[] = "/tmp/gw_hostile40n.XXXXXX", sub[64], file[64];
    EXPECT(mkdtemp(dir) != NULL);
    snprintf(sub, sizeof sub, "%s/a.csv", dir);
    EXPECT(mkdir(sub, 0700) == 0);
    const char *const names[] = {"a.csv", NULL};
    EXPECT(refused(gw_out_names_check(dir, names, NULL, &e), &e, "output: '"));
    EXPECT(strncmp(e.msg, "output: ", 8) == 0);
    rmdir(sub);
    FILE *fp = fopen(sub, "w");
    EXPECT(fp != NULL);
    fputs("abc\n", fp);
    fclose(fp);
    EXPECT(refused(gw_outset_check_input(dir, names, sub, NULL, &e), &e, "is the file this run writes"));
    EXPECT(strncmp(e.msg, "input: ", 7) == 0);
    EXPECT(gw_out_names_check(dir, names, NULL, &e) == GW_OK); /* control: a regular file there */
    /* the hash: "read failed" (GW_EIO) before */
    EXPECT(refused(gw_fnv1a64_file(sub, "x", NULL, &e), &e, "h is NULL"));
    unsigned long long h = 0;
    EXPECT(gw_fnv1a64_file(sub, "x", &h, &e) == GW_OK && h == gw_fnv1a64(GW_FNV1A64_INIT, "abc\n", 4));
    snprintf(file, sizeof file, "%s", sub);
    unlink(file);
    rmdir(dir);
    return 0;
}

/* ---- the lead's: a method no backend runs, a pluviation's warning at a NaN t_max ---- */

static int method_used_and_make_warnings(void)
{
    /* "bdf" for no backend, "erk" for cvode with erk, before */
    EXPECT(strcmp(gw_solver_method_used(NULL, GW_METHOD_DEFAULT), "unknown") == 0);
    EXPECT(strcmp(gw_solver_method_used(gw_solver_cvode, GW_ARKODE_ERK), "unknown") == 0);
    EXPECT(strcmp(gw_solver_method_used(gw_solver_arkode, GW_CVODE_ADAMS), "unknown") == 0);
    EXPECT(strcmp(gw_solver_method_used(gw_solver_cvode, 99), "unknown") == 0);
    /* controls: each backend's own */
    EXPECT(strcmp(gw_solver_method_used(gw_solver_cvode, GW_METHOD_DEFAULT), "bdf") == 0);
    EXPECT(strcmp(gw_solver_method_used(gw_solver_cvode, GW_CVODE_ADAMS), "adams") == 0);
    EXPECT(strcmp(gw_solver_method_used(gw_solver_arkode, GW_METHOD_DEFAULT), "erk") == 0);
    EXPECT(strcmp(gw_solver_method_used(gw_solver_arkode, GW_ARKODE_DIRK), "dirk") == 0);
    EXPECT(strcmp(gw_solver_method_used(gw_solver_rk4, GW_CVODE_BDF), "none") == 0);
    /* an unsettled pluviation at t_max NaN or inf: "t-max = nan s" with GW_OK before */
    gw_layer_make_result r;
    memset(&r, 0, sizeof r);
    r.t_judge = 0.1, r.ke_final = 1;
    char *list = NULL;
    EXPECT(gw_layer_make_result_warnings(&r, NAN, NULL, &list) == GW_EINVAL && list == NULL);
    EXPECT(gw_layer_make_result_warnings(&r, INFINITY, NULL, &list) == GW_EINVAL && list == NULL);
    EXPECT(gw_layer_make_result_warnings(&r, 0.05, NULL, &list) == GW_OK && list &&
           strstr(list, "t-max = 0.05 s ends before the settling is judged")); /* control */
    free(list);
    return 0;
}

int main(void)
{
    static const child_row cases[] = {
        {"gw_layer_sample_pile_hash/gw_layer_impact_check: samples filled by hand", pile_hash_hand},
        {"gw_layer_sample_porosity/gw_layer_impact_dem_dt: a disc of NaN or infinite values, or r <= 0",
         porosity_bad_disc},
        {"gw_stats_json/gw_stats_write_files: analyses filled by hand", stats_analysis_hand},
        {"gw_thornton_force/_loading_work: NULL and NaN overlaps", thornton_nan},
        {"gw_layer_law_force/_energy/_overlap/_contact_radius: NULL and NaN", layer_law_nan},
        {"gw_layer_until/mass_law/clump_mass_name: values outside the enum", enum_names},
        {"gw_layer_kt_factor/gw_chain_kc/gw_chain_disp_kappa: off their domain", closed_forms},
        {"gw_chain_falcon_speeds: NaN and infinite gravity, negative counts", falcon_speeds},
        {"gw_solver_tolerances_check/gw_out_names_check/gw_outset_check_input/gw_fnv1a64_file", unnamed_messages},
        {"gw_sweep_journal_scan/_open/_open_at/_resume_check/gw_sweep_write_table/gw_sweep_out_inputs_check: "
         "configs filled by hand",
         sweep_journal_hand},
        {"gw_solver_method_used: no backend, a variant not the backend's; gw_layer_make_result_warnings: NaN t_max",
         method_used_and_make_warnings},
    };
    return child_cases_run(cases, sizeof cases / sizeof cases[0]);
}
