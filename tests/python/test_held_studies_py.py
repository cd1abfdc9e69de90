"""The Python studies leave out the columns gravity holds on the wall (issue 18,
left by the twenty-third session; the C side: tests/test_chain_held_studies.c).

granwave.falcon, wavespeed and softwall return the library's outcome: each
column held by gravity is flagged (`held`, counted in `n_held`), its values
are those of the stop, and the fits are those of the decided columns alone,
checked here against numpy's least squares over the decided columns' own
results (1e-12); the program's JSON says the same, and a fit left without
two decided points is NaN with a warning naming gravity and vimp. Before,
falcon(n=(1, 8), vimp=[0.3], heights=[], gravity=1e3) gave t_q = 68.4 us from
the four held columns (27.9 us over the decided ones) and no flags.
"""
import json
import math
import subprocess
import warnings

import numpy as np

import granwave


def _rel(a, b):
    return abs(a - b) / abs(b)


def test_falcon_fits_the_decided_columns(program):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        f = granwave.falcon(n=(1, 8), vimp=[0.3], heights=[], gravity=1e3, jobs=1)
    held = np.asarray(f["held"][0])
    assert held.dtype == bool and 1 <= held.sum() <= 5 and f["n_held"] == held.sum()
    x, y = np.arange(8.0), np.asarray(f["tau_n"][0])
    c1, c0 = np.polyfit(x[~held], y[~held], 1)
    a1, _ = np.polyfit(x, y, 1)
    assert _rel(f["t_q"][0], c1) < 1e-12 and _rel(f["tau_fit_intercept"][0], c0) < 1e-12
    assert _rel(f["t_q"][0], a1) > 0.1  # the line over every column, held ones too, is another
    assert f["f_max_max"][0] == np.max(np.asarray(f["f_max"][0])[~held])
    said = [str(x.message) for x in w if "held by gravity" in str(x.message)]
    # the program's flags as keywords here: "raise vimp or lower gravity"
    assert len(said) == 1 and "lower gravity" in said[0] and "leave them out" in said[0]
    # the program's summary: the same T_q and flags
    out = subprocess.run([program, "falcon", "--n", "1:8", "--vimp", "0.3", "--heights", "none", "--gravity", "1e3",
                          "--jobs", "1", "--quiet", "--json"], check=True, capture_output=True, text=True)
    v = json.loads(out.stdout)["velocities"][0]
    assert v["t_q"] == f["t_q"][0] and v["held"] == held.tolist()
    assert v["tau_n_last"] is None  # N = 8 held: undecided


def test_softwall_n_d_undecided_and_wavespeed_fit_undecided():
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        s = granwave.softwall(n=(1, 14), kwall=1e9, gravity=30, tol=0.02, jobs=1)
    held = np.asarray(s["held"][0])
    assert held[12] and held[13] and not held[11] and s["n_held"] == held.sum()
    assert s["f_plateau"][0] == s["f_max"][0][11]  # the longest decided column
    assert math.isnan(s["n_d"][0]) and s["saturated"].tolist() == [None]  # undecided, not False
    assert any("undecided: N_d" in str(x.message) for x in w)
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r = granwave.wavespeed(n=(4, 10), vimp=[0.3, 0.5, 1, 2], gravity=1e3, jobs=1)
    decided = ~np.asarray(r["held"])[:, -1]  # the longest column decided at that speed
    assert decided.sum() == 1 and np.all(np.isnan(np.asarray(r["v_group"])[~decided]))
    assert math.isnan(r["fits"]["group"]["beta"])  # one decided speed: no line
    assert any("fits over v_imp" in str(x.message) and "raise vimp" in str(x.message) for x in w)


def test_no_gravity_nothing_held():
    f = granwave.falcon(n=(1, 8), vimp=[0.3], heights=[], jobs=1)
    assert f["n_held"] == 0 and not np.any(f["held"])
    c1, _ = np.polyfit(np.arange(8.0), np.asarray(f["tau_n"][0]), 1)
    assert _rel(f["t_q"][0], c1) < 1e-12 and not f["warnings"]
