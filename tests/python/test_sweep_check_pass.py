"""One case's check is a one-case sweep's check pass (session 48).

granwave.sweep_case_check ran the model's check of the case alone
(gw_sweep_case_check), not the sweep's pass: the pass's refusals of the config
as a whole were missed, so sweep_case_check("chain", n=1, k=1e9) passed while
sweep("chain", {"n": [1]}, k=1e9) was refused ("k: has no effect on one body
(n = 1) in any case"), and its refusals lacked the "case 0: " the sweep says.
Now both run the library's one pass (gw_sweep_check_pass, through
gw_sweep_case_check_pass and gw_sweep_check_text), as the program's
`granwave sweep --check` does.

Each case below is held four ways: sweep_case_check(model, **case), the new
sweep_check(model, grid, **rest) of the one-case sweep, the sweep() run of it
(refused before any case runs) and the program's `sweep CONFIG --check` (exit
2, one line "granwave sweep: CONFIG: MSG", MSG the library's with the inputs
named by their keywords; exit 0 for a case that passes). The verdicts
(None or the exception's class and text) must agree.
"""
import subprocess
from pathlib import Path

import pytest

import granwave
from granwave import _core, _sweep

REPO = Path(__file__).resolve().parents[2]
SAMPLE = str(REPO / "data" / "measured" / "restitution_full" / "sample.txt")

# (model, the case's keywords, the grid key of its one-case sweep, whether
# the pass refuses it: vimp = 0 is refused by the config's reader first, as
# "[params] vimp: ...", before the pass; the verdict is the same)
REFUSED = [
    ("chain", {"n": 1, "k": 1e9}, "n", True),          # the config as a whole: k on one body in every case
    ("chain", {"n": 1, "k": 1e9, "vimp": 0.3}, "vimp", True),
    ("chain", {"n": 3, "vimp": 0}, "n", False),         # the value's rule, in the reader
    ("chain", {"n": 3, "solver": "rk4", "rtol": 1e-8}, "n", True),  # the case's own check
    ("chain", {"n": 2, "vimp": 0.3, "gamma": 1e3}, "n", True),     # gamma without its damping model
    ("layer", {"sample": SAMPLE, "vi": 0.001}, "vi", True),
    ("layer", {"sample": SAMPLE, "vi": 20, "point": 5, "points": 2}, "vi", True),
]
PASSED = [
    ("chain", {"n": 3, "vimp": 0.3}, "n"),
    ("chain", {"n": 2, "k": 1e9}, "n"),           # k acts on two beads
    ("chain", {"n": 1, "kwall": 1e9}, "n"),       # the wall's coefficient acts on one body
    ("layer", {"sample": SAMPLE, "vi": 20}, "vi"),
    ("layer", {"sample": SAMPLE, "vi": 20, "point": 1, "points": 2}, "vi"),
]


def _ids(c):
    return c[0] + ":" + ",".join(f"{k}={v}" for k, v in c[1].items() if k != "sample")


def _one_case(case, key):
    rest = dict(case)
    grid = {key: [rest.pop(key)]}
    return grid, rest


def _verdict(f, *args, **kwargs):
    try:
        f(*args, **kwargs)
    except granwave.GranwaveError as e:
        return type(e), str(e)
    return None


def _program_check(program, tmp_path, model, grid, rest):
    """`granwave sweep CONFIG --check` of the one-case sweep: (exit code,
    stderr), nothing written."""
    cfg = tmp_path / "c.ini"
    lines = ["[sweep]", f"model = {model}", f"out = {tmp_path / 'o'}", "[grid]"]
    lines += [f"{k.replace('_', '-')} = {v[0]}" for k, v in grid.items()]
    lines += ["[params]"] + [f"{k.replace('_', '-')} = {v}" for k, v in rest.items()]
    cfg.write_text("\n".join(lines) + "\n")
    r = subprocess.run([program, "sweep", str(cfg), "--check", "--quiet"], capture_output=True, text=True,
                       timeout=120)
    assert not (tmp_path / "o").exists()
    return cfg, r


@pytest.mark.parametrize("case", REFUSED, ids=_ids)
def test_refused_case_as_its_one_case_sweep(program, tmp_path, case):
    model, kw, key, by_pass = case
    grid, rest = _one_case(kw, key)
    checked = _verdict(granwave.sweep_case_check, model, **kw)
    assert checked is not None and checked[0] is granwave.GranwaveValueError, checked
    # the one-case sweep's pass, and its run, refuse it with the same text
    swept = _verdict(granwave.sweep_check, model, grid, **rest)
    assert swept == _verdict(granwave.sweep, model, grid, **rest)
    assert swept[0] is checked[0]
    if by_pass:
        assert swept == checked
    # and the program: exit 2, the library's message
    cfg, r = _program_check(program, tmp_path, model, grid, rest)
    assert r.returncode == 2 and r.stderr.count("\n") == 1, r.stderr
    if by_pass:  # (the reader's refusal names the config's line)
        prefix = f"granwave sweep: {cfg}: "
        assert r.stderr.startswith(prefix), r.stderr
        m = _sweep.sweep_models()[model]
        names = _sweep._sweep_names(model, m)
        assert swept[1] == "sweep: " + _core.keyword_text(r.stderr[len(prefix):-1], names, _core._texts(kw.values()))


@pytest.mark.parametrize("case", PASSED, ids=_ids)
def test_passed_case_as_its_one_case_sweep(program, tmp_path, case):
    model, kw, key = case[:3]
    grid, rest = _one_case(kw, key)
    assert granwave.sweep_case_check(model, **kw) is None
    assert isinstance(granwave.sweep_check(model, grid, **rest), list)
    cfg, r = _program_check(program, tmp_path, model, grid, rest)
    assert r.returncode == 0, r.stderr
    if model == "chain":  # cheap to run: the run of the sweep passes its checks too
        res = granwave.sweep(model, grid, **rest)
        assert res["ncases"] == 1


def test_k_on_one_body_only_in_every_case():
    # the refusal is of the config as a whole: a sweep whose other case has
    # two beads takes k, and its case of one body passes its pass alone
    # only where k acts somewhere
    with pytest.raises(granwave.GranwaveValueError, match=r"^sweep: k: has no effect on one body .n = 1. in any "
                                                          r"case .1 of 1 cases; the first, case 0."):
        granwave.sweep_case_check("chain", n=1, k=1e9)
    assert isinstance(granwave.sweep_check("chain", {"n": [1, 2]}, k=1e9), list)
    with pytest.raises(granwave.GranwaveValueError, match=r"in any case .2 of 2 cases; the first, case 0."):
        granwave.sweep_check("chain", {"vimp": [0.2, 0.3]}, n=1, k=1e9)


def test_sweep_check_warnings_are_the_sweeps():
    # a dt above the step the cases take: the pass's warning, as sweep() lists it
    grid, kw = {"n": [2, 3]}, {"solver": "rk4", "dt": 1e-3}
    said = granwave.sweep_check("chain", grid, **kw)
    with pytest.warns(granwave.GranwaveWarning):
        res = granwave.sweep("chain", grid, **kw)
    assert said and said == res["warnings"][:len(said)]
    assert granwave.sweep_check("chain", {"n": [2, 3]}) == []


def test_sweep_check_refuses_as_sweep():
    # the module's own refusals, before the library, are sweep()'s
    for grid, kw in (({}, {}), ({"n": []}, {}), ({"vimpp": [1]}, {}), ({"n": [1]}, {"vimpp": 1})):
        try:
            granwave.sweep("chain", grid, **kw)
        except (TypeError, granwave.GranwaveError) as e:
            ran = (type(e), str(e))
        with pytest.raises(ran[0]) as e:
            granwave.sweep_check("chain", grid, **kw)
        assert str(e.value) == ran[1]
