/*
 * colliding.c: a program outside the project, built against an installed
 * libgranwave (tests/test_install.sh), that runs column collisions
 * (physics.md 1.1, eq. F.11) for N = 1 and N = 7 steel beads at v_imp = 0.3 m/s
 * on the default steel wall.
 *
 * Checks (exit status = number of failures):
 *  - the library's version equals the expected project version (argv[1]) and
 *    the headers' GW_VERSION, and its numbers equal GW_VERSION_MAJOR/MINOR/PATCH;
 *  - N = 1: F_max against the closed form F_max(1) = K d_max^(3/2) (F.13) to
 *    1e-6 relative (the integration at rtol = atol = 1e-12 is ~1e-9 accurate; a
 *    wrong exponent or constant is off by orders of magnitude more);
 *  - N = 7 on a rigid wall (K > K_c): F_max within 5 % of the N = 1 value
 *    (physics.md 1.3, the paper's bound; the soft-wall growth is larger), and
 *    bead 7 leaves faster than v_imp (the paper's detachment finding).
 * Units: SI (N, s, m/s).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <granwave.h>

static int failures;

static void check(int ok, const char *what)
{
    printf("%s: %s\n", ok ? "PASS" : "FAIL", what);
    failures += !ok;
}

static int collide(int n, double v, gw_chain_result *r)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = n;
    p.v_imp = v;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.sp.rtol = 1e-12;
    o.sp.atol = 1e-12;
    gw_chain *c = NULL;
    gw_err err = {{0}};
    int rc = gw_chain_create(&p, &c, &err);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, &o, r, &err);
    gw_chain_free(c);
    if (rc != GW_OK)
        printf("FAIL: N = %d: %s (%s)\n", n, err.msg, gw_strerror(rc));
    return rc;
}

int main(int argc, char **argv)
{
    const char *expect = argc > 1 ? argv[1] : GW_VERSION;
    char nums[64];
    snprintf(nums, sizeof nums, "%d.%d.%d", gw_version_major(), gw_version_minor(), gw_version_patch());
    printf("library %s, headers %s, expected %s\n", gw_version(), GW_VERSION, expect);
    check(strcmp(gw_version(), expect) == 0, "library version = project version");
    check(strcmp(GW_VERSION, expect) == 0, "header version = project version");
    check(strcmp(nums, expect) == 0, "major.minor.patch = version string");
    check(gw_version_major() == GW_VERSION_MAJOR && gw_version_minor() == GW_VERSION_MINOR &&
              gw_version_patch() == GW_VERSION_PATCH,
          "numbers = GW_VERSION_MAJOR/MINOR/PATCH");

    const double v = 0.3;
    gw_chain_params d = gw_chain_params_default();
    double f1 = gw_chain_fmax1(d.mass, d.kwall, v);
    gw_chain_result r1, r7;
    memset(&r1, 0, sizeof r1);
    memset(&r7, 0, sizeof r7);
    if (collide(1, v, &r1) != GW_OK || collide(7, v, &r7) != GW_OK) {
        gw_chain_result_free(&r1);
        gw_chain_result_free(&r7);
        return 1 + failures;
    }
    double rel = fabs(r1.f_max - f1) / f1;
    printf("N = 1: F_max %.10g N, closed form %.10g N (rel %.2g), tau_1 %.6g us\n", r1.f_max, f1, rel,
           r1.tau_n * 1e6);
    printf("N = 7: F_max %.10g N, tau_7 %.6g us, top bead %.6g m/s\n", r7.f_max, r7.tau_n * 1e6,
           r7.final_v[6]);
    check(rel <= 1e-6, "N = 1: F_max = closed form (F.13) to 1e-6");
    check(d.kwall > gw_chain_kc(d.k), "steel wall is rigid (K > K_c, F.22)");
    check(fabs(r7.f_max - r1.f_max) / r1.f_max < 0.05, "N = 7: F_max within 5 % of N = 1 (rigid wall)");
    check(-r7.final_v[6] > v, "N = 7: the top bead leaves faster than v_imp");
    gw_chain_result_free(&r1);
    gw_chain_result_free(&r7);
    return failures;
}
