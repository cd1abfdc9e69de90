/*
 * layer_create.c: the disc layer as an object (docs/physics.md 2.1): its
 * parameters (defaults and checks), the material laws it is made with,
 *   K_n = 2 sqrt(2 R_p) G / (3 (1 - nu))                  (B.3)
 *   K_t / F_n^(1/3) = 2 (3 G^2 (1 - nu) R_p)^(1/3) / (2 - nu)   (B.4)
 *   m = pi r^2 rho (disc, unit thickness) or 4/3 pi r^3 rho (sphere),
 *   I = m r^2 / 2 (disc) or 2/5 m r^2 (sphere),
 * its creation from bodies and freeing, and the accessors of its state and
 * counters. Separate from the equations of motion (layer_model.c): nothing
 * here runs within a step.
 * Units: SI (m, kg, kg m^2, Pa, N/m^(3/2)).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_locale.h"
#include "layer_impl.h"

gw_layer_params gw_layer_params_default(void)
{
    gw_layer_params p;
    memset(&p, 0, sizeof p);
    p.shear_modulus = 40e9;
    p.poisson = 0.25;
    p.friction_deg = 30;
    p.density = 2650;
    p.gravity = 9.81;
    p.width = 50 * 0.325;
    p.walls = GW_LAYER_WALLS_ALL;
    p.mass_law = GW_LAYER_MASS_DISC;
    p.damping = 0;
    p.skin = 0.1;
    return p;
}

int gw_layer_params_validate(const gw_layer_params *p, gw_err *err)
{
    if (!p)
        return gw_err_set(err, GW_EINVAL, "gw_layer_params_validate: p is NULL");
    int rc;
    /* the upper bounds keep K_n u^(3/2) and the energies finite in double
     * precision (diamond is 5e11 Pa, osmium 2.2e4 kg/m^3) */
    if ((rc = gw_check_range(p->shear_modulus, "shear modulus G (Pa)", 1e-3, 1e15, err)) != GW_OK ||
        (rc = gw_check_range(p->poisson, "Poisson ratio nu", 0, 0.499999, err)) != GW_OK ||
        (rc = gw_check_range(p->density, "density (kg/m^3)", 1e-6, 1e6, err)) != GW_OK ||
        (rc = gw_check_range(p->gravity, "gravity (m/s^2)", 0, 1e4, err)) != GW_OK ||
        (rc = gw_check_positive(p->width, "box width (m)", err)) != GW_OK ||
        (rc = gw_check_range(p->damping, "normal damping alpha (s/m)", 0, 1e3, err)) != GW_OK ||
        (rc = gw_check_range(p->skin, "contact-list skin (m)", GW_LAYER_SKIN_MIN, 1e6, err)) != GW_OK)
        return rc;
    char fs[32]; /* as given, not rounded onto 90 or 0 */
    if (!(p->friction_deg >= 0 && p->friction_deg < 90))
        return gw_err_set(err, GW_EINVAL, "friction angle phi: %s deg is outside [0, 90)",
                          gw_num_text(fs, sizeof fs, p->friction_deg));
    if (p->mass_law != GW_LAYER_MASS_DISC && p->mass_law != GW_LAYER_MASS_SPHERE)
        return gw_err_set(err, GW_EINVAL, "mass law: unknown value %d", p->mass_law);
    if (p->clump_mass != GW_LAYER_CLUMP_MASS_SUM && p->clump_mass != GW_LAYER_CLUMP_MASS_UNION)
        return gw_err_set(err, GW_EINVAL, "clump mass: unknown value %d", p->clump_mass);
    /* named as the option (the program's --mass-law, Python's mass_law): the
     * message named none, and an impact's union comes from its sample */
    if (p->clump_mass == GW_LAYER_CLUMP_MASS_UNION && p->mass_law != GW_LAYER_MASS_DISC)
        return gw_err_set(err, GW_EINVAL, "mass-law: sphere with clump mass 'union', which weighs a clump as the "
                          "area of its members' union (the disc law): give mass-law disc, or clump-mass sum");
    if (p->walls < 0 || p->walls > GW_LAYER_WALLS_ALL)
        return gw_err_set(err, GW_EINVAL, "walls: bad mask %d", p->walls);
    /* the yes/no members: -1 or 2 ran as 1 with GW_OK (the fiftieth pass) */
    if (p->no_events != 0 && p->no_events != 1)
        return gw_err_set(err, GW_EINVAL, "no_events: %d is not a flag (0 or 1)", p->no_events);
    if (p->potential_from_start != 0 && p->potential_from_start != 1)
        return gw_err_set(err, GW_EINVAL, "potential_from_start: %d is not a flag (0 or 1)", p->potential_from_start);
    return GW_OK;
}

double gw_layer_kn(const gw_layer_params *p, double rp)
{
    if (!p || !(rp >= 0))
        return NAN;
    return 2.0 * sqrt(2.0 * rp) * p->shear_modulus / (3.0 * (1.0 - p->poisson));
}

double gw_layer_kt_factor(const gw_layer_params *p, double rp)
{
    if (!p || !(rp >= 0)) /* cbrt of a negative rp gave a negative factor, where K_n is NaN */
        return NAN;
    double G = p->shear_modulus, nu = p->poisson;
    return 2.0 * cbrt(3.0 * G * G * (1.0 - nu) * rp) / (2.0 - nu);
}

double gw_layer_mass(const gw_layer_params *p, double r)
{
    if (!p)
        return NAN;
    if (p->mass_law == GW_LAYER_MASS_SPHERE)
        return 4.0 / 3.0 * M_PI * r * r * r * p->density;
    return M_PI * r * r * p->density;
}

double gw_layer_inertia(const gw_layer_params *p, double r)
{
    if (!p)
        return NAN;
    double m = gw_layer_mass(p, r);
    return (p->mass_law == GW_LAYER_MASS_SPHERE ? 0.4 : 0.5) * m * r * r;
}

const char *gw_layer_mass_law_name(int mass_law)
{
    return mass_law == GW_LAYER_MASS_SPHERE ? "sphere" : mass_law == GW_LAYER_MASS_DISC ? "disc (unit thickness)"
                                                                                      : "unknown";
}

int gw_layer_create(const gw_layer_params *p, int n, const gw_layer_body *b, gw_layer **out,
                    gw_err *err)
{
    if (!out)
        return gw_err_set(err, GW_EINVAL, "gw_layer_create: out is NULL");
    if (!p) {
        *out = NULL;
        return gw_err_set(err, GW_EINVAL, "gw_layer_create: p is NULL");
    }
    *out = NULL;
    int rc = gw_layer_params_validate(p, err);
    if (rc != GW_OK)
        return rc;
    if (n < 1)
        return gw_err_set(err, GW_EINVAL, "layer: at least one particle needed, got %d", n);
    if (!b)
        return gw_err_set(err, GW_EINVAL, "gw_layer_create: bodies is NULL");
    for (int i = 0; i < n; i++) {
        /* (the check the impact's check reads a sample's particles with) */
        if ((rc = layer_particle_check(&b[i], i, p->walls, p->width, "particle", err)) != GW_OK)
            return rc;
        if (b[i].clump < 0)
            return gw_err_set(err, GW_EINVAL, "particle %d: clump id %d must be >= 0 (0: no clump)",
                              i, b[i].clump);
    }
    gw_layer *L = calloc(1, sizeof *L);
    if (!L)
        return gw_err_set(err, GW_ENOMEM, "layer: out of memory");
    L->p = *p;
    L->n = n;
    L->block = L->block_body = -1;
    L->tan_phi = tan(p->friction_deg * M_PI / 180.0);
    L->r = malloc(7 * (size_t)n * sizeof *L->r);
    L->fixed = calloc((size_t)n, 1);
    L->x_list = malloc(2 * (size_t)n * sizeof *L->x_list);
    L->cap_y = 6L * n + 2;
    L->y = malloc((size_t)L->cap_y * sizeof *L->y);
    L->scale = malloc((size_t)L->cap_y * sizeof *L->scale);
    L->drift = malloc((size_t)L->cap_y * sizeof *L->drift);
    L->snap_xy = malloc(2 * (size_t)n * sizeof *L->snap_xy);
    L->snap_breg = calloc((size_t)n + 1, sizeof *L->snap_breg);
    if (!L->r || !L->fixed || !L->x_list || !L->y || !L->scale || !L->drift || !L->snap_xy ||
        !L->snap_breg) {
        gw_layer_free(L);
        return gw_err_set(err, GW_ENOMEM, "layer: out of memory for %d particles", n);
    }
    L->m = L->r + n;
    L->inertia = L->r + 2 * n;
    L->minv = L->r + 3 * n;
    L->iinv = L->r + 4 * n;
    L->y_ref = L->r + 5 * n;
    L->brad = L->r + 6 * n;
    for (int i = 0; i < n; i++) {
        L->r[i] = b[i].r;
        if (b[i].r > L->rmax)
            L->rmax = b[i].r;
    }
    if ((rc = layer_bodies_build(L, b, err)) != GW_OK) {
        gw_layer_free(L);
        return rc;
    }
    const int nb = L->nb;
    double vmax = 0;
    for (int q = 0; q < nb; q++) {
        const double *s = L->y + 6 * q;
        double v = hypot(s[3], s[4]) + fabs(s[5]) * L->brad[q];
        if (v > vmax)
            vmax = v;
    }
    L->y[6 * nb] = L->y[6 * nb + 1] = 0;
    L->ntail = 2;
    L->dim = 6L * nb + 2;
    L->v_scale = fmax(vmax, sqrt(fmax(p->gravity, 1e-3) * L->rmax));
    L->u_scale = 1e-3 * L->rmax;
    L->f_scale = gw_layer_kn(p, L->rmax) * pow(L->u_scale, 1.5);
    L->stamp = 1;
    *out = L;
    return GW_OK;
}

void gw_layer_free(gw_layer *L)
{
    if (!L)
        return;
    gw_solver_free(L->solver);
    free(L->r);
    free(L->fixed);
    free(L->x_list);
    free(L->y);
    free(L->scale);
    free(L->drift);
    free(L->un_last);
    free(L->wake);
    free(L->travel);
    free(L->tix);
    free(L->dem_act);
    free(L->dem_w);
    free(L->tscr);
    free(L->tmode);
    free(L->ymid);
    free(L->dem_book);
    free(L->geo);
    free(L->facc);
    free(L->dem_rate);
    free(L->dem_f);
    free(L->pk_y);
    free(L->pk_c);
    free(L->snap);
    free(L->snap_xy);
    free(L->snap_breg);
    free(L->wblk);
    free(L->ring_np);
    free(L->spr);
    free(L->c);
    free(L->roots);
    free(L->bid);
    free(L->off);
    free(L);
}

void gw_layer_energy_of(const gw_layer *L, gw_layer_energy *e)
{
    gw_layer_ledgers(L, e, NULL); /* (NULL L: a ledger of NaN) */
}

double gw_layer_energy_initial(const gw_layer *L)
{
    if (!L)
        return NAN;
    return L->e0;
}

int gw_layer_n(const gw_layer *L)
{
    if (!L)
        return 0;
    return L->n;
}

double gw_layer_time(const gw_layer *L)
{
    if (!L)
        return NAN;
    return L->t;
}

double gw_layer_radius(const gw_layer *L, int i)
{
    if (!L || i < 0 || i >= L->n)
        return NAN;
    return L->r[i];
}

double gw_layer_particle_mass(const gw_layer *L, int i)
{
    if (!L || i < 0 || i >= L->n)
        return NAN;
    return L->m[layer_body(L, i)];
}

double gw_layer_particle_inertia(const gw_layer *L, int i)
{
    if (!L || i < 0 || i >= L->n)
        return NAN;
    return L->inertia[layer_body(L, i)];
}

const gw_layer_params *gw_layer_get_params(const gw_layer *L)
{
    /* NULL: NULL (&L->p of a NULL L was undefined behaviour, a sanitizer report) */
    return L ? &L->p : NULL;
}

void gw_layer_set_block(gw_layer *L, int i)
{
    if (!L)
        return;
    if (i < 0 || i >= L->n) /* no such particle: no block (99 of 2 was kept and its body read past bid) */
        i = -1;
    L->block = i;
    L->block_body = i >= 0 ? layer_body(L, i) : -1;
}

void gw_layer_get_stats(const gw_layer *L, gw_layer_stats *st)
{
    if (!L || !st) {
        if (st)
            memset(st, 0, sizeof *st);
        return;
    }
    *st = L->st;
    if (L->solver) {
        gw_solver_stats ss;
        gw_solver_get_stats(L->solver, &ss);
        st->steps += ss.steps;
        st->rhs_evals += ss.rhs_evals;
    }
}
