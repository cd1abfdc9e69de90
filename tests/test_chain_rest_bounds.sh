#!/bin/bash
# test_chain_rest_bounds.sh GRANWAVE SRCDIR: a column that gravity holds on the
# wall (gravity takes back the impact speed within the collision's expected
# length, g t_e > v_imp) never separates: bead 1 bounces on the wall, the top
# contacts chatter, cvode restarts at each of their events, and the run goes on
# to t-max. The plan bounds that work before the run (issue 18, unbounded
# work): samples (at the finer of dt-out and tau_1/200) over t-max times the
# beads, at most 1e7.
#   - chain --n 300 --gravity 100 --vimp 1e-3 (about 100 s of CPU before: 1.9 s
#     per 3 ms of its 0.152 s default t-max) exits 2 at once (within 5 s) with
#     one line naming --gravity, vimp, t-max and the bound, nothing written with
#     --out; the same with an explicit --t-max 1 (without --out: with it the
#     written trace's bound trips first), in a chain sweep's case (before
#     OUT is made) and in Python's chain();
#   - the t-max the message suggests is accepted, and what the bound must leave
#     alone still runs: a held column of 3 beads at 1e-9 m/s, 10 beads at
#     1e-3 m/s under 100 m/s^2, a column that leaves the wall under gravity
#     (--n 40 --gravity 9.81, converged) and the same 300 beads cut at 2e-3 s.
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
test_setup "$@"
PY=/usr/bin/python3

# --- refused before the run (the old code ran it for about 100 s: killed at 5 s)
REFUSE_TIMEOUT=5
held="takes back the impact speed \(vimp 0.001 m/s\) in 1e-05 s, within the collision's expected 0.00759 s: the column stays on the wall"
refused "chain --n 300 --gravity 100 --vimp 1e-3 (default t-max)" \
    "^granwave chain --gravity: 100 m/s\^2 $held.* t-max 0.152 s, about 8.6[0-9]e\+05 samples .* times 300 beads, above the bound 1e\+07 .*lower t-max to 0.0058 s or less, raise vimp or lower gravity$" \
    chain --n 300 --gravity 100 --vimp 1e-3 --out "$tmp/o"
refused "chain --n 300 --gravity 100 --vimp 1e-3 --t-max 1" "^granwave chain --gravity: .* goes on to t-max 1 s, about 5.6[0-9]e\+06 samples" \
    chain --n 300 --gravity 100 --vimp 1e-3 --t-max 1
printf '[sweep]\nmodel = chain\n[grid]\nvimp = 1e-3\n[params]\nn = 300\ngravity = 100\n' >"$tmp/s.ini"
refused "a chain sweep's case with n = 300, gravity = 100, vimp = 1e-3 (before OUT is made)" \
    "^granwave sweep: .*s.ini: case 0: gravity: 100 m/s\^2 takes back .* above the bound 1e\+07" sweep "$tmp/s.ini" --out "$tmp/o"

# Python: the same check in the library
if out=$(pyenv cpu_run 20 $PY -c "
import granwave
try:
    granwave.chain(n=300, gravity=100, vimp=1e-3)
except granwave.GranwaveValueError as e:
    print(e)
else:
    print('ran')
" 2>&1) && [[ $out == *"gravity: 100 m/s^2 takes back the impact speed"*"above the bound 1e+07"* ]]; then
    ok "Python chain(n=300, gravity=100, vimp=1e-3) refused: ${out:0:120}"
else ko "Python chain(n=300, gravity=100, vimp=1e-3): ${out:0:300}"; fi

# --- the suggested t-max is accepted (60 beads: suggested 0.038 s of 0.0404 s)
cpu_run 5 "$GW" chain --n 60 --gravity 100 --vimp 1e-3 >/dev/null 2>"$tmp/e60" </dev/null
lim=$(sed -n 's/.*lower t-max to \([0-9.e+-]*\) s or less.*/\1/p' "$tmp/e60")
if [ -z "$lim" ]; then ko "chain --n 60 --gravity 100 --vimp 1e-3: no suggested t-max ($(head -c 300 "$tmp/e60"))"
else
    # accepted: not refused at once (still running when killed at 3 s of CPU, or done)
    rc=$( (cpu_run 3 "$GW" chain --n 60 --gravity 100 --vimp 1e-3 --t-max "$lim" >/dev/null 2>"$tmp/e" </dev/null
           echo $?) 2>/dev/null)
    if [ $rc -eq 2 ]; then ko "the suggested --t-max $lim is refused: $(head -c 300 "$tmp/e")"
    else ok "the suggested --t-max $lim is accepted (exit $rc, 137 = still running at 3 s of CPU)"; fi
fi

# --- what the bound leaves alone
for a in "--n 3 --vimp 1e-9 --gravity 9.81" "--n 10 --gravity 100 --vimp 1e-3"; do
    # shellcheck disable=SC2086
    runs_json "chain $a (held, small)" "$tmp/r.json" chain $a && ok "chain $a runs (held on the wall, within the bound)"
done
if runs_json "chain --n 40 --gravity 9.81" "$tmp/g.json" chain --n 40 --gravity 9.81; then
    r=$(jq_py "$tmp/g.json" "d['converged']")
    [ "$r" = True ] && ok "chain --n 40 --gravity 9.81 leaves the wall and converges" || ko "chain --n 40 --gravity 9.81: converged $r"
fi
timeout -s KILL 60 "$GW" chain --n 300 --gravity 100 --vimp 1e-3 --t-max 2e-3 >/dev/null 2>"$tmp/e" </dev/null; rc=$?
[ $rc -eq 1 ] && grep -q "bead 1 still on the wall at t_max = 0.002 s" "$tmp/e" &&
    ok "--t-max 2e-3 on the 300 beads runs (exit 1: bead 1 still on the wall)" ||
    ko "--t-max 2e-3 on the 300 beads: exit $rc, $(head -c 300 "$tmp/e")"

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
