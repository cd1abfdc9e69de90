"""The forty-first hostile pass over the Python module and, through ctypes, the
library calls it does not wrap (issue 18).

The module reads a layer sample from a file only, and the reader refuses a
particle that is not finite (GranwaveValueError naming the line and the
particle, for `layer_impact` and a layer `sweep` alike). A caller who builds a
sample in memory with ctypes reaches gw_layer_impact_check, the check a sweep
runs before its cases: it took a particle of a NaN or infinite x, y or r, a
radius <= 0 or a centre outside the walls (0, GW_OK), which gw_layer_impact
then refused when it built the layer. The check and the run now read the
particles through one check (layer_particle_check) and give the same status
and message, naming the particle's index and its field. Each C call runs in a
child process: gw_layer_impact_rest_check read a NULL y (SIGSEGV).
"""
import ctypes
import math
import subprocess
import sys

import pytest

import granwave
from sample_mirror import _Sample  # the struct's mirror, shared

GW_EINVAL = -1


def _opaque(lib, name):
    """A struct the test never reads, as bytes of the library's size (returned
    by value through a hidden pointer: every one here is above 16 bytes)."""
    lib.gw_struct_size.restype = ctypes.c_size_t
    size = lib.gw_struct_size(name.encode())
    assert size > 16, name
    return type(name, (ctypes.Structure,), {"_fields_": [("b", ctypes.c_ubyte * size)]})


@pytest.fixture(scope="module")
def lib():
    lib = ctypes.CDLL(granwave.library_path)
    lib.gw_layer_sample_size.restype = ctypes.c_size_t
    assert ctypes.sizeof(_Sample) == lib.gw_layer_sample_size()
    return lib


def _sample(x=(0.3, 0.5, 0.7), y=(0.1, 0.1, 0.1), r=(0.1, 0.1, 0.1)):
    d = lambda v: (ctypes.c_double * 3)(*v)  # noqa: E731
    return _Sample(n=3, width=1.0, rm=0.1, volume_ratio=0, porosity=float("nan"), seed=0, mass_law=0, clump_mass=0,
                   x=d(x), y=d(y), r=d(r), body=None)


def _check_and_run(lib, s):
    """gw_layer_impact_check and gw_layer_impact of the default impact on s:
    (status, message) of each."""
    IP, LP, SP, RES = (_opaque(lib, n) for n in ("gw_layer_impact_params", "gw_layer_params", "gw_solver_params",
                                                 "gw_layer_impact_result"))
    lib.gw_layer_impact_params_default.restype = IP
    lib.gw_layer_params_default.restype = LP
    lib.gw_solver_params_default.restype = SP
    ip, lp, sp, res = lib.gw_layer_impact_params_default(), lib.gw_layer_params_default(), \
        lib.gw_solver_params_default(), RES()
    verlet = ctypes.c_void_p.in_dll(lib, "gw_solver_verlet")
    ec, er = ctypes.create_string_buffer(512), ctypes.create_string_buffer(512)
    rc = lib.gw_layer_impact_check(ctypes.byref(s), ctypes.byref(ip), ec)
    rr = lib.gw_layer_impact(ctypes.byref(s), ctypes.byref(lp), ctypes.byref(ip), verlet, ctypes.byref(sp),
                             ctypes.byref(res), er)
    lib.gw_layer_impact_result_free(ctypes.byref(res))
    return (rc, ec.value.decode()), (rr, er.value.decode())


BAD = [("x", 1, math.nan, "particle 1: x = nan m is not a finite number"),
       ("x", 1, math.inf, "particle 1: x = inf m is not a finite number"),
       ("y", 2, -math.inf, "particle 2: y = -inf m is not a finite number"),
       ("r", 0, math.nan, "particle 0: r = nan m is not a finite number"),
       ("r", 1, 0.0, "particle 1: radius r = 0 m must be positive"),
       ("r", 1, -0.1, "particle 1: radius r = -0.1 m must be positive"),
       # (outside the walls before session 43; now the box every sample is held to)
       ("x", 1, -0.05, "particle 1: particle outside the box (0 <= x <= 1, y >= 0)")]


@pytest.mark.parametrize("field, i, value, named", BAD)
def test_impact_check_and_run_agree(lib, field, i, value, named):
    cols = {"x": [0.3, 0.5, 0.7], "y": [0.1] * 3, "r": [0.1] * 3}
    cols[field][i] = value
    check, run = _check_and_run(lib, _sample(**cols))
    assert check[0] == GW_EINVAL and named in check[1], check  # (0, '') before: the check took it
    assert run == check, (run, check)


def test_impact_check_takes_the_sample_as_built(lib):
    # control: the three discs as built pass the check (the run is not made: 2 s of impact)
    IP = _opaque(lib, "gw_layer_impact_params")
    lib.gw_layer_impact_params_default.restype = IP
    ip = lib.gw_layer_impact_params_default()
    err = ctypes.create_string_buffer(512)
    assert lib.gw_layer_impact_check(ctypes.byref(_sample()), ctypes.byref(ip), err) == 0, err.value


def _child(code):
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, (p.returncode, p.stderr[-400:])
    return p.stdout.strip()


def test_rest_check_null_y():
    """gw_layer_impact_rest_check(s with y NULL): SIGSEGV before; now
    GW_EINVAL naming y, and the discs as built pass (in a child process)."""
    code = f"""
import ctypes, sys
sys.path.insert(0, {str(__import__('pathlib').Path(__file__).parent)!r})
from test_hostile_pass41 import _sample, _opaque
lib = ctypes.CDLL({granwave.library_path!r})
LP = _opaque(lib, "gw_layer_params")
lib.gw_layer_params_default.restype = LP
lp = lib.gw_layer_params_default()
err = ctypes.create_string_buffer(512)
s = _sample()
print(lib.gw_layer_impact_rest_check(ctypes.byref(s), ctypes.byref(lp), b"p", err), err.value.decode())
s.y = None
print(lib.gw_layer_impact_rest_check(ctypes.byref(s), ctypes.byref(lp), b"p", err), err.value.decode())
"""
    lines = _child(code).splitlines()
    assert lines[0] == "0 ", lines
    assert lines[1].startswith("-1 sample 'p': n = 3 particles, y NULL"), lines


def test_module_sample_file_refused_alike(tmp_path):
    """The module's way in, a file: a NaN particle is refused by the reader,
    for layer_impact and a layer sweep alike, naming the line and the
    particle (a guard: so before)."""
    p = tmp_path / "s.txt"
    p.write_text("granwave-layer-sample 1\nwidth 1\nrm 0.1\nn 3\n0.3 0.1 0.1\nnan 0.1 0.1\n0.7 0.1 0.1\n")
    with pytest.raises(granwave.GranwaveValueError) as e1:
        granwave.layer_impact(sample=str(p), t_max=1e-4)
    with pytest.raises(granwave.GranwaveValueError) as e2:
        granwave.sweep("layer", grid={"sample": [str(p)], "vi": [1, 2]}, t_max=1e-4)
    for e in (e1, e2):
        assert "line 6" in str(e.value) and "particle 2 of 3" in str(e.value), str(e.value)
