/*
 * layer_sweep_model.c: the 2D layer (docs/physics.md section 2) as the `layer` model
 * of `granwave sweep` (gw_sweep.h): one block impact per case, for bouncing
 * diagrams and impact-point statistics.
 *
 * Keys: the options of `granwave layer-impact` without json/out (one option
 * table, layer_cli.c, so a case and the command resolve the same options to the
 * same gw_layer_impact call); the flags remove-walls and full take 0/1/true/
 * false. Extra keys place the block on one of `points` impact points `spacing`
 * apart around x (docs/physics.md 2.3, statistics: N = 100 points d_i = 0.05 m apart):
 *     x_impact = x + (point - (points - 1) / 2) spacing          (m, from the box centre)
 * with 0 <= point < points (defaults point 0, points 1, spacing 0.05 m).
 *
 * Row (SI; angles in degrees): x_impact, bounced (0/1), e_n, e, alpha_r
 * (B.16-B.18), v_ni, v_nr, v_r (m/s), penetration (m), penetration_rm (in R_m),
 * dissipated_first_contact and block_loss_first_contact (over E_incident,
 * docs/physics.md 2.5), energy_error (ledger closure B.7-B.14), wave_speed (m/s, from
 * the crowns' strain peaks), t_end (s), steps, then (added last, so readers of
 * the earlier columns keep working) the first free-flight maximum e_n_first,
 * e_first, alpha_r_first, v_nr_first, v_r_first, and the event times t_leave
 * (the block leaves moving up), t_rebound (T_i) and t_f (T_f) in s
 * (layer_outcome.c). Undefined values (e.g. e_n of a block that does not
 * bounce, a wave speed without enough crowns) are NaN, written as "nan"
 * whatever the sign bit, so tables are byte-identical however the cases ran.
 * Undecided outcomes are NaN too: bounced = nan when the run ended before the
 * verdict, e_n = e = alpha_r = nan in a bouncing row when it ended before T_f
 * (or `until = verdict` stopped it); layer-stats leaves such rows out of the
 * shares and means they cannot enter, and says how many. No wall-clock time
 * in the row.
 *
 * The sample file is read for every case (and once more by the check pass),
 * with no cache: parsing, reading and checking a case on the 300-disc sample
 * takes 0.18 ms (`sweep --check` of 8000 cases in 1.4 s, bench/README_layer.md),
 * 0.5 % of the cheapest impact measured (40 ms) and 0.004 % of the mean one
 * (4.5 s); no state is shared between the sweep's threads.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "gw_cli.h"
#include "gw_sweep.h"
#include "layer_cli.h"

static const char *const columns[] = {
    "x_impact", "bounced", "e_n", "e", "alpha_r", "v_ni", "v_nr", "v_r", "penetration", "penetration_rm",
    "dissipated_first_contact", "block_loss_first_contact", "energy_error", "wave_speed", "t_end", "steps",
    "e_n_first", "e_first", "alpha_r_first", "v_nr_first", "v_r_first", "t_leave", "t_rebound", "t_f"};
#define NCOLUMNS ((int)(sizeof columns / sizeof columns[0]))

typedef struct case_opts {
    layer_impact_cli c;
    gw_opt o[LAYER_IMPACT_NOPTS + 4]; /* + point, points, spacing, {0} */
    long point, points;
    double spacing;
} case_opts;

static void case_init(case_opts *co)
{
    int i = layer_impact_options(&co->c, co->o);
    co->point = 0;
    co->points = 1;
    co->spacing = 0.05;
    co->o[i++] = OPT_L("point", &co->point, "K", "impact point, 0 .. points-1 [0]", 0, 1000000000);
    co->o[i++] = OPT_L("points", &co->points, "N", "number of impact points around x [1]", 1, 1000000000);
    co->o[i++] = OPT_D("spacing", &co->spacing, "D", "distance between impact points d_i, m [0.05]", 0, 1e6, 0);
    co->o[i] = (gw_opt){0};
}

static int has_key(const char *name)
{
    case_opts co;
    case_init(&co);
    return gw_cli_find(co.o, name) != NULL;
}


/* Parse the pairs with the command's table (as argv "--name value", flags as
 * "--name" when true), resolve them, place the impact point and read the
 * sample into *s (freed by the caller with gw_layer_sample_free, also after a
 * failure). Every failure is GW_EINVAL with a message naming the key or file. */
static int prepare(case_opts *co, int nk, const char *const *names, const char *const *values,
                   gw_layer_sample *s, gw_err *err)
{
    memset(s, 0, sizeof *s);
    case_init(co);
    char **argv = calloc(2 * (size_t)nk + 1, sizeof *argv);
    char **dashed = calloc((size_t)nk + 1, sizeof *dashed); /* the "--name" strings */
    int argc = 0, rc = argv && dashed ? GW_OK : gw_err_set(err, GW_ENOMEM, "out of memory");
    for (int i = 0; rc == GW_OK && i < nk; i++) {
        const gw_opt *o = gw_cli_find(co->o, names[i]);
        const int flag = o && o->kind == GW_OPT_FLAG, on = flag ? gw_parse_flag(values[i]) : 1;
        size_t len = strlen(names[i]) + 3;
        if (on < 0)
            rc = gw_err_set(err, GW_EINVAL, "%s: '%s' is not a flag value (0, 1, true, false)", names[i], values[i]);
        else if (on && !(dashed[i] = malloc(len)))
            rc = gw_err_set(err, GW_ENOMEM, "out of memory");
        else if (on) {
            snprintf(dashed[i], len, "--%s", names[i]);
            argv[argc++] = dashed[i];
            if (!flag) /* an unknown key is refused by the parser */
                argv[argc++] = (char *)values[i];
        }
    }
    int help = 0, npos = 0;
    const char *pos[1];
    if (rc == GW_OK)
        rc = gw_cli_parse("layer", co->o, argc, argv, &help, pos, 0, &npos, err);
    for (int i = 0; dashed && i < nk; i++)
        free(dashed[i]);
    free(dashed);
    free(argv);
    if (rc == GW_OK)
        rc = layer_impact_resolve(&co->c, err);
    if (rc == GW_OK && co->point >= co->points)
        rc = gw_err_set(err, GW_EINVAL, "point: %ld is outside [0, points - 1 = %ld]", co->point, co->points - 1);
    if (rc == GW_OK) {
        co->c.ip.x += ((double)co->point - 0.5 * (double)(co->points - 1)) * co->spacing;
        rc = gw_layer_sample_read(co->c.sample, s, err);
    }
    if (rc == GW_OK)
        rc = layer_impact_use_sample(&co->c, co->o, s, err);
    return rc == GW_OK || rc == GW_ENOMEM ? rc : GW_EINVAL;
}

static int check(int nk, const char *const *names, const char *const *values, gw_err *err)
{
    case_opts co;
    gw_layer_sample s;
    int rc = prepare(&co, nk, names, values, &s, err);
    gw_layer_sample_free(&s);
    return rc;
}

/* NaN with a clear sign bit, so that every undefined value prints as "nan". */
static double canon(double v)
{
    return isnan(v) ? NAN : v;
}

static int run(int nk, const char *const *names, const char *const *values, double *out, gw_err *err)
{
    case_opts co;
    gw_layer_sample s;
    gw_layer_impact_result r;
    memset(&r, 0, sizeof r);
    int rc = prepare(&co, nk, names, values, &s, err);
    if (rc == GW_OK) {
        rc = gw_layer_impact(&s, &co.c.m.lp, &co.c.ip, co.c.type, &co.c.sp, NULL, &r, err);
        if (rc == GW_EUNSUPPORTED) /* a bad input found only by the run */
            rc = GW_EINVAL;
    }
    if (rc == GW_OK) {
        const double v[NCOLUMNS] = {co.c.ip.x, r.bounced < 0 ? NAN : r.bounced, r.e_n, r.e, r.alpha_r_deg,
                                    r.v_ni, r.v_nr, r.v_r, r.penetration, r.penetration / co.c.rm,
                                    r.dissipated_first_contact, r.block_loss_first_contact, r.energy_error,
                                    r.wave_speed, r.t_end, (double)r.stats.steps, r.e_n_first, r.e_first,
                                    r.alpha_r_first_deg, r.v_nr_first, r.v_r_first, r.t_leave, r.t_rebound,
                                    r.t_f};
        for (int i = 0; i < NCOLUMNS; i++)
            out[i] = canon(v[i]);
    }
    gw_layer_impact_result_free(&r);
    gw_layer_sample_free(&s);
    return rc;
}

const gw_sweep_model gw_layer_sweep_model = {"layer", NCOLUMNS, columns, has_key, run, check};
