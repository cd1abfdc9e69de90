"""The column's studies against an independent integrator (issue #18, seventeenth pass).

The reference below is written from docs/physics.md 1.1-1.5 and docs/drop.md only:
point masses, Hertz contacts (Kuwabara-Kono gamma d^(1/2) d' with gamma_w = gamma K/k
and bead-bead gamma scaled by k_i/k_1, or Hunt-Crossley (1 + (3/2) alpha d')), forces
clamped at 0, gravity toward the wall. SciPy's DOP853 at rtol 1e-12 is stopped at every
contact opening and closing (a terminal event) and restarted there; wall-force maxima
are events of the sign of dF/dt. The program's --json (CVODE BDF at 1e-12) must agree
with it: F_max, tau_max, tau_N, period, final velocities, eps_eff, eps_col, E_rel/E_K
and detachment times to 1e-7, counts (maxima, N_s, cluster, wall contacts, peaks,
impacts) exactly, the calibrated damping constant to 1e-6 relative, softwall's F_max(N)
and tau_max(N) to 1e-7, the drop's peaks and impacts to 1e-7. Measured agreement when
written: 1e-10 to 1e-8 (docs/reliability.md, pass 17). About 6 s.
"""
import math

import numpy as np
import pytest

from conftest import run_cli

integrate = pytest.importorskip("scipy.integrate")
optimize = pytest.importorskip("scipy.optimize")
special = pytest.importorskip("scipy.special")

C_TAU = 0.8 * special.gamma(0.4) * special.gamma(0.5) / special.gamma(0.9)
STEEL = (21.6e10, 0.276, 7850.0)  # E, nu, rho (physics.md 1.2)
TOL = 1e-7


def hertz_k(r1, r2):
    """(4/3) E* sqrt(R_eff) of steel on steel, r2 = 0 a flat (physics.md 1.2)."""
    e, nu, _ = STEEL
    inv_r = 1.0 / r1 + (1.0 / r2 if r2 else 0.0)
    return 4.0 / 3.0 * e / (2 * (1 - nu * nu)) * math.sqrt(1.0 / inv_r)


class Column:
    def __init__(self, m, kc, kw, damping="none", c=0.0, g=0.0):
        self.m = np.asarray(m, float)
        self.n = len(self.m)
        self.k = np.concatenate(([kw], np.asarray(kc, float)))
        self.kw, self.damping, self.c, self.g = kw, damping, c, g
        k1 = kc[0] if self.n > 1 else None
        self.gam = c * self.k / (k1 if k1 else 1.0)

    def set_k1(self, k1):  # one bead: gamma_w = gamma K / k of the beads
        self.gam = self.c * self.k / k1

    def gaps(self, y):
        x = y[:self.n]
        return np.concatenate(([x[0]], np.diff(x)))

    def forces(self, y):
        v = y[self.n:]
        d = np.maximum(self.gaps(y), 0.0)
        dd = np.concatenate(([v[0]], np.diff(v)))
        s = np.sqrt(d)
        f = self.k * d * s
        if self.damping == "kk":
            f = f + self.gam * s * dd
        elif self.damping == "hc":
            f = f * (1 + 1.5 * self.c * dd)
        return np.maximum(f, 0.0)

    def rhs(self, t, y):
        f = self.forces(y)
        a = -f
        a[:-1] += f[1:]
        return np.concatenate((y[self.n:], a / self.m + self.g))

    def wall_rate(self, t, y):
        x, v = y[0], y[self.n]
        if x <= 0 or self.damping == "none":
            return v
        a = self.rhs(t, y)[self.n]
        sx = math.sqrt(x)
        if self.damping == "kk":
            gw = self.gam[0]
            return 1.5 * self.kw * sx * v + gw * (0.5 * v * v / sx + sx * a)
        return 1.5 * self.kw * sx * v * (1 + 1.5 * self.c * v) + 1.5 * self.c * self.kw * x * sx * a


def follow(col, y, t_max, stop_when_apart, threshold=0.0):
    """Integrate from state y at t = 0 to t_max (or until every contact is open and
    every pair separating, bead 1 leaving). Returns the record of contacts and maxima."""
    n = col.n
    d0 = (5 * col.m[0] * y[n] ** 2 / (4 * col.kw)) ** 0.4
    atol = np.concatenate((np.full(n, 1e-14 * d0), np.full(n, 1e-14 * abs(y[n]))))
    eps = 1e-12 * d0  # hysteresis, so that a restart does not re-find its own root
    closed = col.gaps(y) >= 0
    last_open = np.full(n, -np.inf)
    rec = dict(maxima=[], wall_closings=1, tau_n=None, episodes=[[0.0, y[n], None, None]])
    t = 0.0
    while t < t_max:
        evs = []
        for j in range(n):
            h = -eps if closed[j] else eps
            ev = (lambda tt, yy, j=j, h=h: col.gaps(yy)[j] - h)
            ev.terminal, ev.direction = True, (-1 if closed[j] else 1)
            evs.append(ev)
        evm = (lambda tt, yy: col.wall_rate(tt, yy))
        evm.terminal, evm.direction = False, -1
        evs.append(evm)
        sol = integrate.solve_ivp(col.rhs, (t, t_max), y, method="DOP853", rtol=1e-12, atol=atol, events=evs)
        for te, ye in zip(sol.t_events[-1], sol.y_events[-1]):
            f = col.forces(ye)[0]
            if ye[0] > 0 and f > 0 and f >= threshold:
                rec["maxima"].append((te, f, len(rec["episodes"]) - 1))
        if sol.status != 1:
            t, y = sol.t[-1], sol.y[:, -1]
            break
        j = next(i for i, te in enumerate(sol.t_events[:-1]) if len(te))
        t, y = sol.t_events[j][0], sol.y_events[j][0]
        closed[j] = not closed[j]
        if not closed[j]:
            last_open[j] = t
            if j == 0:
                cl = 1
                while cl < n and closed[cl]:
                    cl += 1
                rec.update(tau_n=t, v_tau_n=y[n:].copy(), cluster=cl)
                rec["episodes"][-1][2:] = [t, y[n]]
        elif j == 0:
            rec["wall_closings"] += 1
            rec["episodes"].append([t, y[n], None, None])
        if stop_when_apart and not closed.any() and y[n] <= 0 and np.all(np.diff(y[n:]) <= 0):
            break
    rec.update(t_end=t, y=y, last_open=last_open)
    return rec


def collide(col, v, t_max):
    n = col.n
    r = follow(col, np.concatenate((np.zeros(n), np.full(n, v))), t_max, True)
    vf = r["y"][n:]
    mt = col.m.sum()
    mx = r["maxima"]
    vt = r["v_tau_n"]
    vg = (col.m * vt).sum() / mt
    lo = r["last_open"]
    return dict(f_max=max(f for _, f, _ in mx), tau_max=max(mx, key=lambda q: q[1])[0], tau_n=r["tau_n"],
                n_maxima=len(mx), period=(mx[-1][0] - mx[0][0]) / (len(mx) - 1) if len(mx) > 1 else None,
                final_velocities=vf, eps_eff=-(col.m * vf).sum() / (mt * v),
                eps_col=math.sqrt((col.m * vf * vf).sum() / (mt * v * v)),
                e_rel_over_e_k=(col.m * (vt - vg) ** 2).sum() / (col.m * vt * vt).sum(), velocities_at_tau_n=vt,
                n_s=n - r["cluster"], cluster=r["cluster"], wall_contacts=r["wall_closings"], t_end=r["t_end"],
                detach_times=[max(lo[i], lo[i + 1] if i < n - 1 else -np.inf) for i in range(n)])


def model_of(j):
    md = j["settings"]["model"]
    n = j["n"]
    if "radii" in md:
        r = md["radii"]
        m = [4 / 3 * math.pi * ri ** 3 * STEEL[2] for ri in r]
        kc = [hertz_k(r[i], r[i + 1]) for i in range(n - 1)]
        kw = hertz_k(r[0], 0)
    else:
        m, kc, kw = [md["mass"]] * n, [md["k"]] * (n - 1), md["kwall"]
    return m, kc, kw, md


def assert_chain_agrees(j, ref):
    for key in ("f_max", "tau_max", "tau_n", "eps_eff", "eps_col", "e_rel_over_e_k", "t_end"):
        assert j[key] == pytest.approx(ref[key], rel=TOL), key
    if ref["period"] is None:
        assert j["period"] is None
    else:
        assert j["period"] == pytest.approx(ref["period"], rel=TOL)
    for key in ("final_velocities", "velocities_at_tau_n", "detach_times"):
        a, b = np.array(j[key], float), np.array(ref[key], float)
        assert np.max(np.abs(a - b)) <= TOL * np.max(np.abs(b)), key
    for key in ("n_maxima", "n_s", "cluster", "wall_contacts"):
        assert j[key] == ref[key], key


@pytest.mark.parametrize("args", [
    ("--n", 5),
    ("--n", 6, "--radii", "4e-3,2e-3,2e-3,6e-3,1e-3,4e-3", "--damping", "kk", "--gamma", 2e4),
    ("--n", 10, "--damping", "hc", "--alpha", 3),
    ("--n", 6, "--damping", "kk", "--gamma", 3000, "--gravity", 9.81, "--kwall", 1e8),
])
def test_chain_against_reference(program, args):
    j = run_cli(program, "chain", *args)
    m, kc, kw, md = model_of(j)
    assert md["k"] == pytest.approx(kc[0] if kc else md["k"], rel=1e-14)
    assert md["kwall"] == pytest.approx(kw, rel=1e-14)
    c = md["gamma"] if md["damping"] == "kk" else md["alpha"]
    col = Column(m, kc, kw, md["damping"], c, md["gravity"])
    ref = collide(col, j["v_imp"], j["settings"]["solver"]["t_max"])
    assert_chain_agrees(j, ref)
    # closed forms (physics.md 1.3) of bead 1
    v, k = j["v_imp"], md["k"]
    cf = j["closed_forms"]
    assert cf["tau_1"] == pytest.approx(C_TAU * (5 * m[0] / (4 * kw)) ** 0.4 * v ** -0.2, rel=1e-12)
    assert cf["f_max_1"] == pytest.approx(kw * (5 * m[0] * v * v / (4 * kw)) ** 0.6, rel=1e-12)
    assert cf["t_q"] == pytest.approx(2 * (m[0] / k) ** 0.4 * v ** -0.2, rel=1e-12)
    assert cf["k_c"] == pytest.approx((C_TAU / 4) ** 2.5 * 1.25 * k, rel=1e-12)


@pytest.mark.parametrize("damping,e,extra", [("kk", 0.1, ()), ("hc", 0.9, ("--restitution-v", 0.05))])
def test_restitution_calibration_against_reference(program, damping, e, extra):
    j = run_cli(program, "chain", "--n", 3, "--damping", damping, "--restitution", e, *extra)
    md = j["settings"]["model"]
    vr, m, k, kw = md["restitution_v"], md["mass"], md["k"], md["kwall"]
    t1 = C_TAU * (5 * m / (4 * kw)) ** 0.4 * vr ** -0.2

    def e_of(c):
        col = Column([m], [], kw, damping, c)
        col.set_k1(k)
        r = follow(col, np.array([0.0, vr]), 40 * t1, True)
        return -r["y"][1] / vr - e

    c = md["gamma"] if damping == "kk" else md["alpha"]
    # the program's constant only brackets the root: brentq needs e_of to change sign
    # across [c/1.5, 1.5 c] and then finds the reference's own root
    c_ref = optimize.brentq(e_of, c / 1.5, 1.5 * c, rtol=1e-10)
    assert c == pytest.approx(c_ref, rel=1e-6)
    col = Column([m] * 3, [k] * 2, kw, damping, c)
    assert_chain_agrees(j, collide(col, j["v_imp"], j["settings"]["solver"]["t_max"]))


def test_softwall_against_reference(program):
    j = run_cli(program, "softwall", "--kwall", 1e9, "--n", "1:4", "--jobs", 1, "--quiet")
    md = j["settings"]["model"]
    m, k, v = md["mass"], md["k"], j["v_imp"]
    assert v == pytest.approx(math.sqrt(2 * 9.81 * 2.9e-3), rel=1e-12)
    assert j["k_c"] == pytest.approx((C_TAU / 4) ** 2.5 * 1.25 * k, rel=1e-12)
    assert j["wall"] == ("rigid" if 1e9 > j["k_c"] else "soft")
    for i, n in enumerate(j["n"]):
        ref = collide(Column([m] * n, [k] * (n - 1), 1e9), v, 1.0)
        assert j["f_max"][i] == pytest.approx(ref["f_max"], rel=TOL)
        assert j["tau_max"][i] == pytest.approx(ref["tau_max"], rel=TOL)
    # tau_max(N = 1) = tau_1 / 2 (F.21)
    assert j["tau_max"][0] == pytest.approx(C_TAU * (5 * m / 4e9) ** 0.4 * v ** -0.2 / 2, rel=TOL)


@pytest.mark.parametrize("args", [
    ("--n", 1, "--t-max", 0.1),
    ("--n", 4, "--gap", "1e-5,0,3e-5"),
    ("--n", 5, "--gravity", 1e4, "--t-max", 2e-3),
    ("--n", 4, "--block", "--damping", "kk", "--restitution", 0.9, "--t-max", 0.07),
])
def test_drop_against_reference(program, args):
    j = run_cli(program, "drop", *args)
    md, dr = j["settings"]["model"], j["settings"]["drop"]
    n, g, h = dr["n_column"], dr["gravity"], dr["height"]
    v = math.sqrt(2 * g * h)
    assert j["v_imp"] == pytest.approx(v, rel=1e-14)
    assert j["t_fall"] == pytest.approx(math.sqrt(2 * h / g), rel=1e-14)
    nb = 1 if dr["block"] else n  # the block: one body of the column's mass (settings.model.mass)
    c = md["gamma"] if md["damping"] == "kk" else md["alpha"]
    col = Column([md["mass"]] * nb, [md["k"]] * (nb - 1), md["kwall"], md["damping"], c, g)
    col.set_k1(md["k"])
    gaps = dr["gaps"] * (n - 1) if len(dr["gaps"]) == 1 else (dr["gaps"] or [0.0] * (nb - 1))
    x = -np.concatenate(([0.0], np.cumsum(gaps)))[:nb]
    r = follow(col, np.concatenate((x, np.full(nb, v))), dr["t_max"], False, j["peak_threshold"])
    peaks = r["maxima"]
    assert j["n_peaks"] == len(peaks)
    assert j["n_contact_episodes"] == len(r["episodes"])
    for p, (t, f, _) in zip(j["wall_peaks"], peaks):
        assert p["t"] == pytest.approx(t, rel=TOL, abs=TOL * dr["t_max"])
        assert p["f"] == pytest.approx(f, rel=TOL)
    eps = [i for i in range(len(r["episodes"])) if any(q[2] == i for q in peaks)]
    assert j["n_impacts"] == len(eps)
    for imp, i in zip(j["impacts"], eps):
        t0, vin, t1, vout = r["episodes"][i]
        best = max((q for q in peaks if q[2] == i), key=lambda q: q[1])
        assert imp["f_max"] == pytest.approx(best[1], rel=TOL)
        assert imp["t_start"] == pytest.approx(t0, abs=TOL * dr["t_max"])
        assert imp["v_in"] == pytest.approx(vin, rel=TOL)
        if t1 is None:
            assert imp["t_end"] is None
        else:
            assert imp["t_end"] == pytest.approx(t1, rel=TOL)
            assert imp["v_out"] == pytest.approx(vout, rel=TOL)
    y = r["y"]
    ek = 0.5 * (col.m * y[nb:] ** 2).sum()
    assert j["energy"]["kinetic"] == pytest.approx(ek, abs=1e-7 * j["energy"]["e0"])
    assert j["energy"]["gravity"] == pytest.approx(-(col.m * g * y[:nb]).sum(), abs=1e-7 * j["energy"]["e0"])
