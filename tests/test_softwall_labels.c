/*
 * test_softwall_labels.c: gw_chain_softwall_sheet_material, the one place a
 * caller takes sheet w's material label from a softwall outcome (the program's
 * softwall --sheets --json did it by hand before).
 *
 *  1. Under every sheet law, each sheet's label is field w of the outcome's
 *     ';'-separated sheet_materials, split here independently; the sheet none
 *     reads "no sheet (M sensor)" under hertz, layer and material (M the
 *     wall material, steel when not given) and its table material under fitted;
 *     the other sheets read their Table 2 material whatever the law.
 *  2. A w outside the sheets (-1, nsheet), a NULL outcome, a buffer shorter than
 *     the label, or a single-wall outcome without a sheet: GW_EINVAL and an
 *     empty buffer, never a read past the text.
 * Columns of 1..3 beads (the walls run in well under a second each law).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gw_chain_study.h"
#include "gw_common.h"
#include "gw_test.h"

static int run(const char *law, const char *wall, int sheets, gw_chain_softwall_outcome *o)
{
    gw_chain_softwall_setup s;
    gw_err err = {{0}};
    const gw_param *t = gw_chain_softwall_setup_params();
    int rc = gw_chain_softwall_setup_init(&s);
    if (rc == GW_OK)
        rc = gw_param_set(t, &s, "n", "1:3", &err);
    if (rc == GW_OK && sheets)
        rc = gw_param_set(t, &s, "sheets", "1", &err);
    if (rc == GW_OK && !sheets)
        rc = gw_param_set(t, &s, "kwall", "1e9", &err);
    if (rc == GW_OK && law)
        rc = gw_param_set(t, &s, "sheet-law", law, &err);
    if (rc == GW_OK && wall)
        rc = gw_param_set(t, &s, "wall-material", wall, &err);
    if (rc == GW_OK)
        rc = gw_param_set(t, &s, "jobs", "1", &err);
    if (rc == GW_OK)
        rc = gw_chain_softwall_run(&s, NULL, NULL, o, &err);
    if (rc != GW_OK)
        printf("softwall %s %s: %s\n", law ? law : "-", wall ? wall : "-", err.msg);
    gw_chain_softwall_setup_clear(&s);
    return rc;
}

/* field w of text split at ';' into buf (the test's own split) */
static void field(const char *text, int w, char *buf, size_t n)
{
    const char *p = text;
    for (int i = 0; i < w && p; i++)
        p = strchr(p, ';') ? strchr(p, ';') + 1 : NULL;
    size_t len = p ? strcspn(p, ";") : 0;
    snprintf(buf, n, "%.*s", (int)len, p ? p : "");
}

static void check_law(const char *law, const char *wall)
{
    gw_chain_softwall_outcome o;
    char what[160], got[GW_SOFTWALL_LABEL_MAX], want[GW_SOFTWALL_LABEL_MAX], none[64];
    snprintf(what, sizeof what, "%s%s%s: softwall --sheets runs", law, wall ? " --wall-material " : "",
             wall ? wall : "");
    gw_test_true(run(law, wall, 1, &o) == GW_OK, what);
    gw_test_true(o.nsheet == gw_sheet_count(), "one label per sheet of Table 2");
    snprintf(none, sizeof none, "no sheet (%s sensor)", wall ? wall : "steel");
    int same = 1, named = 1;
    for (int w = 0; w < o.nsheet; w++) {
        const gw_sheet *sh = gw_sheet_get(w);
        int rc = gw_chain_softwall_sheet_material(&o, w, got, sizeof got);
        field(o.sheet_materials, w, want, sizeof want);
        same &= rc == GW_OK && strcmp(got, want) == 0;
        const char *expect = !(sh->thickness > 0) && strcmp(law, "fitted") != 0 ? none : sh->material;
        named &= strcmp(got, expect) == 0;
        if (strcmp(got, expect) != 0)
            printf("  sheet %d (%s): label '%s', expected '%s'\n", w, sh->name, got, expect);
    }
    snprintf(what, sizeof what, "%s%s%s: each label is field w of sheet_materials", law, wall ? " " : "",
             wall ? wall : "");
    gw_test_true(same, what);
    snprintf(what, sizeof what, "%s%s%s: sheet none names %s, the others their material", law, wall ? " " : "",
             wall ? wall : "", strcmp(law, "fitted") ? none : "its table material");
    gw_test_true(named, what);

    strcpy(got, "x");
    gw_test_true(gw_chain_softwall_sheet_material(&o, o.nsheet, got, sizeof got) == GW_EINVAL && !got[0],
                 "w = nsheet: GW_EINVAL, buffer emptied");
    strcpy(got, "x");
    gw_test_true(gw_chain_softwall_sheet_material(&o, -1, got, sizeof got) == GW_EINVAL && !got[0],
                 "w = -1: GW_EINVAL, buffer emptied");
    /* the first sheet's label one character longer than the buffer */
    field(o.sheet_materials, 0, want, sizeof want);
    char small[GW_SOFTWALL_LABEL_MAX];
    gw_test_true(gw_chain_softwall_sheet_material(&o, 0, small, strlen(want)) == GW_EINVAL && !small[0],
                 "a buffer one short of the label: GW_EINVAL, empty (no truncated label)");
    gw_test_true(gw_chain_softwall_sheet_material(&o, 0, small, strlen(want) + 1) == GW_OK &&
                     strcmp(small, want) == 0,
                 "a buffer that just fits: the whole label");
    gw_chain_softwall_outcome_free(&o);
}

int main(void)
{
    check_law("fitted", NULL);
    check_law("hertz", NULL);
    check_law("layer", "brass");
    check_law("material", "pvc");

    char buf[8] = "x";
    gw_test_true(gw_chain_softwall_sheet_material(NULL, 0, buf, sizeof buf) == GW_EINVAL && !buf[0],
                 "NULL outcome: GW_EINVAL");
    gw_test_true(gw_chain_softwall_sheet_material(NULL, 0, NULL, 0) == GW_EINVAL, "NULL buffer: GW_EINVAL");

    /* one wall of stiffness kwall: no sheet compared, so no label */
    gw_chain_softwall_outcome o;
    gw_test_true(run(NULL, NULL, 0, &o) == GW_OK && o.nsheet == 0, "softwall --kwall 1e9 runs without sheets");
    strcpy(buf, "x");
    gw_test_true(gw_chain_softwall_sheet_material(&o, 0, buf, sizeof buf) == GW_EINVAL && !buf[0],
                 "no sheet compared: w = 0 is GW_EINVAL");
    gw_chain_softwall_outcome_free(&o);
    return gw_test_summary("test_softwall_labels");
}
