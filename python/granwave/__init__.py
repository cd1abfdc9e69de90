"""granwave: wave propagation in granular matter, from Python.

A thin layer over the C library libgranwave (ctypes, no compilation): the
same models and numbers as the `granwave` program.

    import granwave
    r = granwave.chain(n=7, vimp=0.3)            # a column of 7 beads hits a wall
    r.f_max, r.tau_n, r.final_velocities         # N, s, m/s (numpy array)
    r = granwave.chain(n=7, vimp=0.3, trace=True)
    r.t, r.f_wall                                # the wall-force trace
    f = granwave.falcon(n=(1, 20), vimp=[0.3], heights=[])   # the Falcon study
    f.t_q, f.wave_speed, f.f_max                 # per velocity; [velocity, N]
    granwave.layer_make(n=60, width_rm=16, seed=3, out="a.txt")   # a small sample
    r = granwave.layer_impact(sample="a.txt", rb_rm=1, vi=20)
    r.e_n, r.ledger["total"]                     # restitution, energy ledger series
    s = granwave.sweep("chain", grid={"n": range(1, 11), "vimp": [0.2, 0.3]}, solver="rk4")
    s.n, s.f_max                                 # one entry per case
    g = granwave.sweep_n((1, 10), [0.2, 0.3])    # the library's N x v grid
    g.f_max, g.warnings                          # [velocity, N]; its warnings
    st = granwave.layer_stats("out/results.csv")  # statistics of a layer sweep table
    st.groups["bounce_share"], st.diagrams["r_crit"]

Keyword names are the flags of the program's commands with '-' written '_'
(`granwave chain --dt-out` is dt_out=); help(granwave.chain) lists them with
units, defaults and ranges, from the library's own parameter tables.
Errors raise exceptions: a bad value GranwaveValueError (a ValueError naming
the parameter), an unknown keyword TypeError, an unreadable file
GranwaveIOError (an OSError), a failed run GranwaveRunError (a RuntimeError).
A run the program warns about (cut at t_max, not settled, undecided) returns
its result and issues a GranwaveWarning (a RuntimeWarning) with that text: the
library's own, which the result lists too (r.warnings, one str per warning).

The library is found in the build tree (./setup.sh build), next to an
installed module (cmake --install), or at GRANWAVE_LIB.
"""
import numpy as _np

from . import _checks, _core, _grid, _sweep
from ._core import (GranwaveError, GranwaveIOError, GranwaveRunError, GranwaveUnsupported,
                    GranwaveValueError, GranwaveWarning, Result)
from ._lib import lib as _clib
from ._lib import path as library_path

# shown as granwave.GranwaveValueError (the name users import), not granwave._core....
for _c in (GranwaveError, GranwaveIOError, GranwaveRunError, GranwaveUnsupported, GranwaveValueError,
           GranwaveWarning, Result):
    _c.__module__ = "granwave"

__all__ = ["version", "version_info", "chain", "falcon", "wavespeed", "softwall", "dispersion", "drop",
           "layer_make", "layer_impact", "layer_stats", "sweep", "sweep_n", "params", "library_path",
           "layer_impact_check", "layer_impact_settling", "layer_make_check", "sweep_case_check",
           "sweep_check",
           "Result", "GranwaveError", "GranwaveValueError", "GranwaveIOError", "GranwaveRunError",
           "GranwaveUnsupported", "GranwaveWarning"]


def version():
    """The library's version string, "MAJOR.MINOR.PATCH"."""
    return _clib.gw_version().decode()


def version_info():
    """The library's version as (major, minor, patch)."""
    return (_clib.gw_version_major(), _clib.gw_version_minor(), _clib.gw_version_patch())


__version__ = version()

_studies = {}


def _study(name):
    if not isinstance(name, str):
        raise TypeError(f"a study name is a str (\"chain\", \"layer-impact\"), not {type(name).__name__}")
    if name not in _studies:
        known = [_clib.gw_study_get(i).contents.name.decode() for i in range(_clib.gw_study_count())]
        name = name.replace("_", "-") if name.replace("_", "-") in known else name
        if name not in known:
            # quoted as the library quotes a caller's text (_line): params("chain\0")
            # and params("ch\x1bain") put the NUL and the ESC raw into the message
            raise GranwaveValueError(f"no study '{_core._line(name)}' (one of {', '.join(known)})", _core.GW_EINVAL)
    if name not in _studies:
        _studies[name] = _core.Study(name)
    return _studies[name]


def params(study):
    """The parameter table of a study ("chain", "layer-impact") as a list of
    dicts: keyword, flag name, type, unit, min, max, or_zero (0 is taken
    besides [min, max]), default (text), optional (a value given at the
    default's is told from none), help."""
    st = _study(study)
    return [{"keyword": p.keyword, "name": p.name, "type": _core._TYPE_NAMES[p.type], "unit": p.unit,
             "min": p.min, "max": p.max, "or_zero": p.or_zero, "default": p.default, "optional": p.optional,
             "choices": p.choices, "help": p.help}
            for p in st.params]


# A run that ended with results that are not final (cut at t_max, not settled,
# undecided) issues a GranwaveWarning per text of the library's result (its
# `warnings`, what the program prints on stderr): Study.run in _core, for every
# study alike. No warning text is written here.

def chain(**kwargs):
    return _study("chain").run(kwargs)


def layer_make(*, progress=None, **kwargs):
    return _study("layer-make").run(kwargs, progress)


_SNAP_COLS = ("x", "y", "theta", "vx", "vy", "omega")


def _mass_law_name(code):
    """The mass law by its choice name ('disc', 'sphere': what the keyword takes
    and the first word of the JSON settings' name), from the impact's table."""
    choices = next(p.choices for p in _study("layer-impact").params if p.keyword == "mass_law")
    return choices[int(code)]


def layer_impact(*, progress=None, **kwargs):
    r = _study("layer-impact").run(kwargs, progress)
    r["mass_law"] = _mass_law_name(r["mass_law"])  # 0/1 before; its name, as softwall's sheet_law
    ng = max(r["nrings"] - 1, 0)  # ring pairs k, k + 1; NaN without the analysis (the program's null)
    for k in ("xcorr_delay", "xcorr_rho"):
        if k not in r:
            r[k] = _np.full(ng, _np.nan)
    if "spec_strain" not in r:
        r["spec_strain"] = r["spec_kinetic"] = _np.zeros((0, r["nrings"]))
    r["spec_f"] = _np.arange(r["spec_len"]) * r["spec_df"]
    snaps = None
    if r["nsnap"] > 0:
        n, m = r["nsnap"], r["nparticles"]
        tab = r.pop("snapshot")
        snaps = {"t": r.pop("snapshot_t"), "r": r.pop("snapshot_r"), "block": r["block_index"]}
        for c in _SNAP_COLS:
            snaps[c] = tab[c].reshape(n, m)
    r["snapshots"] = snaps
    return r


# the tables' yes/no columns (never NaN); convergence's bounced stays a number: NaN
# where the impact was undecided, as the sweep table's
_STATS_FLAGS = (("groups", ("bouncing", "verdict_certain")), ("walls", ("walls_bouncing", "walls_removed_bouncing")),
                ("diagrams", ("ok", "fit_ok")))

# the tables' columns before they took the names of the JSON and the CSV files
# (one name per statistic in every form): still read, with a warning
_WALL_SIDE_BEFORE = ("n_points", "bounce_share", "bouncing", "e_n_mean", "e_mean", "penetration_rm_mean",
                     "rebound_energy_mean")
_STATS_NAMES_BEFORE = {
    "groups": {"n_rebound": "n_e", "n_rebound_first": "n_e_first",
               "block_loss_mean": "block_loss_first_contact_mean", "block_loss_std": "block_loss_first_contact_std",
               "dissipated_mean": "dissipated_first_contact_mean",
               "dissipated_std": "dissipated_first_contact_std"},
    "binary": {"n": "n_block_loss_first_contact", "block_loss_mean": "block_loss_first_contact_mean",
               "block_loss_std": "block_loss_first_contact_std"},
    "walls": {"group_walls": "walls_group", "group_removed": "walls_removed_group",
              "walls_block_loss_mean": "walls_block_loss_first_contact_mean",
              "removed_block_loss_mean": "walls_removed_block_loss_first_contact_mean",
              **{"removed_" + c: "walls_removed_" + c for c in _WALL_SIDE_BEFORE}},
}


class _Columns(dict):
    """A table's columns; a name it had before reads the column of its new name,
    with a DeprecationWarning (not listed, not `in`)."""

    def __init__(self, columns=(), before=None):
        super().__init__(columns)
        self._before = before or {}

    def __missing__(self, name):
        now = getattr(self, "_before", {}).get(name)
        if now is None or now not in self:
            raise KeyError(name)
        import warnings
        warnings.warn(f"layer_stats: column '{name}' is now '{now}' (the name of the JSON and the CSV files)",
                      DeprecationWarning, stacklevel=2)
        return self[now]


def layer_stats(input=None, **kwargs):
    st = _study("layer-stats")
    r = st.run(dict(kwargs, input=input) if input is not None else kwargs)
    for f in st.fields:  # a table without rows (no diagram, no walls): empty columns
        if f.type == _core.DARRAY and f.choices and f.name not in r:
            r[f.name] = {c: _np.empty(0) for c in f.choices}
    for t, cols in _STATS_FLAGS:  # yes/no columns as bools, as the JSON's true/false
        for c in cols:
            if t in r and c in r[t] and not _np.isnan(r[t][c]).any():
                r[t][c] = r[t][c] != 0
    # per diagram: the fit's offset source and why there is no fit, as the JSON's
    # fit.offset_source and fit_reason (None where the JSON has none), the
    # layer-stats inputs named by their keywords ("delta_rm" where the program
    # writes "--delta-rm")
    keep = _core._texts(list(kwargs.values()) + [input])
    for col, key in (("offset_source", "offset_sources"), ("fit_reason", "fit_reasons")):
        lines = (r.pop(key, None) or "").split("\n")[:-1]
        r["diagrams"][col] = _np.array([_core.keyword_text(t, st.names, keep) if t else None for t in lines],
                                       dtype=object)
    names = r.pop("group_keys", None)
    r["group_keys"] = names.split(",") if names else []  # as the JSON's list
    keys = r.pop("keys", None)
    if keys is not None and "groups" in r:
        for j, name in enumerate(r["group_keys"]):
            r["groups"][name] = keys[:, j].copy()
    for t, before in _STATS_NAMES_BEFORE.items():
        if t in r:
            r[t] = _Columns(r[t], before)
    return r


def layer_impact_check(**kwargs):
    """What layer_impact(**kwargs) refuses before it runs, without running
    (gw_layer_impact_setup_check): the keywords, the sample read and checked
    (gw_layer_impact_check's form and limits) and the impact resolved against
    it under the given material (gw_layer_impact_check_with's side walls, the
    pile at rest and its recorded settling, the gap, the step). None when the
    run would start; else raises what layer_impact raises, with its text (the
    library's message, inputs named by their keywords). Nothing is written."""
    _checks.layer_impact_check(_study("layer-impact"), kwargs)


def layer_impact_settling(**kwargs):
    """The sample's settling as layer_impact(**kwargs) would take it, without
    running (gw_layer_impact_setup_settling): layer_impact_check's refusals
    first (a pile not at rest under the given material, other_settling of no
    effect), then a dict: load_ratio, the weight the pile's contacts carry
    under the impact's material against at rest (1: the material it settled
    with; NaN when the sample records no settling), and warning, the settling
    warning layer_impact's result would list (None when none), its inputs
    named by their keywords. Nothing is run or written."""
    return _checks.layer_impact_settling(_study("layer-impact"), kwargs)


def layer_make_check(**kwargs):
    """What layer_make(**kwargs) refuses before it pluviates, without running
    (gw_layer_make_plan): the keywords, the rules between them, the material,
    and out tried as a sample file to write (never written). None when the run
    would start; else raises what layer_make raises, with its text."""
    _checks.layer_make_check(_study("layer-make"), kwargs)


def sweep_case_check(model="layer", **params):
    """One case of a sweep model ("layer" or "chain"), each keyword one value
    as a sweep's grid or params give it, through the sweep's own check pass
    over a sweep of that one case (gw_sweep_case_check_pass), as a sweep
    checks its cases before any case runs: the model's check (for the layer
    model the setup's check, layer_impact_check's, and the impact point's
    placement: point, points, spacing) and the pass's refusals of the config
    as a whole (a chain key of no effect in every case: k on one body). None
    when the case passes; else raises what sweep() of that one case raises,
    with its text ("sweep: case 0: ..."). Nothing runs."""
    _checks.sweep_case_check(model, params)


def sweep_check(model="chain", grid=None, **params):
    """What sweep(model, grid, **params) refuses before any case runs, without
    running (gw_sweep_check_text): its keywords, its config and the sweep's
    check pass over every case (gw_sweep_check_pass: each case's check, then
    the refusals of the config as a whole). Raises what sweep() raises, with
    its text; else returns the pass's warnings as sweep() lists them (a list
    of str, empty when none). The memory of the cases run at once (jobs) is
    sweep()'s. Nothing is written."""
    return _sweep.check_sweep(model, grid or {}, params)


def falcon(*, progress=None, **kwargs):
    # As `granwave falcon`: the accuracy target picks RK4 only when no solver
    # option is given, and both given are refused. The library decides: its
    # solver rows have a "not given" state, so solver="cvode" (the default's
    # value) given is the solver as given there too.
    return _study("falcon").run(kwargs, progress)


def wavespeed(*, progress=None, **kwargs):
    r = _study("wavespeed").run(kwargs, progress)
    r["fits"] = {w: {k: r["fit_%s_%s" % (w, k)] for k in ("beta", "beta_err", "prefactor", "c3")}
                 for w in ("tq", "front", "group", "group_front")}
    return r


_SHEET_LAWS = ("fitted", "hertz", "layer", "material")


def softwall(*, progress=None, **kwargs):
    r = _study("softwall").run(kwargs, progress)
    r["sheet_law"] = _SHEET_LAWS[r["sheet_law"]]
    table = r.pop("sheet_table", None)
    names = (r.pop("sheet_names", None) or "").split(",")
    materials = (r.pop("sheet_materials", None) or "").split(";")
    sheets = []
    for i in range(r["nsheet"]):
        row = {c: float(table[c][i]) for c in table}
        e = {"name": names[i], "material": materials[i]}
        for k in list(row)[:12]:
            e[k] = row[k]
        e["n_d_model_by_tol"] = [{"tol": t, "n_d": row["n_d_tol_%g" % t], "tau_max_nd": row["tau_max_nd_tol_%g" % t]}
                                 for t in (0.01, 0.02, 0.05, 0.1)]
        for k in ("f_max_1_model", "f_plateau_model", "eps_eff_1_model", "kwall", "a_over_h_1"):
            e[k] = row[k]
        if e["a_over_h_1"] != e["a_over_h_1"]:  # NaN: not a layer law (the program leaves it out)
            del e["a_over_h_1"]
        sheets.append(e)
    r["sheets"] = sheets
    return r


def dispersion(**kwargs):
    return _study("dispersion").run(kwargs)


_IMPACT_INTS = ("n_peaks", "cluster")


def drop(*, progress=None, **kwargs):
    r = _study("drop").run(kwargs, progress)
    first = {"n": r.pop("n_first"), "v_imp": r["v_imp"]}
    for k in [k for k in r if k.startswith("first_")]:
        first[k[len("first_"):]] = r.pop(k)
    if _np.isnan(first.get("chatter", 0.0)):  # not checked (cut at t_max): no key, as drop --json
        del first["chatter"]
    r["first_collision"] = first
    r["energy"] = {"e0": r.pop("e0")}
    for k in ("kinetic", "elastic", "gravity", "dissipated", "total"):
        r["energy"][k] = r.pop("energy_" + k)
    n = r["n"]
    empty = {"t": _np.zeros(0), "f": _np.zeros(0)}
    r["wall_peaks"] = r.get("wall_peaks", empty)
    for k in ("peak_impact", "peak_cluster"):
        r[k] = r.get(k, _np.zeros(0, dtype=_np.intc))
    r["peak_contacts"] = r.get("peak_contacts", _np.zeros((0, n), dtype=_np.intc)).reshape(-1, n)
    imp = r.get("impacts") or {c: _np.zeros(0) for c in _IMPACT_COLS}
    for k in _IMPACT_INTS:
        imp[k] = imp[k].astype(int)
    imp["located"] = imp["located"].astype(bool)
    r["impacts"] = imp
    r["gaps"] = r.get("gaps", _np.zeros(0))
    return r


_IMPACT_COLS = ("t_start", "t_end", "f_max", "t_fmax", "v_in", "v_out", "n_peaks", "cluster", "located", "chatter")


def sweep(model="chain", grid=None, *, jobs=0, progress=None, **params):
    """Run a grid of cases of a sweep model ("chain" or "layer") in memory,
    on `jobs` threads (0: one per CPU), with the library's sweep engine (the
    cases and columns of `granwave sweep`).

    grid: {keyword: values}, every combination is a case (the last key varies
    fastest); values are a list, a range, or a string "A:B" (integers) or
    "a,b,c" (a list item "A:B" is refused: the library would run it as a
    range). Consecutive integers are written A:B; any number of other values
    fit (a long list goes on over several lines of the config, as a sweep file
    writes it). Other keywords are the model's parameters, the same for every
    case. progress: optional f(done, total), called as cases finish (from the
    worker threads, one call at a time); return True (or raise) to stop. Returns a Result with one array per grid key and
    per result column (f_max, tau_n, ... for the chain), one entry per case.
    """
    return _sweep.run_sweep(model, grid or {}, params, jobs, progress)


def sweep_n(n, vimp, *, jobs=0, progress=None, **kwargs):
    """The library's N x v grid (gw_chain_sweep_n_warned): one collision of
    the column for every impact speed in vimp (m/s, a number or a list) and
    every N in n = (A, B) (N = A..B; a range or one N too), on `jobs` threads
    (0: one per CPU); a speed given twice (or within a relative 1e-12, as a
    chain sweep's config refuses a value listed twice) is refused naming vimp
    and both items. Other keywords are granwave.chain's (its column: model
    and solver; not n, vimp or trace), resolved as falcon resolves its column
    (N = A, the first speed: a restitution target is calibrated there).
    progress: optional f(done, total) per collision, from the worker threads
    one call at a time; return True (or raise) to stop.

    Returns a Result: n [N], v_imp [velocity], and each result of
    granwave.chain's collision (f_max, tau_n, eps_eff, converged, steps, ...)
    as an array [velocity, N]; the per-bead series (final_velocities,
    detach_times, velocities_at_tau_n) a list [velocity][N] of arrays.
    warnings: the grid's "no effect" lines as a chain sweep's check pass says
    them, with their count over the grid's cases (case k = iv * (B - A + 1) +
    (N - A): "the sensor body's dashpot has no effect in 2 of 2 cases (the
    first, case 0): ..."), then the collisions that did not end at t_max (as
    falcon says them); each also issued as a GranwaveWarning.
    """
    return _grid.run_grid(_study("chain"), n, vimp, jobs, progress, kwargs)


chain.__doc__ = _study("chain").doc(
    "One collision of a column of n beads with a wall (Falcon et al. 1998, eq. F.11):\n"
    "Hertz contacts, beads initially touching and moving at vimp toward the wall, as\n"
    "`granwave chain`. trace=True adds the series t, f_wall, x, v (numpy arrays).")
falcon.__doc__ = _study("falcon").doc(
    "The rigid-wall study of Falcon et al. (1998), as `granwave falcon`: one collision\n"
    "for every N in n = (A, B) at each impact velocity (vimp, and heights in mm), the\n"
    "line tau_N = T_q (N - 1) + tau_1, the wave speed 4R/T_q against (F.27), F_max(N).\n"
    "Per-case results are arrays [velocity, N]; the bead table (bead_v_imp, bead_n,\n"
    "bead, final_v, detach_t, v_tau_n: nbeads rows, velocity, N, bead 1..N) holds the\n"
    "rows of the program's falcon_final_velocities.csv (the program runs the same\n"
    "library call). progress: optional f(done, total) per collision, called from\n"
    "the worker threads one call at a time; return True (or raise) to stop.\n"
    "heights=[] (or 'none') for none.")
wavespeed.__doc__ = _study("wavespeed").doc(
    "The deformation-wave speed of the column against the impact velocity, as\n"
    "`granwave wavespeed`: (a) 4R/T_q from the slope of tau_N(N), (b) the front's time\n"
    "of flight, (c) the group speed of the chain compressed by the mean wall force and\n"
    "c/sqrt(3/2); power-law fits v = A v_imp^beta (F.16; fits[...] per estimator), the\n"
    "period fit (F.15). Series per velocity are numpy arrays. progress: f(done, total)\n"
    "per collision, called from the worker threads one call at a time.")
softwall.__doc__ = _study("softwall").doc(
    "Columns on a soft wall, as `granwave softwall`: F_max(N), tau_max(N) for a wall\n"
    "coefficient (kwall, default 1e9) or every sheet of the paper's Table 2\n"
    "(sheets=True, under sheet_law), the saturation number N_d against (F.8), K_c (F.22).\n"
    "Per-wall arrays [wall] and [wall, N]; sheets: a list of dicts, model against measured,\n"
    "keys as the program's JSON. progress: f(done, total) per wall.")
dispersion.__doc__ = _study("dispersion").doc(
    "Small-amplitude dispersion of a precompressed Hertz chain, as `granwave dispersion`:\n"
    "the ridge omega_ridge(q) of the space-time power spectrum against\n"
    "omega = 2 sqrt(kappa/m) |sin(qa/2)| (physics.md 1.6); power is [q, omega bin].\n"
    "column_n=N instead: the wall-force spectrum of an N-bead column (freq, spectrum,\n"
    "f_peak against 1/period).")
drop.__doc__ = _study("drop").doc(
    "The whole drop (Falcon et al. 1998, Fig. 12), as `granwave drop`: the column released\n"
    "from rest with bead 1 at height above the sensor, followed from its first contact\n"
    "(t = 0, v_imp = sqrt(2 g h)) through the first collision, flights and later impacts\n"
    "up to t_max. Returns the sensor signal (t, f_wall; x, v with trace=True), wall_peaks\n"
    "({'t', 'f'} arrays, with peak_impact, peak_cluster, peak_contacts [peak, contact]),\n"
    "impacts (a dict of arrays by column), first_collision (a dict with the keys of\n"
    "granwave.chain's result: f_max, tau_max, tau_n, eps_eff, ...) and energy (the ledger\n"
    "at t_end). progress: f(done, total) in output samples of the drop and of its first\n"
    "collision's own run (total = 2 t_max / dt_out); return True (or raise) to stop.")
layer_make.__doc__ = _study("layer-make").doc(
    "Pluviate a 2D sample (Bourrier et al. 2008, physics.md 2.2), as `granwave layer-make`:\n"
    "polydisperse discs (clumps=True: rigid clumps) dropped under gravity until the kinetic\n"
    "energy is below a threshold. Deterministic for a seed. out=FILE writes the sample\n"
    "for layer_impact(sample=FILE); the result holds the discs (x, y, r) either way.\n"
    "progress: f(done, total) every 0.01 s of simulated settling (hundredths of a second of\n"
    "t_max; the pile usually settles before); return True (or raise) to stop.")
layer_impact.__doc__ = _study("layer-impact").doc(
    "One block impact on a 2D granular layer (Bourrier et al. 2008), as\n"
    "`granwave layer-impact` (fast default: verlet; exact=True for the exact mode).\n"
    "sample is a file written by `granwave layer-make`. The result holds what the\n"
    "program's --json and --out files do: spec_f (Hz) goes with spec_strain and\n"
    "spec_kinetic [frequency, ring]. snapshots=[t1, t2, ...] (s; off by default) adds\n"
    "snapshots: {'t': [snapshot], 'x', 'y', 'theta', 'vx', 'vy', 'omega': [snapshot,\n"
    "particle], 'r': [particle], 'block': the block's particle index}, each the first\n"
    "output sample at or after the time asked for (the end state when the run ended\n"
    "before it: snapshots=[t_max] gives the end); None without. progress: f(done, total)\n"
    "in output samples up to t_max (the run ends at T_f with done = total); return True\n"
    "(or raise) to stop.")
# each function's signature from its table: help() and a notebook's completion
# showed (**kwargs) (chain, dispersion) or (*, progress=None, **kwargs)
for _f, _name, _pos, _prog in ((chain, "chain", (), False), (falcon, "falcon", (), True),
                               (wavespeed, "wavespeed", (), True), (softwall, "softwall", (), True),
                               (dispersion, "dispersion", (), False), (drop, "drop", (), True),
                               (layer_make, "layer-make", (), True), (layer_impact, "layer-impact", (), True),
                               (layer_stats, "layer-stats", ("input",), False)):
    _f.__signature__ = _study(_name).signature(_pos, _prog)
layer_impact_check.__signature__ = _study("layer-impact").signature()
layer_make_check.__signature__ = _study("layer-make").signature()
layer_stats.__doc__ = _study("layer-stats").doc(
    "Statistics of a layer sweep table (OUT/results.csv of `granwave sweep` with model =\n"
    "layer; Bourrier et al. 2008, physics.md 2.3, 2.5), as `granwave layer-stats INPUT`:\n"
    "per group of impact points (every grid key but point) the moments of e_n, e, alpha_r\n"
    "and the bounce share; the first contact against the binary impact (B.24-B.28);\n"
    "walls on/off; per bouncing diagram R_crit, (R_min, H_min), the boundary H* and the\n"
    "B.31 fit. Tables with named columns are dicts of numpy arrays, one entry per row:\n"
    "groups (with the grouping keys' values, NaN where not numeric), convergence,\n"
    "binary, walls, diagrams, cells, boundary; group_keys lists the grouping keys. The\n"
    "names are those of the JSON and the CSV files of `--out` (a statistic X of the\n"
    "JSON, {mean, std, n}, is X_mean, X_std and n_X). input may be given by position.")
