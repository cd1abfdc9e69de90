#!/usr/bin/python3
"""peer_lsoda3.py: CPU time of SciPy solve_ivp(method='LSODA', rtol=1e-6) on the
40-bead Falcon column, run 3 times (one collision each). Peer measurement for
bench/falcon_vs_lsoda.sh; never a pass/fail test.

Model and events as bench/peer_scipy.py (docs/physics.md 1.1, eq. F.11; SI units):
N beads at v_imp hitting a rigid wall, F = k d^(3/2) per contact, wall K x_1^(3/2);
events v_1 = 0 (F_max) and x_1 = 0 falling (tau_N); integrated from 0 to t_end,
the time granwave's run stops. atol per component = rtol times the granwave scale
(d_max of one bead on the wall for x, v_imp for v).

Usage: peer_lsoda3.py --params k K m v --ref fmax tau_n t_end [--n 40] [--rtol 1e-6]
Prints one line per collision and
  LSODA3 <cpu seconds of the 3 solve_ivp calls> <F_max rel err> <tau_N rel err>
(CPU time: time.process_time around solve_ivp only, interpreter start and imports
excluded).
"""
import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_scipy  # noqa: E402  (make_rhs, run: the same model and events)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--params", nargs=4, type=float, required=True)
    ap.add_argument("--ref", nargs=3, type=float, required=True)
    ap.add_argument("--n", type=int, default=40)
    ap.add_argument("--rtol", type=float, default=1e-6)
    a = ap.parse_args()
    k, kw, m, v = a.params
    fref, tref, t_end = a.ref
    n = a.n
    dmax1 = (5 * m * v * v / (4 * kw)) ** 0.4
    scale = np.concatenate((np.full(n, dmax1), np.full(n, v)))
    total = 0.0
    for i in range(3):
        c0 = time.process_time()
        r = peer_scipy.run("LSODA", a.rtol, n, k, kw, m, v, t_end, a.rtol * scale)
        cpu = time.process_time() - c0
        if r is None:
            print("LSODA failed")
            sys.exit(1)
        _ms, fmax, tau, nfev = r
        ef, et = abs(fmax - fref) / fref, abs(tau - tref) / tref
        print(f"LSODA rtol {a.rtol:g} collision {i + 1}: {cpu * 1e3:.1f} ms CPU, nfev {nfev}, "
              f"F_max err {ef:.2e}, tau_N err {et:.2e}")
        total += cpu
    print(f"LSODA3 {total:.4f} {ef:.3g} {et:.3g}")


if __name__ == "__main__":
    main()
