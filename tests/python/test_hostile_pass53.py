"""The fifty-third hostile pass through Python, aimed at granwave.sweep_n
(about 45 calls: speeds repeated, 1 ulp, 1e-12 and 1e-9 apart, as a list,
a tuple, a numpy array, a set and a generator; 0-d arrays of a float, an int,
a bool, a string and a complex number, alone and as items; float32 and
non-contiguous arrays; n as numpy integers, floats, bools, 3-tuples, ranges
of step 2 and empty; jobs -1, 1.5 and None; keyword typos; trace None;
progress callbacks raising KeyboardInterrupt and SystemExit, returning a
string, taking no argument). What it found:

- granwave.sweep_n((1, 2), [0.3, 0.3]) ran every collision of the speed twice,
  into two rows of its result (falcon and a chain sweep's config refuse a
  speed given twice): a speed given twice, or two the same to 12 digits (the
  config's rule), is refused naming vimp and both items, as the library's
  gw_chain_sweep_n refuses it.
- sweep_n(n, np.array(0.3)) raised "iteration over a 0-d array", naming no
  keyword: a 0-d array of a number is that speed (as granwave.chain takes
  it), one of another kind refused naming vimp.
- sweep_n((1, 2), 10**400) raised OverflowError "int too large to convert to
  float": the library holds the integer to vimp's range, as granwave.chain
  and falcon do ("'10000000000000000000...' (401 characters) is not a finite
  number").
- sweep_n((1415, 1415), [0.3]) was told "2e+06 bead^2 of work ..., above the
  bound 2e+06": the work in the digits that tell it from the bound.
The rest was refused with one message naming the keyword, or run: no fault.
"""
import numpy as np
import pytest

import granwave

_TWICE = "(each of its collisions would run twice)"


@pytest.mark.parametrize("speeds, said", [
    ([0.3, 0.3], "item 2 is the impact velocity 0.3 m/s of item 1"),
    ((0.3, 0.3), "item 2 is the impact velocity 0.3 m/s of item 1"),
    (np.array([0.2, 0.4, 0.4, 0.2]), "item 3 is the impact velocity 0.4 m/s of item 2"),
    ([0.5, 0.2, 0.5], "item 3 is the impact velocity 0.5 m/s of item 1"),
    ((x for x in [0.3, 0.3]), "item 2 is the impact velocity 0.3 m/s of item 1"),
    ([0.3, 0.30000000000000004],
     "item 2, 0.30000000000000004 m/s, and item 1, 0.3 m/s, are the same impact velocity to 12 digits"),
    ([1.0, 0.7, 1.0 + 5e-13],
     "item 3, 1.0000000000005 m/s, and item 1, 1.0 m/s, are the same impact velocity to 12 digits"),
])
def test_sweep_n_speed_twice_refused(speeds, said):
    with pytest.raises(granwave.GranwaveValueError) as e:
        granwave.sweep_n((1, 2), speeds, jobs=1)
    assert str(e.value) == f"sweep_n: vimp: {said} {_TWICE}"


def test_sweep_n_speed_twice_before_any_run():
    """refused before the progress callback hears of any collision"""
    seen = []
    with pytest.raises(granwave.GranwaveValueError, match="vimp: item 2"):
        granwave.sweep_n((1, 2), [0.3, 0.3], jobs=1, progress=lambda d, t: seen.append(d))
    assert seen == []


def test_sweep_n_distinct_speeds_control():
    """speeds a relative 1e-9 apart are two (the grid fits nothing over
    them); the sweep's config and falcon refuse a repeat as before"""
    g = granwave.sweep_n((1, 1), [0.3, 0.3 * (1 + 1e-9)], jobs=1)
    assert g["f_max"].shape == (2, 1) and g["f_max"][0, 0] != g["f_max"][1, 0]
    with pytest.raises(granwave.GranwaveValueError, match="each case would run twice"):
        granwave.sweep("chain", grid={"n": [1], "vimp": [0.3, 0.3]})
    with pytest.raises(granwave.GranwaveValueError, match="would run twice"):
        granwave.falcon(n=(1, 2), vimp=[0.3, 0.3], heights=[], jobs=1)


@pytest.mark.parametrize("vimp", [np.array(0.3), [np.array(0.3)], np.float64(0.3)])
def test_sweep_n_zero_d_speed(vimp):
    g = granwave.sweep_n((1, 2), vimp, jobs=1)
    ref = granwave.sweep_n((1, 2), [0.3], jobs=1)
    assert list(g["v_imp"]) == [0.3] and np.array_equal(g["f_max"], ref["f_max"])


def test_sweep_n_zero_d_int_speed():
    g = granwave.sweep_n((1, 1), [np.array(1), 0.5], jobs=1)
    assert list(g["v_imp"]) == [1.0, 0.5]


@pytest.mark.parametrize("vimp", [np.array("0.3"), np.array(True), np.array(0.3 + 0j), np.array(None)])
def test_sweep_n_zero_d_other_refused(vimp):
    with pytest.raises(TypeError) as e:
        granwave.sweep_n((1, 2), vimp, jobs=1)
    assert str(e.value).startswith("sweep_n(): vimp must be a speed or a list of speeds (m/s), not ndarray")


@pytest.mark.parametrize("item", [np.array("0.3"), np.array(True), np.array([0.3])])
def test_sweep_n_zero_d_other_item_refused(item):
    with pytest.raises(TypeError) as e:
        granwave.sweep_n((1, 2), [0.4, item], jobs=1)
    assert str(e.value).startswith("sweep_n(): vimp: an item is a number (m/s), not ndarray")


@pytest.mark.parametrize("exc", [KeyboardInterrupt, SystemExit])
def test_sweep_n_progress_raises_through(exc):
    def stop(done, total):
        raise exc()
    with pytest.raises(exc):
        granwave.sweep_n((1, 2), [0.3, 0.4], jobs=1, progress=stop)


def test_sweep_n_huge_int_speed():
    with pytest.raises(granwave.GranwaveValueError) as e:
        granwave.sweep_n((1, 2), 10**400, jobs=1)
    assert str(e.value) == "sweep_n: vimp: '10000000000000000000...' (401 characters) is not a finite number"
    with pytest.raises(granwave.GranwaveValueError) as e:
        granwave.sweep_n((1, 2), [0.3, 10**5000], jobs=1)
    assert str(e.value) == "sweep_n: vimp: an integer of about 5001 digits is beyond every input's range"


def test_sweep_n_int_speeds_control():
    g = granwave.sweep_n((1, 1), [1, np.int64(2)], jobs=1)
    assert list(g["v_imp"]) == [1.0, 2.0] and g["v_imp"].dtype == float
    with pytest.raises(granwave.GranwaveValueError, match="item 2 is the impact velocity 1.0 m/s of item 1"):
        granwave.sweep_n((1, 1), [1, 1.0], jobs=1)


def test_sweep_n_work_digits():
    with pytest.raises(granwave.GranwaveValueError) as e:
        granwave.sweep_n((1415, 1415), [0.3], jobs=1)
    assert str(e.value).startswith("sweep_n: n: 1415:1415 at 1 column per N is 2002225 bead^2 of work")
