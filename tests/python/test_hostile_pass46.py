"""The forty-sixth hostile pass through Python: integers beyond Python's own
limit on their decimal digits.

str() of an int of more than 4300 digits raises Python's ValueError
("Exceeds the limit (4300 digits) for integer string conversion"). The module
turns every integer it sends the library into its digits with str(), so
chain(vimp=10**5000), a list's item, a range's end, a sweep's grid value and
sweep(jobs=10**5000) raised that bare ValueError, naming neither the call nor
the keyword. No input's range comes near such a number: each is now refused
as a GranwaveValueError (GW_EINVAL) naming the keyword, before any work. An
integer within Python's limit (2**70, 4000 digits) still goes to the library,
which refuses it out of its row's range as before.
"""
import pytest

import granwave

GW_EINVAL = -1
HUGE = 10**5000  # 5001 digits, beyond Python's 4300


def refused(call, *named, short=True):
    with pytest.raises(granwave.GranwaveValueError) as e:
        call()
    text = str(e.value)
    assert e.value.status == GW_EINVAL, text
    for w in named:
        assert w in text, text
    assert "\n" not in text and (len(text) < 200 or not short), text
    return text


CASES = [
    ("a float keyword", lambda: granwave.chain(n=3, vimp=HUGE), ("chain: vimp:", "5001 digits")),
    ("a negative one", lambda: granwave.chain(n=3, vimp=-HUGE), ("chain: vimp:", "5001 digits")),
    ("an int keyword", lambda: granwave.chain(n=HUGE), ("chain: n:", "5001 digits")),
    ("an int keyword of drop", lambda: granwave.drop(n=HUGE), ("drop: n:",)),
    ("a layer keyword", lambda: granwave.layer_impact(vi=HUGE), ("layer_impact: vi:",)),
    ("a list's item", lambda: granwave.chain(n=2, radii=[1e-3, HUGE]), ("radii: item 2",)),
    ("a range keyword's integer", lambda: granwave.falcon(n=HUGE), ("falcon: n:",)),
    ("a range keyword's end", lambda: granwave.falcon(n=(1, HUGE)), ("falcon: n:",)),
    ("a range object's end", lambda: granwave.falcon(n=range(1, HUGE)), ("falcon: n:",)),
    ("a sweep's grid value", lambda: granwave.sweep("chain", {"n": [2, HUGE]}), ("n:", "5001 digits")),
    ("a sweep's range", lambda: granwave.sweep("chain", {"n": range(HUGE, HUGE + 3)}), ("n:",)),
    ("a sweep's parameter", lambda: granwave.sweep("chain", {"n": [2]}, vimp=HUGE), ("vimp",)),
    ("a sweep's jobs", lambda: granwave.sweep("chain", {"n": [2]}, jobs=HUGE), ("sweep: jobs:",)),
]


@pytest.mark.parametrize("label, call, named", CASES, ids=[c[0] for c in CASES])
def test_huge_integer_named(label, call, named):
    refused(call, *named)


@pytest.mark.parametrize("value", [2**70, 10**4000], ids=["2**70", "10**4000"])
def test_integers_within_the_limit_reach_the_library(value):
    # the library's own refusal, naming the range, as before (its quote of
    # 4001 digits cut to about 500 characters)
    refused(lambda: granwave.chain(n=value), "chain: n:", "outside [1, 50000000]", short=False)
    refused(lambda: granwave.chain(n=3, vimp=value), "chain: vimp:", short=False)


def test_the_module_runs_after_a_refusal():
    with pytest.raises(granwave.GranwaveValueError):
        granwave.chain(n=3, vimp=HUGE)
    assert granwave.chain(n=3, vimp=1)["f_max"] == granwave.chain(n=3, vimp=1.0)["f_max"]
