#!/bin/bash
# test_chain_progress.sh GRANWAVE SRCDIR: `granwave chain` reports a long run's
# progress on stderr, as `granwave drop` does (issue 18).
#  - with the display's delay and period set to 0 (GW_PROGRESS_MS=0, so the
#    lines do not depend on the machine's speed) a run (250 beads under cvode
#    bdf) prints a header naming the column, its expected length and t-max
#    (the JSON's settings.solver.t_max), then lines
#    "  t = T ms of ~E ms expected (P%...), X s elapsed, ..." whose P = T/E
#    grows from line to line, the last "ended" at the run's t_end (the
#    JSON's); nothing else on stderr;
#  - --quiet prints nothing on stderr;
#  - progress changes no result: stdout's JSON parses and equals the quiet
#    run's but for wall_time_ms; the --out files are the same, byte for byte
#    but for the recorded command line (which holds --quiet) and wall_time_ms:
#    the CSV files, chain.json, and chain.h5's datasets;
#  - a run shorter than the delay says nothing: a short run (20 beads) with
#    the delay at 1e9 ms prints nothing on stderr, and the same run with the
#    delay at 0 prints its header and lines (what the delay held back); at the
#    default delay (2 s) any line it prints says 2 s elapsed or more;
#  - a malformed GW_PROGRESS_MS (abc, -1, inf, empty) is refused: exit 2, one
#    line naming it, nothing on stdout;
#  - the column's end from its state (session 46): a run that goes on to 1.56
#    times its expected length (200 beads under rk4) says "or more" until its
#    column flies free, then names its last closing pair's meeting, before
#    t_end and within 3 % of it; its JSON is the quiet run's.
# Before GW_PROGRESS_MS, whether the long run lasted 2 s and the short one
# less depended on the machine's load.
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"
PY=/usr/bin/python3

# a long column, sampled every 10 us (the files stay at about 30 MB)
LONG=(chain --n 250 --dt-out 1e-5 --json)
GW_PROGRESS_MS=0 "$GW" "${LONG[@]}" --out "$tmp/p" >"$tmp/p.json" 2>"$tmp/p.err"; rc_p=$?
"$GW" "${LONG[@]}" --out "$tmp/q" --quiet >"$tmp/q.json" 2>"$tmp/q.err"; rc_q=$?
[ $rc_p -eq 0 ] && ok "long run exits 0" || ko "long run exit $rc_p: $(head -3 "$tmp/p.err")"
[ $rc_q -eq 0 ] && ok "long run --quiet exits 0" || ko "long run --quiet exit $rc_q: $(head -3 "$tmp/q.err")"
[ ! -s "$tmp/q.err" ] && ok "--quiet: nothing on stderr" || ko "--quiet: stderr $(head -3 "$tmp/q.err")"

# the progress lines against the run's own JSON; one PASS/FAIL line per check
$PY - "$tmp/p.json" "$tmp/p.err" >"$tmp/lines.out" 2>&1 <<'EOF'
import json, re, sys
res = json.load(open(sys.argv[1]))
err = open(sys.argv[2]).read().splitlines()
def check(cond, what):
    print(("PASS: " if cond else "FAIL: ") + what)
num = r"([0-9.]+(?:e[+-]?[0-9]+)?)"
scale = {"s": 1.0, "ms": 1e-3, "us": 1e-6}
head = re.fullmatch(r"granwave chain: 250 beads, the collision expected to last about %s (s|ms|us) "
                    r"\(t-max %s (s|ms|us)\)" % (num, num), err[0] if err else "")
check(head is not None, "header line: %r" % (err[0] if err else None))
t_max = res["settings"]["solver"]["t_max"]
if head:
    e_head = float(head.group(1)) * scale[head.group(2)]
    tm = float(head.group(3)) * scale[head.group(4)]
    check(abs(tm - t_max) <= 1e-3 * t_max, "header's t-max %g s is the run's %g s" % (tm, t_max))
    # the expected length: n transits and the wall contact, so of the order of tau_N
    check(0.3 * res["tau_n"] < e_head < 3 * res["tau_n"],
          "expected length %g s within a factor 3 of tau_N %g s" % (e_head, res["tau_n"]))
line = re.compile(r"  t = %s (s|ms|us) of ~%s \2 expected \(%s%%(?:, t-max %s \2)?(\): ended)?.*, %s s elapsed(.*)"
                  % (num, num, num, num, num))
rows = [line.fullmatch(l) for l in err[1:]]
check(all(rows), "every other stderr line is a progress line: %r" % [l for l, m in zip(err[1:], rows) if not m])
rows = [m for m in rows if m]
check(len(rows) >= 2, "%d progress lines (one during the run and the last, at least)" % len(rows))
if rows:
    fr = [float(m.group(4)) for m in rows]
    ts = [float(m.group(1)) * scale[m.group(2)] for m in rows]
    # (at delay 0 lines come a twentieth of the time elapsed apart: P, to 0.1 %, may repeat,
    # and so may T, printed to 4 digits, when a loaded machine holds the run between two lines)
    check(all(b >= a for a, b in zip(ts, ts[1:])) and ts[-1] > ts[0] and all(b >= a for a, b in zip(fr, fr[1:])),
          "the fraction grows (T and P never fall, T rises over the run): %s" % fr)
    for m in rows:  # the percentage is T over E
        t, e = float(m.group(1)), float(m.group(3))
        check(abs(100 * t / e - float(m.group(4))) <= 0.06 + 1e-3 * float(m.group(4)),
              "%s: %.4g %% is T/E" % (m.group(0).strip(), 100 * t / e))
    el = [float(m.group(7)) for m in rows]
    check(all(b >= a for a, b in zip(el, el[1:])), "elapsed never decreases: %s" % el)
    last = rows[-1]
    check(last.group(6) is not None and all(m.group(6) is None for m in rows[:-1]),
          "the last line, and only it, says ended")
    t_last = float(last.group(1)) * scale[last.group(2)]
    check(abs(t_last - res["t_end"]) <= 1e-3 * res["t_end"],
          "the last line's t %g s is the run's t_end %g s" % (t_last, res["t_end"]))
    if head:
        check(all(abs(float(m.group(3)) * scale[m.group(2)] - e_head) <= 1e-3 * e_head for m in rows),
              "every line's expected length is the header's")
EOF
while IFS= read -r l; do
    case $l in PASS:*) ok "${l#PASS: }" ;; FAIL:*) ko "${l#FAIL: }" ;; *) ko "checker: $l" ;; esac
done <"$tmp/lines.out"

# stdout: the same JSON but for the run's own timing
$PY - "$tmp/p.json" "$tmp/q.json" <<'EOF' && ok "stdout JSON parses and equals the quiet run's but for wall_time_ms" \
    || ko "stdout JSON differs from the quiet run's (or does not parse)"
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
for d in (a, b):
    d.pop("wall_time_ms")
sys.exit(0 if a == b else 1)
EOF

# the --out files: the same names, the same bytes but for the command line and the timing
names_p=$(cd "$tmp/p" 2>/dev/null && ls); names_q=$(cd "$tmp/q" 2>/dev/null && ls)
[ -n "$names_p" ] && [ "$names_p" = "$names_q" ] && ok "the same --out files: $(echo $names_p)" \
    || ko "--out files differ: [$names_p] and [$names_q]"
for f in chain_wall_force.csv chain_beads.csv; do
    if [ -s "$tmp/p/$f" ] && cmp -s <(grep -v '^# command:' "$tmp/p/$f") <(grep -v '^# command:' "$tmp/q/$f"); then
        ok "$f identical but for the command line"
    else
        ko "$f differs beyond the command line"
    fi
done
if [ -s "$tmp/p/chain.json" ] && cmp -s <(grep -v '"wall_time_ms"' "$tmp/p/chain.json") \
    <(grep -v '"wall_time_ms"' "$tmp/q/chain.json"); then
    ok "chain.json identical but for wall_time_ms"
else
    ko "chain.json differs beyond wall_time_ms"
fi
if [ -e "$tmp/p/chain.h5" ]; then
    $PY - "$tmp/p/chain.h5" "$tmp/q/chain.h5" <<'EOF' && ok "chain.h5: the same datasets, bytes and units" \
        || ko "chain.h5 differs"
import sys, h5py, numpy as np
a, b = (h5py.File(f, "r") for f in sys.argv[1:3])
names = sorted(a.keys())
same = names == sorted(b.keys()) and len(names) > 0
for k in names:
    same = same and a[k].dtype == b[k].dtype and np.array_equal(a[k][()], b[k][()]) \
        and dict(a[k].attrs) == dict(b[k].attrs)
sys.exit(0 if same else 1)
EOF
fi

# a run shorter than the delay says nothing (the delay set beyond any run's length)
GW_PROGRESS_MS=1e9 "$GW" chain --n 20 --json >"$tmp/s.json" 2>"$tmp/s.err"; rc=$?
if [ $rc -eq 0 ] && [ ! -s "$tmp/s.err" ] && $PY -c 'import json,sys; json.load(open(sys.argv[1]))' "$tmp/s.json"; then
    ok "a run shorter than the delay (20 beads, GW_PROGRESS_MS=1e9): exit 0, nothing on stderr, JSON on stdout"
else
    ko "short run: exit $rc, stderr $(head -3 "$tmp/s.err")"
fi
# ... and what the delay held back: the same run at delay 0 prints its header and lines, the last "ended"
GW_PROGRESS_MS=0 "$GW" chain --n 20 --json >"$tmp/s0.json" 2>"$tmp/s0.err"; rc=$?
if [ $rc -eq 0 ] && head -1 "$tmp/s0.err" | grep -q '^granwave chain: 20 beads, ' \
    && [ "$(grep -c '^  t = .* s elapsed' "$tmp/s0.err")" -ge 2 ] && tail -1 "$tmp/s0.err" | grep -q '): ended, '; then
    ok "the same run at GW_PROGRESS_MS=0: the header and $(grep -c '^  t = ' "$tmp/s0.err") lines, the last ended"
else
    ko "the short run at delay 0: exit $rc, stderr $(head -3 "$tmp/s0.err")"
fi
# at the default delay (2 s): a line, if the machine is slow enough for one, says 2 s elapsed or more
env -u GW_PROGRESS_MS "$GW" chain --n 20 --json >"$tmp/sd.json" 2>"$tmp/sd.err"; rc=$?
early=$(grep -o '[0-9.]* s elapsed' "$tmp/sd.err" | awk '$1 < 2.0' | head -1)
[ $rc -eq 0 ] && [ -z "$early" ] && ok "at the default delay: no line before 2 s elapsed ($(wc -l <"$tmp/sd.err") lines)" \
    || ko "at the default delay: exit $rc, a line at $early"

# a malformed delay: refused before anything is done
for v in abc -1 inf '' 1e999 ' 5' 0x10; do
    GW_PROGRESS_MS="$v" "$GW" chain --n 20 --json >"$tmp/m.out" 2>"$tmp/m.err"; rc=$?
    if [ $rc -eq 2 ] && [ ! -s "$tmp/m.out" ] && [ "$(wc -l <"$tmp/m.err")" -eq 1 ] && grep -q "GW_PROGRESS_MS '$v'" "$tmp/m.err"; then
        ok "GW_PROGRESS_MS='$v': exit 2, one line naming it, nothing on stdout"
    else
        ko "GW_PROGRESS_MS='$v': exit $rc, stdout $(head -c 80 "$tmp/m.out"), stderr $(head -2 "$tmp/m.err")"
    fi
done

# the column's end from its state (session 46): chain --n 200 --solver rk4 runs
# on to 1.56 times its expected length, its last closing pair meeting at 7.74
# ms (t_end 7.86 ms). Until bead 1 is off the wall and every contact open the
# lines say "~L s left or more"; then they name that meeting, before t_end and
# within 3 % of it, from past the expected length on (t under it there);
# nothing in the results changes (the JSON is the quiet run's)
GW_PROGRESS_MS=0 "$GW" chain --n 200 --solver rk4 --json >"$tmp/e.json" 2>"$tmp/e.err"; rc_e=$?
"$GW" chain --n 200 --solver rk4 --json --quiet >"$tmp/eq.json" 2>/dev/null
[ $rc_e -eq 0 ] && ok "chain --n 200 --solver rk4 exits 0" || ko "chain --n 200 --solver rk4: exit $rc_e"
$PY - "$tmp/e.json" "$tmp/e.err" "$tmp/eq.json" >"$tmp/end.out" 2>&1 <<'EOF'
import json, re, sys
res = json.load(open(sys.argv[1]))
quiet = json.load(open(sys.argv[3]))
err = open(sys.argv[2]).read().splitlines()
def check(cond, what):
    print(("PASS: " if cond else "FAIL: ") + what)
num = r"([0-9.]+(?:e[+-]?[0-9]+)?)"
line = re.compile(r"  t = %s ms of ~%s ms expected \(%s%%\), %s s elapsed, ~%s s left(.*)" % (num, num, num, num, num))
rows = [m for m in map(line.fullmatch, err) if m]
more = [i for i, m in enumerate(rows) if m.group(6) == " or more"]
meet = [i for i, m in enumerate(rows) if m.group(6).startswith(" (the last closing pair meets at about ")]
check(len(more) >= 1 and len(meet) >= 1, "%d 'or more' lines and %d naming the last meeting" % (len(more), len(meet)))
check(bool(more and meet) and max(more) < min(meet), "every 'or more' line before every line naming the meeting")
t_end = res["t_end"] * 1e3
ts = [float(re.search(r"meets at about %s ms" % num, rows[i].group(6)).group(1)) for i in meet]
check(bool(ts) and all(0.97 * t_end <= t < t_end for t in ts),
      "the meetings named %s ms: before t_end %.4g ms, within 3 %% of it" % (sorted(set(ts)), t_end))
check(bool(meet) and all(float(rows[i].group(1)) >= float(rows[i].group(2)) and float(rows[i].group(1)) < ts[j]
                         for j, i in enumerate(meet)),
      "the meeting named only past the expected length, and while it is ahead")
for d in (res, quiet):
    d.pop("wall_time_ms", None)
check(res == quiet, "the JSON is the quiet run's but for wall_time_ms")
EOF
while IFS= read -r l; do
    case $l in PASS:*) ok "${l#PASS: }" ;; FAIL:*) ko "${l#FAIL: }" ;; *) ko "checker: $l" ;; esac
done <"$tmp/end.out"

test_summary test_chain_progress
