/*
 * gw_cli.c: table-driven command-line options with range checks. Every error names
 * the option and the offending value in one line.
 */
#include <math.h>
#include <string.h>

#include "gw_cli.h"
#include "gw_common.h"

const gw_opt *gw_cli_find(const gw_opt *opts, const char *name)
{
    for (const gw_opt *o = opts; o->name; o++)
        if (strcmp(o->name, name) == 0)
            return o;
    return NULL;
}

static int set_value(const char *cmd, gw_opt *o, const char *val, gw_err *err)
{
    char name[128];
    snprintf(name, sizeof name, "%s --%s", cmd, o->name);
    int rc = GW_OK;
    switch (o->kind) {
    case GW_OPT_DOUBLE: {
        double v;
        if ((rc = gw_parse_double(val, name, &v, err)) != GW_OK)
            return rc;
        if (v < o->lo || v > o->hi || (o->open_lo && !(v > o->lo))) {
            if (o->open_lo && !isfinite(o->hi))
                return gw_err_set(err, GW_EINVAL, "%s: %s must be > %g", name, val, o->lo);
            return gw_err_set(err, GW_EINVAL, "%s: %s is outside %s%g, %g]", name, val,
                              o->open_lo ? "(" : "[", o->lo, o->hi);
        }
        *(double *)o->dest = v;
        break;
    }
    case GW_OPT_LONG: {
        long lo = (long)o->lo + (o->open_lo ? 1 : 0);
        long v;
        if ((rc = gw_parse_long(val, name, lo, (long)o->hi, &v, err)) != GW_OK)
            return rc;
        *(long *)o->dest = v;
        break;
    }
    case GW_OPT_STRING:
        if (!*val)
            return gw_err_set(err, GW_EINVAL, "%s: empty value", name);
        *(const char **)o->dest = val;
        break;
    case GW_OPT_FLAG:
        *(int *)o->dest = 1;
        break;
    }
    o->seen = 1;
    return GW_OK;
}

int gw_cli_parse(const char *cmd, gw_opt *opts, int argc, char **argv, int *help,
                 const char **pos, int maxpos, int *npos, gw_err *err)
{
    *help = 0;
    *npos = 0;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            *help = 1;
            continue;
        }
        if (strncmp(a, "--", 2) != 0) {
            if (*npos >= maxpos)
                return gw_err_set(err, GW_EINVAL, "%s: unexpected argument '%s' (see %s --help)",
                                  cmd, a, cmd);
            pos[(*npos)++] = a;
            continue;
        }
        char name[96];
        const char *eq = strchr(a + 2, '=');
        size_t len = eq ? (size_t)(eq - (a + 2)) : strlen(a + 2);
        if (len == 0 || len >= sizeof name)
            return gw_err_set(err, GW_EINVAL, "%s: unknown option '%s' (see %s --help)", cmd,
                              a, cmd);
        memcpy(name, a + 2, len);
        name[len] = '\0';
        gw_opt *o = (gw_opt *)gw_cli_find(opts, name);
        if (!o)
            return gw_err_set(err, GW_EINVAL, "%s: unknown option '--%s' (see %s --help)", cmd,
                              name, cmd);
        if (o->kind == GW_OPT_FLAG) {
            if (eq)
                return gw_err_set(err, GW_EINVAL, "%s: option '--%s' takes no value", cmd, name);
            set_value(cmd, o, "", err);
            continue;
        }
        const char *val = eq ? eq + 1 : NULL;
        if (!val) {
            if (i + 1 >= argc)
                return gw_err_set(err, GW_EINVAL, "%s: option '--%s' needs a value %s", cmd,
                                  name, o->metavar ? o->metavar : "");
            val = argv[++i];
        }
        int rc = set_value(cmd, o, val, err);
        if (rc != GW_OK)
            return rc;
    }
    return GW_OK;
}

void gw_cli_help(FILE *fp, const char *cmd, const char *usage, const char *summary,
                 const gw_opt *opts)
{
    fprintf(fp, "usage: %s\n\n%s\n\noptions:\n", usage, summary);
    for (const gw_opt *o = opts; o->name; o++) {
        char left[64];
        snprintf(left, sizeof left, "--%s%s%s", o->name, o->metavar ? " " : "",
                 o->metavar ? o->metavar : "");
        fprintf(fp, "  %-22s %s\n", left, o->help);
    }
    fprintf(fp, "  %-22s %s\n", "--help", "show this help and exit");
    (void)cmd;
}
