/*
 * bench_tts.c: time to solution of the 40-bead column at a fixed accuracy, the
 * granwave side of bench/run_peers.sh. Never a pass/fail test.
 *
 * Case: N = 40 steel beads (gw_chain_params_default: k, K, m), v_imp = 0.3 m/s,
 * rigid steel wall, no damping (docs/physics.md 1.1, eq. F.11). Observables: the
 * peak wall force F_max (F.13) and the contact duration tau_N (F.4), from
 * gw_chain_collide, which locates every contact change as a root and restarts
 * the integrator there.
 *
 * Reference: RK4 with dt = tc/6400 (tc = (m/k)^(2/5) v_imp^(-1/5)); its own
 * error is estimated against dt = tc/3200 and printed. For each backend the
 * setting is tightened (rk4: dt = tc/M with M growing by sqrt 2; adaptive:
 * rtol = atol falling by sqrt 10, from tc/8 and 1e-4) until F_max and tau_N are both within --acc
 * (default 1e-6) relative of the reference; the time of that first passing
 * setting (best of --reps runs of gw_chain_collide) is the time to solution.
 *
 * Output: a human-readable table, plus machine-readable lines
 *   REF <f_max N> <tau_n s> <t_end s> <ref self-error>
 *   PARAMS <k N/m^1.5> <K N/m^1.5> <m kg> <v_imp m/s> <R m>
 *   TTS <backend> <setting> <ms> <F_max rel err> <tau_N rel err>
 * that bench/run_peers.sh parses (t_end is where gw_chain_collide stops: every
 * contact open; peers integrate to the same time).
 * gw_chain_collide samples the state every dt_out (default tau_1/200) and lands
 * on every sample, so rk4's effective step is min(dt, dt_out); --dt-out S sets
 * a different sampling interval (s) for the timed runs.
 * Usage: bench_tts [--acc A] [--reps R] [--dt-out S]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"

static int collide(const gw_chain *c, const gw_chain_run_opts *o, gw_chain_result *r)
{
    gw_err err;
    int rc = gw_chain_collide(c, o, r, &err);
    if (rc != GW_OK)
        fprintf(stderr, "bench_tts: %s\n", err.msg);
    return rc;
}

int main(int argc, char **argv)
{
    double acc = 1e-6, dt_out = 0;
    int reps = 5;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--acc"))
            acc = atof(argv[i + 1]);
        else if (!strcmp(argv[i], "--reps"))
            reps = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--dt-out"))
            dt_out = atof(argv[i + 1]);
        else {
            fprintf(stderr, "bench_tts: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    if (!(acc > 0) || reps < 1) {
        fprintf(stderr, "bench_tts: bad --acc or --reps\n");
        return 2;
    }
    gw_chain_params p = gw_chain_params_default();
    p.n = 40;
    gw_chain *c = NULL;
    gw_err err;
    if (gw_chain_create(&p, &c, &err) != GW_OK) {
        fprintf(stderr, "bench_tts: %s\n", err.msg);
        return 1;
    }
    const double tc = gw_chain_time_scale(&p);
    gw_chain_run_opts o = gw_chain_run_opts_default();
    o.solver = gw_solver_rk4;
    o.sp.dt = tc / 6400;
    gw_chain_result ref, ref2;
    if (collide(c, &o, &ref) != GW_OK)
        return 1;
    o.sp.dt = tc / 3200;
    if (collide(c, &o, &ref2) != GW_OK)
        return 1;
    double self = fmax(fabs(ref2.f_max - ref.f_max) / ref.f_max,
                       fabs(ref2.tau_n - ref.tau_n) / ref.tau_n);
    printf("granwave %s bench_tts: 40-bead column, v_imp %.2g m/s, k %.6g, K %.6g, m %.6g\n",
           gw_version(), p.v_imp, p.k, p.kwall, p.mass);
    printf("reference rk4 dt = tc/6400: F_max %.12g N, tau_N %.12g s, t_end %.9g s "
           "(change from tc/3200: %.1e)\n",
           ref.f_max, ref.tau_n, ref.t_end, self);
    printf("REF %.17g %.17g %.17g %.3g\n", ref.f_max, ref.tau_n, ref.t_end, self);
    printf("PARAMS %.17g %.17g %.17g %.17g %.17g\n", p.k, p.kwall, p.mass, p.v_imp, p.radius);
    printf("time to solution at %.0e relative accuracy, best of %d\n", acc, reps);
    printf("%-12s %-18s %10s %8s %11s %11s\n", "backend", "setting", "ms", "steps", "F_max err",
           "tau_N err");

    const char *bk[][2] = {{"rk4", "default"}, {"cvode", "adams"}, {"arkode", "erk"}, {"cvode", "bdf"}};
    for (size_t b = 0; b < sizeof bk / sizeof bk[0]; b++) {
        int is_rk4 = !strcmp(bk[b][0], "rk4");
        int passed = 0;
        for (int k = 0; k < 40 && !passed; k++) {
            gw_chain_run_opts q = gw_chain_run_opts_default();
            q.dt_out = dt_out;
            q.solver = gw_solver_type_find(bk[b][0]);
            q.sp.method = gw_solver_method_find(bk[b][1]);
            char setting[64];
            if (is_rk4) {
                double m = 8 * pow(2, 0.5 * k);
                q.sp.dt = tc / m;
                snprintf(setting, sizeof setting, "dt=tc/%.0f", m);
            } else {
                q.sp.rtol = q.sp.atol = 1e-4 * pow(10, -0.5 * k);
                snprintf(setting, sizeof setting, "tol=%.2g", q.sp.rtol);
                if (q.sp.rtol < 1e-14)
                    break;
            }
            gw_chain_result r;
            if (collide(c, &q, &r) != GW_OK)
                continue;
            double ef = fabs(r.f_max - ref.f_max) / ref.f_max;
            double et = fabs(r.tau_n - ref.tau_n) / ref.tau_n;
            long steps = r.stats.steps;
            gw_chain_result_free(&r);
            if (!(ef <= acc && et <= acc))
                continue;
            passed = 1;
            double best = 1e300;
            for (int rep = 0; rep < reps; rep++) {
                double t0 = gw_clock_ms();
                if (collide(c, &q, &r) != GW_OK)
                    return 1;
                best = fmin(best, gw_clock_ms() - t0);
                gw_chain_result_free(&r);
            }
            char name[32];
            snprintf(name, sizeof name, "%s/%s", bk[b][0], bk[b][1]);
            printf("%-12s %-18s %10.3f %8ld %11.1e %11.1e\n", name, setting, best, steps, ef, et);
            printf("TTS %s %s %.6g %.3g %.3g\n", name, setting, best, ef, et);
        }
        if (!passed)
            printf("%s/%s: no setting reached %.0e\n", bk[b][0], bk[b][1], acc);
    }
    gw_chain_result_free(&ref);
    gw_chain_result_free(&ref2);
    gw_chain_free(c);
    return 0;
}
