/*
 * gw_hermite.h: the cubic Hermite basis on one interval (private to the solver
 * layer): the state at a time between two ends whose values and slopes are
 * known, as the backends read a state between their steps (cvode's and
 * arkode's in gw_sun_advance_peek, verlet_peek_state).
 */
#ifndef GW_HERMITE_H
#define GW_HERMITE_H

/* The four weights of the cubic Hermite at th = (t - t0) / h in [0, 1] on an
 * interval of length h: y(t) = w[0] y0 + w[1] y0' + w[2] y1 + w[3] y1', where
 * y0, y0' are the value and slope at t0 and y1, y1' at t0 + h (the slopes
 * weighted with h folded in). */
static inline void gw_hermite(double th, double h, double w[4])
{
    const double u = 1 - th;
    w[0] = (1 + 2 * th) * u * u;
    w[1] = th * u * u * h;
    w[2] = th * th * (3 - 2 * th);
    w[3] = -th * th * u * h;
}

/* The rates of the four weights in time (d/dt of gw_hermite's, same order). */
static inline void gw_hermite_rate(double th, double h, double w[4])
{
    w[0] = 6 * th * (th - 1) / h;
    w[1] = (3 * th - 1) * (th - 1);
    w[2] = -w[0];
    w[3] = th * (3 * th - 2);
}

#endif
