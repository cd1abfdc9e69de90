/*
 * layer_sweep_model.c: the 2D layer (docs/physics.md section 2) as the `layer` model
 * of `granwave sweep` (gw_sweep.h): one block impact per case, for bouncing
 * diagrams and impact-point statistics.
 *
 * Keys: the rows of the impact's parameter table (gw_layer_impact_setup_params,
 * gw_layer_study.h: the options of `granwave layer-impact` without json/out),
 * set and checked by gw_param_set and resolved by gw_layer_impact_run as the
 * command's are, so a case and the command run the same impact; the flags
 * remove-walls, full and exact take 0/1/true/false. No command line is built.
 * Extra keys (their own table below) place the block on one of `points`
 * impact points `spacing` apart around x (docs/physics.md 2.3, statistics:
 * N = 100 points d_i = 0.05 m apart):
 *     x_impact = x + (point - (points - 1) / 2) spacing          (m, from the box centre)
 * with 0 <= point < points (defaults point 0, points 1, spacing 0.05 m).
 *
 * Row (SI; angles in degrees): x_impact, bounced (0/1), e_n, e, alpha_r
 * (B.16-B.18), v_ni, v_nr, v_r (m/s), penetration (m), penetration_rm (in R_m),
 * dissipated_first_contact and block_loss_first_contact (over E_incident,
 * docs/physics.md 2.5), energy_error (ledger closure B.7-B.14), wave_speed (m/s, from
 * the crowns' strain peaks), t_end (s), steps, then (added last, so readers of
 * the earlier columns keep working) the first free-flight maximum e_n_first,
 * e_first, alpha_r_first, v_nr_first, v_r_first, and the event times t_leave
 * (the block leaves moving up), t_rebound (T_i) and t_f (T_f) in s
 * (layer_outcome.c), then the sample's settling against the case's material
 * (layer_settled.c): settled_load_ratio q, the weight the pile's contacts
 * carry under it over the weight they carried at rest (1: at rest as settled;
 * nan: the sample records no settling), and settling_warning, 1 when the case
 * ran on a sample settled under another material, gravity, mass law, clump
 * mass or friction (the warning layer-impact prints; with other-settling, one
 * far from rest), else 0. A reader of the table alone sees which rows hold the
 * pile's own motion as well as the block's: the check pass's tally (below) is
 * said once on stderr, and layer-stats counts these rows. The two are columns,
 * not a line of the table's head, because the head is written by the sweep
 * (common/sweep/) from the journal's rows alone, and a row carries its own
 * case's verdict through a resume, an MPI gather and a table cut to some
 * rows; a journal of the build before them is refused by its "# build" line
 * and its row width, as for any column added. Undefined values (e.g. e_n of a block that does not
 * bounce, a wave speed without enough crowns) are NaN, written as "nan"
 * whatever the sign bit, so tables are byte-identical however the cases ran.
 * Undecided outcomes are NaN too: bounced = nan when the run ended before the
 * verdict, e_n = e = alpha_r = nan in a bouncing row when it ended before T_f
 * (or `until = verdict` stopped it); layer-stats leaves such rows out of the
 * shares and means they cannot enter, and says how many. No wall-clock time
 * in the row.
 *
 * The run reads the sample file for every case, with no cache (0.4 ms on the
 * 300-disc sample, 1 % of the cheapest impact measured, 40 ms; no state is
 * shared between the sweep's threads). The check pass (`sweep --check`, and
 * before every sweep) checks every case before any runs, and reading and
 * checking the sample was nearly all of its cost: it reads and checks each
 * sample file once, keeping the sample read (check_memo below), and for each
 * case hashes the file (FNV-1a 64 of its bytes, as the sweep's inputs are)
 * to know it is the same, and finds a sample's settling verdict once per
 * material (layer_settling_verdict), where each case found it twice. The pass
 * also refuses two sample paths holding one pile (pile_note: a copy,
 * layer-make run twice with one seed, or the particles listed in another
 * order), which the sweep's own check of file identity cannot see.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_layer_study.h"
#include "gw_locale.h"
#include "gw_sweep.h"
#include "gw_sweep_impl.h"
#include "layer_impl.h"
#include "layer_setup_rows.h"

static const char *const columns[] = {
    "x_impact", "bounced", "e_n", "e", "alpha_r", "v_ni", "v_nr", "v_r", "penetration", "penetration_rm",
    "dissipated_first_contact", "block_loss_first_contact", "energy_error", "wave_speed", "t_end", "steps",
    "e_n_first", "e_first", "alpha_r_first", "v_nr_first", "v_r_first", "t_leave", "t_rebound", "t_f",
    "settled_load_ratio", "settling_warning", "fell_off", "slump_ke", "crowns_nulled"};
#define NCOLUMNS ((int)(sizeof columns / sizeof columns[0]))

/* The impact point among points (the sweep's own keys). */
typedef struct placement {
    long point, points;
    double spacing;
    double x0; /* x before the point's shift, m (set by prepare) */
} placement;

/* The abscissa, from the box centre, of impact point k of pl around x0, as
 * prepare places a case's block. */
static double point_x(const placement *pl, long k)
{
    return pl->x0 + ((double)k - 0.5 * (double)(pl->points - 1)) * pl->spacing;
}

/* Case pl's impact point and its neighbour (the next point, or the one
 * before for the last) put the block at one position, 0.5 width + x as
 * gw_layer_impact places it (width 0: the abscissas alone, the sample not
 * at hand): the same impact, run once per point and counted so by
 * layer-stats (spacing = 0 with points = 4 gave four identical rows, one
 * group of n 4 with spreads 0). GW_EINVAL naming spacing, or GW_OK. */
static int placement_distinct(const placement *pl, double width, gw_err *err)
{
    if (pl->points <= 1)
        return GW_OK;
    const long nb = pl->point + 1 < pl->points ? pl->point + 1 : pl->point - 1;
    const double a = point_x(pl, pl->point), b = point_x(pl, nb);
    if (a != b && 0.5 * width + a != 0.5 * width + b)
        return GW_OK;
    char half[96] = "";
    if (a != b) /* apart by less than the rounding of the block's position */
        gw_snprintf(half, sizeof half, " and %.17g m, one position once the box's half-width %g m is added", b,
                    0.5 * width);
    return gw_err_set(err, GW_EINVAL, "spacing: %g m puts impact points %ld and %ld of %ld at one block position "
                      "(x = %.17g m%s): the same impact would run once per point and count so in layer-stats; "
                      "give the points a spacing that moves the block, or points = 1", pl->spacing,
                      pl->point < nb ? pl->point : nb, pl->point < nb ? nb : pl->point, pl->points, a, half);
}

static const gw_param placement_params[] = {
    {.name = "point", .type = GW_PARAM_LONG, .offset = offsetof(placement, point), .unit = "", .min = 0,
     .max = 1e9, .def = "0", .metavar = "K", .help = "impact point, 0 .. points-1 [0]"},
    {.name = "points", .type = GW_PARAM_LONG, .offset = offsetof(placement, points), .unit = "", .min = 1,
     .max = 1e9, .def = "1", .metavar = "N", .help = "number of impact points around x [1]"},
    {.name = "spacing", .type = GW_PARAM_DOUBLE, .offset = offsetof(placement, spacing), .unit = "m", .min = 0,
     .max = 1e6, .def = "0.05", .metavar = "D", .help = "distance between impact points d_i, m [0.05]"},
    GW_PARAM_END};

static int has_key(const char *name)
{
    const gw_param *p = gw_param_find(gw_layer_impact_setup_params(), name);
    /* snapshots keep the particles in memory: a library option, not a sweep key */
    return (p && gw_param_is_input(p) && strcmp(p->name, "snapshots") != 0) || gw_param_find(placement_params, name);
}

/* The case's setup from its pairs with the impact point placed (x shifted);
 * free with gw_layer_impact_setup_clear, also after a failure. GW_EINVAL
 * "NAME: reason" for a bad value. */
static int prepare(gw_layer_impact_setup *s, int nk, const char *const *names, const char *const *values,
                   placement *plo, gw_err *err)
{
    placement pl = {0, 1, 0, 0};
    int rc = gw_layer_impact_setup_init(s);
    if (rc == GW_OK)
        rc = gw_param_init(placement_params, &pl, err);
    if (rc == GW_OK)
        rc = gw_sweep_pairs_check("gw_layer_sweep_model", nk, names, values, err);
    for (int i = 0; rc == GW_OK && i < nk; i++)
        rc = gw_param_find(placement_params, names[i])
                 ? gw_param_set(placement_params, &pl, names[i], values[i], err)
                 : has_key(names[i]) ? gw_param_set(gw_layer_impact_setup_params(), s, names[i], values[i], err)
                                     : gw_err_set(err, GW_EINVAL, "unknown parameter '%s'", names[i]);
    if (rc == GW_OK && pl.point >= pl.points)
        rc = gw_err_set(err, GW_EINVAL, "point: %ld is outside [0, points - 1 = %ld]", pl.point, pl.points - 1);
    /* placement keys that would not do what they say: points > 1 without a
     * point key runs point 0 alone, (points - 1) / 2 spacings left of x; a
     * spacing with one point moves nothing */
    int has_point = 0, has_spacing = 0;
    for (int i = 0; rc == GW_OK && i < nk; i++)
        has_point |= strcmp(names[i], "point") == 0, has_spacing |= strcmp(names[i], "spacing") == 0;
    if (rc == GW_OK && pl.points > 1 && !has_point)
        rc = gw_err_set(err, GW_EINVAL, "points: %ld points but no key point: every case would run point 0 "
                        "alone, %g m left of x; give point = 0:%ld in [grid]", pl.points,
                        0.5 * (double)(pl.points - 1) * pl.spacing, pl.points - 1);
    if (rc == GW_OK && pl.points == 1 && has_spacing)
        rc = gw_err_set(err, GW_EINVAL, "spacing: has no effect with one impact point (points = 1)");
    if (rc == GW_OK) {
        const double x0 = pl.x0 = s->x;
        s->x = point_x(&pl, pl.point);
        if (!(fabs(s->x) <= 1e6)) /* the x row's range, named by the keys that moved it there */
            rc = gw_err_set(err, GW_EINVAL, "spacing: impact point %ld of %ld, %g m apart around x = %g m, lies "
                            "at %g m, outside [-1e6, 1e6]", pl.point, pl.points, pl.spacing, x0, s->x);
        else
            rc = placement_distinct(&pl, 0, err);
    }
    if (plo)
        *plo = pl;
    return rc == GW_OK || rc == GW_ENOMEM ? rc : GW_EINVAL;
}

/* A refusal of x found with the sample (the block does not fit in the box)
 * for a point moved there by the placement keys names them: 'spacing = 1e6'
 * was refused as "x: block ... at x = -1e+06 m", a key the config never set. */
static void name_placement(const gw_layer_impact_setup *s, const placement *pl, gw_err *err)
{
    if (!err || pl->points <= 1 || strncmp(err->msg, "x: ", 3) != 0)
        return;
    const double x0 = s->x - ((double)pl->point - 0.5 * (double)(pl->points - 1)) * pl->spacing;
    char tmp[sizeof err->msg];
    gw_snprintf(tmp, sizeof tmp, "%s", err->msg + 3);
    gw_err_set(err, GW_EINVAL, "spacing: impact point %ld of %ld, %g m apart around x = %g m: %s", pl->point,
               pl->points, pl->spacing, x0, tmp);
}

/* The samples a pass of checks has read and checked (the memo its caller
 * keeps, gw_sweep_model.check_memo), by path and the hash of the bytes read:
 * a case whose file hashes the same now is checked against the sample kept
 * (the rows and the resolution, layer_impact_setup_check_sample), any other
 * reads it (gw_layer_impact_plan_make, as the run does). Keyed by content, not
 * by the file's inode and times: a file rewritten in place with the same size
 * within the file system's timestamp resolution (4 ms on ext4) is still seen.
 * Up to MEMO_SLOTS files (a grid over several samples), the least recently
 * used replaced, each of at most MEMO_NMAX particles (2.8 MB; larger samples
 * are read for every case, as before): at most 11 MB, with each slot's
 * settling verdicts (44 kB), held until the pass ends (memo_free). */
#define MEMO_SLOTS 4
#define MEMO_NMAX 100000
typedef struct memo_slot {
    char *path;
    unsigned long long hash, used;
    gw_layer_sample s;
    /* its settling verdicts under the materials of the cases checked on it
     * (layer_settling_verdict): found once for the cases of one material,
     * where each case found it twice (its resolution, then settling_tally) */
    layer_settling_memo *settle;
} memo_slot;
typedef struct check_memo {
    unsigned long long tick;
    memo_slot slot[MEMO_SLOTS];
    /* cases checked, and those on a sample settled under another material
     * (gw_layer_impact_settled_check's warning, the first one's text kept) */
    long ncases, nsettling;
    char settling[768];
    /* every sample path the pass read, with the hashes of its bytes and of
     * its pile (pile_note) */
    struct pile {
        char *path;
        unsigned long long file_hash, pile_hash;
        int zero_springs; /* hashed without its springs (a case under zero-springs) */
    } *piles;
    long npiles, cap;
    /* the block positions the cases put it at (x_note): an open-addressing
     * table of nx of cap_x entries, cap_x a power of two, at most half full */
    struct x_seen {
        int used;
        unsigned long long sample; /* the sample's content hash */
        long point, points;
        double spacing, pos, x0; /* pos: 0.5 width + x in the box; x0: x given */
    } *xs;
    size_t nx, cap_x;
    /* the samples' content hashes, kept while stat finds each file as it
     * was hashed (gw_io_hash_memo): the pass hashed a case's sample again
     * for each case, 1.5 ms per MiB, over the whole grid */
    gw_hash_memo hashes;
} check_memo;

static unsigned long long x_key(const struct x_seen *e)
{
    unsigned long long h = gw_fnv1a64(GW_FNV1A64_INIT, &e->sample, sizeof e->sample);
    h = gw_fnv1a64(h, &e->point, sizeof e->point);
    h = gw_fnv1a64(h, &e->points, sizeof e->points);
    h = gw_fnv1a64(h, &e->spacing, sizeof e->spacing);
    return gw_fnv1a64(h, &e->pos, sizeof e->pos);
}

/* Case pl's block position on the sample (content hash `sample`, box width)
 * against the cases the pass checked before: two values of x whose block
 * positions are one double (x = 0 and 1e-300 in a box 0.5 m wide: 0.25 + 1e-300
 * is 0.25) run the same impacts, and layer-stats, which groups rows by their
 * grid values, counted them as two groups of one configuration. Refused
 * naming x (the same point of the same placement, the rest of the case
 * aside: the grid is a product, so the other keys' values come with both x);
 * two placements that share a position (x = 0, spacing 0.1 and x = 0.1,
 * spacing 0.2 at point 0) are two groups and pass. GW_EINVAL, GW_ENOMEM or
 * GW_OK. */
static int x_note(check_memo *c, unsigned long long sample, const placement *pl, double width, gw_err *err)
{
    const struct x_seen e = {1, sample, pl->point, pl->points, pl->spacing, 0.5 * width + point_x(pl, pl->point),
                             pl->x0};
    if (2 * (c->nx + 1) > c->cap_x) {
        const size_t cap = c->cap_x ? 2 * c->cap_x : 64;
        struct x_seen *t = calloc(cap, sizeof *t);
        if (!t)
            return gw_err_set(err, GW_ENOMEM, "out of memory");
        for (size_t i = 0; i < c->cap_x; i++) {
            if (!c->xs[i].used)
                continue;
            size_t k = x_key(&c->xs[i]) & (cap - 1);
            while (t[k].used)
                k = (k + 1) & (cap - 1);
            t[k] = c->xs[i];
        }
        free(c->xs);
        c->xs = t, c->cap_x = cap;
    }
    size_t k = x_key(&e) & (c->cap_x - 1);
    for (; c->xs[k].used; k = (k + 1) & (c->cap_x - 1)) {
        const struct x_seen *o = &c->xs[k];
        if (o->sample != e.sample || o->point != e.point || o->points != e.points || o->spacing != e.spacing ||
            o->pos != e.pos)
            continue;
        if (o->x0 == e.x0) /* the same x with other values of the other keys */
            return GW_OK;
        char a[32], b[32];
        /* the fewest digits that read back (1e-300, not 1.0000000000000001e-300) */
        gw_num_text(a, sizeof a, o->x0);
        gw_num_text(b, sizeof b, e.x0);
        return gw_err_set(err, GW_EINVAL, "x: %s and %s m put the block at one position (its centre %.17g m from the "
                          "box's left wall, width %g m%s): each impact would run twice, as two groups of layer-stats; "
                          "list one of them", a, b, e.pos, width, e.points > 1 ? ", at the same impact point" : "");
    }
    c->xs[k] = e;
    c->nx++;
    return GW_OK;
}

/* Sample path, read with bytes hashing to file_hash as s, holds a pile no
 * other sample of the pass holds. The sweep tells its grid's files apart by
 * identity (common/sweep/gw_sweep_inputs.c), but a copy of a sample, or
 * layer-make run twice with the same seed and options, is another file with
 * other bytes (its comments record the command) and the same particles: each
 * case ran twice and layer-stats counted its point twice (n 8 where 4 are
 * distinct); a file listing the same particles in another order, or with its
 * clumps numbered otherwise, is the same pile too (the run differs only by
 * rounding). Compared by gw_layer_sample_pile_hash; a path already noted with
 * the same bytes is not hashed again. A case under zero-springs reads no
 * springs, so its pile is hashed without them: a sample run so and its copy
 * without the springs section (or run so too) are one pile; before, such a
 * grid ran every impact twice with exit 0 (2 samples, 4 cases, the rows
 * alike) and layer-stats refused its table. GW_OK, GW_EINVAL naming both
 * files, GW_ENOMEM. */
static int pile_note(check_memo *c, const char *path, unsigned long long file_hash, const gw_layer_sample *s,
                     int zero_springs, gw_err *err)
{
    zero_springs = zero_springs && s->n_springs > 0; /* without springs: one pile either way */
    for (long i = 0; i < c->npiles; i++)
        if (c->piles[i].file_hash == file_hash && c->piles[i].zero_springs == zero_springs &&
            strcmp(c->piles[i].path, path) == 0)
            return GW_OK;
    unsigned long long h;
    gw_layer_sample bare = *s; /* shallow: the pile the run reads */
    if (zero_springs)
        bare.n_springs = 0;
    const int hrc = layer_sample_pile_hash(&bare, &h);
    if (hrc != GW_OK) /* (a sample read from a file has its arrays: only out of memory) */
        return hrc == GW_ENOMEM ? gw_err_set(err, GW_ENOMEM, "out of memory")
                                : layer_sample_shape_check(&bare, path, err);
    for (long i = 0; i < c->npiles; i++)
        if (c->piles[i].pile_hash == h && strcmp(c->piles[i].path, path) != 0)
            return gw_err_set(err, GW_EINVAL, "sample: '%s' and '%s' hold the same pile (the same particles, in "
                              "whatever order, box and settling record%s): each case would run twice and its point "
                              "count twice in layer-stats; list one of them", c->piles[i].path, path,
                              c->piles[i].zero_springs || zero_springs ? "; springs left out under zero-springs" : "");
    if (c->npiles == c->cap) {
        const long cap = c->cap ? 2 * c->cap : 8;
        struct pile *p = realloc(c->piles, (size_t)cap * sizeof *p);
        if (!p)
            return gw_err_set(err, GW_ENOMEM, "out of memory");
        c->piles = p, c->cap = cap;
    }
    char *copy = strdup(path);
    if (!copy)
        return gw_err_set(err, GW_ENOMEM, "out of memory");
    c->piles[c->npiles++] = (struct pile){copy, file_hash, h, zero_springs};
    return GW_OK;
}

/* The slot the memo keeps for path, as the case just checked read it; NULL
 * when none is kept (a sample above MEMO_NMAX, no memo). */
static memo_slot *memo_find(check_memo *c, const char *path)
{
    for (int k = 0; c && path && k < MEMO_SLOTS; k++) {
        memo_slot *m = &c->slot[k];
        if (m->path && m->used == c->tick && strcmp(m->path, path) == 0)
            return m;
    }
    return NULL;
}

/* Tally case s's settling warning against the sample kept for it (none kept:
 * a sample above MEMO_NMAX, whose runs still record theirs). The material
 * resolves as the run's does (layer_setup.c: the sample's mass law unless
 * given); the verdict is the one the case's check just found, kept in the
 * slot (layer_settling_verdict finds it again only if the two materials'
 * bytes differ). */
static void settling_tally(check_memo *c, const gw_layer_impact_setup *s)
{
    c->ncases++;
    memo_slot *m = memo_find(c, s->sample);
    if (!m)
        return;
    gw_layer_params lp = gw_layer_params_default();
    GW_LAYER_MATERIAL_TO_PARAMS(&lp, s);
    lp.mass_law = s->mass_law >= 0 ? s->mass_law : m->s.mass_law;
    lp.clump_mass = s->clump_mass >= 0 ? s->clump_mass : m->s.clump_mass;
    char w[768] = "";
    gw_err e = {{0}};
    if (layer_settling_verdict(&m->s, &lp, s->other_settling, s->sample, m->settle, w, sizeof w, &e) == GW_OK &&
        w[0] && c->nsettling++ == 0)
        memcpy(c->settling, w, sizeof w);
}

static int memo_warnings(const void *memo, char **list)
{
    const check_memo *c = memo;
    if (!c || c->nsettling == 0)
        return GW_OK;
    return gw_warnings_add(list, "%ld of %ld cases run on a sample settled under another material or not "
                           "settled (their rows hold its motion too, and say so: settling_warning = 1); the first: "
                           "%s", c->nsettling,
                           c->ncases, c->settling);
}

static void memo_free(void *memo)
{
    check_memo *c = memo;
    if (!c)
        return;
    for (int k = 0; k < MEMO_SLOTS; k++) {
        free(c->slot[k].path);
        free(c->slot[k].settle);
        gw_layer_sample_free(&c->slot[k].s);
    }
    for (long i = 0; i < c->npiles; i++)
        free(c->piles[i].path);
    free(c->piles);
    free(c->xs);
    gw_io_hash_memo_free(&c->hashes);
    free(c);
}

/* layer_impact_setup_check_case of s (a sweep case's setup check), through the memo *memo (NULL: none; *memo
 * NULL: made here, on the first sample read; out of memory for it: the check
 * without it). *width and *hash get the sample's box width and content hash
 * whenever the memo had it or the check read it, kept or not (a sample above
 * MEMO_NMAX too: its block positions are compared as any other's); *width is
 * NaN when the check went without the memo. */
static int setup_check(void **memo, const gw_layer_impact_setup *s, double *width, unsigned long long *hash,
                       gw_err *err)
{
    unsigned long long h;
    gw_err e = {{0}};
    *width = NAN;
    *hash = 0;
    /* out of memory for the memo or a slot is said (GW_ENOMEM): a pass that
     * went on without them lost its cases' settling tally, and the table's
     * "# warning:" line said 3 of 4 cases where 4 were (test_alloc_failure) */
    if (memo && !*memo && !(*memo = calloc(1, sizeof(check_memo))))
        return gw_err_set(err, GW_ENOMEM, "out of memory");
    check_memo *c = memo ? *memo : NULL;
    /* hashed in the pass of the reader's rules (a sparse 200 GB file was hashed whole first) */
    const int frc = c && s->sample ? gw_io_hash_memo(&c->hashes, s->sample, layer_sample_file_check, &h, &e)
                                   : GW_EINVAL;
    if (frc == GW_ENOMEM) /* (not checked again without the memo: its tally lost the case) */
        return gw_err_set(err, GW_ENOMEM, "%s", e.msg[0] ? e.msg : "out of memory");
    if (frc != GW_OK)
        return layer_impact_setup_check_case(s, err); /* its own message for a missing or odd file */
    memo_slot *old = &c->slot[0];
    for (int k = 0; k < MEMO_SLOTS; k++) {
        memo_slot *m = &c->slot[k];
        if (m->path && m->hash == h && strcmp(m->path, s->sample) == 0) {
            m->used = ++c->tick;
            *width = m->s.width, *hash = h;
            int rc = layer_impact_setup_check_sample(s, &m->s, m->settle, err);
            return rc == GW_OK ? pile_note(c, s->sample, h, &m->s, s->zero_springs, err) : rc;
        }
        if (m->used < old->used)
            old = m;
    }
    gw_layer_impact_plan p;
    layer_settling_memo *settle = calloc(1, sizeof *settle); /* NULL: found again by the next case */
    int rc = layer_impact_plan_make_memo(s, &p, settle, err);
    if (rc == GW_OK)
        rc = pile_note(c, s->sample, h, &p.sample, s->zero_springs, err);
    if (p.sample.x)
        *width = p.sample.width, *hash = h;
    /* kept when read, whatever this case's verdict (x outside the box is the case's) */
    const int keep = p.sample.x && p.sample.n <= MEMO_NMAX;
    char *path = keep ? strdup(s->sample) : NULL;
    if (keep && (!path || !settle)) {
        free(path);
        path = NULL;
        if (rc == GW_OK)
            rc = gw_err_set(err, GW_ENOMEM, "out of memory");
    }
    if (path) {
        free(old->path);
        gw_layer_sample_free(&old->s);
        free(old->settle);
        *old = (memo_slot){path, p.sample.content_hash, ++c->tick, p.sample, settle};
        memset(&p.sample, 0, sizeof p.sample);
    } else {
        free(settle);
    }
    gw_layer_impact_plan_free(&p);
    return rc;
}

static int check_memo_fn(void **memo, int nk, const char *const *names, const char *const *values, gw_err *err)
{
    gw_layer_impact_setup s;
    placement pl;
    double width = NAN;
    unsigned long long hash = 0;
    int rc = prepare(&s, nk, names, values, &pl, err);
    if (rc == GW_OK) /* the sample and the resolution: as the run checks them */
        if ((rc = setup_check(memo, &s, &width, &hash, err)) == GW_EINVAL)
            name_placement(&s, &pl, err);
    /* the points in the box's frame (its width is the sample's), and its x
     * against the other cases': for every sample the check read, kept in the
     * memo or not (above MEMO_NMAX particles the x check was skipped: x = 0,
     * 1e-300 ran one impact twice); only a pass without a memo (out of
     * memory for it) compares none */
    if (rc == GW_OK && memo && *memo && !isnan(width)) {
        rc = placement_distinct(&pl, width, err);
        if (rc == GW_OK)
            rc = x_note(*memo, hash, &pl, width, err);
    }
    if (rc == GW_OK && memo && *memo)
        settling_tally(*memo, &s);
    gw_layer_impact_setup_clear(&s);
    return rc == GW_OK || rc == GW_ENOMEM ? rc : GW_EINVAL;
}

static int check(int nk, const char *const *names, const char *const *values, gw_err *err)
{
    return check_memo_fn(NULL, nk, names, values, err);
}

/* A case's peak memory: the series it allocates for t-max (time, ledger 8,
 * block 4 and 4 per ring at each sample: 8 (13 + 4 rings) B a sample), times
 * 1.5 for the crowns analysis at the end, plus 16 MB for the model, the
 * 300-disc sample and the program. Measured (peak RSS of layer-impact --json
 * on the 300-disc sample): 14.5 MB at t-max 0.003 s; --rings 1000 --dt-out
 * 4e-6 --full at t-max 0.02 and 0.04 s: 251 and 486 MB for 161 and 321 MB of
 * series (1.47 times the series, plus the 14.5 MB). */
static int memory(int nk, const char *const *names, const char *const *values, double *bytes, gw_err *err)
{
    gw_layer_impact_setup s;
    int rc = prepare(&s, nk, names, values, NULL, err);
    if (rc == GW_OK) {
        const double nsamp = ceil(s.t_max / s.dt_out) + 2;
        *bytes = 16e6 + 1.5 * 8.0 * nsamp * (13.0 + 4.0 * (double)s.rings);
    }
    gw_layer_impact_setup_clear(&s);
    return rc == GW_OK || rc == GW_ENOMEM ? rc : GW_EINVAL;
}

/* NaN with a clear sign bit, so that every undefined value prints as "nan". */
static double canon(double v)
{
    return isnan(v) ? NAN : v;
}

int gw_layer_sweep_run_part(int nk, const char *const *names, const char *const *values, double *out,
                            unsigned long long *read_hash, void (*part)(void *pctx, double x), void *pctx,
                            gw_err *err)
{
    if (!out || (nk > 0 && (!names || !values)))
        return gw_err_set(err, GW_EINVAL, "gw_layer_sweep_run_part: %s is NULL",
                          !out ? "out" : !names ? "names" : "values");
    gw_layer_impact_setup s;
    gw_layer_impact_outcome o;
    memset(&o, 0, sizeof o);
    placement pl;
    int rc = prepare(&s, nk, names, values, &pl, err);
    if (rc == GW_OK) {
        /* its part: its simulated time over the end expected (layer_run_part) */
        rc = layer_impact_run_part(&s, NULL, NULL, part, pctx, &o, err);
        if (rc == GW_EUNSUPPORTED || rc == GW_EFORMAT || rc == GW_EIO) /* a bad input found only by the run */
            rc = GW_EINVAL;
        if (rc == GW_EINVAL)
            name_placement(&s, &pl, err);
    }
    if (rc == GW_OK) {
        const gw_layer_impact_result *r = &o.r;
        const double v[NCOLUMNS] = {s.x, r->bounced < 0 ? NAN : r->bounced, r->e_n, r->e, r->alpha_r_deg,
                                    r->v_ni, r->v_nr, r->v_r, r->penetration, o.penetration_rm,
                                    r->dissipated_first_contact, r->block_loss_first_contact, r->energy_error,
                                    r->wave_speed, r->t_end, (double)r->stats.steps, r->e_n_first, r->e_first,
                                    r->alpha_r_first_deg, r->v_nr_first, r->v_r_first, r->t_leave,
                                    r->t_rebound, r->t_f, r->settled_load_ratio, r->settling[0] ? 1 : 0,
                                    r->fell_off > 0 ? 1 : 0, r->slump_ke, (double)o.crowns_nulled};
        for (int i = 0; i < NCOLUMNS; i++)
            out[i] = canon(v[i]);
        /* the content hash of the sample bytes this run read (the sweep
         * compares it with the file's hash when it started) */
        unsigned long long h = 0;
        if (!o.sample_fnv1a64 || !gw_fnv1a64_parse(o.sample_fnv1a64, strlen(o.sample_fnv1a64), &h))
            rc = gw_err_set(err, GW_ENOMEM, "out of memory");
        else if (read_hash)
            *read_hash = h;
    }
    gw_layer_impact_outcome_free(&o);
    gw_layer_impact_setup_clear(&s);
    return rc;
}

static int run(int nk, const char *const *names, const char *const *values, double *out,
               unsigned long long *read_hash, gw_err *err)
{
    return gw_layer_sweep_run_part(nk, names, values, out, read_hash, NULL, NULL, err);
}

/* ---- a case's weight before it runs (gw_sweep_weigh) ----
 * Its bodies times its steps over the simulated time it is expected to run:
 * the discs and the block are stepped together at a fixed step (verlet's the
 * shortest contact time / 100, rk4's 1e-6 s, or dt), or an adaptive step
 * that the contacts bound alike. A run to the rebound ends at the block's
 * first free-flight maximum T_f, about REBOUND_E v_i / g after the impact
 * (its rebound speed over g; e measured below), or at t-max; a run to the
 * verdict, a full run or one without gravity runs to t-max (an upper bound
 * for the verdict). The sample's bodies and the step depend on the sample,
 * its materials and the solver, not on the speed, the point or the times:
 * found by a plan (the sample read) once per such case in the pass's memo. */
#define REBOUND_E 0.15
#define WEIGH_SLOTS 8

typedef struct weigh_slot {
    char *key; /* the case's pairs but those of the speed, the point and the times */
    double bodies, step;
    int kind; /* its backend, method and mode (GW_SWEEP_KIND; -1: none) */
} weigh_slot;

typedef struct weigh_memo {
    weigh_slot slot[WEIGH_SLOTS];
    int next;
} weigh_memo;

static int weigh_ignored(const char *name)
{
    static const char *const ignored[] = {"vi", "x", "alpha", "t_max", "dt_out", "until", "full", "rings",
                                          "ring_width", "energy_tol", "spacing", "point", "points"};
    char n[64];
    gw_snprintf(n, sizeof n, "%s", name);
    for (char *c = n; *c; c++)
        if (*c == '-')
            *c = '_';
    for (size_t i = 0; i < sizeof ignored / sizeof ignored[0]; i++)
        if (strcmp(n, ignored[i]) == 0)
            return 1;
    return 0;
}

static char *weigh_key(int nk, const char *const *names, const char *const *values)
{
    size_t len = 1;
    for (int i = 0; i < nk; i++)
        if (!weigh_ignored(names[i]))
            len += strlen(names[i]) + strlen(values[i]) + 2;
    char *k = malloc(len), *p = k;
    if (!k)
        return NULL;
    *p = '\0';
    for (int i = 0; i < nk; i++)
        if (!weigh_ignored(names[i]))
            p += gw_snprintf(p, len - (size_t)(p - k), "%s=%s\n", names[i], values[i]);
    return k;
}

static void weigh_memo_free(void *memo)
{
    weigh_memo *w = memo;
    if (!w)
        return;
    for (int i = 0; i < WEIGH_SLOTS; i++)
        free(w->slot[i].key);
    free(w);
}

static double weigh(void **memo, int nk, const char *const *names, const char *const *values, int *kind)
{
    gw_layer_impact_setup s;
    gw_err e = {{0}};
    double w = NAN;
    if (kind)
        *kind = -1;
    if (prepare(&s, nk, names, values, NULL, &e) != GW_OK) {
        gw_layer_impact_setup_clear(&s);
        return NAN;
    }
    weigh_memo *m = memo ? *memo : NULL;
    if (memo && !m)
        m = *memo = calloc(1, sizeof *m);
    char *key = m ? weigh_key(nk, names, values) : NULL;
    weigh_slot *hit = NULL;
    for (int i = 0; key && i < WEIGH_SLOTS && !hit; i++)
        if (m->slot[i].key && strcmp(m->slot[i].key, key) == 0)
            hit = &m->slot[i];
    weigh_slot found = {NULL, NAN, NAN, -1};
    if (!hit) {
        gw_layer_impact_plan p;
        if (gw_layer_impact_plan_make(&s, &p, &e) == GW_OK) {
            const double dem = layer_impact_dem_dt(&p.sample, &p.lp, &p.ip); /* (the plan checked it) */
            found.bodies = p.sample.n + 1.0;
            found.step = p.type == gw_solver_rk4 ? (p.sp.dt > 0 ? p.sp.dt : 1e-6)
                                                 : p.type == gw_solver_verlet && p.sp.dt > 0 ? p.sp.dt : dem;
            /* the exact mode stops at every event: its steps cost another pace */
            found.kind = GW_SWEEP_KIND(p.type, p.sp.method, s.exact);
        }
        gw_layer_impact_plan_free(&p);
        if (key) { /* kept, the oldest replaced */
            weigh_slot *k = &m->slot[m->next];
            m->next = (m->next + 1) % WEIGH_SLOTS;
            free(k->key);
            *k = (weigh_slot){key, found.bodies, found.step, found.kind};
            key = NULL;
        }
        hit = &found;
    }
    free(key);
    double end = s.t_max;
    if (!s.full && s.until != GW_LAYER_UNTIL_VERDICT && s.gravity > 0 && s.vi > 0)
        end = fmin(s.t_max, REBOUND_E * s.vi / s.gravity);
    if (hit->bodies > 0 && hit->step > 0 && end > 0)
        w = hit->bodies * end / hit->step;
    if (kind)
        *kind = hit->kind;
    gw_layer_impact_setup_clear(&s);
    return isfinite(w) && w > 0 ? w : NAN;
}

const gw_sweep_weigh gw_layer_sweep_weigh = {weigh, weigh_memo_free};

const gw_sweep_model gw_layer_sweep_model = {"layer",  NCOLUMNS, columns,       has_key,  run,
                                             check,    memory,   "sample",      check_memo_fn, memo_free,
                                             memo_warnings};

/* ---- the crowns' warnings over the rows (gw_sweep_rows_rule) ----
 * A case's crown speeds nulled by a rule are said by a warning of its single
 * run, which the table's row alone did not carry: `sweep` over the 40-disc
 * pile of `layer-make --n 40` at vi = 10, 20 with until = verdict gave every
 * row's wave_speed nan and no "# warning:" line. The row's crowns_nulled
 * (GW_LAYER_NULLED_* bits) is counted here, one line per rule, from the
 * rows alone: the same on a resume, over threads and MPI ranks. */
static const struct {
    int bit;
    const char *what;
} nulled_kinds[] = {
    {GW_LAYER_NULLED_SAMPLING, "by the sampling (dt-out too coarse for the crowns, or the first impact sampled "
                               "under 4 times): give a smaller dt-out"},
    {GW_LAYER_NULLED_CUT, "by the run's end before the wave's strain peaks reached 3 rings (t-max, the bounce "
                          "verdict of until = verdict, or no bounce): raise t-max, or until = rebound or full = 1"},
    {GW_LAYER_NULLED_LOCKED, "as following the pile's slow motion over the first impact, not the wave "
                             "(undecided)"},
    {GW_LAYER_NULLED_SCATTER, "for their scatter (a standard error at or above half the speed; undecided)"},
};
#define NKINDS ((int)(sizeof nulled_kinds / sizeof nulled_kinds[0]))

typedef struct nulled_acc {
    long total, n[NKINDS], first[NKINDS];
} nulled_acc;

static void nulled_row(void *acc, const gw_sweep_config *cfg, long k, const double *row)
{
    (void)cfg;
    nulled_acc *a = acc;
    const double v = row[NCOLUMNS - 1];
    a->total++;
    if (!(v > 0) || !(v < 256))
        return;
    for (int q = 0; q < NKINDS; q++)
        if ((int)v & nulled_kinds[q].bit) {
            if (a->n[q] == 0 || k < a->first[q])
                a->first[q] = k;
            a->n[q]++;
        }
}

static int nulled_warnings(const void *acc, const gw_sweep_config *cfg, char **list)
{
    const nulled_acc *a = acc;
    int rc = GW_OK;
    for (int q = 0; q < NKINDS && rc == GW_OK; q++)
        if (a->n[q] > 0)
            rc = gw_warnings_add(list, "crowns: %ld of %ld cases have a crown speed (wave_speed, wave_speed_kinetic "
                                 "or wave_speed_xcorr) null %s; the first, case %ld; their crowns_nulled column "
                                 "holds %d (a single run of the case says which)", a->n[q],
                                 cfg ? cfg->ncases : a->total, nulled_kinds[q].what, a->first[q],
                                 nulled_kinds[q].bit);
    return rc;
}

static const gw_sweep_rows_rule nulled_rule = {sizeof(nulled_acc), nulled_row, nulled_warnings};

/* One value of a key as a case takes it (gw_sweep_value_rule: what
 * layer-stats holds a table's settings to): a number row of the placement or
 * of the impact, set as prepare() sets it (gw_param_set's checks: range,
 * integer, no subnormal); any other name is not this rule's. */
static int value_rule(const char *name, const char *value, gw_err *err)
{
    if (!name || !value)
        return GW_OK;
    const gw_param *p = gw_param_find(placement_params, name);
    if (!p && has_key(name))
        p = gw_param_find(gw_layer_impact_setup_params(), name);
    if (!p)
        return GW_OK;
    return gw_sweep_number_check(p, value, err);
}

/* The sweep's rules for the samples it hashes: the sample reader's
 * (layer_sample_file_check), and for one value of a key (value_rule),
 * registered when the library is loaded */
__attribute__((constructor)) static void input_rule(void)
{
    gw_sweep_input_rule_set(gw_layer_sweep_model.name, layer_sample_file_check);
    gw_sweep_value_rule_set(gw_layer_sweep_model.name, value_rule);
    gw_sweep_rows_rule_set(gw_layer_sweep_model.name, &nulled_rule);
}
