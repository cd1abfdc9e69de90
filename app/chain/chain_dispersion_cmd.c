/*
 * chain_dispersion_cmd.c: `granwave dispersion`, the dispersion study of
 * chain_dispersion.c (docs/physics.md 1.6) and, with --column-n, the wall-force
 * spectrum of a column (chain_spectrum.c), both run by the library's
 * gw_chain_dispersion_run (chain_disp_study.c). SI units; JSON, CSV and FFTW wisdom
 * (--wisdom: read only from a regular file that holds FFTW wisdom, which is then
 * the only kind of file it overwrites; checked with --out before any work).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <fftw3.h>

#include "gw_cli.h"
#include "chain_options.h"
#include "gw_io_impl.h"

/* ---- `granwave dispersion` ---- */

static const char *disp_summary =
    "Small-amplitude dispersion of a Hertz chain under static precompression F0\n"
    "(docs/physics.md 1.6): random small velocities, velocities sampled in time, space-time\n"
    "power spectrum (FFTW r2c, Hann window in time), ridge omega(q) against\n"
    "omega = 2 sqrt(kappa/m) |sin(qa/2)|, kappa = (3/2) k^(2/3) F0^(1/3). Steel beads\n"
    "(R = 4 mm). Wavenumbers in lattice units qa. --column-n N instead runs one column\n"
    "collision (granwave chain) and reports the wall-force spectrum peak against 1/P.";

typedef struct disp_cli {
    long n, t_samples, steps, seed, column_n;
    double f0, dt_out, amp, min_bins, rtol, atol, vimp;
    int measure, json, quiet;
    const char *ends, *solver, *method, *out, *wisdom;
    /* the FFTW wisdom imported before planning, as FNV-1a 64 of its bytes (set
     * when wisdom_read): plans made over it can differ from fresh ones in the
     * last bit, so the settings say which wisdom a run planned over */
    int wisdom_read;
    unsigned long long wisdom_fnv1a64;
} disp_cli;

enum { DISP_NOPTS = 21 };

#define DOPT_L(nm, dst, mv, hl, lo_, hi_)                                                 \
    (gw_opt) { .name = nm, .kind = GW_OPT_LONG, .dest = dst, .metavar = mv, .help = hl, \
               .lo = lo_, .hi = hi_ }
#define DOPT_D(nm, dst, mv, hl, lo_, hi_, open_)                                           \
    (gw_opt) { .name = nm, .kind = GW_OPT_DOUBLE, .dest = dst, .metavar = mv, .help = hl, \
               .lo = lo_, .hi = hi_, .open_lo = open_ }
/* a count held as a double (the library's min_bins): whole numbers only */
#define DOPT_C(nm, dst, mv, hl, lo_, hi_)                                                  \
    (gw_opt) { .name = nm, .kind = GW_OPT_COUNT, .dest = dst, .metavar = mv, .help = hl, \
               .lo = lo_, .hi = hi_ }
#define DOPT_S(nm, dst, mv, hl) \
    (gw_opt) { .name = nm, .kind = GW_OPT_STRING, .dest = dst, .metavar = mv, .help = hl }

static void disp_options(disp_cli *c, gw_opt *o)
{
    gw_chain_disp_params d = gw_chain_disp_params_default();
    memset(c, 0, sizeof *c);
    c->n = d.n;
    c->f0 = d.f0;
    c->t_samples = d.t_samples;
    c->steps = d.steps_per_sample;
    c->amp = d.amp;
    c->seed = (long)d.seed;
    c->min_bins = d.min_bins;
    c->rtol = c->atol = 1e-10;
    c->vimp = 0.3;
    c->ends = "periodic";
    c->solver = "rk4";
    c->method = "default";
    int i = 0;
    o[i++] = DOPT_L("n", &c->n, "N", "number of beads [1024]", 8, 1 << 22);
    o[i++] = DOPT_D("f0", &c->f0, "F", "static precompression, N [10]", 0, 1e9, 1);
    o[i++] = DOPT_S("ends", &c->ends, "KIND", "periodic or fixed [periodic]");
    o[i++] = DOPT_L("t-samples", &c->t_samples, "T", "velocity samples in time, even [2048]", 64, 1 << 24);
    o[i++] = DOPT_D("dt-out", &c->dt_out, "DT", "sampling interval, s, in [0, 1] [0 = pi / (1.25 omega_c)]", 0, 1, 0);
    o[i++] = DOPT_L("steps-per-sample", &c->steps, "K", "RK4 steps per sampling interval (rk4 only) [16]", 1, 100000);
    o[i++] = DOPT_D("amp", &c->amp, "A", "rms overlap perturbation / d0 of the initial velocities, in [1e-12, 0.1] "
                    "(smaller nears the rounding of d0) [1e-3]", GW_CHAIN_DISP_AMP_MIN, 0.1, 0);
    o[i++] = DOPT_L("seed", &c->seed, "S", "seed of the random mode phases of the initial velocities [1]", 0, 9.0e18);
    o[i++] = DOPT_C("min-bins", &c->min_bins, "B", "ridge resolved from B frequency bins up, B <= T/2 - 2 [8]", 1,
                    GW_CHAIN_DISP_MIN_BINS_MAX);
    o[i++] = DOPT_S("solver", &c->solver, "NAME", "rk4, cvode or arkode [rk4; column-n: cvode]");
    o[i++] = DOPT_S("method", &c->method, "NAME", "cvode: adams|bdf; arkode: erk|dirk (bdf, dirk: fixed ends) [adams / erk; column-n: bdf / erk]");
    o[i++] = DOPT_D("rtol", &c->rtol, "R", "relative tolerance, cvode/arkode [1e-10]", GW_TOL_MIN, GW_TOL_MAX, 0);
    o[i++] = DOPT_D("atol", &c->atol, "A", "absolute tolerance in units of the perturbation scales [1e-10]", GW_TOL_MIN, GW_TOL_MAX, 0);
    o[i++] = (gw_opt){.name = "fftw-measure", .kind = GW_OPT_FLAG, .dest = &c->measure,
                      .help = "plan the FFTs with FFTW_MEASURE (default FFTW_ESTIMATE)"};
    o[i++] = DOPT_S("wisdom", &c->wisdom, "FILE", "import FFTW wisdom from FILE if present (absent or empty: none), export it after the run");
    o[i++] = DOPT_L("column-n", &c->column_n, "N", "instead: wall-force spectrum of an N-bead column collision, in [1, 100000] as parsed, and at most "
                        "1414: its work over the whole collision, N^2, is held to 2e6", 1, 100000);
    o[i++] = DOPT_D("vimp", &c->vimp, "V", "impact velocity of that column, m/s [0.3]", GW_CHAIN_VIMP_MIN,
                    GW_CHAIN_VIMP_MAX, 0);
    o[i++] = (gw_opt){.name = "json", .kind = GW_OPT_FLAG, .dest = &c->json, .help = "print results as one JSON object on stdout"};
    o[i++] = DOPT_S("out", &c->out, "DIR", "write dispersion_ridge.csv, dispersion_power.csv and dispersion.json into DIR (--column-n: wall_spectrum.csv and dispersion.json)");
    o[i++] = (gw_opt){.name = "quiet", .kind = GW_OPT_FLAG, .dest = &c->quiet,
                      .help = "no progress lines (a run that lasts 2 s or more reports on stderr)"};
    o[i++] = (gw_opt){0};
}

/* Progress lines on stderr once a run has lasted DISP_PROGRESS_MS, as `granwave
 * drop` and `chain`: the default run takes 0.6 s, --n 8192 about 6 s, and the
 * work bound (1e10 bead-steps) minutes, with nothing said before. */
#define DISP_PROGRESS_MS 2000.0

typedef struct disp_progress {
    gw_cli_progress p;
    char header[200];
    long n, column_n;
} disp_progress;

static int disp_progress_report(void *ctx, long done, long total)
{
    disp_progress *dp = ctx;
    if (!dp->header[0]) { /* the counts are the study's (gw_chain_dispersion_run_progress) */
        if (dp->column_n > 0)
            snprintf(dp->header, sizeof dp->header, "granwave dispersion: a column of %ld bead%s, %ld samples over "
                     "the collision's expected length (past it, the count waits one short until the end)",
                     dp->column_n, dp->column_n == 1 ? "" : "s", total);
        else
            snprintf(dp->header, sizeof dp->header, "granwave dispersion: %ld beads, %ld velocity samples (the "
                     "transform follows the last)", dp->n, total);
        dp->p.header = dp->header;
    }
    return gw_cli_progress_report(&dp->p, done, total);
}

static void disp_progress_start(disp_progress *dp, const disp_cli *c)
{
    memset(dp, 0, sizeof *dp);
    dp->n = c->n;
    dp->column_n = c->column_n;
    gw_cli_progress_init(&dp->p, "  ", "samples", DISP_PROGRESS_MS);
    dp->p.after_ms = gw_cli_progress_ms(DISP_PROGRESS_MS);
}

/* the wisdom a run planned over: its FNV-1a 64 (hex), or null when none was read */
static void disp_wisdom_json(cJSON *o, const disp_cli *c)
{
    char hx[17];
    snprintf(hx, sizeof hx, "%016llx", c->wisdom_fnv1a64);
    if (c->wisdom_read)
        cJSON_AddStringToObject(o, "fftw_wisdom_fnv1a64", hx);
    else
        cJSON_AddNullToObject(o, "fftw_wisdom_fnv1a64");
}

/* p, type, sp: what ran (the library's outcome, defaults resolved) */
static cJSON *disp_settings_json(const disp_cli *c, const gw_chain_disp_params *p, const gw_solver_type *type,
                                 const gw_solver_params *sp)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "version", gw_version());
    cJSON *m = cJSON_AddObjectToObject(o, "model");
    cJSON_AddNumberToObject(m, "n", p->n);
    cJSON_AddNumberToObject(m, "f0", p->f0);
    cJSON_AddStringToObject(m, "ends", p->ends == GW_CHAIN_DISP_FIXED ? "fixed" : "periodic");
    cJSON_AddNumberToObject(m, "mass", p->mass);
    cJSON_AddNumberToObject(m, "k", p->k);
    cJSON_AddNumberToObject(m, "radius", p->radius);
    cJSON_AddNumberToObject(m, "amp", p->amp);
    cJSON_AddNumberToObject(m, "seed", (double)p->seed);
    cJSON *s = cJSON_AddObjectToObject(o, "solver");
    cJSON_AddStringToObject(s, "name", gw_solver_type_name(type));
    cJSON_AddStringToObject(s, "method", type == gw_solver_rk4 ? "none"
                                         : sp->method != GW_METHOD_DEFAULT ? gw_solver_method_name(sp->method)
                                         : type == gw_solver_cvode ? "adams" : "erk");
    cJSON_AddNumberToObject(s, "rtol", sp->rtol);
    cJSON_AddNumberToObject(s, "atol", sp->atol);
    if (type == gw_solver_rk4) {
        cJSON_AddNumberToObject(s, "steps_per_sample", p->steps_per_sample);
        cJSON_AddNumberToObject(s, "rk4_dt", gw_chain_disp_dt_sample(p) / p->steps_per_sample);
    } else { /* cvode and arkode choose their steps: no RK4 step ran (it read dt_out / 16) */
        cJSON_AddNullToObject(s, "steps_per_sample");
        cJSON_AddNullToObject(s, "rk4_dt");
    }
    cJSON *f = cJSON_AddObjectToObject(o, "spectrum");
    cJSON_AddNumberToObject(f, "t_samples", p->t_samples);
    cJSON_AddNumberToObject(f, "dt_out", gw_chain_disp_dt_sample(p));
    cJSON_AddStringToObject(f, "window", "hann (time)");
    cJSON_AddStringToObject(f, "fftw_planner", p->fftw_measure ? "measure" : "estimate");
    disp_wisdom_json(f, c);
    cJSON_AddNumberToObject(f, "min_bins", p->min_bins);
    return o;
}

/* DIR/name through an atomic file: header, then body(ctx). */
static int write_csv(const char *dir, const char *name, const char *hdr,
                     void (*body)(FILE *, const void *), const void *ctx, gw_err *err)
{
    char path[4096];
    gw_afile f;
    if (gw_path_join(path, sizeof path, dir, name) != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s/%s: path too long", dir, name);
    int rc = gw_afile_open(&f, path, err);
    if (rc != GW_OK)
        return rc;
    gw_write_comment(f.fp, hdr);
    body(f.fp, ctx);
    return gw_afile_commit(&f, err);
}

static void ridge_body(FILE *fp, const void *ctx)
{
    const gw_chain_disp_result *r = ctx;
    fprintf(fp, "j,qa_rad,omega_ridge_rad_s,omega_theory_rad_s,rel_err,resolved,ridge_power\n");
    for (int k = 0; k < r->nq; k++)
        fprintf(fp, "%d,%.10g,%.10g,%.10g,%.6g,%d,%.6g\n", k + 1, r->qa[k], r->omega_ridge[k],
                r->omega_theory[k], fabs(r->omega_ridge[k] / r->omega_theory[k] - 1), r->resolved[k],
                r->ridge_power[k]);
}

/* The power spectrum reduced to at most 128 x 256 blocks (max over a block keeps
 * the ridge visible), long format. */
static void power_body(FILE *fp, const void *ctx)
{
    const gw_chain_disp_result *r = ctx;
    const int gq = (r->nq + 127) / 128, gw = (r->n_omega + 255) / 256;
    const int rows = (r->nq + gq - 1) / gq, cols = (r->n_omega + gw - 1) / gw;
    fprintf(fp, "# grid: %d qa rows x %d omega columns, each the max over %d x %d bins\n", rows, cols, gq, gw);
    fprintf(fp, "qa_rad,omega_rad_s,power\n");
    for (int bq = 0; bq < rows; bq++)
        for (int bw = 0; bw < cols; bw++) {
            double pmax = 0, qs = 0, ws = 0;
            int cq = 0, cw = 0;
            for (int j = bq * gq; j < r->nq && j < (bq + 1) * gq; j++, cq++) {
                qs += r->qa[j];
                for (int l = bw * gw; l < r->n_omega && l < (bw + 1) * gw; l++)
                    pmax = fmax(pmax, r->power[(size_t)j * (size_t)r->n_omega + (size_t)l]);
            }
            for (int l = bw * gw; l < r->n_omega && l < (bw + 1) * gw; l++, cw++)
                ws += l * r->d_omega;
            fprintf(fp, "%.8g,%.8g,%.6g\n", qs / cq, ws / cw, pmax);
        }
}

static cJSON *disp_json(const gw_chain_disp_params *p, const gw_chain_disp_result *r,
                        cJSON *settings, double wall_ms)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "version", gw_version());
    cJSON_AddNumberToObject(o, "n", p->n);
    cJSON_AddNumberToObject(o, "f0", p->f0);
    cJSON_AddStringToObject(o, "ends", p->ends == GW_CHAIN_DISP_FIXED ? "fixed" : "periodic");
    cJSON_AddNumberToObject(o, "d0", r->d0);
    cJSON_AddNumberToObject(o, "kappa", r->kappa);
    cJSON_AddNumberToObject(o, "a", r->a);
    cJSON_AddNumberToObject(o, "omega_c_theory", r->omega_c_theory);
    cJSON_AddNumberToObject(o, "omega_c_measured", r->omega_c_measured);
    cJSON_AddNumberToObject(o, "omega_c_rel_err", r->omega_c_rel_err);
    cJSON_AddNumberToObject(o, "omega_edge", r->omega_edge);
    cJSON_AddNumberToObject(o, "ridge_max_rel_err", r->ridge_max_rel_err);
    cJSON_AddNumberToObject(o, "n_resolved", r->n_resolved);
    cJSON_AddNumberToObject(o, "qa_resolved_min", r->qa_resolved_min);
    cJSON_AddNumberToObject(o, "qa_resolved_max", r->qa_resolved_max);
    cJSON_AddNumberToObject(o, "c0", r->c0_theory);
    cJSON_AddNumberToObject(o, "c0_measured", r->c0_measured);
    cJSON_AddNumberToObject(o, "c0_rel_err", fabs(r->c0_measured / r->c0_theory - 1));
    cJSON_AddNumberToObject(o, "max_overlap_dev", r->max_overlap_dev);
    cJSON_AddNumberToObject(o, "d_omega", r->d_omega);
    cJSON_AddNumberToObject(o, "dt_out", r->dt_sample);
    cJSON_AddNumberToObject(o, "dt_step", r->dt_step);
    cJSON_AddNumberToObject(o, "t_total", r->t_total);
    cJSON_AddStringToObject(o, "q_units", "qa, rad per bead");
    cJSON_AddItemToObject(o, "q", gw_json_doubles(r->qa, r->nq));
    cJSON_AddItemToObject(o, "omega_ridge", gw_json_doubles(r->omega_ridge, r->nq));
    cJSON_AddItemToObject(o, "omega_theory", gw_json_doubles(r->omega_theory, r->nq));
    cJSON_AddItemToObject(o, "resolved", gw_json_bools(r->resolved, r->nq)); /* a flag per q, as every flag */
    cJSON_AddNumberToObject(o, "steps", (double)r->stats.steps);
    cJSON_AddNumberToObject(o, "rhs_evals", (double)r->stats.rhs_evals);
    cJSON_AddNumberToObject(o, "integrate_ms", r->integrate_ms);
    cJSON_AddNumberToObject(o, "fft_ms", r->fft_ms);
    cJSON_AddNumberToObject(o, "wall_time_ms", wall_ms);
    cJSON_AddItemToObject(o, "settings", cJSON_Duplicate(settings, 1));
    return o;
}

static void disp_print(const gw_chain_disp_params *p, const gw_solver_type *type, const gw_chain_disp_result *r,
                       double wall_ms)
{
    printf("granwave %s dispersion: n = %d beads, F0 = %g N, %s ends, solver %s\n", gw_version(), p->n, p->f0,
           p->ends == GW_CHAIN_DISP_FIXED ? "fixed" : "periodic", gw_solver_type_name(type));
    printf("  d0 = %.6g m, kappa = %.6g N/m, a = %.6g m\n", r->d0, r->kappa, r->a);
    printf("  omega_c   theory %.6g rad/s, ridge max %.6g at qa %.4g (rel err %.2e), edge %.6g\n",
           r->omega_c_theory, r->omega_c_measured, r->qa_resolved_max, r->omega_c_rel_err, r->omega_edge);
    printf("  ridge     max rel err %.2e over qa in [%.4g, %.4g] (%d of %d resolved)\n",
           r->ridge_max_rel_err, r->qa_resolved_min, r->qa_resolved_max, r->n_resolved, r->nq);
    printf("  c0        theory %.6g m/s, long-wave fit %.6g m/s\n", r->c0_theory, r->c0_measured);
    printf("  linearity max |d - d0| / d0 = %.3g\n", r->max_overlap_dev);
    printf("  run       %.0f ms (integration %.0f ms, %ld steps; FFT %.0f ms)\n", wall_ms,
           r->integrate_ms, r->stats.steps, r->fft_ms);
}

/* every file dispersion --out may write: the study's three, or --column-n's
 * wall_spectrum.csv and dispersion.json */
static const char *const disp_files[] = {"dispersion_ridge.csv", "dispersion_power.csv", "dispersion.json",
                                         "wall_spectrum.csv", NULL};

static int disp_write_out(const char *dir, const char *hdr, const cJSON *o,
                          const gw_chain_disp_result *r, gw_err *err)
{
    char path[4096];
    gw_outset oset; /* this run's files, all (the --column-n run's wall_spectrum.csv goes), or none */
    char made[4096] = ""; /* the first directory of --out this run creates, taken back on a failure */
    int rc = gw_cli_outset_begin(&oset, dir, disp_files, made, sizeof made, err);
    if (rc == GW_OK)
        rc = write_csv(dir, "dispersion_ridge.csv", hdr, ridge_body, r, err);
    if (rc == GW_OK)
        rc = write_csv(dir, "dispersion_power.csv", hdr, power_body, r, err);
    if (rc == GW_OK && gw_path_join(path, sizeof path, dir, "dispersion.json") != GW_OK)
        rc = gw_err_set(err, GW_EINVAL, "%s: path too long", dir);
    if (rc == GW_OK)
        rc = gw_json_write(path, o, err);
    if (rc == GW_OK)
        rc = gw_outset_commit(&oset, err);
    gw_cli_outset_end(&oset, dir, made, rc == GW_OK);
    return rc;
}

static void spectrum_body(FILE *fp, const void *ctx)
{
    const gw_chain_spectrum *sp = ctx;
    fprintf(fp, "freq_hz,power_n2s2\n");
    for (int l = 0; l < sp->len && sp->freq[l] <= 8 * sp->f_peak; l++)
        fprintf(fp, "%.8g,%.6g\n", sp->freq[l], sp->power[l]);
}

/* The study the flags set (gw_cli_study_setup) run with the progress line:
 * *OUT filled (freed by gw_chain_dispersion_outcome_free whatever the
 * status), a refusal named in ERR ("NAME:" -> "--NAME:",
 * gw_cli_study_error); GW_ENOMEM with ERR empty when no setup could be made. */
static int disp_study_run(const disp_cli *c, const gw_opt *opts, int argc, char **argv,
                          gw_chain_dispersion_outcome *out, gw_err *err)
{
    memset(out, 0, sizeof *out);
    err->msg[0] = '\0';
    gw_chain_dispersion_setup ds;
    if (gw_chain_dispersion_setup_init(&ds) != GW_OK) {
        gw_chain_dispersion_setup_clear(&ds);
        return GW_ENOMEM;
    }
    int rc = gw_cli_study_setup(gw_chain_dispersion_setup_params(), &ds, opts, argc, argv, "dispersion", err);
    disp_progress prog;
    disp_progress_start(&prog, c);
    if (rc == GW_OK && (rc = gw_chain_dispersion_run_progress(&ds, c->quiet ? NULL : disp_progress_report, &prog,
                                                              out, err)) != GW_OK)
        gw_cli_study_error(gw_chain_dispersion_setup_params(), "dispersion", rc, err);
    gw_chain_dispersion_setup_clear(&ds);
    return rc;
}

/* --column-n: one column collision, then the wall-force spectrum over the
 * contact [0, tau_N] against 1/P from the maxima of the wall force. */
static int disp_column(const disp_cli *c, const gw_opt *opts, int argc, char **argv)
{
    gw_err err = {{0}};
    gw_chain_dispersion_outcome out;
    int rc = disp_study_run(c, opts, argc, argv, &out, &err);
    if (rc == GW_ENOMEM && !err.msg[0])
        return gw_cli_nomem("dispersion");
    int code = 0;
    gw_chain_params p = gw_chain_params_default();
    p.n = out.column_n;
    p.v_imp = out.v_imp;
    struct {
        double dt_out;
        gw_solver_params sp;
        const gw_solver_type *solver;
    } o = {out.dt_out, out.solver_params, out.solver};
    struct {
        double tau_n, period;
        int n_maxima;
    } r = {out.tau_n, out.period, out.n_maxima};
    const gw_chain_spectrum sp = out.sp;
    if (rc != GW_OK) {
        if (strncmp(err.msg, "dispersion ", 11) == 0) /* named by gw_cli_study_error: "dispersion --NAME: ..." */
            fprintf(stderr, "granwave %s\n", err.msg);
        else
            fprintf(stderr, "granwave dispersion --column-n: %s\n", err.msg);
        code = rc == GW_EINVAL ? 2 : 1;
    } else {
        cJSON *js = cJSON_CreateObject();
        cJSON_AddStringToObject(js, "version", gw_version());
        cJSON_AddStringToObject(js, "mode", "column_wall_spectrum");
        cJSON_AddNumberToObject(js, "column_n", p.n);
        cJSON_AddNumberToObject(js, "v_imp", p.v_imp);
        cJSON_AddStringToObject(js, "solver", gw_solver_type_name(o.solver));
        /* the method the column ran (the chain's: cvode bdf, arkode erk by default) */
        cJSON_AddStringToObject(js, "method", o.solver == gw_solver_rk4 ? "none"
                                              : o.sp.method != GW_METHOD_DEFAULT ? gw_solver_method_name(o.sp.method)
                                              : o.solver == gw_solver_cvode ? "bdf" : "erk");
        cJSON_AddNumberToObject(js, "rtol", o.sp.rtol);
        cJSON_AddNumberToObject(js, "atol", o.sp.atol);
        cJSON_AddNumberToObject(js, "mass", p.mass);
        cJSON_AddNumberToObject(js, "k", p.k);
        cJSON_AddNumberToObject(js, "kwall", p.kwall);
        cJSON_AddNumberToObject(js, "radius", p.radius);
        cJSON_AddNumberToObject(js, "dt_out", o.dt_out);
        cJSON_AddNumberToObject(js, "tau_n", r.tau_n);
        cJSON_AddNumberToObject(js, "period", r.period);
        cJSON_AddNumberToObject(js, "inv_period", out.inv_period);
        cJSON_AddNumberToObject(js, "f_peak", sp.f_peak);
        cJSON_AddNumberToObject(js, "f_peak_rel_diff", out.f_peak_rel_diff);
        cJSON_AddNumberToObject(js, "df", sp.df);
        cJSON_AddNumberToObject(js, "f_min", sp.f_min);
        cJSON_AddNumberToObject(js, "samples", sp.samples);
        cJSON_AddNumberToObject(js, "n_maxima", r.n_maxima);
        cJSON_AddStringToObject(js, "fftw_planner", c->measure ? "measure" : "estimate");
        disp_wisdom_json(js, c);
        gw_cli_warnings("dispersion", out.warnings);   /* the column's collision's, as chain's */
        gw_cli_json_warnings(js, out.warnings);        /* and in dispersion.json and --json, [] when none */
        { /* "settings", as every command's JSON (formats.md): the run's settings above, again */
            static const char *const keys[] = {"column_n", "v_imp", "solver", "method", "rtol", "atol", "mass", "k",
                                               "kwall", "radius", "dt_out", "fftw_planner"};
            cJSON *set = cJSON_CreateObject();
            for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
                cJSON_AddItemToObject(set, keys[i], cJSON_Duplicate(cJSON_GetObjectItem(js, keys[i]), 1));
            disp_wisdom_json(set, c); /* the wisdom file and its hash, as the study's settings */
            cJSON_AddItemToObject(js, "settings", set);
        }
        char *hdr = gw_cli_provenance("dispersion", argc, argv, cJSON_GetObjectItem(js, "settings"));
        gw_outset oset; /* the study's files of an earlier run go when this one is placed */
        memset(&oset, 0, sizeof oset);
        char jpath[4096]; /* dispersion.json: the --json object, as every command's --out */
        char made[4096] = ""; /* the first directory of --out this run creates, taken back on a failure */
        if (c->out && (!hdr ? gw_err_set(&err, GW_ENOMEM, "out of memory") != GW_OK :
                       gw_cli_outset_begin(&oset, c->out, disp_files, made, sizeof made, &err) != GW_OK ||
                       write_csv(c->out, "wall_spectrum.csv", hdr ? hdr : "", spectrum_body, &sp, &err) != GW_OK ||
                       (gw_path_join(jpath, sizeof jpath, c->out, "dispersion.json") != GW_OK &&
                        gw_err_set(&err, GW_EINVAL, "%s: path too long", c->out) != GW_OK) ||
                       gw_json_write(jpath, js, &err) != GW_OK ||
                       gw_outset_commit(&oset, &err) != GW_OK)) {
            gw_cli_outset_end(&oset, c->out, made, 0);
            fprintf(stderr, "granwave dispersion --out: %s\n", err.msg);
            code = 1;
        } else if (c->out)
            gw_cli_outset_end(&oset, c->out, made, 1);
        if (code == 0 && c->json)
            code = gw_cli_json_stdout("dispersion", js);
        else if (code == 0) {
            char ip[32], rd[32];
            printf("granwave %s dispersion --column-n %d (v_imp %g m/s): wall-force peak %.6g Hz, "
                   "1/P %s Hz (rel diff %s), bin %.3g Hz, contact %.4g us\n",
                   gw_version(), p.n, p.v_imp, sp.f_peak, gw_cli_num(ip, sizeof ip, "%.6g", out.inv_period),
                   gw_cli_num(rd, sizeof rd, "%+.2e", out.f_peak_rel_diff), sp.df, r.tau_n * 1e6);
        }
        free(hdr);
        cJSON_Delete(js);
    }
    gw_chain_dispersion_outcome_free(&out);
    return code;
}

/* The end of the wisdom in text[0, len): the byte after the ')' that closes
 * its first '(' and the blanks after it; 0 when that ')' is missing. FFTW
 * reads the wisdom and ignores what follows, which the export at the end then
 * dropped: notes kept after the wisdom, or a second file appended to it, were
 * lost with exit 0 (and the recorded hash stopped at a NUL byte). */
static size_t wisdom_end(const char *text, size_t len)
{
    long depth = 0;
    size_t i = 0;
    for (; i < len; i++) {
        depth += text[i] == '(';
        depth -= text[i] == ')';
        if (text[i] == '\0' || depth < 0)
            return 0;
        if (depth == 0 && text[i] == ')')
            break;
    }
    if (i == len)
        return 0;
    for (i++; i < len && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r'); i++)
        ;
    return i;
}

/* The preamble of FFTW wisdom in text[0, len): "(fftw-3.3.10 fftw_wisdom #x.. #x.. #x.. #x..",
 * the library's version, its precision (fftw_ double, fftwf_ single, fftwl_
 * long double, fftwq_ quad) and its planner's signature, into ver, kind and sig
 * (each NUL-terminated, at most 63 characters); 0 when text does not begin so. */
typedef struct wisdom_head {
    char ver[64], kind[64], sig[64];
} wisdom_head;

static int wisdom_preamble(const char *text, size_t len, wisdom_head *h)
{
    memset(h, 0, sizeof *h);
    size_t i = 1;
    if (len < 7 || strncmp(text, "(fftw-", 6) != 0)
        return 0;
    char *tok[2] = {h->ver, h->kind};
    for (int k = 0; k < 2; k++) {
        size_t n = 0;
        for (; i < len && n < sizeof h->ver - 1 && (text[i] == '.' || text[i] == '-' || text[i] == '_' ||
                                                     (text[i] >= '0' && text[i] <= '9') ||
                                                     (text[i] >= 'a' && text[i] <= 'z')); i++)
            tok[k][n++] = text[i];
        if (n == 0 || i >= len || text[i] != ' ')
            return 0;
        i++;
    }
    size_t n = 0; /* the signature: the rest of the line, its blanks kept */
    for (; i < len && n < sizeof h->sig - 1 && text[i] != '\n' && text[i] != '(' && text[i] != ')' &&
           text[i] != '\0'; i++)
        h->sig[n++] = text[i];
    while (n > 0 && (h->sig[n - 1] == ' ' || h->sig[n - 1] == '\r'))
        h->sig[--n] = '\0';
    const size_t kl = strlen(h->kind); /* fftw_wisdom, fftwf_wisdom, ... */
    return kl >= 11 && strncmp(h->kind, "fftw", 4) == 0 && strcmp(h->kind + kl - 7, "_wisdom") == 0;
}

static const char *wisdom_precision(const char *kind)
{
    return strcmp(kind, "fftw_wisdom") == 0    ? "double precision"
           : strcmp(kind, "fftwf_wisdom") == 0 ? "single precision"
           : strcmp(kind, "fftwl_wisdom") == 0 ? "long-double precision"
           : strcmp(kind, "fftwq_wisdom") == 0 ? "quad precision"
                                               : "unknown precision";
}

/* Why wisdom that this build's FFTW did not import is refused: it is another
 * FFTW's (version or precision, both named), or this version's from another
 * configuration of it (its planner's signature differs), else not wisdom. It
 * was told "is not FFTW wisdom" for a file of fftw-3.3.9's wisdom. */
static int wisdom_refusal(const char *path, const char *text, size_t len, gw_err *err)
{
    wisdom_head f, o;
    char *own = fftw_export_wisdom_to_string(); /* this build's preamble (nothing planned yet) */
    const int ok_f = wisdom_preamble(text, len, &f), ok_o = own && wisdom_preamble(own, strlen(own), &o);
    free(own);
    if (ok_f && ok_o && (strcmp(f.ver, o.ver) != 0 || strcmp(f.kind, o.kind) != 0))
        return gw_err_set(err, GW_EINVAL, "dispersion --wisdom: '%s' is FFTW wisdom of another FFTW version or "
                          "precision (%s, %s) than this build's (%s, %s); refusing to overwrite it", path, f.ver,
                          wisdom_precision(f.kind), o.ver, wisdom_precision(o.kind));
    if (ok_f && ok_o && strcmp(f.sig, o.sig) != 0)
        return gw_err_set(err, GW_EINVAL, "dispersion --wisdom: '%s' is FFTW wisdom of %s (%s) from another "
                          "configuration of it (its planner's signature '%s', this build's '%s'); refusing to "
                          "overwrite it", path, f.ver, wisdom_precision(f.kind), f.sig, o.sig);
    if (ok_f && !ok_o)
        return gw_err_set(err, GW_EINVAL, "dispersion --wisdom: '%s' is FFTW wisdom of %s (%s) that this build's "
                          "FFTW (%s) does not import; refusing to overwrite it", path, f.ver,
                          wisdom_precision(f.kind), fftw_version);
    return gw_err_set(err, GW_EINVAL, "dispersion --wisdom: '%s' is not FFTW wisdom; refusing to overwrite it", path);
}

/* Wisdom is read through gw_input_read (a regular file, at most 64 MiB: a FIFO or
 * /dev/zero is refused, never read forever). An absent file, or an empty
 * regular one (made by touch or mktemp: nothing in it to lose), is planned
 * afresh and written at the end; any other file must be FFTW wisdom, since it
 * is overwritten at the end of the run. */
static int disp_import_wisdom(disp_cli *c, gw_err *err)
{
    const char *path = c->wisdom;
    struct stat st;
    if (stat(path, &st) != 0) {
        /* st is not filled then: its mode was read, and a file stat could not
         * reach (EACCES, ENOTDIR, EIO, ELOOP) taken by chance as an empty one */
        const int e = errno;
        if (e == ENOENT) /* in --out, still to make: it is made before the wisdom is saved */
            return gw_io_out_file_check_in(path, c->out, disp_files, "dispersion --wisdom", err);
        return gw_err_set(err, GW_EINVAL, "dispersion --wisdom: '%s': cannot read: %s", path, strerror(e));
    }
    if (S_ISREG(st.st_mode) && st.st_size == 0)
        return gw_out_file_check(path, "dispersion --wisdom", err);
    char *text = NULL;
    size_t len = 0;
    int rc = gw_input_read(path, "dispersion --wisdom", (size_t)64 << 20, &text, &len, err);
    if (rc != GW_OK)
        return GW_EINVAL;
    const size_t end = wisdom_end(text, len);
    if (strncmp(text, "(fftw-3", 7) != 0 || !end || !fftw_import_wisdom_from_string(text)) {
        rc = wisdom_refusal(path, text, len, err);
    } else if (end < len) {
        rc = gw_err_set(err, GW_EINVAL, "dispersion --wisdom: '%s' holds more than FFTW wisdom (byte %zu on: %s); "
                        "refusing to overwrite it", path, end + 1, memchr(text + end, '\0', len - end) ? "a NUL byte"
                        : "text after the wisdom");
    } else {
        c->wisdom_read = 1;
        c->wisdom_fnv1a64 = gw_fnv1a64(GW_FNV1A64_INIT, text, len);
    }
    free(text);
    return rc == GW_OK ? gw_out_file_check(path, "dispersion --wisdom", err) : rc;
}

static void disp_export_wisdom(const char *path)
{
    gw_afile f;
    gw_err err = {{0}};
    if (gw_afile_open(&f, path, &err) != GW_OK) {
        fprintf(stderr, "granwave dispersion --wisdom: %s (not saved)\n", err.msg);
        return;
    }
    fftw_export_wisdom_to_file(f.fp);
    if (gw_afile_commit(&f, &err) != GW_OK)
        fprintf(stderr, "granwave dispersion --wisdom: %s (not saved)\n", err.msg);
}

int gw_cmd_dispersion(int argc, char **argv)
{
    disp_cli c;
    gw_opt opts[DISP_NOPTS];
    disp_options(&c, opts);
    gw_err err = {{0}};
    int help = 0, npos = 0;
    const char *pos[1];
    if (gw_cli_parse("dispersion", opts, argc, argv, &help, pos, 0, &npos, &err) != GW_OK)
        return chain_cli_fail(err.msg);
    if (help)
        return gw_cli_help(stdout, "dispersion", "granwave dispersion [options]", disp_summary, opts, help);
    /* inputs and output locations before any work: a refused run writes nothing */
    if ((c.out && gw_out_check(c.out, "dispersion --out", &err) != GW_OK) ||
        (c.out && gw_out_names_check(c.out, disp_files, "dispersion --out", &err) != GW_OK) ||
        (c.out && gw_outset_check_input(c.out, disp_files, c.wisdom, "dispersion --wisdom", &err) != GW_OK) ||
        (c.wisdom && disp_import_wisdom(&c, &err) != GW_OK))
        return chain_cli_fail(err.msg);
    if (c.column_n > 0) {
        int code = disp_column(&c, opts, argc, argv);
        if (c.wisdom && code == 0)
            disp_export_wisdom(c.wisdom);
        return code;
    }
    gw_chain_dispersion_outcome out;
    int rc = disp_study_run(&c, opts, argc, argv, &out, &err);
    if (rc == GW_ENOMEM && !err.msg[0])
        return gw_cli_nomem("dispersion");
    const gw_chain_disp_result r = out.r;
    double wall_ms = out.wall_time_ms;
    int code = 0;
    if (rc != GW_OK) {
        fprintf(stderr, "granwave %s\n", err.msg);
        code = rc == GW_EINVAL || rc == GW_EUNSUPPORTED ? 2 : 1;
    } else {
        const gw_chain_disp_params *p = &out.params; /* what ran */
        cJSON *settings = disp_settings_json(&c, p, out.solver, &out.solver_params);
        cJSON *o = disp_json(p, &r, settings, wall_ms);
        gw_cli_json_warnings(o, out.warnings); /* in dispersion.json and --json as on stderr */
        char *hdr = gw_cli_provenance("dispersion", argc, argv, settings);
        if (c.out && (!hdr ? gw_err_set(&err, GW_ENOMEM, "out of memory") != GW_OK
                           : disp_write_out(c.out, hdr, o, &r, &err) != GW_OK)) {
            fprintf(stderr, "granwave dispersion --out: %s\n", err.msg);
            code = 1;
        }
        if (code == 0) /* no wavenumber resolved: the ridge error is NaN (JSON null), said why */
            gw_cli_warnings("dispersion", out.warnings);
        if (code == 0 && c.json)
            code = gw_cli_json_stdout("dispersion", o);
        else if (code == 0)
            disp_print(&out.params, out.solver, &r, wall_ms);
        free(hdr);
        cJSON_Delete(o);
        cJSON_Delete(settings);
    }
    if (c.wisdom && code == 0)
        disp_export_wisdom(c.wisdom);
    gw_chain_dispersion_outcome_free(&out);
    return code;
}
