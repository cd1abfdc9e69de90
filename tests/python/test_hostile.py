"""The Python side of the hostile pass over the layer commands (issue 18):
a path with a NUL, the pluviation's step and failure, a sample out of scale;
and of the chain's: falcon's accuracy where it cannot act, speeds below 1e-9 m/s.

A str holding a NUL reached C cut at the NUL, so 'a\\0b.txt' named 'a' (another
file, silently); it is refused naming the keyword. layer_make refuses a step
the pile's contacts cannot resolve (GranwaveValueError naming dt, nothing
written) and fails as a run (GranwaveRunError) when the discs sink through a
wall, before anything is written.
"""
import granwave
import pytest


def test_a_nul_in_a_path_is_refused(sample, tmp_path):
    other = tmp_path / "a"
    other.write_text(sample.read_text())  # what the cut name would open
    with pytest.raises(granwave.GranwaveValueError, match="sample: .* holds a NUL character"):
        granwave.layer_impact(sample=str(other) + "\0.txt", t_max=0.002)
    with pytest.raises(granwave.GranwaveValueError, match="out: .* holds a NUL character"):
        granwave.layer_make(n=10, out=str(tmp_path / "b\0.txt"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a"]
    # the same call without the NUL runs on that file
    assert granwave.layer_impact(sample=other, t_max=0.002)["t_end"] == pytest.approx(0.002, rel=1e-12)


def test_layer_make_step_and_failure(tmp_path):
    out = tmp_path / "s.txt"
    with pytest.raises(granwave.GranwaveValueError, match=r"dt: a step of 2e-05 s is above 1/2 of the shortest contact"):
        granwave.layer_make(n=20, width_rm=10, rm=1e-4, out=out)
    assert not out.exists()
    with pytest.raises(granwave.GranwaveRunError, match="did not settle into a valid sample.*too soft"):
        granwave.layer_make(n=60, width_rm=12, shear_modulus=1e-3, t_max=0.3, out=out)
    assert not out.exists()
    # below one settling chunk (0.01 s) it still runs to t-max: 250 steps of 2e-5 s
    m = granwave.layer_make(n=20, width_rm=10, t_max=0.005, out=out)
    assert m.t_settle == pytest.approx(0.005, rel=1e-12) and m.steps == 250 and not m.converged


def test_a_sample_out_of_scale_is_refused(sample, tmp_path):
    text = sample.read_text().splitlines()
    bad = tmp_path / "rm.txt"
    bad.write_text("\n".join("rm 1e-300" if line.startswith("rm ") else line for line in text) + "\n")
    with pytest.raises(granwave.GranwaveValueError, match=r"rm 1e-300 m is outside \[1e-05, 1000\] m"):
        granwave.layer_impact(sample=bad, t_max=0.002)


def test_falcon_accuracy_where_it_cannot_act():
    # The step study picks RK4 by the accuracy target only for its own columns and
    # with the solver at its defaults; an accuracy asked for elsewhere was silently
    # ignored by the library (the command refused it).
    with pytest.raises(granwave.GranwaveValueError, match="accuracy: give either accuracy or the solver options"):
        granwave.falcon(heights=None, n=(1, 3), accuracy=1e-4, solver="arkode")
    with pytest.raises(granwave.GranwaveValueError, match="accuracy: the step study covers"):
        granwave.falcon(heights=None, n=(1, 50), accuracy=1e-4)
    # refused by the row itself, [1e-9, 1e-2] or 0 (its range said [0, 1e-2] before)
    with pytest.raises(granwave.GranwaveValueError, match=r"accuracy: 1e-12 is outside \[1e-09, 0.01\] \(or 0\)"):
        granwave.falcon(heights=None, n=(1, 3), accuracy=1e-12)
    # where it acts, it is recorded; with the solver given and accuracy left alone, 0
    assert granwave.falcon(heights=None, n=(1, 3), accuracy=1e-4).accuracy == 1e-4
    assert granwave.falcon(heights=None, n=(1, 3), solver="arkode").accuracy == 0


def test_chain_speeds_below_a_nanometre_per_second_are_refused():
    with pytest.raises(granwave.GranwaveValueError, match=r"vimp: 1e-200 is outside \[1e-09, 1000\]"):
        granwave.chain(n=3, vimp=1e-200)
    r = granwave.chain(n=1, vimp=1e-9)
    ref = granwave.chain(n=1, vimp=0.3)
    # Hertz: F_max ~ v^(6/5) (docs/physics.md 1.2)
    assert r.f_max == pytest.approx(ref.f_max * (1e-9 / 0.3) ** 1.2, rel=1e-3)


def _lattice_sample(path, ncol=25, nrow=200, r=0.325):
    """A square lattice of equal discs 1 mm apart resting on the floor."""
    d = 2 * r + 1e-3
    rows = ["granwave-layer-sample 1", f"width {ncol * d!r}", f"rm {r!r}", "volume_ratio 1",
            "seed 1", "mass_law disc", f"n {ncol * nrow}"]
    rows += [f"{d / 2 + i * d!r} {r + 5e-4 + j * d!r} {r!r}" for j in range(nrow) for i in range(ncol)]
    path.write_text("\n".join(rows) + "\n")
    return path


def test_resources_bounded_before_the_run(tmp_path):
    # 10000 snapshots of a 5000-disc sample reached 5.8 GB (2.4 GB in C, then
    # copied into arrays); the snapshots are bounded at 1 GiB before the run
    s = _lattice_sample(tmp_path / "lattice.txt")
    with pytest.raises(granwave.GranwaveValueError,
                       match=r"snapshots: 10000 snapshots of 5001 particles need 2.4 GB, above the 1.07 GB limit: "
                             r"at most 4473 of this sample"):
        granwave.layer_impact(sample=s, snapshots=[0.0] * 10000, t_max=1e-4, skin=1e-3)
    r = granwave.layer_impact(sample=s, snapshots=[0.0] * 100, t_max=1e-4, skin=1e-3)
    assert len(r["snapshots"]["t"]) == 100
    # a pluviation's work (1e10 particle-steps) and a drop's stored trace (5 GB
    # of files, 1.4 GB in memory) as the commands refuse them
    out = tmp_path / "s.txt"
    with pytest.raises(granwave.GranwaveValueError, match=r"n: 100000 particles .* more than 1e10: lower n to 6666"):
        granwave.layer_make(n=100000, out=out)
    assert not out.exists()
    with pytest.raises(granwave.GranwaveValueError, match=r"dt_out: the trace of 1000 beads .*160 GB in memory"):
        granwave.drop(n=1000, t_max=1, dt_out=1e-7, trace=True)


def test_results_record_the_settings_that_ran():
    # The studies over N and the drop recorded t_max, dt_out, dt and dt_max as 0
    # (the default marker), not what ran; every result now carries the values each
    # collision used, equal to those of the same column run alone.
    c = granwave.chain(n=3, solver="rk4")
    assert c.t_max == pytest.approx(20 * (3 * c.t_q + c.tau_1), rel=1e-12)
    assert c.dt_out == pytest.approx(c.tau_1 / 200, rel=1e-12)
    assert c.dt == pytest.approx(c.t_q / 800, rel=1e-12) and 0 < c.dt_max < c.tau_1
    f = granwave.falcon(heights=[], n=(1, 3), vimp=[0.3, 0.5], solver="arkode")
    for iv, v in enumerate((0.3, 0.5)):
        for k, n in enumerate((1, 2, 3)):
            one = granwave.chain(n=n, vimp=v, solver="arkode")
            for key in ("t_max", "dt_out", "dt_max"):
                assert f[key][iv][k] == pytest.approx(one[key], rel=1e-12), (key, v, n)
            assert f.dt[iv][k] == 0  # arkode: no fixed step
    d = granwave.drop(n=3, solver="rk4")
    assert d.dt > 0 and d.dt_max > 0
    one = granwave.chain(n=3, vimp=d.v_imp, solver="rk4", gravity=9.81)
    assert d.dt == pytest.approx(one.dt, rel=1e-12) and d.dt_max == pytest.approx(one.dt_max, rel=1e-12)
    s = granwave.softwall(n=(1, 3))
    assert s.t_max.shape == (1, 3) and all(s.t_max[0] > 0) and all(s.dt_max[0] > 0)
    w = granwave.wavespeed(n=(6, 8), vimp=[0.3])
    assert w.t_max[0][2] == pytest.approx(granwave.chain(n=8, vimp=0.3).t_max, rel=1e-12)


def test_a_column_memory_is_bounded_before_allocation():
    # chain(n=50000000) ended "out of memory" from its first allocation; a
    # sensor body's states, ordered before the beads in the implicit methods'
    # band, keep its memory linear in n (the whole band before: at most 3339)
    with pytest.raises(granwave.GranwaveValueError,
                       match=r"n: a column of 50000000 beads needs about 47.2 GB .* at most 2274873 beads here"):
        granwave.chain(n=50000000)
    with pytest.raises(granwave.GranwaveValueError, match=r"n: a column of 20000000 beads .* at most 2164797 beads"):
        granwave.chain(n=20000000, sensor_mass=100, sensor_stiffness=1e3)  # 1 kg: its ring's steps first


def test_a_speed_given_twice_is_refused():
    with pytest.raises(granwave.GranwaveValueError, match=r"vimp: item 2 gives the impact velocity 0.3 m/s of item 1"):
        granwave.falcon(heights=[], n=(1, 3), vimp=[0.3, 0.3])
    with pytest.raises(granwave.GranwaveValueError, match=r"vimp: item 3 gives the impact velocity 0.3 m/s of item 1"):
        granwave.wavespeed(n=(6, 8), vimp=[0.3, 0.5, 0.3])


def test_a_range_keyword_takes_two_integer_ends():
    # n=(1.5, 3) was cut to 1:3 by int() (a silent change of the input) and
    # n=(1, 2, 3) raised a bare "too many values to unpack"
    with pytest.raises(granwave.GranwaveValueError, match=r"n: '1.5:3' is not a range A:B of integers, A <= B \(its start: '1.5' is not an integer"):
        granwave.falcon(n=(1.5, 3), heights=[])
    with pytest.raises(TypeError, match=r"n: expected \(A, B\), an integer or a range"):
        granwave.falcon(n=(1, 2, 3), heights=[])
    with pytest.raises(TypeError, match=r"n: a range end must be a number, got True"):
        granwave.falcon(n=(True, 3), heights=[])
    assert granwave.falcon(n=[1, 3], heights=[]).nn == 3


def test_falcon_runs_the_solver_given():
    # solver="cvode" (the default's value) was taken as not given: RK4 by the
    # accuracy target ran instead, as recorded (accuracy 1e-6, dt > 0)
    f = granwave.falcon(n=(1, 3), heights=[], solver="cvode")
    assert f.accuracy == 0 and (f.dt == 0).all()
    one = granwave.chain(n=3, solver="cvode")
    assert f.f_max[0][2] == pytest.approx(one.f_max, rel=1e-12)
    g = granwave.falcon(n=(1, 3), heights=[])  # nothing given: the accuracy target, RK4
    assert g.accuracy == 1e-6 and (g.dt > 0).all()


def test_a_failed_run_names_the_study_once():
    """The library's run messages start with the study ("chain: bead 1 ..."):
    Python said it twice ("chain: chain: ...", "drop: drop: ...")."""
    with pytest.raises(granwave.GranwaveRunError) as e:
        granwave.chain(n=3, t_max=1e-7)
    assert str(e.value) == "chain: bead 1 still on the wall at t_max = 1e-07 s"
    with pytest.raises(granwave.GranwaveRunError) as e:
        granwave.drop(energy_tol=1e-20)
    assert str(e.value).startswith("drop: relative energy error ") and "drop: drop" not in str(e.value)
    with pytest.raises(granwave.GranwaveValueError) as e:  # a parameter's message: the study, then the keyword
        granwave.chain(t_max=1e300)
    assert str(e.value).startswith("chain: t_max: ")


@pytest.mark.parametrize("e", [0, 1])
def test_restitution_range_is_open_at_both_ends(e):
    """restitution=1 was refused as "1 must be below 1", 0 as outside (0, 1]."""
    with pytest.raises(granwave.GranwaveValueError) as x:
        granwave.chain(restitution=e, damping="hc")
    assert str(x.value) == f"chain: restitution: {e} is outside (0, 1)"


def test_a_blown_up_run_fails_with_its_time():
    """An RK4 step 260 times the 30 um bead's: the run blew up and returned with
    F_max NaN; it fails now, at the time it blew up."""
    with pytest.raises(granwave.GranwaveRunError) as e:
        granwave.chain(n=3, radii=[4e-3, 3e-5, 4e-3], solver="rk4", dt=7e-8)
    assert str(e.value).startswith("chain: the solution blew up at t = ")


def test_a_value_python_refuses_names_the_study():
    """A NUL or a bool refused before the library saw them said "material: ..." and
    "n: expected a number" without the study every other refusal names."""
    with pytest.raises(granwave.GranwaveValueError) as e:
        granwave.chain(material="steel\0x")
    assert str(e.value).startswith("chain: material: ")
    with pytest.raises(TypeError) as t:
        granwave.drop(n=True)
    assert str(t.value) == "drop: n: expected a number, got True"
