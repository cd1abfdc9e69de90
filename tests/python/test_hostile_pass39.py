"""The thirty-ninth hostile pass over the Python module (issue 18).

The pass called the module with numpy scalars of every kind (float16,
longdouble, complex, datetime64, str_), Fractions and Decimals, float and int
subclasses whose conversions raise, bytes, memoryviews, huge ints, surrogates,
full-width digits, strings with NUL, arrays of other dtypes, shapes and
strides, generators, and progress callbacks that return arrays, strings or
objects whose truth raises (about 110 calls), and compared refusals with the
program's. One fault: a real number no double holds, given as an
np.longdouble or a Fraction, was turned into a double first: 1e-4000
underflowed to 0 and was refused as "vimp: 0 is outside [1e-09, 1000]", a
value not given, where the program refuses `--vimp 1e-4000` as "'1e-4000' is
too small in magnitude"; a Fraction above the largest double was "cannot use
a Fraction" (a TypeError) where the int 10**400 is refused as not finite. Such
a value now goes to the library as its own digits, so the module and the
program refuse it alike; every value a double holds goes as before.
"""
import fractions
import subprocess

import numpy as np
import pytest

import granwave


def _message(f):
    with pytest.raises(granwave.GranwaveValueError) as ei:
        f()
    assert ei.value.status == -1
    assert "\n" not in str(ei.value)
    return str(ei.value)


def _program(program, *args):
    p = subprocess.run([program, "chain", *args], capture_output=True, text=True)
    assert p.returncode == 2 and p.stdout == ""
    return p.stderr.strip()


@pytest.mark.parametrize("value, text", [
    (np.longdouble("1e-4000"), "'1e-4000' is too small in magnitude"),
    (fractions.Fraction(1, 10 ** 400), "'1e-400' is too small in magnitude"),
    (-fractions.Fraction(1, 10 ** 400), "'-1e-400' is too small in magnitude"),
])
def test_below_every_double_named_as_given(value, text, program):
    m = _message(lambda: granwave.chain(vimp=value, t_max=1e-3))
    assert m.startswith("chain: vimp: ") and text in m, m
    assert "0 is outside" not in m
    # the program says the same of the same digits
    digits = text.split("'")[1]
    assert _program(program, "--vimp", digits, "--t-max", "1e-3").endswith(m[len("chain: vimp: "):]), m


@pytest.mark.parametrize("value", [np.longdouble("-1e4000"), fractions.Fraction(10 ** 400), fractions.Fraction(-10 ** 400, 3)])
def test_above_every_double_refused_as_not_finite(value):
    m = _message(lambda: granwave.chain(vimp=value, t_max=1e-3))
    assert "is not a finite number" in m and "inf" not in m, m


def test_in_a_list_too():
    m = _message(lambda: granwave.falcon(n="2:3", heights="none", vimp=[0.1, fractions.Fraction(1, 10 ** 400)]))
    assert "falcon: vimp: '1e-400' is too small in magnitude" in m, m


def test_values_a_double_holds_unchanged():
    # control: the same double as float() gives, bit for bit
    for v in (np.longdouble("0.1"), fractions.Fraction(1, 10), np.float32(0.1), fractions.Fraction(3, 7)):
        r = granwave.chain(vimp=v, t_max=1e-3)
        assert r["v_imp"] == float(v)
    assert granwave.chain(vimp=np.longdouble(0.3), t_max=1e-3)["f_max"] == granwave.chain(vimp=0.3, t_max=1e-3)["f_max"]
    # a subnormal double is the library's refusal as before (the text of the value)
    m = _message(lambda: granwave.chain(vimp=np.longdouble("1e-320"), t_max=1e-3))
    assert "'1e-320' is too small in magnitude" in m
