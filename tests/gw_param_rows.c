/*
 * gw_param_rows.c: prints the input rows of every study's parameter table
 * (gw_study.h), one per line, for the CLI property test
 * (test_cli_property.sh), which tries each number row of a command's table
 * from the table itself rather than from a hand list:
 *
 *   STUDY NAME TYPE MIN MAX OPEN_MIN OPEN_MAX BELOW ABOVE DEFAULT OR_ZERO INSIDE_MIN INSIDE_MAX
 *
 * TYPE is the row's type (double, long, int, flag, choice, text, list, range,
 * count: a whole number held as a double, its ends moved as an integer's);
 * MIN and MAX its accepted numbers (inf for none); BELOW and ABOVE the nearest
 * numbers just outside the range that a command must refuse ("-" when the side
 * is unbounded): an open end itself, a closed end moved by 1e-9 of its size
 * (or of 1), an integer end moved by 1. DEFAULT is the row's default text or
 * "-". OR_ZERO is 1 for a row that takes 0 besides [MIN, MAX] (gw_param.or_zero).
 * INSIDE_MIN and INSIDE_MAX are the numbers just inside each end that a
 * command must take by the row's range (it may still refuse them by a rule
 * over other settings, never as out of range): an end moved inward by 1e-9 of
 * its size, or by 1e-300 from 0 (so a row (0, 1] whose model refuses
 * (0, 1e-9) is caught), an integer open end by 1; "-" when unbounded.
 * Numbers with 17 significant digits (units: the row's, SI).
 * Usage: gw_param_rows [STUDY]
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gw_study.h"

static void outside(const gw_param *p, double end, int open, int dir, char *buf, size_t n)
{
    int integer = p->type == GW_PARAM_INT || p->type == GW_PARAM_LONG || p->type == GW_PARAM_RANGE ||
                  p->type == GW_PARAM_COUNT;
    if (!isfinite(end) || (integer && fabs(end) >= 9e18)) {
        snprintf(buf, n, "-");
        return;
    }
    double v;
    if (integer)
        v = open ? end : (dir < 0 ? ceil(end) - 1 : floor(end) + 1);
    else
        v = open ? end : end + dir * 1e-9 * fmax(fabs(end), 1);
    snprintf(buf, n, integer ? "%.0f" : "%.17g", v);
}

static void inside(const gw_param *p, double end, int open, int dir, char *buf, size_t n)
{
    int integer = p->type == GW_PARAM_INT || p->type == GW_PARAM_LONG || p->type == GW_PARAM_RANGE ||
                  p->type == GW_PARAM_COUNT;
    if (!isfinite(end) || (integer && fabs(end) >= 9e18)) {
        snprintf(buf, n, "-");
        return;
    }
    double v = integer ? end - dir * open : end - dir * fmax(fabs(end) * 1e-9, 1e-300);
    snprintf(buf, n, integer ? "%.0f" : "%.17g", v);
}

int main(int argc, char **argv)
{
    for (int i = 0; i < gw_study_count(); i++) {
        const gw_study *s = gw_study_get(i);
        if (argc > 1 && strcmp(argv[1], s->name) != 0)
            continue;
        const gw_param *t = s->params();
        for (int k = 0; t[k].name; k++) {
            const gw_param *p = &t[k];
            if (!gw_param_is_input(p))
                continue;
            char lo[40], hi[40], ilo[40], ihi[40];
            outside(p, p->min, p->open_min, -1, lo, sizeof lo);
            outside(p, p->max, p->open_max, +1, hi, sizeof hi);
            inside(p, p->min, p->open_min, -1, ilo, sizeof ilo);
            inside(p, p->max, p->open_max, +1, ihi, sizeof ihi);
            int number = p->type == GW_PARAM_DOUBLE || p->type == GW_PARAM_INT || p->type == GW_PARAM_LONG ||
                         p->type == GW_PARAM_COUNT ||
                         p->type == GW_PARAM_LIST || p->type == GW_PARAM_RANGE;
            printf("%s %s %s %.17g %.17g %d %d %s %s %s %d %s %s\n", s->name, p->name,
                   gw_param_type_name(p->type),
                   number ? p->min : 0, number ? p->max : 0, p->open_min, p->open_max, number ? lo : "-",
                   number ? hi : "-", p->def && *p->def ? p->def : "-", p->or_zero, number ? ilo : "-",
                   number ? ihi : "-");
        }
    }
    return 0;
}
