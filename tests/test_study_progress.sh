#!/bin/bash
# test_study_progress.sh GRANWAVE SRCDIR: the studies on many collisions
# (falcon, wavespeed, softwall) report their progress within the collisions,
# by the clock (issue 18). A falcon study printed its first line after a tenth
# of its collisions (33.7 s into `falcon --n 1:100` on a sensor body),
# wavespeed likewise, softwall after each wall: a study of a few long
# collisions said nothing for minutes.
#  - long studies (columns of 300 and 400 beads, several seconds each; falcon
#    and wavespeed on 2 and 3 threads): a header line, then whole lines
#    "  k/n collisions, P% of the work, E s elapsed, ~L s left", the first
#    within 6 s of the start (stamped here as each line arrives on the pipe)
#    and before any collision has ended (k = 0, P > 0), the next ones at most
#    4.5 s apart (due every 2 s), P and k never decreasing, n the study's
#    collisions (wavespeed's front columns and softwall's 20 rigid-wall ones
#    counted); nothing else on stderr. Each is stopped once it has printed
#    three lines (12 s without them is a failure);
#  - a sweep of two such columns (chain, n = 400, 401, 2 threads): after its
#    header, lines "sweep: 0/2 cases, J under way, P% of the work, E s
#    elapsed, ~L s left" within 6 s and at most 4.5 s apart, where it said
#    nothing until a case ended; P > 0 and rising while no case has ended
#    (the cases seen inside: before, "0/2 cases, 2 under way" and no P);
#  - a layer sweep of two exact impacts on a 40-disc pile at 20 and 21 m/s,
#    rk4, one thread, to T_f = 0.31 s: a line "sweep: 0/2 cases, 1 under
#    way, P% ..." with P > 0 inside the first case, and one with P above 10 %
#    (a case's part its simulated time over the end its block's flight
#    gives: over t-max, P stayed under 7.7 % until a case ended), a line at
#    100 % at the end, exit 0, and the table of its --quiet twin (results bit
#    for bit). On the clock shim (20 s a read: the ticker's every read, each
#    100 ms, is a line) the cases are rk4 at 2e-6 s, about 1 s each; without
#    it at 4e-7 s, about 5 s each on an idle machine, for the wall's 2 s
#    between lines (up to a minute under load before session 44, when it
#    waited on the wall's clock with the shim too);
#  - layer-make --n 300 (16 s on a loaded machine) in a pipe: its line
#    within 6 s, where it spoke on a terminal only;
#  - --quiet: nothing on stderr over the same time;
#  - a study (falcon --n 140:141) with the display's delay and period at 0
#    (GW_PROGRESS_MS=0, whatever the machine's speed) prints a line before
#    its last, the last "n/n collisions, 100.0% of the work", and its stdout
#    --json parses;
#  - short studies with the delay at 1e9 ms (shorter than the delay, on any
#    machine): the header and the last line only, stdout's JSON that of
#    --quiet but for the wall time, and nothing with --quiet.
# About 30 s (the three long studies at once, the layer sweep, then falcon
# --n 140:141); the layer sweep about 3 s of it with the shim.
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"
PY=/usr/bin/python3
cd "$tmp" || exit 1

# the clock that counts its reads (tests/clock_shim.c), when given: the long
# runs' lines then come on their own steps, not the wall's seconds
clock_preload=
if clock_shim=$(shim_path "${3:-}" clock); then
    clock_preload=$(preload_list "$clock_shim")
else
    echo "NOTE: no clock shim: the long runs' lines waited for by the wall's clock"
fi
$PY - "$GW" "$clock_preload" >"$tmp/checks.out" 2>&1 <<'EOF'
import json, os, re, subprocess, sys, threading, time
GW = sys.argv[1]
# LD_PRELOAD for the clock shim ("" without it): GW_CLOCK_STEP_MS ms a read
SHIM = sys.argv[2]
def check(cond, what):
    print(("PASS: " if cond else "FAIL: ") + what, flush=True)

# (a line before any work is measured, P = 0, ends at "E s elapsed": at GW_PROGRESS_MS=0 the
# first lines of a study come then)
LINE = re.compile(r"  (\d+)/(\d+) collisions, ([0-9.]+)% of the work, ([0-9.]+) s elapsed(?:, ~([0-9.]+) s left)?")
# a sweep's line: the cases ended and under way, the share of the work (the
# cases under way by their parts), the time left once the share is above 0
SWEEP = re.compile(r"sweep: (\d+)/(\d+) cases, (\d+) under way, ([0-9.]+)% of the work, ([0-9.]+) s elapsed"
                   r"(?:, ~([0-9.]+) s left)?")

class Run:
    """A run of the program whose stderr lines are stamped as they arrive."""
    def __init__(self, args, delay_ms=None, step_ms=None):
        """delay_ms: GW_PROGRESS_MS, the display's delay and period (None: unset, the program's own);
        step_ms: with the clock shim, its clock's step a read (None: the wall's clock)"""
        self.args = args
        env = dict(os.environ)
        for k in ("GW_PROGRESS_MS", "GW_CLOCK_STEP_MS", "LD_PRELOAD"):
            env.pop(k, None)
        if delay_ms is not None:
            env["GW_PROGRESS_MS"] = delay_ms
        if step_ms is not None and SHIM:
            env["GW_CLOCK_STEP_MS"] = step_ms
            env["LD_PRELOAD"] = SHIM
        self.t0 = time.monotonic()
        self.p = subprocess.Popen([GW] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
        self.lines, self.out = [], b""
        self.t_end = None
        self.reader = threading.Thread(target=self._read)
        self.reader.start()
        self.outreader = threading.Thread(target=self._read_out)
        self.outreader.start()
    def _read(self):
        for raw in self.p.stderr:
            self.lines.append((time.monotonic() - self.t0, raw.decode(errors="replace").rstrip("\n")))
    def _read_out(self):
        self.out = self.p.stdout.read()
    def progress(self, line=LINE):
        return [(t, line.fullmatch(l)) for t, l in self.lines[1:] if line.fullmatch(l)]
    def stop(self):
        """Kill the run if still running; its elapsed time when stopped."""
        el = time.monotonic() - self.t0
        if self.p.poll() is None:
            self.p.kill()
        self.p.wait()
        self.reader.join()
        self.outreader.join()
        return el

def name(r):
    return " ".join(r.args[:4])

def when(t, m, g):
    """A line's time: as it arrived on the pipe (t, s), or with the clock shim
    the time the line says (group g of m), that clock's: its reads, not the wall"""
    return float(m.group(g)) if SHIM else t

# the shim's step a read, ms: a study's watch call (a sample of a collision)
# and a layer-make step read it once, a sweep's ticker each 100 ms of the
# wall, layer-make's report once a step of its pluviation, so 2 s of the
# shim's clock is a thousand samples, 8 ticks, 4 reports
STUDY_STEP, SWEEP_STEP, LM_STEP = "2", "250", "500"
# the layer sweep's: each ticker read 20 s, past the gap between lines (2 s,
# then a twentieth of the time elapsed, at most 30 s): a line at every read
# of the ticker, every 100 ms of the wall, however short or loaded the case
LAYER_STEP = "20000"
# the long runs' window (s of the wall): a failure's bound with the shim,
# where the lines come within about a second
WINDOW = 60 if SHIM else 12

# --- the long studies, at once, each with its --quiet twin ---
LONG = [
    (["falcon", "--n", "400:401", "--heights", "none", "--vimp", "0.3", "--jobs", "2"], 2, "granwave falcon: 2 collisions"),
    (["wavespeed", "--n", "400:402", "--vimp", "0.3", "--jobs", "3"], 4, "granwave wavespeed: 4 collisions"),
    (["softwall", "--n", "300:302", "--jobs", "2"], 23, "granwave softwall: N = 300..302 on one wall"),
]
# a sweep of two such columns on 2 threads: its cases end after the window
for o in ("sw", "swq"):
    open(o + ".ini", "w").write("[sweep]\nmodel = chain\nout = %s\n[grid]\nn = 400, 401\n" % o)
runs = [(Run(a, step_ms=STUDY_STEP), Run(a + ["--quiet"], step_ms=STUDY_STEP), n, h) for a, n, h in LONG]
sw, swq = Run(["sweep", "sw.ini", "--jobs", "2"], step_ms=SWEEP_STEP), \
    Run(["sweep", "swq.ini", "--jobs", "2", "--quiet"], step_ms=SWEEP_STEP)
# a pluviation of 300 discs (16 s here) in a pipe: it spoke on a terminal only
lm, lmq = Run(["layer-make", "--n", "300", "--seed", "1", "--out", "lm.txt"], step_ms=LM_STEP), \
    Run(["layer-make", "--n", "300", "--seed", "1", "--out", "lmq.txt", "--quiet"], step_ms=LM_STEP)
deadline = time.monotonic() + WINDOW
while time.monotonic() < deadline and any(len(r.progress()) < 3 and r.p.poll() is None for r, _, _, _ in runs) or \
        (time.monotonic() < deadline and len(sw.progress(SWEEP)) < 3 and sw.p.poll() is None):
    time.sleep(0.05)
while time.monotonic() < deadline and not lm.lines and lm.p.poll() is None:
    time.sleep(0.05)
el, el_q = lm.stop(), lmq.stop()
LM = re.compile(r"granwave layer-make: t = [0-9.e+-]+ s simulated \(until the pile settles, at most t-max 6 s\), "
                r"([0-9]+) s elapsed")
check(len(lm.lines) >= 1 and all(LM.fullmatch(l) for _, l in lm.lines)
      and 2 <= when(lm.lines[0][0], LM.fullmatch(lm.lines[0][1]), 1) <= 6.0,
      "layer-make --n 300 in a pipe: a line within 6 s, not before 2 s, whole lines: %r" % lm.lines[:2])
check(not lmq.lines, "layer-make --quiet: nothing on stderr in %.1f s: %r" % (el_q, lmq.lines[:2]))
el, el_q = sw.stop(), swq.stop()
prog = sw.progress(SWEEP)
check(len(sw.lines) >= 1 and sw.lines[0][1].startswith("sweep: 2 cases, 0 already done, 2 to run on threads"),
      "sweep: its header first: %r" % sw.lines[:1])
check(len(prog) == len(sw.lines) - 1, "sweep: every other line a whole progress line: %r"
      % [l for _, l in sw.lines[1:] if not SWEEP.fullmatch(l)])
check(len(prog) >= 3, "sweep: three lines within %d s (%d in %.1f s)" % (WINDOW, len(prog), el))
if prog:
    t0 = when(prog[0][0], prog[0][1], 5)
    check(2.0 <= float(prog[0][1].group(5)) and t0 <= 6.0 and prog[0][1].group(1) == "0"
          and prog[0][1].group(3) == "2",
          "sweep: the first line within 6 s and not before 2 s, before any case ended, its cases under way: "
          "%.2f s %s" % (t0, prog[0][1].group(0)))
    inside = [x for _, x in prog if x.group(1) == "0"]
    ps = [float(x.group(4)) for x in inside]
    check(len(ps) >= 2 and ps[0] > 0 and all(b > a for a, b in zip(ps, ps[1:])) and ps[-1] < 100
          and all(x.group(6) is not None for x in inside),
          "sweep: inside its cases (0/2 ended) the share of the work above 0 and rising, under 100 %%, with a "
          "time left: %s" % ps)
    # at most 4.5 s apart (as they arrive, or by the shim's clock), and at
    # least the period (2 s, by the times they say): no line repeated
    gaps = [when(b[0], b[1], 5) - when(a[0], a[1], 5) for a, b in zip(prog, prog[1:])]
    said = [float(b[1].group(5)) - float(a[1].group(5)) for a, b in zip(prog, prog[1:])]
    check(all(g <= max(4.5, float(a[1].group(5)) / 20 + 1) for g, a in zip(gaps, prog)) and all(g >= 1.9 for g in said),
          "sweep: lines at most 4.5 s apart, and 2 s or more by the times they say: %s %s"
          % (["%.2f" % g for g in gaps], ["%.1f" % g for g in said]))
    check(all(x.group(2) == "2" for _, x in prog), "sweep: n = 2 cases in every line")
check(not swq.lines, "sweep --quiet: nothing on stderr in %.1f s: %r" % (el_q, swq.lines[:2]))

for r, q, n, head in runs:
    el, el_q = r.stop(), q.stop()
    lines = r.lines
    prog = r.progress()
    what = name(r)
    check(len(lines) >= 1 and lines[0][1].startswith(head), "%s: the header first: %r" % (what, lines[:1]))
    check(len(prog) == len(lines) - 1, "%s: every other line a whole progress line: %r"
          % (what, [l for _, l in lines[1:] if not LINE.fullmatch(l)]))
    check(len(prog) >= 3, "%s: three lines within %d s (%d in %.1f s)" % (what, WINDOW, len(prog), el))
    if prog:
        t0 = when(prog[0][0], prog[0][1], 4)
        check(t0 <= 6.0 and float(prog[0][1].group(4)) >= 2.0,
              "%s: the first line %.2f s after the start (at most 6 s), saying %s s (not before 2 s)"
              % (what, t0, prog[0][1].group(4)))
        m = prog[0][1]
        if what.startswith("softwall"):  # the rigid wall's 20 short columns may be done, no 300-bead one
            # (its work begun: a column ended, or a share above 0; with the
            # shim the first line comes after a thousand samples, 0.0 %)
            check(int(m.group(1)) <= 20 and (float(m.group(3)) > 0 or int(m.group(1)) > 0),
                  "%s: the first line within the walls' columns: %s" % (what, m.group(0).strip()))
        else:
            check(int(m.group(1)) == 0 and float(m.group(3)) > 0,
                  "%s: the first line before any collision ended, its work begun: %s" % (what, m.group(0).strip()))
        gaps = [when(b[0], b[1], 4) - when(a[0], a[1], 4) for a, b in zip(prog, prog[1:])]
        said = [float(b[1].group(4)) - float(a[1].group(4)) for a, b in zip(prog, prog[1:])]
        # (a twentieth of the time elapsed past 90 s: the lines of a run
        # that went on while the others came to their third)
        check(all(g <= max(4.5, float(a[1].group(4)) / 20 + 1) for g, a in zip(gaps, prog)) and all(g >= 1.9 for g in said),
              "%s: lines at most 4.5 s apart, and 2 s or more by the times they say: %s %s"
              % (what, ["%.2f" % g for g in gaps], ["%.1f" % g for g in said]))
        ks = [int(x.group(1)) for _, x in prog]
        ps = [float(x.group(3)) for _, x in prog]
        check(all(b >= a for a, b in zip(ks, ks[1:])) and all(b >= a for a, b in zip(ps, ps[1:])),
              "%s: k and P never decrease: %s %s" % (what, ks, ps))
        check(all(int(x.group(2)) == n for _, x in prog), "%s: n = %d collisions in every line" % (what, n))
        check(all(float(x.group(3)) < 100 for _, x in prog) or r.p.returncode == 0,
              "%s: under 100%% while running" % what)
    check(not q.lines, "%s --quiet: nothing on stderr in %.1f s: %r" % (what, el_q, q.lines[:2]))

# --- a layer sweep of two exact impacts, one at a time, each several seconds ---
subprocess.run([GW, "layer-make", "--n", "40", "--seed", "1", "--out", "s40.txt", "--quiet"], check=True,
               stdout=subprocess.DEVNULL)
# rk4's step: with the shim the lines come on the ticker's reads, and cases of
# about a second each (2e-6 s) hold several; on the wall's clock, cases of
# about 5 s each (4e-7 s) for lines 2 s apart
LAYER_DT = "2e-6" if SHIM else "4e-7"
for o in ("ly", "lyq"):
    open(o + ".ini", "w").write("[sweep]\nmodel = layer\nout = %s\n[grid]\nsample = s40.txt\nvi = 20, 21\n"
                                "[params]\nexact = 1\ndt = %s\n" % (o, LAYER_DT))
ly_t0 = time.monotonic()
ly, lyq = Run(["sweep", "ly.ini", "--jobs", "1"], step_ms=LAYER_STEP), Run(["sweep", "lyq.ini", "--jobs", "1", "--quiet"])
ly.p.wait(timeout=300)
lyq.p.wait(timeout=300)
ly.stop(), lyq.stop()
print("NOTE: layer sweep (rk4 at %s s, %s): %.1f s" % (LAYER_DT, "clock shim" if SHIM else "wall's clock",
                                                     time.monotonic() - ly_t0), flush=True)
prog = ly.progress(SWEEP)
# (the sweep's warning lines apart: since session 46 the crowns' speeds nulled for
# their scatter on this pile are said in one line before the last)
ly_said = [l for _, l in ly.lines if not l.startswith("granwave sweep: warning: ")]
check(ly.p.returncode == 0 and lyq.p.returncode == 0 and len(prog) == len(ly_said) - 2,
      "layer sweep: exit 0 (%s, --quiet %s), the header, whole progress lines and the last line: %r"
      % (ly.p.returncode, lyq.p.returncode, [l for _, l in ly.lines]))
first = [x for _, x in prog if x.group(1) == "0"]
check(any(float(x.group(4)) > 0 and x.group(3) == "1" and x.group(6) is not None for x in first),
      "layer sweep: a line inside its first case (0/2 ended, 1 under way) with a share of the work above 0 and a "
      "time left: %r" % [x.group(0) for x in first])
# its part: the impact's simulated time over the end its block's flight gives
# (T_f), not over t-max (then at most 0.31 / 2 of a case, 7.7 % of the sweep,
# until a case ended): the last line inside the first case (at 2 s or later
# of its 5 s or more) is past a tenth of the sweep
check(any(float(x.group(4)) > 10 for x in first),
      "layer sweep: inside its first case the share passes 10 %% (its part over the flight's end, not t-max): %s"
      % [x.group(4) for x in first])
check(bool(prog) and prog[-1][1].group(1) == "2" and prog[-1][1].group(4) == "100.0",
      "layer sweep: the last line 2/2 at 100 %%: %s" % (prog[-1][1].group(0) if prog else None))
try:
    rows = [[l for l in open(o + "/results.csv", "rb") if not l.startswith(b"#")] for o in ("ly", "lyq")]
    same = rows[0] == rows[1] and len(rows[0]) == 3
except OSError:
    same = False
check(same, "layer sweep: its table's rows those of its --quiet twin, byte for byte")
# --- a study of a few seconds to its end: the last line, and stdout's JSON ---
r = Run(["falcon", "--n", "140:141", "--heights", "none", "--vimp", "0.3", "--jobs", "2", "--json"], "0")
r.p.wait(timeout=120)
el = r.stop()
prog = r.progress()
check(r.p.returncode == 0, "falcon --n 140:141: exit 0 (%s)" % r.p.returncode)
try:
    res = json.loads(r.out)
    check(isinstance(res, dict) and "tau_n" in json.dumps(res), "falcon --n 140:141 --json: stdout parses as JSON")
except ValueError as e:
    check(False, "falcon --n 140:141 --json: stdout does not parse: %s" % e)
check(len(r.lines) >= 2 and r.lines[0][1].startswith("granwave falcon: 2 collisions")
      and len(prog) == len(r.lines) - 1, "falcon --n 140:141: the header and whole lines: %r" % [l for _, l in r.lines])
if prog:
    last = prog[-1][1]
    check(last.group(1) == last.group(2) == "2" and last.group(3) == "100.0", "the last line 2/2 at 100%%: %s"
          % last.group(0).strip())
# at delay 0 a line is due at once, whatever the machine's speed: one before the last
check(len(prog) >= 2 and prog[0][1].group(3) != "100.0", "falcon --n 140:141 (%.1f s, GW_PROGRESS_MS=0): a line "
      "before the last: %s" % (el, [x.group(3) for _, x in prog]))

# --- short studies: the header and the last line; the same JSON with --quiet ---
SHORT = [(["falcon", "--n", "1:5", "--heights", "none", "--json"], 5),
         (["wavespeed", "--n", "5:10", "--vimp", "0.3", "--json"], 7),
         (["softwall", "--n", "1:6", "--json"], 26)]
for a, n in SHORT:
    r, q = Run(a, "1e9"), Run(a + ["--quiet"], "1e9")  # shorter than the delay on any machine
    r.p.wait(timeout=60)
    q.p.wait(timeout=60)
    el = r.stop()
    q.stop()
    what = " ".join(a[:3])
    try:
        jr, jq = json.loads(r.out), json.loads(q.out)
        for j in (jr, jq):
            j.pop("wall_time_ms", None)
            j.pop("wall_time_s", None)
        check(jr == jq, "%s: stdout's JSON parses and is --quiet's but for the wall time" % what)
    except ValueError as e:
        check(False, "%s: stdout is not JSON: %s" % (what, e))
    prog = r.progress()
    check(r.p.returncode == 0 and len(prog) == len(r.lines) - 1 and len(prog) >= 1 and
          prog[-1][1].group(1) == prog[-1][1].group(2) == str(n), "%s: exit 0, the header and whole lines ending "
          "%d/%d: %r" % (what, n, n, [l for _, l in r.lines]))
    check(len(prog) == 1, "%s (%.2f s, GW_PROGRESS_MS=1e9): the last line only" % (what, el))
    check(q.p.returncode == 0 and not q.lines, "%s --quiet: nothing on stderr: %r" % (what, q.lines[:2]))
EOF
while IFS= read -r l; do
    case $l in PASS:*) ok "${l#PASS: }" ;; FAIL:*) ko "${l#FAIL: }" ;; NOTE:*) echo "$l" ;; *) ko "checker: $l" ;; esac
done <"$tmp/checks.out"
[ "$passes" -gt 0 ] || ko "no check ran"

test_summary test_study_progress
