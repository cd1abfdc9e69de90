"""Ctrl-C during a call that writes a file, and the signal handling the module
leaves to the program (issue 18).

The granwave program installs a handler for SIGINT, SIGTERM and SIGHUP that
removes its temporaries before the signal ends it (gw_temps_on_signals). The
module must not: the interpreter's signal handling is the Python program's.
It needs none for Ctrl-C either. SIGINT never ends the interpreter inside a
call (the library's handler during the call, Python's outside, only set a
flag), and the file is written through a temporary held from its open to its
rename: a call stopped before it writes writes nothing, a call that was
writing finishes the file and then raises KeyboardInterrupt.

In a child process (signals and pytest do not mix): layer_make(out=FILE) over
an earlier file, SIGINT at 10 % to 103 % of the time the same call took
uninterrupted (so some land in the pluviation, some around the write, some
after). After each: KeyboardInterrupt or a return, no temporary beside FILE,
and FILE byte for byte the earlier one or the uninterrupted call's. And the
module installs no handler at the C level: SIGTERM and SIGHUP are caught by
no one (/proc/self/status SigCgt) after import and after the calls, and
SIGINT's is Python's own.
"""
import json
import os
import signal
import subprocess
import sys
import textwrap

import pytest

CHILD = textwrap.dedent("""
    import filecmp, json, os, shutil, signal, sys, threading, time
    import granwave

    d = sys.argv[1]
    path = os.path.join(d, "s.txt")

    def caught():
        for line in open("/proc/self/status"):
            if line.startswith("SigCgt:"):
                return int(line.split()[1], 16)

    out = {"caught_import": caught()}
    args = dict(n=60, width_rm=16, seed=3, out=path)
    granwave.layer_make(n=60, width_rm=16, seed=4, out=path)  # the earlier file
    shutil.copy(path, os.path.join(d, "earlier"))
    t0 = time.monotonic()
    granwave.layer_make(**args)
    full = time.monotonic() - t0
    shutil.copy(path, os.path.join(d, "new"))
    out["runs"] = []
    for frac in (0.1, 0.5, 0.9, 0.97, 1.0, 1.03):
        shutil.copy(os.path.join(d, "earlier"), path)
        timer = threading.Timer(frac * full, lambda: os.kill(os.getpid(), signal.SIGINT))
        timer.start()
        try:
            granwave.layer_make(**args)
            raised = None
            while timer.is_alive():  # a SIGINT after the call: raised here
                time.sleep(0.01)
            time.sleep(0.05)
        except KeyboardInterrupt:
            raised = "KeyboardInterrupt"
        timer.join()
        left = sorted(f for f in os.listdir(d) if ".tmp." in f)
        same = ("earlier" if filecmp.cmp(path, os.path.join(d, "earlier"), shallow=False) else
                "new" if filecmp.cmp(path, os.path.join(d, "new"), shallow=False) else "neither")
        out["runs"].append({"frac": frac, "raised": raised, "left": left, "file": same})
    out["caught_after"] = caught()
    out["python_sigint"] = signal.getsignal(signal.SIGINT) is signal.default_int_handler
    print(json.dumps(out))
""")


@pytest.fixture(scope="module")
def child(tmp_path_factory):
    d = tmp_path_factory.mktemp("interrupt_files")
    p = subprocess.run([sys.executable, "-c", CHILD, str(d)], capture_output=True, text=True, timeout=300,
                       env=dict(os.environ))
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout.strip().splitlines()[-1])


def test_ctrl_c_while_writing(child):
    for r in child["runs"]:
        assert r["raised"] == "KeyboardInterrupt", r
        assert r["left"] == [], r
        assert r["file"] in ("earlier", "new"), r
    # the early SIGINTs stopped the call before it wrote: the earlier file
    assert child["runs"][0]["file"] == "earlier", child
    assert child["python_sigint"]


@pytest.mark.parametrize("when", ["caught_import", "caught_after"])
def test_no_handler_behind_pythons_back(child, when):
    mask = child[when]
    for sig in (signal.SIGTERM, signal.SIGHUP):  # bit n - 1 for signal n
        assert not mask >> (sig - 1) & 1, f"{sig.name} caught ({mask:x}) at {when}"
