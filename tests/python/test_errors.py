"""Errors reach Python as exceptions: a bad value is a ValueError naming the
parameter (by its keyword), an unknown keyword a TypeError, an unreadable
sample an OSError naming the file, a failed run a RuntimeError; a wrong
GRANWAVE_LIB fails the import with a message naming it."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

import granwave


@pytest.mark.parametrize("kw, name", [
    (dict(vimp=0), "vimp"), (dict(vimp=-0.3), "vimp"), (dict(vimp=float("nan")), "vimp"),
    (dict(vimp="fast"), "vimp"), (dict(n=0), "n"), (dict(n=2.5), "n"), (dict(dt_out=-1), "dt_out"),
    (dict(material="unobtainium"), "material"), (dict(damping="viscous"), "damping"),
    (dict(rtol=1e-3), "rtol"), (dict(kwall=0), "kwall"), (dict(radii=[4e-3, 0]), "radii"),
    (dict(n=3, radii=[4e-3, 3e-3]), "radii"), (dict(gamma=3), "gamma"),
    (dict(solver="rk4", method="bdf"), "method"), (dict(sheet="brass", kwall=1e9), "sheet"),
])
def test_bad_chain_value_is_a_value_error_naming_it(kw, name):
    with pytest.raises(ValueError) as e:
        granwave.chain(**kw)
    assert f"{name}:" in str(e.value) and "--" not in str(e.value)
    assert isinstance(e.value, granwave.GranwaveValueError) and e.value.status == -1


def test_unknown_keyword_is_a_type_error():
    with pytest.raises(TypeError, match="bogus"):
        granwave.chain(bogus=1)
    with pytest.raises(TypeError, match="json"):
        granwave.chain(json=True)  # an output flag of the program, not a parameter
    with pytest.raises(TypeError, match="nope"):
        granwave.sweep("chain", grid={"nope": [1]})
    with pytest.raises(TypeError, match="nope"):
        granwave.sweep("chain", grid={"n": [1]}, nope=2)


def test_missing_sample_is_an_os_error(tmp_path):
    missing = tmp_path / "missing.txt"
    with pytest.raises(OSError) as e:
        granwave.layer_impact(sample=missing)
    assert str(missing) in str(e.value)


def test_malformed_sample_is_a_value_error(tmp_path):
    bad = tmp_path / "bad.txt"
    bad.write_text("granwave-layer-sample 1\nwidth 5\nrm x\n")
    with pytest.raises(ValueError, match="bad.txt"):
        granwave.layer_impact(sample=bad)


def test_bad_layer_values(sample):
    with pytest.raises(ValueError, match="sample"):
        granwave.layer_impact()
    for kw, name in [(dict(vi=-1), "vi"), (dict(alpha=90), "alpha"), (dict(rb_rm=100), "rb_rm"),
                     (dict(rings=0), "rings"), (dict(exact=True, solver="verlet"), "exact")]:
        with pytest.raises(ValueError) as e:
            granwave.layer_impact(sample=sample, **kw)
        assert str(e.value).startswith(f"layer_impact: {name}:"), str(e.value)


def test_bad_sweep_value_names_the_case():
    # a grid value is read by its option's rule with the config (no case yet):
    # the key and the value named, as the program names them with their line
    with pytest.raises(ValueError, match=r"^sweep: \[grid\] vimp: 0 is outside"):
        granwave.sweep("chain", grid={"vimp": [0.3, 0]})
    with pytest.raises(ValueError, match="model"):
        granwave.sweep("nomodel", grid={"n": [1]})


def test_run_failure_is_a_runtime_error():
    with pytest.raises(RuntimeError, match="mxstep|steps"):
        granwave.chain(n=40, max_steps=30)


def test_wrong_granwave_lib_fails_the_import(tmp_path):
    env = dict(os.environ, GRANWAVE_LIB=str(tmp_path / "nolib.so"),
               PYTHONPATH=str(Path(granwave.__file__).parents[1]))
    p = subprocess.run([sys.executable, "-c", "import granwave"], env=env, capture_output=True, text=True)
    assert p.returncode != 0 and "GRANWAVE_LIB" in p.stderr and "nolib.so" in p.stderr
