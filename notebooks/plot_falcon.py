#!/usr/bin/python3
"""plot_falcon.py DIR: figures of a `granwave falcon --out DIR` run, written to DIR/figures/.
plot_falcon.py --module DIR [--n A:B]: the same figures from the Python module granwave
(granwave.falcon for the study, granwave.chain for the traces and the final velocities;
no program run, nothing read but data/falcon1998), written to DIR/figures/.

Reads (all produced by the program; nothing is recomputed here but unit conversions):
  falcon_runs.csv              F_max, tau_N, E_rel/E_K per (v_imp, N)
  falcon_final_velocities.csv  final velocity of every bead
  falcon_summary.json          per-velocity fit (T_q, intercept) and closed forms
  trace_n7_wall_force.csv, trace_n7_beads.csv   required
  trace_n15_wall_force.csv, trace_n30_wall_force.csv   optional (the program writes them
                               only when N = 15 / 30 is in its --n range): a missing one
                               is reported on stderr and left out of the figure
and data/falcon1998/rigid_wall.csv for the paper's measured F_max (69 N at h = 5.1 mm,
51.8 N at h = 3.1 mm, drawn with a +-5 % band).

Writes fmax_vs_n.png, taun_vs_n.png, wall_force_n7_15_30.png, velocities_n7.png,
erel_vs_n.png, final_velocities.png. Each PNG carries the program version and settings
in its metadata and a footer line.

With --module the run is run_from_module(n): the default study of `granwave falcon`
(N = 1..40 unless --n; v_imp = 0.3 m/s and the heights 1.9, 2.9, 3.1, 5.1 mm; RK4 with the
step of the 1e-6 accuracy target), the traces for N = 7, 15, 30 and the final velocities at
0.3 m/s from granwave.chain with its own default solver (CVODE, rtol 1e-12). The program's
files use the study's RK4 for these, so they differ by what its 1e-6 target allows: trace
peaks by 4e-7 of F_max and final velocities by 2.3e-7 m/s (measured at N = 1..30), far
below what the figures resolve; the study's own numbers are the same library call.
The library is found as the module finds it (GRANWAVE_LIB, ...).

Exit status: 0 ok, 2 if DIR or a required file is missing, unreadable, not a regular file
or malformed (no rows, a key or a number missing), or (--module) if the module cannot be
loaded or refuses a value; 1 if a figure cannot be written.
Use Debian's /usr/bin/python3. The functions (load_run, run_from_module, make_figures)
are also used by notebooks/falcon_column.ipynb to show the figures inline.
"""

import json
import os
import sys

import numpy as np
import matplotlib
from matplotlib.figure import Figure

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gwdata  # noqa: E402

US = 1e6  # s -> us
REQUIRED = ["falcon_runs.csv", "falcon_final_velocities.csv", "falcon_summary.json",
            "trace_n7_wall_force.csv", "trace_n7_beads.csv"]
OPTIONAL_TRACES = [15, 30]
RUN_COLUMNS = ["v_imp_m_s", "h_mm", "n", "f_max_N", "tau_n_s", "e_rel_over_e_k"]
FINAL_COLUMNS = ["v_imp_m_s", "n", "bead", "final_v_m_s"]
FIGURES = ["fmax_vs_n", "taun_vs_n", "wall_force_n7_15_30", "velocities_n7", "erel_vs_n",
           "final_velocities"]
PAPER_BAND = 0.05  # "independent of N within 5 %" (docs/physics.md 1.7)


InputError = gwdata.InputError    # exit 2
OutputError = gwdata.OutputError  # exit 1


def _csv(path, columns=(), finite=()):
    try:
        t = gwdata.load_csv(path)
    except FileNotFoundError:
        raise InputError(f"missing file {path}")
    except (ValueError, OSError) as e:
        raise InputError(gwdata.read_error(path, e))
    missing = [c for c in columns if c not in t]
    if missing:
        raise InputError(f"{path}: missing column(s) {', '.join(missing)}")
    for c in columns:
        if not isinstance(t[c], np.ndarray):
            raise InputError(f"{path}: column {c} is not numeric")
    if columns and len(t[columns[0]]) == 0:
        raise InputError(f"{path}: no rows (a run cut short?)")
    for c in finite:
        if not np.all(np.isfinite(t[c])):
            raise InputError(f"{path}: column {c} has an empty or non-finite cell")
    return t


def _is_number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def load_run(d):
    """Everything plot_falcon needs from DIR d, as a dict. Raises InputError."""
    if not os.path.isdir(d):
        raise InputError(f"no such directory {d} (run: granwave falcon --out {d})")
    for f in REQUIRED:
        if not os.path.lexists(os.path.join(d, f)):
            raise InputError(f"missing file {os.path.join(d, f)} "
                             f"(is {d} the --out directory of granwave falcon?)")
    run = {"dir": d, "notes": []}
    run["runs"] = _csv(os.path.join(d, "falcon_runs.csv"), RUN_COLUMNS, finite=("v_imp_m_s", "n"))
    run["final"] = _csv(os.path.join(d, "falcon_final_velocities.csv"), FINAL_COLUMNS,
                        finite=("v_imp_m_s", "n", "bead"))
    path = os.path.join(d, "falcon_summary.json")
    try:
        run["summary"] = gwdata.load_json(path)
    except FileNotFoundError:
        raise InputError(f"missing file {path}")
    except (OSError, ValueError) as e:
        raise InputError(gwdata.read_error(path, e))
    vel = run["summary"].get("velocities")
    if not isinstance(vel, list) or not vel or not all(isinstance(v, dict) for v in vel):
        raise InputError(f"{path}: 'velocities' is not a non-empty list of objects")
    for v in vel:
        for key in ("v_imp", "h_mm", "t_q", "t_q_err", "tau_fit_intercept", "f_max_1_theory"):
            if key not in v:
                raise InputError(f"{path}: missing key '{key}' in velocities")
            if not (v[key] is None or _is_number(v[key])) or (key == "v_imp" and not _is_number(v[key])):
                raise InputError(f"{path}: velocities' {key} = {v[key]!r} is not a number")
    if not isinstance(run["summary"].get("settings", {}), dict):
        raise InputError(f"{path}: 'settings' is not an object")
    run["wall"] = {}
    for n in [7] + OPTIONAL_TRACES:
        p = os.path.join(d, f"trace_n{n}_wall_force.csv")
        if n != 7 and not os.path.lexists(p):
            run["notes"].append(f"{p} not found (N = {n} outside the run's --n range?): "
                                f"left out of wall_force_n7_15_30.png")
            continue
        run["wall"][n] = _csv(p, ["t_s", "f_wall_N"])
    run["beads7"] = _csv(os.path.join(d, "trace_n7_beads.csv"), ["t_s", "v1_m_s"], finite=("v1_m_s",))
    return run


# keywords of granwave.falcon that granwave.chain does not take
_STUDY_ONLY = ("vimp", "heights", "n", "accuracy", "jobs")
_SOLVER_KEYS = ("solver", "method", "rtol", "atol", "dt")


def _nan_none(x):
    x = float(x)
    return None if not np.isfinite(x) else x


def run_from_module(n=(1, 40), progress=None, **kw):
    """The run dict of load_run, computed with the Python module granwave instead of read
    from a `granwave falcon --out` directory.

    n = (A, B): column sizes (default 1..40, as `granwave falcon`); other keywords are granwave.falcon's (vimp, heights, material,
    solver, ...); the model keywords go to granwave.chain as well. The study is one
    granwave.falcon call; the traces (N = 7, 15, 30 at the first velocity, sampled every
    tau_1/50 as the program's) and the final velocities (every N at the reference velocity
    of fig_final) are granwave.chain calls. Raises InputError if the module cannot be
    loaded or refuses a value (the message names it).
    """
    try:
        gw = gwdata.import_granwave()
    except gwdata.GranwaveError as e:
        raise InputError(str(e))
    try:
        f = gw.falcon(n=tuple(int(x) for x in n), progress=progress, **kw)
        model = {k: v for k, v in kw.items() if k not in _STUDY_ONLY}
        nv, ns = len(f.v_imp), np.asarray(f.n, dtype=float)
        runs = {"v_imp_m_s": np.repeat(f.v_imp, len(ns)), "h_mm": np.repeat(f.h_mm, len(ns)),
                "n": np.tile(ns, nv)}
        for col, key in (("f_max_N", "f_max"), ("tau_max_s", "tau_max"), ("tau_n_s", "tau_n"),
                         ("period_s", "period"), ("e_rel_over_e_k", "e_rel_over_e_k"),
                         ("eps_eff", "eps_eff"), ("eps_col", "eps_col"), ("n_s", "n_s"),
                         ("energy_error", "energy_error")):
            runs[col] = np.asarray(f[key], dtype=float).reshape(-1)
        per_v = ("t_q", "t_q_err", "tau_fit_intercept", "tau_fit_intercept_err", "r2", "t_q_n20",
                 "t_q_n20_err", "wave_speed", "wave_speed_n20", "wave_speed_theory", "t_q_theory",
                 "tau_1_theory", "f_max_1_theory", "f_max_mean", "f_max_min", "f_max_max",
                 "tau_max_mean", "period_mean")
        velocities = []
        for i in range(nv):
            e = {"v_imp": float(f.v_imp[i]), "h_mm": _nan_none(f.h_mm[i])}
            e.update({k: _nan_none(f[k][i]) for k in per_v if k in f})
            velocities.append(e)
        v0 = float(f.v_imp[0])
        wall, beads7 = {}, None
        for nt in (7, 15, 30):
            if nt > ns.max() or nt < ns.min():
                continue
            r = gw.chain(n=nt, vimp=v0, trace=True, dt_out=float(f.tau_1_theory[0]) / 50, **model)
            wall[nt] = {"t_s": np.asarray(r.t), "f_wall_N": np.asarray(r.f_wall)}
            if nt == 7:
                beads7 = {"t_s": np.asarray(r.t)}
                beads7.update({f"v{j + 1}_m_s": np.asarray(r.v)[:, j] for j in range(nt)})
        groups = [(v, None) for v in f.v_imp]
        vref = next((v for v, _ in groups if abs(v - 0.3) < 1e-9), v0)
        fin = {"v_imp_m_s": [], "n": [], "bead": [], "final_v_m_s": []}
        for nn in ns.astype(int):
            r = gw.chain(n=int(nn), vimp=vref, **model)
            fv = np.asarray(r.final_velocities, dtype=float)
            fin["v_imp_m_s"] += [vref] * len(fv)
            fin["n"] += [nn] * len(fv)
            fin["bead"] += list(range(1, len(fv) + 1))
            fin["final_v_m_s"] += list(fv)
    except gw.GranwaveError as e:
        raise InputError(f"granwave module: {e}")
    except TypeError as e:  # an unknown keyword
        raise InputError(f"granwave module: {e}")
    given = [k for k in _SOLVER_KEYS if k in kw]
    if given:
        solver = {"name": kw.get("solver", "cvode"), "rtol": kw.get("rtol", 1e-12)}
    else:
        solver = {"name": "rk4", "accuracy": float(kw.get("accuracy", f.accuracy))}
    mass = gw.chain(n=1, vimp=v0, **model).mass
    summary = {"version": gw.version(), "velocities": velocities, "n_min": int(ns.min()),
               "n_max": int(ns.max()),
               "settings": {"model": {"material": kw.get("material", "steel"), "mass": mass},
                            "solver": solver, "python": {"n": list(n), **{k: str(v) for k, v in kw.items()}}}}
    run = {"dir": None, "source": f"Python module granwave ({gw.library_path})",
           "notes": [], "runs": runs, "summary": summary, "wall": wall, "beads7": beads7,
           "final": {k: np.asarray(v, dtype=float) for k, v in fin.items()}}
    if beads7 is None:
        raise InputError(f"the figures need N = 7 in n = {n}")
    return run


def _velocity_groups(run):
    """[(v_imp, h_mm or None, summary entry or None, row mask)], in the file's order."""
    r = run["runs"]
    out, seen = [], []
    summ = run["summary"].get("velocities", [])
    for v in r["v_imp_m_s"]:
        if any(abs(v - s) <= 1e-12 * max(1.0, abs(v)) for s in seen):
            continue
        seen.append(v)
        mask = np.abs(r["v_imp_m_s"] - v) <= 1e-12 * max(1.0, abs(v))
        h = r["h_mm"][mask][0]
        entry = next((s for s in summ if abs(s["v_imp"] - v) <= 1e-9 * max(1.0, abs(v))), None)
        out.append((v, None if not np.isfinite(h) else float(h), entry, mask))
    return out


def _label(v, h):
    return f"v_imp = {v:.3f} m/s" if h is None else f"h = {h:g} mm (v_imp = {v:.3f} m/s)"


def _color(i):
    return matplotlib.colormaps["tab10"](i % 10)


def _footer(fig, run):
    s = run["summary"]
    solver = s.get("settings", {}).get("solver", {})
    model = s.get("settings", {}).get("model", {})
    if "steps_per_tc" in solver:  # rk4 with the step chosen by an accuracy target
        setting = f"dt = T_c/{solver['steps_per_tc']:g}"
    elif "accuracy" in solver:    # the same, through the module (the step is not returned)
        setting = f"dt for accuracy {solver['accuracy']:g}"
    else:
        setting = f"rtol {solver.get('rtol', '?')}"
    source = run.get("source") or os.path.abspath(run["dir"])
    text = (f"granwave {s.get('version', '?')} falcon; {model.get('material', '?')} beads, "
            f"m = {model.get('mass', float('nan')):.4g} kg; {solver.get('name', '?')} "
            f"{setting}; {source}")
    fig.text(0.005, 0.003, text, fontsize=6, color="0.4", ha="left", va="bottom")
    # keep the axes (and their x label) clear of this footer line
    fig.get_layout_engine().set(rect=(0, 0.025, 1, 0.975))


def _reference_velocity(groups):
    """The group to use for single-velocity figures: v_imp = 0.3 if present, else the first."""
    for g in groups:
        if abs(g[0] - 0.3) < 1e-9:
            return g
    return groups[0]


def fig_fmax(run, groups):
    fig = Figure(figsize=(10.5, 5.5), layout="constrained")
    ax = fig.add_subplot()
    r = run["runs"]
    nmax = np.nanmax(r["n"])
    for i, (v, h, s, m) in enumerate(groups):
        c = _color(i)
        ax.plot(r["n"][m], r["f_max_N"][m], "o-", ms=3.5, lw=1, color=c, label=_label(v, h))
        if s is not None and s.get("f_max_1_theory") is not None:
            ax.axhline(s["f_max_1_theory"], color=c, ls="--", lw=0.9)
    ax.plot([], [], "k--", lw=0.9, label="single bead F_max(1), closed form (F.13)")
    for h_paper in (5.1, 3.1):
        pv = gwdata.paper_value("f_max", h_paper)
        if pv is None:
            continue
        idx = next((i for i, g in enumerate(groups) if g[1] is not None
                    and abs(g[1] - h_paper) < 1e-9), None)
        c = _color(idx) if idx is not None else "k"
        val = pv[0]
        ax.axhspan(val * (1 - PAPER_BAND), val * (1 + PAPER_BAND), color=c, alpha=0.12, lw=0)
        ax.errorbar([nmax + 1.5], [val], yerr=[[val * PAPER_BAND], [val * PAPER_BAND]],
                    fmt="*", ms=11, color=c, mec="k", capsize=4,
                    label=f"paper (exp.) h = {h_paper:g} mm: {val:g} N +- 5 % band")
    ax.set_xlabel("number of beads N")
    ax.set_ylabel("peak wall force F_max (N)")
    ax.set_title("Peak wall force vs column length (rigid wall, no dissipation)")
    ax.set_xlim(0, nmax + 3)
    ax.legend(fontsize=7.5, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.grid(alpha=0.3)
    _footer(fig, run)
    return fig


def fig_taun(run, groups):
    fig = Figure(figsize=(8, 5.5), layout="constrained")
    ax = fig.add_subplot()
    r = run["runs"]
    paper_tq = {h: gwdata.paper_value("t_q", h) for h in (5.1, 2.9)}
    for i, (v, h, s, m) in enumerate(groups):
        c = _color(i)
        n, tau = r["n"][m], r["tau_n_s"][m]
        ax.plot(n, tau * US, "o", ms=3.5, color=c)
        label = _label(v, h)
        if s is not None and s.get("t_q") is not None:
            nn = np.linspace(np.nanmin(n), np.nanmax(n), 2)
            ax.plot(nn, (s["t_q"] * (nn - 1) + s["tau_fit_intercept"]) * US, "-", lw=1, color=c)
            err = s.get("t_q_err")
            label += f": T_q = {s['t_q'] * US:.2f}" + (f" +- {err * US:.2f}" if err else "") + " us"
            tq20 = s.get("t_q_n20")
            if tq20 is not None and np.nanmax(n) > 20 and abs(tq20 - s["t_q"]) > 1e-12:
                label += f" [N <= 20: {tq20 * US:.2f}]"
            pt = paper_tq.get(h) if h is not None else None
            if pt is not None:
                label += f" (paper {pt[0]:g} us)"
        ax.plot([], [], "o-", ms=3.5, lw=1, color=c, label=label)
    ax.set_xlabel("number of beads N")
    ax.set_ylabel("contact duration tau_N (us)")
    ax.set_title("Column-wall contact duration; lines: fit tau_N = T_q (N - 1) + intercept (F.4)")
    ax.legend(fontsize=7.5, loc="upper left")
    ax.grid(alpha=0.3)
    _footer(fig, run)
    return fig


def fig_wall_force(run, groups):
    fig = Figure(figsize=(9, 5), layout="constrained")
    ax = fig.add_subplot()
    for i, (n, t) in enumerate(sorted(run["wall"].items())):
        ax.plot(t["t_s"] * US, t["f_wall_N"], lw=1, color=_color(i), label=f"N = {n}")
    ax.set_xlabel("time since first contact t (us)")
    ax.set_ylabel("wall force F_0 (N)")
    v0 = run["beads7"]["v1_m_s"][0]  # the traces' impact velocity (0.3 m/s by default)
    ax.set_title(f"Force on the wall (sensor) at v_imp = {v0:.3g} m/s")
    ax.legend()
    ax.grid(alpha=0.3)
    _footer(fig, run)
    return fig


def fig_velocities_n7(run, groups):
    b = run["beads7"]
    t = b["t_s"] * US
    nb = sum(1 for k in b if k.startswith("v") and k.endswith("_m_s"))
    fig = Figure(figsize=(9, 5.5), layout="constrained")
    ax = fig.add_subplot()
    cmap = matplotlib.colormaps["viridis"]
    for i in range(1, nb + 1):
        ax.plot(t, b[f"v{i}_m_s"], lw=1, color=cmap((i - 1) / max(1, nb - 1)),
                label=f"bead {i}" + (" (wall)" if i == 1 else " (top)" if i == nb else ""))
    v0 = b["v1_m_s"][0]
    ax.axhline(v0, color="0.5", ls=":", lw=0.8)
    ax.axhline(-v0, color="0.5", ls=":", lw=0.8)
    ax.axhline(0, color="0.7", lw=0.6)
    ax.set_xlabel("time since first contact t (us)")
    ax.set_ylabel("bead velocity v_i (m/s, positive toward the wall)")
    ax.set_title(f"Bead velocities, N = {nb}, v_imp = {v0:.3g} m/s (dotted: +-v_imp)")
    ax.legend(fontsize=8, ncol=2)
    ax.grid(alpha=0.3)
    _footer(fig, run)
    return fig


def fig_erel(run, groups):
    fig = Figure(figsize=(8, 5), layout="constrained")
    ax = fig.add_subplot()
    r = run["runs"]
    markers = "os^dvP*X"
    for i, (v, h, s, m) in enumerate(groups):
        ax.plot(r["n"][m], r["e_rel_over_e_k"][m], markers[i % len(markers)] + "-",
                ms=7 - 0.9 * i, lw=0.8, mfc="none", color=_color(i), label=_label(v, h))
    ax.set_xlabel("number of beads N")
    ax.set_ylabel("E_rel / E_K at tau_N (F.20)")
    ax.set_title("Relative kinetic energy (granular temperature) at the end of the collision\n"
                 "(curves coincide when E_rel/E_K does not depend on v_imp, as for the "
                 "dissipation-free Hertz chain)", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    _footer(fig, run)
    return fig


def fig_final(run, groups):
    fv = run["final"]
    v, h, _, _ = _reference_velocity(groups)
    sel = np.abs(fv["v_imp_m_s"] - v) <= 1e-9 * max(1.0, abs(v))
    ns = sorted(set(int(n) for n in fv["n"][sel]))
    wanted = [n for n in (3, 5, 10, 20, 30, 40) if n in ns] or ns[-4:]
    fig = Figure(figsize=(8, 5.5), layout="constrained")
    ax = fig.add_subplot()
    cmap = matplotlib.colormaps["plasma"]
    for j, n in enumerate(wanted):
        m = sel & (fv["n"] == n)
        order = np.argsort(fv["bead"][m])
        ax.plot(fv["bead"][m][order], -fv["final_v_m_s"][m][order] / v, "o-", ms=3.5, lw=1,
                color=cmap(j / max(1, len(wanted))), label=f"N = {n}")
    ax.axhline(1.0, color="k", ls="--", lw=0.9, label="rebound speed = v_imp")
    ax.set_xlabel("bead index i (1 = bead on the wall)")
    ax.set_ylabel("final rebound speed -v_i^f / v_imp")
    ax.set_title(f"Final velocities, {_label(v, h)}: top beads faster than v_imp, "
                 "bottom ones slower", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    _footer(fig, run)
    return fig


_MAKERS = {"fmax_vs_n": fig_fmax, "taun_vs_n": fig_taun, "wall_force_n7_15_30": fig_wall_force,
           "velocities_n7": fig_velocities_n7, "erel_vs_n": fig_erel,
           "final_velocities": fig_final}


def make_figures(run):
    """{name: matplotlib Figure} for a run from load_run (no backend or pyplot needed)."""
    groups = _velocity_groups(run)
    if not groups:
        raise InputError(f"{run.get('source') or run['dir']}: no runs")
    return {name: _MAKERS[name](run, groups) for name in FIGURES}


def write_figures(d, quiet=False, run=None):
    """Load DIR d (or take run, e.g. from run_from_module), write DIR/figures/*.png;
    returns the list of paths. Raises InputError."""
    if run is None:
        run = load_run(d)
    for note in run["notes"]:
        print(f"plot_falcon.py: note: {note}", file=sys.stderr)
    figs = make_figures(run)
    outdir = os.path.join(d, "figures")
    try:
        os.makedirs(outdir, exist_ok=True)
    except OSError as e:
        raise InputError(f"cannot create {outdir}: {e}")
    meta = {"Software": f"granwave {run['summary'].get('version', '?')} + plot_falcon.py",
            "Description": json.dumps(run["summary"].get("settings", {}), sort_keys=True),
            "Source": run.get("source") or os.path.abspath(d)}
    return gwdata.save_pngs(figs, outdir, 120, meta, quiet)


USAGE = ("usage: plot_falcon.py DIR                    (DIR = granwave falcon --out DIR)\n"
         "       plot_falcon.py --module DIR [--n A:B]   (the study through the Python module)")


def _parse_n(text):
    try:
        a, b = (int(x) for x in text.split(":"))
    except ValueError:
        raise InputError(f"--n {text}: expected A:B (integers)")
    if not 1 <= a <= 7 <= b:
        raise InputError(f"--n {text}: the figures need 1 <= A <= 7 <= B")
    return a, b


def main(argv):
    matplotlib.use("Agg")
    args = argv[1:]
    if args in (["-h"], ["--help"]):
        print(USAGE)
        return 0
    try:
        if args and args[0] == "--module":
            if len(args) not in (2, 4) or (len(args) == 4 and args[2] != "--n"):
                print(USAGE, file=sys.stderr)
                return 2
            n = _parse_n(args[3]) if len(args) == 4 else (1, 40)   # granwave falcon's default
            write_figures(args[1], run=run_from_module(n=n))
            return 0
        if len(args) != 1:
            print(USAGE, file=sys.stderr)
            return 2
        write_figures(args[0])
    except InputError as e:
        print(f"plot_falcon.py: error: {e}", file=sys.stderr)
        return 2
    except OutputError as e:
        print(f"plot_falcon.py: error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(gwdata.run_main(main, sys.argv))
