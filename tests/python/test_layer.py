"""granwave.layer_impact on a small sample (60 discs) against the program's
JSON for the same inputs, and the energy ledger's closure (physics.md 2.4).

The library call and `granwave layer-impact` run the same code on the same
sample, so their numbers agree to the printing (1e-12). The ledger closure
bounds are those of tests/test_layer_cli.sh: below 2e-3 for the fast default
(verlet), 1e-4 for the exact mode (RK4 stopping at every event)."""
import numpy as np
import pytest

import granwave
from conftest import run_cli

KEYS = ["e_n", "e", "alpha_r", "v_nr", "v_ni", "v_r", "t_rebound", "penetration", "penetration_rm",
        "energy_error", "e_incident", "dissipated_first_contact", "block_loss_first_contact",
        "t_first_contact", "contact_angle", "wave_speed", "wave_speed_kinetic", "t_end", "block_mass",
        "froude"]


def compare(r, cli):
    assert bool(r.bounced) == cli["bounced"]
    for k in KEYS:
        want = float("nan") if cli[k] is None else cli[k]  # JSON null: undecided, NaN here
        assert r[k] == pytest.approx(want, rel=1e-12, nan_ok=True), k
    assert (r.n_mobile, r.n_frozen, r.wave_rings) == (cli["n_mobile"], cli["n_frozen"], cli["wave_rings"])
    for k, v in cli["ledger_end"].items():
        if k != "A":
            assert r.ledger[k][-1] == pytest.approx(v, rel=1e-12, abs=1e-9), k
    assert r.a_total == pytest.approx(cli["ledger_end"]["A"], rel=1e-12)


def test_default_impact_as_the_program(program, sample):
    r = granwave.layer_impact(sample=sample, rb_rm=1, vi=20)
    compare(r, run_cli(program, "layer-impact", "--sample", sample, "--rb-rm", 1, "--vi", 20))
    assert r.exact == 0 and 0 < r.dt < 2e-5  # the fast default: verlet with its own step


def test_other_inputs_as_the_program(program, sample):
    kw = dict(rb_rm=1.5, vi=12.5, alpha=30, x=0.2, rings=8, friction=25)
    r = granwave.layer_impact(sample=sample, **kw)
    args = []
    for k, v in kw.items():
        args += ["--" + k.replace("_", "-"), v]
    compare(r, run_cli(program, "layer-impact", "--sample", sample, *args))
    assert r.ring_kinetic.shape == (r.ns, 8) and r.peak_strain_t.shape == (8,)


def test_until_verdict_as_the_program(program, sample):
    """until is a row of the impact's table (the command's --until): the run stops
    at the bounce verdict, e_n undecided (NaN; the program's null) and t_end
    before the rebound's end, the same numbers as the program's."""
    r = granwave.layer_impact(sample=sample, vi=10, until="verdict")
    cli = run_cli(program, "layer-impact", "--sample", sample, "--vi", 10, "--until", "verdict")
    compare(r, cli)
    full = granwave.layer_impact(sample=sample, vi=10)
    assert r.t_end < full.t_end and np.isnan(r.e_n) and bool(r.bounced) == bool(full.bounced)


def test_ledger_closes(sample):
    r = granwave.layer_impact(sample=sample)
    led = r.ledger
    parts = sum(led[k] for k in ("kinetic_block", "kinetic_soil", "strain_normal", "strain_tangent",
                                 "mindlin_excess", "dissipated", "potential"))
    np.testing.assert_allclose(parts, led["total"], rtol=1e-12, atol=1e-9 * r.a_total)
    closure = np.abs(led["total"] - r.a_total) / r.a_total
    assert closure.max() == pytest.approx(r.energy_error, rel=1e-9)
    assert r.energy_error < 2e-3
    # the kinetic energy at the start is the block's: (1/2) M V_i^2
    assert led["kinetic_block"][0] == pytest.approx(r.e_incident, rel=1e-9)
    assert r.e_incident == pytest.approx(0.5 * r.block_mass * 20**2, rel=1e-12)
    # the regions at the end add up to the ledger
    total_regions = r.regions["total"].sum()
    assert total_regions == pytest.approx(led["total"][-1], rel=1e-9)


def test_exact_mode_closes_tighter(sample):
    r = granwave.layer_impact(sample=sample, exact=True, t_max=0.01)
    assert r.exact == 1 and r.energy_error < 1e-4


def test_layer_make_writes_the_programs_sample(sample, tmp_path):
    """granwave.layer_make with the inputs of the fixture's `granwave layer-make`
    writes the same discs (pluviation is deterministic for a seed), returns them,
    and records its settings in the file's header."""
    out = tmp_path / "py.txt"
    m = granwave.layer_make(n=60, width_rm=16, seed=3, out=out)
    data = [line for line in out.read_text().splitlines() if not line.startswith("#")]
    assert data == [line for line in sample.read_text().splitlines() if not line.startswith("#")]
    assert '"seed":3' in out.read_text() and m.converged == 1 and m.n == 60
    assert m.x.shape == m.y.shape == m.r.shape == (60,)
    assert m.height == pytest.approx((m.y + m.r).max(), rel=1e-15)
    assert m.width == pytest.approx(16 * 0.325, rel=1e-15)
    with pytest.raises(ValueError, match="aspect_max"):
        granwave.layer_make(n=10, aspect_max=2)
    with pytest.raises(ValueError, match="gravity"):
        granwave.layer_make(n=10, gravity=0)
