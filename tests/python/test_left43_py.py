"""What the forty-second session left in the Python module (the forty-third
session):

- a sweep giving `k` to cases that are all one body (n = 1) is refused as the
  program's sweep refuses it (test_no_effect_drag, part 3), naming k and the
  cases; a grid where k acts on some cases runs (this was untested);
- an integer no double holds given for a real keyword (vimp=2**1100) was
  refused quoting its 332 digits (the library quoted the text it was given,
  and the program did the same on the command line): the library's refusal
  now quotes a number of more than 40 characters by its first 20 and its
  length, one short line naming vimp, in Python and in the program alike;
- the module's own refusals of a sweep's grid and params values ("n: empty
  list of grid values", "n: a grid value holds ','", a value that cannot go
  into a config) named no call, where the library's say "sweep: [grid] n:":
  they say it too;
- gravity=-1 and mass=1e300 (and a sensor mass of 1e300) are refused by every
  study that takes them and by a sweep's grid and params, with the program's
  own words (the library's parameter checks, run by both).
"""
import os
import subprocess

import pytest

import granwave

GW_EINVAL = -1
PROGRAM = os.environ.get("GRANWAVE_PROGRAM")


def refusal(call):
    with pytest.raises(granwave.GranwaveValueError) as e:
        call()
    text = str(e.value)
    assert e.value.status == GW_EINVAL and "\n" not in text, text
    return text


# --- a sweep's k on one body ---

def test_sweep_k_on_one_body_is_refused():
    text = refusal(lambda: granwave.sweep("chain", {"k": [1e3, 2e3]}, n=1, jobs=1))
    assert "k: has no effect on one body (n = 1) in any case (2 of 2 cases; the first, case 0)" in text, text


def test_sweep_k_on_one_body_as_the_grid_is_refused():
    text = refusal(lambda: granwave.sweep("chain", {"n": [1]}, k=1e3, jobs=1))
    assert "k: has no effect on one body" in text, text


def test_sweep_k_acting_on_some_cases_runs():
    s = granwave.sweep("chain", {"n": [1, 3]}, k=1e9, jobs=1)
    assert s.ncases == 2 and list(s.n) == [1, 3]


# --- a number of many digits quoted short ---

BIG = 2**1100  # 332 digits, beyond the doubles


@pytest.mark.parametrize("call, named", [
    (lambda: granwave.chain(vimp=BIG), "chain: vimp: '13582985290493858492...' (332 characters) is not a finite"),
    (lambda: granwave.chain(vimp=-BIG), "chain: vimp: '-1358298529049385849...' (333 characters) is not a finite"),
    (lambda: granwave.falcon(vimp=[0.3, BIG]), "falcon: vimp:"),
    (lambda: granwave.chain(n=2, radii=[1e-3, BIG]), "chain: radii:"),
    (lambda: granwave.chain(n=BIG), "chain: n: 13582985290493858492... (332 characters) is outside [1, 50000000]"),
    (lambda: granwave.chain(n=2**200), "chain: n: 16069380442589902755... (61 characters) is outside"),
    (lambda: granwave.dispersion(vimp=BIG), "dispersion: vimp:"),
], ids=["vimp", "-vimp", "falcon vimp list", "radii item", "n", "n 2**200", "dispersion vimp"])
def test_a_long_number_is_quoted_short(call, named):
    text = refusal(call)
    assert named in text and len(text) < 160, text


def test_a_number_of_40_characters_is_quoted_whole():
    v = "1" * 40  # 1.1e39: outside the range, quoted whole as given
    text = refusal(lambda: granwave.chain(n=int(v)))
    assert f"chain: n: {v} is outside" in text, text


@pytest.mark.skipif(not PROGRAM, reason="GRANWAVE_PROGRAM not set")
def test_the_program_quotes_it_short_too():
    r = subprocess.run([PROGRAM, "chain", "--vimp", str(BIG)], capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and r.stdout == "", (r.returncode, r.stdout)
    assert r.stderr == "granwave chain --vimp: '13582985290493858492...' (332 characters) is not a finite number\n", \
        r.stderr


# --- the sweep's own refusals name the call ---

@pytest.mark.parametrize("call, start", [
    (lambda: granwave.sweep("chain", {"n": []}), "sweep: [grid] n: empty list of grid values"),
    (lambda: granwave.sweep("chain", {"n": ["1,2"]}), "sweep: [grid] n: a grid value holds ','"),
    (lambda: granwave.sweep("chain", {"n": ["1\nvimp = 5"]}), "sweep: [grid] n: value"),
    (lambda: granwave.sweep("chain", {"n": [2]}, solver="rk4;x"), "sweep: [params] solver: value"),
    (lambda: granwave.sweep("chain", {"n": [2, 10**5000]}), "sweep: [grid] n: an integer of about 5001 digits"),
    (lambda: granwave.sweep("chain", {"n": [2]}, vimp=10**5000), "sweep: [params] vimp: an integer of about"),
    (lambda: granwave.sweep("chain", {"vimp": [0]}), "sweep: [grid] vimp: 0 is outside"),  # the library's (control)
], ids=["empty", "comma", "newline", "params ;", "grid huge", "params huge", "library's"])
def test_sweep_value_refusals_name_the_call(call, start):
    text = refusal(call)
    assert text.startswith(start), text


# --- gravity and mass refused as the program refuses them ---

STUDIES = {"chain": granwave.chain, "drop": granwave.drop, "falcon": granwave.falcon,
           "wavespeed": granwave.wavespeed, "softwall": granwave.softwall, "layer-make": granwave.layer_make,
           "layer-impact": granwave.layer_impact}
BAD = [("gravity", -1), ("mass", 1e300), ("sensor-mass", 1e300)]
CASES = [(s, k, v) for s in STUDIES for k, v in BAD
         if any(p["name"] == k for p in granwave.params(s))]


@pytest.mark.parametrize("study, key, value", CASES, ids=[f"{s} {k}" for s, k, _ in CASES])
def test_gravity_and_mass_refused_as_the_program(study, key, value):
    kw = key.replace("-", "_")
    text = refusal(lambda: STUDIES[study](**{kw: value}))
    func = study.replace("-", "_")
    assert text.startswith(f"{func}: {kw}: ") and "is outside" in text, text
    if PROGRAM:
        r = subprocess.run([PROGRAM, study, f"--{key}", repr(value)], capture_output=True, text=True, timeout=60)
        assert r.returncode == 2, (r.returncode, r.stderr)
        # the same words after the name: "granwave STUDY --KEY: ..." against "FUNC: KEY: ..."
        assert r.stderr.rstrip("\n").split(": ", 1)[1] == text.split(": ", 2)[2], (r.stderr, text)


@pytest.mark.parametrize("grid, params", [({"gravity": [-1]}, {}), ({"n": [2]}, {"gravity": -1}),
                                          ({"mass": [1e300]}, {}), ({"n": [2]}, {"mass": 1e300})],
                         ids=["grid gravity", "params gravity", "grid mass", "params mass"])
def test_gravity_and_mass_refused_by_a_sweep(grid, params):
    text = refusal(lambda: granwave.sweep("chain", grid, jobs=1, **params))
    assert text.startswith("sweep: [") and "is outside" in text, text
