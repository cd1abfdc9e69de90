"""The module from several Python threads at once (ctypes releases the GIL, so
the library's calls really run concurrently): every result equals the same
call made alone, and the interpreter survives.

Before the tenth pass the column's wall spectrum and the dispersion study
planned their FFTs without the lock gw_xcorr held, and FFTW's planner is not
thread-safe: four threads calling granwave.dispersion (fftw_measure=True)
killed the interpreter in 3 runs of 3 ("corrupted size vs. prev_size", "double
free or corruption", SIGSEGV). The child process below is that call; a crash
shows as a negative return code.
"""
import os
import subprocess
import sys
import textwrap
import threading

import numpy as np

import granwave

CHILD = textwrap.dedent("""
    import threading, numpy as np, granwave
    got = {}
    def work(k):
        for i in range(10):  # a new size each call: the planner works every time
            if k % 2:
                got[(k, i)] = granwave.dispersion(n=64 + 8 * i + 4 * (k // 2), f0=10, fftw_measure=True).power
            else:
                got[(k, i)] = granwave.dispersion(column_n=3 + i + 16 * (k // 2), fftw_measure=True).spectrum
    ts = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in ts: t.start()
    for t in ts: t.join()
    bad = 0
    for (k, i), r in got.items():  # the same call alone (plans may differ: rounding only)
        if k % 2:
            a = granwave.dispersion(n=64 + 8 * i + 4 * (k // 2), f0=10).power
        else:
            a = granwave.dispersion(column_n=3 + i + 16 * (k // 2)).spectrum
        bad += not np.allclose(r, a, rtol=1e-9, atol=1e-12 * np.abs(a).max())
    print("calls", len(got), "bad", bad)
""")


def test_fft_studies_from_four_threads_at_once():
    p = subprocess.run([sys.executable, "-c", CHILD], capture_output=True, text=True, timeout=300,
                       env=dict(os.environ))
    assert p.returncode == 0, f"child died ({p.returncode}): {p.stderr[-500:]}"
    assert p.stdout.strip() == "calls 40 bad 0"
    assert p.stderr == ""  # the library prints nothing


def test_restitution_calibration_from_threads_equals_alone():
    # the calibration's Brent iteration turns GSL's process-wide error handler
    # off for its section: sections on several threads are serialised
    kws = [dict(n=3, damping="kk", restitution=e) for e in (0.5, 0.7, 0.9)] + \
          [dict(n=2, damping="hc", restitution=e) for e in (0.6, 0.8)]
    ref = [granwave.chain(**kw).eps_eff for kw in kws]
    out = {}
    errs = []

    def work(k):
        try:
            for j in range(3):
                out[(k, j)] = granwave.chain(**kws[(k + j) % len(kws)]).eps_eff
        except Exception as e:  # noqa: BLE001 - reported below
            errs.append(e)
    ts = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    assert not errs
    for (k, j), v in out.items():
        assert v == ref[(k + j) % len(kws)]
