"""The fiftieth hostile pass through Python: a sweep's grid refusals named as
the call's others, and the column's closed forms through ctypes.

sweep("chain", grid={"n": "5:1"}) said "n: empty list of grid values" (the
reversed range taken as a list of none, not named), grid={"n": []} and a
grid value holding ',' named neither the call nor the grid: each now says
"sweep: [grid] n: ...", the reversed range as the library says it ("range
'5:1' is empty (start > end)").

Through ctypes: gw_chain_tau1 of a finite K above 4.5e307 N/m^1.5 was 0 s
(4 K overflowed; k = 1.8e308 was refused as "a step of 0 s") and
gw_chain_dmax1 at v = 1e200 m/s inf m (v^2 overflowed; the run failed as
"solver: scale[0] = inf"): each is now its closed form's value, a double.
Controls: a range "1:2" runs its two cases; ordinary closed forms as before.
"""
import ctypes
import math
import sys

import pytest

import granwave


@pytest.mark.parametrize("grid, said", [
    ({"n": "5:1"}, "sweep: [grid] n: range '5:1' is empty (start > end)"),
    ({"n": " 7 : 3 "}, "sweep: [grid] n: range '7 : 3' is empty (start > end)"),
    ({"n": []}, "sweep: [grid] n: empty list of grid values"),
    ({"n": ["1,2"]}, "sweep: [grid] n: a grid value holds ','"),
])
def test_sweep_grid_refusals_named(grid, said):
    with pytest.raises(granwave.GranwaveValueError) as e:
        granwave.sweep("chain", grid=grid, solver="rk4", jobs=1)
    assert said in str(e.value), str(e.value)
    assert "\n" not in str(e.value)


def test_sweep_range_control():
    """a range given as "1:2" runs its two cases (control)"""
    s = granwave.sweep("chain", grid={"n": "1:2"}, solver="rk4", jobs=1)
    assert list(s.n) == [1, 2] and all(s.f_max > 0)


def _lib():
    lib = ctypes.CDLL(granwave.library_path)
    for f in (lib.gw_chain_tau1, lib.gw_chain_dmax1):
        f.argtypes = [ctypes.c_double] * 3
        f.restype = ctypes.c_double
    return lib


def test_tau1_stiff_wall():
    lib = _lib()
    big = sys.float_info.max
    c = lib.gw_chain_tau1(1, 1, 1) / 1.25 ** 0.4  # tau_1 = c (5 m / 4 K)^(2/5) v^(-1/5)
    t = lib.gw_chain_tau1(1, big, 1)
    assert t > 0 and math.isclose(t, c * (1.25 / big) ** 0.4, rel_tol=1e-12)


def test_dmax1_fast_impact():
    lib = _lib()
    d = lib.gw_chain_dmax1(2e-3, 1e10, 1e200)
    assert math.isfinite(d) and math.isclose(d, (1.25 * 2e-3 / 1e10) ** 0.4 * 1e200 ** 0.8, rel_tol=1e-12)


def test_closed_forms_control():
    """ordinary values as the closed forms give them, a rigid wall's 0 (control)"""
    lib = _lib()
    assert lib.gw_chain_dmax1(2e-3, 1e10, 0.3) == pytest.approx((5 * 2e-3 * 0.09 / 4e10) ** 0.4, rel=1e-15)
    assert lib.gw_chain_tau1(2e-3, math.inf, 0.3) == 0
