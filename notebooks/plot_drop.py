#!/usr/bin/python3
"""plot_drop.py DIR [--run] [--quick]: the whole drop (`granwave drop`) beside the paper's Fig. 12.

The cases (each a `granwave drop --out DIR/<case>` run; steel beads R = 4 mm on a steel
sensor, Kuwabara-Kono damping calibrated so that one bead hitting the sensor at v_imp
rebounds with e = 0.9, CVODE at rtol = atol = 1e-12):
  column_h5.1_10ms    N = 40, h = 5.1 mm, 10 ms (the paper's Fig. 12 window)
  column_h1.9_10ms    N = 40, h = 1.9 mm, 10 ms
  column_h5.1_100ms   N = 40, h = 5.1 mm, 100 ms (about 9 s of CPU, 3/4 of --run)
  bead_h5.1_300ms     one bead, h = 5.1 mm, 300 ms
  block_h5.1_300ms    one rigid block of 40 bead masses (--block), h = 5.1 mm, 300 ms
Read from each: drop.json (impacts, peaks, first collision, settings) and
drop_wall_force.csv (the sensor signal). With --run the program makes them first (found
as $GRANWAVE, ../build/granwave or build/granwave); only the files the figures use are
kept (drop_beads.csv and drop.h5 are removed, and drop_wall_force.csv of the cases whose
signal is not drawn: their impacts and peaks are in drop.json, drop_impacts.csv and
drop_peaks.csv). --quick leaves out column_h5.1_100ms.

The paper's trace of Fig. 12 is not digitized in data/falcon1998, and physics.md states
neither its N nor its h; the figures draw beside the model the numbers the paper reports
for these columns (data/falcon1998/rigid_wall.csv: F_max = 69 N +- 5 % at h = 5.1 mm,
collision time 1.04 ms for N = 40 at h = 5.1 mm).

Writes DIR/figures/drop_signal.png (the sensor signal over 10 ms) and
DIR/figures/drop_impacts.png (every impact's peak force against time: the column against a
single bead and a rigid block). Exit status: 0 ok, 2 on a missing or malformed input (a
file that is not a regular file, a key or the signal's rows missing), 1 if a run of the
program fails or a figure cannot be written.
Use Debian's /usr/bin/python3. notebooks/experiment.ipynb uses run_cases_module (the same
cases through the Python module's granwave.drop, in memory: the keys of drop.json that
the figures read, and the signal) and make_figures.
"""

import json
import os
import sys

import numpy as np
import matplotlib
from matplotlib.figure import Figure

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gwdata  # noqa: E402

MS = 1e3  # s -> ms
DAMPING = ["--damping", "kk", "--restitution", "0.9"]
CASES = {
    "column_h5.1_10ms": ["--n", 40, "--height", 5.1e-3, "--t-max", 10e-3, "--dt-out", 5e-6],
    "column_h1.9_10ms": ["--n", 40, "--height", 1.9e-3, "--t-max", 10e-3, "--dt-out", 5e-6],
    "column_h5.1_100ms": ["--n", 40, "--height", 5.1e-3, "--t-max", 0.1, "--dt-out", 2e-5],
    "bead_h5.1_300ms": ["--n", 1, "--height", 5.1e-3, "--t-max", 0.3, "--dt-out", 1e-4],
    "block_h5.1_300ms": ["--n", 40, "--block", "--height", 5.1e-3, "--t-max", 0.3,
                         "--dt-out", 1e-4],
}
SLOW = {"column_h5.1_100ms"}
SIGNAL = {"column_h5.1_10ms", "column_h1.9_10ms"}  # the cases whose signal is drawn
PAPER_BAND = 0.05  # "independent of N within 5 %" (physics.md 1.7)


InputError = gwdata.InputError    # exit 2
OutputError = gwdata.OutputError  # exit 1


def run_cases(d, names=None, program=None):
    """Run `granwave drop` for each case name (default: all) into d/<name>."""
    os.makedirs(d, exist_ok=True)
    for name in names or CASES:
        out = os.path.join(d, name)
        gwdata.run_granwave(["drop", *CASES[name], *DAMPING, "--out", out], json=True,
                            program=program)
        unused = ["drop_beads.csv", "drop.h5"] + ([] if name in SIGNAL else ["drop_wall_force.csv"])
        for f in unused:
            p = os.path.join(out, f)
            if os.path.isfile(p):
                os.remove(p)


def _kwargs(args):
    """A case's program options (CASES, DAMPING) as granwave.drop keywords."""
    kw, it = {}, iter(args)
    for flag in it:
        key = flag[2:].replace("-", "_")
        if key == "block":  # the one flag without a value
            kw[key] = True
            continue
        kw[key] = next(it)
    return kw


def _none(v):
    """NaN -> None, numpy scalars -> Python numbers (the program's JSON)."""
    if isinstance(v, dict):
        return {k: _none(x) for k, x in v.items()}
    if isinstance(v, (list, tuple, np.ndarray)):
        return [_none(x) for x in v]
    if isinstance(v, (np.bool_, bool)):
        return bool(v)
    if isinstance(v, (np.integer, int)):
        return int(v)
    if isinstance(v, (np.floating, float)):
        return None if v != v else float(v)
    return v


def case_from_module(name, gw=None):
    """Case name run through the Python module (granwave.drop, the library's drop:
    the program's numbers): {"json": the keys of drop.json the figures and tables
    read, "t": s, "f": N (the sensor signal, every case)}. In memory, no files."""
    gw = gw or gwdata.import_granwave()
    kw = _kwargs([*CASES[name], *DAMPING])
    r = gw.drop(**kw)
    defaults = {p["keyword"]: p["default"] for p in gw.params("drop")}
    # the solver rows have no table default (not given: cvode, its default
    # method, rtol = atol = 1e-12, as docs/library.md says); the program's
    # drop.json records those values
    defaults.update({k: v for k, v in (("solver", "cvode"), ("method", "default"), ("rtol", 1e-12),
                                       ("atol", 1e-12)) if defaults.get(k) is None})
    im = r["impacts"]
    impacts = [{c: im[c][i] for c in im} for i in range(len(im["f_max"]))]
    wp = r["wall_peaks"]
    peaks = [{"t": wp["t"][i], "f": wp["f"][i], "impact": r["peak_impact"][i], "cluster": r["peak_cluster"][i],
              "contacts": "".join(str(int(c)) for c in r["peak_contacts"][i])} for i in range(len(wp["t"]))]
    js = {k: r[k] for k in ("n", "block", "height", "v_imp", "t_fall", "t_max", "peak_threshold", "n_impacts",
                            "n_contact_episodes", "n_peaks", "f_max", "t_fmax", "impact_rises",
                            "impacts_monotone", "energy_error", "t_end")}
    js.update(version=gw.version(), command="drop", solver=kw.get("solver", defaults["solver"]),
              impacts=impacts, wall_peaks=peaks, first_collision=r["first_collision"], energy=r["energy"])
    js["settings"] = {
        "version": gw.version(),
        "model": {"material": kw.get("material", defaults["material"]),
                  "wall_material": kw.get("wall_material", defaults["wall_material"]),
                  "radius": r["radius"], "mass": r["mass"], "k": r["k"], "kwall": r["kwall"],
                  "gravity": r["gravity"], "damping": kw.get("damping", defaults["damping"]),
                  "gamma": r["gamma"], "alpha": r["alpha"], "restitution_target": float(kw["restitution"]) if "restitution" in kw else None,
                  "restitution_v": kw.get("restitution_v", r["v_imp"])},
        "solver": {"name": kw.get("solver", defaults["solver"]), "method": kw.get("method", defaults["method"]),
                   "rtol": float(kw.get("rtol", defaults["rtol"])), "atol": float(kw.get("atol", defaults["atol"]))},
        "drop": {"n_column": r["n_column"], "block": r["block"], "height": r["height"], "gravity": r["gravity"],
                 "t_max": r["t_max"], "dt_out": r["dt_out"], "peak_threshold": r["peak_threshold"]}}
    return {"name": name, "json": _none(js), "t": np.asarray(r["t"]), "f": np.asarray(r["f_wall"])}


def run_cases_module(names=None, gw=None):
    """{name: case_from_module(name)} for the case names (default: all)."""
    return {n: case_from_module(n, gw) for n in names or CASES}


def load_case(d, name):
    """{"json": drop.json, "t": s, "f": N} of case directory d/name. Raises InputError."""
    base = os.path.join(d, name)
    path = os.path.join(base, "drop.json")
    try:
        js = gwdata.load_json(path)
    except FileNotFoundError:
        raise InputError(f"missing file {path} (make it with: plot_drop.py {d} --run)")
    except (OSError, ValueError) as e:
        raise InputError(gwdata.read_error(path, e))
    for key, kind in (("impacts", list), ("wall_peaks", list), ("first_collision", dict),
                      ("settings", dict), ("n_impacts", int)):
        if key not in js:
            raise InputError(f"{path}: missing key '{key}'")
        if not isinstance(js[key], kind):
            raise InputError(f"{path}: '{key}' is not {'a list' if kind is list else 'an object' if kind is dict else 'an integer'}")
    if not js["impacts"] or not all(isinstance(i, dict) and all(isinstance(i.get(k), (int, float))
                                                                for k in ("t_fmax", "f_max"))
                                    for i in js["impacts"]):
        raise InputError(f"{path}: 'impacts' is empty or an impact has no t_fmax, f_max")
    if not all(isinstance(js["settings"].get(k), dict) for k in ("model", "solver")):
        raise InputError(f"{path}: 'settings' has no 'model' or 'solver' object")
    sig = os.path.join(base, "drop_wall_force.csv")
    if name not in SIGNAL and not os.path.isfile(sig):
        return {"name": name, "json": js, "t": None, "f": None}
    try:
        t = gwdata.load_csv(sig)
        ts, fs = np.asarray(t["t_s"], float), np.asarray(t["f_wall_N"], float)
    except FileNotFoundError:
        raise InputError(f"missing file {sig}")
    except KeyError as e:
        raise InputError(f"{sig}: missing column {e}")
    except (ValueError, TypeError, OSError) as e:
        raise InputError(gwdata.read_error(sig, e))
    if len(ts) == 0:
        raise InputError(f"{sig}: no rows (a run cut short?)")
    return {"name": name, "json": js, "t": ts, "f": fs}


def load_cases(d, names=None):
    """{name: case} for the case names (default: every case present, at least the 10 ms ones)."""
    if not os.path.isdir(d):
        raise InputError(f"no such directory {d} (make it with: plot_drop.py {d} --run)")
    if names is None:
        names = [n for n in CASES if n not in SLOW or os.path.isdir(os.path.join(d, n))]
    return {n: load_case(d, n) for n in names}


def _footer(fig, case):
    js = case["json"]
    s = js["settings"]
    m, sv = s["model"], s["solver"]
    text = (f"granwave {js.get('version', '?')} drop; {m['material']} beads R = {m['radius'] * 1e3:g} mm, "
            f"m = {m['mass']:.4g} kg, damping {m['damping']} (e = {m['restitution_target']:g} at "
            f"{m['restitution_v']:.3f} m/s), g = {m['gravity']:g}; {sv['name']} rtol {sv['rtol']:g}")
    fig.text(0.005, 0.003, text, fontsize=6, color="0.4", ha="left", va="bottom")
    fig.get_layout_engine().set(rect=(0, 0.025, 1, 0.975))


def _impact_marks(ax, js, color):
    im = js["impacts"]
    ax.plot([i["t_fmax"] * MS for i in im], [i["f_max"] for i in im], "v", ms=5, color=color,
            mec="k", mew=0.4, zorder=3, label=f"impacts ({len(im)}): largest located peak")


def fig_signal(cases):
    """The sensor signal: first collision (linear), then 10 ms (log force) at two heights."""
    a, b = cases["column_h5.1_10ms"], cases["column_h1.9_10ms"]
    fig = Figure(figsize=(11, 8.5), layout="constrained")
    axs = fig.subplot_mosaic([["first", "first"], ["h51", "h19"]], height_ratios=[1, 1.3])
    ax = axs["first"]
    js = a["json"]
    fc = js["first_collision"]
    m = a["t"] <= 1.3e-3
    ax.plot(a["t"][m] * MS, a["f"][m], "-", lw=0.8, color="C0",
            label=f"granwave drop, N = {js['n']}, h = {js['height'] * 1e3:g} mm")
    pf = gwdata.paper_value("f_max", 5.1)
    if pf is not None:
        ax.axhspan(pf[0] * (1 - PAPER_BAND), pf[0] * (1 + PAPER_BAND), color="C3", alpha=0.15, lw=0,
                   label=f"paper (exp.), h = 5.1 mm: F_max = {pf[0]:g} N +- 5 % (any N)")
    ct = gwdata.paper_value("collision_time", 5.1, unit="ms")
    if ct is not None:
        ax.axvline(ct[0], color="C3", ls="--", lw=1,
                   label=f"paper (exp.): collision time {ct[0]:g} ms (N = 40, h = 5.1 mm)")
    ax.axvline(fc["tau_n"] * MS, color="C0", ls=":", lw=1,
               label=f"model: tau_N = {fc['tau_n'] * MS:.3f} ms, F_max = {fc['f_max']:.1f} N")
    ax.set_xlim(0, 1.3)
    ax.set_xlabel("time after the first contact (ms)")
    ax.set_ylabel("sensor force (N)")
    ax.set_title("First collision of the dropped column (zoom of the left panel below)")
    ax.legend(fontsize=7.5, loc="upper right")
    ax.grid(alpha=0.3)
    for key, c, color in (("h51", a, "C0"), ("h19", b, "C2")):
        ax = axs[key]
        js = c["json"]
        pos = c["f"] > 0
        ax.semilogy(c["t"][pos] * MS, c["f"][pos], ".", ms=1.2, color=color)
        ax.plot([], [], ".", color=color, label="sensor signal (zero in flight, not drawn)")
        _impact_marks(ax, js, "C1")
        ax.axhline(js["peak_threshold"], color="0.5", lw=0.8, ls=":",
                   label=f"peak threshold {js['peak_threshold']:.2f} N")
        ax.set_ylim(0.3, 120)
        ax.set_xlim(-0.2, js["t_max"] * MS + 0.2)
        ax.set_xlabel("time after the first contact (ms)")
        ax.set_ylabel("sensor force (N)")
        ax.set_title(f"N = {js['n']}, h = {js['height'] * 1e3:g} mm: {js['n_impacts']} impacts, "
                     f"{js['impact_rises']} above the one before", fontsize=10)
        ax.legend(fontsize=7, loc="upper right")
        ax.grid(alpha=0.3, which="both")
    fig.suptitle("granwave drop beside the paper's Fig. 12 (trace not digitized: the paper's "
                 "reported numbers are drawn)", fontsize=10)
    _footer(fig, a)
    return fig


def fig_impacts(cases):
    """Every impact's peak force against time: the column, a bead and a rigid block."""
    fig = Figure(figsize=(10, 5.5), layout="constrained")
    ax = fig.add_subplot()
    col = cases.get("column_h5.1_100ms") or cases["column_h5.1_10ms"]
    series = [(col, "C0", "o-", "column N = 40"),
              (cases["bead_h5.1_300ms"], "C1", "s-", "single bead"),
              (cases["block_h5.1_300ms"], "C2", "D-", "rigid block of 40 bead masses")]
    for c, color, style, label in series:
        js = c["json"]
        im = js["impacts"]
        f0 = im[0]["f_max"]
        ax.semilogy([i["t_fmax"] * MS for i in im], [i["f_max"] / f0 for i in im], style,
                    ms=3.5, lw=0.7, color=color,
                    label=f"{label}: {len(im)} impacts in {js['t_max'] * MS:g} ms, first "
                          f"{f0:.1f} N, {js['impact_rises']} above the one before")
    ax.axvline(10, color="0.5", ls=":", lw=1, label="10 ms (the paper's Fig. 12 window)")
    ax.set_xlabel("time after the first contact (ms)")
    ax.set_ylabel("impact peak force / first impact's")
    ax.set_title("h = 5.1 mm, same contact law and damping constant: the column does not bounce "
                 "as one block", fontsize=10)
    ax.legend(fontsize=7.5, loc="lower right")
    ax.grid(alpha=0.3, which="both")
    _footer(fig, col)
    return fig


def make_figures(cases):
    """{name: matplotlib Figure} from load_cases (no backend or pyplot needed)."""
    return {"drop_signal": fig_signal(cases), "drop_impacts": fig_impacts(cases)}


def write_figures(d, quiet=False):
    cases = load_cases(d)
    outdir = os.path.join(d, "figures")
    try:
        os.makedirs(outdir, exist_ok=True)
    except OSError as e:
        raise OutputError(f"cannot create {outdir}: {e.strerror or e}")
    first = cases["column_h5.1_10ms"]["json"]
    meta = {"Software": f"granwave {first.get('version', '?')} + plot_drop.py",
            "Description": json.dumps({n: c["json"]["settings"] for n, c in cases.items()},
                                      sort_keys=True),
            "Source": os.path.abspath(d)}
    return gwdata.save_pngs(make_figures(cases), outdir, 110, meta, quiet)


def main(argv):
    matplotlib.use("Agg")
    args = [a for a in argv[1:] if not a.startswith("--")]
    flags = [a for a in argv[1:] if a.startswith("--")]
    if "--help" in flags or "-h" in argv[1:]:
        print(__doc__)
        return 0
    bad = [f for f in flags if f not in ("--run", "--quick")]
    if len(args) != 1 or bad:
        print("usage: plot_drop.py DIR [--run] [--quick]"
              + (f"  (unknown: {' '.join(bad)})" if bad else ""), file=sys.stderr)
        return 2
    d = args[0]
    try:
        if "--run" in flags:
            names = [n for n in CASES if "--quick" not in flags or n not in SLOW]
            run_cases(d, names)
        write_figures(d)
    except InputError as e:
        print(f"plot_drop.py: error: {e}", file=sys.stderr)
        return 2
    except (gwdata.GranwaveError, OutputError) as e:
        print(f"plot_drop.py: error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(gwdata.run_main(main, sys.argv))
