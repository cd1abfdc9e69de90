"""The twenty-seventh hostile pass over the Python module (input files and the
values a sweep writes into its config).

- A sweep over a sample whose name is not UTF-8 (as os.listdir gives it, the
  undecodable bytes as surrogates) raised UnicodeEncodeError naming nothing,
  where layer_impact(sample=...) opens the file: the sweep's config text was
  encoded strictly. File names now go to the library as the OS's bytes, as a
  study's keyword does, and any other value that cannot be encoded is a
  GranwaveValueError naming its key.
- A sample name with a blank at its start or end ran another file in a sweep:
  the config reader strips the blanks around a value, so sample=" a.txt" ran
  'a.txt' (the result's column said ' a.txt'), where layer_impact opens
  ' a.txt'. Refused now, naming the key and what the reader would run.
- Messages that quote a caller's value were unbounded and could fail: a list of
  10**6 numbers given for vimp made a TypeError of 7.9 MB, and a value whose
  __repr__ raised replaced the refusal naming the keyword by its own error.
  Every quoted value is now cut to about 80 characters (reprlib), a failing
  __repr__ shown as '<TYPE instance at ...>'.
"""
import os
import shutil

import pytest

import granwave

# the short runs are undecided (t_max 2 ms): their warning is not what is tested
pytestmark = pytest.mark.filterwarnings("ignore::granwave.GranwaveWarning")


def test_sweep_runs_a_sample_whose_name_is_not_utf8(sample, tmp_path):
    name = os.fsdecode(bytes(tmp_path) + b"/s\xff.txt")  # 's\udcff.txt'
    shutil.copy(sample, name)
    want = granwave.layer_impact(sample=name, vi=20, t_max=2e-3).penetration
    s = granwave.sweep("layer", grid={"vi": [20]}, sample=name, t_max=2e-3, jobs=1)
    assert s.ncases == 1 and s.penetration[0] == want
    s = granwave.sweep("layer", grid={"sample": [name]}, vi=20, t_max=2e-3, jobs=1)
    assert s.ncases == 1 and s.penetration[0] == want and list(s.sample) == [name]


@pytest.mark.parametrize("grid, params, key", [({"vimp": ["0.3\udcff"]}, {}, "vimp"),
                                               ({"n": [2]}, {"solver": "rk4\udcff"}, "solver")])
def test_sweep_value_that_cannot_be_encoded_is_named(grid, params, key):
    with pytest.raises(granwave.GranwaveValueError, match=rf"^sweep: \[(grid|params)\] {key}: .* cannot be encoded"):
        granwave.sweep("chain", grid=grid, **params)


@pytest.mark.parametrize("spelt", [" {}", "{} ", "\t{}"])
def test_sweep_sample_with_blanks_around_it_is_refused(sample, tmp_path, spelt):
    # the file named as given does not exist; the stripped name does: the
    # sweep ran it before
    name = spelt.format(sample)
    assert not os.path.exists(name) and os.path.exists(name.strip())
    with pytest.raises(ValueError, match=r"^sweep: \[params\] sample: value .* begins or ends with a blank"):
        granwave.sweep("layer", grid={"vi": [20]}, sample=name, t_max=2e-3, jobs=1)
    with pytest.raises(ValueError, match=r"^sweep: \[grid\] sample: value .* begins or ends with a blank"):
        granwave.sweep("layer", grid={"sample": [name]}, vi=20, t_max=2e-3, jobs=1)
    with pytest.raises(granwave.GranwaveIOError, match="cannot open"):  # the study opens the name as given
        granwave.layer_impact(sample=name, vi=20, t_max=2e-3)


def test_messages_quote_a_long_value_briefly():
    big = list(range(10**6))
    for call, key in [(lambda: granwave.chain(vimp=big), "vimp"),
                      (lambda: granwave.chain(n=2, radii=[0.004, big]), "radii"),
                      (lambda: granwave.sweep("chain", grid={"vimp": [big]}), "vimp"),
                      (lambda: granwave.layer_impact(sample=big), "sample")]:
        with pytest.raises(TypeError) as info:
            call()
        assert key in str(info.value) and len(str(info.value)) < 300, str(info.value)[:300]


class _BadRepr:
    def __repr__(self):
        raise RuntimeError("the caller's own __repr__ failed")


class _FloatBadRepr(float):
    def __repr__(self):
        raise RuntimeError("the caller's own __repr__ failed")


@pytest.mark.parametrize("call, key", [
    (lambda: granwave.chain(vimp=_BadRepr()), "vimp"),
    (lambda: granwave.chain(n=2, radii=[0.004, _BadRepr()]), "radii"),
    (lambda: granwave.falcon(n=_FloatBadRepr(3)), "n"),
    (lambda: granwave.layer_impact(sample=_FloatBadRepr(3)), "sample"),
    (lambda: granwave.sweep("chain", grid={"vimp": [_BadRepr()]}), "vimp"),
    (lambda: granwave.sweep("chain", grid={_BadRepr(): [1]}), "key"),
])
def test_a_value_whose_repr_fails_is_still_refused_by_keyword(call, key):
    with pytest.raises(TypeError, match=key):
        call()
