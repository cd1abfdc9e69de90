/*
 * own_names.c: a program outside the project, linked statically against an
 * installed libgranwave.a (tests/test_install_api.sh), that defines its own
 * global functions under names the library uses inside itself: chain_blown_up,
 * chain_steps_check and gw_sun_rhs lie on the path of a column collision,
 * layer_snapshot on the layer's. Their signatures here are the program's own,
 * not the library's.
 *
 * The archive's internal symbols are local (docs/library.md, "Symbols"), so the
 * program links (it did not: "multiple definition of chain_blown_up") and each
 * side calls its own functions. Checks (exit status = number of failures):
 *  - N = 1 at v_imp = 0.3 m/s (tolerances 1e-12) on the default steel wall:
 *    F_max against the closed form F_max(1) = K d_max^(3/2) (F.13) to 1e-6;
 *  - the library called none of the program's functions (their counters are
 *    zero after the collision), and the program reaches its own (each answers
 *    its own value).
 * Units: SI (N, s, m/s).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <granwave.h>

static int failures;
static int calls; /* calls of the functions below */

static void check(int ok, const char *what)
{
    printf("%s: %s\n", ok ? "PASS" : "FAIL", what);
    failures += !ok;
}

/* The program's own functions: global, under the library's internal names. */
double chain_blown_up(double x);
const char *chain_steps_check(void);
long gw_sun_rhs(long a, long b);
int layer_snapshot(int k);

double chain_blown_up(double x)
{
    calls++;
    return 2.0 * x;
}

const char *chain_steps_check(void)
{
    calls++;
    return "own";
}

long gw_sun_rhs(long a, long b)
{
    calls++;
    return a * b;
}

int layer_snapshot(int k)
{
    calls++;
    return k + 1;
}

int main(void)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = 1;
    p.v_imp = 0.3;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.sp.rtol = 1e-12;
    o.sp.atol = 1e-12;
    gw_chain *c = NULL;
    gw_chain_result r;
    memset(&r, 0, sizeof r);
    gw_err err = {{0}};
    int rc = gw_chain_create(&p, &c, &err);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, &o, &r, &err);
    gw_chain_free(c);
    check(rc == GW_OK, rc == GW_OK ? "N = 1 collision runs" : err.msg);
    double f1 = gw_chain_fmax1(p.mass, p.kwall, p.v_imp);
    double rel = fabs(r.f_max - f1) / f1;
    printf("N = 1: F_max %.10g N, closed form %.10g N (rel %.2g)\n", r.f_max, f1, rel);
    check(rc == GW_OK && rel <= 1e-6, "N = 1: F_max = closed form (F.13) to 1e-6");
    gw_chain_result_free(&r);
    check(calls == 0, "the library called none of the program's functions");

    check(chain_blown_up(1.5) == 3.0 && strcmp(chain_steps_check(), "own") == 0 && gw_sun_rhs(6, 7) == 42 &&
              layer_snapshot(41) == 42 && calls == 4,
          "the program calls its own chain_blown_up, chain_steps_check, gw_sun_rhs, layer_snapshot");
    return failures;
}
