"""The tenth pass over the Python module: values of the wrong kind.

Before, each of these ran with a value the caller did not mean, or failed late
and without naming the keyword:
- a number given for a file (sample=3) went to C as the file name '3';
- a set or a dict for a list keyword (radii, snapshots) ran in hash order, an
  array of two or more dimensions was flattened, a None item failed in float()
  naming neither the keyword nor the item;
- a file name as the OS gives it (bytes, or a str with surrogate escapes of
  undecodable bytes) was refused or raised UnicodeEncodeError;
- a progress callback that is not callable failed only at its first report,
  after that much of the run, with "'int' object is not callable";
- sweep(grid=...) with a list of pairs, a None, a set or a 2-D array of values
  raised AttributeError or a TypeError naming no key;
- params(None) raised AttributeError, params("layer_impact") said no study.
"""
import os

import numpy as np
import pytest

import granwave


def test_a_number_is_not_a_file_name(sample, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "3").write_text(sample.read_text())  # what the digits named
    with pytest.raises(TypeError, match=r"layer_impact: sample: expected a str or a path, got int"):
        granwave.layer_impact(sample=3, t_max=0.002)
    with pytest.raises(TypeError, match=r"layer_make: out: expected a str or a path, got float"):
        granwave.layer_make(n=10, out=1.5)
    with pytest.raises(TypeError, match=r"layer_stats: input: expected a str or a path"):
        granwave.layer_stats(7)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["3"]


def test_a_file_name_as_bytes_or_undecodable(sample, tmp_path):
    ref = granwave.layer_impact(sample=sample, t_max=0.002)
    assert granwave.layer_impact(sample=os.fsencode(sample), t_max=0.002)["e_incident"] == ref["e_incident"]
    raw = os.fsencode(str(tmp_path)) + b"/s\xff.txt"  # not UTF-8: os.listdir gives a surrogate
    with open(raw, "wb") as f:
        f.write(sample.read_bytes())
    name = os.fsdecode(raw)
    assert "\udcff" in name
    r = granwave.layer_impact(sample=name, t_max=0.002)
    assert r["e_incident"] == ref["e_incident"]
    # a surrogate in a keyword that is not a file: refused naming it
    with pytest.raises(granwave.GranwaveValueError, match=r"chain: material: .* cannot be encoded"):
        granwave.chain(n=2, material="st\udcffeel")


@pytest.mark.parametrize("value, text", [
    ({4e-3, 5e-3}, "expected a number or a sequence of numbers, got set"),
    ({4e-3: 1, 5e-3: 2}, "expected a number or a sequence of numbers, got dict"),
    (np.full((2, 1), 4e-3), r"expected a 1-D sequence of numbers, got an array of shape \(2, 1\)"),
    ([4e-3, None], r"item 2 is not a number \(None\)"),
    ([4e-3, True], r"item 2 is not a number \(True\)"),
    (True, "expected a number or a sequence"),
])
def test_a_list_keyword_takes_an_ordered_sequence(value, text):
    with pytest.raises(TypeError, match="chain: radii: " + text):
        granwave.chain(n=2, radii=value)


def test_a_list_keyword_accepts_what_it_did():
    base = granwave.chain(n=3, radii=[4e-3, 5e-3, 4.5e-3])
    for v in (np.array([4e-3, 5e-3, 4.5e-3]), (4e-3, 5e-3, 4.5e-3), (x for x in [4e-3, 5e-3, 4.5e-3]),
              ["4e-3", "5e-3", "4.5e-3"]):
        assert granwave.chain(n=3, radii=v)["f_max"] == base["f_max"]
    assert granwave.chain(n=1, radii=np.float64(5e-3))["f_max"] == granwave.chain(n=1, radii=[5e-3])["f_max"]
    with pytest.raises(TypeError, match=r"layer_impact: snapshots: expected a 1-D sequence"):
        granwave.layer_impact(sample="unused.txt", snapshots=np.array([[1e-3], [2e-3]]))


def test_a_progress_that_is_not_callable_is_refused_before_the_run():
    for call in (lambda: granwave.falcon(n=(1, 3), progress=5),
                 lambda: granwave.drop(n=2, progress="yes"),
                 lambda: granwave.wavespeed(progress=[])):
        with pytest.raises(TypeError, match=r"^(falcon|drop|wavespeed): progress must be a callable"):
            call()
    with pytest.raises(TypeError, match=r"^sweep: progress must be a callable"):
        granwave.sweep("chain", grid={"n": [1, 2]}, progress=3)
    # the module goes on working after each refusal
    assert granwave.chain(n=1)["f_max"] == pytest.approx(granwave.chain(n=1)["f_max_1"], rel=1e-4)


@pytest.mark.parametrize("grid, text", [
    ([("n", [1])], r"sweep\(\): grid must be a dict"),
    ({"n": None}, r"sweep\(\) grid: 'n': expected a list"),
    ({"n": {1, 2}}, r"sweep\(\) grid: 'n': expected a list"),
    ({"n": np.array([[1, 2], [3, 4]])}, r"sweep\(\) grid: 'n': expected a list"),
    ({"n": [1, [2]]}, r"sweep\(\) grid: 'n': cannot use a list"),
])
def test_sweep_grids_of_the_wrong_kind_name_the_key(grid, text):
    with pytest.raises(TypeError, match=text):
        granwave.sweep("chain", grid=grid)


def test_params_names():
    assert granwave.params("layer_impact") == granwave.params("layer-impact")
    with pytest.raises(TypeError, match="a study name is a str"):
        granwave.params(None)
    with pytest.raises(ValueError, match=r"no study 'bogus' \(one of chain, "):
        granwave.params("bogus")
