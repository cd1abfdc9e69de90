/*
 * test_layer_settled.c: the settling's record of a sample (gw_layer_settled,
 * layer_sample_settings.c) and the impact's check of it (layer_settled.c).
 *
 *  1. The reader: a one-disc sample with layer-make's settings line in the
 *     program's dialect (a "material" object) and the library's (flat rows,
 *     "mass-law": "sphere"), after blanks, with CRLF line ends, among the
 *     particle lines, keeps the material exactly (the numbers as written) and
 *     the line; no line, a "settingsX:" comment and a JSON object without
 *     material are "not recorded"; an altered line (not JSON, trailing text,
 *     empty, a string or missing value, density 0, poisson 0.5, gravity 0, a
 *     mass law "cube", a second line, a line of 70000 characters) is
 *     GW_EFORMAT naming the file and the line.
 *  2. gw_layer_make's sample records its lp, the true G after a softened
 *     start (modulus_factor 0.5).
 *  3. gw_layer_settled_load_ratio against the formula computed here
 *     (G/(1 - nu) ratio x the weights' ratio, discs and spheres), to 1e-14.
 *  4. gw_layer_impact_settled_check: refused below 0.5 and above 1.5 (with the
 *     values named), run with a warning by other_settling, warned inside
 *     [0.5, 1.5], for a higher friction or another mass law; a lower
 *     friction, even by 0.01 degree, refused and run with a warning by
 *     other_settling (test_settling_friction.sh); nothing for the same
 *     material, for a material in the same proportions (density x 2 and
 *     gravity / 2: the same rest) and when nothing is recorded.
 * Before this change the sample had no settling record: none of this compiles.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_layer.h"
#include "gw_test.h"

static char dir[] = "/tmp/gw_settled_XXXXXX";

static const char *program_line =
    "# settings: {\"n\":1,\"material\":{\"shear_modulus\":400000000000,\"poisson\":0.3,\"friction_deg\":25,"
    "\"density\":100.5,\"gravity\":1.62,\"skin\":0.1,\"normal_damping\":0,\"mass_law\":\"disc (unit thickness)\","
    "\"clump_mass\":\"sum\"}}";
static const char *library_line =
    "# settings: {\"friction\":12,\"shear-modulus\":3e9,\"poisson\":0.1,\"density\":7800,\"gravity\":3.71,"
    "\"mass-law\":\"sphere\",\"out\":\"x.txt\"}\nmass_law sphere"; /* the header's mass law, the line's */

/* A one-disc sample (the reader's checks pass it) with the lines pre before
 * its header, mid between "n 1" and the disc, and CRLF ends when crlf. */
static const char *write_sample(const char *name, const char *pre, const char *mid, int crlf)
{
    static char path[256];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    const char *e = crlf ? "\r\n" : "\n";
    fprintf(f, "granwave-layer-sample 1%s%s%s", e, pre ? pre : "", pre && *pre ? e : "");
    fprintf(f, "width 20%srm 0.325%svolume_ratio 1%sn 1%s", e, e, e, e);
    fprintf(f, "%s%s10 0.325 0.325%s", mid ? mid : "", mid && *mid ? e : "", e);
    fclose(f);
    return path;
}

static void read_ok(const char *what, const char *path, int recorded, long line, gw_layer_sample *s)
{
    gw_err err = {{0}};
    int rc = gw_layer_sample_read(path, s, &err);
    char m[900];
    snprintf(m, sizeof m, "%s: read (%s), recorded %d at line %ld", what, rc ? err.msg : "ok", s->settled.recorded,
             s->settled.line);
    gw_test_true(rc == GW_OK && s->settled.recorded == recorded && s->settled.line == line, m);
}

static void read_refused(const char *what, const char *path, const char *want)
{
    gw_err err = {{0}};
    gw_layer_sample s;
    int rc = gw_layer_sample_read(path, &s, &err);
    char m[700];
    snprintf(m, sizeof m, "%s: GW_EFORMAT naming '%s': %d %s", what, want, rc, err.msg);
    gw_test_true(rc == GW_EFORMAT && strstr(err.msg, path) && strstr(err.msg, want) && s.n == 0 && !s.x, m);
}

/* the program's line with FROM replaced by TO */
static const char *program_edit(const char *from, const char *to)
{
    static char buf[1024];
    const char *p = strstr(program_line, from);
    snprintf(buf, sizeof buf, "%.*s%s%s", (int)(p - program_line), program_line, to, p + strlen(from));
    return buf;
}

static void reading(void)
{
    gw_layer_sample s;
    read_ok("no settings line", write_sample("none.txt", NULL, NULL, 0), 0, 0, &s);
    gw_layer_sample_free(&s);
    read_ok("program's dialect", write_sample("prog.txt", program_line, NULL, 0), 1, 2, &s);
    gw_test_true(s.settled.shear_modulus == 4e11 && s.settled.poisson == 0.3 && s.settled.friction_deg == 25 &&
                 s.settled.density == 100.5 && s.settled.gravity == 1.62 && s.settled.mass_law == GW_LAYER_MASS_DISC,
                 "program's dialect: the values as written");
    gw_layer_sample_free(&s);
    /* the reader knows the program's text of the disc law by heart (it links without the model) */
    gw_test_true(strcmp(gw_layer_mass_law_name(GW_LAYER_MASS_DISC), "disc (unit thickness)") == 0,
                 "the program's mass-law text is the one the reader knows");
    read_ok("library's dialect", write_sample("lib.txt", library_line, NULL, 0), 1, 2, &s);
    gw_test_true(s.settled.shear_modulus == 3e9 && s.settled.poisson == 0.1 && s.settled.friction_deg == 12 &&
                 s.settled.density == 7800 && s.settled.gravity == 3.71 && s.settled.mass_law == GW_LAYER_MASS_SPHERE,
                 "library's dialect: the values as written, mass law sphere");
    gw_layer_sample_free(&s);
    char blanks[1200];
    snprintf(blanks, sizeof blanks, "  \t#\t settings:%s", program_line + strlen("# settings:"));
    read_ok("blanks around '#'", write_sample("blanks.txt", blanks, NULL, 0), 1, 2, &s);
    gw_layer_sample_free(&s);
    read_ok("CRLF", write_sample("crlf.txt", program_line, NULL, 1), 1, 2, &s);
    gw_test_true(s.settled.gravity == 1.62, "CRLF: gravity 1.62");
    gw_layer_sample_free(&s);
    read_ok("among the particle lines", write_sample("mid.txt", "# a comment", program_line, 0), 1, 7, &s);
    gw_layer_sample_free(&s);
    read_ok("settingsX: another comment", write_sample("x.txt", "# settingsX: {oops", NULL, 0), 0, 0, &s);
    gw_layer_sample_free(&s);
    read_ok("JSON without material", write_sample("nomat.txt", "# settings: {\"note\": \"by hand\"}", NULL, 0), 0,
            0, &s);
    gw_layer_sample_free(&s);

    read_refused("not JSON", write_sample("b1.txt", "# settings: {oops", NULL, 0), "line 2: layer-make's settings "
                 "line is not a JSON object");
    char trail[1200];
    snprintf(trail, sizeof trail, "%s x", program_line);
    read_refused("text after the JSON", write_sample("b2.txt", trail, NULL, 0), "line 2: layer-make's settings");
    read_refused("empty", write_sample("b3.txt", "# settings:", NULL, 0), "line 2: layer-make's settings line is not");
    read_refused("a string", write_sample("b4.txt", program_edit("\"density\":100.5", "\"density\":\"100.5\""), NULL,
                                          0), "not a finite number: density");
    read_refused("missing gravity", write_sample("b5.txt", program_edit("\"gravity\":1.62,", ""), NULL, 0),
                 "lacks gravity");
    read_refused("density 0", write_sample("b6.txt", program_edit("\"density\":100.5", "\"density\":0"), NULL, 0),
                 "outside the material's range: density");
    read_refused("poisson 0.5", write_sample("b7.txt", program_edit("\"poisson\":0.3", "\"poisson\":0.5"), NULL, 0),
                 "outside the material's range: poisson");
    read_refused("gravity 0", write_sample("b8.txt", program_edit("\"gravity\":1.62", "\"gravity\":0"), NULL, 0),
                 "outside the material's range: gravity");
    read_refused("mass law cube", write_sample("b9.txt", program_edit("disc (unit thickness)", "cube"), NULL, 0),
                 "neither disc nor sphere");
    read_refused("a second line", write_sample("b10.txt", program_line, program_line, 0),
                 "line 7: a second settings line (the first at line 2)");
    char *big = malloc(70100);
    snprintf(big, 70100, "# settings: {\"pad\": \"%0*d\"}", 70000, 0);
    read_refused("70000 characters", write_sample("b11.txt", big, NULL, 0), "longer than 65536 characters");
    free(big);
}

static void made(void)
{
    gw_layer_params lp = gw_layer_params_default();
    lp.density = 1234;
    lp.friction_deg = 20;
    gw_layer_make_params mp = gw_layer_make_params_default();
    mp.n = 12;
    mp.width_rm = 10;
    mp.t_max = 0.2;
    mp.modulus_factor = 0.5;
    gw_layer_sample s;
    gw_layer_make_result r;
    gw_err err = {{0}};
    int rc = gw_layer_make(&lp, &mp, &s, &r, &err);
    gw_test_true(rc == GW_OK && s.settled.recorded && s.settled.shear_modulus == lp.shear_modulus &&
                 s.settled.density == 1234 && s.settled.friction_deg == 20 && s.settled.gravity == lp.gravity &&
                 s.settled.poisson == lp.poisson && s.settled.mass_law == lp.mass_law,
                 "gw_layer_make records its material, G and not 0.5 G");
    if (rc == GW_OK)
        gw_layer_sample_free(&s);
}

static gw_layer_sample three(double rho, double g, double G, double nu, int law)
{
    static double x[3] = {1, 2, 3}, y[3] = {0.2, 0.3, 0.4}, r[3] = {0.2, 0.3, 0.4};
    /* the sample's mass law the record's, as a file's header and settings
     * line must agree (the shared sample check holds a record so) */
    gw_layer_sample s = {.n = 3, .width = 4, .rm = 0.3, .mass_law = law, .x = x, .y = y, .r = r};
    s.settled = (gw_layer_settled){.recorded = 1, .shear_modulus = G, .poisson = nu, .friction_deg = 30,
                                   .density = rho, .gravity = g, .mass_law = law};
    return s;
}

static double weight(int law, double rho, double g)
{
    double w = 0;
    for (int i = 0; i < 3; i++) {
        double r = 0.2 + 0.1 * i;
        w += law == GW_LAYER_MASS_SPHERE ? 4.0 / 3.0 * M_PI * rho * r * r * r : M_PI * rho * r * r;
    }
    return w * g;
}

static void ratio(void)
{
    gw_layer_params lp = gw_layer_params_default(); /* 40e9, 0.25, 2650, 9.81, disc */
    gw_layer_sample s = three(100, 9.81, 40e9, 0.25, GW_LAYER_MASS_DISC);
    gw_test_rel(gw_layer_settled_load_ratio(&s, &lp), 100.0 / 2650, 1e-14, "density 100 under 2650: 100/2650");
    s = three(1800, 1.62, 4e11, 0.1, GW_LAYER_MASS_SPHERE);
    const double q = (40e9 / 0.75) / (4e11 / 0.9) * weight(GW_LAYER_MASS_SPHERE, 1800, 1.62) /
                     weight(GW_LAYER_MASS_DISC, 2650, 9.81);
    gw_test_rel(gw_layer_settled_load_ratio(&s, &lp), q, 1e-14, "sphere, G 4e11, nu 0.1, g 1.62 under the defaults");
    s.settled.recorded = 0;
    gw_test_true(isnan(gw_layer_settled_load_ratio(&s, &lp)), "not recorded: NaN");
}

static void check(const char *what, gw_layer_sample s, const gw_layer_params *lp, int other, int want_rc,
                  const char *want_text)
{
    char w[768] = "x";
    gw_err err = {{0}};
    int rc = gw_layer_impact_settled_check(&s, lp, other, "S", w, sizeof w, &err);
    const char *text = rc == GW_OK ? w : err.msg;
    char m[1200];
    snprintf(m, sizeof m, "%s: status %d, '%s'", what, rc, text);
    gw_test_true(rc == want_rc && (want_text ? strstr(text, want_text) != NULL : w[0] == '\0'), m);
}

static void checks(void)
{
    gw_layer_params lp = gw_layer_params_default();
    check("q 0.0377: refused", three(100, 9.81, 40e9, 0.25, 0), &lp, 0, GW_EINVAL,
          "sample 'S': it settled with density 100 kg/m^3 against the impact's 2650");
    check("q 0.0377 with other_settling: a warning", three(100, 9.81, 40e9, 0.25, 0), &lp, 1, GW_OK,
          "carry 0.0377 times the weight they carried at rest (outside [0.5, 1.5]");
    check("q 0.49: refused", three(0.49 * 2650, 9.81, 40e9, 0.25, 0), &lp, 0, GW_EINVAL, "0.49 times");
    check("q 0.51: a warning", three(0.51 * 2650, 9.81, 40e9, 0.25, 0), &lp, 0, GW_OK, "0.51 times");
    check("q 1.49: a warning", three(1.49 * 2650, 9.81, 40e9, 0.25, 0), &lp, 0, GW_OK, "springs up into the impact");
    check("q 1.51: refused", three(1.51 * 2650, 9.81, 40e9, 0.25, 0), &lp, 0, GW_EINVAL, "1.51 times");
    check("G 4e9 (q 10): refused", three(2650, 9.81, 4e9, 0.25, 0), &lp, 0, GW_EINVAL,
          "shear-modulus 4e+09 Pa against the impact's 4e+10");
    check("the same material: nothing", three(2650, 9.81, 40e9, 0.25, 0), &lp, 0, GW_OK, NULL);
    check("density x 2, gravity / 2 (the same rest): nothing", three(5300, 4.905, 40e9, 0.25, 0), &lp, 0, GW_OK,
          NULL);
    gw_layer_params lf = lp;
    lf.friction_deg = 20; /* tan 20 / tan 30 = 0.63 */
    check("friction 20 against 30: refused", three(2650, 9.81, 40e9, 0.25, 0), &lf, 0, GW_EINVAL,
          "friction 30 deg against the impact's 20");
    check("friction 20 against 30, other_settling: a warning that it may flow", three(2650, 9.81, 40e9, 0.25, 0),
          &lf, 1, GW_OK, "the pile may flow on it");
    lf.friction_deg = 29.99;
    check("friction 29.99 against 30: refused", three(2650, 9.81, 40e9, 0.25, 0), &lf, 0, GW_EINVAL,
          "settling's friction (30 deg) or more");
    lf.friction_deg = 40;
    check("friction 40 against 30: a warning", three(2650, 9.81, 40e9, 0.25, 0), &lf, 0, GW_OK,
          "friction 30 deg against the impact's 40");
    gw_layer_params ls = lp;
    ls.mass_law = GW_LAYER_MASS_SPHERE;
    ls.density = 2650 / 0.3; /* the spheres' weight about the discs' */
    check("another mass law", three(2650, 9.81, 40e9, 0.25, 0), &ls, 1, GW_OK, "mass-law disc against the impact's "
          "sphere");
    gw_layer_params l0 = lp;
    l0.gravity = 0;
    check("no gravity in the impact: refused", three(2650, 9.81, 40e9, 0.25, 0), &l0, 0, GW_EINVAL,
          "without gravity in the impact its contacts hold the forces of its settling");
    gw_layer_sample none = three(100, 9.81, 40e9, 0.25, 0);
    none.settled.recorded = 0;
    check("not recorded: nothing", none, &lp, 0, GW_OK, NULL);
}

int main(void)
{
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    reading();
    made();
    ratio();
    checks();
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        printf("note: %s not removed\n", dir);
    return gw_test_summary("test_layer_settled");
}
