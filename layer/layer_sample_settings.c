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
#include <string.h>

#include "layer_sample_impl.h"
#include "gw_locale.h"

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

int layer_sample_settled_unsettled(const char *text)
{
    /* both writers (the program's layer-make, gw_layer_make_run) print
     * "settled: t = %.4g s, E_k = %.4g J, converged %d, ..." */
    static const char key[] = "settled:", conv[] = ", converged ";
    if (!text || strncmp(text, key, sizeof key - 1) != 0)
        return 0;
    const char *c = strstr(text, conv);
    return c && c[sizeof conv - 1] == '0' && !isdigit((unsigned char)c[sizeof conv]);
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

int layer_sample_settings_parse(const char *text, const char *path, const char *where, gw_layer_settled *out,
                                gw_err *err)
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
        else if ((v[k] = x->valuedouble) < ranges[k].lo || (ranges[k].lo_open && v[k] == ranges[k].lo) ||
                 v[k] > ranges[k].hi || (ranges[k].hi_open && v[k] == ranges[k].hi))
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
