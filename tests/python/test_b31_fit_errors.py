"""The B.31 fit's parameters and standard errors against SciPy's curve_fit.

gw_stats_b31_fit_points (called here through ctypes) is compared, for each
fit variant (beta, a/b with or without the offset and tan gamma), with
scipy.optimize.curve_fit on the same objective and parameterization (offset
and beta as they are, a/b and tan gamma as logarithms): the same minimum
(parameters to 1e-6, sum of squares to 1e-9) and the same standard errors
(curve_fit's covariance, scaled by chi^2/dof as absolute_sigma=False does, to
1e-3). The boundaries are B.31 with noise, with points near beta so that every
variant has an interior minimum (at_bound empty).
"""
import ctypes
import math

import numpy as np
import pytest

granwave = pytest.importorskip("granwave")
scipy_optimize = pytest.importorskip("scipy.optimize")

OFFSET, BETA, AB, TANG = 1, 2, 4, 8


class B31(ctypes.Structure):
    _fields_ = [("offset", ctypes.c_double), ("beta", ctypes.c_double), ("a_over_b", ctypes.c_double),
                ("tan_gamma", ctypes.c_double)]


class B31Fit(ctypes.Structure):
    """Mirror of gw_stats_b31_fit (common/stats/gw_stats.h)."""
    _fields_ = [("p", B31), ("err", B31), ("corr_beta_ab", ctypes.c_double), ("free_mask", ctypes.c_int),
                ("n", ctypes.c_int), ("dof", ctypes.c_int), ("iterations", ctypes.c_int),
                ("converged", ctypes.c_int), ("at_bound", ctypes.c_int), ("evaluations", ctypes.c_long),
                ("rms", ctypes.c_double), ("x_min", ctypes.c_double), ("h_min", ctypes.c_double)]


def b31(x, off, beta, ab, T):
    u = x - beta
    return off + (np.sqrt(u * u + ab * T * x * x) - u) / (2 * T)


def lib_fit(x, h, start, mask):
    f = granwave._clib.gw_stats_b31_fit_points
    f.restype = ctypes.c_int
    n = len(x)
    xs, hs = (ctypes.c_double * n)(*x), (ctypes.c_double * n)(*h)
    out, err = B31Fit(), ctypes.create_string_buffer(512)
    rc = f(xs, hs, n, ctypes.byref(start), mask, ctypes.byref(out), err)
    assert rc == 0, err.value
    return out


TRUTH = dict(off=0.8, beta=1.2, ab=5.0, T=math.tan(math.radians(0.2)))
XS = np.array([1.21, 1.23, 1.26, 1.3, 1.35, 1.4, 1.6, 2, 2.5, 3, 4, 5, 6, 8])


@pytest.mark.parametrize("mask", [BETA | AB, BETA | AB | OFFSET, BETA | AB | TANG, BETA | AB | OFFSET | TANG])
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_b31_fit_is_curve_fit(mask, seed):
    rng = np.random.default_rng(seed)
    t = TRUTH
    h = b31(XS, t["off"], t["beta"], t["ab"], t["T"]) + 0.05 * rng.standard_normal(len(XS))
    start = B31(t["off"], 1.0, 1.0, t["T"])
    f = lib_fit(XS, h, start, mask)
    assert f.at_bound == 0, "the case was meant to have an interior minimum"

    # curve_fit in the library's parameterization, started from the library's minimum
    names = [k for k, bit in (("off", OFFSET), ("beta", BETA), ("lab", AB), ("lT", TANG)) if mask & bit]

    def model(x, *q):
        v = dict(off=t["off"], beta=None, lab=None, lT=math.log(t["T"]))
        v.update(zip(names, q))
        return b31(x, v["off"], v["beta"], math.exp(v["lab"]), math.exp(v["lT"]))

    lib = dict(off=f.p.offset, beta=f.p.beta, lab=math.log(f.p.a_over_b), lT=math.log(f.p.tan_gamma))
    # from the library's minimum and from the truth: both must land on it
    for p0 in ([lib[k] for k in names], [dict(off=t["off"], beta=t["beta"], lab=math.log(t["ab"]),
                                              lT=math.log(t["T"]))[k] for k in names]):
        q, cov = scipy_optimize.curve_fit(model, XS, h, p0=p0, xtol=1e-15, ftol=1e-15, gtol=1e-15, maxfev=20000)
        ssr = float(np.sum((model(XS, *q) - h) ** 2))
        assert f.rms ** 2 * len(XS) == pytest.approx(ssr, rel=1e-9, abs=1e-14)
        got = dict(zip(names, q))
        for k in names:
            assert lib[k] == pytest.approx(got[k], rel=1e-6, abs=1e-9), k
    sd = dict(zip(names, np.sqrt(np.diag(cov))))
    assert f.err.beta == pytest.approx(sd["beta"], rel=1e-3)
    assert f.err.a_over_b == pytest.approx(f.p.a_over_b * sd["lab"], rel=1e-3)
    if mask & OFFSET:
        assert f.err.offset == pytest.approx(sd["off"], rel=1e-3)
    if mask & TANG:
        assert f.err.tan_gamma == pytest.approx(f.p.tan_gamma * sd["lT"], rel=1e-3)
    ib, ia = names.index("beta"), names.index("lab")
    assert f.corr_beta_ab == pytest.approx(cov[ib, ia] / math.sqrt(cov[ib, ib] * cov[ia, ia]), rel=1e-3, abs=1e-6)
