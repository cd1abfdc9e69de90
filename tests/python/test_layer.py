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
    assert (None if r.bounced < 0 else bool(r.bounced)) == cli["bounced"]  # undecided: -1, the JSON's null
    for k in KEYS:
        want = float("nan") if cli[k] is None else cli[k]  # JSON null: undecided, NaN here
        assert r[k] == pytest.approx(want, rel=1e-12, nan_ok=True), k
    assert (r.n_mobile, r.n_frozen, r.wave_rings) == (cli["n_mobile"], cli["n_frozen"], cli["wave_rings"])
    for k, v in cli["ledger_end"].items():
        if k != "A":
            assert r.ledger[k][-1] == pytest.approx(v, rel=1e-12, abs=1e-9), k
    assert r.a_total == pytest.approx(cli["ledger_end"]["A"], rel=1e-12)
    # the mass law by its name, the JSON settings' first word (it was 0/1 here: softwall's
    # sheet_law was already its name), a value the keyword takes
    assert r.mass_law == cli["settings"]["material"]["mass_law"].split()[0] and r.mass_law in ("disc", "sphere")


def test_default_impact_as_the_program(program, sample):
    r = granwave.layer_impact(sample=sample, rb_rm=1, vi=20)
    compare(r, run_cli(program, "layer-impact", "--sample", sample, "--rb-rm", 1, "--vi", 20))
    assert r.exact == 0 and 0 < r.dt < 2e-5  # the fast default: verlet with its own step


def test_other_inputs_as_the_program(program, sample):
    kw = dict(rb_rm=1.5, vi=12.5, alpha=30, x=0.2, rings=8, friction=35)  # above the settling's 30
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
    m = granwave.layer_make(n=60, width_rm=16, seed=4, out=out)
    data = [line for line in out.read_text().splitlines() if not line.startswith("#")]
    assert data == [line for line in sample.read_text().splitlines() if not line.startswith("#")]
    assert '"seed":4' in out.read_text() and m.converged == 1 and m.n == 60
    assert m.x.shape == m.y.shape == m.r.shape == (60,)
    assert m.height == pytest.approx((m.y + m.r).max(), rel=1e-15)
    assert m.width == pytest.approx(16 * 0.325, rel=1e-15)
    with pytest.raises(ValueError, match="aspect_max"):
        granwave.layer_make(n=10, aspect_max=2)
    with pytest.raises(ValueError, match="gravity"):
        granwave.layer_make(n=10, gravity=0)


def _csv(path):
    """A CSV of `layer-impact --out` ('#' lines, then a header) as {column: float array}."""
    lines = [ln for ln in path.read_text().splitlines() if not ln.startswith("#")]
    cols = lines[0].split(",")
    rows = [[float(c) if c else np.nan for c in ln.split(",")] for ln in lines[1:]]
    return {c: np.array([r[j] for r in rows]) for j, c in enumerate(cols)}


def _vtk(path):
    """Points (x, y), radius, block flag and velocity (vx, vy) of a snapshot_*.vtk."""
    lines = path.read_text().splitlines()
    i = next(k for k, s in enumerate(lines) if s.startswith("POINTS"))
    n = int(lines[i].split()[1])
    pts = np.array([[float(v) for v in lines[i + 1 + j].split()[:2]] for j in range(n)])

    def block(name, width):
        k = next(k for k, s in enumerate(lines) if s.split()[:2] in (["SCALARS", name], ["VECTORS", name]))
        k += 2 if lines[k].startswith("SCALARS") else 1
        return np.array([[float(v) for v in lines[k + j].split()[:width]] for j in range(n)])
    return pts, block("radius", 1)[:, 0], block("block", 1)[:, 0], block("velocity", 2)


def test_crowns_spectra_first_maximum_and_snapshots_as_the_program(program, sample, tmp_path):
    """What `layer-impact --json --out` adds to the library's table: the crowns by
    cross-correlation, the rings' spectra, T_f, the take-off and the first
    free-flight maximum, and the snapshots (here at t = 0 and the end, the
    program's snapshot_0.vtk and snapshot_end.vtk). The same code on the same
    sample: the JSON's numbers (17 digits) agree to 1e-12, impact.h5's spectra
    (doubles) to 1e-12; the CSV (9 digits) and VTK (9 digits) files to 1e-8
    relative (their printing, 5e-9), positions to 1e-8 of the box width."""
    kw = dict(rb_rm=1, vi=20, full=True, t_max=0.03)  # the block leaves at 1.6 ms
    out = tmp_path / "out"
    cli = run_cli(program, "layer-impact", "--sample", sample, "--rb-rm", 1, "--vi", 20, "--full", "--t-max",
                  0.03, "--out", out)
    r = granwave.layer_impact(sample=sample, snapshots=[0, 1], **kw)
    compare(r, cli)
    for k in ("t_f", "t_leave", "e_n_first", "e_first", "alpha_r_first", "v_nr_first", "v_r_first",
              "t_rebound_first", "wave_speed_xcorr", "wave_speed_xcorr_err"):
        want = float("nan") if cli[k] is None else cli[k]
        assert r[k] == pytest.approx(want, rel=1e-12, nan_ok=True), k
    assert np.isfinite(r.e_n_first) and np.isfinite(r.wave_speed_xcorr)  # this impact leaves and has a wave
    assert (r.wave_xcorr_gaps, r.zeno_guards, r.undecided) == (cli["wave_xcorr_gaps"], cli["zeno_guards"],
                                                              cli["undecided"])
    for k in ("xcorr_delay", "xcorr_rho"):
        want = np.array([np.nan if v is None else v for v in cli["crowns"][k]])
        assert r[k].shape == want.shape == (r.nrings - 1,)
        np.testing.assert_allclose(r[k], want, rtol=1e-12, equal_nan=True, err_msg=k)
    # crowns_peaks.csv: one row per ring, the delay to the next ring (empty for the last)
    peaks = _csv(out / "crowns_peaks.csv")
    np.testing.assert_allclose(r.xcorr_delay, peaks["xcorr_delay_next"][:-1], rtol=1e-8, equal_nan=True)
    # crowns_spectra.csv: rows (f, ring), ring fastest
    spec = _csv(out / "crowns_spectra.csv")
    assert r.spec_strain.shape == r.spec_kinetic.shape == (r.spec_len, r.nrings) and r.spec_len > 100
    np.testing.assert_allclose(r.spec_f, spec["f"][::r.nrings], rtol=1e-8)
    np.testing.assert_allclose(r.spec_strain.ravel(), spec["psd_strain"], rtol=1e-8, atol=1e-300)
    np.testing.assert_allclose(r.spec_kinetic.ravel(), spec["psd_kinetic"], rtol=1e-8, atol=1e-300)
    try:  # impact.h5 holds them as doubles (HDF5 builds; h5py is optional)
        import h5py
    except ImportError:
        h5py = None
    if h5py is not None and (out / "impact.h5").exists():
        with h5py.File(out / "impact.h5", "r") as f:
            np.testing.assert_allclose(r.spec_strain, f["spec_strain"][()], rtol=1e-12, atol=0)
            np.testing.assert_allclose(r.spec_kinetic, f["spec_kinetic"][()], rtol=1e-12, atol=0)
            np.testing.assert_allclose(r.spec_f, f["spec_freq"][()], rtol=1e-12, atol=0)
    # snapshots against the program's VTK files, at t = 0 and at the end (1 s > t_max)
    s = r.snapshots
    assert list(s["t"]) == [0.0, r.t_end] and s["x"].shape == (2, 61) and s["block"] == 60
    width = 16 * 0.325
    for j, name in enumerate(("snapshot_0.vtk", "snapshot_end.vtk")):
        pts, rad, blk, vel = _vtk(out / name)
        assert list(np.flatnonzero(blk)) == [s["block"]]
        np.testing.assert_allclose(s["x"][j], pts[:, 0], rtol=0, atol=1e-8 * width)
        np.testing.assert_allclose(s["y"][j], pts[:, 1], rtol=0, atol=1e-8 * width)
        np.testing.assert_allclose(s["r"], rad, rtol=1e-8)
        np.testing.assert_allclose(np.c_[s["vx"][j], s["vy"][j]], vel, rtol=1e-8, atol=1e-8 * 20)
    # the end snapshot's block is the block series' last sample
    assert s["x"][1][s["block"]] == r.block["x"][-1] and s["vy"][1][s["block"]] == r.block["vy"][-1]


def test_snapshots_at_samples_and_off_by_default(sample):
    """A snapshot is the first output sample at or after the time asked for (the
    block's position there is the block series' at that sample), in the order
    asked for; the run's numbers do not change with snapshots; none by default."""
    r0 = granwave.layer_impact(sample=sample, t_max=0.004)
    assert r0.snapshots is None and r0.nsnap == 0 and r0.block_index == -1
    asked = [2.5e-3, 1e-3, 1.01e-3]
    r = granwave.layer_impact(sample=sample, t_max=0.004, snapshots=asked)
    np.testing.assert_array_equal(r.t, r0.t)
    np.testing.assert_array_equal(r.ledger["total"], r0.ledger["total"])
    s = r.snapshots
    for j, t in enumerate(asked):
        k = int(np.searchsorted(r.t, t * (1 - 1e-12)))  # the first sample at or after t
        assert s["t"][j] == r.t[k] and s["t"][j] >= t * (1 - 1e-12) and r.t[k - 1] < t
        assert s["x"][j][s["block"]] == r.block["x"][k] and s["vy"][j][s["block"]] == r.block["vy"][k]
    with pytest.raises(ValueError, match="snapshots"):
        granwave.layer_impact(sample=sample, snapshots=[-1])


def test_progress_reaches_the_caller_and_stops_the_run(sample):
    """progress(done, total) counts output samples up to t-max (total), rising, a
    last call with done = total when the run ends (at T_f, before t-max); the
    run's numbers do not change with it; a true return stops the run
    (GW_ECANCELED), an exception in the callback is raised again."""
    r0 = granwave.layer_impact(sample=sample, t_max=0.004)
    seen = []
    r = granwave.layer_impact(sample=sample, t_max=0.004, progress=lambda d, n: seen.append((d, n)))
    total = int(round(0.004 / 2e-5)) + 1
    assert seen[0] == (0, total) and seen[-1] == (total, total)
    assert all(b[0] > a[0] for a, b in zip(seen, seen[1:])) and all(n == total for _, n in seen)
    assert len(seen) >= r.ns - 1  # a run this short reports every sample
    np.testing.assert_array_equal(r.ledger["total"], r0.ledger["total"])
    assert r.e_n_first == r0.e_n_first or (np.isnan(r.e_n_first) and np.isnan(r0.e_n_first))
    with pytest.raises(granwave.GranwaveError) as e:
        granwave.layer_impact(sample=sample, t_max=0.004, progress=lambda d, n: d >= 50)
    assert e.value.status == -9 and "progress" in str(e.value)

    def boom(d, n):
        if d >= 20:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        granwave.layer_impact(sample=sample, t_max=0.004, progress=boom)


def test_layer_make_progress_and_cancel():
    """layer_make reports every 0.01 s of simulated settling, in hundredths of t_max
    (it took no progress argument before), and a True return stops it (status -9)."""
    seen = []
    r = granwave.layer_make(n=60, width_rm=16, seed=3, progress=lambda d, t: seen.append((d, t)))
    done = [d for d, _ in seen]
    assert seen and all(t == 600 for _, t in seen)  # t_max 6 s in hundredths
    assert done == list(range(1, len(done) + 1))  # one call per 0.01 s, in order
    assert abs(done[-1] / 100 - r["t_settle"]) < 1e-9  # the last at the settled time
    with pytest.raises(granwave.GranwaveError) as e:
        granwave.layer_make(n=60, width_rm=16, seed=3, progress=lambda d, t: d >= 20)
    assert e.value.status == -9 and "at t = 0.2 s" in str(e.value)
    # the same run without a progress callback settles the same pile
    assert granwave.layer_make(n=60, width_rm=16, seed=3)["t_settle"] == r["t_settle"]
