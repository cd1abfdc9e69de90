/*
 * test_falcon_one_path.c: `granwave falcon` and the library's
 * gw_chain_falcon_run are one path (granwave issue #18). The program ran its
 * own loop of collisions beside the library's study, because the study's
 * outcome lacked the per-bead final velocities and the traces the program
 * writes; two paths for one study could give two answers, and did:
 * `--dt-out 0` sampled every tau_1/200 in the program and tau_1/10 (the
 * documented default by --accuracy) in the library and Python, so F_max,
 * the steps and the energy error differed.
 *
 * For a few option sets, the library's outcome (traces on, the options set
 * by name in the study's table, a solver option meaning accuracy 0, as the
 * program and Python do) is written in the program's formats and compared
 * with the program's --out files byte for byte (past the header line):
 * falcon_runs.csv, falcon_final_velocities.csv, and the traces
 * (trace_n*_wall_force.csv, trace_n7_beads.csv, written by gw_chain_trace_write
 * under the program's own header); and every per-velocity number of
 * falcon_summary.json equals the outcome's array of the same name, exactly.
 * Usage: test_falcon_one_path PATH-TO-granwave
 */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_chain_study.h"
#include "gw_test.h"
#include "gw_test_files.h"

/* Past the first line (the provenance header). */
static const char *body(const char *s)
{
    const char *nl = s ? strchr(s, '\n') : NULL;
    return nl ? nl + 1 : "";
}

/* A growing string with printf. */
typedef struct sbuf {
    char *s;
    size_t len, cap;
} sbuf;

static void sb_printf(sbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void sb_printf(sbuf *b, const char *fmt, ...)
{
    va_list ap;
    for (;;) {
        va_start(ap, fmt);
        int n = vsnprintf(b->s ? b->s + b->len : NULL, b->s ? b->cap - b->len : 0, fmt, ap);
        va_end(ap);
        if (n < 0)
            return;
        if (b->s && b->len + (size_t)n < b->cap) {
            b->len += (size_t)n;
            return;
        }
        b->cap = 2 * (b->cap + (size_t)n + 64);
        b->s = realloc(b->s, b->cap);
        if (!b->s)
            abort();
    }
}

/* The program's falcon_runs.csv body for outcome o (app/chain/chain_falcon.c). */
static char *runs_csv(const gw_chain_falcon_outcome *o)
{
    sbuf b = {0};
    sb_printf(&b, "v_imp_m_s,h_mm,n,f_max_N,tau_max_s,tau_n_s,period_s,n_maxima,n_s,cluster,"
                  "e_rel_over_e_k,eps_eff,eps_col,energy_error,steps,rhs_evals,t_max_s,dt_out_s,dt_s,dt_max_s,held\n");
    for (int iv = 0; iv < o->nv; iv++)
        for (int k = 0; k < o->nn; k++) {
            int c = iv * o->nn + k;
            sb_printf(&b, "%.10g,%.4g,%d,%.12g,%.12g,%.12g,%.12g,%d,%d,%d,%.12g,%.12g,%.12g,%.4g,%ld,%ld,%.17g,%.17g,"
                          "%.17g,%.17g,%d\n",
                      o->v_imp[iv], o->h_mm[iv], (int)o->n[k], o->f_max[c], o->tau_max[c], o->tau_n[c], o->period[c],
                      (int)o->n_maxima[c], (int)o->n_s[c], (int)o->cluster[c], o->e_rel_over_e_k[c], o->eps_eff[c],
                      o->eps_col[c], o->energy_error[c], (long)o->steps[c], (long)o->rhs_evals[c], o->t_max[c],
                      o->dt_out[c], o->dt[c], o->dt_max[c], o->held[c]);
        }
    return b.s;
}

/* The program's falcon_final_velocities.csv body for o. */
static char *beads_csv(const gw_chain_falcon_outcome *o)
{
    sbuf b = {0};
    sb_printf(&b, "v_imp_m_s,n,bead,final_v_m_s,detach_t_s,v_tau_n_m_s\n");
    for (int i = 0; i < o->nbeads; i++)
        sb_printf(&b, "%.10g,%d,%d,%.12g,%.12g,%.12g\n", o->bead_v_imp[i], (int)o->bead_n[i], (int)o->bead[i],
                  o->final_v[i], o->detach_t[i], o->v_tau_n[i]);
    return b.s;
}

/* The file name of a trace file. */
static void tpath(char *p, size_t n, const char *dir, int nb, const char *what)
{
    snprintf(p, n, "%s/trace_n%d_%s.csv", dir, nb, what);
}

/* argv-style option set: "--name value" pairs (values never start with "--"). */
static void one_set(const char *program, const char *label, const char *const *args)
{
    printf("--- %s\n", label);
    char dir[] = "/tmp/gw_falcon_one_path.XXXXXX", lib[sizeof dir + 8], cmd[4096];
    if (!mkdtemp(dir)) {
        gw_test_true(0, "mkdtemp");
        return;
    }
    char prog[sizeof dir + 8];
    snprintf(lib, sizeof lib, "%s/lib", dir);
    snprintf(prog, sizeof prog, "%s/prog", dir);
    /* the program */
    int len = snprintf(cmd, sizeof cmd, "'%s' falcon", program);
    for (int i = 0; args[i]; i++)
        len += snprintf(cmd + len, sizeof cmd - (size_t)len, " '%s'", args[i]);
    snprintf(cmd + len, sizeof cmd - (size_t)len, " --out '%s/prog' --quiet --jobs 2 > /dev/null 2> '%s/stderr'", dir,
             dir);
    int prc = system(cmd);
    gw_test_true(prc == 0, "the program ran (exit 0)");
    /* the library, from the same options by name */
    gw_chain_falcon_setup s;
    gw_chain_falcon_setup_init(&s);
    gw_err err = {{0}};
    int rc = GW_OK, solver_given = 0;
    for (int i = 0; args[i] && rc == GW_OK; i += 2) {
        const char *name = args[i] + 2;
        rc = gw_param_set(gw_chain_falcon_setup_params(), &s, name, args[i + 1], &err);
        for (const char *const *sv = (const char *const[]){"solver", "method", "rtol", "atol", "dt", NULL}; *sv; sv++)
            solver_given |= strcmp(name, *sv) == 0;
    }
    if (solver_given)
        s.accuracy = 0; /* the solver options as given (as the program and Python) */
    s.jobs = 2;
    s.traces = 1;
    gw_chain_falcon_outcome o;
    if (rc == GW_OK)
        rc = gw_chain_falcon_run(&s, NULL, NULL, &o, &err);
    else
        memset(&o, 0, sizeof o);
    gw_test_true(rc == GW_OK, rc == GW_OK ? "gw_chain_falcon_run ran" : err.msg);
    if (prc == 0 && rc == GW_OK) {
        char p[4200];
        snprintf(p, sizeof p, "%s/prog/falcon_runs.csv", dir);
        char *f = gw_test_slurp(p, NULL), *mine = runs_csv(&o);
        gw_test_true(f && strcmp(body(f), mine) == 0, "falcon_runs.csv = the outcome's cases, byte for byte");
        free(f);
        free(mine);
        snprintf(p, sizeof p, "%s/prog/falcon_final_velocities.csv", dir);
        f = gw_test_slurp(p, NULL);
        mine = beads_csv(&o);
        gw_test_true(f && strcmp(body(f), mine) == 0,
                     "falcon_final_velocities.csv = the outcome's bead table, byte for byte");
        free(f);
        free(mine);
        /* the traces: the library's, written under the program's header */
        int want = (s.n[1] >= 7) + (s.n[1] >= 15) + (s.n[1] >= 30);
        gw_test_true(o.ntrace == want, "the traces of N = 7, 15, 30 up to n_hi");
        char mk[4300];
        snprintf(mk, sizeof mk, "mkdir -p '%s'", lib);
        int mrc = system(mk);
        for (int k = 0; mrc == 0 && k < o.ntrace; k++) {
            const gw_chain_falcon_trace *t = &o.trace[k];
            char pw[4200], lw[4200], stem[32], what[96];
            snprintf(stem, sizeof stem, "trace_n%d", t->n);
            tpath(pw, sizeof pw, prog, t->n, "wall_force");
            tpath(lw, sizeof lw, lib, t->n, "wall_force");
            char *pf = gw_test_slurp(pw, NULL), *nl = pf ? strchr(pf, '\n') : NULL;
            char *hdr = nl && nl - pf > 2 ? strndup(pf + 2, (size_t)(nl - pf - 2)) : NULL; /* "# " ... "\n" */
            int wrc = hdr ? gw_chain_trace_write(&t->tr, lib, stem, hdr, &err) : GW_EIO;
            char *lf = wrc == GW_OK ? gw_test_slurp(lw, NULL) : NULL;
            snprintf(what, sizeof what, "trace_n%d_wall_force.csv = the outcome's trace, byte for byte", t->n);
            gw_test_true(pf && lf && strcmp(pf, lf) == 0, what);
            free(pf);
            free(lf);
            free(hdr);
            tpath(pw, sizeof pw, prog, t->n, "beads");
            tpath(lw, sizeof lw, lib, t->n, "beads");
            pf = gw_test_slurp(pw, NULL);
            lf = gw_test_slurp(lw, NULL);
            snprintf(what, sizeof what, "trace_n%d_beads.csv: %s", t->n,
                     t->n == 7 ? "the outcome's, byte for byte" : "neither writes it");
            gw_test_true(t->n == 7 ? (pf && lf && strcmp(pf, lf) == 0) : (!pf && !lf && t->tr.n == 0), what);
            free(pf);
            free(lf);
        }
        /* every per-velocity number of the JSON summary: the outcome's array of that name */
        snprintf(p, sizeof p, "%s/prog/falcon_summary.json", dir);
        f = gw_test_slurp(p, NULL);
        cJSON *j = f ? cJSON_Parse(f) : NULL;
        free(f);
        const cJSON *vel = cJSON_GetObjectItemCaseSensitive(j, "velocities");
        int nkeys = 0, bad = 0;
        for (const gw_param *fd = gw_chain_falcon_outcome_fields(); fd->name; fd++) {
            if (fd->type != GW_PARAM_DARRAY || !fd->rows || strcmp(fd->rows, "nv") != 0 || fd->cols)
                continue;
            const double *a = *(double *const *)((const char *)&o + fd->offset);
            for (int iv = 0; iv < o.nv; iv++) {
                const cJSON *x = cJSON_GetObjectItemCaseSensitive(cJSON_GetArrayItem(vel, iv), fd->name);
                double jv = cJSON_IsNumber(x) ? x->valuedouble : NAN; /* null: NaN */
                int same = x && (jv == a[iv] || (isnan(jv) && isnan(a[iv])));
                if (!same)
                    printf("  %s[%d]: program %.17g, library %.17g\n", fd->name, iv, jv, a[iv]);
                bad += !same;
            }
            nkeys++;
        }
        cJSON *acc = cJSON_GetObjectItemCaseSensitive(j, "accuracy_target");
        cJSON *unf = cJSON_GetObjectItemCaseSensitive(j, "unfinished");
        char what[160];
        snprintf(what, sizeof what, "falcon_summary.json: %d per-velocity keys x %d velocities = the outcome's, exactly",
                 nkeys, o.nv);
        gw_test_true(j && cJSON_GetArraySize(vel) == o.nv && nkeys >= 21 && bad == 0, what);
        gw_test_true(j && (acc ? acc->valuedouble == o.accuracy : o.accuracy == 0) && unf &&
                         unf->valuedouble == o.unfinished,
                     "accuracy_target and unfinished as the outcome's");
        cJSON_Delete(j);
    }
    gw_chain_falcon_outcome_free(&o);
    gw_chain_falcon_setup_clear(&s);
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        printf("note: could not remove %s\n", dir);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: test_falcon_one_path PATH-TO-granwave\n");
        return 2;
    }
    const char *pg = argv[1];
    one_set(pg, "RK4 by the accuracy target, one speed", (const char *const[]){"--n", "1:8", "--heights", "none", NULL});
    one_set(pg, "three speeds (one a height), N = 5..16: traces 7 and 15",
            (const char *const[]){"--n", "5:16", "--vimp", "0.2,0.45", "--heights", "3.1", NULL});
    one_set(pg, "--dt-out 0: the default sampling (the program sampled every tau_1/200)",
            (const char *const[]){"--n", "1:8", "--heights", "none", "--dt-out", "0", NULL});
    one_set(pg, "--solver cvode (the default's value, given)",
            (const char *const[]){"--n", "1:8", "--heights", "none", "--solver", "cvode", NULL});
    one_set(pg, "Hunt-Crossley by restitution: outside the step study, cvode",
            (const char *const[]){"--n", "2:8", "--heights", "none", "--damping", "hc", "--restitution", "0.9", NULL});
    one_set(pg, "arkode under gravity, a height",
            (const char *const[]){"--n", "1:7", "--vimp", "0.25", "--heights", "2", "--gravity", "9.81", "--solver",
                                  "arkode", NULL});
    return gw_test_summary("test_falcon_one_path");
}
