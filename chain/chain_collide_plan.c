/*
 * chain_collide_plan.c: what a collision will run with, and the bounds on it
 * checked before anything is allocated (docs/physics.md 1.3): the run options'
 * defaults and RK4's steps per contact time for an accuracy, t_max and dt_out,
 * the solver's step, and the bounds on its steps (chain_steps_check, a sensor
 * body's oscillation), its memory (gw_chain_memory_check), its samples
 * (chain_sampling_check), a light bead's ringing (chain_ring_check) and a
 * column gravity holds on the wall (chain_held_check). Separate from the run
 * (chain_collide.c): it holds no state of a run and its checks are made on
 * their own, before one (gw_chain_run_check, chain_run_steps).
 * Units: SI (s, m, kg, bytes).
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gw_chain.h"
#include "gw_chain_study.h"
#include "chain_model.h"
#include "chain_collide_impl.h"
#include "gw_locale.h"

gw_chain_run_opts gw_chain_run_opts_default(void)
{
    gw_chain_run_opts o;
    memset(&o, 0, sizeof o);
    o.solver = gw_solver_cvode;
    o.sp = gw_solver_params_default();
    return o;
}

/* Measured (bench_falcon_accuracy, RK4 with events as roots, dt = T_c/M, against
 * CVODE BDF at 1e-12, N = 1..40 at three v_imp): the worst relative error, on
 * F_max, is 4.0e-6 at M = 16 and falls as M^-2.5 (7.2e-7 at 32, 1.3e-7 at 64),
 * not M^-4: every contact closing restarts the method on the d^(3/2) force, whose
 * expansion is not smooth at the restart. tau_N errors are smaller. A factor 2
 * margin covers the scatter between N. */
int gw_chain_rk4_steps_per_tc(double rel_acc)
{
    if (!(rel_acc >= GW_CHAIN_RK4_ACCURACY_MIN && rel_acc <= GW_CHAIN_RK4_ACCURACY_MAX))
        return 0;
    double m = 16.0 * pow(4.0e-6 / (0.5 * rel_acc), 1.0 / 2.5);
    return m < 16 ? 16 : (int)ceil(m);
}

int gw_chain_rk4_study_covers(const gw_chain_params *p, long n_max)
{
    /* a column of no bead (n_max -5 was covered), or none at all (a NaN mass
     * was covered: chain_scales_domain) */
    if (!p || n_max < 1 || !chain_scales_domain(p))
        return 0;
    int general = p->wall.layer || p->wall.yield_pressure > 0 || p->wall.loss > 0 || p->sensor.mass > 0 ||
                  p->guide.coulomb > 0 || p->guide.viscous > 0;
    return !(p->damping != GW_DAMP_NONE || p->gravity != 0 || n_max > 40 || general);
}

int gw_chain_rk4_study_apply(gw_chain_run_opts *run, const gw_chain_params *p, double rel_acc, double vmax,
                             int keep_dt_out)
{
    int m = gw_chain_rk4_steps_per_tc(rel_acc);
    /* NULL was written through (SIGSEGV); a vmax of 0, NaN or inf set a
     * dt_out of inf, NaN or 0 (1e-308 m/s: 1.3e59 s) */
    if (m <= 0 || !run || !p || (!keep_dt_out && !(vmax > 0 && isfinite(vmax))))
        return 0;
    run->solver = gw_solver_rk4;
    run->sp.method = GW_METHOD_DEFAULT;
    run->steps_per_tc = m;
    if (!keep_dt_out)
        run->dt_out = gw_chain_tau1(p->mass, p->kwall, vmax) / 10;
    return m;
}
/* 1e8 steps: minutes at n = 3; the default RK4 step T_c/400 makes about 800 n
 * over a collision, so columns up to 1.25e5 beads (a day of CPU already) */
int chain_steps_check(const gw_solver_type *type, const gw_solver_params *sp, const gw_solver_params *given,
                      double t_len, const char *over, gw_err *err)
{
    const double max_steps_run = 1e8;
    const double step = type == gw_solver_rk4 ? fmin(sp->dt, sp->dt_max) : sp->dt_max;
    const int is_dt = type == gw_solver_rk4 && sp->dt <= sp->dt_max;
    /* a step the run chose itself resolves the stiffest contact (or the sensor
     * body's oscillation): "raise it" would be wrong advice there */
    const int chosen = is_dt ? !(given->dt > 0) : !(given->dt_max > 0);
    /* rk4's dt given: its step is at most the dt-max (a quarter of the shortest
     * contact), and raising the dt past it changes nothing (dt 1e-9 on kwall
     * 1e-30: 3.5e20 steps, 5e16 at the cap, was told "raise it") */
    char raise[200] = "raise it";
    if (is_dt && !chosen && !(t_len / sp->dt_max <= max_steps_run))
        gw_snprintf(raise, sizeof raise, "raising it cannot help alone: rk4's step is at most %g s here (%s), still "
                    "about %.3g steps", sp->dt_max, given->dt_max > 0 ? "the dt-max given" : "a quarter of the "
                    "shortest contact", t_len / sp->dt_max);
    if (!(t_len / step <= max_steps_run))
        return gw_err_set(err, GW_EINVAL, "%s: a step of %g s needs about %.3g steps over %s (about %.3g s); "
                          "at most %.0e: %s", is_dt ? "dt" : "dt-max", step, t_len / step, over, t_len, max_steps_run,
                          !chosen ? raise
                          : is_dt ? "the default step resolves the stiffest contact, the sensor body's oscillation or "
                                    "the wall's fastest Maxwell arm (a longer one loses the run): use cvode or arkode"
                                  : "the default largest step is a quarter of the shortest contact (a longer one can "
                                    "step over a contact): fewer beads or a shorter run");
    return GW_OK;
}

/* The steps cvode and arkode take per radian of the sensor body's fastest
 * oscillation, at rtol = atol = 1e-12 and as (tol / 1e-12)^-0.2 above it
 * (never below 2). Measured at n = 3 over the first 50 to 200 us (cvode bdf
 * unless said): 7.1 to 27 at 1e-12 (M 1e-7 kg on 1e9 N/m: 17.4; --k 1e3:
 * 27; M 1e-3 on 1e14: 7.1; --kwall 1e14: 21.6 and 37; --vimp 10: 26; adams
 * and arkode erk 8 and 9), 3.5 at 1e-8, 1.0 at 1e-6. Before, 2 a radian of
 * sqrt(k_s/M) was taken: --n 3 --radius 1 --sensor-mass 1e-7
 * --sensor-stiffness 1e9, estimated at 5.5e6 steps, ran 2e8 (438 s on an
 * idle machine) into the run's own bound and exited 1. */
#define SENSOR_STEPS_PER_RAD 20.0

/* A damped body: the estimate is continuous in its damping ratio zeta =
 * c_s / (2 M omega), for every backend that uses it (cvode bdf and adams,
 * arkode dirk, imex and erk; rk4's step is chain_steps_check's): the
 * collision's own steps at the largest step (t_len / dt_max) plus the ring's.
 * Before, it was piecewise: the undamped estimate below 0.2 of critical and a
 * decay count from 0.2 under bdf and dirk, with nothing for the collision's
 * own steps, the undamped one for the others whatever the damping.
 *
 * cvode bdf and arkode dirk (the body implicit): each of the contacts' events,
 * 4 (n + 1) and counted at least 24 (a short column's steps on the ring did
 * not fall with n: 1e-7 kg at 0.1 of critical, 135,594 steps at n = 1,
 * 149,908 at 5), excites a ring that decays as exp(-zeta omega t) (an
 * overdamped body, zeta > 1, relaxes no faster than omega), followed at
 * per_rad steps a radian until it is below the tolerance: F / min(zeta, 1)
 * steps, F = events per_rad ln(1/tol) (the floor: every event resolved).
 * Below about 0.1 of critical bdf follows it longer: its orders 3 to 5 are
 * stable on the ring only when the mode's angle from the negative axis,
 * arccos(zeta), is within their A(alpha) wedge (order 3: zeta > 0.07),
 * counted as a factor w = 1 + (0.08 / zeta)^3. Light damping keeps bdf on the
 * ring over the whole collision: the undamped estimate U = per_rad omega
 * t_len, falling with the damping as g = exp(-zeta / 0.033) (dirk, which
 * steps over even the undamped ring, as exp(-zeta / 0.008)). The ring's steps
 * are min(F w / min(zeta, 1), max(F, U g)): U at zeta = 0, continuous in
 * zeta. Measured steps at rtol = atol = 1e-12, n = 5, 1e12 N/m, bdf (zeta 0,
 * 0.05, 0.1, 0.15, 0.2, 0.5, 1, 2, 10):
 *   1e-9 kg  6.89e6 1,016,686 16,895 8,711 8,926 7,369 7,244 7,190 7,388
 *   1e-8 kg  2.59e6 1,022,411 51,576 19,401 4,417 3,600 3,570 3,588 3,949
 *   1e-7 kg  2.79e6 652,288 149,908 42,303 3,965 3,038 2,944 2,805 2,980
 *   1e-6 kg  1.01e6 210,826 15,756 5,615 7,679 2,957 2,771 2,994 3,133
 *   1e-5 kg  364,111 66,837 5,675 5,100 3,627 3,080 2,928 2,839 3,206
 * and dirk 4,700 to 13,500 from 0.05 to 2 (18,589 to 133,750 undamped). The
 * estimate over them, damped: 1.3 to 17 for bdf, 1.5 to 16 for dirk (before:
 * 70.6, 250 and 2,670 for bdf on 1e-7 kg at 0.1, 0.15 and 0.2, 0.41 to 0.99
 * at 2 and 10; dirk 1,340 at 0.1 and 0.13 to 0.96 at 2 and 10). At rtol 1e-8
 * bdf steps over the ring sooner (1,368 steps on 1e-7 kg at 0.05: the
 * estimate 90 times).
 *
 * dirk steps over the undamped ring: its steps did not grow with omega as U
 * (estimate over steps 25 to 5,700 with U, 1,450 at rtol 1e-8). Measured
 * undamped at 1e-12, n = 5, 1e12 N/m: 18,589, 29,521, 94,680, 83,311,
 * 133,750, 141,295, 91,713, 56,540, 35,398 and 14,759 steps on 1e-9, 1e-8,
 * 1e-7, 3e-7, 1e-6, 3e-6, 1e-5, 3e-5, 1e-4 and 1e-3 kg (0.7 to 10.7 F, F =
 * 13,260 there); n = 1, 3 and 20: 20,884 (1e-9 kg), 81,150 (1e-7), 139,741
 * (1e-6), 81,397 (1e-7) and 90,986 (1e-6); 7,239 and 3,703 at 1e-10 on 1e-9
 * and 1e-6 kg (1.6 and 0.84 F), 11,587, 1,451, 671 and 742 at 1e-8 on 1e-9,
 * 1e-7, 1e-6, 1e-5 kg (8.3 to 0.48 F). Its U is held to SENSOR_DIRK_OVER F
 * (beyond the collision's span, in proportion). Heavily overdamped, its steps
 * grow with the fast root r = omega (zeta + sqrt(zeta^2 - 1)), about c_s / M:
 * 30,602, 85,860 and 257,152 on 1e-9 kg at 100, 300 and 1000 of critical
 * (below 15,000 up to 30), 77,836 on 1e-8 kg and 23,528 on 1e-7 kg at 1000,
 * 17,963 and 8,954 at rtol 1e-8 and 1e-10 on 1e-9 kg at 1000: about 4e-5 a
 * unit of r t_len, counted as SENSOR_DIRK_FAST (per_rad / 20) r t_len.
 * (Up to 30 of critical on 1e-9 kg and 10 on 1e-7 kg it failed its error
 * test before, gw_sundials.h.) The estimate over these steps: 1.5 to 11.8
 * undamped at 1e-12 (16 to 34 at 1e-8 on 1e-7 to 1e-5 kg), 4.9 and 7.2 at
 * 0.01, 1.35 to 5.1 beyond critical (9.8 and 48 at 1e-8 and 1e-10 on 1e-9
 * kg at 1000); 3-bead drops over 1 ms on 1e-7 kg, 6.8 undamped (145,492
 * steps), 4.9 and 4.4 at 0.1 and 10 of critical.
 *
 * cvode adams and arkode erk are held to the body's fastest mode by their
 * stability whatever the damping (sensor_fast_steps; beyond critical damping
 * its fast root, counted with erk's drag). arkode imex (the body's forces
 * implicit, the pair's explicit part) steps over the ring too but more slowly
 * as the ring is faster, and more with the damping. Measured at 1e-12, n = 5,
 * 1e12 N/m (zeta 0, 0.1, 1, 10): 1e-9 kg 894,177, -, 945,381, 1,257,986;
 * 1e-8 kg 376,610; 1e-7 kg 240,271, 182,805, 248,774, 579,921; 1e-6 kg
 * 138,600; 1e-5 kg 84,147, 46,554, 71,545, 241,899 (368,551 and 597,999 at
 * 30 and 100); 1e-3 kg 14,891; on 1e-7 kg at n = 1 and 20: 108,356 and
 * 448,955; 60,868 at 1e-10; at 1e-8 12,828 (1e-7 kg), 72,085 (1e-9) and 5,021
 * (1e-5); at 1e-8 on 1e-7 kg at 1 and 10 of critical 13,904 and 27,401, on
 * 1e-9 kg at 10 67,621. U over them was 12 to 233: about U (omega / W)^-1/2,
 * W = 1e7 rad/s, times sqrt(1 + zeta / 2) for the damping; counted as U
 * min(1, (omega / SENSOR_IMEX_RATE)^-1/2) sqrt(1 + zeta / 2),
 * SENSOR_IMEX_RATE = 3 W: the estimate over the steps 3.3 to 7.7 at 1e-12,
 * 6.8 to 18.8 at 1e-10 and 1e-8 (a 3-bead drop over 1 ms on 1e-7 kg, 200,643
 * steps undamped: 31). */
/* At looser tolerances (the forty-sixth session) the estimate was loose or
 * below the steps taken. Measured over a grid at n = 5 on 1e12 N/m (cvode
 * bdf, arkode dirk, imex, erk; rtol = atol 1e-6, 1e-8, 1e-10; 1e-9 to 0.1 kg;
 * 0, 0.05, 1 and 10 of critical), estimate over steps before: bdf 0.52 to
 * 1,230 (it steps over a fast ring that the collision excites below the
 * tolerance: 1,370 steps on 1e-7 kg undamped at 1e-8, the estimate 1.68e6;
 * below the steps on 1e-3 to 0.1 kg, a slow ring it follows beside the
 * collision's own steps; 0.46 on 1e-9 kg at 0.05 of critical at 1e-10, past
 * its decay count), dirk 0.13 to 54 (its undamped cap 16 floors at any
 * tolerance; at 1e-6 45,000 to 66,000 steps on 1e-9 kg), imex 4 to 42 at
 * 1e-6, erk 0.58 on 0.1 kg at 0.05 of critical at 1e-10. Now: bdf steps over
 * a ring faster than SENSOR_BDF_OVER_W (tol / 1e-8)^-a (a 0.4 at and above
 * 1e-8, 0.7 below: 2.1e8 rad/s at 1e-6, 3.3e10 at 1e-10; counted as 1 / (1 +
 * (omega / that)^6) of the ring it follows) and counts its floor beside the
 * ring, its light damping followed to exp(-zeta / (0.033 (tol / 1e-12)^0.034))
 * and its wedge as (0.08 / zeta)^5; dirk's cap on the undamped ring is 16
 * (tol / 1e-12)^-0.25 floors, with SENSOR_DIRK_LIGHT (tol / 1e-6)^0.58
 * sqrt(omega t_len) steps on a body faster than about 1.5e9 rad/s and the
 * overdamped body's ring 1 + 0.15 sqrt(zeta - 1) times; imex's steps a radian
 * fall as tol^-0.225 (20 at 1e-12); erk and adams count at least the floor;
 * the steps a radian are at least 3 (2 before). Steps taken (zeta 0, 0.05, 1,
 * 10; - not run: refused, or estimated above 3e6 before) and the estimate
 * over them now:
 * bdf 1e-06
 *   1e-09  6.52k 6.54k 6.54k 6.67k        2.34 2.33 2.33 2.28
 *   1e-08  2.67k 2.88k 2.84k 2.73k        2.49 2.31 2.35 2.44
 *   1e-07  1.14k 1.24k 1.3k 1.4k          2.85 2.62 2.5 2.32
 *   1e-06  587 631 723 1.03k              3.29 3.02 2.62 1.83
 *   1e-05  2.61k 492 467 804              4.85 11.7 2.9 1.68
 *   0.0001 494 493 667 673                103 41.4 1.71 1.69
 *   0.001  9.8k 579 455 480               1.73 12.5 2.33 2.21
 *   0.01   3.47k 1.46k 651 818            1.75 2.06 1.6 1.28
 *   0.1    1.46k 862 495 440              1.81 1.93 2.11 2.37
 * bdf 1e-08
 *   1e-09  - 6.68k 6.72k 6.63k            - 2.34 2.33 2.36
 *   1e-08  2.79k 2.79k 2.97k 2.8k         2.54 2.53 2.38 2.53
 *   1e-07  1.37k 1.37k 1.32k 1.34k        8.56 4.62 2.77 2.72
 *   1e-06  315k 16.5k 852 1.6k            1.41 8.96 2.7 1.44
 *   1e-05  60.8k 32.2k 973 1.25k          2.79 1.78 1.81 1.4
 *   0.0001 28.8k 10.6k 802 1.15k          1.9 1.8 1.93 1.34
 *   0.001  12.2k 6.58k 823 842            1.5 1.07 1.78 1.74
 *   0.01   6.13k 2.53k 837 830            1.1 1.27 1.73 1.75
 *   0.1    2.69k 1.33k 828 816            1.17 1.51 1.75 1.78
 * bdf 1e-10
 *   1e-09  - 1M 6.83k 6.94k               - 1.03 2.73 2.69
 *   1e-08  - 322k 3.13k 3.07k             - 3.16 3.22 3.28
 *   1e-07  - 391k 1.62k 1.96k             - 2.59 4.1 3.4
 *   1e-06  463k 126k 1.7k 1.79k           2.9 2.94 3.11 2.96
 *   1e-05  86.3k 25.4k 1.49k 1.59k        4.95 4.74 3.19 2.99
 *   0.0001 59.6k 21.4k 1.43k 1.55k        2.31 1.92 3.19 2.93
 *   0.001  27.6k 7.61k 1.52k 1.49k        1.69 2.11 2.93 3
 *   0.01   11.7k 3.27k 1.56k 1.5k         1.52 2.48 2.85 2.96
 *   0.1    5.69k 2.28k 1.51k 1.55k        1.53 2.46 2.94 2.87
 * dirk 1e-06
 *   1e-09  54.4k 45.2k 44.6k 66.6k        1.67 2.02 2.04 1.4
 *   1e-08  45.7k 7.46k 7.09k 22.4k        1.1 6.76 7.12 2.3
 *   1e-07  21.6k 1.83k 1.47k 6.71k        1.3 15.3 19.1 4.27
 *   1e-06  590 967 656 825                4.46 2.72 4.02 3.8
 *   1e-05  218 903 553 484                5.39 1.3 2.13 3.38
 *   0.0001 196 678 309 360                5.44 1.57 3.45 4.22
 *   0.001  258 326 183 493                3.98 3.15 5.62 3
 *   0.01   189 150 125 297                5.39 6.79 8.15 4.94
 *   0.1    251 114 103 160                4.06 8.94 9.89 9.17
 * dirk 1e-08
 *   1e-09  11.6k 11.1k 10.8k 11.9k        1.3 1.29 1.33 1.39
 *   1e-08  2.88k 2.75k 2.66k 2.9k         2.89 2.71 2.82 2.97
 *   1e-07  1.45k 1.55k 1.22k 2.02k        3.56 2.79 3.54 2.54
 *   1e-06  671 798 720 2.37k              4.13 2.42 2.69 1.1
 *   1e-05  742 589 523 1.61k              3.26 2.68 3.02 1.38
 *   0.0001 590 509 462 864                3.92 2.9 3.19 2.44
 *   0.001  1.23k 382 382 601              1.85 3.76 3.76 3.44
 *   0.01   1.48k 302 313 450              1.53 4.72 4.55 4.57
 *   0.1    650 242 228 375                2.63 5.89 6.25 4.57
 * dirk 1e-10
 *   1e-09  7.24k 7.17k 6.98k 7.11k        4.11 1.66 1.74 2.55
 *   1e-08  4.01k 3.62k 3.3k 4.21k         6.32 2.06 2.28 2.56
 *   1e-07  3.23k 2.5k 2.23k 3.39k         7.28 2.26 2.54 2.38
 *   1e-06  3.7k 2.04k 1.93k 2.61k         6.13 2.38 2.52 2.67
 *   1e-05  6.84k 1.59k 1.76k 2.3k         3.28 2.87 2.6 2.87
 *   0.0001 16.9k 1.24k 1.44k 2.14k        1.32 3.61 3.12 3.02
 *   0.001  7.4k 1.03k 1.09k 1.73k         3.01 4.29 4.06 3.72
 *   0.01   3.06k 690 759 1.4k             4.38 6.41 5.83 4.56
 *   0.1    1.28k 513 525 1.03k            3.34 8.31 8.12 4.15
 * imex 1e-06
 *   1e-09  55.6k 43.5k 42.7k 66.1k        2.75 3.56 4.35 5.52
 *   1e-08  21k 11.6k 8.89k 30k            4.04 7.41 11.6 6.79
 *   1e-07  4.83k 4.57k 3.04k 11.3k        9.78 10.5 19 10.1
 *   1e-06  2.51k 2.93k 2.76k 5.93k        10.5 9.13 11.7 10.8
 *   1e-05  1.31k 1.82k 1.58k 2.85k        11.3 8.22 11.4 12.6
 *   0.0001 849 1.22k 1.16k 2.07k          9.75 6.86 8.74 9.76
 *   0.001  596 955 662 1.91k              7.8 4.93 8.59 5.94
 *   0.01   409 370 419 1.18k              3.72 4.17 4.44 3.13
 *   0.1    264 223 278 651                1.89 2.27 2.18 1.83
 * imex 1e-08
 *   1e-09  72.1k 84k 59.5k 67.6k          5.8 5.04 8.58 15
 *   1e-08  28k 33.5k 21k 39.8k            8.37 7.07 13.6 14.3
 *   1e-07  12.8k 14.3k 13.9k 27.4k        10.2 9.29 11.5 11.7
 *   1e-06  7.24k 8.51k 10k 17.2k          10.2 8.75 8.97 10.4
 *   1e-05  5.02k 4.85k 5.91k 12.3k        8.23 8.62 8.55 8.22
 *   0.0001 3.44k 3.2k 4.01k 8.39k         6.74 7.34 7.08 6.76
 *   0.001  2.25k 1.87k 2.43k 5.72k        5.8 7.06 6.56 5.57
 *   0.01   1.48k 995 1.37k 3.71k          2.88 4.32 3.79 2.79
 *   0.1    640 508 762 2.29k              2.13 2.72 2.19 1.45
 * imex 1e-10
 *   1e-09  232k 228k 183k -               5.03 5.19 7.79 -
 *   1e-08  126k 118k 95.5k 138k           5.18 5.62 8.39 11.6
 *   1e-07  60.9k 58.6k 66.6k 111k         6.04 6.35 6.76 8.12
 *   1e-06  32.5k 29.4k 40k 94.4k          6.36 7.11 6.33 5.36
 *   1e-05  20.9k 17.6k 23.8k 60.2k        5.54 6.69 5.96 4.72
 *   0.0001 16.8k 9.41k 13.4k 37.4k        3.88 7.02 5.97 4.27
 *   0.001  7.36k 4.77k 7.21k 23k          4.98 7.78 6.23 3.9
 *   0.01   3.07k 2.36k 3.82k 13.1k        3.88 5.12 3.82 2.22
 *   0.1    1.3k 1.24k 2.01k 7.11k         2.92 3.1 2.31 1.31
 * erk 1e-06
 *   1e-06  254k 66.4k - -                 1.98 2.53 - -
 *   1e-05  63.5k 20.2k 285k -             2.51 2.63 3.72 -
 *   0.0001 16.3k 6.11k 90.2k 1.79M        3.09 2.76 3.72 1.18
 *   0.001  4.33k 1.9k 28.7k 27.1k         3.68 2.81 3.7 24.7
 *   0.01   1.3k 636 9.23k 8.6k            3.89 2.68 3.64 24.6
 *   0.1    492 248 3.02k 2.86k            3.3 4.11 3.53 23.5
 * erk 1e-08
 *   1e-06  247k 59.2k - -                 2.16 2.84 - -
 *   1e-05  62.3k 18.5k 287k -             2.7 2.87 3.7 -
 *   0.0001 17.5k 6.08k 92k 1.79M          3.04 2.77 3.65 1.18
 *   0.001  5.96k 2.14k 29.9k 26.8k        2.83 2.5 3.55 24.9
 *   0.01   2.44k 841 9.9k 9.11k           2.19 2.02 3.39 23.2
 *   0.1    1.04k 424 672 3.43k            1.65 3.36 15.9 19.6
 * erk 1e-10
 *   1e-06  250k 60.7k - -                 5.34 2.77 - -
 *   1e-05  75k 20.8k 298k -               5.63 2.56 3.55 -
 *   0.0001 29.3k 8.02k 98.7k 1.8M         4.56 2.1 3.4 1.18
 *   0.001  12.4k 3.46k 33.4k 34.7k        3.4 1.54 3.18 19.3
 *   0.01   5.29k 1.64k 11.7k 14.7k        2.53 2.7 2.87 14.4
 *   0.1    2.36k 965 1.6k 6.92k           1.81 4.58 6.67 9.72
 * Outside [1, 20]: bdf at 1e-6 on 1e-4 kg (103 undamped, 41 at 0.05: it
 * steps over the ring there, 494 steps, but follows it on 2e-4 kg, 19,747
 * steps, and partly on 1e-5 kg, 2,611: not foreseeable from the inputs, the
 * following counted); erk at 10 of critical on 1e-3 to 0.1 kg at 1e-6 and
 * 1e-8 (23 to 25, its fast root's count, where 1e-4 kg takes 1.79 million
 * steps at 1.18). The undamped 1e-9 kg body under bdf at 1e-8, estimated
 * 15,600 (1.68e7 before), had not ended after 90 s of CPU. */
#define SENSOR_WEDGE_ZETA 0.08
#define SENSOR_WEDGE_P 5.0
#define SENSOR_FOLLOW_ZETA_BDF 0.033
#define SENSOR_FOLLOW_ZETA_BDF_TOL 0.034
#define SENSOR_FOLLOW_ZETA_BEYOND 0.05
#define SENSOR_FOLLOW_ZETA_DIRK 0.008
#define SENSOR_FAST_STEPS 20.0
#define SENSOR_DIRK_OVER 16.0
#define SENSOR_DIRK_FAST 1e-4
#define SENSOR_IMEX_RATE 3e7
/* Measured over a grid at looser tolerances (see sensor_steps' table):
 * bdf steps over a ring faster than SENSOR_BDF_OVER_W (tol / 1e-8)^-a rad/s
 * (a = SENSOR_BDF_OVER_LOOSE at and above 1e-8, SENSOR_BDF_OVER_TIGHT below),
 * dirk's cap on the undamped ring falls as tol^-SENSOR_DIRK_OVER_TOL from 16
 * floors at 1e-12, dirk on a body faster than SENSOR_DIRK_LIGHT_W takes
 * SENSOR_DIRK_LIGHT (tol / 1e-6)^SENSOR_DIRK_LIGHT_TOL steps a square root of
 * a radian, imex's steps a radian fall as tol^-SENSOR_IMEX_TOL. */
#define SENSOR_BDF_OVER_W 1.3e9
#define SENSOR_BDF_OVER_LOOSE 0.4
#define SENSOR_BDF_OVER_TIGHT 0.7
#define SENSOR_BDF_OVER_P 6.0
#define SENSOR_DIRK_OVER_TOL 0.25
#define SENSOR_DIRK_LIGHT 36.0
#define SENSOR_DIRK_LIGHT_TOL 0.58
#define SENSOR_DIRK_LIGHT_W 1.5e9
#define SENSOR_DIRK_OVERDAMPED 0.15
#define SENSOR_IMEX_TOL 0.225

/* The steps an explicit method (cvode adams, arkode erk) takes over t_len on
 * a body of rate omega and damping ratio zeta, continuous in zeta: up to
 * critical damping the larger of per_rad a radian falling as exp(-zeta /
 * 0.02) (the ring followed for accuracy while it lasts) and a stability bound
 * that does not fall with the tolerance, SENSOR_FAST_STEPS max(floor,
 * zeta^2) a radian (floor 0.05 for erk, 0.1 for adams); beyond critical
 * (fast != 0) SENSOR_FAST_STEPS zeta^(-1/2) a unit of the overdamped pair's
 * fast root omega (zeta + sqrt(zeta^2 - 1)), about c_s / M (erk's drag,
 * drag_steps), else SENSOR_FAST_STEPS a radian of omega. Measured a radian at
 * 1e-12 (erk / adams, 1e-6 and 1e-5 kg on 1e12 N/m): undamped 2.7-3.0 /
 * 5.3-4.5; 0.05 to 0.5 of critical 0.45-0.76 / 0.96-1.5 (erk 0.30 at 1e-8);
 * critical 5.9-6.3 / 1.3-1.9 (erk 5.4 at 1e-8); a unit of the fast root at
 * 10, 5.4 / 1.3 (erk on 1e-6 kg: 17.9 million steps, 65 s, where the
 * undamped estimate had 3.35 million); erk on 1e-3 kg and 1e9 N/m 2.3, 0.93,
 * 0.41 and 0.29 a unit at 10, 100, 1000 and 5000 (the count 6.3, 2, 0.63 and,
 * with DRAG_STEPS_ERK, 0.3). */
static double sensor_fast_steps(double omega, double zeta, double per_rad, int adams, int fast, double t_len)
{
    if (!(zeta > 1) || !fast) {
        const double z = fmin(fmax(zeta, 0.0), 1.0), floor_rad = adams ? 0.1 : 0.05;
        return fmax(per_rad * exp(-z / 0.02), SENSOR_FAST_STEPS * fmax(floor_rad, z * z)) * omega * t_len;
    }
    const double root = omega * (zeta + sqrt((zeta - 1) * (zeta + 1)));
    return SENSOR_FAST_STEPS / sqrt(zeta) * root * t_len;
}

/* The steps cvode or arkode take over t_len on the sensor body's oscillation
 * (its rate in *omega, the steps a radian in *per_rad, its damping ratio in
 * *zeta; in *damped 1 where the damping lowered the estimate below the
 * undamped one, 2 where the method's stepping over the ring did, else 0); 0
 * without a body. type NULL: the undamped estimate. */
static double sensor_steps(const gw_chain_params *p, const gw_solver_type *type, const gw_solver_params *sp,
                           double t_len, double *omega, double *per_rad, double *zeta, int *damped)
{
    *omega = *per_rad = *zeta = 0;
    *damped = 0;
    if (!(p->sensor.mass > 0 && p->sensor.stiffness > 0))
        return 0;
    /* The body rings between its spring and bead 1's contact, which adds the
     * contact's stiffness dF/dd = 1.5 K d^(1/2) at bead 1's overlap on a
     * rigid wall (an upper bound: the body gives way): a heavy bead (--radius
     * 1, 3.3e4 kg) on 1e-7 kg and 1e9 N/m rings 2.8 times faster than
     * sqrt(k_s/M) */
    const double m1 = p->masses ? p->masses[0] : p->mass,
                 kc = p->kwall > 0 && m1 > 0 && p->v_imp > 0 ? 1.5 * p->kwall * sqrt(gw_chain_dmax1(m1, p->kwall, p->v_imp))
                                                                : 0.0;
    *omega = sqrt((p->sensor.stiffness + (isfinite(kc) ? kc : 0.0)) / p->sensor.mass);
    /* the damping ratio on that stiffness (the contact's counted: a lower
     * ratio, the safe side) */
    *zeta = p->sensor.damping > 0 ? p->sensor.damping / (2.0 * p->sensor.mass * *omega) : 0.0;
    double tol = sp ? fmax(sp->rtol, sp->atol) : 1e-12;
    if (!(tol > 0))
        tol = 1e-12;
    *per_rad = fmax(3.0, SENSOR_STEPS_PER_RAD * pow(fmax(tol, 1e-12) / 1e-12, -0.2));
    const double undamped = *per_rad * *omega * t_len;
    const char *used = type && type != gw_solver_rk4 ? gw_solver_method_used(type, sp ? sp->method : GW_METHOD_DEFAULT)
                                                     : "";
    const int bdf = strcmp(used, "bdf") == 0, dirk = strcmp(used, "dirk") == 0;
    if (!type)
        return undamped;
    const double base = sp && sp->dt_max > 0 ? t_len / sp->dt_max : 0.0;
    if (strcmp(used, "imex") == 0) {
        /* steps over the ring, more slowly than dirk (SENSOR_IMEX_RATE) */
        const double imex = undamped * SENSOR_STEPS_PER_RAD * pow(fmax(tol, 1e-12) / 1e-12, -SENSOR_IMEX_TOL) /
                            *per_rad * fmin(1.0, sqrt(SENSOR_IMEX_RATE / *omega)) * sqrt(1.0 + *zeta / 2.0);
        *damped = imex < undamped ? 2 : 0;
        return base + imex;
    }
    if (!(*zeta > 0) && !dirk && !bdf)
        return base + undamped;
    if (strcmp(used, "erk") == 0 || strcmp(used, "adams") == 0) {
        /* at least the contacts' events resolved, as for bdf and dirk below
         * (erk on 0.1 kg at 0.05 of critical, 1e-10: 965 steps, 557 counted) */
        const double events = 4.0 * ((double)(p->n > 5 ? p->n : 5) + 1.0);
        return base + fmax(events * *per_rad * log(1.0 / fmin(fmax(tol, 1e-15), 0.1)),
                           sensor_fast_steps(*omega, *zeta, *per_rad, strcmp(used, "adams") == 0, 0, t_len));
    }
    if (!bdf && !dirk)
        return base + undamped;
    /* The collision's span, two expected collision lengths at most; beyond it
     * (a drop, a run to t-max) the contacts' events recur and bdf follows a
     * lightly damped ring all the time: a drop of 3 beads on 1e-7 kg and
     * 1e12 N/m took 1.76 and 1.51 million steps over 0.5 ms at 0.05 and 0.1
     * of critical (about 1 a radian), 6,450 at 0.2 and 5,068 at 0.5; counted
     * there as per_rad a radian falling as exp(-zeta / 0.05). The same drop
     * over 10 ms at 0.1: 36,496,580 steps, 65.7 s of CPU, 7.4 MB, estimated
     * 8.4e7 (2.3 times); over 1 ms 3,410,409, estimated 6.9e6 */
    gw_chain_params q = *p;
    q.v_imp = chain_speed_scale(p);
    const double t_span = 2.0 * chain_collision_length(&q, NULL),
                 t_c = t_span > 0 && t_span < t_len ? t_span : t_len, t_b = t_len - t_c,
                 u_c = *per_rad * *omega * t_c, u_b = *per_rad * *omega * t_b;
    const double z = *zeta, events = 4.0 * ((double)(p->n > 5 ? p->n : 5) + 1.0),
                 floor_steps = events * *per_rad * log(1.0 / fmin(fmax(tol, 1e-15), 0.1)),
                 /* dirk steps over even the undamped ring (no more than
                  * SENSOR_DIRK_OVER times the floor), bdf does not */
                 over_c = dirk ? SENSOR_DIRK_OVER * pow(fmax(tol, 1e-12) / 1e-12, -SENSOR_DIRK_OVER_TOL) * floor_steps
                               : INFINITY,
                 /* bdf steps over a ring the collision excites below the
                  * tolerance (its amplitude falls as omega^-1.5) */
                 w_over = SENSOR_BDF_OVER_W * pow(fmax(tol, 1e-15) / 1e-8, tol < 1e-8 ? -SENSOR_BDF_OVER_TIGHT
                                                                                       : -SENSOR_BDF_OVER_LOOSE),
                 keep = bdf ? 1.0 / (1.0 + pow(*omega / w_over, SENSOR_BDF_OVER_P)) : 1.0,
                 /* beyond the collision (a drop) at 16 floors whatever the
                  * tolerance, as bdf's ring there is not kept (below) */
                 over_b = t_b > 0 ? (dirk ? SENSOR_DIRK_OVER * floor_steps : INFINITY) * t_b / t_span : 0.0,
                 wedge = bdf ? 1.0 + pow(SENSOR_WEDGE_ZETA / z, SENSOR_WEDGE_P) : 1.0,
                 decay = z > 0 ? floor_steps * wedge / fmin(z, 1.0) : INFINITY,
                 /* dirk's steps on an overdamped body grow with it (1e-6 kg at
                  * 10 of critical: 2,373 steps at 1e-8, 1,986 counted) */
                 over_damped = dirk ? 1.0 + SENSOR_DIRK_OVERDAMPED * sqrt(fmax(z - 1.0, 0.0)) : 1.0,
                 /* bdf follows the damped ring longer at a looser tolerance (1e-3 kg at
                  * 0.05 of critical: 6,584 steps at 1e-8, 0.54 of the undamped) */
                 follow = fmin(u_c, over_c) * keep *
                          exp(-z / (bdf ? SENSOR_FOLLOW_ZETA_BDF * pow(fmax(tol, 1e-12) / 1e-12, SENSOR_FOLLOW_ZETA_BDF_TOL)
                                        : SENSOR_FOLLOW_ZETA_DIRK)),
                 beyond = t_b > 0 ? fmax(floor_steps * t_b / t_span,
                                         /* not kept to `keep`: a drop's recurring
                                          * contacts hold bdf on the ring (3 beads on
                                          * 1e-7 kg over 0.5 ms at 1e-8 and 0.05 of
                                          * critical: 1,650,209 steps) */
                                         fmin(u_b, over_b) *
                                             exp(-z / (bdf ? SENSOR_FOLLOW_ZETA_BEYOND : SENSOR_FOLLOW_ZETA_DIRK)))
                                  : 0.0,
                 /* dirk on a heavily overdamped body: steps growing with its
                  * fast root omega (zeta + sqrt(zeta^2 - 1)), about c_s / M */
                 fast = dirk ? SENSOR_DIRK_FAST * *per_rad / SENSOR_STEPS_PER_RAD * *omega *
                                   (z + sqrt(fmax(z * z - 1.0, 0.0))) * t_len
                             : 0.0,
                 /* dirk at a loose tolerance on a light body */
                 x_light = pow(*omega / SENSOR_DIRK_LIGHT_W, 6.0),
                 light = dirk ? SENSOR_DIRK_LIGHT * pow(fmax(tol, 1e-15) / 1e-6, SENSOR_DIRK_LIGHT_TOL) *
                                    sqrt(*omega * t_len) * x_light / (1.0 + x_light)
                              : 0.0,
                 /* bdf: the collision's own steps (the floor) beside the ring it follows */
                 ring = fmin(decay, bdf ? floor_steps + follow : fmax(floor_steps, follow)) * over_damped + beyond + fast + light;
    /* bdf counts the collision's own steps beside the ring it follows
     * undamped: a 5-bead column's floor (a long column's floor, 4 (n + 1)
     * events, would refuse a 1 kg body under 2e7 beads at 4.4e10 steps where
     * its ring counts 1.33e8) */
    const double own = bdf ? fmin(floor_steps, 24.0 * *per_rad * log(1.0 / fmin(fmax(tol, 1e-15), 0.1))) : 0.0;
    if (!(ring < undamped + own))
        return base + undamped + own;
    *damped = z > 0 ? 1 : 2;
    return base + ring;
}

int chain_sensor_steps_check(const gw_chain_params *p, const gw_solver_type *type, const gw_solver_params *sp,
                             double t_len, const char *over, gw_err *err)
{
    if (type == gw_solver_rk4)
        return GW_OK; /* rk4: its step is bounded by chain_steps_check */
    double omega, per_rad, zeta;
    int damped;
    const double steps = sensor_steps(p, type, sp, t_len, &omega, &per_rad, &zeta, &damped);
    if (!(steps <= 1e8)) {
        const char *used = gw_solver_method_used(type, sp ? sp->method : GW_METHOD_DEFAULT);
        const int implicit = strcmp(used, "bdf") == 0 || strcmp(used, "dirk") == 0;
        char why[320];
        if (damped == 2)
            gw_snprintf(why, sizeof why, "%.3g a radian at this tolerance; %s steps over the ring, counted at the "
                        "pace measured on it, %s%.4g of critical", per_rad, used, zeta > 0 ? "damped at " : "undamped: ",
                        zeta);
        else if (damped)
            gw_snprintf(why, sizeof why, "damped at %.4g of critical: %.0f contact events, each ringing until its "
                        "decay is below the tolerance, and %s following the lightly damped ring", zeta,
                        4.0 * ((double)(p->n > 5 ? p->n : 5) + 1.0), used);
        else if (implicit)
            gw_snprintf(why, sizeof why, "%.3g a radian at this tolerance, measured 7-37 at 1e-12; %s%.4g of "
                        "critical (c_s = %.3g N s/m is critical), too lightly for %s to step over the ring", per_rad,
                        zeta > 0 ? "damped at " : "undamped: ", zeta, 2.0 * p->sensor.mass * omega, used);
        else
            gw_snprintf(why, sizeof why, "%.3g a radian at this tolerance, measured 7-37 at 1e-12; damped at %.4g of "
                        "critical, which %s follows at its stability's pace", per_rad, zeta, used);
        return gw_err_set(err, GW_EINVAL, "sensor-stiffness: a sensor body oscillating at %.3g rad/s (sqrt((k_s + the "
                          "contact's stiffness)/M)) needs about %.3g steps over %s (about %.3g s; %s); at most 1e+08: "
                          "a softer or heavier sensor body, looser tolerances or a shorter run", omega, steps, over,
                          t_len, why);
    }
    return GW_OK;
}

/* The explicit methods (cvode adams, arkode erk) on a sensor body that rings
 * far faster than the collision: their step is held to the ring by their
 * stability, whatever the tolerance (measured at n = 3, 1e-7 kg on 1e13 N/m:
 * erk 2.11 million steps at 1e-12 and 2.08 at 1e-8, 2.3 a radian; adams 4.8
 * and 4.6 million, 5.2), and the errors of those steps stay in the undamped
 * ring: erk's F_max error grows with the radians. The implicit methods step
 * over a ring that the collision barely excites (its amplitude falls as
 * omega^-1.5). Measured against RK4 at 1e-11 and 5e-12 s (converged within
 * 3e-8 N), F_max's error at 1e-12, erk / adams / cvode bdf, with the radians
 * over the collision's 9.2e-5 s (the plan counts them over its expected
 * 1.1e-4 s, 1.2 times more):
 *   1e10 N/m (2.9e4 radians)                     +6.5e-8 / -2.4e-7 / -1.2e-6 N
 *   1e11 (9.2e4)                                 +4.7e-7 / -1.0e-6 / -8.4e-6
 *   1e12 (2.9e5)                                 +3.8e-6 / -9.7e-6 / +1.2e-5
 *   1e13 (9.2e5)                                 +2.4e-5 / -1.8e-6 / -2.1e-6 (the ring's own)
 *   1e14 (2.9e6, the converged ring 3.8e-7 N)    +7.2e-5 / +3.9e-6 / within 1e-8 of dirk
 * with 8.2 and 9.5 million steps (33 and 44 s) at 1e14 where arkode dirk
 * takes 10,393 (0.6 s); at 1e-8, 1e13, erk's F_max was 0.235 N high (dirk
 * 1.5e-6 N low). Up to 1e12 N/m (3.5e5 radians as the plan counts them)
 * the explicit methods are as close as the implicit ones; beyond 5e5 they
 * are refused (1e13 N/m: 1.1e6), where the ring is more than 1e3 times the
 * beads' shortest contact's pi/tau (8.4e4 at 1e13 N/m). */
#define RING_RAD_MAX 5e5
/* A ring within 1e3 times the beads' shortest contact's pi/tau is the
 * column's own kind of motion, which the explicit methods resolve with its
 * contacts: a 1e-3 kg body on 1e9 N/m (about 9 times) turns 5.1e5 radians
 * under a 20,000-bead column. The rings measured above are 2.7e3 to 2.7e5
 * times. */
#define RING_RATIO_MIN 1e3
#define RING_STEPS_ERK 2.3
#define RING_STEPS_ADAMS 5.2

int chain_ring_explicit_check(const gw_chain_params *p, const gw_solver_type *type, const gw_solver_params *sp,
                              double t_len, const char *over, gw_err *err)
{
    if (type == gw_solver_rk4)
        return GW_OK; /* its step is chain_steps_check's */
    const char *used = gw_solver_method_used(type, sp ? sp->method : GW_METHOD_DEFAULT);
    const int adams = strcmp(used, "adams") == 0, erk = strcmp(used, "erk") == 0;
    if (!adams && !erk)
        return GW_OK; /* bdf, dirk, imex step over the ring */
    double omega, per_rad, zeta;
    int damped;
    sensor_steps(p, NULL, sp, t_len, &omega, &per_rad, &zeta, &damped); /* omega only */
    /* the beads' contacts, bead 1's on a rigid sensor (on the body itself it
     * is as short as the body is light) */
    gw_chain_params rigid = *p;
    rigid.sensor.mass = rigid.sensor.stiffness = rigid.sensor.damping = 0;
    const double rad = omega * t_len, ratio = omega * chain_contact_tau_min(&rigid, 2 * p->v_imp) / M_PI;
    if (!(rad > RING_RAD_MAX && ratio > RING_RATIO_MIN))
        return GW_OK;
    return gw_err_set(err, GW_EINVAL, "sensor-stiffness: a sensor body ringing at %.3g rad/s (sqrt((k_s + the "
                      "contact's stiffness)/M)), %.3g times the beads' shortest contact's pi/tau, turns %.3g radians over "
                      "%s (about %.3g s), above 5e+05: %s %s (explicit) holds its step to it at any tolerance, "
                      "about %.3g steps, and leaves their errors undamped in it: use cvode bdf or arkode dirk "
                      "(implicit: they step over the ring)",
                      omega, ratio, rad, over, t_len, gw_solver_type_name(type), used,
                      (adams ? RING_STEPS_ADAMS : RING_STEPS_ERK) * rad);
}

double chain_rk4_default_dt(const gw_chain_params *p, double steps_per_tc)
{
    double dt = gw_chain_step_scale(p) / (steps_per_tc > 0 ? steps_per_tc : 400.0);
    /* RK4 is stable on a decay of rate r while h r < 2.79; h r <= 1 keeps a
     * margin. The beads' drags are in the step scale (0.5 m/c, over the steps
     * a contact); the sensor body's only bounds the step here: --sensor-mass
     * 1e-3 --sensor-stiffness 1e9 --sensor-damping 1e7 blew up at the default
     * T_c/400 (h r = 25) and runs at h = M/c_s */
    double r[CHAIN_DRAG_N];
    chain_drag_rates(p, r);
    if (r[CHAIN_DRAG_SENSOR] > 0)
        dt = fmin(dt, 1.0 / r[CHAIN_DRAG_SENSOR]);
    /* A viscoelastic wall's Maxwell arm relaxes as dq/dt = ... - q/tau: RK4 is
     * stable on it while h < 2.79 tau, and the arms are not in the step scale
     * (the contacts): arms of 1e-8 to 1e-6 s blew up at T_c/400. The fastest
     * arm bounds the step at h = tau (h r = 1, as the sensor's drag) only where
     * it is shorter than the contacts' step, so runs on slower arms (the
     * default 1e-5 to 1e-3 s) keep their step bit for bit. */
    double tau_arm;
    if (p->wall.loss > 0 && chain_wall_arms(&p->wall, &tau_arm, NULL) > 0 && tau_arm > 0)
        dt = fmin(dt, tau_arm);
    return dt;
}

/* Steps per unit of r t_len an explicit method takes on a drag of rate r
 * (its stability bound, whatever the tolerance), measured at n = 3 over the
 * collision (steel, --sensor-mass 1e-3 --sensor-stiffness 1e9, c_s 1e5 to
 * 1e8 N s/m, and the guide's friction on 1e-4 m beads): cvode adams 1.24 to
 * 1.97 (1.4 at 1e7 and above), arkode erk 0.27 to 0.63 (0.27 at 1e7 and
 * above). cvode bdf, arkode dirk and imex (the forces implicit) are not held
 * by it: bdf took 1480 to 1818 steps at c_s 1e7 to 1e9 and M 1e-7 to 1 kg.
 * Before, no drag was counted: --sensor-damping 1e9 ran for minutes under
 * adams (1.3e8 steps estimated), --radius 1e-5 --guide-friction 1 likewise
 * under adams and erk. */
#define DRAG_STEPS_ADAMS 1.5
#define DRAG_STEPS_ERK 0.3
/* The guide's Coulomb friction, regularised by tanh(v/v_reg), holds them to
 * more at its slope's rate F/(v_reg m): --radius 1e-4 --guide-friction 1
 * (1e11 1/s) took about 3.7 per unit of adams (31.7 s at 1.5 us a step) and
 * 0.35 of erk, over the whole run to t-max: a guide that stops a bead
 * within the collision ((F + c_g v) / m t_e > v_imp) keeps bead 1 on the
 * wall until t-max (exit 1 after 31.7 s there; --radius 1e-5 --guide-viscous
 * 100, 3e12 1/s: 0.83 a unit of adams, 20.6 s, and 0.33 of erk). */
#define DRAG_STEPS_ADAMS_COULOMB 4.0
#define DRAG_STEPS_ERK_COULOMB 0.4

/* The most steps a run may spend on a drag's decay under an explicit method
 * (cvode adams, arkode erk, rk4 at the step the drag sets): each step goes to
 * the method's stability, which cvode bdf does without (1,480 to 1,850 steps
 * at c_s/M = 1e10 to 1e12), and the reading it gives is no better. 1e7 steps
 * is about 15 to 60 s at n = 3. At the general bound, 1e8, such runs were
 * admitted for minutes: --n 3 --sensor-mass 1e-3 --sensor-stiffness 1e9
 * --sensor-damping 1e9 under arkode erk (3.3e7 estimated) took 24.6 million
 * steps, 66 to 108 s; --sensor-damping 1e8 under cvode adams (1.65e7) 18.6
 * million steps, 114 s, with an energy error of 1.3e-7; falcon --n 1:5
 * --sensor-damping 1e9 --solver arkode past 60 s. Measured within it: erk at
 * 1e8 2.57 million steps (13.7 s), adams at 1e7 1.24 million (5.9 s). */
#define DRAG_STEPS_MAX 1e7

/* The steps a drag holds an explicit method to over t_len (0: none, or a
 * method it does not hold), *k the drag (chain_drag_rates' index) and *rate
 * its rate. */
static double drag_steps(const gw_chain_params *p, const gw_solver_type *type, const gw_solver_params *sp,
                         const gw_solver_params *given, double steps_per_tc, double t_len, double t_run, int *k,
                         double *rate, double *t_used)
{
    *t_used = t_len;
    double r[CHAIN_DRAG_N];
    chain_drag_rates(p, r);
    /* the guide's two frictions slow the same bead */
    const double rg = r[CHAIN_DRAG_GUIDE_VISCOUS] + r[CHAIN_DRAG_GUIDE_COULOMB];
    *k = r[CHAIN_DRAG_GUIDE_COULOMB] > r[CHAIN_DRAG_GUIDE_VISCOUS] ? CHAIN_DRAG_GUIDE_COULOMB : CHAIN_DRAG_GUIDE_VISCOUS;
    *rate = rg;
    if (r[CHAIN_DRAG_CONTACT] > *rate)
        *rate = r[CHAIN_DRAG_CONTACT], *k = CHAIN_DRAG_CONTACT;
    if (r[CHAIN_DRAG_SENSOR] > *rate)
        *rate = r[CHAIN_DRAG_SENSOR], *k = CHAIN_DRAG_SENSOR;
    if (!(*rate > 0))
        return 0;
    const char *used = gw_solver_method_used(type, sp ? sp->method : GW_METHOD_DEFAULT);
    if (type == gw_solver_rk4) {
        if (given && given->dt > 0)
            return 0; /* a step given: chain_steps_check */
        /* the step this drag sets (chain_rk4_default_dt, gw_chain_step_scale),
         * counted only where it is the run's */
        const double spt = steps_per_tc > 0 ? steps_per_tc : 400.0,
                     h = *k == CHAIN_DRAG_SENSOR ? 1.0 / *rate : 0.5 / fmax(rg, r[CHAIN_DRAG_CONTACT]) / spt,
                     dt = chain_rk4_default_dt(p, steps_per_tc), step = sp && sp->dt_max > 0 ? fmin(dt, sp->dt_max) : dt;
        return h <= step * (1 + 1e-9) ? t_len / step : 0;
    }
    const int adams = strcmp(used, "adams") == 0, erk = strcmp(used, "erk") == 0;
    if (!adams && !erk)
        return 0; /* bdf, dirk, imex */
    if (*k == CHAIN_DRAG_GUIDE_COULOMB || *k == CHAIN_DRAG_GUIDE_VISCOUS) {
        /* the guide slows the lightest bead by (F_c + c_g v) / m: stopped
         * within t_len, bead 1 stays on the wall to t_run */
        double m_min = p->masses ? p->masses[0] : p->mass;
        for (int i = 0; p->masses && i < p->n; i++)
            m_min = fmin(m_min, p->masses[i]);
        if ((p->guide.coulomb + p->guide.viscous * p->v_imp) / m_min * t_len > p->v_imp)
            *t_used = fmax(t_len, t_run);
    }
    if (erk && *k == CHAIN_DRAG_SENSOR) {
        /* an overdamped body excited by the contacts holds erk to its fast root
         * at more than DRAG_STEPS_ERK a unit below about zeta = 1000
         * (sensor_fast_steps): 1e-5 kg on 1e12 N/m at zeta 10 took 5.65
         * million steps (26 s) at rtol 1e-8, 5.3 a unit of c_s/M, where 0.3
         * was counted; 1e-3 kg on 1e9 N/m 2.3 a unit at 10, 0.93 at 100,
         * 0.41 at 1000, 0.29 at 5000 (rtol 1e-12) */
        double omega, per_rad, zeta;
        int damped;
        sensor_steps(p, NULL, sp, *t_used, &omega, &per_rad, &zeta, &damped);
        if (zeta > 1)
            return fmax(DRAG_STEPS_ERK * *rate * *t_used, sensor_fast_steps(omega, zeta, per_rad, 0, 1, *t_used));
    }
    if (*k == CHAIN_DRAG_GUIDE_COULOMB)
        return (adams ? DRAG_STEPS_ADAMS_COULOMB : DRAG_STEPS_ERK_COULOMB) * *rate * *t_used;
    return (adams ? DRAG_STEPS_ADAMS : DRAG_STEPS_ERK) * *rate * *t_used;
}

int chain_drag_steps_check(const gw_chain_params *p, const gw_solver_type *type, const gw_solver_params *sp,
                           const gw_solver_params *given, double steps_per_tc, double t_len, double t_run,
                           const char *over, gw_err *err)
{
    int k = 0;
    double rate = 0, t_used = t_len;
    const double steps = drag_steps(p, type, sp, given, steps_per_tc, t_len, t_run, &k, &rate, &t_used);
    if (steps <= DRAG_STEPS_MAX)
        return GW_OK;
    const char *what = k == CHAIN_DRAG_SENSOR ? "the sensor body's damping"
                       : k == CHAIN_DRAG_CONTACT ? "the contact damping"
                                                 : "the guide's friction";
    return gw_err_set(err, GW_EINVAL, "%s: %s decays at %.3g 1/s (c/m), which %s %s follows with about %.3g steps "
                      "over %s (about %.3g s), above 1e+07: use cvode with its default method bdf (implicit: "
                      "its step is not held by the damping), or %s", chain_drag_flag[k], what, rate,
                      gw_solver_type_name(type),
                      type == gw_solver_rk4 ? "(explicit)" : gw_solver_method_used(type, sp->method), steps,
                      t_used > t_len ? "the run to t-max (the guide stops a bead within the collision and bead 1 "
                                       "stays on the wall)"
                                     : over,
                      t_used,
                      k == CHAIN_DRAG_SENSOR ? "a smaller damping or a heavier sensor body"
                      : k == CHAIN_DRAG_CONTACT ? "weaker contact damping"
                                                : "a weaker guide friction or heavier beads");
}

/* Bytes a run of column p allocates, by what gw_chain_create, gw_chain_collide
 * (or the drop) and the backend hold: the model's and the result's per-bead
 * arrays (about 14 doubles a bead; the force-rate root's scratch of 2 dim doubles,
 * touched only by the general model's central difference, is within the margin
 * the measured sizes below leave), the solver's vectors over the state (dim =
 * 2n + a few: rk4 10 of them with its root values, cvode and arkode about 24 with
 * their histories and stages, arkode's implicit methods 34) and, for the implicit
 * methods (cvode bdf, arkode dirk and imex), three band matrices of dim x (smu +
 * ml + 1) doubles (the Jacobian, its saved copy and the factor workspace). The
 * band is 2 above and 3 below the diagonal; a sensor body's and a plastic or
 * viscoelastic wall's k states, ordered before the beads (gw_chain_create),
 * widen it to k + 1 on both sides (k at most 2 + 2 + GW_WALL_MAX_ARMS). Before
 * that order they made it the whole system (dim x (2 dim - 1), n^2: 200 MB at
 * n = 1000). Measured peak resident sizes at n = 1e6 (t-max 1e-9 s): 218 B a
 * bead for rk4, 637 cvode bdf, 295 adams, 381 arkode erk, 810 dirk. The
 * estimate is an upper bound for each. */
static int implicit_method(const gw_solver_type *t, int method)
{
    const char *used = gw_solver_method_used(t, method);
    return t != gw_solver_rk4 && (strcmp(used, "bdf") == 0 || strcmp(used, "dirk") == 0 || strcmp(used, "imex") == 0);
}

static double memory_bytes(const gw_chain_params *p, const gw_solver_type *type, int method)
{
    const double n = p->n;
    /* the states ordered before the beads: x_s, v_s; W, D_max - D and the arms
     * (a yield stress and a loss together give all three) */
    const int plastic = p->wall.yield_pressure > 0, visco = p->wall.loss > 0;
    const double k = 2.0 * (p->sensor.mass > 0) + (plastic || visco) + plastic + (visco ? GW_WALL_MAX_ARMS : 0);
    const double dim = 2 * n + 8 + k, mu = fmax(2, k + 1), ml = fmax(3, k + 1);
    const gw_solver_type *t = type ? type : gw_solver_cvode;
    const int implicit = implicit_method(t, method);
    double vectors = t == gw_solver_rk4 ? 10 : implicit && t != gw_solver_cvode ? 34 : 24;
    double bytes = 8 * (14 * n + vectors * dim);
    if (implicit) {
        double ldim = fmin(dim - 1, mu + ml) + ml + 1;
        bytes += 3 * 8 * dim * ldim + 8 * dim;
    }
    return bytes;
}

/* The most beads within GW_CHAIN_MEMORY_MAX (memory_bytes grows with n). */
static long memory_n_ok(const gw_chain_params *p, const gw_solver_type *type, int method)
{
    gw_chain_params q = *p;
    long lo = 0, hi = (long)p->n + 1;
    while (hi - lo > 1) {
        long mid = lo + (hi - lo) / 2;
        q.n = (int)mid;
        if (memory_bytes(&q, type, method) <= GW_CHAIN_MEMORY_MAX)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

int gw_chain_memory_check(const gw_chain_params *p, const gw_solver_type *type, int method, gw_err *err)
{
    if (!p)
        return gw_err_set(err, GW_EINVAL, "gw_chain_memory_check: p is NULL");
    const int nrc = chain_n_check(p->n, err);
    if (nrc != GW_OK)
        return nrc;
    /* a method no backend has (-5, 11) was sized as an explicit one; one its
     * backend lacks (cvode erk) is gw_solver_create's GW_EUNSUPPORTED */
    if (strcmp(gw_solver_method_name(method), "unknown") == 0)
        return gw_check_range(method, "method (GW_METHOD_DEFAULT 0 or a variant, GW_CVODE_BDF 1 to GW_ARKODE_IMEX 5)",
                              GW_METHOD_DEFAULT, GW_ARKODE_IMEX, err);
    const double limit = GW_CHAIN_MEMORY_MAX;
    double need = memory_bytes(p, type, method);
    if (need <= limit)
        return GW_OK;
    long lo = memory_n_ok(p, type, method);
    const gw_solver_type *t = type ? type : gw_solver_cvode;
    return gw_err_set(err, GW_EINVAL,
                      "n: a column of %d beads needs about %.3g GB for its state and the %s (%s) solver's workspace, "
                      "above the %.3g GB limit: at most %ld beads here", p->n, need / 1e9, gw_solver_type_name(t),
                      gw_solver_method_used(t, method), limit / 1e9, lo);
}

/* v rounded down to two significant digits (a suggested bound that passes). */
static double floor_2digits(double v)
{
    const double p = pow(10, floor(log10(v)) - 1);
    return floor(v / p) * p;
}

/* A light bead held by heavy ones rings on its contacts all the time they
 * hold it, and cvode and arkode follow every oscillation: the run stops and
 * restarts at each maximum and minimum of the wall force, and BDF starts again
 * at order 1 there. Measured (cvode bdf at rtol 1e-12, --n 2 --radii 1e-3,X):
 * 258 to 266 steps per oscillation of chain_ring_period over the expected
 * length at X = 1e-2, 3e-2, 0.1 and 1 (1.7e4 to 1.7e7 steps); fewer at looser
 * tolerances, as (tol / 1e-12)^-0.11 (99 at 1e-8, 58 at 1e-6), adams 113 and
 * arkode's erk 133 at 1e-12. --radii 1e-3,1 took 17.1 million steps and 45 s
 * of CPU (2.6 us a step). The plan bounds these steps times the beads at 2e7
 * (about 30 s of CPU) when the ringing is not the column's own: more than
 * RING_RATIO_MAX oscillations per bead transit (2n + 1 of them over the
 * collision's expected length, whatever the run's length t_len). Equal beads
 * would ring 0.37 to 0.61 times per transit (n = 1 to 1000, gravity, sheets),
 * mixed radii of ratio 2 to 20 up to 13; a bead of 1e-3 m under 3e-2, 0.1 and
 * 1 m 67, 407 and 12900 times, 3e-5 m between two of 4e-3 m 564 (within the
 * bound: 3.1e6 bead-steps). Equal beads are not checked: a wall far
 * stiffer than their contacts (--n 10 --k 1e3 --kwall 1e14) has bead 1 bounce
 * between the two (9 wall contacts, 1.26e6 steps), not held ringing. rk4's
 * steps are the fixed step's, bounded by chain_steps_check. The drop's own
 * run over t_max does not call it: its calibration is not this one (drop --n
 * 2 --radii 1e-3,1 took 929331 steps over its 10 ms, 5.8 s, where this would
 * estimate 1.4e7); its first collision, run again by the chain's code, does,
 * before the drop runs (chain_collide_drop_check). */
#define RING_RATIO_MAX 100.0
#define RING_WORK_MAX 2e7
#define RING_STEPS_PER_OSC 260.0

int chain_ring_check(const gw_chain_params *p, const gw_solver_type *type, const gw_solver_params *sp,
                     double t_len, double t_col, const char *over, gw_err *err)
{
    if (type == gw_solver_rk4 || !p->masses)
        return GW_OK;
    /* the run passes the chain's own masses (gw_chain_create fills them for
     * equal beads too): --n 10 --k 1e3 --kwall 1e14 --dt-out 1e-7 was refused
     * at the run as "bead 1 is 1 times lighter than bead 1" */
    int equal = 1;
    for (int i = 1; i < p->n && equal; i++)
        equal = p->masses[i] == p->masses[0];
    if (equal)
        return GW_OK;
    int f = 0;
    const double n = p->n, tr = chain_ring_period(p, &f), osc = t_len / tr;
    double tol = fmax(sp->rtol, sp->atol);
    if (!(tol > 0))
        tol = 1e-12;
    const double per_osc = RING_STEPS_PER_OSC * pow(fmin(tol, 1.0) / 1e-12, -0.11);
    const double work = n * per_osc * osc;
    /* the ringing against the column's own scale: its collision's expected
     * length t_col (whatever t_len) */
    if (!(t_col / tr > RING_RATIO_MAX * (2 * n + 1)) || !(work > RING_WORK_MAX))
        return GW_OK;
    int h = 0;
    for (int i = 1; i < p->n; i++)
        if (p->masses[i] > p->masses[h])
            h = i;
    return gw_err_set(err, GW_EINVAL,
                      "radii: bead %d (%.3g kg) is %.3g times lighter than bead %d (%.3g kg) and rings every %.3g s "
                      "while the heavy beads hold it, about %.3g oscillations over %s (about %.3g s): about %.3g "
                      "bead-steps of %s (%.0f steps an oscillation), above the bound %.0e (about 30 s): use rk4 (its "
                      "fixed step is bounded on its own) or closer radii",
                      f + 1, p->masses[f], p->masses[h] / p->masses[f], h + 1, p->masses[h], tr, osc, over, t_len,
                      work, gw_solver_type_name(type), per_osc, RING_WORK_MAX);
}

/* A column that gravity holds on the wall: when gravity takes back the impact
 * speed within the collision's expected length (g t_e > v_imp), the beads
 * leaving the wall fall back before the column has separated, and the run goes
 * on to t_max with bead 1 bouncing on the wall and the top contacts chattering,
 * cvode restarting at each of their events. Measured (steel, cvode at 1e-12,
 * default t-max and dt-out): the collision ended at g t_e / v_imp = 0.009 to
 * 0.15 (n = 10, 40; g = 9.81, 100; v_imp 0.3 to 0.03) and never at 0.35 and
 * above. The cost of such a run is its samples and steps, each O(n): 0.4 to
 * 1.6 us a bead-sample at the default sampling tau_1/200 (steps 1 to 3.4 per
 * sample: n = 300, g = 100, v_imp = 1e-3 ran 16715 steps and 17189 samples in
 * 1.9 s up to t = 3e-3 s, about 100 s to its default t-max of 0.152 s; n = 40,
 * g = 100, v_imp = 1e-3 407013 steps, 126228 samples, 8 s; profiled again:
 * 7728 contact events and 446 force maxima over its 29 ms, about 200 a
 * contact, each a real collision of beads bouncing under their weight (18 at
 * a relative speed below 1e-9 m/s, none within 1e-7 s of the contact's
 * previous event: no chattering), each a restart of BDF at order 1, about 95
 * steps a restart, 780k steps, half the CPU in the band LU; adams took 1.2 s,
 * arkode's erk 0.6 s, bdf 5.1 s). The steps follow
 * the contacts, not the sampling: the estimate counts samples at the finer of
 * dt-out and tau_1/200, times the beads, over t_max, bounded at 1e7 (about 4
 * to 16 s) whatever t_max was given. The run itself now stops once the beads'
 * momentum is back toward the wall before the collision ended (chain_collide.c,
 * held_by_gravity: n = 40, g = 100, v_imp = 1e-3 at 2.5 ms, 0.15 s of CPU);
 * this bound stays for a run that never shows that turn before t_max. */
#define HELD_WORK_MAX 1e7

/* The longest t_max the bound admits for a held column (INFINITY when gravity
 * does not hold it), rounded down to two digits. */
static double held_t_lim(const gw_chain_params *p, double t_col, double tau1, double dt_out)
{
    if (!(p->gravity > 0) || !(p->gravity * t_col > p->v_imp))
        return INFINITY;
    return floor_2digits(HELD_WORK_MAX / p->n * fmin(dt_out, tau1 / 200.0));
}

int chain_held_check(const gw_chain_params *p, double t_max, double t_col, double tau1, double dt_out, gw_err *err)
{
    if (!isfinite(held_t_lim(p, t_col, tau1, dt_out)))
        return GW_OK;
    const double dt = fmin(dt_out, tau1 / 200.0), samples = t_max / dt, work = p->n * samples;
    if (!(work > HELD_WORK_MAX))
        return GW_OK;
    return gw_err_set(err, GW_EINVAL,
                      "gravity: %g m/s^2 takes back the impact speed (vimp %g m/s) in %.3g s, within the collision's "
                      "expected %.3g s: the column stays on the wall, bouncing on it, and the run goes on to t-max "
                      "%.3g s, about %.3g samples of %.3g s times %d beads, above the bound %.0e (about 15 s): lower "
                      "t-max to %g s or less, raise vimp or lower gravity",
                      p->gravity, p->v_imp, p->v_imp / p->gravity, t_col, t_max, samples, dt, p->n, HELD_WORK_MAX,
                      held_t_lim(p, t_col, tau1, dt_out));
}

/* Every sample costs a fixed part (the drive's stop, the root functions, the
 * observation) besides its O(n): about 0.6 us at n = 2. The default dt-out,
 * tau_1/200 of bead 1 on the wall, gives about 185 samples per bead transit of
 * an ordinary column (200 over the wall contact, 2n + 1 transits of 2 T_c);
 * a wall far stiffer than the bead contacts makes tau_1 tiny against the
 * column's own length (--n 2 --k 1e3 --kwall 1e14: tau_1 = 0.87 us over a
 * collision of 28 ms, dt-out 4.4 ns, 6.4e6 samples). Sampling finer than 1e4
 * a bead transit and more than 3e6 samples over the collision (about 2 s at
 * n = 2; rk4 on --radii 1e-3,1, 1.8e6 samples, ran in 1.6 s) is refused, naming dt-out and the interval that passes; the large
 * counts of long columns (200 + 370 n at the defaults) come from their length,
 * not their sampling, and stay bounded by the plan's 1e9. */
#define SAMPLING_MAX 3e6
#define SAMPLING_PER_TRANSIT_MAX 1e4

int chain_sampling_check(int n, double t_expect, double dt_out, int given, const char *over, const char *why,
                         gw_err *err)
{
    const double samples = t_expect / dt_out, transits = 2.0 * n + 1;
    if (!(samples > SAMPLING_MAX) || !(samples / transits > SAMPLING_PER_TRANSIT_MAX))
        return GW_OK;
    /* the interval that passes, rounded up to two digits */
    const double lim = t_expect / fmax(SAMPLING_MAX, SAMPLING_PER_TRANSIT_MAX * transits),
                 q = pow(10, floor(log10(lim)) - 1);
    return gw_err_set(err, GW_EINVAL,
                      "dt-out: %s%g s gives about %.3g samples over %s (about %.3g s), %.3g per bead "
                      "transit of %d beads; at most %.0e when above %.0e a transit: raise dt-out to %.2g s or more%s",
                      given ? "" : "the default tau_1/200 = ", dt_out, samples, over, t_expect, samples / transits, n,
                      SAMPLING_MAX, SAMPLING_PER_TRANSIT_MAX, ceil(lim / q) * q,
                      given ? ""
                      : why ? why
                            : " (the wall's contact is far shorter than the column's: a stiff wall on soft contacts)");
}

/* The run options' numbers whose 0 is "the default" or "off": each finite
 * and >= 0. A NaN or negative value failed every "> 0" test and ran as that
 * default (dt_out -1 sampled every tau_1/200, steps_per_tc NaN took 400 RK4
 * steps per T_c, t_max NaN the default t-max), with GW_OK; so did the solver
 * settings' dt and dt_max (sp.dt, sp.dt_max). GW_EINVAL naming the member,
 * or GW_OK. */
static int opts_numbers_check(const gw_chain_run_opts *o, gw_err *err)
{
    const struct {
        const char *name;
        double v;
    } f[] = {{"dt_out", o->dt_out}, {"t_max", o->t_max}, {"energy_tol", o->energy_tol},
             {"front_threshold", o->front_threshold}, {"steps_per_tc", o->steps_per_tc},
             /* the solver's steps, 0 the default as well: rk4 ran a dt of -1, NaN
              * or -inf, and every backend a dt_max of -1 or NaN, as that default
              * with GW_OK (cvode and arkode refused the dt at their create, after
              * gw_chain_run_check had passed it) */
             {"sp.dt", o->sp.dt}, {"sp.dt_max", o->sp.dt_max}};
    for (size_t i = 0; i < sizeof f / sizeof f[0]; i++) {
        if (!(isfinite(f[i].v) && f[i].v >= 0))
            return gw_err_set(err, GW_EINVAL, "gw_chain_run_opts.%s: %g is not a finite number >= 0 (0: the default)",
                              f[i].name, f[i].v);
        /* a subnormal is no time, tolerance or count: t_max 4.9e-324 s "blew
         * up" under cvode and arkode ("lower dt-max, rtol or atol"),
         * steps_per_tc 4.9e-324 made rk4's step T_c / it inf ("solver: dt must
         * be >= 0, got inf"), naming neither (the fiftieth pass) */
        if (f[i].v > 0 && f[i].v < DBL_MIN)
            return gw_err_set(err, GW_EINVAL, "gw_chain_run_opts.%s: %g is a subnormal number (below 2.2251e-308, "
                              "the smallest normal double): give 0 for the default or a normal number",
                              f[i].name, f[i].v);
    }
    /* the tolerances, which every backend's create refuses outside [1e-15,
     * 1e-4]: this check passed rtol NaN or atol -1 and the run refused them
     * only when it was started ("solver: rtol: nan ...") */
    if (o->sp.use_jac != 0 && o->sp.use_jac != 1) /* any int ran as 1 (the fiftieth pass) */
        return gw_err_set(err, GW_EINVAL, "gw_chain_run_opts.sp.use_jac: %d is not 0 (difference quotients) or 1 "
                          "(the model's Jacobian)", o->sp.use_jac);
    return gw_solver_tolerances_check(o->sp.rtol, o->sp.atol, "gw_chain_run_opts.sp.rtol",
                                      "gw_chain_run_opts.sp.atol", err);
}

/* The run's steps over its expected collision (as plan_make counts them)
 * with the bead-bead coefficient k in place of p's, every other input p's
 * and o's: NaN where the column's scales leave the doubles. */
static double steps_of(const gw_chain_params *p, const gw_chain_run_opts *o, const gw_solver_type *type);

static double steps_at_k(const gw_chain_params *p, const gw_chain_run_opts *o, const gw_solver_type *type, double k)
{
    gw_chain_params q = *p;
    q.k = k;
    q.kc = NULL; /* (stiff_refusal: each of them p's k) */
    return steps_of(&q, o, type);
}

/* the same for the column q as it is */
static double steps_of(const gw_chain_params *p, const gw_chain_run_opts *o, const gw_solver_type *type)
{
    const gw_chain_params q = *p;
    const double t_col = chain_collision_length(&q, NULL);
    const double t_expect = fmin(o->t_max > 0 ? o->t_max : 20.0 * t_col, t_col);
    gw_solver_params sp = o->sp;
    if (!(sp.dt_max > 0))
        sp.dt_max = 0.25 * chain_contact_tau_min(&q, 2 * q.v_imp);
    if (type == gw_solver_rk4 && !(sp.dt > 0))
        sp.dt = chain_rk4_default_dt(&q, o->steps_per_tc);
    const double r = t_expect / (type == gw_solver_rk4 ? fmin(sp.dt, sp.dt_max) : sp.dt_max);
    return isfinite(r) && r > 0 ? r : NAN;
}

/* The steps' bound refused a step the run chose itself from the column's
 * contacts: k = 1.8e308 N/m^1.5 (with the default kwall, masses and v_imp;
 * the library's struct, whose k has no range of its own, the column being
 * scale-free) was refused as "dt-max: a step of 2.86e-125 s needs about
 * 1.22e+120 steps ... fewer beads or a shorter run", naming a quantity
 * derived from k and advice beside the point (the fiftieth pass; left after
 * session 43). Where the bound holds for some k (one k at every contact, the
 * other inputs as given) and not for the k given, the refusal names k, its
 * value and the range of k within the bound, and what the steps came to. The
 * steps are one-humped in log k (falling while the wall's contact sets the
 * step and the transits shorten, rising once the bead-bead contact sets it):
 * their least found by golden section, each end of the range by bisection, to
 * 1e-7 decades, given to two digits inside it; about 130 evaluations, each
 * O(1) for equal beads, O(n) otherwise. GW_OK (err untouched) where k is not
 * the cause: a k within the bound, a bead-bead contact that is not the
 * column's shortest (a stiff wall's is: kwall the cause), kc other than k at
 * a contact, a step given, or no k within the bound (too many beads: the
 * message as it was).
 *
 * The wall's kwall alike (wall 1): a kwall of 1.8e308 was refused under the
 * names of what it sets, "dt-out: the default tau_1/200 = 8.68e-127 s gives
 * about 8.63e+121 samples" (the default dt-out), "dt-max: a step of 3.78e-125
 * s" (dt-out given) or rk4's "dt: a step of 1.78e-127 s" (left after session
 * 44). Where the wall's contact is the column's shortest, kwall is named
 * with its range within the steps' bound; the default dt-out's samples
 * (tau_1/200, tau_1 the wall's) are put on kwall only where its steps are
 * refused too (else a dt-out passes: chain --n 2 --k 1e3 --kwall 1e14 is told
 * the dt-out that does). */
static double stiff_over(const gw_chain_params *p, const gw_chain_run_opts *o, const gw_solver_type *type, int wall,
                         double x)
{
    if (!wall)
        return steps_at_k(p, o, type, x) / 1e8;
    gw_chain_params q = *p;
    q.kwall = x;
    return steps_of(&q, o, type) / 1e8;
}

/* The coefficient (k, wall 0; kwall, wall 1) of the column q set to x */
static gw_chain_params with_coef(const gw_chain_params *q, int wall, double x)
{
    gw_chain_params w = *q;
    if (wall)
        w.kwall = x;
    else {
        w.k = x;
        w.kc = NULL; /* (stiff_refusal: each of them q's k) */
    }
    return w;
}

/* No k (kwall) keeps the run within the steps' bound (stiff_refusal's least
 * steps, `least` at log10 k = best, above it). Under rk4 with a dt given whose
 * step the given coefficient's contact cuts (a quarter of it below the dt:
 * the run steps at that quarter) the refusal named the dt-max, which was not
 * given ("dt-max: a step of 5.74e-14 s ... the default largest step is a
 * quarter of the shortest contact": dt 1e-13 with k 1e30, left after the
 * forty-fifth session). Two inputs are wrong there, named in one line in a
 * stated order, the dt first: the dt, where it is the step at the best
 * coefficient (too small for any: "raise it"), and the coefficient, too stiff
 * for the dt, with the largest value whose contact keeps the dt as the step.
 * Where the dt is not the step even at the best coefficient (another input,
 * a soft wall's long collision, holds the steps up), the coefficient alone is
 * named, saying that no value of it keeps the run within the bound at that
 * dt. GW_OK (err untouched) elsewhere: no dt given, a dt the contact does not
 * cut (the dt's own refusal), or another contact already shorter than 4 dt. */
static int rk4_dt_stiff(const gw_chain_params *q, const gw_chain_run_opts *o, const gw_solver_type *type, int wall,
                        double k, double best, double least, const char *over, gw_err *err)
{
    const double dt = o->sp.dt, v2 = 2 * q->v_imp;
    if (!(type == gw_solver_rk4 && dt > 0))
        return GW_OK;
    const double tau = chain_contact_tau_min(q, v2);
    gw_chain_params soft = with_coef(q, wall, DBL_MIN);
    if (!(0.25 * tau < dt) || !(0.25 * chain_contact_tau_min(&soft, v2) >= dt))
        return GW_OK;
    /* the largest coefficient whose contact keeps the dt as the step (the
     * shortest contact falls as the coefficient grows) */
    double in = log10(DBL_MIN), out = log10(k);
    for (int it = 0; it < 80 && out - in > 1e-7; it++) {
        const double mid = 0.5 * (in + out);
        gw_chain_params w = with_coef(q, wall, pow(10, mid));
        if (0.25 * chain_contact_tau_min(&w, v2) >= dt)
            in = mid;
        else
            out = mid;
    }
    const double k_dt = pow(10, in), qd = pow(10, floor(in) - 1), k_dt2 = fmax(floor(k_dt / qd) * qd, DBL_MIN);
    /* the least steps lie at or below k_dt (the dt the step there; the
     * steps rise with the coefficient above it): within the search's 1e-6
     * decades of it, at it */
    const int dt_is_step = best <= in + 1e-5;
    const char *name = wall ? "kwall" : "k", *whose = wall ? "the wall's" : "its shortest";
    char stiff[320];
    gw_snprintf(stiff, sizeof stiff, "%s: %g N/m^1.5 is too stiff for that dt: %s contact lasts %.3g s, a quarter of "
                "it (%.3g s) below the dt; %s up to %.2g keeps the dt as the step", name, k, whose, tau, 0.25 * tau,
                name, k_dt2);
    if (dt_is_step)
        return gw_err_set(err, GW_EINVAL, "dt: a step of %g s needs at least about %.3g steps over %s at any %s (the "
                          "rest as given; at most 1e+08): raise it; and %s (named in the order dt, k, kwall)", dt,
                          least, over, name, stiff);
    return gw_err_set(err, GW_EINVAL, "%s (the dt given: %g s); no %s keeps this column within 1e+08 steps at that dt "
                      "(at least about %.3g over %s, the rest as given)", stiff, dt, name, least, over);
}

/* Bead 1's largest overlap on the wall (the closed form at v_imp) beyond its
 * radius: a wall too soft for the Hertz law it is given (kwall 1e-30 N/m^1.5:
 * 3.6e10 m), whose contact makes the collision as long as it likes (3.5e11 s).
 * The one absolute scale of the column: the contacts' times and the step are
 * otherwise relative to each other (k 1e30 on the default wall is as far from
 * the wall as kwall 1e-30 on the default beads, and there k is the cause). */
static int wall_too_soft(const gw_chain_params *q)
{
    const double m0 = q->masses ? q->masses[0] : q->mass;
    return gw_chain_dmax1(m0, q->kwall, q->v_imp) > q->radius;
}

/* soft 1 (wall 1 only): the wall's soft side, a wall too soft for its law
 * (wall_too_soft) below its best with some kwall within the bound, the rest
 * as given: its contact lengthens the collision while the bead contacts set
 * the step. Its kwall was never named: the refusal said "dt: ... raise it"
 * under rk4 with a dt given (dt 1e-9: raising it to rk4's largest step, a
 * quarter of the bead contact, still left 5e16 steps), and k (outside
 * [1.5e-42, 1.6e-18]) without one (left after session 46). */
static int stiff_refusal(const gw_chain_params *p, const gw_chain_run_opts *o, const gw_solver_type *type, int wall,
                         int soft, const char *over, gw_err *err)
{
    /* (rk4 with a dt given was left out for k: k = 1.8e308 at dt 1e-9 was
     * refused as "dt-max: a step of 2.86e-125 s ..." (left after session 44);
     * its steps over k are those of the dt given where it is below a quarter
     * of the contacts, steps_of's, and k is named as without a dt) */
    if (p->n < (wall ? 1 : 2) || o->sp.dt_max > 0)
        return GW_OK;
    for (int i = 0; !wall && p->kc && i < p->n - 1; i++) /* the chain's own kc: each k, unless given per contact */
        if (p->kc[i] != p->k)
            return GW_OK;
    gw_chain_params q = *p;
    int equal = q.masses != NULL; /* equal beads: the scalar mass (each evaluation O(1)) */
    for (int i = 1; equal && i < q.n; i++)
        equal = q.masses[i] == q.masses[0];
    if (equal) {
        q.mass = q.masses[0];
        q.masses = NULL;
    }
    const double k = wall ? p->kwall : p->k, lk = log10(k), lo_end = log10(DBL_MIN), hi_end = log10(DBL_MAX);
#define K_STEPS(x) stiff_over(&q, o, type, wall, pow(10, (x)))
#define K_OK(x) (K_STEPS(x) <= 1.0)
    if (K_OK(lk))
        return GW_OK;
    /* the cause: its contact the shortest, shorter than every other (the
     * wall's, a sensor's; the bead-bead ones) as with the softest. A column on
     * a wall of kwall 1.8e308 was otherwise told to take k above 3.9e290. */
    gw_chain_params softest = q;
    softest.kc = NULL;
    if (wall)
        softest.kwall = DBL_MIN;
    else
        softest.k = DBL_MIN;
    gw_chain_params given = softest;
    if (wall)
        given.kwall = k;
    else
        given.k = k;
    if (!soft &&
        !(chain_contact_tau_min(&given, 2 * q.v_imp) < chain_contact_tau_min(&softest, 2 * q.v_imp) * (1 - 1e-9)))
        return GW_OK;
    /* the least steps (NaN, beyond the doubles, as more than any) */
    const double g = 0.5 * (sqrt(5.0) - 1);
    double a = lo_end, b = hi_end, c = b - g * (b - a), d = a + g * (b - a);
    double fc = K_STEPS(c), fd = K_STEPS(d);
    for (int it = 0; it < 70 && b - a > 1e-6; it++) {
        if (!(fc >= fd) && !isnan(fc)) { /* fc < fd, or fd NaN */
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = K_STEPS(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = K_STEPS(d);
        }
    }
    const double best = 0.5 * (a + b);
    if (soft && !(wall && wall_too_soft(&q) && lk < best && K_OK(best)))
        return GW_OK;
    if (!K_OK(best)) /* no k within the bound: under rk4 with a dt given, maybe the dt and k both */
        return rk4_dt_stiff(&q, o, type, wall, k, best, K_STEPS(best) * 1e8, over, err);
    /* under rk4 with a dt given, a k below its best makes too many steps of
     * that dt: the dt is the cause and is named (softwall --solver rk4 --dt
     * 1e-12 was told that its default k, 6.97e9, is outside [1.4e12, 1e28]);
     * k is named above it, where its contact is shorter than the dt allows */
    if (!soft && type == gw_solver_rk4 && o->sp.dt > 0 && lk < best)
        return GW_OK;
    double ends[2];
    for (int side = 0; side < 2; side++) {
        double in = best, out = side ? hi_end : lo_end;
        if (K_OK(out)) { /* within the bound to the doubles' end */
            ends[side] = side ? DBL_MAX : DBL_MIN;
            continue;
        }
        for (int it = 0; it < 60 && fabs(out - in) > 1e-7; it++) {
            const double mid = 0.5 * (in + out);
            if (K_OK(mid))
                in = mid;
            else
                out = mid;
        }
        ends[side] = pow(10, in);
    }
#undef K_OK
#undef K_STEPS
    /* two digits, inside the range */
    const double q0 = pow(10, floor(log10(ends[0])) - 1), q1 = pow(10, floor(log10(ends[1])) - 1);
    const double lo = ends[0] > DBL_MIN ? ceil(ends[0] / q0) * q0 : ends[0],
                 hi = ends[1] < DBL_MAX ? floor(ends[1] / q1) * q1 : ends[1];
    const double t_col = chain_collision_length(&q, NULL);
    const double t_expect = fmin(o->t_max > 0 ? o->t_max : 20.0 * t_col, t_col);
    const double tau = chain_contact_tau_min(&q, 2 * q.v_imp);
    /* rk4's dt given above a quarter of that contact: its steps are the
     * contact's (a dt below it sets them itself: the range is then that dt's) */
    char dt_given[128] = "";
    if (type == gw_solver_rk4 && o->sp.dt > 0.25 * tau)
        gw_snprintf(dt_given, sizeof dt_given, "; the dt given (%g s) does not change that: rk4's step is at most a "
                    "quarter of the shortest contact", o->sp.dt);
    if (soft) {
        const double m0 = q.masses ? q.masses[0] : q.mass;
        return gw_err_set(err, GW_EINVAL, "kwall: %g N/m^1.5 is outside [%.2g, %.2g], where the run stays within "
                          "1e+08 steps (%d beads, k %g N/m^1.5, the rest as given): too soft, bead 1 overlapping the "
                          "wall by %.3g m for %.3g s, the step (at most a quarter of the shortest contact, %.3g s) "
                          "needing about %.3g steps over %s",
                          k, lo, hi, p->n, p->k, gw_chain_dmax1(m0, k, q.v_imp), gw_chain_tau1(m0, k, q.v_imp), tau,
                          steps_of(&q, o, type), over);
    }
    if (wall)
        return gw_err_set(err, GW_EINVAL, "kwall: %g N/m^1.5 is outside [%.2g, %.2g], where this column's run stays "
                          "within 1e+08 steps (%d beads, k %g N/m^1.5, masses, radii and v_imp as given): at this "
                          "kwall its shortest contact, the wall's, lasts %.3g s, and the step chosen to resolve it "
                          "needs about %.3g steps over %s (about %.3g s)%s",
                          k, lo, hi, p->n, p->k, tau, steps_of(&q, o, type), over, t_expect, dt_given);
    return gw_err_set(err, GW_EINVAL, "k: %g N/m^1.5 is outside [%.2g, %.2g], where this column's run stays within "
                      "%.0e steps (%d beads, kwall %g N/m^1.5, masses, radii and v_imp as given): at this k its "
                      "shortest contact lasts %.3g s, and the step chosen to resolve it needs about %.3g steps over %s "
                      "(about %.3g s)%s",
                      k, lo, hi, 1e8, p->n, p->kwall, tau, steps_at_k(&q, o, type, k), over, t_expect, dt_given);
}

/* k (unless wall_only), then kwall: GW_OK where neither is the cause (err
 * untouched). A dt_max given above the contacts does not lower the work: the
 * solver resolves each contact under any cap. k = 1.8e308 with dt_max 1e-9
 * passed the check (left after session 44) and failed at its fourth step
 * (cvode: "corrector convergence test failed", h = 9.6e-16 s), k = 1e30 ran
 * on for minutes: with a dt_max given, k and kwall are held to their ranges
 * at the default cap, the refusal naming the dt-max given too. */
static int stiffness_refusal(const gw_chain_params *p, const gw_chain_run_opts *o, const gw_solver_type *type,
                             int wall_only, const char *over, gw_err *err)
{
    gw_chain_run_opts od = *o;
    od.sp.dt_max = 0;
    gw_err ek = {{0}};
    /* a soft wall first: its contact sets the collision's length, which no k
     * or dt shortens */
    int rc = stiff_refusal(p, &od, type, 1, 1, over, &ek);
    if (rc != GW_OK && type == gw_solver_rk4 && o->sp.dt > 0 && p->n > 1) {
        /* and the bead contacts, where they cut the dt given (k 1e30 at dt
         * 1e-9 on kwall 1e-30: both wrong, k named before the soft wall) */
        gw_chain_params beads = *p;
        beads.kwall = DBL_MIN;
        const double tau_b = chain_contact_tau_min(&beads, 2 * p->v_imp);
        if (0.25 * tau_b < o->sp.dt) {
            const gw_err was = ek;
            gw_err_set(&ek, rc, "%s; and %s: %g N/m^1.5 is too stiff for that dt (its contact %.3g s, a quarter "
                       "below the dt)", was.msg, p->kc ? "kc" : "k", p->k, tau_b);
        }
    }
    if (rc == GW_OK && !wall_only)
        rc = stiff_refusal(p, &od, type, 0, 0, over, &ek);
    if (rc == GW_OK)
        rc = stiff_refusal(p, &od, type, 1, 0, over, &ek);
    if (rc == GW_OK)
        return GW_OK;
    if (o->sp.dt_max > 0)
        return gw_err_set(err, rc, "%s; the dt-max given (%g s) does not change that: the solver resolves each "
                          "contact under any cap", ek.msg, o->sp.dt_max);
    return gw_err_set(err, rc, "%s", ek.msg);
}

/* The CPU time of a column at the bound, as chain_column_work_check says it:
 * chain --n 1414 (cvode bdf, a whole collision) took 353 s of CPU, 1.35e6
 * steps (docs/cli.md); the other solvers less, so the bound is one for all:
 * --solver rk4 39.9 s (2.95e6 steps), --solver arkode (erk) 33.6 s (3.2e5
 * steps) */
#define COLUMN_WORK_CPU "6 min"

int chain_column_work_check(long n, double t_expect, double t_col, const char *over, const char *name,
                            const char *t_max_name, gw_err *err)
{
    /* A column's work grows as N^2 (N beads, steps over a collision of N
     * transits): the studies' bound (GW_CHAIN_STUDY_WORK_MAX, N = 1414 over a
     * whole collision) holds for one column too, over the share of its
     * collision the run covers (t_expect / t_col: a short t-max runs the start
     * of a long column). Before the forty-fifth session one column was bounded
     * by its memory alone: chain --n 100000 (a collision of 2.5 s) ran, its
     * progress saying 6.5e5 s left (N = 400 took 15.5 s of CPU) */
    const double share = t_col > 0 ? fmin(1.0, t_expect / t_col) : 1.0, work = (double)n * (double)n * share;
    if (work <= GW_CHAIN_STUDY_WORK_MAX)
        return GW_OK;
    char more[96] = "";
    if (t_max_name)
        gw_snprintf(more, sizeof more, ", or %s to run only the collision's start", t_max_name);
    return gw_err_set(err, GW_EINVAL, "%s: a column of %ld beads over %s (about %.3g s) is %.4g bead^2 of work (N^2 "
                      "times the share of the collision run), above the bound %.0e of the studies (N = %.0f over a "
                      "whole collision, about %s of CPU): lower %s%s", name, n, over ? over : "the collision",
                      t_expect, work, GW_CHAIN_STUDY_WORK_MAX, floor(sqrt(GW_CHAIN_STUDY_WORK_MAX)),
                      COLUMN_WORK_CPU, name, more);
}

/* The plan; whole 0: only the bounds that hold whatever t_max the run is cut
 * at (t_max above the collision's expected length), not those of a run going
 * on to t_max (chain_collide_plan_early) */
static int plan_make(const gw_chain_params *p0, const gw_chain_run_opts *o, collide_plan *pl, int whole, gw_err *err)
{
    memset(pl, 0, sizeof *pl);
    int orc = opts_numbers_check(o, err);
    if (orc != GW_OK)
        return orc;
    gw_chain_params q = *p0; /* the time scales at chain_speed_scale; p0 itself for the rest */
    q.v_imp = chain_speed_scale(p0);
    const gw_chain_params *p = &q;
    const int n = p->n;
    const double m0 = p->masses ? p->masses[0] : p->mass;
    pl->type = o->solver ? o->solver : gw_solver_cvode;
    pl->tau1 = gw_chain_tau1(m0, p->kwall, p->v_imp);
    pl->dt_out = o->dt_out > 0 ? o->dt_out : pl->tau1 / 200.0;
    /* The collision's expected length: n bead-to-bead transits of 2 T_c plus
     * the wall contact, each on the scale of the heaviest bead it can involve
     * (bead 1's for equal beads), plus the column's ride on a sensor body's
     * spring (chain_collision_length). Bead 1's alone made a light bead under
     * a heavy one end at the default t-max still on the wall (--radii
     * 5e-4,1e-2: t-max 0.197 ms, the collision 0.248 ms, exit 1). */
    double tc_col = 0;
    const double t_col = chain_collision_length(p, &tc_col), /* the ring, held and t-max bounds' too */
                 t_ride = chain_sensor_carry_time(p);
    pl->tc = tc_col;
    /* the bounds over a collision that is mostly the column's ride on a soft
     * sensor spring say so, and the default dt-out's refusal names the ride
     * (its other advice, a stiff wall on soft contacts, is about the wall) */
    const int rides = t_ride > 0.5 * t_col;
    const char *over = rides ? "the collision on the sensor body's spring" : "the collision";
    char why[160] = "";
    if (rides)
        gw_snprintf(why, sizeof why, " (the column rides the sensor body's spring for pi sqrt((sum m + M)/k_s) = %.3g "
                    "s: a stiffer spring shortens it)", t_ride);
    pl->t_max = o->t_max > 0 ? o->t_max : 20.0 * t_col;
    /* Every sample costs O(n) (energy, contacts): bound the samples over the
     * collision's expected length (or t_max when shorter). The
     * default dt-out gives about 100 n + 200 of them; checked before the run. */
    pl->t_expect = fmin(pl->t_max, t_col);
    int rc;
    pl->sp = o->sp;
    /* The root finders compare signs at step ends only: a step longer than half a
     * contact could step over a whole contact. Contacts last at least about the
     * binary contact time at twice v_imp, so cap the step at a quarter of it. */
    if (!(pl->sp.dt_max > 0))
        pl->sp.dt_max = 0.25 * chain_contact_tau_min(p, 2 * p->v_imp); /* the wall's too */
    pl->type = o->solver ? o->solver : gw_solver_cvode;
    /* the step resolves the stiffest contact (a small bead between large ones was
     * taken at bead 1's scale and blew up) and a sensor body's oscillation */
    if (pl->type == gw_solver_rk4 && !(pl->sp.dt > 0))
        pl->sp.dt = chain_rk4_default_dt(p, o->steps_per_tc);
    /* and at least t_expect / step steps of O(n) each: bounded before the run
     * (the RK4 step, or the largest step of cvode/arkode) */
    /* Steps and samples grow about as n, memory as n:
     * when several trip, the one that passes the fewest beads is named. */
    const double max_samples = 1e9, step = pl->type == gw_solver_rk4 ? fmin(pl->sp.dt, pl->sp.dt_max) : pl->sp.dt_max;
    gw_err e[3] = {{{0}}};
    double n_ok[3] = {INFINITY, INFINITY, INFINITY};
    if (chain_steps_check(pl->type, &pl->sp, &o->sp, pl->t_expect, over, &e[0]) != GW_OK) {
        n_ok[0] = n * 1e8 / (pl->t_expect / step);
        stiffness_refusal(p, o, pl->type, 0, over, &e[0]); /* k or kwall the cause: named, with its range */
        /* a wall too soft for its law, where no kwall alone is within the
         * bound (a dt and k wrong too): named first, the rest after it */
        if (wall_too_soft(p) && strncmp(e[0].msg, "kwall:", 6) != 0) {
            const gw_err was = e[0];
            const double m0 = p->masses ? p->masses[0] : p->mass;
            gw_err_set(&e[0], GW_EINVAL, "kwall: %g N/m^1.5 is too soft (bead 1 would overlap the wall by about %.3g "
                       "m, beyond its radius, in a contact of about %.3g s); and %s", p->kwall,
                       gw_chain_dmax1(m0, p->kwall, p->v_imp), gw_chain_tau1(m0, p->kwall, p->v_imp), was.msg);
        }
    }
    /* cvode and arkode follow a sensor body's oscillation too (8 s for 0.1 ms at
     * 1e-7 kg on 1e14 N/m, 5.8e7 steps) */
    if ((rc = chain_sensor_steps_check(p, pl->type, &pl->sp, pl->t_expect, over, err)) != GW_OK)
        return rc;
    /* and the explicit methods its ring, where it is far faster than the collision */
    if ((rc = chain_ring_explicit_check(p, pl->type, &pl->sp, pl->t_expect, over, err)) != GW_OK)
        return rc;
    /* and the explicit methods a drag's decay (chain_drag_steps_check) */
    if ((rc = chain_drag_steps_check(p, pl->type, &pl->sp, &o->sp, o->steps_per_tc, pl->t_expect, pl->t_max,
                                     over, err)) != GW_OK)
        return rc;
    if (gw_chain_memory_check(p, pl->type, pl->sp.method, &e[1]) != GW_OK)
        n_ok[1] = memory_n_ok(p, pl->type, pl->sp.method);
    if (!(pl->t_expect / pl->dt_out <= max_samples)) {
        gw_err_set(&e[2], GW_EINVAL, "dt-out: %s%g s gives about %.3g samples over %s (about %.3g s); "
                   "at most %.0e: raise dt-out%s", o->dt_out > 0 ? "" : "the default tau_1/200 = ", pl->dt_out,
                   pl->t_expect / pl->dt_out, over, pl->t_expect, max_samples,
                   o->dt_out > 0 ? ""
                   : rides       ? why
                                 : " (bead 1's wall contact is far shorter than the column's collision: unequal "
                                   "radii or masses, or a stiff wall)");
        n_ok[2] = n * max_samples / (pl->t_expect / pl->dt_out);
        /* the default dt-out is the wall's tau_1/200: kwall the cause, named
         * where its steps are refused too (a dt-out alone passes otherwise:
         * chain --n 2 --k 1e3 --kwall 1e14 is told the dt-out that passes) */
        if (!(o->dt_out > 0) && isfinite(n_ok[0]))
            stiffness_refusal(p, o, pl->type, 1, over, &e[2]);
    }
    int worst = -1;
    for (int i = 0; i < 3; i++)
        if (isfinite(n_ok[i]) && (worst < 0 || n_ok[i] < n_ok[worst]))
            worst = i;
    if (worst >= 0)
        return gw_err_set(err, GW_EINVAL, "%s", e[worst].msg);
    /* a dt_max given above the contacts: k and kwall held to their ranges at
     * the default cap (stiffness_refusal) */
    if (o->sp.dt_max > 0 && (rc = stiffness_refusal(p, o, pl->type, 0, over, err)) != GW_OK)
        return rc;
    /* cvode and arkode follow a light bead that heavy beads hold, all the time
     * they hold it (chain_ring_check) */
    if ((rc = chain_ring_check(p, pl->type, &pl->sp, pl->t_expect, t_col, over, err)) != GW_OK)
        return rc;
    /* A column's work bounded as a study's (chain_column_work_check), before
     * the stored trace's bound: with --out, chain --n 100000 was told to run
     * without storing it, a run of days */
    if ((rc = chain_column_work_check(n, pl->t_expect, t_col, over, "n", "t-max", err)) != GW_OK)
        return rc;
    /* A stored trace (gw_chain_trace_sample) keeps t, the wall force and every
     * bead's x and v at each sample and event (about 4 events per bead): bound
     * it before the run (--n 1000 --dt-out 1e-9 grew toward 400 GB; written,
     * 28 B a value, 1000 beads at the default dt-out came to 8 GB of files). */
    if (o->sample == gw_chain_trace_sample &&
        (rc = gw_chain_trace_check(n, pl->t_expect, pl->dt_out, 4.0 * n + 2, err)) != GW_OK)
        return rc;
    /* sampling far finer than the column's own scale (chain_sampling_check;
     * after the stored trace's bound, which names what --out would write) */
    if ((rc = chain_sampling_check(n, pl->t_expect, pl->dt_out, o->dt_out > 0, over, rides ? why : NULL, err)) != GW_OK)
        return rc;
    if (!whole)
        return GW_OK;
    /* A run that does not end (a column held on the wall by gravity and damping,
     * a sensor body still ringing) goes on to t_max: the bounds above hold over
     * the expected collision, an explicit --t-max far beyond it must meet them too
     * (--t-max 1e6 ran 1e11 steps, hours, with nothing said). The default t_max is
     * 20 expected lengths, so it stays within 20 times the bounds. */
    if (o->t_max > 0 && pl->t_max > pl->t_expect) {
        const double t_lim = fmin(1e8 * step, max_samples * pl->dt_out);
        if (!(pl->t_max <= t_lim))
            return gw_err_set(err, GW_EINVAL, "t-max: %g s would take about %.3g steps of %g s and %.3g samples "
                              "of %g s if the collision has not ended by then; at most 1e+08 steps and 1e+09 samples: "
                              "lower t-max to %g s or less", pl->t_max, pl->t_max / step, step,
                              pl->t_max / pl->dt_out, pl->dt_out,
                              /* one that passes the held column's bound too (chain_held_check) */
                              fmin(floor_2digits(t_lim), held_t_lim(p0, t_col, pl->tau1,
                                                                    pl->dt_out)));
        if ((rc = chain_sensor_steps_check(p, pl->type, &pl->sp, pl->t_max, "t-max", err)) != GW_OK ||
            (rc = chain_drag_steps_check(p, pl->type, &pl->sp, &o->sp, o->steps_per_tc, pl->t_max, pl->t_max,
                                         "t-max", err)) != GW_OK)
            return rc;
        if (o->sample == gw_chain_trace_sample) {
            gw_err te = {{0}};
            if (gw_chain_trace_check(n, pl->t_max, pl->dt_out, 4.0 * n + 2, &te) != GW_OK)
                return gw_err_set(err, GW_EINVAL, "t-max: %g s would store about %.3g samples of %d beads if the "
                                  "collision has not ended by then, above the 5 GB limit of the written trace: lower "
                                  "t-max or raise dt-out", pl->t_max, pl->t_max / pl->dt_out + 1, n);
        }
    }
    /* A column that gravity holds on the wall runs to t_max (chain_held_check) */
    if ((rc = chain_held_check(p0, pl->t_max, t_col, pl->tau1, pl->dt_out, err)) != GW_OK)
        return rc;
    return GW_OK;
}

int chain_collide_plan_make(const gw_chain_params *p0, const gw_chain_run_opts *o, collide_plan *pl, gw_err *err)
{
    return plan_make(p0, o, pl, 1, err);
}

/* plan_make's values for chain_held_check: bead 1's wall contact, the
 * sampling and the collision's length, at the column's speed scale */
static double held_values(const gw_chain_params *p0, const gw_chain_run_opts *o, double *tau1, double *dt_out)
{
    gw_chain_params q = *p0;
    q.v_imp = chain_speed_scale(p0);
    const double m0 = q.masses ? q.masses[0] : q.mass;
    *tau1 = gw_chain_tau1(m0, q.kwall, q.v_imp);
    *dt_out = o->dt_out > 0 ? o->dt_out : *tau1 / 200.0;
    double tc = 0;
    return chain_collision_length(&q, &tc);
}

double chain_collide_held_t(const gw_chain_params *p0, const gw_chain_run_opts *o)
{
    /* chain_held_check refuses t_max above HELD_WORK_MAX / n times the
     * sampling (exactly, not rounded) */
    double tau1, dt_out;
    const double t_col = held_values(p0, o, &tau1, &dt_out);
    if (!isfinite(held_t_lim(p0, t_col, tau1, dt_out)))
        return INFINITY;
    return HELD_WORK_MAX / p0->n * fmin(dt_out, tau1 / 200.0);
}

int chain_collide_held_refuse(const gw_chain_params *p0, const gw_chain_run_opts *o, gw_err *err)
{
    double tau1, dt_out;
    const double t_col = held_values(p0, o, &tau1, &dt_out);
    return chain_held_check(p0, o->t_max, t_col, tau1, dt_out, err);
}

int chain_collide_plan_early(const gw_chain_params *p0, const gw_chain_run_opts *o, gw_err *err)
{
    collide_plan pl;
    return plan_make(p0, o, &pl, 0, err);
}

int gw_chain_run_check(const gw_chain_params *p, const gw_chain_run_opts *o, gw_err *err)
{
    if (!p || !o)
        return gw_err_set(err, GW_EINVAL, "gw_chain_run_check: %s is NULL", !p ? "p" : "o");
    /* the column first, as gw_chain_create checks it before gw_chain_collide
     * plans: the plan's bounds read v_imp at the column's speed scale, and an
     * infinite v_imp (or mass, k, ...) passed them */
    int rc = gw_chain_params_validate(p, err);
    if (rc != GW_OK)
        return rc;
    collide_plan pl;
    return chain_collide_plan_make(p, o, &pl, err);
}

int chain_run_step(const gw_chain_params *p, const gw_chain_run_opts *o, double *dt, double *dt_max, gw_err *err)
{
    collide_plan pl;
    int rc = chain_collide_plan_make(p, o, &pl, err);
    if (rc != GW_OK)
        return rc;
    *dt = chain_plan_step(&pl);
    *dt_max = pl.sp.dt_max;
    return GW_OK;
}

int chain_run_steps(const gw_chain_params *p, const gw_chain_run_opts *o, double *steps, gw_err *err)
{
    collide_plan pl;
    int rc = chain_collide_plan_make(p, o, &pl, err);
    if (rc != GW_OK)
        return rc;
    const double step = pl.type == gw_solver_rk4 ? fmin(pl.sp.dt, pl.sp.dt_max) : pl.sp.dt_max;
    double s = pl.t_expect / step;
    /* the sensor body's oscillation as a single run counts it (2 a radian
     * before: a tenth of the 7-37 measured) */
    double omega, per_rad, zeta;
    int damped;
    if (pl.type != gw_solver_rk4) {
        /* bdf takes the collision's own steps beside the body's */
        const double b = sensor_steps(p, pl.type, &pl.sp, pl.t_expect, &omega, &per_rad, &zeta, &damped);
        const int add = b > 0 && strcmp(gw_solver_method_used(pl.type, pl.sp.method), "bdf") == 0;
        s = add ? s + b : fmax(s, b);
    }
    int k = 0;
    double rate = 0, t_used = 0;
    s = fmax(s, drag_steps(p, pl.type, &pl.sp, &o->sp, o->steps_per_tc, pl.t_expect, pl.t_max, &k, &rate, &t_used));
    *steps = s;
    return GW_OK;
}
