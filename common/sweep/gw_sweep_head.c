/*
 * gw_sweep_head.c: a sweep journal's head, which says what made it: the line
 * "# granwave sweep journal HASH, format N" (the config's hash, the journal
 * format), the "# build" line (gw_sweep_build.c), the "# input" lines (the files' content hashes), the "# grid" and
 * "# param" lines (the config's keys as spelt). A journal found in an output
 * directory is of another format, or another config, and then the key, the
 * file or the format that differs is named. No units.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_sweep.h"
#include "gw_locale.h"
#include "gw_number_impl.h"
#include "gw_sweep_impl.h"

/* "# input KEY = VALUE fnv1a64 HEX" lines of cfg, then its "# grid KEY = v1,
 * v2, ..." lines (the values as the config gives them, ranges listed) and
 * "# param KEY = VALUE" lines in the config's order, into a new string. A
 * journal held the config's hash alone: a rerun after a small edit that makes
 * another sweep (0.1 spelt 1e-1, two [params] lines swapped) was refused as
 * "another sweep (different config)", naming nothing the user could find. */
char *gw_sweep_head_lines(const gw_sweep_config *cfg)
{
    size_t n = 1;
    for (int i = 0; i < cfg->ninputs; i++)
        n += strlen(cfg->inputs[i].key) + strlen(cfg->inputs[i].value) + 48;
    for (int i = 0; i < cfg->ngrid; i++) {
        n += strlen(cfg->grid[i].name) + 12;
        for (int j = 0; j < cfg->grid[i].nvalues; j++)
            n += strlen(cfg->grid[i].values[j]) + 2;
    }
    for (int i = 0; i < cfg->nparams; i++)
        n += strlen(cfg->params[i].name) + strlen(cfg->params[i].values[0]) + 14;
    char *s = malloc(n), *p = s;
    if (!s)
        return NULL;
    *p = '\0';
    for (int i = 0; i < cfg->ninputs; i++)
        p += gw_snprintf(p, n - (size_t)(p - s), "# input %s = %s fnv1a64 %016llx\n", cfg->inputs[i].key,
                      cfg->inputs[i].value, cfg->inputs[i].hash);
    for (int i = 0; i < cfg->ngrid; i++) {
        p += gw_snprintf(p, n - (size_t)(p - s), "# grid %s = ", cfg->grid[i].name);
        for (int j = 0; j < cfg->grid[i].nvalues; j++)
            p += gw_snprintf(p, n - (size_t)(p - s), "%s%s", j ? ", " : "", cfg->grid[i].values[j]);
        p += gw_snprintf(p, n - (size_t)(p - s), "\n");
    }
    for (int i = 0; i < cfg->nparams; i++)
        p += gw_snprintf(p, n - (size_t)(p - s), "# param %s = %s\n", cfg->params[i].name, cfg->params[i].values[0]);
    return s;
}

/* The journal's "# grid" or "# param" line of key name (sec "grid " or
 * "param "): its value (the text after " = ") and length, or NULL. nth: the
 * key's place among the journal's lines of that section. */
static const char *journal_key(const char *buf, size_t len, const char *sec, const char *name, size_t *vl, int *nth)
{
    const size_t sl = strlen(sec), nl = strlen(name);
    *nth = 0;
    for (const char *p = memchr(buf, '\n', len); p && (size_t)(p + 1 - buf) < len && p[1] == '#';
         p = memchr(p + 1, '\n', len - (size_t)(p + 1 - buf))) {
        const char *line = p + 1, *end = memchr(line, '\n', len - (size_t)(line - buf));
        if (!end)
            break;
        if ((size_t)(end - line) < 2 + sl || memcmp(line + 2, sec, sl) != 0)
            continue;
        const char *k = line + 2 + sl;
        if ((size_t)(end - k) >= nl + 3 && memcmp(k, name, nl) == 0 && memcmp(k + nl, " = ", 3) == 0) {
            *vl = (size_t)(end - k - nl - 3);
            return k + nl + 3;
        }
        (*nth)++;
    }
    return NULL;
}

/* The number of "# SEC" lines in the journal's head. */
static int journal_nkeys(const char *buf, size_t len, const char *sec)
{
    int n = 0;
    size_t vl;
    journal_key(buf, len, sec, "\n", &vl, &n); /* no key is named "\n": counts them all */
    return n;
}

/* a and b (n values of a key, or one text a and the list b) are the same
 * numbers, spelt otherwise: 1 (0.1 and 1e-1) */
static int same_numbers(const char *a, size_t al, char *const *b, int nb)
{
    char *copy = malloc(al + 1), *save = NULL;
    if (!copy)
        return 0;
    memcpy(copy, a, al);
    copy[al] = '\0';
    int i = 0, same = 1;
    for (char *t = strtok_r(copy, ",", &save); same && t; t = strtok_r(NULL, ",", &save), i++) {
        t = gw_str_trim(t);
        if (i >= nb) {
            same = 0;
            break;
        }
        double x, y; /* by the data files' rule: 0x1p-2 is no number, as in the config */
        same = gw_data_number(t, &x) == GW_DATA_NUMBER && gw_data_number(b[i], &y) == GW_DATA_NUMBER && x == y;
    }
    free(copy);
    return same && i == nb;
}

/* An existing journal of another config: name the first key whose place or
 * value differs from cfg's (journals that record their keys: "# grid" and
 * "# param" lines). GW_OK when it cannot tell. */
int gw_sweep_head_changed_keys(const gw_sweep_config *cfg, const char *buf, size_t len, const char *dir, gw_err *err)
{
    static const char *const fix = "remove the journal or choose another output to start this one";
    const int ng = journal_nkeys(buf, len, "grid "), np = journal_nkeys(buf, len, "param ");
    if (ng == 0)
        return GW_OK; /* a journal before these lines */
    for (int sec = 0; sec < 2; sec++) {
        const gw_sweep_key *keys = sec ? cfg->params : cfg->grid;
        const int n = sec ? cfg->nparams : cfg->ngrid, nj = sec ? np : ng;
        const char *sname = sec ? "param " : "grid ", *what = sec ? "[params]" : "[grid]";
        for (int i = 0; i < n; i++) {
            size_t vl = 0;
            int at = 0;
            const char *v = journal_key(buf, len, sname, keys[i].name, &vl, &at);
            if (!v) {
                /* a journal of a granwave that kept the config's spelling
                 * (dt_out): the same key, now held as dt-out */
                char alt[128];
                gw_snprintf(alt, sizeof alt, "%s", keys[i].name);
                for (char *a = alt; *a; a++)
                    if (*a == '-')
                        *a = '_';
                size_t al = 0;
                int aat = 0;
                if (strcmp(alt, keys[i].name) != 0 && journal_key(buf, len, sname, alt, &al, &aat))
                    return gw_err_set(err, GW_EINVAL, "%s: this directory holds another sweep: its journal has %s "
                                      "%s, an earlier granwave's spelling of %s (a sweep now holds each key under "
                                      "its option's '-' spelling, and its hashes with it); finish that sweep with the "
                                      "granwave that started it, or %s", dir, what, alt, keys[i].name, fix);
                return gw_err_set(err, GW_EINVAL, "%s: this directory holds another sweep: %s %s is not in the "
                                  "config of its journal; %s", dir, what, keys[i].name, fix);
            }
            /* the config's values as the journal writes them */
            size_t cl = 0;
            for (int j = 0; j < keys[i].nvalues; j++)
                cl += strlen(keys[i].values[j]) + (j ? 2 : 0);
            char *c = malloc(cl + 1), *q = c;
            if (!c)
                return gw_err_set(err, GW_ENOMEM, "%s: out of memory", dir);
            for (int j = 0; j < keys[i].nvalues; j++)
                q += gw_snprintf(q, cl + 1 - (size_t)(q - c), "%s%s", j ? ", " : "", keys[i].values[j]);
            const int same = vl == cl && memcmp(v, c, cl) == 0;
            const int ci = (int)(cl < 160 ? cl : 160), vi = (int)(vl < 160 ? vl : 160);
            int rc = GW_OK;
            if (!same && same_numbers(v, vl, keys[i].values, keys[i].nvalues))
                rc = gw_err_set(err, GW_EINVAL, "%s: this directory holds another sweep: %s %s = %.*s%s here, %.*s%s "
                                "in its journal, the same numbers spelt otherwise (rows and hashes hold the values as "
                                "spelt): spell them as the journal does to resume, or %s", dir, what, keys[i].name,
                                ci, c, ci < (int)cl ? "..." : "", vi, v, vi < (int)vl ? "..." : "", fix);
            else if (!same)
                rc = gw_err_set(err, GW_EINVAL, "%s: this directory holds another sweep: %s %s = %.*s%s here, %.*s%s "
                                "in its journal; %s", dir, what, keys[i].name, ci, c, ci < (int)cl ? "..." : "", vi,
                                v, vi < (int)vl ? "..." : "", fix);
            else if (at != i)
                rc = gw_err_set(err, GW_EINVAL, "%s: this directory holds another sweep: its journal has the %s "
                                "keys in another order (%s is key %d here, %d there; %s): restore the journal's "
                                "order to resume, or %s", dir, what, keys[i].name, i + 1, at + 1,
                                sec ? "each row's config hash is over the [params] in order"
                                    : "the case numbers would name other combinations", fix);
            free(c);
            if (rc != GW_OK)
                return rc;
        }
        if (nj > n)
            return gw_err_set(err, GW_EINVAL, "%s: this directory holds another sweep: its journal has %d %s keys, "
                              "the config %d; %s", dir, nj, what, n, fix);
    }
    return GW_OK;
}

/* The content hash that ends a journal's "# input KEY = VALUE fnv1a64 HEX"
 * line [line, end): 16 lowercase hex digits, no more, no less (strtoull took
 * " 0x12", "-1" and a shorter hash). *at: where " fnv1a64 " starts. GW_EINVAL
 * naming the journal's line when it is not so. */
int gw_sweep_head_input_hash(const char *path, long lineno, const char *line, const char *end, const char **at,
                           unsigned long long *h, gw_err *err)
{
    const char *f = NULL;
    for (const char *q = line; q + 9 <= end; q++)
        if (memcmp(q, " fnv1a64 ", 9) == 0)
            f = q;
    if (f && gw_fnv1a64_parse(f + 9, (size_t)(end - f - 9), h)) {
        *at = f;
        return GW_OK;
    }
    const int n = (int)(end - line) < 200 ? (int)(end - line) : 200;
    return gw_err_set(err, GW_EINVAL, "%s:%ld: '# input %.*s' does not end with ' fnv1a64 ' and the file's content "
                      "hash in 16 hex digits (an edited journal): restore the line, or remove the journal to rerun "
                      "its cases", path, lineno, n, line);
}

/* An existing journal of another config: when one of its "# input" lines
 * names a file of this config whose content differs, say so (a resumed sweep
 * of the same config over a changed sample was "another sweep (different
 * config)", naming neither the file nor the change). */
int gw_sweep_head_changed_input(const gw_sweep_config *cfg, const char *buf, size_t len, const char *path,
                         const char *dir, gw_err *err)
{
    const char *p = memchr(buf, '\n', len);
    long lineno = 1;
    if (p && (size_t)(p + 1 - buf) < len && strncmp(p + 1, "# build ", 8) == 0) { /* format 3's second line */
        p = memchr(p + 1, '\n', len - (size_t)(p + 1 - buf));
        lineno++;
    }
    while (p && (size_t)(p + 1 - buf) < len && strncmp(p + 1, "# input ", 8) == 0) {
        const char *line = p + 9, *end = memchr(line, '\n', len - (size_t)(line - buf)), *at = NULL;
        if (!end)
            break;
        unsigned long long was;
        int rc = gw_sweep_head_input_hash(path, ++lineno, line, end, &at, &was, err);
        if (rc != GW_OK)
            return rc;
        for (int i = 0; i < cfg->ninputs; i++) {
            const struct gw_sweep_input *in = &cfg->inputs[i];
            size_t kl = strlen(in->key), vl = strlen(in->value);
            if ((size_t)(at - line) == kl + 3 + vl && strncmp(line, in->key, kl) == 0 &&
                strncmp(line + kl, " = ", 3) == 0 && strncmp(line + kl + 3, in->value, vl) == 0 &&
                was != in->hash)
                return gw_err_set(err, GW_EINVAL, "%s: %s '%s' changed since the sweep in it started (content "
                                  "fnv1a64 %016llx in its journal, now %016llx): its finished cases ran on the "
                                  "old file; restore it, or choose another output", dir, in->key, in->value,
                                  was, in->hash);
        }
        p = end;
    }
    return GW_OK;
}

/* The format of a journal's first line "# granwave sweep journal HASH" (16
 * lowercase hex digits, as GW_SWEEP_JOURNAL_HEAD writes it), then nothing
 * (format 1, the first) or ", format N" (N a decimal number with no leading
 * zero, no sign) and the line's end: 1 with *fmt and *hash; 2 when the line
 * starts as a granwave journal's but goes on otherwise (a format no granwave
 * this one knows of writes, or an edited head); 0 when it does not start so
 * (not a granwave sweep journal). */
int gw_sweep_head_format(const char *buf, size_t len, long *fmt, unsigned long *hash)
{
    static const char pre[] = "# granwave sweep journal ";
    const size_t pl = sizeof pre - 1;
    if (len < pl || memcmp(buf, pre, pl) != 0)
        return 0;
    const char *nl = memchr(buf, '\n', len);
    const char *p = buf + pl, *end = nl ? nl : buf + len;
    unsigned long h = 0;
    for (int i = 0; i < 16; i++, p++) {
        if (p >= end || !((*p >= '0' && *p <= '9') || (*p >= 'a' && *p <= 'f')))
            return 2;
        h = h << 4 | (unsigned long)(*p <= '9' ? *p - '0' : *p - 'a' + 10);
    }
    *hash = h;
    if (p == end) {
        /* a head without its newline is no journal a sweep made (it writes
         * the head and its lines whole): not format 1 */
        if (!nl)
            return 2;
        *fmt = 1;
        return 1;
    }
    static const char fsep[] = ", format ";
    const size_t fl = sizeof fsep - 1;
    if ((size_t)(end - p) < fl + 1 || memcmp(p, fsep, fl) != 0)
        return 2;
    p += fl;
    if (*p < '1' || *p > '9' || end - p > 9) /* up to 9 digits: no overflow, and no format a sweep writes */
        return 2;
    long n = 0;
    for (; p < end; p++) {
        if (*p < '0' || *p > '9')
            return 2;
        n = 10 * n + (*p - '0');
    }
    /* "format 1" was never written (format 1 had no suffix) */
    if (n < 2 || !nl)
        return 2;
    *fmt = n;
    return 1;
}

/* The journal's first line for a message: at most n - 1 bytes, each byte
 * that is not printable ASCII as '?', "..." when cut. */
void gw_sweep_head_first_line(const char *buf, size_t len, char *out, size_t n)
{
    const char *nl = memchr(buf, '\n', len);
    size_t l = nl ? (size_t)(nl - buf) : len, w = 0;
    const int cut = l > n - 4;
    if (cut)
        l = n - 4;
    for (size_t i = 0; i < l; i++)
        out[w++] = buf[i] >= 0x20 && buf[i] < 0x7f ? buf[i] : '?';
    if (cut)
        out[w++] = '.', out[w++] = '.', out[w++] = '.';
    out[w] = '\0';
}
