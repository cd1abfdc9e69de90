"""The Python side of the seventh hostile pass over the layer (issue 18).

granwave.sweep runs its cases on `jobs` threads of one process: their memory adds
up. The library sums the `jobs` largest estimates before any case runs and
refuses (GranwaveValueError naming jobs and the most that fit) when they pass
80 % of what the process may use; each test runs in a child process under an
address-space limit (resource.RLIMIT_AS, as `ulimit -v`) so that the memory is
known whatever the machine.
"""
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
SAMPLE = REPO / "data" / "measured" / "restitution_full" / "sample.txt"


def _under_limit(code, limit_kb):
    """Run code in a child Python under RLIMIT_AS = limit_kb KiB; return it."""
    pre = ("import resource\n"
           f"resource.setrlimit(resource.RLIMIT_AS, ({limit_kb} * 1024, {limit_kb} * 1024))\n")
    return subprocess.run([sys.executable, "-c", pre + code], capture_output=True, text=True, timeout=120,
                          env=dict(os.environ))


SWEEP = ("import granwave\n"
         "try:\n"
         "    granwave.sweep('layer', {{'vi': [10, 20, 30, 40]}}, jobs={jobs}, sample={sample!r}, rings=1000,\n"
         "                   t_max={t_max}, dt_out=4e-6)\n"
         "    print('ran')\n"
         "except granwave.GranwaveValueError as e:\n"
         "    print('refused:', e)\n")


def test_sweep_jobs_memory_is_bounded():
    # four cases of about 0.498 GB each (1.5 x 0.321 GB of series + 16 MB)
    r = _under_limit(SWEEP.format(jobs=4, sample=str(SAMPLE), t_max=0.04), 1700000)
    if "cannot allocate" in r.stderr or "AddressSanitizer" in r.stderr:
        pytest.skip("this interpreter cannot run under a 1.7 GB address-space limit")
    assert r.stdout.strip() == ("refused: sweep: jobs: 4 cases at once need about 1.99 GB (the largest, case 0, "
                                "0.498 GB), above 80 % of the 1.74 GB available (ulimit -v): at most 2 jobs"), r.stderr


def test_sweep_jobs_that_fit_run():
    # the same grid with short cases (t-max 2e-4 s: about 18 MB each) runs on 4 jobs
    r = _under_limit(SWEEP.format(jobs=4, sample=str(SAMPLE), t_max=2e-4), 1700000)
    assert r.stdout.strip() == "ran", r.stderr


@pytest.mark.parametrize("jobs, exc, text", [
    (1.5, TypeError, "jobs must be an integer, not float"),    # ran 1 thread
    (True, TypeError, "jobs must be an integer, not bool"),
    ("2", TypeError, "jobs must be an integer, not str"),
    (-1, ValueError, r"jobs: -1 is outside \[0, 4096\]"),       # ran one per CPU
    (5000, ValueError, r"jobs: 5000 is outside \[0, 4096\]"),   # the command's --jobs stops at 4096
    (10**12, ValueError, r"jobs: 1000000000000 is outside"),   # wrapped to a negative C int
])
def test_sweep_jobs_keyword(jobs, exc, text):
    import granwave
    with pytest.raises(exc, match=text):
        granwave.sweep("layer", {"vi": [10, 20]}, jobs=jobs, sample=SAMPLE, t_max=1e-4, skin=1e-3)


def test_sweep_flag_spellings_are_one_value():
    import granwave
    # True and np.bool_(True) are one value: the same case twice (1 and True
    # were, before a flag took bools only)
    with pytest.raises(granwave.GranwaveValueError, match="exact: .* are the same value"):
        granwave.sweep("layer", {"exact": [np.bool_(True), True]}, sample=SAMPLE, t_max=1e-4, skin=1e-3)
    r = granwave.sweep("layer", {"exact": [False, True]}, jobs=2, sample=SAMPLE, t_max=1e-4, skin=1e-3)
    assert len(r["t_end"]) == 2


def test_sweep_long_grid_lists():
    import granwave
    # point = range(100), the paper's 100 points, went into the config as a
    # 390-character list that the INI reader cut (refused as '5' listed twice);
    # consecutive integers now go as the range 0:99
    r = granwave.sweep("layer", {"point": range(100)}, jobs=2, sample=SAMPLE, points=100, spacing=1e-3,
                       t_max=1e-5, skin=1e-3)
    assert list(r["point"]) == list(range(100)) and len(r["t_end"]) == 100
    # a long list that is no range goes on over several config lines (it was
    # refused: one line holds at most 198 characters); every value runs
    vi = [10 + 0.001 * k for k in range(40)]
    r = granwave.sweep("layer", {"vi": vi}, jobs=2, sample=SAMPLE, t_max=1e-5, skin=1e-3)
    assert list(r["vi"]) == vi and len(r["t_end"]) == 40
    # a ',' inside one grid value ran it as two cases
    with pytest.raises(ValueError, match="sample: a grid value holds ','"):
        granwave.sweep("layer", {"sample": [str(SAMPLE) + ",x"]}, t_max=1e-5)
