"""The sheet laws, the sensor body and guide friction as rows of the column's
table (issue 17): keywords of granwave.chain and granwave.falcon, keys of a
chain sweep, and the same numbers as the program's flags.

Tolerances: the CLI comparisons are 1e-12 (same library, same inputs: only the
printing rounds); the physical checks are those of tests/test_chain_sheets.sh
(a stiff light sensor body leaves F_max within 1e-4 of the rigid sensor's) and
of the friction's sign (friction takes energy: the column leaves slower)."""
import pytest

import granwave
from conftest import run_cli

V = 0.2385


@pytest.mark.parametrize("law", ["hertz", "layer", "material"])
def test_sheet_law_matches_cli(program, law):
    r = granwave.chain(n=3, vimp=V, sheet="pvc", sheet_law=law)
    c = run_cli(program, "chain", "--n", 3, "--vimp", V, "--sheet", "pvc", "--sheet-law", law)
    for k in ("f_max", "tau_max", "tau_n", "eps_eff", "kwall"):
        assert r[k] == pytest.approx(c[k] if k in c else c["settings"]["model"][k], rel=1e-12), k


def test_sheet_law_changes_the_wall():
    fitted = granwave.chain(n=1, vimp=V, sheet="pvc")
    layer = granwave.chain(n=1, vimp=V, sheet="pvc", sheet_law="layer")
    # a bonded 0.5 mm-class layer on steel is stiffer than the Hertz half-space of
    # the same polymer, and the fitted K_eff is another number again: the law acts
    assert layer.f_max != pytest.approx(fitted.f_max, rel=1e-3)


def test_sensor_body_and_guide_match_cli(program):
    kw = dict(n=4, sensor_mass=1e-3, sensor_stiffness=1e10, sensor_damping=6, guide_friction=0.01)
    r = granwave.chain(**kw)
    args = [x for k, v in kw.items() for x in ("--" + k.replace("_", "-"), v)]
    c = run_cli(program, "chain", *args)
    assert r.f_max == pytest.approx(c["f_max"], rel=1e-12)
    assert r.tau_n == pytest.approx(c["tau_n"], rel=1e-12)
    stiff = granwave.chain(n=4, sensor_mass=1e-7, sensor_stiffness=1e14)
    rigid = granwave.chain(n=4)
    assert stiff.f_max == pytest.approx(rigid.f_max, rel=1e-4)
    rub = granwave.chain(n=4, guide_viscous=0.5)
    assert rub.eps_col < rigid.eps_col - 1e-6


def test_falcon_takes_the_wall_rows(program):
    f = granwave.falcon(n=(1, 4), vimp=[0.3], heights=[], sensor_mass=3e-3, sensor_stiffness=1e9, jobs=1)
    c = run_cli(program, "falcon", "--n", "1:4", "--heights", "none", "--vimp", 0.3, "--sensor-mass", 3e-3,
                "--sensor-stiffness", 1e9, "--jobs", 1, "--quiet")
    for key in ("t_q", "wave_speed", "f_max_mean", "f_max_max", "tau_max_mean"):
        assert f[key][0] == pytest.approx(c["velocities"][0][key], rel=1e-12), key
    assert f.accuracy == 0  # a sensor body is outside the RK4 step study


def test_sweep_takes_the_wall_rows():
    s = granwave.sweep("chain", grid={"guide_viscous": [0, 0.5]}, n=3, jobs=1)
    r = granwave.chain(n=3, guide_viscous=0.5)
    assert s.f_max[1] == r.f_max and s.eps_col[1] == r.eps_col
    assert s.eps_col[1] < s.eps_col[0]


@pytest.mark.parametrize("kw, name", [
    (dict(sheet_law="layer"), "sheet_law"),
    (dict(sheet="pvc", sheet_law="foam"), "sheet_law"),
    (dict(sheet="brass", sheet_yield=2e8), "sheet_yield"),
    (dict(sheet="brass", sheet_law="material", sheet_yield=10), "sheet_yield"),
    (dict(sensor_stiffness=1e9), "sensor_stiffness"),
    (dict(sensor_mass=3e-3), "sensor_mass"),
    (dict(sensor_mass=0, sensor_stiffness=1e9), "sensor_mass"),
    (dict(guide_friction=-0.1), "guide_friction"),
    (dict(guide_viscous=1e9), "guide_viscous"),
])
def test_bad_wall_values_name_the_keyword(kw, name):
    with pytest.raises(ValueError, match=name):
        granwave.chain(**kw)
