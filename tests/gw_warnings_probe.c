/*
 * gw_warnings_probe.c: a C caller of the library's study index (gw_study.h)
 * that prints the warnings of one run, for the test of issue 18's "one source
 * for each warning" (tests/python/test_warnings_one_source.py): the texts a C
 * caller gets (gw_study_warnings) are compared there with the program's stderr
 * and Python's GranwaveWarning for the same inputs.
 *
 *   gw_warnings_probe STUDY [NAME=VALUE ...]
 *
 * NAME is a row of the study's table (the program's flag without "--"). Prints
 * the warnings as the library gives them (one text per line; nothing when
 * none) and exits 0; a refused input or a failed run: its message on stderr,
 * exit 1; bad usage: exit 2.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_study.h"

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: gw_warnings_probe STUDY [NAME=VALUE ...]\n");
        return 2;
    }
    const gw_study *st = gw_study_find(argv[1]);
    if (!st) {
        fprintf(stderr, "gw_warnings_probe: no study '%s'\n", argv[1]);
        return 2;
    }
    void *setup = calloc(1, st->params_size), *out = calloc(1, st->fields_size);
    gw_err err = {{0}};
    int rc = setup && out ? st->init(setup) : GW_ENOMEM;
    for (int i = 2; rc == GW_OK && i < argc; i++) {
        char *eq = strchr(argv[i], '=');
        if (!eq) {
            fprintf(stderr, "gw_warnings_probe: '%s' is not NAME=VALUE\n", argv[i]);
            rc = GW_EINVAL;
            break;
        }
        *eq = '\0';
        rc = gw_param_set(st->params(), setup, argv[i], eq + 1, &err);
    }
    if (rc == GW_OK)
        rc = st->run(setup, out, NULL, NULL, &err);
    if (rc == GW_OK) {
        const char *w = gw_study_warnings(st, out);
        fputs(w ? w : "", stdout);
    } else if (err.msg[0]) {
        fprintf(stderr, "gw_warnings_probe %s: %s\n", argv[1], err.msg);
    }
    if (out)
        st->free_out(out);
    if (setup)
        st->clear(setup);
    free(out);
    free(setup);
    return rc == GW_OK ? 0 : 1;
}
