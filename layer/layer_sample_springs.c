/*
 * layer_sample_springs.c: the tangential springs a settled pile leans on
 * (gw_layer_spring) as a sample holds them: checked when a sample is read or
 * written (layer_springs_check), and the helpers the layer's side shares
 * (layer_springs.c: from the settling's last state into the sample, from the
 * sample into an impact's first contact list). Nothing here needs a layer,
 * so the sample reader builds alone (the fuzz target). docs/physics.md 2.1,
 * eqs. B.1-B.4.
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
 * checked against under the settling it records (the model's cap over its
 * K_t, layer_springs_take, equals it to rounding).
 * The overlap of a spring's contact is computed from the sample's own
 * positions (layer_spring_overlap), by the writer and the reader alike: a spring
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
 * records (its friction edited from 30 to 29.9 degrees: 3.8e-3). */
#define SPRING_BOUND_TOL 1e-3

int layer_spring_cmp(const void *pa, const void *pb)
{
    const gw_layer_spring *a = pa, *b = pb;
    if (a->a != b->a)
        return a->a < b->a ? -1 : 1;
    return (a->b > b->b) - (a->b < b->b);
}

/* Overlap u_n of the contact (a, b) (b a wall: GW_LAYER_SPRING_*) of discs at
 * (x, y) with radii r in a box of width w; as layer_pair_geometry has it. */
double layer_spring_overlap(const double *x, const double *y, const double *r, double w, int a, int b)
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
gw_layer_spring layer_spring_sorted(gw_layer_spring q)
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

int layer_spring_form_check(const gw_layer_sample *s, int k, const char *path, const long *lines, int status,
                            gw_err *err)
{
    const gw_layer_spring *q = &s->springs[k];
    const int a = q->a, b = q->b;
    char where[48], pair[40], us[40];
    if (a < 0 || a >= s->n || b >= s->n || b < GW_LAYER_SPRING_BOTTOM || a == b)
        return gw_err_set(err, status, "sample '%s': %s: spring %d %d: the pair must be two particles in [0, %d) "
                          "or a particle and a wall", path, spring_where(lines, k, where), a, b, s->n);
    if (!isfinite(q->u))
        return gw_err_set(err, status, "sample '%s': %s: spring %s: displacement u = %s m is not a finite number",
                          path, spring_where(lines, k, where), pair_text(a, b, pair), gw_num_text(us, sizeof us, q->u));
    return GW_OK;
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
    /* the bound over the overlap, tan(phi) (2 - nu) / (3 (1 - nu)) of the
     * recorded settling (0: none recorded, nothing checked) */
    const int bound = s->settled.recorded;
    const double nu = s->settled.poisson;
    const double per_un = bound ? tan(s->settled.friction_deg * M_PI / 180) * (2 - nu) / (3 * (1 - nu)) : 0;
    char where[48];
    for (int k = 0; k < s->n_springs; k++) {
        const gw_layer_spring *q = &s->springs[k];
        const int a = q->a, b = q->b;
        const int rc = layer_spring_form_check(s, k, path, lines, status, err);
        if (rc != GW_OK)
            return rc;
        spring_where(lines, k, where);
        char pair[40];
        pair_text(a, b, pair);
        if (b >= 0 && s->body && s->body[a] == s->body[b])
            return gw_err_set(err, status, "sample '%s': %s: spring %s: the two discs are one clump (body %d): "
                              "discs of a clump have no contact", path, where, pair, s->body[a]);
        const double un = layer_spring_overlap(s->x, s->y, s->r, s->width, a, b);
        if (!(un > 0))
            return gw_err_set(err, status, "sample '%s': %s: spring %s: the pair is not in contact (gap %.3g m): "
                              "a spring needs a closed contact", path, where, pair, -un);
        if (bound) {
            const double most = per_un * un;
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
        cp[k] = layer_spring_sorted(s->springs[k]), cp[k].u = k;
    qsort(cp, (size_t)s->n_springs, sizeof *cp, layer_spring_cmp);
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
