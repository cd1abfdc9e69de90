#!/usr/bin/python3
"""plot_sheets.py [DATA_DIR [OUT_DIR]]: the sheets of Falcon et al.'s Table 2 from their
material constants, and the decaying-plateau study (issue 19, parts 2-3).

DATA_DIR (default data/measured/sheets) holds what the program wrote; nothing is
recomputed here but unit conversions, plateau window means and straight-line fits:
  softwall_<law>_tol<T>.json   `granwave softwall --sheets --sheet-law <law> --tol <T/100>
                               [--sensor-...] --json` (law: fitted, hertz, layer, material,
                               material_sensor); the "sheets" list: model against measured
  plateau/<case>/falcon_runs.csv, plateau/<case>/trace_n30_wall_force.csv
                               `granwave falcon --vimp 0.316 --heights none --n 1:40 ...`
                               for each mechanism of the plateau study (CASES below)
and data/falcon1998/soft_walls_table2.csv for the measured values.

Functions used by notebooks/experiment.ipynb:
  load_softwall(data_dir, law, tol)   JSON of one softwall run (None if absent)
  sheets_rows(sw)                     per sheet: model and measured N_d and tau_max
  sheets_markdown(data_dir, tol)      the tables of docs/sheets.md (every law)
  brass_markdown(data_dir, tol)       brass under Thornton for three yield stresses
  fig_sheets(data_dir, tol)           N_d and tau_max(1), model against measured
  fig_fmax_n(sw)                      F_max(N) of every sheet for one law
  load_plateau(data_dir)              {case: {"runs": ..., "trace": ...}}
  plateau_stats(case)                 decay of the windowed mean force, eps_eff(N) slope
  plateau_markdown(data_dir)          the plateau table of docs/sheets.md
  fig_plateau(data_dir)               wall force of N = 30 and eps_eff(N) per mechanism
  write_figures(data_dir, out_dir)    all PNGs (what main() does)

Exit status: 0 ok, 2 if DATA_DIR or a required file is missing. Headless (Agg); use
Debian's /usr/bin/python3.
"""

import json
import os
import sys

import numpy as np
import matplotlib
from matplotlib.figure import Figure

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import gwdata  # noqa: E402

US = 1e6
DEFAULT_DATA = os.path.normpath(os.path.join(HERE, "..", "data", "measured", "sheets"))
LAWS = ["fitted", "hertz", "layer", "material", "material_sensor"]
LAW_LABELS = {"fitted": "fitted K_eff (Hertz)", "hertz": "Hertz half-space",
              "layer": "bonded layer", "material": "layer + loss / plastic",
              "material_sensor": "material + sensor body"}
# the plateau study: mechanism -> (label, extra program options)
CASES = {
    "elastic": ("elastic Hertz (reference)", []),
    "damping": ("contact damping, e = 0.9", ["--damping", "hc", "--restitution", "0.9"]),
    "sensor": ("sensor body 3 g on 2e9 N/m", ["--sensor-mass", "3e-3", "--sensor-stiffness", "2e9"]),
    "sensor_visco": ("sensor body, 50 % critical damping",
                     ["--sensor-mass", "3e-3", "--sensor-stiffness", "2e9", "--sensor-damping", "2449"]),
    "guide_0.005": ("guide friction 0.005 N", ["--guide-friction", "0.005"]),
    "guide_0.05": ("guide friction 0.05 N", ["--guide-friction", "0.05"]),
    "pmma": ("PMMA sheet, tan delta 0.06", ["--sheet", "pmma", "--sheet-law", "material"]),
}
PLATEAU_BASE = ["falcon", "--vimp", "0.316", "--heights", "none", "--n", "1:40", "--solver", "arkode",
                "--method", "erk", "--rtol", "1e-10", "--atol", "1e-10", "--dt-out", "1e-6", "--quiet",
                "--jobs", "2"]
WINDOW = 50e-6   # plateau window (about two wall-force periods), s


class InputError(Exception):
    """A missing or malformed input; main() prints it and exits with 2."""


# ---- sheets ----

def load_softwall(data_dir, law, tol):
    path = os.path.join(data_dir, f"softwall_{law}_tol{int(round(tol * 100)):02d}.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def sheets_rows(sw):
    """Per sheet: name, N_d model / measured (+-), tau_max(1) and tau_max(N_d) in us."""
    rows = []
    for e in sw["sheets"]:
        rows.append({
            "name": e["name"],
            "n_d_model": e["n_d_model"], "n_d_measured": e["n_d_measured"],
            "n_d_err": e["n_d_measured_err"],
            "tau1_model": e["tau_max_1_model"] * US if e["tau_max_1_model"] is not None else np.nan,
            "tau1_measured": e["tau_max_1_measured"] * US,
            "taund_model": e["tau_max_nd_model"] * US if e["tau_max_nd_model"] is not None else np.nan,
            "taund_measured": e["tau_max_nd_measured"] * US,
            "taund_err": (e["tau_max_nd_measured_err"] or 0) * US,
            "f_plateau": e["f_plateau_model"], "f1": e.get("f_max_1_model"),
            "eps1": e.get("eps_eff_1_model"), "a_over_h": e.get("a_over_h_1"),
        })
    return rows


def _by_tol(e, tol):
    for b in e["n_d_model_by_tol"]:
        if abs(b["tol"] - tol) < 1e-9:
            return b["n_d"]
    return None


def _fmt_nd(e):
    f = lambda x: "-" if x is None else f"{x:.0f}"
    return f"{f(_by_tol(e, 0.05))} / {f(_by_tol(e, 0.10))}"


def sheets_markdown(data_dir, tol=0.05):
    """Three tables: N_d (plateau within 5 % / 10 %), tau_max(1), and the tolerance-free
    comparison at the measured N_d. tol selects the files (softwall_<law>_tol<tol>.json)."""
    runs = {law: load_softwall(data_dir, law, tol) for law in LAWS}
    runs = {k: v for k, v in runs.items() if v}
    if "fitted" not in runs:
        raise InputError(f"no softwall_fitted_tol{int(round(tol * 100)):02d}.json in {data_dir}")
    names = [e["name"] for e in runs["fitted"]["sheets"]]
    entry = {law: {e["name"]: e for e in sw["sheets"]} for law, sw in runs.items()}
    meas = {e["name"]: e for e in runs["fitted"]["sheets"]}
    laws = [l for l in LAWS if l in runs]
    nmax = runs["fitted"]["n"][-1]
    out = [f"N_d of the model as the first N from which F_max stays within 5 % / 10 % of "
           f"F_max({nmax}) (\"-\": not saturated by N = {nmax}):", "",
           "| sheet | measured | " + " | ".join(LAW_LABELS[l] for l in laws) + " |",
           "|---|---|" + "---|" * len(laws)]
    for n in names:
        m = meas[n]
        ms = f"{m['n_d_measured']:g}" + (f" +- {m['n_d_measured_err']:g}" if m["n_d_measured_err"] else "")
        out.append(f"| {n} | {ms} | " + " | ".join(_fmt_nd(entry[l][n]) if n in entry[l] else "" for l in laws) + " |")
    out += ["", "tau_max(N = 1), us:", "",
            "| sheet | measured | " + " | ".join(LAW_LABELS[l] for l in laws) + " |",
            "|---|---|" + "---|" * len(laws)]
    for n in names:
        out.append(f"| {n} | {meas[n]['tau_max_1_measured'] * US:.1f} | " +
                   " | ".join(f"{entry[l][n]['tau_max_1_model'] * US:.1f}" if n in entry[l] else "" for l in laws) + " |")
    out += ["", "At the measured N_d: the model's tau_max there (us) against the measured tau_max(N_d), and the "
            "model's F_max there as a fraction of its plateau:", "",
            "| sheet | measured tau_max(N_d) | " + " | ".join(f"{LAW_LABELS[l]}: tau_max, F/F_plateau" for l in laws) + " |",
            "|---|---|" + "---|" * len(laws)]
    for n in names:
        m = meas[n]
        ms = f"{m['tau_max_nd_measured'] * US:.0f}" + (f" +- {m['tau_max_nd_measured_err'] * US:.0f}"
                                                        if m["tau_max_nd_measured_err"] else "")
        cells = []
        for l in laws:
            e = entry[l].get(n)
            if not e or e["tau_max_at_measured_nd_model"] is None:
                cells.append("")
                continue
            cells.append(f"{e['tau_max_at_measured_nd_model'] * US:.0f}, {e['f_max_at_measured_nd_over_plateau']:.2f}")
        out.append(f"| {n} | {ms} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def brass_markdown(data_dir, tol=0.05):
    """Brass under the Thornton law for three yield stresses."""
    rows = ["| yield stress Y (p_y = 2.8 Y) | tau_max(1) (us) | e (one bead) | N_d (5 % / 10 %) | "
            "tau_max at N = 2 (us) |", "|---|---|---|---|---|"]
    for tag, y in (("brass_y100", 100), ("material", 200), ("brass_y350", 350)):
        sw = load_softwall(data_dir, tag, tol)
        if not sw:
            continue
        e = next(x for x in sw["sheets"] if x["name"] == "brass")
        rows.append(f"| {y} MPa | {e['tau_max_1_model'] * US:.1f} | {e['eps_eff_1_model']:.3f} | {_fmt_nd(e)} | "
                    f"{e['tau_max_at_measured_nd_model'] * US:.1f} |")
    rows.append("| measured | 47.5 | | 2 | 46 |")
    return "\n".join(rows)


def _footer(fig, text):
    fig.text(0.01, 0.005, text, fontsize=6, color="0.4")


def fig_sheets(data_dir, tol, nd_tol=None):
    """N_d (plateau within nd_tol, default tol, read from n_d_model_by_tol) and
    tau_max(1) per sheet and law, against Table 2; files softwall_<law>_tol<tol>.json."""
    nd_tol = tol if nd_tol is None else nd_tol
    fig = Figure(figsize=(11, 4.4))
    ax1, ax2 = fig.subplots(1, 2)
    markers = dict(zip(LAWS, "sovD^"))
    any_run = False
    for j, law in enumerate(LAWS):
        sw = load_softwall(data_dir, law, tol)
        if not sw:
            continue
        any_run = True
        rows = sheets_rows(sw)
        x = np.arange(len(rows)) + (j - 2) * 0.12
        nd = np.array([np.nan if _by_tol(e, nd_tol) is None else _by_tol(e, nd_tol) for e in sw["sheets"]])
        nmax = sw["n"][-1]
        sat = ~np.isnan(nd)
        ax1.plot(x[sat], nd[sat], markers[law], ms=5, label=LAW_LABELS[law])
        ax1.plot(x[~sat], np.full((~sat).sum(), nmax), markers[law], ms=5, mfc="none", color=f"C{j}")
        ax2.plot(x, [r["tau1_model"] for r in rows], markers[law], ms=5, label=LAW_LABELS[law])
    if not any_run:
        raise InputError(f"no softwall_<law>_tol{int(round(tol * 100)):02d}.json in {data_dir}")
    rows = sheets_rows(next(load_softwall(data_dir, law, tol) for law in LAWS if load_softwall(data_dir, law, tol)))
    x = np.arange(len(rows))
    ax1.errorbar(x, [r["n_d_measured"] for r in rows], yerr=[r["n_d_err"] for r in rows], fmt="k_",
                 ms=14, capsize=3, label="measured (Table 2)")
    ax2.plot(x, [r["tau1_measured"] for r in rows], "k_", ms=14, label="measured (Table 2)")
    for ax in (ax1, ax2):
        ax.set_xticks(x)
        ax.set_xticklabels([r["name"] for r in rows], rotation=40, fontsize=8)
    ax1.set_yscale("log")
    ax1.set_ylabel("N_d (open: not saturated at n_max)")
    ax1.set_title(f"saturation number, F_max within {100 * nd_tol:g} % of its plateau", fontsize=9)
    ax2.set_yscale("log")
    ax2.set_ylabel("tau_max(N = 1) (us)")
    ax2.set_title("single-bead time of the peak force", fontsize=9)
    ax1.legend(fontsize=7)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    _footer(fig, "granwave softwall --sheets --sheet-law LAW (h = 2.9 mm); measured: Falcon et al. 1998, Table 2")
    return fig


def fig_fmax_n(sw, title=""):
    fig = Figure(figsize=(6.5, 4.4))
    ax = fig.subplots()
    n = np.array(sw["n"])
    for i, w in enumerate(sw["walls"]):
        f = np.array([np.nan if v is None else v for v in w["f_max"]])
        ax.plot(n, f, "-o", ms=2.5, color=f"C{i % 10}", label=w["sheet"])
        e = sw["sheets"][i]
        if e["n_d_model"] is not None:
            ax.plot(e["n_d_model"], f[int(e["n_d_model"]) - n[0]], "k|", ms=12)
    ax.set_xlabel("N")
    ax.set_ylabel("F_max (N)")
    ax.set_title(title or f"F_max(N), sheet law {sw.get('sheet_law', '?')} (|: model N_d)", fontsize=9)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    _footer(fig, f"granwave {sw['version']} softwall, tol {sw['tol']:g}")
    return fig


# ---- plateau ----

def load_plateau(data_dir):
    out = {}
    for case in CASES:
        d = os.path.join(data_dir, "plateau", case)
        runs_p, tr_p = os.path.join(d, "falcon_runs.csv"), os.path.join(d, "trace_n30_wall_force.csv")
        if not (os.path.exists(runs_p) and os.path.exists(tr_p)):
            continue
        out[case] = {"runs": gwdata.load_csv(runs_p), "trace": gwdata.load_csv(tr_p)}
    return out


def _trace_arrays(tr):
    t = np.asarray(tr[next(k for k in tr if k.startswith("t"))], float)
    f = np.asarray(tr[next(k for k in tr if k.startswith("f"))], float)
    return t, f


PLATEAU_START = 0.15e-3  # s: after the first peaks (the single-bead transient)
PLATEAU_END = 0.7        # of tau_N(30): before the release wave from the top reaches the wall


def plateau_stats(c):
    """Windowed (50 us) mean wall force of N = 30 over [0.15 ms, 0.7 tau_N] (the plateau:
    the release from the top arrives at about 0.78 tau_N) and its straight-line slope
    (relative change per ms), with the eps_eff(N) slope over N = 1..40."""
    t, f = _trace_arrays(c["trace"])
    runs = c["runs"]
    n = np.asarray(runs["n"], float)
    tau_n = float(np.asarray(runs["tau_n_s"])[n == 30][0])
    edges = np.arange(PLATEAU_START, PLATEAU_END * tau_n - WINDOW + 1e-12, WINDOW)
    tm, fm = [], []
    for a in edges:
        sel = (t >= a) & (t < a + WINDOW)
        if sel.sum() < 3:
            continue
        ts, fs = t[sel], f[sel]
        fm.append(np.trapz(fs, ts) / (ts[-1] - ts[0]))
        tm.append(0.5 * (ts[0] + ts[-1]))
    tm, fm = np.array(tm), np.array(fm)
    slope, icpt = np.polyfit(tm, fm, 1) if len(tm) >= 2 else (np.nan, np.nan)
    eps = np.asarray(runs["eps_eff"], float)
    es = np.polyfit(n, eps, 1)[0]
    return {"t": tm, "f_mean": fm, "f0": icpt + slope * tm[0] if len(tm) else np.nan,
            "decay_per_ms": slope * 1e-3 / np.mean(fm) if len(fm) else np.nan,
            "eps1": eps[n == 1][0], "eps40": eps[n == n.max()][0], "eps_slope": es, "tau_n30": tau_n}


def plateau_markdown(data_dir):
    p = load_plateau(data_dir)
    lines = ["| mechanism | mean force N = 30 (N) | change of the mean per ms | eps_eff(1) | eps_eff(40) | "
             "d eps_eff / dN |", "|---|---|---|---|---|---|"]
    for case, c in p.items():
        s = plateau_stats(c)
        lines.append(f"| {CASES[case][0]} | {np.mean(s['f_mean']):.2f} | {100 * s['decay_per_ms']:+.2f} % | "
                     f"{s['eps1']:.4f} | {s['eps40']:.4f} | {s['eps_slope']:+.2e} |")
    return "\n".join(lines)


def fig_plateau(data_dir):
    p = load_plateau(data_dir)
    if not p:
        raise InputError(f"no plateau/<case> runs in {data_dir}")
    fig = Figure(figsize=(11, 4.4))
    ax1, ax2 = fig.subplots(1, 2)
    for i, (case, c) in enumerate(p.items()):
        s = plateau_stats(c)
        t, f = _trace_arrays(c["trace"])
        col = f"C{i % 10}"
        ax1.plot(t * 1e3, f, color=col, lw=0.4, alpha=0.35)
        ax1.plot(s["t"] * 1e3, s["f_mean"], "-o", ms=3, color=col, label=CASES[case][0])
        runs = c["runs"]
        ax2.plot(runs["n"], runs["eps_eff"], "-o", ms=2.5, color=col, label=CASES[case][0])
    ax1.set_xlim(0, 1.2)
    ax1.set_xlabel("t (ms)")
    ax1.set_ylabel("wall force read, N = 30 (N); dots: 50 us means")
    ax1.set_title("plateau of the wall force (cf. the paper's Fig. 4d), h = 5.1 mm", fontsize=9)
    ax2.set_xlabel("N")
    ax2.set_ylabel("eps_eff")
    ax2.set_title("effective restitution (cf. the paper's Fig. 11)", fontsize=9)
    ax1.legend(fontsize=6)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    _footer(fig, "granwave " + " ".join(PLATEAU_BASE) + " [mechanism options]")
    return fig


def run_study(out_dir, granwave=None):
    """Re-run the plateau cases into out_dir/plateau/<case> (several minutes)."""
    gw = granwave or gwdata.find_granwave()
    import subprocess
    for case, (_, extra) in CASES.items():
        d = os.path.join(out_dir, "plateau", case)
        subprocess.run([gw] + PLATEAU_BASE + extra + ["--out", d], check=True)


def write_figures(data_dir, out_dir, quiet=False):
    os.makedirs(out_dir, exist_ok=True)
    figs = {"sheets_nd_tau1_tol05": lambda: fig_sheets(data_dir, 0.05, 0.05),
            "sheets_nd_tau1_tol10": lambda: fig_sheets(data_dir, 0.05, 0.10),
            "plateau": lambda: fig_plateau(data_dir)}
    sw = load_softwall(data_dir, "material", 0.05)
    if sw:
        figs["fmax_vs_n_material"] = lambda: fig_fmax_n(sw)
    for name, make in figs.items():
        fig = make()
        path = os.path.join(out_dir, name + ".png")
        fig.savefig(path, dpi=120)
        if not quiet:
            print(path)


def main(argv):
    data = argv[1] if len(argv) > 1 else DEFAULT_DATA
    out = argv[2] if len(argv) > 2 else os.path.join(data, "figures")
    matplotlib.use("Agg")
    try:
        if not os.path.isdir(data):
            raise InputError(f"no directory {data}")
        write_figures(data, out)
    except InputError as e:
        print(f"plot_sheets.py: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
