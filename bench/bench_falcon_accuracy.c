/*
 * bench_falcon_accuracy.c: convergence study behind the falcon main job's step.
 * Never a pass/fail test: prints measurements.
 *
 * Case: the Falcon column (docs/physics.md 1.1, eq. F.11; gw_chain_params_default,
 * steel) of N beads hitting the rigid wall at v_imp. Observables: F_max (largest
 * wall force, N), tau_max (its time, s), tau_N (last time bead 1 leaves the wall,
 * s) and the force period P (s). Reference: CVODE BDF at rtol = atol = 1e-12 (the
 * main job's former setting; 3e-10 from a tight RK4 reference on 40 beads,
 * bench_chain). Trial: RK4 with events as roots and dt = T_c / M, T_c =
 * (m/k)^(2/5) v_imp^(-1/5) (gw_chain_time_scale), sampling only at events
 * (dt_out = 1 s) or every tau_1/10 (the main job's sweep; RK4 lands on each
 * sample, so finer sampling would also shorten the steps).
 *
 * RK4's global error would fall as dt^4 for a smooth right-hand side; measured, it
 * falls as M^-2.5 (every contact closing restarts the method on the d^(3/2)
 * force), so err(M) M^2.5 is printed and is roughly constant. The main job picks
 * M from the worst case measured here (gw_chain_rk4_steps_per_tc,
 * chain_collide_plan.c). Without gravity or damping the model is scale
 * invariant (lengths scale with d_max, times with T_c), so relative errors do not
 * depend on v_imp; three velocities are run to show it.
 *
 * Usage: bench_falcon_accuracy [nmax]   (N = 1, 2, 3, 5, 8, 13, 20, 30, 40 up to nmax)
 * Times: CPU time of this thread (the machine is shared).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "gw_chain.h"

static double cpu_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

static double rel(double a, double b)
{
    return fabs(a - b) / fabs(b);
}

/* One collision of n beads at v_imp with run options o; *cpu += its CPU ms. */
static int collide(int n, double v_imp, const gw_chain_run_opts *o, gw_chain_result *r, double *cpu,
                   gw_err *err)
{
    gw_chain_params p = gw_chain_params_default();
    p.n = n;
    p.v_imp = v_imp;
    gw_chain *c = NULL;
    double t0 = cpu_ms();
    int rc = gw_chain_create(&p, &c, err);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, o, r, err);
    *cpu += cpu_ms() - t0;
    gw_chain_free(c);
    return rc;
}

int main(int argc, char **argv)
{
    int nmax = argc > 1 ? atoi(argv[1]) : 40;
    const int ns[] = {1, 2, 3, 5, 8, 13, 20, 30, 40};
    const double vs[] = {0.3, sqrt(2 * 9.81 * 1.9e-3), sqrt(2 * 9.81 * 5.1e-3)};
    const double ms[] = {12, 16, 20, 24, 32, 48, 64, 96};
    enum { NN = sizeof ns / sizeof ns[0], NV = sizeof vs / sizeof vs[0], NM = sizeof ms / sizeof ms[0] };
    gw_chain_result ref[NV][NN];
    gw_err err;
    printf("granwave %s bench_falcon_accuracy: RK4 dt = T_c/M against CVODE BDF 1e-12\n", gw_version());
    double ref_ms = 0;
    for (int iv = 0; iv < NV; iv++)
        for (int in = 0; in < NN && ns[in] <= nmax; in++) {
            gw_chain_run_opts o = gw_chain_run_opts_default();
            o.sp.rtol = o.sp.atol = 1e-12;
            o.dt_out = 1.0; /* events only */
            if (collide(ns[in], vs[iv], &o, &ref[iv][in], &ref_ms, &err) != GW_OK) {
                fprintf(stderr, "reference N = %d: %s\n", ns[in], err.msg);
                return 1;
            }
        }
    printf("reference: %.0f ms CPU\n\n", ref_ms);
    printf("%5s %-10s %10s %10s %10s %10s %12s %12s %9s\n", "M", "sampling", "F_max", "tau_max",
           "tau_N", "P", "F_max M^2.5", "tau_N M^2.5", "CPU ms");
    for (int s = 0; s < 2; s++)
        for (int im = 0; im < NM; im++) {
            double ef = 0, etm = 0, etn = 0, ep = 0, cpu = 0;
            for (int iv = 0; iv < NV; iv++)
                for (int in = 0; in < NN && ns[in] <= nmax; in++) {
                    gw_chain_run_opts o = gw_chain_run_opts_default();
                    o.solver = gw_solver_rk4;
                    o.steps_per_tc = ms[im];
                    gw_chain_params p = gw_chain_params_default();
                    double tau1 = gw_chain_tau1(p.mass, p.kwall, vs[iv]);
                    o.dt_out = s == 0 ? 1.0 : tau1 / 10;
                    gw_chain_result r;
                    if (collide(ns[in], vs[iv], &o, &r, &cpu, &err) != GW_OK) {
                        fprintf(stderr, "M = %g N = %d: %s\n", ms[im], ns[in], err.msg);
                        return 1;
                    }
                    const gw_chain_result *q = &ref[iv][in];
                    ef = fmax(ef, rel(r.f_max, q->f_max));
                    etm = fmax(etm, rel(r.tau_max, q->tau_max));
                    etn = fmax(etn, rel(r.tau_n, q->tau_n));
                    if (q->n_maxima >= 2 && r.n_maxima == q->n_maxima)
                        ep = fmax(ep, rel(r.period, q->period));
                    else if (q->n_maxima >= 2)
                        ep = INFINITY;
                    gw_chain_result_free(&r);
                }
            double m4 = pow(ms[im], 2.5);
            printf("%5g %-10s %10.2e %10.2e %10.2e %10.2e %12.3g %12.3g %9.1f\n", ms[im],
                   s == 0 ? "events" : "tau_1/10", ef, etm, etn, ep, ef * m4, etn * m4, cpu);
        }
    printf("(largest relative error over N and v_imp; tau_max errors are discrete when the\n"
           " largest maximum moves to another peak of nearly the same height)\n");
    for (int iv = 0; iv < NV; iv++)
        for (int in = 0; in < NN && ns[in] <= nmax; in++)
            gw_chain_result_free(&ref[iv][in]);
    return 0;
}
