"""granwave.sweep over the library's sweep engine (the cases and columns of
`granwave sweep`): every case equals the single call with the same inputs, the
Hertz scaling holds across the grid, progress reaches the caller.

RK4 (dt = T_c/400, T_c scaling with v like every time of the problem) keeps
the scaling invariance to rounding, so 1e-6 holds (tests/test_chain_scaling.c)."""
import numpy as np
import pytest

import granwave


def test_chain_grid_matches_single_calls_and_scales():
    calls = []
    s = granwave.sweep("chain", grid={"n": range(1, 5), "vimp": [0.1, 0.4]}, solver="rk4", jobs=2,
                       progress=lambda done, total: calls.append((done, total)))
    assert s.ncases == 8 and list(s.n) == [1, 1, 2, 2, 3, 3, 4, 4] and list(s.vimp) == [0.1, 0.4] * 4
    assert [c[0] for c in calls] == list(range(1, 9)) and all(c[1] == 8 for c in calls)
    for i in range(8):
        r = granwave.chain(n=int(s.n[i]), vimp=s.vimp[i], solver="rk4")
        assert s.f_max[i] == r.f_max and s.tau_n[i] == r.tau_n and s.eps_eff[i] == r.eps_eff
    fs = s.f_max * s.vimp**-1.2
    np.testing.assert_allclose(fs[0::2], fs[1::2], rtol=1e-6)
    np.testing.assert_allclose((s.tau_n * s.vimp**0.2)[0::2], (s.tau_n * s.vimp**0.2)[1::2], rtol=1e-6)
    assert (s.converged == 1).all()


def test_layer_grid(sample):
    s = granwave.sweep("layer", grid={"vi": [10, 20]}, sample=sample, jobs=1)
    for i, vi in enumerate([10, 20]):
        r = granwave.layer_impact(sample=sample, vi=vi)
        assert s.e_n[i] == pytest.approx(r.e_n, rel=1e-12, nan_ok=True)
        assert s.penetration[i] == pytest.approx(r.penetration, rel=1e-12)
        assert s.energy_error[i] == pytest.approx(r.energy_error, rel=1e-12)


def test_progress_can_stop_a_sweep():
    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop

    with pytest.raises(Stop):
        granwave.sweep("chain", grid={"n": "1:6"}, solver="rk4", jobs=1, progress=stop)
    with pytest.raises(granwave.GranwaveError) as e:
        granwave.sweep("chain", grid={"n": "1:6"}, solver="rk4", jobs=1, progress=lambda d, t: True)
    assert e.value.status == -9 and "canceled" in str(e.value)
