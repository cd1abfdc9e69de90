#!/bin/bash
# test_dispersion_progress.sh GRANWAVE SRCDIR: `granwave dispersion` reports a
# long run's progress on stderr, as `granwave drop` and `chain` do (issue 18).
#  - with the display's delay and period set to 0 (GW_PROGRESS_MS=0: a line
#    each tenth of the count, whatever the machine's speed), a run (--n 8192)
#    prints a header naming the beads and the velocity samples, then whole
#    lines "  k/2048 samples, R samples/s, E s elapsed, ~L s left" whose k
#    grows to 2048; nothing else on stderr;
#  - --quiet prints nothing, and stdout's JSON equals the progress run's but
#    for the timings (wall_time_ms, integrate_ms, fft_ms);
#  - --column-n 200 counts the column's samples of dt_out over the
#    collision's expected length, growing to the total, which the last line
#    reaches;
#  - a run shorter than the delay says nothing: the default run (1024 beads)
#    with the delay at 1e9 ms prints nothing on stderr, and at delay 0 its
#    header and lines (what the delay held back); at the default delay (2 s)
#    any line it prints says 2 s elapsed or more.
# Before GW_PROGRESS_MS the runs had to last 2 s (and the default one less)
# on the machine of the day.
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"
PY=/usr/bin/python3

GW_PROGRESS_MS=0 "$GW" dispersion --n 8192 --json >"$tmp/p.json" 2>"$tmp/p.err"; rc_p=$?
"$GW" dispersion --n 8192 --json --quiet >"$tmp/q.json" 2>"$tmp/q.err"; rc_q=$?
GW_PROGRESS_MS=0 "$GW" dispersion --column-n 200 --json >"$tmp/c.json" 2>"$tmp/c.err"; rc_c=$?
[ $rc_p -eq 0 ] && [ $rc_q -eq 0 ] && [ $rc_c -eq 0 ] && ok "the three long runs exit 0" \
    || ko "exit $rc_p / $rc_q / $rc_c: $(head -2 "$tmp/p.err" "$tmp/q.err" "$tmp/c.err")"
[ ! -s "$tmp/q.err" ] && ok "--quiet: nothing on stderr" || ko "--quiet: stderr $(head -3 "$tmp/q.err")"

# lines FILE.json FILE.err HEADER-REGEX: the lines against the run's JSON, one PASS/FAIL line per check
lines() {
    $PY - "$@" <<'EOF'
import json, re, sys
res = json.load(open(sys.argv[1]))
err = open(sys.argv[2]).read().splitlines()
def check(cond, what):
    print(("PASS: " if cond else "FAIL: ") + what)
head = re.fullmatch(sys.argv[3], err[0] if err else "")
check(head is not None, "header line: %r" % (err[0] if err else None))
line = re.compile(r"  (\d+)/(\d+) samples, [0-9.]+ samples/s, ([0-9.]+) s elapsed, ~[0-9.]+ s left")
rows = [line.fullmatch(l) for l in err[1:]]
check(len(rows) >= 2 and all(rows), "%d lines, each a progress line: %r" % (len(rows), err[1:]))
rows = [m for m in rows if m]
if rows and head:
    k = [int(m.group(1)) for m in rows]
    tot = {int(m.group(2)) for m in rows}
    check(tot == {int(head.group(1))}, "every line's total is the header's %s: %s" % (head.group(1), tot))
    # (at GW_PROGRESS_MS=0 each report of a tenth is due: the column's count, reported twice at
    # one value, may repeat; it never falls and it rises)
    check(all(b >= a for a, b in zip(k, k[1:])) and len(set(k)) >= 2,
          "the count grows from line to line (never falls, rises): %s" % k)
    check(k[-1] == int(head.group(1)), "the last line reaches the total (%d of %s)" % (k[-1], head.group(1)))
    total = int(head.group(1))
    if "settings" in res and "spectrum" in res["settings"]:
        ts = res["settings"]["spectrum"]["t_samples"]
        check(total == ts, "the total is the JSON's t_samples %d" % ts)
    else:  # the expected length in samples of dt_out: n transits and the wall contact, about tau_N
        te = total * res["dt_out"]
        check(0.3 * res["tau_n"] < te < 3 * res["tau_n"],
              "the total's length %g s within a factor 3 of tau_N %g s" % (te, res["tau_n"]))
EOF
}
# check_lines WHAT FILE: the checker's lines counted (read from a file: a pipe's loop would count in a subshell)
check_lines() {
    while IFS= read -r l; do
        case $l in PASS:*) ok "$1: ${l#PASS: }" ;; FAIL:*) ko "$1: ${l#FAIL: }" ;; *) ko "$1: checker: $l" ;; esac
    done <"$2"
}
lines "$tmp/p.json" "$tmp/p.err" \
    'granwave dispersion: 8192 beads, (\d+) velocity samples \(the transform follows the last\)' >"$tmp/p.out" 2>&1
check_lines "--n 8192" "$tmp/p.out"
lines "$tmp/c.json" "$tmp/c.err" \
    "granwave dispersion: a column of 200 beads, (\d+) samples over the collision's expected length .*" \
    >"$tmp/c.out" 2>&1
check_lines "--column-n 200" "$tmp/c.out"

$PY - "$tmp/p.json" "$tmp/q.json" <<'EOF' && ok "stdout JSON parses and equals the quiet run's but for the timings" \
    || ko "stdout JSON differs from the quiet run's (or does not parse)"
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
for d in (a, b):
    for k in ("wall_time_ms", "integrate_ms", "fft_ms"):
        d.pop(k, None)
sys.exit(0 if a == b else 1)
EOF

# a run shorter than the delay says nothing (the delay set beyond any run's length)
GW_PROGRESS_MS=1e9 "$GW" dispersion --json >"$tmp/s.json" 2>"$tmp/s.err"; rc=$?
if [ $rc -eq 0 ] && [ ! -s "$tmp/s.err" ] && $PY -c 'import json,sys; json.load(open(sys.argv[1]))' "$tmp/s.json"; then
    ok "the default run at GW_PROGRESS_MS=1e9: exit 0, nothing on stderr, JSON on stdout"
else
    ko "default run: exit $rc, stderr $(head -3 "$tmp/s.err")"
fi
# ... and what the delay held back: at delay 0 its header, and lines up to the total
GW_PROGRESS_MS=0 "$GW" dispersion --json >"$tmp/s0.json" 2>"$tmp/s0.err"; rc=$?
if [ $rc -eq 0 ] && head -1 "$tmp/s0.err" | grep -q '^granwave dispersion: 1024 beads, ' \
    && [ "$(grep -c '^  [0-9]*/[0-9]* samples, ' "$tmp/s0.err")" -ge 2 ]; then
    ok "the default run at GW_PROGRESS_MS=0: the header and $(grep -c '^  [0-9]' "$tmp/s0.err") lines"
else
    ko "the default run at delay 0: exit $rc, stderr $(head -3 "$tmp/s0.err")"
fi
# at the default delay (2 s): a line, if the machine is slow enough for one, says 2 s elapsed or more
env -u GW_PROGRESS_MS "$GW" dispersion --json >"$tmp/sd.json" 2>"$tmp/sd.err"; rc=$?
early=$(grep -o '[0-9.]* s elapsed' "$tmp/sd.err" | awk '$1 < 2.0' | head -1)
[ $rc -eq 0 ] && [ -z "$early" ] && ok "at the default delay: no line before 2 s elapsed ($(wc -l <"$tmp/sd.err") lines)" \
    || ko "at the default delay: exit $rc, a line at $early"

test_summary test_dispersion_progress
