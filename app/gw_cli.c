/*
 * gw_cli.c: table-driven command-line options with range checks. Every error names
 * the option and the offending value in one line.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_cli.h"
#include "gw_common.h"
#include "gw_locale.h"
#include "gw_number_impl.h"
#include "gw_param.h"

const gw_opt *gw_cli_find(const gw_opt *opts, const char *name)
{
    for (const gw_opt *o = opts; o->name; o++)
        if (strcmp(o->name, name) == 0)
            return o;
    return NULL;
}

int gw_cli_opt_param(const gw_param *p, void *dest, gw_opt *o, gw_err *err)
{
    *o = (gw_opt){.name = p->name, .dest = dest, .metavar = p->metavar, .help = p->help, .lo = p->min,
                  .hi = p->max, .open_lo = p->open_min, .open_hi = p->open_max, .param = p};
    switch (p->type) {
    case GW_PARAM_DOUBLE: o->kind = GW_OPT_DOUBLE; break;
    case GW_PARAM_COUNT: o->kind = GW_OPT_COUNT; break;
    case GW_PARAM_LONG: o->kind = GW_OPT_LONG; break;
    case GW_PARAM_FLAG: o->kind = GW_OPT_FLAG; break;
    case GW_PARAM_CHOICE:
    case GW_PARAM_TEXT:
        o->kind = GW_OPT_STRING;
        *(const char **)dest = p->optional ? NULL : p->def; /* an optional row: not given (gw_param.h) */
        return GW_OK;
    default:
        return gw_err_set(err, GW_EINVAL, "%s: a %s row is not a command-line option", p->name,
                          gw_param_type_name(p->type));
    }
    if (p->type == GW_PARAM_FLAG) {
        *(int *)dest = 0;
        return p->def && strcmp(p->def, "0") != 0
                   ? gw_err_set(err, GW_EINVAL, "%s: a flag option is off by default", p->name) : GW_OK;
    }
    if (p->type == GW_PARAM_DOUBLE || p->type == GW_PARAM_COUNT)
        *(double *)dest = NAN;
    else
        *(long *)dest = p->optional ? GW_PARAM_UNSET_LONG : 0;
    return p->def && !p->optional ? gw_param_set_value(p, dest, p->def, err) : GW_OK;
}

/* The value checked by the option's table row: the row's message "NAME:
 * reason" becomes "CMD --NAME: reason". */
static int set_by_row(const char *cmd, gw_opt *o, const char *val, gw_err *err)
{
    const gw_param *p = o->param;
    gw_err e = {{0}};
    int rc, idx;
    if (o->kind == GW_OPT_STRING && p->type == GW_PARAM_CHOICE)
        rc = gw_param_set_value(p, &idx, val, &e); /* checked; the text is kept */
    else if (o->kind == GW_OPT_STRING)
        rc = *val ? GW_OK : gw_err_set(&e, GW_EINVAL, "%s: empty value", p->name);
    else
        rc = gw_param_set_value(p, o->dest, val, &e);
    if (rc != GW_OK) {
        size_t n = strlen(p->name);
        const char *why = strncmp(e.msg, p->name, n) == 0 && e.msg[n] == ':' ? e.msg + n + 1 : e.msg;
        return gw_err_set(err, rc, "%s --%s:%s%s", cmd, o->name, why == e.msg ? " " : "", why);
    }
    if (o->kind == GW_OPT_STRING)
        *(const char **)o->dest = val;
    o->seen = 1;
    return GW_OK;
}

/* One end of an option's range as its refusal prints it: -inf or inf when
 * unbounded, an integer's or a count's in full (a count's 8388606 was
 * 8.3886e+06), a real's rounded toward the inside (gw_num_bound: the printed
 * bound is taken when given back). */
static void range_end(char *buf, size_t n, double x, int whole, int upper)
{
    if (!isfinite(x))
        gw_snprintf(buf, n, "%s", upper ? "inf" : "-inf");
    else if (whole)
        gw_snprintf(buf, n, "%.0f", upper ? floor(x) : ceil(x));
    else
        gw_num_bound(buf, n, x, upper);
}

static int set_value(const char *cmd, gw_opt *o, const char *val, gw_err *err)
{
    char name[128];
    snprintf(name, sizeof name, "%s --%s", cmd, o->name);
    int rc = GW_OK;
    if (o->param && o->kind != GW_OPT_FLAG)
        return set_by_row(cmd, o, val, err);
    switch (o->kind) {
    case GW_OPT_DOUBLE:
    case GW_OPT_COUNT: {
        double v; /* a subnormal refused naming the option's range */
        const gw_num_range r = {o->lo, o->hi, o->open_lo, o->open_hi, 0, o->kind == GW_OPT_COUNT};
        const int count = o->kind == GW_OPT_COUNT;
        if ((rc = gw_parse_double_in(val, name, &r, &v, err)) != GW_OK)
            return rc;
        char ls[32], hs[32]; /* numbers the range holds (range_end) */
        range_end(ls, sizeof ls, o->lo, count, 0);
        range_end(hs, sizeof hs, o->hi, count, 1);
        if (v < o->lo || v > o->hi || (o->open_lo && !(v > o->lo)) || (o->open_hi && !(v < o->hi))) {
            if (o->open_lo && !isfinite(o->hi))
                return gw_err_set(err, GW_EINVAL, "%s: %s must be > %s", name, val, ls);
            return gw_err_set(err, GW_EINVAL, "%s: %s is outside %s%s, %s%s", name, val,
                              o->open_lo ? "(" : "[", ls, hs, o->open_hi ? ")" : "]");
        }
        if (count && v != floor(v)) /* a count as the library's count rows take it (gw_param.h) */
            return gw_err_set(err, GW_EINVAL, "%s: '%s' is not a whole number (give an integer in [%s, %s])", name,
                              val, ls, hs);
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

/* 1 when a is one of opts' options as the command line gives them ("--NAME",
 * "--NAME=VALUE", "--help", "-h") */
static int is_option(const gw_opt *opts, const char *a)
{
    if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0)
        return 1;
    if (strncmp(a, "--", 2) != 0)
        return 0;
    char name[96];
    const char *eq = strchr(a + 2, '=');
    size_t len = eq ? (size_t)(eq - (a + 2)) : strlen(a + 2);
    if (len == 0 || len >= sizeof name)
        return 0;
    memcpy(name, a + 2, len);
    name[len] = '\0';
    return gw_cli_find(opts, name) != NULL;
}

int gw_cli_parse(const char *cmd, gw_opt *opts, int argc, char **argv, int *help,
                 const char **pos, int maxpos, int *npos, gw_err *err)
{
    *help = 0;
    *npos = 0;
    int ended = 0; /* "--" seen: what follows is positional (POSIX guideline 10) */
    int json_help = 0; /* the argument index of a --json that opts lacks (0: none) */
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (!ended && strcmp(a, "--") == 0) { /* was "unknown option '--'" */
            ended = 1;
            continue;
        }
        if (!ended && (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0)) {
            *help = 1;
            continue;
        }
        if (ended || strncmp(a, "--", 2) != 0) {
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
        if (!o && !eq && strcmp(name, "json") == 0 && !json_help) { /* a table without --json: with --help only */
            json_help = i + 1;
            continue;
        }
        if (!o && strcmp(name, "help") == 0) /* "--help=1": the option is known, its value is not */
            return gw_err_set(err, GW_EINVAL, "%s: option '--help' takes no value", cmd);
        if (!o)
            return gw_err_set(err, GW_EINVAL, "%s: unknown option '--%s' (see %s --help)", cmd,
                              name, cmd);
        if (o->seen) /* the last value winning silently hid a mistake ("--n 3 ... --n 30") */
            return gw_err_set(err, GW_EINVAL, "%s --%s: given twice", cmd, name);
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
            /* the next option taken as this one's value left it without effect:
             * `--out --json` made a directory "--json" and printed no JSON */
            if (is_option(opts, argv[i + 1]))
                return gw_err_set(err, GW_EINVAL, "%s --%s: needs a value %s, and '%s' is an option of %s (give "
                                  "--%s=%s for a value of that spelling)", cmd, name,
                                  o->metavar ? o->metavar : "", argv[i + 1], cmd, name, argv[i + 1]);
            val = argv[++i];
        }
        int rc = set_value(cmd, o, val, err);
        if (rc != GW_OK)
            return rc;
    }
    if (json_help && !*help) /* --json is no option of this command's run */
        return gw_err_set(err, GW_EINVAL, "%s: unknown option '--json' (see %s --help)", cmd, cmd);
    const gw_opt *json = gw_cli_find(opts, "json");
    if (*help && (json_help || (json && json->kind == GW_OPT_FLAG && json->seen)))
        *help = GW_CLI_HELP_JSON;
    return GW_OK;
}

/* what a range that also takes 0 prints after its brackets, as the parameter
 * table's refusals do (gw_param.c) */
#define OR_ZERO " (or 0)"

/* The text of a help line from its "[" or "(" at from to the first "]" or ")"
 * after it, brackets included, and the OR_ZERO that follows it, if
 * any, as a new cJSON string; NULL when not closed. */
static cJSON *help_span(const char *from)
{
    const char *close = strpbrk(from + 1, "])");
    if (!close)
        return NULL;
    const size_t z = strlen(OR_ZERO);
    int len = (int)(close + 1 - from) + (strncmp(close + 1, OR_ZERO, z) == 0 ? (int)z : 0);
    char buf[256];
    gw_snprintf(buf, sizeof buf, "%.*s", len, from);
    return cJSON_CreateString(buf);
}

/* The opening bracket of the range a help prints ("in [LO, HI]", "in (LO,
 * HI)": its first, closed), or NULL. */
static const char *range_at(const char *help)
{
    for (const char *p = help; p && (p = strstr(p, "in ")) != NULL; p++)
        if ((p == help || p[-1] == ' ') && (p[3] == '[' || p[3] == '('))
            return strpbrk(p + 4, "])") ? p + 3 : NULL;
    return NULL;
}

/* The range the help prints (range_at), brackets included, or NULL; *at its
 * opening bracket. */
static cJSON *help_range(const char *help, const char **at)
{
    *at = range_at(help);
    return *at ? help_span(*at) : NULL;
}

/* The last "[...]" of a help line that does not open at skip (the range's
 * bracket, or NULL): its "[", *end its "]"; NULL when none. The default's. */
static const char *last_brackets(const char *help, const char *skip, const char **end)
{
    const char *last = NULL;
    *end = NULL;
    for (const char *p = help ? strchr(help, '[') : NULL; p; p = strchr(p + 1, '[')) {
        const char *close = strchr(p, ']');
        if (!close)
            break;
        if (p != skip) {
            last = p;
            *end = close;
        }
        p = close;
    }
    return last;
}

/* The default the help prints: the text of its last "[...]" that is not the
 * range (at), or NULL. */
static cJSON *help_default(const char *help, const char *at)
{
    const char *end, *last = last_brackets(help, at, &end);
    if (!last)
        return NULL;
    char buf[256];
    gw_snprintf(buf, sizeof buf, "%.*s", (int)(end - last - 1), last + 1);
    return cJSON_CreateString(buf);
}

/* The unit the help prints before its range ("bead radius, m, in [...]": "m"),
 * or NULL: the short field between ", " and ", in " (at: the range's bracket).
 * Read where the row's own text prints its range only: before one help_line
 * adds, the field is whatever the text ends with ("even", "cvode/arkode"). */
static cJSON *help_unit(const char *help, const char *at)
{
    if (!at || at - help < 6 || strncmp(at - 5, ", in ", 5) != 0)
        return NULL;
    const char *end = at - 5, *start = end;
    while (start > help && !(start[-1] == ' ' && start - 1 > help && start[-2] == ','))
        start--;
    if (start == help || end - start < 1 || end - start > 12)
        return NULL;
    char buf[16];
    gw_snprintf(buf, sizeof buf, "%.*s", (int)(end - start), start);
    return cJSON_CreateString(buf);
}

/* The range the parser checks into buf, in its refusal's notation ("(0,
 * 1e+06]", "[1e-09, 0.01] (or 0)", "(0, inf)"): 1, or 0 (buf "") when o is no
 * number option or has no bound. */
static int parser_range(const gw_opt *o, char *buf, size_t n)
{
    buf[0] = '\0';
    if (!o || (o->kind != GW_OPT_DOUBLE && o->kind != GW_OPT_LONG && o->kind != GW_OPT_COUNT) ||
        (!isfinite(o->lo) && !isfinite(o->hi)))
        return 0;
    char ls[32], hs[32];
    const int whole = o->kind == GW_OPT_LONG || o->kind == GW_OPT_COUNT;
    range_end(ls, sizeof ls, o->lo, whole, 0);
    range_end(hs, sizeof hs, o->hi, whole, 1);
    const int or_zero = o->param && o->param->or_zero;
    gw_snprintf(buf, n, "%s%s, %s%s%s", o->open_lo || !isfinite(o->lo) ? "(" : "[", ls, hs,
                o->open_hi || !isfinite(o->hi) ? ")" : "]", or_zero ? OR_ZERO : "");
    return 1;
}

/* The help line of option o (help: its text; o NULL: --help's) as the text
 * help and the JSON's "help" print it: the text, and where it prints no range
 * ("in [...]") and the parser checks one (parser_range), ", in RANGE" put
 * before the default's brackets (the last "[...]"), else at the end, as the
 * lines that print theirs do ("impact velocity, m/s, in [1e-09, 1000]
 * [0.3]"); *added (may be NULL) 1 when it did. A new string the caller
 * frees; NULL when out of memory. */
static char *help_line(const gw_opt *o, const char *help, int *added)
{
    const char *end;
    char range[96] = "";
    help = help ? help : "";
    const int add = !range_at(help) && parser_range(o, range, sizeof range);
    if (added)
        *added = add;
    const char *def = add ? last_brackets(help, NULL, &end) : NULL;
    size_t cut = def ? (size_t)(def - help) : strlen(help);
    const int space = def && cut > 0 && help[cut - 1] == ' ';
    cut -= space; /* ", in RANGE" after the text, the blank before the default kept */
    const size_t n = strlen(help) + strlen(range) + 8;
    char *line = malloc(n);
    if (line)
        gw_snprintf(line, n, "%.*s%s%s%s%s", (int)cut, help, add ? ", in " : "", add ? range : "",
                    def && !space ? " " : "", help + cut);
    return line;
}

static const char *opt_kind_name(const gw_opt *o)
{
    if (o->kind == GW_OPT_STRING && o->param && o->param->type == GW_PARAM_CHOICE)
        return "choice";
    return o->kind == GW_OPT_FLAG                                ? "flag"
           : o->kind == GW_OPT_DOUBLE                            ? "number"
           : o->kind == GW_OPT_LONG || o->kind == GW_OPT_COUNT ? "integer" /* a count: a whole number */
                                                                 : "text";
}

static cJSON *num_or_null(double v)
{
    return isfinite(v) ? cJSON_CreateNumber(v) : cJSON_CreateNull();
}

static cJSON *str_or_null(const char *s)
{
    return s && *s ? cJSON_CreateString(s) : cJSON_CreateNull();
}

/* One option of the help as JSON: what its help line (help_line: the text
 * help's) says, field by field; NULL when out of memory. */
static cJSON *opt_json(const char *name, const char *text, const gw_opt *o)
{
    int added;
    char *help = help_line(o, text, &added);
    cJSON *j = help ? cJSON_CreateObject() : NULL;
    if (!j) {
        free(help);
        return NULL;
    }
    const gw_param *p = o ? o->param : NULL;
    const char *at;
    cJSON *range = help_range(help, &at), *def = help_default(help, at);
    if (!def && p && p->def && o->kind != GW_OPT_FLAG)
        def = cJSON_CreateString(p->def);
    cJSON_AddItemToObject(j, "name", cJSON_CreateString(name));
    cJSON_AddItemToObject(j, "metavar", str_or_null(o ? o->metavar : NULL));
    cJSON_AddItemToObject(j, "kind", cJSON_CreateString(o ? opt_kind_name(o) : "flag"));
    cJSON *unit = p && p->unit && *p->unit ? cJSON_CreateString(p->unit) : added ? NULL : help_unit(help, at);
    cJSON_AddItemToObject(j, "unit", unit ? unit : cJSON_CreateNull());
    cJSON_AddItemToObject(j, "range", range ? range : cJSON_CreateNull());
    const int num = o && (o->kind == GW_OPT_DOUBLE || o->kind == GW_OPT_LONG || o->kind == GW_OPT_COUNT);
    cJSON_AddItemToObject(j, "min", num ? num_or_null(o->lo) : cJSON_CreateNull());
    cJSON_AddItemToObject(j, "max", num ? num_or_null(o->hi) : cJSON_CreateNull());
    cJSON_AddItemToObject(j, "default", def ? def : !o || o->kind == GW_OPT_FLAG ? cJSON_CreateFalse()
                                                                                : cJSON_CreateNull());
    cJSON *ch = cJSON_CreateArray();
    for (const char *c = p && p->type == GW_PARAM_CHOICE ? p->choices : NULL; ch && c && *c;) {
        size_t len = strcspn(c, ",");
        char buf[64];
        gw_snprintf(buf, sizeof buf, "%.*s", (int)len, c);
        cJSON_AddItemToArray(ch, cJSON_CreateString(buf));
        c += len + (c[len] == ',');
    }
    cJSON_AddItemToObject(j, "choices", p && p->type == GW_PARAM_CHOICE ? ch : (cJSON_Delete(ch), cJSON_CreateNull()));
    cJSON_AddItemToObject(j, "help", cJSON_CreateString(help));
    free(help);
    return j;
}

static int help_json(const char *cmd, const char *usage, const char *summary, const gw_opt *opts)
{
    cJSON *o = cJSON_CreateObject(), *list = NULL;
    int ok = o && cJSON_AddStringToObject(o, "command", cmd) &&
             cJSON_AddStringToObject(o, "usage", usage) && cJSON_AddStringToObject(o, "summary", summary) &&
             (list = cJSON_AddArrayToObject(o, "options")) != NULL;
    for (const gw_opt *p = opts; ok && p->name; p++) {
        cJSON *one = opt_json(p->name, p->help, p);
        ok = one && cJSON_AddItemToArray(list, one);
    }
    cJSON *h = ok ? opt_json("help", GW_CLI_HELP_TEXT, NULL) : NULL;
    ok = ok && h && cJSON_AddItemToArray(list, h);
    const int code = gw_cli_json_stdout(cmd, ok ? o : NULL);
    cJSON_Delete(o);
    return code;
}

int gw_cli_help(FILE *fp, const char *cmd, const char *usage, const char *summary, const gw_opt *opts, int help)
{
    if (help == GW_CLI_HELP_JSON)
        return help_json(cmd, usage, summary, opts);
    fprintf(fp, "usage: %s\n\n%s\n\noptions:\n", usage, summary);
    for (const gw_opt *o = opts; o->name; o++) {
        char left[64];
        snprintf(left, sizeof left, "--%s%s%s", o->name, o->metavar ? " " : "",
                 o->metavar ? o->metavar : "");
        char *line = help_line(o, o->help, NULL);
        if (!line)
            return gw_cli_nomem(cmd);
        fprintf(fp, "  %-22s %s\n", left, line);
        free(line);
    }
    fprintf(fp, "  %-22s %s\n", "--help", GW_CLI_HELP_TEXT);
    return 0;
}

int gw_cli_study_error(const gw_param *t, const char *cmd, int rc, gw_err *err)
{
    char tmp[sizeof err->msg], name[64];
    snprintf(tmp, sizeof tmp, "%s", err->msg);
    const size_t c = strlen(cmd);
    if (strncmp(tmp, cmd, c) == 0 && (tmp[c] == ':' || tmp[c] == ' '))
        return rc; /* it names the command already ("softwall: out of memory"): not twice */
    const char *colon = strchr(tmp, ':');
    size_t n = colon ? (size_t)(colon - tmp) : 0;
    int named = 0;
    if (colon && n < sizeof name) {
        memcpy(name, tmp, n);
        name[n] = '\0';
        named = gw_param_find(t, name) != NULL;
    }
    return gw_err_set(err, rc, named ? "%s --%s" : "%s: %s", cmd, tmp);
}

const char *gw_cli_path(char *buf, size_t n, const char *path)
{
    gw_one_line(buf, n, path ? path : "");
    return buf;
}

int gw_cli_nomem(const char *cmd)
{
    fprintf(stderr, "granwave %s: out of memory\n", cmd);
    return 1;
}

int gw_cli_stdout_failed(const char *cmd, int e)
{
    fprintf(stderr, "granwave%s%s: stdout: write failed: %s\n", cmd ? " " : "", cmd ? cmd : "",
            strerror(e ? e : EIO));
    clearerr(stdout);
    return 1;
}

int gw_cli_json_stdout(const char *cmd, const cJSON *o)
{
    const int rc = o ? gw_json_print(o, stdout) : GW_ENOMEM;
    if (rc == GW_EIO) /* its errno now: the flush emptied the buffer (a closed pipe said "Input/output error") */
        return gw_cli_stdout_failed(cmd, errno);
    if (rc == GW_OK)
        return 0;
    fprintf(stderr, "granwave %s: out of memory for the JSON result\n", cmd);
    return 1;
}

void gw_cli_error(const char *cmd, const char *msg)
{
    const size_t n = strlen(cmd);
    if (strncmp(msg, cmd, n) == 0 && (msg[n] == ' ' || msg[n] == ':'))
        fprintf(stderr, "granwave %s\n", msg);
    else
        fprintf(stderr, "granwave %s: %s\n", cmd, msg);
}

void gw_cli_warnings(const char *cmd, const char *list)
{
    for (const char *p = list; p && *p;) {
        const char *nl = strchr(p, '\n');
        const int len = nl ? (int)(nl - p) : (int)strlen(p);
        fprintf(stderr, "granwave %s: warning: %.*s\n", cmd, len, p);
        p += len + (nl != NULL);
    }
}

void gw_cli_json_warnings(cJSON *o, const char *list)
{
    cJSON *wl = o ? cJSON_AddArrayToObject(o, "warnings") : NULL;
    for (const char *p = list; wl && p && *p;) {
        const char *nl = strchr(p, '\n');
        const size_t len = nl ? (size_t)(nl - p) : strlen(p);
        char *one = malloc(len + 1);
        if (one) {
            memcpy(one, p, len);
            one[len] = '\0';
            cJSON_AddItemToArray(wl, cJSON_CreateString(one));
        }
        free(one);
        p += len + (nl != NULL);
    }
}

int gw_cli_study_setup(const gw_param *t, void *setup, const gw_opt *opts, int argc, char **argv,
                          const char *cmd, gw_err *err)
{
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *eq = strncmp(a, "--", 2) == 0 ? strchr(a + 2, '=') : NULL;
        if (strcmp(a, "--") == 0) /* the end of the options (gw_cli_parse) */
            break;
        if (strncmp(a, "--", 2) != 0)
            continue;
        char name[96];
        size_t len = eq ? (size_t)(eq - (a + 2)) : strlen(a + 2);
        if (len == 0 || len >= sizeof name)
            continue;
        memcpy(name, a + 2, len);
        name[len] = '\0';
        const gw_opt *o = gw_cli_find(opts, name);
        if (!o)
            continue;
        const char *val = "1";
        if (o->kind != GW_OPT_FLAG) {
            if (!eq && i + 1 >= argc)
                continue;
            val = eq ? eq + 1 : argv[++i];
        }
        if (!gw_param_find(t, name) || !gw_param_is_input(gw_param_find(t, name)))
            continue;
        int rc = gw_param_set(t, setup, name, val, err);
        if (rc != GW_OK)
            return gw_cli_study_error(t, cmd, rc, err);
    }
    return GW_OK;
}
