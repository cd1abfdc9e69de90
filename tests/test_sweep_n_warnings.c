/*
 * test_sweep_n_warnings.c: the library's N x v grid (gw_chain_sweep_n_warned)
 * says the "no effect" warnings a chain sweep's check pass says
 * (gw_sweep_run_warned), in the same text and count form, the case the
 * result's index (gw_chain_sweep_n gave none; the studies on it did).
 *
 *  1 a sensor body's dashpot of 1e-12 N s/m on 1e-2 kg, 1e7 N/m (damping
 *    ratio 1.58e-15, below rtol) over N = 1, 2 at 0.3 m/s: one line, "the
 *    sensor body's dashpot has no effect in 2 of 2 cases (the first, case
 *    0)", the chain sweep's line over the same cases but for the flag's
 *    dashes (the sweep names its config's key, sensor-damping); the cases
 *    ran (f_max > 0).
 *  2 damping kk with gamma 0: "is no damping: 2 of 2 cases", the sweep's
 *    form.
 *  3 a guide's viscous friction of 1e-15 N s/m over 0.2, 0.3 m/s: "the
 *    guide's friction has no effect in 2 of 2 cases (the first, case 0)".
 *  4 controls: a dashpot of 10 N s/m (ratio 0.016) says nothing (the list
 *    left NULL); a grid refused (no speed) appends nothing; warnings NULL
 *    runs as gw_chain_sweep_n_progress (f_max bit-equal).
 */
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"
#include "gw_sweep.h"
#include "gw_test.h"

/* the grid's warnings over v[0..nv) and N = 1, 2 of p; f_max of its first case */
static int grid(const gw_chain_params *p, const double *v, int nv, char **w, double *f0)
{
    gw_chain_run_opts o = gw_chain_run_opts_default();
    gw_chain_result res[4];
    gw_err err = {{0}};
    *w = NULL;
    int rc = gw_chain_sweep_n_warned(p, &o, v, nv, 1, 2, 1, NULL, NULL, res, w, &err);
    *f0 = rc == GW_OK ? res[0].f_max : -1;
    for (int i = 0; nv > 0 && i < 2 * nv; i++)
        gw_chain_result_free(&res[i]);
    if (rc != GW_OK && nv > 0)
        fprintf(stderr, "grid: %s\n", err.msg);
    return rc;
}

/* the lines of list that begin with prefix */
static int lines_with(const char *list, const char *prefix)
{
    int n = 0;
    for (const char *p = list; p && *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : p + strlen(p))
        n += strncmp(p, prefix, strlen(prefix)) == 0;
    return n;
}

/* text without the dashes of its flags ("--sensor-damping" as "sensor-damping") */
static void undash(char *text)
{
    char *o = text;
    for (const char *p = text; *p;) {
        if (p[0] == '-' && p[1] == '-' && (p == text || p[-1] == ' ' || p[-1] == '('))
            p += 2;
        else
            *o++ = *p++;
    }
    *o = '\0';
}

/* the chain sweep's warnings (gw_sweep_run_warned) over the config text */
static char *sweep_warnings(const char *cfg_text)
{
    const gw_sweep_model *models[] = {&gw_chain_sweep_model}, *m = NULL;
    gw_sweep_config cfg;
    gw_err err = {{0}};
    if (gw_sweep_config_read_string(cfg_text, "test", models, 1, &cfg, &m, &err) != GW_OK) {
        fprintf(stderr, "config: %s\n", err.msg);
        return NULL;
    }
    double *v = malloc((size_t)cfg.ncases * (size_t)m->ncolumns * sizeof *v);
    char *w = NULL;
    if (v && gw_sweep_run_warned(&cfg, m, 1, NULL, NULL, v, &w, &err) != GW_OK)
        fprintf(stderr, "sweep: %s\n", err.msg);
    free(v);
    gw_sweep_config_free(&cfg);
    return w;
}

int main(void)
{
    const double v3 = 0.3, v23[2] = {0.2, 0.3};
    double f0 = 0;
    char *w = NULL;

    /* 1 the sensor's dashpot */
    gw_chain_params p = gw_chain_params_default();
    p.sensor.mass = 1e-2;
    p.sensor.stiffness = 1e7;
    p.sensor.damping = 1e-12;
    int rc = grid(&p, &v3, 1, &w, &f0);
    const char *want = "the sensor body's dashpot has no effect in 2 of 2 cases (the first, case 0): its damping "
                       "ratio c/(2 sqrt(k_s m_s)), at most 1.58e-15 there, is below the case's rtol, and their rows "
                       "are those of --sensor-damping 0 (give a larger --sensor-damping)\n";
    gw_test_true(rc == GW_OK && w && strcmp(w, want) == 0 && f0 > 0,
                 "1 sensor-damping 1e-12 over N = 1, 2: one line, 2 of 2 cases, the first case 0, the cases run");
    if (w && strcmp(w, want) != 0)
        fprintf(stderr, "  got: %s", w);
    char *sw = sweep_warnings("[sweep]\nmodel = chain\n[grid]\nn = 1, 2\n[params]\nvimp = 0.3\nsensor-mass = 1e-2\n"
                              "sensor-stiffness = 1e7\nsensor-damping = 1e-12\n");
    char *mine = w ? strdup(w) : NULL;
    if (mine)
        undash(mine);
    gw_test_true(sw && mine && lines_with(sw, "the sensor body's dashpot") == 1 && strstr(sw, mine) != NULL,
                 "1 the chain sweep's line over the same cases, but for the flag's dashes");
    if (sw && mine && !strstr(sw, mine))
        fprintf(stderr, "  sweep: %s  grid: %s", sw, mine);
    free(sw);
    free(mine);
    free(w);

    /* 2 damping kk with gamma 0 */
    p = gw_chain_params_default();
    p.damping = GW_DAMP_KUWABARA_KONO;
    p.gamma = 0;
    rc = grid(&p, &v3, 1, &w, &f0);
    gw_test_true(rc == GW_OK && lines_with(w, "damping kk with gamma 0, or hc with alpha 0, is no damping: 2 of 2 "
                                              "cases, whose rows are those of damping none") == 1,
                 "2 damping kk, gamma 0: 'is no damping: 2 of 2 cases'");
    free(w);

    /* 3 the guide's friction */
    p = gw_chain_params_default();
    p.guide.viscous = 1e-15;
    rc = grid(&p, v23, 2, &w, &f0);
    gw_test_true(rc == GW_OK && lines_with(w, "the guide's friction has no effect in 4 of 4 cases (the first, case "
                                              "0): ") == 1,
                 "3 guide-viscous 1e-15 over 0.2, 0.3 m/s and N = 1, 2: 4 of 4 cases, the first case 0");
    free(w);

    /* 4 controls */
    p = gw_chain_params_default();
    p.sensor.mass = 1e-2;
    p.sensor.stiffness = 1e7;
    p.sensor.damping = 10;
    rc = grid(&p, &v3, 1, &w, &f0);
    gw_test_true(rc == GW_OK && w == NULL, "4 a dashpot that acts (sensor-damping 10): no warning");
    free(w);
    p.sensor.damping = 1e-12;
    rc = grid(&p, &v3, 0, &w, &f0);
    gw_test_true(rc == GW_EINVAL && w == NULL, "4 a grid refused (no speed): GW_EINVAL, nothing appended");
    free(w);
    {
        gw_chain_run_opts o = gw_chain_run_opts_default();
        gw_chain_result a[2], b[2];
        gw_err err = {{0}};
        p = gw_chain_params_default();
        int ra = gw_chain_sweep_n_warned(&p, &o, &v3, 1, 1, 2, 1, NULL, NULL, a, NULL, &err);
        int rb = gw_chain_sweep_n_progress(&p, &o, &v3, 1, 1, 2, 1, NULL, NULL, b, &err);
        gw_test_true(ra == GW_OK && rb == GW_OK && a[0].f_max == b[0].f_max && a[1].f_max == b[1].f_max,
                     "4 warnings NULL: the grid's results those of gw_chain_sweep_n_progress (bit-equal)");
        for (int i = 0; i < 2; i++)
            gw_chain_result_free(&a[i]), gw_chain_result_free(&b[i]);
    }
    return gw_test_summary("test_sweep_n_warnings");
}
