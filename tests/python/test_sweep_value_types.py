"""A sweep's values in every form a study's keyword takes, converted as the study
converts them (the twentieth pass).

granwave.sweep wrote each grid value and fixed keyword into the sweep's config
with a conversion of its own that knew no parameter: a bool became "1" or "0"
for every key. grid={"n": [True, 2]} ran a column of 1 bead and one of 2,
grid={"vimp": [True]} and vimp=True an impact at 1 m/s, and a layer sweep's
spacing=[False] 0 m, where chain(n=True) and chain(vimp=True) are refused
("expected a number, got True"). A bool is now the value of a flag (a row of
type bool, converted by the row as a study's keyword is) and refused for any
other key. 7 of the 8 tests fail on the module before (the four bools in a
grid, the fixed keyword and the choice, the layer's placement key, and the flag
given 2, which reached the library as '2').
"""
import numpy as np
import pytest

import granwave


@pytest.mark.parametrize("value", [True, False, np.bool_(True), np.array(True)])
def test_a_bool_is_no_number_in_a_grid(value):
    with pytest.raises(TypeError, match=r"sweep\(\) grid: 'n': expected a number, got"):
        granwave.sweep("chain", {"n": [value, 2]})
    with pytest.raises(TypeError, match=r"chain: n: expected a number, got"):  # as the study says
        granwave.chain(n=value)


def test_a_bool_is_no_number_as_a_fixed_keyword():
    with pytest.raises(TypeError, match=r"sweep\(\): 'vimp': expected a number, got True"):
        granwave.sweep("chain", {"n": [2]}, vimp=True)
    with pytest.raises(TypeError, match=r"sweep\(\) grid: 'solver': expected a number, got True"):
        granwave.sweep("chain", {"solver": [True]})


def test_a_bool_is_no_number_for_the_layer_placement(sample):
    # spacing, point, points belong to the layer model alone (no study row)
    with pytest.raises(TypeError, match=r"sweep\(\) grid: 'spacing': expected a number, got False"):
        granwave.sweep("layer", {"spacing": [False]}, sample=sample, t_max=0.002)


@pytest.mark.filterwarnings("ignore::granwave.GranwaveWarning")
def test_flags_take_bools_as_the_study_does(sample):
    s = granwave.sweep("layer", {"exact": [np.bool_(True), False]}, sample=sample, vi=20, t_max=0.002)
    assert s.ncases == 2
    one = granwave.layer_impact(sample=sample, vi=20, t_max=0.002, exact=True)
    assert s.penetration[0] == one.penetration
    with pytest.raises(TypeError, match=r"sweep\(\) grid: 'exact': expected True or False, got int \(2\)"):
        granwave.sweep("layer", {"exact": [2]}, sample=sample, t_max=0.002)


def test_numbers_in_other_forms_run_as_their_values():
    ref = granwave.sweep("chain", {"n": [1, 2]}, vimp=0.3)
    for grid, kw in [({"n": [np.int64(1), np.array(2)]}, {"vimp": np.float64(0.3)}),
                     ({"n": range(1, 3)}, {"vimp": "0.3"}),
                     ({"n": "1:2"}, {"vimp": np.array(0.3)})]:
        s = granwave.sweep("chain", grid, **kw)
        assert list(s.n) == [1, 2] and list(s.f_max) == list(ref.f_max)
