"""Bool keywords take bools only (issue 18, the nineteenth session of stage 2).

A flag row (type bool: trace, exact, full, sheets, remove_walls, clumps, ...)
took any number equal to 0 or 1 and any text the library parses as a flag:
chain(trace=1.0), trace=np.float64(1), trace=np.int64(1) and trace="true" ran
with the trace, trace=0 and trace="0" without, where trace=2 was refused. The
module converts every bool keyword in one place (_core._flag, under _core._text,
which the studies' keywords and the sweeps' flag values both go through): a
Python bool, an np.bool_ or a 0-d bool array, else TypeError naming the
keyword. Every bool keyword of every study is tried, found from the tables
(granwave.params), so that a new one is covered.
On the module before, 12 of the 19 tests fail: 11 of the 14 refusals (b"1",
np.array([True]) and [True] were refused already) and the sweep's flags.
"""
import numpy as np
import pytest

import granwave

STUDIES = ["chain", "falcon", "wavespeed", "softwall", "dispersion", "drop", "layer-make", "layer-impact",
           "layer-stats"]
FLAGS = [(s, p["keyword"]) for s in STUDIES for p in granwave.params(s) if p["type"] == "bool"]

NOT_BOOLS = [1.0, 0.0, 1, 0, np.float64(1.0), np.int64(1), np.uint8(0), "true", "1", "0", "False", b"1",
             np.array([True]), [True]]


def test_the_tables_have_bool_keywords():
    # the studies' flags (the list grows with the tables; these are there today)
    keys = {k for _, k in FLAGS}
    assert {"trace", "exact", "full", "sheets", "remove_walls"} <= keys, keys
    assert len(FLAGS) >= 8, FLAGS


@pytest.mark.parametrize("value", NOT_BOOLS, ids=[repr(v) for v in NOT_BOOLS])
def test_every_bool_keyword_refuses_what_is_no_bool(value):
    # refused while the keywords are set, before anything runs (no sample or
    # table is read: the other keywords are left at their defaults)
    for study, kw in FLAGS:
        fn = getattr(granwave, study.replace("-", "_"))
        with pytest.raises(TypeError, match=rf"^{fn.__name__}: {kw}: expected True or False, got "):
            fn(**{kw: value})


@pytest.mark.parametrize("value", [True, np.bool_(True), np.array(True)], ids=["True", "np.bool_", "0-d array"])
def test_a_bool_in_every_form_is_taken(value):
    r = granwave.chain(n=2, trace=value)
    assert "t" in r and len(r["t"]) > 2  # the trace is there
    r = granwave.chain(n=2, trace=not bool(value))
    assert "t" not in r


def test_a_sweep_flag_takes_bools_only(sample):
    for v in (1, 1.0, "1", "true"):
        with pytest.raises(TypeError, match=r"^sweep\(\) grid: 'exact': expected True or False, got"):
            granwave.sweep("layer", {"exact": [v]}, sample=sample, t_max=0.002)
        with pytest.raises(TypeError, match=r"^sweep\(\): 'remove_walls': expected True or False, got"):
            granwave.sweep("layer", {"vi": [10]}, sample=sample, t_max=0.002, remove_walls=v)
    # a string of values is split into strings: refused as the items are
    with pytest.raises(TypeError, match=r"^sweep\(\) grid: 'exact': expected True or False, got str"):
        granwave.sweep("layer", {"exact": "0,1"}, sample=sample, t_max=0.002)
