"""granwave.sweep_n: the library's N x v grid (gw_chain_sweep_n_warned) from
Python, against the C call (tests/gw_grid_probe, built beside the program):
the same values bit for bit (f_max, tau_n, eps_eff, steps, converged of every
case) and the same warnings (the grid's "no effect" lines with their count
over its cases, the collisions that did not end), each issued as a
GranwaveWarning; the module had no such call (the studies on the grid,
falcon and the rest, gave their own numbers only).
"""
import os
import re
import subprocess
import warnings
from pathlib import Path

import numpy as np
import pytest

import granwave

PROGRAM = os.environ.get("GRANWAVE_PROGRAM", str(Path(__file__).resolve().parents[2] / "build" / "granwave"))
PROBE = str(Path(PROGRAM).parent / "tests" / "gw_grid_probe")


def c_grid(lo, hi, speeds, **kw):
    """The C call's cases {(iv, N): (f_max, tau_n, eps_eff, steps, converged)} and warnings."""
    assert Path(PROBE).exists(), f"the C caller {PROBE} is not built (tests/CMakeLists.txt: gw_grid_probe)"
    args = [PROBE, "grid", str(lo), str(hi), ",".join(map(repr, speeds))]
    args += [f"{k.replace('_', '-')}={v}" for k, v in kw.items()]
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    cases, said = {}, []
    for line in out.splitlines():
        if line.startswith("case "):
            _, iv, n, f, t, e, s, c = line.split()
            cases[int(iv), int(n)] = (float(f), float(t), float(e), int(s), int(c))
        elif line.startswith("warning: "):
            said.append(line[len("warning: "):])
    return cases, said


def keywords(text):
    """A C text's flags as Python's keywords ("--sensor-damping" as sensor_damping)."""
    return re.sub(r"--([a-z][a-z0-9-]*)", lambda m: m.group(1).replace("-", "_"), text)


def py_grid(lo, hi, speeds, **kw):
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        g = granwave.sweep_n((lo, hi), speeds, jobs=1, **kw)
    issued = [str(w.message) for w in got if issubclass(w.category, granwave.GranwaveWarning)]
    return g, issued


def same(lo, hi, speeds, **kw):
    """Python's grid against the C call's: values bit for bit, warnings alike."""
    g, issued = py_grid(lo, hi, speeds, **kw)
    cases, said = c_grid(lo, hi, speeds, **kw)
    assert list(g.n) == list(range(lo, hi + 1)) and list(g.v_imp) == list(speeds)
    assert g.f_max.shape == (len(speeds), hi - lo + 1)
    for (iv, n), (f, t, e, s, c) in cases.items():
        j = n - lo
        assert (g.f_max[iv, j], g.tau_n[iv, j], g.steps[iv, j], bool(g.converged[iv, j])) == (f, t, s, bool(c))
        assert g.eps_eff[iv, j] == e or (np.isnan(g.eps_eff[iv, j]) and np.isnan(e))
    assert g.warnings == [keywords(t) for t in said]
    assert issued == ["sweep_n: " + t for t in g.warnings]
    return g


def test_dashpot_of_no_effect():
    g = same(1, 2, [0.3], sensor_mass=1e-2, sensor_stiffness=1e7, sensor_damping=1e-12)
    assert len(g.warnings) == 1
    assert g.warnings[0].startswith("the sensor body's dashpot has no effect in 2 of 2 cases (the first, case 0): ")
    assert (g.f_max > 0).all()


def test_guide_friction_over_two_speeds():
    g = same(1, 2, [0.2, 0.3], guide_viscous=1e-15)
    assert len(g.warnings) == 1 and "in 4 of 4 cases (the first, case 0)" in g.warnings[0]
    # each case is the single collision granwave.chain runs, bit for bit
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        one = granwave.chain(n=2, vimp=0.2, guide_viscous=1e-15)
    assert g.f_max[0, 1] == one.f_max and g.tau_n[0, 1] == one.tau_n


def test_cases_cut_at_t_max():
    g = same(6, 7, [0.3], t_max=1.94e-4)
    assert list(g.converged[0]) == [True, False]
    assert len(g.warnings) == 1 and "1 of 2" in g.warnings[0]


def test_control_no_warning():
    g = same(1, 2, [0.3], sensor_mass=1e-2, sensor_stiffness=1e7, sensor_damping=10)
    assert g.warnings == []


def test_refused_inputs():
    with pytest.raises(TypeError, match="trace"):
        granwave.sweep_n((1, 2), [0.3], trace=True)
    with pytest.raises(granwave.GranwaveValueError, match="vimp"):
        granwave.sweep_n((1, 2), [0.3, -1.0])
    with pytest.raises(granwave.GranwaveValueError, match="^sweep_n: n"):
        granwave.sweep_n((3, 2), [0.3])
    with pytest.raises(granwave.GranwaveValueError, match="^sweep_n: n: 1:100000"):
        granwave.sweep_n((1, 100000), [0.3])


def test_layer_stats_says_the_tables_warnings(tmp_path):
    """granwave.layer_stats lists (and issues) a table's "# warning:" lines
    first, once each, as layer-stats says them; its numbers unchanged."""
    src = Path(__file__).resolve().parents[2] / "data" / "measured" / "layer_diagram" / "results.csv"
    lines = src.read_text().splitlines(keepends=True)
    at = next(i for i, t in enumerate(lines) if not t.startswith("#"))
    text = "a warning of the sweep (case 3)"
    warned, plain = tmp_path / "warned.csv", tmp_path / "plain.csv"
    warned.write_text("".join(lines[:at] + [f"# warning: {text}\n"] * 2 + lines[at:]))
    plain.write_text("".join(lines))
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        a = granwave.layer_stats(str(warned))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        b = granwave.layer_stats(str(plain))
    said = f"{warned}: the sweep that wrote it warned: {text}"
    assert a.warnings[0] == said and a.warnings.count(said) == 1
    assert [str(w.message) for w in got if issubclass(w.category, granwave.GranwaveWarning)][0] == "layer_stats: " + said
    assert a.warnings[1:] == [t.replace(str(plain), str(warned)) for t in b.warnings]
    for k in ("groups", "diagrams", "boundary", "binary"):
        for c in b[k]:
            assert np.array_equal(np.asarray(a[k][c]), np.asarray(b[k][c]), equal_nan=a[k][c].dtype.kind == "f")
