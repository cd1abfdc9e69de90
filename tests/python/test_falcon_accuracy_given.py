"""granwave.falcon's accuracy keyword as the command's --accuracy (seventeenth
hostile pass, issue #18): an accuracy given with a solver keyword is refused, as
`granwave falcon --accuracy A --solver S` is (exit 2); accuracy=1e-6 with a
damped column is refused, as --accuracy 1e-6 is. Before, solver="cvode" (its
default's value) with accuracy=1e-6 ran RK4 by the accuracy target (steps_per_tc
37), and accuracy=1e-6 with damping ran cvode silently (accuracy 0): 3 of 4
tests fail on 22cefeb. Not given, a solver keyword still runs the solver as
given, and accuracy=0 with one too."""
import os
import subprocess

import pytest

import granwave

BASE = dict(n=(2, 3), heights=[], jobs=1)
PROGRAM = os.environ.get("GRANWAVE_PROGRAM") or os.environ.get("GRANWAVE")


@pytest.mark.parametrize("solver", [dict(solver="cvode"), dict(rtol=1e-10)])
def test_accuracy_with_a_solver_keyword_refused(solver):
    with pytest.raises(granwave.GranwaveValueError, match="accuracy: give either accuracy or the solver options"):
        granwave.falcon(accuracy=1e-6, **solver, **BASE)
    if PROGRAM:  # the command refuses the same pair
        flag, value = next(iter(solver.items()))
        p = subprocess.run([PROGRAM, "falcon", "--n", "2:3", "--heights", "none", "--quiet", "--accuracy", "1e-6",
                            "--" + flag, str(value)], capture_output=True, text=True, timeout=60)
        assert p.returncode == 2 and "falcon --accuracy: give either accuracy or the solver options" in p.stderr


def test_default_accuracy_given_on_a_damped_column_refused():
    with pytest.raises(granwave.GranwaveValueError, match="accuracy: the step study covers"):
        granwave.falcon(accuracy=1e-6, damping="kk", restitution=0.9, **BASE)


def test_not_given_or_zero_runs_the_solver_as_given():
    r = granwave.falcon(solver="cvode", **BASE)
    assert r.accuracy == 0 and r.steps_per_tc == 0
    r = granwave.falcon(solver="cvode", accuracy=0, **BASE)
    assert r.accuracy == 0 and r.steps_per_tc == 0
    r = granwave.falcon(**BASE)
    assert r.accuracy == 1e-6 and r.steps_per_tc == 37
