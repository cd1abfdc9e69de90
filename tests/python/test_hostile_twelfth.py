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
        if time.time() - t0 > 60:  # a guard: 4 s could end a busy child under load
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
    r = child(FORK.format(busy=busy, work=work, forks=12), timeout=900)  # a guard (85 s seen under load)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["hung", "0"], r.stdout + r.stderr


def test_ctrl_c_works_in_a_child_forked_during_a_call():
    # Before: a child forked by another thread while the main thread was in a
    # call kept the library's SIGINT handler for good: Ctrl-C did nothing in it.
    # The fork comes once the call has used 0.2 s of CPU (of about 1 s), not
    # after 0.3 s of wall time: on an idle machine the call could have ended
    # by then (the child then tested nothing); the child says it came in the call.
    r = child("""
        import granwave, os, signal, threading, time
        res = {"in_call": True}
        def forker():
            c0 = time.process_time()
            while time.process_time() - c0 < 0.2 and res["in_call"]:
                time.sleep(0.005)
            pid = os.fork()
            in_call = res["in_call"]  # still in it after the fork: in it during the fork
            if pid == 0:
                try:
                    threading.Timer(0.2, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
                    time.sleep(600)  # (3 s could end before the timer on a loaded machine)
                    os._exit(5)
                except KeyboardInterrupt:
                    os._exit(0)
            res["st"] = os.waitpid(pid, 0)[1]
            res["forked_in_call"] = in_call
        t = threading.Thread(target=forker)
        t.start()
        try:  # about 1 s of a column that has not left the wall by t_max
            granwave.chain(n=400, solver="rk4", t_max=4e-3)
        except granwave.GranwaveRunError:
            pass
        res["in_call"] = False
        t.join()
        print("child", os.waitstatus_to_exitcode(res["st"]), "forked_in_call", res["forked_in_call"])
    """)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["child", "0", "forked_in_call", "True"], r.stdout + r.stderr


# ---- Ctrl-C while a progress callback runs on the main thread ----

CALLBACK = """
import granwave, os, signal, threading, time
def fire():
    os.kill(os.getpid(), signal.SIGINT)
state = {"calls": 0, "flag": False}
def slow(done, total):  # a callback that takes its time: plotting, saving, waiting
    state["calls"] += 1
    if state["calls"] == 1:
        # SIGINT sent from within the first call (a timer started before the
        # call could fire before the call began on a loaded machine)
        threading.Timer(0.5, fire).start()
        t0 = time.monotonic()
        while time.monotonic() - t0 < 600 and not state["flag"]:
            time.sleep(0.01)
    return state["flag"]
calls = {
    "drop": lambda: granwave.drop(n=2, height=1e-4, t_max=1e-3, progress=slow),
    "layer_make": lambda: granwave.layer_make(n=10, width_rm=8, seed=1, progress=slow),
}
if "{handler}" == "own":  # the program's own handler: sets a flag the callback reads
    signal.signal(signal.SIGINT, lambda s, f: state.update(flag=True))
t0 = time.monotonic()
try:
    r = calls["{call}"]()
    what = "returned"
except KeyboardInterrupt:
    what = "KeyboardInterrupt"
except granwave.GranwaveError as e:
    what = "status%d" % e.status
except BaseException as e:
    what = type(e).__name__
print(what, round(time.monotonic() - t0, 2), state["calls"])
"""


@pytest.mark.parametrize("call", ["drop", "layer_make"])
def test_ctrl_c_during_a_progress_callback_acts_at_once(call):
    # Before: the library's SIGINT handler stayed in place while the callback's
    # Python ran, so Ctrl-C 0.5 s into a 20 s callback raised KeyboardInterrupt
    # only once the callback had returned (20 s). The callback waits 600 s
    # now: 60 s is a guard, not a measure (5 s of the clock could pass under load)
    r = child(CALLBACK.replace("{call}", call).replace("{handler}", "default"), timeout=300)
    assert r.returncode == 0, r.stderr
    what, elapsed, ncalls = r.stdout.split()
    assert what == "KeyboardInterrupt" and float(elapsed) < 60 and ncalls == "1", r.stdout


def test_the_programs_own_handler_runs_during_a_callback():
    # a handler of the program's runs while the callback does (it sets a flag the
    # callback returns: the call stops, as any callback's True stops it: status -9)
    r = child(CALLBACK.replace("{call}", "drop").replace("{handler}", "own"), timeout=300)
    assert r.returncode == 0, r.stderr
    what, elapsed, ncalls = r.stdout.split()
    assert what == "status-9" and float(elapsed) < 60 and ncalls == "1", r.stdout


# ---- inputs of odd kinds ----

def test_a_0d_array_is_refused_naming_the_keyword():
    # before: "chain: iteration over a 0-d array" and, in a grid, "iteration
    # over a 0-d array" with no key named
    import numpy as np
    with pytest.raises(TypeError, match=r"^chain: radii: expected a 1-D sequence of numbers, got an array of shape \(\)"):
        granwave.chain(n=1, radii=np.array(0.004))
    with pytest.raises(TypeError, match=r"^sweep\(\) grid: 'n': expected a list"):
        granwave.sweep("chain", grid={"n": np.array(3)})


def test_sweep_keys_of_the_wrong_kind_or_spelled_twice():
    # before: AttributeError ('int' object has no attribute 'replace'), and
    # "sweep: sweep:5: duplicate key 't-max'" naming a line of a text never shown
    with pytest.raises(TypeError, match=r"^sweep\(\) grid: a key is a keyword name \(str\), got int \(3\)"):
        granwave.sweep("chain", grid={3: [1]})
    with pytest.raises(TypeError, match=r"^sweep\(\): 't_max' and 't-max' name the same parameter"):
        granwave.sweep("chain", grid={"t_max": [1e-3], "t-max": [2e-3]})
    with pytest.raises(TypeError, match=r"^sweep\(\): 't_max' and 't-max' name the same parameter"):
        granwave.sweep("chain", grid={"t_max": [1e-3]}, **{"t-max": 2e-3})
    assert list(granwave.sweep("chain", grid={"n": [1, 2]}, t_max=None).n) == [1, 2]


def test_numpy_inputs_of_any_layout_give_the_same_run():
    import numpy as np
    radii = [0.004, 0.003, 0.002]
    base = granwave.chain(n=3, radii=radii).f_max
    ro = np.array(radii)
    ro.flags.writeable = False
    for a in (np.array(radii, dtype=">f8"), np.array([0.004, 9, 0.003, 9, 0.002])[::2], ro,
              np.array(radii, dtype=np.longdouble), (x for x in radii)):
        assert granwave.chain(n=3, radii=a).f_max == base


# ---- memory over many calls ----

def _rss_mb():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 1e6


def test_memory_stays_flat_over_many_calls_failing_or_stopped():
    # 1000 calls each of runs that fail in C, values refused, and callbacks that
    # raise (falcon and sweep from worker threads, layer_make from this one):
    # measured flat to 0.1 MB; a leak of one outcome (kB) per call would show
    import gc

    def boom(done, total):
        raise ValueError("stop")
    calls = [lambda: granwave.chain(n=3, vimp=0.3, max_steps=5),
             lambda: granwave.chain(n=-1),
             lambda: granwave.falcon(n=(1, 3), vimp=[0.3], heights=[], solver="rk4", progress=boom),
             lambda: granwave.sweep("chain", grid={"n": [1, 2]}, solver="rk4", jobs=1, progress=boom),
             lambda: granwave.layer_make(n=10, width_rm=8, seed=1, progress=boom),
             lambda: granwave.chain(n=3, vimp=0.3, solver="rk4", trace=True)]

    def loop(n):
        for _ in range(n):
            for c in calls:
                try:
                    c()
                except (ValueError, granwave.GranwaveError):
                    pass
        gc.collect()
    loop(50)
    before = _rss_mb()
    loop(1000)
    assert _rss_mb() - before < 3.0


# ---- the import with a library that is not granwave's ----

@pytest.mark.parametrize("make, text", [
    # before: OSError "...: file too short", naming neither granwave nor GRANWAVE_LIB
    (lambda d: (d / "bad.so").write_text("not a library") and d / "bad.so", r"GRANWAVE_LIB=.*bad\.so cannot be loaded"),
    # before: AttributeError "...: undefined symbol: gw_version"
    (lambda d: next(p for p in ("/lib/x86_64-linux-gnu/libm.so.6", "/usr/lib/x86_64-linux-gnu/libm.so.6",
                                "/lib64/libm.so.6") if os.path.exists(p)),
     r"libm\.so\.6 is not a libgranwave this module can use \(it has no gw_version\)"),
], ids=["not-a-library", "another-library"])
def test_a_library_that_is_not_granwaves_fails_the_import_clearly(tmp_path, make, text):
    import re
    lib = make(tmp_path)
    env = dict(ENV, GRANWAVE_LIB=str(lib))
    p = subprocess.run([sys.executable, "-c", "import granwave"], env=env, capture_output=True, text=True)
    last = p.stderr.strip().splitlines()[-1]
    assert p.returncode != 0 and last.startswith("ImportError: granwave: ") and re.search(text, last), p.stderr


def test_every_progress_keyword_is_documented():
    # help(granwave.layer_impact) said nothing of its progress keyword
    import inspect
    for name in granwave.__all__:
        fn = getattr(granwave, name)
        if callable(fn) and not isinstance(fn, type) and "progress" in inspect.signature(fn).parameters:
            assert "progress: " in fn.__doc__, name
