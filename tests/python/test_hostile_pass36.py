"""The thirty-sixth hostile pass over the Python module, and two gaps of the
layer sweep that the thirty-fifth pass left (issue 18).

The pass called every function with keywords of the wrong type, NaN,
infinities, 1e308 and subnormals, numpy arrays of other dtypes, shapes,
strides and read-only ones, huge lists and generators, KeyboardInterrupt in
progress callbacks and calls from threads (about 130 calls). The module held
for all of them but one class: refusals raised by the module itself, not the
library, in sweep() (an unknown model, an empty grid, an empty list of grid
values, a value with a newline, ';' or '#', a value with blanks around it, a
grid value with ',', a list item 'A:B') and in params() (an unknown study)
were plain ValueErrors: `except granwave.GranwaveError` missed them, where the
docs (library.md, Errors) say a bad value is a GranwaveValueError naming the
keyword. They are now.

The layer sweep's gaps:
- `x = 0, 1e-300` put the block at one position (0.5 width + 1e-300 is
  0.5 width): the same impact ran as two groups of layer-stats. The check pass
  now refuses two values of x at one block position (the same point of the
  same placement), naming x and both values; x = 0, 0.01 runs.
- q = inf (the load ratio of an impact without gravity under other-settling)
  was null in layer-impact's JSON, which is also "undefined", and inf in the
  sweep's table. The JSON now writes the text "inf", which float() reads as
  the table's value; Python's sweep gives the float inf.
"""
import json
import math
import subprocess
import warnings

import numpy as np
import pytest

import granwave


def _gw_value_error(f, *needles):
    with pytest.raises(granwave.GranwaveError) as ei:
        f()
    assert isinstance(ei.value, granwave.GranwaveValueError) and isinstance(ei.value, ValueError)
    assert ei.value.status == -1  # GW_EINVAL
    for n in needles:
        assert n in str(ei.value), (n, str(ei.value))
    assert "\n" not in str(ei.value)


# --- the module's own refusals are GranwaveValueErrors naming the keyword ---

@pytest.mark.parametrize("call, needles", [
    (lambda: granwave.sweep("nope", grid={"n": [1]}), ("sweep: unknown model 'nope'",)),
    (lambda: granwave.sweep("chain", grid={}), ("sweep: grid needs at least one key",)),
    (lambda: granwave.sweep("chain", grid={"n": []}), ("n: empty list of grid values",)),
    (lambda: granwave.sweep("chain", grid={"n": range(0)}), ("n: empty list",)),
    (lambda: granwave.sweep("chain", grid={"n": ["1\nvimp = 5"]}), ("n: value", "cannot go into a sweep")),
    (lambda: granwave.sweep("chain", grid={"n": [1]}, material="steel # x"), ("material: value",)),
    (lambda: granwave.sweep("chain", grid={"n": ["1,2"]}), ("n: a grid value holds ','",)),
    (lambda: granwave.sweep("chain", grid={"n": ["1:3", "5"]}), ("'n': a list item '1:3' is a range",)),
    (lambda: granwave.params("bogus"), ("no study 'bogus'",)),
])
def test_module_refusals_are_granwave_errors(call, needles):
    _gw_value_error(call, *needles)


def test_blank_sample_value_is_granwave_error(tmp_path):
    s = tmp_path / "s.txt"
    s.write_text("")
    _gw_value_error(lambda: granwave.sweep("layer", grid={"vi": [5, 6]}, sample=" " + str(s)),
                    "sample: value", "begins or ends with a blank")


# --- neighbours that held (controls; they pass on the code before too) ---

@pytest.mark.parametrize("kw, needle", [
    (dict(n=1, vimp=float("nan")), "vimp"), (dict(n=1, vimp=float("inf")), "vimp"),
    (dict(n=1, vimp=1e308), "vimp"), (dict(n=1, vimp=1e-308), "vimp"), (dict(n=1, vimp=5e-324), "vimp"),
    (dict(n=2.5), "n"), (dict(n=2 ** 70), "n"), (dict(n=np.uint64(2 ** 63)), "n"),
    (dict(n=1, material="steel\x00x"), "material"), (dict(n=2, radii=np.array([4e-3, np.nan])), "radii"),
    (dict(n=2, radii=[4e-3]), "radii"), (dict(n=1, sheet="pvc", sheet_law="material", sheet_yield=float("nan")),
                                         "sheet_yield"),
])
def test_chain_hostile_values(kw, needle):
    with pytest.raises(granwave.GranwaveValueError, match=rf"^chain: {needle}: "):
        granwave.chain(**kw)


@pytest.mark.parametrize("kw, needle", [
    (dict(n=2 + 0j), "n"), (dict(n=1, material=b"steel"), "material"),
    (dict(n=2, radii=np.full((2, 1), 4e-3)), "radii"), (dict(n=2, radii=np.array([True, True])), "radii"),
    (dict(n=2, radii=np.array(["2020-01-01", "2020-01-02"], dtype="datetime64[D]")), "radii"),
])
def test_chain_wrong_types(kw, needle):
    with pytest.raises(TypeError, match=rf"^chain: {needle}: "):
        granwave.chain(**kw)


def test_arrays_of_other_layouts_run_as_lists():
    """float32, non-contiguous and read-only radii run as the same list of doubles."""
    want = granwave.chain(n=2, radii=[4e-3, 4e-3]).f_max
    ro = np.full(2, 4e-3)
    ro.setflags(write=False)
    for radii in (np.full(4, 4e-3)[::2], ro, np.array([4e-3, 4e-3], dtype=np.longdouble)):
        assert granwave.chain(n=2, radii=radii).f_max == want
    f32 = granwave.chain(n=2, radii=np.array([4e-3, 4e-3], dtype=np.float32)).f_max
    assert abs(f32 / want - 1) < 1e-5  # 4e-3 in float32 is 1.9e-10 m off


def test_huge_lists_and_endless_generators():
    with pytest.raises(granwave.GranwaveValueError, match=r"^falcon: vimp: 3000000 items, at most 2000000"):
        granwave.falcon(n=(1, 2), vimp=[0.3] * 3000000)
    with pytest.raises(granwave.GranwaveValueError, match=r"^falcon: vimp: more than 2000000 items"):
        granwave.falcon(n=(1, 2), vimp=(0.1 + i * 1e-3 for i in iter(int, 1)))
    with pytest.raises(granwave.GranwaveValueError, match=r"'vimp': 600000 items, at most 524288"):
        granwave.sweep("chain", grid={"n": [1], "vimp": np.linspace(0.1, 0.2, 600000)})


def test_keyboard_interrupt_in_progress():
    def stop(done, total):
        raise KeyboardInterrupt
    with pytest.raises(KeyboardInterrupt):
        granwave.sweep("chain", grid={"n": [1, 2, 3]}, progress=stop, jobs=1)
    assert granwave.chain(n=2).converged  # the module goes on after it


# --- the layer sweep: two values of x at one block position ---

@pytest.fixture(scope="module")
def small_sample(program, tmp_path_factory):
    path = tmp_path_factory.mktemp("pass36") / "s.txt"
    subprocess.run([program, "layer-make", "--n", "40", "--width-rm", "16", "--seed", "1", "--out", str(path),
                    "--quiet"], check=True, capture_output=True)
    return path


def test_sweep_x_one_position_refused(small_sample):
    with pytest.raises(granwave.GranwaveValueError) as ei:
        granwave.sweep("layer", grid={"x": [0, 1e-300]}, sample=str(small_sample), t_max=0.002)
    msg = str(ei.value)
    assert "x: 0 and 1e-300 m put the block at one position" in msg and "\n" not in msg
    # and at one impact point of several, 1e-17 beside 0 (0.5 width + 1e-17 is 0.5 width)
    with pytest.raises(granwave.GranwaveValueError, match=r"x: 0 and 1e-17 m put the block at one position"):
        granwave.sweep("layer", grid={"x": [0, 1e-17], "point": range(3)}, points=3, sample=str(small_sample),
                       t_max=0.002)


def test_sweep_x_one_position_cli(program, small_sample, tmp_path):
    ini = tmp_path / "a.ini"
    ini.write_text(f"[sweep]\nmodel = layer\nout = o\n[grid]\nx = 0, 1e-300\n[params]\nsample = {small_sample}\n"
                   "t-max = 0.002\n")
    p = subprocess.run([program, "sweep", str(ini), "--check"], capture_output=True, text=True)
    assert p.returncode == 2 and not (tmp_path / "o").exists()
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1 and "case 1: x: 0 and 1e-300 m put the block at one position" in lines[0]


def test_sweep_x_apart_runs(small_sample):
    """Controls: x apart, and two placements sharing one position (two groups), pass the check."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", granwave.GranwaveWarning)
        s = granwave.sweep("layer", grid={"x": [0, 0.01]}, sample=str(small_sample), t_max=0.002, until="verdict")
    assert list(s.x_impact) == [0.0, 0.01]


# --- q = inf: the JSON's "inf", the table's inf, Python's float inf ---

@pytest.fixture(scope="module")
def cut_pile(program, tmp_path_factory):
    """A pile cut by t-max in the air (floor load 0): hit without gravity under
    other-settling it runs with q = W_settled / W_impact = inf."""
    path = tmp_path_factory.mktemp("pass36q") / "cut.txt"
    subprocess.run([program, "layer-make", "--n", "8", "--width-rm", "6", "--seed", "1", "--t-max", "0.2", "--out",
                    str(path), "--quiet"], check=True, capture_output=True)
    return path


def test_load_ratio_inf_everywhere(program, cut_pile, tmp_path):
    out = tmp_path / "o"
    p = subprocess.run([program, "layer-impact", "--sample", str(cut_pile), "--gravity", "0", "--other-settling",
                        "--t-max", "0.01", "--json", "--out", str(out)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    for text in (p.stdout, (out / "impact.json").read_text()):
        q = json.loads(text)["settings"]["sample_settled"]["load_ratio"]
        assert q == "inf" and float(q) == math.inf  # it was None, JSON's "undefined"
    # the sweep's table and Python's sweep: the same value
    ini = tmp_path / "g0.ini"
    ini.write_text(f"[sweep]\nmodel = layer\nout = {tmp_path / 'g0'}\n[grid]\nvi = 5, 6\n[params]\n"
                   f"sample = {cut_pile}\ngravity = 0\nother-settling = 1\nt-max = 0.01\n")
    p = subprocess.run([program, "sweep", str(ini), "--quiet"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    rows = [r for r in (tmp_path / "g0" / "results.csv").read_text().splitlines() if not r.startswith("#")]
    col = rows[0].split(",").index("settled_load_ratio")
    assert [r.split(",")[col] for r in rows[1:]] == ["inf", "inf"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", granwave.GranwaveWarning)
        s = granwave.sweep("layer", grid={"vi": [5, 6]}, sample=str(cut_pile), gravity=0, other_settling=True,
                           t_max=0.01)
    assert list(s.settled_load_ratio) == [math.inf, math.inf]


def test_load_ratio_finite_stays_a_number(program, cut_pile):
    """Control: with gravity q is a number (the pile settled at 9.81; the impact at 4.905: q = 2)."""
    p = subprocess.run([program, "layer-impact", "--sample", str(cut_pile), "--gravity", "4.905",
                        "--other-settling", "--t-max", "0.002", "--json"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    q = json.loads(p.stdout)["settings"]["sample_settled"]["load_ratio"]
    assert isinstance(q, (int, float)) and not isinstance(q, bool) and abs(q - 2) < 1e-12
