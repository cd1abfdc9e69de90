"""The Python side of the hostile pass over the layer commands (issue 20):
a path with a NUL, the pluviation's step and failure, a sample out of scale.

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
