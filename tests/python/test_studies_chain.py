"""granwave.wavespeed and granwave.softwall (and drop, dispersion where built):
the column's studies as library calls, against physical laws and against the
program's JSON for the same inputs.

Tolerances: the CLI comparisons are 1e-12 (same library, same inputs: only the
printing rounds); the wave-speed exponent is held to 0.005 of 1/5, the bound of
tests/test_chain_studies.sh (F.16); the one-wall soft-wall run must classify a
wall below K_c as soft and saturate (N_d found) within 1:30 as the CLI test
does."""
import math

import numpy as np
import pytest

import granwave
from conftest import run_cli


def close(a, b, rel=1e-12):
    """a (Python, NaN for not defined) against b (CLI JSON, null for NaN)."""
    if b is None:
        return a is None or (isinstance(a, float) and math.isnan(a))
    if isinstance(b, list):
        return len(a) == len(b) and all(close(x, y, rel) for x, y in zip(a, b))
    if isinstance(b, dict):
        return all(k in a and close(a[k], b[k], rel) for k in b)
    if isinstance(b, str):
        return a == b
    return a == pytest.approx(b, rel=rel, abs=0)


def test_wavespeed_exponent_is_one_fifth():
    w = granwave.wavespeed(n=(5, 20), vimp=[0.1, 0.3, 0.6], jobs=2)
    assert isinstance(w.v_tq, np.ndarray) and w.v_tq.shape == (3,)
    for name in ("tq", "front", "group"):
        assert abs(w.fits[name]["beta"] - 0.2) < 0.005, name  # F.16
    # the speed rises with v_imp and the three estimators agree within 20 %
    assert np.all(np.diff(w.v_tq) > 0) and w.max_disagreement < 0.2


def test_wavespeed_matches_cli(program):
    w = granwave.wavespeed(n=(5, 12), vimp=[0.1, 0.3], jobs=1)
    c = run_cli(program, "wavespeed", "--n", "5:12", "--vimp", "0.1,0.3", "--jobs", 1, "--quiet")
    for k in ("v_imp", "v_tq", "v_front", "v_group", "v_group_front", "t_q", "mean_wall_force", "period",
              "beta", "beta_err", "c3", "c3_theory", "fits", "c2", "beta_period", "max_disagreement",
              "front_threshold_fraction", "n_min", "n_max"):
        assert close(w[k].tolist() if isinstance(w[k], np.ndarray) else w[k], c[k]), k


def test_softwall_one_wall(program):
    s = granwave.softwall(n=(1, 30), jobs=2)
    assert s.kwall[0] == 1e9 and s.kwall[0] < s.k_c and s.rigid[0] == 0  # 1e9 < K_c = 4.05e9 (F.22)
    assert s.saturated[0] == 1 and s.n_d[0] >= 2
    assert s.f_max.shape == (1, 30) and np.all(np.abs(s.f_max[0, int(s.n_d[0]) - 1:] / s.f_plateau[0] - 1) <= 0.01)
    c = run_cli(program, "softwall", "--n", "1:30", "--jobs", 1, "--quiet")
    assert close(s.f_max[0].tolist(), c["f_max"]) and close(s.tau_max[0].tolist(), c["tau_max"])
    for k in ("n_d", "n_d_predicted", "n_d_fixed_point", "f_plateau", "tau_max_at_n_d", "kwall"):
        assert close(float(s[k][0]), c[k]), k
    assert close(s.t_q_rigid, c["t_q_rigid"]) and close(s.k_c, c["k_c"])


@pytest.mark.parametrize("law", ["fitted", "material"])
def test_softwall_sheets_match_cli(program, law):
    s = granwave.softwall(sheets=True, sheet_law=law, n=(1, 4), jobs=2)
    c = run_cli(program, "softwall", "--sheets", "--sheet-law", law, "--n", "1:4", "--jobs", 1, "--quiet")
    assert s.sheet_law == c["sheet_law"] and len(s.sheets) == len(c["sheets"]) == 9
    for a, b in zip(s.sheets, c["sheets"]):
        assert set(b) <= set(a), set(b) - set(a)  # every key of the program's JSON
        assert close(a, b), a["name"]
    for w, e in enumerate(c["walls"]):
        assert close(s.f_max[w].tolist(), e["f_max"]) and close(float(s.kwall[w]), e["kwall"])


def test_softwall_one_sheet_matches_cli(program):
    s = granwave.softwall(sheet="pvc", sheet_law="layer", n=(1, 5), jobs=1)
    c = run_cli(program, "softwall", "--sheet", "pvc", "--sheet-law", "layer", "--n", "1:5", "--jobs", 1, "--quiet")
    assert len(s.sheets) == 1 and "a_over_h_1" in s.sheets[0] and close(s.sheets[0], c["sheets"][0])


@pytest.mark.parametrize("study, kw, name", [
    ("wavespeed", dict(n=(1, 3)), "n"),
    ("wavespeed", dict(threshold=0), "threshold"),
    ("wavespeed", dict(vimp=[0.3, -1]), "vimp"),
    ("wavespeed", dict(radii=[4e-3] * 3), "radii"),
    ("softwall", dict(tol=0.9), "tol"),
    ("softwall", dict(sheets=True, kwall=1e9), "kwall"),
    ("softwall", dict(sheets=True, sheet_law="material", sheet_yield=2e8), "sheet_yield"),
    ("softwall", dict(vimp=0), "vimp"),
])
def test_bad_values_name_the_keyword(study, kw, name):
    with pytest.raises(ValueError, match=name):
        getattr(granwave, study)(**kw)


def test_progress_stops_wavespeed():
    with pytest.raises(granwave.GranwaveError) as e:
        granwave.wavespeed(n=(5, 10), vimp=[0.3], jobs=1, progress=lambda d, t: d >= 2)
    assert e.value.status == -9


def test_dispersion_matches_cli_and_theory(program):
    d = granwave.dispersion(n=64, t_samples=256)
    c = run_cli(program, "dispersion", "--n", 64, "--t-samples", 256)
    for k in ("q", "omega_ridge", "omega_theory", "resolved", "d0", "kappa", "a", "omega_c_theory",
              "omega_c_measured", "ridge_max_rel_err", "n_resolved", "c0", "c0_measured", "c0_rel_err",
              "max_overlap_dev", "d_omega", "dt_out", "dt_step", "t_total", "steps"):
        assert close(d[k].tolist() if isinstance(d[k], np.ndarray) else d[k], c[k]), k
    assert d.power.shape == (d.nq, d.n_omega)
    ok = d.resolved == 1
    # the ridge follows 2 sqrt(kappa/m) |sin(qa/2)| (physics.md 1.6) where resolved;
    # 2 % is the bound of tests/test_chain_dispersion.c on the 1024-bead default
    assert ok.sum() >= 10
    np.testing.assert_allclose(d.omega_ridge[ok], d.omega_theory[ok], rtol=0.02)


def test_dispersion_fixed_ends_and_column(program):
    d = granwave.dispersion(n=32, t_samples=128, ends="fixed")
    c = run_cli(program, "dispersion", "--n", 32, "--t-samples", 128, "--ends", "fixed")
    assert close(d.omega_ridge.tolist(), c["omega_ridge"]) and d.nq == 32
    w = granwave.dispersion(column_n=10)
    c = run_cli(program, "dispersion", "--column-n", 10)
    for k in ("tau_n", "period", "f_peak", "df", "f_min", "samples", "n_maxima", "kwall", "dt_out"):
        assert close(w[k], c[k]), k
    assert abs(w.f_peak * w.period - 1) < 0.02  # the plateau oscillation at 1/P
    assert w.freq.shape == w.spectrum.shape == (w.len,)


@pytest.mark.parametrize("kw, name", [
    (dict(n=4), "n"), (dict(f0=0), "f0"), (dict(ends="open"), "ends"), (dict(t_samples=65), "t_samples"),
    (dict(amp=0.5), "amp"), (dict(solver="rk4", method="bdf"), "method"), (dict(rtol=1), "rtol"),
])
def test_dispersion_bad_values(kw, name):
    with pytest.raises(ValueError, match=name):
        granwave.dispersion(**kw)
