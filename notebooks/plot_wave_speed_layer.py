#!/usr/bin/python3
"""plot_wave_speed_layer.py: the layer's wave speed against the impact speed V_i.

    plot_wave_speed_layer.py run DIR [--sample FILE] [--speeds LIST] [--points N]
                                     [--spacing D] [--t-max T] [--mass-law LAW] [--gravity G]
                                     [--rings K] [--tag NAME]
    plot_wave_speed_layer.py plot DIR

run: one `granwave layer-impact --full` per (V_i, impact point), in the fast default mode,
on the sample (default data/measured/restitution_full/sample.txt, the 300-disc seed-1
sample of the README's layer studies), the block R_b = R_m, normal incidence; N points
D apart around the box centre (physics.md 2.3). Appends to DIR/impacts.csv (one row per
impact: the cross-correlation speed wave_speed_xcorr and its error, the peak-picking
speeds) and DIR/delays.csv (the delay of every ring pair used, 6 digits); rows already present (same
tag, V_i, x) are skipped, so an interrupted run resumes. Each impact runs under
`nice -n 10`, one at a time.

plot: reads DIR/impacts.csv and DIR/delays.csv, writes DIR/fit.json and DIR/figures/
(wave_speed_vs_vi.png, local_speed_vs_r.png, gravity.png: speeds under 4 g over 1 g). Nothing physical is computed here but
averages and fits of the program's numbers:
  - per (tag, V_i): mean speed over the impact points and its standard error;
  - power law c = A V_i^beta over 5 <= V_i <= 40 m/s (least squares in log-log,
    weighted by the standard errors), beta with its standard error;
  - the local exponent d ln c / d ln V_i between neighbouring speeds;
  - the crossover between a linear sound speed c0 (gravity prestress) and the Hertz
    sonic-vacuum law c ~ V^(1/5): the Rankine-Hugoniot speed of a compression front
    in a Hertz chain precompressed to overlap d0 (docs/crowns.md derives it),
        (c/c0)^2 = (2/3) (x^(3/2) - 1) / (x - 1),   u/U0 = (c/c0) (x - 1),
    x = d1/d0 the overlap ratio across the front, u the particle velocity behind it,
    U0 = c0 d0 / a; it tends to c0 for u << U0 and to (2/3)^(2/5) c0 (u/U0)^(1/5)
    (the sonic vacuum, physics.md F.27) for u >> U0, the two asymptotes meeting at
    u = (9/4) U0. With u proportional to V_i, u/U0 = (9/4) V_i / V*, the fit gives c0
    and the crossover speed V* (the V_i where the asymptotes meet).
Exit status: 0 ok, 2 on a missing or malformed input (message names it), 1 when a run
of the program fails.
Use Debian's /usr/bin/python3 (numpy, scipy, matplotlib with the Agg backend).
"""

import csv
import json
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gwdata  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SAMPLE = os.path.normpath(os.path.join(HERE, "..", "data", "measured", "restitution_full",
                                               "sample.txt"))
DEFAULT_SPEEDS = "0.5,1,2,3,5,7,10,14,20,28,40,80,160"
IMPACT_COLUMNS = ["tag", "sample", "rings", "mass_law", "gravity", "vi", "x", "wave_speed_xcorr", "wave_speed_xcorr_err",
                  "wave_xcorr_gaps", "wave_speed", "wave_speed_err", "wave_speed_kinetic",
                  "wave_rings", "energy_error", "t_end", "wall_time_ms"]
DELAY_COLUMNS = ["tag", "vi", "x", "ring", "r_mid", "r_next", "delay", "rho"]
FIT_RANGE = (5.0, 40.0)
MAIN_TAGS = ("disc", "disc_r7", "sphere")  # drawn in wave_speed_vs_vi.png when present
GRAVITY_PAIRS = (("disc_r7", "disc_g4_r7"), ("seed2_r7", "seed2_g4_r7"), ("disc", "disc_g4"))
PAPER_SPEED = 1000.0  # physics.md 2.5: c = d_c / Delta t is about 1000 m/s


class InputError(Exception):
    """A missing or malformed input; main() prints it and exits with 2."""


# ------------------------------------------------------------------ run ----

def _fmt(v):
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "nan"
    return f"{v:.9g}" if isinstance(v, float) else str(v)


def _existing(path):
    if not os.path.exists(path):
        return set()
    t = gwdata.load_csv(path)
    return {(str(a), float(v), float(x)) for a, v, x in zip(t["tag"], t["vi"], t["x"])}


def _append(path, columns, rows, header):
    new = not os.path.exists(path)
    with open(path, "a", newline="") as f:
        if new:
            for line in header:
                f.write("# " + line + "\n")
            f.write(",".join(columns) + "\n")
        w = csv.writer(f)
        for r in rows:
            w.writerow([r[c] if isinstance(r[c], str) else _fmt(r[c]) for c in columns])


def run(args):
    import argparse
    p = argparse.ArgumentParser(prog="plot_wave_speed_layer.py run")
    p.add_argument("dir")
    p.add_argument("--sample", default=DEFAULT_SAMPLE)
    p.add_argument("--speeds", default=DEFAULT_SPEEDS)
    p.add_argument("--points", type=int, default=16)
    p.add_argument("--spacing", type=float, default=0.15)
    p.add_argument("--t-max", type=float, default=0.02)
    p.add_argument("--mass-law", default="")
    p.add_argument("--gravity", type=float, default=0.0)
    p.add_argument("--rings", type=int, default=0)
    p.add_argument("--tag", default="disc")
    a = p.parse_args(args)
    if not os.path.isfile(a.sample):
        raise InputError(f"--sample: no file {a.sample}")
    try:
        speeds = [float(s) for s in a.speeds.split(",")]
    except ValueError:
        raise InputError(f"--speeds: '{a.speeds}' is not a comma-separated list of numbers")
    if (a.points < 1 or not 0 <= a.spacing < math.inf or not 0 < a.t_max < math.inf
            or any(not 0 < v < math.inf for v in speeds)):
        raise InputError("--points >= 1, finite --spacing >= 0, --t-max > 0 and speeds > 0 are required")
    gw = gwdata.find_granwave()
    os.makedirs(a.dir, exist_ok=True)
    imp, dly = os.path.join(a.dir, "impacts.csv"), os.path.join(a.dir, "delays.csv")
    done = _existing(imp)
    version = subprocess.run([gw, "version"], capture_output=True, text=True).stdout.strip()
    header = [version, "plot_wave_speed_layer.py run " + " ".join(args),
              f"sample {a.sample}; layer-impact --full --t-max {a.t_max} --rb-rm 1 --alpha 0, fast "
              "default (verlet); speeds in m/s, x in m from the box centre, delays in s"]
    for vi in speeds:
        for k in range(a.points):
            x = round((k - 0.5 * (a.points - 1)) * a.spacing, 10)
            if (a.tag, vi, x) in done:
                continue
            cmd = ["nice", "-n", "10", gw, "layer-impact", "--sample", a.sample, "--vi", repr(vi),
                   "--x", repr(x), "--full", "--t-max", repr(a.t_max), "--json"]
            if a.mass_law:
                cmd += ["--mass-law", a.mass_law]
            if a.gravity > 0:
                cmd += ["--gravity", repr(a.gravity)]
            if a.rings > 0:
                cmd += ["--rings", str(a.rings)]
            out = subprocess.run(cmd, capture_output=True, text=True)
            if out.returncode != 0:
                sys.stderr.write(f"granwave failed ({out.returncode}): {' '.join(cmd)}\n{out.stderr}")
                return 1
            d = json.loads(out.stdout)
            row = {c: d.get(c) for c in IMPACT_COLUMNS}
            row.update(tag=a.tag, sample=a.sample, rings=len(d["crowns"]["ring_r"]), vi=vi, x=x,
                       mass_law=d["settings"]["material"]["mass_law"].split()[0],
                       gravity=d["settings"]["material"]["gravity"])
            _append(imp, IMPACT_COLUMNS, [row], header)
            cr = d["crowns"]
            rows = [{"tag": a.tag, "vi": vi, "x": x, "ring": q, "r_mid": cr["ring_r"][q],
                     "r_next": cr["ring_r"][q + 1], "delay": float(f"{cr['xcorr_delay'][q]:.6g}"),
                     "rho": float(f"{cr['xcorr_rho'][q]:.6g}")}
                    for q in range(len(cr["xcorr_delay"])) if cr["xcorr_delay"][q] is not None]
            _append(dly, DELAY_COLUMNS, rows, header)
            print(f"{a.tag} V_i {vi:6g} x {x:+.3f}: c_xcorr {_fmt(d['wave_speed_xcorr'])} "
                  f"+- {_fmt(d['wave_speed_xcorr_err'])}, peaks {_fmt(d['wave_speed'])}", flush=True)
    return 0


# ----------------------------------------------------------------- plot ----

def secant_speed(u_over_u0):
    """c/c0 of a front in a precompressed Hertz chain against u/U0 (module docstring)."""
    from scipy.optimize import brentq
    out = []
    for s in np.atleast_1d(u_over_u0):
        def f(x):
            y = math.sqrt((2.0 / 3.0) * (x ** 1.5 - 1.0) / (x - 1.0))
            return y * (x - 1.0) - s
        hi = 2.0
        while f(hi) < 0:
            hi *= 2.0
        x = brentq(f, 1.0 + 1e-12, hi, xtol=1e-14, rtol=1e-14)
        out.append(math.sqrt((2.0 / 3.0) * (x ** 1.5 - 1.0) / (x - 1.0)))
    return np.array(out)


def crossover_model(vi, c0, vstar):
    return c0 * secant_speed(2.25 * np.asarray(vi) / vstar)


def load(d):
    if not os.path.isdir(d):
        raise InputError(f"no directory {d}")
    out = []
    for name, cols in (("impacts.csv", IMPACT_COLUMNS), ("delays.csv", DELAY_COLUMNS)):
        path = os.path.join(d, name)
        try:
            t = gwdata.load_csv(path)
        except FileNotFoundError:
            raise InputError(f"missing file {path}")
        except (ValueError, OSError) as e:
            raise InputError(gwdata.read_error(path, e))
        miss = [c for c in cols if c not in t]
        if miss:
            raise InputError(f"{path}: missing column(s) {', '.join(miss)}")
        if len(t[cols[0]]) == 0:
            raise InputError(f"{path}: no rows (run: plot_wave_speed_layer.py run {d})")
        out.append(t)
    return out


def error_check(imp, key, err_key):
    """{tag: [[V_i, mean reported error, standard deviation over the points], ...]}: whether
    one impact's error bar describes the scatter from one impact point to the next."""
    res = {}
    tags = np.array(imp["tag"])
    for tag in sorted(set(tags)):
        rows = []
        for v in sorted(set(imp["vi"][tags == tag])):
            s = (tags == tag) & (imp["vi"] == v) & np.isfinite(imp[key]) & np.isfinite(imp[err_key])
            if s.sum() > 1:
                rows.append([float(v), float(imp[err_key][s].mean()), float(imp[key][s].std(ddof=1))])
        res[tag] = rows
    return res


def groups(imp, key="wave_speed_xcorr"):
    """{tag: (V_i array, mean, standard error, count)} over the impact points."""
    res = {}
    tags = np.array(imp["tag"])
    vi = imp["vi"]
    for tag in sorted(set(tags)):
        vs, ms, es, ns = [], [], [], []
        for v in sorted(set(vi[tags == tag])):
            c = imp[key][(tags == tag) & (vi == v)]
            c = c[np.isfinite(c)]
            if len(c) == 0:
                continue
            vs.append(v), ms.append(c.mean()), ns.append(len(c))
            es.append(c.std(ddof=1) / math.sqrt(len(c)) if len(c) > 1 else float("nan"))
        res[tag] = tuple(np.array(a) for a in (vs, ms, es, ns))
    return res


def power_fit(v, m, e, lo, hi):
    sel = (v >= lo) & (v <= hi) & np.isfinite(e) & (e > 0)
    x, y, s = np.log(v[sel]), np.log(m[sel]), e[sel] / m[sel]
    w = 1 / s ** 2
    X = np.vstack([np.ones_like(x), x]).T
    cov = np.linalg.inv(X.T @ (w[:, None] * X))
    b = cov @ (X.T @ (w * y))
    chi2 = float(np.sum(w * (y - X @ b) ** 2))
    dof = max(len(x) - 2, 1)
    scale = max(1.0, chi2 / dof)  # inflate the errors when the points scatter more than their bars
    return {"A": float(math.exp(b[0])), "beta": float(b[1]), "beta_err": float(math.sqrt(cov[1, 1] * scale)),
            "chi2_per_dof": chi2 / dof, "n_speeds": int(sel.sum()), "range": [lo, hi]}


def crossover_fit(v, m, e):
    from scipy.optimize import curve_fit
    sel = np.isfinite(e) & (e > 0)
    p, cov = curve_fit(crossover_model, v[sel], m[sel], p0=[m[sel].min(), 5.0], sigma=e[sel],
                       absolute_sigma=True, bounds=([1, 1e-3], [1e5, 1e5]))
    r = (m[sel] - crossover_model(v[sel], *p)) / e[sel]
    chi2 = float(np.sum(r ** 2)) / max(int(sel.sum()) - 2, 1)
    err = np.sqrt(np.diag(cov) * max(1.0, chi2))
    lo, hi = FIT_RANGE
    h = 1e-4
    local = [float((math.log(crossover_model([vv * (1 + h)], *p)[0]) - math.log(crossover_model([vv], *p)[0]))
                   / math.log(1 + h)) for vv in (lo, hi)]
    return {"c0": float(p[0]), "c0_err": float(err[0]), "v_star": float(p[1]), "v_star_err": float(err[1]),
            "chi2_per_dof": chi2, "local_exponent_at_5_and_40": local}


def analyse(imp, dly):
    g = groups(imp)
    gp = groups(imp, "wave_speed")
    fit = {"paper_speed": PAPER_SPEED, "tags": {}}
    ex, ep = error_check(imp, "wave_speed_xcorr", "wave_speed_xcorr_err"), error_check(imp, "wave_speed", "wave_speed_err")
    for tag, (v, m, e, n) in g.items():
        f = {"vi": v.tolist(), "c_xcorr_mean": m.tolist(), "c_xcorr_se": e.tolist(), "points": n.tolist(),
             "xcorr_error_vs_scatter": ex[tag], "peak_error_vs_scatter": ep[tag]}
        pv, pm, pe, pn = gp[tag]
        f.update(peak_vi=pv.tolist(), c_peak_mean=pm.tolist(), c_peak_se=pe.tolist(), peak_points=pn.tolist())
        if np.sum((v >= FIT_RANGE[0]) & (v <= FIT_RANGE[1])) >= 3:
            f["power_law_xcorr"] = power_fit(v, m, e, *FIT_RANGE)
            f["power_law_peaks"] = power_fit(pv, pm, pe, *FIT_RANGE)
        f["local_exponent"] = [[float(v[i]), float(v[i + 1]), float(math.log(m[i + 1] / m[i]) / math.log(v[i + 1] / v[i]))]
                               for i in range(len(v) - 1)]
        if len(v) >= 4:
            try:
                f["crossover"] = crossover_fit(v, m, e)
            except (RuntimeError, ValueError) as ex:
                f["crossover"] = {"error": str(ex)}
        # local speed per ring pair: d_c / delay, mean over the points
        tags = np.array(dly["tag"])
        loc = {}
        for vv in v:
            sel = (tags == tag) & (dly["vi"] == vv) & np.isfinite(dly["delay"])
            rows = []
            for q in sorted(set(dly["ring"][sel].astype(int))):
                s = sel & (dly["ring"] == q)
                cl = (dly["r_next"][s] - dly["r_mid"][s]) / dly["delay"][s]
                rows.append([float(0.5 * (dly["r_mid"][s][0] + dly["r_next"][s][0])), float(cl.mean()),
                             float(cl.std(ddof=1) / math.sqrt(len(cl))) if len(cl) > 1 else float("nan"),
                             int(len(cl))])
            loc[repr(float(vv))] = rows
        f["local_speed_by_r"] = loc
        fit["tags"][tag] = f
    fit["gravity_ratios"] = {}
    for a, b in GRAVITY_PAIRS:
        if a in fit["tags"] and b in fit["tags"]:
            fa, fb = fit["tags"][a], fit["tags"][b]
            rows = []
            for v, m, e in zip(fb["vi"], fb["c_xcorr_mean"], fb["c_xcorr_se"]):
                if v in fa["vi"]:
                    i = fa["vi"].index(v)
                    r = m / fa["c_xcorr_mean"][i]
                    rows.append([v, r, r * math.hypot(e / m, fa["c_xcorr_se"][i] / fa["c_xcorr_mean"][i])])
            fit["gravity_ratios"][f"{b}/{a}"] = rows
    # what a prestress scaled by 4 predicts from the inner rings' crossover fit:
    # c0 ~ F0^(1/6), U0 = c0 d0 / a ~ F0^(5/6)
    cr = fit["tags"].get("disc_r7", {}).get("crossover", {})
    if "c0" in cr:
        vv = [1.0, 2.0, 3.0, 5.0, 10.0, 20.0, 40.0, 80.0]
        r = crossover_model(vv, cr["c0"] * 4 ** (1 / 6), cr["v_star"] * 4 ** (5 / 6)) / \
            crossover_model(vv, cr["c0"], cr["v_star"])
        fit["gravity_prediction_4g"] = [[v, float(x)] for v, x in zip(vv, r)]
    return fit


def points_label(fit, tags=MAIN_TAGS):
    """"16 impact points" (or "2 to 16 impact points"): the numbers of points behind the
    means drawn, read from the fit (the run's --points; the stored series have 16)."""
    n = sorted({int(k) for t, f in fit["tags"].items() if t in tags for k in f["points"]})
    if not n:
        return "no impact points"
    return (f"{n[0]}" if n[0] == n[-1] else f"{n[0]} to {n[-1]}") + (" impact point" if n == [1] else " impact points")


def figures(d, fit):
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    os.makedirs(os.path.join(d, "figures"), exist_ok=True)
    fig = Figure(figsize=(7.5, 5))
    ax = fig.subplots()
    colors = {"disc": "C0", "disc_r7": "C2", "sphere": "C3"}
    for i, (tag, f) in enumerate(fit["tags"].items()):
        if tag not in MAIN_TAGS:
            continue
        col = colors.get(tag, f"C{i + 4}")
        v, m, e = np.array(f["vi"]), np.array(f["c_xcorr_mean"]), np.array(f["c_xcorr_se"])
        ax.errorbar(v, m, yerr=np.nan_to_num(e), fmt="o", color=col, label=f"{tag}: cross-correlation")
        ax.plot(f["peak_vi"], f["c_peak_mean"], "x", color=col, alpha=0.6, label=f"{tag}: strain peak picking")
        if "power_law_xcorr" in f:
            p = f["power_law_xcorr"]
            vv = np.geomspace(*FIT_RANGE, 30)
            ax.plot(vv, p["A"] * vv ** p["beta"], "-", color=col,
                    label=f"{tag} fit 5-40 m/s: beta = {p['beta']:.3f} +- {p['beta_err']:.3f}")
        cr = f.get("crossover", {})
        if "c0" in cr:
            vv = np.geomspace(min(v), max(v), 80)
            ax.plot(vv, crossover_model(vv, cr["c0"], cr["v_star"]), "--", color=col, lw=1,
                    label=f"{tag} precompressed Hertz front: c0 = {cr['c0']:.0f}, V* = {cr['v_star']:.2g} m/s")
            ax.plot(vv, cr["c0"] * (vv / cr["v_star"]) ** 0.2, ":", color=col, lw=1)
            ax.axhline(cr["c0"], color=col, lw=0.5, ls=":")
    ax.axhline(fit["paper_speed"], color="k", lw=1, ls="-.", label="paper: about 1000 m/s")
    ax.axvspan(*FIT_RANGE, color="0.9", zorder=0)
    ax.set_xscale("log"), ax.set_yscale("log")
    ax.set_xlabel("impact speed V_i (m/s)"), ax.set_ylabel("wave speed c (m/s)")
    ax.set_title("layer wave speed: R_b = R_m, normal impacts, mean over " + points_label(fit))
    ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "figures", "wave_speed_vs_vi.png"), dpi=110)
    fig = Figure(figsize=(7.5, 4.5))
    ax = fig.subplots()
    f = fit["tags"].get("disc") or next(iter(fit["tags"].values()))
    keys = sorted(f["local_speed_by_r"], key=float)
    cmap = matplotlib.colormaps["viridis"]
    for i, k in enumerate(keys):
        rows = np.array(f["local_speed_by_r"][k])
        if len(rows) == 0:
            continue
        ax.errorbar(rows[:, 0], rows[:, 1], yerr=np.nan_to_num(rows[:, 2]), fmt="o-", ms=3,
                    color=cmap(i / max(len(keys) - 1, 1)), label=f"{float(k):g} m/s")
    ax.set_xlabel("ring pair mid radius (m)"), ax.set_ylabel("local speed d_c / delay (m/s)")
    ax.set_title("local speed ring to ring (cross-correlation), by V_i")
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "figures", "local_speed_vs_r.png"), dpi=110)
    if fit["gravity_ratios"]:
        fig = Figure(figsize=(7.5, 4.5))
        ax, bx = fig.subplots(1, 2)
        for i, (a, b) in enumerate(p for p in GRAVITY_PAIRS if f"{p[1]}/{p[0]}" in fit["gravity_ratios"]):
            for tag, ls in ((a, "-"), (b, "--")):
                f = fit["tags"][tag]
                ax.errorbar(f["vi"], f["c_xcorr_mean"], yerr=np.nan_to_num(f["c_xcorr_se"]), fmt="o" + ls, ms=3, color=f"C{i}",
                            label=tag)
            rows = np.array(fit["gravity_ratios"][f"{b}/{a}"])
            bx.errorbar(rows[:, 0], rows[:, 1], yerr=np.nan_to_num(rows[:, 2]), fmt="o-", ms=3, color=f"C{i}", label=f"{b} / {a}")
        bx.axhline(4 ** (1 / 6), color="k", ls=":", lw=1, label="4^(1/6): linear speed, Hertz prestress")
        if "gravity_prediction_4g" in fit:
            pr = np.array(fit["gravity_prediction_4g"])
            bx.plot(pr[:, 0], pr[:, 1], "k--", lw=1, label="precompressed front, prestress x 4 (disc_r7 fit)")
        bx.axhline(1, color="k", lw=0.5)
        for x in (ax, bx):
            x.set_xscale("log"), x.set_xlabel("V_i (m/s)"), x.legend(fontsize=6)
        ax.set_yscale("log"), ax.set_ylabel("c (m/s)"), bx.set_ylabel("speed ratio 4 g / 1 g")
        ax.set_title("1 g (solid) and 4 g (dashed) samples", fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(d, "figures", "gravity.png"), dpi=110)


def plot(args):
    if len(args) != 1:
        raise InputError("usage: plot_wave_speed_layer.py plot DIR")
    d = args[0]
    imp, dly = load(d)
    fit = analyse(imp, dly)
    try:
        figures(d, fit)
        with open(os.path.join(d, "fit.json"), "w") as fp:
            json.dump(fit, fp, indent=1)
    except OSError as e:
        sys.stderr.write(f"plot_wave_speed_layer.py: cannot write under {d}: {e.strerror or e}"
                         + (f" ({e.filename})" if e.filename else "") + "\n")
        return 1
    for tag, f in fit["tags"].items():
        print(f"{tag}: {fit_summary(f)}")
    return 0


def fit_summary(f):
    """One tag's fits in words; a fit the series cannot give is said so, not printed as nan."""
    p, cr = f.get("power_law_xcorr"), f.get("crossover", {})
    n_range = sum(1 for v in f["vi"] if FIT_RANGE[0] <= v <= FIT_RANGE[1])
    if p:
        out = f"beta({FIT_RANGE[0]:g}-{FIT_RANGE[1]:g}) = {p['beta']:.4f} +- {p['beta_err']:.4f}; "
    else:
        out = (f"beta({FIT_RANGE[0]:g}-{FIT_RANGE[1]:g}) not fitted ({n_range} speed(s) in "
               f"{FIT_RANGE[0]:g}-{FIT_RANGE[1]:g} m/s, 3 needed); ")
    if "c0" in cr:
        out += (f"c0 = {cr['c0']:.1f} +- {cr['c0_err']:.1f} m/s, "
                f"V* = {cr['v_star']:.3g} +- {cr['v_star_err']:.2g} m/s")
    elif "error" in cr:
        out += f"crossover not fitted ({cr['error']})"
    else:
        out += f"crossover not fitted ({len(f['vi'])} speed(s), 4 needed)"
    return out


def main(argv):
    if len(argv) == 2 and argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0
    try:
        if len(argv) < 2 or argv[1] not in ("run", "plot"):
            raise InputError("usage: plot_wave_speed_layer.py run DIR [options] | plot DIR")
        return run(argv[2:]) if argv[1] == "run" else plot(argv[2:])
    except InputError as e:
        sys.stderr.write(f"plot_wave_speed_layer.py: {e}\n")
        return 2
    except gwdata.GranwaveError as e:
        sys.stderr.write(f"plot_wave_speed_layer.py: {e}\n")
        return 2


if __name__ == "__main__":
    sys.exit(gwdata.run_main(main, sys.argv))
