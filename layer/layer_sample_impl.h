/*
 * layer_sample_impl.h: what the three parts of the sample files share (not
 * installed): the reader and writers (layer_sample.c, text; layer_sample_h5.c,
 * HDF5) and the checks both apply to the fields they read or write
 * (layer_sample_check.c). Units: SI (m).
 */
#ifndef GW_LAYER_SAMPLE_IMPL_H
#define GW_LAYER_SAMPLE_IMPL_H

#include "layer_impl.h"

#define SAMPLE_NMAX 10000000L /* 240 MB of coordinates */
#define SAMPLE_MAGIC "granwave-layer-sample" /* the text format's first word; HDF5's "format" attribute */

/* Where a header value came from, for the messages of the box and porosity
 * checks: a text file's line (line[K] > 0), an HDF5 attribute (h5), or a
 * sample in memory being written (NULL). */
enum { K_WIDTH, K_RM, K_VR, K_POR, K_SEED, K_LAW, K_CMASS, K_N, K_COUNT };
typedef struct hdr_src {
    int h5;
    long line[K_COUNT];
} hdr_src;

/* Up to 40 characters of untrusted text s for a message in out, non-printables
 * as '?'; returns out. */
const char *layer_sample_shown(const char *s, char out[48]);

/* The header fields alone (width, rm, volume_ratio, porosity, seed, mass
 * laws): status with a message "sample 'PATH': ..." when one is refused. */
int layer_sample_header_check(const gw_layer_sample *s, const char *path, int status, gw_err *err);

/* One particle (x, y, r) of a sample of that width and rm; where names it in
 * the message ("line 12", "particle at index 3"). */
int layer_sample_particle_check(double width, double rm, double x, double y, double r, const char *path,
                                const char *where, int status, gw_err *err);

/* The checks that need the whole sample (bodies, grading, box, porosity), once
 * its header and particles have passed; GW_ENOMEM when a scratch allocation
 * fails. src: where the header came from (NULL: a sample in memory). */
int layer_sample_whole_check(const gw_layer_sample *s, const char *path, const hdr_src *src, int status,
                             gw_err *err);

/* All of them: the header, n and each particle, then the whole sample. */
int layer_sample_check(const gw_layer_sample *s, const char *path, const hdr_src *src, int status, gw_err *err);

/* The settings line's JSON text (layer_sample_settings.c) into *out: recorded
 * 1 with the settling's material, or recorded 0 when the object has no
 * material; GW_EFORMAT "sample 'PATH': WHERE: ..." when it is not a JSON
 * object or its material is incomplete, of the wrong type or out of range,
 * or (a line with material, layer-make's) when its pluviation's fields (n, rm,
 * volume ratio, width, seed, clumps, mass law, clump mass) disagree with the
 * sample s's header and body (src: where the header came from; s NULL: not
 * compared); GW_ENOMEM. *out is zeroed first. */
#define SAMPLE_SETTINGS_MAX 65536 /* longest settings line read, characters (layer-make's: under 30000) */
int layer_sample_settings_parse(const char *text, const char *path, const char *where, const gw_layer_sample *s,
                                const hdr_src *src, gw_layer_settled *out, gw_err *err);

/* The settling record of s (gw_layer_settled; recorded 0: GW_OK) held to
 * what the reader holds a settings line to: G, nu, phi, rho and g finite and
 * within the material's ranges (g > 0), the mass law the sample's, the clump
 * mass the sample's or -1. A record built in memory was taken as it was: a
 * NaN or negative modulus or density gave a load ratio of NaN or -40 and a
 * refusal saying the pile "carries nan times" its weight (a run under
 * other-settling), a NaN or negative friction passed the friction bound, a
 * mass law of 7 was told "disc against the impact's disc". status and the
 * message as the other sample checks ("sample 'PATH': settled.FIELD ..."). */
int layer_settled_record_check(const gw_layer_sample *s, const char *path, int status, gw_err *err);

/* 1 when text, a header line without its '#' and leading blanks, is
 * layer-make's "settled: ..." line and says "converged 0": the pile was
 * written before it settled (gw_layer_settled.unsettled); else 0. */
int layer_sample_settled_unsettled(const char *text);
/* 1 when text is layer-make's "settled:" line of a pile that settled
 * ("converged 1": gw_layer_sample.settled_converged); else 0. */
int layer_sample_settled_converged(const char *text);

#if GW_HAVE_HDF5
/* The HDF5 sample (layer_sample_h5.c): s, already checked, written
 * atomically; read (its superblock, version 2 or 3, checked at open by
 * layer_sample.c) into s, which the caller frees on failure. */
int layer_sample_h5_write(const gw_layer_sample *s, const char *path, const char *header, gw_err *err);
int layer_sample_h5_read(const char *path, gw_layer_sample *s, gw_err *err);
/* The file opened by HDF5 and its root group's and datasets x, y, r's object
 * headers loaded (their checksums verified), a few kB read: GW_OK, or the
 * reader's GW_EFORMAT; before the file is hashed (sample_open). */
int layer_sample_h5_open_check(const char *path, gw_err *err);
#endif

#endif
