"""The fifty-first hostile pass through Python (about 140 calls: numpy
scalars of every kind, bytes, Decimal, Fraction, surrogates, NUL and control
characters in values, keywords and model names, generators, strided and
big-endian arrays, results pickled, copied and indexed, sweeps given INI
syntax inside values, threads running good and bad calls at once). The
module refused what it should; what it reached in the library:

- layer_make recorded an `out` longer than 255 characters in the sample's
  header as "out": null (gw_param_json went through a 256-byte buffer): the
  path is now written whole.
- layer_stats refused fit="beta, a_over_b" as "unknown parameter
  ' a_over_b'", where every other list takes blanks around its items.

Through ctypes: gw_path_join joined an empty directory as "/NAME" (a file in
the root directory), gw_stats_b31_eval was NaN from x = 1e154 where B.31 has
a value, gw_stats_b31_min gave a minimum of a curve that is NaN everywhere
(tan gamma 0), and gw_parse_int_range read a NULL name (SIGSEGV; run in a
child interpreter). Controls next to each.
"""
import ctypes
import json
import math
import subprocess
import sys
import warnings

import pytest

import granwave
from conftest import write_synthetic_sweep


def _settings(path):
    with open(path) as f:
        for line in f:
            if line.startswith("# settings: "):
                return json.loads(line[len("# settings: "):])
    raise AssertionError("no settings line in " + str(path))


def _make(out):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        granwave.layer_make(n=10, width_rm=8, t_max=0.05, out=str(out))


def test_long_out_recorded_in_the_sample(tmp_path):
    d = tmp_path / ("d" * 150) / ("e" * 120)
    d.mkdir(parents=True)
    out = d / "s.txt"
    assert len(str(out)) > 255
    _make(out)
    assert _settings(out)["out"] == str(out)


def test_short_out_recorded_control(tmp_path):
    out = tmp_path / "s.txt"
    _make(out)
    assert _settings(out)["out"] == str(out)


@pytest.fixture(scope="module")
def table(tmp_path_factory):
    return str(write_synthetic_sweep(tmp_path_factory.mktemp("p51") / "results.csv"))


@pytest.mark.parametrize("fit", ["beta, a_over_b", " beta , a_over_b ", "beta,\ta_over_b"])
def test_fit_names_with_blanks(table, fit):
    assert granwave.layer_stats(table, fit=fit) == granwave.layer_stats(table, fit="beta,a_over_b")


def test_fit_unknown_name_quoted_without_its_blanks(table):
    with pytest.raises(granwave.GranwaveValueError) as e:
        granwave.layer_stats(table, fit="beta, gamma")
    assert "unknown parameter 'gamma'" in str(e.value)


def _lib():
    return ctypes.CDLL(granwave.library_path)


def test_path_join_empty_dir():
    lib = _lib()
    f = lib.gw_path_join
    f.argtypes = [ctypes.c_char_p, ctypes.c_size_t, ctypes.c_char_p, ctypes.c_char_p]
    f.restype = ctypes.c_int
    buf = ctypes.create_string_buffer(b"keep", 64)
    assert f(buf, 64, b"", b"journal.csv") == -1 and buf.value == b"keep"
    assert f(buf, 64, b"out", b"journal.csv") == 0 and buf.value == b"out/journal.csv"  # control


class _B31(ctypes.Structure):
    _fields_ = [("offset", ctypes.c_double), ("beta", ctypes.c_double), ("a_over_b", ctypes.c_double),
                ("tan_gamma", ctypes.c_double)]


def _b31():
    lib = _lib()
    ev, mn = lib.gw_stats_b31_eval, lib.gw_stats_b31_min
    ev.argtypes = [ctypes.POINTER(_B31), ctypes.c_double]
    ev.restype = ctypes.c_double
    mn.argtypes = [ctypes.POINTER(_B31), ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_double)]
    mn.restype = None
    return ev, mn


def test_b31_far_out():
    ev, _ = _b31()
    p = _B31(0.1, 1.0, 2.0, 0.5)  # K = 1
    x = 1e200
    assert math.isclose(ev(ctypes.byref(p), x), 0.1 + x / ((math.sqrt(2) + 1) * 1.0), rel_tol=1e-14)
    # control: an ordinary x as B.31 gives it
    u, r = 1.5, math.sqrt(1.5 ** 2 + 2.5 ** 2)
    assert ev(ctypes.byref(p), 2.5) == pytest.approx(0.1 + 2.5 * 2.5 / (r + u), rel=1e-15)


def test_b31_min_of_no_curve():
    ev, mn = _b31()
    xm, fm = ctypes.c_double(7), ctypes.c_double(7)
    mn(ctypes.byref(_B31(0.1, 1.0, 2.0, 0.0)), ctypes.byref(xm), ctypes.byref(fm))
    assert math.isnan(xm.value) and math.isnan(fm.value)
    assert math.isnan(ev(ctypes.byref(_B31(0.1, 1.0, 2.0, 0.0)), 2.0))
    mn(ctypes.byref(_B31(0.1, 1.0, 2.0, 0.5)), ctypes.byref(xm), ctypes.byref(fm))  # control
    assert xm.value == 1.0 and fm.value == 1.1


def test_parse_int_range_null_name():
    code = ("import ctypes, granwave\n"
            "lib = ctypes.CDLL(granwave.library_path)\n"
            "a, b = ctypes.c_long(), ctypes.c_long()\n"
            "e = ctypes.create_string_buffer(512)\n"
            "f = lib.gw_parse_int_range\n"
            "f.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_long, ctypes.c_long, ctypes.c_void_p,"
            " ctypes.c_void_p, ctypes.c_void_p]\n"
            "print(f(b'1:x', None, 0, 10, ctypes.byref(a), ctypes.byref(b), e), e.value.decode())\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, (r.returncode, r.stderr)
    assert r.stdout.startswith("-1 value: '1:x' is not a range"), r.stdout
