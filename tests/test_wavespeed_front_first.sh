#!/bin/bash
# test_wavespeed_front_first.sh GRANWAVE SRCDIR: a front threshold under the
# energy bound (front_reach_check) that the contacts still do not reach
# (session 48). `wavespeed --n 3:8 --vimp 0.3,0.4 --k 1000 --threshold 0.005`
# passed the bound (0.33 N against 0.37 N: all the column's kinetic energy in
# one contact) and exited 1, "no front fit" (0 of contacts 2..6 reached it,
# two beads meeting at 2 v_imp carrying about 0.16 N), after every column of
# the tau_N sweep: 11.4 s of CPU. No sounder bound decides it before any run
# (the energy may gather in one contact), so the front columns run first and
# the failure comes after them, before the sweep: exit 1 within 4 s of CPU,
# one line naming --threshold, nothing written under --out. Control: the
# defaults give the same JSON as before the reordering (the front columns
# are the same runs), checked on a few values.
# shellcheck source=refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

rm -rf "$tmp/o"
cpu_run 4 "$GW" wavespeed --n 3:8 --vimp 0.3,0.4 --k 1000 --threshold 0.005 --quiet --out "$tmp/o" \
    >"$tmp/stdout" 2>"$tmp/stderr" </dev/null
rc=$?
if [ $rc -eq 1 ] && [ "$(wc -l <"$tmp/stderr")" -eq 1 ] &&
    grep -q "^granwave wavespeed: no front fit at v_imp = 0.3 (the force of 0 of contacts 2..6 .*lower --threshold)" \
        "$tmp/stderr" && [ ! -e "$tmp/o" ] && [ ! -s "$tmp/stdout" ]; then
    ok "wavespeed --k 1000 --threshold 0.005: no front fit after the front columns (within 4 s of CPU), nothing written"
else
    ko "wavespeed --k 1000 --threshold 0.005: exit $rc ($(head -c 300 "$tmp/stderr")), $(ls "$tmp/o" 2>/dev/null | tr '\n' ' ')"
fi

# control: the defaults, their front and tau_N speeds as before the reordering
if runs_json "control: wavespeed --n 3:8 --vimp 0.3,0.4" ws.json wavespeed --n 3:8 --vimp 0.3,0.4; then
    got=$(jq_py ws.json "' '.join('%.9g' % x for x in d['v_front'] + d['v_tq'] + d['v_group'] + [d['unfinished'], d['n_held']])")
    want="626.46279 663.564323 630.037275 667.350503 767.393242 812.841217 0 0"
    [ "$got" = "$want" ] && ok "control: the defaults' v_front, v_tq, v_group as before" ||
        ko "control: the defaults' speeds: $got, wanted $want"
fi
test_summary test_wavespeed_front_first
