/*
 * test_solver_matrix_free.c: the implicit methods on a system flagged
 * matrix_free (gw_solver.h): cvode bdf and arkode dirk solve their Newton
 * systems with GMRES, holding no matrix, and still give the right answer.
 *
 * The system: the discrete diffusion equation on N = 200,000 points with
 * Dirichlet ends, y_i' = D (y_(i-1) - 2 y_i + y_(i+1)) (y_0 = y_(N+1) = 0),
 * declared with no band (mu = ml = 0, the layer's case). A band solver would
 * take the whole matrix, N x 3N doubles = 960 GB: its allocation fails, so
 * only a solver without a matrix can run it. The sine mode
 *   y_i(0) = sin(pi m i / (N + 1))
 * is an eigenvector: y_i(t) = y_i(0) exp(lambda t), lambda = -4 D sin^2(pi m /
 * (2 (N + 1))). With D = 1000 s^-1 and m = N/2, lambda = -2000 s^-1 (to 1e-5)
 * and the spectrum reaches -4000 s^-1: over t = 1e-3 s the mode decays to
 * exp(-2) = 0.135. Checked, per method, at rtol = atol = 1e-8: every
 * component within 1e-6 of the closed form (the tolerance the local errors
 * sum to over a few hundred steps; a wrong Newton solve or a missing coupling
 * term misses by far more), and no Jacobian evaluation (no matrix was formed).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gw_solver.h"
#include "gw_test.h"

#define N 200000L
static const double D = 1000.0, T_END = 1e-3;

static int diff_rhs(double t, const double *y, double *yd, void *P)
{
    (void)t, (void)P;
    for (long i = 0; i < N; i++) {
        const double l = i > 0 ? y[i - 1] : 0.0, r = i < N - 1 ? y[i + 1] : 0.0;
        yd[i] = D * (l - 2 * y[i] + r);
    }
    return 0;
}

static void run(const char *name, int method)
{
    const long m = N / 2;
    const double k = M_PI * (double)m / (double)(N + 1);
    const double lambda = -4 * D * sin(0.5 * k) * sin(0.5 * k);
    double *y = malloc(N * sizeof *y);
    if (!y) {
        GW_TEST_OK(0, "%s: allocation", name);
        return;
    }
    for (long i = 0; i < N; i++)
        y[i] = sin(k * (double)(i + 1));
    gw_system sys = {.dim = N, .rhs = diff_rhs, .matrix_free = 1};
    gw_solver_params p = gw_solver_params_default();
    p.rtol = p.atol = 1e-8;
    p.method = method;
    gw_solver *s = NULL;
    gw_err err = {{0}};
    const gw_solver_type *type = method == GW_CVODE_BDF ? gw_solver_cvode : gw_solver_arkode;
    int rc = gw_solver_create(type, &sys, &p, 0.0, y, &s, &err);
    GW_TEST_OK(rc == GW_OK, "%s: created without a matrix (%s)", name, rc == GW_OK ? "ok" : err.msg);
    double t = 0;
    if (rc == GW_OK)
        rc = gw_solver_advance(s, T_END, &t, y, NULL);
    GW_TEST_OK(rc == GW_OK && t == T_END, "%s: ran to %g s (%s)", name, T_END, rc == GW_OK ? "ok" : gw_solver_error(s));
    if (rc == GW_OK) {
        double worst = 0, decay = exp(lambda * T_END);
        for (long i = 0; i < N; i++)
            worst = fmax(worst, fabs(y[i] - sin(k * (double)(i + 1)) * decay));
        GW_TEST_OK(worst < 1e-6, "%s: the sine mode decays to exp(lambda t) = %.6f within 1e-6 (worst %.2e)", name,
                   decay, worst);
        gw_solver_stats st;
        gw_solver_get_stats(s, &st);
        GW_TEST_OK(st.jac_evals == 0 && st.steps > 0, "%s: %ld steps, %ld rhs, no Jacobian (%ld)", name, st.steps,
                   st.rhs_evals, st.jac_evals);
    }
    gw_solver_free(s);
    free(y);
}

int main(void)
{
    run("cvode bdf", GW_CVODE_BDF);
    run("arkode dirk", GW_ARKODE_DIRK);
    return gw_test_summary("test_solver_matrix_free");
}
