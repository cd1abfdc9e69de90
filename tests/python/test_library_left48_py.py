"""What the forty-eighth library pass left, through Python.

The progress callback stopped the run on any truthy return: "no", 1 or a
list stopped it as True does, 0.0 or "" let it go on. The contract now: None
or False go on, True (numpy's bool too) stops; anything else stops the call
with a TypeError naming the callback and what it returned. A sweep's
[params] value that is a range ('3:5') was refused only at the first case's
check: it is refused when the module's config is read, naming the key.
"""
import numpy as np
import pytest

import granwave


def _calls(returned):
    seen = []

    def cb(done, total):
        seen.append(done)
        return returned

    return cb, seen


@pytest.mark.parametrize("returned", ["no", "", 1, 0, 0.0, [], [1]])
def test_progress_other_types_refused(returned):
    cb, seen = _calls(returned)
    with pytest.raises(TypeError) as e:
        granwave.sweep("chain", grid={"n": [1, 2, 3]}, jobs=1, progress=cb)
    assert "cb" in str(e.value) and type(returned).__name__ in str(e.value)
    assert len(seen) == 1  # stopped at its first report


@pytest.mark.parametrize("returned", [None, False, np.False_])
def test_progress_goes_on(returned):
    cb, seen = _calls(returned)
    r = granwave.sweep("chain", grid={"n": [1, 2, 3]}, jobs=1, progress=cb)
    assert seen == [1, 2, 3]
    assert len(r["n"]) == 3


@pytest.mark.parametrize("returned", [True, np.True_])
def test_progress_stops(returned):
    cb, seen = _calls(returned)
    with pytest.raises(granwave.GranwaveError) as e:
        granwave.sweep("chain", grid={"n": [1, 2, 3]}, jobs=1, progress=cb)
    assert e.value.status == -9
    assert seen == [1]


def test_progress_study_numpy_comparison():
    # a study's callback comparing numpy numbers: np.bool_ is a verdict
    seen = []

    def cb(done, total):
        seen.append(done)
        return np.int64(done) >= 2

    with pytest.raises(granwave.GranwaveError) as e:
        granwave.wavespeed(n=(5, 10), vimp=[0.3], jobs=1, progress=cb)
    assert e.value.status == -9
    assert seen[-1] == 2


def test_sweep_params_range_refused_at_read():
    with pytest.raises(granwave.GranwaveValueError) as e:
        granwave.sweep("chain", grid={"vimp": [0.3, 0.4]}, jobs=1, n="3:5")
    assert "[params] n:" in str(e.value) and "case 0" not in str(e.value)
