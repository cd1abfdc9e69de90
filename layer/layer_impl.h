/*
 * layer_impl.h (private to layer/): the gw_layer object shared by the model
 * (layer_model.c), the contact list (layer_contacts.c) and the run driver
 * (layer_sim.c).
 */
#ifndef GW_LAYER_IMPL_H
#define GW_LAYER_IMPL_H

#include <math.h>

#include "gw_layer.h"
#include "layer_plan_run.h"

/* Sliding margin of the tangential state outside the Coulomb cap and its
 * restoring rate (layer_model.c): LAYER_CAP_RATE 1/s for the adaptive
 * backends, LAYER_CAP_RATE_STEP / dt for the fixed-step rk4 (1e4 /s at its
 * default 1 us), so that the rate keeps its place among the run's time scales
 * when they scale (gw_layer.cap_rate). */
#define LAYER_CAP_MARGIN 1e-4
#define LAYER_CAP_RATE 1e4
#define LAYER_CAP_RATE_STEP 1e-2

/* Zeno guard of layer_sim.c: events closer than LAYER_ZENO_DT s, how many in a
 * row trigger it, and how long the contact roots stay off (for rk4 the
 * _STEP values times its step: the same at its default 1 us). */
#define LAYER_ZENO_DT 1e-12
#define LAYER_ZENO_COUNT 20
#define LAYER_ZENO_QUIET 1e-7
#define LAYER_ZENO_DT_STEP 1e-6
#define LAYER_ZENO_QUIET_STEP 0.1
/* ... and its wide tier: more than LAYER_ZENO_WIDE_COUNT events in a row, each
 * within LAYER_ZENO_WIDE zeno_dt of the one before. A contact chattering under
 * arkode at rtol 1e-5 (a 40-disc sample, t = 34.6 ms) stopped every 1.0e-12 to
 * 1.2e-12 s, just past the window, 85,314 times in a row: the run did not
 * advance for minutes. Ordinary runs measured: at most 21 such events in a
 * row (arkode at 1e-7 on the same sample, 34,658 events). */
#define LAYER_ZENO_WIDE 100
#define LAYER_ZENO_WIDE_COUNT 200

/* The DEM step's hot loops (layer_dem.c's drift, the samples' ledgers) are
 * compiled twice, for AVX and for the baseline x86-64, and the program runs
 * the one its CPU has (chosen when it loads: GCC's target_clones, an ELF
 * ifunc). AVX without FMA does the same IEEE operations in the same order,
 * so the numbers are the same to the last bit; its three-operand encoding
 * only drops the register copies of SSE2's two-operand form (16 % of the
 * drift's instructions on the default impact). Off elsewhere (other
 * compilers or CPUs, or -DGW_NO_CLONES). */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__) && \
    !defined(GW_NO_CLONES) && !defined(__AVX__)
#define LAYER_HOT __attribute__((target_clones("avx", "default")))
#else
#define LAYER_HOT
#endif

/* Walls are contact partners with negative ids. */
enum { LAYER_LEFT = -1, LAYER_RIGHT = -2, LAYER_BOTTOM = -3 };

/* Overlap and outward unit normal of a disc of radius ra centred at p against
 * wall (LAYER_LEFT, LAYER_RIGHT or LAYER_BOTTOM) of a box of width w. */
static inline double layer_wall_overlap(int wall, double ra, const double p[2], double w, double n[2])
{
    switch (wall) {
    case LAYER_LEFT:
        n[0] = -1, n[1] = 0;
        return ra - p[0];
    case LAYER_RIGHT:
        n[0] = 1, n[1] = 0;
        return ra - (w - p[0]);
    default: /* LAYER_BOTTOM */
        n[0] = 0, n[1] = -1;
        return ra - p[1];
    }
}

typedef struct layer_contact {
    int a, b;        /* particle a < b, or b = LAYER_* wall */
    int qa, qb;      /* bodies of a and b (qb = b for a wall) */
    double kn;       /* K_n (B.3) */
    double kts;      /* k_t K_n^(1/3), k_t from K_t = k_t F_n^(1/3) (B.4): K_t = kts
                        sqrt(u_n), no cube root in the loop */
    double ra, rb;   /* radii of a and b (rb = 0 for a wall) */
} layer_contact;

/* The block as the watch roots saw it (layer_watch.c): time, the two watch
 * functions (v_y, largest overlap), centre and velocity. */
typedef struct layer_probe {
    double t, g[2], x, y, vx, vy, ay;
} layer_probe;

/* The block's first contact with one disc (layer_watch_first_contact), read at
 * every evaluation of the watch roots (in DEM mode every step end), not at the
 * samples: from the touch to the block's smallest kinetic energy while it
 * still touches that disc, and the contact's opening (the overlap's zero
 * between two evaluations, by linear interpolation). ed: the ledger's
 * dissipation E_d then, edb the block region's part of it (NaN without
 * regions). Frozen at the impact's verdict (layer_watch_first_contact_freeze):
 * what comes after it depends on where the run stops, the first output sample
 * after the verdict or t-max with --full. J, s. */
typedef struct layer_first_contact {
    int target;            /* the disc watched, -1: off */
    int frozen;            /* the verdict is in: no more updates */
    int n_touch;           /* evaluations that saw it overlapped before it opened */
    double kb_min, t_min, ed_min, edb_min;
    double t_open, ed_open, kb_open; /* NaN until it opens */
    double t_last, ov_last, ed_last, kb_last, edb_last; /* the last evaluation that saw it overlapped */
    /* the overlapped evaluations next to the smallest kb in time, before (lo)
     * and after (hi) it: t, kb, ed, edb (t NaN: none yet) */
    double lo[4], hi[4];
} layer_first_contact;

struct gw_layer {
    gw_layer_params p;
    double tan_phi;
    int n, block;      /* discs; the block's disc index (-1: none) */
    /* Rigid bodies (layer_clumps.c): nb bodies, disc i belongs to body bid[i]
     * and sits at off[2 i .. 2 i + 1] from its centre of mass in the body frame.
     * Without clumps bid = off = NULL and body i is disc i (the disc-only code
     * path, kept bit for bit). */
    int nb, block_body;
    int *bid;
    double *off;
    double *r;         /* [n] disc radii */
    double *m, *inertia, *minv, *iinv; /* [nb] per body; minv = iinv = 0 when fixed */
    double *brad;      /* [nb] bounding radius of the body (r for a disc) */
    unsigned char *fixed; /* [nb] */
    double *y_ref;     /* [nb] potential-energy reference heights */
    double rmax;       /* largest disc radius */
    /* contact list */
    layer_contact *c;
    int nc, cap_c;
    double *x_list;    /* [2n] disc positions at the last list build */
    /* state and solver */
    double t;
    double *y;         /* [dim] */
    double *scale;     /* [dim] */
    long dim, cap_y;
    gw_system sys;
    gw_solver *solver;
    const gw_solver_type *type;
    gw_solver_params sp;
    int *roots;        /* [nroots] */
    double e0;         /* A */
    /* Energy regions (gw_layer_set_regions): rings of width reg_w around
     * (reg_cx, reg_cy), then "outside", then "block"; ntail = 2 + 2 (reg_n + 2)
     * state components after the contacts (E_d, W_K, then E_d and W_K per
     * region), or 2 without regions. */
    double reg_cx, reg_cy, reg_w, reg_iw2; /* reg_iw2 = 1/reg_w^2 */
    int reg_n, ntail;
    double v_scale, u_scale, f_scale, e_scale;
    gw_layer_stats st;
    double t_event, quiet_until; /* Zeno guard (layer_sim.c) */
    long adv_steps0;             /* the steps taken when gw_layer_advance was called (its bound) */
    int adv_over;                /* 1: that call went past its bound (layer_sim.c) */
    double peek;                 /* layer_advance_peek's time while it runs, else 0 */
    double zeno_dt, zeno_quiet;  /* its window and quiet time, s (gw_layer_start) */
    double cap_rate;             /* the sliding margin's restoring rate, 1/s (gw_layer_start) */
    int storm, storm_wide, no_events_user;
    gw_layer_event_fn hook;
    void *hook_ctx;
    /* Block watch (gw_layer_watch_block, layer_watch.c): two roots after the
     * others; probe[1] is the block at the last evaluation of the roots,
     * probe[0] at the one before (in DEM mode: the end and the start of the
     * last step); ext the running extremes. */
    int watch;
    int gone;          /* the block left the layer for good: GW_LAYER_BLOCK_GONE reported */
    gw_layer_block_fn watch_fn;
    void *watch_ctx;
    layer_probe probe[2];
    gw_layer_block_extremes ext;
    /* The evaluations around the largest v_y (layer_watch.c): [1] the largest,
     * [0] the latest before it in time and [2] the earliest after it (t NaN:
     * none yet); t, v_y, dv_y/dt, v_x and the largest overlap g_c at each. */
    double vb_t[3], vb_vy[3], vb_ay[3], vb_vx[3], vb_gc[3];
    layer_first_contact fc; /* layer_watch_first_contact: the block on disc fc.target */
    /* The listed contacts that touch the block (indices into c), for the watch
     * roots: made for list number wblk_gen (st.rebuilds) and body wblk_body. */
    int *wblk, nwblk, wblk_body;
    long wblk_gen;
    /* Explicit DEM mode (the verlet backend): no contact events; drift maps
     * positions to velocities; un_last[k] is contact k's overlap at the last rhs
     * evaluation (0 when open), which for verlet is the state at the step end:
     * the start of the next step for layer_dem_drift (layer_dem.c). */
    int dem;
    /* The list rebuild is checked at the ends of the steps, unlocated, with a
     * margin (layer_roots): DEM mode, and rk4 without events or a block watch
     * (the pluviation), which then also zeroes F_t of open contacts after every
     * step (layer_step_project): the step grid and the state then do not depend
     * on the skin. */
    int stepend;
    long *drift;        /* [cap_y] */
    double *un_last;    /* [cap_c] */
    /* DEM mode, discs only: a contact open at both ends of a step with a gap
     * g sleeps (drift_discs, layer_dem.c) until the travel of its two discs
     * since then may have closed it: travel[i] sums a bound of how far disc i
     * has moved since the list was built (2 h (|v_x| + |v_y|) per step, v the
     * half-step velocity), wake[k] the travel sum of contact k's discs at
     * which it wakes (0: awake). Both new with every list. */
    double *wake;       /* [cap_c] */
    double *travel;     /* [nb + 1]; travel[nb] = 0, a wall's */
    int *tix;           /* [2 cap_c]: the travel indices of contact k's two discs
                           (qa, and qb or nb for a wall) */
    struct layer_tscr *tscr; /* [cap_c], DEM mode only */
    /* DEM mode, discs only: the drift's scratch for the contacts a step works
     * on (drift_discs, layer_dem.c): their indices, and LAYER_DEM_W arrays of
     * nc + 1 doubles each (inputs and results of its three passes). */
    int *dem_act;       /* [cap_c + 1] */
    double *dem_w;      /* [LAYER_DEM_W (cap_c + 1)] */
    /* The exact mode's tangential branch per contact, held through the steps
     * and switched only where the solver stops (layer_tmode_update,
     * layer_sim.c): 1 at the Coulomb cap, 0 inside it. Read by the rhs while
     * tmode_on (the stick/slip roots are located: not in DEM mode, not without
     * events); otherwise each evaluation compares |F_t| with the cap. */
    unsigned char *tmode;
    int tmode_cap, tmode_on;
    /* 1: the tail's second entries (global and per region) hold the tangential
     * work E_st + W_K, from which the ledger subtracts E_st (the state
     * function) to give W_K: the rate form (not DEM mode), where W_K's own
     * rate is near-singular at phi near 90 deg (layer_tangential). 0: W_K
     * itself (DEM mode books it per step, layer_dem.c). Set by gw_layer_start,
     * which converts the tail when it changes. */
    int tail_work;
    double *ymid;       /* [6 nb], DEM mode: the mid-step state (layer_dem.c) */
    double *dem_book;   /* [ntail], DEM mode: the ledger increments of a step */
    double *geo;        /* [4 cap_c], DEM mode, discs only: u_n, sqrt(u_n), normal
                           of the step's end positions (layer_dem_drift) */
    double *facc;       /* [3 nb], DEM mode, discs only: contact forces and torques
                           per body at the step's end (layer_dem.c) */
    double *dem_rate;   /* [ntail], DEM mode, discs only: the ledger tail's rates */
    /* A list rebuild in DEM mode re-creates the solver, whose first rhs call
     * would evaluate the velocity-dependent rates (the normal damping, its
     * ledger) at the step's final velocities, where the running verlet step
     * has them at its predicted ones: the trajectory then depended on when
     * the skin made the list rebuild. The rebuild keeps the old solver's rates
     * instead (gw_solver_rates): the bodies' 6 nb, then the tail's ntail (the
     * contacts' rates are 0 in DEM mode), and the new solver's first rhs call
     * hands them back when dem_carry is set (layer_dem_carried). */
    double *dem_f;      /* [6 nb + ntail], DEM mode */
    int dem_carry;
    /* DEM mode: the start of a step that holds a peek (layer_advance_peek),
     * kept by its drift (layer_dem_peek_keep) for the samples in it
     * (layer_dem_peek): the bodies' half-step state ph and predicted end y
     * (pk_y[0, 12 nb); after them 12 nb + ntail of the sample's scratch), and
     * each contact's F_t, overlap, K_t, 1/K_t and region at the step's start.
     * The step is (pk_t0, pk_t0 + pk_h]; pk_valid 0: none kept (a new list). */
    double *pk_y;       /* [24 nb + ntail + 1] */
    struct layer_pkc *pk_c; /* [cap_c] */
    double pk_t0, pk_h;
    int pk_valid;
    int listed;        /* 1 once a contact list was built (layer_contacts.c) */
    int geo_valid;      /* facc and dem_rate hold the state the next rhs sees */
    int geo_pos;        /* geo holds the positions of the last rhs evaluation
                           (layer_dem_rhs; 0 after a list rebuild) */
    int geo_peek;       /* 1 while y holds a state read between two steps
                           (layer_advance_peek under verlet): geo_pos is then 0,
                           so that the snapshot reads y, and comes back at the
                           next advance (geo the solver's state's again) */
    /* Contact snapshot for the ledger and ring analyses (layer_snapshot): one
     * pass of contact geometry per state, shared by every consumer. stamp
     * counts the changes of y; snap_stamp is the stamp the snapshot was made at. */
    unsigned long stamp, snap_stamp;
    double *snap;       /* [6 cap_c]: u_n, F_n (elastic), F_t used, K_t, contact point x, y */
    double *snap_xy;    /* [2 n] disc centres */
    int *snap_breg;     /* [nb] region of each body by its centre (layer_body_region;
                           0 without regions) */
    int *ring_np;       /* [ring_cap] scratch of gw_layer_rings */
    size_t ring_cap;
    /* A sample's tangential springs for the first contact list
     * (layer_springs_pend; sorted by pair, freed once loaded by
     * gw_layer_start, layer_springs_load). */
    gw_layer_spring *spr;
    int nspr;
};

/* Contact k of the snapshot (layer_snapshot). */
enum { LAYER_SNAP_UN, LAYER_SNAP_FN, LAYER_SNAP_FT, LAYER_SNAP_KT, LAYER_SNAP_PX, LAYER_SNAP_PY,
       LAYER_SNAP_W };

/* The snapshot of state L->y, made if y changed since the last one: per
 * contact (LAYER_SNAP_W doubles each) u_n, elastic F_n, used F_t, K_t (all 0
 * when open) and the contact point; disc centres in L->snap_xy. */
const double *layer_snapshot(const gw_layer *L);

/* Overlap u_n of contact c whose discs are centred at pa and pb (pb unused
 * against a wall), box width w; its unit normal n (a -> b). layer_model.c,
 * shared with the snapshot (layer_snapshot.c). */
double layer_pair_geometry(const layer_contact *c, const double pa[2], const double pb[2], double w,
                           double n[2]);

/* Region of body i by its centre of mass in state y: the ring (0 .. reg_n - 1),
 * reg_n outside them, reg_n + 1 for the block. */
static inline int layer_body_region(const gw_layer *L, int i, const double *y)
{
    if (i == L->block_body)
        return L->reg_n + 1;
    const double *s = y + 6 * i;
    double dx = s[0] - L->reg_cx, dy = s[1] - L->reg_cy, d = sqrt(dx * dx + dy * dy) / L->reg_w;
    return d < L->reg_n ? (int)d : L->reg_n;
}

/* Ring index of the offset (dx, dy) from the centre for rings of width w, or
 * -1 beyond the last ring (the distance truncated, as (int)(hypot / w)). */
static inline int layer_ring_of(double dx, double dy, double w, int nring)
{
    double d = sqrt(dx * dx + dy * dy) / w;
    return d < nring ? (int)d : -1;
}

/* gw_layer_ledgers (e given; regions may be NULL) and gw_layer_rings of the
 * same state, in one pass when the rings are the regions' (same centre, width
 * and count) in DEM mode with discs only, else by the two calls; the same
 * numbers either way. diss (may be NULL) gets the rings' E_d when the rings
 * are the regions (NaN otherwise): the regions' sums are then not needed at
 * every sample (layer-impact reads them once, at the end). Returns the
 * region count written (0 without regions). */
int layer_ledgers_rings(const gw_layer *L, gw_layer_energy *e, gw_layer_energy *regions, double cx, double cy,
                        double w, int nring, double *kin, double *strain, double *coord, double *diss);

/* layer_body_region knowing the body's region q0 at a nearby earlier state:
 * q0 when the centre is still in that ring (or still outside them), without
 * the square root. */
static inline int layer_body_region_near(const gw_layer *L, int i, const double *y, int q0)
{
    if (q0 >= 0 && q0 <= L->reg_n && i != L->block_body) { /* a ring, or outside them */
        const double *s = y + 6 * i;
        double dx = s[0] - L->reg_cx, dy = s[1] - L->reg_cy;
        double d2 = (dx * dx + dy * dy) * L->reg_iw2;
        if ((double)q0 * q0 <= d2 && (q0 == L->reg_n || d2 < (double)(q0 + 1) * (q0 + 1)))
            return q0;
    }
    return layer_body_region(L, i, y);
}

/* Region of a contact from its contact point (px, py): as
 * layer_contact_region_at. */
static inline int layer_contact_region_pt(const gw_layer *L, const layer_contact *c, double px,
                                          double py)
{
    /* (the block's region only where there is a block: without one block_body
     * is -1, the left wall's body code, and a library layer with regions
     * counted its left-wall contacts in the block's region) */
    if (L->block_body >= 0 && (c->qa == L->block_body || c->qb == L->block_body))
        return L->reg_n + 1;
    double dx = px - L->reg_cx, dy = py - L->reg_cy;
    double d2 = (dx * dx + dy * dy) / (L->reg_w * L->reg_w);
    double lim = (double)L->reg_n * L->reg_n;
    return d2 < lim ? (int)sqrt(d2) : L->reg_n;
}

/* layer_contact_region_pt knowing the contact's region q0 (-1: unknown) at a
 * nearby earlier point: q0 when the point is still in that ring, without the
 * square root. */
static inline int layer_contact_region_near(const gw_layer *L, const layer_contact *c, double px,
                                            double py, int q0)
{
    if (q0 >= 0 && q0 < L->reg_n && ((c->qa != L->block_body && c->qb != L->block_body) || L->block_body < 0)) {
        double dx = px - L->reg_cx, dy = py - L->reg_cy;
        double d2 = (dx * dx + dy * dy) * L->reg_iw2;
        if ((double)q0 * q0 <= d2 && d2 < (double)(q0 + 1) * (q0 + 1))
            return q0;
    }
    return layer_contact_region_pt(L, c, px, py);
}

/* The number of arrays in gw_layer.dem_w (drift_discs, layer_dem.c): v_t,
 * u_n, K_s and k_ts in; sqrt(u_n), 1/K_e, K_m and 1/K_m out. */
enum { LAYER_DEM_W = 8 };

/* A settled pile rests on the floor: the floor's Hertz forces carry its weight
 * (0.88 to 1.006 of it measured, wall friction holding the rest). Above this
 * many times the weight a pile is not at rest: layer-make goes on settling
 * (layer_make.c) and layer-impact refuses the sample
 * (gw_layer_impact_rest_check). */
#define LAYER_FLOOR_LOAD_MAX 1.5
/* The share of a pile's weight a side wall an impact takes away may carry
 * (its normal and friction forces' resultant, layer_side_walls_rest_check):
 * piles at rest against their walls measured 0.26 (the stored 300-disc pile)
 * and 0.51 (`layer-make --n 40 --width-rm 14 --seed 2 --ke-threshold 1e-2`,
 * its right wall), the wedged narrow clump piles 1.29 (`--clumps --width-rm
 * 6 --n 20 --seed 1`) and 2.2 to 4.7 (--n 40, seeds 1 to 4).
 * Measured in session 46 over 47 piles (46 of layer-make, discs and clumps, n
 * 20 to 100, width 4 to 20 R_m, seeds 1 to 4, friction 10 to 45 deg, G 4e9, the
 * sphere law, a loose ke-threshold; and the stored 300-disc pile), each run
 * 0.05 s with its more loaded wall taken away under a block of 0.2 R_m at 0.5
 * m/s: the slump grows with this load and no value separates it sharply. Piles
 * at 0.13 to 1.54 reach 4e-5 to 2.3e-3 M g R_m of kinetic energy by 5 ms (their
 * open face falling; 9.5e-4 to 2.9e-2 by 0.05 s), piles at 1.76 to 29 spring
 * out: 5.3e-3 to 0.12 M g R_m by 5 ms, 0.97 to 1 of the strain energy they held
 * released by 0.05 s (--n 40 --width-rm 10 --shear-modulus 4e9 at 1.76, --n 80
 * --width-rm 10 seeds 1 and 2 at 2.27 and 2.0, --n 20 --width-rm 4 at 29). Kept
 * at 1: it refuses the 10 measured piles at 1.04 to 1.54 (slumping as mildly as
 * those below), and leaves a margin of 1.76 to the first pile that springs out. */
#define LAYER_SIDE_WALL_LOAD_MAX 1.0
/* Below this many times the weight the floor does not carry the pile: a pile
 * with a small E_k at the top of a bounce is in the air (layer-make --n 20 at
 * --ke-threshold 0.1 to 1 was called settled with a floor load of 0, at 0.01
 * with 0.47, landing), and layer-make goes on settling. A pile at rest that
 * the floor carries less than this of is one the side walls' friction holds
 * (Janssen): 0.88 in a 12 R_m box, 0.84 for 300 discs in an 8 R_m box
 * still settling at 6 s, 0.54 for 100 discs settled in a 4 R_m column 114 R_m
 * tall; only taller and narrower columns fall below half, and layer-make then
 * calls the pile settled when the floor and the side walls together carry half
 * its weight or more (held_by_walls, layer_make.c; a narrow clump pile rests
 * with 0.2 on its floor), else warns that it did not settle, naming the
 * floor's load. Half the
 * weight: every measured pile at rest (0.54 to 1.006) passes, the piles in
 * the air above (0 to 0.47) do not. An impact on a pile whose settled line
 * says converged 1 and whose floor carries less warns (layer_settled.c). */
#define LAYER_FLOOR_LOAD_MIN 0.5
/* layer-make's settling (layer_make.c) looks at the pile every
 * LAYER_SETTLE_CHUNK s (a check). A pile the side walls help hold
 * (layer_load_rests by the walls' share, held_by_walls) must pass the rest
 * rules at LAYER_WALL_CALM_CHECKS successive checks to be called settled: one
 * instant is not a pile at rest. `--clumps --width-rm 6 --n 40 --seed 4` was
 * called settled at 4.47 s at a dip of its E_k to 0.88 of the threshold, its
 * floor carrying 2.25 of the weight and the walls -1.24; run on, the pile
 * rocks between its walls, E_k below the threshold for 5 to 10 checks at a
 * time (4.47 to 4.56 s, 5.15 to 5.21, 5.52 to 5.56, 5.76 to 5.80, 5.93 to
 * 5.97) and 5 to 84 times it in between. A pile its floor alone carries is
 * judged at one check, as before (the default pile's sample unchanged; at 2
 * checks for every pile the default pile settled one check later, 4.18 s for
 * 4.17, a sample of its own).
 * The span, 20 checks (0.2 s), is fixed, not the pile's own period: measured
 * (session 43) on the wall-held piles `--clumps --width-rm W --n N --seed S`
 * (W N S = 6 40 3, 6 40 4, 6 40 5, 6 60 1, 6 60 2, 8 80 1; t-max 6 s), it
 * is 4.5 to 9 of the pile's elastic periods on its floor contacts,
 * T = 2 pi sqrt(M / sum 1.5 K_n sqrt(u)): 0.033, 0.023, 0.023, 0.044, 0.042
 * and 0.042 s (the walls' contacts only stiffen it), and twice the longest
 * calm spell of a pile that went on rocking: seed 4's E_k passed the rules
 * for 10, 7, 5, 5 and 5 checks between 4.47 and 6 s (below the threshold
 * again every 0.16 s at the median, its log E_k correlated again at 1.1 s),
 * 8 80 1's for 1, 1, 1 and 3 before it settled at 3.65 s, 6 60 1's for 2;
 * every pile that settled passed its 20 checks in its first or second spell
 * after 2.5 s (6 40 3 at 2.66 s, 6 40 5 at 3.10, 6 60 1 at 3.75, 6 60 2 at
 * 2.78). A span of a few elastic periods (0.07 to 0.13 s at 3) would take
 * seed 4's spell of 10 checks (0.1 s) for rest. */
#define LAYER_SETTLE_CHUNK 0.01
#define LAYER_WALL_CALM_CHECKS 20
/* Whether a pile whose floor carries f and whose side walls carry walls
 * (upward; negative: pulling it down; 0 without side walls or springs) of a
 * weight w (any one unit) rests on its supports: the floor alone, or the floor
 * and the side walls together, carry between LAYER_FLOOR_LOAD_MIN and
 * LAYER_FLOOR_LOAD_MAX times w. The one rule layer-make settles by
 * (held_by_walls, layer_make.c), its did-not-settle warning states
 * (gw_layer_make_result_warnings, from floor_load and wall_load) and
 * layer-impact's rest check refuses by (layer_rest_check). NaN: 0. */
int layer_load_rests(double f, double walls, double w);

/* The floor's Hertz forces (N, *f) and the weight (N, *w) of n discs under
 * lp's material and gravity, with centre heights y and radii r, the i-th of
 * each stride bytes after the first. */
void layer_floor_load(const gw_layer_params *lp, int n, const double *y, const double *r, size_t stride, double *f,
                      double *w);
/* The upward force (N, negative: downward) the side walls' friction exerts on
 * the pile of smp through the tangential springs it keeps against the left and
 * right walls, under lp's material and a friction angle of friction_deg, as
 * an impact loads them (layer_settled.c). */
double layer_sample_wall_hold(const gw_layer_sample *smp, const gw_layer_params *lp, double friction_deg);
/* The same of one side wall (side GW_LAYER_SPRING_LEFT or _RIGHT; 0: both,
 * layer_sample_wall_hold, summed in the springs' order). */
double layer_sample_side_hold(const gw_layer_sample *smp, const gw_layer_params *lp, double friction_deg, int side);
/* gw_layer_impact_rest_check with other_settling: 1 allows the floor load the
 * sample's recorded settling explains, LAYER_FLOOR_LOAD_MAX q times the weight
 * (q = gw_layer_settled_load_ratio above 1), as other-settling allows the
 * settling check's q (layer-impact and a layer sweep, with the warning
 * gw_layer_impact_settled_check records); 0 is gw_layer_impact_rest_check. */
/* A pile an impact keeps without a side wall (ip->side_walls other than
 * both, the floor kept) must rest on its floor alone, and each wall taken
 * away carry at most LAYER_SIDE_WALL_LOAD_MAX of its weight, under the
 * material the sample records it settled with, else lp's (NULL: the
 * default material): GW_EINVAL naming side-walls, the floor's and the walls'
 * shares, otherwise (layer_impact.c; the run, a plan's or a sweep case's
 * check, and gw_layer_impact_check with lp NULL: one rule). */
int layer_side_walls_rest_check(const gw_layer_sample *smp, const gw_layer_params *lp,
                                const gw_layer_impact_params *ip, gw_err *err);
int layer_rest_check(const gw_layer_sample *smp, const gw_layer_params *lp, int other_settling, const char *name,
                     double q, gw_err *err);
/* gw_layer_impact_settled_check on a sample that passed the shared check
 * (layer_sample_limits_check: smp and lp not NULL; the public call checks
 * them, a run, the plan and the sweep's tally took it before), and into *q
 * gw_layer_settled_load_ratio of smp under lp, found once (NaN: nothing
 * recorded, or a refusal before it was found): the ratio weighs a union-clump
 * pile hit under clump-mass sum (or the reverse) by building its model, 0.014
 * s for 150 clumps, and a run needs it for the check, its result and the rest
 * check. */
int layer_settled_check_q(const gw_layer_sample *smp, const gw_layer_params *lp, int other_settling,
                          const char *name, char *warning, size_t n, double *q, gw_err *err);
/* gw_layer_settled_load_ratio of a sample that passed the shared check. */
double layer_settled_load_ratio(const gw_layer_sample *smp, const gw_layer_params *lp);

/* The rules of the impact's public checks on a sample that passed the shared
 * check (layer_sample_shape_check), so that a run takes that O(n) check once
 * (layer_impact_run), each public check taking it first:
 * layer_impact_params_check is gw_layer_impact_check's rules of the impact
 * (springs unless zero_springs, block, speed, gap's range, times, x, height);
 * layer_impact_gap_rules gw_layer_impact_gap_check's (the fall, the drift,
 * the reach), layer_impact_fall_rule gw_layer_impact_fall_check's, with
 * gap_default 1 when the gap is the default's, not given (the refusal of a
 * slow impact then names vi and the default gap, else the gap): the public
 * calls take a gap at the default's value as not given, the setup knows
 * (layer_setup.c); layer_impact_dem_dt gw_layer_impact_dem_dt's step. */
int layer_impact_params_check(const gw_layer_sample *smp, const gw_layer_impact_params *p, gw_err *err);
int layer_impact_gap_rules(const gw_layer_sample *smp, const gw_layer_impact_params *p, double g, int gap_default,
                           gw_err *err);
int layer_impact_fall_rule(const gw_layer_impact_params *ip, double g, int gap_default, gw_err *err);
/* The state at tpeek (L->t, L->y), on the way to tout, without a stop there:
 * the solver (cvode, rk4) makes the steps and roots of gw_layer_advance(L, tout),
 * and the next gw_layer_advance(L, tout) goes on from where it is (its roots
 * and outputs as if no peek had been made). Another backend stops at tpeek
 * (gw_layer_advance(L, tpeek)). GW_OK, or gw_layer_advance's failures. */
int layer_advance_peek(gw_layer *L, double tpeek, double tout, gw_err *err);
/* 1 when layer_advance_peek does not stop the run at tpeek (cvode, arkode, rk4, verlet) */
int layer_can_peek(const gw_solver_type *type);
double layer_impact_dem_dt(const gw_layer_sample *s, const gw_layer_params *lp, const gw_layer_impact_params *ip);
/* layer_settling_found and layer_impact_run: layer_plan_run.h (the program
 * runs them too) */

/* What the last rhs evaluation found of a closed frictional contact, kept in
 * DEM mode for the next step (layer_dem.c): K_t at the step's start and the
 * contact's region (-1: none). */
typedef struct layer_tscr {
    double kt, ikt; /* K_t and 1/K_t */
    int q;
} layer_tscr;

/* A contact at the start of a step that holds a peek (gw_layer.pk_c): F_t,
 * the overlap (0 when open) and what layer_tscr holds. */
typedef struct layer_pkc {
    double f, u, kt, ikt;
    int q;
} layer_pkc;

/* The Coulomb cap F_n tan(phi) of a contact of stiffness kn at overlap un (0
 * when open), rounded as the right-hand side rounds it (layer_model.c: tp (kn
 * un sqrt(un)), the elastic F_n first). The stick/slip root |F_t| - cap uses
 * it, so that a located end of sliding (the root finder stops where |F_t| <=
 * cap) is sticking for the right-hand side too (layer_tangential: |F_t| = cap
 * sticks). With the root's cap rounded as (tp kn un) sqrt(un), the state lay
 * one ulp above the right-hand side's cap at about half of those stops, and
 * the first RK4 stage after them booked the sliding branch's dissipation: a
 * draw of rounding worth 1e-7 of the ledger, the exact mode's residual under
 * scaling and under a change of one ulp of its inputs. (The projections of
 * layer_sim.c keep their rounding: they only put the state a margin of 1e-4
 * outside the cap, and the pluviation's samples depend on them bit for bit.) */
static inline double layer_cap(double tp, double kn, double un)
{
    return un > 0 ? tp * (kn * un * sqrt(un)) : 0;
}

/* The tangential law of layer_model.c (B.2) for a closed contact with state f,
 * K_t = kt, tangential velocity vt, dF_n/dt = fnd, elastic F_n = fel, tan phi =
 * tp: the force used (f clamped to the cap), the state's rate, and the
 * rates of the dissipation and of the tangential work E_st + W_K (B.7-B.14). mode: the held branch
 * (gw_layer.tmode: 1 at the cap, the force used is the cap; 0 inside), or -1
 * to decide from |f| against the cap at this evaluation. Held, an RK4 stage
 * whose extrapolated state dips inside a collapsing cap still slides: decided
 * per stage, the unloading of a contact at phi = 89.9 deg booked no
 * dissipation at the midpoint stages (the cap, convex in time, lies above
 * their linear extrapolation), and E_d fell 28 % short on a binary collision
 * at 1 us (ledger closure 7.9e-2, docs/layer.md). */
static inline void layer_tangential(double f, double kt, double vt, double fnd, double fel, double tp,
                                    double lam, int mode, double *ft, double *rate, double *cd, double *ck)
{
    double cap = tp * fel, re = kt * vt;
    double sg = f > 0 ? 1 : f < 0 ? -1 : (re >= 0 ? 1 : -1);
    double rc = sg * tp * fnd, fud = re;
    *rate = re;
    /* at the cap: the branch held since the last stop (mode 1), or |F_t|
     * above the cap at this evaluation without held branches (mode -1; |F_t|
     * = cap sticks: where a located end of sliding lands, layer_cap). Held
     * inside (mode 0), a stage past the located stick/slip root continues the
     * sticking branch, so that the root finder sees a smooth |F_t| - cap
     * (with the branch switched at the stages past it, the root landed 0.12
     * us late at phi = 89.9 deg and 1 us) */
    const int at_cap = mode > 0 || (mode < 0 && fabs(f) > cap);
    if (at_cap) {
        fud = rc; /* the force used rides the cap */
        if (sg * re > sg * rc) /* sliding: keep the state a margin outside */
            *rate = rc + sg * lam * (cap * (1 + LAYER_CAP_MARGIN) - fabs(f));
    }
    *ft = mode > 0 ? sg * cap : f > cap ? cap : f < -cap ? -cap : f;
    *cd = *ft * (vt - fud / kt);
    /* the rate of E_st + W_K, F_t (dF_t/dt) / K_t (= F_t v_t - dE_d/dt): the
     * tail integrates it (gw_layer.tail_work), not dW_K/dt = F_t^2 (dF_n/dt) /
     * (6 K_t F_n), which grows as u_n^(-3/2) while a contact stuck at phi
     * near 90 deg unloads towards a small overlap */
    *ck = *ft * fud / kt;
}

/* The forces of a closed contact, as every right-hand side applies them
 * (layer_rhs, layer_dem_rhs and the drift's force pass drift_discs) and the
 * block watch reads them (layer_body_contact_fy), so that these cannot part:
 * contact c with sqrt(u_n) = su, elastic F_n = fel = K_n u_n su > 0, approach
 * speed und (du_n/dt), tangential velocity vt and tangential state f.
 *   F_n: Hunt-Crossley, fel (1 + 3/2 alpha und), never below 0; fel itself
 *        without damping (alpha 0: und is not read).
 *   F_t by mode (layer_ft_modes), tp = tan(phi): LAYER_FT_NONE without
 *        friction, 0; LAYER_FT_FAST, the fast (DEM) mode, whose drift advances
 *        f (layer_dem.c): f clamped to the cap tp fel (layer_cap); otherwise
 *        the exact mode's law, layer_tangential with K_t = k_ts su, dF_n/dt =
 *        3/2 K_n su und, the cap's restoring rate lam and the branch mode (1, 0
 *        held, LAYER_FT_EXACT = -1 decided here), which alone gives F_t's rate and the rates of
 *        E_d and E_st + W_K (rate, cd, ck; 0 for the other modes).
 * (The mode, not tp, tells the frictionless case: the drift's callers pass
 * LAYER_FT_FAST as a constant, and its hot loop then tests nothing.) */
enum { LAYER_FT_NONE = -3, LAYER_FT_FAST = -2, LAYER_FT_EXACT = -1 };
typedef struct layer_cforce {
    double fn, ft, rate, cd, ck;
} layer_cforce;
static inline layer_cforce layer_contact_force(const layer_contact *c, double su, double fel, double und,
                                               double vt, double f, double alpha, double tp, double lam, int mode)
{
    layer_cforce o = {fel, 0, 0, 0, 0};
    if (alpha > 0) {
        o.fn = fel * (1.0 + 1.5 * alpha * und);
        if (o.fn < 0)
            o.fn = 0;
    }
    if (mode == LAYER_FT_NONE)
        return o;
    if (mode == LAYER_FT_FAST) {
        const double cap = tp * fel;
        o.ft = f > cap ? cap : f < -cap ? -cap : f;
    } else {
        layer_tangential(f, c->kts * su, vt, 1.5 * c->kn * su * und, fel, tp, lam, mode, &o.ft, &o.rate, &o.cd,
                         &o.ck);
    }
    return o;
}

/* The modes of layer_contact_force for the contacts of L, read once before a
 * loop over them: LAYER_FT_NONE without friction, LAYER_FT_FAST in DEM mode,
 * else LAYER_FT_EXACT, and then *held the held branches (gw_layer.tmode;
 * NULL: none held): contact k's mode is held ? held[k] : the value returned. */
static inline int layer_ft_modes(const gw_layer *L, const unsigned char **held)
{
    const int m = !(L->tan_phi > 0) ? LAYER_FT_NONE : L->dem ? LAYER_FT_FAST : LAYER_FT_EXACT;
    *held = m == LAYER_FT_EXACT && L->tmode_on ? L->tmode : NULL;
    return m;
}

/* The last pass of a right-hand side: the summed forces and torques of the n
 * bodies in yd become accelerations (gravity g downwards); a frozen body's
 * derivatives are all zero. Then the ledger's two rows: dissipated power pd and
 * the rate pk of its other term (0 where the path has none). */
static inline void layer_rhs_finish(const gw_layer *L, double *yd, int n, double g, double pd, double pk)
{
    for (int i = 0; i < n; i++) {
        double *d = yd + 6 * i;
        if (L->fixed[i]) {
            d[0] = d[1] = d[2] = d[3] = d[4] = d[5] = 0;
            continue;
        }
        d[3] *= L->minv[i];
        d[4] = d[4] * L->minv[i] - g;
        d[5] *= L->iinv[i];
    }
    yd[6 * n + L->nc] = pd;
    yd[6 * n + L->nc + 1] = pk;
}

/* Body of disc i. */
static inline int layer_body(const gw_layer *L, int i)
{
    return L->bid ? L->bid[i] : i;
}

/* Centre p of disc i in state y and, for a clump member, its arm (centre minus
 * the body's centre of mass, world frame; 0 for discs). */
void layer_disc_xy(const gw_layer *L, const double *y, int i, double p[2], double arm[2]);

/* Set up the bodies of L (bid, off, nb, masses, inertia, brad, fixed, y_ref)
 * from the particles b (layer_clumps.c). Writes the body states into L->y. */
int layer_bodies_build(gw_layer *L, const gw_layer_body *b, gw_err *err);

/* (clump id, particle index) pairs sorted by clump, then index. */
typedef struct layer_clump_key {
    int clump, i;
} layer_clump_key;
int layer_clump_key_cmp(const void *pa, const void *pb);

/* 1 when the k particles m[] (indices into x, y, r; reordered) overlap or touch
 * as one connected set; stack: k ints of scratch (layer_clump_check.c). */
int layer_members_connected(const double *x, const double *y, const double *r, int *m, int k,
                            int *stack);

/* A gw_layer_impact_result whose series have their arrays (ns, nrings and
 * spec_len >= 0, each array of a nonzero count given): GW_OK, else GW_EINVAL
 * "impact result: ..." (layer_crowns.c). whole 0: the arrays gw_layer_crowns
 * reads (t, the ring strain and kinetic series, the peaks, ring_r); 1: every
 * series gw_layer_impact_write_h5 writes. */
int layer_result_shape(const gw_layer_impact_result *r, int whole, gw_err *err);

/* The wave speeds of r left NaN by its sampling (the arrivals or the pairs'
 * delays put the wave across a crown in fewer than two sampling intervals, or
 * the first impact holds fewer than 4 samples: their count into *few, else 0):
 * bits 1 strain peaks, 2 kinetic peaks, 4 cross-correlation; the sampling
 * interval and the crown width into *dt_s, *dc_s (layer_crowns.c). */
unsigned layer_crowns_undersampled(const gw_layer_impact_result *r, double *dt_s, double *dc_s, int *few);

/* gw_layer_crowns of r over the series t[n] and the block *buf (the run's
 * checks: layer_impact.c) in place of r's written ones (t NULL: r's own),
 * which r keeps. *buf holds 2 nrings doubles of room, then strain
 * [rows * nrings], then kin [rows * nrings] (n <= rows); the analysis turns it
 * into r's xcorr_delay block in place (the spectra over the series, ring by
 * ring: the peak memory is the series', not twice it) and sets *buf NULL, or
 * leaves it to the caller to free (fewer than 4 samples, or out of memory).
 * The series' interval, its samples of
 * the first impact and their span go to peak_strain_t[3 nrings .. 3 nrings + 2]
 * (LAYER_CROWN_GRID doubles after the peaks and ring_r, allocated by the run
 * only), where layer_crowns_undersampled reads them. */
#define LAYER_CROWN_GRID 3
/* 1 when the crowns' cross-correlation speed is not the wave's: its pairs'
 * mean delay per crown (*delay, s) above LAYER_XCORR_LOCK times the first
 * contact's opening time, or without one the crown's transit at the faster
 * peak speed (*ref, s); gw_layer_crowns then reports it as NaN (layer_crowns.c).
 * Asked of a run's result (its resolution rule at the interval of the series
 * the crowns were read from: layer_crowns_series), as is layer_crowns_peaks_locked.
 * Over 29 impacts (42 runs: the 40-disc pile, the stored 300-disc sample and
 * `layer-make --n 300 --seed 1`, --vi 5 to 60, gravity 9.81, 1, 0.5, alpha 30)
 * the ratio was 23.2 to 103 on the 16 locked, 0.47 to 0.76 on the 7 kept (1.8
 * to 9.5 on 6 the resolution rule nulls first); the peak speeds' crown
 * transit 11.6 to 110 times on the 23 nulled, at most 4.25 on those kept. */
#define LAYER_XCORR_LOCK 10.0
int layer_crowns_xcorr_locked(const gw_layer_impact_result *r, double *delay, double *ref);
/* Bits 1, 2 when the strain, kinetic peak speed (as fit, resolved) crosses a
 * crown in more than LAYER_XCORR_LOCK times the first contact's opening time
 * (*ref, s; none when it did not open), the speeds read into c[0], c[1]:
 * gw_layer_crowns then reports them as NaN (layer_crowns.c). */
unsigned layer_crowns_peaks_locked(const gw_layer_impact_result *r, double c[2], double *ref);
int layer_crowns_series(gw_layer_impact_result *r, double *t, double **buf, int rows, int n);

/* The checks a sample read from a file passes (layer_sample_check of
 * layer_sample_check.c and layer_overlaps_check): GW_EFORMAT with a message starting
 * "sample 'WHAT'" when s would be refused on reading. */
int layer_sample_readable(const gw_layer_sample *s, const char *what, gw_err *err);

/* The rules every sample file meets before a byte of it is parsed or hashed
 * (gw_layer_sample_read applies them first): a regular file (gw_input_open),
 * at most LAYER_SAMPLE_FILE_MAX bytes, and either HDF5 (its signature at 0 or
 * after a user block; GW_EUNSUPPORTED in a build without HDF5) or text with
 * no NUL byte in its first 64 KiB. GW_OK, or the reader's status and message
 * ("sample 'PATH': ..."). The sweep (the rule layer_sweep_model.c registers,
 * gw_sweep_input_rule) and the layer model's check memo hash a sample only
 * through it: h not NULL, the file is then read whole once more, at most
 * LAYER_SAMPLE_FILE_MAX bytes, its hash into *h, a text sample refused at a
 * NUL byte anywhere (read up to it, not hashed whole first), and a sample
 * with a hole (a sparse file's never written bytes) is refused, HDF5 too,
 * before that read. */
#define LAYER_SAMPLE_FILE_MAX ((unsigned long long)1 << 32) /* bytes: 4 GiB */
int layer_sample_file_check(const char *path, unsigned long long *h, gw_err *err);

/* gw_layer_sample_pile_hash of s into *h, GW_OK; GW_EINVAL (*h 0) for a
 * sample layer_sample_shape_check refuses, GW_ENOMEM (*h 0) when the bodies
 * of a clump sample cannot be gathered (layer_sample_pile.c). */
int layer_sample_pile_hash(const gw_layer_sample *s, unsigned long long *h);

/* A sample's settling verdicts under the materials it was checked under (lp
 * and other_settling): gw_layer_impact_settled_check's status, message and
 * warning, then layer_rest_check's. The sweep's check pass checks many setups
 * of one sample under a few materials (a grid of impact points or speeds,
 * perhaps of densities) and keeps one of these per sample read, so that a
 * verdict is found once per sample and material, not twice per case
 * (layer_settling_verdict). The last LAYER_SETTLING_KEPT materials are kept
 * (44 kB), the oldest replaced: a grid of more materials on one sample finds
 * a verdict once per case (twice before). A struct zeroed keeps none. */
#define LAYER_SETTLING_KEPT 32
typedef struct layer_settling_memo {
    struct layer_settling_kept {
        int valid, other_settling, rc;
        gw_layer_params lp; /* compared by its bytes: a miss only finds the verdict again */
        gw_err err;         /* the refusal (rc not GW_OK) */
        char warning[768];  /* the warning (rc GW_OK; "" for none) */
        double q;           /* the load ratio found (NaN: none) */
    } kept[LAYER_SETTLING_KEPT];
    int next; /* the one replaced next */
} layer_settling_memo;

/* gw_layer_impact_settled_check of smp under lp, then layer_rest_check, the
 * sample named name in their messages; memo (may be NULL) gives the verdict
 * found before for the same lp and other_settling and keeps the one found
 * here (a memo serves one sample under one name; GW_ENOMEM is not kept).
 * Sets warning (n bytes; may be NULL) as gw_layer_impact_settled_check does
 * (layer_settled.c). */
int layer_settling_verdict(const gw_layer_sample *smp, const gw_layer_params *lp, int other_settling,
                           const char *name, layer_settling_memo *memo, char *warning, size_t n, gw_err *err);
/* The same, and into *found (may be NULL) the verdict a run takes (GW_OK). */
int layer_settling_verdict_found(const gw_layer_sample *smp, const gw_layer_params *lp, int other_settling,
                                 const char *name, layer_settling_memo *memo, layer_settling_found *found,
                                 char *warning, size_t n, gw_err *err);

/* gw_layer_impact_setup_check with the sample s->sample names already read
 * (and checked) into smp by gw_layer_sample_read: the rows and the resolution
 * against smp, for the sweep's check pass, which checks many setups of one
 * sample file (layer_setup.c; smp is only read); its settling verdict through
 * memo (may be NULL: found here). The reader's check is the shared sample
 * check (layer_sample_limits_check): the resolution does not take it again. */
struct gw_layer_impact_setup;
/* gw_layer_impact_setup_check as a sweep's case takes it: without the
 * single run's refusals of other-settling and zero-springs of no effect on
 * the sample (a grid's key acts on its other samples). */
int layer_impact_setup_check_case(const struct gw_layer_impact_setup *s, gw_err *err);
int layer_impact_setup_check_sample(const struct gw_layer_impact_setup *s, const gw_layer_sample *smp,
                                    layer_settling_memo *memo, gw_err *err);

/* The part of an impact's run done at its output sample (L the run's layer,
 * ip its parameters), for a sweep's progress lines (gw_layer_sweep_run_part):
 * its simulated time over the end expected. A run to the rebound ends when
 * the block's v_y is back to zero after turning upward (T_f, or the rebound's
 * end inside the layer): with the block rising under gravity g, past its
 * largest v_y (the push that turned it over), that is expected in v_y / g
 * (exact in free flight, and the block leaves the layer early: at 1.6 ms of
 * the 40-disc pile's T_f = 0.31 s at 20 m/s), else at t-max (an upper bound:
 * before the block rises and while it is pushed up, a run until the verdict,
 * a full run, a run without gravity). In [0, 1]. */
double layer_run_part(const gw_layer *L, const gw_layer_impact_params *ip);
/* gw_layer_impact_run_progress with part(part_ctx, x) (may be NULL) called
 * with layer_run_part as progress is, but not at the run's end */
int layer_impact_run_part(const struct gw_layer_impact_setup *s, gw_progress_fn progress, void *pctx,
                          void (*part)(void *part_ctx, double x), void *part_ctx,
                          struct gw_layer_impact_outcome *out, gw_err *err);

/* gw_layer_impact_plan_make with its settling verdict through memo (may be
 * NULL). */
struct gw_layer_impact_plan;
int layer_impact_plan_make_memo(const struct gw_layer_impact_setup *s, struct gw_layer_impact_plan *p,
                                layer_settling_memo *memo, gw_err *err);

/* A uniform grid of square cells over n points (px[i stride], py[i stride]),
 * of side h or coarser (doubled until there are at most 16 n + 64 cells, so
 * that a far point does not blow it up); cell k holds the points
 * idx[start[k] .. start[k + 1]) in index order, and point i lies in cell[i]
 * = cy nx + cx. GW_ELIMIT when the extent is not finite or h not positive,
 * GW_ENOMEM; layer_grid_free frees it (and a zeroed grid). */
typedef struct layer_grid {
    long nx, ny;
    int *start, *idx, *cell;
} layer_grid;
int layer_grid_build(layer_grid *g, int n, const double *px, const double *py, int stride, double h);
void layer_grid_free(layer_grid *g);

/* Discs i, j of different bodies (body may be NULL) overlapping by more than
 * 0.05 R_p, R_p = 2 r_i r_j / (r_i + r_j): GW_EFORMAT "WHAT: particles i and j
 * overlap by ..." (a read sample; a settled one overlaps by about 0.002 R_p). */
int layer_overlaps_check(int n, const double *x, const double *y, const double *r, const int *body,
                         const char *what, gw_err *err);

/* One particle as a layer takes it (gw_layer_create) and as a run takes a
 * sample's (layer_sample_shape_check, gw_layer_impact_check): x, y, r, vx, vy
 * and w finite, r > 0, and with walls (GW_LAYER_WALL_* bits; 0: none) its
 * centre inside those of a box of width width (0 <= x <= width, y >= 0).
 * GW_EINVAL "WHAT I: FIELD = V UNIT ..." naming the index i and the field. The
 * impact's check and its run both read a sample's particles through it: the
 * check passed a NaN coordinate, a radius <= 0 or a centre outside the walls
 * that the run then refused (session 35). */
int layer_particle_check(const gw_layer_body *b, int i, int walls, double width, const char *what, gw_err *err);

/* Body ids of a sample (NULL: none): in [0, n), members of one body connected by
 * overlap or touch, at most LAYER_CLUMP_MEMBERS per body. status (GW_EINVAL or GW_EFORMAT) with a message starting
 * with what. */
int layer_bodies_check(int n, const double *x, const double *y, const double *r, const int *body,
                       const char *what, int status, gw_err *err);

/* A quasi-rectangular clump of equivalent radius req (m), aspect ratio in
 * [1, 4], long axis at angle (rad): a row of k <= 6 discs. Writes the member
 * offsets from the clump centre and their radii into ox, oy, r [6]; returns k. */
#define LAYER_CLUMP_MAX 6
/* Most members a clump may have (samples and gw_layer_create). */
#define LAYER_CLUMP_MEMBERS 64
int layer_clump_shape(double req, double aspect, double angle, double *ox, double *oy, double *r);

/* A sample's tangential springs (layer_sample_springs.c, layer_springs.c). At most
 * LAYER_SPRINGS_MOST(n) in a sample of n particles (a settled pile has about
 * 2 contacts a disc). */
#define LAYER_SPRINGS_MOST(n) (8L * ((long)(n) + 1))
/* s's springs: pairs in range and of different bodies, finite, each pair
 * once, in contact from s's positions, within the Coulomb bound of the
 * settling s records (none checked without a record); status with a message
 * "sample 'PATH': line L: ..." (lines[k] the file's line of spring k; NULL:
 * "spring at index k"), GW_ENOMEM. */
int layer_springs_check(const gw_layer_sample *s, const char *path, const long *lines, int status, gw_err *err);
/* Spring k of s as a record: its pair two particles in [0, n) or a particle
 * and a wall, its displacement u finite (a sign is a direction along t: any
 * finite u is a form, the Coulomb bound is layer_springs_check's). status
 * with "sample 'PATH': spring at index k: spring 0 1: displacement u = nan m
 * is not a finite number" (lines as layer_springs_check's). The form check's
 * and layer_springs_check's first rule. */
int layer_spring_form_check(const gw_layer_sample *s, int k, const char *path, const long *lines, int status,
                            gw_err *err);
/* The limits every sample is held to, read from a file, written or built in
 * memory (layer_sample_check.c): n in [1, 1e7] with its x, y and r, the
 * header's fields (width, rm and their scales, volume_ratio, porosity, seed,
 * mass laws), each particle finite, of radius within [1e-3, 1e3] R_m, inside
 * the box to 0.02 r and at most 1e6 R_m high, body ids in [0, n) with each
 * clump connected, n_springs >= 0 with its array and each spring's pair in
 * range and displacement finite, and
 * no two particles of different bodies overlapping by more than 0.05 R_p.
 * status naming the field and the index, "sample 'PATH': particle 17: r =
 * nan m is not a finite number". layer_sample_shape_check is it with
 * GW_EINVAL: the impact's checks, its step, the porosity and the settling's
 * checks take it, as the reader and the writer do (the pile's hash its form
 * only, layer_sample_form_check). */
int layer_sample_limits_check(const gw_layer_sample *s, const char *path, int status, gw_err *err);
/* Its first part, the form of a sample (n and its arrays, width and rm
 * finite and > 0, each particle finite with r > 0, body ids in [0, n), each
 * spring's pair in range and its displacement finite,
 * layer_spring_form_check): what the pile's hash needs to read a sample. */
int layer_sample_form_check(const gw_layer_sample *s, const char *path, int status, gw_err *err);
/* The porosity of s without its checks (gw_layer_sample_porosity checks s
 * first): for the reader's porosity check and for layer-make, whose sample
 * is checked after. */
double layer_sample_porosity_of(const gw_layer_sample *s);
/* 1 when no disc of s reaches into the porosity's window (its porosity NaN:
 * not measurable), else 0. */
int layer_sample_window_empty(const gw_layer_sample *s);
int layer_sample_shape_check(const gw_layer_sample *s, const char *path, gw_err *err);
/* The springs of L's contacts (its state's F_t, clamped to the cap) as
 * displacements at the overlaps of the discs x, y, r of a box of width
 * width (the positions a sample is written with; contacts open there are
 * left out, and the block's): *out (malloc'd; NULL when none), *nout.
 * GW_ENOMEM. */
int layer_springs_take(const gw_layer *L, const double *x, const double *y, const double *r, double width,
                       gw_layer_spring **out, int *nout);
/* Keep n springs (disc indices of L) for the first contact list: gw_layer_start
 * starts the listed contacts from them (layer_springs_load). GW_ENOMEM. */
int layer_springs_pend(gw_layer *L, const gw_layer_spring *sp, int n);
/* Once the first list is built (gw_layer_start): each listed contact that
 * has a pending spring and is closed in L->y starts from F_t = K_t u, clipped
 * to tan(phi) F_n; the pending springs are freed (a spring whose pair is not
 * listed, its bodies frozen or a wall removed, is dropped). */
void layer_springs_load(gw_layer *L);
/* A wall's name in a text sample ("left", "right", "bottom") and back (0: none). */
int layer_spring_wall(const char *s);
const char *layer_spring_wall_name(int b);
/* Overlap u_n of the contact (a, b) (b a wall: GW_LAYER_SPRING_*) of discs at
 * (x, y) with radii r in a box of width w, as layer_pair_geometry has it. */
double layer_spring_overlap(const double *x, const double *y, const double *r, double w, int a, int b);
/* Springs ordered by (a, b), as the contact list is; a pair of discs as a < b
 * (either order is one contact with one value: n and t both turn over). */
int layer_spring_cmp(const void *pa, const void *pb);
gw_layer_spring layer_spring_sorted(gw_layer_spring q);

/* Build the contact list from the positions in L->y (cell list, skin L->p.skin)
 * carrying F_t of contacts present in both lists. Rewrites L->y, L->scale and
 * L->sys for the new dimension. */
int layer_contacts_build(gw_layer *L, gw_err *err);

/* Set the held tangential branches (gw_layer.tmode) from the state where the
 * solver stops, with the roots that fired there (NULL: none; contact roots
 * first, stick/slip roots from layer_root_slip): off the cap where a
 * stick/slip root went down; for a contact with F_t = 0 (closing), on the cap
 * when it slides from the start (K_t |v_t| > tan(phi) dF_n/dt: F_t / cap
 * tends to 2 k_t K_n^(1/3) |v_t| / (3 tan(phi) K_n du_n/dt) as u_n -> 0, and
 * with both at 0 no root marks the switch); else |F_t| above the cap.
 * Returns the number of branches changed. */
int layer_tmode_update(gw_layer *L, const int *roots);

/* Number of rebuild roots: one per particle, or when the rebuild is checked at
 * the steps' ends (L->stepend) one for all (the smallest margin: it is not
 * located, and one sign to watch per step is cheaper than n). */
static inline int layer_root_nrebuild(const gw_layer *L)
{
    return L->stepend ? 1 : L->n;
}
/* Index of the first rebuild root and of the first stick/slip root (-1: none). */
static inline int layer_root_rebuild(const gw_layer *L)
{
    return L->p.no_events ? 0 : L->nc;
}
static inline int layer_root_slip(const gw_layer *L)
{
    return L->p.no_events || !(L->tan_phi > 0) ? -1 : L->nc + layer_root_nrebuild(L);
}
/* Roots without the block watch, and the index of the first watch root (the
 * watch's two roots come last). */
static inline int layer_root_count(const gw_layer *L)
{
    return L->p.no_events ? layer_root_nrebuild(L) : L->nc * (L->tan_phi > 0 ? 2 : 1) + layer_root_nrebuild(L);
}

/* Block watch (layer_watch.c): fill the two watch roots at g[layer_root_count]
 * for state (t, y) and record the probe and the extremes. */
void layer_watch_roots(gw_layer *L, double t, const double *y, double *g);
/* Follow the block's first contact with disc target (after gw_layer_watch_block,
 * before gw_layer_start); read L->fc after the run. */
void layer_watch_first_contact(gw_layer *L, int target);
/* Stop following it: the values so far are the first contact's (the verdict). */
void layer_watch_first_contact_freeze(gw_layer *L);
/* The smallest block kinetic energy of the first contact, located: the vertex of
 * the parabola through the smallest evaluated value and the overlapped
 * evaluations next to it in time, with the dissipations (ed, edb) taken there on
 * the quadratics through the same three evaluations; the evaluated smallest
 * value itself when it is not bracketed. At the evaluations themselves the
 * time and E_d erred by up to half a step times their rates: the default fast
 * impact's dissipated_first_contact read 0.05516 at its 10 us step ends against
 * 0.05471 and 0.05470 at 5 and 2.5 us. t, kb, ed, edb: s, J, J, J. */
void layer_watch_first_contact_min(const gw_layer *L, double *t, double *kb, double *ed, double *edb);
/* After a solver stop with roots: report the watch roots that fired (in time
 * order) to the watch callback. Returns 1 when a root other than the watch's
 * fired (the run driver then handles the stop as before), 0 otherwise. */
int layer_watch_dispatch(gw_layer *L);

/* Region of contact c (state y) when regions are set: ring index, reg_n
 * beyond the last ring, reg_n + 1 for a contact of the block. */
int layer_contact_region(const gw_layer *L, const layer_contact *c, const double *y);
/* The same from the overlap and normal already computed. */
int layer_contact_region_at(const gw_layer *L, const layer_contact *c, const double *y,
                            double un, const double nn[2]);

/* Add the state-function terms of the ledger (kinetic, potential, strain) into
 * *global and into regions[region] (either may be NULL; layer_regions.c). */
void layer_ledger_sum(const gw_layer *L, gw_layer_energy *global, gw_layer_energy *regions);

/* The DEM step (layer_dem.c): gw_system.drift_fn and .project in DEM mode. */
int layer_dem_drift(double t, double h, const double *ph, double *y, void *P);
int layer_dem_project(double t, double h, double *y, double *ydot, void *P);
/* rk4 with the rebuild at the steps' ends (L->stepend, layer_sim.c): after every
 * step, F_t of the contacts open at its end is zeroed (and a state far outside
 * the Coulomb cap brought back), what every stop of the run did before, so that
 * the stops (outputs, rebuilds) change nothing of the state. */
int layer_step_project(double t, double h, double *y, double *ydot, void *P);
int layer_dem_rhs(double t, const double *y, double *yd, void *P);
/* The rhs call right after a DEM list rebuild (L->dem_carry): yd from L->dem_f
 * (contacts 0), the disc geometry of y into L->geo; clears dem_carry. */
int layer_dem_carried(gw_layer *L, const double *y, double *yd);
/* A sample read between two steps under verlet (layer_advance_peek): the
 * tangential forces and the ledger's tail of L->y at t made the step's own
 * (a partial step of t - pk_t0 from the step's start, not committed: L->y's
 * line between the step's ends puts a slip's increments anywhere in the
 * step); nothing when no start was kept for a step that holds t. */
void layer_dem_peek(gw_layer *L, double t);

/* Overlap (*un) and tangential relative velocity of contact c in state y, the
 * velocity also when the contact is open there (layer_model.c). */
void layer_contact_rates(const gw_layer *L, const layer_contact *c, const double *y, double *un, double *und,
                         double *vt);
double layer_contact_vt(const gw_layer *L, const layer_contact *c, const double *y, double *un);
/* The vertical force on body q from the listed contacts idx[0 .. n_idx - 1]
 * (all contacts with idx NULL) in state y, as the right-hand side applies it
 * (the fast mode's F_t: the state clamped to the cap; the exact mode's: its
 * held branch), N. */
/* The vertical force (N, up positive) the left and right walls exert on the
 * bodies in state y: their contacts' friction (and damping) along the walls.
 * With the floor's load it carries a pile at rest in a narrow box (Janssen). */
double layer_side_walls_fy(const gw_layer *L, const double *y);
double layer_body_contact_fy(const gw_layer *L, const double *y, int q, const int *idx, int n_idx);

/* Fill sys (rhs, roots, dim, scale, drift) for the current list. */
void layer_system_fill(gw_layer *L);

/* Overlap u_n (m), unit normal n (a -> b), tangent t = (-n_y, n_x) and the
 * contact point of contact c in state y. */
void layer_contact_geometry(const gw_layer *L, const layer_contact *c, const double *y,
                            double *un, double n[2], double pt[2]);

#endif
