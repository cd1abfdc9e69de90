/*
 * layer_sample_settings.c: the settling's record of a sample (gw_layer_settled,
 * gw_layer.h): the material and gravity layer-make settled the pile under,
 * read from the settings line it writes into the sample's header, so that an
 * impact can tell a pile at rest under its own material from one that is not
 * (gw_layer_impact_settled_check, layer_impact.c; the equilibrium overlap of a
 * Hertz contact scales as (m g / K_n)^(2/3), physics.md 2.1, B.3).
 *
 * Two dialects are written: the program's (`granwave layer-make`: an object
 * "material" with shear_modulus, poisson, friction_deg, density, gravity,
 * mass_law "disc (unit thickness)" | "sphere", clump_mass "sum" | "union")
 * and the library's (gw_layer_make_run, Python's layer_make: the flat rows
 * shear-modulus, poisson, friction, density, gravity, mass-law "disc" |
 * "sphere", clump-mass "sum" | "union"). The clump mass changes the weight a
 * clump pile settled under (the union of overlapping members weighs less than
 * their sum): a line without it (one written before clump samples) leaves it
 * to the sample's own clump_mass line, which layer-make writes too. A JSON
 * object with neither is "not recorded"; one with some of the keys, a value
 * of the wrong type or outside the material rows' ranges (layer_setup_rows.h)
 * is refused: the line was altered, and read as "not recorded" it would turn
 * the check off while the file still claims layer-make's settings.
 * Units: SI (Pa, kg/m^3, m/s^2), angles in degrees.
 */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_sample_impl.h"
#include "gw_locale.h"
#include "gw_number_impl.h"

/* unsettled (gw_layer.h) sits in what was the padding after clump_mass: the
 * struct's size, and gw_layer_sample's, stay those that callers compiled
 * against the header before it (and ctypes mirrors) lay out. */
struct settled_before {
    int recorded;
    double shear_modulus, poisson, friction_deg, density, gravity;
    int mass_law;
    long line;
    int clump_mass;
};
_Static_assert(sizeof(gw_layer_settled) == sizeof(struct settled_before), "gw_layer_settled grew");

/* The digit of a "settled:" line's "converged N" ('0' or '1'), else 0. */
static char settled_digit(const char *text)
{
    /* both writers (the program's layer-make, gw_layer_make_run) print
     * "settled: t = %.4g s, E_k = %.4g J, converged %d, ..." */
    static const char key[] = "settled:", conv[] = ", converged ";
    if (!text || strncmp(text, key, sizeof key - 1) != 0)
        return 0;
    const char *c = strstr(text, conv);
    return c && (c[sizeof conv - 1] == '0' || c[sizeof conv - 1] == '1') && !isdigit((unsigned char)c[sizeof conv])
               ? c[sizeof conv - 1] : 0;
}

int layer_sample_settled_unsettled(const char *text)
{
    return settled_digit(text) == '0';
}

int layer_sample_settled_converged(const char *text)
{
    return settled_digit(text) == '1';
}

/* One dialect: the keys of G, nu, phi, rho, g and the mass law, in that order. */
typedef struct dialect {
    const char *keys[6];
} dialect;

static const dialect program_keys = {{"shear_modulus", "poisson", "friction_deg", "density", "gravity", "mass_law"}};
static const dialect library_keys = {{"shear-modulus", "poisson", "friction", "density", "gravity", "mass-law"}};

/* The ranges of the material rows (layer_setup_rows.h) and of pluviation's
 * gravity (gw_layer_make_plan: > 0): lo, hi, hi open. */
static const struct {
    double lo, hi;
    int lo_open, hi_open;
} ranges[5] = {{1e-3, 1e15, 0, 0}, {0, 0.499999, 0, 0}, {0, 90, 0, 1}, {1e-6, 1e6, 0, 0}, {0, 1e4, 1, 0}};

/* 1 when v, the settling's value k (G, nu, phi, rho, g), lies in its range
 * (not NaN) */
static int in_range(int k, double v)
{
    return v >= ranges[k].lo && !(ranges[k].lo_open && v == ranges[k].lo) && v <= ranges[k].hi &&
           !(ranges[k].hi_open && v == ranges[k].hi);
}

int layer_settled_record_check(const gw_layer_sample *s, const char *path, int status, gw_err *err)
{
    const gw_layer_settled *st = &s->settled;
    if (!st->recorded)
        return GW_OK;
    static const char *const names[5] = {"shear_modulus", "poisson", "friction_deg", "density", "gravity"};
    static const char *const units[5] = {" Pa", "", " deg", " kg/m^3", " m/s^2"};
    const double v[5] = {st->shear_modulus, st->poisson, st->friction_deg, st->density, st->gravity};
    for (int k = 0; k < 5; k++)
        if (!in_range(k, v[k])) {
            char lo[32], hi[32];
            return gw_err_set(err, status, "sample '%s': settled.%s = %g%s is outside %s%s, %s%s (the settling "
                              "record a settings line may hold; recorded 0 for none)", path, names[k], v[k],
                              units[k], ranges[k].lo_open ? "(" : "[", gw_num_bound(lo, sizeof lo, ranges[k].lo, 0),
                              gw_num_bound(hi, sizeof hi, ranges[k].hi, 1), ranges[k].hi_open ? ")" : "]");
        }
    if (st->mass_law != s->mass_law)
        return gw_err_set(err, status, "sample '%s': settled.mass_law = %d where the sample's mass_law is %d "
                          "(a settings line gives the header's)", path, st->mass_law, s->mass_law);
    if (st->clump_mass != -1 && st->clump_mass != s->clump_mass)
        return gw_err_set(err, status, "sample '%s': settled.clump_mass = %d where the sample's clump_mass is %d "
                          "(a settings line gives the header's, or -1: not said)", path, st->clump_mass,
                          s->clump_mass);
    return GW_OK;
}

static int bad(const char *path, const char *where, gw_err *err, const char *why, const char *key)
{
    return gw_err_set(err, GW_EFORMAT, "sample '%s': %s: layer-make's settings line %s%s%s (an altered file? "
                      "remove the line to read the sample without its settling record)", path, where, why,
                      key ? " " : "", key ? key : "");
}

/* The first name an object within x holds twice (NULL: none). JSON leaves a
 * repeated name to the reader: cJSON's lookup takes the first value, Python's
 * json and jq the last, so '"friction_deg":30,"friction_deg":5' was a settling
 * at 30 degrees here and at 5 to those tools. Depth is bounded by cJSON's
 * nesting limit. */
static const char *json_twice(const cJSON *x)
{
    for (const cJSON *a = x ? x->child : NULL; a; a = a->next) {
        if (cJSON_IsObject(x) && a->string)
            for (const cJSON *b = a->next; b; b = b->next)
                if (b->string && strcmp(a->string, b->string) == 0)
                    return a->string;
        const char *inner = json_twice(a);
        if (inner)
            return inner;
    }
    return NULL;
}

/* Where the header's value of key came from, for a message: a text line, an
 * HDF5 attribute, or a line the file does not have. */
static const char *hdr_place(const hdr_src *src, int key, const char *name, char out[64])
{
    if (src && src->h5)
        gw_snprintf(out, 64, "HDF5 attribute '%s'", name);
    else if (src && src->line[key] > 0)
        gw_snprintf(out, 64, "header line %ld '%s'", src->line[key], name);
    else
        gw_snprintf(out, 64, "header (no '%s' line)", name);
    return out;
}

/* The pluviation's own fields of layer-make's settings line against the
 * sample's header and body. layer-make writes both from one value (the
 * header's rm, width = width_rm rm, volume_ratio and seed are the settings'
 * doubles; mass law and clump mass the material's), so a disagreement is a
 * file altered after it was written: an rm or a seed edited in one place
 * only, a cut file's n fixed up by hand. Only the particle count may
 * legitimately differ: a trim to height_rm > 0 keeps the bodies wholly below
 * it (at most n of them, n when it took nothing away), so the bodies are n
 * exactly without a trim and at most n with one (height_rm not given: an
 * older line, at most n). A clump sample (clumps true) counts its bodies by
 * their ids and carries a body column; a disc sample carries none. A field
 * the line does not hold is not compared (older or partial lines). */
static int pluviation_check(const cJSON *j, int library, const gw_layer_sample *s, const hdr_src *src,
                            const char *path, const char *where, gw_err *err)
{
    char why[400], place[64], a[32], b[32], c[32];
    const char *kvr = library ? "volume-ratio" : "volume_ratio", *kw = library ? "width-rm" : "width_rm",
               *kh = library ? "height-rm" : "height_rm";
    const char *numkeys[6] = {"n", "rm", kvr, kw, "seed", kh};
    double v[6];
    int have[6];
    for (int k = 0; k < 6; k++) {
        const cJSON *x = cJSON_GetObjectItemCaseSensitive(j, numkeys[k]);
        have[k] = x != NULL;
        if (x && (!cJSON_IsNumber(x) || !isfinite(x->valuedouble)))
            return bad(path, where, err, "has a value that is not a finite number:", numkeys[k]);
        v[k] = x ? x->valuedouble : 0;
    }
    const cJSON *cl = cJSON_GetObjectItemCaseSensitive(j, "clumps");
    if (cl && !cJSON_IsBool(cl))
        return bad(path, where, err, "has a value that is not true or false:", "clumps");
    /* a relative 1e-12: the same double, whichever digits a JSON printer chose */
#define SAME(a, b) (fabs((a) - (b)) <= 1e-12 * fmax(fabs(a), fabs(b)))
    if (have[1] && !SAME(v[1], s->rm)) {
        gw_snprintf(why, sizeof why, "says rm %s m where the %s says %s m", gw_num_text(a, sizeof a, v[1]),
                    hdr_place(src, K_RM, "rm", place), gw_num_text(b, sizeof b, s->rm));
        return bad(path, where, err, why, NULL);
    }
    if (have[2] && !SAME(v[2], s->volume_ratio)) {
        gw_snprintf(why, sizeof why, "says %s %s where the %s says %s", kvr, gw_num_text(a, sizeof a, v[2]),
                    hdr_place(src, K_VR, "volume_ratio", place), gw_num_text(b, sizeof b, s->volume_ratio));
        return bad(path, where, err, why, NULL);
    }
    if (have[3] && have[1] && !SAME(v[3] * v[1], s->width)) {
        gw_snprintf(why, sizeof why, "says %s %s and rm %s m, a box %.6g m wide, where the %s says %s m", kw,
                    gw_num_text(a, sizeof a, v[3]), gw_num_text(b, sizeof b, v[1]), v[3] * v[1],
                    hdr_place(src, K_WIDTH, "width", place), gw_num_text(c, sizeof c, s->width));
        return bad(path, where, err, why, NULL);
    }
    /* the seed is written as a JSON number (a double): the header's integer
     * is compared as the double it rounds to */
    if (have[4] && v[4] != (double)s->seed) {
        if (v[4] == floor(v[4]))
            gw_snprintf(a, sizeof a, "%.0f", v[4]);
        else
            gw_num_text(a, sizeof a, v[4]);
        gw_snprintf(why, sizeof why, "says seed %s where the %s says %ld", a,
                    hdr_place(src, K_SEED, "seed", place), s->seed);
        return bad(path, where, err, why, NULL);
    }
    const int clumps = cl && cJSON_IsTrue(cl);
    if (cl && clumps != (s->body != NULL)) {
        gw_snprintf(why, sizeof why, "says clumps %s where the file %s", clumps ? "true" : "false",
                    clumps ? (src && src->h5 ? "has no dataset 'body' (a disc sample)"
                                             : "has no body column (format version 1, a disc sample)")
                           : (src && src->h5 ? "has a dataset 'body' (a clump sample)"
                                             : "has a body column (format version 2, a clump sample)"));
        return bad(path, where, err, why, NULL);
    }
    if (have[5] && v[5] < 0)
        return bad(path, where, err, "has a negative value:", kh);
    if (have[0]) {
        if (!(v[0] >= 1 && v[0] == floor(v[0])))
            return bad(path, where, err, "has a value that is not an integer >= 1:", "n");
        long bodies = s->n; /* discs, or the clumps' distinct ids */
        if (s->body) {
            unsigned char *seen = calloc((size_t)s->n, 1);
            if (!seen)
                return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for its body ids", path);
            bodies = 0;
            for (int i = 0; i < s->n; i++)
                if (s->body[i] >= 0 && s->body[i] < s->n && !seen[s->body[i]])
                    seen[s->body[i]] = 1, bodies++;
            free(seen);
        }
        const char *what = s->body ? "clumps" : "particles";
        const int trimmed = !have[5] || v[5] > 0;
        if ((double)bodies > v[0] || (!trimmed && (double)bodies != v[0])) {
            if (trimmed && have[5])
                gw_snprintf(why, sizeof why, "says n %.0f where the file holds %ld %s: a trim to %s %g keeps at "
                            "most n", v[0], bodies, what, kh, v[5]);
            else if (trimmed)
                gw_snprintf(why, sizeof why, "says n %.0f where the file holds %ld %s: a pile holds at most n",
                            v[0], bodies, what);
            else
                gw_snprintf(why, sizeof why, "says n %.0f and %s 0 (no trim) where the file holds %ld %s (%s)",
                            v[0], kh, bodies, what, hdr_place(src, K_N, "n", place));
            return bad(path, where, err, why, NULL);
        }
    }
#undef SAME
    return GW_OK;
}

int layer_sample_settings_parse(const char *text, const char *path, const char *where, const gw_layer_sample *s,
                                const hdr_src *from, gw_layer_settled *out, gw_err *err)
{
    memset(out, 0, sizeof *out);
    const char *end = NULL;
    cJSON *j = cJSON_ParseWithOpts(text, &end, 1);
    if (!j && gw_json_failures()) /* cJSON out of memory, not the file's fault */
        return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for its settings line", path);
    if (!j || !cJSON_IsObject(j)) {
        cJSON_Delete(j);
        return bad(path, where, err, "is not a JSON object", NULL);
    }
    const char *twice = json_twice(j);
    if (twice) {
        char key[80];
        gw_snprintf(key, sizeof key, "'%.60s'%s", twice, strlen(twice) > 60 ? "..." : "");
        cJSON_Delete(j);
        return bad(path, where, err, "holds a name twice (JSON readers differ on which value counts):", key);
    }
    const cJSON *mat = cJSON_GetObjectItemCaseSensitive(j, "material");
    const dialect *d = mat ? &program_keys : &library_keys;
    const cJSON *src = mat ? mat : j;
    if (mat && !cJSON_IsObject(mat)) {
        cJSON_Delete(j);
        return bad(path, where, err, "has a 'material' that is not an object", NULL);
    }
    int found = 0;
    for (int k = 0; k < 6; k++)
        found += cJSON_GetObjectItemCaseSensitive(src, d->keys[k]) != NULL;
    if (found == 0 && !mat) { /* settings of some other writer, or without material: nothing recorded */
        cJSON_Delete(j);
        return GW_OK;
    }
    double v[5];
    int rc = GW_OK;
    for (int k = 0; k < 5 && rc == GW_OK; k++) {
        const cJSON *x = cJSON_GetObjectItemCaseSensitive(src, d->keys[k]);
        if (!x)
            rc = bad(path, where, err, "lacks", d->keys[k]);
        else if (!cJSON_IsNumber(x) || !isfinite(x->valuedouble))
            rc = bad(path, where, err, "has a value that is not a finite number:", d->keys[k]);
        else if (!in_range(k, v[k] = x->valuedouble))
            rc = bad(path, where, err, "has a value outside the material's range:", d->keys[k]);
    }
    const cJSON *law = cJSON_GetObjectItemCaseSensitive(src, d->keys[5]);
    const char *ls = cJSON_GetStringValue(law);
    /* the program writes gw_layer_mass_law_name's "disc (unit thickness)" (the
     * text, not the call: the reader links without the model, as the fuzz
     * target does), the library the choice "disc" */
    const int disc = ls && (strcmp(ls, "disc") == 0 || strcmp(ls, "disc (unit thickness)") == 0);
    const int sphere = ls && strcmp(ls, "sphere") == 0;
    if (rc == GW_OK && !law)
        rc = bad(path, where, err, "lacks", d->keys[5]);
    else if (rc == GW_OK && !disc && !sphere)
        rc = bad(path, where, err, "has a mass law that is neither disc nor sphere:", d->keys[5]);
    /* optional: sum or union, and union is of the disc law (gw_layer_create) */
    const cJSON *cm = cJSON_GetObjectItemCaseSensitive(src, mat ? "clump_mass" : "clump-mass");
    const char *cs = cJSON_GetStringValue(cm);
    const int clump = cs ? gw_layer_clump_mass_parse(cs) : -1;
    if (rc == GW_OK && cm && clump < 0)
        rc = bad(path, where, err, "has a clump mass that is neither sum nor union:",
                 mat ? "clump_mass" : "clump-mass");
    else if (rc == GW_OK && clump == GW_LAYER_CLUMP_MASS_UNION && sphere)
        rc = bad(path, where, err, "has clump mass union with mass law sphere (union is of discs):",
                 mat ? "clump_mass" : "clump-mass");
    /* the material's mass law and clump mass, as the header's (one value each) */
    if (rc == GW_OK && s && (sphere ? GW_LAYER_MASS_SPHERE : GW_LAYER_MASS_DISC) != s->mass_law) {
        char why[200], place[64];
        gw_snprintf(why, sizeof why, "says mass law %s where the %s says %s", sphere ? "sphere" : "disc",
                    hdr_place(from, K_LAW, "mass_law", place), s->mass_law == GW_LAYER_MASS_SPHERE ? "sphere" : "disc");
        rc = bad(path, where, err, why, NULL);
    }
    if (rc == GW_OK && s && clump >= 0 && clump != s->clump_mass) {
        char why[200], place[64];
        gw_snprintf(why, sizeof why, "says clump mass %s where the %s says %s", gw_layer_clump_mass_name(clump),
                    hdr_place(from, K_CMASS, "clump_mass", place), gw_layer_clump_mass_name(s->clump_mass));
        rc = bad(path, where, err, why, NULL);
    }
    if (rc == GW_OK && s)
        rc = pluviation_check(j, !mat, s, from, path, where, err);
    cJSON_Delete(j);
    if (rc != GW_OK)
        return rc;
    out->recorded = 1;
    out->clump_mass = clump;
    out->shear_modulus = v[0];
    out->poisson = v[1];
    out->friction_deg = v[2];
    out->density = v[3];
    out->gravity = v[4];
    out->mass_law = sphere ? GW_LAYER_MASS_SPHERE : GW_LAYER_MASS_DISC;
    return GW_OK;
}
