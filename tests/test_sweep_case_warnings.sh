#!/bin/bash
# test_sweep_case_warnings.sh GRANWAVE SRCDIR: what the forty-eighth pass left
# of chain sweeps' warnings, damping that cannot act, and the sweep's paths.
#  1 A chain sweep's cases pressed beyond one bead radius were not warned of
#    (`granwave chain` warns of its one run): the table records each case's
#    overlap_max_rel and the sweep says once, with --quiet too, how many of
#    its cases passed one radius, the largest and the first; read back from
#    the table, a resume that runs no case says it too. The same for the
#    energy error above 1e-3 with energy-tol off (control: energy-tol 0.5).
#  2 `chain --damping kk --gamma 1e-30` ran undamped in silence: a damping
#    whose predicted relative effect on the restitution (hc: alpha v_imp; kk:
#    gamma v_imp/(k d_max)) is below rtol is warned of, naming the constant
#    and the estimate (chain, its --json, drop, falcon and wavespeed at their
#    largest speed, a chain sweep once, Python); eps_eff
#    measured on both sides of the bound (warned: within rtol of the constant
#    1e-30's; an effect of 1e-4 not warned, and eps_eff moved by it).
#  3 The sweep's stderr lines printed paths raw: a config, an --out and a
#    moved directory whose names hold a space, a newline and a quote made
#    two lines of one message; each is one line now, the newline written \n.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
cd "$tmp" || exit 1
export LC_ALL=C

# lines FILE: its line count
lines() { wc -l <"$1" | tr -d ' '; }
# col FILE NAME: the column NAME of the sweep table FILE, one value a line
col() { /usr/bin/python3 -c "
import csv, sys
rows = [r for r in csv.reader(l for l in open(sys.argv[1]) if not l.startswith('#'))]
i = rows[0].index(sys.argv[2])
print('\n'.join(r[i] for r in rows[1:]))" "$1" "$2"; }
# eps FLAGS...: chain's eps_eff (repr) and W when a warning says "has no effect", else -
eps() { "$GW" chain "$@" --json --quiet 2>/dev/null | /usr/bin/python3 -c '
import json, sys
d = json.load(sys.stdin)
print(repr(d["eps_eff"]), "W" if any("has no effect" in w for w in d["warnings"]) else "-")'; }

# --- 1 a chain sweep's overlaps and energy errors ---
printf '[sweep]\nmodel = chain\nout = O\n[grid]\nvimp = 1e-6, 1000, 500\n[params]\nmass = 1e3\nkwall = 1e3\n' >o.ini
"$GW" sweep o.ini --quiet 2>o.err; rc=$?
single=$("$GW" chain --vimp 1000 --mass 1e3 --kwall 1e3 --quiet 2>&1 >/dev/null | sed -n 's/.*overlap was \([^ ]*\) bead radii.*/\1/p')
ov=$(col O/results.csv overlap_max_rel 2>/dev/null | tr '\n' ' ')
hi=$(col O/results.csv overlap_max_rel 2>/dev/null | sort -g | tail -1)
hi3=$(printf '%.3g' "$hi" 2>/dev/null)
if [ $rc -eq 0 ] && [ "$(lines o.err)" -eq 1 ] &&
    grep -qF "granwave sweep: warning: the largest contact overlap was $hi3 bead radii (2 of 3 cases beyond one radius; the first, case 1)" o.err; then
    ok "1 sweep over vimp 1e-6, 1000, 500: one line, $(cut -c1-130 o.err)"
else
    ko "1 sweep's overlaps: exit $rc, table largest '$hi3', $(head -c 300 o.err)"
fi
# the row holds the case's overlap: below one radius at 1e-6 m/s, the single run's at 1000 m/s
read -r o0 o1 o2 <<<"$ov"
if [ -n "$o2" ] && awk -v a="$o0" -v b="$o1" -v c="$o2" -v s="$single" \
    'BEGIN { exit !(a < 1e-2 && b > 1 && c > 1 && sprintf("%.3g", b) == s) }'; then
    ok "  overlap_max_rel per case: $o0 $o1 $o2 (chain --vimp 1000 alone: $single radii)"
else
    ko "  overlap_max_rel column: '$ov', the single run's '$single'"
fi
# resumed with every case journaled: the table rewritten, the line from it
rm -f O/results.csv
"$GW" sweep o.ini --quiet 2>o2.err; rc=$?
[ $rc -eq 0 ] && [ -s o2.err ] && cmp -s o.err o2.err && ok "  resumed (no case run): the same line from the table" ||
    ko "  resumed: exit $rc, $(head -c 300 o2.err)"
printf '[sweep]\nmodel = chain\nout = E\n[grid]\nrtol = 1e-4, 1e-12\n[params]\nn = 20\natol = 1e-4\n' >e.ini
"$GW" sweep e.ini --quiet 2>e.err; rc=$?
[ $rc -eq 0 ] && [ "$(lines e.err)" -eq 1 ] &&
    grep -q "relative energy error reached 0.006 .* in 2 of 2 cases (the first, case 0; their energy_error column) with energy-tol off" e.err &&
    ok "1 energy error 6e-3 at rtol = atol = 1e-4: one line, 2 of 2 cases" || ko "1 energy error: exit $rc, $(head -c 300 e.err)"
printf 'energy-tol = 0.5\n' >>e.ini
sed -i 's/out = E/out = E2/' e.ini
"$GW" sweep e.ini --quiet 2>e2.err; rc=$?
[ $rc -eq 0 ] && [ ! -s e2.err ] && ok "  control: energy-tol 0.5 given, nothing said" || ko "  energy-tol 0.5: exit $rc, $(head -c 300 e2.err)"

# --- 2 a damping too small to act ---
"$GW" chain --damping kk --gamma 1e-30 --json --quiet >k.json 2>k.err; rc=$?
w=$(jq_py k.json '[w for w in d["warnings"] if "has no effect" in w]' 2>&1)
[ $rc -eq 0 ] && [ "$(lines k.err)" -eq 1 ] &&
    grep -qF "warning: the contact damping (damping kk, gamma 1e-30 N s/m^1.5) has no effect: its predicted relative effect on the restitution, gamma v_imp/(k d_max) = 1.21e-35, is below the solver's rtol 1e-12" k.err &&
    grep -qF "$(sed 's/^granwave chain: warning: //' k.err | cut -c1-120)" <<<"$w" &&
    ok "2 chain --damping kk --gamma 1e-30: warned on stderr and in --json, effect 1.21e-35" ||
    ko "2 kk 1e-30: exit $rc, $(head -c 300 k.err) json $w"
"$GW" chain --damping hc --alpha 1e-30 --quiet >/dev/null 2>h.err
grep -qF "(damping hc, alpha 1e-30 s/m) has no effect: its predicted relative effect on the restitution, alpha v_imp = 3e-31" h.err &&
    ok "2 chain --damping hc --alpha 1e-30: warned, alpha v_imp = 3e-31" || ko "2 hc 1e-30: $(head -c 300 h.err)"
"$GW" drop --damping kk --gamma 1e-30 --quiet >/dev/null 2>dr.err
grep -q "^granwave drop: warning: the contact damping (damping kk, gamma 1e-30 N s/m^1.5) has no effect" dr.err &&
    ok "2 drop --damping kk --gamma 1e-30: warned" || ko "2 drop: $(head -c 300 dr.err)"
"$GW" falcon --damping kk --gamma 1e-30 --n 2:3 --quiet >/dev/null 2>fa.err
grep -q "^granwave falcon: warning: the contact damping (damping kk, gamma 1e-30 N s/m^1.5) has no effect" fa.err &&
    ok "2 falcon --damping kk --gamma 1e-30: warned" || ko "2 falcon: $(head -c 300 fa.err)"
"$GW" wavespeed --damping hc --alpha 1e-30 --n 8:10 --quiet >/dev/null 2>ws.err
grep -q "^granwave wavespeed: warning: the contact damping (damping hc, alpha 1e-30 s/m) has no effect: .* alpha v_imp = 5e-31" ws.err &&
    ok "2 wavespeed --damping hc --alpha 1e-30: warned at its largest speed" || ko "2 wavespeed: $(head -c 300 ws.err)"
# eps_eff on both sides of the bound (one bead, v_imp 0.3): hc alpha 3e-13
# (effect 9e-14, warned) within rtol of alpha 1e-30's; alpha 3.3e-4 and kk
# gamma 8.3 (effect 1e-4 predicted) not warned, eps_eff lower by 1e-4 (hc
# 0.99e-4 measured, kk 1.26e-4)
read -r z zw <<<"$(eps --damping hc --alpha 1e-30)"
read -r lo low <<<"$(eps --damping hc --alpha 3e-13)"
read -r a aw <<<"$(eps --damping hc --alpha 3.3e-4)"
read -r kz kzw <<<"$(eps --damping kk --gamma 1e-30)"
read -r g gw <<<"$(eps --damping kk --gamma 8.3)"
if [ "$zw$low$aw$kzw$gw" = "WW-W-" ] && awk -v z="$z" -v lo="$lo" -v a="$a" -v kz="$kz" -v g="$g" 'BEGIN {
        d = z - lo; if (d < 0) d = -d
        ea = (z - a) / z; eg = (kz - g) / kz
        exit !(d < 1e-12 && ea > 0.9e-4 && ea < 1.1e-4 && eg > 0.8e-4 && eg < 1.5e-4) }'; then
    ok "2 eps_eff: hc 3e-13 warned, $lo against $z; hc 3.3e-4 ($a) and kk 8.3 ($g) not warned, 1e-4 lower"
else
    ko "2 eps_eff about the bound: hc 1e-30 $z $zw, 3e-13 $lo $low, 3.3e-4 $a $aw; kk 1e-30 $kz $kzw, 8.3 $g $gw"
fi
[ "$(eps --damping kk --restitution 0.9 | cut -d' ' -f2)" = - ] && ok "  control: --restitution 0.9 not warned" ||
    ko "  --restitution 0.9 warned"
printf '[sweep]\nmodel = chain\nout = D\n[grid]\ngamma = 1e-30, 8.3, 1e-8\n[params]\ndamping = kk\n' >d.ini
"$GW" sweep d.ini --quiet 2>d.err; rc=$?
[ $rc -eq 0 ] && [ "$(lines d.err)" -eq 1 ] && grep -q "the contact damping has no effect in 2 of 3 cases: .* at most 1.21e-13 there" d.err &&
    ok "2 sweep over gamma 1e-30, 8.3, 1e-8: one line, 2 of 3 cases" || ko "2 sweep's damping: exit $rc, $(head -c 300 d.err)"
# Python: the library's single run and sweep say the same (pyenv: this build's module)
py_checks 3 <<'EOF'
warned("granwave.chain(damping='kk', gamma=1e-30)", "has no effect: its predicted relative effect", granwave.chain,
       damping="kk", gamma=1e-30)
warned("granwave.sweep('chain') over vimp 1e-6, 1000", "(1 of 2 cases beyond one radius; the first, case 1)",
       granwave.sweep, "chain", grid={"vimp": [1e-6, 1000]}, mass=1e3, kwall=1e3, jobs=1)
warned("granwave.sweep('chain') over gamma 1e-30, 8.3", "the contact damping has no effect in 1 of 2 cases",
       granwave.sweep, "chain", grid={"gamma": [1e-30, 8.3]}, damping="kk", jobs=1)
EOF

# --- 3 the sweep's paths on one line ---
odd="a b'c"$'\n'"d"
esc="a b'c\\nd"
mkdir -p "$odd"
printf '[sweep]\nmodel = chain\nout = R\n[grid]\nn = 1, 2\n[params]\ndt-max = 1e-13\n' >"$odd/s.ini"
"$GW" sweep "$odd/s.ini" --quiet >/dev/null 2>c.err; rc=$?
[ $rc -eq 2 ] && [ "$(lines c.err)" -eq 1 ] && grep -qF "granwave sweep: $esc/s.ini: case 0: " c.err && [ ! -e "$odd/R" ] &&
    ok "3 a refused case of config '$esc/s.ini': exit 2, one line naming it, nothing written" ||
    ko "3 config refused: exit $rc, $(lines c.err) lines: $(head -c 300 c.err)"
printf '[sweep]\nmodel = chain\nout = R\n[grid]\nn = 2:9\n[params]\nvimp = 0.1\n' >"$odd/t.ini"
"$GW" sweep "$odd/t.ini" --check >c.out 2>&1; rc=$?
[ $rc -eq 0 ] && head -1 c.out | grep -qF "sweep: $esc/t.ini is valid: model chain, 8 cases" &&
    ok "3 --check: 'sweep: $esc/t.ini is valid' on one line" || ko "3 --check: exit $rc, $(head -c 300 c.out)"
if shim_path "" move >/dev/null; then
    export ODD=$tmp/$odd
    rm -rf "$ODD/R" "$tmp/m"
    # the journal removed at row 3: put back, one warning line naming the --out
    at_row 3 'rm "$ODD/R/journal.csv"' "$GW" sweep "$odd/t.ini" --out "$ODD/R" --quiet --jobs 1 >/dev/null 2>j.err; rc=$?
    [ $rc -eq 0 ] && [ "$(lines j.err)" -eq 1 ] &&
        grep -qF "granwave sweep: warning: $tmp/$esc/R/journal.csv was removed while the sweep ran: put back" j.err &&
        ok "3 journal removed under '$esc/R': one line" || ko "3 journal removed: exit $rc, $(head -c 300 j.err)"
    # moved to the odd name, then stopped: exit 130, one line naming both
    mkdir -p m && printf '[sweep]\nmodel = chain\nout = D\n[grid]\nn = 2:9\n[params]\nvimp = 0.1\n' >m/s.ini
    at_row 3 'mv "$ODD/../m/D" "$ODD/M" && kill -TERM $PPID' "$GW" sweep m/s.ini --quiet --jobs 1 >/dev/null 2>i.err; rc=$?
    [ $rc -eq 130 ] && [ "$(lines i.err)" -eq 1 ] &&
        grep -qF "$tmp/m/D was moved to $tmp/$esc/M while the sweep ran: move it back and rerun the same command to resume (or rerun with --out $tmp/$esc/M)" i.err &&
        ok "3 moved to '$esc/M' and stopped: exit 130, one line" || ko "3 moved and stopped: exit $rc, $(head -c 400 i.err)"
    # moved to the odd name, finished there: one line
    rm -rf "$ODD/M" m/D
    at_row 3 'mv "$ODD/../m/D" "$ODD/M"' "$GW" sweep m/s.ini --quiet --jobs 1 >/dev/null 2>f.err; rc=$?
    [ $rc -eq 0 ] && [ "$(lines f.err)" -eq 1 ] &&
        grep -qF "granwave sweep: warning: $tmp/m/D was moved while the sweep ran: its journal and table are in $tmp/$esc/M" f.err &&
        [ -f "$ODD/M/results.csv" ] && ok "3 moved to '$esc/M', finished there: one line" ||
        ko "3 moved and finished: exit $rc, $(head -c 400 f.err)"
else
    echo "SKIP: no move shim (not built here): the moved and removed checks"
fi

test_summary
