/*
 * gw_cli_out.c: what the program adds to every output (gw_cli.h), built in one
 * place: the provenance header (version, command line, settings as one-line
 * JSON) that heads each table, trace and HDF5 "run" attribute, and the progress
 * lines on stderr of the long commands (falcon, wavespeed, sweep). The library
 * never prints: it gets the header as a string and reports progress through a
 * gw_progress_fn, which is gw_cli_progress_report here.
 *
 * Progress: after d of n units at t seconds elapsed, rate = d / t units/s and
 * the time left is (n - d) / rate seconds.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gw_cli.h"
#include "gw_io_impl.h"

/* arg as a POSIX shell reads it back: as it is when it holds only characters
 * no shell treats specially, else in single quotes ('\'' for a quote), and in
 * $'...' (\n, \t, \xHH) when it holds a control character such as a newline
 * or a byte that is not UTF-8 (a Latin-1 file name), so that the command line
 * stays one header line of UTF-8 text, in the JSON too, and can be run again
 * as written (before, "--out a b" read as two arguments, a newline in a path
 * split the line and a byte 0xff made the JSON invalid). Writes at most 4
 * bytes per byte of arg plus 4; returns the bytes written. */
static size_t shell_word(char *out, const char *arg)
{
    static const char safe[] = "_@%+=:,./-";
    int plain = *arg != '\0', ctrl = 0;
    for (size_t i = 0, k; arg[i]; i += k ? k : 1) {
        const unsigned char c = (unsigned char)arg[i];
        k = gw_utf8_len(arg + i);
        if (c < 0x20 || c == 0x7f || k == 0)
            ctrl = 1;
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || strchr(safe, c)))
            plain = 0;
    }
    char *w = out;
    if (plain) {
        size_t n = strlen(arg);
        memcpy(w, arg, n);
        return n;
    }
    if (ctrl)
        *w++ = '$';
    *w++ = '\'';
    for (size_t i = 0, k; arg[i]; i += k ? k : 1) {
        const unsigned char c = (unsigned char)arg[i];
        k = gw_utf8_len(arg + i);
        if (c == '\'' && !ctrl) {
            memcpy(w, "'\\''", 4);
            w += 4;
        } else if (ctrl && (c == '\'' || c == '\\')) {
            *w++ = '\\';
            *w++ = (char)c;
        } else if (ctrl && c == '\n') {
            *w++ = '\\', *w++ = 'n';
        } else if (ctrl && c == '\t') {
            *w++ = '\\', *w++ = 't';
        } else if (ctrl && (c < 0x20 || c == 0x7f || k == 0)) {
            static const char hex[] = "0123456789abcdef";
            *w++ = '\\', *w++ = 'x', *w++ = hex[c >> 4], *w++ = hex[c & 15];
        } else {
            memcpy(w, arg + i, k); /* a character, whole */
            w += k;
        }
    }
    *w++ = '\'';
    return (size_t)(w - out);
}

char *gw_cli_command_line(const char *cmd, int argc, char **argv)
{
    size_t len = 16 + strlen(cmd);
    for (int i = 0; i < argc; i++)
        len += 4 * strlen(argv[i]) + 5;
    char *h = malloc(len);
    if (!h)
        return NULL;
    size_t w = (size_t)snprintf(h, len, "granwave %s", cmd);
    for (int i = 0; i < argc; i++) {
        h[w++] = ' ';
        w += shell_word(h + w, argv[i]);
    }
    h[w] = '\0';
    return h;
}

char *gw_cli_provenance_add(char *hdr, const char *key, const cJSON *value)
{
    if (!hdr)
        return NULL;
    if (!value && !gw_json_failures())
        return hdr; /* nothing to add */
    /* a value cJSON could not build (NULL, or an object short of a member):
     * out of memory, never a header that leaves the settings out */
    char *js = value ? gw_json_string(value, 0) : NULL;
    char *out = NULL;
    if (js) {
        size_t len = strlen(hdr) + strlen(key) + strlen(js) + 4;
        if ((out = malloc(len)))
            snprintf(out, len, "%s\n%s: %s", hdr, key, js);
    }
    cJSON_free(js);
    free(hdr);
    return out;
}

char *gw_cli_provenance(const char *cmd, int argc, char **argv, const cJSON *settings)
{
    char *line = gw_cli_command_line(cmd, argc, argv);
    if (!line)
        return NULL;
    const char *v = gw_version();
    size_t len = strlen(v) + strlen(line) + 32;
    char *h = malloc(len);
    if (h)
        snprintf(h, len, "granwave %s\ncommand: %s", v, line);
    free(line);
    return gw_cli_provenance_add(h, "settings", settings);
}

const char *gw_cli_num(char *buf, size_t n, const char *fmt, double v)
{
    if (!isfinite(v))
        snprintf(buf, n, "%s", GW_CLI_NA);
    else
        snprintf(buf, n, fmt, v);
    return buf;
}

char *gw_cli_one_line(char *text, char sep)
{
    for (char *p = text; p && *p; p++)
        if (*p == '\n')
            *p = sep;
    return text;
}

/* ---- progress ---- */

/* GW_PROGRESS_MS as read by gw_cli_progress_env (< 0: unset, the commands' own
 * delays and periods) */
static double progress_env_ms = -1.0;

int gw_cli_progress_env(void)
{
    const char *v = getenv(GW_CLI_PROGRESS_ENV);
    if (!v)
        return 0;
    char *end = NULL;
    errno = 0;
    const double ms = strtod(v, &end);
    /* a plain decimal number: no "inf", "nan" or hexadecimal, no blank around it */
    const int plain = v[0] != '\0' && strspn(v, "0123456789.eE+-") == strlen(v);
    if (!plain || end == v || *end != '\0' || errno == ERANGE || !isfinite(ms) || ms < 0) {
        fprintf(stderr, "granwave: %s '%s' is not a delay in milliseconds (a number, 0 or more: 0 prints at once, "
                        "a large value never)\n", GW_CLI_PROGRESS_ENV, v);
        return -1;
    }
    progress_env_ms = ms;
    return 0;
}

double gw_cli_progress_ms(double ms) { return progress_env_ms >= 0 ? progress_env_ms : ms; }

void gw_cli_progress_init(gw_cli_progress *p, const char *prefix, const char *unit, double every_ms)
{
    memset(p, 0, sizeof *p);
    p->prefix = prefix;
    p->unit = unit;
    p->before = -1;
    p->every_ms = gw_cli_progress_ms(every_ms);
    p->fp = stderr;
    p->t0 = p->last = gw_clock_ms();
}

int gw_cli_progress_report(void *ctx, long done, long total)
{
    gw_cli_progress *p = ctx;
    if (!p || p->quiet || done <= 0)
        return 0;
    double now = gw_clock_ms();
    if (p->after_ms > 0 && now - p->t0 < p->after_ms)
        return 0;
    int due = done >= total || (p->every_ms > 0 ? now - p->last >= p->every_ms : done % (total / 10 + 1) == 0);
    if (!due)
        return 0;
    if (p->header) {
        fprintf(p->fp, "%s\n", p->header);
        p->header = NULL;
    }
    double el = (now - p->t0) / 1e3;
    double rate = el > 0 ? done / el : 0;
    fprintf(p->fp, "%s%ld/%ld %s", p->prefix, done, total, p->unit);
    if (p->before >= 0)
        fprintf(p->fp, " (%ld done before)", p->before);
    fprintf(p->fp, ", %.2f %s/s, %.1f s elapsed, ~%.1f s left\n", rate, p->unit, el,
            el / (double)done * (double)(total - done));
    p->last = now;
    return 0;
}

double gw_cli_progress_gap(const gw_cli_progress *p, double el_ms)
{
    return fmin(fmax(p->every_ms, el_ms / 20.0), fmax(p->every_ms, GW_CLI_PROGRESS_GAP_MAX_MS));
}

void gw_cli_progress_part(gw_cli_progress *p, long done, long total, double part, int last)
{
    if (!p || p->quiet || total <= 0)
        return;
    const double now = gw_clock_ms(), el_ms = now - p->t0;
    if (!last && now - p->last < gw_cli_progress_gap(p, el_ms))
        return;
    char line[512];
    int len = 0;
    if (p->header) /* one write with the line below: a thread's output never falls between them */
        len = snprintf(line, sizeof line, "%s\n", p->header);
    const double el = el_ms / 1e3;
    part = last ? 1.0 : fmin(fmax(part, 0.0), 1.0);
    /* no time left before any work is measured: a study's first line can come
     * while it builds its walls and calibrations, before its first collision
     * (softwall --sheets --sheet-law layer --restitution 0.5: "0/47 collisions,
     * 0.0% of the work, 2.2 s elapsed, ~0.0 s left", the end announced before
     * the start); the line then ends at the time elapsed, as a sweep's does */
    if (len >= 0 && (size_t)len < sizeof line)
        len += snprintf(line + len, sizeof line - (size_t)len, "%s%ld/%ld %s, %.1f%% of the work, %.1f s elapsed",
                        p->prefix, done, total, p->unit, 100.0 * part, el);
    if (len >= 0 && (size_t)len < sizeof line)
        snprintf(line + len, sizeof line - (size_t)len, part > 0 ? ", ~%.1f s left\n" : "\n",
                 part > 0 ? el / part * (1.0 - part) : 0.0);
    /* one fputs of the whole line: stderr is unbuffered, and a line written in
     * pieces could take another writer's text between them */
    fputs(line, p->fp);
    fflush(p->fp);
    p->header = NULL;
    p->last = now;
}

void gw_cli_progress_watch(void *ctx, long done, long total, double part)
{
    gw_cli_progress_part(ctx, done, total, part, 0);
}

const char *gw_cli_time_unit(double t, double *scale)
{
    *scale = t >= 1.0 ? 1.0 : t >= 1e-3 ? 1e3 : 1e6;
    return t >= 1.0 ? "s" : t >= 1e-3 ? "ms" : "us";
}

const double gw_cli_column_starts[GW_CLI_COLUMN_PHASES] = {0.0, 0.5, 0.65, 0.8, 1.05, 1.15};

void gw_cli_column_init(gw_cli_column *c, int n, int restarts)
{
    memset(c, 0, sizeof *c);
    c->n = n;
    c->restarts = restarts;
    for (int i = 0; i < GW_CLI_COLUMN_PHASES; i++)
        c->el0[i] = c->x0[i] = -1.0;
    c->el_free = c->x_free = -1.0;
}

void gw_cli_column_note(gw_cli_column *c, double el, double x)
{
    if (!c || !(el >= 0) || !(x >= 0))
        return;
    for (int i = 0; i < GW_CLI_COLUMN_PHASES && x >= gw_cli_column_starts[i]; i++)
        if (c->el0[i] < 0) {
            c->el0[i] = el;
            c->x0[i] = x;
        }
    if (c->t_end > 0 && c->el_free < 0) {
        c->el_free = el;
        c->x_free = x;
    }
}

/* Phase i's pace relative to the first half's (gw_cli.h) */
static double column_weight(const gw_cli_column *c, int i)
{
    if (!c->restarts)
        return 1.0;
    static const double w[GW_CLI_COLUMN_PHASES] = {1.0, 0.0, 0.0, 0.57, 0.82, 0.06};
    const double r = fmax(1.0, c->n / 200.0);
    return i == 1 ? 3.2 * sqrt(r) : i == 2 ? 1.1 * pow(r, 0.6) : w[i];
}

double gw_cli_column_left(const gw_cli_column *c, double el, double x, double x_end)
{
    if (!c || !(el > 0) || !(x > 0))
        return NAN;
    if (!(x_end > x))
        return 0.0;
    int cur = 0;
    while (cur + 1 < GW_CLI_COLUMN_PHASES && x >= gw_cli_column_starts[cur + 1])
        cur++;
    /* the first half's pace, s per unit of x: measured over it (or so far) */
    const double base = cur == 0 || c->el0[1] < 0 ? el / x : c->el0[1] / fmax(c->x0[1], gw_cli_column_starts[1]);
    double left = 0;
    for (int i = cur; i < GW_CLI_COLUMN_PHASES; i++) {
        const double a = i == cur ? x : gw_cli_column_starts[i],
                     b = i + 1 < GW_CLI_COLUMN_PHASES ? fmin(x_end, gw_cli_column_starts[i + 1]) : x_end;
        if (b <= a)
            break;
        double pace = base * column_weight(c, i);
        /* the free flight's own pace, once it has run 0.05 of x (its cost
         * is the solver's: cvode's long steps, rk4's fixed ones) */
        if (i == GW_CLI_COLUMN_PHASES - 1 && c->el_free >= 0 && x - c->x_free >= 0.05 && el > c->el_free)
            pace = (el - c->el_free) / (x - c->x_free);
        left += (b - a) * pace;
    }
    return left;
}

void gw_cli_progress_time(gw_cli_progress *p, gw_cli_column *col, double t, double t_expect, double t_max, int last)
{
    if (!p || p->quiet || !(t_expect > 0))
        return;
    const double now = gw_clock_ms(), el_ms = now - p->t0;
    if (col && !last)
        gw_cli_column_note(col, el_ms / 1e3, t / t_expect);
    if (p->after_ms > 0 && el_ms < p->after_ms)
        return;
    if (!last && now - p->last < gw_cli_progress_gap(p, el_ms))
        return;
    if (p->header) {
        fprintf(p->fp, "%s\n", p->header);
        p->header = NULL;
    }
    double sc;
    const char *u = gw_cli_time_unit(t_expect, &sc);
    const double el = el_ms / 1e3, frac = t / t_expect;
    fprintf(p->fp, "%st = %.4g %s of ~%.4g %s expected (%.1f%%", p->prefix, t * sc, u, t_expect * sc, u, 100.0 * frac);
    if (last)
        fprintf(p->fp, "): ended, %.1f s elapsed\n", el);
    else if (t <= 0) /* no pace yet: no time left (it said ~0.0 s) */
        fprintf(p->fp, "), %.1f s elapsed\n", el);
    else if (col && col->t_end > 0) { /* the column's state says its end */
        fprintf(p->fp, "), %.1f s elapsed, ~%.1f s left", el,
                gw_cli_column_left(col, el, frac, fmin(col->t_end, t_max) / t_expect));
        if (col->t_meet > t)
            fprintf(p->fp, " (the last closing pair meets at about %.4g %s)\n", col->t_meet * sc, u);
        else
            fputs(" (every contact open or opening)\n", p->fp);
    } else if (col && frac < GW_CLI_COLUMN_END_GUESS) /* the phases' paces, to a guessed end */
        fprintf(p->fp, "), %.1f s elapsed, ~%.1f s left or more\n", el,
                gw_cli_column_left(col, el, frac, fmin(GW_CLI_COLUMN_END_GUESS * t_expect, t_max) / t_expect));
    else if (t < t_expect) /* at the pace so far */
        fprintf(p->fp, "), %.1f s elapsed, ~%.1f s left\n", el, el / t * (t_expect - t));
    else /* the end comes when every contact has opened: at the latest at t_max */
        fprintf(p->fp, ", t-max %.4g %s), %.1f s elapsed, at most ~%.1f s left\n", t_max * sc, u, el,
                el / t * fmax(t_max - t, 0.0));
    fflush(p->fp);
    p->last = now;
}

/* Remove the empty directories from path up to made (what this run created). */
void gw_cli_unmake(const char *path, const char *made) { gw_temps_unmake(path, made); }

/* What it made is also handed to the signal handler's table: a run ended by
 * SIGINT, SIGTERM or SIGHUP takes it back (if still empty) with its
 * temporaries; before, it stayed, empty (layer-impact --out NEW). */
int gw_cli_mkdir_out(const char *path, char *made, size_t n, gw_err *err)
{
    return gw_mkdir_made(path, made, n, err);
}

int gw_cli_outset_begin(gw_outset *s, const char *dir, const char *const *names, char *made, size_t n,
                        gw_err *err)
{
    memset(s, 0, sizeof *s);
    int rc = gw_mkdir_made(dir, made, n, err);
    if (rc == GW_OK && (rc = gw_outset_begin(s, dir, names, err)) != GW_OK && made[0])
        gw_cli_unmake(dir, made);
    if (rc != GW_OK)
        made[0] = '\0';
    return rc;
}

void gw_cli_outset_end(gw_outset *s, const char *dir, const char *made, int placed)
{
    gw_outset_abort(s); /* nothing after a commit: the set is closed */
    if (dir && made && made[0]) {
        if (placed)
            gw_temps_drop(dir); /* it holds this run's files now: no signal takes it */
        else
            gw_cli_unmake(dir, made);
    }
}
