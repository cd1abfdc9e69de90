"""One rule for the module's integer keywords (the forty-sixth pass, second
part): sweep(jobs=np.array(2)) was refused ("jobs must be an integer, not
ndarray") where n=np.array(5), a table's integer row, ran. Every integer
keyword now takes what n takes (an int, a numpy integer, a 0-d array of one)
and refuses the same (a bool, a float, a str, a 1-D array): jobs as a table's
row does, with the same result as jobs=2.
"""
import numpy as np
import pytest

import granwave


def f_max(**kw):
    return list(granwave.sweep("chain", {"n": [2, 3]}, **kw)["f_max"])


@pytest.mark.parametrize("jobs", [np.array(2), np.array(1, dtype=np.uint8), np.int64(2)],
                         ids=["np.array(2)", "np.array(1, uint8)", "np.int64(2)"])
def test_jobs_takes_what_n_takes(jobs):
    assert f_max(jobs=jobs) == f_max(jobs=2)


@pytest.mark.parametrize("jobs", [np.array(True), np.array(2.0), np.array([2]), 2.0, True, "2"],
                         ids=["np.array(True)", "np.array(2.0)", "np.array([2])", "2.0", "True", "'2'"])
def test_jobs_refuses_what_is_no_integer(jobs):
    with pytest.raises(TypeError) as e:
        granwave.sweep("chain", {"n": [2, 3]}, jobs=jobs)
    assert str(e.value).startswith("sweep(): jobs must be an integer"), str(e.value)


def test_jobs_0d_out_of_range_named():
    with pytest.raises(granwave.GranwaveValueError) as e:
        granwave.sweep("chain", {"n": [2]}, jobs=np.array(-1))
    assert str(e.value).startswith("sweep: jobs: -1 is outside [0, 4096]"), str(e.value)


def test_n_as_before():
    # the rule jobs now shares: a 0-d integer array runs as its int; a range
    # keyword's end too
    assert granwave.chain(n=np.array(5))["f_max"] == granwave.chain(n=5)["f_max"]
    with pytest.raises(TypeError):
        granwave.chain(n=np.array([5]))
