"""The thirty-seventh hostile pass over the Python module and the library
under it (issue 18).

The pass called the module with numpy scalars and 0-d arrays, bools, huge
ints, strided and NaN arrays, strings with NUL, nested calls from progress
callbacks, SystemExit in one, results mutated and run again, and checked the
physics of results (a column's kinetic energy, F_max ~ v^(6/5), tau ~
v^(-1/5)): about 150 calls. Faults found, each checked here:
- a sweep grid given as the string 'A:B' was expanded into a list before any
  bound: grid={"n": "1:9223372036854775807"} raised a bare MemoryError naming
  nothing, where range(1, 2**80) is refused naming the key. The string now
  goes through the range's bound.
- a layer grid's x check (x = 0, 1e-300: one block position, one impact run
  as two groups of layer-stats) covered only the samples the check pass keeps
  in memory, up to 1e5 particles: on a row of 100001 discs both cases ran (8 s
  each). It now holds for every sample the check reads.
- through ctypes: gw_check_range took a NaN bound as none (any finite value
  passed) and a sweep model's case ran the defaults for a negative count of
  keys (GW_OK); both are GW_EINVAL naming the bound or nkeys now.
"""
import ctypes
import math
import subprocess

import numpy as np
import pytest

import granwave


def _refused(f, *needles):
    with pytest.raises(granwave.GranwaveValueError) as ei:
        f()
    assert ei.value.status == -1
    for n in needles:
        assert n in str(ei.value), (n, str(ei.value))
    assert "\n" not in str(ei.value)


# --- a grid range as text is bounded as a range object ---

# (not 0:1000000000 here: on the code before, a list of 1e9 ints takes all the memory there is)
@pytest.mark.parametrize("text", ["1:9223372036854775807", "-5:10000000000"])
def test_text_range_bounded(text):
    _refused(lambda: granwave.sweep("chain", grid={"n": text}), "'n'", text, "more than 1e9 values")


def test_text_range_control():
    """the texts that ran still run, as their ranges (pass before too)"""
    for text in ("1:3", "+1:3", " 1 : 3 "):
        s = granwave.sweep("chain", grid={"n": text}, t_max=1e-3)
        assert list(s.n) == [1, 2, 3]
        assert s.f_max[0] == granwave.chain(n=1, t_max=1e-3).f_max


# --- the x check on a sample above the check's memory (1e5 particles) ---

def _row_sample(path, n, r=0.01):
    """n touching discs of radius r in a row on the floor: one particle high,
    at rest, no settling recorded"""
    i = np.arange(n)
    xyz = np.column_stack(((2 * i + 1) * r, np.full(n, r), np.full(n, r)))
    with open(path, "w") as f:
        f.write(f"granwave-layer-sample 1\nwidth {2 * r * n!r}\nrm {r!r}\nvolume_ratio 1\nseed 0\nn {n}\n")
        np.savetxt(f, xyz, fmt="%.17g")


@pytest.mark.parametrize("n", [1000, 100001])
def test_x_check_any_sample_size(tmp_path, n):
    path = tmp_path / f"row{n}.txt"
    _row_sample(path, n)
    _refused(lambda: granwave.sweep("layer", grid={"x": [0, 1e-300]}, sample=str(path), t_max=1e-4, vi=1),
             "x: 0 and 1e-300 m put the block at one position", f"width {2 * 0.01 * n:g} m")


def test_x_check_cli(program, tmp_path):
    """`sweep --check` on the 100001-disc row: x = 0, 1e-300 refused (exit 2,
    one line, nothing written), x = 0, 1 (two impacts 1 m apart) passes"""
    path = tmp_path / "row.txt"
    _row_sample(path, 100001)
    for xs, code in (("0, 1e-300", 2), ("0, 1", 0)):
        ini = tmp_path / "a.ini"
        ini.write_text(f"[sweep]\nmodel = layer\nout = o\n[grid]\nx = {xs}\n[params]\nsample = {path}\n"
                       "t-max = 1e-4\nvi = 1\n")
        p = subprocess.run([program, "sweep", str(ini), "--check"], capture_output=True, text=True, timeout=60)
        assert p.returncode == code, (xs, p.stderr)
        assert not (tmp_path / "o").exists()
        if code == 2:
            lines = p.stderr.strip().splitlines()
            assert len(lines) == 1 and "case 1: x: 0 and 1e-300 m put the block at one position" in lines[0]


# --- the library's checks through ctypes ---

def _lib():
    """a handle of its own, so the prototypes set here are not the module's"""
    return ctypes.CDLL(granwave.library_path)


def _err():
    class Err(ctypes.Structure):
        _fields_ = [("msg", ctypes.c_char * 512)]
    return Err()


def test_check_range_nan_bounds():
    f = _lib().gw_check_range
    f.restype = ctypes.c_int
    f.argtypes = [ctypes.c_double, ctypes.c_char_p, ctypes.c_double, ctypes.c_double, ctypes.c_void_p]
    e = _err()
    for lo, hi, needle in ((math.nan, 2.0, "lo is NaN"), (0.0, math.nan, "hi is NaN"), (5.0, 2.0, "lo > hi")):
        assert f(1.0, b"a", lo, hi, ctypes.byref(e)) == -1
        assert needle in e.msg.decode() and "a: " in e.msg.decode()
    assert f(1.0, b"a", 0.0, 2.0, ctypes.byref(e)) == 0  # control
    assert f(3.0, b"a", 0.0, 2.0, ctypes.byref(e)) == -1 and "a: 3 is outside [0, 2]" in e.msg.decode()


def test_sweep_model_negative_count():
    f = _lib().gw_chain_sweep_run_part
    f.restype = ctypes.c_int
    f.argtypes = [ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.POINTER(ctypes.c_double), ctypes.c_void_p,
                  ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]
    out = (ctypes.c_double * 64)()
    e = _err()
    names = (ctypes.c_char_p * 1)(b"n")
    values = (ctypes.c_char_p * 1)(b"2")
    assert f(-1, names, values, out, None, None, None, ctypes.byref(e)) == -1
    assert "nkeys: -1" in e.msg.decode()
    assert f(1, names, values, out, None, None, None, ctypes.byref(e)) == 0  # control: the sweep's row of n = 2
    s = granwave.sweep("chain", grid={"n": [2]})
    first = [k for k in s.keys() if k not in ("n", "ncases", "warnings")][0]
    assert out[0] == s[first][0]
