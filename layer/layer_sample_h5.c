/*
 * layer_sample_h5.c: the HDF5 layer samples (docs/physics.md 2.2; format in
 * gw_layer.h), when granwave is built with HDF5: datasets x, y, r [n] (m),
 * body [n] for clump samples, and the header as attributes of the root group,
 * written atomically (gw_afile) and read back with the checks of
 * layer_sample_check.c, the same as a text sample's. Only files with metadata
 * checksums (superblock version 2 or later) are opened, and HDF5's own error
 * printing is replaced by a recorded message (gw_err).
 * Units: SI (m); the file's and each coordinate dataset's units attribute say
 * so, and a reader refuses others.
 */
#include "layer_sample_impl.h"
#if GW_HAVE_HDF5
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <hdf5.h>
#include "gw_h5.h"
#include "gw_locale.h"

/* the units attributes of an HDF5 sample: the file's, and each coordinate
 * dataset's (x, y, r); a reader refuses others (h5_units_check) */
#define SAMPLE_H5_UNITS "SI: x, y, r, width, rm in metres"
#define SAMPLE_H5_COLUMN_UNITS "m"

/* HDF5 prints its error stack by default. While granwave calls it (a
 * gw_h5_section, gw_h5.h), a handler records the most specific message of the
 * first failure instead (for gw_err). */
typedef struct h5_quiet {
    char why[160];
    int nomem; /* a failed allocation in HDF5: "out of memory" */
} h5_quiet;

static herr_t h5_innermost(unsigned k, const H5E_error2_t *e, void *ctx)
{
    char *why = ctx;
    if (k == 0 && e->desc) {
        gw_snprintf(why, 160, "%s", e->desc);
        for (char *p = why; *p; p++)
            if (*p == '\n' || *p == '\r')
                *p = ' ';
    }
    return 0;
}

static herr_t h5_record(hid_t stack, void *ctx)
{
    h5_quiet *q = ctx;
    char *why = q->why;
    if (gw_h5_stack_nomem(stack))
        q->nomem = 1;
    if (!why[0])
        H5Ewalk2(stack, H5E_WALK_UPWARD, h5_innermost, why);
    if (!why[0])
        gw_snprintf(why, 160, "HDF5 call failed");
    return 0;
}

/* A section of HDF5 calls with h5_record as its handler. */
static void h5_enter(gw_h5_section *sec, h5_quiet *q)
{
    q->why[0] = '\0';
    q->nomem = 0;
    gw_h5_enter(sec, h5_record, q);
}

static int h5_attr_write(hid_t loc, const char *name, hid_t type, const void *v)
{
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = sp < 0 ? -1 : H5Acreate2(loc, name, type, sp, H5P_DEFAULT, H5P_DEFAULT);
    int bad = a < 0 || H5Awrite(a, type, v) < 0;
    if (a >= 0)
        H5Aclose(a);
    if (sp >= 0)
        H5Sclose(sp);
    return bad;
}

/* A fixed-length string attribute; cut at 16 kB, well below the 64 kB an
 * object header can hold, so a long command line cannot fail the write. */
static int h5_attr_write_str(hid_t loc, const char *name, const char *v)
{
    size_t len = strnlen(v, 16384);
    char *copy = malloc(len + 1);
    hid_t t = H5Tcopy(H5T_C_S1);
    int bad = !copy || t < 0 || H5Tset_size(t, len + 1) < 0;
    if (!bad) {
        memcpy(copy, v, len);
        copy[len] = '\0';
        bad = h5_attr_write(loc, name, t, copy);
    }
    free(copy);
    if (t >= 0)
        H5Tclose(t);
    return bad;
}

static int h5_column_write(hid_t f, const char *name, const double *v, int n)
{
    hsize_t dim = (hsize_t)n;
    hid_t sp = H5Screate_simple(1, &dim, NULL);
    hid_t d = sp < 0 ? -1 : H5Dcreate2(f, name, H5T_IEEE_F64LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    int bad = d < 0 || H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0 ||
              h5_attr_write_str(d, "units", SAMPLE_H5_COLUMN_UNITS);
    if (d >= 0)
        H5Dclose(d);
    if (sp >= 0)
        H5Sclose(sp);
    return bad;
}

/* The rigid-body ids of a clump sample as 32-bit integers. */
static int h5_body_write(hid_t f, const int *v, int n)
{
    hsize_t dim = (hsize_t)n;
    hid_t sp = H5Screate_simple(1, &dim, NULL);
    hid_t d = sp < 0 ? -1 : H5Dcreate2(f, "body", H5T_STD_I32LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    int bad = d < 0 || H5Dwrite(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0;
    if (d >= 0)
        H5Dclose(d);
    if (sp >= 0)
        H5Sclose(sp);
    return bad;
}

/* The springs as three datasets of m values: spring_a, spring_b (32-bit
 * integers; b < 0 a wall, GW_LAYER_SPRING_*) and spring_u (m). */
static int h5_springs_write(hid_t f, const gw_layer_sample *s)
{
    const int m = s->n_springs;
    int *ab = malloc(2 * (size_t)m * sizeof *ab);
    double *u = malloc((size_t)m * sizeof *u);
    int bad = !ab || !u;
    for (int k = 0; !bad && k < m; k++)
        ab[k] = s->springs[k].a, ab[m + k] = s->springs[k].b, u[k] = s->springs[k].u;
    hsize_t dim = (hsize_t)m;
    hid_t sp = bad ? -1 : H5Screate_simple(1, &dim, NULL);
    for (int j = 0; j < 2 && !bad; j++) {
        hid_t d = sp < 0 ? -1 : H5Dcreate2(f, j ? "spring_b" : "spring_a", H5T_STD_I32LE, sp, H5P_DEFAULT,
                                           H5P_DEFAULT, H5P_DEFAULT);
        bad = d < 0 || H5Dwrite(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, ab + j * (size_t)m) < 0;
        if (d >= 0)
            H5Dclose(d);
    }
    if (sp >= 0)
        H5Sclose(sp);
    bad = bad || h5_column_write(f, "spring_u", u, m);
    free(ab);
    free(u);
    return bad;
}

/* Written under a temporary name through gw_afile (signals held, fsync, rename
 * on commit): HDF5 creates the temporary by name (gw_afile_open_named). The
 * 1.8 file format (superblock 2) puts checksums on all metadata (see read_h5). */
static int write_h5_locked(const gw_layer_sample *s, const char *path, const char *header,
                           const h5_quiet *q, gw_err *err)
{
    int version = 1, n = s->n;
    gw_h5_mem mem;
    hid_t file = gw_h5_mem_create(&mem, path, 1); /* in memory, written as one image (gw_h5.h) */
    int bad = file < 0 || h5_column_write(file, "x", s->x, n) || h5_column_write(file, "y", s->y, n) ||
              h5_column_write(file, "r", s->r, n) || h5_attr_write_str(file, "format", SAMPLE_MAGIC) ||
              h5_attr_write(file, "format_version", H5T_NATIVE_INT, &version) ||
              h5_attr_write_str(file, "granwave_version", gw_version()) ||
              h5_attr_write(file, "width", H5T_NATIVE_DOUBLE, &s->width) ||
              h5_attr_write(file, "rm", H5T_NATIVE_DOUBLE, &s->rm) ||
              h5_attr_write(file, "volume_ratio", H5T_NATIVE_DOUBLE, &s->volume_ratio) ||
              (!isnan(s->porosity) && h5_attr_write(file, "porosity", H5T_NATIVE_DOUBLE, &s->porosity)) ||
              h5_attr_write(file, "seed", H5T_NATIVE_LONG, &s->seed) ||
              h5_attr_write_str(file, "mass_law", s->mass_law == GW_LAYER_MASS_SPHERE ? "sphere" : "disc") ||
              (s->clump_mass == GW_LAYER_CLUMP_MASS_UNION && h5_attr_write_str(file, "clump_mass", gw_layer_clump_mass_name(s->clump_mass))) ||
              h5_attr_write(file, "n", H5T_NATIVE_INT, &n) ||
              h5_attr_write_str(file, "units", SAMPLE_H5_UNITS) ||
              (header && h5_attr_write_str(file, "header", header)) ||
              (s->body && h5_body_write(file, s->body, n)) ||
              (s->n_springs > 0 && h5_springs_write(file, s));
    int rc = GW_OK;
    if (bad) {
        int nomem = q->nomem;
        if (file >= 0)
            gw_h5_mem_abort(&mem);
        rc = nomem ? gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory", path)
                   : gw_err_set(err, GW_EIO, "sample '%s': HDF5 write failed%s%s", path, q->why[0] ? ": " : "", q->why);
    } else {
        rc = gw_h5_mem_write(&mem, path, err);
    }
    return rc;
}

/* one section of HDF5 calls (gw_h5.h): HDF5 and its error handler, one thread at a time */
int layer_sample_h5_write(const gw_layer_sample *s, const char *path, const char *header, gw_err *err)
{
    gw_h5_section sec;
    h5_quiet q;
    h5_enter(&sec, &q);
    int rc = write_h5_locked(s, path, header, &q, err);
    gw_h5_leave(&sec);
    return rc;
}

/* An attribute's handles closed: a, its dataspace sp and type t (-1: none) */
static void attr_close(hid_t a, hid_t sp, hid_t t)
{
    if (t >= 0)
        H5Tclose(t);
    if (sp >= 0)
        H5Sclose(sp);
    if (a >= 0)
        H5Aclose(a);
}

/* A scalar root attribute of class want (H5T_FLOAT also takes integers; a
 * string goes into char[64]) read as memtype: 0 absent, 1 read, -1 malformed. */
static int h5_attr_read(hid_t f, const char *name, H5T_class_t want, hid_t memtype, void *out)
{
    htri_t ex = H5Aexists(f, name);
    if (ex == 0)
        return 0;
    hid_t a = ex > 0 ? H5Aopen(f, name, H5P_DEFAULT) : -1;
    hid_t t = a >= 0 ? H5Aget_type(a) : -1, sp = a >= 0 ? H5Aget_space(a) : -1;
    H5T_class_t cls = t >= 0 ? H5Tget_class(t) : H5T_NO_CLASS;
    int ok = sp >= 0 && H5Sget_simple_extent_type(sp) == H5S_SCALAR &&
             (cls == want || (want == H5T_FLOAT && cls == H5T_INTEGER));
    if (ok && want == H5T_STRING) { /* fixed or variable length */
        char *vs = NULL;
        htri_t var = H5Tis_variable_str(t);
        size_t size = H5Tget_size(t);
        hid_t mt = H5Tcopy(H5T_C_S1);
        ok = var >= 0 && mt >= 0 && (var > 0 || (size > 0 && size < 64)) &&
             H5Tset_size(mt, var > 0 ? H5T_VARIABLE : 64) >= 0 && H5Tset_cset(mt, H5Tget_cset(t)) >= 0 &&
             H5Tset_strpad(mt, H5T_STR_NULLTERM) >= 0 && H5Aread(a, mt, var > 0 ? (void *)&vs : out) >= 0;
        if (ok && var > 0) {
            ok = vs && strlen(vs) < 64;
            if (ok)
                memcpy(out, vs, strlen(vs) + 1);
        }
        if (vs)
            H5free_memory(vs);
        if (mt >= 0)
            H5Tclose(mt);
        if (ok)
            ((char *)out)[63] = '\0';
    } else if (ok) {
        ok = H5Aread(a, memtype, out) >= 0;
    }
    attr_close(a, sp, t);
    return ok ? 1 : -1;
}

/* Where the data of dataset name lies: 1 in the file itself (a hard link to a
 * dataset whose layout is compact, contiguous or chunked in this file), 0
 * elsewhere (an external or user-defined link, raw data in external files, a
 * virtual dataset), -1 unknown. Data outside the file would be read through a
 * path the file names: a FIFO there hung the reader, /dev/zero gave zeros,
 * a superblock-0 file there skipped the checksum rule of read_h5, and the
 * sample's content hash (its own bytes) would not cover what was read. */
static int h5_in_file(hid_t f, const char *name, const char **what)
{
    H5L_info_t li;
    *what = "";
    if (H5Lget_info(f, name, &li, H5P_DEFAULT) < 0)
        return -1;
    if (li.type != H5L_TYPE_HARD) {
        *what = li.type == H5L_TYPE_SOFT ? "a soft link" : li.type == H5L_TYPE_EXTERNAL ? "an external link"
                : "a user-defined link";
        return 0;
    }
    hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
    hid_t pl = d >= 0 ? H5Dget_create_plist(d) : -1;
    int in = -1;
    if (pl >= 0) {
        const int next = H5Pget_external_count(pl);
        const H5D_layout_t lay = H5Pget_layout(pl);
        in = next == 0 && (lay == H5D_COMPACT || lay == H5D_CONTIGUOUS || lay == H5D_CHUNKED);
        *what = next != 0 ? "stored in external files" : lay == H5D_VIRTUAL ? "a virtual dataset" : "";
    }
    if (pl >= 0)
        H5Pclose(pl);
    if (d >= 0)
        H5Dclose(d);
    return in;
}

/* The units attribute of loc (the file, or dataset name), when there is one,
 * must be want, the units granwave writes and reads the values in: a sample
 * converted to millimetres with its units attribute saying "mm" ran as metres
 * (a 1000 times larger box, block and particles), exit 0. Absent: the values
 * are taken as SI, as the format says. */
static int h5_attrs_scalar(hid_t loc, const char *name, const char *path, gw_err *err);
static int h5_units_check(hid_t loc, const char *name, const char *want, const char *path, gw_err *err)
{
    char str[64], show[48];
    if (name && h5_attrs_scalar(loc, name, path, err) != GW_OK)
        return GW_EFORMAT;
    const int got = h5_attr_read(loc, "units", H5T_STRING, -1, str);
    if (got == 0 || (got == 1 && strcmp(str, want) == 0))
        return GW_OK;
    char what[96];
    if (got < 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute units of %s%s%s is not one string "
                          "(granwave writes '%s')", path, name ? "dataset '" : "the file", name ? name : "",
                          name ? "'" : "", want);
    if (name)
        gw_snprintf(what, sizeof what, "HDF5 dataset '%s' has units", name);
    else
        gw_snprintf(what, sizeof what, "HDF5 attribute units is");
    return gw_err_set(err, GW_EFORMAT, "sample '%s': %s '%s', not '%s': the values are read in metres, as "
                      "granwave writes them (convert them, and their units)", path, what, layer_sample_shown(str, show), want);
}

/* Dataset name: one dimension of n numbers, read as doubles into v (NULL:
 * checked only, nothing read); its units attribute, when it has one, must be
 * units (NULL: not checked). */
static int h5_column_read(hid_t f, const char *name, long n, double *v, const char *units, const char *path,
                          const char *why, gw_err *err)
{
    htri_t ex = H5Lexists(f, name, H5P_DEFAULT);
    const char *where = "";
    const int in = ex > 0 ? h5_in_file(f, name, &where) : -1;
    if (in == 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset '%s' is %s: a sample holds its data in "
                          "the file itself (hard links, no external storage)", path, name, where);
    hid_t d = in > 0 ? H5Dopen2(f, name, H5P_DEFAULT) : -1;
    if (d < 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset '%s' %s%s%s", path, name,
                          ex == 0 ? "missing" : "unreadable", why[0] ? ": " : "", why);
    hid_t sp = H5Dget_space(d), t = H5Dget_type(d);
    hsize_t dim = 0;
    H5T_class_t cls = t >= 0 ? H5Tget_class(t) : H5T_NO_CLASS;
    int shape = sp >= 0 && H5Sget_simple_extent_ndims(sp) == 1 && H5Sget_simple_extent_dims(sp, &dim, NULL) == 1;
    int rc = GW_OK;
    if (!shape || (cls != H5T_FLOAT && cls != H5T_INTEGER))
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset '%s' must be a 1-D array of numbers",
                        path, name);
    else if (dim != (hsize_t)n)
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset '%s' has %llu values, n = %ld", path, name,
                        (unsigned long long)dim, n);
    else if (units && h5_units_check(d, name, units, path, err) != GW_OK)
        rc = GW_EFORMAT;
    else if (v && H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0)
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset '%s' unreadable: %s", path, name, why);
    if (t >= 0)
        H5Tclose(t);
    if (sp >= 0)
        H5Sclose(sp);
    H5Dclose(d);
    return rc;
}

/* The "header" attribute (a string, as written at most 16 kB; NULL when
 * absent) into *out (owned); GW_EFORMAT when it is not one string. */
static int h5_header_read(hid_t f, char **out, const char *path, gw_err *err)
{
    *out = NULL;
    htri_t ex = H5Aexists(f, "header");
    if (ex == 0)
        return GW_OK;
    hid_t a = ex > 0 ? H5Aopen(f, "header", H5P_DEFAULT) : -1;
    hid_t t = a >= 0 ? H5Aget_type(a) : -1, sp = a >= 0 ? H5Aget_space(a) : -1;
    htri_t var = t >= 0 ? H5Tis_variable_str(t) : -1;
    size_t size = t >= 0 ? H5Tget_size(t) : 0;
    int ok = sp >= 0 && H5Sget_simple_extent_type(sp) == H5S_SCALAR && H5Tget_class(t) == H5T_STRING && var >= 0 &&
             (var > 0 || (size > 0 && size <= 65536));
    char *vs = NULL, *buf = ok && var == 0 ? malloc(size + 1) : NULL;
    int nomem = ok && var == 0 && !buf;
    size_t nul_at = 0;
    hid_t mt = -1;
    if (nomem)
        ok = 0;
    if (ok && var > 0) { /* a variable-length string: copied out of HDF5's memory */
        mt = H5Tcopy(H5T_C_S1);
        ok = mt >= 0 && H5Tset_size(mt, H5T_VARIABLE) >= 0 && H5Aread(a, mt, (void *)&vs) >= 0;
        size_t len = ok && vs ? strnlen(vs, 65537) : 0;
        ok = ok && vs && len <= 65536;
        if (ok && !(buf = malloc(len + 1)))
            nomem = 1, ok = 0;
        if (ok)
            memcpy(buf, vs, len), buf[len] = '\0';
    } else if (ok) {
        /* A fixed-length string, read as its own bytes (the file's type, no
         * conversion) and ended here by its padding: trailing spaces for
         * space-padded, the first NUL otherwise. HDF5's conversion to a C
         * string ended it at a NUL inside, and what followed (the settings
         * line with the settling's record) was dropped silently, so the
         * impact ran unchecked: NULs may only pad the end. */
        ok = H5Aread(a, t, buf) >= 0;
        size_t len = size;
        if (ok && H5Tget_strpad(t) == H5T_STR_SPACEPAD)
            while (len > 0 && buf[len - 1] == ' ')
                len--;
        const char *z = ok ? memchr(buf, '\0', len) : NULL;
        for (const char *c = z; c && c < buf + len; c++)
            if (*c != '\0') {
                nul_at = (size_t)(z - buf) + 1, ok = 0;
                break;
            }
        if (ok)
            buf[z ? (size_t)(z - buf) : len] = '\0';
    }
    if (vs)
        H5free_memory(vs);
    if (mt >= 0)
        H5Tclose(mt);
    attr_close(a, sp, t);
    if (!ok) {
        free(buf);
        if (nul_at)
            return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute header has a NUL byte at byte %zu of "
                              "its %zu, text after it: a header is text (what follows a NUL would be lost)", path,
                              nul_at, size);
        return nomem ? gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for its header attribute", path)
                     : gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute header is not one string of at "
                                  "most 65536 bytes", path);
    }
    *out = buf;
    return GW_OK;
}

/* The settling's record (gw_layer_settled) from the header attribute's line
 * "settings: {JSON}" (layer_sample_settings.c). The writer cuts the header at
 * 16 kB: a settings line cut there (the header that long, the line its last)
 * is not recorded rather than refused. */
static int h5_settings_read(hid_t f, gw_layer_sample *s, const char *path, gw_err *err)
{
    char *h;
    int rc = h5_header_read(f, &h, path, err);
    if (rc != GW_OK || !h)
        return rc;
    static const char key[] = "settings:";
    char *line = NULL;
    int unsettled = 0, converged = 0;
    for (char *p = h; p && *p; p = strchr(p, '\n'), p = p ? p + 1 : NULL) {
        char one[128]; /* the line alone, as far as "converged N" (the text reader's too) */
        const size_t l = strcspn(p, "\n");
        gw_snprintf(one, sizeof one, "%.*s", (int)(l < sizeof one - 1 ? l : sizeof one - 1), p);
        unsettled |= layer_sample_settled_unsettled(one); /* the "settled:" line: converged 0 */
        converged |= layer_sample_settled_converged(one);
        if (strncmp(p, key, sizeof key - 1) != 0)
            continue;
        if (line) {
            free(h);
            return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute header: a second settings line: "
                              "layer-make writes one", path);
        }
        line = p + sizeof key - 1;
    }
    char *nl = line ? strchr(line, '\n') : NULL;
    if (nl)
        *nl = '\0';
    const int cut = line && !nl && strlen(h) >= 16384;
    if (line && !cut)
        {
        const hdr_src src = {.h5 = 1};
        rc = layer_sample_settings_parse(line, path, "HDF5 attribute header", s, &src, &s->settled, err);
    }
    if (rc == GW_OK) /* after the settings' parse, which zeroes the record */
        s->settled.unsettled = unsettled, s->settled_converged = converged && !unsettled;
    free(h);
    return rc;
}

/* The springs when the file has them (spring_u, with spring_a and
 * spring_b of as many values), checked for form here and for sense by
 * layer_springs_check once the settling's record is read. */
static int h5_springs_read(hid_t f, gw_layer_sample *s, const char *path, const char *why, gw_err *err)
{
    const char *names[3] = {"spring_a", "spring_b", "spring_u"};
    int have = 0;
    for (int j = 0; j < 3; j++)
        have += H5Lexists(f, names[j], H5P_DEFAULT) > 0;
    if (have == 0)
        return GW_OK;
    if (have != 3)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 datasets spring_a, spring_b and spring_u go "
                          "together (the file has %d of them)", path, have);
    /* each a dataset of this file before any is opened: opening spring_u to
     * learn its length followed an external link, and HDF5 opened the file it
     * names, a FIFO without a writer blocking the read for ever (the particles'
     * columns were checked so before they were opened, the springs' only
     * after) */
    for (int j = 0; j < 3; j++) {
        const char *where = "";
        const int in = h5_in_file(f, names[j], &where);
        if (in == 0) /* (-1, not a dataset: said below, as of the particles) */
            return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset '%s' is %s: a sample holds its data in "
                              "the file itself (hard links, no external storage)", path, names[j], where);
    }
    /* the length from spring_u (h5_column_read then checks all three) */
    hid_t d = H5Dopen2(f, "spring_u", H5P_DEFAULT), sp = d >= 0 ? H5Dget_space(d) : -1;
    hsize_t dim = 0;
    const int ok = sp >= 0 && H5Sget_simple_extent_ndims(sp) == 1 && H5Sget_simple_extent_dims(sp, &dim, NULL) == 1;
    if (sp >= 0)
        H5Sclose(sp);
    if (d >= 0)
        H5Dclose(d);
    const long most = LAYER_SPRINGS_MOST(s->n);
    if (!ok || dim > (hsize_t)most)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset 'spring_u' must be a 1-D array of at most "
                          "%ld numbers (8 (n + 1) contacts)", path, most);
    const long m = (long)dim;
    if (m == 0)
        return GW_OK;
    double *v = malloc(3 * (size_t)m * sizeof *v);
    s->springs = malloc((size_t)m * sizeof *s->springs);
    if (!v || !s->springs) {
        free(v);
        return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for %ld springs", path, m);
    }
    int rc = GW_OK;
    for (int j = 0; j < 3 && rc == GW_OK; j++)
        rc = h5_column_read(f, names[j], m, v + j * m, j == 2 ? SAMPLE_H5_COLUMN_UNITS : NULL, path, why, err);
    for (long k = 0; rc == GW_OK && k < m; k++) {
        const double a = v[k], b = v[m + k];
        if (!(a >= 0 && a < s->n && a == floor(a)) ||
            !(b >= GW_LAYER_SPRING_BOTTOM && b < s->n && b == floor(b)))
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 spring at index %ld: pair %g %g is not a particle "
                            "index in [0, %d) and an index or a wall (-1 left, -2 right, -3 bottom)", path, k, a,
                            b, s->n);
        else
            s->springs[k] = (gw_layer_spring){.a = (int)a, .b = (int)b, .u = v[2 * m + k]};
    }
    free(v);
    if (rc == GW_OK)
        s->n_springs = (int)m;
    return rc;
}

/* The attributes the reader takes (the file's; dataset name's units when name
 * is not NULL) are scalars, as granwave writes them. A one-element array (shape
 * (1,), or (1, 1)) was read as its element, so n = [5] ran as n = 5 while the
 * format says a scalar: refused, naming the attribute and its shape. */
static int h5_attrs_scalar(hid_t loc, const char *name, const char *path, gw_err *err)
{
    static const char *const root[] = {"format", "format_version", "width", "rm", "volume_ratio", "porosity",
                                       "seed", "mass_law", "clump_mass", "n", "header", "units", NULL};
    static const char *const dset[] = {"units", NULL};
    for (const char *const *a = name ? dset : root; *a; a++) {
        if (H5Aexists(loc, *a) <= 0)
            continue; /* absent (or unreadable: the read names it) */
        hid_t at = H5Aopen(loc, *a, H5P_DEFAULT), sp = at >= 0 ? H5Aget_space(at) : -1;
        const H5S_class_t cls = sp >= 0 ? H5Sget_simple_extent_type(sp) : H5S_NO_CLASS;
        hsize_t dims[4] = {0};
        const int rank = cls == H5S_SIMPLE ? H5Sget_simple_extent_dims(sp, dims, NULL) : 0;
        if (sp >= 0)
            H5Sclose(sp);
        if (at >= 0)
            H5Aclose(at);
        if (cls == H5S_SCALAR || sp < 0)
            continue;
        char shape[96] = "no value (a null dataspace)";
        if (cls == H5S_SIMPLE && rank >= 1 && rank <= 4) {
            size_t at_c = (size_t)gw_snprintf(shape, sizeof shape, "an array of shape (");
            for (int d = 0; d < rank && at_c < sizeof shape; d++)
                at_c += (size_t)gw_snprintf(shape + at_c, sizeof shape - at_c, "%llu%s",
                                            (unsigned long long)dims[d], rank == 1 ? ",)" : d + 1 < rank ? ", " : ")");
        } else if (cls == H5S_SIMPLE) {
            gw_snprintf(shape, sizeof shape, "an array of rank %d", rank);
        }
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute '%s'%s%s%s is %s, not a scalar (granwave "
                          "writes and reads its attributes as scalars: store the value itself, not a list of one)",
                          path, *a, name ? " of dataset '" : "", name ? name : "", name ? "'" : "", shape);
    }
    return GW_OK;
}

static int h5_fields(hid_t f, gw_layer_sample *s, const char *path, const char *why, gw_err *err)
{
    char str[64], show[48];
    long long ver = 0, n = 0, seed = 0;
    int shape = h5_attrs_scalar(f, NULL, path, err);
    if (shape != GW_OK)
        return shape;
    int got = h5_attr_read(f, "format", H5T_STRING, -1, str);
    if (got < 0 && why[0])
        return gw_err_set(err, GW_EFORMAT, "sample '%s': corrupt HDF5 file (%s)", path, why);
    if (got != 1 || strcmp(str, SAMPLE_MAGIC) != 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 file is not a granwave layer sample (no "
                          "attribute format = '" SAMPLE_MAGIC "')", path);
    if (h5_attr_read(f, "format_version", H5T_INTEGER, H5T_NATIVE_LLONG, &ver) != 1 || ver != 1)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute format_version (%lld) missing or "
                          "unsupported (this build reads 1)", path, ver);
    const struct {
        const char *name;
        double *v;
        int required;
    } num[] = {{"width", &s->width, 1}, {"rm", &s->rm, 1}, {"volume_ratio", &s->volume_ratio, 0},
               {"porosity", &s->porosity, 0}};
    s->porosity = NAN; /* absent: unknown */
    for (size_t k = 0; k < sizeof num / sizeof num[0]; k++) {
        got = h5_attr_read(f, num[k].name, H5T_FLOAT, H5T_NATIVE_DOUBLE, num[k].v);
        if (got < 0 || (got == 0 && num[k].required) || (got == 1 && !isfinite(*num[k].v)))
            return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute '%s' %s", path, num[k].name,
                              got < 0 ? "is not one number" : got == 0 ? "missing" : "is not a finite number");
    }
    /* read twice, signed and unsigned: HDF5 converts an out-of-range integer to
     * the nearest one it can hold, so a uint64 seed above 2^63 was read as
     * 2^63 - 1 and a negative one ran; the two reads agree only in range */
    unsigned long long useed = 0;
    got = h5_attr_read(f, "seed", H5T_INTEGER, H5T_NATIVE_LLONG, &seed);
    if (got == 1)
        got = h5_attr_read(f, "seed", H5T_INTEGER, H5T_NATIVE_ULLONG, &useed);
    if (got < 0 || (got == 1 && (seed < 0 || seed > LONG_MAX || (unsigned long long)seed != useed)))
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute 'seed' is not one integer in [0, %ld] "
                          "(layer-make's seeds are in [0, 9e18])", path, LONG_MAX);
    s->seed = (long)seed;
    got = h5_attr_read(f, "mass_law", H5T_STRING, -1, str);
    if (got < 0 || (got > 0 && strcmp(str, "disc") != 0 && strcmp(str, "sphere") != 0))
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute mass_law '%s' is not disc or sphere",
                          path, got > 0 ? layer_sample_shown(str, show) : "?");
    s->mass_law = got > 0 && strcmp(str, "sphere") == 0 ? GW_LAYER_MASS_SPHERE : GW_LAYER_MASS_DISC;
    got = h5_attr_read(f, "clump_mass", H5T_STRING, -1, str);
    s->clump_mass = got > 0 ? gw_layer_clump_mass_parse(str) : GW_LAYER_CLUMP_MASS_SUM;
    if (got < 0 || s->clump_mass < 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute clump_mass '%s' is not sum or union",
                          path, got > 0 ? layer_sample_shown(str, show) : "?");
    got = h5_attr_read(f, "n", H5T_INTEGER, H5T_NATIVE_LLONG, &n);
    if (got != 1) /* it said "n = 0" for a missing n, a string or a float */
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute 'n' %s", path,
                          got == 0 ? "missing" : "is not one integer");
    if (n < 1 || n > SAMPLE_NMAX)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 attribute n = %lld must be an integer in [1, %ld]",
                          path, n, SAMPLE_NMAX);
    int rc = layer_sample_header_check(s, path, GW_EFORMAT, err);
    if (rc != GW_OK)
        return rc;
    /* the columns' lengths against n before n is allocated: a 7 kB file whose
     * n was edited to 1e7 took 240 MB first, and under a memory limit was
     * "out of memory for 10000000 particles" (exit 1) rather than a file whose
     * x holds 40 values */
    if ((rc = h5_units_check(f, NULL, SAMPLE_H5_UNITS, path, err)) != GW_OK ||
        (rc = h5_column_read(f, "x", (long)n, NULL, SAMPLE_H5_COLUMN_UNITS, path, why, err)) != GW_OK ||
        (rc = h5_column_read(f, "y", (long)n, NULL, SAMPLE_H5_COLUMN_UNITS, path, why, err)) != GW_OK ||
        (rc = h5_column_read(f, "r", (long)n, NULL, SAMPLE_H5_COLUMN_UNITS, path, why, err)) != GW_OK ||
        (H5Lexists(f, "body", H5P_DEFAULT) > 0 &&
         (rc = h5_column_read(f, "body", (long)n, NULL, NULL, path, why, err)) != GW_OK))
        return rc;
    s->x = malloc(3 * (size_t)n * sizeof *s->x);
    if (!s->x)
        return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for %lld particles", path, n);
    s->y = s->x + n, s->r = s->x + 2 * n;
    s->n = (int)n;
    if ((rc = h5_column_read(f, "x", (long)n, s->x, SAMPLE_H5_COLUMN_UNITS, path, why, err)) != GW_OK ||
        (rc = h5_column_read(f, "y", (long)n, s->y, SAMPLE_H5_COLUMN_UNITS, path, why, err)) != GW_OK ||
        (rc = h5_column_read(f, "r", (long)n, s->r, SAMPLE_H5_COLUMN_UNITS, path, why, err)) != GW_OK)
        return rc;
    if (H5Lexists(f, "body", H5P_DEFAULT) > 0) { /* a clump sample: ids read as numbers, then checked */
        double *v = malloc((size_t)n * sizeof *v);
        s->body = malloc((size_t)n * sizeof *s->body);
        if (!v || !s->body) {
            free(v);
            return gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory for %lld body ids", path, n);
        }
        rc = h5_column_read(f, "body", (long)n, v, NULL, path, why, err);
        for (long long i = 0; rc == GW_OK && i < n; i++) {
            if (!(v[i] >= 0 && v[i] < (double)n && v[i] == floor(v[i])))
                rc = gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset 'body': value %g at index %lld is "
                                "not an integer in [0, %lld)", path, v[i], i, n);
            else
                s->body[i] = (int)v[i];
        }
        free(v);
        if (rc != GW_OK)
            return rc;
    }
    const hdr_src src = {.h5 = 1};
    rc = layer_sample_check(s, path, &src, GW_EFORMAT, err);
    if (rc == GW_OK)
        rc = h5_settings_read(f, s, path, err);
    /* (their sense is checked last, by gw_layer_sample_read) */
    return rc == GW_OK ? h5_springs_read(f, s, path, why, err) : rc;
}

/* libhdf5 decodes metadata without bounds checks, so a corrupt file can crash
 * it (memory errors found by fuzzing 1.10.8 with superblock-0 files).
 * Superblocks from version 2 on (HDF5 1.8 format and later) come with
 * checksums on all metadata, which HDF5 verifies before decoding: only those
 * files are opened (the superblock's version is checked where the file is
 * opened, before it is hashed: h5_superblock_check, layer_sample.c). */
static int read_h5_locked(const char *path, gw_layer_sample *s, const h5_quiet *q, gw_err *err)
{
    int rc;
    /* strong close: H5Fclose also closes what a failed read left open */
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    hid_t f = fapl < 0 || H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG) < 0 ? -1 :
              H5Fopen(path, H5F_ACC_RDONLY, fapl);
    if (f < 0) {
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': corrupt or truncated HDF5 file (%s)", path, q->why);
    } else {
        rc = h5_fields(f, s, path, q->why, err);
        if (H5Fclose(f) < 0 && rc == GW_OK)
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': corrupt HDF5 file (%s)", path, q->why);
    }
    if (fapl >= 0)
        H5Pclose(fapl);
    return rc;
}

/* What a sample file's HDF5 objects hold, counted at the open check: the
 * superblock and its extension, the shared-message tables and tracked free
 * space (H5Fget_info2), and for each object reached from the root (H5Ovisit)
 * its header, its links' and attributes' indexes and heaps, and a dataset's
 * stored data (H5Dget_storage_size). A file past that by more than
 * H5_HELD_SLACK and more than as much again is refused before it is hashed:
 * a valid sample holding 100 MB of zeros that no object holds (a dataset
 * written and deleted, its space never reused) was hashed whole, twice by a
 * read and three times by a sweep. The bound is the file's size against
 * these counts only: bytes HDF5 does not count (a global heap of
 * variable-length strings, a user block) fit in the slack for any sample.
 * The unheld bytes within the slack are hashed with the rest, and that is
 * kept: a sample's content hash is its file's bytes (the journals' and
 * tables' "# input" lines, the memo's and the pile check's keys), so a hash
 * of the held bytes alone would change every HDF5 sample's and refuse their
 * journals on resume, and a smaller slack would refuse valid files whose
 * uncounted bytes HDF5 does not report. Its cost, measured on layer-make's
 * 40-disc sample (6994 bytes) with 0.9 MiB freed by h5py (952,786 bytes):
 * `sweep --check` over 2 cases read 5.8 MB against 0.13 MB and took 0.01 to
 * 0.02 s of CPU against under 0.01. A sweep now hashes each sample once
 * while stat finds it unchanged (gw_io_hash_memo): the slack is read once
 * for the check pass and once for the rows' checks, not again for each case.
 * Hashing the held bytes alone stays unsound as well as incompatible: HDF5
 * reports what its objects hold as sizes, not as byte ranges, so the bytes
 * the reader holds cannot be told from the slack without reading its format
 * ourselves. */
#define H5_HELD_SLACK (1ULL << 20)
typedef struct h5_held {
    unsigned long long bytes;
    long objects;
    int failed;
} h5_held;

static void h5_held_add(h5_held *h, unsigned long long v)
{
    h->bytes = v > ~0ULL - h->bytes ? ~0ULL : h->bytes + v;
}

/* An object's header and its link and attribute indexes and heaps: the same
 * members in HDF5 1.10's H5O_info_t and 1.12's H5O_native_info_t */
#define H5_HELD_ADD_META(h, info)                                                                  \
    do {                                                                                           \
        h5_held_add(h, (info).hdr.space.total);                                                    \
        h5_held_add(h, (info).meta_size.obj.index_size);                                           \
        h5_held_add(h, (info).meta_size.obj.heap_size);                                            \
        h5_held_add(h, (info).meta_size.attr.index_size);                                          \
        h5_held_add(h, (info).meta_size.attr.heap_size);                                           \
    } while (0)

static herr_t h5_held_object(hid_t loc, const char *name, H5O_type_t type, h5_held *h)
{
    h->objects++;
#if H5_VERSION_GE(1, 12, 0)
    H5O_native_info_t ni;
    if (H5Oget_native_info_by_name(loc, name, &ni, H5O_NATIVE_INFO_HDR | H5O_NATIVE_INFO_META_SIZE,
                                   H5P_DEFAULT) < 0) {
        h->failed = 1;
        return -1;
    }
    H5_HELD_ADD_META(h, ni);
#else
    H5O_info_t oi;
    if (H5Oget_info_by_name2(loc, name, &oi, H5O_INFO_HDR | H5O_INFO_META_SIZE, H5P_DEFAULT) < 0) {
        h->failed = 1;
        return -1;
    }
    H5_HELD_ADD_META(h, oi);
#endif
    if (type == H5O_TYPE_DATASET) {
        hid_t d = H5Dopen2(loc, name, H5P_DEFAULT);
        if (d < 0) {
            h->failed = 1;
            return -1;
        }
        h5_held_add(h, H5Dget_storage_size(d));
        H5Dclose(d);
    }
    return 0;
}

#if H5_VERSION_GE(1, 12, 0)
static herr_t h5_held_visit(hid_t loc, const char *name, const H5O_info2_t *info, void *data)
#else
static herr_t h5_held_visit(hid_t loc, const char *name, const H5O_info_t *info, void *data)
#endif
{
    return h5_held_object(loc, name, info->type, data);
}

/* GW_OK when f's size is within what its objects hold (above), else
 * GW_EFORMAT naming the file and both sizes */
static int h5_held_check(hid_t f, const char *path, const h5_quiet *q, gw_err *err)
{
    h5_held h = {0, 0, 0};
    H5F_info2_t fi;
    hsize_t size = 0, ub = 0;
    hid_t fcpl = H5Fget_create_plist(f);
    int bad = fcpl < 0 || H5Pget_userblock(fcpl, &ub) < 0 || H5Fget_filesize(f, &size) < 0 ||
              H5Fget_info2(f, &fi) < 0;
    if (fcpl >= 0)
        H5Pclose(fcpl);
    if (!bad) {
        h5_held_add(&h, ub);
        h5_held_add(&h, fi.super.super_size);
        h5_held_add(&h, fi.super.super_ext_size);
        h5_held_add(&h, fi.free.meta_size);
        h5_held_add(&h, fi.free.tot_space);
        h5_held_add(&h, fi.sohm.hdr_size);
        h5_held_add(&h, fi.sohm.msgs_info.index_size);
        h5_held_add(&h, fi.sohm.msgs_info.heap_size);
#if H5_VERSION_GE(1, 12, 0)
        bad = H5Ovisit3(f, H5_INDEX_NAME, H5_ITER_NATIVE, h5_held_visit, &h, H5O_INFO_BASIC) < 0 || h.failed;
#else
        bad = H5Ovisit2(f, H5_INDEX_NAME, H5_ITER_NATIVE, h5_held_visit, &h, H5O_INFO_BASIC) < 0 || h.failed;
#endif
    }
    if (bad)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': corrupt HDF5 file (%s)", path,
                          q->why[0] ? q->why : "HDF5 call failed");
    const unsigned long long held = h.bytes, fsize = (unsigned long long)size;
    if (fsize > held && fsize - held > H5_HELD_SLACK && fsize - held > held)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': %llu bytes, of which its %ld HDF5 objects hold %llu "
                          "(headers, indexes, datasets' data): %llu bytes that no object holds (space freed "
                          "and never reused, or zeros) are more than 1 MiB and more than the objects hold, "
                          "so it is not hashed (h5repack copies the objects alone)",
                          path, fsize, h.objects, held, fsize - held);
    return GW_OK;
}

/* The file's metadata as HDF5 itself takes it, before a byte of the file is
 * hashed: its superblock (HDF5 verifies its checksum and its end-of-file
 * address against the file's size at the open), the root group's object
 * header, and the object headers of the datasets x, y and r where they are
 * hard links (each header's checksum verified as it is loaded). A few kB are
 * read. The superblock check of layer_sample.c compares addresses and sizes
 * and looks at 4 bytes of the root header: a copied superblock and root
 * header with an end-of-file address edited to a size of written zeros
 * (64 MiB) passed it, and the zeros were hashed whole (twice by a read,
 * three times by a sweep) before HDF5 refused the checksum. Refused with the
 * reader's own messages (corrupt HDF5 file, dataset unreadable). */
static int open_check_locked(const char *path, const h5_quiet *q, gw_err *err)
{
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    hid_t f = fapl < 0 || H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG) < 0 ? -1 :
              H5Fopen(path, H5F_ACC_RDONLY, fapl);
    if (fapl >= 0)
        H5Pclose(fapl);
    if (f < 0)
        return gw_err_set(err, GW_EFORMAT, "sample '%s': corrupt or truncated HDF5 file (%s)", path, q->why);
    int rc = GW_OK;
    hid_t o = H5Oopen(f, "/", H5P_DEFAULT); /* the root group's header, loaded */
    if (o < 0)
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': corrupt HDF5 file (%s)", path, q->why);
    else
        H5Oclose(o);
    static const char *const names[] = {"x", "y", "r"};
    for (size_t k = 0; k < sizeof names / sizeof names[0] && rc == GW_OK; k++) {
        H5L_info_t li;
        const htri_t ex = H5Lexists(f, names[k], H5P_DEFAULT); /* the root group's links read */
        if (ex < 0 || (ex > 0 && H5Lget_info(f, names[k], &li, H5P_DEFAULT) < 0)) {
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': corrupt HDF5 file (%s)", path,
                            q->why[0] ? q->why : "HDF5 call failed");
            break;
        }
        if (ex == 0 || li.type != H5L_TYPE_HARD)
            continue; /* missing, or not in the file: the reader says which */
        o = H5Oopen(f, names[k], H5P_DEFAULT);
        if (o < 0)
            rc = gw_err_set(err, GW_EFORMAT, "sample '%s': HDF5 dataset '%s' unreadable: %s", path, names[k],
                            q->why[0] ? q->why : "HDF5 call failed");
        else
            H5Oclose(o);
    }
    if (rc == GW_OK) /* then its size against what its objects hold, before it is hashed */
        rc = h5_held_check(f, path, q, err);
    if (H5Fclose(f) < 0 && rc == GW_OK)
        rc = gw_err_set(err, GW_EFORMAT, "sample '%s': corrupt HDF5 file (%s)", path, q->why);
    return rc;
}

/* One HDF5 call on a sample under the library's lock, with HDF5's own
 * printing off (s NULL: the open check, else the read). A call that failed
 * because an allocation inside HDF5 did (its stack holds a resource error) is
 * out of memory, not a bad sample: the dataset's sizes were checked against n
 * before it was read. After some corrupt files HDF5 1.10 loses track of a
 * block (a leak inside the library) and at exit prints "infinite loop closing
 * library" unless automatic error printing is off: after a failed call it
 * stays off, here and in the exiting thread (granwave reports HDF5 errors
 * through gw_err). */
static int h5_sample_call(const char *path, gw_layer_sample *s, gw_err *err)
{
    gw_h5_section sec;
    h5_quiet q;
    h5_enter(&sec, &q);
    int rc = s ? read_h5_locked(path, s, &q, err) : open_check_locked(path, &q, err);
    if (rc != GW_OK && rc != GW_ENOMEM && q.nomem)
        rc = gw_err_set(err, GW_ENOMEM, "sample '%s': out of memory (in HDF5: %s)", path, q.why);
    if (rc == GW_OK)
        gw_h5_leave(&sec);
    else
        gw_h5_leave_failed_read(&sec);
    return rc;
}

int layer_sample_h5_open_check(const char *path, gw_err *err)
{
    return h5_sample_call(path, NULL, err);
}

int layer_sample_h5_read(const char *path, gw_layer_sample *s, gw_err *err)
{
    /* (its superblock, version 2 or 3, checked at open: layer_sample.c) */
    return h5_sample_call(path, s, err);
}
#endif
