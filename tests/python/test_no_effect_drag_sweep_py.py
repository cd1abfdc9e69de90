"""A chain sweep's "no effect" check of the sensor body's dashpot and the
guide's friction in Python (the forty-fourth session; the program's side is
tests/test_no_effect_drag_sweep.sh): `granwave.sweep` of cases whose dashpot
or friction is below their rtol issues one GranwaveWarning for each, counting
the cases and naming the first, with the keywords as Python names them
(sensor_damping), and lists it in the result's `warnings`; a dashpot that acts
and the default column warn of neither.
"""
import warnings

import granwave

SENSOR = dict(vimp=0.3, sensor_mass=1e-2, sensor_stiffness=1e7, jobs=1)


def swept(grid, **params):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        res = granwave.sweep("chain", grid, **params)
    return res, [str(x.message) for x in w if issubclass(x.category, granwave.GranwaveWarning)]


def no_effect(texts, what):
    return [t for t in texts if what in t and "has no effect" in t]


def test_sweep_dashpot_of_no_effect_warned_once_with_its_count():
    res, said = swept({"n": [1, 3], "sensor_damping": [1e-12, 10]}, **SENSOR)
    got = no_effect(said, "sensor body's dashpot")
    assert len(got) == 1, said
    assert ("the sensor body's dashpot has no effect in 2 of 4 cases (the first, case 0): its damping ratio "
            "c/(2 sqrt(k_s m_s)), at most 1.58e-15 there") in got[0], got
    assert "sensor_damping 0 (give a larger sensor_damping)" in got[0] and "sensor-damping" not in got[0], got
    assert no_effect(res["warnings"], "sensor body's dashpot") == [g[len("sweep: "):] for g in got], res["warnings"]
    assert res["ncases"] == 4


def test_sweep_guide_of_no_effect_warned_once_with_its_count():
    res, said = swept({"vimp": [0.2, 0.3], "guide_viscous": [1e-15, 1e-2]}, n=3, guide_friction=1e-15, jobs=1)
    got = no_effect(said, "guide's friction")
    assert len(got) == 1, said
    assert "the guide's friction has no effect in 2 of 4 cases (the first, case 0)" in got[0], got
    assert "(give a larger guide_friction or guide_viscous)" in got[0], got
    assert len(no_effect(res["warnings"], "guide's friction")) == 1, res["warnings"]


def test_sweep_dashpot_that_acts_not_warned():
    res, said = swept({"n": [1, 3], "sensor_damping": [10, 100]}, guide_viscous=1e-2, **SENSOR)
    assert not [t for t in said if "no effect" in t], said
    assert not [t for t in res["warnings"] if "no effect" in t], res["warnings"]


def test_sweep_default_column_not_warned():
    res, said = swept({"n": [1, 3]}, vimp=0.3, jobs=1)
    assert said == [] and res["warnings"] == [], said
