/*
 * gw_cli.h: the program's option parser (gw_cli.c): options described by
 * gw_opt tables, parsed from argv, with --help from the same table. Used by the
 * commands; not one of the library's public headers (not installed).
 */
#ifndef GW_CLI_H
#define GW_CLI_H

#include <stdio.h>

#include "gw_common.h"

/* ---- command-line options ---- */

typedef enum { GW_OPT_FLAG, GW_OPT_DOUBLE, GW_OPT_LONG, GW_OPT_STRING } gw_opt_kind;

typedef struct gw_opt {
    const char *name;    /* option "--name" */
    gw_opt_kind kind;
    void *dest;          /* int* (flag), double*, long*, const char** */
    const char *metavar; /* shown in --help, e.g. "N" */
    const char *help;    /* one line, with units and default */
    double lo, hi;       /* accepted range for numbers (inclusive) */
    int open_lo;         /* 1: value must be > lo */
    int seen;            /* set by the parser */
} gw_opt;

/* Parse argv[0..argc) against opts (terminated by name == NULL). Accepts
 * "--name value" and "--name=value"; "--help"/"-h" sets *help. Positional
 * arguments go to pos (at most maxpos; more is an error). Returns GW_EINVAL with
 * a message naming the option on unknown options, missing or bad values. */
int gw_cli_parse(const char *cmd, gw_opt *opts, int argc, char **argv, int *help,
                 const char **pos, int maxpos, int *npos, gw_err *err);
/* Print usage and every option's help. */
void gw_cli_help(FILE *fp, const char *cmd, const char *usage, const char *summary,
                 const gw_opt *opts);
/* The option named name, or NULL. */
const gw_opt *gw_cli_find(const gw_opt *opts, const char *name);

#endif
