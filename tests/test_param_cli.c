/*
 * test_param_cli.c: a command-line option built from a parameter-table row
 * (gw_cli_opt_param) accepts and refuses exactly what the library's
 * gw_param_set accepts and refuses, for every number and choice row of every
 * study (gw_study.h: chain, falcon, layer-impact, layer-make), so a command and
 * the library check each parameter by one rule.
 *
 * For each row, values at and around its range: each closed end, the number
 * just outside each end (an open end itself; a closed end moved by 1e-9 of its
 * size, or of 1; an integer end by 1), the middle, nan, inf, junk, an empty
 * value, a fractional value for an integer or count row (and a count's
 * whole minimum written as a real, "1.0"). Asserted: the parser's verdict
 * equals gw_param_set's; an accepted value is stored bit-equal in both; a
 * refusal names "CMD --NAME" on the command line and "NAME" in the library,
 * with the same reason after it. Choice rows: every choice accepted, a
 * misspelt one refused, by both. The row's default is what gw_param_init
 * gives (bit-equal).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_cli.h"
#include "gw_study.h"
#include "gw_test.h"

static int nchecks;

static void one(const gw_study *s, const gw_param *p, const char *value)
{
    void *obj = calloc(1, s->params_size);
    s->init(obj);
    union { double d; long l; const char *c; } dest;
    gw_opt o[2];
    char what[1400];
    snprintf(what, sizeof what, "%s %s '%s'", s->name, p->name, value);
    gw_test_true(gw_cli_opt_param(p, &dest, &o[0], NULL) == GW_OK, what);
    o[1] = (gw_opt){0};
    char flag[96];
    snprintf(flag, sizeof flag, "--%s", p->name);
    char *argv[2] = {flag, (char *)value};
    int help = 0, npos = 0;
    const char *pos[1];
    gw_err ec = {{0}}, el = {{0}};
    int rc_cli = gw_cli_parse("cmd", o, 2, argv, &help, pos, 0, &npos, &ec);
    int rc_lib = gw_param_set(s->params(), obj, p->name, value, &el);
    snprintf(what, sizeof what, "%s %s '%s': command line %d (%s), library %d (%s)", s->name, p->name, value,
             rc_cli, ec.msg, rc_lib, el.msg);
    gw_test_true(rc_cli == rc_lib, what);
    if (rc_cli == GW_OK && rc_lib == GW_OK) {
        const char *f = (const char *)obj + p->offset;
        if (p->type == GW_PARAM_DOUBLE || p->type == GW_PARAM_COUNT)
            gw_test_true(memcmp(f, &dest.d, sizeof(double)) == 0, what);
        else if (p->type == GW_PARAM_LONG)
            gw_test_true(*(const long *)f == dest.l, what);
        else if (p->type == GW_PARAM_CHOICE)
            gw_test_true(dest.c == value, what);
    } else if (rc_cli != GW_OK && rc_lib != GW_OK) {
        char head[128];
        snprintf(head, sizeof head, "cmd --%s: ", p->name);
        size_t n = strlen(p->name);
        gw_test_true(strncmp(ec.msg, head, strlen(head)) == 0 && strncmp(el.msg, p->name, n) == 0 &&
                         el.msg[n] == ':' && strcmp(ec.msg + strlen(head), el.msg + n + 2) == 0,
                     what);
    }
    gw_param_clear(s->params(), obj);
    free(obj);
    nchecks++;
}

/* the number just outside end (dir -1: below the minimum, +1: above the maximum) */
static int outside(const gw_param *p, double end, int open, int dir, char *buf, size_t n)
{
    int integer = p->type == GW_PARAM_LONG || p->type == GW_PARAM_COUNT;
    if (!isfinite(end) || (integer && fabs(end) >= 9e18))
        return 0;
    double v = integer ? (open ? end : (dir < 0 ? ceil(end) - 1 : floor(end) + 1))
                       : (open ? end : end + dir * 1e-9 * fmax(fabs(end), 1));
    snprintf(buf, n, integer ? "%.0f" : "%.17g", v);
    return 1;
}

int main(void)
{
    for (int i = 0; i < gw_study_count(); i++) {
        const gw_study *s = gw_study_get(i);
        const gw_param *t = s->params();
        for (int k = 0; t[k].name; k++) {
            const gw_param *p = &t[k];
            char b[64];
            if (p->type == GW_PARAM_DOUBLE || p->type == GW_PARAM_LONG || p->type == GW_PARAM_COUNT) {
                const int real = p->type != GW_PARAM_LONG; /* a count is held as a double */
                /* the option's default is the table's (gw_param_init) */
                void *obj = calloc(1, s->params_size);
                s->init(obj);
                double dd;
                long dl;
                gw_opt o;
                gw_cli_opt_param(p, real ? (void *)&dd : (void *)&dl, &o, NULL);
                const char *f = (const char *)obj + p->offset;
                gw_test_true(real ? memcmp(f, &dd, sizeof dd) == 0 || (isnan(dd) && isnan(*(const double *)f))
                                                        : *(const long *)f == dl,
                             p->name);
                gw_param_clear(t, obj);
                free(obj);
                const char *fixed[] = {"nan", "inf", "-inf", "junk", "", "1e5000", "0x10"};
                for (size_t j = 0; j < sizeof fixed / sizeof fixed[0]; j++)
                    one(s, p, fixed[j]);
                if (outside(p, p->min, p->open_min, -1, b, sizeof b))
                    one(s, p, b);
                if (outside(p, p->max, p->open_max, +1, b, sizeof b))
                    one(s, p, b);
                if (isfinite(p->min) && !p->open_min) {
                    snprintf(b, sizeof b, p->type != GW_PARAM_DOUBLE ? "%.0f" : "%.17g", p->min);
                    one(s, p, b);
                }
                if (isfinite(p->max) && !p->open_max && fabs(p->max) < 9e18) {
                    snprintf(b, sizeof b, p->type != GW_PARAM_DOUBLE ? "%.0f" : "%.17g", p->max);
                    one(s, p, b);
                }
                if (isfinite(p->min) && isfinite(p->max)) {
                    snprintf(b, sizeof b, "%.17g", 0.5 * (p->min + p->max));
                    one(s, p, b);
                }
                if (p->type == GW_PARAM_LONG || p->type == GW_PARAM_COUNT)
                    one(s, p, "1.5");
                if (p->type == GW_PARAM_COUNT && isfinite(p->min)) { /* a whole number written as a real */
                    snprintf(b, sizeof b, "%.1f", ceil(p->min));
                    one(s, p, b);
                }
            } else if (p->type == GW_PARAM_CHOICE) {
                char list[512];
                snprintf(list, sizeof list, "%s", p->choices);
                for (char *c = strtok(list, ","); c; c = strtok(NULL, ","))
                    one(s, p, c);
                one(s, p, "no-such-choice");
            }
        }
    }
    printf("%d values checked on the command line and in the library\n", nchecks);
    gw_test_true(nchecks > 300, "every study's rows were tried");
    return gw_test_summary("test_param_cli");
}
