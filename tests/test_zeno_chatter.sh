#!/bin/bash
# test_zeno_chatter.sh GRANWAVE SRCDIR: a contact chattering just past the
# Zeno guard's window no longer holds a layer run still.
#  The guard of layer_sim.c switched the contact roots off after more than 20
#  events in a row each within 1e-12 s of the one before. On the 40-disc pile
#  of `layer-make --n 40`, `layer-impact --solver arkode --rtol 1e-5 --atol
#  1e-5` reached t = 34.6 ms and then stopped at a contact every 1.0e-12 to
#  1.2e-12 s, just past the window, 85,314 times in a row: it printed no
#  progress for minutes (killed here after 240 s; a hang, not a timing: the
#  run now takes about 10 s). The guard's wide tier (over 200 events in a row
#  each within 100 windows) steps over the chatter as the first tier does.
#  Checked: the run ends with exit 0 within the limit, counts Zeno guards in
#  its JSON, and its e_n and penetration agree with cvode's default run on the
#  same pile to 1e-3 (measured 1.7e-5 and 6e-5); cvode's run takes no guard
#  (kept: ordinary runs are untouched by the wide tier).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

"$GW" layer-make --n 40 --out p40.txt >/dev/null 2>mk.err || ko "layer-make --n 40: $(head -c 300 mk.err)"
"$GW" layer-impact --sample p40.txt --json >ref.json 2>ref.err || ko "cvode's run: $(head -c 300 ref.err)"
timeout 240 "$GW" layer-impact --sample p40.txt --solver arkode --rtol 1e-5 --atol 1e-5 --json >ark.json 2>ark.err
rc=$?
if [ $rc -eq 0 ]; then
    ok "arkode at rtol 1e-5 on the 40-disc pile ends (exit 0)"
else
    ko "arkode at rtol 1e-5 on the 40-disc pile: exit $rc (124: still running after 240 s): $(tail -c 300 ark.err)"
fi
g=$(jq_py ark.json "d['zeno_guards']" 2>/dev/null)
g0=$(jq_py ref.json "d['zeno_guards']" 2>/dev/null)
if [ -n "$g" ] && [ "$g" -gt 0 ] && [ "$g0" = 0 ]; then
    ok "the chatter is stepped over by Zeno guards ($g); cvode's run takes none"
else
    ko "Zeno guards: arkode '${g}', cvode '${g0}'"
fi
for key in e_n penetration; do
    a=$(jq_py ark.json "d['$key']" 2>/dev/null) r=$(jq_py ref.json "d['$key']" 2>/dev/null)
    if /usr/bin/python3 -c "import sys; a, r = float(sys.argv[1]), float(sys.argv[2]); sys.exit(not abs(a - r) <= 1e-3 * abs(r))" "$a" "$r" 2>/dev/null; then
        ok "$key $a agrees with cvode's $r to 1e-3"
    else
        ko "$key: arkode '$a', cvode '$r'"
    fi
done
test_summary test_zeno_chatter
