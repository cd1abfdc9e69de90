#!/bin/bash
# test_chatter_warned.sh GRANWAVE SRCDIR: bead 1 chattering on a light sensor
# body (its wall contact closing 10 times or more), which amplifies the
# integration's error, said wherever a result rests on it.
#  1 A costly chatter was neither run again nor warned (`chain --n 3
#    --sensor-mass 1e-7 --sensor-stiffness 1e3`: 6707 contacts, 4.8 million
#    steps, silent): a run above 1e6 steps times beads is still not run again,
#    but warned, on stderr and in --json, naming the rerun to compare and the
#    sensor body's options; --json "chatter" is -1. Here rk4 on 1e-4 kg (68
#    contacts, 2.3e6 steps, about 2 s). A rigid sensor says nothing ("chatter" 0).
#  2 falcon, wavespeed and softwall ran their cheap chattering collisions
#    again (about 30 % more) and dropped what the reruns measured: each now
#    says it in one line with a count of its collisions, on stderr and in
#    --json (one line, not one per collision); falcon on a rigid sensor
#    says nothing.
#  3 A chain sweep's cases: a chatter column (the spread a rerun measured, -1
#    not run again) and one warning line over the rows.
#    drop's contact episodes were not checked (44 in 10 ms on 1e-4 kg, no
#    word): they are, as chain's collisions (a rerun at 10 times tighter
#    tolerances, the impacts' F_max compared; rk4's costly drop named), with a
#    chatter key at the top, in first_collision and in each impact run again.
#    A study's and a sweep's line names the rerun of the solver run (under
#    cvode it said "(rk4: half the step)" too).
#  4 Python: chain's result and a study's carry the line (their keywords) and
#    chain's the chatter value, a sweep's result the chatter column and the line,
#    drop's the line and its chatter values.
#  Session 45: the drop's line says its first collision's check sees one
#    contact (it ends half way to bead 1's second, the drop's next impact);
#    under rk4 the drop is run again at half the step up to 1e7 (5e7 from
#    session 46) steps times bodies (1e-4 kg: -1 before, now 0, every impact measured), above it the
#    line says why; Python's drop has the impacts' chatter column.
#  Session 45 too: a study's and a sweep's line said "10 times tighter
#    tolerances" where the reruns were 10 times looser, a tolerance being at
#    the 1e-15 floor (falcon --rtol 1e-15 --atol 1e-15, a sweep with rtol 1e-15
#    in [params]); they name the reruns' values where the tolerances are one
#    setting, "rtol 1e-14, atol 1e-14 (10 times looser: 1e-15 is the floor)"
#    as the single run does, and both words where the cases differ.
# About 20 s of CPU (softwall's 23 collisions the most).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
cd "$tmp" || exit 1
export LC_ALL=C

S="--sensor-mass 1e-4 --sensor-stiffness 1e3"
# nlines FILE: the lines of FILE that say a chatter
nlines() { grep -c "chattered on the sensor body" "$1"; }
# jwarn FILE: the --json warnings of FILE that say a chatter, then its "chatter" key
jwarn() { /usr/bin/python3 -c "
import json, sys
d = json.load(open(sys.argv[1]))
w = [x for x in d.get('warnings', []) if 'chattered on the sensor body' in x]
print(len(w), d.get('chatter', 'missing'))
print(w[0] if w else '')" "$1"; }

# --- 1 chain: a costly chatter, a rigid sensor
# shellcheck disable=SC2086
cpu_run 60 "$GW" chain --n 5 $S --solver rk4 --json >c.json 2>c.err
read -r nj ch < <(jwarn c.json)
txt=$(jwarn c.json | sed -n 2p)
if [ "$(nlines c.err)" = 1 ] && [ "$nj" = 1 ] && grep -q "was not run again" c.err &&
    grep -qF -- "--sensor-stiffness, --sensor-mass, --sensor-damping" c.err && grep -qF -- "compare a run at --dt " c.err; then
    ok "1 chain rk4 on 1e-4 kg: one line on stderr and in --json: $(echo "$txt" | cut -c1-150)"
else
    ko "1 chain rk4 on 1e-4 kg: $(nlines c.err) stderr lines, $nj in --json: $(head -c 300 c.err)"
fi
[ "$ch" = -1 ] && ok "  --json chatter -1 (not run again)" || ko "  --json chatter '$ch', expected -1"
cpu_run 60 "$GW" chain --n 5 --json >r.json 2>r.err
read -r nj ch < <(jwarn r.json)
if [ "$(nlines r.err)" = 0 ] && [ "$nj" = 0 ]; then
    ok "  a rigid sensor (the defaults): no chatter line"
else
    ko "  a rigid sensor: $(head -c 300 r.err)"
fi
[ "$ch" = 0 ] && ok "  a rigid sensor: --json chatter 0" || ko "  a rigid sensor: --json chatter '$ch'"

# --- 2 studies: one line each, with the count of their collisions
# study NAME NEEDLE ARGS...: one line on stderr and one in --json holding NEEDLE
study() {
    local name=$1 needle=$2
    shift 2
    cpu_run 120 "$GW" "$name" "$@" --quiet --json >"$name.json" 2>"$name.err"
    local rc=$? nj
    nj=$(jwarn "$name.json" 2>/dev/null | sed -n 1p | cut -d' ' -f1)
    if [ $rc -eq 0 ] && [ "$(nlines "$name.err")" = 1 ] && [ "$nj" = 1 ] && grep -qF "$needle" "$name.err"; then
        ok "2 $name $*: one line: $(grep -o 'chattered on the sensor body in [^:]*' "$name.err" | cut -c1-200)"
    else
        ko "2 $name $*: exit $rc, $(nlines "$name.err") stderr lines, '$nj' in --json, '$needle' wanted: $(grep chatter "$name.err" | head -c 300)"
    fi
}
# shellcheck disable=SC2086
study falcon "in 2 of 2 collisions (up to " --n 4:5 --heights none $S
# shellcheck disable=SC2086
study wavespeed "in 4 of 4 collisions (up to " --n 6:8 --vimp 0.3 $S
study softwall "of 23 collisions (up to " --n 1:3 --sensor-mass 1e-3 --sensor-stiffness 1e5
cpu_run 60 "$GW" falcon --n 4:5 --heights none --quiet --json >f0.json 2>f0.err
if [ "$(nlines f0.err)" = 0 ] && [ "$(jwarn f0.json | sed -n 1p | cut -d' ' -f1)" = 0 ]; then
    ok "  falcon on a rigid sensor: no chatter line"
else
    ko "  falcon on a rigid sensor: $(head -c 300 f0.err)"
fi

# --- 3 a chain sweep: the chatter column, one line
printf '[sweep]\nmodel = chain\nout = O\n[grid]\nn = 2, 5\nsolver = rk4, cvode\n[params]\nsensor_mass = 1e-4\nsensor_stiffness = 1e3\n' >s.ini
cpu_run 120 "$GW" sweep s.ini --quiet 2>s.err
chcol=$(/usr/bin/python3 -c "
import csv, sys
rows = [r for r in csv.reader(l for l in open('O/results.csv') if not l.startswith('#'))]
i = rows[0].index('chatter')
print(' '.join(r[i] for r in rows[1:]))" 2>/dev/null)
read -r c0 c1 c2 c3 <<<"$chcol"
if [ "$c0" = -1 ] && [ "$c1" = 0 ] && [ "$c2" = -1 ] && awk -v x="$c3" 'BEGIN { exit !(x > 1e-6) }'; then
    ok "3 sweep: the chatter column $chcol (rk4 not run again; 2 beads on cvode agree; 5 beads on cvode moved)"
else
    ko "3 sweep: the chatter column '$chcol'"
fi
if [ "$(nlines s.err)" = 1 ] && grep -qF "in 3 of 4 cases (the first, case 0; their chatter column); in 1 a rerun" s.err &&
    grep -qF "2 too costly to run again" s.err; then
    ok "  sweep: one line, $(grep -o 'chattered on the sensor body in [^:]*' s.err | cut -c1-200)"
else
    ko "  sweep: $(nlines s.err) lines: $(head -c 300 s.err)"
fi

# --- 3b drop: its contact episodes checked as chain's collisions (44 in 10 ms
# on 1e-4 kg said nothing); its first collision checked as chain's, with the
# chatter key in first_collision, at the top and in each impact run again
cpu_run 60 "$GW" drop --n 2 --json --quiet >d.json 2>d.err
if /usr/bin/python3 -c "import json,sys; d=json.load(open('d.json')); f=d['first_collision']
sys.exit(not (f.get('chatter') == 0 and d.get('chatter') == 0 and all('chatter' not in i for i in d['impacts'])))" &&
    [ "$(nlines d.err)" = 0 ]; then
    ok "3 drop on a rigid sensor: chatter 0 at the top and in first_collision (checked), none in the impacts, no line"
else
    ko "3 drop on a rigid sensor: $(head -c 300 d.json) $(head -c 200 d.err)"
fi
# shellcheck disable=SC2086
cpu_run 60 "$GW" drop --n 3 $S --json --quiet >d4.json 2>d4.err
dch=$(/usr/bin/python3 -c "
import json
d = json.load(open('d4.json'))
c = [i.get('chatter') for i in d['impacts']]
w = [x for x in d.get('warnings', []) if 'chattered on the sensor body' in x]
print(d.get('chatter'), d['first_collision'].get('chatter'), len(c), sum(x is not None for x in c),
      max([x for x in c if x is not None] or [0]), len(w), d['n_contact_episodes'])" 2>/dev/null)
read -r dtop dfirst nimp nchk dmax dw neps <<<"$dch"
if [ "$(nlines d4.err)" = 1 ] && [ "$dw" = 1 ] && grep -qF "its wall contact closed $neps times in 10 ms" d4.err &&
    grep -qF "a rerun at rtol 1e-13, atol 1e-13 changed the impacts' F_max by up to" d4.err &&
    grep -qF -- "--sensor-stiffness, --sensor-mass, --sensor-damping" d4.err; then
    ok "3 drop on 1e-4 kg: one chatter line on stderr and in --json: $(grep -o 'closed [0-9]* times[^:]*' d4.err)"
else
    ko "3 drop on 1e-4 kg: $(nlines d4.err) lines on stderr, '$dw' in --json: $(head -c 300 d4.err)"
fi
if awk -v t="$dtop" -v m="$dmax" -v f="$dfirst" -v n="$nimp" -v c="$nchk" \
    'BEGIN { exit !(t > 1e-6 && t == m && f == 0 && n > 10 && c == n) }'; then
    ok "  drop --json: chatter $dtop (the largest of the $nchk impacts' chatter), first_collision's $dfirst"
else
    ko "  drop --json: chatter '$dtop', impacts' largest '$dmax', $nchk of $nimp impacts with the key, first '$dfirst'"
fi
# the first collision ends half way to bead 1's second contact (the drop's
# next impact): its own check sees one contact, which the line says (session 45)
if grep -qF "the first collision ends half way to the second, its check seeing one contact" d4.err &&
    /usr/bin/python3 -c "import json,sys; sys.exit(json.load(open('d4.json'))['first_collision']['wall_contacts'] != 1)"; then
    ok "3 drop on 1e-4 kg: the line says the first collision's check sees one contact (its wall_contacts 1)"
else
    ko "3 drop on 1e-4 kg: the first collision's one contact not said: $(head -c 300 d4.err)"
fi
# rk4's rerun at half the step costs twice the drop's steps, known before it is
# made: run again up to 5e7 steps times bodies (9.8e5 steps times 3 here:
# chatter -1 before, session 45), every impact's chatter measured, within 1e-6
# (no line); above it (1e-6 kg on 1e5 N/m with 10 beads: 6e6 steps times 10;
# 3 beads, 1.8e7, were above the 1e7 before session 46) -1, the line saying why
# shellcheck disable=SC2086
cpu_run 60 "$GW" drop --n 3 $S --solver rk4 --json --quiet >d5.json 2>d5.err
d5=$(/usr/bin/python3 -c "
import json
d = json.load(open('d5.json'))
c = [i.get('chatter') for i in d['impacts']]
print(d.get('chatter'), len(c), sum(x is not None for x in c), max([x for x in c if x is not None] or [-1]))" 2>/dev/null)
read -r d5top d5n d5chk d5max <<<"$d5"
if [ "$(nlines d5.err)" = 0 ] && [ "$d5top" = 0 ] &&
    awk -v n="$d5n" -v c="$d5chk" -v m="$d5max" 'BEGIN { exit !(n > 10 && c == n && m >= 0 && m <= 1e-6) }'; then
    ok "3 drop rk4 on 1e-4 kg: run again at half the step (chatter 0, $d5chk of $d5n impacts measured, up to $d5max), no line"
else
    ko "3 drop rk4 on 1e-4 kg: chatter '$d5top', $d5chk of $d5n impacts measured (up to $d5max): $(head -c 300 d5.err)"
fi
cpu_run 60 "$GW" drop --n 10 --sensor-mass 1e-6 --sensor-stiffness 1e5 --solver rk4 --json --quiet >d6.json 2>d6.err
if [ "$(nlines d6.err)" = 1 ] && grep -qF "was not run again" d6.err && grep -qF "compare a run at --dt " d6.err &&
    grep -qF "above the 5e+07 a rerun at half rk4's step, twice the drop's steps, is made within" d6.err &&
    [ "$(jwarn d6.json | sed -n 1p)" = "1 -1" ]; then
    ok "3 drop rk4 of 10 beads on 1e-6 kg, 1e5 N/m (costly): one line naming --dt and why (twice the drop's steps above 5e7), chatter -1"
else
    ko "3 drop rk4 costly: $(nlines d6.err) lines, --json '$(jwarn d6.json | sed -n 1p)': $(head -c 500 d6.err)"
fi

# --- 3c the reruns named by the solver run: a study under cvode was told
# "(rk4: half the step)" too
# (session 45: with the reruns' values, the tolerances being one setting)
tight="a rerun at 10 times tighter tolerances (rtol 1e-13, atol 1e-13) moved eps_eff"
if grep -qF "$tight" falcon.err && ! grep -q "rk4" falcon.err; then
    ok "3 falcon under cvode: '$tight', no rk4"
else
    ko "3 falcon under cvode: $(grep -o 'in [0-9]* a rerun at[^:]*' falcon.err)"
fi
if grep -qF "in 1 $tight" s.err && ! grep -q "rk4" s.err; then
    ok "3 sweep (the moved case under cvode): no rk4 in its rerun, its tolerances named"
else
    ko "3 sweep: $(grep -o 'in [0-9]* a rerun at[^:]*' s.err)"
fi

# --- 3d at the 1e-15 floor the reruns are 10 times looser (chain_chatter_rerun),
# and a study's and a sweep's line said "10 times tighter tolerances" (session 45)
loose="a rerun at rtol 1e-14, atol 1e-14 (10 times looser: 1e-15 is the floor) moved eps_eff"
# shellcheck disable=SC2086
cpu_run 60 "$GW" falcon --n 1:3 --heights none $S --rtol 1e-15 --atol 1e-15 --quiet --json >fl.json 2>fl.err
if [ "$(nlines fl.err)" = 1 ] && grep -qF "in 1 $loose" fl.err && ! grep -q "tighter" fl.err &&
    [ "$(jwarn fl.json | sed -n 1p | cut -d' ' -f1)" = 1 ] && jwarn fl.json | sed -n 2p | grep -qF "$loose"; then
    ok "3 falcon at rtol = atol = 1e-15: '$loose', on stderr and in --json"
else
    ko "3 falcon at 1e-15: $(grep -o 'in [0-9]* a rerun at[^:]*' fl.err)"
fi
printf '[sweep]\nmodel = chain\nout = OL\n[grid]\nn = 3, 5\n[params]\nsensor_mass = 1e-4\nsensor_stiffness = 1e3\nrtol = 1e-15\natol = 1e-15\n' >sl.ini
cpu_run 120 "$GW" sweep sl.ini --quiet 2>sl.err
if [ "$(nlines sl.err)" = 1 ] && grep -qF "in 2 $loose" sl.err && ! grep -q "tighter" sl.err; then
    ok "3 sweep at rtol = atol = 1e-15: '$loose'"
else
    ko "3 sweep at 1e-15: $(grep -o 'in [0-9]* a rerun at[^:]*' sl.err)"
fi
# cases at the floor and above it: both said, no values (they differ)
printf '[sweep]\nmodel = chain\nout = OM\n[grid]\nn = 3, 5\nrtol = 1e-15, 1e-12\n[params]\nsensor_mass = 1e-4\nsensor_stiffness = 1e3\n' >sm.ini
cpu_run 120 "$GW" sweep sm.ini --quiet 2>sm.err
mixed="in 4 a rerun at 10 times tighter tolerances (10 times looser where one was at the 1e-15 floor) moved eps_eff"
if [ "$(nlines sm.err)" = 1 ] && grep -qF "$mixed" sm.err; then
    ok "3 sweep over rtol 1e-15, 1e-12: '$mixed'"
else
    ko "3 sweep over rtol 1e-15, 1e-12: $(grep -o 'in [0-9]* a rerun at[^:]*' sm.err)"
fi

# --- 4 Python
py_checks 6 <<'PY'
r, ws = caught(granwave.chain, n=5, sensor_mass=1e-4, sensor_stiffness=1e3, solver="rk4")
w = [m for m in ws if "chattered on the sensor body" in m]
check(len(w) == 1 and "was not run again" in w[0] and "sensor_stiffness" in w[0] and
      len([m for m in r["warnings"] if "chattered" in m]) == 1 and r.get("chatter") == -1,
      "4 Python chain: one chatter warning, in the result too, naming sensor_stiffness, chatter %s as --json's -1: %s"
      % (r.get("chatter"), [m[:80] for m in w]))
r, ws = caught(granwave.falcon, n="4:5", heights="none", sensor_mass=1e-4, sensor_stiffness=1e3)
w = [m for m in ws if "chattered on the sensor body" in m]
check(len(w) == 1 and "in 2 of 2 collisions" in w[0] and len([m for m in r["warnings"] if "chattered" in m]) == 1,
      "4 Python falcon: one line with the count: %s" % [m[:100] for m in w])
r, ws = caught(granwave.sweep, "chain", grid={"n": [2, 5]}, solver="rk4", sensor_mass=1e-4, sensor_stiffness=1e3,
               jobs=1)
w = [m for m in r["warnings"] if "chattered on the sensor body" in m]
check(list(r.get("chatter", [])) == [-1, -1] and len(w) == 1 and "in 2 of 2 cases" in w[0],
      "4 Python sweep: the chatter column %s, one line: %s" % (list(r.get("chatter", [])), [m[:100] for m in w]))
r, ws = caught(granwave.falcon, n="1:3", heights="none", sensor_mass=1e-4, sensor_stiffness=1e3, rtol=1e-15,
               atol=1e-15)
w = [m for m in ws if "chattered on the sensor body" in m]
check(len(w) == 1 and "a rerun at rtol 1e-14, atol 1e-14 (10 times looser: 1e-15 is the floor)" in w[0],
      "4 Python falcon at rtol = atol = 1e-15: the reruns 10 times looser: %s" % [m[:200] for m in w])
r, ws = caught(granwave.drop, n=3, sensor_mass=1e-4, sensor_stiffness=1e3)
w = [m for m in ws if "chattered on the sensor body" in m]
check(len(w) == 1 and "times in 10 ms" in w[0] and r.get("chatter", 0) > 1e-6 and
      r["first_collision"].get("chatter") == 0,
      "4 Python drop: one chatter warning, chatter %s as --json's, first_collision's %s: %s"
      % (r.get("chatter"), r["first_collision"].get("chatter"), [m[:100] for m in w]))
# the impacts' chatter column, each as --json's per-impact chatter (session 45)
import json
d4 = json.load(open("d4.json"))
col = list(r["impacts"].get("chatter", []))
want = [i.get("chatter") for i in d4["impacts"]]
check(len(col) == len(want) > 10 and all(a == b for a, b in zip(col, want)),
      "4 Python drop: the impacts' chatter column (%d values, up to %s) as --json's per impact"
      % (len(col), max(col) if col else None))
PY

test_summary test_chatter_warned
