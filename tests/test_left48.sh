#!/bin/bash
# test_left48.sh GRANWAVE SRCDIR: what the forty-eighth pass left, asserted
# through the program.
#  1 `chain --n 20 --rtol 1e-4 --atol 1e-4` ended at a relative energy error of
#    0.6 % with no warning while --energy-tol was off: above 1e-3 it is warned
#    (stderr, the JSON's warnings, Python), naming rtol and atol; the default
#    tolerances (5.4e-10) and --energy-tol given warn nothing. The same for
#    layer-impact (--solver cvode --rtol 1e-4 --atol 1e-4: 1.55 %).
#  3 A range-valued option (falcon, wavespeed, softwall --n A:B) refused
#    '1:3:1' as "'3:1' is not an integer", quoting a fragment: the refusal now
#    quotes the whole value given and the form a range takes (A:B, A <= B),
#    then the end's own reason (gw_parse_int_range, which every range option
#    of the program and of a sweep's configuration reads through).
#  4 `layer-impact --alpha 89.9` (20 m/s) was refused naming --vi only: the
#    incidence is the driver of the normal speed. The refusal names the
#    incidence and the largest one that runs, and that one runs (exit 0) while
#    one 1e-4 deg above it is refused.
#  5 layer-make's text output printed a raw newline of an --out name holding
#    one ("written to s<newline>t.txt"): every path the program echoes goes
#    through gw_one_line (gw_cli_path), the name printed s\nt.txt on one line.
#    Since session 42 such a name to make is refused; a directory the user
#    made with a newline (s<newline>d/t.txt) is written into and echoed so.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 chain: a large energy error under loose tolerances is warned ---
# rtol = atol = 1e-4 ends at 0.6 % (the default tolerances: 5.4e-10); the bound 1e-3
if runs_json "chain --rtol 1e-4 --atol 1e-4" c.json chain --n 20 --rtol 1e-4 --atol 1e-4; then
    res=$(jq_py c.json '(d["energy_error"] > 1e-3, sum("energy error reached" in w and "rtol = 0.0001, atol = 0.0001" in w for w in d["warnings"]))')
    nerr=$(grep -c "granwave chain: warning: the relative energy error reached 0.006 .* rtol = 0.0001, atol = 0.0001" "$tmp/stderr")
    [ "$res" = "(True, 1)" ] && [ "$nerr" = 1 ] && ok "chain --rtol 1e-4 --atol 1e-4: energy error above 1e-3 warned once on stderr and in the JSON, naming rtol and atol" ||
        ko "chain --rtol 1e-4 --atol 1e-4: $res, $nerr stderr warnings: $(head -c 300 "$tmp/stderr")"
fi
# controls: the default run and a run with --energy-tol on (it stops at its bound instead) warn nothing
cpu_run 60 "$GW" chain --n 20 --quiet --json >d.json 2>"$tmp/stderr"
[ $? = 0 ] && [ ! -s "$tmp/stderr" ] && [ "$(jq_py d.json 'd["warnings"]')" = "[]" ] &&
    ok "control: chain --n 20 at the default tolerances: no warning" || ko "control: chain --n 20: $(head -c 300 "$tmp/stderr")"
cpu_run 60 "$GW" chain --n 20 --rtol 1e-4 --atol 1e-4 --energy-tol 1 --quiet --json >e.json 2>"$tmp/stderr"
[ $? = 0 ] && [ "$(jq_py e.json 'd["warnings"]')" = "[]" ] &&
    ok "control: --energy-tol 1 given: no energy warning" || ko "control: --energy-tol 1: $(jq_py e.json 'd["warnings"]')"
# layer-impact --solver cvode --rtol 1e-4 --atol 1e-4 on a 40-disc pile: 1.55 % (defaults: 3.4e-5 rk4, 1.4e-6 CVODE)
make_sample pile.txt --n 40 --quiet
if runs_json "layer-impact --solver cvode --rtol 1e-4 --atol 1e-4" l.json layer-impact --sample pile.txt --solver cvode --rtol 1e-4 --atol 1e-4; then
    res=$(jq_py l.json '(d["energy_error"] > 1e-3, sum("energy error reached" in w and "rtol = 0.0001, atol = 0.0001" in w for w in d["warnings"]))')
    nerr=$(grep -c "granwave layer-impact: warning: the relative energy error reached .* rtol = 0.0001, atol = 0.0001" "$tmp/stderr")
    [ "$res" = "(True, 1)" ] && [ "$nerr" = 1 ] && ok "layer-impact cvode at 1e-4: energy error above 1e-3 warned on stderr and in the JSON, naming rtol and atol" ||
        ko "layer-impact cvode at 1e-4: $res, $nerr stderr warnings: $(head -c 300 "$tmp/stderr")"
fi
for a in "" "--solver cvode" "--solver cvode --rtol 1e-4 --atol 1e-4 --energy-tol 1"; do
    # shellcheck disable=SC2086
    cpu_run 60 "$GW" layer-impact --sample pile.txt $a --quiet --json >m.json 2>"$tmp/stderr"
    # (no warning but the crowns' own: since session 46 this pile's cross-correlation,
    # nulled for its scatter, is warned of)
    [ $? = 0 ] && ! grep -v "warning: crowns: " "$tmp/stderr" | grep -q . &&
        [ "$(jq_py m.json 'all(w.startswith("crowns: ") for w in d["warnings"])')" = True ] &&
        ok "control: layer-impact ${a:-(default)}: no warning" || ko "control: layer-impact $a: $(head -c 300 "$tmp/stderr")"
done
# Python: the same warning from granwave.chain and granwave.layer_impact
if ! sanitizer_build; then
    got=$(pyenv /usr/bin/python3 -c "
import warnings, granwave
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter('always')
    granwave.chain(n=20, rtol=1e-4, atol=1e-4)
print(sum('energy error reached' in str(x.message) and 'rtol = 0.0001' in str(x.message) for x in w))
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter('always')
    granwave.layer_impact(sample='pile.txt', solver='cvode', rtol=1e-4, atol=1e-4)
print(sum('energy error reached' in str(x.message) and 'rtol = 0.0001' in str(x.message) for x in w))" 2>&1 | tr '\n' ' ')
    [ "$got" = "1 1 " ] && ok "Python chain and layer_impact at rtol = atol = 1e-4: the energy warning" || ko "Python: $got"
fi

# --- 3 a range option's refusal quotes the whole value and the form A:B ---
refused "falcon --n 1:3:1" "^granwave falcon --n: '1:3:1' is not a range A:B of integers, A <= B" falcon --n 1:3:1
refused "wavespeed --n 1:x" "^granwave wavespeed --n: '1:x' is not a range A:B of integers, A <= B \(its end" wavespeed --n 1:x
refused "softwall --n 0:3" "^granwave softwall --n: '0:3' is not a range A:B of integers, A <= B \(its start: 0 is outside" softwall --n 0:3
# control: a range that is one still runs past the parse (refused later or run: not a range refusal)
"$GW" falcon --n 3:1 >/dev/null 2>"$tmp/stderr"
grep -q "range '3:1' is empty" "$tmp/stderr" && ok "control: falcon --n 3:1 refused as an empty range" ||
    ko "control: falcon --n 3:1: $(cat "$tmp/stderr")"

# --- 4 layer-impact: a steep incidence named with vi, and the largest that runs ---
rm -rf o
if exits_refused "layer-impact --alpha 89.9" "^granwave layer-impact --vi: 20 m/s at incidence alpha 89.9 deg is too slow" 30 \
    "$GW" layer-impact --sample pile.txt --alpha 89.9; then
    amax=$(grep -o 'an incidence alpha of at most [0-9.]* deg' "$tmp/stderr" | grep -o '[0-9][0-9.]*')
    if [ -n "$amax" ]; then
        ok "layer-impact --alpha 89.9: refused naming vi and the incidence, largest alpha $amax"
        cpu_run 60 "$GW" layer-impact --sample pile.txt --alpha "$amax" --t-max 1e-4 --quiet --json >/dev/null 2>&1
        rc=$?
        above=$(/usr/bin/python3 -c "print($amax + 1e-4)")
        cpu_run 60 "$GW" layer-impact --sample pile.txt --alpha "$above" --t-max 1e-4 --quiet --json >/dev/null 2>&1
        rc2=$?
        [ $rc = 0 ] && [ $rc2 = 2 ] && ok "layer-impact --alpha $amax runs, --alpha $above is refused" ||
            ko "layer-impact --alpha $amax: exit $rc, --alpha $above: exit $rc2 (expected 0, 2)"
    else
        ko "layer-impact --alpha 89.9: no largest incidence named: $(cat "$tmp/stderr")"
    fi
fi

# --- 5 layer-make: an --out name with a newline echoed on one line ---
# (session 42: a name to make that holds a control character is refused, exit
# 2, one line, nothing written; a directory the user made with one is written
# into, and its name echoed on one line)
name=$(printf 's\nt.txt')
cpu_run 60 "$GW" layer-make --n 40 --out "$name" --quiet >"$tmp/lm.out" 2>"$tmp/stderr" </dev/null
rc=$?
[ $rc = 2 ] && [ ! -e "$name" ] && [ "$(wc -l <"$tmp/stderr")" -eq 1 ] && grep -q 'control character' "$tmp/stderr" &&
    ok "layer-make --out 's<newline>t.txt': refused (exit 2, one line), nothing written" ||
    ko "layer-make --out 's<newline>t.txt': exit $rc, $(tr '\n' '|' <"$tmp/stderr")"
d=$(printf 's\nd')
mkdir -p "$d"
cpu_run 60 "$GW" layer-make --n 40 --out "$d/t.txt" >"$tmp/lm.out" 2>"$tmp/stderr" </dev/null
rc=$?
last=$(tail -n 1 "$tmp/lm.out")
[ $rc = 0 ] && [ -s "$d/t.txt" ] && [ "$last" = "${last%written to s\\nd/t.txt}written to s\\nd/t.txt" ] &&
    ! grep -qx 'd/t.txt' "$tmp/lm.out" &&
    ok "layer-make --out 's<newline>d/t.txt' (a directory the user made): written, its name printed s\\nd/t.txt on one line" ||
    ko "layer-make --out 's<newline>d/t.txt': exit $rc, output ends: $(tail -n 2 "$tmp/lm.out" | tr '\n' '|')"

test_summary test_left48
