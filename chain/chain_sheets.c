/*
 * chain_sheets.c: the paper's sheets (Table 2) as wall laws from their material
 * constants and thickness (no fitting to the table):
 *   hertz     K = (4/3) E* sqrt(R), 1/E* = (1-nu_b^2)/E_b + (1-nu^2)/E     (F.3)
 *   layer     the bonded elastic layer of thickness h (chain_layer.c)
 *   material  layer with the generalized-Maxwell loss tan(delta) (chain_wall.c),
 *             or, for a sheet with a yield stress Y, Thornton elastic-plastic on
 *             the Hertz law with p_y = 2.8 Y (GW_SHEET_TABOR)
 *   fitted    the Hertz K_eff of gw_sheet_kwall (the measured tau_max(N = 1))
 * The sheet "none" is the bare sensor: the Hertz wall of the sensor's material
 * (fitted: its K_eff). Units: SI.
 */
#include <math.h>
#include <string.h>

#include "chain_material.h"
#include "gw_chain.h"

static const char *const law_names[] = {"fitted", "hertz", "layer", "material"};

int gw_sheet_law_find(const char *name)
{
    for (int i = 0; name && i < 4; i++)
        if (strcmp(name, law_names[i]) == 0)
            return i;
    return -1;
}

const char *gw_sheet_law_name(gw_sheet_law law)
{
    return (int)law >= 0 && (int)law < 4 ? law_names[law] : "unknown"; /* "?" before the forty-ninth pass, where every other enum name says "unknown" */
}

int gw_sheet_apply(const gw_sheet *s, gw_sheet_law law, double yield, double loss,
                   const gw_material *bead, const gw_material *wall, gw_chain_params *p,
                   gw_layer_law **layer, gw_err *err)
{
    if (!s || !p || !layer)
        return gw_err_set(err, GW_EINVAL, "gw_sheet_apply: %s is NULL", !s ? "s" : !p ? "p" : "layer");
    *layer = NULL;
    /* a law outside the enum ran as the layer law, and a NaN yield or loss as
     * the sheet's own, with GW_OK; NULL materials gave a NaN kwall */
    if (!(law >= GW_SHEET_FITTED && law <= GW_SHEET_MATERIAL))
        return gw_err_set(err, GW_EINVAL, "sheet-law: %d is not a sheet law (fitted, hertz, layer, material)", (int)law);
    if (isnan(yield) || isinf(yield) || isnan(loss) || isinf(loss))
        return gw_err_set(err, GW_EINVAL, "%s: %g is not a finite number (< 0: the sheet's own)",
                          isnan(yield) || isinf(yield) ? "sheet-yield" : "sheet-loss",
                          isnan(yield) || isinf(yield) ? yield : loss);
    if (!bead || !wall)
        return gw_err_set(err, GW_EINVAL, "gw_sheet_apply: %s is NULL", !bead ? "bead" : "wall");
    /* materials filled by hand: a Young modulus of 0 or below, NaN, a Poisson
     * ratio outside (-1, 0.5] gave a law or a "rigid" coefficient with GW_OK */
    int rc;
    if ((rc = chain_material_check(bead, "bead material", err)) != GW_OK ||
        (rc = chain_material_check(wall, "wall material", err)) != GW_OK)
        return rc;
    if (law != GW_SHEET_FITTED && s->thickness > 0) {
        const gw_material own = {s->material ? s->material : s->name, s->young, s->poisson, NAN};
        if ((rc = chain_material_check(&own, "sheet material", err)) != GW_OK)
            return rc;
    }
    memset(&p->wall, 0, sizeof p->wall);
    if (law == GW_SHEET_FITTED) {
        p->kwall = gw_sheet_kwall(s, p->mass);
        return GW_OK;
    }
    if (!(s->thickness > 0)) {
        p->kwall = gw_hertz_coefficient(p->radius, bead, INFINITY, wall);
        return GW_OK;
    }
    gw_material m = {s->material, s->young, s->poisson, NAN};
    p->kwall = gw_hertz_coefficient(p->radius, bead, INFINITY, &m);
    double y = yield >= 0 ? yield : s->yield, l = loss >= 0 ? loss : s->loss;
    if (law == GW_SHEET_HERTZ)
        return GW_OK;
    if (law == GW_SHEET_MATERIAL && y > 0) {
        p->wall.yield_pressure = GW_SHEET_TABOR * y;
        return GW_OK;
    }
    rc = gw_layer_law_create(p->radius, bead, s->thickness, s->young, s->poisson, layer, err);
    if (rc != GW_OK)
        return rc;
    p->wall.layer = *layer;
    if (law == GW_SHEET_MATERIAL && l > 0)
        p->wall.loss = l;
    return GW_OK;
}
