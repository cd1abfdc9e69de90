"""Fixtures of the Python tests (run by ctest as test_python, label python).

ctest sets GRANWAVE_LIB (the build's libgranwave), PYTHONPATH (python/) and
GRANWAVE_PROGRAM (the build's granwave program, for comparisons with the CLI)
and GRANWAVE_VERSION (the project version). Run by hand from the repository:
    GRANWAVE_LIB=build/lib/libgranwave.so GRANWAVE_PROGRAM=build/granwave \
    PYTHONPATH=python /usr/bin/python3 -m pytest -q tests/python
"""
import json
import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def program():
    p = os.environ.get("GRANWAVE_PROGRAM") or str(REPO / "build" / "granwave")
    if not Path(p).exists():
        pytest.skip(f"no granwave program at {p}")
    return p


def run_cli(program, *args):
    """Run the program, return its --json output parsed."""
    out = subprocess.run([program, *map(str, args), "--json"], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


@pytest.fixture(scope="session")
def sample(program, tmp_path_factory):
    """A small pluviated sample (60 discs, 16 R_m wide, seed 4: the sample of
    test_layer_cli.sh), made once by `granwave layer-make` (about 1.5 s)."""
    path = tmp_path_factory.mktemp("layer") / "a.txt"
    subprocess.run([program, "layer-make", "--n", "60", "--width-rm", "16", "--seed", "4", "--out", str(path)],
                   check=True, capture_output=True)
    return path
