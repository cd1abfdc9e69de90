#!/usr/bin/python3
"""test_stdout_errors.py GRANWAVE: results that cannot reach stdout, named with their reason.

Every command that prints its results on stdout, as text and as --json, is run
with stdout

- a pipe whose read end is closed before the program starts, SIGPIPE ignored
  (as under a Python parent, or `trap '' PIPE` in a shell): the write fails
  with EPIPE;
- /dev/full (where it exists): the write fails with ENOSPC.

Each must exit 1 with exactly one stderr line "granwave[ CMD]: stdout: write
failed: REASON" naming the errno of the failed write (Broken pipe, No space
left on device). Before, --json said "Input/output error" for both: the JSON
printer flushed stdout itself, and the program's final check of stdout found
the error flag set with the errno gone. Issue 18, item 8 (a write failure said
with its real reason).

Exit 0 when every check passes, 1 otherwise; the closing line counts them.
"""
import os
import signal
import subprocess
import sys
import tempfile

GW = os.path.abspath(sys.argv[1])
SRC = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
failures = 0
checks = 0


def check(ok, what):
    global failures, checks
    checks += 1
    if ok:
        print(f"ok   {what}")
    else:
        failures += 1
        print(f"FAIL {what}")


def ignore_sigpipe():
    signal.signal(signal.SIGPIPE, signal.SIG_IGN)


def run_closed_pipe(args, cwd):
    r, w = os.pipe()
    os.close(r)  # no reader before the program writes anything: EPIPE, deterministically
    try:
        p = subprocess.run([GW] + args, stdout=w, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                           preexec_fn=ignore_sigpipe, cwd=cwd, timeout=300)
    finally:
        os.close(w)
    return p.returncode, p.stderr.decode(errors="replace")


def run_dev_full(args, cwd):
    with open("/dev/full", "wb") as full:
        p = subprocess.run([GW] + args, stdout=full, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                           cwd=cwd, timeout=300)
    return p.returncode, p.stderr.decode(errors="replace")


def expect(name, args, cwd, reason, rc, err):
    lines = [l for l in err.splitlines() if "write failed" in l]
    who = "granwave" + (f" {name}" if name else "")
    want = f"{who}: stdout: write failed: {reason}"
    check(rc == 1 and lines == [want],
          f"{' '.join(args)} > {'closed pipe' if reason == 'Broken pipe' else '/dev/full'}: exit 1, "
          f"'{want}' (exit {rc}, said {lines})")


def main():
    tmp = tempfile.mkdtemp(prefix="gw_stdout_")
    sample = os.path.join(tmp, "s20.txt")
    rc = subprocess.run([GW, "layer-make", "--n", "20", "--width-rm", "8", "--seed", "1", "--out", sample],
                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
    check(rc == 0 and os.path.isfile(sample), "layer-make of the 20-disc sample for layer-impact")
    cfg = os.path.join(tmp, "s.ini")
    with open(cfg, "w") as f:
        f.write("[sweep]\nmodel = chain\nout = out\n[grid]\nn = 2:3\n[params]\nvimp = 0.3\n")
    stats = os.path.join(SRC, "data", "measured", "layer_walls", "results.csv")
    # (command name in the message, arguments, has --json)
    cases = [
        (None, ["version"], True),
        (None, ["--help"], False),
        ("chain", ["chain", "--help"], False),
        ("chain", ["chain", "--n", "3"], True),
        ("falcon", ["falcon", "--n", "1:2", "--heights", "none", "--quiet"], True),
        ("wavespeed", ["wavespeed", "--vimp", "0.3", "--n", "5:8", "--quiet"], True),
        ("softwall", ["softwall", "--n", "1:4", "--quiet"], True),
        ("drop", ["drop", "--n", "3", "--t-max", "1e-3"], True),
        ("dispersion", ["dispersion", "--n", "16", "--t-samples", "64"], True),
        ("layer-make", ["layer-make", "--n", "12", "--width-rm", "6", "--seed", "2", "--out",
                        os.path.join(tmp, "m.txt")], True),
        ("layer-impact", ["layer-impact", "--sample", sample, "--t-max", "0.002"], True),
        ("layer-stats", ["layer-stats", stats], True),
        ("sweep", ["sweep", cfg, "--check"], False),
    ]
    have_full = os.path.exists("/dev/full") and os.access("/dev/full", os.W_OK)
    for name, args, has_json in cases:
        for a in [args] + ([args + ["--json"]] if has_json else []):
            rc, err = run_closed_pipe(a, tmp)
            expect(name, a, tmp, "Broken pipe", rc, err)
            if have_full:
                rc, err = run_dev_full(a, tmp)
                expect(name, a, tmp, "No space left on device", rc, err)
    if not have_full:
        print("skip /dev/full: not writable here")
    print(f"{checks - failures} of {checks} checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
