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
and, for runs held in memory ({label: softwall JSON}, e.g. fresh `softwall --sheets --json`,
or granwave.softwall(sheets=True) through softwall_from_module):
  softwall_from_module(r, version)    the module's Result in the layout of the program's JSON
  table2_pairs(sw)                    each sheets[] entry with its row of soft_walls_table2.csv
  fig_sheets_compare(runs, nd_tol)    N_d, tau_max(1), tau_max(N_d) per sheet against Table 2
  closeness_markdown(runs, nd_tol)    how close each sheet gets, per law
  run_plateau_case(case, work_dir)    one plateau case, fresh (module or program)
  fig_plateau_runs(cases)             fig_plateau for cases held in memory, with the paper's numbers
  plateau_table(cases)                plateau_markdown's rows plus tau_N(40) against 1.04 ms

Exit status: 0 ok, 2 if DATA_DIR or a required file is missing, not a regular file or
malformed, or on extra arguments (nothing is written then); 1 if a figure cannot be
written. Headless (Agg); use
Debian's /usr/bin/python3.
"""

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
PAPER_BAND = 0.05  # the paper's F_max is "independent of N within 5 %" (docs/physics.md 1.7)


InputError = gwdata.InputError    # exit 2
OutputError = gwdata.OutputError  # exit 1


# ---- sheets ----

def load_softwall(data_dir, law, tol):
    path = os.path.join(data_dir, f"softwall_{law}_tol{int(round(tol * 100)):02d}.json")
    if not os.path.lexists(path):
        return None
    try:
        return gwdata.load_json(path)
    except (OSError, ValueError) as e:
        raise InputError(gwdata.read_error(path, e))


_INT_KEYS = ("n_d_model", "n_d_measured", "n_d_measured_err", "n_d_predicted_f8", "n_d", "n_d_predicted",
             "n_d_fixed_point", "n_d_at_most")


def _json_value(k, v):
    """A module value as the program's JSON writes it: NaN -> None, counts as int."""
    if isinstance(v, dict):
        return {a: _json_value(a, b) for a, b in v.items()}
    if isinstance(v, (list, tuple, np.ndarray)):
        return [_json_value(k, x) for x in v]
    if isinstance(v, (float, np.floating)):
        if v != v:
            return None
        return int(v) if k in _INT_KEYS and float(v).is_integer() else float(v)
    if isinstance(v, np.integer):
        return int(v)
    return v


def softwall_from_module(r, version):
    """granwave.softwall's Result (sheets=True) in the layout of `granwave softwall
    --sheets --json` that the functions here read: version, tol, n, sheet_law, v_imp,
    k_c, sheets (NaN as None, N_d as integers) and walls (per sheet: the keys of the
    program's walls[], F_max(N) and tau_max(N) with None where a collision gave none)."""
    sheets = [_json_value("", e) for e in r["sheets"]]
    walls = []
    for i, e in enumerate(sheets):
        w = {"sheet": e["name"], "tau_max_n1_measured": e["tau_max_1_measured"], "n_d_measured": e["n_d_measured"],
             "n_d_measured_err": e["n_d_measured_err"], "wall": "rigid" if r["rigid"][i] else "soft"}
        for k in ("kwall", "f_max", "tau_max", "n_d", "n_d_predicted", "n_d_fixed_point", "f_plateau",
                  "tau_max_at_n_d", "n_d_at_most"):
            w[k] = _json_value(k, r[k][i])
        w["saturated"] = bool(r["saturated"][i])
        walls.append(w)
    return {"version": version, "v_imp": float(r["v_imp"]), "k_c": float(r["k_c"]),
            "t_q_rigid": float(r["t_q_rigid"]), "tol": float(r["tol"]), "n": [int(x) for x in r["n"]],
            "walls": walls, "sheet_law": r["sheet_law"], "sheets": sheets,
            "wall_time_s": float(r["wall_time_s"])}


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
        if not (os.path.lexists(runs_p) and os.path.lexists(tr_p)):
            continue
        c = {}
        for key, path, cols in (("runs", runs_p, ("n", "tau_n_s", "eps_eff")), ("trace", tr_p, ())):
            try:
                c[key] = gwdata.load_csv(path)
            except (OSError, ValueError) as e:
                raise InputError(gwdata.read_error(path, e))
            miss = [k for k in cols if not isinstance(c[key].get(k), np.ndarray)]
            if miss:
                raise InputError(f"{path}: missing or non-numeric column(s) {', '.join(miss)}")
            if not c[key] or not len(next(iter(c[key].values()))):
                raise InputError(f"{path}: no rows (a run cut short?)")
        out[case] = c
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


# ---- the same for runs held in memory (notebooks/experiment.ipynb) ----

def table2_pairs(sw):
    """[(sheets[] entry, row of data/falcon1998/soft_walls_table2.csv as a dict)] in the
    run's order. The program's ids ("tape", "cardboard2") differ from the paper's names
    ("adhesive tape", "cardboard II"): the row is the one with the same measured N_d and
    tau_max(1) (both unique in Table 2). Raises InputError if an entry has no row."""
    t = gwdata.load_table("soft_walls_table2")
    out = []
    for e in sw["sheets"]:
        hit = [i for i in range(len(t["sheet"]))
               if t["n_d"][i] == e["n_d_measured"]
               and abs(t["tau_max_n1_us"][i] - e["tau_max_1_measured"] * US) < 1e-6]
        if len(hit) != 1:
            raise InputError(f"sheet {e['name']}: no single row of soft_walls_table2.csv with "
                             f"N_d = {e['n_d_measured']} and tau_max(1) = {e['tau_max_1_measured'] * US:g} us")
        i = hit[0]
        out.append((e, {k: t[k][i] for k in t}))
    return out


def _nd_at(e, tol):
    b = _by_tol(e, tol)
    return np.nan if b is None else float(b)


def _taund_at(e, tol):
    for b in e["n_d_model_by_tol"]:
        if abs(b["tol"] - tol) < 1e-9 and b.get("tau_max_nd") is not None:
            return b["tau_max_nd"] * US
    return np.nan


def _err(x):
    return 0.0 if x is None or not np.isfinite(x) else float(x)


def fig_sheets_compare(runs, nd_tol=0.05, title=""):
    """Three panels per sheet of Table 2 (x axis), one marker per run of runs
    ({label: softwall JSON}): the model's N_d (F_max within nd_tol of F_max(n_max); open
    marker at n_max: not saturated), tau_max(1), and tau_max(N_d) (filled: at the model's
    own N_d; open: at the measured N_d, the tolerance-free comparison), against the paper's
    Table 2 (black, with its error bars; soft_walls_table2.csv)."""
    if not runs:
        raise InputError("no softwall runs to draw")
    first = next(iter(runs.values()))
    pairs = table2_pairs(first)
    names = [row["sheet"] for _, row in pairs]
    x = np.arange(len(names))
    fig = Figure(figsize=(13, 4.6))
    ax1, ax2, ax3 = fig.subplots(1, 3)
    nrun = len(runs)
    for j, (label, sw) in enumerate(runs.items()):
        col, mk = f"C{j % 10}", "sovD^<>p"[j % 8]
        ent = {e["name"]: e for e in sw["sheets"]}
        ref = [ent.get(e["name"]) for e, _ in pairs]
        xs = x + (j - (nrun - 1) / 2) * 0.13
        nmax = sw["n"][-1]
        nd = np.array([np.nan if e is None else _nd_at(e, nd_tol) for e in ref])
        have = np.array([e is not None for e in ref])
        sat = have & np.isfinite(nd)
        ax1.plot(xs[sat], nd[sat], mk, ms=5, color=col, label=label)
        uns = have & ~np.isfinite(nd)
        ax1.plot(xs[uns], np.full(uns.sum(), nmax), mk, ms=5, mfc="none", color=col)
        t1 = np.array([np.nan if e is None else e["tau_max_1_model"] * US for e in ref])
        ax2.plot(xs, t1, mk, ms=5, color=col, label=label)
        tnd = np.array([np.nan if e is None else _taund_at(e, nd_tol) for e in ref])
        tms = np.array([np.nan if e is None or e["tau_max_at_measured_nd_model"] is None
                        else e["tau_max_at_measured_nd_model"] * US for e in ref])
        ax3.plot(xs, tnd, mk, ms=5, color=col, label=label)
        ax3.plot(xs, tms, mk, ms=5, mfc="none", color=col)
    nd_p = [row["n_d"] for _, row in pairs]
    ax1.errorbar(x, nd_p, yerr=[_err(row["n_d_err"]) for _, row in pairs], fmt="k_", ms=14,
                 capsize=3, label="paper, Table 2")
    ax2.plot(x, [row["tau_max_n1_us"] for _, row in pairs], "k_", ms=14, label="paper, Table 2")
    ax3.errorbar(x, [row["tau_max_nd_us"] for _, row in pairs],
                 yerr=[_err(row["tau_max_nd_err_us"]) for _, row in pairs], fmt="k_", ms=14,
                 capsize=3, label="paper, Table 2")
    ax3.plot([], [], "o", mfc="none", color="0.4", label="model at the paper's N_d")
    for ax in (ax1, ax2, ax3):
        ax.set_xticks(x)
        ax.set_xticklabels(names, rotation=40, fontsize=8)
        ax.set_yscale("log")
        ax.grid(alpha=0.3, which="both")
    ax1.set_ylabel(f"N_d (open: no plateau by N = {first['n'][-1]})")
    ax1.set_title(f"saturation number: F_max within {100 * nd_tol:g} % of F_max(n_max)", fontsize=9)
    ax2.set_ylabel("tau_max(N = 1) (us)")
    ax2.set_title("time of the peak force, one bead", fontsize=9)
    ax3.set_ylabel("tau_max(N_d) (us)")
    ax3.set_title("time of the peak force at N_d (filled: model's N_d)", fontsize=9)
    ax1.legend(fontsize=7)
    ax3.legend(fontsize=7)
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    _footer(fig, f"granwave {first.get('version', '?')} softwall --sheets (h = 2.9 mm, v_imp = "
                 f"{first.get('v_imp', float('nan')):.4g} m/s); paper: Falcon et al. 1998, Table 2 "
                 "(data/falcon1998/soft_walls_table2.csv)")
    return fig


def _within(model, meas, err):
    return np.isfinite(model) and abs(model - meas) <= err + 1e-9


def closeness_rows(sw, tols=(0.05, 0.10)):
    """Per sheet of one run: the model's N_d at each tolerance, whether it is within the
    measured N_d +- its error (0 where the paper gives none), and the relative differences
    of tau_max(1) and of tau_max at the measured N_d (with whether that is within the
    paper's error, or 5 % where it gives none)."""
    rows = []
    for e, row in table2_pairs(sw):
        nd, nde = row["n_d"], _err(row["n_d_err"])
        r = {"sheet": row["sheet"], "name": e["name"], "nd": nd, "nd_err": nde,
             "nd_model": {t: _nd_at(e, t) for t in tols},
             "tau1_rel": e["tau_max_1_model"] * US / row["tau_max_n1_us"] - 1}
        r["nd_within"] = {t: _within(r["nd_model"][t], nd, nde) for t in tols}
        tm = e["tau_max_at_measured_nd_model"]
        tmeas, terr = row["tau_max_nd_us"], row["tau_max_nd_err_us"]
        terr = terr if np.isfinite(terr) else 0.05 * tmeas
        r["taund_rel"] = np.nan if tm is None else tm * US / tmeas - 1
        r["taund_within"] = tm is not None and abs(tm * US - tmeas) <= terr
        r["f_over_plateau"] = e["f_max_at_measured_nd_over_plateau"]
        rows.append(r)
    return rows


def closeness_markdown(runs, tols=(0.05, 0.10)):
    """How close each sheet gets, one column per run of runs ({label: softwall JSON}); a
    cell: N_d at 5 % / 10 % (a star where within the paper's N_d +- error), tau_max(1)
    against the paper, tau_max at the paper's N_d against the paper's tau_max(N_d) (a star
    where within its error, 5 % where none). Then, per run, the sheets within."""
    per = {label: {r["sheet"]: r for r in closeness_rows(sw, tols)} for label, sw in runs.items()}
    sheets = [r["sheet"] for r in closeness_rows(next(iter(runs.values())), tols)]
    t0 = gwdata.load_table("soft_walls_table2")
    paper = {n: i for i, n in enumerate(t0["sheet"])}
    f = lambda v: "-" if not np.isfinite(v) else f"{v:.0f}"
    lines = ["| sheet | paper: N_d, tau_max(1), tau_max(N_d) (us) | " + " | ".join(per) + " |",
             "|---|---|" + "---|" * len(per)]
    for sh in sheets:
        i = paper[sh]
        nde, te = t0["n_d_err"][i], t0["tau_max_nd_err_us"][i]
        pc = (f"{t0['n_d'][i]:g}" + (f" +- {nde:g}" if np.isfinite(nde) else "") +
              f", {t0['tau_max_n1_us'][i]:g}, {t0['tau_max_nd_us'][i]:g}" + (f" +- {te:g}" if np.isfinite(te) else ""))
        cells = []
        for label in per:
            r = per[label].get(sh)
            if r is None:
                cells.append("")
                continue
            nd = " / ".join(f(r["nd_model"][t]) + ("*" if r["nd_within"][t] else "") for t in tols)
            td = "-" if not np.isfinite(r["taund_rel"]) else f"{100 * r['taund_rel']:+.0f} %" + ("*" if r["taund_within"] else "")
            cells.append(f"N_d {nd}; tau_max(1) {100 * r['tau1_rel']:+.0f} %; tau_max(N_d) {td}")
        lines.append(f"| {sh} | {pc} | " + " | ".join(cells) + " |")
    lines += ["", "| run | N_d within the paper's +- at " + " / ".join(f"{100 * t:g} %" for t in tols) +
              " | tau_max at the paper's N_d within its +- (5 % where none) |", "|---|---|---|"]
    for label, rs in per.items():
        wn = " / ".join(", ".join(r["sheet"] for r in rs.values() if r["nd_within"][t]) or "none" for t in tols)
        wt = ", ".join(r["sheet"] for r in rs.values() if r["taund_within"]) or "none"
        lines.append(f"| {label} | {wn} | {wt} |")
    return "\n".join(lines)


# the plateau cases whose options the Python module takes (the others need the program's
# sheet-law, sensor and guide options, which are not rows of the module's tables yet)
def _module_kwargs(extra):
    kw, it = {}, iter(extra)
    for flag in it:
        kw[flag[2:].replace("-", "_")] = next(it)
    return kw


def run_plateau_case(case, work_dir, granwave=None, use_module=True):
    """One case of CASES run afresh: {"runs": falcon_runs columns (n, tau_n_s, eps_eff,
    f_max_N), "trace": the N = 30 wall force (t_s, f_wall_N), "how": "module" or
    "program"}. Through the Python module (granwave.falcon and granwave.chain with the
    settings of PLATEAU_BASE) when the case's options are module keywords and use_module;
    else through the program (`granwave falcon ... --out work_dir/<case>`)."""
    extra = CASES[case][1]
    kw = _module_kwargs(extra)
    base = {"vimp": [0.316], "heights": [], "n": (1, 40), "solver": "arkode", "method": "erk",
            "rtol": 1e-10, "atol": 1e-10, "dt_out": 1e-6}
    if use_module:
        gw = gwdata.import_granwave()
        names = {p["keyword"] for p in gw.params("falcon")} & {p["keyword"] for p in gw.params("chain")}
        use_module = all(k in names for k in kw)
    if use_module:
        f = gw.falcon(jobs=2, **base, **kw)
        chain_kw = {k: v for k, v in base.items() if k not in ("vimp", "heights", "n")}
        r = gw.chain(n=30, vimp=0.316, trace=True, **chain_kw, **kw)
        runs = {"n": np.asarray(f.n, float), "tau_n_s": np.asarray(f.tau_n[0], float),
                "eps_eff": np.asarray(f.eps_eff[0], float), "f_max_N": np.asarray(f.f_max[0], float)}
        return {"runs": runs, "trace": {"t_s": np.asarray(r.t), "f_wall_N": np.asarray(r.f_wall)},
                "how": "module"}
    # program until the module has the sheet-law, sensor and guide options
    d = os.path.join(work_dir, case)
    gwdata.run_granwave(PLATEAU_BASE + extra + ["--out", d], json=False, program=granwave)
    return {"runs": gwdata.load_csv(os.path.join(d, "falcon_runs.csv")),
            "trace": gwdata.load_csv(os.path.join(d, "trace_n30_wall_force.csv")), "how": "program"}


def plateau_table(cases):
    """Rows of plateau_markdown for cases held in memory ({case: {"runs", "trace"}}), with
    tau_N(40) against the paper's 1.04 ms (h = 5.1 mm, rigid_wall.csv) and how each ran."""
    pv = gwdata.paper_value("collision_time", 5.1, unit="ms")
    lines = ["| mechanism | mean force N = 30 (N) | change of the mean per ms | eps_eff(1) | eps_eff(40) | "
             "d eps_eff / dN | tau_N(40) (ms; paper %s) | run by |" % (f"{pv[0]:g}" if pv else "-"),
             "|---|---|---|---|---|---|---|---|"]
    for case, c in cases.items():
        s = plateau_stats(c)
        n = np.asarray(c["runs"]["n"], float)
        t40 = np.asarray(c["runs"]["tau_n_s"], float)[n == 40]
        t40 = f"{t40[0] * 1e3:.3f}" if len(t40) else "-"
        lines.append(f"| {CASES[case][0]} | {np.mean(s['f_mean']):.2f} | {100 * s['decay_per_ms']:+.2f} % | "
                     f"{s['eps1']:.4f} | {s['eps40']:.4f} | {s['eps_slope']:+.2e} | {t40} | {c.get('how', 'stored')} |")
    return "\n".join(lines)


def fig_plateau_runs(cases, title=""):
    """fig_plateau for cases held in memory, with the numbers the paper gives at h = 5.1 mm
    (rigid_wall.csv): the peak force F_max = 69 N +- 5 % (a band: the peaks, not the mean).
    Three panels: the N = 30 wall force with its window means, the means relative to the
    first, and eps_eff(N). The paper's N = 40 collision time (1.04 ms) is in plateau_table.
    The traces of the paper's Fig. 4d and the values of its Fig. 11 are not in
    data/falcon1998 and are not drawn."""
    if not cases:
        raise InputError("no plateau cases to draw")
    fig = Figure(figsize=(15, 4.8))
    ax1, ax3, ax2 = fig.subplots(1, 3)
    for i, (case, c) in enumerate(cases.items()):
        s = plateau_stats(c)
        t, f = _trace_arrays(c["trace"])
        col = f"C{i % 10}"
        ax1.plot(t * 1e3, f, color=col, lw=0.4, alpha=0.3)
        ax1.plot(s["t"] * 1e3, s["f_mean"], "-o", ms=3, color=col, label=CASES[case][0])
        ax3.plot(s["t"] * 1e3, s["f_mean"] / s["f_mean"][0], "-o", ms=3, color=col,
                 label=f"{CASES[case][0]}: {100 * s['decay_per_ms']:+.2f} %/ms")
        ax2.plot(c["runs"]["n"], c["runs"]["eps_eff"], "-o", ms=2.5, color=col, label=CASES[case][0])
    fm = gwdata.paper_value("f_max", 5.1)
    if fm:
        ax1.axhspan(fm[0] * (1 - PAPER_BAND), fm[0] * (1 + PAPER_BAND), color="k", alpha=0.08, lw=0)
        ax1.axhline(fm[0], color="k", lw=0.8, ls="--", label=f"paper: F_max {fm[0]:g} N +- 5 % (peaks)")
    ax1.axvspan(PLATEAU_START * 1e3, PLATEAU_END * plateau_stats(next(iter(cases.values())))["tau_n30"] * 1e3,
                color="y", alpha=0.08, lw=0)
    ax1.set_xlim(0, 1.2)
    ax1.set_xlabel("t (ms)")
    ax1.set_ylabel("wall force read, N = 30 (N); dots: 50 us means")
    ax1.set_title("wall force, h = 5.1 mm (the paper's Fig. 4d: not digitized)", fontsize=9)
    ax3.set_xlabel("t (ms), centre of the 50 us window")
    ax3.set_ylabel("window mean / first window mean")
    ax3.set_title("the mean force in the window, relative; legend: straight-line slope", fontsize=9)
    ax2.set_xlabel("N")
    ax2.set_ylabel("eps_eff (F.7)")
    ax2.set_title("effective restitution (the paper's Fig. 11: decreases with N, no values)", fontsize=9)
    ax1.legend(fontsize=6, loc="lower right")
    ax2.legend(fontsize=6)
    ax3.legend(fontsize=6)
    for ax in (ax1, ax2, ax3):
        ax.grid(alpha=0.3)
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    _footer(fig, "granwave falcon --vimp 0.316 --heights none --n 1:40 (arkode erk, rtol 1e-10) "
                 "[mechanism options]; yellow: the window of the means (first case); paper: rigid_wall.csv")
    return fig


def run_study(out_dir, granwave=None):
    """Re-run the plateau cases into out_dir/plateau/<case> (several minutes)."""
    gw = granwave or gwdata.find_granwave()
    import subprocess
    for case, (_, extra) in CASES.items():
        d = os.path.join(out_dir, "plateau", case)
        subprocess.run([gw] + PLATEAU_BASE + extra + ["--out", d], check=True)


def write_figures(data_dir, out_dir, quiet=False):
    """Every figure is made before out_dir is created: a refused input writes nothing."""
    figs = {"sheets_nd_tau1_tol05": lambda: fig_sheets(data_dir, 0.05, 0.05),
            "sheets_nd_tau1_tol10": lambda: fig_sheets(data_dir, 0.05, 0.10),
            "plateau": lambda: fig_plateau(data_dir)}
    sw = load_softwall(data_dir, "material", 0.05)
    if sw:
        figs["fmax_vs_n_material"] = lambda: fig_fmax_n(sw)
    made = {name: make() for name, make in figs.items()}
    try:
        os.makedirs(out_dir, exist_ok=True)
    except OSError as e:
        raise OutputError(f"cannot create {out_dir}: {e.strerror or e}")
    gwdata.save_pngs(made, out_dir, 120, quiet=quiet)


def main(argv):
    if len(argv) > 1 and argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0
    if len(argv) > 3:
        print("usage: plot_sheets.py [DATA_DIR [OUT_DIR]]  (unexpected: "
              + " ".join(argv[3:]) + ")", file=sys.stderr)
        return 2
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
    except OutputError as e:
        print(f"plot_sheets.py: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(gwdata.run_main(main, sys.argv))
