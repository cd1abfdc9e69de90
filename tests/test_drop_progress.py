#!/usr/bin/python3
"""test_drop_progress.py GRANWAVE: a long drop says how far it is, on stderr only.

`granwave drop --n 1000` took about 66 s of CPU with nothing said before or
during the run (issue 18). A drop now reports on stderr, through the display
of falcon, wavespeed, softwall and sweep, once it has lasted 2 s: a header
line naming the beads and the samples counted, then lines "k/n samples, R
samples/s, E s elapsed, ~L s left", the count running over the drop and the
first collision's own run (2 t_max / dt_out samples) to its total. --quiet
says nothing; stdout holds the results alone (the JSON parses, the same with
and without --quiet but for the wall time). A drop shorter than 2 s stays
silent, so a refusal or a warning is still one line.

Whether a run lasted 2 s used to depend on the machine: the runs now set the
display's delay and period through GW_PROGRESS_MS (0: the lines at once, each
tenth of the count; 1e9: none before the end, and a drop shorter than the
delay says nothing), so every check is made on any machine. The check that
lines appear fails on the program before this change (no line at all). At the
default delay (2 s), a line the default drop prints, if any, says 2 s elapsed
or more.

Exit 0 when every check passes, 1 otherwise; the closing line counts them.
"""
import json
import os
import re
import subprocess
import sys
import time

GW = os.path.abspath(sys.argv[1])
failures = 0
checks = 0
LINE = re.compile(r"^  (\d+)/(\d+) samples, [0-9.]+ samples/s, [0-9.]+ s elapsed, ~[0-9.]+ s left$")


def check(ok, what):
    global failures, checks
    checks += 1
    print(f"{'ok  ' if ok else 'FAIL'} {what}")
    if not ok:
        failures += 1


def run(args, delay_ms=None):
    """The program on args, with GW_PROGRESS_MS at delay_ms (None: unset, the default delay)."""
    env = dict(os.environ)
    env.pop("GW_PROGRESS_MS", None)
    if delay_ms is not None:
        env["GW_PROGRESS_MS"] = delay_ms
    t0 = time.monotonic()
    p = subprocess.run([GW] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                       timeout=900, env=env)
    return p.returncode, p.stdout.decode(), p.stderr.decode(), time.monotonic() - t0


def without_wall_time(text):
    o = json.loads(text)
    o.pop("wall_time_ms", None)
    return o


def main():
    long_args = ["drop", "--n", "200"]  # t-max 10 ms, dt-out 1 us: 2 x 10000 samples
    rc, out, err, wall = run(long_args + ["--json"], "0")
    lines = err.splitlines()
    check(rc == 0, f"drop --n 200 --json: exit 0 (exit {rc}, {wall:.1f} s)")
    try:
        j = without_wall_time(out)
        check(j.get("n") == 200, "its stdout is the JSON result alone (it parses, n = 200)")
    except ValueError as e:
        j = None
        check(False, f"its stdout is the JSON result alone ({e})")
    prog = [LINE.match(l) for l in lines[1:]]
    if True:  # delay 0: the lines whatever the machine's speed
        check(len(lines) >= 2 and re.match(r"^granwave drop: 200 beads, 10 ms from the first contact, then the "
                                           r"first collision again \(at most as long\): 20000 samples$", lines[0]),
              f"a header line naming the beads and the samples counted (said {lines[:1]})")
        check(len(lines) >= 2 and all(prog),
              f"then whole progress lines 'k/n samples, R samples/s, E s elapsed, ~L s left' ({len(lines) - 1})")
        done = [int(m.group(1)) for m in prog if m]
        totals = {int(m.group(2)) for m in prog if m}
        check(totals == {20000} and done and done[-1] == 20000 and all(b > a for a, b in zip(done, done[1:])),
              f"counting up to 2 t_max / dt_out = 20000, the last line at the total (done {done[:3]}..{done[-1:]})")

    rc, outq, errq, wallq = run(long_args + ["--json", "--quiet"])
    check(rc == 0 and errq == "", f"drop --n 200 --json --quiet: exit 0, nothing on stderr ({wallq:.1f} s; exit {rc}, "
                                  f"said {errq.splitlines()[:2]})")
    try:
        check(j is not None and without_wall_time(outq) == j,
              "the same JSON with and without --quiet (but the wall time): progress changes no result")
    except ValueError as e:
        check(False, f"--quiet: the JSON parses ({e})")

    # a drop shorter than the delay (the default drop, the delay 1e9 ms): silent, stdout the text result
    rc, out, err, wall = run(["drop"], "1e9")
    check(rc == 0 and err == "" and out.startswith("granwave ") and " drop: n = 1," in out.splitlines()[0],
          f"the default drop at GW_PROGRESS_MS=1e9 ({wall:.2f} s): exit 0, the text result, no line on stderr "
          f"(said {err[:200]!r})")
    # ... what the delay held back: at delay 0 the same drop prints its header and lines to its total
    rc, out, err, wall = run(["drop"], "0")
    el = err.splitlines()
    check(rc == 0 and len(el) >= 2 and el[0].startswith("granwave drop: 1 bead, ") and all(LINE.match(l) for l in el[1:])
          and LINE.match(el[-1]).group(1) == LINE.match(el[-1]).group(2),
          f"the default drop at GW_PROGRESS_MS=0: the header and whole lines to the total (said {el[:2]}..{el[-1:]})")
    # at the default delay (2 s): a line, if the machine is slow enough for one, says 2 s elapsed or more
    rc, out, err, wall = run(["drop"])
    early = [l for l in err.splitlines() if re.search(r"([0-9.]+) s elapsed", l)
             and float(re.search(r"([0-9.]+) s elapsed", l).group(1)) < 2.0]
    check(rc == 0 and not early, f"the default drop at the default delay: no line before 2 s elapsed ({early[:1]})")
    print(f"{checks - failures} of {checks} checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
