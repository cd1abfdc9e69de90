"""The forty-eighth hostile pass through Python: a sweep table's settings
against the layer model's rows, and two library calls through ctypes.

layer_stats held a table's settings (its grid cells and "# param" lines) to a
domain of its own (rb-rm > 0, vi > 0, ...), so a table edited by hand with
values no layer sweep runs (rb-rm 1e308 or 1e-7, a height of 2e6 or a
subnormal 1e-320, an impact point 3.5, vi 1e308, density 1e7, points
2147483648) was analysed as if a sweep had run it. The reader now holds every
setting to the layer model's own rows (the ones a sweep's case is set with):
GranwaveValueError naming the line, the key and the row's range. Controls:
the table as written and its settings at the rows' closed ends run.

A grid value given twice was refused naming a line of the config the
module writes ("sweep: sweep:4: n: ..."), which the caller never sees: the
line is left out, the key named.

Through ctypes: gw_fit_linear of points near 1e300 gave a NaN line with GW_OK
(now the plain fit's line scaled), and gw_cases_run returned a case that
failed without a message with an empty one (now naming the case and the
status).
"""
import ctypes
import math
import warnings

import pytest

import granwave
from conftest import write_synthetic_sweep


def _edited(tmp_path, cell=None, before=None, after=None, params=()):
    """The synthetic table with column `cell` (1 rb-rm, 2 height-rm, 3 point)
    of every row holding `before` set to `after`, and `params` ("name = value")
    added to its "# param" lines."""
    path = write_synthetic_sweep(tmp_path / "results.csv")
    out = []
    for line in path.read_text().splitlines():
        if line.startswith("# param") and params:
            out.extend(f"# param {p}" for p in params)
        cells = line.split(",")
        if cell is not None and not line.startswith("#") and cells[0] != "case" and cells[cell] == before:
            cells[cell] = after
        out.append(",".join(cells))
    path.write_text("\n".join(out) + "\n")
    return path


REFUSED = [
    ("rb-rm 1e308", dict(cell=1, before="6", after="1e308"), "grid key rb-rm", "[1e-06, 1e+06]"),
    ("rb-rm 1e-7", dict(cell=1, before="0.5", after="1e-07"), "grid key rb-rm", "[1e-06, 1e+06]"),
    ("height-rm 2e6", dict(cell=2, before="21", after="2e6"), "grid key height-rm", "[0, 1e+06]"),
    ("height-rm subnormal", dict(cell=2, before="3", after="1e-320"), "grid key height-rm", "too small"),
    ("point 3.5", dict(cell=3, before="3", after="3.5"), "grid key point", "not an integer"),
    ("param vi 1e308", dict(params=("vi = 1e308",)), "param vi", "(0, 1000]"),
    ("param density 1e7", dict(params=("density = 1e7",)), "param density", "[1e-06, 1e+06]"),
    ("param points 2**31", dict(params=("points = 2147483648",)), "param points", "[1, 1000000000]"),
]


@pytest.mark.parametrize("label, edit, key, why", REFUSED, ids=[r[0] for r in REFUSED])
def test_setting_no_sweep_runs_refused(tmp_path, label, edit, key, why):
    path = _edited(tmp_path, **edit)
    with pytest.raises(granwave.GranwaveValueError) as ei:
        granwave.layer_stats(str(path))
    msg = str(ei.value)
    assert "results.csv:" in msg and key in msg and why in msg and "is not a value a sweep runs" in msg, msg
    assert "\n" not in msg


def test_table_and_closed_ends_run(tmp_path):
    """Controls: the table as written, and at rb-rm 1e6, vi 1000, density 1e-6."""
    plain = granwave.layer_stats(str(write_synthetic_sweep(tmp_path / "plain.csv")))
    assert len(plain["binary"]["rb_rm"]) == 6
    (tmp_path / "ends").mkdir()
    with warnings.catch_warnings():  # the B.31 fit at its box's edge, with rb-rm 1e6 in the diagram
        warnings.simplefilter("ignore", granwave.GranwaveWarning)
        ends = granwave.layer_stats(str(_edited(tmp_path / "ends", cell=1, before="6", after="1e6",
                                                params=("density = 1e-6",))))
    rb = sorted(ends["binary"]["rb_rm"])
    assert rb[-1] == 1e6 and rb[:-1] == sorted(plain["binary"]["rb_rm"])[:-1]


def _lib():
    return ctypes.CDLL(granwave.library_path)


class _Linfit(ctypes.Structure):
    _fields_ = [("c0", ctypes.c_double), ("c1", ctypes.c_double), ("c0_err", ctypes.c_double),
                ("c1_err", ctypes.c_double), ("r2", ctypes.c_double), ("max_rel_resid", ctypes.c_double),
                ("n", ctypes.c_int)]


def _fit(lib, x, y):
    arr = ctypes.c_double * len(x)
    f = _Linfit()
    lib.gw_fit_linear.argtypes = [ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_double), ctypes.c_int,
                                  ctypes.POINTER(_Linfit)]
    rc = lib.gw_fit_linear(arr(*x), arr(*y), len(x), ctypes.byref(f))
    return rc, f


@pytest.mark.parametrize("xs, ys", [(1e300, 1.0), (1.0, 1e300), (1e-160, 1.0)])
def test_fit_of_large_and_small_points(xs, ys):
    lib = _lib()
    x, y = [1.0, 2.0, 3.0, 4.0], [2.1, 3.9, 6.2, 7.8]
    rc0, p = _fit(lib, x, y)
    rc, f = _fit(lib, [v * xs for v in x], [v * ys for v in y])
    assert rc0 == 0 and rc == 0
    assert math.isclose(f.c1, p.c1 * ys / xs, rel_tol=1e-12) and math.isclose(f.c0, p.c0 * ys, rel_tol=1e-12)
    assert math.isclose(f.c1_err, p.c1_err * ys / xs, rel_tol=1e-12) and math.isclose(f.r2, p.r2, rel_tol=1e-12)


_CASE = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_long, ctypes.c_void_p)


def test_pool_case_failing_without_a_message():
    lib = _lib()
    lib.gw_cases_run.argtypes = [ctypes.c_long, ctypes.c_int, _CASE, ctypes.c_void_p, ctypes.c_void_p,
                                 ctypes.c_void_p, ctypes.c_char_p]
    case = _CASE(lambda ctx, k, err: -1 if k == 2 else 0)
    err = ctypes.create_string_buffer(512)
    rc = lib.gw_cases_run(5, 1, case, None, None, None, err)
    assert rc == -1
    assert "case 2 of 5" in err.value.decode() and "no message" in err.value.decode(), err.value


SAME_VALUES = [
    ({"n": [3, 3]}, "sweep: n: '3' and '3' in list '3, 3' are the same value"),
    ({"vimp": [0.1, 0.10]}, "sweep: vimp: '0.1' and '0.1'"),
    ({"material": ["steel", "steel"]}, "sweep: material: 'steel' and 'steel'"),
]


@pytest.mark.parametrize("grid, said", SAME_VALUES, ids=["n", "vimp", "material"])
def test_sweep_refusal_names_no_line_of_its_config(grid, said):
    """A grid value given twice was refused as "sweep: sweep:4: n: ...", a line
    of the config the module writes and the caller never sees; the key it
    names is the caller's."""
    with pytest.raises(granwave.GranwaveValueError) as ei:
        granwave.sweep("chain", grid)
    msg = str(ei.value)
    assert msg.startswith(said), msg
    assert "sweep:4" not in msg and "sweep: sweep" not in msg
