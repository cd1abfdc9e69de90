/*
 * chain_wavespeed.c: `granwave wavespeed`, the deformation-wave speed of the
 * column against v_imp, measured three independent ways (docs/physics.md 1.3):
 *   (a) v_tq    = 4R / T_q, T_q the slope of tau_N against N (F.4, F.6);
 *   (b) v_front = time of flight of the compression front: the first time each
 *                 contact carries a force threshold (default 10 % of the
 *                 single-bead peak F_max(1), F.13), position 2R i fitted
 *                 linearly against time over the contacts 2..N-2 of the longest
 *                 column (away from the wall and the free end);
 *   (c) v_group = long-wave group (= sound) speed of small vibrations, docs/physics.md
 *                 1.6: c0 = 2R sqrt(kappa/m), kappa = (3/2) k^(2/3) F^(1/3), of a
 *                 chain statically compressed by the column's mean wall force
 *                 F = (wall impulse)/tau_N of the longest column.
 * (c) is the speed of small vibrations, not of the front. In the uniformly
 * compressed state behind a front moving at V (the momentum balance of F.27:
 * k d^(3/2) = m v_imp V/(2R), d = 2R v_imp/V) the linear sound speed is
 * c0 = 2R sqrt((3/2) k d^(1/2)/m) = sqrt(3/2) V, so c0/sqrt(3/2) is a third,
 * independent estimate of the front speed (v_group_front, reported beside c0;
 * the factor is this relation, not a fit).
 * Each is fitted as v = A v_imp^beta (GSL, log-log) and A is expressed as C3 in
 * v = C3 (k/m)^(2/5) R v_imp^beta (F.16; the momentum balance F.27 gives C3 = 2).
 * The wall-force period is fitted as P = C2 (m/k)^(2/5) v_imp^(-1/5) (F.15).
 * Units: SI.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_cli.h"
#include "chain_options.h"

typedef struct ws_fit {
    double beta, beta_err, a, c3;
} ws_fit;

static ws_fit power_fit(const double *v, const double *s, int n, double scale)
{
    ws_fit f = {NAN, NAN, NAN, NAN};
    gw_linfit lf;
    if (n >= 2 && gw_fit_power(v, s, n, &lf) == GW_OK) {
        f.beta = lf.c1;
        f.beta_err = lf.c1_err;
        f.a = exp(lf.c0);
        f.c3 = f.a / scale;
    }
    return f;
}

static cJSON *fit_json(const ws_fit *f)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "beta", f->beta);
    cJSON_AddNumberToObject(o, "beta_err", f->beta_err);
    cJSON_AddNumberToObject(o, "prefactor", f->a);
    cJSON_AddNumberToObject(o, "c3", f->c3);
    return o;
}

/* Front speed of one long column: linear fit of 2R k against front_t[k]. */
static double front_speed(const gw_chain_params *p, const gw_chain_run_opts *run,
                          double frac, double *t_front_err, gw_err *err)
{
    gw_chain *c = NULL;
    gw_chain_run_opts o = *run;
    o.front_threshold = frac * gw_chain_fmax1(p->mass, p->kwall, p->v_imp);
    gw_chain_result r;
    memset(&r, 0, sizeof r);
    double speed = NAN;
    int rc = gw_chain_create(p, &c, err);
    if (rc == GW_OK)
        rc = gw_chain_collide(c, &o, &r, err);
    if (rc == GW_OK) {
        int n = p->n, m = 0;
        double *x = malloc(2 * (size_t)n * sizeof *x), *y = x ? x + n : NULL;
        for (int k = 2; x && k <= n - 2; k++)
            if (isfinite(r.front_t[k])) {
                x[m] = r.front_t[k];
                y[m] = 2 * p->radius * k;
                m++;
            }
        gw_linfit lf;
        if (m >= 3 && gw_fit_linear(x, y, m, &lf) == GW_OK) {
            speed = lf.c1;
            *t_front_err = lf.c1_err;
        }
        free(x);
    }
    gw_chain_result_free(&r);
    gw_chain_free(c);
    return speed;
}

static const char *ws_summary =
    "Deformation-wave speed of the column against the impact velocity, three ways:\n"
    "(a) 4R/T_q from the slope of tau_N(N), (b) time of flight of the compression\n"
    "front, (c) long-wave group velocity of the chain compressed by the mean wall\n"
    "force. Power-law fits v = A v_imp^beta with standard errors, C3 of (F.16), and\n"
    "the period fit P = C2 (m/k)^(2/5) v_imp^(-1/5) (F.15).";

int gw_cmd_wavespeed(int argc, char **argv)
{
    chain_cli c;
    gw_opt opts[CHAIN_CLI_NOPTS + 6];
    chain_cli_options(&c, opts);
    const char *vlist = "0.075,0.15,0.3,0.5", *nrange = "5:40";
    double frac = 0.1;
    long jobs = 0;
    int quiet = 0, k = CHAIN_CLI_NOPTS;
    opts[k++] = (gw_opt){.name = "vimp", .kind = GW_OPT_STRING, .dest = &vlist, .metavar = "V,V..",
                         .help = "impact velocities, m/s [0.075,0.15,0.3,0.5]"};
    opts[k++] = (gw_opt){.name = "n", .kind = GW_OPT_STRING, .dest = &nrange, .metavar = "A:B",
                         .help = "column sizes for the tau_N fit; B is the front column [5:40]"};
    opts[k++] = (gw_opt){.name = "threshold", .kind = GW_OPT_DOUBLE, .dest = &frac, .metavar = "F",
                         .help = "front threshold as a fraction of F_max(1) [0.1]", .lo = 0, .hi = 1, .open_lo = 1};
    chain_cli_sweep_opts(opts, &k, &jobs, &quiet);
    opts[k] = (gw_opt){0};
    int done = chain_cli_parse("wavespeed", "granwave wavespeed [options]", ws_summary, opts, argc, argv);
    if (done >= 0)
        return done;
    if (c.radii)
        return chain_cli_fail("wavespeed --radii: per-bead radii need a fixed N (use granwave chain)");
    gw_err err = {{0}};
    long a, b;
    double *v = NULL;
    int nv = 0;
    if (gw_parse_int_range(nrange, "wavespeed --n", 1, 100000, &a, &b, &err) != GW_OK ||
        gw_parse_double_list_in(vlist, "wavespeed --vimp", 0, GW_CHAIN_VIMP_MAX, 1, &v, &nv, &err) != GW_OK)
        return chain_cli_fail(err.msg);
    if (b - a < 2 || b < 8) {
        free(v);
        return chain_cli_fail("wavespeed --n: need at least 3 sizes and a largest column of >= 8 beads");
    }
    c.params.n = (int)b;
    c.params.v_imp = v[0];
    if (chain_cli_resolve(&c, opts, "wavespeed", &err) != GW_OK ||
        (c.out && gw_mkdir_p(c.out, &err) != GW_OK)) {
        free(v);
        chain_cli_free(&c);
        return chain_cli_fail(err.msg);
    }
    const gw_chain_params *p = &c.params;
    int per_v = (int)(b - a + 1), code = 0;
    gw_chain_result *res = calloc((size_t)(nv * per_v), sizeof *res);
    double *out = calloc(7 * (size_t)nv, sizeof *out);
    double *v_tq = out, *v_front = out + nv, *v_group = out + 2 * nv, *period = out + 3 * nv;
    double *t_q = out + 4 * nv, *fbar = out + 5 * nv, *v_gf = out + 6 * nv;
    if (!res || !out) {
        free(res);
        free(out);
        free(v);
        chain_cli_free(&c);
        return chain_cli_fail("wavespeed: out of memory");
    }
    double t0 = gw_clock_ms();
    if (!quiet)
        fprintf(stderr, "granwave wavespeed: %d collisions\n", nv * per_v);
    int rc = gw_chain_sweep_n(p, &c.run, v, nv, (int)a, (int)b, (int)jobs, !quiet, res, &err);
    for (int iv = 0; rc == GW_OK && iv < nv; iv++) {
        gw_chain_result *rv = &res[iv * per_v];
        double *x = malloc(2 * (size_t)per_v * sizeof *x);
        if (!x) {
            rc = gw_err_set(&err, GW_ENOMEM, "wavespeed: out of memory");
            break;
        }
        int np = 0;
        period[iv] = 0;
        for (int j = 0; j < per_v; j++) {
            x[j] = a + j - 1;
            x[per_v + j] = rv[j].tau_n;
            if (a + j >= 10 && rv[j].n_maxima >= 2) {
                period[iv] += rv[j].period;
                np++;
            }
        }
        period[iv] = np ? period[iv] / np : NAN;
        gw_linfit lf;
        gw_fit_linear(x, x + per_v, per_v, &lf);
        free(x);
        t_q[iv] = lf.c1;
        v_tq[iv] = 4 * p->radius / lf.c1;
        const gw_chain_result *rl = &rv[per_v - 1];
        fbar[iv] = rl->impulse / rl->tau_n;
        double kappa = 1.5 * pow(p->k, 2.0 / 3.0) * cbrt(fbar[iv]);
        v_group[iv] = 2 * p->radius * sqrt(kappa / p->mass);
        v_gf[iv] = v_group[iv] / sqrt(1.5);
        gw_chain_params q = *p;
        q.v_imp = v[iv];
        double ferr = 0;
        v_front[iv] = front_speed(&q, &c.run, frac, &ferr, &err);
        if (!isfinite(v_front[iv]))
            rc = gw_err_set(&err, GW_ESOLVER, "wavespeed: no front fit at v_imp = %g (%s)", v[iv], err.msg);
    }
    double wall_s = (gw_clock_ms() - t0) / 1e3;
    if (rc != GW_OK) {
        fprintf(stderr, "granwave wavespeed: %s\n", err.msg);
        code = rc == GW_EINVAL ? 2 : 1;
    } else {
        double scale = pow(p->k / p->mass, 0.4) * p->radius;
        ws_fit f_tq = power_fit(v, v_tq, nv, scale), f_fr = power_fit(v, v_front, nv, scale);
        ws_fit f_gr = power_fit(v, v_group, nv, scale), f_gf = power_fit(v, v_gf, nv, scale);
        ws_fit f_p = power_fit(v, period, nv, pow(p->mass / p->k, 0.4));
        double c2 = 0, worst = 0;
        for (int iv = 0; iv < nv; iv++) {
            c2 += period[iv] * pow(v[iv], 0.2) / pow(p->mass / p->k, 0.4) / nv;
            double s3[3] = {v_tq[iv], v_front[iv], v_gf[iv]};
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    worst = fmax(worst, fabs(s3[i] - s3[j]) / s3[j]);
        }
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "version", gw_version());
        cJSON_AddItemToObject(o, "v_imp", gw_json_doubles(v, nv));
        cJSON_AddItemToObject(o, "v_tq", gw_json_doubles(v_tq, nv));
        cJSON_AddItemToObject(o, "v_front", gw_json_doubles(v_front, nv));
        cJSON_AddItemToObject(o, "v_group", gw_json_doubles(v_group, nv));
        cJSON_AddItemToObject(o, "v_group_front", gw_json_doubles(v_gf, nv));
        cJSON_AddItemToObject(o, "t_q", gw_json_doubles(t_q, nv));
        cJSON_AddItemToObject(o, "mean_wall_force", gw_json_doubles(fbar, nv));
        cJSON_AddItemToObject(o, "period", gw_json_doubles(period, nv));
        cJSON_AddNumberToObject(o, "beta", f_tq.beta);
        cJSON_AddNumberToObject(o, "beta_err", f_tq.beta_err);
        cJSON_AddNumberToObject(o, "c3", f_tq.c3);
        cJSON_AddNumberToObject(o, "c3_theory", 2.0);
        cJSON *fits = cJSON_AddObjectToObject(o, "fits");
        cJSON_AddItemToObject(fits, "tq", fit_json(&f_tq));
        cJSON_AddItemToObject(fits, "front", fit_json(&f_fr));
        cJSON_AddItemToObject(fits, "group", fit_json(&f_gr));
        cJSON_AddItemToObject(fits, "group_front", fit_json(&f_gf));
        cJSON_AddNumberToObject(o, "c2", c2);
        cJSON_AddNumberToObject(o, "beta_period", f_p.beta);
        cJSON_AddNumberToObject(o, "beta_period_err", f_p.beta_err);
        cJSON_AddNumberToObject(o, "max_disagreement", worst); /* tq, front, group/sqrt(3/2) */
        cJSON_AddNumberToObject(o, "front_threshold_fraction", frac);
        cJSON_AddNumberToObject(o, "n_min", (double)a);
        cJSON_AddNumberToObject(o, "n_max", (double)b);
        cJSON_AddNumberToObject(o, "wall_time_s", wall_s);
        cJSON_AddItemToObject(o, "settings", chain_cli_settings_json(&c));
        char path[4096];
        if (c.out) {
            gw_afile af;
            char *hdr = chain_cli_header(&c, "wavespeed", argc, argv);
            for (char *h = hdr; h && *h; h++)
                if (*h == '\n')
                    *h = ' ';
            if (gw_path_join(path, sizeof path, c.out, "wavespeed.csv") != GW_OK ||
                gw_afile_open(&af, path, &err) != GW_OK) {
                code = 1;
            } else {
                fprintf(af.fp, "# %s\nv_imp_m_s,v_tq_m_s,v_front_m_s,v_group_m_s,v_group_front_m_s,t_q_s,period_s,mean_wall_force_N\n",
                        hdr ? hdr : "");
                for (int iv = 0; iv < nv; iv++)
                    fprintf(af.fp, "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", v[iv], v_tq[iv],
                            v_front[iv], v_group[iv], v_gf[iv], t_q[iv], period[iv], fbar[iv]);
                if (gw_afile_commit(&af, &err) != GW_OK)
                    code = 1;
            }
            if (code == 0 && (gw_path_join(path, sizeof path, c.out, "wavespeed.json") != GW_OK ||
                              gw_json_write(path, o, &err) != GW_OK))
                code = 1;
            if (code)
                fprintf(stderr, "granwave wavespeed --out: %s\n", err.msg);
            free(hdr);
        }
        if (code == 0 && c.json) {
            gw_json_print(o, stdout);
        } else if (code == 0) {
            printf("granwave %s wavespeed (%.1f s)\n  v_imp     v_tq    v_front  v_group  v_group/sqrt(3/2)  (m/s)\n",
                   gw_version(), wall_s);
            for (int iv = 0; iv < nv; iv++)
                printf("  %-8.4g %8.2f %8.2f %8.2f %8.2f\n", v[iv], v_tq[iv], v_front[iv], v_group[iv], v_gf[iv]);
            printf("  beta: tq %.5f +- %.5f, front %.5f +- %.5f, group %.5f +- %.5f\n", f_tq.beta,
                   f_tq.beta_err, f_fr.beta, f_fr.beta_err, f_gr.beta, f_gr.beta_err);
            printf("  C3: tq %.4f, front %.4f, group %.4f, group/sqrt(3/2) %.4f (F.27: 2)\n", f_tq.c3, f_fr.c3,
                   f_gr.c3, f_gf.c3);
            printf("  period: C2 %.4f, beta %.5f; front-speed estimators (tq, front, group/sqrt(3/2)) "
                   "disagree by up to %.1f %%\n", c2, f_p.beta, 100 * worst);
        }
        cJSON_Delete(o);
    }
    for (int i = 0; i < nv * per_v; i++)
        gw_chain_result_free(&res[i]);
    free(res);
    free(out);
    free(v);
    chain_cli_free(&c);
    return code;
}
