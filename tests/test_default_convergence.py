"""Reported numbers converged at the defaults (the nineteenth hostile pass, part 2).

Each command's defaults were refined (tighter rtol, the other backends, smaller
steps, the exact mode) and the reported quantities compared. Three were not
converged, and this test asserts that they are now:

- drop: the contacts and the cluster at each wall-force peak. The root flags
  flip at zero overlap, where beads the wave has not reached yet touch, so the
  N = 40 drop's fourth peak had cluster 40 under cvode and 12 under arkode;
  they are now read from the overlaps with the drop's own tolerance.
- drop: first_collision.wall_done. The first collision is cut half way
  through bead 1's flight, where its velocity is zero but for the integration's
  error; the flag followed that sign (false at rtol 1e-12, true at 1e-13).
- layer-impact: the first contact (t_first_contact, dissipated_first_contact)
  was read at the step end of the smallest block energy, an error of up to half
  a step times the rates: the default impact's dissipation moved by 0.8 %
  between its 10 us step and 5 us. The minimum is now located on a parabola.

And one that was fine and is kept so: falcon's automatic solver gives F_max,
tau_N, tau_max and the period within its 1e-6 target.

Run by ctest (test_default_convergence) with GRANWAVE_PROGRAM, PYTHONPATH and
GRANWAVE_LIB set as for test_python; by hand:
    PYTHONPATH=python GRANWAVE_PROGRAM=build/granwave /usr/bin/python3 -m pytest -q tests/test_default_convergence.py
"""
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import granwave

REPO = Path(__file__).resolve().parents[1]
DROP = dict(n=40, damping="kk", restitution=0.9)


def _peaks(r):
    return np.asarray(r.peak_cluster).tolist(), np.asarray(r.peak_contacts).tolist()


@pytest.mark.parametrize("height", [5.1e-3, 1.9e-3])
def test_drop_peak_contacts_the_same_on_every_backend(height):
    base = granwave.drop(height=height, **DROP)
    for kw in (dict(rtol=1e-13, atol=1e-13), dict(solver="arkode")):
        r = granwave.drop(height=height, **DROP, **kw)
        assert r.n_peaks == base.n_peaks and r.n_impacts == base.n_impacts, kw
        assert np.allclose(r.wall_peaks["t"], base.wall_peaks["t"], rtol=1e-7, atol=0), kw
        assert _peaks(r) == _peaks(base), kw
        assert [int(c) for c in r.impacts["cluster"]] == [int(c) for c in base.impacts["cluster"]], kw


@pytest.mark.parametrize("height", [5.1e-3, 1.9e-3])
def test_drop_first_collision_done_at_its_half_flight_cut(height):
    for kw in (dict(), dict(rtol=1e-13, atol=1e-13), dict(solver="arkode"), dict(solver="rk4"), dict(dt_out=7.3e-6)):
        r = granwave.drop(height=height, **DROP, **kw)
        fc = r.first_collision
        # cut in bead 1's first flight (not the chain's own end), bead 1 turning there
        assert fc["converged"] is False and r.cut_first_collision is False, kw
        assert abs(fc["final_velocities"][0]) < 1e-8 * r.v_imp, kw
        assert fc["wall_done"] is True, kw


@pytest.fixture(scope="module")
def sample(tmp_path_factory):
    program = os.environ.get("GRANWAVE_PROGRAM") or str(REPO / "build" / "granwave")
    if not Path(program).exists():
        pytest.skip(f"no granwave program at {program}")
    path = tmp_path_factory.mktemp("layer") / "a.txt"
    subprocess.run([program, "layer-make", "--n", "60", "--width-rm", "16", "--seed", "4", "--out", str(path)],
                   check=True, capture_output=True)
    return str(path)


@pytest.mark.parametrize("case", [dict(), dict(vi=10), dict(alpha=30), dict(vi=40)])
def test_layer_first_contact_located_between_step_ends(sample, case):
    ex = granwave.layer_impact(sample=sample, until="verdict", exact=True, **case)
    for dt in (0, 5e-6, 2.5e-6):
        r = granwave.layer_impact(sample=sample, until="verdict", dt=dt, **case)
        step = r.dt
        # the smallest block energy located: within a tenth of the step of the
        # exact mode's (it was the step end: up to half a step off)
        assert abs(r.t_first_contact - ex.t_first_contact) < 0.1 * step, (case, dt)
        assert r.dissipated_first_contact == pytest.approx(ex.dissipated_first_contact, rel=2e-3), (case, dt)
        assert r.block_loss_first_contact == pytest.approx(ex.block_loss_first_contact, rel=1e-4), (case, dt)
    # the exact mode's own 1 us evaluations, located the same way
    assert ex.t_first_contact != pytest.approx(round(ex.t_first_contact / 1e-6) * 1e-6, abs=1e-12)


def test_falcon_automatic_solver_within_its_target():
    d = granwave.falcon(n=(1, 12), heights=[])
    ref = granwave.falcon(n=(1, 12), heights=[], solver="cvode", rtol=1e-13, atol=1e-13)
    assert d.accuracy == 1e-6 and d.steps_per_tc == 37
    for k in ("f_max", "tau_n", "tau_max", "period"):
        a, b = np.asarray(d[k], float), np.asarray(ref[k], float)
        ok = np.isfinite(b)
        assert np.array_equal(np.isfinite(a), ok), k
        assert np.max(np.abs(a[ok] - b[ok]) / np.abs(b[ok])) < 1e-6, k
    for k in ("n_maxima", "n_s", "cluster"):
        assert np.array_equal(np.asarray(d[k]), np.asarray(ref[k])), k
