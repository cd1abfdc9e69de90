/*
 * layer_cli.c: the option tables of the layer commands (layer_cli.h). One
 * table for an impact (docs/physics.md 2.3: R_b = rb-rm R_m, V_i, alpha_i, impact
 * abscissa, height H = height-rm R_m; B.5, B.6) for `granwave layer-impact`,
 * whose values the library resolves (gw_layer_impact_plan_make), and one for
 * `granwave layer-make`.
 * Units: SI, angles in degrees.
 */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "gw_cli.h"
#include "layer_cli.h"

/* The option of row name of table t writing into dest: name, help, metavar,
 * range and default are the row's, the value is checked by the row
 * (gw_cli_opt_param). A name missing from the table, or a row of a type the
 * command line cannot hold, is a bug: the option is then left unchecked and
 * layer_opts_ok reports it. */
static void row_opt(const gw_param *t, const char *name, void *dest, gw_opt *o)
{
    const gw_param *p = gw_param_find(t, name);
    if (!p || gw_cli_opt_param(p, dest, o, NULL) != GW_OK)
        *o = (gw_opt){.name = name, .kind = GW_OPT_STRING, .dest = dest, .help = "(not in the table)"};
}

int layer_opts_ok(const gw_opt *o, gw_err *err)
{
    for (; o->name; o++)
        if (o->help && strcmp(o->help, "(not in the table)") == 0)
            return gw_err_set(err, GW_EINVAL, "--%s: no row of that name in the parameter table (a bug)", o->name);
    return GW_OK;
}

int layer_mat_options(const gw_param *t, layer_mat_cli *m, gw_opt *o)
{
    m->lp = gw_layer_params_default(); /* the fields the table does not set */
    int i = 0;
    /* the rows of layer_setup_rows.h, in both commands' tables */
    row_opt(t, "friction", &m->lp.friction_deg, &o[i++]);
    row_opt(t, "shear-modulus", &m->lp.shear_modulus, &o[i++]);
    row_opt(t, "poisson", &m->lp.poisson, &o[i++]);
    row_opt(t, "density", &m->lp.density, &o[i++]);
    row_opt(t, "gravity", &m->lp.gravity, &o[i++]);
    row_opt(t, "skin", &m->lp.skin, &o[i++]);
    row_opt(t, "mass-law", &m->mass_law, &o[i++]);
    row_opt(t, "clump-mass", &m->clump_mass, &o[i++]);
    return i;
}

int layer_impact_options(layer_impact_cli *c, gw_opt *o)
{
    const gw_param *t = gw_layer_impact_setup_params();
    memset(c, 0, sizeof *c);
    int i = layer_mat_options(t, &c->m, o);
    c->ip = gw_layer_impact_params_default(); /* the fields the table does not set */
    /* the rows of the library's table (layer_setup.c), in the order of --help;
     * the physical ranges are the rows', so that the command, a sweep case and
     * the library refuse the same values with the same message. An option added
     * here must also raise LAYER_IMPACT_NOPTS (layer_cli.h): callers size their
     * tables by it. */
    row_opt(t, "sample", &c->sample, &o[i++]);
    row_opt(t, "rb-rm", &c->ip.rb_rm, &o[i++]);
    row_opt(t, "vi", &c->ip.vi, &o[i++]);
    row_opt(t, "alpha", &c->ip.alpha_deg, &o[i++]);
    row_opt(t, "x", &c->ip.x, &o[i++]);
    row_opt(t, "height-rm", &c->ip.height_rm, &o[i++]);
    row_opt(t, "gap", &c->ip.gap, &o[i++]);
    row_opt(t, "t-max", &c->ip.t_max, &o[i++]);
    row_opt(t, "dt-out", &c->ip.dt_out, &o[i++]);
    row_opt(t, "ring-width", &c->ip.ring_width, &o[i++]);
    row_opt(t, "rings", &c->rings, &o[i++]);
    row_opt(t, "solver", &c->solver, &o[i++]); /* not given: verlet, or rk4 with --exact */
    row_opt(t, "method", &c->method, &o[i++]);
    row_opt(t, "dt", &c->dt, &o[i++]);
    row_opt(t, "exact", &c->exact, &o[i++]);
    row_opt(t, "rtol", &c->rtol, &o[i++]);
    row_opt(t, "atol", &c->atol, &o[i++]);
    row_opt(t, "energy-tol", &c->ip.energy_tol, &o[i++]);
    row_opt(t, "remove-walls", &c->ip.remove_walls, &o[i++]);
    row_opt(t, "side-walls", &c->ip.side_walls, &o[i++]);
    row_opt(t, "full", &c->ip.full, &o[i++]);
    row_opt(t, "other-settling", &c->ip.other_settling, &o[i++]);
    row_opt(t, "zero-springs", &c->ip.zero_springs, &o[i++]);
    row_opt(t, "until", &c->until, &o[i++]);
    return i;
}

int layer_make_options(layer_make_cli *c, gw_opt *o)
{
    const gw_param *t = gw_layer_make_setup_params();
    memset(c, 0, sizeof *c);
    int i = layer_mat_options(t, &c->m, o);
    c->mp = gw_layer_make_params_default(); /* the fields the table does not set */
    /* the final overlap check is O(n^2): 1e5 particles take seconds there (and
     * days of pluviation before): the table's n is at most 1e5 */
    row_opt(t, "n", &c->n, &o[i++]);
    row_opt(t, "rm", &c->mp.rm, &o[i++]);
    row_opt(t, "volume-ratio", &c->mp.volume_ratio, &o[i++]);
    row_opt(t, "width-rm", &c->mp.width_rm, &o[i++]);
    row_opt(t, "seed", &c->seed, &o[i++]);
    row_opt(t, "ke-threshold", &c->mp.ke_threshold, &o[i++]);
    row_opt(t, "t-max", &c->mp.t_max, &o[i++]);
    row_opt(t, "damping", &c->mp.damping, &o[i++]);
    row_opt(t, "modulus-factor", &c->mp.modulus_factor, &o[i++]);
    row_opt(t, "dt", &c->mp.dt, &o[i++]);
    row_opt(t, "solver", &c->solver, &o[i++]);
    row_opt(t, "height-rm", &c->mp.height_rm, &o[i++]);
    row_opt(t, "clumps", &c->mp.clumps, &o[i++]);
    row_opt(t, "aspect-max", &c->mp.aspect_max, &o[i++]);
    row_opt(t, "out", &c->out, &o[i++]);
    o[i - 1].help = "sample file to write (required)"; /* the library's is optional */
    o[i++] = (gw_opt){.name = "json", .kind = GW_OPT_FLAG, .dest = &c->json, .help = "print the result as JSON"};
    return i;
}
