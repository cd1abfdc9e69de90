/*
 * layer_vtk.c: VTK legacy (ASCII POLYDATA) snapshots of the layer, for ParaView.
 *
 * Points: particle centres (z = 0) with point data radius (m), velocity (m/s,
 * 3-vector), omega (rad/s), fixed (0/1), block (0/1), body (the rigid body
 * the particle belongs to: one value per clump, its own for a free disc and for
 * the block); one vertex cell per
 * particle (so that ParaView draws the points), then one line cell per closed
 * particle-particle contact (u_n > 0); cell data F_n and F_t (N, from B.1 and
 * the capped tangential state; 0 on the vertex cells). Field data TIME (s):
 * the layer's time. The title line gives the units. Written atomically.
 * gw_layer_write_pvd: a ParaView collection (.pvd, XML) of such snapshots
 * with their times, so that ParaView opens them as one time series.
 * Units: SI.
 */
#include <math.h>
#include <stdlib.h>

#include "layer_impl.h"
#include "gw_locale.h"

int gw_layer_write_vtk(const gw_layer *L, const char *path, const char *title, gw_err *err)
{
    if (!L || !title) /* L was read after the file was opened (SIGSEGV); a NULL title was written "(null)" */
        return gw_err_set(err, GW_EINVAL, "gw_layer_write_vtk: %s is NULL", !L ? "L" : "title");
    /* The title is the format's second line, one line of at most 255
     * characters: a newline in it ended that line early, and the file's
     * "ASCII" line was then the title's rest, which VTK's readers refuse. The
     * title made one line (a newline written \n, as in messages) and cut
     * between characters at 120 bytes. */
    char line[121];
    gw_one_line(line, sizeof line, title);
    gw_afile f;
    int rc = gw_afile_open(&f, path, err);
    if (rc != GW_OK)
        return rc;
    FILE *fp = f.fp;
    const int n = L->n;
    const double *snap = layer_snapshot(L);
#define CLOSED_PAIR(k) (L->c[k].b >= 0 && snap[LAYER_SNAP_W * (k) + LAYER_SNAP_FN] > 0)
    int nl = 0;
    for (int k = 0; k < L->nc; k++)
        nl += CLOSED_PAIR(k);
    gw_fprintf(fp, "# vtk DataFile Version 3.0\n%s (granwave %s); units: m, m/s, rad/s, N, TIME s\n"
            "ASCII\nDATASET POLYDATA\nFIELD FieldData 1\nTIME 1 1 double\n%.17g\n", line, gw_version(), L->t);
    gw_fprintf(fp, "POINTS %d double\n", n);
    for (int i = 0; i < n; i++) {
        double s[6];
        gw_layer_particle(L, i, s);
        gw_fprintf(fp, "%.9g %.9g 0\n", s[0], s[1]);
    }
    gw_fprintf(fp, "VERTICES %d %d\n", n, 2 * n);
    for (int i = 0; i < n; i++)
        gw_fprintf(fp, "1 %d\n", i);
    gw_fprintf(fp, "LINES %d %d\n", nl, 3 * nl);
    for (int k = 0; k < L->nc; k++)
        if (CLOSED_PAIR(k))
            gw_fprintf(fp, "2 %d %d\n", L->c[k].a, L->c[k].b);
    gw_fprintf(fp, "POINT_DATA %d\nSCALARS radius double 1\nLOOKUP_TABLE default\n", n);
    for (int i = 0; i < n; i++)
        gw_fprintf(fp, "%.9g\n", L->r[i]);
    gw_fprintf(fp, "SCALARS omega double 1\nLOOKUP_TABLE default\n");
    for (int i = 0; i < n; i++)
        gw_fprintf(fp, "%.9g\n", L->y[6 * layer_body(L, i) + 5]);
    gw_fprintf(fp, "SCALARS fixed int 1\nLOOKUP_TABLE default\n");
    for (int i = 0; i < n; i++)
        gw_fprintf(fp, "%d\n", L->fixed[layer_body(L, i)]);
    gw_fprintf(fp, "SCALARS block int 1\nLOOKUP_TABLE default\n");
    for (int i = 0; i < n; i++)
        gw_fprintf(fp, "%d\n", i == L->block);
    gw_fprintf(fp, "SCALARS body int 1\nLOOKUP_TABLE default\n");
    for (int i = 0; i < n; i++)
        gw_fprintf(fp, "%d\n", layer_body(L, i));
    gw_fprintf(fp, "VECTORS velocity double\n");
    for (int i = 0; i < n; i++) {
        double s[6];
        gw_layer_particle(L, i, s);
        gw_fprintf(fp, "%.9g %.9g 0\n", s[3], s[4]);
    }
    { /* cells: the n vertices, then the nl lines */
        gw_fprintf(fp, "CELL_DATA %d\nSCALARS F_n double 1\nLOOKUP_TABLE default\n", n + nl);
        for (int pass = 0; pass < 2; pass++) {
            if (pass == 1)
                gw_fprintf(fp, "SCALARS F_t double 1\nLOOKUP_TABLE default\n");
            for (int i = 0; i < n; i++)
                fputs("0\n", fp);
            for (int k = 0; k < L->nc; k++)
                if (CLOSED_PAIR(k))
                    gw_fprintf(fp, "%.9g\n", snap[LAYER_SNAP_W * k + (pass == 0 ? LAYER_SNAP_FN : LAYER_SNAP_FT)]);
        }
    }
#undef CLOSED_PAIR
    if (ferror(fp)) {
        gw_afile_abort(&f);
        return gw_err_set(err, GW_EIO, "%s: write error", path);
    }
    return gw_afile_commit(&f, err);
}

/* name as an XML attribute's value: '&', '<', '>', '"' and '\'' as entities */
static void pvd_name(FILE *fp, const char *name)
{
    for (const char *c = name; *c; c++) {
        const char *ent = *c == '&' ? "&amp;" : *c == '<' ? "&lt;" : *c == '>' ? "&gt;" : *c == '"' ? "&quot;"
                        : *c == '\'' ? "&apos;" : NULL;
        if (ent)
            fputs(ent, fp);
        else
            fputc(*c, fp);
    }
}

int gw_layer_write_pvd(const char *path, int n, const char *const *files, const double *times, gw_err *err)
{
    /* NULL lists were read (SIGSEGV), n < 0 wrote an empty collection */
    if (n < 0 || (n > 0 && (!files || !times)))
        return gw_err_set(err, GW_EINVAL, "gw_layer_write_pvd: %s", n < 0 ? "n < 0" : !files ? "files is NULL" :
                          "times is NULL");
    /* A file name is an XML attribute's value: a '"', '&' or '<' in it was
     * written as it is, and the collection was no XML (ParaView refuses it);
     * they are written as entities now (pvd_name). A control character or a
     * byte of no whole UTF-8 character has no place in an XML 1.0 document
     * (a newline in an attribute reads back as a space): refused, naming the
     * snapshot, nothing written. */
    for (int k = 0; k < n; k++) {
        if (!files[k] || !isfinite(times[k]))
            return gw_err_set(err, GW_EINVAL, "gw_layer_write_pvd: snapshot %d: %s", k,
                              !files[k] ? "file is NULL" : "time not finite");
        /* a collection is one series in time: times out of order (1, 0) or
         * repeated were written as given, and ParaView played them in the
         * order of their times, not of the list */
        if (k > 0 && !(times[k] > times[k - 1]))
            return gw_err_set(err, GW_EINVAL, "gw_layer_write_pvd: snapshot %d: time %.17g s is not after snapshot "
                              "%d's %.17g s (times must increase)", k, times[k], k - 1, times[k - 1]);
        for (const char *c = files[k]; *c;) {
            const size_t len = gw_utf8_len(c);
            if (len == 0 || (unsigned char)*c < 0x20 || *c == 0x7f)
                return gw_err_set(err, GW_EINVAL, "gw_layer_write_pvd: snapshot %d: file '%s' holds %s at byte %ld, "
                                  "which an XML file cannot hold", k, files[k],
                                  len == 0 ? "no whole UTF-8 character" : "a control character",
                                  (long)(c - files[k]) + 1);
            c += len;
        }
    }
    gw_afile f;
    int rc = gw_afile_open(&f, path, err);
    if (rc != GW_OK)
        return rc;
    gw_fprintf(f.fp, "<?xml version=\"1.0\"?>\n<!-- granwave %s: layer snapshots (legacy VTK), time in s -->\n"
            "<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n", gw_version());
    for (int k = 0; k < n; k++) {
        gw_fprintf(f.fp, "    <DataSet timestep=\"%.17g\" group=\"\" part=\"0\" file=\"", times[k]);
        pvd_name(f.fp, files[k]);
        fputs("\"/>\n", f.fp);
    }
    gw_fprintf(f.fp, "  </Collection>\n</VTKFile>\n");
    if (ferror(f.fp)) {
        gw_afile_abort(&f);
        return gw_err_set(err, GW_EIO, "%s: write error", path);
    }
    return gw_afile_commit(&f, err);
}
