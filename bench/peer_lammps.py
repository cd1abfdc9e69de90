#!/usr/bin/python3
"""peer_lammps.py: LAMMPS (pair_style granular, fix wall/gran) on the Falcon
column, as a peer of granwave. Never a pass/fail test. Python only writes the
LAMMPS input, runs the LAMMPS binary and reads its output; the time reported is
LAMMPS's own "Loop time" of the integration run.

Force law. LAMMPS's granular `hertz` normal model is
    F = k_N R_eff^(1/2) delta^(3/2),  R_eff = R_i R_j / (R_i + R_j)
(pair_granular doc; fix wall/gran uses R_eff = R_i for a flat wall). With
damping coefficient eta_n0 = 0 (no normal damping, whatever the damping model)
and `tangential linear_nohistory 0 0` (no tangential force; the motion is along
the line of centres anyway) the force is exactly the Hertz law of docs/physics.md
1.1 when
    bead-bead: k_N = k / sqrt(R/2)      wall: k_N = K / sqrt(R)
The wall is `fix wall/gran granular hertz ... zplane 0 NULL`, a true rigid
Hertz plane (no frozen particle needed). Beads sit on the z axis, bead 1
touching the wall: z_i = R + 2R (i - 1), all moving at -v_imp; per-atom mass
set to granwave's m. Integrator: fix nve/sphere (velocity Verlet), fixed step.

Observables from a run that prints z_1, vz_1 every step (overlap with the wall
delta = R - z_1): tau = last falling zero of delta, F_max = K delta_max^(3/2)
over the maxima of delta, both located by cubic Hermite interpolation between
steps. The timed run is the same run without per-step output.

Modes:
  --verify: one bead on the wall; contact time against the closed form
            tau_1 = (4/5) B(2/5, 1/2) (5m/(4K))^(2/5) v^(-1/5) (F.2) and
            F_max(1) = K d_max^(3/2) (F.13), for a sequence of steps.
  default : N beads (40); dt = tc/M scanned until F_max and tau_N are within
            acc of the reference; prints
            PEER lammps <setting> <ms> <F_max rel err> <tau_N rel err>
Usage: peer_lammps.py --lmp BIN --params k K m v R [--verify]
                      [--ref fmax tau_n t_end] [--n 40] [--acc 1e-6] [--reps 3]
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile


def lammps_input(n, k, kw, m, v, r, dt, steps, trace):
    knp = k / math.sqrt(r / 2)
    knw = kw / math.sqrt(r)
    ztop = 2 * r * n + 0.01
    lines = [
        "units si",
        "atom_style sphere",
        "atom_modify map array",
        "boundary f f f",
        "newton off",
        "comm_modify vel yes",
        f"region box block -0.01 0.01 -0.01 0.01 -0.001 {ztop:.17g}",
        "create_box 1 box",
    ]
    for i in range(n):
        lines.append(f"create_atoms 1 single 0 0 {r + 2 * r * i:.17g} units box")
    lines += [
        f"set type 1 diameter {2 * r:.17g}",
        f"set type 1 mass {m:.17g}",
        f"velocity all set 0 0 {-v:.17g}",
        "pair_style granular",
        f"pair_coeff * * hertz {knp:.17g} 0.0 tangential linear_nohistory 0.0 0.0",
        "neighbor 0.001 bin",
        "neigh_modify every 1 delay 0 check yes",
        f"fix wall all wall/gran granular hertz {knw:.17g} 0.0 tangential linear_nohistory 0.0 0.0 zplane 0.0 NULL",
        "fix int all nve/sphere",
        f"timestep {dt:.17g}",
        "thermo_style custom step time",
        f"thermo {steps}",
        "variable z1 equal z[1]",
        "variable v1 equal vz[1]",
        "variable mm equal mass[1]",
        'print "MASS ${mm}"',
    ]
    if trace:
        lines.append(f'fix tr all print 1 "T $(time:%.17g) $(v_z1:%.17g) $(v_v1:%.17g)" screen no file {trace}')
    lines.append(f"run {steps}")
    return "\n".join(lines) + "\n"


def run_lammps(lmp, inp, workdir):
    path = os.path.join(workdir, "in.chain")
    with open(path, "w") as f:
        f.write(inp)
    p = subprocess.run([lmp, "-in", path, "-log", "none", "-nocite"], cwd=workdir,
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("peer_lammps: lammps failed:\n" + p.stdout[-2000:] + p.stderr[-2000:])
    mt = re.search(r"Loop time of ([0-9.eE+-]+)", p.stdout)
    mm = re.search(r"MASS ([0-9.eE+-]+)", p.stdout)
    return float(mt.group(1)) * 1e3, float(mm.group(1)) if mm else float("nan")


def hermite(t0, t1, p0, p1, d0, d1):
    """Cubic Hermite on [t0, t1]: returns p(s), p'(s) as functions of s in [0, 1]."""
    h = t1 - t0
    a = 2 * p0 - 2 * p1 + h * d0 + h * d1
    b = -3 * p0 + 3 * p1 - 2 * h * d0 - h * d1
    c = h * d0
    return (lambda s: ((a * s + b) * s + c) * s + p0), (lambda s: (3 * a * s + 2 * b) * s + c), a, b, c


def analyse(trace, r, kw):
    """tau (last falling zero of delta = r - z1) and F_max from the per-step trace."""
    ts, ds, vs = [], [], []
    with open(trace) as f:
        for line in f:
            if line.startswith("T "):
                _, t, z, vz = line.split()
                ts.append(float(t))
                ds.append(r - float(z))
                vs.append(-float(vz))
    tau, dmax = float("nan"), 0.0
    for i in range(len(ts) - 1):
        t0, t1, p0, p1, d0, d1 = ts[i], ts[i + 1], ds[i], ds[i + 1], vs[i], vs[i + 1]
        if p0 > 0 and p1 <= 0:  # wall contact opens: bisection on the cubic
            p, _, _, _, _ = hermite(t0, t1, p0, p1, d0, d1)
            lo, hi = 0.0, 1.0
            for _ in range(100):
                mid = 0.5 * (lo + hi)
                if p(mid) > 0:
                    lo = mid
                else:
                    hi = mid
            tau = t0 + 0.5 * (lo + hi) * (t1 - t0)
        if d0 > 0 and d1 <= 0 and max(p0, p1) > 0:  # maximum of delta
            p, dp, a, b, c = hermite(t0, t1, p0, p1, d0, d1)
            lo, hi = 0.0, 1.0
            for _ in range(100):
                mid = 0.5 * (lo + hi)
                if dp(mid) > 0:
                    lo = mid
                else:
                    hi = mid
            dmax = max(dmax, p(0.5 * (lo + hi)))
    return tau, kw * dmax ** 1.5


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lmp", default="lmp")
    ap.add_argument("--params", nargs=5, type=float, required=True)
    ap.add_argument("--ref", nargs=3, type=float)
    ap.add_argument("--verify", action="store_true")
    ap.add_argument("--n", type=int, default=40)
    ap.add_argument("--acc", type=float, default=1e-6)
    ap.add_argument("--reps", type=int, default=3)
    a = ap.parse_args()
    k, kw, m, v, r = a.params
    tc = (m / k) ** 0.4 * v ** -0.2
    work = tempfile.mkdtemp(prefix="gw_lammps_")
    trace = os.path.join(work, "trace.txt")
    if a.verify:
        cst = 0.8 * math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9)
        tau1 = cst * (5 * m / (4 * kw)) ** 0.4 * v ** -0.2
        dmax = (5 * m * v * v / (4 * kw)) ** 0.4
        f1 = kw * dmax ** 1.5
        print(f"one bead on the wall: closed form tau_1 = {tau1:.9g} s (constant {cst:.7f}), "
              f"F_max = {f1:.9g} N")
        print(f"{'dt':>12} {'tau_1 lammps':>16} {'rel err':>9} {'F_max lammps':>16} {'rel err':>9} {'mass':>12}")
        worst = None
        for div in (100, 1000, 10000):
            dt = tau1 / div
            steps = int(math.ceil(1.3 * tau1 / dt))
            _, mass = run_lammps(a.lmp, lammps_input(1, k, kw, m, v, r, dt, steps, trace), work)
            tau, fmax = analyse(trace, r, kw)
            et, ef = abs(tau - tau1) / tau1, abs(fmax - f1) / f1
            print(f"{'tau_1/%d' % div:>12} {tau:16.10g} {et:9.1e} {fmax:16.10g} {ef:9.1e} {mass:12.6g}")
            worst = (et, ef)
        ok = worst[0] <= 1e-3 and worst[1] <= 1e-3
        print(f"VERIFY lammps {'pass' if ok else 'FAIL'} tau_err {worst[0]:.3g} fmax_err {worst[1]:.3g}")
        return
    if not a.ref:
        sys.exit("peer_lammps: --ref fmax tau_n t_end needed")
    fref, tref, t_end = a.ref
    n = a.n
    print(f"lammps, {n} beads, run to t_end {t_end:.6g} s, accuracy {a.acc:g}, best of {a.reps}")
    print(f"{'setting':>12} {'steps':>9} {'ms (loop)':>10} {'F_max err':>10} {'tau_N err':>10}")
    found = False
    for j in range(0, 16):
        div = 100 * 2 ** j
        dt = tc / div
        steps = int(math.ceil(t_end / dt))
        _, _ = run_lammps(a.lmp, lammps_input(n, k, kw, m, v, r, dt, steps, trace), work)
        tau, fmax = analyse(trace, r, kw)
        ef, et = abs(fmax - fref) / fref, abs(tau - tref) / tref
        ok = ef <= a.acc and et <= a.acc
        ms = float("nan")
        if ok:
            ms = min(run_lammps(a.lmp, lammps_input(n, k, kw, m, v, r, dt, steps, None), work)[0]
                     for _ in range(a.reps))
        print(f"{'tc/%d' % div:>12} {steps:9d} {ms:10.1f} {ef:10.1e} {et:10.1e}"
              + ("  <- first pass" if ok else ""))
        sys.stdout.flush()
        if ok:
            print(f"PEER lammps dt=tc/{div} {ms:.6g} {ef:.3g} {et:.3g}")
            found = True
            break
        if steps > 2e7:
            break
    if not found:
        print("PEER lammps none nan nan nan")


if __name__ == "__main__":
    main()
