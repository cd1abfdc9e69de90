"""Unusual inputs to every function of the module (issue 18, the nineteenth
session of stage 2): about 240 tried as a hostile new user would (wrong types,
numpy scalars and arrays where a scalar goes, NaN, infinities, huge integers,
-0.0, empty lists, directories, FIFOs, devices, unicode and undecodable file
names, generators, masked values, broken progress callbacks). Two went wrong:
- radii=[1e-3, 2**2000] raised OverflowError "int too large to convert to
  float", naming no keyword: a list's integer items went through float(). They
  now go to the library by their digits, as a scalar's do, which refuses them
  naming the keyword;
- sweep(grid={"n": range(2, 10**12)}) took the memory there was and raised an
  empty MemoryError (range(1, 2**80): OverflowError): the range was expanded
  before the library's bound of 1e9 cases. A range above it is refused first.
The rest were refused with TypeError or ValueError naming the function and the
keyword, or ran as their value; a selection of them is kept here (each refused
before anything runs) so that they stay so. On the module before, 3 tests fail
(the two above; the bool flags are test_bool_keywords.py's).
"""
import fractions
import os
import time

import numpy as np
import pytest

import granwave


def test_a_list_item_beyond_a_double_is_refused_by_keyword():
    with pytest.raises(granwave.GranwaveValueError, match=r"^chain: radii: '1148130695274254524232833201177"):
        granwave.chain(n=2, radii=[1e-3, 2**2000])
    with pytest.raises(granwave.GranwaveValueError, match=r"^falcon: vimp: '-1797693134862315907729305190789"):
        granwave.falcon(n=(2, 3), vimp=[0.3, -(2**1024)], heights=[])
    # integers in a list still run as their value (an exact float: the same digits)
    a = granwave.chain(n=2, radii=[np.int64(1), 1e-3])
    b = granwave.chain(n=2, radii=[1.0, 1e-3])
    assert a == b


@pytest.mark.parametrize("values", [range(2, 10**12), range(1, 2**80)], ids=["1e12", "2**80"])
def test_a_grid_range_beyond_the_bound_is_refused_at_once(values):
    t0 = time.monotonic()
    with pytest.raises(granwave.GranwaveValueError, match=r"^sweep\(\) grid: 'n': range\(.*\) holds more than "
                       r"1e9 values: the grid has more than 1e9 cases$"):
        granwave.sweep("chain", {"n": values})
    assert time.monotonic() - t0 < 1.0


@pytest.fixture(scope="module")
def odd_files(tmp_path_factory):
    d = tmp_path_factory.mktemp("odd")
    os.mkfifo(d / "fifo")
    (d / "adir").mkdir()
    return d


# (function, keywords, exception, the start of its message): each refused
# while the keywords are set or checked, before a run
REFUSED = [
    ("chain", dict(n=np.array([3])), TypeError, "chain: n: cannot use a ndarray"),
    ("chain", dict(n=3.0), ValueError, "chain: n: '3.0' is not an integer"),
    ("chain", dict(n=-0.0), ValueError, "chain: n: '-0.0' is not an integer"),
    ("chain", dict(n=2**70), ValueError, "chain: n: 1180591620717411303424 is outside"),
    ("chain", dict(n=np.uint64(2**64 - 1)), ValueError, "chain: n: 18446744073709551615 is outside"),
    ("chain", dict(n="\u0663"), ValueError, "chain: n: '\u0663' is not an integer"),
    ("chain", dict(n=b"3"), TypeError, "chain: n: cannot use a bytes"),
    ("chain", dict(vimp=float("nan")), ValueError, "chain: vimp: 'nan' is not a finite number"),
    ("chain", dict(vimp=float("-inf")), ValueError, "chain: vimp: '-inf' is not a finite number"),
    ("chain", dict(vimp=-0.0), ValueError, "chain: vimp: -0 is outside"),
    ("chain", dict(vimp=complex(0.3, 0)), TypeError, "chain: vimp: cannot use a complex"),
    ("chain", dict(vimp=np.array([[0.3]])), TypeError, "chain: vimp: cannot use a ndarray"),
    ("chain", dict(vimp=np.ma.masked), TypeError, "chain: vimp: cannot use a MaskedConstant"),
    ("chain", dict(vimp=np.datetime64("2020")), TypeError, "chain: vimp: cannot use a datetime64"),
    ("chain", dict(vimp="1e400"), ValueError, "chain: vimp: '1e400' is not a finite number"),
    ("chain", dict(vimp=""), ValueError, "chain: vimp: expected a number, got an empty value"),
    ("chain", dict(n=2, radii=[1e-3, float("nan")]), ValueError, "chain: radii: 'nan' is not a finite number"),
    ("chain", dict(n=2, radii=np.array([[1e-3, 1e-3]])), TypeError, "chain: radii: expected a 1-D sequence"),
    ("chain", dict(n=2, radii=[1e-3, True]), TypeError, "chain: radii: item 2 is not a number (True)"),
    ("chain", dict(n=2, radii=np.ma.masked_array([1e-3, 2e-3], mask=[0, 1])), TypeError,
     "chain: radii: item 2 is not a number"),
    ("chain", dict(n=2, radii=[1e-3, "1e-3,2e-3"]), ValueError, "chain: radii: an item holds ','"),
    ("chain", dict(solver="rk4\0x"), ValueError, "chain: solver: 'rk4\\x00x' holds a NUL character"),
    ("chain", dict(solver="\uff52\uff4b\uff14"), ValueError, "chain: solver: unknown value"),
    ("chain", dict(dt_out=5e-324), ValueError, "chain: dt_out: '5e-324' is too small in magnitude"),
    ("chain", dict(t_max=np.timedelta64(1, "s")), TypeError, "chain: t_max: cannot use a timedelta64"),
    ("falcon", dict(n=(3, 2), vimp=[0.3], heights=[]), ValueError, "falcon: n: range '3:2' is empty"),
    ("falcon", dict(n=range(2, 4, 2), vimp=[0.3], heights=[]), ValueError, "falcon: n: a range of step 1"),
    ("falcon", dict(n=(True, 3), vimp=[0.3], heights=[]), TypeError, "falcon: n: a range end must be a number"),
    ("falcon", dict(n=(2, 3), vimp=np.array([]), heights=[]), ValueError, "falcon: vimp: no impact velocity"),
    ("falcon", dict(n=(2, 3), vimp=[0.3, 0.3], heights=[]), ValueError, "falcon: vimp: item 2 gives the impact"),
    ("falcon", dict(n=(2, 3), vimp=[0.3], heights=[], jobs=2**40), ValueError, "falcon: jobs: 1099511627776 is"),
    ("falcon", dict(n=(2, 3), vimp=[0.3], heights=[], progress=1), TypeError, "falcon: progress must be a callable"),
    ("dispersion", dict(n=2**31), ValueError, "dispersion: n: 2147483648 is outside"),
    ("layer_impact", dict(sample="{d}/adir"), ValueError, "layer_impact: sample: {d}/adir is a directory"),
    ("layer_impact", dict(sample="{d}/fifo"), ValueError, "layer_impact: sample: {d}/fifo is a FIFO"),
    ("layer_impact", dict(sample="/dev/zero"), ValueError, "layer_impact: sample: /dev/zero is a character device"),
    ("layer_impact", dict(sample=""), ValueError, "layer_impact: sample: empty value"),
    ("layer_impact", dict(sample="{d}/no such \u00e9\u2603.txt"), OSError, "layer_impact: sample: {d}/no such"),
    ("layer_make", dict(n=20, out="{d}/fifo"), ValueError, "layer_make: out: '{d}/fifo' is a FIFO"),
    ("layer_make", dict(n=20, out="{d}/adir/"), ValueError, "layer_make: out: '{d}/adir/' is a directory"),
    ("layer_make", dict(n=20, seed=2**64), ValueError, "layer_make: seed: 18446744073709551616 is outside"),
    ("layer_stats", dict(input="{d}/fifo"), ValueError, "layer_stats: sweep table: {d}/fifo is a FIFO"),
    ("layer_stats", dict(input=3), TypeError, "layer_stats: input: expected a str or a path"),
    ("sweep", dict(model="chain", grid={"n": np.array([])}), ValueError, "sweep() grid: n: empty list of grid values"),
    ("sweep", dict(model="chain", grid={"n": np.array(2)}), TypeError, "sweep() grid: 'n': expected a list"),
    ("sweep", dict(model="chain", grid={"n": [2]}, jobs=1.0), TypeError, "sweep(): jobs must be an integer"),
    ("sweep", dict(model="chain", grid={"n": [2]}, jobs=np.int64(2**40)), ValueError, "sweep: jobs: 1099511627776"),
    ("sweep", dict(model="chain", grid={"vimp": ["0.3;x"]}), ValueError, "vimp: value '0.3;x' cannot go into"),
    ("sweep", dict(model="chain", grid={"n": [2]}, solver="rk4\n[grid]\nn=9"), ValueError, "solver: value"),
    ("sweep", dict(model="chain", grid={"n": [2, 2.0]}), ValueError, "sweep: n: '2' and '2.0'"),
    ("sweep", dict(model="chain", grid={"vimp": [float("nan")]}), ValueError, "sweep: [grid] vimp: 'nan' is not"),
    ("sweep", dict(model="chain", grid=[("n", [2])]), TypeError, "sweep(): grid must be a dict"),
    ("sweep", dict(model="layer", grid={"vi": [10]}, sample="{d}/fifo"), ValueError,
     "sweep: [params] sample: {d}/fifo is a FIFO"),
]


@pytest.mark.parametrize("fn, kw, exc, start", REFUSED, ids=[f"{f}-{i}" for i, (f, *_) in enumerate(REFUSED)])
def test_refused_naming_the_keyword(odd_files, fn, kw, exc, start):
    d = str(odd_files)
    kw = {k: v.replace("{d}", d) if isinstance(v, str) else v for k, v in kw.items()}
    start = start.replace("{d}", d)
    t0 = time.monotonic()
    with pytest.raises(exc) as e:
        getattr(granwave, fn)(**kw)
    assert str(e.value).startswith(start), str(e.value)
    assert "\n" not in str(e.value).rstrip("\n") or fn == "sweep"  # one line (a sweep's own value may hold one)
    assert time.monotonic() - t0 < 5  # refused before a run, never a hang on the FIFO


def test_numbers_in_other_forms_run_as_their_value():
    ref = granwave.chain(n=3, vimp=0.25, t_max=1e-3)
    for n, v in ((np.int64(3), "2.5e-1"), (np.array(3, dtype=">i8"), fractions.Fraction(1, 4)),
                 (np.str_("3"), np.array(0.25, dtype=">f8")), (" 3 ", np.float64(0.25))):
        assert granwave.chain(n=n, vimp=v, t_max=1e-3) == ref, (n, v)


def test_hexadecimal_text_is_refused_as_for_integers():
    # numbers in text are decimal, for a real as for an integer (the flags and
    # config files read them through the same parser): "0x1p-2" ran as 0.25
    for kw, word in (({"vimp": "0x1p-2"}, "chain: vimp: '0x1p-2' is not a decimal number"), ({"n": "0x3"}, "chain: n: '0x3'")):
        with pytest.raises(granwave.GranwaveValueError) as e:
            granwave.chain(**{"n": 3, "vimp": 0.25, "t_max": 1e-3, **kw})
        assert str(e.value).startswith(word), str(e.value)


@pytest.mark.parametrize("call", [
    lambda: granwave.sweep(model="chain", grid={"vimp\nn": [0.1]}),
    lambda: granwave.sweep(model="chain", grid={"n": [3]}, **{"t\rmax\x1b": 1e-3}),
    lambda: granwave.chain(**{"vimp\nn": 0.1}),
])
def test_a_key_with_control_characters_is_quoted_on_one_line(call):
    # quoted as the library quotes a text (\n, \r, \xHH): the key was quoted
    # raw, a TypeError of two lines
    with pytest.raises(TypeError) as e:
        call()
    msg = str(e.value)
    assert "\n" not in msg and "\r" not in msg and "\x1b" not in msg, msg
    assert "'vimp\\nn'" in msg or "'t\\rmax\\x1b'" in msg, msg
