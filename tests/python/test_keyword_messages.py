"""Python's messages name Python's keywords (issue 18, the nineteenth session
of stage 2).

The library writes its texts for the program: an input is the flag ("raise
--t-max", "an --f0 so small", "a --dt-out too fine for --t-samples") or the
row's name ("t-max = 0.05 s", "dt-out: ...", "raise dt-out, lower t-max").
Python issued and raised them as they were, so a caller who wrote t_max= was
told to raise --t-max; only a message's leading "NAME:" was renamed, and a
sweep's not at all ("sweep: case 0: t-max: -1 is outside ..."). The module now
words every library text it passes on (errors, warnings, the result's
`warnings`) with the call's inputs named by their keywords
(_core.keyword_text); a flag the function does not take (layer_impact's
"files with --out") and a quoted command line of the program ("granwave chain
--n 3") stay as they are. The program's messages are unchanged, byte for byte
(tests/python/test_warnings_one_source.py compares the three callers' texts).
On the module before, 6 of the 9 tests fail (the quoted command line, the
program's own messages and a value quoted back pass).
"""
import re
import subprocess
import warnings

import pytest

import granwave


def _warnings(fn, **kw):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r = fn(**kw)
    texts = [str(x.message) for x in w if issubclass(x.category, granwave.GranwaveWarning)]
    assert r.warnings == [t.split(": ", 1)[1] for t in texts]
    return texts


def _no_flags(text, study):
    """No input of the study named as a flag or by its row's name with a '-'."""
    for p in granwave.params(study):
        n = p["name"]
        assert "--" + n not in text and not ("-" in n and re.search(rf"(?<![\w/-]){re.escape(n)}(?![\w-])", text)), \
            (n, text)


def test_a_cut_collision_says_raise_t_max():
    (t,) = _warnings(granwave.chain, n=7, t_max=1.94e-4)
    assert t.endswith("; raise t_max"), t
    _no_flags(t, "chain")


def test_the_dispersion_warning_names_f0_dt_out_t_samples():
    (t,) = _warnings(granwave.dispersion, n=64, f0=1e-300)
    assert ("(an f0 so small that it underflows, a dt_out too fine for t_samples, or a min_bins near half of "
            "t_samples)") in t, t
    _no_flags(t, "dispersion")


def test_the_overlap_warning_names_vimp_and_gravity():
    (t,) = _warnings(granwave.chain, n=3, vimp=1000, mass=1e3, k=1e3, kwall=1e3)
    assert "(a lower vimp or gravity, or stiffer or lighter beads)" in t, t


def test_layer_make_names_t_max_by_its_keyword():
    (t,) = _warnings(granwave.layer_make, n=60, width_rm=16, seed=3, t_max=0.05)
    assert t.startswith("layer_make: the sample did not settle: t_max = 0.05 s ends before") and \
        t.endswith("raise t_max)"), t
    _no_flags(t, "layer-make")


def test_an_error_names_every_input_by_its_keyword(sample):
    with pytest.raises(granwave.GranwaveValueError) as e:
        granwave.layer_impact(sample=sample, rings=1000, t_max=0.5, dt_out=8e-6)
    msg = str(e.value)
    assert msg.startswith("layer_impact: dt_out: ") and msg.endswith("(raise dt_out, lower t_max or rings)"), msg
    assert "of files with --out" in msg  # the program's option: layer_impact takes no out


def test_a_sweep_names_its_keys_by_their_keywords():
    with pytest.raises(granwave.GranwaveValueError, match=r"^sweep: \[grid\] t_max: -1 is outside \[0, 1e\+06\]$"):
        granwave.sweep("chain", {"t_max": [-1]})
    with pytest.raises(granwave.GranwaveValueError, match=r"^sweep: case 0: dt_out: .*: raise dt_out$"):
        granwave.sweep("chain", {"n": [2]}, dt_out=1e-30, t_max=1)


def test_a_quoted_command_line_stays_the_programs():
    with pytest.raises(granwave.GranwaveValueError, match=r"^falcon: n: 3:3 is one column size.*\(one column's "
                       r"collision: granwave chain --n 3\)$"):
        granwave.falcon(n=(3, 3), vimp=[0.3], heights=[])


def test_the_program_still_names_its_flags(program, tmp_path):
    p = subprocess.run([program, "chain", "--n", "7", "--t-max", "1.94e-4"], capture_output=True, text=True,
                       timeout=60)
    assert p.returncode == 0 and p.stderr.rstrip().endswith("; raise --t-max"), p.stderr
    (tmp_path / "c.ini").write_text("[sweep]\nmodel = chain\n[grid]\nt-max = -1\n")
    p = subprocess.run([program, "sweep", str(tmp_path / "c.ini"), "--check", "--out", str(tmp_path / "o")],
                       capture_output=True, text=True,
                       timeout=60)
    assert p.returncode == 2 and "c.ini:4: [grid] t-max: -1 is outside" in p.stderr, p.stderr


def test_a_value_quoted_back_stays_as_given(tmp_path, monkeypatch):
    # a sample file called t-max is the caller's text, not the input t_max
    monkeypatch.chdir(tmp_path)
    with pytest.raises(granwave.GranwaveIOError, match=r"^layer_impact: sample: t-max: cannot open"):
        granwave.layer_impact(sample="t-max")
    with pytest.raises(granwave.GranwaveValueError, match=r"^sweep: case 0: sample: dt-out: cannot open"):
        granwave.sweep("layer", {"vi": [10]}, sample="dt-out")
