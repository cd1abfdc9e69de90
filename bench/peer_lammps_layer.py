#!/usr/bin/python3
"""peer_lammps_layer.py: LAMMPS (pair_style granular, fix wall/gran) on the
Bourrier layer impact (docs/physics.md 2.1-2.3), as a peer of `granwave
layer-impact`. Measurement only, never a pass/fail test. Python writes the
LAMMPS input, runs the LAMMPS binary and reads its output; LAMMPS does all the
integration. The time reported here is LAMMPS's own "Loop time"; the bench
script (bench_layer_peer.sh) also takes the CPU time of the whole process.

Model (granwave, layer_model.c). Contact overlap u, two discs of radii R_a, R_b:
    F_n = K_n u^(3/2),  K_n = 2 sqrt(2 R_p) G / (3 (1 - nu))              (B.1, B.3)
    dF_t = K_t du_t, |F_t| <= mu F_n, mu = tan(phi),
    K_t = 2 (3 G^2 (1 - nu) R_p)^(1/3) / (2 - nu) F_n^(1/3)              (B.2, B.4)
    R_p = 2 R_a R_b / (R_a + R_b) (two discs), R_p = R_a (disc on a wall).
With F_n^(1/3) = K_n^(1/3) u^(1/2) the Mindlin stiffness is
    K_t = 2 sqrt(2) G sqrt(R_p u) / (2 - nu).
No normal or tangential damping; friction is the only loss.

LAMMPS 29 Sep 2021 (Debian `lammps`), pair_style granular, for R_eff =
R_a R_b / (R_a + R_b) (pair_granular doc page):
    hertz/material E eta_n0 nu:  F_n = (4/3) E_eff sqrt(R_eff) u^(3/2),
        E_eff = 1 / ((1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b) = E / (2 (1 - nu^2))
    tangential mindlin/force k_t x_gamma_t mu: incremental tangential force
        dF_t = -k_t a dxi, a = sqrt(R_eff u) (k_t NULL: 8 G_eff,
        G_eff = E / (4 (2 - nu)(1 + nu)) for two equal materials),
        capped at mu |F_n| (the stored force is rescaled onto the cap).
Two discs: R_p = 2 R_eff, so granwave's K_n = (4/3) G / (1 - nu) sqrt(R_eff)
and K_t = 4 G sqrt(R_eff u) / (2 - nu). They match with
    E_pair = 2 (1 + nu) G (the material's true Young modulus, 1e11 Pa),
    nu_LAMMPS = nu,  k_t,pair = 4 G / (2 - nu)
(E_eff = G / (1 - nu); k_t,pair is also what NULL gives from E_pair).
`mindlin/force` (force history, incremented) is granwave's incremental law;
`mindlin` would store a displacement and give F_t = k_t a xi, which differs
when a changes during the contact.
Walls (fix wall/gran granular, a flat wall: R_eff = R_a = R_p): measured,
not taken from the doc page. With hertz/material this LAMMPS version gives
the wall E_eff = E / (2 (1 - nu)) (not (1 - nu^2)): a disc dropped on the wall
with E = 1.1314e11 Pa had contact times matching E/(2 (1 - nu)) to 1e-4 at
nu = 0.25 and at nu = 0.4. granwave's wall K_n = (2 sqrt(2)/3) G / (1 - nu)
sqrt(R_a) then needs
    E_wall = sqrt(2) G = 5.657e10 Pa,  k_t,wall = 2 sqrt(2) G / (2 - nu),
the latter given explicitly: with NULL the wall's tangential stiffness came
out 2.09 times below granwave's (oscillation period 9.895 ms against
6.845 ms in the --verify test). --verify checks all four numbers.
Disc masses pi r^2 rho (unit thickness; `--mass-law disc`, granwave's default,
read from the sample's mass_law) with I = m r^2 / 2 (`fix nve/sphere disc`);
sphere masses 4/3 pi r^3 rho with I = 2/5 m r^2 (`fix nve/sphere`) when the
sample says `mass_law sphere`. Gravity 9.81 along -y, `fix enforce2d`, walls
at x = 0, x = W and y = 0, neighbour skin 0.1 m (granwave's contact-list skin)
checked every step, velocity Verlet at dt = 1e-5 s.
Small differences that remain: LAMMPS's torque arm is R - u/2 (granwave's
disc layer uses R; u/R ~ 1e-4), and LAMMPS keeps the tangential history as a
vector rotated into the current tangent plane where granwave stores a scalar
in the contact frame (identical in 2D up to O(dt)).

Impact set-up (layer_impact.c): block radius R_b = rb_rm R_m centred at
x_c = W/2 + x, lowered until it is `gap` (1e-6 m) above the first particle
under it, velocity V_i (sin alpha, -cos alpha), no spin. Outcome as granwave
computes it, from samples every dt_out = 2e-5 s: bounced when v_y > 0 while the
block has no contact (LAMMPS compute contact/atom: disc contacts only; the block
never reaches a wall here), e_n = largest upward v_y / (V_i cos alpha),
penetration = y_0 - min y; the outcome stops at the first sample after the
largest upward velocity with the block free (granwave's stopping rule); --full
runs on to --t-end for the penetration and adds e_n_run_max, the run's largest
upward v_y over V_i cos alpha (later hops included). The LAMMPS run itself lasts --t-end (take granwave's JSON
t_end so that both simulate the same span).

Modes:
  --verify : binary head-on disc collision (no gravity) against the closed
             form tau = c (m*/K_n)^(2/5) v^(-1/5), c = (4/5) B(2/5, 1/2) (5/4)^(2/5)
             = 3.21807, restitution 1, at dt 1e-5 and 1e-6; the same for a disc
             on the bottom wall (m* = m, K_n with R_p = R); tangential
             oscillation of a disc resting (gravity) on the bottom wall and on
             a fixed disc: period 2 pi sqrt(m/(3 K_t)) with K_t at the static
             overlap (a disc, I = m R^2/2: the contact point's effective mass
             is m/3).
  --sample FILE [--rb-rm R --vi V --alpha A --x X --gap G --t-end T --full]:
             the impact; prints "PEER ..." and "OUTCOME {json}" lines.
Usage: peer_lammps_layer.py [--lmp BIN] (--verify | --sample FILE ...)
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

G_DEF, NU_DEF, PHI_DEF, RHO_DEF, GRAV_DEF, SKIN_DEF = 40e9, 0.25, 30.0, 2650.0, 9.81, 0.1
HERTZ_C = 0.8 * math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9) * 1.25 ** 0.4


class Material:
    def __init__(self, g=G_DEF, nu=NU_DEF, phi=PHI_DEF, rho=RHO_DEF, mass_law="disc"):
        self.g, self.nu, self.mu, self.rho, self.mass_law = g, nu, math.tan(math.radians(phi)), rho, mass_law
        self.e_pair = 2 * (1 + nu) * g
        self.e_wall = math.sqrt(2) * g
        self.kt_pair = 4 * g / (2 - nu)
        self.kt_wall = 2 * math.sqrt(2) * g / (2 - nu)

    def kn(self, rp):  # granwave B.3
        return 2 * math.sqrt(2 * rp) * self.g / (3 * (1 - self.nu))

    def kt(self, rp, fn):  # granwave B.4
        return 2 * (3 * self.g ** 2 * (1 - self.nu) * rp) ** (1 / 3) / (2 - self.nu) * fn ** (1 / 3)

    def mass(self, r):
        if self.mass_law == "sphere":
            return 4 / 3 * math.pi * r ** 3 * self.rho
        return math.pi * r * r * self.rho

    def coeffs(self, e, kt):
        return (f"hertz/material {e:.17g} 0.0 {self.nu:.17g} "
                f"tangential mindlin/force {kt:.17g} 0.0 {self.mu:.17g}")

    def nve(self):
        return "fix int mobile nve/sphere" + (" disc" if self.mass_law == "disc" else "")


def header(mat, xlo, xhi, ylo, yhi, xwalls, ywall):
    """Box and interactions: returns (lines before the atoms, lines after).
    xwalls = (lo, hi) or None; ywall: a wall at y = 0."""
    lines = [
        "units si",
        "dimension 2",
        "atom_style sphere",
        "atom_modify map array",
        "boundary f fm p",
        "newton off",
        "comm_modify vel yes",
        f"region box block {xlo:.17g} {xhi:.17g} {ylo:.17g} {yhi:.17g} -0.5 0.5",
        "create_box 1 box",
    ]
    inter = ["pair_style granular", f"pair_coeff * * {mat.coeffs(mat.e_pair, mat.kt_pair)}"]
    if xwalls:
        inter.append(f"fix wx all wall/gran granular {mat.coeffs(mat.e_wall, mat.kt_wall)} "
                     f"xplane {xwalls[0]:.17g} {xwalls[1]:.17g}")
    if ywall:
        inter.append(f"fix wy all wall/gran granular {mat.coeffs(mat.e_wall, mat.kt_wall)} yplane 0.0 NULL")
    return lines, inter


def atoms_lines(mat, atoms):
    """atoms: list of (x, y, r, vx, vy); per-atom diameter and mass (granwave's)."""
    out = []
    for i, (x, y, r, vx, vy) in enumerate(atoms, 1):
        out += [f"create_atoms 1 single {x:.17g} {y:.17g} 0.0 units box",
                f"set atom {i} diameter {2 * r:.17g}",
                f"set atom {i} mass {mat.mass(r):.17g}"]
        if vx or vy:
            out += [f"group v{i} id {i}", f"velocity v{i} set {vx:.17g} {vy:.17g} 0.0"]
    return out


def run_lammps(lmp, text, work, name="in.layer"):
    path = os.path.join(work, name)
    with open(path, "w") as f:
        f.write(text)
    spath = os.path.join(work, "screen.txt")
    p = subprocess.run([lmp, "-in", path, "-log", "none", "-nocite", "-screen", spath],
                       cwd=work, capture_output=True, text=True)
    screen = open(spath).read() if os.path.exists(spath) else ""
    if p.returncode != 0 or "ERROR" in screen:
        sys.exit("peer_lammps_layer: lammps failed:\n" + screen[-3000:] + p.stdout[-1000:] + p.stderr[-1000:])
    m = re.search(r"Loop time of ([0-9.eE+-]+)", screen)
    return float(m.group(1)) if m else float("nan"), screen


def read_trace(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("T "):
                rows.append([float(v) for v in line.split()[1:]])
    return rows


def crossings(ts, fs, ds, rising):
    """Zero crossings of f (derivative d) located by cubic Hermite + bisection."""
    out = []
    for i in range(len(ts) - 1):
        t0, t1, p0, p1 = ts[i], ts[i + 1], fs[i], fs[i + 1]
        if (rising and p0 <= 0 < p1) or (not rising and p0 > 0 >= p1):
            h = t1 - t0
            a = 2 * p0 - 2 * p1 + h * ds[i] + h * ds[i + 1]
            b = -3 * p0 + 3 * p1 - 2 * h * ds[i] - h * ds[i + 1]
            c = h * ds[i]
            lo, hi = 0.0, 1.0
            for _ in range(80):
                mid = 0.5 * (lo + hi)
                val = ((a * mid + b) * mid + c) * mid + p0
                if (val > 0) == (p0 > 0):
                    lo = mid
                else:
                    hi = mid
            out.append(t0 + 0.5 * (lo + hi) * h)
    return out


def verify_collision(lmp, mat, work, wall, dt, ra=0.325, rb=0.25, v=20.0):
    """Head-on collision, no gravity: two discs along x (or disc a on the
    bottom wall). Returns (tau, tau_closed, e)."""
    if wall:
        atoms = [(1.0, ra + 0.5 * v * dt, ra, 0.0, -v)]
        rp, mstar = ra, mat.mass(ra)
    else:
        atoms = [(1.0, 1.0, ra, v / 2, 0.0), (1.0 + ra + rb + 0.5 * v * dt, 1.0, rb, -v / 2, 0.0)]
        rp = 2 * ra * rb / (ra + rb)
        ma, mb = mat.mass(ra), mat.mass(rb)
        mstar = ma * mb / (ma + mb)
    kn = mat.kn(rp)
    tau_c = HERTZ_C * (mstar / kn) ** 0.4 * v ** -0.2
    steps = int(math.ceil(1.4 * tau_c / dt))
    hd, inter = header(mat, 0.0, 2.5, -0.01, 2.5, None, wall)
    lines = hd + atoms_lines(mat, atoms) + ["group mobile type 1"] + inter
    lines += ["neighbor 0.1 bin", "neigh_modify every 1 delay 0 check yes", mat.nve(), "fix e2 all enforce2d",
              f"timestep {dt:.17g}", f"thermo {steps}"]
    trace = os.path.join(work, "trace.txt")
    if wall:
        lines.append(f'fix tr all print 1 "T $(time:%.17g) $(y[1]:%.17g) $(vy[1]:%.17g)" screen no file {trace}')
    else:
        lines.append(f'fix tr all print 1 "T $(time:%.17g) $(x[1]:%.17g) $(x[2]:%.17g) $(vx[1]:%.17g) '
                     f'$(vx[2]:%.17g)" screen no file {trace}')
    lines.append(f"run {steps}")
    run_lammps(lmp, "\n".join(lines) + "\n", work)
    rows = read_trace(trace)
    ts = [r[0] for r in rows]
    if wall:
        un = [ra - r[1] for r in rows]
        ud = [-r[2] for r in rows]
        e = rows[-1][2] / v
    else:
        un = [ra + rb - (r[2] - r[1]) for r in rows]
        ud = [-(r[4] - r[3]) for r in rows]
        e = (rows[-1][4] - rows[-1][3]) / v
    up, down = crossings(ts, un, ud, True), crossings(ts, un, ud, False)
    t_in = up[0] if up else 0.0
    t_out = [t for t in down if t > t_in]
    tau = t_out[0] - t_in if t_out else float("nan")
    return tau, tau_c, e


def verify_tangential(lmp, mat, work, wall, dt=1e-6, ra=0.325, rb=0.4, v0=1e-3, g=GRAV_DEF):
    """A disc resting under gravity on the bottom wall (or on a fixed disc of
    radius rb), started at its static overlap with a small sideways velocity:
    the contact sticks and the disc oscillates at omega = sqrt(3 K_t / m)."""
    m = mat.mass(ra)
    fn = m * g
    rp = ra if wall else 2 * ra * rb / (ra + rb)
    u0 = (fn / mat.kn(rp)) ** (2 / 3)
    kt = mat.kt(rp, fn)
    period = 2 * math.pi * math.sqrt(m / (3 * kt))
    steps = int(math.ceil(5.2 * period / dt))
    if wall:
        atoms = [(1.0, ra - u0, ra, v0, 0.0)]
    else:
        atoms = [(1.0, rb, rb, 0.0, 0.0), (1.0, 2 * rb + ra - u0, ra, v0, 0.0)]
    hd, inter = header(mat, 0.0, 2.5, -0.01, 2.5, None, True)
    lines = hd + atoms_lines(mat, atoms) + inter
    lines.append(f"group mobile id {len(atoms)}")
    lines += ["neighbor 0.1 bin", "neigh_modify every 1 delay 0 check yes", mat.nve(), "fix e2 all enforce2d",
              f"fix grav mobile gravity {g:.17g} vector 0 -1 0", f"timestep {dt:.17g}", f"thermo {steps}"]
    i = len(atoms)
    trace = os.path.join(work, "trace.txt")
    lines.append(f'fix tr all print 1 "T $(time:%.17g) $(vx[{i}]:%.17g) $(fx[{i}]:%.17g)" screen no file {trace}')
    lines.append(f"run {steps}")
    run_lammps(lmp, "\n".join(lines) + "\n", work)
    rows = read_trace(trace)
    # the rolling mode has zero frequency: the oscillation is in the force
    z = []
    for i in range(1, len(rows) - 1):
        t0, t1, f0, f1 = rows[i][0], rows[i + 1][0], rows[i][2], rows[i + 1][2]
        if (f0 < 0 <= f1) or (f0 > 0 >= f1):
            z.append(t0 + (t1 - t0) * f0 / (f0 - f1))
    meas = 2 * (z[-1] - z[0]) / (len(z) - 1) if len(z) >= 3 else float("nan")
    fmax = max(abs(r[2]) for r in rows)
    return meas, period, fmax / (mat.mu * fn)


def verify(lmp, work):
    mat = Material()
    print("LAMMPS mapping: E_pair = 2 (1 + nu) G = %.6g Pa (the true E), E_wall = sqrt(2) G = %.6g Pa, nu = %g, "
          "mu = tan(30 deg) = %.6f" % (mat.e_pair, mat.e_wall, mat.nu, mat.mu))
    print("Hertz contact-time constant c = (4/5) B(2/5, 1/2) (5/4)^(2/5) = %.6f" % HERTZ_C)
    print("%-34s %8s %14s %14s %10s %12s" % ("normal, 20 m/s", "dt", "tau lammps", "tau closed", "rel err", "1 - e"))
    res = {}
    for wall, name in ((False, "disc-disc R 0.325 + 0.25 m"), (True, "disc on bottom wall R 0.325 m")):
        for dt in (1e-5, 1e-6):
            tau, tc, e = verify_collision(lmp, mat, work, wall, dt)
            res[(wall, dt)] = (tau - tc) / tc
            print("%-34s %8.0e %14.9g %14.9g %10.2e %12.2e" % (name, dt, tau, tc, (tau - tc) / tc, 1 - e))
    print("%-34s %8s %14s %14s %10s %12s" % ("tangential, at rest (gravity)", "dt", "T lammps", "2pi sqrt(m/3K_t)",
                                            "rel err", "F_t/cap"))
    for wall, name in ((True, "disc R 0.325 on bottom wall"), (False, "disc R 0.325 on fixed R 0.4")):
        meas, per, ratio = verify_tangential(lmp, mat, work, wall)
        res[("t", wall)] = (meas - per) / per
        print("%-34s %8.0e %14.9g %14.9g %10.2e %12.3f" % (name, 1e-6, meas, per, (meas - per) / per, ratio))
    worst = max(abs(v) for v in res.values())
    print("VERIFY lammps-layer largest relative error %.3g (normal at dt 1e-5: pair %.2e, wall %.2e)" % (
        worst, res[(False, 1e-5)], res[(True, 1e-5)]))


def read_sample(path):
    hdr, xs = {}, []
    with open(path) as f:
        first = f.readline().split()
        if first[:2] != ["granwave-layer-sample", "1"]:
            sys.exit("peer_lammps_layer: %s: not a version 1 text sample (clump samples are not supported)" % path)
        n = None
        for line in f:
            s = line.strip()
            if not s or s.startswith("#"):
                continue
            if n is None:
                k, v = s.split(None, 1)
                hdr[k] = v
                if k == "n":
                    n = int(v)
                continue
            if len(xs) == n:  # the contacts' springs follow (a LAMMPS data file carries none:
                break          # granwave's side runs with --zero-springs, like with like)
            x, y, r = (float(t) for t in s.split()[:3])
            xs.append((x, y, r))
    if n is None or len(xs) != n:
        sys.exit("peer_lammps_layer: %s: expected %s particles, read %d" % (path, n, len(xs)))
    return hdr, xs


def impact(a, work):
    hdr, parts = read_sample(a.sample)
    mass_law = hdr.get("mass_law", "disc")
    mat = Material(mass_law=mass_law)
    width, rm = float(hdr["width"]), float(hdr["rm"])
    rb, xc = a.rb_rm * rm, 0.5 * width + a.x
    top, yb = 0.0, -math.inf
    for x, y, r in parts:
        top = max(top, y + r)
        dx, reach = x - xc, rb + r
        if abs(dx) < reach:
            yy = y + math.sqrt(reach * reach - dx * dx)
            if yy > yb:
                yb = yy
    if yb == -math.inf:
        sys.exit("peer_lammps_layer: no particle under the block")
    yb += a.gap
    al = math.radians(a.alpha)
    vx, vy = a.vi * math.sin(al), -a.vi * math.cos(al)
    atoms = [(x, y, r, 0.0, 0.0) for x, y, r in parts] + [(xc, yb, rb, vx, vy)]
    nb = len(atoms)
    steps = int(round(a.t_end / a.dt))
    every = max(1, int(round(a.dt_out / a.dt)))
    hd, inter = header(mat, 0.0, width, -0.01 * rm, yb + rb + 2 * rm, (0.0, width), True)
    lines = ["# granwave layer impact, written by bench/peer_lammps_layer.py",
             f"# sample {a.sample}: n {len(parts)}, width {width}, rm {rm}, mass_law {mass_law}",
             f"# block R_b = {a.rb_rm} R_m at x = {a.x} m, V_i = {a.vi} m/s, alpha = {a.alpha} deg, gap {a.gap} m"]
    lines += hd + atoms_lines(mat, atoms) + ["group mobile type 1"] + inter
    lines += [f"neighbor {SKIN_DEF:.17g} bin", "neigh_modify every 1 delay 0 check yes",
              mat.nve(), "fix e2 all enforce2d", f"fix grav all gravity {GRAV_DEF:.17g} vector 0 -1 0",
              "compute cc all contact/atom", f"timestep {a.dt:.17g}",
              "thermo_style custom step time", f"thermo {steps}", "thermo_modify lost error"]
    trace = os.path.join(work, "impact_trace.txt")
    lines.append(f'fix tr all print {every} "T $(time:%.12g) $(x[{nb}]:%.15g) $(y[{nb}]:%.15g) $(vx[{nb}]:%.12g) '
                 f'$(vy[{nb}]:%.12g) $(c_cc[{nb}]:%.0f)" screen no file {trace}')
    lines.append(f"run {steps}")
    extra = 0 if a.full else int(round(a.t_settle / a.dt))
    if extra > 0:
        # settle the outcome past t_end with granwave's stopping rule: the
        # block free of contacts and moving up
        lines += [f"variable up equal (c_cc[{nb}]==0)*(vy[{nb}]>0)",
                  f"fix halt all halt {every} v_up > 0.5 error continue",
                  f"run {extra}"]
    text = "\n".join(lines) + "\n"
    if a.keep_input:
        with open(a.keep_input, "w") as f:
            f.write(text)
    loop, screen = run_lammps(a.lmp, text, work)
    loops = [float(v) for v in re.findall(r"Loop time of ([0-9.eE+-]+)", screen)]
    ran = [int(v) for v in re.findall(r"Loop time of [0-9.eE+-]+ on \d+ procs for (\d+) steps", screen)]
    rows = read_trace(trace)
    v_ni = a.vi * math.cos(al)
    # The outcome by granwave's rule with or without --full (granwave's --full runs on
    # for the crowns but keeps the outcome it decided): the largest upward v_y up to the
    # first sample after it with the block free. With --full the run's largest upward v_y
    # (later hops, kicks from ejected grains, in contact or not) is reported beside it.
    ymin, vmax_up, t_reb, bounced, t_stop = yb, 0.0, float("nan"), False, rows[-1][0] if rows else 0.0
    decided, vmax_run = False, 0.0
    for t, x, y, bvx, bvy, cc in rows[1:]:
        ymin = min(ymin, y)
        vmax_run = max(vmax_run, bvy)
        if bvy > 0 and not decided:
            free = cc == 0
            bounced |= free
            if bvy > vmax_up:
                vmax_up, t_reb = bvy, t
            elif free:
                t_stop, decided = t, True
                if not a.full:
                    break
    out = {"peer": "lammps", "bounced": bool(bounced), "e_n": vmax_up / v_ni, "t_rebound": t_reb,
           "penetration": yb - ymin, "t_end_run": rows[-1][0] if rows else 0.0, "t_outcome_end": t_stop,
           "steps": steps, "steps_settle": sum(ran[1:]), "discs": nb, "loop_time_s": loops[0] if loops else loop,
           "loop_time_settle_s": sum(loops[1:]), "dt": a.dt, "mass_law": mass_law,
           "e_pair": mat.e_pair, "e_wall": mat.e_wall}
    if a.full:
        out["e_n_run_max"] = vmax_run / v_ni
    if a.series:
        with open(a.series, "w") as f:
            f.write("t,x,y,vx,vy,contacts\n")
            for r in rows:
                f.write(",".join("%.9g" % v for v in r) + "\n")
    print("PEER lammps-layer rb_rm %g vi %g steps %d (+%d to settle the outcome) discs %d loop_s %.4g (+%.4g)" % (
        a.rb_rm, a.vi, steps, out["steps_settle"], nb, out["loop_time_s"], out["loop_time_settle_s"]))
    print("OUTCOME " + json.dumps(out))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lmp", default=shutil.which("lmp") or "lmp")
    ap.add_argument("--verify", action="store_true")
    ap.add_argument("--sample")
    ap.add_argument("--rb-rm", type=float, default=1.0)
    ap.add_argument("--vi", type=float, default=20.0)
    ap.add_argument("--alpha", type=float, default=0.0)
    ap.add_argument("--x", type=float, default=0.0)
    ap.add_argument("--gap", type=float, default=1e-6)
    ap.add_argument("--t-end", type=float, default=0.0106)
    ap.add_argument("--dt", type=float, default=1e-5)
    ap.add_argument("--dt-out", type=float, default=2e-5)
    ap.add_argument("--full", action="store_true", help="outcome over the whole run (granwave --full)")
    ap.add_argument("--t-settle", type=float, default=2e-3,
                    help="without --full: after --t-end, run at most this long more, until the block is free and "
                         "moving up (granwave's stopping rule), to settle bounced/e_n (s)")
    ap.add_argument("--series", help="write the block's trace (t, x, y, vx, vy, contacts) as CSV")
    ap.add_argument("--keep-input", help="also write the LAMMPS input to this file")
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="gw_lammps_layer_")
    try:
        if a.verify:
            verify(a.lmp, work)
        elif a.sample:
            impact(a, work)
        else:
            ap.error("--verify or --sample FILE needed")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
