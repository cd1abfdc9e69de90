"""granwave.falcon: the rigid-wall study as a library call, against the
program's `granwave falcon --json` for the same inputs (1e-12: same library)
and against the laws of the short column (physics.md 1.3; bounds of
tests/test_chain_scaling.c): F_max flat in N within 5 %, tau_N linear in N
(r^2 > 0.999), T_q within 5 % of 2 (m/k)^(2/5) v^(-1/5) (F.17, F.29)."""
import numpy as np
import pytest

import granwave
from conftest import run_cli


def test_falcon_as_the_program_and_the_laws(program):
    seen = []
    f = granwave.falcon(n=(1, 12), vimp=[0.3], heights=[3.1], jobs=2,
                        progress=lambda d, t: seen.append(d))
    cli = run_cli(program, "falcon", "--n", "1:12", "--vimp", "0.3", "--heights", "3.1", "--jobs", 2, "--quiet")
    assert f.nv == 2 and f.nn == 12 and sorted(seen) == list(range(1, 25))
    assert f.v_imp[1] == pytest.approx(np.sqrt(2 * 9.81 * 3.1e-3), rel=1e-15) and np.isnan(f.h_mm[0])
    for iv, vel in enumerate(cli["velocities"]):
        for key, ckey in [("t_q", "t_q"), ("wave_speed", "wave_speed"), ("f_max_mean", "f_max_mean"),
                          ("period_mean", "period_mean"), ("tau_fit_intercept", "tau_fit_intercept"),
                          ("wave_speed_theory", "wave_speed_theory"), ("r2", "r2")]:
            assert f[key][iv] == pytest.approx(vel[ckey], rel=1e-12), key
    assert f.accuracy == cli["accuracy_target"] and f.k_c == pytest.approx(cli["k_c"], rel=1e-15)
    for iv in range(2):
        fm = f.f_max[iv]
        assert (fm.max() - fm.min()) / fm.min() < 0.05
        assert f.r2[iv] > 0.999
        assert f.t_q_n20[iv] == pytest.approx(f.t_q_theory[iv], rel=0.05)
        # tau_N against N - 1 is the fitted line: the slope is T_q
        slope = np.polyfit(f.n - 1, f.tau_n[iv], 1)[0]
        assert slope == pytest.approx(f.t_q[iv], rel=1e-9)


def test_falcon_refusals():
    with pytest.raises(ValueError, match="heights"):
        granwave.falcon(heights=[-1])
    with pytest.raises(ValueError, match="accuracy"):
        granwave.falcon(accuracy=0.5)
    with pytest.raises(ValueError, match="radii"):
        granwave.falcon(radii=[4e-3])
    with pytest.raises(ValueError, match="vimp"):
        granwave.falcon(vimp=[], heights=[])
    # a height's fall under the run's gravity beyond the speeds (it ran at 31623 m/s)
    with pytest.raises(ValueError, match=r"heights: item 1 is 5e\+07 mm: at gravity 10000 .* 31622.8 m/s"):
        granwave.falcon(n=(1, 2), vimp=[], heights=[5e7], gravity=1e4)


def test_falcon_heights_under_gravity_as_the_program(program):
    """One rule (gw_chain_falcon_speeds): heights fall in the run's gravity, the
    library and the program alike."""
    f = granwave.falcon(n=(1, 3), vimp=[0.3], heights=[5.1], gravity=100, accuracy=0)
    cli = run_cli(program, "falcon", "--n", "1:3", "--vimp", "0.3", "--heights", "5.1", "--gravity", 100, "--quiet")
    assert f.v_imp[1] == pytest.approx(np.sqrt(2 * 100 * 5.1e-3), rel=1e-15)
    assert [v["v_imp"] for v in cli["velocities"]] == list(f.v_imp)
