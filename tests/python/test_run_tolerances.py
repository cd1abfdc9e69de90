"""The run's tolerances in the results of granwave.chain and granwave.drop
(session 46): gw_chain_result.run_rtol and run_atol, kept before in a hidden
buffer the library alone read, are the outcomes' `rtol` and `atol` (the
study's default 1e-12, the values given under cvode and arkode, nan under rk4,
which has no error test); a drop's are its first collision's. Each listed by
help() with the other results.
"""
import math

import granwave


def test_chain_default_and_given():
    r = granwave.chain(n=3)
    assert r["rtol"] == 1e-12 and r["atol"] == 1e-12
    r = granwave.chain(n=3, rtol=1e-9, atol=1e-11)
    assert r["rtol"] == 1e-9 and r["atol"] == 1e-11
    r = granwave.chain(n=3, solver="arkode", rtol=1e-8, atol=1e-10)
    assert r["rtol"] == 1e-8 and r["atol"] == 1e-10


def test_chain_rk4_none():
    r = granwave.chain(n=3, solver="rk4")
    assert math.isnan(r["rtol"]) and math.isnan(r["atol"])


def test_drop_first_collision():
    d = granwave.drop(n=2, rtol=1e-10, atol=1e-13)
    assert d["rtol"] == 1e-10 and d["atol"] == 1e-13
    d = granwave.drop(n=2, solver="rk4")
    assert math.isnan(d["rtol"]) and math.isnan(d["atol"])


def test_listed_in_help():
    for f in (granwave.chain, granwave.drop):
        assert "rtol" in f.__doc__ and "tolerance the run used" in f.__doc__
