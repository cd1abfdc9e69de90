/*
 * layer_sample.c: the sample files of pluviated layers (docs/physics.md 2.2):
 * the text format (versions 1 and 2), the choice between text and HDF5, and
 * the public reader and writer.
 *
 * Text format, documented in gw_layer.h: a magic line, "key value" header lines,
 * then "n N" and N lines "x y r" in metres (version 2, clump samples of type B
 * soil: "x y r body", the rigid-body id; disc samples keep writing version 1,
 * so their files are unchanged), then optionally the pile's tangential
 * springs, "springs M" and M lines "a b u" (gw_layer_spring; read here,
 * checked last by layer_sample_springs.c). '#' starts a comment line (the
 * writer puts the program version and the command line there); the one
 * "# settings: {JSON}" line layer-make writes among them is read for the
 * settling's material (layer_sample_settings.c, gw_layer_settled), and its
 * "# settled: ..." line for 'converged 0' (a pile written before it settled,
 * gw_layer_settled.unsettled). Lines end in LF
 * or CRLF, the last line too (a file ending inside a record was cut short).
 * The reader refuses anything else with the file name and line number,
 * and opens only regular files (gw_input_open: a FIFO or device never blocks it).
 * HDF5 samples (layer_sample_h5.c) are told apart by the HDF5 signature, not
 * by the file name. Both formats' fields pass the same checks
 * (layer_sample_check.c: the header, each particle, then the bodies, the
 * grading, the box against the packing and the porosity,
 * layer_sample_porosity.c).
 * Units: SI (m).
 */
#define _GNU_SOURCE /* fileno, fstat, pread; SEEK_HOLE (layer_sample_file_check) */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "layer_sample_impl.h"
#include "gw_io_impl.h"
#include "gw_locale.h"
#include "gw_number_impl.h"

#define SAMPLE_LINE_MAX 1024  /* longest header or particle line; comments may be longer */
/* longest line of any kind, a comment too, in bytes: layer-make's longest is
 * its settings line (under 30000 characters, SAMPLE_SETTINGS_MAX), and a line
 * that never ends (a '#' and then a sparse file's zeros, or gigabytes of text
 * without a newline) was read to its end before anything was said */
#define SAMPLE_RAW_LINE_MAX (1L << 20)
static const unsigned char h5_signature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};

void gw_layer_sample_free(gw_layer_sample *s)
{
    if (!s)
        return;
    free(s->x);
    free(s->body);
    free(s->springs);
    s->x = s->y = s->r = NULL;
    s->body = NULL;
    s->springs = NULL;
    s->n = s->n_springs = 0;
}

/* 1 when the name asks for HDF5 (.h5, .hdf5; any case). */
static int wants_h5(const char *path)
{
    size_t n = strlen(path);
    return (n >= 3 && strcasecmp(path + n - 3, ".h5") == 0) ||
           (n >= 5 && strcasecmp(path + n - 5, ".hdf5") == 0);
}

int gw_layer_sample_out_check(const char *path, const char *what, gw_err *err)
{
    if (!path)
        return gw_err_set(err, GW_EINVAL, "gw_layer_sample_out_check: path is NULL");
    if (!what)
        what = "sample";
    if (wants_h5(path) && !GW_HAVE_HDF5)
        return gw_err_set(err, GW_EUNSUPPORTED, "%s: '%s': HDF5 samples need granwave built with HDF5 "
                          "(GW_WITH_HDF5=ON and libhdf5); give a text name such as sample.txt", what, path);
    /* the place the sample goes, before the run: a FIFO, device or directory of
     * that name, or a missing or read-only directory, is refused */
    int rc = gw_out_file_check(path, what, err);
    if (rc != GW_OK)
        return rc;
    /* an existing file is replaced only when it is a sample (text or HDF5) or
     * empty: a mistyped --out never overwrites someone's data */
    FILE *fp = fopen(path, "rb");
    if (fp) {
        unsigned char head[sizeof SAMPLE_MAGIC - 1] = {0};
        const size_t got = fread(head, 1, sizeof head, fp);
        fclose(fp);
        const int text = got == sizeof head && memcmp(head, SAMPLE_MAGIC, sizeof head) == 0;
        const int h5 = got >= sizeof h5_signature && memcmp(head, h5_signature, sizeof h5_signature) == 0;
        if (got > 0 && !text && !h5)
            return gw_err_set(err, GW_EINVAL, "%s: '%s' exists and is not a granwave sample; refusing to "
                              "overwrite it", what, path);
    }
    /* and a directory that refuses new files whatever its mode says (root in
     * /proc, a read-only mount): the temporary file of the atomic write is
     * made and removed at once, before hours of pluviation */
    gw_afile f;
    gw_err e = {{0}};
    int orc = gw_afile_open(&f, path, &e);
    if (orc == GW_ENOMEM) /* not the place's fault */
        return gw_err_set(err, orc, "%s: '%s': %s", what, path, e.msg);
    if (orc != GW_OK)
        return gw_err_set(err, GW_EINVAL, "%s: '%s' cannot be written there (%s)", what, path, e.msg);
    gw_afile_abort(&f);
    return GW_OK;
}

int gw_layer_sample_format_check(const char *path, gw_err *err)
{
    if (!path) /* named as the other call ("gw_layer_sample_out_check: path is NULL") */
        return gw_err_set(err, GW_EINVAL, "gw_layer_sample_format_check: path is NULL");
    return gw_layer_sample_out_check(path, "sample", err);
}

/* how the writer's comment line announcing the springs section begins */
#define SPRINGS_SAID "lines after 'springs'"

/* ------------------------------------------------------------- text ---- */

static int write_text(const gw_layer_sample *s, const char *path, const char *header, gw_err *err)
{
    gw_afile f;
    int rc = gw_afile_open(&f, path, err);
    if (rc != GW_OK)
        return rc;
    gw_fprintf(f.fp, SAMPLE_MAGIC " %d\n", s->body ? 2 : 1);
    gw_write_comment(f.fp, header);
    gw_fprintf(f.fp, "# units: metres; lines after 'n' are: x y r%s\n", s->body ? " body" : "");
    if (s->n_springs > 0)
        gw_fprintf(f.fp, "# " SPRINGS_SAID " are: a b u, a contact (two particles' indices, or a particle "
                   "and a wall: left, right, bottom) and its tangential spring's elastic displacement (m)\n");
    gw_fprintf(f.fp, "width %.17g\nrm %.17g\nvolume_ratio %.17g\n", s->width, s->rm, s->volume_ratio);
    if (!isnan(s->porosity)) /* NaN: unknown, not written */
        gw_fprintf(f.fp, "porosity %.17g\n", s->porosity);
    gw_fprintf(f.fp, "seed %ld\n", s->seed);
    gw_fprintf(f.fp, "mass_law %s\n", s->mass_law == GW_LAYER_MASS_SPHERE ? "sphere" : "disc");
    if (s->clump_mass == GW_LAYER_CLUMP_MASS_UNION) /* sum, the default, is not written */
        gw_fprintf(f.fp, "clump_mass %s\n", gw_layer_clump_mass_name(s->clump_mass));
    gw_fprintf(f.fp, "n %d\n", s->n);
    for (int i = 0; i < s->n; i++) {
        if (s->body)
            gw_fprintf(f.fp, "%.17g %.17g %.17g %d\n", s->x[i], s->y[i], s->r[i], s->body[i]);
        else
            gw_fprintf(f.fp, "%.17g %.17g %.17g\n", s->x[i], s->y[i], s->r[i]);
    }
    if (s->n_springs > 0)
        gw_fprintf(f.fp, "springs %d\n", s->n_springs);
    for (int k = 0; k < s->n_springs; k++) {
        const gw_layer_spring *q = &s->springs[k];
        if (q->b >= 0)
            gw_fprintf(f.fp, "%d %d %.17g\n", q->a, q->b, q->u);
        else
            gw_fprintf(f.fp, "%d %s %.17g\n", q->a, layer_spring_wall_name(q->b), q->u);
    }
    return gw_afile_commit(&f, err);
}

/* A line source: the bytes already read to look for the HDF5 signature, then
 * the stream (so pipes work too). */
typedef struct text_in {
    FILE *fp;
    const char *path;
    unsigned char pre[8];
    size_t npre, ipre;
    long line;
    int last; /* the last byte read */
    /* FNV-1a 64 of every byte read (text_getc): the sample's content hash is
     * that of the bytes parsed. Read again from byte 0 after the parse, a file
     * grown or rewritten in between was hashed over bytes never parsed. */
    unsigned long long hash;
    /* the file's size at open and the bytes read (pre included): a byte past
     * that size ends the read (grew set; gw_layer_sample_read refuses the
     * file). It read to the file's end, so a file appended to while it was
     * read (a comment line a millisecond) kept it reading without bound. */
    unsigned long long size, nread;
    int grew;
    char buf[SAMPLE_LINE_MAX + 1];
    /* layer-make's settings line, a comment "# settings: {JSON}": its JSON
     * (owned, NUL-terminated; NULL: none) and line */
    char *set;
    size_t nset, capset;
    long set_line;
    /* the start of the comment line being read, from its first character
     * after '#' and the blanks (layer-make's "settled: ..., converged N"
     * comes within it), and whether a "settled:" line said converged 0 or 1 */
    char com[128];
    size_t ncom;
    int unsettled, converged; /* the settled line's converged 0, 1 */
    long spr_said; /* the line of the writer's "# lines after 'springs' ..." (0: none) */
    long *spr_lines; /* the line of each spring read (owned) */
} text_in;

/* Append c to the settings text; GW_ENOMEM, or GW_EFORMAT past SAMPLE_SETTINGS_MAX. */
static int settings_put(text_in *t, int c, gw_err *err)
{
    if (t->nset >= SAMPLE_SETTINGS_MAX)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: layer-make's settings line is longer than "
                          "%d characters", t->path, t->line + 1, SAMPLE_SETTINGS_MAX);
    if (t->nset + 1 >= t->capset) {
        size_t nc = t->capset ? 2 * t->capset : 1024;
        char *b = realloc(t->set, nc);
        if (!b)
            return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for its settings line", t->path);
        t->set = b, t->capset = nc;
    }
    t->set[t->nset++] = (char)c;
    t->set[t->nset] = '\0';
    return GW_OK;
}

static int text_getc(text_in *t)
{
    if (t->grew)
        return EOF;
    const int c = t->ipre < t->npre ? t->pre[t->ipre++] : getc(t->fp);
    if (c != EOF && t->nread >= t->size) { /* one byte past the size at open: no more */
        t->grew = 1;
        return EOF;
    }
    if (c != EOF) {
        t->nread++;
        const unsigned char b = (unsigned char)c;
        t->last = c;
        t->hash = gw_fnv1a64(t->hash, &b, 1);
    }
    return c;
}

/* Next line that is neither blank nor a comment into t->buf, without its LF or
 * CRLF. 1: a line; 0: end of file; < 0: GW_EFORMAT (NUL byte, line too long)
 * or GW_EIO (read error), with err set. */
static int text_next(text_in *t, gw_err *err)
{
    static const char set_key[] = "settings:";
    for (;;) {
        int c, any = 0, lead = 1, comment = 0;
        long raw = 0; /* the bytes of the line so far */
        /* in a comment: -1 after '#' (blanks), k >= 0 the characters of
         * "settings:" matched, sizeof set_key - 1 the key whole (the rest is
         * the JSON), -2 another comment */
        int key = -1;
        size_t len = 0;
        t->ncom = 0;
        while ((c = text_getc(t)) != EOF && c != '\n') {
            any = 1;
            /* said at once: a NUL inside a comment was found at the line's end
             * only, and a '#' before a 200 GB sparse file's zeros read them all
             * (killed at the time limit, nothing said) */
            if (c == 0)
                return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: NUL byte (binary data, not a text sample)",
                                  t->path, t->line + 1);
            if (++raw > SAMPLE_RAW_LINE_MAX)
                return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: longer than %ld bytes, a comment too (the "
                                  "longest line layer-make writes, its settings line, is under %d): not a text sample",
                                  t->path, t->line + 1, SAMPLE_RAW_LINE_MAX, SAMPLE_SETTINGS_MAX);
            /* a CR not before the LF: lines that end in CR alone were one line,
             * refused as "longer than 1024 characters" (or, short, as a header) */
            if (c == '\r' && (c = text_getc(t)) != '\n' && c != EOF)
                return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: a carriage return inside the line: "
                                  "lines that end in CR alone are one line to the reader; convert them to LF "
                                  "(CR LF is read too)", t->path, t->line + 1);
            if (c == '\n' || c == EOF)
                break;
            if (lead && (c == ' ' || c == '\t'))
                continue;
            if (lead) {
                comment = c == '#', lead = 0;
                if (comment)
                    continue;
            }
            if (comment && t->ncom < sizeof t->com - 1 && (t->ncom > 0 || (c != ' ' && c != '\t')))
                t->com[t->ncom++] = (char)c;
            if (comment && key == (int)sizeof set_key - 1) {
                int rc = settings_put(t, c, err);
                if (rc != GW_OK)
                    return rc;
            } else if (comment && key == -1 && (c == ' ' || c == '\t')) {
                /* the blanks between '#' and the key */
            } else if (comment && key != -2) {
                key = c == set_key[key < 0 ? 0 : key] ? (key < 0 ? 1 : key + 1) : -2;
                if (key == (int)sizeof set_key - 1) { /* the key: a settings line */
                    if (t->set_line > 0)
                        return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: a second settings line (the "
                                          "first at line %ld): layer-make writes one", t->path, t->line + 1,
                                          t->set_line);
                    t->set_line = t->line + 1;
                    int rc = settings_put(t, ' ', err); /* an empty one is text too: refused as not JSON */
                    if (rc != GW_OK)
                        return rc;
                }
            }
            if (comment)
                continue;
            if (len == SAMPLE_LINE_MAX)
                return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: longer than %d characters",
                                  t->path, t->line + 1, SAMPLE_LINE_MAX);
            t->buf[len++] = (char)c;
        }
        if (c == EOF && ferror(t->fp))
            return gw_err_set(err, GW_EIO, "sample '%s': read error after line %ld: %s", t->path,
                              t->line, strerror(errno));
        if (c == EOF && !any)
            return 0;
        t->line++;
        if (comment) { /* a pile written before it settled: an impact on it warns */
            t->com[t->ncom] = '\0';
            t->unsettled |= layer_sample_settled_unsettled(t->com);
            t->converged |= layer_sample_settled_converged(t->com);
            if (!t->spr_said && strncmp(t->com, SPRINGS_SAID, sizeof SPRINGS_SAID - 1) == 0)
                t->spr_said = t->line;
        }
        if (len > 0 && t->buf[len - 1] == '\r')
            len--;
        /* a record without its newline (LF, or the CR of a CR LF) is the end
         * of a file cut short: the writer ends every line, and a number cut
         * in its digits still reads
         * (the last radius of a 40-disc sample cut from 0.2296 to 0.22 m ran
         * with exit 0, its penetration 53 % deeper) */
        /* ended: its last byte an LF, or the CR of a CR LF (gw_io_lines.h's rule) */
        if (c == EOF && !comment && len > 0 && t->last != '\n' && t->last != '\r')
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: the file ends inside this line (no newline "
                              "after it): cut short? layer-make ends every line with one", t->path, t->line);
        t->buf[len] = '\0';
        if (!comment && len > 0)
            return 1;
    }
}

/* Split s at blanks in place into at most max tokens; returns the token count,
 * max + 1 when there are more. */
static int split(char *s, char **tok, int max)
{
    int k = 0;
    for (;;) {
        while (*s == ' ' || *s == '\t')
            s++;
        if (!*s)
            return k;
        if (k == max)
            return max + 1;
        tok[k++] = s;
        while (*s && *s != ' ' && *s != '\t')
            s++;
        if (*s)
            *s++ = '\0';
    }
}

/* The whole token as a finite double (underflow to a subnormal is fine), by
 * the data files' rule (gw_data_number: decimal, as the program's options;
 * strtod's hexadecimal "0x1p-2" was read as 0.25): 1, or 0 with *why its
 * gw_data_number code (GW_DATA_HUGE for nan and inf) when why is not NULL. */
static int parse_num(const char *s, double *v, int *why)
{
    int c = gw_data_number(s, v);
    if (c == GW_DATA_NUMBER && !isfinite(*v))
        c = GW_DATA_HUGE;
    if (why)
        *why = c;
    return c == GW_DATA_NUMBER;
}

static int parse_long(const char *s, long *v)
{
    char *end;
    errno = 0;
    *v = strtol(s, &end, 10);
    return end != s && *end == '\0' && errno == 0;
}

static const char *const header_keys[K_COUNT] = {"width", "rm", "volume_ratio", "porosity",
                                                 "seed", "mass_law", "clump_mass", "n"};

/* Header lines up to and including "n N": fills s, *n, the format version and
 * the line of each key in src (a porosity not given is NaN, unknown). */
static int text_header(text_in *t, gw_layer_sample *s, long *n, int *version, hdr_src *src, gw_err *err)
{
    char *tok[3], show[48];
    int rc = text_next(t, err), seen = 0;
    if (rc <= 0)
        return rc < 0 ? rc : gw_err_set(err, GW_EFORMAT, "sample '%s': empty file, not a granwave layer sample",
                                        t->path);
    /* a UTF-8 byte-order mark (an editor's "save as UTF-8"): skipped, as
     * layer-stats does with its tables; it was refused as "not a granwave layer
     * sample" without a word on the mark */
    if (strncmp(t->buf, "\xEF\xBB\xBF", 3) == 0) {
        memmove(t->buf, t->buf + 3, strlen(t->buf + 3) + 1);
        /* the mark alone on a blank or comment line: text_next took the mark
         * for text and returned the line; the header is on a later line (a
         * mark then blank lines read tok[0] unset: SIGSEGV, found by
         * fuzz_layer_sample) */
        const char *p = t->buf + strspn(t->buf, " \t");
        if ((*p == '\0' || *p == '#') && (rc = text_next(t, err)) <= 0)
            return rc < 0 ? rc : gw_err_set(err, GW_EFORMAT, "sample '%s': empty file, not a granwave layer sample",
                                            t->path);
    }
    int k = split(t->buf, tok, 2);
    if (k < 1 || strcmp(tok[0], SAMPLE_MAGIC) != 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: not a granwave layer sample (expected '"
                          SAMPLE_MAGIC " 1')", t->path, t->line);
    if (k > 2)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: characters after '" SAMPLE_MAGIC " %s'",
                          t->path, t->line, layer_sample_shown(tok[1], show));
    if (k != 2 || (strcmp(tok[1], "1") != 0 && strcmp(tok[1], "2") != 0))
        return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: unsupported format version '%s' "
                          "(this build reads 1 and 2)", t->path, t->line, k == 2 ? layer_sample_shown(tok[1], show) : "");
    *version = tok[1][0] - '0';
    while ((rc = text_next(t, err)) > 0) {
        k = split(t->buf, tok, 2);
        int key = 0;
        while (key < K_COUNT && strcmp(tok[0], header_keys[key]) != 0)
            key++;
        if (key == K_COUNT)
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: unknown key '%s'", t->path, t->line,
                              layer_sample_shown(tok[0], show));
        if (k != 2)
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: expected '%s VALUE'%s", t->path,
                              t->line, header_keys[key], k > 2 ? " and nothing after it" : "");
        if (seen & (1 << key))
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: '%s' given twice", t->path, t->line,
                              header_keys[key]);
        seen |= 1 << key;
        src->line[key] = t->line;
        double v = 0;
        int ok = 1, why = GW_DATA_NUMBER;
        if (key == K_LAW) {
            ok = strcmp(tok[1], "disc") == 0 || strcmp(tok[1], "sphere") == 0;
            s->mass_law = strcmp(tok[1], "sphere") == 0 ? GW_LAYER_MASS_SPHERE : GW_LAYER_MASS_DISC;
        } else if (key == K_CMASS) {
            s->clump_mass = gw_layer_clump_mass_parse(tok[1]);
            ok = s->clump_mass >= 0;
        } else if (key == K_SEED) { /* layer-make's seeds are >= 0: "-1" was taken */
            ok = parse_long(tok[1], &s->seed) && s->seed >= 0;
        } else {
            ok = parse_num(tok[1], &v, &why);
        }
        if (!ok)
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: %s '%s' is not %s", t->path, t->line,
                              header_keys[key], layer_sample_shown(tok[1], show),
                              key == K_LAW ? "disc or sphere" : key == K_CMASS ? "sum or union"
                              : key == K_SEED ? "an integer >= 0"
                              : why == GW_DATA_HEX ? "a decimal number (no hexadecimal, as the program's options)"
                              : "a finite number");
        if (key == K_WIDTH)
            s->width = v;
        else if (key == K_RM)
            s->rm = v;
        else if (key == K_VR)
            s->volume_ratio = v;
        else if (key == K_POR)
            s->porosity = v;
        else if (key == K_N) {
            if (!(v >= 1 && v <= SAMPLE_NMAX && v == floor(v)))
                /* as given: %g showed n 10000001 as "n = 1e+07", a value inside the range it named */
                return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: n = %s must be an integer in "
                                  "[1, %ld]", t->path, t->line, layer_sample_shown(tok[1], show), SAMPLE_NMAX);
            *n = (long)v;
            break;
        }
    }
    if (rc < 0)
        return rc;
    if (!(seen & (1 << K_POR)))
        s->porosity = NAN;
    if (!(seen & (1 << K_N)) || !(seen & (1 << K_WIDTH)) || !(seen & (1 << K_RM)))
        return gw_err_set(err, GW_EFORMAT, "sample '%s': header incomplete after line %ld (needs width, rm "
                          "and then n)", t->path, t->line);
    return layer_sample_header_check(s, t->path, GW_EFORMAT, err);
}

/* Room for cap particles in one block x | y | r (the sample owns s->x only);
 * grows with the file so that a short file claiming a large n costs little. */
static int grow(gw_layer_sample *s, long *cap, long want, int bodies)
{
    long nc = *cap;
    while (nc < want)
        nc = nc ? 2 * nc : 1024;
    if (nc > SAMPLE_NMAX)
        nc = SAMPLE_NMAX;
    if (bodies) {
        int *bd = realloc(s->body, (size_t)nc * sizeof *bd);
        if (!bd)
            return GW_ENOMEM;
        s->body = bd;
    }
    double *b = realloc(s->x, 3 * (size_t)nc * sizeof *b);
    if (!b)
        return GW_ENOMEM;
    /* r first: its new place [2 nc, 2 nc + cap) lies above the old y */
    memmove(b + 2 * nc, b + 2 * *cap, (size_t)*cap * sizeof *b);
    memmove(b + nc, b + *cap, (size_t)*cap * sizeof *b);
    s->x = b, s->y = b + nc, s->r = b + 2 * nc;
    *cap = nc;
    return GW_OK;
}

/* The optional springs section after the n particles, its first line in
 * t->buf: "springs M", then M lines "a b u" (b an index or a wall's name),
 * into s; lines[k] (owned by the caller, freed on any return) the line of
 * spring k. The values are checked later (layer_springs_check), once the
 * settling's record is read. */
static int read_springs(text_in *t, gw_layer_sample *s, long n, long **lines, gw_err *err)
{
    char *tok[3], show[48];
    long m = 0;
    const long most = LAYER_SPRINGS_MOST(n);
    int k = split(t->buf, tok, 2);
    if (strcmp(tok[0], "springs") != 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: data after the %ld particles (only a "
                          "'springs M' section may follow them)", t->path, t->line, n);
    if (k != 2 || !parse_long(tok[1], &m) || m < 0 || m > most)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: expected 'springs M', M an integer in [0, "
                          "%ld] (at most 8 (n + 1) contacts)", t->path, t->line, most);
    long cap = 0;
    for (long i = 0; i < m; i++) {
        int got = text_next(t, err);
        if (got <= 0)
            return got < 0 ? got : gw_err_set(err, GW_EFORMAT, "sample '%s': truncated after line %ld: %ld of "
                                              "%ld springs", t->path, t->line, i, m);
        if (i == cap) { /* grown with the file: a short file claiming many costs little */
            cap = cap ? 2 * cap : 1024;
            cap = cap > m ? m : cap;
            gw_layer_spring *q = realloc(s->springs, (size_t)cap * sizeof *q);
            long *l = realloc(*lines, (size_t)cap * sizeof *l);
            if (q)
                s->springs = q;
            if (l)
                *lines = l;
            if (!q || !l)
                return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for %ld springs", t->path, m);
        }
        long a = 0, b = 0;
        double u = 0;
        const int ntok = split(t->buf, tok, 3), wall = ntok == 3 ? layer_spring_wall(tok[1]) : 0;
        (*lines)[i] = t->line;
        int why = GW_DATA_NUMBER;
        if (ntok == 3 && parse_long(tok[0], &a) && (wall || parse_long(tok[1], &b)) &&
            !parse_num(tok[2], &u, &why) && why == GW_DATA_HEX)
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: u '%s' of spring %ld of %ld is %s", t->path,
                              t->line, layer_sample_shown(tok[2], show), i + 1, m, gw_data_number_why(why));
        if (ntok != 3 || !parse_long(tok[0], &a) || (!wall && !parse_long(tok[1], &b)) || why != GW_DATA_NUMBER)
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: expected 'a b u' (spring %ld of %ld: two "
                              "particle indices, or an index and left, right or bottom, and a finite number)",
                              t->path, t->line, i + 1, m);
        if (a < 0 || a >= n || (!wall && (b < 0 || b >= n)))
            return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: spring %ld %s: a particle index outside "
                              "[0, %ld)", t->path, t->line, a, wall ? layer_spring_wall_name(wall) : tok[1], n);
        s->springs[i] = (gw_layer_spring){.a = (int)a, .b = wall ? wall : (int)b, .u = u};
        s->n_springs = (int)(i + 1);
    }
    int got = text_next(t, err);
    if (got > 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: data after the %ld springs", t->path, t->line, m);
    return got < 0 ? got : GW_OK;
}

static int read_text(text_in *t, gw_layer_sample *s, gw_err *err)
{
    long n = 0, cap = 0, i = 0, id = 0;
    int version = 1;
    hdr_src src = {0};
    int rc = text_header(t, s, &n, &version, &src, err);
    const int ncol = version == 2 ? 4 : 3;
    char *tok[4], where[48];
    while (rc == GW_OK && i < n) {
        int got = text_next(t, err);
        if (got <= 0) {
            rc = got < 0 ? got : gw_err_set(err, GW_EFORMAT, "sample '%s': truncated after line %ld: %ld of "
                                            "%ld particles", t->path, t->line, i, n);
            break;
        }
        if (i == cap && grow(s, &cap, i + 1, version == 2) != GW_OK) {
            rc = gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for %ld particles", t->path, n);
            break;
        }
        const int ntok = split(t->buf, tok, ncol);
        int why[3] = {GW_DATA_NONE, GW_DATA_NONE, GW_DATA_NONE};
        if (ntok == ncol && !(parse_num(tok[0], &s->x[i], &why[0]) & parse_num(tok[1], &s->y[i], &why[1]) &
                              parse_num(tok[2], &s->r[i], &why[2]))) {
            const int f = why[0] == GW_DATA_HEX ? 0 : why[1] == GW_DATA_HEX ? 1 : why[2] == GW_DATA_HEX ? 2 : -1;
            if (f >= 0) { /* the field named: a hexadecimal number is a number, in another base */
                char show[48];
                rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: %s '%s' of particle %ld of %ld is %s",
                                t->path, t->line, f == 0 ? "x" : f == 1 ? "y" : "r",
                                layer_sample_shown(tok[f], show), i + 1, n, gw_data_number_why(GW_DATA_HEX));
                break;
            }
        }
        if (ntok != ncol || why[0] || why[1] || why[2] || (ncol == 4 && !parse_long(tok[3], &id))) {
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: expected %s (particle %ld of %ld)",
                            t->path, t->line, ncol == 4 ? "three finite numbers and an integer 'x y r body'"
                            : "three finite numbers 'x y r'", i + 1, n);
            break;
        }
        if (ncol == 4 && (id < 0 || id >= n)) {
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: body id %ld outside [0, %ld)", t->path,
                            t->line, id, n);
            break;
        }
        if (ncol == 4)
            s->body[i] = (int)id;
        gw_snprintf(where, sizeof where, "line %ld", t->line);
        rc = layer_sample_particle_check(s->width, s->rm, s->x[i], s->y[i], s->r[i], t->path, where, GW_EFORMAT, err);
        i++;
    }
    long *lines = NULL; /* the springs' lines */
    if (rc == GW_OK && (rc = text_next(t, err)) > 0)
        rc = read_springs(t, s, n, &lines, err);
    else if (rc == 0 && t->spr_said) /* the writer said springs follow: the file was cut before them */
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': ends after its %ld particles, but line %ld says a "
                        "'springs M' section follows: the file is cut short (a sample without springs has "
                        "no such line)", t->path, n, t->spr_said);
    if (rc != GW_OK) {
        free(lines);
        return rc;
    }
    if (cap > n) { /* close the gaps of the x | y | r block */
        memmove(s->x + n, s->y, (size_t)n * sizeof *s->x);
        memmove(s->x + 2 * n, s->r, (size_t)n * sizeof *s->x);
        double *b = realloc(s->x, 3 * (size_t)n * sizeof *b);
        if (b)
            s->x = b;
        s->y = s->x + n, s->r = s->x + 2 * n;
    }
    s->n = (int)n;
    rc = layer_sample_whole_check(s, t->path, &src, GW_EFORMAT, err);
    if (rc == GW_OK && t->set) { /* the settling's record, once the sample is whole */
        char where[32];
        gw_snprintf(where, sizeof where, "line %ld", t->set_line);
        if ((rc = layer_sample_settings_parse(t->set, t->path, where, s, &src, &s->settled, err)) == GW_OK &&
            s->settled.recorded)
            s->settled.line = t->set_line;
    }
    if (rc == GW_OK) /* after the settings' parse, which zeroes the record */
        s->settled.unsettled = t->unsettled, s->settled_converged = t->converged && !t->unsettled;
    if (rc == GW_OK) /* checked by the caller, last (gw_layer_sample_read) */
        t->spr_lines = lines;
    else
        free(lines);
    return rc;
}

/* The header a writer is given, as the readers will take it back: its lines
 * become comments ("# LINE"), so a carriage return inside one (not before
 * its newline) makes the text reader see one line where the header had two
 * and refuse it, a line over SAMPLE_RAW_LINE_MAX is refused, and a line that
 * reads as layer-make's "settings: {JSON}" (after blanks) is parsed as the
 * sample's settling record: one such line at most, JSON the record's parse
 * takes (layer_sample_settings_parse) against s. Before session 46 a header
 * "settings: not json", a settings line with a modulus of -5, two of them or
 * a CR inside a line were written and the file refused by the reader.
 * GW_EINVAL naming the header's line, GW_ENOMEM. */
static int header_check(const gw_layer_sample *s, const char *path, const char *header, gw_err *err)
{
    static const char key[] = "settings:";
    long k = 0, seen = 0;
    for (const char *p = header; p && *p; k++) {
        const size_t len = strcspn(p, "\n");
        const char *cr = memchr(p, '\r', len);
        if (cr && cr != p + len - 1)
            return gw_err_set(err, GW_EINVAL, "sample '%s': header line %ld: a carriage return inside the line, "
                              "which the reader takes for no line end (the line and the next read as one)",
                              path, k + 1);
        if (len + 2 > (size_t)SAMPLE_RAW_LINE_MAX)
            return gw_err_set(err, GW_EINVAL, "sample '%s': header line %ld: longer than %ld bytes, the longest "
                              "line the reader takes", path, k + 1, SAMPLE_RAW_LINE_MAX - 2);
        size_t b = 0;
        while (b < len && (p[b] == ' ' || p[b] == '\t'))
            b++;
        if (len - b >= sizeof key - 1 && strncmp(p + b, key, sizeof key - 1) == 0) {
            if (seen)
                return gw_err_set(err, GW_EINVAL, "sample '%s': header line %ld: a second settings line (the "
                                  "first at line %ld): the reader takes one", path, k + 1, seen);
            seen = k + 1;
            const size_t n = len - b - (sizeof key - 1) - (cr != NULL);
            if (n > SAMPLE_SETTINGS_MAX)
                return gw_err_set(err, GW_EINVAL, "sample '%s': header line %ld: a settings line longer than %d "
                                  "characters", path, k + 1, SAMPLE_SETTINGS_MAX);
            char *text = malloc(n + 1), where[48];
            if (!text)
                return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for its header's settings line", path);
            memcpy(text, p + b + sizeof key - 1, n);
            text[n] = '\0';
            gw_layer_settled rec;
            gw_snprintf(where, sizeof where, "header line %ld", k + 1);
            const int rc = layer_sample_settings_parse(text, path, where, s, NULL, &rec, err);
            free(text);
            if (rc != GW_OK)
                return rc == GW_EFORMAT ? GW_EINVAL : rc; /* (the message is the parse's) */
        }
        p += len + (p[len] == '\n');
    }
    return GW_OK;
}

/* -------------------------------------------------------- public API ---- */

int gw_layer_sample_write(const gw_layer_sample *s, const char *path, const char *header,
                          gw_err *err)
{
    if (!s || !path) /* as gw_layer_sample_read (the path's name was read: SIGSEGV) */
        return gw_err_set(err, GW_EINVAL, "gw_layer_sample_write: %s is NULL", !s ? "s" : "path");
    int rc = gw_layer_sample_format_check(path, err);
    /* the limits every sample is held to (the reader's and the in-memory
     * calls' one check: two discs deep inside each other were written, and
     * the file then refused on reading), then the header against its
     * particles (grading, box, porosity) */
    if (rc == GW_OK)
        rc = layer_sample_limits_check(s, path, GW_EINVAL, err);
    if (rc == GW_OK)
        rc = layer_sample_check(s, path, NULL, GW_EINVAL, err);
    if (rc == GW_OK) /* and its springs, as the reader would find them */
        rc = layer_springs_check(s, path, NULL, GW_EINVAL, err);
    if (rc == GW_OK) /* and the header, as the reader will take it back */
        rc = header_check(s, path, header, err);
    if (rc != GW_OK)
        return rc;
#if GW_HAVE_HDF5
    if (wants_h5(path))
        return layer_sample_h5_write(s, path, header, err);
#endif
    return write_text(s, path, header, err);
}

/* 1 when the file is HDF5: its signature at offset 0 (pre, the first 8
 * bytes) or, after a user block, at 512, 1024, 2048, ... (HDF5 looks there
 * too; a valid sample written by h5py with userblock_size=512 was read as
 * text and refused as "NUL byte"); *sb: the superblock version, the byte
 * after the signature (-1: none); *at: the signature's offset. The stream is
 * left at offset 8. */
static int h5_signature_at(FILE *fp, const unsigned char pre[8], int *sb, unsigned long long *at)
{
    *at = 0;
    if (memcmp(pre, h5_signature, 8) == 0) {
        *sb = getc(fp);
        return fseek(fp, 8, SEEK_SET) == 0;
    }
    int found = 0;
    unsigned char b[9];
    for (long off = 512; off <= (1L << 24) && !found; off *= 2) {
        if (fseek(fp, off, SEEK_SET) != 0 || fread(b, 1, 8, fp) != 8)
            break;
        found = memcmp(b, h5_signature, 8) == 0;
        if (found)
            *sb = getc(fp), *at = (unsigned long long)off;
    }
    return fseek(fp, 8, SEEK_SET) == 0 && found;
}

/* An HDF5 sample's superblock (version sb at byte at, after the signature)
 * against the file's size, before any of it is hashed or opened: a sample
 * granwave reads has a version 2 or 3 superblock (the 1.8 format and later,
 * metadata checksummed), whose end-of-file address less its base address
 * (both absolute as written: the base is the superblock's own offset, 512
 * behind a user block) is the length from the superblock to where the file
 * HDF5 wrote ends. The signature and then zeros (written, not sparse: no hole
 * to find) up to 4 GiB were hashed whole, twice, before the HDF5 library
 * refused them (a superblock version 0); a real superblock followed by
 * gigabytes of zeros was hashed whole and then read. Refused here: no
 * superblock after the signature, a version other than 2 or 3, an address
 * size HDF5 does not write, an end before the base, a file shorter than its
 * end (cut short), and bytes past the end over LAYER_SAMPLE_HOLE_MIN and over
 * half the file (the hole rule's bounds: HDF5 reads past a few, as a copy
 * with 8 KiB of sparse zeros after its end). GW_EFORMAT naming the file. */
#define LAYER_SAMPLE_HOLE_MIN (1ULL << 20)
static int h5_superblock_check(int fd, const char *path, int sb, unsigned long long at, unsigned long long size,
                               gw_err *err)
{
    if (sb < 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': truncated HDF5 file (signature only)", path);
    if (sb < 2)
        /* granwave writes its samples in the 1.8 format (layer-make, gw_h5_mem_create
         * with v18) and its other HDF5 outputs in the default one: a superblock
         * below 2 is another program's sample or an output that is no sample
         * (layer-impact's impact.h5 given as --sample said only "write it with
         * the 1.8 format") */
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 file without metadata checksums (superblock "
                          "version %d): not a sample granwave wrote (layer-make writes the 1.8 format; "
                          "impact.h5 and granwave's other HDF5 outputs are not samples); a sample written "
                          "elsewhere needs the 1.8 format or later, e.g. h5py libver='v108'", path, sb);
    if (sb > 3)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 superblock version %d, not one a sample is read in "
                          "(2 or 3, the 1.8 format and later): not a sample granwave wrote", path, sb);
    /* versions 2 and 3: signature, version, size of offsets, size of
     * lengths, flags, then the base, extension, end-of-file and root
     * addresses, little-endian */
    unsigned char b[12 + 4 * 32];
    const ssize_t got = pread(fd, b, sizeof b, (off_t)at);
    const int so = got >= 12 ? b[9] : 0;
    if (so != 2 && so != 4 && so != 8 && so != 16 && so != 32)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 superblock with %d-byte addresses (HDF5 writes 2, 4, "
                          "8, 16 or 32): corrupt, not a sample granwave wrote", path, so);
    unsigned long long addr[4] = {0, 0, 0, 0}; /* base, extension, end of file, root group's object header */
    int big = got < 12 + 4 * so;               /* the superblock cut short: no end to read */
    for (int a = 0; a < 4 && !big; a++)
        for (int k = so - 1; k >= 0 && !big; k--) {
            const unsigned char v = b[12 + a * so + k];
            big = k >= 8 && v != 0;
            addr[a] = k >= 8 ? addr[a] : addr[a] << 8 | v;
        }
    const unsigned long long base = addr[0], eof = addr[2];
    if (big || eof < base || eof - base > ~0ULL - at)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 superblock of base address %llu and end-of-file "
                          "address %llu%s: corrupt, not a sample granwave wrote", path, base, eof,
                          big ? " (or beyond 2^64)" : "");
    const unsigned long long end = at + (eof - base);
    if (end > size)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': %llu bytes, but its HDF5 superblock says the file ends at "
                          "byte %llu: cut short (a copy not finished?)", path, size, end);
    if (size - end > LAYER_SAMPLE_HOLE_MIN && size - end > size / 2)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': %llu bytes, but its HDF5 superblock says the file ends at "
                          "byte %llu, and %llu bytes follow it: not a sample granwave wrote", path, size, end,
                          size - end);
    /* the root group's object header, where the superblock says it is: a
     * superblock that claims a 4 GiB end in front of 4 GiB of written zeros
     * agrees with its size (the rules above compare the two and nothing
     * else), and the zeros were hashed whole before HDF5 found no root group.
     * A sample's root (the 1.8 format) is a version 2 header, "OHDR"; a
     * version 1 header (version byte 1, then 0) is taken too */
    /* its address is relative to the superblock (behind a user block of 512
     * bytes, a base of 512 and a root at 48 put the header at byte 560) */
    const unsigned long long root = addr[3];
    unsigned char oh[4] = {0, 0, 0, 0};
    const int inside = root < eof - base && eof - base - root >= 4;
    const ssize_t ohn = inside ? pread(fd, oh, sizeof oh, (off_t)(at + root)) : 0;
    if (ohn != (ssize_t)sizeof oh || !(memcmp(oh, "OHDR", 4) == 0 || (oh[0] == 1 && oh[1] == 0)))
        return gw_err_set(err, GW_EFORMAT, "sample '%s': its HDF5 superblock puts the root group at byte %llu, "
                          "where %s: corrupt, not a sample granwave wrote", path, at + root,
                          !inside ? "the file it describes has no room for one"
                                  : "no object header begins (no HDF5 metadata)");
    return GW_OK;
}

/* A sample file's holes (SEEK_HOLE: bytes never written, a sparse file's,
 * read as NUL bytes): GW_EFORMAT naming the file, its size and the first
 * hole's first byte, what ending the message ("not a text sample"); GW_OK
 * without one (or where the system cannot tell). A text sample holds no NUL
 * byte, so any hole refuses it; an HDF5 sample may hold zero runs as holes
 * (a sample granwave wrote, copied by cp --sparse=always, was refused for
 * its last 16 bytes), so only holes over half its bytes and over
 * LAYER_SAMPLE_HOLE_MIN refuse one: 4 GiB of sparse zeros after a superblock.
 * The read offset of fd is left as it was. */
static int hole_check(int fd, const char *path, int h5, const char *what, gw_err *err)
{
    struct stat st;
    unsigned long long hole = 0, bytes = 0;
    if (fstat(fd, &st) != 0 || !gw_input_holes(fd, &hole, h5 ? &bytes : NULL))
        return GW_OK;
    if (h5 && !(bytes > LAYER_SAMPLE_HOLE_MIN && bytes > (unsigned long long)st.st_size / 2))
        return GW_OK;
    if (h5)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': %llu bytes, %llu of them holes (never written, read as "
                          "NUL bytes: a sparse file) from byte %llu on: %s", path, (unsigned long long)st.st_size,
                          bytes, hole + 1, what);
    return gw_err_set(err, GW_EFORMAT, "sample '%s': %llu bytes, and its bytes from %llu on are a hole (never "
                      "written, read as NUL bytes: a sparse file): %s", path, (unsigned long long)st.st_size,
                      hole + 1, what);
}

/* A sample file opened for reading: a regular file only (a FIFO or a device
 * is refused before any read), at most LAYER_SAMPLE_FILE_MAX bytes (a sparse
 * 200 GB file was hashed whole, for minutes, before its first byte was
 * refused), its size at open in *size (LAYER_SAMPLE_FILE_MAX when fstat
 * fails: the most any read of it takes), its first bytes in pre (*npre of
 * them), *h5 1 when it is HDF5 (*sb its superblock version). The stream is
 * left at offset *npre. */
static int sample_open(const char *path, FILE **fp, unsigned char pre[8], size_t *npre, int *h5, int *sb,
                       unsigned long long *size, gw_err *err)
{
    *h5 = 0, *sb = -1, *npre = 0, *size = LAYER_SAMPLE_FILE_MAX;
    int rc = gw_input_open(path, "sample", fp, err);
    if (rc != GW_OK)
        return rc;
    struct stat st;
    if (fstat(fileno(*fp), &st) == 0)
        *size = st.st_size > 0 ? (unsigned long long)st.st_size : 0;
    if (*size > LAYER_SAMPLE_FILE_MAX) {
        fclose(*fp);
        *fp = NULL;
        return gw_err_set(err, GW_EFORMAT, "sample '%s': %llu bytes, larger than a sample file may be (%llu "
                          "bytes, 4 GiB): not a sample",
                          path, *size, LAYER_SAMPLE_FILE_MAX);
    }
    *npre = fread(pre, 1, 8, *fp);
    unsigned long long at = 0;
    *h5 = *npre == 8 && h5_signature_at(*fp, pre, sb, &at);
    /* an HDF5 sample mostly holes: 4 GiB of sparse zeros after a superblock
     * were hashed whole twice (a minute, three times by a sweep) before the
     * library refused the file (a text sample's holes: text_zeros_check);
     * then its superblock against its size, the same zeros written */
    rc = *h5 ? hole_check(fileno(*fp), path, 1, "not a sample granwave wrote", err) : GW_OK;
    if (rc == GW_OK && *h5)
        rc = h5_superblock_check(fileno(*fp), path, *sb, at, *size, err);
#if GW_HAVE_HDF5
    /* then the checksums of its superblock and root group (and datasets x,
     * y, r), by HDF5 itself: a copied superblock and root header in front of
     * 64 MiB of written zeros, its end address edited to match, passed the
     * rules above and was hashed whole before HDF5 refused it */
    if (rc == GW_OK && *h5)
        rc = layer_sample_h5_open_check(path, err);
#endif
    if (rc != GW_OK) {
        fclose(*fp);
        *fp = NULL;
    }
    return rc;
}

/* A text sample's zeros past the first 64 KiB, found without reading up to
 * them: a hole (SEEK_HOLE: bytes never written, a sparse file's) or a NUL
 * byte in its last ZEROS_TAIL bytes (a file extended or zero-filled after its
 * text). A valid header and particles over 64 KiB, then 4 GiB of sparse zeros,
 * passed the look at its head, were hashed whole by a sweep (seconds) and
 * refused by the reader only then. GW_OK, or GW_EFORMAT naming the file, its
 * size and the byte; the read offset of fd is left as it was. */
#define ZEROS_TAIL 4096
static int text_zeros_check(int fd, const char *path, gw_err *err)
{
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size <= 0)
        return GW_OK;
    const unsigned long long size = (unsigned long long)st.st_size;
    const int rc = hole_check(fd, path, 0, "not a text sample", err);
    if (rc != GW_OK)
        return rc;
    unsigned char tail[ZEROS_TAIL];
    const off_t from = st.st_size > ZEROS_TAIL ? st.st_size - ZEROS_TAIL : 0;
    const ssize_t got = pread(fd, tail, sizeof tail, from);
    const unsigned char *z = got > 0 ? memchr(tail, 0, (size_t)got) : NULL;
    if (z)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': %llu bytes, and its byte %llu is a NUL byte, near its end "
                          "(zeros after its text, or binary data): not a text sample", path, size,
                          (unsigned long long)from + (unsigned long long)(z - tail) + 1);
    return GW_OK;
}

/* layer_sample_file_check's rules, before any hash (*text: 1 for a text sample) */
static int sample_rules(const char *path, int *text, gw_err *err)
{
    FILE *fp = NULL;
    unsigned char pre[8];
    size_t npre;
    int h5, sb;
    unsigned long long size;
    int rc = sample_open(path, &fp, pre, &npre, &h5, &sb, &size, err);
    if (rc != GW_OK)
        return rc;
    *text = !h5;
    if (h5) {
        fclose(fp);
#if GW_HAVE_HDF5
        return GW_OK;
#else
        return gw_err_set(err, GW_EUNSUPPORTED, "sample '%s': an HDF5 file, and this granwave was built "
                          "without HDF5", path);
#endif
    }
    /* text: the reader refuses a NUL byte wherever it is; the first 64 KiB
     * are looked at here, then its holes and its last bytes
     * (text_zeros_check); the whole file is read by the reader alone */
    unsigned char buf[4096];
    long line = 1, left = 16;
    size_t got = npre;
    memcpy(buf, pre, npre);
    got += fread(buf + npre, 1, sizeof buf - npre, fp);
    while (got > 0) {
        for (size_t i = 0; i < got; i++) {
            if (buf[i] == 0) {
                fclose(fp);
                return gw_err_set(err, GW_EFORMAT, "sample '%s': line %ld: NUL byte (binary data, not a text "
                                  "sample)", path, line);
            }
            line += buf[i] == '\n';
        }
        got = --left > 0 ? fread(buf, 1, sizeof buf, fp) : 0;
    }
    rc = ferror(fp) ? gw_err_set(err, GW_EIO, "sample '%s': read failed", path) : GW_OK;
    if (rc == GW_OK)
        rc = text_zeros_check(fileno(fp), path, err);
    fclose(fp);
    return rc;
}

int layer_sample_file_check(const char *path, unsigned long long *h, gw_err *err)
{
    if (!path)
        return gw_err_set(err, GW_EINVAL, "layer_sample_file_check: path is NULL");
    int text = 0;
    const int rc = sample_rules(path, &text, err);
    if (rc != GW_OK || !h)
        return rc;
    /* the rest of a text sample read for a NUL byte in the pass that hashes
     * it: written zeros between its text and a last line (no hole) were hashed
     * whole, 4 GiB, and refused by the reader only then */
    return gw_fnv1a64_file_max(path, "sample", LAYER_SAMPLE_FILE_MAX, text, h, err);
}

int gw_layer_sample_read(const char *path, gw_layer_sample *s, gw_err *err)
{
    if (s) { /* emptied on every refusal, a NULL path's too (docs/library.md) */
        memset(s, 0, sizeof *s);
        s->mass_law = GW_LAYER_MASS_DISC;
    }
    if (!s || !path)
        return gw_err_set(err, GW_EINVAL, "gw_layer_sample_read: %s is NULL", !s ? "s" : "path");
    text_in t = {.path = path, .hash = GW_FNV1A64_INIT};
    int rc, sb = -1, h5 = 0;
    int orc = sample_open(path, &t.fp, t.pre, &t.npre, &h5, &sb, &t.size, err);
    if (orc != GW_OK)
        return orc;
    long *spr_lines = NULL;
    if (h5) {
        fclose(t.fp);
#if GW_HAVE_HDF5
        /* read by the library through its own open: hashed before and after,
         * a file changed in between refused (it was hashed after alone, over
         * bytes the read may not have seen) */
        unsigned long long h0 = 0;
        rc = gw_fnv1a64_file(path, "sample", &h0, err);
        if (rc == GW_OK)
            rc = layer_sample_h5_read(path, s, err);
        if (rc == GW_OK && (rc = gw_fnv1a64_file(path, "sample", &s->content_hash, err)) == GW_OK &&
            s->content_hash != h0)
            rc = gw_err_set(err, GW_EIO, "sample '%s': the file changed while it was read (its content hash "
                            "%016llx before, %016llx after): read it again once it is written", path, h0,
                            s->content_hash);
#else
        (void)sb;
        rc = gw_err_set(err, GW_EUNSUPPORTED, "sample '%s': an HDF5 file, and this granwave was built "
                        "without HDF5", path);
#endif
    } else {
        rc = read_text(&t, s, err);
        free(t.set);
        spr_lines = t.spr_lines;
        /* the content hash of the bytes read, to the end the parse reached
         * (read on to it where the parse stopped short, as the whole file
         * was hashed before) */
        while (rc == GW_OK && text_getc(&t) != EOF)
            ;
        if (rc == GW_OK && ferror(t.fp))
            rc = gw_err_set(err, GW_EIO, "sample '%s': read failed", path);
        /* more bytes than its size at open: whatever the parse said of the
         * bytes it saw (cut at that size, or read on), the file is still
         * being written (or no file on disk) */
        if (t.grew)
            rc = gw_io_grew("sample", path, t.size, err);
        if (rc == GW_OK)
            s->content_hash = t.hash;
        fclose(t.fp);
    }
    if (rc == GW_OK) /* the limits every sample is held to, in memory too: its deep overlaps last */
        rc = layer_sample_limits_check(s, path, GW_EFORMAT, err);
    /* the springs last, under the settling's record (its Coulomb bound): a
     * file whose particles are refused says so first */
    if (rc == GW_OK)
        rc = layer_springs_check(s, path, spr_lines, GW_EFORMAT, err);
    free(spr_lines);
    if (rc != GW_OK) {
        gw_layer_sample_free(s);
        memset(s, 0, sizeof *s);
    }
    return rc;
}

size_t gw_layer_sample_size(void)
{
    return sizeof(gw_layer_sample);
}
