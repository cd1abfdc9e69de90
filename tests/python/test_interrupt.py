"""Ctrl-C during a long call.

ctypes runs a library call with the interpreter released, and Python acts on
SIGINT only once the call has returned: before, `granwave.chain(n=20000,
solver="rk4")` went on for more than 5 minutes after Ctrl-C (killed by a
timeout), and layer_make(n=300) and dispersion(n=4096) raised KeyboardInterrupt
only when they had finished, 9 and 11 s later. Now a call from the main thread
installs the library's SIGINT handler (gw_interrupt_begin), every solver step
checks the request, and the signal goes to Python's own handler as soon as the
call returns (KeyboardInterrupt by default; a handler of the program's runs
instead; a SIGINT the program ignores stays ignored).

Each case runs in a child process (signals and pytest do not mix): a thread
sends SIGINT once a call that takes more than 25 s uninterrupted has used 0.5 s
of CPU (measured: the calls below did not finish in 25 s), and the child reports
what was raised and after how much CPU, whether the same short run gives the same result before and
after (the request is cleared), and whether Python's own Ctrl-C handling is back
(SIGINT during time.sleep raises KeyboardInterrupt at once).
"""
import json
import os
import subprocess
import sys
import textwrap

import pytest

# what both child scripts begin with: the module, and SIGINT sent to the
# process at once (fire) or once a call has used 0.5 s of CPU (fire_in_call)
PRELUDE = textwrap.dedent("""
    import json, os, signal, sys, threading, time
    import granwave

    def fire():
        os.kill(os.getpid(), signal.SIGINT)

    def fire_in_call(cpu0):
        # once the call has used 0.5 s of CPU (process time, every thread): in
        # the call whatever the load, where a timer of 0.5 s of the clock could
        # fire before it began
        while time.process_time() < cpu0 + 0.5:
            time.sleep(0.01)
        fire()
""")

CHILD = PRELUDE + textwrap.dedent("""
    # called, not eval'd: a KeyboardInterrupt out of eval() makes CPython
    # end the process with SIGINT at exit, even when it was caught
    calls = {
        "chain-rk4": lambda: granwave.chain(n=1400, solver="rk4"),  # the fixed-step loop
        "chain-cvode": lambda: granwave.chain(n=1400, solver="cvode"),  # through CVODE's rhs
        "layer-make": lambda: granwave.layer_make(n=1000),  # the layer's verlet steps
        "sweep": lambda: granwave.sweep(model="chain", grid={"n": [1400, 1401]}, jobs=2,
                                        solver="arkode"),  # two worker threads, ARKode
    }

    before = granwave.chain(n=3, solver="cvode")["f_max"]
    t0 = time.process_time()
    threading.Thread(target=fire_in_call, args=(t0,), daemon=True).start()
    out = {}
    try:
        calls[sys.argv[1]]()
        out["raised"] = None
    except KeyboardInterrupt:
        out["raised"] = "KeyboardInterrupt"
    except BaseException as e:
        out["raised"] = type(e).__name__ + ": " + str(e)
    out["elapsed"] = time.process_time() - t0
    out["same_after"] = granwave.chain(n=3, solver="cvode")["f_max"] == before
    t1 = time.monotonic()
    try:
        # (the timer started in the try: a SIGINT before the sleep began is
        # Python's KeyboardInterrupt too, caught here)
        threading.Timer(0.2, fire).start()
        time.sleep(600)
        out["sleep"] = "not interrupted"
    except KeyboardInterrupt:
        out["sleep"] = "KeyboardInterrupt"
    out["sleep_elapsed"] = time.monotonic() - t1
    print(json.dumps(out))
""")

# each takes more than 25 s uninterrupted (measured: none finished in 25 s)
CALLS = ["chain-rk4", "chain-cvode", "layer-make", "sweep"]


@pytest.mark.parametrize("call", CALLS)
def test_ctrl_c_stops_the_call(call):
    p = subprocess.run([sys.executable, "-c", CHILD, call], capture_output=True, text=True, timeout=120,
                       env=dict(os.environ))
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout.strip().splitlines()[-1])
    assert out["raised"] == "KeyboardInterrupt", out
    # SIGINT at 0.5 s of the call's CPU; the steps check it every step: back
    # within a few seconds of CPU (the clock's on a loaded machine ran longer),
    # where the call takes more than 25 s uninterrupted
    assert out["elapsed"] < 6.0, out
    assert out["same_after"], out
    # a sleep of 600 s: interrupted, not ended (60 s: a guard, not a measure)
    assert out["sleep"] == "KeyboardInterrupt" and out["sleep_elapsed"] < 60.0, out


HANDLERS = PRELUDE + textwrap.dedent("""
    out = {}
    # a handler of the program's own: it runs (once), no KeyboardInterrupt, and
    # the stopped call fails with status -9
    got = []
    signal.signal(signal.SIGINT, lambda s, f: got.append(s))
    t0 = time.process_time()
    threading.Thread(target=fire_in_call, args=(t0,), daemon=True).start()
    try:
        granwave.chain(n=1400, solver="rk4")
        out["custom"] = "returned"
    except granwave.GranwaveError as e:
        out["custom"] = "status %d: %s" % (e.status, e)
    out["custom_elapsed"] = time.process_time() - t0
    out["custom_calls"] = len(got)
    # SIGINT ignored by the program: ignored during the call too (the run goes on)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    threading.Timer(0.1, fire).start()
    t0 = time.monotonic()
    r = granwave.layer_make(n=60, width_rm=16, seed=3)
    out["ignored_elapsed"] = time.monotonic() - t0
    out["ignored_settled"] = r["t_settle"]
    print(json.dumps(out))
""")


def test_the_programs_own_sigint_handling():
    p = subprocess.run([sys.executable, "-c", HANDLERS], capture_output=True, text=True, timeout=120,
                       env=dict(os.environ))
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout.strip().splitlines()[-1])
    assert out["custom"].startswith("status -9") and "interrupted" in out["custom"], out
    assert out["custom_elapsed"] < 6.0 and out["custom_calls"] == 1, out
    # the 60-disc pluviation (1.2 s) runs to its end with SIGINT, sent 0.1 s in, ignored
    assert out["ignored_elapsed"] > 0.15 and out["ignored_settled"] > 0.5, out
