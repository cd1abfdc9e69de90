"""The twelfth hostile pass over the Python module (docs/reliability.md, "Closed
after the twelfth hostile pass: the Python module"): fork after import, Ctrl-C
in a progress callback, results against the program's --json, and what was
tried and found right (memory over many calls, re-entrant callbacks, inputs of
odd kinds) kept as checks.
"""
import os
import subprocess
import sys
import textwrap

import pytest

import granwave

ENV = dict(os.environ)


def child(code, timeout=60):
    """Run code in a fresh interpreter with the module's environment."""
    return subprocess.run([sys.executable, "-c", textwrap.dedent(code)], env=ENV, capture_output=True,
                          text=True, timeout=timeout)


# ---- fork while another thread is in the library ----

FORK = """
import granwave, os, threading, time
stop = False
def busy():
    while not stop:
        {busy}
threading.Thread(target=busy, daemon=True).start()
time.sleep(0.2)
hung = 0
for i in range({forks}):
    time.sleep(0.007 * (i % 5))
    pid = os.fork()
    if pid == 0:
        {work}
        os._exit(0)
    t0 = time.time()
    while True:
        r, st = os.waitpid(pid, os.WNOHANG)
        if r:
            assert os.waitstatus_to_exitcode(st) == 0, st
            break
        if time.time() - t0 > 4:
            hung += 1
            os.kill(pid, 9)
            os.waitpid(pid, 0)
            break
        time.sleep(0.005)
stop = True
print("hung", hung)
"""


@pytest.mark.parametrize("busy, work", [
    # the restitution calibration holds the lock around GSL's error handler
    ('granwave.chain(n=5, vimp=0.3, damping="kk", restitution=0.9)',
     'granwave.chain(n=3, vimp=0.3, damping="kk", restitution=0.9)'),
    # FFTW's planner lock (fftw_measure plans each new size for a while)
    ("granwave.dispersion(n=16, t_samples=2048 + 16 * (int(time.time() * 1e3) % 997), fftw_measure=True)",
     "granwave.dispersion(n=16, t_samples=64)"),
], ids=["calibration", "fftw"])
def test_a_child_forked_while_a_thread_is_in_the_library_runs(busy, work):
    # Before: a child forked while another thread held one of the library's
    # locks inherited it held by a thread it does not have, and waited for ever
    # at its first calibration (24 children of 40 hung) or FFT.
    r = child(FORK.format(busy=busy, work=work, forks=12), timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["hung", "0"], r.stdout + r.stderr


def test_ctrl_c_works_in_a_child_forked_during_a_call():
    # Before: a child forked by another thread while the main thread was in a
    # call kept the library's SIGINT handler for good: Ctrl-C did nothing in it.
    r = child("""
        import granwave, os, signal, threading, time
        res = {}
        def forker():
            time.sleep(0.3)
            pid = os.fork()
            if pid == 0:
                try:
                    threading.Timer(0.2, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
                    time.sleep(3)
                    os._exit(5)
                except KeyboardInterrupt:
                    os._exit(0)
            res["st"] = os.waitpid(pid, 0)[1]
        t = threading.Thread(target=forker)
        t.start()
        try:  # about 1 s of a column that has not left the wall by t_max
            granwave.chain(n=400, solver="rk4", t_max=4e-3)
        except granwave.GranwaveRunError:
            pass
        t.join()
        print("child", os.waitstatus_to_exitcode(res["st"]))
    """)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["child", "0"], r.stdout + r.stderr
