"""Fixtures of the Python tests (run by ctest as test_python, label python).

ctest sets GRANWAVE_LIB (the build's libgranwave), PYTHONPATH (python/) and
GRANWAVE_PROGRAM (the build's granwave program, for comparisons with the CLI)
and GRANWAVE_VERSION (the project version). Run by hand from the repository:
    GRANWAVE_LIB=build/lib/libgranwave.so GRANWAVE_PROGRAM=build/granwave \
    PYTHONPATH=python /usr/bin/python3 -m pytest -q tests/python
"""
import json
import math
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


# The columns of a layer sweep's results.csv after case,rb-rm,height-rm,point.
SWEEP_COLS = ("x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,penetration_rm,dissipated_first_contact,"
              "block_loss_first_contact,energy_error,wave_speed,t_end,steps")


def write_synthetic_sweep(path, penetration=True):
    """Write a synthetic layer sweep table to path and return path: bounce iff
    H < B.31(R_b/R_m) with beta 1, a/b 4, offset 1, gamma 0.2 deg, 6 R_b/R_m x
    7 heights x 4 points, point 0 bouncing 0.3 R_m higher (so the boundary is
    crossed within cells). Without a penetration (NaN) the B.31 offset has no
    measured source (test_stats.py, test_sequence_bounds.py)."""
    T = math.tan(math.radians(0.2))

    def b31(x):
        u = x - 1.0
        return 1.0 + (math.sqrt(u * u + 4.0 * T * x * x) - u) / (2 * T)

    lines = ["# synthetic layer sweep", "# param vi = 20", "case,rb-rm,height-rm,point," + SWEEP_COLS]
    case = 0
    for x in (0.5, 1.5, 2, 3, 4, 6):
        for h in (3, 6, 9, 12, 15, 18, 21):
            for p in range(4):
                b = 1 if h < b31(x) + (0.3 if p == 0 else 0) else 0
                e = 0.3 + 0.01 * p + 0.02 * x
                pen = 0.4 + 0.01 * h if penetration else "nan"
                lines.append(f"{case},{x},{h},{p},{0.05 * p},{b},{e if b else 'nan'},{e if b else 'nan'},"
                             f"{10 + p if b else 'nan'},20,{8 * e},{20 * e},0.1,{pen},0.001,"
                             f"{0.5 + 0.01 * p},1e-6,nan,0.01,100")
                case += 1
    Path(path).write_text("\n".join(lines) + "\n")
    return path
