"""The fortieth hostile pass over the Python module and, through ctypes, the
library calls it does not wrap (issue 18).

The pass gave every keyword of layer_stats, sweep, params and the studies
wrong types, numpy arrays of other dtypes, shapes and strides, NaN, huge
values, keyword misuse and callbacks that raise or return odd values (about
90 calls). One fault in the module: `fit`, a list of names and no file, took
a path object or bytes as its text (`fit=pathlib.Path("beta,a_over_b")` ran)
and refused a list of names as "expected a str or a path", a path it never
takes. Through ctypes, what the C pass found in calls a Python user reaches
with ctypes: gw_chain_falcon_speeds took a NaN gravity as Earth's (GW_OK),
gw_layer_until_name named 9 "rebound", gw_chain_kc of a negative k was
negative and gw_solver_tolerances_check with no names wrote "(null): ...".
"""
import ctypes
import math
import pathlib

import pytest

import granwave
from conftest import write_synthetic_sweep


@pytest.fixture(scope="module")
def table(tmp_path_factory):
    return str(write_synthetic_sweep(tmp_path_factory.mktemp("p40") / "results.csv"))


@pytest.mark.parametrize("value", [["beta", "a_over_b"], ("beta", "a_over_b"), pathlib.Path("beta,a_over_b"),
                                   b"beta,a_over_b", 3])
def test_fit_takes_text_only(table, value):
    with pytest.raises(TypeError) as ei:
        granwave.layer_stats(table, fit=value)
    m = str(ei.value)
    assert m.startswith("layer_stats: fit: expected a str (comma-separated names") and "path" not in m, m


def test_fit_as_text_and_paths_as_paths(table):
    # control: the text runs as the default, and the table's path as a path object
    base = granwave.layer_stats(table)
    assert granwave.layer_stats(table, fit="beta,a_over_b") == base
    assert granwave.layer_stats(pathlib.Path(table)) == base
    assert granwave.layer_stats(table.encode()) == base


# --- through ctypes ---

class _Err(ctypes.Structure):
    _fields_ = [("msg", ctypes.c_char * 512)]


@pytest.fixture(scope="module")
def lib():
    return ctypes.CDLL(granwave.library_path)


def test_falcon_speeds_gravity(lib):
    f = lib.gw_chain_falcon_speeds
    f.restype = ctypes.c_int
    D = ctypes.POINTER(ctypes.c_double)
    f.argtypes = [D, ctypes.c_int, D, ctypes.c_int, ctypes.c_double, D, D, ctypes.c_void_p]
    vimp, heights = (ctypes.c_double * 1)(0.3), (ctypes.c_double * 1)(5.1)
    v, h, e = (ctypes.c_double * 2)(), (ctypes.c_double * 2)(), _Err()
    for g in (math.nan, math.inf, -1.0):  # NaN ran as Earth's with GW_OK
        assert f(vimp, 1, heights, 1, g, v, h, ctypes.byref(e)) == -1
        assert e.msg.decode().startswith("gravity: "), e.msg
    assert f(vimp, 1, heights, 1, 0.0, v, h, ctypes.byref(e)) == 0  # control: Earth's fall
    assert abs(v[1] - math.sqrt(2 * 9.81 * 5.1e-3)) < 1e-15


def test_names_and_closed_forms(lib):
    lib.gw_layer_until_name.restype = ctypes.c_char_p
    lib.gw_layer_until_name.argtypes = [ctypes.c_int]
    assert lib.gw_layer_until_name(9) == b"unknown"  # "rebound" before
    assert lib.gw_layer_until_name(1) == b"verdict"
    lib.gw_chain_kc.restype = ctypes.c_double
    lib.gw_chain_kc.argtypes = [ctypes.c_double]
    assert math.isnan(lib.gw_chain_kc(-1e9))  # negative before
    assert lib.gw_chain_kc(2e9) == pytest.approx(2 * lib.gw_chain_kc(1e9), rel=1e-14)
    f = lib.gw_solver_tolerances_check
    f.restype = ctypes.c_int
    f.argtypes = [ctypes.c_double, ctypes.c_double, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_void_p]
    e = _Err()
    assert f(-1.0, 1e-9, None, None, ctypes.byref(e)) == -1
    assert e.msg.decode().startswith("rtol: -1 is outside"), e.msg  # "(null): " before
