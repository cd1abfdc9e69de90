/*
 * layer_sim.c: the run driver of the layer (docs/physics.md 2.1, numerical notes of
 * 1.1): integrates the ODE system of layer_model.c through the gw_solver layer.
 *
 * - At every root of a contact overlap (u_n = 0) the solver is restarted
 *   (gw_solver_reset), because the Hertz force is only C^1 there.
 * - When a particle has moved half the skin since the list was built (root
 *   (s/2)^2 - |dx|^2 = 0; checked at the steps' ends with a margin in DEM mode
 *   and for rk4 without events, L->stepend) the contact list is rebuilt: the state dimension
 *   changes, so the solver is freed and re-created with the new gw_system. In
 *   DEM mode the new solver starts from the old one's rates (gw_solver_rates,
 *   L->dem_f) and the contacts keep what the step knew of them, so that a
 *   rebuild changes nothing of the trajectory: the same run at any skin is the
 *   same to the last bit.
 * - At every stop the tangential state is projected: F_t = 0 on open contacts and
 *   on contacts that just closed; a state drifted far outside the Coulomb cap is
 *   brought back to the sliding margin. The ledger books the capped force, so
 *   the projection moves no energy.
 * - DEM mode (the verlet backend, gw_solver.h): no contact or stick/slip
 *   events, only the list rebuild root, reported at the end of the step that
 *   crossed it. The tangential force is advanced as a coordinate of the step
 *   and the ledger books it feeds are added after the step (layer_dem.c).
 * - Zeno guard: more than LAYER_ZENO_COUNT events within L->zeno_dt of each
 *   other (seen with CVODE when a contact grazes u_n = 0) switch the event roots
 *   off for L->zeno_quiet s (1e-12 and 1e-7 s, or 1e-6 and 0.1 rk4 steps in the
 *   exact mode), or more than LAYER_ZENO_WIDE_COUNT within 100 times that
 *   window (a contact chattering just past it); counted in
 *   gw_layer_stats.zeno_guards.
 * Units: SI.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layer_impl.h"
#include "gw_locale.h"

/* The bounds of one gw_layer_advance call, the program's: at most
 * LAYER_ADVANCE_SPAN s (layer-make's longest t-max; layer-impact's is 1e3 s),
 * at most LAYER_ADVANCE_STEPS steps and LAYER_ADVANCE_WORK particle-steps
 * (steps times particles and listed contacts, layer-impact's bound on its
 * fixed step). gw_layer_advance(L, 1e300) ran until the solver's step limit
 * of one stretch between events (1e7 by default, none past an event: hours). */
#define LAYER_ADVANCE_SPAN 1e4
#define LAYER_ADVANCE_STEPS 1e9
#define LAYER_ADVANCE_WORK 1e10

/* Project F_t; closing[k] > 0 marks contacts that just closed, slipping[k] > 0
 * contacts that just reached the Coulomb cap (both may be NULL).
 * Returns the number of components changed. */
static int project_y(gw_layer *L, double *y, const int *closing, const int *slipping)
{
    int changed = 0;
    const int n = L->nb;
    for (int k = 0; k < L->nc; k++) {
        double *f = y + 6 * n + k;
        if (*f == 0)
            continue;
        double un, nn[2];
        const layer_contact *c = &L->c[k];
        if (L->off) {
            layer_contact_geometry(L, c, y, &un, nn, NULL);
        } else { /* discs: the overlap alone (body = disc), as layer_contact_geometry has it */
            const double *sa = y + 6 * c->qa;
            if (c->b == LAYER_LEFT)
                un = c->ra - sa[0];
            else if (c->b == LAYER_RIGHT)
                un = c->ra - (L->p.width - sa[0]);
            else if (c->b == LAYER_BOTTOM)
                un = c->ra - sa[1];
            else {
                const double *sb = y + 6 * c->qb, dx = sb[0] - sa[0], dy = sb[1] - sa[1];
                un = c->ra + c->rb - sqrt(dx * dx + dy * dy);
            }
        }
        double cap = un > 0 ? L->tan_phi * L->c[k].kn * un * sqrt(un) : 0;
        double nf = *f;
        if ((closing && closing[k] > 0) || !(un > 0))
            nf = 0;
        else if (slipping && slipping[k] > 0) /* onto the sliding branch */
            nf = nf > 0 ? cap * (1 + LAYER_CAP_MARGIN) : -cap * (1 + LAYER_CAP_MARGIN);
        else if (fabs(nf) > cap * (1 + 4 * LAYER_CAP_MARGIN))
            nf = nf > 0 ? cap * (1 + LAYER_CAP_MARGIN) : -cap * (1 + LAYER_CAP_MARGIN);
        if (nf != *f) {
            *f = nf;
            changed++;
        }
    }
    L->st.projections += changed;
    L->stamp += changed > 0;
    return changed;
}

static int project(gw_layer *L, const int *closing, const int *slipping)
{
    return project_y(L, L->y, closing, slipping);
}

int layer_step_project(double t, double h, double *y, double *ydot, void *P)
{
    (void)t, (void)h, (void)ydot;
    project_y(P, y, NULL, NULL);
    return 0;
}

static void harvest_stats(gw_layer *L)
{
    if (!L->solver)
        return;
    gw_solver_stats ss;
    gw_solver_get_stats(L->solver, &ss);
    L->st.steps += ss.steps;
    L->st.rhs_evals += ss.rhs_evals;
}

int layer_tmode_update(gw_layer *L, const int *roots)
{
    L->tmode_on = 0;
    const int s0 = layer_root_slip(L);
    if (L->dem || s0 < 0)
        return 0; /* the stick/slip switches are not located: decided at each evaluation */
    if (L->tmode_cap < L->nc + 1) {
        unsigned char *m = realloc(L->tmode, (size_t)L->nc + 1);
        if (!m)
            return 0; /* (out of memory: decided at each evaluation, as before) */
        memset(m + L->tmode_cap, 0, (size_t)(L->nc + 1 - L->tmode_cap));
        L->tmode = m;
        L->tmode_cap = L->nc + 1;
    }
    const double *f = L->y + 6 * L->nb;
    int changed = 0;
    for (int k = 0; k < L->nc; k++) {
        const layer_contact *c = &L->c[k];
        int m = 0;
        if (roots && roots[s0 + k] < 0) {
            m = 0; /* the root just crossed into the cap, whatever the rounding */
        } else if (f[k] == 0) { /* open, or closing: does it slide from the start? */
            double un, und, vt;
            layer_contact_rates(L, c, L->y, &un, &und, &vt);
            m = un >= 0 && und > 0 && c->kts * fabs(vt) > 1.5 * L->tan_phi * c->kn * und;
        } else {
            double un, nn[2];
            layer_contact_geometry(L, c, L->y, &un, nn, NULL);
            m = fabs(f[k]) > layer_cap(L->tan_phi, c->kn, un);
        }
        changed += L->tmode[k] != m;
        L->tmode[k] = (unsigned char)m;
    }
    L->tmode_on = 1;
    return changed;
}

static int make_solver(gw_layer *L, gw_err *err)
{
    harvest_stats(L);
    layer_tmode_update(L, NULL);
    gw_solver_free(L->solver);
    L->solver = NULL;
    int rc = gw_solver_create(L->type, &L->sys, &L->sp, L->t, L->y, &L->solver, err);
    if (rc != GW_OK) {
        char tmp[sizeof err->msg];
        gw_snprintf(tmp, sizeof tmp, "%s", err ? err->msg : "");
        return gw_err_set(err, rc, "layer: solver set-up failed at t = %.9g s: %s", L->t, tmp);
    }
    return GW_OK;
}

int gw_layer_start(gw_layer *L, const gw_solver_type *type, const gw_solver_params *sp,
                   gw_err *err)
{
    if (!L || !sp) /* (sp was copied from NULL: SIGSEGV) */
        return gw_err_set(err, GW_EINVAL, "gw_layer_start: %s is NULL", !L ? "L" : "sp");
    if (!type)
        return gw_err_set(err, GW_EINVAL, "layer: no solver backend given");
    L->type = type;
    L->sp = *sp;
    /* one stretch between events within gw_layer_advance's bound on steps */
    if (L->sp.max_steps > (long)LAYER_ADVANCE_STEPS)
        L->sp.max_steps = (long)LAYER_ADVANCE_STEPS;
    L->dem = type == gw_solver_verlet;
    /* rk4 without contact events or a block watch (the pluviation) need not
     * locate the list rebuild: checked at the steps' ends with a margin, as
     * verlet does, and F_t projected after every step, the run does not depend
     * on the skin (with the rebuild roots located, each rebuild added a
     * shortened step and a projection at a skin-dependent instant) */
    L->stepend = L->dem || (type == gw_solver_rk4 && L->p.no_events && !L->watch);
    if (L->dem) { /* explicit DEM: no contact events (gw_layer_params.no_events) */
        L->p.no_events = 1;
        free(L->ymid), free(L->dem_book), free(L->facc), free(L->dem_rate), free(L->dem_f), free(L->pk_y);
        L->dem_carry = 0;
        L->pk_valid = 0;
        L->ymid = malloc(6 * (size_t)L->nb * sizeof *L->ymid);
        L->pk_y = malloc((24 * (size_t)L->nb + (size_t)L->ntail + 1) * sizeof *L->pk_y);
        L->dem_f = malloc((6 * (size_t)L->nb + (size_t)L->ntail) * sizeof *L->dem_f);
        L->facc = malloc(3 * (size_t)L->nb * sizeof *L->facc);
        L->dem_book = calloc((size_t)L->ntail + 1, sizeof *L->dem_book);
        L->dem_rate = calloc((size_t)L->ntail + 1, sizeof *L->dem_rate);
        if (!L->ymid || !L->facc || !L->dem_book || !L->dem_rate || !L->dem_f || !L->pk_y)
            return gw_err_set(err, GW_ENOMEM, "layer: out of memory for the DEM step");
    }
    /* The contact network couples particles far apart in the state vector (no
     * useful band), and the Hertz-Mindlin layer is not stiff at the solver
     * tolerances used: CVODE runs Adams with fixed-point iteration unless a
     * method is asked for (BDF with a diagonal band is far slower here). */
    if (type == gw_solver_cvode && L->sp.method == GW_METHOD_DEFAULT)
        L->sp.method = GW_CVODE_ADAMS;
    /* The sliding margin's restoring rate and the Zeno guard's times are
     * numerical devices with no physical scale of their own. Fixed in s, they
     * made the exact mode depend on the size of the problem: lengths x 1000
     * (R_m = 325 m) with V_i kept, g / 1000 and the step x 1000 (1 ms, the
     * same number of steps per contact) put 1e4 /s x 1 ms = 10 beyond RK4's
     * stability bound (2.8 for a decay) and the friction loss of the first
     * contact came out 4.5 times too small (0.00059 against 0.00264), the
     * ledger closure 0.16; lengths x 4 moved it by 1.7e-4. Tied to rk4's step
     * they scale with the run and are unchanged at its default 1 us; the
     * adaptive backends have no step and keep them in s, and so does rk4
     * without events (the pluviation, whose 20 us steps would otherwise
     * change every sample; its settling is timed in s anyway) */
    double h = type == gw_solver_rk4 && !L->p.no_events && L->sp.dt > 0 ? L->sp.dt : 0;
    if (h > 0 && L->sp.dt_max > 0 && L->sp.dt_max < h)
        h = L->sp.dt_max; /* the step rk4 takes (gw_solver_create) */
    L->cap_rate = h > 0 ? LAYER_CAP_RATE_STEP / h : LAYER_CAP_RATE;
    L->zeno_dt = h > 0 ? LAYER_ZENO_DT_STEP * h : LAYER_ZENO_DT;
    L->zeno_quiet = h > 0 ? LAYER_ZENO_QUIET_STEP * h : LAYER_ZENO_QUIET;
    L->t = 0;
    int rc = layer_contacts_build(L, err);
    if (rc != GW_OK)
        return rc;
    layer_springs_load(L); /* a sample's springs (layer_springs_pend), before the ledger's start */
    project(L, NULL, NULL);
    gw_layer_energy e;
    if (L->tail_work != !L->dem) { /* the tail's convention changes: keep W_K */
        const int nr = gw_layer_region_count(L);
        gw_layer_energy *reg = nr > 0 ? calloc((size_t)nr, sizeof *reg) : NULL;
        if (nr > 0 && !reg)
            return gw_err_set(err, GW_ENOMEM, "layer: out of memory");
        gw_layer_ledgers(L, &e, reg);
        double *tail = L->y + 6 * L->nb + L->nc, sg = L->dem ? 0 : 1;
        tail[1] = e.mindlin_excess + sg * e.strain_tangent;
        for (int q = 0; q < nr; q++)
            tail[3 + 2 * q] = reg[q].mindlin_excess + sg * reg[q].strain_tangent;
        free(reg);
        L->tail_work = !L->dem;
    }
    gw_layer_energy_of(L, &e);
    L->e0 = e.total;
    double mg = 0;
    for (int i = 0; i < L->nb; i++)
        mg += L->m[i] * L->p.gravity * L->brad[i];
    L->e_scale = fmax(fabs(e.total), fmax(e.kinetic_block + e.kinetic_soil, mg));
    layer_system_fill(L);
    return make_solver(L, err);
}

/* The run's hooks (gw_solver_drive). At the target time: the exact mode's
 * projection of open contacts' tangential forces (a restart if it changed
 * any). At roots: the block watch, then the contact events (projection of
 * closing and slipping contacts, a restart), or a hand-back for a list rebuild
 * or a Zeno guard, which recreate the solver. */
static int layer_on_output(void *ctx, double t, double *y, gw_err *err)
{
    (void)y, (void)err;
    gw_layer *L = ctx;
    L->stamp++;
    L->t = t;
    int changed = !L->dem && project(L, NULL, NULL) > 0;
    if (!L->dem && L->tmode_on) /* (a branch that the roots missed is switched here) */
        changed += layer_tmode_update(L, NULL) > 0;
    return changed ? GW_DRIVE_RESET : GW_DRIVE_ON;
}

static int layer_on_root(void *ctx, double t, double *y, const int *roots, gw_err *err)
{
    (void)y, (void)err;
    gw_layer *L = ctx;
    L->stamp++;
    L->t = t;
    if (!layer_watch_dispatch(L))
        return GW_DRIVE_ON; /* only the block watch's roots: nothing to project or restart */
    L->st.events++;
    L->storm = L->t - L->t_event < L->zeno_dt ? L->storm + 1 : 0;
    L->storm_wide = L->t - L->t_event < LAYER_ZENO_WIDE * L->zeno_dt ? L->storm_wide + 1 : 0;
    L->t_event = L->t;
    const int r0 = layer_root_rebuild(L), s0 = layer_root_slip(L);
    for (int k = 0; L->hook && !L->p.no_events && k < L->nc; k++)
        if (roots[k])
            L->hook(L->hook_ctx, L->t, L->c[k].a, L->c[k].b, roots[k] > 0 ? 1 : -1);
    int rebuild = 0;
    for (int i = 0; i < layer_root_nrebuild(L); i++)
        rebuild |= roots[r0 + i] != 0;
    project(L, L->p.no_events ? NULL : roots, s0 >= 0 ? roots + s0 : NULL);
    layer_tmode_update(L, roots);
    if ((L->storm > LAYER_ZENO_COUNT || L->storm_wide > LAYER_ZENO_WIDE_COUNT) && L->quiet_until == 0) {
        /* Zeno guard: the root finder keeps stopping at the same instant (a
         * contact grazing u_n = 0 with CVODE's zero-at-restart rule). Step
         * over L->zeno_quiet s with only the rebuild roots, then resume. */
        L->no_events_user = L->p.no_events;
        L->p.no_events = 1;
        L->quiet_until = L->t + L->zeno_quiet;
        L->st.zeno_guards++;
        L->storm = L->storm_wide = 0;
        return GW_DRIVE_YIELD;
    }
    return rebuild ? GW_DRIVE_YIELD : GW_DRIVE_RESET;
}


/* An adaptive backend's steps within the call, counted after every root and
 * output (between them, the solver's own step limit holds, at most
 * LAYER_ADVANCE_STEPS: gw_layer_start): GW_ELIMIT past the bounds. */
static int layer_after_bound(void *ctx, double t, const double *y, gw_err *err)
{
    (void)y;
    gw_layer *L = ctx;
    gw_layer_stats st;
    gw_layer_get_stats(L, &st);
    const double steps = (double)(st.steps - L->adv_steps0), work = steps * ((double)L->n + (double)L->nc);
    if (steps <= LAYER_ADVANCE_STEPS && work <= LAYER_ADVANCE_WORK)
        return GW_DRIVE_ON;
    L->adv_over = 1;
    return gw_err_set(err, GW_ELIMIT, "layer: %s took %.3g steps of %d particles and %d listed contacts in one "
                      "gw_layer_advance call, to t = %.9g s: more than %.3g steps or %.3g particle-steps",
                      gw_solver_type_name(L->type), steps, L->n, L->nc, t, LAYER_ADVANCE_STEPS,
                      LAYER_ADVANCE_WORK);
}

int gw_layer_advance(gw_layer *L, double tout, gw_err *err)
{
    if (!L)
        return gw_err_set(err, GW_EINVAL, "gw_layer_advance: L is NULL");
    if (!L->solver)
        return gw_err_set(err, GW_EINVAL, "layer: gw_layer_start was not called");
    /* a NaN tout ran nothing and returned GW_OK at t = 0, an earlier one
     * stayed where the layer was with GW_OK (as rk4's solver did before the
     * thirty-eighth pass) */
    if (!isfinite(tout) || tout < L->t)
        return gw_err_set(err, GW_EINVAL, "layer: tout %g s is %s", tout,
                          !isfinite(tout) ? "not a finite time" : "before the layer's own time");
    /* bounded before any step (the layer unchanged): the span, and a fixed
     * step's count and work to tout */
    const double span = tout - L->t;
    if (span > LAYER_ADVANCE_SPAN)
        return gw_err_set(err, GW_EINVAL, "layer: tout %g s is %g s after the layer's time %g s, more than the "
                          "%g s one call advances (the longest t-max the program takes)", tout, span, L->t,
                          LAYER_ADVANCE_SPAN);
    const int fixed = L->type == gw_solver_verlet || L->type == gw_solver_rk4;
    const double dt = L->sp.dt_max > 0 && L->sp.dt_max < L->sp.dt ? L->sp.dt_max : L->sp.dt;
    const int bounded = fixed && dt > 0; /* up front; else counted as it runs (layer_after_bound) */
    if (bounded) {
        const double steps = span / dt, work = steps * ((double)L->n + (double)L->nc);
        if (steps > LAYER_ADVANCE_STEPS || work > LAYER_ADVANCE_WORK)
            return gw_err_set(err, GW_EINVAL, "layer: tout %g s is %.3g %s steps of %g s from t = %g s, of %d "
                              "particles and %d listed contacts: %.3g particle-steps, more than %.3g steps or "
                              "%.3g particle-steps in one call", tout, steps, gw_solver_type_name(L->type), dt, L->t,
                              L->n, L->nc, work, LAYER_ADVANCE_STEPS, LAYER_ADVANCE_WORK);
    }
    {
        gw_layer_stats st0;
        gw_layer_get_stats(L, &st0);
        L->adv_steps0 = st0.steps;
        L->adv_over = 0;
    }
    if (L->geo_peek) /* (layer_advance_peek) the solver's state comes back into y below */
        L->geo_peek = 0, L->geo_pos = 1;
    while (L->t < tout) {
        if (L->quiet_until > 0 && L->t >= L->quiet_until) { /* end of a Zeno guard */
            L->quiet_until = 0;
            L->p.no_events = L->no_events_user;
            layer_system_fill(L);
            int rc = make_solver(L, err);
            if (rc != GW_OK)
                return rc;
        }
        double t = L->t, target = L->quiet_until > 0 && L->quiet_until < tout ? L->quiet_until : tout;
        gw_solver_set_peek(L->solver, L->peek > L->t && L->peek < target ? L->peek : 0);
        gw_drive drive = {.t_end = target, .on_root = layer_on_root, .on_output = layer_on_output,
                          .after = bounded ? NULL : layer_after_bound, .ctx = L};
        int rc = gw_solver_drive(L->solver, &drive, &t, L->y, L->roots, err);
        gw_solver_set_peek(L->solver, 0);
        if (rc == GW_SOLVER_PEEK) { /* L->y the state there; the solver on its way to target */
            L->stamp++;
            L->t = t;
            /* DEM mode (verlet): geo is the geometry of the step's end, not
             * of y (interpolated between two steps); the snapshot reads y */
            if (L->geo_pos && !L->geo_peek)
                L->geo_peek = 1, L->geo_pos = 0;
            /* and its tangential forces and ledgers the step's own: a
             * partial step from the step's start, not committed */
            layer_dem_peek(L, t);
            return GW_OK;
        }
        if (rc < 0 && L->adv_over) { /* the bound's own message (layer_after_bound) */
            L->stamp++;
            L->t = t;
            return rc;
        }
        if (rc < 0) {
            L->stamp++;
            L->t = t;
            return gw_err_set(err, rc, "layer: %s solver failed at t = %.9g s (%d particles, %d "
                              "listed contacts): %s", gw_solver_type_name(L->type), t, L->n, L->nc,
                              gw_solver_error(L->solver));
        }
        if (rc != GW_ROOT)
            continue;
        /* a list rebuild or a Zeno guard: a new solver; in DEM mode it starts
         * from the rates the old one would have stepped on with (dem_f) */
        const double *f = L->dem ? gw_solver_rates(L->solver) : NULL;
        if (f) {
            const size_t nb6 = 6 * (size_t)L->nb;
            memcpy(L->dem_f, f, nb6 * sizeof *f);
            memcpy(L->dem_f + nb6, f + nb6 + L->nc, (size_t)L->ntail * sizeof *f);
        }
        if ((rc = layer_contacts_build(L, err)) != GW_OK)
            return rc;
        L->dem_carry = f != NULL;
        rc = make_solver(L, err);
        L->dem_carry = 0;
        if (rc != GW_OK)
            return rc;
    }
    return GW_OK;
}

int layer_can_peek(const gw_solver_type *type)
{
    return type == gw_solver_cvode || type == gw_solver_arkode || type == gw_solver_rk4 || type == gw_solver_verlet;
}

int layer_advance_peek(gw_layer *L, double tpeek, double tout, gw_err *err)
{
    if (!L || !layer_can_peek(L->type) || !(tpeek < tout))
        return gw_layer_advance(L, tpeek, err);
    if (!(tpeek > L->t)) /* (the layer is there) */
        return tpeek == L->t ? GW_OK : gw_layer_advance(L, tpeek, err);
    L->peek = tpeek;
    int rc = gw_layer_advance(L, tout, err);
    L->peek = 0;
    if (rc == GW_OK && L->t != tpeek) /* (tout reached first: cannot be, tpeek < tout) */
        return gw_err_set(err, GW_ESOLVER, "layer: the state at t = %.9g s was not reached (t = %.9g s)", tpeek,
                          L->t);
    return rc;
}

void gw_layer_set_event_hook(gw_layer *L, gw_layer_event_fn fn, void *ctx)
{
    if (!L)
        return;
    L->hook = fn;
    L->hook_ctx = ctx;
}
