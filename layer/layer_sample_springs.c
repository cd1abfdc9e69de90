/*
 * layer_sample_springs.c: the tangential springs a settled pile leans on
 * (gw_layer_spring), from the settling's last state into the sample
 * (layer_springs_take, layer_make.c), checked when a sample is read or
 * written (layer_springs_check), and from the sample into an impact's first
 * contact list (layer_springs_pend, layer_springs_load; layer_impact.c,
 * layer_sim.c). docs/physics.md 2.1, eqs. B.1-B.4.
 *
 * The model's state holds the elastic tangential force F_t of every contact
 * (layer_model.c). A sample keeps the spring's elastic displacement
 *   u_t = F_t / K_t,  K_t = k_t F_n^(1/3) = (k_t K_n^(1/3)) u_n^(1/2)   (B.4)
 * so that E_st = F_t^2 / (2 K_t) = K_t u_t^2 / 2: the spring is geometry, as
 * the overlaps are the positions', and an impact with another material turns
 * both into its own forces: F_t = K_t u_t with its K_t, clipped to its Coulomb
 * bound tan(phi) F_n (a displacement beyond it has slipped: the contact starts
 * at the cap, sliding; the contact was not carried by this friction). With the
 * settling's own material the force comes back to rounding (K_t u_t of the
 * same K_t). The bound on the displacement,
 *   |u_t| <= tan(phi) F_n / K_t = tan(phi) u_n (2 - nu) / (3 (1 - nu))
 * (K_n and k_t of B.3, B.4: G and R_p cancel), is what a sample's springs are
 * checked against under the settling it records; computed here as the model
 * computes the cap and K_t (layer_cap, kts = k_t K_n^(1/3)), so that a
 * spring at the cap passes to rounding.
 * The overlap of a spring's contact is computed from the sample's own
 * positions (spring_overlap), by the writer and the reader alike: a spring
 * written is one the reader finds in contact.
 * Units: SI (m, N).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_sample_impl.h"
#include "gw_locale.h"

/* A spring's bound checked to a relative SPRING_BOUND_TOL. The sliding
 * contacts of a settled pile hold their springs on the bound, and the bound
 * moves with the overlap: positions rounded or moved by d move it by d / u_n
 * (1e-9 m: 3e-5 of a settled overlap of the default pile, 3e-5 m), and
 * within this the impact clips the spring (layer_springs_load), a change of
 * the order of the move. Beyond it the file contradicts the settling it
 * records (its friction edited from 30 to 29.9 degrees: 4.5e-3). */
#define SPRING_BOUND_TOL 1e-3
/* A spring counted as clipped by the impact's bound (layer_springs_load):
 * beyond the rounding of the division u_t = F_t / K_t. */
#define SPRING_CLIP_TOL 1e-9

static int spring_cmp(const void *pa, const void *pb)
{
    const gw_layer_spring *a = pa, *b = pb;
    if (a->a != b->a)
        return a->a < b->a ? -1 : 1;
    return (a->b > b->b) - (a->b < b->b);
}

/* Overlap u_n of the contact (a, b) (b a wall: GW_LAYER_SPRING_*) of discs at
 * (x, y) with radii r in a box of width w; as layer_pair_geometry has it. */
static double spring_overlap(const double *x, const double *y, const double *r, double w, int a, int b)
{
    switch (b) {
    case GW_LAYER_SPRING_LEFT:
        return r[a] - x[a];
    case GW_LAYER_SPRING_RIGHT:
        return r[a] - (w - x[a]);
    case GW_LAYER_SPRING_BOTTOM:
        return r[a] - y[a];
    default: {
        const double dx = x[b] - x[a], dy = y[b] - y[a];
        return r[a] + r[b] - sqrt(dx * dx + dy * dy);
    }
    }
}

/* K_t and the cap tan(phi) F_n of the contact (radii ra, rb; rb 0 for a
 * wall) at overlap un > 0 under the material p, as layer_contacts_build and
 * the right-hand side compute them. */
static void spring_law(const gw_layer_params *p, double tp, double ra, double rb, double un, double *kt,
                       double *cap)
{
    const double rp = rb > 0 ? 2 * ra * rb / (ra + rb) : ra, kn = gw_layer_kn(p, rp);
    *kt = gw_layer_kt_factor(p, rp) * cbrt(kn) * sqrt(un);
    *cap = layer_cap(tp, kn, un);
}

static const char *wall_name(int b)
{
    return b == GW_LAYER_SPRING_LEFT ? "left" : b == GW_LAYER_SPRING_RIGHT ? "right" : "bottom";
}

/* The pair as a file writes it: "a b" or "a WALL". */
static const char *pair_text(int a, int b, char out[40])
{
    if (b >= 0)
        gw_snprintf(out, 40, "%d %d", a, b);
    else
        gw_snprintf(out, 40, "%d %s", a, wall_name(b));
    return out;
}

/* Two discs in either order are one contact with one value (n and t both
 * turn over with the order): a pair is kept as a < b. */
static gw_layer_spring spring_sorted(gw_layer_spring q)
{
    if (q.b >= 0 && q.b < q.a) {
        const int t = q.a;
        q.a = q.b, q.b = t;
    }
    return q;
}

int layer_spring_wall(const char *s)
{
    return strcmp(s, "left") == 0 ? GW_LAYER_SPRING_LEFT : strcmp(s, "right") == 0 ? GW_LAYER_SPRING_RIGHT
           : strcmp(s, "bottom") == 0 ? GW_LAYER_SPRING_BOTTOM : 0;
}

const char *layer_spring_wall_name(int b)
{
    return wall_name(b);
}

/* "line L" (lines given) or "spring at index k" into out. */
static const char *spring_where(const long *lines, int k, char out[48])
{
    if (lines)
        gw_snprintf(out, 48, "line %ld", lines[k]);
    else
        gw_snprintf(out, 48, "spring at index %d", k);
    return out;
}

int layer_springs_check(const gw_layer_sample *s, const char *path, const long *lines, int status, gw_err *err)
{
    if (s->n_springs == 0) /* springs not NULL then: an empty list, as NULL */
        return GW_OK;
    if (s->n_springs < 0 || !s->springs)
        return gw_err_set(err, status, "sample '%s': n_springs = %d with %s springs", path, s->n_springs,
                          s->springs ? "its" : "no");
    if (s->n_springs > LAYER_SPRINGS_MOST(s->n))
        return gw_err_set(err, status, "sample '%s': %d springs for %d particles, more than %ld (a settled pile "
                          "has about 2 contacts a disc)", path, s->n_springs, s->n, LAYER_SPRINGS_MOST(s->n));
    gw_layer_params p = gw_layer_params_default();
    const int bound = s->settled.recorded;
    double tp = 0;
    if (bound) {
        p.shear_modulus = s->settled.shear_modulus;
        p.poisson = s->settled.poisson;
        tp = tan(s->settled.friction_deg * M_PI / 180);
    }
    char where[48];
    for (int k = 0; k < s->n_springs; k++) {
        const gw_layer_spring *q = &s->springs[k];
        const int a = q->a, b = q->b;
        spring_where(lines, k, where);
        if (a < 0 || a >= s->n || b >= s->n || b < GW_LAYER_SPRING_BOTTOM || a == b)
            return gw_err_set(err, status, "sample '%s': %s: spring %d %d: the pair must be two particles "
                              "in [0, %d) or a particle and a wall", path, where, a, b, s->n);
        char pair[40];
        pair_text(a, b, pair);
        if (!isfinite(q->u))
            return gw_err_set(err, status, "sample '%s': %s: spring %s: displacement %g is not a finite number",
                              path, where, pair, q->u);
        if (b >= 0 && s->body && s->body[a] == s->body[b])
            return gw_err_set(err, status, "sample '%s': %s: spring %s: the two discs are one clump (body %d): "
                              "discs of a clump have no contact", path, where, pair, s->body[a]);
        const double un = spring_overlap(s->x, s->y, s->r, s->width, a, b);
        if (!(un > 0))
            return gw_err_set(err, status, "sample '%s': %s: spring %s: the pair is not in contact (gap %.3g m): "
                              "a spring needs a closed contact", path, where, pair, -un);
        if (bound) {
            double kt, cap;
            spring_law(&p, tp, s->r[a], b >= 0 ? s->r[b] : 0, un, &kt, &cap);
            const double most = cap / kt;
            if (!(fabs(q->u) <= most * (1 + SPRING_BOUND_TOL)))
                return gw_err_set(err, status, "sample '%s': %s: spring %s: displacement %.6g m is beyond the "
                                  "Coulomb bound %.6g m of the settling the sample records (friction %g deg, "
                                  "overlap %.6g m)", path, where, pair, q->u, most, s->settled.friction_deg, un);
        }
    }
    /* each pair once: a sorted copy, u carrying the index */
    gw_layer_spring *cp = malloc((size_t)s->n_springs * sizeof *cp);
    if (!cp)
        return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory checking %d springs", path, s->n_springs);
    for (int k = 0; k < s->n_springs; k++)
        cp[k] = spring_sorted(s->springs[k]), cp[k].u = k;
    qsort(cp, (size_t)s->n_springs, sizeof *cp, spring_cmp);
    int rc = GW_OK;
    for (int k = 1; k < s->n_springs && rc == GW_OK; k++)
        if (cp[k].a == cp[k - 1].a && cp[k].b == cp[k - 1].b) {
            const int j = (int)fmax(cp[k].u, cp[k - 1].u), i = (int)fmin(cp[k].u, cp[k - 1].u);
            char w2[48], pair[40];
            spring_where(lines, i, w2);
            rc = gw_err_set(err, status, "sample '%s': %s: spring %s given twice (first at %s)", path,
                            spring_where(lines, j, where), pair_text(cp[k].a, cp[k].b, pair), w2);
        }
    free(cp);
    return rc;
}

int layer_springs_take(const gw_layer *L, const double *x, const double *y, const double *r, double width,
                       gw_layer_spring **out, int *nout)
{
    *out = NULL;
    *nout = 0;
    const double *f = L->y + 6 * L->nb;
    int m = 0;
    for (int k = 0; k < L->nc; k++)
        m += f[k] != 0;
    if (m == 0)
        return GW_OK;
    gw_layer_spring *sp = malloc((size_t)m * sizeof *sp);
    if (!sp)
        return GW_ENOMEM;
    int j = 0;
    for (int k = 0; k < L->nc; k++) {
        const layer_contact *c = &L->c[k];
        if (f[k] == 0 || c->a == L->block || c->b == L->block)
            continue;
        /* the overlap of the positions written (the reader's), K_t and the cap
         * there: the force used (the state clamped to the cap) as u_t */
        const double un = spring_overlap(x, y, r, width, c->a, c->b);
        if (!(un > 0))
            continue;
        const double kt = c->kts * sqrt(un), cap = layer_cap(L->tan_phi, c->kn, un);
        const double ft = fmax(-cap, fmin(cap, f[k]));
        if (!(kt > 0) || ft == 0)
            continue;
        sp[j++] = (gw_layer_spring){.a = c->a, .b = c->b, .u = ft / kt};
    }
    if (j == 0) {
        free(sp);
        return GW_OK;
    }
    *out = sp;
    *nout = j;
    return GW_OK;
}

int layer_springs_pend(gw_layer *L, const gw_layer_spring *sp, int n)
{
    free(L->spr);
    L->spr = NULL;
    L->nspr = 0;
    if (n <= 0)
        return GW_OK;
    L->spr = malloc((size_t)n * sizeof *L->spr);
    if (!L->spr)
        return GW_ENOMEM;
    for (int k = 0; k < n; k++)
        L->spr[k] = spring_sorted(sp[k]);
    qsort(L->spr, (size_t)n, sizeof *L->spr, spring_cmp);
    L->nspr = n;
    return GW_OK;
}

void layer_springs_load(gw_layer *L)
{
    if (!L->spr)
        return;
    double *f = L->y + 6 * L->nb;
    for (int k = 0; k < L->nc; k++) {
        const layer_contact *c = &L->c[k];
        const gw_layer_spring key = {.a = c->a, .b = c->b};
        const gw_layer_spring *q = bsearch(&key, L->spr, (size_t)L->nspr, sizeof key, spring_cmp);
        if (!q)
            continue;
        double un, nn[2];
        layer_contact_geometry(L, c, L->y, &un, nn, NULL);
        if (!(un > 0))
            continue;
        const double kt = c->kts * sqrt(un), cap = layer_cap(L->tan_phi, c->kn, un), ft = kt * q->u;
        f[k] = fmax(-cap, fmin(cap, ft));
        L->spr_loaded++;
        L->spr_clipped += fabs(ft) > cap * (1 + SPRING_CLIP_TOL);
    }
    free(L->spr);
    L->spr = NULL;
    L->nspr = 0;
    L->stamp++;
}
