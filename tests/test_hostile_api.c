/*
 * test_hostile_api.c: the library's C interface used as a careless or hostile
 * caller would (docs/library.md "The contract of every call"): NULL for every
 * pointer argument of the entry points, zeroed and hand-filled structs, results
 * freed twice or never filled, studies run into a result struct that is reused,
 * progress callbacks that call the library again or stop it, and several
 * threads running the same studies at once.
 *
 * The rules checked: the library never crashes, prints or exits; a refused call
 * returns GW_EINVAL with one line in gw_err naming the call and the argument,
 * and writes nothing but the output a caller frees (a study's result, a plan),
 * which it empties whatever the refusal; free and clear calls take NULL and can
 * be repeated.
 * Every case runs in its own child process (a crash in one is reported as that
 * case's failure, not the end of the test), with a time limit.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "granwave.h"
#include "test_child.h"

static int nfail, ncases;

static void check(int ok, const char *what)
{
    ncases++;
    if (!ok) {
        nfail++;
        printf("FAIL: %s\n", what);
    }
}

/* Run body in a child (time limit 120 s, ASan builds are ~10x slower): it must
 * end by returning 0 (its own checks passed), never by a signal. What it
 * printed on stdout and stderr is captured: the library must print nothing, so
 * a child that wrote anything fails too (the children print only on failure). */

static void in_child(const char *label, case_fn body)
{
    int st = 0;
    char buf[2048];
    if (child_run(body, &st, buf, sizeof buf) != 0) {
        check(0, "a child for the case (mkstemp or fork)");
        return;
    }
    char what[3072];
    if (WIFSIGNALED(st))
        snprintf(what, sizeof what, "%s: killed by signal %d (%s)", label, WTERMSIG(st), buf);
    else if (WEXITSTATUS(st) != 0)
        snprintf(what, sizeof what, "%s: exit %d: %s", label, WEXITSTATUS(st), buf);
    else
        snprintf(what, sizeof what, "%s: printed \"%s\"", label, buf);
    check(WIFEXITED(st) && WEXITSTATUS(st) == 0 && buf[0] == '\0', what);
}

/* ---- every study through the index: NULL, zeroed, freed twice ---- */

static const gw_study *cur; /* the study of the case running */

static int study_null_init(void)
{
    EXPECT(cur->init(NULL) == GW_EINVAL);
    cur->clear(NULL);
    cur->free_out(NULL);
    return 0;
}

/* A NULL setup leaves out as every other refusal does: emptied (the state a
 * zeroed setup's refusal leaves, which free_out frees as nothing; until
 * session 46 the nine study runs left out as it was given, garbage and all,
 * while their other refusals emptied it, and a result reused after a NULL
 * setup still held the previous run's arrays). */
static int study_null_run(void)
{
    char *out = malloc(cur->fields_size), *ref = malloc(cur->fields_size), *p = calloc(1, cur->params_size);
    memset(out, 0x5a, cur->fields_size);
    memset(ref, 0x5a, cur->fields_size);
    gw_err e = {{0}};
    EXPECT(refused(cur->run(NULL, out, NULL, NULL, &e), &e, "setup is NULL"));
    EXPECT(cur->run(p, ref, NULL, NULL, NULL) == GW_EINVAL); /* p zeroed: refused by a row */
    EXPECT(memcmp(out, ref, cur->fields_size) == 0);    /* out emptied as by that refusal */
    cur->free_out(out);                                  /* and freed as nothing */
    memset(out, 0x5a, cur->fields_size);
    EXPECT(cur->run(NULL, out, NULL, NULL, NULL) == GW_EINVAL); /* err NULL alike */
    EXPECT(memcmp(out, ref, cur->fields_size) == 0);
    EXPECT(cur->init(p) == GW_OK);
    e.msg[0] = '\0';
    EXPECT(refused(cur->run(p, NULL, NULL, NULL, &e), &e, "out is NULL"));
    EXPECT(cur->run(NULL, NULL, NULL, NULL, NULL) == GW_EINVAL); /* err may be NULL */
    cur->clear(p);
    free(p);
    free(ref);
    free(out);
    return 0;
}

/* A zeroed setup (never initialised) is refused by name, with or without err;
 * its zeroed result and the setup can be freed and cleared twice. */
static int study_zeroed(void)
{
    void *p = calloc(1, cur->params_size), *o = calloc(1, cur->fields_size);
    gw_err e = {{0}};
    int rc = cur->run(p, o, NULL, NULL, &e);
    EXPECT(rc == GW_EINVAL && e.msg[0] && !strchr(e.msg, '\n'));
    cur->free_out(o);
    cur->free_out(o);
    EXPECT(cur->run(p, o, NULL, NULL, NULL) == GW_EINVAL);
    cur->free_out(o);
    cur->clear(p);
    cur->clear(p);
    void *z = calloc(1, cur->fields_size); /* a never-filled result frees as nothing */
    cur->free_out(z);
    free(z);
    free(p);
    free(o);
    return 0;
}

/* init, clear twice, init again (a cleared setup is reusable) */
static int study_reinit(void)
{
    void *p = calloc(1, cur->params_size);
    EXPECT(cur->init(p) == GW_OK);
    cur->clear(p);
    cur->clear(p);
    EXPECT(cur->init(p) == GW_OK);
    cur->clear(p);
    free(p);
    return 0;
}

/* ---- the parameter tables ---- */

static int param_nulls(void)
{
    const gw_param *t = gw_chain_setup_params();
    gw_chain_setup s;
    EXPECT(gw_chain_setup_init(&s) == GW_OK);
    gw_err e = {{0}};
    EXPECT(refused(gw_param_set(t, NULL, "n", "3", &e), &e, "obj is NULL"));
    EXPECT(refused(gw_param_set(NULL, &s, "n", "3", &e), &e, "gw_param_set: table is NULL"));
    EXPECT(refused(gw_param_set(t, &s, NULL, "3", &e), &e, "gw_param_set: name is NULL"));
    EXPECT(refused(gw_param_set(t, &s, "n", NULL, &e), &e, "n: no value"));
    EXPECT(gw_param_set(t, NULL, "n", "3", NULL) == GW_EINVAL);
    EXPECT(refused(gw_param_set_double(t, NULL, "vimp", 0.3, &e), &e, "obj is NULL"));
    EXPECT(refused(gw_param_set_value(gw_param_find(t, "n"), NULL, "3", &e), &e, "fieldp is NULL"));
    EXPECT(refused(gw_param_set_value(NULL, &s.n, "3", &e), &e, "gw_param_set_value: p is NULL"));
    EXPECT(refused(gw_param_check(t, NULL, &e), &e, "obj is NULL"));
    EXPECT(refused(gw_param_check(NULL, &s, &e), &e, "table is NULL"));
    EXPECT(refused(gw_param_init(t, NULL, &e), &e, "obj is NULL"));
    EXPECT(refused(gw_param_init(NULL, &s, &e), &e, "table is NULL"));
    EXPECT(refused(gw_param_copy(t, sizeof s, NULL, &s, &e), &e, "dst is NULL"));
    EXPECT(gw_param_json(t, NULL) == NULL);
    EXPECT(gw_param_find(NULL, "n") == NULL && gw_param_find(t, NULL) == NULL);
    EXPECT(gw_param_count(NULL) == 0 && gw_param_is_input(NULL) == 0);
    char buf[64];
    EXPECT(gw_param_format(NULL, &s, buf, sizeof buf) == -1);
    EXPECT(gw_param_format(gw_param_find(t, "n"), NULL, buf, sizeof buf) == -1);
    EXPECT(gw_param_format(gw_param_find(t, "n"), &s, NULL, 64) == -1);
    EXPECT(strcmp(gw_param_type_name((gw_param_type)99), "unknown") == 0);
    gw_param_clear(t, NULL);
    gw_param_clear(NULL, &s);
    /* the refused calls left s as it was: n is still the default */
    EXPECT(gw_param_format(gw_param_find(t, "n"), &s, buf, sizeof buf) == 1 && strcmp(buf, "1") == 0);
    gw_chain_setup_clear(&s);
    return 0;
}

/* A list filled by hand with a count but no values, or a negative count: the
 * check refuses it by name instead of reading through NULL. */
static int param_list_by_hand(void)
{
    gw_chain_setup s;
    EXPECT(gw_chain_setup_init(&s) == GW_OK);
    s.n = 3;
    s.radii.n = 3; /* v left NULL */
    gw_err e = {{0}};
    EXPECT(refused(gw_param_check(gw_chain_setup_params(), &s, &e), &e, "radii:"));
    gw_chain_collision c;
    EXPECT(refused(gw_chain_collision_run(&s, &c, &e), &e, "radii:"));
    gw_chain_collision_free(&c);
    s.radii.n = -2;
    EXPECT(refused(gw_chain_collision_run(&s, &c, &e), &e, "radii:"));
    gw_chain_collision_free(&c);
    gw_chain_setup copy;
    s.radii.n = 3;
    EXPECT(gw_param_copy(gw_chain_setup_params(), sizeof s, &copy, &s, &e) == GW_OK);
    EXPECT(copy.radii.v == NULL && copy.radii.n == 0);
    s.radii.n = 0;
    gw_chain_setup_clear(&copy);
    gw_chain_setup_clear(&s);
    return 0;
}

/* ---- messages and values: one line, every accepted value given again ---- */

/* msg is one line of UTF-8: no control character, every multi-byte character
 * whole (a message quotes the caller's value, and is cut at 511 bytes) */
static int one_line_utf8(const char *msg)
{
    const unsigned char *c = (const unsigned char *)msg;
    while (*c) {
        int want = *c < 0x80 ? 1 : *c >= 0xc2 && *c <= 0xdf ? 2 : *c >= 0xe0 && *c <= 0xef ? 3
                 : *c >= 0xf0 && *c <= 0xf4 ? 4 : 0;
        if (want == 0 || *c < 0x20 || *c == 0x7f)
            return 0;
        for (int k = 1; k < want; k++)
            if ((c[k] & 0xc0) != 0x80)
                return 0;
        c += want;
    }
    return 1;
}

/* Every input row of every study given a value with a newline, a carriage
 * return, a terminal escape or a Latin-1 byte: the refusal is one line that
 * names the row and shows the bytes escaped; a value far longer than a message
 * is cut between characters. (The message quoted the value as it was: two
 * lines for '1\n2', and "granwave chain --n" printed both.) */
static int messages_one_line(void)
{
    static const char *const values[] = {"1\n2", "0.3\r", "a\x1b[31mred", "st\xe9" "el", "\n"};
    char longv[1500];
    size_t o = 0;
    while (o + 3 < sizeof longv) { /* "é" (2 bytes) over and over, then a newline */
        longv[o++] = '\xc3';
        longv[o++] = '\xa9';
    }
    longv[o - 1] = '\n';
    longv[o] = '\0';
    int bad = 0, refusals = 0;
    for (int i = 0; i < gw_study_count(); i++) {
        const gw_study *st = gw_study_get(i);
        for (const gw_param *p = st->params(); p->name; p++) {
            if (p->type == GW_PARAM_TEXT) /* a text row takes any bytes (a path) */
                continue;
            for (size_t k = 0; k <= sizeof values / sizeof values[0]; k++) {
                const char *v = k < sizeof values / sizeof values[0] ? values[k] : longv;
                void *obj = calloc(1, st->params_size);
                EXPECT(st->init(obj) == GW_OK);
                gw_err e;
                memset(e.msg, 'Z', sizeof e.msg);
                int rc = gw_param_set(st->params(), obj, p->name, v, &e);
                size_t len = strlen(p->name);
                if (rc == GW_OK) {
                    printf("%s %s: accepted a value with a control character\n", st->name, p->name);
                    bad++;
                } else if (!memchr(e.msg, '\0', sizeof e.msg) || !one_line_utf8(e.msg) ||
                           strncmp(e.msg, p->name, len) != 0 || e.msg[len] != ':') {
                    if (bad++ < 5)
                        printf("%s %s: message not one line naming the row: '%s'\n", st->name, p->name, e.msg);
                } else
                    refusals++;
                if (rc != GW_OK && k == 0 && p->type == GW_PARAM_INT && !strstr(e.msg, "'1\\n2'")) {
                    printf("%s %s: the newline is not shown escaped: '%s'\n", st->name, p->name, e.msg);
                    bad++;
                }
                st->clear(obj);
                free(obj);
            }
        }
    }
    EXPECT(bad == 0 && refusals > 300);
    /* the same through the model's own parser and a sweep config given as text */
    gw_err e = {{0}};
    double d;
    EXPECT(gw_parse_double("0.3\n", "vimp", &d, &e) == GW_EINVAL && one_line_utf8(e.msg) && strstr(e.msg, "'0.3\\n'"));
    double *vals = NULL;
    long nc = 0;
    const gw_sweep_model *m = NULL;
    EXPECT(gw_sweep_run_text("[sweep]\nmodel = chain\n[grid]\nvimp = 0.1, 0.2\n[params]\nmaterial = st\xe9" "el\n", "mem", 1,
                             NULL, NULL, &vals, &nc, &m, &e) == GW_EINVAL);
    EXPECT(one_line_utf8(e.msg) && strstr(e.msg, "st\\xe9el"));
    gw_free(vals);
    return 0;
}

/* A subnormal double (5e-324, 1e-310) is refused as text ("too small in
 * magnitude"); through gw_param_set_double, or written into the struct and
 * checked, it was accepted, so a run took a value that the settings' text
 * (gw_param_format, gw_param_json: "4.9406564584124654e-324") could not give
 * again, nor a sweep config or Python. Now every number a row accepts as a double
 * sets back from its formatted text to the same value. */
static int doubles_given_again(void)
{
    static const double values[] = {5e-324, -5e-324, 1e-310, 2.2250738585072014e-308, 0.5, -0.0, 1e300, 3.0};
    int bad = 0, accepted = 0, subnormal_refused = 0;
    for (int i = 0; i < gw_study_count(); i++) {
        const gw_study *st = gw_study_get(i);
        const gw_param *t = st->params();
        for (const gw_param *p = t; p->name; p++) {
            if (p->type != GW_PARAM_DOUBLE && p->type != GW_PARAM_INT && p->type != GW_PARAM_LONG &&
                p->type != GW_PARAM_FLAG && p->type != GW_PARAM_COUNT)
                continue;
            for (size_t k = 0; k < sizeof values / sizeof values[0]; k++) {
                void *obj = calloc(1, st->params_size), *again = calloc(1, st->params_size);
                EXPECT(st->init(obj) == GW_OK && st->init(again) == GW_OK);
                gw_err e = {{0}};
                int subnormal = values[k] != 0 && fabs(values[k]) < 2.2250738585072014e-308;
                if (gw_param_set_double(t, obj, p->name, values[k], &e) == GW_OK) {
                    accepted++;
                    char text[64], text2[64];
                    EXPECT(gw_param_format(p, obj, text, sizeof text) >= 0);
                    if (subnormal || gw_param_set(t, again, p->name, text, &e) != GW_OK ||
                        gw_param_format(p, again, text2, sizeof text2) < 0 || strcmp(text, text2) != 0) {
                        if (bad++ < 5)
                            printf("%s %s: %g accepted as a double, its text '%s' does not set again: %s\n", st->name,
                                   p->name, values[k], text, e.msg);
                    }
                } else if (subnormal && strstr(e.msg, "too small in magnitude") && one_line_utf8(e.msg))
                    subnormal_refused++;
                st->clear(obj);
                st->clear(again);
                free(obj);
                free(again);
            }
        }
    }
    EXPECT(bad == 0 && accepted > 100 && subnormal_refused > 100);
    /* written by hand into the struct: gw_param_check and the run refuse it by name */
    gw_chain_setup s;
    EXPECT(gw_chain_setup_init(&s) == GW_OK);
    s.guide_friction = 5e-324;
    gw_err e = {{0}};
    EXPECT(refused(gw_param_check(gw_chain_setup_params(), &s, &e), &e, "guide-friction: 4.9406564584124654e-324 is too small"));
    gw_chain_collision c;
    EXPECT(refused(gw_chain_collision_run(&s, &c, &e), &e, "guide-friction:"));
    gw_chain_collision_free(&c);
    gw_chain_setup_clear(&s);
    gw_chain_drop_setup d; /* a list item: the drop's gaps, [0, 0.1] m */
    EXPECT(gw_chain_drop_setup_init(&d) == GW_OK);
    EXPECT(gw_param_set(gw_chain_drop_setup_params(), &d, "gap", "0,1e-3", &e) == GW_OK);
    d.gap.v[0] = 1e-320;
    EXPECT(refused(gw_param_check(gw_chain_drop_setup_params(), &d, &e), &e, "gap: item 1 is "));
    EXPECT(strstr(e.msg, "too small in magnitude"));
    gw_chain_drop_setup_clear(&d);
    return 0;
}

/* ---- the index, the sweep in memory, the model's own structs ---- */

static int index_nulls(void)
{
    EXPECT(gw_study_find(NULL) == NULL && gw_study_find("") == NULL && gw_study_find("chain ") == NULL);
    EXPECT(gw_study_get(-1) == NULL && gw_study_get(gw_study_count()) == NULL && gw_study_get(1 << 30) == NULL);
    EXPECT(gw_sweep_models(NULL) != NULL);
    gw_free(NULL);
    EXPECT(gw_strerror(12345) != NULL && gw_strerror(-12345) != NULL && gw_strerror(GW_EINVAL) != NULL);
    EXPECT(gw_err_set(NULL, GW_EIO, "%s", "nowhere") == GW_EIO);
    double *v = (double *)&v;
    long nc = 7;
    const gw_sweep_model *m = (const gw_sweep_model *)&m;
    gw_err e = {{0}};
    EXPECT(refused(gw_sweep_run_text(NULL, "x", 1, NULL, NULL, &v, &nc, &m, &e), &e, "text is NULL"));
    EXPECT(v == NULL && nc == 0 && m == NULL);
    EXPECT(refused(gw_sweep_run_text("[sweep]\n", "x", 1, NULL, NULL, NULL, &nc, &m, &e), &e, "values is NULL"));
    EXPECT(refused(gw_sweep_run_text("[sweep]\n", "x", 1, NULL, NULL, &v, NULL, &m, &e), &e, "ncases is NULL"));
    EXPECT(refused(gw_sweep_run_text("[sweep]\n", "x", 1, NULL, NULL, &v, &nc, NULL, &e), &e, "model is NULL"));
    /* the warned form: its warnings set to NULL on a refusal, none asked (NULL) taken */
    char *w = (char *)&w;
    EXPECT(refused(gw_sweep_run_text_warned(NULL, "x", 1, NULL, NULL, &v, &nc, &m, &w, &e), &e, "text is NULL"));
    EXPECT(w == NULL && v == NULL);
    EXPECT(refused(gw_sweep_run_text_warned("[sweep]\n", "x", 1, NULL, NULL, NULL, &nc, &m, NULL, &e), &e, "values is NULL"));
    return 0;
}

static int chain_model_nulls(void)
{
    gw_chain_params p = gw_chain_params_default();
    gw_chain_run_opts o = gw_chain_run_opts_default();
    gw_chain *c = (gw_chain *)&c;
    gw_err e = {{0}};
    EXPECT(refused(gw_chain_create(NULL, &c, &e), &e, "gw_chain_create: p is NULL"));
    EXPECT(c == NULL);
    EXPECT(refused(gw_chain_create(&p, NULL, &e), &e, "gw_chain_create: out is NULL"));
    EXPECT(gw_chain_create(&p, &c, NULL) == GW_OK);
    gw_chain_result r;
    EXPECT(refused(gw_chain_collide(NULL, &o, &r, &e), &e, "gw_chain_collide: c is NULL"));
    gw_chain_result_free(&r); /* zeroed by the refused call */
    EXPECT(refused(gw_chain_collide(c, NULL, &r, &e), &e, "gw_chain_collide: o is NULL"));
    gw_chain_result_free(&r);
    EXPECT(refused(gw_chain_collide(c, &o, NULL, &e), &e, "gw_chain_collide: r is NULL"));
    EXPECT(gw_chain_collide(c, &o, &r, NULL) == GW_OK);
    gw_chain_result_free(&r);
    gw_chain_result_free(&r);
    gw_chain_result_free(NULL);
    gw_chain_free(c);
    gw_chain_free(NULL);
    /* the sweep over N: NULL arrays, empty and reversed ranges */
    double v = 0.3;
    EXPECT(refused(gw_chain_sweep_n_progress(NULL, &o, &v, 1, 1, 2, 1, NULL, NULL, &r, &e), &e, "tmpl is NULL"));
    EXPECT(refused(gw_chain_sweep_n_progress(&p, &o, NULL, 1, 1, 2, 1, NULL, NULL, &r, &e), &e, "v is NULL"));
    EXPECT(refused(gw_chain_sweep_n_progress(&p, &o, &v, 1, 1, 1, 1, NULL, NULL, NULL, &e), &e, "res is NULL"));
    EXPECT(refused(gw_chain_sweep_n_progress(&p, &o, &v, 1, 3, 2, 1, NULL, NULL, &r, &e), &e, "n_lo"));
    EXPECT(refused(gw_chain_sweep_n_progress(&p, &o, &v, -1, 1, 2, 1, NULL, NULL, &r, &e), &e, "nv"));
    return 0;
}

/* the utilities, readers and writers of gw_common.h and the models' readers
 * and frees: NULL refused (GW_EINVAL naming it) or ignored, never followed */
static int utilities_nulls(void)
{
    gw_err e = {{0}};
    double d = 0, *v = NULL;
    int n = 0;
    EXPECT(refused(gw_parse_double("1", "x", NULL, &e), &e, "out is NULL"));
    EXPECT(refused(gw_parse_double(NULL, "x", &d, &e), &e, "x: expected a number"));
    EXPECT(refused(gw_parse_double_list("1,2", "x", NULL, &n, &e), &e, "out is NULL"));
    EXPECT(gw_str_trim(NULL) == NULL && gw_parse_flag(NULL) == -1);
    EXPECT(gw_fnv1a64(GW_FNV1A64_INIT, NULL, 10) == GW_FNV1A64_INIT);
    EXPECT(refused(gw_afile_open(NULL, "/tmp/x", &e), &e, "f is NULL"));
    gw_afile f;
    EXPECT(refused(gw_afile_open(&f, NULL, &e), &e, "path is NULL"));
    EXPECT(refused(gw_afile_commit(NULL, &e), &e, "f is NULL"));
    gw_afile_abort(NULL);
    gw_outset os;
    EXPECT(refused(gw_outset_begin(NULL, "/tmp", NULL, &e), &e, "s is NULL"));
    EXPECT(refused(gw_outset_begin(&os, NULL, NULL, &e), &e, "dir is NULL"));
    EXPECT(refused(gw_outset_commit(NULL, &e), &e, "s is NULL"));
    gw_outset_abort(NULL);
    EXPECT(refused(gw_input_read("/dev/null", "x", 10, NULL, NULL, &e), &e, "out is NULL"));
    EXPECT(refused(gw_write_text(NULL, "x", &e), &e, "path is NULL"));
    EXPECT(refused(gw_write_text("/tmp/gw_hostile_api_never", NULL, &e), &e, "text is NULL"));
    EXPECT(access("/tmp/gw_hostile_api_never", F_OK) != 0); /* nothing written */
    EXPECT(refused(gw_mkdir_p(NULL, &e), &e, "path is NULL"));
    gw_write_comment(NULL, "x");
    gw_path_parent(NULL);
    gw_linfit fit;
    double x[3] = {1, 2, 3};
    EXPECT(gw_fit_linear(NULL, x, 3, &fit) == GW_EINVAL && gw_fit_linear(x, x, 3, NULL) == GW_EINVAL);
    EXPECT(gw_fit_linear(x, x, -5, &fit) == GW_EINVAL);
    EXPECT(gw_json_doubles(NULL, 5) == NULL);
    gw_layer *L = (gw_layer *)&L;
    EXPECT(refused(gw_layer_create(NULL, 3, NULL, &L, &e), &e, "p is NULL") && L == NULL);
    EXPECT(refused(gw_layer_sample_read(NULL, NULL, &e), &e, "is NULL"));
    EXPECT(refused(gw_stats_table_read(NULL, NULL, &e), &e, "is NULL"));
    gw_sweep_config cfg;
    const gw_sweep_model *m = NULL;
    EXPECT(refused(gw_sweep_config_read_string(NULL, "x", NULL, 0, &cfg, &m, &e), &e, "text is NULL"));
    EXPECT(refused(gw_sweep_config_read(NULL, NULL, 0, NULL, NULL, &e), &e, "cfg is NULL"));
    gw_layer_free(NULL);
    gw_layer_sample_free(NULL);
    gw_layer_impact_result_free(NULL);
    gw_layer_impact_plan_free(NULL);
    gw_stats_table_free(NULL);
    gw_stats_analysis_free(NULL);
    gw_stats_groups_free(NULL);
    gw_stats_diagram_free(NULL);
    gw_sweep_config_free(NULL);
    gw_chain_trace_free(NULL);
    gw_chain_disp_result_free(NULL);
    gw_chain_drop_result_free(NULL);
    gw_chain_spectrum_free(NULL);
    gw_chain_resolved_free(NULL);
    gw_solver_free(NULL);
    gw_layer_law_free(NULL);
    (void)v;
    return 0;
}

static int case_ok(void *ctx, long k, gw_err *err)
{
    (void)ctx;
    (void)k;
    (void)err;
    return GW_OK;
}

static int stop_at_once(void *ctx, long done, long total)
{
    (void)done;
    (void)total;
    ++*(int *)ctx;
    return 1;
}

static int pool_hostile(void)
{
    gw_err e = {{0}};
    EXPECT(refused(gw_cases_run(3, 1, NULL, NULL, NULL, NULL, &e), &e, "fn is NULL"));
    EXPECT(gw_cases_run(0, 1, NULL, NULL, NULL, NULL, &e) == GW_OK);   /* nothing to run */
    EXPECT(gw_cases_run(-5, -7, case_ok, NULL, NULL, NULL, &e) == GW_OK);
    int calls = 0; /* a huge set stopped by its first progress call: returns at once */
    EXPECT(gw_cases_run(1L << 62, 2, case_ok, NULL, stop_at_once, &calls, &e) == GW_ECANCELED);
    EXPECT(calls == 1);
    EXPECT(gw_cases_run(10, -1000000, case_ok, NULL, NULL, NULL, &e) == GW_OK);
    EXPECT(gw_cases_run(10, 1 << 30, case_ok, NULL, NULL, NULL, NULL) == GW_OK);
    return 0;
}

/* ---- real runs: freed twice, reused, progress that re-enters or stops ---- */

static int set(const gw_study *s, void *p, const char *k, const char *v)
{
    gw_err e = {{0}};
    int rc = gw_param_set(s->params(), p, k, v, &e);
    if (rc != GW_OK)
        printf("%s %s=%s: %s\n", s->name, k, v, e.msg);
    return rc;
}

static double chain_fmax(int n)
{
    const gw_study *c = gw_study_find("chain");
    gw_chain_setup s;
    gw_chain_collision o;
    char nb[16];
    snprintf(nb, sizeof nb, "%d", n);
    double f = NAN;
    if (c->init(&s) == GW_OK && set(c, &s, "n", nb) == GW_OK && c->run(&s, &o, NULL, NULL, NULL) == GW_OK)
        f = o.r.f_max;
    c->free_out(&o);
    c->clear(&s);
    return f;
}

static int reentered;
static double reentered_fmax;

static int progress_reenters(void *ctx, long done, long total)
{
    (void)ctx;
    (void)done;
    (void)total;
    reentered++;
    reentered_fmax = chain_fmax(2);
    return 0;
}

static int runs_reused(void)
{
    const gw_study *f = gw_study_find("falcon");
    gw_chain_falcon_setup s;
    gw_chain_falcon_outcome o, o2;
    EXPECT(f->init(&s) == GW_OK);
    EXPECT(set(f, &s, "n", "1:3") == GW_OK && set(f, &s, "vimp", "0.3") == GW_OK &&
           set(f, &s, "heights", "none") == GW_OK);
    gw_err e = {{0}};
    EXPECT(f->run(&s, &o, progress_reenters, NULL, &e) == GW_OK);
    EXPECT(reentered == 3);                           /* once per column */
    EXPECT(reentered_fmax == chain_fmax(2));          /* the nested call's answer is the plain one */
    f->free_out(&o);
    f->free_out(&o);                                  /* freed twice */
    EXPECT(f->run(&s, &o, NULL, NULL, &e) == GW_OK);  /* the freed struct reused */
    EXPECT(f->run(&s, &o2, NULL, NULL, &e) == GW_OK);
    EXPECT(o.f_max_mean[0] == o2.f_max_mean[0]);      /* same answer both times */
    f->free_out(&o);
    f->free_out(&o2);
    int calls = 0;
    EXPECT(f->run(&s, &o, stop_at_once, &calls, &e) == GW_ECANCELED && calls == 1 && strstr(e.msg, "canceled"));
    f->free_out(&o);
    f->clear(&s);
    return 0;
}

/* ---- threads: the same studies at once give the answers of one at a time ---- */

static double serial_f[8];

static void *thread_run(void *arg)
{
    long k = (long)arg;
    double *f = malloc(sizeof *f);
    *f = chain_fmax(1 + (int)(k % 8));
    return f;
}

/* one gw_chain (const) shared by threads: each gw_chain_collide has its own solver */
static gw_chain *shared_chain;

static void *thread_collide(void *arg)
{
    (void)arg;
    gw_chain_run_opts o = gw_chain_run_opts_default();
    gw_chain_result r;
    double *f = malloc(sizeof *f);
    *f = gw_chain_collide(shared_chain, &o, &r, NULL) == GW_OK ? r.f_max : NAN;
    gw_chain_result_free(&r);
    return f;
}

static int threads_agree(void)
{
    for (int k = 0; k < 8; k++)
        serial_f[k] = chain_fmax(1 + k);
    enum { NT = 16 };
    pthread_t t[NT];
    for (long k = 0; k < NT; k++)
        EXPECT(pthread_create(&t[k], NULL, thread_run, (void *)k) == 0);
    int same = 1;
    for (long k = 0; k < NT; k++) {
        void *r = NULL;
        pthread_join(t[k], &r);
        same = same && r && *(double *)r == serial_f[k % 8] && serial_f[k % 8] > 0;
        free(r);
    }
    EXPECT(same);
    gw_chain_params p = gw_chain_params_default();
    p.n = 6;
    EXPECT(gw_chain_create(&p, &shared_chain, NULL) == GW_OK);
    double *alone = thread_collide(NULL);
    for (long k = 0; k < NT; k++)
        EXPECT(pthread_create(&t[k], NULL, thread_collide, NULL) == 0);
    for (long k = 0; k < NT; k++) {
        void *r = NULL;
        pthread_join(t[k], &r);
        same = same && r && *(double *)r == *alone && *alone > 0;
        free(r);
    }
    free(alone);
    gw_chain_free(shared_chain);
    EXPECT(same);
    return 0;
}

/* The readers empty their result on a NULL argument as on any other refusal
 * (here an empty file name): until session 46 gw_layer_sample_read,
 * gw_stats_table_read and gw_sweep_config_read(_string) left it as it was
 * given, and freeing it freed what its bytes pointed at. */
static int readers_null_empty(void)
{
    gw_err e = {{0}};
    gw_layer_sample s, sref;
    memset(&s, 0x5a, sizeof s);
    memset(&sref, 0x5a, sizeof sref);
    EXPECT(refused(gw_layer_sample_read(NULL, &s, &e), &e, "path is NULL"));
    EXPECT(gw_layer_sample_read("", &sref, NULL) != GW_OK);
    EXPECT(memcmp(&s, &sref, sizeof s) == 0);
    gw_layer_sample_free(&s);
    gw_stats_table t, tref;
    memset(&t, 0x5a, sizeof t);
    memset(&tref, 0x5a, sizeof tref);
    EXPECT(refused(gw_stats_table_read(NULL, &t, &e), &e, "path is NULL"));
    EXPECT(gw_stats_table_read("", &tref, NULL) != GW_OK);
    EXPECT(memcmp(&t, &tref, sizeof t) == 0);
    gw_stats_table_free(&t);
    int nm = 0;
    const gw_sweep_model *const *models = gw_sweep_models(&nm);
    gw_sweep_config c, cref; /* the empty config: what the reader zeroes first */
    const gw_sweep_model *m = (const gw_sweep_model *)&m;
    memset(&c, 0x5a, sizeof c);
    memset(&cref, 0, sizeof cref);
    EXPECT(refused(gw_sweep_config_read_string(NULL, "x", models, nm, &c, &m, &e), &e, "text is NULL"));
    EXPECT(memcmp(&c, &cref, sizeof c) == 0 && m == NULL);
    gw_sweep_config_free(&c);
    memset(&c, 0x5a, sizeof c);
    m = (const gw_sweep_model *)&m;
    EXPECT(refused(gw_sweep_config_read(NULL, models, nm, &c, &m, &e), &e, "path is NULL"));
    EXPECT(memcmp(&c, &cref, sizeof c) == 0 && m == NULL);
    gw_sweep_config_free(&c);
    return 0;
}

int main(void)
{
    static const struct {
        const char *name;
        case_fn fn;
    } per_study[] = {{"init/clear/free_out(NULL)", study_null_init},
                     {"run(NULL)", study_null_run},
                     {"zeroed setup and result", study_zeroed},
                     {"init, clear twice, init", study_reinit}};
    for (int i = 0; i < gw_study_count(); i++) {
        cur = gw_study_get(i);
        for (size_t k = 0; k < sizeof per_study / sizeof per_study[0]; k++) {
            char label[128];
            snprintf(label, sizeof label, "%s: %s", cur->name, per_study[k].name);
            in_child(label, per_study[k].fn);
        }
    }
    in_child("gw_param_* with NULL", param_nulls);
    in_child("a list filled by hand", param_list_by_hand);
    in_child("refusals are one line of UTF-8 naming the row", messages_one_line);
    in_child("every double a row accepts can be given again as text", doubles_given_again);
    in_child("the index and the sweep in memory with NULL", index_nulls);
    in_child("gw_chain_create/collide/sweep with NULL", chain_model_nulls);
    in_child("gw_cases_run hostile sizes", pool_hostile);
    in_child("utilities, readers and frees with NULL", utilities_nulls);
    in_child("readers empty their result on a NULL argument", readers_null_empty);
    in_child("runs freed twice, reused, re-entered, stopped", runs_reused);
    in_child("16 threads", threads_agree);
    printf("%d of %d checks failed\n", nfail, ncases);
    return nfail != 0;
}
