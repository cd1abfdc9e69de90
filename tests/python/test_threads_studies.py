"""Every public study of the module from a ThreadPoolExecutor at once gives, bit
for bit, what the same call gives alone (ctypes releases the GIL, so the
library's calls really run concurrently): different calls at once, and the
same call on four threads at once. The C side of the same contract is
tests/test_threads.c.
"""
import math
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import granwave


def _timing(key):
    return "_ms" in key or "wall_time" in key  # run times (wall_time_ms, integrate_ms, ...)


def _same(a, b):
    """Equal to the last bit (NaN equal to NaN), recursively over a Result; run times aside."""
    if isinstance(a, dict):
        return isinstance(b, dict) and a.keys() == b.keys() and all(_same(a[k], b[k]) for k in a if not _timing(k))
    if isinstance(a, np.ndarray):
        return (isinstance(b, np.ndarray) and a.shape == b.shape and a.dtype == b.dtype
                and a.tobytes() == b.tobytes())
    if isinstance(a, (list, tuple)):
        return type(a) is type(b) and len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    if isinstance(a, float) and isinstance(b, float):
        return (math.isnan(a) and math.isnan(b)) or np.float64(a).tobytes() == np.float64(b).tobytes()
    return a == b


def _call(case):
    fn, kw = case
    try:
        return getattr(granwave, fn)(**kw)
    except granwave.GranwaveError as e:  # a refusal is a result too: its text and status
        return ("error", type(e).__name__, str(e), e.status)


@pytest.fixture(scope="module")
def cases(sample, tmp_path_factory):
    h5 = tmp_path_factory.mktemp("threads") / "s.h5"
    granwave.layer_make(n=60, width_rm=16, seed=4, out=h5)
    table = tmp_path_factory.mktemp("threads") / "t.csv"
    table.write_text(
        "# granwave 0.1.0 sweep, model layer\n# param vi = 12.5\n"
        "case,rb-rm,height-rm,point,x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,penetration_rm,"
        "dissipated_first_contact,block_loss_first_contact,energy_error,wave_speed,t_end,steps\n"
        "0,2,5,2,0.05,1,0.3,0.4,20,1,1,1,0.3,3,0.1,0.5,1e-7,0,0,0\n"
        "1,2,5,0,-0.15,1,0.1,0.2,10,1,1,1,0.1,1,0.2,0.7,3e-7,0,0,0\n"
        "2,2,5,3,0.15,1,0.5,0.6,60,1,1,1,0.6,6,0.3,0.6,2e-7,0,0,0\n"
        "3,2,5,1,-0.05,0,0.8,0.9,80,1,1,1,0.2,2,0.4,0.6,nan,0,0,0\n")
    return [
        ("chain", dict(n=5, vimp=0.3)),
        ("chain", dict(n=3, damping="kk", restitution=0.75)),
        ("chain", dict(n=2, damping="hc", restitution=0.65)),
        ("chain", dict(n=3, sheet="brass", sheet_law="layer", trace=True)),
        ("falcon", dict(n=(1, 3), vimp=0.3, heights=[])),
        ("wavespeed", dict(n=(6, 8), vimp=[0.1, 0.3], jobs=2)),
        ("softwall", dict(n=(1, 3), vimp=0.3, solver="rk4", jobs=2)),
        ("dispersion", dict(n=32, f0=10)),
        ("dispersion", dict(column_n=4)),
        ("drop", dict(n=3, t_max=0.004)),
        ("layer_make", dict(n=12, width_rm=6, seed=2, t_max=0.1)),
        ("layer_impact", dict(sample=sample, t_max=0.003)),
        ("layer_impact", dict(sample=h5, t_max=0.003, rings=2)),
        ("layer_impact", dict(sample=sample, exact=True, t_max=0.0005)),
        ("layer_stats", dict(input=table)),
        ("sweep", dict(model="chain", grid={"n": [2, 3], "vimp": [0.1, 0.3]}, jobs=2,
                       damping="kk", restitution=0.85)),
        ("chain", dict(n=3, vimp=2000)),  # refused
    ]


def test_different_studies_at_once_equal_alone(cases):
    # at once first (the calibration memo empty for restitution 0.75, 0.65, 0.85), then alone
    order = [cases[(i * 7) % len(cases)] for i in range(len(cases))] * 3
    with ThreadPoolExecutor(max_workers=4) as pool:
        got = list(pool.map(_call, order))
    alone = {id(c): _call(c) for c in cases}
    bad = [(c[0], c[1]) for c, r in zip(order, got) if not _same(r, alone[id(c)])]
    assert bad == []
    assert alone[id(cases[-1])][0] == "error"  # the refusal is one


def test_same_call_on_four_threads_equals_alone(cases):
    for case in cases:
        with ThreadPoolExecutor(max_workers=4) as pool:
            got = list(pool.map(_call, [case] * 4))
        ref = _call(case)
        assert all(_same(r, ref) for r in got), case[0]


CHILD = """
import sys, warnings
from concurrent.futures import ThreadPoolExecutor
import granwave
warnings.simplefilter("ignore", granwave.GranwaveWarning)  # a flip that spoils nothing runs and may warn
def impact(path):
    try:
        granwave.layer_impact(sample=path, t_max=0.001)
    except granwave.GranwaveError as e:
        return str(e)
with ThreadPoolExecutor(max_workers=2) as pool:
    print(len([m for m in pool.map(impact, sys.argv[1:]) if m and "HDF5" in m]))
"""


def test_corrupt_hdf5_sample_read_on_threads_prints_nothing_at_exit(tmp_path):
    # HDF5's error printing is per thread: a corrupt sample read on a worker
    # thread left the main thread's on, and HDF5 printed "HDF5: infinite loop
    # closing library" and a line of "FL,FL,..." when the interpreter exited
    import os
    import subprocess
    import sys
    good = tmp_path / "s.h5"
    granwave.layer_make(n=40, width_rm=14, seed=4, out=good)
    data = good.read_bytes()
    bad = []
    for off in range(97, 1200, 97):
        b = bytearray(data)
        b[off] ^= 1
        p = tmp_path / f"bad{off}.h5"
        p.write_bytes(bytes(b))
        bad.append(str(p))
    r = subprocess.run([sys.executable, "-c", CHILD, *bad], capture_output=True, text=True, timeout=300,
                       env=dict(os.environ))
    assert r.returncode == 0, r.stderr[-500:]
    assert int(r.stdout) >= len(bad) // 2  # most refused, naming HDF5 (10 of 12 measured)
    assert r.stderr == ""
